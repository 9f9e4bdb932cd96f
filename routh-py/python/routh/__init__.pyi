"""Type stubs of the Python package `routh` (docs/python.md)."""

from os import PathLike
from typing import Any, Callable, Literal, Mapping, Sequence, TypedDict, Union

from typing_extensions import Unpack

import numpy as np
import numpy.typing as npt

Verdict = Literal["secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate"]
EventKind = Literal["fold", "branch_point", "hamiltonian_hopf", "arnold_degenerate", "resonance"]
NonlinearVerdict = Literal["secularly_stable", "lyapunov_stable", "unstable", "undecided"]
OrbitStability = Literal["elliptic", "parabolic", "hyperbolic", "inverse_hyperbolic"]
OrbitEventKind = Literal[
    "fold", "branch_point", "period_doubling", "twist_degenerate", "third_order_resonance",
    "fourth_order_resonance",
]
OrbitNonlinearVerdict = Literal["orbitally_stable", "unstable", "undecided"]
OrbitResonance = Literal["third", "fourth"]
ParamValue = Union[float, Sequence[float], Sequence[Sequence[float]], npt.ArrayLike]
Vec3 = Union[Sequence[float], npt.NDArray[np.float64]]

# The keywords of the analyses: every field of the Rust options struct, defaults its `Default`
# (`routh._options_schema()`; routh-py/tests/test_options.py checks these against it). None
# for a keyword is its default.

class _OrbitFamilyOptions(TypedDict, total=False):
    """The fields of `OrbitOptions` an orbit chart's families share with any family."""

    atol: float  # default 1e-12
    event_tol: float  # default 1e-9
    initial_amplitude: float  # default 0.001
    initial_step: float  # default 0.02
    max_iter: int  # default 12
    max_period_ratio: float  # default 20.0
    max_step: float  # default 0.1
    max_steps: int  # default 100000
    min_step: float  # default 1e-7
    newton_tol: float  # default 1e-9
    parabolic_tol: float  # default 1e-6
    resonance_tol: float  # default 0.001
    rtol: float  # default 1e-11

class _OrbitOptions(_OrbitFamilyOptions, total=False):
    """`OrbitOptions`: the periodic orbits and their families."""

    energy_bounds: tuple[float, float] | None  # default None
    max_orbits: int  # default 100
    nonlinear: bool  # default False

class _OrbitNonlinearOptions(TypedDict, total=False):
    """`OrbitNonlinearOptions`: an orbit's stability beyond linear."""

    atol: float  # default 1e-13
    criterion_tol: float  # default 1e-6
    max_steps: int  # default 100000
    resonance_tol: float  # default 1e-6
    rtol: float  # default 1e-11
    twist_tol: float  # default 1e-6

class _OrbitChartOptions(_OrbitFamilyOptions, total=False):
    """`OrbitChartOptions`: an orbit chart, its families' fields by their own names (not
    `energy_bounds` and `nonlinear`, which the chart sets)."""

    join_tol: float  # default 0.05
    max_orbits: int  # default 200
    nx: int  # default 41

class _ContinuationOptions(TypedDict, total=False):
    """`ContinuationOptions`: a bifurcation diagram, the fields of its `search` and
    `classify` by their own names (`zero_eigenvalue_tol`, in both, only as
    `**{"classify.zero_eigenvalue_tol": ...}`); `nonlinear=True` locates the nonlinear events."""

    double_root_tol: float  # default 1e-10
    em_turn_degrees: float  # default 3.0
    event_tol: float  # default 1e-10
    gradient_tol: float  # default 1e-10
    initial_step: float  # default 0.01
    max_branches: int  # default 64
    max_iterations: int  # default 100
    max_step: float  # default 0.05
    max_steps: int  # default 20000
    min_step: float  # default 1e-7
    newton_tol: float  # default 1e-12
    nonlinear: bool | None  # default None
    seeds: int  # default 5
    starts: int  # default 400
    steady_tol: float  # default 1e-5
    verify_counts: bool  # default True

class _AtlasOptions(TypedDict, total=False):
    """`AtlasOptions`: a stability atlas, the fields of its `classify` by their own names;
    `nonlinear=True` as for a diagram."""

    curve_step: float  # default 0.005
    curve_tol: float  # default 1e-10
    double_root_tol: float  # default 1e-10
    max_curve_points: int  # default 20000
    max_guess_angle: float  # default 0.35
    nonlinear: bool | None  # default None
    nx: int  # default 41
    ny: int  # default 41
    start: tuple[float, float] | None  # default None
    steady_tol: float  # default 1e-5
    threads: int  # default 0
    zero_eigenvalue_tol: float  # default 1e-8

class _SimOptions(TypedDict, total=False):
    """`SimOptions`: a simulation (its `output` is the keyword `times`; `method` as serde
    writes it, `"Dop853"` or `{"LieRk4": {"step": h}}`)."""

    atol: float  # default 1e-12
    attitude: bool  # default False
    h_init: float | None  # default None
    h_max: float | None  # default None
    max_steps: int  # default 100000
    method: str | dict[str, Any]  # default "Dop853"
    rate_atol: float | None  # default None
    rtol: float  # default 1e-10

class _SectionOptions(TypedDict, total=False):
    """`SectionOptions`: a Poincaré section and an orbit's crossings."""

    atol: float  # default 1e-12
    crossings: int  # default 200
    normal: Vec3  # default (1.0, 0.0, 0.0)
    orbits: int  # default 50
    rtol: float  # default 1e-10
    steps_per_crossing: int  # default 2000

class _NonlinearOptions(TypedDict, total=False):
    """`NonlinearOptions`: a steady motion's nonlinear stability, the fields of its
    `classify` by their own names."""

    arnold_tol: float  # default 1e-8
    criterion_tol: float  # default 1e-6
    double_root_tol: float  # default 1e-10
    resonance_tol: float  # default 1e-6
    steady_tol: float  # default 1e-5
    zero_eigenvalue_tol: float  # default 1e-8

VERDICTS: tuple[str, ...]
EVENT_KINDS: tuple[str, ...]
NONLINEAR_VERDICTS: tuple[str, ...]
ORBIT_STABILITIES: tuple[str, ...]
ORBIT_EVENT_KINDS: tuple[str, ...]
ORBIT_NONLINEAR_VERDICTS: tuple[str, ...]
MAX_ATLAS_NODES: int
"""The largest atlas grid nx·ny accepted (larger ones raise RouthError before allocating)."""
__version__: str

class RouthError(Exception):
    """An error of routh's analyses; `kind` names the Rust variant ("NonFinite",
    "InvalidOption", ...; "Panic" for an internal error caught at the boundary)."""

    kind: str

class ModelError(RouthError):
    """A mistake in a model's text or parameters, at `line`, `column` (from 1) in the text, or
    None for both where it has no place in a text (`set`, `with_params`, a file not read)."""

    line: int | None
    column: int | None
    message: str

class SteadyMotion:
    """A steady motion (33): a critical point of U_r on the sphere.

    >>> m = top.steady_motions(3.0)[0]
    >>> m.gamma, m.psi_dot, m.energy
    """
    def _repr_html_(self) -> str: ...
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
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> SteadyMotion:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = SteadyMotion.from_json(r.to_json())
        """

class StabilityReport:
    """The stability of a steady motion (sections 4–5).

    >>> r = top.classify(top.steady_motions(3.0)[0])
    >>> r.verdict, r.degree_of_instability, r.f2_roots
    """
    def _repr_html_(self) -> str: ...
    verdict: Verdict
    degree_of_instability: int
    restricted_hessian_eigenvalues: npt.NDArray[np.float64]
    f2_roots: npt.NDArray[np.complex128]
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> StabilityReport:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = StabilityReport.from_json(r.to_json())
        """

class CircleReport:
    """A circle of steady motions of a symmetric body, decided modulo the symmetry by the
    doubly amended potential: `curvature` = V'' = `across` + `momentum_term`.

    >>> c = [m for m in top.steady_motions(3.0) if not m.isolated][0]
    >>> top.classify_circle(c, (0, 0, 1)).verdict
    'stable'
    """
    verdict: Literal["stable", "unstable", "degenerate"]
    curvature: float
    across: float
    momentum_term: float
    axis_momentum: float
    axis: npt.NDArray[np.float64]
    report: StabilityReport
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> CircleReport:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = CircleReport.from_json(r.to_json())
        """

class Branch:
    """A branch of a diagram: `s` (n,), `gamma` (n, 3), `p_psi` and `energy` (n,) (the
    energy–momentum diagram), `verdicts` (n strings)."""
    s: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    p_psi: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    verdicts: list[Verdict]
    isolated: bool
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Branch:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Branch.from_json(r.to_json())
        """

class Event:
    """A fold, branch point or Hamiltonian–Hopf point on branch `branch` (with
    `nonlinear=True` also Arnold's D = 0 and the 1:2, 1:3 resonances)."""
    kind: EventKind
    s: float
    gamma: npt.NDArray[np.float64]
    branch: int
    before: Verdict
    after: Verdict
    resonance: str | None
    """"1:2" or "1:3" for a resonance event, else None."""
    nonlinear: tuple[NonlinearVerdict, NonlinearVerdict, NonlinearVerdict] | None
    """The nonlinear verdicts (before, at, after) of a nonlinear event, else None."""
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Event:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Event.from_json(r.to_json())
        """

class NonlinearReport:
    """The nonlinear stability of a steady motion (Birkhoff normal form, Arnold–Moser).

    >>> m = max(top.steady_motions(2.2), key=lambda s: s.gamma[2])   # the sleeping top (γ₃ = 1)
    >>> r = top.nonlinear_stability(m)
    >>> r.verdict, r.arnold_determinant, r.resonance
    """
    verdict: NonlinearVerdict
    reason: str
    linear: StabilityReport
    frequencies: npt.NDArray[np.float64]
    krein_signs: tuple[int, int]
    normal_form: npt.NDArray[np.float64]
    arnold_determinant: float
    resonance: str | None
    resonance_distance: float
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> NonlinearReport:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = NonlinearReport.from_json(r.to_json())
        """

class Diagram:
    """A bifurcation diagram; in Jupyter it shows its tables and figure.

    >>> d = top.bifurcation_diagram((0.0, 5.0))
    >>> ax = d.plot()          # stable solid, unstable dashed, events marked and named
    """
    branches: list[Branch]
    events: list[Event]
    stop: str | None
    """None, or why the diagram stopped early (a budget ran out)."""
    checks: list[tuple[float, int, int]]
    """(s, on_branches, searched): steady motions on the branches at s against a global search."""
    def consistent(self) -> bool:
        """Whether every count check agreed (True when none was made)."""
    def plot(
        self,
        ax: Any = None,
        component: int = 2,
        *,
        xlabel: str = "p_ψ",
        ylabel: str | None = None,
        values: bool = False,
        circles: Model | None = None,
        axis: Vec3 = (0.0, 0.0, 1.0),
    ) -> Any:
        """Draw s against γ[component] on `ax` (a new one, a journal column wide, if None) in
        the style of `plot_style()`; `xlabel` names the family's parameter, `values` writes each
        event's value, `circles` (the model) draws the circles with `classify_circle`'s verdict.
        Returns the axes."""
    def _repr_svg_(self) -> str: ...
    def _repr_html_(self) -> str: ...

    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Diagram:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Diagram.from_json(r.to_json())
        """

BifurcationDiagram = Diagram

class Boundary:
    """A curve of an atlas where the verdict changes: `points` (n, 2) of (x, y)."""
    kind: EventKind
    points: npt.NDArray[np.float64]
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Boundary:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Boundary.from_json(r.to_json())
        """

class Atlas:
    """A stability atlas: `verdicts[j][i]` at (x[i], y[j]) (ny rows of nx, as in Rust), `lost`
    (True where the motion was lost, not absent), `stop` and the `boundaries`.

    >>> a = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
    ...                           (0.5, 2.0), (0.5, 5.0), nx=21, ny=21)
    >>> ax = a.plot()
    """
    x: npt.NDArray[np.float64]
    y: npt.NDArray[np.float64]
    verdicts: list[list[Verdict | None]]
    """`verdicts[j][i]` at (x[i], y[j]); None where there is no steady motion or it was lost."""
    lost: list[list[bool]]
    """`lost[j][i]`: True where the motion was lost (nothing is known there)."""
    stop: str | None
    """None when the atlas is complete; otherwise why it stopped early."""
    boundaries: list[Boundary]
    def plot(
        self, ax: Any = None, *, xlabel: str = "first parameter", ylabel: str = "second parameter"
    ) -> Any:
        """Draw the verdict regions (tints and hatches), the boundary curves and a legend, the
        axes named `xlabel` and `ylabel`; returns the axes."""
    def _repr_svg_(self) -> str: ...
    def _repr_html_(self) -> str: ...

    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Atlas:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Atlas.from_json(r.to_json())
        """

StabilityAtlas = Atlas

class Trajectory:
    """A solution of the full equations (8).

    `attitude` (with `simulate(..., attitude=True)`, else None) is (n, 4): the rotation R body →
    space as unit quaternions in the order (x, y, z, w), scalar last, as
    `scipy.spatial.transform.Rotation.from_quat` reads them; γ = Rᵀe₃.

    >>> tr = top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 10.0, attitude=True)
    >>> psi, theta, phi = tr.euler_angles().T
    >>> ax = tr.plot_apex()
    """
    t: npt.NDArray[np.float64]
    omega: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    p_psi: npt.NDArray[np.float64]
    attitude: npt.NDArray[np.float64] | None
    def euler_angles(self) -> npt.NDArray[np.float64]:
        """z-x-z Euler angles (ψ, θ, φ), (n, 3), ψ and φ unwrapped; RouthError without attitude."""
    def plot_apex(self, ax: Any = None, axis: tuple[float, float, float] = (0.0, 0.0, 1.0)) -> Any:
        """Draw the path in space of the body axis `axis`, seen from above; returns the axes."""
    def _repr_svg_(self) -> str | None: ...
    def _repr_html_(self) -> str: ...
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Trajectory:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Trajectory.from_json(r.to_json())
        """

class ReducedTrajectory:
    """A solution of the reduced equations (13) with the reconstruction (15); `attitude` as in
    Trajectory (quaternions (x, y, z, w))."""
    t: npt.NDArray[np.float64]
    big_omega: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    psi: npt.NDArray[np.float64]
    psi_dot: npt.NDArray[np.float64]
    omega: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    p_psi: npt.NDArray[np.float64]
    attitude: npt.NDArray[np.float64] | None
    def euler_angles(self) -> npt.NDArray[np.float64]:
        """z-x-z Euler angles (ψ, θ, φ) of the attitude (not the gauge angle `psi`)."""
    def plot_apex(self, ax: Any = None, axis: tuple[float, float, float] = (0.0, 0.0, 1.0)) -> Any:
        """Draw the apex locus (see Trajectory.plot_apex)."""
    def _repr_svg_(self) -> str | None: ...
    def _repr_html_(self) -> str: ...
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> ReducedTrajectory:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = ReducedTrajectory.from_json(r.to_json())
        """

class Certificate:
    """A certified enumeration: when `complete`, `motions` are all the steady motions.

    >>> c = top.certify(2.2)
    """
    def _repr_html_(self) -> str: ...
    complete: bool
    motions: list[SteadyMotion]
    p_psi: float
    boxes: int
    undecided: int
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> Certificate:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = Certificate.from_json(r.to_json())
        """

class LatexFormulas:
    """The derived formulas in LaTeX (no delimiters); Jupyter typesets all seven.

    >>> f = top.latex()
    >>> print(f.amended_potential)
    """
    lagrangian: str
    psi_dot: str
    routhian: str
    amended_potential: str
    a: str
    g: str
    c: str
    def as_dict(self) -> dict[str, str]: ...
    def __getitem__(self, name: str) -> str: ...
    def _repr_latex_(self) -> str: ...

class SympyFormulas:
    """The derived formulas in SymPy's syntax (`omega1`, `gamma3`, `p_psi`, parameters by name,
    components from 1: `inertia_3`); `to_sympy()` parses them (SymPy needed).

    >>> f = top.sympy()
    >>> f.amended_potential
    """
    lagrangian: str
    psi_dot: str
    routhian: str
    amended_potential: str
    a: str
    g: str
    c: str
    definitions: list[tuple[str, str]]
    symbols: list[tuple[str, str]]
    def as_dict(self) -> dict[str, str]: ...
    def __getitem__(self, name: str) -> str: ...
    def to_sympy(self) -> dict[str, Any]:
        """The formulas as SymPy expressions (`sympy.Matrix` for a, g, c)."""

class PeriodicOrbit:
    """A periodic orbit of the full equations (a relative periodic orbit of the body).

    >>> o = m.periodic_orbit([0, 0, 0], [0, np.sin(0.5), -np.cos(0.5)], 6.0)
    >>> o.period, o.stability_index, o.stability
    """
    omega0: npt.NDArray[np.float64]
    gamma0: npt.NDArray[np.float64]
    period: float
    energy: float
    p_psi: float
    precession: float
    body_turn: float
    multipliers: npt.NDArray[np.complex128]
    stability_index: float
    stability: OrbitStability
    degenerate: bool
    amplitude: float
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> PeriodicOrbit:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = PeriodicOrbit.from_json(r.to_json())
        """

class OrbitEvent:
    """A fold, branch point or period doubling of a family of periodic orbits."""
    kind: OrbitEventKind
    energy: float
    orbit: PeriodicOrbit
    before: OrbitStability
    after: OrbitStability
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> OrbitEvent:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = OrbitEvent.from_json(r.to_json())
        """

class OrbitFamily:
    """A family of periodic orbits at one p_ψ, in the order of continuation.

    >>> f = m.lyapunov_family(hanging, 0, max_orbits=40)
    >>> ax = f.plot()                       # k against E, k = ±1, events named
    >>> ax = f.plot(quantity="period")      # T against E
    """
    orbits: list[PeriodicOrbit]
    events: list[OrbitEvent]
    stop: str | None
    energy: npt.NDArray[np.float64]
    period: npt.NDArray[np.float64]
    stability_index: npt.NDArray[np.float64]
    precession: npt.NDArray[np.float64]
    stability: list[OrbitStability]
    def __len__(self) -> int: ...
    def plot(self, ax: Any = None, quantity: Literal["stability_index", "period"] = "stability_index") -> Any: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> OrbitFamily:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = OrbitFamily.from_json(r.to_json())
        """

class OrbitParameterFamily:
    """A family of periodic orbits at one energy through a parameter of the model
    (`Model.continue_orbit_in`): the orbits and events in `family`, the parameter's value at each
    in `parameter` and `event_parameter`.

    >>> f = m.continue_orbit_in(orbit, "mgl", (1.2, 2.0))
    >>> f.parameter, f.family.period
    """
    name: str
    family: OrbitFamily
    parameter: npt.NDArray[np.float64]
    event_parameter: npt.NDArray[np.float64]
    def __len__(self) -> int: ...

class OrbitNonlinearReport:
    """The orbital stability of a periodic orbit beyond the linear test
    (`Model.orbit_nonlinear_stability`): rotation number ρ, twist τ = dρ/dA (A the enclosed
    symplectic area), resonance and verdict.

    >>> r = m.orbit_nonlinear_stability(f.orbits[-1])
    >>> r.verdict, r.rotation_number, r.twist
    """
    orbit: PeriodicOrbit
    rotation_number: float
    twist: float
    resonance: OrbitResonance | None
    verdict: OrbitNonlinearVerdict
    reason: str
    area_defect: float
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> OrbitNonlinearReport:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = OrbitNonlinearReport.from_json(r.to_json())
        """

class OrbitChartCurve:
    """A curve of an orbit chart: `kind` (an orbit event kind) and `points` (n, 2): (x, h)."""
    kind: OrbitEventKind
    points: npt.NDArray[np.float64]
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> OrbitChartCurve:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = OrbitChartCurve.from_json(r.to_json())
        """

class OrbitChart:
    """The chart of a mode's Lyapunov family over a parameter x and the energy h = E − E_s(x)
    above the steady motion (`routh.orbit_chart`, `Model.orbit_chart`).

    >>> c = m.orbit_chart("b", [0, 0, -1], (1.9, 2.1), (0.0, 2.8), nx=5)
    >>> ax = c.plot()
    >>> df, curves = c.to_pandas(), c.curves_frame()
    """
    parameter: str
    x: npt.NDArray[np.float64]
    steady_energy: npt.NDArray[np.float64]
    families: list[OrbitFamily | None]
    failures: list[str | None]
    curves: list[OrbitChartCurve]
    stop: str | None
    samples: npt.NDArray[np.float64]
    def __len__(self) -> int: ...
    def plot(self, ax: Any = None, xlabel: str | None = None) -> Any:
        """The orbits coloured by linear stability, the curves one dash per kind, a legend."""
    def curves_frame(self) -> Any:
        """The curves' points as a DataFrame: `kind`, `curve`, `x`, `h`."""
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> OrbitChart:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = OrbitChart.from_json(r.to_json())
        """

class PoincareSection:
    """Crossings of the plane γ·n = 0 at (p_ψ, E) in the coordinates (θ, M_n).

    >>> s = m.poincare_section(0.0, -1.0, orbits=20, crossings=100)
    >>> ax = s.plot(fixed_points=m.orbit_crossings(orbit))
    """
    p_psi: float
    energy: float
    normal: npt.NDArray[np.float64]
    points: list[npt.NDArray[np.float64]]
    starts: npt.NDArray[np.float64]
    def plot(self, ax: Any = None, fixed_points: npt.ArrayLike | None = None) -> Any: ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame, columns as in docs/python.md ("Export"); ImportError without pandas.

        >>> df = r.to_pandas()
        """
    def to_csv(self, path: str | PathLike[str]) -> None:
        """Writes `to_pandas()` (no index) to the CSV file `path`, whole or not at all."""
    def to_json(self) -> str:
        """Strict JSON text; NaN and ±∞ as "NaN", "Infinity", "-Infinity"."""
    @classmethod
    def from_json(cls, text: str) -> PoincareSection:
        """The object of `to_json()` again, numbers bit for bit.

        >>> same = PoincareSection.from_json(r.to_json())
        """

class Model:
    """A rigid body: a Lagrangian in the derive's language and its parameters.

    >>> top = routh.Model(
    ...     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
    ...     {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    """
    def __init__(self, lagrangian: str, parameters: Mapping[str, ParamValue] | None = None) -> None: ...
    @staticmethod
    def from_toml(text: str) -> Model: ...
    @staticmethod
    def from_file(path: str | PathLike[str]) -> Model:
        """A model from a TOML file (the Rust `Model::from_file`); `load` is an alias."""
    @staticmethod
    def load(path: str | PathLike[str]) -> Model:
        """Alias of `Model.from_file`, kept for existing code."""
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
    def latex(self) -> LatexFormulas:
        """L, ψ̇, R, U_r, A, G, C in LaTeX."""
    def _repr_latex_(self) -> str:
        """R and U_r typeset (Jupyter)."""
    def sympy(self) -> SympyFormulas:
        """L, ψ̇, R, U_r, A, G, C in SymPy's syntax."""
    def to_sympy(self) -> dict[str, Any]:
        """L, ψ̇, R, U_r, A, G, C as SymPy objects (ImportError without SymPy)."""
    def formula_values(
        self, omega: Vec3, gamma: Vec3, p_psi: float
    ) -> dict[str, float | npt.NDArray[np.float64]]:
        """The seven formulas' values from the generated code."""
    def amended_potential(self, gamma: Vec3, p_psi: float) -> float:
        """U_r(γ, p_ψ) at a unit γ (| |γ| − 1 | ≤ 1e-8, as `simulate`; else RouthError)."""
    def steady_motions(self, p_psi: float) -> list[SteadyMotion]: ...
    def classify(self, motion: SteadyMotion) -> StabilityReport: ...
    def classify_circle(self, motion: SteadyMotion, axis: Vec3) -> CircleReport:
        """A circle of steady motions decided modulo the symmetry about `axis`."""
    def periodic_orbit(
        self,
        omega: Vec3,
        gamma: Vec3,
        period: float,
        **options: Unpack[_OrbitOptions],
    ) -> PeriodicOrbit: ...
    def lyapunov_family(
        self,
        motion: SteadyMotion,
        mode: int = 0,
        **options: Unpack[_OrbitOptions],
    ) -> OrbitFamily: ...
    def continue_orbit(
        self,
        orbit: PeriodicOrbit,
        energy_range: tuple[float, float],
        **options: Unpack[_OrbitOptions],
    ) -> OrbitFamily: ...
    def continue_orbit_in(
        self,
        orbit: PeriodicOrbit,
        name: str,
        s_range: tuple[float, float],
        **options: Unpack[_OrbitOptions],
    ) -> OrbitParameterFamily: ...
    def period_doubled_family(
        self, event: OrbitEvent, **options: Unpack[_OrbitOptions]
    ) -> OrbitFamily: ...
    def switch_branch(self, event: OrbitEvent, **options: Unpack[_OrbitOptions]) -> OrbitFamily:
        """The family crossing `event`'s family at that "branch_point", followed both ways from it.

        RouthError (kind "InvalidOption") for an event that is not a branch point.

        >>> bp = next(e for e in f.events if e.kind == "branch_point")
        >>> g = m.switch_branch(bp, max_orbits=20)
        """
    def poincare_section(
        self,
        p_psi: float,
        energy: float,
        **options: Unpack[_SectionOptions],
    ) -> PoincareSection: ...
    def orbit_crossings(
        self, orbit: PeriodicOrbit, **options: Unpack[_SectionOptions]
    ) -> npt.NDArray[np.float64]: ...
    def orbit_path(self, orbit: PeriodicOrbit, n: int = 200) -> Trajectory: ...
    def orbit_nonlinear_stability(
        self,
        orbit: PeriodicOrbit,
        **options: Unpack[_OrbitNonlinearOptions],
    ) -> OrbitNonlinearReport:
        """The rotation number, twist and verdict of an orbit beyond the linear test (§5h)."""
    def orbit_chart(
        self,
        parameter: str,
        gamma_guess: Vec3,
        x_range: tuple[float, float],
        excess_energy: tuple[float, float],
        *,
        mode: int = 0,
        momentum: float | None = None,
        **options: Unpack[_OrbitChartOptions],
    ) -> OrbitChart:
        """`routh.orbit_chart(self, gamma_guess, x_range, excess_energy, parameter=parameter, ...)`."""
    def nonlinear_stability(
        self,
        motion: SteadyMotion,
        **options: Unpack[_NonlinearOptions],
    ) -> NonlinearReport: ...
    def bifurcation_diagram(
        self,
        range: tuple[float, float],
        *,
        progress: bool = False,
        **options: Unpack[_ContinuationOptions],
    ) -> Diagram: ...
    def simulate_full(
        self, omega0: Vec3, gamma0: Vec3, t_end: float, *,
        times: Sequence[float] | npt.NDArray[np.float64] | None = None,
        **options: Unpack[_SimOptions],
    ) -> Trajectory:
        """Integrate the full equations (8) (the Rust `simulate_full`); `simulate` is an alias."""
    def simulate(
        self, omega0: Vec3, gamma0: Vec3, t_end: float, *,
        times: Sequence[float] | npt.NDArray[np.float64] | None = None,
        **options: Unpack[_SimOptions],
    ) -> Trajectory:
        """Alias of `Model.simulate_full`, kept for existing code."""
    def simulate_reduced(
        self, big_omega0: Vec3, gamma0: Vec3, p_psi: float, t_end: float, *,
        times: Sequence[float] | npt.NDArray[np.float64] | None = None,
        **options: Unpack[_SimOptions],
    ) -> ReducedTrajectory: ...
    def steady_motions_certified(
        self, p_psi: float, *, initial_split: int | None = None, min_width: float | None = None,
        max_boxes: int | None = None, refine_iterations: int | None = None,
    ) -> Certificate:
        """A certified enumeration of the steady motions at p_psi (interval arithmetic; the Rust
        `steady_motions_certified`); `certify` is an alias."""
    def certify(
        self, p_psi: float, *, initial_split: int | None = None, min_width: float | None = None,
        max_boxes: int | None = None, refine_iterations: int | None = None,
    ) -> Certificate:
        """Alias of `Model.steady_motions_certified`, kept for existing code."""

def bifurcation_diagram(
    family: Callable[[float], tuple[Model, float]],
    range: tuple[float, float],
    *,
    progress: bool = False,
    **options: Unpack[_ContinuationOptions],
) -> Diagram: ...
def orbit_chart(
    family: Model | Callable[[float], tuple[Model, float]],
    gamma_guess: Vec3,
    x_range: tuple[float, float],
    excess_energy: tuple[float, float],
    *,
    mode: int = 0,
    parameter: str | None = None,
    momentum: float | None = None,
    **options: Unpack[_OrbitChartOptions],
) -> OrbitChart:
    """The chart of the Lyapunov family of `mode` over a parameter x and h = E − E_s(x): a
    `Model` through its scalar parameter `parameter` (or "p_psi") at p_ψ = `momentum`, or a
    callable `x -> (Model, p_psi)`.

    >>> c = routh.orbit_chart(m, [0, 0, -1], (1.9, 2.1), (0.0, 2.8), parameter="b", nx=5)
    """
def plot_style() -> dict[str, Any]:
    """The one style of routh's figures (colours, widths, dashes, markers, fonts) as a dict,
    shared with the Rust SVGs (`routh::style`)."""
def stability_atlas(
    family: Callable[[float, float], tuple[Model, float]],
    gamma_guess: Vec3,
    x: tuple[float, float],
    y: tuple[float, float],
    *,
    progress: bool = False,
    **options: Unpack[_AtlasOptions],
) -> Atlas: ...
def study(
    job: Union[str, Callable[..., Any]],
    model: Model,
    grid: Union[Mapping[str, Sequence[Any]], Sequence[Mapping[str, Any]]],
    client: Any = None,
    chunk: int | None = None,
    progress: bool = True,
    n_workers: int = 2,
    timeout: float | None = None,
) -> Any:
    """`job(model, **point)` (or the `Model` method named `job`) at every point of `grid` on a
    Dask cluster (a LocalCluster of `n_workers` processes by default, or `client`: a
    `dask.distributed.Client` or an address): a pandas.DataFrame, one row per point, the
    result's fields as columns and an `error` column. Needs `routh[dask]`."""
def to_pandas(results: Any) -> Any:
    """The DataFrame of a result, or of a list of results (their rows one after another).

    >>> df = routh.to_pandas(top.steady_motions(3.0))
    """
def to_csv(results: Any, path: str | PathLike[str]) -> None:
    """Writes `to_pandas(results)` to the CSV file `path`, whole or not at all."""
def to_json(results: Any) -> str:
    """The JSON text of a result, or a JSON array for a list of results."""
def from_json(text: str) -> Any:
    """The result (or list of results) of `to_json` text, numbers bit for bit.

    >>> d2 = routh.from_json(d.to_json())
    """
def _restore(kind: str, state: Any) -> Any: ...
def _options_schema() -> dict[str, dict[str, Any]]:
    """{options struct: {keyword: default}}: the keywords of the analyses and their defaults."""
