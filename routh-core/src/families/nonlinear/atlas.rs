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
    analyse_with_tape, frequencies_only, indicator_kind, indicators, locate_crossing, needs_tape,
    Solved,
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

/// The grid of an atlas with its followed steady motions, for the nonlinear curves.
struct Grid<'a, F> {
    family: &'a F,
    xs: &'a [f64],
    ys: &'a [f64],
    opts: &'a NonlinearOptions,
}

/// The crossings of one indicator on one row of edges: `h[j][i]` on the edge
/// `(i, j)–(i + 1, j)`, `v[j][i]` on `(i, j)–(i, j + 1)`.
type EdgeRow = Vec<Option<(f64, f64)>>;

/// The crossings of each indicator on the edges of one row of nodes: `(h, v)`, `v` `None` on
/// the top row.
type RowEdges = [(EdgeRow, Option<EdgeRow>); 3];

impl<F> Grid<'_, F> {
    /// The indicators at the gyroscopically stabilised nodes of row `j`.
    fn indicated_row<M: Routhian>(
        &self,
        j: usize,
        row: &[GridNode],
    ) -> Result<Vec<Indicated>, RouthError>
    where
        F: Fn(f64, f64) -> (M, f64),
    {
        let mut out = vec![None; self.xs.len()];
        for (i, node) in row.iter().enumerate().take(self.xs.len()) {
            let Some((gamma, Stability::GyroscopicallyStabilized)) = node else {
                continue;
            };
            let (model, p) = (self.family)(self.xs[i], self.ys[j]);
            let Ok(steady) = SteadyMotion::at(&model, *gamma, p, true) else {
                continue;
            };
            match analyse_with_tape(&model, &steady, self.opts) {
                Ok(rep) => out[i] = Some((steady.gamma, indicators(&rep))),
                Err(RouthError::NotASteadyMotion { .. }) => {}
                Err(e) => return Err(e),
            }
        }
        Ok(out)
    }

    /// The crossing of indicator `k` on the edge from node `a` to node `b` (`(i, j)` each), if
    /// any.
    fn crossing<M: Routhian>(
        &self,
        ind: &[Vec<Indicated>],
        a: (usize, usize),
        b: (usize, usize),
        k: usize,
    ) -> Option<(f64, f64)>
    where
        F: Fn(f64, f64) -> (M, f64),
    {
        let (ga, va) = ind[a.1][a.0]?;
        let (gb, vb) = ind[b.1][b.0]?;
        if va[k] * vb[k] >= 0.0 || va[k].is_nan() || vb[k].is_nan() {
            return None;
        }
        let (xs, ys) = (self.xs, self.ys);
        let (pa, pb) = ((xs[a.0], ys[a.1]), (xs[b.0], ys[b.1]));
        let lerp = |t: f64| (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1));
        let solve = |t: f64, guess: &Vector3<f64>, full: bool| -> Result<Solved, RouthError> {
            let (x, y) = lerp(t);
            let (model, p) = (self.family)(x, y);
            let steady = steady_motion_near(&model, *guess, p)?;
            let rep = if full {
                analyse_with_tape(&model, &steady, self.opts)?
            } else {
                frequencies_only(&model, &steady, &self.opts.classify)?
            };
            Ok((steady, rep))
        };
        let (t, _) = locate_crossing(
            &solve,
            k,
            (0.0, ga, va[k]),
            (1.0, gb, vb[k]),
            &|_| EDGE_TOL,
            false,
        )?;
        Some(lerp(t))
    }

    /// The crossings of each indicator on the edges of row `j`: rightwards from each node, and
    /// upwards unless `j` is the top row.
    fn edge_row<M: Routhian>(&self, ind: &[Vec<Indicated>], j: usize) -> RowEdges
    where
        F: Fn(f64, f64) -> (M, f64),
    {
        let nx = self.xs.len();
        let up = j + 1 < self.ys.len();
        [0, 1, 2].map(|k| {
            let h = (0..nx - 1)
                .map(|i| self.crossing(ind, (i, j), (i + 1, j), k))
                .collect();
            let v = up.then(|| {
                (0..nx)
                    .map(|i| self.crossing(ind, (i, j), (i, j + 1), k))
                    .collect()
            });
            (h, v)
        })
    }
}

/// Whether the family's model has a Routh-function tape, checked at the first gyroscopically
/// stabilised node (none: nothing to check).
fn check_tape<M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: &F,
    xs: &[f64],
    ys: &[f64],
    nodes: &[Vec<GridNode>],
) -> Result<(), RouthError> {
    for (j, row) in nodes.iter().enumerate().take(ys.len()) {
        for (i, node) in row.iter().enumerate().take(xs.len()) {
            if let Some((_, Stability::GyroscopicallyStabilized)) = node {
                return needs_tape(&family(xs[i], ys[j]).0, "AtlasOptions::nonlinear");
            }
        }
    }
    Ok(())
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
    curves_with(
        &Grid {
            family,
            xs,
            ys,
            opts,
        },
        nodes,
        |g| {
            (0..ys.len())
                .map(|j| g.indicated_row(j, &nodes[j]))
                .collect()
        },
        |g, ind| (0..ys.len()).map(|j| g.edge_row(ind, j)).collect(),
    )
}

/// [`atlas_curves`] with the rows of nodes and of edges on the current thread pool (that of
/// [`stability_atlas_parallel`](crate::stability_atlas_parallel)): the same result, bit for bit,
/// each crossing being located from its own edge's ends alone.
pub(crate) fn atlas_curves_parallel<M: Routhian, F: Fn(f64, f64) -> (M, f64) + Sync>(
    family: &F,
    xs: &[f64],
    ys: &[f64],
    nodes: &[Vec<GridNode>],
    opts: &NonlinearOptions,
) -> Result<Vec<NonlinearCurve>, RouthError> {
    use rayon::prelude::*;
    curves_with(
        &Grid {
            family,
            xs,
            ys,
            opts,
        },
        nodes,
        |g| {
            (0..ys.len())
                .into_par_iter()
                .map(|j| g.indicated_row(j, &nodes[j]))
                .collect()
        },
        |g, ind| {
            (0..ys.len())
                .into_par_iter()
                .map(|j| g.edge_row(ind, j))
                .collect()
        },
    )
}

/// The body of [`atlas_curves`] and [`atlas_curves_parallel`], the rows of the grid mapped by
/// `indicate` (the indicators at the nodes of each row) and then by `edges` (the crossings on
/// each row's edges), sequentially or in parallel.
fn curves_with<'a, M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    g: &Grid<'a, F>,
    nodes: &[Vec<GridNode>],
    indicate: impl FnOnce(&Grid<'a, F>) -> Result<Vec<Vec<Indicated>>, RouthError>,
    edges: impl FnOnce(&Grid<'a, F>, &[Vec<Indicated>]) -> Vec<RowEdges>,
) -> Result<Vec<NonlinearCurve>, RouthError> {
    g.opts.validate()?;
    check_tape(g.family, g.xs, g.ys, nodes)?;
    let ind = indicate(g)?;
    Ok(join(g.xs.len(), g.ys.len(), &edges(g, &ind)))
}

/// The curves from the crossings of each indicator `k` on the horizontal and vertical edges
/// (`edges[j][k]`, row by row), joined within the cells: two crossings by a segment, four (a
/// saddle) by two.
fn join(nx: usize, ny: usize, edges: &[RowEdges]) -> Vec<NonlinearCurve> {
    let mut curves = Vec::new();
    for k in 0..3 {
        let h: Vec<&EdgeRow> = edges.iter().map(|row| &row[k].0).collect();
        let v: Vec<&EdgeRow> = edges.iter().filter_map(|row| row[k].1.as_ref()).collect();
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
    curves
}
