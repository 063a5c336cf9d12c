//! # segvoronoi
//!
//! The Voronoi diagram of points and line segments in the plane, built by
//! the topology-oriented method of Sugihara, Iri and Imai: the combinatorial
//! structure is kept valid by integer bookkeeping alone, and floating point
//! only chooses among valid structures. The build never fails on degenerate
//! or near-degenerate input. For point sites, with the exact predicates used
//! here, the topology is the exact one; segment sites are newer and still
//! have known gaps (see `ARCHITECTURE.md`).
//!
//! On top of the diagram: polygons bound a domain ([`Builder::add_polygon`],
//! [`Diagram::locate_point`]); its medial axis ([`Diagram::medial_axis`],
//! [`MedialAxisFilter`]) and largest inscribed disk; and offsets at any
//! signed distance ([`Diagram::offset`], [`Diagram::offsets`]): closed,
//! oriented and nested loops of exact line pieces and circular arcs
//! ([`OffsetLoop`], [`OffsetPiece`]), with polylines within a tolerance and
//! exact areas.
//!
//! ```
//! use segvoronoi::{Builder, EdgeEnd};
//!
//! let mut builder = Builder::new();
//! builder.add_points([[0.0, 0.0], [2.0, 0.0], [1.0, 2.0], [1.0, 0.7]])?;
//! let diagram = builder.build()?;
//! for edge in diagram.edges() {
//!     let [a, b] = edge.sites;
//!     match edge.ends {
//!         [EdgeEnd::Vertex(u), EdgeEnd::Vertex(v)] => println!("{a}|{b}: segment {u}-{v}"),
//!         _ => println!("{a}|{b}: ray or line"),
//!     }
//! }
//! assert_eq!(diagram.vertex_count(), 3);
//! # Ok::<(), segvoronoi::Error>(())
//! ```
//!
//! ## Map of the crate
//! Dependencies point one way, top to bottom:
//! - [`geometry`]: coordinates, exact predicates (enums, never raw
//!   determinants), vertex solvers, power-of-two normalisation.
//! - `diagram`: the half-edge store with typed ids and its invariant checker
//!   ([`Diagram::validate`]); it never reads coordinates to decide anything.
//! - `construct`: [`Builder`], input checking, insertion order, the
//!   topology-oriented insertion of points and segments.
//! - `query`: iteration over vertices, edges and cells, canonical topology,
//!   the domain, the medial axis, offsets.
//!
//! The C API (`segvoronoi.h`, `libsegvoronoi.so` and `.a`) is the crate
//! `segvoronoi-capi` in the repository's `capi/`, built on this one's public
//! API, so a Rust dependant builds no C artefact.

// An undocumented public item fails the build.
#![deny(missing_docs)]
// The `unsafe` of the C API is in its own crate (`capi/`).
#![forbid(unsafe_code)]
// `!(a < b)` is how this crate says "not less, or not comparable": a NaN
// takes the negated branch on purpose (the refusals and fallbacks), which
// `a >= b` would not, and `partial_cmp` would bury.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

#[doc(hidden)]
pub mod boost_text;
mod construct;
mod diagram;
mod error;
pub mod geometry;
mod query;
#[doc(hidden)]
pub mod splitmix;

pub use construct::{Builder, ChainPiece, MAX_POINTS};
pub use diagram::{BuildStats, Diagram, EdgeId, SiteId, ValidationError, VertexId};
pub use error::{Error, ErrorKind};
pub use geometry::{CircularArc, Point, Site};
pub use query::EdgeShape;
pub use query::{
    Cell, Chain, Edge, EdgeEnd, HalfEdge, Indices, Location, MedialAxis, MedialAxisFilter, Offset, OffsetLoop, OffsetPiece,
    Piece, TopologyOptions, Vertex, ZERO_LENGTH,
};

/// Fault injection for tests: make the floating-point decisions lie and watch
/// the topology survive (or the build give up with [`ErrorKind::Internal`],
/// never with an invalid diagram). Only in builds with the `fault-injection`
/// feature.
#[cfg(feature = "fault-injection")]
pub mod fault_injection {
    pub use crate::construct::set_restart_budget;
    pub use crate::geometry::fault::{set_fault_mode, FaultMode};
}

/// Diagnostics for benchmarks and tests: how the segment predicates of
/// the builds on this thread were decided (the `f64` filter, or one of the
/// refinement stages of `geometry::segments::oracle`), and how a build ran
/// in halves on two threads (`take_halves_report`; `set_halves_from`
/// makes small builds run so, and `set_halves_left_share` moves the cut,
/// for tests). Rust only; not part of the C API.
pub mod diagnostics {
    pub use crate::construct::{set_halves_from, set_halves_left_share, take_halves_report, HalvesReport};
    pub use crate::geometry::segments::oracle::{take_predicate_counts, PredicateCounts};
}

/// The README's Rust quick start, run as a doctest so it cannot rot.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

/// The crate version, as in `Cargo.toml`.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");
