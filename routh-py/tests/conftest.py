import pathlib

import pytest

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]

TOP_TEXT = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


@pytest.fixture
def top():
    """The Lagrange top of examples/heavy_top.rs: A₁ = 1, C = 1.25, mgl = 1."""
    return routh.Model(TOP_TEXT, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})


@pytest.fixture
def gyrostat():
    """The Kelvin gyrostat of paper Example 1 (examples/models/gyrostat.toml)."""
    return routh.Model.load(ROOT / "examples" / "models" / "gyrostat.toml")
