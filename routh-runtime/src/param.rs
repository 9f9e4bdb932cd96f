//! [`Param`]: the value of a model parameter.

use nalgebra::{Matrix3, Vector3};

/// The value of a parameter of a [`Model`](crate::Model): a scalar (`f64` field of a derived
/// model), a vector (`Vector3<f64>`) or a matrix (`Matrix3<f64>`).
///
/// ```
/// use routh_runtime::Param;
/// use nalgebra::Matrix3;
/// assert_eq!(Param::from(2.0), Param::Scalar(2.0));
/// assert_eq!(Param::from([[1.0, 2.0, 3.0], [0.0; 3], [0.0; 3]]), Param::Matrix(Matrix3::new(1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Param {
    /// A number.
    Scalar(f64),
    /// A 3-vector.
    Vector(Vector3<f64>),
    /// A 3×3 matrix.
    Matrix(Matrix3<f64>),
}

impl Param {
    /// `"f64"`, `"Vector3<f64>"` or `"Matrix3<f64>"`: the field type of a derived model.
    pub fn shape_name(&self) -> &'static str {
        match self {
            Param::Scalar(_) => "f64",
            Param::Vector(_) => "Vector3<f64>",
            Param::Matrix(_) => "Matrix3<f64>",
        }
    }

    /// Whether `self` and `other` have the same shape.
    pub fn same_shape(&self, other: &Param) -> bool {
        std::mem::discriminant(self) == std::mem::discriminant(other)
    }

    /// Why `self` cannot be the value of parameter `name`: a NaN or infinite number, vector
    /// component or matrix entry (named), or `None` when every number is finite.
    pub fn non_finite(&self, name: &str) -> Option<String> {
        let bad = |x: f64| if x.is_nan() { "a NaN" } else { "an infinite" };
        let what = match self {
            Param::Scalar(x) if x.is_nan() => "is NaN".to_string(),
            Param::Scalar(x) if !x.is_finite() => "is infinite".to_string(),
            Param::Vector(v) => {
                let i = v.iter().position(|x| !x.is_finite())?;
                format!("has {} component [{i}]", bad(v[i]))
            }
            Param::Matrix(m) => {
                let k = (0..9).find(|&k| !m[(k / 3, k % 3)].is_finite())?;
                let (i, j) = (k / 3, k % 3);
                format!("has {} entry [{i}][{j}]", bad(m[(i, j)]))
            }
            Param::Scalar(_) => return None,
        };
        Some(format!(
            "parameter `{name}` {what}: parameter values must be finite numbers"
        ))
    }

    /// The scalar a derived model's code reads: the value, component `i` or entry `(i, j)`.
    pub(crate) fn read(&self, access: &routh_codegen::lower::Access) -> f64 {
        use routh_codegen::lower::Access;
        match (self, access) {
            (Param::Scalar(x), _) => *x,
            (Param::Vector(v), Access::Component(i)) => v[*i],
            (Param::Matrix(m), Access::Entry(i, j)) => m[(*i, *j)],
            // The shapes agree by construction (the struct's fields have these shapes).
            _ => f64::NAN,
        }
    }
}

impl From<f64> for Param {
    fn from(x: f64) -> Self {
        Param::Scalar(x)
    }
}

impl From<Vector3<f64>> for Param {
    fn from(v: Vector3<f64>) -> Self {
        Param::Vector(v)
    }
}

impl From<Matrix3<f64>> for Param {
    fn from(m: Matrix3<f64>) -> Self {
        Param::Matrix(m)
    }
}

impl From<[f64; 3]> for Param {
    fn from(v: [f64; 3]) -> Self {
        Param::Vector(Vector3::from(v))
    }
}

/// Rows.
impl From<[[f64; 3]; 3]> for Param {
    fn from(r: [[f64; 3]; 3]) -> Self {
        Param::Matrix(Matrix3::from_fn(|i, j| r[i][j]))
    }
}
