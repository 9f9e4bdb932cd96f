//! Linear symplectic normalisation of `H₂` and the Birkhoff normal form to order four
//! (docs/method.md §10.2–11.3).
//!
//! The quadratic part `H₂ = ½zᵀSz` (`z = (q₁, q₂, p₁, p₂)`) has the Hamiltonian matrix
//! `K = 𝕁S`, whose eigenvalues `±iω_k` solve `λ⁴ − ½tr(K²)λ² + det K = 0`. For each `ω_k` a real
//! `a_k` spans with `b_k = −Ka_k/ω_k` the invariant plane (`a_k` from the kernel of `K² + ω_k²`);
//! the Krein sign is `s_k = sign(a_kᵀSa_k)`, and the columns `c a_k`, `s_k c b_k`
//! (`c = (s_k a_kᵀ𝕁b_k)^{−½}`) form a symplectic `T` with `H₂(Tz) = Σ s_kω_k(q_k² + p_k²)/2`.
//!
//! In the complex coordinates `ξ_k = (q_k + ip_k)/√2`, `η_k = (q_k − ip_k)/√2` (bracket
//! `{ξ_k, η_k} = −i`, `I_k = ξ_kη_k`), `{H₂, ξ^aη^b} = −i⟨σ, b − a⟩ξ^aη^b` with `σ_k = s_kω_k`,
//! so the Lie generator `W₃ = Σ −i h_{ab}/⟨σ, b − a⟩ ξ^aη^b` removes every non-resonant cubic
//! term, and the quartic part becomes `H₄ + ½{H₃ + H₃ʳᵉˢ, W₃}`, whose coefficients of
//! `I₁², I₁I₂, I₂²` are `c₂₀, c₁₁, c₀₂` (the other non-resonant quartic terms are removed by a
//! `W₄` that does not change them).

use nalgebra::{Complex, Matrix4};

use super::jet::{lower_index, monomial_index, monomials, product_table, raise_table, Jet, NCOEF};

type C = Complex<f64>;

/// A complex polynomial of degree ≤ 4 in `(ξ₁, ξ₂, η₁, η₂)` (slots 0–3), truncated like a
/// [`Jet`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct CPoly {
    pub(crate) c: [C; NCOEF],
}

impl CPoly {
    fn zero() -> Self {
        CPoly {
            c: [C::new(0.0, 0.0); NCOEF],
        }
    }
    #[cfg(test)]
    fn one() -> Self {
        let mut p = Self::zero();
        p.c[0] = C::new(1.0, 0.0);
        p
    }
    fn mul(&self, o: &CPoly) -> CPoly {
        let mut out = Self::zero();
        for &(i, j, k) in product_table() {
            out.c[k as usize] += self.c[i as usize] * o.c[j as usize];
        }
        out
    }
    fn add_scaled(&mut self, o: &CPoly, s: C) {
        for (a, b) in self.c.iter_mut().zip(o.c.iter()) {
            *a += b * s;
        }
    }
    fn partial(&self, v: usize) -> CPoly {
        let mut out = Self::zero();
        let exps = monomials();
        for (k, e) in exps.iter().enumerate() {
            if let Some(l) = lower_index(v, k) {
                out.c[l] += self.c[k] * f64::from(e[v]);
            }
        }
        out
    }
    fn homogeneous(&self, d: usize) -> CPoly {
        let mut out = Self::zero();
        for (k, e) in monomials().iter().enumerate() {
            if e.iter().map(|&x| x as usize).sum::<usize>() == d {
                out.c[k] = self.c[k];
            }
        }
        out
    }
    pub(crate) fn coeff(&self, e: [u8; 4]) -> C {
        monomial_index(e).map_or(C::new(0.0, 0.0), |k| self.c[k])
    }
}

/// `{F, G} = −i Σ_k (∂F/∂ξ_k ∂G/∂η_k − ∂F/∂η_k ∂G/∂ξ_k)`.
fn bracket(f: &CPoly, g: &CPoly) -> CPoly {
    let mut out = CPoly::zero();
    let mi = C::new(0.0, -1.0);
    for k in 0..2 {
        out.add_scaled(&f.partial(k).mul(&g.partial(2 + k)), mi);
        out.add_scaled(&f.partial(2 + k).mul(&g.partial(k)), -mi);
    }
    out
}

/// The result of the linear normalisation.
#[derive(Debug, Clone)]
pub(crate) struct Normalisation {
    /// `ω₁ ≥ ω₂ > 0`.
    pub(crate) omega: [f64; 2],
    /// Krein signs.
    pub(crate) signs: [i8; 2],
    /// Columns `(q₁, q₂, p₁, p₂)` in the chart's canonical coordinates.
    pub(crate) t: Matrix4<f64>,
    /// `max |TᵀJT − J|`, a check of the construction.
    pub(crate) symplectic_defect: f64,
}

fn jmat() -> Matrix4<f64> {
    let mut j = Matrix4::zeros();
    j[(0, 2)] = 1.0;
    j[(1, 3)] = 1.0;
    j[(2, 0)] = -1.0;
    j[(3, 1)] = -1.0;
    j
}

/// The Hessian `S` of the quadratic part of `h`.
pub(crate) fn quadratic_form(h: &Jet) -> Matrix4<f64> {
    let mut s = Matrix4::zeros();
    for i in 0..4 {
        for j in 0..4 {
            let mut e = [0u8; 4];
            e[i] += 1;
            e[j] += 1;
            let c = h.coeff(e);
            s[(i, j)] = if i == j { 2.0 * c } else { c };
        }
    }
    s
}

/// The squared frequencies `ω₁² ≥ ω₂²` of `H₂ = ½zᵀSz`, from `λ⁴ − ½tr(K²)λ² + det K`; `None`
/// unless both are real and positive (linear stability with simple or double frequencies).
pub(crate) fn squared_frequencies(s: &Matrix4<f64>) -> Option<[f64; 2]> {
    let k = jmat() * s;
    let sum = -0.5 * (k * k).trace(); // ω₁² + ω₂²
    let prod = k.determinant(); // ω₁²ω₂²
    let disc = sum * sum - 4.0 * prod;
    if !(sum > 0.0 && prod > 0.0 && disc >= -1e-12 * sum * sum) {
        return None;
    }
    let r = disc.max(0.0).sqrt();
    let w1 = 0.5 * (sum + r);
    Some([w1, prod / w1])
}

/// The symplectic normalisation of `H₂ = ½zᵀSz` for distinct frequencies.
pub(crate) fn normalise(s: &Matrix4<f64>, omega2: [f64; 2]) -> Option<Normalisation> {
    let k = jmat() * s;
    let j = jmat();
    let mut t = Matrix4::zeros();
    let mut omega = [0.0; 2];
    let mut signs = [0i8; 2];
    for m in 0..2 {
        let w = omega2[m].sqrt();
        let n = k * k + Matrix4::identity() * omega2[m];
        let svd = n.svd(false, true);
        let vt = svd.v_t?;
        let imin = svd.singular_values.imin();
        let a = vt.row(imin).transpose();
        let b = -(k * a) / w;
        let sa = (a.transpose() * s * a)[(0, 0)];
        let sign = if sa > 0.0 { 1.0 } else { -1.0 };
        let ajb = (a.transpose() * j * b)[(0, 0)];
        if sign * ajb <= 0.0 {
            return None;
        }
        let c = 1.0 / (sign * ajb).sqrt();
        t.set_column(m, &(a * c));
        t.set_column(2 + m, &(b * (sign * c)));
        omega[m] = w;
        signs[m] = sign as i8;
    }
    let symplectic_defect = (t.transpose() * j * t - j).amax();
    Some(Normalisation {
        omega,
        signs,
        t,
        symplectic_defect,
    })
}

/// The Birkhoff normal form to order four.
#[derive(Debug, Clone)]
pub(crate) struct BirkhoffForm {
    /// `c₂₀, c₁₁, c₀₂`.
    pub(crate) coefficients: [f64; 3],
    /// The largest modulus of a resonant cubic coefficient (kept in the normal form).
    pub(crate) resonant_cubic: f64,
    /// The largest modulus of a resonant quartic coefficient other than `I₁², I₁I₂, I₂²`.
    pub(crate) resonant_quartic: f64,
    /// The scale of `resonant_cubic`: the largest modulus of a cubic coefficient, or
    /// `√(ω₁·h₄)` with `h₄` the largest quartic one when larger (the cubic terms can all vanish
    /// by a symmetry; `h₃²/ω` has the dimension of `h₄`).
    pub(crate) cubic_scale: f64,
    /// `max |H̃₂ − Σσ_kI_k|`, a check of the normalisation.
    pub(crate) quadratic_defect: f64,
}

/// Where the monomials of each degree start in the graded order of a [`Jet`]: degree `d` is
/// `BLOCK[d]..BLOCK[d + 1]`.
const BLOCK: [usize; 6] = [0, 1, 5, 15, 35, NCOEF];

/// The degree of monomial `k` in the graded order.
fn degree_of(k: usize) -> usize {
    BLOCK.iter().rposition(|&b| b <= k).unwrap_or(0)
}

/// `h(L(ξ, η))` in degrees 2–4, `L` the linear change of variables whose row `v` gives old
/// variable `v` as a linear form in the new ones.
///
/// Horner's scheme by degree: with `m_e = Π_v L_v^{e_v}` the images of the monomials of degree
/// ≤ 3 (each the image of its parent times one linear form), the part of degree `d` is
/// `Σ_v (Σ_e h_e m_{e − 1_v}) L_v` over the monomials `e` of degree `d` whose first variable is
/// `v`: about 2·10³ complex products where multiplying out every monomial costs 6·10⁴.
fn substitute(h: &Jet, lin: &[[C; 4]; 4]) -> CPoly {
    let zero = C::new(0.0, 0.0);
    let exps = monomials();
    let raise = raise_table();
    // m_e for the monomials of degree ≤ 3, each as its homogeneous block (at most 20 wide).
    let mut image = [[zero; 20]; BLOCK[4]];
    image[0][0] = C::new(1.0, 0.0);
    let first_var = |k: usize| exps[k].iter().position(|&x| x > 0).unwrap_or(0);
    // `p` (degree d − 1, local to its block) times `L_v`, added into `out` (degree d, local).
    let times_linear = |p: &[C], d: usize, l: &[C; 4], out: &mut [C]| {
        for (a, &pa) in p.iter().enumerate().take(BLOCK[d] - BLOCK[d - 1]) {
            if pa == zero {
                continue;
            }
            for (m, &lm) in l.iter().enumerate() {
                if let Some(r) = raise[m][BLOCK[d - 1] + a] {
                    out[usize::from(r) - BLOCK[d]] += pa * lm;
                }
            }
        }
    };
    for k in 1..BLOCK[4] {
        let d = degree_of(k);
        let v = first_var(k);
        let parent = lower_index(v, k).unwrap_or(0);
        let (before, after) = image.split_at_mut(k);
        times_linear(&before[parent], d, &lin[v], &mut after[0]);
    }
    let mut ht = CPoly::zero();
    for d in 2..=4 {
        let mut block = [zero; 35];
        for (v, l) in lin.iter().enumerate() {
            let mut q = [zero; 20];
            for k in BLOCK[d]..BLOCK[d + 1] {
                if h.c[k] == 0.0 || first_var(k) != v {
                    continue;
                }
                let parent = lower_index(v, k).unwrap_or(0);
                for (qa, &ma) in q.iter_mut().zip(&image[parent]) {
                    *qa += ma * h.c[k];
                }
            }
            times_linear(&q, d, l, &mut block);
        }
        ht.c[BLOCK[d]..BLOCK[d + 1]].copy_from_slice(&block[..BLOCK[d + 1] - BLOCK[d]]);
    }
    ht
}

/// Substitutes `z = T(q, p)` and `q = (ξ + η)/√2`, `p = −i(ξ − η)/√2` in `h` (degrees 2–4), then
/// removes the non-resonant cubic terms. A term `ξ^aη^b` is resonant when
/// `|⟨σ, b − a⟩| ≤ tol·ω₁`.
pub(crate) fn birkhoff(h: &Jet, nf: &Normalisation, tol: f64) -> BirkhoffForm {
    let r2 = std::f64::consts::FRAC_1_SQRT_2;
    let i = C::new(0.0, 1.0);
    // The old coordinates as linear forms in (ξ₁, ξ₂, η₁, η₂).
    let mut lin = [[C::new(0.0, 0.0); 4]; 4];
    for (row, l) in lin.iter_mut().enumerate() {
        for k in 0..2 {
            let tq = nf.t[(row, k)];
            let tp = nf.t[(row, 2 + k)];
            l[k] = (C::new(tq, 0.0) - i * tp) * r2;
            l[2 + k] = (C::new(tq, 0.0) + i * tp) * r2;
        }
    }
    let ht = substitute(h, &lin);
    let sigma = [
        f64::from(nf.signs[0]) * nf.omega[0],
        f64::from(nf.signs[1]) * nf.omega[1],
    ];
    let mut quadratic_defect = 0.0f64;
    for (k, e) in monomials().iter().enumerate() {
        let deg: usize = e.iter().map(|&x| x as usize).sum();
        if deg == 2 {
            let expect = if e[0] == 1 && e[2] == 1 {
                sigma[0]
            } else if e[1] == 1 && e[3] == 1 {
                sigma[1]
            } else {
                0.0
            };
            quadratic_defect = quadratic_defect.max((ht.c[k] - expect).norm());
        }
    }
    let h3 = ht.homogeneous(3);
    let h4 = ht.homogeneous(4);
    let mut w3 = CPoly::zero();
    let mut h3res = CPoly::zero();
    let mut resonant_cubic = 0.0f64;
    let mut cubic_scale = 0.0f64;
    for (k, e) in monomials().iter().enumerate() {
        if h3.c[k] == C::new(0.0, 0.0) {
            continue;
        }
        cubic_scale = cubic_scale.max(h3.c[k].norm());
        let d = sigma[0] * (f64::from(e[2]) - f64::from(e[0]))
            + sigma[1] * (f64::from(e[3]) - f64::from(e[1]));
        if d.abs() > tol * nf.omega[0] {
            w3.c[k] = -i * h3.c[k] / d;
        } else {
            h3res.c[k] = h3.c[k];
            resonant_cubic = resonant_cubic.max(h3.c[k].norm());
        }
    }
    let quartic_scale = h4.c.iter().fold(0.0f64, |m, c| m.max(c.norm()));
    let cubic_scale = cubic_scale.max((nf.omega[0] * quartic_scale).sqrt());
    let mut sum3 = h3;
    sum3.add_scaled(&h3res, C::new(1.0, 0.0));
    let mut h4n = h4;
    h4n.add_scaled(&bracket(&sum3, &w3).homogeneous(4), C::new(0.5, 0.0));
    let mut resonant_quartic = 0.0f64;
    for (k, e) in monomials().iter().enumerate() {
        let deg: usize = e.iter().map(|&x| x as usize).sum();
        if deg != 4 || (e[0] == e[2] && e[1] == e[3]) {
            continue;
        }
        let d = sigma[0] * (f64::from(e[2]) - f64::from(e[0]))
            + sigma[1] * (f64::from(e[3]) - f64::from(e[1]));
        if d.abs() <= tol * nf.omega[0] {
            resonant_quartic = resonant_quartic.max(h4n.c[k].norm());
        }
    }
    BirkhoffForm {
        coefficients: [
            h4n.coeff([2, 0, 2, 0]).re,
            h4n.coeff([1, 1, 1, 1]).re,
            h4n.coeff([0, 2, 0, 2]).re,
        ],
        resonant_cubic,
        resonant_quartic,
        cubic_scale,
        quadratic_defect,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `h(L(ξ, η))` the plain way: every monomial multiplied out as a product of powers of the
    /// linear forms.
    fn multiplied_out(h: &Jet, lin: &[[C; 4]; 4]) -> CPoly {
        let mut forms = [CPoly::zero(); 4];
        for (f, l) in forms.iter_mut().zip(lin) {
            f.c[1..5].copy_from_slice(l);
        }
        let mut out = CPoly::zero();
        for (k, e) in monomials().iter().enumerate() {
            if e.iter().map(|&x| x as usize).sum::<usize>() < 2 {
                continue;
            }
            let mut term = CPoly::one();
            for (v, &n) in e.iter().enumerate() {
                for _ in 0..n {
                    term = term.mul(&forms[v]);
                }
            }
            out.add_scaled(&term, C::new(h.c[k], 0.0));
        }
        out
    }

    #[test]
    fn horner_substitution_agrees_with_multiplying_out() {
        // A fixed pseudo-random jet and change of variables (no zero entries).
        let mut x = 0.3_f64;
        let mut next = || {
            x = (x * 997.0 + 0.123).fract();
            2.0 * x - 1.0
        };
        let mut h = Jet::constant(next());
        for c in h.c.iter_mut() {
            *c = next();
        }
        let mut lin = [[C::new(0.0, 0.0); 4]; 4];
        for row in lin.iter_mut() {
            for c in row.iter_mut() {
                *c = C::new(next(), next());
            }
        }
        let (fast, plain) = (substitute(&h, &lin), multiplied_out(&h, &lin));
        for k in 0..NCOEF {
            let want = if degree_of(k) < 2 {
                C::new(0.0, 0.0)
            } else {
                plain.c[k]
            };
            assert!(
                (fast.c[k] - want).norm() <= 1e-13 * (1.0 + want.norm()),
                "{k}"
            );
        }
    }
}
