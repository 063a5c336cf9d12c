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

use super::classify::{point_conflict, segment_conflict};
use super::normalise::Normalised;
use super::Conflict;
use crate::geometry::Point;

/// A sparse uniform grid: cells are `(column, row)` packed in a `u64`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Grid {
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
    pub(super) single: bool,
}

/// No axis has more than this many cells, so a cell index fits in 32 bits
/// and a cell is wide enough for `margin` to exceed the rounding errors.
const MAX_CELLS_PER_AXIS: f64 = (1u32 << 24) as f64;

impl Grid {
    /// The grid for the kept segments (there is at least one).
    pub(super) fn for_segments(segments: &[(usize, [Point; 2])]) -> Grid {
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
        Grid { min, h, inv_h, margin: h / 1024.0, single }
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
    pub(super) fn cell_of(&self, p: Point) -> u64 {
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
    pub(super) fn cover(&self, a: Point, b: Point, out: &mut Vec<u64>) {
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
pub(super) fn find_conflict(norm: &Normalised) -> Option<Conflict> {
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
                if best_point.map_or(true, |best| pair < best) && point_conflict(norm, pair.0 as usize, s as usize).is_some() {
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
