//! The input checker for line-segment sites: normalisation and the
//! intersection rules of DESIGN §1, decided before any diagram is built.
//!
//! # What it does
//! - *Normalisation.* A zero-length segment is a point. A segment that repeats
//!   an earlier one (same endpoints, either direction) is dropped; so is a
//!   point that repeats an earlier point or any segment endpoint. All three are
//!   counted for the build statistics. Equality is coordinate equality, so
//!   `-0.0` equals `+0.0`.
//! - *Conflicts.* Two segments may meet only at a common endpoint (exactly
//!   equal coordinates), any number of them at one point. Everything else is a
//!   [`Conflict`] naming both input indices: a proper crossing, an endpoint in
//!   the open interior of another segment (T-junction), two collinear segments
//!   sharing more than a point, an isolated point in the open interior of a
//!   segment. When several conflicts exist, the one reported is always the same
//!   whatever the grid: the first segment pair in input order, else the first
//!   (point, segment) pair.
//!
//! # Exactness
//! Every decision is an exact orientation sign
//! ([`orientation`](crate::geometry::predicates::orientation), never perturbed by fault injection) or a coordinate comparison ([`strictly_between`]); no
//! epsilon anywhere. Like the point builder, the checker first multiplies the
//! input by a power of two ([`Scale`]) so that 1e300 does not overflow and
//! 1e-300 does not underflow inside the predicates; the answers are those for
//! the coordinates the builder itself works with. Two limits, shared with the
//! point builder: the predicates are exact only while their products do not
//! underflow (points closer than about 1e-70 times the largest coordinate may
//! be misjudged), and an input spanning more than about 600 decimal orders of
//! magnitude loses its tiniest differences in the scaling.
//!
//! # Which pairs are tested: a uniform grid
//! Candidate pairs come from a uniform grid over the bounding box of the
//! segments, stored sparsely (a sorted list of `(cell, item)` incidences, so
//! empty cells cost nothing). The cell side is the mean segment length
//! (`total length / number of segments`), which keeps the number of
//! (segment, cell) incidences at most a small constant times the number of
//! segments for *any* input; it is raised where needed so that no axis has
//! more than 2^24 cells. Each segment is registered in every cell it touches,
//! conservatively (see [`Grid::cover`]); each isolated point in its one cell.
//! Two items are tested only if they share a cell, and a segment pair only in
//! the first cell they share, so no pair is tested twice.
//!
//! Cost: hashing for the normalisation, O(n) expected; sorting the
//! incidences, O(n log n); plus the pairs sharing a cell.
//! For segments spread over the plane with bounded local density that is O(n)
//! pairs, so O(n log n) in all. Worst case O(n²): many segments through one
//! cell (a star of k segments at one point costs k²/2 tests, a dense bundle of
//! long parallel segments likewise; p points in a cell crossed by k segments
//! cost p·k). A Shamos–Hoey sweep would bound the crossing
//! test by O(n log n) always, but it needs exact comparisons of segments at a
//! sweep position and special handling of the shared endpoints that are the
//! normal case here; the grid needs only the orientation predicate.

use std::collections::{HashMap, HashSet};

use crate::geometry::predicates::{exact_orientation as orientation, strictly_between, Orientation};
use crate::geometry::scale::Scale;
use crate::geometry::Point;

/// Where a point of the checked input came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PointSource {
    /// An isolated input point, by its index among the points.
    Point(usize),
    /// A zero-length input segment, by its index among the segments.
    Segment(usize),
}

/// The normalised input: what the builder inserts.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CheckedInput {
    /// Distinct points that are not endpoints of a kept segment, in input
    /// order: isolated points first, then zero-length segments. Coordinates
    /// are the input ones with `-0.0` made `+0.0`.
    pub points: Vec<(PointSource, Point)>,
    /// The kept segments with their input index, in input order, endpoints as
    /// given (with `-0.0` made `+0.0`).
    pub segments: Vec<(usize, [Point; 2])>,
    /// Isolated points and zero-length segments dropped because they repeat
    /// an earlier point or any segment endpoint.
    pub duplicate_points: usize,
    /// Segments dropped because they repeat an earlier segment.
    pub duplicate_segments: usize,
    /// Zero-length segments (each became a point, or merged with one).
    pub degenerate_segments: usize,
    /// Per input segment: the index in `segments` of the kept segment it is
    /// or repeats; `None` for a zero-length segment.
    pub kept_of_input: Vec<Option<usize>>,
}

/// Why the input cannot be built: the kind of intersection and the two input
/// indices involved. Segment and point indices are kept apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Conflict {
    /// Two segments cross at a point interior to both.
    SegmentsCross {
        /// The earlier segment (input index).
        first: usize,
        /// The later segment (input index).
        second: usize,
    },
    /// Two collinear segments share more than a point.
    SegmentsOverlap {
        /// The earlier segment (input index).
        first: usize,
        /// The later segment (input index).
        second: usize,
    },
    /// An endpoint of `endpoint_of` lies in the open interior of `segment`
    /// (a T-junction; `endpoint_of` may be a zero-length segment).
    EndpointOnSegment {
        /// The segment whose interior is touched (input index).
        segment: usize,
        /// The segment whose endpoint touches it (input index).
        endpoint_of: usize,
    },
    /// An isolated point lies in the open interior of a segment.
    PointOnSegment {
        /// The point (input index among the points).
        point: usize,
        /// The segment (input index among the segments).
        segment: usize,
    },
}

impl Conflict {
    /// A sentence naming both input indices, for the error message.
    pub(crate) fn message(&self) -> String {
        match *self {
            Conflict::SegmentsCross { first, second } => format!("segments {first} and {second} cross"),
            Conflict::SegmentsOverlap { first, second } => {
                format!("segments {first} and {second} are collinear and overlap")
            }
            Conflict::EndpointOnSegment { segment, endpoint_of } => {
                format!("an endpoint of segment {endpoint_of} lies inside segment {segment}")
            }
            Conflict::PointOnSegment { point, segment } => format!("point {point} lies inside segment {segment}"),
        }
    }
}

/// Normalises and checks points and segments (finite coordinates, as the
/// builder guarantees). See the module documentation for the rules.
pub(crate) fn check_segments(points: &[Point], segments: &[[Point; 2]]) -> Result<CheckedInput, Conflict> {
    let scale = scale_for(points, segments);
    let internal = |p: Point| p.scaled(scale.to_internal).canonical_zero();
    let norm = normalise(points, segments, internal);
    if let Some(conflict) = find_conflict(&norm) {
        return Err(conflict);
    }
    Ok(CheckedInput {
        points: norm
            .points
            .iter()
            .map(|&(src, _)| (src, input_point(points, segments, src)))
            .collect(),
        segments: norm
            .segments
            .iter()
            .map(|&(i, _)| (i, [segments[i][0].canonical_zero(), segments[i][1].canonical_zero()]))
            .collect(),
        duplicate_points: norm.duplicate_points,
        duplicate_segments: norm.duplicate_segments,
        degenerate_segments: norm.degenerate_segments,
        kept_of_input: norm.kept_of_input,
    })
}

/// The power of two that brings the coordinates into the range where the
/// predicates are exact (`Scale::for_coordinates`).
fn scale_for(points: &[Point], segments: &[[Point; 2]]) -> Scale {
    Scale::for_coordinates(points.iter().chain(segments.iter().flatten()).flat_map(|p| [p.x, p.y]))
}

fn input_point(points: &[Point], segments: &[[Point; 2]], src: PointSource) -> Point {
    match src {
        PointSource::Point(i) => points[i].canonical_zero(),
        PointSource::Segment(i) => segments[i][0].canonical_zero(),
    }
}

/// The input after normalisation, in internal (scaled) coordinates.
#[derive(Debug, Default)]
struct Normalised {
    points: Vec<(PointSource, Point)>,
    segments: Vec<(usize, [Point; 2])>,
    duplicate_points: usize,
    duplicate_segments: usize,
    degenerate_segments: usize,
    kept_of_input: Vec<Option<usize>>,
}

/// Bit pattern of a point with canonical zeros: equal points, equal keys.
fn point_key(p: Point) -> [u64; 2] {
    [p.x.to_bits(), p.y.to_bits()]
}

/// Key of a segment, the same in both directions.
fn segment_key(a: Point, b: Point) -> [u64; 4] {
    let (ka, kb) = (point_key(a), point_key(b));
    let (lo, hi) = if ka <= kb { (ka, kb) } else { (kb, ka) };
    [lo[0], lo[1], hi[0], hi[1]]
}

/// Zero-length segments become points; repeated segments and points are
/// dropped (the first one is kept). Segment endpoints take precedence over
/// isolated points, which take precedence over zero-length segments.
fn normalise(points: &[Point], segments: &[[Point; 2]], internal: impl Fn(Point) -> Point) -> Normalised {
    let mut out = Normalised::default();
    let mut degenerate = Vec::new();
    let mut kept_by_key: HashMap<[u64; 4], usize> = HashMap::with_capacity(segments.len());
    for (i, s) in segments.iter().enumerate() {
        let (a, b) = (internal(s[0]), internal(s[1]));
        if a == b {
            out.degenerate_segments += 1;
            degenerate.push((PointSource::Segment(i), a));
            out.kept_of_input.push(None);
            continue;
        }
        let kept = *kept_by_key.entry(segment_key(a, b)).or_insert_with(|| {
            out.segments.push((i, [a, b]));
            out.segments.len() - 1
        });
        if out.segments[kept].0 != i {
            out.duplicate_segments += 1;
        }
        out.kept_of_input.push(Some(kept));
    }
    drop(kept_by_key);
    if points.is_empty() && degenerate.is_empty() {
        // Nothing to compare with the endpoints: no set of them needed.
        // (The keys are the caller's coordinates: the default hasher's
        // random keys keep crafted input from colliding them.)
        return out;
    }
    let mut seen_points: HashSet<[u64; 2]> = out.segments.iter().flat_map(|(_, s)| s.map(point_key)).collect();
    let isolated = points
        .iter()
        .enumerate()
        .map(|(i, &p)| (PointSource::Point(i), internal(p)));
    for (src, p) in isolated.chain(degenerate) {
        if seen_points.insert(point_key(p)) {
            out.points.push((src, p));
        } else {
            out.duplicate_points += 1;
        }
    }
    out
}

/// How two distinct, non-degenerate segments `s` and `t` meet, if they meet
/// in anything other than a common endpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PairConflict {
    Cross,
    Overlap,
    /// An endpoint of `t` lies inside `s`.
    EndpointOfSecondOnFirst,
    /// An endpoint of `s` lies inside `t`.
    EndpointOfFirstOnSecond,
}

/// Exact classification of two distinct non-degenerate segments.
fn classify(s: [Point; 2], t: [Point; 2]) -> Option<PairConflict> {
    let [a, b] = s;
    let [c, d] = t;
    let (oc, od) = (orientation(a, b, c), orientation(a, b, d));
    if oc == Orientation::Collinear && od == Orientation::Collinear {
        // On one line the segments are intervals; distinct intervals share
        // more than a point exactly when an endpoint of one lies strictly
        // inside the other (a common endpoint alone is allowed).
        let inside = strictly_between(a, b, c)
            || strictly_between(a, b, d)
            || strictly_between(c, d, a)
            || strictly_between(c, d, b);
        return inside.then_some(PairConflict::Overlap);
    }
    let (oa, ob) = (orientation(c, d, a), orientation(c, d, b));
    if opposite(oc, od) && opposite(oa, ob) {
        return Some(PairConflict::Cross);
    }
    // Not both collinear, so each of c, d, a, b that lies on the other's
    // line is the only point where the two segments can meet: a conflict
    // when it is inside the other segment, fine when it is a common endpoint
    // or beyond the other segment's ends.
    let on_s = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(a, b, p);
    let on_t = |p: Point, o: Orientation| o == Orientation::Collinear && strictly_between(c, d, p);
    if on_s(c, oc) || on_s(d, od) {
        Some(PairConflict::EndpointOfSecondOnFirst)
    } else if on_t(a, oa) || on_t(b, ob) {
        Some(PairConflict::EndpointOfFirstOnSecond)
    } else {
        None
    }
}

/// Strictly on opposite sides.
fn opposite(p: Orientation, q: Orientation) -> bool {
    matches!(
        (p, q),
        (Orientation::Clockwise, Orientation::CounterClockwise)
            | (Orientation::CounterClockwise, Orientation::Clockwise)
    )
}

/// Whether the point lies in the open interior of the segment.
fn point_inside(p: Point, s: [Point; 2]) -> bool {
    orientation(s[0], s[1], p) == Orientation::Collinear && strictly_between(s[0], s[1], p)
}

/// The conflict for kept segments `i < j` (positions in `norm.segments`).
fn segment_conflict(norm: &Normalised, i: usize, j: usize) -> Option<Conflict> {
    let (first, s) = norm.segments[i];
    let (second, t) = norm.segments[j];
    Some(match classify(s, t)? {
        PairConflict::Cross => Conflict::SegmentsCross { first, second },
        PairConflict::Overlap => Conflict::SegmentsOverlap { first, second },
        PairConflict::EndpointOfSecondOnFirst => Conflict::EndpointOnSegment {
            segment: first,
            endpoint_of: second,
        },
        PairConflict::EndpointOfFirstOnSecond => Conflict::EndpointOnSegment {
            segment: second,
            endpoint_of: first,
        },
    })
}

/// The conflict for kept point `p` and kept segment `s` (positions).
fn point_conflict(norm: &Normalised, p: usize, s: usize) -> Option<Conflict> {
    let (src, q) = norm.points[p];
    let (segment, seg) = norm.segments[s];
    if !point_inside(q, seg) {
        return None;
    }
    Some(match src {
        PointSource::Point(point) => Conflict::PointOnSegment { point, segment },
        PointSource::Segment(endpoint_of) => Conflict::EndpointOnSegment { segment, endpoint_of },
    })
}

/// A sparse uniform grid: cells are `(column, row)` packed in a `u64`.
#[derive(Clone, Copy, Debug)]
struct Grid {
    /// Lower-left corner of the bounding box.
    min: Point,
    /// Cell side.
    h: f64,
    /// `1 / h`.
    inv_h: f64,
    /// Widening of every range before it is turned into cells: far larger
    /// than the rounding of the interpolations (a few ulps of the extent,
    /// while `h >= extent / 2^24`), far smaller than a cell.
    margin: f64,
    /// All items in one cell: the extent is too tiny for the margin.
    single: bool,
}

/// No axis has more than this many cells, so a cell index fits in 32 bits
/// and a cell is wide enough for `margin` to exceed the rounding errors.
const MAX_CELLS_PER_AXIS: f64 = (1u32 << 24) as f64;

impl Grid {
    /// The grid for the kept segments (there is at least one).
    fn for_segments(segments: &[(usize, [Point; 2])]) -> Grid {
        let (min, max) = bounding_box(segments);
        let total_length: f64 = segments.iter().map(|(_, [a, b])| a.distance(*b)).sum();
        let extent = (max.x - min.x).max(max.y - min.y);
        // The mean length bounds the incidences: a segment of length l
        // touches at most about 3 (l / h + 1) cells, and those sum to O(n).
        let h = (total_length / segments.len() as f64).max(extent / MAX_CELLS_PER_AXIS);
        let inv_h = 1.0 / h;
        // Below this (an extent under ~1e-290 after scaling) the margin
        // would sink into subnormal numbers; one cell is then the safe grid.
        let single = !(h >= f64::MIN_POSITIVE * 2f64.powi(60) && inv_h.is_finite());
        Grid {
            min,
            h,
            inv_h,
            margin: h / 1024.0,
            single,
        }
    }

    /// Cell index of an offset from the grid corner along one axis: a
    /// monotone function of the offset (rounding keeps order; the cast
    /// truncates toward zero and saturates below 0), which is what makes the
    /// covering conservative.
    fn index(&self, offset: f64) -> u32 {
        (offset * self.inv_h) as u32
    }

    fn key(column: u32, row: u32) -> u64 {
        (u64::from(column) << 32) | u64::from(row)
    }

    /// A point's offset from the grid corner. Everything is computed in
    /// offsets: their rounding errors are ulps of the extent, never of the
    /// coordinates (near 1e15 an ulp of a coordinate can exceed a cell).
    fn offset(&self, p: Point) -> Point {
        Point::new(p.x - self.min.x, p.y - self.min.y)
    }

    /// The cell of a point.
    fn cell_of(&self, p: Point) -> u64 {
        if self.single {
            return 0;
        }
        let o = self.offset(p);
        Grid::key(self.index(o.x), self.index(o.y))
    }

    /// Appends every cell the segment `ab` touches, and possibly a few
    /// neighbours: a superset of the cells holding its points.
    ///
    /// It walks the cells along the segment's dominant axis (so the slope
    /// along it is at most 1 and interpolation errors stay a few ulps of the
    /// extent). Along that axis the range of cells is exact, by monotonicity
    /// of [`Grid::index`]. Within one such cell the segment's range on the
    /// other axis is interpolated at the cell's sides widened by `margin`,
    /// widened by `margin` again, and clipped to the segment's own exact
    /// range of cells.
    fn cover(&self, a: Point, b: Point, out: &mut Vec<u64>) {
        if self.single {
            out.push(0);
            return;
        }
        let (a, b) = (self.offset(a), self.offset(b));
        if (b.x - a.x).abs() >= (b.y - a.y).abs() {
            self.cover_along_x(a, b, &mut |major, minor| out.push(Grid::key(major, minor)));
        } else {
            let flip = |p: Point| Point::new(p.y, p.x);
            self.cover_along_x(flip(a), flip(b), &mut |major, minor| out.push(Grid::key(minor, major)));
        }
    }

    /// [`Grid::cover`] for offsets `a`, `b` with `|dx| >= |dy|` (and not both
    /// zero); `emit(column, row)`.
    fn cover_along_x(&self, a: Point, b: Point, emit: &mut impl FnMut(u32, u32)) {
        let (a, b) = if a.x <= b.x { (a, b) } else { (b, a) };
        // b.x > a.x: distinct floats never subtract to 0, and |dx| >= |dy|.
        let slope = (b.y - a.y) / (b.x - a.x);
        let (row_lo, row_hi) = (self.index(a.y.min(b.y)), self.index(a.y.max(b.y)));
        for column in self.index(a.x)..=self.index(b.x) {
            let x0 = (f64::from(column) * self.h - self.margin).max(a.x);
            let x1 = (f64::from(column + 1) * self.h + self.margin).min(b.x);
            let (y0, y1) = (a.y + (x0 - a.x) * slope, a.y + (x1 - a.x) * slope);
            let first = self.index(y0.min(y1) - self.margin).max(row_lo);
            let last = self.index(y0.max(y1) + self.margin).min(row_hi);
            for row in first..=last {
                emit(column, row);
            }
        }
    }
}

/// The first conflict (segment pairs in input order first, then
/// (point, segment) pairs), found through the grid.
fn find_conflict(norm: &Normalised) -> Option<Conflict> {
    if norm.segments.is_empty() {
        return None; // distinct points never conflict
    }
    let grid = Grid::for_segments(&norm.segments);
    let cells = SegmentCells::new(&grid, &norm.segments);
    let incidences = incidences(&grid, &cells, norm);
    let m = norm.segments.len() as u32;
    let mut best_segments: Option<(u32, u32)> = None;
    let mut best_point: Option<(u32, u32)> = None;
    for group in incidences.chunk_by(|x, y| x.0 == y.0) {
        let cell = group[0].0;
        let split = group.partition_point(|&(_, item)| item < m);
        let (segments, points) = (&group[..split], &group[split..]);
        for (k, &(_, i)) in segments.iter().enumerate() {
            for &(_, j) in &segments[k + 1..] {
                // Items are sorted, so i < j; test only in the first shared
                // cell, and only pairs that could beat the best so far.
                if best_segments.is_some_and(|best| (i, j) >= best) || cells.first_common(i, j) != Some(cell) {
                    continue;
                }
                if segment_conflict(norm, i as usize, j as usize).is_some() {
                    best_segments = Some((i, j));
                }
            }
        }
        if best_segments.is_some() {
            continue; // a segment conflict wins over any point conflict
        }
        for &(_, p) in points {
            for &(_, s) in segments {
                let pair = (p - m, s);
                if best_point.map_or(true, |best| pair < best)
                    && point_conflict(norm, pair.0 as usize, s as usize).is_some()
                {
                    best_point = Some(pair);
                }
            }
        }
    }
    if let Some((i, j)) = best_segments {
        return segment_conflict(norm, i as usize, j as usize);
    }
    best_point.and_then(|(p, s)| point_conflict(norm, p as usize, s as usize))
}

/// Each segment's cells, sorted, in one flat array.
struct SegmentCells {
    cells: Vec<u64>,
    /// Segment `i` owns `cells[start[i]..start[i + 1]]`.
    start: Vec<usize>,
}

impl SegmentCells {
    fn new(grid: &Grid, segments: &[(usize, [Point; 2])]) -> SegmentCells {
        let mut cells = Vec::with_capacity(4 * segments.len());
        let mut start = Vec::with_capacity(segments.len() + 1);
        start.push(0);
        for (_, [a, b]) in segments {
            let from = cells.len();
            grid.cover(*a, *b, &mut cells);
            cells[from..].sort_unstable();
            start.push(cells.len());
        }
        SegmentCells { cells, start }
    }

    fn of(&self, i: u32) -> &[u64] {
        &self.cells[self.start[i as usize]..self.start[i as usize + 1]]
    }

    /// The smallest cell of both segments (a merge of two sorted lists).
    fn first_common(&self, i: u32, j: u32) -> Option<u64> {
        let (mut x, mut y) = (self.of(i).iter().peekable(), self.of(j).iter().peekable());
        while let (Some(&&p), Some(&&q)) = (x.peek(), y.peek()) {
            match p.cmp(&q) {
                std::cmp::Ordering::Less => {
                    x.next();
                }
                std::cmp::Ordering::Greater => {
                    y.next();
                }
                std::cmp::Ordering::Equal => return Some(p),
            }
        }
        None
    }
}

/// All `(cell, item)` pairs sorted, where items `0..m` are the kept segments
/// and `m + p` is kept point `p`. Points outside the segments' bounding box
/// cannot touch a segment and are left out.
fn incidences(grid: &Grid, cells: &SegmentCells, norm: &Normalised) -> Vec<(u64, u32)> {
    let m = norm.segments.len();
    assert!(m + norm.points.len() <= u32::MAX as usize, "item ids are 32-bit");
    let mut out: Vec<(u64, u32)> = Vec::with_capacity(cells.cells.len() + norm.points.len());
    for i in 0..m as u32 {
        out.extend(cells.of(i).iter().map(|&c| (c, i)));
    }
    let (lo, hi) = bounding_box(&norm.segments);
    for (p, &(_, q)) in norm.points.iter().enumerate() {
        if lo.x <= q.x && q.x <= hi.x && lo.y <= q.y && q.y <= hi.y {
            out.push((grid.cell_of(q), (m + p) as u32));
        }
    }
    out.sort_unstable();
    out
}

fn bounding_box(segments: &[(usize, [Point; 2])]) -> (Point, Point) {
    let mut lo = Point::new(f64::INFINITY, f64::INFINITY);
    let mut hi = Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in segments.iter().flat_map(|(_, s)| s) {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn s(ax: f64, ay: f64, bx: f64, by: f64) -> [Point; 2] {
        [p(ax, ay), p(bx, by)]
    }

    fn check(segments: &[[Point; 2]]) -> Result<CheckedInput, Conflict> {
        check_segments(&[], segments)
    }

    fn up(x: f64) -> f64 {
        f64::from_bits(x.to_bits() + 1)
    }

    fn down(x: f64) -> f64 {
        f64::from_bits(x.to_bits() - 1)
    }

    // ---- normalisation ----

    #[test]
    fn empty_and_points_only() {
        let out = check_segments(&[], &[]).unwrap();
        assert!(out.points.is_empty() && out.segments.is_empty());
        let out = check_segments(&[p(1., 2.), p(1., 2.), p(3., 4.)], &[]).unwrap();
        assert_eq!(
            out.points,
            vec![(PointSource::Point(0), p(1., 2.)), (PointSource::Point(2), p(3., 4.))]
        );
        assert_eq!(out.duplicate_points, 1);
    }

    #[test]
    fn zero_length_segment_is_a_point_and_negative_zero_equals_zero() {
        let out = check(&[s(0., -0., -0., 0.), s(1., 1., 2., 2.)]).unwrap();
        assert_eq!(out.degenerate_segments, 1);
        assert_eq!(out.points, vec![(PointSource::Segment(0), p(0., 0.))]);
        assert!(out.points[0].1.x.is_sign_positive() && out.points[0].1.y.is_sign_positive());
        assert_eq!(out.segments, vec![(1, s(1., 1., 2., 2.))]);
    }

    #[test]
    fn duplicate_segments_merge_in_either_direction() {
        let out = check(&[
            s(0., 0., 1., 0.),
            s(1., 0., 0., 0.),
            s(0., 0., 1., 0.),
            s(-0., 0., 1., -0.),
        ])
        .unwrap();
        assert_eq!(out.segments, vec![(0, s(0., 0., 1., 0.))]);
        assert_eq!(out.duplicate_segments, 3);
        assert_eq!(out.kept_of_input, vec![Some(0); 4]);
    }

    #[test]
    fn points_on_endpoints_and_repeated_points_merge() {
        let points = [p(1., 0.), p(5., 5.), p(5., 5.)];
        let segments = [
            s(0., 0., 1., 0.),
            s(5., 5., 5., 5.),
            s(7., 7., 7., 7.),
            s(0., 0., 0., 0.),
        ];
        let out = check_segments(&points, &segments).unwrap();
        // Endpoint (1,0) absorbs point 0; point 1 absorbs point 2 and the
        // zero-length segment 1; segment 3 repeats an endpoint.
        assert_eq!(
            out.points,
            vec![(PointSource::Point(1), p(5., 5.)), (PointSource::Segment(2), p(7., 7.))]
        );
        assert_eq!((out.duplicate_points, out.degenerate_segments), (4, 3));
    }

    #[test]
    fn output_keeps_input_coordinates_of_huge_inputs() {
        let input = [s(1e300, -1e300, 3e300, 2e300)];
        let out = check_segments(&[p(-1e300, 7e299)], &input).unwrap();
        assert_eq!(out.segments, vec![(0, input[0])]);
        assert_eq!(out.points, vec![(PointSource::Point(0), p(-1e300, 7e299))]);
    }

    // ---- conflicts ----

    #[test]
    fn crossing_segments() {
        let r = check(&[s(0., 0., 2., 2.), s(5., 5., 6., 6.), s(0., 2., 2., 0.)]);
        assert_eq!(r, Err(Conflict::SegmentsCross { first: 0, second: 2 }));
        assert_eq!(r.unwrap_err().message(), "segments 0 and 2 cross");
    }

    #[test]
    fn horizontal_and_vertical() {
        assert_eq!(
            check(&[s(-1., 0., 1., 0.), s(0., -1., 0., 1.)]),
            Err(Conflict::SegmentsCross { first: 0, second: 1 })
        );
        // Vertical stem ending on a horizontal bar, both orders.
        let t = Conflict::EndpointOnSegment {
            segment: 0,
            endpoint_of: 1,
        };
        assert_eq!(check(&[s(-1., 0., 1., 0.), s(0., 0., 0., 1.)]), Err(t));
        let t = Conflict::EndpointOnSegment {
            segment: 1,
            endpoint_of: 0,
        };
        assert_eq!(check(&[s(0., 5., 0., 1.), s(1., 1., -1., 1.)]), Err(t));
        // An L and a vertical pair touching end to end are fine.
        assert!(check(&[s(0., 0., 1., 0.), s(1., 0., 1., 1.), s(1., 1., 1., 3.)]).is_ok());
    }

    #[test]
    fn t_junction_names_both_segments() {
        let r = check(&[s(0., 0., 1., 3.), s(0., 0., 4., 0.), s(2., 0., 2., 3.)]);
        let c = Conflict::EndpointOnSegment {
            segment: 1,
            endpoint_of: 2,
        };
        assert_eq!(r, Err(c));
        assert_eq!(c.message(), "an endpoint of segment 2 lies inside segment 1");
    }

    #[test]
    fn collinear_cases() {
        let overlap = |a, b| Err(Conflict::SegmentsOverlap { first: a, second: b });
        assert_eq!(check(&[s(0., 0., 2., 2.), s(1., 1., 3., 3.)]), overlap(0, 1));
        assert_eq!(
            check(&[s(0., 0., 4., 0.), s(3., 0., 1., 0.)]),
            overlap(0, 1),
            "contained"
        );
        assert_eq!(
            check(&[s(0., 0., 4., 0.), s(0., 0., 1., 0.)]),
            overlap(0, 1),
            "contained, common end"
        );
        assert_eq!(
            check(&[s(0., 0., 0., 4.), s(0., 4., 0., 1.)]),
            overlap(0, 1),
            "vertical"
        );
        assert!(
            check(&[s(0., 0., 1., 1.), s(1., 1., 2., 2.), s(2., 2., 5., 5.)]).is_ok(),
            "consecutive"
        );
        assert!(check(&[s(0., 0., 1., 1.), s(2., 2., 3., 3.)]).is_ok(), "disjoint");
        assert!(
            check(&[s(0., 0., 1., 0.), s(3., 0., 2., 0.), s(-1., 0., -3., 0.)]).is_ok(),
            "disjoint"
        );
        assert_eq!(
            Conflict::SegmentsOverlap { first: 4, second: 9 }.message(),
            "segments 4 and 9 are collinear and overlap"
        );
    }

    #[test]
    fn point_inside_segment() {
        let r = check_segments(&[p(9., 9.), p(1., 1.)], &[s(0., 0., 2., 2.)]);
        assert_eq!(r, Err(Conflict::PointOnSegment { point: 1, segment: 0 }));
        assert_eq!(r.unwrap_err().message(), "point 1 lies inside segment 0");
        // On the line but outside, and on an endpoint: fine.
        assert!(check_segments(&[p(3., 3.), p(2., 2.)], &[s(0., 0., 2., 2.)]).is_ok());
        // A zero-length segment inside a segment is an endpoint on it.
        let r = check(&[s(0., 0., 2., 2.), s(1., 1., 1., 1.)]);
        assert_eq!(
            r,
            Err(Conflict::EndpointOnSegment {
                segment: 0,
                endpoint_of: 1
            })
        );
    }

    #[test]
    fn first_conflict_in_input_order_is_reported() {
        // Pairs (1,2) and (0,3) both cross; (0,3) comes first.
        let segments = [
            s(0., 10., 2., 12.),
            s(0., 0., 2., 2.),
            s(0., 2., 2., 0.),
            s(0., 12., 2., 10.),
        ];
        assert_eq!(check(&segments), Err(Conflict::SegmentsCross { first: 0, second: 3 }));
        // A segment conflict wins over an earlier point conflict.
        let r = check_segments(
            &[p(1., 11.)],
            &[s(0., 11., 2., 11.), s(0., 0., 2., 2.), s(0., 2., 2., 0.)],
        );
        assert_eq!(r, Err(Conflict::SegmentsCross { first: 1, second: 2 }));
    }

    // ---- allowed shared endpoints ----

    #[test]
    fn star_of_256_segments() {
        let centre = p(0.5, -0.25);
        let star: Vec<[Point; 2]> = (0..256)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 256.0;
                [centre, p(centre.x + t.cos(), centre.y + t.sin())]
            })
            .collect();
        let out = check(&star).unwrap();
        assert_eq!(out.segments.len(), 256);
        // One more spoke through the centre crosses nothing but overlaps
        // the spoke pointing the same way.
        let mut bad = star.clone();
        bad.push([p(centre.x - 0.5, centre.y), p(centre.x + 0.5, centre.y)]);
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 0, second: 256 }));
    }

    fn polygon(centre: Point, radius: f64, n: usize) -> Vec<[Point; 2]> {
        let corner = |k: usize| {
            let t = (k % n) as f64 * std::f64::consts::TAU / n as f64;
            p(centre.x + radius * t.cos(), centre.y + radius * t.sin())
        };
        (0..n).map(|k| [corner(k), corner(k + 1)]).collect()
    }

    #[test]
    fn closed_polygon_and_polygon_with_hole() {
        let outer = polygon(p(0., 0.), 10., 1000);
        assert!(check(&outer).is_ok());
        let mut with_hole = outer.clone();
        with_hole.extend(polygon(p(1., 0.), 3., 37));
        with_hole.extend(polygon(p(-5., 0.), 1., 3));
        let out = check_segments(&[p(0.5, 0.5)], &with_hole).unwrap();
        assert_eq!(out.segments.len(), 1040);
        // A hole too big for its polygon crosses it.
        let mut bad = outer;
        bad.extend(polygon(p(5., 0.), 6., 5));
        assert!(matches!(check(&bad), Err(Conflict::SegmentsCross { .. })));
    }

    // ---- exactness ----

    #[test]
    fn one_ulp_decides() {
        let bar = s(0., 0., 2., 0.);
        assert!(check(&[bar, s(1., up(0.), 1., 5.)]).is_ok(), "one ulp above");
        assert_eq!(
            check(&[bar, s(1., 0., 1., 5.)]),
            Err(Conflict::EndpointOnSegment {
                segment: 0,
                endpoint_of: 1
            })
        );
        assert_eq!(
            check(&[bar, s(1., -f64::from_bits(1), 1., 5.)]),
            Err(Conflict::SegmentsCross { first: 0, second: 1 })
        );
        // Near the end of the bar: one ulp beyond it is fine.
        assert!(check(&[bar, s(up(2.), 0., 3., 5.)]).is_ok());
        assert_eq!(
            check(&[bar, s(down(2.), 0., 3., 5.)]),
            Err(Conflict::EndpointOnSegment {
                segment: 0,
                endpoint_of: 1
            })
        );
        // A diagonal: a point one ulp off the line is not on it.
        let diag = s(0.1, 0.1, 0.7, 0.7);
        assert!(check_segments(&[p(0.3, up(0.3))], &[diag]).is_ok());
        assert!(check_segments(&[p(0.3, 0.3)], &[diag]).is_err());
        // Nearly parallel segments one ulp apart.
        assert!(check(&[s(0., 1., 1e6, 1.), s(0., up(1.), 1e6, up(1.))]).is_ok());
        assert!(check(&[s(0., 1., 1e6, 1.), s(0., up(1.), 1e6, down(1.))]).is_err());
    }

    #[test]
    fn huge_and_tiny_coordinates() {
        for &f in &[1e300, 1e-300, 1.0, f64::from_bits(8) /* 8 × 2^-1074 */] {
            let cross = [s(-f, -f, f, f), s(-f, f, f, -f)];
            assert_eq!(
                check(&cross),
                Err(Conflict::SegmentsCross { first: 0, second: 1 }),
                "{f}"
            );
            let apart = [s(-f, -f, f, f), s(-f, f, -f / 2.0, 0.5 * f)];
            assert!(check(&apart).is_ok(), "{f}");
        }
        // Tiny: on the diagonal, and one ulp off it (products underflow
        // without the power-of-two scaling).
        let diag = s(0., 0., 2e-300, 2e-300);
        assert!(check_segments(&[p(1e-300, 1e-300)], &[diag]).is_err());
        assert!(check_segments(&[p(1e-300, up(1e-300))], &[diag]).is_ok());
        // Huge: a T-junction and its one-ulp miss (products overflow
        // without the scaling).
        let bar = s(-1e300, 1e300, 1e300, -1e300);
        assert!(check(&[bar, s(3e299, -3e299, 1e300, 1e300)]).is_err());
        assert!(
            check(&[bar, s(3e299, down(-3e299), 1e300, 1e300)]).is_ok(),
            "one ulp nearer zero"
        );
        // Beyond the documented range: a difference of 1e-324 next to 1e300
        // vanishes in the scaling (as in the point builder), so this touches.
        assert!(check(&[bar, s(f64::from_bits(1), 0., 1e300, 1e300)]).is_err());
    }

    #[test]
    fn tiny_extent_next_to_a_far_point_uses_one_cell() {
        // The far point sets the scale, so the segments' extent stays near
        // 1e-300: the grid falls back to one cell. (The orientations there
        // underflow, beyond the predicates' documented exact range, so only
        // "no panic, an answer" is asserted.)
        let t = 1e-300;
        let segments = [s(0., 0., t, 0.), s(t, 0., t, t), s(0., t, 0.5 * t, 2. * t)];
        let grid = Grid::for_segments(&segments.map(|q| (0, q)));
        assert!(grid.single);
        let mut cells = Vec::new();
        grid.cover(segments[2][0], segments[2][1], &mut cells);
        assert_eq!((cells, grid.cell_of(p(t, t))), (vec![0], 0));
        let _ = check_segments(&[p(1.0, 1.0)], &segments);
    }

    // ---- the grid against brute force ----

    /// All pairs, in the order `find_conflict` promises.
    fn brute_force(norm: &Normalised) -> Option<Conflict> {
        let m = norm.segments.len();
        let seg = (0..m)
            .flat_map(|i| (i + 1..m).map(move |j| (i, j)))
            .find_map(|(i, j)| segment_conflict(norm, i, j));
        seg.or_else(|| {
            (0..norm.points.len())
                .flat_map(|q| (0..m).map(move |s| (q, s)))
                .find_map(|(q, s)| point_conflict(norm, q, s))
        })
    }

    /// Whether integer input breaks the rules, decided independently of
    /// `classify`: intersections computed in exact integer arithmetic.
    fn integer_oracle(points: &[(i64, i64)], segments: &[[(i64, i64); 2]]) -> bool {
        let mut kept: Vec<[(i64, i64); 2]> = Vec::new();
        let mut lone: Vec<(i64, i64)> = points.to_vec();
        for &[a, b] in segments {
            if a == b {
                lone.push(a);
            } else if !kept.iter().any(|&[c, d]| (a, b) == (c, d) || (a, b) == (d, c)) {
                kept.push([a, b]);
            }
        }
        let pairs = (0..kept.len()).any(|i| (i + 1..kept.len()).any(|j| integer_pair_conflict(kept[i], kept[j])));
        pairs || lone.iter().any(|&q| kept.iter().any(|&seg| integer_inside(q, seg)))
    }

    fn sub(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        (a.0 - b.0, a.1 - b.1)
    }
    fn cross(u: (i64, i64), v: (i64, i64)) -> i64 {
        u.0 * v.1 - u.1 * v.0
    }
    fn dot(u: (i64, i64), v: (i64, i64)) -> i64 {
        u.0 * v.0 + u.1 * v.1
    }

    fn integer_inside(q: (i64, i64), [a, b]: [(i64, i64); 2]) -> bool {
        let (r, w) = (sub(b, a), sub(q, a));
        cross(r, w) == 0 && 0 < dot(r, w) && dot(r, w) < dot(r, r)
    }

    /// Closed segments meet in anything but a common endpoint.
    fn integer_pair_conflict([a, b]: [(i64, i64); 2], [c, d]: [(i64, i64); 2]) -> bool {
        let (r, q, w) = (sub(b, a), sub(d, c), sub(c, a));
        let den = cross(r, q);
        if den == 0 {
            if cross(r, w) != 0 {
                return false; // parallel lines
            }
            // Same line: parameters along r; conflict iff the overlap has length.
            let (tc, td) = (dot(r, w), dot(r, sub(d, a)));
            return tc.max(td).min(dot(r, r)) > tc.min(td).max(0);
        }
        // a + t r = c + u q with t = tn / den, u = un / den.
        let (tn, un) = (cross(w, q), cross(w, r));
        let (tn, un, den) = if den < 0 { (-tn, -un, -den) } else { (tn, un, den) };
        let meets = (0..=den).contains(&tn) && (0..=den).contains(&un);
        let at_end = |n: i64| n == 0 || n == den;
        meets && !(at_end(tn) && at_end(un))
    }

    /// `v * scale + offset`, exact for the placements used here.
    fn to_f64(v: (i64, i64), (scale, offset): (f64, f64)) -> Point {
        p(v.0 as f64 * scale + offset, v.1 as f64 * scale + offset)
    }

    type IntInput = (Vec<(i64, i64)>, Vec<[(i64, i64); 2]>);

    /// Coordinates on a small grid: shared endpoints, T-junctions and
    /// collinear neighbours are common.
    fn small_grid_input() -> impl Strategy<Value = IntInput> {
        let v = (0i64..6, 0i64..6);
        (
            prop::collection::vec(v.clone(), 0..5),
            prop::collection::vec([v.clone(), v], 0..12),
        )
    }

    /// Short segments spread over a larger grid: many grid cells in use.
    fn spread_input() -> impl Strategy<Value = IntInput> {
        let seg = ((0i64..40, 0i64..40), (-4i64..=4, -4i64..=4)).prop_map(|(a, d)| [a, (a.0 + d.0, a.1 + d.1)]);
        (
            prop::collection::vec((0i64..40, 0i64..40), 0..20),
            prop::collection::vec(seg, 0..50),
        )
    }

    /// A random walk on a small grid as a polyline: every inner vertex is a
    /// shared endpoint, and the walk often touches or retraces itself.
    fn polyline_input() -> impl Strategy<Value = IntInput> {
        let steps = prop::collection::vec((-2i64..=2, -2i64..=2), 1..10);
        (
            (0i64..8, 0i64..8),
            steps,
            prop::collection::vec((0i64..8, 0i64..8), 0..3),
        )
            .prop_map(|(start, steps, points)| {
                let mut at = start;
                let mut segments = Vec::new();
                for (dx, dy) in steps {
                    let next = (at.0 + dx, at.1 + dy);
                    segments.push([at, next]);
                    at = next;
                }
                (points, segments)
            })
    }

    fn run(input: &IntInput, f: (f64, f64)) -> Result<(), TestCaseError> {
        let (points, segments) = input;
        let fp: Vec<Point> = points.iter().map(|&v| to_f64(v, f)).collect();
        let fs: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|v| to_f64(v, f))).collect();
        let norm = normalise(&fp, &fs, |q| q.scaled(scale_for(&fp, &fs).to_internal).canonical_zero());
        let grid_answer = find_conflict(&norm);
        prop_assert_eq!(grid_answer, brute_force(&norm));
        prop_assert_eq!(grid_answer.is_some(), integer_oracle(points, segments));
        prop_assert_eq!(check_segments(&fp, &fs).err(), grid_answer);
        Ok(())
    }

    /// Exact placements `(scale, offset)` of the integer inputs, so that
    /// the integer oracle stays right: powers of two (and 3) move them to
    /// magnitudes where the power-of-two scaling matters; the offsets put
    /// them far from the origin, where one ulp of a coordinate is a sizeable
    /// part of a grid cell.
    fn placement() -> impl Strategy<Value = (f64, f64)> {
        prop::sample::select(vec![
            (1.0, 0.0),
            (3.0, 0.0),
            (2f64.powi(1000), 0.0),
            (2f64.powi(-1000), 0.0),
            (f64::from_bits(1 << 4), 0.0), // 2^-1070, subnormal
            (0.25, 2f64.powi(50)),         // ulp 0.25
            (1.0, -(2f64.powi(52))),       // ulp 0.5 to 1
        ])
    }

    /// Segments with real coordinates in `[-r, r)`.
    fn real_segments(r: f64, count: std::ops::Range<usize>) -> impl Strategy<Value = Vec<[(f64, f64); 2]>> {
        let v = (-r..r, -r..r);
        prop::collection::vec([v.clone(), v], count)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

        #[test]
        fn grid_agrees_with_brute_force_small_grid(input in small_grid_input(), f in placement()) {
            run(&input, f)?;
        }

        #[test]
        fn grid_agrees_with_brute_force_spread(input in spread_input(), f in placement()) {
            run(&input, f)?;
        }

        #[test]
        fn grid_agrees_with_brute_force_polyline(input in polyline_input(), f in placement()) {
            run(&input, f)?;
        }

        /// Random real coordinates: crossings are common, collinearity not.
        #[test]
        fn grid_agrees_with_brute_force_reals(
            segments in real_segments(100.0, 0..40),
        ) {
            let fs: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|(x, y)| p(x, y))).collect();
            let norm = normalise(&[], &fs, |q| q.canonical_zero());
            prop_assert_eq!(find_conflict(&norm), brute_force(&norm));
        }

        /// Points computed along a segment land in cells it registered.
        #[test]
        fn cover_is_conservative(
            segments in real_segments(1e3, 1..30),
        ) {
            let kept: Vec<(usize, [Point; 2])> = segments
                .iter()
                .map(|s| s.map(|(x, y)| p(x, y)))
                .filter(|[a, b]| a != b)
                .enumerate()
                .collect();
            prop_assume!(!kept.is_empty());
            let grid = Grid::for_segments(&kept);
            for (_, [a, b]) in &kept {
                let mut cells = Vec::new();
                grid.cover(*a, *b, &mut cells);
                for k in 0..=64 {
                    let t = k as f64 / 64.0;
                    let q = p(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
                    prop_assert!(cells.contains(&grid.cell_of(q)), "{:?} {:?} t={}", a, b, t);
                }
            }
        }
    }

    // ---- scale ----

    /// A tiny xorshift generator: the test needs no other dependency.
    struct Rng(u64);
    impl Rng {
        fn unit(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// One short segment in each cell of a 317 × 317 lattice (never
    /// crossing), plus a point in each cell away from its segment.
    fn jittered_segments(n_side: usize, rng: &mut Rng) -> (Vec<Point>, Vec<[Point; 2]>) {
        let mut segments = Vec::with_capacity(n_side * n_side);
        let mut points = Vec::new();
        for i in 0..n_side {
            for j in 0..n_side {
                let (x, y) = (i as f64, j as f64);
                let mut corner = || p(x + 0.05 + 0.9 * rng.unit(), y + 0.05 + 0.45 * rng.unit());
                segments.push([corner(), corner()]);
                if (i + j) % 10 == 0 {
                    points.push(p(x + 0.05 + 0.9 * rng.unit(), y + 0.55 + 0.4 * rng.unit()));
                }
            }
        }
        (points, segments)
    }

    #[test]
    fn scale_100k_segments() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let (points, segments) = jittered_segments(317, &mut rng);
        let start = std::time::Instant::now();
        let out = check_segments(&points, &segments).unwrap();
        let jittered = start.elapsed();
        assert_eq!(out.segments.len(), segments.len());

        // An open polyline through one corner per lattice cell, column by
        // column, up one column and down the next: consecutive cells are
        // neighbours, so it never crosses itself, and every inner vertex is
        // shared by two segments.
        let side = 317;
        let corner = |i: usize, j: usize| segments[i * side + j][0];
        let snake_order =
            (0..side).flat_map(|i| (0..side).map(move |j| (i, if i % 2 == 0 { j } else { side - 1 - j })));
        let vertices: Vec<Point> = snake_order.map(|(i, j)| corner(i, j)).collect();
        let snake: Vec<[Point; 2]> = vertices.windows(2).map(|w| [w[0], w[1]]).collect();
        let start = std::time::Instant::now();
        let out = check(&snake).unwrap();
        let polyline = start.elapsed();
        assert_eq!(out.segments.len(), snake.len());
        println!(
            "segment_input: {} jittered segments + {} points checked in {:?}; {}-edge polyline in {:?}",
            segments.len(),
            points.len(),
            jittered,
            snake.len(),
            polyline,
        );

        // The same segments with one crossing added at the end: found.
        let mut bad = segments.clone();
        let last = segments[segments.len() - 1];
        bad.push([p(last[0].x, last[1].y), p(last[1].x, last[0].y)]);
        if let Err(c) = check(&bad) {
            assert!(matches!(c, Conflict::SegmentsCross { second, .. } if second == segments.len()));
        } else {
            panic!("added crossing missed");
        }
    }
}
