//! The symbolic engine behind `#[derive(Lagrangian)]`: a hash-consed expression DAG whose
//! children come before their parents, simplifying constructors, symbolic differentiation,
//! shapes (scalar / 3-vector / 3×3 matrix) lowered to scalars, scheduling for straight-line code
//! generation, and an interpreter [`Graph::eval`] used by tests.
//!
//! ```
//! use routh_symbolic::Graph;
//! let mut g = Graph::new();
//! let v = g.new_var("x");             // the variable, to differentiate by
//! let x = g.var_id(v);                 // and its node, to build with
//! let s = g.func(routh_symbolic::Func::Sin, x);
//! let f = g.mul(x, s);                 // x sin x
//! let df = g.diff(f, v);               // sin x + x cos x
//! let v = g.eval(&[df], &[0.5])[0];
//! assert!((v - (0.5f64.sin() + 0.5 * 0.5f64.cos())).abs() < 1e-15);
//! ```
#![forbid(unsafe_code)]

pub mod analysis;
mod graph;
pub mod latex;
pub mod shape;

pub use analysis::{degree, extra_cost, op_counts, schedule, to_infix, Degree, OpCounts, Plan};
pub use graph::{Func, Graph, Id, Node, Var};
pub use latex::{
    latex_symbol, matrix_to_latex, matrix_to_latex_named, on_sphere, replace_nodes,
    sympy_identifiers, sympy_symbol, to_latex, to_sympy, LatexSymbols, INTERMEDIATES,
    SYMPY_FUNCTIONS, SYMPY_STATE,
};
pub use shape::{Shape, ShapeError, Value};
