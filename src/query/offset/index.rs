//! What the offsets of one side (growing or shrinking) share across
//! distances, built once: the edges they may cross with the range of the
//! clearance along each (an interval tree, so one distance looks only at
//! the edges it crosses), each half-edge's place around its cell, the
//! cells an offset may circle without crossing any edge, and the two merge
//! trees that give the nesting.

use std::collections::HashMap;

use super::conic::{ConicEnd, ConicTrack};
use super::interval_tree::IntervalTree;
use super::level_tree::LevelTree;
use crate::diagram::{Diagram, EdgeId, SiteId};
use crate::geometry::curves::edge_track::{EdgeTrack, TrackEnd};
use crate::geometry::Site;
use crate::query::{EdgeEnd, EdgeShape, HalfEdge, Location};

/// Which way the offset goes: away from the sites (a positive distance)
/// or, with a domain, into it (a negative one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Side {
    Grow,
    Shrink,
}

impl Side {
    /// The clearance below which (growing), or at or below which
    /// (shrinking), a point counts as within the band of width `r` along
    /// the sites. The band is open when growing and closed when shrinking,
    /// so that the region the loops bound is always open: where two parts
    /// of it touch at one point, the loops stay apart (see
    /// `Diagram::offset`). Clearances within `LEVEL_TOLERANCE × r` of `r`
    /// count as equal to it: a part of the region thinner than that is
    /// what rounding alone makes or unmakes (the clearances of a corridor
    /// between parallel segments, exactly `r`, are stored a few ulps either
    /// side), so it is left out, the same way for every edge.
    #[inline]
    pub(super) fn threshold(self, r: f64) -> f64 {
        match self {
            Side::Grow => r * (1.0 - LEVEL_TOLERANCE),
            Side::Shrink => r * (1.0 + LEVEL_TOLERANCE),
        }
    }

    /// Whether a clearance `c` is within the band whose `threshold` is
    /// `t`.
    #[inline]
    pub(super) fn in_band(self, c: f64, t: f64) -> bool {
        match self {
            Side::Grow => c < t,
            Side::Shrink => c <= t,
        }
    }
}

/// See [`Side::threshold`].
pub(super) const LEVEL_TOLERANCE: f64 = 1e-10;

/// An edge beside an arc: its track, and per knot its leaf of
/// `OffsetIndex::above` (a peak's own leaf, `NO_LEAF` for a lowest
/// point).
pub(super) struct ConicEdge {
    pub(super) track: ConicTrack,
    pub(super) leaves: Vec<u32>,
}

/// No leaf of `above` (a lowest point of a conic edge).
pub(super) const NO_LEAF: u32 = u32::MAX;

/// One stop along an edge for the offsets, from its first end to its
/// second: the parameter of a conic track, the
/// clearance (input units) as the offsets take it, and its leaf of
/// `above` (`NO_LEAF` for none).
#[derive(Clone, Copy, Debug)]
pub(super) struct Stop {
    pub(super) t: f64,
    pub(super) level: f64,
    pub(super) leaf: u32,
}

/// The shared part of the offsets on one side (see the module doc).
pub(super) struct OffsetIndex {
    pub(super) side: Side,
    /// The edges that can carry the offset, by their clearance range.
    pub(super) edges: IntervalTree,
    /// Per half-edge, its place counter-clockwise around its cell.
    pub(super) rank: Vec<u32>,
    /// Point sites whose cell can hold a whole circle: the lowest
    /// clearance on the cell's boundary, the site, and a leaf of `above`
    /// on that boundary; by that clearance.
    pub(super) circles: Vec<(f64, SiteId, u32)>,
    /// Per finite vertex, then infinity, the clearance the offsets take
    /// there (`Diagram::vertex_level`), computed once.
    pub(super) levels: Vec<f64>,
    /// The components of what lies above a level: leaves are the finite
    /// vertices, then infinity, then the peaks of conic edges (a region
    /// above a level may hold such a peak and no vertex).
    pub(super) above: LevelTree,
    /// The edges beside arcs, by edge index: their tracks and the leaves of
    /// their knots.
    pub(super) conics: HashMap<u32, ConicEdge>,
    /// The components of what lies below: leaves are the sites, then the
    /// outside of the domain's outer rings.
    pub(super) below: LevelTree,
}

impl OffsetIndex {
    pub(super) fn new(diagram: &Diagram, side: Side) -> OffsetIndex {
        let edge_count = diagram.edges.len();
        let infinity = diagram.finite_vertices as u32;
        let outside = diagram.sites.len() as u32;
        let mut levels: Vec<f64> =
            (0..diagram.finite_vertices).map(|v| diagram.vertex_level(crate::diagram::VertexId::from_index(v), side)).collect();
        levels.push(f64::INFINITY);
        let mut low = vec![f64::INFINITY; edge_count];
        let mut intervals = Vec::new();
        let mut above_links = Vec::new();
        let mut below_links = Vec::new();
        let mut conics = HashMap::new();
        for e in (0..edge_count).map(EdgeId::from_index) {
            if !diagram.offset_may_cross(e, side) {
                continue;
            }
            if let Some(track) = diagram.conic_track(e) {
                let to_input = diagram.scale.to_input;
                let leaves = track
                    .knots
                    .iter()
                    .map(|k| {
                        if k.peak {
                            levels.push(k.value * to_input);
                            (levels.len() - 1) as u32
                        } else {
                            NO_LEAF
                        }
                    })
                    .collect();
                conics.insert(e.index() as u32, ConicEdge { track, leaves });
            }
            let stops = diagram.stops(e, &levels, side, &conics);
            let lo = stops.iter().map(|s| s.level).fold(f64::INFINITY, f64::min);
            let hi = stops.iter().map(|s| s.level).fold(f64::NEG_INFINITY, f64::max);
            low[e.index()] = lo;
            intervals.push((lo, hi, e.index() as u32));
            // the stops with leaves, each linked to the next at the lowest
            // clearance between them
            let mut held: Option<(u32, f64)> = None;
            for stop in &stops {
                held = match held {
                    None => Some((stop.leaf, stop.level)),
                    Some((leaf, lowest)) => {
                        let lowest = lowest.min(stop.level);
                        if stop.leaf == NO_LEAF {
                            Some((leaf, lowest))
                        } else {
                            above_links.push((leaf, stop.leaf, lowest));
                            Some((stop.leaf, stop.level))
                        }
                    }
                };
            }
            let [h, t] = diagram.half_edges(e).expect("in range");
            let cells = [h, t].map(|h| diagram.half_edge_cell(h).expect("in range").index() as u32);
            below_links.push((cells[0], cells[1], lo));
        }
        below_links.extend(ring_links(diagram, side, outside));

        let mut rank = vec![0u32; 2 * edge_count];
        let mut circles = Vec::new();
        for s in (0..diagram.sites.len()).map(SiteId::from_index) {
            let mut lowest = f64::INFINITY;
            let mut first: Option<HalfEdge> = None;
            for (k, h) in diagram.cell_half_edges(s).enumerate() {
                rank[h.index()] = k as u32;
                lowest = lowest.min(low[h.edge().index()]);
                first.get_or_insert(h);
            }
            if matches!(diagram.sites.at(s.index()), Site::Point(_)) && diagram.offset_may_circle(s, side) {
                let leaf = first.and_then(|h| diagram.target_vertex(h)).map_or(infinity, |v| v.index() as u32);
                circles.push((lowest, s, leaf));
            }
        }
        circles.sort_by(|a, b| a.0.total_cmp(&b.0));

        OffsetIndex {
            side,
            edges: IntervalTree::new(intervals),
            rank,
            circles,
            above: LevelTree::new(levels.clone(), above_links, true),
            levels,
            conics,
            below: LevelTree::new(vec![f64::NEG_INFINITY; diagram.sites.len() + 1], below_links, false),
        }
    }
}

/// Links of `below` that hold at every level: the sites of each ring
/// (the ring itself is at distance zero), and rings to the ring that
/// encloses them across a part of the plane on the far side of the
/// offsets: outside the domain when shrinking (the outer rings to
/// `outside`), inside it when growing.
fn ring_links(diagram: &Diagram, side: Side, outside: u32) -> Vec<(u32, u32, f64)> {
    let rings = diagram.ring_nesting();
    let mut links = Vec::new();
    for (sites, depth, parent) in &rings {
        let first = sites[0].index() as u32;
        links.extend(sites[1..].iter().map(|s| (first, s.index() as u32, f64::NEG_INFINITY)));
        // between a ring of even depth and its encloser lies the outside
        let across_outside = depth % 2 == 0;
        let joins = match side {
            Side::Shrink => across_outside,
            Side::Grow => !across_outside,
        };
        if !joins {
            continue;
        }
        let other = match parent {
            Some(p) => rings[*p].0[0].index() as u32,
            None if side == Side::Shrink => outside,
            None => continue,
        };
        links.push((first, other, f64::NEG_INFINITY));
    }
    links
}

impl Diagram {
    /// Whether the offsets on `side` may cross edge `e`: every edge without
    /// a domain; with one, the edges outside it when growing, inside when
    /// shrinking, and on both sides an edge through a straight corner (its
    /// part on that side: `Diagram::end_levels`).
    pub(super) fn offset_may_cross(&self, e: EdgeId, side: Side) -> bool {
        match (self.edge_location(e), side) {
            (None, _) => true,
            _ if self.inside_end_through_corner(e).is_some() => true,
            (Some(l), Side::Grow) => l == Location::Outside,
            (Some(l), Side::Shrink) => l == Location::Inside,
        }
    }

    /// Whether a whole circle around point site `s` may be an offset on
    /// `side` (its cell on that side of the domain).
    fn offset_may_circle(&self, s: SiteId, side: Side) -> bool {
        match (self.cell_location(s), side) {
            (None, _) => true,
            (Some(l), Side::Grow) => l == Location::Outside,
            (Some(l), Side::Shrink) => l == Location::Inside,
        }
    }

    /// The stops along edge `e` (see [`Stop`]): its two ends, and between
    /// them, for an edge beside an arc, where its clearance turns (and the
    /// far points of ends at infinity); for other edges, the lowest point
    /// inside it where there is one. Between two stops the clearance is
    /// monotone.
    pub(super) fn stops(&self, e: EdgeId, levels: &[f64], side: Side, conics: &HashMap<u32, ConicEdge>) -> Vec<Stop> {
        let [c0, c1] = self.end_levels(e, levels, side);
        let infinity = self.finite_vertices as u32;
        let ends = self.end_vertices(e);
        let leaf = |k: usize| ends[k].map_or(infinity, |v| v.index() as u32);
        // (a conic track's parameter runs from 0 to 1; other edges do not
        // use it)
        let mut stops = vec![Stop { t: 0.0, level: c0, leaf: leaf(0) }];
        if let Some(conic) = conics.get(&(e.index() as u32)) {
            let to_input = self.scale.to_input;
            stops.extend(conic.track.knots.iter().zip(&conic.leaves).map(|(k, &leaf)| Stop {
                t: k.t,
                level: k.value * to_input,
                leaf,
            }));
            stops.push(Stop { t: 1.0, level: c1, leaf: leaf(1) });
        } else {
            let interior = self.edge_track(e).and_then(|t| t.interior_minimum()).map(|m| m * self.scale.to_input);
            if let Some(m) = interior {
                stops.push(Stop { t: f64::NAN, level: m, leaf: NO_LEAF });
            }
            stops.push(Stop { t: f64::NAN, level: c1, leaf: leaf(1) });
            stops[0].t = f64::NAN;
        }
        stops
    }

    /// Where the clearance along edge `e` beside an arc peaks strictly
    /// inside it (no vertex there: the largest empty circle touching both
    /// sites at the ends of a diameter), with that clearance, in input
    /// units; empty for other edges.
    pub(crate) fn conic_peaks(&self, e: EdgeId) -> Vec<(crate::geometry::Point, f64)> {
        let Some(track) = self.conic_track(e) else { return Vec::new() };
        let to_input = self.scale.to_input;
        track
            .knots
            .iter()
            .filter(|k| k.peak)
            .filter_map(|k| Some((self.scale.point_to_input(track.point(k.t)?), k.value * to_input)))
            .collect()
    }

    /// The track of edge `e` when it lies beside an arc (a conic), in
    /// internal coordinates.
    pub(super) fn conic_track(&self, e: EdgeId) -> Option<ConicTrack> {
        let edge = self.edge(e)?;
        let EdgeShape::Conic { .. } = self.shape_of(&edge) else { return None };
        let f = self.scale.to_internal;
        let sites = edge.sites.map(|s| self.sites.at(s.index()).scaled(f));
        let end = |end: EdgeEnd| match end {
            EdgeEnd::Vertex(v) => ConicEnd::At(self.store.position[v.index()].scaled(f)),
            EdgeEnd::Infinite { direction } => ConicEnd::Towards(direction),
        };
        ConicTrack::new(sites, end(edge.ends[0]), end(edge.ends[1]))
    }

    /// The clearance at both ends of `e` as the offsets on `side` take it
    /// (`levels`: see `OffsetIndex::levels`); infinite at infinity. An edge
    /// through a straight ring corner (a separator on the perpendicular
    /// there, clearance zero at the corner) is cut at the corner: its end
    /// on the other side of the domain's boundary is taken at the corner,
    /// at clearance zero, so the offsets on each side cross only its part
    /// on that side (along which the clearance only rises from the corner).
    pub(super) fn end_levels(&self, e: EdgeId, levels: &[f64], side: Side) -> [f64; 2] {
        let mut ends = self.end_vertices(e).map(|v| v.map_or(f64::INFINITY, |v| levels[v.index()]));
        if let Some(inside) = self.inside_end_through_corner(e) {
            let kept = if side == Side::Shrink { inside } else { 1 - inside };
            ends[1 - kept] = 0.0;
        }
        ends
    }

    /// The clearance of vertex `v` as the vertices store it, but zero at a
    /// vertex where an edge the offsets on `side` may cross meets one they
    /// may not (a ring corner): so that around every cell the crossings
    /// alternate whatever the stored numbers, the part of a cell boundary
    /// the offsets do not cross counting as within the band.
    fn vertex_level(&self, v: crate::diagram::VertexId, side: Side) -> f64 {
        let off_side = self.has_domain()
            && self.vertex_half_edges(v).is_some_and(|out| out.iter().any(|h| !self.offset_may_cross(h.edge(), side)));
        if off_side {
            0.0
        } else {
            self.store.clearance[v.index()]
        }
    }

    /// The track of edge `e` (internal coordinates) from `ends[0]` to
    /// `ends[1]`.
    pub(super) fn edge_track(&self, e: EdgeId) -> Option<EdgeTrack> {
        let edge = self.edge(e)?;
        let f = self.scale.to_internal;
        let [a, b] = edge.sites.map(|s| self.sites.at(s.index()).scaled(f));
        let end = |end: EdgeEnd| match end {
            EdgeEnd::Vertex(v) => TrackEnd::At(self.store.position[v.index()].scaled(f)),
            EdgeEnd::Infinite { direction } => TrackEnd::Towards(direction),
        };
        EdgeTrack::new([&a, &b], end(edge.ends[0]), end(edge.ends[1]))
    }

    /// The finite vertex where `h` ends.
    pub(super) fn target_vertex(&self, h: HalfEdge) -> Option<crate::diagram::VertexId> {
        self.end_vertices(h.edge())[usize::from(!h.is_reversed())]
    }
}
