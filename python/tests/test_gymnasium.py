"""The Gymnasium environment: registered, passes the checker, reproducible, rewards."""

from __future__ import annotations

import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import deckland
from deckland.env import ENV_ID, ERROR_WEIGHT, REWARDS, CarrierLandingEnv


def test_the_environment_is_registered_and_passes_the_checker():
    env = gymnasium.make(ENV_ID)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped)
    assert [str(w.message) for w in caught] == []
    env.close()


def run_episode(env, seed, policy):
    observation, info = env.reset(seed=seed)
    trajectory = [observation]
    rewards = []
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation, info))
        trajectory.append(observation)
        rewards.append(reward)
        if terminated or truncated:
            return np.array(trajectory), np.array(rewards), info, terminated, truncated


def follow_the_cascade(env):
    return lambda observation, info: env.action_for(info["theta_command_rad"], info["thrust_command_n"])


def test_episodes_with_the_same_seed_are_the_same():
    env = CarrierLandingEnv()
    actions = np.random.default_rng(0).uniform(-0.05, 0.05, size=(10_000, 2)).astype(np.float32)

    def replay():
        step = iter(actions)
        return run_episode(env, 17, lambda o, i: next(step))

    first, second = replay(), replay()
    assert np.array_equal(first[0], second[0])
    assert np.array_equal(first[1], second[1])


def test_reset_with_a_seed_is_the_approach_with_that_seed():
    env = CarrierLandingEnv()
    _, info = env.reset(seed=12)
    assert info == deckland.Approach(seed=12).reset()
    # Without a seed, the next seeds come from the generator the last seed set.
    _, first = env.reset()
    env.reset(seed=12)
    _, again = env.reset()
    assert first == again and first["time_s"] == 0.0
    assert env.approach.seed != 12


def test_the_cascade_as_an_agent_lands_and_is_rewarded_for_the_outcome():
    env = CarrierLandingEnv()
    trajectory, rewards, info, terminated, truncated = run_episode(env, 1, follow_the_cascade(env))
    outcome = info["outcome"]
    assert terminated != truncated
    assert outcome in {"trap", "bolter", "wave_off", "ramp_strike", "hard_landing", "diverged", "timeout"}
    interval = env.approach.control_interval_s
    error = info["glide_path_error_m"]
    shaping = -ERROR_WEIGHT * min(error * error, 100.0) * interval
    terminal = REWARDS[outcome] + (REWARDS["wire_bonus"][info["wire"]] if outcome == "trap" else 0.0)
    assert rewards[-1] == pytest.approx(shaping + terminal, abs=1e-12)
    assert np.all(rewards[:-1] <= 0.0)
    assert trajectory.dtype == np.float32 and np.all(np.isfinite(trajectory))


def test_a_large_glide_path_error_is_a_wave_off():
    env = CarrierLandingEnv(wave_off_error_m=0.5, rewards=dict(REWARDS, wave_off=-7.0))
    env.reset(seed=1)
    while True:
        _, reward, terminated, truncated, info = env.step(np.array([1.0, 1.0], dtype=np.float32))
        if terminated or truncated:
            break
    assert terminated and info["outcome"] == "wave_off"
    assert abs(info["glide_path_error_m"]) > 0.5
    assert reward < -7.0 + 1e-9
    with pytest.raises(RuntimeError, match="call reset"):
        env.step(np.zeros(2, dtype=np.float32))


def test_actions_map_onto_the_commands():
    env = CarrierLandingEnv()
    env.reset(seed=1)
    trim = env.approach.trim
    assert env.commands(np.zeros(2)) == {"pitch_command_rad": trim["theta_rad"], "thrust_n": trim["thrust_n"]}
    assert np.allclose(env.action_for(trim["theta_rad"] + np.deg2rad(5.0), trim["thrust_n"]), [0.5, 0.0])
    with pytest.raises(ValueError, match="`action`"):
        env.commands(np.array([np.nan, 0.0]))
