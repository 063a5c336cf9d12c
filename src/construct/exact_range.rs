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
//! requires finite positions), becomes an [`ErrorKind::UnsupportedRange`]
//! naming the two coordinates, never [`ErrorKind::Internal`] and never an
//! invalid diagram returned as a success.

use crate::diagram::Diagram;
use crate::error::{Error, ErrorKind};
use crate::geometry::point::Point;
use crate::geometry::scale::{Magnitudes, EXACT_SPAN};

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
        Ok(diagram) => match diagram.validate() {
            Ok(()) => Ok(diagram),
            Err(e) => Err(refusal(format!("gave a diagram that fails its check ({e:?})"))),
        },
        other => other,
    }
}
