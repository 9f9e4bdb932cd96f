//! The examples declare their bodies in their own files (an example is one file a user can copy),
//! while `tests/examples_facts.rs` checks the facts they print through the same declarations in
//! the `derived-models` crate. This test keeps the two in step: each example's model (its derive,
//! its `#[lagrangian]` attribute and its fields) and every function it shares with
//! derived-models are token for token the same, doc comments and visibility aside.

use std::collections::BTreeMap;
use std::path::Path;

use quote::ToTokens;
use syn::{Attribute, Item, ItemStruct, Visibility};

/// The tokens of a struct without its doc comments.
fn struct_tokens(mut s: ItemStruct) -> String {
    strip_docs(&mut s.attrs);
    for f in s.fields.iter_mut() {
        strip_docs(&mut f.attrs);
    }
    s.to_token_stream().to_string()
}

fn strip_docs(attrs: &mut Vec<Attribute>) {
    attrs.retain(|a| !a.path().is_ident("doc"));
}

fn parse_file(rel: &str) -> syn::File {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{rel}: {e}"));
    syn::parse_file(&text).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn find_struct(file: &syn::File, name: &str) -> Option<ItemStruct> {
    file.items.iter().find_map(|i| match i {
        Item::Struct(s) if s.ident == name => Some(s.clone()),
        _ => None,
    })
}

/// The functions of `file` (free, and in inherent `impl`s, as `Type::name`), each as the tokens of
/// its signature and body.
fn functions(file: &syn::File) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for item in &file.items {
        match item {
            Item::Fn(f) => {
                let (sig, block) = (&f.sig, &f.block);
                out.insert(
                    f.sig.ident.to_string(),
                    quote::quote!(#sig #block).to_string(),
                );
            }
            Item::Const(c) => {
                let mut c = c.clone();
                strip_docs(&mut c.attrs);
                c.vis = Visibility::Inherited;
                out.insert(c.ident.to_string(), c.to_token_stream().to_string());
            }
            Item::Impl(i) if i.trait_.is_none() => {
                let ty = i.self_ty.to_token_stream().to_string();
                for it in &i.items {
                    if let syn::ImplItem::Fn(f) = it {
                        let (sig, block) = (&f.sig, &f.block);
                        out.insert(
                            format!("{ty}::{}", f.sig.ident),
                            quote::quote!(#sig #block).to_string(),
                        );
                    }
                }
            }
            _ => {}
        }
    }
    out
}

/// Asserts that `example` declares `model` as derived-models does (`derived`, or the struct
/// parsed from `derived_src`), and that each of `shared` is the same in both files.
fn check(example: &str, derived: &syn::File, model: ItemStruct, shared: &[&str]) {
    let ex = parse_file(example);
    let name = model.ident.to_string();
    let mine =
        find_struct(&ex, &name).unwrap_or_else(|| panic!("{example} declares no struct {name}"));
    assert_eq!(
        struct_tokens(mine),
        struct_tokens(model),
        "{example}: the declaration of {name} differs from derived-models'"
    );
    let (fe, fd) = (functions(&ex), functions(derived));
    for f in shared {
        let a = fe
            .get(*f)
            .unwrap_or_else(|| panic!("{example} has no function {f}"));
        let b = fd
            .get(*f)
            .unwrap_or_else(|| panic!("derived-models has no function {f} (for {example})"));
        assert_eq!(a, b, "{example}: {f} differs from derived-models'");
    }
}

#[test]
fn gyrostat_example_declares_the_model_that_examples_facts_checks() {
    let derived = parse_file("test-models/derived/src/gyrostat.rs");
    let model: ItemStruct =
        syn::parse_str(derived_models::GYROSTAT_SRC).expect("the bench model parses");
    check(
        "examples/gyrostat.rs",
        &derived,
        model,
        &[
            "Gyrostat::kelvin",
            "Gyrostat::coupled",
            "Gyrostat::mgl",
            "Gyrostat::rest_rotor_threshold",
            "Gyrostat::a_dot_gamma",
            "Gyrostat::amended_potential_closed_form",
            "Gyrostat::amended_potential_formula",
            "SUB",
            "linear_form",
            "quadratic_form",
        ],
    );
}

#[test]
fn ellipsoid_example_declares_the_model_that_examples_facts_checks() {
    let derived = parse_file("test-models/derived/src/ellipsoid.rs");
    let model = find_struct(&derived, "Ellipsoid").expect("derived-models declares Ellipsoid");
    check(
        "examples/ellipsoid_on_plane.rs",
        &derived,
        model,
        &[
            "uniform_inertia",
            "Ellipsoid::spheroid",
            "Ellipsoid::triaxial",
            "Ellipsoid::height",
            "Ellipsoid::ell",
            "Ellipsoid::pole_hessian",
            "Ellipsoid::spheroid_threshold",
            "Ellipsoid::spin_threshold",
        ],
    );
}

#[test]
fn fluid_example_declares_the_model_that_examples_facts_checks() {
    let derived = parse_file("test-models/derived/src/fluid_body.rs");
    let model = find_struct(&derived, "FluidBody").expect("derived-models declares FluidBody");
    let shared = [
        "Kirchhoff::body_of_revolution",
        "Kirchhoff::chiral",
        "Kirchhoff::parameters",
        "Kirchhoff::energy",
        "Kirchhoff::axial_threshold",
        "perturbed_axial",
    ];
    check("examples/body_in_fluid.rs", &derived, model, &shared);
    let kirchhoff = find_struct(&derived, "Kirchhoff").expect("derived-models declares Kirchhoff");
    check("examples/body_in_fluid.rs", &derived, kirchhoff, &[]);
}

#[test]
fn periodic_example_declares_the_model_that_examples_facts_checks() {
    let derived = parse_file("test-models/derived/src/heavy_body.rs");
    let model = find_struct(&derived, "HeavyBody").expect("derived-models declares HeavyBody");
    check(
        "examples/periodic.rs",
        &derived,
        model,
        &[
            "HeavyBody::on_axis",
            "hanging",
            "elliptic_k",
            "stability_intervals",
        ],
    );
}

#[test]
fn examples_do_not_use_derived_models() {
    // heavy_top.rs is left to its own rewrite; op_counts.rs measures the bench models' expansion
    // and takes their source text from derived-models on purpose.
    for name in [
        "gyrostat",
        "ellipsoid_on_plane",
        "body_in_fluid",
        "certify",
        "periodic",
    ] {
        let rel = format!("examples/{name}.rs");
        let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(&rel))
            .unwrap_or_else(|e| panic!("{rel}: {e}"));
        assert!(
            !text.contains("derived_models"),
            "{rel} uses derived_models"
        );
    }
    let common = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/common/mod.rs"),
    )
    .expect("examples/common/mod.rs");
    assert!(!common.contains("derived_models"));
}
