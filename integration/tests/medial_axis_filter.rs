//! The medial axis filters (`Diagram::medial_axis_filtered`,
//! `MedialAxisFilter`): closed forms (a rectangle pruned to its middle line,
//! a stadium whose flattened ends lose their spurs, a regular polygon kept
//! whole), and on random polygons with holes what a filter may and may not
//! do: leave out only branches that meet its rule, never change the
//! number of components or of independent cycles.

mod common;

use common::star_ring;
use segvoronoi::{Builder, Chain, Diagram, EdgeEnd, EdgeId, MedialAxis, MedialAxisFilter, Point, Site, VertexId};
use std::collections::{HashMap, HashSet};

fn build(rings: &[Vec<[f64; 2]>]) -> Diagram {
    let mut b = Builder::new();
    b.add_polygon(rings).expect("a valid polygon");
    let d = b.build().expect("a diagram");
    d.validate().unwrap();
    d
}

fn edges_of(axis: &MedialAxis) -> HashSet<EdgeId> {
    axis.chains.iter().flat_map(|c| c.pieces.iter().map(|p| p.edge)).collect()
}

fn vertex_ends(axis: &MedialAxis) -> Vec<[VertexId; 2]> {
    let mut out = Vec::new();
    for p in axis.chains.iter().flat_map(|c| &c.pieces) {
        if let [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] = p.ends {
            out.push([a, b]);
        }
    }
    out
}

/// (components, independent cycles) of the axis as a graph.
fn components_and_cycles(axis: &MedialAxis) -> (usize, usize) {
    let (vertices, edges, components) = common::axis_graph(axis);
    (components, edges + components - vertices)
}

fn degree_in(axis: &MedialAxis) -> HashMap<VertexId, usize> {
    let mut degree = HashMap::new();
    for [a, b] in vertex_ends(axis) {
        *degree.entry(a).or_insert(0) += 1;
        *degree.entry(b).or_insert(0) += 1;
    }
    degree
}

fn chain_length(d: &Diagram, chain: &Chain) -> f64 {
    let points = d.sample_chain(chain, 1e-6).expect("finite");
    points.windows(2).map(|w| Point::new(w[0][0], w[0][1]).distance(Point::new(w[1][0], w[1][1]))).sum()
}

#[test]
fn a_rectangle_pruned_is_its_middle_line() {
    let d = build(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]]);
    // branches sqrt(2) long, the junctions' clearance 1
    let kept = d.medial_axis_filtered(&MedialAxisFilter::new().with_spur_pruning(1.4));
    assert_eq!(edges_of(&kept).len(), 5, "1.4 < sqrt(2): nothing pruned");
    let pruned = d.medial_axis_filtered(&MedialAxisFilter::new().with_spur_pruning(1.5));
    assert_eq!(pruned.chains.len(), 1);
    let piece = pruned.chains[0].pieces[0];
    assert_eq!(pruned.chains[0].pieces.len(), 1);
    assert_eq!(piece.clearance, [1.0, 1.0]);
    // a rectangle's corners are right angles: above 89 degrees every
    // branch goes, as the spur filter's; above 90 none
    assert_eq!(d.medial_axis_filtered(&MedialAxisFilter::new().with_corner_angle(90.0)), d.medial_axis());
    assert_eq!(d.medial_axis_filtered(&MedialAxisFilter::new().with_corner_angle(89.0)), pruned);
    // the defaults and NaN leave everything
    assert_eq!(d.medial_axis_filtered(&MedialAxisFilter::default()), d.medial_axis());
    let nan = MedialAxisFilter::new().with_corner_angle(f64::NAN).with_spur_pruning(f64::NAN);
    assert_eq!(d.medial_axis_filtered(&nan), d.medial_axis());
}

/// A stadium: two half circles of radius `r` (flattened into `n` chords
/// each) joined by straight sides of length `l`. Its exact medial axis is
/// the segment between the circles' centres, at clearance `r`.
fn stadium(n: usize, r: f64, l: f64) -> Vec<[f64; 2]> {
    let mut ring = Vec::new();
    for (cx, from) in [(l, -std::f64::consts::FRAC_PI_2), (0.0, std::f64::consts::FRAC_PI_2)] {
        for k in 0..=n {
            let t = from + std::f64::consts::PI * k as f64 / n as f64;
            ring.push([cx + r * t.cos(), r * t.sin()]);
        }
    }
    ring
}

#[test]
fn a_flattened_stadium_loses_its_spurs_to_the_corner_filter() {
    for n in [8, 16, 33] {
        let (r, l) = (2.0, 7.0);
        let d = build(&[stadium(n, r, l)]);
        let full = d.medial_axis();
        // every corner of the flattened ends has its spur
        let corners = degree_in(&full).into_iter().filter(|&(v, k)| k == 1 && d.vertex(v).unwrap().clearance == 0.0).count();
        assert_eq!(corners, 2 * (n + 1), "n = {n}");
        let corner_angle = 180.0 - 180.0 / n as f64; // between consecutive chords
        let filtered = d.medial_axis_filtered(&MedialAxisFilter::new().with_corner_angle(corner_angle - 1e-6));
        assert_eq!(components_and_cycles(&filtered), (1, 0));
        // what is left is the middle line, at clearance r between the
        // straight sides and down to the chords' distance from the centres
        let chords = r * (std::f64::consts::PI / (2 * n) as f64).cos();
        for chain in &filtered.chains {
            for [x, y, c] in d.sample_chain(chain, 1e-6).unwrap() {
                let ok = (chords - 1e-9..=r + 1e-9).contains(&c) && y.abs() < 1e-9 && (-1e-9..=l + 1e-9).contains(&x);
                assert!(ok, "n = {n}: ({x}, {y}) {c}");
            }
        }
        let length: f64 = filtered.chains.iter().map(|c| chain_length(&d, c)).sum();
        assert!((length - l).abs() < 1e-9, "n = {n}: {length}");
        // the corners where the sides meet the ends are flatter (the turn
        // is half a chord's): above the chords' angle only their four
        // branches go, above theirs none
        let few = d.medial_axis_filtered(&MedialAxisFilter::new().with_corner_angle(corner_angle + 1e-6));
        let gone = degree_in(&full).into_keys().filter(|v| !degree_in(&few).contains_key(v)).count();
        assert_eq!(gone, 4, "n = {n}");
        let side_corner = 180.0 - 90.0 / n as f64;
        let none = d.medial_axis_filtered(&MedialAxisFilter::new().with_corner_angle(side_corner + 1e-6));
        assert_eq!(edges_of(&none), edges_of(&full));
    }
}

/// Every spoke of a regular polygon is a branch into a corner. Where the
/// spokes meet at one vertex (a triangle) the component would vanish and
/// is kept whole; rounded coordinates of larger ones make their centre a
/// tiny tree of true edges between junctions, which stays.
#[test]
fn a_regular_polygon_whose_every_spoke_qualifies_keeps_its_centre() {
    for n in [3, 6, 40] {
        let ring: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64 + 0.2;
                [5.0 * t.cos(), 5.0 * t.sin()]
            })
            .collect();
        let d = build(&[ring]);
        let all = MedialAxisFilter::new().with_corner_angle(0.0).with_spur_pruning(1e9);
        let filtered = d.medial_axis_filtered(&all);
        assert_eq!(components_and_cycles(&filtered), (1, 0), "{n}-gon");
        if n == 3 {
            assert_eq!(filtered, d.medial_axis());
        }
        for chain in &filtered.chains {
            for [x, y, c] in d.sample_chain(chain, 1e-6).unwrap() {
                let apothem = 5.0 * (std::f64::consts::PI / n as f64).cos();
                assert!(n == 3 || (x.hypot(y) < 1e-9 && (c - apothem).abs() < 1e-9), "{n}-gon: ({x}, {y}) {c}");
            }
        }
    }
}

/// The rules, checked on random polygons with holes: every edge left out
/// is in a branch of the unfiltered axis that meets the filter's rule;
/// every such branch is left out unless its component would vanish; the
/// components and independent cycles stay.
#[test]
fn filters_leave_out_only_branches_that_meet_their_rule() {
    let mut rng = common::Rng(29);
    for case in 0..25 {
        let rings = vec![
            star_ring(20 + (rng.next_u64() % 120) as usize, 0.0, 0.0, 7.0, 10.0, &mut rng),
            star_ring(8, 0.5, 0.0, 1.0, 2.5, &mut rng),
        ];
        let d = build(&rings);
        let full = d.medial_axis();
        let degree = degree_in(&full);
        let filters = [
            MedialAxisFilter::new().with_corner_angle(100.0 + (case % 7) as f64 * 10.0),
            MedialAxisFilter::new().with_spur_pruning(0.5 + (case % 5) as f64 * 0.5),
            MedialAxisFilter::new().with_corner_angle(150.0).with_spur_pruning(1.0),
        ];
        for filter in filters {
            let filtered = d.medial_axis_filtered(&filter);
            assert_eq!(components_and_cycles(&filtered), components_and_cycles(&full), "case {case}, {filter:?}");
            let kept = edges_of(&filtered);
            assert!(kept.is_subset(&edges_of(&full)));
            for chain in &full.chains {
                let ends = [chain.pieces[0].ends[0], chain.pieces.last().unwrap().ends[1]];
                let [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] = ends else { continue };
                let (da, db) = (degree[&a], degree[&b]);
                let branch = match (da, db) {
                    (1, k) if k >= 3 => Some((a, chain.pieces[0], b)),
                    (k, 1) if k >= 3 => Some((b, *chain.pieces.last().unwrap(), a)),
                    _ => None,
                };
                let removed = chain.pieces.iter().all(|p| !kept.contains(&p.edge));
                let partly = chain.pieces.iter().any(|p| !kept.contains(&p.edge)) && !removed;
                assert!(!partly, "case {case}: a chain cut in the middle");
                // within a hair either side of the thresholds (the
                // library measures parabolas on a polyline of its own)
                let qualifies = |slack: f64| {
                    branch.is_some_and(|(leaf, piece, junction)| {
                        let r = d.vertex(junction).unwrap().clearance;
                        let short = filter.spur_factor > 0.0 && chain_length(&d, chain) < filter.spur_factor * r * (1.0 + slack);
                        let flat = d.vertex(leaf).unwrap().clearance == 0.0
                            && corner_angle(&d, piece.edge) > filter.corner_angle - slack;
                        short || flat
                    })
                };
                if removed {
                    assert!(qualifies(1e-6), "case {case}: a chain left out that is not a branch meeting the rule");
                } else {
                    assert!(!qualifies(-1e-6), "case {case}: a qualifying branch kept ({filter:?})");
                }
            }
        }
    }
}

/// The angle, in degrees, between the two segments of a corner's branch
/// (the edge between them), at their shared endpoint.
fn corner_angle(d: &Diagram, edge: EdgeId) -> f64 {
    let [s, t] = d.edge(edge).unwrap().sites.map(|s| d.site(s).unwrap());
    let (Site::Segment { a, b }, Site::Segment { a: c, b: e }) = (s, t) else {
        unreachable!("a corner's branch is between its two segments")
    };
    let p = if a == c || a == e { a } else { b };
    let u = if a == p { b } else { a };
    let w = if c == p { e } else { c };
    let (ux, uy, wx, wy) = (u.x - p.x, u.y - p.y, w.x - p.x, w.y - p.y);
    (ux * wy - uy * wx).abs().atan2(ux * wx + uy * wy).to_degrees()
}
