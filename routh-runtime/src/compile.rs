//! From a model's text to its tapes, through the derive's own front end: the text, lexed by
//! `proc_macro2` so that spans keep their line and column, is the body and the parameters (with
//! their shapes) are the fields, and `routh_codegen::analyse_parts` parses, checks, lowers and
//! reduces them exactly as `#[derive(Lagrangian)]` does for a struct. Each generated method's outputs ([`routh_codegen::layout`])
//! become one tape ([`routh_codegen::tape`]), its parameters left as `Op::Param` to be bound
//! by [`crate::Model`].

use crate::error::ModelError;
use crate::Param;
use proc_macro2::{Span, TokenStream};
use routh_codegen::layout::{Bundle, BundleAndSystem, EquationTerms, Gyroscopic, JacobianTerms};
use routh_codegen::lower::Access;
use routh_codegen::{Body, Field, FieldKind};
use routh_symbolic::Id;
use routh_tape::Tape;

/// `["name[0]", "name[1]", "name[2]"]`.
macro_rules! v3 {
    ($n:literal) => {
        [concat!($n, "[0]"), concat!($n, "[1]"), concat!($n, "[2]")]
    };
}

/// The 3×3 entries `name[i][j]`, row-major.
macro_rules! m33 {
    ($n:literal) => {
        [
            [
                concat!($n, "[0][0]"),
                concat!($n, "[0][1]"),
                concat!($n, "[0][2]"),
            ],
            [
                concat!($n, "[1][0]"),
                concat!($n, "[1][1]"),
                concat!($n, "[1][2]"),
            ],
            [
                concat!($n, "[2][0]"),
                concat!($n, "[2][1]"),
                concat!($n, "[2][2]"),
            ],
        ]
    };
}

/// The tapes of one model, one per generated method (see `routh_codegen::emit`); the unbound
/// form has `Op::Param(k)` for the `k`-th read of [`Compiled::reads`].
#[derive(Clone, Debug)]
pub(crate) struct Tapes<T> {
    pub lagrangian: T,
    pub dl_domega: T,
    pub dl_dgamma: T,
    pub d2l_domega2: T,
    pub d2l_domega_dgamma: T,
    pub energy: T,
    pub cyclic_momentum: T,
    pub full_equations: T,
    pub full_jacobian: T,
    pub psi_dot: T,
    pub routhian: T,
    pub dr_domega: T,
    pub dr_dgamma: T,
    pub dr_dp: T,
    pub d2r_domega2: T,
    pub d2r_domega_dgamma: T,
    pub d2r_dgamma2: T,
    pub amended_potential: T,
    pub bundle: T,
    pub gyroscopic_system: T,
    pub reduced_equations: T,
    pub bundle_and_system: T,
}

/// The methods of the tapes, in the order of [`Tapes::fields`].
pub(crate) const TAPE_NAMES: [&str; TAPES] = [
    "lagrangian",
    "dl_domega",
    "dl_dgamma",
    "d2l_domega2",
    "d2l_domega_dgamma",
    "energy",
    "cyclic_momentum",
    "full_equations",
    "full_jacobian",
    "psi_dot",
    "routhian",
    "dr_domega",
    "dr_dgamma",
    "dr_dp",
    "d2r_domega2",
    "d2r_domega_dgamma",
    "d2r_dgamma2",
    "amended_potential",
    "bundle",
    "gyroscopic_system",
    "reduced_equations",
    "bundle_and_system",
];

/// The number of tapes of a model (one per generated method).
pub(crate) const TAPES: usize = 22;

/// The position of each tape in [`Tapes::fields`] and [`TAPE_NAMES`].
pub(crate) mod index {
    pub const LAGRANGIAN: usize = 0;
    pub const DL_DOMEGA: usize = 1;
    pub const DL_DGAMMA: usize = 2;
    pub const D2L_DOMEGA2: usize = 3;
    pub const D2L_DOMEGA_DGAMMA: usize = 4;
    pub const ENERGY: usize = 5;
    pub const CYCLIC_MOMENTUM: usize = 6;
    pub const FULL_EQUATIONS: usize = 7;
    pub const FULL_JACOBIAN: usize = 8;
    pub const PSI_DOT: usize = 9;
    pub const ROUTHIAN: usize = 10;
    pub const DR_DOMEGA: usize = 11;
    pub const DR_DGAMMA: usize = 12;
    pub const DR_DP: usize = 13;
    pub const D2R_DOMEGA2: usize = 14;
    pub const D2R_DOMEGA_DGAMMA: usize = 15;
    pub const D2R_DGAMMA2: usize = 16;
    pub const AMENDED_POTENTIAL: usize = 17;
    pub const BUNDLE: usize = 18;
    pub const GYROSCOPIC_SYSTEM: usize = 19;
    pub const REDUCED_EQUATIONS: usize = 20;
    pub const BUNDLE_AND_SYSTEM: usize = 21;
}

impl<T> Tapes<T> {
    /// Every tape, in the order of [`TAPE_NAMES`] (indices in [`index`]).
    pub fn fields(&self) -> [&T; TAPES] {
        [
            &self.lagrangian,
            &self.dl_domega,
            &self.dl_dgamma,
            &self.d2l_domega2,
            &self.d2l_domega_dgamma,
            &self.energy,
            &self.cyclic_momentum,
            &self.full_equations,
            &self.full_jacobian,
            &self.psi_dot,
            &self.routhian,
            &self.dr_domega,
            &self.dr_dgamma,
            &self.dr_dp,
            &self.d2r_domega2,
            &self.d2r_domega_dgamma,
            &self.d2r_dgamma2,
            &self.amended_potential,
            &self.bundle,
            &self.gyroscopic_system,
            &self.reduced_equations,
            &self.bundle_and_system,
        ]
    }
}

/// A model's text reduced to tapes.
#[derive(Clone, Debug)]
pub(crate) struct Compiled {
    /// How `Op::Param(k)` is read: the parameter's name and which scalar of it.
    pub reads: Vec<(String, Access)>,
    pub tapes: Tapes<Tape>,
    /// `J₀` of `J = J₀ + c v vᵀ` (a tape of parameters only), when the kinetic energy has that
    /// form.
    pub constant_inertia: Option<Tape>,
    /// Whether the equations carry `(c, v)`.
    pub rank_one: bool,
    pub certification: Tape,
    pub routh: Tape,
    /// `L` and the derivatives of (8) ([`routh_tape::FLOW_OUTPUTS`]).
    pub flow: Tape,
    /// Each tape of [`Compiled::tapes`] (in the order of [`Tapes::fields`]) cut into its
    /// parameter-only part and the rest ([`crate::hoist`]): what the kernels evaluate.
    pub split: Vec<crate::hoist::Split>,
    /// `L`, `U_r` and `ψ̇` at rest after simplification, as the derive's `DerivedFormulas`.
    pub formulas: [String; 3],
    /// The formulas in LaTeX, every parameter printed as `\mathit{name}` (the model's own
    /// symbols are put in by [`Model::latex`](crate::Model::latex)): printed the first time
    /// they are asked for ([`latex`]), as printing them costs a third of a build.
    pub latex: std::sync::OnceLock<routh_codegen::latex::LatexText>,
    /// The same formulas in SymPy's syntax ([`sympy`]), printed the first time they are asked
    /// for.
    pub sympy: std::sync::OnceLock<routh_codegen::latex::SympyText>,
}

/// The deepest nesting of brackets accepted: deeper texts are refused before they are lexed
/// (the parsers recurse on nesting).
const MAX_NESTING: usize = 64;

/// Reduces `text` with `params` as its parameters to the tapes of a model.
pub(crate) fn compile(
    text: &str,
    params: &[(String, Param)],
    symmetric: &[String],
) -> Result<Compiled, ModelError> {
    on_large_stack(|| {
        let model = analyse(text, params, symmetric)?;
        build(&model).map_err(|e| {
            ModelError::general(format!(
                "internal error: the reduced model does not make a valid tape ({e})"
            ))
        })
    })
}

/// The stack of the thread a model is analysed on (reserved, not committed: the pages a text
/// does not need are never touched).
const ANALYSIS_STACK: usize = 512 << 20;

/// Runs `f` on a thread of its own with an [`ANALYSIS_STACK`] stack: the parser (`syn`), the
/// destructors of its syntax trees and some passes of the analysis recurse on the length of
/// a chain (a flat sum of 50 000 terms is a left-deep tree 50 000 levels deep), and the
/// caller's thread (a Python thread, a test thread) may have a small stack. Deep nesting is
/// refused before this ([`check_nesting`], [`check_prefix_runs`]); this is what makes long
/// flat texts safe whatever thread builds the model. Falls back to the caller's thread when a
/// thread cannot be started.
pub(crate) fn on_large_stack<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    let f = std::sync::Mutex::new(Some(f));
    let run = || (f.lock().unwrap_or_else(|e| e.into_inner()).take()).map(|f| f());
    let out = std::thread::scope(|s| {
        match std::thread::Builder::new()
            .name("routh-analyse".into())
            .stack_size(ANALYSIS_STACK)
            .spawn_scoped(s, run)
        {
            Ok(h) => Some(h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))),
            Err(_) => None,
        }
    });
    match out.flatten() {
        Some(r) => r,
        None => {
            let f = f.into_inner().unwrap_or_else(|e| e.into_inner());
            f.expect("the analysis ran neither on its thread nor here")()
        }
    }
}

/// The LaTeX of the formulas of the model of `text` (every parameter as `\mathit{name}`): the
/// text analysed again (it was when the model was built, so it cannot fail; empty formulas if
/// it did), as the analysed model cannot be kept in a `Send + Sync` `Model`.
pub(crate) fn latex(
    text: &str,
    params: &[(String, Param)],
    symmetric: &[String],
) -> routh_codegen::latex::LatexText {
    // The parameters in the order the Lagrangian first names them (the `[parameters]` table
    // comes sorted by name): the LaTeX's products list them in that order, `m g l` as the
    // text writes `mass * g * l`, not `g l m`.
    let mut params = params.to_vec();
    params.sort_by_key(|(name, _)| first_offset(text, name));
    on_large_stack(|| {
        analyse(text, &params, symmetric)
            .map(|m| routh_codegen::latex::latex_formulas(&m, &[]))
            .unwrap_or_default()
    })
}

/// The byte offset of the first use of the identifier `name` in `text` (`usize::MAX` if none).
fn first_offset(text: &str, name: &str) -> usize {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(name)
        .find(|&(at, _)| {
            !text[..at].chars().next_back().is_some_and(ident)
                && !text[at + name.len()..].chars().next().is_some_and(ident)
        })
        .map_or(usize::MAX, |(at, _)| at)
}

/// The formulas of the model of `text` in SymPy's syntax, analysed again as for [`latex`].
pub(crate) fn sympy(
    text: &str,
    params: &[(String, Param)],
    symmetric: &[String],
) -> routh_codegen::latex::SympyText {
    analyse(text, params, symmetric)
        .map(|m| routh_codegen::latex::sympy_formulas(&m))
        .unwrap_or_default()
}

/// Parses, checks, lowers and reduces `text` with `params` as its parameters.
fn analyse(
    text: &str,
    params: &[(String, Param)],
    symmetric: &[String],
) -> Result<routh_codegen::Model, ModelError> {
    check_nesting(text)?;
    let body: TokenStream = text.parse().map_err(|e: proc_macro2::LexError| {
        if let Some(err) = unbalanced(text) {
            return err;
        }
        let s = e.span();
        let (a, b) = (s.start(), s.end());
        let width = if a.line == b.line {
            b.column.saturating_sub(a.column)
        } else {
            1
        };
        ModelError::at(
            format!("the text cannot be read here ({e}): a Lagrangian is made of numbers, names, `+ - * /`, `.`, brackets, `=` and commas"),
            text,
            a.line,
            a.column + 1,
            width,
        )
    })?;
    check_prefix_runs(&body, text)?;
    let mut fields = Vec::new();
    for (name, p) in params {
        let ident: syn::Ident = syn::parse_str(name).map_err(|_| {
            let (line, column) = first_use(text, name);
            ModelError::at(
                format!(
                    "`{name}` is not a valid parameter name (a Rust identifier, not a keyword)"
                ),
                text,
                line,
                column,
                name.chars().count(),
            )
        })?;
        let kind = match p {
            Param::Scalar(_) => FieldKind::Scalar,
            Param::Vector(_) => FieldKind::Vector,
            Param::Matrix(_) => FieldKind::Matrix,
        };
        let mut field = Field::new(ident, kind);
        // Not in the text: an error about it is placed at the parameter's first use.
        field.symmetric = symmetric.contains(name).then(Span::call_site);
        fields.push(field);
    }
    for s in symmetric {
        if !params.iter().any(|(n, _)| n == s) {
            let (line, column) = first_use(text, s);
            return Err(ModelError::at(
                format!("`symmetric` names `{s}`, which is not a parameter of the model"),
                text,
                line,
                column,
                s.chars().count(),
            ));
        }
    }
    routh_codegen::analyse_parts(&fields, &Body::text(body))
        .map_err(|e| to_model_error(&e, text, params))
}

/// The first unbalanced bracket of `text`, as an error at it (`(` never closed, `)` closing
/// nothing or another kind of bracket), or `None` when the brackets balance. Strings and
/// comments are not skipped: it explains a lexing error, which they would be too.
fn unbalanced(text: &str) -> Option<ModelError> {
    let mut open: Vec<(char, usize)> = Vec::new();
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' | '{' => open.push((c, i)),
            ')' | ']' | '}' => {
                let want = match c {
                    ')' => '(',
                    ']' => '[',
                    _ => '{',
                };
                match open.pop() {
                    Some((o, _)) if o == want => {}
                    Some((o, at)) => {
                        let (line, column) = crate::error::line_column(text, at);
                        return Some(ModelError::at_byte(
                            format!(
                                "`{c}` does not close the `{o}` at line {line}, column {column}"
                            ),
                            text,
                            i,
                            i + 1,
                        ));
                    }
                    None => {
                        return Some(ModelError::at_byte(
                            format!("`{c}` closes no bracket"),
                            text,
                            i,
                            i + 1,
                        ))
                    }
                }
            }
            _ => {}
        }
    }
    open.pop()
        .map(|(o, at)| ModelError::at_byte(format!("`{o}` is never closed"), text, at, at + 1))
}

/// Refuses texts nested deeper than [`MAX_NESTING`], at the first bracket too deep.
fn check_nesting(text: &str) -> Result<(), ModelError> {
    let mut depth = 0usize;
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' | '{' => {
                depth += 1;
                if depth > MAX_NESTING {
                    return Err(ModelError::at_byte(
                        format!("brackets nested more than {MAX_NESTING} deep; split the expression with `let` items"),
                        text,
                        i,
                        i + 1,
                    ));
                }
            }
            ')' | ']' | '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    Ok(())
}

/// Refuses more than [`MAX_NESTING`] prefix operators in a row (`- - - x`: each is a level of
/// the parser's recursion), at the first one too many. Walks the token tree with a stack of
/// its own.
fn check_prefix_runs(body: &TokenStream, text: &str) -> Result<(), ModelError> {
    use proc_macro2::TokenTree;
    let mut stack = vec![body.clone().into_iter()];
    let mut run = 0usize;
    while let Some(top) = stack.last_mut() {
        let Some(tt) = top.next() else {
            stack.pop();
            run = 0;
            continue;
        };
        match tt {
            TokenTree::Punct(p) if matches!(p.as_char(), '-' | '!' | '&' | '*') => {
                run += 1;
                if run > MAX_NESTING {
                    let at = p.span().start();
                    return Err(ModelError::at(
                        format!("more than {MAX_NESTING} signs or operators in a row (each is a level of nesting); simplify them or split the expression with `let` items"),
                        text,
                        at.line,
                        at.column + 1,
                        1,
                    ));
                }
            }
            TokenTree::Group(g) => {
                run = 0;
                stack.push(g.stream().into_iter());
            }
            _ => run = 0,
        }
    }
    Ok(())
}

/// `(line, column)` of the first occurrence of `name` in `text` as a word, or `(1, 1)`.
pub(crate) fn first_use(text: &str, name: &str) -> (usize, usize) {
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(k) = text.get(from..).and_then(|t| t.find(name)) {
        let at = from + k;
        let before = text[..at].chars().next_back();
        let after = text[at + name.len()..].chars().next();
        if !name.is_empty() && !before.is_some_and(is_word) && !after.is_some_and(is_word) {
            return crate::error::line_column(text, at);
        }
        from = at + name.len().max(1);
    }
    (1, 1)
}

/// The front end's errors as a [`ModelError`] (the first, the others attached). An error whose
/// span is not in the text (it is about a parameter) is placed at the first use of the
/// parameter it names, or at the start of the text.
fn to_model_error(err: &syn::Error, text: &str, params: &[(String, Param)]) -> ModelError {
    let mut all = err.clone().into_iter().map(|e| one_error(&e, text, params));
    let mut first = all
        .next()
        .unwrap_or_else(|| ModelError::general("the model could not be read"));
    first.others = all.collect();
    first
}

fn one_error(e: &syn::Error, text: &str, params: &[(String, Param)]) -> ModelError {
    let message = e.to_string();
    let span: Span = e.span();
    let (a, b) = (span.start(), span.end());
    let lines = text.lines().count().max(1);
    if ((1..=lines).contains(&a.line) && (a.line, a.column) != (1, 0)) || from_text(text, a) {
        let width = if a.line == b.line {
            b.column.saturating_sub(a.column)
        } else {
            text.lines()
                .nth(a.line - 1)
                .map_or(1, |l| l.chars().count().saturating_sub(a.column))
        };
        return ModelError::at(message, text, a.line, a.column + 1, width);
    }
    // About a parameter: at its first use.
    for (name, _) in params {
        if message.contains(&format!("`{name}`")) {
            let (line, column) = first_use(text, name);
            return ModelError::at(message, text, line, column, name.chars().count());
        }
    }
    ModelError::at(message, text, 1, 1, 1)
}

/// Whether a position `(1, 0)` is really the start of the text (and not `Span::call_site()`,
/// where errors about a parameter or the text as a whole are, which `proc_macro2` places at
/// `(1, 0)` too).
fn from_text(text: &str, a: proc_macro2::LineColumn) -> bool {
    a.line == 1 && a.column == 0 && !text.starts_with(char::is_whitespace) && !text.is_empty()
}

/// The tapes of every generated method of an analysed model.
fn build(m: &routh_codegen::Model) -> Result<Compiled, routh_tape::TapeError> {
    use routh_codegen::tape::tape;
    let sym = &m.lowered.sym;
    let o = &m.outputs;
    let eq = &m.equations;
    let rank_one = m.rank_one.as_ref();
    let one = |name: &'static str, id: Id| tape(sym, &[(name, id)]);
    let three = |names: [&'static str; 3], ids: [Id; 3]| {
        tape(sym, &names.into_iter().zip(ids).collect::<Vec<_>>())
    };
    let nine = |names: [[&'static str; 3]; 3], ids: [[Id; 3]; 3]| {
        let outs: Vec<_> = names
            .into_iter()
            .flatten()
            .zip(ids.into_iter().flatten())
            .collect();
        tape(sym, &outs)
    };
    let terms_names = |psi_dot: bool| EquationTerms {
        inertia: m33!("inertia"),
        right_side: v3!("right_side"),
        psi_dot: psi_dot.then_some("psi_dot"),
        rank_one: rank_one.map(|_| ("weight", v3!("vector"))),
    };
    let terms = |right_side, psi_dot: Option<Id>| EquationTerms {
        inertia: o.d2l_domega2,
        right_side,
        psi_dot,
        rank_one: rank_one.map(|r| (r.weight, r.vector)),
    };
    let zip = |names: Vec<&'static str>, ids: Vec<Id>| -> Vec<(&'static str, Id)> {
        names.into_iter().zip(ids).collect()
    };
    let bundle_names = Bundle {
        routhian: "routhian",
        psi_dot: "psi_dot",
        dr_domega: v3!("dr_domega"),
        dr_dgamma: v3!("dr_dgamma"),
        dr_dp: "dr_dp",
        d2r_domega2: m33!("d2r_domega2"),
        d2r_domega_dgamma: m33!("d2r_domega_dgamma"),
        d2r_dgamma2: m33!("d2r_dgamma2"),
    };
    let gyro_names = Gyroscopic {
        a: m33!("a"),
        g: m33!("g"),
        c: m33!("c"),
    };
    let tapes = Tapes {
        lagrangian: one("lagrangian", o.lagrangian)?,
        dl_domega: three(v3!("dl_domega"), o.dl_domega)?,
        dl_dgamma: three(v3!("dl_dgamma"), o.dl_dgamma)?,
        d2l_domega2: nine(m33!("d2l_domega2"), o.d2l_domega2)?,
        d2l_domega_dgamma: nine(m33!("d2l_domega_dgamma"), o.d2l_domega_dgamma)?,
        energy: one("energy", o.energy)?,
        cyclic_momentum: one("cyclic_momentum", o.cyclic_momentum)?,
        full_equations: tape(
            sym,
            &zip(terms_names(false).flatten(), terms(eq.full, None).flatten()),
        )?,
        full_jacobian: tape(
            sym,
            &zip(
                JacobianTerms {
                    inertia: m33!("inertia"),
                    right_side: v3!("right_side"),
                    dright_domega: m33!("dright_domega"),
                    dright_dgamma: m33!("dright_dgamma"),
                    dinertia_dgamma: [
                        m33!("dinertia_dgamma[0]"),
                        m33!("dinertia_dgamma[1]"),
                        m33!("dinertia_dgamma[2]"),
                    ],
                }
                .flatten(),
                eq.jacobian.flatten(),
            ),
        )?,
        psi_dot: one("psi_dot", o.psi_dot)?,
        routhian: one("routhian", o.routhian)?,
        dr_domega: three(v3!("dr_domega"), o.dr_domega)?,
        dr_dgamma: three(v3!("dr_dgamma"), o.dr_dgamma)?,
        dr_dp: one("dr_dp", o.dr_dp)?,
        d2r_domega2: nine(m33!("d2r_domega2"), o.d2r_domega2)?,
        d2r_domega_dgamma: nine(m33!("d2r_domega_dgamma"), o.d2r_domega_dgamma)?,
        d2r_dgamma2: nine(m33!("d2r_dgamma2"), o.d2r_dgamma2)?,
        amended_potential: one("amended_potential", o.amended_potential)?,
        bundle: tape(sym, &zip(bundle_names.flatten(), o.bundle().flatten()))?,
        gyroscopic_system: tape(sym, &zip(gyro_names.flatten(), o.gyroscopic().flatten()))?,
        reduced_equations: tape(
            sym,
            &zip(
                terms_names(true).flatten(),
                terms(eq.reduced, Some(o.psi_dot)).flatten(),
            ),
        )?,
        // The derive's fused body: A, G, C of (64) formed from the bundle's own nodes.
        bundle_and_system: tape(
            sym,
            &zip(
                BundleAndSystem {
                    bundle: bundle_names,
                    system: gyro_names,
                }
                .flatten(),
                o.bundle_and_system().flatten(),
            ),
        )?,
    };
    let constant_inertia = rank_one
        .map(|r| nine(m33!("constant_inertia"), r.constant))
        .transpose()?;
    let reads = sym
        .params
        .iter()
        .map(|p| (p.field.to_string(), p.access))
        .collect();
    let graph = &sym.graph;
    let formulas = [o.lagrangian, o.amended_potential, o.psi_dot_at_rest]
        .map(|id| routh_symbolic::to_infix(graph, id));
    let split = tapes
        .fields()
        .into_iter()
        .map(crate::hoist::split)
        .collect::<Result<_, _>>()?;
    Ok(Compiled {
        reads,
        split,
        tapes,
        constant_inertia,
        rank_one: rank_one.is_some(),
        certification: routh_codegen::tape::certification(sym, o)?,
        routh: routh_codegen::tape::routhian(sym, o)?,
        flow: routh_codegen::tape::flow(sym, o)?,
        formulas,
        latex: std::sync::OnceLock::new(),
        sympy: std::sync::OnceLock::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The indices name the tapes they index, in [`TAPE_NAMES`].
    #[test]
    fn indices_name_their_tapes() {
        let pairs = [
            (index::LAGRANGIAN, "lagrangian"),
            (index::DL_DOMEGA, "dl_domega"),
            (index::DL_DGAMMA, "dl_dgamma"),
            (index::D2L_DOMEGA2, "d2l_domega2"),
            (index::D2L_DOMEGA_DGAMMA, "d2l_domega_dgamma"),
            (index::ENERGY, "energy"),
            (index::CYCLIC_MOMENTUM, "cyclic_momentum"),
            (index::FULL_EQUATIONS, "full_equations"),
            (index::FULL_JACOBIAN, "full_jacobian"),
            (index::PSI_DOT, "psi_dot"),
            (index::ROUTHIAN, "routhian"),
            (index::DR_DOMEGA, "dr_domega"),
            (index::DR_DGAMMA, "dr_dgamma"),
            (index::DR_DP, "dr_dp"),
            (index::D2R_DOMEGA2, "d2r_domega2"),
            (index::D2R_DOMEGA_DGAMMA, "d2r_domega_dgamma"),
            (index::D2R_DGAMMA2, "d2r_dgamma2"),
            (index::AMENDED_POTENTIAL, "amended_potential"),
            (index::BUNDLE, "bundle"),
            (index::GYROSCOPIC_SYSTEM, "gyroscopic_system"),
            (index::REDUCED_EQUATIONS, "reduced_equations"),
            (index::BUNDLE_AND_SYSTEM, "bundle_and_system"),
        ];
        assert_eq!(pairs.len(), TAPES);
        for (k, name) in pairs {
            assert_eq!(TAPE_NAMES[k], name);
        }
        // And the tapes' own output names agree: compile a model and look.
        let c = compile(
            "kinetic = 0.5 * omega.dot(omega), potential = gamma.z",
            &[],
            &[],
        )
        .expect("a model");
        let f = c.tapes.fields();
        assert_eq!(f[index::BUNDLE].outputs()[0].name, "routhian");
        assert_eq!(f[index::GYROSCOPIC_SYSTEM].outputs()[0].name, "a[0][0]");
        assert_eq!(f[index::BUNDLE_AND_SYSTEM].outputs().len(), 63);
        assert_eq!(
            f[index::AMENDED_POTENTIAL].outputs()[0].name,
            "amended_potential"
        );
        assert_eq!(f[index::DR_DP].outputs()[0].name, "dr_dp");
    }
}
