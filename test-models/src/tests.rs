//! Independent checks of the num-dual derivatives (central finite differences of the plain `f64`
//! functions) and of the hand-written `R` against the hand-written `L` ((14), (18), (19), (38),
//! Theorem 2, errata E4, E6).

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_core::{Lagrangian, Routhian};

use crate::identities::reduction_identities;
use crate::*;

type V6 = SVector<f64, 6>;

fn stack(a: &Vector3<f64>, b: &Vector3<f64>) -> V6 {
    V6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

fn top(v: &V6) -> Vector3<f64> {
    Vector3::new(v[0], v[1], v[2])
}

fn bottom(v: &V6) -> Vector3<f64> {
    Vector3::new(v[3], v[4], v[5])
}

/// Central-difference gradient, step `h`.
fn fd_gradient(f: &dyn Fn(&V6) -> f64, x: &V6, h: f64) -> V6 {
    V6::from_fn(|i, _| {
        let mut xp = *x;
        let mut xm = *x;
        xp[i] += h;
        xm[i] -= h;
        (f(&xp) - f(&xm)) / (2.0 * h)
    })
}

/// Central-difference Hessian (four-point formula), step `h`.
fn fd_hessian(f: &dyn Fn(&V6) -> f64, x: &V6, h: f64) -> SMatrix<f64, 6, 6> {
    SMatrix::<f64, 6, 6>::from_fn(|i, j| {
        let at = |si: f64, sj: f64| {
            let mut y = *x;
            y[i] += si * h;
            y[j] += sj * h;
            f(&y)
        };
        (at(1.0, 1.0) - at(1.0, -1.0) - at(-1.0, 1.0) + at(-1.0, -1.0)) / (4.0 * h * h)
    })
}

fn assert_close(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        crate::compare::close_to(got, want, tol, 1.0 + want.abs()),
        "{what}: got {got:e}, want {want:e}, diff {:e}",
        (got - want).abs()
    );
}

fn assert_vec_close<const R: usize, const C: usize>(
    what: &str,
    got: &SMatrix<f64, R, C>,
    want: &SMatrix<f64, R, C>,
    tol: f64,
) {
    let scale = 1.0 + want.amax();
    assert!(
        (got - want).amax() <= tol * scale,
        "{what}: max diff {:e} (scale {scale:e})\ngot {got}\nwant {want}",
        (got - want).amax()
    );
}

/// A random point: Ω in [−2, 2]³, γ of norm in [0.8, 1.2] (R is defined off the sphere too),
/// p_ψ in [−3, 3].
fn random_point(rng: &mut ChaCha8Rng) -> (Vector3<f64>, Vector3<f64>, f64) {
    let omega = random_vector(rng, 2.0);
    let gamma = random_unit_vector(rng) * rng.gen_range(0.8..1.2);
    let p = rng.gen_range(-3.0..3.0);
    (omega, gamma, p)
}

fn check_model<M: Routhian + GenericModel>(model: &M, rng: &mut ChaCha8Rng) {
    let (w, g, p) = random_point(rng);
    let x = stack(&w, &g);

    // L: gradient and Hessian vs finite differences.
    let lf = |v: &V6| model.lagrangian(&top(v), &bottom(v));
    let grad_fd = fd_gradient(&lf, &x, 1e-6);
    assert_vec_close("dL/dω", &model.dl_domega(&w, &g), &top(&grad_fd), 1e-7);
    assert_vec_close("dL/dγ", &model.dl_dgamma(&w, &g), &bottom(&grad_fd), 1e-7);
    let hess_fd = fd_hessian(&lf, &x, 1e-4);
    let j_fd: Matrix3<f64> = hess_fd.fixed_view::<3, 3>(0, 0).into_owned();
    let m_fd: Matrix3<f64> = hess_fd.fixed_view::<3, 3>(0, 3).into_owned();
    assert_vec_close("J", &model.d2l_domega2(&g), &j_fd, 1e-5);
    assert_vec_close("d2L/dωdγ", &model.d2l_domega_dgamma(&w, &g), &m_fd, 1e-5);

    // R: gradient, Hessian and ∂R/∂p vs finite differences.
    let rf = |v: &V6| model.routhian(&top(v), &bottom(v), p);
    let grad_fd = fd_gradient(&rf, &x, 1e-6);
    let b = model.bundle(&w, &g, p);
    assert_vec_close("dR/dΩ", &b.dr_domega, &top(&grad_fd), 1e-7);
    assert_vec_close("dR/dγ", &b.dr_dgamma, &bottom(&grad_fd), 1e-7);
    let hess_fd = fd_hessian(&rf, &x, 1e-4);
    let blk = |r, c| -> Matrix3<f64> { hess_fd.fixed_view::<3, 3>(r, c).into_owned() };
    assert_vec_close("d2R/dΩ2", &b.d2r_domega2, &blk(0, 0), 1e-5);
    assert_vec_close("d2R/dΩdγ", &b.d2r_domega_dgamma, &blk(0, 3), 1e-5);
    assert_vec_close("d2R/dγ2", &b.d2r_dgamma2, &blk(3, 3), 1e-5);
    let h = 1e-6;
    let dp_fd = (model.routhian(&w, &g, p + h) - model.routhian(&w, &g, p - h)) / (2.0 * h);
    assert_close("dR/dp", b.dr_dp, dp_fd, 1e-7);

    // The bundle agrees with the individual methods.
    assert_close("bundle R", b.routhian, model.routhian(&w, &g, p), 1e-14);
    assert_vec_close(
        "bundle dR/dΩ",
        &b.dr_domega,
        &model.dr_domega(&w, &g, p),
        1e-14,
    );
    assert_vec_close(
        "bundle dR/dγ",
        &b.dr_dgamma,
        &model.dr_dgamma(&w, &g, p),
        1e-14,
    );
    assert_vec_close(
        "bundle H",
        &b.d2r_dgamma2,
        &model.d2r_dgamma2(&w, &g, p),
        1e-14,
    );
    assert_eq!(b.psi_dot, model.psi_dot(&w, &g, p));
    assert_eq!(b.dr_dp, model.dr_dp(&w, &g, p));

    // (15): ∂R/∂p = −ψ̇ (num-dual vs closed form (38)).
    assert_close("(15)", b.dr_dp, -b.psi_dot, 1e-12);

    // (12), Theorem 2 (16)–(17), errata E4, E6.
    for identity in reduction_identities(model, &w, &g, p) {
        identity.assert_within(1e-12);
    }
    let omega = w + g * b.psi_dot;
    // (14): R = L(Ω + ψ̇γ, γ) − ψ̇ p.
    assert_close(
        "(14)",
        b.routhian,
        model.lagrangian(&omega, &g) - b.psi_dot * p,
        1e-12,
    );
    // (18): ∂R/∂Ω = ∂L/∂ω; (19): ∂R/∂γ = ∂L/∂γ + ψ̇ ∂R/∂Ω.
    assert_vec_close("(18)", &b.dr_domega, &model.dl_domega(&omega, &g), 1e-12);
    let rhs19 = model.dl_dgamma(&omega, &g) + b.dr_domega * b.psi_dot;
    assert_vec_close("(19)", &b.dr_dgamma, &rhs19, 1e-12);

    // The trait's default ψ̇ (from J(γ) and ∂L/∂ω) agrees with the closed form.
    let q = model.dl_domega(&w, &g).dot(&g);
    let default_psi_dot = (p - q) / g.dot(&(model.d2l_domega2(&g) * g));
    assert_close("(38) default", default_psi_dot, b.psi_dot, 1e-12);

    // The gyroscopic system is formed (smoke) and A annihilates γ.
    let sys = model.gyroscopic_system(&g, p);
    assert_vec_close("A γ", &(sys.a * g), &Vector3::zeros(), 1e-12);
}

#[test]
fn gyrostat_derivatives() {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    for _ in 0..20 {
        let model = Gyrostat::random(&mut rng);
        check_model(&model, &mut rng);
    }
}

#[test]
fn ellipsoid_derivatives() {
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    for _ in 0..20 {
        let model = Ellipsoid::random(&mut rng);
        check_model(&model, &mut rng);
    }
}

#[test]
fn gyrostat_closed_forms() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let model = Gyrostat::random(&mut rng);
    let (w, g, _) = random_point(&mut rng);
    // ∂L/∂ω = Iω + K + Bγ, J = I, ∂²L/∂ω∂γ = B, ∂L/∂γ = Bᵀω − m g r.
    let dl = model.inertia * w + model.rotor + model.coupling * g;
    assert_vec_close("dL/dω", &model.dl_domega(&w, &g), &dl, 1e-13);
    assert_vec_close("J", &model.d2l_domega2(&g), &model.inertia, 1e-13);
    assert_vec_close(
        "B",
        &model.d2l_domega_dgamma(&w, &g),
        &model.coupling,
        1e-13,
    );
    let dg = model.coupling.transpose() * w - model.com * (model.mass * model.g);
    assert_vec_close("dL/dγ", &model.dl_dgamma(&w, &g), &dg, 1e-13);
    // Lagrange top: amended potential (40) at γ = e₃: p²/(2C) + m g l.
    let lt = Gyrostat::lagrange_top(2.0, 1.0, 3.0);
    assert_close(
        "(40)",
        lt.amended_potential(&Vector3::z(), 4.0),
        16.0 / 2.0 + 3.0,
        1e-14,
    );
}

#[test]
fn ellipsoid_closed_forms() {
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let model = Ellipsoid::random(&mut rng);
    let (_, g, _) = random_point(&mut rng);
    // J(γ) = I + m u uᵀ with u = n × γ; γᵀJγ = γᵀIγ (E6).
    let n = model.height_gradient(&g);
    let u = n.cross(&g);
    let j = model.inertia + u * u.transpose() * model.mass;
    assert_vec_close("J", &model.d2l_domega2(&g), &j, 1e-12);
    assert_close("E6", g.dot(&(j * g)), g.dot(&(model.inertia * g)), 1e-12);
    // The support function: a sphere of radius ρ with its centre at the centre of mass has
    // C₃ = ρ|γ| and n = ργ/|γ|.
    let sphere = Ellipsoid::homogeneous(Vector3::repeat(0.7), 1.0, 9.81);
    assert_close("C3 sphere", sphere.height(&Vector3::z()), 0.7, 1e-15);
    assert_vec_close(
        "n sphere",
        &sphere.height_gradient(&g),
        &(g * (0.7 / g.norm())),
        1e-15,
    );
    // Resting on the flattest side is the minimum of C₃ (E2): a₃ the smallest semi-axis.
    let flat = Ellipsoid::homogeneous(Vector3::new(1.0, 0.8, 0.3), 1.0, 9.81);
    assert_close("C3 flat", flat.height(&Vector3::z()), 0.3, 1e-15);
    assert_close("C3 side", flat.height(&Vector3::x()), 1.0, 1e-15);
    // The cross-product matrix convention used by the core crate.
    assert_vec_close("[x]×", &(g.cross_matrix() * n), &g.cross(&n), 1e-15);
}

#[test]
fn random_helpers() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for _ in 0..50 {
        let u = random_unit_vector(&mut rng);
        assert!((u.norm() - 1.0).abs() < 1e-15);
        let t = random_tangent(&mut rng, &u);
        assert!(t.dot(&u).abs() < 1e-15 && (t.norm() - 1.0).abs() < 1e-15);
        let s = random_spd(&mut rng);
        assert_eq!(s, s.transpose());
        let eig = s.symmetric_eigenvalues();
        assert!(eig.min() > 1.0 - 1e-12 && eig.max() < 3.0 + 1e-12, "{eig}");
    }
}
