"""routh's Python API against closed forms of classical mechanics and independent numerics."""

import math

import numpy as np
import pytest

import routh
from conftest import ROOT, TOP_TEXT

A1, C, MGL = 1.0, 1.25, 1.0


def upright(model, p):
    ms = [m for m in model.steady_motions(p) if abs(m.gamma[2] - 1.0) < 1e-9]
    assert len(ms) == 1
    return ms[0]


def test_sleeping_top_steady_motion_closed_form(top):
    p = 3.0
    m = upright(top, p)
    # ω = ψ̇ e₃, p_ψ = Cψ̇; E = ½Cψ̇² + mgl; U_r = p²/(2C) + mgl (paper (38), (42)).
    assert m.psi_dot == pytest.approx(p / C, rel=1e-12)
    assert m.energy == pytest.approx(0.5 * C * (p / C) ** 2 + MGL, rel=1e-12)
    assert m.amended_potential == pytest.approx(p * p / (2 * C) + MGL, rel=1e-12)
    assert m.p_psi == p
    assert m.isolated is True
    assert top.amended_potential(m.gamma, p) == pytest.approx(m.amended_potential, rel=1e-14)


@pytest.mark.parametrize(
    "p, verdict",
    [(1.5, "unstable"), (2.2, "gyroscopically_stabilized"), (3.0, "secularly_stable")],
)
def test_sleeping_top_verdicts_maievskii(top, p, verdict):
    # Maievskii: gyroscopic stability iff p² > 4A₁mgl (p > 2); secular iff p² > mglC²/(C − A₁)
    # (p > 2.5).
    r = top.classify(upright(top, p))
    assert r.verdict == verdict
    roots = r.f2_roots
    if verdict == "unstable":
        assert roots.real.max() > 1e-6
    else:
        assert np.abs(roots.real).max() < 1e-9
    # Classical small oscillations of the sleeping top in space: A₁ν² − pν + mgl = 0 (λ = iν),
    # ν = (p ± √(p² − 4A₁mgl))/(2A₁). γ is measured in the body frame, which spins at ω₃ = p/C
    # about the axis: λ_body = i(ν − p/C), with the conjugates and negatives (f₂ is even, real).
    nu = [(p + sgn * complex(p * p - 4 * A1 * MGL) ** 0.5) / (2 * A1) for sgn in (1, -1)]
    lam = [1j * (n - p / C) for n in nu]
    expected = {complex(round(z.real, 6), round(z.imag, 6)) for l in lam for z in (l, -l, l.conjugate(), -l.conjugate())}
    got = {complex(round(z.real, 6), round(z.imag, 6)) for z in roots}
    assert got == expected, (got, expected)



def test_degree_of_instability_and_hessian(top):
    # U_r near the upright top: the restricted second variation has a double eigenvalue whose
    # sign changes at the secular bound p = 2.5 (degree 2 below, 0 above).
    r_low = top.classify(upright(top, 2.2))
    r_high = top.classify(upright(top, 3.0))
    assert r_low.degree_of_instability == 2
    assert r_high.degree_of_instability == 0
    assert (r_low.restricted_hessian_eigenvalues < 0).all()
    assert (r_high.restricted_hessian_eigenvalues > 0).all()


def test_classify_circle_matches_the_doubly_amended_potential(top):
    # The circle of tilted steady motions at p = 3: `classify` says degenerate; modulo the
    # symmetry about e3 it is decided by V(θ) = (p − p_φ cos θ)²/(2A₁ sin²θ) + p_φ²/(2C) + mgl cos θ
    # (Euler angles, written here by hand), whose second derivative it must equal.
    a1, c, mgl, p = 1.0, 1.25, 1.0, 3.0
    motion = [m for m in top.steady_motions(p) if not m.isolated][0]
    report = top.classify_circle(motion, (0.0, 0.0, 1.0))
    assert report.report.verdict == "degenerate"
    assert report.verdict == "stable"
    z = motion.gamma[2]
    th0 = math.acos(z)
    p_phi = c * motion.psi_dot * z
    assert report.axis_momentum == pytest.approx(p_phi, rel=1e-12)

    def v(th):
        return (p - p_phi * math.cos(th)) ** 2 / (2 * a1 * math.sin(th) ** 2) + p_phi**2 / (
            2 * c
        ) + mgl * math.cos(th)

    h = 1e-3
    d2 = (v(th0 + h) - 2 * v(th0) + v(th0 - h)) / h**2
    assert report.curvature == pytest.approx(d2, rel=1e-5)
    assert report.curvature == pytest.approx(report.across + report.momentum_term)
    assert report.across < 0 < report.curvature  # one negative eigenvalue, yet stable
    with pytest.raises(routh.RouthError, match="not symmetric about the axis"):
        top.classify_circle(motion, (1.0, 0.0, 0.0))


def test_gyrostat_steady_motions_are_critical_points(gyrostat):
    # Independent of the solver: U_r restricted to the sphere is stationary at each steady
    # motion (central finite differences along two tangent directions).
    p = 4.0
    ms = gyrostat.steady_motions(p)
    assert len(ms) >= 2
    h = 1e-5
    for m in ms:
        g = m.gamma
        assert np.linalg.norm(g) == pytest.approx(1.0, abs=1e-12)
        t1 = np.cross(g, [1.0, 0.0, 0.0] if abs(g[0]) < 0.9 else [0.0, 1.0, 0.0])
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(g, t1)
        for t in (t1, t2):
            def u(e):
                q = g * math.cos(e) + t * math.sin(e)
                return gyrostat.amended_potential(q, p)
            d = (u(h) - u(-h)) / (2 * h)
            assert abs(d) < 1e-6, (m, d)
        r = gyrostat.classify(m)
        assert r.verdict in routh.VERDICTS


def test_bifurcation_diagram_events_closed_form(top):
    d = top.bifurcation_diagram((0.0, 5.0))
    kinds = {e.kind: e for e in d.events}
    assert kinds["hamiltonian_hopf"].s == pytest.approx(2.0, abs=1e-7)
    assert kinds["branch_point"].s == pytest.approx(math.sqrt(MGL * C * C / (C - A1)), abs=1e-7)
    hh = kinds["hamiltonian_hopf"]
    assert (hh.before, hh.after) == ("unstable", "gyroscopically_stabilized")
    for e in d.events:
        assert e.kind in routh.EVENT_KINDS
        assert e.gamma.shape == (3,)
    for b in d.branches:
        n = len(b.verdicts)
        assert b.s.shape == (n,) and b.s.dtype == np.float64
        assert b.gamma.shape == (n, 3) and b.gamma.dtype == np.float64
        assert set(b.verdicts) <= set(routh.VERDICTS)
        np.testing.assert_allclose(np.linalg.norm(b.gamma, axis=1), 1.0, atol=1e-9)


def test_family_diagram_matches_model_diagram(top):
    d1 = top.bifurcation_diagram((0.0, 5.0))
    d2 = routh.bifurcation_diagram(lambda s: (top, s), (0.0, 5.0))
    assert [e.kind for e in d1.events] == [e.kind for e in d2.events]
    np.testing.assert_allclose([e.s for e in d1.events], [e.s for e in d2.events])


def test_family_over_a_parameter(top):
    # Fixed p = 3, mgl varying: the upright top loses secular stability at
    # mgl = p²(C − A₁)/C² = 1.44 and gyroscopic stability at mgl = p²/(4A₁) = 2.25.
    d = routh.bifurcation_diagram(lambda mgl: (top.with_params(mgl=mgl), 3.0), (0.5, 3.0))
    s = sorted((e.kind, round(e.s, 6)) for e in d.events)
    assert ("branch_point", 1.44) in s
    assert ("hamiltonian_hopf", 2.25) in s


def test_stability_atlas_hopf_curve():
    a1, c = 1.0, 1.2
    base = routh.Model(TOP_TEXT, {"inertia": [a1, a1, c], "mgl": 1.0})
    atlas = routh.stability_atlas(
        lambda mgl, p: (base.with_params(mgl=mgl), p), [0.0, 0.0, 1.0], (0.5, 2.0), (0.5, 5.0),
        nx=11, ny=11,
    )
    assert atlas.x.shape == (11,) and atlas.y.shape == (11,)
    # verdicts[j][i] at (x[i], y[j]) = (mgl, p): at mgl = 0.5, p = 5 the upright top is
    # secularly stable (p² > mgl C²/(C − A₁) = 3.6), at mgl = 2, p = 0.5 unstable.
    assert atlas.verdicts[0][0] == "unstable"
    assert atlas.verdicts[10][0] == "secularly_stable"
    assert atlas.verdicts[0][10] == "unstable"
    assert len(atlas.lost) == 11 and not any(any(r) for r in atlas.lost)
    assert atlas.stop is None
    hopf = [b for b in atlas.boundaries if b.kind == "hamiltonian_hopf"]
    assert hopf and hopf[0].points.shape[1] == 2
    mgl, p = hopf[0].points[:, 0], hopf[0].points[:, 1]
    np.testing.assert_allclose(p * p / (4 * a1 * mgl), 1.0, atol=1e-7)


def test_simulate_lagrange_top_integrals(top):
    w0, g0 = np.array([0.0, 0.3, 5.0]), np.array([0.6, 0.0, 0.8])
    tr = top.simulate(w0, g0, 5.0, rtol=1e-10, atol=1e-12)
    n = len(tr.t)
    assert tr.t.shape == (n,) and tr.omega.shape == (n, 3) and tr.gamma.shape == (n, 3)
    assert tr.t[0] == 0.0 and tr.t[-1] == 5.0
    # Euler: ω₃ constant for A₁ = A₂; energy and |γ| kept (computed here, not by routh).
    np.testing.assert_allclose(tr.omega[:, 2], 5.0, atol=1e-9)
    e = 0.5 * (A1 * (tr.omega[:, 0] ** 2 + tr.omega[:, 1] ** 2) + C * tr.omega[:, 2] ** 2) + MGL * tr.gamma[:, 2]
    np.testing.assert_allclose(e, e[0], atol=1e-8)
    np.testing.assert_allclose(np.linalg.norm(tr.gamma, axis=1), 1.0, atol=1e-9)


def test_reduced_simulation_agrees_with_full(top):
    # ω = Ω + ψ̇γ: the reduced equations reconstruct the full solution.
    g0 = np.array([0.6, 0.0, 0.8])
    big0 = np.array([0.0, 0.3, 0.0])
    red = top.simulate_reduced(big0, g0, 3.0, 2.0)
    assert red.big_omega.shape == (len(red.t), 3) and red.psi.shape == (len(red.t),)
    full = top.simulate(red.omega[0], g0, 2.0)
    np.testing.assert_allclose(full.gamma[-1], red.gamma[-1], atol=1e-7)
    np.testing.assert_allclose(full.omega[-1], red.omega[-1], atol=1e-7)
    np.testing.assert_allclose(red.p_psi, 3.0, atol=1e-8)


def test_toml_load_and_set(top):
    m = routh.Model.from_toml((ROOT / "examples" / "models" / "heavy_top.toml").read_text())
    m2 = routh.Model.load(str(ROOT / "examples" / "models" / "heavy_top.toml"))
    assert m.parameters.keys() == m2.parameters.keys()
    g = np.array([0.0, 0.0, 1.0])
    # heavy_top.toml is the same top as the fixture (A₁ = 1, C = 1.25, mgl = 1).
    assert m.amended_potential(g, 2.0) == pytest.approx(top.amended_potential(g, 2.0), rel=1e-14)
    m.set("g", 2.0)
    assert m.amended_potential(g, 2.0) == pytest.approx(2.0**2 / 2.5 + 2.0, rel=1e-14)
    heavier = top.with_params(mgl=3.0, inertia=np.array([1.0, 1.0, 1.25]))
    assert heavier.amended_potential(g, 2.0) == pytest.approx(1.6 + 3.0, rel=1e-14)
    assert top.amended_potential(g, 2.0) == pytest.approx(1.6 + 1.0, rel=1e-14)  # unchanged


def test_matrix_parameters_numpy_and_nested():
    text = "kinetic = 0.5 * omega.dot(inertia * omega), potential = mgl * gamma.z"
    a = routh.Model(text, {"inertia": np.diag([1.0, 1.0, 1.25]), "mgl": 1.0})
    b = routh.Model(text, {"inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1.25]], "mgl": 1})
    g = [0.0, 0.6, 0.8]
    assert a.amended_potential(g, 2.0) == b.amended_potential(g, 2.0)


def test_certify(gyrostat):
    c = gyrostat.certify(4.0)
    assert isinstance(c.complete, bool)
    found = gyrostat.steady_motions(4.0)
    for m in c.motions:
        assert min(np.linalg.norm(m.gamma - f.gamma) for f in found) < 1e-6


def test_toml_latex_table_and_formulas(gyrostat):
    # The [latex] table of examples/models/gyrostat.toml.
    assert gyrostat.latex_symbols == {
        "inertia": "I", "rotor": "K", "coupling": "B", "com": "r_c", "mass": "m",
    }
    f = gyrostat.formulas
    assert set(f) == {"L", "U_r", "psi_dot"} and all(isinstance(v, str) and v for v in f.values())


def test_certify_options(top):
    # The sleeping top at p = 2.2 has exactly two steady motions, γ = ±e₃ (the tilted circle
    # appears only above the secular bound p = 2.5): complete with the defaults, undecided when
    # the box budget runs out.
    c = top.certify(2.2)
    assert c.complete and len(c.motions) == 2
    assert sorted(round(m.gamma[2]) for m in c.motions) == [-1, 1]
    short = top.certify(2.2, max_boxes=10)
    assert not short.complete and short.boxes == 10 and short.undecided >= 1


def test_nonlinear_stability_docstring_example_is_right(top):
    """The docstring's example: steady_motions(2.2)[0] is the hanging top (secularly
    stable); the sleeping top is the one with γ₃ = 1, gyroscopically stabilised."""
    hanging = top.steady_motions(2.2)[0]
    assert hanging.gamma[2] < -0.99
    assert top.nonlinear_stability(hanging).verdict == "secularly_stable"
    sleeping = max(top.steady_motions(2.2), key=lambda s: s.gamma[2])
    assert sleeping.gamma[2] > 0.99
    assert top.classify(sleeping).verdict == "gyroscopically_stabilized"
    assert top.nonlinear_stability(sleeping).verdict == "lyapunov_stable"
    assert "key=lambda s: s.gamma[2]" in routh.Model.nonlinear_stability.__doc__
