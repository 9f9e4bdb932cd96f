//! The linear row of a corrector's system: one linear equation `n·w = c` on the unknowns, appended
//! to the equations a Newton iteration solves (docs/method.md §5, §6b, §11).

use nalgebra::SVector;

/// A linear equation `n·w = c` on the unknowns `w ∈ ℝᴺ` of a Newton system: the
/// pseudo-arclength row `τ·(w − w_pred) = 0` of a continuation step, a fixed parameter
/// `w_k = c` (natural-parameter stepping, the energy of a periodic orbit, an edge of the atlas's
/// square), or the meridian-plane row `c·ξ = 0` of a branch of circles. Each user says in which
/// coordinates `w` is (absolute, or relative to the predicted point).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LinearRow<const N: usize> {
    /// `n`, the normal of the hyperplane `n·w = c`.
    pub normal: SVector<f64, N>,
    /// `c`, the right-hand side.
    pub rhs: f64,
}

impl<const N: usize> LinearRow<N> {
    /// `normal·w = rhs`.
    pub fn new(normal: SVector<f64, N>, rhs: f64) -> Self {
        LinearRow { normal, rhs }
    }

    /// The hyperplane with normal `normal` through `point`: `n·(w − point) = 0`, written
    /// `n·w = n·point` (the pseudo-arclength row through a prediction).
    pub fn through(normal: SVector<f64, N>, point: &SVector<f64, N>) -> Self {
        LinearRow {
            rhs: normal.dot(point),
            normal,
        }
    }

    /// The coordinate `w_k` fixed at `value`.
    pub fn fixed(k: usize, value: f64) -> Self {
        let mut normal = SVector::zeros();
        normal[k] = 1.0;
        LinearRow { normal, rhs: value }
    }

    /// The residual `n·w − c` of the row at `w`.
    #[inline(always)]
    pub fn residual(&self, w: &SVector<f64, N>) -> f64 {
        self.normal.dot(w) - self.rhs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    /// The three constructors against the equations they stand for, at points chosen by hand.
    #[test]
    fn rows_vanish_on_their_hyperplanes() {
        let n = Vector3::new(1.0, -2.0, 0.5);
        let p = Vector3::new(0.25, 0.5, 4.0);
        let through = LinearRow::through(n, &p);
        // n·p = 0.25 − 1 + 2 = 1.25; a point moved along a vector orthogonal to n stays on it.
        assert_eq!(through.rhs, 1.25);
        assert_eq!(through.residual(&(p + Vector3::new(2.0, 1.0, 0.0))), 0.0);
        assert_eq!(through.residual(&(p + n)), 5.25);
        let fixed = LinearRow::<3>::fixed(1, 3.0);
        assert_eq!(fixed.normal, Vector3::new(0.0, 1.0, 0.0));
        assert_eq!(fixed.residual(&Vector3::new(7.0, 3.0, -9.0)), 0.0);
        assert_eq!(fixed.residual(&Vector3::new(7.0, 5.0, -9.0)), 2.0);
        assert_eq!(LinearRow::new(n, 1.25), through);
    }
}
