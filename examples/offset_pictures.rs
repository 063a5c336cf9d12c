//! Draws the picture of offsets committed in `docs/`:
//!
//! `cargo run --example offset_pictures > docs/glyph_offsets.svg`
//!
//! The glyph B of DejaVu Sans (`tests/data/glyph_B.rings`) and its offsets
//! at eight distances, all from one `Diagram::offsets` call. Inward (blue):
//! the two holes grow, break through the thin parts of the ring around
//! them (one loop at 75 font units), the rest splits into the stem and the
//! two bowls, which vanish one after the other, and at 110 only a sliver of
//! the stem is left. Outward (orange): the holes shrink, and at 250 the
//! upper one has closed. Every loop is drawn exactly, as an SVG path of
//! lines (`L`) and circular arcs (`A`); holes (clockwise loops) are dashed.
//! The glyph's outline is on top.

use segvoronoi::{Builder, OffsetLoop, OffsetPiece, Point};
use std::f64::consts::PI;
use std::fmt::Write;

/// Inward distances, in font units (2048 per em), shallowest first.
const INWARD: [f64; 5] = [-25.0, -50.0, -75.0, -95.0, -110.0];
/// Outward distances, nearest first.
const OUTWARD: [f64; 3] = [40.0, 120.0, 250.0];

/// The rings of a file in the rings format (`rings R`, then per ring a
/// count and its points; `#` comments), as `tests/data/glyph_*.rings`.
fn read_rings(text: &str) -> Vec<Vec<[f64; 2]>> {
    let mut numbers = text.lines().filter(|l| !l.starts_with('#')).flat_map(str::split_whitespace).skip(1);
    let mut next = || numbers.next().expect("a complete rings file").parse::<f64>().expect("a number");
    let count = next() as usize;
    (0..count).map(|_| (0..next() as usize).map(|_| [next(), next()]).collect()).collect()
}

/// Input coordinates to pixels: `scale` pixels per unit, the point
/// `(x0, y1)` at `(left, top)`, the y axis flipped (it points down in SVG).
#[derive(Clone, Copy)]
struct Frame {
    scale: f64,
    x0: f64,
    y1: f64,
    left: f64,
    top: f64,
}

impl Frame {
    fn pixel(&self, p: Point) -> String {
        let (x, y) = (self.left + self.scale * (p.x - self.x0), self.top + self.scale * (self.y1 - p.y));
        format!("{x:.2},{y:.2}")
    }
}

/// A loop as SVG path data: `M`, an `L` per line piece and an `A` per arc,
/// `Z`. With y pointing down, an arc counter-clockwise in the input is
/// clockwise on the screen: sweep flag 0. An arc whose ends fall on the
/// same pixel (a whole circle) would not be drawn at all, so one over half
/// a turn becomes two half circles through the point opposite its start;
/// a shorter one is too small to see and left out.
fn loop_path(frame: &Frame, l: &OffsetLoop) -> String {
    let mut d = format!("M{}", frame.pixel(l.pieces[0].from()));
    for piece in &l.pieces {
        match *piece {
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                let r = radius * frame.scale;
                let turn = piece.sweep().expect("an arc");
                let (start, end) = (frame.pixel(from), frame.pixel(to));
                let flag = u8::from(!counter_clockwise);
                if start != end {
                    let _ = write!(d, " A{r:.2},{r:.2} 0 {} {flag} {end}", u8::from(turn > PI));
                } else if turn > PI {
                    let opposite = frame.pixel(Point::new(2.0 * centre.x - from.x, 2.0 * centre.y - from.y));
                    let _ = write!(d, " A{r:.2},{r:.2} 0 0 {flag} {opposite} A{r:.2},{r:.2} 0 0 {flag} {end}");
                }
            }
            // a line (or a kind of piece this example does not know): straight on
            _ => {
                let _ = write!(d, " L{}", frame.pixel(piece.to()));
            }
        }
    }
    d.push_str(" Z");
    d
}

fn main() -> Result<(), segvoronoi::Error> {
    let rings = read_rings(include_str!("../tests/data/glyph_B.rings"));
    let mut b = Builder::new();
    b.add_polygon(&rings)?;
    let diagram = b.build()?;
    let distances: Vec<f64> = INWARD.iter().chain(&OUTWARD).copied().collect();
    let offsets = diagram.offsets(&distances)?;

    // the glyph's bounding box grown by the largest distance, fitted into
    // 500 pixels of height
    let grow = OUTWARD.iter().fold(0.0f64, |a, &b| a.max(b));
    let points = || rings.iter().flatten();
    let (x0, x1) = points().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p[0]), b.max(p[0])));
    let (y0, y1) = points().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p[1]), b.max(p[1])));
    let (x0, x1, y0, y1) = (x0 - grow, x1 + grow, y0 - grow, y1 + grow);
    let scale = 500.0 / (y1 - y0);
    let frame = Frame { scale, x0, y1, left: 20.0, top: 40.0 };
    let (width, height) = ((scale * (x1 - x0) + 280.0).round(), 560.0);

    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    );
    let _ = writeln!(svg, r#"<rect width="{width}" height="{height}" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<text x="20" y="24" font-family="sans-serif" font-size="15">offsets of B (DejaVu Sans): exact lines and arcs</text>"#
    );
    let mut path = String::new();
    for ring in &rings {
        for (k, &[x, y]) in ring.iter().enumerate() {
            let _ = write!(path, "{}{} ", if k == 0 { "M" } else { "L" }, frame.pixel(Point::new(x, y)));
        }
        path.push_str("Z ");
    }
    let _ = writeln!(svg, r##"<path d="{path}" fill="#eef2f7" fill-rule="evenodd"/>"##);

    // the legend, beside the glyph
    let legend_x = frame.left + scale * (x1 - x0) + 30.0;
    let mut legend_y = 70.0;
    for (offset, colour) in offsets.iter().zip(colours()) {
        let _ = writeln!(svg, r#"<g fill="none" stroke="{colour}" stroke-width="1.6" stroke-linejoin="round">"#);
        for l in &offset.loops {
            let dash = if l.hole { r#" stroke-dasharray="5 3""# } else { "" };
            let _ = writeln!(svg, r#"<path d="{}"{dash}/>"#, loop_path(&frame, l));
        }
        svg.push_str("</g>\n");
        let holes = offset.loops.iter().filter(|l| l.hole).count();
        let _ = writeln!(
            svg,
            r#"<line x1="{legend_x}" y1="{y}" x2="{x2}" y2="{y}" stroke="{colour}" stroke-width="2.5"/>"#,
            y = legend_y - 5.0,
            x2 = legend_x + 24.0
        );
        let _ = writeln!(
            svg,
            r#"<text x="{x}" y="{legend_y}" font-family="sans-serif" font-size="13">d = {:+}: {} loop{}, {holes} hole{}</text>"#,
            offset.distance,
            offset.loops.len(),
            if offset.loops.len() == 1 { "" } else { "s" },
            if holes == 1 { "" } else { "s" },
            x = legend_x + 32.0,
        );
        legend_y += 22.0;
    }
    let _ = writeln!(
        svg,
        r##"<text x="{legend_x}" y="{y}" font-family="sans-serif" font-size="12" fill="#555">font units, 2048 per em;</text>"##,
        y = legend_y + 14.0
    );
    let _ = writeln!(
        svg,
        r##"<text x="{legend_x}" y="{y}" font-family="sans-serif" font-size="12" fill="#555">holes (clockwise loops) dashed</text>"##,
        y = legend_y + 30.0
    );
    let _ = writeln!(svg, r##"<path d="{path}" fill="none" stroke="#222" stroke-width="1.2"/>"##);
    svg.push_str("</svg>\n");
    print!("{svg}");
    Ok(())
}

/// One colour per distance, in the order of `INWARD` then `OUTWARD`: blues
/// getting darker inwards, oranges getting lighter outwards.
fn colours() -> impl Iterator<Item = &'static str> {
    ["#9ecae1", "#6baed6", "#3182bd", "#08519c", "#08306b", "#e6550d", "#fd8d3c", "#fdae6b"].into_iter()
}
