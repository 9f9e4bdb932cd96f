//! The certification tape that `#[derive(Lagrangian)]` emits: `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0`
//! as the derive's own expression DAG, children first, evaluated here with any [`TapeScalar`]
//! (f64 for tests, [`Interval`] for the certified search). The text format is documented in
//! `routh-codegen/src/tape.rs`.

use super::interval::Interval;

/// A number type the tape can be evaluated with.
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
    fn from_f64(x: f64) -> Self {
        x
    }
    fn recip(self) -> Self {
        1.0 / self
    }
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    fn powf(self, y: Self) -> Self {
        f64::powf(self, y)
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
            Func::Sign => {
                if self == 0.0 {
                    0.0
                } else {
                    self.signum()
                }
            }
        }
    }
}

impl TapeScalar for Interval {
    fn from_f64(x: f64) -> Self {
        Interval::point(x)
    }
    fn recip(self) -> Self {
        Interval::recip(self)
    }
    fn powi(self, n: i32) -> Self {
        Interval::powi(self, n)
    }
    fn powf(self, y: Self) -> Self {
        Interval::powf(self, y)
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

/// The elementary functions of the DSL.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    Sqrt,
    Sin,
    Cos,
    Tan,
    Exp,
    Ln,
    Abs,
    Sign,
}

impl Func {
    fn from_name(s: &str) -> Option<Func> {
        Some(match s {
            "sqrt" => Func::Sqrt,
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "exp" => Func::Exp,
            "ln" => Func::Ln,
            "abs" => Func::Abs,
            "sign" => Func::Sign,
            _ => return None,
        })
    }
}

/// One operation of the tape; operands are earlier slots.
#[derive(Debug, Clone, Copy)]
enum Op {
    Const(f64),
    Gamma(usize),
    PPsi,
    Add(usize, usize),
    Mul(usize, usize),
    Neg(usize),
    Recip(usize),
    Powi(usize, i32),
    Powf(usize, usize),
    Func(Func, usize),
}

/// `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0` of a derived model, with the model's parameter values bound:
/// what [`crate::Routhian::certification_tape`] returns and
/// [`steady_motions_certified`](super::steady_motions_certified) evaluates over boxes of the
/// sphere.
#[derive(Debug, Clone)]
pub struct RouthTape {
    ops: Vec<Op>,
    /// Slots of the gradient (3) and the upper Hessian (6).
    outputs: [usize; 9],
}

/// The gradient and the (symmetric) Hessian of `R(0, ·, p_ψ)` in γ.
pub type GradHess<T> = ([T; 3], [[T; 3]; 3]);

impl RouthTape {
    /// Parses the tape text the derive emits, binding `f k` to `params[k]`. `None` if the text
    /// is malformed (which the derive never emits).
    pub fn parse(text: &str, params: &[f64]) -> Option<RouthTape> {
        let mut ops = Vec::new();
        let mut outputs = None;
        for item in text.split(';') {
            let mut t = item.split(' ');
            let head = t.next()?;
            let n = ops.len();
            let mut slot = || -> Option<usize> {
                let s: usize = t.next()?.parse().ok()?;
                (s < n).then_some(s)
            };
            let op = match head {
                "c" => {
                    let bits = u64::from_str_radix(item.get(2..)?, 16).ok()?;
                    Op::Const(f64::from_bits(bits))
                }
                "g" => {
                    let k: usize = item.get(2..)?.parse().ok()?;
                    (k < 3).then_some(Op::Gamma(k))?
                }
                "p" => Op::PPsi,
                "f" => {
                    let k: usize = item.get(2..)?.parse().ok()?;
                    Op::Const(*params.get(k)?)
                }
                "+" => Op::Add(slot()?, slot()?),
                "*" => Op::Mul(slot()?, slot()?),
                "-" => Op::Neg(slot()?),
                "/" => Op::Recip(slot()?),
                "^" => {
                    let a = slot()?;
                    Op::Powi(a, t.next()?.parse().ok()?)
                }
                "P" => Op::Powf(slot()?, slot()?),
                "F" => {
                    let mut w = item.split(' ').skip(1);
                    let f = Func::from_name(w.next()?)?;
                    let a: usize = w.next()?.parse().ok()?;
                    (a < n).then_some(Op::Func(f, a))?
                }
                "o" => {
                    let mut o = [0usize; 9];
                    for x in &mut o {
                        *x = slot()?;
                    }
                    outputs = Some(o);
                    continue;
                }
                _ => return None,
            };
            ops.push(op);
        }
        Some(RouthTape {
            ops,
            outputs: outputs?,
        })
    }

    /// Number of operations.
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether the tape has no operations.
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0`, `(γ, p_ψ)`, evaluated with `T`; `scratch` is reused
    /// between calls.
    pub fn eval<T: TapeScalar>(
        &self,
        gamma: [T; 3],
        p_psi: T,
        scratch: &mut Vec<T>,
    ) -> GradHess<T> {
        scratch.clear();
        for op in &self.ops {
            let v = |i: usize| scratch[i];
            let x = match *op {
                Op::Const(c) => T::from_f64(c),
                Op::Gamma(k) => gamma[k],
                Op::PPsi => p_psi,
                Op::Add(a, b) => v(a) + v(b),
                Op::Mul(a, b) if a == b => v(a).powi(2),
                Op::Mul(a, b) => v(a) * v(b),
                Op::Neg(a) => -v(a),
                Op::Recip(a) => v(a).recip(),
                Op::Powi(a, n) => v(a).powi(n),
                Op::Powf(a, b) => v(a).powf(v(b)),
                Op::Func(f, a) => v(a).func(f),
            };
            scratch.push(x);
        }
        let o = |k: usize| scratch[self.outputs[k]];
        let grad = [o(0), o(1), o(2)];
        let (h00, h01, h02, h11, h12, h22) = (o(3), o(4), o(5), o(6), o(7), o(8));
        (grad, [[h00, h01, h02], [h01, h11, h12], [h02, h12, h22]])
    }
}
