//! The outermost points of a set seen from each side of its bounding box,
//! by buckets: per column of the box the highest and the lowest, per row
//! the rightmost and the leftmost.
//!
//! Both halves of the parallel build hold the points near the input's
//! boundary: the circles of the cells along the hull are huge and dip
//! into the input. Along a straight boundary a rim of even depth holds
//! them; along a lumpy one (a sheet of parts, stars, a coast) the bumps
//! stand out of any rim that is not as deep as the dips between them, and
//! such a rim holds a large share of the input. The points near the
//! skyline instead (within a depth of the outermost point of their own
//! column or row) follow the bumps down into the dips.

use crate::geometry::Point;

/// Per bucket of a side, the outermost value seen (`-inf`: none).
#[derive(Clone)]
pub(crate) struct Skyline {
    lo: Point,
    bucket: f64,
    /// Per column: the highest y and the lowest y negated.
    columns: Vec<[f64; 2]>,
    /// Per row: the rightmost x and the leftmost x negated.
    rows: Vec<[f64; 2]>,
}

/// The most buckets along a side.
const MOST_BUCKETS: usize = 1 << 16;

impl Skyline {
    /// The skyline of no point, over the box from `lo` to `hi` in buckets
    /// of `bucket` (fewer where that would make more than 65,536 a side).
    pub(crate) fn empty(lo: Point, hi: Point, bucket: f64) -> Skyline {
        let count = |extent: f64| {
            let n = extent / bucket;
            if n.is_finite() && n >= 0.0 {
                (n.min(MOST_BUCKETS as f64) as usize).saturating_add(1).min(MOST_BUCKETS)
            } else {
                1
            }
        };
        let (columns, rows) = (count(hi.x - lo.x), count(hi.y - lo.y));
        // (the bucket widened where the count was capped)
        let bucket = bucket.max((hi.x - lo.x) / MOST_BUCKETS as f64).max((hi.y - lo.y) / MOST_BUCKETS as f64);
        Skyline { lo, bucket, columns: vec![[f64::NEG_INFINITY; 2]; columns], rows: vec![[f64::NEG_INFINITY; 2]; rows] }
    }

    #[inline]
    fn buckets(&self, p: Point) -> (usize, usize) {
        // (a value that is not finite, or outside the box, goes to an end)
        let at = |v: f64, n: usize| {
            let k = v / self.bucket;
            if k >= 0.0 {
                (k as usize).min(n - 1)
            } else {
                0
            }
        };
        (at(p.x - self.lo.x, self.columns.len()), at(p.y - self.lo.y, self.rows.len()))
    }

    /// Adds the points `points`.
    pub(crate) fn add(&mut self, points: &[Point]) {
        for &p in points {
            let (c, r) = self.buckets(p);
            let column = &mut self.columns[c];
            column[0] = if p.y > column[0] { p.y } else { column[0] };
            column[1] = if -p.y > column[1] { -p.y } else { column[1] };
            let row = &mut self.rows[r];
            row[0] = if p.x > row[0] { p.x } else { row[0] };
            row[1] = if -p.x > row[1] { -p.x } else { row[1] };
        }
    }

    /// The skyline of both sets (made over the same box and buckets).
    pub(crate) fn merge(mut self, other: &Skyline) -> Skyline {
        let join = |a: &mut [f64; 2], b: &[f64; 2]| {
            a[0] = a[0].max(b[0]);
            a[1] = a[1].max(b[1]);
        };
        self.columns.iter_mut().zip(&other.columns).for_each(|(a, b)| join(a, b));
        self.rows.iter_mut().zip(&other.rows).for_each(|(a, b)| join(a, b));
        self
    }

    /// Whether `p` lies within `depth` of the outermost point of its
    /// column or row, on any of the four sides.
    #[inline]
    pub(crate) fn near(&self, p: Point, depth: f64) -> bool {
        let (c, r) = self.buckets(p);
        let ([top, bottom], [right, left]) = (self.columns[c], self.rows[r]);
        (p.y >= top - depth) | (-p.y >= bottom - depth) | (p.x >= right - depth) | (-p.x >= left - depth)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// Every point within the depth of the outermost of its own column or
    /// row is near, as a plain search finds, and the merged skyline of two
    /// parts is the whole one's.
    #[test]
    fn near_points_are_those_within_the_depth_of_their_bucket() {
        let mut rng = SplitMix64(5);
        let points: Vec<Point> = (0..5000).map(|_| Point::new(10.0 * rng.unit(), 3.0 * rng.unit())).collect();
        let (lo, hi) = (Point::new(0.0, 0.0), Point::new(10.0, 3.0));
        let bucket = 0.25;
        let mut whole = Skyline::empty(lo, hi, bucket);
        whole.add(&points);
        let (mut a, mut b) = (Skyline::empty(lo, hi, bucket), Skyline::empty(lo, hi, bucket));
        a.add(&points[..1234]);
        b.add(&points[1234..]);
        let merged = a.merge(&b);
        let depth = 0.05;
        let index = |v: f64| ((v / bucket) as usize).min(39);
        for &p in &points {
            let column: Vec<&Point> = points.iter().filter(|q| index(q.x) == index(p.x)).collect();
            let row: Vec<&Point> =
                points.iter().filter(|q| ((q.y / bucket) as usize).min(12) == ((p.y / bucket) as usize).min(12)).collect();
            let plain = column.iter().all(|q| q.y <= p.y + depth)
                || column.iter().all(|q| q.y >= p.y - depth)
                || row.iter().all(|q| q.x <= p.x + depth)
                || row.iter().all(|q| q.x >= p.x - depth);
            assert_eq!(whole.near(p, depth), plain, "{p:?}");
            assert_eq!(merged.near(p, depth), plain, "{p:?}");
        }
    }

    /// Points outside the box, or not finite, fall in an end bucket
    /// without a panic; a box too wide for its buckets gets wider ones.
    #[test]
    fn odd_points_and_boxes_go_to_an_end() {
        let mut s = Skyline::empty(Point::new(0.0, 0.0), Point::new(1.0, 1.0), 0.1);
        s.add(&[Point::new(f64::NAN, 5.0), Point::new(-3.0, f64::INFINITY), Point::new(7.0, -7.0)]);
        assert!(s.near(Point::new(7.0, -7.0), 0.0));
        let wide = Skyline::empty(Point::new(-f64::MAX, 0.0), Point::new(f64::MAX, 1.0), 1e-300);
        assert_eq!(wide.columns.len(), 1);
        let fine = Skyline::empty(Point::new(0.0, 0.0), Point::new(1e9, 1.0), 1.0);
        assert_eq!(fine.columns.len(), MOST_BUCKETS);
        // (more buckets than a usize counts)
        let mut tiny = Skyline::empty(Point::new(0.0, 0.0), Point::new(1.0, 1.0), 1e-300);
        tiny.add(&[Point::new(1.0, 0.5), Point::new(0.25, 1.0)]);
        assert_eq!((tiny.columns.len(), tiny.rows.len()), (MOST_BUCKETS, MOST_BUCKETS));
        assert!(tiny.near(Point::new(1.0, 0.5), 0.0) && tiny.near(Point::new(0.25, 1.0), 0.0));
    }
}
