//! How two closed segments meet, and whether a point lies inside a
//! segment: the contact rules of the input (DESIGN §1), decided exactly —
//! exact orientation signs ([`exact_orientation`], never perturbed by fault
//! injection) and coordinate comparisons ([`strictly_between`]), no epsilon
//! anywhere. The input check (`construct/input_check/`) asks these.

use super::predicates::{exact_orientation as orientation, strictly_between, Orientation};
use super::Point;

/// How two distinct, non-degenerate segments `s` and `t` meet, if they meet
/// in anything other than a common endpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SegmentContact {
    Cross,
    Overlap,
    /// An endpoint of `t` lies inside `s`.
    EndpointOfSecondOnFirst,
    /// An endpoint of `s` lies inside `t`.
    EndpointOfFirstOnSecond,
}

/// Exact classification of two distinct non-degenerate segments.
pub(crate) fn segment_contact(s: [Point; 2], t: [Point; 2]) -> Option<SegmentContact> {
    let [a, b] = s;
    let [c, d] = t;
    let (oc, od) = (orientation(a, b, c), orientation(a, b, d));
    if oc == Orientation::Collinear && od == Orientation::Collinear {
        // On one line the segments are intervals; distinct intervals share
        // more than a point exactly when an endpoint of one lies strictly
        // inside the other (a common endpoint alone is allowed).
        let inside =
            strictly_between(a, b, c) || strictly_between(a, b, d) || strictly_between(c, d, a) || strictly_between(c, d, b);
        return inside.then_some(SegmentContact::Overlap);
    }
    let (oa, ob) = (orientation(c, d, a), orientation(c, d, b));
    if opposite(oc, od) && opposite(oa, ob) {
        return Some(SegmentContact::Cross);
    }
    // Not both collinear, so each of c, d, a, b that lies on the other's
    // line is the only point where the two segments can meet: a conflict
    // when it is inside the other segment, fine when it is a common endpoint
    // or beyond the other segment's ends.
    let on_s = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(a, b, p);
    let on_t = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(c, d, p);
    if on_s(c, oc) || on_s(d, od) {
        Some(SegmentContact::EndpointOfSecondOnFirst)
    } else if on_t(a, oa) || on_t(b, ob) {
        Some(SegmentContact::EndpointOfFirstOnSecond)
    } else {
        None
    }
}

/// Strictly on opposite sides.
fn opposite(p: Orientation, q: Orientation) -> bool {
    matches!(
        (p, q),
        (Orientation::Clockwise, Orientation::CounterClockwise) | (Orientation::CounterClockwise, Orientation::Clockwise)
    )
}

/// Whether the point lies in the open interior of the segment.
pub(crate) fn inside_segment(p: Point, s: [Point; 2]) -> bool {
    orientation(s[0], s[1], p) == Orientation::Collinear && strictly_between(s[0], s[1], p)
}
