//! The loops at one distance, traced through the cells of the diagram.
//!
//! The clearance is quasi-convex along every edge (`geometry::curves::edge_track`),
//! so an edge crosses the level `r` at most twice. Which edges cross it,
//! and how often, follows from the vertices' stored clearances and the
//! lowest clearance inside each edge, never from a recomputed position: an
//! edge whose ends lie on different sides of the band crosses once, an
//! edge with both ends beyond it and its lowest point within crosses
//! twice. Every cell walked counter-clockwise then meets its crossings
//! alternately rising out of the band and falling back into it, and the
//! offset inside the cell runs from each rising crossing to the next
//! falling one (counter-clockwise around a point site, parallel to a
//! segment site, with the band on its left). The falling crossing is the
//! rising crossing of the cell across the edge, where the loop goes on.

use super::index::{ConicEdge, OffsetIndex, Stop, NO_LEAF};
use crate::diagram::{Diagram, EdgeId, SiteId};
use crate::geometry::{Point, Site};
use crate::query::HalfEdge;

/// Within this fraction of the distance a crossing is taken to be at the
/// vertex it nears, or the two crossings of one edge at its lowest point:
/// the roots of a near-tangency are only that precise (a square root of
/// rounding), and offsets that touch there then touch exactly.
const SNAP: f64 = 1e-10;

/// A point of the level on an edge.
#[derive(Clone, Copy, Debug)]
pub(super) struct Crossing {
    pub(super) at: Point,
    /// The leaf of `OffsetIndex::above` on its side above the level: the
    /// end of its edge (or peak of a conic edge) the clearance rises to.
    pub(super) above: u32,
}

/// One view of a crossing from a cell: the half-edge it is on, and
/// whether the clearance rises out of the band there walking that
/// half-edge.
#[derive(Clone, Copy, Debug)]
struct View {
    cell: u32,
    rank: u32,
    order: u8,
    crossing: u32,
    rising: bool,
    half_edge: HalfEdge,
}

/// The offset inside one cell, from a rising crossing to the next falling
/// one.
#[derive(Clone, Copy, Debug)]
pub(super) struct Span {
    pub(super) site: SiteId,
    pub(super) from: u32,
    pub(super) to: u32,
    /// The half-edge of the rising crossing (its target lies beyond the
    /// band), and of the falling one.
    pub(super) rising_on: HalfEdge,
    pub(super) falling_on: HalfEdge,
    /// Whether the falling crossing comes before the rising one on the same
    /// half-edge (the span goes all the way round the cell).
    pub(super) wraps: bool,
}

/// The crossings and spans at one distance, and how the spans follow each
/// other.
pub(super) struct Traced {
    pub(super) crossings: Vec<Crossing>,
    pub(super) spans: Vec<Span>,
    /// Per span, the span after it (the one starting where it ends).
    pub(super) next: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl Diagram {
    /// Crossings and spans of the level `r` (input units) on `index`'s
    /// side.
    pub(super) fn trace(&self, index: &OffsetIndex, r: f64) -> Traced {
        let side = index.side;
        let threshold = side.threshold(r);
        let mut hits = Vec::new();
        index.edges.stab(threshold, |c| side.in_band(c, threshold), &mut hits);
        hits.sort_unstable();
        let mut crossings = Vec::new();
        let mut views = Vec::new();
        for &e in &hits {
            let e = EdgeId::from_index(e as usize);
            let placed = self.edge_crossings(e, index, r);
            let n = placed.len();
            let [h, t] = self.half_edges(e).expect("in range");
            let cells = [h, t].map(|h| self.half_edge_cell(h).expect("in range").index() as u32);
            for (k, (at, rising, above)) in placed.into_iter().enumerate() {
                let id = crossings.len() as u32;
                crossings.push(Crossing { at, above });
                views.push(View {
                    cell: cells[0],
                    rank: index.rank[h.index()],
                    order: k as u8,
                    crossing: id,
                    rising,
                    half_edge: h,
                });
                views.push(View {
                    cell: cells[1],
                    rank: index.rank[t.index()],
                    order: (n - 1 - k) as u8,
                    crossing: id,
                    rising: !rising,
                    half_edge: t,
                });
            }
        }
        views.sort_unstable_by_key(|v| (v.cell, v.rank, v.order));
        let mut spans = Vec::new();
        let mut start_of = vec![NONE; crossings.len()];
        for group in views.chunk_by(|a, b| a.cell == b.cell) {
            for (i, up) in group.iter().enumerate().filter(|(_, v)| v.rising) {
                let down = group[(i + 1) % group.len()];
                if down.rising {
                    // not alternating: an inconsistency the pairing skips.
                    // Without arcs a bug; with arcs (floating-point
                    // decisions) it leaves a loop open, which the offsets'
                    // check refuses (`check_pieces_beside_arcs`)
                    debug_assert!(self.arc_sites > 0, "crossings of cell {} do not alternate", up.cell);
                    continue;
                }
                start_of[up.crossing as usize] = spans.len() as u32;
                spans.push(Span {
                    site: SiteId::from_index(up.cell as usize),
                    from: up.crossing,
                    to: down.crossing,
                    rising_on: up.half_edge,
                    falling_on: down.half_edge,
                    wraps: down.rank == up.rank && down.order < up.order,
                });
            }
        }
        let next = spans.iter().map(|s| start_of[s.to as usize]).collect();
        Traced { crossings, spans, next }
    }

    /// Where edge `e` crosses the level `r`, in the order of its
    /// `ends[0] → ends[1]`, each with whether the clearance rises there and
    /// its leaf of `above`.
    fn edge_crossings(&self, e: EdgeId, index: &OffsetIndex, r: f64) -> Vec<(Point, bool, u32)> {
        if let Some(conic) = index.conics.get(&(e.index() as u32)) {
            return self.conic_crossings(e, conic, index, r);
        }
        let infinity = self.finite_vertices as u32;
        let leaves = self.end_vertices(e).map(|v| v.map_or(infinity, |v| v.index() as u32));
        let radial = self.radial_separator(e);
        let with_leaf = |(at, rising): (Point, bool)| {
            // on an arc's separator, the point of the radial line at `r`
            // from the endpoint: the vertices an arc's vertex solver places
            // are only as precise as its tolerance, and the crossing of the
            // endpoint's other separator (a tangent segment's, exact) must
            // meet this one where the cell between them is thinner than
            // rounding
            let at = radial.map_or(at, |(end, u)| {
                let side = if (at.x - end.x) * u.x + (at.y - end.y) * u.y >= 0.0 { r } else { -r };
                Point::new(end.x + side * u.x, end.y + side * u.y)
            });
            (at, rising, leaves[usize::from(rising)])
        };
        self.straight_or_parabolic_crossings(e, index, r).into_iter().map(with_leaf).collect()
    }

    /// For the separator between an arc and one of its endpoints (on the
    /// radial line through that endpoint): the endpoint and the outward
    /// unit direction from the arc's centre, in input coordinates.
    fn radial_separator(&self, e: EdgeId) -> Option<(Point, Point)> {
        let edge = self.edge(e)?;
        let [a, b] = edge.sites.map(|s| self.sites.at(s.index()));
        let (arc, end) = match (a, b) {
            (Site::Arc(arc), Site::Point(p)) | (Site::Point(p), Site::Arc(arc)) => (arc, p),
            _ => return None,
        };
        if end != arc.start() && end != arc.end() {
            return None;
        }
        let c = arc.centre();
        let length = c.distance(end);
        (length > 0.0)
            .then(|| Point::new((end.x - c.x) / length, (end.y - c.y) / length))
            .filter(|u| u.is_finite())
            .map(|u| (end, u))
    }

    /// Where an edge beside an arc crosses the level `r`: at most once
    /// between each two of its stops (the clearance is monotone there), by
    /// bisection along its track.
    fn conic_crossings(&self, e: EdgeId, conic: &ConicEdge, index: &OffsetIndex, r: f64) -> Vec<(Point, bool, u32)> {
        let side = index.side;
        let threshold = side.threshold(r);
        let stops = self.stops(e, &index.levels, side, &index.conics);
        let level = r * self.scale.to_internal;
        let snap = SNAP * r;
        let ends = self.end_vertices(e).map(|v| v.map(|v| self.store.position[v.index()]));
        let mut out = Vec::new();
        // a turning point at the level to within the band's tolerance: the
        // region touches itself there (two sites 2r apart), or a part of it
        // shrinks to that point; both crossings beside it are that point,
        // so that the loops meet there and split, or the part's loop is
        // one point and dropped (the roots of a tangency are only the
        // square root of rounding apart, not equal)
        let touching =
            |stop: &Stop| (stop.level - r).abs() <= 2.0 * super::index::LEVEL_TOLERANCE * r && stop.t > 0.0 && stop.t < 1.0;
        for (k, pair) in stops.windows(2).enumerate() {
            let (a, b) = (pair[0], pair[1]);
            let (in_a, in_b) = (side.in_band(a.level, threshold), side.in_band(b.level, threshold));
            if in_a == in_b {
                continue;
            }
            let lowest = [a, b].into_iter().find(touching);
            // (which end is in the band is the stops' word, not the
            // clearance recomputed along the track: an end at the level
            // to rounding must not send the root to the other end)
            let t = lowest.map_or_else(|| conic.track.root(a.t, b.t, level, in_a), |stop| stop.t);
            let Some(at) = conic.track.point(t) else { continue };
            // (a turning point at the level is where it is; a root is
            // polished onto both offset curves)
            let at = if lowest.is_none() { conic.track.onto_level(at, level) } else { at };
            let at = self.scale.point_to_input(at);
            // next to a vertex (rounding: the vertex is at the level), the
            // vertex itself, so that the loops of both its cells agree
            let near = |v: Option<Point>| v.filter(|v| v.distance(at) <= snap);
            let at = near(ends[0]).or(near(ends[1])).unwrap_or(at);
            let rising = in_a;
            out.push((at, rising, upper_leaf(&stops, if rising { k + 1 } else { k }, rising)));
        }
        out
    }

    /// Where a straight or parabolic edge crosses the level `r` (see
    /// `edge_crossings`).
    fn straight_or_parabolic_crossings(&self, e: EdgeId, index: &OffsetIndex, r: f64) -> Vec<(Point, bool)> {
        let side = index.side;
        let [c0, c1] = self.end_levels(e, &index.levels, side);
        let threshold = side.threshold(r);
        let (b0, b1) = (side.in_band(c0, threshold), side.in_band(c1, threshold));
        let track = self.edge_track(e);
        let kinds: &[bool] = match (b0, b1) {
            (true, false) => &[true],
            (false, true) => &[false],
            (false, false) => {
                let dips =
                    track.and_then(|t| t.interior_minimum()).is_some_and(|m| side.in_band(m * self.scale.to_input, threshold));
                if dips {
                    &[false, true]
                } else {
                    &[]
                }
            }
            (true, true) => &[],
        };
        let ends = self.end_vertices(e);
        let vertex_at = |k: usize| ends[k].map(|v| self.store.position[v.index()]);
        let Some(track) = track else {
            // no curve to follow (not expected): the crossing at a finite end
            let at = vertex_at(0).or(vertex_at(1)).unwrap_or_default();
            return kinds.iter().map(|&rising| (at, rising)).collect();
        };
        let level = r * self.scale.to_internal;
        let roots = track.roots(level);
        let lowest = track.clamp(track.lowest());
        let snap = SNAP * level;
        if let (2, Some((lo, hi))) = (kinds.len(), roots) {
            if hi - lo <= 2.0 * snap {
                let at = self.scale.point_to_input(track.point(lowest));
                return vec![(at, false), (at, true)];
            }
        }
        kinds
            .iter()
            .map(|&rising| {
                let root = roots.map(|(lo, hi)| if rising { hi } else { lo });
                let t = track.clamp(root.unwrap_or(lowest));
                // A root beyond the edge (by rounding: the vertex is at the
                // level) is that end vertex exactly; so is a root whose
                // point lies next to one. Otherwise the point at the level.
                let end = if root.is_some_and(|t| t <= track.from) {
                    vertex_at(0)
                } else if root.is_some_and(|t| t >= track.to) {
                    vertex_at(1)
                } else {
                    None
                };
                let at = self.scale.point_to_input(track.point_at_distance(t, level));
                let near = |v: Option<Point>| v.filter(|v| v.distance(at) <= snap * self.scale.to_input);
                let at = end.or(near(vertex_at(0))).or(near(vertex_at(1))).unwrap_or(at);
                (at, rising)
            })
            .collect()
    }

    /// Whether the point site `p` is an endpoint of a segment: its cell
    /// has a separator.
    pub(super) fn is_segment_endpoint(&self, p: SiteId) -> bool {
        self.cell_half_edges(p).any(|h| self.is_separator(h.edge()) == Some(true))
    }

    /// Whether the circle round the point site `site` (at `centre`)
    /// through `at` lies in the site's cell, sampled a quarter, a half and
    /// three quarters of a turn from `at`: no neighbouring site nearer to
    /// those. A whole circle touches its cell's boundary at one point and
    /// holds the rest; a cell thinner than rounding that reaches
    /// out past the circle (a point a rounding off a tangent joint,
    /// LibreCAD's LA-2: its cell a sliver along the joint's normal) has
    /// its two crossings a rounding apart, possibly the wrong way round,
    /// and holds none of it.
    pub(super) fn holds_the_circle(&self, site: SiteId, centre: Point, at: Point) -> bool {
        let (dx, dy) = (at.x - centre.x, at.y - centre.y);
        let r = dx.hypot(dy);
        // the point opposite and the two a quarter turn either side (one
        // alone may tie: opposite a point on an arc, along its radius)
        let samples = [
            Point::new(centre.x - dx, centre.y - dy),
            Point::new(centre.x - dy, centre.y + dx),
            Point::new(centre.x + dy, centre.y - dx),
        ];
        let neighbours: Vec<Site> = self
            .cell_half_edges(site)
            .filter_map(|h| self.edge(h.edge()))
            .flat_map(|e| e.sites)
            .filter(|&s| s != site)
            .filter_map(|s| self.sites.get(s.index()))
            .collect();
        samples.iter().all(|&q| neighbours.iter().all(|other| other.distance(q) >= r * (1.0 - 1e-9)))
    }

    /// Whether the cell boundary between the span's two crossings goes
    /// anywhere farther than `tolerance` from `at` (or to infinity): so that
    /// crossings at one point mean a whole circle, not nothing.
    pub(super) fn span_leaves(&self, span: &Span, at: Point, tolerance: f64) -> bool {
        if span.rising_on == span.falling_on {
            return span.wraps;
        }
        let mut h = span.rising_on;
        for _ in 0..self.edges.len() {
            match self.target_vertex(h) {
                None => return true,
                Some(v) if self.store.position[v.index()].distance(at) > tolerance => return true,
                Some(_) => {}
            }
            match self.next_half_edge(h) {
                Some(next) if next != span.falling_on => h = next,
                _ => return false,
            }
        }
        true
    }
}

/// The leaf of the stop `k` or, if it has none (a lowest point, which only
/// rounding makes the upper end of a monotone piece), of the first stop
/// beyond it that has one, going on the way the clearance rose.
fn upper_leaf(stops: &[Stop], mut k: usize, forward: bool) -> u32 {
    loop {
        if stops[k].leaf != NO_LEAF {
            return stops[k].leaf;
        }
        if forward && k + 1 < stops.len() {
            k += 1;
        } else if !forward && k > 0 {
            k -= 1;
        } else {
            // (the ends always have leaves)
            return stops[k].leaf;
        }
    }
}
