"""Scenario keys by dotted path, round trips through TOML."""

from __future__ import annotations

import pytest

import deckland


def test_keys_are_read_and_set_by_dotted_path():
    scenario = deckland.Scenario.default()
    # The default ship is the carrier in a seaway, which sets its own RMS: the filter
    # ship's keys are refused until the filters are chosen.
    with pytest.raises(ValueError, match="environment.ship.heave_rms_m"):
        scenario["environment.ship.heave_rms_m"] = 1.0
    scenario["environment.ship.model"] = "filters"
    scenario["environment.ship.heave_rms_m"] = 1.0
    assert scenario["environment.ship.heave_rms_m"] == 1.0
    assert scenario["environment.ship"]["heave_rms_m"] == 1.0
    scenario["environment.deck.wire_positions_m"] = [-20.0, -7.0, 7.0, 20.0]
    assert scenario["environment.deck.wire_positions_m"] == [-20.0, -7.0, 7.0, 20.0]
    scenario["seed"] = 42
    assert scenario["seed"] == 42 and isinstance(scenario["seed"], int)
    assert "environment.ship.heave_rms_m" in scenario
    assert "environment.ship.swell" not in scenario


def test_every_key_round_trips_through_the_scenario_file():
    scenario = deckland.Scenario.default()
    scenario["control.pitch"] = {"type": "pid"}
    scenario["approach.start_height_offset_m"] = 3.0
    again = deckland.Scenario.from_toml(scenario.to_toml())
    assert again == scenario
    keys = scenario.keys()
    assert "control.pitch.type" in keys and "approach.start_range_m" in keys
    for key in keys:
        assert again[key] == scenario[key]


def test_a_section_switches_whole():
    scenario = deckland.Scenario.default()
    assert scenario["control.pitch.type"] == "observer_pd"
    scenario["control.pitch"] = {"type": "pid"}
    assert scenario["control.pitch.type"] == "pid"
    assert repr(scenario) == 'Scenario(name="adverse", seed=1, pitch_law="PID")'


def test_an_integer_is_taken_for_a_float_key():
    scenario = deckland.Scenario.default()
    scenario["approach.start_range_m"] = 1200
    assert scenario["approach.start_range_m"] == 1200.0


def test_the_six_dof_model_is_selected_by_its_key_and_flies_the_three_dof_path():
    """`aircraft.model = "6dof"` flies the 6-DOF aircraft; in the 3-DOF's environment
    (`approach.three_dimensional = false`), every disturbance longitudinal, its lateral
    states stay at rest and it flies the 3-DOF trajectory (docs/model.md §2.10; the
    library's reduction test asserts 1e-9 on every state)."""
    import numpy as np

    # The 3-DOF behind a stationary ship (the default is the 3-D approach, the 6-DOF
    # behind a steaming ship), and the 6-DOF in the same environment.
    longitudinal = deckland.Scenario.default()
    longitudinal["aircraft.model"] = "3dof"
    longitudinal["environment.ship.forward_speed_mps"] = 0.0
    six = longitudinal.copy()
    six["aircraft.model"] = "6dof"
    six["approach.three_dimensional"] = False
    assert six["aircraft.model"] == "6dof"
    three = deckland.fly(longitudinal, seed=3)
    flown = deckland.fly(six, seed=3)
    assert flown.summary["outcome"] == three.summary["outcome"]
    for column in ("altitude_m", "theta_deg", "elevator_deg"):
        a = np.asarray(three.time_series[column])
        b = np.asarray(flown.time_series[column])
        assert a.shape == b.shape
        assert np.max(np.abs(a - b)) <= 1e-9 * max(1.0, float(np.max(np.abs(a)))), column
    with pytest.raises(ValueError, match="aircraft.model"):
        six["aircraft.model"] = "7dof"
