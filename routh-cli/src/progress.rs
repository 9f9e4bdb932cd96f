//! A spinner on stderr for the longer analyses (diagrams, atlases, certificates): the library
//! reports no fractional progress, so it shows what runs and for how long. Hidden when stderr is
//! not a terminal (indicatif's `ProgressDrawTarget::stderr`), cleared when dropped.

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
