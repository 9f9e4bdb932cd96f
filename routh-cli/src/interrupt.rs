//! Ctrl-C: the first sets the cancel flag that the analyses' [`RunControl`] reads (a family
//! ends with what it has, a section stops), and the run ends with exit code 130 and no file
//! written; an analysis that does not read the flag is ended 0.5 s later, and a second Ctrl-C
//! ends the run at once.

use routh::RunControl;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};
use std::time::Duration;

/// The exit code of a run ended by Ctrl-C (128 + SIGINT, as a shell reports it).
pub const EXIT_INTERRUPTED: i32 = 130;

/// How long an analysis has to stop after the first Ctrl-C.
const GRACE: Duration = Duration::from_millis(500);

fn flag() -> &'static Arc<AtomicBool> {
    static FLAG: OnceLock<Arc<AtomicBool>> = OnceLock::new();
    FLAG.get_or_init(|| Arc::new(AtomicBool::new(false)))
}

/// Installs the handler (once, at the start of `main`). A handler that cannot be installed
/// leaves Ctrl-C to the default action (the process ends at once), which loses nothing either.
pub fn install() {
    let _ = ctrlc::set_handler(|| {
        if flag().swap(true, Ordering::SeqCst) {
            end();
        }
        std::thread::spawn(|| {
            std::thread::sleep(GRACE);
            end();
        });
    });
}

/// Whether Ctrl-C was pressed.
pub fn requested() -> bool {
    flag().load(Ordering::SeqCst)
}

/// The run control of the analyses of this run: cancelled by Ctrl-C.
pub fn control() -> RunControl {
    RunControl::default().with_cancel(flag().clone())
}

/// Ends the run: interrupted.
pub fn end() -> ! {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "error: interrupted");
    std::process::exit(EXIT_INTERRUPTED)
}
