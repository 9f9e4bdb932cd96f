//! Tapes with a model's parameter values bound, as the model traits hand them out.

use crate::{Inputs, Output, Tape, TapeError, TapeScalar};

/// The output names of a [`CertificationTape`], in order: `∂R/∂γ` at `Ω = 0`, then the upper
/// triangle of `∂²R/∂γ²` at `Ω = 0`, row by row.
pub const CERTIFICATION_OUTPUTS: [&str; 9] = [
    "dr_dgamma[0]",
    "dr_dgamma[1]",
    "dr_dgamma[2]",
    "d2r_dgamma2[0][0]",
    "d2r_dgamma2[0][1]",
    "d2r_dgamma2[0][2]",
    "d2r_dgamma2[1][1]",
    "d2r_dgamma2[1][2]",
    "d2r_dgamma2[2][2]",
];

/// The output name of a [`RouthianTape`].
pub const ROUTHIAN_OUTPUT: &str = "routhian";

/// The output names of a [`FlowTape`], in order: `L`, `∂L/∂ω`, `∂L/∂γ`, the upper triangle
/// of `J = ∂²L/∂ω²` row by row, then `N = ∂²L/∂ω∂γ` row by row (`N[i][j] = ∂²L/∂ω_i∂γ_j`).
pub const FLOW_OUTPUTS: [&str; 22] = [
    "lagrangian",
    "dl_domega[0]",
    "dl_domega[1]",
    "dl_domega[2]",
    "dl_dgamma[0]",
    "dl_dgamma[1]",
    "dl_dgamma[2]",
    "d2l_domega2[0][0]",
    "d2l_domega2[0][1]",
    "d2l_domega2[0][2]",
    "d2l_domega2[1][1]",
    "d2l_domega2[1][2]",
    "d2l_domega2[2][2]",
    "d2l_domega_dgamma[0][0]",
    "d2l_domega_dgamma[0][1]",
    "d2l_domega_dgamma[0][2]",
    "d2l_domega_dgamma[1][0]",
    "d2l_domega_dgamma[1][1]",
    "d2l_domega_dgamma[1][2]",
    "d2l_domega_dgamma[2][0]",
    "d2l_domega_dgamma[2][1]",
    "d2l_domega_dgamma[2][2]",
];

/// The gradient and the (symmetric) Hessian of `R(0, ·, p_ψ)` in γ.
pub type GradHess<T> = ([T; 3], [[T; 3]; 3]);

/// Checks that `tape` has exactly the outputs `names` and reads `params.len()` parameters.
fn check_shape(tape: &Tape, names: &[&'static str], params: &[f64]) -> Result<(), TapeError> {
    if params.len() != tape.num_params() {
        return Err(TapeError::ParamCount {
            want: tape.num_params(),
            got: params.len(),
        });
    }
    let got: Vec<&str> = tape.outputs().iter().map(|o: &Output| o.name).collect();
    match names.iter().zip(&got).find(|(n, g)| n != g) {
        Some((n, _)) => Err(TapeError::MissingOutput { name: n }),
        None if got.len() != names.len() => Err(TapeError::MissingOutput {
            name: names
                .get(got.len())
                .copied()
                .unwrap_or("(none: too many outputs)"),
        }),
        None => Ok(()),
    }
}

/// `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0` of a model, its parameter values bound: what
/// `Routhian::certification_tape` returns and the certified search evaluates with intervals
/// over boxes of the sphere. The outputs are [`CERTIFICATION_OUTPUTS`].
#[derive(Clone, PartialEq, Debug)]
pub struct CertificationTape {
    tape: Tape,
    params: Vec<f64>,
}

impl CertificationTape {
    /// Binds `params` to a tape whose outputs are [`CERTIFICATION_OUTPUTS`].
    pub fn new(tape: Tape, params: Vec<f64>) -> Result<Self, TapeError> {
        check_shape(&tape, &CERTIFICATION_OUTPUTS, &params)?;
        Ok(CertificationTape { tape, params })
    }

    /// The tape.
    pub fn tape(&self) -> &Tape {
        &self.tape
    }

    /// Number of operations.
    pub fn len(&self) -> usize {
        self.tape.len()
    }

    /// Whether the tape has no operations.
    pub fn is_empty(&self) -> bool {
        self.tape.is_empty()
    }

    /// `∂R/∂γ` and `∂²R/∂γ²` at `(Ω = 0, γ, p_ψ)`, evaluated with `T`; `scratch` is reused
    /// between calls.
    pub fn eval<T: TapeScalar>(
        &self,
        gamma: [T; 3],
        p_psi: T,
        scratch: &mut Vec<T>,
    ) -> GradHess<T> {
        let zero = T::from_f64(0.0);
        let inputs = Inputs {
            omega: [zero; 3],
            gamma,
            p_psi,
        };
        let mut o = [zero; 9];
        self.tape.eval(&inputs, &self.params, scratch, &mut o);
        let (h00, h01, h02, h11, h12, h22) = (o[3], o[4], o[5], o[6], o[7], o[8]);
        (
            [o[0], o[1], o[2]],
            [[h00, h01, h02], [h01, h11, h12], [h02, h12, h22]],
        )
    }
}

/// The Routh function `R(Ω, γ, p_ψ)` of (14) of a model as a tape, its parameter values bound:
/// what `Routhian::routh_tape` returns, for analyses that need derivatives beyond the Hessian
/// (evaluate it with a Taylor-jet scalar to get third and fourth derivatives).
///
/// The tape is the derive's own expression of `R`, general in all of its arguments: `Ω`, `γ`
/// (as an unconstrained vector of ℝ³, as when the derive differentiates) and `p_ψ` are inputs,
/// and nothing assumes `Ω = 0` or `|γ| = 1`. Its single output is [`ROUTHIAN_OUTPUT`].
///
/// ```
/// use routh_tape::{Op, Output, RouthianTape, Tape};
/// // R = k · Ω₀ · γ₂ + p_ψ, with the parameter k bound to 2.
/// let t = Tape::new(
///     vec![Op::Param(0), Op::Omega(0), Op::Mul(0, 1), Op::Gamma(2), Op::Mul(2, 3), Op::PPsi, Op::Add(4, 5)],
///     vec![Output { name: "routhian", slot: 6 }],
///     1,
/// ).unwrap();
/// let r = RouthianTape::new(t, vec![2.0]).unwrap();
/// assert_eq!(r.routhian::<f64>(&[1.5, 0.0, 0.0], &[0.0, 0.0, 3.0], 0.25), 9.25);
/// ```
#[derive(Clone, PartialEq, Debug)]
pub struct RouthianTape {
    tape: Tape,
    params: Vec<f64>,
}

impl RouthianTape {
    /// Binds `params` to a tape whose single output is [`ROUTHIAN_OUTPUT`].
    pub fn new(tape: Tape, params: Vec<f64>) -> Result<Self, TapeError> {
        check_shape(&tape, &[ROUTHIAN_OUTPUT], &params)?;
        Ok(RouthianTape { tape, params })
    }

    /// The tape (its parameters are [`RouthianTape::params`]).
    pub fn tape(&self) -> &Tape {
        &self.tape
    }

    /// The bound parameter values, in the order of the tape's [`crate::Op::Param`]s.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// `R(Ω, γ, p_ψ)` evaluated with `S` (allocates its working storage; see
    /// [`RouthianTape::routhian_with`] to reuse it).
    pub fn routhian<S: TapeScalar>(&self, big_omega: &[S; 3], gamma: &[S; 3], p_psi: S) -> S {
        self.routhian_with(big_omega, gamma, p_psi, &mut Vec::new())
    }

    /// [`RouthianTape::routhian`] with working storage `slots` reused between calls.
    pub fn routhian_with<S: TapeScalar>(
        &self,
        big_omega: &[S; 3],
        gamma: &[S; 3],
        p_psi: S,
        slots: &mut Vec<S>,
    ) -> S {
        let inputs = Inputs {
            omega: *big_omega,
            gamma: *gamma,
            p_psi,
        };
        let mut out = [p_psi];
        self.tape.eval(&inputs, &self.params, slots, &mut out);
        out[0]
    }
}

/// `L(ω, γ)` and the derivatives the equations (8) are made of, at one state: what a
/// [`FlowTape`] evaluates.
#[derive(Clone, Copy, PartialEq, Debug)]
pub struct FlowTerms<S> {
    /// `L`.
    pub lagrangian: S,
    /// `∂L/∂ω`.
    pub dl_domega: [S; 3],
    /// `∂L/∂γ`.
    pub dl_dgamma: [S; 3],
    /// `J = ∂²L/∂ω²` (symmetric).
    pub d2l_domega2: [[S; 3]; 3],
    /// `N[i][j] = ∂²L/∂ω_i∂γ_j`.
    pub d2l_domega_dgamma: [[S; 3]; 3],
}

/// The Lagrangian `L(ω, γ)` of a model and the derivatives its full equations (8) are made of,
/// as one tape with the parameter values bound: what `Lagrangian::flow_tape` returns, for
/// analyses that evaluate the flow of (8) at Taylor jets (jets of the flow in its initial
/// conditions; Taylor coefficients in time). Its outputs are [`FLOW_OUTPUTS`]; `ω` is
/// [`crate::Op::Omega`], `γ` [`crate::Op::Gamma`] (an unconstrained vector of ℝ³).
#[derive(Clone, PartialEq, Debug)]
pub struct FlowTape {
    tape: Tape,
    params: Vec<f64>,
}

impl FlowTape {
    /// Binds `params` to a tape whose outputs are [`FLOW_OUTPUTS`].
    pub fn new(tape: Tape, params: Vec<f64>) -> Result<Self, TapeError> {
        check_shape(&tape, &FLOW_OUTPUTS, &params)?;
        Ok(FlowTape { tape, params })
    }

    /// The tape (its parameters are [`FlowTape::params`]).
    pub fn tape(&self) -> &Tape {
        &self.tape
    }

    /// The bound parameter values, in the order of the tape's [`crate::Op::Param`]s.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The terms at `(ω, γ)` evaluated with `S`, working storage `slots` reused between calls.
    pub fn eval<S: TapeScalar>(
        &self,
        omega: &[S; 3],
        gamma: &[S; 3],
        slots: &mut Vec<S>,
    ) -> FlowTerms<S> {
        let zero = S::from_f64(0.0);
        let inputs = Inputs {
            omega: *omega,
            gamma: *gamma,
            p_psi: zero,
        };
        let mut out = [zero; 22];
        self.tape.eval(&inputs, &self.params, slots, &mut out);
        let j = |i: usize| out[7 + i];
        FlowTerms {
            lagrangian: out[0],
            dl_domega: [out[1], out[2], out[3]],
            dl_dgamma: [out[4], out[5], out[6]],
            d2l_domega2: [[j(0), j(1), j(2)], [j(1), j(3), j(4)], [j(2), j(4), j(5)]],
            d2l_domega_dgamma: [
                [out[13], out[14], out[15]],
                [out[16], out[17], out[18]],
                [out[19], out[20], out[21]],
            ],
        }
    }
}
