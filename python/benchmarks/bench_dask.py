"""Speed-up of ``deckland.dask.campaign`` on a local cluster (figures in BENCHMARKS.md).

    python python/benchmarks/bench_dask.py [--runs 2000] [--repeat 3] [--scenario FILE]

Flies the same campaign (``--scenario``, default ``scenarios/heavy-sea.toml``, seed 1, ``--runs`` approaches in
8 shards, one thread per shard) on a ``LocalCluster`` of 1 and of 2 worker processes
with one thread each, alternately, ``--repeat`` times, and prints the runs per second of
each (median) and their ratio. The cluster is started before the clock starts and a
small campaign warms every worker, so the figures are flying, shipping and merging
shards, not starting Python.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import distributed

import deckland
import deckland.dask

SCENARIO = Path(__file__).resolve().parents[2] / "scenarios" / "heavy-sea.toml"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--shards", type=int, default=8)
    parser.add_argument("--scenario", type=Path, default=SCENARIO)
    args = parser.parse_args()
    scenario = deckland.Scenario.from_file(args.scenario)
    clients = {}
    for workers in (1, 2):
        cluster = distributed.LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
        )
        clients[workers] = distributed.Client(cluster)
        deckland.dask.campaign(clients[workers], scenario, 8, seed=1, shards=workers * 2)
    rates = {1: [], 2: []}
    reference = None
    for _ in range(args.repeat):
        for workers, client in clients.items():
            started = time.perf_counter()
            result = deckland.dask.campaign(client, scenario, args.runs, seed=1, shards=args.shards)
            elapsed = time.perf_counter() - started
            rates[workers].append(args.runs / elapsed)
            if reference is None:
                reference = result.runs
            assert result.runs.equals(reference), "the result depends on the workers"
            print(f"{workers} worker(s): {args.runs} runs in {elapsed:.2f} s ({args.runs / elapsed:.1f} runs/s)")
    one, two = statistics.median(rates[1]), statistics.median(rates[2])
    print(f"median: 1 worker {one:.1f} runs/s, 2 workers {two:.1f} runs/s, speed-up {two / one:.2f}x")
    for client in clients.values():
        client.close()


if __name__ == "__main__":
    main()
