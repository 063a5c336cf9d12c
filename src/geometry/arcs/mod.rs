//! What the insertion of a circular arc asks of the current diagram, and
//! where the vertices of arcs go: the arc's conflict with a vertex's
//! circle, the side of the arc a site lies on (the left-degree of the path
//! search), the cone of influence (the arcs' strip), the margin of an edge
//! cut twice (`arc_predicates`); the vertex of three sites among which is
//! an arc (`arc_vertex`). Points along the conic edge beside an arc are
//! `curves::bisector`'s.
//!
//! Unlike segments, these decisions are taken in floating point with
//! tolerances, not certified: the topology stays valid whatever they
//! answer (the construction keeps P3–P5 by bookkeeping), but a near tie
//! may be decided wrong. The conflict of an arc with a vertex's circle,
//! the question asked most, is refined in double-double near a tie
//! (`refined_depth`: a tie below 2^-90 of the size). Where the arc meets
//! the vertex's sites at one of its endpoints (the joins of a chain), the
//! turns between the pieces there are exact (`exact_join`): a join an ulp
//! off tangent is a corner, decided by its sign, and only an exactly
//! tangent join is left to the curvature rules. The answers use the same
//! types as the segments' (`segments::segment_predicates`), so the
//! insertion asks both alike.

pub(crate) mod arc_predicates;
pub(crate) mod arc_vertex;
pub(crate) mod at_infinity;
pub(crate) mod exact_join;
pub(crate) mod refined_depth;
