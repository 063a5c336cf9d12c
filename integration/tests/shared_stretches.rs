//! Polygon rings that share a stretch (issue 27): two squares of a
//! MultiPolygon along one edge or part of one, a hole along its shell's
//! edge, a spike out and back, blocks of cells sharing edges, three copies
//! of one ring. By the even-odd rule two copies of a stretch cancel; the
//! build drops them, exactly, and the domain is the even-odd region of the
//! rings as given.
//!
//! Each case comes with the same domain drawn without the shared stretches
//! (by hand, with the same vertices, so as a set of sites it is the same
//! input), and sometimes its area in closed form. The diagram of the rings
//! sharing stretches must have exactly the sites of the one drawn without
//! them (no piece of a cancelled stretch, no point left alone where every
//! edge cancelled), the same domain at every point of a grid (exact integer
//! even-odd test of the reference), the same medial axis (every sample at
//! its clearance from the reference boundary, the same largest inscribed
//! circle), and the same offsets at distances of both signs (areas, and
//! every point of every loop at its distance from the reference boundary).
//! Every case is tried reversed, with its rings started elsewhere, its
//! polygons shuffled, mirrored, scaled by powers of two and moved far from
//! the origin.

mod common;

use segvoronoi::{Builder, Diagram, ErrorKind, Location, Point, Site};

/// A point in integer units.
type V = [i64; 2];

/// An exact placement: `x -> (±x + t) · 2^k`, `y -> (y + t) · 2^k`.
#[derive(Clone, Copy, Debug)]
struct Place {
    mirror: bool,
    k: i32,
    t: f64,
}

const PLACES: [Place; 5] = [
    Place { mirror: false, k: 0, t: 0.0 },
    Place { mirror: true, k: 0, t: 0.0 },
    Place { mirror: false, k: -7, t: 1e6 },
    Place { mirror: true, k: 30, t: -3e9 },
    Place { mirror: false, k: -200, t: 0.0 },
];

impl Place {
    /// A point given in eighths of a unit.
    fn at8(&self, [x, y]: V) -> Point {
        let f = 2f64.powi(self.k);
        let x = x as f64 / 8.0;
        Point::new((if self.mirror { -x } else { x } + self.t) * f, (y as f64 / 8.0 + self.t) * f)
    }

    fn at(&self, [x, y]: V) -> Point {
        self.at8([8 * x, 8 * y])
    }

    fn unit(&self) -> f64 {
        2f64.powi(self.k)
    }
}

/// Polygons, each its rings, in integer units.
type Polygons = Vec<Vec<Vec<V>>>;

fn square(x: i64, y: i64, side: i64) -> Vec<V> {
    vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
}

fn builder(polygons: &Polygons, place: Place) -> Builder {
    let mut b = Builder::new();
    for polygon in polygons {
        let rings: Vec<Vec<[f64; 2]>> =
            polygon.iter().map(|r| r.iter().map(|&v| place.at(v)).map(|p| [p.x, p.y]).collect()).collect();
        b.add_polygon(&rings).expect("a polygon");
    }
    b
}

fn cross(a: V, b: V, c: V) -> i64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Where `q` (in eighths) lies against `rings` by the even-odd rule,
/// exactly (the reference rings share no stretch).
fn exact_location(rings: &[Vec<V>], q: V) -> Location {
    let mut odd = false;
    for ring in rings {
        for k in 0..ring.len() {
            let (a, b) = (ring[k].map(|c| 8 * c), ring[(k + 1) % ring.len()].map(|c| 8 * c));
            let within = q[0] >= a[0].min(b[0]) && q[0] <= a[0].max(b[0]) && q[1] >= a[1].min(b[1]) && q[1] <= a[1].max(b[1]);
            if cross(a, b, q) == 0 && within {
                return Location::Boundary;
            }
            if (a[1] > q[1]) != (b[1] > q[1]) {
                let den = b[1] - a[1];
                let (lhs, rhs) = ((q[0] - a[0]) * den, (q[1] - a[1]) * (b[0] - a[0]));
                if (den > 0 && lhs < rhs) || (den < 0 && lhs > rhs) {
                    odd = !odd;
                }
            }
        }
    }
    if odd {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// The sites of a diagram as sorted keys: points, and segments with their
/// ends in order (the same set whatever the order of the input).
fn site_keys(d: &Diagram) -> Vec<[u64; 4]> {
    let key = |p: Point| [p.x.to_bits(), p.y.to_bits()];
    let mut keys: Vec<[u64; 4]> = (0..d.site_count())
        .map(|s| match d.site(segvoronoi::SiteId::from_index(s)).unwrap() {
            Site::Point(p) => [key(p)[0], key(p)[1], u64::MAX, u64::MAX],
            Site::Segment { a, b } => {
                let (a, b) = if key(a) <= key(b) { (key(a), key(b)) } else { (key(b), key(a)) };
                [a[0], a[1], b[0], b[1]]
            }
            _ => unreachable!("a point or a segment"),
        })
        .collect();
    keys.sort_unstable();
    keys
}

/// One case: polygons sharing stretches, the same domain drawn without
/// them, how many ring pieces cancel, and the area of the domain when it
/// has a closed form (in square units).
struct Case {
    name: &'static str,
    polygons: Polygons,
    reference: Vec<Vec<V>>,
    cancelled: usize,
    /// The offset's area at distance `d` (units), when known in closed
    /// form.
    area: Option<fn(f64) -> f64>,
}

/// The distances tried, in units.
const DISTANCES: [f64; 6] = [-1.5, -0.75, -0.125, 0.25, 1.0, 3.0];

/// Builds `polygons` at `place` and checks them against the reference.
fn check(case: &Case, polygons: &Polygons, place: Place, what: &str) {
    let what = format!("{}, {what}, at {place:?}", case.name);
    let d = builder(polygons, place).build().unwrap_or_else(|e| panic!("{what}: {e}"));
    d.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(d.stats().cancelled_ring_pieces, case.cancelled, "{what}");
    assert!(d.has_domain(), "{what}");
    let r = builder(&vec![case.reference.clone()], place).build().unwrap_or_else(|e| panic!("{what}: reference: {e}"));
    assert_eq!(r.stats().cancelled_ring_pieces, 0, "{what}");
    // the same sites: no cancelled piece, no point left alone
    assert_eq!(site_keys(&d), site_keys(&r), "{what}: sites");
    assert_eq!(d.piece_count(), d.stats().pieces, "{what}");
    // every piece came from its input segments, all of them ring segments
    let inputs = d.stats().input_segments;
    for p in 0..d.piece_count() {
        assert!(d.inputs_of_piece(p).all(|j| j < inputs) && d.inputs_of_piece(p).len() % 2 == 1, "{what}: piece {p}");
    }

    let unit = place.unit();
    let extent = case.reference.iter().flatten().flatten().fold(0.0f64, |m, &c| m.max(c.abs() as f64));
    let tol = 1e-12 * (extent + place.t.abs()) * unit + 1e-9 * unit;
    // the domain on a grid of eighths, boundary points included
    let (mut lo, mut hi) = ([i64::MAX; 2], [i64::MIN; 2]);
    for v in case.reference.iter().flatten() {
        for c in 0..2 {
            lo[c] = lo[c].min(8 * v[c] - 16);
            hi[c] = hi[c].max(8 * v[c] + 16);
        }
    }
    for x in (lo[0]..=hi[0]).step_by(3) {
        for y in (lo[1]..=hi[1]).step_by(3) {
            let expected = exact_location(&case.reference, [x, y]);
            assert_eq!(d.locate_point(place.at8([x, y])), Some(expected), "{what}: ({x}/8, {y}/8)");
        }
    }
    // every vertex where the reference's vertex at its place is
    for v in d.vertices() {
        let twin = r.vertices().find(|w| (w.position.x - v.position.x).hypot(w.position.y - v.position.y) <= tol);
        let twin = twin.unwrap_or_else(|| panic!("{what}: no reference vertex at {:?}", v.position));
        assert_eq!(d.vertex_location(v.id), r.vertex_location(twin.id), "{what}: vertex at {:?}", v.position);
    }

    // the medial axis against the reference boundary
    let boundary = common::ring_segments(
        &case.reference.iter().map(|ring| ring.iter().map(|&v| place.at(v)).map(|p| [p.x, p.y]).collect()).collect::<Vec<_>>(),
    );
    let nearest = |q: Point| boundary.iter().map(|s| s.distance(q)).fold(f64::INFINITY, f64::min);
    let axis = d.medial_axis();
    let mut length = 0.0;
    for chain in &axis.chains {
        let samples = d.sample_chain(chain, 1e-3 * unit).unwrap();
        for w in samples.windows(2) {
            length += (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        }
        for [x, y, clearance] in samples {
            let q = Point::new(x, y);
            assert!((nearest(q) - clearance).abs() <= tol + 1e-9 * clearance, "{what}: axis at {q:?}");
            assert_ne!(d.locate_point(q), Some(Location::Outside), "{what}: axis at {q:?}");
        }
    }
    let reference_length: f64 = r
        .medial_axis()
        .chains
        .iter()
        .map(|c| {
            r.sample_chain(c, 1e-3 * unit).unwrap().windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum::<f64>()
        })
        .sum();
    assert!((length - reference_length).abs() <= 1e-9 * reference_length, "{what}: axis length {length} for {reference_length}");
    let (c, radius) = d.max_inscribed_circle().unwrap();
    let (rc, rr) = r.max_inscribed_circle().unwrap();
    assert!((radius - rr).abs() <= tol && (nearest(c) - radius).abs() <= tol, "{what}: circle {c:?} {radius}, {rc:?} {rr}");

    // the offsets: areas as the reference's (and the closed form), every
    // loop point at its distance from the reference boundary
    let distances: Vec<f64> = DISTANCES.iter().map(|&x| x * unit).collect();
    let offsets = d.offsets(&distances).unwrap();
    let reference = r.offsets(&distances).unwrap();
    for ((o, ro), &dist) in offsets.iter().zip(&reference).zip(&distances) {
        let at = format!("{what} at {}", dist / unit);
        assert_eq!(o.loops.len(), ro.loops.len(), "{at}: loops");
        let (area, reference_area) = (o.area(), ro.area());
        assert!(
            (area - reference_area).abs() <= 1e-12 * reference_area.abs().max(unit * unit),
            "{at}: {area} for {reference_area}"
        );
        if let Some(f) = case.area {
            let want = f(dist / unit) * unit * unit;
            assert!((area - want).abs() <= 1e-9 * want, "{at}: area {area}, closed form {want}");
        }
        for points in o.polylines(1e-4 * unit).unwrap() {
            for q in points {
                assert!((nearest(q) - dist.abs()).abs() <= 2e-4 * unit + tol, "{at}: {q:?} is {} off", nearest(q));
            }
        }
    }
}

/// The case as given, reversed (every ring, and the polygons' order),
/// with every ring started at its second point, with the polygons in a
/// shuffled order, each at every placement.
fn check_everywhere(case: &Case) {
    let reversed: Polygons =
        case.polygons.iter().rev().map(|p| p.iter().map(|r| r.iter().rev().copied().collect()).collect()).collect();
    let rotated: Polygons = case.polygons.iter().map(|p| p.iter().map(|r| [&r[1..], &r[..1]].concat()).collect()).collect();
    let mut shuffled = case.polygons.clone();
    let n = shuffled.len();
    for k in 0..n {
        shuffled.swap(k, (k * 7 + 3) % n);
    }
    for place in PLACES {
        check(case, &case.polygons, place, "as given");
        check(case, &reversed, place, "reversed");
        check(case, &rotated, place, "rotated");
        check(case, &shuffled, place, "shuffled");
    }
}

fn rectangle_area(w: f64, h: f64) -> impl Fn(f64) -> f64 {
    move |d| if d >= 0.0 { w * h + 2.0 * (w + h) * d + std::f64::consts::PI * d * d } else { (w + 2.0 * d) * (h + 2.0 * d) }
}

#[test]
fn two_squares_sharing_an_edge_are_their_rectangle() {
    let case = Case {
        name: "two squares sharing an edge",
        polygons: vec![vec![square(0, 0, 4)], vec![square(4, 0, 4)]],
        reference: vec![vec![[0, 0], [4, 0], [8, 0], [8, 4], [4, 4], [0, 4]]],
        cancelled: 2,
        area: Some(|d| rectangle_area(8.0, 4.0)(d)),
    };
    check_everywhere(&case);
    // one polygon with the two squares as its rings: the same
    check_everywhere(&Case { polygons: vec![case.polygons.concat()], ..case });
}

#[test]
fn two_squares_sharing_part_of_an_edge() {
    check_everywhere(&Case {
        name: "two squares sharing part of an edge",
        polygons: vec![vec![square(0, 0, 4)], vec![square(4, 1, 2)]],
        reference: vec![vec![[0, 0], [4, 0], [4, 1], [6, 1], [6, 3], [4, 3], [4, 4], [0, 4]]],
        cancelled: 2,
        area: None,
    });
    // the small square's edge runs past the big one's corner: cut there too
    check_everywhere(&Case {
        name: "two squares sharing part of an edge past a corner",
        polygons: vec![vec![square(0, 0, 4)], vec![square(4, 2, 4)]],
        reference: vec![vec![[0, 0], [4, 0], [4, 2], [8, 2], [8, 6], [4, 6], [4, 4], [0, 4]]],
        cancelled: 2,
        area: None,
    });
}

#[test]
fn a_hole_along_its_shell_is_a_notch() {
    check_everywhere(&Case {
        name: "a hole along its shell's edge",
        polygons: vec![vec![square(0, 0, 10), vec![[0, 2], [3, 2], [3, 4], [0, 4]]]],
        reference: vec![vec![[0, 0], [10, 0], [10, 10], [0, 10], [0, 4], [3, 4], [3, 2], [0, 2]]],
        cancelled: 2,
        area: None,
    });
}

#[test]
fn a_spike_out_and_back_is_no_part_of_the_domain() {
    // out and back to the same point: its tip is no site
    check_everywhere(&Case {
        name: "a spike out and back",
        polygons: vec![vec![vec![[0, 0], [4, 0], [4, 4], [6, 4], [4, 4], [0, 4]]]],
        reference: vec![square(0, 0, 4)],
        cancelled: 2,
        area: Some(|d| rectangle_area(4.0, 4.0)(d)),
    });
    // along an edge and back part of the way
    check_everywhere(&Case {
        name: "a spike along an edge",
        polygons: vec![vec![vec![[0, 0], [6, 0], [4, 0], [4, 4], [0, 4]]]],
        reference: vec![square(0, 0, 4)],
        cancelled: 2,
        area: Some(|d| rectangle_area(4.0, 4.0)(d)),
    });
    // up and back only part of the way, then on
    check_everywhere(&Case {
        name: "a spike coming back part of the way",
        polygons: vec![vec![vec![[0, 0], [4, 0], [4, 4], [3, 4], [3, 6], [3, 5], [1, 4], [0, 4]]]],
        reference: vec![vec![[0, 0], [4, 0], [4, 4], [3, 4], [3, 5], [1, 4], [0, 4]]],
        cancelled: 2,
        area: None,
    });
}

#[test]
fn blocks_of_cells_sharing_edges() {
    // a 2 x 2 block: its middle point loses every edge and is no site
    let cells = |list: &[(i64, i64)]| list.iter().map(|&(i, j)| vec![square(4 * i, 4 * j, 4)]).collect::<Polygons>();
    check_everywhere(&Case {
        name: "a 2 x 2 block",
        polygons: cells(&[(0, 0), (1, 0), (0, 1), (1, 1)]),
        reference: vec![vec![[0, 0], [4, 0], [8, 0], [8, 4], [8, 8], [4, 8], [0, 8], [0, 4]]],
        cancelled: 8,
        area: Some(|d| rectangle_area(8.0, 8.0)(d)),
    });
    // an L of three cells, and a fourth touching it at a corner only
    check_everywhere(&Case {
        name: "an L and a cell at its corner",
        polygons: cells(&[(0, 0), (1, 0), (1, 1), (2, 2)]),
        reference: vec![vec![[0, 0], [4, 0], [8, 0], [8, 4], [8, 8], [4, 8], [4, 4], [0, 4]], square(8, 8, 4)],
        cancelled: 4,
        area: None,
    });
    // an H of seven cells: six shared edges, the outline straight through
    // eight cell corners
    check_everywhere(&Case {
        name: "an H of cells",
        polygons: cells(&[(0, 0), (2, 0), (0, 1), (1, 1), (2, 1), (0, 2), (2, 2)]),
        reference: vec![vec![
            [0, 0],
            [4, 0],
            [4, 4],
            [8, 4],
            [8, 0],
            [12, 0],
            [12, 4],
            [12, 8],
            [12, 12],
            [8, 12],
            [8, 8],
            [4, 8],
            [4, 12],
            [0, 12],
            [0, 8],
            [0, 4],
        ]],
        cancelled: 12,
        area: None,
    });
}

#[test]
fn three_copies_leave_one_and_two_leave_none() {
    check_everywhere(&Case {
        name: "three copies of a square",
        polygons: vec![vec![square(0, 0, 4)], vec![square(0, 0, 4)], vec![square(0, 0, 4)]],
        reference: vec![square(0, 0, 4)],
        cancelled: 8,
        area: Some(|d| rectangle_area(4.0, 4.0)(d)),
    });
    // a square beside two copies of another: the copies cancel (6 pieces),
    // and of the three copies of the edge between them one is left (2)
    let mut b = builder(&vec![vec![square(0, 0, 4)], vec![square(4, 0, 4).into_iter().rev().collect()]], PLACES[0]);
    b.add_polygon(&[vec![[4.0, 0.0], [8.0, 0.0], [8.0, 4.0], [4.0, 4.0]]]).unwrap();
    let d = b.build().unwrap();
    assert_eq!((d.stats().cancelled_ring_pieces, d.piece_count()), (8, 4));
    assert_eq!(d.locate_point(Point::new(6.0, 2.0)), Some(Location::Outside));
    assert_eq!(d.locate_point(Point::new(2.0, 2.0)), Some(Location::Inside));
    // two copies: nothing left, an empty domain
    let mut b = builder(&vec![vec![square(0, 0, 4)], vec![square(0, 0, 4)]], PLACES[0]);
    let d = b.build().unwrap();
    d.validate().unwrap();
    assert_eq!((d.stats().cancelled_ring_pieces, d.site_count(), d.piece_count()), (8, 0, 0));
    assert!(d.has_domain());
    assert_eq!(d.locate_point(Point::new(2.0, 2.0)), Some(Location::Outside));
    assert!(d.pieces_of_input(0).next().is_none());
    assert!(d.offsets(&[-1.0, 1.0]).unwrap().iter().all(|o| o.loops.is_empty()));
    // with a point inside, the point stays and is outside
    b.add_point([2.0, 2.0]).unwrap();
    let d = b.build().unwrap();
    assert_eq!((d.site_count(), d.locate_point(Point::new(2.0, 2.0))), (1, Some(Location::Outside)));
}

#[test]
fn overlapping_obstacles_are_still_refused() {
    // a polyline along a ring's edge: an obstacle has no even-odd rule
    let mut b = builder(&vec![vec![square(0, 0, 4)]], PLACES[0]);
    b.add_polyline(&[[1.0, 0.0], [3.0, 0.0]]).unwrap();
    let e = b.build().unwrap_err();
    assert_eq!((e.kind(), e.indices()), (ErrorKind::Intersecting, &[0, 4][..]));
    assert_eq!(
        e.message(),
        "segments 0 and 4 are collinear and overlap from (1, 0) to (3, 0) (segment 0 is in polygon 0, ring 0)"
    );
    assert_eq!(b.check().unwrap_err().message(), e.message());
    // two polylines along each other
    let mut b = Builder::new();
    b.add_polyline(&[[0.0, 0.0], [4.0, 0.0]]).unwrap();
    b.add_polyline(&[[2.0, 0.0], [6.0, 0.0]]).unwrap();
    assert_eq!(b.build().unwrap_err().message(), "segments 0 and 1 are collinear and overlap from (2, 0) to (4, 0)");
    // a polyline repeating a ring's edge merges with it, as repeats do, and
    // stays an obstacle where the ring's copies of that edge cancel
    let mut b = builder(&vec![vec![square(0, 0, 4)], vec![square(4, 0, 4)]], PLACES[0]);
    b.add_polyline(&[[4.0, 0.0], [4.0, 4.0]]).unwrap();
    let d = b.build().unwrap();
    d.validate().unwrap();
    assert_eq!((d.stats().cancelled_ring_pieces, d.piece_count()), (2, 7));
    let shared = d.pieces_of_input(8).collect::<Vec<_>>();
    assert_eq!(shared.len(), 1);
    assert_eq!(d.inputs_of_piece(shared[0]).collect::<Vec<_>>(), vec![1, 7, 8]);
    assert_eq!(d.locate_point(Point::new(3.0, 2.0)), Some(Location::Inside));
    // crossings still need split_crossings
    let e = builder(&vec![vec![square(0, 0, 4)], vec![square(2, 2, 4)]], PLACES[0]).build().unwrap_err();
    assert!(e.message().contains("cross"), "{}", e.message());
}
