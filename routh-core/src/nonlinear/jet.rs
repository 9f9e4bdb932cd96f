//! Truncated multivariate Taylor jets: polynomials of degree ≤ [`ORDER`] in [`NVARS`] variables,
//! with the arithmetic of truncated power series. Evaluating an expression with jets whose
//! linear parts are seeded (`Jet::variable`) gives its Taylor expansion to order four at the
//! point, exactly up to round-off: this is how the nonlinear test gets the third and fourth
//! derivatives of the Routh function from the model's own expression DAG, without finite
//! differences (docs/method.md §10).
//!
//! Coefficients are stored densely, indexed by the monomials of degree ≤ 4 in graded order
//! ([`monomials`]); products run over a precomputed list of the 495 index pairs whose degrees add
//! up to at most 4. No allocation per operation.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};
use std::sync::OnceLock;

use crate::certify::{Func, TapeScalar};

/// Number of variables of a jet.
pub const NVARS: usize = 4;
/// Truncation order of a jet.
pub const ORDER: usize = 4;
/// Number of monomials of degree ≤ [`ORDER`] in [`NVARS`] variables: C(8, 4) = 70.
pub const NCOEF: usize = 70;

/// Exponents of one monomial.
pub type Exponents = [u8; NVARS];

struct Tables {
    exps: [Exponents; NCOEF],
    /// `(i, j, k)`: monomial i times monomial j is monomial k.
    products: Vec<(u8, u8, u8)>,
    /// `products` gathered by result, for [`Jet`]'s product.
    gathered: Gathered,
    /// The same for the products of the monomials in `x₀, x₁` alone (70 of the 495).
    gathered01: Gathered,
    /// Whether each monomial has `x₂` or `x₃`.
    with23: [bool; NCOEF],
    /// `lower[v][k]`: the index of monomial k divided by variable v (when its exponent is ≥ 1).
    lower: [[Option<u8>; NCOEF]; NVARS],
    /// `raise[v][k]`: the index of monomial k times variable v (when of degree < 4).
    raise: [[Option<u8>; NCOEF]; NVARS],
}

/// A product table gathered by result: for each monomial `k` in increasing order, the pairs
/// `(i, j)` whose product it is, in the order of the table (so that each coefficient of a
/// product is summed in the same order, one accumulator per coefficient).
struct Gathered {
    pairs: Vec<(u8, u8)>,
    /// `(k, end)`: the pairs of `k` end at `end` and start at the previous end.
    ends: Vec<(u8, u16)>,
}

impl Gathered {
    fn new(products: impl Iterator<Item = (u8, u8, u8)>) -> Self {
        let mut by_k: Vec<(u8, u8, u8)> = products.collect();
        by_k.sort_by_key(|&(_, _, k)| k); // stable: the table's order within each k
        let mut ends: Vec<(u8, u16)> = Vec::new();
        for (n, &(_, _, k)) in by_k.iter().enumerate() {
            match ends.last_mut() {
                Some((last, end)) if *last == k => *end = n as u16 + 1,
                _ => ends.push((k, n as u16 + 1)),
            }
        }
        Gathered {
            pairs: by_k.iter().map(|&(i, j, _)| (i, j)).collect(),
            ends,
        }
    }

    /// The product of the jets with coefficients `a` and `b`.
    fn product(&self, a: &[f64; NCOEF], b: &[f64; NCOEF]) -> [f64; NCOEF] {
        let mut out = [0.0; NCOEF];
        let mut start = 0;
        for &(k, end) in &self.ends {
            let end = usize::from(end);
            let mut acc = 0.0;
            for &(i, j) in &self.pairs[start..end] {
                acc += a[usize::from(i)] * b[usize::from(j)];
            }
            out[usize::from(k)] = acc;
            start = end;
        }
        out
    }
}

fn degree(e: &Exponents) -> usize {
    e.iter().map(|&x| x as usize).sum()
}

fn tables() -> &'static Tables {
    static T: OnceLock<Tables> = OnceLock::new();
    T.get_or_init(|| {
        let mut exps = [[0u8; NVARS]; NCOEF];
        let mut n = 0;
        for d in 0..=ORDER {
            // Lexicographically decreasing exponents within each degree.
            for a in (0..=d).rev() {
                for b in (0..=d - a).rev() {
                    for c in (0..=d - a - b).rev() {
                        exps[n] = [a as u8, b as u8, c as u8, (d - a - b - c) as u8];
                        n += 1;
                    }
                }
            }
        }
        debug_assert_eq!(n, NCOEF);
        let find = |e: &Exponents| exps.iter().position(|x| x == e);
        let mut products = Vec::new();
        for i in 0..NCOEF {
            for j in 0..NCOEF {
                if degree(&exps[i]) + degree(&exps[j]) <= ORDER {
                    let mut e = exps[i];
                    for v in 0..NVARS {
                        e[v] += exps[j][v];
                    }
                    if let Some(k) = find(&e) {
                        products.push((i as u8, j as u8, k as u8));
                    }
                }
            }
        }
        let in01 = |e: &Exponents| e[2] == 0 && e[3] == 0;
        let gathered = Gathered::new(products.iter().copied());
        let gathered01 = Gathered::new(
            products
                .iter()
                .copied()
                .filter(|&(i, j, _)| in01(&exps[i as usize]) && in01(&exps[j as usize])),
        );
        let with23 = exps.map(|e| !in01(&e));
        let mut lower = [[None; NCOEF]; NVARS];
        let mut raise = [[None; NCOEF]; NVARS];
        for v in 0..NVARS {
            for k in 0..NCOEF {
                let e = exps[k];
                if e[v] > 0 {
                    let mut f = e;
                    f[v] -= 1;
                    lower[v][k] = find(&f).map(|x| x as u8);
                }
                if degree(&e) < ORDER {
                    let mut f = e;
                    f[v] += 1;
                    raise[v][k] = find(&f).map(|x| x as u8);
                }
            }
        }
        Tables {
            exps,
            products,
            gathered,
            gathered01,
            with23,
            lower,
            raise,
        }
    })
}

/// The exponents of the monomials, in the order of the coefficients of a [`Jet`]: degree 0,
/// then the 4 of degree 1 (`x₀, x₁, x₂, x₃`), then 10 of degree 2, 20 of degree 3, 35 of degree 4.
pub fn monomials() -> &'static [Exponents; NCOEF] {
    &tables().exps
}

/// The index of the monomial with exponents `e` (degree ≤ 4), if any.
pub fn monomial_index(e: Exponents) -> Option<usize> {
    monomials().iter().position(|x| *x == e)
}

pub(crate) fn product_table() -> &'static [(u8, u8, u8)] {
    &tables().products
}

pub(crate) fn lower_index(v: usize, k: usize) -> Option<usize> {
    tables().lower[v][k].map(usize::from)
}

/// `raise_table()[v][k]`: [`raise_index`]`(v, k)` as stored.
pub(crate) fn raise_table() -> &'static [[Option<u8>; NCOEF]; NVARS] {
    &tables().raise
}

pub(crate) fn raise_index(v: usize, k: usize) -> Option<usize> {
    tables().raise[v][k].map(usize::from)
}

/// A polynomial of degree ≤ 4 in 4 variables with the arithmetic of power series truncated
/// after order 4: the Taylor jet of a function at a point.
///
/// ```
/// use routh_core::nonlinear::Jet;
/// // f(x, y) = exp(x)·sin(y) at (0, 0): the coefficient of x y is ∂²f/∂x∂y = 1.
/// let (x, y) = (Jet::variable(0.0, 0), Jet::variable(0.0, 1));
/// let f = x.exp() * y.sin();
/// assert!((f.coeff([1, 1, 0, 0]) - 1.0).abs() < 1e-15);
/// // and of x y³: 1·(−1/3!); degree 5 and above is truncated.
/// assert!((f.coeff([1, 3, 0, 0]) + 1.0 / 6.0).abs() < 1e-15);
/// assert_eq!(f.coeff([2, 3, 0, 0]), 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Jet {
    /// Taylor coefficients, in the order of [`monomials`].
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float::array"))]
    pub c: [f64; NCOEF],
}

impl Default for Jet {
    fn default() -> Self {
        Jet::constant(0.0)
    }
}

impl Jet {
    /// The constant `a`.
    pub fn constant(a: f64) -> Self {
        let mut c = [0.0; NCOEF];
        c[0] = a;
        Jet { c }
    }
    /// The variable `x_i` at the value `a`: `a + x_i`.
    pub fn variable(a: f64, i: usize) -> Self {
        let mut j = Jet::constant(a);
        j.c[1 + i] = 1.0;
        j
    }
    /// The value at the point (the constant term).
    pub fn value(&self) -> f64 {
        self.c[0]
    }
    /// The Taylor coefficient of the monomial with exponents `e` (0 for a degree above 4), that
    /// is `∂^|e| f / ∂x^e` divided by `e₀! e₁! e₂! e₃!`.
    pub fn coeff(&self, e: Exponents) -> f64 {
        monomial_index(e).map_or(0.0, |k| self.c[k])
    }
    /// The partial derivative `∂^|e| f / ∂x^e` at the point.
    pub fn derivative(&self, e: Exponents) -> f64 {
        let fact: f64 = e
            .iter()
            .map(|&k| (1..=k).map(f64::from).product::<f64>())
            .product();
        self.coeff(e) * fact
    }
    /// The homogeneous part of degree `d`.
    pub fn homogeneous(&self, d: usize) -> Jet {
        let mut out = Jet::constant(0.0);
        for (k, e) in monomials().iter().enumerate() {
            if degree(e) == d {
                out.c[k] = self.c[k];
            }
        }
        out
    }
    /// `∂f/∂x_v` as a jet (exact to order 3; its order-4 part is zero).
    pub fn partial(&self, v: usize) -> Jet {
        let mut out = Jet::constant(0.0);
        let exps = monomials();
        for (k, e) in exps.iter().enumerate() {
            if let Some(l) = lower_index(v, k) {
                out.c[l] += self.c[k] * f64::from(e[v]);
            }
        }
        out
    }
    /// The antiderivative in `x_v` vanishing at `x_v = 0` (terms of degree above 4 dropped).
    pub fn integrate(&self, v: usize) -> Jet {
        let mut out = Jet::constant(0.0);
        let exps = monomials();
        for (k, e) in exps.iter().enumerate() {
            if let Some(r) = raise_index(v, k) {
                out.c[r] += self.c[k] / (f64::from(e[v]) + 1.0);
            }
        }
        out
    }
    /// `Σ_k d[k]/k! · (x − a)^k` with `a` the value: a scalar function with derivatives `d` at `a`
    /// composed with the jet.
    pub fn compose(&self, d: [f64; ORDER + 1]) -> Jet {
        let mut h = *self;
        h.c[0] = 0.0;
        let mut r = Jet::constant(d[4] / 24.0);
        r = r * h + d[3] / 6.0;
        r = r * h + d[2] / 2.0;
        r = r * h + d[1];
        r = r * h + d[0];
        r
    }
    /// `x^r` for a real exponent (derivatives `r(r−1)…(r−k+1) a^{r−k}`).
    pub fn powf_const(&self, r: f64) -> Jet {
        self.compose(power_derivatives(self.value(), r))
    }
    /// `x^n` for an integer exponent.
    pub fn powi(&self, n: i32) -> Jet {
        if n >= 0 {
            // Repeated squaring keeps x^n exact at a = 0.
            let mut out = Jet::constant(1.0);
            let mut base = *self;
            let mut k = n;
            while k > 0 {
                if k & 1 == 1 {
                    out = out * base;
                }
                k >>= 1;
                if k > 0 {
                    base = base * base;
                }
            }
            out
        } else {
            self.powi(-n).recip()
        }
    }
    /// `1/x`.
    pub fn recip(&self) -> Jet {
        let a = self.value();
        let r = 1.0 / a;
        self.compose([
            r,
            -r * r,
            2.0 * r.powi(3),
            -6.0 * r.powi(4),
            24.0 * r.powi(5),
        ])
    }
    /// `√x`.
    pub fn sqrt(&self) -> Jet {
        self.powf_const(0.5)
    }
    /// `sin x`.
    pub fn sin(&self) -> Jet {
        let (s, c) = self.value().sin_cos();
        self.compose([s, c, -s, -c, s])
    }
    /// `cos x`.
    pub fn cos(&self) -> Jet {
        let (s, c) = self.value().sin_cos();
        self.compose([c, -s, -c, s, c])
    }
    /// `tan x`.
    pub fn tan(&self) -> Jet {
        let t = self.value().tan();
        let t2 = 1.0 + t * t;
        self.compose([
            t,
            t2,
            2.0 * t * t2,
            2.0 * t2 * (1.0 + 3.0 * t * t),
            8.0 * t * t2 * (2.0 + 3.0 * t * t),
        ])
    }
    /// `exp x`.
    pub fn exp(&self) -> Jet {
        let e = self.value().exp();
        self.compose([e; ORDER + 1])
    }
    /// `ln x`.
    pub fn ln(&self) -> Jet {
        let a = self.value();
        let r = 1.0 / a;
        self.compose([a.ln(), r, -r * r, 2.0 * r.powi(3), -6.0 * r.powi(4)])
    }
    /// `|x|` (its jet at `a ≠ 0`; at 0 the derivatives are taken as those of `sign(0)·x = 0`).
    pub fn abs(&self) -> Jet {
        *self * sign(self.value())
    }
    /// `sign x` (locally constant).
    pub fn sign(&self) -> Jet {
        Jet::constant(sign(self.value()))
    }
    /// The largest absolute value of a coefficient of degree `d`.
    pub fn max_abs_of_degree(&self, d: usize) -> f64 {
        monomials()
            .iter()
            .zip(self.c.iter())
            .filter(|(e, _)| degree(e) == d)
            .fold(0.0, |m, (_, c)| m.max(c.abs()))
    }
}

/// The derivatives `r(r−1)…(r−k+1) a^{r−k}`, `k < K`, of `x^r` at `a` (exact zeros once the
/// falling factorial vanishes, so that `x²` stays a polynomial at `a = 0`).
pub(crate) fn power_derivatives<const K: usize>(a: f64, r: f64) -> [f64; K] {
    let mut d = [0.0; K];
    let mut fall = 1.0;
    for (k, dk) in d.iter_mut().enumerate() {
        *dk = if fall == 0.0 {
            0.0
        } else {
            fall * a.powf(r - k as f64)
        };
        fall *= r - k as f64;
    }
    d
}

fn sign(a: f64) -> f64 {
    if a == 0.0 {
        0.0
    } else {
        a.signum()
    }
}

impl Add for Jet {
    type Output = Jet;
    fn add(mut self, o: Jet) -> Jet {
        for (a, b) in self.c.iter_mut().zip(o.c.iter()) {
            *a += b;
        }
        self
    }
}

impl AddAssign for Jet {
    fn add_assign(&mut self, o: Jet) {
        *self = *self + o;
    }
}

impl Add<f64> for Jet {
    type Output = Jet;
    fn add(mut self, o: f64) -> Jet {
        self.c[0] += o;
        self
    }
}

impl Sub for Jet {
    type Output = Jet;
    fn sub(mut self, o: Jet) -> Jet {
        for (a, b) in self.c.iter_mut().zip(o.c.iter()) {
            *a -= b;
        }
        self
    }
}

impl Sub<f64> for Jet {
    type Output = Jet;
    fn sub(mut self, o: f64) -> Jet {
        self.c[0] -= o;
        self
    }
}

impl Neg for Jet {
    type Output = Jet;
    fn neg(mut self) -> Jet {
        for a in self.c.iter_mut() {
            *a = -*a;
        }
        self
    }
}

impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        // A constant factor (a parameter, a number of the tape) is a scaling: 70 products
        // instead of the table's 495.
        if o.c[1..].iter().all(|&c| c == 0.0) {
            return self * o.c[0];
        }
        if self.c[1..].iter().all(|&c| c == 0.0) {
            return o * self.c[0];
        }
        // Both in x₀, x₁ alone (the chart's position variables: the jets of γ, Ω and of the
        // Routh function there): 70 products.
        let t = tables();
        // Without early exit, which vectorises: a NaN takes the general table.
        let in01 = |a: &Jet| {
            !a.c.iter()
                .zip(&t.with23)
                .fold(false, |any, (&c, &m)| any | (m & (c != 0.0)))
        };
        let table = if in01(&self) && in01(&o) {
            &t.gathered01
        } else {
            &t.gathered
        };
        Jet {
            c: table.product(&self.c, &o.c),
        }
    }
}

impl Mul<f64> for Jet {
    type Output = Jet;
    fn mul(mut self, o: f64) -> Jet {
        for a in self.c.iter_mut() {
            *a *= o;
        }
        self
    }
}

impl Mul<Jet> for f64 {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        o * self
    }
}

impl Div for Jet {
    type Output = Jet;
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn div(self, o: Jet) -> Jet {
        self * o.recip()
    }
}

impl Div<f64> for Jet {
    type Output = Jet;
    fn div(self, o: f64) -> Jet {
        self * (1.0 / o)
    }
}

impl TapeScalar for Jet {
    fn from_f64(x: f64) -> Self {
        Jet::constant(x)
    }
    fn recip(self) -> Self {
        Jet::recip(&self)
    }
    fn powi(self, n: i32) -> Self {
        Jet::powi(&self, n)
    }
    fn powf(self, y: Self) -> Self {
        // x^y = exp(y ln x); a constant exponent keeps x^r defined for x ≤ 0 where it is.
        if y.c[1..].iter().all(|&c| c == 0.0) {
            self.powf_const(y.value())
        } else {
            (y * self.ln()).exp()
        }
    }
    fn func(self, f: Func) -> Self {
        match f {
            Func::Sqrt => self.sqrt(),
            Func::Sin => self.sin(),
            Func::Cos => self.cos(),
            Func::Tan => self.tan(),
            Func::Exp => self.exp(),
            Func::Ln => self.ln(),
            Func::Abs => self.abs(),
            Func::Sign => self.sign(),
        }
    }
}
