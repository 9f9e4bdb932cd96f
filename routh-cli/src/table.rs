//! Tables aligned for a terminal: a header and rows of cells, each column as wide as its
//! widest cell, numbers right-aligned.

/// A table being built.
pub struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with these column names.
    pub fn new(header: &[&str]) -> Table {
        Table {
            header: header.iter().map(|s| s.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Adds a row (as many cells as the header).
    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }

    /// The table as text, one line per row, columns separated by two spaces.
    pub fn render(&self) -> String {
        let n = self.header.len();
        let mut width = vec![0; n];
        for r in std::iter::once(&self.header).chain(&self.rows) {
            for (w, c) in width.iter_mut().zip(r) {
                *w = (*w).max(c.chars().count());
            }
        }
        let mut out = String::new();
        for r in std::iter::once(&self.header).chain(&self.rows) {
            let cells: Vec<String> = r
                .iter()
                .zip(&width)
                .map(|(c, &w)| {
                    let pad = w - c.chars().count();
                    if c.parse::<f64>().is_ok() {
                        format!("{}{c}", " ".repeat(pad))
                    } else {
                        format!("{c}{}", " ".repeat(pad))
                    }
                })
                .collect();
            out.push_str(cells.join("  ").trim_end());
            out.push('\n');
        }
        out
    }
}

/// A number in a fixed, readable form (`+1.234568e-01`).
pub fn num(x: f64) -> String {
    format!("{x:+.6e}")
}

/// A vector as `(x, y, z)` with six decimals.
pub fn vec3(v: &routh::Vector3<f64>) -> String {
    format!("({:+.6}, {:+.6}, {:+.6})", v.x, v.y, v.z)
}
