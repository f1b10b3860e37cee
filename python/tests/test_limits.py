"""Inputs beyond their physical range or the campaign's limits raise ``ValueError``
naming the field, the value and the range: never a panic, an abort or an infinity.

The ranges are computed here from the scenario's own parameters in degrees and per
engine (not read back from the package), and the regression tests are named after the
defects they pin (the hardening round's D1, D2 and D10)."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

import deckland
import deckland._deckland as core

#: The campaign's limit on runs, as `deckland campaign --runs` documents it.
CLI_MAX_RUNS = 100_000


def physical_ranges(scenario):
    """Each action key's range from the scenario's parameters (degrees, per engine); a
    3-D approach adds the lateral keys, as the `Approach` documentation gives them."""
    ranges = {
        "pitch_command_rad": (-math.pi / 2, math.pi / 2),
        "elevator_rad": (
            math.radians(scenario["aircraft.elevator_actuator.min_deflection_deg"]),
            math.radians(scenario["aircraft.elevator_actuator.max_deflection_deg"]),
        ),
        "thrust_n": (0.0, 2 * scenario["aircraft.engines.max_thrust_per_engine_n"]),
    }
    # `approach.three_dimensional` is true, the default (a scenario lists it only when false).
    if scenario["aircraft.model"] == "6dof":
        aileron = math.radians(scenario["aircraft.aileron_actuator.travel_deg"])
        rudder = math.radians(scenario["aircraft.rudder_actuator.travel_deg"])
        ranges.update(
            bank_command_rad=(-math.pi / 2, math.pi / 2),
            sideslip_command_rad=(-math.radians(30.0), math.radians(30.0)),
            aileron_rad=(-aileron, aileron),
            rudder_rad=(-rudder, rudder),
        )
    return ranges


@pytest.mark.parametrize("model", ["6dof", "3dof"])
def test_the_action_ranges_are_the_surfaces_travel_and_the_commands_envelope(model):
    # The default, the 3-D approach, and the longitudinal approach behind a still ship.
    scenario = deckland.Scenario.default()
    if model == "3dof":
        scenario["aircraft.model"] = "3dof"
        scenario["environment.ship.forward_speed_mps"] = 0.0
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


def test_regression_d10_the_environment_refuses_actions_outside_its_space():
    env = pytest.importorskip("deckland.env").CarrierLandingEnv()
    env.reset(seed=1)
    for action in ([1.5, 0.0, 0.0], [0.0, -1.01, 0.0], [math.nan, 0.0, 0.0], [0.0, math.inf, 0.0], [0.0], "up"):
        with pytest.raises(ValueError, match=r"`action` = .*"):
            env.step(np.asarray(action, dtype=object) if isinstance(action, str) else np.array(action))
    assert env.unwrapped._core.time_s == 0.0
    # The edges are in the space.
    env.step(np.array([1.0, -1.0, 1.0], dtype=np.float32))


def test_a_pitch_span_beyond_the_pitch_range_is_refused():
    environment = pytest.importorskip("deckland.env")
    with pytest.raises(ValueError, match="`pitch_command_span_rad` = 2.0 is not allowed"):
        environment.CarrierLandingEnv(pitch_command_span_rad=2.0)


@pytest.mark.parametrize("runs", [2**40, CLI_MAX_RUNS + 1])
def test_regression_d2_a_campaign_beyond_the_run_limit_is_refused(runs):
    with pytest.raises(ValueError) as raised:
        deckland.campaign(deckland.Scenario.default(), runs=runs)
    assert f"`runs` = {runs} is not allowed" in str(raised.value)
    assert f"[1, {CLI_MAX_RUNS}]" in str(raised.value)
    with pytest.raises(ValueError, match=f"`runs` = {runs}"):
        core.campaign_shard(deckland.Scenario.default(), runs, 0, 2)
    with pytest.raises(ValueError, match="`count` = 100000000000000"):
        core.campaign_shard(deckland.Scenario.default(), 4, 0, 10**14)


@pytest.fixture(scope="module")
def shard_texts():
    scenario = deckland.Scenario.default()
    return [core.campaign_shard(scenario, 3, index, 2, seed=5) for index in range(2)]


def test_regression_d1_a_shard_with_a_huge_count_is_refused(shard_texts):
    forged = json.loads(shard_texts[0])
    forged["shard"] = "0/100000000000000"
    # The library's shard notation refuses it, naming the shard and the limit.
    with pytest.raises(ValueError, match=r"0/100000000000000`: the number of shards M must be at most 100000"):
        core.merge_shards_text([json.dumps(forged)])
    forged = json.loads(shard_texts[0])
    forged["requested_runs"] = 2**40
    with pytest.raises(ValueError, match="`requested_runs` = 1099511627776"):
        core.merge_shards_text([json.dumps(forged), shard_texts[1]])


def hostile_variants(text):
    """Shards tampered field by field with values no campaign writes."""
    payload = json.loads(text)
    values = [None, -1, 0, 2**64, 1e308, math.nan, "", "x", [], {}, True, "0/0", "3/2", "1/18446744073709551615"]
    for key in payload:
        for value in values:
            yield key, json.dumps(dict(payload, **{key: value}))
    rows = payload["runs_csv"].splitlines()
    for cut in (1, len(rows[1]) // 2):
        yield "runs_csv cut", json.dumps(dict(payload, runs_csv="\n".join(rows[:1] + [rows[1][:cut]])))
    yield "runs_csv crash", json.dumps(dict(payload, runs_csv=payload["runs_csv"].replace(",trap,", ",crash,")))
    yield "controllers empty", json.dumps(dict(payload, controllers=[], runs_csv=rows[0] + "\n"))
    yield "not json", text[: len(text) // 2]


def test_a_tampered_shard_raises_value_error_and_never_panics(shard_texts):
    tried = 0
    for name, forged in hostile_variants(shard_texts[0]):
        tried += 1
        try:
            core.merge_shards_text([forged, shard_texts[1]])
        except ValueError:
            pass
        except BaseException as error:  # PanicException is a BaseException
            pytest.fail(f"{name}: {type(error).__name__}: {error}")
    assert tried > 100


def test_r5_a_vector_env_the_memory_cannot_hold_raises_memory_error_naming_num_envs():
    """Regression (issue 45, R5): ``num_envs`` up to 100 000 (about 14 GB) was accepted
    and the interpreter aborted out of memory (SIGABRT); now a count beyond half the
    available memory raises ``MemoryError`` at construction, naming ``num_envs``."""
    env3d = pytest.importorskip("deckland.env3d")
    available = None
    try:
        with open("/proc/meminfo") as meminfo:
            for line in meminfo:
                if line.startswith("MemAvailable:"):
                    available = int(line.split()[1]) * 1024
    except OSError:
        pytest.skip("no /proc/meminfo: only the count's limit applies")
    if available is None or available // 2 >= 100_000 * 192 * 1024:
        pytest.skip("this machine holds 100 000 environments")
    with pytest.raises(MemoryError, match="`num_envs` = 100000"):
        env3d.CarrierLanding3DVecEnv(num_envs=100_000)
    with pytest.raises(ValueError, match=r"`num_envs` = 100001 is not allowed: expected an integer in \[1, 100000\]"):
        env3d.CarrierLanding3DVecEnv(num_envs=100_001)


def test_r8_seeds_and_threads_have_the_clis_range():
    """Regression (issue 45, R8): Python took seeds to 2⁶⁴ − 1 and 1024 threads where the
    CLI takes 2⁶³ − 1 and 256, so a campaign could not be flown again from the CLI."""
    assert core.MAX_SEED == 2**63 - 1
    assert core.MAX_THREADS == 256
    scenario = deckland.Scenario.default()
    for call in (
        lambda **kw: deckland.campaign(scenario, 1, **kw),
        lambda **kw: core.campaign_shard(scenario, 2, 0, 2, **kw),
    ):
        with pytest.raises(ValueError, match=f"`seed` = {2**63} is not allowed"):
            call(seed=2**63)
        with pytest.raises(ValueError, match="`threads` = 257 is not allowed"):
            call(threads=257)


def test_r7_a_shard_count_above_the_run_count_is_refused():
    """Regression (issue 45, R7): 4 runs in 100 000 shards were flown, then refused by
    merge; a campaign of N runs has at most N shards."""
    with pytest.raises(ValueError, match="at most the number of runs"):
        core.campaign_shard(deckland.Scenario.default(), 4, 0, 5)
