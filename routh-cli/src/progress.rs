//! Progress on stderr: a bar for the analyses that report it through their run control (orbit
//! families, sections), a spinner for the others (diagrams, atlases, certificates), which show
//! what runs and for how long. Hidden when stderr is not a terminal (indicatif's
//! `ProgressDrawTarget::stderr`), cleared when dropped.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::time::Duration;

/// A running spinner; clears itself when dropped (on success and on error alike).
pub struct Spinner(ProgressBar);

impl Spinner {
    /// Starts a spinner showing `message` and the elapsed time.
    pub fn start(message: &str) -> Spinner {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        let style = ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner());
        bar.set_style(style);
        bar.set_message(message.to_string());
        bar.enable_steady_tick(Duration::from_millis(120));
        Spinner(bar)
    }
}

impl Drop for Spinner {
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}

/// A bar on stderr for an analysis that reports its progress through its [`routh::RunControl`]
/// (orbits of a section, orbits of a family): `done/total` and the time left. Hidden when stderr
/// is not a terminal, cleared when dropped.
pub struct Bar(ProgressBar);

impl Bar {
    /// Starts a bar showing `message`, its length set by the first report.
    pub fn start(message: &str) -> Bar {
        let bar = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr());
        let style =
            ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} ({elapsed}, {eta} left)")
                .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style.progress_chars("=> "));
        bar.set_message(message.to_string());
        Bar(bar)
    }

    /// The run control of this run (Ctrl-C) reporting its progress to this bar.
    pub fn control(&self) -> routh::RunControl {
        let bar = self.0.clone();
        crate::interrupt::control().with_progress(move |p| {
            bar.set_length(p.total as u64);
            bar.set_position(p.done as u64);
        })
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}
