//! Semantic rules on the parsed input, one per function, each with the reason it exists
//! (after serde_derive's `internals/check.rs`). Every rule records its errors and returns, so
//! all of them run on every input.

use crate::attr::{Input, Item, Term};
use crate::ctxt::Ctxt;
use quote::ToTokens;
use std::collections::HashMap;

/// Names the DSL gives a meaning of its own.
pub const RESERVED: &[&str] = &["omega", "gamma", "diag", "skew", "grad"];

/// Runs every rule.
/// The rules about the struct itself ([`struct_has_named_fields`]) are the derive's own and run
/// before these.
pub fn check(cx: &Ctxt, input: &Input) {
    has_attribute(cx, input);
    fields_have_supported_types(cx, input);
    fields_do_not_shadow_variables(cx, input);
    symmetric_only_on_matrices(cx, input);
    items_are_unique(cx, input);
    kinetic_is_present(cx, input);
    lets_are_unique_and_do_not_shadow(cx, input);
}

/// The Lagrangian reads the model's parameters from named fields (`self.mass`), so tuple
/// structs, unit structs, enums and unions cannot be models.
pub fn struct_has_named_fields(cx: &Ctxt, derive: &syn::DeriveInput) {
    match &derive.data {
        syn::Data::Struct(s) => match &s.fields {
            syn::Fields::Named(_) => {}
            syn::Fields::Unnamed(f) => cx.error_spanned_by(
                f,
                "`#[derive(Lagrangian)]` needs a struct with named fields (its parameters are referred to by name)",
            ),
            syn::Fields::Unit => cx.error_spanned_by(
                &derive.ident,
                "`#[derive(Lagrangian)]` needs a struct with named fields, not a unit struct",
            ),
        },
        syn::Data::Enum(e) => cx.error_spanned_by(
            e.enum_token,
            "`#[derive(Lagrangian)]` only applies to structs with named fields",
        ),
        syn::Data::Union(u) => cx.error_spanned_by(
            u.union_token,
            "`#[derive(Lagrangian)]` only applies to structs with named fields",
        ),
    }
}

/// Without the attribute there is no Lagrangian to differentiate; say what to write.
fn has_attribute(cx: &Ctxt, input: &Input) {
    if !input.has_attr {
        cx.error_spanned_by(
            input.anchor,
            "missing `#[lagrangian(kinetic = ..., linear = ..., potential = ...)]`",
        );
    }
}

/// Generated code reads fields as `f64`, `Vector3<f64>` or `Matrix3<f64>`; anything else would
/// fail to compile in generated code where the user cannot see why.
fn fields_have_supported_types(cx: &Ctxt, input: &Input) {
    for f in input.fields.iter().filter(|f| f.kind.is_none() && !f.skip) {
        cx.error_spanned_by(
            f.ty.as_ref().map_or_else(|| f.ident.to_token_stream(), |t| t.to_token_stream()),
            format!(
                "field `{}` has a type the Lagrangian cannot use: expected `f64`, `Vector3<f64>` or `Matrix3<f64>`; mark it `#[lagrangian(skip)]` if the Lagrangian does not need it",
                f.ident
            ),
        );
    }
}

/// `omega`, `gamma` and the DSL's functions have fixed meanings; a field of the same name would
/// be silently shadowed.
fn fields_do_not_shadow_variables(cx: &Ctxt, input: &Input) {
    for f in input.fields.iter().filter(|f| !f.skip) {
        let name = f.ident.to_string();
        if RESERVED.contains(&name.as_str()) {
            cx.error_spanned_by(
                &f.ident,
                format!("field `{name}` clashes with the DSL's `{name}`; rename it or mark it `#[lagrangian(skip)]`"),
            );
        }
    }
}

/// Symmetry is a property of a 3×3 matrix; on anything else the attribute means nothing.
fn symmetric_only_on_matrices(cx: &Ctxt, input: &Input) {
    for f in input.fields {
        if let Some(span) = f.symmetric {
            if f.kind != Some(crate::attr::FieldKind::Matrix) || f.skip {
                cx.error_at(
                    span,
                    format!("`symmetric` applies to a used field of type `Matrix3<f64>`; `{}` is not one", f.ident),
                );
            }
        }
    }
}

/// Each term of L and the crate path may be given once; a second one is almost surely a typo.
fn items_are_unique(cx: &Ctxt, input: &Input) {
    let mut seen: HashMap<&'static str, ()> = HashMap::new();
    for item in &input.items {
        let (key, span) = match item {
            Item::Term { term, key, .. } => (term.name(), key.span()),
            Item::Crate { key, .. } => ("crate", *key),
            Item::Let { .. } | Item::Failed { .. } => continue,
        };
        if seen.insert(key, ()).is_some() {
            cx.error_at(span, format!("duplicate `{key}` item"));
        }
    }
}

/// A body without kinetic energy has no dynamics: J(γ) = 0 cannot be inverted.
fn kinetic_is_present(cx: &Ctxt, input: &Input) {
    if input.has_attr
        && !input.incomplete
        && !input.items.iter().any(|i| {
            matches!(
                i,
                Item::Term {
                    term: Term::Kinetic,
                    ..
                }
            )
        })
    {
        // Point at the attribute that lacks the item, not at the struct.
        let msg = "missing `kinetic = EXPR` in `#[lagrangian(...)]`";
        cx.error_spanned_by(input.anchor, msg);
    }
}

/// A `let` that rebinds a field, `omega`, `gamma` or an earlier `let` makes the formulas read
/// differently from what they compute.
fn lets_are_unique_and_do_not_shadow(cx: &Ctxt, input: &Input) {
    let mut lets: Vec<String> = vec![];
    for item in &input.items {
        let Item::Let { name, .. } = item else {
            continue;
        };
        let s = name.to_string();
        if RESERVED.contains(&s.as_str()) {
            cx.error_spanned_by(name, format!("`let {s}` would shadow the DSL's `{s}`"));
        } else if input.fields.iter().any(|f| f.ident == s) {
            cx.error_spanned_by(name, format!("`let {s}` would shadow the field `{s}`"));
        } else if lets.contains(&s) {
            cx.error_spanned_by(
                name,
                format!("`{s}` is already defined by an earlier `let`"),
            );
        }
        lets.push(s);
    }
}

/// Routh reduction needs `L = ½ωᵀJ(γ)ω + a(γ)·ω − U(γ)` (section 1, (35)): the kinetic term must
/// be a quadratic form in ω, the linear term linear in ω, and the potential free of ω, otherwise
/// ψ̇ of (12) is not the closed form (38) and the reduction the derive emits would be wrong.
pub fn term_degree(
    cx: &Ctxt,
    g: &routh_symbolic::Graph,
    name: &str,
    id: routh_symbolic::Id,
    expr: &syn::Expr,
    omega: &[routh_symbolic::Var; 3],
) {
    use routh_symbolic::Degree;
    let want = match name {
        "kinetic" => 2,
        "linear" => 1,
        _ => 0,
    };
    let d = routh_symbolic::degree(g, id, omega);
    let zero = g.is_const(id, 0.0);
    if name == "kinetic" && zero {
        cx.error_spanned_by(
            expr,
            "`kinetic` is identically zero: a rigid body needs kinetic energy",
        );
        return;
    }
    if d == Degree::Homogeneous(want) || (zero && want != 2) {
        return;
    }
    let found = match d {
        Degree::Homogeneous(0) => "it does not contain `omega`".to_string(),
        Degree::Homogeneous(k) => format!("it has degree {k} in `omega`"),
        Degree::Mixed => "it mixes terms of different degrees in `omega`".to_string(),
        Degree::NotPolynomial => "it is not a polynomial in `omega`".to_string(),
    };
    let msg = match name {
        "kinetic" => format!("`kinetic` must be a homogeneous quadratic form in `omega` (½ ωᵀJ(γ)ω), but {found}"),
        "linear" if d == Degree::Homogeneous(0) => format!("`linear` must be homogeneous linear in `omega` (a(γ)·ω), but {found}; a term without `omega` belongs in `potential` (with the opposite sign)"),
        "linear" => format!("`linear` must be homogeneous linear in `omega` (a(γ)·ω), but {found}"),
        _ => "`potential` must not depend on `omega`; velocity-dependent terms belong in `kinetic` or `linear`".to_string(),
    };
    cx.error_spanned_by(expr, msg);
}
