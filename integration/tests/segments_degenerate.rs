//! Degenerate segment inputs (seed 000 figure 8 and the usual troublemakers
//! of other Voronoi libraries), each at its own scale and scaled to extents
//! of about 1e-9 and 1e9: every diagram validates (separators included) and
//! passes the brute-force empty-circle check at 1e-9 of its extent.

mod common;

use common::{build_sites, check_empty_circles, polygon, unit_segment_lattice};
use std::f64::consts::{PI, TAU};

type Segment = [[f64; 2]; 2];

/// Builds `points` and `segments` scaled by 1, 1e-9 and 1e9 and checks each.
fn check_at_all_scales(name: &str, points: &[[f64; 2]], segments: &[Segment]) {
    for f in [1.0, 1e-9, 1e9] {
        let pts: Vec<[f64; 2]> = points.iter().map(|p| [p[0] * f, p[1] * f]).collect();
        let segs: Vec<Segment> = segments.iter().map(|s| s.map(|p| [p[0] * f, p[1] * f])).collect();
        let d = build_sites(&pts, &segs);
        assert_eq!(d.site_count() - d.point_site_count(), segs.len(), "{name} at scale {f}: every segment is a site");
        check_empty_circles(&d, 1e-9);
    }
}

/// `n` segments tangent to the unit circle at evenly spaced points, short
/// enough not to meet: the centre is equidistant from all of them (seed 000
/// figure 8 (3)).
fn tangent_segments(n: usize) -> Vec<Segment> {
    let half = 0.8 * (PI / n as f64).tan();
    (0..n)
        .map(|k| {
            let t = TAU * k as f64 / n as f64;
            let (c, s) = (t.cos(), t.sin());
            [[c + half * s, s - half * c], [c - half * s, s + half * c]]
        })
        .collect()
}

/// `n` equal parallel segments, evenly spaced (seed 000 figure 8 (4)).
fn parallel_segments(n: usize) -> Vec<Segment> {
    (0..n).map(|k| [[0.0, k as f64], [10.0, k as f64]]).collect()
}

/// The outline of a capital B from straight pieces, with its two counters
/// (holes), as closed polygons; `gap` pulls each piece's ends that far
/// towards its middle (seed 000 figure 8 (5): endpoints slightly apart).
fn letter_b(gap: f64) -> Vec<Segment> {
    let outer: [[f64; 2]; 11] = [
        [0.0, 0.0],
        [6.0, 0.0],
        [7.5, 0.6],
        [8.0, 2.0],
        [7.6, 3.6],
        [6.6, 4.2],
        [7.4, 4.9],
        [7.8, 6.3],
        [7.3, 7.6],
        [6.0, 8.0],
        [0.0, 8.0],
    ];
    let upper: [[f64; 2]; 6] = [[1.8, 4.8], [5.4, 4.8], [5.9, 5.5], [5.9, 6.5], [5.4, 7.0], [1.8, 7.0]];
    let lower: [[f64; 2]; 6] = [[1.8, 1.0], [5.6, 1.0], [6.2, 1.7], [6.2, 2.9], [5.6, 3.6], [1.8, 3.6]];
    let mut out = Vec::new();
    for ring in [&outer[..], &upper[..], &lower[..]] {
        for k in 0..ring.len() {
            let (p, q) = (ring[k], ring[(k + 1) % ring.len()]);
            let len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
            let t = gap / len;
            out.push([
                [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])],
                [q[0] - t * (q[0] - p[0]), q[1] - t * (q[1] - p[1])],
            ]);
        }
    }
    out
}

#[test]
fn segments_tangent_to_one_circle() {
    for n in [3, 4, 5, 8, 12, 39, 64] {
        check_at_all_scales(&format!("tangent {n}"), &[], &tangent_segments(n));
    }
    // with the centre as a point site, equidistant from all of them
    check_at_all_scales("tangent 16 with centre", &[[0.0, 0.0]], &tangent_segments(16));
}

#[test]
fn thirty_nine_parallel_segments() {
    check_at_all_scales("parallel 39", &[], &parallel_segments(39));
    check_at_all_scales("parallel 39 with points", &[[5.0, 0.5], [-1.0, 3.0], [11.0, 38.5]], &parallel_segments(39));
}

#[test]
fn letter_outline_shared_and_apart() {
    check_at_all_scales("letter B", &[], &letter_b(0.0));
    check_at_all_scales("letter B, ends apart", &[], &letter_b(1e-3));
    check_at_all_scales("letter B, ends barely apart", &[], &letter_b(1e-7));
}

#[test]
fn lattice_of_horizontal_and_vertical_segments() {
    check_at_all_scales("unit lattice 5", &[], &unit_segment_lattice(5));
    // long lines instead of unit pieces: crossing is refused, so offset
    // horizontal and vertical bars that stop short of each other
    let mut bars = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            let (x, y) = (2.0 * i as f64, 2.0 * j as f64);
            bars.push([[x + 0.5, y], [x + 1.5, y]]);
            bars.push([[x, y + 0.5], [x, y + 1.5]]);
        }
    }
    check_at_all_scales("bars", &[], &bars);
}

#[test]
fn regular_polygons_nested_and_with_centre() {
    for n in [3, 4, 6, 8, 16, 33, 64] {
        let mut segs = polygon(n, 2.0, 0.0, 0.0);
        segs.extend(polygon(n, 1.0, 0.0, 0.0));
        check_at_all_scales(&format!("{n}-gons nested"), &[[0.0, 0.0]], &segs);
    }
}

#[test]
fn stars() {
    for n in [3, 4, 7, 64] {
        let star: Vec<Segment> = (0..n)
            .map(|k| {
                let t = TAU * k as f64 / n as f64;
                [[0.0, 0.0], [t.cos(), t.sin()]]
            })
            .collect();
        check_at_all_scales(&format!("star {n}"), &[[2.0, 0.0]], &star);
    }
}

#[test]
fn collinear_chains() {
    // one straight line cut into pieces, with points on both sides and on
    // the line beyond its ends
    let chain: Vec<Segment> = (0..10).map(|k| [[k as f64, 0.0], [k as f64 + 1.0, 0.0]]).collect();
    check_at_all_scales("chain", &[[-1.0, 0.0], [11.5, 0.0], [3.3, 1.0], [6.1, -2.0]], &chain);
    // a diagonal chain, pieces of unequal length, with a parallel neighbour
    let mut diag: Vec<Segment> = [0.0, 0.5, 1.7, 2.0, 3.9].windows(2).map(|w| [[w[0], w[0]], [w[1], w[1]]]).collect();
    diag.push([[1.0, 0.0], [3.0, 2.0]]);
    check_at_all_scales("diagonal chain", &[], &diag);
}

#[test]
fn near_vertical_segments() {
    let mut segs = Vec::new();
    for k in 0..20 {
        let x = k as f64;
        let lean = 1e-9 * (k as f64 - 10.0);
        segs.push([[x, 0.0], [x + lean, 5.0]]);
        segs.push([[x + 0.5, 6.0], [x + 0.5 - lean, 9.0 + 1e-12 * k as f64]]);
    }
    check_at_all_scales("near vertical", &[[0.25, 5.5], [7.0, 10.0]], &segs);
}

/// A chain going on straight through a joint next to a sharp turn (the
/// fixture `straight_joint_zero_length_4seg`, from testgen's
/// `polyline+straight`): the joint's cell has no width, so its edges other
/// than the separators have length zero whatever the insertion order; the
/// topology text (VPAIRS, VVERTICES) was one pair longer in 2 of the 24
/// orders.
#[test]
fn a_straight_joint_has_the_same_topology_text_in_every_order() {
    use segvoronoi::{Builder, TopologyOptions};
    let text = include_str!("../../c_tests/fixtures/straight_joint_zero_length_4seg.txt");
    let input = segvoronoi::boost_text::parse(text).unwrap();
    let segments: Vec<Segment> = input.segments.iter().map(|&[x0, y0, x1, y1]| [[x0, y0], [x1, y1]]).collect();
    let shape = |order: &[usize]| {
        let mut b = Builder::new();
        b.add_segments(order.iter().map(|&k| segments[k])).unwrap();
        let text = b.build().unwrap().topology(TopologyOptions::default().with_voronoi_pairs(true));
        // counts per section, which do not depend on the names
        let header = |l: &&str| l.split(' ').next().is_some_and(|w| w.len() > 2 && w.chars().all(|c| c.is_ascii_uppercase()));
        text.lines().filter(header).map(str::to_string).collect::<Vec<_>>()
    };
    let first = shape(&[0, 1, 2, 3]);
    let mut orders = Vec::new();
    for a in 0..4 {
        for b in (0..4).filter(|&b| b != a) {
            for c in (0..4).filter(|&c| c != a && c != b) {
                let d = 6 - a - b - c;
                orders.push(vec![a, b, c, d]);
            }
        }
    }
    assert_eq!(orders.len(), 24);
    for order in orders {
        assert_eq!(shape(&order), first, "order {order:?}");
    }
}

/// The topology text names sites by input position; this writes each name
/// as its site's coordinates instead, so that texts of one input given in
/// two orders can be compared line by line.
fn text_by_coordinates(d: &segvoronoi::Diagram, segments: &[Segment], text: &str) -> Vec<String> {
    let site = |word: &str| -> String {
        if let Some(k) = word.strip_prefix('P') {
            let p = d.site(segvoronoi::SiteId::from_index(k.parse().unwrap())).unwrap();
            format!("{p:?}")
        } else if let Some(j) = word.strip_prefix('S') {
            let mut ends = segments[j.parse::<usize>().unwrap()];
            ends.sort_by(|a, b| a.partial_cmp(b).unwrap());
            format!("{ends:?}")
        } else {
            word.to_string()
        }
    };
    let mut lines: Vec<String> = Vec::new();
    let mut section: Vec<String> = Vec::new();
    for line in text.lines() {
        if line.split(' ').nth(1).is_some_and(|w| w.parse::<usize>().is_ok()) && !line.starts_with(['P', 'S', 'A']) {
            section.sort();
            lines.append(&mut section);
            lines.push(line.to_string());
            continue;
        }
        let mut words: Vec<String> = line.split(' ').map(site).collect();
        words.sort();
        section.push(words.join(" "));
    }
    section.sort();
    lines.append(&mut section);
    lines
}

/// Degenerate vertices (cocircular points, segments along the grid lines
/// through them, tangent segments round one circle) are cut into degree-3
/// ones the same way whatever the order of the input, and so whatever the
/// insertion order: the whole text with `canonical_cuts`, `EDGES` and
/// `FACES` included, names read as coordinates, is the same for the input
/// reversed and shuffled (`topology::canonical_cut`; without it, `EDGES`
/// and `FACES` of the grid differ, only `VPAIRS` and `VVERTICES` agree).
#[test]
fn degenerate_vertices_are_cut_the_same_way_for_the_input_in_any_order() {
    use segvoronoi::{Builder, TopologyOptions};
    let grid: Vec<[f64; 2]> = (0..10).flat_map(|i| (0..10).map(move |j| [i as f64, j as f64])).collect();
    let columns: Vec<Segment> =
        (0..9).flat_map(|i| (0..10).step_by(3).map(move |j| [[i as f64, j as f64], [i as f64 + 1.0, j as f64]])).collect();
    let octagons: Vec<[f64; 2]> = (1..4)
        .flat_map(|r| (0..8).map(move |k| [r as f64 * (k as f64 * TAU / 8.0).cos(), r as f64 * (k as f64 * TAU / 8.0).sin()]))
        .chain(std::iter::once([0.0, 0.0]))
        .collect();
    let families: Vec<(&str, Vec<[f64; 2]>, Vec<Segment>)> = vec![
        ("grid", grid.clone(), vec![]),
        ("grid with segments along its lines", grid, columns),
        ("concentric octagons", octagons, vec![]),
        ("tangent segments", vec![[0.0, 0.0]], tangent_segments(12)),
    ];
    for (name, points, segments) in families {
        let text = |points: &[[f64; 2]], segments: &[Segment]| {
            let mut b = Builder::new();
            b.add_points(points.iter().copied()).unwrap();
            b.add_segments(segments.iter().copied()).unwrap();
            let d = b.build().unwrap();
            let text = d.topology(TopologyOptions::default().with_voronoi_pairs(true).with_canonical_cuts(true));
            text_by_coordinates(&d, segments, &text)
        };
        let first = text(&points, &segments);
        let mut seed = 7u64;
        for way in ["reversed", "shuffled 1", "shuffled 2", "shuffled 3"] {
            let (mut p, mut s) = (points.clone(), segments.clone());
            if way == "reversed" {
                p.reverse();
                s.reverse();
            } else {
                for k in (1..p.len()).rev() {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    p.swap(k, (seed >> 33) as usize % (k + 1));
                }
                for k in (1..s.len()).rev() {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    s.swap(k, (seed >> 33) as usize % (k + 1));
                }
            }
            let other = text(&p, &s);
            assert_eq!(other.len(), first.len(), "{name} {way}");
            for (a, b) in first.iter().zip(&other) {
                assert_eq!(a, b, "{name} {way}: the texts differ");
            }
        }
    }
}
