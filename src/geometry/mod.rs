//! Geometry: coordinates, exact sign predicates, vertex solvers, and the
//! power-of-two normalisation of the input.
//!
//! Nothing here knows about the diagram. Every numerical question the
//! construction asks is answered here, from sites, vertex positions and
//! radii: signs as enums — [`predicates`] for points (exact),
//! `segment_predicates` for a new segment (certified by `oracle`) — with
//! magnitudes only for ranking (`point_predicates` ranks the conflicts of a
//! new point), and vertex positions from `vertex_placement`. So no other
//! module compares a raw determinant with zero, and the fault-injection
//! build perturbs numbers only here (`fault`).

mod arithmetic;
pub(crate) mod edge_curve;
pub(crate) mod edge_track;
pub(crate) mod fault;
pub(crate) mod oracle;
pub(crate) mod parabola;
pub mod point;
pub(crate) mod point_predicates;
pub mod predicates;
mod quadratic_vertex;
#[doc(hidden)] // the CLI's picture normalises with it; not stable API
pub mod scale;
pub(crate) mod segment_contact;
pub(crate) mod segment_predicates;
pub(crate) mod segment_solvers;
pub mod site;
pub(crate) mod snap;
pub mod solvers;
pub(crate) mod vertex_placement;

pub use point::Point;
pub use site::Site;
