"""Two agents fly one episode each of ``deckland/CarrierLanding-v1`` (``attitude``
mode): a random agent and a scripted one. Nothing is trained.

The scripted agent sends back ``info["autopilot_action"]``, the action the built-in
cascade would take now (the guidance and sink-rate loops' pitch command, the speed
loop's thrust): the cascade sampled every 20 ms, without direct lift and without the
automatic wave-off, a baseline an agent should beat. The random agent samples the action
space.

Run: ``python gym_agents.py`` (needs ``pip install ./python[gymnasium]``).
"""

from __future__ import annotations

import gymnasium
import numpy as np

import deckland  # noqa: F401  (registers deckland/CarrierLanding-v1)


def random_agent(env):
    return lambda observation, info: env.action_space.sample()


def scripted_agent(env):
    return lambda observation, info: info["autopilot_action"]


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
    env = gymnasium.make("deckland/CarrierLanding-v1")
    results = {}
    for name, make_agent in (("random", random_agent), ("scripted", scripted_agent)):
        steps, total, info = episode(env, make_agent(env), seed)
        outcome = info.get("outcome", "time limit")
        results[name] = outcome
        wire = f", wire {info['wire']}" if info.get("wire") else ""
        reason = f" ({info['reason']})" if info.get("reason") else ""
        print(f"{name:>8} agent: {outcome}{wire}{reason} after {steps} steps "
              f"({steps * 0.02:.2f} s), return {total:.1f}")
    env.close()
    return results


if __name__ == "__main__":
    main()
