"""Two agents fly one episode each of ``deckland/CarrierLanding-v0``: a random agent and
a scripted one. Nothing is trained.

The scripted agent reads the built-in cascade's commands from ``info`` (the guidance and
sink-rate loops' pitch command, the speed loop's thrust) and sends them as its action:
the cascade sampled every 20 ms, a baseline an agent should beat. The random agent
samples the action space and is soon waved off or worse.

Run: ``python gym_agents.py`` (needs ``pip install ./python[gymnasium]``).
"""

from __future__ import annotations

import gymnasium
import numpy as np

import deckland  # noqa: F401  (registers deckland/CarrierLanding-v0)


def random_agent(env):
    return lambda observation, info: env.action_space.sample()


def scripted_agent(env):
    unwrapped = env.unwrapped
    return lambda observation, info: unwrapped.action_for(info["theta_command_rad"], info["thrust_command_n"])


def episode(env, agent, seed):
    """Flies one episode; returns (steps, total reward, final info)."""
    observation, info = env.reset(seed=seed)
    env.action_space.seed(seed)
    total, steps = 0.0, 0
    while True:
        observation, reward, terminated, truncated, info = env.step(agent(observation, info))
        total += reward
        steps += 1
        if terminated or truncated:
            return steps, total, info


def main(seed: int = 1) -> dict:
    env = gymnasium.make("deckland/CarrierLanding-v0")
    results = {}
    for name, make_agent in (("random", random_agent), ("scripted", scripted_agent)):
        steps, total, info = episode(env, make_agent(env), seed)
        results[name] = info["outcome"]
        wire = f", wire {info['wire']}" if info.get("wire") else ""
        reason = f" ({info['reason']})" if info.get("reason") else ""
        print(f"{name:>8} agent: {info['outcome']}{wire}{reason} after {steps} steps "
              f"({info['time_s']:.2f} s), return {total:.1f}")
    env.close()
    return results


if __name__ == "__main__":
    main()
