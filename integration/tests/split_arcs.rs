//! `Builder::split_crossings` with circular arcs (issue 32): inputs whose
//! arcs and segments cross, touch, overlap or carry points are cut into
//! pieces that meet only at shared ends (`split::arcs`), and the diagram
//! is that of the pieces. Checked three ways, on named cases and a random
//! family nobody tuned for, each also reversed, shuffled, mirrored and
//! scaled by powers of two:
//! - the diagram of the pieces passes the brute-force audit of `arcs.rs`
//!   (empty circles, edges equidistant, neighbours on a grid);
//! - every input is covered by its pieces (points along it lie within the
//!   reported displacement of a piece of the same input), and every piece
//!   lies within that displacement of its input (at its ends and middle);
//! - the displacement is a few pixels (2^-46 of the input's magnitude).

mod common;

use common::arc_inputs::{add_pieces, audit, distance, variants, Piece};
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Diagram, ErrorKind, Point, Site};

fn split_build(pieces: &[Piece]) -> Result<Diagram, segvoronoi::Error> {
    let mut b = Builder::new();
    add_pieces(&mut b, pieces);
    b.split_crossings(true).build()
}

/// Points along a piece (`n + 1`, ends included).
fn along(piece: &Piece, n: usize) -> Vec<Point> {
    (0..=n)
        .map(|k| {
            let t = k as f64 / n as f64;
            match *piece {
                Piece::Point(p) => p,
                Piece::Segment(a, b) => Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)),
                Piece::Arc(arc) => arc.point_at(t),
            }
        })
        .collect()
}

/// The coverage checks of the module documentation, at `reach` beyond
/// the reported displacement. An input is covered by the sites of its
/// kind; the pieces of an input arc (`inputs_of_arc_piece`, which
/// `arc_pieces_of_input` agrees with) lie along it.
fn check_covered(name: &str, d: &Diagram, pieces: &[Piece], reach: f64) {
    let moved = d.max_split_displacement() + reach;
    // each site with the input arcs it came from (none for other sites)
    let inputs = |s| d.arc_input_index(s).map_or(Vec::new(), |p| d.inputs_of_arc_piece(p).collect::<Vec<_>>());
    let sites: Vec<(Site, Vec<usize>)> = d.site_ids().map(|s| (d.site(s).unwrap(), inputs(s))).collect();
    let mut arc_index = 0;
    for piece in pieces {
        let of_kind: Vec<&Site> = match piece {
            Piece::Point(_) => continue,
            Piece::Segment(..) => sites.iter().filter(|(s, _)| matches!(s, Site::Segment { .. })).map(|(s, _)| s).collect(),
            Piece::Arc(_) => sites.iter().filter(|(s, _)| matches!(s, Site::Arc(_))).map(|(s, _)| s).collect(),
        };
        for q in along(piece, 64) {
            let nearest = of_kind.iter().map(|s| distance(s, q)).fold(f64::INFINITY, f64::min);
            assert!(nearest <= moved, "{name}: {piece:?} at {q:?} is {nearest} from the pieces (displacement {moved})");
        }
        if let Piece::Arc(arc) = piece {
            // and its pieces lie along it
            arc_index += 1;
            let own: Vec<&Site> = sites.iter().filter(|(_, i)| i.contains(&(arc_index - 1))).map(|(s, _)| s).collect();
            assert!(!own.is_empty(), "{name}: no piece of {arc:?}");
            assert_eq!(d.arc_pieces_of_input(arc_index - 1).len(), own.len(), "{name}: {arc:?}");
            for s in &own {
                let Site::Arc(a) = s else { panic!("{name}: an arc's piece {s:?}") };
                for q in [a.start(), a.end(), a.midpoint()] {
                    let off = distance(&Site::Arc(*arc), q);
                    assert!(off <= moved, "{name}: piece {a:?} of {arc:?} is {off} off it at {q:?}");
                }
            }
        }
    }
}

/// Splits `pieces` in every variant: it builds (or, where `may_refuse`,
/// is refused with `Internal` by the build's own checks: never answered
/// wrong), passes the audit (to 1e-8 of the drawing's `size`) and the
/// coverage (the pieces within 1e-12 of the coordinates' `magnitude` of
/// the input). Returns the plain build's stats' (crossings, overlaps,
/// touchings), or zeros where it was refused, and the variants refused.
fn check_split_all_ways(
    name: &str,
    pieces: &[Piece],
    (size, magnitude): (f64, f64),
    seed: u64,
    may_refuse: bool,
) -> ((usize, usize, usize), Vec<String>) {
    let mut plain = None;
    let mut refused = Vec::new();
    for (way, input, scale) in variants(pieces, seed) {
        let d = match split_build(&input) {
            Ok(d) => d,
            Err(e) if may_refuse && e.kind() == ErrorKind::Internal => {
                refused.push(format!("{name} {way}: {e}"));
                plain.get_or_insert((0, 0, 0));
                continue;
            }
            Err(e) => panic!("{name} {way}: {e}: {input:?}"),
        };
        d.validate().unwrap_or_else(|e| panic!("{name} {way}: invalid: {e:?}"));
        let tol = 1e-8 * size * scale;
        let failures = audit(&d, tol);
        assert!(failures.is_empty(), "{name} {way}: {} audit failures, first: {}", failures.len(), failures[0]);
        check_covered(&format!("{name} {way}"), &d, &input, 1e-12 * magnitude * scale);
        let moved = d.max_split_displacement();
        assert!(moved <= 1e-12 * magnitude * scale, "{name} {way}: displacement {moved}");
        let s = d.stats();
        plain.get_or_insert((s.crossings, s.overlaps, s.touchings));
    }
    (plain.unwrap(), refused)
}

#[test]
fn named_contacts_of_arcs_are_split() {
    let p = Point::new;
    let arc = |s: Point, e: Point, b: f64| Piece::Arc(CircularArc::from_bulge(s, e, b).unwrap());
    let through = |s: Point, m: Point, e: Point| Piece::Arc(CircularArc::through(s, m, e).unwrap());
    // (name, pieces, size, the plain build's (crossings, overlaps, touchings))
    let cases: Vec<(&str, Vec<Piece>, f64, (usize, usize, usize))> = vec![
        (
            "two half circles crossing a line and a line crossing both",
            vec![
                arc(p(0.0, 0.0), p(4.0, 0.0), 1.0),
                arc(p(0.0, 1.0), p(4.0, 1.0), -1.0),
                Piece::Segment(p(2.0, -3.0), p(2.0, 5.0)),
                Piece::Segment(p(-1.0, 0.5), p(5.0, 0.5)),
            ],
            8.0,
            (3, 0, 0),
        ),
        (
            "two arcs crossing twice",
            vec![arc(p(0.0, 0.0), p(4.0, 0.0), 1.0), arc(p(-0.5, -3.0), p(4.5, -3.0), -1.0)],
            8.0,
            (1, 0, 0),
        ),
        (
            "a segment tangent to an arc",
            vec![arc(p(0.0, 0.0), p(4.0, 0.0), 1.0), Piece::Segment(p(0.0, -2.0), p(4.0, -2.0))],
            8.0,
            (0, 0, 1),
        ),
        ("a point on an arc", vec![arc(p(0.0, 0.0), p(4.0, 0.0), 1.0), Piece::Point(p(2.0, -2.0))], 8.0, (0, 0, 1)),
        (
            "a segment ending on an arc (a T)",
            vec![arc(p(0.0, 0.0), p(4.0, 0.0), 1.0), Piece::Segment(p(2.0, -2.0), p(2.0, -5.0))],
            8.0,
            (0, 0, 1),
        ),
        (
            "two arcs of one circle overlapping",
            vec![arc(p(-2.0, 0.0), p(2.0, 0.0), 1.0), through(p(0.0, 2.0), p(2.0, 0.0), p(0.0, -2.0))],
            4.0,
            (0, 1, 0),
        ),
        ("an arc twice", vec![arc(p(-2.0, 0.0), p(2.0, 0.0), 0.5), arc(p(2.0, 0.0), p(-2.0, 0.0), -0.5)], 4.0, (0, 1, 0)),
        (
            "a circle of two half circles cut by a line through its centre and a chord",
            vec![
                arc(p(-2.0, 0.0), p(2.0, 0.0), 1.0),
                arc(p(2.0, 0.0), p(-2.0, 0.0), 1.0),
                Piece::Segment(p(-3.0, -1.0), p(3.0, 1.0)),
                Piece::Segment(p(-1.0, -3.0), p(1.0, 3.0)),
            ],
            6.0,
            (5, 0, 0),
        ),
        (
            "an arc's end on another arc, and a point where they cross",
            vec![arc(p(0.0, 0.0), p(4.0, 0.0), 1.0), arc(p(2.0, -2.0), p(6.0, -2.0), 0.6), Piece::Point(p(3.0, 1.5))],
            8.0,
            (0, 0, 1),
        ),
    ];
    for (k, (name, pieces, size, want)) in cases.into_iter().enumerate() {
        let (got, _) = check_split_all_ways(name, &pieces, (size, size), k as u64, false);
        assert_eq!(got, want, "{name}: (crossings, overlaps, touchings)");
    }
}

/// Random arcs and segments in a 10 × 10 square, crossing each other about
/// ten times each, and a few points; 40 seeds (`SPLIT_SEEDS=N` for more),
/// each in every variant (240 builds). Every build is answered right (the
/// audit, the coverage); at 1000 seeds, 6000 of 6000 (5999 until the arcs'
/// solver tried an arc's end that is a point site first: seed 541
/// shuffled was refused, `arcs.rs` `refused_or_right`). 51 of the 240 were refused by the build's own
/// checks of its arc vertices until the edges of a point site were taken
/// round the point (`arcs.rs` "a point a hair from a segment ending on an
/// arc, inside its circle"); before that, 13 of the 40 plain builds until
/// "an arc's start a hair inside another arc's circle" and "an arc past
/// another's end" (`SPLIT_SURVEY=1` lists the plain builds).
#[test]
fn random_crossing_arcs_and_segments_are_split_right() {
    let seeds = std::env::var("SPLIT_SEEDS").ok().and_then(|n| n.parse().ok()).unwrap_or(40usize);
    let (mut contacts, mut refused) = (0, Vec::new());
    for (seed, pieces) in random_drawings(seeds).into_iter().enumerate() {
        if std::env::var_os("SPLIT_SURVEY").is_some() {
            match split_build(&pieces) {
                Ok(d) => eprintln!("seed {seed}: ok, {} audit failures", audit(&d, 2e-7).len()),
                Err(e) => eprintln!("seed {seed}: {e}"),
            }
            continue;
        }
        let ((c, o, t), no) = check_split_all_ways(&format!("seed {seed}"), &pieces, (20.0, 20.0), seed as u64, true);
        contacts += c + o + t;
        refused.extend(no);
    }
    eprintln!("{} of {} builds refused:\n{}", refused.len(), 6 * seeds, refused.join("\n"));
    assert!(contacts > 300, "{contacts} contacts");
    assert!(refused.is_empty(), "{} refused: {refused:?}", refused.len());
}

/// The drawings of the random family that its wide run (`SPLIT_SEEDS=500`)
/// found refused or answered wrong, each in every variant, none refused:
/// 75 (scaled down), 96 (shuffled), 189 (shuffled) and 476 (plain, scaled
/// both ways) were refused by the arcs' vertex checks (`arcs.rs`
/// minimised regressions "two arcs from one end...", "an arc's start a
/// hair outside another arc's circle...", "an arc ending a hair outside
/// another's circle, cut below its end"); 96
/// (plain) and 223 (plain) had an edge's polyline off its edge, through a
/// stretch of its bisector past its ends: the edge of a point inside an
/// arc's circle runs round the point (223: the polyline went round the
/// needle's far end, by the arc's centre), and the edge of two vertices of
/// the same three sites 4e-7 apart has its ends the other way round than
/// its sites say (96: round the point it would be a loop), which the third
/// sites of its end vertices tell (`bisector_point_of_edge`).
#[test]
fn random_drawings_the_wide_run_found() {
    let drawings = random_drawings(477);
    for seed in [75, 96, 189, 223, 476] {
        let (_, refused) = check_split_all_ways(&format!("seed {seed}"), &drawings[seed], (20.0, 20.0), seed as u64, false);
        assert!(refused.is_empty());
    }
}

/// The first 20 drawings of the random family a million from the origin,
/// (10^6, -10^6) added to every coordinate (so rounded there: other
/// inputs than at the origin), each in every variant (120 builds): the
/// split's pixels, the arcs' predicates and solvers where the coordinates
/// carry 20 bits fewer below the drawing's size.
#[test]
fn random_crossing_arcs_and_segments_far_from_the_origin() {
    let far = |p: Point| Point::new(p.x + 1e6, p.y - 1e6);
    let mut refused = Vec::new();
    for (seed, pieces) in random_drawings(20).into_iter().enumerate() {
        let moved: Vec<Piece> = pieces
            .iter()
            .map(|&piece| match piece {
                Piece::Point(p) => Piece::Point(far(p)),
                Piece::Segment(a, b) => Piece::Segment(far(a), far(b)),
                Piece::Arc(arc) => Piece::Arc(CircularArc::from_bulge(far(arc.start()), far(arc.end()), arc.bulge()).unwrap()),
            })
            .collect();
        let (_, no) = check_split_all_ways(&format!("seed {seed} far"), &moved, (20.0, 2e6), seed as u64, true);
        refused.extend(no);
    }
    eprintln!("{} of 120 builds refused:\n{}", refused.len(), refused.join("\n"));
    assert!(refused.is_empty(), "{} refused: {refused:?}", refused.len());
}

/// `n` drawings of 6 random arcs (bulges in [-1, 1], none flatter than
/// 0.05), 6 random segments and 3 points in a 10 × 10 square.
fn random_drawings(n: usize) -> Vec<Vec<Piece>> {
    let mut rng = SplitMix64(20261206);
    let mut unit = move || rng.unit();
    (0..n)
        .map(|_| {
            let mut pieces = Vec::new();
            let point = |u: &mut dyn FnMut() -> f64| Point::new(10.0 * u(), 10.0 * u());
            for _ in 0..6 {
                let (s, e) = (point(&mut unit), point(&mut unit));
                let bulge = 2.0 * unit() - 1.0;
                if let Ok(arc) = CircularArc::from_bulge(s, e, if bulge.abs() < 0.05 { 0.5 } else { bulge }) {
                    pieces.push(Piece::Arc(arc));
                }
            }
            for _ in 0..6 {
                pieces.push(Piece::Segment(point(&mut unit), point(&mut unit)));
            }
            for _ in 0..3 {
                pieces.push(Piece::Point(point(&mut unit)));
            }
            pieces
        })
        .collect()
}

/// Arcs and polygons split together (refused before): a half circle
/// obstacle across a triangle is cut where it crosses its three sides (the
/// bottom twice), the triangle's domain unchanged
/// (`split_curved_domains.rs` checks curved rings so).
#[test]
fn arcs_with_polygons_split_together() {
    let mut b = Builder::new();
    b.add_arc(CircularArc::from_bulge([0.0, 0.0], [4.0, 0.0], 1.0).unwrap()).unwrap();
    b.add_polygon(&[&[[0.0, -1.0], [4.0, -1.0], [2.0, 3.0]][..]]).unwrap();
    let d = b.split_crossings(true).build().unwrap();
    assert_eq!(d.stats().crossings, 3); // (a pair with an arc counts once)
    assert_eq!(d.arc_pieces_of_input(0).len(), 5);
    let p = Point::new;
    assert_eq!(d.locate_point(p(2.0, 0.0)), Some(segvoronoi::Location::Inside));
    assert_eq!(d.locate_point(p(0.2, 1.0)), Some(segvoronoi::Location::Outside));
}

/// Arcs beyond the exact range are refused as without splitting (the
/// cuts could land past the largest double), not as crossing: the C
/// fuzzer's case of a point at 1.8e308 beside 1e-300.
#[test]
fn arcs_beyond_the_exact_range_are_refused_as_such_with_splitting() {
    let mut b = Builder::new();
    b.add_arc(CircularArc::from_bulge([-3.0, -2e-300], [2e-300, 1.7976931348623157e308], -1.0).unwrap()).unwrap();
    b.add_segment([[-3.0, 1.0], [3.0, -1.0]]).unwrap();
    let e = b.split_crossings(true).build().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::UnsupportedRange, "{e}");
}

/// What users have beside arcs: a point exactly on a segment, a straight
/// (180°) vertex where two segments continue each other across an arc, and
/// the whole a million from the origin (the coordinates rounded there).
#[test]
fn a_point_on_a_segment_and_a_straight_vertex_far_from_the_origin() {
    for (ox, oy) in [(0.0, 0.0), (1e6, -1e6)] {
        let p = |x: f64, y: f64| Point::new(ox + x, oy + y);
        let pieces = vec![
            Piece::Arc(CircularArc::from_bulge(p(0.0, 0.0), p(4.0, 0.0), 1.0).unwrap()),
            // straight at (2, 1): two segments on one line, crossing the arc
            Piece::Segment(p(2.0, 1.0), p(2.0, -3.0)),
            Piece::Segment(p(2.0, 3.0), p(2.0, 1.0)),
            // a point exactly on a segment that crosses the arc
            Piece::Segment(p(-1.0, -1.0), p(5.0, -1.0)),
            Piece::Point(p(1.0, -1.0)),
        ];
        let name = format!("point on a segment, straight vertex at ({ox}, {oy})");
        let ((c, _, t), refused) = check_split_all_ways(&name, &pieces, (8.0, 8.0 + ox.abs()), 7, false);
        assert!(refused.is_empty());
        // the vertical line crosses the arc, the horizontal one crosses it
        // twice (one pair) and the vertical line; the point touches
        assert!(c >= 3 && t >= 1, "{name}: crossings {c}, touchings {t}");
    }
}

/// The area of the intersection of two discs of radii `r1` and `r2`
/// whose centres are `d` apart.
fn lens_area(r1: f64, r2: f64, d: f64) -> f64 {
    if d >= r1 + r2 {
        return 0.0;
    }
    if d <= (r1 - r2).abs() {
        return std::f64::consts::PI * r1.min(r2).powi(2);
    }
    let kite = ((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2)).sqrt();
    r1 * r1 * ((d * d + r1 * r1 - r2 * r2) / (2.0 * d * r1)).acos()
        + r2 * r2 * ((d * d + r2 * r2 - r1 * r1) / (2.0 * d * r2)).acos()
        - 0.5 * kite
}

/// LibreCAD's t7: two circles of radius 5, centres 5 apart, each given as
/// two half circles, split where they cross. A piece the split cuts from
/// a half circle is a hair flatter than its circle, so at its far end it
/// meets the next half circle with their circles 4.6e-12 apart; the
/// arcs' solver took a root of those two (near) equations 5e12 away, and
/// the offsets were refused or went wrong. The offsets at `t` are exact:
/// the union of two annuli, by inclusion and exclusion of lens areas.
/// Also with the circles 10 apart (touching at one point, which the split
/// cuts), with a point exactly on the upper circle (a Pythagorean point:
/// the region is the same), and in every variant plus a million from the
/// origin.
#[test]
fn two_circles_of_half_circles_crossing() {
    let p = Point::new;
    for apart in [5.0, 10.0] {
        let mut pieces = Vec::new();
        for cy in [0.5 * apart, -0.5 * apart] {
            pieces.push(Piece::Arc(CircularArc::from_bulge(p(5.0, cy), p(-5.0, cy), 1.0).unwrap()));
            pieces.push(Piece::Arc(CircularArc::from_bulge(p(-5.0, cy), p(5.0, cy), 1.0).unwrap()));
        }
        pieces.push(Piece::Point(p(3.0, 0.5 * apart + 4.0)));
        let far = 1e6;
        let moved: Vec<Piece> = pieces
            .iter()
            .map(|&piece| match piece {
                Piece::Arc(a) => Piece::Arc(
                    CircularArc::from_bulge(p(a.start().x + far, a.start().y + far), p(a.end().x + far, a.end().y + far), 1.0)
                        .unwrap(),
                ),
                Piece::Point(q) => Piece::Point(p(q.x + far, q.y + far)),
                other => other,
            })
            .collect();
        let mut ways = variants(&pieces, 7);
        ways.push(("far out", moved, 1.0));
        for (way, input, scale) in ways {
            let way = format!("{apart} apart, {way}");
            let d = split_build(&input).unwrap_or_else(|e| panic!("{way}: {e}"));
            d.validate().unwrap_or_else(|e| panic!("{way}: invalid: {e:?}"));
            let origin = input.iter().find_map(|piece| if let Piece::Arc(a) = piece { Some(a.start()) } else { None }).unwrap();
            // (far out, the split moves the crossings by up to 3e-9, which
            // leaves the pieces at the circles' right and left ends 1.4e-9
            // smaller than their circles, and their vertex with those ends'
            // points on the axis of symmetry a genuine one, 2.4e9 out)
            for v in d.vertices().filter(|_| !way.ends_with("far out")) {
                assert!(
                    v.position.distance(origin) < 100.0 * scale,
                    "{way}: vertex {:?} at {:?}, clearance {:e}",
                    v.id,
                    v.position,
                    v.clearance
                );
            }
            for t in [0.5, 1.0, 2.0] {
                let (outer, inner) = (5.0 + t, 5.0 - t);
                let annulus = std::f64::consts::PI * (outer * outer - inner * inner);
                let both = lens_area(outer, outer, apart) - 2.0 * lens_area(inner, outer, apart) + lens_area(inner, inner, apart);
                let want = (2.0 * annulus - both) * scale * scale;
                let o = d.offset(t * scale).unwrap_or_else(|e| panic!("{way}, offset {t}: {e}"));
                let area = o.area();
                assert!((area - want).abs() <= 1e-9 * want, "{way}, offset {t}: area {area} against {want}");
            }
        }
    }
}
