//! Reading a finished diagram: sites, vertices, edges, cells, half-edge
//! navigation, edge shapes, and the canonical topology text.

mod access;
#[cfg(test)]
pub(crate) mod audit;
mod domain;
mod exact_turn;
mod medial_axis;
mod medial_axis_filter;
mod navigation;
mod offset;
mod partition;
mod pieces;
mod shape;
mod topology;

pub use access::{Cell, Edge, EdgeEnd, Vertex};
pub(crate) use domain::Domain;
pub use domain::Location;
pub use medial_axis::{Chain, MedialAxis, Piece};
pub use medial_axis_filter::MedialAxisFilter;
pub use navigation::HalfEdge;
pub use offset::{Offset, OffsetLoop, OffsetPiece};
pub use pieces::Indices;
pub use shape::EdgeShape;
pub use topology::{TopologyOptions, ZERO_LENGTH};
