//! Inputs with circular arcs for the arcs' tests (`arcs.rs`, the
//! brute-force audit of the diagram; `arc_offsets.rs`, offsets against
//! chords): the pieces a test gives the builder, the distance to a site
//! computed apart from the library, and the generators both use.

use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Point, Site};
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
