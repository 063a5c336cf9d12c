//! The geometry of an edge: a straight piece or a parabolic arc, as a
//! polyline within a tolerance or as the one quadratic Bézier curve that is
//! the arc.
//!
//! Which shape an edge has follows from its two sites alone:
//! - two points, two segments (a piece of an angle bisector or of the
//!   mid-parallel), or a segment and one of its own endpoints (a separator,
//!   on the perpendicular at that endpoint): a straight piece;
//! - a point and a segment that does not end at it: an arc of the parabola
//!   with the point as focus and the segment's supporting line as directrix.
//!   A point exactly on that line (decided by an exact orientation test)
//!   would make the parabola degenerate into the perpendicular through it;
//!   such an edge is reported as straight.
//!
//! A parabolic edge lies inside the segment's strip (between the
//! perpendiculars at its endpoints), so it is always finite in exact
//! geometry; the drawing methods still refuse rays and lines rather than
//! guess.
//!
//! Precision: not exact. The arc is computed in the diagram's internal,
//! power-of-two scaled coordinates (so inputs near the ends of the `f64`
//! range neither overflow nor underflow) from the parameters of the end
//! vertices along the directrix; every returned point is a few ulps of the
//! input's magnitude off the true parabola, except that the first and last
//! points are the vertex positions themselves, so that drawings join up.

use crate::diagram::{Diagram, EdgeId, SiteId};
use crate::geometry::curves::bisector::bisector_point_of_edge;
use crate::geometry::curves::edge_curve::EdgeCurve;
use crate::geometry::curves::parabola::{focus_and_directrix, Parabola};
use crate::geometry::predicates::Orientation;
use crate::geometry::{Point, Site};
use crate::query::EdgeEnd;

/// Most points [`Diagram::edge_polyline`] returns for one edge.
const MAX_POLYLINE_POINTS: usize = 1_000_000;

/// The shape of a Voronoi edge (see [`Diagram::edge_shape`]). More shapes
/// may come with more site kinds, so a `match` outside this crate needs a
/// wildcard arm.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum EdgeShape {
    /// A straight piece: between two points, between two segments, or
    /// between a segment and one of its endpoints.
    Line,
    /// An arc of the parabola of points equidistant from `focus` and the
    /// line through `directrix[0]` and `directrix[1]`: the edge between a
    /// point site (the focus) and a segment site (whose endpoints are the
    /// directrix points) that does not end at that point.
    Parabola {
        /// The point site, in input coordinates.
        focus: Point,
        /// The segment site's endpoints, in input coordinates; the directrix
        /// is their supporting line.
        directrix: [Point; 2],
    },
    /// A piece of the conic of points equidistant from two sites of which
    /// one (at least) is a circular arc: a line, parabola, ellipse or
    /// hyperbola branch. [`Diagram::edge_polyline`] samples it within a
    /// tolerance; [`Diagram::edge_rational_bezier`] gives the piece as a
    /// rational quadratic Bézier.
    Conic {
        /// The two sites, in input coordinates (the edge's left one first).
        sites: [Site; 2],
    },
}

impl EdgeShape {
    /// The shape of the edge between two sites (see the module doc), with
    /// `turn` the diagram's exact orientation of input points.
    fn between(first: Site, second: Site, turn: impl Fn(Point, Point, Point) -> Orientation) -> EdgeShape {
        if let Some(arc) = [first, second].into_iter().find_map(|s| if let Site::Arc(arc) = s { Some(arc) } else { None }) {
            // an arc and one of its own endpoints: the radial separator
            let own_end = [first, second].iter().any(|s| s.as_point().is_some_and(|p| p == arc.start() || p == arc.end()));
            return if own_end { EdgeShape::Line } else { EdgeShape::Conic { sites: [first, second] } };
        }
        let Some((focus, a, b)) = focus_and_directrix(&first, &second) else { return EdgeShape::Line };
        if turn(a, b, focus) == Orientation::Collinear {
            return EdgeShape::Line;
        }
        EdgeShape::Parabola { focus, directrix: [a, b] }
    }
}

impl Diagram {
    /// The shape of an edge, or `None` if the id is out of range.
    ///
    /// ```
    /// use segvoronoi::{Builder, EdgeShape, Point};
    /// let mut b = Builder::new();
    /// b.add_segment([[0.0, 0.0], [4.0, 0.0]])?;
    /// b.add_point([2.0, 2.0])?;
    /// let d = b.build()?;
    /// let arcs: Vec<EdgeShape> = d
    ///     .edges()
    ///     .filter_map(|e| d.edge_shape(e.id))
    ///     .filter(|s| matches!(s, EdgeShape::Parabola { .. }))
    ///     .collect();
    /// // The point (2, 2) and the segment share one parabolic edge.
    /// assert_eq!(
    ///     arcs,
    ///     [EdgeShape::Parabola {
    ///         focus: Point::new(2.0, 2.0),
    ///         directrix: [Point::new(0.0, 0.0), Point::new(4.0, 0.0)],
    ///     }]
    /// );
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn edge_shape(&self, id: EdgeId) -> Option<EdgeShape> {
        Some(self.shape_of(&self.edge(id)?))
    }

    /// The shape of an edge already looked up.
    pub(crate) fn shape_of(&self, e: &crate::query::Edge) -> EdgeShape {
        self.shape_between(e.sites)
    }

    /// The shape of the edge between two sites (in either order).
    pub(crate) fn shape_between(&self, sites: [SiteId; 2]) -> EdgeShape {
        // two points or two segments (told apart by id): straight, without
        // a look at either; an arc (the last ids) makes a conic
        let first_arc = self.sites.len() - self.arc_sites;
        let any_arc = sites.iter().any(|s| s.index() >= first_arc && s.index() < self.sites.len());
        if !any_arc && (sites[0].index() < self.point_sites) == (sites[1].index() < self.point_sites) {
            return EdgeShape::Line;
        }
        let [first, second] = sites.map(|s| self.sites.at(s.index()));
        EdgeShape::between(first, second, |a, b, c| self.turn(a, b, c))
    }

    /// A polyline along a finite edge, from the position of `ends[0]` to
    /// that of `ends[1]` (both included, exactly), whose every point of
    /// every piece is within `tolerance` (input units) of the true edge.
    ///
    /// A straight edge gives exactly its two end points; a parabolic arc as
    /// few points as its curvature allows for `tolerance`, but never more
    /// than 1,000,000 (the tolerance is then not met).
    ///
    /// `None` when the id is out of range, when `tolerance` is not positive
    /// (or NaN), and for rays and lines: an edge reaching infinity has no
    /// finite polyline (its unit direction is in [`EdgeEnd::Infinite`]).
    /// See the module doc for the precision.
    ///
    /// ```
    /// use segvoronoi::{Builder, EdgeShape};
    /// let mut b = Builder::new();
    /// b.add_segment([[0.0, 0.0], [4.0, 0.0]])?;
    /// b.add_point([2.0, 2.0])?;
    /// let d = b.build()?;
    /// for e in d.edges().filter(|e| !e.is_infinite()) {
    ///     let poly = d.edge_polyline(e.id, 1e-3).unwrap();
    ///     match d.edge_shape(e.id).unwrap() {
    ///         EdgeShape::Line => assert_eq!(poly.len(), 2),
    ///         EdgeShape::Parabola { .. } => {
    ///             assert!(poly.len() > 2);
    ///             // Every point is as far from the point as from the segment.
    ///             let [p, s] = e.sites.map(|s| d.site(s).unwrap());
    ///             assert!(poly.iter().all(|&q| (p.distance(q) - s.distance(q)).abs() < 1e-9));
    ///         }
    ///         other => unreachable!("no other shape between points and segments: {other:?}"),
    ///     }
    /// }
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn edge_polyline(&self, id: EdgeId, tolerance: f64) -> Option<Vec<Point>> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        let mut points = Vec::new();
        self.for_each_edge_polyline_point(id, tolerance, |p| points.push(p))?;
        Some(points)
    }

    /// Calls `emit` with each point of `edge_polyline(id, tolerance)`, in
    /// order, allocating nothing (the C API counts and writes into the
    /// caller's buffer this way); `None`, and no call, where
    /// `edge_polyline` gives `None`.
    pub fn for_each_edge_polyline_point(&self, id: EdgeId, tolerance: f64, emit: impl FnMut(Point)) -> Option<()> {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return None;
        }
        let edge = self.edge(id)?;
        let ends = self.finite_end_vertices(&edge)?;
        self.for_each_polyline_point(self.shape_of(&edge), ends, tolerance, emit);
        Some(())
    }

    /// Calls `emit` with each point of the polyline of `edge_polyline` for
    /// an edge of shape `shape` between the finite vertices `ends` (its
    /// `ends[0]` and `ends[1]`), for a positive `tolerance`, in order,
    /// allocating nothing: at least two points, the first and the last the
    /// vertices' positions exactly. (The parabola of a `Parabola` shape is
    /// the one of its edge's sites: the same focus and directrix points.)
    pub(crate) fn for_each_polyline_point(
        &self,
        shape: EdgeShape,
        ends: [usize; 2],
        tolerance: f64,
        mut emit: impl FnMut(Point),
    ) {
        let (start, end) = (self.store.position[ends[0]], self.store.position[ends[1]]);
        if let EdgeShape::Conic { sites } = shape {
            // in the build's power-of-two scaled coordinates, where
            // differences of distances do not underflow (input at 1e-300);
            // each point passed on when the next comes, so that the first
            // and the last are the vertices themselves
            let (f, scale) = (self.scale.to_internal, self.scale);
            let witnesses = self.end_witnesses(&sites, ends).map(|w| w.map(|w| w.scaled(f)));
            let mut held: Option<Point> = None;
            let sites = sites.map(|s| s.scaled(f));
            conic_polyline(&sites, &witnesses, start.scaled(f), end.scaled(f), tolerance * f, &mut |p: Point| {
                held = Some(match held {
                    None => start,
                    Some(previous) => {
                        emit(previous);
                        scale.point_to_input(p)
                    }
                });
            });
            emit(end);
            return;
        }
        let Some((parabola, s0, s1)) = self.arc_of_shape(shape, start, end) else {
            emit(start);
            emit(end);
            return;
        };
        // A tolerance beyond the scaled range becomes infinite: two points.
        let scale = self.scale;
        // Each point is passed on when the next one comes, so that the last
        // can be replaced by `end` (`sample_into` gives at least two).
        let mut held: Option<Point> = None;
        parabola.sample_into(s0, s1, tolerance * self.scale.to_internal, MAX_POLYLINE_POINTS, |p| {
            let p = match held {
                None => start,
                Some(previous) => {
                    emit(previous);
                    scale.point_to_input(p)
                }
            };
            held = Some(p);
        });
        emit(end);
    }
    /// The quadratic Bézier curve `[start, control, end]` that is a finite
    /// parabolic edge: `start` and `end` are the positions of `ends[0]` and
    /// `ends[1]`, and `control` is where the parabola's tangents at them
    /// meet, so `(1-u)² start + 2u(1-u) control + u² end` runs along the arc
    /// (SVG's `M start Q control end`).
    ///
    /// `None` when the id is out of range, for a straight edge (see
    /// [`Diagram::edge_shape`]), and for rays and lines. See the module doc
    /// for the precision.
    ///
    /// ```
    /// use segvoronoi::{Builder, EdgeEnd};
    /// let mut b = Builder::new();
    /// b.add_segment([[0.0, 0.0], [4.0, 0.0]])?;
    /// b.add_point([2.0, 2.0])?;
    /// let d = b.build()?;
    /// let (e, [start, control, end]) =
    ///     d.edges().find_map(|e| Some((e, d.edge_bezier(e.id)?))).expect("one parabolic arc");
    /// let EdgeEnd::Vertex(v) = e.ends[0] else { unreachable!() };
    /// assert_eq!(start, d.vertex(v).unwrap().position);
    /// // The arc of (2, 2) over the x axis is y = ((x - 2)² + 4) / 4, from
    /// // x = 0 to x = 4: its end tangents meet right below the apex.
    /// assert!((control.x - 2.0).abs() < 1e-12 && control.y.abs() < 1e-12);
    /// assert!((start.y - 2.0).abs() < 1e-12 && (end.y - 2.0).abs() < 1e-12);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn edge_bezier(&self, id: EdgeId) -> Option<[Point; 3]> {
        let edge = self.edge(id)?;
        let (start, end) = self.finite_ends(&edge)?;
        let (parabola, s0, s1) = self.arc(&edge, start, end)?;
        let [_, control, _] = parabola.bezier(s0, s1);
        let control = self.scale.point_to_input(control);
        control.is_finite().then_some([start, control, end])
    }

    /// The rational quadratic Bézier curve `([start, control, end], w)`
    /// that is a finite curved edge: `start` and `end` are the positions of
    /// `ends[0]` and `ends[1]`, `control` is where the edge's tangents at
    /// them meet, and `w` the weight of `control` (the ends' weights are
    /// 1), so that
    /// `((1-u)² start + 2u(1-u) w control + u² end) / ((1-u)² + 2u(1-u) w + u²)`
    /// runs along the edge: a parabola has `w = 1`, an ellipse `w < 1`, a
    /// hyperbola `w > 1`. Conics are exactly rational quadratics, so this is
    /// the edge itself, to the rounding of its four numbers; the weight of
    /// a conic edge is fitted through the edge's point halfway between its
    /// ends.
    ///
    /// `None` when the id is out of range, for a straight edge, for rays
    /// and lines, and for an edge whose tangents at its ends do not meet
    /// ahead of both (a piece that turns by half a turn or more: cut it
    /// with [`Diagram::edge_polyline`] instead).
    pub fn edge_rational_bezier(&self, id: EdgeId) -> Option<([Point; 3], f64)> {
        let edge = self.edge(id)?;
        let (start, end) = self.finite_ends(&edge)?;
        match self.shape_of(&edge) {
            EdgeShape::Conic { sites } => {
                let f = self.scale.to_internal;
                let witnesses = self.end_witnesses(&sites, self.finite_end_vertices(&edge)?).map(|w| w.map(|w| w.scaled(f)));
                let ([_, p1, _], w) = conic_bezier(&sites.map(|s| s.scaled(f)), &witnesses, start.scaled(f), end.scaled(f))?;
                let control = self.scale.point_to_input(p1);
                control.is_finite().then_some(([start, control, end], w))
            }
            EdgeShape::Parabola { .. } => self.edge_bezier(id).map(|b| (b, 1.0)),
            _ => None,
        }
    }

    /// The positions of both ends of a finite edge.
    fn finite_ends(&self, e: &crate::query::Edge) -> Option<(Point, Point)> {
        let [u, v] = self.finite_end_vertices(e)?;
        Some((self.store.position[u], self.store.position[v]))
    }

    /// The vertices (indices) at both ends of a finite edge.
    fn finite_end_vertices(&self, e: &crate::query::Edge) -> Option<[usize; 2]> {
        match e.ends {
            [EdgeEnd::Vertex(u), EdgeEnd::Vertex(v)] => Some([u.index(), v.index()]),
            _ => None,
        }
    }

    /// The third site (input coordinates) of each of the vertices `ends`
    /// of an edge between `sites`: the edge's points are no nearer it than
    /// their own (`bisector_point_of_edge`).
    pub(crate) fn end_witnesses(&self, sites: &[Site; 2], ends: [usize; 2]) -> [Option<Site>; 2] {
        ends.map(|v| {
            self.store
                .sites_of(crate::diagram::VertexId(v as u32))
                .iter()
                .filter(|s| s.index() < self.sites.len())
                .map(|s| self.sites.at(s.index()))
                .find(|w| !sites.contains(w))
        })
    }

    /// For a parabolic edge from `start` to `end`: its parabola in internal
    /// coordinates and the parameters of the two ends. `None` for straight
    /// edges, and when the parabola cannot be set up in floating point (the
    /// focus so close to the directrix that their distance rounds to zero;
    /// the arc is then a straight piece to within rounding).
    fn arc(&self, edge: &crate::query::Edge, start: Point, end: Point) -> Option<(Parabola, f64, f64)> {
        self.arc_of_shape(self.shape_of(edge), start, end)
    }

    /// As `arc`, for an edge of shape `shape`: its focus and directrix are
    /// those of the edge's sites, so the parabola is the one `curve_of`
    /// sets up.
    fn arc_of_shape(&self, shape: EdgeShape, start: Point, end: Point) -> Option<(Parabola, f64, f64)> {
        let EdgeShape::Parabola { focus, directrix: [a, b] } = shape else { return None };
        let f = self.scale.to_internal;
        let parabola = Parabola::new(focus.scaled(f), a.scaled(f), b.scaled(f))?;
        let (from, to) = (parabola.parameter(start.scaled(f)), parabola.parameter(end.scaled(f)));
        (from.is_finite() && to.is_finite()).then_some((parabola, from, to))
    }

    /// The curve of the finite edge `id` in its own direction, from its
    /// `ends[0]` to its `ends[1]` (a conic's points depend on it), in
    /// internal coordinates (the diagram's power-of-two scale); `None` if
    /// the id is out of range or the edge reaches infinity.
    pub(crate) fn edge_curve(&self, id: EdgeId) -> Option<EdgeCurve> {
        let edge = self.edge(id)?;
        let ends = self.finite_end_vertices(&edge)?;
        let f = self.scale.to_internal;
        let sites = edge.sites.map(|s| self.sites.at(s.index()));
        let witnesses = self.end_witnesses(&sites, ends).map(|w| w.map(|w| w.scaled(f)));
        let [first, second] = sites.map(|s| s.scaled(f));
        let [start, end] = ends.map(|v| self.store.position[v].scaled(f));
        Some(EdgeCurve::between(&first, &second, start, end).with_witnesses(witnesses))
    }
}

/// The polyline of a conic edge between `sites` (on its left, on its
/// right) from `start` to `end`, its end vertices' third sites
/// `witnesses`: each chord halved, its middle put on the edge
/// (`bisector_point_of_edge`), until the edge's middle lies within
/// `tolerance` of the chord, at most `MAX_POLYLINE_POINTS` points.
fn conic_polyline(
    sites: &[Site; 2],
    witnesses: &[Option<Site>; 2],
    start: Point,
    end: Point,
    tolerance: f64,
    emit: &mut impl FnMut(Point),
) {
    let [left, right] = sites;
    let mut points = 2usize;
    emit(start);
    // a stack of chords still to draw, the nearest last
    let mut stack = vec![(start, end, 0u32)];
    while let Some((p, q, depth)) = stack.pop() {
        let m = bisector_point_of_edge(left, right, p, q, 0.5, witnesses);
        let chord_middle = Point::new(0.5 * (p.x + q.x), 0.5 * (p.y + q.y));
        let off = m.distance(chord_middle);
        if depth < 40 && points < MAX_POLYLINE_POINTS && off > tolerance && m.is_finite() {
            points += 1;
            stack.push((m, q, depth + 1));
            stack.push((p, m, depth + 1));
        } else {
            emit(q);
        }
    }
}

/// The rational quadratic Bézier of a conic edge (see
/// `Diagram::edge_rational_bezier`).
fn conic_bezier(sites: &[Site; 2], witnesses: &[Option<Site>; 2], start: Point, end: Point) -> Option<([Point; 3], f64)> {
    let [left, right] = sites;
    // the edge's tangent at `x`: across the difference of the two sites'
    // unit directions toward `x`
    let tangent = |x: Point| {
        let unit = |s: &Site| {
            let q = s.nearest_point(x);
            let (dx, dy) = (x.x - q.x, x.y - q.y);
            let n = dx.hypot(dy);
            (dx / n, dy / n)
        };
        let ((ax, ay), (bx, by)) = (unit(left), unit(right));
        Point::new(-(ay - by), ax - bx)
    };
    let (t0, t2) = (tangent(start), tangent(end));
    // where start + s t0 = end + u t2
    let cross = t0.x * t2.y - t0.y * t2.x;
    if !(cross.abs() > 1e-12 * t0.x.hypot(t0.y) * t2.x.hypot(t2.y)) {
        return None;
    }
    let (dx, dy) = (end.x - start.x, end.y - start.y);
    let s = (dx * t2.y - dy * t2.x) / cross;
    let control = Point::new(start.x + s * t0.x, start.y + s * t0.y);
    // ahead of `start` along the edge and behind `end`: the control point
    // is on the chord's side where the edge's middle is
    let middle = bisector_point_of_edge(left, right, start, end, 0.5, witnesses);
    let side = |p: Point| (end.x - start.x) * (p.y - start.y) - (end.y - start.y) * (p.x - start.x);
    if !(side(middle) * side(control) > 0.0) || !control.is_finite() {
        return None;
    }
    // the weight from the middle's barycentric coordinates in the control
    // triangle: w² = τ1² / (4 τ0 τ2)
    let area = |a: Point, b: Point, c: Point| (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    let whole = area(start, control, end);
    let (tau0, tau1, tau2) =
        (area(middle, control, end) / whole, area(start, middle, end) / whole, area(start, control, middle) / whole);
    let w = tau1 / (2.0 * (tau0 * tau2).sqrt());
    (w.is_finite() && w > 0.0).then_some(([start, control, end], w))
}
