//! The keyword options of a continuation, shared by `Model.bifurcation_diagram` and the
//! family functions (`routh.bifurcation_diagram`, `routh.stability_atlas`).

use routh::ContinuationOptions;

/// The keyword options of a continuation (None: the Rust default).
pub struct ContinuationKw {
    pub initial_step: Option<f64>,
    pub max_step: Option<f64>,
    pub min_step: Option<f64>,
    pub max_steps: Option<usize>,
    pub max_branches: Option<usize>,
    pub newton_tol: Option<f64>,
    pub event_tol: Option<f64>,
    pub seeds: Option<usize>,
    pub verify_counts: Option<bool>,
    /// Also locate the nonlinear events (Arnold's D = 0, 1:2 and 1:3 resonances).
    pub nonlinear: bool,
}

/// The Rust defaults with the given keywords applied.
pub fn continuation_options(kw: ContinuationKw) -> ContinuationOptions {
    let mut o = ContinuationOptions::default();
    if let Some(v) = kw.initial_step {
        o.initial_step = v;
    }
    if let Some(v) = kw.max_step {
        o.max_step = v;
    }
    if let Some(v) = kw.min_step {
        o.min_step = v;
    }
    if let Some(v) = kw.max_steps {
        o.max_steps = v;
    }
    if let Some(v) = kw.max_branches {
        o.max_branches = v;
    }
    if let Some(v) = kw.newton_tol {
        o.newton_tol = v;
    }
    if let Some(v) = kw.event_tol {
        o.event_tol = v;
    }
    if let Some(v) = kw.seeds {
        o.seeds = v;
    }
    if let Some(v) = kw.verify_counts {
        o.verify_counts = v;
    }
    if kw.nonlinear {
        o.nonlinear = Some(routh::NonlinearOptions::default());
    }
    o
}
