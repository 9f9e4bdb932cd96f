//! Labels beside markers, placed so that no two overlap and none covers a marker: each label
//! tries positions around its marker, nearest first, then farther out on a short leader line.

use super::curve::Px;

/// A pixel rectangle `[x0, x1] × [y0, y1]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Rect {
    pub(super) x0: i32,
    pub(super) y0: i32,
    pub(super) x1: i32,
    pub(super) y1: i32,
}

impl Rect {
    fn overlaps(&self, o: &Rect, margin: i32) -> bool {
        self.x0 < o.x1 + margin
            && o.x0 < self.x1 + margin
            && self.y0 < o.y1 + margin
            && o.y0 < self.y1 + margin
    }

    fn inside(&self, o: &Rect) -> bool {
        self.x0 >= o.x0 && self.x1 <= o.x1 && self.y0 >= o.y0 && self.y1 <= o.y1
    }

    /// The box of a marker of half-size `r` at `c`.
    pub(super) fn around(c: Px, r: i32) -> Rect {
        Rect {
            x0: c.0 - r,
            y0: c.1 - r,
            x1: c.0 + r,
            y1: c.1 + r,
        }
    }
}

/// A label placed: its text's box (the text is written at its top-left corner) and whether it
/// stands away from its marker (a leader line joins them).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Placed {
    pub(super) anchor: Px,
    pub(super) text: String,
    pub(super) rect: Rect,
    pub(super) leader: bool,
}

/// The width of `text` in pixels at a font of `size` pixels (a generous average advance of a
/// sans-serif font, 0.6 em, so that the estimate does not fall short).
pub(super) fn text_width(text: &str, size: f64) -> i32 {
    (0.6 * size * text.chars().count() as f64).ceil() as i32
}

/// Places each `(anchor, text)` label of a font `size` pixels high inside `area`, clear of the
/// `markers` and of the labels placed before it, and where it can be, of the `curves` (points
/// along the drawn lines). Labels with the same text at (nearly) the same anchor — the two
/// mirror images of a symmetric event — are written once.
pub(super) fn place(
    labels: &[(Px, String)],
    markers: &[Rect],
    curves: &[Px],
    area: Rect,
    size: f64,
) -> Vec<Placed> {
    let h = size.ceil() as i32 + 2;
    let mut placed: Vec<Placed> = Vec::new();
    for (c, text) in labels {
        if placed.iter().any(|p| {
            &p.text == text && (p.anchor.0 - c.0).abs() <= 3 && (p.anchor.1 - c.1).abs() <= 3
        }) {
            continue;
        }
        let w = text_width(text, size);
        let free = |r: &Rect, strict: bool| {
            r.inside(&area)
                && !placed.iter().any(|p| p.rect.overlaps(r, 2))
                && !markers.iter().any(|m| m.overlaps(r, 1))
                && (!strict
                    || !curves.iter().any(|&(x, y)| {
                        x >= r.x0 - 1 && x <= r.x1 + 1 && y >= r.y0 - 1 && y <= r.y1 + 1
                    }))
        };
        // Top-left corners of the box at distance `d` around the marker: right-above,
        // right-below, left-above, left-below, right, left, above, below.
        let at = |d: i32| -> [Px; 8] {
            let (x, y) = *c;
            [
                (x + d, y - d - h),
                (x + d, y + d),
                (x - d - w, y - d - h),
                (x - d - w, y + d),
                (x + d + 2, y - h / 2),
                (x - d - 2 - w, y - h / 2),
                (x - w / 2, y - d - h - 2),
                (x - w / 2, y + d + 2),
            ]
        };
        let rect = |(x, y): Px| Rect {
            x0: x,
            y0: y,
            x1: x + w,
            y1: y + h,
        };
        let mut chosen = None;
        // Clear of the curves if it can be, else over them; near the marker if it can be, else
        // the free place of the area nearest it (scanned on a grid of rows).
        for strict in [true, false] {
            'rings: for (ring, d) in [8, 20, 36, 56, 80].into_iter().enumerate() {
                for p in at(d) {
                    let r = rect(p);
                    if free(&r, strict) {
                        chosen = Some((r, ring > 0));
                        break 'rings;
                    }
                }
            }
            if chosen.is_some() {
                break;
            }
            let mut best: Option<(i64, Rect)> = None;
            let mut y = area.y0;
            while y + h <= area.y1 {
                let mut x = area.x0;
                while x + w <= area.x1 {
                    let r = rect((x, y));
                    if free(&r, strict) {
                        let (dx, dy) = ((x + w / 2 - c.0) as i64, (y + h / 2 - c.1) as i64);
                        let d = dx * dx + dy * dy;
                        if best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, r));
                        }
                    }
                    x += 6;
                }
                y += 4;
            }
            // Far from the marker over a curve beats farther still.
            if let Some((d, r)) = best {
                if !strict || d < 160 * 160 {
                    chosen = Some((r, true));
                    break;
                }
            }
        }
        // Nowhere free (more text than room): beside the marker all the same.
        let (rect, leader) = chosen.unwrap_or((rect(at(8)[0]), false));
        placed.push(Placed {
            anchor: *c,
            text: text.clone(),
            rect,
            leader,
        });
    }
    placed
}

/// A value for a label: four significant digits, without trailing zeros.
pub(super) fn value(x: f64) -> String {
    let digits = (3 - x.abs().max(1e-300).log10().floor() as i32).clamp(0, 12) as usize;
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    s.replacen('-', "−", 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    const AREA: Rect = Rect {
        x0: 0,
        y0: 0,
        x1: 600,
        y1: 400,
    };

    #[test]
    fn crowded_labels_do_not_overlap_each_other_or_the_markers() {
        // Ten events within 30 pixels: the old stacking put them in one column.
        let labels: Vec<(Px, String)> = (0..10)
            .map(|k| ((300 + 3 * k, 200 + (k % 3)), format!("branch point {k}")))
            .collect();
        let markers: Vec<Rect> = labels.iter().map(|l| Rect::around(l.0, 7)).collect();
        let placed = place(&labels, &markers, &[], AREA, 15.0);
        assert_eq!(placed.len(), 10);
        for (i, a) in placed.iter().enumerate() {
            assert!(a.rect.inside(&AREA));
            for b in &placed[i + 1..] {
                assert!(!a.rect.overlaps(&b.rect, 0), "{a:?} {b:?}");
            }
            for m in &markers {
                assert!(!a.rect.overlaps(m, 0), "{a:?} {m:?}");
            }
        }
        // The first sits right by its marker; later ones farther out, on leaders.
        assert!(!placed[0].leader);
        assert!(placed.iter().any(|p| p.leader));
    }

    #[test]
    fn values_have_four_significant_digits() {
        assert_eq!(value(2.23606797), "2.236");
        assert_eq!(value(-0.5), "−0.5");
        assert_eq!(value(1234.5678), "1235");
        assert_eq!(value(0.000123456), "0.0001235");
    }

    #[test]
    fn a_label_keeps_off_the_curves_where_it_can() {
        // A horizontal line through the marker and a vertical one: the label goes in a quadrant.
        let c = (300, 200);
        let curves: Vec<Px> = (0..600)
            .map(|x| (x, 200))
            .chain((0..400).map(|y| (300, y)))
            .collect();
        let placed = place(
            &[(c, "fold".into())],
            &[Rect::around(c, 7)],
            &curves,
            AREA,
            15.0,
        );
        let r = placed[0].rect;
        assert!(r.x1 < 300 || r.x0 > 300, "{r:?}");
        assert!(r.y1 < 200 || r.y0 > 200, "{r:?}");
    }

    #[test]
    fn mirror_images_are_named_once() {
        let labels = vec![
            ((100, 100), "fold".to_string()),
            ((101, 100), "fold".to_string()),
        ];
        assert_eq!(place(&labels, &[], &[], AREA, 15.0).len(), 1);
    }
}
