//! [`with_circle_verdicts`]: the branches of circles of steady motions with the verdict of
//! [`classify_circle`] (stability modulo the symmetry), for the figures to draw.

use crate::{classify_circle, BifurcationDiagram, CircleStability, Routhian, Stability, Vector3};

/// The diagram with each point of each branch of circles of steady motions (`isolated ==
/// false`) given the verdict of [`classify_circle`] about `axis` in place of
/// [`classify`](crate::classify)'s, which is [`Stability::Degenerate`] all along a circle (its
/// tangent is a null direction of the second variation). A circle stable modulo the symmetry
/// (the doubly amended potential at a minimum across it) is drawn as
/// [`Stability::SecularlyStable`], an unstable one as [`Stability::Unstable`]; where the test is
/// inconclusive, or cannot be made (γ along the axis: the branch point where the circle leaves
/// an isolated motion), the point keeps its verdict. `family` is the family the diagram was
/// computed from. Isolated branches and the events are as they were.
///
/// ```
/// use routh::plot::{bifurcation_diagram_svg, with_circle_verdicts, PlotOptions};
/// use routh::{bifurcation_diagram, ContinuationOptions, Lagrangian, Stability, Vector3};
///
/// /// A heavy symmetric (Lagrange) top: its tilted steady motions form circles about e₃.
/// #[derive(Lagrangian, Clone)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let top = Top { inertia: Vector3::new(1.0, 1.0, 1.25), mgl: 1.0 };
/// let coarse = ContinuationOptions { seeds: 2, verify_counts: false, max_step: 0.1, ..Default::default() };
/// let family = |p: f64| (top.clone(), p);
/// let diagram = bifurcation_diagram(family, (0.0, 5.0), &coarse)?;
/// let circles = |d: &routh::BifurcationDiagram| -> Vec<Stability> {
///     d.branches.iter().filter(|b| !b.isolated).flat_map(|b| b.points.iter().map(|p| p.report.verdict)).collect()
/// };
/// let count = |vs: Vec<Stability>, v: Stability| vs.iter().filter(|&&u| u == v).count();
/// // classify: degenerate along the tilted circles (past their first point, the branch point).
/// let n = circles(&diagram).len();
/// assert!(count(circles(&diagram), Stability::Degenerate) >= n - 1);
/// let drawn = with_circle_verdicts(&diagram, family, Vector3::z());
/// // classify_circle: the tilted circles beyond the branch point are stable modulo the symmetry.
/// assert!(count(circles(&drawn), Stability::SecularlyStable) >= n - 2);
/// let path = std::env::temp_dir().join("routh-doc-circle-verdicts.svg");
/// bifurcation_diagram_svg(&drawn, &path, &PlotOptions { x_label: "p_ψ".into(), ..PlotOptions::default() })?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn with_circle_verdicts<M, F>(
    diagram: &BifurcationDiagram,
    family: F,
    axis: Vector3<f64>,
) -> BifurcationDiagram
where
    M: Routhian,
    F: Fn(f64) -> (M, f64),
{
    let mut out = diagram.clone();
    for branch in out.branches.iter_mut().filter(|b| !b.isolated) {
        for p in &mut branch.points {
            let (model, _) = family(p.s);
            if let Ok(circle) = classify_circle(&model, &p.steady, &axis) {
                match circle.verdict {
                    CircleStability::Stable => p.report.verdict = Stability::SecularlyStable,
                    CircleStability::Unstable => p.report.verdict = Stability::Unstable,
                    CircleStability::Degenerate => {}
                }
            }
        }
    }
    out
}
