//! The coordinate type shared by the whole crate.

use super::arithmetic::real::norm;

/// A point of the plane, in `f64` coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Point {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
}

impl Point {
    /// A point from its coordinates.
    #[inline]
    pub const fn new(x: f64, y: f64) -> Self {
        Point { x, y }
    }

    /// The same point with `-0.0` replaced by `+0.0`, so that equal points
    /// compare equal bit for bit.
    #[inline]
    pub(crate) fn canonical_zero(self) -> Self {
        Point::new(self.x + 0.0, self.y + 0.0)
    }

    /// Both coordinates' bits: for points with canonical zeros, equal
    /// points have equal keys (for hashing and sorting by identity).
    #[inline]
    pub(crate) fn bit_key(self) -> [u64; 2] {
        [self.x.to_bits(), self.y.to_bits()]
    }

    /// The [`Point::bit_key`]s of a segment's ends, the same in both
    /// directions.
    #[inline]
    pub(crate) fn segment_key(a: Point, b: Point) -> [u64; 4] {
        let (ka, kb) = (a.bit_key(), b.bit_key());
        let (lo, hi) = if ka <= kb { (ka, kb) } else { (kb, ka) };
        [lo[0], lo[1], hi[0], hi[1]]
    }

    /// Squared Euclidean distance.
    #[inline]
    pub fn distance_squared(self, other: Point) -> f64 {
        let dx = self.x - other.x;
        let dy = self.y - other.y;
        dx * dx + dy * dy
    }

    /// Euclidean distance, without overflow or underflow in between (a
    /// distance of 1e-200 stays 1e-200, where squaring would give 0).
    #[inline]
    pub fn distance(self, other: Point) -> f64 {
        norm(self.x - other.x, self.y - other.y)
    }

    /// `true` when both coordinates are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }

    #[inline]
    pub(crate) fn scaled(self, factor: f64) -> Self {
        Point::new(self.x * factor, self.y * factor)
    }
}

/// The bounding box of `points`, lowest and highest corner (no point:
/// `∞` to `-∞`; NaN coordinates are passed over).
pub(crate) fn bounding_box(points: impl IntoIterator<Item = Point>) -> (Point, Point) {
    let empty = (Point::new(f64::INFINITY, f64::INFINITY), Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
    points
        .into_iter()
        .fold(empty, |(lo, hi), p| (Point::new(lo.x.min(p.x), lo.y.min(p.y)), Point::new(hi.x.max(p.x), hi.y.max(p.y))))
}

impl From<[f64; 2]> for Point {
    fn from(p: [f64; 2]) -> Self {
        Point::new(p[0], p[1])
    }
}

impl From<(f64, f64)> for Point {
    fn from(p: (f64, f64)) -> Self {
        Point::new(p.0, p.1)
    }
}

impl From<Point> for [f64; 2] {
    fn from(p: Point) -> Self {
        [p.x, p.y]
    }
}
