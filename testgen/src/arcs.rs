//! Circular arcs for the arcs' tests and benchmark.

use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{CircularArc, Point};

/// A random arc inside the unit cell at `(x, y)`, its whole circle in the
/// cell: radius 0.05 to 0.4 about the cell's middle, sweep 0.05π to 1.95π
/// either way, half given by a bulge and half through a point.
pub fn random_arc(rng: &mut SplitMix64, x: f64, y: f64) -> CircularArc {
    loop {
        let c = Point::new(x + 0.5, y + 0.5);
        let r = 0.05 + 0.35 * rng.unit();
        let a0 = 2.0 * std::f64::consts::PI * rng.unit();
        let sweep = (0.05 + 1.9 * rng.unit()) * std::f64::consts::PI * if rng.unit() < 0.5 { 1.0 } else { -1.0 };
        let at = |t: f64| Point::new(c.x + r * t.cos(), c.y + r * t.sin());
        let (s, e) = (at(a0), at(a0 + sweep));
        let arc = if rng.unit() < 0.5 {
            CircularArc::from_bulge(s, e, (sweep / 4.0).tan())
        } else {
            CircularArc::through(s, at(a0 + 0.5 * sweep), e)
        };
        if let Ok(arc) = arc {
            return arc;
        }
    }
}
