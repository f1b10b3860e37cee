"""Type stubs of the compiled core (python/src/); the documented API is `deckland`."""

from os import PathLike
from typing import Any, Callable, Dict, List, Optional, Protocol, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
STATE_NAMES: List[str]
INPUT_NAMES: List[str]
MAX_SEED: int
MAX_RUNS: int

PitchLaw = Callable[[Dict[str, float]], float]

class Trim:
    configuration: str
    speed_mps: float
    gamma_deg: float
    alpha_deg: float
    theta_deg: float
    elevator_deg: float
    thrust_n: float
    throttle: float
    residuals: Dict[str, float]
    iterations: int
    def to_dict(self) -> Dict[str, Any]: ...

class LinearModel:
    @property
    def a(self) -> npt.NDArray[np.float64]: ...
    @property
    def b(self) -> npt.NDArray[np.float64]: ...
    @property
    def c(self) -> npt.NDArray[np.float64]: ...
    @property
    def d(self) -> npt.NDArray[np.float64]: ...
    @property
    def eigenvalues(self) -> npt.NDArray[np.complex128]: ...
    @property
    def state_names(self) -> List[str]: ...
    @property
    def state_units(self) -> List[str]: ...
    @property
    def input_names(self) -> List[str]: ...
    @property
    def input_units(self) -> List[str]: ...
    trim: Trim
    modes: List[Dict[str, Any]]

class Scenario:
    name: str
    def __init__(self) -> None: ...
    @staticmethod
    def default() -> Scenario: ...
    @staticmethod
    def paper() -> Scenario: ...
    @staticmethod
    def from_toml(text: str, name: str = "scenario.toml") -> Scenario: ...
    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> Scenario: ...
    def __getitem__(self, path: str) -> Any: ...
    def __setitem__(self, path: str, value: Any) -> None: ...
    def __contains__(self, path: str) -> bool: ...
    def keys(self) -> List[str]: ...
    def to_toml(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def copy(self) -> Scenario: ...

class Approach:
    pitch_law: Optional[PitchLaw]
    def __init__(
        self,
        scenario: Optional[Scenario] = None,
        seed: Optional[int] = None,
        control_interval_s: float = 0.02,
        pitch_law: Optional[PitchLaw] = None,
    ) -> None: ...
    def reset(self, seed: Optional[int] = None) -> Dict[str, Any]: ...
    def step(self, action: Optional[Dict[str, Optional[float]]] = None) -> Dict[str, Any]: ...
    def observation(self) -> Dict[str, Any]: ...
    @property
    def done(self) -> bool: ...
    @property
    def outcome(self) -> Optional[str]: ...
    @property
    def summary(self) -> Optional[Dict[str, Any]]: ...
    @property
    def events(self) -> List[Dict[str, Any]]: ...
    @property
    def time_s(self) -> float: ...
    @property
    def seed(self) -> int: ...
    @property
    def control_interval_s(self) -> float: ...
    @property
    def time_step_s(self) -> float: ...
    @property
    def scenario(self) -> Scenario: ...
    @property
    def trim(self) -> Dict[str, float]: ...
    @property
    def action_ranges(self) -> Dict[str, Tuple[float, float]]: ...

class _EnvConfig:
    def __init__(
        self,
        scenario: Optional[Scenario],
        control: str,
        control_interval_s: float,
        pitch_command_span_rad: float,
        thrust_span_n: Optional[float],
        elevator_span_rad: float,
        climb_rate_span_mps: float,
        rewards: Dict[str, Any],
        reward: str,
        forecast: bool,
        max_episode_steps: Optional[int] = None,
        lateral_spans: Optional[Tuple[float, float, float, float]] = None,
    ) -> None: ...

class _Env:
    def __init__(self, config: _EnvConfig) -> None: ...
    def describe(self) -> Dict[str, Any]: ...
    def reset(self, seed: int) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...
    def step(self, action: Any) -> Tuple[np.ndarray, float, bool, bool, Dict[str, Any]]: ...
    def render(self) -> np.ndarray: ...
    def actions(self) -> np.ndarray: ...
    @property
    def seed(self) -> Optional[int]: ...
    @property
    def time_s(self) -> float: ...

class _VecEnv:
    def __init__(self, num_envs: int, config: _EnvConfig) -> None: ...
    def describe(self) -> Dict[str, Any]: ...
    def reset(self, seeds: List[int]) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...
    def step(
        self, actions: np.ndarray, seeds: Optional[List[int]]
    ) -> Tuple[
        np.ndarray,
        np.ndarray,
        np.ndarray,
        np.ndarray,
        np.ndarray,
        np.ndarray,
        Optional[np.ndarray],
        Optional[np.ndarray],
        Optional[np.ndarray],
    ]: ...
    def render(self, index: int) -> np.ndarray: ...

def trim(speed_mps: float = 69.1, gamma_deg: float = 0.0, configuration: str = "landing") -> Trim: ...
def linearize(speed_mps: float = 69.1, gamma_deg: float = 0.0, configuration: str = "landing") -> LinearModel: ...
class _SixDofFlightCondition(Protocol):
    """`trim_six_dof` and `linearize_six_dof`: the same flight condition, a dict back."""
    def __call__(
        self,
        speed_mps: float = 69.1,
        gamma_deg: float = 0.0,
        sideslip_deg: float = 0.0,
        crosswind_mps: float = 0.0,
        configuration: str = "landing",
    ) -> Dict[str, Any]: ...

trim_six_dof: _SixDofFlightCondition
linearize_six_dof: _SixDofFlightCondition
def fly(
    scenario: Optional[Scenario] = None,
    seed: Optional[int] = None,
    disperse: bool = False,
    pitch_law: Optional[PitchLaw] = None,
    control_interval_s: float = 0.02,
    acmi: bool = False,
    out: Optional[str] = None,
    force: bool = False,
    plots: bool = True,
    figures: Optional[Any] = None,
) -> Tuple[Dict[str, Any], Dict[str, np.ndarray], List[Dict[str, Any]], Optional[str], Optional[str]]: ...
def lateral_step(
    axis: str = "roll",
    step_deg: float = 10.0,
    seconds: float = 8.0,
    conditions: str = "ideal",
    seed: int = 1,
    controller: str = "both",
    scenario: Optional[Scenario] = None,
) -> Tuple[Dict[str, Any], Dict[str, np.ndarray]]: ...
def campaign(
    scenario: Scenario,
    runs: int,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    compare: bool = False,
    progress: Optional[Callable[[int, int], Any]] = None,
    out: Optional[str] = None,
    force: bool = False,
    figures: Optional[Any] = None,
) -> Tuple[Dict[str, np.ndarray], Dict[str, Any], Optional[str]]: ...
def rare(
    scenario: Scenario,
    event: str,
    threshold: Optional[float] = None,
    target_rel_error: Optional[float] = None,
    max_runs: Optional[int] = None,
    particles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    calibrate_score: Optional[int] = None,
    out: Optional[Union[str, PathLike[str]]] = None,
    force: bool = False,
    save_flights: Optional[int] = None,
    figures: Optional[Any] = None,
) -> Dict[str, Any]: ...
def rare_repetition(
    scenario: Scenario,
    event: str,
    repetition: int,
    share: int,
    threshold: Optional[float] = None,
    particles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    calibrate_score: Optional[int] = None,
) -> Any: ...
def rare_batched(
    scenario: Scenario,
    event: str,
    run_batch: Callable[[int, int, int], List[Any]],
    threshold: Optional[float] = None,
    target_rel_error: Optional[float] = None,
    max_runs: Optional[int] = None,
    particles: Optional[int] = None,
    seed: Optional[int] = None,
    calibrate_score: Optional[int] = None,
) -> Dict[str, Any]: ...
def campaign_shard(
    scenario: Scenario,
    runs: int,
    index: int,
    count: int,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    compare: bool = False,
) -> str: ...
def merge_shards_text(
    shards: List[str], out: Optional[str] = None, force: bool = False, figures: Optional[Any] = None
) -> Tuple[Dict[str, np.ndarray], Dict[str, Any], Optional[str]]: ...
def _bench_stepping(
    scenario: Optional[Scenario] = None, seed: Optional[int] = None, control_interval_s: float = 0.02
) -> Tuple[int, float]: ...
