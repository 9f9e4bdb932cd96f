//! Floats that may be NaN or infinite, in JSON.
//!
//! JSON has no NaN or ∞ (serde_json writes them as `null` and cannot read `null` back as an
//! `f64`). Fields documented as possibly non-finite (the frequencies of an unstable
//! [`NonlinearReport`](crate::NonlinearReport), the endpoints of an unbounded
//! [`Interval`](crate::certify::Interval), the offending value of
//! [`RouthError::NonFinite`](crate::RouthError::NonFinite), …) use this module
//! (`#[serde(with = "crate::serde_support::float")]`): in human-readable formats a non-finite
//! value is the string `"NaN"`, `"Infinity"` or `"-Infinity"` (the convention of the protobuf
//! JSON mapping), a finite one an ordinary number; `null` reads back as NaN. Binary formats get
//! the `f64` unchanged.

use std::fmt;

use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::ser::{SerializeTuple, Serializer};

/// The text of a non-finite value, `None` for a finite one.
fn non_finite_name(x: f64) -> Option<&'static str> {
    if x.is_nan() {
        Some("NaN")
    } else if x == f64::INFINITY {
        Some("Infinity")
    } else if x == f64::NEG_INFINITY {
        Some("-Infinity")
    } else {
        None
    }
}

/// Writes `x`: a number, or in a human-readable format `"NaN"`, `"Infinity"`, `"-Infinity"`.
pub(crate) fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
    match non_finite_name(*x) {
        Some(name) if s.is_human_readable() => s.serialize_str(name),
        _ => s.serialize_f64(*x),
    }
}

/// Reads a number, `"NaN"`, `"Infinity"`, `"-Infinity"` (also `"inf"`, `"-inf"`, any case) or
/// `null` (NaN).
pub(crate) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    if d.is_human_readable() {
        d.deserialize_any(FloatVisitor)
    } else {
        d.deserialize_f64(FloatVisitor)
    }
}

struct FloatVisitor;

impl<'de> Visitor<'de> for FloatVisitor {
    type Value = f64;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number, \"NaN\", \"Infinity\", \"-Infinity\" or null")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<f64, E> {
        Ok(v)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<f64, E> {
        match v.to_ascii_lowercase().as_str() {
            "nan" => Ok(f64::NAN),
            "infinity" | "inf" | "+infinity" | "+inf" => Ok(f64::INFINITY),
            "-infinity" | "-inf" => Ok(f64::NEG_INFINITY),
            _ => Err(E::invalid_value(de::Unexpected::Str(v), &self)),
        }
    }
    fn visit_unit<E: de::Error>(self) -> Result<f64, E> {
        Ok(f64::NAN)
    }
    fn visit_none<E: de::Error>(self) -> Result<f64, E> {
        Ok(f64::NAN)
    }
}

/// A float read and written by this module, for use inside containers.
#[derive(Clone, Copy)]
pub(crate) struct Float(pub f64);

impl serde::Serialize for Float {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        serialize(&self.0, s)
    }
}

impl<'de> serde::Deserialize<'de> for Float {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        deserialize(d).map(Float)
    }
}

/// `[f64; N]` whose entries may be non-finite: a tuple (a JSON array) of entries written as by
/// [`serialize`](self::serialize).
pub(crate) mod array {
    use super::*;

    /// Writes the array as a tuple of [`Float`]s.
    pub(crate) fn serialize<S: Serializer, const N: usize>(
        x: &[f64; N],
        s: S,
    ) -> Result<S::Ok, S::Error> {
        let mut t = s.serialize_tuple(N)?;
        for v in x {
            t.serialize_element(&Float(*v))?;
        }
        t.end()
    }

    /// Reads exactly `N` entries.
    pub(crate) fn deserialize<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<[f64; N], D::Error> {
        d.deserialize_tuple(N, ArrayVisitor::<N>)
    }

    struct ArrayVisitor<const N: usize>;

    impl<'de, const N: usize> Visitor<'de> for ArrayVisitor<N> {
        type Value = [f64; N];

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            write!(f, "an array of {N} numbers")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[f64; N], A::Error> {
            let mut out = [0.0; N];
            for (i, slot) in out.iter_mut().enumerate() {
                let Float(v) = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(i, &self))?;
                *slot = v;
            }
            if seq.next_element::<de::IgnoredAny>()?.is_some() {
                return Err(de::Error::invalid_length(N + 1, &self));
            }
            Ok(out)
        }
    }
}
