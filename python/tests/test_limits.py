"""Inputs beyond their physical range raise ``ValueError`` naming the field, the value
and the range: never an infinity.

The ranges are computed here from the scenario's own parameters in degrees and per
engine (not read back from the package), and the regression tests are named after the
defects they pin (the hardening round's D10)."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import deckland


def physical_ranges(scenario):
    """Each action key's range from the scenario's parameters (degrees, per engine)."""
    return {
        "pitch_command_rad": (-math.pi / 2, math.pi / 2),
        "elevator_rad": (
            math.radians(scenario["aircraft.elevator_actuator.min_deflection_deg"]),
            math.radians(scenario["aircraft.elevator_actuator.max_deflection_deg"]),
        ),
        "thrust_n": (0.0, 2 * scenario["aircraft.engines.max_thrust_per_engine_n"]),
    }


def test_the_action_ranges_are_the_surfaces_travel_and_the_commands_envelope():
    scenario = deckland.Scenario.default()
    scenario["aircraft.elevator_actuator.min_deflection_deg"] = -20.0
    approach = deckland.Approach(scenario)
    expected = physical_ranges(scenario)
    assert approach.action_ranges.keys() == expected.keys()
    for key, (low, high) in expected.items():
        assert approach.action_ranges[key] == pytest.approx((low, high), rel=1e-15), key


BEYOND = [
    ("pitch_command_rad", 1e308),  # D10: gave elevator_command_rad = -inf
    ("pitch_command_rad", -2.0),
    ("elevator_rad", 5.0),  # D10: 286° was taken without a word
    ("elevator_rad", math.radians(-25.5)),
    ("thrust_n", -1.0),
    ("thrust_n", 1e9),
    ("thrust_n", math.inf),
    ("pitch_command_rad", -math.inf),
    ("elevator_rad", math.nan),
]


@pytest.mark.parametrize("key,value", BEYOND)
def test_regression_d10_an_action_beyond_its_range_is_refused_naming_it(key, value):
    approach = deckland.Approach(seed=1)
    approach.reset()
    low, high = physical_ranges(approach.scenario)[key]
    with pytest.raises(ValueError) as raised:
        approach.step({key: value})
    message = str(raised.value)
    shown = re.search(rf"`action {key}` = (\S+) is not allowed", message)
    assert shown, message
    assert float(shown.group(1)) == value or (math.isnan(value) and math.isnan(float(shown.group(1))))
    bounds = re.search(r"in \[(\S+), (\S+)\]", message)
    assert bounds, message
    assert (float(bounds.group(1)), float(bounds.group(2))) == pytest.approx((low, high), rel=1e-15)
    # The approach did not move.
    assert approach.time_s == 0.0


def test_actions_at_the_edges_of_their_ranges_fly_without_infinities():
    for key in ("pitch_command_rad", "elevator_rad", "thrust_n"):
        for edge in (0, 1):
            approach = deckland.Approach(seed=1)
            approach.reset()
            value = physical_ranges(approach.scenario)[key][edge]
            for _ in range(100):
                observation = approach.step({key: value})
            numbers = [v for v in observation.values() if isinstance(v, float)]
            assert not any(math.isinf(v) for v in numbers), (key, value, observation)


def test_regression_d10_action_for_refuses_commands_beyond_their_range():
    env = pytest.importorskip("deckland.env").CarrierLandingEnv()
    env.reset(seed=1)
    trim = env.approach.trim
    for pitch, thrust, named in [
        (math.nan, math.inf, "pitch_command_rad"),
        (trim["theta_rad"], math.inf, "thrust_n"),
        (2.0, trim["thrust_n"], "pitch_command_rad"),
        (trim["theta_rad"], -5.0, "thrust_n"),
    ]:
        with pytest.raises(ValueError, match=f"`{named}` = "):
            env.action_for(pitch, thrust)
    # Within the physical range but beyond the space's reach: the space's edge.
    action = env.action_for(trim["theta_rad"] + 0.5, trim["max_thrust_n"])
    assert action.tolist() == [1.0, 1.0]


def test_regression_d10_the_environment_refuses_actions_outside_its_space():
    env = pytest.importorskip("deckland.env").CarrierLandingEnv()
    env.reset(seed=1)
    for action in ([1.5, 0.0], [0.0, -1.01], [math.nan, 0.0], [0.0, math.inf], [0.0], "up"):
        with pytest.raises(ValueError, match=r"`action` = .*\[-1, 1\]"):
            env.step(np.asarray(action, dtype=object) if isinstance(action, str) else np.array(action))
    assert env.approach.time_s == 0.0
    # The edges are in the space.
    env.step(np.array([1.0, -1.0], dtype=np.float32))


def test_a_pitch_span_beyond_the_pitch_range_is_refused():
    environment = pytest.importorskip("deckland.env")
    with pytest.raises(ValueError, match="`pitch_command_span_rad` = 2.0 is not allowed"):
        environment.CarrierLandingEnv(pitch_command_span_rad=2.0)
