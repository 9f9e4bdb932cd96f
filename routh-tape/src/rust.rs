//! A tape written as Rust source: `static` arrays of typed ops that the derive emits, so that
//! nothing is parsed at run time.

use crate::{Op, Tape};
use std::fmt::Write;

/// The paths the written source uses for the types of this crate (the derive passes aliases
/// of `::routh::__private` items).
#[derive(Copy, Clone, Debug)]
pub struct RustPaths<'a> {
    /// The path of [`Op`].
    pub op: &'a str,
    /// The path of [`crate::Output`].
    pub output: &'a str,
    /// The path of [`Tape`].
    pub tape: &'a str,
    /// The path of [`crate::Func`].
    pub func: &'a str,
}

impl Tape {
    /// Writes three `static` items: `{name}_OPS` (the ops), `{name}_OUT` (the outputs) and
    /// `{name}`, the [`Tape`] over them (checked at compile time by [`Tape::from_static`]).
    ///
    /// ```
    /// use routh_tape::{Op, Output, RustPaths, Tape};
    /// let t = Tape::new(vec![Op::PPsi, Op::Neg(0)], vec![Output { name: "y", slot: 1 }], 0).unwrap();
    /// let mut src = String::new();
    /// let p = RustPaths { op: "Op", output: "Output", tape: "Tape", func: "Func" };
    /// t.write_rust(&mut src, "T", &p);
    /// assert!(src.contains("static T_OPS: [Op; 2] = [Op::PPsi,Op::Neg(0),];"));
    /// ```
    pub fn write_rust(&self, out: &mut String, name: &str, p: &RustPaths<'_>) {
        let op = p.op;
        let _ = write!(out, "static {name}_OPS: [{op}; {}] = [", self.len());
        for (i, o) in self.ops().iter().enumerate() {
            if i % 16 == 15 {
                out.push('\n');
            }
            let _ = match *o {
                Op::Const(bits) => write!(out, "{op}::Const({bits:#x})"),
                Op::Omega(k) => write!(out, "{op}::Omega({k})"),
                Op::Gamma(k) => write!(out, "{op}::Gamma({k})"),
                Op::PPsi => write!(out, "{op}::PPsi"),
                Op::Param(k) => write!(out, "{op}::Param({k})"),
                Op::Add(a, b) => write!(out, "{op}::Add({a},{b})"),
                Op::Mul(a, b) => write!(out, "{op}::Mul({a},{b})"),
                Op::Neg(a) => write!(out, "{op}::Neg({a})"),
                Op::Recip(a) => write!(out, "{op}::Recip({a})"),
                Op::Powi(a, n) => write!(out, "{op}::Powi({a},{n})"),
                Op::Powf(a, b) => write!(out, "{op}::Powf({a},{b})"),
                Op::Func(f, a) => write!(out, "{op}::Func({}::{f:?},{a})", p.func),
            };
            out.push(',');
        }
        out.push_str("];\n");
        let output = p.output;
        let _ = write!(
            out,
            "static {name}_OUT: [{output}; {}] = [",
            self.outputs().len()
        );
        for o in self.outputs() {
            let _ = write!(out, "{output} {{ name: {:?}, slot: {} }},", o.name, o.slot);
        }
        out.push_str("];\n");
        let _ = writeln!(
            out,
            "static {name}: {} = {}::from_static(&{name}_OPS, &{name}_OUT, {});",
            p.tape,
            p.tape,
            self.num_params()
        );
    }
}
