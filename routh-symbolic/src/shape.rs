//! Shapes: scalars, 3-vectors and 3×3 matrices, lowered to scalar nodes of a [`Graph`].
//!
//! Every operation checks its operands' shapes and returns a [`ShapeError`] (never panics), so
//! the code generator can report a mismatch at the user's tokens.

use crate::graph::{Func, Graph, Id};
use std::fmt;

/// A value of one of the three shapes of the DSL.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Value {
    /// A scalar.
    Scalar(Id),
    /// A column 3-vector.
    Vector([Id; 3]),
    /// A 3×3 matrix, row-major: `m[i][j]` is row `i`, column `j`.
    Matrix([[Id; 3]; 3]),
}

/// The shape of a [`Value`].
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Shape {
    Scalar,
    Vector,
    Matrix,
}

impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Shape::Scalar => "a scalar",
            Shape::Vector => "a 3-vector",
            Shape::Matrix => "a 3×3 matrix",
        })
    }
}

/// A shape mismatch, with a message for the user.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct ShapeError(pub String);

impl fmt::Display for ShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ShapeError {}

type R = Result<Value, ShapeError>;

fn err<T>(msg: String) -> Result<T, ShapeError> {
    Err(ShapeError(msg))
}

impl Value {
    /// The shape.
    pub fn shape(&self) -> Shape {
        match self {
            Value::Scalar(_) => Shape::Scalar,
            Value::Vector(_) => Shape::Vector,
            Value::Matrix(_) => Shape::Matrix,
        }
    }

    /// The scalar, or an error naming `what`.
    pub fn scalar(&self, what: &str) -> Result<Id, ShapeError> {
        match *self {
            Value::Scalar(s) => Ok(s),
            other => err(format!("{what} must be a scalar, found {}", other.shape())),
        }
    }

    /// The vector, or an error naming `what`.
    pub fn vector(&self, what: &str) -> Result<[Id; 3], ShapeError> {
        match *self {
            Value::Vector(v) => Ok(v),
            other => err(format!(
                "{what} must be a 3-vector, found {}",
                other.shape()
            )),
        }
    }

    /// The matrix, or an error naming `what`.
    pub fn matrix(&self, what: &str) -> Result<[[Id; 3]; 3], ShapeError> {
        match *self {
            Value::Matrix(m) => Ok(m),
            other => err(format!(
                "{what} must be a 3×3 matrix, found {}",
                other.shape()
            )),
        }
    }

    /// Every scalar node of the value, row-major.
    pub fn ids(&self) -> Vec<Id> {
        match self {
            Value::Scalar(s) => vec![*s],
            Value::Vector(v) => v.to_vec(),
            Value::Matrix(m) => m.iter().flatten().copied().collect(),
        }
    }

    /// Applies `f` to every scalar node.
    pub fn map(&self, g: &mut Graph, mut f: impl FnMut(&mut Graph, Id) -> Id) -> Value {
        match *self {
            Value::Scalar(s) => Value::Scalar(f(g, s)),
            Value::Vector(v) => Value::Vector(v.map(|x| f(g, x))),
            Value::Matrix(m) => Value::Matrix(m.map(|row| row.map(|x| f(g, x)))),
        }
    }

    fn zip(
        &self,
        other: &Value,
        g: &mut Graph,
        mut f: impl FnMut(&mut Graph, Id, Id) -> Id,
    ) -> Option<Value> {
        Some(match (*self, *other) {
            (Value::Scalar(a), Value::Scalar(b)) => Value::Scalar(f(g, a, b)),
            (Value::Vector(a), Value::Vector(b)) => {
                Value::Vector(std::array::from_fn(|i| f(g, a[i], b[i])))
            }
            (Value::Matrix(a), Value::Matrix(b)) => Value::Matrix(std::array::from_fn(|i| {
                std::array::from_fn(|j| f(g, a[i][j], b[i][j]))
            })),
            _ => return None,
        })
    }
}

/// `a + b` (same shapes).
pub fn add(g: &mut Graph, a: &Value, b: &Value) -> R {
    a.zip(b, g, Graph::add)
        .ok_or_else(|| ShapeError(format!("cannot add {} and {}", a.shape(), b.shape())))
}

/// `a - b` (same shapes).
pub fn sub(g: &mut Graph, a: &Value, b: &Value) -> R {
    a.zip(b, g, Graph::sub)
        .ok_or_else(|| ShapeError(format!("cannot subtract {} from {}", b.shape(), a.shape())))
}

/// `-a`.
pub fn neg(g: &mut Graph, a: &Value) -> Value {
    a.map(g, Graph::neg)
}

// Kernels on arrays of nodes (no shape checks), shared by the DSL's operators below and by
// code that builds formulas from known shapes (the Routh reduction).

/// `a·b` for two 3-vectors of nodes.
pub fn dot3(g: &mut Graph, a: &[Id; 3], b: &[Id; 3]) -> Id {
    let t: Vec<Id> = (0..3).map(|i| g.mul(a[i], b[i])).collect();
    g.sum(t)
}

fn column(m: &[[Id; 3]; 3], j: usize) -> [Id; 3] {
    [m[0][j], m[1][j], m[2][j]]
}

/// `a b` for two 3×3 matrices of nodes.
pub fn matmul3(g: &mut Graph, a: &[[Id; 3]; 3], b: &[[Id; 3]; 3]) -> [[Id; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let c = column(b, j);
            dot3(g, &a[i], &c)
        })
    })
}

/// `aᵀ` for a 3×3 matrix of nodes.
pub fn transpose3(a: &[[Id; 3]; 3]) -> [[Id; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

/// `[v]×`, the cross-product matrix of a 3-vector of nodes: `[v]× w = v × w`.
pub fn skew3(g: &mut Graph, v: &[Id; 3]) -> [[Id; 3]; 3] {
    let z = g.zero();
    let n: [Id; 3] = v.map(|x| g.neg(x));
    [[z, n[2], v[1]], [v[2], z, n[0]], [n[1], v[0], z]]
}

/// `a * b`: scalar·anything, matrix·vector, matrix·matrix.
pub fn mul(g: &mut Graph, a: &Value, b: &Value) -> R {
    Ok(match (*a, *b) {
        (Value::Scalar(s), other) | (other, Value::Scalar(s)) => other.map(g, |g, x| g.mul(s, x)),
        (Value::Matrix(m), Value::Vector(v)) => Value::Vector(std::array::from_fn(|i| dot3(g, &m[i], &v))),
        (Value::Matrix(m), Value::Matrix(n)) => Value::Matrix(matmul3(g, &m, &n)),
        (Value::Vector(_), Value::Vector(_)) => {
            return err("cannot multiply two vectors with `*`: use `a.dot(b)`, `a.cross(b)` or `a.component_mul(b)`".into())
        }
        (Value::Vector(_), Value::Matrix(_)) => {
            return err("cannot multiply a vector by a matrix on the right: write `m.transpose() * v`".into())
        }
    })
}

/// `a / b` with a scalar `b`.
pub fn div(g: &mut Graph, a: &Value, b: &Value) -> R {
    let s = b.scalar("the divisor")?;
    let r = g.recip(s);
    Ok(a.map(g, |g, x| g.mul(x, r)))
}

/// `a.dot(b)` for vectors.
pub fn dot(g: &mut Graph, a: &Value, b: &Value) -> R {
    let (a, b) = (
        a.vector("the receiver of `dot`")?,
        b.vector("the argument of `dot`")?,
    );
    Ok(Value::Scalar(dot3(g, &a, &b)))
}

/// `a.cross(b)` for vectors.
pub fn cross(g: &mut Graph, a: &Value, b: &Value) -> R {
    let (a, b) = (
        a.vector("the receiver of `cross`")?,
        b.vector("the argument of `cross`")?,
    );
    let c = |g: &mut Graph, i: usize, j: usize| {
        let p = g.mul(a[i], b[j]);
        let q = g.mul(a[j], b[i]);
        g.sub(p, q)
    };
    Ok(Value::Vector([c(g, 1, 2), c(g, 2, 0), c(g, 0, 1)]))
}

/// `a.norm_squared()`: the squared Euclidean (vector) or Frobenius (matrix) norm.
pub fn norm_squared(g: &mut Graph, a: &Value) -> R {
    match a {
        Value::Scalar(_) => err("`norm_squared` needs a vector or a matrix, found a scalar".into()),
        _ => {
            let t: Vec<Id> = a.ids().into_iter().map(|x| g.powi(x, 2)).collect();
            Ok(Value::Scalar(g.sum(t)))
        }
    }
}

/// `a.norm()`.
pub fn norm(g: &mut Graph, a: &Value) -> R {
    let s = norm_squared(g, a)
        .map_err(|_| ShapeError("`norm` needs a vector or a matrix, found a scalar".into()))?;
    s.scalar("").map(|s| Value::Scalar(g.func(Func::Sqrt, s)))
}

/// `m.transpose()`.
pub fn transpose(_g: &mut Graph, a: &Value) -> R {
    let m = a.matrix("the receiver of `transpose`")?;
    Ok(Value::Matrix(transpose3(&m)))
}

/// `a.component_mul(b)` (same shapes).
pub fn component_mul(g: &mut Graph, a: &Value, b: &Value) -> R {
    if a.shape() == Shape::Scalar || b.shape() == Shape::Scalar {
        return err("`component_mul` needs two vectors or two matrices".into());
    }
    a.zip(b, g, Graph::mul).ok_or_else(|| {
        ShapeError(format!(
            "`component_mul` of {} and {}",
            a.shape(),
            b.shape()
        ))
    })
}

/// `m.trace()`.
pub fn trace(g: &mut Graph, a: &Value) -> R {
    let m = a.matrix("the receiver of `trace`")?;
    Ok(Value::Scalar(g.sum([m[0][0], m[1][1], m[2][2]])))
}

/// `diag(v)`: the diagonal matrix with diagonal `v`.
pub fn diag(g: &mut Graph, a: &Value) -> R {
    let v = a.vector("the argument of `diag`")?;
    let z = g.zero();
    Ok(Value::Matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { v[i] } else { z })
    })))
}

/// `skew(v)`: the cross-product matrix, `skew(v) * w == v.cross(w)`.
pub fn skew(g: &mut Graph, a: &Value) -> R {
    let v = a.vector("the argument of `skew`")?;
    Ok(Value::Matrix(skew3(g, &v)))
}

/// An elementary function or `recip` applied componentwise to a scalar.
pub fn scalar_func(
    g: &mut Graph,
    name: &str,
    a: &Value,
    f: impl FnOnce(&mut Graph, Id) -> Id,
) -> R {
    let s = a.scalar(&format!("the receiver of `{name}`"))?;
    Ok(Value::Scalar(f(g, s)))
}

/// The component `i` (0-based) of a vector.
pub fn component(a: &Value, i: usize) -> R {
    let v = a.vector("an indexed value")?;
    v.get(i).map(|&x| Value::Scalar(x)).ok_or_else(|| {
        ShapeError(format!(
            "index {i} is out of range for a 3-vector (0, 1 or 2)"
        ))
    })
}

/// The entry `(i, j)` (0-based) of a matrix.
pub fn entry(a: &Value, i: usize, j: usize) -> R {
    let m = a.matrix("a value indexed by `(i, j)`")?;
    if i > 2 || j > 2 {
        return err(format!("index ({i}, {j}) is out of range for a 3×3 matrix"));
    }
    Ok(Value::Scalar(m[i][j]))
}

/// `∂s/∂x` for a scalar `s` and a vector of variables `x`: the gradient as a vector.
pub fn grad(g: &mut Graph, s: &Value, x: &[Id; 3]) -> R {
    let s = s.scalar("the first argument of `grad`")?;
    let mut out = [s; 3];
    for (o, &xi) in out.iter_mut().zip(x) {
        let v = g.as_var(xi).ok_or_else(|| {
            ShapeError("`grad` differentiates with respect to variables only".into())
        })?;
        *o = g.diff(s, v);
    }
    Ok(Value::Vector(out))
}
