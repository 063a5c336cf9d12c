//! `--offsets OUT.nc`: the offset loops as G-code for a milling machine
//! (RS-274 as LinuxCNC, GRBL and most controllers read it).
//!
//! The program: `G21` (millimetres: the input's coordinates are written as
//! they are), `G90` (absolute), `G17` (the XY plane for arcs), then per
//! loop a rapid move to the safe height and to the loop's start, a plunge
//! (`G1 Z` at the plunge feed), the pieces (`G1` for lines, `G2`
//! clockwise and `G3` counter-clockwise arcs, `I J` the centre relative to
//! the arc's start) at the cutting feed, and a retract; `M2` ends it.
//!
//! Order: the distances as given; within one, every loop after the loops
//! inside it (children before parents), so that a pocket's inner islands
//! and holes are cut before the boundary around them frees the material.
//! A whole circle is two half circles: a `G2`/`G3` that ends where it
//! starts is read by some controllers as a full turn and by others as
//! nothing. For the same reason a piece whose written end is the written
//! position before it (a sliver of an arc where an offset passes a tangent
//! joint of a curved boundary, or anything `--gcode-digits` rounds away)
//! is left out, and an arc of less than a microradian is cut as its chord.
//!
//! Numbers are Rust's shortest round-trip form of each `f64` (never an
//! exponent), so that the program reads back to the exact loops whatever
//! the coordinates' size (a fixed 4 or 6 decimals would move the points of
//! a small part, and a large one's last digits); `--gcode-digits N` rounds
//! to N decimals for controllers that take no more.

use std::fmt::Write;

use segvoronoi::{Offset, Point};

use crate::offset_arcs::{pieces, sweep, Piece};

/// How to cut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Feed along the loops (mm/min).
    pub feed: f64,
    /// Feed of the plunge (mm/min).
    pub plunge_feed: f64,
    /// Z of the cut.
    pub plunge_depth: f64,
    /// Z of rapid moves.
    pub safe_z: f64,
    /// Decimals of X, Y, I, J (`None`: every digit, exactly).
    pub digits: Option<usize>,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings { feed: 600.0, plunge_feed: 100.0, plunge_depth: -1.0, safe_z: 5.0, digits: None }
    }
}

/// The G-code program for the offsets.
pub fn program(offsets: &[Offset], settings: &Settings) -> String {
    let number = |v: f64| format_number(v, settings.digits);
    let mut out = String::new();
    out.push_str("(segvoronoi offsets: the region on the left of each loop, outer loops counter-clockwise)\n");
    out.push_str("G21\nG90\nG17\n");
    let _ = writeln!(out, "G0 Z{}", number(settings.safe_z));
    for offset in offsets {
        let order = children_first(offset);
        for (n, &k) in order.iter().enumerate() {
            let lp = &offset.loops[k];
            let pieces = pieces(&lp.pieces);
            let Some(first) = pieces.first() else { continue };
            let kind = if lp.hole { "hole" } else { "outer" };
            let _ = writeln!(out, "(offset {}: loop {k}, {kind}, {} of {})", offset.distance, n + 1, order.len());
            let start = first.from();
            let _ = writeln!(out, "G0 X{} Y{}", number(start.x), number(start.y));
            let _ = writeln!(out, "G1 Z{} F{}", number(settings.plunge_depth), number(settings.plunge_feed));
            // the position as the controller has it: the printed numbers
            let mut at = rounded(start, settings.digits);
            let mut feed = Some(settings.feed);
            for piece in &pieces {
                let to = piece.to();
                // A piece that ends where the controller already is moves
                // nowhere: left out. For an arc it matters: a G2/G3 whose
                // end is its start cuts a whole circle (an offset passing a
                // tangent joint of the boundary has such slivers).
                if rounded(to, settings.digits) == at {
                    continue;
                }
                // an arc of less than a microradian strays from its chord by
                // less than 2e-13 of its radius: a line, which no
                // controller can take for a whole circle
                let straight = match *piece {
                    Piece::Line { .. } => true,
                    Piece::Arc { centre, from, counter_clockwise, .. } => sweep(centre, from, to, counter_clockwise) < 1e-6,
                };
                let _ = match *piece {
                    Piece::Arc { centre, counter_clockwise, .. } if !straight => write!(
                        out,
                        "{} X{} Y{} I{} J{}",
                        if counter_clockwise { "G3" } else { "G2" },
                        number(to.x),
                        number(to.y),
                        number(centre.x - at.x),
                        number(centre.y - at.y)
                    ),
                    _ => write!(out, "G1 X{} Y{}", number(to.x), number(to.y)),
                };
                if let Some(f) = feed.take() {
                    let _ = write!(out, " F{}", number(f));
                }
                out.push('\n');
                at = rounded(to, settings.digits);
            }
            let _ = writeln!(out, "G0 Z{}", number(settings.safe_z));
        }
    }
    out.push_str("M2\n");
    out
}

/// The loops' indices, every loop after those inside it: the nesting
/// tree walked depth first, children before their parent, siblings in
/// the library's order.
fn children_first(offset: &Offset) -> Vec<usize> {
    let n = offset.loops.len();
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut roots = Vec::new();
    for (k, lp) in offset.loops.iter().enumerate() {
        match lp.parent {
            Some(p) if p < n && p != k => children[p].push(k),
            _ => roots.push(k),
        }
    }
    let mut order = Vec::with_capacity(n);
    // (loop, whether its children are done), without recursion
    let mut stack: Vec<(usize, bool)> = roots.iter().rev().map(|&r| (r, false)).collect();
    while let Some((k, done)) = stack.pop() {
        if done {
            order.push(k);
        } else {
            stack.push((k, true));
            stack.extend(children[k].iter().rev().map(|&c| (c, false)));
        }
    }
    order
}

/// A number as written: every digit (`{}`, shortest round-trip), or
/// rounded to `digits` decimals without trailing zeros; never `-0`.
pub fn format_number(v: f64, digits: Option<usize>) -> String {
    let text = match digits {
        None => format!("{}", v + 0.0),
        Some(d) => {
            let fixed = format!("{v:.d$}");
            let trimmed = if fixed.contains('.') { fixed.trim_end_matches('0').trim_end_matches('.') } else { &fixed };
            trimmed.to_string()
        }
    };
    if text == "-0" {
        "0".into()
    } else {
        text
    }
}

/// A point as the printed numbers read back.
fn rounded(p: Point, digits: Option<usize>) -> Point {
    let back = |v: f64| format_number(v, digits).parse().unwrap_or(v);
    Point::new(back(p.x), back(p.y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::Builder;

    #[test]
    fn numbers() {
        assert_eq!(format_number(0.1 + 0.2, None), "0.30000000000000004");
        assert_eq!(format_number(-0.0, None), "0");
        assert_eq!(format_number(1e21, None), "1000000000000000000000");
        assert_eq!(format_number(1.23456, Some(3)), "1.235");
        assert_eq!(format_number(2.0, Some(3)), "2");
        assert_eq!(format_number(-0.0001, Some(3)), "0");
    }

    #[test]
    fn a_square_with_a_hole_cuts_the_hole_first() {
        let mut b = Builder::new();
        b.add_polygon(&[
            vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
            vec![[4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [4.0, 6.0]],
        ])
        .unwrap();
        let d = b.build().unwrap();
        let text = program(&[d.offset(-0.5).unwrap()], &Settings::default());
        assert!(text.starts_with("(segvoronoi offsets"), "{text}");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(&lines[1..5], ["G21", "G90", "G17", "G0 Z5"]);
        let hole = lines.iter().position(|l| l.contains(", hole,")).unwrap();
        let outer = lines.iter().position(|l| l.contains(", outer,")).unwrap();
        assert!(hole < outer, "{text}");
        // the hole grew around the inner square: four quarter circles, clockwise
        assert_eq!(text.matches("\nG2 ").count(), 4, "{text}");
        assert!(text.contains("G1 Z-1 F100\n") && text.ends_with("G0 Z5\nM2\n"), "{text}");
        assert_eq!(text.matches(" F600").count(), 2, "{text}");
    }

    #[test]
    fn a_whole_circle_is_two_half_arcs() {
        let mut b = Builder::new();
        b.add_point([1.0, 1.0]).unwrap();
        let d = b.build().unwrap();
        let text = program(&[d.offset(2.0).unwrap()], &Settings::default());
        assert!(text.contains("G0 X3 Y1\n"), "{text}");
        assert!(text.contains("G3 X-1 Y1 I-2 J0 F600\nG3 X3 Y1 I2 J0\n"), "{text}");
    }

    #[test]
    fn a_sliver_at_a_tangent_joint_is_no_whole_circle() {
        // a slot grown by 0.5: its loop passes the joints of the sides and
        // the half circles with arcs of a sweep near 1e-16 around their
        // ends, whose ends are equal once rounded
        let mut b = Builder::new();
        b.add_bulged_polygon(&[vec![([0.0, 0.0], 0.0), ([4.0, 0.0], 1.0), ([4.0, 2.0], 0.0), ([0.0, 2.0], 1.0)]]).unwrap();
        let d = b.build().unwrap();
        for digits in [None, Some(4)] {
            let text = program(&[d.offset(0.5).unwrap()], &Settings { digits, ..Settings::default() });
            let mut at = String::new();
            for line in text.lines() {
                let words: Vec<&str> = line.split_whitespace().collect();
                let end = words.iter().filter(|w| w.starts_with(['X', 'Y'])).copied().collect::<Vec<_>>().join(" ");
                if matches!(words.first(), Some(&("G2" | "G3"))) {
                    assert_ne!(end, at, "{digits:?}: a whole circle: {text}");
                }
                if !end.is_empty() {
                    at = end;
                }
            }
            // the two half circles of radius 1.5, and a feed once
            assert_eq!(text.matches("\nG3 ").count() - text.matches("J0.5").count() - text.matches("J-0.5").count(), 2, "{text}");
            assert_eq!(text.matches(" F600").count(), 1, "{text}");
        }
    }
}
