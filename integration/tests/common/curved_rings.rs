//! Curved polygons as `Builder::add_bulged_polygon` takes them (rings of
//! vertices with bulges), their 256-chord references, and the checks of
//! their offsets and medial axes against those references: shared by
//! `arc_offsets.rs` (the domains as drawn) and `split_curved_domains.rs`
//! (the same split where they cross).

use super::arc_inputs::{distance, filleted_polygon, Piece};
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{CircularArc, Diagram, Offset, OffsetPiece, Point, Site};

/// Chords per arc in the reference.
pub const CHORDS: usize = 256;

/// The distance from `p` to the segment `a b`.
pub fn to_segment(p: Point, a: Point, b: Point) -> f64 {
    distance(&Site::Segment { a, b }, p)
}

/// The largest distance from a point of `from`'s polylines to `to`'s.
pub fn directed_hausdorff(from: &[Vec<Point>], to: &[Vec<Point>]) -> f64 {
    let mut worst = 0.0f64;
    for p in from.iter().flatten() {
        let mut best = f64::INFINITY;
        for ring in to {
            for k in 0..ring.len() {
                best = best.min(to_segment(*p, ring[k], ring[(k + 1) % ring.len()]));
            }
        }
        worst = worst.max(best);
    }
    worst
}

/// How far an offset piece's ends may be from their distance: 1e-9 of the
/// size, and a few ulps of the coordinates (far from the origin an ulp is
/// more than that).
pub fn piece_tolerance(rings: &[Ring], size: f64, r: f64) -> f64 {
    let magnitude = rings.iter().flatten().fold(0.0f64, |m, (p, _)| m.max(p.x.abs()).max(p.y.abs()));
    1e-9 * (size + r.abs()) + 4.0 * f64::EPSILON * magnitude
}

/// What one offset of a diagram with arcs showed.
#[derive(Default, Debug)]
pub struct Seen {
    pub offsets: usize,
    pub arc_pieces: usize,
    pub concave_pieces: usize,
    pub worst_area: f64,
    pub worst_hausdorff: f64,
}

/// The pieces of `offset` (of `d` at `distance`): closed loops, every end
/// at the distance from its site (within `tol`), no piece that is a point
/// but a loop's one whole circle (a few ulps of arc would be a whole circle
/// to G-code that prints its ends rounded), arcs beside arcs concentric at
/// the arc's radius plus or minus the distance, the band on their left
/// where the offset grows.
pub fn check_pieces(what: &str, d: &Diagram, offset: &Offset, distance: f64, tol: f64, seen: &mut Seen) {
    let r = distance.abs();
    for (l, lp) in offset.loops.iter().enumerate() {
        assert!(!lp.pieces.is_empty(), "{what}: loop {l} empty");
        for (k, piece) in lp.pieces.iter().enumerate() {
            let next = lp.pieces[(k + 1) % lp.pieces.len()];
            assert_eq!(piece.to(), next.from(), "{what}: loop {l} opens after piece {k}");
            let whole_circle = lp.pieces.len() == 1 && piece.from() == piece.to();
            assert!(
                whole_circle || piece.from().distance(piece.to()) > 1e-9 * r,
                "{what}: loop {l} piece {k} {piece:?} is a point"
            );
            let site = d.site(piece.site()).unwrap();
            for end in [piece.from(), piece.to()] {
                let off = (self::distance(&site, end) - r).abs();
                assert!(off <= tol, "{what}: loop {l} piece {k} {piece:?} ends {off:e} off the distance from {site:?}");
            }
            if let (Site::Arc(arc), OffsetPiece::Arc { centre, radius, counter_clockwise, .. }) = (site, *piece) {
                assert_eq!(centre, arc.centre(), "{what}: a piece along an arc about another centre");
                let convex = (radius - (arc.radius() + r)).abs() <= tol;
                let concave = (radius - (arc.radius() - r)).abs() <= tol;
                assert!(convex || concave, "{what}: radius {radius} beside an arc of radius {}", arc.radius());
                if distance > 0.0 {
                    assert_eq!(counter_clockwise, convex, "{what}: the band is on the left of a piece");
                }
                seen.arc_pieces += 1;
                seen.concave_pieces += usize::from(concave);
            }
        }
    }
}

/// A ring as `add_bulged_polygon` takes it.
pub type Ring = Vec<(Point, f64)>;

/// A rounded rectangle `w × h` at `(x, y)` with corner radius `r`, as a
/// counter-clockwise bulged ring (reversed: clockwise).
pub fn rounded_ring(x: f64, y: f64, w: f64, h: f64, r: f64, reversed: bool) -> Ring {
    let q = (std::f64::consts::PI / 8.0).tan();
    let p = Point::new;
    let ring = vec![
        (p(x + r, y), 0.0),
        (p(x + w - r, y), q),
        (p(x + w, y + r), 0.0),
        (p(x + w, y + h - r), q),
        (p(x + w - r, y + h), 0.0),
        (p(x + r, y + h), q),
        (p(x, y + h - r), 0.0),
        (p(x, y + r), q),
    ];
    if reversed {
        reverse_ring(&ring)
    } else {
        ring
    }
}

/// The same ring walked the other way (each piece's bulge negated).
pub fn reverse_ring(ring: &Ring) -> Ring {
    let n = ring.len();
    (0..n).map(|k| (ring[n - 1 - k].0, -ring[(2 * n - 2 - k) % n].1)).collect()
}

/// A circle of radius `r` about `(x, y)` as two half circles.
pub fn circle_ring(x: f64, y: f64, r: f64) -> Ring {
    vec![(Point::new(x - r, y), 1.0), (Point::new(x + r, y), 1.0)]
}

/// A slot (stadium) from `(x, y)`: a `w × 2r` rectangle with half circles
/// on its short sides.
pub fn slot_ring(x: f64, y: f64, w: f64, r: f64) -> Ring {
    let p = Point::new;
    vec![(p(x, y), 0.0), (p(x + w, y), 1.0), (p(x + w, y + 2.0 * r), 0.0), (p(x, y + 2.0 * r), 1.0)]
}

/// A filleted convex polygon as a bulged ring (see `filleted_polygon`).
pub fn filleted_ring(rng: &mut SplitMix64, cx: f64, cy: f64, n: usize, radius: f64) -> Ring {
    filleted_polygon(rng, cx, cy, n, radius)
        .iter()
        .map(|piece| match *piece {
            Piece::Arc(arc) => (arc.start(), arc.bulge()),
            Piece::Segment(a, _) => (a, 0.0),
            Piece::Point(_) => unreachable!(),
        })
        .collect()
}

/// The ring's points with each arc replaced by `CHORDS` chords.
pub fn densified_ring(ring: &Ring) -> Vec<Point> {
    let n = ring.len();
    let mut out = Vec::new();
    for k in 0..n {
        let ((p, bulge), (q, _)) = (ring[k], ring[(k + 1) % n]);
        out.push(p);
        if bulge != 0.0 {
            let arc = CircularArc::from_bulge(p, q, bulge).unwrap();
            out.extend((1..CHORDS).map(|j| arc.point_at(j as f64 / CHORDS as f64)));
        }
    }
    out
}

/// The tangent joins of the rings: corners where a segment and an arc, or
/// two arcs, meet with one tangent.
pub fn tangent_joins(rings: &[Ring]) -> Vec<Point> {
    let mut joins = Vec::new();
    for ring in rings {
        let n = ring.len();
        let leaving = |k: usize| {
            let ((p, bulge), (q, _)) = (ring[k], ring[(k + 1) % n]);
            // a bulge's arc leaves its start turned by 2 atan(bulge) from the chord
            let turn = -2.0 * bulge.atan();
            let (dx, dy) = (q.x - p.x, q.y - p.y);
            let l = dx.hypot(dy);
            let (c, s) = (turn.cos(), turn.sin());
            Point::new((c * dx - s * dy) / l, (s * dx + c * dy) / l)
        };
        let arriving = |k: usize| {
            let ((p, bulge), (q, _)) = (ring[k], ring[(k + 1) % n]);
            let turn = 2.0 * bulge.atan();
            let (dx, dy) = (q.x - p.x, q.y - p.y);
            let l = dx.hypot(dy);
            let (c, s) = (turn.cos(), turn.sin());
            Point::new((c * dx - s * dy) / l, (s * dx + c * dy) / l)
        };
        for k in 0..n {
            let before = (k + n - 1) % n;
            let curved = ring[k].1 != 0.0 || ring[before].1 != 0.0;
            let (u, v) = (arriving(before), leaving(k));
            if curved && (u.x * v.y - u.y * v.x).abs() < 1e-9 && u.x * v.x + u.y * v.y > 0.0 {
                joins.push(ring[k].0);
            }
        }
    }
    joins
}

/// Offsets of a curved domain against its chords', both signs; piece ends
/// at the distance from their sites; arcs concentric.
pub fn check_domain_offsets_of(
    name: &str,
    (d, reference): (&Diagram, &Diagram),
    rings: &[Ring],
    distances: &[f64],
    size: f64,
) -> Seen {
    let mut seen = Seen::default();
    for &r in distances {
        let what = format!("{name} at {r}");
        let offset = d.offset(r).unwrap_or_else(|e| panic!("{what}: {e}"));
        let want = reference.offset(r).unwrap();
        check_pieces(&what, &d, &offset, r, piece_tolerance(rings, size, r), &mut seen);
        assert_eq!(offset.loops.len(), want.loops.len(), "{what}: loops, against the chords'");
        for (a, b) in offset.loops.iter().zip(&want.loops) {
            assert_eq!(a.hole, b.hole, "{what}: holes");
        }
        let (area, reference_area) = (offset.area(), want.area());
        // (both empty beyond the deepest point)
        let relative =
            if area == 0.0 && reference_area == 0.0 { 0.0 } else { (area - reference_area).abs() / reference_area.abs() };
        assert!(relative <= 1e-4, "{what}: area {area} against the chords' {reference_area} ({relative:e})");
        let (ours, theirs) = (offset.polylines(1e-5 * size).unwrap(), want.polylines(1e-5 * size).unwrap());
        let hausdorff = directed_hausdorff(&ours, &theirs).max(directed_hausdorff(&theirs, &ours));
        assert!(hausdorff <= 1e-3 * size, "{what}: Hausdorff distance {hausdorff}");
        seen.offsets += 1;
        seen.worst_area = seen.worst_area.max(relative);
        seen.worst_hausdorff = seen.worst_hausdorff.max(hausdorff / size);
    }
    eprintln!("{name}: {seen:?}");
    seen
}

/// The medial axis of a curved domain: every sample inside, at its
/// clearance from the nearest site; no branch ends at a tangent join
/// (`joins`, see `tangent_joins`); the
/// largest inscribed circle is the chords' (to their sagitta).
pub fn check_medial_axis_of(name: &str, (d, reference): (&Diagram, &Diagram), joins: &[Point], size: f64) -> usize {
    let sites: Vec<Site> = d.site_ids().map(|s| d.site(s).unwrap()).collect();
    let axis = d.medial_axis();
    let mut samples = 0;
    for chain in &axis.chains {
        let points = d.sample_chain(chain, 1e-5 * size).unwrap_or_else(|| panic!("{name}: a chain without samples"));
        for [x, y, r] in points {
            let p = Point::new(x, y);
            let nearest = sites.iter().map(|s| distance(s, p)).fold(f64::INFINITY, f64::min);
            assert!((nearest - r).abs() <= 1e-6 * size, "{name}: sample {p:?} r {r}, nearest site at {nearest}");
            if r > 1e-9 * size {
                assert_eq!(d.locate_point(p), Some(segvoronoi::Location::Inside), "{name}: sample {p:?} r {r}");
            }
            samples += 1;
        }
        for piece in &chain.pieces {
            for end in piece.ends {
                if let segvoronoi::EdgeEnd::Vertex(v) = end {
                    let at = d.vertex(v).unwrap().position;
                    assert!(
                        joins.iter().all(|j| j.distance(at) > 1e-9 * size),
                        "{name}: the medial axis reaches the tangent join at {at:?}"
                    );
                }
            }
        }
    }
    let (centre, radius) = d.max_inscribed_circle().expect("a domain");
    let (_, want) = reference.max_inscribed_circle().unwrap();
    let nearest = sites.iter().map(|s| distance(s, centre)).fold(f64::INFINITY, f64::min);
    assert!((nearest - radius).abs() <= 1e-9 * size, "{name}: inscribed circle {centre:?} {radius}, nearest {nearest}");
    assert!((radius - want).abs() <= 1e-3 * size, "{name}: inscribed radius {radius} against the chords' {want}");
    assert_eq!(d.locate_point(centre), Some(segvoronoi::Location::Inside), "{name}");
    eprintln!("{name}: {samples} samples, {} chains, inscribed {radius} (chords {want})", axis.chains.len());
    samples
}

/// `ring` with a vertex inserted in every straight side: at a random point
/// along it (rounded: a vertex a few ulps off the line), and where
/// `nudge` is set moved by one ulp across the side as well; the whole
/// moved by `shift` (far from the origin the sides' ends round too, and
/// the joins with the arcs come out an ulp off tangent).
pub fn with_straight_vertices(ring: &Ring, rng: &mut SplitMix64, nudge: bool, shift: Point) -> Ring {
    let n = ring.len();
    let moved = |q: Point| Point::new(q.x + shift.x, q.y + shift.y);
    let mut out = Vec::with_capacity(2 * n);
    for k in 0..n {
        let ((a, bulge), (b, _)) = (ring[k], ring[(k + 1) % n]);
        out.push((moved(a), bulge));
        if bulge == 0.0 {
            let t = 0.05 + 0.9 * rng.unit();
            let mut m = moved(Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)));
            if nudge {
                // about one ulp of the side's coordinates toward its left
                // (one ulp of 0.0 would be a subnormal, out of range)
                let ulp = f64::EPSILON * [a.x, a.y, b.x, b.y].iter().fold(0.0f64, |m, v| m.max((v + shift.x.max(shift.y)).abs()));
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let length = dx.hypot(dy);
                m = Point::new(m.x - ulp * dy / length, m.y + ulp * dx / length);
            }
            out.push((m, 0.0));
        }
    }
    out
}
