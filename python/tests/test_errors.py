"""Bad input raises a clear error naming the field and the value, with the CLI's text."""

from __future__ import annotations

import math

import numpy as np
import pytest

import deckland

# (dotted path, bad value, the same value as written in a TOML file)
OUT_OF_RANGE = [
    ("environment.ship.yaw_rms_deg", -1.0, "[environment.ship]\nyaw_rms_deg = -1.0\n"),
    ("approach.start_range_m", 1.0, "[approach]\nstart_range_m = 1.0\n"),
    ("time_step_s", 0.5, "time_step_s = 0.5\n"),
    ("control.flight_path.glide_slope_deg", math.inf, "[control.flight_path]\nglide_slope_deg = inf\n"),
]

WRONG_TYPE = [
    ("environment.ship.yaw_rms_deg", "abc", "[environment.ship]\nyaw_rms_deg = \"abc\"\n"),
    ("seed", 1.5, "seed = 1.5\n"),
    ("environment.ship.enabled", 3, "[environment.ship]\nenabled = 3\n"),
    ("environment.ship.swell", 1.0, "[environment.ship]\nswell = 1.0\n"),
    ("control.pitch", {"type": "lqr"}, "[control.pitch]\ntype = \"lqr\"\n"),
]


@pytest.mark.parametrize("path,value,toml", OUT_OF_RANGE + WRONG_TYPE)
def test_setting_a_bad_value_raises_the_cli_message(cli, tmp_path, path, value, toml):
    scenario = deckland.Scenario.default()
    before = scenario.to_toml()
    with pytest.raises(ValueError) as raised:
        scenario[path] = value
    message = str(raised.value)
    assert path.split(".")[-1] in message
    # The CLI names the file and line first, then the same text.
    (tmp_path / "bad.toml").write_text(toml)
    cli_message = cli.error(["scenario", "--check", "bad.toml"], cwd=tmp_path)
    assert cli_message.startswith("bad.toml, line ")
    assert cli_message.endswith(message), (cli_message, message)
    # Nothing changed.
    assert scenario.to_toml() == before


@pytest.mark.parametrize("path,value,toml", OUT_OF_RANGE + WRONG_TYPE)
def test_a_bad_file_raises_the_cli_message_whole(cli, tmp_path, monkeypatch, path, value, toml):
    (tmp_path / "bad.toml").write_text(toml)
    cli_message = cli.error(["scenario", "--check", "bad.toml"], cwd=tmp_path)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError) as from_file:
        deckland.Scenario.from_file("bad.toml")
    assert str(from_file.value) == cli_message
    with pytest.raises(ValueError) as from_toml:
        deckland.Scenario.from_toml(toml, "bad.toml")
    assert str(from_toml.value) == cli_message


def test_malformed_toml_names_the_line(cli, tmp_path):
    text = "[approach]\nstart_range_m = 1500 m\n"
    (tmp_path / "broken.toml").write_text(text)
    cli_message = cli.error(["scenario", "--check", "broken.toml"], cwd=tmp_path)
    with pytest.raises(ValueError) as raised:
        deckland.Scenario.from_toml(text, "broken.toml")
    assert str(raised.value) == cli_message
    assert "line 2" in cli_message and "approach.start_range_m" in cli_message


def test_a_missing_file_raises_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError, match="cannot read the scenario file"):
        deckland.Scenario.from_file(tmp_path / "nowhere.toml")


def test_an_unknown_key_raises_key_error():
    with pytest.raises(KeyError, match="environment.ship.swell"):
        deckland.Scenario.default()["environment.ship.swell"]


def test_an_impossible_trim_raises_the_cli_message(cli):
    cli_message = cli.error(["trim", "--speed", "30"])
    with pytest.raises(ValueError) as raised:
        deckland.trim(speed_mps=30.0)
    assert str(raised.value) == cli_message


def test_an_unknown_configuration_is_named():
    with pytest.raises(ValueError, match=r"`configuration` = wet .*`landing` or `clean`"):
        deckland.trim(configuration="wet")


@pytest.mark.parametrize(
    "call,field",
    [
        (lambda: deckland.fly(seed=-1), "`seed` = -1"),
        (lambda: deckland.fly(seed=2**63), "`seed` = 9223372036854775808"),
        (lambda: deckland.campaign(deckland.Scenario.default(), 0), "`runs` = 0"),
        (lambda: deckland.campaign(deckland.Scenario.default(), 3, threads=0), "`threads` = 0"),
        (lambda: deckland.campaign(deckland.Scenario.default(), 3, seed=-5), "`seed` = -5"),
        (lambda: deckland.Approach(control_interval_s=0.0015), "`control_interval_s` = 0.0015"),
        (lambda: deckland.Approach(control_interval_s=-0.02), "`control_interval_s` = -0.02"),
        (lambda: deckland.Approach().step({"elevator_rad": math.nan}), "`action elevator_rad` = NaN"),
        (lambda: deckland.Approach().step({"flaps_rad": 0.1}), "action `flaps_rad`"),
    ],
)
def test_bad_arguments_raise_value_error_naming_the_field_and_value(call, field):
    with pytest.raises(ValueError) as raised:
        call()
    assert field in str(raised.value)


def test_a_campaign_of_another_mission_is_refused_with_the_cli_text():
    scenario = deckland.Scenario.default()
    scenario["mission"] = {
        "kind": "pitch_step",
        "step_deg": 2.0,
        "step_time_s": 1.0,
        "duration_s": 5.0,
        "start_distance_aft_m": 1000.0,
        "altitude_m": 150.0,
    }
    with pytest.raises(ValueError, match="cannot run the campaign: a campaign flies approaches"):
        deckland.campaign(scenario, 2)


def test_a_pitch_law_that_returns_no_number_raises_type_error():
    approach = deckland.Approach(pitch_law=lambda inputs: "down")
    with pytest.raises(TypeError, match="the pitch law returned 'down'"):
        approach.step()


def test_a_pitch_law_that_raises_stops_the_step_with_its_exception():
    def broken(inputs):
        raise RuntimeError("sensor failure")

    approach = deckland.Approach(pitch_law=broken)
    with pytest.raises(RuntimeError, match="sensor failure"):
        approach.step()
    # The approach did not move.
    assert approach.time_s == 0.0


def test_an_action_of_the_wrong_type_raises_type_error():
    with pytest.raises(TypeError, match="action must be None or a dict"):
        deckland.Approach().step([0.1, 2.0])


def _env3d():
    return pytest.importorskip("deckland.env3d")


@pytest.mark.parametrize(
    "make, name",
    [
        (lambda m: m.CarrierLanding3DEnv(forecast="no"), "forecast"),
        (lambda m: m.CarrierLanding3DEnv(forecast=1), "forecast"),
        (lambda m: m.CarrierLanding3DEnv(rewards={"trapp": 10.0}), "trapp"),
        (lambda m: m.CarrierLanding3DEnv(control_interval_s="0.02"), "control_interval_s"),
        (lambda m: m.CarrierLanding3DEnv(bank_command_span_rad=True), "bank_command_span_rad"),
        (lambda m: m.CarrierLanding3DVecEnv(num_envs=1.5), "num_envs"),
        (lambda m: m.CarrierLanding3DVecEnv(num_envs=True), "num_envs"),
        (lambda m: m.CarrierLanding3DVecEnv(num_envs=2, rewards={"trapp": 10.0}), "trapp"),
        (lambda m: deckland.campaign(deckland.Scenario.default(), runs=True), "runs"),
        (lambda m: deckland.campaign(deckland.Scenario.default(), 2, seed=1.5), "seed"),
        (lambda m: deckland._deckland.campaign_shard(deckland.Scenario.default(), 4, True, 2), "index"),
    ],
)
def test_r9_arguments_python_would_convert_are_refused_naming_them(make, name):
    """Regression (issue 45, R9): the 3-D environment converted bad arguments without a
    word: ``forecast="no"`` turned the forecast on, an unknown reward key was ignored,
    ``num_envs=1.5`` made 1, ``campaign(runs=True)`` flew 1 run."""
    with pytest.raises((TypeError, ValueError)) as raised:
        make(_env3d())
    assert name in str(raised.value)


def test_r9_a_complex_or_bool_action_and_fractional_seeds_are_refused():
    """Regression (issue 45, R9): a complex action lost its imaginary part and
    ``reset(seed=[1.5, 2])`` flew seeds [1, 2]."""
    env3d = _env3d()
    env = env3d.CarrierLanding3DEnv()
    env.reset(seed=1)
    width = env.action_space.shape[0]
    for action in (
        np.zeros(width, dtype=np.complex128) + 0.1j,
        [0.0] * (width - 1) + [0.5 + 0.5j],
        np.zeros(width, dtype=bool),
        [False] * width,
        "0" * width,
    ):
        with pytest.raises((TypeError, ValueError), match="action"):
            env.step(action)
    env.step(np.zeros(width))  # a real action still steps
    with pytest.raises(TypeError, match="seed"):
        env.reset(seed=1.5)
    envs = env3d.CarrierLanding3DVecEnv(num_envs=2)
    for seeds in ([1.5, 2], [True, 2], "12", 1.0, True):
        with pytest.raises(TypeError, match="seed"):
            envs.reset(seed=seeds)
    envs.reset(seed=[1, 2])
    envs.reset(seed=np.array([3, 4]))
