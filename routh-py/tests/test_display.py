"""Jupyter displays: LaTeX of a model, HTML tables of results (with their figures)."""

import numpy as np
import pytest

import routh


def test_latex_formulas(top, gyrostat):
    f = top.latex()
    d = f.as_dict()
    assert set(d) == {"lagrangian", "psi_dot", "routhian", "amended_potential", "a", "g", "c"}
    assert all(isinstance(v, str) and v for v in d.values())
    assert f["routhian"] == f.routhian and f["a"] == f.a
    with pytest.raises(KeyError):
        f["nope"]
    # U_r of the top is mgl γ₃ + p²/(2 γᵀJγ): its symbols, and matrices as pmatrix.
    assert r"\mathit{mgl}" in f.amended_potential and r"p_\psi" in f.amended_potential
    assert "pmatrix" in f.a and "pmatrix" in f.c
    # The TOML's [latex] table replaces the parameter names.
    g = gyrostat.latex()
    assert "I_{" in g.routhian and r"\mathit{inertia}" not in g.routhian
    tex = f._repr_latex_()
    assert tex.startswith("$$") and tex.endswith("$$") and f.psi_dot in tex


def test_model_repr_latex_shows_r_and_u_r(top):
    tex = top._repr_latex_()
    f = top.latex()
    assert tex.startswith("$$") and tex.endswith("$$")
    assert "R &= " + f.routhian in tex and "U_r &= " + f.amended_potential in tex


def test_html_of_motion_report_certificate(top):
    m = top.steady_motions(3.0)[0]
    r = top.classify(m)
    assert "<table" in m._repr_html_() and "psi_dot" in m._repr_html_()
    h = r._repr_html_()
    assert "<table" in h and r.verdict in h
    c = top.certify(2.2)
    assert "<table" in c._repr_html_() and "complete" in c._repr_html_()
    assert "Certificate(complete=" in repr(c)


def test_html_of_diagram_atlas_trajectory(top):
    pytest.importorskip("matplotlib")
    d = top.bifurcation_diagram((0.0, 5.0))
    h = d._repr_html_()
    assert "<table" in h and "hamiltonian_hopf" in h and "<svg" in h
    a = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
                              (0.5, 2.0), (0.5, 5.0), nx=5, ny=5)
    h = a._repr_html_()
    assert "<table" in h and "unstable" in h and "<svg" in h
    assert "StabilityAtlas(5x5 grid" in repr(a)
    tr = top.simulate([0.0, 0.3, 5.0], [0.6, 0.0, 0.8], 2.0, attitude=True)
    h = tr._repr_html_()
    assert "<table" in h and "<svg" in h
    plain = top.simulate_reduced([0.0, 0.3, 0.0], [0.6, 0.0, 0.8], 3.0, 1.0)
    assert "<svg" not in plain._repr_html_() and "<table" in plain._repr_html_()


def test_svg_does_not_touch_pyplot(top):
    plt = pytest.importorskip("matplotlib.pyplot")
    before = plt.get_fignums()
    top.bifurcation_diagram((0.0, 5.0))._repr_svg_()
    assert plt.get_fignums() == before  # no stray figure shown twice in a notebook
    assert isinstance(np.asarray([0]), np.ndarray)
