//! Reading a finished diagram: sites, vertices, edges, cells, and the
//! canonical topology text.

mod access;
#[cfg(test)]
pub(crate) mod audit;
mod shape;
mod topology;

pub use access::{Cell, Edge, EdgeEnd, Vertex};
pub use shape::EdgeShape;
pub use topology::{TopologyOptions, ZERO_LENGTH};
