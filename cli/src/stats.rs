//! The `--stats` report: one `key=value` line per figure, so that scripts can
//! pick figures out with `grep` or split on `=`.

use std::fmt::Write;

use segvoronoi::{Diagram, EdgeEnd, EdgeShape};

/// The report for a diagram whose construction took `build_s` seconds.
pub fn report(diagram: &Diagram, build_s: f64) -> String {
    let stats = diagram.stats();
    let (mut segments, mut rays, mut lines, mut arcs, mut conics) = (0usize, 0usize, 0usize, 0usize, 0usize);
    for edge in diagram.edges() {
        match edge.ends {
            [EdgeEnd::Vertex(_), EdgeEnd::Vertex(_)] => segments += 1,
            [EdgeEnd::Infinite { .. }, EdgeEnd::Infinite { .. }] => lines += 1,
            _ => rays += 1,
        }
        match diagram.edge_shape(edge.id) {
            Some(EdgeShape::Parabola { .. }) => arcs += 1,
            Some(EdgeShape::Conic { .. }) => conics += 1,
            _ => {}
        }
    }
    let arc_sites = diagram.arc_site_count();
    let segment_sites = diagram.site_count() - diagram.point_site_count() - arc_sites;
    let mut out = String::new();
    let figures: [(&str, &dyn std::fmt::Display); 25] = [
        ("input_points", &stats.input_points),
        ("input_segments", &stats.input_segments),
        ("sites", &stats.sites),
        ("segment_sites", &segment_sites),
        ("arc_sites", &arc_sites),
        ("duplicates", &stats.duplicate_points),
        ("duplicate_segments", &stats.duplicate_segments),
        ("zero_length_segments", &stats.zero_length_segments),
        ("dropped_chain_points", &stats.dropped_chain_points),
        ("vertices", &stats.vertices),
        ("edges", &stats.edges),
        ("finite_edges", &segments),
        ("rays", &rays),
        ("lines", &lines),
        ("parabolic_edges", &arcs),
        ("conic_edges", &conics),
        ("pieces", &stats.pieces),
        ("split_at_vertices", &stats.split_at_vertices),
        ("cancelled_ring_pieces", &stats.cancelled_ring_pieces),
        ("crossings", &stats.crossings),
        ("overlaps", &stats.overlaps),
        ("touchings", &stats.touchings),
        ("snap_rounds", &stats.snap_rounds),
        ("max_split_displacement", &diagram.max_split_displacement()),
        ("build_s", &format_args!("{build_s:.6}")),
    ];
    for (key, value) in figures {
        let _ = writeln!(out, "{key}={value}");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(report: &str, key: &str) -> String {
        let prefix = format!("{key}=");
        report.lines().find_map(|l| l.strip_prefix(&prefix)).unwrap_or_else(|| panic!("no {key} in {report}")).to_string()
    }

    #[test]
    fn counts_add_up() {
        let mut b = segvoronoi::Builder::new();
        b.add_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0], [1.0, 1.0]]).unwrap();
        let r = report(&b.build().unwrap(), 0.25);
        assert_eq!(value(&r, "input_points"), "6");
        assert_eq!(value(&r, "sites"), "5");
        assert_eq!(value(&r, "duplicates"), "1");
        assert_eq!(value(&r, "vertices"), "4");
        assert_eq!(value(&r, "edges"), "8");
        assert_eq!(value(&r, "finite_edges"), "4");
        assert_eq!(value(&r, "rays"), "4");
        assert_eq!(value(&r, "lines"), "0");
        assert_eq!(value(&r, "build_s").parse::<f64>().unwrap(), 0.25);
        for key in ["input_segments", "segment_sites", "duplicate_segments", "zero_length_segments", "parabolic_edges"] {
            assert_eq!(value(&r, key), "0", "{key}");
        }
    }

    #[test]
    fn segment_counts() {
        // Two equal segments (one reversed), a zero-length one, and a point
        // above the first: sites are the point, the two endpoints, the
        // zero-length segment's point, and one open segment.
        let mut b = segvoronoi::Builder::new();
        b.add_segments([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [0.0, 0.0]], [[9.0, 9.0], [9.0, 9.0]]]).unwrap();
        b.add_point([2.0, 2.0]).unwrap();
        let r = report(&b.build().unwrap(), 0.0);
        assert_eq!(value(&r, "input_points"), "1");
        assert_eq!(value(&r, "input_segments"), "3");
        assert_eq!(value(&r, "duplicate_segments"), "1");
        assert_eq!(value(&r, "zero_length_segments"), "1");
        assert_eq!(value(&r, "segment_sites"), "1");
        assert_eq!(value(&r, "sites"), "5");
        assert_eq!(value(&r, "parabolic_edges"), "1");
    }

    #[test]
    fn touching_vertices_split_segments() {
        // A hole touching its shell inside the shell's left edge, and a
        // point on the bottom edge: two cuts, two more pieces.
        let mut b = segvoronoi::Builder::new();
        b.add_polygon(&[vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]], vec![[0.0, 5.0], [3.0, 4.0], [3.0, 6.0]]])
            .unwrap();
        b.add_point([4.0, 0.0]).unwrap();
        let r = report(&b.build().unwrap(), 0.0);
        assert_eq!(value(&r, "input_segments"), "7");
        assert_eq!(value(&r, "split_at_vertices"), "2");
        assert_eq!(value(&r, "pieces"), "9");
        assert_eq!(value(&r, "segment_sites"), "9");
        assert_eq!(value(&r, "duplicates"), "0");
        assert_eq!(value(&r, "max_split_displacement"), "0");
    }

    #[test]
    fn collinear_sites_have_lines() {
        let mut b = segvoronoi::Builder::new();
        b.add_points([[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]]).unwrap();
        let r = report(&b.build().unwrap(), 0.0);
        assert_eq!((value(&r, "lines").as_str(), value(&r, "rays").as_str()), ("2", "0"));
    }
}
