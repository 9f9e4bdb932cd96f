//! The nodes reachable from a set of outputs, written as a typed [`Tape`] (the form the derive
//! emits and the runtime model evaluates).

use super::{Graph, Id, Node, Var};
use routh_tape::{Op, Output, Tape, TapeError};

impl Graph {
    /// The tape computing `outputs` (name, node): the nodes they reach, in increasing id order
    /// (children first, each shared subexpression once). Variable `v` becomes `input(v)` (an
    /// [`Op::Omega`], [`Op::Gamma`], [`Op::PPsi`], [`Op::Param`] or a constant); constants keep
    /// their exact bits. The tape reads `num_params` parameters.
    ///
    /// Evaluating the tape with `f64` gives [`Graph::eval`]'s values bit for bit.
    ///
    /// ```
    /// use routh_symbolic::{Func, Graph};
    /// use routh_tape::{Inputs, Op};
    /// let mut g = Graph::new();
    /// let v = g.new_var("x");
    /// let x = g.var_id(v);
    /// let s = g.func(Func::Sin, x);
    /// let f = g.mul(x, s);
    /// let tape = g.to_tape(&[("f", f)], &|_| Op::Gamma(0), 0).unwrap();
    /// let mut out = [0.0];
    /// let at = Inputs { omega: [0.0; 3], gamma: [0.5, 0.0, 0.0], p_psi: 0.0 };
    /// tape.eval(&at, &[], &mut Vec::new(), &mut out);
    /// assert_eq!(out[0], g.eval(&[f], &[0.5])[0]);
    /// ```
    pub fn to_tape(
        &self,
        outputs: &[(&'static str, Id)],
        input: &dyn Fn(Var) -> Op,
        num_params: u32,
    ) -> Result<Tape, TapeError> {
        let top = outputs.iter().map(|(_, o)| o.index()).max().unwrap_or(0);
        let mut needed = vec![false; top + 1];
        for (_, o) in outputs {
            needed[o.index()] = true;
        }
        for i in (0..=top).rev() {
            if needed[i] {
                for c in self.nodes[i].children() {
                    needed[c.index()] = true;
                }
            }
        }
        let mut slot = vec![u32::MAX; top + 1];
        let mut ops = Vec::new();
        for i in (0..=top).filter(|&i| needed[i]) {
            let s = |id: Id| slot[id.index()];
            let op = match self.nodes[i] {
                Node::Const(bits) => Op::Const(bits),
                Node::Var(v) => input(v),
                Node::Add(a, b) => Op::Add(s(a), s(b)),
                Node::Mul(a, b) => Op::Mul(s(a), s(b)),
                Node::Neg(a) => Op::Neg(s(a)),
                Node::Recip(a) => Op::Recip(s(a)),
                Node::Powi(a, n) => Op::Powi(s(a), n),
                Node::Powf(a, b) => Op::Powf(s(a), s(b)),
                Node::Func(f, a) => Op::Func(f, s(a)),
            };
            slot[i] = ops.len() as u32;
            ops.push(op);
        }
        let outputs = outputs
            .iter()
            .map(|&(name, o)| Output {
                name,
                slot: slot[o.index()],
            })
            .collect();
        Tape::new(ops, outputs, num_params)
    }
}
