"""The lateral step from Python (``deckland.lateral_step``) against ``deckland step
--axis roll|yaw``: the same report and the same time series, bit for bit; a scenario's
own roll law flies; bad arguments name themselves."""

from __future__ import annotations

import pytest

import deckland
from conftest import assert_column_equals, read_csv_columns


def _columns(time_series):
    """The package's time series as a dict of columns (DataFrame or dict)."""
    if hasattr(time_series, "to_dict"):
        return {name: time_series[name].to_numpy() for name in time_series.columns}
    return time_series


@pytest.mark.parametrize(
    "axis, step_deg, conditions",
    [("roll", 10.0, "ideal"), ("yaw", 2.0, "adverse")],
)
def test_the_lateral_step_is_the_clis(cli, tmp_path, axis, step_deg, conditions):
    args = [
        "step",
        "--axis",
        axis,
        "--step-deg",
        str(step_deg),
        "--seconds",
        "3",
        "--conditions",
        conditions,
        "--seed",
        "4",
        "--json",
        "--out",
        str(tmp_path),
        "--force",
    ]
    expected = cli.json(args)
    del expected["output_folder"]
    flown = deckland.lateral_step(
        axis=axis, step_deg=step_deg, seconds=3.0, conditions=conditions, seed=4
    )
    assert flown.report == expected
    assert [c["controller"] for c in flown.controllers] == ["O-PD", "PID"]
    csv = read_csv_columns(tmp_path / "step.csv")
    columns = _columns(flown.time_series)
    assert list(columns) == list(csv)
    for name, text in csv.items():
        assert_column_equals(name, text, columns[name])


def test_a_scenarios_roll_law_flies():
    """A roll PID tuned for ω_n = 2 rad/s (K_P = ω_n², K_D = 2ζω_n + L_p with ζ = 1 and
    L_p = −1.16 /s, docs/lateral-control.md) settles the 10° bank later than the
    registered one (ω_n = 4 rad/s); a scenario that names the O-PD keeps the designed
    PID for ``controller="pid"``."""
    designed = deckland.lateral_step(controller="pid", seconds=6.0).controllers[0]
    scenario = deckland.Scenario.default()
    scenario["control.roll"] = {
        "type": "pid",
        "proportional_per_s2": 4.0,
        "integral_per_s3": 0.0,
        "derivative_per_s": 2.84,
    }
    assert scenario["control.roll.type"] == "pid"
    slow = deckland.lateral_step(
        controller="pid", seconds=6.0, scenario=scenario
    ).controllers[0]
    assert designed["settled"] and slow["settled"]
    assert slow["settling_time_s"] > 1.5 * designed["settling_time_s"]
    # The yaw O-PD's keys left out keep the yaw channel's designed tuning.
    scenario["control.yaw.observer.epsilon"] = 0.3
    assert scenario["control.yaw.settling_time_s"] == 2.0


@pytest.mark.parametrize(
    "arguments, words",
    [
        ({"axis": "pitch"}, "`axis`"),
        ({"step_deg": 40.0}, "`step_deg`"),
        ({"step_deg": 0.0}, "`step_deg`"),
        ({"seconds": 1.0}, "`seconds`"),
        ({"conditions": "stormy"}, "`conditions`"),
        ({"controller": "lqr"}, "`controller`"),
        ({"seed": -1}, "`seed`"),
        ({"scenario": deckland.Scenario.paper()}, "paper"),
    ],
)
def test_bad_arguments_are_named(arguments, words):
    with pytest.raises(ValueError) as error:
        deckland.lateral_step(**arguments)
    assert words in str(error.value)


def test_a_bad_lateral_key_is_named():
    scenario = deckland.Scenario.default()
    with pytest.raises(ValueError) as error:
        scenario["control.yaw.damping_ratio"] = 0.0
    assert "control.yaw.damping_ratio" in str(error.value)
    with pytest.raises(ValueError) as error:
        scenario["control.roll"] = {"type": "lqr"}
    assert "lqr" in str(error.value)
