//! `--offsets OUT.wkt --curves`: the offsets with their arcs as arcs, in
//! WKT's curve types as PostGIS writes them: per distance one line, a
//! `MULTISURFACE` of `CURVEPOLYGON`s (per outer loop, see
//! [`Offset::polygons`]: its ring, then its holes), each ring a
//! `COMPOUNDCURVE` of linestrings (runs of straight pieces) and
//! `CIRCULARSTRING`s (an arc each: start, the point halfway along it, end;
//! a whole circle two half circles; an arc so flat that its three points
//! are on one line, as where an offset passes a tangent joint, its chord).
//! `MULTISURFACE EMPTY` for an empty
//! region. The ends are the loops' own, exactly (shortest round-trip
//! numbers); the middle points are rounded, as any third point must be.

use std::fmt::Write;

use segvoronoi::geometry::predicates::{orientation, Orientation};
use segvoronoi::{Offset, Point};

use crate::offset_arcs::{middle, pieces, Piece};

/// One `MULTISURFACE` line per offset, in order.
pub fn wkt(offsets: &[Offset]) -> String {
    let mut out = String::new();
    for offset in offsets {
        let polygons: Vec<String> = offset
            .polygons()
            .iter()
            .map(|loops| {
                let rings: Vec<String> = loops.iter().map(|&k| ring(&pieces(&offset.loops[k].pieces))).collect();
                format!("CURVEPOLYGON ({})", rings.join(", "))
            })
            .collect();
        if polygons.is_empty() {
            out.push_str("MULTISURFACE EMPTY\n");
        } else {
            let _ = writeln!(out, "MULTISURFACE ({})", polygons.join(", "));
        }
    }
    out
}

fn xy(p: Point) -> String {
    format!("{} {}", p.x + 0.0, p.y + 0.0)
}

/// A closed ring as a `COMPOUNDCURVE`: each run of lines one linestring,
/// each arc a `CIRCULARSTRING`; each member starts where the one before
/// ends.
fn ring(pieces: &[Piece]) -> String {
    let mut members: Vec<String> = Vec::new();
    let mut run: Vec<Point> = Vec::new();
    let flush = |run: &mut Vec<Point>, members: &mut Vec<String>| {
        if run.len() >= 2 {
            members.push(format!("({})", run.iter().map(|&p| xy(p)).collect::<Vec<_>>().join(", ")));
        }
        run.clear();
    };
    for piece in pieces {
        // an arc's point halfway along it; none for a line, and none for
        // an arc so flat that its three points are on one line (a sliver
        // where an offset passes a tangent joint), which no reader takes:
        // its chord instead
        let middle = match *piece {
            Piece::Line { .. } => None,
            Piece::Arc { centre, radius, from, to, counter_clockwise } => {
                Some(middle(centre, radius, from, to, counter_clockwise))
                    .filter(|&m| orientation(from, m, to) != Orientation::Collinear)
            }
        };
        let (from, to) = (piece.from(), piece.to());
        match middle {
            None => {
                if run.is_empty() {
                    run.push(from);
                }
                run.push(to);
            }
            Some(m) => {
                flush(&mut run, &mut members);
                members.push(format!("CIRCULARSTRING ({}, {}, {})", xy(from), xy(m), xy(to)));
            }
        }
    }
    flush(&mut run, &mut members);
    format!("COMPOUNDCURVE ({})", members.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wkt::{parse, Shape, Step};
    use segvoronoi::{Builder, OffsetPiece};

    /// Each ring read back matches the loop's pieces: line ends exactly,
    /// arc ends exactly, centres within 1e-12 of the radius, directions.
    fn matches_loops(offset: &Offset, shapes: &[Shape]) {
        let polygons = offset.polygons();
        assert_eq!(shapes.len(), polygons.len());
        for (shape, loops) in shapes.iter().zip(&polygons) {
            let rings: Vec<Vec<Step>> = match shape {
                Shape::CurveRings(rings) => rings.clone(),
                other => panic!("a curve polygon: {other:?}"),
            };
            assert_eq!(rings.len(), loops.len());
            for (steps, &k) in rings.iter().zip(loops) {
                let expected = pieces(&offset.loops[k].pieces);
                // a run of lines reads back as its segments, one per piece
                assert_eq!(steps.len(), expected.len(), "{steps:?}");
                for (step, piece) in steps.iter().zip(&expected) {
                    assert_eq!(step.start(), [piece.from().x, piece.from().y]);
                    assert_eq!(step.end(), [piece.to().x, piece.to().y]);
                    match (step, piece) {
                        (Step::Segment(_), Piece::Line { .. }) => {}
                        (Step::Arc(arc), Piece::Arc { centre, radius, counter_clockwise, .. }) => {
                            assert!(arc.centre().distance(*centre) <= 1e-12 * radius, "{arc:?} vs {centre:?}");
                            assert!((arc.radius() - radius).abs() <= 1e-12 * radius);
                            assert_eq!(arc.is_counter_clockwise(), *counter_clockwise);
                        }
                        other => panic!("a different piece: {other:?}"),
                    }
                }
            }
        }
    }

    #[test]
    fn a_grown_plate_with_a_hole_reads_back_as_its_loops() {
        let mut b = Builder::new();
        b.add_polygon(&[
            vec![[0.0, 0.0], [100.0, 0.0], [100.0, 60.0], [0.0, 60.0]],
            vec![[40.0, 20.0], [60.0, 20.0], [60.0, 40.0], [40.0, 40.0]],
        ])
        .unwrap();
        let d = b.build().unwrap();
        let offsets = d.offsets(&[2.5, -2.5, -40.0]).unwrap();
        let text = wkt(&offsets);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3);
        assert_eq!(lines[2], "MULTISURFACE EMPTY");
        for (line, offset) in lines.iter().zip(&offsets).take(2) {
            assert!(line.starts_with("MULTISURFACE (CURVEPOLYGON (COMPOUNDCURVE ("), "{line}");
            matches_loops(offset, &parse(line).unwrap().shapes);
        }
    }

    #[test]
    fn a_grown_point_is_two_half_circles() {
        let mut b = Builder::new();
        b.add_points([[0.0, 0.0], [10.0, 0.0]]).unwrap();
        let d = b.build().unwrap();
        let offset = d.offset(1.0).unwrap();
        assert!(offset.loops.iter().all(|l| matches!(l.pieces[..], [OffsetPiece::Arc { from, to, .. }] if from == to)));
        let text = wkt(std::slice::from_ref(&offset));
        assert!(text.contains("CURVEPOLYGON (COMPOUNDCURVE (CIRCULARSTRING (1 0, "), "{text}");
        matches_loops(&offset, &parse(&text).unwrap().shapes);
    }
}
