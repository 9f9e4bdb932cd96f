//! Tables out of routh: CSV text of the results whose natural shape is a table — trajectories,
//! the samples of a bifurcation diagram's branches and its events, the grid of a stability atlas
//! and its boundary curves. (Everything else leaves as JSON through the `serde` feature.)
//!
//! Format: a header row of column names, then one row per record, comma-separated, `\n` line
//! ends; numbers in Rust's shortest round-trip form (`f64` → text → `f64` is exact; `NaN`, `inf`
//! and `-inf` as Rust prints them); verdicts and event kinds as fixed snake-case words
//! ([`verdict_name`], [`event_name`]); an empty field where there is no value. The names are
//! units-free: values are in whatever units the model's parameters were given in.
//!
//! # Columns
//!
//! [`Trajectory::to_csv`]: `t, omega_1, omega_2, omega_3, gamma_1, gamma_2, gamma_3, energy,
//! p_psi, energy_drift, p_psi_drift`, then, when the attitude was integrated,
//! `q_w, q_x, q_y, q_z, euler_psi, euler_theta, euler_phi` (the unit quaternion of `R`, body →
//! space, and its z-x-z Euler angles in radians, see [`Trajectory::euler_angles`]). The drifts
//! are `E(t) − E(0)` and `p_ψ(t) − p_ψ(0)`.
//!
//! [`ReducedTrajectory::to_csv`]: `t, big_omega_1..3, gamma_1..3, psi, psi_dot, omega_1..3,
//! energy, p_psi, energy_drift, p_psi_drift` (ψ the gauge angle of (15), Ω the relative angular
//! velocity, ω = Ω + ψ̇γ), then the same attitude columns.
//!
//! [`BifurcationDiagram::to_csv`]: one row per point of every branch, `branch, isolated, s,
//! p_psi, gamma_1, gamma_2, gamma_3, psi_dot, mu, amended_potential, energy, verdict,
//! degree_of_instability, hessian_eigenvalue_1, hessian_eigenvalue_2`;
//! [`BifurcationDiagram::events_to_csv`]: `kind, branch, s, gamma_1, gamma_2, gamma_3, before,
//! after`.
//!
//! [`StabilityAtlas::to_csv`]: one row per grid node, `x, y, verdict` (empty verdict where the
//! followed steady motion does not exist); [`StabilityAtlas::boundaries_to_csv`]:
//! `curve, kind, x, y`, one row per traced point.

use std::fmt::Write as _;
use std::path::Path;

use crate::families::{BifurcationDiagram, EventKind, StabilityAtlas};
use crate::nonlinear::NonlinearVerdict;
use crate::sim::{ReducedTrajectory, Trajectory};
use crate::stability::Stability;

/// The CSV word for a verdict: `secularly_stable`, `gyroscopically_stabilized`, `unstable`,
/// `degenerate`.
pub fn verdict_name(v: Stability) -> &'static str {
    match v {
        Stability::SecularlyStable => "secularly_stable",
        Stability::GyroscopicallyStabilized => "gyroscopically_stabilized",
        Stability::Unstable => "unstable",
        Stability::Degenerate => "degenerate",
    }
}

/// The CSV word for an event kind: `fold`, `branch_point`, `hamiltonian_hopf`,
/// `arnold_degenerate`, `resonance`.
pub fn event_name(k: EventKind) -> &'static str {
    match k {
        EventKind::Fold => "fold",
        EventKind::BranchPoint => "branch_point",
        EventKind::HamiltonianHopf => "hamiltonian_hopf",
        EventKind::ArnoldDegenerate => "arnold_degenerate",
        EventKind::Resonance => "resonance",
    }
}

/// The word for a nonlinear verdict: `secularly_stable`, `lyapunov_stable`, `unstable`,
/// `undecided`.
pub fn nonlinear_verdict_name(v: NonlinearVerdict) -> &'static str {
    match v {
        NonlinearVerdict::SecularlyStable => "secularly_stable",
        NonlinearVerdict::LyapunovStable => "lyapunov_stable",
        NonlinearVerdict::Unstable => "unstable",
        NonlinearVerdict::Undecided => "undecided",
    }
}

/// A table being written: a header, then rows of fields.
struct Table {
    text: String,
    first: bool,
}

impl Table {
    fn new(header: &[&str]) -> Self {
        let mut text = header.join(",");
        text.push('\n');
        Table { text, first: true }
    }
    fn num(&mut self, x: f64) {
        self.sep();
        let _ = write!(self.text, "{x}");
    }
    fn word(&mut self, w: &str) {
        self.sep();
        self.text.push_str(w);
    }
    fn sep(&mut self) {
        if !self.first {
            self.text.push(',');
        }
        self.first = false;
    }
    fn end_row(&mut self) {
        self.text.push('\n');
        self.first = true;
    }
}

const ATTITUDE_COLUMNS: [&str; 7] = [
    "q_w",
    "q_x",
    "q_y",
    "q_z",
    "euler_psi",
    "euler_theta",
    "euler_phi",
];

fn header(base: &[&'static str], attitude: bool) -> Vec<&'static str> {
    let mut h = base.to_vec();
    if attitude {
        h.extend(ATTITUDE_COLUMNS);
    }
    h
}

impl Trajectory {
    /// The trajectory as CSV text (columns in the [module documentation](crate::export)).
    ///
    /// ```
    /// # use routh_core::Trajectory;
    /// let csv = Trajectory::default().to_csv();
    /// assert!(csv.starts_with("t,omega_1,omega_2,omega_3,gamma_1,"));
    /// ```
    #[allow(clippy::needless_range_loop)] // one row from many columns
    pub fn to_csv(&self) -> String {
        let att = !self.attitude.is_empty();
        let mut tb = Table::new(&header(
            &[
                "t",
                "omega_1",
                "omega_2",
                "omega_3",
                "gamma_1",
                "gamma_2",
                "gamma_3",
                "energy",
                "p_psi",
                "energy_drift",
                "p_psi_drift",
            ],
            att,
        ));
        let euler = self.euler_angles();
        let (e0, p0) = (first(&self.energy), first(&self.p_psi));
        for i in 0..self.len() {
            tb.num(self.t[i]);
            self.omega[i].iter().for_each(|&x| tb.num(x));
            self.gamma[i].iter().for_each(|&x| tb.num(x));
            tb.num(self.energy[i]);
            tb.num(self.p_psi[i]);
            tb.num(self.energy[i] - e0);
            tb.num(self.p_psi[i] - p0);
            if att {
                attitude_fields(&mut tb, &self.attitude[i], &euler[i]);
            }
            tb.end_row();
        }
        tb.text
    }

    /// Writes [`to_csv`](Self::to_csv) to the file `path`, whole or not at all
    /// ([`write_file`](crate::files::write_file)).
    ///
    /// # Errors
    ///
    /// The I/O error of creating or writing the file, naming `path`.
    pub fn write_csv(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        crate::files::write_file(path, self.to_csv().as_bytes())
    }
}

impl ReducedTrajectory {
    /// The trajectory as CSV text (columns in the [module documentation](crate::export)).
    #[allow(clippy::needless_range_loop)] // one row from many columns
    pub fn to_csv(&self) -> String {
        let att = !self.attitude.is_empty();
        let mut tb = Table::new(&header(
            &[
                "t",
                "big_omega_1",
                "big_omega_2",
                "big_omega_3",
                "gamma_1",
                "gamma_2",
                "gamma_3",
                "psi",
                "psi_dot",
                "omega_1",
                "omega_2",
                "omega_3",
                "energy",
                "p_psi",
                "energy_drift",
                "p_psi_drift",
            ],
            att,
        ));
        let euler = self.euler_angles();
        let (e0, p0) = (first(&self.energy), first(&self.p_psi));
        for i in 0..self.len() {
            tb.num(self.t[i]);
            self.big_omega[i].iter().for_each(|&x| tb.num(x));
            self.gamma[i].iter().for_each(|&x| tb.num(x));
            tb.num(self.psi[i]);
            tb.num(self.psi_dot[i]);
            self.omega[i].iter().for_each(|&x| tb.num(x));
            tb.num(self.energy[i]);
            tb.num(self.p_psi[i]);
            tb.num(self.energy[i] - e0);
            tb.num(self.p_psi[i] - p0);
            if att {
                attitude_fields(&mut tb, &self.attitude[i], &euler[i]);
            }
            tb.end_row();
        }
        tb.text
    }

    /// Writes [`to_csv`](Self::to_csv) to the file `path`, whole or not at all
    /// ([`write_file`](crate::files::write_file)).
    ///
    /// # Errors
    ///
    /// The I/O error of creating or writing the file, naming `path`.
    pub fn write_csv(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        crate::files::write_file(path, self.to_csv().as_bytes())
    }
}

fn first(x: &[f64]) -> f64 {
    x.first().copied().unwrap_or(0.0)
}

fn attitude_fields(tb: &mut Table, q: &nalgebra::UnitQuaternion<f64>, e: &[f64; 3]) {
    let q = q.quaternion();
    for x in [q.w, q.i, q.j, q.k] {
        tb.num(x);
    }
    e.iter().for_each(|&x| tb.num(x));
}

impl BifurcationDiagram {
    /// The branches' samples as CSV text, one row per [`BranchSample`](crate::BranchPoint)
    /// (columns in the [module documentation](crate::export)).
    pub fn to_csv(&self) -> String {
        let mut tb = Table::new(&[
            "branch",
            "isolated",
            "s",
            "p_psi",
            "gamma_1",
            "gamma_2",
            "gamma_3",
            "psi_dot",
            "mu",
            "amended_potential",
            "energy",
            "verdict",
            "degree_of_instability",
            "hessian_eigenvalue_1",
            "hessian_eigenvalue_2",
        ]);
        for (b, branch) in self.branches.iter().enumerate() {
            for q in &branch.points {
                tb.word(&b.to_string());
                tb.word(if branch.isolated { "true" } else { "false" });
                tb.num(q.s);
                tb.num(q.steady.p_psi);
                q.steady.gamma.iter().for_each(|&x| tb.num(x));
                tb.num(q.steady.psi_dot);
                tb.num(q.steady.mu);
                tb.num(q.steady.amended_potential);
                tb.num(q.steady.energy);
                tb.word(verdict_name(q.report.verdict));
                tb.word(&q.report.degree_of_instability.to_string());
                q.report
                    .restricted_hessian_eigenvalues
                    .iter()
                    .for_each(|&x| tb.num(x));
                tb.end_row();
            }
        }
        tb.text
    }

    /// The events as CSV text: `kind, branch, s, gamma_1, gamma_2, gamma_3, before, after`.
    pub fn events_to_csv(&self) -> String {
        let mut tb = Table::new(&[
            "kind", "branch", "s", "gamma_1", "gamma_2", "gamma_3", "before", "after",
        ]);
        for e in &self.events {
            tb.word(event_name(e.kind));
            tb.word(&e.branch.to_string());
            tb.num(e.s);
            e.gamma.iter().for_each(|&x| tb.num(x));
            tb.word(verdict_name(e.before));
            tb.word(verdict_name(e.after));
            tb.end_row();
        }
        tb.text
    }

    /// Writes [`to_csv`](Self::to_csv) to the file `path`, whole or not at all
    /// ([`write_file`](crate::files::write_file)).
    ///
    /// # Errors
    ///
    /// The I/O error of creating or writing the file, naming `path`.
    pub fn write_csv(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        crate::files::write_file(path, self.to_csv().as_bytes())
    }
}

impl StabilityAtlas {
    /// The grid as CSV text, `x, y, verdict`, one row per node, `x` fastest.
    pub fn to_csv(&self) -> String {
        let mut tb = Table::new(&["x", "y", "verdict"]);
        for (j, &y) in self.y.iter().enumerate() {
            for (i, &x) in self.x.iter().enumerate() {
                tb.num(x);
                tb.num(y);
                let v = self.verdicts.get(j).and_then(|row| row.get(i)).copied();
                tb.word(v.flatten().map(verdict_name).unwrap_or(""));
                tb.end_row();
            }
        }
        tb.text
    }

    /// The boundary curves as CSV text, `curve, kind, x, y`, one row per traced point.
    pub fn boundaries_to_csv(&self) -> String {
        let mut tb = Table::new(&["curve", "kind", "x", "y"]);
        for (c, b) in self.boundaries.iter().enumerate() {
            for &(x, y) in &b.points {
                tb.word(&c.to_string());
                tb.word(event_name(b.kind));
                tb.num(x);
                tb.num(y);
                tb.end_row();
            }
        }
        tb.text
    }

    /// Writes [`to_csv`](Self::to_csv) to the file `path`, whole or not at all
    /// ([`write_file`](crate::files::write_file)).
    ///
    /// # Errors
    ///
    /// The I/O error of creating or writing the file, naming `path`.
    pub fn write_csv(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        crate::files::write_file(path, self.to_csv().as_bytes())
    }
}
