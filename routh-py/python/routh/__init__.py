"""routh: Routh reduction for rigid-body dynamics (Bourov & Chevallier, ZAMM 1998) in Python.

A model is a Lagrangian written in the language of ``#[derive(Lagrangian)]`` and its
parameters; every analysis of the Rust crate runs on it, with numpy arrays in and out.

>>> import routh
>>> top = routh.Model(
...     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
...     {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
>>> sleeping = [m for m in top.steady_motions(3.0) if abs(m.gamma[2] - 1) < 1e-9][0]
>>> top.classify(sleeping).verdict
'secularly_stable'
"""

from ._routh import (
    Atlas,
    Boundary,
    Branch,
    Certificate,
    CircleReport,
    Diagram,
    Event,
    LatexFormulas,
    MAX_ATLAS_NODES,
    Model,
    ModelError,
    NonlinearReport,
    OrbitChart,
    OrbitChartCurve,
    OrbitEvent,
    OrbitFamily,
    OrbitNonlinearReport,
    OrbitParameterFamily,
    PeriodicOrbit,
    PoincareSection,
    ReducedTrajectory,
    RouthError,
    StabilityReport,
    SteadyMotion,
    SympyFormulas,
    Trajectory,
    bifurcation_diagram,
    orbit_chart,
    _options_schema,
    plot_style,
    stability_atlas,
)
from . import _routh
from ._export import from_json, to_csv, to_json, to_pandas
from .study import study


def _restore(kind, state):
    """Makes a pickled routh object again (what every class's ``__reduce__`` names)."""
    return _routh._restore(kind, state)


#: The name the architecture gives the diagram class.
BifurcationDiagram = Diagram
#: The name the architecture gives the atlas class.
StabilityAtlas = Atlas

VERDICTS = ("secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate")
EVENT_KINDS = ("fold", "branch_point", "hamiltonian_hopf", "arnold_degenerate", "resonance")
NONLINEAR_VERDICTS = ("secularly_stable", "lyapunov_stable", "unstable", "undecided")
ORBIT_STABILITIES = ("elliptic", "parabolic", "hyperbolic", "inverse_hyperbolic")
ORBIT_EVENT_KINDS = ("fold", "branch_point", "period_doubling", "twist_degenerate",
                     "third_order_resonance", "fourth_order_resonance")
ORBIT_NONLINEAR_VERDICTS = ("orbitally_stable", "unstable", "undecided")

__all__ = [
    "plot_style",
    "Atlas",
    "BifurcationDiagram",
    "Boundary",
    "Branch",
    "Certificate",
    "CircleReport",
    "Diagram",
    "Event",
    "LatexFormulas",
    "MAX_ATLAS_NODES",
    "Model",
    "ModelError",
    "NONLINEAR_VERDICTS",
    "NonlinearReport",
    "ORBIT_EVENT_KINDS",
    "ORBIT_NONLINEAR_VERDICTS",
    "ORBIT_STABILITIES",
    "OrbitChart",
    "OrbitChartCurve",
    "OrbitEvent",
    "OrbitFamily",
    "OrbitNonlinearReport",
    "OrbitParameterFamily",
    "PeriodicOrbit",
    "PoincareSection",
    "ReducedTrajectory",
    "RouthError",
    "StabilityAtlas",
    "StabilityReport",
    "SteadyMotion",
    "SympyFormulas",
    "Trajectory",
    "bifurcation_diagram",
    "from_json",
    "orbit_chart",
    "stability_atlas",
    "study",
    "to_csv",
    "to_json",
    "to_pandas",
    "VERDICTS",
    "EVENT_KINDS",
]
__version__ = "0.1.0"
