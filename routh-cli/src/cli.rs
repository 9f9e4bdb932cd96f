//! The command line's grammar (clap derive): `routh SUBCOMMAND MODEL.toml [options]`.

use crate::args::{self, NamedRange};
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Steady motions, stability and bifurcations of a rigid body about a fixed point, read from a
/// TOML model file (docs/models.md). Routh reduction after Bourov & Chevallier, ZAMM 1998.
///
/// Exit codes: 0 success, 2 bad input (usage, unreadable or invalid model, bad range), 1 a
/// failed computation.
#[derive(Debug, Parser)]
#[command(name = "routh", version, about, long_about)]
pub struct Cli {
    /// What to compute.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// The steady motions (relative equilibria) at the cyclic momentum p_ψ = P: γ, ψ̇, the
    /// multiplier μ, the amended potential U_r and the energy.
    Steady(AtMomentum),
    /// The steady motions at p_ψ = P with their stability reports: the verdict (secularly
    /// stable, gyroscopically stabilized, unstable), the eigenvalues of the restricted second
    /// variation of U_r, the degree of instability and the roots of f₂; with `--axis`, the
    /// circles of steady motions of a symmetric body decided modulo the symmetry.
    Classify(ClassifyArgs),
    /// The nonlinear (Lyapunov) stability of the steady motions at p_ψ = P: the Birkhoff
    /// normal form to order four, Arnold's determinant D, resonances of order ≤ 4 and the
    /// verdict (secularly stable, Lyapunov stable, unstable, undecided) with its reason.
    Nonlinear(AtMomentum),
    /// A bifurcation diagram: the branches of steady motions and their events (folds, branch
    /// points, Hamiltonian–Hopf) over the momentum (`--momentum LO..HI`) or over a parameter
    /// (`--parameter NAME=LO..HI --momentum P`).
    Diagram(Diagram),
    /// A stability atlas: the verdict of the steady motion followed from `--gamma` over a grid
    /// of two quantities (parameters of the model, or `momentum`), with the boundary curves.
    Atlas(Atlas),
    /// Integrate the full equations (Euler–Poisson, from ω and γ) or, with `--reduced`, the
    /// reduced ones (Routh, from Ω, γ and p_ψ); prints samples and the drift of the invariants.
    Simulate(Simulate),
    /// The steady motions at p_ψ = P with an interval-arithmetic certificate that none is missed.
    Certify(Certify),
    /// One periodic orbit corrected from a guess (`--omega`, `--gamma`, `--period`) at the
    /// energy and p_ψ of the guess: its period, precession Δψ, stability index k and multipliers.
    Orbit(OrbitArgs),
    /// The Lyapunov families of periodic orbits born at the linearly stable steady motions at
    /// p_ψ = P (each mode, or `--mode`), or with `--continue` the family through one corrected
    /// orbit (over the energy, or with `--parameter` at its energy over a parameter): energy, period, precession Δψ and stability index k of the orbits, and the folds,
    /// branch points and period doublings along each family; with `--doubling` also the
    /// period-doubled families born at the period doublings, with `--switch` the families
    /// crossing at the branch points.
    Orbits(Orbits),
    /// A Poincaré section at p_ψ = P and energy E: many orbits crossing the plane γ·n = 0 (the
    /// points as CSV or JSON; regular motion shows as curves, chaos as scattered dots).
    Section(Section),
    /// The chart of a mode's Lyapunov family over a scalar parameter (`--parameter
    /// NAME=LO..HI`) and the energy above the steady motion (`--excess-energy LO..HI`): the
    /// curves where the orbits change linear stability (k = ±1, folds), meet the resonances of
    /// order three and four, and lose their twist (docs/method.md §12).
    OrbitChart(OrbitChartArgs),
    /// The derived formulas: the Lagrangian, the amended potential U_r(γ, p_ψ) and ψ̇(0, γ, p_ψ);
    /// with `--latex`, all seven derived formulas (L, ψ̇, R, U_r, A, G, C) in LaTeX.
    Formulas(Formulas),
}

/// The model file and the output format, common to every subcommand.
#[derive(Debug, Args)]
pub struct Output {
    /// Print JSON (the library's result types) instead of a table.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV instead of a table.
    #[arg(long)]
    pub csv: bool,
}

/// The options of every figure a command writes (`--svg` and the like); without a figure, they
/// do nothing.
#[derive(Debug, Clone, Args)]
pub struct Figure {
    /// The figure's printed width: `column` (3.4 in), `page` (7 in) or inches (e.g. `5.5`); the
    /// SVG then says its size in inches and its texts are printed at their sizes in points.
    /// Default: 900 × 600 pixels, no unit.
    #[arg(long, value_name = "IN|column|page", value_parser = args::figure_width)]
    pub width: Option<f64>,
    /// The size of the tick labels in points (5 to 24; default 8); the axis names, legend and
    /// event names keep their proportions to it.
    #[arg(long, value_name = "PT", value_parser = args::font_size, allow_hyphen_values = true)]
    pub font_size: Option<f64>,
    /// A title above the axes (default: none; a journal's caption goes below the figure).
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// Black, white and greys only: every verdict told apart by its stroke, marker or pattern.
    #[arg(long, visible_alias = "gray")]
    pub grey: bool,
}

impl Figure {
    /// `opts` with these options.
    pub fn apply(&self, opts: routh::plot::PlotOptions) -> routh::plot::PlotOptions {
        routh::plot::PlotOptions {
            width_in: self.width.or(opts.width_in),
            font_pt: self.font_size.unwrap_or(opts.font_pt),
            title: self.title.clone().unwrap_or(opts.title),
            monochrome: self.grey || opts.monochrome,
            ..opts
        }
    }
}

/// `steady` and `classify`.
#[derive(Debug, Args)]
pub struct AtMomentum {
    /// The model file (TOML, see docs/models.md), e.g. examples/models/heavy_top.toml.
    pub model: PathBuf,
    /// The cyclic momentum p_ψ.
    #[arg(long, short = 'p', value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: f64,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `classify`.
#[derive(Debug, Args)]
pub struct ClassifyArgs {
    /// The model, the momentum and the output format.
    #[command(flatten)]
    pub at: AtMomentum,
    /// `X,Y,Z`: a body axis about which the model is symmetric (e.g. `0,0,1` for a top
    /// symmetric about e₃). Each circle of steady motions (a motion that is not isolated) is then
    /// also decided modulo the symmetry, from the doubly amended potential: `V'' > 0` stable,
    /// `V'' < 0` unstable (docs/method.md, 6a).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub axis: Option<[f64; 3]>,
}

/// `diagram`.
#[derive(Debug, Args)]
pub struct Diagram {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// `LO..HI`: follow the steady motions over this momentum range; with `--parameter`, a
    /// single value P (the fixed momentum).
    #[arg(long, short = 'p', allow_hyphen_values = true)]
    pub momentum: String,
    /// `NAME=LO..HI`: follow the steady motions over this scalar parameter of the model, at the
    /// fixed momentum given by `--momentum P`.
    #[arg(long, value_parser = args::named_range, allow_hyphen_values = true)]
    pub parameter: Option<NamedRange>,
    /// Draw the diagram (γ₃ of the steady motions over the swept quantity, coloured by
    /// stability, events marked) into this SVG file.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Draw the energy–momentum diagram (E over p_ψ) into this SVG file (a sweep over the
    /// momentum only).
    #[arg(long, value_name = "FILE", conflicts_with = "parameter")]
    pub energy_momentum_svg: Option<PathBuf>,
    /// `X,Y,Z`: draw the circles of steady motions of a body symmetric about this body axis with
    /// their verdict modulo the symmetry (`classify_circle`: stable or unstable as circles,
    /// where the classification of a single point is degenerate). The figures only: the tables
    /// keep each point's own verdict.
    #[arg(long, value_name = "X,Y,Z", value_parser = args::vec3, allow_hyphen_values = true)]
    pub circles: Option<[f64; 3]>,
    /// Also locate the nonlinear events on gyroscopically stabilised stretches: Arnold's
    /// D = 0 and the 1:2, 1:3 resonances (slower: a normal form at every step there).
    #[arg(long)]
    pub nonlinear: bool,
    /// Figure options.
    #[command(flatten)]
    pub figure: Figure,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `formulas`.
#[derive(Debug, Args)]
pub struct Formulas {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Print the seven derived formulas in LaTeX (`Model::latex`): L, ψ̇, the Routh function R,
    /// the amended potential U_r and the matrices A, G, C of (64), as `align*` display blocks
    /// (amsmath) whose lines fit a page; with `--json`, the `LatexFormulas` object.
    #[arg(long, conflicts_with = "sympy")]
    pub latex: bool,
    /// With `--latex`: print a complete LaTeX document (article, amsmath) that pdflatex
    /// compiles, instead of the display blocks alone.
    #[arg(long, requires = "latex", conflicts_with = "json")]
    pub document: bool,
    /// Print the same seven formulas in SymPy's syntax (`Model::sympy`), as lines
    /// `name = formula` (Python after `from sympy import *`); with `--json`, the
    /// `SympyFormulas` object.
    #[arg(long)]
    pub sympy: bool,
}

/// `atlas`.
#[derive(Debug, Args)]
pub struct Atlas {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// `NAME=LO..HI`: the horizontal axis, a scalar parameter or `momentum`.
    #[arg(long, value_parser = args::named_range, allow_hyphen_values = true)]
    pub x: NamedRange,
    /// `NAME=LO..HI`: the vertical axis, a scalar parameter or `momentum`.
    #[arg(long, value_parser = args::named_range, allow_hyphen_values = true)]
    pub y: NamedRange,
    /// The momentum p_ψ when neither axis is `momentum`.
    #[arg(long, short = 'p', value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: Option<f64>,
    /// `X,Y,Z`: γ of the steady motion to follow (a first guess at the grid's corner).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub gamma: [f64; 3],
    /// Grid columns (default: the library's, `AtlasOptions::default().nx`).
    #[arg(long, value_parser = clap::value_parser!(u16).range(2..=2000))]
    pub nx: Option<u16>,
    /// Grid rows (default: the library's).
    #[arg(long, value_parser = clap::value_parser!(u16).range(2..=2000))]
    pub ny: Option<u16>,
    /// Draw the atlas into this SVG file.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Figure options.
    #[command(flatten)]
    pub figure: Figure,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `simulate`.
#[derive(Debug, Args)]
pub struct Simulate {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// `X,Y,Z`: the initial angular velocity ω (with `--reduced`, the reduced Ω).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub omega: [f64; 3],
    /// `X,Y,Z`: the initial vertical γ in the body frame (a unit vector).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub gamma: [f64; 3],
    /// The final time.
    #[arg(long, value_parser = args::positive, allow_hyphen_values = true)]
    pub t_end: f64,
    /// Integrate the reduced (Routh) equations at `--momentum P` instead of the full ones.
    #[arg(long, requires = "momentum")]
    pub reduced: bool,
    /// The cyclic momentum p_ψ of `--reduced`.
    #[arg(long, short = 'p', value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: Option<f64>,
    /// Relative tolerance of the integrator.
    #[arg(long, value_parser = args::relative_tolerance, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance of the integrator.
    #[arg(long, value_parser = args::positive, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format (`--csv` and `--json`: every recorded step).
    #[command(flatten)]
    pub output: Output,
}

/// `certify`.
#[derive(Debug, Args)]
pub struct Certify {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// The cyclic momentum p_ψ.
    #[arg(long, short = 'p', value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: f64,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// `orbit`.
#[derive(Debug, Args)]
pub struct OrbitArgs {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// `X,Y,Z`: ω of the guess (body frame).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub omega: [f64; 3],
    /// `X,Y,Z`: γ of the guess (body frame, a unit vector); the orbit keeps the guess's energy
    /// and p_ψ.
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub gamma: [f64; 3],
    /// The guess of the period T (above 0).
    #[arg(long, value_parser = args::positive, allow_hyphen_values = true)]
    pub period: f64,
    /// Also decide the orbit's stability beyond the linear test: the rotation number ρ and the
    /// twist τ of its Poincaré map, resonances of order three and four, and the verdict
    /// (orbitally stable by Moser's twist theorem, unstable, undecided).
    #[arg(long)]
    pub nonlinear: bool,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `orbits`.
#[derive(Debug, Args)]
pub struct Orbits {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// The cyclic momentum p_ψ (not with `--continue`: the guess gives it).
    #[arg(
        long,
        short = 'p',
        value_parser = args::finite,
        allow_hyphen_values = true,
        required_unless_present = "continue",
        conflicts_with = "continue"
    )]
    pub momentum: Option<f64>,
    /// 0 (the faster frequency ω₁) or 1 (the slower ω₂); both when omitted.
    #[arg(long, conflicts_with = "continue")]
    pub mode: Option<usize>,
    /// `X,Y,Z`: only the steady motion nearest this γ; with `--continue`, γ of the guess.
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub gamma: Option<[f64; 3]>,
    /// `LO..HI`: keep each family within these energies; with `--continue`, the range to
    /// continue over (needed, unless `--parameter`).
    #[arg(long, value_parser = args::range, allow_hyphen_values = true)]
    pub energy: Option<(f64, f64)>,
    /// Continue the family through the orbit corrected from the guess `--omega`, `--gamma`,
    /// `--period` (as `routh orbit`) over `--energy LO..HI` (or, with `--parameter`, over a
    /// parameter at the orbit's energy), instead of the Lyapunov families.
    #[arg(
        long = "continue",
        id = "continue",
        requires_all = ["omega", "gamma", "period"]
    )]
    pub continue_orbit: bool,
    /// `NAME=LO..HI`: with `--continue`, follow the family at the corrected orbit's fixed
    /// energy through this scalar parameter of the model (or `momentum`, p_ψ) instead of the
    /// energy. The guess is corrected at the model file's value of NAME (for `momentum`, at the
    /// guess's p_ψ), which must lie in LO..HI.
    #[arg(
        long,
        value_name = "NAME=LO..HI",
        value_parser = args::named_range,
        allow_hyphen_values = true,
        requires = "continue",
        conflicts_with_all = ["energy", "doubling", "switch", "svg", "periods_svg"]
    )]
    pub parameter: Option<NamedRange>,
    /// `X,Y,Z`: ω of the guess of `--continue`.
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true, requires = "continue")]
    pub omega: Option<[f64; 3]>,
    /// The guess of the period of `--continue`.
    #[arg(long, value_parser = args::positive, allow_hyphen_values = true, requires = "continue")]
    pub period: Option<f64>,
    /// Also follow the period-doubled family born at each period doubling of the families
    /// computed (one generation: the doubled families' own doublings are listed, not followed).
    #[arg(long)]
    pub doubling: bool,
    /// Also follow the family crossing at each branch point of the families computed (one
    /// generation, as `--doubling`; both may be given).
    #[arg(long)]
    pub switch: bool,
    /// Also locate, along each family, where the twist of the Poincaré map vanishes and where
    /// the orbits meet the resonances of order three (k = −1/2) and four (k = 0).
    #[arg(long)]
    pub nonlinear: bool,
    /// The most orbits per family (default: the library's, `OrbitOptions::default()`).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=10000))]
    pub max_orbits: Option<u16>,
    /// The most rows printed per family in the table (every orbit with `--csv`/`--json`).
    #[arg(long, default_value_t = 12)]
    pub rows: usize,
    /// Draw the family's stability diagram (the index k against E, the lines k = ±1, events
    /// named) into this SVG file; needs exactly one family (choose it with `--mode` and
    /// `--gamma`; not with `--doubling` or `--switch`).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["doubling", "switch"])]
    pub svg: Option<PathBuf>,
    /// Draw the family's periods against E into this SVG file (one family, as `--svg`).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["doubling", "switch"])]
    pub periods_svg: Option<PathBuf>,
    /// Figure options.
    #[command(flatten)]
    pub figure: Figure,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `section`.
#[derive(Debug, Args)]
pub struct Section {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// The cyclic momentum p_ψ.
    #[arg(long, short = 'p', value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: f64,
    /// The energy E.
    #[arg(long, short = 'e', value_parser = args::finite, allow_hyphen_values = true)]
    pub energy: f64,
    /// `X,Y,Z`: the plane is γ·n = 0 (body frame); default 1,0,0.
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub normal: Option<[f64; 3]>,
    /// How many orbits (default: the library's, `SectionOptions::default()`).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=5000))]
    pub orbits: Option<u16>,
    /// Crossings per orbit (default: the library's).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100000))]
    pub crossings: Option<u32>,
    /// Draw the section (θ against M_n, one colour per orbit) into this SVG file.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Figure options.
    #[command(flatten)]
    pub figure: Figure,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format.
    #[command(flatten)]
    pub output: Output,
}

/// `orbit-chart`.
#[derive(Debug, Args)]
pub struct OrbitChartArgs {
    /// The model file (TOML, see docs/models.md).
    pub model: PathBuf,
    /// `NAME=LO..HI`: the scalar parameter of the model the chart runs over.
    #[arg(long, value_name = "NAME=LO..HI", value_parser = args::named_range, allow_hyphen_values = true)]
    pub parameter: NamedRange,
    /// `LO..HI`: the energies above the steady motion, `h = E − E_s` (0 ≤ LO < HI).
    #[arg(long, value_parser = args::range, allow_hyphen_values = true)]
    pub excess_energy: (f64, f64),
    /// `X,Y,Z`: the steady motion nearest this γ at the first value of the parameter (then
    /// followed).
    #[arg(long, value_parser = args::vec3, allow_hyphen_values = true)]
    pub gamma: [f64; 3],
    /// 0 (the faster frequency ω₁) or 1 (the slower ω₂).
    #[arg(long, default_value_t = 0, value_parser = clap::value_parser!(u8).range(0..=1))]
    pub mode: u8,
    /// The cyclic momentum p_ψ.
    #[arg(long, short = 'p', default_value_t = 0.0, value_parser = args::finite, allow_hyphen_values = true)]
    pub momentum: f64,
    /// The number of parameter values, both ends included (default: the library's,
    /// `OrbitChartOptions::default().nx`).
    #[arg(long, value_parser = clap::value_parser!(u16).range(2..=10000))]
    pub nx: Option<u16>,
    /// The most orbits per family (default: the library's, `OrbitChartOptions::default()`).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=10000))]
    pub max_orbits: Option<u16>,
    /// Draw the chart into this SVG file: the regions of the orbits by linear stability, the
    /// curves on top, the parameter across and h up.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Figure options.
    #[command(flatten)]
    pub figure: Figure,
    /// Options.
    #[command(flatten)]
    pub opts: Opts,
    /// Output format (`--csv`: the curves' points; `--json`: the whole chart).
    #[command(flatten)]
    pub output: Output,
}

/// `--opt KEY=VALUE` of an analysis.
#[derive(Debug, Args)]
pub struct Opts {
    /// `KEY=VALUE`: set a field of the analysis's options struct (repeatable; every field is a
    /// key, a nested struct's fields by their own names; VALUE in JSON, e.g. `1e-9`, `true`,
    /// `[-2, 1]`, else a string). Given after the flags, it overrides them; an unknown KEY
    /// lists the valid ones.
    #[arg(
        long = "opt",
        value_name = "KEY=VALUE",
        value_parser = args::opt,
        allow_hyphen_values = true
    )]
    pub opt: Vec<(String, serde_json::Value)>,
}
