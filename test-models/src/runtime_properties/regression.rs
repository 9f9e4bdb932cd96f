//! Inputs that once failed a property, kept as regression cases of the runtime property test.

use routh_core::sim::SimOptions;
use routh_core::steady::{self, SearchOptions, SteadyMotion};
use routh_core::{classify, simulate_full, simulate_reduced, Matrix3, Vector3};

use super::harness::{
    finite, report_defect, steady_defect, trajectory_defect, vecs_finite, Harness,
};
use crate::{Gyrostat, HeavyTop};

/// Inputs that once failed a property, kept as regression cases (run after the random ones,
/// reported as case `u64::MAX`).
pub(crate) fn regression_cases(h: &mut Harness) {
    h.case = u64::MAX;
    let unit_top = HeavyTop {
        j: Matrix3::identity(),
        mgr: Vector3::zeros(),
    };

    // simulate_full: |ω₀| = 1e300 leaves the field (8) finite but the recorded energy (3) ∞;
    // was Ok with a non-finite energy, now `InvalidOption { what: "omega0" }`.
    let w = Vector3::new(1e300, 0.0, 0.0);
    h.check(
        "regression: simulate_full, energy overflow at t = 0",
        || format!("{unit_top:?}, omega0 = {w:?}"),
        || simulate_full(&unit_top, w, Vector3::z(), 0.0, &SimOptions::default()),
        trajectory_defect,
    );
    // simulate_reduced: the same for E' (16).
    h.check(
        "regression: simulate_reduced, energy overflow at t = 0",
        || format!("{unit_top:?}, big_omega0 = {w:?}"),
        || simulate_reduced(&unit_top, w, Vector3::z(), 1.0, 0.0, &SimOptions::default()),
        |tr| {
            let ok = finite(&tr.energy) && finite(&tr.p_psi) && vecs_finite(&tr.omega);
            (!ok).then(|| format!("trajectory {tr:?}"))
        },
    );

    // simulate_full: LieRk4 with a step far too long for a top with moments 55 and 0.02; the
    // state stays finite (ω ≈ 1e198) but the energy overflows. Was Ok with NaN energies, now
    // `NonFiniteState`.
    let top = HeavyTop {
        j: Matrix3::from_column_slice(&[
            55.17334548146032,
            -0.9846393434818353,
            5.587542114463098,
            -0.9846393434818353,
            0.022508777615147357,
            -0.1000474447190113,
            5.587542114463098,
            -0.1000474447190113,
            0.5721291303967168,
        ]),
        mgr: Vector3::new(0.0, -0.00013921895444900172, 0.0),
    };
    let w = Vector3::new(
        -0.0752700973525174,
        0.14752297710732257,
        0.16284712234494647,
    );
    let o = SimOptions {
        max_steps: 5,
        ..SimOptions::lie_rk4(0.9038040560051361)
    };
    h.check(
        "regression: simulate_full, LieRk4 blow-up",
        || format!("{top:?}, omega0 = {w:?}, {o:?}"),
        || simulate_full(&top, w, -Vector3::y(), 1.8076081120102723, &o),
        trajectory_defect,
    );

    // classify: a positive definite J with a subnormal moment; the coefficients of f₂ are
    // finite but its roots overflowed to ±i∞ in an Ok report. Now `NonFiniteModel`.
    let top = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(
            1e-310,
            0.004997672060611541,
            0.029099436750563173,
        )),
        mgr: Vector3::new(0.0, 0.0, -9.390385597692829e-6),
    };
    let p = -10597.205646642626;
    if let Ok(steady) = SteadyMotion::at(&top, -Vector3::z(), p, true) {
        h.check(
            "regression: classify, f2 roots overflow",
            || format!("{top:?}, {steady:?}"),
            || classify(&top, &steady),
            report_defect,
        );
    }

    // steady_motion_search: a gyrostat with a coupling of 5e5 (its amended potential vanishes
    // on a curve) and a loose gradient_tol: 12 starts gave 5436 "steady motions" in 2–3 s,
    // 100 starts 16 501 in 11 s, 400 starts minutes (probes around every point found). Now at
    // most 64 probe centres: well within the call budget.
    let gyro = Gyrostat {
        inertia: Matrix3::from_column_slice(&[
            2.599097393437593,
            0.5712275271507942,
            -1.526788294710992,
            0.5712275271507942,
            0.12974229319681604,
            -0.3418894361008022,
            -1.526788294710992,
            -0.34188943610080214,
            0.9064505994068272,
        ]),
        rotor: Vector3::new(
            -0.41399761808433705,
            -0.0393969984776383,
            0.18704431031158789,
        ),
        coupling: Matrix3::from_column_slice(&[
            496600.6316666974,
            -1392.5425255781229,
            34.953159000293255,
            -615.3498385472059,
            0.0010451604155902877,
            0.10578528012501709,
            -1973.6223172711757,
            0.001152410342946016,
            0.053733996638848,
        ]),
        com: Vector3::new(0.0, 0.0, -431.6927876344234),
        mass: 0.0006460117949872163,
        g: -1.4663354229682605e-6,
    };
    let o = SearchOptions {
        starts: 100,
        max_iterations: 22,
        gradient_tol: 0.0037024904107560916,
        zero_eigenvalue_tol: 2.935245170938167e-9,
    };
    h.check(
        "regression: steady_motion_search, probes of a curve",
        || format!("{gyro:?}, {o:?}"),
        || steady::steady_motion_search(&gyro, 1.1865574957550809e4, &o),
        |r| r.motions.iter().find_map(steady_defect),
    );
}
