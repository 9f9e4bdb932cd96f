//! [`ModelError`]: what is wrong with a model's text, where.

use std::fmt;

/// An error in a model's text or parameters, with its position: `line` and `column` (both from
/// 1, columns counted in characters) in the model's text — the Lagrangian for
/// [`Model::new`](crate::Model::new), the TOML source for
/// [`Model::from_toml`](crate::Model::from_toml) — and that line of text, shown with a caret by
/// `Display`:
///
/// ```text
/// error: unknown name `mas`: …
///  --> line 3, column 17
///   |
/// 3 |     potential = mas * g * com.dot(gamma),
///   |                 ^^^
/// ```
///
/// An error about no particular place (a missing file, a parameter set by
/// [`Model::set`](crate::Model::set)) is at line 1, column 1.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ModelError {
    /// What is wrong (the derive's own message for a mistake in the Lagrangian).
    pub message: String,
    /// The line, from 1.
    pub line: usize,
    /// The column, from 1, in characters.
    pub column: usize,
    /// How many characters the caret underlines (at least 1).
    pub width: usize,
    /// The line of text the error is on (empty if there is none).
    pub source_line: String,
    /// Further errors found in the same pass (the derive reports every mistake at once).
    pub others: Vec<ModelError>,
}

impl ModelError {
    /// An error at `(line, column)` of `text` (both from 1), underlining `width` characters.
    pub(crate) fn at(
        message: impl Into<String>,
        text: &str,
        line: usize,
        column: usize,
        width: usize,
    ) -> ModelError {
        let line = line.max(1);
        let source_line = text.lines().nth(line - 1).unwrap_or("").to_string();
        ModelError {
            message: message.into(),
            line,
            column: column.max(1),
            width: width.max(1),
            source_line,
            others: Vec::new(),
        }
    }

    /// An error about no particular place (line 1, column 1, no source line).
    pub(crate) fn general(message: impl Into<String>) -> ModelError {
        ModelError {
            message: message.into(),
            line: 1,
            column: 1,
            width: 1,
            source_line: String::new(),
            others: Vec::new(),
        }
    }

    /// An error at byte offset `offset` of `text`, underlining the bytes up to `end`.
    pub(crate) fn at_byte(
        message: impl Into<String>,
        text: &str,
        offset: usize,
        end: usize,
    ) -> Self {
        let (line, column) = line_column(text, offset);
        let (end_line, end_column) = line_column(text, end.max(offset));
        let width = if end_line == line {
            end_column.saturating_sub(column)
        } else {
            1
        };
        ModelError::at(message, text, line, column, width)
    }

    /// What is wrong.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// The line, from 1.
    pub fn line(&self) -> usize {
        self.line
    }

    /// The column, from 1 (characters).
    pub fn column(&self) -> usize {
        self.column
    }

    /// Shifts the position by a text that starts at `(line, column)` of a larger one (the
    /// Lagrangian inside a TOML file), re-reading the source line from `outer`.
    pub(crate) fn shifted(mut self, outer: &str, line: usize, column: usize) -> ModelError {
        if self.line == 1 {
            self.column += column - 1;
        }
        self.line += line - 1;
        self.source_line = outer.lines().nth(self.line - 1).unwrap_or("").to_string();
        self.others = self
            .others
            .into_iter()
            .map(|e| e.shifted(outer, line, column))
            .collect();
        self
    }
}

/// `(line, column)` from 1, in characters, of byte `offset` of `text` (clamped to the text, and
/// to a character boundary).
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[start..].chars().count() + 1)
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_one(f, self)?;
        for e in &self.others {
            writeln!(f)?;
            write_one(f, e)?;
        }
        Ok(())
    }
}

fn write_one(f: &mut fmt::Formatter<'_>, e: &ModelError) -> fmt::Result {
    write!(
        f,
        "error: {}\n --> line {}, column {}",
        e.message, e.line, e.column
    )?;
    if !e.source_line.is_empty() {
        let n = e.line.to_string();
        let pad = " ".repeat(n.len());
        // Tabs are kept so that the caret lines up under them.
        let lead: String = e
            .source_line
            .chars()
            .take(e.column - 1)
            .map(|c| if c == '\t' { '\t' } else { ' ' })
            .collect();
        write!(
            f,
            "\n{pad} |\n{n} | {}\n{pad} | {lead}{}",
            e.source_line,
            "^".repeat(e.width)
        )?;
    }
    Ok(())
}

impl std::error::Error for ModelError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_column_counts_characters() {
        let t = "ab\nγδ x\n";
        assert_eq!(line_column(t, 0), (1, 1));
        assert_eq!(line_column(t, 3), (2, 1));
        // 'x' is after two 2-byte characters and a space.
        assert_eq!(line_column(t, t.find('x').unwrap()), (2, 4));
        assert_eq!(line_column(t, 1000), (3, 1));
    }

    #[test]
    fn display_shows_the_line_and_a_caret() {
        let e = ModelError::at("bad", "first\n  second line", 2, 3, 6);
        let s = e.to_string();
        assert!(s.contains("line 2, column 3"), "{s}");
        assert!(s.contains("2 |   second line\n  |   ^^^^^^"), "{s}");
    }
}
