//! Run control of long analyses: cancellation from another thread and progress ([`RunControl`]).

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::RouthError;

/// How far a long analysis is: `done` of `total` units (orbits of a family, orbits of a
/// section).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Units finished.
    pub done: usize,
    /// Units asked for (a budget: a family may end before it).
    pub total: usize,
}

/// A progress callback.
type OnProgress = Arc<dyn Fn(Progress) + Send + Sync>;

/// Run control of long analyses: a cancel flag that another thread sets (a Ctrl-C handler, a
/// GUI's button) and a progress callback, carried in an analysis' options
/// ([`OrbitOptions::control`](crate::OrbitOptions::control),
/// [`SectionOptions::control`](crate::SectionOptions::control)).
///
/// The integrator looks at the flag before every step, so an analysis stops within one step of
/// the flag being set (microseconds to milliseconds). A family then ends with
/// [`OrbitStop::Interrupted`](crate::OrbitStop::Interrupted), keeping the orbits it has; an
/// analysis with no partial result returns [`RouthError::Interrupted`].
///
/// ```
/// use std::sync::{atomic::AtomicBool, Arc};
/// use routh_core::{OrbitOptions, RunControl};
/// let cancel = Arc::new(AtomicBool::new(false));
/// let opts = OrbitOptions {
///     control: RunControl::default()
///         .with_cancel(cancel.clone())
///         .with_progress(|p| eprintln!("{} of {}", p.done, p.total)),
///     ..OrbitOptions::default()
/// };
/// // Another thread (a Ctrl-C handler) may now call `cancel.store(true, Ordering::SeqCst)`.
/// # let _ = opts;
/// ```
///
/// `Default` has neither flag nor callback: the analysis runs to its end, silently. Cloning
/// shares the flag and the callback.
#[derive(Clone, Default)]
pub struct RunControl {
    cancel: Option<Arc<AtomicBool>>,
    progress: Option<OnProgress>,
}

impl RunControl {
    /// With the cancel flag `flag`: once it is true, the analysis stops.
    pub fn with_cancel(mut self, flag: Arc<AtomicBool>) -> Self {
        self.cancel = Some(flag);
        self
    }

    /// With `f` called as the analysis progresses (from the analysis' threads).
    pub fn with_progress(mut self, f: impl Fn(Progress) + Send + Sync + 'static) -> Self {
        self.progress = Some(Arc::new(f));
        self
    }

    /// Whether the caller has asked the analysis to stop.
    pub fn is_cancelled(&self) -> bool {
        self.cancel
            .as_ref()
            .is_some_and(|c| c.load(Ordering::Relaxed))
    }

    /// `Err(RouthError::Interrupted)` once the caller has asked the analysis to stop.
    pub(crate) fn check(&self) -> Result<(), RouthError> {
        if self.is_cancelled() {
            Err(RouthError::Interrupted)
        } else {
            Ok(())
        }
    }

    /// The same cancel flag without the progress callback: for the parts of an analysis that
    /// report their progress as a whole (the families of an orbit chart).
    pub(crate) fn cancel_only(&self) -> RunControl {
        RunControl {
            cancel: self.cancel.clone(),
            progress: None,
        }
    }

    /// Reports `done` of `total`.
    pub(crate) fn report(&self, done: usize, total: usize) {
        if let Some(f) = &self.progress {
            f(Progress { done, total });
        }
    }
}

impl fmt::Debug for RunControl {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RunControl")
            .field(
                "cancel",
                &self.cancel.as_ref().map(|c| c.load(Ordering::Relaxed)),
            )
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

/// Run control is not a setting of the analysis: two options that differ in it alone are equal.
impl PartialEq for RunControl {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;

    /// The flag is read through every clone, and progress reaches the callback.
    #[test]
    fn a_clone_sees_the_flag_and_reports_progress() {
        let flag = Arc::new(AtomicBool::new(false));
        let seen = Arc::new(AtomicUsize::new(0));
        let s = seen.clone();
        let c = RunControl::default()
            .with_cancel(flag.clone())
            .with_progress(move |p| s.store(p.done * 100 + p.total, Ordering::SeqCst));
        let d = c.clone();
        assert!(d.check().is_ok());
        flag.store(true, Ordering::SeqCst);
        assert!(matches!(d.check(), Err(RouthError::Interrupted)));
        d.report(3, 7);
        assert_eq!(seen.load(Ordering::SeqCst), 307);
        assert!(!RunControl::default().is_cancelled());
    }
}
