"""The 3-D approach from Python and the Gymnasium environment
``deckland/CarrierLanding3D-v0``: the CLI's lateral touchdown, the checker, the
autopilot's crosswind landing, the agent's lateral authority, reproducibility."""

from __future__ import annotations

import json
import shutil
import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import deckland
from deckland.env import longitudinal_scenario
from deckland.env3d import (
    CONTROL_MODES_3D,
    ENV_ID_3D,
    CarrierLanding3DEnv,
    CarrierLanding3DVecEnv,
    crosswind_scenario,
)

from conftest import SCENARIOS

MODES = list(CONTROL_MODES_3D)
LATERAL_TOUCHDOWN = (
    "offset_m",
    "drift_rate_mps",
    "bank_deg",
    "heading_to_centreline_deg",
    "ramp_lineup_error_deg",
    "off_centre",
)


def run_episode(env, seed, policy):
    """(observations, infos) of one episode."""
    observation, info = env.reset(seed=seed)
    observations, infos = [observation], [info]
    while True:
        observation, _, terminated, truncated, info = env.step(policy(info))
        observations.append(observation)
        infos.append(info)
        if terminated or truncated:
            return np.array(observations), infos


def autopilot(info):
    return info["autopilot_action"]


def neutral_lateral(env):
    """The autopilot's longitudinal commands, the lateral ones at the trim (zero)."""
    lateral = [env.action_names.index(name) for name in ("bank_command", "sideslip_command")]

    def policy(info):
        action = np.array(info["autopilot_action"])
        action[lateral] = 0.0
        return action

    return policy


def final_cross_track_m(env, infos):
    return infos[-1]["raw"][env.observation_names.index("cross_track_m")]


def test_the_crosswind_scenario_flown_from_python_is_deckland_run(cli, tmp_path):
    shutil.copy(SCENARIOS / "crosswind.toml", tmp_path / "crosswind.toml")
    out = tmp_path / "run"
    cli.run(["run", "crosswind.toml", "--seed", "4", "--no-plots", "--json", "--out", str(out)], cwd=tmp_path)
    with open(out / "summary.json") as f:
        expected = json.load(f)
    scenario = deckland.Scenario.from_file(tmp_path / "crosswind.toml")
    flight = deckland.fly(scenario, seed=4)
    assert flight.summary == expected
    lateral = flight.summary["touchdown"]["lateral"]
    assert set(LATERAL_TOUCHDOWN) <= set(lateral)
    assert all(np.isfinite(lateral[k]) for k in LATERAL_TOUCHDOWN[:-1])
    # The stepping API flies the same approach to the same lateral touchdown.
    approach = deckland.Approach(scenario, seed=4)
    while not approach.done:
        approach.step()
    assert approach.summary["touchdown"]["lateral"] == lateral


def test_the_default_scenario_is_the_crosswind_file():
    file = deckland.Scenario.from_file(SCENARIOS / "crosswind.toml")
    assert crosswind_scenario().to_dict() == file.to_dict()
    flown = CarrierLanding3DEnv().description["scenario"]
    assert flown["aircraft.model"] == "6dof"
    assert flown["environment.wind.crosswind_mps"] == 5.0
    assert flown["environment.ship.roll_rms_deg"] == file["environment.ship.roll_rms_deg"]


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("render_mode", [None, "rgb_array"])
def test_every_mode_is_registered_and_passes_the_checker(mode, render_mode):
    env = gymnasium.make(ENV_ID_3D, control=mode, render_mode=render_mode)
    assert env.action_space.shape == (len(CONTROL_MODES_3D[mode]),)
    assert env.unwrapped.action_names == CONTROL_MODES_3D[mode]
    names = env.unwrapped.observation_names
    assert names[-9:] == (
        "cross_track_m",
        "cross_track_rate_mps",
        "bank_rad",
        "heading_to_centreline_rad",
        "sideslip_rad",
        "roll_rate_radps",
        "yaw_rate_radps",
        "aileron_rad",
        "rudder_rad",
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    assert [str(w.message) for w in caught] == []
    env.close()


@pytest.mark.parametrize("mode", MODES)
def test_the_autopilot_as_a_policy_lands_the_crosswind_approach_on_the_centreline(mode):
    env = CarrierLanding3DEnv(control=mode)
    for seed in (1, 2):
        _, infos = run_episode(env, seed, autopilot)
        assert infos[-1]["outcome"] == "trap", (mode, seed, infos[-1]["reason"])
        assert infos[-1]["off_centre"] is False
        assert abs(final_cross_track_m(env, infos)) < 1.0, (mode, seed)


def test_with_the_lineup_guidance_off_a_neutral_bank_command_does_not_line_up():
    # The agent's bank command replaces the lineup guidance's: held at the trim (wings
    # level), the disturbances' offset is never taken out, where the autopilot's command
    # (the guidance's) lands within a metre of the centreline.
    env = CarrierLanding3DEnv(control="attitude")
    seeds = (1, 2, 3, 4)
    flown = [final_cross_track_m(env, run_episode(env, s, autopilot)[1]) for s in seeds]
    neutral = [final_cross_track_m(env, run_episode(env, s, neutral_lateral(env))[1]) for s in seeds]
    assert max(abs(x) for x in flown) < 1.0
    assert max(abs(x) for x in neutral) > 2.0
    assert np.sqrt(np.mean(np.square(neutral))) > 3.0 * np.sqrt(np.mean(np.square(flown)))


def test_a_held_bank_command_turns_the_aircraft_off_the_centreline():
    env = CarrierLanding3DEnv(control="attitude")
    bank = env.action_names.index("bank_command")
    heading = env.observation_names.index("heading_to_centreline_rad")

    def banked(info):
        action = np.array(info["autopilot_action"])
        action[bank] = 0.25  # 5° right
        return action

    _, infos = run_episode(env, 1, banked)
    _, flown = run_episode(env, 1, autopilot)
    turn = [i["raw"][heading] for i in infos]
    # In the last 12 s the yaw law holds the crab heading (approach.heading_hold_time_to_go_s)
    # and pulls the nose back, so the turn is read at its largest, before the hold.
    assert max(turn) - turn[0] > np.deg2rad(5.0)
    assert final_cross_track_m(env, infos) > final_cross_track_m(env, flown) + 5.0


def trajectory_of(env, seed, actions):
    """The observations of `env` reset with `seed` and stepped with `actions` until the
    episode ends."""
    observation, _ = env.reset(seed=seed)
    observations = [observation]
    for action in actions:
        observation, _, terminated, truncated, _ = env.step(action)
        observations.append(observation)
        if terminated or truncated:
            break
    return np.array(observations)


@pytest.mark.parametrize("mode", MODES)
def test_the_same_seed_gives_the_same_trajectory(mode):
    rng = np.random.default_rng(3)
    env = CarrierLanding3DEnv(control=mode)
    actions = rng.uniform(-0.2, 0.2, size=(400, len(CONTROL_MODES_3D[mode]))).astype(np.float32)
    actions[:, -1] = -1.0
    first = trajectory_of(env, 11, actions)
    assert np.array_equal(first, trajectory_of(env, 11, actions))
    assert np.array_equal(first, trajectory_of(CarrierLanding3DEnv(control=mode), 11, actions))
    assert not np.array_equal(first, trajectory_of(env, 12, actions))


def test_the_vectorised_environment_is_the_single_one_bit_for_bit():
    n, steps = 2, 300
    envs = gymnasium.make_vec(ENV_ID_3D, num_envs=n, vectorization_mode="vector_entry_point")
    assert isinstance(envs, CarrierLanding3DVecEnv)
    width = len(CONTROL_MODES_3D["attitude"])
    actions = np.random.default_rng(5).uniform(-0.3, 0.3, size=(steps, n, width)).astype(np.float32)
    actions[..., -1] = -1.0
    observation, _ = envs.reset(seed=20)
    vector = [observation]
    for t in range(steps):
        vector.append(envs.step(actions[t])[0])
    vector = np.array(vector)
    for i in range(n):
        env = CarrierLanding3DEnv()
        observation, _ = env.reset(seed=20 + i)
        assert np.array_equal(observation, vector[0, i])
        for t in range(steps):
            observation = env.step(actions[t, i])[0]
            assert np.array_equal(observation, vector[t + 1, i]), (i, t)


def test_bad_options_are_refused_by_name():
    with pytest.raises(ValueError, match="bank_command_span_rad"):
        CarrierLanding3DEnv(bank_command_span_rad=-0.1)
    with pytest.raises(ValueError, match="rudder_span_rad"):
        CarrierLanding3DEnv(rudder_span_rad=float("nan"))
    with pytest.raises(ValueError, match="3-D approach"):
        CarrierLanding3DEnv(scenario=longitudinal_scenario())
    env = CarrierLanding3DEnv()
    env.reset(seed=1)
    with pytest.raises(ValueError, match="bank_command"):
        env.step(np.zeros(3, dtype=np.float32))


def test_the_vectorised_info_reports_off_centre_as_the_single_environment_does():
    n = 2
    envs = gymnasium.make_vec(ENV_ID_3D, num_envs=n, vectorization_mode="vector_entry_point")
    _, info = envs.reset(seed=30)
    names = CONTROL_MODES_3D["attitude"]
    climb = [names.index(name) for name in ("pitch_command", "thrust", "wave_off")]
    ended = {}
    grades = {}
    for _ in range(3000):
        actions = np.array(info["autopilot_action"], dtype=np.float32)
        actions[1, climb] = 1.0  # environment 1 waves off and climbs away: no touchdown
        _, _, terminated, truncated, info = envs.step(actions)
        if "off_centre" in info:
            for i in np.flatnonzero(info["_off_centre"]):
                ended.setdefault(int(i), info["off_centre"][i])
                grades.setdefault(int(i), (info["lso_grade"][i], info["lso_points"][i]))
        if len(ended) == n:
            break
    assert set(ended) == {0, 1}
    # Environment 0 flies the single environment's episode (seed 30): its flag.
    _, infos = run_episode(CarrierLanding3DEnv(), 30, autopilot)
    assert infos[-1]["outcome"] == "trap"
    assert ended[0] is infos[-1]["off_centre"] is False
    assert ended[1] is None
    # The LSO's grade, as the single environment gives it; the wave-off is the agent's own.
    assert grades[0] == (infos[-1]["lso_grade"], infos[-1]["lso_points"])
    assert grades[1] == ("own_wave_off", 2.0)


def test_an_approach_steps_with_lateral_commands_in_place_of_the_lateral_loops():
    scenario = crosswind_scenario()
    approach = deckland.Approach(scenario, seed=3)
    ranges = approach.action_ranges
    assert ranges["bank_command_rad"] == pytest.approx((-np.pi / 2, np.pi / 2))
    assert ranges["aileron_rad"] == pytest.approx(np.deg2rad((-25.0, 25.0)))
    assert ranges["rudder_rad"] == pytest.approx(np.deg2rad((-30.0, 30.0)))
    # A bank command replaces the lineup guidance: held at 10° right for 3 s, the roll
    # law banks the aircraft there and it turns right off the centreline, where the
    # built-in lineup holds the wings near level on it.
    free = deckland.Approach(scenario, seed=3)
    for _ in range(150):
        built_in = free.step()
        banked = approach.step({"bank_command_rad": np.deg2rad(10.0)})
    assert abs(built_in["bank_deg"]) < 5.0
    assert banked["bank_deg"] == pytest.approx(10.0, abs=1.0)
    assert banked["cross_track_m"] > built_in["cross_track_m"] + 1.0
    # Aileron and rudder commands replace the laws: the surfaces go where they are sent
    # (the actuators' second-order lag settles well within 0.5 s).
    surfaces = deckland.Approach(scenario, seed=3)
    start = surfaces.observation()
    aileron = np.deg2rad(start["aileron_deg"] + 2.0)
    rudder = np.deg2rad(start["rudder_deg"] - 3.0)
    for _ in range(25):
        moved = surfaces.step({"aileron_rad": aileron, "rudder_rad": rudder})
    assert moved["aileron_deg"] == pytest.approx(np.rad2deg(aileron), abs=0.05)
    assert moved["rudder_deg"] == pytest.approx(np.rad2deg(rudder), abs=0.05)
    assert moved["bank_deg"] > start["bank_deg"] + 0.5  # right aileron rolls right
    # A sideslip command replaces the yaw law's zero sideslip: in the lateral turbulence
    # the sideslip wanders by about a degree either way, so compare the means over 7 s,
    # after the first second, with and without a 3° command.
    slipping, coordinated = (deckland.Approach(scenario, seed=3) for _ in range(2))
    commanded, level = [], []
    for step in range(400):
        slipped = slipping.step({"sideslip_command_rad": np.deg2rad(3.0)})
        flown = coordinated.step()
        if step >= 50:
            commanded.append(slipped["sideslip_deg"])
            level.append(flown["sideslip_deg"])
    assert abs(np.mean(level)) < 0.5
    assert np.mean(commanded) == pytest.approx(3.0, abs=0.5)
    # Beyond a range, or in a 3-DOF approach: refused by name.
    with pytest.raises(ValueError, match="aileron_rad"):
        approach.step({"aileron_rad": 1.0})
    flat = deckland.Approach(longitudinal_scenario(), seed=3)
    assert "bank_command_rad" not in flat.action_ranges
    with pytest.raises(ValueError, match="3-D approach"):
        flat.step({"bank_command_rad": 0.1})
