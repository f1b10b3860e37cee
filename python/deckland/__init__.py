"""deckland: automatic carrier landing of an unmanned F/A-18, from Python.

The simulator is the Rust library `deckland` (the same code as the `deckland` command);
this package calls it directly, so every number is the CLI's, bit for bit.

- :func:`trim` and :func:`linearize`: steady flight and its linear model (numpy arrays,
  ready for ``control.ss``); :func:`trim_six_dof` and :func:`linearize_six_dof` the same
  for the 6-DOF aircraft, in sideslip or a crosswind, with the lateral matrices and modes.
- :class:`Scenario`: every parameter of a run, read and set by dotted path
  (``s["environment.seaway.significant_wave_height_m"] = 5.0``); a bad value raises ``ValueError``.
- :func:`fly`: one approach, with its summary and time series (a pandas DataFrame when
  pandas is installed, else a dict of numpy arrays; the columns of ``approach.csv``).
- :func:`campaign`: many approaches in parallel (Monte Carlo), the rows of ``runs.csv``;
  :func:`deckland.dask.campaign` flies its shards on a Dask cluster (``deckland[dask]``).
- ``out=``: :func:`fly` and :func:`campaign` write the folder ``deckland run`` and
  ``deckland campaign`` write, the plots and ``report.html`` included, by the same code;
  :class:`Figures` sizes the figures.
- :func:`lateral_step`: a bank or sideslip step of the 6-DOF aircraft with the roll and
  yaw laws (``deckland step --axis roll|yaw``), its metrics and time series.
- :class:`Approach`: the stepping API, one control interval at a time, the built-in
  cascade flying or your commands replacing its loops, or your own pitch law.
- ``deckland/CarrierLanding-v1``: a Gymnasium environment on :class:`Approach`'s
  simulation, with a native vectorised version (registered when gymnasium is
  installed; see :mod:`deckland.env`); ``deckland/CarrierLanding3D-v0`` the 3-D
  approach of the 6-DOF aircraft with roll and yaw commands added (:mod:`deckland.env3d`).

Units are SI and angles radians, except where a name says ``_deg``.
"""

from __future__ import annotations

import functools
import os
import sys
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Iterator, List, Optional, TypeVar, Union, cast

from . import _deckland
from ._deckland import (
    MAX_RUNS,
    Approach,
    LinearModel,
    Scenario,
    Trim,
    linearize,
    linearize_six_dof,
    trim,
    trim_six_dof,
)
from ._tables import table
from .lateral import LateralStep, lateral_step

__version__ = _deckland.__version__

__all__ = [
    "MAX_RUNS",
    "Approach",
    "Campaign",
    "Figures",
    "Flight",
    "LateralStep",
    "LinearModel",
    "Scenario",
    "Trim",
    "campaign",
    "fly",
    "rare",
    "lateral_step",
    "linearize",
    "linearize_six_dof",
    "trim",
    "trim_six_dof",
]


PathLike = Union[str, "os.PathLike[str]"]


@dataclass(frozen=True)
class Figures:
    """How the plots of a folder written with ``out=`` are sized, as the command line's
    ``--figure-width-mm``, ``--font-pt``, ``--figure-dpi`` and ``--pdf``.

    ``width_mm`` is the printed width (30 to 500 mm; default 88.9, IEEE's one column),
    ``font_pt`` the small text's size at that width (4 to 36 pt; default 8), ``dpi`` the
    PNG's pixels per inch (72 to 1200; default 300) and ``pdf`` also writes each figure as
    a vector PDF. A value out of range, or of the wrong type, raises when the folder is
    asked for, before anything is flown."""

    width_mm: float = 88.9
    font_pt: float = 8.0
    dpi: int = 300
    pdf: bool = False


@dataclass
class Flight:
    """One flown approach.

    ``summary`` is the dict of ``summary.json`` (``controller``, ``conditions``,
    ``seed``, ``outcome``, ``wire``, ``reason``, ``end_time_s``, ``steps``,
    ``touchdown``, ``ramp_clearance_m``, ``glide_path_error_rms_m``,
    ``glide_path_error_max_m``, ``deck_within_recovery_limits_pct``: the share of the run
    with the true deck within the recovery limits); ``time_series`` has the columns of ``approach.csv``
    (every 10 ms and the last step); ``events`` lists the ramp crossing, touchdown and
    passing of the last wire, as dicts.
    """

    summary: Dict[str, Any]
    time_series: Any
    events: List[Dict[str, Any]] = field(default_factory=list)
    #: The approach as a Tacview ACMI 2.2 text (``fly(..., acmi=True)``), else None.
    acmi: Optional[str] = None
    #: The folder written by ``fly(..., out=...)``, else None.
    folder: Optional[str] = None

    def write_acmi(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes :attr:`acmi` to ``path`` (``approach.acmi`` of ``deckland land --acmi``),
        whole or not at all; raises ``ValueError`` if the flight was flown without it."""
        if self.acmi is None:
            raise ValueError("this flight has no replay: fly it with acmi=True")
        target = os.fspath(path)
        partial = f"{target}.partial"
        with open(partial, "w", encoding="utf-8") as out:
            out.write(self.acmi)
        os.replace(partial, target)

    @property
    def outcome(self) -> str:
        """``trap``, ``bolter``, ``wave_off``, ``ramp_strike``, ``hard_landing``, ``diverged`` or ``timeout``."""
        return self.summary["outcome"]

    @property
    def wire(self) -> Optional[int]:
        """The wire caught (1 aftmost … 4), for a trap or a hard landing that caught one."""
        return self.summary["wire"]

    @property
    def reason(self) -> Optional[str]:
        """Why the run did not trap, in words (None for a trap)."""
        return self.summary["reason"]

    @property
    def touchdown(self) -> Optional[Dict[str, float]]:
        """The touchdown (``time_s``, ``distance_from_aim_m``, ``sink_rate_mps``,
        ``pitch_deg``, ``airspeed_mps``), if the hook reached the deck."""
        return self.summary["touchdown"]

    def __repr__(self) -> str:
        wire = f", wire={self.wire}" if self.wire is not None else ""
        return f"Flight(outcome={self.outcome!r}{wire}, seed={self.summary['seed']})"


@dataclass
class Campaign:
    """A Monte Carlo campaign: ``runs`` has the columns of ``runs.csv`` (one row per run
    and controller, by run index), ``summary`` the keys of the CLI's ``summary.json``
    (outcome rates with 95 % Wilson intervals and touchdown statistics per controller
    under ``"controllers"``)."""

    runs: Any
    summary: Dict[str, Any]
    #: The folder written by ``campaign(..., out=...)``, else None.
    folder: Optional[str] = None

    @property
    def statistics(self) -> List[Dict[str, Any]]:
        """The statistics of each controller (``summary["controllers"]``)."""
        return self.summary["controllers"]

    def __iter__(self) -> Iterator[Any]:
        """``runs, summary = campaign``."""
        return iter((self.runs, self.summary))

    def __repr__(self) -> str:
        rates = ", ".join(
            f"{s['controller']}: {s['boarding']['rate']:.1%} boarding"
            for s in self.statistics
        )
        return f"Campaign({self.summary['finished_runs']} runs; {rates})"


def fly(
    scenario: Optional[Scenario] = None,
    seed: Optional[int] = None,
    *,
    disperse: bool = False,
    pitch_law: Optional[Callable[[Dict[str, float]], float]] = None,
    control_interval_s: float = 0.02,
    acmi: bool = False,
    out: Optional[PathLike] = None,
    force: bool = False,
    plots: bool = True,
    figures: Optional[Figures] = None,
) -> Flight:
    """Flies one approach and returns its :class:`Flight`.

    ``scenario`` defaults to :meth:`Scenario.default` (what ``deckland land`` flies);
    ``seed`` to the scenario's own seed (1 for the default), which seeds every random
    stream. With ``disperse=True`` the scenario's ``[dispersion]`` is drawn from the seed
    as a campaign run draws it (``deckland run FILE --seed S --disperse``), so a row of
    :func:`campaign` can be flown again with its time series.

    ``pitch_law`` flies a Python callable as the pitch law, called once per
    ``control_interval_s`` (see :class:`Approach`); without it the whole run is in Rust
    and the interpreter is released while it flies.

    With ``acmi=True`` the flight also holds the approach as a Tacview ACMI 2.2 replay
    (:attr:`Flight.acmi`, :meth:`Flight.write_acmi`), the file ``deckland land --acmi``
    writes.

    With ``out``, the flight's folder is written there as ``deckland run FILE --out
    OUT`` writes it: ``scenario.toml``, ``approach.csv``, ``trap_sheet.csv``,
    ``summary.json``, the plots (PNG and SVG, sized by ``figures``, a :class:`Figures`;
    none with ``plots=False``), ``approach.acmi`` with ``acmi=True``, and
    ``report.html``, by the command line's own code (:attr:`Flight.folder`). A folder that
    holds files is refused unless ``force=True`` replaces an earlier deckland result in
    it, as ``--force`` does; a folder that cannot be written raises ``OSError``.
    """
    summary, columns, events, replay, folder = _deckland.fly(
        scenario,
        seed,
        disperse,
        pitch_law,
        control_interval_s,
        acmi,
        _path(out),
        _flag("force", force),
        _flag("plots", plots),
        figures,
    )
    return Flight(
        summary=summary, time_series=table(columns), events=events, acmi=replay, folder=folder
    )


def _path(out: Optional[PathLike]) -> Optional[str]:
    """``out`` as a path string (``None`` stays ``None``); anything else raises
    ``TypeError``."""
    if out is None:
        return None
    if not isinstance(out, (str, os.PathLike)):
        raise TypeError(f"`out` = {out!r}: expected a path (str or os.PathLike) or None")
    path = os.fspath(out)
    if not isinstance(path, str):
        raise TypeError(f"`out` = {out!r}: expected a text path, not bytes")
    return path


def _flag(name: str, value: Any) -> bool:
    """``value`` if it is a bool; anything else raises ``TypeError`` naming ``name``."""
    if not isinstance(value, bool):
        raise TypeError(f"`{name}` = {value!r}: expected True or False")
    return value


def progress_callback(
    progress: Union[bool, Callable[[int, int], Any], None], label: str
) -> Optional[Callable[[int, int], Any]]:
    """The ``progress(done, total)`` callable of a ``progress`` argument: ``True`` gives
    :class:`ProgressLines` on stderr, a callable itself, ``None`` or ``False`` none;
    anything else raises ``TypeError``."""
    if progress is None or progress is False:
        return None
    if progress is True:
        return ProgressLines(label)
    if callable(progress):
        return progress
    raise TypeError(
        f"`progress` = {progress!r}: expected True, False, None or a callable progress(done, total)"
    )


class ProgressLines:
    """Writes ``label: done/total runs (p %), t s`` to stderr at each tenth of the work,
    the lines ``deckland campaign`` writes when stderr is not a terminal."""

    def __init__(self, label: str) -> None:
        self.label = label
        self.tenth = 0
        self.started = time.monotonic()

    def __call__(self, done: int, total: int) -> None:
        if total <= 0:
            return
        tenth = min(10, min(done, total) * 10 // total)
        if tenth > self.tenth:
            self.tenth = tenth
            elapsed = time.monotonic() - self.started
            print(
                f"{self.label}: {done}/{total} runs ({tenth * 10} %), {elapsed:.0f} s",
                file=sys.stderr,
                flush=True,
            )


def campaign(
    scenario: Scenario,
    runs: int,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    compare: bool = False,
    progress: Union[bool, Callable[[int, int], Any], None] = None,
    *,
    out: Optional[PathLike] = None,
    force: bool = False,
    figures: Optional[Figures] = None,
) -> Campaign:
    """Flies ``runs`` approaches of ``scenario`` in parallel, as ``deckland campaign``.

    Run ``i`` flies seed SplitMix64(``seed``, i) with the scenario's dispersions drawn
    from it; ``seed`` defaults to the scenario's. ``threads`` defaults to the number of
    CPUs; the result does not depend on it. ``compare=True`` flies the same runs under
    O-PD and PID. The rows are those of ``runs.csv``, bit for bit. A 3-D approach
    (``aircraft.model = "6dof"``, ``approach.three_dimensional``) adds, as the CLI does,
    the lateral touchdown and the trap sheet's columns after the others (``off_centre``
    1 or 0, NaN where the run did not touch down) and their statistics under the
    summary's ``lateral`` and ``trap_sheet``. The column ``deck_within_limits_pct``
    is the share of each run's time (%) with the true deck within every recovery limit
    (lens pitch and roll, total motion, motion in 4 s; NaN for a run that never flew),
    summarised per controller as ``deck_within_limits_pct``. Then
    ``commit_ramp_strike_probability``, ``commit_hard_landing_probability`` and
    ``commit_off_centre_probability`` are the probabilities the forecast gave at the
    commit point (NaN for a run that never reached it, the off-centre one for a 3-DOF
    approach too), held against the outcomes per controller as ``calibration``; the last
    two, ``commit_ramp_clearance_m`` and ``commit_ramp_clearance_sigma_m``, the
    hook-to-ramp clearance c the ramp strike's is taken on and its σ_c, whose
    standardised error (``ramp_clearance_m`` − c)/σ_c the calibration summarises as
    ``ramp_clearance_error``.
    ``runs`` is 1 to :data:`MAX_RUNS` (100 000,
    as ``deckland campaign --runs``); beyond, ``ValueError``.
    ``progress`` reports how far the campaign got: ``True`` writes a line to stderr at
    each tenth of the runs (as ``deckland campaign`` does when stderr is not a terminal),
    a callable is called as ``progress(done, total)`` with the runs flown (at most every
    0.25 s and at the end; an exception it raises stops the campaign); ``None`` (the
    default) or ``False``, nothing.

    With ``out``, the campaign's folder is written there as ``deckland campaign FILE --out
    OUT`` writes it: ``scenario.toml``, ``runs.csv``, ``runs.parquet``, ``summary.json``,
    the plots (sized by ``figures``, a :class:`Figures`) and ``report.html``, by the
    command line's own code (:attr:`Campaign.folder`); ``force`` as for :func:`fly`.
    """
    columns, summary, folder = _deckland.campaign(
        scenario,
        runs,
        seed,
        threads,
        compare,
        progress_callback(progress, "campaign"),
        _path(out),
        _flag("force", force),
        figures,
    )
    return Campaign(runs=table(columns), summary=summary, folder=folder)


_F = TypeVar("_F", bound=Callable[..., Any])


def _folder_checked(function: _F) -> _F:
    """``function`` of the compiled core with its ``out`` and ``force`` checked as
    :func:`fly`'s and :func:`campaign`'s are (:func:`_path`, :func:`_flag`)."""

    @functools.wraps(function)
    def checked(*args: Any, out: Optional[PathLike] = None, force: bool = False, **kwargs: Any) -> Any:
        return function(*args, out=_path(out), force=_flag("force", force), **kwargs)

    return cast(_F, checked)


#: The probability per approach of a catastrophe, by splitting, as ``deckland rare``: the
#: compiled core's ``rare`` (documented there), its folder's arguments checked.
rare = _folder_checked(_deckland.rare)


def _register_gymnasium() -> None:
    """Registers ``deckland/CarrierLanding-v1`` and ``deckland/CarrierLanding3D-v0``
    when gymnasium is installed."""
    import importlib.util

    if importlib.util.find_spec("gymnasium") is None:
        return
    from .env import register
    from .env3d import register as register_3d

    register()
    register_3d()


_register_gymnasium()
