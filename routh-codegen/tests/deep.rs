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

#[test]
fn deep_parentheses_are_an_error() {
    let src = format!("{}mass{}", "(".repeat(1000), ")".repeat(1000));
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
fn long_method_chains_are_an_error() {
    let src = format!("mass{}", ".sin()".repeat(3000));
    let out = std::thread::Builder::new()
        .stack_size(64 << 20)
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
