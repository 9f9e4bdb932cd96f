//! [`Model`]: a model read at run time, and its implementations of the model traits.

use crate::compile::{compile, index, Compiled};
use crate::error::ModelError;
use crate::evaluation::Evaluation;
use crate::kernel::{Backend, INPUTS};
use crate::kernels::{Kernels, Maker};
use crate::results::{gyroscopic, routh_bundle, BUNDLE_LEN};
use crate::Param;
use nalgebra::{Matrix3, Vector3};
use routh_codegen::layout::{EquationTerms, JacobianTerms, TermsShape, JACOBIAN_LEN};
use routh_core::{
    FullEquations, FullJacobian, GyroscopicSystem, Lagrangian, RankOneInertia, ReducedEquations,
    RouthBundle, Routhian,
};
use routh_tape::{CertificationTape, FlowTape, RouthianTape, Tape};
use std::collections::BTreeMap;
use std::fmt;
use std::sync::Arc;

/// A rigid-body model written in the language of `#[derive(Lagrangian)]`, read at run time: the
/// body of the derive's `#[lagrangian(...)]` attribute and the values of its parameters.
///
/// The text is parsed, checked, differentiated and reduced by the derive's own code (the same
/// expression DAG, simplifications and error messages), and each method of [`Lagrangian`] and
/// [`Routhian`] evaluates a tape of that DAG, so every analysis takes a `Model` as it takes a
/// derived struct. The tapes read the parameter values from the model's list of values: a tape
/// is compiled (feature `jit`) the first time it is evaluated, once, and [`Model::set`] and
/// [`Model::with`] change values only (a copy made by `with` shares the compiled code).
///
/// ```
/// use routh_runtime::Model;
/// use routh_core::{steady_motions, Routhian, Vector3};
///
/// // The Lagrange top of examples/heavy_top.rs: A₁ = 1, C = 1.25, mgl = 1.
/// let top = Model::new(
///     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
///     &[("inertia", [1.0, 1.0, 1.25].into()), ("mgl", 1.0.into())],
/// )?;
/// let gamma = Vector3::new(0.0, 0.0, 1.0);
/// // The amended potential of the sleeping top: U_r = p²/(2C) + mgl.
/// let p = 2.5;
/// assert!((top.amended_potential(&gamma, p) - (p * p / 2.5 + 1.0)).abs() < 1e-14);
/// let motions = steady_motions(&top, p)?;
/// assert!(!motions.is_empty());
/// // Parameters can be changed (the values only: nothing is re-derived or recompiled).
/// let heavier = top.with("mgl", 2.0)?;
/// assert!((heavier.amended_potential(&gamma, p) - (p * p / 2.5 + 2.0)).abs() < 1e-14);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone)]
pub struct Model {
    text: Arc<str>,
    // Shared by the clones (a clone is cheap: an analysis clones its model, a diagram once per
    // point); `set` copies the list when it is shared.
    params: Arc<Vec<(String, Param)>>,
    symmetric: Arc<[String]>,
    latex: Arc<BTreeMap<String, String>>,
    compiled: Arc<Compiled>,
    /// The values `Op::Param(k)` reads, `values[k]` (see [`Model::tape_parameters`]).
    values: Arc<[f64]>,
    /// The values each tape's kernel reads: its parameter-only subexpressions at `values`
    /// ([`crate::hoist`]), one list per tape.
    hoisted: Arc<[Vec<f64>]>,
    /// `J₀` of `J = J₀ + c v vᵀ` at these values.
    constant_inertia: Option<Matrix3<f64>>,
    kernels: Arc<Kernels>,
}

/// The JIT where it is available, optimizing (see `docs/performance.md`: optimized code is
/// faster to run and slower to compile; a model compiles a tape only when it is first used).
fn default_maker() -> Maker {
    #[cfg(feature = "jit")]
    return Maker::Jit { optimize: true };
    #[cfg(not(feature = "jit"))]
    return Maker::Interpreter;
}

impl fmt::Debug for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Model")
            .field("lagrangian", &&*self.text)
            .field("parameters", &self.params)
            .field("symmetric", &self.symmetric)
            .finish_non_exhaustive()
    }
}

impl Model {
    /// A model of `lagrangian` (the body of a derive's `#[lagrangian(...)]`: `kinetic = ...`,
    /// `linear = ...`, `potential = ...` and `let` items) with the named parameters, which the
    /// text uses as a derived struct's fields. A parameter given and not used is allowed.
    ///
    /// Errors: every mistake the derive reports (an unknown name, a shape mismatch, a kinetic
    /// energy that is not quadratic in ω, …) with its line and column in `lagrangian`; a
    /// parameter given twice or with an invalid name.
    pub fn new(lagrangian: &str, parameters: &[(&str, Param)]) -> Result<Model, ModelError> {
        let params: Vec<(String, Param)> = parameters
            .iter()
            .map(|(n, p)| ((*n).to_string(), *p))
            .collect();
        Model::build(lagrangian, params, Vec::new(), BTreeMap::new())
    }

    /// [`Model::new`] with the matrices of `symmetric` read by their upper triangle only (the
    /// derive's `#[lagrangian(symmetric)]`).
    pub fn with_symmetric(
        lagrangian: &str,
        parameters: &[(&str, Param)],
        symmetric: &[&str],
    ) -> Result<Model, ModelError> {
        let params = parameters
            .iter()
            .map(|(n, p)| ((*n).to_string(), *p))
            .collect();
        let symmetric = symmetric.iter().map(|s| (*s).to_string()).collect();
        Model::build(lagrangian, params, symmetric, BTreeMap::new())
    }

    pub(crate) fn build(
        text: &str,
        params: Vec<(String, Param)>,
        symmetric: Vec<String>,
        latex: BTreeMap<String, String>,
    ) -> Result<Model, ModelError> {
        for (i, (name, _)) in params.iter().enumerate() {
            if params[..i].iter().any(|(n, _)| n == name) {
                let (line, column) = crate::compile::first_use(text, name);
                return Err(ModelError::at(
                    format!("parameter `{name}` is given twice"),
                    text,
                    line,
                    column,
                    name.chars().count(),
                ));
            }
        }
        for (name, p) in &params {
            if let Some(why) = p.non_finite(name) {
                let (line, column) = crate::compile::first_use(text, name);
                return Err(ModelError::at(
                    why,
                    text,
                    line,
                    column,
                    name.chars().count(),
                ));
            }
        }
        let compiled = Arc::new(compile(text, &params, &symmetric)?);
        let values: Arc<[f64]> = values(&compiled, &params)?.into();
        let constant_inertia = constant_inertia(&compiled, &values);
        let hoisted = hoisted(&compiled, &values);
        let kernels = Arc::new(Kernels::new(Arc::clone(&compiled), default_maker()));
        Ok(Model {
            text: text.into(),
            params: Arc::new(params),
            symmetric: symmetric.into(),
            latex: Arc::new(latex),
            compiled,
            values,
            hoisted,
            constant_inertia,
            kernels,
        })
    }

    /// Sets parameter `name` to `value` (of the shape it has): the values the tapes read change,
    /// nothing else (no re-derivation, no recompilation: the reduced expressions and their
    /// compiled code do not depend on the values).
    pub fn set(&mut self, name: &str, value: impl Into<Param>) -> Result<(), ModelError> {
        let value = value.into();
        let Some(slot) = self.params.iter().position(|(n, _)| n == name) else {
            let known: Vec<&str> = self.params.iter().map(|(n, _)| n.as_str()).collect();
            return Err(ModelError::general(format!(
                "unknown parameter `{name}` (the model's parameters: {})",
                if known.is_empty() {
                    "none".to_string()
                } else {
                    known.join(", ")
                }
            )));
        };
        let params = Arc::make_mut(&mut self.params);
        let slot = &mut params[slot];
        if !slot.1.same_shape(&value) {
            return Err(ModelError::general(format!(
                "parameter `{name}` is a {}, not a {}",
                slot.1.shape_name(),
                value.shape_name()
            )));
        }
        if let Some(why) = value.non_finite(name) {
            return Err(ModelError::general(why));
        }
        let old = slot.1;
        slot.1 = value;
        let values: Arc<[f64]> = match values(&self.compiled, &self.params) {
            Ok(v) => v.into(),
            Err(e) => {
                // Cannot happen (every parameter the tapes read has a value): left unchanged.
                if let Some(slot) = Arc::make_mut(&mut self.params)
                    .iter_mut()
                    .find(|(n, _)| n == name)
                {
                    slot.1 = old;
                }
                return Err(e);
            }
        };
        self.constant_inertia = constant_inertia(&self.compiled, &values);
        self.hoisted = hoisted(&self.compiled, &values);
        if let Maker::Custom { backend, .. } = self.kernels.maker() {
            // A custom backend's kernels are made from the bound tapes: made again.
            let maker = Maker::Custom {
                backend: *backend,
                values: Arc::clone(&values),
            };
            self.kernels = Arc::new(Kernels::new(Arc::clone(&self.compiled), maker));
        }
        self.values = values;
        Ok(())
    }

    /// A copy with parameter `name` set to `value` (see [`Model::set`]); it shares the
    /// compiled code of the tapes with `self`.
    pub fn with(&self, name: &str, value: impl Into<Param>) -> Result<Model, ModelError> {
        let mut m = self.clone();
        m.set(name, value)?;
        Ok(m)
    }

    /// The value of parameter `name`.
    pub fn get(&self, name: &str) -> Option<Param> {
        self.params.iter().find(|(n, _)| n == name).map(|(_, p)| *p)
    }

    /// The parameters, in the order given.
    pub fn parameters(&self) -> &[(String, Param)] {
        &self.params
    }

    /// The Lagrangian's text.
    pub fn lagrangian_text(&self) -> &str {
        &self.text
    }

    /// The matrices read by their upper triangle only.
    pub fn symmetric(&self) -> &[String] {
        &self.symmetric
    }

    /// The LaTeX symbols of the TOML file's optional `[latex]` table (name → symbol), for
    /// reports.
    pub fn latex_symbols(&self) -> &BTreeMap<String, String> {
        &self.latex
    }

    /// This model with the LaTeX symbols `latex` (name → symbol, as the TOML's `[latex]` table
    /// gives them) in place of its own: what a copy made from the text, parameters and
    /// symmetric list needs to print as the original (the Python package's pickling).
    pub fn with_latex_symbols(mut self, latex: BTreeMap<String, String>) -> Model {
        self.latex = Arc::new(latex);
        self
    }

    /// The derived formulas in LaTeX, printed from the same DAG as the evaluation: `L`, `ψ̇` (38),
    /// `R` (14), `U_r` (34) and `A`, `G`, `C` of (64) as `pmatrix`es (the derive's
    /// `DerivedFormulas::latex`). A parameter prints as the symbol the TOML's `[latex]` table gives
    /// it, else as `\mathit{name}`; components are subscripted (`I_{11}`, `\gamma_3`).
    ///
    /// ```
    /// let top = routh_runtime::Model::from_toml(r#"
    /// [model]
    /// lagrangian = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"
    /// [parameters]
    /// inertia = [1.0, 1.0, 1.25]
    /// mgl = 1.0
    /// [latex]
    /// inertia = "I"
    /// "#)?;
    /// let f = top.latex();
    /// assert!(f.amended_potential.contains("I_{"));
    /// assert!(f.amended_potential.contains(r"\mathit{mgl}"));
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn latex(&self) -> routh_core::LatexFormulas {
        let symbols: Vec<(String, String)> = self
            .latex
            .iter()
            .map(|(name, symbol)| {
                (
                    format!("\\mathit{{{}}}", name.replace('_', "\\_")),
                    // A symbol with a sub- or superscript of its own in braces: `{r_c}_{1}`,
                    // not the double subscript `r_c_{1}` (as `routh_symbolic::latex_symbol`).
                    if symbol.contains(['_', '^']) {
                        format!("{{{symbol}}}")
                    } else {
                        symbol.clone()
                    },
                )
            })
            .collect();
        let put = |s: &str| {
            symbols.iter().fold(s.to_string(), |acc, (from, to)| {
                acc.replace(from.as_str(), to)
            })
        };
        let t = self
            .compiled
            .latex
            .get_or_init(|| crate::compile::latex(&self.text, &self.params, &self.symmetric));
        routh_core::LatexFormulas {
            lagrangian: put(&t.lagrangian),
            psi_dot: put(&t.psi_dot),
            routhian: put(&t.routhian),
            amended_potential: put(&t.amended_potential),
            a: put(&t.a),
            g: put(&t.g),
            c: put(&t.c),
        }
    }

    /// The derived formulas of [`Model::latex`] in SymPy's syntax, to parse with
    /// `sympy.sympify` and keep computing: the same expressions in the same order, with
    /// `omega1` (`Omega1` in ψ̇ and R), `gamma1`, `p_psi`, each parameter by its name and
    /// components from 1 (`inertia_3`, `J_12`), matrices as `Matrix([[…], …])` (see
    /// [`routh_core::SympyFormulas`]). Printed the first time it is asked for.
    ///
    /// ```
    /// use routh_runtime::{Model, Param};
    /// let inertia = Param::Vector(routh_core::Vector3::new(1.0, 1.0, 1.25));
    /// let top = Model::new(
    ///     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
    ///     &[("inertia", inertia), ("mgl", 1.0.into())],
    /// )?;
    /// let f = top.sympy();
    /// assert_eq!(
    ///     f.lagrangian,
    ///     "1/2*(inertia_1*omega1**2 + inertia_2*omega2**2 + inertia_3*omega3**2) - mgl*gamma3"
    /// );
    /// assert!(f.a.starts_with("Matrix([["));
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn sympy(&self) -> routh_core::SympyFormulas {
        let t = self
            .compiled
            .sympy
            .get_or_init(|| crate::compile::sympy(&self.text, &self.params, &self.symmetric));
        routh_core::SympyFormulas {
            lagrangian: t.lagrangian.clone(),
            psi_dot: t.psi_dot.clone(),
            routhian: t.routhian.clone(),
            amended_potential: t.amended_potential.clone(),
            a: t.a.clone(),
            g: t.g.clone(),
            c: t.c.clone(),
            definitions: t.definitions.clone(),
            symbols: t.symbols.clone(),
        }
    }

    /// `L`, the amended potential `U_r(γ, p_ψ)` (34) and `ψ̇` at rest (38) after simplification,
    /// as text (the derive's `DerivedFormulas`).
    pub fn formulas(&self) -> [&str; 3] {
        let f = &self.compiled.formulas;
        [&f[0], &f[1], &f[2]]
    }

    /// Replaces the evaluation of every tape by `backend`, tape by tape (e.g.
    /// [`crate::kernel::interpret`], or [`crate::kernel::jit`] to compile each tape on its
    /// own); the default compiles all the tapes together to native code (feature `jit`), or
    /// interprets them.
    ///
    /// The backend receives each tape with the parameter values bound (folded in as
    /// constants), the first time the tape is evaluated, and again after [`Model::set`].
    pub fn with_backend(&self, backend: Backend) -> Result<Model, ModelError> {
        Ok(self.with_maker(Maker::Custom {
            backend,
            values: Arc::clone(&self.values),
        }))
    }

    /// A copy that interprets its tapes ([`crate::kernel::Interpreter`]) instead of compiling
    /// them: what a model does without the feature `jit`.
    ///
    /// ```
    /// use routh_runtime::{Evaluation, Model};
    /// let top = Model::new("kinetic = 0.5 * omega.dot(omega), potential = gamma.z", &[])?;
    /// let slow = top.interpreted()?;
    /// assert_eq!(slow.evaluation(), Evaluation::Interpreter);
    /// let g = routh_core::Vector3::new(0.6, 0.0, 0.8);
    /// use routh_core::Routhian;
    /// // The same IEEE operations: the same bits.
    /// assert_eq!(top.amended_potential(&g, 1.5), slow.amended_potential(&g, 1.5));
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn interpreted(&self) -> Result<Model, ModelError> {
        Ok(self.with_maker(Maker::Interpreter))
    }

    /// How the tapes are evaluated: [`Evaluation::Jit`] by default where the feature `jit` is
    /// on and Cranelift supports the host, else [`Evaluation::Interpreter`].
    ///
    /// ```
    /// use routh_runtime::{Evaluation, Model};
    /// let top = Model::new("kinetic = 0.5 * omega.dot(omega), potential = gamma.z", &[])?;
    /// if routh_runtime::kernel::jit_supported() {
    ///     assert_eq!(top.evaluation(), Evaluation::Jit);
    /// }
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn evaluation(&self) -> Evaluation {
        self.kernels.evaluation()
    }

    /// How many of the model's tapes have been compiled (or prepared for the interpreter) so
    /// far: a tape is, the first time one of its methods is evaluated, once for the model, its
    /// clones and the copies [`Model::with`] makes (they share the code).
    ///
    /// ```
    /// use routh_runtime::Model;
    /// use routh_core::{Routhian, Vector3};
    /// let top = Model::new("kinetic = 0.5 * omega.dot(omega), potential = mgl * gamma.z",
    ///     &[("mgl", 1.0.into())])?;
    /// assert_eq!(top.tapes_made(), 0); // building compiles nothing
    /// let g = Vector3::new(0.0, 0.6, 0.8);
    /// top.amended_potential(&g, 1.0);
    /// assert_eq!(top.tapes_made(), 1);
    /// let heavier = top.with("mgl", 2.0)?;
    /// heavier.amended_potential(&g, 1.0);
    /// assert_eq!(top.tapes_made(), 1); // the copy used the same code
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn tapes_made(&self) -> usize {
        self.kernels.made()
    }

    /// The tape of the generated method `method` (a method name of [`Lagrangian`] or
    /// [`Routhian`]: `"bundle"`, `"routhian"`, `"gyroscopic_system"`, …) with its parameters
    /// unbound: `Op::Param(k)` reads the `k`-th value of [`Model::tape_parameters`]. `None` for
    /// another name.
    ///
    /// ```
    /// use routh_runtime::Model;
    /// let top = Model::new("kinetic = 0.5 * omega.dot(omega), potential = mgl * gamma.z",
    ///     &[("mgl", 2.0.into())])?;
    /// let tape = top.tape("amended_potential").expect("a generated method");
    /// assert_eq!(tape.num_params(), 1);
    /// assert_eq!(top.tape_parameters()?, vec![2.0]);
    /// assert!(top.tape("no_such_method").is_none());
    /// # Ok::<(), routh_runtime::ModelError>(())
    /// ```
    pub fn tape(&self, method: &str) -> Option<&Tape> {
        let k = crate::compile::TAPE_NAMES
            .iter()
            .position(|n| *n == method)?;
        Some(self.compiled.tapes.fields()[k])
    }

    /// The parameter values the unbound tapes ([`Model::tape`]) read, `Op::Param(k)` being the
    /// `k`-th.
    pub fn tape_parameters(&self) -> Result<Vec<f64>, ModelError> {
        Ok(self.values.to_vec())
    }

    /// A copy whose tapes are compiled by the JIT (the interpreter where it is not available:
    /// see [`Model::evaluation`]), `optimize`d (Cranelift's `speed` level and backtracking
    /// register allocator: faster code) or not (no optimization passes, single-pass register
    /// allocator: compiles many times faster, for large models or models built often).
    pub fn jit(&self, optimize: bool) -> Result<Model, ModelError> {
        #[cfg(feature = "jit")]
        let maker = Maker::Jit { optimize };
        #[cfg(not(feature = "jit"))]
        let maker = {
            let _ = optimize;
            Maker::Interpreter
        };
        Ok(self.with_maker(maker))
    }

    /// A copy whose kernels are made by `maker` (none made yet).
    fn with_maker(&self, maker: Maker) -> Model {
        let mut m = self.clone();
        m.kernels = Arc::new(Kernels::new(Arc::clone(&self.compiled), maker));
        m
    }
}

/// The values of the tapes' parameters, `Op::Param(k)` being `reads[k]`.
fn values(compiled: &Compiled, params: &[(String, Param)]) -> Result<Vec<f64>, ModelError> {
    compiled
        .reads
        .iter()
        .map(|(name, access)| {
            params
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, p)| p.read(access))
                .ok_or_else(|| ModelError::general(format!("parameter `{name}` has no value")))
        })
        .collect()
}

/// The values each tape's kernel reads at the parameter values `values`.
fn hoisted(compiled: &Compiled, values: &[f64]) -> Arc<[Vec<f64>]> {
    compiled
        .split
        .iter()
        .map(|s| s.main_params(values))
        .collect()
}

/// `J₀` of `J = J₀ + c v vᵀ` at the parameter values `values` (a tape of parameters only).
fn constant_inertia(compiled: &Compiled, values: &[f64]) -> Option<Matrix3<f64>> {
    let t = compiled.constant_inertia.as_ref()?;
    let mut out = [0.0; 9];
    let zero = routh_tape::Inputs {
        omega: [0.0; 3],
        gamma: [0.0; 3],
        p_psi: 0.0,
    };
    t.eval(&zero, values, &mut Vec::new(), &mut out);
    Some(Matrix3::from_row_slice(&out))
}

fn inputs(w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> [f64; INPUTS] {
    [w.x, w.y, w.z, g.x, g.y, g.z, p]
}

fn v3(o: &[f64]) -> Vector3<f64> {
    Vector3::new(o[0], o[1], o[2])
}

fn m3(o: &[f64]) -> Matrix3<f64> {
    Matrix3::from_row_slice(&o[..9])
}

impl Model {
    /// Tape `which` (an index of [`crate::compile::index`]) at `x`, its `N` outputs.
    #[inline]
    fn eval<const N: usize>(&self, which: usize, x: [f64; INPUTS]) -> [f64; N] {
        let mut out = [0.0; N];
        let params = self.hoisted.get(which).map_or(&[][..], |v| &v[..]);
        self.kernels.eval(which, &x, params, &mut out);
        out
    }

    fn terms(&self, which: usize, x: [f64; INPUTS], psi_dot: bool) -> EquationTerms<f64> {
        let out = self.eval::<17>(which, x);
        let shape = TermsShape {
            psi_dot,
            rank_one: self.compiled.rank_one,
        };
        let n = 12 + usize::from(psi_dot) + 4 * usize::from(self.compiled.rank_one);
        EquationTerms::from_flat(out[..n].iter().copied(), shape)
    }
}

fn rank_one(r: Option<(f64, [f64; 3])>) -> Option<RankOneInertia> {
    r.map(|(weight, v)| RankOneInertia {
        weight,
        vector: Vector3::from(v),
    })
}

fn matrix(m: [[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m[i][j])
}

impl Lagrangian for Model {
    fn lagrangian(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        self.eval::<1>(index::LAGRANGIAN, inputs(omega, gamma, 0.0))[0]
    }
    fn dl_domega(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64> {
        v3(&self.eval::<3>(index::DL_DOMEGA, inputs(omega, gamma, 0.0)))
    }
    fn dl_dgamma(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64> {
        v3(&self.eval::<3>(index::DL_DGAMMA, inputs(omega, gamma, 0.0)))
    }
    fn d2l_domega2(&self, gamma: &Vector3<f64>) -> Matrix3<f64> {
        let x = inputs(&Vector3::zeros(), gamma, 0.0);
        m3(&self.eval::<9>(index::D2L_DOMEGA2, x))
    }
    fn d2l_domega_dgamma(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Matrix3<f64> {
        m3(&self.eval::<9>(index::D2L_DOMEGA_DGAMMA, inputs(omega, gamma, 0.0)))
    }
    fn energy(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        self.eval::<1>(index::ENERGY, inputs(omega, gamma, 0.0))[0]
    }
    fn cyclic_momentum(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        self.eval::<1>(index::CYCLIC_MOMENTUM, inputs(omega, gamma, 0.0))[0]
    }
    fn constant_inertia(&self) -> Option<Matrix3<f64>> {
        self.constant_inertia
    }
    fn full_equations(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> FullEquations {
        let t = self.terms(index::FULL_EQUATIONS, inputs(omega, gamma, 0.0), false);
        FullEquations {
            inertia: matrix(t.inertia),
            right_side: Vector3::from(t.right_side),
            rank_one: rank_one(t.rank_one),
        }
    }
    /// One tape: the nodes of `J` and of the right side of (8) differentiated on the DAG
    /// (`routh_codegen`'s `full_jacobian` outputs), exact, no finite differences.
    fn full_jacobian(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> FullJacobian {
        let x = inputs(omega, gamma, 0.0);
        let o = self.eval::<JACOBIAN_LEN>(index::FULL_JACOBIAN, x);
        let t = JacobianTerms::from_flat(o);
        FullJacobian {
            inertia: matrix(t.inertia),
            right_side: Vector3::from(t.right_side),
            dright_domega: matrix(t.dright_domega),
            dright_dgamma: matrix(t.dright_dgamma),
            dinertia_dgamma: t.dinertia_dgamma.map(matrix),
        }
    }
    fn flow_tape(&self) -> Option<FlowTape> {
        FlowTape::new(self.compiled.flow.clone(), self.values.to_vec()).ok()
    }
}

impl Routhian for Model {
    fn psi_dot(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        self.eval::<1>(index::PSI_DOT, inputs(big_omega, gamma, p_psi))[0]
    }
    fn routhian(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        self.eval::<1>(index::ROUTHIAN, inputs(big_omega, gamma, p_psi))[0]
    }
    fn dr_domega(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Vector3<f64> {
        v3(&self.eval::<3>(index::DR_DOMEGA, inputs(big_omega, gamma, p_psi)))
    }
    fn dr_dgamma(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Vector3<f64> {
        v3(&self.eval::<3>(index::DR_DGAMMA, inputs(big_omega, gamma, p_psi)))
    }
    fn dr_dp(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        self.eval::<1>(index::DR_DP, inputs(big_omega, gamma, p_psi))[0]
    }
    fn d2r_domega2(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64> {
        m3(&self.eval::<9>(index::D2R_DOMEGA2, inputs(big_omega, gamma, p_psi)))
    }
    fn d2r_domega_dgamma(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64> {
        m3(&self.eval::<9>(index::D2R_DOMEGA_DGAMMA, inputs(big_omega, gamma, p_psi)))
    }
    fn d2r_dgamma2(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> Matrix3<f64> {
        m3(&self.eval::<9>(index::D2R_DGAMMA2, inputs(big_omega, gamma, p_psi)))
    }
    fn bundle(&self, big_omega: &Vector3<f64>, gamma: &Vector3<f64>, p_psi: f64) -> RouthBundle {
        let o = self.eval::<BUNDLE_LEN>(index::BUNDLE, inputs(big_omega, gamma, p_psi));
        routh_bundle(&o, 0)
    }
    /// One tape for the bundle and `A`, `G`, `C` of (64) formed from its nodes: the derive's
    /// fused body (`routh_codegen`'s `bundle_and_system` outputs of the same DAG).
    fn bundle_and_system(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> (RouthBundle, GyroscopicSystem) {
        let x = inputs(big_omega, gamma, p_psi);
        let o = self.eval::<{ BUNDLE_LEN + 27 }>(index::BUNDLE_AND_SYSTEM, x);
        (routh_bundle(&o, 0), gyroscopic(&o, BUNDLE_LEN))
    }
    fn amended_potential(&self, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        let x = inputs(&Vector3::zeros(), gamma, p_psi);
        self.eval::<1>(index::AMENDED_POTENTIAL, x)[0]
    }
    fn gyroscopic_system(&self, gamma: &Vector3<f64>, p_psi: f64) -> GyroscopicSystem {
        let x = inputs(&Vector3::zeros(), gamma, p_psi);
        gyroscopic(&self.eval::<27>(index::GYROSCOPIC_SYSTEM, x), 0)
    }
    fn reduced_equations(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        p_psi: f64,
    ) -> ReducedEquations {
        let x = inputs(big_omega, gamma, p_psi);
        let t = self.terms(index::REDUCED_EQUATIONS, x, true);
        ReducedEquations {
            inertia: matrix(t.inertia),
            right_side: Vector3::from(t.right_side),
            psi_dot: t.psi_dot.unwrap_or(f64::NAN),
            rank_one: rank_one(t.rank_one),
        }
    }
    fn certification_tape(&self) -> Option<CertificationTape> {
        CertificationTape::new(self.compiled.certification.clone(), self.values.to_vec()).ok()
    }
    fn routh_tape(&self) -> Option<RouthianTape> {
        RouthianTape::new(self.compiled.routh.clone(), self.values.to_vec()).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_send_sync<T: Send + Sync + Clone + fmt::Debug>() {}

    #[test]
    fn model_is_send_sync_clone_debug() {
        assert_send_sync::<Model>();
    }
}
