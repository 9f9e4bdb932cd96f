//! The LaTeX of a `#[derive(Lagrangian)]` model, printed when it is first asked for: the derive
//! emits the struct's text (its fields and `#[lagrangian(...)]` attributes) instead of the
//! formulas, as printing them at expansion was a fifth of what the derive adds to a user's
//! build, for formulas most programs never ask for.

use std::sync::OnceLock;

use routh_core::LatexFormulas;

/// What the derive's `DerivedFormulas::latex` reads: the struct's text, analysed and printed
/// on the first call ([`DerivedLatex::get`]), by the same front end, reduction and printer as
/// at expansion (`routh_codegen::analyse`, `routh_codegen::latex::latex_formulas`), so the
/// formulas are those the derive would have printed. Not API: the derive's generated code
/// names it through `routh::__private`.
#[doc(hidden)]
pub struct DerivedLatex {
    source: &'static str,
    text: OnceLock<LatexFormulas>,
}

impl DerivedLatex {
    /// The formulas of the struct `source` (a `syn::DeriveInput` as text), not printed yet.
    pub const fn new(source: &'static str) -> Self {
        DerivedLatex {
            source,
            text: OnceLock::new(),
        }
    }

    /// The formulas, printed on the first call. The derive checked the text, so it analyses
    /// again without error; empty formulas if it did not.
    pub fn get(&self) -> LatexFormulas {
        (self.text.get_or_init(|| print(self.source))).clone()
    }
}

/// Analyses the struct `source` and prints its formulas with its fields' LaTeX symbols (on a
/// thread with a large stack, as a run-time model's text is: the analysis recurses).
fn print(source: &str) -> LatexFormulas {
    crate::compile::on_large_stack(|| {
        let Ok(di) = syn::parse_str::<syn::DeriveInput>(source) else {
            return LatexFormulas::default();
        };
        let Ok(model) = routh_codegen::analyse(&di) else {
            return LatexFormulas::default();
        };
        let t = routh_codegen::latex::latex_formulas(&model, &model.latex_symbols);
        LatexFormulas {
            lagrangian: t.lagrangian,
            psi_dot: t.psi_dot,
            routhian: t.routhian,
            amended_potential: t.amended_potential,
            a: t.a,
            g: t.g,
            c: t.c,
        }
    })
}
