"""Records the trajectories that ``test_gym_trajectories.py`` compares the Gymnasium
environments with, into ``gym_trajectories.npz`` beside this file:

    python python/tests/record_gym_trajectories.py

The file in the repository was written by the environment classes as they were before
issue 41 (item 6) merged them into one: ``deckland.env.CarrierLandingEnv`` and
``CarrierLandingVecEnv`` for ``deckland/CarrierLanding-v1``,
``deckland.env3d.CarrierLanding3DEnv`` and ``CarrierLanding3DVecEnv`` for
``deckland/CarrierLanding3D-v0``, and the separate single and vectorised steppers of
``python/src/gym/``. Run it again only for a change meant to alter what the
environments give (then say so in the change).

Each case flies a registered id through ``gymnasium.make`` (one environment, an episode
to its end, then a few steps of the next episode, whose seed the environment draws) or
``gymnasium.make_vec(..., vectorization_mode="vector_entry_point")`` (three
environments, with autoresets), with actions that depend only on a fixed generator and
on what the environment returned. What it records, for each case: every array the
environment returned, step after step (observations, rewards, the flags, ``info``'s
arrays), as a SHA-256 digest of its bytes (bit for bit) and, for the observations, every
50th row and the last rows in full (to show where two runs part); ``info``'s other
entries (outcome, wire, reason, grades, seeds, ...) as JSON, exact (floats as ``repr``).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any, Dict, List, Tuple

import gymnasium
import numpy as np

import deckland  # noqa: F401  (registers the ids)

FIXTURE = Path(__file__).resolve().parent / "gym_trajectories.npz"

V1 = "deckland/CarrierLanding-v1"
V3D = "deckland/CarrierLanding3D-v0"

#: (name, registered id, keyword arguments) of the single-environment cases.
SINGLE_CASES: List[Tuple[str, str, Dict[str, Any]]] = [
    ("v1-surfaces", V1, {"control": "surfaces"}),
    ("v1-attitude", V1, {"control": "attitude"}),
    ("v1-guidance", V1, {"control": "guidance"}),
    ("v1-attitude-forecast-sparse", V1, {"control": "attitude", "forecast": True, "reward": "sparse"}),
    (
        "v1-guidance-options",
        V1,
        {"control": "guidance", "control_interval_s": 0.04, "climb_rate_span_mps": 3.0, "rewards": {"trap": 50.0}},
    ),
    ("3d-surfaces", V3D, {"control": "surfaces"}),
    ("3d-attitude", V3D, {"control": "attitude"}),
    ("3d-guidance", V3D, {"control": "guidance"}),
    ("3d-attitude-forecast", V3D, {"control": "attitude", "forecast": True}),
    (
        "3d-attitude-options",
        V3D,
        {
            "control": "attitude",
            "bank_command_span_rad": 0.2,
            "sideslip_command_span_rad": 0.05,
            "rewards": {"off_centre": -10.0, "error_weight": 0.2},
        },
    ),
]

#: (name, registered id, keyword arguments) of the vectorised cases (3 environments).
VECTOR_CASES: List[Tuple[str, str, Dict[str, Any]]] = [
    ("vec-v1-attitude", V1, {"control": "attitude"}),
    ("vec-v1-surfaces-limit", V1, {"control": "surfaces", "max_episode_steps": 300}),
    ("vec-3d-attitude", V3D, {"control": "attitude"}),
    ("vec-3d-guidance-forecast", V3D, {"control": "guidance", "forecast": True}),
]

SEED = 5
#: Steps of the next episode flown after the first ended (single cases).
NEXT_STEPS = 40
#: Steps of the vectorised cases.
VECTOR_STEPS = 2000
#: Every how many rows of the observations are kept in full.
EVERY = 50


def digest(array: Any) -> str:
    """SHA-256 of an array's dtype, shape and bytes."""
    array = np.ascontiguousarray(array)
    h = hashlib.sha256()
    h.update(f"{array.dtype.str}{array.shape}".encode())
    h.update(array.tobytes())
    return h.hexdigest()


def _plain(value: Any) -> Any:
    """``value`` as JSON-able Python (numpy scalars and arrays turned into Python's)."""
    if isinstance(value, np.ndarray):
        return [_plain(v) for v in value.tolist()]
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _policy(rng: np.random.Generator, pilot: np.ndarray) -> np.ndarray:
    """The autopilot's action with a little noise, the wave-off (last entry) off."""
    action = np.asarray(pilot, dtype=np.float32) + rng.uniform(-0.05, 0.05, size=len(pilot)).astype(np.float32)
    action = np.clip(action, -1.0, 1.0).astype(np.float32)
    action[-1] = -1.0
    return action


def _summary(rows: Dict[str, List[Any]]) -> Dict[str, Any]:
    """The digests of the stacked rows, and the observations' rows kept in full."""
    out: Dict[str, Any] = {}
    for key, values in rows.items():
        out[f"digest:{key}"] = digest(np.array(values))
    observations = np.array(rows["observation"])
    out["observation_rows"] = np.concatenate([observations[::EVERY], observations[-3:]])
    return out


def single(env_id: str, kwargs: Dict[str, Any]) -> Dict[str, Any]:
    """One episode to its end with seed :data:`SEED`, then :data:`NEXT_STEPS` of the
    next (its seed drawn by the environment)."""
    env = gymnasium.make(env_id, **kwargs)
    rng = np.random.default_rng(11)
    rows: Dict[str, List[Any]] = {k: [] for k in ("observation", "reward", "terminated", "truncated", "raw", "autopilot_action")}
    events: List[Any] = []
    observation, info = env.reset(seed=SEED)
    unwrapped = env.unwrapped
    events.append(
        {
            "observation_names": list(unwrapped.observation_names),
            "action_names": list(unwrapped.action_names),
            "spaces": [repr(env.action_space), repr(env.observation_space)],
        }
    )

    def keep(observation, reward, terminated, truncated, info):
        rows["observation"].append(observation)
        rows["reward"].append(np.float64(reward))
        rows["terminated"].append(bool(terminated))
        rows["truncated"].append(bool(truncated))
        rows["raw"].append(info["raw"])
        rows["autopilot_action"].append(info["autopilot_action"])
        # info's other entries, at the steps that have any (a reset, an episode's end).
        extra = {k: _plain(v) for k, v in sorted(info.items()) if k not in ("raw", "autopilot_action")}
        if extra:
            events.append({"row": len(rows["observation"]) - 1, **extra})

    keep(observation, 0.0, False, False, info)
    for episode in range(2):
        steps = 0
        while True:
            observation, reward, terminated, truncated, info = env.step(_policy(rng, info["autopilot_action"]))
            steps += 1
            keep(observation, reward, terminated, truncated, info)
            if terminated or truncated or (episode == 1 and steps == NEXT_STEPS):
                break
        if episode == 0:
            observation, info = env.reset()
            keep(observation, 0.0, False, False, info)
    out = _summary(rows)
    out["meta"] = events
    out["steps"] = len(rows["observation"])
    return out


def vector(env_id: str, kwargs: Dict[str, Any]) -> Dict[str, Any]:
    """Three environments over :data:`VECTOR_STEPS` steps with autoresets: environment
    0 flies the autopilot with a little noise, 1 random actions (the wave-off among
    them), 2 the zero action (the trim)."""
    envs = gymnasium.make_vec(env_id, num_envs=3, vectorization_mode="vector_entry_point", **kwargs)
    rng = np.random.default_rng(13)
    rows: Dict[str, List[Any]] = {k: [] for k in ("observation", "reward", "terminated", "truncated", "raw", "autopilot_action")}
    observation, info = envs.reset(seed=40)
    events: List[Any] = [{"seed": _plain(info["seed"])}]
    rows["observation"].append(observation)
    rows["raw"].append(info["raw"])
    rows["autopilot_action"].append(info["autopilot_action"])
    width = envs.single_action_space.shape[0]
    for t in range(VECTOR_STEPS):
        actions = np.zeros((3, width), dtype=np.float32)
        actions[0] = _policy(rng, info["autopilot_action"][0])
        actions[1] = rng.uniform(-1.0, 1.0, size=width).astype(np.float32)
        observation, reward, terminated, truncated, info = envs.step(actions)
        rows["observation"].append(observation)
        rows["reward"].append(reward)
        rows["terminated"].append(terminated)
        rows["truncated"].append(truncated)
        rows["raw"].append(info["raw"])
        rows["autopilot_action"].append(info["autopilot_action"])
        extra = {k: _plain(v) for k, v in sorted(info.items()) if k not in ("raw", "autopilot_action")}
        if extra:
            events.append({"t": t, **extra})
    out = _summary(rows)
    out["meta"] = events
    out["steps"] = len(rows["observation"])
    return out


def record() -> Dict[str, Dict[str, Any]]:
    """Every case's record, by name."""
    cases = {name: single(env_id, kwargs) for name, env_id, kwargs in SINGLE_CASES}
    cases.update({name: vector(env_id, kwargs) for name, env_id, kwargs in VECTOR_CASES})
    return cases


def to_arrays(cases: Dict[str, Dict[str, Any]]) -> Dict[str, np.ndarray]:
    """The records as the arrays of the ``.npz`` file: ``NAME/observation_rows``, and
    ``NAME/json`` (every other entry, as JSON text)."""
    arrays: Dict[str, np.ndarray] = {}
    for name, case in cases.items():
        arrays[f"{name}/observation_rows"] = case["observation_rows"]
        rest = {k: v for k, v in case.items() if k != "observation_rows"}
        arrays[f"{name}/json"] = np.array(json.dumps(rest, sort_keys=True, allow_nan=True))
    return arrays


def main() -> None:
    arrays = to_arrays(record())
    np.savez_compressed(FIXTURE, **arrays)
    print(f"wrote {FIXTURE} ({FIXTURE.stat().st_size} bytes, {len(arrays) // 2} cases)")


if __name__ == "__main__":
    main()
