"""Type stubs of the Python package `routh` (ARCHITECTURE §5e)."""

from os import PathLike
from typing import Any, Callable, Literal, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

Verdict = Literal["secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate"]
EventKind = Literal["fold", "branch_point", "hamiltonian_hopf"]
ParamValue = Union[float, Sequence[float], Sequence[Sequence[float]], npt.ArrayLike]
Vec3 = Union[Sequence[float], npt.NDArray[np.float64]]

VERDICTS: tuple[str, ...]
EVENT_KINDS: tuple[str, ...]
__version__: str

class RouthError(Exception):
    """An error of routh's analyses; `kind` names the Rust variant."""

    kind: str

class ModelError(RouthError):
    """A mistake in a model's text or parameters, at `line`, `column` (from 1)."""

    line: int
    column: int
    message: str

class SteadyMotion:
    @property
    def gamma(self) -> npt.NDArray[np.float64]: ...
    @property
    def p_psi(self) -> float: ...
    @property
    def psi_dot(self) -> float: ...
    @property
    def mu(self) -> float: ...
    @property
    def energy(self) -> float: ...
    @property
    def amended_potential(self) -> float: ...
    @property
    def isolated(self) -> bool: ...

class StabilityReport:
    verdict: Verdict
    degree_of_instability: int
    restricted_hessian_eigenvalues: npt.NDArray[np.float64]
    f2_roots: npt.NDArray[np.complex128]

class Branch:
    s: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    verdicts: list[Verdict]
    isolated: bool
    def __len__(self) -> int: ...

class Event:
    kind: EventKind
    s: float
    gamma: npt.NDArray[np.float64]
    branch: int
    before: Verdict
    after: Verdict

class Diagram:
    branches: list[Branch]
    events: list[Event]
    def plot(self, ax: Any = None, component: int = 2) -> Any: ...
    def _repr_svg_(self) -> str: ...

BifurcationDiagram = Diagram

class Boundary:
    kind: EventKind
    points: npt.NDArray[np.float64]

class Atlas:
    x: npt.NDArray[np.float64]
    y: npt.NDArray[np.float64]
    verdicts: list[list[Verdict | None]]
    boundaries: list[Boundary]
    def plot(self, ax: Any = None) -> Any: ...
    def _repr_svg_(self) -> str: ...

StabilityAtlas = Atlas

class Trajectory:
    t: npt.NDArray[np.float64]
    omega: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    p_psi: npt.NDArray[np.float64]

class ReducedTrajectory:
    t: npt.NDArray[np.float64]
    big_omega: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    psi: npt.NDArray[np.float64]
    psi_dot: npt.NDArray[np.float64]
    omega: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    p_psi: npt.NDArray[np.float64]

class Certificate:
    complete: bool
    motions: list[SteadyMotion]
    p_psi: float
    boxes: int
    undecided: int

class Model:
    def __init__(self, lagrangian: str, parameters: Mapping[str, ParamValue] | None = None) -> None: ...
    @staticmethod
    def from_toml(text: str) -> Model: ...
    @staticmethod
    def load(path: str | PathLike[str]) -> Model: ...
    def set(self, name: str, value: ParamValue) -> None: ...
    def with_params(self, **kw: ParamValue) -> Model: ...
    def get_param(self, name: str) -> float | npt.NDArray[np.float64] | None: ...
    @property
    def parameters(self) -> dict[str, float | npt.NDArray[np.float64]]: ...
    @property
    def lagrangian(self) -> str: ...
    @property
    def latex_symbols(self) -> dict[str, str]: ...
    @property
    def formulas(self) -> dict[str, str]: ...
    def amended_potential(self, gamma: Vec3, p_psi: float) -> float: ...
    def steady_motions(self, p_psi: float) -> list[SteadyMotion]: ...
    def classify(self, motion: SteadyMotion) -> StabilityReport: ...
    def bifurcation_diagram(
        self,
        range: tuple[float, float],
        *,
        initial_step: float | None = None,
        max_step: float | None = None,
        min_step: float | None = None,
        max_steps: int | None = None,
        max_branches: int | None = None,
        newton_tol: float | None = None,
        event_tol: float | None = None,
        seeds: int | None = None,
        verify_counts: bool | None = None,
    ) -> Diagram: ...
    def simulate(
        self, omega0: Vec3, gamma0: Vec3, t_end: float, *, rtol: float = 1e-10, atol: float = 1e-12,
        max_steps: int | None = None,
    ) -> Trajectory: ...
    def simulate_reduced(
        self, big_omega0: Vec3, gamma0: Vec3, p_psi: float, t_end: float, *, rtol: float = 1e-10,
        atol: float = 1e-12, max_steps: int | None = None,
    ) -> ReducedTrajectory: ...
    def certify(self, p_psi: float) -> Certificate: ...

def bifurcation_diagram(
    family: Callable[[float], tuple[Model, float]],
    range: tuple[float, float],
    *,
    initial_step: float | None = None,
    max_step: float | None = None,
    min_step: float | None = None,
    max_steps: int | None = None,
    max_branches: int | None = None,
    newton_tol: float | None = None,
    event_tol: float | None = None,
    seeds: int | None = None,
    verify_counts: bool | None = None,
    progress: bool = False,
) -> Diagram: ...
def stability_atlas(
    family: Callable[[float, float], tuple[Model, float]],
    gamma_guess: Vec3,
    x: tuple[float, float],
    y: tuple[float, float],
    *,
    nx: int | None = None,
    ny: int | None = None,
    curve_tol: float | None = None,
    curve_step: float | None = None,
    max_curve_points: int | None = None,
    progress: bool = False,
) -> Atlas: ...
