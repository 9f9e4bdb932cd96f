//! Every construct of the DSL (README, “A body in ten lines”) in one model, checked against the same
//! Lagrangian written by hand with nalgebra (the value), and its derivatives against central
//! finite differences.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{Lagrangian, Matrix3, Routhian, Vector3};

/// Not physical; it exercises every operator, method and function of the DSL.
#[derive(Lagrangian)]
#[lagrangian(
    crate = "::routh",
    let w = inertia * omega,
    let e = (gamma.dot(gamma) + 1.0).ln() + (0.3 * gamma.x).exp() + (0.2 * gamma.y).sin()
        + (0.1 * gamma.z).cos() + (0.2 * gamma[0]).tan() + (gamma.norm_squared() + 2.0).sqrt()
        + (2.0 + gamma.y).powf(1.5) + (3.0 + gamma.z).powf(gamma.x) + (gamma.z - 3.0).abs()
        + (4.0 + gamma.x).recip() + gamma.norm() + gamma.y.powi(3) + (gamma.z + 3.0).powi(-2),
    let h = grad(e, gamma),
    kinetic = 0.5 * omega.dot(&w) + 0.25 * (skew(h) * omega).norm_squared()
        + 0.1 * omega.component_mul(omega).dot(diag(com) * com) * inertia.transpose().trace() / 3.0,
    linear = (rotor + coupling.transpose() * gamma).dot(omega) + self.mass * omega.cross(com)[2]
        + inertia[(0, 1)] * omega.z - (-omega.y) * e,
    potential = mass * g * com.dot(gamma) + e * e / 2,
)]
struct Everything {
    inertia: Matrix3<f64>,
    rotor: Vector3<f64>,
    coupling: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
    #[lagrangian(skip)]
    #[allow(dead_code)]
    label: String,
}

impl Everything {
    fn e(g: &Vector3<f64>) -> f64 {
        (g.dot(g) + 1.0).ln()
            + (0.3 * g.x).exp()
            + (0.2 * g.y).sin()
            + (0.1 * g.z).cos()
            + (0.2 * g.x).tan()
            + (g.norm_squared() + 2.0).sqrt()
            + (2.0 + g.y).powf(1.5)
            + (3.0 + g.z).powf(g.x)
            + (g.z - 3.0).abs()
            + 1.0 / (4.0 + g.x)
            + g.norm()
            + g.y.powi(3)
            + (g.z + 3.0).powi(-2)
    }

    /// ∂e/∂γ, differentiated by hand.
    fn grad_e(g: &Vector3<f64>) -> Vector3<f64> {
        let (x, y, z) = (g.x, g.y, g.z);
        let n2 = g.norm_squared();
        let (ln_d, sq, n) = (n2 + 1.0, (n2 + 2.0).sqrt(), g.norm());
        let common = |c: f64| 2.0 * c / ln_d + c / sq + c / n;
        Vector3::new(
            common(x)
                + 0.3 * (0.3 * x).exp()
                + 0.2 / (0.2 * x).cos().powi(2)
                + (3.0 + z).powf(x) * (3.0 + z).ln()
                - 1.0 / (4.0 + x).powi(2),
            common(y) + 0.2 * (0.2 * y).cos() + 1.5 * (2.0 + y).sqrt() + 3.0 * y * y,
            common(z) - 0.1 * (0.1 * z).sin() + x * (3.0 + z).powf(x - 1.0) + (z - 3.0).signum()
                - 2.0 * (z + 3.0).powi(-3),
        )
    }

    /// The same Lagrangian by hand.
    fn by_hand(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
        let e = Self::e(g);
        let h = Self::grad_e(g);
        let kinetic = 0.5 * w.dot(&(self.inertia * w))
            + 0.25 * h.cross(w).norm_squared()
            + 0.1
                * w.component_mul(w)
                    .dot(&(Matrix3::from_diagonal(&self.com) * self.com))
                * self.inertia.trace()
                / 3.0;
        let linear = (self.rotor + self.coupling.transpose() * g).dot(w)
            + self.mass * w.cross(&self.com).z
            + self.inertia[(0, 1)] * w.z
            + w.y * e;
        let potential = self.mass * self.g * self.com.dot(g) + e * e / 2.0;
        kinetic + linear - potential
    }
}

#[test]
fn every_construct_of_the_dsl_computes_what_it_says() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let model = Everything {
        inertia: test_models::random_spd(&mut rng),
        rotor: test_models::random_vector(&mut rng, 0.5),
        coupling: test_models::random_matrix(&mut rng, 0.5),
        com: test_models::random_vector(&mut rng, 1.0),
        mass: 1.3,
        g: 9.81,
        label: "skipped".into(),
    };
    for _ in 0..50 {
        let w = test_models::random_vector(&mut rng, 1.0);
        let g = test_models::random_unit_vector(&mut rng) * rng.gen_range(0.7..1.2);
        let l = model.lagrangian(&w, &g);
        let hand = model.by_hand(&w, &g);
        assert!(
            (l - hand).abs() <= 1e-12 * (1.0 + hand.abs()),
            "L = {l} vs {hand}"
        );
        // First derivatives against central differences of the generated L itself, and the
        // energy (3) and momentum (9) against their definitions.
        let step = 1e-6;
        for i in 0..3 {
            let (mut wp, mut wm, mut gp, mut gmm) = (w, w, g, g);
            wp[i] += step;
            wm[i] -= step;
            gp[i] += step;
            gmm[i] -= step;
            let dw = (model.lagrangian(&wp, &g) - model.lagrangian(&wm, &g)) / (2.0 * step);
            let dg = (model.lagrangian(&w, &gp) - model.lagrangian(&w, &gmm)) / (2.0 * step);
            let scale = 1.0 + l.abs();
            assert!((model.dl_domega(&w, &g)[i] - dw).abs() <= 1e-7 * scale);
            assert!((model.dl_dgamma(&w, &g)[i] - dg).abs() <= 1e-7 * scale);
        }
        let p = model.dl_domega(&w, &g).dot(&g);
        assert!((model.cyclic_momentum(&w, &g) - p).abs() <= 1e-12 * (1.0 + p.abs()));
        let e = model.dl_domega(&w, &g).dot(&w) - l;
        assert!((model.energy(&w, &g) - e).abs() <= 1e-12 * (1.0 + e.abs()));
        // The Routh function is consistent with L: Theorem 2, (∂R/∂Ω, γ) = p_ψ.
        let b = model.bundle(&w, &g, 0.7);
        let scale = 1.0 + b.dr_domega.norm() * g.norm();
        assert!(
            (b.dr_domega.dot(&g) - 0.7).abs() <= 1e-12 * scale,
            "{} vs 0.7 (scale {scale})",
            b.dr_domega.dot(&g)
        );
    }
}

/// `full_jacobian` (the right side of (8) and J differentiated on the DAG) against a Richardson
/// extrapolation of central differences of the generated `full_equations`, on the model that
/// uses every construct of the DSL.
#[test]
fn full_jacobian_of_every_construct_matches_richardson() {
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let model = Everything {
        inertia: test_models::random_spd(&mut rng),
        rotor: test_models::random_vector(&mut rng, 0.5),
        coupling: test_models::random_matrix(&mut rng, 0.5),
        com: test_models::random_vector(&mut rng, 1.0),
        mass: 1.3,
        g: 9.81,
        label: "skipped".into(),
    };
    // Both fields of (8) flattened: the right side, then J row by row.
    let field = |w: &Vector3<f64>, g: &Vector3<f64>| {
        let e = model.full_equations(w, g);
        let mut out: Vec<f64> = e.right_side.iter().copied().collect();
        out.extend(e.inertia.transpose().iter().copied());
        out
    };
    for _ in 0..20 {
        let w = test_models::random_vector(&mut rng, 1.0);
        let g = test_models::random_unit_vector(&mut rng) * rng.gen_range(0.7..1.2);
        let jac = model.full_jacobian(&w, &g);
        // The same nodes, written in another order (rounding may differ in the last bit).
        let j = model.d2l_domega2(&g);
        assert!((jac.inertia - j).amax() <= 1e-14 * j.amax());
        let f = model.full_equations(&w, &g).right_side;
        assert!((jac.right_side - f).amax() <= 1e-13 * (1.0 + f.amax()));
        for k in 0..3 {
            for on_gamma in [false, true] {
                // d/dt at t = 0 along x_k: central differences at h, h/2, h/4, extrapolated
                // twice (error O(h⁶)).
                let central = |h: f64| -> Vec<f64> {
                    let (mut wp, mut gp, mut wm, mut gm) = (w, g, w, g);
                    if on_gamma {
                        gp[k] += h;
                        gm[k] -= h;
                    } else {
                        wp[k] += h;
                        wm[k] -= h;
                    }
                    let (p, m) = (field(&wp, &gp), field(&wm, &gm));
                    p.iter().zip(&m).map(|(a, b)| (a - b) / (2.0 * h)).collect()
                };
                let h = 0.005;
                let (d1, d2, d4) = (central(h), central(h / 2.0), central(h / 4.0));
                let want: Vec<f64> = (0..d1.len())
                    .map(|i| {
                        let r1 = (4.0 * d2[i] - d1[i]) / 3.0;
                        let r2 = (4.0 * d4[i] - d2[i]) / 3.0;
                        (16.0 * r2 - r1) / 15.0
                    })
                    .collect();
                let df = if on_gamma {
                    jac.dright_dgamma
                } else {
                    jac.dright_domega
                };
                let mut got: Vec<f64> = df.column(k).iter().copied().collect();
                if on_gamma {
                    got.extend(jac.dinertia_dgamma[k].transpose().iter().copied());
                } else {
                    // J does not depend on ω.
                    got.extend([0.0; 9]);
                }
                let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
                for (i, (a, b)) in got.iter().zip(&want).enumerate() {
                    assert!(
                        (a - b).abs() <= 1e-8 * scale,
                        "entry {i} along {} {k}: {a} vs {b} at w = {w:?}, g = {g:?}",
                        if on_gamma { "γ" } else { "ω" }
                    );
                }
            }
        }
    }
}
