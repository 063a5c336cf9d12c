//! `--input-wkt OUT.wkt`: the input as the program read it, in WKT: what
//! a DXF drawing became (its chains joined into rings, ends snapped, arcs
//! cut where entities end on them), and a way to hand it to tools that
//! read WKT (PostGIS, GEOS, QGIS).
//!
//! One `GEOMETRYCOLLECTION`: each ring a polygon of its own, since the
//! domain is the even-odd region of all rings together (a ring inside
//! another is a hole whichever polygon it came from); each open chain and
//! linestring a line; each point a `POINT`. Arcs become chords within the
//! tolerance (`POLYGON`, `LINESTRING`), or with `--curves` stay arcs
//! (`CURVEPOLYGON` of a `COMPOUNDCURVE`, `COMPOUNDCURVE`, each arc a
//! `CIRCULARSTRING` of its start, middle and end), as PostGIS writes
//! curves, which the program reads back. Chain ends are the input's own
//! coordinates (shortest round-trip numbers); only arcs' middles and
//! chord points are computed. Boost.Polygon's text gives its points and
//! segments; the built-in demo, none of this.

use std::fmt::Write;

use segvoronoi::CircularArc;

use crate::input::Input;
use crate::wkt::{Step, Xy};

/// The input as one `GEOMETRYCOLLECTION` line (`GEOMETRYCOLLECTION EMPTY`
/// when it has nothing).
pub fn wkt(input: &Input, tolerance: f64, curves: bool) -> String {
    let mut members: Vec<String> = Vec::new();
    if let Some((points, segments)) = input.boost_sites() {
        members.extend(points.iter().map(|&p| format!("POINT ({})", xy(p))));
        members.extend(segments.iter().map(|s| format!("LINESTRING ({}, {})", xy([s[0], s[1]]), xy([s[2], s[3]]))));
    }
    for ring in input.rings() {
        members.push(if curves && has_arc(&ring) {
            format!("CURVEPOLYGON ({})", compound(&ring))
        } else {
            format!("POLYGON (({}))", coordinates(&chords(&ring, tolerance)))
        });
    }
    let (lines, points) = input.obstacles();
    for line in lines {
        members.push(if curves && has_arc(&line) {
            compound(&line)
        } else {
            format!("LINESTRING ({})", coordinates(&chords(&line, tolerance)))
        });
    }
    members.extend(points.iter().map(|&p| format!("POINT ({})", xy(p))));
    if members.is_empty() {
        "GEOMETRYCOLLECTION EMPTY\n".to_string()
    } else {
        format!("GEOMETRYCOLLECTION ({})\n", members.join(", "))
    }
}

fn xy(p: Xy) -> String {
    // (+ 0.0: no negative zero)
    format!("{} {}", p[0] + 0.0, p[1] + 0.0)
}

fn coordinates(points: &[Xy]) -> String {
    points.iter().map(|&p| xy(p)).collect::<Vec<_>>().join(", ")
}

fn has_arc(chain: &[Step]) -> bool {
    chain.iter().any(|s| matches!(s, Step::Arc(_)))
}

/// The chain's points, each arc as chords whose sagitta is within
/// `tolerance` (at least one chord an arc), from the first step's start to
/// the last step's end.
fn chords(chain: &[Step], tolerance: f64) -> Vec<Xy> {
    let mut out: Vec<Xy> = chain.first().map(|s| vec![s.start()]).unwrap_or_default();
    for step in chain {
        if let Step::Arc(arc) = step {
            let n = chord_count(arc, tolerance);
            out.extend((1..n).map(|k| {
                let p = arc.point_at(k as f64 / n as f64);
                [p.x, p.y]
            }));
        }
        out.push(step.end());
    }
    out
}

/// How many chords keep the arc within `tolerance` of them: a chord of
/// angle `θ` has sagitta `r (1 − cos(θ/2))`. Capped, for a tolerance far
/// below the arc's rounding.
fn chord_count(arc: &CircularArc, tolerance: f64) -> usize {
    let r = arc.radius();
    let per_chord = if tolerance > 0.0 && tolerance < r { 2.0 * (1.0 - tolerance / r).acos() } else { std::f64::consts::PI };
    let n = (arc.sweep().abs() / per_chord).ceil();
    if n.is_finite() {
        (n as usize).clamp(1, 1 << 16)
    } else {
        1
    }
}

/// A chain as a `COMPOUNDCURVE`: each run of segments one linestring,
/// each arc a `CIRCULARSTRING` (start, its middle, end).
fn compound(chain: &[Step]) -> String {
    let mut members: Vec<String> = Vec::new();
    let mut run: Vec<Xy> = Vec::new();
    for step in chain {
        match step {
            Step::Segment([a, b]) => {
                if run.is_empty() {
                    run.push(*a);
                }
                run.push(*b);
            }
            Step::Arc(arc) => {
                if run.len() >= 2 {
                    members.push(format!("({})", coordinates(&run)));
                }
                run.clear();
                let middle = arc.midpoint();
                let mut text = String::new();
                let _ = write!(text, "CIRCULARSTRING ({}, {}, {})", xy(step.start()), xy([middle.x, middle.y]), xy(step.end()));
                members.push(text);
            }
        }
    }
    if run.len() >= 2 {
        members.push(format!("({})", coordinates(&run)));
    }
    format!("COMPOUNDCURVE ({})", members.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chords_keep_within_the_tolerance() {
        let arc = CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        let points = chords(&[Step::Arc(arc)], 1e-3);
        assert_eq!((points[0], *points.last().unwrap()), ([1.0, 0.0], [-1.0, 0.0]));
        // every chord's middle within 1e-3 of the circle
        for w in points.windows(2) {
            let m = [(w[0][0] + w[1][0]) / 2.0, (w[0][1] + w[1][1]) / 2.0];
            assert!(1.0 - m[0].hypot(m[1]) <= 1e-3 + 1e-15, "{w:?}");
        }
        // a half circle of radius 1 at 1e-3: π / (2 acos(0.999)) = 35.1, so 36 chords
        assert_eq!(points.len(), 37);
    }

    #[test]
    fn compound_curves_keep_ends_exact() {
        let arc = CircularArc::from_bulge([4.0, 0.0], [4.0, 2.0], 1.0).unwrap();
        let chain = [Step::Segment([[0.0, 0.0], [4.0, 0.0]]), Step::Arc(arc), Step::Segment([[4.0, 2.0], [0.0, 2.0]])];
        assert_eq!(compound(&chain), "COMPOUNDCURVE ((0 0, 4 0), CIRCULARSTRING (4 0, 5 1, 4 2), (4 2, 0 2))");
    }
}
