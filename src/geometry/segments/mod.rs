//! What the insertion of a segment asks, and where a vertex goes, decided
//! to the end: the questions themselves (`segment_predicates`: conflict
//! depth, left-degree, the strip, the middle margin), the question put to
//! a vertex (`reach`), the certified stage that answers it where `f64`
//! cannot (`oracle`: filter, refinement, exact decision; `quadratic_vertex`
//! its exact shortcut), and the placement of every new vertex
//! (`vertex_placement`: the solvers' circle, polished by the oracle when a
//! segment is among its sites). The top floor of `geometry`: it stands on
//! the solvers, the curves, the predicates and the arithmetic.

pub(crate) mod oracle;
mod quadratic_vertex;
mod reach;
pub(crate) mod segment_predicates;
mod tangent_lines;
pub(crate) mod vertex_placement;
