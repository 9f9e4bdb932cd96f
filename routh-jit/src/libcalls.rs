//! The transcendental functions the compiled code calls, as `extern "C"` wrappers of Rust's own
//! `f64` functions (so the JIT computes exactly what the interpreter and the derive compute),
//! registered by name in the JIT's symbol table.

use routh_tape::Func;

extern "C" fn routh_jit_sin(x: f64) -> f64 {
    x.sin()
}
extern "C" fn routh_jit_cos(x: f64) -> f64 {
    x.cos()
}
extern "C" fn routh_jit_tan(x: f64) -> f64 {
    x.tan()
}
extern "C" fn routh_jit_exp(x: f64) -> f64 {
    x.exp()
}
extern "C" fn routh_jit_ln(x: f64) -> f64 {
    x.ln()
}
extern "C" fn routh_jit_powf(x: f64, y: f64) -> f64 {
    x.powf(y)
}

/// The symbol of the wrapper of `f`, for the functions compiled as calls (`sin`, `cos`, `tan`,
/// `exp`, `ln`); `None` for those compiled inline (`sqrt`, `abs`, `sign`).
pub(crate) fn unary(f: Func) -> Option<&'static str> {
    match f {
        Func::Sin => Some("routh_jit_sin"),
        Func::Cos => Some("routh_jit_cos"),
        Func::Tan => Some("routh_jit_tan"),
        Func::Exp => Some("routh_jit_exp"),
        Func::Ln => Some("routh_jit_ln"),
        Func::Sqrt | Func::Abs | Func::Sign => None,
    }
}

/// The symbol of the wrapper of `powf`.
pub(crate) const POWF: &str = "routh_jit_powf";

/// Every wrapper with its address, for `JITBuilder::symbols`.
pub(crate) fn symbols() -> [(&'static str, *const u8); 6] {
    let unary = |f: extern "C" fn(f64) -> f64| f as *const u8;
    [
        ("routh_jit_sin", unary(routh_jit_sin)),
        ("routh_jit_cos", unary(routh_jit_cos)),
        ("routh_jit_tan", unary(routh_jit_tan)),
        ("routh_jit_exp", unary(routh_jit_exp)),
        ("routh_jit_ln", unary(routh_jit_ln)),
        (
            POWF,
            routh_jit_powf as extern "C" fn(f64, f64) -> f64 as *const u8,
        ),
    ]
}
