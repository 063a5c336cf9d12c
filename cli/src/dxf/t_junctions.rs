//! Arcs split where another entity's end lies on them.
//!
//! A drawing's LINE that ends on an ARC (a wall meeting a round one, a
//! spoke of a wheel) ends there only to the file's rounding: its end is a
//! hair inside or outside the circle. The library takes that as written:
//! a segment's end 1e-12 from an arc's interior is two sites apart by
//! 1e-12, a contact its arcs' decisions (floating point) cannot see
//! clearly, and the drawing's outline does not close there. So, after the
//! ends are snapped together (`snap`), an arc of a chain with a vertex of
//! any item within `SNAP` × extent of its interior (away from its ends) is
//! cut at that vertex: two arcs of the same turn in all, each from its
//! bulge, meeting exactly at the vertex as written.

use super::entities::{Item, Raw};
use super::snap::{extent, SNAP};
use crate::wkt::Xy;
use segvoronoi::{CircularArc, Point};

/// Cuts every arc of `items`' chains at the vertices (of any item) within
/// `SNAP` × extent of its interior; returns how many cuts it made.
pub fn split_arcs_at_vertices(items: &mut [Item]) -> usize {
    let tolerance = SNAP * extent(items);
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return 0;
    }
    let mut vertices: Vec<Xy> = Vec::new();
    for item in items.iter() {
        match &item.raw {
            Raw::Point(_) => {}
            Raw::Line(ends) => vertices.extend_from_slice(ends),
            Raw::Chain { vertices: v, .. } => vertices.extend(v.iter().map(|(p, _)| *p)),
        }
    }
    vertices.retain(|p| p.iter().all(|c| c.is_finite()));
    vertices.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut cuts = 0;
    for item in items.iter_mut() {
        let Raw::Chain { vertices: chain, closed } = &mut item.raw else { continue };
        let n = chain.len();
        let pieces = if *closed { n } else { n.saturating_sub(1) };
        let mut out: Vec<(Xy, f64)> = Vec::with_capacity(n);
        for k in 0..n {
            let (from, bulge) = chain[k];
            if k >= pieces || bulge == 0.0 {
                out.push((from, bulge));
                continue;
            }
            let to = chain[(k + 1) % n].0;
            let on = vertices_on_arc(&vertices, from, to, bulge, tolerance);
            if on.is_empty() {
                out.push((from, bulge));
                continue;
            }
            // from the start, each cut at its turn along the arc
            let turn = 4.0 * bulge.atan();
            let mut done = 0.0;
            let mut at = from;
            for (along, v) in on {
                out.push((at, ((along - done) / 4.0).tan()));
                done = along;
                at = v;
                cuts += 1;
            }
            out.push((at, ((turn - done) / 4.0).tan()));
        }
        *chain = out;
    }
    cuts
}

/// The vertices within `tolerance` of the interior of the arc `from → to`
/// with `bulge` (farther than `tolerance` from both ends), each with its
/// turn along the arc from `from` (signed as the arc turns), in order.
fn vertices_on_arc(sorted: &[Xy], from: Xy, to: Xy, bulge: f64, tolerance: f64) -> Vec<(f64, Xy)> {
    let Ok(arc) = CircularArc::from_bulge(from, to, bulge) else { return Vec::new() };
    let (c, r) = (arc.centre(), arc.radius());
    let reach = r + tolerance;
    let lo = sorted.partition_point(|p| p[0] < c.x - reach);
    let start = (from[1] - c.y).atan2(from[0] - c.x);
    let turn = arc.sweep();
    let mut found: Vec<(f64, Xy)> = Vec::new();
    for &v in sorted[lo..].iter().take_while(|p| p[0] <= c.x + reach) {
        let p = Point::new(v[0], v[1]);
        let near_end = |e: Xy| (e[0] - v[0]).hypot(e[1] - v[1]) <= tolerance;
        if (p.distance(c) - r).abs() > tolerance || near_end(from) || near_end(to) || !arc.spans(p) {
            continue;
        }
        // the turn from the start to `v`, the way the arc turns
        let angle = (v[1] - c.y).atan2(v[0] - c.x) - start;
        let full = std::f64::consts::TAU;
        let along = if turn > 0.0 { angle.rem_euclid(full) } else { -(-angle).rem_euclid(full) };
        if along.abs() < turn.abs() && !found.iter().any(|(_, q)| q == &v) {
            found.push((along, v));
        }
    }
    found.sort_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(raw: Raw) -> Item {
        Item { raw, name: String::new() }
    }

    #[test]
    fn a_line_ending_on_a_half_circle_cuts_it_there() {
        // a half circle from (2, 0) over (0, 2) to (-2, 0), and a line from
        // above ending a hair outside it at its top
        let mut items = vec![
            item(Raw::Chain { vertices: vec![([2.0, 0.0], 1.0), ([-2.0, 0.0], 0.0)], closed: false }),
            item(Raw::Line([[0.0, 5.0], [0.0, 2.0 + 1e-13]])),
        ];
        assert_eq!(split_arcs_at_vertices(&mut items), 1);
        let Raw::Chain { vertices, .. } = &items[0].raw else { panic!() };
        assert_eq!(vertices.len(), 3);
        assert_eq!(vertices[1].0, [0.0, 2.0 + 1e-13]);
        // two quarter turns, each tan(π/8)
        let quarter = (std::f64::consts::PI / 8.0).tan();
        assert!((vertices[0].1 - quarter).abs() < 1e-12 && (vertices[1].1 - quarter).abs() < 1e-12, "{vertices:?}");
        assert_eq!(vertices[2], ([-2.0, 0.0], 0.0));
    }

    #[test]
    fn clockwise_arcs_closed_chains_and_several_cuts() {
        // a whole circle as two clockwise halves, spokes ending on both
        let mut items = vec![
            item(Raw::Chain { vertices: vec![([1.0, 0.0], -1.0), ([-1.0, 0.0], -1.0)], closed: true }),
            item(Raw::Line([[0.0, 0.0], [0.0, -1.0]])),
            item(Raw::Line([[0.0, 0.0], [0.0, 1.0]])),
            item(Raw::Line([[0.0, 0.0], [-0.6, -0.8]])),
        ];
        assert_eq!(split_arcs_at_vertices(&mut items), 3);
        let Raw::Chain { vertices, .. } = &items[0].raw else { panic!() };
        let points: Vec<Xy> = vertices.iter().map(|v| v.0).collect();
        // clockwise from (1, 0): down through (0, -1) and (-0.6, -0.8) to
        // (-1, 0), then up through (0, 1)
        assert_eq!(points, vec![[1.0, 0.0], [0.0, -1.0], [-0.6, -0.8], [-1.0, 0.0], [0.0, 1.0]]);
        let turn: f64 = vertices.iter().map(|v| 4.0 * v.1.atan()).sum();
        assert!((turn + std::f64::consts::TAU).abs() < 1e-12, "{vertices:?}");
        assert!(vertices.iter().all(|v| v.1 < 0.0));
    }

    #[test]
    fn ends_and_far_vertices_cut_nothing() {
        let mut items = vec![
            item(Raw::Chain { vertices: vec![([2.0, 0.0], 1.0), ([-2.0, 0.0], 0.0)], closed: false }),
            item(Raw::Line([[2.0, 0.0], [5.0, 0.0]])),
            item(Raw::Line([[0.0, 5.0], [0.0, 2.001]])),
            item(Raw::Line([[0.0, -5.0], [0.0, -2.0]])),
        ];
        assert_eq!(split_arcs_at_vertices(&mut items), 0);
    }
}
