//! Parsing of a model: its parameters (the struct's fields) and the items of its body (the
//! `#[lagrangian(...)]` attributes, or a model's text read at run time).
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

/// A parameter of a model: a field of the struct (the derive) or a named parameter of a model
/// read at run time. Both front ends hand their parameters to [`crate::analyse_parts`] in this
/// form.
pub struct Field {
    pub ident: syn::Ident,
    /// `None` for fields whose type is not supported (an error has been recorded unless skipped).
    pub kind: Option<FieldKind>,
    /// The field's type as written (the derive), where an unsupported type is reported; `None`
    /// for a run-time parameter, whose shape is its value's.
    pub ty: Option<syn::Type>,
    pub skip: bool,
    /// `#[lagrangian(symmetric)]` on a `Matrix3<f64>`: only the upper triangle is read and the
    /// matrix is taken to be symmetric (an inertia tensor), which the generated code exploits.
    pub symmetric: Option<proc_macro2::Span>,
    /// `#[lagrangian(latex = "I")]`: the field's symbol in the LaTeX of the derived formulas
    /// (default `\mathit{name}`).
    pub latex: Option<String>,
}

impl Field {
    /// A used parameter of the given shape, not symmetric, with the default LaTeX symbol.
    pub fn new(ident: syn::Ident, kind: FieldKind) -> Field {
        Field {
            ident,
            kind: Some(kind),
            ty: None,
            skip: false,
            symmetric: None,
            latex: None,
        }
    }
}

/// The body of a model: the items of the struct's `#[lagrangian(...)]` attributes (the derive)
/// or a model's text (run time), as tokens whose spans point into the user's source.
pub struct Body {
    /// Each attribute in order.
    pub parts: Vec<BodyPart>,
    /// What errors about the body as a whole point at (no attribute at all; a missing
    /// `kinetic`): the first attribute, or the struct's name when it has none. Empty for a
    /// model's text (the error is then at its start).
    pub anchor: TokenStream,
}

/// One `#[lagrangian ...]` attribute of a [`Body`].
pub enum BodyPart {
    /// `#[lagrangian(ITEMS)]`: the items' tokens and the span of the delimiters (where an empty
    /// list is reported).
    List(TokenStream, Span),
    /// An attribute that is not a list (`#[lagrangian]`, `#[lagrangian = ...]`): its tokens, where
    /// the error points.
    NotAList(TokenStream),
}

impl Body {
    /// A model's text, lexed: one list of items, errors about the whole at the text's start.
    pub fn text(tokens: TokenStream) -> Body {
        Body {
            parts: vec![BodyPart::List(tokens, Span::call_site())],
            anchor: TokenStream::new(),
        }
    }

    /// The `#[lagrangian(...)]` attributes of a struct (not those of its fields).
    pub fn of(input: &syn::DeriveInput) -> Body {
        use quote::ToTokens;
        let attrs: Vec<_> = (input.attrs.iter())
            .filter(|a| a.path().is_ident("lagrangian"))
            .collect();
        let parts = (attrs.iter())
            .map(|attr| match &attr.meta {
                syn::Meta::List(list) => {
                    BodyPart::List(list.tokens.clone(), list.delimiter.span().join())
                }
                other => BodyPart::NotAList(other.to_token_stream()),
            })
            .collect();
        let anchor = match attrs.first() {
            Some(attr) => attr.to_token_stream(),
            None => input.ident.to_token_stream(),
        };
        Body { parts, anchor }
    }
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

/// A model's parameters with the parsed items of its body: what the checks and the lowering
/// read.
pub struct Input<'a> {
    pub fields: &'a [Field],
    pub items: Vec<Item>,
    /// Whether the body has at least one `#[lagrangian ...]` (a model's text always has).
    pub has_attr: bool,
    /// Where errors about the body as a whole point ([`Body::anchor`]).
    pub anchor: &'a TokenStream,
    /// Whether some part of an attribute did not parse (already reported): rules about missing
    /// items stay silent then, since the missing item may be the one that failed.
    pub incomplete: bool,
}

/// The parsed items of a [`Body`].
pub struct Items {
    pub items: Vec<Item>,
    /// Whether some part of the body did not parse (already reported).
    pub incomplete: bool,
}

/// Parses every item of `body`, recording every error in `cx`.
pub fn parse_body(cx: &Ctxt, body: &Body) -> Items {
    let mut items = Vec::new();
    let mut incomplete = false;
    for part in &body.parts {
        match part {
            BodyPart::List(tokens, span) => {
                incomplete |= !parse_items(cx, tokens.clone(), *span, &mut items);
            }
            BodyPart::NotAList(tokens) => {
                incomplete = true;
                cx.error_spanned_by(
                    tokens,
                    "expected `#[lagrangian(kinetic = ..., linear = ..., potential = ...)]`",
                );
            }
        }
    }
    Items { items, incomplete }
}

impl<'a> Input<'a> {
    /// The parameters `fields` with the items parsed from `body`.
    pub fn new(fields: &'a [Field], body: &'a Body, items: Items) -> Input<'a> {
        Input {
            fields,
            items: items.items,
            has_attr: !body.parts.is_empty(),
            anchor: &body.anchor,
            incomplete: items.incomplete,
        }
    }
}

/// The named fields of the struct, recording errors in their `#[lagrangian(...)]` attributes.
/// Other shapes of input have none (reported by [`crate::check::struct_has_named_fields`]).
pub fn fields(cx: &Ctxt, input: &syn::DeriveInput) -> Vec<Field> {
    match &input.data {
        syn::Data::Struct(syn::DataStruct {
            fields: syn::Fields::Named(named),
            ..
        }) => named
            .named
            .iter()
            .filter_map(|f| parse_field(cx, f))
            .collect(),
        _ => Vec::new(),
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
        ty: Some(f.ty.clone()),
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
