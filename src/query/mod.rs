//! Reading a finished diagram: sites, vertices, edges, cells, half-edge
//! navigation, edge shapes, and the canonical topology text.

mod access;
#[cfg(test)]
pub(crate) mod audit;
mod navigation;
mod shape;
mod topology;

pub use access::{Cell, Edge, EdgeEnd, Vertex};
pub use navigation::HalfEdge;
pub use shape::EdgeShape;
pub use topology::{TopologyOptions, ZERO_LENGTH};
