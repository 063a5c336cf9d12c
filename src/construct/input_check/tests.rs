//! Tests of the input check: normalisation, conflicts, exactness, the
//! degenerate cases of the sweep, the sweep against brute force, and a large
//! input.

use super::classify::segment_conflict_at;
use super::normalise::{normalise, Normalised};
use super::sweep::{find_conflict, find_conflict_at, sweep, PRESORTED_FROM};
use super::*;
use crate::construct::input_scale;
use crate::geometry::input::segment_contact::ContactPoint;
use crate::geometry::input::segment_contact::{inside_segment, lex_key};
use proptest::prelude::*;
use std::cmp::Ordering;

/// The check as the builder calls it, with the build's one scale.
fn check_segments(points: &[Point], segments: &[[Point; 2]]) -> Result<CheckedInput, Conflict> {
    super::check_segments(points, segments, &[], input_scale(points, segments))
}

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

fn s(ax: f64, ay: f64, bx: f64, by: f64) -> [Point; 2] {
    [p(ax, ay), p(bx, by)]
}

fn check(segments: &[[Point; 2]]) -> Result<CheckedInput, Conflict> {
    check_segments(&[], segments)
}

/// The splits of a checked input as (input index of the segment split,
/// the vertex), or the conflict.
fn cuts(points: &[Point], segments: &[[Point; 2]]) -> Result<Vec<(usize, Vertex)>, Conflict> {
    let out = check_segments(points, segments)?;
    Ok(out.splits.iter().map(|c| (out.segments[c.segment].0, c.at)).collect())
}

/// End `end` of input segment `segment`.
fn end(segment: usize, end: usize) -> Vertex {
    Vertex::End { segment, end }
}

fn up(x: f64) -> f64 {
    f64::from_bits(x.to_bits() + 1)
}

fn down(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

// ---- normalisation ----

#[test]
fn empty_and_points_only() {
    let out = check_segments(&[], &[]).unwrap();
    assert!(out.points.is_empty() && out.segments.is_empty());
    let out = check_segments(&[p(1., 2.), p(1., 2.), p(3., 4.)], &[]).unwrap();
    assert_eq!(out.points, vec![(PointSource::Point(0), p(1., 2.)), (PointSource::Point(2), p(3., 4.))]);
    assert_eq!(out.duplicate_points, 1);
}

#[test]
fn zero_length_segment_is_a_point_and_negative_zero_equals_zero() {
    let out = check(&[s(0., -0., -0., 0.), s(1., 1., 2., 2.)]).unwrap();
    assert_eq!(out.degenerate_segments, 1);
    assert_eq!(out.points, vec![(PointSource::Segment(0), p(0., 0.))]);
    assert!(out.points[0].1.x.is_sign_positive() && out.points[0].1.y.is_sign_positive());
    assert_eq!(out.segments, vec![(1, s(1., 1., 2., 2.))]);
}

#[test]
fn duplicate_segments_merge_in_either_direction() {
    let out = check(&[s(0., 0., 1., 0.), s(1., 0., 0., 0.), s(0., 0., 1., 0.), s(-0., 0., 1., -0.)]).unwrap();
    assert_eq!(out.segments, vec![(0, s(0., 0., 1., 0.))]);
    assert_eq!(out.duplicate_segments, 3);
    assert_eq!(out.kept_of_input, vec![Some(0); 4]);
}

#[test]
fn points_on_endpoints_and_repeated_points_merge() {
    let points = [p(1., 0.), p(5., 5.), p(5., 5.)];
    let segments = [s(0., 0., 1., 0.), s(5., 5., 5., 5.), s(7., 7., 7., 7.), s(0., 0., 0., 0.)];
    let out = check_segments(&points, &segments).unwrap();
    // Endpoint (1,0) absorbs point 0; point 1 absorbs point 2 and the
    // zero-length segment 1; segment 3 repeats an endpoint.
    assert_eq!(out.points, vec![(PointSource::Point(1), p(5., 5.)), (PointSource::Segment(2), p(7., 7.))]);
    assert_eq!((out.duplicate_points, out.degenerate_segments), (4, 3));
}

#[test]
fn output_keeps_input_coordinates_of_huge_inputs() {
    let input = [s(1e300, -1e300, 3e300, 2e300)];
    let out = check_segments(&[p(-1e300, 7e299)], &input).unwrap();
    assert_eq!(out.segments, vec![(0, input[0])]);
    assert_eq!(out.points, vec![(PointSource::Point(0), p(-1e300, 7e299))]);
}

// ---- conflicts ----

#[test]
fn crossing_segments() {
    let r = check(&[s(0., 0., 2., 2.), s(5., 5., 6., 6.), s(0., 2., 2., 0.)]);
    assert_eq!(r, Err(Conflict::SegmentsCross { first: 0, second: 2 }));
    assert_eq!(r.unwrap_err().message(&[]), "segments 0 and 2 cross");
}

#[test]
fn horizontal_and_vertical() {
    assert_eq!(check(&[s(-1., 0., 1., 0.), s(0., -1., 0., 1.)]), Err(Conflict::SegmentsCross { first: 0, second: 1 }));
    // Vertical stem ending on a horizontal bar, both orders: the bar is
    // split at the stem's end.
    assert_eq!(cuts(&[], &[s(-1., 0., 1., 0.), s(0., 0., 0., 1.)]), Ok(vec![(0, end(1, 0))]));
    assert_eq!(cuts(&[], &[s(0., 5., 0., 1.), s(1., 1., -1., 1.)]), Ok(vec![(1, end(0, 1))]));
    // An L and a vertical pair touching end to end are fine.
    assert!(check(&[s(0., 0., 1., 0.), s(1., 0., 1., 1.), s(1., 1., 1., 3.)]).is_ok());
}

#[test]
fn t_junction_splits_the_segment() {
    let r = cuts(&[], &[s(0., 0., 1., 3.), s(0., 0., 4., 0.), s(2., 0., 2., 3.)]);
    assert_eq!(r, Ok(vec![(1, end(2, 0))]));
    // Several vertices on one segment, found along it from its smaller
    // end, whatever its direction; a vertex on two segments' interiors
    // would be a crossing.
    let bar = s(8., 0., 0., 0.);
    let r = cuts(&[p(5., 0.)], &[bar, s(6., 0., 6., 1.), s(2., -1., 2., 0.), s(3., 0., 3., -1.), s(2., 0., 2., 1.)]);
    assert_eq!(r, Ok(vec![(0, end(2, 1)), (0, end(3, 0)), (0, Vertex::Point(0)), (0, end(1, 0))]));
    // A checkerboard's corner: two squares touching at a corner split nothing.
    let square = |x: f64, y: f64| polygon_of(&[p(x, y), p(x + 1., y), p(x + 1., y + 1.), p(x, y + 1.)]);
    let mut board = square(0., 0.);
    board.extend(square(1., 1.));
    assert_eq!(cuts(&[], &board), Ok(vec![]));
    // A hole touching its shell inside an edge splits that edge.
    let mut shell = polygon_of(&[p(0., 0.), p(10., 0.), p(10., 10.), p(0., 10.)]);
    shell.extend(polygon_of(&[p(0., 5.), p(3., 4.), p(3., 6.)]));
    assert_eq!(cuts(&[], &shell), Ok(vec![(3, end(4, 0))]));
}

/// The closed ring through `corners`, as segments.
fn polygon_of(corners: &[Point]) -> Vec<[Point; 2]> {
    (0..corners.len()).map(|k| [corners[k], corners[(k + 1) % corners.len()]]).collect()
}

#[test]
fn collinear_cases() {
    let overlap = |a, b| Err(Conflict::SegmentsOverlap { first: a, second: b });
    assert_eq!(check(&[s(0., 0., 2., 2.), s(1., 1., 3., 3.)]), overlap(0, 1));
    assert_eq!(check(&[s(0., 0., 4., 0.), s(3., 0., 1., 0.)]), overlap(0, 1), "contained");
    assert_eq!(check(&[s(0., 0., 4., 0.), s(0., 0., 1., 0.)]), overlap(0, 1), "contained, common end");
    assert_eq!(check(&[s(0., 0., 0., 4.), s(0., 4., 0., 1.)]), overlap(0, 1), "vertical");
    assert!(check(&[s(0., 0., 1., 1.), s(1., 1., 2., 2.), s(2., 2., 5., 5.)]).is_ok(), "consecutive");
    assert!(check(&[s(0., 0., 1., 1.), s(2., 2., 3., 3.)]).is_ok(), "disjoint");
    assert!(check(&[s(0., 0., 1., 0.), s(3., 0., 2., 0.), s(-1., 0., -3., 0.)]).is_ok(), "disjoint");
    let segments = [s(0., 0., 4., 0.), s(3., 0., 1., 0.)];
    assert_eq!(
        Conflict::SegmentsOverlap { first: 0, second: 1 }.message(&segments),
        "segments 0 and 1 are collinear and overlap from (1, 0) to (3, 0)"
    );
}

#[test]
fn point_inside_segment() {
    // An isolated point inside a segment splits it, as an endpoint does.
    let r = cuts(&[p(9., 9.), p(1., 1.)], &[s(0., 0., 2., 2.)]);
    assert_eq!(r, Ok(vec![(0, Vertex::Point(1))]));
    // On the line but outside, and on an endpoint: nothing to split.
    assert_eq!(cuts(&[p(3., 3.), p(2., 2.)], &[s(0., 0., 2., 2.)]), Ok(vec![]));
    // A zero-length segment inside a segment splits it too.
    let r = cuts(&[], &[s(0., 0., 2., 2.), s(1., 1., 1., 1.)]);
    assert_eq!(r, Ok(vec![(0, end(1, 0))]));
}

#[test]
fn leftmost_conflict_is_reported() {
    // Pairs (1,2) and (0,3) both cross, at (1,1) and (1,11): the lower
    // one is lexicographically first, whatever the input order.
    let segments = [s(0., 10., 2., 12.), s(0., 0., 2., 2.), s(0., 2., 2., 0.), s(0., 12., 2., 10.)];
    assert_eq!(check(&segments), Err(Conflict::SegmentsCross { first: 1, second: 2 }));
    let reversed: Vec<[Point; 2]> = segments.iter().rev().copied().collect();
    assert_eq!(check(&reversed), Err(Conflict::SegmentsCross { first: 1, second: 2 }));
    // A point inside a segment left of a crossing is no conflict: the
    // crossing is reported.
    let r = check_segments(&[p(0.5, 11.)], &[s(0., 11., 2., 11.), s(0., 0., 2., 2.), s(0., 2., 2., 0.)]);
    assert_eq!(r, Err(Conflict::SegmentsCross { first: 1, second: 2 }));
    // At one x the lower contact point wins: a crossing at (1, 1) against
    // an overlap starting at (1, 7); a T-junction at (1, 5) between them
    // is a split.
    let segments =
        [s(1., 7., 3., 7.), s(0., 7., 2., 7.), s(0., 5., 2., 5.), s(1., 5., 1., 6.), s(0., 0., 2., 2.), s(0., 2., 2., 0.)];
    assert_eq!(check(&segments), Err(Conflict::SegmentsCross { first: 4, second: 5 }));
    assert_eq!(check(&segments[..4]), Err(Conflict::SegmentsOverlap { first: 0, second: 1 }));
    assert_eq!(cuts(&[], &segments[2..4]), Ok(vec![(0, end(1, 0))]));
}

#[test]
fn crossing_point_is_compared_exactly() {
    // Segments 0 and 1 cross at (1/3, 1/3) exactly. Segment 3 overlaps
    // the vertical bar 2 at x from (x, -4) on: the double nearest 1/3 lies
    // below 1/3, so that overlap is further left than the crossing; one
    // ulp up, it is further right.
    let third = 1.0 / 3.0;
    let cross = [s(0., 0., 1., 1.), s(0., 1., 0.5, 0.)];
    let at = ContactPoint::crossing(cross[0], cross[1]);
    assert_eq!(ContactPoint::At(p(third, 9.0)).cmp(&at), Ordering::Less);
    assert_eq!(ContactPoint::At(p(up(third), -9.0)).cmp(&at), Ordering::Greater);
    let with_t = |x: f64| {
        let mut v = cross.to_vec();
        v.extend([s(x, -6., x, -3.), s(x, -4., x, -2.)]);
        v
    };
    assert_eq!(check(&with_t(third)), Err(Conflict::SegmentsOverlap { first: 2, second: 3 }));
    assert_eq!(check(&with_t(up(third))), Err(Conflict::SegmentsCross { first: 0, second: 1 }));
    // Exactly on a crossing: (1/2, 1/2) for the diagonals of a square.
    let y = ContactPoint::crossing(s(0., 0., 1., 1.), s(0., 1., 1., 0.));
    assert_eq!(ContactPoint::At(p(0.5, 0.5)).cmp(&y), Ordering::Equal);
    assert_eq!(ContactPoint::At(p(0.5, up(0.5))).cmp(&y), Ordering::Greater);
    assert_eq!(ContactPoint::At(p(down(0.5), 7.0)).cmp(&y), Ordering::Less);
    // Two crossings one ulp apart in y at the same x.
    let z = ContactPoint::crossing(s(0., 0., 1., 2.), s(0., 2., 1., 0.)); // (1/2, 1)
    let w = ContactPoint::crossing(s(0., up(0.), 1., 2.), s(0., 2., 1., up(0.)));
    assert_eq!(z.cmp(&w), Ordering::Less);
    assert_eq!(w.cmp(&z), Ordering::Greater);
    assert_eq!(z.cmp(&z.clone()), Ordering::Equal);
}

// ---- allowed shared endpoints ----

#[test]
fn star_of_256_segments() {
    let centre = p(0.5, -0.25);
    let star: Vec<[Point; 2]> = (0..256)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 256.0;
            [centre, p(centre.x + t.cos(), centre.y + t.sin())]
        })
        .collect();
    let out = check(&star).unwrap();
    assert_eq!(out.segments.len(), 256);
    // One more spoke through the centre crosses nothing but overlaps
    // the spoke pointing the same way.
    let mut bad = star.clone();
    bad.push([p(centre.x - 0.5, centre.y), p(centre.x + 0.5, centre.y)]);
    assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 0, second: 256 }));
}

fn polygon(centre: Point, radius: f64, n: usize) -> Vec<[Point; 2]> {
    let corner = |k: usize| {
        let t = (k % n) as f64 * std::f64::consts::TAU / n as f64;
        p(centre.x + radius * t.cos(), centre.y + radius * t.sin())
    };
    (0..n).map(|k| [corner(k), corner(k + 1)]).collect()
}

#[test]
fn closed_polygon_and_polygon_with_hole() {
    let outer = polygon(p(0., 0.), 10., 1000);
    assert!(check(&outer).is_ok());
    let mut with_hole = outer.clone();
    with_hole.extend(polygon(p(1., 0.), 3., 37));
    with_hole.extend(polygon(p(-5., 0.), 1., 3));
    let out = check_segments(&[p(0.5, 0.5)], &with_hole).unwrap();
    assert_eq!(out.segments.len(), 1040);
    // A hole too big for its polygon crosses it.
    let mut bad = outer;
    bad.extend(polygon(p(5., 0.), 6., 5));
    assert!(matches!(check(&bad), Err(Conflict::SegmentsCross { .. })));
}

// ---- exactness ----

#[test]
fn one_ulp_decides() {
    let bar = s(0., 0., 2., 0.);
    assert!(check(&[bar, s(1., up(0.), 1., 5.)]).is_ok(), "one ulp above");
    assert_eq!(cuts(&[], &[bar, s(1., 0., 1., 5.)]), Ok(vec![(0, end(1, 0))]));
    assert_eq!(check(&[bar, s(1., -f64::from_bits(1), 1., 5.)]), Err(Conflict::SegmentsCross { first: 0, second: 1 }));
    // Near the end of the bar: one ulp beyond it is fine.
    assert!(check(&[bar, s(up(2.), 0., 3., 5.)]).is_ok());
    assert!(check(&[bar, s(up(2.), 0., 3., 5.)]).unwrap().splits.is_empty());
    assert_eq!(cuts(&[], &[bar, s(down(2.), 0., 3., 5.)]), Ok(vec![(0, end(1, 0))]));
    // A diagonal: a point one ulp off the line is not on it.
    let diag = s(0.1, 0.1, 0.7, 0.7);
    assert_eq!(cuts(&[p(0.3, up(0.3))], &[diag]), Ok(vec![]));
    assert_eq!(cuts(&[p(0.3, 0.3)], &[diag]), Ok(vec![(0, Vertex::Point(0))]));
    // Nearly parallel segments one ulp apart.
    assert!(check(&[s(0., 1., 1e6, 1.), s(0., up(1.), 1e6, up(1.))]).is_ok());
    assert!(check(&[s(0., 1., 1e6, 1.), s(0., up(1.), 1e6, down(1.))]).is_err());
}

#[test]
fn huge_and_tiny_coordinates() {
    for &f in &[1e300, 1e-300, 1.0, f64::from_bits(8) /* 8 × 2^-1074 */] {
        let cross = [s(-f, -f, f, f), s(-f, f, f, -f)];
        assert_eq!(check(&cross), Err(Conflict::SegmentsCross { first: 0, second: 1 }), "{f}");
        let apart = [s(-f, -f, f, f), s(-f, f, -f / 2.0, 0.5 * f)];
        assert!(check(&apart).is_ok(), "{f}");
    }
    // Tiny: on the diagonal, and one ulp off it (products underflow
    // without the power-of-two scaling).
    let diag = s(0., 0., 2e-300, 2e-300);
    assert_eq!(cuts(&[p(1e-300, 1e-300)], &[diag]), Ok(vec![(0, Vertex::Point(0))]));
    assert_eq!(cuts(&[p(1e-300, up(1e-300))], &[diag]), Ok(vec![]));
    // Huge: a T-junction and its one-ulp miss (products overflow
    // without the scaling).
    let bar = s(-1e300, 1e300, 1e300, -1e300);
    assert_eq!(cuts(&[], &[bar, s(3e299, -3e299, 1e300, 1e300)]), Ok(vec![(0, end(1, 0))]));
    assert_eq!(cuts(&[], &[bar, s(3e299, down(-3e299), 1e300, 1e300)]), Ok(vec![]), "one ulp nearer zero");
    // Beyond the documented range: a difference of 1e-324 next to 1e300
    // vanishes in the scaling (as in the point builder), so this touches.
    assert_eq!(cuts(&[], &[bar, s(f64::from_bits(1), 0., 1e300, 1e300)]), Ok(vec![(0, end(1, 0))]));
}

#[test]
fn tiny_extent_next_to_a_far_point() {
    // The far point sets the scale, so the segments' extent stays near
    // 1e-300. (The orientations there underflow, beyond the predicates'
    // documented exact range, so only "no panic, an answer" is asserted.)
    let t = 1e-300;
    let segments = [s(0., 0., t, 0.), s(t, 0., t, t), s(0., t, 0.5 * t, 2. * t)];
    let _ = check_segments(&[p(1.0, 1.0)], &segments);
}

// ---- degenerate cases of the sweep ----

/// The factors the degenerate cases are tried at: ordinary, huge, tiny.
const FACTORS: [f64; 3] = [1.0, 1e300, 1e-300];

#[test]
fn star_of_1000_spokes() {
    for f in FACTORS {
        // Spokes both start and end at the centre (those pointing left end
        // there): 1000 segments sharing one point, no conflict.
        let centre = p(0.5 * f, -0.25 * f);
        let star: Vec<[Point; 2]> = (0..1000)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 1000.0;
                [centre, p(centre.x + t.cos() * f, centre.y + t.sin() * f)]
            })
            .collect();
        assert!(check(&star).is_ok(), "{f}");
        // With an isolated point near the centre, and one on a spoke's
        // line but beyond its tip: still fine.
        assert!(check_segments(&[p(centre.x, centre.y + 1e-3 * f), p(centre.x + 2.0 * f, centre.y)], &star).is_ok());
    }
}

#[test]
fn star_with_a_spoke_overlapping_another() {
    for f in FACTORS {
        // Tips on the boundary of a square: all directions distinct.
        let mut tips: Vec<(f64, f64)> = Vec::new();
        for k in -10..10 {
            let k = f64::from(k);
            tips.extend([(k, -10.), (10., k), (-k, 10.), (-10., -k)]);
        }
        let star: Vec<[Point; 2]> = tips.iter().map(|&(x, y)| [p(0., 0.), p(x * f, y * f)]).collect();
        assert!(check(&star).is_ok(), "{f}");
        let index_of = |x: f64, y: f64| tips.iter().position(|&t| t == (x, y)).unwrap();
        let n = star.len();
        // Half the spoke to (10, 4), from the centre: overlaps it there.
        let mut bad = star.clone();
        bad.push([p(0., 0.), p(5. * f, 2. * f)]);
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: index_of(10., 4.), second: n }), "{f}");
        // Twice the spoke to (-10, -4), ending at the centre: the overlap
        // starts at (-10, -4), left of the centre, so it is reported.
        bad.push([p(-20. * f, -8. * f), p(0., 0.)]);
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: index_of(-10., -4.), second: n + 1 }), "{f}");
        // Through the centre, along two spokes: it overlaps them.
        let mut through = star.clone();
        through.push([p(-3. * f, 0.), p(3. * f, 0.)]);
        assert!(matches!(check(&through), Err(Conflict::SegmentsOverlap { .. })));
        // Through the centre between spokes: it crosses none, and is split
        // at the centre, where every spoke ends.
        let mut through = star.clone();
        through.push([p(-3. * f, -f), p(3. * f, f)]);
        assert_eq!(cuts(&[], &through), Ok(vec![(n, end(0, 0))]), "{f}");
    }
}

#[test]
fn stacked_vertical_segments() {
    for f in FACTORS {
        let stack: Vec<[Point; 2]> = (0..100).map(|i| s(0., f64::from(i) * f, 0., f64::from(i + 1) * f)).collect();
        assert!(check(&stack).is_ok(), "{f}");
        // Reversed ends, and a second stack with gaps beside it.
        let mut two: Vec<[Point; 2]> = stack.iter().map(|&[a, b]| [b, a]).collect();
        two.extend((0..50).map(|i| s(f, f64::from(2 * i) * f, f, f64::from(2 * i + 1) * f)));
        assert!(check(&two).is_ok(), "{f}");
        // Shifted by half: overlaps segment 50 from (0, 50.5) on.
        let mut bad = stack.clone();
        bad.push(s(0., 50.5 * f, 0., 51.5 * f));
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 50, second: 100 }), "{f}");
        // Contained in one, with no common end.
        let mut bad = stack.clone();
        bad.push(s(0., 70.25 * f, 0., 70.75 * f));
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 70, second: 100 }), "{f}");
        // A horizontal crossing one, and one ending on one.
        let mut bad = stack.clone();
        bad.push(s(-f, 30.25 * f, f, 30.25 * f));
        assert_eq!(check(&bad), Err(Conflict::SegmentsCross { first: 30, second: 100 }), "{f}");
        let mut bad = stack.clone();
        bad.push(s(-f, 30.25 * f, 0., 30.25 * f));
        assert_eq!(cuts(&[], &bad), Ok(vec![(30, end(100, 1))]), "{f}");
        // Touching the stack at a shared end from the side: fine.
        let mut fine = stack.clone();
        fine.push(s(-f, 30. * f, 0., 30. * f));
        fine.push(s(0., 30. * f, f, 31. * f));
        assert!(check(&fine).is_ok(), "{f}");
    }
}

#[test]
fn point_inside_a_vertical_segment() {
    for f in FACTORS {
        let segments = [s(0., 0., 0., f), s(0., f, 0., 2. * f), s(-f, f, 0., f), s(0., 3. * f, 0., 4. * f)];
        // Points at the same x as many events: between the segments, and
        // on their ends (merged), are fine.
        let fine = [p(0., 2.5 * f), p(0., -f), p(0., 5. * f), p(0., 0.)];
        assert!(check_segments(&fine, &segments).is_ok(), "{f}");
        let r = cuts(&[p(0., 2.5 * f), p(0., 1.5 * f)], &segments);
        assert_eq!(r, Ok(vec![(1, Vertex::Point(1))]), "{f}");
        // As a zero-length segment.
        let mut with = segments.to_vec();
        with.push(s(0., 3.5 * f, 0., 3.5 * f));
        assert_eq!(cuts(&[], &with), Ok(vec![(3, end(4, 0))]), "{f}");
    }
}

#[test]
fn collinear_chain() {
    for f in FACTORS {
        // Ends alternately reversed; all on the line y = 2x.
        let chain: Vec<[Point; 2]> = (0..1000)
            .map(|i| {
                let (a, b) = (f64::from(i), f64::from(i + 1));
                let seg = s(a * f, 2. * a * f, b * f, 2. * b * f);
                if i % 2 == 0 {
                    seg
                } else {
                    [seg[1], seg[0]]
                }
            })
            .collect();
        assert!(check(&chain).is_ok(), "{f}");
        let mut bad = chain.clone();
        bad.push(s(500.5 * f, 1001. * f, 600. * f, 1200. * f));
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 500, second: 1000 }), "{f}");
        // The same line continued past the end: fine.
        let mut fine = chain.clone();
        fine.push(s(1000. * f, 2000. * f, 1500. * f, 3000. * f));
        assert!(check(&fine).is_ok(), "{f}");
    }
}

#[test]
fn t_junction_at_an_x_shared_with_many_events() {
    for f in FACTORS {
        // 400 segments start or end at x = 5, at y = 0..400; a diagonal
        // passes x = 5 at y = 500, a vertical bar spans y = 1000..2000.
        let mut segments: Vec<[Point; 2]> = Vec::new();
        for k in 0..200 {
            let k = f64::from(k);
            segments.push(s(5. * f, 2. * k * f, 6. * f, 2. * k * f));
            segments.push(s(4. * f, (2. * k + 1.) * f, 5. * f, (2. * k + 1.) * f));
        }
        segments.push(s(0., 0., 10. * f, 1000. * f)); // 400
        segments.push(s(5. * f, 1000. * f, 5. * f, 2000. * f)); // 401
        segments.push(s(5. * f, 490. * f, 7. * f, 490. * f)); // 402, just below it
        assert!(check(&segments).is_ok(), "{f}");
        // Starting on the diagonal at x = 5, and ending on the bar there.
        let mut bad = segments.clone();
        bad.push(s(5. * f, 500. * f, 6. * f, 500. * f));
        assert_eq!(cuts(&[], &bad), Ok(vec![(400, end(403, 0))]), "{f}");
        let mut bad = segments.clone();
        bad.push(s(4. * f, 1500. * f, 5. * f, 1500. * f));
        assert_eq!(cuts(&[], &bad), Ok(vec![(401, end(403, 1))]), "{f}");
        // Both, listed by segment.
        bad.push(s(5. * f, 500. * f, 6. * f, 500. * f));
        assert_eq!(cuts(&[], &bad), Ok(vec![(400, end(404, 0)), (401, end(403, 1))]), "{f}");
        // One more starting on the diagonal there, along it: an overlap.
        bad.push(s(5. * f, 500. * f, 10. * f, 1000. * f));
        assert_eq!(check(&bad), Err(Conflict::SegmentsOverlap { first: 400, second: 405 }), "{f}");
    }
}

/// The check asks only exact predicates: lying ones change nothing.
#[cfg(feature = "fault-injection")]
#[test]
fn fault_injection_does_not_reach_the_check() {
    use crate::geometry::fault::{set_fault_mode, FaultMode};
    let star = |extra: Option<[Point; 2]>| {
        let mut v: Vec<[Point; 2]> = (0..64)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 64.0;
                [p(0., 0.), p(t.cos(), t.sin())]
            })
            .collect();
        v.extend(extra);
        v
    };
    let inputs = [
        star(None),
        star(Some(s(0.2, -0.5, 0.2, 0.5))),
        star(Some(s(-2., 0., -1., 0.))),
        vec![s(0., 0., 2., 2.), s(0., 2., 2., 0.), s(5., 5., 6., 6.)],
        vec![s(0., 0., 4., 0.), s(2., 0., 2., 3.), s(0., 1., 0., 2.)],
    ];
    let expected: Vec<_> = inputs.iter().map(|i| check(i).err()).collect();
    for mode in [FaultMode::Random, FaultMode::Noise(1e-3)] {
        set_fault_mode(mode, 7);
        let got: Vec<_> = inputs.iter().map(|i| check(i).err()).collect();
        set_fault_mode(FaultMode::Off, 0);
        assert_eq!(got, expected, "{mode:?}");
    }
}

// ---- the sweep against brute force ----

/// Every conflict of every pair, with its contact point: O(n²).
fn all_conflicts(norm: &Normalised) -> Vec<(Conflict, ContactPoint)> {
    let m = norm.segments.len();
    (0..m).flat_map(|i| (i + 1..m).map(move |j| (i, j))).filter_map(|(i, j)| segment_conflict_at(norm, i, j)).collect()
}

/// Every vertex inside every kept segment, by brute force, as (segment,
/// the vertex's sort key), sorted: O(n²).
fn all_splits(norm: &Normalised) -> Vec<(usize, (u64, u64))> {
    let mut vertices: Vec<Point> =
        norm.segments.iter().flat_map(|&(_, s)| s).chain(norm.points.iter().map(|&(_, q)| q)).collect();
    vertices.sort_by_key(|&q| lex_key(q));
    vertices.dedup();
    let mut out: Vec<(usize, (u64, u64))> = (0..norm.segments.len())
        .flat_map(|k| vertices.iter().filter(move |&&q| inside_segment(q, norm.segments[k].1)).map(move |&q| (k, lex_key(q))))
        .collect();
    out.sort_unstable();
    out
}

/// Where a split's vertex is (internal coordinates).
fn vertex_point(norm: &Normalised, v: Vertex) -> Point {
    let lone = |src: PointSource| norm.points.iter().find(|&&(s, _)| s == src).expect("a kept point").1;
    match v {
        Vertex::Point(i) => lone(PointSource::Point(i)),
        Vertex::End { segment, end } => match norm.kept_of_input[segment] {
            Some(k) => {
                assert_eq!(norm.segments[k].0, segment, "the vertex of a kept segment");
                norm.segments[k].1[end]
            }
            None => lone(PointSource::Segment(segment)),
        },
    }
}

/// The smallest contact point of all conflicts, by brute force.
fn brute_force(norm: &Normalised) -> Option<ContactPoint> {
    all_conflicts(norm).into_iter().map(|(_, at)| at).min_by(|a, b| a.cmp(b))
}

/// The sweep's answer agrees with brute force: both find nothing, or the
/// sweep's conflict is one of the pairs' conflicts, at its contact point,
/// and that point is the smallest of all. Returns the sweep's answer.
fn sweep_agrees(norm: &Normalised) -> Result<Option<(Conflict, ContactPoint)>, TestCaseError> {
    let found = find_conflict_at(norm);
    let all = all_conflicts(norm);
    match (&found, brute_force(norm)) {
        (None, None) => {}
        (Some((c, at)), Some(min)) => {
            prop_assert_eq!(at.cmp(&min), Ordering::Equal, "{:?} at {:?}, min {:?}", c, at, min);
            prop_assert!(all.iter().any(|(d, e)| d == c && e.cmp(at) == Ordering::Equal), "{:?} is no conflict", c);
        }
        (f, b) => prop_assert!(false, "sweep {:?}, brute force {:?}", f, b),
    }
    prop_assert_eq!(found.as_ref().map(|f| f.0), find_conflict(norm));
    if found.is_none() {
        // Every split, in order along each segment, and each vertex is
        // where it says.
        let (_, splits) = sweep(norm);
        let got: Vec<(usize, (u64, u64))> = splits.iter().map(|c| (c.segment, lex_key(vertex_point(norm, c.at)))).collect();
        prop_assert_eq!(got, all_splits(norm));
    }
    Ok(found)
}

/// Whether integer input breaks the rules (a crossing or an overlap), and
/// how many (vertex, segment) splits it has, decided independently of
/// `segment_contact`: intersections computed in exact integer arithmetic.
fn integer_oracle(points: &[(i64, i64)], segments: &[[(i64, i64); 2]]) -> (bool, usize) {
    let mut kept: Vec<[(i64, i64); 2]> = Vec::new();
    let mut lone: Vec<(i64, i64)> = points.to_vec();
    for &[a, b] in segments {
        if a == b {
            lone.push(a);
        } else if !kept.iter().any(|&[c, d]| (a, b) == (c, d) || (a, b) == (d, c)) {
            kept.push([a, b]);
        }
    }
    let pairs = (0..kept.len()).any(|i| (i + 1..kept.len()).any(|j| integer_pair_conflict(kept[i], kept[j])));
    let mut vertices: Vec<(i64, i64)> = kept.iter().flatten().copied().chain(lone).collect();
    vertices.sort_unstable();
    vertices.dedup();
    let splits = kept.iter().map(|&seg| vertices.iter().filter(|&&q| integer_inside(q, seg)).count()).sum();
    (pairs, splits)
}

fn sub(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
    (a.0 - b.0, a.1 - b.1)
}
fn cross(u: (i64, i64), v: (i64, i64)) -> i64 {
    u.0 * v.1 - u.1 * v.0
}
fn dot(u: (i64, i64), v: (i64, i64)) -> i64 {
    u.0 * v.0 + u.1 * v.1
}

fn integer_inside(q: (i64, i64), [a, b]: [(i64, i64); 2]) -> bool {
    let (r, w) = (sub(b, a), sub(q, a));
    cross(r, w) == 0 && 0 < dot(r, w) && dot(r, w) < dot(r, r)
}

/// Closed segments cross (at a point inside both) or overlap; an endpoint
/// of one inside the other is a split, no conflict.
fn integer_pair_conflict([a, b]: [(i64, i64); 2], [c, d]: [(i64, i64); 2]) -> bool {
    let (r, q, w) = (sub(b, a), sub(d, c), sub(c, a));
    let den = cross(r, q);
    if den == 0 {
        if cross(r, w) != 0 {
            return false; // parallel lines
        }
        // Same line: parameters along r; conflict iff the overlap has length.
        let (tc, td) = (dot(r, w), dot(r, sub(d, a)));
        return tc.max(td).min(dot(r, r)) > tc.min(td).max(0);
    }
    // a + t r = c + u q with t = tn / den, u = un / den.
    let (tn, un) = (cross(w, q), cross(w, r));
    let (tn, un, den) = if den < 0 { (-tn, -un, -den) } else { (tn, un, den) };
    let meets = (0..=den).contains(&tn) && (0..=den).contains(&un);
    let at_end = |n: i64| n == 0 || n == den;
    meets && !at_end(tn) && !at_end(un)
}

/// `v * scale + offset`, exact for the placements used here.
fn to_f64(v: (i64, i64), (scale, offset): (f64, f64)) -> Point {
    p(v.0 as f64 * scale + offset, v.1 as f64 * scale + offset)
}

type IntInput = (Vec<(i64, i64)>, Vec<[(i64, i64); 2]>);

/// Coordinates on a small grid: shared endpoints, T-junctions and
/// collinear neighbours are common.
fn small_grid_input() -> impl Strategy<Value = IntInput> {
    let v = (0i64..6, 0i64..6);
    (prop::collection::vec(v.clone(), 0..5), prop::collection::vec([v.clone(), v], 0..12))
}

/// Short segments spread over a larger grid: many grid cells in use.
fn spread_input() -> impl Strategy<Value = IntInput> {
    let seg = ((0i64..40, 0i64..40), (-4i64..=4, -4i64..=4)).prop_map(|(a, d)| [a, (a.0 + d.0, a.1 + d.1)]);
    (prop::collection::vec((0i64..40, 0i64..40), 0..20), prop::collection::vec(seg, 0..50))
}

/// A random walk on a small grid as a polyline: every inner vertex is a
/// shared endpoint, and the walk often touches or retraces itself.
fn polyline_input() -> impl Strategy<Value = IntInput> {
    let steps = prop::collection::vec((-2i64..=2, -2i64..=2), 1..10);
    ((0i64..8, 0i64..8), steps, prop::collection::vec((0i64..8, 0i64..8), 0..3)).prop_map(|(start, steps, points)| {
        let mut at = start;
        let mut segments = Vec::new();
        for (dx, dy) in steps {
            let next = (at.0 + dx, at.1 + dy);
            segments.push([at, next]);
            at = next;
        }
        (points, segments)
    })
}

/// A hub: more spokes starting at one centre than the sweep sorts exactly
/// without an approximate sort first ([`PRESORTED_FROM`]), in any order.
/// Either primitive tips (coprime coordinates: all directions distinct, no
/// conflict among the spokes) on both sides of the centre, so that as
/// many end there as start there, or any tips right of the centre
/// (collinear spokes of different lengths overlap); plus a few segments
/// and points.
fn hub_input() -> impl Strategy<Value = IntInput> {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 {
            a.abs()
        } else {
            gcd(b, a % b)
        }
    }
    let right: Vec<(i64, i64)> =
        (0..=12).flat_map(|x| (-12..=12).map(move |y| (x, y))).filter(|&(x, y)| x > 0 || y > 0).collect();
    let primitive: Vec<(i64, i64)> =
        right.iter().filter(|&&(x, y)| gcd(x, y) == 1).flat_map(|&(x, y)| [(x, y), (-x, -y)]).collect();
    let tips = prop_oneof![
        Just(primitive)
            .prop_shuffle()
            .prop_flat_map(|t| (2 * PRESORTED_FROM + 2..3 * PRESORTED_FROM).prop_map(move |k| t[..k].to_vec())),
        Just(right).prop_shuffle().prop_flat_map(|t| (PRESORTED_FROM + 1..2 * PRESORTED_FROM).prop_map(move |k| t[..k].to_vec())),
    ];
    let v = (-13i64..14, -13i64..14);
    (tips, prop::collection::vec([v.clone(), v.clone()], 0..3), prop::collection::vec(v, 0..3)).prop_map(
        |(tips, extra, points)| {
            let mut segments: Vec<[(i64, i64); 2]> = tips.into_iter().map(|t| [(0, 0), t]).collect();
            segments.extend(extra);
            (points, segments)
        },
    )
}

/// Shared endpoints galore: spokes from one or two centres to points of a
/// small grid (collinear spokes, overlapping spokes), plus a few segments
/// and points.
fn star_input() -> impl Strategy<Value = IntInput> {
    let v = (0i64..7, 0i64..7);
    let centres = prop::collection::vec(v.clone(), 1..3);
    let tips = prop::collection::vec((0usize..2, v.clone()), 1..16);
    let extra = prop::collection::vec([v.clone(), v.clone()], 0..4);
    (centres, tips, extra, prop::collection::vec(v, 0..3)).prop_map(|(centres, tips, extra, points)| {
        let mut segments: Vec<[(i64, i64); 2]> = tips.into_iter().map(|(c, t)| [centres[c % centres.len()], t]).collect();
        segments.extend(extra);
        (points, segments)
    })
}

/// Normalised as the builder does it, at placement `f`.
fn normalised(input: &IntInput, f: (f64, f64)) -> (Vec<Point>, Vec<[Point; 2]>, Normalised) {
    let (points, segments) = input;
    let fp: Vec<Point> = points.iter().map(|&v| to_f64(v, f)).collect();
    let fs: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|v| to_f64(v, f))).collect();
    let norm = normalise(&fp, &fs, |q| q.scaled(input_scale(&fp, &fs).to_internal).canonical_zero());
    (fp, fs, norm)
}

fn run(input: &IntInput, f: (f64, f64)) -> Result<(), TestCaseError> {
    let (fp, fs, norm) = normalised(input, f);
    let found = sweep_agrees(&norm)?;
    let (conflict, splits) = integer_oracle(&input.0, &input.1);
    prop_assert_eq!(found.is_some(), conflict);
    let checked = check_segments(&fp, &fs);
    prop_assert_eq!(checked.as_ref().err().copied(), found.map(|f| f.0));
    if let Ok(checked) = checked {
        prop_assert_eq!(checked.splits.len(), splits);
    }
    Ok(())
}

/// The same input in another order or another placement: the same
/// verdict, and the same contact point where the order of points is kept.
fn invariance(input: &IntInput, seed: u64) -> Result<(), TestCaseError> {
    let (_, _, norm) = normalised(input, (1.0, 0.0));
    let found = sweep_agrees(&norm)?;
    let (points, segments) = input;
    // Reversed: both lists, and each segment's ends.
    let reversed: IntInput = (points.iter().rev().copied().collect(), segments.iter().rev().map(|&[a, b]| [b, a]).collect());
    // Shuffled, by a seeded Fisher–Yates.
    let mut rng = Rng(seed | 1);
    let mut shuffled = input.clone();
    for k in (1..shuffled.1.len()).rev() {
        shuffled.1.swap(k, (rng.unit() * (k + 1) as f64) as usize % (k + 1));
    }
    for k in (1..shuffled.0.len()).rev() {
        shuffled.0.swap(k, (rng.unit() * (k + 1) as f64) as usize % (k + 1));
    }
    for other in [reversed, shuffled] {
        let (_, _, other_norm) = normalised(&other, (1.0, 0.0));
        let again = sweep_agrees(&other_norm)?;
        prop_assert_eq!(again.is_some(), found.is_some());
        if found.is_none() {
            prop_assert_eq!(sweep(&other_norm).1.len(), sweep(&norm).1.len());
        }
        if let (Some((_, a)), Some((_, b))) = (&found, &again) {
            prop_assert_eq!(a.cmp(b), Ordering::Equal);
        }
    }
    // Mirrored: the same verdict (the leftmost contact is another one).
    let mirrored: IntInput =
        (points.iter().map(|&(x, y)| (-x, y)).collect(), segments.iter().map(|s| s.map(|(x, y)| (-x, y))).collect());
    let (_, _, mirrored_norm) = normalised(&mirrored, (1.0, 0.0));
    prop_assert_eq!(sweep_agrees(&mirrored_norm)?.is_some(), found.is_some());
    if found.is_none() {
        prop_assert_eq!(sweep(&mirrored_norm).1.len(), sweep(&norm).1.len());
    }
    // Scaled by powers of two: every decision is the same, so the same
    // conflict, and the same contact point in input coordinates.
    let input_contact = |f: (f64, f64), found: &Option<(Conflict, ContactPoint)>| {
        let (fp, fs, _) = normalised(input, f);
        match found {
            Some((_, ContactPoint::At(q))) => Some(q.scaled(input_scale(&fp, &fs).to_input)),
            _ => None,
        }
    };
    for k in [-1000, -60, -1, 1, 61, 1000] {
        let f = (2f64.powi(k), 0.0);
        let (_, _, scaled_norm) = normalised(input, f);
        let again = sweep_agrees(&scaled_norm)?;
        prop_assert_eq!(again.as_ref().map(|f| f.0), found.as_ref().map(|f| f.0));
        prop_assert_eq!(sweep(&scaled_norm).1, sweep(&norm).1);
        let expected = input_contact((1.0, 0.0), &found).map(|q| q.scaled(f.0));
        prop_assert_eq!(input_contact(f, &again), expected);
    }
    Ok(())
}

/// Exact placements `(scale, offset)` of the integer inputs, so that
/// the integer oracle stays right: powers of two (and 3) move them to
/// magnitudes where the power-of-two scaling matters; the offsets put
/// them far from the origin, where one ulp of a coordinate is a sizeable
/// part of a grid cell.
fn placement() -> impl Strategy<Value = (f64, f64)> {
    prop::sample::select(vec![
        (1.0, 0.0),
        (3.0, 0.0),
        (2f64.powi(1000), 0.0),
        (2f64.powi(-1000), 0.0),
        (f64::from_bits(1 << 4), 0.0), // 2^-1070, subnormal
        (0.25, 2f64.powi(50)),         // ulp 0.25
        (1.0, -(2f64.powi(52))),       // ulp 0.5 to 1
    ])
}

/// Segments with real coordinates in `[-r, r)`.
fn real_segments(r: f64, count: std::ops::Range<usize>) -> impl Strategy<Value = Vec<[(f64, f64); 2]>> {
    let v = (-r..r, -r..r);
    prop::collection::vec([v.clone(), v], count)
}

proptest! {
    // Fewer cases: each has up to 95 segments, and brute force is
    // quadratic (the other inputs have at most about 20).
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn sweep_agrees_with_brute_force_hubs(input in hub_input(), f in placement()) {
        run(&input, f)?;
    }

    /// A hub reversed, shuffled, mirrored and scaled.
    #[test]
    fn sweep_is_invariant_on_hubs(input in hub_input(), seed in any::<u64>()) {
        invariance(&input, seed)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn sweep_agrees_with_brute_force_small_grid(input in small_grid_input(), f in placement()) {
        run(&input, f)?;
    }

    #[test]
    fn sweep_agrees_with_brute_force_spread(input in spread_input(), f in placement()) {
        run(&input, f)?;
    }

    #[test]
    fn sweep_agrees_with_brute_force_polyline(input in polyline_input(), f in placement()) {
        run(&input, f)?;
    }

    #[test]
    fn sweep_agrees_with_brute_force_stars(input in star_input(), f in placement()) {
        run(&input, f)?;
    }

    /// Reversed, shuffled, mirrored and scaled inputs: the same verdict
    /// and the same leftmost contact point.
    #[test]
    fn sweep_is_invariant(input in prop_oneof![small_grid_input(), star_input(), polyline_input()], seed in any::<u64>()) {
        invariance(&input, seed)?;
    }

    /// Small grids, polylines that retrace themselves and hubs of
    /// collinear spokes, some or all of them ring segments that may share
    /// stretches.
    #[test]
    fn sweep_agrees_with_brute_force_ring_overlaps(
        input in prop_oneof![small_grid_input(), polyline_input(), spread_input()],
        f in placement(),
        ring_bits in prop_oneof![Just(u64::MAX), any::<u64>()],
    ) {
        run_rings(&input, f, ring_bits)?;
    }

    /// Random real coordinates: crossings are common, collinearity not;
    /// the leftmost crossing is compared exactly with the others.
    #[test]
    fn sweep_agrees_with_brute_force_reals(
        segments in real_segments(100.0, 0..40),
    ) {
        let fs: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|(x, y)| p(x, y))).collect();
        let norm = normalise(&[], &fs, |q| q.canonical_zero());
        sweep_agrees(&norm)?;
    }
}

/// Ring segments may share stretches (`Normalised::may_overlap`): with the
/// segments whose bit in `ring_bits` is set marked as a ring's, the sweep
/// still finds the leftmost conflict left (an overlap of two ring segments
/// is none), and without one every split, the ends of every shared stretch
/// among them; `check_segments` agrees.
fn run_rings(input: &IntInput, f: (f64, f64), ring_bits: u64) -> Result<(), TestCaseError> {
    let (fp, fs, mut norm) = normalised(input, f);
    let ring: Vec<bool> = (0..fs.len()).map(|k| ring_bits >> (k % 64) & 1 == 1).collect();
    norm.allow_ring_overlaps(&ring);
    let found = sweep_agrees(&norm)?;
    let checked = super::check_segments(&fp, &fs, &ring, input_scale(&fp, &fs));
    prop_assert_eq!(checked.as_ref().err().copied(), found.map(|f| f.0));
    Ok(())
}

#[test]
fn ring_segments_sharing_stretches_are_split_at_their_ends() {
    // the bottom edge of a square run over from 1 to 3 by a spike, and a
    // third ring segment inside that stretch: every end inside another
    let segments = [s(0., 0., 4., 0.), s(3., 0., 1., 0.), s(1.5, 0., 2.5, 0.), s(0., 0., 0., 4.)];
    let ring = [true; 4];
    let checked = super::check_segments(&[], &segments, &ring, input_scale(&[], &segments)).unwrap();
    let got: Vec<(usize, Vertex)> = checked.splits.iter().map(|c| (checked.segments[c.segment].0, c.at)).collect();
    assert_eq!(got, vec![(0, end(1, 1)), (0, end(2, 0)), (0, end(2, 1)), (0, end(1, 0)), (1, end(2, 0)), (1, end(2, 1))]);
    // an obstacle along a ring segment is refused, as two obstacles are
    let obstacle = [true, true, false, true];
    let conflict = super::check_segments(&[], &segments, &obstacle, input_scale(&[], &segments)).unwrap_err();
    // (0 and 1 both overlap it from the same point: the sweep meets 1 there)
    assert!(matches!(conflict, Conflict::SegmentsOverlap { second: 2, .. }), "{conflict:?}");
    assert!(check(&segments).is_err());
}

// ---- scale ----

/// A tiny xorshift generator: the test needs no other dependency.
struct Rng(u64);
impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// One short segment in each cell of a 317 × 317 lattice (never
/// crossing), plus a point in each cell away from its segment.
fn jittered_segments(n_side: usize, rng: &mut Rng) -> (Vec<Point>, Vec<[Point; 2]>) {
    let mut segments = Vec::with_capacity(n_side * n_side);
    let mut points = Vec::new();
    for i in 0..n_side {
        for j in 0..n_side {
            let (x, y) = (i as f64, j as f64);
            let mut corner = || p(x + 0.05 + 0.9 * rng.unit(), y + 0.05 + 0.45 * rng.unit());
            segments.push([corner(), corner()]);
            if (i + j) % 10 == 0 {
                points.push(p(x + 0.05 + 0.9 * rng.unit(), y + 0.55 + 0.4 * rng.unit()));
            }
        }
    }
    (points, segments)
}

#[test]
fn scale_100k_segments() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (points, segments) = jittered_segments(317, &mut rng);
    let start = std::time::Instant::now();
    let out = check_segments(&points, &segments).unwrap();
    let jittered = start.elapsed();
    assert_eq!(out.segments.len(), segments.len());

    // An open polyline through one corner per lattice cell, column by
    // column, up one column and down the next: consecutive cells are
    // neighbours, so it never crosses itself, and every inner vertex is
    // shared by two segments.
    let side = 317;
    let corner = |i: usize, j: usize| segments[i * side + j][0];
    let snake_order = (0..side).flat_map(|i| (0..side).map(move |j| (i, if i % 2 == 0 { j } else { side - 1 - j })));
    let vertices: Vec<Point> = snake_order.map(|(i, j)| corner(i, j)).collect();
    let snake: Vec<[Point; 2]> = vertices.windows(2).map(|w| [w[0], w[1]]).collect();
    let start = std::time::Instant::now();
    let out = check(&snake).unwrap();
    let polyline = start.elapsed();
    assert_eq!(out.segments.len(), snake.len());
    println!(
        "input_check: {} jittered segments + {} points checked in {:?}; {}-edge polyline in {:?}",
        segments.len(),
        points.len(),
        jittered,
        snake.len(),
        polyline,
    );

    // The same segments with one crossing added at the end: found.
    let mut bad = segments.clone();
    let last = segments[segments.len() - 1];
    bad.push([p(last[0].x, last[1].y), p(last[1].x, last[0].y)]);
    if let Err(c) = check(&bad) {
        assert!(matches!(c, Conflict::SegmentsCross { second, .. } if second == segments.len()));
    } else {
        panic!("added crossing missed");
    }
}
