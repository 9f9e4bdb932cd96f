//! The regions of a stability atlas, clipped to its traced boundaries: each pixel of the axes
//! takes the verdict of the nearest grid node that it can reach without crossing a boundary curve
//! (of the four nodes around it), so that the shading follows the traced curves rather than the
//! stair steps of the grid's cells. The regions are painted as rows of rectangles and their
//! patterns (dots, hatching, cross-hatching) are laid over them on a lattice global in pixels,
//! clipped to each region.

use plotters::prelude::*;

use super::labels::Rect;
use super::marks::{Px, Root};
use super::style::{cell_fill, Pattern, HATCH_INK, HATCH_SPACING, VERDICTS};
use super::{drawing_error, PlotError};
use crate::{Stability, StabilityAtlas};

/// A segment of a boundary curve, in data coordinates.
type Segment = ((f64, f64), (f64, f64));

/// The code of "no verdict" in [`Regions::codes`].
const NONE: u8 = VERDICTS.len() as u8;

/// The verdict of each pixel of the axes.
pub(super) struct Regions {
    rect: Rect,
    w: usize,
    /// Row-major, `w` a row: an index into [`VERDICTS`], or [`NONE`].
    codes: Vec<u8>,
}

fn code(v: Option<Stability>) -> u8 {
    v.and_then(|v| VERDICTS.iter().position(|&u| u == v))
        .map_or(NONE, |k| k as u8)
}

/// `+1`, `0` or `−1`: the side of `c` from the line `a → b`.
/// A point within a relative 1e−9 of the line counts as on it (`0`): a grid node on a traced
/// boundary is then cut off from both sides, rather than from one by rounding.
fn orient(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    let (u, v) = ((b.0 - a.0, b.1 - a.1), (c.0 - a.0, c.1 - a.1));
    let cross = u.0 * v.1 - u.1 * v.0;
    if cross.abs() <= 1e-9 * u.0.hypot(u.1) * v.0.hypot(v.1) {
        0.0
    } else {
        cross.signum()
    }
}

/// Whether the segments `p q` and `a b` meet (touching counts).
fn crosses(p: (f64, f64), q: (f64, f64), a: (f64, f64), b: (f64, f64)) -> bool {
    let (o1, o2) = (orient(p, q, a), orient(p, q, b));
    let (o3, o4) = (orient(a, b, p), orient(a, b, q));
    o1 * o2 <= 0.0 && o3 * o4 <= 0.0 && !(o1 == 0.0 && o2 == 0.0)
}

/// The cell `i` of the grid `nodes` holding `t` (`nodes[i] ≤ t ≤ nodes[i + 1]`, clamped).
fn cell(nodes: &[f64], t: f64) -> usize {
    nodes
        .partition_point(|&v| v <= t)
        .saturating_sub(1)
        .min(nodes.len().saturating_sub(2))
}

impl Regions {
    /// The regions over the pixel rectangle `rect` of the axes, `to_data` mapping a pixel's
    /// centre to data coordinates. The grid is checked by the caller.
    pub(super) fn new(
        atlas: &StabilityAtlas,
        rect: Rect,
        to_data: impl Fn(f64, f64) -> (f64, f64),
    ) -> Regions {
        let (x, y) = (&atlas.x, &atlas.y);
        let (nx, ny) = (x.len(), y.len());
        let (cx, cy) = (nx.saturating_sub(1).max(1), ny.saturating_sub(1).max(1));
        // The boundary segments met by each cell of the grid.
        let mut buckets: Vec<Vec<Segment>> = vec![Vec::new(); cx * cy];
        if nx > 1 && ny > 1 {
            for curve in &atlas.boundaries {
                for s in curve.points.windows(2) {
                    let (a, b) = (s[0], s[1]);
                    if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
                        continue;
                    }
                    let (i0, i1) = (cell(x, a.0.min(b.0)), cell(x, a.0.max(b.0)));
                    let (j0, j1) = (cell(y, a.1.min(b.1)), cell(y, a.1.max(b.1)));
                    for j in j0..=j1 {
                        for i in i0..=i1 {
                            buckets[j * cx + i].push((a, b));
                        }
                    }
                }
            }
        }
        let verdict = |i: usize, j: usize| code(atlas.verdicts[j][i]);
        let w = (rect.x1 - rect.x0).max(0) as usize;
        let h = (rect.y1 - rect.y0).max(0) as usize;
        let mut codes = vec![NONE; w * h];
        for r in 0..h {
            for c in 0..w {
                let p = to_data(
                    f64::from(rect.x0) + c as f64 + 0.5,
                    f64::from(rect.y0) + r as f64 + 0.5,
                );
                let (i, j) = (cell(x, p.0), cell(y, p.1));
                let (i1, j1) = ((i + 1).min(nx - 1), (j + 1).min(ny - 1));
                let corners = [(i, j), (i1, j), (i, j1), (i1, j1)];
                let first = verdict(i, j);
                codes[r * w + c] = if corners.iter().all(|&(a, b)| verdict(a, b) == first) {
                    first
                } else {
                    // Nearest first, in units of the cell's sides.
                    let (dx, dy) = ((x[i1] - x[i]).max(1e-300), (y[j1] - y[j]).max(1e-300));
                    let mut by_distance = corners;
                    let dist = |&(a, b): &(usize, usize)| {
                        ((p.0 - x[a]) / dx).powi(2) + ((p.1 - y[b]) / dy).powi(2)
                    };
                    by_distance.sort_by(|m, n| dist(m).total_cmp(&dist(n)));
                    let crossings = |&(a, b): &(usize, usize)| -> usize {
                        let node = (x[a], y[b]);
                        // The cells the segment p → node may pass through.
                        let (ia, ib) = (i.min(a).min(cx - 1), i.max(a).min(cx - 1));
                        let (ja, jb) = (j.min(b).min(cy - 1), j.max(b).min(cy - 1));
                        let mut n = 0;
                        for jj in ja..=jb {
                            for ii in ia..=ib {
                                n += buckets[jj * cx + ii]
                                    .iter()
                                    .filter(|&&(u, v)| crosses(p, node, u, v))
                                    .count();
                            }
                        }
                        n
                    };
                    // The nearest corner reachable without crossing a boundary; where a region
                    // is narrower than a cell and none is, the node within two cells across the
                    // fewest boundaries (the nearest of those).
                    let (a, b) = match by_distance.iter().copied().find(|n| crossings(n) == 0) {
                        Some(n) => n,
                        None => {
                            let mut best = (usize::MAX, f64::INFINITY, by_distance[0]);
                            for b in j.saturating_sub(2)..=(j + 3).min(ny - 1) {
                                for a in i.saturating_sub(2)..=(i + 3).min(nx - 1) {
                                    let key = (crossings(&(a, b)), dist(&(a, b)));
                                    if key.0 < best.0 || (key.0 == best.0 && key.1 < best.1) {
                                        best = (key.0, key.1, (a, b));
                                    }
                                }
                            }
                            best.2
                        }
                    };
                    verdict(a, b)
                };
            }
        }
        Regions { rect, w, codes }
    }

    /// The verdicts with at least `min` pixels.
    pub(super) fn shown(&self, min: usize) -> Vec<Stability> {
        let mut count = [0usize; VERDICTS.len() + 1];
        for &c in &self.codes {
            count[c as usize] += 1;
        }
        VERDICTS
            .iter()
            .zip(count)
            .filter(|&(_, n)| n >= min)
            .map(|(&v, _)| v)
            .collect()
    }

    fn at(&self, px: i32, py: i32) -> u8 {
        let (c, r) = ((px - self.rect.x0) as usize, (py - self.rect.y0) as usize);
        self.codes[r * self.w + c]
    }

    fn pattern(&self, px: i32, py: i32, mono: bool) -> Pattern {
        match self.at(px, py) {
            NONE => Pattern::Plain,
            k => cell_fill(VERDICTS[k as usize], mono).1,
        }
    }

    /// The runs `(first column, past the last, code)` of row `r`.
    fn runs(&self, r: usize) -> Vec<(usize, usize, u8)> {
        let row = &self.codes[r * self.w..(r + 1) * self.w];
        let mut out = Vec::new();
        let mut start = 0;
        for c in 1..=row.len() {
            if c == row.len() || row[c] != row[start] {
                out.push((start, c, row[start]));
                start = c;
            }
        }
        out
    }

    /// Paints the regions: their tints as rectangles (rows of equal runs merged), then their
    /// patterns clipped to them.
    pub(super) fn paint(&self, root: &Root, mono: bool) -> Result<(), PlotError> {
        let h = self.codes.len() / self.w.max(1);
        let (x0, y0) = (self.rect.x0, self.rect.y0);
        let mut r0 = 0;
        while r0 < h {
            let runs = self.runs(r0);
            let mut r1 = r0 + 1;
            while r1 < h && self.runs(r1) == runs {
                r1 += 1;
            }
            for &(c0, c1, k) in &runs {
                if k != NONE {
                    let color = cell_fill(VERDICTS[k as usize], mono).0;
                    root.draw(&Rectangle::new(
                        [
                            (x0 + c0 as i32, y0 + r0 as i32),
                            // One pixel over into the next block (painted after), so that no
                            // seam of anti-aliasing shows between blocks.
                            (x0 + c1 as i32, y0 + (r1 + usize::from(r1 < h)) as i32),
                        ],
                        color.filled(),
                    ))
                    .map_err(drawing_error)?;
                }
            }
            r0 = r1;
        }
        self.paint_patterns(root, mono)
    }

    fn paint_patterns(&self, root: &Root, mono: bool) -> Result<(), PlotError> {
        const SP: i32 = HATCH_SPACING;
        let Rect { x0, y0, x1, y1 } = self.rect;
        let (x1, y1) = (x1 - 1, y1 - 1); // the last pixel
        if x1 < x0 || y1 < y0 {
            return Ok(());
        }
        let style = HATCH_INK.stroke_width(1);
        // Strokes the pixels of a line where `on` holds, in segments.
        let line = |pts: &mut dyn Iterator<Item = (i32, i32)>,
                    on: &dyn Fn(Pattern) -> bool|
         -> Result<(), PlotError> {
            let mut seg: Option<(Px, Px)> = None;
            let flush = |seg: &mut Option<(Px, Px)>| -> Result<(), PlotError> {
                if let Some((a, b)) = seg.take() {
                    if a != b {
                        root.draw(&PathElement::new(vec![a, b], style))
                            .map_err(drawing_error)?;
                    }
                }
                Ok(())
            };
            for p in pts {
                if on(self.pattern(p.0, p.1, mono)) {
                    seg = Some(seg.map_or((p, p), |(a, _)| (a, p)));
                } else {
                    flush(&mut seg)?;
                }
            }
            flush(&mut seg)
        };
        let hatched = |p: Pattern| matches!(p, Pattern::Hatch | Pattern::CrossHatch);
        // "/" lines: px + py = c.
        let c0 = (x0 + y0).div_euclid(SP) * SP;
        for c in (c0..=x1 + y1).step_by(SP as usize) {
            let (a, b) = ((c - y1).max(x0), (c - y0).min(x1));
            line(&mut (a..=b).map(|px| (px, c - px)), &hatched)?;
        }
        // "\" lines: px − py = c, where cross-hatched.
        let c0 = (x0 - y1).div_euclid(SP) * SP;
        for c in (c0..=x1 - y0).step_by(SP as usize) {
            let (a, b) = ((c + y0).max(x0), (c + y1).min(x1));
            line(&mut (a..=b).map(|px| (px, px - c)), &|p| {
                p == Pattern::CrossHatch
            })?;
        }
        // Dots: a staggered lattice.
        for py in (y0.div_euclid(SP) * SP..=y1).step_by(SP as usize) {
            if py < y0 {
                continue;
            }
            let off = if py.div_euclid(SP) % 2 == 0 {
                0
            } else {
                SP / 2
            };
            let start = (x0 - off).div_euclid(SP) * SP + off;
            for px in (start..=x1).step_by(SP as usize) {
                if px >= x0 && self.pattern(px, py, mono) == Pattern::Dots {
                    root.draw(&Circle::new((px, py), 1, HATCH_INK.filled()))
                        .map_err(drawing_error)?;
                }
            }
        }
        Ok(())
    }

    /// The verdict at a pixel (for tests): `None` outside the axes or where there is none.
    #[cfg(test)]
    fn verdict(&self, px: i32, py: i32) -> Option<Stability> {
        let inside =
            px >= self.rect.x0 && px < self.rect.x1 && py >= self.rect.y0 && py < self.rect.y1;
        inside
            .then(|| self.at(px, py))
            .filter(|&k| k != NONE)
            .map(|k| VERDICTS[k as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BoundaryCurve, EventKind};

    #[test]
    fn the_regions_follow_the_traced_boundary_not_the_cells() {
        // A coarse 5 × 5 grid on [0, 1]², stable above the line y = x + 0.1, unstable below;
        // the boundary traced exactly. Drawn on 400 × 400 pixels (y up).
        let g: Vec<f64> = (0..5).map(|k| k as f64 / 4.0).collect();
        let side = |x: f64, y: f64| y > x + 0.1;
        let verdicts = g
            .iter()
            .map(|&y| {
                g.iter()
                    .map(|&x| {
                        Some(if side(x, y) {
                            Stability::SecularlyStable
                        } else {
                            Stability::Unstable
                        })
                    })
                    .collect()
            })
            .collect();
        let atlas = StabilityAtlas {
            x: g.clone(),
            y: g.clone(),
            verdicts,
            boundaries: vec![BoundaryCurve {
                kind: EventKind::BranchPoint,
                points: (0..=90)
                    .map(|k| (k as f64 / 100.0, k as f64 / 100.0 + 0.1))
                    .collect(),
            }],
            ..Default::default()
        };
        let rect = Rect {
            x0: 0,
            y0: 0,
            x1: 400,
            y1: 400,
        };
        let to_data = |px: f64, py: f64| (px / 400.0, 1.0 - py / 400.0);
        let regions = Regions::new(&atlas, rect, to_data);
        // Every pixel farther than 2 px from the line is on its side of it: the nearest-node
        // rule alone gets a stair step wrong by up to half a cell (50 px).
        let mut wrong = 0;
        for py in 0..400 {
            for px in 0..400 {
                let (x, y) = to_data(px as f64 + 0.5, py as f64 + 0.5);
                if ((y - x - 0.1) / 2f64.sqrt()).abs() * 400.0 < 2.0 || y > 1.0 {
                    continue;
                }
                let want = if side(x, y) {
                    Stability::SecularlyStable
                } else {
                    Stability::Unstable
                };
                if regions.verdict(px, py) != Some(want) {
                    wrong += 1;
                }
            }
        }
        assert_eq!(wrong, 0);
    }
}
