//! No-panic fuzzing of `routh_codegen::derive`: DSL mistakes are compile errors, never panics.
//!
//! The attribute bodies of a few valid models are mutated at the token level (deleting,
//! duplicating, swapping, replacing, inserting, wrapping in and unwrapping groups, transplanting
//! subtrees between models, recursively inside groups); every mutant is expanded inside
//! `catch_unwind`. Deterministic: the seed and the number of inputs can be changed with
//! `ROUTH_FUZZ_SEED` and `ROUTH_FUZZ_N`.

use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashSet;
use std::panic::{self, AssertUnwindSafe};
use std::str::FromStr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// `(attribute body, fields)` of valid models.
const SEEDS: &[(&str, &str)] = &[
    // Kelvin gyrostat (the README's DSL example).
    (
        "kinetic = 0.5 * omega.dot(inertia * omega),
         linear = (rotor + coupling * gamma).dot(omega),
         potential = mass * g * com.dot(gamma),",
        "pub inertia: Matrix3<f64>, pub rotor: Vector3<f64>, pub coupling: Matrix3<f64>,
         pub com: Vector3<f64>, pub mass: f64, pub g: f64,",
    ),
    // Ellipsoid on a plane, with `let` and `grad` (examples/smoke.rs).
    (
        "let d = diag(semi_axes.component_mul(semi_axes)),
         let c3 = (gamma.dot(d * gamma)).sqrt() - offset.dot(gamma),
         let n = grad(c3, gamma),
         kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
         potential = mass * g * c3,",
        "pub inertia: Matrix3<f64>, pub semi_axes: Vector3<f64>, pub offset: Vector3<f64>,
         pub mass: f64, pub g: f64,",
    ),
    // Heavy top with `diag`.
    (
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega),
         potential = mgl * gamma.z,",
        "inertia: Vector3<f64>, mgl: f64,",
    ),
    // Every method, function and index form.
    (
        "let s = skew(b),
         let m = (a + a.transpose()) * 0.5 + diag(b.component_mul(b)),
         let t = m.trace(),
         kinetic = 0.5 * omega.dot(m * omega) + t * omega.norm_squared()
             + (s * omega).norm_squared() + omega[0] * omega[(1)] * c.abs()
             + omega.x * omega.z * a[(2, 1)] / (1 + gamma.norm()),
         linear = (skew(b) * gamma).dot(omega) * gamma.z.sin() + omega.y * gamma[2].cos()
             + omega.z * (gamma.x.tan() + gamma.y.exp() + (2.0 + gamma.z * gamma.z).ln()
             + (1.0 + gamma.x.powi(2)).recip()),
         potential = c * gamma.dot(b) + d * (2.0 + gamma.z).powf(1.5) + (3.0 + gamma.x).powf(d)
             + a[(0, 2)] * gamma.x - (gamma.z.powi(4) / c).sqrt() + gamma.y.powi(-2),",
        "a: Matrix3<f64>, b: Vector3<f64>, c: f64, d: f64, #[lagrangian(skip)] name: String,",
    ),
    // `self.` paths, references, unary minus, `crate = "..."`.
    (
        "crate = \"::routh\",
         kinetic = 0.5 * &omega.dot(&(self.inertia * omega)),
         linear = -(omega.dot(&self.spin)),
         potential = -(-self.mass) * self.g * gamma.z,",
        "inertia: ::routh::Matrix3<f64>, spin: nalgebra::Vector3<f64>, mass: core::primitive::f64,
         g: f64,",
    ),
    // Gyrostat with a contact normal from `grad` and `cross`.
    (
        "let h = grad(0.5 * gamma.dot(k * gamma), gamma),
         kinetic = 0.5 * omega.dot(inertia * omega) + 0.5 * m * h.cross(omega).norm_squared(),
         linear = rotor.dot(omega) + omega.dot(gamma.cross(h)),
         potential = m * g * h.dot(com) / (1 + gamma.norm()),",
        "inertia: Matrix3<f64>, k: Matrix3<f64>, rotor: Vector3<f64>, com: Vector3<f64>, m: f64,
         g: f64,",
    ),
    // Lagrange top written with scalars only.
    (
        "kinetic = 0.5 * (a * omega.x.powi(2) + b * omega.y * omega.y + c * omega.z * omega.z),
         potential = mgl * gamma[2],",
        "a: f64, b: f64, c: f64, mgl: f64,",
    ),
];

/// Tokens that the mutator inserts or substitutes.
const IDENTS: &[&str] = &[
    "omega",
    "gamma",
    "kinetic",
    "linear",
    "potential",
    "let",
    "crate",
    "self",
    "diag",
    "skew",
    "grad",
    "dot",
    "cross",
    "norm",
    "norm_squared",
    "transpose",
    "component_mul",
    "trace",
    "sqrt",
    "powi",
    "powf",
    "sin",
    "cos",
    "tan",
    "exp",
    "ln",
    "recip",
    "abs",
    "x",
    "y",
    "z",
    "w",
    "inertia",
    "mass",
    "g",
    "a",
    "b",
    "c",
    "d",
    "n",
    "h",
    "m",
    "foo",
    "if",
    "else",
    "as",
    "f64",
    "Vector3",
    "skip",
    "r#omega",
    "_",
];
const PUNCTS: &[char] = &[
    '+', '-', '*', '/', '%', ',', '=', '.', '!', '&', '|', '<', '>', ';', ':', '#', '^', '?', '@',
];
const LITERALS: &[&str] = &[
    "0",
    "1",
    "2",
    "3",
    "-1",
    "64",
    "65",
    "0.5",
    "0.0",
    "-0.0",
    "1e308",
    "1e400",
    "1e-320",
    "2.5f64",
    "1f32",
    "2u8",
    "7i64",
    "99999999999999999999",
    "0x10",
    "\"s\"",
    "\"::routh\"",
    "\"\"",
    "'c'",
    "b'x'",
    "true",
];

#[derive(Clone)]
enum Tok {
    Leaf(TokenTree),
    Group(Delimiter, Vec<Tok>),
}

fn to_toks(ts: TokenStream) -> Vec<Tok> {
    ts.into_iter()
        .map(|tt| match tt {
            TokenTree::Group(g) => Tok::Group(g.delimiter(), to_toks(g.stream())),
            other => Tok::Leaf(other),
        })
        .collect()
}

fn to_stream(toks: &[Tok]) -> TokenStream {
    toks.iter()
        .map(|t| match t {
            Tok::Leaf(tt) => tt.clone(),
            Tok::Group(d, inner) => TokenTree::Group(Group::new(*d, to_stream(inner))),
        })
        .collect()
}

/// Every token sequence of the tree (the top level and the inside of every group), as paths of
/// group indices.
fn sequences(toks: &[Tok], path: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
    out.push(path.clone());
    for (i, t) in toks.iter().enumerate() {
        if let Tok::Group(_, inner) = t {
            path.push(i);
            sequences(inner, path, out);
            path.pop();
        }
    }
}

fn seq_mut<'a>(toks: &'a mut Vec<Tok>, path: &[usize]) -> &'a mut Vec<Tok> {
    let mut cur = toks;
    for &i in path {
        cur = match &mut cur[i] {
            Tok::Group(_, inner) => inner,
            Tok::Leaf(_) => unreachable!("paths only name groups"),
        };
    }
    cur
}

fn random_subtree(rng: &mut ChaCha8Rng, toks: &[Tok]) -> Option<Tok> {
    let t = toks.choose(rng)?;
    match t {
        Tok::Group(_, inner) if rng.gen_bool(0.5) && !inner.is_empty() => {
            random_subtree(rng, inner)
        }
        _ => Some(t.clone()),
    }
}

fn random_delimiter(rng: &mut ChaCha8Rng) -> Delimiter {
    *[
        Delimiter::Parenthesis,
        Delimiter::Bracket,
        Delimiter::Brace,
        Delimiter::None,
    ]
    .choose(rng)
    .unwrap()
}

fn random_token(rng: &mut ChaCha8Rng, donors: &[Vec<Tok>]) -> Tok {
    match rng.gen_range(0..10) {
        0..=3 => {
            let s = *IDENTS.choose(rng).unwrap();
            let id = match s.strip_prefix("r#") {
                Some(raw) => Ident::new_raw(raw, Span::call_site()),
                None => Ident::new(s, Span::call_site()),
            };
            Tok::Leaf(TokenTree::Ident(id))
        }
        4..=6 => {
            let c = *PUNCTS.choose(rng).unwrap();
            let spacing = if rng.gen_bool(0.3) {
                Spacing::Joint
            } else {
                Spacing::Alone
            };
            Tok::Leaf(TokenTree::Punct(Punct::new(c, spacing)))
        }
        7 | 8 => {
            let s = *LITERALS.choose(rng).unwrap();
            let ts = TokenStream::from_str(s).unwrap();
            let mut toks = to_toks(ts);
            if toks.len() == 1 {
                toks.pop().unwrap()
            } else {
                // `-1`: a negative literal, built directly.
                Tok::Leaf(TokenTree::Literal(Literal::i32_unsuffixed(-1)))
            }
        }
        _ => {
            let donor = donors.choose(rng).unwrap();
            random_subtree(rng, donor).unwrap_or(Tok::Group(random_delimiter(rng), vec![]))
        }
    }
}

/// Applies one random mutation somewhere in the tree.
fn mutate(rng: &mut ChaCha8Rng, toks: &mut Vec<Tok>, donors: &[Vec<Tok>]) {
    let mut paths = vec![];
    sequences(toks, &mut vec![], &mut paths);
    let path = paths.choose(rng).unwrap().clone();
    let fresh = random_token(rng, donors);
    let delim = random_delimiter(rng);
    let seq = seq_mut(toks, &path);
    let n = seq.len();
    if n == 0 {
        seq.push(fresh);
        return;
    }
    let i = rng.gen_range(0..n);
    match rng.gen_range(0..10) {
        // delete one token
        0 => {
            seq.remove(i);
        }
        // delete a run
        1 => {
            let j = rng.gen_range(i..=n.min(i + 4));
            seq.drain(i..j);
        }
        // duplicate a run
        2 => {
            let j = rng.gen_range(i + 1..=n.min(i + 5));
            let run: Vec<Tok> = seq[i..j].to_vec();
            let at = rng.gen_range(0..=n);
            seq.splice(at..at, run);
        }
        // repeat a run in place (`.powi(2).powi(2)...`, `- - -x`)
        9 => {
            let j = rng.gen_range(i + 1..=n.min(i + 4));
            let run: Vec<Tok> = seq[i..j].to_vec();
            let k = rng.gen_range(1..=32);
            let copies: Vec<Tok> = std::iter::repeat_n(run, k).flatten().collect();
            seq.splice(j..j, copies);
        }
        // swap two tokens
        3 => {
            let j = rng.gen_range(0..n);
            seq.swap(i, j);
        }
        // replace
        4 | 5 => seq[i] = fresh,
        // insert
        6 => seq.insert(i, fresh),
        // wrap a run in a group
        7 => {
            let j = rng.gen_range(i..=n.min(i + 4));
            let run: Vec<Tok> = seq.drain(i..j).collect();
            seq.insert(i, Tok::Group(delim, run));
        }
        // unwrap a group, or change its delimiter
        _ => {
            if let Tok::Group(d, inner) = seq[i].clone() {
                if rng.gen_bool(0.5) {
                    seq.splice(i..=i, inner);
                } else {
                    seq[i] = Tok::Group(
                        if d == delim {
                            Delimiter::Parenthesis
                        } else {
                            delim
                        },
                        inner,
                    );
                }
            } else {
                seq.remove(i);
            }
        }
    }
}

/// `#[lagrangian(BODY)] pub struct Model { FIELDS }`.
fn derive_input(body: &TokenStream, fields: &TokenStream) -> TokenStream {
    let attr: TokenStream = [
        TokenTree::Ident(Ident::new("lagrangian", Span::call_site())),
        TokenTree::Group(Group::new(Delimiter::Parenthesis, body.clone())),
    ]
    .into_iter()
    .collect();
    let mut ts: TokenStream = [
        TokenTree::Punct(Punct::new('#', Spacing::Alone)),
        TokenTree::Group(Group::new(Delimiter::Bracket, attr)),
    ]
    .into_iter()
    .collect();
    ts.extend(TokenStream::from_str("pub struct Model").unwrap());
    ts.extend([TokenTree::Group(Group::new(
        Delimiter::Brace,
        fields.clone(),
    ))]);
    ts
}

/// The traits implemented for `ident` in the `const _: () = { ... };` blocks of `file`.
fn trait_impls(file: &syn::File, ident: &Ident) -> Vec<String> {
    let mut out = vec![];
    for item in &file.items {
        let syn::Item::Const(c) = item else { continue };
        let syn::Expr::Block(b) = &*c.expr else {
            continue;
        };
        for stmt in &b.block.stmts {
            let syn::Stmt::Item(syn::Item::Impl(imp)) = stmt else {
                continue;
            };
            let self_is_ident =
                matches!(&*imp.self_ty, syn::Type::Path(p) if p.path.is_ident(ident));
            if let (Some((_, path, _)), true) = (&imp.trait_, self_is_ident) {
                if let Some(seg) = path.segments.last() {
                    out.push(seg.ident.to_string());
                }
            }
        }
    }
    out
}

/// Hand-written edge cases, run before the random ones: `(attribute body, fields)`; `None` for the
/// fields means the gyrostat's.
const EDGE_CASES: &[(&str, Option<&str>)] = &[
    // Integer powers that overflow `i32`/`u32` exponents or degrees.
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = gamma.z.powi(64).powi(64).powi(64).powi(64).powi(64).powi(64) * gamma.z", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = gamma.z.powi(64).powi(64).powi(64).powi(64).powi(64).powi(-64)", None),
    ("kinetic = (omega.x * omega.y * omega.z).powi(64).powi(64).powi(64).powi(64).powi(64).powi(64)", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = gamma.z.powi(-64).powi(-64).powi(-64)", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = gamma.z.powf(1e300).powf(1e300)", None),
    // Literals.
    ("kinetic = 1e400 * omega.dot(inertia * omega), potential = -1e400 * gamma.z", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = (0.0 / 0.0) * gamma.z + -0.0 + 1e-320", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = 99999999999999999999 * gamma.z", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega), potential = 0x10 * gamma.z + 1_000.5e-3 + 1f64", None),
    ("kinetic = (0.0 / 0.0) * omega.dot(omega)", None),
    ("kinetic = 0.5 * omega.dot(inertia * omega) / 0", None),
    // Malformed items.
    ("", None),
    (",,,", None),
    ("kinetic", None),
    ("kinetic =", None),
    ("kinetic = = omega.dot(omega)", None),
    ("let", None),
    ("let x", None),
    ("let x =", None),
    ("let 1 = 2, kinetic = omega.dot(omega)", None),
    ("crate", None),
    ("crate =", None),
    ("crate = 1, kinetic = omega.dot(omega)", None),
    ("crate = \"\", kinetic = omega.dot(omega)", None),
    ("crate = \"a b\", kinetic = omega.dot(omega)", None),
    ("kinetic = omega.dot(omega); potential = mass", None),
    ("kinetic = |x| x", None),
    // Functions, methods and indices at the edges.
    ("kinetic = omega.dot(omega), potential = grad(grad(mass * gamma.z.powi(3), gamma).z, gamma).z", None),
    ("kinetic = omega.dot(omega), potential = grad(1, gamma).x + diag().trace() + skew(com, com).trace()", None),
    ("kinetic = omega.dot(omega), potential = grad(mass) + grad(com, gamma) + grad(mass, gamma.x)", None),
    ("kinetic = omega.dot(omega), potential = inertia[(0, 1, 2)] + inertia[(-1, 0)] + inertia[()] + com[-1]", None),
    ("kinetic = omega.dot(omega), potential = com[1usize] + com[&1] + com[(1)] + inertia[&(0, 1)] + mass[0]", None),
    ("kinetic = omega.dot(omega), potential = self.omega.x + self.mass + self + self.0 + com.0 + Self::mass + ::mass", None),
    ("kinetic = omega.dot(omega), potential = mass.dot() + mass.powi() + mass.powf() + mass.sqrt(1) + mass.powi(65)", None),
    ("kinetic = omega.dot(omega), potential = inertia.norm() + inertia.norm_squared() + mass.norm() + com.trace() + com.transpose().x", None),
    ("kinetic = omega.dot(omega), potential = com.component_mul(mass).x + inertia.component_mul(inertia).trace() + com.cross(inertia).x", None),
    ("kinetic = omega.dot(omega), potential = mass.sin.cos + (mass)() + mass::<f64>() + mass.abs::<f64>()", None),
    ("kinetic = omega.dot(omega), potential = mass += 1", None),
    ("kinetic = omega.dot(omega), potential = [mass, g][0] + (mass, g).0 + { mass } + mass as f64", None),
    // Names.
    ("let omega = 1, let gamma = 2, let diag = 3, let mass = 4, let t = 5, let t = 6, kinetic = omega.dot(omega) * t", None),
    ("let a = b, let b = a, kinetic = omega.dot(omega) * a * b", None),
    ("let a = a, kinetic = omega.dot(omega) * a", None),
    // Structs.
    ("kinetic = omega.dot(omega)", Some("gamma: Vector3<f64>, omega: f64, diag: Matrix3<f64>, #[lagrangian(skip)] skew: f64")),
    ("kinetic = omega.dot(omega) * x", Some("#[lagrangian] x: f64, #[lagrangian = 1] y: f64, #[lagrangian(skip, skip)] z: f64, #[lagrangian(skip)] #[lagrangian(skip)] w: Vec<u8>")),
    ("kinetic = omega.dot(omega) * x", Some("x: <f64 as Trait>::Output, y: Vector3<f64, f64>, z: Matrix3<>, w: Vector3<Vector3<f64>>, v: &'static f64, u: [f64; 3], t: (f64,), s: fn(f64)")),
];

/// Whole derive inputs.
const EDGE_INPUTS: &[&str] = &[
    "#[lagrangian(kinetic = omega.dot(omega))] pub struct M<T: Copy, const N: usize> where T: Default { #[lagrangian(skip)] t: [T; N], m: f64 }",
    "#[lagrangian(kinetic = omega.dot(omega))] pub struct M<'a> { #[lagrangian(skip)] r: &'a f64 }",
    "#[lagrangian(kinetic = omega.dot(omega))] union U { a: f64, b: u64 }",
    "#[lagrangian(kinetic = omega.dot(omega))] enum E {}",
    "#[lagrangian(kinetic = omega.dot(omega))] struct S;",
    "#[lagrangian(kinetic = omega.dot(omega))] struct S();",
    "#[lagrangian(kinetic = omega.dot(omega))] struct S {}",
    "#[lagrangian(kinetic = omega.dot(omega))] #[lagrangian(kinetic = omega.dot(omega), crate = \"::routh\")] #[lagrangian(crate = \"::routh\")] struct S {}",
    "#[lagrangian] #[lagrangian = 1] #[lagrangian()] #[lagrangian{kinetic = omega.dot(omega)}] struct S {}",
    "struct S { m: f64 }",
    "struct S",
    "",
    "fn f() {}",
];

/// Expands inputs and checks the output; records failures.
#[derive(Default)]
struct Checker {
    failures: Vec<String>,
    ran: usize,
    valid: usize,
    in_derive: Duration,
    in_parse: Duration,
    /// Outputs of valid models already parsed (mutants often give the same model).
    parsed_ok: HashSet<String>,
    last_panic: Arc<Mutex<String>>,
}

impl Checker {
    fn check(&mut self, input: TokenStream) {
        self.ran += 1;
        let text = input.to_string();
        let t0 = Instant::now();
        let result = panic::catch_unwind(AssertUnwindSafe(|| routh_codegen::derive(input.clone())));
        self.in_derive += t0.elapsed();
        let out = match result {
            Ok(out) => out,
            Err(_) => {
                let msg = self.last_panic.lock().unwrap().clone();
                self.failures
                    .push(format!("PANIC ({msg}) on input:\n{text}"));
                return;
            }
        };
        if out.is_empty() {
            self.failures
                .push(format!("EMPTY output on input:\n{text}"));
            return;
        }
        let Ok(di) = syn::parse2::<syn::DeriveInput>(input) else {
            return;
        };
        let key = out.to_string();
        if self.parsed_ok.contains(&key) {
            self.valid += 1;
            return;
        }
        let t1 = Instant::now();
        let parsed = syn::parse2::<syn::File>(out);
        self.in_parse += t1.elapsed();
        let file = match parsed {
            Ok(file) => file,
            Err(e) => {
                self.failures.push(format!(
                    "output does not parse as items ({e}) on input:\n{text}\noutput:\n{key}"
                ));
                return;
            }
        };
        let errors = file.items.iter().any(|i| {
            matches!(i, syn::Item::Macro(m) if m.mac.path.segments.last().is_some_and(|s| s.ident == "compile_error"))
        });
        if errors {
            // Errors come with stub impls of both traits, so that no follow-on errors appear.
            let impls = trait_impls(&file, &di.ident);
            if !(impls.iter().any(|t| t == "Lagrangian") && impls.iter().any(|t| t == "Routhian")) {
                self.failures.push(format!(
                    "errors without the stub impls on input:\n{text}\noutput:\n{key}"
                ));
            }
        } else {
            self.valid += 1;
            self.parsed_ok.insert(key);
        }
    }
}

#[test]
fn derive_never_panics() {
    let seed: u64 = std::env::var("ROUTH_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_2024);
    let total: usize = std::env::var("ROUTH_FUZZ_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);

    let seeds: Vec<(TokenStream, TokenStream)> = SEEDS
        .iter()
        .map(|(b, f)| {
            (
                TokenStream::from_str(b).unwrap(),
                TokenStream::from_str(f).unwrap(),
            )
        })
        .collect();
    let donors: Vec<Vec<Tok>> = seeds.iter().map(|(b, _)| to_toks(b.clone())).collect();

    // Every seed is a valid model: no error, and the output is items.
    for (i, (b, f)) in seeds.iter().enumerate() {
        let out = routh_codegen::derive(derive_input(b, f)).to_string();
        assert!(
            !out.contains("compile_error"),
            "seed {i} is not a valid model:\n{out}"
        );
        syn::parse_str::<syn::File>(&out)
            .unwrap_or_else(|e| panic!("seed {i}: output does not parse: {e}"));
    }

    // Record panic messages instead of printing them.
    let mut ck = Checker::default();
    let prev_hook = panic::take_hook();
    {
        let last_panic = ck.last_panic.clone();
        panic::set_hook(Box::new(move |info| {
            let loc = info
                .location()
                .map(|l| format!(" at {}:{}", l.file(), l.line()))
                .unwrap_or_default();
            let payload = info.payload();
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            *last_panic.lock().unwrap() = format!("{msg}{loc}");
        }));
    }
    let start = Instant::now();

    let gyrostat_fields = &seeds[0].1;
    for (body, fields) in EDGE_CASES {
        let body = TokenStream::from_str(body).unwrap();
        let fields = fields.map_or_else(
            || gyrostat_fields.clone(),
            |f| TokenStream::from_str(f).unwrap(),
        );
        ck.check(derive_input(&body, &fields));
    }
    for input in EDGE_INPUTS {
        ck.check(TokenStream::from_str(input).unwrap());
    }
    let edge = ck.ran;

    let mut whole = 0usize;
    while ck.ran < edge + total {
        let (body, fields) = seeds.choose(&mut rng).unwrap();
        let mutations = rng.gen_range(1..=4);
        let input = if rng.gen_bool(0.1) {
            // Mutate the whole derive input (struct, fields and field attributes too).
            whole += 1;
            let mut toks = to_toks(derive_input(body, fields));
            for _ in 0..mutations {
                mutate(&mut rng, &mut toks, &donors);
            }
            to_stream(&toks)
        } else {
            let mut toks = to_toks(body.clone());
            for _ in 0..mutations {
                mutate(&mut rng, &mut toks, &donors);
            }
            derive_input(&to_stream(&toks), fields)
        };
        ck.check(input);
    }
    panic::set_hook(prev_hook);

    let elapsed = start.elapsed();
    println!(
        "fuzz: ran {} inputs ({edge} hand-written, {total} mutants of which {whole} with the whole struct mutated; {} valid models, {} distinct) in {elapsed:.2?} ({:.2?} in derive, {:.2?} parsing outputs), seed {seed:#x}, {} failures",
        ck.ran,
        ck.valid,
        ck.parsed_ok.len(),
        ck.in_derive,
        ck.in_parse,
        ck.failures.len()
    );
    for f in ck.failures.iter().take(20) {
        println!("----\n{f}");
    }
    assert!(
        ck.failures.is_empty(),
        "{} of {} inputs failed (printed above)",
        ck.failures.len(),
        ck.ran
    );
}
