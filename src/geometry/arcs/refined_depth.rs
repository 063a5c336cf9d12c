//! The second stage of an arc's conflict with a vertex (`arc_predicates::
//! arc_depth` without an endpoint of the arc among the vertex's sites):
//! where the `f64` depth is within the rounding of the vertex and of the
//! circles, the vertex is found again in double-double and the depth taken
//! there.
//!
//! The vertex is the circle tangent to its three sites, each at the feature
//! the `f64` vertex touches (a point, an endpoint, a segment's line, an
//! arc's circle from outside or inside: `Feature`). Newton's method on the
//! three equations `distance(x, feature) = t` from the `f64` vertex doubles
//! the correct bits each step: four steps in double-double take an `f64`
//! start to the arithmetic's own precision (about 2^-104). Arcs are their
//! circles computed in double-double from the endpoints and the datum
//! (`CircularArc::circle_in`), not the `f64` roundings every other stage
//! uses. (Big floats were tried first: at 320 bits the tangent chains of
//! the benchmark, where nearly every conflict is a tie, took 3.6 times as
//! long.)
//!
//! Strength: not a proof. The refined depth decides when it exceeds 2^-90
//! of the vertex's size and coordinates; below that it is taken as the tie
//! it almost surely is (equal rounded rectangles in a grid, arcs on one
//! circle, concentric arcs), answered "touches", never "enters".
//! Two sites touched at one point (a vertex at a shared endpoint) leave
//! Newton's system singular: such vertices keep the `f64` answer.

use crate::geometry::arc::CircularArc;
use crate::geometry::arithmetic::double_double::DoubleDouble;
use crate::geometry::arithmetic::real::Real;
use crate::geometry::point::Point;
use crate::geometry::site::{segment_parameter, Site};

/// Below this share of the vertex's size and coordinates a refined depth
/// is a tie (double-double leaves some 2^-100 of them after the vertex's
/// Newton steps).
const TIE: f64 = 1.0 / (1u128 << 90) as f64;

/// Where the `f64` depth needs the refinement: within this share of the
/// vertex's size and coordinates (the solver's vertices and the arcs'
/// rounded circles are good to some 2^-45 of them).
const NEAR: f64 = 1.0 / (1u64 << 36) as f64;

/// An arithmetic the refinement runs in, which takes an `f64` exactly.
trait Fine: Real + Copy {
    fn lift(x: f64) -> Self;
}

impl Fine for DoubleDouble {
    fn lift(x: f64) -> DoubleDouble {
        DoubleDouble::from_f64(x)
    }
}

/// An `f64` in the arithmetic `T`.
fn lift<T: Fine>(x: f64) -> T {
    T::lift(x)
}

/// The part of a site a vertex touches, in double-double.
enum Feature<T> {
    /// A point (a point site or a piece's endpoint).
    Point(T, T),
    /// A segment's line, with the unit normal toward the vertex.
    Line { ax: T, ay: T, nx: T, ny: T },
    /// An arc's exact circle, touched from outside (`outside`) or inside.
    Circle { cx: T, cy: T, r: T, outside: bool },
}

impl<T: Fine> Feature<T> {
    /// The feature of `site` nearest to the `f64` vertex `x`.
    fn of(site: &Site, x: Point) -> Option<Feature<T>> {
        let point = |p: Point| Feature::Point(lift::<T>(p.x), lift::<T>(p.y));
        Some(match *site {
            Site::Point(p) => point(p),
            Site::Segment { a, b } => {
                let t = segment_parameter(a, b, x);
                if !(t > 0.0 && t < 1.0) {
                    return Some(point(if a.distance_squared(x) <= b.distance_squared(x) { a } else { b }));
                }
                let (ux, uy) = (lift::<T>(b.x).sub(&lift::<T>(a.x)), lift::<T>(b.y).sub(&lift::<T>(a.y)));
                let length = T::hypot(&ux, &uy);
                let side = (b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x);
                if side == 0.0 {
                    return None;
                }
                // the left normal, turned toward the vertex
                let (nx, ny) = (uy.neg().div(&length), ux.div(&length));
                let (nx, ny) = if side < 0.0 { (nx.neg(), ny.neg()) } else { (nx, ny) };
                Feature::Line { ax: lift::<T>(a.x), ay: lift::<T>(a.y), nx, ny }
            }
            Site::Arc(arc) if arc.spans(x) => {
                let (cx, cy, r) = arc.circle_in(&lift::<T>)?;
                let outside = arc.centre().distance(x) > arc.radius();
                Feature::Circle { cx, cy, r, outside }
            }
            Site::Arc(arc) => {
                point(if arc.start().distance_squared(x) <= arc.end().distance_squared(x) { arc.start() } else { arc.end() })
            }
        })
    }

    /// The distance from `(x, y)` and its gradient.
    fn distance(&self, x: &T, y: &T) -> (T, T, T) {
        match self {
            Feature::Point(px, py) => {
                let (dx, dy) = (x.sub(px), y.sub(py));
                let d = T::hypot(&dx, &dy);
                (d, dx.div(&d), dy.div(&d))
            }
            Feature::Line { ax, ay, nx, ny } => (x.sub(ax).mul(nx).add(&y.sub(ay).mul(ny)), *nx, *ny),
            Feature::Circle { cx, cy, r, outside } => {
                let (dx, dy) = (x.sub(cx), y.sub(cy));
                let rho = T::hypot(&dx, &dy);
                let (gx, gy) = (dx.div(&rho), dy.div(&rho));
                if *outside {
                    (rho.sub(r), gx, gy)
                } else {
                    (r.sub(&rho), gx.neg(), gy.neg())
                }
            }
        }
    }
}

/// The refined depth of the open `arc` in the circle of the vertex
/// (`centre`, `radius`) of `sites`, none of which is an endpoint of `arc`:
/// `Some(0.0)` for a tie, the depth (its sign certain to the refinement)
/// otherwise, `None` where the refinement does not apply (see the module).
pub(crate) fn refined_arc_depth(arc: &CircularArc, sites: &[Site; 3], centre: Point, radius: f64) -> Option<f64> {
    refined_in::<DoubleDouble>(arc, sites, centre, radius)
}

/// [`refined_arc_depth`] in the arithmetic `T`.
fn refined_in<T: Fine>(arc: &CircularArc, sites: &[Site; 3], centre: Point, radius: f64) -> Option<f64> {
    // (arrays, not Vecs: nine allocations a call in the tangent chains,
    // where nearly every conflict is refined)
    let [f0, f1, f2] = sites.each_ref().map(|s| Feature::of(s, centre));
    let features = [f0?, f1?, f2?];
    let (mut x, mut y, mut t) = (lift::<T>(centre.x), lift::<T>(centre.y), lift::<T>(radius));
    for _ in 0..4 {
        // F_i = d_i(x) − t, J_i = (∂d_i/∂x, ∂d_i/∂y, −1): solve J·δ = −F
        // by Cramer's rule, the third column all −1
        let rows: [(T, T, T); 3] = features.each_ref().map(|f| f.distance(&x, &y));
        let minus_f: [T; 3] = rows.map(|(d, _, _)| t.sub(&d));
        let gx = [rows[0].1, rows[1].1, rows[2].1];
        let gy = [rows[0].2, rows[1].2, rows[2].2];
        // det [c1 c2 (−1, −1, −1)] = −(c1 × c2)·(1, 1, 1)
        let det3 = |c1: [T; 3], c2: [T; 3]| {
            let m = |i: usize, j: usize| c1[i].mul(&c2[j]).sub(&c1[j].mul(&c2[i]));
            m(1, 2).add(&m(2, 0)).add(&m(0, 1)).neg()
        };
        let det = det3(gx, gy);
        if !(det.to_f64().abs() >= 1e-6) {
            return None;
        }
        let rhs = [minus_f[0], minus_f[1], minus_f[2]];
        let dx = det3(rhs, gy).div(&det);
        let dy = det3(gx, rhs).div(&det);
        // the third unknown from the first row: gx·dx + gy·dy − dt = −F
        let dt = gx[0].mul(&dx).add(&gy[0].mul(&dy)).sub(&minus_f[0]);
        x = x.add(&dx);
        y = y.add(&dy);
        t = t.add(&dt);
    }
    if t.signum() < 0 || !t.to_f64().is_finite() {
        return None;
    }
    let depth = match Feature::of(&Site::Arc(*arc), centre)? {
        Feature::Point(..) => {
            let to = |p: Point| Feature::<T>::Point(lift::<T>(p.x), lift::<T>(p.y)).distance(&x, &y).0;
            let (s, e) = (to(arc.start()), to(arc.end()));
            let nearer = if s.sub(&e).signum() <= 0 { s } else { e };
            nearer.sub(&t)
        }
        circle => circle.distance(&x, &y).0.abs().sub(&t),
    };
    let size = radius.abs() + arc.radius() + centre.x.abs().max(centre.y.abs());
    let value = depth.to_f64();
    if !value.is_finite() {
        return None;
    }
    Some(if value.abs() <= TIE * size { 0.0 } else { value })
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
        // rounding noise. (Scales as the construction has them, see
        // `geometry::scale`; near 1e±160 the squares leave double-double's
        // range and the refinement declines, keeping the `f64` answer.)
        let a = 0.1;
        for scale in [1.0, 3.0, 0.1, 1e-15, 1e15, 2f64.powi(-60), 2f64.powi(60)] {
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
    fn out_of_range_the_refinement_declines() {
        let (arc, sites) = touching(0.1, 0.1, 1e-200);
        assert_eq!(refined_arc_depth(&arc, &sites, p(0.0, 0.0), 0.1 * 1e-200), None);
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
