//! The two ways into the one front end agree: a struct through `analyse` (its fields and its
//! `#[lagrangian(...)]`) and the same parameters and body through `analyse_parts`, as
//! `routh-runtime` calls it for a model's text, give the same formulas and the same errors.

use proc_macro2::{Span, TokenStream};
use routh_codegen::{analyse, analyse_parts, Body, Field, FieldKind};

/// A struct with `body` as its attribute and the fields of [`PARAMS`].
fn derive_input(body: &str) -> syn::DeriveInput {
    let fields: Vec<String> = PARAMS
        .iter()
        .map(|(name, kind, symmetric)| {
            let ty = match kind {
                FieldKind::Scalar => "f64",
                FieldKind::Vector => "Vector3<f64>",
                FieldKind::Matrix => "Matrix3<f64>",
            };
            let attr = if *symmetric {
                "#[lagrangian(symmetric)] "
            } else {
                ""
            };
            format!("{attr}{name}: {ty}")
        })
        .collect();
    let src = format!(
        "#[lagrangian({body})] struct Model {{ {} }}",
        fields.join(", ")
    );
    syn::parse_str(&src).expect("the struct parses")
}

/// The parameters of the benchmark gyrostat: name, shape, symmetric.
const PARAMS: &[(&str, FieldKind, bool)] = &[
    ("inertia", FieldKind::Matrix, true),
    ("rotor", FieldKind::Vector, false),
    ("coupling", FieldKind::Matrix, false),
    ("com", FieldKind::Vector, false),
    ("mass", FieldKind::Scalar, false),
    ("g", FieldKind::Scalar, false),
];

/// [`PARAMS`] as a run-time model hands them over.
fn fields() -> Vec<Field> {
    PARAMS
        .iter()
        .map(|&(name, kind, symmetric)| {
            let mut f = Field::new(syn::Ident::new(name, Span::call_site()), kind);
            f.symmetric = symmetric.then(Span::call_site);
            f
        })
        .collect()
}

fn parts(body: &str) -> Result<routh_codegen::Model, syn::Error> {
    let tokens: TokenStream = body.parse().expect("the body lexes");
    analyse_parts(&fields(), &Body::text(tokens))
}

const GYROSTAT: &str = "kinetic = 0.5 * omega.dot(inertia * omega), \
    linear = (rotor + coupling * gamma).dot(omega), \
    potential = mass * g * com.dot(gamma)";

#[test]
fn the_derive_and_the_front_end_make_the_same_model() {
    let a = analyse(&derive_input(GYROSTAT)).unwrap_or_else(|e| panic!("{e}"));
    let b = parts(GYROSTAT).unwrap_or_else(|e| panic!("{e}"));
    let infix = |m: &routh_codegen::Model| {
        let o = &m.outputs;
        let g = &m.lowered.sym.graph;
        let mut ids = vec![
            o.lagrangian,
            o.amended_potential,
            o.psi_dot_at_rest,
            o.routhian,
        ];
        ids.extend(o.d2r_dgamma2.iter().flatten());
        ids.extend(o.gyroscopic().flatten());
        ids.into_iter()
            .map(|id| routh_symbolic::to_infix(g, id))
            .collect::<Vec<_>>()
    };
    assert_eq!(infix(&a), infix(&b));
    let reads = |m: &routh_codegen::Model| {
        (m.lowered.sym.params.iter())
            .map(|p| (p.field.to_string(), p.access))
            .collect::<Vec<_>>()
    };
    assert_eq!(reads(&a), reads(&b));
    // The symmetric inertia is read from its upper triangle only: 6 reads, not 9.
    let inertia = reads(&b).iter().filter(|(f, _)| f == "inertia").count();
    assert_eq!(inertia, 6);
    assert_eq!(a.rank_one.is_some(), b.rank_one.is_some());
}

#[test]
fn both_ways_in_report_the_same_errors() {
    let bodies = [
        // An unknown name and a shape error: both reported.
        "kinetic = 0.5 * omega.dot(inertai * omega), potential = com * gamma",
        // No kinetic energy.
        "potential = mass * g * com.dot(gamma)",
        // A duplicated item and a kinetic energy of degree 3.
        "kinetic = omega.x * omega.y * omega.z, kinetic = omega.dot(omega)",
        // A malformed item among good ones.
        "kinetic = 0.5 * omega.dot(omega), potential = , let a = mass",
        // A `let` that shadows a parameter.
        "let mass = 2.0, kinetic = mass * omega.dot(omega)",
        // An empty body.
        "",
    ];
    for body in bodies {
        let messages = |r: Result<routh_codegen::Model, syn::Error>| -> Vec<String> {
            match r {
                Ok(_) => panic!("`{body}` was accepted"),
                Err(e) => e.into_iter().map(|e| e.to_string()).collect(),
            }
        };
        let from_struct = messages(analyse(&derive_input(body)));
        let from_parts = messages(parts(body));
        assert!(!from_struct.is_empty());
        assert_eq!(from_struct, from_parts, "body `{body}`");
    }
}
