//! Emission of the generated impls with `quote!`.
//!
//! Each method is straight-line code: the inputs it needs are read into `__v*` locals, then the
//! nodes its outputs need are written in increasing id order (children before parents, so every
//! shared subexpression is computed once) as `let __t* = ...;`. A negation feeding only a sum is
//! written as a subtraction, a reciprocal used once as a division, and small integer powers as
//! products. Paths go through `<crate>::__private`; no allocation, no `unsafe`.

use crate::layout::{Bundle, Gyroscopic};
use crate::lower::{Access, Symbols};
use crate::reduce::{Outputs, M3, V3};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};
use routh_symbolic::{Func, Graph, Id, Node, Plan, Var};

/// How a variable is read in one method.
#[derive(Clone, Copy)]
pub enum Inputs {
    /// `(omega, gamma)` of the Lagrangian methods.
    Lagrangian,
    /// `(big_omega, gamma, p_psi)` of the Routhian methods.
    Routhian,
}

/// Writes one method body computing `outputs` and returning `build(output tokens)`.
pub struct Emitter<'a> {
    pub sym: &'a Symbols,
    pub krate: &'a TokenStream,
}

fn lit(c: f64, krate: &TokenStream) -> TokenStream {
    if c.is_nan() {
        quote!(#krate::__private::f64::NAN)
    } else if c.is_infinite() {
        if c > 0.0 {
            quote!(#krate::__private::f64::INFINITY)
        } else {
            quote!((-#krate::__private::f64::INFINITY))
        }
    } else if c < 0.0 {
        let l = Literal::f64_suffixed(-c);
        quote!((-#l))
    } else {
        let l = Literal::f64_suffixed(c);
        quote!(#l)
    }
}

impl Emitter<'_> {
    fn g(&self) -> &Graph {
        &self.sym.graph
    }

    /// The tokens reading variable `var` from the method's arguments or from `self`.
    fn input_tokens(&self, var: Var, inputs: Inputs) -> TokenStream {
        let s = self.sym;
        let idx = |vars: &[Var; 3]| vars.iter().position(|&x| x == var);
        if let Some(i) = idx(&s.omega) {
            return match inputs {
                Inputs::Lagrangian => quote!(__omega[#i]),
                Inputs::Routhian => quote!(__big_omega[#i]),
            };
        }
        if let Some(i) = idx(&s.gamma) {
            return quote!(__gamma[#i]);
        }
        if s.p_psi == var {
            return quote!(__p_psi);
        }
        match s.params.iter().find(|p| p.var == var) {
            Some(p) => {
                let f = &p.field;
                match p.access {
                    Access::Scalar => quote!(self.#f),
                    Access::Component(i) => quote!(self.#f[#i]),
                    Access::Entry(i, j) => quote!(self.#f[(#i, #j)]),
                }
            }
            // Every variable is ω, γ, p_ψ or a parameter.
            None => quote!(0.0f64),
        }
    }

    fn local(id: Id) -> Ident {
        format_ident!("__t{}", id.index())
    }

    /// The local an input is read into.
    fn input_local(v: Var) -> Ident {
        format_ident!("__v{}", v.index())
    }

    /// The tokens naming the value of `id` (a literal, an input local or a node local).
    fn operand(&self, id: Id) -> TokenStream {
        match self.g().node(id) {
            Node::Const(b) => lit(f64::from_bits(b), self.krate),
            Node::Var(v) => {
                let n = Self::input_local(v);
                quote!(#n)
            }
            _ => {
                let n = Self::local(id);
                quote!(#n)
            }
        }
    }

    fn expr(&self, id: Id, plan: &Plan) -> TokenStream {
        let g = self.g();
        let o = |c: Id| self.operand(c);
        match g.node(id) {
            Node::Add(a, b) => match (plan.folds(g, id, a), plan.folds(g, id, b)) {
                (_, Some(x)) => {
                    let (a, x) = (o(a), o(x));
                    quote!(#a - #x)
                }
                (Some(x), _) => {
                    let (b, x) = (o(b), o(x));
                    quote!(#b - #x)
                }
                _ => {
                    let (a, b) = (o(a), o(b));
                    quote!(#a + #b)
                }
            },
            Node::Mul(a, b) => match (plan.folds(g, id, a), plan.folds(g, id, b)) {
                (_, Some(x)) => {
                    let (a, x) = (o(a), o(x));
                    quote!(#a / #x)
                }
                (Some(x), _) => {
                    let (b, x) = (o(b), o(x));
                    quote!(#b / #x)
                }
                _ => {
                    let (a, b) = (o(a), o(b));
                    quote!(#a * #b)
                }
            },
            Node::Neg(a) => {
                let a = o(a);
                quote!(-#a)
            }
            Node::Recip(a) => {
                let a = o(a);
                quote!(1.0f64 / #a)
            }
            Node::Powi(a, n) => self.power(o(a), n),
            Node::Powf(a, b) => {
                let (a, b) = (o(a), o(b));
                quote!(#a.powf(#b))
            }
            Node::Func(Func::Sign, a) => {
                let (a, k) = (o(a), self.krate);
                quote!(#k::__private::sign(#a))
            }
            Node::Func(f, a) => {
                let (a, m) = (o(a), Ident::new(f.name(), Span::call_site()));
                quote!(#a.#m())
            }
            Node::Const(_) | Node::Var(_) => o(id),
        }
    }

    fn power(&self, x: TokenStream, n: i32) -> TokenStream {
        match n {
            2 => quote!(#x * #x),
            3 => quote!(#x * #x * #x),
            _ => quote!(#x.powi(#n)),
        }
    }

    /// Statements computing `outputs`, then the output tokens.
    pub fn body(&self, outputs: &[Id], inputs: Inputs) -> (TokenStream, Vec<TokenStream>) {
        let g = self.g();
        let plan = Plan::new(g, outputs);
        let k = self.krate;
        let mut stmts = TokenStream::new();
        // Inputs first (only those read), then the nodes in order.
        for (i, _) in plan.emit.iter().enumerate().filter(|(_, &e)| e) {
            if let Node::Var(v) = g.node(Id::from_index(i)) {
                let name = Self::input_local(v);
                let src = self.input_tokens(v, inputs);
                stmts.extend(quote!(let #name: #k::__private::f64 = #src;));
            }
        }
        for id in plan.statements(g) {
            let name = Self::local(id);
            let e = self.expr(id, &plan);
            stmts.extend(quote!(let #name: #k::__private::f64 = #e;));
        }
        let outs = outputs.iter().map(|&o| self.operand(o)).collect();
        (stmts, outs)
    }
}

/// Signature pieces shared by every generated method.
pub struct Types {
    pub v3: TokenStream,
    pub m3: TokenStream,
}

impl Types {
    pub fn new(k: &TokenStream) -> Self {
        Types {
            v3: quote!(#k::__private::Vector3<#k::__private::f64>),
            m3: quote!(#k::__private::Matrix3<#k::__private::f64>),
        }
    }
}

fn vec_tokens(k: &TokenStream, t: &[TokenStream]) -> TokenStream {
    quote!(#k::__private::Vector3::new(#(#t),*))
}

fn mat_tokens(k: &TokenStream, t: &[TokenStream]) -> TokenStream {
    quote!(#k::__private::Matrix3::new(#(#t),*))
}

fn flat_v(v: &V3) -> Vec<Id> {
    v.to_vec()
}

fn flat_m(m: &M3) -> Vec<Id> {
    m.iter().flatten().copied().collect()
}

/// One generated method: outputs, then how to assemble them.
enum Ret {
    Scalar(Id),
    Vector(V3),
    Matrix(M3),
}

impl Emitter<'_> {
    fn method(
        &self,
        name: &str,
        args: TokenStream,
        ret_ty: &TokenStream,
        ret: Ret,
        inputs: Inputs,
    ) -> TokenStream {
        let k = self.krate;
        let ids = match &ret {
            Ret::Scalar(s) => vec![*s],
            Ret::Vector(v) => flat_v(v),
            Ret::Matrix(m) => flat_m(m),
        };
        let (stmts, outs) = self.body(&ids, inputs);
        let value = match ret {
            Ret::Scalar(_) => outs[0].clone(),
            Ret::Vector(_) => vec_tokens(k, &outs),
            Ret::Matrix(_) => mat_tokens(k, &outs),
        };
        let name = Ident::new(name, Span::call_site());
        quote! {
            #[inline]
            fn #name(&self, #args) -> #ret_ty {
                #stmts
                #value
            }
        }
    }

    /// The methods of `impl Lagrangian`.
    pub fn lagrangian_methods(&self, o: &Outputs) -> TokenStream {
        let k = self.krate;
        let t = Types::new(k);
        let (v3, m3) = (&t.v3, &t.m3);
        let f64t = quote!(#k::__private::f64);
        let wg = quote!(__omega: &#v3, __gamma: &#v3);
        let gonly = quote!(__gamma: &#v3);
        let l = Inputs::Lagrangian;
        let ms = [
            self.method(
                "lagrangian",
                wg.clone(),
                &f64t,
                Ret::Scalar(o.lagrangian),
                l,
            ),
            self.method("dl_domega", wg.clone(), v3, Ret::Vector(o.dl_domega), l),
            self.method("dl_dgamma", wg.clone(), v3, Ret::Vector(o.dl_dgamma), l),
            self.method("d2l_domega2", gonly, m3, Ret::Matrix(o.d2l_domega2), l),
            self.method(
                "d2l_domega_dgamma",
                wg.clone(),
                m3,
                Ret::Matrix(o.d2l_domega_dgamma),
                l,
            ),
            self.method("energy", wg.clone(), &f64t, Ret::Scalar(o.energy), l),
            self.method(
                "cyclic_momentum",
                wg,
                &f64t,
                Ret::Scalar(o.cyclic_momentum),
                l,
            ),
        ];
        quote!(#(#ms)*)
    }

    /// The methods of `impl Routhian`.
    pub fn routhian_methods(&self, o: &Outputs) -> TokenStream {
        let k = self.krate;
        let t = Types::new(k);
        let (v3, m3) = (&t.v3, &t.m3);
        let f64t = quote!(#k::__private::f64);
        let a = quote!(__big_omega: &#v3, __gamma: &#v3, __p_psi: #f64t);
        let ga = quote!(__gamma: &#v3, __p_psi: #f64t);
        let r = Inputs::Routhian;
        let mut ms = vec![
            self.method("psi_dot", a.clone(), &f64t, Ret::Scalar(o.psi_dot), r),
            self.method("routhian", a.clone(), &f64t, Ret::Scalar(o.routhian), r),
            self.method("dr_domega", a.clone(), v3, Ret::Vector(o.dr_domega), r),
            self.method("dr_dgamma", a.clone(), v3, Ret::Vector(o.dr_dgamma), r),
            self.method("dr_dp", a.clone(), &f64t, Ret::Scalar(o.dr_dp), r),
            self.method("d2r_domega2", a.clone(), m3, Ret::Matrix(o.d2r_domega2), r),
            self.method(
                "d2r_domega_dgamma",
                a.clone(),
                m3,
                Ret::Matrix(o.d2r_domega_dgamma),
                r,
            ),
            self.method("d2r_dgamma2", a.clone(), m3, Ret::Matrix(o.d2r_dgamma2), r),
            self.method(
                "amended_potential",
                ga.clone(),
                &f64t,
                Ret::Scalar(o.amended_potential),
                r,
            ),
        ];
        // bundle: every output from one straight-line body.
        let (stmts, outs) = self.body(&o.bundle().flatten(), r);
        let b = Bundle::from_flat(outs);
        let (rr, pd, dp) = (&b.routhian, &b.psi_dot, &b.dr_dp);
        let dw = vec_tokens(k, &b.dr_domega);
        let dg = vec_tokens(k, &b.dr_dgamma);
        let hw = mat_tokens(k, b.d2r_domega2.as_flattened());
        let hwg = mat_tokens(k, b.d2r_domega_dgamma.as_flattened());
        let hg = mat_tokens(k, b.d2r_dgamma2.as_flattened());
        ms.push(quote! {
            #[inline]
            fn bundle(&self, #a) -> #k::__private::RouthBundle {
                #stmts
                #k::__private::RouthBundle {
                    routhian: #rr,
                    psi_dot: #pd,
                    dr_domega: #dw,
                    dr_dgamma: #dg,
                    dr_dp: #dp,
                    d2r_domega2: #hw,
                    d2r_domega_dgamma: #hwg,
                    d2r_dgamma2: #hg,
                }
            }
        });
        let (stmts, outs) = self.body(&o.gyroscopic().flatten(), r);
        let s = Gyroscopic::from_flat(outs);
        let (ma, mg, mc) = (
            mat_tokens(k, s.a.as_flattened()),
            mat_tokens(k, s.g.as_flattened()),
            mat_tokens(k, s.c.as_flattened()),
        );
        ms.push(quote! {
            #[inline]
            fn gyroscopic_system(&self, #ga) -> #k::__private::GyroscopicSystem {
                #stmts
                #k::__private::GyroscopicSystem { a: #ma, g: #mg, c: #mc }
            }
        });
        quote!(#(#ms)*)
    }
}
