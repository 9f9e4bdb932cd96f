//! The shapes of node arrays every pass shares: a 3-vector and a row-major 3×3 matrix of graph
//! nodes (`m[i][j]` is row `i`, column `j`).

use routh_symbolic::Id;

/// A column 3-vector of nodes.
pub type V3 = [Id; 3];
/// A 3×3 matrix of nodes, row-major.
pub type M3 = [[Id; 3]; 3];
