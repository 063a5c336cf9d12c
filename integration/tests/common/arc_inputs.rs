//! Inputs with circular arcs for the arcs' tests (`arcs.rs`, the
//! brute-force audit of the diagram; `arc_offsets.rs`, offsets against
//! chords): the pieces a test gives the builder, the distance to a site
//! computed apart from the library, and the generators both use.

use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Diagram, Point, Site};
use segvoronoi_testgen::arcs::random_arc;

/// One input piece.
#[derive(Clone, Copy, Debug)]
pub enum Piece {
    Point(Point),
    Segment(Point, Point),
    Arc(CircularArc),
}

/// The distance from `p` to a site, computed here apart from the library.
pub fn distance(site: &Site, p: Point) -> f64 {
    match *site {
        Site::Point(q) => q.distance(p),
        Site::Segment { a, b } => {
            // in coordinates of size about 1 (a power of two), so that the
            // products neither underflow at 1e-300 nor overflow at 1e300
            let size = [a.x, a.y, b.x, b.y, p.x, p.y].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let f = if size > 0.0 { 2f64.powi(-(size.log2().round() as i32)) } else { 1.0 };
            let (a, b, p) = (Point::new(a.x * f, a.y * f), Point::new(b.x * f, b.y * f), Point::new(p.x * f, p.y * f));
            let (ux, uy) = (b.x - a.x, b.y - a.y);
            let t = (((p.x - a.x) * ux + (p.y - a.y) * uy) / (ux * ux + uy * uy)).clamp(0.0, 1.0);
            Point::new(a.x + t * ux, a.y + t * uy).distance(p) / f
        }
        Site::Arc(arc) => {
            // by angles, not by the library's span test
            let c = arc.centre();
            let angle = |q: Point| (q.y - c.y).atan2(q.x - c.x);
            let sweep = arc.sweep();
            let mut along = angle(p) - angle(arc.start());
            let full = 2.0 * std::f64::consts::PI;
            if sweep > 0.0 {
                along = along.rem_euclid(full);
            } else {
                along = -(-along).rem_euclid(full);
            }
            let inside = along.abs() <= sweep.abs();
            let ends = arc.start().distance(p).min(arc.end().distance(p));
            if inside {
                (c.distance(p) - arc.radius()).abs().min(ends)
            } else {
                ends
            }
        }
        _ => unreachable!("no other site kinds"),
    }
}

/// One point, segment or arc (a quarter each, arcs half) in every cell
/// of a `side × side` grid.
pub fn random_cells(seed: u64, side: usize) -> Vec<Piece> {
    let mut rng = SplitMix64(seed);
    let mut pieces = Vec::new();
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            let cell = |rng: &mut SplitMix64| Point::new(x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit());
            match rng.next_u64() % 4 {
                0 => pieces.push(Piece::Point(cell(&mut rng))),
                1 => pieces.push(Piece::Segment(cell(&mut rng), cell(&mut rng))),
                _ => pieces.push(Piece::Arc(random_arc(&mut rng, x, y))),
            }
        }
    }
    pieces
}

/// A rounded rectangle `w × h` at `(x, y)` with corner radius `r`, as
/// pieces: sides and quarter arcs, tangent-continuous.
pub fn rounded_rectangle(x: f64, y: f64, w: f64, h: f64, r: f64) -> Vec<Piece> {
    let q = (std::f64::consts::PI / 8.0).tan();
    let p = Point::new;
    let corners = [
        (p(x + r, y), p(x + w - r, y), p(x + w, y + r)),
        (p(x + w, y + r), p(x + w, y + h - r), p(x + w - r, y + h)),
        (p(x + w - r, y + h), p(x + r, y + h), p(x, y + h - r)),
        (p(x, y + h - r), p(x, y + r), p(x + r, y)),
    ];
    let mut pieces = Vec::new();
    for (a, b, c) in corners {
        pieces.push(Piece::Segment(a, b));
        pieces.push(Piece::Arc(CircularArc::from_bulge(b, c, q).unwrap()));
    }
    pieces
}

/// A convex polygon with every corner rounded by a fillet of radius up to
/// `radius`, as CAD programs and DXF files give it: the fillet's ends are
/// the tangent points computed in floating point and its bulge
/// `tan(turn / 4)`, so the joints are tangent only to within rounding.
pub fn filleted_polygon(rng: &mut SplitMix64, cx: f64, cy: f64, n: usize, radius: f64) -> Vec<Piece> {
    let mut angles: Vec<f64> =
        (0..n).map(|k| (k as f64 + 0.3 + 0.4 * rng.unit()) * 2.0 * std::f64::consts::PI / n as f64).collect();
    angles.sort_by(f64::total_cmp);
    let corners: Vec<Point> = angles.iter().map(|&t| Point::new(cx + t.cos(), cy + t.sin())).collect();
    let mut ends = Vec::new(); // per corner: (before, after, bulge)
    for k in 0..n {
        let (prev, v, next) = (corners[(k + n - 1) % n], corners[k], corners[(k + 1) % n]);
        let unit = |a: Point, b: Point| {
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let l = dx.hypot(dy);
            (dx / l, dy / l, l)
        };
        let (ux, uy, lu) = unit(prev, v);
        let (wx, wy, lw) = unit(v, next);
        let turn = (ux * wy - uy * wx).atan2(ux * wx + uy * wy);
        let rho = radius * (0.3 + 0.7 * rng.unit());
        let l = (rho * (turn / 2.0).tan()).min(0.45 * lu.min(lw));
        ends.push((Point::new(v.x - l * ux, v.y - l * uy), Point::new(v.x + l * wx, v.y + l * wy), (turn / 4.0).tan()));
    }
    let mut pieces = Vec::new();
    for k in 0..n {
        let (before, after, bulge) = ends[k];
        pieces.push(Piece::Arc(CircularArc::from_bulge(before, after, bulge).unwrap()));
        pieces.push(Piece::Segment(after, ends[(k + 1) % n].0));
    }
    pieces
}

/// Adds every piece to the builder, as given.
pub fn add_pieces(b: &mut Builder, pieces: &[Piece]) {
    for piece in pieces {
        match *piece {
            Piece::Point(p) => drop(b.add_point(p).unwrap()),
            Piece::Segment(p, q) => drop(b.add_segment([p, q]).unwrap()),
            Piece::Arc(arc) => drop(b.add_arc(arc).unwrap()),
        }
    }
}

/// The failures of the brute-force audit at tolerance `tol` (absolute).
pub fn audit(d: &Diagram, tol: f64) -> Vec<String> {
    let sites: Vec<Site> = d.site_ids().map(|s| d.site(s).unwrap()).collect();
    let mut failures = Vec::new();
    let nearest = |p: Point| sites.iter().map(|s| distance(s, p)).fold(f64::INFINITY, f64::min);
    for v in d.vertices() {
        let r = v.clearance;
        for s in v.sites {
            let ds = distance(&sites[s.index()], v.position);
            if !((ds - r).abs() <= tol + 1e-12 * r) {
                failures.push(format!(
                    "vertex {:?} at {:?} r {r} of {:?}: its site {:?} at {ds}",
                    v.id,
                    v.position,
                    v.sites.map(|s| sites[s.index()]),
                    sites[s.index()]
                ));
            }
        }
        let tol = tol + 1e-12 * r; // far vertices: relative to their distance
        let (k, n) = sites.iter().enumerate().map(|(k, s)| (k, distance(s, v.position))).fold((0, f64::INFINITY), |a, b| {
            if b.1 < a.1 {
                b
            } else {
                a
            }
        });
        if n < r - tol {
            failures.push(format!(
                "vertex {:?} at {:?} r {r} of {:?}: site {k} {:?} nearer at {n}",
                v.id,
                v.position,
                v.sites.map(|s| sites[s.index()]),
                sites[k]
            ));
        }
    }
    // Grid points clearly nearest to two sites (the third well behind)
    // lie on an edge between them: those two must be neighbours.
    let neighbours: std::collections::HashSet<(usize, usize)> =
        d.edges().map(|e| (e.sites[0].index().min(e.sites[1].index()), e.sites[0].index().max(e.sites[1].index()))).collect();
    let points: Vec<Point> = sites.iter().filter_map(Site::as_point).collect();
    let (lo, hi) = points
        .iter()
        .fold((Point::new(f64::INFINITY, f64::INFINITY), Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY)), |(lo, hi), p| {
            (Point::new(lo.x.min(p.x), lo.y.min(p.y)), Point::new(hi.x.max(p.x), hi.y.max(p.y)))
        });
    let span = (hi.x - lo.x).max(hi.y - lo.y).max(tol);
    let steps = 150;
    let h = 2.0 * span / steps as f64;
    for i in 0..=steps {
        for j in 0..=steps {
            let q = Point::new(lo.x - 0.5 * span + i as f64 * h, lo.y - 0.5 * span + j as f64 * h);
            let mut best = [(f64::INFINITY, 0usize); 3];
            for (k, site) in sites.iter().enumerate() {
                let dk = distance(site, q);
                if dk < best[2].0 {
                    best[2] = (dk, k);
                    best.sort_by(|x, y| x.0.total_cmp(&y.0));
                }
            }
            let [(d1, s1), (d2, s2), (d3, _)] = best;
            if d2 - d1 < 0.05 * h && d3 - d2 > 0.5 * h && !neighbours.contains(&(s1.min(s2), s1.max(s2))) {
                failures.push(format!(
                    "grid point {q:?}: sites {s1} {:?} and {s2} {:?} meet there but are not neighbours",
                    sites[s1], sites[s2]
                ));
            }
        }
    }
    // Far out in the direction of an edge to infinity, its two sites are
    // the nearest (to the curvature, span²/far): a site that reached
    // further that way would own the direction. (The grid above only
    // sees the box around the input.)
    let centre = Point::new(0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y));
    let far = 1e6 * span;
    for e in d.edges() {
        for end in e.ends {
            let segvoronoi::EdgeEnd::Infinite { direction: u } = end else { continue };
            let length = u.x.hypot(u.y);
            let q = Point::new(centre.x + far * u.x / length, centre.y + far * u.y / length);
            let [a, b] = e.sites.map(|s| sites[s.index()]);
            let (da, db, n) = (distance(&a, q), distance(&b, q), nearest(q));
            if da.max(db) > n + 1e-5 * span {
                failures.push(format!(
                    "edge {:?} between {a:?} and {b:?} to infinity toward {u:?}: there at {da} / {db}, another site at {n}",
                    e.id
                ));
            }
        }
    }
    for e in d.edges() {
        let Some(poly) = d.edge_polyline(e.id, tol * 10.0) else { continue };
        let [a, b] = e.sites.map(|s| sites[s.index()]);
        for &q in &poly[1..poly.len() - 1] {
            let (da, db) = (distance(&a, q), distance(&b, q));
            if !((da - db).abs() <= 10.0 * tol) || nearest(q) < da.min(db) - 10.0 * tol {
                failures.push(format!(
                    "edge {:?} between {a:?} and {b:?}: point {q:?} at {da} / {db}, nearest {}",
                    e.id,
                    nearest(q)
                ));
                break;
            }
        }
    }
    failures
}

/// `pieces` with every point moved by `f` (an arc through its moved ends
/// and middle, or with its bulge, negated where `f` `flip`s orientation).
pub fn mapped(pieces: &[Piece], f: &dyn Fn(Point) -> Point, flip: bool) -> Vec<Piece> {
    pieces
        .iter()
        .map(|&p| match p {
            Piece::Point(q) => Piece::Point(f(q)),
            Piece::Segment(a, b) => Piece::Segment(f(a), f(b)),
            Piece::Arc(arc) => {
                let bulge = if flip { -arc.bulge() } else { arc.bulge() };
                Piece::Arc(match arc.via() {
                    Some(m) => CircularArc::through(f(arc.start()), f(m), f(arc.end())).unwrap(),
                    None => CircularArc::from_bulge(f(arc.start()), f(arc.end()), bulge).unwrap(),
                })
            }
        })
        .collect()
}

/// `pieces` and its variants: reversed arcs and segments, shuffled,
/// mirrored, scaled by 2^-20 and 2^20; each with the factor of its size.
pub fn variants(pieces: &[Piece], seed: u64) -> Vec<(&'static str, Vec<Piece>, f64)> {
    let reversed: Vec<Piece> = pieces
        .iter()
        .map(|&p| match p {
            Piece::Segment(a, b) => Piece::Segment(b, a),
            Piece::Arc(arc) => Piece::Arc(arc.reversed()),
            other => other,
        })
        .collect();
    let mut shuffled = pieces.to_vec();
    let mut rng = SplitMix64(seed);
    for i in (1..shuffled.len()).rev() {
        shuffled.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
    }
    let map = |f: &dyn Fn(Point) -> Point, flip: bool| mapped(pieces, f, flip);
    let mirrored = map(&|q: Point| Point::new(-q.x, q.y), true);
    let small = map(&|q: Point| Point::new(q.x * 2f64.powi(-20), q.y * 2f64.powi(-20)), false);
    let large = map(&|q: Point| Point::new(q.x * 2f64.powi(20), q.y * 2f64.powi(20)), false);
    vec![
        ("plain", pieces.to_vec(), 1.0),
        ("reversed", reversed, 1.0),
        ("shuffled", shuffled, 1.0),
        ("mirrored", mirrored, 1.0),
        ("scaled down", small, 2f64.powi(-20)),
        ("scaled up", large, 2f64.powi(20)),
    ]
}
