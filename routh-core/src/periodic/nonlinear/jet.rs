//! Truncated power series in two variables to order three, real ([`MapJet`]) or complex
//! ([`CJet`]): the jets of the flow of (8) in the two coordinates of a Poincaré section, and the
//! Poincaré map's expansion in `(z, z̄)` for its normal form (docs/method.md §12).
//!
//! Coefficients are ordered by degree, then by the power of the second variable:
//! `1, a, b, a², ab, b², a³, a²b, ab², b³`.

use std::ops::{Add, Mul, Neg, Sub};

use nalgebra::Complex;
use routh_tape::{Func, TapeScalar};

/// Number of coefficients.
pub(crate) const N: usize = 10;

/// The exponents `(i, j)` of the monomial `aⁱbʲ` of coefficient `k`.
pub(crate) const EXPS: [(u8, u8); N] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
];

/// The index of `aⁱbʲ` (degree ≤ 3).
pub(crate) const fn index(i: u8, j: u8) -> usize {
    let d = (i + j) as usize;
    d * (d + 1) / 2 + j as usize
}

/// `(p, q, r)`: coefficient `p` times coefficient `q` lands in `r`, over the 35 pairs whose
/// degrees add to at most 3.
#[cfg(test)]
const PRODUCTS: [(u8, u8, u8); 35] = products();

#[cfg(test)]
const fn products() -> [(u8, u8, u8); 35] {
    let mut out = [(0u8, 0u8, 0u8); 35];
    let mut n = 0;
    let mut p = 0;
    while p < N {
        let mut q = 0;
        while q < N {
            let (i, j) = (EXPS[p].0 + EXPS[q].0, EXPS[p].1 + EXPS[q].1);
            if i + j <= 3 {
                out[n] = (p as u8, q as u8, index(i, j) as u8);
                n += 1;
            }
            q += 1;
        }
        p += 1;
    }
    out
}

/// What a coefficient needs: a commutative ring with the reals in it.
pub(crate) trait Coef:
    Copy + PartialEq + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    fn real(x: f64) -> Self;
}

impl Coef for f64 {
    fn real(x: f64) -> Self {
        x
    }
}

impl Coef for Complex<f64> {
    fn real(x: f64) -> Self {
        Complex::new(x, 0.0)
    }
}

/// A power series in two variables truncated after order three.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Series<T> {
    pub c: [T; N],
}

/// A real jet: the Taylor expansion of a function of the section's two coordinates.
pub(crate) type MapJet = Series<f64>;
/// A complex jet in `(z, z̄)`.
pub(crate) type CJet = Series<Complex<f64>>;

impl<T: Coef> Series<T> {
    pub fn constant(a: T) -> Self {
        let mut c = [T::real(0.0); N];
        c[0] = a;
        Series { c }
    }
    /// The variable `v` (0 or 1) at the value 0.
    pub fn variable(v: usize) -> Self {
        let mut s = Self::constant(T::real(0.0));
        s.c[1 + v] = T::real(1.0);
        s
    }
    pub fn value(&self) -> T {
        self.c[0]
    }
    /// The coefficient of `aⁱbʲ`.
    pub fn coeff(&self, i: u8, j: u8) -> T {
        self.c[index(i, j)]
    }
    pub fn scale(mut self, s: T) -> Self {
        for x in self.c.iter_mut() {
            *x = *x * s;
        }
        self
    }
    /// `Σ_k d[k]/k! (x − a)^k`, `a` the value: a function with derivatives `d` at `a`
    /// composed with the series.
    pub fn compose(&self, d: [f64; 4]) -> Self {
        let mut h = *self;
        h.c[0] = T::real(0.0);
        let mut r = Self::constant(T::real(d[3] / 6.0));
        r = r * h + Self::constant(T::real(d[2] / 2.0));
        r = r * h + Self::constant(T::real(d[1]));
        r * h + Self::constant(T::real(d[0]))
    }
    /// The series `p(x, y)` with the polynomial `self` evaluated at the series `x`, `y`.
    pub fn substitute(&self, x: &Self, y: &Self) -> Self {
        // Powers of x and y to degree 3.
        let one = Self::constant(T::real(1.0));
        let xp = [one, *x, *x * *x, *x * *x * *x];
        let yp = [one, *y, *y * *y, *y * *y * *y];
        let mut out = Self::constant(T::real(0.0));
        for (k, &(i, j)) in EXPS.iter().enumerate() {
            out = out + (xp[i as usize] * yp[j as usize]).scale(self.c[k]);
        }
        out
    }
}

impl CJet {
    /// The complex conjugate as a series in `(z, z̄)`: `conj(Σ c_{ij} zⁱ z̄ʲ) = Σ c̄_{ij} z̄ⁱ zʲ`.
    pub fn conj(&self) -> Self {
        let mut out = *self;
        for (k, &(i, j)) in EXPS.iter().enumerate() {
            out.c[index(j, i)] = self.c[k].conj();
        }
        out
    }
}

impl MapJet {
    fn recip(&self) -> Self {
        let r = 1.0 / self.value();
        self.compose([r, -r * r, 2.0 * r * r * r, -6.0 * r.powi(4)])
    }
    fn powf_const(&self, r: f64) -> Self {
        self.compose(crate::nonlinear::jet::power_derivatives(self.value(), r))
    }
}

impl<T: Coef> Add for Series<T> {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        for (a, b) in self.c.iter_mut().zip(o.c) {
            *a = *a + b;
        }
        self
    }
}

impl<T: Coef> Sub for Series<T> {
    type Output = Self;
    fn sub(mut self, o: Self) -> Self {
        for (a, b) in self.c.iter_mut().zip(o.c) {
            *a = *a - b;
        }
        self
    }
}

impl<T: Coef> Neg for Series<T> {
    type Output = Self;
    fn neg(mut self) -> Self {
        for a in self.c.iter_mut() {
            *a = -*a;
        }
        self
    }
}

impl<T: Coef> Mul for Series<T> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        // A constant factor (a parameter, a number of the tape, a constant inertia) is a
        // scaling: 10 products instead of 35.
        let zero = T::real(0.0);
        if o.c[1..].iter().all(|&x| x == zero) {
            return self.scale(o.c[0]);
        }
        if self.c[1..].iter().all(|&x| x == zero) {
            return o.scale(self.c[0]);
        }
        // The 35 products of `PRODUCTS` written out by output coefficient (no read–modify–write
        // of the output in memory; a test checks them against the table).
        let (a, b) = (&self.c, &o.c);
        Series {
            c: [
                a[0] * b[0],
                a[0] * b[1] + a[1] * b[0],
                a[0] * b[2] + a[2] * b[0],
                a[0] * b[3] + a[1] * b[1] + a[3] * b[0],
                a[0] * b[4] + a[1] * b[2] + a[2] * b[1] + a[4] * b[0],
                a[0] * b[5] + a[2] * b[2] + a[5] * b[0],
                a[0] * b[6] + a[1] * b[3] + a[3] * b[1] + a[6] * b[0],
                a[0] * b[7] + a[1] * b[4] + a[2] * b[3] + a[3] * b[2] + a[4] * b[1] + a[7] * b[0],
                a[0] * b[8] + a[1] * b[5] + a[2] * b[4] + a[4] * b[2] + a[5] * b[1] + a[8] * b[0],
                a[0] * b[9] + a[2] * b[5] + a[5] * b[2] + a[9] * b[0],
            ],
        }
    }
}

impl TapeScalar for MapJet {
    fn from_f64(x: f64) -> Self {
        Series::constant(x)
    }
    fn recip(self) -> Self {
        MapJet::recip(&self)
    }
    fn powi(self, n: i32) -> Self {
        if n < 0 {
            return TapeScalar::powi(self, -n).recip();
        }
        if n == 0 {
            return Series::constant(1.0);
        }
        if n > 64 {
            return self.powf_const(f64::from(n));
        }
        // Repeated products keep xⁿ exact where the value is 0.
        let mut out = self;
        for _ in 1..n {
            out = out * self;
        }
        out
    }
    fn powf(self, y: Self) -> Self {
        if y.c[1..].iter().all(|&c| c == 0.0) {
            self.powf_const(y.value())
        } else {
            // xʸ = exp(y ln x).
            let a = self.value();
            let r = 1.0 / a;
            let ln = self.compose([a.ln(), r, -r * r, 2.0 * r * r * r]);
            let e = y * ln;
            let v = e.value().exp();
            e.compose([v; 4])
        }
    }
    fn func(self, f: Func) -> Self {
        let a = self.value();
        match f {
            Func::Sqrt => self.powf_const(0.5),
            Func::Sin => {
                let (s, c) = a.sin_cos();
                self.compose([s, c, -s, -c])
            }
            Func::Cos => {
                let (s, c) = a.sin_cos();
                self.compose([c, -s, -c, s])
            }
            Func::Tan => {
                let t = a.tan();
                let t2 = 1.0 + t * t;
                self.compose([t, t2, 2.0 * t * t2, 2.0 * t2 * (1.0 + 3.0 * t * t)])
            }
            Func::Exp => self.compose([a.exp(); 4]),
            Func::Ln => {
                let r = 1.0 / a;
                self.compose([a.ln(), r, -r * r, 2.0 * r * r * r])
            }
            Func::Abs => self.scale(routh_tape::sign(a)),
            Func::Sign => Series::constant(routh_tape::sign(a)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The product written out equals the table of the pairs of monomials whose degrees add to
    /// at most three, on coefficients with no common structure.
    #[test]
    fn the_written_out_product_is_the_tables() {
        let a = Series {
            c: std::array::from_fn(|k| 1.0 + (k as f64 * 0.37).sin()),
        };
        let b = Series {
            c: std::array::from_fn(|k| 0.5 - (k as f64 * 1.13).cos()),
        };
        let mut c = [0.0; N];
        for &(p, q, r) in PRODUCTS.iter() {
            c[r as usize] += a.c[p as usize] * b.c[q as usize];
        }
        let d = (a * b).c;
        for k in 0..N {
            assert!((c[k] - d[k]).abs() < 1e-15, "{k}: {} {}", c[k], d[k]);
        }
    }

    /// Every operation against the closed-form Taylor coefficients of a function of (a, b).
    #[test]
    fn coefficients_are_the_closed_form_taylor_coefficients() {
        let a = MapJet::variable(0) + Series::constant(0.3);
        let b = MapJet::variable(1) - Series::constant(0.2);
        // f = sin(a)·exp(b)/(1 + a b) at (0.3, −0.2): finite differences of a 4th-order
        // central scheme against the jet's second and third derivatives.
        let f = |x: f64, y: f64| x.sin() * y.exp() / (1.0 + x * y);
        let j = a.func(Func::Sin) * b.func(Func::Exp) * (Series::constant(1.0) + a * b).recip();
        let h = 1e-3;
        let d_ab = (f(0.3 + h, -0.2 + h) - f(0.3 + h, -0.2 - h) - f(0.3 - h, -0.2 + h)
            + f(0.3 - h, -0.2 - h))
            / (4.0 * h * h);
        assert!(
            (j.coeff(1, 1) - d_ab).abs() < 1e-6,
            "{} {}",
            j.coeff(1, 1),
            d_ab
        );
        let d_aaa = (f(0.3 + 2.0 * h, -0.2) - 2.0 * f(0.3 + h, -0.2) + 2.0 * f(0.3 - h, -0.2)
            - f(0.3 - 2.0 * h, -0.2))
            / (2.0 * h * h * h);
        assert!((j.coeff(3, 0) * 6.0 - d_aaa).abs() < 1e-4);
        assert!((j.value() - f(0.3, -0.2)).abs() < 1e-15);
        // sqrt and powi: (√(1 + a))² = 1 + a exactly to order 3.
        let s = (Series::constant(1.0) + MapJet::variable(0)).func(Func::Sqrt);
        let sq = TapeScalar::powi(s, 2);
        assert!((sq.coeff(1, 0) - 1.0).abs() < 1e-15);
        assert!(sq.coeff(2, 0).abs() < 1e-15 && sq.coeff(3, 0).abs() < 1e-15);
    }

    #[test]
    fn conjugate_and_substitution() {
        // (z + 2i z̄²)‾ = z̄ − 2i z².
        let mut p = CJet::variable(0);
        p.c[index(0, 2)] = Complex::new(0.0, 2.0);
        let q = p.conj();
        assert_eq!(q.coeff(0, 1), Complex::new(1.0, 0.0));
        assert_eq!(q.coeff(2, 0), Complex::new(0.0, -2.0));
        // p(x, y) = x y at x = a + b, y = a − b is a² − b².
        let mut xy = MapJet::constant(0.0);
        xy.c[index(1, 1)] = 1.0;
        let (a, b) = (MapJet::variable(0), MapJet::variable(1));
        let r = xy.substitute(&(a + b), &(a - b));
        assert_eq!(
            (r.coeff(2, 0), r.coeff(1, 1), r.coeff(0, 2)),
            (1.0, 0.0, -1.0)
        );
    }
}
