//! The generated `Lagrangian` and `Routhian` impls against num-dual derivatives of the same L and
//! of R written by hand (crate `test-models`), at random points including |γ| ≠ 1
//! (docs/method.md §4).

use crate::common;

use common::{close, m, s, v};
use derived_models::{Ellipsoid, Gyrostat};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{GyroscopicSystem, Lagrangian, Matrix3, Routhian, Vector3};

const POINTS: usize = 150;

fn check_lagrangian<G: Lagrangian, H: Lagrangian>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..POINTS {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        // Scalars that are sums with cancellation (L = (∂L/∂ω, ω) − E, E, p = (∂L/∂ω, γ)) are
        // compared relative to the size of their terms, which bounds the rounding error of any
        // evaluation (the reference's too); vectors and matrices normwise.
        let dl = reference.dl_domega(&w, &g);
        let e_ref = reference.energy(&w, &g);
        let terms_e = dl.norm() * w.norm() + reference.lagrangian(&w, &g).abs();
        let terms_l = dl.norm() * w.norm() + e_ref.abs();
        let terms_p = dl.norm() * g.norm();
        let checks: [(&str, Vec<f64>, Vec<f64>, f64); 7] = [
            (
                "L",
                s(gen.lagrangian(&w, &g)),
                s(reference.lagrangian(&w, &g)),
                terms_l,
            ),
            ("dL/dω", v(gen.dl_domega(&w, &g)), v(dl), 1e-12),
            (
                "dL/dγ",
                v(gen.dl_dgamma(&w, &g)),
                v(reference.dl_dgamma(&w, &g)),
                1e-12,
            ),
            (
                "J",
                m(gen.d2l_domega2(&g)),
                m(reference.d2l_domega2(&g)),
                1e-12,
            ),
            (
                "d2L/dωdγ",
                m(gen.d2l_domega_dgamma(&w, &g)),
                m(reference.d2l_domega_dgamma(&w, &g)),
                1e-12,
            ),
            ("E", s(gen.energy(&w, &g)), s(e_ref), terms_e),
            (
                "p",
                s(gen.cyclic_momentum(&w, &g)),
                s(reference.cyclic_momentum(&w, &g)),
                terms_p,
            ),
        ];
        for (name, a, b, floor) in checks {
            let e = close(&a, &b, tol, floor)
                .unwrap_or_else(|e| panic!("{name} at ω={w:?} γ={g:?}: {e}"));
            worst = worst.max(e);
        }
    }
    worst
}

fn check_routhian<G: Routhian, H: Routhian + test_models::GenericModel>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..POINTS {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p = rng.gen_range(-5.0..5.0);
        let b = gen.bundle(&w, &g, p);
        let nd = test_models::numdual_bundle(reference, &w, &g, p);
        let z = Vector3::zeros();
        let checks: [(&str, Vec<f64>, Vec<f64>); 19] = [
            (
                "psi_dot",
                s(gen.psi_dot(&w, &g, p)),
                s(reference.psi_dot(&w, &g, p)),
            ),
            (
                "R",
                s(gen.routhian(&w, &g, p)),
                s(reference.routhian(&w, &g, p)),
            ),
            (
                "dR/dΩ",
                v(gen.dr_domega(&w, &g, p)),
                v(reference.dr_domega(&w, &g, p)),
            ),
            (
                "dR/dγ",
                v(gen.dr_dgamma(&w, &g, p)),
                v(reference.dr_dgamma(&w, &g, p)),
            ),
            ("dR/dp", s(gen.dr_dp(&w, &g, p)), s(nd.dr_dp)),
            ("d2R/dΩ2", m(gen.d2r_domega2(&w, &g, p)), m(nd.d2r_domega2)),
            (
                "d2R/dΩdγ",
                m(gen.d2r_domega_dgamma(&w, &g, p)),
                m(nd.d2r_domega_dgamma),
            ),
            ("d2R/dγ2", m(gen.d2r_dgamma2(&w, &g, p)), m(nd.d2r_dgamma2)),
            ("bundle.R", s(b.routhian), s(nd.routhian)),
            ("bundle.psi_dot", s(b.psi_dot), s(nd.psi_dot)),
            ("bundle.dR/dΩ", v(b.dr_domega), v(nd.dr_domega)),
            ("bundle.dR/dγ", v(b.dr_dgamma), v(nd.dr_dgamma)),
            ("bundle.dR/dp", s(b.dr_dp), s(nd.dr_dp)),
            ("bundle.d2R/dΩ2", m(b.d2r_domega2), m(nd.d2r_domega2)),
            (
                "bundle.d2R/dΩdγ",
                m(b.d2r_domega_dgamma),
                m(nd.d2r_domega_dgamma),
            ),
            ("bundle.d2R/dγ2", m(b.d2r_dgamma2), m(nd.d2r_dgamma2)),
            (
                "U_r",
                s(gen.amended_potential(&g, p)),
                s(-reference.routhian(&z, &g, p)),
            ),
            (
                "A",
                m(gen.gyroscopic_system(&g, p).a),
                m(reference.gyroscopic_system(&g, p).a),
            ),
            (
                "G",
                m(gen.gyroscopic_system(&g, p).g),
                m(reference.gyroscopic_system(&g, p).g),
            ),
        ];
        for (name, a, b) in checks {
            let e = close(&a, &b, tol, 1e-12)
                .unwrap_or_else(|e| panic!("{name} at Ω={w:?} γ={g:?} p={p}: {e}"));
            worst = worst.max(e);
        }
        let c = (
            m(gen.gyroscopic_system(&g, p).c),
            m(reference.gyroscopic_system(&g, p).c),
        );
        let e = close(&c.0, &c.1, tol, 1e-12).unwrap_or_else(|e| panic!("C at γ={g:?} p={p}: {e}"));
        worst = worst.max(e);
    }
    worst
}

/// The generated `bundle_and_system` (one straight-line body for the bundle and A, G, C of (64))
/// against, at every point: the generated `bundle` followed by `GyroscopicSystem::from_bundle`
/// (to round-off: the same formulas, evaluated through memory instead of registers); the
/// matrix products of errata E6 on the num-dual bundle of the twin, `A = ∂²R/∂Ω²`,
/// `2G = M[γ]× + [γ]×Mᵀ − [∂R/∂Ω]×`, `C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]×` (normwise, `tol`); and at
/// `Ω = 0`, where (64) is the linearisation, the generated `gyroscopic_system` (a separate body
/// specialised at rest).
fn check_fused<G: Routhian, H: Routhian + test_models::GenericModel>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for k in 0..POINTS {
        let g = test_models::random_gamma(rng);
        let p = rng.gen_range(-5.0..5.0);
        // Every other point at rest.
        let w = if k % 2 == 0 {
            Vector3::zeros()
        } else {
            test_models::random_vector(rng, 2.0)
        };
        let (fb, fs) = gen.bundle_and_system(&w, &g, p);
        let b = gen.bundle(&w, &g, p);
        let composed = GyroscopicSystem::from_bundle(&b, &g);
        let nd = test_models::numdual_bundle(reference, &w, &g, p);
        let gx = g.cross_matrix();
        let mx = nd.d2r_domega_dgamma;
        let want_g = 0.5 * (mx * gx + gx * mx.transpose() - nd.dr_domega.cross_matrix());
        let mu = nd.dr_dgamma.dot(&g);
        let want_c = gx.transpose() * (Matrix3::from_diagonal_element(mu) - nd.d2r_dgamma2) * gx;
        let round_off = 1e-14;
        let mut checks: Vec<(&str, Vec<f64>, Vec<f64>, f64)> = vec![
            ("R vs bundle", s(fb.routhian), s(b.routhian), round_off),
            ("psi_dot vs bundle", s(fb.psi_dot), s(b.psi_dot), round_off),
            (
                "dR/dΩ vs bundle",
                v(fb.dr_domega),
                v(b.dr_domega),
                round_off,
            ),
            (
                "dR/dγ vs bundle",
                v(fb.dr_dgamma),
                v(b.dr_dgamma),
                round_off,
            ),
            ("dR/dp vs bundle", s(fb.dr_dp), s(b.dr_dp), round_off),
            (
                "d2R/dΩ2 vs bundle",
                m(fb.d2r_domega2),
                m(b.d2r_domega2),
                round_off,
            ),
            (
                "d2R/dΩdγ vs bundle",
                m(fb.d2r_domega_dgamma),
                m(b.d2r_domega_dgamma),
                round_off,
            ),
            (
                "d2R/dγ2 vs bundle",
                m(fb.d2r_dgamma2),
                m(b.d2r_dgamma2),
                round_off,
            ),
            ("A vs from_bundle", m(fs.a), m(composed.a), round_off),
            ("G vs from_bundle", m(fs.g), m(composed.g), round_off),
            ("C vs from_bundle", m(fs.c), m(composed.c), round_off),
            ("R vs num-dual", s(fb.routhian), s(nd.routhian), tol),
            ("dR/dγ vs num-dual", v(fb.dr_dgamma), v(nd.dr_dgamma), tol),
            (
                "d2R/dΩdγ vs num-dual",
                m(fb.d2r_domega_dgamma),
                m(nd.d2r_domega_dgamma),
                tol,
            ),
            ("A vs num-dual", m(fs.a), m(nd.d2r_domega2), tol),
            ("G vs num-dual (E6)", m(fs.g), m(want_g), tol),
            ("C vs num-dual (E6)", m(fs.c), m(want_c), tol),
        ];
        if k % 2 == 0 {
            let rest = gen.gyroscopic_system(&g, p);
            checks.push(("A vs gyroscopic_system", m(fs.a), m(rest.a), tol));
            checks.push(("G vs gyroscopic_system", m(fs.g), m(rest.g), tol));
            checks.push(("C vs gyroscopic_system", m(fs.c), m(rest.c), tol));
        }
        for (name, a, b, t) in checks {
            let e = close(&a, &b, t, 1e-12)
                .unwrap_or_else(|e| panic!("{name} at Ω={w:?} γ={g:?} p={p}: {e}"));
            worst = worst.max(e);
        }
        // The structure of (64): G skew, C symmetric, both annihilate γ (errata E5).
        assert_eq!(fs.g, -fs.g.transpose());
        assert_eq!(fs.c, fs.c.transpose());
        // Round-off relative to the sizes of the terms: |tr M|·|γ|² for Gγ, and for Cγ
        // ‖μE − ∂²R/∂γ²‖·|γ|³ (C is a sandwich of that matrix and may be much smaller).
        let g_scale = fs.g.amax() * g.norm();
        let c_scale = (mu.abs() + fb.d2r_dgamma2.amax()) * g.norm_squared() * g.norm();
        assert!((fs.g * g).amax() <= 1e-14 * g_scale, "Gγ = {}", fs.g * g);
        assert!((fs.c * g).amax() <= 1e-13 * c_scale, "Cγ = {}", fs.c * g);
    }
    worst
}

/// Runs `check` on four random twins drawn by `twin` (seeded with `seed`), each against its
/// derived model, and reports the worst error.
fn over_random_twins<T, G>(
    seed: u64,
    twin: fn(&mut ChaCha8Rng) -> T,
    check: fn(&G, &T, &mut ChaCha8Rng, f64) -> f64,
    tol: f64,
) where
    G: for<'a> From<&'a T>,
{
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut worst = 0.0f64;
    for _ in 0..4 {
        let reference = twin(&mut rng);
        worst = worst.max(check(&G::from(&reference), &reference, &mut rng, tol));
    }
    eprintln!(
        "worst normwise relative error: {worst:e} over {} points",
        4 * POINTS
    );
}

#[test]
fn gyrostat_lagrangian_matches_numdual() {
    over_random_twins::<_, Gyrostat>(1, test_models::Gyrostat::random, check_lagrangian, 1e-13);
}

#[test]
fn ellipsoid_lagrangian_matches_numdual() {
    over_random_twins::<_, Ellipsoid>(2, test_models::Ellipsoid::random, check_lagrangian, 1e-13);
}

#[test]
fn gyrostat_routhian_matches_numdual() {
    over_random_twins::<_, Gyrostat>(3, test_models::Gyrostat::random, check_routhian, 1e-12);
}

#[test]
fn ellipsoid_routhian_matches_numdual() {
    over_random_twins::<_, Ellipsoid>(4, test_models::Ellipsoid::random, check_routhian, 1e-12);
}

#[test]
fn gyrostat_bundle_and_system_matches_numdual_and_the_composed_path() {
    over_random_twins::<_, Gyrostat>(9, test_models::Gyrostat::random, check_fused, 1e-12);
}

#[test]
fn ellipsoid_bundle_and_system_matches_numdual_and_the_composed_path() {
    over_random_twins::<_, Ellipsoid>(10, test_models::Ellipsoid::random, check_fused, 1e-12);
}

/// The generated one-body vector-field terms, `full_equations` (8) and `reduced_equations` (13),
/// against the trait's defaults on the num-dual twin, which combine its num-dual derivatives
/// term by term (J, ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)γ̇, and the same with R), where the
/// generated bodies are one expression DAG each. The right sides are sums with cancellation,
/// so they are compared relative to the size of their terms.
fn check_equations<G: Routhian, H: Routhian>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..POINTS {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p = rng.gen_range(-3.0..3.0);
        let (got, want) = (gen.full_equations(&w, &g), reference.full_equations(&w, &g));
        let gd = g.cross(&w);
        let terms = reference.dl_domega(&w, &g).norm() * w.norm()
            + reference.dl_dgamma(&w, &g).norm() * g.norm()
            + reference.d2l_domega_dgamma(&w, &g).norm() * gd.norm();
        let (gr, wr) = (
            gen.reduced_equations(&w, &g, p),
            reference.reduced_equations(&w, &g, p),
        );
        let terms_r = reference.dr_domega(&w, &g, p).norm() * w.norm()
            + reference.dr_dgamma(&w, &g, p).norm() * g.norm()
            + reference.d2r_domega_dgamma(&w, &g, p).norm() * gd.norm();
        // A body on a plane also hands out its J as J₀ + c v vᵀ (docs/method.md §2a): the
        // completed matrix against the twin's num-dual J, in both equations.
        let complete = |r: Option<routh::RankOneInertia>| match (gen.constant_inertia(), r) {
            (Some(j0), Some(r)) => m(r.complete(&j0)),
            (None, None) => m(want.inertia),
            (j0, r) => panic!("J₀ {j0:?} without c v vᵀ {r:?}, or the other way"),
        };
        let checks: [(&str, Vec<f64>, Vec<f64>, f64); 7] = [
            ("J", m(got.inertia), m(want.inertia), 1e-12),
            (
                "J₀ + c v vᵀ",
                complete(got.rank_one),
                m(want.inertia),
                1e-12,
            ),
            (
                "J₀ + c v vᵀ in (13)",
                complete(gr.rank_one),
                m(want.inertia),
                1e-12,
            ),
            (
                "(8) right side",
                v(got.right_side),
                v(want.right_side),
                terms,
            ),
            ("J in (13)", m(gr.inertia), m(wr.inertia), 1e-12),
            (
                "(13) right side",
                v(gr.right_side),
                v(wr.right_side),
                terms_r,
            ),
            ("psi_dot", s(gr.psi_dot), s(wr.psi_dot), 1e-12),
        ];
        for (name, a, b, floor) in checks {
            match close(&a, &b, tol, floor) {
                Ok(e) => worst = worst.max(e),
                Err(msg) => panic!("{name} at w = {w:?}, g = {g:?}, p = {p}: {msg}"),
            }
        }
    }
    worst
}

#[test]
fn gyrostat_equations_match_numdual() {
    over_random_twins::<_, Gyrostat>(5, test_models::Gyrostat::random, check_equations, 1e-12);
}

#[test]
fn ellipsoid_equations_match_numdual() {
    over_random_twins::<_, Ellipsoid>(6, test_models::Ellipsoid::random, check_equations, 1e-12);
}

/// The derive finds `J = J₀ + c v vᵀ` in the ellipsoid on a plane, with `J₀ = I` and `c = m`
/// (its kinetic energy is `½ωᵀIω + ½m(n·(γ × ω))²`), and not in the gyrostat, whose J is
/// constant.
#[test]
fn the_rank_one_form_is_found_where_it_is() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let twin = test_models::Ellipsoid::random(&mut rng);
    let e = Ellipsoid::from(&twin);
    assert_eq!(e.constant_inertia(), Some(twin.inertia));
    let (w, g) = (
        test_models::random_vector(&mut rng, 2.0),
        test_models::random_gamma(&mut rng),
    );
    let r = e.full_equations(&w, &g).rank_one.expect("c v vᵀ");
    assert_eq!(r.weight, twin.mass);
    assert_eq!(e.reduced_equations(&w, &g, 0.7).rank_one, Some(r));
    let gyrostat = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
    assert_eq!(gyrostat.constant_inertia(), None);
    assert_eq!(gyrostat.full_equations(&w, &g).rank_one, None);
}

/// `reduced_vector_field` solves (13) in its gauge: with `A = ∂²R/∂Ω²` and the right side `b`
/// of the num-dual twin, `A Ω̇ = b` and `Ω̇·γ = 0` (the field solves with J and projects,
/// docs/method.md §3, never with A), at random states including |γ| ≠ 1. Returns the worst
/// relative residual of (13).
fn check_gauge<G: Routhian, H: Routhian>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..POINTS {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p = rng.gen_range(-3.0..3.0);
        let (x, gd, psi_dot) = routh::sim::reduced_vector_field(gen, &w, &g, p).expect("field");
        let a = reference.d2r_domega2(&w, &g, p);
        let eq = reference.reduced_equations(&w, &g, p);
        let b = eq.right_side;
        let residual = (a * x - b).norm() / (a.norm() * x.norm() + b.norm());
        let along = x.dot(&g).abs() / (x.norm() * g.norm());
        let at = format!("w = {w:?}, g = {g:?}, p = {p}");
        assert!(residual < tol, "A Ω̇ − b: {residual:e} at {at}");
        assert!(along < 1e-14, "Ω̇·γ: {along:e} at {at}");
        assert_eq!(gd, g.cross(&w));
        assert!((psi_dot - eq.psi_dot).abs() <= 1e-12 * eq.psi_dot.abs().max(1.0));
        worst = worst.max(residual);
    }
    worst
}

#[test]
fn gyrostat_reduced_field_solves_13_in_the_gauge() {
    over_random_twins::<_, Gyrostat>(7, test_models::Gyrostat::random, check_gauge, 1e-13);
}

#[test]
fn ellipsoid_reduced_field_solves_13_in_the_gauge() {
    over_random_twins::<_, Ellipsoid>(8, test_models::Ellipsoid::random, check_gauge, 1e-13);
}

/// The simulations of a body on a plane, which solve with `J = J₀ + c v vᵀ` by Sherman–Morrison
/// (docs/method.md §2a), against those of its num-dual twin, which has no `constant_inertia` and
/// so factorises J at every stage: the same trajectories at tight tolerances, full (8) and
/// reduced (13), on random bodies whose `J₀` is within the solver's condition bound.
#[test]
fn rank_one_simulations_match_the_twin() {
    use routh::{simulate_full, simulate_reduced, SimOptions};
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut checked = 0;
    while checked < 3 {
        let twin = test_models::Ellipsoid::random(&mut rng);
        let e = Ellipsoid::from(&twin);
        let j0 = e.constant_inertia().expect("J₀");
        // The solver's bound ‖J₀‖∞³/det J₀ ≤ 16 (field.rs), so that Sherman–Morrison is used.
        let norm = (0..3).map(|i| j0.row(i).abs().sum()).fold(0.0, f64::max);
        if norm.powi(3) / j0.determinant() > 16.0 {
            continue;
        }
        checked += 1;
        let w0 = test_models::random_vector(&mut rng, 2.0);
        let g0 = test_models::random_unit_vector(&mut rng);
        let opts = SimOptions::with_tolerances(1e-12, 1e-14);
        let t_end = 3.0;
        let (a, b) = (
            simulate_full(&e, w0, g0, t_end, &opts).expect("derived"),
            simulate_full(&twin, w0, g0, t_end, &opts).expect("twin"),
        );
        let last = |t: &routh::Trajectory| (*t.omega.last().unwrap(), *t.gamma.last().unwrap());
        let ((wa, ga), (wb, gb)) = (last(&a), last(&b));
        assert!(
            (wa - wb).amax() < 1e-8 * (1.0 + wb.amax()),
            "ω: {wa} vs {wb}"
        );
        assert!((ga - gb).amax() < 1e-8, "γ: {ga} vs {gb}");
        let p = e.cyclic_momentum(&w0, &g0);
        let o0 = w0 - g0 * w0.dot(&g0);
        let (ra, rb) = (
            simulate_reduced(&e, o0, g0, p, t_end, &opts).expect("derived"),
            simulate_reduced(&twin, o0, g0, p, t_end, &opts).expect("twin"),
        );
        let (oa, ob) = (*ra.omega.last().unwrap(), *rb.omega.last().unwrap());
        assert!(
            (oa - ob).amax() < 1e-8 * (1.0 + ob.amax()),
            "reduced ω: {oa} vs {ob}"
        );
        // And both reduced runs end where the full one does (Routh's reduction is exact).
        assert!(
            (oa - wa).amax() < 1e-7 * (1.0 + wa.amax()),
            "reduced vs full: {oa} vs {wa}"
        );
    }
}

/// `d/dt x(t)` at `t = 0` by central differences at `h`, `h/2`, `h/4` extrapolated twice
/// (Richardson): the error is O(h⁶), every entry of `x` at once.
fn richardson(x: impl Fn(f64) -> Vec<f64>, h: f64) -> Vec<f64> {
    let central = |h: f64| -> Vec<f64> {
        let (p, q) = (x(h), x(-h));
        p.iter().zip(&q).map(|(a, b)| (a - b) / (2.0 * h)).collect()
    };
    let (d1, d2, d4) = (central(h), central(h / 2.0), central(h / 4.0));
    (0..d1.len())
        .map(|i| {
            let r1 = (4.0 * d2[i] - d1[i]) / 3.0;
            let r2 = (4.0 * d4[i] - d2[i]) / 3.0;
            (16.0 * r2 - r1) / 15.0
        })
        .collect()
}

/// `∂/∂x_k` of `field` (`J` or the right side of (8), flattened) by [`richardson`] along
/// `ω_k` (`on_gamma` false) or `γ_k`, as the columns of a matrix (a vector field) or one
/// matrix per `k` (J).
fn partials(
    field: &impl Fn(&Vector3<f64>, &Vector3<f64>) -> Vec<f64>,
    w: &Vector3<f64>,
    g: &Vector3<f64>,
    k: usize,
    on_gamma: bool,
) -> Vec<f64> {
    richardson(
        |t| {
            let (mut w, mut g) = (*w, *g);
            if on_gamma {
                g[k] += t;
            } else {
                w[k] += t;
            }
            field(&w, &g)
        },
        // Small enough for the ellipsoid near |γ| = 0.6, whose higher derivatives in γ grow like
        // powers of 1/|γ|; rounding stays below 1e−11.
        0.005,
    )
}

/// `Lagrangian::full_jacobian` of the derive (exact, from the DAG) and the trait's default on
/// the twin (central differences of its num-dual `full_equations`) against a Richardson
/// extrapolation of the twin's num-dual `full_equations`: `J` and the right side of (8)
/// themselves, `∂f/∂ω`, `∂f/∂γ` and `∂J/∂γ_k`, at random points with |γ| ≠ 1. Returns the worst
/// normwise relative error of the derive.
fn check_jacobian<G: Lagrangian, H: Lagrangian>(
    gen: &G,
    reference: &H,
    rng: &mut ChaCha8Rng,
    tol: f64,
) -> f64 {
    let mut worst = 0.0f64;
    let rhs = |w: &Vector3<f64>, g: &Vector3<f64>| v(reference.full_equations(w, g).right_side);
    let inertia = |w: &Vector3<f64>, g: &Vector3<f64>| m(reference.full_equations(w, g).inertia);
    for _ in 0..POINTS / 3 {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let want = reference.full_equations(&w, &g);
        // ∂f/∂x as a matrix (i, j) = ∂f_i/∂x_j: column j is the derivative along x_j.
        let columns = |on_gamma| {
            let cols: Vec<Vec<f64>> = (0..3)
                .map(|k| partials(&rhs, &w, &g, k, on_gamma))
                .collect();
            m(Matrix3::from_fn(|i, j| cols[j][i]))
        };
        let (df_dw, df_dg) = (columns(false), columns(true));
        let dj: Vec<Vec<f64>> = (0..3)
            .map(|k| partials(&inertia, &w, &g, k, true))
            .collect();
        // The parameters and points are O(1): every output is compared relative to its
        // largest entry and at least to 1 (the right side is a sum with cancellation).
        let got = gen.full_jacobian(&w, &g);
        let default = reference.full_jacobian(&w, &g);
        for (who, jac, tol) in [("derive", &got, tol), ("default", &default, 1e-6)] {
            let checks: [(&str, Vec<f64>, &[f64]); 7] = [
                ("J", m(jac.inertia), &m(want.inertia)),
                ("f", v(jac.right_side), &v(want.right_side)),
                ("∂f/∂ω", m(jac.dright_domega), &df_dw),
                ("∂f/∂γ", m(jac.dright_dgamma), &df_dg),
                ("∂J/∂γ₀", m(jac.dinertia_dgamma[0]), &dj[0]),
                ("∂J/∂γ₁", m(jac.dinertia_dgamma[1]), &dj[1]),
                ("∂J/∂γ₂", m(jac.dinertia_dgamma[2]), &dj[2]),
            ];
            for (name, a, b) in checks {
                match close(&a, b, tol, 1.0) {
                    Ok(e) if who == "derive" => worst = worst.max(e),
                    Ok(_) => {}
                    Err(msg) => panic!("{who} {name} at w = {w:?}, g = {g:?}: {msg}"),
                }
            }
        }
        // J is the whole matrix also where the model splits it as J₀ + c v vᵀ (the same nodes
        // as `d2l_domega2`, written in another order).
        let j = gen.d2l_domega2(&g);
        assert!((got.inertia - j).amax() <= 1e-14 * j.amax());
    }
    worst
}

#[test]
fn gyrostat_full_jacobian_matches_richardson_of_numdual() {
    over_random_twins::<_, Gyrostat>(11, test_models::Gyrostat::random, check_jacobian, 1e-9);
}

#[test]
fn ellipsoid_full_jacobian_matches_richardson_of_numdual() {
    over_random_twins::<_, Ellipsoid>(12, test_models::Ellipsoid::random, check_jacobian, 1e-9);
}

/// The other derived models, which have no num-dual twin: `full_jacobian` against a Richardson
/// extrapolation of their own `full_equations` (the derivatives are still formed
/// independently).
#[test]
fn every_derived_full_jacobian_matches_richardson() {
    use derived_models::ellipsoid::DiagonalEllipsoid;
    use derived_models::{AsymmetricTop, FluidBody, LagrangeTop};
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let mut worst = 0.0f64;
    for _ in 0..3 {
        let pot = test_models::random_matrix(&mut rng, 1.0);
        let fluid = FluidBody {
            a_kin: test_models::random_spd(&mut rng),
            lin: test_models::random_matrix(&mut rng, 1.0),
            pot: pot + pot.transpose(),
        };
        worst = worst.max(check_jacobian(&fluid, &fluid, &mut rng, 1e-9));
        let top = AsymmetricTop {
            inertia: Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0)),
            com: test_models::random_vector(&mut rng, 1.0),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        };
        worst = worst.max(check_jacobian(&top, &top, &mut rng, 1e-9));
        let ellipsoid = DiagonalEllipsoid::random(&mut rng);
        worst = worst.max(check_jacobian(&ellipsoid, &ellipsoid, &mut rng, 1e-9));
    }
    let lagrange = LagrangeTop::example();
    worst = worst.max(check_jacobian(&lagrange, &lagrange, &mut rng, 1e-9));
    eprintln!("worst normwise relative error: {worst:e}");
}
