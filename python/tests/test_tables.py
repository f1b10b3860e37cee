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
    # The share of each run's time with the deck within the recovery limits: the last
    # column, a number in [0, 100] for every flown run, and its mean and least in the
    # summary.
    assert list(runs)[-1] == "deck_within_limits_pct"
    deck = runs["deck_within_limits_pct"]
    flown = deck[~np.isnan(deck)]
    assert deck.dtype == np.float64 and len(flown) >= 1
    assert np.all((flown >= 0.0) & (flown <= 100.0))
    shares = result.statistics[0]["deck_within_limits_pct"]
    assert shares["count"] == len(flown)
    assert abs(shares["mean"] - float(np.mean(flown))) < 1e-9
    assert shares["min"] == float(np.min(flown))
