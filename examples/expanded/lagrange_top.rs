// A small model whose generated code is shown beside it in `lagrange_top.expanded.rs`.
// `tests/expand.rs` re-expands this file and fails if the snapshot differs
// (run `ROUTH_BLESS=1 cargo test --test main expand::` to accept a change to the generated code).

/// The Lagrange top: a heavy symmetric top about a fixed point on its axis.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mgl * gamma.z,
)]
pub struct LagrangeTop {
    /// Equatorial moment of inertia A₁ about the fixed point.
    pub a1: f64,
    /// Axial moment of inertia C.
    pub c: f64,
    /// m g l: weight times the distance of the centre of mass from the fixed point.
    pub mgl: f64,
}
