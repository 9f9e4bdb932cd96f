//! The formulas of `DerivedFormulas` (the printed text of L, U_r and ψ̇ at Ω = 0) are the
//! functions the derive generates: each text is parsed and evaluated by the small evaluator
//! below, with the model's fields, ω, γ and p_ψ substituted, and compared with the generated
//! `lagrangian`, `amended_potential` and `psi_dot` at random points.

use std::collections::HashMap;

use derived_models::{
    AsymmetricTop, DiagonalEllipsoid, Ellipsoid, FluidBody, Gyrostat, Kirchhoff, LagrangeTop,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh::{DerivedFormulas, Matrix3, Routhian, Vector3};

// ---------------------------------------------------------------------------------------------
// An evaluator for the printed syntax: sums `a + b`, `a - b`; products `a·b`, quotients `a / b`;
// unary minus; powers `a^2`, `a^(b)`; calls `sqrt(…)` etc.; decimal constants; variables
// `name`, `name[i]`, `name[(i,j)]`, `ω₁`, `γ₃`, `p_ψ`.

#[derive(Debug, Clone, PartialEq)]
enum Token {
    Num(f64),
    Name(String),
    Op(char),
}

fn tokenize(text: &str) -> Vec<Token> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            out.push(Token::Num(
                s.parse().unwrap_or_else(|_| panic!("number {s}")),
            ));
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            if i < chars.len() && chars[i] == '[' {
                while chars[i] != ']' {
                    i += 1;
                }
                i += 1;
            }
            out.push(Token::Name(chars[start..i].iter().collect()));
        } else if "+-·/^()".contains(c) {
            out.push(Token::Op(c));
            i += 1;
        } else {
            panic!("unexpected character {c:?} in {text}");
        }
    }
    out
}

struct Parser<'a> {
    tokens: Vec<Token>,
    pos: usize,
    vars: &'a HashMap<String, f64>,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }
    fn eat(&mut self, op: char) -> bool {
        if self.peek() == Some(&Token::Op(op)) {
            self.pos += 1;
            true
        } else {
            false
        }
    }
    /// expr := term (('+' | '-') term)*
    fn expr(&mut self) -> f64 {
        let mut v = self.term();
        loop {
            if self.eat('+') {
                v += self.term();
            } else if self.eat('-') {
                v -= self.term();
            } else {
                return v;
            }
        }
    }
    /// term := unary (('·' | '/') unary)*
    fn term(&mut self) -> f64 {
        let mut v = self.unary();
        loop {
            if self.eat('·') {
                v *= self.unary();
            } else if self.eat('/') {
                v /= self.unary();
            } else {
                return v;
            }
        }
    }
    /// unary := '-' unary | atom ('^' unary)?
    fn unary(&mut self) -> f64 {
        if self.eat('-') {
            return -self.unary();
        }
        let base = self.atom();
        if self.eat('^') {
            let e = self.unary();
            if e.fract() == 0.0 && e.abs() < 64.0 {
                base.powi(e as i32)
            } else {
                base.powf(e)
            }
        } else {
            base
        }
    }
    fn atom(&mut self) -> f64 {
        let token = self.tokens.get(self.pos).cloned();
        self.pos += 1;
        match token {
            Some(Token::Num(x)) => x,
            Some(Token::Op('(')) => {
                let v = self.expr();
                assert!(self.eat(')'), "missing ')'");
                v
            }
            Some(Token::Name(name)) if self.peek() == Some(&Token::Op('(')) => {
                self.pos += 1;
                let x = self.expr();
                assert!(self.eat(')'), "missing ')' after {name}(");
                match name.as_str() {
                    "sqrt" => x.sqrt(),
                    "sin" => x.sin(),
                    "cos" => x.cos(),
                    "tan" => x.tan(),
                    "exp" => x.exp(),
                    "ln" => x.ln(),
                    "abs" => x.abs(),
                    "sign" => {
                        if x == 0.0 {
                            0.0
                        } else {
                            x.signum()
                        }
                    }
                    _ => panic!("unknown function {name}"),
                }
            }
            Some(Token::Name(name)) => *self
                .vars
                .get(&name)
                .unwrap_or_else(|| panic!("unknown variable {name}")),
            t => panic!("unexpected {t:?} at token {}", self.pos - 1),
        }
    }
}

fn eval(text: &str, vars: &HashMap<String, f64>) -> f64 {
    let mut p = Parser {
        tokens: tokenize(text),
        pos: 0,
        vars,
    };
    let v = p.expr();
    assert_eq!(p.pos, p.tokens.len(), "trailing tokens in {text}");
    v
}

#[test]
fn evaluator_reads_the_printed_syntax() {
    let vars: HashMap<String, f64> = [("x", 2.0), ("m[(0,1)]", 3.0), ("γ₁", 0.5)]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect();
    for (text, value) in [
        ("1 + 2·3 - 4 / 2", 5.0),
        ("-x^2", -4.0),
        ("(-x)^2 + x^(-1)", 4.5),
        ("2·x / (m[(0,1)]·γ₁)", 8.0 / 3.0),
        ("0.5·(x - γ₁)^2 / x", 0.5625),
        ("sqrt(x·x) - -x", 4.0),
    ] {
        assert!((eval(text, &vars) - value).abs() < 1e-15, "{text}");
    }
}

// ---------------------------------------------------------------------------------------------
// The variables of a model.

/// Binds a field's value(s) under the names the formulas use.
trait Bind {
    fn bind(&self, name: &str, vars: &mut HashMap<String, f64>);
}

impl Bind for f64 {
    fn bind(&self, name: &str, vars: &mut HashMap<String, f64>) {
        vars.insert(name.to_string(), *self);
    }
}

impl Bind for Vector3<f64> {
    fn bind(&self, name: &str, vars: &mut HashMap<String, f64>) {
        for i in 0..3 {
            vars.insert(format!("{name}[{i}]"), self[i]);
        }
    }
}

impl Bind for Matrix3<f64> {
    fn bind(&self, name: &str, vars: &mut HashMap<String, f64>) {
        for i in 0..3 {
            for j in 0..3 {
                vars.insert(format!("{name}[({i},{j})]"), self[(i, j)]);
            }
        }
    }
}

/// `name => field` pairs as a variable table.
macro_rules! fields {
    ($($name:literal => $value:expr),* $(,)?) => {{
        let mut vars = HashMap::new();
        $(Bind::bind(&$value, $name, &mut vars);)*
        vars
    }};
}

fn with_point(
    mut vars: HashMap<String, f64>,
    w: &Vector3<f64>,
    g: &Vector3<f64>,
    p: f64,
) -> HashMap<String, f64> {
    for (i, sub) in ["₁", "₂", "₃"].iter().enumerate() {
        vars.insert(format!("ω{sub}"), w[i]);
        vars.insert(format!("γ{sub}"), g[i]);
    }
    vars.insert("p_ψ".into(), p);
    vars
}

/// Evaluates the three formulas of `M` at `n` random points `(ω, γ, p_ψ)` (|γ| in [0.5, 1.5])
/// and compares them with the generated functions; returns the worst relative error.
fn check<M: Routhian + DerivedFormulas>(
    model: &M,
    vars: HashMap<String, f64>,
    rng: &mut ChaCha8Rng,
    what: &str,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..50 {
        let w = test_models::random_vector(rng, 2.0);
        let g = test_models::random_gamma(rng);
        let p = rng.gen_range(-5.0..5.0);
        let vars = with_point(vars.clone(), &w, &g, p);
        for (name, text, generated) in [
            ("L", M::LAGRANGIAN, model.lagrangian(&w, &g)),
            ("U_r", M::AMENDED_POTENTIAL, model.amended_potential(&g, p)),
            (
                "ψ̇",
                M::PSI_DOT_AT_REST,
                model.psi_dot(&Vector3::zeros(), &g, p),
            ),
        ] {
            let printed = eval(text, &vars);
            let err = (printed - generated).abs() / (1.0 + generated.abs());
            assert!(
                err <= 1e-12,
                "{what}: {name} = {text}\n  printed formula gives {printed}, generated code {generated}"
            );
            worst = worst.max(err);
        }
    }
    worst
}

#[test]
fn printed_formulas_evaluate_to_the_generated_functions() {
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let mut worst = 0.0f64;
    for _ in 0..3 {
        let m = Gyrostat::from(&test_models::Gyrostat::random(&mut rng));
        let vars = fields! {
            "inertia" => m.inertia, "rotor" => m.rotor, "coupling" => m.coupling,
            "com" => m.com, "mass" => m.mass, "g" => m.g,
        };
        worst = worst.max(check(&m, vars, &mut rng, "Gyrostat"));

        let m = Ellipsoid::from(&test_models::Ellipsoid::random(&mut rng));
        let vars = fields! {
            "inertia" => m.inertia, "semi_axes" => m.semi_axes, "offset" => m.offset,
            "mass" => m.mass, "g" => m.g,
        };
        worst = worst.max(check(&m, vars, &mut rng, "Ellipsoid"));

        let m = DiagonalEllipsoid::random(&mut rng);
        let vars = fields! {
            "inertia" => m.inertia, "semi_axes" => m.semi_axes, "offset" => m.offset,
            "mass" => m.mass, "g" => m.g,
        };
        worst = worst.max(check(&m, vars, &mut rng, "DiagonalEllipsoid"));

        let m = LagrangeTop {
            a1: rng.gen_range(0.5..2.0),
            c: rng.gen_range(0.5..2.0),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
            l: rng.gen_range(-1.0..1.0),
        };
        let vars = fields! {
            "a1" => m.a1, "c" => m.c, "mass" => m.mass, "g" => m.g, "l" => m.l,
        };
        worst = worst.max(check(&m, vars, &mut rng, "LagrangeTop"));

        let m = AsymmetricTop {
            inertia: Vector3::from_fn(|_, _| rng.gen_range(1.0..3.0)),
            com: test_models::random_vector(&mut rng, 1.0),
            mass: rng.gen_range(0.5..2.0),
            g: 9.81,
        };
        let vars = fields! { "inertia" => m.inertia, "com" => m.com, "mass" => m.mass, "g" => m.g };
        worst = worst.max(check(&m, vars, &mut rng, "AsymmetricTop"));

        let m = FluidBody::from(
            &Kirchhoff::chiral()
                .parameters(rng.gen_range(0.5..2.0))
                .unwrap(),
        );
        let vars = fields! { "a_kin" => m.a_kin, "lin" => m.lin, "pot" => m.pot };
        worst = worst.max(check(&m, vars, &mut rng, "FluidBody"));
    }
    eprintln!("worst relative difference, printed formula vs generated code: {worst:.1e}");
}
