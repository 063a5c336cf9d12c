//! Geometry: coordinates, exact sign predicates, vertex solvers, and the
//! power-of-two normalisation of the input.
//!
//! Nothing here knows about the diagram. Every sign decision the construction
//! makes goes through [`predicates`], which returns enums, so no other module
//! compares a raw determinant with zero.

mod bigfloat;
mod double_double;
mod expansion;
pub(crate) mod oracle;
pub(crate) mod parabola;
pub(crate) mod fault;
pub mod point;
pub mod predicates;
pub(crate) mod scale;
pub mod solvers;
pub mod site;
pub(crate) mod segment_solvers;

pub use point::Point;
pub use site::Site;
