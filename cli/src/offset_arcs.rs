//! The geometry of an offset's arc pieces that the DXF, G-code and WKT
//! curve writers share: an arc's sweep, bulge and middle, and a loop's
//! pieces with whole circles cut in two (a CIRCULARSTRING, a G2/G3 or a
//! bulge whose end is its start says nothing of the way round, or of the
//! circle).

use std::f64::consts::TAU;

use segvoronoi::{OffsetPiece, Point};

/// A piece as the writers see it: a straight line, or an arc of less than
/// a full turn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece {
    Line { from: Point, to: Point },
    Arc { centre: Point, radius: f64, from: Point, to: Point, counter_clockwise: bool },
}

impl Piece {
    pub fn from(&self) -> Point {
        match *self {
            Piece::Line { from, .. } | Piece::Arc { from, .. } => from,
        }
    }

    pub fn to(&self) -> Point {
        match *self {
            Piece::Line { to, .. } | Piece::Arc { to, .. } => to,
        }
    }
}

/// A loop's pieces, a whole circle (an arc back to its start) as two half
/// circles through the point opposite its start. A piece of a kind this
/// program does not know yet (`OffsetPiece` may grow) is its chord.
pub fn pieces(loop_pieces: &[OffsetPiece]) -> Vec<Piece> {
    let mut out = Vec::with_capacity(loop_pieces.len() + 1);
    for piece in loop_pieces {
        match *piece {
            OffsetPiece::Line { from, to, .. } => out.push(Piece::Line { from, to }),
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } if from == to => {
                let opposite = Point::new(2.0 * centre.x - from.x, 2.0 * centre.y - from.y);
                out.push(Piece::Arc { centre, radius, from, to: opposite, counter_clockwise });
                out.push(Piece::Arc { centre, radius, from: opposite, to, counter_clockwise });
            }
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                out.push(Piece::Arc { centre, radius, from, to, counter_clockwise })
            }
            ref other => out.push(Piece::Line { from: other.from(), to: other.to() }),
        }
    }
    out
}

/// Whether a loop is one whole circle: `(centre, radius)`.
pub fn whole_circle(loop_pieces: &[OffsetPiece]) -> Option<(Point, f64)> {
    match loop_pieces {
        [OffsetPiece::Arc { centre, radius, from, to, .. }] if from == to => Some((*centre, *radius)),
        _ => None,
    }
}

/// The angle an arc sweeps from `from` to `to` the way it runs, in
/// `(0, 2π]` (2π for a whole circle).
pub fn sweep(centre: Point, from: Point, to: Point, counter_clockwise: bool) -> f64 {
    if from == to {
        return TAU;
    }
    let angle = |p: Point| (p.y - centre.y).atan2(p.x - centre.x);
    let turn = if counter_clockwise { angle(to) - angle(from) } else { angle(from) - angle(to) };
    match turn.rem_euclid(TAU) {
        // ends a hair apart: the shortest arc, not a full turn
        t if t == 0.0 || t >= TAU => f64::MIN_POSITIVE,
        t => t,
    }
}

/// DXF's bulge of an arc: `tan(sweep / 4)`, negative when clockwise.
/// From the chord rather than the angle: with `a` half the chord and `h`
/// the centre's distance from the chord's middle, `tan(sweep / 4)` is
/// `a / (r + h)` for less than a half turn and `(r + h) / a` for more, so
/// that a half circle's is 1 (not `tan(π/4)`, 0.9999999999999999) and a
/// tiny arc's keeps its digits.
pub fn bulge(centre: Point, from: Point, to: Point, counter_clockwise: bool) -> f64 {
    let a = 0.5 * from.distance(to);
    let middle = Point::new(0.5 * (from.x + to.x), 0.5 * (from.y + to.y));
    let h = centre.distance(middle);
    let r = 0.5 * (centre.distance(from) + centre.distance(to));
    let minor = sweep(centre, from, to, counter_clockwise) < std::f64::consts::PI;
    let b = if minor { a / (r + h) } else { (r + h) / a };
    if counter_clockwise {
        b
    } else {
        -b
    }
}

/// The point of the arc halfway along it.
pub fn middle(centre: Point, radius: f64, from: Point, to: Point, counter_clockwise: bool) -> Point {
    let half = sweep(centre, from, to, counter_clockwise) / 2.0;
    let start = (from.y - centre.y).atan2(from.x - centre.x);
    let angle = if counter_clockwise { start + half } else { start - half };
    Point::new(centre.x + radius * angle.cos(), centre.y + radius * angle.sin())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn sweeps_bulges_and_middles() {
        let c = Point::new(0.0, 0.0);
        let (a, b) = (Point::new(1.0, 0.0), Point::new(0.0, 1.0));
        assert!((sweep(c, a, b, true) - PI / 2.0).abs() < 1e-15);
        assert!((sweep(c, a, b, false) - 1.5 * PI).abs() < 1e-15);
        assert!((bulge(c, a, b, true) - (PI / 8.0).tan()).abs() < 1e-15);
        assert!((bulge(c, a, b, false) + (3.0 * PI / 8.0).tan()).abs() < 1e-14);
        assert_eq!(sweep(c, a, a, true), TAU);
        assert_eq!(bulge(c, a, Point::new(-1.0, 0.0), true), 1.0);
        assert_eq!(bulge(c, a, Point::new(-1.0, 0.0), false), -1.0);
        let m = middle(c, 1.0, a, b, true);
        assert!((m.x - m.y).abs() < 1e-15 && m.x > 0.0);
        let m = middle(c, 1.0, a, b, false);
        assert!((m.x - m.y).abs() < 1e-15 && m.x < 0.0);
    }

    #[test]
    fn a_whole_circle_is_two_halves() {
        let site = segvoronoi::SiteId::from_index(0);
        let circle = [OffsetPiece::Arc {
            centre: Point::new(1.0, 2.0),
            radius: 0.5,
            from: Point::new(1.5, 2.0),
            to: Point::new(1.5, 2.0),
            counter_clockwise: true,
            site,
        }];
        assert_eq!(whole_circle(&circle), Some((Point::new(1.0, 2.0), 0.5)));
        let halves = pieces(&circle);
        assert_eq!(halves.len(), 2);
        assert_eq!(
            (halves[0].to(), halves[1].from(), halves[1].to()),
            (Point::new(0.5, 2.0), Point::new(0.5, 2.0), Point::new(1.5, 2.0))
        );
    }
}
