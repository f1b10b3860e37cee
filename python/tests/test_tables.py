"""Tables are pandas DataFrames with pandas, dicts of numpy arrays without."""

from __future__ import annotations

import numpy as np
import pandas

import deckland


def test_the_time_series_is_a_dataframe_or_a_dict_of_the_same_arrays():
    frame = deckland.fly(seed=2).time_series
    assert isinstance(frame, pandas.DataFrame)
    deckland._tables.use_pandas = False
    arrays = deckland.fly(seed=2).time_series
    assert isinstance(arrays, dict)
    assert list(arrays) == list(frame.columns)
    for name, column in arrays.items():
        assert isinstance(column, np.ndarray)
        assert np.array_equal(column, frame[name].to_numpy(), equal_nan=True), name


def test_campaign_columns_have_the_types_of_their_values():
    scenario = deckland.Scenario.default()
    deckland._tables.use_pandas = False
    result = deckland.campaign(scenario, 3, seed=1)
    runs = result.runs
    assert runs["run_index"].dtype == np.int64 and list(runs["run_index"]) == [0, 1, 2]
    assert runs["seed"].dtype == np.int64
    assert runs["touchdown_distance_m"].dtype == np.float64
    assert runs["wire"].dtype == np.float64
    assert runs["outcome"].dtype == object and all(isinstance(o, str) for o in runs["outcome"])
    # Text columns are str or None; a column with no value at all is NaN, as
    # pandas.read_csv reads an empty column of runs.csv.
    reasons = runs["reason"]
    assert reasons.dtype == object or np.all(np.isnan(reasons))
    # The share of each run's time with the deck within the recovery limits: a number in
    # [0, 100] for every flown run, and its mean and least in the summary.
    assert list(runs)[-4] == "deck_within_limits_pct"
    deck = runs["deck_within_limits_pct"]
    flown = deck[~np.isnan(deck)]
    assert deck.dtype == np.float64 and len(flown) >= 1
    assert np.all((flown >= 0.0) & (flown <= 100.0))
    shares = result.statistics[0]["deck_within_limits_pct"]
    assert shares["count"] == len(flown)
    assert abs(shares["mean"] - float(np.mean(flown))) < 1e-9
    assert shares["min"] == float(np.min(flown))
    # The probabilities the forecast gave at the commit point: the last three columns, in
    # [0, 1] (NaN for a run that never reached it), summed and counted per criterion in
    # the summary's calibration.
    names = ["commit_ramp_strike_probability", "commit_hard_landing_probability",
             "commit_off_centre_probability"]
    assert list(runs)[-3:] == names
    calibration = result.statistics[0]["calibration"]
    ramp = runs["commit_ramp_strike_probability"]
    reached = ramp[~np.isnan(ramp)]
    assert calibration["runs_at_commit"] == len(reached)
    for name, key, outcome in [
        (names[0], "ramp_strike", "ramp_strike"),
        (names[1], "hard_landing", "hard_landing"),
    ]:
        p = runs[name][~np.isnan(ramp)]
        assert np.all((p >= 0.0) & (p <= 1.0))
        if len(reached) > 0:
            criterion = calibration[key]
            assert abs(criterion["expected_events"] - float(np.sum(p))) < 1e-12
            observed = sum(1 for o, r in zip(runs["outcome"], ramp) if o == outcome and r == r)
            assert criterion["observed_events"] == observed
