//! The TOML form of a model (docs/models.md):
//!
//! ```toml
//! [model]
//! lagrangian = """
//!     kinetic = 0.5 * omega.dot(inertia * omega),
//!     potential = mass * g * com.dot(gamma),
//! """
//! symmetric = ["inertia"]          # optional
//! [parameters]
//! inertia = [[2.0, 0.1, 0.0], [0.1, 2.5, 0.0], [0.0, 0.0, 3.0]]   # Matrix3, rows
//! com = [0.0, 0.0, 1.0]                                           # Vector3
//! mass = 1                                                        # f64 (integers accepted)
//! g = 9.81
//! [latex]                          # optional: name → LaTeX symbol
//! mass = "m"
//! ```

use crate::error::{line_column, ModelError};
use crate::{Model, Param};
use nalgebra::{Matrix3, Vector3};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    model: ModelTable,
    #[serde(default)]
    parameters: BTreeMap<Spanned<String>, Spanned<toml::Value>>,
    #[serde(default)]
    latex: BTreeMap<String, String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ModelTable {
    lagrangian: Spanned<String>,
    #[serde(default)]
    symmetric: Vec<Spanned<String>>,
}

/// A number of a parameter: a float or an integer.
fn number(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// Three numbers.
fn triple(v: &toml::Value) -> Option<[f64; 3]> {
    match v {
        toml::Value::Array(a) if a.len() == 3 => {
            Some([number(&a[0])?, number(&a[1])?, number(&a[2])?])
        }
        _ => None,
    }
}

/// A parameter's value: a number, 3 numbers (a vector) or 3 rows of 3 (a matrix).
fn param(v: &toml::Value) -> Option<Param> {
    if let Some(x) = number(v) {
        return Some(Param::Scalar(x));
    }
    if let Some(t) = triple(v) {
        return Some(Param::Vector(Vector3::from(t)));
    }
    match v {
        toml::Value::Array(rows) if rows.len() == 3 => {
            let r = [triple(&rows[0])?, triple(&rows[1])?, triple(&rows[2])?];
            Some(Param::Matrix(Matrix3::from_fn(|i, j| r[i][j])))
        }
        _ => None,
    }
}

/// Where the string value at `span` of `src` starts, as `(line, column)` of its first
/// character, if its text in the file is the string itself (no escapes), so that positions in
/// the string map to positions in the file.
fn content_start(src: &str, span: Range<usize>, value: &str) -> Option<(usize, usize)> {
    let raw = src.get(span.clone())?;
    let (open, close) = if raw.starts_with("\"\"\"") || raw.starts_with("'''") {
        (3, 3)
    } else {
        (1, 1)
    };
    let mut start = span.start + open;
    let inner = src.get(start..span.end.checked_sub(close)?)?;
    // A newline right after the opening delimiter of a multi-line string is trimmed.
    let inner = if open == 3 {
        if let Some(rest) = inner.strip_prefix("\r\n") {
            start += 2;
            rest
        } else if let Some(rest) = inner.strip_prefix('\n') {
            start += 1;
            rest
        } else {
            inner
        }
    } else {
        inner
    };
    (inner == value).then(|| line_column(src, start))
}

impl Model {
    /// A model from the TOML form (see docs/models.md and the [module docs](crate)): the
    /// Lagrangian's text under `[model]`, optional `symmetric` matrices, the parameters'
    /// values under `[parameters]` (a number, a vector `[x, y, z]`, a matrix as 3 rows;
    /// integers are accepted), and an optional `[latex]` table of symbols.
    ///
    /// Errors carry their line and column in `src`: TOML syntax, a parameter given twice, a
    /// value of no parameter shape, a `symmetric` name that is not a parameter, and every error
    /// of [`Model::new`] in the Lagrangian (placed in the file when the string has no escapes,
    /// else in the Lagrangian's text). A parameter the text uses and the file does not give is
    /// an "unknown name" error at its use.
    pub fn from_toml(src: &str) -> Result<Model, ModelError> {
        let file: File = toml::from_str(src).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            ModelError::at_byte(e.message().trim_end(), src, span.start, span.end)
        })?;
        let text = file.model.lagrangian.get_ref().as_str();
        let start = content_start(src, file.model.lagrangian.span(), text);
        let place = |e: ModelError| match start {
            Some((line, column)) => e.shifted(src, line, column),
            None => e,
        };
        let mut params = Vec::new();
        for (name, value) in &file.parameters {
            let span = value.span();
            let Some(p) = param(value.get_ref()) else {
                return Err(ModelError::at_byte(
                    format!(
                        "parameter `{}` is not a number, a vector `[x, y, z]` or a matrix of 3 rows `[[..], [..], [..]]`",
                        name.get_ref()
                    ),
                    src,
                    span.start,
                    span.end,
                ));
            };
            if let Some(why) = p.non_finite(name.get_ref()) {
                return Err(ModelError::at_byte(why, src, span.start, span.end));
            }
            params.push((name.get_ref().clone(), p));
        }
        let mut symmetric = Vec::new();
        for s in &file.model.symmetric {
            let name = s.get_ref();
            match file.parameters.keys().find(|k| k.get_ref() == name) {
                Some(k)
                    if !matches!(param(file.parameters[k].get_ref()), Some(Param::Matrix(_))) =>
                {
                    let span = s.span();
                    return Err(ModelError::at_byte(
                        format!("`symmetric` names `{name}`, which is not a matrix parameter"),
                        src,
                        span.start,
                        span.end,
                    ));
                }
                Some(_) => symmetric.push(name.clone()),
                None => {
                    let span = s.span();
                    return Err(ModelError::at_byte(
                        format!("`symmetric` names `{name}`, which is not under [parameters]"),
                        src,
                        span.start,
                        span.end,
                    ));
                }
            }
        }
        Model::build(text, params, symmetric, file.latex).map_err(place)
    }

    /// [`Model::from_toml`] of the file at `path`; a file that cannot be read is an error
    /// naming it.
    pub fn from_file(path: impl AsRef<std::path::Path>) -> Result<Model, ModelError> {
        let path = path.as_ref();
        let src = std::fs::read_to_string(path).map_err(|e| {
            ModelError::general(format!(
                "cannot read the model file {}: {e}",
                path.display()
            ))
        })?;
        Model::from_toml(&src)
    }
}
