//! The generated methods of the impls, each a straight-line body written by
//! [`Emitter::body`] (or [`Emitter::body_in_parts`]) and the literal assembling its outputs
//! into the result type; and the methods returning the interval and Routhian tapes.

use crate::emit::{Emitter, Inputs};
use crate::equations::Equations;
use crate::inertia::RankOne;
use crate::layout::{Bundle, BundleAndSystem, EquationTerms, Gyroscopic, JacobianTerms};
use crate::lower::Symbols;
use crate::nodes::{M3, V3};
use crate::reduce::Outputs;
use routh_symbolic::Id;
use std::fmt::Write;

/// `__Vector3::new(a, b, c)` / `__Matrix3::new(...)`.
fn construct(out: &mut String, ty: &str, t: &[String]) {
    out.push_str(ty);
    out.push_str("::new(");
    out.push_str(&t.join(", "));
    out.push(')');
}

fn flat_m(m: &M3) -> Vec<Id> {
    m.iter().flatten().copied().collect()
}

/// `__RouthBundle { .. }` from the tokens naming each output.
fn bundle_literal(s: &mut String, b: &Bundle<String>) {
    let _ = write!(
        s,
        "__RouthBundle {{\nrouthian: {},\npsi_dot: {},\ndr_domega: ",
        b.routhian, b.psi_dot
    );
    construct(s, "__Vector3", &b.dr_domega);
    s.push_str(",\ndr_dgamma: ");
    construct(s, "__Vector3", &b.dr_dgamma);
    let _ = write!(s, ",\ndr_dp: {},\nd2r_domega2: ", b.dr_dp);
    construct(s, "__Matrix3", b.d2r_domega2.as_flattened());
    s.push_str(",\nd2r_domega_dgamma: ");
    construct(s, "__Matrix3", b.d2r_domega_dgamma.as_flattened());
    s.push_str(",\nd2r_dgamma2: ");
    construct(s, "__Matrix3", b.d2r_dgamma2.as_flattened());
    s.push_str(",\n}");
}

/// `__GyroscopicSystem { .. }` from the tokens naming `A`, `G`, `C`.
fn system_literal(s: &mut String, m: &Gyroscopic<String>) {
    s.push_str("__GyroscopicSystem {\na: ");
    construct(s, "__Matrix3", m.a.as_flattened());
    s.push_str(",\ng: ");
    construct(s, "__Matrix3", m.g.as_flattened());
    s.push_str(",\nc: ");
    construct(s, "__Matrix3", m.c.as_flattened());
    s.push_str(",\n}");
}

/// One generated method: outputs, then how to assemble them.
enum Ret {
    Scalar(Id),
    Vector(V3),
    Matrix(M3),
    /// `Some(matrix)`.
    SomeMatrix(M3),
}

/// The arguments of the Lagrangian methods.
const WG: &str = ", __omega: &__Vector3, __gamma: &__Vector3";
/// The arguments of the Routhian methods.
const ROUTH: &str = ", __big_omega: &__Vector3, __gamma: &__Vector3, __p_psi: __F64";
/// The arguments of the methods at rest.
const REST: &str = ", __gamma: &__Vector3, __p_psi: __F64";

impl Emitter<'_> {
    /// Writes `#[inline] fn name(&self<args>) -> ret_ty { ... }`; `args` is empty or starts
    /// with `, ` (as [`WG`], [`ROUTH`] and [`REST`] do).
    fn method(&self, out: &mut String, name: &str, args: &str, ret: Ret, inputs: Inputs) {
        let (ids, ret_ty) = match &ret {
            Ret::Scalar(s) => (vec![*s], "__F64"),
            Ret::Vector(v) => (v.to_vec(), "__Vector3"),
            Ret::Matrix(m) => (flat_m(m), "__Matrix3"),
            Ret::SomeMatrix(m) => (flat_m(m), "__MaybeMatrix3"),
        };
        let _ = writeln!(out, "#[inline]\nfn {name}(&self{args}) -> {ret_ty} {{");
        let outs = self.body(out, &ids, inputs);
        match ret {
            Ret::Scalar(_) => out.push_str(&outs[0]),
            Ret::Vector(_) | Ret::Matrix(_) => construct(out, ret_ty, &outs),
            Ret::SomeMatrix(_) => {
                out.push_str("__MaybeMatrix3::Some(");
                construct(out, "__Matrix3", &outs);
                out.push(')');
            }
        }
        out.push_str("\n}\n");
    }

    /// The methods of `impl Lagrangian`.
    pub fn lagrangian_methods(
        &self,
        o: &Outputs,
        eq: &Equations,
        rank_one: Option<&RankOne>,
    ) -> String {
        let mut out = String::new();
        let l = Inputs::Lagrangian;
        let s = &mut out;
        self.method(s, "lagrangian", WG, Ret::Scalar(o.lagrangian), l);
        self.method(s, "dl_domega", WG, Ret::Vector(o.dl_domega), l);
        self.method(s, "dl_dgamma", WG, Ret::Vector(o.dl_dgamma), l);
        let gonly = ", __gamma: &__Vector3";
        self.method(s, "d2l_domega2", gonly, Ret::Matrix(o.d2l_domega2), l);
        let mx = Ret::Matrix(o.d2l_domega_dgamma);
        self.method(s, "d2l_domega_dgamma", WG, mx, l);
        self.method(s, "energy", WG, Ret::Scalar(o.energy), l);
        self.method(s, "cyclic_momentum", WG, Ret::Scalar(o.cyclic_momentum), l);
        if let Some(r) = rank_one {
            self.method(s, "constant_inertia", "", Ret::SomeMatrix(r.constant), l);
        }
        let terms = EquationTerms {
            inertia: o.d2l_domega2,
            right_side: eq.full,
            psi_dot: None,
            rank_one: rank_one.map(|r| (r.weight, r.vector)),
        };
        self.equations_method(s, "full_equations", WG, "__FullEquations", terms, l);
        self.jacobian_method(s, &eq.jacobian);
        out
    }

    /// Writes `full_jacobian`: `J`, the right side of (8) and their first derivatives in
    /// `(ω, γ)` from one straight-line body.
    fn jacobian_method(&self, out: &mut String, terms: &JacobianTerms<Id>) {
        let _ = writeln!(
            out,
            "#[inline]\nfn full_jacobian(&self{WG}) -> __FullJacobian {{"
        );
        let outs = self.body(out, &terms.flatten(), Inputs::Lagrangian);
        let t = JacobianTerms::from_flat(outs);
        out.push_str("__FullJacobian {\ninertia: ");
        construct(out, "__Matrix3", t.inertia.as_flattened());
        out.push_str(",\nright_side: ");
        construct(out, "__Vector3", &t.right_side);
        out.push_str(",\ndright_domega: ");
        construct(out, "__Matrix3", t.dright_domega.as_flattened());
        out.push_str(",\ndright_dgamma: ");
        construct(out, "__Matrix3", t.dright_dgamma.as_flattened());
        out.push_str(",\ndinertia_dgamma: [");
        for (k, m) in t.dinertia_dgamma.iter().enumerate() {
            if k > 0 {
                out.push_str(", ");
            }
            construct(out, "__Matrix3", m.as_flattened());
        }
        out.push_str("],\n}\n}\n");
    }

    /// Writes `full_equations` or `reduced_equations`: J, the right side of (8) or (13) and,
    /// for (13), ψ̇, from one straight-line body.
    fn equations_method(
        &self,
        out: &mut String,
        name: &str,
        args: &str,
        ret_ty: &str,
        terms: EquationTerms<Id>,
        inputs: Inputs,
    ) {
        let shape = terms.shape();
        let _ = writeln!(out, "#[inline]\nfn {name}(&self{args}) -> {ret_ty} {{");
        let outs = self.body(out, &terms.flatten(), inputs);
        let t = EquationTerms::from_flat(outs, shape);
        let _ = write!(out, "{ret_ty} {{\ninertia: ");
        construct(out, "__Matrix3", t.inertia.as_flattened());
        out.push_str(",\nright_side: ");
        construct(out, "__Vector3", &t.right_side);
        if let Some(psi_dot) = t.psi_dot {
            let _ = write!(out, ",\npsi_dot: {psi_dot}");
        }
        match t.rank_one {
            Some((c, v)) => {
                let _ = write!(
                    out,
                    ",\nrank_one: __MaybeRankOne::Some(__RankOneInertia {{\nweight: {c},\nvector: "
                );
                construct(out, "__Vector3", &v);
                out.push_str(",\n})");
            }
            None => out.push_str(",\nrank_one: __MaybeRankOne::None"),
        }
        out.push_str(",\n}\n}\n");
    }

    /// The methods of `impl Routhian`.
    pub fn routhian_methods(
        &self,
        o: &Outputs,
        eq: &Equations,
        rank_one: Option<&RankOne>,
    ) -> String {
        let mut out = String::new();
        let r = Inputs::Routhian;
        let s = &mut out;
        self.method(s, "psi_dot", ROUTH, Ret::Scalar(o.psi_dot), r);
        self.method(s, "routhian", ROUTH, Ret::Scalar(o.routhian), r);
        self.method(s, "dr_domega", ROUTH, Ret::Vector(o.dr_domega), r);
        self.method(s, "dr_dgamma", ROUTH, Ret::Vector(o.dr_dgamma), r);
        self.method(s, "dr_dp", ROUTH, Ret::Scalar(o.dr_dp), r);
        self.method(s, "d2r_domega2", ROUTH, Ret::Matrix(o.d2r_domega2), r);
        let mx = Ret::Matrix(o.d2r_domega_dgamma);
        self.method(s, "d2r_domega_dgamma", ROUTH, mx, r);
        self.method(s, "d2r_dgamma2", ROUTH, Ret::Matrix(o.d2r_dgamma2), r);
        let ur = Ret::Scalar(o.amended_potential);
        self.method(s, "amended_potential", REST, ur, r);

        // bundle: every output from one straight-line body.
        let _ = writeln!(s, "#[inline]\nfn bundle(&self{ROUTH}) -> __RouthBundle {{");
        let outs = self.body(s, &o.bundle().flatten(), r);
        bundle_literal(s, &Bundle::from_flat(outs));
        s.push_str("\n}\n");

        let _ = writeln!(
            s,
            "#[inline]\nfn gyroscopic_system(&self{REST}) -> __GyroscopicSystem {{"
        );
        let outs = self.body(s, &o.gyroscopic().flatten(), r);
        system_literal(s, &Gyroscopic::from_flat(outs));
        s.push_str("\n}\n");

        // bundle_and_system: the bundle and A, G, C of (64) built from its nodes, one body.
        let _ = writeln!(
            s,
            "#[inline]\nfn bundle_and_system(&self{ROUTH}) -> (__RouthBundle, __GyroscopicSystem) {{"
        );
        // The bundle is assembled into a local as soon as its statements are written, before
        // those of A, G, C: its 36 values need not stay live through the rest.
        let BundleAndSystem { bundle, system } = o.bundle_and_system();
        let (bundle, system) = (bundle.flatten(), system.flatten());
        let outs = self.body_in_parts(s, &[&bundle, &system], r, |s, k, names| {
            if k == 0 {
                s.push_str("let __bundle = ");
                bundle_literal(s, &Bundle::from_flat(names.iter().cloned()));
                s.push_str(";\n");
            }
        });
        let system = Gyroscopic::from_flat(outs.into_iter().nth(1).unwrap_or_default());
        s.push_str("(__bundle, ");
        system_literal(s, &system);
        s.push_str(")\n}\n");

        let terms = EquationTerms {
            inertia: o.d2l_domega2,
            right_side: eq.reduced,
            psi_dot: Some(o.psi_dot),
            rank_one: rank_one.map(|r| (r.weight, r.vector)),
        };
        self.equations_method(
            s,
            "reduced_equations",
            ROUTH,
            "__ReducedEquations",
            terms,
            r,
        );
        out
    }
}

/// The paths [`routh_tape::Tape::write_rust`] writes, all aliases of [`ALIASES`].
const TAPE_PATHS: routh_tape::RustPaths<'static> = routh_tape::RustPaths {
    op: "__Op",
    output: "__Output",
    tape: "__Tape",
    func: "__Func",
};

/// Writes `fn certification_tape` (the interval tape of `∂R/∂γ`, `∂²R/∂γ²` at `Ω = 0`) and
/// `fn routh_tape` (the tape of `R(Ω, γ, p_ψ)`) to `out` (the `Routhian` impl), and
/// `fn flow_tape` (`L` and the derivatives of (8), [`crate::tape::flow`]) to `lag` (the
/// `Lagrangian` impl), each as `static` typed ops ([`crate::tape`]) bound to the parameter
/// values read from `self`.
pub fn tapes(
    out: &mut String,
    lag: &mut String,
    sym: &Symbols,
    o: &Outputs,
) -> Result<(), routh_tape::TapeError> {
    let params = crate::tape::param_reads(sym).join(", ");
    let cert = crate::tape::certification(sym, o)?;
    out.push_str("#[inline]\nfn certification_tape(&self) -> __MaybeTape {\n");
    cert.write_rust(out, "__CERTIFICATION", &TAPE_PATHS);
    let _ = writeln!(
        out,
        "__CertificationTape::new(__Tape::clone(&__CERTIFICATION), <[__F64]>::to_vec(&[{params}])).ok()\n}}"
    );
    let r = crate::tape::routhian(sym, o)?;
    out.push_str("#[inline]\nfn routh_tape(&self) -> __MaybeRouthianTape {\n");
    r.write_rust(out, "__ROUTHIAN", &TAPE_PATHS);
    let _ = writeln!(
        out,
        "__RouthianTape::new(__Tape::clone(&__ROUTHIAN), <[__F64]>::to_vec(&[{params}])).ok()\n}}"
    );
    let f = crate::tape::flow(sym, o)?;
    lag.push_str("#[inline]\nfn flow_tape(&self) -> __MaybeFlowTape {\n");
    f.write_rust(lag, "__FLOW", &TAPE_PATHS);
    let _ = writeln!(
        lag,
        "__FlowTape::new(__Tape::clone(&__FLOW), <[__F64]>::to_vec(&[{params}])).ok()\n}}"
    );
    Ok(())
}
