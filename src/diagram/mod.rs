//! The diagram store: a half-edge structure in flat arrays with typed `u32`
//! ids, and its invariant checker.
//!
//! The store holds topology, plus the vertex positions the construction
//! computed; it never reads a coordinate to decide anything.
//!
//! Representation. Every Voronoi vertex has degree 3 (a degenerate vertex is
//! several degree-3 vertices joined by zero-length edges), so vertex `v` owns
//! the three half-edges `3v`, `3v+1`, `3v+2` that leave it. Around `v` its
//! three cells `s0, s1, s2` are in counter-clockwise order; half-edge `3v+i`
//! runs between `s_i` (on its right) and `s_(i+1)` (on its left). Only the
//! twin of each half-edge is stored; `next`, `prev`, origin and the cells
//! follow by arithmetic. A cell's boundary, walked with `next`, is
//! counter-clockwise with the cell on the left.
//!
//! The point at infinity is a site like the others (its id is
//! [`Store::infinite_site`]); its cell is the outside of the convex hull.
//! Vertices that have it among their sites lie at infinity: their stored
//! "position" is the unit direction in which the edges run off.

mod built;
mod ids;
mod pieces;
mod site_table;
mod store;
mod validate;

pub use built::{BuildStats, Diagram};
pub(crate) use ids::NONE;
pub use ids::{EdgeId, HalfEdgeId, SiteId, VertexId};
pub(crate) use pieces::SplitPieces;
pub(crate) use site_table::SiteTable;
pub(crate) use store::Store;
pub use validate::ValidationError;
