//! Parsers of the command line's values: finite numbers, ranges `LO..HI`, named ranges
//! `NAME=LO..HI` and vectors `X,Y,Z`. Each rejects NaN, infinities and inverted ranges with a
//! message naming the problem (clap turns it into a usage error, exit code 2).

/// A finite number.
pub fn finite(s: &str) -> Result<f64, String> {
    let x: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("`{s}` is not a finite number"))
    }
}

/// A finite number above 0 (a time, an absolute tolerance).
pub fn positive(s: &str) -> Result<f64, String> {
    let x = finite(s)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(format!("`{s}` must be above 0"))
    }
}

/// A relative tolerance: above 0 and below 1.
pub fn relative_tolerance(s: &str) -> Result<f64, String> {
    let x = finite(s)?;
    if x > 0.0 && x < 1.0 {
        Ok(x)
    } else {
        Err(format!(
            "`{s}` is not a relative tolerance (above 0 and below 1, e.g. 1e-10)"
        ))
    }
}

/// A range `LO..HI` of finite numbers with `LO < HI`.
pub fn range(s: &str) -> Result<(f64, f64), String> {
    let (lo, hi) = s
        .split_once("..")
        .ok_or_else(|| format!("`{s}` is not a range LO..HI"))?;
    if hi.trim_start().starts_with('.') {
        // `0...1` would read as 0..0.1.
        return Err(format!(
            "`{s}` is not a range LO..HI: two dots between the bounds (write a bound `.5` as `0.5`)"
        ));
    }
    let (lo, hi) = (finite(lo)?, finite(hi)?);
    if lo < hi {
        Ok((lo, hi))
    } else {
        Err(format!(
            "the range `{s}` is empty or inverted (LO must be below HI)"
        ))
    }
}

/// A range over a named quantity: `NAME=LO..HI`.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedRange {
    /// A parameter of the model, or `momentum`.
    pub name: String,
    /// `(LO, HI)`, `LO < HI`.
    pub range: (f64, f64),
}

/// Parses `NAME=LO..HI`.
pub fn named_range(s: &str) -> Result<NamedRange, String> {
    let (name, r) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}` is not NAME=LO..HI"))?;
    let name = name.trim();
    if name.is_empty() {
        return Err(format!("`{s}` has no name before `=`"));
    }
    Ok(NamedRange {
        name: name.to_string(),
        range: range(r)?,
    })
}

/// A vector `X,Y,Z` of finite numbers.
pub fn vec3(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(format!("`{s}` is not a vector X,Y,Z (three numbers)"));
    }
    Ok([finite(parts[0])?, finite(parts[1])?, finite(parts[2])?])
}

/// The name of a figure's axis for a quantity of the command line: `momentum` is the cyclic
/// momentum p_ψ, anything else a parameter of the model.
pub fn axis_name(quantity: &str) -> String {
    if quantity == "momentum" {
        "cyclic momentum p_ψ".to_string()
    } else {
        format!("parameter {quantity}")
    }
}

/// The model's name in a figure's title: the file name without its extension.
pub fn model_name(path: &std::path::Path) -> String {
    path.file_stem()
        .map_or_else(|| "model".to_string(), |s| s.to_string_lossy().into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        assert_eq!(range("0..5"), Ok((0.0, 5.0)));
        assert_eq!(range("-1.5..2e0"), Ok((-1.5, 2.0)));
        assert!(range("5..0").is_err());
        assert!(range("1..1").is_err());
        assert!(range("NaN..1").is_err());
        assert!(range("0..inf").is_err());
        assert!(range("0-1").is_err());
        assert_eq!(named_range("c=1..2").map(|n| n.name), Ok("c".to_string()));
        assert!(named_range("=1..2").is_err());
        assert_eq!(vec3("0, 0.1,1"), Ok([0.0, 0.1, 1.0]));
        assert!(vec3("0,1").is_err());
        assert!(finite("nan").is_err());
    }
}
