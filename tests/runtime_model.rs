//! `routh::Model` against `#[derive(Lagrangian)]`: for every derived model of
//! `test-models/derived`, a `Model` from the same text and parameter values gives the same
//! values as the generated code — every output of every method (`full_jacobian` too), at random points with Ω ≠ 0
//! and |γ| ≠ 1, to 1e−14 relative — the same steady motions and the same verdicts; and one
//! check against the hand-written num-dual twin. The model evaluates its tapes compiled by the
//! JIT (the default); its interpreted copy agrees with the derive to the same 1e−14, and with
//! the JIT exactly (the two do the same IEEE operations: every output equal).

use crate::common;

use common::close;
use derived_models::ellipsoid::DiagonalEllipsoid;
use derived_models::{AsymmetricTop, Ellipsoid, FluidBody, Gyrostat, LagrangeTop};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::Evaluation;
use routh::{classify, steady_motions, Matrix3, Model, Param, Routhian, Vector3};

const GYROSTAT: &str = "kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),";
const ELLIPSOID: &str = "let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,";
const DIAGONAL_ELLIPSOID: &str = "let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,";
const LAGRANGE_TOP: &str =
    "kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mass * g * l * gamma.z,";
const ASYMMETRIC_TOP: &str = "kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = mass * g * com.dot(gamma),";
const FLUID_BODY: &str = "kinetic = 0.5 * omega.dot(a_kin * omega),
    linear = (lin * gamma).dot(omega),
    potential = 0.5 * gamma.dot(pot * gamma),";

fn s(x: f64) -> Vec<f64> {
    vec![x]
}
fn v(x: Vector3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}
fn m(x: Matrix3<f64>) -> Vec<f64> {
    x.iter().copied().collect()
}

/// Every output of every method of `a` (generated) and `b` (runtime) at random points; the
/// worst normwise relative difference.
fn compare<A: Routhian, B: Routhian>(
    a: &A,
    b: &B,
    rng: &mut ChaCha8Rng,
    tol: f64,
    derived: bool,
) -> f64 {
    let mut worst = 0.0f64;
    let mut check = |what: &str, x: Vec<f64>, y: Vec<f64>| {
        // Relative to the largest entry of the output, and at least to 1: the parameters and
        // points are O(1), so the terms of every output are, and an output that is a sum with
        // cancellation (R = T − U − ψ̇p_ψ …) is compared relative to the size of its terms. The
        // two evaluate the same DAG; they differ in how the derive writes a few operations
        // (a division for a reciprocal used once, products for small powers).
        match close(&y, &x, tol, 1.0) {
            Ok(e) => worst = worst.max(e),
            Err(msg) => panic!("{what}: {msg}"),
        }
    };
    if derived {
        assert_eq!(a.constant_inertia(), b.constant_inertia());
    }
    let (ta, tb) = (a.certification_tape(), b.certification_tape());
    let (ra, rb) = (a.routh_tape(), b.routh_tape());
    for _ in 0..40 {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p: f64 = rng.gen_range(-3.0..3.0);
        check("L", s(a.lagrangian(&w, &g)), s(b.lagrangian(&w, &g)));
        check("dL/dω", v(a.dl_domega(&w, &g)), v(b.dl_domega(&w, &g)));
        check("dL/dγ", v(a.dl_dgamma(&w, &g)), v(b.dl_dgamma(&w, &g)));
        check("J", m(a.d2l_domega2(&g)), m(b.d2l_domega2(&g)));
        check(
            "d2L/dωdγ",
            m(a.d2l_domega_dgamma(&w, &g)),
            m(b.d2l_domega_dgamma(&w, &g)),
        );
        check("E", s(a.energy(&w, &g)), s(b.energy(&w, &g)));
        check(
            "p",
            s(a.cyclic_momentum(&w, &g)),
            s(b.cyclic_momentum(&w, &g)),
        );
        let (fa, fb) = (a.full_equations(&w, &g), b.full_equations(&w, &g));
        check("full J", m(fa.inertia), m(fb.inertia));
        check("full rhs", v(fa.right_side), v(fb.right_side));
        if derived {
            assert_eq!(fa.rank_one.is_some(), fb.rank_one.is_some());
        }
        if let (Some(x), Some(y)) = (fa.rank_one, fb.rank_one) {
            check("full c", s(x.weight), s(y.weight));
            check("full v", v(x.vector), v(y.vector));
        }
        let (ja, jb) = (a.full_jacobian(&w, &g), b.full_jacobian(&w, &g));
        check("jacobian J", m(ja.inertia), m(jb.inertia));
        check("jacobian f", v(ja.right_side), v(jb.right_side));
        // The derivatives: the derive's and the runtime's are exact (the same DAG); the
        // num-dual twin's are the trait's central differences (tests/generated_vs_numdual.rs
        // checks both against a Richardson extrapolation).
        if derived {
            check("∂f/∂ω", m(ja.dright_domega), m(jb.dright_domega));
            check("∂f/∂γ", m(ja.dright_dgamma), m(jb.dright_dgamma));
            for k in 0..3 {
                check(
                    "∂J/∂γ_k",
                    m(ja.dinertia_dgamma[k]),
                    m(jb.dinertia_dgamma[k]),
                );
            }
        }
        check("ψ̇", s(a.psi_dot(&w, &g, p)), s(b.psi_dot(&w, &g, p)));
        check("R", s(a.routhian(&w, &g, p)), s(b.routhian(&w, &g, p)));
        check(
            "dR/dΩ",
            v(a.dr_domega(&w, &g, p)),
            v(b.dr_domega(&w, &g, p)),
        );
        check(
            "dR/dγ",
            v(a.dr_dgamma(&w, &g, p)),
            v(b.dr_dgamma(&w, &g, p)),
        );
        check("dR/dp", s(a.dr_dp(&w, &g, p)), s(b.dr_dp(&w, &g, p)));
        check(
            "d2R/dΩ2",
            m(a.d2r_domega2(&w, &g, p)),
            m(b.d2r_domega2(&w, &g, p)),
        );
        check(
            "d2R/dΩdγ",
            m(a.d2r_domega_dgamma(&w, &g, p)),
            m(b.d2r_domega_dgamma(&w, &g, p)),
        );
        check(
            "d2R/dγ2",
            m(a.d2r_dgamma2(&w, &g, p)),
            m(b.d2r_dgamma2(&w, &g, p)),
        );
        let (ba, bb) = (a.bundle(&w, &g, p), b.bundle(&w, &g, p));
        check("bundle R", s(ba.routhian), s(bb.routhian));
        check("bundle ψ̇", s(ba.psi_dot), s(bb.psi_dot));
        check("bundle dR/dΩ", v(ba.dr_domega), v(bb.dr_domega));
        check("bundle dR/dγ", v(ba.dr_dgamma), v(bb.dr_dgamma));
        check("bundle dR/dp", s(ba.dr_dp), s(bb.dr_dp));
        check("bundle d2R/dΩ2", m(ba.d2r_domega2), m(bb.d2r_domega2));
        check(
            "bundle d2R/dΩdγ",
            m(ba.d2r_domega_dgamma),
            m(bb.d2r_domega_dgamma),
        );
        check("bundle d2R/dγ2", m(ba.d2r_dgamma2), m(bb.d2r_dgamma2));
        check(
            "U_r",
            s(a.amended_potential(&g, p)),
            s(b.amended_potential(&g, p)),
        );
        let (ga, gb) = (a.gyroscopic_system(&g, p), b.gyroscopic_system(&g, p));
        check("A", m(ga.a), m(gb.a));
        check("G", m(ga.g), m(gb.g));
        check("C", m(ga.c), m(gb.c));
        // bundle_and_system: the trait's default (bundle, then from_bundle) on one side, the
        // derive's fused body on the other.
        let ((fa, sa), (fb, sb)) = (
            a.bundle_and_system(&w, &g, p),
            b.bundle_and_system(&w, &g, p),
        );
        check("fused bundle dR/dγ", v(fa.dr_dgamma), v(fb.dr_dgamma));
        check("fused bundle d2R/dγ2", m(fa.d2r_dgamma2), m(fb.d2r_dgamma2));
        check("fused A", m(sa.a), m(sb.a));
        check("fused G", m(sa.g), m(sb.g));
        check("fused C", m(sa.c), m(sb.c));
        let (ea, eb) = (
            a.reduced_equations(&w, &g, p),
            b.reduced_equations(&w, &g, p),
        );
        check("reduced J", m(ea.inertia), m(eb.inertia));
        check("reduced rhs", v(ea.right_side), v(eb.right_side));
        check("reduced ψ̇", s(ea.psi_dot), s(eb.psi_dot));
        if let (Some(x), Some(y)) = (ea.rank_one, eb.rank_one) {
            check("reduced c", s(x.weight), s(y.weight));
            check("reduced v", v(x.vector), v(y.vector));
        }
        let garr = [g.x, g.y, g.z];
        if let (Some(x), Some(y)) = (&ta, &tb) {
            let ((gx, hx), (gy, hy)) = (
                x.eval(garr, p, &mut Vec::new()),
                y.eval(garr, p, &mut Vec::new()),
            );
            check("tape grad", gx.to_vec(), gy.to_vec());
            check("tape hess", hx.concat(), hy.concat());
        }
        if let (Some(x), Some(y)) = (&ra, &rb) {
            let warr = [w.x, w.y, w.z];
            check(
                "R tape",
                s(x.routhian(&warr, &garr, p)),
                s(y.routhian(&warr, &garr, p)),
            );
        }
    }
    if derived {
        assert!(ta.is_some() && tb.is_some() && ra.is_some() && rb.is_some());
    }
    worst
}

/// The same steady motions (γ to 1e-8) with the same verdicts.
fn same_steady_motions<A: Routhian, B: Routhian>(a: &A, b: &B, momenta: &[f64]) {
    for &p in momenta {
        let (sa, sb) = (steady_motions(a, p).unwrap(), steady_motions(b, p).unwrap());
        assert_eq!(sa.len(), sb.len(), "p = {p}");
        for x in &sa {
            let y = sb
                .iter()
                .find(|y| (y.gamma - x.gamma).norm() < 1e-8)
                .unwrap_or_else(|| panic!("p = {p}: {:?} not found by the runtime model", x.gamma));
            let (va, vb) = (
                classify(a, x).unwrap().verdict,
                classify(b, y).unwrap().verdict,
            );
            assert_eq!(va, vb, "p = {p}, γ = {:?}", x.gamma);
        }
    }
}

/// The derive `d` against the runtime model `r` compiled by the JIT and against its
/// interpreted copy (each to `tol`), and the JIT against the interpreter exactly; the worst
/// difference from the derive.
fn derive_jit_interpreter<D: Routhian>(d: &D, r: &Model, rng: &mut ChaCha8Rng, tol: f64) -> f64 {
    if routh_runtime::kernel::jit_supported() {
        assert_eq!(r.evaluation(), Evaluation::Jit);
    }
    let interpreted = r.interpreted().unwrap();
    assert_eq!(interpreted.evaluation(), Evaluation::Interpreter);
    let worst = compare(d, r, rng, tol, true);
    let worst_interpreted = compare(d, &interpreted, rng, tol, true);
    compare(r, &interpreted, rng, 0.0, true);
    worst.max(worst_interpreted)
}

fn vec3(x: Vector3<f64>) -> Param {
    Param::Vector(x)
}
fn mat3(x: Matrix3<f64>) -> Param {
    Param::Matrix(x)
}

#[test]
fn every_derived_model_agrees_with_its_runtime_twin() {
    let mut rng = ChaCha8Rng::seed_from_u64(22);
    let tol = 1e-14;
    let mut worst = Vec::new();
    for _ in 0..3 {
        let d = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
        let p = [
            ("inertia", mat3(d.inertia)),
            ("rotor", vec3(d.rotor)),
            ("coupling", mat3(d.coupling)),
            ("com", vec3(d.com)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::with_symmetric(GYROSTAT, &p, &["inertia"]).unwrap();
        worst.push(("gyrostat", derive_jit_interpreter(&d, &r, &mut rng, tol)));

        let d = Ellipsoid::from(&test_models::Ellipsoid::random(&mut rng));
        let p = [
            ("inertia", mat3(d.inertia)),
            ("semi_axes", vec3(d.semi_axes)),
            ("offset", vec3(d.offset)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::new(ELLIPSOID, &p).unwrap();
        worst.push(("ellipsoid", derive_jit_interpreter(&d, &r, &mut rng, tol)));

        let d = DiagonalEllipsoid::random(&mut rng);
        let p = [
            ("inertia", vec3(d.inertia)),
            ("semi_axes", vec3(d.semi_axes)),
            ("offset", vec3(d.offset)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::new(DIAGONAL_ELLIPSOID, &p).unwrap();
        worst.push((
            "diagonal ellipsoid",
            derive_jit_interpreter(&d, &r, &mut rng, tol),
        ));

        let d = AsymmetricTop {
            inertia: Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0)),
            com: test_models::random_vector(&mut rng, 1.0),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        };
        let p = [
            ("inertia", vec3(d.inertia)),
            ("com", vec3(d.com)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::new(ASYMMETRIC_TOP, &p).unwrap();
        worst.push((
            "asymmetric top",
            derive_jit_interpreter(&d, &r, &mut rng, tol),
        ));

        let pot = test_models::random_matrix(&mut rng, 1.0);
        let d = FluidBody {
            a_kin: test_models::random_spd(&mut rng),
            lin: test_models::random_matrix(&mut rng, 1.0),
            pot: pot + pot.transpose(),
        };
        let p = [
            ("a_kin", mat3(d.a_kin)),
            ("lin", mat3(d.lin)),
            ("pot", mat3(d.pot)),
        ];
        let r = Model::new(FLUID_BODY, &p).unwrap();
        worst.push(("fluid body", derive_jit_interpreter(&d, &r, &mut rng, tol)));
    }
    let d = LagrangeTop::example();
    let p = [
        ("a1", d.a1.into()),
        ("c", d.c.into()),
        ("mass", d.mass.into()),
        ("g", d.g.into()),
        ("l", d.l.into()),
    ];
    let r = Model::new(LAGRANGE_TOP, &p).unwrap();
    worst.push((
        "Lagrange top",
        derive_jit_interpreter(&d, &r, &mut rng, tol),
    ));
    println!("worst relative differences: {worst:?}");
}

#[test]
fn same_steady_motions_and_verdicts() {
    let d = LagrangeTop::example();
    let p = [
        ("a1", d.a1.into()),
        ("c", d.c.into()),
        ("mass", d.mass.into()),
        ("g", d.g.into()),
        ("l", d.l.into()),
    ];
    let r = Model::new(LAGRANGE_TOP, &p).unwrap();
    same_steady_motions(&d, &r, &[1.0, 2.2, 3.0]);

    for d in [Gyrostat::kelvin(), Gyrostat::coupled()] {
        let p = [
            ("inertia", mat3(d.inertia)),
            ("rotor", vec3(d.rotor)),
            ("coupling", mat3(d.coupling)),
            ("com", vec3(d.com)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::with_symmetric(GYROSTAT, &p, &["inertia"]).unwrap();
        same_steady_motions(&d, &r, &[0.5, 3.5, 6.0]);
    }
    for d in [Ellipsoid::spheroid(), Ellipsoid::triaxial()] {
        let p = [
            ("inertia", mat3(d.inertia)),
            ("semi_axes", vec3(d.semi_axes)),
            ("offset", vec3(d.offset)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ];
        let r = Model::new(ELLIPSOID, &p).unwrap();
        same_steady_motions(&d, &r, &[1.0, 5.0]);
    }
}

#[test]
fn runtime_gyrostat_agrees_with_the_num_dual_twin() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for _ in 0..5 {
        let twin = test_models::Gyrostat::random(&mut rng);
        let p = [
            ("inertia", mat3(twin.inertia)),
            ("rotor", vec3(twin.rotor)),
            ("coupling", mat3(twin.coupling)),
            ("com", vec3(twin.com)),
            ("mass", twin.mass.into()),
            ("g", twin.g.into()),
        ];
        let r = Model::with_symmetric(GYROSTAT, &p, &["inertia"]).unwrap();
        // The twin differentiates by num-dual: agreement to its rounding, 1e-12.
        compare(&twin, &r, &mut rng, 1e-11, false);
    }
}

#[test]
fn runtime_models_can_be_certified() {
    // The asymmetric top of the facade's documentation: exactly two steady motions at p = 0.5.
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z";
    let p = [
        ("inertia", vec3(Vector3::new(1.0, 2.0, 3.0))),
        ("mgl", 1.0.into()),
    ];
    let r = Model::new(text, &p).unwrap();
    let opts = routh::CertifyOptions::default();
    let cert = routh::steady_motions_certified(&r, 0.5, &opts).unwrap();
    assert!(cert.complete);
    assert_eq!(cert.motions.len(), 2);
}

/// Parameters changed by `with` and `set` (values only: the tapes are compiled once and read
/// the values at run time): the runtime model built for one gyrostat and one ellipsoid, then
/// given every parameter of another, agrees with the derive of the other to 1e−14, its JIT with
/// its interpreter exactly; the copies share the compiled code (no tape is made again).
#[test]
fn parameters_changed_by_with_agree_with_the_derive() {
    let mut rng = ChaCha8Rng::seed_from_u64(2211);
    let tol = 1e-14;
    for _ in 0..2 {
        let first = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
        let d = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
        let params = |d: &Gyrostat| {
            [
                ("inertia", mat3(d.inertia)),
                ("rotor", vec3(d.rotor)),
                ("coupling", mat3(d.coupling)),
                ("com", vec3(d.com)),
                ("mass", d.mass.into()),
                ("g", d.g.into()),
            ]
        };
        let r0 = Model::with_symmetric(GYROSTAT, &params(&first), &["inertia"]).unwrap();
        derive_jit_interpreter(&first, &r0, &mut rng, tol);
        let made = r0.tapes_made();
        let mut r = r0.clone();
        for (name, value) in params(&d) {
            r = r.with(name, value).unwrap();
        }
        derive_jit_interpreter(&d, &r, &mut rng, tol);
        assert_eq!(
            r0.tapes_made(),
            made,
            "`with` copies share the compiled tapes"
        );
        // And back with `set`: the first model again, exactly.
        let mut back = r.clone();
        for (name, value) in params(&first) {
            back.set(name, value).unwrap();
        }
        compare(&r0, &back, &mut rng, 0.0, true);
    }
    let first = Ellipsoid::from(&test_models::Ellipsoid::random(&mut rng));
    let d = Ellipsoid::from(&test_models::Ellipsoid::random(&mut rng));
    let params = |d: &Ellipsoid| {
        [
            ("inertia", mat3(d.inertia)),
            ("semi_axes", vec3(d.semi_axes)),
            ("offset", vec3(d.offset)),
            ("mass", d.mass.into()),
            ("g", d.g.into()),
        ]
    };
    let mut r = Model::new(ELLIPSOID, &params(&first)).unwrap();
    for (name, value) in params(&d) {
        r.set(name, value).unwrap();
    }
    derive_jit_interpreter(&d, &r, &mut rng, tol);
}

/// A custom backend receives the tapes with the values bound: after `set`, the new values.
#[test]
fn a_custom_backend_sees_the_new_values() {
    let d = LagrangeTop::example();
    let p = [
        ("a1", d.a1.into()),
        ("c", d.c.into()),
        ("mass", d.mass.into()),
        ("g", d.g.into()),
        ("l", d.l.into()),
    ];
    let r = Model::new(LAGRANGE_TOP, &p).unwrap();
    let mut custom = r.with_backend(routh_runtime::kernel::interpret).unwrap();
    assert_eq!(custom.evaluation(), Evaluation::Custom);
    let g = Vector3::new(0.6, 0.0, 0.8);
    // U_r at rest ... = mass g l γ₃ + p²/(2(a1 γ⊥² + c γ₃²)) (the Lagrange top's (40)).
    let u = |m: &Model| m.amended_potential(&g, 1.5);
    let closed = |mgl: f64| mgl * 0.8 + 1.5f64.powi(2) / (2.0 * (d.a1 * 0.36 + d.c * 0.64));
    assert!((u(&custom) - closed(d.mass * d.g * d.l)).abs() < 1e-13);
    custom.set("l", 2.0 * d.l).unwrap();
    assert!((u(&custom) - closed(2.0 * d.mass * d.g * d.l)).abs() < 1e-13);
    assert_eq!(u(&custom), u(&r.with("l", 2.0 * d.l).unwrap()));
}
