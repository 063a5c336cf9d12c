//! Offsets (`Diagram::offset`, `offsets`) by brute force on generated
//! inputs nobody tuned for: random polygons with holes, polygons inscribed
//! in circles, glyph outlines, and plain sites (random, lattices,
//! cocircular, collinear, parallel and fanned segments), each at several
//! distances including the exact clearances of vertices (pinches and
//! vanishing parts). For every offset:
//! - every loop closes exactly, parents come first, holes run clockwise;
//! - every point of every polyline (on the exact curve) is at the distance
//!   from the nearest site (brute force over all sites), and on the side of
//!   the domain it should be;
//! - the polylines cross neither themselves nor each other;
//! - each loop's nesting depth is the number of loops around it
//!   (even-odd), and its parent the innermost of them;
//! - the region the loops bound is the brute-force region on a grid of
//!   sample points away from its boundary;
//! - the exact area agrees with the polylines' within the tolerance.

mod common;

use segvoronoi::{Builder, Diagram, Location, Offset, Point};
use segvoronoi_testgen as testgen;

/// A case: a diagram, its sites as geometry, and its size.
struct Case {
    name: String,
    diagram: Diagram,
    sites: Vec<segvoronoi::Site>,
    bounds: [f64; 4],
}

impl Case {
    fn new(name: String, diagram: Diagram) -> Case {
        diagram.validate().unwrap();
        let sites: Vec<segvoronoi::Site> = diagram.site_ids().map(|s| diagram.site(s).unwrap()).collect();
        let mut bounds = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
        for s in &sites {
            let ends = match *s {
                segvoronoi::Site::Point(p) => [p, p],
                segvoronoi::Site::Segment { a, b } => [a, b],
                _ => unreachable!(),
            };
            for p in ends {
                bounds = [bounds[0].min(p.x), bounds[1].min(p.y), bounds[2].max(p.x), bounds[3].max(p.y)];
            }
        }
        Case { name, diagram, sites, bounds }
    }

    fn size(&self) -> f64 {
        (self.bounds[2] - self.bounds[0]).hypot(self.bounds[3] - self.bounds[1]).max(f64::MIN_POSITIVE)
    }

    fn distance(&self, p: Point) -> f64 {
        self.sites.iter().map(|s| s.distance(p)).fold(f64::INFINITY, f64::min)
    }

    /// Whether `p` is in the region of the offset at `d`, by brute force.
    fn in_region(&self, p: Point, d: f64) -> bool {
        let near = self.distance(p) < d.abs();
        match self.diagram.locate_point(p) {
            None => near,
            Some(l) if d > 0.0 => l == Location::Inside || near,
            Some(l) => l == Location::Inside && !near,
        }
    }
}

fn from_rings(name: String, rings: &[Vec<[f64; 2]>]) -> Case {
    let mut b = Builder::new();
    b.add_polygon(rings).unwrap();
    Case::new(name, b.build().unwrap())
}

fn from_sites(name: String, input: &testgen::Input) -> Case {
    let mut b = Builder::new();
    b.add_points(input.points.iter().copied()).unwrap();
    for s in &input.segments {
        b.add_segment(*s).unwrap();
    }
    Case::new(name, b.build().unwrap())
}

/// Distances for a case: fractions of its size and of its largest vertex
/// clearance, and the exact clearances of a few vertices.
fn distances(case: &Case, with_domain: bool, seed: u64) -> Vec<f64> {
    let d = &case.diagram;
    let mut clearances: Vec<f64> = d
        .vertices()
        .filter(|v| v.clearance > 0.0 && v.clearance.is_finite())
        .filter(|v| !with_domain || d.vertex_location(v.id) == Some(Location::Inside))
        .map(|v| v.clearance)
        .collect();
    clearances.sort_by(f64::total_cmp);
    let largest = clearances.last().copied().unwrap_or(case.size() / 4.0);
    let mut out = vec![largest * 0.1, largest * 0.45, largest * 0.9, case.size() * 0.05, case.size() * 0.3];
    let mut rng = testgen::Rng(seed);
    for _ in 0..3 {
        if !clearances.is_empty() {
            out.push(clearances[rng.below(clearances.len())]);
        }
    }
    if with_domain {
        let shrink: Vec<f64> = out.iter().filter(|&&r| r < largest * 1.01).map(|r| -r).collect();
        out.extend(shrink);
    }
    out
}

/// Whether segments `ab` and `cd` cross properly, each end more than `tol`
/// from the other's line (a crossing within rounding is a touch).
fn cross(a: Point, b: Point, c: Point, d: Point, tol: f64) -> bool {
    let side = |p: Point, q: Point, r: Point| {
        let length = p.distance(q);
        ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)) / length
    };
    let (d1, d2, d3, d4) = (side(a, b, c), side(a, b, d), side(c, d, a), side(c, d, b));
    let clear = [d1, d2, d3, d4].iter().all(|x| x.abs() > tol);
    clear && d1 * d2 < 0.0 && d3 * d4 < 0.0
}

fn contains(polyline: &[Point], p: Point) -> bool {
    let mut inside = false;
    for k in 0..polyline.len() {
        let (a, b) = (polyline[k], polyline[(k + 1) % polyline.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            inside = !inside;
        }
    }
    inside
}

fn check(case: &Case, offset: &Offset) {
    let what = format!("{} at {}", case.name, offset.distance);
    let r = offset.distance.abs();
    let size = case.size();
    let tolerance = 1e-6 * (size + r);
    // closed, ordered, oriented
    for (k, l) in offset.loops.iter().enumerate() {
        for (i, p) in l.pieces.iter().enumerate() {
            assert_eq!(p.to(), l.pieces[(i + 1) % l.pieces.len()].from(), "{what}: loop {k} piece {i} does not close");
        }
        if let Some(p) = l.parent {
            assert!(p < k, "{what}: parent after child");
        }
        let area = l.signed_area();
        assert_eq!(l.hole, area < 0.0, "{what}: loop {k} hole {} area {area}", l.hole);
    }
    let polylines = offset.polylines(tolerance).unwrap();
    // on the level, on the right side of the domain
    for (k, line) in polylines.iter().enumerate() {
        for &p in line {
            let dist = case.distance(p);
            // within 1e-9 of the offset's bounding box
            assert!((dist - r).abs() <= 1e-9 * (size + 2.0 * r), "{what}: loop {k} point {p:?} at {dist}");
            if let Some(l) = case.diagram.locate_point(p) {
                let want = if offset.distance > 0.0 { Location::Outside } else { Location::Inside };
                assert_eq!(l, want, "{what}: loop {k} point {p:?}");
            }
        }
    }
    // simple and disjoint
    let mut segments: Vec<(Point, Point, usize)> = Vec::new();
    for (k, line) in polylines.iter().enumerate() {
        for i in 0..line.len() {
            segments.push((line[i], line[(i + 1) % line.len()], k));
        }
    }
    segments.sort_by(|a, b| a.0.x.min(a.1.x).total_cmp(&b.0.x.min(b.1.x)));
    for i in 0..segments.len() {
        let (a, b, _) = segments[i];
        let right = a.x.max(b.x);
        for &(c, d, _) in segments[i + 1..].iter().take_while(|s| s.0.x.min(s.1.x) <= right) {
            assert!(!cross(a, b, c, d, 1e-9 * (size + r)), "{what}: {a:?}-{b:?} crosses {c:?}-{d:?}");
        }
    }
    // nesting against even-odd containment
    let depth_of = |k: usize| {
        let mut depth = 0;
        let mut at = offset.loops[k].parent;
        while let Some(p) = at {
            depth += 1;
            at = offset.loops[p].parent;
        }
        depth
    };
    for (k, line) in polylines.iter().enumerate() {
        // a point just left of the middle of its longest chord: in the
        // loop's own region, so inside exactly its ancestors (and itself
        // when it is an outer boundary)
        let i = (0..line.len()).max_by(|&i, &j| {
            let len = |i: usize| line[i].distance(line[(i + 1) % line.len()]);
            len(i).total_cmp(&len(j))
        });
        let Some(i) = i else { continue };
        let (a, b) = (line[i], line[(i + 1) % line.len()]);
        let left = 1e-4;
        let probe = Point::new((a.x + b.x) / 2.0 - (b.y - a.y) * left, (a.y + b.y) / 2.0 + (b.x - a.x) * left);
        let around: Vec<usize> = (0..polylines.len()).filter(|&o| o != k && contains(&polylines[o], probe)).collect();
        assert_eq!(around.len(), depth_of(k), "{what}: loop {k} is inside {around:?}");
        let innermost = around.iter().copied().max_by_key(|&o| depth_of(o));
        assert_eq!(innermost, offset.loops[k].parent, "{what}: loop {k}'s parent");
    }
    // the region on a grid, away from its boundary
    let [x0, y0, x1, y1] = case.bounds;
    let pad = r * 1.1;
    let n = 40;
    let mut mismatches = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let p = Point::new(
                x0 - pad + (x1 - x0 + 2.0 * pad) * (i as f64 + 0.37) / n as f64,
                y0 - pad + (y1 - y0 + 2.0 * pad) * (j as f64 + 0.61) / n as f64,
            );
            if (case.distance(p) - r).abs() < 1e-3 * size {
                continue;
            }
            let ours = polylines.iter().filter(|l| contains(l, p)).count() % 2 == 1;
            if ours != case.in_region(p, offset.distance) {
                mismatches.push(p);
            }
        }
    }
    assert!(mismatches.is_empty(), "{what}: region differs at {:?}", &mismatches[..mismatches.len().min(5)]);
    // exact area against the polylines'
    let shoelace: f64 = polylines
        .iter()
        .map(|l| {
            let o = l[0];
            let term = |a: Point, b: Point| (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
            (0..l.len()).map(|i| term(l[i], l[(i + 1) % l.len()])).sum::<f64>() / 2.0
        })
        .sum();
    let perimeter: f64 = polylines.iter().map(|l| (0..l.len()).map(|i| l[i].distance(l[(i + 1) % l.len()])).sum::<f64>()).sum();
    assert!(
        (offset.area() - shoelace).abs() <= tolerance * perimeter * 1.01 + 1e-9 * (size + r) * (size + r),
        "{what}: area {} vs polylines {shoelace}",
        offset.area()
    );
}

fn run(case: &Case, with_domain: bool, seed: u64) {
    let ds = distances(case, with_domain, seed);
    let all = case.diagram.offsets(&ds).unwrap();
    for (offset, &d) in all.iter().zip(&ds) {
        assert_eq!(offset.distance, d);
        check(case, offset);
    }
}

#[test]
fn random_polygons_with_holes() {
    for seed in 1..=12 {
        let n = 12 + (seed as usize * 7) % 40;
        let rings = testgen::rings::generate_rings("rings-holes", n, seed).unwrap();
        run(&from_rings(format!("rings-holes n={n} seed={seed}"), &rings), true, seed);
    }
}

#[test]
fn polygons_inscribed_in_circles() {
    for family in ["rings-inscribed", "rings-inscribed-jitter"] {
        for seed in 1..=4 {
            let rings = testgen::rings::generate_rings(family, 24, seed).unwrap();
            run(&from_rings(format!("{family} seed={seed}"), &rings), true, seed);
        }
    }
}

#[test]
fn glyph_outlines() {
    for seed in 1..=3 {
        let rings = testgen::rings::generate_rings("glyphs", 0, seed).unwrap();
        run(&from_rings(format!("glyph seed={seed}"), &rings), true, seed);
    }
}

#[test]
fn plain_sites_of_every_kind() {
    let families = [
        ("uniform", 30),
        ("lattice", 25),
        ("circle", 16),
        ("collinear", 8),
        ("seg-random1", 12),
        ("polyline", 15),
        ("star", 8),
        ("seg-lattice", 9),
        ("parallel", 6),
        ("fan", 7),
        ("tangent", 8),
        ("kinked-chain", 10),
    ];
    for (family, n) in families {
        for seed in 1..=3 {
            let input = testgen::generate(family, n, seed).unwrap();
            run(&from_sites(format!("{family} n={n} seed={seed}"), &input), false, seed);
        }
    }
}

#[test]
fn a_disk_like_4096_gon_at_many_distances() {
    let n = 4096;
    let ring: Vec<[f64; 2]> =
        (0..n).map(|k| std::f64::consts::TAU * k as f64 / n as f64).map(|a| [100.0 * a.cos(), 100.0 * a.sin()]).collect();
    let mut b = Builder::new();
    b.add_polygon(&[ring]).unwrap();
    let d = b.build().unwrap();
    let distances: Vec<f64> = (1..=20).map(|k| k as f64 * 4.9).flat_map(|r| [r, -r]).collect();
    let apothem = 100.0 * (std::f64::consts::PI / n as f64).cos();
    let side = 200.0 * (std::f64::consts::PI / n as f64).sin();
    for o in d.offsets(&distances).unwrap() {
        let r = o.distance.abs();
        assert_eq!(o.loops.len(), 1, "{}", o.distance);
        let polygon_area = n as f64 * apothem * side / 2.0;
        let want = if o.distance > 0.0 {
            polygon_area + n as f64 * side * r + std::f64::consts::PI * r * r
        } else {
            let a = apothem - r;
            n as f64 * a * a * (std::f64::consts::PI / n as f64).tan()
        };
        assert!((o.area() - want).abs() < 1e-9 * want, "{}: {} vs {want}", o.distance, o.area());
    }
}

/// The test domains with edges cut at exactly collinear points (straight
/// vertices: the corner's cell is a piece of the perpendicular, without
/// area) and with each cut point then moved by an ulp (nearly straight:
/// reflex or convex, the cell a wedge thinner than rounding). The domain
/// is the same, or the same within an ulp, so every offset must be: each
/// passes the brute-force checks, and its area and number of loops equal
/// the uncut domain's.
#[test]
fn straight_and_nearly_straight_vertices_change_no_offset() {
    let mut domains: Vec<(String, Vec<Vec<[f64; 2]>>)> = Vec::new();
    for seed in 1..=5 {
        let n = 12 + (seed as usize * 7) % 40;
        domains.push((format!("rings-holes n={n} seed={seed}"), testgen::rings::generate_rings("rings-holes", n, seed).unwrap()));
    }
    for family in ["rings-inscribed", "rings-inscribed-jitter"] {
        domains.push((family.to_string(), testgen::rings::generate_rings(family, 24, 3).unwrap()));
    }
    domains.push(("glyph".to_string(), testgen::rings::generate_rings("glyphs", 0, 1).unwrap()));
    domains.push(("square".to_string(), vec![vec![[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]]]));
    for (name, rings) in domains {
        let rings = common::cut_rings(&rings, 0.0, false, 0);
        let plain = from_rings(name.clone(), &rings);
        let ds = distances(&plain, true, 7);
        let want = plain.diagram.offsets(&ds).unwrap();
        // the glyph (hundreds of segments) with half its edges cut only
        let variants = [(false, 0.5), (true, 0.5), (false, 1.0), (true, 1.0)];
        let variants = if name == "glyph" { &variants[..2] } else { &variants[..] };
        for (k, &(nudge, share)) in variants.iter().enumerate() {
            let cut = common::cut_rings(&rings, share, nudge, 100 + k as u64);
            let case = from_rings(format!("{name} cut {share} nudged {nudge}"), &cut);
            let size = case.size();
            for ((offset, expected), &d) in case.diagram.offsets(&ds).unwrap().iter().zip(&want).zip(&ds) {
                check(&case, offset);
                let scale = (size + d.abs()) * (size + d.abs());
                assert!(
                    (offset.area() - expected.area()).abs() <= 1e-9 * scale,
                    "{} at {d}: area {} against {} uncut",
                    case.name,
                    offset.area(),
                    expected.area()
                );
                let areas = |o: &Offset| {
                    o.loops
                        .iter()
                        .map(|l| (l.signed_area(), if l.pieces.len() < 6 { format!("{:?}", l.pieces) } else { String::new() }))
                        .collect::<Vec<_>>()
                };
                assert_eq!(
                    offset.loops.len(),
                    expected.loops.len(),
                    "{} at {d}: loops {:?} uncut {:?}",
                    case.name,
                    areas(offset),
                    areas(expected)
                );
            }
        }
    }
}

/// The outlines of issue 27, with their areas in closed form: a square with
/// a straight vertex in the middle of a side (exactly, and 1e-15 off to
/// either side), a straight polyline, a straight vertex on a slanted side.
#[test]
fn straight_vertices_of_issue_27_give_the_closed_form_areas() {
    use std::f64::consts::PI;
    // also far from the origin, where the middle vertex is still exactly on
    // the side (the shift is exact) or an ulp of the shift off it
    for (x, shift) in [(0.0, 0.0), (1e-15, 0.0), (-1e-15, 0.0), (0.0, 1e6), (f64::from_bits(1e6f64.to_bits() + 1) - 1e6, 1e6)] {
        let square: Vec<Vec<[f64; 2]>> = vec![vec![[100.0, 0.0], [100.0, 100.0], [0.0, 100.0], [x, 50.0], [0.0, 0.0]]
            .into_iter()
            .map(|[px, py]| [px + shift, py + shift])
            .collect()];
        let case = from_rings(format!("square with ({x}, 50) moved by {shift}"), &square);
        for (d, want) in [(5.0, 10000.0 + 2000.0 + 25.0 * PI), (-5.0, 8100.0), (0.5, 10000.0 + 200.0 + 0.25 * PI), (-45.0, 100.0)]
        {
            let o = case.diagram.offset(d).unwrap();
            check(&case, &o);
            assert_eq!(o.loops.len(), 1, "{} at {d}", case.name);
            assert!((o.area() - want).abs() < 1e-7 * want, "{} at {d}: {} for {want}", case.name, o.area());
        }
    }
    let mut b = Builder::new();
    b.add_polyline(&[[0.0, 0.0], [50.0, 0.0], [100.0, 0.0]]).unwrap();
    let case = Case::new("straight polyline".into(), b.build().unwrap());
    let o = case.diagram.offset(5.0).unwrap();
    check(&case, &o);
    assert_eq!(o.loops.len(), 1);
    assert!((o.area() - (1000.0 + 25.0 * PI)).abs() < 1e-9 * 1000.0, "{}", o.area());
    // the triangle (0, 0), (8, 4), (0, 8) shrunk by 0.5: similar, with the
    // inradius less 0.5
    let case = from_rings("slanted".into(), &[vec![[0.0, 0.0], [4.0, 2.0], [8.0, 4.0], [0.0, 8.0]]]);
    let inradius = 64.0 / (2.0 * 80f64.sqrt() + 8.0);
    let o = case.diagram.offset(-0.5).unwrap();
    check(&case, &o);
    let want = 32.0 * ((inradius - 0.5) / inradius).powi(2);
    assert!((o.area() - want).abs() < 1e-9 * want, "{} for {want}", o.area());
}

/// Rings that touch at points (testgen's `rings-touching`: diamonds
/// sharing corners, touching the outer square inside its sides), valid OGC
/// polygons that build as they are: the offsets by brute force, at the
/// distances of every case (the diamonds' cells are exactly cocircular).
#[test]
fn rings_touching_at_points() {
    for seed in 1..=4 {
        let n = [8, 16, 30, 50][seed as usize - 1];
        let rings = testgen::straight::touching_rings(n, &mut testgen::Rng(seed));
        run(&from_rings(format!("rings-touching n={n} seed={seed}"), &rings), true, seed);
    }
}

/// Sides exactly `2 × distance` apart along a stretch leave a corridor of
/// no width: traced, it was a loop of area 0 (LibreCAD's mk3: two stubs 5
/// apart at 2.5) or a slit the outer loop ran into and back out of (ed9:
/// a line 5 above a rectangle's top), polygons no reader takes. Now no
/// loop has zero area and none runs back along itself; the areas are the
/// brute-force check's (`check`).
#[test]
fn corridors_of_no_width_leave_no_loop_and_no_slit() {
    let mut b = Builder::new();
    b.add_polygon(&[vec![[5.0, -5.0], [15.0, -5.0], [15.0, 10.0], [5.0, 10.0]]]).unwrap();
    for s in [[[0.0, 5.0], [5.0, 5.0]], [[15.0, 5.0], [20.0, 5.0]], [[0.0, 0.0], [5.0, 0.0]]] {
        b.add_segment(s).unwrap();
    }
    let mk3 = Case::new("mk3".into(), b.build().unwrap());
    let mut b = Builder::new();
    b.add_polygon(&[vec![[0.0, 0.0], [20.0, 0.0], [20.0, 10.0], [0.0, 10.0]]]).unwrap();
    b.add_polyline(&[[10.0, 10.0], [10.0, 15.0], [15.0, 15.0]]).unwrap();
    let ed9 = Case::new("ed9".into(), b.build().unwrap());
    for case in [mk3, ed9] {
        for r in [2.5, 2.5 * (1.0 + 1e-12), -2.5] {
            let o = case.diagram.offset(r).unwrap();
            check(&case, &o);
            for l in &o.loops {
                assert!(l.signed_area().abs() > 1e-6, "{} at {r}: a loop of area {}", case.name, l.signed_area());
                let n = l.pieces.len();
                for k in 0..n {
                    let (a, b) = (l.pieces[k], l.pieces[(k + 1) % n]);
                    let (u, v) = ((a.to().x - a.from().x, a.to().y - a.from().y), (b.to().x - b.from().x, b.to().y - b.from().y));
                    let along = (u.0 * v.1 - u.1 * v.0).abs() <= 1e-12 * u.0.hypot(u.1) * v.0.hypot(v.1);
                    let back = u.0 * v.0 + u.1 * v.1 < 0.0 && along;
                    assert!(!back, "{} at {r}: piece {k} of {n} runs back along the one before: {a:?} {b:?}", case.name);
                }
            }
        }
    }
}
