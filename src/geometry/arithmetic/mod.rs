//! The numbers under the geometry: every arithmetic the predicates and
//! solvers compute in, from exact sums of doubles to exact square roots.
//!
//! Nothing here knows a point or a site; the rest of `geometry` is written
//! on top of it. [`expansion`] keeps exact sums of products of doubles (the
//! signs `robust` does not cover); [`real`] is the trait the solvers and
//! the oracle's Newton iteration are written against, in `f64`,
//! [`double_double`] (about 106 bits) and [`bigfloat`] (any precision);
//! [`certified`] (balls with a separation bound) and [`radical_tower`]
//! (exact square roots) decide the values that refinement cannot tell from
//! zero.

pub(super) mod bigfloat;
pub(super) mod certified;
pub(super) mod double_double;
pub(super) mod expansion;
pub(super) mod radical_tower;
pub(super) mod real;
pub(super) mod root_sums;
