//! Python keywords as an analysis's options struct: `**kwargs` laid over the struct's `Default`
//! by `routh::options` (the command line's `--opt` uses the same), so that every field is a
//! keyword and the defaults are written once, in Rust. `routh._options_schema()` lists the
//! keywords and their defaults of each struct (the stub `__init__.pyi` is checked against it).

use crate::lenient::Lenient;
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyComplex, PyDict, PyFloat, PyInt, PyString};
use routh::options::{keywords, overlay, OptionError, Options};
use routh::{
    AtlasOptions, ContinuationOptions, NonlinearOptions, OrbitChartOptions, OrbitNonlinearOptions,
    OrbitOptions, SectionOptions, SimOptions,
};
use serde_json::{Number, Value};

/// A Python value as JSON: None, bools, numbers (NaN and infinities as the strings the lenient
/// reader takes), strings, sequences and dicts.
fn value(key: &str, v: &Bound<'_, PyAny>) -> PyResult<Value> {
    if v.is_none() {
        return Ok(Value::Null);
    }
    if v.is_instance_of::<PyBool>() {
        return Ok(Value::Bool(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(Value::String(v.extract()?));
    }
    if v.is_instance_of::<PyComplex>() {
        return Err(PyTypeError::new_err(format!(
            "option `{key}`: expected a real number, not complex"
        )));
    }
    if v.is_instance_of::<PyInt>() || (!v.is_instance_of::<PyFloat>() && v.hasattr("__index__")?) {
        if let Ok(i) = v.extract::<i64>() {
            return Ok(Value::from(i));
        }
        if let Ok(u) = v.extract::<u64>() {
            return Ok(Value::from(u));
        }
        return Err(PyOverflowError::new_err(format!(
            "option `{key}`: {} is out of range",
            v.str()?
        )));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        let mut m = serde_json::Map::new();
        for (k, x) in d.iter() {
            m.insert(k.extract()?, value(key, &x)?);
        }
        return Ok(Value::Object(m));
    }
    if v.is_instance_of::<PyFloat>() || v.hasattr("__float__")? {
        let x: f64 = v.extract()?;
        return Ok(Number::from_f64(x).map_or_else(
            || {
                Value::String(
                    if x.is_nan() {
                        "NaN"
                    } else if x > 0.0 {
                        "Infinity"
                    } else {
                        "-Infinity"
                    }
                    .into(),
                )
            },
            Value::Number,
        ));
    }
    if let Ok(items) = v.try_iter() {
        return items
            .map(|x| value(key, &x?))
            .collect::<PyResult<_>>()
            .map(Value::Array);
    }
    Err(PyTypeError::new_err(format!(
        "option `{key}`: cannot read a {}",
        v.get_type().name()?
    )))
}

/// `T::default()` with the keywords `kwargs` of `function` laid over it: an unknown keyword is a
/// `TypeError` naming it and the valid ones; a value of the wrong type a `TypeError` (a negative
/// count an `OverflowError`, another bad value a `ValueError`) naming the keyword.
pub(crate) fn from_keywords<T: Options>(
    function: &str,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<T> {
    let mut pairs = Vec::new();
    for (k, v) in kwargs.into_iter().flat_map(|d| d.iter()) {
        let k: String = k.extract()?;
        let v = value(&k, &v)?;
        pairs.push((k, v));
    }
    overlay(T::default(), pairs, |v| T::deserialize(Lenient(v))).map_err(|e| match &e {
        OptionError::Unknown { .. } => PyTypeError::new_err(format!(
            "{function}() got an unexpected keyword argument: {e}"
        )),
        OptionError::Invalid { message, .. } => {
            let msg = format!("{function}(): {e}");
            if message.starts_with("invalid type") {
                PyTypeError::new_err(msg)
            } else if message.starts_with("invalid value: integer `-") {
                PyOverflowError::new_err(msg)
            } else {
                PyValueError::new_err(msg)
            }
        }
    })
}

/// The keywords of `T` and their defaults as a dict.
fn schema<'py, T: Options>(py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let json = py.import("json")?;
    for (k, v) in keywords::<T>() {
        d.set_item(k, json.call_method1("loads", (v.to_string(),))?)?;
    }
    Ok(d)
}

/// {options struct: {keyword: default}} of every options struct whose fields are keywords.
#[pyfunction]
pub fn _options_schema(py: Python<'_>) -> PyResult<Py<PyDict>> {
    let d = PyDict::new(py);
    d.set_item("OrbitOptions", schema::<OrbitOptions>(py)?)?;
    d.set_item(
        "OrbitNonlinearOptions",
        schema::<OrbitNonlinearOptions>(py)?,
    )?;
    d.set_item("OrbitChartOptions", schema::<OrbitChartOptions>(py)?)?;
    d.set_item("ContinuationOptions", schema::<ContinuationOptions>(py)?)?;
    d.set_item("AtlasOptions", schema::<AtlasOptions>(py)?)?;
    d.set_item("SimOptions", schema::<SimOptions>(py)?)?;
    d.set_item("SectionOptions", schema::<SectionOptions>(py)?)?;
    d.set_item("NonlinearOptions", schema::<NonlinearOptions>(py)?)?;
    Ok(d.unbind())
}
