//! The layouts of the methods that return many outputs from one straight-line body,
//! `Routhian::bundle`, `Routhian::gyroscopic_system`, `Routhian::bundle_and_system`,
//! `Lagrangian::full_equations`, `Lagrangian::full_jacobian` and `Routhian::reduced_equations`:
//! which output is which, by name.
//!
//! [`reduce`](crate::reduce) derives the outputs as nodes and [`emit`](crate::emit) writes one
//! body for all of them, which hands back one token per node in the order it was given. Both
//! sides go through these structs, so the order of the scalars is written down once
//! ([`Bundle::flatten`] and [`Bundle::from_flat`]) instead of as offsets (`outs[2..5]`) on each
//! side that must agree. The structs are generic over what is stored per scalar: nodes
//! ([`Id`](routh_symbolic::Id)) on the way in, tokens on the way out.

/// What `Routhian::bundle` returns, one field per field of `routh::RouthBundle` and in its
/// order: `R`, `ψ̇` and the first and second derivatives of `R`.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct Bundle<T> {
    /// `R(Ω, γ, p_ψ)` (14).
    pub routhian: T,
    /// `ψ̇` (38).
    pub psi_dot: T,
    /// `∂R/∂Ω`.
    pub dr_domega: [T; 3],
    /// `∂R/∂γ`.
    pub dr_dgamma: [T; 3],
    /// `∂R/∂p_ψ = −ψ̇` (15).
    pub dr_dp: T,
    /// `∂²R/∂Ω²`, row-major.
    pub d2r_domega2: [[T; 3]; 3],
    /// `∂²R/∂Ω_i∂γ_j`, row-major.
    pub d2r_domega_dgamma: [[T; 3]; 3],
    /// `∂²R/∂γ²`, row-major.
    pub d2r_dgamma2: [[T; 3]; 3],
}

impl<T> Bundle<T> {
    /// The scalars in layout order (fields in declaration order, matrices row-major).
    pub fn flatten(self) -> Vec<T> {
        let mut out = vec![self.routhian, self.psi_dot];
        out.extend(self.dr_domega);
        out.extend(self.dr_dgamma);
        out.push(self.dr_dp);
        for m in [self.d2r_domega2, self.d2r_domega_dgamma, self.d2r_dgamma2] {
            out.extend(m.into_iter().flatten());
        }
        out
    }

    /// The inverse of [`Bundle::flatten`].
    ///
    /// # Panics
    /// If `flat` does not hold exactly one scalar per field (a bug in the caller: it is always
    /// the image of a flattened bundle).
    pub fn from_flat(flat: impl IntoIterator<Item = T>) -> Self {
        read_exactly(flat, |it| Bundle {
            routhian: take(it),
            psi_dot: take(it),
            dr_domega: take3(it),
            dr_dgamma: take3(it),
            dr_dp: take(it),
            d2r_domega2: take33(it),
            d2r_domega_dgamma: take33(it),
            d2r_dgamma2: take33(it),
        })
    }
}

/// What `Routhian::gyroscopic_system` returns: `A`, `G`, `C` of (64) at `Ω = 0`, in the order of
/// `routh::GyroscopicSystem`.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct Gyroscopic<T> {
    /// `A = ∂²R/∂Ω²` at rest, row-major.
    pub a: [[T; 3]; 3],
    /// The gyroscopic matrix `G`, row-major.
    pub g: [[T; 3]; 3],
    /// The stiffness matrix `C`, row-major.
    pub c: [[T; 3]; 3],
}

impl<T> Gyroscopic<T> {
    /// The scalars in layout order (`A`, `G`, `C`, each row-major).
    pub fn flatten(self) -> Vec<T> {
        [self.a, self.g, self.c]
            .into_iter()
            .flatten()
            .flatten()
            .collect()
    }

    /// The inverse of [`Gyroscopic::flatten`].
    ///
    /// # Panics
    /// If `flat` does not hold exactly 27 scalars.
    pub fn from_flat(flat: impl IntoIterator<Item = T>) -> Self {
        read_exactly(flat, |it| Gyroscopic {
            a: take33(it),
            g: take33(it),
            c: take33(it),
        })
    }
}

/// The number of scalars of a [`Bundle`]: R, ψ̇, two 3-vectors, ∂R/∂p_ψ and three 3×3 blocks.
const BUNDLE_LEN: usize = 2 + 3 + 3 + 1 + 3 * 9;
/// The number of scalars of a [`Gyroscopic`].
const GYROSCOPIC_LEN: usize = 3 * 9;

/// What `Routhian::bundle_and_system` returns: the bundle at `(Ω, γ, p_ψ)` and `A`, `G`, `C`
/// of (64) formed from it, in the order of the tuple `(routh::RouthBundle,
/// routh::GyroscopicSystem)`.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct BundleAndSystem<T> {
    /// The 36 scalars of the bundle.
    pub bundle: Bundle<T>,
    /// The 27 scalars of `A`, `G`, `C`.
    pub system: Gyroscopic<T>,
}

impl<T> BundleAndSystem<T> {
    /// The scalars in layout order: [`Bundle::flatten`], then [`Gyroscopic::flatten`].
    pub fn flatten(self) -> Vec<T> {
        let mut out = self.bundle.flatten();
        out.extend(self.system.flatten());
        out
    }

    /// The inverse of [`BundleAndSystem::flatten`].
    ///
    /// # Panics
    /// If `flat` does not hold exactly 36 + 27 scalars.
    pub fn from_flat(flat: impl IntoIterator<Item = T>) -> Self {
        read_exactly(flat, |it| BundleAndSystem {
            bundle: Bundle::from_flat(it.by_ref().take(BUNDLE_LEN)),
            system: Gyroscopic::from_flat(it.by_ref().take(GYROSCOPIC_LEN)),
        })
    }
}

/// What `Lagrangian::full_equations` and `Routhian::reduced_equations` return: `J`, the right
/// side of (8) or (13), (for (13) only) `ψ̇`, and (for a model with `J = J₀ + c v vᵀ`) `c` and
/// `v`, in the order of `routh::FullEquations` and `routh::ReducedEquations`.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct EquationTerms<T> {
    /// `J = ∂²L/∂ω²`, row-major.
    pub inertia: [[T; 3]; 3],
    /// The right side solved for the angular acceleration.
    pub right_side: [T; 3],
    /// `ψ̇` (38), for the reduced equations.
    pub psi_dot: Option<T>,
    /// `(c, v)` of `J = J₀ + c v vᵀ` ([`crate::inertia`]).
    pub rank_one: Option<(T, [T; 3])>,
}

/// Which optional parts an [`EquationTerms`] has, to read it back from its scalars.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct TermsShape {
    pub psi_dot: bool,
    pub rank_one: bool,
}

impl<T> EquationTerms<T> {
    /// Which optional parts it has.
    pub fn shape(&self) -> TermsShape {
        TermsShape {
            psi_dot: self.psi_dot.is_some(),
            rank_one: self.rank_one.is_some(),
        }
    }

    /// The scalars in layout order (`J` row-major, the right side, then `ψ̇`, `c` and `v` if
    /// present).
    pub fn flatten(self) -> Vec<T> {
        let mut out: Vec<T> = self.inertia.into_iter().flatten().collect();
        out.extend(self.right_side);
        out.extend(self.psi_dot);
        if let Some((c, v)) = self.rank_one {
            out.push(c);
            out.extend(v);
        }
        out
    }

    /// The inverse of [`EquationTerms::flatten`], for the given shape.
    ///
    /// # Panics
    /// If `flat` does not hold exactly 12 scalars, plus 1 with `ψ̇` and 4 with `(c, v)`.
    pub fn from_flat(flat: impl IntoIterator<Item = T>, shape: TermsShape) -> Self {
        read_exactly(flat, |it| EquationTerms {
            inertia: take33(it),
            right_side: take3(it),
            psi_dot: shape.psi_dot.then(|| take(it)),
            rank_one: shape.rank_one.then(|| (take(it), take3(it))),
        })
    }
}

/// What `Lagrangian::full_jacobian` returns: `J`, the right side `f` of (8) and their first
/// derivatives in `(ω, γ)`, in the order of `routh::FullJacobian`.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct JacobianTerms<T> {
    /// `J = ∂²L/∂ω²` (the whole matrix), row-major.
    pub inertia: [[T; 3]; 3],
    /// `f`, the right side of (8).
    pub right_side: [T; 3],
    /// `∂f_i/∂ω_j`, row-major.
    pub dright_domega: [[T; 3]; 3],
    /// `∂f_i/∂γ_j`, row-major.
    pub dright_dgamma: [[T; 3]; 3],
    /// `∂J/∂γ_k` for `k = 0, 1, 2`, each row-major.
    pub dinertia_dgamma: [[[T; 3]; 3]; 3],
}

/// The number of scalars of a [`JacobianTerms`]: `J`, `f`, two 3×3 blocks and three more.
pub const JACOBIAN_LEN: usize = 9 + 3 + 9 + 9 + 27;

impl<T> JacobianTerms<T> {
    /// The scalars in layout order (fields in declaration order, matrices row-major).
    pub fn flatten(self) -> Vec<T> {
        let mut out: Vec<T> = self.inertia.into_iter().flatten().collect();
        out.extend(self.right_side);
        out.extend(self.dright_domega.into_iter().flatten());
        out.extend(self.dright_dgamma.into_iter().flatten());
        out.extend(self.dinertia_dgamma.into_iter().flatten().flatten());
        out
    }

    /// The inverse of [`JacobianTerms::flatten`].
    ///
    /// # Panics
    /// If `flat` does not hold exactly [`JACOBIAN_LEN`] scalars.
    pub fn from_flat(flat: impl IntoIterator<Item = T>) -> Self {
        read_exactly(flat, |it| JacobianTerms {
            inertia: take33(it),
            right_side: take3(it),
            dright_domega: take33(it),
            dright_dgamma: take33(it),
            dinertia_dgamma: std::array::from_fn(|_| take33(it)),
        })
    }
}

/// A layout read from `flat` by `read`, which must use up every scalar.
fn read_exactly<T, I: IntoIterator<Item = T>, S>(
    flat: I,
    read: impl FnOnce(&mut I::IntoIter) -> S,
) -> S {
    let mut it = flat.into_iter();
    let layout = read(&mut it);
    assert!(it.next().is_none(), "more scalars than the layout holds");
    layout
}

fn take<T>(it: &mut impl Iterator<Item = T>) -> T {
    it.next().expect("fewer scalars than the layout holds")
}

fn take3<T>(it: &mut impl Iterator<Item = T>) -> [T; 3] {
    // `from_fn` calls the closure for indices 0, 1, 2 in order.
    std::array::from_fn(|_| take(it))
}

fn take33<T>(it: &mut impl Iterator<Item = T>) -> [[T; 3]; 3] {
    std::array::from_fn(|_| take3(it))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundle_round_trips_in_field_order() {
        let b = Bundle::from_flat(0..36);
        assert_eq!((b.routhian, b.psi_dot), (0, 1));
        assert_eq!(
            (b.dr_domega, b.dr_dgamma, b.dr_dp),
            ([2, 3, 4], [5, 6, 7], 8)
        );
        assert_eq!(b.d2r_domega2[1][2], 9 + 3 + 2);
        assert_eq!(b.d2r_domega_dgamma[0][0], 18);
        assert_eq!(b.d2r_dgamma2[2][2], 35);
        assert_eq!(b.flatten(), (0..36).collect::<Vec<_>>());
    }

    #[test]
    fn gyroscopic_round_trips_in_field_order() {
        let s = Gyroscopic::from_flat(0..27);
        assert_eq!((s.a[0][1], s.g[0][0], s.c[2][2]), (1, 9, 26));
        assert_eq!(s.flatten(), (0..27).collect::<Vec<_>>());
    }

    #[test]
    fn bundle_and_system_round_trips_in_field_order() {
        let f = BundleAndSystem::from_flat(0..63);
        assert_eq!((f.bundle.routhian, f.bundle.d2r_dgamma2[2][2]), (0, 35));
        assert_eq!(
            (f.system.a[0][0], f.system.g[0][0], f.system.c[2][2]),
            (36, 45, 62)
        );
        assert_eq!(f.flatten(), (0..63).collect::<Vec<_>>());
    }

    #[test]
    #[should_panic(expected = "fewer scalars")]
    fn a_short_fused_run_is_a_bug() {
        let _ = BundleAndSystem::from_flat(0..62);
    }

    #[test]
    #[should_panic(expected = "more scalars")]
    fn a_long_fused_run_is_a_bug() {
        let _ = BundleAndSystem::from_flat(0..64);
    }

    #[test]
    fn equation_terms_round_trip_in_field_order() {
        let shape = |psi_dot, rank_one| TermsShape { psi_dot, rank_one };
        let full = EquationTerms::from_flat(0..12, shape(false, false));
        assert_eq!(
            (full.inertia[1][0], full.right_side, full.psi_dot),
            (3, [9, 10, 11], None)
        );
        assert_eq!(full.flatten(), (0..12).collect::<Vec<_>>());
        let reduced = EquationTerms::from_flat(0..13, shape(true, false));
        assert_eq!(reduced.psi_dot, Some(12));
        assert_eq!(reduced.flatten(), (0..13).collect::<Vec<_>>());
        let split = EquationTerms::from_flat(0..17, shape(true, true));
        assert_eq!(split.rank_one, Some((13, [14, 15, 16])));
        assert_eq!(split.shape(), shape(true, true));
        assert_eq!(split.flatten(), (0..17).collect::<Vec<_>>());
        let full_split = EquationTerms::from_flat(0..16, shape(false, true));
        assert_eq!(full_split.rank_one, Some((12, [13, 14, 15])));
    }

    #[test]
    fn jacobian_terms_round_trip_in_field_order() {
        let j = JacobianTerms::from_flat(0..JACOBIAN_LEN);
        assert_eq!((j.inertia[2][2], j.right_side), (8, [9, 10, 11]));
        assert_eq!((j.dright_domega[0][0], j.dright_dgamma[0][0]), (12, 21));
        assert_eq!(j.dinertia_dgamma[0][0][0], 30);
        assert_eq!(j.dinertia_dgamma[2][2][2], 56);
        assert_eq!(j.flatten(), (0..JACOBIAN_LEN).collect::<Vec<_>>());
    }

    #[test]
    #[should_panic(expected = "fewer scalars")]
    fn a_short_run_is_a_bug() {
        let _ = Bundle::from_flat(0..35);
    }

    #[test]
    #[should_panic(expected = "more scalars")]
    fn a_long_run_is_a_bug() {
        let _ = Gyroscopic::from_flat(0..28);
    }
}
