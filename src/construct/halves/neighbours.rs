//! How far across a cut the Voronoi neighbours of the sites beside it
//! lie: the band the halves' first attempt takes along a lumpy boundary
//! (`Plan::along_a_lumpy_boundary`).
//!
//! A half's cell is final when its halo holds every site that is a
//! neighbour of it (shares an edge with it) in the whole diagram. On even
//! input those lie a few mean spacings away; between the parts of a sheet,
//! or across the bays of a coast, a site's neighbour lies across the gap,
//! many spacings off. A band of spacings fell short wherever the cut ran
//! beside such a gap: five of eleven cuts of the headline's sheet (shares
//! 0.40 to 0.60) took a second attempt, and two threads took longer than
//! one.
//!
//! The estimate: the sites in a strip along the cut marked on a grid of
//! cells; for every cell, the nearest marked one (an exact Euclidean
//! feature transform between cell centres: Felzenszwalb and Huttenlocher's
//! distance transform, a row pass and a column pass, keeping where each
//! minimum came from); and wherever two side-by-side cells have nearest
//! marks on either side of the cut, the distance of the far one from the
//! cut. Two such cells lie on either side of a Voronoi edge between sites
//! in those marked cells (up to the cells' size), so the largest distance
//! is how far across the cut a neighbour lies. It only sets a band: the
//! halves' checks still decide, and a band too narrow costs a second
//! attempt, never a wrong answer.

use crate::geometry::Point;

/// The most rows and columns of the grid: it costs a millisecond or two
/// at most, beside halves of tens of milliseconds.
const MOST_ROWS: usize = 2048;
const MOST_COLUMNS: usize = 512;

/// A squared distance (in cells) above any on the grid: an empty row or
/// column (finite, so that the transform's differences stay numbers).
const FAR: f64 = 1e18;

/// How far across the cut `x = cut` the neighbours of the sites on its
/// other side lie, among `points` and `segments` (pairs of indices into
/// `points`), for edges within `widest` of the cut inside the input's box
/// `lo..hi` (whose mean spacing is `spacing`), padded by the grid's cells.
/// Infinite where no site lies near the cut (it runs through an empty
/// stretch) or the numbers are not finite.
pub(super) fn reach_across(
    points: &[Point],
    segments: &[[usize; 2]],
    cut: f64,
    (lo, hi): (Point, Point),
    spacing: f64,
    widest: f64,
) -> f64 {
    // The strip holds the sites twice as far from the cut as the cells
    // asked of: a cell's nearest site may lie beyond its own column.
    let (x0, x1) = ((cut - 2.0 * widest).max(lo.x), (cut + 2.0 * widest).min(hi.x));
    let cell = spacing.max((hi.y - lo.y) / MOST_ROWS as f64).max((x1 - x0) / MOST_COLUMNS as f64);
    if !(cell > 0.0 && cell.is_finite() && x0 < x1 && lo.y.is_finite() && hi.y.is_finite() && widest.is_finite()) {
        return f64::INFINITY;
    }
    let columns = ((x1 - x0) / cell) as usize + 1;
    let rows = ((hi.y - lo.y) / cell) as usize + 1;
    let grid = Grid { x0, y0: lo.y, cell, columns, rows };
    let marks = grid.marked(points, segments);
    if !marks.iter().any(|&m| m) {
        return f64::INFINITY;
    }
    let nearest = grid.nearest_marks(&marks);
    // (a mark stands for sites anywhere in its cell: half a cell further)
    let beyond = |mark: usize| grid.x0 + ((mark % columns) as f64 + 0.5) * cell - cut;
    let pad = cell;
    let mut reach: f64 = 0.0;
    let asked = |column: usize| ((grid.x0 + (column as f64 + 0.5) * cell) - cut).abs() <= widest;
    for row in 0..rows {
        for column in (0..columns).filter(|&c| asked(c)) {
            let here = nearest[row * columns + column];
            // (the cell to the right, and the one above)
            let right = (column + 1 < columns).then(|| nearest[row * columns + column + 1]);
            let above = (row + 1 < rows).then(|| nearest[(row + 1) * columns + column]);
            for there in [right, above].into_iter().flatten() {
                let (a, b) = (beyond(here as usize), beyond(there as usize));
                if (a < 0.0) != (b < 0.0) {
                    reach = reach.max(a.abs().max(b.abs()) + pad);
                }
            }
        }
    }
    reach
}

/// A grid of square cells over the strip, from its lower-left corner.
struct Grid {
    x0: f64,
    y0: f64,
    cell: f64,
    columns: usize,
    rows: usize,
}

impl Grid {
    /// Per cell (row by row): whether a site (a point, or a point of a
    /// segment) lies in it.
    fn marked(&self, points: &[Point], segments: &[[usize; 2]]) -> Vec<bool> {
        let mut marks = vec![false; self.columns * self.rows];
        let x1 = self.x0 + self.columns as f64 * self.cell;
        let mut mark = |p: Point| {
            if p.x >= self.x0 && p.x < x1 && p.y.is_finite() {
                let column = (((p.x - self.x0) / self.cell) as usize).min(self.columns - 1);
                let row = (((p.y - self.y0) / self.cell) as usize).min(self.rows - 1);
                marks[row * self.columns + column] = true;
            }
        };
        points.iter().for_each(|&p| mark(p));
        for &[a, b] in segments {
            let (p, q) = (points[a], points[b]);
            if p.x.max(q.x) < self.x0 || p.x.min(q.x) >= x1 {
                continue;
            }
            // (the part within the strip, at steps of half a cell)
            let (mut t0, mut t1) = (0.0f64, 1.0f64);
            if p.x != q.x {
                let (ta, tb) = ((self.x0 - p.x) / (q.x - p.x), (x1 - p.x) / (q.x - p.x));
                t0 = t0.max(ta.min(tb));
                t1 = t1.min(ta.max(tb));
            }
            let length = (t1 - t0) * (q.x - p.x).hypot(q.y - p.y);
            let steps = (length / (0.5 * self.cell)).ceil().min((4 * (self.columns + self.rows)) as f64) as usize;
            for k in 0..=steps {
                let t = t0 + (t1 - t0) * (k as f64 / steps.max(1) as f64);
                mark(Point::new(p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)));
            }
        }
        marks
    }

    /// Per cell, the index of a marked cell whose centre is nearest its
    /// centre (some marked cell where there is none: the caller asks only
    /// where some cell is marked).
    fn nearest_marks(&self, marks: &[bool]) -> Vec<u32> {
        let (columns, rows) = (self.columns, self.rows);
        let mut envelope = Envelope::with_room(columns.max(rows));
        // Rows: per cell, the squared distance to the nearest mark in its
        // row, and that mark's column.
        let mut squared = vec![0.0; columns * rows];
        let mut column_of = vec![0u32; columns * rows];
        for row in 0..rows {
            let line = &marks[row * columns..(row + 1) * columns];
            envelope.solve(line.iter().map(|&m| if m { 0.0 } else { FAR }));
            for column in 0..columns {
                let (d, from) = envelope.at(column);
                squared[row * columns + column] = d;
                column_of[row * columns + column] = from as u32;
            }
        }
        // Columns: the nearest over the rows' answers.
        let mut nearest = vec![0u32; columns * rows];
        for column in 0..columns {
            envelope.solve((0..rows).map(|row| squared[row * columns + column]));
            for row in 0..rows {
                let (_, from) = envelope.at(row);
                nearest[row * columns + column] = (from * columns) as u32 + column_of[from * columns + column];
            }
        }
        nearest
    }
}

/// The lower envelope of the parabolas `(q - p)² + f(p)` over a line of
/// values `f` (one dimension of the transform), with its buffers.
struct Envelope {
    f: Vec<f64>,
    /// The roots of the envelope's parabolas, left to right, and where
    /// each starts to be lowest (`z[k]` to `z[k + 1]`).
    v: Vec<usize>,
    z: Vec<f64>,
    len: usize,
    /// The parabola lowest at the last point asked (asked in order).
    k: usize,
}

impl Envelope {
    fn with_room(n: usize) -> Envelope {
        Envelope { f: vec![0.0; n], v: vec![0; n], z: vec![0.0; n + 1], len: 0, k: 0 }
    }

    fn solve(&mut self, values: impl Iterator<Item = f64>) {
        let mut n = 0;
        for (slot, value) in self.f.iter_mut().zip(values) {
            *slot = value;
            n += 1;
        }
        let (f, v, z) = (&self.f[..n], &mut self.v, &mut self.z);
        let parabola = |q: usize| f[q] + (q * q) as f64;
        let mut k = 0;
        v[0] = 0;
        z[0] = f64::NEG_INFINITY;
        z[1] = f64::INFINITY;
        for q in 1..n {
            loop {
                let p = v[k];
                let s = (parabola(q) - parabola(p)) / (2.0 * (q - p) as f64);
                if s <= z[k] && k > 0 {
                    k -= 1;
                } else {
                    k += 1;
                    v[k] = q;
                    z[k] = s;
                    z[k + 1] = f64::INFINITY;
                    break;
                }
            }
        }
        (self.len, self.k) = (n, 0);
    }

    /// The envelope at `q` (asked in increasing order after `solve`): its
    /// value and the root of the parabola that gives it.
    fn at(&mut self, q: usize) -> (f64, usize) {
        debug_assert!(q < self.len);
        while self.z[self.k + 1] < q as f64 {
            self.k += 1;
        }
        let p = self.v[self.k];
        let d = q as f64 - p as f64;
        (d * d + self.f[p], p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// Each cell's nearest mark is at the least distance a brute force
    /// finds, on random marks (sparse, dense, one, a single row or column).
    #[test]
    fn the_nearest_marks_are_nearest() {
        let mut rng = SplitMix64(41);
        for (columns, rows, density) in [(7, 5, 0.1), (1, 9, 0.3), (12, 1, 0.2), (30, 40, 0.02), (16, 16, 0.6), (5, 5, 0.0)] {
            let grid = Grid { x0: 0.0, y0: 0.0, cell: 1.0, columns, rows };
            let mut marks: Vec<bool> = (0..columns * rows).map(|_| rng.unit() < density).collect();
            marks[(rng.unit() * (columns * rows) as f64) as usize] = true;
            let nearest = grid.nearest_marks(&marks);
            let at = |i: usize| ((i % columns) as f64, (i / columns) as f64);
            let squared = |i: usize, j: usize| (at(i).0 - at(j).0).powi(2) + (at(i).1 - at(j).1).powi(2);
            for i in 0..columns * rows {
                let brute = (0..columns * rows).filter(|&j| marks[j]).map(|j| squared(i, j)).fold(f64::INFINITY, f64::min);
                let found = nearest[i] as usize;
                assert!(marks[found], "{columns}x{rows} cell {i}: {found} is not marked");
                assert_eq!(squared(i, found), brute, "{columns}x{rows} cell {i}");
            }
        }
    }

    /// How far across `cut` the neighbours of the sites beside it lie in
    /// the diagram of `points` itself, for edges with a finite end within
    /// `widest` of the cut and inside the box `lo..hi`: what the estimate
    /// stands for (the edges out of the box are the hull's).
    fn true_reach(points: &[Point], cut: f64, widest: f64, (lo, hi): (Point, Point)) -> f64 {
        let inside = |p: Point| p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
        use crate::EdgeEnd;
        let mut b = crate::Builder::new();
        b.add_points(points.iter().map(|p| [p.x, p.y])).unwrap();
        let d = b.build().unwrap();
        let x_of = |s| match d.site(s) {
            Some(crate::geometry::Site::Point(p)) => p.x,
            _ => f64::NAN,
        };
        let near = |end: &EdgeEnd| match end {
            EdgeEnd::Vertex(v) => d.vertex(*v).is_some_and(|v| (v.position.x - cut).abs() <= widest && inside(v.position)),
            EdgeEnd::Infinite { .. } => false,
        };
        d.edges()
            .filter(|e| e.ends.iter().any(near))
            .map(|e| (x_of(e.sites[0]) - cut, x_of(e.sites[1]) - cut))
            .filter(|(a, b)| (*a < 0.0) != (*b < 0.0))
            .map(|(a, b)| a.abs().max(b.abs()))
            .fold(0.0, f64::max)
    }

    /// Points of a lattice with a rectangular hole across the cut, cut
    /// through the hole, beside it and far from it, and random points:
    /// the reach is at least the true one (the diagram's own edges) less
    /// a cell, and at most two cells more. With no point near the cut, it
    /// is infinite.
    #[test]
    fn the_reach_is_as_far_as_the_neighbours_across_the_cut() {
        let hole = |x: f64, y: f64| (40.0..65.0).contains(&x) && (30.0..45.0).contains(&y);
        let lattice: Vec<Point> =
            (0..100 * 80).map(|i| Point::new((i % 100) as f64, (i / 100) as f64)).filter(|p| !hole(p.x, p.y)).collect();
        let mut rng = SplitMix64(43);
        let random: Vec<Point> = (0..4000).map(|_| Point::new(99.0 * rng.unit(), 79.0 * rng.unit())).collect();
        let (lo, hi) = (Point::new(0.0, 0.0), Point::new(99.0, 79.0));
        for (points, cuts) in [(&lattice, [45.3, 50.5, 62.7, 10.5]), (&random, [20.1, 50.0, 70.3, 88.8])] {
            for cut in cuts {
                let reach = reach_across(points, &[], cut, (lo, hi), 1.0, 12.0);
                let truth = true_reach(points, cut, 12.0, (lo, hi));
                assert!(reach >= truth - 1.0 && reach <= truth + 2.0, "cut {cut}: reach {reach}, true {truth}");
            }
        }
        // segments mark the cells along them: horizontal segments a unit
        // apart have their neighbours a unit off
        let ends: Vec<Point> = (0..80).flat_map(|y| [Point::new(0.0, y as f64), Point::new(99.0, y as f64)]).collect();
        let rungs: Vec<[usize; 2]> = (0..80).map(|k| [2 * k, 2 * k + 1]).collect();
        let reach = reach_across(&ends, &rungs, 50.5, (lo, hi), 1.0, 12.0);
        assert!(reach <= 3.0, "between segments: {reach}");
        let far: Vec<Point> = lattice.iter().filter(|p| p.x < 20.0).copied().collect();
        assert_eq!(reach_across(&far, &[], 70.0, (lo, hi), 1.0, 5.0), f64::INFINITY);
    }
}
