//! A pair's conflict, named by input indices, and where the pair first
//! meets: two kept segments, or a kept point and a kept segment, by the
//! exact contact test of `geometry::segment_contact`.

use super::normalise::Normalised;
use super::{Conflict, PointSource};
use crate::geometry::segment_contact::{first_contact, inside_segment, segment_contact, ContactPoint, SegmentContact};

/// The conflict for kept segments `i < j` (positions in `norm.segments`),
/// with the pair's first contact point.
pub(super) fn segment_conflict_at(norm: &Normalised, i: usize, j: usize) -> Option<(Conflict, ContactPoint)> {
    let (first, s) = norm.segments[i];
    let (second, t) = norm.segments[j];
    let contact = segment_contact(s, t)?;
    let conflict = match contact {
        SegmentContact::Cross => Conflict::SegmentsCross { first, second },
        SegmentContact::Overlap => Conflict::SegmentsOverlap { first, second },
        SegmentContact::EndpointOfSecondOnFirst => Conflict::EndpointOnSegment { segment: first, endpoint_of: second },
        SegmentContact::EndpointOfFirstOnSecond => Conflict::EndpointOnSegment { segment: second, endpoint_of: first },
    };
    Some((conflict, first_contact(s, t, contact)))
}

/// The conflict for kept point `p` and kept segment `s` (positions).
pub(super) fn point_conflict(norm: &Normalised, p: usize, s: usize) -> Option<Conflict> {
    let (src, q) = norm.points[p];
    let (segment, seg) = norm.segments[s];
    if !inside_segment(q, seg) {
        return None;
    }
    Some(match src {
        PointSource::Point(point) => Conflict::PointOnSegment { point, segment },
        PointSource::Segment(endpoint_of) => Conflict::EndpointOnSegment { segment, endpoint_of },
    })
}

/// [`point_conflict`] with the contact point (the point itself).
pub(super) fn point_conflict_at(norm: &Normalised, p: usize, s: usize) -> Option<(Conflict, ContactPoint)> {
    point_conflict(norm, p, s).map(|c| (c, ContactPoint::At(norm.points[p].1)))
}
