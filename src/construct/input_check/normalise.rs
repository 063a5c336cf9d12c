//! Normalisation of the input: zero-length segments become points, repeated
//! segments and points are dropped and counted (the first one is kept).

use std::collections::HashSet;

use super::PointSource;
use crate::geometry::input::segment_contact::lex_key;
use crate::geometry::Point;

/// The input after normalisation, in internal (scaled) coordinates.
#[derive(Debug, Default)]
pub(super) struct Normalised {
    pub(super) points: Vec<(PointSource, Point)>,
    pub(super) segments: Vec<(usize, [Point; 2])>,
    pub(super) duplicate_points: usize,
    pub(super) duplicate_segments: usize,
    pub(super) degenerate_segments: usize,
    pub(super) kept_of_input: Vec<Option<usize>>,
    /// The kept segments (positions in `segments`) by first point, then by
    /// last point, lexicographically (the sweep's order).
    pub(super) by_first_point: Vec<u32>,
    /// Per kept segment, whether it may overlap another such one: every
    /// input segment it stands for is a ring segment (`allow_ring_overlaps`).
    /// Empty: none may.
    pub(super) may_overlap: Vec<bool>,
}

impl Normalised {
    /// Whether kept segments `i` and `j` may share a stretch: both are ring
    /// segments, whose shared stretches cancel (`construct::shared_stretches`).
    pub(super) fn may_overlap(&self, i: usize, j: usize) -> bool {
        !self.may_overlap.is_empty() && self.may_overlap[i] && self.may_overlap[j]
    }

    /// Marks the kept segments that stand only for ring segments (`ring`:
    /// per input segment, whether a polygon's ring made it; empty for none)
    /// as allowed to overlap each other.
    pub(super) fn allow_ring_overlaps(&mut self, ring: &[bool]) {
        if ring.is_empty() {
            return;
        }
        let mut ok = vec![true; self.segments.len()];
        for (i, kept) in self.kept_of_input.iter().enumerate() {
            if let Some(k) = *kept {
                ok[k] &= ring[i];
            }
        }
        self.may_overlap = ok;
    }
}

/// Zero-length segments become points; repeated segments and points are
/// dropped (the first one is kept). Segment endpoints take precedence over
/// isolated points, which take precedence over zero-length segments.
pub(super) fn normalise(points: &[Point], segments: &[[Point; 2]], internal: impl Fn(Point) -> Point) -> Normalised {
    let mut out = Normalised::default();
    let mut degenerate = Vec::new();
    // Repeats found by sorting the segments by their ends in the sweep's
    // order (first point, then last point; with the input index, so the
    // first of equal keys is the earliest): O(n log n) on sequential
    // memory, where a hash map of a million segments spends most of its
    // time waiting for memory. The sorted order is also the order in which
    // the sweep meets the kept segments' first points, so it sorts nothing
    // more for its start events.
    let mut keyed: Vec<([u64; 4], u32)> = Vec::with_capacity(segments.len());
    // Per input segment, the earliest with its key (itself if none is
    // earlier, `ZERO_LENGTH` for a point); then, once kept, that one's
    // position among the kept. (Each is its own earliest but for repeats,
    // which are rare: only they are written out of input order.)
    let mut first: Vec<u32> = Vec::with_capacity(segments.len());
    for (i, s) in segments.iter().enumerate() {
        let (a, b) = (internal(s[0]), internal(s[1]));
        if a == b {
            out.degenerate_segments += 1;
            degenerate.push((PointSource::Segment(i), a));
            first.push(ZERO_LENGTH);
        } else {
            keyed.push((sweep_key(a, b), i as u32));
            first.push(i as u32);
        }
    }
    keyed.sort_unstable();
    for group in keyed.chunk_by(|x, y| x.0 == y.0).filter(|g| g.len() > 1) {
        for &(_, i) in &group[1..] {
            first[i as usize] = group[0].1;
        }
    }
    for (i, s) in segments.iter().enumerate() {
        let earliest = first[i];
        let kept = if earliest == ZERO_LENGTH {
            out.kept_of_input.push(None);
            continue;
        } else if earliest as usize == i {
            out.segments.push((i, [internal(s[0]), internal(s[1])]));
            first[i] = (out.segments.len() - 1) as u32;
            out.segments.len() - 1
        } else {
            out.duplicate_segments += 1;
            first[earliest as usize] as usize // already its position among the kept
        };
        out.kept_of_input.push(Some(kept));
    }
    out.by_first_point = keyed.chunk_by(|x, y| x.0 == y.0).map(|g| first[g[0].1 as usize]).collect();
    drop((keyed, first));
    if points.is_empty() && degenerate.is_empty() {
        // Nothing to compare with the endpoints: no set of them needed.
        return out;
    }
    // (The keys are the caller's coordinates: the default hasher's random
    // keys keep crafted input from colliding them.)
    let mut seen_points: HashSet<[u64; 2]> = out.segments.iter().flat_map(|(_, s)| s.map(Point::bit_key)).collect();
    let isolated = points.iter().enumerate().map(|(i, &p)| (PointSource::Point(i), internal(p)));
    for (src, p) in isolated.chain(degenerate) {
        if seen_points.insert(Point::bit_key(p)) {
            out.points.push((src, p));
        } else {
            out.duplicate_points += 1;
        }
    }
    out
}

/// Marks a zero-length segment among the earliest indices.
const ZERO_LENGTH: u32 = u32::MAX;

/// A segment's [`lex_key`]s, its lexicographically smaller end first: equal
/// for the same segment in either direction (with canonical zeros), and
/// ordered by first point as the sweep meets them.
fn sweep_key(a: Point, b: Point) -> [u64; 4] {
    let (ka, kb) = (lex_key(a), lex_key(b));
    let ((x0, y0), (x1, y1)) = if ka <= kb { (ka, kb) } else { (kb, ka) };
    [x0, y0, x1, y1]
}
