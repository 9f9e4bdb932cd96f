//! Defining equations.
