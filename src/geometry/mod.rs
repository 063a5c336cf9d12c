//! Geometry: coordinates, exact sign predicates, vertex solvers, and the
//! power-of-two normalisation of the input.
//!
//! Nothing here knows about the diagram. Every numerical question the
//! construction asks is answered here, from sites, vertex positions and
//! radii: signs as enums — [`predicates`] for points (exact),
//! `segments::segment_predicates` for a new segment (certified by
//! `segments::oracle`) — with magnitudes only for ranking
//! (`predicates::point_predicates` ranks the conflicts of a new point), and
//! vertex positions from `segments::vertex_placement`. So no other module
//! compares a raw determinant with zero, and the fault-injection build
//! perturbs numbers only here (`fault`).
//!
//! The rooms, from the ground up; each imports only the ones below it:
//! - `arithmetic`: the numbers (expansions, double-double, big floats,
//!   certified balls, the radical tower, the `Real` trait); no geometry.
//! - the basics, in this folder: [`point`], [`site`], `scale` (the
//!   power-of-two normalisation), `fault` (fault injection).
//! - [`predicates`]: exact signs on points, and rankings for a new point.
//! - [`solvers`]: Voronoi vertices from their sites; `input`: the exact
//!   contacts of input segments and the snap-rounding grid; `curves`:
//!   edges as parabolic or straight curves and as tracks for the offsets.
//! - `segments`: what the insertion of a segment asks, the certified
//!   oracle that answers it, and where each new vertex goes.

pub mod arc;
pub(crate) mod arcs;
mod arithmetic;
pub(crate) mod curves;
pub(crate) mod fault;
pub(crate) mod input;
pub(crate) mod left_out;
pub mod point;
pub mod predicates;
pub(crate) mod scale;
pub(crate) mod seam;
pub(crate) mod segments;
pub mod site;
pub(crate) mod skyline;
pub mod solvers;

pub use arc::CircularArc;
pub use point::Point;
pub use site::Site;
