//! Tests of segment insertion inside the construction.

use super::*;
use crate::construct::insert_point::Inserted;
use crate::diagram::NONE;

/// Builds the point diagram of `points` (not all collinear), then
/// inserts `segments` (pairs of indices into `points`).
fn build(points: &[Point], segments: &[[usize; 2]]) -> Construction {
    let mut d = Construction::new(points.len() + segments.len());
    let ids = d.start_collinear(&points[..2]);
    let mut all = ids.clone();
    let mut last = ids[1];
    for &p in &points[2..] {
        match d.insert(p, last) {
            Inserted::New(s) => {
                all.push(s);
                last = s;
            }
            Inserted::Duplicate(_) => panic!("test points must be distinct"),
        }
    }
    for &[i, j] in segments {
        d.insert_segment(all[i], all[j]).expect("a path");
    }
    d
}

/// The finite vertices in use: id, sites, position, clearance.
pub(super) fn finite_vertices(d: &Construction) -> impl Iterator<Item = (usize, [SiteId; 3], Point, f64)> + '_ {
    (0..d.store.vertex_count()).filter_map(|vi| {
        let sites = d.store.sites_of(VertexId::from_index(vi));
        let unused_or_infinite = sites.contains(&INFINITE) || sites[0].0 == NONE;
        (!unused_or_infinite).then(|| (vi, sites, d.store.position[vi], d.store.clearance[vi]))
    })
}

/// Whether the vertex is equidistant from its three sites and no site
/// is closer (brute force), within `tol` (or 1e-12 of its clearance,
/// for far vertices: their distances are rounded at that size).
pub(super) fn check_vertex(
    d: &Construction,
    (vi, sites, pos, r): (usize, [SiteId; 3], Point, f64),
    tol: f64,
) -> Result<(), String> {
    let tol = tol.max(1e-12 * r);
    for s in (1..d.sites.len()).map(SiteId::from_index) {
        let dist = d.site_geometry(s).distance(pos);
        if dist < r - tol || (sites.contains(&s) && (dist - r).abs() > tol) {
            return Err(format!("vertex {vi} {sites:?} at {pos:?}: site {s:?} at {dist}, clearance {r}"));
        }
    }
    Ok(())
}

/// Every finite vertex passes `check_vertex`.
fn check_geometry(d: &Construction, tol: f64) {
    for v in finite_vertices(d) {
        check_vertex(d, v, tol).unwrap_or_else(|e| panic!("{e}"));
    }
}

fn validate(d: &Construction) {
    d.store.validate().unwrap_or_else(|e| panic!("{e}"));
}

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

#[test]
fn one_segment_among_points() {
    let pts = [p(0.0, 0.0), p(4.0, 0.3), p(2.0, 3.0), p(1.5, -2.5), p(5.0, 4.0), p(-1.0, 3.5), p(2.2, 0.9)];
    let d = build(&pts, &[[0, 6]]);
    validate(&d);
    check_geometry(&d, 1e-9);
}

/// Points on a jittered grid; in some cells two points joined by a short
/// segment that stays inside its cell, so no two segments meet.
fn jittered(side: usize, seed: u64) -> (Vec<Point>, Vec<[usize; 2]>) {
    let mut rng = crate::splitmix::SplitMix64(seed);
    let mut unit = move || rng.unit();
    let (mut pts, mut segs) = (Vec::new(), Vec::new());
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            let a = p(x + 0.1 + 0.8 * unit(), y + 0.1 + 0.8 * unit());
            pts.push(a);
            if unit() < 0.5 {
                let b = p(x + 0.1 + 0.8 * unit(), y + 0.1 + 0.8 * unit());
                if b != a {
                    pts.push(b);
                    segs.push([pts.len() - 2, pts.len() - 1]);
                }
            }
        }
    }
    (pts, segs)
}

#[test]
fn random_disjoint_segments() {
    for seed in 0..40 {
        let (pts, segs) = jittered(6 + (seed as usize % 10), seed);
        let d = build(&pts, &segs);
        validate(&d);
        check_geometry(&d, 1e-9);
    }
}

/// Whether every segment so far has exactly one separator with each endpoint.
#[cfg(feature = "fault-injection")]
fn separators_ok(d: &Construction) -> Result<(), String> {
    for (s, ends) in d.segment_sites() {
        for e in ends {
            let n = d.store.cell_boundary(s).filter(|&h| d.store.right(h) == e).count();
            if n != 1 {
                return Err(format!("segment {s:?} has {n} separators with {e:?}"));
            }
        }
    }
    Ok(())
}

/// Every insertion keeps every segment's separators, under random
/// arithmetic; names the first insertion that does not.
#[cfg(feature = "fault-injection")]
#[test]
fn separators_under_random_arithmetic() {
    for seed in 0..3 {
        let (pts, segs) = jittered(20, seed);
        crate::fault_injection::set_fault_mode(crate::fault_injection::FaultMode::Random, seed);
        let mut d = Construction::new(pts.len() + segs.len());
        let ids = d.start_collinear(&pts[..2]);
        let mut all = ids.clone();
        let mut last = ids[1];
        for &p in &pts[2..] {
            if let Inserted::New(s) = d.insert(p, last) {
                all.push(s);
                last = s;
            } else {
                panic!("distinct");
            }
        }
        for (k, &[i, j]) in segs.iter().enumerate() {
            d.fresh_epoch();
            let e = d.add_segment_site(all[i], all[j]);
            let found = d.find_segment_path(all[i], all[j]);
            let path = d.tree.clone();
            d.grow_segment_tree(all[i], all[j]);
            d.replace_tree(e);
            let ok = separators_ok(&d);
            if ok.is_err() {
                crate::fault_injection::set_fault_mode(crate::fault_injection::FaultMode::Off, 0);
            }
            if let Err(msg) = ok {
                panic!("seed {seed} segment {k} ({e:?}): path found {found}, path {}: {msg}", path.len());
            }
        }
        crate::fault_injection::set_fault_mode(crate::fault_injection::FaultMode::Off, 0);
    }
}

mod replay {
    //! Inserts the segments of an input one at a time and checks the
    //! diagram after every insertion: valid, every surviving vertex's circle
    //! free of the new segment, every new vertex equidistant from its sites
    //! with no site closer. Names the first insertion that goes wrong.
    use super::*;
    use crate::geometry::predicates::{orientation, Orientation};
    use crate::splitmix::SplitMix64 as SplitMix;

    /// Tolerance relative to the largest coordinate.
    const TOLERANCE: f64 = 1e-9;

    /// An input in Boost.Polygon's text format (`boost_text`).
    fn parse(text: &str) -> (Vec<Point>, Vec<[Point; 2]>) {
        let input = crate::boost_text::parse(text).expect("an input in Boost.Polygon's text format");
        let points = input.points.iter().map(|&[x, y]| Point::new(x, y)).collect();
        let segments = input.segments.iter().map(|&[x1, y1, x2, y2]| [Point::new(x1, y1), Point::new(x2, y2)]).collect();
        (points, segments)
    }

    /// The first wrong insertion, if any (inputs whose points are not all
    /// collinear).
    fn replay(points: &[Point], segments: &[[Point; 2]]) -> Result<(), String> {
        let all: Vec<Point> = points.iter().copied().chain(segments.iter().flatten().copied()).collect();
        let tol = TOLERANCE * all.iter().fold(f64::MIN_POSITIVE, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        let mut d = Construction::new(all.len() + segments.len());
        let mut ids = d.start_collinear(&all[..2]);
        let mut last = ids[1];
        for &p in &all[2..] {
            let id = match d.insert(p, last) {
                Inserted::New(s) => s,
                Inserted::Duplicate(s) => s,
            };
            ids.push(id);
            last = id;
        }
        for (n, k) in (0..segments.len()).enumerate() {
            let base = points.len() + 2 * k;
            let e = d.insert_segment(ids[base], ids[base + 1]).map_err(|_| format!("segment {n}: no path"))?;
            d.store.validate().map_err(|err| format!("segment {n}: {err}"))?;
            check_after(&d, e, tol).map_err(|err| format!("segment {n}: {err}"))?;
        }
        Ok(())
    }

    fn check_after(d: &Construction, e: SiteId, tol: f64) -> Result<(), String> {
        let segment = d.site_geometry(e);
        for v @ (vi, sites, pos, r) in super::finite_vertices(d) {
            if segment.distance(pos) < r - tol.max(1e-12 * r) {
                return Err(format!(
                    "vertex {vi} {sites:?} at {pos:?} kept with the new segment inside its circle (at {}, clearance {r})",
                    segment.distance(pos)
                ));
            }
            if sites.contains(&e) {
                super::check_vertex(d, v, tol).map_err(|err| format!("new {err}"))?;
            }
        }
        Ok(())
    }

    /// Whether the closed segments `p` and `q` meet (exact orientations).
    fn meet(p: [Point; 2], q: [Point; 2]) -> bool {
        let side = |a: Point, b: Point, c: Point| orientation(a, b, c) as i32;
        let (d1, d2) = (side(p[0], p[1], q[0]), side(p[0], p[1], q[1]));
        let (d3, d4) = (side(q[0], q[1], p[0]), side(q[0], q[1], p[1]));
        d1 != d2 && d3 != d4 || [d1, d2, d3, d4].contains(&(Orientation::Collinear as i32))
    }

    /// Seed 000's first method: random endpoints in the unit square, a
    /// segment that meets an earlier one redrawn.
    fn random_segments(n: usize, seed: u64) -> Vec<[Point; 2]> {
        let mut rng = SplitMix(seed);
        let mut unit = move || rng.unit();
        let mut out: Vec<[Point; 2]> = Vec::new();
        while out.len() < n {
            let s = [Point::new(unit(), unit()), Point::new(unit(), unit())];
            if !out.iter().any(|&t| meet(s, t)) {
                out.push(s);
            }
        }
        out
    }

    #[test]
    fn fixtures_are_right_after_every_insertion() {
        for (name, text) in [
            ("collinear_continuation", include_str!("../../../c_tests/fixtures/collinear_continuation.txt")),
            ("two_segments_near_endpoint", include_str!("../../../c_tests/fixtures/two_segments_near_endpoint.txt")),
        ] {
            let (points, segments) = parse(text);
            replay(&points, &segments).unwrap_or_else(|err| panic!("{name}: {err}"));
        }
    }

    /// Long random segments: cells wrapped around points and arcs cut twice
    /// (what first showed the need for edges cut at both ends).
    #[test]
    fn random_long_segments_are_right_after_every_insertion() {
        for seed in 0..12 {
            let segments = random_segments(60, seed);
            replay(&[], &segments).unwrap_or_else(|err| panic!("seed {seed}: {err}"));
        }
    }

    /// Debug aid: `SEGFILE=input.txt cargo test --lib replay_file -- --ignored`
    /// replays any input in Boost.Polygon's text format.
    #[test]
    #[ignore]
    fn replay_file() {
        let path = std::env::var("SEGFILE").expect("SEGFILE names the input to replay");
        let (points, segments) = parse(&std::fs::read_to_string(path).expect("a readable input"));
        replay(&points, &segments).unwrap_or_else(|err| panic!("{err}"));
    }
}
