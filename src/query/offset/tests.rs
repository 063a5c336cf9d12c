//! Offsets on hand-sized inputs with closed forms; the randomised brute
//! force and the comparison with GEOS live in `tests/offsets.rs` and
//! `c_tests/`.

use std::f64::consts::PI;

use crate::{Builder, Diagram, ErrorKind, OffsetPiece};

fn polygon(rings: &[Vec<[f64; 2]>]) -> Diagram {
    let mut b = Builder::new();
    b.add_polygon(rings).unwrap();
    b.build().unwrap()
}

fn regular(n: usize, r: f64, cx: f64, cy: f64) -> Vec<[f64; 2]> {
    (0..n).map(|k| 2.0 * PI * k as f64 / n as f64).map(|a| [cx + r * a.cos(), cy + r * a.sin()]).collect()
}

/// Every loop closes exactly, and a parent comes before its child.
fn check_closed(o: &crate::Offset) {
    for (k, l) in o.loops.iter().enumerate() {
        assert!(!l.pieces.is_empty());
        for (i, p) in l.pieces.iter().enumerate() {
            let next = &l.pieces[(i + 1) % l.pieces.len()];
            assert_eq!(p.to(), next.from(), "loop {k} piece {i}");
        }
        if let Some(p) = l.parent {
            assert!(p < k);
            assert_eq!(l.hole, !o.loops[p].hole);
        } else {
            assert!(!l.hole);
        }
        let area = l.signed_area();
        assert!(if l.hole { area < 0.0 } else { area > 0.0 }, "loop {k}: area {area}, hole {}", l.hole);
    }
}

#[test]
fn one_point_is_a_circle() {
    let mut b = Builder::new();
    b.add_point([1.0, 2.0]).unwrap();
    let d = b.build().unwrap();
    let o = d.offset(0.5).unwrap();
    check_closed(&o);
    assert_eq!(o.loops.len(), 1);
    assert!((o.area() - PI * 0.25).abs() < 1e-12);
}

#[test]
fn two_points_are_two_circles_or_one_lens_union() {
    let mut b = Builder::new();
    b.add_points([[0.0, 0.0], [2.0, 0.0]]).unwrap();
    let d = b.build().unwrap();
    let apart = d.offset(0.9).unwrap();
    check_closed(&apart);
    assert_eq!(apart.loops.len(), 2);
    assert!((apart.area() - 2.0 * PI * 0.81).abs() < 1e-9);
    // touching exactly: still two circles, split at the touching point
    let touching = d.offset(1.0).unwrap();
    check_closed(&touching);
    assert_eq!(touching.loops.len(), 2);
    assert!((touching.area() - 2.0 * PI).abs() < 1e-9);
    let joined = d.offset(2.0).unwrap();
    check_closed(&joined);
    assert_eq!(joined.loops.len(), 1);
    // two disks of radius 2 at distance 2: 2 (4π) minus the lens
    let lens = 2.0 * 4.0 * (0.5f64).acos() - 0.5 * 2.0 * (16.0f64 - 4.0).sqrt();
    assert!((joined.area() - (8.0 * PI - lens)).abs() < 1e-9, "{}", joined.area());
}

#[test]
fn a_segment_is_a_stadium() {
    let mut b = Builder::new();
    b.add_segment([[0.0, 0.0], [3.0, 1.0]]).unwrap();
    let d = b.build().unwrap();
    let o = d.offset(0.5).unwrap();
    check_closed(&o);
    assert_eq!(o.loops.len(), 1);
    let lines = o.loops[0].pieces.iter().filter(|p| matches!(p, OffsetPiece::Line { .. })).count();
    assert_eq!(lines, 2);
    let length = 10.0f64.sqrt();
    assert!((o.area() - (PI * 0.25 + length)).abs() < 1e-9, "{}", o.area());
}

#[test]
fn convex_polygon_grows_by_steiner() {
    let hexagon = regular(6, 2.0, 0.3, -0.1);
    let d = polygon(std::slice::from_ref(&hexagon));
    let area = 6.0 * 0.5 * 4.0 * (PI / 3.0).sin();
    let perimeter = 6.0 * 2.0;
    for r in [0.1, 1.0, 7.5] {
        let o = d.offset(r).unwrap();
        check_closed(&o);
        assert_eq!(o.loops.len(), 1);
        let want = area + perimeter * r + PI * r * r;
        assert!((o.area() - want).abs() < 1e-9 * want, "r {r}: {} vs {want}", o.area());
    }
}

#[test]
fn regular_polygon_shrinks_to_a_smaller_one() {
    let n = 7;
    let d = polygon(&[regular(n, 3.0, 0.0, 0.0)]);
    let apothem = 3.0 * (PI / n as f64).cos();
    for r in [0.2, 1.0, 2.5] {
        let o = d.offset(-r).unwrap();
        check_closed(&o);
        assert_eq!(o.loops.len(), 1);
        let a = apothem - r;
        let want = n as f64 * a * a * (PI / n as f64).tan();
        assert!((o.area() - want).abs() < 1e-9, "r {r}: {} vs {want}", o.area());
        assert!(o.loops[0].pieces.iter().all(|p| matches!(p, OffsetPiece::Line { .. })));
    }
    // beyond the inscribed circle: nothing; at it exactly (the clearance of
    // the centre vertex, as stored): nothing either, the region is a point
    assert!(d.offset(-apothem - 0.1).unwrap().loops.is_empty());
    let centre = d.vertices().max_by(|a, b| a.clearance.total_cmp(&b.clearance)).unwrap();
    assert!((centre.clearance - apothem).abs() < 1e-12);
    assert!(d.offset(-centre.clearance).unwrap().loops.is_empty());
    // and a hair inside it, a tiny heptagon
    let tiny = d.offset(-centre.clearance * (1.0 - 1e-6)).unwrap();
    assert_eq!(tiny.loops.len(), 1);
    assert_eq!(tiny.loops[0].pieces.len(), n);
}

#[test]
fn annulus_shrinks_to_a_thinner_one_and_grows_without_its_hole() {
    let outer = regular(64, 10.0, 0.0, 0.0);
    let inner = regular(64, 4.0, 0.0, 0.0);
    let d = polygon(&[outer, inner]);
    let o = d.offset(-1.0).unwrap();
    check_closed(&o);
    assert_eq!(o.loops.len(), 2);
    assert_eq!(o.loops.iter().filter(|l| l.hole).count(), 1);
    assert_eq!(o.loops[1].parent, Some(0));
    // the inner ring's offset at 1 grows it by P r + π r², the outer's shrinks
    let ngon = |r: f64, n: f64| n / 2.0 * r * r * (2.0 * PI / n).sin();
    let side = |r: f64, n: f64| 2.0 * r * (PI / n).sin();
    let a_outer = {
        let ap = 10.0 * (PI / 64.0).cos() - 1.0;
        64.0 * ap * ap * (PI / 64.0).tan()
    };
    let a_inner = ngon(4.0, 64.0) + 64.0 * side(4.0, 64.0) + PI;
    assert!((o.area() - (a_outer - a_inner)).abs() < 1e-8, "{} vs {}", o.area(), a_outer - a_inner);
    // grown by 3 the hole (radius about 4) keeps a hole of radius about 1
    let g = d.offset(3.0).unwrap();
    check_closed(&g);
    assert_eq!(g.loops.len(), 2);
    // grown by 5 the hole is gone
    let g = d.offset(5.0).unwrap();
    check_closed(&g);
    assert_eq!(g.loops.len(), 1);
}

#[test]
fn dumbbell_pinches_into_two_loops_at_the_neck_clearance() {
    // two 4 × 4 squares joined by a 2-wide corridor of length 4
    let ring = vec![
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [8.0, 1.0],
        [8.0, 0.0],
        [12.0, 0.0],
        [12.0, 4.0],
        [8.0, 4.0],
        [8.0, 3.0],
        [4.0, 3.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ];
    let d = polygon(&[ring]);
    let one = d.offset(-0.5).unwrap();
    check_closed(&one);
    assert_eq!(one.loops.len(), 1);
    // at exactly the corridor's half width the corridor has no interior
    let pinched = d.offset(-1.0).unwrap();
    check_closed(&pinched);
    assert_eq!(pinched.loops.len(), 2);
    // per square: the inner 2 × 2, and the 1 × 2 towards the corridor
    // less a quarter circle around each of its corners
    let want = 2.0 * (4.0 + 2.0 - PI / 2.0);
    assert!((pinched.area() - want).abs() < 1e-9, "{} vs {want}", pinched.area());
    let two = d.offset(-1.5).unwrap();
    check_closed(&two);
    assert_eq!(two.loops.len(), 2);
}

#[test]
fn offsets_at_a_vertex_clearance_stay_closed_and_split() {
    // every vertex clearance of a notched shape as a distance
    let ring = vec![[0.0, 0.0], [6.0, 0.0], [6.0, 5.0], [3.5, 2.0], [2.5, 2.0], [0.0, 5.0]];
    let d = polygon(&[ring]);
    let mut distances: Vec<f64> = d.vertices().map(|v| v.clearance).filter(|&c| c > 0.0).collect();
    distances.sort_by(f64::total_cmp);
    distances.dedup();
    for r in distances {
        for o in [d.offset(-r).unwrap(), d.offset(r).unwrap()] {
            check_closed(&o);
        }
    }
}

#[test]
fn many_distances_match_one_at_a_time() {
    let d = polygon(&[regular(9, 5.0, 1.0, 1.0), regular(5, 1.0, 0.5, 0.0)]);
    let distances = [-3.0, -0.5, 0.25, 2.0, -1.0];
    let all = d.offsets(&distances).unwrap();
    for (o, &r) in all.iter().zip(&distances) {
        assert_eq!(o, &d.offset(r).unwrap());
        check_closed(o);
    }
}

#[test]
fn bad_distances_are_errors() {
    let mut b = Builder::new();
    b.add_point([0.0, 0.0]).unwrap();
    let d = b.build().unwrap();
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(d.offset(r).unwrap_err().kind(), ErrorKind::InvalidArgument, "{r}");
    }
    let d = polygon(&[regular(4, 1.0, 0.0, 0.0)]);
    assert!(d.offset(-0.1).is_ok());
    assert_eq!(d.offset(0.0).unwrap_err().kind(), ErrorKind::InvalidArgument);
}

#[test]
fn polylines_are_within_tolerance_and_areas_agree() {
    let d = polygon(&[regular(5, 2.0, 0.0, 0.0)]);
    let o = d.offset(1.5).unwrap();
    for tolerance in [1e-1, 1e-3, 1e-6] {
        let lines = o.polylines(tolerance).unwrap();
        let shoelace: f64 = lines
            .iter()
            .map(|l| (0..l.len()).map(|i| l[i].x * l[(i + 1) % l.len()].y - l[(i + 1) % l.len()].x * l[i].y).sum::<f64>() / 2.0)
            .sum();
        // chords cut inside the arcs: at most tolerance × perimeter less
        let perimeter = 5.0 * 2.0 * 2.0 * (PI / 5.0).sin() + 2.0 * PI * 1.5;
        assert!(
            shoelace <= o.area() + 1e-9 && o.area() - shoelace <= tolerance * perimeter,
            "{tolerance}: {shoelace} {}",
            o.area()
        );
    }
}

/// No loop passes a point twice (the touching point of two parts).
fn check_no_point_twice(o: &crate::Offset) {
    for (k, l) in o.loops.iter().enumerate() {
        let mut starts: Vec<(u64, u64)> = l.pieces.iter().map(|p| (p.from().x.to_bits(), p.from().y.to_bits())).collect();
        starts.sort_unstable();
        starts.dedup();
        assert_eq!(starts.len(), l.pieces.len(), "loop {k} passes a point twice: {:?}", l.pieces);
    }
}

#[test]
fn holes_touching_at_a_point_are_two_loops() {
    // two obstacles 2 apart: shrunk by 1 their holes touch at (5, 5)
    let mut b = Builder::new();
    b.add_polygon(&[vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]]).unwrap();
    b.add_points([[4.0, 5.0], [6.0, 5.0]]).unwrap();
    let d = b.build().unwrap();
    let o = d.offset(-1.0).unwrap();
    check_closed(&o);
    check_no_point_twice(&o);
    assert_eq!(o.loops.len(), 3);
    assert_eq!(o.loops.iter().filter(|l| l.hole).count(), 2);
    assert!((o.area() - (64.0 - 2.0 * PI)).abs() < 1e-9);
    // a hole's corner and a point 1 apart, shrunk by 0.5
    let mut b = Builder::new();
    b.add_polygon(&[
        vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
        vec![[3.0, 2.0], [5.0, 2.0], [5.0, 4.0], [3.0, 4.0]],
    ])
    .unwrap();
    b.add_point([6.0, 2.0]).unwrap();
    let d = b.build().unwrap();
    let o = d.offset(-0.5).unwrap();
    check_closed(&o);
    check_no_point_twice(&o);
    assert_eq!(o.loops.iter().filter(|l| l.hole).count(), 2);
}
