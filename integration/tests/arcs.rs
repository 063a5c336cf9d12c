//! Diagrams with circular arcs, checked by brute force (there is no CGAL
//! for arcs): every vertex is equidistant from its three sites with no
//! site nearer (an empty circle), and points along every finite edge are
//! equidistant from its two sites with no site nearer. On families nobody
//! tuned for: random arcs, segments and points in the cells of a grid;
//! rounded rectangles, slots, concentric arcs and tangent chains; each
//! also reversed, shuffled, mirrored and scaled by powers of two.

mod common;

use common::arc_inputs::{
    add_pieces, audit, distance, filleted_polygon, mapped, random_cells, rounded_rectangle, variants, Piece,
};
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Diagram, Point, Site};

fn build(pieces: &[Piece]) -> Diagram {
    let mut b = Builder::new();
    add_pieces(&mut b, pieces);
    match b.build() {
        Ok(d) => d,
        Err(e) => panic!("{e}: {pieces:?}"),
    }
}

/// Builds `pieces` and its variants and audits each; returns the number
/// of finite vertices of the plain build (every variant has as many).
fn check_all_ways(name: &str, pieces: &[Piece], size: f64, seed: u64) -> usize {
    let tol = 1e-8 * size;
    let mut count = 0;
    for (way, input, scale) in variants(pieces, seed) {
        let d = build(&input);
        d.validate().unwrap_or_else(|e| panic!("{name} {way}: invalid: {e:?}"));
        let f = audit(&d, tol * scale);
        assert!(f.is_empty(), "{name} {way}: {} failures, first:\n{}", f.len(), f[..f.len().min(5)].join("\n"));
        if way == "plain" {
            count = d.vertex_count();
        } else {
            assert_eq!(d.vertex_count(), count, "{name} {way}: another vertex count");
        }
    }
    count
}

/// Each variant of `pieces` answered right (`validate`, the audit) or
/// refused as `Internal`, never answered wrong; the variants refused.
fn right_or_refused(name: &str, pieces: &[Piece], size: f64, seed: u64) -> Vec<&'static str> {
    let mut refused = Vec::new();
    for (way, input, scale) in variants(pieces, seed) {
        let mut b = Builder::new();
        add_pieces(&mut b, &input);
        match b.build() {
            Ok(d) => {
                d.validate().unwrap_or_else(|e| panic!("{name} {way}: invalid: {e:?}"));
                let f = audit(&d, 1e-8 * size * scale);
                assert!(f.is_empty(), "{name} {way}: answered wrong: {}", f[..f.len().min(5)].join("\n"));
            }
            Err(e) => {
                assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "{name} {way}: {e}");
                refused.push(way);
            }
        }
    }
    eprintln!("{name}: refused {refused:?}");
    refused
}

/// A single arc of nearly a whole turn (bulge -2.5e7: all but 1.6e-7 rad),
/// found by the C API's fuzzer at 1e-300 (case 0x5647c6b33fd94086): its
/// cell at infinity owns all but the sliver of directions its ends' cells
/// take, a step round the cell at infinity of nearly a whole turn, which
/// the build's check of the edges to infinity first took for a step back
/// and refused. Answered right at 1e-300, 1 and 1e180 (exact powers of two
/// apart), audited (the edges to infinity far out included).
#[test]
fn a_nearly_whole_circle_alone() {
    let ends = [Point::new(1.0, 0.0), Point::new(-1.0, 0.0)];
    for scale in [2f64.powi(-997), 1.0, 2f64.powi(600)] {
        for bulge in [-2.5e7, 2.5e7] {
            let at = |q: Point| Point::new(q.x * scale, q.y * scale);
            let arc = CircularArc::from_bulge(at(ends[0]), at(ends[1]), bulge).unwrap();
            let mut b = Builder::new();
            b.add_arc(arc).unwrap();
            let d = b.build().unwrap_or_else(|e| panic!("scale {scale:e}, bulge {bulge}: {e}"));
            d.validate().unwrap();
            let f = audit(&d, 1e-8 * arc.radius());
            assert!(f.is_empty(), "scale {scale:e}, bulge {bulge}: {}", f.join("\n"));
        }
    }
}

#[test]
fn random_arcs_segments_and_points_in_cells() {
    for seed in 0..12 {
        let side = 2 + (seed as usize % 4);
        check_all_ways(&format!("cells seed {seed}"), &random_cells(seed, side), side as f64, seed);
    }
}

#[test]
fn rounded_rectangles_nested_and_apart() {
    let mut pieces = rounded_rectangle(0.0, 0.0, 10.0, 6.0, 1.5);
    pieces.extend(rounded_rectangle(2.0, 2.0, 3.0, 2.0, 0.5));
    pieces.extend(rounded_rectangle(12.0, 0.5, 4.0, 4.0, 2.0)); // a circle of four arcs... and no sides
    pieces.push(Piece::Point(Point::new(7.5, 3.0)));
    check_all_ways("rounded rectangles", &pieces, 16.0, 1);
}

#[test]
fn slots_and_a_point_at_an_arc_centre() {
    let p = Point::new;
    let mut pieces = vec![
        Piece::Segment(p(0.0, 0.0), p(4.0, 0.0)),
        Piece::Arc(CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap()),
        Piece::Segment(p(4.0, 2.0), p(0.0, 2.0)),
        Piece::Arc(CircularArc::from_bulge(p(0.0, 2.0), p(0.0, 0.0), 1.0).unwrap()),
    ];
    check_all_ways("slot", &pieces, 4.0, 2);
    pieces.push(Piece::Point(p(4.0, 1.0)));
    check_all_ways("slot with its centre", &pieces, 4.0, 3);
}

#[test]
fn concentric_arcs() {
    check_all_ways("concentric", &concentric(), 10.0, 4);
}

/// Five concentric arcs of different spans and a point at their centre.
fn concentric() -> Vec<Piece> {
    let mut pieces = Vec::new();
    for k in 1..6 {
        let r = k as f64;
        let at = |t: f64| Point::new(r * t.cos(), r * t.sin());
        pieces.push(Piece::Arc(CircularArc::through(at(0.1 * k as f64), at(1.0 + 0.1 * k as f64), at(2.5)).unwrap()));
    }
    pieces.push(Piece::Point(Point::new(0.0, 0.0)));
    pieces
}

#[test]
fn a_full_circle_as_two_arcs_around_points() {
    let p = Point::new;
    let pieces = vec![
        Piece::Arc(CircularArc::from_bulge(p(3.0, 0.0), p(-3.0, 0.0), 1.0).unwrap()),
        Piece::Arc(CircularArc::from_bulge(p(-3.0, 0.0), p(3.0, 0.0), 1.0).unwrap()),
        Piece::Point(p(0.5, 0.25)),
        Piece::Point(p(-1.0, 1.0)),
        Piece::Segment(p(-1.0, -1.0), p(1.0, -1.5)),
    ];
    check_all_ways("full circle", &pieces, 6.0, 5);
}

/// Whether `pieces` build and pass the audit.
fn passes(pieces: &[Piece], tol: f64) -> bool {
    let mut b = Builder::new();
    for piece in pieces {
        let _ = match *piece {
            Piece::Point(p) => b.add_point(p),
            Piece::Segment(p, q) => b.add_segment([p, q]),
            Piece::Arc(arc) => b.add_arc(arc),
        };
    }
    match b.build() {
        Ok(d) => d.validate().is_ok() && audit(&d, tol).is_empty(),
        Err(_) => false,
    }
}

/// The failing input made smaller, piece by piece, while it still fails.
fn minimise(mut pieces: Vec<Piece>, tol: f64) -> Vec<Piece> {
    let mut k = 0;
    while k < pieces.len() {
        let mut fewer = pieces.clone();
        fewer.remove(k);
        if !passes(&fewer, tol) {
            pieces = fewer;
        } else {
            k += 1;
        }
    }
    pieces
}

#[test]
#[ignore = "a debugging aid: minimises the failing families"]
fn minimise_failures() {
    let seeds = std::env::var("ARC_SEEDS").ok().and_then(|v| v.parse().ok()).unwrap_or(12u64);
    let mut families: Vec<(String, Vec<Piece>, f64, u64)> = Vec::new();
    for seed in 0..seeds {
        let side = 2 + (seed as usize % 4);
        families.push((format!("cells {seed}"), random_cells(seed, side), side as f64, seed));
        families.push((format!("stars {seed}"), stars(seed), 6.0, seed));
        families.push((format!("filleted {seed}"), filleted(seed), 6.0, seed));
        families.push((format!("equal rounded grid {seed}"), equal_rounded_grid(seed), 8.0, seed));
        families.push((format!("half circle rows {seed}"), half_circle_rows(seed), 12.0, seed));
        families.push((format!("touching chains {seed}"), touching_chains(seed), 4.0, seed));
    }
    families.push(("concentric".to_string(), concentric(), 10.0, 4));
    let mut inputs = Vec::new();
    for (name, pieces, size, seed) in families {
        for (way, input, scale) in variants(&pieces, seed) {
            inputs.push((format!("{name} {way}"), input, size * scale));
        }
    }
    for (name, pieces, size) in inputs {
        if !passes(&pieces, 1e-8 * size) {
            let small = minimise(pieces, 1e-8 * size);
            println!("{name}: {} pieces\n{small:?}", small.len());
        }
    }
}

/// Exact ties everywhere, as drawings have them: a grid of equal rounded
/// rectangles aligned on common lines (their sides collinear, their
/// corners' circles equal and in rows), sizes in binary fractions so every
/// tie stays exact; with the seed's bits a point at some corner centres.
fn equal_rounded_grid(seed: u64) -> Vec<Piece> {
    let mut rng = SplitMix64(seed ^ 0x7135);
    let (cols, rows) = (1 + (seed % 4) as usize, 1 + (seed / 4 % 3) as usize);
    let quarter = |rng: &mut SplitMix64| 0.25 * (rng.next_u64() % 4) as f64;
    let (w, h) = (0.75 + quarter(&mut rng), 0.75 + quarter(&mut rng));
    let r = if rng.unit() < 0.5 { 0.125 } else { 0.25 };
    let gap = 0.25 + quarter(&mut rng);
    let mut pieces = Vec::new();
    for i in 0..cols {
        for j in 0..rows {
            let (x, y) = (i as f64 * (w + gap), j as f64 * (h + gap));
            pieces.extend(rounded_rectangle(x, y, w, h, r));
            if rng.unit() < 0.3 {
                pieces.push(Piece::Point(Point::new(x + r, y + r)));
            }
        }
    }
    pieces
}

/// Rows of equal half circles, apart (not chained), each bulging up or
/// down by the seed's bits, the rows stacked so that the bisectors of ends
/// run parallel out to infinity; with points at some centres.
fn half_circle_rows(seed: u64) -> Vec<Piece> {
    let mut rng = SplitMix64(seed ^ 0x4a1f);
    let (count, rows) = (1 + (seed % 5) as usize, 1 + (seed / 5 % 3) as usize);
    let pitch = 1.5 + 0.5 * (rng.next_u64() % 3) as f64;
    let mut pieces = Vec::new();
    for j in 0..rows {
        for i in 0..count {
            let (x, y) = (i as f64 * pitch, j as f64 * 2.0);
            let bulge = if rng.unit() < 0.5 { 1.0 } else { -1.0 };
            pieces.push(Piece::Arc(CircularArc::from_bulge(Point::new(x, y), Point::new(x + 1.0, y), bulge).unwrap()));
            if rng.unit() < 0.25 {
                pieces.push(Piece::Point(Point::new(x + 0.5, y)));
            }
        }
    }
    pieces
}

/// Closed chains that touch at one point: a lens (a chord and an arc) and
/// a rounded slot whose vertex is the lens's end, a triangle sharing the
/// lens's other end, all on one line through the touching points.
fn touching_chains(seed: u64) -> Vec<Piece> {
    let mut rng = SplitMix64(seed ^ 0x70c4);
    let p = Point::new;
    let b = 0.25 + 0.5 * rng.unit();
    let mut pieces = vec![
        Piece::Segment(p(0.0, 0.0), p(2.0, 0.0)),
        Piece::Arc(CircularArc::from_bulge(p(2.0, 0.0), p(0.0, 0.0), b).unwrap()),
        // a slot to the right, its left end's vertex at (2, 0)
        Piece::Arc(CircularArc::from_bulge(p(2.0, 0.0), p(3.0, -0.5), 0.5 - 0.5 * rng.unit()).unwrap()),
        Piece::Segment(p(3.0, -0.5), p(3.0, 0.5)),
        Piece::Arc(CircularArc::from_bulge(p(3.0, 0.5), p(2.0, 0.0), 0.3).unwrap()),
        // a triangle to the left, touching at (0, 0)
        Piece::Segment(p(0.0, 0.0), p(-1.0, 0.5)),
        Piece::Segment(p(-1.0, 0.5), p(-1.0, -0.5)),
        Piece::Segment(p(-1.0, -0.5), p(0.0, 0.0)),
    ];
    if seed % 2 == 1 {
        pieces.push(Piece::Point(p(1.0, 0.0)));
    }
    pieces
}

#[test]
fn exact_ties_in_aligned_equal_shapes() {
    for seed in 0..12 {
        let grid = equal_rounded_grid(seed);
        check_all_ways(&format!("equal rounded grid seed {seed}"), &grid, 8.0, seed);
    }
    for seed in 0..15 {
        check_all_ways(&format!("half circle rows seed {seed}"), &half_circle_rows(seed), 12.0, seed);
    }
    for seed in 0..4 {
        check_all_ways(&format!("touching chains seed {seed}"), &touching_chains(seed), 4.0, seed);
    }
}

#[test]
fn larger_random_cells() {
    for seed in 100..106 {
        let side = 8 + (seed as usize % 5);
        check_all_ways(&format!("large cells seed {seed}"), &random_cells(seed, side), side as f64, seed);
    }
}

/// A star-shaped closed chain around `(cx, cy)`: vertices at sorted random
/// angles and radii, each piece a segment or a gentle arc (bulges up to
/// 0.3 either way, which keep the pieces apart).
fn bulged_star(rng: &mut SplitMix64, cx: f64, cy: f64, n: usize) -> Vec<Piece> {
    let mut angles: Vec<f64> =
        (0..n).map(|k| (k as f64 + 0.2 + 0.6 * rng.unit()) * 2.0 * std::f64::consts::PI / n as f64).collect();
    angles.sort_by(f64::total_cmp);
    let vertices: Vec<Point> = angles
        .iter()
        .map(|&t| {
            let r = 0.6 + 0.4 * rng.unit();
            Point::new(cx + r * t.cos(), cy + r * t.sin())
        })
        .collect();
    (0..n)
        .map(|k| {
            let (a, b) = (vertices[k], vertices[(k + 1) % n]);
            if rng.unit() < 0.3 {
                Piece::Segment(a, b)
            } else {
                let bulge = 0.3 * (2.0 * rng.unit() - 1.0);
                match CircularArc::from_bulge(a, b, if bulge.abs() < 0.02 { 0.1 } else { bulge }) {
                    Ok(arc) => Piece::Arc(arc),
                    Err(_) => Piece::Segment(a, b),
                }
            }
        })
        .collect()
}

/// Four shapes in a 2 × 2 layout, 3 apart, each with a point near its
/// centre (`shape` makes one around a centre from the generator).
fn four_shapes(seed: u64, shape: impl Fn(&mut SplitMix64, f64, f64) -> Vec<Piece>) -> Vec<Piece> {
    let mut rng = SplitMix64(seed);
    let mut pieces = Vec::new();
    for i in 0..2 {
        for j in 0..2 {
            let (cx, cy) = (3.0 * i as f64, 3.0 * j as f64);
            pieces.extend(shape(&mut rng, cx, cy));
            pieces.push(Piece::Point(Point::new(cx + 0.1 * rng.unit(), cy + 0.1 * rng.unit())));
        }
    }
    pieces
}

/// Four bulged stars with a point near each centre and one between.
fn stars(seed: u64) -> Vec<Piece> {
    let mut pieces = four_shapes(seed, |rng, cx, cy| {
        let n = 5 + (rng.next_u64() % 12) as usize;
        bulged_star(rng, cx, cy, n)
    });
    pieces.push(Piece::Point(Point::new(1.5, 1.5)));
    pieces
}

#[test]
fn bulged_stars_with_points_inside_and_out() {
    for seed in 0..8 {
        check_all_ways(&format!("stars seed {seed}"), &stars(seed), 6.0, seed);
    }
}

#[test]
fn tangent_waves_of_half_circles() {
    // a wave of half circles, alternately up and down, tangent at every
    // joint (vertical tangents there), with a straight lead-in and lead-out
    // along the tangent, and points in the troughs
    let p = Point::new;
    let mut pieces = vec![Piece::Segment(p(0.0, -2.0), p(0.0, 0.0))];
    for k in 0..6 {
        let bulge = if k % 2 == 0 { -1.0 } else { 1.0 };
        pieces.push(Piece::Arc(CircularArc::from_bulge(p(2.0 * k as f64, 0.0), p(2.0 * k as f64 + 2.0, 0.0), bulge).unwrap()));
        pieces.push(Piece::Point(p(2.0 * k as f64 + 1.0, if k % 2 == 0 { -0.5 } else { 0.5 })));
    }
    pieces.push(Piece::Segment(p(12.0, 0.0), p(12.0, 2.0)));
    check_all_ways("wave", &pieces, 12.0, 7);
}

#[test]
fn arcs_sharing_a_circle_and_points_at_centres() {
    let p = Point::new;
    let on = |t: f64| p(2.0 * t.cos(), 2.0 * t.sin());
    let pieces = vec![
        Piece::Arc(CircularArc::through(on(0.1), on(0.6), on(1.2)).unwrap()),
        Piece::Arc(CircularArc::through(on(2.0), on(2.5), on(3.0)).unwrap()),
        Piece::Arc(CircularArc::through(on(4.0), on(4.8), on(5.5)).unwrap()),
        Piece::Point(p(0.0, 0.0)),
        Piece::Arc(CircularArc::from_bulge(p(5.0, 0.0), p(7.0, 0.0), 0.5).unwrap()),
        Piece::Point(p(6.0, 0.75)), // near that arc's centre side
    ];
    check_all_ways("one circle", &pieces, 8.0, 8);
}

#[test]
fn tiny_arcs_and_far_from_the_origin() {
    let p = Point::new;
    let ulp = f64::EPSILON;
    let pieces = vec![
        Piece::Arc(CircularArc::from_bulge(p(1.0, 0.0), p(1.0, 4.0 * ulp), 0.5).unwrap()),
        Piece::Arc(CircularArc::from_bulge(p(0.5, 0.0), p(0.5, ulp / 2.0), -0.5).unwrap()), // one ulp of 0.5
        Piece::Arc(CircularArc::from_bulge(p(0.0, 0.0), p(1e-9, 0.0), -0.7).unwrap()),
        Piece::Point(p(0.5, 0.5)),
        Piece::Segment(p(0.0, 1.0), p(1.0, 1.0)),
    ];
    // The arc four ulps long, its ends on the line x = 1 with the
    // segment's end, lies beyond that line by its sagitta (2.2e-16, a
    // rounding of its coordinates): it takes the vertex at infinity of its
    // end and the segment's (`at_infinity`: an arc leaving a hull site
    // that is its own end clearly outward). Taken for a tie, the end's
    // separator ran to infinity through the segment above, answered in
    // every variant and then refused by the check of the edges to
    // infinity. The arc one ulp long was refused alone: its vertex missed
    // its sites by less than the rounding of its coordinates, which the
    // check's tolerance now counts.
    check_all_ways("tiny arcs", &pieces, 1.0, 9);
    // a rounded rectangle 1e6 from the origin (not a power of two: the
    // geometry itself moves by rounding, the audit must still pass)
    let far: Vec<Piece> = rounded_rectangle(1e6, 1e6, 10.0, 6.0, 1.5);
    check_all_ways("far", &far, 1e6, 10);
}

/// Lying arithmetic: every decided quantity perturbed, or random; arcs'
/// builds still end in a valid diagram or `Internal`, never a panic or an
/// invalid diagram. `cargo test --features fault-injection --test arcs`.
#[cfg(feature = "fault-injection")]
#[test]
fn arcs_under_fault_injection_stay_valid() {
    use segvoronoi::fault_injection::{set_fault_mode, FaultMode};
    let mut inputs: Vec<Vec<Piece>> = (0..6).map(|seed| random_cells(seed, 3 + seed as usize % 3)).collect();
    inputs.extend((0..4).map(stars));
    inputs.push(rounded_rectangle(0.0, 0.0, 10.0, 6.0, 1.5));
    let (mut built, mut internal) = (0, 0);
    for (k, pieces) in inputs.iter().enumerate() {
        for (mode, seed) in
            [(FaultMode::Noise(1e-3), k as u64), (FaultMode::Random, k as u64 + 100), (FaultMode::Noise(1e-9), k as u64)]
        {
            let mut b = Builder::new();
            for piece in pieces {
                let _ = match *piece {
                    Piece::Point(p) => b.add_point(p),
                    Piece::Segment(p, q) => b.add_segment([p, q]),
                    Piece::Arc(arc) => b.add_arc(arc),
                };
            }
            set_fault_mode(mode, seed);
            let result = b.build();
            set_fault_mode(FaultMode::Off, 0);
            match result {
                Ok(d) => {
                    d.validate().unwrap_or_else(|e| panic!("input {k} {mode:?}: invalid: {e}"));
                    built += 1;
                }
                Err(e) => {
                    assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "input {k} {mode:?}: {e}");
                    internal += 1;
                }
            }
        }
    }
    println!("{built} built, {internal} refused as Internal");
    assert!(built > internal, "most builds complete under faults");
}

/// The failures the families found while the arcs were written, each
/// minimised (`minimise_failures`) and kept by name.
#[test]
fn minimised_regressions() {
    let p = Point::new;
    let q = (std::f64::consts::PI / 8.0).tan();
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let through = |s: Point, m: Point, e: Point| Piece::Arc(CircularArc::through(s, m, e).unwrap());
    // an arc's start a hair inside another arc's circle (below)
    let hair_inside = vec![
        through(
            p(5.808044335711884, 7.4917414154294875),
            p(7.0282152175759816, 8.007711214713378),
            p(8.031638893646512, 8.872686787214244),
        ),
        through(
            p(7.674061215067299, 8.562466963775199),
            p(6.720899228874549, 8.4008467689579),
            p(5.798575006730061, 8.111093617911592),
        ),
    ];
    let cases: Vec<(&str, Vec<Piece>, f64)> = vec![
        // The random split family's seed 476 (`SPLIT_SEEDS=500`),
        // minimised: an arc ending 0.0024 outside another arc's circle,
        // both beside a segment. The edge of that end and the other arc
        // runs round the end, and the new arc, ending there, cuts it once
        // below the end; the vertex solver also fits a circle in the order
        // asked on the same bisector past the edge's kept end, nearer the
        // end that goes, and took it (`arc_vertex::past_kept_end` now tells
        // them apart by the turn round the point).
        (
            "an arc ending a hair outside another's circle, cut below its end",
            vec![
                through(
                    p(4.967386712648022, 7.733474233921925),
                    p(4.829273075855989, 7.738864395332237),
                    p(4.691054559044005, 7.739132943736649),
                ),
                through(
                    p(4.679995050844127, 7.773365064392237),
                    p(4.788948379212266, 7.759136805452498),
                    p(4.897028908968462, 7.739341093730717),
                ),
                Piece::Segment(p(4.967386712648022, 7.733474233921925), p(6.156660651101674, 9.479628515482318)),
            ],
            8.0,
        ),
        // Three more of the random split family (`split_arcs.rs`, 200
        // seeds: seeds 189, 75 and 96, shuffled or scaled down), minimised.
        // Two arcs from one end, the shorter's other end 1.2e-4 inside the
        // longer's circle: that end's cell, a needle from it to the
        // longer's centre, loses its whole boundary to the shorter arc but
        // the stretch of its edge with the longer arc past the shorter's
        // end, outside its cone, where the distances tie (the arc is as
        // far as its own end there).
        (
            "two arcs from one end, the shorter's end a hair inside the longer's circle",
            vec![
                through(
                    p(5.651539346372829, 3.6620563868959835),
                    p(5.373651382483308, 4.497849811024895),
                    p(5.237946811337224, 5.368112206892874),
                ),
                through(
                    p(5.651539346372829, 3.6620563868959835),
                    p(5.511150236306625, 4.061969819814719),
                    p(5.381834615586341, 4.465600004874951),
                ),
            ],
            8.0,
        ),
        // The same, the longer arc in first, with a point and a third arc
        // beside: the needle crosses the edge of that end and the point,
        // 0.85 long, in a stretch of 0.01 that 23 samples miss.
        (
            "two arcs from one end, a needle of a cell across a point's edge",
            vec![
                through(
                    p(5.651539346372829, 3.6620563868959835),
                    p(5.373651382483308, 4.497849811024895),
                    p(5.237946811337224, 5.368112206892874),
                ),
                through(
                    p(5.986511868252364, 5.420543811886546),
                    p(5.9361608889298045, 4.407673405529537),
                    p(5.76844588578615, 3.4075167383452936),
                ),
                through(
                    p(5.651539346372829, 3.6620563868959835),
                    p(5.511150236306625, 4.061969819814719),
                    p(5.381834615586341, 4.465600004874951),
                ),
                Piece::Point(p(5.890132807428784, 4.406534931214474)),
            ],
            8.0,
        ),
        // An arc's start 0.32 outside another arc's circle: the unbounded
        // edge of that start and the other arc wraps round the start, and
        // its stretch outside the first arc's cone stays, where no
        // perpendicular from its chord reaches (scaled by 2^20 from the
        // family's scaled-down variant).
        (
            "an arc's start a hair outside another arc's circle, its ray round the start",
            vec![
                through(
                    p(0.18863703442089208, 7.207879912822123),
                    p(-0.3024239688053415, 4.6100497653846455),
                    p(1.1253094895582763, 2.384866726690234),
                ),
                through(
                    p(0.4614383928924437, 2.505598139200984),
                    p(2.9895535340801036, -1.3373239583276653),
                    p(7.287707819070564, 0.3013603179117985),
                ),
            ],
            8.0,
        ),
        // An arc's start 0.002 outside another arc's circle, as above, a
        // third arc from the other's start.
        (
            "an arc starting 0.002 outside another arc, a third from that one's start",
            vec![
                through(
                    p(3.0787640391943114, 9.034358862207682),
                    p(5.538115282929401, 9.771612624551505),
                    p(8.07833162653021, 9.398447007358836),
                ),
                through(
                    p(5.055826535149097, 9.717999529777215),
                    p(11.048404979349991, 7.125419801931789),
                    p(9.139824873469442, 0.8812394686475844),
                ),
                through(
                    p(3.0787640391943114, 9.034358862207682),
                    p(2.452289331583585, 9.241759375725348),
                    p(1.7951917203064272, 9.180863878870491),
                ),
            ],
            16.0,
        ),
        // Pieces of `split_arcs.rs`'s random family (its seeds 18 and 23,
        // minimised; refused in 5 and 6 of their variants before the edges
        // of a point site went round the point): an arc's end 0.013 from
        // another arc's end, the second arc 0.038 long beside a segment;
        // and a point 0.006 below a segment ending on an arc and 0.42
        // inside the arc's circle, its cell a thin tongue across the arc
        // whose only part left is its far end, by the point (the edge of
        // the point and the segment, cut twice, was judged lost from the
        // middle of its chord, 0.23 long across the tongue's foot). The
        // least of it: the arc, the segment and the point alone.
        (
            "a point a hair from a segment ending on an arc, inside its circle",
            vec![
                through(
                    p(5.117341867941843, 2.81283625319022),
                    p(4.812002785450521, 3.860212031892211),
                    p(4.570201258195539, 4.924054124744998),
                ),
                Piece::Segment(p(9.518620573920021, 1.6656106032598605), p(4.570201258195539, 4.924054124744998)),
                Piece::Point(p(5.072411572380088, 4.588234845661327)),
            ],
            16.0,
        ),
        (
            "an arc's end a hair from another arc's end, a segment from it",
            vec![
                through(
                    p(1.956146326845328, 0.7527017914292173),
                    p(2.350585294694265, 1.758247019095212),
                    p(2.4467399658076374, 2.8340990458455053),
                ),
                through(
                    p(2.4343895486438214, 2.8289796576520985),
                    p(2.4191144204388824, 2.8178817841702366),
                    p(2.40386548644298, 2.8067479461309466),
                ),
                Piece::Segment(p(2.4343895486438214, 2.8289796576520985), p(0.1411879009209216, 1.878421527896621)),
                Piece::Segment(p(7.265873054502859, 0.0036845424673892513), p(1.956146326845328, 0.7527017914292173)),
            ],
            16.0,
        ),
        (
            "a point a hair from a segment ending on an arc, another arc across",
            vec![
                through(
                    p(5.117341867941843, 2.81283625319022),
                    p(4.812002785450521, 3.860212031892211),
                    p(4.570201258195539, 4.924054124744998),
                ),
                through(
                    p(3.7134106448279454, 4.276760515748265),
                    p(3.841511901692683, 3.6318740128627716),
                    p(3.932755369665334, 2.980749475491824),
                ),
                Piece::Segment(p(9.518620573920021, 1.6656106032598605), p(4.570201258195539, 4.924054124744998)),
                Piece::Point(p(5.072411572380088, 4.588234845661327)),
            ],
            16.0,
        ),
        // equal half circles facing each other (and mirrored, at x = -0):
        // their ends tie at infinity, the direction of the edge there is
        // a sampled zero of the support functions' difference
        ("facing half circles", vec![arc(p(4.0, 0.0), p(5.0, 0.0), -1.0), arc(p(4.0, 2.0), p(5.0, 2.0), 1.0)], 6.0),
        ("facing half circles mirrored", vec![arc(p(-0.0, 0.0), p(-1.0, 0.0), 1.0), arc(p(-0.0, 2.0), p(-1.0, 2.0), -1.0)], 2.0),
        // three rounded rectangles of the arcs benchmark: a vertex of a
        // corner arc, its own end and a point 54,000 units below (the
        // solver's line of solutions was taken for a lightlike one)
        (
            "far vertex below three rounded rectangles",
            [
                [
                    37.33650505565682,
                    3.0563224950002255,
                    37.49520944453021,
                    37.7002343595738,
                    3.261347410043811,
                    3.6677345373677985,
                    3.872759452411384,
                    37.131480140613235,
                ],
                [
                    39.28767677978566,
                    3.073274328081456,
                    39.5581893647876,
                    39.75960649998314,
                    3.274691463276995,
                    3.533899871497817,
                    3.735317006693356,
                    39.08625964459012,
                ],
                [
                    48.20689749505568,
                    3.0552683093191235,
                    48.583022652472934,
                    48.734759665807,
                    3.20700532265319,
                    3.5005678829861306,
                    3.652304896320197,
                    48.055160481721614,
                ],
            ]
            .iter()
            .flat_map(|&[x0, y0, x1, x2, y1, y2, y3, x3]| {
                // the corners of a rounded rectangle: sides x3, x2 and
                // y0, y3; arcs from x1 to x2, y2 to y3, x0 to x3, y1 to y0
                let corners = [p(x0, y0), p(x1, y0), p(x2, y1), p(x2, y2), p(x1, y3), p(x0, y3), p(x3, y2), p(x3, y1)];
                (0..8).map(move |k| {
                    let (s, e) = (corners[k], corners[(k + 1) % 8]);
                    if k % 2 == 0 {
                        Piece::Segment(s, e)
                    } else {
                        arc(s, e, q)
                    }
                })
            })
            .collect(),
            50.0,
        ),
        // the edge at infinity between two quarter arcs (its direction
        // was the left normal of the midpoints; now where the arcs reach
        // equally far)
        ("two quarters above", vec![arc(p(16.0, 2.5), p(14.0, 4.5), q), arc(p(10.0, 4.5), p(8.5, 6.0), q)], 16.0),
        // the separator of an arc and its own end at infinity: the radial
        // ray, where the support functions only touch
        ("two quarters below", vec![arc(p(8.5, 0.0), p(10.0, 1.5), q), arc(p(14.0, 0.5), p(16.0, 2.5), q)], 16.0),
        // a vertex on a segment's separator beside an arc: the two circles
        // told apart by the limit order of the touching points
        (
            "segment separator beside a major arc",
            vec![
                through(
                    p(0.5860536738139531, 1.688329738735034),
                    p(0.6774860034388183, 1.393360214496651),
                    p(0.37412067599131615, 1.3355989019014738),
                ),
                Piece::Segment(p(1.5862830710843003, 1.2351925335102054), p(1.7091949701180797, 1.2075232970850867)),
            ],
            2.0,
        ),
        // a circle through an arc's far end touching it outside its span
        // is no vertex of the arc
        (
            "small major arc and points",
            vec![
                arc(p(2.5653053577611127, 0.49907584082533846), p(2.4460306712080997, 0.5367825416772518), -1.3448508542112902),
                Piece::Point(p(2.698588263057324, 2.7544267987067874)),
                Piece::Point(p(2.3026185181333516, 1.5238059107847193)),
            ],
            3.0,
        ),
        // two arcs bent at a common end: the vertex of the end's own circle
        // fits the distances too, but is not the triple's
        (
            "bent chain of two arcs",
            vec![
                arc(
                    p(-3.365341295494898, -0.8634076946683307),
                    p(-3.4563483427289916, -0.38961647773224206),
                    0.056736216684684246,
                ),
                arc(
                    p(-3.4563483427289916, -0.38961647773224206),
                    p(-3.6721166247612738, -0.2677190730692256),
                    -0.03755259995762972,
                ),
            ],
            4.0,
        ),
        // a fillet continuing a segment to within rounding (DXF's bulge
        // tan(turn/4)): along their common separator at infinity the arc
        // reaches exactly as far as the segment, a tie
        (
            "fillet after a segment",
            vec![
                arc(p(3.915172883037511, 0.3229822720338445), p(3.846383266350475, 0.4442167111175046), 0.26381388851567816),
                Piece::Segment(p(3.915305808673275, -0.23756022561524337), p(3.915172883037511, 0.3229822720338445)),
            ],
            4.0,
        ),
        // a fillet before a tangent segment: the vertex at the arc's
        // centre ties with the arc (all of it on the circle)
        (
            "fillet before a segment",
            vec![
                arc(p(0.8247334520687937, 0.4030376653859736), p(0.7259978576020354, 0.5207989039518675), 0.4885384011451861),
                Piece::Segment(p(0.7259978576020354, 0.5207989039518675), p(-0.6790901116763554, 0.4704468506287919)),
                Piece::Segment(p(0.5700974603517577, 2.1934299860049036), p(0.9011832625331512, 2.59626404596324)),
            ],
            3.0,
        ),
        // half circles in a row (LibreCAD's ant3.dxf), a cusp where they
        // meet: the whole normal from the cusp to the next centre ties the
        // cusp, both arcs and the next end; the exact turn (zero) must
        // leave the decision to the rules built for such ties
        (
            "half circles meeting in a cusp",
            vec![
                arc(p(4.0, 3.0), p(0.0, 3.0), 1.0),
                arc(p(8.0, 3.0), p(4.0, 3.0), 1.0),
                Piece::Segment(p(12.0, 3.0), p(12.0, 0.0)),
            ],
            12.0,
        ),
        // a half circle whose ends lie on two segments that leave them the
        // arc's way (LibreCAD's c14.dxf, where the segments go on past the
        // ends too): cusps at both ends, the vertex of a segment, its end
        // and the other segment at the arc's centre, on the arc's circle;
        // kept, it left the edge between the segments cut in its middle
        (
            "half circle between segments leaving its ends its way",
            vec![
                arc(p(8.75, -2.5), p(8.75, 2.5), 1.0),
                Piece::Segment(p(8.75, 2.5), p(15.0, 2.5)),
                Piece::Segment(p(15.0, -2.5), p(8.75, -2.5)),
            ],
            16.0,
        ),
        // c14 itself: the arc's ends lie exactly inside the rectangle's
        // sides (split there by the build, as at any input vertex)
        (
            "half circle with its ends inside a rectangle's sides",
            vec![
                arc(p(8.75, -2.5), p(8.75, 2.5), 1.0),
                Piece::Segment(p(5.0, 2.5), p(15.0, 2.5)),
                Piece::Segment(p(15.0, 2.5), p(15.0, -2.5)),
                Piece::Segment(p(15.0, -2.5), p(5.0, -2.5)),
                Piece::Segment(p(5.0, -2.5), p(5.0, 2.5)),
            ],
            16.0,
        ),
        // LibreCAD's t2.dxf, a transformer's coils: a half circle whose
        // top end lies 1.8e-15 below the line of the points beside it. The
        // circle of those points is 1e16 across, and the arc leaves its end
        // into it at an angle of 3e-16 (exact: `leaves_into_circle`); the
        // vertex of the end, a point and the arc is then 1e15 away (sought
        // far only where no near one fits). (Two such half circles and a
        // point: below.)
        (
            "half circle an ulp below two points' line",
            vec![
                arc(p(4.0, -4.000000000000002), p(4.0, -1.7763568394002505e-15), 1.0),
                Piece::Point(p(0.0, 0.0)),
                Piece::Point(p(15.0, 0.0)),
            ],
            16.0,
        ),
        // the same with a segment ending at the arc's end's neighbour
        // (`leaves_into_tangent_circle`; the segment's foot at a vertex
        // 1e15 away moves along it by the vertex's rounding)
        (
            "half circle an ulp below a segment's line",
            vec![
                arc(p(11.0, -1.7763568394002505e-15), p(11.0, -4.000000000000002), 1.0),
                Piece::Segment(p(4.0, -1.7763568394002505e-15), p(0.0, 0.0)),
            ],
            16.0,
        ),
        // Found by splitting random crossing arcs (`split_arcs.rs`), each
        // refused by the build's vertex check before. An arc's start a hair
        // (0.026) inside another arc's circle: the edge between that start
        // and the other arc is an ellipse round the start, and from the
        // chord of its ends it ran the long way round the start's far side,
        // where the start's cell keeps its middle once the new arc passes;
        // points put on the edge from the chord (`bisector_point`) never
        // reached there, and the middle was taken for lost
        // (`round_enclosed_point`: by the angle round the point)
        ("an arc's start a hair inside another arc's circle", hair_inside.clone(), 16.0),
        // the same with a segment from the second arc's end
        (
            "an arc's start a hair inside another arc's circle, a segment from its end",
            [
                &hair_inside[..],
                &[Piece::Segment(p(5.798575006730061, 8.111093617911592), p(6.0005340338871065, 8.370670631587497))],
            ]
            .concat(),
            16.0,
        ),
        // An arc's start beyond the end of another, whose end lies inside
        // its circle: the edge of that end and the first arc runs out to
        // infinity, and the second arc's cell takes a stretch out of its
        // middle (kept between two vertices, 8 and 57 away); only edges
        // with both ends finite, or at infinity, could keep their middle
        // (`is_ray`, `arc_middle_margin_on_ray`)
        (
            "an arc past another's end, that end inside its circle",
            vec![
                through(
                    p(9.666802336949146, 1.0336287889499274),
                    p(9.202668932680496, 5.632146700932871),
                    p(7.236404940677728, 9.814920029424307),
                ),
                through(
                    p(8.757227316646803, 8.1177348272542),
                    p(6.233302635300408, 10.995736862812265),
                    p(2.5449875521090535, 9.971323195932998),
                ),
            ],
            64.0,
        ),
        // LibreCAD's alg30.dxf with its circle cut where a line along the
        // circle's tangent starts (a cusp of the line and the quarter after
        // the cut): the vertex at the centre of the segment, the quarter's
        // far end and the other quarter ties with the new quarter (all of
        // it on the circle), and an edge of it runs into the quarter's
        // sector (in conflict then); the growth goes on past the centre,
        // the cone's apex; three arcs of one circle meet at its centre
        (
            "a circle in three arcs and a segment along its tangent",
            vec![
                arc(p(10.0, 10.0), p(-10.0, 10.0), 1.0),
                arc(p(-10.0, 10.0), p(0.0, 0.0), q),
                arc(p(0.0, 0.0), p(10.0, 10.0), q),
                Piece::Segment(p(0.0, 0.0), p(10.0, 0.0)),
            ],
            24.0,
        ),
        // LibreCAD's ed83 with its circle cut where lines end on it: two
        // arcs 1e-10 off one circle meet at a line's end, a radial line
        // leaves the second's far end, and a chord's end is 2 from the
        // centre. The centre is as far from all three but lies the wrong
        // way round for the vertex asked (it lies out along the join's
        // normal); it was taken, not empty
        (
            "arcs a rounding off one circle, a radial line and a chord",
            vec![
                arc(p(0.0, 15.0), p(-4.581438725, 12.002603108), 0.2980619733770786),
                arc(p(-4.581438725, 12.002603108), p(-5.0, 10.0), 0.10338726200537364),
                Piece::Segment(p(-5.0, 10.0), p(-10.0, 10.0)),
                Piece::Segment(p(0.0, 8.0), p(4.582575695, 8.0)),
            ],
            24.0,
        ),
        // LibreCAD's Logic-NAND: a half circle from a segment's end back to
        // a quarter's start, on the quarter's radial line. The vertex of
        // the two ends and the quarter (the half circle's centre) is a
        // double root of the quarter touched inside; placed 5e-8 off, it
        // fell outside the half circle's cone and its growth stopped there,
        // keeping a vertex the half circle is 2 nearer
        (
            "half circle from a segment's end to a quarter's start",
            vec![
                Piece::Segment(p(35.0, 5.0), p(40.0, 5.0)),
                arc(p(30.0, 5.0), p(20.0, 15.0), 0.41421356237309503),
                arc(p(35.0, 5.0), p(30.0, 5.0), 1.0),
            ],
            24.0,
        ),
        // DejaVu Sans' æ as biarcs: two arcs of different radii meeting an
        // ulp off tangent at the bottom of both circles, and a third arc
        // beside them. The exact side of the join's point at infinity
        // (asked there for kinks over 1e-12 rad only) left the bisector of
        // the two arcs a direction at infinity the search cannot place,
        // and a vertex 196 off its sites was refused
        (
            "biarcs an ulp off tangent and an arc beside them",
            vec![
                arc(p(1551.4238890980798, -23.49286533105294), p(1446.0, -29.0), -0.026101213169333854),
                arc(p(1446.0, -29.0), p(1282.8746788617236, -12.222197506761372), -0.05129082412037185),
                arc(p(660.7620668864039, -12.645282015561707), p(522.0, -29.0), -0.05872754765340209),
            ],
            2048.0,
        ),
        // Two arcs of a circle cut where lines end on it (`arc_offsets`'
        // random cut circles, seed 120), ends written to 8 decimals: their
        // circles 6e-9 apart, not sharing an end. Their vertex with an end
        // point lies in a cluster within 1e-8 of the centre, where the
        // solvers' equations are one to rounding; nothing fitted, and the
        // build was refused (the fallback, an arc's centre, asked the
        // sites to touch its circle to 1e-9 of the radius, now 1e-7)
        (
            "two arcs of circles a rounding apart, not sharing an end",
            vec![
                arc(p(5.39035147, 2.0853777), p(7.04046698, -0.52083896), 0.23403504305444195),
                arc(p(8.60739031, -1.01891763), p(12.321979, 2.38764228), 0.4293765944397774),
            ],
            16.0,
        ),
        // LibreCAD's Coil-air, split: a lens of two circles of radius 2.5
        // whose centres are 2.5 apart, the upper arc cut 1e-7 wide where it
        // passes the lower one's centre. The separators of that short
        // piece's ends meet the lens's axis at a tangent (the ends' edges
        // with the lower arc are circles of radius 1.25 round them, its
        // edge with the upper arc the line they touch); the arcs' solver
        // found no circle for (lower arc, right piece, left piece), and the
        // vertex put among its sites missed them by 0.39. It is placed on
        // its edge now, where the new site is as near as the edge's own.
        // (Checked to 4e-7, the library's own check, 1e-7 of the extent:
        // at the short piece's ends, whose joins bend by 4e-8 rad, a vertex
        // of it and both long pieces stands 1e-7 from one of them.)
        (
            "a lens with a piece 1e-7 long at the other circle's centre",
            vec![
                arc(p(4.999999948380946, 7.5), p(5.000000051619054, 7.5), 1.0323810816317232e-8),
                through(p(2.834936490538894, 6.25), p(5.0000000000000036, 5.000000000001137), p(7.165063509461106, 6.25)),
                through(p(7.165063509461106, 6.25), p(6.250000022351555, 7.165063496556068), p(5.000000051619054, 7.5)),
                through(p(4.999999948380946, 7.5), p(3.749999977648447, 7.16506349655607), p(2.834936490538894, 6.25)),
            ],
            40.0,
        ),
        // LibreCAD's Lamp.dxf minimised: arcs of radius 2.5 round (0, 22.5)
        // and (0, 17.5) touching at (0, 20), their rounded circles 2.6e-15
        // apart; a third through both the lower one's centre and its end,
        // a segment's end 2.5 below that centre. The vertex of the lower
        // arc's two ends and the upper arc lies a rounding beyond the
        // centre, so the lower arc takes it; the rounded answer (at the
        // centre: a tie) left the upper arc's cell reaching the centre and
        // the lower arc's cell a point there, and the third arc then found
        // a vertex 2.5 from its own, another site nearer. Now decided
        // exactly (`exact_join::beyond_centre_touching`: the distance
        // between the circles against the sum of their radii).
        (
            "arcs touching at a point of both, a third through a centre",
            vec![
                arc(p(0.0, 25.0), p(2.165063509461096, 21.25), 1.7320508075688767),
                arc(p(2.165063509461097, 18.75), p(-1.2499999999999996, 19.665063509461095), 0.41421356237309503),
                arc(p(-2.5, 20.0), p(2.165063509461097, 18.75), 0.7673269879789604),
                Piece::Segment(p(0.0, 15.0), p(0.0, 0.0)),
            ],
            50.0,
        ),
        // LibreCAD's LA-2.dxf minimised: a line 1.8e-16 rad off the
        // tangent of a half circle's start, below it. The vertex of the
        // start, the line and the arc lies on the arc's normal at the
        // start, 6.5e16 out; the arcs' solver found no circle and the
        // vertex put among its sites missed them by 1.9. It is solved now
        // as that of the start, the line and a segment along the arc's
        // tangent there (`by_the_tangent_at_an_end`).
        (
            "a line an ulp off a half circle's tangent at its start",
            vec![Piece::Segment(p(0.0, 0.0), p(-1.46957615898e-15, -8.0)), arc(p(0.0, 6.0), p(4.0, 6.0), 1.0)],
            16.0,
        ),
        // LibreCAD's Headphone.dxf: an arc whose start is 1e-11 outside a
        // half circle. That start's cell is a sliver out to infinity round
        // the half circle's radius, bounded by one edge with both ends at
        // infinity; the arc reaches further in all its directions (4.7 at
        // the radius) and takes both ends, and the start keeps that edge's
        // middle, a 1e-11 cell (`growth::is_line`,
        // `arc_middle_margin_on_line`). With the half circle in first it
        // kept its cell at infinity (61 degrees of directions where the
        // other arc reaches further), which passed `validate` and the grid
        // audit; the far check sees it. Refused, once the build checked its
        // edges to infinity, until the tree took the edge's middle.
        (
            "an arc ending a hair outside a half circle",
            vec![
                arc(p(14.26776695297, 0.0), p(10.73223304703, 0.0), 1.0),
                arc(p(11.249999999998423, 1.2500000000240807), p(28.750000000001577, 1.2500000000240854), -1.3257299841847874),
            ],
            32.0,
        ),
    ];
    for (k, (name, pieces, size)) in cases.into_iter().enumerate() {
        check_all_ways(name, &pieces, size, k as u64);
    }
}

/// Inputs that are still refused in some variant (`Internal`, the build's
/// check of its arc vertices), or answered with another vertex count in
/// some: each variant must be refused or answered right (the audit),
/// never answered wrong, and no more variants refused than the case says
/// (which are is printed).
#[test]
fn refused_or_right() {
    let p = Point::new;
    let q = (std::f64::consts::PI / 8.0).tan();
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let through = |s: Point, m: Point, e: Point| Piece::Arc(CircularArc::through(s, m, e).unwrap());
    let cases: Vec<(&str, Vec<Piece>, f64, usize)> = vec![
        // LibreCAD's t2.dxf minimised: two half circles whose tops lie
        // 1.8e-15 below a point's line. The second arc's vertex with the
        // first arc, its own top end and the point is 1e16 away; whether
        // the second arc enters its circle is a sign of 3e-16, exact since
        // `exact_join::leaves_into_circle_touching` (refused in every
        // variant before). Answered in every variant now, but with the
        // second half circle inserted first, one vertex fewer: the first
        // reaches 3e-15 further than the point along the direction 4e-16
        // rad off the vertical where the second and the point tie, which
        // the floating-point direction at infinity cannot see, so its
        // cell misses that sliver of directions and the vertex 1e16 away
        // that closes it. (Deciding that tie exactly broke the rounded
        // families, whose bulges are roundings of their tangent ones: the
        // rest of the construction answers those as ties.)
        (
            "half circles an ulp below their neighbours' line",
            vec![
                arc(p(4.0, -4.000000000000002), p(4.0, -1.7763568394002505e-15), 1.0),
                arc(p(11.0, -1.7763568394002505e-15), p(11.0, -4.000000000000002), 1.0),
                Piece::Point(p(15.0, 0.0)),
            ],
            16.0,
            0,
        ),
        // LibreCAD's Chair-sofa-V.dxf: two quarter circles meeting in a
        // cusp, both leaving it downward and curving apart. The vertex of
        // the first quarter and the second's ends is the second's centre
        // (the first touches its circle at the cusp), in conflict with the
        // second; the vertex of both quarters and the second's far end is
        // there too, which the solvers do not single out. Answered in every
        // variant; mirrored, with one vertex fewer: the segment from that
        // centre to the cusp ties the cusp and both quarters, and whether
        // the first quarter touches the centre with an edge of no length
        // is a matter of representation
        (
            "quarter circles meeting in a cusp",
            vec![arc(p(175.0, -650.0), p(215.0, -610.0), q), arc(p(215.0, -610.0), p(255.0, -650.0), q)],
            128.0,
            0,
        ),
        // The random split family's seed 541 (shuffled), minimised: an arc
        // ending on another's end, a third arc starting 0.06 from there,
        // nearly on the first's circle, and a point. It was the one build
        // of 6000 (`SPLIT_SEEDS=1000`) refused, in 3 of these 6 variants:
        // nothing fitted the vertex of the three arcs, the first's centre
        // was taken for it, where the point is nearer, and the build's
        // check refused it. Answered since the solver tries an arc's end
        // that is a point site of the triple first (`arc_vertex`).
        (
            "an arc's start nearly on another's circle by its end",
            vec![
                through(
                    p(3.4370047627451026, 9.505708857571024),
                    p(3.6482486700110983, 9.445289528456986),
                    p(3.8545648817801066, 9.369737530145358),
                ),
                through(
                    p(3.8680495183093626, 9.429848115412597),
                    p(1.9830292494669661, 9.586333385922298),
                    p(0.11901633611806517, 9.26501592187516),
                ),
                through(
                    p(4.249176428047122, 5.470360329710957),
                    p(3.740592761138627, 7.388548040255944),
                    p(3.8545648817801066, 9.369737530145358),
                ),
                Piece::Point(p(5.380208355508902, 8.218026819909095)),
            ],
            16.0,
            REFUSED_SPLIT_SEED_541,
        ),
    ];
    for (k, (name, pieces, size, most_refused)) in cases.into_iter().enumerate() {
        let refused = right_or_refused(name, &pieces, size, k as u64);
        assert!(refused.len() <= most_refused, "{name}: refused {refused:?}, at most {most_refused} expected");
    }
}

/// The LibreCAD cases of `minimised_regressions` that hang on roundings
/// of 1e-15 (arcs touching with their circles 2e-15 apart; a line 1.8e-16
/// rad off an arc's tangent), a thousand and a million from the origin:
/// there the rounding of the coordinates is larger than the configuration,
/// which becomes another one (the touching arcs cross at 1e3, and are
/// split); each must be answered right (`validate` and the audit) or
/// refused as `Internal`, never answered wrong.
#[test]
fn touching_and_ulp_off_tangent_cases_far_from_the_origin() {
    let p = Point::new;
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let cases: Vec<(&str, Vec<Piece>, f64)> = vec![
        (
            "arcs touching at a point of both, a third through a centre",
            vec![
                arc(p(0.0, 25.0), p(2.165063509461096, 21.25), 1.7320508075688767),
                arc(p(2.165063509461097, 18.75), p(-1.2499999999999996, 19.665063509461095), 0.41421356237309503),
                arc(p(-2.5, 20.0), p(2.165063509461097, 18.75), 0.7673269879789604),
                Piece::Segment(p(0.0, 15.0), p(0.0, 0.0)),
            ],
            50.0,
        ),
        (
            "a line an ulp off a half circle's tangent at its start",
            vec![Piece::Segment(p(0.0, 0.0), p(-1.46957615898e-15, -8.0)), arc(p(0.0, 6.0), p(4.0, 6.0), 1.0)],
            16.0,
        ),
    ];
    let mut answered = 0;
    for (name, pieces, size) in cases {
        for shift in [1e3, 1e6] {
            let input = mapped(&pieces, &|q: Point| p(q.x + shift, q.y - shift), false);
            let mut b = Builder::new();
            add_pieces(&mut b, &input);
            // the arcs' rounded circles may cross there: split, as a user
            // told so would
            let built = match b.build() {
                Err(e) if e.kind() == segvoronoi::ErrorKind::Intersecting => b.split_crossings(true).build(),
                other => other,
            };
            match built {
                Ok(d) => {
                    d.validate().unwrap_or_else(|e| panic!("{name} at {shift}: invalid: {e:?}"));
                    // the audit's tolerance: the size's, or the rounding there
                    let f = audit(&d, (1e-8 * size).max(1e-9 * shift));
                    assert!(f.is_empty(), "{name} at {shift}: answered wrong: {}", f[..f.len().min(5)].join("\n"));
                    answered += 1;
                }
                Err(e) => assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "{name} at {shift}: {e}"),
            }
        }
    }
    // (measured: all four answered)
    assert_eq!(answered, 4, "far from the origin: {answered} of 4 answered");
}

/// Variants of the split family's seed 541 in `refused_or_right` that are
/// refused (measured: none since the solver's order of tangencies put an
/// arc's end that is a point site first; 3 before).
const REFUSED_SPLIT_SEED_541: usize = 0;

/// Time per arc against time per segment on the same layout (each arc
/// replaced by its chord): `cargo test --release --test arcs time_per_arc -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement"]
fn time_per_arc() {
    let side: usize = std::env::var("ARC_SIDE").ok().and_then(|v| v.parse().ok()).unwrap_or(100);
    let pieces = random_cells(42, side);
    let chords: Vec<Piece> = pieces
        .iter()
        .map(|&p| match p {
            Piece::Arc(arc) => Piece::Segment(arc.start(), arc.end()),
            other => other,
        })
        .collect();
    let arcs = pieces.iter().filter(|p| matches!(p, Piece::Arc(_))).count();
    for (name, input) in [("chords", &chords), ("arcs", &pieces)] {
        let start = std::time::Instant::now();
        let d = build(input);
        let t = start.elapsed().as_secs_f64();
        println!("{name}: {} pieces ({arcs} arcs or their chords): {t:.3} s, {} vertices", input.len(), d.vertex_count());
    }
}

/// An arc's cell can reach infinity in a whole range of directions and
/// take the middle of another site's range there: a nearly full arc around
/// a lone point, and a point beside a half circle's convex side (the
/// point's edge at infinity is then cut twice, its middle kept).
#[test]
fn arcs_that_take_the_middle_of_a_range_at_infinity() {
    let p = Point::new;
    let (s, e) = (p(4.103645997839492e-6, 4.444875403163561e-6), p(4.072980325062098e-6, 4.396651608325269e-6));
    let whole = CircularArc::from_bulge(s, e, -16.91563043820798).unwrap();
    let lone = Piece::Point(p(4.414853528807503e-6, 2.55279099708072e-7));
    check_all_ways("nearly full arc around a point", &[lone, Piece::Arc(whole)], 5e-6, 11);
    let m = whole.midpoint();
    let half = (whole.sweep() / 8.0).tan();
    let halves = [
        lone,
        Piece::Arc(CircularArc::from_bulge(s, m, half).unwrap()),
        Piece::Arc(CircularArc::from_bulge(m, e, half).unwrap()),
    ];
    check_all_ways("the same in halves", &halves, 5e-6, 12);
    let beside = [Piece::Point(p(0.5, 3.0)), Piece::Arc(CircularArc::through(p(0.0, 0.0), p(0.5, 0.5), p(1.0, 0.0)).unwrap())];
    assert_eq!(check_all_ways("a point beside a half circle", &beside, 3.0, 13), 1, "the centre alone is a finite vertex");
}

/// Crossing, touching and overlapping inputs are refused, exactly and
/// naming both, by `check` and `build` alike; a shared end, a tangent join
/// and an arc's end inside a segment (which splits it) are not.
#[test]
fn the_input_check_names_both() {
    let p = Point::new;
    let half = |s: Point, e: Point| CircularArc::from_bulge(s, e, 1.0).unwrap();
    let refused = |b: &Builder, message: &str| {
        let e = b.check().unwrap_err();
        assert_eq!(e.kind(), segvoronoi::ErrorKind::Intersecting, "{e}");
        assert!(e.message().contains(message), "{e}");
        assert_eq!(b.build().unwrap_err(), e);
    };
    // an arc and a segment across it
    let mut b = Builder::new();
    b.add_arc(half(p(1.0, 0.0), p(-1.0, 0.0))).unwrap();
    b.add_segment([[0.0, 0.0], [0.0, 2.0]]).unwrap();
    refused(&b, "arc 0 and segment 0 cross");
    // a segment tangent to the arc at its top: touching inside
    let mut b = Builder::new();
    b.add_arc(half(p(1.0, 0.0), p(-1.0, 0.0))).unwrap();
    b.add_segment([[-1.0, 1.0], [1.0, 1.0]]).unwrap();
    refused(&b, "arc 0 and segment 0");
    // two crossing arcs, and an arc overlapping another on one circle
    let mut b = Builder::new();
    b.add_arc(half(p(1.0, 0.0), p(-1.0, 0.0))).unwrap();
    b.add_arc(half(p(2.5, 0.0), p(0.5, 0.0))).unwrap();
    refused(&b, "arcs 0 and 1");
    let mut b = Builder::new();
    b.add_arc(half(p(1.0, 0.0), p(-1.0, 0.0))).unwrap();
    b.add_arc(CircularArc::through(p(0.0, 1.0), p(-0.6, 0.8), p(-0.8, -0.6)).unwrap()).unwrap();
    refused(&b, "arcs 0 and 1"); // an end of one inside the other, on one circle
                                 // a point on the arc
    let mut b = Builder::new();
    b.add_arc(half(p(5.0, 0.0), p(-5.0, 0.0))).unwrap();
    b.add_point([3.0, 4.0]).unwrap();
    refused(&b, "point 0 lies on arc 0");
    // fine: a tangent join, a full circle as two arcs, an arc's end inside
    // a segment (the segment is split there)
    let mut b = Builder::new();
    b.add_segment([[-3.0, 1.0], [1.0, 1.0]]).unwrap();
    b.add_arc(CircularArc::from_bulge([1.0, 1.0], [1.0, -1.0], -1.0).unwrap()).unwrap();
    b.add_arc(half(p(8.0, 0.0), p(6.0, 0.0))).unwrap();
    b.add_arc(half(p(6.0, 0.0), p(8.0, 0.0))).unwrap();
    b.add_arc(half(p(-1.0, 1.0), p(-2.0, 1.0))).unwrap();
    if let Err(e) = b.check() {
        panic!("{e}");
    }
    let d = b.build().unwrap();
    d.validate().unwrap();
    assert!(audit(&d, 1e-7).is_empty());
    assert_eq!(d.stats().split_at_vertices, 2, "the segment is cut at both ends of the last arc");
}

/// Convergence: the diagram of arcs against the diagrams of their chord
/// approximations (4, 16, 64 and 256 chords an arc; segment diagrams,
/// which agree with CGAL's on every family of the C tests). Every vertex of
/// the arcs' diagram has a vertex of the chords' diagram near it, nearer
/// as the chords shrink, at the rate of their sagitta (1/n²).
#[test]
fn chord_diagrams_converge_to_the_arcs_diagram() {
    let mut pieces = rounded_rectangle(0.0, 0.0, 10.0, 6.0, 1.5);
    pieces.extend(rounded_rectangle(2.0, 2.0, 3.0, 2.0, 0.5));
    pieces.extend(stars(3).into_iter().map(|p| {
        match p {
            Piece::Point(q) => Piece::Point(Point::new(q.x + 12.0, q.y)),
            Piece::Segment(a, b) => Piece::Segment(Point::new(a.x + 12.0, a.y), Point::new(b.x + 12.0, b.y)),
            Piece::Arc(arc) => Piece::Arc(
                CircularArc::from_bulge(
                    Point::new(arc.start().x + 12.0, arc.start().y),
                    Point::new(arc.end().x + 12.0, arc.end().y),
                    arc.bulge(),
                )
                .unwrap(),
            ),
        }
    }));
    pieces.push(Piece::Point(Point::new(7.0, 3.0)));
    let exact = build(&pieces);
    let chords = |per_turn: usize| -> Vec<Piece> {
        let mut out = Vec::new();
        for p in &pieces {
            match *p {
                Piece::Arc(arc) => {
                    let n = per_turn;
                    let points: Vec<Point> = (0..=n).map(|k| arc.point_at(k as f64 / n as f64)).collect();
                    out.extend(points.windows(2).map(|w| Piece::Segment(w[0], w[1])));
                }
                other => out.push(other),
            }
        }
        out
    };
    let mut errors = Vec::new();
    for per_turn in [4usize, 16, 64, 256] {
        let approx = build(&chords(per_turn));
        // the chords' diagram as a drawing: its vertices every chord length
        // along an edge are O(1/n) apart, its edges O(1/n²) from the arcs'
        let mut near: Vec<(Point, Point)> = Vec::new();
        for e in approx.edges() {
            if let Some(poly) = approx.edge_polyline(e.id, 1e-7) {
                near.extend(poly.windows(2).map(|w| (w[0], w[1])));
            }
        }
        let to_piece = |q: Point, (a, b): (Point, Point)| distance(&Site::Segment { a, b }, q);
        // vertices within the input's own scale (a vertex far out where
        // sites are nearly parallel moves far for a tiny change of them)
        let worst = exact
            .vertices()
            .filter(|v| v.clearance < 3.0)
            .map(|v| near.iter().map(|&piece| to_piece(v.position, piece)).fold(f64::INFINITY, f64::min))
            .fold(0.0f64, f64::max);
        println!("{per_turn} chords an arc: farthest vertex {worst:.3e}");
        errors.push(worst);
    }
    // coarse chords change the topology near gentle arcs; once they
    // follow it, the error falls as the sagitta, by 16 for 4 times the chords
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "{errors:?}");
    assert!(errors[3] < errors[2] / 8.0, "no quadratic convergence: {errors:?}");
    assert!(errors[3] < 2e-5, "{errors:?}");
}

fn filleted(seed: u64) -> Vec<Piece> {
    four_shapes(seed, |rng, cx, cy| {
        let n = 3 + (rng.next_u64() % 8) as usize;
        filleted_polygon(rng, cx, cy, n, 0.3)
    })
}

#[test]
fn filleted_polygons_as_cad_gives_them() {
    for seed in 0..10 {
        check_all_ways(&format!("filleted seed {seed}"), &filleted(seed), 6.0, seed);
    }
}

/// A slot and a rounded rectangle at 1e-300 and at 1e300 (and 1e8 from
/// the origin): the build scales them by a power of two and back.
/// Arcs among coordinates that span more than the exact range are
/// refused as `UnsupportedRange` before any work (found by the C API's
/// fuzz driver: a full circle of radius 2.5e-160 at x = -2.3e282, whose
/// endpoints round together once the input is scaled, panicked).
#[test]
fn arcs_beyond_the_exact_range_are_refused() {
    let p = Point::new;
    let mut b = Builder::new();
    let (x, y0, y1) = (-2.2647270765748143e282, -7.0000000000000006e-160, -2.0000000000000006e-160);
    b.add_bulged_polyline(&[(p(x, y0), 1.0), (p(x, y1), 1.0)], true).unwrap();
    let e = b.build().unwrap_err();
    assert_eq!(e.kind(), segvoronoi::ErrorKind::UnsupportedRange, "{e}");
    assert!(e.message().contains("with arcs"), "{e}");
    // the same circle at an ordinary place builds
    let mut b = Builder::new();
    b.add_bulged_polyline(&[(p(0.0, y0), 1.0), (p(0.0, y1), 1.0)], true).unwrap();
    let d = b.build().unwrap();
    assert!(audit(&d, 1e-8 * 1e-159).is_empty());
}

#[test]
fn extreme_magnitudes() {
    for k in [1e-300, 1e300, 1.0] {
        let p = |x: f64, y: f64| Point::new(x * k, y * k);
        let mut pieces = vec![
            Piece::Segment(p(0.0, 0.0), p(4.0, 0.0)),
            Piece::Arc(CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap()),
            Piece::Segment(p(4.0, 2.0), p(0.0, 2.0)),
            Piece::Arc(CircularArc::from_bulge(p(0.0, 2.0), p(0.0, 0.0), 1.0).unwrap()),
            Piece::Point(p(4.5, 1.0)),
        ];
        if k == 1.0 {
            pieces = pieces
                .into_iter()
                .map(|q| match q {
                    Piece::Point(a) => Piece::Point(Point::new(a.x + 1e8, a.y)),
                    Piece::Segment(a, b) => Piece::Segment(Point::new(a.x + 1e8, a.y), Point::new(b.x + 1e8, b.y)),
                    Piece::Arc(arc) => Piece::Arc(
                        CircularArc::from_bulge(
                            Point::new(arc.start().x + 1e8, arc.start().y),
                            Point::new(arc.end().x + 1e8, arc.end().y),
                            arc.bulge(),
                        )
                        .unwrap(),
                    ),
                })
                .collect();
        }
        let d = build(&pieces);
        d.validate().unwrap();
        let f = audit(&d, 1e-8 * 4.0 * k.max(if k == 1.0 { 1e8 } else { 0.0 }).max(k));
        assert!(f.is_empty(), "scale {k}: {} failures, first:\n{}", f.len(), f[..f.len().min(3)].join("\n"));
    }
}

/// The medial axis of a diagram with arcs (without a domain: every edge
/// but the separators) samples conic pieces on their curves: each sample's
/// clearance is its distance to the nearest site.
#[test]
fn medial_axis_samples_on_conic_edges() {
    let p = Point::new;
    let mut pieces = rounded_rectangle(0.0, 0.0, 10.0, 6.0, 1.5);
    pieces.extend([
        Piece::Point(p(4.5, 1.0)),
        Piece::Arc(CircularArc::from_bulge(p(12.0, 0.0), p(12.0, 2.0), 1.0).unwrap()),
        Piece::Point(p(12.5, 1.0)),
    ]);
    let d = build(&pieces);
    let sites: Vec<Site> = d.site_ids().map(|s| d.site(s).unwrap()).collect();
    let axis = d.medial_axis();
    let mut samples = 0;
    for chain in &axis.chains {
        let Some(points) = d.sample_chain(chain, 1e-6) else { continue };
        for [x, y, r] in points {
            if !r.is_finite() {
                continue;
            }
            let nearest = sites.iter().map(|s| distance(s, p(x, y))).fold(f64::INFINITY, f64::min);
            assert!((nearest - r).abs() < 1e-6 * (1.0 + r), "sample ({x}, {y}) r {r}: nearest site at {nearest}");
            samples += 1;
        }
    }
    assert!(samples > 100, "{samples}");
    // offsets of arcs are traced (checked in `arc_offsets.rs`)
    assert!(d.offset(0.5).unwrap().area() > 0.0);
}

/// Inputs that were refused (`Internal`, the vertex check catching a
/// wrong decision) and build right now: two half circles one above the
/// other, whose bisectors with the other's ends run parallel out to
/// infinity (the arc ties along its own end at infinity: the order along
/// the supporting line decides, `geometry::arcs::at_infinity`), and a
/// rounded rectangle away from the origin.
#[test]
fn ties_at_infinity_and_a_far_rounded_rectangle() {
    let p = Point::new;
    let half = |s: Point, e: Point, b: f64| CircularArc::from_bulge(s, e, b).unwrap();
    let mut two = Builder::new();
    two.add_arc(half(p(0.0, 0.0), p(1.0, 0.0), -1.0)).unwrap();
    two.add_arc(half(p(0.0, 2.0), p(1.0, 2.0), -1.0)).unwrap();
    let mut rounded = Builder::new();
    let q = (std::f64::consts::PI / 8.0).tan();
    let (x, y, w, h, r) = (0.1, 0.1, 0.6, 0.7, 0.1);
    rounded
        .add_bulged_polyline(
            &[
                ([x + r, y], 0.0),
                ([x + w - r, y], q),
                ([x + w, y + r], 0.0),
                ([x + w, y + h - r], q),
                ([x + w - r, y + h], 0.0),
                ([x + r, y + h], q),
                ([x, y + h - r], 0.0),
                ([x, y + r], q),
            ],
            true,
        )
        .unwrap();
    for b in [two, rounded] {
        let d = b.build().unwrap();
        let failures = audit(&d, 1e-8);
        assert!(failures.is_empty(), "{failures:?}");
    }
}

/// What users have, with arcs: a straight (180°) vertex in a bulged chain,
/// one a hair off straight, a point exactly on a segment beside an arc
/// (the segment is split there), and two closed chains touching at one
/// point, 1e6 off the origin too.
#[test]
fn user_shapes_with_arcs() {
    let p = Point::new;
    let slot_with_straight_vertex = vec![
        Piece::Segment(p(0.0, 0.0), p(2.0, 0.0)),
        Piece::Segment(p(2.0, 0.0), p(4.0, 0.0)), // straight on at (2, 0)
        Piece::Arc(CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap()),
        Piece::Segment(p(4.0, 2.0), p(2.0, 2.0 + 1e-16)), // an ulp-scale bend
        Piece::Segment(p(2.0, 2.0 + 1e-16), p(0.0, 2.0)),
        Piece::Arc(CircularArc::from_bulge(p(0.0, 2.0), p(0.0, 0.0), 1.0).unwrap()),
        Piece::Point(p(3.0, 0.0)), // exactly on the lower side
        Piece::Point(p(1.0, 1.0)),
    ];
    let count = check_all_ways("slot with a straight vertex and a point on a side", &slot_with_straight_vertex, 4.0, 21);
    assert!(count > 0);
    // two closed chains touching at (6, 1): the slot's... a lens to its right
    let mut touching = slot_with_straight_vertex.clone();
    touching.extend([
        Piece::Segment(p(6.0, 1.0), p(8.0, 0.0)),
        Piece::Arc(CircularArc::from_bulge(p(8.0, 0.0), p(8.0, 2.0), 0.5).unwrap()),
        Piece::Segment(p(8.0, 2.0), p(6.0, 1.0)),
        Piece::Segment(p(6.0, 1.0), p(5.5, 1.0)), // a spike from the touching point toward the slot
    ]);
    check_all_ways("two closed chains touching at a point", &touching, 8.0, 23);
    let far: Vec<Piece> = touching
        .iter()
        .map(|&q| {
            let m = |a: Point| Point::new(a.x + 1e6, a.y - 1e6);
            match q {
                Piece::Point(a) => Piece::Point(m(a)),
                Piece::Segment(a, b) => Piece::Segment(m(a), m(b)),
                Piece::Arc(arc) => Piece::Arc(CircularArc::from_bulge(m(arc.start()), m(arc.end()), arc.bulge()).unwrap()),
            }
        })
        .collect();
    check_all_ways("the same 1e6 off the origin", &far, 1e6, 24);
}
