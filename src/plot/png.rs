//! [`png_from_svg`]: a figure as PNG at a chosen width, rasterised from its SVG (feature `png`).

use std::path::Path;

use super::frame::write_whole;
use super::PlotError;

/// Writes the SVG figure `svg` (a file this module wrote, or any SVG) as a PNG `width` pixels
/// wide (the height in proportion), rasterised by resvg with the system's fonts (DejaVu Sans,
/// the style's family, where it is installed; another sans-serif otherwise). A journal column
/// of 3.5 in at 600 dpi is 2100 pixels. The PNG is written whole or not at all. PDF is not
/// offered: it would need a PDF writer of its own (convert the SVG, e.g. `rsvg-convert -f pdf`).
///
/// # Errors
///
/// [`PlotError::InvalidOptions`] for a width of 0 or over 20 000 pixels,
/// [`PlotError::InvalidData`] for a file that is not an SVG, [`PlotError::Io`] if a file cannot
/// be read or written.
///
/// ```
/// use routh::plot::{png_from_svg, stability_atlas_svg, PlotOptions};
/// use routh::{Stability, StabilityAtlas};
///
/// let x: Vec<f64> = (0..=4).map(|i| i as f64).collect();
/// let verdicts = vec![vec![Some(Stability::SecularlyStable); 5]; 5];
/// let atlas = StabilityAtlas { x: x.clone(), y: x, verdicts, ..Default::default() };
/// let svg = std::env::temp_dir().join("routh-doc-png.svg");
/// stability_atlas_svg(&atlas, &svg, &PlotOptions::default())?;
/// let png = svg.with_extension("png");
/// png_from_svg(&svg, &png, 1050)?;
/// assert!(std::fs::read(&png)?.starts_with(b"\x89PNG"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn png_from_svg<P: AsRef<Path>, Q: AsRef<Path>>(
    svg: P,
    png: Q,
    width: u32,
) -> Result<(), PlotError> {
    use resvg::{tiny_skia, usvg};
    if width == 0 || width > 20_000 {
        return Err(PlotError::InvalidOptions(format!(
            "a PNG {width} pixels wide (1 to 20 000)"
        )));
    }
    let data = std::fs::read(svg.as_ref())?;
    let mut opt = usvg::Options::default();
    // "sans-serif" (the SVGs' family) is the style's family where the system has it.
    let family = crate::style::FONT.family;
    opt.font_family = family.to_string();
    let db = opt.fontdb_mut();
    db.load_system_fonts();
    db.set_sans_serif_family(family);
    let tree = usvg::Tree::from_data(&data, &opt)
        .map_err(|e| PlotError::InvalidData(format!("not an SVG: {e}")))?;
    let size = tree.size();
    let scale = width as f32 / size.width();
    let height = (size.height() * scale).ceil().max(1.0) as u32;
    let mut pixmap = tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| PlotError::InvalidOptions(format!("a PNG of {width} × {height}")))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    let bytes = pixmap
        .encode_png()
        .map_err(|e| PlotError::Drawing(e.to_string()))?;
    write_whole(png.as_ref(), &bytes)
}
