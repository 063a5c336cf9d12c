//! Splitting an input with circular arcs (`Builder::split_crossings` with
//! arcs): the snap rounding of the module above, with arcs among the
//! pieces.
//!
//! Each round, besides the segments' contacts (`contact_pixels`), every
//! pair with an arc among it is tested exactly (the input check's sweep,
//! `input_check::arcs::for_each_arc_conflict`), and where one meets, the
//! pixels of its contact points are hot: where a segment or another arc
//! crosses or touches it, where a point or an end lies on it, where two
//! arcs of one circle overlap (their ends inside each other). The contact
//! points are rounded (floating-point intersections of lines and circles);
//! the exact test decides that they meet, the rounding only where. Both
//! pieces of a contact are bent through the centre of its pixel whether
//! or not they meet that pixel exactly (they pass within rounding of it),
//! and every arc also through each hot pixel it passes within half a
//! pixel's diagonal of. An arc bent through centres becomes arcs from one
//! to the next, each with the bulge of its share of the original sweep,
//! 2^-40 flatter (`sub_arc`: a sub-arc's circle is then within a pixel of
//! the original's, and a hair flatter, so that where the arc touched a
//! line it does not cross it again beside the cut). Arcs that come out
//! with the same ends and the same middle (to a pixel) merge. The loop ends when the exact tests find nothing,
//! so the result is accepted by the strict check, as with segments.
//!
//! Polygons' rings are put together again from the pieces by
//! `split::rings::split_rings_with_arcs` (the even-odd boundary, arcs
//! included).

use std::collections::HashMap;

use super::contacts::contact_pixels;
use super::route::{route_also_through, HotPixels};
use super::{max_displacement, not_converged, Layout, Piece, SplitInput, MAX_ROUNDS};
use crate::construct::input_check::arcs::{for_each_arc_conflict, ArcConflict};
use crate::error::{Error, ErrorKind};
use crate::geometry::input::arc_contact::{ArcArcContact, SegmentArcContact};
use crate::geometry::input::snap::{Pixel, PixelGrid};
use crate::geometry::scale::Scale;
use crate::geometry::{CircularArc, Point, Site};

/// An arc while it is being split, and the input arcs it came from.
#[derive(Clone, Debug)]
pub(crate) struct ArcPiece {
    pub arc: CircularArc,
    pub origins: Vec<u32>,
}

/// The input with arcs after splitting, in input coordinates: the points
/// and segment pieces as `split` gives them (its counts and displacement
/// include the arcs': an arc crossing a segment or an arc is a crossing,
/// two arcs of one circle sharing a stretch an overlap, a tangent or an
/// end or a point on an arc a touching, each pair once), and the arcs.
#[derive(Clone, Debug)]
pub(crate) struct SplitWithArcs {
    pub input: SplitInput,
    /// The arc pieces, with the input arcs each came from.
    pub arcs: Vec<ArcPiece>,
}

/// Splits `segments` and `arcs` (finite coordinates) against each other
/// and against `points`; see the module documentation.
pub(crate) fn split_with_arcs(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Result<SplitWithArcs, Error> {
    let arc_points = |a: &CircularArc| [a.start(), a.end(), a.centre()].into_iter().chain(a.via());
    let all = || points.iter().copied().chain(segments.iter().flatten().copied()).chain(arcs.iter().flat_map(arc_points));
    let scale = Scale::for_coordinates(all().flat_map(|p| [p.x, p.y]).filter(|v| v.is_finite()));
    let internal = |p: Point| p.scaled(scale.to_internal).canonical_zero();
    let max_abs = all().map(internal).fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let pixels = PixelGrid::for_magnitude(max_abs);
    let mut pieces: Vec<Piece> =
        segments.iter().enumerate().map(|(i, s)| Piece { ends: s.map(internal), origins: vec![i as u32] }).collect();
    let mut arc_pieces: Vec<ArcPiece> =
        arcs.iter().enumerate().map(|(i, a)| ArcPiece { arc: a.scaled(scale.to_internal), origins: vec![i as u32] }).collect();
    let mut moved: Vec<Point> = points.iter().map(|&p| internal(p)).collect();
    let mut hot = HotPixels::new();
    let mut first = None;
    let mut rounds = 0;
    loop {
        let layout = Layout::of(&pieces, &moved);
        let mut found = Vec::new();
        let counts = contact_pixels(&layout, &pixels, &mut found);
        let contacts = arc_contacts(&moved, &pieces, &arc_pieces, &pixels);
        first.get_or_insert((counts, contacts.kinds));
        if counts.total() == 0 && contacts.count == 0 {
            break;
        }
        if rounds == MAX_ROUNDS {
            return Err(not_converged(counts.total() + contacts.count));
        }
        hot.extend(found);
        hot.extend(contacts.pixels.iter().copied());
        pieces = route_also_through(pieces, &hot, &pixels, &contacts.of_segment);
        moved = moved.into_iter().map(|p| hot.snap(&pixels, p)).collect();
        arc_pieces = route_arcs(arc_pieces, &hot, &pixels, &contacts.of_arc)?;
        rounds += 1;
    }
    let to_input = |p: Point| {
        let q = p.scaled(scale.to_input);
        Point::new(q.x.clamp(-f64::MAX, f64::MAX), q.y.clamp(-f64::MAX, f64::MAX))
    };
    let displacement = max_displacement(&pieces, segments, internal).max(arc_displacement(&arc_pieces, arcs, scale));
    let (counts, [arc_crossings, arc_overlaps, arc_touchings]) = first.unwrap_or_default();
    Ok(SplitWithArcs {
        input: SplitInput {
            points: moved.into_iter().map(to_input).collect(),
            pieces: pieces.into_iter().map(|p| Piece { ends: p.ends.map(to_input), origins: p.origins }).collect(),
            crossings: counts.crossings + arc_crossings,
            overlaps: counts.overlaps + arc_overlaps,
            touchings: counts.touchings + arc_touchings,
            rounds,
            pixel: pixels.size() * scale.to_input,
            max_displacement: displacement * scale.to_input,
            // (a build with arcs checks its pieces afresh)
            contact_free_in: None,
        },
        arcs: arc_pieces.into_iter().map(|a| ArcPiece { arc: a.arc.scaled(scale.to_input), origins: a.origins }).collect(),
    })
}

/// One round's contacts with an arc among them: how many pairs meet, the
/// pixels of their contact points, and by piece which of them it must be
/// bent through.
#[derive(Default)]
struct ArcContacts {
    count: usize,
    /// Crossings, overlaps and touchings.
    kinds: [usize; 3],
    pixels: Vec<Pixel>,
    of_segment: HashMap<usize, Vec<Pixel>>,
    of_arc: HashMap<usize, Vec<Pixel>>,
}

/// Every pair with an arc among the points, segment pieces and arc pieces
/// that meets (exactly), and where (rounded).
fn arc_contacts(points: &[Point], pieces: &[Piece], arcs: &[ArcPiece], pixels: &PixelGrid) -> ArcContacts {
    let mut out = ArcContacts::default();
    if arcs.is_empty() {
        return out;
    }
    let segments: Vec<[Point; 2]> = pieces.iter().map(|p| p.ends).collect();
    let geometry: Vec<CircularArc> = arcs.iter().map(|a| a.arc).collect();
    let mut conflicts = Vec::new();
    for_each_arc_conflict(points, &segments, &geometry, |_| true, |c| conflicts.push(c));
    out.count = conflicts.len();
    for c in &conflicts {
        let kind = match c {
            ArcConflict::ArcSegment { contact: SegmentArcContact::Cross, .. }
            | ArcConflict::Arcs { contact: ArcArcContact::Cross, .. } => 0,
            ArcConflict::Arcs { contact: ArcArcContact::Overlap, .. } => 1,
            _ => 2,
        };
        out.kinds[kind] += 1;
    }
    let near = 4.0 * pixels.size();
    for conflict in conflicts {
        let (at, segment, arcs_met): (Vec<Point>, Option<usize>, Vec<usize>) = match conflict {
            ArcConflict::PointOnArc { point, arc } => (vec![points[point]], None, vec![arc]),
            ArcConflict::ArcSegment { arc, segment, contact } => {
                let tangent = contact == SegmentArcContact::Tangent;
                (segment_meets_arc(segments[segment], &geometry[arc], near, tangent), Some(segment), vec![arc])
            }
            ArcConflict::Arcs { first, second, contact } => {
                let tangent = contact == ArcArcContact::Tangent;
                (arc_meets_arc(&geometry[first], &geometry[second], near, tangent), None, vec![first, second])
            }
        };
        for p in at {
            let pixel = pixels.pixel_of(p);
            out.pixels.push(pixel);
            if let Some(k) = segment {
                out.of_segment.entry(k).or_default().push(pixel);
            }
            for &k in &arcs_met {
                out.of_arc.entry(k).or_default().push(pixel);
            }
        }
    }
    out
}

/// Where the segment `s` meets the arc (rounded): the line's points on
/// the circle, and `s`'s ends on the arc, within `near` of both; where
/// rounding loses all, the point of the circle nearest the line. Where
/// they are `tangent` (decided exactly), that point alone: the rounded
/// roots of a tangent line stand apart by the square root of rounding
/// (1e-7 of the radius), and cutting the arc at both would leave between
/// them a piece of arc straight to the last bit.
fn segment_meets_arc(s: [Point; 2], arc: &CircularArc, near: f64, tangent: bool) -> Vec<Point> {
    let [a, b] = s;
    let (c, r) = (arc.centre(), arc.radius());
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let length2 = dx * dx + dy * dy;
    let mut candidates = vec![a, b];
    if length2 > 0.0 {
        // the foot of the centre on the line, and the half chord from it
        let t = ((c.x - a.x) * dx + (c.y - a.y) * dy) / length2;
        let foot = Point::new(a.x + t * dx, a.y + t * dy);
        let h2 = r * r - foot.distance_squared(c);
        let half = h2.max(0.0).sqrt() / length2.sqrt();
        if !tangent {
            for sign in [-1.0, 1.0] {
                candidates.push(Point::new(foot.x + sign * half * dx, foot.y + sign * half * dy));
            }
        }
    }
    let segment = Site::Segment { a, b };
    let arc_site = Site::Arc(*arc);
    let mut at: Vec<Point> =
        candidates.into_iter().filter(|&p| segment.distance(p) <= near && arc_site.distance(p) <= near).collect();
    if at.is_empty() {
        // the point of the circle toward the foot of the centre on the segment
        let t = if length2 > 0.0 { (((c.x - a.x) * dx + (c.y - a.y) * dy) / length2).clamp(0.0, 1.0) } else { 0.0 };
        at.push(toward(c, r, Point::new(a.x + t * dx, a.y + t * dy)));
    }
    at
}

/// Where two arcs meet (rounded): their circles' common points, and the
/// ends of each on the other, within `near` of both; where rounding loses
/// all, or where they are `tangent` (decided exactly: see
/// `segment_meets_arc`), the point of the first circle toward the second's
/// centre, or away from it.
fn arc_meets_arc(x: &CircularArc, y: &CircularArc, near: f64, tangent: bool) -> Vec<Point> {
    let (c1, r1, c2, r2) = (x.centre(), x.radius(), y.centre(), y.radius());
    let mut candidates = vec![x.start(), x.end(), y.start(), y.end()];
    let d = c1.distance(c2);
    if d > 0.0 && !tangent {
        // along the centres' line from c1, and across it
        let along = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
        let across = (r1 * r1 - along * along).max(0.0).sqrt();
        let (ux, uy) = ((c2.x - c1.x) / d, (c2.y - c1.y) / d);
        for sign in [-1.0, 1.0] {
            candidates.push(Point::new(c1.x + along * ux - sign * across * uy, c1.y + along * uy + sign * across * ux));
        }
    }
    let (sx, sy) = (Site::Arc(*x), Site::Arc(*y));
    let mut at: Vec<Point> = candidates.into_iter().filter(|&p| sx.distance(p) <= near && sy.distance(p) <= near).collect();
    at.dedup();
    if at.is_empty() {
        let toward_second = toward(c1, r1, c2);
        let away = Point::new(2.0 * c1.x - toward_second.x, 2.0 * c1.y - toward_second.y);
        let best = [toward_second, away].into_iter().min_by(|p, q| sy.distance(*p).total_cmp(&sy.distance(*q)));
        at.extend(best);
    }
    at
}

/// The point of the circle (`c`, `r`) in the direction of `p`.
fn toward(c: Point, r: f64, p: Point) -> Point {
    let d = c.distance(p);
    if !(d > 0.0) {
        return Point::new(c.x + r, c.y);
    }
    Point::new(c.x + r * (p.x - c.x) / d, c.y + r * (p.y - c.y) / d)
}

/// The arcs after one round of snapping through `hot`, each also bent
/// through its pixels in `also` (its contacts').
fn route_arcs(
    arcs: Vec<ArcPiece>,
    hot: &HotPixels,
    pixels: &PixelGrid,
    also: &HashMap<usize, Vec<Pixel>>,
) -> Result<Vec<ArcPiece>, Error> {
    // the hot pixels by x, for the arcs' boxes
    let mut by_x: Vec<Pixel> = hot.set.iter().copied().collect();
    by_x.sort_unstable();
    let reach = 0.5 * std::f64::consts::SQRT_2 * pixels.size() * (1.0 + 1e-9);
    let mut out: Vec<ArcPiece> = Vec::with_capacity(arcs.len());
    let mut index: HashMap<[u64; 4], Vec<usize>> = HashMap::new();
    for (k, piece) in arcs.into_iter().enumerate() {
        let arc = piece.arc;
        let (c, r) = (arc.centre(), arc.radius());
        let site = Site::Arc(arc);
        let (lo, hi) = (pixels.pixel_of(Point::new(c.x - r, c.y - r)), pixels.pixel_of(Point::new(c.x + r, c.y + r)));
        let from = by_x.partition_point(|p| p[0] < lo[0] - 1);
        let mut met: Vec<Pixel> = by_x[from..]
            .iter()
            .take_while(|p| p[0] <= hi[0] + 1)
            .filter(|p| p[1] >= lo[1] - 1 && p[1] <= hi[1] + 1)
            .filter(|&&p| site.distance(pixels.centre(p)) <= reach)
            .copied()
            .collect();
        for &p in also.get(&k).into_iter().flatten() {
            if !met.contains(&p) {
                met.push(p);
            }
        }
        let (ps, pe) = (pixels.pixel_of(arc.start()), pixels.pixel_of(arc.end()));
        met.retain(|&p| p != ps && p != pe);
        let (start, end) = (hot.snap(pixels, arc.start()), hot.snap(pixels, arc.end()));
        // along the arc, by the fraction of its sweep
        let mut route: Vec<(f64, Point)> =
            met.iter().map(|&p| (fraction_along(&arc, pixels.centre(p)), pixels.centre(p))).collect();
        route.sort_by(|a, b| a.0.total_cmp(&b.0));
        route.insert(0, (0.0, start));
        route.push((1.0, end));
        route.dedup_by(|a, b| a.1 == b.1);
        for w in route.windows(2) {
            let ((t0, p0), (t1, p1)) = (w[0], w[1]);
            if p0 == p1 {
                continue;
            }
            let sub = if (p0, p1) == (arc.start(), arc.end()) {
                arc
            } else {
                sub_arc(&arc, (t0, p0), (t1, p1)).map_err(|e| {
                    Error::new(
                        ErrorKind::Internal,
                        format!(
                            "splitting crossings could not cut arc {:?} at ({}, {}) - ({}, {}): {e}; please report this input",
                            piece.origins, p0.x, p0.y, p1.x, p1.y
                        ),
                        piece.origins.iter().map(|&i| i as usize).collect(),
                    )
                })?
            };
            push_merged(&mut out, &mut index, sub, &piece.origins, pixels.size());
        }
    }
    Ok(out)
}

/// The part of `arc` from fraction `t0` of its sweep to `t1`, its ends
/// moved to `p0` and `p1` (pixel centres): by its bulge, the share of the
/// sweep, times 1 − 2^-40 (a hair flatter: see `flattened`). The bulge
/// keeps the sub-arc on its circle to the rounding of its ends; through
/// three points (the ends and the middle of the arc, each rounded), a
/// piece of 30 degrees 1e6 from the origin had its centre 4e-8 off its
/// neighbour's, and the solver saw two circles where there was one. Where
/// the bulge makes no arc, through the flattened middle.
fn sub_arc(arc: &CircularArc, (t0, p0): (f64, Point), (t1, p1): (f64, Point)) -> Result<CircularArc, Error> {
    let bulge = ((t1 - t0) * arc.sweep() / 4.0).tan() * (1.0 - 2f64.powi(-40));
    let by_bulge = if bulge != 0.0 && bulge.is_finite() { CircularArc::from_bulge(p0, p1, bulge).ok() } else { None };
    match by_bulge {
        Some(sub) => Ok(sub),
        None => CircularArc::through(p0, flattened(p0, arc.point_at(0.5 * (t0 + t1)), p1), p1),
    }
}

/// `m` (the middle of a sub-arc from `p0` to `p1`) moved toward their
/// chord by 2^-40 of its distance from it: the sub-arc a hair flatter
/// than its circle, as `sub_arc`'s bulge is. Where the arc touched a line
/// or another circle at a cut (a tangent contact), its circle through the
/// cut's pixel centre may dip across the other piece just before the cut,
/// a crossing no further cut can remove; a flatter sub-arc arrives at the
/// cut from its own side.
fn flattened(p0: Point, m: Point, p1: Point) -> Point {
    let middle = Point::new(0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y));
    let keep = 1.0 - 2f64.powi(-40);
    Point::new(middle.x + keep * (m.x - middle.x), middle.y + keep * (m.y - middle.y))
}

/// Adds `arc` with its `origins` to `out`, or merges them into an arc
/// already there with the same ends (either way) and its middle within a
/// pixel (two input arcs of one circle cut at their overlap's ends).
fn push_merged(
    out: &mut Vec<ArcPiece>,
    index: &mut HashMap<[u64; 4], Vec<usize>>,
    arc: CircularArc,
    origins: &[u32],
    pixel: f64,
) {
    let key = Point::segment_key(arc.start(), arc.end());
    let same =
        index.get(&key).and_then(|ks| ks.iter().copied().find(|&k| out[k].arc.midpoint().distance(arc.midpoint()) <= pixel));
    match same {
        Some(k) => {
            let merged = &mut out[k].origins;
            merged.extend_from_slice(origins);
            merged.sort_unstable();
            merged.dedup();
        }
        None => {
            index.entry(key).or_default().push(out.len());
            out.push(ArcPiece { arc, origins: origins.to_vec() });
        }
    }
}

/// The fraction of the arc's sweep from its start to the direction of
/// `p` from its centre, in `[0, 1]` (beyond the span: the nearer end).
fn fraction_along(arc: &CircularArc, p: Point) -> f64 {
    let c = arc.centre();
    let angle = |q: Point| (q.y - c.y).atan2(q.x - c.x);
    let sweep = arc.sweep();
    let tau = std::f64::consts::TAU;
    let turned = (angle(p) - angle(arc.start())) * sweep.signum();
    let turned = turned.rem_euclid(tau);
    if turned <= sweep.abs() {
        turned / sweep.abs()
    } else if turned - sweep.abs() < tau - turned {
        1.0
    } else {
        0.0
    }
}

/// The largest distance from an arc piece's ends and middle to an input
/// arc it came from, in internal coordinates.
fn arc_displacement(pieces: &[ArcPiece], arcs: &[CircularArc], scale: Scale) -> f64 {
    let mut worst = 0.0f64;
    for piece in pieces {
        for &i in &piece.origins {
            let origin = Site::Arc(arcs[i as usize].scaled(scale.to_internal));
            let a = piece.arc;
            worst = [a.start(), a.end(), a.midpoint()].iter().map(|&q| origin.distance(q)).fold(worst, f64::max);
        }
    }
    worst
}
