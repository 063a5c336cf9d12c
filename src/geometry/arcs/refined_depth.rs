//! The second stage of an arc's conflict with a vertex (`arc_predicates::
//! arc_depth` without an endpoint of the arc among the vertex's sites):
//! where the `f64` depth is within the rounding of the vertex and of the
//! circles, the vertex is found again in big floats and the depth taken
//! there.
//!
//! The vertex is the circle tangent to its three sites, each at the feature
//! the `f64` vertex touches (a point, an endpoint, a segment's line, an
//! arc's exact circle from outside or inside: `Feature`). Newton's method
//! on the three equations `distance(x, feature) = t` from the `f64` vertex
//! doubles the correct bits each step: five steps at 320 bits take an `f64`
//! start to far beyond 2^-200 of the vertex's size. Arcs are their exact
//! circles (`arc_contact::circle_in_bigfloat`, from the endpoints and the
//! datum), not the `f64` roundings every other stage uses.
//!
//! Strength: not a proof. The depth at 320 bits decides when it exceeds
//! 2^-200 of the vertex's size and coordinates; below that it is taken as
//! the tie it almost surely is (equal rounded rectangles in a grid, arcs
//! on one circle, concentric arcs), answered "touches", never "enters".
//! Two sites touched at one point (a vertex at a shared endpoint) leave
//! Newton's system singular: such vertices keep the `f64` answer.

use crate::geometry::arc::CircularArc;
use crate::geometry::arithmetic::bigfloat::BigFloat;
use crate::geometry::input::arc_contact::circle_in_bigfloat;
use crate::geometry::point::Point;
use crate::geometry::site::{segment_parameter, Site};

/// The precision of the refinement.
const BITS: u64 = 320;

/// Below this share of the vertex's size and coordinates a refined depth
/// is a tie.
const TIE_EXPONENT: i64 = -200;

/// Where the `f64` depth needs the refinement: within this share of the
/// vertex's size and coordinates (the solver's vertices and the arcs'
/// rounded circles are good to some 2^-45 of them).
const NEAR: f64 = 1.0 / (1u64 << 36) as f64;

/// The part of a site a vertex touches, in big floats.
enum Feature {
    /// A point (a point site or a piece's endpoint).
    Point(BigFloat, BigFloat),
    /// A segment's line, with the unit normal toward the vertex.
    Line { ax: BigFloat, ay: BigFloat, nx: BigFloat, ny: BigFloat },
    /// An arc's exact circle, touched from outside (`outside`) or inside.
    Circle { cx: BigFloat, cy: BigFloat, r: BigFloat, outside: bool },
}

fn big(x: f64) -> BigFloat {
    BigFloat::from_f64(x, BITS)
}

impl Feature {
    /// The feature of `site` nearest to the `f64` vertex `x`.
    fn of(site: &Site, x: Point) -> Option<Feature> {
        let point = |p: Point| Feature::Point(big(p.x), big(p.y));
        Some(match *site {
            Site::Point(p) => point(p),
            Site::Segment { a, b } => {
                let t = segment_parameter(a, b, x);
                if !(t > 0.0 && t < 1.0) {
                    return Some(point(if a.distance_squared(x) <= b.distance_squared(x) { a } else { b }));
                }
                let (ux, uy) = (&big(b.x) - &big(a.x), &big(b.y) - &big(a.y));
                let length = (&(&ux * &ux) + &(&uy * &uy)).sqrt();
                // the left normal, turned toward the vertex
                let (mut nx, mut ny) = ((-&uy).div(&length), ux.div(&length));
                let side = (b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x);
                if side == 0.0 {
                    return None;
                }
                if side < 0.0 {
                    (nx, ny) = (-&nx, -&ny);
                }
                Feature::Line { ax: big(a.x), ay: big(a.y), nx, ny }
            }
            Site::Arc(arc) if arc.spans(x) => {
                let (cx, cy, r) = circle_in_bigfloat(&arc, BITS);
                let outside = arc.centre().distance(x) > arc.radius();
                Feature::Circle { cx, cy, r, outside }
            }
            Site::Arc(arc) => {
                point(if arc.start().distance_squared(x) <= arc.end().distance_squared(x) { arc.start() } else { arc.end() })
            }
        })
    }

    /// The distance from `(x, y)` and its gradient.
    fn distance(&self, x: &BigFloat, y: &BigFloat) -> (BigFloat, BigFloat, BigFloat) {
        match self {
            Feature::Point(px, py) => {
                let (dx, dy) = (x - px, y - py);
                let d = (&(&dx * &dx) + &(&dy * &dy)).sqrt();
                let (gx, gy) = (dx.div(&d), dy.div(&d));
                (d, gx, gy)
            }
            Feature::Line { ax, ay, nx, ny } => {
                let d = &(&(x - ax) * nx) + &(&(y - ay) * ny);
                (d, nx.clone(), ny.clone())
            }
            Feature::Circle { cx, cy, r, outside } => {
                let (dx, dy) = (x - cx, y - cy);
                let rho = (&(&dx * &dx) + &(&dy * &dy)).sqrt();
                let (gx, gy) = (dx.div(&rho), dy.div(&rho));
                if *outside {
                    (&rho - r, gx, gy)
                } else {
                    (r - &rho, -&gx, -&gy)
                }
            }
        }
    }
}

/// The refined depth of the open `arc` in the circle of the vertex
/// (`centre`, `radius`) of `sites`, none of which is an endpoint of `arc`:
/// `Some(0.0)` for a tie, `Some(±size)` for a decided sign, `None` where
/// the refinement does not apply (see the module).
pub(crate) fn refined_arc_depth(arc: &CircularArc, sites: &[Site; 3], centre: Point, radius: f64) -> Option<f64> {
    let features: Vec<Feature> = sites.iter().map(|s| Feature::of(s, centre)).collect::<Option<_>>()?;
    let (mut x, mut y, mut t) = (big(centre.x), big(centre.y), big(radius));
    for _ in 0..5 {
        // F_i = d_i(x) − t, J_i = (∂d_i/∂x, ∂d_i/∂y, −1): solve J·δ = −F
        // by Cramer's rule, the third column all −1
        let rows: Vec<_> = features.iter().map(|f| f.distance(&x, &y)).collect();
        let f: Vec<BigFloat> = rows.iter().map(|(d, _, _)| d - &t).collect();
        let (g1, g2, g3) = (&rows[0], &rows[1], &rows[2]);
        let det3 = |c1: [&BigFloat; 3], c2: [&BigFloat; 3]| {
            // det [c1 c2 (−1,−1,−1)] = −(c1 × c2)·(1,1,1)
            let m = |i: usize, j: usize| &(c1[i] * c2[j]) - &(c1[j] * c2[i]);
            -&(&(&m(1, 2) + &m(2, 0)) + &m(0, 1))
        };
        let gx = [&g1.1, &g2.1, &g3.1];
        let gy = [&g1.2, &g2.2, &g3.2];
        let det = det3(gx, gy);
        if det.to_f64().abs() < 1e-6 {
            return None;
        }
        let minus_f: Vec<BigFloat> = f.iter().map(|v| -v).collect();
        let rhs = [&minus_f[0], &minus_f[1], &minus_f[2]];
        let dx = det3(rhs, gy).div(&det);
        let dy = det3(gx, rhs).div(&det);
        // the third unknown from the first row: gx·dx + gy·dy − dt = −F
        let dt = &(&(gx[0] * &dx) + &(gy[0] * &dy)) + &f[0];
        x = &x + &dx;
        y = &y + &dy;
        t = &t + &dt;
    }
    if t.signum() < 0 {
        return None;
    }
    let depth = match Feature::of(&Site::Arc(*arc), centre)? {
        Feature::Point(..) => {
            let to = |p: Point| Feature::Point(big(p.x), big(p.y)).distance(&x, &y).0;
            let (s, e) = (to(arc.start()), to(arc.end()));
            let nearer = if (&s - &e).signum() <= 0 { s } else { e };
            &nearer - &t
        }
        circle => {
            let d = circle.distance(&x, &y).0;
            &d.abs() - &t
        }
    };
    let size = radius.abs() + arc.radius() + centre.x.abs().max(centre.y.abs());
    let tie = BigFloat::pow2(TIE_EXPONENT + size.log2().ceil() as i64, BITS);
    if (&depth.abs() - &tie).signum() <= 0 {
        return Some(0.0);
    }
    let value = depth.to_f64();
    Some(if value == 0.0 { depth.signum() as f64 * f64::MIN_POSITIVE } else { value })
}

/// Whether an `f64` depth of the arc in the vertex's circle is close
/// enough to zero to refine.
pub(crate) fn needs_refinement(depth: f64, arc: &CircularArc, centre: Point, radius: f64) -> bool {
    let size = radius.abs() + arc.radius() + centre.x.abs().max(centre.y.abs());
    depth.abs() <= NEAR * size
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// The vertex of three points around the origin at distance `a`, and an
    /// arc on a circle centred on the x axis through `(via_x, 0)`: it
    /// touches the vertex's circle exactly when `via_x == a`, though no
    /// `f64` holds its centre.
    fn touching(a: f64, via_x: f64, scale: f64) -> (CircularArc, [Site; 3]) {
        let s = |x: f64, y: f64| p(x * scale, y * scale);
        let sites = [Site::Point(s(0.0, a)), Site::Point(s(-a, 0.0)), Site::Point(s(0.0, -a))];
        let arc = CircularArc::through(s(0.5, 0.3), s(via_x, 0.0), s(0.5, -0.3)).unwrap();
        (arc, sites)
    }

    #[test]
    fn an_exact_tie_is_a_tie_and_an_ulp_off_is_decided() {
        // the arc's centre (0.4125, 0) · scale is no f64: its f64 depth is
        // rounding noise
        let a = 0.1;
        for scale in [1.0, 3.0, 0.1, 1e-200, 1e200, 2f64.powi(-1000), 2f64.powi(1000)] {
            let r = a * scale;
            let (centre, radius) = (p(0.0, 0.0), r);
            let (arc, sites) = touching(a, a, scale);
            assert_eq!(refined_arc_depth(&arc, &sites, centre, radius), Some(0.0), "scale {scale}");
            let ulp = r * f64::EPSILON;
            for (via, sign) in [(r + ulp, 1.0), (r - ulp, -1.0)] {
                let (arc, sites) = touching(a, via / scale, scale);
                let arc = CircularArc::through(arc.start(), p(via, 0.0), arc.end()).unwrap();
                let depth = refined_arc_depth(&arc, &sites, centre, radius).unwrap();
                assert!(depth * sign > 0.0, "scale {scale}, via {via}: {depth}");
            }
        }
    }

    #[test]
    fn a_clear_depth_keeps_its_sign() {
        // random vertices of a point, a segment and an arc, and random arcs
        // whose f64 depth is clear: the refinement agrees with it
        let mut rng = SplitMix64(11);
        let mut compared = 0;
        for _ in 0..400 {
            let mut v = || rng.unit() * 4.0 - 2.0;
            let arc = CircularArc::from_bulge([v(), v()], [v(), v()], 0.2 + v().abs());
            let other = CircularArc::from_bulge([v(), v()], [v(), v()], -0.3 - v().abs());
            let sites = [Site::Point(p(v(), v())), Site::Segment { a: p(v(), v()), b: p(v(), v()) }, Site::Point(p(v(), v()))];
            let (Ok(arc), Ok(other)) = (arc, other) else { continue };
            let sites = [sites[0], sites[1], Site::Arc(other)];
            let Some((centre, radius)) = super::super::arc_vertex::arc_vertex(&sites) else { continue };
            let depth = arc.distance(centre) - radius;
            if depth.abs() < 1e-6 {
                continue;
            }
            if let Some(refined) = refined_arc_depth(&arc, &sites, centre, radius) {
                assert_eq!(refined.signum(), depth.signum(), "{arc:?} {sites:?}: {depth} vs {refined}");
                compared += 1;
            }
        }
        assert!(compared > 50, "{compared} compared");
    }
}
