//! `#[derive(Lagrangian)]`: a shim over [`routh_codegen::derive_with`]. See the `routh` crate for
//! the DSL.

/// Derives `routh::Lagrangian` and `routh::Routhian` from a `#[lagrangian(...)]` attribute.
#[proc_macro_derive(Lagrangian, attributes(lagrangian))]
pub fn derive_lagrangian(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    // The generated methods are source text, lexed by the compiler in one call (see
    // `routh_codegen::expand_with`).
    let lex = |src: &str| src.parse::<proc_macro::TokenStream>().ok().map(Into::into);
    routh_codegen::derive_with(input.into(), &lex).into()
}
