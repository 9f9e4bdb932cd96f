//! The tape of the Routh function (`Routhian::routh_tape`) of derived models: its f64 value is
//! the generated `routhian` at arbitrary `(Ω, γ, p_ψ)` (|γ| ≠ 1, Ω ≠ 0), and evaluated with a
//! second-order jet (num-dual's `Dual2`, through a newtype implementing `TapeScalar`) its
//! second directional derivative is the quadratic form of the generated Hessians — the use
//! the tape is for (derivatives beyond the Hessian, by jets).

use derived_models::{Ellipsoid, Gyrostat};
use num_dual::{Dual2_64, DualNum};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{Routhian, Vector3};
use routh_tape::{Func, TapeScalar};
use std::ops::{Add, Mul, Neg};

/// A second-order jet in one direction.
#[derive(Clone, Copy, Debug)]
struct Jet(Dual2_64);

impl Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        Jet(self.0 + o.0)
    }
}
impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        Jet(self.0 * o.0)
    }
}
impl Neg for Jet {
    type Output = Jet;
    fn neg(self) -> Jet {
        Jet(-self.0)
    }
}
impl TapeScalar for Jet {
    fn from_f64(x: f64) -> Self {
        Jet(Dual2_64::from(x))
    }
    fn recip(self) -> Self {
        Jet(self.0.recip())
    }
    fn powi(self, n: i32) -> Self {
        Jet(self.0.powi(n))
    }
    fn powf(self, y: Self) -> Self {
        // x^y = exp(y ln x)
        Jet((y.0 * self.0.ln()).exp())
    }
    fn func(self, f: Func) -> Self {
        let x = self.0;
        let s = routh_tape::sign(x.re);
        Jet(match f {
            Func::Sqrt => x.sqrt(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Abs => x * s,
            Func::Sign => Dual2_64::from(s),
        })
    }
}

fn arr(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn check<M: Routhian>(model: &M, rng: &mut ChaCha8Rng) -> (f64, f64) {
    let tape = model
        .routh_tape()
        .expect("derived models have a Routh tape");
    let (mut worst_value, mut worst_jet) = (0.0f64, 0.0f64);
    let mut slots = Vec::new();
    for _ in 0..50 {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p: f64 = rng.gen_range(-3.0..3.0);
        // The value.
        let r = tape.routhian_with(&arr(&w), &arr(&g), p, &mut slots);
        let b = model.bundle(&w, &g, p);
        let scale = b.routhian.abs().max(1.0);
        worst_value = worst_value.max((r - b.routhian).abs() / scale);
        // d²/dt² R(Ω + t u, γ + t v, p_ψ) at t = 0 = uᵀR_ΩΩu + 2uᵀR_Ωγ v + vᵀR_γγ v.
        let u = test_models::random_vector(rng, 1.0);
        let v = test_models::random_vector(rng, 1.0);
        let jet = |x: f64, d: f64| Jet(Dual2_64::new(x, d, 0.0));
        let big = [0, 1, 2].map(|i| jet(w[i], u[i]));
        let gam = [0, 1, 2].map(|i| jet(g[i], v[i]));
        let d2 = tape.routhian::<Jet>(&big, &gam, Jet::from_f64(p)).0.v2;
        let want = u.dot(&(b.d2r_domega2 * u))
            + 2.0 * u.dot(&(b.d2r_domega_dgamma * v))
            + v.dot(&(b.d2r_dgamma2 * v));
        let scale =
            (b.d2r_domega2.norm() + b.d2r_domega_dgamma.norm() + b.d2r_dgamma2.norm()).max(1.0);
        worst_jet = worst_jet.max((d2 - want).abs() / scale);
    }
    (worst_value, worst_jet)
}

#[test]
fn routh_tape_is_the_generated_routhian_and_its_jets_the_hessians() {
    let mut rng = ChaCha8Rng::seed_from_u64(22);
    for _ in 0..10 {
        let g = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
        let (value, jet) = check(&g, &mut rng);
        assert!(value < 1e-13 && jet < 1e-11, "gyrostat: {value:e}, {jet:e}");
        let e = Ellipsoid::from(&test_models::Ellipsoid::random(&mut rng));
        let (value, jet) = check(&e, &mut rng);
        assert!(
            value < 1e-13 && jet < 1e-11,
            "ellipsoid: {value:e}, {jet:e}"
        );
    }
}

#[test]
fn hand_written_models_have_no_tape() {
    let top = test_models::HeavyTop::lagrange(1.0, 1.25, 1.0);
    assert!(top.routh_tape().is_none());
}
