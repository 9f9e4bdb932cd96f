//! [`RouthError`] as a value: `Serialize` and `Deserialize`, so that a failed analysis can be
//! written next to the results that succeeded (the CLI's `--json`, Python, a batch of runs).
//!
//! The JSON of an error is an object tagged by its variant, with the variant's fields and the
//! `Display` message:
//!
//! ```json
//! {"kind": "NonFinite", "what": "p_psi", "value": "NaN", "message": "non-finite input: p_psi = NaN"}
//! ```
//!
//! `message` is written for readers and ignored when read back (it is recomputed from the
//! fields). Non-finite numbers follow [`float`](super::float). The variants name their input in
//! a `&'static str` (`what`); reading one back interns the name: each distinct name is allocated
//! once for the life of the process, at most [`MAX_NAMES`] of them and [`MAX_NAME_LEN`] bytes
//! each (longer names are cut, further ones read as `"(unknown)"`), so that no input can make
//! reading errors use unbounded memory.

use std::collections::HashSet;
use std::sync::{Mutex, OnceLock};

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::float;
use crate::error::RouthError;

/// The most distinct names that deserialising errors keeps (see the module documentation).
pub(crate) const MAX_NAMES: usize = 1024;
/// The longest name kept, in bytes.
pub(crate) const MAX_NAME_LEN: usize = 200;

/// The interned `&'static str` equal to `name` (cut to [`MAX_NAME_LEN`] bytes at a character
/// boundary), or `"(unknown)"` once [`MAX_NAMES`] names are kept.
pub(crate) fn intern(name: &str) -> &'static str {
    let mut end = name.len().min(MAX_NAME_LEN);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    let name = &name[..end];
    static NAMES: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    let mut names = NAMES
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(&kept) = names.get(name) {
        return kept;
    }
    if names.len() >= MAX_NAMES {
        return "(unknown)";
    }
    let kept: &'static str = Box::leak(name.to_owned().into_boxed_str());
    names.insert(kept);
    kept
}

/// The variants of [`RouthError`] with owned names: what is written and read.
#[derive(Serialize, Deserialize)]
#[serde(tag = "kind")]
enum Wire {
    NonFinite {
        what: String,
        #[serde(with = "float")]
        value: f64,
    },
    NonFiniteModel {
        what: String,
        #[serde(with = "float::array")]
        gamma: [f64; 3],
    },
    NonUnitGamma {
        what: String,
        #[serde(with = "float")]
        norm: f64,
        #[serde(with = "float")]
        tol: f64,
    },
    KineticNotPositiveDefinite {
        #[serde(with = "float::array")]
        gamma: [f64; 3],
        #[serde(with = "float")]
        min_eigenvalue: f64,
    },
    DegenerateVerticalInertia {
        #[serde(with = "float::array")]
        gamma: [f64; 3],
        #[serde(with = "float")]
        value: f64,
    },
    SingularReducedKinetic {
        #[serde(with = "float::array")]
        gamma: [f64; 3],
        #[serde(with = "float")]
        min_eigenvalue: f64,
    },
    NotASteadyMotion {
        #[serde(with = "float::array")]
        gamma: [f64; 3],
        #[serde(with = "float")]
        residual: f64,
        #[serde(with = "float")]
        tol: f64,
    },
    InvalidModel {
        what: String,
        reason: String,
    },
    AtParameter {
        #[serde(with = "float")]
        s: f64,
        source: Box<RouthError>,
    },
    InvalidOption {
        what: String,
        reason: String,
    },
    StepSizeUnderflow {
        #[serde(with = "float")]
        t: f64,
        #[serde(with = "float")]
        h: f64,
    },
    TooManySteps {
        #[serde(with = "float")]
        t: f64,
        steps: usize,
    },
    NonFiniteState {
        #[serde(with = "float")]
        t: f64,
    },
    NoConvergence {
        what: String,
        iterations: usize,
        #[serde(with = "float")]
        residual: f64,
    },
    Interrupted,
}

impl From<&RouthError> for Wire {
    fn from(e: &RouthError) -> Wire {
        use RouthError as E;
        let name = |s: &&str| (*s).to_owned();
        match e {
            E::NonFinite { what, value } => Wire::NonFinite {
                what: name(what),
                value: *value,
            },
            E::NonFiniteModel { what, gamma } => Wire::NonFiniteModel {
                what: name(what),
                gamma: *gamma,
            },
            E::NonUnitGamma { what, norm, tol } => Wire::NonUnitGamma {
                what: name(what),
                norm: *norm,
                tol: *tol,
            },
            E::KineticNotPositiveDefinite {
                gamma,
                min_eigenvalue,
            } => Wire::KineticNotPositiveDefinite {
                gamma: *gamma,
                min_eigenvalue: *min_eigenvalue,
            },
            E::DegenerateVerticalInertia { gamma, value } => Wire::DegenerateVerticalInertia {
                gamma: *gamma,
                value: *value,
            },
            E::SingularReducedKinetic {
                gamma,
                min_eigenvalue,
            } => Wire::SingularReducedKinetic {
                gamma: *gamma,
                min_eigenvalue: *min_eigenvalue,
            },
            E::NotASteadyMotion {
                gamma,
                residual,
                tol,
            } => Wire::NotASteadyMotion {
                gamma: *gamma,
                residual: *residual,
                tol: *tol,
            },
            E::InvalidModel { what, reason } => Wire::InvalidModel {
                what: name(what),
                reason: reason.clone(),
            },
            E::AtParameter { s, source } => Wire::AtParameter {
                s: *s,
                source: source.clone(),
            },
            E::InvalidOption { what, reason } => Wire::InvalidOption {
                what: name(what),
                reason: reason.clone(),
            },
            E::StepSizeUnderflow { t, h } => Wire::StepSizeUnderflow { t: *t, h: *h },
            E::TooManySteps { t, steps } => Wire::TooManySteps {
                t: *t,
                steps: *steps,
            },
            E::NonFiniteState { t } => Wire::NonFiniteState { t: *t },
            E::NoConvergence {
                what,
                iterations,
                residual,
            } => Wire::NoConvergence {
                what: name(what),
                iterations: *iterations,
                residual: *residual,
            },
            E::Interrupted => Wire::Interrupted,
        }
    }
}

impl From<Wire> for RouthError {
    fn from(w: Wire) -> RouthError {
        use RouthError as E;
        match w {
            Wire::NonFinite { what, value } => E::NonFinite {
                what: intern(&what),
                value,
            },
            Wire::NonFiniteModel { what, gamma } => E::NonFiniteModel {
                what: intern(&what),
                gamma,
            },
            Wire::NonUnitGamma { what, norm, tol } => E::NonUnitGamma {
                what: intern(&what),
                norm,
                tol,
            },
            Wire::KineticNotPositiveDefinite {
                gamma,
                min_eigenvalue,
            } => E::KineticNotPositiveDefinite {
                gamma,
                min_eigenvalue,
            },
            Wire::DegenerateVerticalInertia { gamma, value } => {
                E::DegenerateVerticalInertia { gamma, value }
            }
            Wire::SingularReducedKinetic {
                gamma,
                min_eigenvalue,
            } => E::SingularReducedKinetic {
                gamma,
                min_eigenvalue,
            },
            Wire::NotASteadyMotion {
                gamma,
                residual,
                tol,
            } => E::NotASteadyMotion {
                gamma,
                residual,
                tol,
            },
            Wire::InvalidModel { what, reason } => E::InvalidModel {
                what: intern(&what),
                reason,
            },
            Wire::AtParameter { s, source } => E::AtParameter { s, source },
            Wire::InvalidOption { what, reason } => E::InvalidOption {
                what: intern(&what),
                reason,
            },
            Wire::StepSizeUnderflow { t, h } => E::StepSizeUnderflow { t, h },
            Wire::TooManySteps { t, steps } => E::TooManySteps { t, steps },
            Wire::NonFiniteState { t } => E::NonFiniteState { t },
            Wire::NoConvergence {
                what,
                iterations,
                residual,
            } => E::NoConvergence {
                what: intern(&what),
                iterations,
                residual,
            },
            Wire::Interrupted => E::Interrupted,
        }
    }
}

/// What is written: the variant with its fields, and the message.
#[derive(Serialize)]
struct Written {
    #[serde(flatten)]
    error: Wire,
    message: String,
}

/// What is read: the variant with its fields (`message`, if present, is ignored).
#[derive(Deserialize)]
struct Read {
    #[serde(flatten)]
    error: Wire,
}

impl Serialize for RouthError {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        Written {
            error: Wire::from(self),
            message: self.to_string(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for RouthError {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Read::deserialize(d).map(|r| r.error.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_interned_once_and_bounded() {
        let a = intern("gamma0");
        let b = intern(&String::from("gamma0"));
        assert!(std::ptr::eq(a, b));
        let long = "é".repeat(MAX_NAME_LEN);
        let cut = intern(&long);
        assert!(cut.len() <= MAX_NAME_LEN && long.starts_with(cut));
    }
}
