"""The Gymnasium environment: control authority, observations, rewards, the vectorised
environment against the single one, rendering, copying, the checker."""

from __future__ import annotations

import copy
import pickle
import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import deckland
from deckland.env import (
    CONTROL_MODES,
    ENV_ID,
    MAX_EPISODE_STEPS,
    REWARDS,
    CarrierLandingEnv,
    CarrierLandingVecEnv,
    longitudinal_scenario,
)

MODES = list(CONTROL_MODES)


def calm(scenario=None):
    """The environment's default scenario (the 3-DOF behind a stationary ship) in still
    air over a still deck, with a perfect pitch sensor."""
    scenario = (scenario or longitudinal_scenario()).copy()
    for key in (
        "environment.wind.mean_wind",
        "environment.wind.turbulence",
        "environment.wind.steady_wake",
        "environment.wind.periodic_wake",
        "environment.ship.enabled",
        "environment.pitch_noise.enabled",
    ):
        scenario[key] = False
    return scenario


def run_episode(env, seed, policy):
    """(observations, rewards, infos, terminated, truncated) of one episode."""
    observation, info = env.reset(seed=seed)
    observations, rewards, infos = [observation], [], [info]
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation, info))
        observations.append(observation)
        rewards.append(reward)
        infos.append(info)
        if terminated or truncated:
            return np.array(observations), np.array(rewards), infos, terminated, truncated


def zero(env):
    return lambda observation, info: np.zeros(env.action_space.shape, dtype=np.float32)


def autopilot(observation, info):
    return info["autopilot_action"]


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("render_mode", [None, "rgb_array"])
def test_every_mode_is_registered_and_passes_the_checker(mode, render_mode):
    env = gymnasium.make(ENV_ID, control=mode, render_mode=render_mode)
    assert env.spec.max_episode_steps == MAX_EPISODE_STEPS
    assert env.action_space.shape == (len(CONTROL_MODES[mode]),)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    assert [str(w.message) for w in caught] == []
    env.close()


def test_surfaces_with_a_zero_action_is_the_run_with_every_loop_replaced_by_the_trim():
    # The independent run: the stepping API with its own overrides of every loop (the
    # elevator and the thrust held at the trim), direct lift and the wave-off off in
    # the scenario. The surfaces mode must fly exactly it: no loop reaches a surface.
    env = CarrierLandingEnv(control="surfaces")
    scenario = env.description["scenario"].copy()
    scenario["control.direct_lift.enabled"] = False
    trim = env.description["trim"]
    held = {"elevator_rad": trim["elevator_rad"], "thrust_n": trim["thrust_n"]}
    seen = {"glide_path_error_m": 0, "theta_measured_rad": 2, "q_radps": 3, "alpha_rad": 4,
            "airspeed_mps": 5, "elevator_rad": 6, "range_to_go_m": 9}
    for seed in (3, 8):
        approach = deckland.Approach(scenario, seed=seed)
        approach.reset()
        _, _, infos, _, _ = run_episode(env, seed, zero(env))
        for info in infos[1:]:
            observation = approach.step(held)
            for key, index in seen.items():
                assert info["raw"][index] == observation[key], (seed, key, observation["time_s"])
        assert approach.done and approach.outcome == infos[-1]["outcome"]


def test_surfaces_with_a_zero_action_in_calm_air_holds_the_trim_of_the_independent_solver():
    # Open loop from trim in still air: the attitude, angle of attack, airspeed and sink
    # rate stay at the trim that deckland.trim solves for the glide slope, while the
    # built-in loops, which would fly the aircraft from 5 m above the path down onto it,
    # compute commands that differ.
    scenario = calm()
    scenario["approach.start_height_offset_m"] = 5.0
    env = CarrierLandingEnv(control="surfaces", scenario=scenario)
    trim = deckland.trim(speed_mps=69.1, gamma_deg=-3.5)
    _, _, infos, _, _ = run_episode(env, 1, zero(env))
    raw = np.array([info["raw"] for info in infos])
    assert np.max(np.abs(raw[:, 2] - np.deg2rad(trim.theta_deg))) < 1e-12
    assert np.max(np.abs(raw[:, 4] - np.deg2rad(trim.alpha_deg))) < 1e-12
    assert np.max(np.abs(raw[:, 5] - 69.1)) < 1e-12
    assert np.max(np.abs(raw[:, 3])) < 1e-12
    assert np.max(np.abs(raw[:, 1] - 69.1 * np.sin(np.deg2rad(3.5)))) < 1e-9
    assert np.max(np.abs(raw[:, 8])) == 0.0  # no direct lift
    pilot = np.array([info["autopilot_action"] for info in infos])
    assert np.max(np.abs(pilot[:, :3])) > 0.1
    assert abs(raw[0, 0] + 5.0) < 1e-9 and raw[-1, 0] < -4.0  # it stays above the path


@pytest.mark.parametrize("mode", MODES)
def test_the_loops_still_flying_are_listed(mode):
    env = CarrierLandingEnv(control=mode)
    _, info = env.reset(seed=1)
    loops = info["built_in_loops"]
    assert loops == env.built_in_loops
    names = {loop.split(":")[0] for loop in loops}
    assert names == {"surfaces": set(), "attitude": {"pitch_law"},
                     "guidance": {"sink_rate", "wake_feedforward", "pitch_law", "speed"}}[mode]


@pytest.mark.parametrize("mode", ["attitude", "guidance"])
def test_direct_lift_stays_off_where_the_agent_flies_the_path(mode):
    env = CarrierLandingEnv(control=mode)
    _, _, infos, _, _ = run_episode(env, 2, autopilot)
    assert all(info["raw"][8] == 0.0 for info in infos)


def test_the_wave_off_is_the_agents_and_flying_over_the_wires_after_it_is_a_wave_off():
    def climb(wave):
        return lambda observation, info: np.array([0.6, 1.0, 1.0 if wave else -1.0], dtype=np.float32)

    env = CarrierLandingEnv(control="attitude")
    observations, rewards, infos, terminated, _ = run_episode(env, 1, climb(True))
    waved = env.observation_names.index("waved_off")
    assert observations[0][waved] == 0.0 and np.all(observations[1:, waved] == 1.0)
    assert terminated and infos[-1]["outcome"] == "wave_off"
    assert rewards[-1] <= REWARDS["wave_off"]
    # The LSO grades the agent's own wave-off OWO, 2 points (AIRBOSS's points table).
    assert (infos[-1]["lso_grade"], infos[-1]["lso_points"]) == ("own_wave_off", 2.0)
    assert all("lso_grade" not in info for info in infos[:-1])
    # The same flight without the decision: the physics' outcome, a bolter (2.5 points).
    _, _, infos, _, _ = run_episode(env, 1, climb(False))
    assert infos[-1]["outcome"] == "bolter"
    assert (infos[-1]["lso_grade"], infos[-1]["lso_points"]) == ("bolter", 2.5)
    # The autopilot never waves off for the agent: in the scenario it is off.
    assert env.description["scenario"]["control.wave_off.enabled"] is False


@pytest.mark.parametrize("reward", ["shaped", "sparse"])
def test_the_reward_is_the_documented_sum(reward):
    env = CarrierLandingEnv(control="attitude", reward=reward)
    _, rewards, infos, _, _ = run_episode(env, 5, autopilot)
    errors = np.array([info["raw"][0] for info in infos[1:]])
    per_step = -0.1 * np.minimum(errors**2, 100.0) * 0.02 if reward == "shaped" else np.zeros_like(errors)
    outcome = infos[-1]["outcome"]
    end = REWARDS[outcome] + (REWARDS["wire_bonus"][infos[-1]["wire"]] if outcome == "trap" else 0.0)
    expected = per_step.copy()
    expected[-1] += end
    assert np.allclose(rewards, expected, rtol=0, atol=1e-12)


def test_observations_are_normalised_and_the_raw_values_are_in_info():
    env = CarrierLandingEnv(control="attitude", forecast=True)
    observations, _, infos, _, _ = run_episode(env, 4, autopilot)
    rows = env.description["observations"]
    assert [row["name"] for row in rows][13:] == [
        "forecast_landing_point_height_m", "forecast_landing_point_climb_rate_mps",
        "forecast_ramp_height_m", "forecast_deck_pitch_rad", "forecast_available",
        "forecast_ramp_height_sigma_m", "forecast_landing_point_climb_rate_sigma_mps"]
    offsets = np.array([row["offset"] for row in rows])
    scales = np.array([row["scale"] for row in rows])
    raw = np.array([info["raw"] for info in infos])
    low, high = env.observation_space.low, env.observation_space.high
    expected = np.clip((raw - offsets) / scales, low, high).astype(np.float32)
    assert np.array_equal(observations, expected)
    assert np.all(np.abs(observations[:, :12]) < 12.0)
    # The default deck predictor (the estimator) forecasts all along; the forecast moves.
    assert np.all(observations[:, 17] == 1.0) and np.std(raw[:, 13]) > 0.1
    # Its uncertainty: the default guidance asks for it (a ramp-strike probability limit),
    # so the σ are positive, and the ramp's grows with the horizon (the sea still to
    # come): larger far out than at the ramp.
    sigmas = raw[:, 18:]
    assert np.all(sigmas > 0.0) and np.all(np.isfinite(sigmas))
    assert sigmas[0, 0] > sigmas[-1, 0]
    # Raw against the stepping API's own observation: the approach flown by the same
    # commands shows the same numbers (θ with the sensor's noise).
    approach = deckland.Approach(env.description["scenario"], seed=4)
    first = approach.reset()
    assert raw[0, 2] == first["theta_measured_rad"] != first["theta_rad"]
    assert raw[0, 0] == first["glide_path_error_m"] and raw[0, 9] == first["range_to_go_m"]


def test_the_vectorised_environment_is_the_single_one_bit_for_bit_across_autoresets():
    n, steps = 3, 1500
    envs = gymnasium.make_vec(ENV_ID, num_envs=n, vectorization_mode="vector_entry_point")
    assert isinstance(envs, CarrierLandingVecEnv)
    actions = np.random.default_rng(7).uniform(-1, 1, size=(steps, n, 3)).astype(np.float32)
    actions[..., 0] = actions[..., 0] * 0.1 - 0.9  # nose down: each episode ends in seconds
    actions[..., 2] = -1.0  # no wave-off
    observation, _ = envs.reset(seed=40)
    vector = [observation]
    rewards, ends, outcomes = [], [], []
    for t in range(steps):
        observation, reward, terminated, truncated, info = envs.step(actions[t])
        vector.append(observation)
        rewards.append(reward)
        ends.append(terminated | truncated)
        # Gymnasium's dict of arrays: the outcome (with its mask) only at steps where
        # episodes end, None for the others.
        assert ("outcome" in info) == bool(ends[-1].any())
        outcomes.append(info["outcome"] if "outcome" in info else [None] * n)
        if "outcome" in info:
            assert np.array_equal(info["_outcome"], ends[-1])
            assert all((name is None) != ended for name, ended in zip(info["outcome"], ends[-1]))
    vector, rewards, ends = np.array(vector), np.array(rewards), np.array(ends)
    assert ends.sum() >= 2 * n  # every environment reset at least once on its own
    for i in range(n):
        env = gymnasium.make(ENV_ID)
        observation, _ = env.reset(seed=40 + i)
        assert np.array_equal(observation, vector[0, i])
        ended = False
        for t in range(steps):
            if ended:  # next-step autoreset: the next seed from the env's own generator
                observation, _ = env.reset()
                reward, ended = 0.0, False
            else:
                observation, reward, terminated, truncated, info = env.step(actions[t, i])
                ended = terminated or truncated
                assert outcomes[t][i] == info.get("outcome"), (i, t)
            assert np.array_equal(observation, vector[t + 1, i]), (i, t)
            assert reward == rewards[t, i] and ended == ends[t, i], (i, t)


def test_the_vectorised_environment_truncates_at_its_step_limit_and_reports_outcomes():
    envs = CarrierLandingVecEnv(num_envs=2, max_episode_steps=5)
    envs.reset(seed=1)
    for _ in range(4):
        _, _, terminated, truncated, info = envs.step(np.zeros((2, 3), dtype=np.float32))
        assert not truncated.any() and "outcome" not in info
    _, _, terminated, truncated, info = envs.step(np.zeros((2, 3), dtype=np.float32))
    assert truncated.all() and not terminated.any()
    observation, reward, terminated, truncated, _ = envs.step(np.ones((2, 3), dtype=np.float32))
    assert np.all(reward == 0.0) and not (terminated | truncated).any()  # reset


def test_vectorised_bad_actions_are_refused_naming_the_environment():
    envs = CarrierLandingVecEnv(num_envs=2)
    envs.reset(seed=1)
    bad = np.zeros((2, 3), dtype=np.float32)
    bad[1, 0] = 1.5
    with pytest.raises(ValueError, match=r"`actions\[1\]` = \[1.5, 0.0, 0.0\] is not allowed"):
        envs.step(bad)
    with pytest.raises(ValueError, match=r"shape \(2, 3\)"):
        envs.step(np.zeros((3, 3), dtype=np.float32))


@pytest.mark.parametrize("mode", MODES)
def test_a_copy_or_a_pickle_continues_the_episode_bit_for_bit(mode):
    env = CarrierLandingEnv(control=mode)
    env.reset(seed=9)
    rng = np.random.default_rng(1)
    for _ in range(50):
        env.step(rng.uniform(-0.2, 0.2, env.action_space.shape).astype(np.float32))
    copies = [copy.deepcopy(env), pickle.loads(pickle.dumps(env))]
    actions = rng.uniform(-0.2, 0.2, (100,) + env.action_space.shape).astype(np.float32)
    runs = []
    for e in [env] + copies:
        runs.append([e.step(a)[0] for a in actions])
        runs[-1].append(e.reset()[0])  # the generator is copied too
    assert all(np.array_equal(np.array(runs[0]), np.array(r)) for r in runs[1:])
    assert pickle.loads(pickle.dumps(CarrierLandingEnv())).reset(seed=1)[0].shape == (13,)


def test_rgb_array_frames_show_the_aircraft_moving():
    env = CarrierLandingEnv(render_mode="rgb_array")
    env.reset(seed=1)
    first = env.render()
    assert first.shape == (200, 400, 3) and first.dtype == np.uint8
    for _ in range(200):
        env.step(np.zeros(3, dtype=np.float32))
    later = env.render()
    assert len(np.unique(first.reshape(-1, 3), axis=0)) >= 5
    assert np.count_nonzero(np.any(first != later, axis=2)) > 20
    assert CarrierLandingEnv().render() is None


def test_bad_options_and_actions_are_refused_by_name():
    with pytest.raises(ValueError, match="`control` = \"rudder\" is not allowed"):
        CarrierLandingEnv(control="rudder")
    with pytest.raises(ValueError, match="`reward` = \"dense\" is not allowed"):
        CarrierLandingEnv(reward="dense")
    with pytest.raises(ValueError, match="`render_mode` = 'human' is not allowed"):
        CarrierLandingEnv(render_mode="human")
    with pytest.raises(ValueError, match="`pitch_command_span_rad` = 2.0 is not allowed"):
        CarrierLandingEnv(pitch_command_span_rad=2.0)
    with pytest.raises(ValueError, match="`thrust_span_n` = -1.0 is not allowed"):
        CarrierLandingEnv(thrust_span_n=-1.0)
    with pytest.raises(ValueError, match=r"rewards\[\"trap\"\]"):
        CarrierLandingEnv(rewards={"trap": "many"})
    env = CarrierLandingEnv(control="guidance")
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros(2, dtype=np.float32))
    env.reset(seed=1)
    for action in ([1.5, 0.0], [np.nan, 0.0], [0.0, np.inf], [0.0], [0.0, 0.0, 0.0]):
        with pytest.raises(ValueError, match=r"`action` = .* is not allowed: expected 2 numbers in \[-1, 1\]"):
            env.step(np.array(action, dtype=np.float32))
    with pytest.raises(ValueError, match="`action` = 'up'"):
        env.step("up")
    assert env.unwrapped._core.time_s == 0.0
    env.step(np.array([1.0, -1.0], dtype=np.float32))  # the edges are in the space


def test_the_autopilot_as_a_policy_in_guidance_mode_flies_the_cascade():
    # Guidance: the agent's climb-rate command replaces the guidance loop's; sending the
    # loop's own command back changes only its sampling (held over 20 ms), so the
    # approach ends as the cascade's does.
    env = CarrierLandingEnv(control="guidance", scenario=calm())
    _, _, infos, _, _ = run_episode(env, 1, autopilot)
    flight = deckland.fly(calm(), seed=1)
    assert infos[-1]["outcome"] == flight.outcome
    assert abs(infos[-1]["time_s"] - flight.summary["end_time_s"]) < 0.1
