//! A closed interval of reals with outward rounding: the number type of the certified search
//! (docs/method.md §9).
//!
//! Every operation returns an interval that contains the exact result of the operation applied
//! to every pair of points of its operands. Arithmetic (`+ − × ÷`) and `sqrt` are correctly
//! rounded in IEEE 754, so moving each endpoint one ulp outwards (`next_down`/`next_up`) encloses
//! the exact value. `exp`, `ln`, `sin`, `cos`, `tan` and `powf` come from the platform's libm,
//! which is not correctly rounded; their endpoints are moved [`LIBM_ULPS`] ulps outwards, which
//! covers the documented worst errors of glibc's, musl's and Apple's implementations (≤ 2 ulp in
//! double precision). Anything undefined on part of an operand (a division by an interval
//! containing 0, `ln` of an interval reaching 0, a NaN) gives the whole real line, which makes
//! the search that uses it undecided rather than wrong.
//!
//! Why not a crate: the well-kept interval crate for Rust (inari) requires building the whole
//! program with `-C target-cpu=haswell` and GMP/MPFR for its elementary functions; a library
//! cannot impose either on its users. This type does only what the certified search needs.

use std::ops::{Add, Mul, Neg, Sub};

/// How many ulps the results of libm functions are widened by on each side.
pub const LIBM_ULPS: u32 = 4;

/// A closed interval `[lo, hi]` (`lo ≤ hi`; both may be infinite; never NaN).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Interval {
    /// Lower endpoint.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub lo: f64,
    /// Upper endpoint.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_support::float"))]
    pub hi: f64,
}

fn down(x: f64) -> f64 {
    x.next_down()
}

fn up(x: f64) -> f64 {
    x.next_up()
}

fn down_n(mut x: f64, n: u32) -> f64 {
    for _ in 0..n {
        x = x.next_down();
    }
    x
}

fn up_n(mut x: f64, n: u32) -> f64 {
    for _ in 0..n {
        x = x.next_up();
    }
    x
}

impl Interval {
    /// The whole real line: what an undefined or overflowing operation gives.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// `[lo, hi]`; the whole line if either is NaN or `lo > hi`.
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo.is_nan() || hi.is_nan() || lo > hi {
            Self::ENTIRE
        } else {
            Interval { lo, hi }
        }
    }

    /// The point interval `[x, x]` (exact: `x` is a double).
    pub fn point(x: f64) -> Self {
        Self::new(x, x)
    }

    /// Outward-rounded result of a correctly rounded operation whose round-to-nearest endpoints
    /// are `lo`, `hi`.
    fn rounded(lo: f64, hi: f64) -> Self {
        Self::new(down(lo), up(hi))
    }

    /// The midpoint (finite for a bounded interval).
    pub fn mid(self) -> f64 {
        if self.lo == self.hi {
            return self.lo;
        }
        let m = 0.5 * self.lo + 0.5 * self.hi;
        m.clamp(self.lo, self.hi)
    }

    /// `hi − lo`, rounded up.
    pub fn width(self) -> f64 {
        up(self.hi - self.lo)
    }

    /// `max(|lo|, |hi|)`.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// Whether both endpoints are finite.
    pub fn is_bounded(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// Whether `x` lies in the interval.
    pub fn contains(self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether `self` lies in the interior of `other`.
    pub fn interior_of(self, other: Interval) -> bool {
        other.lo < self.lo && self.hi < other.hi
    }

    /// Whether `self ⊆ other`.
    pub fn subset_of(self, other: Interval) -> bool {
        other.lo <= self.lo && self.hi <= other.hi
    }

    /// `self ∩ other`, `None` if empty.
    pub fn intersect(self, other: Interval) -> Option<Interval> {
        let (lo, hi) = (self.lo.max(other.lo), self.hi.min(other.hi));
        (lo <= hi).then_some(Interval { lo, hi })
    }

    /// The smallest interval containing both.
    pub fn hull(self, other: Interval) -> Interval {
        Interval {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// `[lo, mid]` and `[mid, hi]`.
    pub fn bisect(self) -> (Interval, Interval) {
        let m = self.mid();
        (Interval::new(self.lo, m), Interval::new(m, self.hi))
    }

    /// `x²` (tighter than `x·x`, which ignores that both factors are the same number).
    pub fn sqr(self) -> Interval {
        let (a, b) = (self.lo.abs(), self.hi.abs());
        let (small, large) = if self.contains(0.0) {
            (0.0, a.max(b))
        } else {
            (a.min(b), a.max(b))
        };
        let lo = if small == 0.0 {
            0.0
        } else {
            down(small * small).max(0.0)
        };
        Interval::new(lo, up(large * large))
    }

    /// `1 / x`; the whole line if `0 ∈ x`.
    pub fn recip(self) -> Interval {
        if self.contains(0.0) {
            return Self::ENTIRE;
        }
        Self::rounded(1.0 / self.hi, 1.0 / self.lo)
    }

    /// `x^n` for an integer `n`.
    pub fn powi(self, n: i32) -> Interval {
        match n {
            0 => Interval::point(1.0),
            1 => self,
            2 => self.sqr(),
            n if n < 0 => self.powi_pos(n.unsigned_abs()).recip(),
            n => self.powi_pos(n as u32),
        }
    }

    /// `x^n`, `n ≥ 1`, by squaring (each step encloses, so the result does).
    fn powi_pos(self, n: u32) -> Interval {
        if n == 1 {
            return self;
        }
        let half = self.powi_pos(n / 2).sqr();
        if n.is_multiple_of(2) {
            half
        } else {
            half * self
        }
    }

    /// `√x` on the part of `x` where it is defined; the whole line if `x` reaches below 0.
    pub fn sqrt(self) -> Interval {
        if self.lo < 0.0 {
            return Self::ENTIRE;
        }
        Interval::new(down(self.lo.sqrt()).max(0.0), up(self.hi.sqrt()))
    }

    /// A monotone increasing libm function applied to the endpoints.
    fn increasing(self, f: fn(f64) -> f64) -> Interval {
        Interval::new(down_n(f(self.lo), LIBM_ULPS), up_n(f(self.hi), LIBM_ULPS))
    }

    /// `eˣ`.
    pub fn exp(self) -> Interval {
        let r = self.increasing(f64::exp);
        Interval::new(r.lo.max(0.0), r.hi)
    }

    /// `ln x`; the whole line unless `x > 0`.
    pub fn ln(self) -> Interval {
        if self.lo <= 0.0 {
            return Self::ENTIRE;
        }
        self.increasing(f64::ln)
    }

    /// `xʸ = exp(y ln x)` for `x > 0`.
    pub fn powf(self, y: Interval) -> Interval {
        (y * self.ln()).exp()
    }

    /// `|x|`.
    pub fn abs(self) -> Interval {
        if self.lo >= 0.0 {
            self
        } else if self.hi <= 0.0 {
            -self
        } else {
            Interval::new(0.0, self.mag())
        }
    }

    /// `sign(x)` with `sign(0) = 0`.
    pub fn sign(self) -> Interval {
        let s = |x: f64| {
            if x == 0.0 {
                0.0
            } else {
                x.signum()
            }
        };
        Interval::new(s(self.lo), s(self.hi))
    }

    /// `sin x`.
    pub fn sin(self) -> Interval {
        // sin x = cos(x − π/2); the shift is enclosed by the interval of π/2.
        (self - Interval::half_pi()).cos()
    }

    /// `cos x`: the endpoints' values, plus ±1 where a multiple of π (an extremum) may lie in
    /// `x` (decided conservatively: an extremum that might be inside is taken as inside).
    pub fn cos(self) -> Interval {
        if !self.is_bounded() || self.width() >= 6.0 || self.mag() > 1e15 {
            return Interval::new(-1.0, 1.0);
        }
        let widen = |r: Interval| Interval::new(r.lo.max(-1.0), r.hi.min(1.0));
        let (a, b) = (self.lo.cos(), self.hi.cos());
        let mut lo = down_n(a.min(b), LIBM_ULPS);
        let mut hi = up_n(a.max(b), LIBM_ULPS);
        // Extrema at kπ: k from ⌊lo/π⌋ − 1 to ⌈hi/π⌉ + 1, each tested with an enclosure of kπ.
        let pi = Interval::pi();
        let k0 = (self.lo / std::f64::consts::PI).floor() - 1.0;
        let k1 = (self.hi / std::f64::consts::PI).ceil() + 1.0;
        let mut k = k0;
        while k <= k1 {
            let kpi = Interval::point(k) * pi;
            if kpi.hi >= self.lo && kpi.lo <= self.hi {
                if (k as i64).rem_euclid(2) == 0 {
                    hi = 1.0;
                } else {
                    lo = -1.0;
                }
            }
            k += 1.0;
        }
        widen(Interval::new(lo, hi))
    }

    /// `tan x`; the whole line where a pole (π/2 + kπ) may lie in `x`.
    pub fn tan(self) -> Interval {
        if !self.is_bounded() || self.width() >= 3.0 || self.mag() > 1e15 {
            return Self::ENTIRE;
        }
        let pi = Interval::pi();
        let k0 = ((self.lo - std::f64::consts::FRAC_PI_2) / std::f64::consts::PI).floor() - 1.0;
        let k1 = ((self.hi - std::f64::consts::FRAC_PI_2) / std::f64::consts::PI).ceil() + 1.0;
        let mut k = k0;
        while k <= k1 {
            let pole = Interval::half_pi() + Interval::point(k) * pi;
            if pole.hi >= self.lo && pole.lo <= self.hi {
                return Self::ENTIRE;
            }
            k += 1.0;
        }
        self.increasing(f64::tan)
    }

    /// An enclosure of π.
    pub fn pi() -> Interval {
        let p = std::f64::consts::PI;
        Interval::new(down(p), up(p))
    }

    /// An enclosure of π/2.
    pub fn half_pi() -> Interval {
        let p = std::f64::consts::FRAC_PI_2;
        Interval::new(down(p), up(p))
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval::rounded(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval::rounded(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        // 0 · ∞ would be NaN; a factor that is exactly 0 gives 0.
        if (self.lo == 0.0 && self.hi == 0.0) || (o.lo == 0.0 && o.hi == 0.0) {
            return Interval::point(0.0);
        }
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return Interval::ENTIRE;
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::rounded(lo, hi)
    }
}

impl std::ops::Div for Interval {
    type Output = Interval;
    // x / y = x · (1/y): both enclose, so the product encloses the quotient.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn div(self, o: Interval) -> Interval {
        self * o.recip()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points spread over an interval, endpoints included.
    fn samples(x: Interval) -> Vec<f64> {
        (0..=16)
            .map(|k| (x.lo + (x.hi - x.lo) * f64::from(k) / 16.0).clamp(x.lo, x.hi))
            .collect()
    }

    fn encloses(r: Interval, v: f64) -> bool {
        v.is_nan() || r.contains(v)
    }

    #[test]
    fn every_operation_encloses_sampled_values() {
        let boxes = [
            Interval::new(-2.5, -0.3),
            Interval::new(-0.7, 1.9),
            Interval::new(0.1, 0.2),
            Interval::new(3.0, 9.5),
            Interval::new(-40.0, 40.0),
            Interval::new(1e-300, 1e-299),
        ];
        for &x in &boxes {
            for &y in &boxes {
                for a in samples(x) {
                    for b in samples(y) {
                        assert!(encloses(x + y, a + b));
                        assert!(encloses(x - y, a - b));
                        assert!(encloses(x * y, a * b));
                        if !y.contains(0.0) {
                            assert!(encloses(x / y, a / b), "{x:?} / {y:?} at {a}, {b}");
                        }
                        if x.lo > 0.0 {
                            assert!(encloses(x.powf(y), a.powf(b)));
                        }
                    }
                }
            }
            for a in samples(x) {
                assert!(encloses(x.sqr(), a * a));
                for n in [-3, -2, 3, 4, 5] {
                    if !(n < 0 && x.contains(0.0)) {
                        assert!(encloses(x.powi(n), a.powi(n)), "{x:?}^{n} at {a}");
                    }
                }
                assert!(encloses(x.exp(), a.exp()));
                assert!(encloses(x.sin(), a.sin()), "sin {x:?} at {a}");
                assert!(encloses(x.cos(), a.cos()), "cos {x:?} at {a}");
                assert!(encloses(x.tan(), a.tan()), "tan {x:?} at {a}");
                assert!(encloses(x.abs(), a.abs()));
                if x.lo > 0.0 {
                    assert!(encloses(x.sqrt(), a.sqrt()));
                    assert!(encloses(x.ln(), a.ln()));
                }
            }
        }
    }

    #[test]
    fn extrema_of_cos_and_sin_are_included() {
        // cos over [−0.1, 0.1] reaches 1 at 0, which no endpoint shows.
        assert_eq!(Interval::new(-0.1, 0.1).cos().hi, 1.0);
        assert_eq!(Interval::new(3.0, 3.3).cos().lo, -1.0);
        assert_eq!(Interval::new(1.5, 1.6).sin().hi, 1.0);
        // A pole of tan inside: the whole line.
        assert_eq!(Interval::new(1.5, 1.6).tan(), Interval::ENTIRE);
    }

    #[test]
    fn undefined_operations_give_the_whole_line() {
        assert_eq!(Interval::new(-1.0, 1.0).recip(), Interval::ENTIRE);
        assert_eq!(Interval::new(-1.0, 1.0).ln(), Interval::ENTIRE);
        assert_eq!(Interval::new(-1.0, 1.0).sqrt(), Interval::ENTIRE);
        assert_eq!(Interval::new(f64::NAN, 1.0), Interval::ENTIRE);
        assert_eq!(
            Interval::point(0.0) * Interval::ENTIRE,
            Interval::point(0.0)
        );
    }
}
