//! The charts of the sphere on the faces of the cube, and the field `F = (t_a, t_b)` of a chart
//! box with its Jacobian, in interval arithmetic from the certification tape.

use super::interval::Interval;
use super::RouthTape;

/// A face of the cube: `x = σe_k + u e_a + v e_b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Face {
    pub(super) k: usize,
    pub(super) sigma: f64,
}

impl Face {
    pub(super) fn all() -> [Face; 6] {
        std::array::from_fn(|i| Face {
            k: i / 2,
            sigma: if i % 2 == 0 { 1.0 } else { -1.0 },
        })
    }
    /// The two free axes `(a, b)`.
    pub(super) fn ab(self) -> (usize, usize) {
        ((self.k + 1) % 3, (self.k + 2) % 3)
    }
    /// `γ(u, v)` and `1/r`, as intervals.
    pub(super) fn gamma(self, u: Interval, v: Interval) -> ([Interval; 3], Interval) {
        let one = Interval::point(1.0);
        let r_inv = (one + u.sqr() + v.sqr()).sqrt().recip();
        let (a, b) = self.ab();
        let mut g = [Interval::point(0.0); 3];
        g[self.k] = Interval::point(self.sigma) * r_inv;
        g[a] = u * r_inv;
        g[b] = v * r_inv;
        (g, r_inv)
    }
    /// The chart coordinates `(u, v) = σ(γ_a, γ_b)/γ_k` of a box of γ (`None` if `γ_k` may vanish
    /// or has the other sign).
    pub(super) fn coordinates(self, g: &[Interval; 3]) -> Option<(Interval, Interval)> {
        let gk = Interval::point(self.sigma) * g[self.k];
        if gk.lo <= 0.0 {
            return None;
        }
        let (a, b) = self.ab();
        Some((g[a] / gk, g[b] / gk))
    }
}

/// A box of a chart.
#[derive(Debug, Clone, Copy)]
pub(super) struct ChartBox {
    pub(super) face: Face,
    pub(super) u: Interval,
    pub(super) v: Interval,
}

/// `F` and (optionally) `F'` over a chart box.
pub(super) struct Field {
    pub(super) f: [Interval; 2],
    pub(super) df: Option<[[Interval; 2]; 2]>,
}

pub(super) fn dot(a: &[Interval; 3], b: &[Interval; 3]) -> Interval {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The evaluator: the tape, `p_ψ` and a scratch buffer.
pub(super) struct Evaluator<'a> {
    pub(super) tape: &'a RouthTape,
    pub(super) p: Interval,
    pub(super) scratch: Vec<Interval>,
}

impl Evaluator<'_> {
    /// `F = (t_a, t_b)` over the box, and `F'` if `jacobian`.
    pub(super) fn field(&mut self, b: &ChartBox, jacobian: bool) -> Field {
        let (gamma, r_inv) = b.face.gamma(b.u, b.v);
        let (g, h) = self.tape.eval(gamma, self.p, &mut self.scratch);
        let gg = dot(&g, &gamma);
        let (ia, ib) = b.face.ab();
        let t = |i: usize| g[i] - gg * gamma[i];
        let f = [t(ia), t(ib)];
        if !jacobian {
            return Field { f, df: None };
        }
        // dt/dγ = H − γ(Hγ + g)ᵀ − (g·γ)I.
        let w: [Interval; 3] = std::array::from_fn(|j| dot(&h[j], &gamma) + g[j]);
        let dt = |i: usize, j: usize| {
            let x = h[i][j] - gamma[i] * w[j];
            if i == j {
                x - gg
            } else {
                x
            }
        };
        // dγ/du = (e_a − γγ_a)/r, dγ/dv = (e_b − γγ_b)/r.
        let dgamma = |c: usize| -> [Interval; 3] {
            std::array::from_fn(|j| {
                let e = if j == c {
                    Interval::point(1.0)
                } else {
                    Interval::point(0.0)
                };
                (e - gamma[j] * gamma[c]) * r_inv
            })
        };
        let (du, dv) = (dgamma(ia), dgamma(ib));
        let row = |i: usize| -> [Interval; 2] {
            let d: [Interval; 3] = std::array::from_fn(|j| dt(i, j));
            [dot(&d, &du), dot(&d, &dv)]
        };
        Field {
            f,
            df: Some([row(ia), row(ib)]),
        }
    }
}
