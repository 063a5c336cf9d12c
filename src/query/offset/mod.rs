//! Offset curves: the points at one distance from the sites, as closed
//! loops of exact pieces — line pieces parallel to segment sites, circular
//! arcs around point sites and concentric with arc sites, never parabolas
//! or conics — traced through the cells of the diagram, oriented, and
//! nested.
//!
//! - `trace`: the crossings of the level with the edges and the pieces
//!   inside each cell;
//! - `conic`: the clearance along edges beside arcs (not quasi-convex:
//!   cut where it turns) and their crossings, by bisection;
//! - `index`: what many distances share (edges by clearance range, the
//!   merge trees of the nesting);
//! - `approximation`: polylines within a tolerance, and areas.

mod approximation;
mod conic;
mod index;
mod interval_tree;
mod level_point;
mod level_tree;
mod trace;

use std::collections::HashMap;

use crate::diagram::{Diagram, SiteId};
use crate::error::{Error, ErrorKind};
use crate::geometry::scale::{Magnitudes, EXACT_SPAN};
use crate::geometry::{Point, Site};
use index::{OffsetIndex, Side};

/// Points of an offset at distance `r` closer than `COINCIDENT × r` are one
/// point: the ends of a span that goes nowhere, a loop that is the trace of
/// a part with no interior. So are points a few ulps of their coordinates
/// apart (`coincident`): far from the origin that is more.
const COINCIDENT: f64 = 1e-9;

/// How near two points of an offset at distance `r` around `at` are one
/// point (see [`COINCIDENT`]).
fn coincident(r: f64, at: Point) -> f64 {
    (COINCIDENT * r).max(8.0 * f64::EPSILON * at.x.abs().max(at.y.abs()))
}

/// One piece of an offset loop, in the loop's direction. Every piece lies
/// in the cell of one site and is at the offset's distance from it. More
/// kinds may come with more site kinds, so a `match` outside this crate
/// needs a wildcard arm.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum OffsetPiece {
    /// A straight piece, parallel to the segment site `site`.
    Line {
        /// Where it starts.
        from: Point,
        /// Where it ends.
        to: Point,
        /// The segment site it runs along.
        site: SiteId,
    },
    /// An arc of a circle: around the point site `site` at the offset's
    /// distance, or concentric with the arc site `site`, at its radius plus
    /// the distance on its convex side and minus it on its concave side.
    Arc {
        /// The point site's position, or the arc site's centre.
        centre: Point,
        /// The offset's distance around a point; the arc's radius plus or
        /// minus it beside an arc.
        radius: f64,
        /// Where it starts.
        from: Point,
        /// Where it ends; equal to `from` for a whole circle.
        to: Point,
        /// The way round from `from` to `to`.
        counter_clockwise: bool,
        /// The point or arc site it keeps its distance from.
        site: SiteId,
    },
}

impl OffsetPiece {
    /// Where the piece starts.
    pub fn from(&self) -> Point {
        match *self {
            OffsetPiece::Line { from, .. } | OffsetPiece::Arc { from, .. } => from,
        }
    }

    /// Where the piece ends.
    pub fn to(&self) -> Point {
        match *self {
            OffsetPiece::Line { to, .. } | OffsetPiece::Arc { to, .. } => to,
        }
    }

    /// The site the piece keeps its distance from.
    pub fn site(&self) -> SiteId {
        match *self {
            OffsetPiece::Line { site, .. } | OffsetPiece::Arc { site, .. } => site,
        }
    }

    /// The same piece walked the other way.
    fn reversed(self) -> OffsetPiece {
        match self {
            OffsetPiece::Line { from, to, site } => OffsetPiece::Line { from: to, to: from, site },
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, site } => {
                OffsetPiece::Arc { centre, radius, from: to, to: from, counter_clockwise: !counter_clockwise, site }
            }
        }
    }
}

/// A closed loop of an offset: each piece ends where the next starts, the
/// last where the first starts. The region of the offset is on its left.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetLoop {
    /// The pieces, in order.
    pub pieces: Vec<OffsetPiece>,
    /// The loop it lies directly inside (an index into
    /// [`Offset::loops`]), `None` for an outermost loop.
    pub parent: Option<usize>,
    /// Whether it bounds a hole of the region: it is nested inside an odd
    /// number of loops, and runs clockwise (outer boundaries run
    /// counter-clockwise).
    pub hole: bool,
}

/// The offset at one distance: its loops, with their nesting.
#[derive(Clone, Debug, PartialEq)]
pub struct Offset {
    /// The signed distance it was asked for.
    pub distance: f64,
    /// The loops; a loop's parent comes before it.
    pub loops: Vec<OffsetLoop>,
}

/// The largest extent of an offset's region (the input's extent plus twice
/// the distance): `2^510`, so that its area, at most the square of it,
/// stays finite with room for the sums that compute it.
const MAX_OFFSET_REACH: f64 = 3.3519519824856493e153;

impl Diagram {
    /// The offset at signed distance `distance`: the closed loops at that
    /// distance from the sites, of exact line pieces and circular arcs.
    ///
    /// Circular arc sites (`Builder::add_arc`, `add_bulged_polyline`) are
    /// offset like the others: beside an arc the loops run along the
    /// concentric circle, of radius `R + distance` on its convex side and
    /// `R - distance` on its concave side (where that is positive). Where
    /// they cross an edge beside an arc (a conic) is found by bisection
    /// along the edge to the precision of `f64`, not in closed form: such a
    /// piece's ends are at the distance from its site to a few ulps of the
    /// input's extent, and the vertices an arc meets are placed by the
    /// arcs' vertex solver (to about `1e-8` of the extent; see
    /// `docs/guarantees.md`).
    ///
    /// With a domain (polygons were added), the sign follows GEOS's buffer:
    /// a negative distance shrinks the domain (the loops bound the points
    /// of the domain at least `|distance|` from its boundary), a positive
    /// one grows it (the points at most `distance` from the domain).
    /// Without a domain, `distance > 0` gives the boundary of the points
    /// within `distance` of any site. Isolated points and free segments
    /// count as sites either way: the distance is to the nearest site.
    ///
    /// Loops are oriented with the region on their left (outer boundaries
    /// counter-clockwise, holes clockwise), and each knows the loop it lies
    /// directly inside, found from the diagram's structure (which regions
    /// above and below the distance each loop separates), not from
    /// distances.
    ///
    /// Degenerate distances: the region is taken open, so where two parts
    /// of it touch at one point — a distance equal to the clearance of a
    /// medial-axis vertex where the offset pinches, or two sites exactly
    /// `2 × distance` apart — the loops are split there: each passes the
    /// touching point once, and no loop passes any point twice. A part that
    /// shrinks to a point or a line at that distance (a hole's inscribed
    /// circle) has no loop. Which side of the distance a vertex lies on is
    /// decided from its stored clearance, the same way for every edge, so
    /// the loops always close; a clearance within `1e-10 × |distance|` of
    /// the distance counts as equal to it, so that a part of the region
    /// thinner than that — which rounding alone would make or unmake, as in
    /// a corridor between parallel segments exactly `2 × |distance|` wide —
    /// is left out rather than traced as a sliver.
    ///
    /// Errors ([`ErrorKind::InvalidArgument`]): a distance that is NaN,
    /// infinite or zero, or not positive without a domain, or one at which
    /// the input's extent plus twice the distance exceeds `2^510` (about
    /// `3e153`), in input coordinates and in the construction's (an input
    /// the construction scales up by a power of two, such as one of extent
    /// 1e-159, has a bound that much smaller; the message gives it): beyond
    /// it the loops' areas and the arithmetic of their points leave `f64`.
    ///
    /// ```
    /// use segvoronoi::{Builder, OffsetPiece};
    /// let mut b = Builder::new();
    /// b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]])?;
    /// let d = b.build()?;
    /// // grown by 1: four sides and four quarter circles
    /// let grown = d.offset(1.0)?;
    /// assert_eq!(grown.loops.len(), 1);
    /// let arcs = grown.loops[0].pieces.iter().filter(|p| matches!(p, OffsetPiece::Arc { .. })).count();
    /// assert_eq!(arcs, 4);
    /// assert!((grown.area() - (8.0 + 12.0 + std::f64::consts::PI)).abs() < 1e-9);
    /// // shrunk by 0.5: a 3 × 1 rectangle
    /// let shrunk = d.offset(-0.5)?;
    /// assert!((shrunk.area() - 3.0).abs() < 1e-9);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn offset(&self, distance: f64) -> Result<Offset, Error> {
        Ok(self.offsets(&[distance])?.pop().expect("one distance"))
    }

    /// The offsets at several distances (see [`Diagram::offset`]), in the
    /// order given. The work shared by all distances on one side is done
    /// once: an index of the edges by the range of their clearance, so that
    /// each distance costs about its output (and a logarithm) rather than
    /// the size of the diagram.
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let mut b = Builder::new();
    /// b.add_point([0.0, 0.0])?;
    /// let d = b.build()?;
    /// let rings = d.offsets(&[1.0, 2.0, 3.0])?;
    /// let areas: Vec<f64> = rings.iter().map(|o| o.area() / std::f64::consts::PI).collect();
    /// assert!(areas.iter().zip([1.0, 4.0, 9.0]).all(|(a, b)| (a - b).abs() < 1e-12));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn offsets(&self, distances: &[f64]) -> Result<Vec<Offset>, Error> {
        let sides: Vec<Side> = distances.iter().map(|&d| self.offset_side(d)).collect::<Result<_, _>>()?;
        let mut grow: Option<OffsetIndex> = None;
        let mut shrink: Option<OffsetIndex> = None;
        let mut out = Vec::with_capacity(distances.len());
        for (&distance, &side) in distances.iter().zip(&sides) {
            let slot = if side == Side::Grow { &mut grow } else { &mut shrink };
            let index = slot.get_or_insert_with(|| OffsetIndex::new(self, side));
            let offset = self.offset_with(index, distance);
            self.check_finite(&offset, distance)?;
            self.check_pieces_beside_arcs(&offset, distance)?;
            out.push(offset);
        }
        Ok(out)
    }

    /// An offset is returned only with finite points and area. Within the
    /// exact range and `MAX_OFFSET_REACH` that always holds; beyond the
    /// exact range (an input whose smallest differences underflow in the
    /// products the tracing needs) it is checked, and refused by kind.
    fn check_finite(&self, offset: &Offset, distance: f64) -> Result<(), Error> {
        let finite = |p: Point| p.x.is_finite() && p.y.is_finite();
        let pieces_finite = offset.loops.iter().flat_map(|l| &l.pieces).all(|p| finite(p.from()) && finite(p.to()));
        if pieces_finite && offset.area().is_finite() {
            return Ok(());
        }
        let sites = (0..self.site_count()).filter_map(|k| self.site(SiteId::from_index(k)));
        let points: Vec<Point> = sites.flat_map(|s| s.ends()).collect();
        let span = Magnitudes::of_points(points.iter()).span();
        let (kind, why) = if span > EXACT_SPAN {
            (
                ErrorKind::UnsupportedRange,
                format!("the input's coordinates span {span} bits, beyond the exact range of {EXACT_SPAN}"),
            )
        } else {
            (ErrorKind::Internal, "a bug in segvoronoi: please report the input".to_string())
        };
        Err(Error::new(
            kind,
            format!("offset distance {distance}: the loops came out with points or an area beyond f64 ({why})"),
            Vec::new(),
        ))
    }

    /// With arcs among the sites (whose decisions are not certified yet,
    /// see `geometry::arcs`), every loop of an offset is checked before it
    /// is returned: closed (each piece ends exactly where the next begins)
    /// and every piece with both its ends as far from its site as the
    /// distance, and an arc's on its circle (to 1e-7 of the input's extent,
    /// as the build checks its vertices). A loop that is not is the mark of
    /// a wrong decision near an arc (a segment's end within rounding of an
    /// arc's interior, in real drawings); the offset is then refused as
    /// `Internal`, naming the arc nearest the place, rather than returned
    /// wrong.
    fn check_pieces_beside_arcs(&self, offset: &Offset, distance: f64) -> Result<(), Error> {
        if self.arc_sites == 0 || crate::geometry::fault::active() {
            return Ok(());
        }
        let r = distance.abs();
        let tolerance = 1e-7 * (self.extent + r);
        let refuse = |what: String, end: Point| {
            let first_arc = self.sites.len() - self.arc_sites;
            let nearest = (first_arc..self.sites.len())
                .min_by(|&a, &b| self.sites.at(a).distance(end).total_cmp(&self.sites.at(b).distance(end)))
                .map_or(0, |s| self.arc_input.get(s - first_arc).copied().unwrap_or(0) as usize);
            Err(Error::new(
                ErrorKind::Internal,
                format!(
                    "offset distance {distance}: {what} at ({}, {}), beside arc {nearest}: a decision near the arcs went \
                     wrong; please report this input",
                    end.x, end.y
                ),
                vec![nearest],
            ))
        };
        for pieces in offset.loops.iter().map(|l| &l.pieces) {
            for (k, piece) in pieces.iter().enumerate() {
                // closed: each piece ends where the next begins
                let next = &pieces[(k + 1) % pieces.len()];
                if piece.to() != next.from() {
                    return refuse("a loop does not close".to_string(), piece.to());
                }
                let Some(site) = self.site(piece.site()) else { continue };
                for end in [piece.from(), piece.to()] {
                    // at the distance from its site, and an arc's on its circle
                    let round = match *piece {
                        OffsetPiece::Arc { centre, radius, .. } => (centre.distance(end) - radius).abs(),
                        OffsetPiece::Line { .. } => 0.0,
                    };
                    let off = (site.distance(end) - r).abs().max(round);
                    if off > tolerance {
                        return refuse(format!("a piece ends {off:e} off its distance"), end);
                    }
                }
            }
        }
        Ok(())
    }

    /// Which way `distance` goes, or why it cannot.
    fn offset_side(&self, distance: f64) -> Result<Side, Error> {
        let invalid =
            |why: &str| Err(Error::new(ErrorKind::InvalidArgument, format!("offset distance {distance}: {why}"), Vec::new()));
        if !distance.is_finite() {
            return invalid("not a finite number");
        }
        if distance == 0.0 {
            return invalid("zero (the offset at distance zero is the input itself)");
        }
        if distance < 0.0 && !self.has_domain() {
            return invalid("negative, and there is no domain to shrink (add polygons, or ask for a positive distance)");
        }
        // The region's size, in input coordinates and in the construction's
        // (scaled by a power of two: a tiny input is scaled up, and a
        // distance far beyond its extent with it).
        let reach = self.extent() + 2.0 * distance.abs();
        let limit = MAX_OFFSET_REACH * self.scale.to_input.min(1.0);
        if reach > limit {
            return invalid(&format!(
                "the offset's region would reach {reach:e} (the input's extent {:e} plus twice the distance), \
                 beyond {limit:e} for this input, past which its area and the arithmetic of its points \
                 leave the range of f64",
                self.extent()
            ));
        }
        Ok(if distance > 0.0 { Side::Grow } else { Side::Shrink })
    }

    /// The offset at `distance` from its side's index.
    fn offset_with(&self, index: &OffsetIndex, distance: f64) -> Offset {
        let r = distance.abs();
        let side = index.side;
        let threshold = side.threshold(r);
        let mut traced = self.trace(index, r);

        let empty = self.drop_empty_spans(&mut traced, r);
        split_at_touching_points(&mut traced);

        // Follow the spans into loops; each loop's two regions (a leaf of
        // each merge tree) come from one of its spans.
        let mut loops: Vec<(Vec<OffsetPiece>, u32, u32)> = Vec::new();
        let mut seen = vec![false; traced.spans.len()];
        for start in 0..traced.spans.len() {
            if seen[start] {
                continue;
            }
            let mut pieces = Vec::new();
            let mut k = start as u32;
            let mut faces = None;
            while (k as usize) < traced.spans.len() && !seen[k as usize] {
                seen[k as usize] = true;
                let span = traced.spans[k as usize];
                if !empty[k as usize] {
                    faces.get_or_insert((traced.crossings[span.from as usize].above, span.site.index() as u32));
                    let (from, to) = (traced.crossings[span.from as usize].at, traced.crossings[span.to as usize].at);
                    pieces.push(match self.circle_of_span(span.site, from, to, r) {
                        Some((centre, radius, counter_clockwise)) => {
                            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, site: span.site }
                        }
                        None => OffsetPiece::Line { from, to, site: span.site },
                    });
                }
                k = traced.next[k as usize];
            }
            // a loop within rounding of one point is the trace of a part
            // with no interior (the region touching itself there)
            let near = pieces.first().map_or(0.0, |p| coincident(r, p.from()));
            cancel_slits(&mut pieces, near);
            self.no_whole_turn_at_a_joint(&mut pieces);
            let tiny = pieces.iter().all(|p| matches!(p, OffsetPiece::Line { .. }) || p.from() != p.to())
                && pieces
                    .iter()
                    .all(|p| p.from().distance(pieces[0].from()) <= near && p.to().distance(pieces[0].from()) <= near);
            if let (Some((above, below)), false, false) = (faces, tiny, a_line_both_ways(&pieces, near)) {
                loops.push((pieces, above, below));
            }
        }
        // Whole circles in cells the level never leaves.
        let first_circle = index.circles.partition_point(|c| side.in_band(c.0, threshold));
        for &(_, site, leaf) in &index.circles[first_circle..] {
            let centre = self.sites.at(site.index()).as_point().expect("a point site");
            let at = Point::new(centre.x + r, centre.y);
            loops.push((
                vec![OffsetPiece::Arc { centre, radius: r, from: at, to: at, counter_clockwise: true, site }],
                leaf,
                site.index() as u32,
            ));
        }

        let (parents, depths) = self.nest(index, r, &loops);
        let mut order: Vec<usize> = (0..loops.len()).collect();
        order.sort_by_key(|&k| depths[k]);
        let mut position = vec![0usize; loops.len()];
        for (new, &old) in order.iter().enumerate() {
            position[old] = new;
        }
        let mut pieces_of: Vec<Option<Vec<OffsetPiece>>> = loops.into_iter().map(|(p, _, _)| Some(p)).collect();
        let loops = order
            .iter()
            .map(|&old| {
                let mut pieces = pieces_of[old].take().expect("each loop once");
                if side == Side::Shrink {
                    // traced with the band on the left; the region is the other side
                    pieces.reverse();
                    pieces.iter_mut().for_each(|p| *p = p.reversed());
                }
                OffsetLoop { pieces, parent: parents[old].map(|p| position[p]), hole: depths[old] % 2 == 1 }
            })
            .collect();
        Offset { distance, loops }
    }

    /// Which spans are nothing: a span whose ends are one point (within
    /// `COINCIDENT` of the distance), with the cell boundary between them
    /// going nowhere (a whole circle if it goes round). The end of a
    /// dropped span moves to its start, so the pieces either side still
    /// meet.
    fn drop_empty_spans(&self, traced: &mut trace::Traced, r: f64) -> Vec<bool> {
        let mut empty = vec![false; traced.spans.len()];
        let mut whole = vec![false; traced.spans.len()];
        let mut moved_to: Vec<u32> = (0..traced.crossings.len() as u32).collect();
        for (k, span) in traced.spans.iter().enumerate() {
            let (from, to) = (traced.crossings[span.from as usize].at, traced.crossings[span.to as usize].at);
            let near = coincident(r, from);
            if from.distance(to) > near {
                continue;
            }
            let centre = self.sites.at(span.site.index()).as_point();
            // Only an isolated point's cell can hold a whole circle: the
            // cell of a segment's endpoint lies in the half-plane beyond
            // that segment's perpendicular there, so a span of it sweeps at
            // most half a turn, and one whose ends meet sweeps nothing (the
            // cell of a straight or nearly straight joint is a line or a
            // wedge thinner than rounding).
            whole[k] = centre.is_some_and(|c| {
                !self.is_segment_endpoint(span.site)
                    && self.span_leaves(span, from, near)
                    && self.holds_the_circle(span.site, c, from)
            });
            let whole = whole[k];
            // (an arc's cell neither: it lies in the arc's cone, and a span
            // of it sweeps at most the arc's own sweep, less than a turn).
            // Any other span whose ends are one point is nothing, whether
            // they are equal, a few ulps apart (the trace past the joint of
            // a side and the arc continuing it along its tangent: a sliver
            // of the joint's cell) or the wrong way round: kept, a tiny arc
            // would be a whole circle to a program that prints its ends
            // rounded (G-code).
            if !whole {
                empty[k] = true;
                moved_to[span.to as usize] = span.from;
            }
        }
        // the end of a dropped span moves to its start (through chains of
        // them), so that the pieces on either side still meet
        for c in 0..moved_to.len() {
            let mut at = c as u32;
            for _ in 0..moved_to.len() {
                if moved_to[at as usize] == at {
                    break;
                }
                at = moved_to[at as usize];
            }
            traced.crossings[c].at = traced.crossings[at as usize].at;
        }
        // what the moves closed up is nothing too
        for (k, span) in traced.spans.iter().enumerate() {
            if !whole[k] && traced.crossings[span.from as usize].at == traced.crossings[span.to as usize].at {
                empty[k] = true;
            }
        }

        empty
    }

    /// The circle an offset piece at distance `r` in the cell of `site`
    /// runs along, from `from` to `to`, and which way round (with the band
    /// along the site on its left): around a point site counter-clockwise;
    /// around an arc's centre at its radius plus `r` on its convex side
    /// (counter-clockwise), minus `r` on its concave side (clockwise: the
    /// band lies outside that circle). `None` for a segment site.
    fn circle_of_span(&self, site: SiteId, from: Point, to: Point, r: f64) -> Option<(Point, f64, bool)> {
        match self.sites.at(site.index()) {
            Site::Point(centre) => Some((centre, r, true)),
            Site::Arc(arc) => {
                let c = arc.centre();
                // the ends are both at R + r or both at R - r from the centre
                let convex = c.distance(from) + c.distance(to) > 2.0 * arc.radius();
                Some(if convex { (c, arc.radius() + r, true) } else { (c, (arc.radius() - r).max(0.0), false) })
            }
            _ => None,
        }
    }

    /// The parent and depth of each loop. Each loop separates one region
    /// where the clearance is above `r` from one where it is below; those
    /// regions and loops form a tree, rooted at the region that reaches
    /// infinity, and a loop's parent is the loop through which its outer
    /// region is reached from the root.
    fn nest(&self, index: &OffsetIndex, r: f64, loops: &[(Vec<OffsetPiece>, u32, u32)]) -> (Vec<Option<usize>>, Vec<usize>) {
        let side = index.side;
        let threshold = side.threshold(r);
        let above = |leaf: u32| index.above.component(leaf as usize, |l| !side.in_band(l, threshold));
        let below = |leaf: u32| index.below.component(leaf as usize, |l| side.in_band(l, threshold));
        let mut region_of: HashMap<(bool, usize), usize> = HashMap::new();
        let mut region = |key: (bool, usize)| {
            let n = region_of.len();
            *region_of.entry(key).or_insert(n)
        };
        let root = match side {
            Side::Grow => region((true, above(self.finite_vertices as u32))),
            Side::Shrink => region((false, below(self.sites.len() as u32))),
        };
        let ends: Vec<[usize; 2]> =
            loops.iter().map(|(_, a, b)| [region((true, above(*a))), region((false, below(*b)))]).collect();
        let mut around: Vec<Vec<usize>> = vec![Vec::new(); region_of.len()];
        for (k, e) in ends.iter().enumerate() {
            around[e[0]].push(k);
            around[e[1]].push(k);
        }
        let mut parent = vec![None; loops.len()];
        let mut depth = vec![0usize; loops.len()];
        let mut placed = vec![false; loops.len()];
        let mut reached = vec![false; region_of.len()];
        // breadth first from the root region: (region, loop it was entered by)
        let mut queue = std::collections::VecDeque::from([(root, None::<usize>)]);
        reached[root] = true;
        while let Some((g, entered_by)) = queue.pop_front() {
            for &k in &around[g] {
                if placed[k] {
                    continue;
                }
                placed[k] = true;
                parent[k] = entered_by;
                depth[k] = entered_by.map_or(0, |p| depth[p] + 1);
                let inner = if ends[k][0] == g { ends[k][1] } else { ends[k][0] };
                if !reached[inner] {
                    reached[inner] = true;
                    queue.push_back((inner, Some(k)));
                }
            }
        }
        (parent, depth)
    }
}

impl Diagram {
    /// Turns the round joins at a chain's joint the short way where their
    /// ends are within 1e-6 of the radius and would go the long way round.
    /// Such a join passes a kink of the chain (two pieces meeting off
    /// tangent by that much); where the kink is a rounding of 1e-9 rad
    /// the side of it its point's cell took can be the other one, and the
    /// join's two crossings then come in the other order, a join all the
    /// way round less 1e-9 (a random circle cut at 8-decimal points: the
    /// area 0.28 short, every piece at its distance). The short way is the
    /// offset to 1e-9 of the radius. Never for a point that is no joint
    /// (a lone point's circle nearly closed by a tangency is a real turn).
    fn no_whole_turn_at_a_joint(&self, pieces: &mut [OffsetPiece]) {
        for piece in pieces.iter_mut() {
            let OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, site } = piece else { continue };
            let chord = from.distance(*to);
            if !(chord > 0.0 && chord <= 1e-6 * *radius) || !self.is_segment_endpoint(*site) {
                continue;
            }
            let turn = (from.x - centre.x) * (to.y - centre.y) - (from.y - centre.y) * (to.x - centre.x);
            if turn != 0.0 && (turn > 0.0) != *counter_clockwise {
                *counter_clockwise = !*counter_clockwise;
            }
        }
    }
}

/// Takes out of a loop the slits it runs into and back out of: a straight
/// piece followed by one along the same line the other way (a corridor of
/// the rest of the plane with no width at this distance, between two
/// parallel sides exactly `2 × distance` apart, that the loop would enter
/// and leave: LibreCAD's ed9 at 2.5, a line 5 above a rectangle's top).
/// The two become the piece from the first's start to the second's end,
/// of the site whose piece holds it, or nothing where that is one point;
/// around the loop's start too. No loop then passes a stretch twice, and
/// the polygons are valid for every reader.
fn cancel_slits(pieces: &mut Vec<OffsetPiece>, near: f64) {
    // the line piece from `a`'s start to `b`'s end, where `b` runs back
    // along `a`: `Some(None)` where nothing is left
    let merged = |a: &OffsetPiece, b: &OffsetPiece| -> Option<Option<OffsetPiece>> {
        let (OffsetPiece::Line { from, to, site }, OffsetPiece::Line { from: back, to: end, site: other }) = (*a, *b) else {
            return None;
        };
        let (u, v) = (Point::new(to.x - from.x, to.y - from.y), Point::new(end.x - back.x, end.y - back.y));
        let (lu, lv) = (u.x.hypot(u.y), v.x.hypot(v.y));
        let along_back = u.x * v.x + u.y * v.y < 0.0 && (u.x * v.y - u.y * v.x).abs() <= 1e-12 * lu * lv;
        if to != back || !along_back || !(lu > 0.0 && lv > 0.0) {
            return None;
        }
        if from.distance(end) <= near {
            return Some(None);
        }
        // the rest lies on the longer of the two
        let site = if lu >= lv { site } else { other };
        Some(Some(OffsetPiece::Line { from, to: end, site }))
    };
    let mut out: Vec<OffsetPiece> = Vec::with_capacity(pieces.len());
    for &p in pieces.iter() {
        let mut next = Some(p);
        while let (Some(q), Some(last)) = (next, out.last()) {
            match merged(last, &q) {
                Some(m) => {
                    out.pop();
                    next = m;
                }
                None => break,
            }
        }
        out.extend(next);
    }
    // around the start
    while out.len() >= 2 {
        let (last, first) = (out[out.len() - 1], out[0]);
        match merged(&last, &first) {
            Some(m) => {
                out.pop();
                out.remove(0);
                out.extend(m);
            }
            None => break,
        }
    }
    *pieces = out;
}

/// Whether a loop of straight pieces encloses nothing: its area within
/// rounding of zero (`near`, a few ulps of its coordinates, times its
/// length). It is the trace of a part of the region (or of the rest of the
/// plane) that is a line at this distance: a corridor between two sites
/// exactly `2 × distance` apart, traced along one side and back (LibreCAD's
/// mk3 at 2.5, two stubs 5 apart: a loop of two pieces of area 0, which
/// no reader of polygons takes).
fn a_line_both_ways(pieces: &[OffsetPiece], near: f64) -> bool {
    if pieces.is_empty() || !pieces.iter().all(|p| matches!(p, OffsetPiece::Line { .. })) {
        return false;
    }
    let o = pieces[0].from();
    let (mut twice_area, mut length) = (0.0, 0.0);
    for p in pieces {
        let (a, b) = (p.from(), p.to());
        twice_area += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
        length += a.distance(b);
    }
    twice_area.abs() <= 2.0 * near * length
}

/// Where parts of the region touch at one point, a loop may pass that
/// point twice (the crossings there were placed at the same point: a
/// tangency, or a vertex at the distance). Of the two ways to join the four
/// ends of the two passes without crossing, take the one that makes two
/// loops: exchange what follows the two spans ending there. (The ends
/// alternate in and out around the point, so the exchange never makes the
/// loops cross.)
fn split_at_touching_points(traced: &mut trace::Traced) {
    let n = traced.spans.len();
    let mut end_of = vec![u32::MAX; traced.crossings.len()];
    for (k, span) in traced.spans.iter().enumerate() {
        end_of[span.to as usize] = k as u32;
    }
    let key = |c: usize| {
        let p = traced.crossings[c].at;
        ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
    };
    let mut by_point: Vec<usize> = (0..traced.crossings.len()).collect();
    by_point.sort_unstable_by_key(|&c| key(c));
    let groups: Vec<Vec<u32>> = by_point
        .chunk_by(|&a, &b| key(a) == key(b))
        .filter(|g| g.len() > 1)
        .map(|g| g.iter().map(|&c| end_of[c]).filter(|&s| s != u32::MAX).collect())
        .collect();
    if groups.is_empty() {
        return;
    }
    // the loop of every span
    let mut loop_of = vec![u32::MAX; n];
    let mut loops = 0u32;
    let label = |from: u32, loop_of: &mut [u32], next: &[u32], id: u32| {
        let mut k = from;
        for _ in 0..n {
            loop_of[k as usize] = id;
            k = next[k as usize];
            if k as usize >= n || k == from {
                break;
            }
        }
    };
    for s in 0..n {
        if loop_of[s] == u32::MAX {
            label(s as u32, &mut loop_of, &traced.next, loops);
            loops += 1;
        }
    }
    for group in groups {
        for i in 0..group.len() {
            for j in i + 1..group.len() {
                let (a, b) = (group[i] as usize, group[j] as usize);
                if loop_of[a] == loop_of[b] {
                    traced.next.swap(a, b);
                    label(a as u32, &mut loop_of, &traced.next, loops);
                    loops += 1;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
