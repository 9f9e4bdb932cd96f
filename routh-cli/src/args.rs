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
/// momentum p_ψ; a parameter of the model is named by its symbol in the model's `[latex]` table
/// where it has one (`mass = "m"` gives `m`, `a1 = "A_1"` gives `A₁`), else by its name.
pub fn axis_name(quantity: &str, symbols: &std::collections::BTreeMap<String, String>) -> String {
    if quantity == "momentum" {
        "cyclic momentum p_ψ".to_string()
    } else {
        symbols
            .get(quantity)
            .and_then(|s| plain_symbol(s))
            .unwrap_or_else(|| quantity.to_string())
    }
}

/// A LaTeX symbol as plain text with Unicode letters (`\omega_0` → `ω₀`, `A_1` → `A₁`,
/// `m_{2}` → `m₂`), or `None` when it holds what plain text cannot show (other commands,
/// subscripts other than digits, superscripts).
pub fn plain_symbol(latex: &str) -> Option<String> {
    const GREEK: [(&str, char); 34] = [
        ("alpha", 'α'),
        ("beta", 'β'),
        ("gamma", 'γ'),
        ("delta", 'δ'),
        ("epsilon", 'ε'),
        ("varepsilon", 'ε'),
        ("zeta", 'ζ'),
        ("eta", 'η'),
        ("theta", 'θ'),
        ("iota", 'ι'),
        ("kappa", 'κ'),
        ("lambda", 'λ'),
        ("mu", 'μ'),
        ("nu", 'ν'),
        ("xi", 'ξ'),
        ("pi", 'π'),
        ("rho", 'ρ'),
        ("sigma", 'σ'),
        ("tau", 'τ'),
        ("phi", 'φ'),
        ("varphi", 'φ'),
        ("chi", 'χ'),
        ("psi", 'ψ'),
        ("omega", 'ω'),
        ("Gamma", 'Γ'),
        ("Delta", 'Δ'),
        ("Theta", 'Θ'),
        ("Lambda", 'Λ'),
        ("Xi", 'Ξ'),
        ("Pi", 'Π'),
        ("Sigma", 'Σ'),
        ("Phi", 'Φ'),
        ("Psi", 'Ψ'),
        ("Omega", 'Ω'),
    ];
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    let mut out = String::new();
    let mut chars = latex.trim().chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let mut name = String::new();
                while let Some(&l) = chars.peek().filter(|l| l.is_ascii_alphabetic()) {
                    name.push(l);
                    chars.next();
                }
                out.push(GREEK.iter().find(|g| g.0 == name)?.1);
            }
            '_' => {
                let mut sub = String::new();
                if chars.peek() == Some(&'{') {
                    chars.next();
                    for l in chars.by_ref() {
                        if l == '}' {
                            break;
                        }
                        sub.push(l);
                    }
                } else {
                    sub.push(chars.next()?);
                }
                if sub.is_empty() || !sub.chars().all(|d| d.is_ascii_digit()) {
                    return None;
                }
                out.extend(
                    sub.chars()
                        .map(|d| SUB[d.to_digit(10).unwrap_or(0) as usize]),
                );
            }
            '{' | '}' => {}
            '^' | '$' => return None,
            c => out.push(c),
        }
    }
    (!out.is_empty()).then_some(out)
}

/// A figure's printed width: `column` (3.4 in), `page` (7 in) or a number of inches.
pub fn figure_width(s: &str) -> Result<f64, String> {
    let w = match s.trim() {
        "column" => routh::style::COLUMN_WIDTH_IN,
        "page" => routh::style::PAGE_WIDTH_IN,
        other => finite(other.trim_end_matches("in")).map_err(|_| {
            format!("`{s}` is not a width: `column` (3.4 in), `page` (7 in) or inches, e.g. 5.5")
        })?,
    };
    if (2.8..=40.0).contains(&w) {
        Ok(w)
    } else {
        Err(format!("a figure {w} in wide: from 2.8 to 40 in"))
    }
}

/// A font size in points, 5 to 24.
pub fn font_size(s: &str) -> Result<f64, String> {
    let pt = finite(s.trim().trim_end_matches("pt"))?;
    if (5.0..=24.0).contains(&pt) {
        Ok(pt)
    } else {
        Err(format!("a font of {pt} pt: from 5 to 24"))
    }
}

/// `KEY=VALUE` of `--opt`: the value read as JSON (`1e-9`, `true`, `[0, 2]`, `null`), or as a
/// string when it is not JSON (`--opt method=LieRk4`).
pub fn opt(s: &str) -> Result<(String, serde_json::Value), String> {
    let (key, value) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}` is not KEY=VALUE"))?;
    let key = key.trim();
    if key.is_empty() {
        return Err(format!("`{s}`: the key is empty"));
    }
    let value = value.trim();
    let value = serde_json::from_str(value)
        .unwrap_or_else(|_| serde_json::Value::String(value.to_string()));
    Ok((key.to_string(), value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_and_figure_values() {
        assert_eq!(plain_symbol("A_1").as_deref(), Some("A₁"));
        assert_eq!(plain_symbol("\\omega_{0}").as_deref(), Some("ω₀"));
        assert_eq!(plain_symbol("m").as_deref(), Some("m"));
        assert_eq!(plain_symbol("x^2"), None);
        assert_eq!(plain_symbol("\\mathrm{m}"), None);
        assert_eq!(plain_symbol("r_c"), None);
        let symbols = [("mass".to_string(), "m".to_string())].into();
        assert_eq!(axis_name("mass", &symbols), "m");
        assert_eq!(axis_name("length", &symbols), "length");
        assert_eq!(figure_width("column"), Ok(3.4));
        assert_eq!(figure_width("page"), Ok(7.0));
        assert_eq!(figure_width("5.5in"), Ok(5.5));
        assert!(figure_width("1").is_err() && figure_width("wide").is_err());
        assert_eq!(font_size("9"), Ok(9.0));
        assert!(font_size("2").is_err() && font_size("NaN").is_err());
    }

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
