//! `Builder::threads`: the same diagram for every thread count, on inputs
//! large enough that a build runs work on a second thread (the input
//! check beside the point insertions from 20k segments, the sort of the
//! insertion order from 100k points, the check of the arcs' vertices from
//! 50k vertices), and the same error for an input that is refused.

use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, Diagram, TopologyOptions};
use segvoronoi_testgen::arcs::random_arc;
use segvoronoi_testgen::bench::{float_points, generate, Method};

/// The canonical topology and every vertex's position and clearance, bit
/// for bit.
fn fingerprint(d: &Diagram) -> (String, Vec<[u64; 3]>) {
    let vertices = d.vertices().map(|v| [v.position.x.to_bits(), v.position.y.to_bits(), v.clearance.to_bits()]).collect();
    (d.topology(TopologyOptions::default()), vertices)
}

fn same_for_every_thread_count(what: &str, b: &mut Builder) {
    let one = fingerprint(&b.threads(1).build().unwrap_or_else(|e| panic!("{what}: {e}")));
    for n in [2, 3, 0] {
        let other = fingerprint(&b.threads(n).build().unwrap_or_else(|e| panic!("{what} at {n} threads: {e}")));
        assert!(one == other, "{what}: another diagram at {n} threads than at one");
    }
}

#[test]
fn segments_and_points_the_same_at_every_thread_count() {
    let mut b = Builder::new();
    let segments = generate(Method::Short, 25_000, 7).segments;
    b.add_segments(segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]])).unwrap();
    same_for_every_thread_count("25k short segments", &mut b);
    let mut b = Builder::new();
    b.add_points(float_points(120_000, 11)).unwrap();
    same_for_every_thread_count("120k points", &mut b);
}

#[test]
fn arcs_the_same_at_every_thread_count() {
    let mut rng = SplitMix64(31);
    let mut b = Builder::new();
    for k in 0..12_000 {
        b.add_arc(random_arc(&mut rng, (k % 120) as f64, (k / 120) as f64)).unwrap();
    }
    same_for_every_thread_count("12k random arcs", &mut b);
}

#[test]
fn the_same_error_at_every_thread_count() {
    // 25k short segments and one more crossing the first
    let segments = generate(Method::Short, 25_000, 7).segments;
    let mut b = Builder::new();
    b.add_segments(segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]])).unwrap();
    let s = segments[0];
    let (mx, my) = (0.5 * f64::from(s[0] + s[2]), 0.5 * f64::from(s[1] + s[3]));
    let (dx, dy) = (f64::from(s[2] - s[0]), f64::from(s[3] - s[1]));
    b.add_segment([[mx - 0.1 * dy, my + 0.1 * dx], [mx + 0.1 * dy, my - 0.1 * dx]]).unwrap();
    let errors: Vec<String> = [1, 2, 0].into_iter().map(|n| b.threads(n).build().unwrap_err().to_string()).collect();
    assert!(errors.iter().all(|e| *e == errors[0]), "{errors:?}");
    assert!(errors[0].contains("25000"), "{}", errors[0]);
}
