//! `nonlinear_stability` on models with a Routh-function tape (the derive's and a run-time
//! `Model`'s), against the same method fed by a hand-written `R` (39) evaluated at jets: the
//! tape must give the same frequencies, Krein signs, Birkhoff coefficients and verdicts.

use routh::nonlinear::{nonlinear_stability_with, Jet};
use routh::{
    nonlinear_stability, Lagrangian, Model, NonlinearOptions, NonlinearVerdict, Stability,
    SteadyMotion, Vector3,
};

/// A heavy top with principal moments `inertia` and centre of mass on e₃ at height `l` (m g = 1).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = l * gamma.z,
)]
struct Top {
    inertia: Vector3<f64>,
    l: f64,
}

/// `R = ½ΩᵀIΩ − l γ₃ − ½(p − (IΩ)·γ)²/(γᵀIγ)` (39), written by hand over jets.
fn hand_r(top: &Top) -> impl Fn(&[Jet; 3], &[Jet; 3], f64) -> Jet + '_ {
    move |w: &[Jet; 3], g: &[Jet; 3], p: f64| {
        let i = top.inertia;
        let iw = [w[0] * i.x, w[1] * i.y, w[2] * i.z];
        let ig = [g[0] * i.x, g[1] * i.y, g[2] * i.z];
        let dot = |a: &[Jet; 3], b: &[Jet; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let q = -dot(&iw, g) + p;
        dot(&iw, w) * 0.5 - g[2] * top.l - q * q / dot(&ig, g) * 0.5
    }
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-9 * scale.max(1.0)
}

#[test]
fn the_tape_gives_the_hand_written_normal_form() {
    let opts = NonlinearOptions::default();
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z";
    // An asymmetric prolate top (I₃ smallest) sleeping at momenta on its gyroscopic stretch, and
    // a Lagrange top above Maievskii's bound.
    for (inertia, p) in [
        (Vector3::new(2.0, 2.5, 1.5), 6.0),
        (Vector3::new(2.0, 2.5, 1.5), 9.0),
        (Vector3::new(1.0, 1.0, 0.8), 2.5),
    ] {
        let top = Top { inertia, l: 1.0 };
        let runtime = Model::new(text, &[("inertia", inertia.into()), ("l", 1.0.into())]).unwrap();
        let s = SteadyMotion::at(&top, Vector3::z(), p, true).unwrap();
        let hand = nonlinear_stability_with(&top, &s, &hand_r(&top), &opts).unwrap();
        assert_eq!(hand.linear.verdict, Stability::GyroscopicallyStabilized);
        let derived = nonlinear_stability(&top, &s, &opts).unwrap();
        let s_rt = SteadyMotion::at(&runtime, Vector3::z(), p, true).unwrap();
        let from_text = nonlinear_stability(&runtime, &s_rt, &opts).unwrap();
        for rep in [&derived, &from_text] {
            assert_eq!(rep.verdict, hand.verdict, "{rep}\nvs\n{hand}");
            assert_eq!(rep.krein_signs, hand.krein_signs);
            assert_eq!(rep.resonance, hand.resonance);
            for k in 0..2 {
                assert!(close(
                    rep.frequencies[k],
                    hand.frequencies[k],
                    hand.frequencies[0]
                ));
            }
            let scale = hand.normal_form.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            for k in 0..3 {
                assert!(
                    close(rep.normal_form[k], hand.normal_form[k], scale),
                    "c[{k}]: {} vs {}",
                    rep.normal_form[k],
                    hand.normal_form[k]
                );
            }
        }
        assert_ne!(hand.verdict, NonlinearVerdict::Unstable, "{hand}");
    }
}
