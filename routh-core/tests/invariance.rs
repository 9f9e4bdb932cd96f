//! Invariance of the analysis (steady motions (31)–(34), stability (62)–(64)) under
//! transformations of the model whose effect is known exactly, derived below from the Lagrangian.
//! Each test runs `steady_motion_search` and `classify` on a model and on its transform and
//! compares the counts, the sets of γ (matched to 1e−8), the verdicts, the eigenvalues of the
//! restricted second variation and the roots of `f₂` with what the transformation predicts.
//!
//! The models are `test_models::Gyrostat` (written by hand, derivatives by num-dual):
//! `L = ½ωᵀIω + (K + Bγ)·ω − m g r·γ` with a full inertia tensor, a rotor `K`, a coupling `B`
//! and an off-axis centre of mass, so that every parameter can be transformed. Their steady
//! motions are isolated (no symmetry), so γ can be matched point by point.
//!
//! The scaling `J → sJ`, `U → sU`, `p_ψ → s·p_ψ` is checked in `tests/trust.rs`
//! (`scaling_the_model_changes_nothing`, `extreme_momenta_change_nothing`).

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use routh_core::steady::{steady_motion_search, SearchOptions, SearchResult};
use routh_core::{classify, Complex, Matrix3, StabilityReport, Vector3};
use test_models::jacobian::match_roots_within;
use test_models::Gyrostat;

/// The steady motions at `p` and the report of each.
fn analyse(model: &Gyrostat, p: f64) -> (SearchResult, Vec<StabilityReport>) {
    let r = steady_motion_search(model, p, &SearchOptions::default()).unwrap();
    let reports = r
        .motions
        .iter()
        .map(|s| classify(model, s).unwrap())
        .collect();
    (r, reports)
}

/// What a transformation predicts: γ ↦ `map(γ)`, the restricted second variation multiplied by
/// `kappa`, `U_r` by `kappa` as well, `ψ̇` by `psi_dot`, the roots of `f₂` by `roots`.
struct Prediction<'a> {
    map: &'a dyn Fn(&Vector3<f64>) -> Vector3<f64>,
    kappa: f64,
    psi_dot: f64,
    roots: f64,
}

/// Compares the analysis of a model (`base`) with that of its transform (`other`) against the
/// prediction; returns the number of steady motions compared and the largest relative deviation
/// of the f₂ roots.
fn compare(
    what: &str,
    base: &(SearchResult, Vec<StabilityReport>),
    other: &(SearchResult, Vec<StabilityReport>),
    pred: &Prediction<'_>,
) -> (usize, f64) {
    let ((b, b_reports), (o, o_reports)) = (base, other);
    assert!(
        b.consistent,
        "{what}: the base search is not reconciled: {b:?}"
    );
    assert_eq!(o.motions.len(), b.motions.len(), "{what}: {:#?}", o.motions);
    assert_eq!(o.consistent, b.consistent, "{what}");
    assert_eq!(o.euler_characteristic, b.euler_characteristic, "{what}");
    let mut worst = 0.0f64;
    for (y, want) in b.motions.iter().zip(b_reports) {
        assert!(y.isolated, "{what}: a generic gyrostat has no curves: {y}");
        let target = (pred.map)(&y.gamma);
        let hits: Vec<usize> = (0..o.motions.len())
            .filter(|&k| (o.motions[k].gamma - target).norm() <= 1e-8)
            .collect();
        assert_eq!(
            hits.len(),
            1,
            "{what}: {y} ↦ γ = {target:?}: {:#?}",
            o.motions
        );
        let (x, got) = (&o.motions[hits[0]], &o_reports[hits[0]]);
        let ctx = format!("{what}: {y}\n  ↦ {x}\n  {want}\n  {got}");
        assert!(x.isolated, "{ctx}");
        // U_r and ψ̇ (both to round-off of their own size).
        let u = pred.kappa * y.amended_potential;
        assert!(
            (x.amended_potential - u).abs() <= 1e-12 * u.abs().max(pred.kappa),
            "{ctx}"
        );
        let pd = pred.psi_dot * y.psi_dot;
        assert!(
            (x.psi_dot - pd).abs() <= 1e-12 * pd.abs().max(pred.psi_dot.abs()),
            "{ctx}"
        );
        // The verdict, the degree and the restricted second variation. The eigenvalues are
        // compared relative to the larger one: both points are located to about 1e−13 rad and the
        // eigenvalues are computed to round-off of the raw derivatives.
        assert_eq!(got.verdict, want.verdict, "{ctx}");
        assert_eq!(
            got.degree_of_instability, want.degree_of_instability,
            "{ctx}"
        );
        let [w0, w1] = want.restricted_hessian_eigenvalues;
        let k_scale = pred.kappa * w0.abs().max(w1.abs());
        for (e, f) in got.restricted_hessian_eigenvalues.iter().zip([w0, w1]) {
            assert!((e - pred.kappa * f).abs() <= 1e-9 * k_scale, "{ctx}");
        }
        // The roots of f₂.
        let scaled: Vec<Complex<f64>> = want.f2_roots.iter().map(|z| z * pred.roots).collect();
        let scale = scaled.iter().map(|z| z.norm()).fold(0.0, f64::max);
        let d = match_roots_within(&got.f2_roots, &scaled, |_| 1e-9 * scale)
            .unwrap_or_else(|e| panic!("{ctx}\n  f₂: {e}"));
        worst = worst.max(d / scale);
    }
    (b.motions.len(), worst)
}

/// Generic gyrostats (full inertia, rotor, coupling, off-axis centre of mass) and momenta at
/// which they have two, four or six steady motions (36 in all), with secularly stable, unstable
/// and gyroscopically stabilised ones among them.
fn cases() -> Vec<(Gyrostat, f64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut out = Vec::new();
    for _ in 0..3 {
        let body = Gyrostat::random(&mut rng);
        for p in [4.0, 12.0, 30.0] {
            out.push((body.clone(), p));
        }
    }
    out
}

#[test]
fn the_cases_are_not_trivial() {
    let mut counts = Vec::new();
    let mut verdicts = std::collections::HashSet::new();
    for (body, p) in cases() {
        let (r, reports) = analyse(&body, p);
        counts.push(r.motions.len());
        verdicts.extend(reports.iter().map(|r| r.verdict));
    }
    assert_eq!(counts.iter().sum::<usize>(), 36, "{counts:?}");
    for n in [2, 4, 6] {
        assert!(counts.contains(&n), "{counts:?}");
    }
    use routh_core::Stability::*;
    for v in [SecularlyStable, Unstable, GyroscopicallyStabilized] {
        assert!(verdicts.contains(&v), "{verdicts:?}");
    }
}

/// A rotation matrix from an axis (normalised) and an angle (Rodrigues).
fn rotation(axis: Vector3<f64>, angle: f64) -> Matrix3<f64> {
    let n = axis.normalize();
    let k = n.cross_matrix();
    Matrix3::identity() + angle.sin() * k + (1.0 - angle.cos()) * k * k
}

#[test]
fn time_scaling() {
    // Run every motion k times faster, ω' = kω. L'(ω', γ) = k²L(ω'/k, γ) has the same
    // equations of motion in the time t' = t/k, and
    //   L' = ½ω'ᵀIω' + k(K + Bγ)·ω' − k²m g r·γ:
    // J unchanged, the gyroscopic term a → k·a (rotor and coupling), U → k²U. Its cyclic momentum
    // (9) is p' = ((Iω' + k a), γ) = k·p. By (38) ψ̇' = (kp − k a·γ)/(γᵀIγ) = kψ̇, and (40)
    // U_r' = ½(kp − k a·γ)²/(γᵀIγ) + k²U = k²U_r: the same critical points γ, the restricted
    // second variation (62)–(63) multiplied by k², the same verdicts. In (64) A = ∂²R/∂Ω² does not
    // involve p, a or U, G is linear in them (k·G) and C = k²C, so
    // f₂'(λ) = det(Aλ² + 2kGλ + k²C) = k⁴f₂(λ/k): the roots are multiplied by k.
    let mut count = 0;
    let mut worst = 0.0f64;
    for (body, p) in cases() {
        let base = analyse(&body, p);
        for k in [3.0, 1e-3, -1.0 / 7.0] {
            let t = Gyrostat {
                rotor: k * body.rotor,
                coupling: k * body.coupling,
                g: k * k * body.g,
                ..body.clone()
            };
            let other = analyse(&t, k * p);
            let id = |g: &Vector3<f64>| *g;
            let pred = Prediction {
                map: &id,
                kappa: k * k,
                psi_dot: k,
                roots: k,
            };
            let (n, w) = compare(&format!("p = {p}, k = {k}"), &base, &other, &pred);
            count += n;
            worst = worst.max(w);
        }
    }
    eprintln!("time scaling: {count} steady motions compared, f₂ roots to {worst:e} (relative)");
    assert_eq!(count, 3 * 36);
}

#[test]
fn rotating_the_body_frame() {
    // Express the body in a frame turned by the rotation Q: I' = QIQᵀ, K' = QK, B' = QBQᵀ,
    // r' = Qr. Then L'(Qω, Qγ) = L(ω, γ), so a steady motion γ of the body is the steady motion
    // Qγ of the transform, with the same ψ̇ (p_ψ = (∂L/∂ω, γ) is a scalar), the same U_r, and the
    // second variation, A, G, C all conjugated by Q: the same eigenvalues on the tangent plane,
    // the same f₂ (errata E5: its coefficients do not depend on the basis P), the same verdicts.
    let mut count = 0;
    let mut worst = 0.0f64;
    let rotations = [
        rotation(Vector3::new(1.0, 2.0, 3.0), 0.7),
        rotation(Vector3::new(-0.3, 0.1, 1.0), 2.9),
        rotation(Vector3::new(0.0, 1.0, 0.0), std::f64::consts::FRAC_PI_2),
    ];
    for (body, p) in cases() {
        let base = analyse(&body, p);
        for q in &rotations {
            assert!((q * q.transpose() - Matrix3::identity()).norm() < 1e-15);
            assert!((q.determinant() - 1.0).abs() < 1e-15);
            let t = Gyrostat {
                inertia: q * body.inertia * q.transpose(),
                rotor: q * body.rotor,
                coupling: q * body.coupling * q.transpose(),
                com: q * body.com,
                ..body.clone()
            };
            let other = analyse(&t, p);
            let map = |g: &Vector3<f64>| q * g;
            let pred = Prediction {
                map: &map,
                kappa: 1.0,
                psi_dot: 1.0,
                roots: 1.0,
            };
            let (n, w) = compare(&format!("p = {p}, Q = {q}"), &base, &other, &pred);
            count += n;
            worst = worst.max(w);
        }
    }
    eprintln!("rotation: {count} steady motions compared, f₂ roots to {worst:e} (relative)");
    assert_eq!(count, 3 * 36);
}

#[test]
fn reversing_the_momentum_and_the_gyroscopic_terms() {
    // Reverse time: L'(ω, γ) = L(−ω, γ) = ½ωᵀIω − (K + Bγ)·ω − m g r·γ (rotor and coupling
    // reversed). Its cyclic momentum at ω' = −ω is ((Iω' − a), γ) = −p, and (40)
    // U_r' = ½(−p + a·γ)²/(γᵀIγ) + U = U_r: the same steady motions γ, ψ̇' = −ψ̇ (ω' = ψ̇'γ = −ω),
    // the same restricted second variation and verdicts. In (64) only G changes sign, and f₂
    // depends on G through g² only (c₂ = … + 4g²): the same roots.
    let mut count = 0;
    let mut worst = 0.0f64;
    for (body, p) in cases() {
        let base = analyse(&body, p);
        let t = Gyrostat {
            rotor: -body.rotor,
            coupling: -body.coupling,
            ..body.clone()
        };
        let other = analyse(&t, -p);
        let id = |g: &Vector3<f64>| *g;
        let pred = Prediction {
            map: &id,
            kappa: 1.0,
            psi_dot: -1.0,
            roots: 1.0,
        };
        let (n, w) = compare(&format!("p = {p}, reversed"), &base, &other, &pred);
        count += n;
        worst = worst.max(w);
    }
    eprintln!("reversal: {count} steady motions compared, f₂ roots to {worst:e} (relative)");
    assert_eq!(count, 36);
}
