//! `routh orbit` and `routh orbits --continue`, `--doubling`, `--switch`, run as a user would,
//! their numbers checked against what routh did not compute: the pendulum's period 4K(m)/ω₀ (K by
//! the arithmetic–geometric mean) for the planar swings of a heavy body J = diag(1, 2, 3) with
//! m g l = 1.5, and the period-doubled and switched orbits integrated again here by a plain RK4
//! of the Euler–Poisson equations.

mod common;

use common::{fails, ok, routh, stderr, stdout, ASYMMETRIC, SWINGING as BODY};

const BRANCHING: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/models/branching_body.toml"
);
/// m g l and J₁ of the swinging body: ω₀² = mgl/J₁.
const MGL: f64 = 1.5;
const J1: f64 = 1.0;

/// K(m) = π / (2 AGM(1, √(1 − m))), the complete elliptic integral of the first kind.
fn ellip_k(m: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - m).sqrt());
    for _ in 0..60 {
        let (a1, b1) = (0.5 * (a + b), (a * b).sqrt());
        a = a1;
        b = b1;
    }
    std::f64::consts::PI / (2.0 * a)
}

/// The pendulum's period at energy E (E = ½J₁θ̇² − mgl cos θ): 4K(m)/ω₀, m = sin²(θ_max/2),
/// cos θ_max = −E/mgl.
fn pendulum_period(e: f64) -> f64 {
    let cos_max = -e / MGL;
    let m = 0.5 * (1.0 - cos_max);
    4.0 * ellip_k(m) / (MGL / J1).sqrt()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn v3(v: &serde_json::Value) -> [f64; 3] {
    [f(&v[0]), f(&v[1]), f(&v[2])]
}

#[test]
fn orbit_period_is_the_pendulums() {
    // ω = (1, 0, 0) at the bottom: E = ½ − 1.5 = −1.0, θ_max = arccos(2/3).
    let args = [
        "orbit", BODY, "--omega", "1,0,0", "--gamma", "0,0,-1", "--period", "5.4",
    ];
    let mut json_args = args.to_vec();
    json_args.push("--json");
    let v: serde_json::Value = serde_json::from_str(&ok(&json_args)).expect("JSON");
    // The Python document of the Rust value.
    assert_eq!(v["routh"], "PeriodicOrbit");
    assert_eq!(v["format"], 1);
    let e = f(&v["energy"]);
    assert!((e - (0.5 - MGL)).abs() < 1e-12, "E = {e}");
    let t = f(&v["period"]);
    let want = pendulum_period(e);
    assert!(
        ((t - want) / want).abs() < 1e-8,
        "T = {t}, 4K(m)/ω₀ = {want}, relative {:e}",
        (t - want) / want
    );
    assert!(f(&v["p_psi"]).abs() < 1e-12);
    assert!(f(&v["precession"]).abs() < 1e-8);
    // Rust reads the CLI's JSON as its own type (the two Python keys are ignored).
    let o: routh::PeriodicOrbit = serde_json::from_value(v.clone()).expect("a PeriodicOrbit");
    assert_eq!(o.period, t);
    assert_eq!(o.omega0.x, f(&v["omega0"][0]));
    // CSV: Python's PeriodicOrbit columns, the same numbers bit for bit.
    let mut csv_args = args.to_vec();
    csv_args.push("--csv");
    let csv = ok(&csv_args);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header,
        [
            "period",
            "energy",
            "p_psi",
            "precession",
            "body_turn",
            "degenerate",
            "stability_index",
            "stability",
            "amplitude",
            "omega1",
            "omega2",
            "omega3",
            "gamma1",
            "gamma2",
            "gamma3",
            "multiplier1_re",
            "multiplier1_im",
            "multiplier2_re",
            "multiplier2_im"
        ]
    );
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(lines.next(), None);
    let col = |name: &str| row[header.iter().position(|h| *h == name).unwrap()];
    assert_eq!(col("period").parse::<f64>().unwrap(), t);
    assert_eq!(col("energy").parse::<f64>().unwrap(), e);
    assert_eq!(
        col("stability"),
        v["stability"].as_str().unwrap().to_lowercase()
    );
    // Δφ and the degenerate flag: 0 and false on a body without axial symmetry.
    assert_eq!(col("body_turn").parse::<f64>().unwrap(), f(&v["body_turn"]));
    assert_eq!(f(&v["body_turn"]), 0.0);
    assert_eq!(col("degenerate"), "false");
    assert_eq!(v["degenerate"], false);
    let g0 = v3(&v["gamma0"]);
    for (i, name) in ["gamma1", "gamma2", "gamma3"].iter().enumerate() {
        assert_eq!(col(name).parse::<f64>().unwrap(), g0[i]);
    }
    // The table.
    let table = ok(&args);
    assert!(table.starts_with("periodic orbit at p_psi = "), "{table}");
    assert!(table.contains(&format!("{t:.12}")), "{table}");
}

#[test]
fn orbit_refuses_bad_guesses_with_the_documented_codes() {
    // Bad input, exit code 2: γ not a unit vector, T ≤ 0, a steady motion, a malformed vector.
    fails(
        &[
            "orbit", BODY, "--omega", "1,0,0", "--gamma", "0,0,-2", "--period", "5",
        ],
        2,
        "unit vector",
    );
    fails(
        &[
            "orbit", BODY, "--omega", "1,0,0", "--gamma", "0,0,-1", "--period", "-5",
        ],
        2,
        "must be above 0",
    );
    fails(
        &[
            "orbit", BODY, "--omega", "1,0", "--gamma", "0,0,-1", "--period", "5",
        ],
        2,
        "not a vector",
    );
    fails(
        &["orbit", BODY, "--omega", "1,0,0", "--gamma", "0,0,-1"],
        2,
        "--period",
    );
    fails(
        &[
            "orbit",
            "no/such/model.toml",
            "--omega",
            "1,0,0",
            "--gamma",
            "0,0,-1",
            "--period",
            "5",
        ],
        2,
        "no/such/model.toml",
    );
    // The steady motion itself (nothing periodic to find): refused by the library, bad input.
    fails(
        &[
            "orbit", BODY, "--omega", "0,0,0", "--gamma", "0,0,-1", "--period", "5",
        ],
        2,
        "the guess is a steady motion",
    );
    // A failed computation, exit code 1: a corrector that does not converge from a guess far
    // from any periodic orbit of that period.
    let o = routh(&[
        "orbit",
        BODY,
        "--omega",
        "3,2,1",
        "--gamma",
        "0.6,0,0.8",
        "--period",
        "0.01",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("no periodic orbit from the guess"),
        "{}",
        stderr(&o)
    );
    assert!(!stderr(&o).contains("panicked") && stdout(&o).is_empty());
}

#[test]
fn continue_follows_the_pendulum_family() {
    // Through the swing at E = −1 over E ∈ [−1.4, −0.5]: each orbit is a swing of the pendulum,
    // its period 4K(m)/ω₀ at its own energy.
    let out = ok(&[
        "orbits",
        BODY,
        "--continue",
        "--omega",
        "1,0,0",
        "--gamma",
        "0,0,-1",
        "--period",
        "5.4",
        "--energy=-1.4..-0.5",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let fams = v.as_array().expect("an array of families");
    assert_eq!(fams.len(), 1);
    let fam = &fams[0];
    assert_eq!(fam["routh"], "OrbitFamily");
    assert_eq!(fam["origin"], "continued");
    assert!(fam["motion"].is_null() && fam["mode"].is_null());
    let orbits = fam["orbits"].as_array().unwrap();
    assert!(orbits.len() >= 5, "{} orbits", orbits.len());
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for o in orbits {
        let e = f(&o["energy"]);
        lo = lo.min(e);
        hi = hi.max(e);
        assert!((-1.4 - 1e-9..=-0.5 + 1e-9).contains(&e), "E = {e}");
        let t = f(&o["period"]);
        let want = pendulum_period(e);
        assert!(
            ((t - want) / want).abs() < 1e-8,
            "E = {e}: T = {t}, 4K(m)/ω₀ = {want}"
        );
        assert!(f(&o["p_psi"]).abs() < 1e-9);
    }
    // Both directions from E = −1 were followed.
    assert!(lo < -1.2 && hi > -0.7, "[{lo}, {hi}]");
    // Rust reads the array as its own families.
    let back: Vec<routh::OrbitFamily> = serde_json::from_str(&out).expect("OrbitFamily values");
    assert_eq!(back[0].orbits.len(), orbits.len());
    // CSV: one row per orbit, then the events; the initial conditions are the JSON's.
    let csv = ok(&[
        "orbits",
        BODY,
        "--continue",
        "--omega",
        "1,0,0",
        "--gamma",
        "0,0,-1",
        "--period",
        "5.4",
        "--energy=-1.4..-0.5",
        "--csv",
    ]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    let col = |r: &Vec<&str>, name: &str| -> String {
        r[header.iter().position(|h| *h == name).unwrap()].to_string()
    };
    let orbit_rows: Vec<&Vec<&str>> = rows.iter().filter(|r| col(r, "kind") == "orbit").collect();
    assert_eq!(orbit_rows.len(), orbits.len());
    assert_eq!(
        rows.len(),
        orbits.len() + fam["events"].as_array().unwrap().len()
    );
    for (r, o) in orbit_rows.iter().zip(orbits) {
        assert_eq!(col(r, "origin"), "continued");
        assert_eq!(col(r, "period").parse::<f64>().unwrap(), f(&o["period"]));
        assert_eq!(col(r, "omega1").parse::<f64>().unwrap(), f(&o["omega0"][0]));
        assert_eq!(col(r, "gamma3").parse::<f64>().unwrap(), f(&o["gamma0"][2]));
    }
}

#[test]
fn continue_refuses_what_it_cannot_do() {
    let guess = ["--omega", "1,0,0", "--gamma", "0,0,-1", "--period", "5.4"];
    // The orbit's energy (−1) outside the range: bad input, named.
    let mut a = vec!["orbits", BODY, "--continue"];
    a.extend(guess);
    a.push("--energy=-0.9..-0.5");
    fails(&a, 2, "outside --energy");
    // No range, no guess, a momentum besides the guess: usage errors.
    let mut a = vec!["orbits", BODY, "--continue"];
    a.extend(guess);
    fails(&a, 2, "--energy");
    fails(
        &["orbits", BODY, "--continue", "--energy=-1.4..-0.5"],
        2,
        "--omega",
    );
    let mut a = vec![
        "orbits",
        BODY,
        "--continue",
        "-p",
        "0",
        "--energy=-1.4..-0.5",
    ];
    a.extend(guess);
    fails(&a, 2, "cannot be used with");
    // A guess without --continue, and no momentum at all.
    fails(
        &[
            "orbits", BODY, "-p", "0", "--omega", "1,0,0", "--period", "5",
        ],
        2,
        "--continue",
    );
    fails(&["orbits", BODY], 2, "--momentum");
}

const SWING_IN_A: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/models/swinging_in_a.toml"
);

/// The arguments of `routh orbits` continuing the swing of amplitude arccos(2/3) (E = −1) of
/// tests/models/swinging_in_a.toml through `--parameter` `par`, and `extra`.
fn through<'a>(par: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut a = vec![
        "orbits",
        SWING_IN_A,
        "--continue",
        "--omega",
        "1,0,0",
        "--gamma",
        "0,0,-1",
        "--period",
        "5.4",
        "--parameter",
        par,
    ];
    a.extend(extra);
    a
}

#[test]
fn continue_through_a_parameter_follows_the_pendulum_at_fixed_energy() {
    // J = diag(a, 2, 3), mgl = 1.5: at E = −1 each planar swing is a pendulum of amplitude
    // θ₀ = arccos(2/3) whatever a, ω₀ = √(mgl/a): T(a) = 4K(sin²(θ₀/2))/√(mgl/a).
    let out = ok(&through("a=0.8..1.5", &["--json"]));
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let fams = v.as_array().expect("an array of families");
    assert_eq!(fams.len(), 1);
    let fam = &fams[0];
    assert_eq!(fam["routh"], "OrbitFamily");
    assert_eq!(fam["origin"], "continued");
    assert_eq!(fam["parameter_name"], "a");
    assert!(fam["stop"].is_null(), "{}", fam["stop"]);
    let orbits = fam["orbits"].as_array().unwrap();
    let a: Vec<f64> = fam["parameter"].as_array().unwrap().iter().map(f).collect();
    assert_eq!(a.len(), orbits.len());
    assert_eq!(
        fam["event_parameter"].as_array().unwrap().len(),
        fam["events"].as_array().unwrap().len()
    );
    assert!(orbits.len() >= 5, "{} orbits", orbits.len());
    // From one end of the range to the other, both reached (the family is monotone in a).
    assert_eq!((a[0], a[a.len() - 1]), (0.8, 1.5), "{a:?}");
    let theta0 = (2.0f64 / 3.0).acos();
    let m = (theta0 / 2.0).sin().powi(2);
    for (o, &a) in orbits.iter().zip(&a) {
        assert!((0.8..=1.5).contains(&a), "a = {a}");
        let e = f(&o["energy"]);
        assert!((e + 1.0).abs() < 1e-9, "a = {a}: E = {e}");
        assert!(f(&o["p_psi"]).abs() < 1e-9);
        let t = f(&o["period"]);
        let want = 4.0 * ellip_k(m) / (MGL / a).sqrt();
        assert!(
            (t - want).abs() < 1e-8,
            "a = {a}: T = {t}, 4K(m)/√(mgl/a) = {want}, off by {:e}",
            t - want
        );
    }
    // Rust reads the array as its own families (the three keys more are ignored).
    let back: Vec<routh::OrbitFamily> = serde_json::from_str(&out).expect("OrbitFamily values");
    assert_eq!(back[0].orbits.len(), orbits.len());
    // CSV: `parameter_name, parameter` at the end, a row per orbit, the JSON's numbers.
    let csv = ok(&through("a=0.8..1.5", &["--csv"]));
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[header.len() - 2..], ["parameter_name", "parameter"]);
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    assert_eq!(
        rows.len(),
        orbits.len() + fam["events"].as_array().unwrap().len()
    );
    let col = |r: &Vec<&str>, name: &str| -> String {
        r[header.iter().position(|h| *h == name).unwrap()].to_string()
    };
    for ((r, o), &a) in rows.iter().zip(orbits).zip(&a) {
        assert_eq!(col(r, "kind"), "orbit");
        assert_eq!(col(r, "parameter_name"), "a");
        assert_eq!(col(r, "parameter").parse::<f64>().unwrap(), a);
        assert_eq!(col(r, "period").parse::<f64>().unwrap(), f(&o["period"]));
    }
    // The table: a column named after the parameter, the range in the title.
    let table = ok(&through("a=0.8..1.5", &[]));
    assert!(
        table.contains("at a = 1 over a in [0.8, 1.5] at fixed energy"),
        "{table}"
    );
    let head = table
        .lines()
        .find(|l| l.starts_with('#'))
        .expect("a header");
    assert_eq!(
        head.split_whitespace().take(4).collect::<Vec<_>>(),
        ["#", "a", "E", "T"]
    );
}

#[test]
fn continue_through_the_momentum_keeps_the_energy() {
    // `momentum`: p_ψ itself; each orbit's p_ψ is the parameter printed, its energy the swing's.
    let out = ok(&through(
        "momentum=-0.2..0.2",
        &["--json", "--max-orbits", "9"],
    ));
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let fam = &v[0];
    assert_eq!(fam["parameter_name"], "momentum");
    let orbits = fam["orbits"].as_array().unwrap();
    assert_eq!(orbits.len(), 9);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (o, p) in orbits.iter().zip(fam["parameter"].as_array().unwrap()) {
        let p = f(p);
        lo = lo.min(p);
        hi = hi.max(p);
        assert!(
            (f(&o["p_psi"]) - p).abs() < 1e-9,
            "p_psi {} at {p}",
            o["p_psi"]
        );
        assert!((f(&o["energy"]) + 1.0).abs() < 1e-9);
    }
    assert!(lo < 0.0 && hi > 0.0, "[{lo}, {hi}]");
}

#[test]
fn continue_through_a_parameter_refuses_what_it_cannot_do() {
    // The file's a = 1 outside the range, an unknown name, a vector parameter, the guess's
    // p_ψ = 0 outside a momentum range: bad input, named.
    fails(&through("a=1.1..1.5", &[]), 2, "outside the range");
    fails(&through("b=0.8..1.5", &[]), 2, "unknown parameter `b`");
    fails(&through("momentum=0.1..1", &[]), 2, "outside the range");
    let mut a = through("inertia=0.8..1.5", &[]);
    a[1] = BODY;
    fails(&a, 2, "Vector3<f64>");
    // Not with --energy, --doubling, --switch, --svg; not without --continue; a bad range.
    fails(
        &through("a=0.8..1.5", &["--energy=-1.2..-0.5"]),
        2,
        "cannot be used with",
    );
    fails(
        &through("a=0.8..1.5", &["--switch"]),
        2,
        "cannot be used with",
    );
    fails(
        &through("a=0.8..1.5", &["--doubling"]),
        2,
        "cannot be used with",
    );
    fails(
        &through("a=0.8..1.5", &["--svg", "/nonexistent/f.svg"]),
        2,
        "cannot be used with",
    );
    fails(
        &["orbits", SWING_IN_A, "-p", "0", "--parameter", "a=0.8..1.5"],
        2,
        "--continue",
    );
    fails(&through("a=1.5..0.8", &[]), 2, "inverted");
    fails(&through("a", &[]), 2, "NAME=LO..HI");
    // A guess that the corrector cannot close (a period far too short): a failed computation.
    let mut a = through("a=0.8..1.5", &[]);
    a[8] = "0.3";
    fails(&a, 1, "no periodic orbit");
}

/// A heavy body for the Euler–Poisson equations: J = diag(`j`) about the fixed point, the
/// centre of mass at m g c = `c`.
struct Body {
    j: [f64; 3],
    c: [f64; 3],
}

/// The asymmetric top of examples/models/asymmetric_top.toml.
const ASYMMETRIC_TOP: Body = Body {
    j: [1.0, 3.0, 6.0],
    c: [0.4, 0.3, 1.5],
};

/// The body of tests/models/branching_body.toml.
const BRANCHING_BODY: Body = Body {
    j: [1.0, 1.6, 2.3],
    c: [0.0, 0.0, 1.0],
};

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl Body {
    /// The Euler–Poisson equations: Jω' = Jω × ω + γ × mgc, γ' = γ × ω.
    fn rhs(&self, x: &[f64; 6]) -> [f64; 6] {
        let j = self.j;
        let (w, g) = ([x[0], x[1], x[2]], [x[3], x[4], x[5]]);
        let jw = [j[0] * w[0], j[1] * w[1], j[2] * w[2]];
        let t1 = cross(jw, w);
        let t2 = cross(g, self.c);
        let dg = cross(g, w);
        [
            (t1[0] + t2[0]) / j[0],
            (t1[1] + t2[1]) / j[1],
            (t1[2] + t2[2]) / j[2],
            dg[0],
            dg[1],
            dg[2],
        ]
    }

    /// The states over time `t` by RK4 with `n` steps: `n + 1` of them, `x0` first.
    fn path(&self, x0: [f64; 6], t: f64, n: usize) -> Vec<[f64; 6]> {
        let h = t / n as f64;
        let add = |x: &[f64; 6], k: &[f64; 6], s: f64| {
            let mut y = *x;
            for i in 0..6 {
                y[i] += s * k[i];
            }
            y
        };
        let mut x = x0;
        let mut out = Vec::with_capacity(n + 1);
        out.push(x);
        for _ in 0..n {
            let k1 = self.rhs(&x);
            let k2 = self.rhs(&add(&x, &k1, 0.5 * h));
            let k3 = self.rhs(&add(&x, &k2, 0.5 * h));
            let k4 = self.rhs(&add(&x, &k3, h));
            for i in 0..6 {
                x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            out.push(x);
        }
        out
    }

    /// The state after time `t` by RK4 with `n` steps.
    fn rk4(&self, x0: [f64; 6], t: f64, n: usize) -> [f64; 6] {
        *self.path(x0, t, n).last().expect("n + 1 states")
    }
}

/// (ω₀, γ₀) of an orbit's JSON.
fn start(o: &serde_json::Value) -> [f64; 6] {
    let (w, g) = (v3(&o["omega0"]), v3(&o["gamma0"]));
    [w[0], w[1], w[2], g[0], g[1], g[2]]
}

fn distance(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

#[test]
fn doubling_follows_the_period_doubled_families() {
    // The hanging asymmetric top's mode-0 swings have two period doublings within 40 orbits
    // (tests/cli.rs). Each starts a family of orbits of twice the period: integrated again here,
    // its orbits close after T and not after T/2.
    let out = ok(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
        "--doubling",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let fams = v.as_array().unwrap();
    let parent = &fams[0];
    assert_eq!(parent["origin"], "lyapunov");
    assert_eq!(parent["mode"], 0);
    assert_eq!(parent["motion"]["routh"], "SteadyMotion");
    let doublings: Vec<usize> = parent["events"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .filter(|(_, e)| e["kind"] == "PeriodDoubling")
        .map(|(j, _)| j)
        .collect();
    assert_eq!(doublings.len(), 2);
    let doubled: Vec<&serde_json::Value> = fams
        .iter()
        .filter(|f| f["origin"] == "period_doubled")
        .collect();
    assert_eq!(doubled.len(), 2, "one family per period doubling");
    for d in &doubled {
        assert_eq!(d["parent"], 0);
        let j = d["event"].as_u64().unwrap() as usize;
        assert!(doublings.contains(&j));
        let event = &parent["events"][j];
        let t_event = f(&event["orbit"]["period"]);
        let orbits = d["orbits"].as_array().unwrap();
        assert!(orbits.len() >= 3, "{} orbits", orbits.len());
        // Born at the event: twice its period, k = 2k² − 1 = +1 there.
        let first = &orbits[0];
        let t = f(&first["period"]);
        assert!(
            (t / (2.0 * t_event) - 1.0).abs() < 2e-2,
            "T = {t}, 2T_event = {}",
            2.0 * t_event
        );
        assert!((f(&first["energy"]) - f(&event["energy"])).abs() < 1e-2);
        for o in orbits.iter().take(3).chain(orbits.last()) {
            let x0 = start(o);
            let t = f(&o["period"]);
            let scale = 1.0 + x0[..3].iter().map(|x| x * x).sum::<f64>().sqrt();
            let closed = distance(&ASYMMETRIC_TOP.rk4(x0, t, 40_000), &x0);
            assert!(
                closed < 1e-7 * scale,
                "not closed after T = {t}: {closed:e}"
            );
            let half = distance(&ASYMMETRIC_TOP.rk4(x0, 0.5 * t, 20_000), &x0);
            assert!(
                half > 1e-4 * scale,
                "closed after T/2 = {}: {half:e}",
                0.5 * t
            );
        }
    }
    // The table says which family followed which event.
    let table = ok(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
        "--doubling",
    ]);
    assert!(
        table.contains("(followed: family 1)") && table.contains("(followed: family 2)"),
        "{table}"
    );
    assert!(table.contains("period-doubled, born at event"), "{table}");
    // CSV: every family's orbits, then the events, the doubled families naming their parent.
    let csv = ok(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
        "--doubling",
        "--csv",
    ]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let n_orbits: usize = fams
        .iter()
        .map(|f| f["orbits"].as_array().unwrap().len())
        .sum();
    let n_events: usize = fams
        .iter()
        .map(|f| f["events"].as_array().unwrap().len())
        .sum();
    assert_eq!(rows.len(), n_orbits + n_events);
    // The events come after every orbit: their own section.
    let first_event = rows.iter().position(|r| r[at("kind")] != "orbit").unwrap();
    assert!(rows[first_event..].iter().all(|r| r[at("kind")] != "orbit"));
    assert!(rows[..first_event]
        .iter()
        .all(|r| r[at("before")].is_empty()));
    let pd: Vec<&Vec<&str>> = rows
        .iter()
        .filter(|r| r[at("kind")] == "period_doubling" && r[at("family")] == "0")
        .collect();
    assert_eq!(pd.len(), 2);
    for r in pd {
        let k: f64 = r[at("stability_index")].parse().unwrap();
        assert!((k + 1.0).abs() < 1e-6, "k = {k}");
        assert!(!r[at("omega1")].is_empty() && !r[at("before")].is_empty());
    }
    assert!(rows
        .iter()
        .any(|r| r[at("origin")] == "period_doubled" && r[at("parent")] == "0"));
}

#[test]
fn doubling_without_a_period_doubling_says_so() {
    let o = routh(&[
        "orbits",
        BODY,
        "--continue",
        "--omega",
        "1,0,0",
        "--gamma",
        "0,0,-1",
        "--period",
        "5.4",
        "--energy=-1.2..-0.9",
        "--doubling",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("no period doubling along the families computed"),
        "{}",
        stdout(&o)
    );
}

/// `orbits` of the branching body's planar swings (mode 0 at the hanging rest, p_ψ = 0), with
/// `extra` options.
fn branching(extra: &[&str]) -> String {
    let mut args = vec![
        "orbits",
        BRANCHING,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "0,0,-1",
        "--max-orbits",
        "30",
    ];
    args.extend(extra);
    ok(&args)
}

/// The largest |γ₁| and |ω₂| + |ω₃| along one period of an orbit: 0 on a planar swing about e₁.
fn off_plane(o: &serde_json::Value) -> f64 {
    let path = BRANCHING_BODY.path(start(o), f(&o["period"]), 4_000);
    path.iter()
        .map(|x| x[3].abs().max(x[1].abs() + x[2].abs()))
        .fold(0.0, f64::max)
}

#[test]
fn switch_follows_the_family_crossing_at_the_branch_point() {
    // A heavy body J = diag(1, 1.6, 2.3), m g l = 1 hanging at p_ψ = 0: its mode-0 orbits are
    // planar swings about e₁ (the smallest moment); at E ≈ 0.2725 they lose stability at a
    // branch point, where a family of non-planar orbits crosses them (a pitchfork: the
    // swings' plane is a plane of symmetry), its energy stationary there.
    let out = branching(&["--switch", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let fams = v.as_array().unwrap();
    assert_eq!(fams.len(), 2, "the swings and one switched family");
    let (parent, switched) = (&fams[0], &fams[1]);
    assert_eq!(parent["origin"], "lyapunov");
    assert_eq!(switched["origin"], "switched");
    assert_eq!(switched["parent"], 0);
    assert!(switched["motion"].is_null() && switched["mode"].is_null());
    let j = switched["event"].as_u64().unwrap() as usize;
    let event = &parent["events"][j];
    assert_eq!(event["kind"], "BranchPoint");
    let e_branch = f(&event["energy"]);
    assert!((0.2..0.35).contains(&e_branch), "E = {e_branch}");
    // The parent's orbits are planar swings.
    for o in parent["orbits"].as_array().unwrap().iter().step_by(7) {
        assert!(
            off_plane(o) < 1e-9,
            "a swing leaves the plane: {}",
            off_plane(o)
        );
        assert!(f(&o["precession"]).abs() < 1e-9);
    }
    let orbits = switched["orbits"].as_array().unwrap();
    assert!(orbits.len() >= 10, "{} orbits", orbits.len());
    // Through the branch point: the energy is least there, with the event's period.
    let nearest = orbits
        .iter()
        .min_by(|a, b| f(&a["energy"]).total_cmp(&f(&b["energy"])))
        .unwrap();
    assert!(
        (f(&nearest["energy"]) - e_branch).abs() < 2e-2,
        "least E {} against the branch point's {e_branch}",
        f(&nearest["energy"])
    );
    let t_event = f(&event["orbit"]["period"]);
    assert!((f(&nearest["period"]) / t_event - 1.0).abs() < 1e-2);
    // Both ways from the branch point: above it on either side, with Δψ of both signs.
    let precessions: Vec<f64> = orbits.iter().map(|o| f(&o["precession"])).collect();
    assert!(precessions.iter().any(|p| *p > 0.1) && precessions.iter().any(|p| *p < -0.1));
    // Each orbit closes (integrated again here), and is not a planar swing: it leaves the plane.
    for o in orbits.iter().step_by(6).chain(orbits.last()) {
        let x0 = start(o);
        let t = f(&o["period"]);
        assert_eq!(f(&o["body_turn"]), 0.0);
        assert_eq!(o["degenerate"], false);
        let scale = 1.0 + x0[..3].iter().map(|x| x * x).sum::<f64>().sqrt();
        let closed = distance(&BRANCHING_BODY.rk4(x0, t, 40_000), &x0);
        assert!(
            closed < 1e-7 * scale,
            "not closed after T = {t}: {closed:e}"
        );
        if (f(&o["energy"]) - e_branch).abs() > 0.05 {
            assert!(off_plane(o) > 1e-2, "E = {}: planar", f(&o["energy"]));
        }
    }
    // The table and the CSV name it.
    let table = branching(&["--switch"]);
    assert!(table.contains(", 1 switched family"), "{table}");
    assert!(table.contains("(followed: family 1)"), "{table}");
    assert!(
        table.contains("switched, crossing family 0 at its branch point"),
        "{table}"
    );
    let csv = branching(&["--switch", "--csv"]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let switched_rows: Vec<&Vec<&str>> = rows
        .iter()
        .filter(|r| r[at("origin")] == "switched" && r[at("kind")] == "orbit")
        .collect();
    assert_eq!(switched_rows.len(), orbits.len());
    for (r, o) in switched_rows.iter().zip(orbits) {
        assert_eq!(r[at("family")], "1");
        assert_eq!(r[at("parent")], "0");
        assert_eq!(r[at("body_turn")], "0");
        assert_eq!(r[at("degenerate")], "false");
        assert_eq!(r[at("omega2")].parse::<f64>().unwrap(), start(o)[1]);
    }
}

#[test]
fn switch_refuses_what_it_cannot_do() {
    // No branch point along the swings of the pendulum-like body over this range: said.
    let out = ok(&[
        "orbits",
        BODY,
        "--continue",
        "--omega",
        "1,0,0",
        "--gamma",
        "0,0,-1",
        "--period",
        "5.4",
        "--energy=-1.2..-0.9",
        "--switch",
        "--doubling",
    ]);
    assert!(
        out.contains("skipped: --switch: no branch point along the families computed"),
        "{out}"
    );
    assert!(out.contains("0 switched families"), "{out}");
    // Figures draw one family: not with the families born at events (a usage error, before
    // any computation; no file written).
    let svg = std::env::temp_dir().join(format!("routh-switch-{}.svg", std::process::id()));
    let svg = svg.to_str().unwrap();
    for flag in ["--switch", "--doubling"] {
        for figure in ["--svg", "--periods-svg"] {
            fails(
                &[
                    "orbits", BRANCHING, "-p", "0", "--mode", "0", flag, figure, svg,
                ],
                2,
                "cannot be used with",
            );
        }
    }
    assert!(!std::path::Path::new(svg).exists());
}

/// The commands whose output routh-py/tests/test_cli_json.py reads from routh-py/tests/data/
/// (the Python tests do not need a built CLI): the file and the arguments after `routh`.
fn python_data() -> [(&'static str, Vec<&'static str>); 3] {
    [
        (
            "cli_orbit.json",
            vec![
                "orbit", BODY, "--omega", "1,0,0", "--gamma", "0,0,-1", "--period", "5.4", "--json",
            ],
        ),
        (
            "cli_orbits.json",
            vec![
                "orbits",
                ASYMMETRIC,
                "-p",
                "0",
                "--mode",
                "0",
                "--gamma=-0.25,-0.19,-0.95",
                "--max-orbits",
                "20",
                "--energy=-1.6..-0.85",
                "--doubling",
                "--json",
            ],
        ),
        (
            "cli_orbits_parameter.json",
            through("a=0.8..1.5", &["--max-orbits", "8", "--json"]),
        ),
    ]
}

/// The shape of a JSON value: its keys, array lengths and strings, every number as `0`.
fn shape(v: &serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match v {
        Value::Number(_) => Value::from(0),
        Value::Array(a) => Value::Array(a.iter().map(shape).collect()),
        Value::Object(o) => Value::Object(o.iter().map(|(k, v)| (k.clone(), shape(v))).collect()),
        v => v.clone(),
    }
}

#[test]
fn the_python_tests_data_is_what_the_cli_prints() {
    // The CLI still prints what the Python tests read: the same keys (a field added to
    // PeriodicOrbit must reach the data too), families, orbits, events and strings. With
    // ROUTH_BLESS=1 the files are written again from the CLI.
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../routh-py/tests/data");
    for (name, args) in python_data() {
        let out = ok(&args);
        let path = dir.join(name);
        if std::env::var_os("ROUTH_BLESS").is_some_and(|v| v == "1") {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&path, &out).unwrap();
        }
        let kept = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (ROUTH_BLESS=1 writes it)", path.display()));
        let (kept, now): (serde_json::Value, serde_json::Value) = (
            serde_json::from_str(&kept).expect("JSON"),
            serde_json::from_str(&out).expect("JSON"),
        );
        assert_eq!(
            shape(&kept),
            shape(&now),
            "{name} is not what `routh {}` prints now (ROUTH_BLESS=1 writes it again)",
            args.join(" ")
        );
    }
}

/// Ctrl-C (SIGINT, sent with `kill`) during a section that runs for minutes (2000 orbits of 5000
/// crossings): the run ends with exit code 130 and "interrupted",
/// writes no figure and leaves no temporary file; the time bound is a loose one for a loaded
/// machine, the analyses stop within an integration step.
#[cfg(unix)]
#[test]
fn ctrl_c_ends_a_long_run_at_once_and_writes_nothing() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let dir = std::env::temp_dir().join(format!("routh-cli-sigint-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("s.svg");
    let svg_arg = svg.to_str().unwrap().to_string();
    let runs: [Vec<&str>; 1] = [vec![
        "section",
        BODY,
        "-p",
        "0",
        "-e",
        "-1",
        "--orbits",
        "2000",
        "--crossings",
        "5000",
        "--svg",
        &svg_arg,
    ]];
    for args in runs {
        let child = Command::new(env!("CARGO_BIN_EXE_routh"))
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(700));
        let sent = Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(sent.success());
        let t0 = Instant::now();
        let out = child.wait_with_output().unwrap();
        let waited = t0.elapsed();
        assert_eq!(out.status.code(), Some(130), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains("interrupted"), "{}", stderr(&out));
        assert!(waited < Duration::from_secs(5), "{args:?}: {waited:?}");
        let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
