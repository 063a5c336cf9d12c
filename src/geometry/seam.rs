//! The two questions the parallel build (`construct/halves`) asks before it
//! keeps a cell built in one half: can a site left out of that half come
//! nearer to some point of the cell than the cell's own site.
//!
//! The sites left out of a half lie in a known box beyond a vertical line
//! (the split line moved by the halo's width). A point `p` of a cell is
//! safe from them when its disk (centre `p`, radius its clearance) stays on
//! this side of the box's near side. Along a Voronoi edge the disk's reach
//! in x (`p.x ± clearance`) is convex (a line, a hyperbola's or parabola's
//! branch, parametrised linearly), and from any point of a cell the reach
//! grows along the ray away from the site's nearest point, which stays in
//! the cell: so over a bounded cell the reach is largest at a vertex
//! ([`vertex_stays_short_of`]). An unbounded cell reaches infinitely far in
//! x, and there what matters is the hull: far along an edge to infinity the
//! disks become the half-plane beyond the supporting line of the edge's two
//! sites, and the box must lie strictly inside it
//! ([`edge_to_infinity_clears`]).
//!
//! Both answers are in floating point with a margin far above the rounding
//! of a stored vertex (positions and clearances are correctly rounded
//! solutions, to a few ulps): `false` is always allowed (the build then
//! takes a wider halo or one thread), `true` must never be wrong.

use crate::geometry::point::bounding_box;
use crate::geometry::{Point, Site};

/// The relative margin of both questions (and of `left_out`'s): of the
/// coordinates' magnitude where a value is rounded relative to it (a
/// stored vertex's position, a point's value along a direction), else of
/// the spread. About 45,000 ulps, far above the few ulps those roundings
/// take, and far below the spacing of any input whose width is more than
/// a ten-millionth of its distance from the origin: 1e-7 once, and the
/// halves of 200,000 points 8 km wide, 2^30 out (a spacing of 1.6e-8 of
/// the magnitude), failed every check and were built for nothing.
pub(crate) const MARGIN: f64 = 1e-11;

/// Whether the disk of a finite vertex (centre `position`, radius
/// `clearance`) stays strictly short of the vertical line `x = line`, on
/// the side `toward` (`1.0`: the line lies to the right, the left half's
/// question; `-1.0`: to the left).
pub(crate) fn vertex_stays_short_of(position: Point, clearance: f64, line: f64, toward: f64) -> bool {
    let reach = position.x * toward + clearance;
    let margin = MARGIN * (position.x.abs() + clearance + line.abs());
    reach.is_finite() && clearance >= 0.0 && reach + margin < line * toward
}

/// Whether every point of `outside` lies strictly inside the supporting
/// line of an edge to infinity: the line with outward unit normal
/// `direction` (the stored direction of a vertex at infinity) touching the
/// edge's `sites` (each given by its points: a point site once, a segment
/// by its ends).
pub(crate) fn edge_to_infinity_clears(direction: Point, sites: &[Point], outside: &[Point]) -> bool {
    let along = |p: &Point| p.x * direction.x + p.y * direction.y;
    let support = sites.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
    let beyond = outside.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
    let size = outside.iter().chain(sites).map(|p| p.x.abs() + p.y.abs()).fold(0.0, f64::max);
    support.is_finite() && !beyond.is_nan() && beyond + MARGIN * size < support
}

/// The extreme points of a set in eight directions (mergeable, so that
/// two threads can each take half the set).
#[derive(Clone, Copy)]
pub(crate) struct Extremes {
    best: [(f64, Point); 8],
}

/// The eight directions of [`Extremes`], counter-clockwise.
const EIGHT: [(f64, f64); 8] =
    [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (-1.0, -1.0), (0.0, -1.0), (1.0, -1.0)];

impl Extremes {
    /// The extremes of no point (`add` them one by one).
    pub(crate) const NONE: Extremes = Extremes { best: [(f64::NEG_INFINITY, Point::new(f64::NAN, f64::NAN)); 8] };

    /// The extremes of `points`: those [`add`](Self::add) gives, one by
    /// one, found faster by blocks: each point's values along the
    /// directions taken without a branch, and a block added point by point
    /// only where it holds a new extreme (on most input, a few blocks at
    /// the start).
    pub(crate) fn of(points: &[Point]) -> Extremes {
        let mut extremes = Extremes::NONE;
        for block in points.chunks(64) {
            let mut top = [f64::NEG_INFINITY; 8];
            for p in block {
                for (t, &(dx, dy)) in top.iter_mut().zip(&EIGHT) {
                    let v = p.x * dx + p.y * dy;
                    *t = if v > *t { v } else { *t };
                }
            }
            // (a NaN point is no extreme, as in `add`)
            if top.iter().zip(&extremes.best).any(|(t, b)| *t > b.0) {
                block.iter().for_each(|&p| extremes.add(p));
            }
        }
        extremes
    }

    /// The extremes of the set with `p` added.
    #[inline]
    pub(crate) fn add(&mut self, p: Point) {
        for (best, &(dx, dy)) in self.best.iter_mut().zip(&EIGHT) {
            let v = p.x * dx + p.y * dy;
            if v > best.0 {
                *best = (v, p);
            }
        }
    }

    /// The extremes of the union of the two sets.
    pub(crate) fn merge(self, other: Extremes) -> Extremes {
        let mut best = self.best;
        for (b, o) in best.iter_mut().zip(other.best) {
            if o.0 > b.0 {
                *b = o;
            }
        }
        Extremes { best }
    }

    /// The least and the greatest x of the set (`∞` and `-∞` when empty).
    pub(crate) fn x_range(&self) -> (f64, f64) {
        (-self.best[4].0, self.best[0].0)
    }

    /// The points of the set (all of `points`) that may be vertices of
    /// their convex hull: all but those strictly inside the octagon of the
    /// extremes, then strictly inside the polygon of those left's extremes
    /// in [`FINE`] directions, with a margin (a point kept is never wrong).
    /// What [`edge_to_infinity_clears`] needs of the sites left out, in a
    /// few points where they are many.
    pub(crate) fn hull_candidates(&self, points: impl IntoIterator<Item = Point>) -> Vec<Point> {
        let octagon = self.octagon();
        let coarse: Vec<Point> = points.into_iter().filter(|&p| octagon.may_hold_on_its_boundary(p)).collect();
        let fine = self.fine_polygon(&coarse);
        coarse.into_iter().filter(|&p| fine.may_hold_on_its_boundary(p)).collect()
    }

    /// The polygon of `candidates`' extremes in [`FINE`] directions, with
    /// the octagon's margin: inscribed in the set's hull when `candidates`
    /// hold every point of the set outside the octagon (no point strictly
    /// inside it is extreme in any direction). Where the octagon is a poor
    /// fit (clusters near the hull, a curve's points), it keeps a fraction
    /// of what the octagon keeps (a third on the unit test's curve).
    pub(crate) fn fine_polygon(&self, candidates: &[Point]) -> Polygon {
        let directions: Vec<(f64, f64)> =
            (0..FINE).map(|k| std::f64::consts::TAU * k as f64 / FINE as f64).map(|a| (a.cos(), a.sin())).collect();
        let mut best = vec![(f64::NEG_INFINITY, Point::new(f64::NAN, f64::NAN)); FINE];
        for &p in candidates {
            for (b, &(dx, dy)) in best.iter_mut().zip(&directions) {
                let v = p.x * dx + p.y * dy;
                if v > b.0 {
                    *b = (v, p);
                }
            }
        }
        Polygon::through(best.iter().map(|b| b.1), self.edge_margin())
    }

    /// The octagon of the extremes, its edges worked out once.
    pub(crate) fn octagon(&self) -> Polygon {
        Polygon::through(self.best.iter().map(|b| b.1), self.edge_margin())
    }

    /// The margin of a [`Polygon`]'s edges through points of the set,
    /// asked of points of the set: `MARGIN` of the square of its spread
    /// (its bounding box's width and height together). An edge's value at
    /// a point is a cross product of differences of coordinates of the
    /// set, each rounded to half an ulp of itself (not of the coordinates:
    /// a difference is exact or rounded relative to its result), so its
    /// rounding is a few ulps of the spread squared, whatever the
    /// coordinates' magnitude: points a million wide 2^30 out are asked
    /// at the margin of the same points at the origin. At least [`TINY`]
    /// (far above the absolute rounding of subnormal products), and
    /// infinite for an empty set.
    fn edge_margin(&self) -> f64 {
        let (least_x, greatest_x) = self.x_range();
        let spread = (greatest_x - least_x) + (self.best[2].0 + self.best[6].0);
        if spread.is_finite() {
            (MARGIN * spread * spread).max(TINY)
        } else {
            f64::INFINITY
        }
    }
}

/// How many directions [`Extremes::fine_polygon`] takes.
const FINE: usize = 64;

/// A convex polygon inscribed in a set's hull, through the set's extremes
/// in directions counter-clockwise: its edges from a corner, along
/// `(dx, dy)`, the degenerate ones left out.
pub(crate) struct Polygon {
    edges: Vec<(Point, f64, f64)>,
    margin: f64,
    /// Its points strictly inside every edge by twice the margin: no
    /// vertex of the hull.
    deep: InnerBox,
}

impl Polygon {
    /// The polygon through `corners`, counter-clockwise (repeated or not
    /// finite ones skipped).
    fn through(corners: impl Iterator<Item = Point> + Clone, margin: f64) -> Polygon {
        let next = corners.clone().cycle().skip(1);
        let edges: Vec<(Point, f64, f64)> = corners
            .zip(next)
            .filter(|(a, b)| a != b && a.x.is_finite() && b.x.is_finite())
            .map(|(a, b)| (a, b.x - a.x, b.y - a.y))
            .collect();
        let (lo, hi) = bounding_box(edges.iter().map(|e| e.0));
        let inside_every_edge = |c: Point| edges.iter().all(|&(a, dx, dy)| dx * (c.y - a.y) - dy * (c.x - a.x) > 2.0 * margin);
        // (the margin far above the rounding of an edge's value: see `InnerBox`)
        let deep = if edges.len() >= 3 && margin.is_finite() && margin > TINY {
            InnerBox::within(lo, hi, inside_every_edge)
        } else {
            InnerBox::EMPTY
        };
        Polygon { edges, margin, deep }
    }

    /// Whether `p` (of the set) may be a vertex of its convex hull: it is
    /// not strictly inside every edge by the margin (or there are fewer
    /// than three edges).
    #[inline]
    pub(crate) fn may_hold_on_its_boundary(&self, p: Point) -> bool {
        // (most points are deep inside: a box answers for them)
        !self.deep.holds(p) && self.asked_of_every_edge(p)
    }

    /// [`may_hold_on_its_boundary`](Self::may_hold_on_its_boundary)
    /// without the box.
    fn asked_of_every_edge(&self, p: Point) -> bool {
        // (every edge asked, without a branch)
        let outside_an_edge =
            self.edges.iter().fold(false, |out, &(a, dx, dy)| out | (dx * (p.y - a.y) - dy * (p.x - a.x) <= self.margin));
        self.edges.len() < 3 || outside_an_edge
    }
}

/// The least margin [`InnerBox`] builds on: far above the absolute
/// rounding of subnormal numbers.
const TINY: f64 = 1e-280;

/// A box whose points all answer a test alike, found once, so that the
/// test is asked only of the few points outside it (most points of a
/// large set lie deep inside its hull, far from the boundary both
/// [`Polygon::may_hold_on_its_boundary`] and [`NearSides::holds`] look
/// for).
///
/// Both tests are linear in the point (a value along a direction, from a
/// side or an edge, against a threshold), so a box passes one when its four
/// corners do: its points are averages of them. The corners are asked with
/// twice the test's margin, and the margins (`MARGIN` of the set's size,
/// or of its spread squared for a polygon's edges) are far above the
/// rounding of the values (a few ulps of those), so a point strictly inside the box
/// passes the test as computed, not only exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct InnerBox {
    lo: Point,
    hi: Point,
}

impl InnerBox {
    /// The box of no point.
    pub(crate) const EMPTY: InnerBox =
        InnerBox { lo: Point::new(f64::INFINITY, f64::INFINITY), hi: Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY) };

    /// Whether `p` lies strictly inside (`false` for NaN).
    #[inline]
    pub(crate) fn holds(&self, p: Point) -> bool {
        (p.x > self.lo.x) & (p.x < self.hi.x) & (p.y > self.lo.y) & (p.y < self.hi.y)
    }

    /// The box `lo..hi` shrunk about its centre as little as bisection
    /// finds with all four corners passing `deep` (a convex region holding
    /// the centre holds the corners up to some factor, and none beyond);
    /// empty where the centre fails or anything is not finite.
    fn within(lo: Point, hi: Point, deep: impl Fn(Point) -> bool) -> InnerBox {
        let centre = Point::new(0.5 * lo.x + 0.5 * hi.x, 0.5 * lo.y + 0.5 * hi.y);
        let (half_x, half_y) = (0.5 * hi.x - 0.5 * lo.x, 0.5 * hi.y - 0.5 * lo.y);
        if !(centre.x.is_finite() && centre.y.is_finite() && half_x.is_finite() && half_y.is_finite()) {
            return InnerBox::EMPTY;
        }
        let shrunk = |t: f64| InnerBox {
            lo: Point::new(centre.x - t * half_x, centre.y - t * half_y),
            hi: Point::new(centre.x + t * half_x, centre.y + t * half_y),
        };
        let passes = |t: f64| {
            let b = shrunk(t);
            [b.lo, b.hi, Point::new(b.lo.x, b.hi.y), Point::new(b.hi.x, b.lo.y)].into_iter().all(&deep)
        };
        if !passes(0.0) {
            return InnerBox::EMPTY;
        }
        let (mut good, mut bad) = (0.0, 1.0);
        if passes(bad) {
            good = bad;
        } else {
            for _ in 0..20 {
                let t = 0.5 * (good + bad);
                if passes(t) {
                    good = t;
                } else {
                    bad = t;
                }
            }
        }
        // (the same corners as asked: `shrunk` is a pure function of `t`)
        shrunk(good)
    }
}

/// [`Enclosure::near_a_side`] for one band ([`Enclosure::near_sides`]).
pub(crate) struct NearSides<'a> {
    enclosure: &'a Enclosure,
    band: f64,
    /// Its points are near no side.
    deep: InnerBox,
}

impl NearSides<'_> {
    /// Whether `p` lies within the band of a side (as
    /// [`Enclosure::near_a_side`] answers).
    #[inline]
    pub(crate) fn holds(&self, p: Point) -> bool {
        !self.deep.holds(p) && self.enclosure.near_a_side(p, self.band)
    }
}

/// The directions of [`Enclosure`]'s sides: sixteen, evenly spaced.
const SIDES: usize = 16;

/// A convex polygon round a set of points: the half-planes of their
/// extremes in sixteen directions. A point of the set within `band` of a
/// side is near the boundary; the others lie inside every side moved in by
/// `band`, which a disk beyond one of those moved sides cannot reach.
pub(crate) struct Enclosure {
    support: [f64; SIDES],
    /// A margin above the rounding of a point's value along a direction.
    slack: f64,
}

impl Enclosure {
    pub(crate) fn of(points: &[Point]) -> Enclosure {
        let mut support = [f64::NEG_INFINITY; SIDES];
        let mut size: f64 = 0.0;
        // (comparisons, not `f64::max`: a NaN is skipped alike, and
        // without its checks the sixteen sides run side by side)
        for &p in points {
            let l1 = p.x.abs() + p.y.abs();
            size = if l1 > size { l1 } else { size };
            for (k, s) in support.iter_mut().enumerate() {
                let v = along(p, k);
                *s = if v > *s { v } else { *s };
            }
        }
        Enclosure { support, slack: MARGIN * size }
    }

    /// The margin above the rounding of a point's value along a side
    /// (`MARGIN` of the set's magnitude).
    pub(crate) fn slack(&self) -> f64 {
        self.slack
    }

    /// The enclosure of the union of the two sets.
    pub(crate) fn merge(self, other: Enclosure) -> Enclosure {
        let mut support = self.support;
        support.iter_mut().zip(other.support).for_each(|(s, o)| *s = s.max(o));
        Enclosure { support, slack: self.slack.max(other.slack) }
    }

    /// The set's bounding box (the sides along the axes): its lower-left
    /// and upper-right corners.
    pub(crate) fn bounding_box(&self) -> (Point, Point) {
        let s = &self.support;
        (Point::new(-s[SIDES / 2], -s[3 * SIDES / 4]), Point::new(s[0], s[SIDES / 4]))
    }

    /// The area of the set's bounding box (the sides along the axes).
    pub(crate) fn box_area(&self) -> f64 {
        let s = &self.support;
        (s[0] + s[SIDES / 2]) * (s[SIDES / 4] + s[3 * SIDES / 4])
    }

    /// The depth from a side of the set's bounding box that holds as many
    /// of `sample` (points of the set at an even stride) as a strip
    /// `depth` deep along that side would at their mean density over the
    /// box, at the deepest of the four sides, and `depth` at least. About
    /// `depth` where the points spread evenly; deeper where they thin out
    /// toward a side, as segments' ends sticking out of a dense region
    /// do, to the depth of the segments' length (the circles through
    /// the sparse points there dip that deep into the set).
    pub(crate) fn depth_holding(&self, sample: &[Point], depth: f64) -> f64 {
        let s = &self.support;
        let (width, height) = (s[0] + s[SIDES / 2], s[SIDES / 4] + s[3 * SIDES / 4]);
        let area = width * height;
        let mut deepest = depth;
        if !(area > 0.0 && area.is_finite() && depth >= 0.0) {
            return deepest;
        }
        let mut depths = Vec::with_capacity(sample.len());
        for (k, side_length) in [(0, height), (SIDES / 4, width), (SIDES / 2, height), (3 * SIDES / 4, width)] {
            // (how many an even spread puts within `depth` of this side)
            let expected = sample.len() as f64 * (depth * side_length / area);
            if !(expected >= 1.0 && expected < sample.len() as f64) {
                continue;
            }
            depths.clear();
            depths.extend(sample.iter().map(|&p| s[k] - along(p, k)));
            let (_, &mut d, _) = depths.select_nth_unstable_by(expected as usize, f64::total_cmp);
            deepest = if d > deepest { d } else { deepest };
        }
        deepest
    }

    /// [`near_a_side`](Self::near_a_side) for one `band`, asked of many
    /// points: those deep inside are answered by a box.
    pub(crate) fn near_sides(&self, band: f64) -> NearSides<'_> {
        let s = &self.support;
        let (lo, hi) = self.bounding_box();
        // (inside every side moved in by the band, by twice the slack; the
        // slack far above the rounding of a value along a side: see `InnerBox`)
        let short_of_every_side = |c: Point| (0..SIDES).all(|k| along(c, k) <= (s[k] - band - self.slack) - self.slack);
        let deep = if self.slack.is_finite() && self.slack > TINY {
            InnerBox::within(lo, hi, short_of_every_side)
        } else {
            InnerBox::EMPTY
        };
        NearSides { enclosure: self, band, deep }
    }

    /// Whether `p` lies within `band` of a side (or near enough that
    /// rounding cannot tell): such points are held by both halves.
    pub(crate) fn near_a_side(&self, p: Point, band: f64) -> bool {
        // (every side asked, without a branch: most points are near none)
        (0..SIDES).fold(false, |near, k| near | (along(p, k) > self.support[k] - band - self.slack))
    }

    /// Whether the disk of a finite vertex (centre `position`, radius
    /// `clearance`) lies wholly beyond some side moved in by `band`: then
    /// it holds no point that is not [`near_a_side`](Self::near_a_side).
    pub(crate) fn vertex_beyond_a_side(&self, position: Point, clearance: f64, band: f64) -> bool {
        let margin = self.vertex_margin(clearance);
        clearance >= 0.0
            && clearance.is_finite()
            && (0..SIDES).any(|k| along(position, k) - clearance > self.support[k] - band + margin)
    }

    /// The margin of a vertex's disk of radius `clearance` against the
    /// sides: far above the rounding of the support, of a point along a
    /// side, and of the disk's stored centre and radius.
    fn vertex_margin(&self, clearance: f64) -> f64 {
        self.slack + MARGIN * clearance.min(1.0) + 1e-12 * clearance
    }

    /// A convex polygon (corners counter-clockwise; none when it is empty)
    /// that holds every point near no side moved in by `band` (every
    /// point [`near_a_side`](Self::near_a_side) does not take): the
    /// sides' half-planes moved in by `band`, intersected, and let out by
    /// the slack, far more than the rounding of the clipping. `None` where
    /// a side or a corner is not finite (then no disk is taken to miss it).
    pub(crate) fn inside(&self, band: f64) -> Option<Vec<Point>> {
        let limit = |k: usize| self.support[k] - band;
        if !(0..SIDES).all(|k| limit(k).is_finite()) || !self.slack.is_finite() {
            return None;
        }
        let (right, top, left, bottom) = (limit(0), limit(SIDES / 4), -limit(SIDES / 2), -limit(3 * SIDES / 4));
        if !(left <= right && bottom <= top) {
            return Some(Vec::new());
        }
        let mut corners =
            vec![Point::new(left, bottom), Point::new(right, bottom), Point::new(right, top), Point::new(left, top)];
        for k in (0..SIDES).filter(|k| k % (SIDES / 4) != 0) {
            // (Sutherland and Hodgman: the corners within the side, and
            // where the polygon's edges cross it)
            let over = |p: Point| along(p, k) - limit(k);
            let mut clipped = Vec::with_capacity(corners.len() + 1);
            for (i, &a) in corners.iter().enumerate() {
                let b = corners[(i + 1) % corners.len()];
                let (da, db) = (over(a), over(b));
                if da <= 0.0 {
                    clipped.push(a);
                }
                if (da <= 0.0) != (db <= 0.0) {
                    let t = da / (da - db);
                    clipped.push(Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)));
                }
            }
            corners = clipped;
            if corners.is_empty() {
                break;
            }
        }
        corners.iter().all(|p| p.x.is_finite() && p.y.is_finite()).then_some(corners)
    }

    /// Whether the disk of a finite vertex (centre `position`, radius
    /// `clearance`) misses the polygon `inside` (from
    /// [`inside`](Self::inside), for the band the points near a side were
    /// taken with): then every point in it is near a side. It holds where
    /// [`vertex_beyond_a_side`](Self::vertex_beyond_a_side) does, and also
    /// for the disks that reach beyond two sides at once (round a corner
    /// of the input, where no single side has them all).
    pub(crate) fn vertex_misses(&self, inside: Option<&[Point]>, position: Point, clearance: f64) -> bool {
        let finite = clearance >= 0.0 && clearance.is_finite() && position.x.is_finite() && position.y.is_finite();
        let Some(inside) = inside.filter(|_| finite) else {
            return false;
        };
        if inside.is_empty() {
            return true; // (every point is near a side)
        }
        // The distance from the centre to the polygon, if outside it: the
        // centre to the right of an edge is outside (a point is taken for
        // the polygon's whole when it has fewer than three corners).
        let mut outside = inside.len() < 3;
        let mut nearest = f64::INFINITY;
        for (i, &a) in inside.iter().enumerate() {
            let b = inside[(i + 1) % inside.len()];
            outside |= (b.x - a.x) * (position.y - a.y) - (b.y - a.y) * (position.x - a.x) < 0.0;
            nearest = nearest.min(Site::Segment { a, b }.distance(position));
        }
        outside && nearest > clearance + self.vertex_margin(clearance)
    }
}

/// `p` along the `k`-th direction of the sides.
#[inline]
fn along(p: Point, k: usize) -> f64 {
    let (cos, sin) = DIRECTIONS[k];
    p.x * cos + p.y * sin
}

/// The sides' directions, `(cos, sin)` of `k` sixteenths of a turn.
const DIRECTIONS: [(f64, f64); SIDES] = {
    // cos and sin of multiples of 22.5 degrees
    const C1: f64 = 0.923_879_532_511_286_7;
    const C2: f64 = std::f64::consts::FRAC_1_SQRT_2;
    const C3: f64 = 0.382_683_432_365_089_8;
    [
        (1.0, 0.0),
        (C1, C3),
        (C2, C2),
        (C3, C1),
        (0.0, 1.0),
        (-C3, C1),
        (-C2, C2),
        (-C1, C3),
        (-1.0, 0.0),
        (-C1, -C3),
        (-C2, -C2),
        (-C3, -C1),
        (0.0, -1.0),
        (C3, -C1),
        (C2, -C2),
        (C1, -C3),
    ]
};

#[cfg(test)]
mod tests {
    use super::*;

    /// `n` uniform random points in the unit square, and `n` in the unit disk.
    fn square_and_disk(rng: &mut crate::splitmix::SplitMix64, n: usize) -> (Vec<Point>, Vec<Point>) {
        let square = (0..n).map(|_| Point::new(rng.unit(), rng.unit())).collect();
        let disk = (0..n)
            .map(|_| {
                let (a, r) = (rng.unit() * std::f64::consts::TAU, rng.unit().sqrt());
                Point::new(r * a.cos(), r * a.sin())
            })
            .collect();
        (square, disk)
    }

    /// `n` points of the integer lattice, `columns` a row.
    fn lattice(n: usize, columns: usize) -> Vec<Point> {
        (0..n).map(|i| Point::new((i % columns) as f64, (i / columns) as f64)).collect()
    }

    /// `points` moved 2^30 out, right and down.
    fn far_out(points: &[Point]) -> Vec<Point> {
        points.iter().map(|p| Point::new(p.x + 2f64.powi(30), p.y - 2f64.powi(30))).collect()
    }

    /// `depth_holding`: about the depth asked where the points spread
    /// evenly (a square, a lattice, far out too), at least the depth asked
    /// where a side is thinly held (a disk: its box's sides touch it at one
    /// point each), and as deep as the thin fringe below a dense square
    /// where its points thin out toward the bottom (as far as a tenth of
    /// the square, as segments' ends sticking out of it do).
    #[test]
    fn the_rim_is_as_deep_as_the_input_thins() {
        let mut rng = crate::splitmix::SplitMix64(12);
        let (square, disk) = square_and_disk(&mut rng, 30_000);
        let (lattice, far) = (lattice(30_000, 200), far_out(&square));
        let spacing = |points: &[Point]| (Enclosure::of(points).box_area() / points.len() as f64).sqrt();
        for (name, points) in [("square", &square), ("lattice", &lattice), ("far", &far)] {
            let depth = 3.0 * spacing(points);
            let rim = Enclosure::of(points).depth_holding(points, depth);
            assert!(rim >= depth && rim < 1.5 * depth, "{name}: {rim} for {depth}");
        }
        let depth = 3.0 * spacing(&disk);
        assert!(Enclosure::of(&disk).depth_holding(&disk, depth) >= depth);
        // below the square, a fringe a tenth deep whose density falls from
        // the square's to none
        let mut fringed = square.clone();
        fringed.extend((0..1_500).map(|_| Point::new(rng.unit(), -0.1 * (1.0 - rng.unit().sqrt()))));
        let depth = 3.0 * spacing(&fringed);
        let rim = Enclosure::of(&fringed).depth_holding(&fringed, depth);
        assert!(rim > 2.0 * depth && rim < 0.1 + depth, "fringed: {rim} for {depth}");
        // nothing to measure: the depth asked
        assert_eq!(Enclosure::of(&square).depth_holding(&[], depth), depth);
        assert_eq!(Enclosure::of(&[Point::new(1.0, 2.0)]).depth_holding(&[Point::new(1.0, 2.0)], depth), depth);
    }

    /// `inside` holds every point not near a side, and a disk that
    /// `vertex_misses` passes holds none of them: on a square, a disk and
    /// a lattice (corners, straight sides, ties), far from the origin too,
    /// with disks round the corners and along the sides, nearly touching.
    #[test]
    fn a_disk_that_misses_the_inside_holds_only_points_near_a_side() {
        let mut rng = crate::splitmix::SplitMix64(9);
        let (square, disk) = square_and_disk(&mut rng, 4000);
        let (lattice, far) = (lattice(3000, 60), far_out(&square));
        let (mut passed, mut failed) = (0, 0);
        for points in [square, disk, lattice, far] {
            let enclosure = Enclosure::of(&points);
            let (lo, hi) = bounding_box(points.iter().copied());
            let size = (hi.x - lo.x).max(hi.y - lo.y);
            for band in [0.01 * size, 0.05 * size, 0.3 * size] {
                let inside = enclosure.inside(band).expect("finite sides");
                let not_near: Vec<Point> = points.iter().copied().filter(|&p| !enclosure.near_a_side(p, band)).collect();
                // every such point is in the polygon (all its edges keep it on their left)
                for p in &not_near {
                    let n = inside.len();
                    assert!(n >= 3);
                    assert!((0..n).all(|i| {
                        let (a, b) = (inside[i], inside[(i + 1) % n]);
                        (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) >= 0.0
                    }));
                }
                for _ in 0..3000 {
                    // a disk through a random point of the set's boundary region, out to the side
                    let a = rng.unit() * std::f64::consts::TAU;
                    let r = size * [0.01, 0.1, 1.0, 30.0][(rng.unit() * 4.0) as usize];
                    let centre = Point::new(
                        (lo.x + hi.x) / 2.0 + a.cos() * (0.5 * size + r * (0.9 + 0.2 * rng.unit())),
                        (lo.y + hi.y) / 2.0 + a.sin() * (0.5 * size + r * (0.9 + 0.2 * rng.unit())),
                    );
                    let nearest = not_near
                        .iter()
                        .map(|p| ((p.x - centre.x).powi(2) + (p.y - centre.y).powi(2)).sqrt())
                        .fold(f64::INFINITY, f64::min);
                    if enclosure.vertex_misses(Some(&inside), centre, r) {
                        assert!(nearest > r, "a disk passed with a point not near a side in it");
                        passed += 1;
                    } else {
                        failed += 1;
                    }
                    // a side's own test passes only disks the polygon's passes
                    if enclosure.vertex_beyond_a_side(centre, r, band) {
                        assert!(enclosure.vertex_misses(Some(&inside), centre, r));
                    }
                }
            }
        }
        assert!(passed > 1000 && failed > 1000, "{passed} passed, {failed} failed: disks not on both sides");
        // sides beyond the range of f64: nothing known, and no disk passes
        let huge = Enclosure::of(&[Point::new(f64::MAX, f64::MAX), Point::new(-f64::MAX, -f64::MAX), Point::new(0.0, 1.0)]);
        assert!(huge.inside(1.0).is_none());
        assert!(!huge.vertex_misses(None, Point::new(0.0, 1e300), 1.0));
    }

    #[test]
    fn extremes_by_blocks_are_those_point_by_point() {
        let mut rng = crate::splitmix::SplitMix64(5);
        let uniform: Vec<Point> = (0..10_000).map(|_| Point::new(rng.unit() - 0.5, rng.unit() * 1e6)).collect();
        let mut sorted = uniform.clone();
        sorted.sort_by(|a, b| a.x.total_cmp(&b.x)); // (a new extreme in every block)
        let lattice: Vec<Point> = (0..5000).map(|i| Point::new((i % 70) as f64, (i / 70) as f64)).collect(); // ties
        let mut with_nan = uniform[..300].to_vec();
        with_nan[100] = Point::new(f64::NAN, 1e9);
        for points in [uniform, sorted, lattice, with_nan, Vec::new(), vec![Point::new(-0.0, 0.0)]] {
            let mut a = Extremes::NONE;
            points.iter().for_each(|&p| a.add(p));
            let b = Extremes::of(&points);
            let bits = |e: &Extremes| e.best.map(|(v, p)| [v.to_bits(), p.x.to_bits(), p.y.to_bits()]);
            assert_eq!(bits(&a), bits(&b));
        }
    }

    #[test]
    fn a_disk_reaching_the_line_is_not_short_of_it() {
        let c = Point::new(0.0, 0.0);
        assert!(vertex_stays_short_of(c, 0.9, 1.0, 1.0));
        assert!(!vertex_stays_short_of(c, 1.0, 1.0, 1.0));
        assert!(!vertex_stays_short_of(c, 1.1, 1.0, 1.0));
        assert!(vertex_stays_short_of(c, 0.9, -1.0, -1.0));
        assert!(!vertex_stays_short_of(c, 0.9, -0.5, -1.0));
        assert!(!vertex_stays_short_of(c, f64::INFINITY, 1.0, 1.0));
        assert!(!vertex_stays_short_of(c, f64::NAN, 1.0, 1.0));
    }

    #[test]
    fn points_beyond_or_on_the_hull_line_are_not_clear() {
        // the edge to infinity of (0,0) and (1,0) going down: the hull line y = 0
        let sites = [Point::new(0.0, 0.0), Point::new(1.0, 0.0)];
        let down = Point::new(0.0, -1.0);
        let above = [Point::new(5.0, 0.5), Point::new(9.0, 3.0)];
        assert!(edge_to_infinity_clears(down, &sites, &above));
        assert!(edge_to_infinity_clears(down, &sites, &[]));
        assert!(!edge_to_infinity_clears(down, &sites, &[above[0], Point::new(5.0, 0.0)]));
        assert!(!edge_to_infinity_clears(down, &sites, &[Point::new(5.0, -0.5), above[1]]));
    }

    #[test]
    fn a_disk_beyond_a_side_moved_in_misses_the_points_not_near_one() {
        let points: Vec<Point> =
            (0..11).flat_map(|i| (0..11).map(move |j| Point::new(i as f64 / 10.0, j as f64 / 10.0))).collect();
        let e = Enclosure::of(&points);
        assert_eq!(e.box_area(), 1.0);
        assert!(e.near_a_side(Point::new(0.5, 0.95), 0.1));
        assert!(!e.near_a_side(Point::new(0.5, 0.85), 0.1));
        // a huge circle through three points along the top
        assert!(e.vertex_beyond_a_side(Point::new(0.5, 101.0), 100.05, 0.1));
        assert!(!e.vertex_beyond_a_side(Point::new(0.5, 101.0), 100.15, 0.1));
        assert!(!e.vertex_beyond_a_side(Point::new(0.5, 0.5), 0.1, 0.1));
    }

    #[test]
    fn hull_candidates_keep_every_hull_vertex_and_drop_the_inside() {
        let mut points = vec![Point::new(0.0, 0.0), Point::new(4.0, 0.0), Point::new(4.0, 4.0), Point::new(0.0, 4.0)];
        points.extend((1..4).flat_map(|i| (1..4).map(move |j| Point::new(i as f64, j as f64))));
        points.push(Point::new(2.0, 0.0)); // on the hull, not a vertex: may stay
        let kept = Extremes::of(&points).hull_candidates(points.iter().copied());
        for corner in &points[..4] {
            assert!(kept.contains(corner));
        }
        assert!(!kept.contains(&Point::new(2.0, 2.0)));
        // for every direction, the kept points reach as far as all of them
        for k in 0..64 {
            let a = k as f64 * std::f64::consts::TAU / 64.0;
            let along = |p: &Point| p.x * a.cos() + p.y * a.sin();
            let all = points.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            let some = kept.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            assert_eq!(all, some);
        }
    }

    /// Points along a wiggly curve, where the octagon fits the hull poorly
    /// and keeps more: the finer polygon keeps every hull vertex
    /// (each point that is extreme in some direction, found by brute
    /// force over 720 directions) and under half of what the octagon keeps.
    #[test]
    fn hull_candidates_of_a_curve_are_few_and_keep_every_extreme() {
        let points: Vec<Point> = (0..20_000)
            .map(|i| {
                let t = f64::from(i) / 100.0;
                Point::new(10.0 * t + 5.0 * (3.1 * t).sin(), 300.0 * (0.7 * t).sin() + 20.0 * (5.3 * t).cos())
            })
            .collect();
        let extremes = Extremes::of(&points);
        let octagon = extremes.octagon();
        let coarse = points.iter().filter(|&&p| octagon.may_hold_on_its_boundary(p)).count();
        let kept = extremes.hull_candidates(points.iter().copied());
        assert!(kept.len() * 2 < coarse, "{} of {coarse}", kept.len());
        for k in 0..720 {
            let a = f64::from(k) * std::f64::consts::TAU / 720.0;
            let along = |p: &Point| p.x * a.cos() + p.y * a.sin();
            let all = points.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            let some = kept.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            assert_eq!(all, some, "direction {k}");
        }
    }

    /// The margin of the hull's polygons follows the points' spread, not
    /// their magnitude: integer points a million wide keep the same
    /// candidates 2^30 out as at the origin (the differences, and so the
    /// edges' values, are exact in both), a few hundred of 20,000, every
    /// vertex of the hull among them. It once followed the magnitude, and
    /// 2^30 out kept every point.
    #[test]
    fn hull_candidates_far_out_are_those_at_the_origin() {
        let mut rng = crate::splitmix::SplitMix64(29);
        let points: Vec<Point> =
            (0..20_000).map(|_| Point::new((rng.unit() * 1e6).floor(), (rng.unit() * 1e6).floor())).collect();
        let far = far_out(&points);
        let kept = Extremes::of(&points).hull_candidates(points.iter().copied());
        let kept_far = Extremes::of(&far).hull_candidates(far.iter().copied());
        assert!(kept.len() < 1000, "{} kept", kept.len());
        assert_eq!(far_out(&kept), kept_far);
        for k in 0..720 {
            let a = f64::from(k) * std::f64::consts::TAU / 720.0;
            let along = |p: &Point| p.x * a.cos() + p.y * a.sin();
            let all = points.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            let some = kept.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
            assert_eq!(all, some, "direction {k}");
        }
    }

    /// `x` moved by `ulps` units in the last place (toward +∞ for positive
    /// `ulps`), through zero.
    fn nudged(x: f64, ulps: i64) -> f64 {
        let mut y = x;
        for _ in 0..ulps.unsigned_abs() {
            let up = ulps > 0;
            y = if y == 0.0 {
                if up {
                    f64::from_bits(1)
                } else {
                    -f64::from_bits(1)
                }
            } else if (y > 0.0) == up {
                f64::from_bits(y.to_bits() + 1)
            } else {
                f64::from_bits(y.to_bits() - 1)
            };
        }
        y
    }

    /// The boxes answer as the whole tests do: for the octagon and the
    /// fine polygon of a set's extremes and for the enclosure's sides at
    /// several bands, on the set's points, random points round it, and
    /// points on, just inside and just outside each box's edges and
    /// corners; on a square, a disk, a lattice, a sliver, points on a line,
    /// one point, far from the origin, and tiny and huge magnitudes. On the
    /// square the boxes hold most points (the quick answer is taken).
    #[test]
    fn inner_boxes_answer_as_the_whole_tests() {
        let mut rng = crate::splitmix::SplitMix64(17);
        let (square, disk) = square_and_disk(&mut rng, 3000);
        let lattice = lattice(2500, 50);
        let sliver: Vec<Point> = (0..1000).map(|_| Point::new(rng.unit(), 1e-9 * rng.unit())).collect();
        let line: Vec<Point> = (0..500).map(|i| Point::new(i as f64, 2.0 * i as f64)).collect();
        let one = vec![Point::new(3.0, 4.0)];
        let moved =
            |points: &[Point], f: &dyn Fn(f64) -> f64| points.iter().map(|p| Point::new(f(p.x), f(p.y))).collect::<Vec<_>>();
        let far = moved(&square, &|v| v + 2f64.powi(30));
        let tiny = moved(&square, &|v| v * 1e-150);
        let huge = moved(&disk, &|v| v * 1e150);
        let mut quick = 0;
        for (name, points) in [
            ("square", &square),
            ("disk", &disk),
            ("lattice", &lattice),
            ("sliver", &sliver),
            ("line", &line),
            ("one", &one),
            ("far", &far),
            ("tiny", &tiny),
            ("huge", &huge),
        ] {
            let (lo, hi) = bounding_box(points.iter().copied());
            let size = (hi.x - lo.x).max(hi.y - lo.y);
            let mut queries: Vec<Point> = points.clone();
            for _ in 0..3000 {
                let (u, v) = (1.4 * rng.unit() - 0.2, 1.4 * rng.unit() - 0.2);
                queries.push(Point::new(lo.x + u * (hi.x - lo.x), lo.y + v * (hi.y - lo.y)));
            }
            queries.extend([Point::new(f64::NAN, lo.y), Point::new(f64::INFINITY, f64::NEG_INFINITY)]);
            let around = |b: &InnerBox| {
                let mut at = Vec::new();
                for x in [b.lo.x, b.hi.x, 0.5 * b.lo.x + 0.5 * b.hi.x] {
                    for y in [b.lo.y, b.hi.y, 0.5 * b.lo.y + 0.5 * b.hi.y] {
                        for (dx, dy) in [(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (3, -3)] {
                            at.push(Point::new(nudged(x, dx), nudged(y, dy)));
                        }
                    }
                }
                at.into_iter().filter(|p| p.x.is_finite() && p.y.is_finite()).collect::<Vec<_>>()
            };
            let extremes = Extremes::of(points);
            for polygon in [extremes.octagon(), extremes.fine_polygon(points)] {
                let mut asked = queries.clone();
                asked.extend(around(&polygon.deep));
                for &p in &asked {
                    assert_eq!(polygon.may_hold_on_its_boundary(p), polygon.asked_of_every_edge(p), "{name}: {p:?}");
                }
                if name == "square" {
                    assert!(points.iter().filter(|&&p| polygon.deep.holds(p)).count() > points.len() * 9 / 10, "{name}");
                    quick += 1;
                }
            }
            let enclosure = Enclosure::of(points);
            for band in [0.0, 0.003 * size, 0.05 * size, 0.4 * size, 3.0 * size] {
                let near = enclosure.near_sides(band);
                let mut asked = queries.clone();
                asked.extend(around(&near.deep));
                for &p in &asked {
                    assert_eq!(near.holds(p), enclosure.near_a_side(p, band), "{name}, band {band}: {p:?}");
                }
                if name == "square" && band <= 0.05 * size {
                    // (the box inside the sides moved in by the band: about (1 - 2 band)^2 of the square)
                    assert!(points.iter().filter(|&&p| near.deep.holds(p)).count() > points.len() * 7 / 10, "{name} {band}");
                    quick += 1;
                }
            }
        }
        assert_eq!(quick, 5);
    }
}
