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
    assert list(runs)[-6] == "deck_within_limits_pct"
    deck = runs["deck_within_limits_pct"]
    flown = deck[~np.isnan(deck)]
    assert deck.dtype == np.float64 and len(flown) >= 1
    assert np.all((flown >= 0.0) & (flown <= 100.0))
    shares = result.statistics[0]["deck_within_limits_pct"]
    assert shares["count"] == len(flown)
    assert abs(shares["mean"] - float(np.mean(flown))) < 1e-9
    assert shares["min"] == float(np.min(flown))
    # The probabilities the forecast gave at the commit point: three columns before the
    # last two, in [0, 1] (NaN for a run that never reached it), summed and counted per
    # criterion in the summary's calibration.
    names = ["commit_ramp_strike_probability", "commit_hard_landing_probability",
             "commit_off_centre_probability"]
    assert list(runs)[-5:-2] == names
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
    # Last, the clearance the ramp strike's probability is taken on and its σ, there
    # exactly where the probability is; the summary's standardised error of the clearance
    # flown against them, recomputed here with numpy.
    assert list(runs)[-2:] == ["commit_ramp_clearance_m", "commit_ramp_clearance_sigma_m"]
    c, sigma = runs["commit_ramp_clearance_m"], runs["commit_ramp_clearance_sigma_m"]
    assert np.array_equal(np.isnan(c), np.isnan(ramp))
    assert np.array_equal(np.isnan(sigma), np.isnan(ramp))
    flown = runs["ramp_clearance_m"]
    both = ~np.isnan(c) & ~np.isnan(flown) & (np.nan_to_num(sigma) > 0.0)
    z = (flown[both] - c[both]) / sigma[both]
    error = calibration["ramp_clearance_error"]
    if len(z) >= 2:
        assert error["runs"] == len(z)
        assert abs(error["mean"] - float(np.mean(z))) < 1e-9
        assert abs(error["sd"] - float(np.std(z, ddof=1))) < 1e-9
    else:
        assert error is None
