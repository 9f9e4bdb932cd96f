// A body on a smooth plane, whose generated code is shown beside it in `ellipsoid.expanded.rs`:
// its kinetic matrix is `J = diag(I) + m v vᵀ`, so the derive emits `constant_inertia` and the
// `rank_one` part of the equations (docs/method.md §2a).
// `tests/expand.rs` re-expands this file and fails if the snapshot differs
// (run `ROUTH_BLESS=1 cargo test --test main expand::` to accept a change to the generated code).

/// A heavy ellipsoid on a smooth horizontal plane (paper Example 2, errata E1, E2, E6).
#[derive(Lagrangian)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct DiagonalEllipsoid {
    /// Principal moments of inertia `(I₁, I₂, I₃)`.
    pub inertia: Vector3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)`.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}
