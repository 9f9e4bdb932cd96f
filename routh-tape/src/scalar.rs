//! The number types a tape can be evaluated with.

use crate::Func;

/// A number type a [`Tape`](crate::Tape) can be evaluated with: `f64`, the interval type of
/// `routh::certify`, or a truncated Taylor series (a jet) to get higher derivatives.
///
/// Implementations must give each operation its meaning over the reals (enclosures for
/// intervals): the tape is the derive's expression DAG, and nothing in it assumes a particular
/// scalar.
pub trait TapeScalar:
    Copy + std::ops::Add<Output = Self> + std::ops::Mul<Output = Self> + std::ops::Neg<Output = Self>
{
    /// The exact value of a double.
    fn from_f64(x: f64) -> Self;
    /// `1 / x`.
    fn recip(self) -> Self;
    /// `x^n`.
    fn powi(self, n: i32) -> Self;
    /// `x^y`.
    fn powf(self, y: Self) -> Self;
    /// An elementary function.
    fn func(self, f: Func) -> Self;
}

impl TapeScalar for f64 {
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn recip(self) -> Self {
        1.0 / self
    }
    #[inline]
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    #[inline]
    fn powf(self, y: Self) -> Self {
        f64::powf(self, y)
    }
    #[inline]
    fn func(self, f: Func) -> Self {
        f.apply(self)
    }
}
