//! The exact geometry of the input itself, before any diagram: how two
//! closed segments meet and whether a point lies inside a segment
//! (`segment_contact`, the contact rules the input check applies), and the
//! grid of snap rounding with its exact segment-meets-pixel test and
//! crossing points (`snap`, used by the split of a self-crossing input).
//! Both decide with exact signs from `predicates`, no epsilon.

pub(crate) mod arc_contact;
pub(crate) mod segment_contact;
pub(crate) mod snap;
