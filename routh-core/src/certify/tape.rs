//! The interval evaluation of the derive's tapes: [`TapeScalar`] for [`Interval`] (the tape,
//! the scalar trait and the f64 impl live in `routh-tape`, docs of `routh_tape::Tape`).

use super::interval::Interval;
use routh_tape::{Func, TapeScalar};

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
