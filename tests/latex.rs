//! The LaTeX of `DerivedFormulas::latex()` evaluated by an independent parser of the LaTeX
//! subset it uses (numbers, symbols with subscripts, + −, products by juxtaposition, `\frac`,
//! `^`, `\sqrt`, `\left( \right)`, `\left| \right|`, elementary functions, `pmatrix`) and
//! compared with the generated functions at random points (unit γ: the formulas are simplified
//! with |γ|² = 1), for every paper model: the Lagrange and asymmetric tops, the gyrostat, the
//! ellipsoid on a plane, the body in a fluid. A formula too large to print inline comes with
//! its shared subexpressions named (`… \quad \text{where} \quad \sigma_{1} = …,\; …`): the
//! evaluator evaluates the definitions in order and the formula with them.
//!
//! Since the formulas print in a canonical order and the matrices name the paper's
//! intermediates: the evaluator reads `\gamma^{\mathsf{T}} J \gamma`, `\dot\psi` and
//! `\mu` as symbols defined in the `where` clause (`intermediates`), because A, G, C are now
//! written with them instead of only `\sigma_{k}`; the values compared are unchanged (the order
//! of terms changes no value), and the report line counts the matrices that still need a
//! `\sigma_{k}` (the tops' need none).

use std::collections::HashMap;

use crate::common::close_to;

use derived_models::{
    AsymmetricTop, DiagonalEllipsoid, Ellipsoid, FluidBody, Gyrostat, LagrangeTop,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{DerivedFormulas, Matrix3, Routhian, Vector3};

// ---------------------------------------------------------------- the LaTeX-subset evaluator

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(f64),
    /// A symbol's base: a letter, a Greek command, or the text of `\mathit{…}`.
    Sym(String),
    Cmd(String),
    Ch(char),
}

fn lex(s: &str) -> Vec<Tok> {
    let c: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        if ch.is_whitespace() {
            i += 1;
        } else if ch == '\\' {
            let start = i + 1;
            let mut j = start;
            while j < c.len() && c[j].is_ascii_alphabetic() {
                j += 1;
            }
            if j == start {
                // `\\`, `\_`, `\,` …
                out.push(Tok::Cmd(c[start].to_string()));
                i = start + 1;
                continue;
            }
            let name: String = c[start..j].iter().collect();
            i = j;
            match name.as_str() {
                "mathit" | "operatorname" | "text" => {
                    assert_eq!(c[i], '{', "{s}");
                    let mut k = i + 1;
                    while c[k] != '}' {
                        k += 1;
                    }
                    let raw: String = c[i + 1..k].iter().collect();
                    let raw = raw.replace("\\_", "_");
                    i = k + 1;
                    match name.as_str() {
                        "mathit" => out.push(Tok::Sym(raw)),
                        "text" => panic!("formula not printed: {raw}"),
                        _ => out.push(Tok::Cmd(raw)),
                    }
                }
                "gamma" | "omega" | "Omega" | "psi" | "sigma" => {
                    out.push(Tok::Sym(format!("\\{name}")))
                }
                _ => out.push(Tok::Cmd(name)),
            }
        } else if ch.is_ascii_digit() || ch == '.' {
            let mut j = i;
            while j < c.len() && (c[j].is_ascii_digit() || c[j] == '.') {
                j += 1;
            }
            let t: String = c[i..j].iter().collect();
            out.push(Tok::Num(t.parse().unwrap()));
            i = j;
        } else if ch.is_ascii_alphabetic() {
            out.push(Tok::Sym(ch.to_string()));
            i += 1;
        } else {
            out.push(Tok::Ch(ch));
            i += 1;
        }
    }
    out
}

struct Parser<'a> {
    t: Vec<Tok>,
    at: usize,
    env: &'a HashMap<String, f64>,
    src: &'a str,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.at)
    }
    fn next(&mut self) -> Tok {
        let t = self.t.get(self.at).cloned();
        self.at += 1;
        t.unwrap_or_else(|| panic!("unexpected end in {}", self.src))
    }
    fn expect(&mut self, want: Tok) {
        let got = self.next();
        assert_eq!(got, want, "at token {} of {}", self.at, self.src);
    }
    fn expr(&mut self) -> f64 {
        let mut sign = 1.0;
        if self.peek() == Some(&Tok::Ch('-')) {
            self.at += 1;
            sign = -1.0;
        }
        let mut v = sign * self.term();
        loop {
            match self.peek() {
                Some(Tok::Ch('+')) => {
                    self.at += 1;
                    v += self.term();
                }
                Some(Tok::Ch('-')) => {
                    self.at += 1;
                    v -= self.term();
                }
                _ => return v,
            }
        }
    }
    fn starts_factor(&self) -> bool {
        match self.peek() {
            Some(Tok::Num(_)) | Some(Tok::Sym(_)) | Some(Tok::Ch('{')) => true,
            Some(Tok::Cmd(c)) => matches!(
                c.as_str(),
                "frac" | "sqrt" | "left" | "sin" | "cos" | "tan" | "exp" | "ln" | "sgn" | "cdot"
            ),
            _ => false,
        }
    }
    fn term(&mut self) -> f64 {
        let mut v = self.factor();
        while self.starts_factor() {
            if self.peek() == Some(&Tok::Cmd("cdot".into())) {
                self.at += 1;
            }
            v *= self.factor();
        }
        v
    }
    fn factor(&mut self) -> f64 {
        let base = self.primary();
        if self.peek() == Some(&Tok::Ch('^')) {
            self.at += 1;
            let e = match self.next() {
                Tok::Ch('{') => {
                    let e = self.expr();
                    self.expect(Tok::Ch('}'));
                    e
                }
                Tok::Num(n) => n,
                t => panic!("exponent {t:?} in {}", self.src),
            };
            return base.powf(e);
        }
        base
    }
    fn group(&mut self) -> f64 {
        self.expect(Tok::Ch('{'));
        let v = self.expr();
        self.expect(Tok::Ch('}'));
        v
    }
    /// The text of a subscript: `_1`, `_{11}`, `_\psi`.
    fn subscript(&mut self) -> String {
        match self.next() {
            Tok::Num(n) => format!("{n}"),
            Tok::Sym(s) => s,
            Tok::Ch('{') => {
                let mut s = String::new();
                loop {
                    match self.next() {
                        Tok::Ch('}') => return s,
                        Tok::Num(n) => s.push_str(&format!("{n}")),
                        Tok::Sym(x) => s.push_str(&x),
                        t => panic!("subscript {t:?} in {}", self.src),
                    }
                }
            }
            t => panic!("subscript {t:?} in {}", self.src),
        }
    }
    fn primary(&mut self) -> f64 {
        match self.next() {
            Tok::Num(n) => n,
            Tok::Sym(base) => {
                let key = if self.peek() == Some(&Tok::Ch('_')) {
                    self.at += 1;
                    format!("{base}_{}", self.subscript())
                } else {
                    base
                };
                *self
                    .env
                    .get(&key)
                    .unwrap_or_else(|| panic!("unknown symbol {key} in {}", self.src))
            }
            Tok::Ch('{') => {
                // `{r_c}_{1}`: a symbol with a subscript of its own, wrapped, then indexed
                // (issue 47); the key is `r_c_1`, as `Env::vector` names it.
                let start = self.at;
                let close = (start..self.t.len()).find(|&k| self.t[k] == Tok::Ch('}'));
                if let Some(close) = close.filter(|&k| self.t.get(k + 1) == Some(&Tok::Ch('_'))) {
                    let base: String = (self.t[start..close].iter())
                        .map(|t| match t {
                            Tok::Sym(x) => x.clone(),
                            Tok::Ch('_') => "_".to_string(),
                            Tok::Num(n) => format!("{n}"),
                            t => panic!("wrapped symbol {t:?} in {}", self.src),
                        })
                        .collect();
                    self.at = close + 2;
                    let key = format!("{base}_{}", self.subscript());
                    return *self
                        .env
                        .get(&key)
                        .unwrap_or_else(|| panic!("unknown symbol {key} in {}", self.src));
                }
                let v = self.expr();
                self.expect(Tok::Ch('}'));
                v
            }
            Tok::Cmd(c) => match c.as_str() {
                "frac" => {
                    let a = self.group();
                    let b = self.group();
                    a / b
                }
                "sqrt" => self.group().sqrt(),
                "left" => match self.next() {
                    Tok::Ch('(') => {
                        let v = self.expr();
                        self.expect(Tok::Cmd("right".into()));
                        self.expect(Tok::Ch(')'));
                        v
                    }
                    Tok::Ch('|') => {
                        let v = self.expr();
                        self.expect(Tok::Cmd("right".into()));
                        self.expect(Tok::Ch('|'));
                        v.abs()
                    }
                    t => panic!("\\left{t:?} in {}", self.src),
                },
                "sin" => self.primary().sin(),
                "cos" => self.primary().cos(),
                "tan" => self.primary().tan(),
                "exp" => self.primary().exp(),
                "ln" => self.primary().ln(),
                "sgn" => {
                    let x = self.primary();
                    if x == 0.0 {
                        0.0
                    } else {
                        x.signum()
                    }
                }
                _ => panic!("command \\{c} in {}", self.src),
            },
            t => panic!("unexpected {t:?} at token {} in {}", self.at, self.src),
        }
    }
}

/// What separates a formula from the definitions of its named subexpressions.
const WHERE: &str = " \\quad \\text{where} \\quad ";

/// `src` without its `where` clause, and `env` with the clause's definitions (`\sigma_{k} = …`,
/// separated by `,\;`, each evaluated with the ones before it).
fn definitions(src: &str, env: &HashMap<String, f64>) -> (String, HashMap<String, f64>) {
    let mut env = env.clone();
    let src = &intermediates(src);
    let Some((main, defs)) = src.split_once(WHERE) else {
        return (src.to_string(), env);
    };
    for def in defs.split(",\\; ") {
        let (name, value) = def
            .split_once(" = ")
            .unwrap_or_else(|| panic!("definition {def}"));
        let key = match name.trim().strip_prefix("\\mathit{") {
            // The paper's intermediates (see `intermediates`).
            Some(rest) => rest.trim_end_matches('}').to_string(),
            None => name.trim().replace(['{', '}'], ""),
        };
        assert!(
            key.starts_with("\\sigma_") || ["gJg", "psidot", "mu"].contains(&key.as_str()),
            "{key}"
        );
        assert!(!env.contains_key(&key), "{key} defined twice");
        let v = eval(value, &env);
        env.insert(key, v);
    }
    (main.to_string(), env)
}

/// `src` with the symbols of the intermediate quantities that the matrices name as the paper
/// does (γᵀJγ, ψ̇ at rest, μ; defined in the `where` clause) as one-token symbols
/// `\mathit{gJg}`, `\mathit{psidot}`, `\mathit{mu}` for the evaluator.
fn intermediates(src: &str) -> String {
    src.replace("\\gamma^{\\mathsf{T}} J \\gamma", "\\mathit{gJg}")
        .replace("\\dot\\psi", "\\mathit{psidot}")
        .replace("\\mu", "\\mathit{mu}")
}

/// The value of a LaTeX expression (with its `where` clause, if any).
fn eval(src: &str, env: &HashMap<String, f64>) -> f64 {
    let src = &intermediates(src);
    if src.contains(WHERE) {
        let (main, env) = definitions(src, env);
        return eval(&main, &env);
    }
    let mut p = Parser {
        t: lex(src),
        at: 0,
        env,
        src,
    };
    let v = p.expr();
    assert_eq!(p.at, p.t.len(), "trailing tokens in {src}");
    v
}

/// The values of the seven formulas of `LatexFormulas::display` (one for a scalar, nine for a
/// matrix, row by row), read back from its `align*` blocks: the continuation of a line
/// (`\\ &\quad {}`) and the `\right.`/`\left.` closing and reopening a bracket across it
/// removed, each line `name &= value` evaluated in order (the definitions first: σ, the paper's
/// intermediates, a matrix's entries `A_{11}`), the last line of a block being the formula.
/// A name used before its definition is an "unknown symbol" panic.
fn eval_display(text: &str, env: &HashMap<String, f64>) -> Vec<Vec<f64>> {
    let mut env = env.clone();
    let mut out = Vec::new();
    for block in text.split("\\begin{align*}\n").skip(1) {
        let body = block
            .split_once("\n\\end{align*}")
            .unwrap_or_else(|| panic!("unclosed block {block}"))
            .0
            .replace(" \\\\\n  &\\quad {}", " ")
            .replace("\\right.", "")
            .replace("\\left.", "");
        let rows: Vec<&str> = body.split(" \\\\\n").collect();
        let (last, defs) = rows.split_last().unwrap();
        for row in defs {
            let (name, value) = row
                .split_once(" &= ")
                .unwrap_or_else(|| panic!("row {row}"));
            let name = intermediates(name);
            let key = match name.strip_prefix("\\mathit{") {
                Some(rest) => rest.trim_end_matches('}').to_string(),
                None => name.replace(['{', '}'], ""),
            };
            let v = eval(value, &env);
            // Each block defines the paper's intermediates it uses (a block pasted alone is
            // whole): the same definition again, never another value; a σ once.
            if let Some(old) = env.insert(key.clone(), v) {
                assert!(
                    !key.starts_with("\\sigma") && old.to_bits() == v.to_bits(),
                    "{key}"
                );
            }
        }
        let value = last
            .split_once(" &= ")
            .unwrap_or_else(|| panic!("row {last}"))
            .1;
        out.push(if value.contains("not printed") {
            vec![f64::NAN; 9]
        } else if value.starts_with("\\begin{pmatrix}") {
            eval_matrix(value, &env)
                .transpose()
                .iter()
                .copied()
                .collect()
        } else {
            vec![eval(value, &env)]
        });
    }
    assert_eq!(out.len(), 7, "{text}");
    out
}

/// The value of a `\begin{pmatrix} … \end{pmatrix}`.
fn eval_matrix(src: &str, env: &HashMap<String, f64>) -> Matrix3<f64> {
    let (src, env) = definitions(src, env);
    let env = &env;
    let body = src
        .trim()
        .strip_prefix("\\begin{pmatrix}")
        .and_then(|s| s.strip_suffix("\\end{pmatrix}"))
        .unwrap_or_else(|| panic!("not a pmatrix: {src}"));
    let rows: Vec<&str> = body.split("\\\\").collect();
    assert_eq!(rows.len(), 3, "{src}");
    let mut m = Matrix3::zeros();
    for (i, row) in rows.iter().enumerate() {
        let cells: Vec<&str> = row.split('&').collect();
        assert_eq!(cells.len(), 3, "{src}");
        for (j, cell) in cells.iter().enumerate() {
            m[(i, j)] = eval(cell, env);
        }
    }
    m
}

#[test]
fn the_evaluator_reads_its_subset() {
    let env: HashMap<String, f64> = [
        ("\\gamma_1".to_string(), 0.5),
        ("I_11".to_string(), 2.0),
        ("p_\\psi".to_string(), 3.0),
        ("mgl".to_string(), 4.0),
    ]
    .into_iter()
    .collect();
    let v = eval(
        "\\frac{1}{2} I_{11} \\gamma_1^{2} - \\frac{p_\\psi^{2}}{\\left(1 + \\gamma_1\\right)} + \\sqrt{\\mathit{mgl}}",
        &env,
    );
    assert!((v - (0.25 - 9.0 / 1.5 + 2.0)).abs() < 1e-15);
}

// ---------------------------------------------------------------- the models

/// Symbol values: scalars `name`, vectors `name_i`, matrices `name_ij` (from 1).
#[derive(Default)]
struct Env(HashMap<String, f64>);

impl Env {
    fn scalar(&mut self, name: &str, v: f64) -> &mut Self {
        self.0.insert(name.to_string(), v);
        self
    }
    fn vector(&mut self, name: &str, v: &Vector3<f64>) -> &mut Self {
        for i in 0..3 {
            self.0.insert(format!("{name}_{}", i + 1), v[i]);
        }
        self
    }
    fn matrix(&mut self, name: &str, m: &Matrix3<f64>) -> &mut Self {
        for i in 0..3 {
            for j in 0..3 {
                self.0
                    .insert(format!("{name}_{}{}", i + 1, j + 1), m[(i, j)]);
            }
        }
        self
    }
}

fn unit(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::from_fn(|_, _| rng.gen_range(-1.0..1.0));
        if v.norm() > 0.2 && v.norm() < 1.0 {
            return v.normalize();
        }
    }
}

/// Asserts that a LaTeX formula's value `a` agrees with the generated code's `b`.
fn agrees(a: f64, b: f64, scale: f64, what: &str) {
    assert!(
        close_to(a, b, 1e-9, scale),
        "{what}: LaTeX {a} vs generated {b}"
    );
}

/// Evaluates every printed formula of `model` at random points against the generated code;
/// returns how many formulas were printed (a formula too large to read is a `\text`).
fn check<M: Routhian + DerivedFormulas>(name: &str, model: &M, env: &Env) -> usize {
    let f = model.latex();
    let display = f.display();
    crate::latex_document::compiles(name, &f.document(name));
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    // A formula too large even with named subexpressions would be `\text{(… not printed)}`.
    let printed = |s: &str| !s.contains("not printed");
    let mut count = 0;
    for s in [
        &f.lagrangian,
        &f.psi_dot,
        &f.routhian,
        &f.amended_potential,
        &f.a,
        &f.g,
        &f.c,
    ] {
        assert!(!s.is_empty(), "{name}: empty formula");
        count += usize::from(printed(s));
    }
    for _ in 0..20 {
        let gamma = unit(&mut rng);
        let w = Vector3::from_fn(|_, _| rng.gen_range(-2.0..2.0));
        let p = rng.gen_range(-3.0..3.0);
        let mut e = env.0.clone();
        for i in 0..3 {
            e.insert(format!("\\gamma_{}", i + 1), gamma[i]);
            e.insert(format!("\\omega_{}", i + 1), w[i]);
            e.insert(format!("\\Omega_{}", i + 1), w[i]);
        }
        e.insert("p_\\psi".to_string(), p);
        if printed(&f.lagrangian) {
            let want = model.lagrangian(&w, &gamma);
            agrees(
                eval(&f.lagrangian, &e),
                want,
                want.abs(),
                &format!("{name} L"),
            );
        }
        if printed(&f.psi_dot) {
            let want = model.psi_dot(&w, &gamma, p);
            agrees(eval(&f.psi_dot, &e), want, want.abs(), &format!("{name} ψ̇"));
        }
        if printed(&f.routhian) {
            let want = model.routhian(&w, &gamma, p);
            agrees(
                eval(&f.routhian, &e),
                want,
                want.abs(),
                &format!("{name} R"),
            );
        }
        if printed(&f.amended_potential) {
            let want = model.amended_potential(&gamma, p);
            agrees(
                eval(&f.amended_potential, &e),
                want,
                want.abs(),
                &format!("{name} U_r"),
            );
        }
        // The display blocks (issue 47), read back, equal the formulas: the layout keeps
        // every value.
        let shown = eval_display(&display, &e);
        for (k, s) in [&f.lagrangian, &f.psi_dot, &f.routhian, &f.amended_potential]
            .into_iter()
            .enumerate()
        {
            if printed(s) {
                let want = eval(s, &e);
                agrees(
                    shown[k][0],
                    want,
                    want.abs(),
                    &format!("{name} display {k}"),
                );
            }
        }
        let sys = model.gyroscopic_system(&gamma, p);
        for (k, m) in [sys.a, sys.g, sys.c].iter().enumerate() {
            if printed([&f.a, &f.g, &f.c][k]) {
                for (i, v) in shown[4 + k].iter().enumerate() {
                    let want = m[(i / 3, i % 3)];
                    agrees(*v, want, m.amax(), &format!("{name} display matrix {k}"));
                }
            }
        }
        for (tex, m, what) in [(&f.a, sys.a, "A"), (&f.g, sys.g, "G"), (&f.c, sys.c, "C")] {
            if printed(tex) {
                let got = eval_matrix(tex, &e);
                let scale = m.amax();
                for k in 0..9 {
                    agrees(got[k], m[k], scale, &format!("{name} {what}"));
                }
            }
        }
    }
    let named = [
        &f.lagrangian,
        &f.psi_dot,
        &f.routhian,
        &f.amended_potential,
        &f.a,
        &f.g,
        &f.c,
    ]
    .iter()
    .filter(|s| s.contains(WHERE))
    .count();
    let longest = [
        &f.lagrangian,
        &f.psi_dot,
        &f.routhian,
        &f.amended_potential,
        &f.a,
        &f.g,
        &f.c,
    ]
    .iter()
    .map(|s| s.len())
    .max()
    .unwrap_or(0);
    let sigmas = [&f.a, &f.g, &f.c]
        .iter()
        .filter(|s| s.contains("\\sigma_"))
        .count();
    eprintln!(
        "{name}: {count}/7 formulas printed and checked ({named} with a `where` clause, \
         {sigmas} of the matrices with σ; longest {longest} characters); U_r = {}",
        f.amended_potential
    );
    count
}

#[test]
fn lagrange_top() {
    let top = LagrangeTop::with_mgl(1.3, 0.7, 2.1);
    let mut env = Env::default();
    env.scalar("A_1", top.a1)
        .scalar("C", top.c)
        .scalar("mass", top.mass)
        .scalar("g", top.g)
        .scalar("l", top.l);
    assert_eq!(check("Lagrange top", &top, &env), 7);
    let f = top.latex();
    eprintln!("{f:#?}");
    // The field symbols and the |γ|² = 1 rule: ψ̇ at rest has the denominator A₁ + (C − A₁)γ₃²,
    // no γ₁² or γ₂².
    assert!(f.lagrangian.contains("A_1") && f.lagrangian.contains("\\mathit{mass}"));
    assert!(
        !f.amended_potential.contains("\\gamma_1"),
        "{}",
        f.amended_potential
    );
}

#[test]
fn asymmetric_top() {
    let top = AsymmetricTop {
        inertia: Vector3::new(1.0, 2.0, 3.5),
        mass: 1.2,
        g: 9.81,
        com: Vector3::new(0.3, -0.2, 0.5),
    };
    let mut env = Env::default();
    env.vector("inertia", &top.inertia)
        .vector("com", &top.com)
        .scalar("mass", top.mass)
        .scalar("g", top.g);
    assert_eq!(check("asymmetric top", &top, &env), 7);
}

#[test]
fn gyrostat() {
    let twin = test_models::Gyrostat::random(&mut ChaCha8Rng::seed_from_u64(3));
    let m = Gyrostat::from(&twin);
    let mut env = Env::default();
    env.matrix("I", &m.inertia)
        .vector("rotor", &m.rotor)
        .matrix("coupling", &m.coupling)
        .vector("com", &m.com)
        .scalar("mass", m.mass)
        .scalar("g", m.g);
    assert_eq!(check("gyrostat", &m, &env), 7);
    assert!(m.latex().lagrangian.contains("I_{11}"));
}

#[test]
fn ellipsoids() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let d = DiagonalEllipsoid::random(&mut rng);
    let mut env = Env::default();
    env.vector("inertia", &d.inertia)
        .vector("semi_axes", &d.semi_axes)
        .vector("offset", &d.offset)
        .scalar("mass", d.mass)
        .scalar("g", d.g);
    assert_eq!(check("diagonal ellipsoid", &d, &env), 7);
    let e = Ellipsoid {
        inertia: Matrix3::from_diagonal(&d.inertia),
        semi_axes: d.semi_axes,
        offset: d.offset,
        mass: d.mass,
        g: d.g,
    };
    let mut env = Env::default();
    env.matrix("inertia", &e.inertia)
        .vector("semi_axes", &e.semi_axes)
        .vector("offset", &e.offset)
        .scalar("mass", e.mass)
        .scalar("g", e.g);
    assert_eq!(check("ellipsoid", &e, &env), 7);
}

#[test]
fn fluid_body() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut spd = || {
        let a = Matrix3::from_fn(|_, _| rng.gen_range(-0.5..0.5));
        a * a.transpose() + Matrix3::identity() * 2.0
    };
    let (a_kin, pot) = (spd(), spd());
    let lin = Matrix3::from_fn(|i, j| (i as f64 - j as f64) * 0.3 + 0.1);
    let b = FluidBody { a_kin, lin, pot };
    let mut env = Env::default();
    env.matrix("a_kin", &b.a_kin)
        .matrix("lin", &b.lin)
        .matrix("pot", &b.pot);
    assert_eq!(check("body in a fluid", &b, &env), 7);
}

/// The derive prints its LaTeX at run time, on the first call, from the struct's text it emits
/// (its fields and `#[lagrangian]` attributes): the same formulas as the printer gives on the
/// declaration itself, symbols of the fields included (the gyrostat's `I`).
#[test]
fn printed_at_run_time_as_from_the_declaration() {
    let twin = test_models::Gyrostat::random(&mut ChaCha8Rng::seed_from_u64(3));
    let d = DiagonalEllipsoid::random(&mut ChaCha8Rng::seed_from_u64(5));
    let models = [
        (derived_models::GYROSTAT_SRC, Gyrostat::from(&twin).latex()),
        (derived_models::DIAGONAL_ELLIPSOID_SRC, d.latex()),
    ];
    for (src, f) in models {
        let file: syn::File = syn::parse_str(src).expect("the declaration parses");
        let item = (file.items.into_iter())
            .find_map(|i| match i {
                syn::Item::Struct(s) => Some(s),
                _ => None,
            })
            .expect("a struct");
        let di: syn::DeriveInput =
            syn::parse2(quote::ToTokens::into_token_stream(item)).expect("a DeriveInput");
        let m = routh_codegen::analyse(&di).expect("the model analyses");
        let t = routh_codegen::latex::latex_formulas(&m, &m.latex_symbols);
        assert!(!f.lagrangian.is_empty());
        assert_eq!(f.lagrangian, t.lagrangian);
        assert_eq!(f.psi_dot, t.psi_dot);
        assert_eq!(f.routhian, t.routhian);
        assert_eq!(f.amended_potential, t.amended_potential);
        assert_eq!((f.a, f.g, f.c), (t.a, t.g, t.c));
    }
}

/// A tag the macro below names through `$crate`, a path no text parses back.
#[derive(Debug, Clone, Default)]
pub struct Tag;

/// The Lagrange top declared by a `macro_rules!` whose skipped field's type names `$crate`: the
/// struct's text does not parse back at run time, so the derive prints its LaTeX at expansion.
macro_rules! lagrange_top_in_a_macro {
    () => {
        #[derive(routh::Lagrangian, Debug, Clone)]
        #[lagrangian(
            kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
            potential = mass * g * l * gamma.z,
        )]
        struct TaggedTop {
            #[lagrangian(latex = "A_1")]
            a1: f64,
            #[lagrangian(latex = "C")]
            c: f64,
            mass: f64,
            g: f64,
            l: f64,
            #[lagrangian(skip)]
            #[allow(dead_code)]
            tag: $crate::latex::Tag,
        }
    };
}
lagrange_top_in_a_macro!();

#[test]
fn a_struct_declared_by_a_macro_with_crate_paths_prints_its_latex() {
    let (a1, c, mgl) = (1.3, 0.7, 2.1);
    let tagged = TaggedTop {
        a1,
        c,
        mass: 1.0,
        g: 1.0,
        l: mgl,
        tag: Tag,
    };
    let plain = LagrangeTop::with_mgl(a1, c, mgl);
    let (t, p) = (tagged.latex(), plain.latex());
    assert!(!t.lagrangian.is_empty() && !t.c.is_empty(), "{t:#?}");
    assert_eq!(t, p);
}
