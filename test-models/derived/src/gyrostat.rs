//! Paper Example 1: a heavy body about a fixed point with gyroscopic forces,
//! `L = ½(Iω, ω) + (a(γ), ω) − U(γ)` (35), with `a(γ) = K + Bγ` and `U = m g (r_c, γ)`. Its
//! twin is [`test_models::Gyrostat`]; it is also the bench model M1 (generic: full symmetric I,
//! K, general B).

use routh::{Lagrangian, Matrix3, Vector3};

use crate::num;

model! { GYROSTAT_SRC:
    /// A heavy gyrostat with `a(γ) = rotor + coupling·γ` (35): `rotor = K` is the Kelvin gyrostat's
    /// constant rotor momentum, `coupling = B` the field-dependent part `a(γ) = Bγ`.
    #[derive(Lagrangian, Debug, Clone)]
    #[lagrangian(
        kinetic = 0.5 * omega.dot(inertia * omega),
        linear = (rotor + coupling * gamma).dot(omega),
        potential = mass * g * com.dot(gamma),
    )]
    pub struct Gyrostat {
        /// Inertia tensor `I` about the fixed point (symmetric: only its upper triangle is read).
        #[lagrangian(symmetric)]
        #[lagrangian(latex = "I")]
        pub inertia: Matrix3<f64>,
        /// Constant part `K` of `a(γ)` (the rotor's momentum).
        pub rotor: Vector3<f64>,
        /// Linear part `B` of `a(γ) = K + Bγ`.
        pub coupling: Matrix3<f64>,
        /// Centre of mass `r_c` in the body frame.
        pub com: Vector3<f64>,
        /// Mass `m`.
        pub mass: f64,
        /// Gravity `g`.
        pub g: f64,
    }
}

impl From<&test_models::Gyrostat> for Gyrostat {
    fn from(m: &test_models::Gyrostat) -> Self {
        Gyrostat {
            inertia: m.inertia,
            rotor: m.rotor,
            coupling: m.coupling,
            com: m.com,
            mass: m.mass,
            g: m.g,
        }
    }
}

/// The runtime property test's family over the weight: `g` scaled by `s`, as for the twin.
impl test_models::runtime_properties::Model for Gyrostat {
    fn scaled(&self, s: f64) -> Self {
        Gyrostat {
            g: self.g * s,
            ..self.clone()
        }
    }
}

impl Gyrostat {
    /// A Kelvin gyrostat, `a = K`: an asymmetric heavy body (`I = diag(2, 2.5, 1.5)`, centre of
    /// mass on `e₃` at `l = 0.1`, `m = 1`, `g = 9.81`) carrying a rotor of momentum
    /// `K = 3.5 e₃` along the axis through the centre of mass.
    pub fn kelvin() -> Self {
        Gyrostat {
            inertia: Matrix3::from_diagonal(&Vector3::new(2.0, 2.5, 1.5)),
            rotor: Vector3::new(0.0, 0.0, 3.5),
            coupling: Matrix3::zeros(),
            com: Vector3::new(0.0, 0.0, 0.1),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// The same body with `a(γ) = Bγ`, `B` not symmetric: only its symmetric part enters the
    /// amended potential (40) through `(Bγ, γ)`; its skew part acts through the gyroscopic forces
    /// only.
    pub fn coupled() -> Self {
        Gyrostat {
            rotor: Vector3::zeros(),
            coupling: Matrix3::new(1.0, 0.8, 0.0, -0.8, 0.4, 0.0, 0.0, 0.0, 2.0),
            ..Gyrostat::kelvin()
        }
    }

    /// `m g l` for a centre of mass on the `e₃` axis at `l = com₃`.
    pub fn mgl(&self) -> f64 {
        self.mass * self.g * self.com.z
    }

    /// The Kelvin gyrostat at rest upright (`γ = e₃`, `ω = 0`, so `p_ψ = K₃` and `ψ̇ = 0`) with
    /// `K = K₃e₃`, the centre of mass above the fixed point: linearising `Iω̇ = K × ω + torque`
    /// with `θ̈ᵢ` the small tilts gives `I₁θ̈₁ + K₃θ̇₂ − mglθ₁ = 0`, `I₂θ̈₂ − K₃θ̇₁ − mglθ₂ = 0`,
    /// `I₁I₂λ⁴ + (K₃² − (I₁ + I₂)mgl)λ² + (mgl)² = 0`: all roots imaginary iff
    /// `K₃² − (I₁ + I₂)mgl > 2√(I₁I₂) mgl`, i.e. `|K₃| > √(mgl)(√I₁ + √I₂)`.
    pub fn rest_rotor_threshold(&self) -> f64 {
        self.mgl().sqrt() * (self.inertia[(0, 0)].sqrt() + self.inertia[(1, 1)].sqrt())
    }

    /// `(a(γ), γ) = (K, γ) + (Bγ, γ)`.
    pub fn a_dot_gamma(&self, gamma: &Vector3<f64>) -> f64 {
        (self.rotor + self.coupling * gamma).dot(gamma)
    }

    /// The amended potential (40) evaluated from its closed form,
    /// `U_r = ½(p_ψ − (a(γ), γ))²/(Iγ, γ) + U(γ)`, independently of the derive.
    pub fn amended_potential_closed_form(&self, gamma: &Vector3<f64>, p_psi: f64) -> f64 {
        let q = p_psi - self.a_dot_gamma(gamma);
        0.5 * q * q / gamma.dot(&(self.inertia * gamma)) + self.mass * self.g * self.com.dot(gamma)
    }

    /// The amended potential (40) of this gyrostat as a formula in `γ₁, γ₂, γ₃` and `p_ψ`, built
    /// from the model's numbers.
    pub fn amended_potential_formula(&self) -> String {
        let sym = 0.5 * (self.coupling + self.coupling.transpose());
        let mut a_lin = linear_form(&self.rotor);
        let a_quad = quadratic_form(&sym);
        let a_gamma = match (a_lin.as_str(), a_quad.as_str()) {
            ("0", q) => q.to_string(),
            (_, "0") => std::mem::take(&mut a_lin),
            (l, q) => format!("{l} + {q}"),
        };
        let a_gamma = a_gamma.replace("+ -", "− ");
        let numerator = if a_gamma == "0" {
            "p_ψ²".to_string()
        } else {
            format!("(p_ψ − ({a_gamma}))²")
        };
        let inertia = quadratic_form(&self.inertia);
        let potential = linear_form(&(self.mass * self.g * self.com));
        format!("U_r(γ; p_ψ) = ½ {numerator} / ({inertia}) + {potential}").replace("+ -", "− ")
    }
}

const SUB: [&str; 3] = ["₁", "₂", "₃"];

/// `Σ vᵢγᵢ` as text, zero terms left out.
fn linear_form(v: &Vector3<f64>) -> String {
    let terms: Vec<String> = (0..3)
        .filter(|&i| v[i] != 0.0)
        .map(|i| format!("{}γ{}", num(v[i], 6), SUB[i]))
        .collect();
    if terms.is_empty() {
        "0".into()
    } else {
        terms.join(" + ")
    }
}

/// `γᵀSγ` for a symmetric `S` as text, zero terms left out.
fn quadratic_form(s: &Matrix3<f64>) -> String {
    let mut terms = Vec::new();
    for i in 0..3 {
        if s[(i, i)] != 0.0 {
            terms.push(format!("{}γ{}²", num(s[(i, i)], 6), SUB[i]));
        }
    }
    for i in 0..3 {
        for j in i + 1..3 {
            let c = s[(i, j)] + s[(j, i)];
            if c != 0.0 {
                terms.push(format!("{}γ{}γ{}", num(c, 6), SUB[i], SUB[j]));
            }
        }
    }
    if terms.is_empty() {
        "0".into()
    } else {
        terms.join(" + ")
    }
}
