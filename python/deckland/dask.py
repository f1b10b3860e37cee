"""Campaigns and rare-event estimates on a Dask cluster.

Campaigns: the shards of one campaign flown by Dask workers.

:func:`campaign` splits a campaign into shards (shard K of M flies the runs i with
i mod M = K), maps them over a ``dask.distributed`` cluster — each task calls the
compiled core to fly one shard and returns its rows — and merges the shards with the
same Rust code as ``deckland merge``. Run i depends only on the campaign seed and i, so
the result is :func:`deckland.campaign`'s, bit for bit, on any cluster: the code here
only sees a :class:`distributed.Client`, whether it talks to a ``LocalCluster``, to
Slurm or PBS through ``dask-jobqueue``, or to Kubernetes through ``dask-kubernetes``
(python/README.md shows each).

Rare events: :func:`rare` flies each batch of splitting's independent repetitions as
Dask tasks, one repetition a task, and drives the estimate with the same Rust code as
:func:`deckland.rare`: repetition r depends only on the scenario, the request and r, so
the estimate is :func:`deckland.rare`'s, bit for bit.

Needs the ``dask`` extra (``pip install "deckland[dask]"``) here and deckland installed
on every worker.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, List, Optional, Union

from . import Campaign, Figures, PathLike, Scenario, _deckland, _flag, _path, progress_callback
from ._tables import table

__all__ = ["campaign", "rare"]


def _fly_shard(
    index: int,
    scenario: Scenario,
    runs: int,
    count: int,
    seed: Optional[int],
    threads: int,
    compare: bool,
) -> str:
    """One task: flies shard ``index``/``count`` on a worker; the shard as text."""
    return _deckland.campaign_shard(scenario, runs, index, count, seed, threads, compare)


def campaign(
    client: Any,
    scenario: Scenario,
    runs: int,
    seed: Optional[int] = None,
    shards: Optional[int] = None,
    *,
    compare: bool = False,
    threads_per_shard: int = 1,
    progress: Union[bool, Callable[[int, int], Any], None] = None,
    out: Optional[PathLike] = None,
    force: bool = False,
    figures: Optional[Figures] = None,
) -> Campaign:
    """Flies ``runs`` approaches of ``scenario`` as shards on the cluster of ``client``.

    ``shards`` defaults to the number of worker threads of the cluster (at most
    ``runs``); more shards than workers balance uneven workers better. Each shard flies
    on ``threads_per_shard`` threads of its worker (1: Dask's threads are the
    parallelism). ``seed`` and ``compare`` are :func:`deckland.campaign`'s.

    Returns the :class:`deckland.Campaign` (``runs``, ``summary``; it unpacks as
    ``runs, summary = ...``) that :func:`deckland.campaign` returns for the same
    arguments, except the timing keys of the summary; ``summary["merged_from"]`` names
    the shards. Raises ``ValueError`` if a shard comes back partial (a worker stopped)
    or does not belong to the campaign.

    ``progress`` is :func:`deckland.campaign`'s, counted as the shards come back:
    ``True`` writes a line to stderr at each tenth of the runs, a callable is called as
    ``progress(done, total)`` with the runs of the shards finished so far.

    With ``out``, the merged campaign's folder is written there (on the client's
    machine), as ``deckland merge`` writes it: :func:`deckland.campaign`'s ``out``,
    ``force`` and ``figures``.
    """
    out, force = _path(out), _flag("force", force)
    if not isinstance(runs, int) or isinstance(runs, bool) or not 1 <= runs <= _deckland.MAX_RUNS:
        raise ValueError(f"`runs` = {runs!r} is not allowed: expected a whole number in [1, {_deckland.MAX_RUNS}]")
    if shards is None:
        shards = max(1, sum(client.nthreads().values()))
    if not isinstance(shards, int) or isinstance(shards, bool) or shards < 1:
        raise ValueError(f"shards = {shards!r}: expected a whole number ≥ 1")
    shards = min(shards, runs)
    futures = client.map(
        _fly_shard,
        list(range(shards)),
        scenario=scenario,
        runs=runs,
        count=shards,
        seed=seed,
        threads=threads_per_shard,
        compare=compare,
        pure=False,
    )
    report = progress_callback(progress, "dask campaign")
    if report is not None:
        _report_shards(futures, runs, shards, 2 if compare else 1, report)
    texts = client.gather(futures)
    columns, summary, folder = _deckland.merge_shards_text(list(texts), out, force, figures)
    return Campaign(runs=table(columns), summary=summary, folder=folder)


def _report_shards(
    futures: Any, runs: int, shards: int, controllers: int, report: Callable[[int, int], Any]
) -> None:
    """Calls ``report(done, total)`` as each shard's future completes, with the runs of
    the finished shards (shard K of M flies the runs i < ``runs`` with i mod M = K)."""
    from distributed import as_completed

    index = {future.key: k for k, future in enumerate(futures)}
    total = runs * controllers
    done = 0
    report(0, total)
    for future in as_completed(futures):
        k = index[future.key]
        done += (runs - k + shards - 1) // shards * controllers
        report(done, total)



def _fly_repetition(
    repetition: int,
    scenario: Scenario,
    event: str,
    share: int,
    threshold: Optional[float],
    particles: Optional[int],
    seed: Optional[int],
    threads: int,
    calibrate_score: Optional[int] = None,
) -> Any:
    """One task: repetition ``repetition`` of the estimate, on a worker."""
    return _deckland.rare_repetition(
        scenario, event, repetition, share, threshold, particles, seed, threads, calibrate_score
    )


def rare(
    client: Any,
    scenario: Scenario,
    event: str,
    threshold: Optional[float] = None,
    target_rel_error: Optional[float] = None,
    max_runs: Optional[int] = None,
    particles: Optional[int] = None,
    seed: Optional[int] = None,
    *,
    calibrate_score: Optional[int] = None,
    threads_per_task: int = 1,
    progress: Union[bool, Callable[[int, int], Any], None] = None,
) -> Dict[str, Any]:
    """:func:`deckland.rare` on the cluster of ``client``: the probability per approach of
    ``event`` by splitting, each repetition a Dask task.

    The arguments are :func:`deckland.rare`'s; each task flies one repetition on
    ``threads_per_task`` threads of its worker (with ``calibrate_score``, each task flies
    the calibration's flights again: the calibration is a function of the scenario and the
    request, so every task's is the same). Returns the dict that
    :func:`deckland.rare` returns for the same arguments, bit for bit. Splitting decides
    after each batch of 8 repetitions whether the target is met, so the cluster keeps at
    most 8 tasks busy; larger clusters pay off through ``threads_per_task``.

    ``progress``: ``True`` writes a line to stderr at each batch, a callable is called as
    ``progress(done, None)`` with the repetitions finished so far (the total is not known
    in advance: splitting stops at the target).
    """
    if progress is True:
        report: Optional[Callable[[int, Any], Any]] = _repetition_lines()
    elif progress is None or progress is False or callable(progress):
        report = progress or None
    else:
        raise TypeError(
            f"`progress` = {progress!r}: expected True, False, None or a callable progress(done, total)"
        )
    done = [0]

    def run_batch(first: int, size: int, share: int) -> List[Any]:
        futures = client.map(
            _fly_repetition,
            list(range(first, first + size)),
            scenario=scenario,
            event=event,
            share=share,
            threshold=threshold,
            particles=particles,
            seed=seed,
            threads=threads_per_task,
            calibrate_score=calibrate_score,
            pure=False,
        )
        runs = client.gather(futures)
        done[0] += size
        if report is not None:
            report(done[0], None)
        return runs

    return _deckland.rare_batched(
        scenario, event, run_batch, threshold, target_rel_error, max_runs, particles, seed, calibrate_score
    )


def _repetition_lines() -> Callable[[int, Any], None]:
    """Writes ``dask rare: N repetitions, t s`` to stderr after each batch."""
    import sys
    import time

    started = time.monotonic()

    def report(done: int, _total: Any) -> None:
        print(f"dask rare: {done} repetitions, {time.monotonic() - started:.0f} s", file=sys.stderr, flush=True)

    return report
