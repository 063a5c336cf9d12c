//! Draws the pictures of the medial axis committed in `docs/`:
//!
//! `cargo run --example medial_axis_pictures > docs/medial_axis_filters.svg`
//! `cargo run --example medial_axis_pictures -- glyph > docs/glyph_medial_axis.svg`
//!
//! The second is the glyph B of DejaVu Sans (`tests/data/glyph_B.rings`),
//! its medial axis whole and with the corner filter at 150 degrees. The
//! first shows what the two filters remove.
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

/// Where a panel of a shape goes: `scale` pixels per unit, its bounding
/// box's corner `(x0, y1)` at the panel's top left.
#[derive(Clone, Copy)]
struct Frame {
    scale: f64,
    x0: f64,
    y1: f64,
}

impl Frame {
    /// The frame that fits the rings into `width` by `height` pixels.
    fn fitting(rings: &[Vec<[f64; 2]>], width: f64, height: f64) -> Frame {
        let points = || rings.iter().flatten();
        let (x0, x1) = points().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p[0]), b.max(p[0])));
        let (y0, y1) = points().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p[1]), b.max(p[1])));
        Frame { scale: (width / (x1 - x0)).min(height / (y1 - y0)), x0, y1 }
    }
}

/// One panel: the domain, the kept branches and the removed ones.
fn panel(svg: &mut String, d: &Diagram, rings: &[Vec<[f64; 2]>], kept: &HashSet<EdgeId>, frame: Frame, dx: f64, title: &str) {
    let map = |[x, y]: [f64; 2]| (dx + 20.0 + frame.scale * (x - frame.x0), 40.0 + frame.scale * (frame.y1 - y));
    let mut path = String::new();
    for ring in rings {
        for (k, &p) in ring.iter().enumerate() {
            let (x, y) = map(p);
            let _ = write!(path, "{}{x:.2},{y:.2} ", if k == 0 { "M" } else { "L" });
        }
        path.push_str("Z ");
    }
    let _ = writeln!(svg, r##"<path d="{path}" fill="#eef2f7" fill-rule="evenodd" stroke="#333" stroke-width="1.2"/>"##);
    let tolerance = 1e-3 / frame.scale;
    for chain in &d.medial_axis().chains {
        for piece in &chain.pieces {
            let Some(points) = d.sample_piece(piece, tolerance) else { continue };
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

/// The rings of a file in the rings format (`rings R`, then per ring a
/// count and its points; `#` comments), as `tests/data/glyph_*.rings`.
fn read_rings(text: &str) -> Vec<Vec<[f64; 2]>> {
    let mut numbers = text.lines().filter(|l| !l.starts_with('#')).flat_map(str::split_whitespace).skip(1);
    let mut next = || numbers.next().expect("a complete rings file").parse::<f64>().expect("a number");
    let count = next() as usize;
    (0..count).map(|_| (0..next() as usize).map(|_| [next(), next()]).collect()).collect()
}

/// The panels of one shape, side by side, one per filter, as an SVG.
fn picture(rings: &[Vec<[f64; 2]>], panels: &[(MedialAxisFilter, &str)], height: f64) -> Result<String, segvoronoi::Error> {
    let mut b = Builder::new();
    b.add_polygon(rings)?;
    let d = b.build()?;
    let frame = Frame::fitting(rings, 400.0, height - 60.0);
    let width = 440.0 * panels.len() as f64;
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    );
    let _ = writeln!(svg, r#"<rect width="{width}" height="{height}" fill="white"/>"#);
    for (k, &(filter, title)) in panels.iter().enumerate() {
        let kept = d.medial_axis_filtered(&filter).chains.iter().flat_map(|c| c.pieces.iter().map(|p| p.edge)).collect();
        panel(&mut svg, &d, rings, &kept, frame, 440.0 * k as f64, title);
    }
    svg.push_str("</svg>\n");
    Ok(svg)
}

fn main() -> Result<(), segvoronoi::Error> {
    let svg = match std::env::args().nth(1).as_deref() {
        Some("glyph") => {
            let text = include_str!("../tests/data/glyph_B.rings");
            let panels = [
                (MedialAxisFilter::new(), "medial axis of B (DejaVu Sans)"),
                (MedialAxisFilter::new().with_corner_angle(150.0), "corner filter, 150°"),
            ];
            picture(&read_rings(text), &panels, 560.0)?
        }
        _ => {
            let rings = vec![outline(10.0, 6.0, 2.0, 6), circle(3.2, 3.0, 1.0, 16)];
            let panels = [
                (MedialAxisFilter::new(), "medial axis"),
                (MedialAxisFilter::new().with_corner_angle(160.0), "corner filter, 160°"),
                (MedialAxisFilter::new().with_spur_pruning(1.5), "spur filter, k = 1.5"),
            ];
            picture(&rings, &panels, 330.0)?
        }
    };
    print!("{svg}");
    Ok(())
}
