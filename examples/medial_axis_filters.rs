//! Draws what the two medial-axis filters remove, as the SVG committed in
//! `docs/medial_axis_filters.svg`:
//!
//! `cargo run --example medial_axis_filters > docs/medial_axis_filters.svg`
//!
//! The shape is a rounded rectangle (its corners flattened into chords, as
//! curves in fonts and icons are) with a round hole and a small bump. Left:
//! the whole medial axis. Middle: the corner filter at 160 degrees takes the
//! branches into the chords' corners (each about 169 degrees). Right: the
//! spur filter at k = 1.5 takes the leaf branches shorter than 1.5 times
//! the clearance at their junction. Kept branches are blue, removed ones red and dashed.

use segvoronoi::{Builder, Diagram, EdgeId, MedialAxisFilter};
use std::collections::HashSet;
use std::f64::consts::{FRAC_PI_2, TAU};
use std::fmt::Write;

/// A rectangle `w` by `h` with corners of radius `r`, each in `n` chords,
/// and a bump on its top side.
fn outline(w: f64, h: f64, r: f64, n: usize) -> Vec<[f64; 2]> {
    let mut ring = Vec::new();
    let corners = [(w - r, r, -FRAC_PI_2), (w - r, h - r, 0.0), (r, h - r, FRAC_PI_2), (r, r, 2.0 * FRAC_PI_2)];
    for (k, &(cx, cy, from)) in corners.iter().enumerate() {
        if k == 2 {
            // the bump, on the top side between the second and third corner
            ring.extend([[0.62 * w, h], [0.58 * w, h + 0.5], [0.54 * w, h]]);
        }
        for j in 0..=n {
            let t = from + FRAC_PI_2 * j as f64 / n as f64;
            ring.push([cx + r * t.cos(), cy + r * t.sin()]);
        }
    }
    ring
}

fn circle(cx: f64, cy: f64, r: f64, n: usize) -> Vec<[f64; 2]> {
    (0..n).map(|k| TAU * k as f64 / n as f64).map(|t| [cx + r * t.cos(), cy + r * t.sin()]).collect()
}

/// One panel: the domain, the kept branches and the removed ones.
fn panel(svg: &mut String, d: &Diagram, rings: &[Vec<[f64; 2]>], kept: &HashSet<EdgeId>, dx: f64, title: &str) {
    let (scale, top) = (40.0, 6.9);
    let map = |[x, y]: [f64; 2]| (dx + 20.0 + scale * x, 40.0 + scale * (top - y));
    let mut path = String::new();
    for ring in rings {
        for (k, &p) in ring.iter().enumerate() {
            let (x, y) = map(p);
            let _ = write!(path, "{}{x:.2},{y:.2} ", if k == 0 { "M" } else { "L" });
        }
        path.push_str("Z ");
    }
    let _ = writeln!(svg, r##"<path d="{path}" fill="#eef2f7" fill-rule="evenodd" stroke="#333" stroke-width="1.2"/>"##);
    for chain in &d.medial_axis().chains {
        for piece in &chain.pieces {
            let Some(points) = d.sample_piece(piece, 1e-3) else { continue };
            let line: Vec<String> = points
                .iter()
                .map(|&[x, y, _]| {
                    let (x, y) = map([x, y]);
                    format!("{x:.2},{y:.2}")
                })
                .collect();
            let style = if kept.contains(&piece.edge) {
                r##"stroke="#1f5fbf" stroke-width="2""##
            } else {
                r##"stroke="#d03030" stroke-width="1.5" stroke-dasharray="4 3""##
            };
            let _ = writeln!(svg, r#"<polyline points="{}" fill="none" {style}/>"#, line.join(" "));
        }
    }
    let _ = writeln!(svg, r#"<text x="{:.0}" y="24" font-family="sans-serif" font-size="15">{title}</text>"#, dx + 20.0);
}

fn main() -> Result<(), segvoronoi::Error> {
    let rings = vec![outline(10.0, 6.0, 2.0, 6), circle(3.2, 3.0, 1.0, 16)];
    let mut b = Builder::new();
    b.add_polygon(&rings)?;
    let d = b.build()?;
    let edges = |filter: MedialAxisFilter| -> HashSet<EdgeId> {
        d.medial_axis_filtered(&filter).chains.iter().flat_map(|c| c.pieces.iter().map(|p| p.edge)).collect()
    };
    let panels = [
        (MedialAxisFilter::new(), "medial axis"),
        (MedialAxisFilter::new().with_corner_angle(160.0), "corner filter, 160°"),
        (MedialAxisFilter::new().with_spur_pruning(1.5), "spur filter, k = 1.5"),
    ];
    let mut svg = String::new();
    let _ = writeln!(svg, r#"<svg xmlns="http://www.w3.org/2000/svg" width="1320" height="330" viewBox="0 0 1320 330">"#);
    let _ = writeln!(svg, r#"<rect width="1320" height="330" fill="white"/>"#);
    for (k, (filter, title)) in panels.into_iter().enumerate() {
        panel(&mut svg, &d, &rings, &edges(filter), 440.0 * k as f64, title);
    }
    svg.push_str("</svg>\n");
    print!("{svg}");
    Ok(())
}
