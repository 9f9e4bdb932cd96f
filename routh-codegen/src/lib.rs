//! The code generator behind `#[derive(Lagrangian)]` (the proc-macro crate `routh-macros` is a
//! shim over [`derive()`]). Kept in a plain crate so that it can be unit-tested, fuzzed and
//! benchmarked.
//!
//! Pipeline: [`attr`] parses the struct and its `#[lagrangian(...)]` items, [`check`] applies the
//! semantic rules, [`lower`] turns the DSL's expressions into a `routh_symbolic::Graph`,
//! [`reduce`] derives the Routh reduction ([`system`]: A, G, C of (64)), [`emit`] writes the
//! impls ([`methods`]: one generated method each; [`order`]: the order of the statements;
//! [`layout`] names the outputs of the methods that return many at once, for both). Every stage records its
//! errors in a [`ctxt::Ctxt`] and carries on, so all mistakes of an attribute are reported at
//! once; on error the output is `compile_error!`s plus a stub impl, so no follow-on errors appear.
//!
//! [`analyse_parts`] (parameters and a body of items) is the one front end for model text: the
//! derive reaches it through [`analyse`] (the struct's fields and attributes), models read at run
//! time (`routh-runtime`) call it with their parameters and their lexed text.

pub mod attr;
pub mod check;
pub mod ctxt;
pub mod emit;
pub mod equations;
pub mod inertia;
pub mod latex;
pub mod layout;
pub mod lower;
pub mod methods;
pub mod nodes;
pub mod order;
pub mod reduce;
pub mod system;
pub mod tape;

pub use attr::{Body, Field, FieldKind};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// Expands `#[derive(Lagrangian)]`. Never panics: every mistake becomes a `compile_error!`.
pub fn derive(input: TokenStream) -> TokenStream {
    derive_with(input, &lex)
}

/// [`derive()`], with `lex` turning the generated methods' source text into tokens (see
/// [`expand_with`]).
pub fn derive_with(input: TokenStream, lex: &dyn Fn(&str) -> Option<TokenStream>) -> TokenStream {
    let di: syn::DeriveInput = match syn::parse2(input) {
        Ok(di) => di,
        Err(e) => return e.to_compile_error(),
    };
    match expand_with(&di, lex) {
        Ok(ts) => ts,
        Err(e) => fallback(&di, e),
    }
}

/// Lexes source text with `proc_macro2` (which, in a proc macro, lexes it twice: once unoptimised
/// in `proc_macro2` to validate it, once in the compiler).
fn lex(src: &str) -> Option<TokenStream> {
    src.parse().ok()
}

/// A model that passed every check, lowered and reduced.
pub struct Model {
    pub lowered: lower::Lowered,
    pub outputs: reduce::Outputs,
    /// The right sides of (8) and (13), for the vector fields.
    pub equations: equations::Equations,
    /// `J = J₀ + c v vᵀ`, when the kinetic energy has that form.
    pub rank_one: Option<inertia::RankOne>,
    /// The LaTeX symbols the fields were given (`#[lagrangian(latex = "I")]`): field name →
    /// symbol, for [`latex::latex_formulas`].
    pub latex_symbols: Vec<(String, String)>,
}

/// The front end for model text, shared by the derive and by models read at run time (as
/// `pest_meta` is for `pest`): parses the items of `body` ([`attr::parse_body`]), applies the
/// rules ([`check`]) with `params` as the model's parameters, lowers and reduces; all errors
/// combined, each spanned at the tokens of `body` (or a parameter's) it is about.
pub fn analyse_parts(params: &[Field], body: &Body) -> Result<Model, syn::Error> {
    let cx = ctxt::Ctxt::new();
    let items = attr::parse_body(&cx, body);
    analyse_parsed(cx, attr::Input::new(params, body, items))
}

/// [`analyse_parts`] for a struct: its fields are the parameters, its `#[lagrangian(...)]`
/// attributes the body. The struct's own rules (named fields, the fields' attributes) are
/// checked here; everything else is [`analyse_parts`]'s.
pub fn analyse(di: &syn::DeriveInput) -> Result<Model, syn::Error> {
    let cx = ctxt::Ctxt::new();
    let body = Body::of(di);
    // In the order of the errors: the body's items, then the fields, then the struct.
    let items = attr::parse_body(&cx, &body);
    let params = attr::fields(&cx, di);
    check::struct_has_named_fields(&cx, di);
    analyse_parsed(cx, attr::Input::new(&params, &body, items))
}

/// Checks, lowers and reduces parsed input, with the errors already in `cx`.
fn analyse_parsed(cx: ctxt::Ctxt, input: attr::Input) -> Result<Model, syn::Error> {
    let latex_symbols = (input.fields.iter())
        .filter_map(|f| Some((f.ident.to_string(), f.latex.clone()?)))
        .collect();
    check::check(&cx, &input);
    let lowered = lower::lower(&cx, &input);
    cx.check()?;
    let Some(mut lowered) = lowered else {
        return Err(syn::Error::new_spanned(
            input.anchor,
            "the Lagrangian could not be lowered",
        ));
    };
    // First, while the graph holds only the model (its walks are linear in the graph's size).
    let rank_one = inertia::rank_one(&mut lowered.sym, lowered.kinetic);
    let outputs = reduce::reduce(&mut lowered);
    let equations = equations::equations(&mut lowered.sym, &outputs);
    Ok(Model {
        lowered,
        outputs,
        equations,
        rank_one,
        latex_symbols,
    })
}

fn crate_path(m: &Model) -> TokenStream {
    match &m.lowered.krate {
        Some(p) => quote!(#p),
        None => quote!(::routh),
    }
}

/// The generated code for a valid input, or all its errors.
pub fn expand(di: &syn::DeriveInput) -> Result<TokenStream, syn::Error> {
    expand_with(di, &lex)
}

/// [`expand`], with `lex` turning source text into tokens. The methods are written as text (see
/// [`emit`]) and lexed in one call: `routh-macros` passes the compiler's lexer
/// (`proc_macro::TokenStream::from_str`), so that a user's debug build, which runs this crate
/// unoptimised, neither builds nor lexes their tokens one by one. The tokens get
/// `Span::call_site()`, like those `quote!` makes; what comes from the user's tokens (the
/// struct's name and generics, the crate path) is interpolated with its own spans.
pub fn expand_with(
    di: &syn::DeriveInput,
    lex: &dyn Fn(&str) -> Option<TokenStream>,
) -> Result<TokenStream, syn::Error> {
    let model = analyse(di)?;
    let krate = crate_path(&model);
    let e = emit::Emitter::new(&model.lowered.sym);
    let lex = |src: String| {
        lex(&src).ok_or_else(|| {
            syn::Error::new_spanned(
                &di.ident,
                "internal error in #[derive(Lagrangian)]: the generated code does not lex",
            )
        })
    };
    let split = model.rank_one.as_ref();
    let mut lag_text = e.lagrangian_methods(&model.outputs, &model.equations, split);
    let mut routh_text = e.routhian_methods(&model.outputs, &model.equations, split);
    let (sym, o) = (&model.lowered.sym, &model.outputs);
    methods::tapes(&mut routh_text, &mut lag_text, sym, o).map_err(|e| {
        syn::Error::new_spanned(
            &di.ident,
            format!("internal error in #[derive(Lagrangian)]: invalid tape ({e})"),
        )
    })?;
    // Only the aliases the text uses are declared (an unused one would be dead code). They are
    // looked for outside the statements `let __t… = …;` and the input reads `let __v…: __F64 =
    // …;`, which name no alias but `__F64` (in a literal such as `__F64::NAN`; every method's
    // signature names it too): most of the text is statements, and searching all of it for
    // every alias was a tenth of an unoptimised expansion.
    let mut skeleton = String::new();
    for text in [&lag_text, &routh_text] {
        for line in text.split('\n') {
            if !(line.starts_with("let __t") || line.starts_with("let __v")) {
                skeleton.push_str(line);
                skeleton.push('\n');
            }
        }
    }
    let used = |alias: &str| skeleton.contains(alias);
    let used_aliases: Vec<_> = emit::ALIASES.iter().filter(|(a, _)| used(a)).collect();
    let lag = lex(lag_text)?;
    let routh = lex(routh_text)?;
    let aliases = used_aliases.into_iter().map(|&(alias, item)| {
        let generic = matches!(item, "Vector3" | "Matrix3");
        let (alias, item) = (
            Ident::new(alias, Span::call_site()),
            Ident::new(item, Span::call_site()),
        );
        if generic {
            quote!(type #alias = #krate::__private::#item<#krate::__private::f64>;)
        } else {
            quote!(type #alias = #krate::__private::#item;)
        }
    });
    let sign = e.uses_sign().then(|| {
        let sign = Ident::new(emit::SIGN, Span::call_site());
        quote! {
            #[inline(always)]
            fn #sign(__x: __F64) -> __F64 {
                #krate::__private::sign(__x)
            }
        }
    });
    let ident = &di.ident;
    let (ig, tg, wc) = di.generics.split_for_impl();
    let graph = &model.lowered.sym.graph;
    let o = &model.outputs;
    let [f_l, f_ur, f_pd] = [o.lagrangian, o.amended_potential, o.psi_dot_at_rest]
        .map(|id| routh_symbolic::to_infix(graph, id));
    // The LaTeX is printed at run time, on the first call of `latex()`, from the struct's text
    // (`routh::__private::DerivedLatex`): printing it here was a fifth of the expansion. A text
    // that does not parse back (tokens only a macro expansion can hold, such as `$crate`) would
    // print nothing then, so its formulas are printed here instead.
    let source = latex_source(di);
    let latex_body = if syn::parse_str::<syn::DeriveInput>(&source).is_ok() {
        quote! {
            static __LATEX: #krate::__private::DerivedLatex =
                #krate::__private::DerivedLatex::new(#source);
            __LATEX.get()
        }
    } else {
        let t = latex::latex_formulas(&model, &model.latex_symbols);
        let [l, pd, r, ur, a, g, c] = [
            &t.lagrangian,
            &t.psi_dot,
            &t.routhian,
            &t.amended_potential,
            &t.a,
            &t.g,
            &t.c,
        ];
        quote! {
            #krate::__private::LatexFormulas {
                lagrangian: ::std::string::String::from(#l),
                psi_dot: ::std::string::String::from(#pd),
                routhian: ::std::string::String::from(#r),
                amended_potential: ::std::string::String::from(#ur),
                a: ::std::string::String::from(#a),
                g: ::std::string::String::from(#g),
                c: ::std::string::String::from(#c),
            }
        }
    };
    Ok(quote! {
        #[doc(hidden)]
        #[allow(non_upper_case_globals, unused_qualifications, clippy::all, clippy::pedantic, clippy::nursery)]
        const _: () = {
            #(#aliases)*
            #sign
            #[automatically_derived]
            impl #ig #krate::__private::Lagrangian for #ident #tg #wc {
                #lag
            }
            #[automatically_derived]
            impl #ig #krate::__private::Routhian for #ident #tg #wc {
                #routh
            }
            #[automatically_derived]
            impl #ig #krate::__private::DerivedFormulas for #ident #tg #wc {
                const LAGRANGIAN: &'static str = #f_l;
                const AMENDED_POTENTIAL: &'static str = #f_ur;
                const PSI_DOT_AT_REST: &'static str = #f_pd;
                fn latex(&self) -> #krate::__private::LatexFormulas {
                    #latex_body
                }
            }
        };
    })
}

/// The text `DerivedFormulas::latex` prints the formulas from at run time: the struct with
/// only its `#[lagrangian(...)]` attributes (on the struct and its fields), which is all that
/// [`analyse`] reads.
fn latex_source(di: &syn::DeriveInput) -> String {
    let ours = |attrs: &mut Vec<syn::Attribute>| attrs.retain(|a| a.path().is_ident("lagrangian"));
    let mut di = di.clone();
    ours(&mut di.attrs);
    if let syn::Data::Struct(s) = &mut di.data {
        for f in s.fields.iter_mut() {
            ours(&mut f.attrs);
        }
    }
    quote!(#di).to_string()
}

/// On error: the errors as `compile_error!`s plus stub impls of both traits, so that code using
/// the model does not pile follow-on errors on top (after thiserror's `fallback.rs`).
pub fn fallback(di: &syn::DeriveInput, err: syn::Error) -> TokenStream {
    let errors = err.to_compile_error();
    let ident = &di.ident;
    let (ig, tg, wc) = di.generics.split_for_impl();
    // The crate path may itself be wrong; the stub uses the default.
    let k = quote!(::routh);
    let v3 = quote!(#k::__private::Vector3<#k::__private::f64>);
    let m3 = quote!(#k::__private::Matrix3<#k::__private::f64>);
    let f = quote!(#k::__private::f64);
    let body = quote!({ ::core::unreachable!() });
    quote! {
        #errors
        #[doc(hidden)]
        #[allow(unused_variables, clippy::all)]
        const _: () = {
            #[automatically_derived]
            impl #ig #k::__private::Lagrangian for #ident #tg #wc {
                fn lagrangian(&self, _: &#v3, _: &#v3) -> #f #body
                fn dl_domega(&self, _: &#v3, _: &#v3) -> #v3 #body
                fn dl_dgamma(&self, _: &#v3, _: &#v3) -> #v3 #body
                fn d2l_domega2(&self, _: &#v3) -> #m3 #body
                fn d2l_domega_dgamma(&self, _: &#v3, _: &#v3) -> #m3 #body
            }
            #[automatically_derived]
            impl #ig #k::__private::Routhian for #ident #tg #wc {
                fn routhian(&self, _: &#v3, _: &#v3, _: #f) -> #f #body
                fn dr_domega(&self, _: &#v3, _: &#v3, _: #f) -> #v3 #body
                fn dr_dgamma(&self, _: &#v3, _: &#v3, _: #f) -> #v3 #body
                fn d2r_domega2(&self, _: &#v3, _: &#v3, _: #f) -> #m3 #body
                fn d2r_domega_dgamma(&self, _: &#v3, _: &#v3, _: #f) -> #m3 #body
                fn d2r_dgamma2(&self, _: &#v3, _: &#v3, _: #f) -> #m3 #body
            }
            #[automatically_derived]
            impl #ig #k::__private::DerivedFormulas for #ident #tg #wc {
                const LAGRANGIAN: &'static str = "";
                const AMENDED_POTENTIAL: &'static str = "";
                const PSI_DOT_AT_REST: &'static str = "";
            }
        };
    }
}
