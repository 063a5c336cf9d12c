//! Every generated input of segvoronoi's tests in one place: the families
//! of the CGAL cross-check (`c_tests/cgal_crosscheck.cpp` reads the files
//! that [`write_text`] writes), its randomised search ([`search`]), the
//! shapes of the cargo tests ([`shapes`]) and the benchmark's inputs
//! ([`bench`], [`long_segments`]).
//!
//! Everything is driven by one generator, [`Rng`] (SplitMix64), so that an
//! input depends on nothing but its family, size and seed, on every
//! platform. The cross-check's families were written in C++ first; they are
//! the same here bit for bit (same draws in the same order, the same
//! arithmetic, exact contact tests), so an input named by a test or a
//! regression note is still the same input.
//!
//! Segment inputs are legal by construction where the family says so: no
//! two segments cross, overlap or touch except at a shared endpoint, and no
//! isolated point lies inside a segment, tested exactly ([`exact`]).

// The generators write the C++ harness's constants digit for digit (so the
// families stay bit-identical), not the `std::f64::consts` they round to.
#![allow(clippy::approx_constant, clippy::unusual_byte_groupings)]

/// The Rust guide (`docs/guide.md`), run as doctests so that it cannot rot:
/// the library's own doctests run the README's blocks, and this crate,
/// which depends on the library, runs the guide's.
#[cfg(doctest)]
#[doc = include_str!("../../docs/guide.md")]
struct RustGuideDoctests;

pub mod arcs;
pub mod bench;
pub mod exact;
pub mod long_segments;
mod near_degenerate;
mod points;
pub mod rings;
pub mod search;
mod segments;
pub mod shapes;
mod split;
pub mod straight;
pub mod ties;

use segvoronoi::splitmix::SplitMix64;
use std::io::{self, Write};

/// A point `[x, y]`.
pub type Point = [f64; 2];
/// A segment by its two endpoints, first then second.
pub type Segment = [Point; 2];

/// 2π as the generators write it (the C++ harness's literal).
pub(crate) const TWO_PI: f64 = 6.283185307179586;

/// SplitMix64 (Steele, Lea, Flood 2014), the library's own
/// (`segvoronoi::splitmix`): tiny, and the same sequence on every platform
/// (the standard libraries' distributions are not).
#[derive(Clone, Debug)]
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.step(SplitMix64::next_u64)
    }

    /// Uniform in [0, 1), 53 random bits (the most an `f64` holds).
    pub fn unit(&mut self) -> f64 {
        self.step(SplitMix64::unit)
    }

    /// One draw of the library's generator from this state.
    fn step<T>(&mut self, draw: impl FnOnce(&mut SplitMix64) -> T) -> T {
        let mut g = SplitMix64(self.0);
        let value = draw(&mut g);
        self.0 = g.0;
        value
    }

    /// Uniform in `0..bound` (by remainder: the tiny bias does not matter here).
    pub fn below(&mut self, bound: usize) -> usize {
        (self.next_u64() % bound as u64) as usize
    }

    /// Standard normal by Box-Muller (one of the pair).
    pub fn normal(&mut self) -> f64 {
        let u = 1.0 - self.unit(); // in (0, 1], so the log is finite
        let v = self.unit();
        (-2.0 * u.ln()).sqrt() * (TWO_PI * v).cos()
    }
}

/// Fisher-Yates, from the back.
pub fn shuffle<T>(items: &mut [T], rng: &mut Rng) {
    for i in (2..=items.len()).rev() {
        items.swap(i - 1, rng.below(i));
    }
}

/// A generated input and how the cross-check compares it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Input {
    pub points: Vec<Point>,
    pub segments: Vec<Segment>,
    /// Degenerate input has many valid Delaunay graphs: only the Voronoi
    /// sections (positive-length edges, merged vertices) are unique.
    pub degenerate: bool,
}

/// The cross-check's families, in the order `--list` prints them, each
/// with whether it is compared as degenerate. Point families first.
pub const FAMILIES: &[(&str, bool)] = &[
    ("uniform", false),
    ("clustered", false),
    ("tiny", false),
    ("tiny-offset", false),
    ("huge", false),
    ("lattice", true),
    ("circle", true),
    ("collinear", true),
    ("tiny-lattice", true),
    ("snapped", true),
    ("seg-random1", false),
    ("seg-random2", false),
    ("seg-random3", false),
    ("seg-short", false),
    ("polyline", false),
    ("square-hole", false),
    ("polygon", true),
    ("star", true),
    ("polygon-holes", false),
    ("seg-lattice", true),
    ("tangent", true),
    ("parallel", true),
    ("letter", true),
    ("letter-gap", false),
    ("near-vertical", false),
    ("boost-split", false),
    ("inscribed", false),
    ("inscribed-jitter", false),
    ("fan", false),
    ("kinked-chain", false),
    ("ulp-off-line", false),
    ("ulp-ends", false),
    ("glyph", false),
    ("ulp-parallel", false),
];

/// The families of [`FAMILIES`] that make chains or rings (polylines,
/// polygons, stars, glyph-like outlines): each also comes as every variant
/// of [`straight::VARIANTS`], its name with the variant's suffix
/// (`polyline+straight`, `glyph+nudged`), the family's input of size `n`
/// with edges cut at exact points ([`straight::cut_segments`]). The exact
/// variants are compared as degenerate (a straight joint is a cell of no
/// width: its Voronoi edges to every neighbour but its two segments have
/// length zero); the nudged ones as the family is.
pub const CHAIN_FAMILIES: &[&str] = &[
    "polyline",
    "square-hole",
    "polygon",
    "star",
    "polygon-holes",
    "letter",
    "letter-gap",
    "near-vertical",
    "boost-split",
    "inscribed",
    "inscribed-jitter",
    "fan",
    "kinked-chain",
    "ulp-ends",
    "glyph",
];

/// How the harness compares `family` (with any variant suffix):
/// "degenerate", "generic", or "polygon" for a ring family (the harness's
/// --polygon); `None` for an unknown family.
pub fn comparison(family: &str) -> Option<&'static str> {
    let (base, straight) = straight::split_variant(family);
    if rings::RING_FAMILIES.contains(&base) {
        return Some("polygon");
    }
    if straight.is_some() && !CHAIN_FAMILIES.contains(&base) {
        return None;
    }
    let degenerate = FAMILIES.iter().find(|(name, _)| *name == base)?.1;
    Some(if degenerate || straight.is_some_and(|s| !s.nudge) { "degenerate" } else { "generic" })
}

/// Family `family` of size `n` from `seed` (see the top of
/// `c_tests/cgal_crosscheck.cpp` for what each is; a family of
/// [`CHAIN_FAMILIES`] also with a variant suffix of
/// [`straight::VARIANTS`]); `None` for an unknown family or a size it
/// cannot make.
pub fn generate(family: &str, n: usize, seed: u64) -> Option<Input> {
    use near_degenerate as nd;
    if let (base, Some(straight)) = straight::split_variant(family) {
        if !CHAIN_FAMILIES.contains(&base) {
            return None;
        }
        let mut input = generate(base, n, seed)?;
        input.segments = straight::cut_segments(&input.segments, &straight, &mut straight::variant_rng(seed));
        input.degenerate = comparison(family) == Some("degenerate");
        return Some(input);
    }
    let degenerate = FAMILIES.iter().find(|(name, _)| *name == family)?.1;
    let mut rng = Rng(seed);
    let rng = &mut rng;
    let least = match family {
        "polygon" | "tangent" | "inscribed" | "inscribed-jitter" => 3,
        "polygon-holes" => 3 * 4 + 3,
        "seg-lattice" => 4,
        "parallel" | "fan" | "kinked-chain" | "ulp-ends" => 2,
        "ulp-off-line" | "ulp-parallel" => 1,
        "glyph" => 6,
        _ => 0,
    };
    if n < least {
        return None;
    }
    let mut input = Input { degenerate, ..Input::default() };
    let segments = &mut input.segments;
    match family {
        "uniform" => input.points = points::scaled_uniform(n, rng, 0.0, 1.0),
        "clustered" => input.points = points::clustered(n, rng),
        "tiny" => input.points = points::scaled_uniform(n, rng, 0.0, 1e-9),
        "tiny-offset" => input.points = points::scaled_uniform(n, rng, 1.0, 1e-9),
        "huge" => input.points = points::scaled_uniform(n, rng, 0.0, 1e9),
        "lattice" => input.points = points::lattice(n, rng),
        "circle" => input.points = points::circle(n, rng),
        "collinear" => input.points = points::collinear(n, rng),
        "tiny-lattice" => input.points = points::tiny_lattice(n, rng),
        "snapped" => input.points = points::snapped(n, rng),
        "seg-random1" => *segments = segments::seg_random1(n, rng),
        "seg-random2" => *segments = segments::seg_random2(n, rng),
        "seg-random3" => *segments = segments::seg_random3(n, rng),
        "seg-short" => *segments = segments::seg_short(n, rng),
        "polyline" => *segments = segments::polyline(n, rng),
        "square-hole" => *segments = segments::square_hole(),
        "polygon" => *segments = shapes::polygon(n, 1.0, 0.0, 0.0),
        "star" => *segments = segments::star(n, rng),
        "polygon-holes" => *segments = segments::polygon_holes(n, rng),
        "seg-lattice" => *segments = segments::seg_lattice(n, rng),
        "tangent" => *segments = segments::tangent(n),
        "parallel" => *segments = segments::parallel(n),
        "letter" => *segments = segments::letter_r(false),
        "letter-gap" => *segments = segments::letter_r(true),
        "near-vertical" => *segments = segments::near_vertical(n, rng),
        "boost-split" => *segments = split::boost_split(n, rng, 1e6),
        "inscribed" => *segments = nd::inscribed(n, seed, rng, false),
        "inscribed-jitter" => *segments = nd::inscribed(n, seed, rng, true),
        "fan" => *segments = nd::fan(n, seed, rng),
        "kinked-chain" => *segments = nd::kinked_chain(n, seed, rng),
        "ulp-off-line" => nd::ulp_off_line(n, seed, rng, &mut input),
        "ulp-parallel" => nd::ulp_parallel(n, seed, rng, &mut input),
        "ulp-ends" => *segments = nd::ulp_ends(n, seed, rng),
        "glyph" => *segments = nd::glyph(n, seed, rng),
        _ => return None,
    }
    Some(input)
}

/// `v` as C's `printf("%.17g")` writes it: every digit needed to read back
/// the same double, in the form the harness and the existing fixtures use.
pub fn format_g17(v: f64) -> String {
    if v == 0.0 {
        return if v.is_sign_negative() { "-0".into() } else { "0".into() };
    }
    if !v.is_finite() {
        return if v.is_nan() {
            "nan".into()
        } else if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    let scientific = format!("{v:.16e}");
    let (mantissa, exponent) = scientific.split_once('e').expect("an exponent");
    let exponent: i32 = exponent.parse().expect("an integer exponent");
    let trim = |digits: &str| -> String {
        if digits.contains('.') {
            digits.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            digits.to_string()
        }
    };
    if !(-4..17).contains(&exponent) {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exponent.abs())
    } else {
        trim(&format!("{v:.*}", (16 - exponent) as usize))
    }
}

/// Boost.Polygon's text format: the point count, one line "x y" per point,
/// the segment count, one line "x1 y1 x2 y2" per segment; every number with
/// the digits to read back the same double.
pub fn write_text(out: &mut impl Write, points: &[Point], segments: &[Segment]) -> io::Result<()> {
    writeln!(out, "{}", points.len())?;
    for p in points {
        writeln!(out, "{} {}", format_g17(p[0]), format_g17(p[1]))?;
    }
    writeln!(out, "{}", segments.len())?;
    for [a, b] in segments {
        writeln!(out, "{} {} {} {}", format_g17(a[0]), format_g17(a[1]), format_g17(b[0]), format_g17(b[1]))?;
    }
    Ok(())
}

/// [`write_text`] into a string.
pub fn text(points: &[Point], segments: &[Segment]) -> String {
    let mut out = Vec::new();
    write_text(&mut out, points, segments).expect("writing to memory");
    String::from_utf8(out).expect("ASCII")
}

/// `v` moved by one ulp toward `+∞` (`up`) or `-∞`, as C's `nextafter`.
pub(crate) fn next_after(v: f64, up: bool) -> f64 {
    if v.is_nan() || (v.is_infinite() && (v > 0.0) == up) {
        return v;
    }
    if v == 0.0 {
        let least = f64::from_bits(1);
        return if up { least } else { -least };
    }
    let bits = v.to_bits();
    // Away from zero the bit pattern grows, toward zero it shrinks.
    f64::from_bits(if (v > 0.0) == up { bits + 1 } else { bits - 1 })
}

/// `2^k` for `-1022 <= k <= 1023`, exactly.
pub(crate) fn power_of_two(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// C++'s `std::min` and `std::max` (the first argument on ties, so that the
/// sign of a zero is the same as there).
pub(crate) fn cmin(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

pub(crate) fn cmax(a: f64, b: f64) -> f64 {
    if a < b {
        b
    } else {
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g17_matches_printf() {
        let cases = [
            (1.0, "1"),
            (0.5, "0.5"),
            (0.1, "0.10000000000000001"),
            (1e-5, "1.0000000000000001e-05"),
            (1e6, "1000000"),
            (1e17, "1e+17"),
            (123456789012345678.0, "1.2345678901234568e+17"),
            (-3e-17, "-3.0000000000000001e-17"),
            (f64::from_bits(1), "4.9406564584124654e-324"),
            (0.0001, "0.0001"),
            (-0.0, "-0"),
            (6.283185307179586, "6.2831853071795862"),
        ];
        for (v, text) in cases {
            assert_eq!(format_g17(v), text, "{v:e}");
        }
    }

    #[test]
    fn next_after_steps_one_ulp() {
        assert_eq!(next_after(1.0, true), 1.0 + f64::EPSILON);
        assert_eq!(next_after(1.0, false), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(next_after(-1.0, true), -1.0 + f64::EPSILON / 2.0);
        assert_eq!(next_after(-0.0, true), f64::from_bits(1));
        assert_eq!(next_after(0.0, false), -f64::from_bits(1));
    }

    #[test]
    fn every_family_generates() {
        for &(family, _) in FAMILIES {
            let input = generate(family, 64, 3).unwrap_or_else(|| panic!("{family}"));
            assert!(!input.points.is_empty() || !input.segments.is_empty(), "{family}");
            assert_eq!(Some(input), generate(family, 64, 3), "{family} is deterministic");
        }
        for &family in CHAIN_FAMILIES {
            for (suffix, straight) in straight::VARIANTS {
                let name = format!("{family}{suffix}");
                let base = generate(family, 64, 3).unwrap();
                let input = generate(&name, 64, 3).unwrap_or_else(|| panic!("{name}"));
                assert_eq!(Some(&input), generate(&name, 64, 3).as_ref(), "{name} is deterministic");
                assert!(straight::legal(&input.segments), "{name} is legal");
                assert!(input.segments.len() > base.segments.len(), "{name} cuts nothing");
                assert_eq!(input.degenerate, base.degenerate || !straight.nudge, "{name}");
            }
        }
        assert!(generate("uniform+straight", 64, 3).is_none());
        assert!(generate("polygon", 2, 1).is_none());
        assert!(generate("no-such-family", 10, 1).is_none());
    }
}
