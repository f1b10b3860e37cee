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
    assert turn[-1] - turn[0] > np.deg2rad(5.0)
    assert final_cross_track_m(env, infos) > final_cross_track_m(env, flown) + 5.0


def trajectory_of_a_new_env(mode, seed, actions):
    env = CarrierLanding3DEnv(control=mode)
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

    def trajectory(seed):
        observation, _ = env.reset(seed=seed)
        observations = [observation]
        for action in actions:
            observation, _, terminated, truncated, _ = env.step(action)
            observations.append(observation)
            if terminated or truncated:
                break
        return np.array(observations)

    first = trajectory(11)
    assert np.array_equal(first, trajectory(11))
    assert np.array_equal(first, trajectory_of_a_new_env(mode, 11, actions))
    assert not np.array_equal(first, trajectory(12))


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
        CarrierLanding3DEnv(scenario=deckland.Scenario.default())
    env = CarrierLanding3DEnv()
    env.reset(seed=1)
    with pytest.raises(ValueError, match="bank_command"):
        env.step(np.zeros(3, dtype=np.float32))
