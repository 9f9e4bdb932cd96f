//! Parsing of the derive input: the struct, its fields and the `#[lagrangian(...)]` items.
//!
//! Parsing never stops at the first mistake: the attribute body is split at its top-level commas
//! and every item is parsed on its own, so that every malformed item is reported.

use crate::ctxt::Ctxt;
use proc_macro2::{Span, TokenStream, TokenTree};
use syn::parse::{Parse, ParseStream};
use syn::spanned::Spanned;

/// The shape of a field the Lagrangian can use.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum FieldKind {
    /// `f64`
    Scalar,
    /// `Vector3<f64>`
    Vector,
    /// `Matrix3<f64>`
    Matrix,
}

/// A field of the model struct.
pub struct Field {
    pub ident: syn::Ident,
    /// `None` for fields whose type is not supported (an error has been recorded unless skipped).
    pub kind: Option<FieldKind>,
    pub ty: syn::Type,
    pub skip: bool,
    /// `#[lagrangian(symmetric)]` on a `Matrix3<f64>`: only the upper triangle is read and the
    /// matrix is taken to be symmetric (an inertia tensor), which the generated code exploits.
    pub symmetric: Option<proc_macro2::Span>,
    /// `#[lagrangian(latex = "I")]`: the field's symbol in the LaTeX of the derived formulas
    /// (default `\mathit{name}`).
    pub latex: Option<String>,
}

/// Which term of `L = kinetic + linear − potential` an item defines.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Term {
    Kinetic,
    Linear,
    Potential,
}

impl Term {
    pub fn name(self) -> &'static str {
        match self {
            Term::Kinetic => "kinetic",
            Term::Linear => "linear",
            Term::Potential => "potential",
        }
    }
}

/// One item of the attribute body.
pub enum Item {
    /// `let NAME = EXPR`
    Let { name: syn::Ident, expr: syn::Expr },
    /// `kinetic = EXPR`, `linear = EXPR`, `potential = EXPR`
    Term {
        term: Term,
        key: syn::Ident,
        expr: syn::Expr,
    },
    /// `crate = "path"`
    Crate { key: Span, path: syn::Path },
    /// An item that did not parse (already reported); `name` if it was a `let`, so that its uses
    /// stay silent.
    Failed { name: Option<syn::Ident> },
}

/// The parsed derive input.
pub struct Input {
    pub ident: syn::Ident,
    pub generics: syn::Generics,
    pub fields: Vec<Field>,
    pub items: Vec<Item>,
    /// Whether the struct carries at least one `#[lagrangian(...)]`.
    pub has_attr: bool,
    /// The first `#[lagrangian(...)]` attribute, where errors about a missing item point.
    pub first_attr: Option<syn::Attribute>,
    /// Whether some part of an attribute did not parse (already reported): rules about missing
    /// items stay silent then, since the missing item may be the one that failed.
    pub incomplete: bool,
}

/// Parses the derive input, recording every error in `cx`.
pub fn parse_input(cx: &Ctxt, input: &syn::DeriveInput) -> Input {
    let mut items = Vec::new();
    let mut has_attr = false;
    let mut first_attr = None;
    let mut incomplete = false;
    for attr in input
        .attrs
        .iter()
        .filter(|a| a.path().is_ident("lagrangian"))
    {
        has_attr = true;
        if first_attr.is_none() {
            first_attr = Some(attr.clone());
        }
        match &attr.meta {
            syn::Meta::List(list) => {
                let span = list.delimiter.span().join();
                incomplete |= !parse_items(cx, list.tokens.clone(), span, &mut items);
            }
            other => {
                incomplete = true;
                cx.error_spanned_by(
                    other,
                    "expected `#[lagrangian(kinetic = ..., linear = ..., potential = ...)]`",
                );
            }
        }
    }
    let fields = match &input.data {
        syn::Data::Struct(s) => match &s.fields {
            syn::Fields::Named(named) => named
                .named
                .iter()
                .filter_map(|f| parse_field(cx, f))
                .collect(),
            syn::Fields::Unnamed(_) | syn::Fields::Unit => {
                // Reported by `check::struct_has_named_fields`.
                Vec::new()
            }
        },
        _ => Vec::new(),
    };
    Input {
        ident: input.ident.clone(),
        generics: input.generics.clone(),
        fields,
        items,
        has_attr,
        first_attr,
        incomplete,
    }
}

fn parse_field(cx: &Ctxt, f: &syn::Field) -> Option<Field> {
    let ident = f.ident.clone()?;
    let mut skip = false;
    let mut symmetric = None;
    let mut latex = None;
    for attr in f.attrs.iter().filter(|a| a.path().is_ident("lagrangian")) {
        let tokens: Vec<TokenTree> = match &attr.meta {
            syn::Meta::List(list) => list.tokens.clone().into_iter().collect(),
            _ => Vec::new(),
        };
        match tokens.as_slice() {
            [TokenTree::Ident(i)] if i == "skip" => skip = true,
            [TokenTree::Ident(i)] if i == "symmetric" => symmetric = Some(i.span()),
            [TokenTree::Ident(i), TokenTree::Punct(p), TokenTree::Literal(l)]
                if i == "latex" && p.as_char() == '=' =>
            {
                match syn::parse_str::<syn::LitStr>(&l.to_string()) {
                    Ok(s) if !s.value().trim().is_empty() => latex = Some(s.value()),
                    _ => cx.error_spanned_by(
                        attr,
                        "expected a non-empty string: `#[lagrangian(latex = \"I\")]`",
                    ),
                }
            }
            _ => cx.error_spanned_by(
                attr,
                "expected `#[lagrangian(skip)]`, `#[lagrangian(symmetric)]` or \
                 `#[lagrangian(latex = \"…\")]` on a field",
            ),
        }
    }
    Some(Field {
        ident,
        kind: field_kind(&f.ty),
        ty: f.ty.clone(),
        skip,
        symmetric,
        latex,
    })
}

/// `f64`, `Vector3<f64>` or `Matrix3<f64>` under any path spelling.
fn field_kind(ty: &syn::Type) -> Option<FieldKind> {
    let syn::Type::Path(tp) = ty else { return None };
    if tp.qself.is_some() {
        return None;
    }
    let seg = tp.path.segments.last()?;
    let is_f64 = |t: &syn::Type| matches!(t, syn::Type::Path(p) if p.qself.is_none() && p.path.segments.last().is_some_and(|s| s.ident == "f64" && s.arguments.is_none()));
    let single_f64 = match &seg.arguments {
        syn::PathArguments::AngleBracketed(a) if a.args.len() == 1 => {
            matches!(a.args.first(), Some(syn::GenericArgument::Type(t)) if is_f64(t))
        }
        _ => false,
    };
    match seg.ident.to_string().as_str() {
        "f64" if seg.arguments.is_none() => Some(FieldKind::Scalar),
        "Vector3" if single_f64 => Some(FieldKind::Vector),
        "Matrix3" if single_f64 => Some(FieldKind::Matrix),
        _ => None,
    }
}

/// Splits `tokens` at top-level commas.
fn split_commas(tokens: TokenStream) -> Vec<TokenStream> {
    let mut out = vec![];
    let mut cur = vec![];
    for tt in tokens {
        match &tt {
            TokenTree::Punct(p) if p.as_char() == ',' => out.push(std::mem::take(&mut cur)),
            _ => cur.push(tt),
        }
    }
    out.push(cur);
    out.into_iter()
        .filter(|c| !c.is_empty())
        .map(|c| c.into_iter().collect())
        .collect()
}

/// Parses every item; returns `false` if any failed (each failure is reported).
fn parse_items(cx: &Ctxt, tokens: TokenStream, span: Span, items: &mut Vec<Item>) -> bool {
    let chunks = split_commas(tokens);
    if chunks.is_empty() {
        cx.error_at(
            span,
            "empty `#[lagrangian()]`: at least `kinetic = EXPR` is required",
        );
        return false;
    }
    let mut ok = true;
    for chunk in chunks {
        // Parsed inside a group spanning the item's last token, so that "expected an
        // expression" at the end of an item points at the item, not at the derive.
        let end = chunk.clone().into_iter().last().map_or(span, |t| t.span());
        let mut group = proc_macro2::Group::new(proc_macro2::Delimiter::Parenthesis, chunk.clone());
        group.set_span(end);
        let parser = |input: ParseStream| {
            let content;
            syn::parenthesized!(content in input);
            let item: Item = content.parse()?;
            if !content.is_empty() {
                return Err(content
                    .error("unexpected tokens after the item: items are separated by commas"));
            }
            Ok(item)
        };
        match syn::parse::Parser::parse2(parser, TokenTree::Group(group).into()) {
            Ok(item) => items.push(item),
            Err(e) => {
                ok = false;
                cx.syn_error(e);
                items.push(Item::Failed {
                    name: let_name(&chunk),
                });
            }
        }
    }
    ok
}

/// The name of a `let NAME ...` item, if the tokens start so.
fn let_name(chunk: &TokenStream) -> Option<syn::Ident> {
    let mut it = chunk.clone().into_iter();
    match (it.next(), it.next()) {
        (Some(TokenTree::Ident(l)), Some(TokenTree::Ident(name))) if l == "let" => Some(name),
        _ => None,
    }
}

impl Parse for Item {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        if input.peek(syn::Token![let]) {
            input.parse::<syn::Token![let]>()?;
            let name: syn::Ident = input.parse()?;
            input.parse::<syn::Token![=]>()?;
            let expr: syn::Expr = input.parse()?;
            return Ok(Item::Let { name, expr });
        }
        if input.peek(syn::Token![crate]) {
            let key = input.parse::<syn::Token![crate]>()?.span;
            input.parse::<syn::Token![=]>()?;
            let lit: syn::LitStr = input.parse()?;
            let path = lit.parse_with(syn::Path::parse_mod_style).map_err(|_| {
                syn::Error::new(
                    lit.span(),
                    format!("`crate = \"{}\"` is not a path", lit.value()),
                )
            })?;
            return Ok(Item::Crate { key, path });
        }
        let key: syn::Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected an item: `kinetic = EXPR`, `linear = EXPR`, `potential = EXPR` or `let NAME = EXPR`",
            )
        })?;
        let term = match key.to_string().as_str() {
            "kinetic" => Term::Kinetic,
            "linear" => Term::Linear,
            "potential" => Term::Potential,
            other => {
                let items =
                    "`kinetic = EXPR`, `linear = EXPR`, `potential = EXPR` or `let NAME = EXPR`";
                let close = ["kinetic", "linear", "potential", "let"]
                    .into_iter()
                    .map(|k| (edit_distance(other, k), k))
                    .min()
                    .filter(|&(d, k)| d <= 2 && d < k.len());
                return Err(syn::Error::new(
                    key.span(),
                    match close {
                        Some((_, k)) => format!(
                            "unknown item `{other}`: did you mean `{k}`? (an item is {items})"
                        ),
                        None => format!("unknown item `{other}`: expected {items}"),
                    },
                ));
            }
        };
        let eq: Option<syn::Token![=]> = input.parse()?;
        if eq.is_none() {
            return Err(syn::Error::new(
                key.span(),
                format!("expected `{} = EXPR`", term.name()),
            ));
        }
        let expr: syn::Expr = input.parse()?;
        let _ = expr.span();
        Ok(Item::Term { term, key, expr })
    }
}

/// The Levenshtein distance between `a` and `b` (in characters): for a did-you-mean.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
