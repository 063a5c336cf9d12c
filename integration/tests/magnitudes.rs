//! Every magnitude: inputs whose coordinates mix 1 with 1e300, 1e-300,
//! subnormal numbers and `f64::MAX` (issue 28).
//!
//! - Within the exact range (largest magnitude at most `2^480` times the
//!   smallest nonzero magnitude or difference), every build succeeds or
//!   gives its input error, and the topology is the same at every
//!   power-of-two scale of the input (an exact transformation: a wrong sign
//!   anywhere would show as a difference).
//! - Beyond it, a build gives a valid diagram with finite positions, or
//!   `UnsupportedRange`: never `Internal`, never an invalid diagram.
//! - Offsets whose region would leave `f64` are refused, the others have
//!   finite, closed loops.

use segvoronoi::{Builder, Diagram, Error, ErrorKind, OffsetPiece, Point, Site, TopologyOptions};

type Segment = [[f64; 2]; 2];

/// A small deterministic generator (splitmix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn builder(points: &[[f64; 2]], segments: &[Segment], factor: f64, split: bool) -> Result<Builder, Error> {
    let mut b = Builder::new();
    b.split_crossings(split);
    for p in points {
        b.add_point([p[0] * factor, p[1] * factor])?;
    }
    for s in segments {
        b.add_segment(s.map(|p| [p[0] * factor, p[1] * factor]))?;
    }
    Ok(b)
}

fn build(points: &[[f64; 2]], segments: &[Segment], factor: f64, split: bool) -> Result<Diagram, Error> {
    builder(points, segments, factor, split)?.build()
}

/// Whether every coordinate survives multiplication by `factor` exactly
/// (no overflow, no rounding in the subnormal range).
fn scales_exactly(points: &[[f64; 2]], segments: &[Segment], factor: f64) -> bool {
    let exact = |v: f64| {
        let w = v * factor;
        w.is_finite() && w / factor == v && (w == 0.0) == (v == 0.0)
    };
    points.iter().chain(segments.iter().flatten()).all(|p| exact(p[0]) && exact(p[1]))
}

/// Everything a diagram reports is finite (a clearance may be infinite for
/// a vertex beyond the range of `f64`, whose position then saturates), and
/// it validates.
fn check_finite(d: &Diagram, what: &str) {
    d.validate().unwrap_or_else(|e| panic!("{what}: invalid diagram: {e:?}"));
    assert!(d.extent().is_finite(), "{what}: extent {}", d.extent());
    for v in d.vertices() {
        assert!(v.position.x.is_finite() && v.position.y.is_finite(), "{what}: vertex at {:?}", v.position);
        assert!(v.clearance >= 0.0, "{what}: clearance {}", v.clearance);
    }
    for k in 0..d.site_count() {
        let site = d.site(segvoronoi::SiteId::from_index(k)).expect("a site");
        let ends: Vec<Point> = match site {
            Site::Point(p) => vec![p],
            Site::Segment { a, b } => vec![a, b],
            _ => unreachable!("points and segments only"),
        };
        assert!(ends.iter().all(|p| p.x.is_finite() && p.y.is_finite()), "{what}: site {site:?}");
    }
}

/// The build's outcome where only these are acceptable: a valid, finite
/// diagram or a typed input error; `Internal` never.
fn assert_never_internal(result: &Result<Diagram, Error>, what: &str) {
    match result {
        Ok(d) => check_finite(d, what),
        Err(e) => assert!(
            matches!(e.kind(), ErrorKind::Intersecting | ErrorKind::UnsupportedRange | ErrorKind::InvalidPolygon),
            "{what}: {:?}: {e}",
            e.kind()
        ),
    }
}

/// The four segments: a segment of length 1 at `-m`, between long
/// ones of extent `m`.
fn four_segments(m: f64) -> Vec<Segment> {
    vec![[[1.0, -m], [-m, 2.0]], [[-m, 2.0], [0.0, -m]], [[0.0, -m], [1.0, -m]], [[1.0, -m], [0.0, m]]]
}

fn topology(d: &Diagram) -> String {
    d.topology(TopologyOptions::default())
}

#[test]
fn the_four_segments_build_within_the_exact_range_at_every_scale() {
    for m in [1e100, 1e140, 1e170, 1e200] {
        let segments = four_segments(m);
        let d = build(&[], &segments, 1.0, false).unwrap_or_else(|e| panic!("M = {m:e}: {e}"));
        check_finite(&d, &format!("M = {m:e}"));
        let text = topology(&d);
        for k in [-1000, -600, -300, 100] {
            let factor = 2f64.powi(k);
            if scales_exactly(&[], &segments, factor) {
                let scaled = build(&[], &segments, factor, false).expect("the same input scaled");
                assert_eq!(topology(&scaled), text, "M = {m:e} scaled by 2^{k}");
            }
        }
    }
}

#[test]
fn the_four_segments_beyond_the_exact_range_build_or_are_refused_by_kind() {
    for m in [1e250, 1e300, f64::MAX] {
        let result = build(&[], &four_segments(m), 1.0, false);
        assert_never_internal(&result, &format!("M = {m:e}"));
        if let Err(e) = result {
            assert!(e.message().contains("span"), "M = {m:e}: the message names the span: {e}");
        }
    }
}

/// A cluster of points and short segments an ulp or a few apart at (1, 1),
/// some unit-sized sites, and a far point (and sometimes a far segment) at
/// `2^(span - 50)`: the input spans about `span` bits.
fn cluster_with_far_sites(seed: u64, span: i32) -> (Vec<[f64; 2]>, Vec<Segment>) {
    let mut r = Rng(seed);
    let ulp = 2f64.powi(-50);
    let far = 2f64.powi(span - 50);
    let near = |r: &mut Rng| [1.0 + ulp * r.below(8) as f64, 1.0 + ulp * r.below(8) as f64];
    let mut points: Vec<[f64; 2]> = (0..3).map(|_| near(&mut r)).collect();
    let mut segments = Vec::new();
    for _ in 0..1 + r.below(2) {
        let a = near(&mut r);
        let b = [a[0] + ulp * (1 + r.below(3)) as f64, a[1] + ulp * (r.below(5) as f64 - 2.0)];
        segments.push([a, b]);
    }
    for _ in 0..2 {
        points.push([r.unit() * 4.0 - 2.0, r.unit() * 4.0 - 2.0]);
    }
    points.push([far * (r.unit() - 0.5), -far]);
    if r.below(2) == 0 {
        segments.push([[-far, far * r.unit()], [far, far]]);
    }
    points.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
    points.dedup();
    (points, segments)
}

#[test]
fn clusters_far_from_their_neighbours_give_one_topology_at_every_scale() {
    for span in [200, 300, 400, 470] {
        for seed in 0..12 {
            let (points, segments) = cluster_with_far_sites(seed * 7919 + span as u64, span);
            let base = build(&points, &segments, 1.0, false);
            let text = match &base {
                Ok(d) => {
                    check_finite(d, &format!("span {span} seed {seed}"));
                    topology(d)
                }
                // the cluster's pieces may touch: an input error, the same at every scale
                Err(e) => {
                    assert_eq!(e.kind(), ErrorKind::Intersecting, "span {span} seed {seed}: {e}");
                    continue;
                }
            };
            for k in [-700, -300, 300] {
                let factor = 2f64.powi(k);
                if scales_exactly(&points, &segments, factor) {
                    let scaled = build(&points, &segments, factor, false).expect("the same input scaled");
                    assert_eq!(topology(&scaled), text, "span {span} seed {seed} scaled by 2^{k}");
                }
            }
        }
    }
}

/// A coordinate from the mix: small integers and quarters, ±1e300,
/// ±1e-300, subnormal multiples, ±f64::MAX (or, `narrow`, magnitudes of
/// 1e70 and 1e-70, which stay within the exact range).
fn mixed_coordinate(r: &mut Rng, narrow: bool) -> f64 {
    let sign = if r.below(2) == 0 { 1.0 } else { -1.0 };
    let (huge, tiny, tiniest, top) = if narrow { (1e70, 1e-70, 1e-70, 3e71) } else { (1e300, 1e-300, 5e-324, f64::MAX) };
    sign * match r.below(6) {
        0 => r.below(10) as f64,
        1 => huge,
        2 => tiny,
        3 => tiniest * r.below(5) as f64,
        4 => top,
        _ => r.below(100) as f64 * 0.25,
    }
}

fn mixed_input(seed: u64, narrow: bool) -> (Vec<[f64; 2]>, Vec<Segment>) {
    let mut r = Rng(seed);
    let points = (0..r.below(4)).map(|_| [mixed_coordinate(&mut r, narrow), mixed_coordinate(&mut r, narrow)]).collect();
    let segments = (0..1 + r.below(6))
        .map(|_| {
            let a = [mixed_coordinate(&mut r, narrow), mixed_coordinate(&mut r, narrow)];
            let b = [mixed_coordinate(&mut r, narrow), mixed_coordinate(&mut r, narrow)];
            [a, b]
        })
        .filter(|[a, b]| a != b)
        .collect();
    (points, segments)
}

#[test]
fn mixed_magnitudes_never_give_internal_or_non_finite_results() {
    let seeds = if cfg!(debug_assertions) { 150 } else { 1500 };
    for split in [false, true] {
        for seed in 0..seeds {
            let (points, segments) = mixed_input(seed, false);
            let Ok(b) = builder(&points, &segments, 1.0, split) else { continue };
            assert_never_internal(&b.build(), &format!("seed {seed} split {split}: {points:?} {segments:?}"));
        }
    }
}

#[test]
fn mixed_magnitudes_within_the_exact_range_always_build() {
    let seeds = if cfg!(debug_assertions) { 150 } else { 1500 };
    for seed in 0..seeds {
        let (points, segments) = mixed_input(seed, true);
        let Ok(b) = builder(&points, &segments, 1.0, true) else { continue };
        let d = b.build().unwrap_or_else(|e| panic!("seed {seed}: {e}: {points:?} {segments:?}"));
        check_finite(&d, &format!("seed {seed}"));
        let text = topology(&d);
        let without_split = build(&points, &segments, 1.0, false);
        if let Ok(plain) = &without_split {
            check_finite(plain, &format!("seed {seed} without splitting"));
        }
        let factor = 2f64.powi(-200);
        if scales_exactly(&points, &segments, factor) {
            let scaled = build(&points, &segments, factor, true).expect("the same input scaled");
            assert_eq!(topology(&scaled), text, "seed {seed} scaled by 2^-200");
        }
    }
}

/// The inputs the C-API fuzz driver found, minimised.
#[test]
fn fuzz_findings_give_valid_diagrams_or_typed_errors() {
    let max = f64::MAX;
    // a polyline from 4e-300 through 2 to f64::MAX: built "OK", then invalid
    let mut b = Builder::new();
    if b.add_polyline(&[[-4e-300, 0.0], [1.4314920874399837e-76, 2.0], [-6.0, -max]]).is_ok() {
        assert_never_internal(&b.build(), "polyline through f64::MAX");
    }
    // a vertex at -inf with a NaN clearance
    let segments = [[[-6.0, 5.0], [-4.914_827_236_133_913e54, -5e300]]];
    assert_never_internal(&build(&[[0.5, -max / 2.0]], &segments, 1.0, false), "far point and segment");
    // a ring of extent f64::MAX: the extent saturates
    let mut b = Builder::new();
    b.add_polygon(&[vec![[6e150, -1.7976931348623155e308], [6e150, max], [-3.1544034563080905e227, max]]]).expect("a ring");
    let result = b.build();
    assert_never_internal(&result, "ring of extent beyond f64");
    if let Ok(d) = result {
        assert_eq!(d.extent(), max);
    }
}

fn square(half: f64) -> Vec<[f64; 2]> {
    vec![[-half, -half], [half, -half], [half, half], [-half, half]]
}

/// Every loop closes (each piece starts where the last ended, within the
/// rounding of the loop's size) and has finite points and area.
fn check_loops(d: &Diagram, distance: f64) {
    let offset = d.offset(distance).unwrap_or_else(|e| panic!("offset {distance:e}: {e}"));
    assert!(offset.area().is_finite(), "offset {distance:e}: area {}", offset.area());
    for l in &offset.loops {
        let ends: Vec<(Point, Point)> = l
            .pieces
            .iter()
            .map(|p| match *p {
                OffsetPiece::Line { from, to, .. } | OffsetPiece::Arc { from, to, .. } => (from, to),
                _ => unreachable!("lines and arcs only"),
            })
            .collect();
        let size = d.extent() + 2.0 * distance.abs();
        for (k, &(from, to)) in ends.iter().enumerate() {
            assert!(from.x.is_finite() && from.y.is_finite() && to.x.is_finite() && to.y.is_finite());
            let next = ends[(k + 1) % ends.len()].0;
            assert!(to.distance(next) <= 1e-9 * size, "offset {distance:e}: a gap of {:e}", to.distance(next));
        }
    }
}

#[test]
fn offsets_are_finite_up_to_their_range_and_refused_beyond() {
    for half in [1.0, 1e100, 1e150] {
        let mut b = Builder::new();
        b.add_polygon(&[square(half)]).expect("a square");
        b.add_points([[0.25 * half, 0.5 * half], [-0.5 * half, 0.125 * half]]).expect("points inside");
        let d = b.build().expect("a diagram");
        for distance in [half / 10.0, -half / 10.0, half] {
            check_loops(&d, distance);
        }
        // far beyond the input: the offset's area would overflow
        let refused = d.offset(1e200).expect_err("a distance beyond the range");
        assert_eq!(refused.kind(), ErrorKind::InvalidArgument);
    }
    // a tiny input is scaled up inside: a distance far beyond its extent
    // is refused, one of its own size is traced
    let mut b = Builder::new();
    b.add_polygon(&[square(1e-159)]).expect("a square");
    let d = b.build().expect("a diagram");
    check_loops(&d, 1e-160);
    check_loops(&d, -1e-160);
    assert_eq!(d.offset(2.0).expect_err("far beyond a tiny input").kind(), ErrorKind::InvalidArgument);
    // an input of extent 1e300 has no offsets within f64
    let mut b = Builder::new();
    b.add_polygon(&[square(1e300)]).expect("a square");
    b.add_point([1e299, 2e299]).expect("a point inside");
    let d = b.build().expect("a diagram");
    check_finite(&d, "square of 1e300");
    let refused = d.offset(1e299).expect_err("an offset beyond the range");
    assert_eq!(refused.kind(), ErrorKind::InvalidArgument);
    assert!(refused.message().contains("extent"), "{refused}");
}

/// A long rectangle (10 × 1) and a point below it, at every scale from
/// subnormal-adjacent to `f64::MAX` wide: the domain is located exactly
/// (the ring's orientation and the point location were decided on the
/// input's own coordinates, whose products overflow or underflow there),
/// so the largest inscribed circle is the closed form's.
#[test]
fn domains_at_the_ends_of_the_range_are_located_exactly() {
    for unit in [1e-300, 1e-200, 1.0, 1e200, 1e300, f64::MAX / 10.0] {
        let corners = [[0.0, 0.0], [10.0 * unit, 0.0], [10.0 * unit, unit], [0.0, unit]];
        for with_point in [false, true] {
            let mut b = Builder::new();
            b.add_polygon(&[corners.to_vec()]).expect("a rectangle");
            if with_point {
                b.add_point([3.0 * unit, -2.0 * unit]).expect("a point below");
            }
            let d = b.build().unwrap_or_else(|e| panic!("unit {unit:e}: {e}"));
            check_finite(&d, &format!("unit {unit:e}"));
            let (centre, r) = d.max_inscribed_circle().unwrap_or_else(|| panic!("unit {unit:e}: no circle"));
            let what = format!("unit {unit:e}, point {with_point}: circle at {centre:?} r {r:e}");
            assert!((r - 0.5 * unit).abs() <= 1e-12 * unit, "{what}");
            assert!((centre.y - 0.5 * unit).abs() <= 1e-12 * unit, "{what}");
            assert_eq!(d.locate_point(centre), Some(segvoronoi::Location::Inside), "{what}");
            assert_eq!(d.locate_point(Point::new(5.0 * unit, 2.0 * unit)), Some(segvoronoi::Location::Outside), "{what}");
        }
    }
}

/// Found by the C-API fuzz driver (case 0x98e14134e143ddc0): a polyline to
/// (5e300, -f64::MAX) crossing a triangle near 5e300, with
/// `split_crossings`. Its last piece runs parallel to the triangle's top
/// edge, one ulp below it. Within the exact range and not a matter of
/// magnitude (scaled by `2^-1000` it failed the same way): the middle
/// margin of the edge between the piece's two endpoints was sampled 1e9
/// out, where it is rounding noise, so the wrong edge of a cycle was cut
/// twice; two vertices that exist only at infinity were made, one located
/// inside the triangle with an infinite inscribed circle. Minimised into
/// the `parallel_*` fixtures (`c_tests/fixtures/`, audited exactly and
/// checked against CGAL) and `parallel_segments_an_ulp_apart_pass_the_audit`.
#[test]
fn polyline_to_minus_max_crossing_a_triangle() {
    let mut b = Builder::new();
    b.split_crossings(true);
    let polyline = [[-7e300, -8e300], [-6e300, -2e300], [1e300, 1e300], [5e300, -f64::MAX], [3e300, 5e300], [5e300, 5e300]];
    b.add_polyline(&polyline).expect("a polyline");
    let top = 5.000_000_000_000_001e300;
    b.add_polygon(&[vec![[-2e300, 4e300], [8e300, top], [-2e300, top]]]).expect("a triangle");
    let d = b.build().expect("a diagram");
    check_finite(&d, "polyline to -f64::MAX");
    let (_, r) = d.max_inscribed_circle().expect("a circle");
    assert!(r < 1e300, "inscribed radius {r:e}");
}

/// Far from the origin, a vertex's centre is rounded at its magnitude: a
/// few units 2^30 out, that rounding is far above the polish's tolerance
/// relative to the sites' size, and every vertex was polished again to
/// the same rounded centre (3,000 crossing segments split: 76,000 polishes
/// for 45,000 vertices, 7.3 s against 62 ms at the origin). Random
/// crossing segments, and GSHHG's coasts and borders of Europe (from
/// Debian's gmt-gshhg, crossing too) with a straight (180-degree) vertex,
/// a point exactly on a segment and two squares touching at a corner,
/// all split, translated exactly 2^20 and 2^30 out: polished about as
/// often as at the origin, with the same pieces and the same topology.
#[test]
fn segments_far_from_the_origin_are_polished_as_at_the_origin() {
    use segvoronoi::diagnostics::take_predicate_counts;
    let mut rng = Rng(31);
    // (coordinates on a grid of 2^-12 in a square of 16: exact 2^30 out)
    let mut at = || (rng.below(1 << 16) as f64) / 4096.0;
    let random: Vec<Segment> = (0..600)
        .map(|_| {
            let (x, y) = (at(), at());
            let (dx, dy) = (at() / 4.0 - 2.0, at() / 4.0 - 2.0);
            [[x, y], [x + dx, y + dy]]
        })
        .collect();
    // (the outline's coordinates are integers: exact 2^30 out)
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/gshhg_coast_borders_c_europe.txt");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let parsed = segvoronoi::boost_text::parse(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut europe: Vec<Segment> = parsed.segments.iter().map(|s| [[s[0], s[1]], [s[2], s[3]]]).collect();
    let (x0, y0) = europe.iter().flatten().fold((f64::INFINITY, f64::INFINITY), |(x, y), p| (x.min(p[0]), y.min(p[1])));
    let (px, py) = (x0, y0 - 20_000.0);
    europe.extend([[[px, py], [px + 5_000.0, py]], [[px + 5_000.0, py], [px + 10_000.0, py]]]);
    for (x, y) in [(px + 20_000.0, py), (px + 24_000.0, py + 4_000.0)] {
        let c = [[x, y], [x + 4_000.0, y], [x + 4_000.0, y + 4_000.0], [x, y + 4_000.0]];
        europe.extend((0..4).map(|k| [c[k], c[(k + 1) % 4]]));
    }
    let canonical = TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true);
    for (what, segments, points, crossings) in
        [("random segments", random, vec![], 400), ("Europe's outline", europe, vec![[px + 1_250.0, py]], 1)]
    {
        let mut counted = Vec::new();
        for o in [0.0, 2f64.powi(20), 2f64.powi(30)] {
            let moved = |p: [f64; 2]| [o + p[0], o - p[1]];
            let mut b = Builder::new();
            b.threads(1).split_crossings(true).add_segments(segments.iter().map(|s| s.map(moved))).unwrap();
            b.add_points(points.iter().map(|&p| moved(p))).unwrap();
            let _ = take_predicate_counts();
            let d = b.build().unwrap_or_else(|e| panic!("{what} {o} out: {e}"));
            d.validate().unwrap_or_else(|e| panic!("{what} {o} out: {e:?}"));
            let stats = d.stats();
            assert!(stats.crossings >= crossings, "{what}: too few crossings to test: {}", stats.crossings);
            if !points.is_empty() {
                assert!(stats.touchings > 0, "{what} {o} out: the point on a segment was not met");
            }
            counted.push((o, take_predicate_counts().polished_vertices, (stats.pieces, d.vertex_count()), d.topology(canonical)));
        }
        let (_, at_origin, sizes, topology) = &counted[0];
        for (o, polished, other_sizes, other_topology) in &counted[1..] {
            assert!(
                *polished <= at_origin + at_origin / 4 + 20,
                "{what} {o} out: {polished} polishes, {at_origin} at the origin"
            );
            assert_eq!(other_sizes, sizes, "{what} {o} out: another split or diagram");
            assert!(other_topology == topology, "{what} {o} out: another topology");
        }
    }
}
