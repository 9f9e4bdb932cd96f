//! Conversions between Python values and routh's: parameters, vectors, errors.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use routh::{Matrix3, Param, Stability, Vector3};

create_exception!(
    routh,
    RouthError,
    PyException,
    "An error of routh's analyses (the Rust `RouthError`); `str(e)` is its message."
);
create_exception!(
    routh,
    ModelError,
    RouthError,
    "A mistake in a model's text or parameters: `e.message`, and `e.line`, `e.column` (from 1) where it is in the text, None for an error with no place in a text (a value given to `set`, a file that cannot be read)."
);

/// A Rust `RouthError` as a Python `routh.RouthError` (with `kind`, the variant's name).
pub fn routh_err(py: Python<'_>, e: &routh::RouthError) -> PyErr {
    let err = RouthError::new_err(e.to_string());
    let debug = format!("{e:?}");
    let kind: String = debug
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    let _ = err.value(py).setattr("kind", kind);
    err
}

/// The Rust shapes of a message in Python's words (`set("inertia", 2.0)` on a vector).
fn python_words(s: &str) -> String {
    s.replace("a Vector3<f64>", "a 3-vector")
        .replace("a Matrix3<f64>", "a 3x3 matrix")
        .replace("a f64", "a number")
}

/// A Rust `ModelError` as a Python `routh.ModelError` (with `line`, `column`, `message`;
/// `line` and `column` are None for an error about no place in a text: a parameter set by
/// `set`, a file that cannot be read).
pub fn model_err(py: Python<'_>, e: &routh::ModelError) -> PyErr {
    let placed = !e.source_line.is_empty();
    if !placed {
        return model_err_unplaced(py, e.message());
    }
    let err = ModelError::new_err(python_words(&e.to_string()));
    let v = err.value(py);
    let _ = v.setattr("line", e.line());
    let _ = v.setattr("column", e.column());
    let _ = v.setattr("message", python_words(e.message()));
    err
}

/// A `routh.ModelError` about no place in a text (`line` and `column` None).
pub fn model_err_unplaced(py: Python<'_>, message: &str) -> PyErr {
    let message = python_words(message);
    let err = ModelError::new_err(message.clone());
    let v = err.value(py);
    let _ = v.setattr("line", py.None());
    let _ = v.setattr("column", py.None());
    let _ = v.setattr("message", message);
    err
}

/// A `TypeError` if `value`, or an element of it down to `depth` levels of lists and tuples,
/// is a `bool` or a complex number where real numbers are expected (Python would convert
/// `True` to 1.0 silently).
fn no_bool_or_complex(what: &str, value: &Bound<'_, PyAny>, depth: usize) -> PyResult<()> {
    use pyo3::types::{PyBool, PyComplex, PyList, PyTuple};
    if value.is_instance_of::<PyBool>() || value.is_instance_of::<PyComplex>() {
        return Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "{what}: expected real numbers, not {}",
            value.get_type().name()?
        )));
    }
    if depth > 0 && (value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>()) {
        for x in value.try_iter()? {
            no_bool_or_complex(what, &x?, depth - 1)?;
        }
    }
    Ok(())
}

/// A real-number argument: a float, an int or anything with `__float__`, but not a `bool` or a
/// complex number (a `TypeError`: Python would turn `True` into 1.0 silently).
#[derive(Clone, Copy, Debug)]
pub struct Real(pub f64);

impl<'a, 'py> FromPyObject<'a, 'py> for Real {
    type Error = PyErr;
    fn extract(obj: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        let any: &Bound<'py, PyAny> = &obj;
        no_bool_or_complex("argument", any, 0)?;
        Ok(Real(any.extract::<f64>()?))
    }
}

/// A parameter value: a number, a 3-sequence or a 3×3 nested sequence (numpy arrays included).
/// A `bool` or a complex number is a `TypeError`; NaN and infinite values are refused by the
/// model (a `ModelError` naming the parameter).
pub fn param(name: &str, value: &Bound<'_, PyAny>) -> PyResult<Param> {
    no_bool_or_complex(&format!("parameter `{name}`"), value, 2)?;
    if let Ok(x) = value.extract::<f64>() {
        return Ok(Param::Scalar(x));
    }
    if let Ok(v) = value.extract::<Vec<f64>>() {
        if v.len() == 3 {
            return Ok(Param::Vector(Vector3::new(v[0], v[1], v[2])));
        }
    }
    if let Ok(rows) = value.extract::<Vec<Vec<f64>>>() {
        if rows.len() == 3 && rows.iter().all(|r| r.len() == 3) {
            return Ok(Param::Matrix(Matrix3::from_fn(|i, j| rows[i][j])));
        }
    }
    Err(model_err_unplaced(
        value.py(),
        &format!("parameter `{name}`: expected a number, a 3-vector or a 3x3 matrix"),
    ))
}

/// A parameter value as a Python object (float, (3,) or (3, 3) array).
pub fn param_to_py(py: Python<'_>, p: &Param) -> Py<PyAny> {
    match p {
        Param::Scalar(x) => x
            .into_pyobject(py)
            .map(|o| o.into_any().unbind())
            .unwrap_or_else(|_| py.None()),
        Param::Vector(v) => vec3(py, v).into_any().unbind(),
        Param::Matrix(m) => {
            let rows: Vec<Vec<f64>> = (0..3)
                .map(|i| (0..3).map(|j| m[(i, j)]).collect())
                .collect();
            match PyArray2::from_vec2(py, &rows) {
                Ok(a) => a.into_any().unbind(),
                Err(_) => py.None(),
            }
        }
    }
}

/// A 3-vector from a Python sequence or numpy array.
pub fn vector3(name: &str, value: &Bound<'_, PyAny>) -> PyResult<Vector3<f64>> {
    no_bool_or_complex(name, value, 1)?;
    let v: Vec<f64> = value
        .extract()
        .map_err(|_| RouthError::new_err(format!("{name}: expected a sequence of 3 numbers")))?;
    if v.len() != 3 {
        return Err(RouthError::new_err(format!(
            "{name}: expected 3 numbers, got {}",
            v.len()
        )));
    }
    Ok(Vector3::new(v[0], v[1], v[2]))
}

/// A (3,) float64 array.
pub fn vec3<'py>(py: Python<'py>, v: &Vector3<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, v.as_slice())
}

/// An (n, 3) float64 array from a list of vectors.
pub fn vecs<'py>(py: Python<'py>, vs: &[Vector3<f64>]) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = vs.iter().flat_map(|v| [v.x, v.y, v.z]).collect();
    let a = PyArray1::from_vec(py, flat);
    // (3n,) → (n, 3): a reshape of a contiguous array cannot fail.
    match a.reshape([vs.len(), 3]) {
        Ok(r) => r,
        Err(_) => PyArray2::zeros(py, [vs.len(), 3], false),
    }
}

/// The verdict's name: "secularly_stable", "gyroscopically_stabilized", "unstable",
/// "degenerate".
pub fn verdict(s: Stability) -> &'static str {
    routh::export::verdict_name(s)
}

/// The nonlinear verdict's name: "secularly_stable", "lyapunov_stable", "unstable",
/// "undecided".
pub fn nonlinear_verdict(v: routh::NonlinearVerdict) -> &'static str {
    routh::export::nonlinear_verdict_name(v)
}

/// The event's name: "fold", "branch_point", "hamiltonian_hopf" (and "arnold_degenerate",
/// "resonance"), the same words as the library's CSV export.
pub fn event_kind(k: routh::EventKind) -> &'static str {
    routh::export::event_name(k)
}

/// Calls `routh.<module>.<name>(*args)` of the pure-Python layer (figures, HTML).
pub fn helper<'py, A>(py: Python<'py>, module: &str, name: &str, args: A) -> PyResult<Py<PyAny>>
where
    A: pyo3::call::PyCallArgs<'py>,
{
    Ok(py.import(module)?.getattr(name)?.call1(args)?.unbind())
}

/// An (n, 4) float64 array of unit quaternions in scipy's order `(x, y, z, w)` (scalar last,
/// `scipy.spatial.transform.Rotation.from_quat`), or None when there are none.
pub fn quaternions(
    py: Python<'_>,
    qs: &[routh::nalgebra::UnitQuaternion<f64>],
) -> Option<Py<PyAny>> {
    if qs.is_empty() {
        return None;
    }
    let flat: Vec<f64> = qs.iter().flat_map(|q| [q.i, q.j, q.k, q.w]).collect();
    let a = PyArray1::from_vec(py, flat);
    a.reshape([qs.len(), 4]).ok().map(|r| r.into_any().unbind())
}

/// An (n, 3) float64 array of rows, or None when there are none.
pub fn rows3(py: Python<'_>, rows: &[[f64; 3]]) -> Option<Py<PyAny>> {
    if rows.is_empty() {
        return None;
    }
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    let a = PyArray1::from_vec(py, flat);
    a.reshape([rows.len(), 3])
        .ok()
        .map(|r| r.into_any().unbind())
}
