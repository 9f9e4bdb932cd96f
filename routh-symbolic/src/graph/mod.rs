//! The hash-consed expression DAG.
//!
//! Every node lives once in a [`Graph`] and is named by an [`Id`]; a node's children always have
//! smaller ids than the node (as in egg's `RecExpr`), so walking ids in increasing order is a
//! topological order, and emitting the nodes reachable from a set of outputs in that order
//! computes every shared subexpression exactly once.
//!
//! Nodes are only ever built through the simplifying constructors ([`Graph::add`],
//! [`Graph::mul`], …), which fold constants, apply the 0/1 identities, put the operands of
//! commutative operations in a canonical order and merge integer powers, so structurally equal
//! expressions get equal ids.
//!
//! This module is the storage: the node types, the hash-cons table and the variables. The
//! other responsibilities are `impl Graph` blocks in submodules, so that each can read the
//! storage but nothing outside can build a node except through a constructor:
//! - `rewrite`: the simplifying constructors and substitution;
//! - `collect`: like-term collection in sums (a part of `add`);
//! - `diff`: symbolic differentiation;
//! - `eval`: numerical evaluation and dependence on variables;
//! - `tape`: the nodes reachable from some outputs as a typed `routh_tape::Tape`.

mod collect;
mod diff;
mod eval;
mod rewrite;
mod table;
mod tape;

use std::fmt;

/// The name of a node in a [`Graph`].
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Id(pub(crate) u32);

impl Id {
    /// "No node": the empty slots of `Graph::diff_memo` (no graph can reach `u32::MAX` nodes,
    /// as `intern` refuses the id after the last).
    pub(crate) const NONE: Id = Id(u32::MAX);

    /// The index of the node (children have smaller indices than their parents).
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The id of the node at `index` (for walking a graph's nodes in order).
    pub fn from_index(index: usize) -> Self {
        Id(index as u32)
    }
}

/// Unary elementary functions: the one definition, in `routh-tape`.
pub use routh_tape::Func;

/// An input variable of a [`Graph`] (its slot among the inputs of [`Graph::eval`] and of the
/// generated code), made by [`Graph::new_var`] or [`Graph::var`].
///
/// A type of its own rather than a bare index so that what is only defined for a variable —
/// differentiating by it ([`Graph::diff`]), substituting for it ([`Graph::substitute`]), asking
/// whether an expression depends on it — cannot be given an arbitrary [`Id`] or a made-up
/// number: a `Var` comes from the graph that made it, and [`Graph::as_var`] is the one checked
/// way from a node to a variable.
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Var(u32);

impl Var {
    /// The slot of the variable: the `index`-th variable made in its graph, counting from 0.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// One node of the DAG. Children are [`Id`]s of earlier nodes.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// A constant, stored as the bits of an `f64` (`-0.0` is normalised to `0.0`).
    Const(u64),
    /// An input variable.
    Var(Var),
    /// `a + b`, operands in canonical order.
    Add(Id, Id),
    /// `a * b`, operands in canonical order.
    Mul(Id, Id),
    /// `-a`.
    Neg(Id),
    /// `1 / a`.
    Recip(Id),
    /// `a^n` for an integer `n ∉ {0, 1}`.
    Powi(Id, i32),
    /// `a^b` for a non-constant or non-integer exponent.
    Powf(Id, Id),
    /// `f(a)`.
    Func(Func, Id),
}

impl Node {
    /// The constant value, if this is a constant.
    pub fn as_const(&self) -> Option<f64> {
        match *self {
            Node::Const(bits) => Some(f64::from_bits(bits)),
            _ => None,
        }
    }

    /// The children of the node.
    pub fn children(&self) -> impl Iterator<Item = Id> {
        let (a, b) = match *self {
            Node::Const(_) | Node::Var(_) => (None, None),
            Node::Add(a, b) | Node::Mul(a, b) | Node::Powf(a, b) => (Some(a), Some(b)),
            Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => (Some(a), None),
        };
        a.into_iter().chain(b)
    }
}

/// A variable's name (for printing) and its node.
#[derive(Clone)]
struct VarSlot {
    name: String,
    id: Id,
}

/// A hash-consed expression DAG with simplifying constructors.
#[derive(Clone, Default)]
pub struct Graph {
    /// Every node, children before parents; an [`Id`] is an index into it.
    nodes: Vec<Node>,
    /// The hash-cons table: the id of every node in `nodes`.
    memo: table::Table,
    /// The variables, by slot.
    vars: Vec<VarSlot>,
    /// `∂f/∂v` already computed: `diff_memo[v][f]`, [`Id::NONE`] where not yet (see `diff`).
    /// Dense per variable, so that differentiating hashes nothing.
    diff_memo: Vec<Vec<Id>>,
}

impl fmt::Debug for Graph {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.vars.iter().map(|v| v.name.as_str()).collect();
        f.debug_struct("Graph")
            .field("nodes", &self.nodes.len())
            .field("vars", &names)
            .finish()
    }
}

impl Graph {
    /// An empty graph.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the graph has no nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The node named `id`.
    pub fn node(&self, id: Id) -> Node {
        self.nodes[id.index()]
    }

    /// All nodes, children before parents.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// Number of variables made with [`Graph::var`] or [`Graph::new_var`].
    pub fn num_vars(&self) -> usize {
        self.vars.len()
    }

    /// The name given to variable `v`.
    pub fn var_name(&self, v: Var) -> &str {
        &self.vars[v.index()].name
    }

    /// The node of variable `v`.
    pub fn var_id(&self, v: Var) -> Id {
        self.vars[v.index()].id
    }

    /// The constant value of `id`, if it is a constant.
    pub fn as_const(&self, id: Id) -> Option<f64> {
        self.node(id).as_const()
    }

    /// Whether `id` is the constant `c`.
    pub fn is_const(&self, id: Id, c: f64) -> bool {
        self.as_const(id) == Some(c)
    }

    /// The id of `node`, added if it is new. Only the constructors call this, with a node
    /// they have already simplified.
    fn intern(&mut self, node: Node) -> Id {
        self.memo.intern(&mut self.nodes, node)
    }

    /// The id of `node` if the graph has it (builds nothing).
    fn find(&self, node: &Node) -> Option<Id> {
        self.memo.get(&self.nodes, node)
    }

    /// A new variable called `name` (names need not be unique; each call is a new variable).
    pub fn new_var(&mut self, name: impl Into<String>) -> Var {
        let v = Var(u32::try_from(self.vars.len()).expect("more than u32::MAX variables"));
        let id = self.intern(Node::Var(v));
        self.vars.push(VarSlot {
            name: name.into(),
            id,
        });
        v
    }

    /// A new variable called `name`, as a node (for building expressions; [`Graph::new_var`]
    /// gives the [`Var`] to differentiate or substitute by).
    pub fn var(&mut self, name: impl Into<String>) -> Id {
        let v = self.new_var(name);
        self.var_id(v)
    }

    /// The variable `id` is, if it is one.
    pub fn as_var(&self, id: Id) -> Option<Var> {
        match self.node(id) {
            Node::Var(v) => Some(v),
            _ => None,
        }
    }

    /// A constant.
    pub fn constant(&mut self, c: f64) -> Id {
        let c = if c == 0.0 { 0.0 } else { c };
        self.intern(Node::Const(c.to_bits()))
    }

    /// `0`.
    pub fn zero(&mut self) -> Id {
        self.constant(0.0)
    }

    /// `1`.
    pub fn one(&mut self) -> Id {
        self.constant(1.0)
    }
}
