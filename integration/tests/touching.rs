//! Input that touches itself exactly (issue 27): an input vertex inside a
//! segment splits it there, in a default build, with nothing moved. Valid
//! OGC polygons whose rings touch at points (a hole touching its shell at a
//! corner or inside an edge, two holes touching, checkerboards of squares
//! touching at corners), T-junctions of polylines and points on segments
//! build; the diagram validates, the pieces map back to their inputs, and
//! the domain, the medial axis and the largest inscribed circle agree with
//! brute force: an exact integer even-odd test on a grid of points
//! (boundary points included), the nearest site of every sample.
//!
//! Every input is made of small integers and placed exactly (mirrored,
//! scaled by a power of two, moved far from the origin), so that touching
//! stays exact and the integer reference stays right.

mod common;

use proptest::prelude::*;
use segvoronoi::{Builder, Diagram, ErrorKind, Location, Point, Site};

/// A point in integer units.
type V = [i64; 2];

/// Polygons (each its rings), open polylines and points, in integer units.
#[derive(Clone, Debug, Default)]
struct Input {
    polygons: Vec<Vec<Vec<V>>>,
    polylines: Vec<Vec<V>>,
    points: Vec<V>,
}

/// An exact placement of integer units: `x -> (±x + t) · 2^k`,
/// `y -> (y + t) · 2^k` (exact for the magnitudes used here: `t` is an
/// integer, far from the input's few units).
#[derive(Clone, Copy, Debug)]
struct Place {
    mirror: bool,
    k: i32,
    t: f64,
}

const PLAIN: Place = Place { mirror: false, k: 0, t: 0.0 };

/// The placements every hand-made case is tried at.
const PLACES: [Place; 6] = [
    PLAIN,
    Place { mirror: true, k: 0, t: 0.0 },
    Place { mirror: false, k: -7, t: 1e6 },
    Place { mirror: true, k: 30, t: -3e9 },
    Place { mirror: true, k: 120, t: 0.0 },
    Place { mirror: false, k: -200, t: 0.0 },
];

impl Place {
    /// A point given in eighths of a unit.
    fn at8(&self, [x, y]: V) -> Point {
        let f = 2f64.powi(self.k);
        let x = x as f64 / 8.0;
        Point::new((if self.mirror { -x } else { x } + self.t) * f, (y as f64 / 8.0 + self.t) * f)
    }

    fn at(&self, [x, y]: V) -> Point {
        self.at8([8 * x, 8 * y])
    }

    fn xy(&self, v: V) -> [f64; 2] {
        let p = self.at(v);
        [p.x, p.y]
    }
}

impl Input {
    fn rings(&self) -> Vec<&Vec<V>> {
        self.polygons.iter().flatten().collect()
    }

    /// Every segment: the rings' (closed), then the polylines'.
    fn segments(&self) -> Vec<[V; 2]> {
        let mut out: Vec<[V; 2]> = Vec::new();
        for ring in self.rings() {
            out.extend((0..ring.len()).map(|k| [ring[k], ring[(k + 1) % ring.len()]]));
        }
        for line in &self.polylines {
            out.extend(line.windows(2).map(|w| [w[0], w[1]]));
        }
        out
    }

    fn builder(&self, place: Place) -> Builder {
        let mut b = Builder::new();
        for polygon in &self.polygons {
            let rings: Vec<Vec<[f64; 2]>> = polygon.iter().map(|r| r.iter().map(|&v| place.xy(v)).collect()).collect();
            b.add_polygon(&rings).expect("a polygon");
        }
        for line in &self.polylines {
            let line: Vec<[f64; 2]> = line.iter().map(|&v| place.xy(v)).collect();
            b.add_polyline(&line).expect("a polyline");
        }
        b.add_points(self.points.iter().map(|&v| place.xy(v))).expect("points");
        b
    }

    /// The (vertex, segment) pairs with the vertex inside the segment, by
    /// brute force in integers (distinct vertices, distinct segments).
    fn touchings(&self) -> usize {
        let mut segments: Vec<[V; 2]> = self.segments().into_iter().map(|[a, b]| if a < b { [a, b] } else { [b, a] }).collect();
        segments.sort_unstable();
        segments.dedup();
        let mut vertices: Vec<V> = segments.iter().flatten().copied().chain(self.points.iter().copied()).collect();
        vertices.sort_unstable();
        vertices.dedup();
        segments.iter().map(|&s| vertices.iter().filter(|&&q| inside(q, s)).count()).sum()
    }
}

fn cross(a: V, b: V, c: V) -> i64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// `q` in the open interior of segment `s`, exactly.
fn inside(q: V, [a, b]: [V; 2]) -> bool {
    let dot = (q[0] - a[0]) * (b[0] - a[0]) + (q[1] - a[1]) * (b[1] - a[1]);
    let len = (b[0] - a[0]).pow(2) + (b[1] - a[1]).pow(2);
    cross(a, b, q) == 0 && 0 < dot && dot < len
}

/// Where `q` (in eighths) lies against the rings by the even-odd rule,
/// exactly, in integers.
fn exact_location(rings: &[&Vec<V>], q: V) -> Location {
    let mut odd = false;
    for ring in rings {
        for k in 0..ring.len() {
            let (a, b) = (ring[k].map(|c| 8 * c), ring[(k + 1) % ring.len()].map(|c| 8 * c));
            let on_line = cross(a, b, q) == 0;
            let within = q[0] >= a[0].min(b[0]) && q[0] <= a[0].max(b[0]) && q[1] >= a[1].min(b[1]) && q[1] <= a[1].max(b[1]);
            if on_line && within {
                return Location::Boundary;
            }
            // a ray to the right, half-open in y
            if (a[1] > q[1]) != (b[1] > q[1]) {
                // q.x < a.x + (q.y - a.y)(b.x - a.x)/(b.y - a.y)
                let den = b[1] - a[1];
                let lhs = (q[0] - a[0]) * den;
                let rhs = (q[1] - a[1]) * (b[0] - a[0]);
                if (den > 0 && lhs < rhs) || (den < 0 && lhs > rhs) {
                    odd = !odd;
                }
            }
        }
    }
    if odd {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// The sites of the input (placed), for brute-force distances.
fn sites(input: &Input, place: Place) -> Vec<Site> {
    let mut out: Vec<Site> = input.segments().iter().map(|&[a, b]| Site::Segment { a: place.at(a), b: place.at(b) }).collect();
    out.extend(input.points.iter().map(|&v| Site::Point(place.at(v))));
    out
}

/// The distance from `q` to the nearest site (in units of the largest
/// difference, so that tiny placements do not underflow).
fn nearest(sites: &[Site], q: Point) -> f64 {
    let distance = |s: &Site| match *s {
        Site::Point(p) => (p.x - q.x).hypot(p.y - q.y),
        Site::Segment { a, b } => common::distance_to_segment(q, [[a.x, a.y], [b.x, b.y]]),
        _ => unreachable!("a point or a segment"),
    };
    sites.iter().map(distance).fold(f64::INFINITY, f64::min)
}

/// The placed rings, for the floating even-odd test away from them.
fn placed_rings(input: &Input, place: Place) -> Vec<Vec<[f64; 2]>> {
    input.rings().iter().map(|r| r.iter().map(|&v| place.xy(v)).collect()).collect()
}

/// Builds `input` at `place` and checks everything against brute force;
/// returns the diagram.
fn check(input: &Input, place: Place) -> Diagram {
    let what = format!("{input:?} at {place:?}");
    let d = input.builder(place).build().unwrap_or_else(|e| panic!("{what}: {e}"));
    d.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
    let segments = input.segments();
    let touchings = input.touchings();
    let stats = d.stats();
    assert_eq!(stats.split_at_vertices, touchings, "{what}");
    assert_eq!(stats.input_segments, segments.len(), "{what}");
    assert_eq!(d.piece_count(), stats.pieces, "{what}");
    assert_eq!((stats.snap_rounds, d.max_split_displacement()), (0, 0.0), "{what}");
    check_pieces(&d, input, place, &what);

    let unit = 2f64.powi(place.k);
    let extent = (segments.iter().flatten().flatten().fold(0.0f64, |m, &c| m.max(c.abs() as f64)) + place.t.abs()) * unit;
    let tol = 1e-12 * extent.max(unit) + 1e-9 * unit;
    let all_sites = sites(input, place);
    let rings = input.rings();
    if rings.is_empty() {
        assert!(!d.has_domain());
        return d;
    }
    let placed = placed_rings(input, place);
    let plain_even_odd = |q: Point| if common::even_odd(&placed, q) { Location::Inside } else { Location::Outside };

    // The domain at every point of a grid of eighths (many on the rings).
    let (mut lo, mut hi) = ([i64::MAX; 2], [i64::MIN; 2]);
    for v in rings.iter().copied().flatten() {
        for c in 0..2 {
            lo[c] = lo[c].min(8 * v[c] - 8);
            hi[c] = hi[c].max(8 * v[c] + 8);
        }
    }
    let step = ((hi[0] - lo[0]).max(hi[1] - lo[1]) / 60).max(1);
    for x in (lo[0]..=hi[0]).step_by(step as usize) {
        for y in (lo[1]..=hi[1]).step_by(step as usize) {
            let expected = exact_location(&rings, [x, y]);
            assert_eq!(d.locate_point(place.at8([x, y])), Some(expected), "{what}: ({x}/8, {y}/8)");
        }
    }
    // and at every ring vertex and the middle of every ring segment
    for &[a, b] in &segments[..rings.iter().map(|r| r.len()).sum::<usize>()] {
        assert_eq!(d.locate_point(place.at(a)), Some(Location::Boundary), "{what}: {a:?}");
        let mid = [4 * (a[0] + b[0]), 4 * (a[1] + b[1])];
        assert_eq!(d.locate_point(place.at8(mid)), Some(Location::Boundary), "{what}: {mid:?}/8");
    }

    // Vertices: on the boundary only at the rings; elsewhere where the
    // even-odd rule puts them.
    for v in d.vertices() {
        let location = d.vertex_location(v.id).unwrap();
        let away = nearest(&all_sites, v.position);
        let to_rings = placed_ring_distance(&placed, v.position);
        if location == Location::Boundary {
            // (or one whose edges are all at straight corners, whose cells
            // are pieces of perpendiculars: said to be on the boundary)
            let straight =
                || v.sites.iter().any(|&s| matches!(d.site(s), Some(Site::Point(p)) if straight_corner(input, place, p)));
            assert!(to_rings <= tol || straight(), "{what}: boundary vertex {v:?} {to_rings} off the rings");
        } else if to_rings > tol && away > tol {
            assert_eq!(location, plain_even_odd(v.position), "{what}: vertex {v:?}");
        }
    }
    // Edges: where their middle point is, when it is off the rings.
    for e in d.edges().filter(|e| !e.is_infinite()) {
        let points = d.edge_polyline(e.id, 1e-3 * unit).unwrap();
        let q = points[points.len() / 2];
        let (a, b) = (points[0], points[points.len() - 1]);
        let q = if points.len() > 2 { q } else { Point::new(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)) };
        if placed_ring_distance(&placed, q) > tol {
            let location = d.edge_location(e.id);
            // (a separator at a straight corner, the corner's cell a piece
            // of the perpendicular, is said to be on the boundary)
            let straight =
                || e.sites.iter().any(|&s| matches!(d.site(s), Some(Site::Point(p)) if straight_corner(input, place, p)));
            if location != Some(Location::Boundary) || !straight() {
                assert_eq!(location, Some(plain_even_odd(q)), "{what}: edge {:?} at {q:?}", e.id);
            }
        }
    }
    // Cells of ring segments and corners are on the boundary.
    for s in 0..d.site_count() {
        let s = segvoronoi::SiteId::from_index(s);
        let on_rings = match d.site(s).unwrap() {
            Site::Point(p) => placed_ring_distance(&placed, p) == 0.0,
            Site::Segment { a, b } => {
                placed_ring_distance(&placed, a) == 0.0
                    && placed_ring_distance(&placed, b) == 0.0
                    && placed_ring_distance(&placed, Point::new(0.5 * (a.x + b.x), 0.5 * (a.y + b.y))) <= tol
            }
            _ => unreachable!("a point or a segment"),
        };
        if on_rings {
            assert_eq!(d.cell_location(s), Some(Location::Boundary), "{what}: cell of {:?}", d.site(s));
        }
    }

    // The medial axis: every sample inside, at its clearance.
    let axis = d.medial_axis();
    assert!(!axis.chains.is_empty(), "{what}");
    for chain in &axis.chains {
        for [x, y, r] in d.sample_chain(chain, 1e-3 * unit).expect("finite in a bounded domain") {
            let q = Point::new(x, y);
            let n = nearest(&all_sites, q);
            assert!((n - r).abs() <= tol + 1e-9 * r, "{what}: clearance {r}, nearest {n} at {q:?}");
            if r > tol {
                assert_eq!(d.locate_point(q), Some(Location::Inside), "{what}: axis sample {q:?} (r {r})");
            }
        }
    }
    // The largest inscribed circle: inside, at its clearance, and no
    // point of the grid inside the domain has a larger one.
    let (c, r) = d.max_inscribed_circle().expect("a bounded domain");
    assert!((nearest(&all_sites, c) - r).abs() <= tol + 1e-9 * r, "{what}: circle {c:?} {r}");
    assert_eq!(d.locate_point(c), Some(Location::Inside), "{what}: circle centre {c:?}");
    for x in (lo[0]..=hi[0]).step_by(step as usize) {
        for y in (lo[1]..=hi[1]).step_by(step as usize) {
            if exact_location(&rings, [x, y]) == Location::Inside {
                let q = place.at8([x, y]);
                let n = nearest(&all_sites, q);
                assert!(n <= r + tol + 1e-9 * r, "{what}: ({x}/8, {y}/8) has clearance {n} > {r}");
            }
        }
    }
    d
}

/// Whether `p` is a straight corner of the rings: exactly two segments
/// (pieces) end there, the rings', in opposite directions, and nothing else.
fn straight_corner(input: &Input, place: Place, p: Point) -> bool {
    let Some(v) = input.segments().iter().flatten().copied().chain(input.points.iter().copied()).find(|&v| place.at(v) == p)
    else {
        return false;
    };
    let rings = input.rings().iter().map(|r| r.len()).sum::<usize>();
    let mut directions: Vec<V> = Vec::new();
    for (k, &[a, b]) in input.segments().iter().enumerate() {
        let ways: Vec<V> = if v == a {
            vec![b]
        } else if v == b {
            vec![a]
        } else if inside(v, [a, b]) {
            vec![a, b]
        } else {
            continue;
        };
        if k >= rings {
            return false; // a polyline ends or passes here
        }
        directions.extend(ways.iter().map(|w| [w[0] - v[0], w[1] - v[1]]));
    }
    directions.len() == 2 && cross([0, 0], directions[0], directions[1]) == 0
}

/// Distance from `q` to the nearest placed ring segment.
fn placed_ring_distance(rings: &[Vec<[f64; 2]>], q: Point) -> f64 {
    let mut best = f64::INFINITY;
    for ring in rings {
        for k in 0..ring.len() {
            best = best.min(common::distance_to_segment(q, [ring[k], ring[(k + 1) % ring.len()]]));
        }
    }
    best
}

/// The pieces: each input segment's pieces run from its first end to its
/// second through input vertices on it, each piece names it alone, and its
/// site is a segment with those ends; a segment touched by nothing is one
/// piece.
fn check_pieces(d: &Diagram, input: &Input, place: Place, what: &str) {
    let segments = input.segments();
    let mut vertices: Vec<V> = segments.iter().flatten().copied().chain(input.points.iter().copied()).collect();
    vertices.sort_unstable();
    vertices.dedup();
    let mut total = 0;
    for (j, &[a, b]) in segments.iter().enumerate() {
        let pieces: Vec<usize> = d.pieces_of_input(j).collect();
        let cuts: Vec<V> = vertices.iter().copied().filter(|&q| inside(q, [a, b])).collect();
        assert_eq!(pieces.len(), cuts.len() + 1, "{what}: segment {j}");
        assert!(pieces.windows(2).all(|w| w[1] == w[0] + 1), "{what}: pieces of {j} are consecutive");
        let mut at = place.at(a);
        for &p in &pieces {
            assert_eq!(d.inputs_of_piece(p).collect::<Vec<_>>(), vec![j], "{what}: piece {p}");
            let [s, t] = d.piece(p).unwrap();
            assert_eq!(s, at, "{what}: piece {p} of {j} starts where the one before ended");
            assert!(cuts.iter().any(|&q| place.at(q) == t) || t == place.at(b), "{what}: piece {p} ends at a vertex");
            let site = d.site_of_segment(p).unwrap();
            assert!(matches!(d.site(site), Some(Site::Segment { .. })), "{what}");
            let [e0, e1] = d.segment_endpoints(site).unwrap().map(|e| d.site(e).unwrap());
            let ends = [Site::Point(s), Site::Point(t)];
            assert!([e0, e1] == ends || [e1, e0] == ends, "{what}: piece {p}'s site");
            at = t;
        }
        assert_eq!(at, place.at(b), "{what}: segment {j} ends at its end");
        total += pieces.len();
    }
    assert_eq!(total, d.piece_count(), "{what}");
    for (i, &v) in input.points.iter().enumerate() {
        assert_eq!(d.site(d.site_of_input(i).unwrap()), Some(Site::Point(place.at(v))), "{what}: point {i}");
    }
}

fn square(x: i64, y: i64, side: i64) -> Vec<V> {
    vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
}

fn polygon(rings: Vec<Vec<V>>) -> Input {
    Input { polygons: vec![rings], ..Input::default() }
}

fn check_everywhere(input: &Input) {
    for place in PLACES {
        check(input, place);
        // rings reversed, polygons in the other order
        let mut other = input.clone();
        other.polygons.reverse();
        for ring in other.polygons.iter_mut().flatten() {
            ring.reverse();
        }
        check(&other, place);
    }
}

#[test]
fn the_issue_s_polygon_builds_exactly() {
    // POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (0 5, 3 4, 3 6, 0 5))
    let input = polygon(vec![square(0, 0, 10), vec![[0, 5], [3, 4], [3, 6]]]);
    let d = check(&input, PLAIN);
    assert_eq!((d.stats().split_at_vertices, d.stats().pieces), (1, 8));
    // the shell's left edge (segment 3, from (0, 10) to (0, 0)) is two pieces
    assert_eq!(d.pieces_of_input(3).collect::<Vec<_>>(), vec![3, 4]);
    assert_eq!(d.piece(3), Some([Point::new(0.0, 10.0), Point::new(0.0, 5.0)]));
    assert_eq!(d.piece(4), Some([Point::new(0.0, 5.0), Point::new(0.0, 0.0)]));
    // the hole's segments follow, one piece each
    assert_eq!(d.pieces_of_input(4).collect::<Vec<_>>(), vec![5]);
    check_everywhere(&input);
}

/// The minimal case of a corner shared by two rings: the shell's straight
/// corner (0, 5) is the hole's corner too, so the point's cell lies in the
/// one wedge of at least a half turn there, outside the shell; with a point
/// outside, the separators there end at finite vertices, which must be
/// outside (they were inside when the hole's corner alone said where the
/// cell lies).
#[test]
fn cell_of_a_point_where_rings_touch() {
    let input = Input { points: vec![[-4, 5]], ..polygon(vec![square(0, 0, 10), vec![[0, 5], [3, 4], [3, 6]]]) };
    let d = input.builder(PLAIN).build().unwrap();
    let outside = d.vertices().filter(|v| v.position.x < 0.0).collect::<Vec<_>>();
    assert!(!outside.is_empty());
    for v in outside {
        assert_eq!(d.vertex_location(v.id), Some(Location::Outside), "{v:?}");
    }
    check_everywhere(&input);
    // an obstacle ending inside a ring's edge, inside and outside
    let input = Input { polylines: vec![vec![[10, 4], [13, 4]], vec![[6, 10], [6, 7]]], ..polygon(vec![square(0, 0, 10)]) };
    check_everywhere(&input);
}

#[test]
fn hole_touching_its_shell_at_a_corner_and_inside_an_edge() {
    check_everywhere(&polygon(vec![square(0, 0, 10), vec![[0, 0], [3, 5], [5, 3]]]));
    check_everywhere(&polygon(vec![square(0, 0, 10), vec![[4, 0], [6, 3], [2, 3]]]));
    // touching two edges of the shell, and one hole touching it at a corner
    check_everywhere(&polygon(vec![
        square(0, 0, 10),
        vec![[0, 4], [5, 0], [5, 4]],
        vec![[10, 10], [7, 8], [8, 7]],
        vec![[6, 10], [5, 7], [4, 10 - 1]],
    ]));
}

/// A hole all of whose corners lie on its shell (a diamond in a square,
/// the domain four triangles): no corner of the hole tells which side of
/// the shell it is on; where its sides leave them does.
#[test]
fn a_hole_touching_its_shell_at_every_corner() {
    check_everywhere(&polygon(vec![square(0, 0, 4), vec![[4, 2], [2, 4], [0, 2], [2, 0]]]));
    check_everywhere(&polygon(vec![square(0, 0, 6), vec![[0, 0], [6, 3], [3, 6]]]));
}

#[test]
fn two_holes_touching() {
    // at a corner of both
    check_everywhere(&polygon(vec![square(0, 0, 10), vec![[2, 2], [5, 2], [2, 5]], vec![[5, 2], [8, 3], [6, 6]]]));
    // a corner of one inside an edge of the other
    check_everywhere(&polygon(vec![square(0, 0, 8), vec![[2, 2], [6, 2], [2, 6]], vec![[4, 4], [6, 4], [4, 6]]]));
    // a chain of three: each touching the next, the last touching the shell
    check_everywhere(&polygon(vec![
        square(0, 0, 12),
        vec![[2, 2], [4, 2], [3, 4]],
        vec![[4, 2], [6, 2], [5, 4]],
        vec![[6, 2], [12, 1], [8, 4]],
    ]));
}

#[test]
fn checkerboards() {
    for n in [2, 3] {
        let squares: Vec<Vec<Vec<V>>> = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .filter(|(i, j)| (i + j) % 2 == 0)
            .map(|(i, j)| vec![square(2 * i, 2 * j, 2)])
            .collect();
        // as a MultiPolygon (one polygon per square) and as one polygon's rings
        let multi = Input { polygons: squares.clone(), ..Input::default() };
        let d = check(&multi, PLAIN);
        assert_eq!(d.stats().split_at_vertices, 0);
        check_everywhere(&multi);
        check_everywhere(&polygon(squares.into_iter().flatten().collect()));
    }
    // diamonds' corners inside a square's edges
    let input = Input {
        polygons: vec![
            vec![square(0, 0, 4)],
            vec![vec![[4, 2], [5, 1], [6, 2], [5, 3]]],
            vec![vec![[2, 4], [3, 5], [2, 6], [1, 5]]],
        ],
        ..Input::default()
    };
    let d = check(&input, PLAIN);
    assert_eq!(d.stats().split_at_vertices, 2);
    check_everywhere(&input);
}

#[test]
fn t_junctions_of_polylines_and_points_on_segments() {
    // a T of two polylines and a point on the bar, beside a polygon; a
    // polyline ending inside a ring's edge; a point on a ring's edge
    let input = Input {
        polygons: vec![vec![square(0, 0, 8)]],
        polylines: vec![vec![[10, 0], [14, 0]], vec![[12, 0], [12, 3]], vec![[8, 4], [11, 4]], vec![[2, 2], [2, 6], [6, 6]]],
        points: vec![[13, 0], [4, 0], [9, 9], [2, 4], [0, 0]],
    };
    let d = check(&input, PLAIN);
    // (12, 0) and (13, 0) on the bar, (8, 4) on the square's right edge,
    // (4, 0) on its bottom edge, (2, 4) on the inner polyline
    assert_eq!(d.stats().split_at_vertices, 5);
    for place in PLACES {
        check(&input, place);
    }
    // polylines alone: no domain, still built and mapped
    let lines = Input { polylines: input.polylines.clone(), points: input.points.clone(), ..Input::default() };
    for place in PLACES {
        check(&lines, place);
    }
}

#[test]
fn shared_stretches_cancel_and_crossings_are_refused() {
    // two squares of one MultiPolygon sharing part of an edge, two rings
    // of one polygon sharing a whole edge, a hole along its shell's edge,
    // a spike out and back: the shared stretches cancel (tests/
    // shared_stretches.rs checks the domains)
    let cases = [
        Input { polygons: vec![vec![square(0, 0, 4)], vec![square(4, 1, 2)]], ..Input::default() },
        polygon(vec![square(0, 0, 10), vec![[0, 2], [3, 2], [3, 4], [0, 4]], vec![[0, 2], [0, 4], [-1, 3]]]),
        polygon(vec![square(0, 0, 10), vec![[0, 2], [3, 2], [3, 4], [0, 4]]]),
        polygon(vec![vec![[0, 0], [4, 0], [4, 4], [6, 4], [4, 4], [0, 4]]]),
    ];
    for input in &cases {
        let d = input.builder(PLAIN).build().unwrap_or_else(|e| panic!("{input:?}: {e}"));
        assert_eq!(d.stats().cancelled_ring_pieces, 2, "{input:?}");
        assert!(input.builder(PLAIN).check().is_ok());
    }
    // crossings still need split_crossings
    let input = polygon(vec![square(0, 0, 4), square(2, 2, 4)]);
    let e = input.builder(PLAIN).build().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Intersecting);
    assert!(e.message().contains("cross"), "{}", e.message());
    assert!(input.builder(PLAIN).split_crossings(true).build().is_ok());
    // `check` agrees with `build` on touching (fine)
    assert!(polygon(vec![square(0, 0, 10), vec![[0, 5], [3, 4], [3, 6]]]).builder(PLAIN).check().is_ok());
}

// ---- random touching configurations ----

/// One cell of a checkerboard: a square of side 4 at `(4i, 4j)`, with
/// holes touching it or each other.
#[derive(Clone, Copy, Debug)]
enum Holes {
    None,
    /// A triangle with one corner on the square's boundary at `a` (0..=4)
    /// along the bottom edge, turned by `turn` quarter turns.
    OnEdge {
        a: i64,
        turn: u8,
    },
    /// Two triangles touching at a corner of both.
    CornerToCorner {
        turn: u8,
    },
    /// A triangle's corner inside the other's edge.
    CornerOnEdge {
        turn: u8,
    },
}

fn turned([x, y]: V, turn: u8) -> V {
    match turn % 4 {
        0 => [x, y],
        1 => [4 - y, x],
        2 => [4 - x, 4 - y],
        _ => [y, 4 - x],
    }
}

fn cell(i: i64, j: i64, holes: Holes) -> Vec<Vec<V>> {
    let at = |v: V, turn: u8| {
        let [x, y] = turned(v, turn);
        [4 * i + x, 4 * j + y]
    };
    let mut rings = vec![square(4 * i, 4 * j, 4)];
    let tri = |vs: [V; 3], turn: u8| vs.iter().map(|&v| at(v, turn)).collect::<Vec<V>>();
    match holes {
        Holes::None => {}
        Holes::OnEdge { a, turn } => rings.push(tri([[a, 0], [1, 2], [3, 3]], turn)),
        Holes::CornerToCorner { turn } => {
            rings.push(tri([[1, 1], [2, 2], [1, 3]], turn));
            rings.push(tri([[2, 2], [3, 1], [3, 3]], turn));
        }
        Holes::CornerOnEdge { turn } => {
            rings.push(tri([[1, 1], [3, 1], [1, 3]], turn));
            rings.push(tri([[2, 2], [3, 2], [2, 3]], turn));
        }
    }
    rings
}

fn holes() -> impl Strategy<Value = Holes> {
    prop_oneof![
        Just(Holes::None),
        (0i64..=4, 0u8..4).prop_map(|(a, turn)| Holes::OnEdge { a, turn }),
        (0u8..4).prop_map(|turn| Holes::CornerToCorner { turn }),
        (0u8..4).prop_map(|turn| Holes::CornerOnEdge { turn }),
    ]
}

/// A random checkerboard of up to 4 × 4 cells (the black ones present or
/// not), each with touching holes, as a MultiPolygon or one polygon; points
/// on the squares' edges; in any order.
fn touching_input() -> impl Strategy<Value = Input> {
    (
        1i64..=4,
        prop::collection::vec((any::<bool>(), holes()), 16),
        any::<bool>(),
        prop::collection::vec((0i64..4, 0i64..4, 0i64..=4, 0u8..4), 0..4),
    )
        .prop_map(|(n, cells, one_polygon, points)| {
            let mut polygons = Vec::new();
            for i in 0..n {
                for j in 0..n {
                    let (present, holes) = cells[(i * 4 + j) as usize];
                    if (i + j) % 2 == 0 && (present || polygons.is_empty()) {
                        polygons.push(cell(i, j, holes));
                    }
                }
            }
            if one_polygon {
                polygons = vec![polygons.into_iter().flatten().collect()];
            }
            // points on the bottom edge of a cell, turned
            let points = points
                .into_iter()
                .map(|(i, j, a, turn)| {
                    let [x, y] = turned([a, 0], turn);
                    [4 * (i % n) + x, 4 * (j % n) + y]
                })
                .collect();
            Input { polygons, polylines: Vec::new(), points }
        })
        .prop_shuffle_polygons()
}

trait ShufflePolygons {
    fn prop_shuffle_polygons(self) -> BoxedStrategy<Input>;
}

impl<S: Strategy<Value = Input> + 'static> ShufflePolygons for S {
    /// The polygons in a random order, and some rings reversed.
    fn prop_shuffle_polygons(self) -> BoxedStrategy<Input> {
        self.prop_flat_map(|input| {
            let n = input.polygons.len();
            (Just(input), Just((0..n).collect::<Vec<usize>>()).prop_shuffle(), prop::collection::vec(any::<bool>(), 64))
        })
        .prop_map(|(input, order, reverse)| {
            let mut polygons: Vec<Vec<Vec<V>>> = order.iter().map(|&k| input.polygons[k].clone()).collect();
            for (k, ring) in polygons.iter_mut().flatten().enumerate() {
                if reverse[k % reverse.len()] {
                    ring.reverse();
                }
            }
            Input { polygons, ..input }
        })
        .boxed()
    }
}

fn place() -> impl Strategy<Value = Place> {
    (any::<bool>(), prop::sample::select(vec![0, -3, 5, 40, -150]), prop::sample::select(vec![0.0, 1e6, -2.5e7]))
        .prop_map(|(mirror, k, t)| Place { mirror, k, t })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Random touching rings (reversed, shuffled, mirrored, scaled by powers
    /// of two, moved far from the origin): the diagram validates, the
    /// pieces map back, and the domain, the medial axis and the largest
    /// circle agree with brute force.
    #[test]
    fn random_touching_rings(input in touching_input(), place in place()) {
        check(&input, place);
    }
}

/// Repeated segments (either direction) cut at the same vertices share
/// their pieces' sites, piece by piece; a zero-length segment inside a
/// segment cuts it and is its point.
#[test]
fn repeated_and_zero_length_segments() {
    let mut b = Builder::new();
    b.add_segments([
        [[0.0, 0.0], [4.0, 0.0]],
        [[4.0, 0.0], [0.0, 0.0]],
        [[2.0, 0.0], [2.0, 3.0]],
        [[3.0, 0.0], [3.0, 0.0]],
        [[0.0, 0.0], [4.0, 0.0]],
    ])
    .unwrap();
    b.add_point([1.0, 0.0]).unwrap();
    let d = b.build().unwrap();
    d.validate().unwrap();
    let stats = d.stats();
    // (1, 0), (2, 0) and (3, 0) cut segment 0 (its repeats share the cuts)
    assert_eq!((stats.split_at_vertices, stats.duplicate_segments, stats.zero_length_segments), (3, 2, 1));
    assert_eq!(d.piece_count(), 4 + 4 + 1 + 1 + 4);
    let pieces = |i: usize| d.pieces_of_input(i).collect::<Vec<_>>();
    assert_eq!(pieces(0), vec![0, 1, 2, 3]);
    assert_eq!(pieces(1), vec![4, 5, 6, 7]);
    assert_eq!(pieces(3), vec![9]);
    let site = |p: usize| d.site_of_segment(p).unwrap();
    for k in 0..4 {
        assert_eq!(site(4 + k), site(3 - k), "the reversed repeat, piece {k}");
        assert_eq!(site(10 + k), site(k), "the repeat, piece {k}");
        // (`piece` gives the geometry of the site, the first's)
        assert_eq!(d.piece(4 + k), d.piece(3 - k));
    }
    assert_eq!(d.site(site(9)), Some(Site::Point(Point::new(3.0, 0.0))));
    assert_eq!(d.site(d.site_of_input(0).unwrap()), Some(Site::Point(Point::new(1.0, 0.0))));
    assert_eq!(d.segment_input_index(site(2)), Some(2));
    // five distinct points, and segment sites: four pieces and the stem
    assert_eq!(d.site_count(), 6 + 5);
}
