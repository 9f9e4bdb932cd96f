//! The files a run writes, all or none: each is written to a temporary file beside it and the
//! temporaries are renamed over their targets only once every file of the run is written. A
//! run that fails leaves every existing file as it was (the temporaries are removed); every
//! error names the file.

use crate::error::CliError;
use std::path::{Path, PathBuf};

/// The files of one run, written to temporaries until [`Outputs::commit`].
#[derive(Default)]
pub struct Outputs {
    /// `(temporary, target)`, in the order they were written.
    staged: Vec<(PathBuf, PathBuf)>,
}

impl Outputs {
    pub fn new() -> Self {
        Self::default()
    }

    /// Writes `target` through `write`, which is given the temporary path to write to.
    pub fn write<E: std::fmt::Display>(
        &mut self,
        target: &Path,
        write: impl FnOnce(&Path) -> Result<(), E>,
    ) -> Result<(), CliError> {
        let tmp = temporary_beside(target);
        // Recorded before writing, so that a temporary written in part is removed too.
        self.staged.push((tmp.clone(), target.to_path_buf()));
        write(&tmp)
            .map_err(|e| CliError::Compute(format!("cannot write {}: {e}", target.display())))
    }

    /// Renames every temporary over its target.
    pub fn commit(mut self) -> Result<(), CliError> {
        while !self.staged.is_empty() {
            let (tmp, target) = &self.staged[0];
            std::fs::rename(tmp, target).map_err(|e| {
                CliError::Compute(format!("cannot write {}: {e}", target.display()))
            })?;
            self.staged.remove(0);
        }
        Ok(())
    }
}

impl Drop for Outputs {
    /// Removes the temporaries not renamed (a failed run).
    fn drop(&mut self) {
        for (tmp, _) in &self.staged {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// `dir/.name.routh-PID.tmp` beside `target` (the same file system, so that the rename is
/// atomic).
fn temporary_beside(target: &Path) -> PathBuf {
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    let tmp = format!(".{name}.routh-{}.tmp", std::process::id());
    match target.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.join(tmp),
        _ => PathBuf::from(tmp),
    }
}
