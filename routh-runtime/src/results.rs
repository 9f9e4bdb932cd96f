//! From a tape's flat outputs to the result types of `routh-core`, by constant offsets.
//!
//! The order of the scalars is `routh_codegen::layout`'s ([`Bundle::flatten`],
//! [`Gyroscopic::flatten`]); it is written out here as offsets ([`BUNDLE_AT`], [`GYROSCOPIC_AT`])
//! so that a `Model::bundle` reads its outputs straight into the result (no iterator over the
//! layout, no intermediate copies: those took more time than the heavy top's tape itself), and a
//! test checks the offsets against `from_flat` of the layout itself.

use nalgebra::{Matrix3, Vector3};
use routh_codegen::layout::{Bundle, Gyroscopic};
use routh_core::{GyroscopicSystem, RouthBundle};

/// Where each scalar of the bundle is among the bundle tape's outputs:
/// `Bundle::from_flat(0..36)`.
pub(crate) const BUNDLE_AT: Bundle<usize> = Bundle {
    routhian: 0,
    psi_dot: 1,
    dr_domega: [2, 3, 4],
    dr_dgamma: [5, 6, 7],
    dr_dp: 8,
    d2r_domega2: [[9, 10, 11], [12, 13, 14], [15, 16, 17]],
    d2r_domega_dgamma: [[18, 19, 20], [21, 22, 23], [24, 25, 26]],
    d2r_dgamma2: [[27, 28, 29], [30, 31, 32], [33, 34, 35]],
};

/// The number of outputs of the bundle tape.
pub(crate) const BUNDLE_LEN: usize = 36;

/// Where each scalar of `A`, `G`, `C` is among the gyroscopic system tape's outputs:
/// `Gyroscopic::from_flat(0..27)`.
pub(crate) const GYROSCOPIC_AT: Gyroscopic<usize> = Gyroscopic {
    a: [[0, 1, 2], [3, 4, 5], [6, 7, 8]],
    g: [[9, 10, 11], [12, 13, 14], [15, 16, 17]],
    c: [[18, 19, 20], [21, 22, 23], [24, 25, 26]],
};

/// `o[k]` (NaN past the end, which the callers' constant offsets never are).
#[inline(always)]
fn at(o: &[f64], k: usize) -> f64 {
    o.get(k).copied().unwrap_or(f64::NAN)
}

#[inline(always)]
fn v3(o: &[f64], base: usize, ix: [usize; 3]) -> Vector3<f64> {
    Vector3::new(
        at(o, base + ix[0]),
        at(o, base + ix[1]),
        at(o, base + ix[2]),
    )
}

/// A 3×3 matrix whose entry `(i, j)` is `o[base + ix[i][j]]`.
#[inline(always)]
pub(crate) fn m33(o: &[f64], base: usize, ix: [[usize; 3]; 3]) -> Matrix3<f64> {
    let e = |i: usize, j: usize| at(o, base + ix[i][j]);
    Matrix3::new(
        e(0, 0),
        e(0, 1),
        e(0, 2),
        e(1, 0),
        e(1, 1),
        e(1, 2),
        e(2, 0),
        e(2, 1),
        e(2, 2),
    )
}

/// The bundle whose scalars are `o[base..base + 36]` in the layout's order.
#[inline(always)]
pub(crate) fn routh_bundle(o: &[f64], base: usize) -> RouthBundle {
    let b = BUNDLE_AT;
    RouthBundle {
        routhian: at(o, base + b.routhian),
        psi_dot: at(o, base + b.psi_dot),
        dr_domega: v3(o, base, b.dr_domega),
        dr_dgamma: v3(o, base, b.dr_dgamma),
        dr_dp: at(o, base + b.dr_dp),
        d2r_domega2: m33(o, base, b.d2r_domega2),
        d2r_domega_dgamma: m33(o, base, b.d2r_domega_dgamma),
        d2r_dgamma2: m33(o, base, b.d2r_dgamma2),
    }
}

/// `A`, `G`, `C` whose scalars are `o[base..base + 27]` in the layout's order.
#[inline(always)]
pub(crate) fn gyroscopic(o: &[f64], base: usize) -> GyroscopicSystem {
    let g = GYROSCOPIC_AT;
    GyroscopicSystem {
        a: m33(o, base, g.a),
        g: m33(o, base, g.g),
        c: m33(o, base, g.c),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use routh_codegen::layout::BundleAndSystem;

    /// The offsets are the layout's own order.
    #[test]
    fn offsets_are_the_layout() {
        assert_eq!(BUNDLE_AT, Bundle::from_flat(0..BUNDLE_LEN));
        assert_eq!(GYROSCOPIC_AT, Gyroscopic::from_flat(0..27));
        let fused = BundleAndSystem::from_flat(0..BUNDLE_LEN + 27);
        assert_eq!(fused.bundle, BUNDLE_AT);
        assert_eq!(
            fused.system,
            Gyroscopic::from_flat(BUNDLE_LEN..BUNDLE_LEN + 27)
        );
    }

    /// The results equal the layout's `from_flat` read into the result types.
    #[test]
    fn results_equal_from_flat() {
        let o: Vec<f64> = (0..BUNDLE_LEN + 27).map(|k| k as f64 * 1.5 - 7.0).collect();
        let b = Bundle::from_flat(o[..BUNDLE_LEN].iter().copied());
        let m = |x: [[f64; 3]; 3]| Matrix3::from_fn(|i, j| x[i][j]);
        let r = routh_bundle(&o, 0);
        assert_eq!(r.routhian, b.routhian);
        assert_eq!(r.psi_dot, b.psi_dot);
        assert_eq!(r.dr_domega, Vector3::from(b.dr_domega));
        assert_eq!(r.dr_dgamma, Vector3::from(b.dr_dgamma));
        assert_eq!(r.dr_dp, b.dr_dp);
        assert_eq!(r.d2r_domega2, m(b.d2r_domega2));
        assert_eq!(r.d2r_domega_dgamma, m(b.d2r_domega_dgamma));
        assert_eq!(r.d2r_dgamma2, m(b.d2r_dgamma2));
        let s = Gyroscopic::from_flat(o[BUNDLE_LEN..].iter().copied());
        let g = gyroscopic(&o, BUNDLE_LEN);
        assert_eq!((g.a, g.g, g.c), (m(s.a), m(s.g), m(s.c)));
    }
}
