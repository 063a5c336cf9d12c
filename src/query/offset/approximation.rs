//! Offsets as polylines within a tolerance, and their areas from the exact
//! pieces.
//!
//! A polyline keeps every line piece and replaces each arc by chords no
//! farther than the tolerance from it, each spanning at most a quarter
//! turn. The chords of an arc then lie in the arc's own sector around its
//! site, and that sector lies in the site's cell (a cell holds the segment
//! from its site to each of its points). The arcs of different loops in
//! one cell are disjoint pieces of the same circle, so their sectors are
//! disjoint: the polylines are simple, pairwise disjoint and nested as the
//! exact loops are, wherever the exact loops are (up to the rounding of
//! the sample points).

use std::f64::consts::{PI, TAU};

use super::{Offset, OffsetLoop, OffsetPiece};
use crate::geometry::Point;

/// Most points one arc is cut into (the tolerance is then not met).
const MAX_ARC_POINTS: usize = 1_000_000;

/// How many chords an arc turning `turn` of radius `radius` is cut into:
/// each strays at most `tolerance` from it and spans at most a quarter
/// turn, and there are at most [`MAX_ARC_POINTS`].
fn arc_chords(turn: f64, radius: f64, tolerance: f64) -> usize {
    // a chord over angle a strays r (1 − cos(a/2)) = 2r sin²(a/4) from the
    // arc; the sine form, because where the tolerance is tiny beside the
    // radius (a nearly straight arc) 1 − t/r rounds to 1 and its
    // arccosine to 0
    let step = if tolerance >= radius { PI } else { 4.0 * (0.5 * tolerance / radius).sqrt().asin() };
    // `as` turns a NaN (from non-finite input) into 0: one chord then
    ((turn / step.min(PI / 2.0)).ceil().clamp(1.0, MAX_ARC_POINTS as f64) as usize).max(1)
}

/// The area between an arc of `radius` turning `turn` and its chord,
/// `r²/2 (θ − sin θ)`. For a small turn it is taken from the arc's length
/// `L = rθ` as `L²θ/12 (1 − θ²/20 + θ⁴/840)` (the series, to 1e-17 below
/// θ = 0.01): a nearly straight arc's radius can be past the square root
/// of the largest double while the area is not, and `θ − sin θ` cancels.
fn circular_segment_area(radius: f64, turn: f64) -> f64 {
    if turn < 0.01 {
        let (length, squared) = (radius * turn, turn * turn);
        length * length * turn / 12.0 * (1.0 - squared / 20.0 + squared * squared / 840.0)
    } else {
        0.5 * radius * (radius * (turn - turn.sin()))
    }
}

/// The angle swept from `from` to `to` around `centre` the given way
/// round, in `(0, 2π]` (equal ends: a whole circle).
///
/// The angle is that between the two radii as unit vectors (the `atan2`
/// of their cross and dot products), not the difference of their angles:
/// an offset beside a nearly straight arc (radius 1e199 over a chord of
/// 1e103) turns by 1e-96, which the difference of two angles near π/2
/// rounds to zero, a whole circle.
pub(super) fn sweep(centre: Point, from: Point, to: Point, counter_clockwise: bool) -> f64 {
    let unit = |p: Point| {
        let (dx, dy) = (p.x - centre.x, p.y - centre.y);
        let length = dx.hypot(dy);
        (dx / length, dy / length)
    };
    let ((ux, uy), (vx, vy)) = (unit(from), unit(to));
    let mut turn = (ux * vy - uy * vx).atan2(ux * vx + uy * vy);
    if !counter_clockwise {
        turn = -turn;
    }
    let turn = turn.rem_euclid(TAU);
    if turn == 0.0 || from == to {
        TAU
    } else {
        turn
    }
}

impl OffsetPiece {
    /// The angle an arc turns from its start to its end the way it runs, in
    /// `(0, 2π]` (`2π` for a whole circle, whose ends are equal); `None`
    /// for a line.
    ///
    /// ```
    /// use segvoronoi::{Builder, OffsetPiece};
    /// let mut b = Builder::new();
    /// b.add_point([0.0, 0.0])?;
    /// let circle = b.build()?.offset(1.0)?;
    /// assert_eq!(circle.loops[0].pieces[0].sweep(), Some(std::f64::consts::TAU));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn sweep(&self) -> Option<f64> {
        match *self {
            OffsetPiece::Arc { centre, from, to, counter_clockwise, .. } => Some(sweep(centre, from, to, counter_clockwise)),
            _ => None,
        }
    }

    /// The points of the piece within `tolerance` of it, from its start up
    /// to but not including its end (the next piece's start). `None` when
    /// `tolerance` is not positive.
    pub fn polyline(&self, tolerance: f64) -> Option<Vec<Point>> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        let mut out = Vec::new();
        self.for_each_point(tolerance, &mut |p| out.push(p));
        Some(out)
    }

    /// How many points `polyline(tolerance)` has, found without making
    /// them (the C API counts before it writes, and allocates nothing).
    fn point_count(&self, tolerance: f64) -> usize {
        match *self {
            OffsetPiece::Line { .. } => 1,
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                arc_chords(sweep(centre, from, to, counter_clockwise), radius, tolerance)
            }
        }
    }

    /// Calls `emit` with each point of `polyline(tolerance)`, in order.
    fn for_each_point(&self, tolerance: f64, emit: &mut impl FnMut(Point)) {
        match *self {
            OffsetPiece::Line { from, .. } => emit(from),
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                let turn = sweep(centre, from, to, counter_clockwise);
                let pieces = arc_chords(turn, radius, tolerance);
                let start = (from.y - centre.y).atan2(from.x - centre.x);
                let sign = if counter_clockwise { 1.0 } else { -1.0 };
                emit(from);
                for k in 1..pieces {
                    let a = start + sign * turn * (k as f64 / pieces as f64);
                    emit(Point::new(centre.x + radius * a.cos(), centre.y + radius * a.sin()));
                }
            }
        }
    }

    /// The signed area this piece adds to its loop's, measured from
    /// `origin`: the triangle from `origin` over its chord, and for an arc
    /// the circular segment between chord and arc.
    fn area_from(&self, origin: Point) -> f64 {
        let (a, b) = (self.from(), self.to());
        let triangle = ((a.x - origin.x) * (b.y - origin.y) - (b.x - origin.x) * (a.y - origin.y)) / 2.0;
        match *self {
            OffsetPiece::Line { .. } => triangle,
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                let segment = circular_segment_area(radius, sweep(centre, from, to, counter_clockwise));
                triangle + if counter_clockwise { segment } else { -segment }
            }
        }
    }
}

impl OffsetLoop {
    /// The loop's points within `tolerance` of it (see the module doc), its
    /// first point not repeated at the end. `None` when `tolerance` is not
    /// positive.
    pub fn polyline(&self, tolerance: f64) -> Option<Vec<Point>> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        let mut out = Vec::with_capacity(self.pieces.len());
        self.for_each_polyline_point(tolerance, |p| out.push(p));
        Some(out)
    }

    /// How many points `polyline(tolerance)` has (saturating at
    /// `usize::MAX`), without making them; `None` when `tolerance` is not
    /// positive.
    pub fn polyline_len(&self, tolerance: f64) -> Option<usize> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        Some(self.pieces.iter().fold(0usize, |n, piece| n.saturating_add(piece.point_count(tolerance))))
    }

    /// Calls `emit` with each point of `polyline(tolerance)`, in order,
    /// allocating nothing; `None` (and no call) when `tolerance` is not
    /// positive.
    pub fn for_each_polyline_point(&self, tolerance: f64, mut emit: impl FnMut(Point)) -> Option<()> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        for piece in &self.pieces {
            piece.for_each_point(tolerance, &mut emit);
        }
        Some(())
    }

    /// The signed area it encloses, from its exact pieces: positive for a
    /// counter-clockwise loop, negative for a hole.
    pub fn signed_area(&self) -> f64 {
        let Some(first) = self.pieces.first() else { return 0.0 };
        let origin = first.from();
        self.pieces.iter().map(|p| p.area_from(origin)).sum()
    }
}

impl Offset {
    /// The area of the region the loops bound, from the exact pieces (the
    /// sum of their signed areas).
    pub fn area(&self) -> f64 {
        self.loops.iter().map(OffsetLoop::signed_area).sum()
    }

    /// Every loop as a polyline (see [`OffsetLoop::polyline`]), in the
    /// order of [`Offset::loops`].
    pub fn polylines(&self, tolerance: f64) -> Option<Vec<Vec<Point>>> {
        self.loops.iter().map(|l| l.polyline(tolerance)).collect()
    }

    /// The region as polygons: per outer loop, its index and then the
    /// indices of the holes directly inside it (as WKT's `MULTIPOLYGON`
    /// and GEOS want them; an island inside a hole is a polygon of its
    /// own).
    pub fn polygons(&self) -> Vec<Vec<usize>> {
        let mut polygon_of = vec![usize::MAX; self.loops.len()];
        let mut polygons: Vec<Vec<usize>> = Vec::new();
        for (k, l) in self.loops.iter().enumerate() {
            if !l.hole {
                polygon_of[k] = polygons.len();
                polygons.push(vec![k]);
            } else if let Some(p) = l.parent.filter(|&p| polygon_of[p] != usize::MAX) {
                polygons[polygon_of[p]].push(k);
            }
        }
        polygons
    }
}

#[cfg(test)]
mod tests {
    use super::{arc_chords, circular_segment_area, sweep};
    use crate::Point;

    /// A piece of a circle 1e199 across over a chord of 2e103 (an offset
    /// beside a nearly straight arc) turns by 2e-96: not a whole circle,
    /// as the difference of its ends' angles said; its segment's area is
    /// finite (the radius squared is not); its polyline has the chords its
    /// tolerance needs, not the million the arccosine of 1 asked for.
    #[test]
    fn a_nearly_straight_piece_turns_a_hair() {
        let centre = Point::new(0.0, -1e199);
        let (from, to) = (Point::new(-1e103, 0.0), Point::new(1e103, 0.0));
        let turn = sweep(centre, from, to, false);
        assert!((turn - 2e-96).abs() <= 1e-108, "{turn:e}");
        assert!((sweep(centre, to, from, true) - turn).abs() <= 1e-108);
        // the other way round is all but a whole turn
        assert!((sweep(centre, from, to, true) - std::f64::consts::TAU).abs() <= 1e-12);
        let area = circular_segment_area(1e199, turn);
        let want = (1e199 * turn).powi(2) * turn / 12.0;
        assert!(area.is_finite() && (area - want).abs() <= 1e-12 * want, "{area:e} against {want:e}");
        // (5e6 from its chord: each chord within the tolerance, and no more
        // of them than that needs)
        let n = arc_chords(turn, 1e199, 1e-3);
        let stray = |n: usize| 2e199 * (turn / n as f64 / 4.0).sin().powi(2);
        assert!(stray(n) <= 1e-3 * (1.0 + 1e-9) && stray(n - 1) > 1e-3, "{n}");
        // and the small-turn form agrees with the plain one where both hold
        for turn in [0.009, 0.0099999, 0.01, 0.011] {
            let plain = 0.5 * 3.0 * (3.0 * (turn - f64::sin(turn)));
            assert!((circular_segment_area(3.0, turn) - plain).abs() <= 1e-9 * plain, "{turn}");
        }
        // a tolerance 1e-18 of the radius: as many chords as that needs
        let n = arc_chords(1e-3, 1e12, 1e-6);
        let stray = |n: usize| 2e12 * (1e-3 / n as f64 / 4.0).sin().powi(2);
        assert!(stray(n) <= 1e-6 * (1.0 + 1e-9) && stray(n - 1) > 1e-6, "{n}");
    }
}
