//! A pair's conflict, named by input indices, and where the pair first
//! meets: two kept segments, by the exact contact test of
//! `geometry::input::segment_contact`. An endpoint of one inside the other is no
//! conflict (the sweep splits the segment there).

use super::normalise::Normalised;
use super::Conflict;
use crate::geometry::input::segment_contact::{first_contact, segment_contact, ContactPoint, SegmentContact};

/// The conflict for kept segments `i < j` (positions in `norm.segments`),
/// with the pair's first contact point: a crossing or an overlap; `None`
/// when they meet at most at one point that is an endpoint of one of them,
/// or when both are ring segments that overlap (`Normalised::may_overlap`).
pub(super) fn segment_conflict_at(norm: &Normalised, i: usize, j: usize) -> Option<(Conflict, ContactPoint)> {
    let (first, s) = norm.segments[i];
    let (second, t) = norm.segments[j];
    let contact = segment_contact(s, t)?;
    let conflict = match contact {
        SegmentContact::Cross => Conflict::SegmentsCross { first, second },
        // ring segments sharing a stretch: split at its ends, and the
        // equal pieces cancel (`construct::shared_stretches`)
        SegmentContact::Overlap if norm.may_overlap(i, j) => return None,
        SegmentContact::Overlap => Conflict::SegmentsOverlap { first, second },
        SegmentContact::EndpointOfSecondOnFirst | SegmentContact::EndpointOfFirstOnSecond => return None,
    };
    Some((conflict, first_contact(s, t, contact)))
}
