//! The built-in demo input: generated, not stored, and the same on every run
//! (a fixed seed). Besides a pleasant picture it exercises the cases that
//! break naive Voronoi code: points on one line, four and more points on one
//! circle (a grid), a repeated point, and line segments: short ones on a
//! jittered grid, a long one alone, and a zigzag polyline whose segments
//! share endpoints.

use segvoronoi::boost_text::Input;

// The demo must not depend on a random-number crate or on the platform:
// the library's SplitMix64.
use segvoronoi::splitmix::SplitMix64;

/// Uniform in `[-1, 1)`.
fn symmetric(rng: &mut SplitMix64) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// About sixty points and a dozen segments (see the module doc).
pub fn input() -> Input {
    let mut rng = SplitMix64(0x5E6_5E60_0003);
    let mut segments = Vec::with_capacity(16);
    // A zigzag above the cluster and the grid: shared endpoints.
    let zigzag = [[-3.0, 6.5], [-1.5, 5.0], [0.0, 6.8], [1.5, 5.2], [3.0, 7.0]];
    for w in zigzag.windows(2) {
        segments.push([w[0][0], w[0][1], w[1][0], w[1][1]]);
    }
    // A long segment alone in the middle.
    segments.push([-2.5, -1.5, 1.5, -0.5]);
    // Short segments in random directions, one per cell of a 3×2 grid of
    // cells 1.5 apart in the lower right, inside the ring and clear of the
    // collinear row: each reaches at most 0.65 from its cell's centre.
    for i in 0..3 {
        for j in 0..2 {
            let centre = [3.1 + 1.5 * i as f64 + 0.1 * symmetric(&mut rng), -2.9 - 1.5 * j as f64 + 0.1 * symmetric(&mut rng)];
            let angle = std::f64::consts::PI * symmetric(&mut rng);
            let half = 0.45 + 0.1 * symmetric(&mut rng);
            let (dx, dy) = (half * angle.cos(), half * angle.sin());
            segments.push([centre[0] - dx, centre[1] - dy, centre[0] + dx, centre[1] + dy]);
        }
    }
    Input { points: points(), segments, ..Input::default() }
}

/// About sixty points: a jittered ring, a tight cluster inside it, a row of
/// collinear points, a 3×3 grid (cocircular quadruples) and one repeat.
fn points() -> Vec<[f64; 2]> {
    let mut rng = SplitMix64(0x5E6_7020_0201);
    let mut points = Vec::with_capacity(64);
    let ring = 36;
    for k in 0..ring {
        let angle = std::f64::consts::TAU * (k as f64 + 0.3 * symmetric(&mut rng)) / ring as f64;
        let radius = 10.0 + 0.7 * symmetric(&mut rng);
        points.push([radius * angle.cos(), radius * angle.sin()]);
    }
    for _ in 0..9 {
        points.push([3.5 + 1.3 * symmetric(&mut rng), 3.0 + 1.3 * symmetric(&mut rng)]);
    }
    // Exactly collinear: integer steps along a line of slope 1/2.
    for k in 0..7 {
        let t = k as f64 - 3.0;
        points.push([-1.0 + 2.0 * t * 0.5, -5.5 + t * 0.5]);
    }
    // A grid: every unit square is four cocircular sites, a degree-4 vertex.
    for i in 0..3 {
        for j in 0..3 {
            points.push([-6.0 + 1.5 * i as f64, 1.0 + 1.5 * j as f64]);
        }
    }
    // A repeated point, merged by the library and counted in the statistics.
    points.push(points[ring]);
    points
}

#[cfg(test)]
mod tests {
    use super::*;

    fn diagram() -> segvoronoi::Diagram {
        let input = input();
        let mut b = segvoronoi::Builder::new();
        b.add_points(input.points).unwrap();
        b.add_segments(input.segments.iter().map(|s| [[s[0], s[1]], [s[2], s[3]]])).unwrap();
        b.build().unwrap()
    }

    #[test]
    fn deterministic_finite_and_about_sixty() {
        let (a, b) = (input(), input());
        assert_eq!(a, b);
        assert!((55..=70).contains(&a.points.len()));
        assert_eq!(a.segments.len(), 11);
        assert!(a.points.iter().flatten().chain(a.segments.iter().flatten()).all(|v| v.is_finite()));
    }

    #[test]
    fn contains_its_degenerate_cases() {
        let diagram = diagram();
        assert!(diagram.validate().is_ok());
        assert_eq!(diagram.stats().duplicate_points, 1);
        // The grid's four unit squares each give a zero-length edge.
        let zero_length = diagram
            .edges()
            .filter(|e| match e.ends {
                [segvoronoi::EdgeEnd::Vertex(a), segvoronoi::EdgeEnd::Vertex(b)] => {
                    let (pa, pb) = (diagram.vertex(a).unwrap().position, diagram.vertex(b).unwrap().position);
                    pa.distance(pb) < 1e-9
                }
                _ => false,
            })
            .count();
        assert!(zero_length >= 4, "{zero_length} zero-length edges");
    }

    #[test]
    fn segments_are_sites_with_parabolic_edges() {
        let diagram = diagram();
        // All eleven segments are distinct open segments; the zigzag's four
        // share three endpoints.
        assert_eq!(diagram.site_count() - diagram.point_site_count(), 11);
        assert_eq!(diagram.point_site_count(), input().points.len() - 1 + 2 * 11 - 3);
        let arcs = diagram.edges().filter(|e| diagram.edge_bezier(e.id).is_some()).count();
        assert!(arcs >= 10, "{arcs} parabolic arcs");
    }
}
