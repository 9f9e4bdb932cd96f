//! Unit tests of the simulation drivers: input validation, zero-length runs, output times.

use super::*;
use crate::{Lagrangian, RouthError};
use nalgebra::{Matrix3, Vector3};

/// A torque-free asymmetric rigid body with a hand-written `L = ½ωᵀIω`.
struct Free {
    inertia: Matrix3<f64>,
}

impl Lagrangian for Free {
    fn lagrangian(&self, w: &Vector3<f64>, _g: &Vector3<f64>) -> f64 {
        0.5 * w.dot(&(self.inertia * w))
    }
    fn dl_domega(&self, w: &Vector3<f64>, _g: &Vector3<f64>) -> Vector3<f64> {
        self.inertia * w
    }
    fn dl_dgamma(&self, _w: &Vector3<f64>, _g: &Vector3<f64>) -> Vector3<f64> {
        Vector3::zeros()
    }
    fn d2l_domega2(&self, _g: &Vector3<f64>) -> Matrix3<f64> {
        self.inertia
    }
    fn d2l_domega_dgamma(&self, _w: &Vector3<f64>, _g: &Vector3<f64>) -> Matrix3<f64> {
        Matrix3::zeros()
    }
}

fn free() -> Free {
    Free {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
    }
}

#[test]
fn invalid_inputs_are_errors() {
    let m = free();
    let w = Vector3::new(1.0, 0.0, 0.0);
    let g = Vector3::z();
    let o = SimOptions::default();
    let nan = f64::NAN;
    assert!(matches!(
        simulate_full(&m, Vector3::new(nan, 0.0, 0.0), g, 1.0, &o),
        Err(RouthError::NonFinite { what: "omega0", .. })
    ));
    assert!(matches!(
        simulate_full(&m, w, Vector3::new(0.0, f64::INFINITY, 0.0), 1.0, &o),
        Err(RouthError::NonFinite { what: "gamma0", .. })
    ));
    assert!(matches!(
        simulate_full(&m, w, g, nan, &o),
        Err(RouthError::NonFinite { what: "t_end", .. })
    ));
    assert!(matches!(
        simulate_full(&m, w, g, -1.0, &o),
        Err(RouthError::InvalidOption { what: "t_end", .. })
    ));
    assert!(matches!(
        simulate_full(&m, w, g * 1.1, 1.0, &o),
        Err(RouthError::NonUnitGamma { .. })
    ));
    let bad = |o: SimOptions| simulate_full(&m, w, g, 1.0, &o);
    assert!(matches!(
        bad(SimOptions {
            rtol: 0.0,
            ..o.clone()
        }),
        Err(RouthError::InvalidOption { what: "rtol", .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            rtol: nan,
            ..o.clone()
        }),
        Err(RouthError::NonFinite { what: "rtol", .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            atol: -1.0,
            ..o.clone()
        }),
        Err(RouthError::InvalidOption { what: "atol", .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            rate_atol: Some(0.0),
            ..o.clone()
        }),
        Err(RouthError::InvalidOption {
            what: "rate_atol",
            ..
        })
    ));
    assert!(matches!(
        bad(SimOptions::lie_rk4(0.0)),
        Err(RouthError::InvalidOption { what: "step", .. })
    ));
    assert!(matches!(
        bad(SimOptions::lie_rk4(nan)),
        Err(RouthError::NonFinite { what: "step", .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            h_max: Some(0.0),
            ..o.clone()
        }),
        Err(RouthError::InvalidOption { what: "h_max", .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            max_steps: 0,
            ..o.clone()
        }),
        Err(RouthError::InvalidOption {
            what: "max_steps",
            ..
        })
    ));
    assert!(matches!(
        bad(o.clone().at_times(vec![0.5, 0.2])),
        Err(RouthError::InvalidOption { what: "output", .. })
    ));
    assert!(matches!(
        bad(o.clone().at_times(vec![0.5, 2.0])),
        Err(RouthError::InvalidOption { what: "output", .. })
    ));
    let tumbling = Vector3::new(1.0, 0.5, 0.3);
    assert!(matches!(
        simulate_full(
            &m,
            tumbling,
            g,
            100.0,
            &SimOptions {
                max_steps: 5,
                ..o.clone()
            }
        ),
        Err(RouthError::TooManySteps { steps: 5, .. })
    ));
    assert!(matches!(
        bad(SimOptions {
            max_steps: 5,
            ..SimOptions::lie_rk4(0.01)
        }),
        Err(RouthError::TooManySteps { .. })
    ));
    // A kinetic form that is not positive definite.
    let indefinite = Free {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, -2.0, 3.0)),
    };
    assert!(matches!(
        simulate_full(&indefinite, w, g, 1.0, &o),
        Err(RouthError::KineticNotPositiveDefinite { min_eigenvalue, .. }) if min_eigenvalue == -2.0
    ));
}

#[test]
fn zero_length_run_records_the_initial_state() {
    let m = free();
    let w = Vector3::new(1.0, 0.5, 0.0);
    for o in [SimOptions::default(), SimOptions::lie_rk4(0.1)] {
        let tr = simulate_full(&m, w, Vector3::z(), 0.0, &o).unwrap();
        assert_eq!(tr.t, vec![0.0]);
        assert_eq!(tr.omega, vec![w]);
        assert_eq!(tr.energy[0], 0.5 * (1.0 + 0.5));
    }
}

/// Torque-free rotation about the stable major axis with a small perturbation: energy and
/// |Iω|² are integrals; the output times are honoured exactly by both methods.
#[test]
fn output_times_and_integrals() {
    let m = free();
    let w0 = Vector3::new(0.05, 0.1, 2.0);
    let times: Vec<f64> = (0..=20).map(|i| i as f64 * 0.25).collect();
    for o in [
        SimOptions::with_tolerances(1e-11, 1e-13).at_times(times.clone()),
        SimOptions::lie_rk4(0.01).at_times(times.clone()),
    ] {
        let tr = simulate_full(&m, w0, Vector3::z(), 5.0, &o).unwrap();
        assert_eq!(tr.t, times);
        let l0 = (m.inertia * w0).norm_squared();
        for w in &tr.omega {
            assert!(((m.inertia * w).norm_squared() - l0).abs() < 1e-8);
        }
        assert!(tr.energy_drift() < 1e-8, "{:e}", tr.energy_drift());
    }
}
