"""Benchmarks of the Python package (figures recorded in BENCHMARKS.md).

    python python/benchmarks/bench_python.py [--cli target/release/deckland] [--repeat 20]

Measures, for the default approach (adverse conditions, O-PD, seed 1):

1. ``deckland land --json --no-plots`` as a whole process (the CLI's cost for one
   approach and its files), against ``deckland.fly()`` per call in a running
   interpreter (the package's cost for one approach and its tables), with and without
   pandas; and, for reference, ``python -c "import deckland; deckland.fly()"`` as a
   whole process.
2. The overhead of ``Approach.step``: the CPU time per step of an approach stepped to
   the end from Python, minus the CPU time per control interval of the same approach
   stepped in Rust alone (``deckland._deckland._bench_stepping``: bare integration
   steps, no observation).
3. The cost of a Python pitch law: CPU time per step of an approach flown to the end by
   a Python PD law, minus that of the approach flown by the built-in law.

Whole runs are medians over ``--repeat`` runs; the per-step figures are the fastest of
interleaved runs (what the machine's other load disturbed least). CPU time (user +
system, of this process or of the child process) is given beside wall time, since it
is what a loaded machine changes least.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import deckland

REPOSITORY = Path(__file__).resolve().parents[2]


def children_cpu_s() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def process(command, repeat):
    """Median wall and CPU time (s) of running `command` as a process."""
    walls, cpus = [], []
    for _ in range(repeat):
        cpu0, wall0 = children_cpu_s(), time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        walls.append(time.perf_counter() - wall0)
        cpus.append(children_cpu_s() - cpu0)
    return statistics.median(walls), statistics.median(cpus)


def call(function, repeat):
    """Median wall and CPU time (s) of calling `function`."""
    walls, cpus = [], []
    for _ in range(repeat):
        cpu0, wall0 = time.process_time(), time.perf_counter()
        function()
        walls.append(time.perf_counter() - wall0)
        cpus.append(time.process_time() - cpu0)
    return statistics.median(walls), statistics.median(cpus)


def stepping_overhead_us(repeat, action):
    """Approach.step CPU time per step, bare CPU time per interval, and their difference
    (µs): the fastest of `repeat` interleaved runs of each (the minimum is the run the
    machine's other load disturbed least)."""
    python_runs, bare_runs = [], []
    for _ in range(repeat):
        approach = deckland.Approach(seed=1)
        observation = approach.reset()
        steps = 0
        cpu0 = time.process_time()
        while not observation["done"]:
            observation = approach.step(action)
            steps += 1
        python_runs.append((time.process_time() - cpu0) / steps)
        cpu0 = time.process_time()
        intervals, _ = deckland._deckland._bench_stepping(seed=1)
        bare_runs.append((time.process_time() - cpu0) / intervals)
        assert intervals == steps
    python, bare = min(python_runs), min(bare_runs)
    return python * 1e6, bare * 1e6, (python - bare) * 1e6


def pitch_law(inputs, kp=2.0, kd=0.8):
    """A discrete PD pitch law (as in the tests), which flies the approach to the deck."""
    error = inputs["theta_ref_rad"] - inputs["theta_measured_rad"]
    return inputs["elevator_trim_rad"] - kp * error + kd * inputs["pitch_rate_radps"]


def pitch_law_cost_us(repeat):
    """CPU cost (µs) per step of flying a Python pitch law: the CPU time per step of an
    approach stepped to the end with the law, minus without (both fly the whole approach;
    the simulation's cost per step does not depend on the trajectory); fastest of
    `repeat` interleaved runs of each."""
    per_step = {None: [], pitch_law: []}
    for _ in range(repeat):
        for law in per_step:
            approach = deckland.Approach(seed=1, pitch_law=law)
            observation = approach.reset()
            steps = 0
            cpu0 = time.process_time()
            while not observation["done"]:
                observation = approach.step()
                steps += 1
            per_step[law].append((time.process_time() - cpu0) / steps)
    return (min(per_step[pitch_law]) - min(per_step[None])) * 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(REPOSITORY / "target" / "release" / "deckland"))
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    out = tempfile.mkdtemp(prefix="deckland-bench-")

    print(f"machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f}; Python {sys.version.split()[0]}")
    land = process([args.cli, "land", "--json", "--no-plots", "--out", out, "--force"], args.repeat)
    print(f"deckland land --json --no-plots (whole process): wall {land[0]*1e3:.1f} ms, CPU {land[1]*1e3:.1f} ms")

    deckland.fly()  # import pandas once, outside the measurement
    fly_frame = call(lambda: deckland.fly(), args.repeat)
    deckland._tables.use_pandas = False
    fly_dict = call(lambda: deckland.fly(), args.repeat)
    deckland._tables.use_pandas = True
    for name, (wall, cpu) in (("DataFrame", fly_frame), ("dict of arrays", fly_dict)):
        print(
            f"deckland.fly() per call, {name}: wall {wall*1e3:.1f} ms, CPU {cpu*1e3:.1f} ms"
            f" -> {cpu/land[1]:.2f}x the CLI's CPU, {wall/land[0]:.2f}x its wall time"
        )
    whole = process([sys.executable, "-c", "import deckland; deckland.fly()"], max(3, args.repeat // 4))
    print(f"python -c 'import deckland; deckland.fly()' (whole process): wall {whole[0]*1e3:.1f} ms, CPU {whole[1]*1e3:.1f} ms")

    for label, action in (("action=None", None), ('action={"pitch_command_rad": None}', {"pitch_command_rad": None})):
        python, bare, overhead = stepping_overhead_us(max(5, args.repeat // 2), action)
        print(f"Approach.step({label}): {python:.2f} us per step, bare 20 integration steps {bare:.2f} us -> overhead {overhead:.2f} us")
    print(f"Python pitch law (a PD in Python): {pitch_law_cost_us(max(5, args.repeat // 2)):.2f} us per call")


if __name__ == "__main__":
    main()
