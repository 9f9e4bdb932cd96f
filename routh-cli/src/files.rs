//! The files a run writes, all or none, through the one writer of routh
//! ([`routh::files::Staged`]): each figure is drawn in memory and staged (a temporary file
//! beside its target, written and flushed; a pipe or device is written last, in place), and
//! the temporaries are renamed over their targets only at [`Outputs::commit`], once every file
//! of the run is ready. A run that fails leaves every existing file as it was (the temporaries
//! are removed, a rename already done is undone); every error names the file.

use crate::error::CliError;
use routh::files::Staged;
use routh::plot::PlotError;
use std::path::Path;

/// The files of one run, staged until [`Outputs::commit`].
#[derive(Default)]
pub struct Outputs {
    staged: Staged,
}

impl Outputs {
    pub fn new() -> Self {
        Self::default()
    }

    /// Stages the figure that `draw` makes (a figure function of `routh::plot`, given a
    /// placeholder path) for `target`.
    pub fn write(
        &mut self,
        target: &Path,
        draw: impl FnOnce(&Path) -> Result<(), PlotError>,
    ) -> Result<(), CliError> {
        let bytes = routh::plot::rendered(draw)?;
        self.staged.write(target, &bytes).map_err(written)
    }

    /// Puts every staged file in place (all or none).
    pub fn commit(self) -> Result<(), CliError> {
        self.staged.commit().map_err(written)
    }
}

/// A write error (its message names the file: `cannot write PATH: REASON`): a failed run.
fn written(e: std::io::Error) -> CliError {
    CliError::Compute(e.to_string())
}
