"""The same scenario and seed give the same results, bit for bit; other seeds do not."""

from __future__ import annotations

import copy
import pickle

import numpy as np

import deckland


def assert_same_series(a, b):
    assert list(a.keys()) == list(b.keys())
    for name in a.keys():
        x, y = np.asarray(a[name]), np.asarray(b[name])
        if x.dtype == object:
            assert list(x) == list(y), name
        else:
            assert np.array_equal(x, y, equal_nan=True), name


def test_the_same_seed_flies_the_same_approach():
    first, second = deckland.fly(seed=3), deckland.fly(seed=3)
    assert first.summary == second.summary
    assert first.events == second.events
    assert_same_series(first.time_series, second.time_series)


def test_another_seed_flies_another_approach():
    first, second = deckland.fly(seed=3), deckland.fly(seed=4)
    assert first.summary["end_time_s"] != second.summary["end_time_s"]
    assert not np.array_equal(first.time_series["wind_x_mps"][:100], second.time_series["wind_x_mps"][:100])


def test_the_seed_argument_is_the_scenario_seed():
    scenario = deckland.Scenario.default()
    scenario["seed"] = 8
    assert deckland.fly(scenario).summary == deckland.fly(seed=8).summary


def test_a_campaign_does_not_depend_on_the_number_of_threads():
    scenario = deckland.Scenario.from_file(deckland_scenario("heavy-sea.toml"))
    one = deckland.campaign(scenario, 8, seed=5, threads=1)
    two = deckland.campaign(scenario, 8, seed=5, threads=2)
    assert_same_series(one.runs, two.runs)
    assert one.statistics == two.statistics


def test_a_campaign_row_flown_again_is_that_run():
    scenario = deckland.Scenario.from_file(deckland_scenario("heavy-sea.toml"))
    result = deckland.campaign(scenario, 3, seed=21, threads=2)
    runs = result.runs
    for index in range(3):
        flight = deckland.fly(scenario, seed=int(runs["seed"][index]), disperse=True)
        assert flight.outcome == runs["outcome"][index]
        assert flight.summary["end_time_s"] == runs["end_time_s"][index]


def test_a_pickled_or_copied_scenario_is_the_same_scenario():
    scenario = deckland.Scenario.default()
    scenario["environment.seaway.significant_wave_height_m"] = 2.5
    scenario.name = "calmer"
    for clone in (pickle.loads(pickle.dumps(scenario)), copy.deepcopy(scenario), scenario.copy()):
        assert clone == scenario and clone.name == "calmer"
        assert deckland.fly(clone, seed=2).summary == deckland.fly(scenario, seed=2).summary
    clone["environment.seaway.significant_wave_height_m"] = 3.0
    assert scenario["environment.seaway.significant_wave_height_m"] == 2.5


def deckland_scenario(name):
    from conftest import SCENARIOS

    return SCENARIOS / name
