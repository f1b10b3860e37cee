"""The Gymnasium environment ``deckland/CarrierLanding3D-v0``: the 3-D approach of the
6-DOF F/A-18 to the angled deck of a moving carrier, with roll and yaw commands added
to the action of ``deckland/CarrierLanding-v1`` (:mod:`deckland.env`).

Everything longitudinal is the 2-D environment's: the step, the wave-off, the seeding,
the vectorised stepping. What the 3-D environment adds (``docs/rl-environment.md``,
"The 3-D environment"):

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

The default scenario is :func:`crosswind_scenario`: the moderate sea with a 5 m/s
crosswind (``scenarios/crosswind.toml``).
"""

from __future__ import annotations

from typing import Any, Dict, Optional

import gymnasium
import numpy as np

from ._deckland import Scenario, _Env, _VecEnv
from .env import (
    MAX_EPISODE_STEPS,
    REWARDS,
    WAVE_OFF_BEFORE_RECOVERY,
    CarrierLandingEnv,
    CarrierLandingVecEnv,
    _check_reward_keys,
    _check_render_mode,
    _options,
    _real,
    _spaces,
)

ENV_ID_3D = "deckland/CarrierLanding3D-v0"

#: The control modes of the 3-D environment: the action's entries in order.
CONTROL_MODES_3D = {
    "surfaces": ("elevator", "thrust", "direct_lift", "aileron", "rudder", "wave_off"),
    "attitude": ("pitch_command", "thrust", "bank_command", "sideslip_command", "wave_off"),
    "guidance": ("climb_rate_command", "bank_command", "wave_off"),
}

#: The rewards of the 3-D environment: the 2-D environment's and, added at the end of an
#: approach that touched down off the centreline, ``off_centre``.
REWARDS_3D: Dict[str, Any] = dict(REWARDS, off_centre=-100.0)

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


def crosswind_scenario() -> Scenario:
    """The 3-D environment's default: the 6-DOF approach in a moderate sea with a 5 m/s
    crosswind (the settings of ``scenarios/crosswind.toml``, :data:`CROSSWIND_SETTINGS`)."""
    scenario = Scenario.default()
    for key, value in CROSSWIND_SETTINGS.items():
        scenario[key] = value
    return scenario


def _lateral_spans(
    bank_command_span_rad: float,
    sideslip_command_span_rad: float,
    aileron_span_rad: float,
    rudder_span_rad: float,
) -> tuple:
    return (
        _real("bank_command_span_rad", bank_command_span_rad),
        _real("sideslip_command_span_rad", sideslip_command_span_rad),
        _real("aileron_span_rad", aileron_span_rad),
        _real("rudder_span_rad", rudder_span_rad),
    )


class CarrierLanding3DEnv(CarrierLandingEnv):
    """Land the 6-DOF F/A-18 on the angled deck of the moving carrier
    (``docs/rl-environment.md``, "The 3-D environment").

    The options of :class:`deckland.env.CarrierLandingEnv` (``scenario`` defaults to
    :func:`crosswind_scenario` and must be a 3-D approach; ``rewards`` replaces entries
    of :data:`REWARDS_3D`), and the spans of the lateral action entries (zero is the
    trim): ``bank_command_span_rad`` (20°), ``sideslip_command_span_rad`` (5°),
    ``aileron_span_rad`` (10°), ``rudder_span_rad`` (10°).
    """

    def __init__(
        self,
        control: str = "attitude",
        scenario: Optional[Scenario] = None,
        control_interval_s: float = 0.02,
        pitch_command_span_rad: float = float(np.deg2rad(10.0)),
        thrust_span_n: Optional[float] = None,
        elevator_span_rad: float = float(np.deg2rad(10.0)),
        climb_rate_span_mps: float = 5.0,
        bank_command_span_rad: float = float(np.deg2rad(20.0)),
        sideslip_command_span_rad: float = float(np.deg2rad(5.0)),
        aileron_span_rad: float = float(np.deg2rad(10.0)),
        rudder_span_rad: float = float(np.deg2rad(10.0)),
        rewards: Optional[Dict[str, Any]] = None,
        reward: str = "shaped",
        forecast: bool = False,
        render_mode: Optional[str] = None,
    ) -> None:
        gymnasium.Env.__init__(self)
        _check_render_mode(render_mode)
        self._kwargs = dict(
            control=control,
            scenario=scenario,
            control_interval_s=control_interval_s,
            pitch_command_span_rad=pitch_command_span_rad,
            thrust_span_n=thrust_span_n,
            elevator_span_rad=elevator_span_rad,
            climb_rate_span_mps=climb_rate_span_mps,
            bank_command_span_rad=bank_command_span_rad,
            sideslip_command_span_rad=sideslip_command_span_rad,
            aileron_span_rad=aileron_span_rad,
            rudder_span_rad=rudder_span_rad,
            rewards=rewards,
            reward=reward,
            forecast=forecast,
            render_mode=render_mode,
        )
        self.control = control
        self.render_mode = render_mode
        _check_reward_keys(rewards, REWARDS_3D)
        table = dict(REWARDS_3D)
        if rewards is not None:
            table.update(rewards)
        self._core = _Env(
            *_options(
                crosswind_scenario() if scenario is None else scenario,
                control,
                control_interval_s,
                pitch_command_span_rad,
                thrust_span_n,
                elevator_span_rad,
                climb_rate_span_mps,
                table,
                reward,
                forecast,
                REWARDS_3D,
            ),
            lateral_spans=_lateral_spans(
                bank_command_span_rad, sideslip_command_span_rad, aileron_span_rad, rudder_span_rad
            ),
        )
        self._describe()


class CarrierLanding3DVecEnv(CarrierLandingVecEnv):
    """``num_envs`` environments of :class:`CarrierLanding3DEnv` stepped in one call to
    Rust (as :class:`deckland.env.CarrierLandingVecEnv`). When episodes end, ``info``
    also holds ``off_centre`` (an object array: True or False after a touchdown, None
    without one) and its mask ``_off_centre``.
    """

    _reports_off_centre = True

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
        bank_command_span_rad: float = float(np.deg2rad(20.0)),
        sideslip_command_span_rad: float = float(np.deg2rad(5.0)),
        aileron_span_rad: float = float(np.deg2rad(10.0)),
        rudder_span_rad: float = float(np.deg2rad(10.0)),
        rewards: Optional[Dict[str, Any]] = None,
        reward: str = "shaped",
        forecast: bool = False,
        render_mode: Optional[str] = None,
        max_episode_steps: Optional[int] = MAX_EPISODE_STEPS,
    ) -> None:
        _check_reward_keys(rewards, REWARDS_3D)
        table = dict(REWARDS_3D)
        if rewards is not None:
            table.update(rewards)
        self._init_vector(
            num_envs,
            render_mode,
            max_episode_steps,
            control,
            lambda steps: _VecEnv(
                int(num_envs),
                *_options(
                    crosswind_scenario() if scenario is None else scenario,
                    control,
                    control_interval_s,
                    pitch_command_span_rad,
                    thrust_span_n,
                    elevator_span_rad,
                    climb_rate_span_mps,
                    table,
                    reward,
                    forecast,
                    REWARDS_3D,
                ),
                steps,
                lateral_spans=_lateral_spans(
                    bank_command_span_rad, sideslip_command_span_rad, aileron_span_rad, rudder_span_rad
                ),
            ),
        )


def register() -> None:
    """Registers :data:`ENV_ID_3D` with gymnasium (once), with its vector entry point."""
    if ENV_ID_3D not in gymnasium.registry:
        gymnasium.register(
            id=ENV_ID_3D,
            entry_point="deckland.env3d:CarrierLanding3DEnv",
            vector_entry_point="deckland.env3d:CarrierLanding3DVecEnv",
            max_episode_steps=MAX_EPISODE_STEPS,
        )
