//! The topology survives lying arithmetic: with every decided quantity
//! perturbed by up to 1e-3 relative, or replaced by random numbers, builds
//! terminate and pass every topological invariant. A build that cannot
//! complete returns `ErrorKind::Internal`, never an invalid diagram (with
//! the restart budget cut to zero, closed chains get there). Run with
//! `cargo test --features fault-injection --test fault_injection`.
#![cfg(feature = "fault-injection")]

mod common;

use common::*;
use segvoronoi::fault_injection::{set_fault_mode, FaultMode};
use segvoronoi::{Builder, Diagram, Error, ErrorKind};

/// `builder.build()` under faults, held to the contract: a diagram that
/// validates, or `ErrorKind::Internal` with a message, and the builder
/// unchanged either way.
fn try_build_with(mode: FaultMode, seed: u64, builder: &Builder) -> Result<Diagram, Error> {
    let counts = (builder.point_count(), builder.segment_count());
    set_fault_mode(mode, seed);
    let result = builder.build();
    set_fault_mode(FaultMode::Off, 0);
    match &result {
        Ok(d) => d.validate().unwrap_or_else(|e| panic!("{mode:?} seed {seed}: Ok with an invalid diagram: {e}")),
        Err(e) => {
            assert_eq!(e.kind(), ErrorKind::Internal, "{mode:?} seed {seed}: {e}");
            assert!(e.message().starts_with("construction could not complete: "), "{e}");
            assert!(e.message().ends_with("; please report this input"), "{e}");
        }
    }
    assert_eq!((builder.point_count(), builder.segment_count()), counts);
    result
}

fn try_build_under(mode: FaultMode, seed: u64, points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Result<Diagram, Error> {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    try_build_with(mode, seed, &b)
}

/// With the full restart budget these inputs always complete.
fn build_under(mode: FaultMode, seed: u64, points: &[[f64; 2]]) -> Diagram {
    try_build_under(mode, seed, points, &[]).unwrap_or_else(|e| panic!("{mode:?} seed {seed}: {e}"))
}

/// A regular `n`-gon of radius `r`, turned by `phase`.
fn ring(n: usize, r: f64, phase: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = phase + std::f64::consts::TAU * k as f64 / n as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

fn lattice(side: usize) -> Vec<[f64; 2]> {
    (0..side * side).map(|i| [(i % side) as f64, (i / side) as f64]).collect()
}

fn circle(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / n as f64;
            [a.cos(), a.sin()]
        })
        .collect()
}

#[test]
fn ten_thousand_points_with_relative_noise() {
    for seed in 0..3 {
        let pts = uniform(10_000, seed);
        let d = build_under(FaultMode::Noise(1e-3), seed, &pts);
        assert_eq!(d.site_count(), 10_000);
    }
}

#[test]
fn ten_thousand_points_with_random_arithmetic() {
    for seed in 0..3 {
        let pts = uniform(10_000, 100 + seed);
        let d = build_under(FaultMode::Random, seed, &pts);
        assert!(d.site_count() >= 1);
    }
}

#[test]
fn degenerate_inputs_with_lying_arithmetic() {
    for (mode, seed) in [(FaultMode::Noise(1e-3), 1), (FaultMode::Random, 2), (FaultMode::Noise(1e-9), 3)] {
        build_under(mode, seed, &lattice(60));
        build_under(mode, seed, &circle(2000));
        let collinear: Vec<[f64; 2]> = (0..500).map(|i| [i as f64, 2.0 * i as f64]).collect();
        build_under(mode, seed, &collinear);
        let mut nearly: Vec<[f64; 2]> = collinear.clone();
        nearly.push([3.0, 1e-12]);
        build_under(mode, seed, &nearly);
    }
}

#[test]
fn exact_mode_is_restored_after_faults() {
    let pts = uniform(2000, 9);
    let exact = build(&pts).topology(Default::default());
    // the faults really change decisions (else these tests would prove nothing)
    let faulty = build_under(FaultMode::Random, 5, &pts).topology(Default::default());
    assert_ne!(faulty, exact);
    let noisy = build_under(FaultMode::Noise(1e-3), 5, &pts).topology(Default::default());
    assert_ne!(noisy, exact);
    assert_eq!(build(&pts).topology(Default::default()), exact);
}

mod small_inputs {
    use super::*;
    use proptest::prelude::*;

    fn points() -> impl Strategy<Value = Vec<[f64; 2]>> {
        prop_oneof![
            prop::collection::vec((0..5i32, 0..5i32).prop_map(|(x, y)| [x as f64, y as f64]), 0..40),
            prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| [x, y]), 0..60),
            prop::collection::vec((0..50i32).prop_map(|t| [t as f64, 3.0 * t as f64]), 0..30),
        ]
    }

    fn mode() -> impl Strategy<Value = FaultMode> {
        prop_oneof![Just(FaultMode::Random), (1e-12f64..0.5).prop_map(FaultMode::Noise)]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

        /// Many tiny, degenerate inputs under every kind of lie: no panic,
        /// no endless loop, always a valid diagram.
        #[test]
        fn any_small_input_under_any_fault(points in points(), mode in mode(), seed in any::<u64>()) {
            build_under(mode, seed, &points);
        }
    }
}

fn build_segments_under(mode: FaultMode, seed: u64, points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) {
    try_build_under(mode, seed, points, segments).unwrap_or_else(|e| panic!("{mode:?} seed {seed}: {e}"));
}

#[test]
fn segments_with_relative_noise() {
    for seed in 0..4 {
        let (pts, segs) = segment_grid(40, seed, 0.7);
        build_segments_under(FaultMode::Noise(1e-3), seed, &pts, &segs);
    }
}

#[test]
fn segments_with_random_arithmetic() {
    for seed in 0..4 {
        let (pts, segs) = segment_grid(40, seed, 0.7);
        build_segments_under(FaultMode::Random, seed, &pts, &segs);
    }
}

#[test]
fn ten_thousand_segments_with_relative_noise() {
    let (pts, segs) = segment_grid(120, 5, 0.7);
    assert!(segs.len() >= 10_000, "{} segments", segs.len());
    build_segments_under(FaultMode::Noise(1e-3), 5, &pts, &segs);
}

#[test]
fn ten_thousand_segments_with_random_arithmetic() {
    let (pts, segs) = segment_grid(120, 6, 0.7);
    assert!(segs.len() >= 10_000, "{} segments", segs.len());
    build_segments_under(FaultMode::Random, 6, &pts, &segs);
}

/// Shared endpoints everywhere: a long polyline, nested regular polygons, a
/// star with points among its spokes, the unit-segment lattice. Closed
/// chains wall off their inside, and lying numbers can misplace a site
/// against them; the construction then starts over with the stuck segment
/// first (`construct::restart::insert_all_from`), which these inputs need
/// for about one seed in three.
#[test]
fn shared_endpoints_with_lying_arithmetic() {
    for mode in [FaultMode::Noise(1e-3), FaultMode::Noise(1e-9), FaultMode::Random] {
        for seed in 0..8 {
            for (k, (pts, segs)) in shared_endpoint_inputs().iter().enumerate() {
                build_segments_under(mode, 8 * seed + k as u64, pts, segs);
            }
        }
    }
}

type PointsAndSegments = (&'static [[f64; 2]], Vec<[[f64; 2]; 2]>);

fn shared_endpoint_inputs() -> [PointsAndSegments; 4] {
    let mut nested = Vec::new();
    for (k, n) in [3usize, 4, 6, 7, 16, 64].into_iter().enumerate() {
        nested.extend(polygon(n, 1.0 + k as f64, 0.0, 0.0));
    }
    let star: Vec<[[f64; 2]; 2]> = (0..256)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 256.0;
            let r = 1.0 + (k % 3) as f64;
            [[0.0, 0.0], [r * t.cos(), r * t.sin()]]
        })
        .collect();
    [
        (&[], snake(40, 1)),
        (&[[0.1, 0.05], [3.5, 0.2]], nested),
        (&[[0.3, 0.2], [5.0, 5.0]], star),
        (&[], unit_segment_lattice(12)),
    ]
}

/// With too few restarts allowed, the closed chains that need them give up
/// with `ErrorKind::Internal`, naming the segment that found no path,
/// instead of handing out the invalid last attempt; the builder is
/// unchanged and builds a valid diagram once the numbers are sound again.
/// Every build either validates or gives up, and the full budget always
/// completes.
#[test]
fn exhausted_restarts_give_internal_not_an_invalid_diagram() {
    // Random lies need a restart on about one seed in 16 of these chains
    // (8 of 128 since the joint solvers of issue 27; 32 seeds found none)
    const SEEDS: u64 = 128;
    let (pts, segs) = closed_chains();
    let mut b = Builder::new();
    b.add_points(pts.iter().copied()).unwrap();
    b.add_segments(segs.iter().copied()).unwrap();
    for mode in [FaultMode::Random, FaultMode::Noise(1e-9)] {
        let mut gave_up = Vec::new();
        for budget in [0, 1, 2, 16] {
            let _budget = RestartBudget::set(budget);
            let mut count = 0;
            for seed in 0..SEEDS {
                let Err(e) = try_build_with(mode, seed, &b) else { continue };
                count += 1;
                let &[j] = e.indices() else { panic!("{mode:?} seed {seed}: {e} names no segment") };
                let [p, q] = segs[j];
                let expect = format!(
                    "construction could not complete: segment {j} ({}, {}) - ({}, {}) found no path",
                    p[0], p[1], q[0], q[1]
                );
                assert!(e.message().starts_with(&expect), "{e}\nexpected: {expect}");
                let restarts = if budget == 1 { "1 restart".to_string() } else { format!("{budget} restarts") };
                assert!(e.message().contains(&format!(" after {restarts}; ")), "{e}");
            }
            gave_up.push(count);
        }
        assert!(gave_up[0] > 0, "{mode:?}: no seed needed a restart, the test proves nothing");
        assert_eq!(gave_up[3], 0, "{mode:?}: the full budget gave up");
    }
    // The same builder, with sound numbers: a valid diagram.
    let _budget = RestartBudget::set(0);
    let d = b.build().unwrap();
    d.validate().unwrap();
    assert_eq!(d.stats().input_segments, segs.len());
}

/// Polygons with holes built with lying arithmetic: the domain and the
/// medial axis of the (valid) diagram are still consistent — every vertex,
/// edge and cell located, each medial-axis edge in one chain, consecutive
/// pieces meeting, the largest disk an inside vertex — and nothing panics.
#[test]
fn medial_axis_of_polygons_with_lying_arithmetic() {
    let mut built = 0;
    for (mode, seed) in [(FaultMode::Noise(1e-3), 1), (FaultMode::Random, 2), (FaultMode::Noise(1e-9), 3)] {
        let mut b = Builder::new();
        b.add_polygon(&[ring(40, 10.0, 0.0), ring(9, 3.0, 0.1)]).unwrap();
        let Ok(d) = try_build_with(mode, seed, &b) else { continue };
        built += 1;
        assert!(d.has_domain());
        for v in d.vertices() {
            assert!(d.vertex_location(v.id).is_some());
        }
        for e in d.edges() {
            assert!(d.edge_location(e.id).is_some());
        }
        let axis = d.medial_axis();
        let mut seen = std::collections::HashSet::new();
        for chain in &axis.chains {
            assert!(!chain.pieces.is_empty());
            for w in chain.pieces.windows(2) {
                assert_eq!(w[0].ends[1], w[1].ends[0], "{mode:?}: consecutive pieces meet");
            }
            for p in &chain.pieces {
                assert!(seen.insert(p.edge), "{mode:?}: an edge in two chains");
                let _ = d.sample_piece(p, 1e-3);
                let _ = d.piece_point_at(p, 0.5);
            }
        }
        if let Some((_, r)) = d.max_inscribed_circle() {
            assert!(r.is_finite() || mode == FaultMode::Random);
        }
        assert!(!axis.chains.is_empty(), "{mode:?}: no medial axis");
        // the filters leave a part of the same edges, each once, chained
        let all = segvoronoi::MedialAxisFilter::new().with_corner_angle(0.0).with_spur_pruning(10.0);
        let filtered = d.medial_axis_filtered(&all);
        assert!(!filtered.chains.is_empty(), "{mode:?}: the filters left nothing");
        let mut kept = std::collections::HashSet::new();
        for chain in &filtered.chains {
            for w in chain.pieces.windows(2) {
                assert_eq!(w[0].ends[1], w[1].ends[0], "{mode:?}: consecutive filtered pieces meet");
            }
            for p in &chain.pieces {
                assert!(seen.contains(&p.edge) && kept.insert(p.edge), "{mode:?}: a filtered edge not once in the axis");
            }
        }
        let circles = d.inscribed_circles();
        assert!(circles.windows(2).all(|w| w[0].1 >= w[1].1), "{mode:?}: disks largest first");
        assert_eq!(circles.first().copied(), d.max_inscribed_circle());
    }
    assert!(built > 0, "no build completed: the test proves nothing");
}

/// The two inputs of the offset tests under lying arithmetic: a polygon
/// with a hole and two points inside (a domain), and points with two
/// segments (no domain).
fn offset_inputs() -> [Builder; 2] {
    let mut b = Builder::new();
    b.add_polygon(&[ring(40, 10.0, 0.0), ring(9, 3.0, 0.1)]).unwrap();
    b.add_points([[6.0, 0.5], [-6.0, 0.2]]).unwrap();
    let mut plain = Builder::new();
    plain.add_points(lattice(6)).unwrap();
    plain.add_segments([[[0.25, 0.6], [3.6, 1.3]], [[1.2, 3.3], [4.3, 3.6]]]).unwrap();
    [b, plain]
}

/// The offsets of `d` at distances across the whole range (both sides of
/// a domain); `closed`: every loop closes and nests as a forest with holes
/// alternating. Every piece names a site and nothing panics either way.
fn check_offsets(d: &Diagram, mode: FaultMode, closed: bool) -> usize {
    let distances: Vec<f64> =
        [0.01, 0.3, 1.0, 2.5, 7.0, 40.0].into_iter().flat_map(|r| if d.has_domain() { vec![r, -r] } else { vec![r] }).collect();
    let mut open = 0;
    for o in d.offsets(&distances).unwrap() {
        for (k, l) in o.loops.iter().enumerate() {
            for (i, p) in l.pieces.iter().enumerate() {
                let joins = p.to() == l.pieces[(i + 1) % l.pieces.len()].from();
                assert!(joins || !closed, "{mode:?} {}: loop {k} open", o.distance);
                open += usize::from(!joins);
                assert!(d.site(p.site()).is_some());
            }
            if let (Some(p), true) = (l.parent, closed) {
                assert!(p < k && o.loops[p].hole != l.hole, "{mode:?} {}: nesting", o.distance);
            }
            let _ = l.polyline(1e-3);
        }
        let _ = o.area();
    }
    open
}

/// Offsets of diagrams built with lying arithmetic (vertex positions and
/// clearances then lie too), six seeds per mode: every loop still closes,
/// every piece names a site, the nesting is a forest with holes
/// alternating, and nothing panics, at distances across the whole range.
/// Not for a domain under random arithmetic, where loops open (see
/// `offsets_of_a_domain_with_random_arithmetic_close`): there only
/// nothing panicking is checked.
#[test]
fn offsets_with_lying_arithmetic() {
    let mut built = 0;
    for seed in 1..=6 {
        for mode in [FaultMode::Noise(1e-3), FaultMode::Random, FaultMode::Noise(1e-9)] {
            for builder in &offset_inputs() {
                let Ok(d) = try_build_with(mode, seed, builder) else { continue };
                built += 1;
                let known_open = matches!(mode, FaultMode::Random) && d.has_domain();
                check_offsets(&d, mode, !known_open);
            }
        }
    }
    assert!(built > 0, "no build completed: the test proves nothing");
}

/// KNOWN FAILURE, ignored (`cargo test --release --features
/// fault-injection --test fault_injection -- --ignored`): with random
/// arithmetic, the offsets of a domain (a ring with a hole) open: the
/// crossings around some cell do not alternate (`offset/trace.rs` skips
/// the pair), in 45 of 59 seeds. Without a domain, and with noise of
/// 1e-3 or 1e-9 with one, every loop closes (39 seeds each). Found when a
/// solver change moved the one seed this test used to run.
#[test]
#[ignore = "known failure: offsets of a domain under random arithmetic open"]
fn offsets_of_a_domain_with_random_arithmetic_close() {
    let [domain, _] = offset_inputs();
    let mut open = 0;
    for seed in 1..=20 {
        if let Ok(d) = try_build_with(FaultMode::Random, seed, &domain) {
            open += check_offsets(&d, FaultMode::Random, false);
        }
    }
    assert_eq!(open, 0, "open joins in the offsets of 20 seeds");
}

/// Splitting decides by exact signs only (fault injection never perturbs
/// them), so under lying arithmetic a crossing input still splits into the
/// same pieces, and the pieces' build keeps the contract.
#[test]
fn split_crossings_under_lying_arithmetic() {
    let mut rng = Rng(21);
    for (k, mode) in [FaultMode::Noise(1e-3), FaultMode::Random].into_iter().cycle().take(8).enumerate() {
        let segments: Vec<[[f64; 2]; 2]> =
            (0..30).map(|_| [[rng.unit() * 10.0, rng.unit() * 10.0], [rng.unit() * 10.0, rng.unit() * 10.0]]).collect();
        let mut b = Builder::new();
        b.add_segments(segments.iter().copied()).unwrap();
        b.split_crossings(true);
        let exact = b.build().unwrap();
        if let Ok(d) = try_build_with(mode, k as u64, &b) {
            assert_eq!(d.stats().pieces, exact.stats().pieces);
            assert_eq!(d.stats().crossings, exact.stats().crossings);
            for p in 0..d.piece_count() {
                assert_eq!(d.piece(p), exact.piece(p));
            }
        }
    }
}

/// Builds in halves on two threads (`diagnostics::set_halves_from`, from
/// 64 sites on), and on four (each half in halves in turn), under lying
/// arithmetic (on the calling thread: the fault mode is per thread, so
/// the right half or the right quarter and the glue lie, the others and
/// the check do not): a valid diagram or `Internal`, never an invalid one. Points, a
/// lattice and segments, each with noise and with random numbers.
#[test]
fn builds_in_halves_with_lying_arithmetic() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    set_halves_from(Some(64));
    let (mut tried, mut nested) = (0, 0);
    for (mode, seed) in [(FaultMode::Noise(1e-3), 11), (FaultMode::Random, 12), (FaultMode::Noise(1e-9), 13)] {
        let (pts, segs) = segment_grid(30, seed, 0.7);
        for (points, segments) in [(uniform(3000, seed), Vec::new()), (lattice(40), Vec::new()), (pts, segs)] {
            for threads in [2, 4] {
                let mut b = Builder::new();
                b.add_points(points.iter().copied()).unwrap();
                b.add_segments(segments.iter().copied()).unwrap();
                b.threads(threads);
                let _ = try_build_with(mode, seed, &b);
                let report = take_halves_report();
                tried += usize::from(report.is_some());
                nested += usize::from(report.is_some_and(|r| r.nested.contains(&true)));
            }
        }
    }
    set_halves_from(None);
    assert_eq!(tried, 18, "every build tried halves");
    assert!(nested >= 6, "only {nested} of 9 builds on four threads built a half in halves");
}
