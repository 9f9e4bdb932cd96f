//! [`DiagramAxis`]: the scalar of a steady motion on the vertical axis of a bifurcation diagram.

use routh_core::Vector3;

#[cfg(doc)]
use super::{bifurcation_diagram_svg, PlotOptions};
use crate::SteadyMotion;

/// The scalar of a steady motion on the vertical axis of [`bifurcation_diagram_svg`].
///
/// ```
/// use routh::plot::{bifurcation_diagram_svg, DiagramAxis, PlotOptions};
/// use routh::{bifurcation_diagram, ContinuationOptions};
/// use routh::{Lagrangian, Vector3};
///
/// #[derive(Lagrangian, Clone)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
/// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
/// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 3.0), &coarse)?;
/// // The same branches seen through three scalars of their steady motions.
/// for y in [DiagramAxis::GammaZ, DiagramAxis::AmendedPotential, DiagramAxis::PsiDot] {
///     let path = std::env::temp_dir().join(format!("routh-doc-plot-axis-{y:?}.svg"));
///     bifurcation_diagram_svg(&diagram, &path, &PlotOptions { y, ..PlotOptions::default() })?;
///     assert!(std::fs::read_to_string(&path)?.contains(y.label()));
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DiagramAxis {
    /// `γ₃ = γ.z`, the cosine of the tilt of the body axis `e₃` from the vertical.
    #[default]
    GammaZ,
    /// `γ₁ = γ.x`.
    GammaX,
    /// `γ₂ = γ.y`.
    GammaY,
    /// The tilt, the angle between γ and `e₃`, in degrees.
    Tilt,
    /// The amended potential `U_r` (34).
    AmendedPotential,
    /// The energy `E` (3).
    Energy,
    /// The rate `ψ̇` of rotation about the vertical (38).
    PsiDot,
}

impl DiagramAxis {
    /// The value of this scalar at a steady motion.
    ///
    /// ```
    /// use routh::plot::DiagramAxis;
    /// use routh::{SteadyMotion, Vector3};
    ///
    /// let s = 0.5f64.sqrt();
    /// let m = SteadyMotion {
    ///     p_psi: 1.0, gamma: Vector3::new(s, 0.0, s), psi_dot: 2.0, mu: 0.0,
    ///     amended_potential: 3.0, energy: 3.0, isolated: true,
    /// };
    /// assert!((DiagramAxis::Tilt.value(&m) - 45.0).abs() < 1e-12);
    /// assert_eq!(DiagramAxis::PsiDot.value(&m), 2.0);
    /// ```
    pub fn value(self, steady: &SteadyMotion) -> f64 {
        match self {
            DiagramAxis::AmendedPotential => steady.amended_potential,
            DiagramAxis::Energy => steady.energy,
            DiagramAxis::PsiDot => steady.psi_dot,
            _ => self
                .of_gamma(&steady.gamma)
                .expect("the other axes are functions of γ"),
        }
    }

    /// The value of this scalar at the vertical γ, if it depends on γ alone.
    ///
    /// An event of a diagram is known by its parameter and its γ: [`bifurcation_diagram_svg`]
    /// puts it at this value where there is one, and interpolates along its branch otherwise.
    ///
    /// ```
    /// use routh::plot::DiagramAxis;
    /// use routh::{bifurcation_diagram, ContinuationOptions, EventKind};
    /// use routh::{Lagrangian, Vector3};
    ///
    /// #[derive(Lagrangian, Clone)]
    /// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
    /// struct Top { inertia: Vector3<f64>, mgl: f64 }
    ///
    /// let tilted = Vector3::new(0.6, 0.0, 0.8);
    /// assert_eq!(DiagramAxis::GammaZ.of_gamma(&tilted), Some(0.8));
    /// assert!((DiagramAxis::Tilt.of_gamma(&tilted).unwrap() - 0.6f64.asin().to_degrees()).abs() < 1e-12);
    /// assert_eq!(DiagramAxis::Energy.of_gamma(&tilted), None); // it depends on p_ψ too
    ///
    /// // The sleeping top (γ = e₃, no tilt) loses its secular stability at a branch point.
    /// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
    /// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
    /// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 3.0), &coarse)?;
    /// let bp = diagram.events.iter().find(|e| e.kind == EventKind::BranchPoint).unwrap();
    /// assert!(DiagramAxis::Tilt.of_gamma(&bp.gamma).unwrap() < 1e-3);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of_gamma(self, gamma: &Vector3<f64>) -> Option<f64> {
        match self {
            DiagramAxis::GammaZ => Some(gamma.z),
            DiagramAxis::GammaX => Some(gamma.x),
            DiagramAxis::GammaY => Some(gamma.y),
            DiagramAxis::Tilt => {
                let n = gamma.norm();
                Some((gamma.z / n).clamp(-1.0, 1.0).acos().to_degrees())
            }
            DiagramAxis::AmendedPotential | DiagramAxis::Energy | DiagramAxis::PsiDot => None,
        }
    }

    /// The default label of the axis: the vertical axis of a bifurcation diagram says this when
    /// [`PlotOptions::y_label`] is empty.
    ///
    /// ```
    /// use routh::plot::{bifurcation_diagram_svg, DiagramAxis, PlotOptions};
    /// use routh::{bifurcation_diagram, ContinuationOptions};
    /// use routh::{Lagrangian, Vector3};
    ///
    /// #[derive(Lagrangian, Clone)]
    /// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
    /// struct Top { inertia: Vector3<f64>, mgl: f64 }
    ///
    /// assert_eq!(DiagramAxis::Energy.label(), "energy E");
    ///
    /// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
    /// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
    /// let diagram = bifurcation_diagram(|p| (top.clone(), p), (0.0, 3.0), &coarse)?;
    /// let path = std::env::temp_dir().join("routh-doc-plot-label.svg");
    /// let by_default = PlotOptions { y: DiagramAxis::Energy, ..PlotOptions::default() };
    /// bifurcation_diagram_svg(&diagram, &path, &by_default)?;
    /// assert!(std::fs::read_to_string(&path)?.contains("energy E"));
    /// let named = PlotOptions { y_label: "E".into(), ..by_default };
    /// bifurcation_diagram_svg(&diagram, &path, &named)?;
    /// assert!(!std::fs::read_to_string(&path)?.contains("energy E"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn label(self) -> &'static str {
        match self {
            DiagramAxis::GammaZ => "γ₃ (cosine of the tilt)",
            DiagramAxis::GammaX => "γ₁",
            DiagramAxis::GammaY => "γ₂",
            DiagramAxis::Tilt => "tilt of e₃ from the vertical (degrees)",
            DiagramAxis::AmendedPotential => "amended potential U_r",
            DiagramAxis::Energy => "energy E",
            DiagramAxis::PsiDot => "ψ̇",
        }
    }
}
