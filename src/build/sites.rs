//! Building from points and segments: check the input (beside the point
//! insertions, on large inputs), list every point in the naming order
//! (isolated points, then each segment's first and second endpoint), insert
//! the points and then the segments, renumber.

use super::finish::{self, SegmentSite};
use super::segment_input::{check_segments, Conflict};
use super::{construct_from, insert_points, run_beside, to_internal, Outcome};
use crate::diagram::{Diagram, SiteId};
use crate::error::{Error, ErrorKind};
use crate::geometry::Point;

/// The diagram of points and segments, and how its construction ended
/// (checked by `Builder::accept`); `Err` for input that crosses itself.
pub(super) fn build_sites(points: &[Point], segments: &[[Point; 2]]) -> Result<(Diagram, Outcome), Error> {
    // P<k> numbers the distinct points of this list by first appearance.
    let mut all: Vec<Point> = Vec::with_capacity(points.len() + 2 * segments.len());
    all.extend_from_slice(points);
    for s in segments {
        all.extend_from_slice(s);
    }
    let (scale, scaled) = to_internal(&all);

    // The points go in whatever the input check finds (a repeated or
    // zero-length segment only repeats points), so on large inputs the
    // check runs on a second thread meanwhile; an error discards the points.
    let (checked, stage) = if segments.len() >= PARALLEL_CHECK_FROM {
        let (checked, stage) =
            run_beside(|| check_segments(points, segments), || insert_points(&scaled, segments.len()));
        (checked, Some(stage))
    } else {
        (check_segments(points, segments), None)
    };
    let checked = checked.map_err(|c| conflict_error(&c))?;
    let stage = stage.unwrap_or_else(|| insert_points(&scaled, segments.len()));

    let endpoint_index = |j: usize| [points.len() + 2 * j, points.len() + 2 * j + 1];
    let kept: Vec<usize> = checked.segments.iter().map(|&(j, _)| j).collect();
    let pairs: Vec<[usize; 2]> = kept.iter().map(|&j| endpoint_index(j)).collect();
    let (built, site_of_input, segment_sites, outcome) = construct_from(stage, &scaled, &pairs);
    let described: Vec<SegmentSite> = kept
        .iter()
        .zip(segment_sites)
        .map(|(&j, internal)| SegmentSite { input: j, internal, ends: segments[j] })
        .collect();
    let mut diagram = finish::finish(built, &site_of_input, &all, &described, scale);

    // Per input segment, its site: a kept one its own, a repeat the first
    // one's, a zero-length one the point it became.
    let first_segment_site = diagram.point_sites;
    diagram.segment_site = checked
        .kept_of_input
        .iter()
        .enumerate()
        .map(|(j, kept)| match *kept {
            Some(k) => SiteId::from_index(first_segment_site + k),
            None => diagram.input_site[endpoint_index(j)[0]],
        })
        .collect();
    diagram.input_site.truncate(points.len());
    diagram.stats.input_points = points.len();
    diagram.stats.input_segments = segments.len();
    diagram.stats.duplicate_points = checked.duplicate_points;
    diagram.stats.duplicate_segments = checked.duplicate_segments;
    diagram.stats.zero_length_segments = checked.degenerate_segments;
    Ok((diagram, outcome))
}

/// From this many segments on, the input check runs beside the point
/// insertions (below, a thread costs more than it saves).
const PARALLEL_CHECK_FROM: usize = 20_000;

/// The builder's error for an input conflict, naming both input indices.
fn conflict_error(conflict: &Conflict) -> Error {
    let indices = match *conflict {
        Conflict::SegmentsCross { first, second } | Conflict::SegmentsOverlap { first, second } => vec![first, second],
        Conflict::EndpointOnSegment { segment, endpoint_of } => vec![segment, endpoint_of],
        Conflict::PointOnSegment { point, segment } => vec![point, segment],
    };
    Error::new(ErrorKind::Intersecting, conflict.message(), indices)
}
