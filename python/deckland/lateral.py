"""The lateral step: a bank-angle or sideslip step of the 6-DOF aircraft with the roll
and yaw laws (``deckland step --axis roll|yaw``; docs/lateral-control.md)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Optional

from . import _deckland
from ._deckland import Scenario
from ._tables import table


@dataclass
class LateralStep:
    """One lateral step flown by one or both controllers.

    ``report`` is the dict ``deckland step --axis AXIS --json`` prints (without
    ``output_folder``): the axis, conditions, step, seed, trim airspeed, settling band,
    the aileron's and rudder's rate limits, and under ``"controllers"`` each
    controller's settling time (±5 %), overshoot, rise time, largest sideslip and bank
    errors, surface peaks, rate RMS and time on the aileron's rate limit.
    ``time_series`` has the columns of its ``step.csv`` (every 2 ms; a pandas DataFrame
    when pandas is installed, else a dict of numpy arrays)."""

    report: Dict[str, Any]
    time_series: Any

    @property
    def controllers(self) -> List[Dict[str, Any]]:
        """Each controller's response (``report["controllers"]``)."""
        return self.report["controllers"]

    def __repr__(self) -> str:
        settled = ", ".join(
            f"{c['controller']}: "
            + (f"{c['settling_time_s']:.3f} s" if c["settled"] else "not settled")
            for c in self.controllers
        )
        return (
            f"LateralStep({self.report['axis']} {self.report['step_deg']:+}°, "
            f"{self.report['conditions']}; {settled})"
        )


def lateral_step(
    axis: str = "roll",
    step_deg: float = 10.0,
    seconds: float = 8.0,
    conditions: str = "ideal",
    seed: int = 1,
    controller: str = "both",
    scenario: Optional[Scenario] = None,
) -> LateralStep:
    """Flies a bank (``axis="roll"``) or sideslip (``axis="yaw"``) step of ``step_deg``
    degrees (nonzero, at most 30 either way) at t = 1 s for ``seconds`` (2–600), in
    ``"ideal"`` or ``"adverse"`` conditions (lateral turbulence and bank and sideslip
    sensor noise, seeded by ``seed``), with ``controller`` ``"opd"``, ``"pid"`` or
    ``"both"`` on both channels, as ``deckland step --axis AXIS`` does.

    ``scenario`` gives the 6-DOF aircraft (its ``aircraft`` section with the aileron and
    rudder actuators), the trim airspeed (``approach.airspeed_mps``) and the laws
    (``control.roll``, ``control.yaw``: the O-PD flown is the scenario's when it names
    one, else the designed one; likewise the PID); the default scenario when ``None``.
    A bad argument raises ``ValueError`` naming it.
    """
    report, columns = _deckland.lateral_step(
        axis, step_deg, seconds, conditions, seed, controller, scenario
    )
    return LateralStep(report=report, time_series=table(columns))
