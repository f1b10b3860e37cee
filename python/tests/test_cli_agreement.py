"""The package gives the CLI's numbers for the same inputs, bit for bit."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

import deckland

from conftest import SCENARIOS, assert_column_equals, read_csv_columns

TRIM_CASES = [
    (69.1, 0.0, "landing"),
    (75.0, -3.5, "landing"),
    (120.0, 2.0, "clean"),
]


def trim_args(speed, gamma, configuration):
    return ["--speed", repr(speed), "--gamma", repr(gamma), "--config", configuration, "--json"]


@pytest.mark.parametrize("speed,gamma,configuration", TRIM_CASES)
def test_trim_is_the_cli_trim(cli, speed, gamma, configuration):
    expected = cli.json(["trim", *trim_args(speed, gamma, configuration)])
    actual = deckland.trim(speed_mps=speed, gamma_deg=gamma, configuration=configuration)
    assert actual.to_dict() == expected
    for key in ("alpha_deg", "theta_deg", "elevator_deg", "thrust_n", "throttle"):
        assert getattr(actual, key) == expected[key], key


@pytest.mark.parametrize("speed,gamma,configuration", TRIM_CASES)
def test_linearize_is_the_cli_linear_model(cli, speed, gamma, configuration):
    expected = cli.json(["linearize", *trim_args(speed, gamma, configuration)])
    model = deckland.linearize(speed, gamma, configuration)
    assert np.array_equal(model.a, np.array(expected["a"]))
    assert np.array_equal(model.b, np.array(expected["b"]))
    assert model.a.shape == (4, 4) and model.b.shape == (4, 2)
    eigenvalues = [complex(e["re"], e["im"]) for e in expected["eigenvalues"]]
    assert list(model.eigenvalues) == eigenvalues
    assert model.state_names == expected["state_names"]
    assert model.input_names == expected["input_names"]
    assert model.state_units == expected["state_units"]
    assert model.input_units == expected["input_units"]
    assert model.modes == expected["modes"]
    assert model.trim.to_dict() == expected["trim"]


SIX_DOF_CASES = [
    (69.1, 0.0, 0.0, 0.0, "landing"),
    (69.1, -3.5, 5.0, 0.0, "landing"),
    (69.1, 0.0, 0.0, 5.0, "landing"),
    (120.0, 2.0, -3.0, 0.0, "clean"),
]


def six_dof_args(speed, gamma, sideslip, crosswind, configuration):
    return [
        "--model", "6dof", "--speed", repr(speed), "--gamma", repr(gamma),
        "--sideslip", repr(sideslip), "--crosswind", repr(crosswind),
        "--config", configuration, "--json",
    ]


@pytest.mark.parametrize("case", SIX_DOF_CASES)
def test_six_dof_trim_is_the_cli_trim(cli, case):
    expected = cli.json(["trim", *six_dof_args(*case)])
    speed, gamma, sideslip, crosswind, configuration = case
    actual = deckland.trim_six_dof(speed, gamma, sideslip, crosswind, configuration)
    assert actual == expected


@pytest.mark.parametrize("case", SIX_DOF_CASES)
def test_six_dof_linear_model_is_the_cli_one(cli, case):
    expected = cli.json(["linearize", *six_dof_args(*case)])
    model = deckland.linearize_six_dof(*case)
    for key in ("lateral_a", "lateral_b", "longitudinal_a", "longitudinal_b"):
        assert np.array_equal(model[key], np.array(expected[key])), key
    assert model["lateral_a"].shape == (4, 4) and model["lateral_b"].shape == (4, 2)
    for key, value in expected.items():
        if not key.endswith(("_a", "_b")):
            assert model[key] == value, key


def test_six_dof_bad_arguments_raise_the_cli_message():
    with pytest.raises(ValueError, match="`sideslip_deg` = 40"):
        deckland.trim_six_dof(sideslip_deg=40.0)
    with pytest.raises(ValueError, match="beyond its 30.0° limit by 6.40°"):
        deckland.trim_six_dof(sideslip_deg=25.0)
    with pytest.raises(ValueError, match="cannot be crabbed"):
        deckland.linearize_six_dof(crosswind_mps=90.0)


def assert_flight_is_the_cli_run(flight, out):
    """`flight` equals the CLI's summary.json and approach.csv in `out`, bit for bit."""
    with open(out / "summary.json") as f:
        assert flight.summary == json.load(f)
    expected = read_csv_columns(out / "approach.csv")
    series = flight.time_series
    assert list(series.keys()) == list(expected.keys())
    for name, column in expected.items():
        assert_column_equals(name, column, series[name])


@pytest.mark.parametrize("seed,controller", [(1, "opd"), (4, "pid")])
def test_fly_is_deckland_land(cli, tmp_path, seed, controller):
    out = tmp_path / "land"
    cli.run(["land", "--no-plots", "--json", "--seed", str(seed), "--controller", controller, "--out", str(out)])
    scenario = deckland.Scenario.default()
    if controller == "pid":
        scenario["control.pitch"] = {"type": "pid"}
    flight = deckland.fly(scenario, seed=seed)
    assert_flight_is_the_cli_run(flight, out)
    assert flight.outcome == flight.summary["outcome"]
    assert flight.touchdown == flight.summary["touchdown"]
    with open(out / "scenario.toml") as f:
        flown = f.read()
    scenario["seed"] = seed
    assert scenario.to_toml() == flown


def test_the_paper_set_is_deckland_land_hardware_paper(cli, tmp_path):
    out = tmp_path / "land"
    cli.run(["land", "--no-plots", "--json", "--hardware", "paper", "--seed", "2", "--out", str(out)])
    flight = deckland.fly(deckland.Scenario.paper(), seed=2)
    assert_flight_is_the_cli_run(flight, out)
    assert deckland.Scenario.paper()["hardware"] == "paper"
    assert deckland.Scenario.default()["hardware"] == "realistic"


def test_fly_of_a_file_with_dispersions_is_deckland_run(cli, tmp_path):
    shutil.copy(SCENARIOS / "heavy-sea.toml", tmp_path / "heavy-sea.toml")
    out = tmp_path / "run"
    cli.run(
        ["run", "heavy-sea.toml", "--seed", "9", "--disperse", "--no-plots", "--json", "--out", str(out)],
        cwd=tmp_path,
    )
    scenario = deckland.Scenario.from_file(tmp_path / "heavy-sea.toml")
    flight = deckland.fly(scenario, seed=9, disperse=True)
    assert flight.summary["conditions"] == "heavy-sea.toml"
    assert_flight_is_the_cli_run(flight, out)


@pytest.mark.parametrize("threads", [1, 2])
def test_campaign_is_deckland_campaign(cli, tmp_path, threads):
    shutil.copy(SCENARIOS / "heavy-sea.toml", tmp_path / "heavy-sea.toml")
    out = tmp_path / "campaign"
    expected_summary = cli.json(
        ["campaign", "heavy-sea.toml", "--runs", "6", "--seed", "11", "--compare", "--threads", "2", "--json", "--out", str(out)],
        cwd=tmp_path,
    )
    # The printed JSON is summary.json's fields and where the files went.
    assert expected_summary.pop("output_folder") == str(out)
    scenario = deckland.Scenario.from_file(tmp_path / "heavy-sea.toml")
    result = deckland.campaign(scenario, 6, seed=11, threads=threads, compare=True)
    expected = read_csv_columns(out / "runs.csv")
    runs = result.runs
    assert list(runs.keys()) == list(expected.keys())
    for name, column in expected.items():
        assert_column_equals(name, column, runs[name])
    assert len(runs["run_index"]) == 12
    timing = {"elapsed_s", "runs_per_s", "threads"}
    assert set(result.summary) == set(expected_summary)
    for key in set(expected_summary) - timing:
        assert result.summary[key] == expected_summary[key], key
    assert result.summary["threads"] == threads
    assert result.statistics == expected_summary["controllers"]


def test_a_three_d_campaign_is_deckland_campaign_with_its_lateral_columns(cli, tmp_path):
    # A 3-D approach campaign's runs.csv adds the lateral touchdown and the trap sheet
    # after the columns of every campaign, and summary.json their statistics.
    shutil.copy(SCENARIOS / "crosswind.toml", tmp_path / "crosswind.toml")
    out = tmp_path / "campaign"
    expected_summary = cli.json(
        ["campaign", "crosswind.toml", "--runs", "3", "--seed", "5", "--threads", "2", "--json", "--out", str(out)],
        cwd=tmp_path,
    )
    assert expected_summary.pop("output_folder") == str(out)
    scenario = deckland.Scenario.from_file(tmp_path / "crosswind.toml")
    result = deckland.campaign(scenario, 3, seed=5, threads=2)
    expected = read_csv_columns(out / "runs.csv")
    assert "touchdown_lateral_offset_m" in expected and "off_centre" in expected
    assert list(result.runs.keys()) == list(expected.keys())
    for name, column in expected.items():
        assert_column_equals(name, column, result.runs[name])
    assert {"lateral", "trap_sheet"} <= set(expected_summary)
    timing = {"elapsed_s", "runs_per_s", "threads"}
    assert set(result.summary) == set(expected_summary)
    for key in set(expected_summary) - timing:
        assert result.summary[key] == expected_summary[key], key


def test_the_default_scenario_is_the_cli_default(cli):
    # `deckland scenario --print-default` is the commented template of the default.
    text = cli.run(["scenario", "--print-default"]).stdout
    assert deckland.Scenario.from_toml(text) == deckland.Scenario.default()


@pytest.mark.parametrize("calibrate_score", [0, 6])
def test_rare_is_deckland_rare(cli, tmp_path, calibrate_score):
    # The same splitting, bit for bit: the estimate, its interval and every level; with
    # the ramp's score plain and calibrated (`--calibrate-score`).
    shutil.copy(SCENARIOS / "paper-adverse.toml", tmp_path / "paper-adverse.toml")
    out = tmp_path / "rare"
    args = ["--event", "ramp_strike", "--threshold", "1.0", "--particles", "8", "--max-runs", "150", "--seed", "4"]
    args += ["--calibrate-score", str(calibrate_score)]
    expected = cli.json(
        ["rare", "paper-adverse.toml", *args, "--save-flights", "0", "--json", "--out", str(out)],
        cwd=tmp_path,
    )
    scenario = deckland.Scenario.from_file(tmp_path / "paper-adverse.toml")
    actual = deckland.rare(
        scenario,
        "ramp_strike",
        threshold=1.0,
        particles=8,
        max_runs=150,
        seed=4,
        threads=1,
        calibrate_score=calibrate_score,
    )
    assert actual["request"]["calibration_runs"] == calibrate_score
    for key in ("estimate", "levels", "request", "thresholds", "approach_steps"):
        assert actual[key] == expected[key], key
    assert 0.0 < actual["estimate"]["probability"] < 1.0


@pytest.mark.parametrize(
    "kwargs,error,message",
    [
        ({"event": "crash"}, ValueError, "crash"),
        ({"event": "ramp_strike", "threshold": True}, TypeError, "threshold"),
        ({"event": "ramp_strike", "threshold": 99.0}, ValueError, "threshold"),
        ({"event": "ramp_strike", "particles": 1.5}, TypeError, "particles"),
        ({"event": "off_centre"}, ValueError, "3-D approach"),
        ({"event": "hard_landing", "calibrate_score": 5}, ValueError, "rare.calibration_runs"),
        ({"event": "ramp_strike", "calibrate_score": -1}, ValueError, "calibrate_score"),
    ],
)
def test_rare_refuses_bad_arguments_by_name(kwargs, error, message):
    with pytest.raises(error, match=message):
        deckland.rare(deckland.Scenario.paper(), **kwargs)
