//! The derived formulas of a model in LaTeX ([`LatexFormulas`]) and in SymPy's syntax ([`SympyFormulas`]), as returned by
//! [`DerivedFormulas::latex`](crate::DerivedFormulas::latex) for a `#[derive(Lagrangian)]`
//! model (and by run-time models, which print them from the same expression graph).

/// The formulas that the symbolic engine derived for a model, in LaTeX (math mode, without
/// delimiters), printed from the same expression graph as the generated code.
///
/// Order: in a product the number first, then the parameters (in the order of the model's
/// fields), then `\omega_1 \omega_2 \omega_3`, `\gamma_1 \gamma_2 \gamma_3`, `p_\psi`, then the
/// rest; a sum by decreasing degree in ω (or Ω), γ and p_ψ, terms of equal degree by their
/// exponents of ω₁ … γ₃, p_ψ in that order (`\omega_1^{2} + \omega_1 \omega_2`), then by their
/// parameters, with a leading negative term put after the first positive one (`1 - \gamma_3^{2}`).
///
/// Symbols: `\omega_i` (or `\Omega_i` in functions of the relative angular velocity),
/// `\gamma_i`, `p_\psi`; each parameter as its name in `\mathit{…}` unless the model gives it a
/// symbol (`#[lagrangian(latex = "I")]` on the field), components subscripted from 1
/// (`I_{11}`, `\mathit{com}_{3}`). Functions of γ are simplified with `|γ|² = 1` where that
/// shortens them (they are then equal to the generated code on the sphere only). The matrices
/// A, G, C are written entry by entry with the paper's intermediate quantities named and
/// defined after the matrix: `\gamma^{\mathsf{T}} J \gamma` (the denominator of (38)),
/// `\dot\psi` (ψ̇ at rest, (38)) and `\mu = (∂R/∂γ, γ)` (errata E6), as far as the matrix uses
/// them. A long formula (more than 250 nodes of expression tree; a matrix: more than 1000 in all
/// its entries) comes with its common subexpressions named and defined after it too:
/// `… \quad \text{where} \quad \sigma_{1} = …,\; \sigma_{2} = …` (each definition uses only the
/// names before it). A formula too large even so is replaced by a `\text{(… not printed)}`.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LatexFormulas {
    /// `L(ω, γ)`.
    pub lagrangian: String,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38).
    pub psi_dot: String,
    /// The Routh function `R(Ω, γ, p_ψ)` of (14).
    pub routhian: String,
    /// The amended potential (34) `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`.
    pub amended_potential: String,
    /// `A = ∂²R/∂Ω²` at Ω = 0 (64), a `pmatrix`.
    pub a: String,
    /// The gyroscopic matrix `G` of (64) at Ω = 0, a `pmatrix`.
    pub g: String,
    /// The stiffness matrix `C` of (64) at Ω = 0, a `pmatrix`.
    pub c: String,
}

/// The derived formulas of [`LatexFormulas`] in SymPy's syntax (Python's infix: `*`, `/`,
/// `**`, `sqrt(…)`), to parse with `sympy.sympify` and keep computing: the same expressions,
/// in the same canonical order, simplified on the sphere the same way.
///
/// Symbols: `omega1 omega2 omega3` (`Omega1 …` in ψ̇ and R, functions of the relative angular
/// velocity), `gamma1 gamma2 gamma3`, `p_psi`; each parameter by its field's name (`mgl`),
/// components with indices from 1 (`inertia_1`, `I_12`), as in the LaTeX, unless that is not a
/// free Python identifier (`lambda`, `sin`, `nan`: see [`SympyFormulas::symbols`]). Matrices are
/// `Matrix([[…], […], […]])`. A formula is written out in full unless its expression tree is
/// very large (more than 20 000 nodes); then it refers to named subexpressions `sigma1`,
/// `sigma2`, … defined in [`SympyFormulas::definitions`], in order, each using only the names
/// before it. Python's `routh.Model.to_sympy()` substitutes them (and reads a sum of any
/// length, which Python's own parser, and so `sympify`, refuses beyond about a thousand terms).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SympyFormulas {
    /// `L(ω, γ)`.
    pub lagrangian: String,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38).
    pub psi_dot: String,
    /// The Routh function `R(Ω, γ, p_ψ)` of (14).
    pub routhian: String,
    /// The amended potential (34) `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`.
    pub amended_potential: String,
    /// `A = ∂²R/∂Ω²` at Ω = 0 (64), a `Matrix`.
    pub a: String,
    /// The gyroscopic matrix `G` of (64) at Ω = 0, a `Matrix`.
    pub g: String,
    /// The stiffness matrix `C` of (64) at Ω = 0, a `Matrix`.
    pub c: String,
    /// `(name, expression)` of the named subexpressions, in order (empty when every formula is
    /// written out in full).
    pub definitions: Vec<(String, String)>,
    /// `(identifier, name)` of every symbol the text may use, the state's first (`omega1 …
    /// omega3`, `Omega1 …`, `gamma1 …`, `p_psi`), then the parameters' in order: the text
    /// calls a symbol by its identifier, SymPy by its name. They are the same but for a
    /// parameter whose name is not a free Python identifier (a keyword such as `lambda`, a name
    /// the text uses: `sin`, `sqrt`, `Abs`, `Matrix`, `Symbol`, `nan`, `oo`, `sigma1`, a
    /// state's; a non-ASCII one), written under its name with `_` appended (`lambda_`), and for
    /// one whose name is another's (a parameter `omega1`, a scalar `com_1` beside a vector
    /// `com`), whose name gets the `_` too. (Empty in a document written before it existed.)
    #[cfg_attr(feature = "serde", serde(default))]
    pub symbols: Vec<(String, String)>,
}

/// The width, in points, a line of a display block is broken to (with the left-hand side and
/// the `=`): less than the text width of LaTeX's `article` at 10 pt (`\textwidth`, 345 pt),
/// as [`width`] only estimates the glyphs' widths.
const LINE_BUDGET: f64 = 300.0;

/// The seven formulas in the order printed: field, heading (LaTeX text), left-hand side, and a
/// comment (plain text).
type Item<'a> = (
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    &'a str,
);

impl LatexFormulas {
    fn items(&self) -> [Item<'_>; 7] {
        [
            (
                "lagrangian",
                "The Lagrangian",
                "L(\\omega, \\gamma)",
                "the Lagrangian",
                &self.lagrangian,
            ),
            (
                "psi_dot",
                "The rate $\\dot\\psi$ of (12)/(38)",
                "\\dot\\psi(\\Omega, \\gamma, p_\\psi)",
                "ψ̇ of (12)/(38)",
                &self.psi_dot,
            ),
            (
                "routhian",
                "The Routh function (14)",
                "R(\\Omega, \\gamma, p_\\psi)",
                "the Routh function (14)",
                &self.routhian,
            ),
            (
                "amended_potential",
                "The amended potential (34), $-R(0, \\gamma, p_\\psi)$",
                "U_r(\\gamma, p_\\psi)",
                "the amended potential (34), −R(0, γ, p_ψ)",
                &self.amended_potential,
            ),
            (
                "a",
                "The matrix $A = \\partial^2 R / \\partial \\Omega^2$ at $\\Omega = 0$ (64)",
                "A",
                "∂²R/∂Ω² at Ω = 0 (64)",
                &self.a,
            ),
            (
                "g",
                "The gyroscopic matrix $G$ of (64) at $\\Omega = 0$",
                "G",
                "the gyroscopic matrix of (64) at Ω = 0",
                &self.g,
            ),
            (
                "c",
                "The stiffness matrix $C$ of (64) at $\\Omega = 0$",
                "C",
                "the stiffness matrix of (64) at Ω = 0",
                &self.c,
            ),
        ]
    }

    /// The seven formulas as display blocks to paste into a LaTeX document (with
    /// `\usepackage{amsmath}`): each an `align*` under a comment naming it, lines broken to fit
    /// the text width of an `article` (345 pt). Definitions come first, then the formula:
    /// the paper's intermediate quantities (`\gamma^{\mathsf{T}} J \gamma`, `\dot\psi`, `\mu`),
    /// the named common subexpressions `\sigma_{k}` (numbered through the whole text, each
    /// defined before its first use), and, for a matrix too wide for a line, its entries
    /// `A_{11} = …` before `A = \begin{pmatrix} A_{11} & … \end{pmatrix}`. A long sum is
    /// continued on the next line after `&\quad`, a bracket open across the break closed by
    /// `\right.` and reopened by `\left.`; a numerator, denominator or root too wide for a line
    /// is named `\sigma_{k}` and defined first. A long block needs `\allowdisplaybreaks` to
    /// break across pages.
    ///
    /// ```
    /// let f = routh_core::LatexFormulas {
    ///     lagrangian: "\\frac{1}{2} C \\omega_3^{2}".into(),
    ///     ..Default::default()
    /// };
    /// let text = f.display();
    /// assert!(text.contains("\\begin{align*}\nL(\\omega, \\gamma) &= \\frac{1}{2} C \\omega_3^{2}\n\\end{align*}"));
    /// ```
    pub fn display(&self) -> String {
        let mut layout = Layout { next: 0 };
        let blocks: Vec<String> = self
            .items()
            .iter()
            .map(|&(name, _, lhs, what, formula)| {
                format!("% {name}: {what}\n{}", layout.block(lhs, formula))
            })
            .collect();
        format!(
            "% The derived formulas (routh formulas --latex): display blocks for amsmath.\n{}",
            blocks.join("\n")
        )
    }

    /// A complete LaTeX document (`article`, `amsmath`) with the seven formulas of
    /// [`LatexFormulas::display`] under headings, titled `title` (plain text; LaTeX's special
    /// characters are escaped). `pdflatex` compiles it with every line within the text width.
    pub fn document(&self, title: &str) -> String {
        let mut layout = Layout { next: 0 };
        let mut out = String::from(
            "\\documentclass{article}\n\\usepackage{amsmath}\n\\allowdisplaybreaks\n\
             \\begin{document}\n",
        );
        out.push_str(&format!("\\section*{{{}}}\n", escape_text(title)));
        for (_, heading, lhs, _, formula) in self.items() {
            out.push_str(&format!(
                "\n\\subsection*{{{heading}}}\n{}",
                layout.block(lhs, formula)
            ));
        }
        out.push_str("\n\\end{document}\n");
        out
    }
}

/// `s` with LaTeX's special characters escaped, for text mode.
fn escape_text(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '_' | '&' | '%' | '$' | '#' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str("\\^{}"),
            '~' => out.push_str("\\~{}"),
            c if c.is_ascii() => out.push(c),
            _ => out.push('?'),
        }
    }
    out
}

/// The `where` clause of the printed formulas.
const WHERE: &str = " \\quad \\text{where} \\quad ";

/// Lays out formulas as `align*` blocks; numbers the `\sigma_{k}` through all of them.
struct Layout {
    /// The largest `k` of `\sigma_{k}` given so far.
    next: usize,
}

impl Layout {
    /// `lhs = formula` (with its `where` clause) as an `align*` block.
    fn block(&mut self, lhs: &str, formula: &str) -> String {
        let (main, defs) = match formula.split_once(WHERE) {
            Some((m, d)) => (m, d.split(",\\; ").collect::<Vec<_>>()),
            None => (formula, Vec::new()),
        };
        // The σ of this formula renumbered after the ones before.
        let offset = self.next;
        let mut most = 0;
        let mut renumber = |s: &str| renumber_sigmas(s, offset, &mut most);
        let main = renumber(main);
        let mut lines: Vec<(String, String)> = Vec::new();
        for d in defs {
            let (name, value) = d.split_once(" = ").unwrap_or((d, ""));
            lines.push((renumber(name), renumber(value)));
        }
        self.next = offset + most;
        if let Some(cells) = main
            .strip_prefix("\\begin{pmatrix} ")
            .and_then(|m| m.strip_suffix(" \\end{pmatrix}"))
        {
            let cells: Vec<String> = cells
                .split(" \\\\ ")
                .flat_map(|row| row.split(" & "))
                .map(str::to_string)
                .collect();
            let whole = format!(
                "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
                matrix_rows(&cells)
            );
            if width(lhs) + width(&whole) + 15.0 <= LINE_BUDGET || cells.len() != 9 {
                lines.push((lhs.to_string(), whole));
            } else {
                // Entries by name, each defined before the matrix; zeros, short entries and
                // ones equal to another (or its negative) written in the matrix.
                let mut shown: Vec<String> = Vec::new();
                for (k, cell) in cells.iter().enumerate() {
                    let name = format!("{lhs}_{{{}{}}}", k / 3 + 1, k % 3 + 1);
                    let same = (0..k).find_map(|j| {
                        let earlier = &cells[j];
                        if earlier == cell {
                            Some(shown[j].clone())
                        } else if single_term(earlier) && single_term(cell) {
                            let neg = |a: &str, b: &str| a.strip_prefix('-') == Some(b);
                            (neg(cell, earlier) || neg(earlier, cell)).then(|| negate(&shown[j]))
                        } else {
                            None
                        }
                    });
                    let text = match same {
                        Some(t) => t,
                        None if width(cell) <= 40.0 => cell.clone(),
                        None => {
                            lines.push((name.clone(), cell.clone()));
                            name
                        }
                    };
                    shown.push(text);
                }
                lines.push((
                    lhs.to_string(),
                    format!(
                        "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
                        matrix_rows(&shown)
                    ),
                ));
            }
        } else {
            lines.push((lhs.to_string(), main));
        }
        // Too wide numerators, denominators and roots named first.
        let mut out: Vec<(String, String)> = Vec::new();
        for (name, value) in lines {
            self.extract(&name, value, &mut out);
        }
        let lhs_w = out.iter().map(|(n, _)| width(n)).fold(0.0, f64::max);
        let budget = LINE_BUDGET - lhs_w - 14.0;
        let rows: Vec<String> = out
            .iter()
            .map(|(name, value)| {
                let parts = break_lines(value, budget - 14.0);
                let mut row = format!("{name} &= {}", parts[0]);
                for p in &parts[1..] {
                    row.push_str(&format!(" \\\\\n  &\\quad {{}}{p}"));
                }
                row
            })
            .collect();
        format!(
            "\\begin{{align*}}\n{}\n\\end{{align*}}\n",
            rows.join(" \\\\\n")
        )
    }

    /// Pushes `name = value` to `out`, after the definitions of the arguments of `\frac` and
    /// `\sqrt` in `value` too wide for a line, named `\sigma_{k}` (each defined once).
    fn extract(&mut self, name: &str, value: String, out: &mut Vec<(String, String)>) {
        let budget = LINE_BUDGET - 120.0;
        let mut value = value;
        while let Some((start, end)) = wide_argument(&value, budget) {
            let arg = value[start..end].to_string();
            let sigma = match out
                .iter()
                .find(|(n, v)| *v == arg && n.starts_with("\\sigma"))
            {
                Some((n, _)) => n.clone(),
                None => {
                    self.next += 1;
                    let n = format!("\\sigma_{{{}}}", self.next);
                    self.extract(&n.clone(), arg.clone(), out);
                    n
                }
            };
            value.replace_range(start..end, &sigma);
        }
        out.push((name.to_string(), value));
    }
}

/// The rows of a 3×3 matrix of cells, `a & b & c \\ …`.
fn matrix_rows(cells: &[String]) -> String {
    let rows: Vec<String> = cells.chunks(3).map(|r| r.join(" & ")).collect();
    rows.join(" \\\\ ")
}

/// `-x` of a cell's text (`x` of `-x`).
fn negate(s: &str) -> String {
    match s.strip_prefix('-') {
        Some(rest) => rest.to_string(),
        None if s == "0" => s.to_string(),
        None => format!("-{s}"),
    }
}

/// Whether `s` has no `+` or `-` between terms outside braces and brackets (one term, perhaps
/// with a leading minus).
fn single_term(s: &str) -> bool {
    let mut depth = 0i32;
    let b = s.as_bytes();
    for i in 0..b.len() {
        match b[i] {
            b'{' => depth += 1,
            b'}' => depth -= 1,
            _ if b[i..].starts_with(b"\\left") => depth += 1,
            _ if b[i..].starts_with(b"\\right") => depth -= 1,
            b' ' if depth == 0 && (b[i..].starts_with(b" + ") || b[i..].starts_with(b" - ")) => {
                return false
            }
            _ => {}
        }
    }
    true
}

/// `s` with every `\sigma_{k}` written `\sigma_{k + offset}`; `most` raised to the largest k.
fn renumber_sigmas(s: &str, offset: usize, most: &mut usize) -> String {
    const PAT: &str = "\\sigma_{";
    let mut out = String::new();
    let mut rest = s;
    while let Some(at) = rest.find(PAT) {
        out.push_str(&rest[..at + PAT.len()]);
        rest = &rest[at + PAT.len()..];
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        match rest[..digits].parse::<usize>() {
            Ok(k) => {
                *most = (*most).max(k);
                out.push_str(&(k + offset).to_string());
            }
            Err(_) => out.push_str(&rest[..digits]),
        }
        rest = &rest[digits..];
    }
    out.push_str(rest);
    out
}

/// The byte range of the outermost argument of a `\frac` or `\sqrt` in `s` wider than
/// `budget` points, if any.
fn wide_argument(s: &str, budget: f64) -> Option<(usize, usize)> {
    let mut i = 0;
    while i < s.len() {
        let rest = &s[i..];
        let (cmd, args) = if rest.starts_with("\\frac{") {
            ("\\frac", 2)
        } else if rest.starts_with("\\sqrt{") {
            ("\\sqrt", 1)
        } else {
            i += rest.chars().next().map_or(1, char::len_utf8);
            continue;
        };
        let mut at = i + cmd.len();
        let mut wide = None;
        for _ in 0..args {
            let end = group_end(s, at);
            if wide.is_none() && width(&s[at + 1..end - 1]) > budget {
                wide = Some((at + 1, end - 1));
            }
            at = end;
        }
        if wide.is_some() {
            return wide;
        }
        // Inside the arguments: only narrower ones (an argument's own arguments are checked
        // when it is the one named).
        i = at;
    }
    None
}

/// The byte index after the `}` closing the group that opens at `s[at] == '{'`.
fn group_end(s: &str, at: usize) -> usize {
    let mut depth = 0;
    for (k, b) in s.bytes().enumerate().skip(at) {
        match b {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return k + 1;
                }
            }
            b'\\'
                if s.as_bytes()
                    .get(k + 1)
                    .is_some_and(|c| *c == b'{' || *c == b'}') => {}
            _ => {}
        }
    }
    s.len()
}

/// `s` broken before `+` and `-` between terms (outside braces, at any depth of
/// `\left … \right` brackets) into lines of at most about `budget` points; a bracket open across
/// a break is closed with `\right.` at the end of the line and reopened with `\left.`.
fn break_lines(s: &str, budget: f64) -> Vec<String> {
    // The places a line may break: (byte index of the space before the sign, open brackets).
    let mut cuts: Vec<(usize, usize)> = Vec::new();
    let (mut braces, mut lefts) = (0i32, 0usize);
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let rest = &b[i..];
        if b[i] == b'\\' && b.get(i + 1).is_some_and(|c| *c == b'{' || *c == b'}') {
            i += 2;
            continue;
        }
        match b[i] {
            b'{' => braces += 1,
            b'}' => braces -= 1,
            _ if braces == 0 && rest.starts_with(b"\\left") => lefts += 1,
            _ if braces == 0 && rest.starts_with(b"\\right") => lefts = lefts.saturating_sub(1),
            b' ' if braces == 0 && (rest.starts_with(b" + ") || rest.starts_with(b" - ")) => {
                cuts.push((i, lefts))
            }
            _ => {}
        }
        i += 1;
    }
    let mut lines = Vec::new();
    let (mut start, mut reopen) = (0usize, 0usize);
    let mut line_start_w = 0.0;
    let mut last: Option<(usize, usize)> = None;
    for k in 0..=cuts.len() {
        let end = cuts.get(k).map_or(s.len(), |c| c.0);
        if line_start_w + width(&s[start..end]) > budget {
            if let Some((at, open)) = last.filter(|l| l.0 > start) {
                let mut line = "\\left. ".repeat(reopen);
                line.push_str(&s[start..at]);
                line.push_str(&" \\right.".repeat(open));
                lines.push(line);
                start = at + 1;
                reopen = open;
                line_start_w = 8.0 * open as f64;
            }
        }
        last = cuts.get(k).copied();
    }
    let mut line = "\\left. ".repeat(reopen);
    line.push_str(&s[start..]);
    lines.push(line);
    lines
}

/// An estimate of the width, in points at 10 pt (Computer Modern, display style), of the LaTeX
/// math `s` of the printer's subset: on the wide side, so that the lines [`break_lines`] makes
/// fit.
fn width(s: &str) -> f64 {
    let c: Vec<char> = s.chars().collect();
    let (w, _) = width_of(&c, 0, 1.0);
    w
}

/// The width of `c[i..]` up to the `}` closing the current group (or the end), at `scale`, and
/// the index after it.
fn width_of(c: &[char], mut i: usize, scale: f64) -> (f64, usize) {
    let mut w = 0.0;
    while i < c.len() {
        let ch = c[i];
        match ch {
            '}' => return (w, i + 1),
            '{' => {
                let (x, j) = width_of(c, i + 1, scale);
                w += x;
                i = j;
            }
            '_' | '^' => {
                let (x, j) = script(c, i + 1, scale * 0.75);
                w += x;
                i = j;
            }
            '\\' => {
                let start = i + 1;
                let mut j = start;
                while j < c.len() && c[j].is_ascii_alphabetic() {
                    j += 1;
                }
                if j == start {
                    // `\{`, `\;`, `\,`, `\\`, `\_`.
                    w += scale * 3.0;
                    i = start + 1;
                    continue;
                }
                let name: String = c[start..j].iter().collect();
                i = j;
                match name.as_str() {
                    "frac" => {
                        let (a, j) = script(c, i, scale);
                        let (b, j) = script(c, j, scale);
                        w += a.max(b) + 3.0 * scale;
                        i = j;
                    }
                    "sqrt" => {
                        let (a, j) = script(c, i, scale);
                        w += a + 10.0 * scale;
                        i = j;
                    }
                    "left" | "right" => {
                        w += 5.0 * scale;
                        i += 1;
                    }
                    "mathit" | "mathsf" | "text" | "operatorname" | "mathrm" => {
                        let (a, j) = script(c, i, scale);
                        w += a + if name == "operatorname" { 3.0 } else { 0.0 };
                        i = j;
                    }
                    "dot" | "hat" | "bar" | "tilde" => {}
                    "quad" => w += 10.0 * scale,
                    "sin" | "cos" | "tan" | "exp" | "log" | "ln" => {
                        w += (5.0 * name.len() as f64 + 3.0) * scale
                    }
                    _ => w += 7.0 * scale,
                }
                continue;
            }
            '+' | '-' | '=' => w += 13.5 * scale,
            ' ' => {}
            '(' | ')' | '|' | ',' | '.' => w += 4.0 * scale,
            c if c.is_ascii_digit() => w += 5.0 * scale,
            _ => w += 6.0 * scale,
        }
        i += 1;
    }
    (w, i)
}

/// The width of the argument at `c[i]` (a `{…}` group or one token, after spaces) and the index
/// after it.
fn script(c: &[char], mut i: usize, scale: f64) -> (f64, usize) {
    while i < c.len() && c[i] == ' ' {
        i += 1;
    }
    match c.get(i) {
        Some('{') => width_of(c, i + 1, scale),
        Some('\\') => {
            let mut j = i + 1;
            while j < c.len() && c[j].is_ascii_alphabetic() {
                j += 1;
            }
            let j = j.max(i + 2);
            (7.0 * scale, j)
        }
        Some(_) => (6.0 * scale, i + 1),
        None => (0.0, i),
    }
}
