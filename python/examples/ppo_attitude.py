"""PPO on ``deckland/CarrierLanding-v1`` in ``attitude`` mode: a CleanRL-style,
single-file implementation in numpy (no deep-learning framework needed), on the native
vectorised environment. An example, not a test: it trains for ``--minutes`` of wall
time and writes its learning curve.

    OMP_NUM_THREADS=1 RAYON_NUM_THREADS=1 python ppo_attitude.py --minutes 28 --out ppo --plot

The policy is a Gaussian over the action (pitch command, thrust, wave-off) whose mean is
an MLP (13 → 64 → 64 → 3, tanh) and whose log standard deviations are parameters; the
value function is a second MLP (13 → 64 → 64 → 1). Actions are clipped to the action
space when sent. The wave-off output's bias starts at −3 (a prior against waving off;
the policy may still learn to wave off). PPO: generalised advantage estimation, the
clipped objective, Adam, gradient-norm clipping (Schulman et al. 2017; the CleanRL
``ppo_continuous_action.py`` defaults: γ = 0.99, λ = 0.95, clip 0.2, 10 epochs, 4
minibatches, learning rate 3·10⁻⁴, rewards scaled by 0.01). The agent decides every
0.1 s (``--control-interval-s``; an approach is about 250 decisions), which γ = 0.99
spans. The vectorised environment's next-step autoreset steps (reward 0, action
ignored) are left out of the loss.

Writes ``OUT.csv`` (env steps, wall seconds, mean return of the episodes that ended in
that iteration, their trap fraction) and, after training, scores over 100 episodes with
seeds 1000–1099 (those of ``baselines.py``), at the same control interval: the
trained policy's mean action, the autopilot (``info["autopilot_action"]``) and a
uniform random policy. With ``--plot`` (matplotlib) it draws ``OUT.png``: the learning
curve against the autopilot's and the random policy's scores.
"""

from __future__ import annotations

import argparse
import csv
import time
from collections import Counter

import numpy as np

from deckland.env import CarrierLandingVecEnv


class Mlp:
    """A tanh MLP with a linear output, and its gradient by backpropagation."""

    def __init__(self, sizes, rng, output_scale):
        self.params = []
        for i, (n_in, n_out) in enumerate(zip(sizes[:-1], sizes[1:])):
            gain = output_scale if i == len(sizes) - 2 else np.sqrt(2.0)
            w = rng.standard_normal((n_in, n_out))
            q, _ = np.linalg.qr(w if n_in >= n_out else w.T)  # orthogonal, as CleanRL
            w = (q if n_in >= n_out else q.T)[:n_in, :n_out] * gain
            self.params += [w, np.zeros(n_out)]

    def forward(self, x):
        cache = [x]
        for i in range(0, len(self.params), 2):
            x = x @ self.params[i] + self.params[i + 1]
            if i < len(self.params) - 2:
                x = np.tanh(x)
            cache.append(x)
        return x, cache

    def backward(self, cache, d_out):
        grads = [None] * len(self.params)
        d = d_out
        for i in range(len(self.params) - 2, -1, -2):
            grads[i] = cache[i // 2].T @ d
            grads[i + 1] = d.sum(axis=0)
            if i > 0:
                d = (d @ self.params[i].T) * (1.0 - cache[i // 2] ** 2)
        return grads


class Adam:
    def __init__(self, params, lr):
        self.lr, self.t = lr, 0
        self.m = [np.zeros_like(p) for p in params]
        self.v = [np.zeros_like(p) for p in params]

    def step(self, params, grads, max_norm):
        norm = np.sqrt(sum(float((g * g).sum()) for g in grads))
        scale = min(1.0, max_norm / (norm + 1e-6))
        self.t += 1
        for p, g, m, v in zip(params, grads, self.m, self.v):
            g = g * scale
            m *= 0.9
            m += 0.1 * g
            v *= 0.999
            v += 0.001 * g * g
            p -= self.lr * (m / (1 - 0.9**self.t)) / (np.sqrt(v / (1 - 0.999**self.t)) + 1e-5)


def evaluate(policy, interval_s, episodes=100, seed=1000):
    """Mean return and outcomes of `policy(observation, info)` over `episodes` seeds."""
    envs = CarrierLandingVecEnv(num_envs=episodes, control="attitude", control_interval_s=interval_s)
    observation, info = envs.reset(seed=seed)
    returns = np.zeros(episodes)
    done = np.zeros(episodes, dtype=bool)
    outcomes = [None] * episodes
    while not done.all():
        action = np.clip(policy(observation, info), -1, 1).astype(np.float32)
        observation, reward, terminated, truncated, info = envs.step(action)
        returns += np.where(done, 0.0, reward)
        ended = (terminated | truncated) & ~done
        for i in np.flatnonzero(ended):
            outcomes[i] = info["outcome"][i] or "time limit"
        done |= ended
    return returns.mean(), Counter(outcomes)


def main() -> None:
    parser = argparse.ArgumentParser(description="PPO in attitude mode")
    parser.add_argument("--minutes", type=float, default=30.0)
    parser.add_argument("--num-envs", type=int, default=32)
    parser.add_argument("--num-steps", type=int, default=64)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--control-interval-s", type=float, default=0.1)
    parser.add_argument("--out", default="ppo")
    parser.add_argument("--plot", action="store_true")
    args = parser.parse_args()

    gamma, lam, clip, epochs, minibatches = 0.99, 0.95, 0.2, 10, 4
    lr, vf_coef, max_norm, reward_scale = 3e-4, 0.5, 0.5, 0.01
    rng = np.random.default_rng(args.seed)
    interval_s = args.control_interval_s
    envs = CarrierLandingVecEnv(num_envs=args.num_envs, control="attitude", control_interval_s=interval_s)
    n, t_len = args.num_envs, args.num_steps
    d = envs.single_observation_space.shape[0]
    a_dim = envs.single_action_space.shape[0]
    actor = Mlp([d, 64, 64, a_dim], rng, 0.01)
    actor.params[-1][-1] = -3.0  # the wave-off output: a prior against waving off
    log_std = np.full(a_dim, -1.0)
    critic = Mlp([d, 64, 64, 1], rng, 1.0)
    actor_opt = Adam(actor.params + [log_std], lr)
    critic_opt = Adam(critic.params, lr)

    observation, _ = envs.reset(seed=args.seed * 100_000)
    autoreset = np.zeros(n, dtype=bool)
    running = np.zeros(n)
    started = time.perf_counter()
    steps = 0
    rows = []
    while time.perf_counter() - started < 60.0 * args.minutes:
        obs_buf = np.zeros((t_len, n, d))
        act_buf = np.zeros((t_len, n, a_dim))
        logp_buf = np.zeros((t_len, n))
        rew_buf = np.zeros((t_len, n))
        done_buf = np.zeros((t_len, n))
        val_buf = np.zeros((t_len, n))
        valid = np.zeros((t_len, n), dtype=bool)
        finished = []
        for t in range(t_len):
            x = observation.astype(np.float64)
            mean, _ = actor.forward(x)
            value, _ = critic.forward(x)
            std = np.exp(log_std)
            action = mean + std * rng.standard_normal(mean.shape)
            obs_buf[t], act_buf[t], val_buf[t] = x, action, value[:, 0]
            logp_buf[t] = (-0.5 * ((action - mean) / std) ** 2 - log_std - 0.5 * np.log(2 * np.pi)).sum(1)
            valid[t] = ~autoreset
            observation, reward, terminated, truncated, info = envs.step(np.clip(action, -1, 1).astype(np.float32))
            ended = terminated | truncated
            rew_buf[t] = reward * reward_scale
            done_buf[t] = ended
            running += np.where(autoreset, 0.0, reward)
            for i in np.flatnonzero(ended):
                finished.append((running[i], info["outcome"][i] == "trap"))
                running[i] = 0.0
            autoreset = ended
        steps += n * t_len
        next_value = critic.forward(observation.astype(np.float64))[0][:, 0]
        advantages = np.zeros((t_len, n))
        last = np.zeros(n)
        for t in reversed(range(t_len)):
            following = next_value if t == t_len - 1 else val_buf[t + 1]
            alive = 1.0 - done_buf[t]
            delta = rew_buf[t] + gamma * following * alive - val_buf[t]
            last = delta + gamma * lam * alive * last
            advantages[t] = last
        returns = advantages + val_buf
        keep = valid.reshape(-1)
        b_obs = obs_buf.reshape(-1, d)[keep]
        b_act = act_buf.reshape(-1, a_dim)[keep]
        b_logp = logp_buf.reshape(-1)[keep]
        b_adv = advantages.reshape(-1)[keep]
        b_ret = returns.reshape(-1)[keep]
        size = len(b_obs)
        for _ in range(epochs):
            order = rng.permutation(size)
            for chunk in np.array_split(order, minibatches):
                x, a = b_obs[chunk], b_act[chunk]
                adv = b_adv[chunk]
                adv = (adv - adv.mean()) / (adv.std() + 1e-8)
                mean, cache = actor.forward(x)
                std = np.exp(log_std)
                z = (a - mean) / std
                logp = (-0.5 * z**2 - log_std - 0.5 * np.log(2 * np.pi)).sum(1)
                ratio = np.exp(logp - b_logp[chunk])
                active = np.where(adv >= 0, ratio <= 1 + clip, ratio >= 1 - clip)
                d_logp = -adv * ratio * active / len(chunk)
                d_mean = d_logp[:, None] * z / std
                d_log_std = (d_logp[:, None] * (z**2 - 1.0)).sum(0)
                grads = actor.backward(cache, d_mean) + [d_log_std]
                actor_opt.step(actor.params + [log_std], grads, max_norm)
                value, cache = critic.forward(x)
                d_value = vf_coef * (value[:, 0] - b_ret[chunk])[:, None] / len(chunk)
                critic_opt.step(critic.params, critic.backward(cache, d_value), max_norm)
        if finished:
            rets = np.array([f[0] for f in finished])
            traps = np.mean([f[1] for f in finished])
            rows.append((steps, time.perf_counter() - started, rets.mean(), traps, len(finished)))
            print(f"{steps:>10} steps {rows[-1][1]:7.0f} s  return {rets.mean():8.1f}  "
                  f"traps {traps:4.2f}  episodes {len(finished)}  std {np.exp(log_std).round(2)}",
                  flush=True)
    wall = time.perf_counter() - started
    with open(f"{args.out}.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["env_steps", "wall_s", "mean_return", "trap_fraction", "episodes"])
        writer.writerows(rows)
    scores = {
        "PPO (mean action)": evaluate(lambda o, i: actor.forward(o.astype(np.float64))[0], interval_s),
        "autopilot": evaluate(lambda o, i: i["autopilot_action"], interval_s),
        "random": evaluate(lambda o, i: rng.uniform(-1, 1, (len(o), a_dim)), interval_s),
    }
    print(f"trained {steps} env steps in {wall:.0f} s ({wall / 60:.1f} min)")
    for name, (score, outcomes) in scores.items():
        print(f"{name}, seeds 1000-1099: mean return {score:.1f}, outcomes {dict(outcomes)}")
    if args.plot:
        plot(rows, args.out, {name: score for name, (score, _) in scores.items()})


def plot(rows, out, scores):
    """The learning curve against the autopilot's and a random policy's scores."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    steps = np.array([r[0] for r in rows]) / 1e6
    returns = np.array([r[2] for r in rows])
    smooth = np.convolve(returns, np.ones(10) / 10, mode="valid") if len(returns) >= 10 else returns
    fig, ax = plt.subplots(figsize=(6, 3.2), dpi=100)
    ax.plot(steps, returns, color="0.75", lw=0.8, label="PPO, episodes ended per iteration")
    ax.plot(steps[len(steps) - len(smooth):], smooth, color="C0", lw=1.5, label="PPO, mean of 10")
    autopilot, random, score = scores["autopilot"], scores["random"], scores["PPO (mean action)"]
    ax.axhline(autopilot, color="C2", ls="--", label=f"autopilot ({autopilot:.1f})")
    ax.axhline(random, color="C3", ls=":", label=f"random ({random:.1f})")
    ax.plot([steps[-1]], [score], "o", color="C0", label=f"PPO, mean action ({score:.1f})")
    ax.set_xlabel("env steps (millions of 0.1-s steps)")
    ax.set_ylabel("episode return")
    ax.set_title("PPO, attitude mode (CarrierLanding-v1)")
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(f"{out}.png")


if __name__ == "__main__":
    main()
