//! Offsets of diagrams with circular arcs (issue 32), against a reference
//! nobody tuned for: the same input with every arc replaced by 256 chords,
//! offset by the library's segment offsets. The chords converge to the
//! arcs, so the areas agree to about 1e-5 relative and the loops lie within
//! about the chords' sagitta of each other (Hausdorff distance between
//! their polylines). Besides: every piece ends at the offset's distance
//! from its site, the pieces along arcs are concentric with them at radius
//! `R + d` (convex side) or `R - d` (concave side), loops close, and every
//! point of every polyline is at the distance from the nearest site.
//!
//! Families (generators shared with `arcs.rs`, `common/arc_inputs.rs`): random arcs, segments and
//! points in the cells of a grid, rounded rectangles nested and apart,
//! slots (with a point at an arc's centre), filleted polygons; each at
//! several distances, including ones where loops merge.

mod common;

use common::arc_inputs::{add_pieces, distance, filleted_polygon, mapped, random_cells, rounded_rectangle, variants, Piece};
use common::curved_rings::{
    check_domain_offsets_of, check_medial_axis_of, check_pieces, circle_ring, densified_ring, directed_hausdorff, filleted_ring,
    piece_tolerance, reverse_ring, rounded_ring, slot_ring, tangent_joins, with_straight_vertices, Ring, Seen, CHORDS,
};
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Diagram, Offset, Point, Site};

fn build(pieces: &[Piece]) -> Diagram {
    let mut b = Builder::new();
    add_pieces(&mut b, pieces);
    b.build().unwrap_or_else(|e| panic!("{e}: {pieces:?}"))
}

/// The input with every arc replaced by `CHORDS` chords (its ends exact).
fn densified(pieces: &[Piece]) -> Diagram {
    let mut b = Builder::new();
    for piece in pieces {
        match *piece {
            Piece::Point(p) => drop(b.add_point(p).unwrap()),
            Piece::Segment(p, q) => drop(b.add_segment([p, q]).unwrap()),
            Piece::Arc(arc) => {
                let points: Vec<Point> = (0..=CHORDS).map(|k| arc.point_at(k as f64 / CHORDS as f64)).collect();
                for w in points.windows(2) {
                    b.add_segment([w[0], w[1]]).unwrap();
                }
            }
        }
    }
    b.build().unwrap_or_else(|e| panic!("densified: {e}: {pieces:?}"))
}

/// Checks the offset of `pieces` at `d` (see the module doc); `size` is
/// the input's extent.
fn check(name: &str, pieces: &[Piece], d: &Diagram, reference: &Diagram, distance_d: f64, size: f64, seen: &mut Seen) {
    let what = format!("{name} at {distance_d}");
    let offset: Offset = d.offset(distance_d).unwrap_or_else(|e| panic!("{what}: {e}"));
    let want: Offset = reference.offset(distance_d).unwrap();
    let sites: Vec<Site> = d.site_ids().map(|s| d.site(s).unwrap()).collect();
    check_pieces(&what, d, &offset, distance_d, 1e-9 * (size + distance_d), seen);
    // every point of every polyline at the distance from the nearest site
    let polylines = offset.polylines(1e-5 * size).unwrap();
    for p in polylines.iter().flatten() {
        let (k, nearest) =
            sites.iter().map(|s| distance(s, *p)).enumerate().fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        let piece = offset.loops.iter().flat_map(|l| &l.pieces).find(|q| q.polyline(1e-5 * size).unwrap().contains(p));
        assert!(
            (nearest - distance_d).abs() <= 2e-5 * size,
            "{what}: point {p:?} at {nearest} from the nearest site {:?}, on {piece:?} of {:?}",
            sites[k],
            piece.map(|q| sites[q.site().index()])
        );
    }
    // against the chords
    assert_eq!(offset.loops.len(), want.loops.len(), "{what}: loops, against the chords'");
    let (area, reference_area) = (offset.area(), want.area());
    let relative = (area - reference_area).abs() / reference_area.abs();
    assert!(relative <= 1e-4, "{what}: area {area} against the chords' {reference_area} ({relative:e})");
    let theirs = want.polylines(1e-5 * size).unwrap();
    let hausdorff = directed_hausdorff(&polylines, &theirs).max(directed_hausdorff(&theirs, &polylines));
    assert!(hausdorff <= 1e-3 * size, "{what}: Hausdorff distance {hausdorff} to the chords' loops");
    seen.offsets += 1;
    seen.worst_area = seen.worst_area.max(relative);
    seen.worst_hausdorff = seen.worst_hausdorff.max(hausdorff / size);
    let _ = pieces;
}

/// Checks `pieces` at each of `distances`.
fn check_all(name: &str, pieces: &[Piece], distances: &[f64], size: f64) -> Seen {
    let d = build(pieces);
    let reference = densified(pieces);
    let mut seen = Seen::default();
    for &r in distances {
        check(name, pieces, &d, &reference, r, size, &mut seen);
    }
    eprintln!("{name}: {seen:?}");
    seen
}

/// A slot: two sides and two half circles.
fn slot() -> Vec<Piece> {
    let p = Point::new;
    vec![
        Piece::Segment(p(0.0, 0.0), p(4.0, 0.0)),
        Piece::Arc(CircularArc::from_bulge(p(4.0, 0.0), p(4.0, 2.0), 1.0).unwrap()),
        Piece::Segment(p(4.0, 2.0), p(0.0, 2.0)),
        Piece::Arc(CircularArc::from_bulge(p(0.0, 2.0), p(0.0, 0.0), 1.0).unwrap()),
    ]
}

#[test]
fn slot_offsets_are_stadiums_inside_and_out() {
    // outside a stadium of radius 1 + d; inside, the concave sides give
    // the stadium of radius 1 - d (the region within d of the outline is
    // the ring between them)
    let seen = check_all("slot", &slot(), &[0.25, 0.5, 1.0, 3.0], 6.0);
    assert!(seen.concave_pieces > 0 && seen.arc_pieces > seen.concave_pieces, "{seen:?}");
    let d = build(&slot());
    let pi = std::f64::consts::PI;
    for r in [0.25, 0.5, 0.75] {
        let outer = 4.0 * 2.0 * (1.0 + r) + pi * (1.0 + r) * (1.0 + r);
        let inner = 4.0 * 2.0 * (1.0 - r) + pi * (1.0 - r) * (1.0 - r);
        let area = d.offset(r).unwrap().area();
        assert!((area - (outer - inner)).abs() < 1e-9 * outer, "slot at {r}: {area} against {}", outer - inner);
    }
    // at 1 and beyond the inside is filled
    let r = 1.5;
    let area = d.offset(r).unwrap().area();
    let outer = 4.0 * 2.0 * (1.0 + r) + pi * (1.0 + r) * (1.0 + r);
    assert!((area - outer).abs() < 1e-9 * outer, "slot at {r}: {area} against {outer}");
}

#[test]
fn a_point_at_an_arc_centre() {
    let mut pieces = slot();
    pieces.push(Piece::Point(Point::new(4.0, 1.0)));
    check_all("slot with its centre", &pieces, &[0.2, 0.5 - 1e-3, 0.5 + 1e-3, 0.7, 2.0], 6.0);
}

#[test]
fn rounded_rectangles_nested_apart_and_merging() {
    let mut pieces = rounded_rectangle(0.0, 0.0, 10.0, 6.0, 1.5);
    pieces.extend(rounded_rectangle(2.0, 2.0, 3.0, 2.0, 0.5));
    pieces.extend(rounded_rectangle(12.0, 0.5, 4.0, 4.0, 2.0));
    pieces.push(Piece::Point(Point::new(7.5, 3.0)));
    // the gap between the first and the third is 2: their outer loops merge past 1
    let seen = check_all("rounded rectangles", &pieces, &[0.1, 0.4, 0.9, 1.1, 1.6, 2.5, 5.0], 16.0);
    assert!(seen.concave_pieces > 0, "{seen:?}");
}

#[test]
fn random_arcs_segments_and_points_in_cells() {
    let mut total = Seen::default();
    for seed in 0..10 {
        let side = 2 + (seed as usize % 3);
        let pieces = random_cells(seed, side);
        let seen = check_all(&format!("cells seed {seed}"), &pieces, &[0.02, 0.07, 0.15, 0.3, 0.6], side as f64);
        total.offsets += seen.offsets;
        total.arc_pieces += seen.arc_pieces;
        total.concave_pieces += seen.concave_pieces;
        total.worst_area = total.worst_area.max(seen.worst_area);
        total.worst_hausdorff = total.worst_hausdorff.max(seen.worst_hausdorff);
    }
    eprintln!("random cells: {total:?}");
    assert!(total.arc_pieces > 100 && total.concave_pieces > 10, "{total:?}");
}

#[test]
fn filleted_polygons() {
    let mut rng = SplitMix64(5);
    for k in 0..6 {
        let n = 3 + k;
        let mut pieces = filleted_polygon(&mut rng, 0.0, 0.0, n, 0.3);
        pieces.extend(filleted_polygon(&mut rng, 2.5, 0.3, n + 1, 0.5));
        check_all(&format!("filleted {n}"), &pieces, &[0.05, 0.2, 0.3, 0.6, 1.5], 4.0);
    }
}

/// A point inside a nearly closed arc, off its centre: the bisector of the
/// point and the arc's concave side is an ellipse whose clearance peaks
/// inside the edge, opposite the point (an empty circle touching both at
/// the ends of a diameter), with no vertex there. Past the peak the hole
/// around it closes; just below it the hole is a small loop crossing that
/// one edge twice. (Near the peak, the chords' peak differs from the arc's
/// by their sagitta, about 1e-4 here: the comparison with them stays
/// 0.01 away.)
#[test]
fn a_point_inside_a_nearly_closed_arc() {
    let at = |deg: f64| Point::new(2.0 * deg.to_radians().cos(), 2.0 * deg.to_radians().sin());
    // the gap around 30°, the point toward it: the peak is toward 210°
    let arc = CircularArc::through(at(45.0), at(210.0), at(15.0)).unwrap();
    let p = Point::new(0.5 * 30f64.to_radians().cos(), 0.5 * 30f64.to_radians().sin());
    let pieces = [Piece::Arc(arc), Piece::Point(p)];
    let peak = (2.0 + 0.5) / 2.0;
    let seen = check_all("point in an arc", &pieces, &[0.3, 0.8, 1.1, peak - 0.03, peak - 0.01, peak + 0.01, 3.0], 4.0);
    assert!(seen.concave_pieces > 0, "{seen:?}");
    // just below the peak: a hole of two pieces (along the arc and around
    // the point) about the peak
    let d = build(&pieces);
    let below = d.offset(peak - 1e-4).unwrap();
    let holes: Vec<_> = below.loops.iter().filter(|l| l.hole).collect();
    assert!(holes.iter().any(|l| l.pieces.len() == 2), "{below:?}");
    let above = d.offset(peak + 1e-4).unwrap();
    assert!(above.loops.len() < below.loops.len(), "{above:?}");
}

/// LibreCAD's tp3.dxf minimised: a half circle continued by a segment
/// 3.5e-15 rad off its tangent, beside a line and two pieces of a small
/// circle. The edge between the half circle and the segment runs down the
/// join's normal to a vertex 1.1e15 away; along it the offsets' parameter
/// was linear in the distance from the centre, which `t`'s ulp near the
/// join resolved to 0.125, and the offset 1 from the join ended 0.75 from
/// it (refused as a wrong decision). In every variant, against the chords.
#[test]
fn a_join_an_ulp_off_tangent_whose_edge_runs_1e15_out() {
    let p = Point::new;
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let pieces = vec![
        arc(p(23.0, 0.0), p(23.0, -10.0), 1.0),
        Piece::Segment(p(23.0, -10.0), p(25.0, -10.000000000000007)),
        Piece::Segment(p(5.0, -10.000000000000007), p(15.317225141903236, -5.31035220822605)),
        arc(p(16.75, -5.0), p(15.25, -5.0), 1.0),
        arc(p(15.25, -5.0), p(15.317225141903236, -5.31035220822605), 0.10706315386359738),
    ];
    // the far vertex is there (else the test would not test it)
    let far = build(&pieces).vertices().map(|v| v.clearance).fold(0.0f64, f64::max);
    assert!(far > 1e14, "no far vertex: {far}");
    for (way, input, scale) in variants(&pieces, 5) {
        check_all(&format!("join an ulp off tangent, {way}"), &input, &[0.5 * scale, scale, 2.0 * scale], 30.0 * scale);
    }
    // the join exactly tangent (a straight join: no far vertex)
    let mut tangent = pieces.clone();
    tangent[1] = Piece::Segment(p(23.0, -10.0), p(25.0, -10.0));
    check_all("join exactly tangent", &tangent, &[0.5, 1.0, 2.0], 30.0);
    // a thousand and a million from the origin (the join is then another
    // rounding of a tangent one)
    for shift in [1e3, 1e6] {
        let input = mapped(&pieces, &|q: Point| p(q.x + shift, q.y - shift), false);
        check_all(&format!("join an ulp off tangent, {shift} out"), &input, &[0.5, 1.0, 2.0], 30.0);
    }
}

// ---- domains bounded by rings of segments and arcs ----------------------

/// The diagram of the polygon of `rings`, and of its 256-chord version.
fn domain_and_reference(rings: &[Ring]) -> (Diagram, Diagram) {
    let mut b = Builder::new();
    b.add_bulged_polygon(rings).unwrap();
    let d = b.build().unwrap_or_else(|e| panic!("{e}: {rings:?}"));
    let mut r = Builder::new();
    r.add_polygon(&rings.iter().map(densified_ring).collect::<Vec<_>>()).unwrap();
    (d, r.build().unwrap())
}

/// Offsets of the curved domain of `rings` against its chords'
/// (`check_domain_offsets_of`).
fn check_domain_offsets(name: &str, rings: &[Ring], distances: &[f64], size: f64) -> Seen {
    let (d, reference) = domain_and_reference(rings);
    check_domain_offsets_of(name, (&d, &reference), rings, distances, size)
}

/// The medial axis of the curved domain of `rings` (`check_medial_axis_of`).
fn check_medial_axis(name: &str, rings: &[Ring], size: f64) -> usize {
    let (d, reference) = domain_and_reference(rings);
    check_medial_axis_of(name, (&d, &reference), &tangent_joins(rings), size)
}

/// The polygon of `rings` with the segments `lines` as obstacles.
fn domain_with_lines(rings: &[Ring], lines: &[[Point; 2]]) -> Result<Diagram, segvoronoi::Error> {
    let mut b = Builder::new();
    b.add_bulged_polygon(rings).unwrap();
    for &s in lines {
        b.add_segment(s).unwrap();
    }
    b.build()
}

#[test]
fn bulged_rings_locate_points_even_odd() {
    let rings =
        [rounded_ring(0.0, 0.0, 10.0, 6.0, 1.5, false), circle_ring(3.0, 3.0, 1.0), rounded_ring(5.0, 1.0, 4.0, 3.0, 1.0, true)];
    let mut b = Builder::new();
    b.add_bulged_polygon(&rings).unwrap();
    let d = b.build().unwrap();
    use segvoronoi::Location::*;
    let p = Point::new;
    for (q, want) in [
        (p(0.3, 0.3), Outside), // cut off by a corner arc
        (p(0.8, 0.8), Inside),
        (p(3.0, 3.0), Outside), // in the round hole, on its chord
        (p(3.0, 3.9), Outside),
        (p(3.0, 4.1), Inside),
        (p(2.0, 3.0), Boundary),
        (p(7.0, 2.5), Outside), // in the rounded hole
        (p(5.1, 1.1), Inside),  // in its corner, outside its arc
        (p(11.0, 3.0), Outside),
    ] {
        assert_eq!(d.locate_point(q), Some(want), "{q:?}");
    }
}

#[test]
fn rounded_rectangles_with_holes_offsets_against_chords() {
    let rings =
        [rounded_ring(0.0, 0.0, 10.0, 6.0, 1.5, false), circle_ring(3.0, 3.0, 1.0), rounded_ring(5.0, 1.0, 4.0, 3.0, 1.0, true)];
    let seen = check_domain_offsets("rounded with holes", &rings, &[-0.1, -0.3, -0.45, -0.6, -1.2, 0.2, 0.5, 1.1, 3.0], 10.0);
    assert!(seen.arc_pieces > 20, "{seen:?}");
    // the same rings the other way round bound the same domain
    let reversed: Vec<Ring> = rings.iter().map(reverse_ring).collect();
    check_domain_offsets("rounded with holes, reversed", &reversed, &[-0.3, 0.5], 10.0);
}

#[test]
fn slots_and_filleted_polygons_offsets_against_chords() {
    check_domain_offsets("slot", &[slot_ring(0.0, 0.0, 4.0, 1.0)], &[-0.2, -0.5, -0.9, 0.3, 2.0], 6.0);
    let mut rng = SplitMix64(11);
    for n in [3, 5, 8] {
        let rings = [filleted_ring(&mut rng, 0.0, 0.0, n, 0.3)];
        check_domain_offsets(&format!("filleted {n}"), &rings, &[-0.05, -0.2, -0.35, 0.1, 0.6], 2.0);
    }
}

#[test]
fn medial_axis_of_curved_domains() {
    let rings =
        [rounded_ring(0.0, 0.0, 10.0, 6.0, 1.5, false), circle_ring(3.0, 3.0, 1.0), rounded_ring(5.0, 1.0, 4.0, 3.0, 1.0, true)];
    assert!(check_medial_axis("rounded with holes", &rings, 10.0) > 100);
    check_medial_axis("slot", &[slot_ring(0.0, 0.0, 4.0, 1.0)], 6.0);
    check_medial_axis("rounded rectangle", &[rounded_ring(0.0, 0.0, 6.0, 4.0, 1.0, false)], 6.0);
    let mut rng = SplitMix64(12);
    for n in [3, 4, 6] {
        check_medial_axis(&format!("filleted {n}"), &[filleted_ring(&mut rng, 0.0, 0.0, n, 0.3)], 2.0);
    }
}

#[test]
fn bad_bulged_rings_are_refused_naming_the_vertex() {
    use segvoronoi::ErrorKind;
    let p = |x: f64, y: f64| Point::new(x, y);
    let cases: [(Ring, ErrorKind, Vec<usize>); 4] = [
        (vec![(p(0.0, 0.0), 0.0), (p(1.0, f64::INFINITY), 0.0), (p(1.0, 1.0), 0.0)], ErrorKind::InvalidCoordinate, vec![1, 1, 1]),
        (vec![(p(0.0, 0.0), 0.0), (p(1.0, 0.0), f64::NAN), (p(1.0, 1.0), 0.0)], ErrorKind::InvalidCoordinate, vec![1, 1, 1]),
        (vec![(p(0.0, 0.0), 0.0), (p(1.0, 0.0), 0.0), (p(0.0, 0.0), 0.0)], ErrorKind::InvalidPolygon, vec![1, 1]),
        (vec![(p(0.0, 0.0), 0.0), (p(1e10, 0.0), 0.0), (p(1e10, 1e10), 1e300)], ErrorKind::InvalidArc, vec![1, 1, 2]),
    ];
    for (bad, kind, indices) in cases {
        let mut b = Builder::new();
        b.add_bulged_polygon(&[slot_ring(0.0, 0.0, 4.0, 1.0)]).unwrap();
        let before = (b.segment_count(), b.arc_count());
        let e = b.add_bulged_polygon(&[circle_ring(10.0, 0.0, 1.0), bad.clone()]).unwrap_err();
        assert_eq!((e.kind(), e.indices()), (kind, &indices[..]), "{bad:?}: {e}");
        assert!(e.message().contains("polygon 1, ring 1"), "{e}");
        assert_eq!((b.segment_count(), b.arc_count()), before, "{bad:?}: the builder changed");
        b.build().unwrap();
    }
    // two vertices close a ring with an arc (a half disc), not without
    let mut b = Builder::new();
    b.add_bulged_polygon(&[vec![(p(0.0, 0.0), 1.0), (p(2.0, 0.0), 0.0)]]).unwrap();
    let d = b.build().unwrap();
    assert_eq!(d.locate_point(p(1.0, -0.5)), Some(segvoronoi::Location::Inside));
    assert_eq!(d.locate_point(p(1.0, 0.5)), Some(segvoronoi::Location::Outside));
    // splitting a bulged ring that meets nothing changes nothing
    let mut b = Builder::new();
    b.add_bulged_polygon(&[slot_ring(0.0, 0.0, 4.0, 1.0)]).unwrap();
    let (plain, split) = (b.build().unwrap(), b.split_crossings(true).build().unwrap());
    assert_eq!(split.stats().crossings + split.stats().touchings, 0);
    assert_eq!(plain.offset(-0.3).unwrap().area(), split.offset(-0.3).unwrap().area());
}

/// Scaled by powers of two, mirrored and walked the other way, a curved
/// domain's offsets scale with it (areas by the square, exactly up to
/// rounding), and a plain polygon with arc obstacles inside is a domain too.
#[test]
fn curved_domains_scaled_mirrored_and_with_arc_obstacles() {
    let base = [rounded_ring(0.0, 0.0, 10.0, 6.0, 1.5, false), circle_ring(3.0, 3.0, 1.0)];
    let area = |rings: &[Ring], r: f64| {
        let mut b = Builder::new();
        b.add_bulged_polygon(rings).unwrap();
        b.build().unwrap().offset(r).unwrap().area()
    };
    let want = [area(&base, -0.5), area(&base, 0.5)];
    for k in [-20i32, -3, 5, 20] {
        let f = 2f64.powi(k);
        for mirrored in [false, true] {
            let map: Vec<Ring> = base
                .iter()
                .map(|ring| {
                    let ring: Ring =
                        ring.iter().map(|&(q, b)| (Point::new(if mirrored { -q.x } else { q.x } * f, q.y * f), b)).collect();
                    // a mirror turns every arc the other way round
                    if mirrored {
                        ring.iter().map(|&(q, b)| (q, -b)).collect()
                    } else {
                        ring
                    }
                })
                .collect();
            for (j, r) in [-0.5, 0.5].into_iter().enumerate() {
                let got = area(&map, r * f) / (f * f);
                assert!((got - want[j]).abs() <= 1e-9 * want[j], "2^{k} mirrored {mirrored} at {r}: {got} against {}", want[j]);
            }
        }
    }
    // a plain square domain with arc obstacles inside (a slot's outline)
    let mut b = Builder::new();
    b.add_polygon(&[vec![[-2.0, -2.0], [8.0, -2.0], [8.0, 4.0], [-2.0, 4.0]]]).unwrap();
    b.add_bulged_polyline(&[([0.0, 0.0], 0.0), ([4.0, 0.0], 1.0), ([4.0, 2.0], 0.0), ([0.0, 2.0], 1.0)], true).unwrap();
    let d = b.build().unwrap();
    // the square shrunk by r less the band within r of the slot's outline
    // (an obstacle: the slot's inside is in the domain), the stadium of
    // radius 1 + r less that of radius 1 - r; past r = 0.5 the band
    // crosses the shrunk square's left side, which cuts a cap of its circle
    let pi = std::f64::consts::PI;
    let stadium = |radius: f64| 4.0 * 2.0 * radius + pi * radius * radius;
    // (at 0.5 the band touches the shrunk square's side at one point: the
    // region pinches there, and the loops split)
    for r in [0.4f64, 0.5, 0.6] {
        let outer = 1.0 + r;
        let beyond = (outer - (2.0 - r)).max(0.0); // the cap's height past the side
        let cap = outer * outer * ((outer - beyond) / outer).acos()
            - (outer - beyond) * (2.0 * outer * beyond - beyond * beyond).sqrt();
        let want = (10.0 - 2.0 * r) * (6.0 - 2.0 * r) - (stadium(outer) - cap) + stadium(1.0 - r);
        let shrunk = d.offset(-r).unwrap();
        assert!((shrunk.area() - want).abs() < 1e-9 * want, "at {r}: {} against {want}", shrunk.area());
    }
}

/// A bulged ring cut at an input point inside one of its segments is the
/// same ring over the pieces: the same domain and offsets.
#[test]
fn a_bulged_ring_cut_at_a_vertex_inside_a_segment() {
    let area = |cut: bool, r: f64| {
        let mut b = Builder::new();
        b.add_bulged_polygon(&[slot_ring(0.0, 0.0, 4.0, 1.0)]).unwrap();
        if cut {
            b.add_point([2.0, 0.0]).unwrap();
        }
        let d = b.build().unwrap();
        assert_eq!(d.stats().split_at_vertices, usize::from(cut));
        assert_eq!(d.locate_point(Point::new(2.0, 1.0)), Some(segvoronoi::Location::Inside));
        d.offset(r).unwrap().area()
    };
    for r in [-0.3, 0.3] {
        let (whole, cut) = (area(false, r), area(true, r));
        assert!((whole - cut).abs() < 1e-9 * whole, "at {r}: {whole} against {cut}");
    }
}

/// Random curved domains: a filleted polygon with round and filleted holes
/// (each in its own cell of a grid inside it), both orientations, at random
/// distances of both signs, against the chords, and their medial axes (as
/// `medial_axis_of_curved_domains`). A build the arcs' vertex
/// check refuses (`Internal`, documented in guarantees.md) is counted, not
/// failed; everything built must offset right.
#[test]
fn random_curved_domains_against_chords() {
    let mut rng = SplitMix64(2026);
    let (mut built, mut refused) = (0, 0);
    for case in 0..16 {
        let n = 5 + (rng.next_u64() % 6) as usize;
        // the outer ring: a filleted polygon of radius 4 (corners on a circle)
        let outer: Ring =
            filleted_ring(&mut rng, 0.0, 0.0, n, 0.3).iter().map(|&(p, b)| (Point::new(4.0 * p.x, 4.0 * p.y), b)).collect();
        let mut rings = vec![if rng.unit() < 0.5 { outer.clone() } else { reverse_ring(&outer) }];
        // holes in the cells of a 2 × 2 grid within the inscribed square
        for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            if rng.unit() < 0.3 {
                continue;
            }
            let (cx, cy) = (-1.2 + 2.4 * i as f64, -1.2 + 2.4 * j as f64);
            let hole = if rng.unit() < 0.5 {
                circle_ring(cx, cy, 0.3 + 0.5 * rng.unit())
            } else {
                let m = 3 + (rng.next_u64() % 4) as usize;
                filleted_ring(&mut rng, cx, cy, m, 0.3)
                    .iter()
                    .map(|&(p, b)| (Point::new(cx + 0.8 * (p.x - cx), cy + 0.8 * (p.y - cy)), b))
                    .collect()
            };
            rings.push(if rng.unit() < 0.5 { hole.clone() } else { reverse_ring(&hole) });
        }
        let mut b = Builder::new();
        b.add_bulged_polygon(&rings).unwrap();
        match b.build() {
            Ok(_) => built += 1,
            Err(e) if e.kind() == segvoronoi::ErrorKind::Internal => {
                refused += 1;
                continue;
            }
            Err(e) => panic!("case {case}: {e}"),
        }
        let distances: Vec<f64> = (0..4).map(|k| if k % 2 == 0 { -1.0 } else { 1.0 } * (0.05 + 1.2 * rng.unit())).collect();
        check_domain_offsets(&format!("random domain {case}"), &rings, &distances, 8.0);
        check_medial_axis(&format!("random domain {case}"), &rings, 8.0);
    }
    eprintln!("random curved domains: {built} built, {refused} refused by the arcs' vertex check");
    assert!(built >= 12, "{built} built, {refused} refused");
}

/// Holes bounded by shallow arcs, whose circles reach far beyond the shell
/// (a letter's counter as biarcs: radius 585 for a hole 240 wide). The
/// shell's box held the hole's circles, not the hole: the hole counted as
/// outside its shell and every cell it touches was located on the wrong
/// side (offsets as open loops of negative area, the inscribed circle a
/// third of its size). Minimised from DejaVu Sans' B as biarcs; then a
/// family of such holes, both ways round, in shells of both kinds.
#[test]
fn holes_of_shallow_arcs_inside_their_shell() {
    let p = Point::new;
    let letter_b = vec![
        vec![(p(201.0, 1493.0), 0.0), (p(1260.0, 418.0), 0.0), (p(201.0, 0.0), 0.0)],
        vec![
            (p(968.5, 646.5), 0.10895931823946167),
            (p(882.303761736809, 692.0082498286635), 0.06727698425695114),
            (p(727.0, 713.0), 0.0),
        ],
    ];
    check_domain_offsets("letter B's counter", &letter_b, &[-20.0, -5.0, 5.0, 40.0], 1500.0);
    check_medial_axis("letter B's counter", &letter_b, 1500.0);
    let mut rng = SplitMix64(585);
    for case in 0..12 {
        let shell = if case % 2 == 0 {
            rounded_ring(0.0, 0.0, 12.0, 8.0, 1.5, rng.unit() < 0.5)
        } else {
            let square = vec![(p(0.0, 0.0), 0.0), (p(12.0, 0.0), 0.0), (p(12.0, 8.0), 0.0), (p(0.0, 8.0), 0.0)];
            if rng.unit() < 0.5 {
                square
            } else {
                reverse_ring(&square)
            }
        };
        let mut rings = vec![shell];
        // in each of three cells, a lens or a D of arcs bulging by 0.02 to 0.15
        for cell in 0..3 {
            let (x, y) = (1.0 + 3.6 * cell as f64 + 0.5 * rng.unit(), 2.0 + 2.0 * rng.unit());
            let (w, h) = (1.8 + 0.8 * rng.unit(), 1.0 + 1.2 * rng.unit());
            let shallow = |rng: &mut SplitMix64| 0.02 + 0.13 * rng.unit();
            let hole = if rng.unit() < 0.5 {
                vec![(p(x, y), shallow(&mut rng)), (p(x + w, y + 0.3 * h), shallow(&mut rng)), (p(x + 0.4 * w, y + h), 0.0)]
            } else {
                vec![(p(x, y), -shallow(&mut rng)), (p(x + w, y), shallow(&mut rng)), (p(x + w, y + h), 0.0), (p(x, y + h), 0.0)]
            };
            rings.push(if rng.unit() < 0.5 { hole.clone() } else { reverse_ring(&hole) });
        }
        let distances: Vec<f64> = (0..4).map(|k| if k % 2 == 0 { -1.0 } else { 1.0 } * (0.05 + 0.6 * rng.unit())).collect();
        check_domain_offsets(&format!("shallow holes {case}"), &rings, &distances, 12.0);
        check_medial_axis(&format!("shallow holes {case}"), &rings, 12.0);
    }
}

/// Two arcs continuing each other along one tangent at a corner `J` (a
/// quadratic of a letter as a biarc, then the next): every point on the
/// normal at `J` is as far from `J` as from both circles, so the vertex of
/// the two arcs and `J` solved as any other was one point of that line, as
/// good as another — far out (a vertex with nearer sites: a wrong diagram)
/// or refused. It is the corner itself, of radius zero. Minimised from
/// DejaVu Sans' @ (refused) and G (wrong: a vertex 1008 out with nearer
/// sites); then rings with two such joins, arcs of unequal radii level with
/// their common rightmost point, both ways round (these the old solver
/// happened to answer; the letters are in python/tests/test_curved_fonts.py).
#[test]
fn arcs_continuing_each_other_along_a_tangent() {
    let p = Point::new;
    let at_sign = vec![vec![
        (p(762.0, 537.0), 0.0),
        (p(1271.3575857432168, 402.6537842896344), 0.07637727960948802),
        (p(1292.0, 537.0), 0.07840030666039141),
        (p(1271.145955129038, 669.1797331733893), 0.10149140361213423),
    ]];
    check_domain_offsets("the @'s tangent arcs", &at_sign, &[-20.0, -5.0, 5.0, 40.0], 1500.0);
    check_medial_axis("the @'s tangent arcs", &at_sign, 1500.0);
    let letter_g = vec![vec![
        (p(889.0, 614.0), 0.0),
        (p(889.0, 780.0), 0.0),
        (p(1296.8125388533142, 66.60631988944365), 0.0),
        (p(312.5, 175.5), 0.0),
        (p(312.5, 1315.5), 0.0),
        (p(370.29754257493084, 1031.7864417833287), 0.07334724269384839),
        (p(328.0, 745.0), 0.07349990352093251),
        (p(370.2418884493109, 459.19222479276993), 0.11009676178142473),
    ]];
    check_domain_offsets("the G's tangent arcs", &letter_g, &[-20.0, -5.0, 5.0, 40.0], 1500.0);
    check_medial_axis("the G's tangent arcs", &letter_g, 1500.0);
    // the same shape turned and scaled: a left edge closing two arcs
    // that meet at their rightmost point `J`, both centres level with it
    // (radii r1 below, r2 above, unequal: a biarc of a letter's bowl), and
    // such joins at several points of one ring
    let mut rng = SplitMix64(1292);
    for case in 0..12 {
        let mut ring: Ring = Vec::new();
        let (x, y) = (10.0 * rng.unit(), 10.0 * rng.unit());
        let mut left = x - 6.0;
        for bowl in 0..2 {
            let y = y + 5.0 * bowl as f64;
            let (r1, r2) = (1.0 + 2.0 * rng.unit(), 1.0 + 2.0 * rng.unit());
            let (phi1, phi2) = (0.3 + 1.0 * rng.unit(), 0.3 + 1.0 * rng.unit());
            // below: from the centre (x − r1, y) at angle −φ1 up to J = (x, y)
            let start = p(x - r1 + r1 * phi1.cos(), y - r1 * phi1.sin());
            let end = p(x - r2 + r2 * phi2.cos(), y + r2 * phi2.sin());
            ring.push((start, (phi1 / 4.0).tan()));
            ring.push((p(x, y), (phi2 / 4.0).tan()));
            ring.push((end, 0.0));
            left = left.min(start.x.min(end.x) - 1.0);
        }
        let (top, bottom) = (ring[5].0.y + 1.0, ring[0].0.y - 1.0);
        ring.push((p(left, top), 0.0));
        ring.push((p(left, bottom), 0.0));
        let rings = vec![if case % 2 == 0 { ring.clone() } else { reverse_ring(&ring) }];
        let distances: Vec<f64> = (0..4).map(|k| if k % 2 == 0 { -1.0 } else { 1.0 } * (0.05 + 1.5 * rng.unit())).collect();
        check_domain_offsets(&format!("tangent arcs {case}"), &rings, &distances, 20.0);
        check_medial_axis(&format!("tangent arcs {case}"), &rings, 20.0);
    }
}

/// A segment bridging two rings from corner to corner (a wall across an
/// annulus, between the points where each circle's two halves meet; a
/// LibreCAD drawing has it): its cell lies in the region of the outer ring,
/// which its first end is inside of though no corner of. That ring was not
/// counted (its region "holds no direction" at a point not its corner):
/// the wall and everything beside it was located outside. Curved and
/// straight, the wall either way round.
#[test]
fn a_wall_from_a_holes_corner_to_its_shells() {
    let p = Point::new;
    let annulus = vec![vec![(p(15.0, 0.0), 1.0), (p(5.0, 0.0), 1.0)], vec![(p(13.0, 0.0), 1.0), (p(7.0, 0.0), 1.0)]];
    let squares = vec![
        vec![(p(0.0, 0.0), 0.0), (p(10.0, 0.0), 0.0), (p(10.0, 10.0), 0.0), (p(0.0, 10.0), 0.0)],
        vec![(p(3.0, 3.0), 0.0), (p(7.0, 3.0), 0.0), (p(7.0, 7.0), 0.0), (p(3.0, 7.0), 0.0)],
    ];
    for (name, rings, wall) in
        [("annulus", &annulus, [p(13.0, 0.0), p(15.0, 0.0)]), ("squares", &squares, [p(7.0, 7.0), p(10.0, 10.0)])]
    {
        for wall in [wall, [wall[1], wall[0]]] {
            let build = |rings: &[Ring]| {
                let mut b = Builder::new();
                b.add_bulged_polygon(rings).unwrap();
                b.add_segment(wall).unwrap();
                b.build().unwrap()
            };
            let d = build(rings);
            let chords: Vec<Ring> = rings.iter().map(|r| densified_ring(r).into_iter().map(|q| (q, 0.0)).collect()).collect();
            let reference = build(&chords);
            let wall_site =
                d.site_ids().find(|&s| matches!(d.site(s), Some(Site::Segment { a, b }) if [a, b] == wall || [b, a] == wall));
            assert_eq!(d.cell_location(wall_site.unwrap()), Some(segvoronoi::Location::Inside), "{name}: the wall's cell");
            for distance in [-0.5, -0.25, 0.3] {
                let (area, want) = (d.offset(distance).unwrap().area(), reference.offset(distance).unwrap().area());
                assert!(
                    (area - want).abs() <= 1e-3 * want.abs(),
                    "{name} {wall:?} at {distance}: area {area} against the chords' {want}"
                );
            }
        }
    }
}

/// What users have, in curved domains: a slot whose long side has a
/// straight (180°) vertex and one an ulp off straight, 1e6 from the origin,
/// so that the side meets the half circle an ulp off tangent. Found wrong:
/// the vertex of the arc's two ends and the side sat an ulp beyond the
/// arc's centre, which a tolerance called the centre (now the exact turn
/// at the join, `exact_join`); the vertex of the join and its two pieces
/// was placed anywhere along the normal (now at the join); the offset
/// along the edge beside the near-tangent join was found by an angle that
/// does not move along it (now across the ray).
#[test]
fn a_curved_ring_with_straight_vertices_far_out() {
    let p = Point::new;
    let (x, y) = (1e6 + 0.37, -1e6 + 0.81);
    let ulp_off = y + f64::EPSILON * 1e6;
    let slot = vec![vec![
        (p(x, y), 0.0),
        (p(x + 1.5, y), 0.0),
        (p(x + 3.0, ulp_off), 0.0),
        (p(x + 4.0, y), 1.0),
        (p(x + 4.0, y + 2.0), 0.0),
        (p(x, y + 2.0), 1.0),
    ]];
    check_domain_offsets("slot with straight vertices at 1e6", &slot, &[-0.3, -0.7, 0.4], 6.0);
    check_medial_axis("slot with straight vertices at 1e6", &slot, 6.0);
}

/// The same slot far out without the straight vertices: passes.
#[test]
fn a_slot_far_from_the_origin() {
    let p = Point::new;
    let (x, y) = (1e6 + 0.37, -1e6 + 0.81);
    let slot = vec![vec![(p(x, y), 0.0), (p(x + 4.0, y), 1.0), (p(x + 4.0, y + 2.0), 0.0), (p(x, y + 2.0), 1.0)]];
    check_domain_offsets("slot at 1e6", &slot, &[-0.3, -0.7, 0.4], 6.0);
    check_medial_axis("slot at 1e6", &slot, 6.0);
}

/// A lens-shaped hole of two arcs whose end touches the shell's side at a
/// point inside it (rings touching at a point; the build cuts the side
/// there). Found wrong: at +0.5 a piece along the lens ended off its
/// distance (fixed with the exact turns at joins, see above).
#[test]
fn a_curved_hole_touching_its_shell() {
    let p = Point::new;
    let touching = vec![
        vec![(p(0.0, 0.0), 0.0), (p(8.0, 0.0), 0.0), (p(8.0, 5.0), 0.0), (p(0.0, 5.0), 0.0)],
        vec![(p(3.0, 0.0), 0.4), (p(5.0, 2.0), 0.4)],
    ];
    check_domain_offsets("a lens touching its shell", &touching, &[-0.2, -0.6, 0.5], 9.0);
    check_medial_axis("a lens touching its shell", &touching, 9.0);
}

/// What users have: every curved family with a vertex on every straight
/// side, straight to rounding or one ulp off, at the origin and far from
/// it. The vertices an ulp off and the joins an ulp off tangent are
/// corners to the exact predicates (`exact_join`), straight to the domain
/// within rounding; offsets and the medial axis must not see the
/// difference.
#[test]
fn curved_families_with_straight_and_ulp_off_vertices() {
    let mut rng = SplitMix64(31);
    let families: Vec<(&str, Vec<Ring>, f64)> = vec![
        ("slot", vec![slot_ring(0.0, 0.0, 4.0, 1.0)], 6.0),
        (
            "rounded with holes",
            vec![
                rounded_ring(0.0, 0.0, 10.0, 6.0, 1.5, false),
                circle_ring(3.0, 3.0, 1.0),
                rounded_ring(5.0, 1.0, 4.0, 3.0, 1.0, true),
            ],
            10.0,
        ),
        ("filleted 3", vec![filleted_ring(&mut rng, 0.0, 0.0, 3, 0.3)], 2.0),
        ("filleted 6", vec![filleted_ring(&mut rng, 0.0, 0.0, 6, 0.3)], 2.0),
    ];
    for (name, rings, size) in &families {
        for shift in [Point::new(0.0, 0.0), Point::new(1e6 + 0.37, -1e6 + 0.81), Point::new(-3e7, 2.5e7)] {
            for nudge in [false, true] {
                let changed: Vec<Ring> = rings.iter().map(|r| with_straight_vertices(r, &mut rng, nudge, shift)).collect();
                let what = format!("{name} at {shift:?}{}", if nudge { ", nudged" } else { "" });
                let distances = [-0.03 * size, -0.08 * size, 0.1 * size];
                check_domain_offsets(&what, &changed, &distances, *size);
                check_medial_axis(&what, &changed, *size);
                let reversed: Vec<Ring> = changed.iter().map(reverse_ring).collect();
                check_domain_offsets(&format!("{what}, reversed"), &reversed, &distances, *size);
                // -0.05 of the rounded rectangle with holes is the level
                // where its corridors close (offsets touching themselves,
                // found wrong: a crossing sent to the far end of its edge).
                // Whether the loops part at a touching point or join there
                // is rounding's choice far out and not yet the same both
                // ways round (known: the order of two crossings at one
                // vertex), so here the pieces and the region are checked.
                let touching = -0.05 * size;
                let mut seen = Seen::default();
                let mut area = |rings: &[Ring]| {
                    let (d, reference) = domain_and_reference(rings);
                    let offset = d.offset(touching).unwrap();
                    check_pieces(&what, &d, &offset, touching, piece_tolerance(rings, *size, touching), &mut seen);
                    (offset.area(), reference.offset(touching).unwrap().area())
                };
                let ((forward, want), (backward, _)) = (area(&changed), area(&reversed));
                assert!(
                    (forward - want).abs() <= 1e-4 * want.abs(),
                    "{what} at {touching}: {forward} against the chords' {want}"
                );
                assert!((forward - backward).abs() <= 1e-9 * size * size, "{what} at {touching}: {forward}, reversed {backward}");
            }
        }
    }
}

/// A square with a circle touching its side and a segment leaving the
/// point where the circle's two halves meet (LibreCAD's Logic-NOT-IEC
/// gate, minimised). Its outward offset had a piece 5 off its distance
/// (an area of 393 for about 302): where the circle touches the square's
/// side at the side's end, the arc and the side leave that point the same
/// way (a cusp), and their edge was taken for the ray of a tangent join.
/// Found by the offsets' check of their pieces, which refused it.
/// LibreCAD's blk1 and block2: a rounded rectangle whose corners' bulges
/// are written with six digits (0.414209 for tan 22.5°), so every join has
/// a kink of 2e-6 rad. The edge between a side and a corner arc there is
/// radial to within that, and its points were found by the angle around
/// the arc's centre, which cannot tell them apart (pieces 1e-5 off their
/// distance); within 1e-4 rad such an edge is found across the ray.
#[test]
fn a_rounded_rectangle_with_bulges_of_six_digits() {
    let p = Point::new;
    let b = 0.414209;
    for (x0, y0) in [(0.0, 0.0), (1e6 + 0.37, -1e6 + 0.81)] {
        let ring = vec![
            (p(x0 + 30.0, y0), b),
            (p(x0 + 35.0, y0 + 5.0), 0.0),
            (p(x0 + 35.0, y0 + 15.0), b),
            (p(x0 + 30.0, y0 + 20.0), 0.0),
            (p(x0, y0 + 20.0), b),
            (p(x0 - 5.0, y0 + 15.0), 0.0),
            (p(x0 - 5.0, y0 + 5.0), b),
            (p(x0, y0), 0.0),
        ];
        for ring in [ring.clone(), reverse_ring(&ring)] {
            check_domain_offsets("rounded, six digits", &[ring], &[-0.5, -2.5, -4.9, 0.5, 3.0], 40.0);
        }
    }
}

/// LibreCAD's n13 with its circles cut where the lines along their tops
/// and bottoms start (as the CLI cuts arcs where an entity ends on them):
/// where a line leaves a cut circle along its tangent, a cusp beside a
/// tangent join at one point. The line's direction from the circle's top
/// runs along the ring's tangent there, and the domain took the line for
/// part of the boundary: the separators at its ends were located there,
/// the outward offset's walk skipped them, and the loop came out open,
/// each piece at its distance (refused since the offsets' check requires
/// closed loops). Now the line lies outside, as the circle curves away
/// from it (`curved_corner_holds`). Against 256-chord builds, and mirrored.
#[test]
fn lines_along_the_tangents_of_two_circles() {
    let p = Point::new;
    let q = (std::f64::consts::PI / 8.0).tan();
    for sign in [1.0, -1.0] {
        let at = |x: f64, y: f64| p(sign * x, y);
        let circle = |cx: f64| {
            let ring = vec![(at(cx + 1.5, 0.0), q), (at(cx, 1.5), q), (at(cx - 1.5, 0.0), q), (at(cx, -1.5), q)];
            if sign < 0.0 {
                reverse_ring(&ring.iter().map(|&(v, b)| (v, -b)).collect())
            } else {
                ring
            }
        };
        let build = |rings: &[Ring]| {
            let mut b = Builder::new();
            b.add_bulged_polygon(rings).unwrap();
            for [s, e] in [
                [at(3.0, 0.0), at(0.0, 0.0)],
                [at(16.0, 0.0), at(13.0, 0.0)],
                [at(4.5, 1.5), at(11.5, 1.5)],
                [at(4.5, -1.5), at(11.5, -1.5)],
            ] {
                b.add_segment([s, e]).unwrap();
            }
            b.build().unwrap()
        };
        let rings = [circle(4.5), circle(11.5)];
        let d = build(&rings);
        let chords: Vec<Ring> = rings.iter().map(|r| densified_ring(r).into_iter().map(|v| (v, 0.0)).collect()).collect();
        let reference = build(&chords);
        for r in [1.0, 0.5, -0.5] {
            let what = format!("mirrored {} at {r}", sign < 0.0);
            let offset = d.offset(r).unwrap_or_else(|e| panic!("{what}: {e}"));
            for l in &offset.loops {
                let n = l.pieces.len();
                assert!((0..n).all(|k| l.pieces[k].to() == l.pieces[(k + 1) % n].from()), "{what}: an open loop");
            }
            let want = reference.offset(r).unwrap();
            assert_eq!(offset.loops.len(), want.loops.len(), "{what}: loops");
            let (area, want) = (offset.area(), want.area());
            assert!((area - want).abs() <= 1e-3 * want.abs(), "{what}: area {area} against the chords' {want}");
        }
    }
}

#[test]
fn a_circle_touching_a_side_at_its_end() {
    let p = Point::new;
    let rings = vec![
        vec![(p(10.0, 10.0), 0.0), (p(10.0, -10.0), 0.0), (p(20.0, -10.0), 0.0), (p(20.0, 10.0), 0.0)],
        vec![(p(25.0, 0.0), 1.0), (p(20.0, 0.0), 1.0)],
    ];
    for with_segment in [false, true] {
        let build = |rings: &[Ring]| {
            let mut b = Builder::new();
            b.add_bulged_polygon(rings).unwrap();
            if with_segment {
                b.add_segment([p(30.0, 0.0), p(25.0, 0.0)]).unwrap();
            }
            b.build().unwrap()
        };
        let d = build(&rings);
        let chords: Vec<Ring> = rings.iter().map(|r| densified_ring(r).into_iter().map(|q| (q, 0.0)).collect()).collect();
        let reference = build(&chords);
        for distance in [1.0, 0.3, -0.5] {
            let want = reference.offset(distance).unwrap().area();
            let offset = d.offset(distance).unwrap_or_else(|e| panic!("at {distance}: {e}"));
            let area = offset.area();
            assert!((area - want).abs() <= 1e-3 * want, "at {distance}: area {area} against the chords' {want}");
        }
    }
    check_domain_offsets("a circle touching a side at its end", &rings, &[-0.5, -2.0, 0.3, 1.0], 20.0);
}

/// LibreCAD's ed125 and ed83 (power station symbols) with their circles
/// cut where lines end on them, as the CLI cuts them: the cut arcs' ends
/// are the lines' ends as written (eight digits), so neighbouring arcs lie
/// on circles 1e-10 apart and meet at kinks of 1e-10 rad. In ed125 the
/// cell of a kink's point took both sides of the ring (the arc joining it
/// saw a tie of 1e-20 at infinity; now an exact turn,
/// `at_infinity::beside_a_shared_end`) and a loop skipped a quarter of
/// the circle; in ed83 a vertex was put at the circle's centre for the
/// three sites in the wrong order, with a line 2 nearer (now the centre
/// only for sites round it in the order asked). Offsets against 256-chord
/// builds, the rings both ways round and mirrored.
#[test]
fn circles_cut_where_lines_end_on_them() {
    let p = Point::new;
    let ed125: (Vec<(Point, f64)>, Vec<[Point; 2]>) = (
        vec![
            (p(12.0, 22.0), 0.1000256901668162),
            (p(11.05844178, 26.65949197), 0.663792257135762),
            (p(-11.05844177, 26.65949197), 0.10002569024851948),
            (p(-12.0, 22.0), 0.41421356237309503),
            (p(0.0, 10.0), 0.41421356237309503),
        ],
        vec![[p(0.0, 0.0), p(0.0, 10.0)], [p(-11.05844177, 26.65949197), p(11.05844178, 26.65949197)]],
    );
    let ed83: (Vec<(Point, f64)>, Vec<[Point; 2]>) = (
        vec![
            (p(5.0, 10.0), 0.41421356237309503),
            (p(0.0, 15.0), 0.2980619733770786),
            (p(-4.581438725, 12.002603108), 0.10338726200537364),
            (p(-5.0, 10.0), 0.41421356237309503),
            (p(0.0, 5.0), 0.2982166266995688),
            (p(4.582575695, 8.0), 0.10324371717470382),
        ],
        vec![
            [p(0.0, 12.0), p(-4.581438725, 12.002603108)],
            [p(-5.0, 10.0), p(-10.0, 10.0)],
            [p(0.0, 5.0), p(0.0, 0.0)],
            [p(0.0, 8.0), p(4.582575695, 8.0)],
            [p(0.0, 15.0), p(0.0, 20.0)],
        ],
    );
    for (name, (ring, lines)) in [("ed125", ed125), ("ed83", ed83)] {
        for (way, mirrored, reversed) in [("as drawn", false, false), ("mirrored", true, false), ("reversed", false, true)] {
            let flip = |q: Point| if mirrored { p(-q.x, q.y) } else { q };
            let mut ring: Ring = ring.iter().map(|&(q, b)| (flip(q), if mirrored { -b } else { b })).collect();
            if reversed {
                ring = reverse_ring(&ring);
            }
            let lines: Vec<[Point; 2]> = lines.iter().map(|&[s, e]| [flip(s), flip(e)]).collect();
            let build = |ring: &Ring| {
                domain_with_lines(std::slice::from_ref(ring), &lines).unwrap_or_else(|e| panic!("{name} {way}: {e}"))
            };
            let d = build(&ring);
            let chords: Ring = densified_ring(&ring).into_iter().map(|q| (q, 0.0)).collect();
            let reference = build(&chords);
            for distance in [1.0, 0.5, -0.5, -2.0] {
                let what = format!("{name} {way} at {distance}");
                let offset = d.offset(distance).unwrap_or_else(|e| panic!("{what}: {e}"));
                for l in &offset.loops {
                    let n = l.pieces.len();
                    assert!((0..n).all(|k| l.pieces[k].to() == l.pieces[(k + 1) % n].from()), "{what}: an open loop");
                }
                let (area, want) = (offset.area(), reference.offset(distance).unwrap().area());
                assert!((area - want).abs() <= 1e-3 * want.abs(), "{what}: area {area} against the chords' {want}");
            }
        }
    }
}

/// An arc with its chord (LibreCAD's kin10: a hatch line cuts a quarter
/// circle, and the CLI cuts the arc at the line's ends): the edge between
/// the arc and the chord has both ends on the circle, and which side of
/// the circle it lies on was read from their rounding. Taken outside, the
/// offsets' track of that edge ran off to 1e14, and a loop of two pieces
/// far from both sites came back (refused by the offsets' check). Now the
/// side is the chord's. As cut in kin10 (its arcs 1e-9 off one circle),
/// and plain lenses, mirrored and reversed.
#[test]
fn an_arc_and_its_chord() {
    let p = Point::new;
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let kin10 = vec![
        Piece::Segment(p(0.0, 0.0), p(4.0, 0.0)),
        Piece::Segment(p(14.1711311583, 0.559442976), p(14.440557024, 0.828868841)),
        arc(p(15.0, 1.0), p(14.440557024, 0.828868841), 0.14952810498430108),
        arc(p(14.440557024, 0.828868841), p(14.1711311583, 0.559442976), 0.09613681550557843),
    ];
    check_all("kin10's cut quarter", &kin10, &[1.0, 0.3, 0.05], 16.0);
    for (name, bulge) in [("shallow lens", 0.1), ("half disc", 1.0), ("deep lens", 2.5), ("clockwise lens", -0.4)] {
        for (way, s, e) in
            [("", p(3.0, 1.0), p(1.0, 2.0)), (" reversed", p(1.0, 2.0), p(3.0, 1.0)), (" mirrored", p(-3.0, 1.0), p(-1.0, 2.0))]
        {
            let bulge = if way == " mirrored" { -bulge } else { bulge };
            let pieces = vec![arc(s, e, bulge), Piece::Segment(s, e)];
            check_all(&format!("{name}{way}"), &pieces, &[1.0, 0.2, 0.01], 4.0);
        }
    }
}

/// Two half discs facing each other across a gap (LibreCAD's Spark-gap):
/// the edge between the two arcs is a whole line, infinite at both ends,
/// and the offsets had no track for it: past half the gap the two loops
/// came out apart and overlapping (found against GEOS). Also with unequal
/// radii (a hyperbola branch) and the arcs the other way round, against
/// 256-chord builds.
#[test]
fn half_discs_facing_across_a_gap() {
    let p = Point::new;
    for (r1, r2) in [(3.75, 3.75), (3.75, 2.0)] {
        let lower = vec![(p(r1, 15.0), 1.0), (p(-r1, 15.0), 0.0)];
        let upper = vec![(p(-r2, 25.0), 1.0), (p(r2, 25.0), 0.0)];
        let name = format!("half discs of radii {r1} and {r2}");
        check_domain_offsets(&name, &[lower.clone(), upper.clone()], &[0.5, 1.0, 2.2, 4.07, 9.0, -0.5], 40.0);
        check_domain_offsets(&format!("{name}, reversed"), &[reverse_ring(&lower), reverse_ring(&upper)], &[2.2, 4.07], 40.0);
    }
}

/// A crescent of two arcs meeting at both ends, each more than half a
/// turn (LibreCAD's Headphone band, its ends 1e-12 off round numbers):
/// the edge between the arcs has both ends on both circles, and which
/// side of the circle it lies on was taken beside the middle of its ends'
/// chord, which lies across the centre from the arc: the inward offset
/// ran off to (-4170, -1193) (refused by the offsets' check). Now beside
/// the arc halfway between its ends. Against 256-chord builds, both ways
/// round.
#[test]
fn a_crescent_of_two_arcs_over_half_a_turn() {
    let p = Point::new;
    let band = vec![
        (p(28.750000000001577, 1.2500000000240854), 1.1530096874061824),
        (p(11.249999999998423, 1.2500000000240807), -1.3257299841847874),
    ];
    for ring in [band.clone(), reverse_ring(&band)] {
        check_domain_offsets("crescent", std::slice::from_ref(&ring), &[-0.2, 0.5, 1.0], 20.0);
        // at -0.5 a thin lens of area 5.6, where the chords' own error is
        // 1.2e-4 of it
        let (d, reference) = domain_and_reference(std::slice::from_ref(&ring));
        let offset = d.offset(-0.5).unwrap();
        let want = reference.offset(-0.5).unwrap();
        assert_eq!((offset.loops.len(), want.loops.len()), (1, 1));
        assert!((offset.area() - want.area()).abs() <= 1e-3 * want.area(), "{} against {}", offset.area(), want.area());
    }
}

/// What a DXF drawing of a circle with lines ending on it becomes once
/// the program cuts the circle at the lines' ends: random circles, each
/// with random points on it written to 8 decimals (a drawing's rounding,
/// 1e-9 off the circle), some with a line out from the centre's
/// direction, some pairs joined by a chord, the circle cut at every such
/// point into arcs by bulge (each arc's circle then a rounding off the
/// others': kinks of 1e-10 rad). The family of LibreCAD's ed83, ed125,
/// kin10, n13 and Headphone, nobody's numbers. Offsets at four distances
/// against the same input with every arc as 256 chords: closed loops, the
/// chords' loop count, areas within 1e-3. It found a circle of two arcs
/// whose edge runs in to the centre and out (`ConicTrack`'s `bent`), a
/// round join at a joint turned the long way (`no_whole_turn_at_a_joint`),
/// and an edge between two arcs sharing both ends taken along the wrong
/// join's ray (`two_arcs_of_one_circle_and_a_line_out_from_a_join`).
#[test]
fn random_circles_cut_where_lines_end_on_them() {
    // at the origin and a million away (the same circles, then rounded there)
    random_circles_cut_at(0.0, 0.0);
    random_circles_cut_at(1e6, -1e6);
}

fn random_circles_cut_at(ox: f64, oy: f64) {
    // Of 300 seeds 291 draw a circle; every one is answered right, as
    // they are of 1500 (CUT_CIRCLE_SEEDS=1500). Once refused: seeds 12,
    // 30 and others whose inward offsets found vertices at the centre
    // located outside (`a_circle_cut_in_four_with_kinks_of_a_rounding`),
    // and 120 and others whose build found no vertex in the cluster of
    // two arcs of circles a rounding apart (`arcs::minimised_regressions`).
    let p = Point::new;
    let round8 = |x: f64| (x * 1e8).round() / 1e8;
    let mut rng = SplitMix64(20261205);
    let (mut cases, mut refused) = (0, Vec::new());
    // (CUT_CIRCLE_SEEDS=1500 sweeps wider, printing what is refused)
    let seeds = std::env::var("CUT_CIRCLE_SEEDS").ok().and_then(|v| v.parse().ok());
    for seed in 0..seeds.unwrap_or(300u64) {
        let (cx, cy, r) = (round8(ox + 20.0 * rng.unit()), round8(oy + 20.0 * rng.unit()), round8(2.0 + 8.0 * rng.unit()));
        let k = 2 + (rng.next_u64() % 5) as usize;
        let mut angles: Vec<f64> = (0..k).map(|_| std::f64::consts::TAU * rng.unit()).collect();
        angles.sort_by(f64::total_cmp);
        // apart by at least 0.2 rad, so that the arcs are not slivers
        angles.dedup_by(|a, b| *a - *b < 0.2);
        if angles.len() < 2 || std::f64::consts::TAU - (angles[angles.len() - 1] - angles[0]) < 0.2 {
            continue;
        }
        let points: Vec<Point> = angles.iter().map(|t| p(round8(cx + r * t.cos()), round8(cy + r * t.sin()))).collect();
        let n = points.len();
        // the ring: the circle cut at the points, each arc by its bulge
        // from the angles of its rounded ends, counter-clockwise
        let angle = |q: Point| (q.y - cy).atan2(q.x - cx);
        let ring: Ring = (0..n)
            .map(|j| {
                let sweep = (angle(points[(j + 1) % n]) - angle(points[j])).rem_euclid(std::f64::consts::TAU);
                (points[j], (sweep / 4.0).tan())
            })
            .collect();
        // lines: outward from every other point, a chord between the first two
        let mut lines: Vec<[Point; 2]> = (0..n)
            .step_by(2)
            .map(|j| {
                let (ux, uy) = ((points[j].x - cx) / r, (points[j].y - cy) / r);
                [points[j], p(round8(points[j].x + 3.0 * ux), round8(points[j].y + 3.0 * uy))]
            })
            .collect();
        if seed % 2 == 1 {
            lines.push([points[0], points[1]]);
        }
        // every tenth seed also reversed, and mirrored (x to −x: each arc's
        // bulge negated, the ring turning the other way)
        let mut ways = vec![("as drawn", ring.clone(), lines.clone())];
        if seed % 10 == 0 {
            let reversed_lines: Vec<[Point; 2]> = lines.iter().rev().map(|&[a, b]| [b, a]).collect();
            ways.push(("reversed", reverse_ring(&ring), reversed_lines));
            let m = |q: Point| p(-q.x, q.y);
            let mirrored: Ring = ring.iter().map(|&(q, bulge)| (m(q), -bulge)).collect();
            ways.push(("mirrored", mirrored, lines.iter().map(|&[a, b]| [m(a), m(b)]).collect()));
        }
        for (way, ring, lines) in &ways {
            check_cut_circle(&format!("seed {seed} ({ox}, {oy}) {way}"), ring, lines, r, &mut refused);
        }
        cases += 1;
    }
    assert!(cases >= 16, "{cases} cases");
    eprintln!("{cases} circles, offsets refused: {refused:?}");
    assert!(refused.is_empty(), "{} offsets refused: {refused:?}", refused.len());
}

/// One case of `random_circles_cut_at` (`what` names it): the offsets of
/// the cut circle `ring` of radius `r` with `lines` at four distances
/// against the same with every arc as 256 chords. A refusal (never a
/// wrong answer) is pushed to `refused`.
fn check_cut_circle(what: &str, ring: &Ring, lines: &[[Point; 2]], r: f64, refused: &mut Vec<(String, f64)>) {
    let build = |ring: &Ring| domain_with_lines(std::slice::from_ref(ring), lines);
    let d = match build(ring) {
        Ok(d) => d,
        Err(e) => {
            // refused by the build's checks of its arc vertices
            assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "{what}: {e}: {ring:?} {lines:?}");
            eprintln!("refused: {what}: {e}: {ring:?} {lines:?}");
            refused.push((what.to_string(), 0.0));
            return;
        }
    };
    let chords: Ring = densified_ring(ring).into_iter().map(|q| (q, 0.0)).collect();
    let reference = build(&chords).unwrap();
    for distance in [0.3, 1.0, -0.3, -0.25 * r] {
        let case = format!("{what} at {distance}: {ring:?} {lines:?}");
        let offset = match d.offset(distance) {
            Ok(offset) => offset,
            Err(e) => {
                // refused by the offsets' checks, never answered wrong
                assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "{case}: {e}");
                eprintln!("refused: {case}: {e}");
                refused.push((what.to_string(), distance));
                continue;
            }
        };
        for l in &offset.loops {
            let m = l.pieces.len();
            assert!((0..m).all(|j| l.pieces[j].to() == l.pieces[(j + 1) % m].from()), "{case}: an open loop");
        }
        let want = reference.offset(distance).unwrap();
        assert_eq!(offset.loops.len(), want.loops.len(), "{case}: loops");
        let (area, want) = (offset.area(), want.area());
        assert!((area - want).abs() <= 1e-3 * want.abs(), "{case}: area {area} against the chords' {want}");
    }
}

/// Circles of two arcs with a line out from one join along the radius,
/// with or without the chord: seeds of
/// `random_circles_cut_where_lines_end_on_them` once answered wrong, each
/// with a whole turn too many or the disc taken for a hole.
/// - Seed 73 (area 489.8 for 247.7 at distance 1): the two arcs share both
///   ends, and the edge between them outside runs along the radius of the
///   join without the line. Its track took the first shared end for the
///   ray (`tangent_join`), the other join's.
/// - Seeds 1460, and 579 a million away (outward offsets a hole of the
///   disc's inward size): the edge between the line and one arc meets
///   the other arc on the radius of the far join, where a circle touches
///   all three in the order asked; so does the circle of radius zero at
///   the near join, where all three end. The solver took that one, off
///   the edge, and the arc's cell outside was cut away
///   (`arc_vertex::better`: the circle nearer the edge's end that goes).
///
/// Both ways round, mirrored, at four distances, against 256 chords.
#[test]
fn two_arcs_of_one_circle_and_a_line_out_from_a_join() {
    let p = Point::new;
    // (the circle's two points and bulges, the line's far end, the chord)
    let cases: [([Point; 2], [f64; 2], Point, bool); 3] = [
        (
            [p(8.05032554, 20.51405669), p(4.74689933, 21.29659965)],
            [0.11044204803864038, 9.054522419306547],
            p(9.36222288, 23.21200506),
            true,
        ),
        (
            [p(1.47380139, 16.08696028), p(1.94746626, 15.01145388)],
            [0.07207093410916308, 13.875219079099752],
            p(-1.4167433, 15.28399616),
            false,
        ),
        (
            [p(1000003.33250638, -999991.53872101), p(1000004.03777243, -999992.68293477)],
            [0.09525517310833251, 10.498117502371374],
            p(1000000.52739926, -999992.60238169),
            false,
        ),
    ];
    for ([a, b], [to_b, to_a], out, with_chord) in cases {
        let ring: Ring = vec![(a, to_b), (b, to_a)];
        let mut lines = vec![[a, out]];
        if with_chord {
            lines.push([a, b]);
        }
        offsets_all_ways_against_chords(&ring, &lines, &[0.3, 1.0, -0.3, -1.0]);
    }
}

/// Seed 6 of `random_circles_cut_where_lines_end_on_them`, whose inward
/// offsets were refused: a circle cut in four, its ends written to 8
/// decimals, so that each arc's circle is a rounding off the next's and
/// every join a kink of 1e-9 rad (a corner, not a tangent join), with two
/// lines out from joins. At a corner without a line the construction
/// gave the corner's cell as a line through it, in to the vertices at the
/// centre; the domain took that cell for the reflex side only (outside),
/// and the vertices at the centre were located outside. Such a separator
/// now passes through its corner, located by its ends, as at a straight
/// one, and the corner's cell tells no edge's side
/// (`domain::ring_segment_sides`).
#[test]
fn a_circle_cut_in_four_with_kinks_of_a_rounding() {
    let p = Point::new;
    let ring: Ring = vec![
        (p(7.93896511, 10.82013001), 0.17417264647499672),
        (p(7.04993427, 7.78096272), 0.4183174724914033),
        (p(12.07199593, 3.39311477), 0.35934682280093394),
        (p(16.37559427, 7.51840399), 0.7715952486056451),
    ];
    let lines =
        [[p(7.93896511, 10.82013001), p(5.51394629, 12.58627942)], [p(12.07199593, 3.39311477), p(12.29466801, 0.40138999)]];
    offsets_all_ways_against_chords(&ring, &lines, &[0.3, 1.0, -0.3, -1.170745845, -4.0]);
}

/// A line tangent to a circle, ending at the tangent point and dipping
/// 1e-11 into it by rounding (LibreCAD's Relay, as its split and the
/// CLI's cut leave it): the circle is cut 1.1e-11 before the line's end,
/// the piece between is straight, and the cut arcs' centres are 1.6e-11
/// apart. Their edges run from the join in to the centre, out to
/// infinity, and between the two arcs within 1e-11 of the centre; the
/// offsets' angle around the centre could not tell their points apart
/// (every offset refused: a piece ending at the join or at the centre).
/// Now such an edge is followed across the ray to its far end. Scaled,
/// and a thousand from the origin (where the configuration rounds
/// another way), both ways round and mirrored.
#[test]
fn a_tangent_line_dipping_into_a_circle_by_rounding() {
    let p = Point::new;
    let (a, b) = (p(4.239412447758696, 19.22797120299265), p(4.239412447750055, 19.227971202999925));
    let ring: Ring = vec![(p(5.875, 20.0), 1.0), (p(3.875, 20.0), 0.2241515709905449), (b, 0.0), (a, 0.6337846124526398)];
    let lines = [[p(8.60297120298, 15.6355875522), a]];
    // as drawn, scaled by powers of two (exactly) and a thousand out
    for (scale, shift) in [(1.0, 0.0), (0.125, 0.0), (1024.0, 0.0), (1.0, 1e3)] {
        let at = |q: Point| p(q.x * scale + shift, q.y * scale - shift);
        let ring: Ring = ring.iter().map(|&(q, bulge)| (at(q), bulge)).collect();
        let lines = lines.map(|l| l.map(at));
        let distances = [-0.1, -0.5, -0.9, 0.5, 1.0, 3.0].map(|d| d * scale);
        offsets_all_ways_against_chords(&ring, &lines, &distances);
    }
}

/// The same drawing as `a_tangent_line_dipping_into_a_circle_by_rounding`
/// given to the library whole (a circle, and the line ending 1e-11 inside
/// it) with `split_crossings`: the split cuts the circle where the line's
/// rounded roots are, 5e-6 before its end, and leaves that stub inside.
/// The stub's free end lies on the circle to rounding, and the structure
/// gives it a cell at infinity beside the arc. That edge went to infinity
/// 12.6 degrees off (no root found: the support functions only touch
/// there), and the edges from the stub's end were located inside the
/// domain with an end at infinity: every offset outside was refused (a
/// loop that does not close). Now the edge runs out along the end's
/// radius (`arc_vertex::direction_at_infinity`) and an edge to infinity
/// is never inside (`domain::classify`).
#[test]
fn a_tangent_line_dipping_into_a_circle_split_by_the_library() {
    let p = Point::new;
    let build = |ring: &Ring| {
        let mut b = Builder::new();
        b.add_bulged_polygon(std::slice::from_ref(ring)).unwrap();
        b.add_segment([p(8.60297120298, 15.6355875522), p(4.23941244775, 19.227971203)]).unwrap();
        b.split_crossings(true).build().unwrap()
    };
    let ring: Ring = vec![(p(5.875, 20.0), 1.0), (p(3.875, 20.0), 1.0)];
    let d = build(&ring);
    let chords: Ring = densified_ring(&ring).into_iter().map(|q| (q, 0.0)).collect();
    let reference = build(&chords);
    for distance in [-0.1, -0.5, 0.5, 1.0, 3.0] {
        let offset = d.offset(distance).unwrap_or_else(|e| panic!("at {distance}: {e}"));
        let (area, want) = (offset.area(), reference.offset(distance).unwrap().area());
        assert!((area - want).abs() <= 1e-3 * want, "at {distance}: area {area} against the chords' {want}");
    }
}

/// The offsets of `ring` with `lines` as obstacles, both ways round and
/// mirrored, at `distances`: the loop count and area of the same input
/// with every arc as 256 chords (to 1e-3).
fn offsets_all_ways_against_chords(ring: &Ring, lines: &[[Point; 2]], distances: &[f64]) {
    let p = Point::new;
    let mirror = |q: Point| p(-q.x, q.y);
    for mirrored in [false, true] {
        let ring: Ring = if mirrored { ring.iter().map(|&(q, b)| (mirror(q), -b)).collect() } else { ring.clone() };
        let lines: Vec<[Point; 2]> = if mirrored { lines.iter().map(|l| l.map(mirror)).collect() } else { lines.to_vec() };
        for ring in [ring.clone(), reverse_ring(&ring)] {
            let d = domain_with_lines(std::slice::from_ref(&ring), &lines).unwrap();
            let chords: Ring = densified_ring(&ring).into_iter().map(|q| (q, 0.0)).collect();
            let reference = domain_with_lines(&[chords], &lines).unwrap();
            for &distance in distances {
                let what = format!("{} lines, mirrored {mirrored}, at {distance}: {ring:?}", lines.len());
                let offset = d.offset(distance).unwrap_or_else(|e| panic!("{what}: {e}"));
                let want = reference.offset(distance).unwrap();
                assert_eq!(offset.loops.len(), want.loops.len(), "{what}: loops");
                let (area, want) = (offset.area(), want.area());
                assert!((area - want).abs() <= 1e-3 * want, "{what}: area {area} against the chords' {want}");
            }
        }
    }
}

/// Found by the C API's fuzzer (case 0x97abe643d20d0a51, minimised by its
/// shrinker): a slot from (-4, -3) to (4, -1), tangent-continuous, and three
/// points, one of them (-2, -3.4e-131), a hair below the line y = 0. Every
/// offset was refused by its own check (a piece ending at a vertex of
/// clearance 1, not at the distance): the point's tiny coordinate makes the
/// internal coordinates about 1e65, where the offset's track of the edge of
/// the left half circle and the point (-4, 1), to infinity, took the
/// direction at infinity's angle from the centre plus that unit direction,
/// which rounded back to the centre (an angle of zero: a track of one
/// point). The same with the hair above the line, at 1e-140 (near the
/// arcs' exact range) and at zero; and as users draw it: a straight
/// (180°) vertex in the slot's long side, a point exactly on that side,
/// and the whole a million from the origin (where the hair rounds away:
/// what stays is the slot far out). Each offset has the area of
/// the plain one (the hair, the point on the side and the straight vertex
/// change no region).
#[test]
fn a_slot_and_a_point_a_hair_off_a_line_offset_at_any_magnitude() {
    let distances = [0.5, 2.0, 2.5, 3.0, 3.5, 10.0];
    let areas = |hair: f64, straight: bool, on_side: bool, shift: f64| -> Vec<f64> {
        let at = |x: f64, y: f64| Point::new(x + shift, y + shift);
        let mut b = Builder::new();
        let mut points = vec![at(-2.0, hair), at(-1.0, -8.0), at(-4.0, 1.0)];
        if on_side {
            points.push(at(1.0, -3.0));
        }
        for p in points {
            b.add_point(p).unwrap();
        }
        let mut ring = vec![(at(-4.0, -3.0), 0.0), (at(4.0, -3.0), 1.0), (at(4.0, -1.0), 0.0), (at(-4.0, -1.0), 1.0)];
        if straight {
            ring.insert(1, (at(0.0, -3.0), 0.0));
        }
        b.add_bulged_polyline(&ring, true).unwrap();
        let what = format!("hair {hair:e}, straight {straight}, on the side {on_side}, shift {shift}");
        let d = b.build().unwrap_or_else(|e| panic!("{what}: {e}"));
        distances
            .iter()
            .map(|&r| {
                let offset = d.offset(r).unwrap_or_else(|e| panic!("{what}, distance {r}: {e}"));
                assert!(!offset.loops.is_empty(), "{what}, distance {r}: no loop");
                offset.area()
            })
            .collect()
    };
    let plain = areas(0.0, false, false, 0.0);
    for hair in [-3.366460833513009e-131, 3.366460833513009e-131, -1e-140] {
        for (straight, on_side, shift) in [(false, false, 0.0), (true, true, 0.0), (true, true, 1e6)] {
            let got = areas(hair, straight, on_side, shift);
            for ((r, a), want) in distances.iter().zip(got).zip(&plain) {
                assert!(
                    (a - want).abs() <= 1e-9 * want,
                    "hair {hair:e}, straight {straight}, on the side {on_side}, shift {shift}, distance {r}: area {a} against {want}"
                );
            }
        }
    }
}

/// Arcs straight to within the rounding of their centre (a bulge below
/// about 2^-42: the centre 2^40 chords away or more) are no arcs to the
/// builder: `add_arc` refuses one (its offsets were refused at a bulge of
/// 1e-17, and 1e12 from the origin a bulge of 1e-20 was offset as a
/// circle, a valid-looking wrong answer), and a bulged polygon takes that
/// piece as a segment. Just above the line, arcs offset as the stadium
/// they all but are, at every magnitude.
#[test]
fn nearly_straight_arcs() {
    use segvoronoi::{ChainPiece, ErrorKind};
    let stadium = 20.0 + std::f64::consts::PI;
    for (x, bulge) in [(0.0, 1e-17), (1e6, 2.5e-17), (1e12, 1e-20), (0.0, -1e-13)] {
        let mut b = Builder::new();
        let arc = CircularArc::from_bulge([x, x], [x + 10.0, x], bulge).unwrap();
        let e = b.add_arc(arc).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidArc, "{x} {bulge}");
        assert!(e.message().contains("straight"), "{e}");
        assert_eq!(b.arc_count(), 0);
    }
    for (x, bulge) in [(0.0, 3e-13), (1e6, 3e-13), (1e12, -3e-13), (-1e15, 3e-13), (1e-6, 3e-13), (0.0, 1e-9)] {
        let mut b = Builder::new();
        b.add_arc(CircularArc::from_bulge([x, x], [x + 10.0, x], bulge).unwrap()).unwrap();
        let o = b.build().unwrap().offset(1.0).unwrap_or_else(|e| panic!("{x} {bulge}: {e}"));
        assert!((o.area() - stadium).abs() <= 1e-9 * stadium, "{x} {bulge}: {}", o.area());
        assert!(o.polylines(1e-3).unwrap().iter().map(Vec::len).sum::<usize>() < 200, "{x} {bulge}");
    }
    // a square with a side of bulge 1e-17 is the square
    let p = Point::new;
    let ring = vec![(p(0.0, 0.0), 1e-17), (p(4.0, 0.0), 0.0), (p(4.0, 4.0), 0.0), (p(0.0, 4.0), 0.0)];
    let mut b = Builder::new();
    let made = b.add_bulged_polygon(&[ring]).unwrap();
    assert_eq!(made[0][0], ChainPiece::Segment(0));
    assert_eq!(b.arc_count(), 0);
    let area = b.build().unwrap().offset(-0.5).unwrap().area();
    assert!((area - 9.0).abs() <= 1e-12, "{area}");
    let mut b = Builder::new();
    let made = b.add_bulged_polyline(&[([0.0, 0.0], 1e-17), ([4.0, 0.0], 0.0)], false).unwrap();
    assert_eq!(made, vec![ChainPiece::Segment(0)]);
}

/// LibreCAD's kin3.dxf minimised: a circle of radius 0.75 with a circle of
/// radius 2 touching it from above (two arcs meeting at the tangent point)
/// and an arc of radius 2 touching it from inside below, as the CLI reads
/// them (the circle cut where the arcs end on it), split. The drawing's
/// rounded numbers make the tangencies crossings; the split cuts the
/// circles at both roots, 4e-8 apart, and leaves an arc piece of that
/// size. Edges from a circle's centre to those pieces
/// were tracked by their angle round that centre, which is rounding there:
/// every offset inside and out was refused (a piece ending on the input).
/// An edge with an end at its arc's centre is now tracked along the radius
/// (`conic::from_the_centre`). Inside, the offset is the circle of radius
/// 0.75 - d exactly; outside, the chords' answer or a refusal.
#[test]
fn a_circle_between_two_it_touches_split_at_both_roots() {
    let p = Point::new;
    let (cx, cy) = (15.4483276641, -0.239048498506);
    let on = |y: f64, degrees: f64| p(cx + 2.0 * degrees.to_radians().cos(), y + 2.0 * degrees.to_radians().sin());
    // the drawing's arcs as the CLI reads them, the circle cut where they
    // end on it (within 1e-9: the CLI's snapping), so that they touch it
    // at its own vertices
    let (top, bottom) = (p(cx, 0.51095150149), p(cx, -0.98904849851));
    let sweep = (29.638383688f64.to_radians() / 4.0).tan();
    let obstacles = [
        CircularArc::from_bulge(bottom, on(1.01095150149, 299.638383688), sweep).unwrap(),
        CircularArc::from_bulge(top, on(2.51095150149, 299.638383688), sweep).unwrap(),
        CircularArc::from_bulge(on(2.51095150149, 240.361616312), top, sweep).unwrap(),
    ];
    let q = (std::f64::consts::PI / 8.0).tan();
    let ring: Ring = vec![(p(cx + 0.75, cy), q), (top, q), (p(cx - 0.75, cy), q), (bottom, q)];
    let build = |chords: bool| {
        let mut b = Builder::new();
        if chords {
            let ring: Ring = densified_ring(&ring).into_iter().map(|q| (q, 0.0)).collect();
            b.add_bulged_polygon(std::slice::from_ref(&ring)).unwrap();
            for a in &obstacles {
                let points: Vec<Point> = (0..=256).map(|k| a.point_at(k as f64 / 256.0)).collect();
                for w in points.windows(2) {
                    b.add_segment([w[0], w[1]]).unwrap();
                }
            }
        } else {
            b.add_bulged_polygon(std::slice::from_ref(&ring)).unwrap();
            for a in &obstacles {
                b.add_arc(*a).unwrap();
            }
        }
        b.split_crossings(true).build().unwrap()
    };
    // Outside: right or refused, never wrong. Refused for now: the split
    // of this input (unlike the CLI's of the drawing, which snaps the
    // drawing's points within 1e-9 first, and whose offsets
    // `real_dxf_parts.rs` checks) leaves a loop inside the circle round a
    // piece of rounding size, and the offsets' check refuses it.
    circle_inside_chords_outside(&build(false), &build(true), 0.75, &[-0.1, -0.25, -0.4, -0.5, -0.74], &[0.1, 0.5, 2.0]);
}

/// Offsets of a domain that is a circle of `radius` with obstacles outside
/// it: inside (`inside`, negative) the circle of radius `radius + d`, its
/// area to 1e-9; outside, the loop count and area of `reference` (the same
/// input in chords) to 1e-3, or refused as `Internal`, never wrong.
fn circle_inside_chords_outside(d: &Diagram, reference: &Diagram, radius: f64, inside: &[f64], outside: &[f64]) {
    for &distance in inside {
        let area = d.offset(distance).unwrap_or_else(|e| panic!("at {distance}: {e}")).area();
        let want = std::f64::consts::PI * (radius + distance) * (radius + distance);
        assert!((area - want).abs() <= 1e-9 * want, "at {distance}: area {area}, the circle's {want}");
    }
    for &distance in outside {
        match d.offset(distance) {
            Ok(offset) => {
                let want = reference.offset(distance).unwrap();
                assert_eq!(offset.loops.len(), want.loops.len(), "at {distance}: loops");
                let (area, want) = (offset.area(), want.area());
                assert!((area - want).abs() <= 1e-3 * want, "at {distance}: area {area} against the chords' {want}");
            }
            Err(e) => assert_eq!(e.kind(), segvoronoi::ErrorKind::Internal, "at {distance}: {e}"),
        }
    }
}

/// LibreCAD's mik2.dxf as the library is given it with exact numbers: a
/// circle of radius 4, a line along the tangent at its top and a line out
/// from its rightmost point, split. Here the tangency is exact and decided
/// so (the drawing as the program reads it is split at both roots of it,
/// 1.7e-7 apart: `cli/tests/real_dxf_parts.rs`,
/// `minimised_tangencies_split_at_both_roots`). Inside, the offset is the
/// circle of radius 4 - d exactly; outside, the chords' answer or a
/// refusal.
#[test]
fn a_circle_under_its_tangent_split_at_both_roots() {
    // as drawn, and far from the origin (shifts exact in binary: the
    // tangency stays exact)
    for (dx, dy) in [(0.0, 0.0), (1024.0, -1024.0), (1048576.0, 1048576.0)] {
        let p = |x: f64, y: f64| Point::new(x + dx, y + dy);
        let ring: Ring = vec![(p(13.0, 0.0), 1.0), (p(5.0, 0.0), 1.0)];
        let lines = [[p(18.0, 0.0), p(13.0, 0.0)], [p(13.000000000000002, 4.0), p(5.0, 4.0)]];
        let build = |ring: &Ring| {
            let mut b = Builder::new();
            b.add_bulged_polygon(std::slice::from_ref(ring)).unwrap();
            for l in &lines {
                b.add_segment(*l).unwrap();
            }
            b.split_crossings(true).build().unwrap()
        };
        let reference = build(&densified_ring(&ring).into_iter().map(|q| (q, 0.0)).collect());
        circle_inside_chords_outside(&build(&ring), &reference, 4.0, &[-0.5, -1.0, -2.0, -3.9], &[0.5, 2.0]);
    }
}
