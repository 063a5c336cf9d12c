//! Polygons with holes as rings, for the medial-axis cross-check
//! (`segvoronoi_cgal_check --polygon`) and the glyph tests: the rings
//! format, an exact even-odd test, and the ring families.
//!
//! The rings format (written here, read here, by the harness and by
//! `tests/glyphs.rs`; the glyph fixtures `tests/data/glyph_*.rings` use it):
//!
//! ```text
//! # comment lines start with '#'; blank lines are ignored
//! rings R
//! K            (ring 1: K points, one per line; the last joins the first)
//! x y
//! ...
//! K'           (ring 2 ...)
//! ...
//! ```
//!
//! The domain is the even-odd region of all rings, whatever their
//! orientation (as `Builder::add_polygon`). Every family below makes rings
//! that are legal input: no two segments meet except consecutive ones of a
//! ring at their shared corner, checked exactly ([`crate::exact`]); each
//! hole lies inside the outer ring and outside the other holes, checked by
//! the exact [`even_odd`].

use crate::exact::{orient, segments_conflict, SegmentGrid};
use crate::near_degenerate::seed_scale;
use crate::shapes::star_ring;
use crate::{power_of_two, Point, Rng, Segment, TWO_PI};
use std::io::{self, Write};

/// The ring families, in the order `--list` prints them (after the others;
/// compared as "polygon"). See [`generate_rings`].
pub const RING_FAMILIES: &[&str] =
    &["rings-holes", "rings-inscribed", "rings-inscribed-jitter", "glyphs", "rings-touching", "rings-touching-split"];

/// The glyph fixtures (scripts/glyph_rings.py): B, 8 and g of DejaVu Sans.
pub const GLYPHS: &[(&str, &str)] = &[
    ("B", include_str!("../../tests/data/glyph_B.rings")),
    ("8", include_str!("../../tests/data/glyph_8.rings")),
    ("g", include_str!("../../tests/data/glyph_g.rings")),
];

/// Family `family` with about `n` corners in all from `seed`; `None` for
/// an unknown family or a size it cannot make.
///
/// - `rings-holes`: an outer star-shaped ring around the origin (radii
///   0.7 .. 1, so not convex) and about n / 32 (1 .. 24) random holes,
///   each a small star-shaped ring at a random place, kept where it is
///   legal and inside the domain; random coordinates, generic.
/// - `rings-inscribed`: an n/2-gon inscribed in the circle of radius
///   seed_scale(seed) (1e-6 .. 1e6) around a concentric n/2-gon of 0.4 of
///   its radius with the same angles, plus (n >= 64) up to 8 octagons in
///   the annulus: cocircular to the last bit, where many medial-axis
///   vertices are nearly degenerate.
/// - `rings-inscribed-jitter`: the same with every corner moved along its
///   circle by up to a third of the spacing.
/// - `glyphs`: the glyph fixture B, 8, g for seed 1, 2, 3 (then again,
///   scaled by 2^-10, 2^10, 2^-20, 2^20 in turn: exact, so the same
///   topology); `n` is ignored.
/// - `rings-touching`: rings that touch at points
///   ([`crate::straight::touching_rings`]: T-junctions, which the library
///   splits exactly); `rings-touching-split`: the same with each touching
///   corner inserted in the side it touches
///   ([`crate::straight::split_at_corners`]), for the CGAL cross-check.
///
/// Each family also comes as every variant of
/// [`crate::straight::VARIANTS`] (`rings-holes+straight`): its rings with
/// edges cut at exact points ([`crate::straight::cut_rings`]).
pub fn generate_rings(family: &str, n: usize, seed: u64) -> Option<Vec<Vec<Point>>> {
    if let (base, Some(straight)) = crate::straight::split_variant(family) {
        let rings = generate_rings(base, n, seed)?;
        return Some(crate::straight::cut_rings(&rings, &straight, &mut crate::straight::variant_rng(seed)));
    }
    let rng = &mut Rng(seed);
    match family {
        "rings-holes" if n >= 6 => Some(random_holes(n, rng)),
        "rings-inscribed" if n >= 6 => Some(inscribed_holes(n, seed, rng, false)),
        "rings-inscribed-jitter" if n >= 6 => Some(inscribed_holes(n, seed, rng, true)),
        "glyphs" => {
            let k = seed.wrapping_sub(1);
            let (_, text) = GLYPHS[(k % GLYPHS.len() as u64) as usize];
            let unit = power_of_two([0, -10, 10, -20, 20][((k / GLYPHS.len() as u64) % 5) as usize]);
            let rings = read_rings(text).expect("the glyph fixtures are well-formed");
            Some(rings.into_iter().map(|r| r.into_iter().map(|[x, y]| [unit * x, unit * y]).collect()).collect())
        }
        "rings-touching" if n >= 4 => Some(crate::straight::touching_rings(n, rng)),
        "rings-touching-split" if n >= 4 => Some(crate::straight::split_at_corners(&crate::straight::touching_rings(n, rng))),
        _ => None,
    }
}

/// Writes `rings` in the rings format, every number with the digits to
/// read back the same double.
pub fn write_rings(out: &mut impl Write, rings: &[Vec<Point>]) -> io::Result<()> {
    writeln!(out, "rings {}", rings.len())?;
    for ring in rings {
        writeln!(out, "{}", ring.len())?;
        for p in ring {
            writeln!(out, "{} {}", crate::format_g17(p[0]), crate::format_g17(p[1]))?;
        }
    }
    Ok(())
}

/// The real outlines of `tests/data` (or of the directory in
/// `SEGVORONOI_OUTLINES`, to try others: `scripts/country_rings.py CODE
/// --out DIR`): countries of the World from Debian's gmt-dcw
/// (`dcw_*.rings`) and islands of GSHHG (`gshhg_islands_*.rings`), by file
/// name, in name order.
pub fn real_outlines() -> Vec<(String, Vec<Vec<Point>>)> {
    let dir =
        std::env::var("SEGVORONOI_OUTLINES").unwrap_or_else(|_| concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data").into());
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{dir}: {e}")) {
        let path = entry.unwrap_or_else(|e| panic!("{dir}: {e}")).path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        if (name.starts_with("dcw_") || name.starts_with("gshhg_islands_")) && name.ends_with(".rings") {
            let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
            out.push((name.clone(), read_rings(&text).unwrap_or_else(|e| panic!("{name}: {e}"))));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(out.len() >= 3, "the real outlines are missing from {dir}");
    out
}

/// Reads the rings format; the error says what is wrong where.
pub fn read_rings(text: &str) -> Result<Vec<Vec<Point>>, String> {
    let mut words = text.lines().filter(|l| !l.trim_start().starts_with('#')).flat_map(str::split_whitespace);
    if words.next() != Some("rings") {
        return Err("the first word is not `rings`".into());
    }
    let ring_count = next_count(&mut words).ok_or("missing or malformed ring count")?;
    let mut rings = Vec::new();
    for r in 0..ring_count {
        let k = next_count(&mut words).ok_or_else(|| format!("ring {r}: missing or malformed point count"))?;
        let mut ring = Vec::new();
        for i in 0..k {
            let x = next_number(&mut words);
            let y = next_number(&mut words);
            let (Some(x), Some(y)) = (x, y) else { return Err(format!("ring {r}, point {i}: missing or not finite")) };
            ring.push([x, y]);
        }
        rings.push(ring);
    }
    if words.next().is_some() {
        return Err("text after the last ring".into());
    }
    Ok(rings)
}

fn next_count<'a>(words: &mut impl Iterator<Item = &'a str>) -> Option<usize> {
    words.next()?.parse().ok()
}

fn next_number<'a>(words: &mut impl Iterator<Item = &'a str>) -> Option<f64> {
    words.next()?.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The segments of closed rings, ring by ring, corner k to corner k + 1:
/// the order `Builder::add_polygon` gives them input indices in.
pub fn ring_segments(rings: &[Vec<Point>]) -> Vec<Segment> {
    rings.iter().flat_map(|r| (0..r.len()).map(move |k| [r[k], r[(k + 1) % r.len()]])).collect()
}

/// Whether `p` lies inside the even-odd region of `rings`, exactly (the
/// crossing number of a ray to +x, each crossing decided by an exact
/// orientation). A point on a ring counts as either; callers ask about
/// points off the rings.
pub fn even_odd(rings: &[Vec<Point>], p: Point) -> bool {
    let mut inside = false;
    for ring in rings {
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            // the half-open rule on y, so a corner at p's height counts once
            if (a[1] > p[1]) != (b[1] > p[1]) {
                // the crossing is right of p when p is left of the edge
                // directed upward
                let (lo, hi) = if a[1] < b[1] { (a, b) } else { (b, a) };
                if orient(lo, hi, p) > 0 {
                    inside = !inside;
                }
            }
        }
    }
    inside
}

/// The rings accepted so far, with a grid of their segments for the
/// exact legality test of the next ring.
struct RingSet {
    rings: Vec<Vec<Point>>,
    segments: Vec<Segment>,
    grid: SegmentGrid,
}

impl RingSet {
    fn new(extent: f64, n: usize) -> RingSet {
        let side = SegmentGrid::side_for(n);
        RingSet { rings: Vec::new(), segments: Vec::new(), grid: SegmentGrid::new([-extent, -extent], [extent, extent], side) }
    }

    /// Adds `ring` when it is legal: at least three corners, no segment
    /// meeting another (its own neighbours at their shared corner only);
    /// after the first ring, inside the domain so far (a hole inside the
    /// outer ring, outside every other hole) with no earlier hole inside it.
    fn try_add(&mut self, ring: Vec<Point>) -> bool {
        let m = ring.len();
        if m < 3 {
            return false;
        }
        let own = ring_segments(std::slice::from_ref(&ring));
        // the ring against itself (star_ring's corners keep their angular
        // order, so it is simple unless rounding folds a nearly straight
        // corner), then against the rings so far
        let (mut lo, mut hi) = (ring[0], ring[0]);
        for p in &ring {
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        let mut local = SegmentGrid::new(lo, hi, SegmentGrid::side_for(m));
        for (i, &s) in own.iter().enumerate() {
            if local.any_near(s, |id| segments_conflict(s, own[id])) {
                return false;
            }
            local.add(s, i);
            let segments = &self.segments;
            if self.grid.any_near(s, |id| segments_conflict(s, segments[id])) {
                return false;
            }
        }
        if !self.rings.is_empty() {
            if !even_odd(&self.rings, ring[0]) {
                return false;
            }
            let new = std::slice::from_ref(&ring);
            if self.rings[1..].iter().any(|hole| even_odd(new, hole[0])) {
                return false;
            }
        }
        for s in own {
            self.grid.add(s, self.segments.len());
            self.segments.push(s);
        }
        self.rings.push(ring);
        true
    }
}

/// `rings-holes` (see [`generate_rings`]).
fn random_holes(n: usize, rng: &mut Rng) -> Vec<Vec<Point>> {
    let holes = (n / 32).clamp(1, 24);
    let hole_corners = (n / (3 * holes)).clamp(3, 64);
    let outer_corners = n.saturating_sub(holes * hole_corners).max(3);
    let mut set = RingSet::new(1.0, n);
    // star_ring keeps the corners in angular order around the centre, so
    // the ring is simple; the exact test still has the last word
    while !set.try_add(star_ring(outer_corners, 0.0, 0.0, 0.7, 1.0, rng)) {}
    let mut placed = 0;
    for _ in 0..50 * holes {
        if placed == holes {
            break;
        }
        let (angle, distance) = (TWO_PI * rng.unit(), 0.65 * rng.unit().sqrt());
        let r = 0.04 + 0.12 * rng.unit();
        let (cx, cy) = (distance * angle.cos(), distance * angle.sin());
        if set.try_add(star_ring(hole_corners, cx, cy, 0.5 * r, r, rng)) {
            placed += 1;
        }
    }
    set.rings
}

/// `rings-inscribed` and `rings-inscribed-jitter` (see [`generate_rings`]).
fn inscribed_holes(n: usize, seed: u64, rng: &mut Rng, jitter: bool) -> Vec<Vec<Point>> {
    let radius = seed_scale(seed);
    let small = if n >= 64 { (n / 64).min(8) } else { 0 };
    let corners = ((n - 8 * small) / 2).max(3);
    let on_circle = |m: usize, cx: f64, cy: f64, r: f64, rng: &mut Rng| -> Vec<Point> {
        let spacing = TWO_PI / m as f64;
        (0..m)
            .map(|k| {
                let angle = spacing * (k as f64 + if jitter { (rng.unit() - 0.5) * 0.66 } else { 0.0 });
                [cx + r * angle.cos(), cy + r * angle.sin()]
            })
            .collect()
    };
    let mut set = RingSet::new(radius, n);
    let outer = on_circle(corners, 0.0, 0.0, radius, rng);
    let inner = on_circle(corners, 0.0, 0.0, 0.4 * radius, rng);
    assert!(set.try_add(outer), "an inscribed polygon is simple");
    // a hole that does not fit (a coarse outer polygon) is left out
    set.try_add(inner);
    for j in 0..small {
        let angle = TWO_PI * (j as f64 + 0.5) / small as f64;
        let (cx, cy) = (0.75 * radius * angle.cos(), 0.75 * radius * angle.sin());
        let ring = on_circle(8, cx, cy, 0.08 * radius, rng);
        set.try_add(ring);
    }
    set.rings
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corners(rings: &[Vec<Point>]) -> usize {
        rings.iter().map(Vec::len).sum()
    }

    #[test]
    fn rings_round_trip() {
        let rings = generate_rings("rings-holes", 200, 7).unwrap();
        let mut out = Vec::new();
        write_rings(&mut out, &rings).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(read_rings(&format!("# a comment\n\n{text}")).unwrap(), rings);
        assert!(read_rings("rings 1\n3\n0 0\n1 0\n").is_err());
        assert!(read_rings("rings 1\n3\n0 0\n1 0\n0 1\n5\n").is_err());
        assert!(read_rings("ring 1\n").is_err());
        assert!(read_rings("rings 1\n3\n0 0\n1 inf\n0 1\n").is_err());
    }

    #[test]
    fn even_odd_is_exact_at_the_last_bit() {
        let square = vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]];
        assert!(even_odd(&square, [0.5, 0.5]));
        assert!(!even_odd(&square, [1.5, 0.5]));
        // a slanted edge from (0, 0) to (1, 3): x = y / 3 on it, rounded
        let tri = vec![vec![[0.0, 0.0], [1.0, 3.0], [-1.0, 3.0]]];
        let y = 1.0;
        let on = 1.0 / 3.0; // rounded: below the exact 1/3, so inside
        assert_eq!(orient([0.0, 0.0], [1.0, 3.0], [on, y]) > 0, even_odd(&tri, [on, y]));
        assert!(!even_odd(&tri, [crate::next_after(on, true), y]));
        // holes flip the region
        let with_hole = vec![square[0].clone(), vec![[0.25, 0.25], [0.75, 0.25], [0.75, 0.75], [0.25, 0.75]]];
        assert!(!even_odd(&with_hole, [0.5, 0.5]));
        assert!(even_odd(&with_hole, [0.1, 0.5]));
    }

    /// Every family, at several sizes and seeds: legal rings (checked
    /// again by brute force), holes inside the outer ring and outside each
    /// other, deterministic, about the size asked for.
    #[test]
    fn ring_families_are_legal() {
        let variants = crate::straight::VARIANTS.iter().map(|(suffix, _)| *suffix);
        let names: Vec<String> = RING_FAMILIES
            .iter()
            .filter(|&&family| !family.starts_with("rings-touching")) // touching by design
            .flat_map(|family| {
                std::iter::once(String::new()).chain(variants.clone().map(String::from)).map(move |v| format!("{family}{v}"))
            })
            .collect();
        for family in &names {
            let family = family.as_str();
            for (n, seed) in [(8, 1), (64, 2), (300, 3), (1000, 4)] {
                let rings = generate_rings(family, n, seed).unwrap_or_else(|| panic!("{family} {n}"));
                assert_eq!(Some(&rings), generate_rings(family, n, seed).as_ref(), "{family} is deterministic");
                let segments = ring_segments(&rings);
                for i in 0..segments.len() {
                    for j in 0..i {
                        assert!(!segments_conflict(segments[i], segments[j]), "{family} {n} {seed}: {i} and {j}");
                    }
                }
                if !family.starts_with("glyphs") {
                    // the first ring is the outer one (the glyphs' are in the font's order)
                    for (k, hole) in rings.iter().enumerate().skip(1) {
                        let others: Vec<Vec<Point>> =
                            rings.iter().enumerate().filter(|&(j, _)| j != k).map(|(_, r)| r.clone()).collect();
                        assert!(even_odd(&others, hole[0]), "{family} {n} {seed}: hole {k} is not in the domain");
                    }
                    assert!(rings.len() >= 2, "{family} {n} {seed}: no hole");
                    assert!(
                        family.contains('+') || corners(&rings) <= n.max(6) + 8,
                        "{family} {n} {seed}: {} corners",
                        corners(&rings)
                    );
                }
            }
        }
        assert!(generate_rings("rings-holes", 5, 1).is_none());
        assert!(generate_rings("no-such-family", 10, 1).is_none());
    }

    #[test]
    fn glyphs_have_their_rings() {
        let rings: Vec<usize> = (1..=3).map(|seed| generate_rings("glyphs", 0, seed).unwrap().len()).collect();
        assert_eq!(rings, [3, 3, 2]);
        // scaled by a power of two, exactly
        let (b, b_small) = (generate_rings("glyphs", 0, 1).unwrap(), generate_rings("glyphs", 0, 4).unwrap());
        assert_eq!(b_small[0][0], [b[0][0][0] / 1024.0, b[0][0][1] / 1024.0]);
    }
}
