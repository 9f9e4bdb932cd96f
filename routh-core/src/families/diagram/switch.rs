//! Branch switching: at a branch point the new branches start along the null direction of
//! `[K | F_s]` orthogonal to the branch (a pitchfork), or as a branch of circles where `K`
//! vanishes altogether (a symmetric body).

use nalgebra::{Vector2, Vector3, Vector4};

use super::builder::Builder;
use super::join::join_tolerances;
use crate::error::RouthError;
use crate::families::continuation::Node;
use crate::families::StopReason;
use crate::model::Routhian;
use crate::solve::path::row::LinearRow;
use crate::sphere::tangent_basis;

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    /// Starts the branches that leave the branch points found so far.
    ///
    /// More than `4·max_branches` branch points (each can start up to two branches) end the
    /// switching with [`StopReason::MaxBranches`].
    ///
    /// Errors: those of [`Builder::follow`].
    pub(super) fn switch_all(&mut self) -> Result<(), RouthError> {
        let mut rounds = 0;
        while let Some(sw) = self.pending.pop() {
            if self.opts.control.is_cancelled() {
                self.stopped(StopReason::Interrupted);
                return Ok(());
            }
            rounds += 1;
            let n = &sw.node;
            if rounds > 4 * self.opts.max_branches {
                self.stopped(StopReason::MaxBranches {
                    s: n.s,
                    gamma: n.gamma,
                });
                return Ok(());
            }
            if self
                .done_switches
                .iter()
                .any(|(s, g)| (s - n.s).abs() <= 1e-6 * self.len() && (g - n.gamma).norm() < 1e-5)
            {
                continue;
            }
            self.done_switches.push((n.s, n.gamma));
            let both_zero = n.eig_zeros() == 2;
            let basis = tangent_basis(&n.gamma);
            let eps = 1e-3;
            let mut candidates: Vec<(Vector3<f64>, f64, bool)> = Vec::new();
            if both_zero && sw.isolated {
                // The birth of a circle of steady motions (a symmetric body): any direction.
                // (A double zero without a symmetry is of codimension two in a one-parameter
                // family: not looked for.)
                candidates.push((basis * Vector2::new(1.0, 0.0), 0.0, false));
            } else {
                // At a branch point [K | F_σ] has rank one: its null space is the plane
                // orthogonal to its dominant row r, spanned by the branch's tangent t and r × t.
                let t = nalgebra::Vector3::new(
                    (basis.transpose() * n.tau_g).x,
                    (basis.transpose() * n.tau_g).y,
                    n.tau_s,
                );
                let r1: Vector3<f64> = n.jac.row(0).transpose();
                let r2: Vector3<f64> = n.jac.row(1).transpose();
                let r = if r1.norm() >= r2.norm() { r1 } else { r2 };
                let d = r.cross(&t);
                if d.norm() < 1e-9 {
                    continue;
                }
                let d = d.normalize();
                candidates.push((basis * Vector2::new(d.x, d.y), d.z, true));
            }
            for (dg, ds, isolated) in candidates {
                for sign in [1.0, -1.0] {
                    self.try_switch(n, sign * dg, sign * ds, eps, isolated)?;
                }
            }
        }
        Ok(())
    }

    /// Starts a branch from the branch point `n` in the direction `(dg, ds)` (in `(γ, σ)`) at
    /// distance `eps`, unless a branch already covers it.
    pub(super) fn try_switch(
        &mut self,
        n: &Node,
        dg: Vector3<f64>,
        ds: f64,
        eps: f64,
        isolated: bool,
    ) -> Result<(), RouthError> {
        // A branch of circles that already ends next to this point of its axis (traced from a
        // seed down to where its circles shrink to the pole) is the one that would start here.
        if !isolated {
            let (ds_tol, dg_tol) = join_tolerances(false, n.s, self.len());
            let ends_here = self.branches.iter().any(|(nodes, iso)| {
                !*iso
                    && [nodes.first(), nodes.last()]
                        .into_iter()
                        .flatten()
                        .any(|e| {
                            (e.s - n.s).abs() <= ds_tol && (e.gamma - n.gamma).norm() <= dg_tol
                        })
            });
            if ends_here {
                return Ok(());
            }
        }
        let scale = self.scale_at(&n.gamma, n.s)?;
        let ctx = self.ctx(isolated, scale);
        let len = ctx.len;
        let g_p = (n.gamma + eps * dg).normalize();
        let s_p = n.s / len + eps * ds;
        // `dg·(γ − γ_n) + ds(σ − σ_n) = eps`, relative to the predicted point.
        let rhs = eps - dg.dot(&(g_p - n.gamma)) - ds * (s_p - n.s / len);
        let row = LinearRow::new(Vector4::new(dg.x, dg.y, dg.z, ds), rhs);
        let Some((g, s, _)) = ctx.correct(&g_p, s_p, &row, None)? else {
            return Ok(());
        };
        if s < self.range.0 || s > self.range.1 || (g - n.gamma).norm() < 0.2 * eps {
            return Ok(());
        }
        if self.covered(s, &g, isolated)? {
            return Ok(());
        }
        let Some(start) = ctx.node(&g, s, None)? else {
            return Ok(());
        };
        // Branches of circles need a zero eigenvalue along them; isolated ones must not be
        // circles.
        let zero = start.eig_zeros() > 0;
        if isolated == zero {
            return Ok(());
        }
        self.follow(&ctx, start)
    }
}
