//! `C` of (64) as the derive forms it (`[γ]× N [γ]×`, `N = ∂²R/∂γ² − μE`) against the matrix
//! product of errata E6, `[γ]×ᵀ(μE − ∂²R/∂γ²)[γ]×`, formed here in plain `f64` from the
//! evaluated Hessian and gradient; and the form's point: no negation among its operations.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_symbolic::{op_counts, Id};

/// The benchmark gyrostat (full symmetric I, K, general B, a potential linear in γ).
const GYROSTAT: &str = "
    #[derive(Lagrangian)]
    #[lagrangian(
        kinetic = 0.5 * omega.dot(inertia * omega),
        linear = (rotor + coupling * gamma).dot(omega),
        potential = mass * g * com.dot(gamma),
    )]
    struct Gyrostat {
        #[lagrangian(symmetric)]
        inertia: Matrix3<f64>,
        rotor: Vector3<f64>,
        coupling: Matrix3<f64>,
        com: Vector3<f64>,
        mass: f64,
        g: f64,
    }
";

/// `[v]×`.
fn skew(v: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]
}

fn matmul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn transpose(a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

#[test]
fn stiffness_is_the_matrix_product_without_negations() {
    let di: syn::DeriveInput = syn::parse_str(GYROSTAT).expect("model parses");
    let model = routh_codegen::analyse(&di).expect("model is valid");
    let (g, o) = (&model.lowered.sym.graph, &model.outputs);
    let sym = &model.lowered.sym;
    let flat = |m: &[[Id; 3]; 3]| -> Vec<Id> { m.iter().flatten().copied().collect() };

    // No negation in C's own operations: what the bundle already computes is not counted.
    let bundle = o.bundle_ids();
    let mut with_c = bundle.clone();
    with_c.extend(flat(&o.system_c));
    let (base, all) = (op_counts(g, &bundle), op_counts(g, &with_c));
    assert_eq!(all.neg, base.neg, "C forms negations: {all} against {base}");
    // μ (5), N's diagonal (3), eight entries of Y and six of C (3 each, one product shared).
    assert!(all.total() - base.total() <= 50, "C costs {all} − {base}");

    let mut rng = ChaCha8Rng::seed_from_u64(0x0057_17ff);
    let mut roots = flat(&o.system_c);
    roots.extend(flat(&o.d2r_dgamma2));
    roots.extend(o.dr_dgamma);
    let mut worst = 0.0f64;
    for _ in 0..200 {
        // Every variable random; then I positive definite (diagonally dominant), so γᵀIγ > 0.
        let mut x: Vec<f64> = (0..g.num_vars())
            .map(|_| rng.gen_range(-1.0..1.0))
            .collect();
        for p in &sym.params {
            if p.field == "inertia" {
                let v = x[p.var.index()];
                x[p.var.index()] = if matches!(p.access, routh_codegen::lower::Access::Entry(i, j) if i == j)
                {
                    3.0 + v
                } else {
                    0.5 * v
                };
            }
        }
        let v = g.eval(&roots, &x);
        let c: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|k| v[3 * i + k]));
        let h: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|k| v[9 + 3 * i + k]));
        let dr = [v[18], v[19], v[20]];
        let gamma = sym.gamma.map(|var| x[var.index()]);
        let mu: f64 = (0..3).map(|i| dr[i] * gamma[i]).sum();
        let k: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { mu - h[i][j] } else { -h[i][j] })
        });
        let gx = skew(gamma);
        let want = matmul(&matmul(&transpose(&gx), &k), &gx);
        let scale = want.iter().flatten().fold(1.0f64, |m, w| m.max(w.abs()));
        for i in 0..3 {
            for j in 0..3 {
                worst = worst.max((c[i][j] - want[i][j]).abs() / scale);
            }
        }
    }
    assert!(worst <= 1e-13, "worst relative error {worst:e}");
}
