//! The curves of the nonlinear test in a stability atlas, when
//! [`AtlasOptions::nonlinear`](crate::AtlasOptions::nonlinear) asks (docs/method.md §10.7): on the
//! gyroscopically stabilised part of the grid, where Arnold's determinant D vanishes and where
//! the frequencies are in 1:2 or 1:3 resonance.
//!
//! At every gyroscopically stabilised node the nonlinear test gives the three indicators of the
//! diagram's events (`D/scale`, `ω₁/ω₂ − 2`, `ω₁/ω₂ − 3`). Where one changes sign between two
//! neighbouring such nodes, the crossing on the grid edge is located (the same locator as the
//! diagram's events, the steady motion re-solved by Newton at each point) to `1e−9` of the edge;
//! a sign change of D through a pole is dropped. In each cell the crossings of one indicator on
//! its edges are joined: two by a segment, four (a saddle) by two segments.

use nalgebra::Vector3;

use super::events::{
    analyse_with_tape, indicator_kind, indicators, locate_crossing, needs_tape, Solved,
};
use crate::error::RouthError;
use crate::families::EventKind;
use crate::model::Routhian;
use crate::nonlinear::{NonlinearOptions, Resonance};
use crate::stability::Stability;
use crate::steady::{steady_motion_near, SteadyMotion};

/// The followed steady motion at a grid node: γ and the linear verdict, if it exists there.
pub(crate) type GridNode = Option<(Vector3<f64>, Stability)>;

/// γ and the three indicators at a gyroscopically stabilised node.
type Indicated = Option<(Vector3<f64>, [f64; 3])>;

/// Crossings are located to this fraction of their grid edge.
const EDGE_TOL: f64 = 1e-9;

/// A curve of the nonlinear test in a stability atlas: where, on gyroscopically stabilised
/// cells, Arnold's determinant vanishes ([`EventKind::ArnoldDegenerate`]) or the frequencies are
/// in 1:2 or 1:3 resonance ([`EventKind::Resonance`]).
///
/// ```
/// use routh_core::families::NonlinearCurve;
/// use routh_core::{EventKind, Resonance};
/// let c = NonlinearCurve {
///     kind: EventKind::Resonance,
///     resonance: Some(Resonance::OneToTwo),
///     crossings: vec![(0.5, 1.0), (0.6, 1.1)],
///     segments: vec![[(0.5, 1.0), (0.6, 1.1)]],
/// };
/// assert_eq!(c.label(), "1:2");
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NonlinearCurve {
    /// [`EventKind::ArnoldDegenerate`] or [`EventKind::Resonance`].
    pub kind: EventKind,
    /// Which resonance, for [`EventKind::Resonance`].
    pub resonance: Option<Resonance>,
    /// The points `(x, y)` where the curve crosses a grid edge between two gyroscopically
    /// stabilised nodes, each located to `1e−9` of its edge.
    pub crossings: Vec<(f64, f64)>,
    /// The crossings joined within the cells: the curve as segments `[(x, y), (x, y)]`.
    pub segments: Vec<[(f64, f64); 2]>,
}

impl NonlinearCurve {
    /// A short name: `"D = 0"`, `"1:2"` or `"1:3"`.
    pub fn label(&self) -> String {
        match self.resonance {
            Some(r) => r.to_string(),
            None => "D = 0".into(),
        }
    }
}

/// The nonlinear curves of an atlas: `nodes[j][i]` is the followed steady motion's γ and linear
/// verdict at `(xs[i], ys[j])`, if it exists there.
///
/// Errors: [`RouthError::InvalidModel`] for a model without a Routh-function tape (as soon as a
/// gyroscopically stabilised node is met), the errors of [`nonlinear_stability`] at a node
/// other than [`RouthError::NotASteadyMotion`] (next to a boundary curve, where the atlas
/// classified the node on its corrector's word; such a node is left out).
///
/// [`nonlinear_stability`]: crate::nonlinear::nonlinear_stability
pub(crate) fn atlas_curves<M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: &F,
    xs: &[f64],
    ys: &[f64],
    nodes: &[Vec<GridNode>],
    opts: &NonlinearOptions,
) -> Result<Vec<NonlinearCurve>, RouthError> {
    opts.validate()?;
    let (nx, ny) = (xs.len(), ys.len());
    // The indicators at the gyroscopically stabilised nodes.
    let mut ind: Vec<Vec<Indicated>> = vec![vec![None; nx]; ny];
    let mut checked = false;
    for (j, row) in nodes.iter().enumerate().take(ny) {
        for (i, node) in row.iter().enumerate().take(nx) {
            let Some((gamma, Stability::GyroscopicallyStabilized)) = node else {
                continue;
            };
            let (model, p) = family(xs[i], ys[j]);
            if !checked {
                needs_tape(&model, "AtlasOptions::nonlinear")?;
                checked = true;
            }
            let Ok(steady) = SteadyMotion::at(&model, *gamma, p, true) else {
                continue;
            };
            match analyse_with_tape(&model, &steady, opts) {
                Ok(rep) => ind[j][i] = Some((steady.gamma, indicators(&rep))),
                Err(RouthError::NotASteadyMotion { .. }) => {}
                Err(e) => return Err(e),
            }
        }
    }
    // The crossing of indicator k on the edge from node a to node b ((i, j) each), if any.
    let crossing = |a: (usize, usize), b: (usize, usize), k: usize| -> Option<(f64, f64)> {
        let (ga, va) = ind[a.1][a.0]?;
        let (gb, vb) = ind[b.1][b.0]?;
        if va[k] * vb[k] >= 0.0 || va[k].is_nan() || vb[k].is_nan() {
            return None;
        }
        let (pa, pb) = ((xs[a.0], ys[a.1]), (xs[b.0], ys[b.1]));
        let lerp = |t: f64| (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1));
        let solve = |t: f64, guess: &Vector3<f64>| -> Result<Solved, RouthError> {
            let (x, y) = lerp(t);
            let (model, p) = family(x, y);
            let steady = steady_motion_near(&model, *guess, p)?;
            let rep = analyse_with_tape(&model, &steady, opts)?;
            Ok((steady, rep))
        };
        let (t, _) = locate_crossing(&solve, k, (0.0, ga, va[k]), (1.0, gb, vb[k]), &|_| EDGE_TOL)?;
        Some(lerp(t))
    };
    let mut curves = Vec::new();
    for k in 0..3 {
        // h[j][i] on the edge (i, j)–(i + 1, j), v[j][i] on (i, j)–(i, j + 1).
        let h: Vec<Vec<Option<(f64, f64)>>> = (0..ny)
            .map(|j| {
                (0..nx - 1)
                    .map(|i| crossing((i, j), (i + 1, j), k))
                    .collect()
            })
            .collect();
        let v: Vec<Vec<Option<(f64, f64)>>> = (0..ny - 1)
            .map(|j| (0..nx).map(|i| crossing((i, j), (i, j + 1), k)).collect())
            .collect();
        let crossings: Vec<(f64, f64)> = h
            .iter()
            .chain(&v)
            .flat_map(|r| r.iter().flatten().copied())
            .collect();
        if crossings.is_empty() {
            continue;
        }
        let mut segments = Vec::new();
        for j in 0..ny - 1 {
            for i in 0..nx - 1 {
                // Around the cell: bottom, right, top, left.
                let on: Vec<(f64, f64)> = [h[j][i], v[j][i + 1], h[j + 1][i], v[j][i]]
                    .into_iter()
                    .flatten()
                    .collect();
                if on.len() == 2 || on.len() == 4 {
                    for pair in on.chunks(2) {
                        segments.push([pair[0], pair[1]]);
                    }
                }
            }
        }
        let (kind, resonance) = indicator_kind(k);
        curves.push(NonlinearCurve {
            kind,
            resonance,
            crossings,
            segments,
        });
    }
    Ok(curves)
}
