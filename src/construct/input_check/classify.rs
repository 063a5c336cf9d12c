//! A pair's conflict, named by input indices: two kept segments, or a kept
//! point and a kept segment, by the exact contact test of
//! `geometry::segment_contact`.

use super::normalise::Normalised;
use super::{Conflict, PointSource};
use crate::geometry::segment_contact::{inside_segment, segment_contact, SegmentContact};

/// The conflict for kept segments `i < j` (positions in `norm.segments`).
pub(super) fn segment_conflict(norm: &Normalised, i: usize, j: usize) -> Option<Conflict> {
    let (first, s) = norm.segments[i];
    let (second, t) = norm.segments[j];
    Some(match segment_contact(s, t)? {
        SegmentContact::Cross => Conflict::SegmentsCross { first, second },
        SegmentContact::Overlap => Conflict::SegmentsOverlap { first, second },
        SegmentContact::EndpointOfSecondOnFirst => Conflict::EndpointOnSegment { segment: first, endpoint_of: second },
        SegmentContact::EndpointOfFirstOnSecond => Conflict::EndpointOnSegment { segment: second, endpoint_of: first },
    })
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
