//! The segment predicates' certified stage: how far a new segment reaches
//! into the circle of a Voronoi vertex, decided from the vertex's three
//! sites, filtered then refined.
//!
//! A vertex of point and segment sites is the centre `c` and radius `r` of
//! the circle touching its three sites. The construction computes `(c, r)`
//! in `f64` (`segment_solvers`, which picks the right one of up to four
//! roots) and asks a signed question about it: does the closed segment `ab`
//! come nearer to `c` than `r` (`Reach::Distance`), or does `ab`, leaving
//! one of the vertex's point sites, head into the circle
//! (`Reach::Entering`). Near degeneracy (a site 1e-20 off the circle) the
//! rounded `(c, r)` gives the wrong sign. Here:
//!
//! 1. **Filter.** The `f64` answer stands when it exceeds a bound on its
//!    error: `1e-3` of the configuration's size outright; below that, the
//!    error of `(c, r)` is estimated as `‖J⁻¹‖ (|F| + 8 ε s)`, from the
//!    residual `F` of the tangency equations at `(c, r)` and their Jacobian
//!    `J` (one Newton step's worth, in `f64`), plus the rounding of the
//!    question itself.
//! 2. **Exact check.** When the rounded `(c, r)` solves the equations
//!    exactly (grids and other inputs with few bits, where cocircular
//!    answers are common), the question is a polynomial in doubles and is
//!    evaluated without rounding: an exact sign, zero included (in
//!    Shewchuk expansions where the coordinates' low bits allow, else in
//!    big floats). Before it, a vertex of two points and a segment's
//!    line is decided exactly from the quadratic of its centre, also in
//!    expansions (`quadratic_vertex`): the true zeros of stacks and
//!    hatches of equal parallel segments with aligned ends, which the
//!    refinement below took to 1200 bits (about 400 µs each).
//! 3. **Refine.** Otherwise the tangency equations are solved again by
//!    Newton's method from the `f64` root, the sites' coordinates taken
//!    exactly: in double-double arithmetic (about 106 bits, no allocation),
//!    then in binary floating point of 160, 400 and 1200 bits (`bigfloat`),
//!    each precision starting from the last one's solution. The answer
//!    stands when the question's value exceeds four times the last Newton
//!    step plus the rounding at that precision times the equations'
//!    condition `‖J⁻¹‖`.
//!    Where double-double leaves the question undecided and the centre
//!    is rational (three points, or two points and a segment ending at
//!    one of them: the equations are then linear in the centre), the
//!    answer is computed exactly from that centre instead
//!    (`System::rational_answer`): on rasterised outlines most true zeros
//!    are of this kind, and 1200 bits cost them about 170 µs each.
//! 4. **Zero.** A value that stays below that bound at 1200 bits (about
//!    `2^-1150` of the configuration's size, for well-conditioned
//!    equations) is evaluated once more from the circle's closed form in
//!    certified big floats (`certified`: balls that hold the exact value,
//!    and the BFMSS separation bound of the expression), at the precision
//!    the bound calls for: it is then proven zero (the segment touches the
//!    circle: cocircular sites, and the caller's topology rules decide) or
//!    told apart. Where the bound needs more than `CERTIFIED_MAX_BITS`
//!    (32,768: the closed forms of two points and a segment with an
//!    irrational centre take 41k to 59k on the `parallel` family, where
//!    65,536 bits would prove all 1,164 zeros but cost 26 times the
//!    build), the value is taken as zero by the cut-off: an engineering
//!    choice, not a proof. Where Newton's method
//!    converges at no precision (a double root: the vertex about to
//!    vanish) the `f64` value stands.
//!
//! The equations per site (a segment's supporting line is used, as by the
//! solvers): a point `p`, `|c − p| = r`; a segment not incident to a point
//! of the triple, `σ n·(c − a) = r` on the side `σ` where the `f64` centre
//! lies; a segment with an endpoint `p` among the triple's points,
//! `(c − p)·(b − a) = 0` (the centre is on its separator at `p`).
//!
//! Fault injection bypasses this module (the caller asks it only when the
//! numbers are honest): its purpose is to show that the topology survives
//! lying numbers, and a refinement would make them honest again.

use super::quadratic_vertex;
use super::reach::Reach;
use super::tangent_lines::{self, SidedLine};
use crate::geometry::arithmetic::bigfloat::{dyadic, BigFloat};
use crate::geometry::arithmetic::certified::{certified_evaluation, Certified};
use crate::geometry::arithmetic::double_double::DoubleDouble;
use crate::geometry::arithmetic::expansion::Expansion;
use crate::geometry::arithmetic::radical_tower::{exact_evaluation, Algebraic};
use crate::geometry::arithmetic::real::norm;
use crate::geometry::arithmetic::real::Real;
use crate::geometry::point::Point;
use crate::geometry::predicates::{exact_orientation, in_circle, strictly_between, CirclePosition, Orientation};
use crate::geometry::scale::Scale;
use crate::geometry::site::Site;
use crate::geometry::solvers::segment_solvers;

/// The precision of double-double arithmetic, in bits (a little under).
const DOUBLE_DOUBLE_BITS: u64 = 100;

/// Precisions of the big-float refinement, in bits.
const PRECISIONS: [u64; 3] = [160, 400, 1200];

/// A precision no sum or product of a few doubles reaches: arithmetic
/// without rounding (the exponent range of doubles spans 2,100 bits).
const EXACT: u64 = 1 << 20;

/// The fraction of the configuration's size beyond which a rounded answer
/// stands outright: the error of a vertex placed by the solvers (polished
/// where they are ill-conditioned) is far below it.
pub(crate) const CLEAR: f64 = 1e-3;

/// Newton steps allowed per precision.
const MAX_STEPS: usize = 60;

/// Where the question's answer lies: `Inside` (it reaches into the open
/// disk), `On` (exactly on the circle) or `Outside`; `None` when the
/// vertex's equations could not be refined (a degenerate triple, or no
/// convergence) and the `f64` value should stand. `depth` is the `f64`
/// value of the question at the rounded `(centre, radius)`.
/// The sites are asked for only when the filter's first test is not enough.
#[inline]
pub(crate) fn reach(
    sites: impl FnOnce() -> [Site; 3],
    centre: Point,
    radius: f64,
    question: Reach,
    depth: f64,
) -> Option<CirclePosition> {
    // The filter's first test, which decides nearly every question, inline
    // in the caller; `decide` (out of line) repeats it and goes on. (An
    // infinite size is a vertex beyond the range of `f64`, or a question
    // with no finite answer: those go to `decide`.)
    let size = question.size(centre, radius);
    let (stage, answer) = if size < f64::INFINITY && depth.abs() < f64::INFINITY && depth.abs() > CLEAR * size {
        (Stage::Filter, Some(sign_position(depth)))
    } else {
        decide(sites, centre, radius, question, depth)
    };
    COUNTS.with(|c| c[stage as usize].set(c[stage as usize].get() + 1));
    answer
}

/// Whether `fourth` lies exactly on the circle of the vertex of `sites`
/// (rounded as `centre`, `radius`): the test for a zero-length edge, whose
/// two vertices are one point exactly when their four sites are
/// cocircular. A point: exact in-circle among points, else the certified
/// distance. A segment whose endpoint is a point of `sites` touches the
/// circle when it is tangent there (the centre on its perpendicular at
/// that endpoint); any other when its nearest point is on the circle
/// (tangent inside it, or its endpoint on the circle). Decided after an exact power-of-two scaling of everything into
/// the safe range, so that products of tiny or huge coordinates neither
/// underflow nor overflow.
pub(crate) fn on_circle(sites: &[Site; 3], centre: Point, radius: f64, fourth: &Site) -> bool {
    if radius == 0.0 {
        // a vertex of radius 0 is a shared endpoint itself (exactly, see
        // `segment_solvers`): on it are the segments ending there
        return match *fourth {
            Site::Point(p) => p == centre,
            Site::Segment { .. } | Site::Arc(_) => fourth.has_endpoint(centre),
        };
    }
    let points = sites.iter().chain(std::iter::once(fourth)).flat_map(Site::ends).chain([centre]);
    let k = Scale::for_coordinates(points.flat_map(|p| [p.x, p.y]).chain([radius])).to_internal;
    let sites = sites.map(|s| s.scaled(k));
    let (c, r) = (centre.scaled(k), radius * k);
    let on = |question: Reach| {
        let depth = question.value(&[c.x, c.y, r], &|x| x);
        reach(|| sites, c, r, question, depth) == Some(CirclePosition::On)
    };
    match fourth.scaled(k) {
        Site::Point(q) => match sites {
            [Site::Point(p0), Site::Point(p1), Site::Point(p2)] => in_circle(p0, p1, p2, q) == CirclePosition::On,
            _ => on(Reach::Distance { a: q, b: q }),
        },
        Site::Segment { a, b } => match sites.iter().find_map(|g| g.as_point().filter(|&p| p == a || p == b)) {
            Some(e) => {
                let to = if e == a { b } else { a };
                // The vertex touches the cell of `e` and of a segment of
                // `sites` ending at `e`, so it lies on their separator, that
                // segment's perpendicular at `e`: where `fourth` goes on
                // straight from it (a straight joint), that is `fourth`'s
                // perpendicular too, exactly, whatever the rounding.
                let goes_on_straight = sites.iter().any(|s| match *s {
                    Site::Segment { a: sa, b: sb } if sa == e || sb == e => {
                        let back = if sa == e { sb } else { sa };
                        exact_orientation(back, e, to) == Orientation::Collinear && strictly_between(back, to, e)
                    }
                    _ => false,
                });
                goes_on_straight || on(Reach::Entering { from: e, to })
            }
            // the closed segment's nearest point on the circle: tangent
            // inside it, or touching at an endpoint (which is then a site
            // on the circle too, and the two vertices one point: five
            // cocircular sites, as on small grids)
            None => on(Reach::Distance { a, b }),
        },
        // arcs are not certified here (`arcs` decides in floating point)
        Site::Arc(_) => false,
    }
}

/// The vertex of `sites` nearer the truth than the solver's `(centre,
/// radius)`, for a solve that misses the tangency equations by more than
/// rounding ([`misses_its_sites`]), that the solver reports
/// ill-conditioned (nearly parallel lines, a circle far larger than its
/// sites: an error that the residuals do not show), or that found no
/// circle (`solved` is `None`, which for such configurations is rounding
/// too): the solver run again in double-double
/// (`segment_solvers::vertex_in`: the same case and root, finer
/// arithmetic), then Newton's method in double-double from there, the
/// result rounded to `f64`. The `f64` answer of a badly conditioned solve
/// can be far from the circle (a kink of 1e-10 rad between two lines puts
/// it in the wrong place altogether), so it is no start for Newton's
/// method. `None` when neither step succeeds.
pub(crate) fn polish_vertex(sites: &[Site; 3], solved: Option<(Point, f64)>) -> Option<(Point, f64)> {
    COUNTS.with(|c| c[POLISHED].set(c[POLISHED].get() + 1));
    let dd = DoubleDouble::from_f64;
    let start = segment_solvers::vertex_in(sites, &dd).or_else(|| solved.map(|(c, r)| [c.x, c.y, r].map(dd)))?;
    let rounded = |v: &[DoubleDouble; 3]| {
        let [x, y, r] = v.map(|v| v.to_f64());
        (x.is_finite() && y.is_finite() && r.is_finite() && r >= 0.0).then_some((Point::new(x, y), r))
    };
    let (start_centre, start_radius) = rounded(&start)?;
    let size = size_of(sites, start_centre, start_radius);
    // Newton's answer only where it truly converged: for a system whose
    // condition approaches double-double's precision (kinks of 1e-15 rad:
    // conditions of 1e30) its steps stop shrinking at garbage, and the
    // double-double solve is the better answer.
    let polished = System::of(sites, start_centre)
        .and_then(|system| system.newton(start, &dd, size, DOUBLE_DOUBLE_BITS))
        .filter(|&(_, last_step, _)| last_step <= CONVERGED * size)
        .and_then(|(solution, _, _)| rounded(&solution));
    polished.or(Some((start_centre, start_radius)))
}

/// Whether a solver's circle misses the tangency equations it solves by
/// more than rounding (`POLISH_TOLERANCE` of the configuration's size),
/// each evaluated in `f64` (cheap: no allocation, at most three square roots). A
/// segment counts by its supporting line, or, where it ends at a point of
/// the triple, by its perpendicular there: the equations of the solvers
/// and of [`System`]. The distance to the closed segment would be the
/// wrong measure: the construction also asks for circles whose tangent
/// point lies beyond a segment's end (the two crossings of an edge that
/// the new cell only grazes, in `middle_margin`); those are no error of
/// the solver, and Newton's method would only find them again (at 100k
/// short random segments, 10,000 of 10,200 polishes were such).
#[inline]
pub(crate) fn misses_its_sites(sites: &[Site; 3], centre: Point, radius: f64) -> bool {
    let points = sites.map(|s| s.as_point());
    let is_point_site = |p: Point| points.contains(&Some(p));
    // Summed, not the largest: a NaN (a centre or radius that is not
    // finite, a segment of length 0) then misses, where `max` would drop
    // it; the sum is at most three times the largest miss.
    let (mut miss, mut reach) = (0.0f64, 0.0f64);
    for site in sites {
        let (site_miss, site_reach) = match *site {
            Site::Point(p) => {
                let d = p.distance(centre);
                ((d - radius).abs(), d)
            }
            Site::Segment { a, b } => {
                let (ux, uy) = (b.x - a.x, b.y - a.y);
                let length = norm(ux, uy);
                let (vx, vy) = (centre.x - a.x, centre.y - a.y);
                let site_miss = if is_point_site(a) {
                    (ux * vx + uy * vy).abs() / length
                } else if is_point_site(b) {
                    (ux * (centre.x - b.x) + uy * (centre.y - b.y)).abs() / length
                } else {
                    ((ux * vy - uy * vx).abs() / length - radius).abs()
                };
                // (in the L1 norm: a size within √2 of `size_of`'s, and
                // one square root fewer)
                (site_miss, vx.abs() + vy.abs())
            }
            Site::Arc(arc) => ((site.distance(centre) - radius).abs(), arc.centre().distance(centre) + arc.radius()),
        };
        miss += site_miss;
        reach = reach.max(site_reach);
    }
    // (an infinite size, from an infinite radius or centre, misses too)
    let size = radius.abs() + reach;
    // No polish does better than the centre's own rounding to `f64`, at
    // its magnitude: far from the origin (2^30 out, sites a few units
    // apart) that is far above `POLISH_TOLERANCE` of the size, and every
    // vertex was polished to the same rounded centre again (at 3,000
    // crossing segments split, 76,000 polishes for 45,000 vertices: 90
    // times the build's time at the origin).
    let rounding = CENTRE_ROUNDING * f64::EPSILON * (centre.x.abs() + centre.y.abs());
    !(miss <= POLISH_TOLERANCE * size + rounding && size < f64::INFINITY)
}

/// The misses the rounding of a centre to `f64` alone may leave, in ulps
/// of its coordinates' magnitude, summed over three sites (each at most
/// about one, with the rounding of its distance).
const CENTRE_ROUNDING: f64 = 8.0;

/// The last Newton step, relative to the size, below which a polish has
/// converged (well below what rounding to `f64` keeps).
const CONVERGED: f64 = 1e-20;

/// A solver's result is polished when a site is farther than this, times
/// the configuration's size, from its circle.
const POLISH_TOLERANCE: f64 = 1e-12;

/// The counter of polished vertices, after the stages'.
const POLISHED: usize = 6;

/// The size of a vertex's configuration, the scale of its tolerances: the
/// radius plus the distance from the centre to the farthest site (a
/// segment by its first end).
fn size_of(sites: &[Site; 3], centre: Point, radius: f64) -> f64 {
    radius.abs() + sites.iter().map(|s| s.ends()[0].distance(centre)).fold(0.0, f64::max)
}

/// Which stage decided a question (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    Filter,
    Exact,
    DoubleDouble,
    BigFloat,
    Zero,
    Unrefined,
}

/// How the questions asked on one thread were decided, by stage.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PredicateCounts {
    /// Per stage: the `f64` filter, the exact check of a rounded vertex
    /// (or of a rational centre), double-double, big floats, taken as
    /// zero, and left to the `f64` value (no convergence or a degenerate
    /// triple).
    pub by_stage: [u64; 6],
    /// Vertices whose solver result missed its sites by more than rounding
    /// and was polished by Newton's method (`polish_vertex`).
    pub polished_vertices: u64,
}

impl PredicateCounts {
    /// Questions the `f64` filter decided.
    pub fn filtered(&self) -> u64 {
        self.by_stage[Stage::Filter as usize]
    }

    /// Questions asked in all.
    pub fn total(&self) -> u64 {
        self.by_stage.iter().sum()
    }
}

thread_local! {
    /// Per stage (by `Stage as usize`), then the polished vertices: one
    /// counter bumped per question, on the hot path.
    static COUNTS: [std::cell::Cell<u64>; 7] = const { [const { std::cell::Cell::new(0) }; 7] };
}

/// The counts of this thread since the last [`take_predicate_counts`], and
/// zero from now on.
pub fn take_predicate_counts() -> PredicateCounts {
    let taken: [u64; 7] = COUNTS.with(|c| std::array::from_fn(|k| c[k].replace(0)));
    let mut by_stage = [0; 6];
    by_stage.copy_from_slice(&taken[..6]);
    PredicateCounts { by_stage, polished_vertices: taken[POLISHED] }
}

#[inline(never)]
fn decide(
    sites: impl FnOnce() -> [Site; 3],
    centre: Point,
    radius: f64,
    question: Reach,
    depth: f64,
) -> (Stage, Option<CirclePosition>) {
    if is_beyond_range(radius) {
        // nothing rounded to `f64` stands for such a vertex
        return (Stage::BigFloat, beyond_range_answer(&sites(), &question));
    }
    let size = question.size(centre, radius);
    if !(size.is_finite() && depth.is_finite()) {
        return (Stage::Unrefined, None);
    }
    if depth.abs() > CLEAR * size {
        return (Stage::Filter, Some(sign_position(depth)));
    }
    let sites = sites();
    let Some(system) = System::of(&sites, centre) else {
        return (Stage::Unrefined, None);
    };
    if let Some(error) = system.f64_error(centre, radius, size) {
        if depth.abs() > 4.0 * error + 16.0 * f64::EPSILON * size {
            return (Stage::Filter, Some(sign_position(depth)));
        }
    }
    // Two points and a line: exact from the quadratic of the centre, at
    // the cost of a few expansions (the true zeros of stacks and hatches).
    if let Some(exact) = system.two_points_line_answer(centre, &question) {
        return (Stage::Exact, Some(exact));
    }
    if let Some(exact) = system.exact_answer(centre, radius, &question) {
        return (Stage::Exact, Some(exact));
    }
    let start = [centre.x, centre.y, radius];
    // double-double first (cheap, no allocation), then big floats
    let dd = DoubleDouble::from_f64;
    let mut undecided_at_double_double = false;
    match refine_at(&system, &question, start.map(dd), &dd, size, DOUBLE_DOUBLE_BITS) {
        Refined::Decided(answer) => return (Stage::DoubleDouble, Some(answer)),
        Refined::Undecided(solution) => {
            // Near zero: the vertex may be one with a short binary expansion
            // that the solver's rounding missed (a degenerate input with few
            // bits); rounded from the refined solution it is checked exactly.
            let [x, y, r] = solution.map(|v| v.to_f64());
            if let Some(exact) = system.exact_answer(Point::new(x, y), r, &question) {
                return (Stage::Exact, Some(exact));
            }
            // Three lines and a fourth: exact from the input's integers.
            if let Some(exact) = system.three_lines_answer(Point::new(x, y), r, &question) {
                return (Stage::Exact, Some(exact));
            }
            undecided_at_double_double = true;
        }
        Refined::Failed => {}
    }
    // Still near zero: where the centre is rational (three points, or two
    // points and a segment ending at one of them), the exact answer costs
    // a few big-number products; the refinement below would take it to
    // 1200 bits and call it zero (on rasterised outlines, most of the
    // build's time).
    if let Some(exact) = system.rational_answer(&question) {
        return (Stage::Exact, Some(exact));
    }
    // Converged at double-double and still near zero: most such questions
    // are true zeros (mirror-symmetric outlines, arcs cut into chords
    // symmetrically), which the big-float stages below would take to 1200
    // bits before the tower of square roots proves them; the tower first
    // decides them exactly at a fraction of the cost.
    if undecided_at_double_double {
        if let Some(exact) = algebraic_answer(&sites, &question) {
            return (Stage::Exact, Some(exact));
        }
    }
    // Each precision starts from the last one's solution, or where there
    // is none from the solver run at that precision: for a system whose
    // condition exceeds the last precision (kinks of 1e-15 rad: 1e30) a
    // start from the rounded vertex is in no basin at all.
    let mut start: Option<[BigFloat; 3]> = None;
    let mut converged = false;
    for bits in PRECISIONS {
        let lift = |x: f64| BigFloat::from_f64(x, bits);
        let begin = match start.take() {
            Some(solution) => solution.map(|x| x.with_precision(bits)),
            None => segment_solvers::vertex_in(&sites, &lift).unwrap_or_else(|| [centre.x, centre.y, radius].map(lift)),
        };
        match refine_at(&system, &question, begin, &lift, size, bits) {
            Refined::Decided(answer) => return (Stage::BigFloat, Some(answer)),
            Refined::Undecided(solution) => {
                start = Some(solution);
                converged = true;
            }
            Refined::Failed => {}
        }
    }
    // Magnitudes far apart (a coordinate near the subnormal range beside
    // ordinary ones): a nonzero value can be far smaller than 2^-1150 of
    // the size (about the square of the tiny coordinate's ratio to the
    // others), so one more precision, twice the span of f64's exponents.
    if let Some(solution) = start.filter(|_| converged && exponent_spread(&sites, &question) > WIDE_SPREAD) {
        if let Some(answer) = refine_wide(&system, &question, solution, size) {
            return (Stage::BigFloat, Some(answer));
        }
    }
    // Zero within 2^-1150 or so of the size (2^-4300 for magnitudes far
    // apart): proven so, or told apart, in certified arithmetic; where the
    // separation bound is out of reach, on the circle by the cut-off.
    // Without convergence at any precision the rounded value stands.
    if !converged {
        return (Stage::Unrefined, None);
    }
    match proven_answer(&sites, &question) {
        Some(answer) => (Stage::Exact, Some(answer)),
        None => (Stage::Zero, Some(CirclePosition::On)),
    }
}

/// The exact answer for a question no refinement could tell from zero:
/// in the tower of square roots (`radical_tower`, exact, within its
/// limits), else from certified big floats and the separation bound.
fn proven_answer(sites: &[Site; 3], question: &Reach) -> Option<CirclePosition> {
    algebraic_answer(sites, question).or_else(|| certified_answer(sites, question))
}

/// The question's exact answer at the circle of `sites`, the closed forms
/// evaluated in exact numbers with square roots (`radical_tower`); `None`
/// when that evaluation exceeds its limits or no circle is found.
fn algebraic_answer(sites: &[Site; 3], question: &Reach) -> Option<CirclePosition> {
    let lift = Algebraic::from_f64;
    let sign = exact_evaluation(|| {
        let solution = segment_solvers::vertex_in_any_range(sites, &lift)?;
        Some(question.value(&solution, &lift).signum())
    })??;
    Some(sign_position(f64::from(sign)))
}

/// `sites` and `question` scaled by the power of two that makes every
/// coordinate an integer, as far as that keeps them below `2^1000` (exact:
/// a power of two, no overflow).
fn integer_scaled(sites: &[Site; 3], question: &Reach) -> ([Site; 3], Reach) {
    let coordinates = || sites.iter().flat_map(Site::ends).chain(question.points()).flat_map(|p| [p.x, p.y]);
    let fraction_bits = coordinates().filter_map(dyadic).map(|(_, e)| -e).max().unwrap_or(0);
    let top = coordinates().filter(|x| *x != 0.0).map(|x| x.abs().log2().ceil() as i64).max().unwrap_or(0);
    let k = fraction_bits.min(1000 - top).clamp(0, 1000) as i32;
    if k == 0 {
        return (*sites, *question);
    }
    let factor = 2f64.powi(k);
    let question = match *question {
        Reach::Distance { a, b } => Reach::Distance { a: a.scaled(factor), b: b.scaled(factor) },
        Reach::Entering { from, to } => Reach::Entering { from: from.scaled(factor), to: to.scaled(factor) },
    };
    (sites.map(|s| s.scaled(factor)), question)
}

/// The precision a certified evaluation starts at, in bits.
const CERTIFIED_START_BITS: u64 = 1200;

/// The precision beyond which [`certified_answer`] gives up, in bits.
const CERTIFIED_MAX_BITS: u64 = 1 << 15;

/// The question's exact answer at the circle of `sites`, `On` only for a
/// proven zero: the circle's closed form (`segment_solvers`) and the
/// question evaluated in certified big floats (`certified`: balls that
/// hold the exact value, and the BFMSS separation bound of the
/// expression). The precision grows to what the ball's width and the bound
/// call for; `None` when that exceeds `CERTIFIED_MAX_BITS`, or no circle
/// is found.
fn certified_answer(sites: &[Site; 3], question: &Reach) -> Option<CirclePosition> {
    // The configuration scaled by a power of two that makes every
    // coordinate an integer (the answer is the same): leaves without
    // denominators give a far better separation bound.
    let (sites, question) = &integer_scaled(sites, question);
    let mut bits = CERTIFIED_START_BITS;
    loop {
        let lift = |x: f64| Certified::from_f64(x, bits);
        let (value, sure) = certified_evaluation(|| {
            segment_solvers::vertex_in_any_range(sites, &lift).map(|solution| question.value(&solution, &lift))
        });
        let value = value?;
        if let Some(sign) = value.exact_sign().filter(|_| sure) {
            return Some(sign_position(f64::from(sign)));
        }
        // the ball must shrink below the separation bound: by as many bits
        // as it is wider, and some
        // (twice the precision where the bound or the ball is out of reach:
        // a nonzero value may still be told)
        let short = value.log_radius() + value.separation_bits();
        let wanted = if short.is_finite() { bits.saturating_add(short.max(0.0) as u64 + 64) } else { 0 };
        let next = wanted.max(2 * bits);
        if next > CERTIFIED_MAX_BITS {
            return None;
        }
        bits = next;
    }
}

/// The precision of the questions about a vertex beyond the range of
/// `f64`: its circle is solved once, from the sites, in big floats. Twice
/// the span of `f64`'s exponents (2,098 bits) and a margin: the solvers'
/// squares of coordinate differences are then exact, however far apart
/// their magnitudes (at 400 bits, a point `2^-1074` off a line of size 1
/// already gets a circle of the wrong size).
pub(crate) const BEYOND_RANGE_BITS: u64 = 4400;

/// Whether the stored radius of a finite vertex marks a circle beyond the
/// range of `f64` (`vertex_placement` stores such a vertex with an infinite
/// radius, the nearest `f64` point to its centre as its position).
pub(crate) fn is_beyond_range(radius: f64) -> bool {
    radius == f64::INFINITY
}

/// The answer for a vertex whose circle lies beyond the range of `f64`
/// (its magnitudes span more than `f64`'s exponents: a point the least
/// subnormal off a segment's line, beside ordinary coordinates). The
/// circle is solved from the sites in big floats, whose exponents are
/// unbounded, and the question's value there decides, in two stages
/// (`BEYOND_RANGE_STAGES`): a value below the first stage's cut-off of
/// the configuration's size is solved again at the second's before it
/// counts as zero. The cut-offs are far below the refinement's `2^-1150`:
/// the size here is the huge radius `r`, and a site off such a circle by
/// an ordinary gap `g` of the input is off it by about `g² / r` only, or
/// less where four sites are nearly on one circle to first order (two
/// nearly collinear segments, one end `δ = 2^-1072` off their line, and
/// the ends facing each other: a value of order `δ³ r`, about `2^-3220`
/// of the size, which the first stage alone took as zero). Each cut-off
/// stays above that stage's rounding even amplified by a condition of
/// `2^1300`. `None` when no circle is found: the caller's `f64` value
/// stands.
fn beyond_range_answer(sites: &[Site; 3], question: &Reach) -> Option<CirclePosition> {
    let mut answer = None;
    for &(bits, cut_off) in BEYOND_RANGE_STAGES {
        let lift = |x: f64| BigFloat::from_f64(x, bits);
        let solution = segment_solvers::vertex_in_any_range(sites, &lift)?;
        let value = question.value(&solution, &lift);
        let bound = question.size_in(&solution, &lift).mul(&BigFloat::pow2(cut_off, bits));
        let position = position_beyond(&value, &bound);
        if position != CirclePosition::On {
            return Some(position);
        }
        answer = Some(position);
    }
    // below both cut-offs: proven zero, or told apart, where the
    // separation bound is within reach
    answer.map(|on| proven_answer(sites, question).unwrap_or(on))
}

/// The precisions (bits) of [`beyond_range_answer`]'s solves and the
/// cut-offs (binary exponents, relative to the configuration's size) below
/// which each stage's value is taken as zero: the first stage is also the
/// precision at which such vertices are placed (`BEYOND_RANGE_BITS`), the
/// second only runs for values within the first's cut-off of zero.
const BEYOND_RANGE_STAGES: &[(u64, i64)] = &[(BEYOND_RANGE_BITS, -3000), (2 * BEYOND_RANGE_BITS, -7000)];

/// The position a big-float value of a question gives: `On` within
/// `bound` of zero, else by its sign.
fn position_beyond(value: &BigFloat, bound: &BigFloat) -> CirclePosition {
    if value.abs().sub(bound).signum() <= 0 {
        CirclePosition::On
    } else if value.signum() < 0 {
        CirclePosition::Inside
    } else {
        CirclePosition::Outside
    }
}

/// The spread, in bits, of the magnitudes of a question's nonzero
/// coordinates (the sites' and the new segment's) above which a value that
/// stays undecided at 1200 bits is refined at `BEYOND_RANGE_BITS` before it
/// is taken as zero.
const WIDE_SPREAD: i32 = 200;

/// The spread of the binary exponents of the nonzero coordinates of
/// `sites` and the question's points.
fn exponent_spread(sites: &[Site; 3], question: &Reach) -> i32 {
    coordinate_exponent_spread(sites.iter().flat_map(Site::ends).chain(question.points()))
}

/// The spread of the binary exponents of the nonzero coordinates of
/// `points` (0 for none).
fn coordinate_exponent_spread(points: impl Iterator<Item = Point>) -> i32 {
    let exponents = points.flat_map(|p| [p.x, p.y]).filter(|&v| v != 0.0 && v.is_finite()).map(|v| v.abs().log2().floor() as i32);
    let (low, high) = exponents.fold((i32::MAX, i32::MIN), |(low, high), e| (low.min(e), high.max(e)));
    if low > high {
        0
    } else {
        high - low
    }
}

/// Newton steps allowed at `BEYOND_RANGE_BITS` from a 1200-bit solution
/// (quadratic convergence needs two).
const WIDE_STEPS: usize = 6;

/// The last stage for magnitudes far apart: Newton's method at
/// `BEYOND_RANGE_BITS` from a converged 1200-bit `start`, with every bound
/// kept in big floats (`f64` holds no `2^-4300` of a size, so `refine_at`'s
/// bounds would vanish). Converged when no step exceeds `R = 2^-4300 (1 +
/// ‖J⁻¹‖)` of the size, about `2^100` times the rounding; the answer
/// stands when the question's value exceeds `8 R`, and is `On` below it.
/// `None` without convergence.
fn refine_wide(system: &System, question: &Reach, start: [BigFloat; 3], size: f64) -> Option<CirclePosition> {
    let bits = BEYOND_RANGE_BITS;
    let lift = |x: f64| BigFloat::from_f64(x, bits);
    let unit = lift(size).mul(&BigFloat::pow2(-4300, bits));
    let mut v = start.map(|x| x.with_precision(bits));
    for _ in 0..WIDE_STEPS {
        let (f, j) = system.linearise(&v, &lift)?;
        let reach = unit.mul(&lift(1.0 + inverse_norm(&j)?));
        let step = solve3(&j, &f)?;
        v = [v[0].sub(&step[0]), v[1].sub(&step[1]), v[2].sub(&step[2])];
        if step.iter().all(|s| s.abs().sub(&reach).signum() <= 0) {
            return Some(position_beyond(&question.value(&v, &lift), &reach.mul(&lift(8.0))));
        }
    }
    None
}

/// What one precision of the refinement found.
enum Refined<T> {
    Decided(CirclePosition),
    /// Converged, but the question's value is within its error bound.
    Undecided([T; 3]),
    /// No convergence at this precision.
    Failed,
}

/// Newton's method at `bits` of precision, then the question at the
/// solution, decided when its value exceeds the error bound: four times
/// the last step (Newton converges quadratically, so the error left is far
/// smaller) plus the rounding, `2^(8 - bits)` of the size amplified by the
/// equations' condition `‖J⁻¹‖` (the question is 1-Lipschitz in the centre
/// and the radius).
fn refine_at<T: Real>(
    system: &System,
    question: &Reach,
    start: [T; 3],
    lift: &impl Fn(f64) -> T,
    size: f64,
    bits: u64,
) -> Refined<T> {
    let Some((solution, last_step, condition)) = system.newton(start, lift, size, bits) else {
        return Refined::Failed;
    };
    let value = question.value(&solution, lift).to_f64();
    let rounding = 2f64.powi(8 - bits as i32) * size * (1.0 + condition);
    if value.abs() > 4.0 * last_step + rounding {
        Refined::Decided(sign_position(value))
    } else {
        Refined::Undecided(solution)
    }
}

#[inline]
fn sign_position(depth: f64) -> CirclePosition {
    if depth < 0.0 {
        CirclePosition::Inside
    } else if depth > 0.0 {
        CirclePosition::Outside
    } else {
        CirclePosition::On
    }
}

impl Reach {
    /// The size of the configuration: the scale of every error bound of
    /// the filter and the refinement. The distances are taken in the L1
    /// norm (no square roots on the filter's hot path): at least the
    /// Euclidean size, so every bound scaled by it only grows.
    fn size(&self, c: Point, r: f64) -> f64 {
        let [p, q] = self.points();
        let l1 = |u: Point, v: Point| (u.x - v.x).abs() + (u.y - v.y).abs();
        r.abs() + l1(c, p) + l1(p, q)
    }

    /// The size in the arithmetic `T`, at `(x, y, r)`, with Euclidean
    /// distances (at most [`Reach::size`]).
    fn size_in<T: Real>(&self, [x, y, r]: &[T; 3], lift: &impl Fn(f64) -> T) -> T {
        let [p, q] = self.points();
        let (px, py) = (lift(p.x), lift(p.y));
        let centre_to_p = T::hypot(&x.sub(&px), &y.sub(&py));
        let along = T::hypot(&lift(q.x).sub(&px), &lift(q.y).sub(&py));
        r.abs().add(&centre_to_p).add(&along)
    }

    /// The question's value at `(x, y, r)`.
    fn value<T: Real>(&self, [x, y, r]: &[T; 3], lift: &impl Fn(f64) -> T) -> T {
        match *self {
            Reach::Distance { a, b } => {
                let (ax, ay, bx, by) = (lift(a.x), lift(a.y), lift(b.x), lift(b.y));
                let (ux, uy) = (bx.sub(&ax), by.sub(&ay));
                let (vx, vy) = (x.sub(&ax), y.sub(&ay));
                let along = ux.mul(&vx).add(&uy.mul(&vy));
                let length2 = ux.mul(&ux).add(&uy.mul(&uy));
                let distance = if along.signum() <= 0 {
                    vx.mul(&vx).add(&vy.mul(&vy)).sqrt()
                } else if along.sub(&length2).signum() >= 0 {
                    let (wx, wy) = (x.sub(&bx), y.sub(&by));
                    wx.mul(&wx).add(&wy.mul(&wy)).sqrt()
                } else {
                    ux.mul(&vy).sub(&uy.mul(&vx)).abs().div(&length2.sqrt())
                };
                distance.sub(r)
            }
            Reach::Entering { from, to } => {
                let (fx, fy) = (lift(from.x), lift(from.y));
                let (ux, uy) = (lift(to.x).sub(&fx), lift(to.y).sub(&fy));
                let along = ux.mul(&x.sub(&fx)).add(&uy.mul(&y.sub(&fy)));
                along.div(&ux.mul(&ux).add(&uy.mul(&uy)).sqrt()).neg()
            }
        }
    }
}

/// One tangency equation of a vertex, `F(x, y, r) = 0`.
#[derive(Clone, Copy, Debug)]
enum Equation {
    /// `|c − p| − r`.
    Circle(Point),
    /// `σ n·(c − a) − r`, `n` the left unit normal of `a → b`.
    Line { a: Point, b: Point, side: f64 },
    /// `û·(c − p)`, `û` the unit direction of the segment from its
    /// endpoint `p` to its other endpoint `q`: the centre lies on the
    /// segment's perpendicular at `p`. (`q − p` is formed in the
    /// arithmetic of the evaluation: rounded to `f64`, its direction tilts
    /// by an ulp, which moves a far centre by more than its own error.)
    Perpendicular { p: Point, q: Point },
}

impl Equation {
    /// The points the equation names.
    fn points(&self) -> impl Iterator<Item = Point> {
        let (p, q) = match *self {
            Equation::Circle(p) => (p, p),
            Equation::Line { a, b, .. } => (a, b),
            Equation::Perpendicular { p, q } => (p, q),
        };
        [p, q].into_iter()
    }
}

/// The three tangency equations of a vertex.
struct System([Equation; 3]);

impl System {
    /// The equations of the vertex of `sites` whose rounded centre is
    /// `centre`; `None` when they do not determine it (a segment's both
    /// ends among the points, two separators at one point: radius 0, which
    /// the callers decide exactly) or the centre is on a supporting line.
    fn of(sites: &[Site; 3], centre: Point) -> Option<System> {
        let points: Vec<Point> = sites.iter().filter_map(Site::as_point).collect();
        let mut perpendicular_at: Vec<Point> = Vec::new();
        let mut equations = [Equation::Circle(Point::new(0.0, 0.0)); 3];
        for (k, site) in sites.iter().enumerate() {
            equations[k] = match *site {
                Site::Point(p) => Equation::Circle(p),
                Site::Arc(_) => return None,
                Site::Segment { a, b } => {
                    let ends: Vec<Point> = points.iter().copied().filter(|&p| p == a || p == b).collect();
                    match ends.as_slice() {
                        [] => {
                            let cross = (b.x - a.x) * (centre.y - a.y) - (b.y - a.y) * (centre.x - a.x);
                            if cross == 0.0 || !cross.is_finite() {
                                return None;
                            }
                            Equation::Line { a, b, side: cross.signum() }
                        }
                        [p] => {
                            if perpendicular_at.contains(p) {
                                return None;
                            }
                            perpendicular_at.push(*p);
                            let other = if *p == a { b } else { a };
                            Equation::Perpendicular { p: *p, q: other }
                        }
                        _ => return None,
                    }
                }
            };
        }
        Some(System(equations))
    }

    /// The exact answer where the three equations are lines (segments
    /// sharing no endpoint with the triple's points) and the question is
    /// the distance to a segment whose nearest point to the centre lies
    /// clearly inside it (`tangent_lines`); `None` otherwise. `centre` and
    /// `radius` are a refined solution: they give the sides only.
    fn three_lines_answer(&self, centre: Point, radius: f64, question: &Reach) -> Option<CirclePosition> {
        let Reach::Distance { a, b } = *question else { return None };
        let lines = self.0.map(|e| match e {
            Equation::Line { a, b, side } => Some(SidedLine { a, b, side }),
            _ => None,
        });
        let [Some(l0), Some(l1), Some(l2)] = lines else { return None };
        // the nearest point of the question's segment inside it, and the
        // centre clearly off its line (both far beyond the refinement's
        // error): the distance is then the line's
        let (ux, uy) = (b.x - a.x, b.y - a.y);
        let (vx, vy) = (centre.x - a.x, centre.y - a.y);
        let length2 = ux * ux + uy * uy;
        let t = (ux * vx + uy * vy) / length2;
        let cross = ux * vy - uy * vx;
        let size = length2.sqrt() * (vx.abs() + vy.abs() + radius.abs());
        if !(t > 1e-9 && t < 1.0 - 1e-9 && cross.abs() > 1e-9 * size) {
            return None;
        }
        let q = SidedLine { a, b, side: cross.signum() };
        tangent_lines::fourth_line_sign([l0, l1, l2], q).map(|s| sign_position(f64::from(s)))
    }

    /// [`System::exact_answer`] in Shewchuk's expansions (a few
    /// products, no allocation of big numbers): `Some` of its answer where
    /// every product of up to four of the coordinates, centre and radius is
    /// exact in them (no set bit below `2^-260`, no overflow), `None`
    /// where the big floats must decide.
    fn exact_answer_in_expansions(&self, centre: Point, radius: f64, question: &Reach) -> Option<Option<CirclePosition>> {
        let coordinates =
            self.0.iter().flat_map(Equation::points).chain(question.points()).chain([centre]).flat_map(|p| [p.x, p.y]);
        if !coordinates.chain([radius]).all(|x| quadratic_vertex::low_bits_fit(x, -260)) {
            return None;
        }
        let (x, y) = (centre.x, centre.y);
        let squared_distance = |p: Point| {
            let mut e = Expansion::default();
            e.add_squared_difference(x, p.x);
            e.add_squared_difference(y, p.y);
            e
        };
        let mut r2 = Expansion::default();
        r2.add_product(radius, radius);
        // cross(b − a, c − a), |b − a|², (b − a)·(c − a)
        let line = |a: Point, b: Point| {
            let (ux, uy) = (Expansion::difference(b.x, a.x), Expansion::difference(b.y, a.y));
            let (vx, vy) = (Expansion::difference(x, a.x), Expansion::difference(y, a.y));
            (ux.times(&vy).minus(&uy.times(&vx)), ux.times(&ux).plus(&uy.times(&uy)), ux.times(&vx).plus(&uy.times(&vy)))
        };
        let sign = |e: Expansion| e.is_finite().then(|| e.sign());
        for equation in &self.0 {
            let holds = match *equation {
                Equation::Circle(p) => sign(squared_distance(p).minus(&r2))? == 0,
                Equation::Line { a, b, side } => {
                    let (cross, length2, _) = line(a, b);
                    sign(cross.clone())? as f64 == side && sign(cross.times(&cross).minus(&r2.times(&length2)))? == 0
                }
                Equation::Perpendicular { p, q } => {
                    let (ux, uy) = (Expansion::difference(q.x, p.x), Expansion::difference(q.y, p.y));
                    let (dx, dy) = (Expansion::difference(x, p.x), Expansion::difference(y, p.y));
                    sign(ux.times(&dx).plus(&uy.times(&dy)))? == 0
                }
            };
            if !holds {
                return Some(None);
            }
        }
        let sign = match *question {
            Reach::Distance { a, b } => {
                let (cross, length2, along) = line(a, b);
                if sign(along.clone())? <= 0 {
                    sign(squared_distance(a).minus(&r2))?
                } else if sign(along.minus(&length2))? >= 0 {
                    sign(squared_distance(b).minus(&r2))?
                } else {
                    sign(cross.times(&cross).minus(&r2.times(&length2)))?
                }
            }
            Reach::Entering { from, to } => -sign(line(from, to).2)?,
        };
        Some(Some(sign_position(f64::from(sign))))
    }

    /// The exact answer for two points and a line (`quadratic_vertex`);
    /// `None` for any other system, or where that arithmetic refuses.
    fn two_points_line_answer(&self, centre: Point, question: &Reach) -> Option<CirclePosition> {
        let (mut points, mut line) = (Vec::with_capacity(2), None);
        for equation in &self.0 {
            match *equation {
                Equation::Circle(p) => points.push(p),
                Equation::Line { a, b, side } => line = Some((a, b, side)),
                Equation::Perpendicular { .. } => return None,
            }
        }
        let ([p, q], Some((a, b, side))) = (<[Point; 2]>::try_from(points).ok()?, line) else {
            return None;
        };
        quadratic_vertex::answer(p, q, (a, b), side, centre, question)
    }

    /// The exact answer when the rounded `(centre, radius)` solves the
    /// tangency equations exactly (as on grids and other inputs with few
    /// bits, where degenerate, cocircular answers are common): the
    /// equations and the question are then polynomial in doubles, and are
    /// evaluated without rounding. `None` otherwise.
    fn exact_answer(&self, centre: Point, radius: f64, question: &Reach) -> Option<CirclePosition> {
        match self.exact_answer_in_expansions(centre, radius, question) {
            Some(answer) => answer,
            None => self.exact_answer_in_big_floats(centre, radius, question),
        }
    }

    /// [`System::exact_answer`] in big floats, whatever the magnitudes.
    fn exact_answer_in_big_floats(&self, centre: Point, radius: f64, question: &Reach) -> Option<CirclePosition> {
        let lift = |x: f64| BigFloat::from_f64(x, EXACT);
        let (x, y, r) = (lift(centre.x), lift(centre.y), lift(radius));
        let squared_distance = |p: Point| {
            let (dx, dy) = (x.sub(&lift(p.x)), y.sub(&lift(p.y)));
            dx.mul(&dx).add(&dy.mul(&dy))
        };
        let r2 = r.mul(&r);
        // cross(b - a, c - a) and |b - a|^2
        let line = |a: Point, b: Point| {
            let (ux, uy) = (lift(b.x).sub(&lift(a.x)), lift(b.y).sub(&lift(a.y)));
            let (vx, vy) = (x.sub(&lift(a.x)), y.sub(&lift(a.y)));
            (ux.mul(&vy).sub(&uy.mul(&vx)), ux.mul(&ux).add(&uy.mul(&uy)), ux.mul(&vx).add(&uy.mul(&vy)))
        };
        for equation in &self.0 {
            let holds = match *equation {
                Equation::Circle(p) => squared_distance(p).sub(&r2).signum() == 0,
                Equation::Line { a, b, side } => {
                    let (cross, length2, _) = line(a, b);
                    cross.signum() as f64 == side && cross.mul(&cross).sub(&r2.mul(&length2)).signum() == 0
                }
                Equation::Perpendicular { p, q } => {
                    let (dx, dy) = (x.sub(&lift(p.x)), y.sub(&lift(p.y)));
                    let (ux, uy) = (lift(q.x).sub(&lift(p.x)), lift(q.y).sub(&lift(p.y)));
                    ux.mul(&dx).add(&uy.mul(&dy)).signum() == 0
                }
            };
            if !holds {
                return None;
            }
        }
        let sign = match *question {
            Reach::Distance { a, b } => {
                let (cross, length2, along) = line(a, b);
                if along.signum() <= 0 {
                    squared_distance(a).sub(&r2).signum()
                } else if along.sub(&length2).signum() >= 0 {
                    squared_distance(b).sub(&r2).signum()
                } else {
                    cross.mul(&cross).sub(&r2.mul(&length2)).signum()
                }
            }
            Reach::Entering { from, to } => -line(from, to).2.signum(),
        };
        Some(match sign {
            -1 => CirclePosition::Inside,
            1 => CirclePosition::Outside,
            _ => CirclePosition::On,
        })
    }

    /// The exact answer when the equations fix the centre linearly: every
    /// equation a point's circle or a perpendicular at a point (no
    /// tangent line), so that subtracting the first circle from the others
    /// leaves two linear equations in `c` (bisectors `2(p − p₀)·c = (p −
    /// p₀)·(p + p₀)`, perpendiculars `(q − p)·c = (q − p)·p`) and
    /// `c = N / D` by Cramer's rule, `r² = |c − p₀|²`. The question is then
    /// a sign of polynomials in `N`, `D` and the doubles (multiplied
    /// through by `D` or `D²`), evaluated without rounding. Three points,
    /// or two points and a segment ending at one of them: the vertices of
    /// grid-like inputs whose centre has no short binary expansion (a third,
    /// or a square root in the radius), where the rounded-vertex check
    /// (`exact_answer`) fails. `None` for any other system, or `D = 0`.
    fn rational_answer(&self, question: &Reach) -> Option<CirclePosition> {
        let lift = |x: f64| BigFloat::from_f64(x, EXACT);
        let mut circles = self.0.iter().filter_map(|e| match *e {
            Equation::Circle(p) => Some(p),
            _ => None,
        });
        let p0 = circles.next()?;
        let mut rows: Vec<([BigFloat; 2], BigFloat)> = Vec::with_capacity(2);
        for equation in &self.0 {
            match *equation {
                Equation::Circle(p) if p == p0 => {}
                Equation::Circle(p) => {
                    let (ux, uy) = (lift(p.x).sub(&lift(p0.x)), lift(p.y).sub(&lift(p0.y)));
                    let rhs = ux.mul(&lift(p.x).add(&lift(p0.x))).add(&uy.mul(&lift(p.y).add(&lift(p0.y))));
                    rows.push(([ux.add(&ux), uy.add(&uy)], rhs));
                }
                Equation::Perpendicular { p, q } => {
                    let (ux, uy) = (lift(q.x).sub(&lift(p.x)), lift(q.y).sub(&lift(p.y)));
                    let rhs = ux.mul(&lift(p.x)).add(&uy.mul(&lift(p.y)));
                    rows.push(([ux, uy], rhs));
                }
                Equation::Line { .. } => return None,
            }
        }
        let [([a1x, a1y], b1), ([a2x, a2y], b2)] = <[_; 2]>::try_from(rows).ok()?;
        let d = a1x.mul(&a2y).sub(&a1y.mul(&a2x));
        let sign_d = d.signum();
        if sign_d == 0 {
            return None;
        }
        let (nx, ny) = (b1.mul(&a2y).sub(&b2.mul(&a1y)), a1x.mul(&b2).sub(&a2x.mul(&b1)));
        // D (c − p), exactly
        let offset = |p: Point| (nx.sub(&d.mul(&lift(p.x))), ny.sub(&d.mul(&lift(p.y))));
        let squared = |(x, y): &(BigFloat, BigFloat)| x.mul(x).add(&y.mul(y));
        // D² r²
        let r2 = squared(&offset(p0));
        let sign = match *question {
            Reach::Distance { a, b } => {
                let (ux, uy) = (lift(b.x).sub(&lift(a.x)), lift(b.y).sub(&lift(a.y)));
                let from_a = offset(a);
                let length2 = ux.mul(&ux).add(&uy.mul(&uy));
                // D (c − a)·u, and D |u|²: their signs times D's order c along ab
                let along = ux.mul(&from_a.0).add(&uy.mul(&from_a.1));
                if along.signum() * sign_d <= 0 {
                    squared(&from_a).sub(&r2).signum()
                } else if along.sub(&length2.mul(&d)).signum() * sign_d >= 0 {
                    squared(&offset(b)).sub(&r2).signum()
                } else {
                    let cross = ux.mul(&from_a.1).sub(&uy.mul(&from_a.0));
                    cross.mul(&cross).sub(&r2.mul(&length2)).signum()
                }
            }
            Reach::Entering { from, to } => {
                let (ux, uy) = (lift(to.x).sub(&lift(from.x)), lift(to.y).sub(&lift(from.y)));
                let from_c = offset(from);
                -(ux.mul(&from_c.0).add(&uy.mul(&from_c.1)).signum() * sign_d)
            }
        };
        Some(match sign {
            -1 => CirclePosition::Inside,
            1 => CirclePosition::Outside,
            _ => CirclePosition::On,
        })
    }

    /// The residuals and the Jacobian at `(x, y, r)` of the system Newton
    /// solves; `None` where a derivative does not exist (the centre on a
    /// point site).
    ///
    /// Equivalent to the tangency equations but conditioned like the
    /// problem, not worse: one equation (the first point's, else the first
    /// line's) fixes `r`, and the other two are taken relative to it, free
    /// of `r` — for two points their bisector `n·(c − m) = 0` in unit-normal
    /// form. (With the tangency equations themselves, a circle much larger
    /// than its sites moves `c` and `r` together and the Jacobian is
    /// singular in `f64`.)
    fn linearise<T: Real>(&self, v: &[T; 3], lift: &impl Fn(f64) -> T) -> Option<([T; 3], [[T; 3]; 3])> {
        let [x, y, r] = v;
        let zero = lift(0.0);
        let one = lift(1.0);
        let rows: Vec<(T, [T; 3])> = self
            .0
            .iter()
            .map(|equation| match *equation {
                Equation::Circle(p) => {
                    let (dx, dy) = (x.sub(&lift(p.x)), y.sub(&lift(p.y)));
                    let rho = dx.mul(&dx).add(&dy.mul(&dy)).sqrt();
                    (rho.signum() != 0).then(|| (rho.sub(r), [dx.div(&rho), dy.div(&rho), one.neg()]))
                }
                Equation::Line { a, b, side } => {
                    let (ux, uy) = (lift(b.x).sub(&lift(a.x)), lift(b.y).sub(&lift(a.y)));
                    let length = ux.mul(&ux).add(&uy.mul(&uy)).sqrt();
                    let s = lift(side);
                    let (nx, ny) = (uy.neg().mul(&s).div(&length), ux.mul(&s).div(&length));
                    let (vx, vy) = (x.sub(&lift(a.x)), y.sub(&lift(a.y)));
                    Some((nx.mul(&vx).add(&ny.mul(&vy)).sub(r), [nx, ny, one.neg()]))
                }
                Equation::Perpendicular { p, q } => {
                    let (ux, uy) = (lift(q.x).sub(&lift(p.x)), lift(q.y).sub(&lift(p.y)));
                    let length = ux.mul(&ux).add(&uy.mul(&uy)).sqrt();
                    let (ux, uy) = (ux.div(&length), uy.div(&length));
                    let (vx, vy) = (x.sub(&lift(p.x)), y.sub(&lift(p.y)));
                    Some((ux.mul(&vx).add(&uy.mul(&vy)), [ux, uy, zero.clone()]))
                }
            })
            .collect::<Option<_>>()?;
        let anchor = self
            .0
            .iter()
            .position(|e| matches!(e, Equation::Circle(_)))
            .or_else(|| self.0.iter().position(|e| matches!(e, Equation::Line { .. })))?;
        let mut f: [T; 3] = [zero.clone(), zero.clone(), zero.clone()];
        let mut j: [[T; 3]; 3] = std::array::from_fn(|_| [zero.clone(), zero.clone(), zero.clone()]);
        for (k, (value, gradient)) in rows.iter().enumerate() {
            (f[k], j[k]) = match (self.0[anchor], self.0[k]) {
                _ if k == anchor => (value.clone(), gradient.clone()),
                (_, Equation::Perpendicular { .. }) => (value.clone(), gradient.clone()),
                (Equation::Circle(p), Equation::Circle(q)) => {
                    // |c - q| - |c - p| = 0 as the bisector of p and q
                    let (nx, ny) = (lift(p.x).sub(&lift(q.x)), lift(p.y).sub(&lift(q.y)));
                    let length = nx.mul(&nx).add(&ny.mul(&ny)).sqrt();
                    let (nx, ny) = (nx.div(&length), ny.div(&length));
                    let half = lift(0.5);
                    let (mx, my) = (lift(p.x).add(&lift(q.x)).mul(&half), lift(p.y).add(&lift(q.y)).mul(&half));
                    let value = nx.mul(&x.sub(&mx)).add(&ny.mul(&y.sub(&my)));
                    (value, [nx, ny, zero.clone()])
                }
                _ => {
                    let (base, base_gradient) = &rows[anchor];
                    let g = [gradient[0].sub(&base_gradient[0]), gradient[1].sub(&base_gradient[1]), zero.clone()];
                    (value.sub(base), g)
                }
            };
        }
        Some((f, j))
    }

    /// A bound on the error of the rounded solution `(centre, radius)`:
    /// `‖J⁻¹‖∞ (‖F‖∞ + 8 ε size)`, in `f64`. `None` for a singular `J`.
    fn f64_error(&self, centre: Point, radius: f64, size: f64) -> Option<f64> {
        let (f, j) = self.linearise(&[centre.x, centre.y, radius], &|x| x)?;
        let inverse_norm = inverse_norm(&j)?;
        let residual = f.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let error = inverse_norm * (residual + 8.0 * f64::EPSILON * size);
        error.is_finite().then_some(error)
    }

    /// Newton's method from `start` at `bits` of precision: the solution,
    /// the size of the last step and `‖J⁻¹‖∞` there. `None` without
    /// convergence (the step no longer shrinks before it is below the
    /// precision, or a singular Jacobian).
    fn newton<T: Real>(&self, start: [T; 3], lift: &impl Fn(f64) -> T, size: f64, bits: u64) -> Option<([T; 3], f64, f64)> {
        let unit = 2f64.powi(-(bits as i32)) * size;
        let mut v = start;
        let mut previous = f64::INFINITY;
        for _ in 0..MAX_STEPS {
            let (f, j) = self.linearise(&v, lift)?;
            // Rounding leaves steps of about ‖J⁻¹‖ units in the last place:
            // below that, the iteration has converged.
            let condition = inverse_norm(&j)?;
            let tolerance = unit * 2f64.powi(24).max(256.0 * condition);
            let step = solve3(&j, &f)?;
            let step_size = step.iter().fold(0.0f64, |m, s| m.max(s.to_f64().abs()));
            if !step_size.is_finite() || step_size > 2.0 * previous.max(tolerance) {
                return None;
            }
            v = [v[0].sub(&step[0]), v[1].sub(&step[1]), v[2].sub(&step[2])];
            if step_size <= tolerance {
                return Some((v, step_size, condition));
            }
            previous = step_size;
        }
        None
    }
}

/// `‖J⁻¹‖∞` of a 3×3 matrix, computed in its arithmetic and rounded;
/// `None` when singular.
fn inverse_norm<T: Real>(j: &[[T; 3]; 3]) -> Option<f64> {
    let det = determinant(j);
    let det_f64 = det.to_f64();
    if det.signum() == 0 || !det_f64.is_finite() {
        return None;
    }
    let mut norm_rows = 0.0f64;
    for row in 0..3 {
        let mut sum = 0.0;
        for col in 0..3 {
            // the cofactor of (col, row), over det; in `T`, since the
            // Jacobian of a nearly singular system may be singular in f64
            let (r1, r2) = ((col + 1) % 3, (col + 2) % 3);
            let (c1, c2) = ((row + 1) % 3, (row + 2) % 3);
            let cofactor = j[r1][c1].mul(&j[r2][c2]).sub(&j[r1][c2].mul(&j[r2][c1]));
            sum += cofactor.div(&det).to_f64().abs();
        }
        norm_rows = norm_rows.max(sum);
    }
    norm_rows.is_finite().then_some(norm_rows)
}

fn determinant<T: Real>(j: &[[T; 3]; 3]) -> T {
    let minor = |r1: usize, r2: usize, c1: usize, c2: usize| j[r1][c1].mul(&j[r2][c2]).sub(&j[r1][c2].mul(&j[r2][c1]));
    j[0][0].mul(&minor(1, 2, 1, 2)).sub(&j[0][1].mul(&minor(1, 2, 0, 2))).add(&j[0][2].mul(&minor(1, 2, 0, 1)))
}

/// The solution of `j s = f` by Cramer's rule; `None` when singular.
fn solve3<T: Real>(j: &[[T; 3]; 3], f: &[T; 3]) -> Option<[T; 3]> {
    let det = determinant(j);
    if det.signum() == 0 {
        return None;
    }
    let column = |c: usize| {
        let mut m = j.clone();
        for (row, value) in m.iter_mut().zip(f.iter()) {
            row[c] = value.clone();
        }
        determinant(&m).div(&det)
    };
    Some([column(0), column(1), column(2)])
}

/// Debug aid for tests: the vertex of `sites` solved in 400-bit floats
/// (4400 where the magnitudes lie far apart, `WIDE_SPREAD`; the solver,
/// then Newton's method), and the signed distance of `other` from its
/// circle (negative inside), rounded; for a circle beyond the
/// range of `f64`, an infinite radius and the distance relative to the
/// configuration's size. `None` when it cannot be solved.
#[cfg(test)]
pub(crate) fn audit_depth(sites: &[Site; 3], other: &Site) -> Option<(Point, f64, f64)> {
    // in the construction's coordinates (an exact power-of-two scaling)
    let points = sites.iter().chain(std::iter::once(other)).flat_map(Site::ends);
    let scale = Scale::for_coordinates(points.flat_map(|p| [p.x, p.y]));
    let (sites, other) = (&sites.map(|s| s.scaled(scale.to_internal)), &other.scaled(scale.to_internal));
    let back = |v: f64| v * scale.to_input;
    let question = match *other {
        Site::Point(p) => Reach::Distance { a: p, b: p },
        Site::Segment { a, b } => Reach::Distance { a, b },
        _ => return None,
    };
    // magnitudes far apart: 400 bits lose the small ones
    let spread = coordinate_exponent_spread(sites.iter().chain(std::iter::once(other)).flat_map(Site::ends));
    let bits = if spread > WIDE_SPREAD { BEYOND_RANGE_BITS } else { 400 };
    let lift = |x: f64| BigFloat::from_f64(x, bits);
    let start = segment_solvers::vertex_in(sites, &lift);
    let Some(start) = start else {
        // beyond the range of f64: the depth relative to the size
        let lift = |x: f64| BigFloat::from_f64(x, BEYOND_RANGE_BITS);
        let solution = segment_solvers::vertex_in_any_range(sites, &lift)?;
        let relative = question.value(&solution, &lift).div(&question.size_in(&solution, &lift));
        let [x, y] = [&solution[0], &solution[1]].map(|v| match v.to_f64_saturated() {
            s if s.abs() == f64::MAX => s,
            s => back(s),
        });
        return Some((Point::new(x, y), f64::INFINITY, relative.to_f64()));
    };
    let [x, y, r] = start.clone().map(|v| v.to_f64());
    let size = size_of(sites, Point::new(x, y), r);
    let solution = System::of(sites, Point::new(x, y))
        .and_then(|system| system.newton(start.clone(), &lift, size, bits))
        .map_or(start, |(v, _, _)| v);
    let depth = back(question.value(&solution, &lift).to_f64());
    let [x, y, r] = solution.map(|v| back(v.to_f64()));
    Some((Point::new(x, y), r, depth))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::solvers::segment_solvers;

    fn point(x: f64, y: f64) -> Site {
        Site::Point(Point::new(x, y))
    }

    /// The polish's trigger measures the equations the solvers solve: a
    /// circle tangent to a segment's line beyond the segment's end is no
    /// miss (the closed segment is farther than the radius there), a
    /// circle moved by 1e-9 is, and so is one that is not finite.
    #[test]
    fn a_solve_misses_its_sites_by_its_own_equations() {
        let p = |x: f64, y: f64| Point::new(x, y);
        // (0, 2) and (4, 2) and the line y = 0 through a segment that ends
        // at x = 1: the circle centred (2, 2), radius 2, touches the line
        // at x = 2, beyond the segment
        let beyond = [point(4.0, 2.0), point(0.0, 2.0), Site::Segment { a: p(-3.0, 0.0), b: p(1.0, 0.0) }];
        let (c, r) = segment_solvers::vertex(&beyond[0], &beyond[1], &beyond[2]).unwrap();
        assert!((c.x - 2.0).abs() < 1e-12 && (c.y - 2.0).abs() < 1e-12 && (r - 2.0).abs() < 1e-12, "{c:?} {r}");
        assert!(beyond[2].distance(c) > r + 0.1, "the closed segment is farther than the circle");
        assert!(!misses_its_sites(&beyond, c, r));
        assert!(misses_its_sites(&beyond, p(c.x + 1e-9, c.y), r));
        assert!(misses_its_sites(&beyond, c, r * (1.0 + 1e-9)));
        assert!(misses_its_sites(&beyond, p(f64::NAN, c.y), r));
        assert!(misses_its_sites(&beyond, c, f64::INFINITY));
        // a segment ending at a point of the triple is measured by its
        // perpendicular there: (0, 0) with the segment (0, 0)-(4, 0) and
        // (0, 2) give the circle centred (0, 1), radius 1
        let ending = [point(0.0, 2.0), point(0.0, 0.0), Site::Segment { a: p(0.0, 0.0), b: p(4.0, 0.0) }];
        let (c, r) = segment_solvers::vertex(&ending[0], &ending[1], &ending[2]).unwrap();
        assert!(!misses_its_sites(&ending, c, r), "{c:?} {r}");
        assert!(misses_its_sites(&ending, p(c.x + 1e-9, c.y), r));
    }

    #[test]
    fn a_segment_grazing_a_circle_by_one_ulp_is_decided() {
        // the circle through (-1,0), (1,0), (0,1): centre 0, radius 1; a
        // segment under it whose line passes 2^-53 below or 2^-54 above its
        // lowest point, or touches it there
        let sites = [point(-1.0, 0.0), point(1.0, 0.0), point(0.0, 1.0)];
        let (c, r) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]).unwrap();
        let ask = |b_y: f64| reach(|| sites, c, r, Reach::Distance { a: Point::new(-3.0, -1.0), b: Point::new(3.0, b_y) }, 0.0);
        assert_eq!(ask(-1.0 - 2f64.powi(-52)), Some(CirclePosition::Outside));
        assert_eq!(ask(-1.0 + 2f64.powi(-53)), Some(CirclePosition::Inside));
        assert_eq!(ask(-1.0), Some(CirclePosition::On));
    }

    #[test]
    fn a_segment_vertex_is_refined() {
        // a point and two segments: the circle through (0, 2) tangent to
        // y = 0 and x = 0 (-ish: the second line tilted by one ulp), and a
        // new segment through its computed bottom-right
        let sites = [
            point(0.5, 2.0),
            Site::Segment { a: Point::new(-5.0, 0.0), b: Point::new(5.0, 0.0) },
            Site::Segment { a: Point::new(-1.0, 5.0), b: Point::new(-1.0 + 2f64.powi(-50), -5.0) },
        ];
        let (c, r) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]).unwrap();
        // the exact answers at f64 distance from the rounded circle
        for (offset, expected) in [(1e-9, CirclePosition::Outside), (-1e-9, CirclePosition::Inside)] {
            let y = c.y - r - offset;
            let question = Reach::Distance { a: Point::new(c.x - 1.0, y), b: Point::new(c.x + 1.0, y) };
            assert_eq!(reach(|| sites, c, r, question, 0.0), Some(expected));
        }
    }

    /// The cocircular answers of a rasterised outline whose centre or
    /// radius has no short binary expansion: exact from the rational
    /// centre, not refined to 1200 bits and taken as zero.
    #[test]
    fn a_rational_centre_is_decided_exactly() {
        let p = |x: f64, y: f64| Point::new(x, y);
        let ask = |sites: [Site; 3], question: Reach| {
            let (c, r) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]).unwrap();
            let _ = take_predicate_counts();
            let answer = reach(|| sites, c, r, question, question.value(&[c.x, c.y, r], &|x| x));
            (answer, take_predicate_counts().by_stage[Stage::Exact as usize])
        };
        // three points, centre (2616 + 1/3, 212): the new segment leaves
        // (2615, 211) along the tangent, or a hair inwards
        let ppp = [point(2615.0, 211.0), point(2618.0, 212.0), point(2615.0, 213.0)];
        let along = |to_y: f64| Reach::Entering { from: p(2615.0, 211.0), to: p(2612.0, to_y) };
        assert_eq!(ask(ppp, along(215.0)), (Some(CirclePosition::On), 1));
        // (double-double decides this one)
        assert_eq!(ask(ppp, along(215.0 + 1e-9)).0, Some(CirclePosition::Inside));
        // two points and a segment ending at one, radius √18: the tangent
        // at (663, 214) and a segment touching the circle from outside
        let pps = [point(663.0, 214.0), point(669.0, 214.0), Site::Segment { a: p(666.0, 217.0), b: p(669.0, 214.0) }];
        assert_eq!(ask(pps, Reach::Entering { from: p(663.0, 214.0), to: p(666.0, 217.0) }), (Some(CirclePosition::On), 1));
        // the segment from (663, 214) through the centre (666, 211) enters
        assert_eq!(ask(pps, Reach::Entering { from: p(663.0, 214.0), to: p(669.0, 208.0) }).0, Some(CirclePosition::Inside));
        // a segment at distance 3 from the centre of a circle of radius √18
        // through the points (3, 3) off it: inside, whatever the stage
        let chord = Reach::Distance { a: p(660.0, 208.0), b: p(672.0, 208.0) };
        assert_eq!(ask(pps, chord).0, Some(CirclePosition::Inside));
    }

    /// The exact answer for three lines and a fourth (`tangent_lines`),
    /// wherever it answers, against the radical tower, on the chords of
    /// 16-gons inscribed in circles and rounded to integers (mirror
    /// symmetric: many true zeros, as in arcs a CAD program cut into
    /// chords), each triple of chords asked about every other chord.
    #[test]
    fn three_lines_agree_with_the_tower_on_chords_of_circles() {
        let mut rng = crate::splitmix::SplitMix64(16);
        let (mut answered, mut zeros) = (0, 0);
        for _ in 0..6 {
            let (cx, cy) = ((rng.next_u64() % 64) as f64 * 1024.0, (rng.next_u64() % 64) as f64 * 1024.0);
            let r = 4096.0 + (rng.next_u64() % 4096) as f64;
            let corners: Vec<Point> = (0..16)
                .map(|k| {
                    let t = std::f64::consts::PI * k as f64 / 8.0;
                    Point::new((cx + r * t.cos()).round(), (cy + r * t.sin()).round())
                })
                .collect();
            let chords: Vec<(Point, Point)> = (0..16).map(|k| (corners[k], corners[(k + 1) % 16])).collect();
            for i in 0..16 {
                for j in i + 2..16 {
                    for k in j + 2..16 {
                        if (k + 2) % 16 == i || (k + 1) % 16 == i {
                            continue;
                        }
                        let sites = [i, j, k].map(|m| Site::Segment { a: chords[m].0, b: chords[m].1 });
                        let Some((centre, radius)) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]) else { continue };
                        let Some(system) = System::of(&sites, centre) else { continue };
                        for q in (0..16).filter(|q| ![i, j, k].contains(q)) {
                            let question = Reach::Distance { a: chords[q].0, b: chords[q].1 };
                            let Some(fast) = system.three_lines_answer(centre, radius, &question) else { continue };
                            let slow = algebraic_answer(&sites, &question);
                            assert_eq!(Some(fast), slow, "{sites:?} {question:?}");
                            answered += 1;
                            zeros += usize::from(fast == CirclePosition::On);
                        }
                    }
                }
            }
        }
        assert!(answered > 1000 && zeros > 20, "{answered} answered, {zeros} zeros");
    }

    /// The fast exact answer for two points and a line
    /// (`quadratic_vertex`), wherever it answers, against the slow exact
    /// one (the radical tower, else certified big floats), on the vertex
    /// the solvers find for the sites in that order.
    fn check_two_points_line(sites: [Site; 3], question: Reach) -> Result<(), proptest::test_runner::TestCaseError> {
        let Some((centre, _)) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]) else {
            return Ok(());
        };
        let Some(system) = System::of(&sites, centre) else {
            return Ok(());
        };
        let Some(fast) = system.two_points_line_answer(centre, &question) else {
            return Ok(());
        };
        if let Some(slow) = proven_answer(&sites, &question) {
            prop_assert_eq!(fast, slow, "{:?} {:?} centre {:?}", sites, question, centre);
        }
        Ok(())
    }

    /// Two points, a line and a question on a small integer lattice: many
    /// answers exactly zero.
    fn lattice_case() -> impl Strategy<Value = ([Site; 3], Reach)> {
        let coordinate = || -6i32..=6;
        let point = move || (coordinate(), coordinate()).prop_map(|(x, y)| Point::new(f64::from(x), f64::from(y)));
        (point(), point(), point(), point(), point(), point(), 0..6usize, any::<bool>()).prop_map(
            |(p, q, a, b, e, f, order, entering)| {
                let line = Site::Segment { a, b };
                let sites = rotate([Site::Point(p), Site::Point(q), line], order);
                let question = if entering { Reach::Entering { from: p, to: e } } else { Reach::Distance { a: e, b: f } };
                (sites, question)
            },
        )
    }

    /// The sites in one of the six orders.
    fn rotate(sites: [Site; 3], order: usize) -> [Site; 3] {
        let [x, y, z] = sites;
        match order {
            0 => [x, y, z],
            1 => [y, z, x],
            2 => [z, x, y],
            3 => [y, x, z],
            4 => [x, z, y],
            _ => [z, y, x],
        }
    }

    /// Symmetric by construction: the question's segment is the line's
    /// segment reflected in the bisector of the two points (the circle is
    /// symmetric in it, so that line is tangent too), or the segment
    /// leaving a point along the line's direction (as in hatches). The
    /// bisector is axis-parallel or diagonal, so the reflection is exact.
    fn symmetric_case() -> impl Strategy<Value = ([Site; 3], Reach)> {
        let small = || -40i32..=40;
        (small(), small(), 1i32..=6, 0..4usize, small(), small(), small(), small(), 0..6usize, 0..3usize, -2i32..=2).prop_map(
            |(px, py, h, axis, ax, ay, bx, by, order, kind, shift)| {
                let d = [(0, h), (h, 0), (h, h), (h, -h)][axis];
                let f = f64::from;
                let p = Point::new(f(px), f(py));
                let q = Point::new(f(px + d.0), f(py + d.1));
                let (mx, my) = (f(2 * px + d.0) / 2.0, f(2 * py + d.1) / 2.0);
                let dd = f(d.0 * d.0 + d.1 * d.1);
                let reflect = |x: Point| {
                    let k = 2.0 * ((x.x - mx) * f(d.0) + (x.y - my) * f(d.1)) / dd;
                    Point::new(x.x - k * f(d.0), x.y - k * f(d.1))
                };
                let (a, b) = (Point::new(f(ax), f(ay)), Point::new(f(bx), f(by)));
                let sites = rotate([Site::Point(p), Site::Point(q), Site::Segment { a, b }], order);
                let question = match kind {
                    0 => Reach::Distance { a: reflect(a), b: reflect(b) },
                    // the reflected segment moved along itself: its end may
                    // be the nearest point
                    1 => {
                        let (ra, rb) = (reflect(a), reflect(b));
                        let t = f(shift);
                        Reach::Distance { a: Point::new(ra.x + t * (rb.x - ra.x), ra.y + t * (rb.y - ra.y)), b: rb }
                    }
                    _ => Reach::Entering { from: q, to: Point::new(q.x + (b.x - a.x), q.y + (b.y - a.y) + f(shift)) },
                };
                (sites, question)
            },
        )
    }

    /// Coordinates with up to 40 significant bits, at several scales: the
    /// expansions grow several components.
    fn float_case() -> impl Strategy<Value = ([Site; 3], Reach)> {
        let coordinate = || {
            (0u64..(1 << 40), 1u32..=40, -8i32..=8)
                .prop_map(|(m, bits, e)| ((m >> (40 - bits)) as f64) * 2f64.powi(e - bits as i32))
        };
        let point = move || (coordinate(), coordinate()).prop_map(|(x, y)| Point::new(x, y));
        (point(), point(), point(), point(), point(), point(), 0..6usize, any::<bool>()).prop_map(
            |(p, q, a, b, e, f, order, entering)| {
                let sites = rotate([Site::Point(p), Site::Point(q), Site::Segment { a, b }], order);
                let question = if entering { Reach::Entering { from: q, to: e } } else { Reach::Distance { a: e, b: f } };
                (sites, question)
            },
        )
    }

    use proptest::prelude::*;
    use proptest::strategy::ValueTree;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        #[test]
        fn two_points_and_a_line_on_a_lattice_agree_with_the_exact_path((sites, question) in lattice_case()) {
            check_two_points_line(sites, question)?;
        }

        #[test]
        fn two_points_and_a_line_by_symmetry_agree_with_the_exact_path((sites, question) in symmetric_case()) {
            check_two_points_line(sites, question)?;
        }

        #[test]
        fn two_points_and_a_line_in_floats_agree_with_the_exact_path((sites, question) in float_case()) {
            check_two_points_line(sites, question)?;
        }

        #[test]
        fn the_rounded_vertex_check_in_expansions_agrees_with_big_floats((sites, question) in lattice_triple(), nudge in any::<bool>()) {
            check_exact_answer(sites, question, nudge)?;
        }
    }

    /// The rounded-vertex check in expansions against the same in big
    /// floats, on lattice vertices of every kind (many of them exact:
    /// the check then answers, zero included) and on vertices moved by an
    /// ulp.
    fn check_exact_answer(sites: [Site; 3], question: Reach, nudge: bool) -> Result<(), proptest::test_runner::TestCaseError> {
        let Some((centre, radius)) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]) else {
            return Ok(());
        };
        let centre = if nudge { Point::new(centre.x.next_up(), centre.y) } else { centre };
        let Some(system) = System::of(&sites, centre) else {
            return Ok(());
        };
        if let Some(fast) = system.exact_answer_in_expansions(centre, radius, &question) {
            prop_assert_eq!(fast, system.exact_answer_in_big_floats(centre, radius, &question), "{:?} {:?}", sites, question);
        }
        Ok(())
    }

    fn lattice_triple() -> impl Strategy<Value = ([Site; 3], Reach)> {
        let coordinate = || (-8i32..=8).prop_map(|v| f64::from(v) / 2.0);
        let point = move || (coordinate(), coordinate()).prop_map(|(x, y)| Point::new(x, y));
        let site = move || {
            (point(), point(), any::<bool>())
                .prop_map(|(a, b, segment)| if segment && a != b { Site::Segment { a, b } } else { Site::Point(a) })
        };
        (site(), site(), site(), point(), point(), any::<bool>()).prop_map(|(x, y, z, e, f, entering)| {
            let question = if entering { Reach::Entering { from: e, to: f } } else { Reach::Distance { a: e, b: f } };
            ([x, y, z], question)
        })
    }

    /// The symmetric cases are mostly exact zeros, and the fast path
    /// answers them (it is no use if it refuses them).
    #[test]
    fn the_fast_path_answers_symmetric_zeros() {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let (mut zeros, mut answered) = (0, 0);
        for _ in 0..2000 {
            let (sites, question) = symmetric_case().new_tree(&mut runner).unwrap().current();
            let Some((centre, _)) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]) else { continue };
            let Some(system) = System::of(&sites, centre) else { continue };
            if proven_answer(&sites, &question) == Some(CirclePosition::On) {
                zeros += 1;
                answered += usize::from(system.two_points_line_answer(centre, &question) == Some(CirclePosition::On));
            }
        }
        assert!(zeros > 200 && answered == zeros, "{answered} of {zeros} zeros answered");
        // and the random cases are answered too, not only refused
        for (name, strategy) in [("lattice", lattice_case().boxed()), ("float", float_case().boxed())] {
            let (mut asked, mut answered) = (0, 0);
            for _ in 0..2000 {
                let (sites, question) = strategy.new_tree(&mut runner).unwrap().current();
                let Some((centre, _)) = segment_solvers::vertex(&sites[0], &sites[1], &sites[2]) else { continue };
                let Some(system) = System::of(&sites, centre) else { continue };
                asked += 1;
                answered += usize::from(system.two_points_line_answer(centre, &question).is_some());
            }
            assert!(answered * 10 > asked * 9, "{name}: {answered} of {asked} answered");
        }
    }

    #[test]
    fn a_clear_answer_is_taken_from_the_filter() {
        let sites = [point(-1.0, 0.0), point(1.0, 0.0), point(0.0, 1.0)];
        let (a, b) = (Point::new(-3.0, 0.5), Point::new(3.0, 0.5));
        let depth = -0.5;
        assert_eq!(reach(|| sites, Point::new(0.0, 0.0), 1.0, Reach::Distance { a, b }, depth), Some(CirclePosition::Inside));
    }
}
