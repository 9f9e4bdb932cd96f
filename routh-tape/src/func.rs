//! The elementary functions of the DSL: the one list of their names and their `f64` meaning.

/// A unary elementary function of the Lagrangian DSL (`x.sqrt()`, `x.sin()`, …), and `sign`,
/// the derivative of `abs`, which differentiation introduces.
///
/// This is the one definition: the symbolic engine, the derive's lowering, the tape and the
/// runtime all use it.
///
/// ```
/// use routh_tape::Func;
/// assert_eq!(Func::from_name("ln"), Some(Func::Ln));
/// assert_eq!(Func::Ln.name(), "ln");
/// assert_eq!(Func::from_name("log"), None);
/// assert_eq!(Func::Sqrt.apply(4.0), 2.0);
/// ```
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub enum Func {
    /// `√x`.
    Sqrt,
    /// `sin x`.
    Sin,
    /// `cos x`.
    Cos,
    /// `tan x`.
    Tan,
    /// `eˣ`.
    Exp,
    /// `ln x`.
    Ln,
    /// `|x|`.
    Abs,
    /// The sign function (derivative of `abs`); `signum` with `sign(0) = 0` (see [`sign`]).
    Sign,
}

impl Func {
    /// Every function, in declaration order.
    pub const ALL: [Func; 8] = [
        Func::Sqrt,
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Exp,
        Func::Ln,
        Func::Abs,
        Func::Sign,
    ];

    /// The function applied to a number.
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Abs => x.abs(),
            Func::Sign => sign(x),
        }
    }

    /// The name of the function in the DSL, which is also its method name in Rust's `f64` API
    /// (except `sign`, see [`sign`]).
    pub const fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Abs => "abs",
            Func::Sign => "sign",
        }
    }

    /// Whether a model's text may call it as a method (`x.sqrt()`): all but [`Func::Sign`],
    /// which only differentiation introduces.
    pub const fn is_dsl_method(self) -> bool {
        !matches!(self, Func::Sign)
    }

    /// The function of a DSL name, the inverse of [`Func::name`].
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.into_iter().find(|f| f.name() == name)
    }
}

/// `sign(x)` with `sign(0) = 0` (and `sign(NaN) = NaN`): the derivative of `abs`.
///
/// ```
/// assert_eq!(routh_tape::sign(-3.0), -1.0);
/// assert_eq!(routh_tape::sign(0.0), 0.0);
/// assert_eq!(routh_tape::sign(-0.0), 0.0);
/// ```
#[inline]
pub fn sign(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x.signum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_are_distinct() {
        for f in Func::ALL {
            assert_eq!(Func::from_name(f.name()), Some(f));
        }
        let mut names: Vec<_> = Func::ALL.iter().map(|f| f.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Func::ALL.len());
    }

    #[test]
    fn apply_matches_std() {
        let x = 0.7f64;
        assert_eq!(Func::Sin.apply(x), x.sin());
        assert_eq!(Func::Tan.apply(x), x.tan());
        assert_eq!(Func::Ln.apply(x), x.ln());
        assert!(Func::Sign.apply(f64::NAN).is_nan());
        assert_eq!(Func::Sign.apply(-2.0), -1.0);
    }
}
