//! Letters with holes from a real font (issue 9): the outlines of B, 8 and
//! g of DejaVu Sans flattened into rings (`tests/data/glyph_*.rings`, made
//! by `scripts/glyph_rings.py`), built with `Builder::add_polygon`, and
//! their medial axis checked against the topology of the domain and the
//! geometry of the rings:
//! - the medial axis graph has one connected component per component of
//!   the domain, and as many independent cycles (edges − vertices +
//!   components) as the domain has holes: the medial axis is a deformation
//!   retract of the domain. Components and holes come from the rings'
//!   nesting (an exact even-odd test), not from the letters' names;
//! - every sampled point is inside the domain by the exact even-odd test
//!   (or is a corner of a ring, where the axis ends), and its clearance is
//!   its distance to the nearest ring segment within 1e-9 of the bounding
//!   box.
//!
//! The same glyphs scaled by powers of two (testgen's `glyphs` family,
//! seeds 4..15) must give the same answers; the CGAL cross-check compares
//! the axis itself (`ctest -L medial_axis`).

mod common;

use segvoronoi::{Builder, Diagram, EdgeEnd, Point, Site};
use segvoronoi_testgen::rings::{even_odd, generate_rings, read_rings, ring_segments, GLYPHS};

type Rings = Vec<Vec<[f64; 2]>>;

/// Components of the domain and holes, from the nesting of the rings: a
/// ring inside an even number of others bounds a component from outside,
/// one inside an odd number is a hole of a component.
fn components_and_holes(rings: &Rings) -> (usize, usize) {
    let (mut outer, mut holes) = (0, 0);
    for (k, ring) in rings.iter().enumerate() {
        let depth =
            rings.iter().enumerate().filter(|&(j, other)| j != k && even_odd(std::slice::from_ref(other), ring[0])).count();
        if depth % 2 == 0 {
            outer += 1;
        } else {
            holes += 1;
        }
    }
    (outer, holes)
}

fn build(rings: &Rings) -> Diagram {
    let mut b = Builder::new();
    b.add_polygon(rings).expect("a valid polygon");
    let d = b.build().expect("a diagram");
    d.validate().unwrap_or_else(|e| panic!("{e}"));
    d
}

/// Vertices, edges and connected components of the medial axis as a graph
/// (every piece an edge, its two vertices; a piece reaching infinity fails).
fn axis_graph(d: &Diagram) -> (usize, usize, usize) {
    let axis = d.medial_axis();
    for piece in axis.chains.iter().flat_map(|c| &c.pieces) {
        assert!(piece.ends.iter().all(|e| matches!(e, EdgeEnd::Vertex(_))), "a medial-axis piece {piece:?} reaches infinity");
    }
    common::axis_graph(&axis)
}

fn bounding_box_diagonal(rings: &Rings) -> f64 {
    let points = || rings.iter().flatten();
    let lo = points().fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
    let hi = points().fold([f64::NEG_INFINITY; 2], |m, p| [m[0].max(p[0]), m[1].max(p[1])]);
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// Samples every chain and checks each point; returns how many there were,
/// and how many of them are ring corners.
fn check_samples(rings: &Rings, d: &Diagram, name: &str) -> (usize, usize) {
    let diagonal = bounding_box_diagonal(rings);
    let segments: Vec<Site> = ring_segments(rings)
        .into_iter()
        .map(|[a, b]| Site::Segment { a: Point::new(a[0], a[1]), b: Point::new(b[0], b[1]) })
        .collect();
    let is_corner = |p: [f64; 2]| rings.iter().flatten().any(|&c| c == p);
    let (mut count, mut corners) = (0, 0);
    for (k, chain) in d.medial_axis().chains.iter().enumerate() {
        let samples = d.sample_chain(chain, 1e-4 * diagonal).unwrap_or_else(|| panic!("{name}: chain {k} not sampled"));
        assert!(samples.len() >= 2, "{name}: chain {k} has {} samples", samples.len());
        for [x, y, r] in samples {
            let p = Point::new(x, y);
            corners += usize::from(is_corner([x, y]));
            assert!(is_corner([x, y]) || even_odd(rings, [x, y]), "{name}: chain {k}: ({x:e}, {y:e}) is outside the domain");
            let nearest = segments.iter().map(|s| s.distance(p)).fold(f64::INFINITY, f64::min);
            assert!(
                (r - nearest).abs() <= 1e-9 * diagonal,
                "{name}: chain {k}: ({x:e}, {y:e}) has clearance {r:e}, nearest segment at {nearest:e}"
            );
            count += 1;
        }
    }
    (count, corners)
}

/// One glyph: the topology and the samples of its medial axis.
fn check_glyph(name: &str, rings: &Rings) {
    let (components, holes) = components_and_holes(rings);
    let d = build(rings);
    let (vertices, edges, axis_components) = axis_graph(&d);
    assert_eq!(axis_components, components, "{name}: medial-axis components");
    assert_eq!(edges + axis_components, vertices + holes, "{name}: independent cycles of the medial axis vs holes");
    let (samples, corners) = check_samples(rings, &d, name);
    assert!(samples > edges, "{name}: {samples} samples for {edges} pieces");
    // the figures, for `--nocapture`
    eprintln!(
        "{name}: {} rings, {components} component(s), {holes} hole(s); medial axis {vertices} vertices, {edges} pieces, \
         {} cycles; {samples} samples ({corners} at ring corners)",
        rings.len(),
        edges + axis_components - vertices
    );
}

fn fixture(name: &str) -> Rings {
    let (_, text) = GLYPHS.iter().find(|(n, _)| *n == name).expect("a glyph fixture");
    read_rings(text).expect("a well-formed fixture")
}

/// B and 8 are letters with two holes, whatever the font; this checks that
/// the fixtures (and the nesting test) see them so.
#[test]
fn b_and_8_have_two_holes() {
    for name in ["B", "8"] {
        assert_eq!(components_and_holes(&fixture(name)), (1, 2), "{name}");
    }
    let g = fixture("g");
    assert_eq!(components_and_holes(&g), (1, g.len() - 1), "g: one outline, the rest holes");
}

#[test]
fn glyph_b() {
    check_glyph("B", &fixture("B"));
}

#[test]
fn glyph_8() {
    check_glyph("8", &fixture("8"));
}

#[test]
fn glyph_g() {
    check_glyph("g", &fixture("g"));
}

/// The glyphs scaled by 2^-20 .. 2^20 (exact), as the cross-check gets
/// them: the same topology, the same samples' properties.
#[test]
fn glyphs_scaled_by_powers_of_two() {
    for seed in 4..=15 {
        let rings = generate_rings("glyphs", 0, seed).expect("the glyphs family");
        check_glyph(&format!("glyphs seed {seed}"), &rings);
    }
}

/// The glyph with its rings reversed and in another order: the domain is
/// even-odd, orientation-free, so nothing changes.
#[test]
fn glyph_orientation_and_order_do_not_matter() {
    for (name, _) in GLYPHS {
        let mut rings = fixture(name);
        let counts = axis_graph(&build(&rings));
        rings.reverse();
        for ring in &mut rings {
            ring.reverse();
        }
        assert_eq!(axis_graph(&build(&rings)), counts, "{name}");
        check_glyph(&format!("{name} reversed"), &rings);
    }
}
