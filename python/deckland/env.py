"""The Gymnasium environments ``deckland/CarrierLanding-v1`` (the longitudinal approach:
land the F/A-18 on the moving carrier deck, with the authority the ``control`` mode gives
the agent) and ``deckland/CarrierLanding3D-v0`` (the 3-D approach of the 6-DOF F/A-18 to
the angled deck, with roll and yaw commands added to the action): one environment class,
:class:`CarrierLandingEnv`, and one vectorised class, :class:`CarrierLandingVecEnv`, each
2-D or 3-D by its option ``three_dimensional``; :class:`CarrierLanding3DEnv` and
:class:`CarrierLanding3DVecEnv` are the same classes 3-D by default (the 3-D id's entry
points; :mod:`deckland.env3d` re-exports them with the 3-D constants).

The whole specification (modes, spaces, observation table with units and sources,
reward term by term, seeding, vectorised stepping, rendering, and what the 3-D
environment adds) is in ``docs/rl-environment.md``; this module's objects carry it:
:data:`CONTROL_MODES`, :data:`CONTROL_MODES_3D`, :data:`REWARDS`, :data:`REWARDS_3D`,
:class:`CarrierLandingEnv`, :class:`CarrierLandingVecEnv`.

In short: one step is one control interval (20 ms), stepped in Rust. The automatic
wave-off is off in every mode: the last action entry is the agent's wave-off (> 0
waves off, for the rest of the episode), and the outcome is the physics' alone (ramp
crossing, touchdown, the wires; flying over the last wire after waving off is a
``wave_off``, without it a ``bolter``). The observation is normalised (``info["raw"]``
holds it in physical units); ``info["autopilot_action"]`` is the action the built-in
cascade would take now (the autopilot as a policy).

The 3-D environment (``three_dimensional=True``) adds:

- the action's lateral entries, before the wave-off (:data:`CONTROL_MODES_3D`): in
  ``attitude`` the bank command and the sideslip command (the built-in roll and yaw laws
  fly the aileron and rudder), in ``surfaces`` the aileron and rudder commands, in
  ``guidance`` the bank command; the built-in lineup guidance's bank command is replaced
  in every mode;
- the observation's lateral entries after the 2-D ones: cross track and its rate, bank,
  heading to the centreline, sideslip, roll and yaw rate, aileron and rudder;
- the shaped reward's error: the hook's distance to the glide path's line (the
  glide-path error and the cross track, squared and summed);
- at the end, ``info["off_centre"]`` (the touchdown more than 6.1 m off the
  centreline; None without a touchdown) and :data:`REWARDS_3D`'s ``off_centre`` added.

Its default scenario is :func:`crosswind_scenario`: the moderate sea with a 5 m/s
crosswind (``scenarios/crosswind.toml``); the 2-D environment's is
:func:`longitudinal_scenario`.
"""

from __future__ import annotations

import copy
import numbers
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from ._deckland import MAX_SEED, Scenario, _Env, _EnvConfig, _VecEnv

ENV_ID = "deckland/CarrierLanding-v1"
ENV_ID_3D = "deckland/CarrierLanding3D-v0"

#: The episode's step limit in the registration: the default scenario's time limit
#: (60 s) in 20-ms steps.
MAX_EPISODE_STEPS = 3000

#: The control modes: what the agent commands, the action's entries in order.
CONTROL_MODES = {
    "surfaces": ("elevator", "thrust", "direct_lift", "wave_off"),
    "attitude": ("pitch_command", "thrust", "wave_off"),
    "guidance": ("climb_rate_command", "wave_off"),
}

#: The control modes of the 3-D environment: the action's entries in order.
CONTROL_MODES_3D = {
    "surfaces": ("elevator", "thrust", "direct_lift", "aileron", "rudder", "wave_off"),
    "attitude": ("pitch_command", "thrust", "bank_command", "sideslip_command", "wave_off"),
    "guidance": ("climb_rate_command", "bank_command", "wave_off"),
}

#: The rewards: at the end per outcome, a trap's wire bonus, and the shaped reward's
#: weight of the squared glide-path error (per second, 1/m²) with its cap (m²).
REWARDS: Dict[str, Any] = {
    "trap": 100.0,
    "wire_bonus": {1: 0.0, 2: 15.0, 3: 25.0, 4: 5.0},
    "bolter": -50.0,
    "hard_landing": -100.0,
    "ramp_strike": -200.0,
    "wave_off": -50.0,
    "diverged": -200.0,
    "timeout": 0.0,
    "error_weight": 0.1,
    "error_cap_m2": 100.0,
}

#: The rewards of the 3-D environment: the 2-D environment's and, added at the end of an
#: approach that touched down off the centreline, ``off_centre``.
REWARDS_3D: Dict[str, Any] = dict(REWARDS, off_centre=-100.0)

#: The spans of the 3-D environment's lateral action entries (rad) when not given: a
#: full entry (±1) is the trim ± the span.
LATERAL_SPANS: Dict[str, float] = {
    "bank_command_span_rad": float(np.deg2rad(20.0)),
    "sideslip_command_span_rad": float(np.deg2rad(5.0)),
    "aileron_span_rad": float(np.deg2rad(10.0)),
    "rudder_span_rad": float(np.deg2rad(10.0)),
}


#: The longitudinal environment's settings over the default scenario when it is given no
#: scenario: the 3-DOF aircraft behind a stationary ship. The default scenario is the 3-D
#: approach (6-DOF, the ship at 15 kn); this environment stays the longitudinal one, bit
#: for bit, with its published observation, reward and speed figures
#: (``docs/rl-environment.md``, "Scenario"), in the paper's sea (the filter ship).
#: The wave-off as the environments flew it before the seaway's recovery limits and the
#: closed-loop probabilities: no early "foul deck: motion" check, no airspeed limit in
#: the wave-off (the paper's sea, which the environments fly, is beyond those limits),
#: the ramp-strike probability on the forecast's clearance, the hard-landing
#: probability on the hook's sink now with a 1.0-m/s scatter, and no commit gate (what a
#: scenario file that names none of these keys flies, ``scenarios/crosswind.toml`` among
#: them).
WAVE_OFF_BEFORE_RECOVERY: Dict[str, Any] = {
    "control.wave_off.climb_out_airspeed_margin_mps": 0.0,
    "control.wave_off.recovery.foul_deck_time_to_go_s": 0.0,
    "control.wave_off.recovery.foul_deck_model": "linear",
    "control.wave_off.ramp_strike_model": "forecast",
    "control.wave_off.hard_landing_model": "forecast",
    "control.wave_off.touchdown_sink_rate_sigma_mps": 1.0,
    "control.wave_off.max_commit_ramp_strike_probability": 0.0,
}

LONGITUDINAL_SETTINGS: Dict[str, Any] = {
    "environment.ship.model": "filters",
    "aircraft.model": "3dof",
    "environment.ship.forward_speed_mps": 0.0,
    **WAVE_OFF_BEFORE_RECOVERY,
}

#: The crosswind scenario's settings over the default scenario (``scenarios/crosswind.toml``).
CROSSWIND_SETTINGS: Dict[str, Any] = {
    "environment.ship.model": "filters",
    "aircraft.model": "6dof",
    "approach.three_dimensional": True,
    "environment.ship.heave_rms_m": 1.0,
    "environment.ship.pitch_rms_deg": 0.75,
    "environment.ship.roll_rms_deg": 0.5,
    "environment.ship.yaw_rms_deg": 0.15,
    "environment.ship.sway_rms_m": 0.25,
    "environment.ship.forward_speed_mps": 7.7,
    "environment.wind.crosswind_mps": 5.0,
    **WAVE_OFF_BEFORE_RECOVERY,
}


def _default_with(settings: Dict[str, Any]) -> Scenario:
    """The default scenario with ``settings`` set."""
    scenario = Scenario.default()
    for key, value in settings.items():
        scenario[key] = value
    return scenario


def longitudinal_scenario() -> Scenario:
    """The longitudinal environment's default: the default scenario flown by the 3-DOF
    aircraft behind a stationary ship (:data:`LONGITUDINAL_SETTINGS`)."""
    return _default_with(LONGITUDINAL_SETTINGS)


def crosswind_scenario() -> Scenario:
    """The 3-D environment's default: the 6-DOF approach in a moderate sea with a 5 m/s
    crosswind (the settings of ``scenarios/crosswind.toml``, :data:`CROSSWIND_SETTINGS`)."""
    return _default_with(CROSSWIND_SETTINGS)


def _whole(name: str, value: Any) -> int:
    """``value`` as an int, refusing what Python would convert without a word: a bool
    (an int to Python), a float such as 1.5, a string (issue 45, R9)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"`{name}` = {value!r} is not allowed: expected a whole number (an int, not a bool, float or string)")
    return int(value)


def _real(name: str, value: Any) -> float:
    """``value`` as a float, refusing a bool, a complex or a string."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"`{name}` = {value!r} is not allowed: expected a real number (an int or float, not a bool, complex or string)")
    return float(value)


def _flag(name: str, value: Any) -> bool:
    """``value`` as a bool, refusing anything but True or False (``"no"`` is truthy)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"`{name}` = {value!r} is not allowed: expected True or False")
    return bool(value)


def _check_reward_keys(rewards: Optional[Dict[str, Any]], known: Dict[str, Any]) -> None:
    """Refuses a key of ``rewards`` that ``known`` does not have (it would be ignored)."""
    if rewards is None:
        return
    if not isinstance(rewards, dict):
        raise TypeError(f"`rewards` = {rewards!r} is not allowed: expected a dict or None")
    unknown = [key for key in rewards if key not in known]
    if unknown:
        raise ValueError(
            f"`rewards` has the unknown key {unknown[0]!r}: expected keys of {', '.join(known)}"
        )


def _arguments(given: Dict[str, Any]) -> Dict[str, Any]:
    """A constructor's arguments (its ``locals()`` as it starts), without ``self``."""
    return {name: value for name, value in given.items() if name not in ("self", "__class__")}


def _is_three_dimensional(env: Any, three_dimensional: Optional[bool]) -> bool:
    """Whether ``env`` is 3-D: ``three_dimensional``, else its class's default."""
    if three_dimensional is None:
        return bool(env.three_dimensional_by_default)
    return _flag("three_dimensional", three_dimensional)


def _core_options(three_dimensional: bool, options: Dict[str, Any]) -> Dict[str, Any]:
    """The keyword arguments of the Rust core's configuration (``_EnvConfig``, which
    ``_Env`` and ``_VecEnv`` take) from the options of
    :class:`CarrierLandingEnv` (by name), checked: a wrong type, an unknown reward and a
    lateral span given to the 2-D environment are refused by name."""
    known = REWARDS_3D if three_dimensional else REWARDS
    rewards = options["rewards"]
    _check_reward_keys(rewards, known)
    table = dict(known)
    if rewards is not None:
        table.update(rewards)
    spans = {name: options[name] for name in LATERAL_SPANS}
    if not three_dimensional:
        for name, value in spans.items():
            if value is not None:
                raise ValueError(
                    f"`{name}` = {value!r} is not allowed: the 2-D environment has no lateral "
                    "action (it is an option of the 3-D one, three_dimensional=True)"
                )
    scenario = options["scenario"]
    if scenario is None:
        scenario = crosswind_scenario() if three_dimensional else longitudinal_scenario()
    thrust_span_n = options["thrust_span_n"]
    core = dict(
        scenario=scenario,
        control=options["control"],
        control_interval_s=_real("control_interval_s", options["control_interval_s"]),
        pitch_command_span_rad=_real("pitch_command_span_rad", options["pitch_command_span_rad"]),
        thrust_span_n=None if thrust_span_n is None else _real("thrust_span_n", thrust_span_n),
        elevator_span_rad=_real("elevator_span_rad", options["elevator_span_rad"]),
        climb_rate_span_mps=_real("climb_rate_span_mps", options["climb_rate_span_mps"]),
        rewards=table,
        reward=options["reward"],
        forecast=_flag("forecast", options["forecast"]),
        lateral_spans=None,
    )
    if three_dimensional:
        core["lateral_spans"] = tuple(
            _real(name, LATERAL_SPANS[name] if value is None else value) for name, value in spans.items()
        )
    return core


def _spaces(description: Dict[str, Any]) -> Tuple[spaces.Box, spaces.Box]:
    rows = description["observations"]
    low = np.array([row["low"] for row in rows], dtype=np.float32)
    high = np.array([row["high"] for row in rows], dtype=np.float32)
    actions = len(description["actions"])
    return (
        spaces.Box(-1.0, 1.0, shape=(actions,), dtype=np.float32),
        spaces.Box(low, high, dtype=np.float32),
    )


def _read_description(env: Any) -> Tuple[spaces.Box, spaces.Box]:
    """Sets ``env``'s description and names from its core; returns the spaces of one
    environment (action, observation)."""
    env.description = env._core.describe()
    env.observation_names = tuple(row["name"] for row in env.description["observations"])
    env.action_names = tuple(env.description["actions"])
    env.built_in_loops = tuple(env.description["built_in_loops"])
    return _spaces(env.description)


def _check_render_mode(render_mode: Optional[str]) -> None:
    if render_mode not in (None, "rgb_array"):
        raise ValueError(f"`render_mode` = {render_mode!r} is not allowed: expected None or 'rgb_array'")


def _draw_seed(generator: np.random.Generator) -> int:
    return int(generator.integers(0, MAX_SEED, endpoint=True))


class CarrierLandingEnv(gymnasium.Env):
    """Land the F/A-18 on the moving carrier deck (``docs/rl-environment.md``): the
    longitudinal approach (``deckland/CarrierLanding-v1``) or, with
    ``three_dimensional=True``, the 3-D approach of the 6-DOF aircraft to the angled
    deck (``deckland/CarrierLanding3D-v0``).

    ``control`` is ``"surfaces"``, ``"attitude"`` (the default) or ``"guidance"``
    (:data:`CONTROL_MODES`, :data:`CONTROL_MODES_3D`); ``scenario`` a
    :class:`deckland.Scenario` (the default: :func:`longitudinal_scenario`, adverse
    conditions on the 3-DOF aircraft behind a stationary ship; in 3-D
    :func:`crosswind_scenario`, and it must be a 3-D approach; its automatic wave-off is
    turned off); ``control_interval_s`` the length of a step; the spans scale the
    actions (zero is the trim): ``pitch_command_span_rad`` (10°), ``thrust_span_n`` (a
    quarter of the maximum thrust), ``elevator_span_rad`` (10°), ``climb_rate_span_mps``
    (5 m/s), and in 3-D only (:data:`LATERAL_SPANS`) ``bank_command_span_rad`` (20°),
    ``sideslip_command_span_rad`` (5°), ``aileron_span_rad`` (10°), ``rudder_span_rad``
    (10°); ``reward`` is ``"shaped"`` or ``"sparse"``; ``rewards`` replaces entries of
    :data:`REWARDS` (3-D: :data:`REWARDS_3D`); ``forecast=True`` adds the deck forecast
    and its uncertainty to the observation; ``render_mode`` is None or ``"rgb_array"``.
    ``three_dimensional`` not given is the class's :attr:`three_dimensional_by_default`
    (False here, True in :class:`CarrierLanding3DEnv`).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 50}

    #: Whether the environment is 3-D when ``three_dimensional`` is not given.
    three_dimensional_by_default = False

    def __init__(
        self,
        control: str = "attitude",
        scenario: Optional[Scenario] = None,
        control_interval_s: float = 0.02,
        pitch_command_span_rad: float = float(np.deg2rad(10.0)),
        thrust_span_n: Optional[float] = None,
        elevator_span_rad: float = float(np.deg2rad(10.0)),
        climb_rate_span_mps: float = 5.0,
        rewards: Optional[Dict[str, Any]] = None,
        reward: str = "shaped",
        forecast: bool = False,
        render_mode: Optional[str] = None,
        *,
        three_dimensional: Optional[bool] = None,
        bank_command_span_rad: Optional[float] = None,
        sideslip_command_span_rad: Optional[float] = None,
        aileron_span_rad: Optional[float] = None,
        rudder_span_rad: Optional[float] = None,
    ) -> None:
        # The arguments as given, to build a copy (first: nothing else is local yet).
        self._kwargs = _arguments(locals())
        super().__init__()
        _check_render_mode(render_mode)
        self.three_dimensional = _is_three_dimensional(self, three_dimensional)
        self.control = control
        self.render_mode = render_mode
        self._core = _Env(_EnvConfig(**_core_options(self.three_dimensional, self._kwargs)))
        self.action_space, self.observation_space = _read_description(self)
        self._episode_seed: Optional[int] = None

    def reset(
        self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
    ) -> Tuple[np.ndarray, Dict[str, Any]]:
        """Starts an episode: ``seed`` flies the scenario with that seed (every random
        stream's); without one the next seed is drawn from the environment's generator,
        itself seeded by the last ``reset(seed=…)``."""
        if seed is not None:
            seed = _whole("seed", seed)
        super().reset(seed=seed)
        if seed is None:
            seed = _draw_seed(self.np_random)
        observation, raw, pilot = self._core.reset(seed)
        self._episode_seed = int(seed)
        info = {
            "raw": raw,
            "autopilot_action": pilot,
            "seed": int(seed),
            "built_in_loops": self.built_in_loops,
        }
        return observation, info

    def step(self, action: np.ndarray) -> Tuple[np.ndarray, float, bool, bool, Dict[str, Any]]:
        return self._core.step(action)

    def render(self) -> Optional[np.ndarray]:
        """The side view of the approach now, a (200, 400, 3) uint8 array (with
        ``render_mode="rgb_array"``; None otherwise)."""
        if self.render_mode != "rgb_array":
            return None
        return self._core.render()

    @property
    def seed_of_episode(self) -> Optional[int]:
        """The seed of the episode flown (None before the first reset)."""
        return self._episode_seed

    # Pickling and copying: the options, the generator, and the episode replayed from its
    # seed with its actions (the simulation is deterministic, so the copy is the
    # original bit for bit).
    def __getstate__(self) -> Dict[str, Any]:
        return {
            "kwargs": self._kwargs,
            "np_random": None if self._np_random is None else copy.deepcopy(self._np_random),
            "seed": self._episode_seed,
            "actions": self._core.actions() if self._episode_seed is not None else None,
        }

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self.__init__(**state["kwargs"])
        if state["seed"] is not None:
            self._core.reset(state["seed"])
            self._episode_seed = state["seed"]
            for action in state["actions"]:
                self.step(action)
        self._np_random = state["np_random"]

    def __deepcopy__(self, memo: Dict[int, Any]) -> "CarrierLandingEnv":
        clone = type(self).__new__(type(self))
        clone.__setstate__(copy.deepcopy(self.__getstate__(), memo))
        return clone


#: ``info["off_centre"]`` by the core's flag + 1: no touchdown, within the limit, off centre.
_OFF_CENTRE = np.array([None, False, True], dtype=object)


class CarrierLandingVecEnv(VectorEnv):
    """``num_envs`` environments of :class:`CarrierLandingEnv` stepped in one call to
    Rust, over threads (``RAYON_NUM_THREADS`` in all, the calling one included;
    default: one per core): numpy arrays in and out, no Python per environment; ``info``
    is a dict of arrays (``docs/rl-environment.md``). The 3-D environments' ``info``
    also holds, when episodes end, ``off_centre`` (an object array: True or False after
    a touchdown, None without one) and its mask ``_off_centre``.

    Autoreset is Gymnasium's next-step mode: the step after an episode ends resets
    that environment (its action ignored, reward 0). Seeds follow Gymnasium:
    ``reset(seed=s)`` seeds environment i with ``s + i`` (a list gives each its own);
    each environment then draws the seeds of its next episodes from its own generator,
    as a single environment does, so environment i flies what a single environment
    reset with the same seed flies, bit for bit. ``max_episode_steps`` truncates an
    episode (the registration's 3000 by default). Same options as
    :class:`CarrierLandingEnv` (``three_dimensional`` not given: False here, True in
    :class:`CarrierLanding3DVecEnv`).
    """

    metadata = {
        "render_modes": ["rgb_array"],
        "render_fps": 50,
        "autoreset_mode": AutoresetMode.NEXT_STEP,
    }

    #: Whether the environments are 3-D when ``three_dimensional`` is not given.
    three_dimensional_by_default = False

    def __init__(
        self,
        num_envs: int = 1,
        control: str = "attitude",
        scenario: Optional[Scenario] = None,
        control_interval_s: float = 0.02,
        pitch_command_span_rad: float = float(np.deg2rad(10.0)),
        thrust_span_n: Optional[float] = None,
        elevator_span_rad: float = float(np.deg2rad(10.0)),
        climb_rate_span_mps: float = 5.0,
        rewards: Optional[Dict[str, Any]] = None,
        reward: str = "shaped",
        forecast: bool = False,
        render_mode: Optional[str] = None,
        max_episode_steps: Optional[int] = MAX_EPISODE_STEPS,
        *,
        three_dimensional: Optional[bool] = None,
        bank_command_span_rad: Optional[float] = None,
        sideslip_command_span_rad: Optional[float] = None,
        aileron_span_rad: Optional[float] = None,
        rudder_span_rad: Optional[float] = None,
    ) -> None:
        options = _arguments(locals())
        _check_render_mode(render_mode)
        num_envs = _whole("num_envs", num_envs)
        if max_episode_steps is not None and not (isinstance(max_episode_steps, (int, np.integer)) and max_episode_steps > 0):
            raise ValueError(
                f"`max_episode_steps` = {max_episode_steps!r} is not allowed: expected a positive integer or None"
            )
        self.num_envs = int(num_envs)
        self.three_dimensional = _is_three_dimensional(self, three_dimensional)
        self.control = control
        self.render_mode = render_mode
        config = _EnvConfig(
            max_episode_steps=None if max_episode_steps is None else int(max_episode_steps),
            **_core_options(self.three_dimensional, options),
        )
        self._core = _VecEnv(self.num_envs, config)
        self.single_action_space, self.single_observation_space = _read_description(self)
        self.outcomes = tuple(self.description["outcomes"])
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self._generators: List[Optional[np.random.Generator]] = [None] * self.num_envs
        # The outcome's name by code, None (code -1) for a running or step-limited episode.
        self._outcome_names = np.array(list(self.outcomes) + [None], dtype=object)
        # The LSO's grade and points by code, None and NaN (code -1) while running.
        self._grade_names = np.array(list(self.description["lso_grades"]) + [None], dtype=object)
        self._grade_points = np.array(list(self.description["lso_points"]) + [np.nan])
        # The environments whose episode ended at the last step (None: none).
        self._restart: Optional[List[int]] = None

    def _seed(self, i: int, seed: Optional[int]) -> int:
        if seed is not None:
            self._generators[i], _ = gymnasium.utils.seeding.np_random(int(seed))
            return int(seed)
        if self._generators[i] is None:
            self._generators[i], _ = gymnasium.utils.seeding.np_random()
        return _draw_seed(self._generators[i])

    def reset(
        self,
        *,
        seed: Optional[Union[int, Sequence[Optional[int]]]] = None,
        options: Optional[Dict[str, Any]] = None,
    ) -> Tuple[np.ndarray, Dict[str, Any]]:
        if seed is None:
            seeds: List[Optional[int]] = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)) and not isinstance(seed, (bool, np.bool_)):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        elif isinstance(seed, (str, bytes, dict)) or not isinstance(seed, Sequence) and not isinstance(seed, np.ndarray):
            raise TypeError(f"`seed` = {seed!r} is not allowed: expected an int, None or {self.num_envs} seeds")
        else:
            seeds = [None if s is None else _whole(f"seed[{i}]", s) for i, s in enumerate(seed)]
            if len(seeds) != self.num_envs:
                raise ValueError(
                    f"`seed` = {seed!r} is not allowed: expected an int, None or {self.num_envs} seeds"
                )
        drawn = [self._seed(i, s) for i, s in enumerate(seeds)]
        observation, raw, pilot = self._core.reset(drawn)
        self._restart = None
        return observation, {"raw": raw, "autopilot_action": pilot, "seed": np.array(drawn, dtype=np.int64)}

    def step(
        self, actions: np.ndarray
    ) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, Dict[str, Any]]:
        seeds = None
        if self._restart is not None:
            # Next-step autoreset: each ended environment's next seed from its generator.
            seeds = [0] * self.num_envs
            for i in self._restart:
                seeds[i] = self._seed(i, None)
        observation, reward, terminated, truncated, raw, pilot, codes, wires, off_centre, grades = self._core.step(
            actions, seeds
        )
        info: Dict[str, Any] = {"raw": raw, "autopilot_action": pilot}
        if codes is not None:  # some episodes ended
            done = terminated | truncated
            info["outcome"] = self._outcome_names[codes]
            info["_outcome"] = done
            info["wire"] = wires
            info["_wire"] = done
            # The LSO's grade of each ended pass (docs/model.md §11), None while running.
            info["lso_grade"] = self._grade_names[grades]
            info["_lso_grade"] = done
            info["lso_points"] = self._grade_points[grades]
            info["_lso_points"] = done
            if self.three_dimensional:
                # True or False after a touchdown, None without one (flag -1).
                info["off_centre"] = _OFF_CENTRE[off_centre + 1]
                info["_off_centre"] = done
            self._restart = np.flatnonzero(done).tolist()
        else:
            self._restart = None
        return observation, reward, terminated, truncated, info

    def render(self) -> Optional[Tuple[np.ndarray, ...]]:
        """Each environment's side view (with ``render_mode="rgb_array"``)."""
        if self.render_mode != "rgb_array":
            return None
        return tuple(self._core.render(i) for i in range(self.num_envs))


class CarrierLanding3DEnv(CarrierLandingEnv):
    """:class:`CarrierLandingEnv`, 3-D unless ``three_dimensional=False``: the entry
    point of ``deckland/CarrierLanding3D-v0`` (``docs/rl-environment.md``, "The 3-D
    environment")."""

    three_dimensional_by_default = True


class CarrierLanding3DVecEnv(CarrierLandingVecEnv):
    """:class:`CarrierLandingVecEnv`, 3-D unless ``three_dimensional=False``: the vector
    entry point of ``deckland/CarrierLanding3D-v0``."""

    three_dimensional_by_default = True


#: The registered ids: (id, entry point, vector entry point), the classes of this module.
REGISTRATIONS: Tuple[Tuple[str, str, str], ...] = (
    (ENV_ID, "CarrierLandingEnv", "CarrierLandingVecEnv"),
    (ENV_ID_3D, "CarrierLanding3DEnv", "CarrierLanding3DVecEnv"),
)


def register() -> None:
    """Registers :data:`ENV_ID` and :data:`ENV_ID_3D` with gymnasium (once each), with
    their vector entry points."""
    for env_id, single, vector in REGISTRATIONS:
        if env_id not in gymnasium.registry:
            gymnasium.register(
                id=env_id,
                entry_point=f"deckland.env:{single}",
                vector_entry_point=f"deckland.env:{vector}",
                max_episode_steps=MAX_EPISODE_STEPS,
            )
