//! Country outlines as a GIS user holds them (issue 27): the Digital Chart
//! of the World from Debian's gmt-dcw, projected to kilometres
//! (`scripts/country_rings.py`, `tests/data/dcw_*.rings`; Denmark's and
//! Switzerland's rings share stretches, which cancel), and the islands
//! of the Aegean from GSHHG (`scripts/island_rings.py`,
//! `tests/data/gshhg_islands_*.rings`), full of straight
//! and nearly straight vertices (points of one line of the integer grid,
//! rounded by the projection), enclaves as holes, and islands. For each:
//! the diagram validates; the medial axis lies inside, each sample at the
//! clearance it says from the nearest boundary segment (brute force), its
//! largest inscribed circle the highest of them; the offsets at several
//! distances close, are oriented and nested, lie at their distance from
//! the boundary (brute force) on the right side, and their areas grow with
//! the distance. `c_tests/geos_offsets.cpp` compares the same offsets with
//! GEOS's buffer.

mod common;

use segvoronoi::{Builder, Diagram, Location, Point};
use segvoronoi_testgen::rings::real_outlines;

/// The distance from `p` to the nearest of `segments`.
fn nearest(segments: &[segvoronoi::Site], p: Point) -> f64 {
    segments.iter().map(|s| s.distance(p)).fold(f64::INFINITY, f64::min)
}

/// Every `step`-th of `points`, and the last.
fn every<T: Copy>(points: &[T], step: usize) -> impl Iterator<Item = T> + '_ {
    points.iter().copied().enumerate().filter(move |(k, _)| k % step == 0 || k + 1 == points.len()).map(|(_, p)| p)
}

/// The segments of the rings that bound the domain: those that the rings
/// run along an odd number of times (countries of several polygons share
/// borders, edge for edge in these files; two copies cancel by the
/// even-odd rule, and the build drops them).
fn boundary(rings: &[Vec<[f64; 2]>]) -> Vec<segvoronoi::Site> {
    let key = |[a, b]: [[f64; 2]; 2]| {
        let (a, b) = (a.map(f64::to_bits), b.map(f64::to_bits));
        if a <= b {
            [a, b]
        } else {
            [b, a]
        }
    };
    let mut count = std::collections::HashMap::new();
    for r in rings {
        for k in 0..r.len() {
            *count.entry(key([r[k], r[(k + 1) % r.len()]])).or_insert(0usize) += 1;
        }
    }
    let odd = |s: &segvoronoi::Site| match *s {
        segvoronoi::Site::Segment { a, b } => count[&key([[a.x, a.y], [b.x, b.y]])] % 2 == 1,
        _ => true,
    };
    let mut segments = common::ring_segments(rings);
    segments.retain(odd);
    segments
}

/// Checks one outline; returns how many ring pieces cancelled in it.
fn check_country(name: &str, rings: &[Vec<[f64; 2]>]) -> usize {
    let mut b = Builder::new();
    b.add_polygon(rings).unwrap_or_else(|e| panic!("{name}: {e}"));
    let d: Diagram = b.build().unwrap_or_else(|e| panic!("{name}: {e}"));
    d.validate().unwrap_or_else(|e| panic!("{name}: {e:?}"));
    let segments = boundary(rings);
    let size = d.extent();
    let tolerance = 1e-4 * size;
    // a few thousand brute-force distances per check, whatever the size
    let budget = 3_000_000 / segments.len().max(1);

    let axis = d.medial_axis();
    let samples: Vec<[f64; 3]> = axis.chains.iter().flat_map(|c| d.sample_chain(c, tolerance).unwrap()).collect();
    let step = (samples.len() / budget.max(1)).max(1);
    let mut highest = 0.0f64;
    for [x, y, clearance] in every(&samples, step) {
        let p = Point::new(x, y);
        let want = nearest(&segments, p);
        assert!((clearance - want).abs() <= 1e-9 * size, "{name}: axis point {p:?} clearance {clearance}, nearest {want}");
        assert_ne!(d.locate_point(p), Some(Location::Outside), "{name}: axis point {p:?} outside");
        highest = highest.max(clearance);
    }
    let (centre, r) = d.max_inscribed_circle().unwrap();
    assert_eq!(d.locate_point(centre), Some(Location::Inside), "{name}: inscribed centre {centre:?}");
    assert!((nearest(&segments, centre) - r).abs() <= 1e-9 * size, "{name}: inscribed radius {r}");
    assert!(r >= highest - 1e-9 * size, "{name}: an axis point at {highest} above the inscribed radius {r}");

    let mut distances = [-0.5 * r, -0.1 * r, -0.01 * r, 0.01 * r, 0.1 * r, 1.0, 10.0, 0.2 * size];
    distances.sort_by(f64::total_cmp);
    let offsets = d.offsets(&distances).unwrap();
    let mut last_area = 0.0;
    for (o, &dist) in offsets.iter().zip(&distances) {
        let what = format!("{name} at {dist}");
        assert!(o.area() > last_area, "{what}: area {} after {last_area}", o.area());
        last_area = o.area();
        for (k, l) in o.loops.iter().enumerate() {
            for (i, piece) in l.pieces.iter().enumerate() {
                assert_eq!(piece.to(), l.pieces[(i + 1) % l.pieces.len()].from(), "{what}: loop {k} open at piece {i}");
            }
            assert_eq!(l.hole, l.signed_area() < 0.0, "{what}: loop {k} hole {} area {}", l.hole, l.signed_area());
            assert!(l.parent.map_or(true, |p| p < k && o.loops[p].hole != l.hole), "{what}: loop {k}'s parent");
        }
        let polylines = o.polylines(tolerance).unwrap();
        let points: Vec<Point> = polylines.iter().flatten().copied().collect();
        for p in every(&points, (points.len() / budget.max(1)).max(1)) {
            let at = nearest(&segments, p);
            assert!((at - dist.abs()).abs() <= 1e-9 * (size + dist.abs()), "{what}: {p:?} at {at}");
            let want = if dist > 0.0 { Location::Outside } else { Location::Inside };
            assert_eq!(d.locate_point(p), Some(want), "{what}: {p:?}");
        }
    }
    d.stats().cancelled_ring_pieces
}

#[test]
fn country_outlines_medial_axis_and_offsets() {
    let mut cancelled = 0;
    for (name, rings) in real_outlines() {
        cancelled += check_country(&name, &rings);
    }
    // Denmark and Switzerland share borders between their rings (an island
    // in two polygons, an enclave given as a polygon and as a hole)
    if std::env::var_os("SEGVORONOI_OUTLINES").is_none() {
        assert!(cancelled > 0, "no outline has a shared stretch");
    }
}

/// What makes these outlines hard: exactly straight and nearly straight
/// vertices (the test above is only worth as much as they are there).
#[test]
fn country_outlines_have_straight_and_nearly_straight_vertices() {
    use segvoronoi_testgen::exact::orient;
    let (mut straight, mut nearly) = (0, 0);
    for (_, rings) in real_outlines() {
        for r in &rings {
            for k in 0..r.len() {
                let (a, b, c) = (r[(k + r.len() - 1) % r.len()], r[k], r[(k + 1) % r.len()]);
                let cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
                let scale = ((b[0] - a[0]).hypot(b[1] - a[1])) * ((c[0] - b[0]).hypot(c[1] - b[1]));
                if orient(a, b, c) == 0 {
                    straight += 1;
                } else if cross.abs() < 1e-12 * scale {
                    nearly += 1;
                }
            }
        }
    }
    assert!(straight > 10 && nearly > 10, "straight {straight}, nearly straight {nearly}");
}
