//! An analysis's options struct as its keyword surface: `key = value` pairs (Python keywords,
//! the command line's `--opt key=value`) laid over the struct's `Default` (or another base)
//! through its serde form, so that the defaults are written once, in the struct.
//!
//! The keys are the struct's fields; the fields of a nested options struct (`orbit` in
//! [`OrbitChartOptions`]) are keys too, by their own names (or `orbit.max_orbits`). A key the
//! struct does not have is an [`OptionError::Unknown`] naming the valid ones; a value of the
//! wrong type an [`OptionError::Invalid`] naming the key; `null` is the default. The values
//! themselves are checked by the analysis, as for any options struct.
//!
//! ```
//! use routh::options::overlay;
//! use routh::OrbitOptions;
//! use serde_json::json;
//!
//! let read = serde_json::from_value;
//! let o: OrbitOptions = overlay(OrbitOptions::default(), [("max_orbits", json!(3))], read).unwrap();
//! assert_eq!(o.max_orbits, 3);
//! let e = overlay(OrbitOptions::default(), [("max_orbit", json!(3))], read).unwrap_err();
//! assert!(e.to_string().contains("did you mean `max_orbits`"));
//! ```

use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::{Map, Value};
use std::fmt;

use crate::{
    AtlasOptions, ContinuationOptions, NonlinearOptions, OrbitChartOptions, OrbitNonlinearOptions,
    OrbitOptions, SectionOptions, SimOptions,
};

/// An options struct whose fields are keywords.
pub trait Options: Serialize + DeserializeOwned + Default {
    /// The fields that are not keywords: the chart's energy bounds are its energies above each
    /// steady motion and its families are always `nonlinear`; a simulation's `output` is the
    /// faces' `times`.
    const FIXED: &'static [&'static str] = &[];

    /// The value of `key` as the struct holds it, from the value given (the aliases of the
    /// faces; default: as given).
    fn value(key: &str, given: Value) -> Value {
        let _ = key;
        given
    }
}

/// `nonlinear = true` for the `Option<NonlinearOptions>` of diagrams and atlases: the nonlinear
/// events located with `NonlinearOptions::default()` (`false`: not located).
fn nonlinear_switch(key: &str, given: Value) -> Value {
    match (key, &given) {
        ("nonlinear", Value::Bool(true)) => {
            serde_json::to_value(NonlinearOptions::default()).unwrap_or(given)
        }
        ("nonlinear", Value::Bool(false)) => Value::Null,
        _ => given,
    }
}

impl Options for OrbitOptions {}
impl Options for OrbitNonlinearOptions {}
impl Options for OrbitChartOptions {
    const FIXED: &'static [&'static str] = &["energy_bounds", "nonlinear"];
}
impl Options for ContinuationOptions {
    fn value(key: &str, given: Value) -> Value {
        nonlinear_switch(key, given)
    }
}
impl Options for AtlasOptions {
    fn value(key: &str, given: Value) -> Value {
        nonlinear_switch(key, given)
    }
}
impl Options for SimOptions {
    const FIXED: &'static [&'static str] = &["output"];
}
impl Options for SectionOptions {}
impl Options for NonlinearOptions {}

/// Why pairs could not be laid over an options struct.
#[derive(Debug, Clone, PartialEq)]
pub enum OptionError {
    /// A key that is not a field.
    Unknown {
        /// The key given.
        key: String,
        /// The nearest valid key, if one is near.
        suggestion: Option<String>,
        /// Every valid key.
        valid: Vec<String>,
    },
    /// A value the field cannot hold (a string for a number, a negative count, …).
    Invalid {
        /// The key given.
        key: String,
        /// serde's words: what was given, what was expected.
        message: String,
    },
}

impl fmt::Display for OptionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OptionError::Unknown {
                key,
                suggestion,
                valid,
            } => {
                write!(f, "unknown option `{key}`")?;
                if let Some(s) = suggestion {
                    write!(f, " (did you mean `{s}`?)")?;
                }
                write!(f, "; the options are {}", valid.join(", "))
            }
            OptionError::Invalid { key, message } => write!(f, "option `{key}`: {message}"),
        }
    }
}

impl std::error::Error for OptionError {}

/// The keys of `T` with their default values, sorted by name (a field of a nested struct by its
/// own name, or by its path `outer.field` when two nested structs have it).
pub fn keywords<T: Options>() -> Vec<(String, Value)> {
    let Ok(Value::Object(top)) = serde_json::to_value(T::default()) else {
        return Vec::new();
    };
    let mut out: Vec<(String, Value)> = Vec::new();
    let mut add = |k: &String, v: &Value| {
        if !T::FIXED.contains(&k.as_str()) && !out.iter().any(|(o, _)| o == k) {
            out.push((k.clone(), v.clone()));
        }
    };
    for (k, v) in &top {
        match v {
            Value::Object(inner) => {
                for (ik, iv) in inner.iter().filter(|(ik, _)| !top.contains_key(*ik)) {
                    if nested(&top, ik).len() == 1 {
                        add(ik, iv);
                    } else {
                        add(&format!("{k}.{ik}"), iv);
                    }
                }
            }
            _ => add(k, v),
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The nested structs that have a field `key`.
fn nested<'a>(top: &'a Map<String, Value>, key: &str) -> Vec<&'a String> {
    top.iter()
        .filter(|(_, v)| v.as_object().is_some_and(|m| m.contains_key(key)))
        .map(|(k, _)| k)
        .collect()
}

/// Where a key lives in the serde form: `[field]` or `[nested, field]` (a field of two nested
/// structs by its path only).
fn path(top: &Map<String, Value>, key: &str) -> Option<Vec<String>> {
    if let Some((outer, inner)) = key.split_once('.') {
        return match top.get(outer) {
            Some(Value::Object(m)) if m.contains_key(inner) => {
                Some(vec![outer.to_string(), inner.to_string()])
            }
            _ => None,
        };
    }
    if top.get(key).is_some_and(|v| !v.is_object()) {
        return Some(vec![key.to_string()]);
    }
    match nested(top, key)[..] {
        [outer] => Some(vec![outer.clone(), key.to_string()]),
        _ => None,
    }
}

fn get(top: &Map<String, Value>, at: &[String]) -> Value {
    let v = match at {
        [k] => top.get(k),
        [outer, inner] => top.get(outer).and_then(|m| m.get(inner)),
        _ => None,
    };
    v.cloned().unwrap_or(Value::Null)
}

fn set(top: &mut Map<String, Value>, at: &[String], value: Value) {
    match at {
        [k] => {
            top.insert(k.clone(), value);
        }
        [outer, inner] => {
            if let Some(Value::Object(m)) = top.get_mut(outer) {
                m.insert(inner.clone(), value);
            }
        }
        _ => {}
    }
}

/// The number of single-character edits between `a` and `b`.
fn edits(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let here = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(here + 1);
            prev = here;
        }
    }
    row[b.len()]
}

fn unknown<T: Options>(key: &str) -> OptionError {
    let valid: Vec<String> = keywords::<T>().into_iter().map(|(k, _)| k).collect();
    let suggestion = valid
        .iter()
        .map(|v| (edits(key, v), v))
        .filter(|(d, v)| *d <= 2.max(v.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, v)| v.clone());
    OptionError::Unknown {
        key: key.to_string(),
        suggestion,
        valid,
    }
}

/// `base` with the `pairs` laid over it (see the module), the result read by `read`:
/// `serde_json::from_value`, or a deserializer that also takes, say, `"NaN"` for a number. With
/// pairs, the fields serde skips (`control`) are their defaults: set them after.
pub fn overlay<T, K>(
    base: T,
    pairs: impl IntoIterator<Item = (K, Value)>,
    read: impl Fn(Value) -> Result<T, serde_json::Error>,
) -> Result<T, OptionError>
where
    T: Options,
    K: AsRef<str>,
{
    let invalid = |key: &str, e: &dyn fmt::Display| OptionError::Invalid {
        key: key.to_string(),
        message: e.to_string(),
    };
    let form = |t: &T| match serde_json::to_value(t) {
        Ok(Value::Object(m)) => Ok(m),
        Ok(_) => Err(invalid("", &"the options are not a struct")),
        Err(e) => Err(invalid("", &e)),
    };
    // Where each key lives is read from the default (a field that is `None` there and a struct
    // in `base` is one key still).
    let shape = form(&T::default())?;
    let start = form(&base)?;
    let mut all = start.clone();
    let mut given = Vec::new();
    for (key, value) in pairs {
        let key = key.as_ref();
        let at = path(&shape, key)
            .filter(|at| !T::FIXED.contains(&at[at.len() - 1].as_str()))
            .filter(|at| at.len() == 1 || !shape.contains_key(&at[1]))
            .ok_or_else(|| unknown::<T>(key))?;
        // `null` is the default (`None` in Python: a keyword not given).
        let value = match value {
            Value::Null => get(&shape, &at),
            v => T::value(key, v),
        };
        set(&mut all, &at, value.clone());
        given.push((key.to_string(), at, value));
    }
    if given.is_empty() {
        return Ok(base);
    }
    match read(Value::Object(all)) {
        Ok(t) => Ok(t),
        Err(whole) => {
            // The first key whose value alone the struct refuses.
            for (key, at, value) in given {
                let mut one = start.clone();
                set(&mut one, &at, value);
                if let Err(e) = read(Value::Object(one)) {
                    return Err(invalid(&key, &e));
                }
            }
            Err(invalid("", &whole))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_nested_field_is_a_key_by_its_own_name_and_by_its_path() {
        let c: OrbitChartOptions = overlay(
            OrbitChartOptions::default(),
            [
                ("max_orbits", json!(7)),
                ("orbit.rtol", json!(1e-9)),
                ("nx", json!(5)),
            ],
            serde_json::from_value,
        )
        .unwrap();
        assert_eq!((c.orbit.max_orbits, c.orbit.rtol, c.nx), (7, 1e-9, 5));
        // The rest is the default.
        assert_eq!(c.join_tol, OrbitChartOptions::default().join_tol);
        assert_eq!(c.orbit.atol, OrbitOptions::default().atol);
    }

    #[test]
    fn the_keys_are_the_fields_less_the_fixed_ones() {
        let keys: Vec<String> = keywords::<OrbitChartOptions>()
            .into_iter()
            .map(|(k, _)| k)
            .collect();
        assert!(keys.contains(&"nx".to_string()) && keys.contains(&"max_orbits".to_string()));
        assert!(!keys.contains(&"orbit".to_string()));
        assert!(!keys.contains(&"energy_bounds".to_string()));
        let e = overlay(
            OrbitChartOptions::default(),
            [("nonlinear", json!(true))],
            serde_json::from_value,
        )
        .unwrap_err();
        assert!(matches!(e, OptionError::Unknown { .. }), "{e}");
        // The chart's own default of a nested field, not the nested struct's.
        let d: Vec<(String, Value)> = keywords::<OrbitChartOptions>();
        assert!(d.contains(&("max_orbits".to_string(), json!(200))));
    }

    #[test]
    fn an_unknown_key_names_itself_a_near_one_and_the_valid_ones() {
        let e = overlay(
            OrbitNonlinearOptions::default(),
            [("twist_toll", json!(1e-3))],
            serde_json::from_value,
        )
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("unknown option `twist_toll` (did you mean `twist_tol`?)"));
        assert!(
            e.contains("resonance_tol") && e.contains("max_steps"),
            "{e}"
        );
        let e = overlay(
            OrbitOptions::default(),
            [("zzz", json!(1))],
            serde_json::from_value,
        )
        .unwrap_err();
        assert!(
            matches!(
                e,
                OptionError::Unknown {
                    suggestion: None,
                    ..
                }
            ),
            "{e}"
        );
    }

    #[test]
    fn a_value_of_the_wrong_type_names_its_key() {
        let e = overlay(
            OrbitOptions::default(),
            [("rtol", json!(1e-9)), ("max_orbits", json!("many"))],
            serde_json::from_value,
        )
        .unwrap_err();
        let OptionError::Invalid { key, message } = &e else {
            panic!("{e}")
        };
        assert_eq!(key, "max_orbits");
        assert!(
            message.contains("invalid type: string \"many\""),
            "{message}"
        );
        let e = overlay(
            OrbitOptions::default(),
            [("energy_bounds", json!([1.0, true]))],
            serde_json::from_value,
        );
        assert!(e.unwrap_err().to_string().contains("energy_bounds"));
    }

    #[test]
    fn no_pairs_give_the_base_itself() {
        let base = OrbitOptions::default().with_max_orbits(9);
        let o = overlay(
            base.clone(),
            Vec::<(String, Value)>::new(),
            serde_json::from_value,
        )
        .unwrap();
        assert_eq!(o, base);
        let o = overlay(base, [("nonlinear", json!(true))], serde_json::from_value).unwrap();
        assert_eq!((o.max_orbits, o.nonlinear), (9, true));
        // null is the default, not the base's value.
        let o = overlay(o, [("max_orbits", Value::Null)], serde_json::from_value).unwrap();
        assert_eq!(o.max_orbits, OrbitOptions::default().max_orbits);
    }

    #[test]
    fn nonlinear_true_is_the_default_nonlinear_options_of_a_diagram() {
        let c: ContinuationOptions = overlay(
            ContinuationOptions::default(),
            [("nonlinear", json!(true))],
            serde_json::from_value,
        )
        .unwrap();
        assert_eq!(c.nonlinear, Some(NonlinearOptions::default()));
        let c: ContinuationOptions =
            overlay(c, [("nonlinear", json!(false))], serde_json::from_value).unwrap();
        assert_eq!(c.nonlinear, None);
        // A nested struct's fields are keys: the classification's and the search's.
        let keys: Vec<String> = keywords::<ContinuationOptions>()
            .into_iter()
            .map(|(k, _)| k)
            .collect();
        assert!(keys.contains(&"starts".to_string()), "{keys:?}");
        // One name in two nested structs: a key by its path only.
        assert!(
            keys.contains(&"classify.zero_eigenvalue_tol".to_string()),
            "{keys:?}"
        );
        assert!(
            !keys.contains(&"zero_eigenvalue_tol".to_string()),
            "{keys:?}"
        );
        let c: ContinuationOptions = overlay(
            ContinuationOptions::default(),
            [("classify.zero_eigenvalue_tol", json!(1e-6))],
            serde_json::from_value,
        )
        .unwrap();
        assert_eq!(c.classify.zero_eigenvalue_tol, 1e-6);
        assert_eq!(c.search, ContinuationOptions::default().search);
        let mut sorted = keys.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), keys.len(), "a key listed twice: {keys:?}");
    }
}
