//! Expansion time of `#[derive(Lagrangian)]` per model: `routh_codegen::expand` (parse the
//! attribute, check, lower to the symbolic DAG, differentiate, reduce, CSE, emit tokens) on a
//! `syn::DeriveInput` parsed once beforehand.
//!
//! - `M1_gyrostat`, `M2_ellipsoid`: the models of `benches/bundle.rs` (`derived-models`);
//! - `lagrange_top`: `examples/expanded/lagrange_top.rs`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use quote::ToTokens;

const LAGRANGE_TOP_SRC: &str = include_str!("../examples/expanded/lagrange_top.rs");

/// The first struct of `src`, as the derive would receive it.
fn derive_input(src: &str) -> syn::DeriveInput {
    let file: syn::File = syn::parse_str(src).expect("model source parses");
    let item = file
        .items
        .into_iter()
        .find_map(|item| match item {
            syn::Item::Struct(s) => Some(s),
            _ => None,
        })
        .expect("a struct");
    syn::parse2(item.into_token_stream()).expect("struct is a DeriveInput")
}

fn bench_expand(c: &mut Criterion) {
    let models = [
        ("M1_gyrostat", derive_input(derived_models::GYROSTAT_SRC)),
        (
            "M2_ellipsoid",
            derive_input(derived_models::DIAGONAL_ELLIPSOID_SRC),
        ),
        ("lagrange_top", derive_input(LAGRANGE_TOP_SRC)),
    ];
    let mut group = c.benchmark_group("expand");
    for (name, di) in &models {
        let tokens = routh_codegen::expand(di).expect("model expands");
        println!(
            "{name}: {} bytes of generated tokens",
            tokens.to_string().len()
        );
        group.bench_function(*name, |b| {
            b.iter(|| routh_codegen::expand(black_box(di)).expect("model expands"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_expand);
criterion_main!(benches);
