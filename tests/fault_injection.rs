//! The topology survives lying arithmetic: with every decided quantity
//! perturbed by up to 1e-3 relative, or replaced by random numbers, builds
//! terminate and pass every topological invariant. Run with
//! `cargo test --features fault-injection --test fault_injection`.
#![cfg(feature = "fault-injection")]

mod common;

use common::*;
use segvoronoi::fault_injection::{set_fault_mode, FaultMode};
use segvoronoi::Builder;

fn build_under(mode: FaultMode, seed: u64, points: &[[f64; 2]]) -> segvoronoi::Diagram {
    set_fault_mode(mode, seed);
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    let d = b.build().unwrap();
    set_fault_mode(FaultMode::Off, 0);
    d.validate().unwrap_or_else(|e| panic!("{mode:?}: {e}"));
    d
}

fn lattice(side: usize) -> Vec<[f64; 2]> {
    (0..side * side).map(|i| [(i % side) as f64, (i / side) as f64]).collect()
}

fn circle(n: usize) -> Vec<[f64; 2]> {
    (0..n).map(|i| {
        let a = i as f64 * std::f64::consts::TAU / n as f64;
        [a.cos(), a.sin()]
    }).collect()
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
    set_fault_mode(mode, seed);
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    let d = b.build();
    set_fault_mode(FaultMode::Off, 0);
    let d = d.unwrap();
    d.validate().unwrap_or_else(|e| panic!("{mode:?} seed {seed}: {e}"));
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
/// first (`build::construct`), which these inputs need for about one seed
/// in three.
#[test]
fn shared_endpoints_with_lying_arithmetic() {
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
    type PointsAndSegments = (&'static [[f64; 2]], Vec<[[f64; 2]; 2]>);
    let inputs: [PointsAndSegments; 4] = [
        (&[], snake(40, 1)),
        (&[[0.1, 0.05], [3.5, 0.2]], nested),
        (&[[0.3, 0.2], [5.0, 5.0]], star),
        (&[], unit_segment_lattice(12)),
    ];
    for mode in [FaultMode::Noise(1e-3), FaultMode::Noise(1e-9), FaultMode::Random] {
        for seed in 0..8 {
            for (k, (pts, segs)) in inputs.iter().enumerate() {
                build_segments_under(mode, 8 * seed + k as u64, pts, segs);
            }
        }
    }
}
