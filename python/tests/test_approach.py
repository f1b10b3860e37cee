"""The stepping API: `Approach` against `fly()`, the actions, and a Python pitch law."""

from __future__ import annotations

import re

import numpy as np
import pytest

import deckland


def fly_by_steps(approach, action=None):
    observation = approach.reset()
    steps = 0
    while not observation["done"]:
        observation = approach.step(action)
        steps += 1
    return observation, steps


@pytest.mark.parametrize("seed,interval", [(1, 0.02), (6, 0.02), (2, 0.05)])
def test_stepping_with_no_action_to_the_end_is_fly(seed, interval):
    flight = deckland.fly(seed=seed)
    approach = deckland.Approach(seed=seed, control_interval_s=interval)
    observation, steps = fly_by_steps(approach)
    assert approach.summary == flight.summary
    assert approach.events == flight.events
    assert observation["outcome"] == flight.outcome
    assert observation["wire"] == flight.wire
    assert observation["reason"] == flight.reason
    # One control interval per step, the last one cut short by the end, which the
    # integration step `steps` (of 1 ms) found.
    assert steps == flight.summary["steps"] // round(interval / 0.001) + 1


def test_the_observation_is_what_fly_records_at_the_same_time():
    flight = deckland.fly(seed=3)
    series = flight.time_series.set_index("time_s")
    approach = deckland.Approach(seed=3)
    observation = approach.reset()
    compared = 0
    while True:
        if observation["time_s"] in series.index:
            row = series.loc[observation["time_s"]]
            o = observation
            pairs = [
                (np.rad2deg(o["theta_rad"]), row["theta_deg"]),
                (np.rad2deg(o["alpha_rad"]), row["alpha_deg"]),
                (np.rad2deg(o["theta_measured_rad"]), row["theta_measured_deg"]),
                (np.rad2deg(o["theta_command_rad"]), row["theta_command_deg"]),
                (np.rad2deg(o["elevator_rad"]), row["elevator_deg"]),
                (np.rad2deg(o["elevator_command_rad"]), row["elevator_command_deg"]),
                (o["airspeed_mps"], row["airspeed_mps"]),
                (o["hook_height_m"], row["hook_height_m"]),
                (o["glide_path_height_m"], row["glide_path_height_m"]),
                (o["glide_path_error_m"], row["glide_path_error_m"]),
                (o["sink_rate_mps"], -row["climb_rate_mps"]),
                (o["sink_rate_command_mps"], -row["climb_rate_command_mps"]),
                (o["deck_height_m"], row["landing_point_height_m"]),
                (o["thrust_n"], row["thrust_n"]),
                (o["thrust_command_n"], row["thrust_command_n"]),
                (o["wind_x_mps"], row["wind_x_mps"]),
                (o["wind_z_mps"], row["wind_z_mps"]),
            ]
            for index, (observed, recorded) in enumerate(pairs):
                assert observed == recorded, (o["time_s"], index, observed, recorded)
            compared += 1
        if observation["done"]:
            break
        observation = approach.step()
    # Every observation: the one at the start and one per step.
    assert compared == approach.summary["steps"] // 20 + 2


def test_reset_replays_the_episode_and_a_new_seed_changes_it():
    approach = deckland.Approach(seed=2)
    first = [approach.reset()] + [approach.step() for _ in range(100)]
    again = [approach.reset()] + [approach.step() for _ in range(100)]
    assert first == again
    other = [approach.reset(seed=3)] + [approach.step() for _ in range(100)]
    assert approach.seed == 3
    assert other[-1]["glide_path_error_m"] != first[-1]["glide_path_error_m"]


def test_every_observation_key_is_documented():
    # The longitudinal approach's keys each by name; the 3-D approach (the default) adds
    # the lineup and lateral signals under `approach.csv`'s names, as documented.
    longitudinal = deckland.Scenario.default()
    longitudinal["aircraft.model"] = "3dof"
    longitudinal["environment.ship.forward_speed_mps"] = 0.0
    observation = deckland.Approach(longitudinal).reset()
    doc = deckland.Approach.__doc__
    for key in observation:
        assert f"`{key}`" in doc, key
    assert all(isinstance(observation[k], float) for k in observation if k not in {"done", "outcome", "wire", "reason"})
    three_d = deckland.Approach().reset()
    columns = set(deckland.fly(seed=1).time_series.keys())
    added = set(three_d) - set(observation)
    assert added and added <= columns, added - columns
    assert all(isinstance(three_d[k], float) for k in added)


def test_a_pitch_command_replaces_guidance_and_the_sink_rate_loop():
    approach = deckland.Approach(seed=1)
    observation = approach.reset()
    command = approach.trim["theta_rad"] + np.deg2rad(4.0)
    for _ in range(150):  # 3 s
        observation = approach.step({"pitch_command_rad": command})
    # The pitch law tracks the command held; the cascade would have kept θ near trim.
    assert abs(observation["theta_rad"] - command) < np.deg2rad(1.0)
    assert abs(observation["theta_command_rad"] - command) > np.deg2rad(1.0)
    # Handing back: the cascade flies again and brings the nose down.
    for _ in range(150):
        observation = approach.step()
    assert observation["theta_rad"] < command - np.deg2rad(1.0)


def test_elevator_and_thrust_replace_every_loop():
    approach = deckland.Approach(seed=1)
    observation = approach.reset()
    trim = approach.trim
    for _ in range(100):  # 2 s at full thrust, elevator at trim
        observation = approach.step({"elevator_rad": trim["elevator_rad"], "thrust_n": trim["max_thrust_n"]})
    assert observation["thrust_n"] > 0.9 * trim["max_thrust_n"]
    assert abs(observation["elevator_rad"] - trim["elevator_rad"]) < 1e-6
    cascade = deckland.Approach(seed=1)
    cascade.reset()
    for _ in range(100):
        reference = cascade.step()
    assert observation["airspeed_mps"] > reference["airspeed_mps"] + 1.0


def test_steps_after_the_end_return_the_final_observation():
    approach = deckland.Approach(seed=1)
    final, _ = fly_by_steps(approach)
    assert approach.done and approach.step() == final


def proportional_derivative(inputs, kp=2.0, kd=0.8):
    """A discrete pitch law: δe = δe* − kp (θ_ref − θ_m) + kd q (rad)."""
    error = inputs["theta_ref_rad"] - inputs["theta_measured_rad"]
    return inputs["elevator_trim_rad"] - kp * error + kd * inputs["pitch_rate_radps"]


class ProportionalDerivative:
    """The law as a callable object that counts its calls."""

    label = "PD in Python"

    def __init__(self):
        self.calls = []

    def __call__(self, inputs):
        self.calls.append(inputs)
        return proportional_derivative(inputs)


def test_a_python_pitch_law_is_called_once_per_interval_and_its_command_held():
    law = ProportionalDerivative()
    flight = deckland.fly(seed=1, pitch_law=law, control_interval_s=0.02)
    assert len(law.calls) == flight.summary["steps"] // 20 + 1
    assert flight.summary["controller"] == "PD in Python"
    assert set(law.calls[0]) == {
        "time_s", "theta_ref_rad", "theta_measured_rad", "pitch_rate_radps",
        "elevator_rad", "theta_trim_rad", "elevator_trim_rad", "interval_s",
    }
    assert [c["time_s"] for c in law.calls[:3]] == [0.0, 0.02, 0.04]
    assert law.calls[0]["interval_s"] == 0.02
    # Every row of the time series (every 10 ms) shows the command the law returned at
    # the start of its interval: held, not interpolated.
    returned = [proportional_derivative(inputs) for inputs in law.calls]
    series = flight.time_series
    for time_s, command_deg in zip(series["time_s"], series["elevator_command_deg"]):
        interval = int(round(time_s / 0.001)) // 20
        assert command_deg == np.rad2deg(returned[interval]), time_s


def test_a_python_pitch_law_through_approach_matches_fly():
    flight = deckland.fly(seed=2, pitch_law=ProportionalDerivative())
    approach = deckland.Approach(seed=2, pitch_law=ProportionalDerivative())
    fly_by_steps(approach)
    assert approach.summary == flight.summary


def test_the_pitch_law_tracks_an_action_pitch_command():
    law = ProportionalDerivative()
    approach = deckland.Approach(seed=1, pitch_law=law)
    approach.reset()
    approach.step({"pitch_command_rad": 0.123})
    assert law.calls[-1]["theta_ref_rad"] == 0.123
    calls = len(law.calls)
    approach.step({"elevator_rad": -0.1})
    assert len(law.calls) == calls, "an elevator action takes precedence over the law"


def test_repr_names_the_state():
    approach = deckland.Approach(seed=4)
    assert re.match(r"Approach\(scenario=\"adverse\", seed=4, control_interval_s=0.02, time_s=0.000, done=false\)", repr(approach))
