//! Exact contact tests between segments and points, so that a generator
//! never hands over two segments the library's exact input check would
//! call intersecting; and a grid that finds the candidates.

use num_bigint::BigInt;

use crate::{cmax, cmin, Point, Segment};

/// The sign of the turn `a -> b -> c`: 1 counter-clockwise, -1 clockwise,
/// 0 collinear. Exact: Shewchuk's adaptive predicate, or big integers where
/// a coordinate is so small that its products could underflow (its error
/// bounds assume they do not).
pub fn orient(a: Point, b: Point, c: Point) -> i32 {
    const SMALL: f64 = 1e-120; // about 2^-400: products of differences stay normal
    if [a, b, c].iter().flatten().any(|&v| v != 0.0 && v.abs() < SMALL) {
        return orient_big(a, b, c);
    }
    let coord = |p: Point| robust::Coord { x: p[0], y: p[1] };
    let det = robust::orient2d(coord(a), coord(b), coord(c));
    if det > 0.0 {
        1
    } else if det < 0.0 {
        -1
    } else {
        0
    }
}

/// `orient` in integers: every coordinate as a multiple of the least
/// power of two among them.
fn orient_big(a: Point, b: Point, c: Point) -> i32 {
    let parts = |v: f64| -> (i64, i32) {
        let bits = v.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i32;
        let fraction = (bits & ((1u64 << 52) - 1)) as i64;
        let (mantissa, power) = if exponent == 0 { (fraction, -1074) } else { (fraction | 1 << 52, exponent - 1075) };
        (if v < 0.0 { -mantissa } else { mantissa }, power)
    };
    let all = [a[0], a[1], b[0], b[1], c[0], c[1]].map(parts);
    let least = all.iter().filter(|(m, _)| *m != 0).map(|&(_, e)| e).min().unwrap_or(0);
    let [ax, ay, bx, by, cx, cy] =
        all.map(|(m, e)| if m == 0 { BigInt::from(0) } else { BigInt::from(m) << (e - least) as usize });
    let det = (&bx - &ax) * (&cy - &ay) - (&by - &ay) * (&cx - &ax);
    match det.sign() {
        num_bigint::Sign::Plus => 1,
        num_bigint::Sign::Minus => -1,
        num_bigint::Sign::NoSign => 0,
    }
}

pub fn same_point(p: Point, q: Point) -> bool {
    p[0] == q[0] && p[1] == q[1]
}

/// `c` lies on the closed segment `ab`, given that `a`, `b`, `c` are collinear.
fn on_collinear_segment(a: Point, b: Point, c: Point) -> bool {
    cmin(a[0], b[0]) <= c[0] && c[0] <= cmax(a[0], b[0]) && cmin(a[1], b[1]) <= c[1] && c[1] <= cmax(a[1], b[1])
}

/// The closed segments share at least one point.
pub fn closed_segments_meet(s: Segment, t: Segment) -> bool {
    let (o1, o2) = (orient(s[0], s[1], t[0]), orient(s[0], s[1], t[1]));
    let (o3, o4) = (orient(t[0], t[1], s[0]), orient(t[0], t[1], s[1]));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && on_collinear_segment(s[0], s[1], t[0]))
        || (o2 == 0 && on_collinear_segment(s[0], s[1], t[1]))
        || (o3 == 0 && on_collinear_segment(t[0], t[1], s[0]))
        || (o4 == 0 && on_collinear_segment(t[0], t[1], s[1]))
}

/// The two cannot be in one input: they meet, except where they share
/// exactly one endpoint and do not overlap.
pub fn segments_conflict(s: Segment, t: Segment) -> bool {
    let shared = same_point(s[0], t[0]) || same_point(s[0], t[1]) || same_point(s[1], t[0]) || same_point(s[1], t[1]);
    if !shared {
        return closed_segments_meet(s, t);
    }
    // Shared endpoint p: a conflict only if the other endpoint of one lies
    // on the other segment (collinear overlap, or a repeat).
    let sp = if same_point(s[0], t[0]) || same_point(s[0], t[1]) { s[0] } else { s[1] };
    let so = if same_point(sp, s[0]) { s[1] } else { s[0] };
    let to = if same_point(sp, t[0]) { t[1] } else { t[0] };
    if orient(sp, so, to) != 0 {
        return false;
    }
    on_collinear_segment(sp, so, to) || on_collinear_segment(sp, to, so)
}

/// `p` lies inside the open segment `s`.
pub fn in_open_segment(s: Segment, p: Point) -> bool {
    !same_point(p, s[0]) && !same_point(p, s[1]) && orient(s[0], s[1], p) == 0 && on_collinear_segment(s[0], s[1], p)
}

/// `s` may join `segs`: it has positive length and conflicts with none.
pub fn legal_addition(segs: &[Segment], s: Segment) -> bool {
    !same_point(s[0], s[1]) && segs.iter().all(|&t| !segments_conflict(s, t))
}

/// `p` may join as an isolated point: it lies inside no segment.
pub fn legal_point(segs: &[Segment], p: Point) -> bool {
    segs.iter().all(|&s| !in_open_segment(s, p))
}

/// Segments registered in every cell of their bounding box; a query walks
/// along the segment in steps of at most one cell and visits the 3x3 cells
/// around each step, which covers every cell the segment passes through.
pub struct SegmentGrid {
    lo: Point,
    side: usize,
    cells: Vec<Vec<usize>>,
    h: f64,
    seen: Vec<u64>,
    stamp: u64,
}

impl SegmentGrid {
    pub fn new(lo: Point, hi: Point, side: usize) -> SegmentGrid {
        let h = cmax(hi[0] - lo[0], hi[1] - lo[1]) / side as f64;
        SegmentGrid { lo, side, cells: vec![Vec::new(); side * side], h, seen: Vec::new(), stamp: 0 }
    }

    /// The grid side for `n` segments.
    pub fn side_for(n: usize) -> usize {
        ((n as f64).sqrt() as usize).clamp(4, 2048)
    }

    fn cell(&self, offset: f64) -> usize {
        // NaN and everything not above zero: the first cell
        if offset.is_nan() || offset <= 0.0 {
            return 0;
        }
        let c = (offset / self.h).floor();
        if c >= (self.side - 1) as f64 {
            self.side - 1
        } else {
            c as usize
        }
    }

    pub fn add(&mut self, s: Segment, id: usize) {
        let [a, b] = s;
        let (x0, x1) = (self.cell(cmin(a[0], b[0]) - self.lo[0]), self.cell(cmax(a[0], b[0]) - self.lo[0]));
        let (y0, y1) = (self.cell(cmin(a[1], b[1]) - self.lo[1]), self.cell(cmax(a[1], b[1]) - self.lo[1]));
        for x in x0..=x1 {
            for y in y0..=y1 {
                self.cells[x * self.side + y].push(id);
            }
        }
    }

    /// Calls `visit(id)` once for every registered segment near `s` (a
    /// superset of those meeting it) until `visit` returns true; returns
    /// whether it did.
    pub fn any_near(&mut self, s: Segment, mut visit: impl FnMut(usize) -> bool) -> bool {
        self.stamp += 1;
        let [a, b] = s;
        let length = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = 1 + (length / self.h) as usize;
        let (mut last_x, mut last_y) = (usize::MAX, usize::MAX);
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let cx = self.cell(a[0] + t * (b[0] - a[0]) - self.lo[0]);
            let cy = self.cell(a[1] + t * (b[1] - a[1]) - self.lo[1]);
            if cx == last_x && cy == last_y {
                continue;
            }
            (last_x, last_y) = (cx, cy);
            for x in cx.saturating_sub(1)..=(cx + 1).min(self.side - 1) {
                for y in cy.saturating_sub(1)..=(cy + 1).min(self.side - 1) {
                    for &id in &self.cells[x * self.side + y] {
                        if id >= self.seen.len() {
                            self.seen.resize(id + 1, 0);
                        }
                        if self.seen[id] == self.stamp {
                            continue;
                        }
                        self.seen[id] = self.stamp;
                        if visit(id) {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_is_exact_near_the_subnormal_range() {
        let least = f64::from_bits(1);
        assert_eq!(orient([0.0, 0.0], [1.0, 0.0], [2.0, least]), 1);
        assert_eq!(orient([least, 3.0], [0.0, 7.0], [2.0 * least, -1.0]), 0);
        assert_eq!(orient([least, 3.0], [0.0, 7.0], [3.0 * least, -1.0]), -1);
        assert_eq!(orient([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]), 0);
        assert_eq!(orient([0.0, 0.0], [1.0, 1.0], [2.0, 2.0 + 4.0 * f64::EPSILON]), 1);
    }

    #[test]
    fn contacts() {
        assert!(closed_segments_meet([[0.0, 0.0], [2.0, 2.0]], [[0.0, 2.0], [2.0, 0.0]]));
        assert!(!segments_conflict([[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [2.0, 1.0]]));
        assert!(segments_conflict([[0.0, 0.0], [2.0, 0.0]], [[0.0, 0.0], [1.0, 0.0]]));
        assert!(in_open_segment([[0.0, 0.0], [2.0, 0.0]], [1.0, 0.0]));
        assert!(!in_open_segment([[0.0, 0.0], [2.0, 0.0]], [2.0, 0.0]));
    }
}
