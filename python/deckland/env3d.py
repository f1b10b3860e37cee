"""The Gymnasium environment ``deckland/CarrierLanding3D-v0``: the 3-D approach of the
6-DOF F/A-18 to the angled deck of a moving carrier, with roll and yaw commands added
to the action of ``deckland/CarrierLanding-v1``.

Kept for the names it has always given: the environment is :mod:`deckland.env`'s one
class with ``three_dimensional=True`` (:class:`CarrierLanding3DEnv` and
:class:`CarrierLanding3DVecEnv` are those classes 3-D by default), where everything about
it is; this module only re-exports the 3-D names (``docs/rl-environment.md``, "The 3-D
environment").
"""

from __future__ import annotations

from ._deckland import Scenario
from .env import (
    CONTROL_MODES_3D,
    CROSSWIND_SETTINGS,
    ENV_ID_3D,
    LATERAL_SPANS,
    MAX_EPISODE_STEPS,
    REWARDS,
    REWARDS_3D,
    WAVE_OFF_BEFORE_RECOVERY,
    CarrierLanding3DEnv,
    CarrierLanding3DVecEnv,
    CarrierLandingEnv,
    CarrierLandingVecEnv,
    crosswind_scenario,
    register,
)

__all__ = [
    "CONTROL_MODES_3D",
    "CROSSWIND_SETTINGS",
    "ENV_ID_3D",
    "LATERAL_SPANS",
    "MAX_EPISODE_STEPS",
    "REWARDS",
    "REWARDS_3D",
    "WAVE_OFF_BEFORE_RECOVERY",
    "CarrierLanding3DEnv",
    "CarrierLanding3DVecEnv",
    "CarrierLandingEnv",
    "CarrierLandingVecEnv",
    "Scenario",
    "crosswind_scenario",
    "register",
]
