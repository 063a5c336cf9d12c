//! Builds of inputs whose coordinates span more than the exact range.
//!
//! Within `scale::EXACT_SPAN` (the largest coordinate magnitude at most
//! `2^480` times the smallest nonzero magnitude or difference), one power
//! of two puts every product of the predicates within `f64`'s normal range,
//! and every sign is exact. Beyond it (`1e300` beside `1`, a zero moved by
//! a subnormal ulp beside ordinary coordinates) no scale does: products of
//! several of the smallest quantities underflow. Many such inputs still
//! build right, those whose smallest quantities meet only ordinary ones in
//! a predicate (`scale::tiny_input_target` places them for that), and
//! refusing them all would refuse a zero nudged by an ulp. So such a
//! build is attempted, and what comes out is checked: a construction that
//! cannot complete, or a diagram that fails `validate` (which also
//! requires finite positions) or has a vertex inside its domain at an
//! infinite clearance, becomes an [`ErrorKind::UnsupportedRange`]
//! naming the two coordinates, never [`ErrorKind::Internal`] and never an
//! invalid diagram returned as a success.

use crate::diagram::Diagram;
use crate::error::{Error, ErrorKind};
use crate::geometry::point::Point;
use crate::geometry::scale::{Magnitudes, EXACT_SPAN};
use crate::query::Location;

/// Runs `build` on the input of `points` and `segments` (the caller's
/// coordinates), and for inputs beyond the exact range turns a failed or
/// invalid result into [`ErrorKind::UnsupportedRange`].
pub(crate) fn checked_build(
    points: &[Point],
    segments: &[[Point; 2]],
    build: impl FnOnce() -> Result<Diagram, Error>,
) -> Result<Diagram, Error> {
    let magnitudes = Magnitudes::of_points(points.iter().chain(segments.iter().flatten()));
    if magnitudes.span() <= EXACT_SPAN {
        return build();
    }
    let refusal = |why: String| {
        let (largest, smallest) = (magnitudes.max_abs, magnitudes.smallest);
        Error::new(
            ErrorKind::UnsupportedRange,
            format!(
                "the input's coordinates span {} bits, from a largest magnitude of {largest:e} down to a \
                 smallest nonzero magnitude or difference of {smallest:e}; beyond {EXACT_SPAN} bits \
                 (about 3e144) signs are not all exact in f64, and this input {why}. Round the smallest \
                 differences away or build parts of narrower span separately",
                magnitudes.span()
            ),
            Vec::new(),
        )
    };
    match build() {
        Err(e) if e.kind() == ErrorKind::Internal => Err(refusal(format!("could not be built ({e})"))),
        Ok(diagram) => match diagram.validate().map_err(|e| format!("{e:?}")).and_then(|()| inside_clearances_finite(&diagram)) {
            Ok(()) => Ok(diagram),
            Err(e) => Err(refusal(format!("gave a diagram that fails its check ({e})"))),
        },
        other => other,
    }
}

/// Every vertex inside the domain has a finite clearance: the domain lies
/// within the input's bounding box, inside `±f64::MAX`, so a disk inside it
/// has a radius of at most `f64::MAX`. An infinite one is a vertex beyond
/// the range of `f64` taken for inside, or a clearance that overflowed.
fn inside_clearances_finite(diagram: &Diagram) -> Result<(), String> {
    match diagram.vertices().find(|v| v.clearance.is_infinite() && diagram.vertex_location(v.id) == Some(Location::Inside)) {
        Some(v) => Err(format!("vertex {} is inside the domain with an infinite clearance", v.id.index())),
        None => Ok(()),
    }
}
