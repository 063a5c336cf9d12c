//! Reading a finished diagram: sites, vertices, edges, cells, and the
//! canonical topology text.

mod access;
mod topology;

pub use access::{Cell, Edge, EdgeEnd, Vertex};
pub use topology::TopologyOptions;
