//! A sparse uniform grid over a set of segments: which cells a segment
//! touches (conservatively), for finding the hot pixels a piece meets when
//! the splitting of crossings routes it (`split/route.rs`).
//!
//! The cell side is the mean segment length (`total length / number of
//! segments`), which keeps the number of (segment, cell) incidences at most a
//! small constant times the number of segments for *any* input; it is raised
//! where needed so that no axis has more than 2^24 cells.

use crate::geometry::Point;

/// A sparse uniform grid: cells are `(column, row)` packed in a `u64`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid {
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
    pub(crate) single: bool,
}

/// No axis has more than this many cells, so a cell index fits in 32 bits
/// and a cell is wide enough for `margin` to exceed the rounding errors.
const MAX_CELLS_PER_AXIS: f64 = (1u32 << 24) as f64;

impl Grid {
    /// The grid for the kept segments (there is at least one).
    pub(crate) fn for_segments(segments: &[(usize, [Point; 2])]) -> Grid {
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
    pub(crate) fn cell_of(&self, p: Point) -> u64 {
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
    pub(crate) fn cover(&self, a: Point, b: Point, out: &mut Vec<u64>) {
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

/// Each segment's cells, sorted, in one flat array.
pub(crate) struct SegmentCells {
    cells: Vec<u64>,
    /// Segment `i` owns `cells[start[i]..start[i + 1]]`.
    start: Vec<usize>,
}

impl SegmentCells {
    pub(crate) fn new(grid: &Grid, segments: &[(usize, [Point; 2])]) -> SegmentCells {
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

    pub(crate) fn of(&self, i: u32) -> &[u64] {
        &self.cells[self.start[i as usize]..self.start[i as usize + 1]]
    }
}

/// The smallest box holding every segment.
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

    #[test]
    fn a_tiny_extent_uses_one_cell() {
        let t = 1e-300;
        let segments = [[p(0., 0.), p(t, 0.)], [p(t, 0.), p(t, t)], [p(0., t), p(0.5 * t, 2. * t)]];
        let grid = Grid::for_segments(&segments.map(|q| (0, q)));
        assert!(grid.single);
        let mut cells = Vec::new();
        grid.cover(segments[2][0], segments[2][1], &mut cells);
        assert_eq!((cells, grid.cell_of(p(t, t))), (vec![0], 0));
    }

    proptest! {
        /// Points computed along a segment land in cells it registered.
        #[test]
        fn cover_is_conservative(
            segments in prop::collection::vec(((-1e3..1e3f64, -1e3..1e3f64), (-1e3..1e3f64, -1e3..1e3f64)), 1..30),
        ) {
            let kept: Vec<(usize, [Point; 2])> = segments
                .iter()
                .map(|&((ax, ay), (bx, by))| [p(ax, ay), p(bx, by)])
                .filter(|[a, b]| a != b)
                .enumerate()
                .collect();
            prop_assume!(!kept.is_empty());
            let grid = Grid::for_segments(&kept);
            let cells = SegmentCells::new(&grid, &kept);
            for (k, (_, [a, b])) in kept.iter().enumerate() {
                for step in 0..=64 {
                    let t = step as f64 / 64.0;
                    let q = p(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
                    prop_assert!(cells.of(k as u32).contains(&grid.cell_of(q)), "{:?} {:?} t={}", a, b, t);
                }
            }
        }
    }
}
