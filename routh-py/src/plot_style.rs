//! `plot_style()`: the one style of routh's figures (`routh::style`), for the matplotlib figures
//! of `routh._plot`, so that the Python package keeps no second copy of it.

use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The style of routh's figures as a dict: `style[group][name]` is a dict of `label`, `color`
/// (`#RRGGBB`), `width` (points), `dash` ((on, off) in points, or None: solid), `marker`
/// (matplotlib's letter, `"O"` an open circle), `fill` and `hatch` (atlas regions) for the groups
/// "verdict", "event", "boundary", "orbit_verdict", "orbit_event" and "reference"; `style["font"]`
/// the family and sizes (points), `style["column_width"]` a journal column's width in inches,
/// `style["palette"]` the colours of several orbits drawn together.
///
/// >>> routh.plot_style()["verdict"]["unstable"]["color"]
/// '#D55E00'
#[pyfunction]
pub fn plot_style(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let out = PyDict::new(py);
    for l in routh::style::STYLE {
        let group = match out.get_item(l.group)? {
            Some(g) => g.cast_into::<PyDict>()?,
            None => {
                let g = PyDict::new(py);
                out.set_item(l.group, &g)?;
                g
            }
        };
        let d = PyDict::new(py);
        d.set_item("label", l.label)?;
        d.set_item("color", l.color)?;
        d.set_item("width", l.width_pt)?;
        d.set_item("dash", l.dash_pt)?;
        d.set_item("marker", l.marker)?;
        d.set_item("fill", l.fill)?;
        d.set_item("hatch", l.hatch)?;
        group.set_item(l.name, d)?;
    }
    let f = routh::style::FONT;
    let font = PyDict::new(py);
    font.set_item("family", f.family)?;
    font.set_item("tick", f.tick_pt)?;
    font.set_item("label", f.label_pt)?;
    font.set_item("legend", f.legend_pt)?;
    font.set_item("annotation", f.annotation_pt)?;
    font.set_item("title", f.title_pt)?;
    out.set_item("font", font)?;
    out.set_item("column_width", routh::style::COLUMN_WIDTH_IN)?;
    out.set_item("palette", routh::style::PALETTE.to_vec())?;
    Ok(out)
}
