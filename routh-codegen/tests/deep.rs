//! Deeply nested input is a compile error, not a stack overflow.

use quote::quote;

fn expand(src: String) -> String {
    let body: proc_macro2::TokenStream = src.parse().expect("tokens");
    let input = quote! {
        #[lagrangian(kinetic = 0.5 * omega.dot(omega), potential = #body)]
        struct M { mass: f64 }
    };
    routh_codegen::derive(input).to_string()
}

/// Expands a model whose potential is `src` and checks that the nesting is reported.
fn assert_too_deep(src: String) {
    let out = std::thread::Builder::new()
        .stack_size(64 << 20) // syn's own recursive descent needs room for the input
        .spawn(move || expand(src))
        .expect("thread")
        .join()
        .expect("no panic");
    assert!(
        out.contains("nested more than"),
        "{}",
        &out[..out.len().min(400)]
    );
}

#[test]
fn deep_parentheses_are_an_error() {
    assert_too_deep(format!("{}mass{}", "(".repeat(1000), ")".repeat(1000)));
}

#[test]
fn long_method_chains_are_an_error() {
    assert_too_deep(format!("mass{}", ".sin()".repeat(3000)));
}
