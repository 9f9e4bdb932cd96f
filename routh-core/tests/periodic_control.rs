//! Run control of the periodic analyses (`OrbitOptions::control`, `SectionOptions::control`):
//! a cancel flag set from the progress callback at a known point (no timing) ends a family with
//! `OrbitStop::Interrupted` and the orbits it had, keeps them right (the pendulum's period in
//! closed form), and ends a section or a single correction with `RouthError::Interrupted`.
//! Ctrl-C in the CLI and in Python are checked in their own tests.

use crate::common::{elliptic_k, hanging, heavy_body as body};
use routh_core::{
    continue_orbit, lyapunov_family, periodic_orbit, poincare_section, OrbitOptions, OrbitStop,
    RouthError, RunControl, SectionOptions, Vector3,
};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// A run control whose flag the progress callback sets once `done` reaches `at`; the progress
/// reports seen are counted.
fn stop_at(at: usize) -> (RunControl, Arc<AtomicUsize>) {
    let flag = Arc::new(AtomicBool::new(false));
    let seen = Arc::new(AtomicUsize::new(0));
    let (f, s) = (flag.clone(), seen.clone());
    let control = RunControl::default()
        .with_cancel(flag)
        .with_progress(move |p| {
            s.fetch_add(1, Ordering::SeqCst);
            if p.done >= at {
                f.store(true, Ordering::SeqCst);
            }
        });
    (control, seen)
}

/// The planar swings of `J = diag(1, 2, 3)`, `mgl = 1.5` about `e₁`: a family asked for 60
/// orbits, stopped when it has 5, ends `Interrupted` with those 5, each the pendulum of its
/// amplitude (period `4K(sin²(θ₀/2))/ω₀`, θ₀ from the energy `−mgl cos θ₀`).
#[test]
fn a_family_stopped_by_its_caller_keeps_its_orbits() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let (control, seen) = stop_at(5);
    let opts = OrbitOptions {
        control,
        ..OrbitOptions::default().with_max_orbits(60)
    };
    let f = lyapunov_family(&m, &hanging(&m, 0.0), 0, &opts).unwrap();
    assert_eq!(f.stop, Some(OrbitStop::Interrupted));
    assert_eq!(f.orbits.len(), 6, "the first orbit and 5 more");
    assert!(seen.load(Ordering::SeqCst) >= 6);
    let w0 = 1.5f64.sqrt();
    for o in &f.orbits {
        let theta0 = (-o.energy / 1.5).acos();
        let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / w0;
        assert!(
            (o.period - exact).abs() < 1e-8 * exact,
            "{} vs {exact}",
            o.period
        );
    }
    // Continued from its last orbit without the flag, the family goes on past it.
    let last = f.orbits.last().unwrap();
    let on = continue_orbit(
        &m,
        last,
        (-1.5, last.energy + 0.3),
        &OrbitOptions::default().with_max_orbits(10),
    )
    .unwrap();
    assert!(on.orbits.iter().any(|o| o.energy > last.energy + 0.05));
}

/// A flag already set: the correction of one orbit and a section stop with `Interrupted`
/// (nothing to keep), the family with no orbit past its first.
#[test]
fn a_flag_set_before_the_start_stops_at_once() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let flag = Arc::new(AtomicBool::new(true));
    let control = RunControl::default().with_cancel(flag);
    let opts = OrbitOptions {
        control: control.clone(),
        ..OrbitOptions::default()
    };
    let g = Vector3::new(0.0, 0.5f64.sin(), -0.5f64.cos());
    let e = periodic_orbit(&m, Vector3::zeros(), g, 5.0, &opts).unwrap_err();
    assert!(matches!(e, RouthError::Interrupted), "{e:?}");
    let s = SectionOptions {
        control,
        ..SectionOptions::default().with_size(100, 1_000)
    };
    let e = poincare_section(&m, 0.0, -1.0, &s).unwrap_err();
    assert!(matches!(e, RouthError::Interrupted), "{e:?}");
}

/// A section stopped by its caller after 3 of its 40 orbits: an error (a section is all its
/// orbits or none), and every orbit reported before.
#[test]
fn a_section_stopped_by_its_caller_is_interrupted() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let (control, seen) = stop_at(3);
    let s = SectionOptions {
        control,
        ..SectionOptions::default().with_size(40, 400)
    };
    let e = poincare_section(&m, 0.0, -1.0, &s).unwrap_err();
    assert!(matches!(e, RouthError::Interrupted), "{e:?}");
    assert!(seen.load(Ordering::SeqCst) >= 3);
}
