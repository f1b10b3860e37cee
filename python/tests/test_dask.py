"""Shards, merges and Dask: ``deckland.dask.campaign`` on a local cluster of two worker
processes is ``deckland.campaign``, bit for bit; the CLI's ``runs.parquet`` reads as its
``runs.csv``; the rare-event bounds match scipy's beta quantiles (an independent
implementation: Clopper–Pearson's bound is the beta distribution's 95 % quantile);
``deckland.dask.rare`` is ``deckland.rare``, bit for bit."""

from __future__ import annotations

import math
import shutil

import pytest

import deckland
from conftest import SCENARIOS

pd = pytest.importorskip("pandas")
distributed = pytest.importorskip("distributed")
import deckland.dask  # noqa: E402  (after the skip: needs dask)

# How the campaign was flown, not what it found: differs between front ends.
EXECUTION = {"threads", "elapsed_s", "runs_per_s", "merged_from"}


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    with distributed.Client(cluster) as dask_client:
        yield dask_client
    cluster.close()


def test_a_local_cluster_gives_the_single_machine_campaign(client):
    scenario = deckland.Scenario.from_file(SCENARIOS / "heavy-sea.toml")
    expected = deckland.campaign(scenario, 17, seed=11, threads=2, compare=True)
    runs, summary = deckland.dask.campaign(client, scenario, 17, seed=11, shards=3, compare=True)
    assert len(runs) == 34
    pd.testing.assert_frame_equal(runs, expected.runs, check_exact=True)
    assert set(summary) == set(expected.summary)
    for key in set(summary) - EXECUTION:
        assert summary[key] == expected.summary[key], key
    assert summary["merged_from"] == ["shard 0/3", "shard 1/3", "shard 2/3"]
    assert summary["partial"] is False


def test_a_three_d_campaign_merged_from_shards_keeps_its_lateral_columns(client):
    scenario = deckland.Scenario.from_file(SCENARIOS / "crosswind.toml")
    expected = deckland.campaign(scenario, 4, seed=3, threads=2)
    runs, summary = deckland.dask.campaign(client, scenario, 4, seed=3, shards=2)
    assert "ramp_lineup_error_deg" in runs.columns and "trap_ar_lineup_mean_m" in runs.columns
    pd.testing.assert_frame_equal(runs, expected.runs, check_exact=True)
    assert {"lateral", "trap_sheet"} <= set(summary)
    for key in set(summary) - EXECUTION:
        assert summary[key] == expected.summary[key], key


def test_a_dask_campaign_writes_the_folder_of_the_campaign_flown_whole(client, tmp_path):
    # The merged folder is the one `deckland.campaign(out=...)` writes, apart from how
    # the campaign was flown (summary.json's and report.html's timing and shard names).
    scenario = deckland.Scenario.from_file(SCENARIOS / "crosswind.toml")
    whole = deckland.campaign(scenario, 4, seed=3, threads=2, out=tmp_path / "whole")
    merged = deckland.dask.campaign(client, scenario, 4, seed=3, shards=2, out=tmp_path / "dask")
    assert merged.folder == str(tmp_path / "dask")
    names = sorted(p.name for p in (tmp_path / "whole").iterdir())
    assert sorted(p.name for p in (tmp_path / "dask").iterdir()) == names
    for name in names:
        if name.endswith((".csv", ".parquet", ".toml", ".svg", ".png")):
            assert (tmp_path / "dask" / name).read_bytes() == (tmp_path / "whole" / name).read_bytes(), name
    assert whole.folder == str(tmp_path / "whole")


def test_the_default_shards_are_the_workers_and_the_seed_the_scenarios(client):
    scenario = deckland.Scenario.from_file(SCENARIOS / "heavy-sea.toml")
    result = deckland.dask.campaign(client, scenario, 5)
    assert len(result.summary["merged_from"]) == 2
    expected = deckland.campaign(scenario, 5, threads=1)
    pd.testing.assert_frame_equal(result.runs, expected.runs, check_exact=True)


def test_bad_arguments_and_foreign_shards_are_refused(client):
    scenario = deckland.Scenario.from_file(SCENARIOS / "heavy-sea.toml")
    for runs in (0, -3, 2.5, True, deckland.MAX_RUNS + 1):
        with pytest.raises(ValueError, match="runs"):
            deckland.dask.campaign(client, scenario, runs)
    with pytest.raises(ValueError, match="shards"):
        deckland.dask.campaign(client, scenario, 4, shards=0)
    zero = deckland._deckland.campaign_shard(scenario, 4, 0, 2, seed=1)
    one = deckland._deckland.campaign_shard(scenario, 4, 1, 2, seed=1)
    other_seed = deckland._deckland.campaign_shard(scenario, 4, 1, 2, seed=2)
    deckland._deckland.merge_shards_text([one, zero])
    with pytest.raises(ValueError, match="missing shard 1/2"):
        deckland._deckland.merge_shards_text([zero])
    with pytest.raises(ValueError, match="both shard 0/2"):
        deckland._deckland.merge_shards_text([zero, zero, one])
    with pytest.raises(ValueError, match="`campaign_seed` is 2 there and 1"):
        deckland._deckland.merge_shards_text([zero, other_seed])
    with pytest.raises(ValueError, match="index"):
        deckland._deckland.campaign_shard(scenario, 4, 2, 2)


def test_runs_parquet_reads_as_runs_csv(cli, tmp_path):
    pytest.importorskip("pyarrow")
    shutil.copy(SCENARIOS / "heavy-sea.toml", tmp_path / "heavy-sea.toml")
    out = tmp_path / "campaign"
    cli.run(
        ["campaign", "heavy-sea.toml", "--runs", "12", "--seed", "3", "--compare", "--json", "--out", str(out)],
        cwd=tmp_path,
    )
    from_csv = pd.read_csv(out / "runs.csv")
    from_parquet = pd.read_parquet(out / "runs.parquet")
    assert list(from_parquet.columns) == list(from_csv.columns)
    assert len(from_parquet) == 24
    for name in from_csv.columns:
        csv_column, parquet_column = from_csv[name], from_parquet[name]
        if csv_column.isna().all():
            # An empty CSV column reads as float NaN; Parquet keeps its type (text).
            assert parquet_column.isna().all(), name
            continue
        pd.testing.assert_series_equal(parquet_column, csv_column, check_exact=True, obj=name)


def test_rare_event_bounds_match_scipy(cli, tmp_path):
    beta = pytest.importorskip("scipy.stats").beta
    scenario = deckland.Scenario.from_file(SCENARIOS / "heavy-sea.toml")
    summary = deckland.campaign(scenario, 40, seed=5, threads=2).summary
    classes = ["boarding", "bolter", "ramp_strike", "hard_landing", "divergence", "timeout", "invalid"]
    for statistics in summary["controllers"]:
        n = statistics["runs"]
        for name in classes:
            k = statistics[name]["count"]
            expected = 1.0 if k >= n else beta.ppf(0.95, k + 1, n - k)
            assert statistics[name]["upper_bound_95"] == pytest.approx(expected, rel=1e-9, abs=1e-15), name
    # With no event: 1 - 0.05^(1/n) ≈ 3/n, the rule of three.
    assert beta.ppf(0.95, 1, 40) == pytest.approx(1 - 0.05 ** (1 / 40), rel=1e-12)

    def runs_needed(events: int, target: float = 1e-4) -> int:
        low, high = events + 1, 10**7
        while high - low > 1:
            middle = (low + high) // 2
            if beta.ppf(0.95, events + 1, middle - events) < target:
                high = middle
            else:
                low = middle
        return high

    needed = {n["events"]: n["runs"] for n in summary["rare_event_target"]["runs_needed"]}
    assert summary["rare_event_target"]["rate"] == 1e-4
    assert needed[0] == math.ceil(math.log(0.05) / math.log(1 - 1e-4))
    for events in (1, 2, 3):
        assert needed[events] == runs_needed(events), events


def test_a_dask_campaign_reports_its_shards_as_they_come_back(client, capsys):
    # The callable sees the runs of the finished shards, from 0 to all of them (2 × 5
    # with --compare); True writes deckland campaign's lines to stderr.
    scenario = deckland.Scenario.from_file(SCENARIOS / "heavy-sea.toml")
    calls = []
    deckland.dask.campaign(
        client, scenario, 5, seed=1, shards=3, compare=True, progress=lambda d, t: calls.append((d, t))
    )
    assert calls[0] == (0, 10) and calls[-1] == (10, 10)
    assert len(calls) == 4 and all(a[0] <= b[0] for a, b in zip(calls, calls[1:]))
    deckland.dask.campaign(client, scenario, 5, seed=1, shards=2, progress=True)
    assert "dask campaign: 5/5 runs (100 %)" in capsys.readouterr().err


@pytest.mark.parametrize("calibrate_score", [0, 4])
def test_a_dask_rare_estimate_is_the_single_machine_one(client, calibrate_score):
    # Splitting's repetitions flown as tasks on two worker processes: the same estimate,
    # interval, levels and flights that reached the event, to the bit, as on one machine;
    # with the ramp's score plain and calibrated (each task calibrates it again).
    scenario = deckland.Scenario.from_file(SCENARIOS / "paper-adverse.toml")
    request = dict(threshold=1.0, particles=8, max_runs=150, seed=4, calibrate_score=calibrate_score)
    expected = deckland.rare(scenario, "ramp_strike", threads=1, **request)
    seen = []
    actual = deckland.dask.rare(
        client, scenario, "ramp_strike", progress=lambda done, total: seen.append(done), **request
    )
    assert actual == expected
    assert 0.0 < actual["estimate"]["probability"] < 1.0
    assert len(actual["levels"]) == actual["estimate"]["repetitions"] + actual["estimate"]["partial_repetitions"]
    assert seen and seen == sorted(seen) and seen[-1] == len(actual["levels"])


def test_a_failing_dask_rare_batch_raises_its_error(client):
    scenario = deckland.Scenario.paper()

    def broken(first, size, share):
        raise RuntimeError(f"worker lost at repetition {first}")

    with pytest.raises(RuntimeError, match="worker lost at repetition 0"):
        deckland._deckland.rare_batched(scenario, "ramp_strike", broken, 1.0, None, 150, 8, 4)
    with pytest.raises(ValueError, match="other than a run"):
        deckland._deckland.rare_batched(
            scenario, "ramp_strike", lambda first, size, share: [None] * size, 1.0, None, 150, 8, 4
        )
