"""Benchmarks of the Gymnasium environment (figures recorded in BENCHMARKS.md).

    python python/benchmarks/bench_gym.py [--rounds 3] [--seconds 1.0] [--envs 64] [--realtime]

Measures in one run, in env steps per second (one step: one 20-ms control interval,
20 integration steps), the action fixed (zeros: the trim), so that no policy's cost
is counted:

1. the physics alone: ``deckland._deckland._bench_stepping`` (the approach stepped in
   Rust, no observation, no Python);
2. one environment, ``gymnasium.make("deckland/CarrierLanding-v1")`` (``attitude``),
   with its wrappers (the env checker, order enforcing, the time limit);
   and the same with ``env.action_space.sample()`` as the action of each step (a
   random agent's cost, as the issue measured it);
3. gymnasium's ``make_vec(..., vectorization_mode="sync")`` of 2 environments;
4. the native vectorised environment, ``make_vec(..., num_envs=--envs,
   vectorization_mode="vector_entry_point")`` (``attitude``), over every core;
5. the 3-D environment ``deckland/CarrierLanding3D-v0`` (``attitude``, the crosswind
   scenario), one environment through ``gymnasium.make`` and ``--envs`` native
   vectorised ones;
6. ``CartPole-v1`` through ``gymnasium.make``, for scale;
7. ``render()`` with ``render_mode="rgb_array"``, frames per second;
8. reproducibility: 4 vectorised environments against 4 single ones with the same
   seeds over 800 steps with autoresets, bit for bit.

Each figure is the fastest of ``--rounds`` interleaved rounds of ``--seconds`` each
(what the machine's other load disturbed least); the CPU time of the process (user +
system, all threads) is given beside it, since a loaded machine changes it least: for
one thread, steps per CPU second is the speed on an idle core; for the vectorised
environment, twice it is what two idle cores would give.

``--realtime`` (Linux, as root): each round runs with every thread of the process
under the real-time policy ``SCHED_FIFO``, so that the machine's other processes wait
while it runs and the wall figures are those of idle cores; back to the normal policy
between rounds. The rounds are then at most 0.5 s with a 0.5-s pause after each, so
that the kernel's limit on real-time threads (95 % of each second by default,
``/proc/sys/kernel/sched_rt_runtime_us``) never stops them in a round.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import gymnasium
import numpy as np

import deckland
from deckland import _deckland
from deckland.env import ENV_ID
from deckland.env3d import CONTROL_MODES_3D, ENV_ID_3D


def realtime(on):
    """Every thread of the process to ``SCHED_FIFO`` (on) or back to the normal policy."""
    policy, priority = (os.SCHED_FIFO, 10) if on else (os.SCHED_OTHER, 0)
    for thread in os.listdir("/proc/self/task"):
        try:
            os.sched_setscheduler(int(thread), policy, os.sched_param(priority))
        except ProcessLookupError:
            pass  # ended meanwhile


def measure(run, seconds, real_time=False):
    """(steps per wall second, steps per CPU second) of `run(deadline)` -> steps."""
    if real_time:
        realtime(True)
    try:
        wall0, cpu0 = time.perf_counter(), time.process_time()
        steps = run(wall0 + seconds)
        wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    finally:
        if real_time:
            realtime(False)
            time.sleep(0.5)
    return steps / wall, steps / max(cpu, 1e-9)


def physics(deadline):
    steps = 0
    while time.perf_counter() < deadline:
        intervals, _ = _deckland._bench_stepping(None, 1)
        steps += intervals
    return steps


def single(env, action):
    """One environment, the same ``action`` each step."""
    return stepping(env, lambda: action)


def sampled(env):
    """One environment with a fresh ``action_space.sample()`` each step."""
    return stepping(env, env.action_space.sample, seed_actions=True)


def stepping(env, next_action, seed_actions=False):
    """Steps of one environment, each with the action ``next_action()`` returns (from the
    action space seeded with 1 at each round's start if ``seed_actions``)."""

    def run(deadline):
        env.reset(seed=1)
        if seed_actions:
            env.action_space.seed(1)
        steps = 0
        while time.perf_counter() < deadline:
            for _ in range(100):
                _, _, terminated, truncated, _ = env.step(next_action())
                if terminated or truncated:
                    env.reset()
            steps += 100
        return steps

    return run


def vector(envs, actions):
    def run(deadline):
        envs.reset(seed=1)
        steps = 0
        while time.perf_counter() < deadline:
            for _ in range(10):
                envs.step(actions)
            steps += 10 * envs.num_envs
        return steps

    return run


def frames(env):
    def run(deadline):
        env.reset(seed=1)
        for _ in range(300):
            env.step(np.zeros(3, dtype=np.float32))
        count = 0
        while time.perf_counter() < deadline:
            for _ in range(50):
                env.render()
            count += 50
        return count

    return run


def reproducible(steps=800, n=4):
    envs = gymnasium.make_vec(ENV_ID, num_envs=n, vectorization_mode="vector_entry_point")
    actions = np.random.default_rng(3).uniform(-1, 1, size=(steps, n, 3)).astype(np.float32)
    actions[..., 0] = actions[..., 0] * 0.1 - 0.9
    actions[..., 2] = -1.0
    first, _ = envs.reset(seed=100)
    vector_run = [first] + [envs.step(actions[t])[0] for t in range(steps)]
    ends = 0
    for i in range(n):
        env = gymnasium.make(ENV_ID)
        observation, _ = env.reset(seed=100 + i)
        same = np.array_equal(observation, vector_run[0][i])
        ended = False
        for t in range(steps):
            if ended:
                observation, _ = env.reset()
                ended = False
            else:
                observation, _, terminated, truncated, _ = env.step(actions[t, i])
                ended = terminated or truncated
                ends += ended
            same = same and np.array_equal(observation, vector_run[t + 1][i])
        if not same:
            return False, ends
    return True, ends


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=1.0)
    parser.add_argument("--envs", type=int, default=64)
    parser.add_argument("--realtime", action="store_true", help="rounds under SCHED_FIFO (Linux, root)")
    args = parser.parse_args()
    if args.realtime:
        args.seconds = min(args.seconds, 0.5)

    single_env = gymnasium.make(ENV_ID)
    sync = gymnasium.make_vec(ENV_ID, num_envs=2, vectorization_mode="sync")
    native = gymnasium.make_vec(ENV_ID, num_envs=args.envs, vectorization_mode="vector_entry_point")
    width_3d = len(CONTROL_MODES_3D["attitude"])
    single_3d = gymnasium.make(ENV_ID_3D)
    native_3d = gymnasium.make_vec(ENV_ID_3D, num_envs=args.envs, vectorization_mode="vector_entry_point")
    cartpole = gymnasium.make("CartPole-v1")
    rendering = gymnasium.make(ENV_ID, render_mode="rgb_array")
    cases = {
        "physics alone (`_bench_stepping`)": physics,
        "one env, `gymnasium.make`": single(single_env, np.zeros(3, dtype=np.float32)),
        "one env, `gymnasium.make`, `action_space.sample()` each step": sampled(single_env),
        "`make_vec`, sync, 2 envs": vector(sync, np.zeros((2, 3), dtype=np.float32)),
        f"`make_vec`, vector_entry_point, {args.envs} envs": vector(
            native, np.zeros((args.envs, 3), dtype=np.float32)
        ),
        "3-D env, `gymnasium.make`": single(single_3d, np.zeros(width_3d, dtype=np.float32)),
        f"3-D env, `make_vec`, vector_entry_point, {args.envs} envs": vector(
            native_3d, np.zeros((args.envs, width_3d), dtype=np.float32)
        ),
        "CartPole-v1, `gymnasium.make`": single(cartpole, 0),
        "`render()`, rgb_array (frames/s)": frames(rendering),
    }
    best = {name: (0.0, 0.0) for name in cases}
    for _ in range(args.rounds):
        for name, run in cases.items():
            wall, cpu = measure(run, args.seconds, args.realtime)
            best[name] = (max(best[name][0], wall), max(best[name][1], cpu))
    same, ends = reproducible()

    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.1f}; deckland {deckland.__version__}, "
          f"gymnasium {gymnasium.__version__}, numpy {np.__version__}")
    policy = ", SCHED_FIFO" if args.realtime else ""
    print(f"rounds {args.rounds} x {args.seconds} s{policy}, fastest round\n")
    print("| what | per wall second | per CPU second |")
    print("|---|---|---|")
    for name, (wall, cpu) in best.items():
        print(f"| {name} | {wall:,.0f} | {cpu:,.0f} |")
    print(f"\nvectorised == single, bit for bit (4 envs, 800 steps, {ends} episode ends): {same}")


if __name__ == "__main__":
    main()
