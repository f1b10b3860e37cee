"""The Gymnasium environment ``deckland/CarrierLanding-v0``: fly the approach to the deck.

The environment wraps :class:`deckland.Approach`. One step is one control interval
(20 ms by default); the agent commands the pitch attitude and the thrust, and the
built-in pitch law (O-PD by default) and the engines follow. Guidance and the sink-rate
loop, the speed loop's job and the deck-motion compensation are the agent's.

**Action** ``Box(-1, 1, (2,), float32)``, held over the interval:

- ``action[0]``: pitch command θ_ref = θ_trim + ``action[0]`` · ``pitch_command_span_rad``
  (10° by default);
- ``action[1]``: total thrust command T = T_trim + ``action[1]`` · ``thrust_span_n``
  (a quarter of the maximum thrust of both engines by default), limited to
  [0, T_max] by the engines.

Zero is the trim of the approach. An action outside the space, or not finite, raises
``ValueError`` naming the action, its value and the range (it is not clipped), and the
pitch commands the space reaches must lie within the pitch attitude's range (±90°).
:meth:`CarrierLandingEnv.action_for` turns a pitch command (rad) and a thrust (N) into
an action.

**Observation** ``Box((11,), float32)``, in the order of :data:`OBSERVATION_NAMES`
and within :data:`OBSERVATION_BOUNDS`: the glide-path error (m, positive below the
path), the sink rate (m/s, positive down), θ − θ_trim (rad), q (rad/s), α (rad), the
airspeed error to the approach speed (m/s), the predicted height of the landing point
above its mean (m), the range to go to the landing point (m), the time to go (s, within
±120), the elevator position (rad) and the thrust as a fraction of the maximum. ``info``
holds :class:`deckland.Approach`'s whole observation dict (physical units, with
``outcome``, ``wire`` and ``reason`` at the end).

**Reward**: each step −0.1 · min(e², 100) · Δt with e the glide-path error in m and Δt
the control interval in s (about −1.2 over a good approach), and at the end:

=============================  =======  =========================================
end                            reward   episode
=============================  =======  =========================================
trap                           +100     terminated; plus a wire bonus: wire 3
                                        +25, wire 2 +15, wire 4 +5, wire 1 0
bolter                         −50      terminated
hard landing                   −100     terminated
ramp strike                    −200     terminated
wave-off                       −50      terminated: \\|e\\| > ``wave_off_error_m``
                                        (6 m by default), as a landing signal
                                        officer would wave the aircraft off
diverged                       −200     terminated (left the model's validity)
time limit                     0        truncated (the scenario's ``max_time_s``)
=============================  =======  =========================================

The values are in :data:`REWARDS` and can be replaced with ``rewards=``.

**Seeding**: ``reset(seed=s)`` flies the scenario with seed ``s``, the seed of every
named random stream (ship heave and pitch, turbulence, sensor noise), so an episode
is reproducible and ``reset(seed=s)`` with the cascade's own commands is
``deckland.fly(seed=s)``; ``reset()`` without a seed draws the next seed from the
environment's generator (itself seeded by the last ``reset(seed=…)``).
"""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple

import gymnasium
import numpy as np
from gymnasium import spaces

from ._deckland import MAX_SEED, Approach, Scenario

ENV_ID = "deckland/CarrierLanding-v0"

#: The observation vector's entries, in order, with the bounds of the observation space
#: (wide physical limits; a value beyond them, possible only far outside the model's
#: validity, is clipped).
OBSERVATION_BOUNDS = {
    "glide_path_error_m": (-1000.0, 1000.0),
    "sink_rate_mps": (-200.0, 200.0),
    "theta_minus_trim_rad": (-2 * np.pi, 2 * np.pi),
    "q_radps": (-20.0, 20.0),
    "alpha_rad": (-np.pi, np.pi),
    "airspeed_error_mps": (-200.0, 200.0),
    "predicted_deck_offset_m": (-100.0, 100.0),
    "range_to_go_m": (-2000.0, 20000.0),
    "time_to_go_s": (-120.0, 120.0),
    "elevator_rad": (-1.0, 1.0),
    "thrust_fraction": (0.0, 1.0),
}
OBSERVATION_NAMES = tuple(OBSERVATION_BOUNDS)
_LOW = np.array([low for low, _ in OBSERVATION_BOUNDS.values()], dtype=np.float32)
_HIGH = np.array([high for _, high in OBSERVATION_BOUNDS.values()], dtype=np.float32)

#: The rewards at the end of an episode, and the wire bonus of a trap.
REWARDS: Dict[str, Any] = {
    "trap": 100.0,
    "wire_bonus": {1: 0.0, 2: 15.0, 3: 25.0, 4: 5.0},
    "bolter": -50.0,
    "hard_landing": -100.0,
    "ramp_strike": -200.0,
    "wave_off": -50.0,
    "diverged": -200.0,
    "timeout": 0.0,
}

#: Weight of the squared glide-path error (1/m² per second) and its cap (m²).
ERROR_WEIGHT = 0.1
ERROR_SQUARED_CAP_M2 = 100.0


class CarrierLandingEnv(gymnasium.Env):
    """Land the F/A-18 on the moving carrier deck: commands are the pitch attitude and
    the thrust (see the module's doc for the spaces, the reward and the seeding).

    ``scenario`` is a :class:`deckland.Scenario` (the default: adverse conditions);
    ``control_interval_s`` the length of a step; ``pitch_command_span_rad`` and
    ``thrust_span_n`` scale the actions; ``wave_off_error_m`` is the glide-path error
    that ends an episode as a wave-off; ``rewards`` replaces :data:`REWARDS`.
    """

    metadata = {"render_modes": []}

    def __init__(
        self,
        scenario: Optional[Scenario] = None,
        control_interval_s: float = 0.02,
        pitch_command_span_rad: float = np.deg2rad(10.0),
        thrust_span_n: Optional[float] = None,
        wave_off_error_m: float = 6.0,
        rewards: Optional[Dict[str, Any]] = None,
        render_mode: Optional[str] = None,
    ) -> None:
        super().__init__()
        if render_mode is not None:
            raise ValueError(f"`render_mode` = {render_mode!r} is not allowed: expected None")
        for name, value in (
            ("pitch_command_span_rad", pitch_command_span_rad),
            ("wave_off_error_m", wave_off_error_m),
        ):
            if not (np.isfinite(value) and value > 0):
                raise ValueError(f"`{name}` = {value!r} is not allowed: expected a positive number")
        self.approach = Approach(scenario, None, control_interval_s)
        trim = self.approach.trim
        self._theta_trim = trim["theta_rad"]
        self._thrust_trim = trim["thrust_n"]
        self._max_thrust = trim["max_thrust_n"]
        self.pitch_command_span_rad = float(pitch_command_span_rad)
        self.thrust_span_n = float(0.25 * self._max_thrust if thrust_span_n is None else thrust_span_n)
        if not (np.isfinite(self.thrust_span_n) and self.thrust_span_n > 0):
            raise ValueError(f"`thrust_span_n` = {thrust_span_n!r} is not allowed: expected a positive number")
        self.action_ranges = self.approach.action_ranges
        low, high = self.action_ranges["pitch_command_rad"]
        reach = min(self._theta_trim - low, high - self._theta_trim)
        if not self.pitch_command_span_rad <= reach:
            raise ValueError(
                f"`pitch_command_span_rad` = {pitch_command_span_rad!r} is not allowed: expected at "
                f"most {reach!r} rad, so that the trim pitch ± the span stays within the pitch "
                f"command's range [{low!r}, {high!r}] rad"
            )
        self.wave_off_error_m = float(wave_off_error_m)
        self.rewards = dict(REWARDS if rewards is None else rewards)
        scenario_now = self.approach.scenario
        self._airspeed_reference = scenario_now["approach.airspeed_mps"]
        self._mean_deck_height = scenario_now["environment.deck.deck_height_m"]
        self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.observation_space = spaces.Box(_LOW, _HIGH, dtype=np.float32)
        self._ended = False

    def action_for(self, pitch_command_rad: float, thrust_n: float) -> np.ndarray:
        """The action that commands ``pitch_command_rad`` and ``thrust_n``.

        Each must lie within its physical range, as an action of :class:`deckland.Approach`
        (:attr:`action_ranges`: the pitch attitude's range, from no thrust to the maximum
        of both engines), else ``ValueError`` names it, its value and the range. A command
        within it but beyond what the action space reaches (θ_trim ±
        ``pitch_command_span_rad``, T_trim ± ``thrust_span_n``) is clipped to the space's
        edge."""
        for name, value in (("pitch_command_rad", pitch_command_rad), ("thrust_n", thrust_n)):
            low, high = self.action_ranges[name]
            if not low <= value <= high:
                raise ValueError(
                    f"`{name}` = {value!r} is not allowed: expected a number in [{low!r}, {high!r}]"
                )
        action = np.array(
            [
                (pitch_command_rad - self._theta_trim) / self.pitch_command_span_rad,
                (thrust_n - self._thrust_trim) / self.thrust_span_n,
            ]
        )
        return np.clip(action, -1.0, 1.0).astype(np.float32)

    def commands(self, action: np.ndarray) -> Dict[str, float]:
        """The Approach action (pitch command in rad, thrust in N) of an env action, which
        must lie in the action space (two numbers in [-1, 1]), else ``ValueError``."""
        try:
            a = np.asarray(action, dtype=np.float64)
        except (TypeError, ValueError):
            a = None
        if a is None or a.shape != (2,) or not np.all((a >= -1.0) & (a <= 1.0)):
            raise ValueError(
                f"`action` = {action!r} is not allowed: expected two numbers in [-1, 1] (the action space)"
            )
        return {
            "pitch_command_rad": self._theta_trim + a[0] * self.pitch_command_span_rad,
            "thrust_n": float(np.clip(self._thrust_trim + a[1] * self.thrust_span_n, 0.0, self._max_thrust)),
        }

    def _vector(self, o: Dict[str, Any]) -> np.ndarray:
        predicted = o["predicted_deck_height_m"]
        values = (
            o["glide_path_error_m"],
            o["sink_rate_mps"],
            o["theta_rad"] - self._theta_trim,
            o["q_radps"],
            o["alpha_rad"],
            o["airspeed_mps"] - self._airspeed_reference,
            (predicted - self._mean_deck_height) if np.isfinite(predicted) else 0.0,
            o["range_to_go_m"],
            o["time_to_go_s"],
            o["elevator_rad"],
            o["thrust_n"] / self._max_thrust,
        )
        vector = np.nan_to_num(np.array(values, dtype=np.float64), nan=0.0)
        return np.clip(vector, _LOW, _HIGH).astype(np.float32)

    def reset(
        self, *, seed: Optional[int] = None, options: Optional[Dict[str, Any]] = None
    ) -> Tuple[np.ndarray, Dict[str, Any]]:
        super().reset(seed=seed)
        if seed is None:
            seed = int(self.np_random.integers(0, MAX_SEED, endpoint=True))
        self._ended = False
        observation = self.approach.reset(seed=seed)
        return self._vector(observation), observation

    def step(self, action: np.ndarray) -> Tuple[np.ndarray, float, bool, bool, Dict[str, Any]]:
        if self._ended:
            raise RuntimeError("the episode has ended: call reset() first")
        o = self.approach.step(self.commands(action))
        error = o["glide_path_error_m"]
        reward = -ERROR_WEIGHT * min(error * error, ERROR_SQUARED_CAP_M2) * self.approach.control_interval_s
        terminated = truncated = False
        if o["done"]:
            outcome = o["outcome"]
            if outcome == "timeout":
                truncated = True
            else:
                terminated = True
            reward += float(self.rewards.get(outcome, 0.0))
            if outcome == "trap":
                reward += float(self.rewards.get("wire_bonus", {}).get(o["wire"], 0.0))
        elif not abs(error) <= self.wave_off_error_m:
            terminated = True
            o = dict(o, outcome="wave_off", reason=f"waved off: glide-path error {error:.1f} m")
            reward += float(self.rewards.get("wave_off", 0.0))
        self._ended = terminated or truncated
        return self._vector(o), float(reward), terminated, truncated, o


def register() -> None:
    """Registers :data:`ENV_ID` with gymnasium (once)."""
    if ENV_ID not in gymnasium.registry:
        gymnasium.register(id=ENV_ID, entry_point="deckland.env:CarrierLandingEnv")
