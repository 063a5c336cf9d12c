//! Splitting mode on real data (issue 11): GSHHG coastlines, national
//! borders and rivers (tests/data/gshhg_*.txt, scripts/coastlines.py; the
//! layers are digitised separately and cross each other). Each file is
//! built strictly and in splitting mode through the public API; the
//! crossings the library reports are the ones a brute-force exact count
//! finds, and the split diagram has the guarantees `common::check_pieces`
//! checks by brute force (strict pieces, within the stated distance of
//! their inputs, covering them).

mod common;

use common::{check_pieces, Segment};
use segvoronoi::{Builder, ErrorKind};

fn fixtures() -> Vec<(String, Vec<Segment>)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        if !(name.starts_with("gshhg_") && name.ends_with(".txt")) {
            continue;
        }
        let input =
            segvoronoi::boost_text::parse(&std::fs::read_to_string(&path).unwrap()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(input.points.is_empty(), "{name}: the GSHHG fixtures have no isolated points");
        out.push((name, input.segments.iter().map(|&[x0, y0, x1, y1]| [[x0, y0], [x1, y1]]).collect()));
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(out.len() >= 4, "the GSHHG fixtures are missing");
    out
}

/// What splitting must find, counted by brute force over all pairs with
/// exact integer orientations (the fixtures have integer coordinates below
/// 2^23, so every product fits an i64): pairs crossing at a point inside
/// both, pairs of collinear segments sharing more than a point (a repeated
/// segment is no overlap: the strict mode accepts it and merges it), and
/// (distinct endpoint, segment) pairs with the endpoint inside the segment.
#[derive(Debug, Default, PartialEq)]
struct Conflicts {
    crossings: usize,
    overlaps: usize,
    touchings: usize,
}

impl Conflicts {
    fn of(stats: &segvoronoi::BuildStats) -> Conflicts {
        Conflicts { crossings: stats.crossings, overlaps: stats.overlaps, touchings: stats.touchings }
    }

    /// Whether the strict mode accepts the input.
    fn none(&self) -> bool {
        self.crossings + self.overlaps + self.touchings == 0
    }
}

fn brute_force_conflicts(segments: &[Segment]) -> Conflicts {
    let int = |v: f64| {
        assert!(v == v.round() && v.abs() < (1 << 23) as f64, "{v} is not a small integer");
        v as i64
    };
    let s: Vec<[[i64; 2]; 2]> = segments.iter().map(|g| g.map(|p| p.map(int))).collect();
    let orient = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum();
    // whether c, collinear with a-b, lies strictly between them
    let between = |[a, b]: [[i64; 2]; 2], c: [i64; 2]| {
        let dot = (c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1]) * (b[1] - a[1]);
        let len2 = (b[0] - a[0]).pow(2) + (b[1] - a[1]).pow(2);
        0 < dot && dot < len2
    };
    let mut found = Conflicts::default();
    for i in 0..s.len() {
        for j in i + 1..s.len() {
            let ([a, b], [c, d]) = (s[i], s[j]);
            let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
            if o1 * o2 < 0 && o3 * o4 < 0 {
                found.crossings += 1;
            } else if o1 == 0 && o2 == 0 {
                // collinear: more than a point in common when an end of one is
                // inside the other, unless they are the same segment
                let same = (a == c && b == d) || (a == d && b == c);
                if !same && (between(s[i], c) || between(s[i], d) || between(s[j], a) || between(s[j], b)) {
                    found.overlaps += 1;
                }
            }
        }
    }
    let mut ends: Vec<[i64; 2]> = s.iter().flatten().copied().collect();
    ends.sort_unstable();
    ends.dedup();
    for &g in &s {
        found.touchings += ends.iter().filter(|&&p| orient(g[0], g[1], p) == 0 && between(g, p)).count();
    }
    found
}

/// Real data repeats segments (a border drawn twice where two bins' pieces
/// meet; the strict mode accepts and merges them): every repetition of a
/// segment (either direction) is cut into the same pieces as its first
/// occurrence: the same pieces when the input was split (one piece naming
/// both inputs), pieces of the same geometry when nothing had to be split
/// (each input its own piece, as without splitting). Returns the number of
/// repetitions.
fn check_repeats_share_their_pieces(d: &segvoronoi::Diagram, segments: &[Segment]) -> usize {
    let undirected = |[a, b]: [[f64; 2]; 2]| if a <= b { [a, b] } else { [b, a] }.map(|p| p.map(f64::to_bits));
    let geometry = |i: usize| {
        let mut pieces: Vec<_> = d.pieces_of_input(i).map(|p| undirected(d.piece(p).unwrap().map(|q| [q.x, q.y]))).collect();
        pieces.sort_unstable();
        pieces
    };
    let mut first = std::collections::HashMap::new();
    let mut repeats = 0;
    for (i, &s) in segments.iter().enumerate() {
        let &mut j = first.entry(undirected(s)).or_insert(i);
        if j != i {
            repeats += 1;
            assert_eq!(geometry(i), geometry(j), "input {i} repeats {j} but is cut differently");
        }
    }
    repeats
}

#[test]
fn gshhg_coast_borders_and_rivers_split_with_the_guarantees() {
    let mut crossing_files = 0;
    for (name, segments) in fixtures() {
        let mut b = Builder::new();
        b.add_segments(segments.iter().copied()).unwrap();
        let expected = brute_force_conflicts(&segments);
        let strict = b.build();
        let d = b.split_crossings(true).build().unwrap_or_else(|e| panic!("{name}: {e}"));
        let stats = d.stats();
        assert_eq!(Conflicts::of(&stats), expected, "{name}: splitting found other conflicts than the brute force");
        if expected.none() {
            // nothing to split: the strict diagram, unchanged
            let strict = strict.unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(d.topology(Default::default()), strict.topology(Default::default()), "{name}");
            assert_eq!((stats.snap_rounds, d.max_split_displacement(), d.piece_count()), (0, 0.0, segments.len()));
        } else {
            crossing_files += 1;
            let refused = strict.expect_err(&name);
            assert_eq!(refused.kind(), ErrorKind::Intersecting, "{name}: {refused}");
            assert!(d.piece_count() > segments.len(), "{name}: crossings but no segment was cut");
        }
        check_pieces(&d, &segments);
        let repeated = check_repeats_share_their_pieces(&d, &segments);
        eprintln!(
            "{name}: {} segments ({repeated} repeating an earlier one), {} crossings, {} overlaps, {} touchings, {} pieces, {} snap rounds, \
             max displacement {:e} (pixel {:e})",
            segments.len(),
            stats.crossings,
            stats.overlaps,
            stats.touchings,
            d.piece_count(),
            stats.snap_rounds,
            d.max_split_displacement(),
            d.split_pixel_size()
        );
    }
    assert!(crossing_files >= 3, "only {crossing_files} GSHHG fixtures cross: they no longer test splitting");
}

/// The same files mirrored and in reverse order, segments reversed:
/// splitting does not depend on the order or orientation of its input.
#[test]
fn gshhg_fixtures_mirrored_and_reversed() {
    for (name, segments) in fixtures() {
        let variant: Vec<Segment> = segments.iter().rev().map(|&[a, b]| [[-b[0], b[1]], [-a[0], a[1]]]).collect();
        let mut b = Builder::new();
        b.add_segments(variant.iter().copied()).unwrap();
        let d = b.split_crossings(true).build().unwrap_or_else(|e| panic!("{name} mirrored: {e}"));
        let expected = brute_force_conflicts(&segments);
        assert_eq!(
            (d.stats().crossings, d.stats().overlaps, d.stats().touchings),
            (expected.crossings, expected.overlaps, expected.touchings),
            "{name} mirrored"
        );
        check_pieces(&d, &variant);
        check_repeats_share_their_pieces(&d, &variant);
    }
}
