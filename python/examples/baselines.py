"""The baselines of ``deckland/CarrierLanding-v1``: the built-in autopilot as a policy
and a random policy, scored in every control mode over the same seeds.

The autopilot sends back ``info["autopilot_action"]``, the action the built-in cascade
would take now in that mode (sampled every 20 ms; it never waves off, since the
automatic wave-off is off). The random policy samples the action space uniformly
(the wave-off entry too, so it usually waves off at once).

Run: ``python baselines.py [--episodes 100] [--seed 1000]``; prints a Markdown table of
the mean return (± its standard error) and the outcomes per mode and policy. Each
episode is environment i of a native vectorised environment reset with seed
``seed + i``.
"""

from __future__ import annotations

import argparse
from collections import Counter

import numpy as np

from deckland.env import CONTROL_MODES, CarrierLandingVecEnv


def score(mode: str, policy: str, episodes: int, seed: int, reward: str = "shaped"):
    """(returns, outcomes) of the first episode of each of `episodes` environments."""
    envs = CarrierLandingVecEnv(num_envs=episodes, control=mode, reward=reward)
    rng = np.random.default_rng(seed)
    _, info = envs.reset(seed=seed)
    returns = np.zeros(episodes)
    outcomes = [None] * episodes
    done = np.zeros(episodes, dtype=bool)
    while not done.all():
        if policy == "autopilot":
            actions = info["autopilot_action"]
        else:
            actions = rng.uniform(-1, 1, size=envs.action_space.shape).astype(np.float32)
        _, reward_, terminated, truncated, info = envs.step(actions)
        returns += np.where(done, 0.0, reward_)
        ended = (terminated | truncated) & ~done
        for i in np.flatnonzero(ended):
            outcomes[i] = info["outcome"][i] or "time limit"
        done |= ended
    return returns, outcomes


def main() -> None:
    parser = argparse.ArgumentParser(description="score the autopilot and a random policy")
    parser.add_argument("--episodes", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1000)
    args = parser.parse_args()
    print("| mode | policy | mean return | traps | outcomes |")
    print("|---|---|---|---|---|")
    for mode in CONTROL_MODES:
        for policy in ("autopilot", "random"):
            returns, outcomes = score(mode, policy, args.episodes, args.seed)
            counts = Counter(outcomes)
            spread = returns.std(ddof=1) / np.sqrt(len(returns))
            listed = ", ".join(f"{name} {count}" for name, count in counts.most_common())
            print(f"| {mode} | {policy} | {returns.mean():.1f} ± {spread:.1f} | "
                  f"{counts.get('trap', 0)}/{len(returns)} | {listed} |")


if __name__ == "__main__":
    main()
