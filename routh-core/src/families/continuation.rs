//! Branch following.
