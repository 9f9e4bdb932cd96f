//! `#[derive(Lagrangian)]`: a shim over [`routh_codegen::derive`]. See the `routh` crate for the
//! DSL.

/// Derives `routh::Lagrangian` and `routh::Routhian` from a `#[lagrangian(...)]` attribute.
#[proc_macro_derive(Lagrangian, attributes(lagrangian))]
pub fn derive_lagrangian(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    routh_codegen::derive(input.into()).into()
}
