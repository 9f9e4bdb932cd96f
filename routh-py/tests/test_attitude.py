"""Attitudes of simulations (quaternions in scipy's (x, y, z, w) order), their Euler angles and
the apex locus, against the kinematics and the classical heavy top, computed here."""

import numpy as np
import pytest

A1, C, MGL = 1.0, 1.25, 1.0


def rotation_matrices(q):
    """R of unit quaternions (x, y, z, w), scalar last (the formula scipy uses), (n, 3, 3)."""
    x, y, z, w = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
        np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
        np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1),
    ], -2)


def rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


@pytest.fixture
def run(top):
    times = np.linspace(0.0, 6.0, 3001)
    return top.simulate([0.0, 0.3, 5.0], [0.6, 0.0, 0.8], 6.0, attitude=True, times=times)


def test_attitude_shape_order_and_gamma(run):
    n = len(run.t)
    assert run.attitude.shape == (n, 4) and run.attitude.dtype == np.float64
    np.testing.assert_allclose(np.linalg.norm(run.attitude, axis=1), 1.0, atol=1e-12)
    r = rotation_matrices(run.attitude)
    # γ = Rᵀe₃ is the third row of R: this fixes the component order (x, y, z, w).
    np.testing.assert_allclose(r[:, 2, :], run.gamma / np.linalg.norm(run.gamma, axis=1)[:, None],
                               atol=1e-10)
    # Ṙ = R[ω]×: (Rᵀ Ṙ) is the skew matrix of ω (central differences on the dense output).
    dt = run.t[1] - run.t[0]
    k = np.arange(1, n - 1, 50)
    rdot = (r[k + 1] - r[k - 1]) / (2 * dt)
    skew = np.einsum("kji,kjl->kil", r[k], rdot)
    w = np.stack([skew[:, 2, 1], skew[:, 0, 2], skew[:, 1, 0]], -1)
    np.testing.assert_allclose(w, run.omega[k], atol=2e-4)


def test_attitude_matches_scipy_if_installed(run):
    rot = pytest.importorskip("scipy.spatial.transform").Rotation
    np.testing.assert_allclose(rot.from_quat(run.attitude).as_matrix(),
                               rotation_matrices(run.attitude), atol=1e-12)


def test_euler_angles_rebuild_the_attitude_and_the_heavy_top(run):
    e = run.euler_angles()
    assert e.shape == (len(run.t), 3) and e.dtype == np.float64
    psi, theta, phi = e.T
    r = rotation_matrices(run.attitude)
    for k in range(0, len(run.t), 300):
        np.testing.assert_allclose(rz(psi[k]) @ rx(theta[k]) @ rz(phi[k]), r[k], atol=1e-10)
    np.testing.assert_allclose(np.cos(theta), run.gamma[:, 2], atol=1e-10)
    # The Lagrange top (Goldstein §5.7): p_ψ (vertical momentum) and p₃ = Cω₃ are conserved,
    # ψ̇ = (p_ψ − p₃ cos θ)/(A₁ sin²θ) and φ̇ = ω₃ − ψ̇ cos θ.
    p3 = C * run.omega[:, 2]
    psi_dot = (run.p_psi - p3 * np.cos(theta)) / (A1 * np.sin(theta) ** 2)
    psi_fd = np.gradient(psi, run.t, edge_order=2)
    np.testing.assert_allclose(psi_fd[5:-5], psi_dot[5:-5], atol=1e-4)
    phi_fd = np.gradient(phi, run.t, edge_order=2)
    np.testing.assert_allclose(phi_fd[5:-5], (run.omega[:, 2] - psi_dot * np.cos(theta))[5:-5],
                               atol=1e-4)


def test_reduced_attitude_agrees_with_full(top):
    g0 = np.array([0.6, 0.0, 0.8])
    red = top.simulate_reduced([0.0, 0.3, 0.0], g0, 3.0, 4.0, attitude=True)
    full = top.simulate(red.omega[0], g0, 4.0, attitude=True)
    assert red.attitude.shape == (len(red.t), 4)
    np.testing.assert_allclose(rotation_matrices(red.attitude[[0, -1]]),
                               rotation_matrices(full.attitude[[0, -1]]), atol=1e-7)
    assert red.euler_angles().shape == (len(red.t), 3)


def test_no_attitude_unless_asked(top):
    import routh

    tr = top.simulate([0.0, 0.3, 5.0], [0.6, 0.0, 0.8], 1.0)
    assert tr.attitude is None
    with pytest.raises(routh.RouthError, match="attitude=True"):
        tr.euler_angles()
    with pytest.raises(routh.RouthError, match="attitude=True"):
        tr.plot_apex()
    assert tr._repr_svg_() is None


def test_times_keyword_records_exactly_there(top):
    times = np.linspace(0.0, 2.0, 11)
    tr = top.simulate([0.0, 0.3, 5.0], [0.6, 0.0, 0.8], 2.0, times=times)
    np.testing.assert_array_equal(tr.t, times)


def test_plot_apex_draws_the_apex(top):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from routh._plot import apex_path

    # A slow top started near the horizontal falls below it: both hemispheres are drawn.
    g0 = np.array([np.sin(1.4), 0.0, np.cos(1.4)])
    tr = top.simulate([0.0, 0.0, 1.0], g0, 3.0, attitude=True, times=np.linspace(0, 3, 601))
    apex = apex_path(tr.attitude)
    # The apex R e₃ has height e₃·R e₃ = γ₃.
    np.testing.assert_allclose(apex[:, 2], tr.gamma[:, 2], atol=1e-10)
    assert apex[:, 2].min() < 0 < apex[:, 2].max()
    ax = tr.plot_apex()
    styles = [l.get_linestyle() for l in ax.get_lines()]
    assert "-" in styles and ":" in styles and "--" in styles  # upper, lower, horizon
    drawn = np.concatenate([l.get_xydata() for l in ax.get_lines()
                            if l.get_linestyle() in ("-", ":")])
    np.testing.assert_allclose(np.sort(drawn[:, 0]), np.sort(apex[:, 0]))
    assert "<svg" in tr._repr_svg_()
    # Another body axis: e₁ of the body, seen in space.
    ax2 = tr.plot_apex(axis=(1.0, 0.0, 0.0))
    assert ax2 is not None
