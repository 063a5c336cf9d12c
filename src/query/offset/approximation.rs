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
    // a chord over angle a strays r (1 − cos(a/2)) from the arc
    let step = if tolerance >= radius { PI } else { 2.0 * (1.0 - tolerance / radius).acos() };
    // `as` turns a NaN (from non-finite input) into 0: one chord then
    ((turn / step.min(PI / 2.0)).ceil().clamp(1.0, MAX_ARC_POINTS as f64) as usize).max(1)
}

/// The angle swept from `from` to `to` around `centre` the given way
/// round, in `(0, 2π]` (equal ends: a whole circle).
pub(super) fn sweep(centre: Point, from: Point, to: Point, counter_clockwise: bool) -> f64 {
    let angle = |p: Point| (p.y - centre.y).atan2(p.x - centre.x);
    let mut turn = angle(to) - angle(from);
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
                let turn = sweep(centre, from, to, counter_clockwise);
                let segment = radius * radius / 2.0 * (turn - turn.sin());
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
