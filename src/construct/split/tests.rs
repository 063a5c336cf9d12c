use super::*;
use crate::geometry::input::segment_contact::{inside_segment, lex_cmp, segment_contact};
use crate::splitmix::SplitMix64;

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

/// Every pair, by brute force: whether anything meets other than at a
/// common endpoint.
/// (In the builder's coordinates, as the strict check works: a power of
/// two away from tiny inputs' subnormal numbers.)
fn contacts_by_brute_force(out: &SplitInput) -> usize {
    let scale = Scale::for_coordinates(out.points.iter().chain(out.pieces.iter().flat_map(|p| &p.ends)).flat_map(|p| [p.x, p.y]));
    let internal = |p: Point| p.scaled(scale.to_internal);
    let proper: Vec<[Point; 2]> = out.pieces.iter().map(|p| p.ends.map(internal)).filter(|e| e[0] != e[1]).collect();
    let mut lone: Vec<Point> = out.points.iter().map(|&p| internal(p)).collect();
    lone.extend(out.pieces.iter().filter(|p| p.ends[0] == p.ends[1]).map(|p| internal(p.ends[0])));
    let mut n = 0;
    for i in 0..proper.len() {
        for j in i + 1..proper.len() {
            n += usize::from(segment_contact(proper[i], proper[j]).is_some());
        }
        n += lone.iter().filter(|&&q| inside_segment(q, proper[i])).count();
    }
    n
}

fn distance_to_segment(q: Point, [a, b]: [Point; 2]) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 { 0.0 } else { (((q.x - a.x) * dx + (q.y - a.y) * dy) / len2).clamp(0.0, 1.0) };
    q.distance(p(a.x + t * dx, a.y + t * dy))
}

/// The guarantees of the module documentation, checked by brute force.
fn check(points: &[Point], segments: &[[Point; 2]]) -> SplitInput {
    let out = split(points, segments).expect("splitting converges");
    assert_eq!(contacts_by_brute_force(&out), 0, "pieces still meet: {segments:?}");
    // measured in the builder's coordinates (tiny inputs' products underflow)
    let scale = Scale::for_coordinates(points.iter().chain(segments.iter().flatten()).flat_map(|p| [p.x, p.y]));
    let segments: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|q| q.scaled(scale.to_internal))).collect();
    let mut scaled = out.clone();
    scaled.pieces.iter_mut().for_each(|p| p.ends = p.ends.map(|q| q.scaled(scale.to_internal)));
    scaled.pixel *= scale.to_internal;
    check_distances(&segments, &scaled);
    out
}

fn check_distances(segments: &[[Point; 2]], out: &SplitInput) {
    // (plus the rounding of the distances themselves)
    let extent = segments.iter().flatten().map(|q| q.x.abs().max(q.y.abs())).fold(0.0, f64::max);
    let bound = (out.rounds as f64) * out.pixel * std::f64::consts::FRAC_1_SQRT_2 * 1.000001 + 1e-14 * extent;
    let mut pieces_of = vec![Vec::new(); segments.len()];
    for (k, piece) in out.pieces.iter().enumerate() {
        assert!(!piece.origins.is_empty() && piece.origins.windows(2).all(|w| w[0] < w[1]));
        for &i in &piece.origins {
            pieces_of[i as usize].push(k);
            for q in piece.ends {
                let d = distance_to_segment(q, segments[i as usize]);
                assert!(d <= bound, "piece {k} is {d} from segment {i} (bound {bound})");
            }
        }
    }
    // the pieces cover each input segment up to the bound
    for (i, s) in segments.iter().enumerate() {
        let length = s[0].distance(s[1]);
        if length <= 2.0 * bound {
            continue; // may have become a point
        }
        for k in 0..=16 {
            let t = k as f64 / 16.0;
            let q = p(s[0].x + t * (s[1].x - s[0].x), s[0].y + t * (s[1].y - s[0].y));
            let d = pieces_of[i].iter().map(|&k| distance_to_segment(q, out.pieces[k].ends)).fold(f64::INFINITY, f64::min);
            assert!(d <= bound, "segment {i} not covered at {q:?}: {d} (bound {bound})");
        }
    }
    // a segment that meets nothing is kept exactly
    if out.rounds == 0 {
        assert_eq!(out.pieces.len(), segments.len());
        for (piece, s) in out.pieces.iter().zip(segments) {
            assert_eq!(piece.ends, *s);
        }
    }
}

#[test]
fn two_crossing_segments_become_four_pieces() {
    let out = check(&[], &[[p(0.0, 0.0), p(2.0, 2.0)], [p(0.0, 2.0), p(2.0, 0.0)]]);
    assert_eq!((out.crossings, out.pieces.len(), out.rounds), (1, 4, 1));
    // (1, 1) is a pixel centre: the crossing is exact
    assert!(out.pieces.iter().all(|piece| piece.ends.contains(&p(1.0, 1.0))));
}

#[test]
fn an_irrational_crossing_is_snapped_within_a_pixel() {
    let out = check(&[], &[[p(0.0, 0.0), p(3.0, 1.0)], [p(1.0, 1.0), p(2.0, -1.0)]]);
    assert_eq!((out.crossings, out.pieces.len()), (1, 4));
}

#[test]
fn overlaps_share_their_common_part() {
    let out = check(&[], &[[p(0.0, 0.0), p(10.0, 0.0)], [p(5.0, 0.0), p(15.0, 0.0)], [p(2.0, 0.0), p(3.0, 0.0)]]);
    assert_eq!(out.overlaps, 2);
    let shared: Vec<&Piece> = out.pieces.iter().filter(|p| p.origins.len() > 1).collect();
    assert_eq!(shared.len(), 2, "{:?}", out.pieces);
    assert!(shared.iter().any(|p| p.origins == [0, 1]) && shared.iter().any(|p| p.origins == [0, 2]));
}

#[test]
fn t_junctions_and_points_inside_segments_become_endpoints() {
    let out = check(&[p(7.0, 0.0), p(50.0, 50.0)], &[[p(0.0, 0.0), p(10.0, 0.0)], [p(3.0, 0.0), p(3.0, 5.0)]]);
    assert_eq!(out.touchings, 2);
    assert_eq!(out.pieces.len(), 4);
    assert_eq!(out.points, vec![p(7.0, 0.0), p(50.0, 50.0)]);
}

#[test]
fn an_input_without_contacts_is_kept_exactly() {
    let s = [[p(0.1, 0.2), p(0.3, 0.7)], [p(0.3, 0.7), p(1.0 / 3.0, -5.0)]];
    let out = check(&[p(0.5, 0.5)], &s);
    assert_eq!(out.rounds, 0);
}

#[test]
fn many_lines_through_one_point_and_a_grid_of_crossings() {
    let mut segments = Vec::new();
    for k in 0..24 {
        let angle = k as f64 * std::f64::consts::PI / 24.0;
        let (c, s) = (angle.cos(), angle.sin());
        segments.push([p(0.3 - c, 0.7 - s), p(0.3 + c, 0.7 + s)]);
    }
    check(&[], &segments);
    let mut grid = Vec::new();
    for k in 0..20 {
        let t = k as f64 * 0.1 + 0.013;
        grid.push([p(t, -0.1), p(t + 0.001, 2.1)]);
        grid.push([p(-0.1, t), p(2.1, t - 0.0007)]);
    }
    let out = check(&[], &grid);
    assert_eq!(out.crossings, 400);
}

#[test]
fn nearly_parallel_crossings_and_huge_or_tiny_coordinates() {
    for scale in [1.0, 1e-300, 1e300, 3.0e-7] {
        let s = [
            [p(0.0, 0.0), p(scale, scale * 1e-13)],
            [p(0.0, scale * 1e-13), p(scale, -scale * 3e-13)],
            [p(0.0, scale * 2e-13), p(scale, -scale * 1e-13)],
        ];
        let out = check(&[], &s);
        assert!(out.crossings >= 2, "{scale}: {}", out.crossings);
    }
}

#[test]
fn random_segments_crossing_everywhere() {
    let mut rng = SplitMix64(11);
    for round in 0..300 {
        let n = 2 + (round % 25);
        let integer = round % 3 == 0;
        let coordinate = |rng: &mut SplitMix64| {
            let u = rng.unit();
            if integer {
                (u * 6.0).floor()
            } else {
                u * 10.0 - 3.0
            }
        };
        let segments: Vec<[Point; 2]> = (0..n)
            .map(|_| {
                let a = p(coordinate(&mut rng), coordinate(&mut rng));
                [a, p(coordinate(&mut rng), coordinate(&mut rng))]
            })
            .collect();
        let points: Vec<Point> = (0..round % 4).map(|_| p(coordinate(&mut rng), coordinate(&mut rng))).collect();
        check(&points, &segments);
        // the same input mirrored and reversed splits as well
        let mirrored: Vec<[Point; 2]> = segments.iter().rev().map(|[a, b]| [p(-b.x, b.y), p(-a.x, a.y)]).collect();
        check(&points, &mirrored);
    }
}

#[test]
fn long_segments_crossing_at_tiny_angles_and_in_one_spot() {
    let mut rng = SplitMix64(5);
    for case in 0..12 {
        let n = 10 + case * 4;
        let segments: Vec<[Point; 2]> = (0..n)
            .map(|k| {
                if case % 2 == 0 {
                    let a = p(rng.unit() * 100.0, rng.unit() * 100.0);
                    [a, p(rng.unit() * 100.0, rng.unit() * 100.0)]
                } else {
                    // every pair crosses within 1e-9 of (500, 0.5)
                    let y0 = k as f64 * 0.01;
                    [p(0.0, y0 + rng.unit() * 1e-9), p(1000.0, 1.0 - y0 + rng.unit() * 1e-9)]
                }
            })
            .collect();
        let out = check(&[], &segments);
        assert!(out.rounds <= 3, "case {case}: {} rounds", out.rounds);
    }
}

/// The sweep's contacts (counts by kind and hot pixels) against every
/// pair tested by brute force, on `pieces` and `points` as one round sees
/// them.
fn sweep_agrees_with_brute_force(segments: &[[Point; 2]], points: &[Point]) -> Result<(), String> {
    use contacts::pair_pixels;
    let pieces: Vec<Piece> = segments.iter().map(|&ends| Piece { ends, origins: vec![0] }).collect();
    let layout = Layout::of(&pieces, points);
    let extent = segments.iter().flatten().chain(points).map(|q| q.x.abs().max(q.y.abs())).fold(1.0, f64::max);
    let pixels = PixelGrid::for_magnitude(extent);
    let mut swept = Vec::new();
    let counts = contact_pixels(&layout, &pixels, &mut swept);
    let mut brute = Vec::new();
    let mut expected = ContactCounts::default();
    let proper: Vec<[Point; 2]> = layout.proper.iter().map(|&(_, s)| s).collect();
    for i in 0..proper.len() {
        for j in i + 1..proper.len() {
            if let Some(contact) = segment_contact(proper[i], proper[j]) {
                pair_pixels(proper[i], proper[j], contact, &pixels, &mut brute, &mut expected);
            }
        }
        for &q in &layout.lone {
            if inside_segment(q, proper[i]) {
                expected.touchings += 1;
                brute.push(pixels.pixel_of(q));
            }
        }
    }
    for list in [&mut swept, &mut brute] {
        list.sort_unstable();
        list.dedup();
    }
    if counts != expected || swept != brute {
        return Err(format!("sweep {counts:?} {swept:?}, brute force {expected:?} {brute:?}"));
    }
    slabs_agree_with_the_whole_sweep(&layout, &pixels)
}

/// The search in two slabs (`contacts::in_slabs`), cut at every end of a
/// piece and every point, and beyond them all, finds what the whole sweep
/// finds: the same counts and the same pixels, as often. So does a slab
/// (from a third of those points to two thirds) cut in two again, at every
/// point inside it, against its own sweep: the slabs nested, as four
/// threads or more run them.
fn slabs_agree_with_the_whole_sweep(layout: &Layout, pixels: &PixelGrid) -> Result<(), String> {
    use contacts::{first_point_first, in_slabs, slab_search, Slab};
    let segments = first_point_first(layout);
    let lone = &layout.lone;
    let found_in = |slab: Slab, cut: Option<Point>| {
        let mut found = Vec::new();
        let counts = match cut {
            Some(cut) => in_slabs(&segments, lone, slab, cut, pixels, &mut found),
            None => {
                let picked = segments.iter().filter(|s| slab.picks(s)).copied().collect();
                let held = lone.iter().copied().filter(|&q| slab.holds(q)).collect();
                slab_search(picked, held, slab, pixels, &mut found) // (small: one sweep)
            }
        };
        found.sort_unstable();
        (counts, found)
    };
    let mut cuts: Vec<Point> = segments.iter().flatten().chain(lone).copied().collect();
    cuts.sort_unstable_by(|a, b| lex_cmp(*a, *b));
    cuts.dedup_by(|a, b| lex_cmp(*a, *b) == std::cmp::Ordering::Equal);
    let whole = found_in(Slab::WHOLE, None);
    let beyond = [p(f64::NEG_INFINITY, 0.0), p(f64::INFINITY, 0.0)];
    for &cut in cuts.iter().chain(&beyond) {
        let in_two = found_in(Slab::WHOLE, Some(cut));
        if in_two != whole {
            return Err(format!("cut at {cut:?}: slabs {in_two:?}, whole sweep {whole:?}"));
        }
    }
    let (first, last) = (cuts.len() / 3, 2 * cuts.len() / 3);
    if let (Some(&from), Some(&until)) = (cuts.get(first), cuts.get(last)) {
        let slab = Slab { from: Some(from), until: Some(until) };
        let own = found_in(slab, None);
        for &cut in cuts.get(first + 1..last).unwrap_or_default() {
            let in_two = found_in(slab, Some(cut));
            if in_two != own {
                return Err(format!("{slab:?} cut at {cut:?}: {in_two:?}, its own sweep {own:?}"));
            }
        }
    }
    Ok(())
}

/// Small integer grids: collinear overlaps, T-junctions, vertical pieces,
/// many pieces through one point, repeated pieces and points on pieces.
fn degenerate_segments() -> impl Strategy<Value = (Vec<[Point; 2]>, Vec<Point>)> {
    let point = (0..7i32, 0..7i32).prop_map(|(x, y)| p(f64::from(x), f64::from(y)));
    (prop::collection::vec((point.clone(), point.clone()), 0..24), prop::collection::vec(point, 0..6))
        .prop_map(|(s, q)| (s.into_iter().map(|(a, b)| [a, b]).collect(), q))
}

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn the_sweep_finds_every_contact_on_degenerate_grids((segments, points) in degenerate_segments()) {
        sweep_agrees_with_brute_force(&segments, &points).map_err(TestCaseError::fail)?;
        // mirrored and transposed: other orders of the sweep's events
        let mirror: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|q| p(-q.x, q.y))).collect();
        let mirrored_points: Vec<Point> = points.iter().map(|q| p(-q.x, q.y)).collect();
        sweep_agrees_with_brute_force(&mirror, &mirrored_points).map_err(TestCaseError::fail)?;
        let swap: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|q| p(q.y, q.x))).collect();
        let swapped_points: Vec<Point> = points.iter().map(|q| p(q.y, q.x)).collect();
        sweep_agrees_with_brute_force(&swap, &swapped_points).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn the_sweep_finds_every_contact_among_random_segments(
        ends in prop::collection::vec(((-1.0..1.0f64, -1.0..1.0f64), (-1.0..1.0f64, -1.0..1.0f64)), 0..40),
        scale in prop::sample::select(vec![1.0, 1e-9, 3e7]),
    ) {
        let segments: Vec<[Point; 2]> =
            ends.iter().map(|&((ax, ay), (bx, by))| [p(ax * scale, ay * scale), p(bx * scale, by * scale)]).collect();
        sweep_agrees_with_brute_force(&segments, &[]).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn the_sweep_finds_crossings_of_long_nearly_parallel_pieces() {
    // a bundle of long pieces fanning out from nearly one point, crossed
    // by a few others: many crossing events close together
    let mut rng = SplitMix64(11);
    let mut segments: Vec<[Point; 2]> =
        (0..60).map(|k| [p(0.0, k as f64 * 1e-7 + rng.unit() * 1e-9), p(1000.0, 60.0 - k as f64 + rng.unit())]).collect();
    segments.extend((0..6).map(|k| [p(100.0 * k as f64 + 3.0, -5.0), p(100.0 * k as f64 + 40.0, 80.0)]));
    sweep_agrees_with_brute_force(&segments, &[p(500.0, 30.0)]).unwrap();
}

/// `n` segments of length `length` from random points of the unit square,
/// in random directions.
fn random_segments(rng: &mut SplitMix64, n: usize, length: f64) -> Vec<[Point; 2]> {
    (0..n)
        .map(|_| {
            let (x, y, a) = (rng.unit(), rng.unit(), rng.unit() * std::f64::consts::TAU);
            [p(x, y), p(x + length * a.cos(), y + length * a.sin())]
        })
        .collect()
}

/// Splitting on two threads (the contact search in slabs, the routing in
/// halves) and on four (slabs of slabs) gives what one thread gives,
/// piece for piece, on inputs large enough for both: random short crossings with what users have among them
/// (collinear overlaps running across the middle, repeated and reversed
/// pieces, points on pieces and on crossings, a straight vertex, rings
/// touching at a corner), as made, mirrored far from the origin, scaled
/// and reversed and shuffled.
#[test]
fn splitting_on_two_threads_gives_one_threads_pieces() {
    let mut rng = SplitMix64(33);
    let mut segments = random_segments(&mut rng, 18_000, 0.01);
    // overlapping runs along y = 0.5 and x = 0.5, across every cut
    segments.extend((0..40).map(|k| [p(k as f64 / 50.0, 0.5), p(k as f64 / 50.0 + 0.3, 0.5)]));
    segments.extend((0..40).map(|k| [p(0.5, k as f64 / 50.0 + 0.3), p(0.5, k as f64 / 50.0)]));
    // repeats, one reversed, from the first half among the second's
    let repeated: Vec<[Point; 2]> =
        segments[..200].iter().enumerate().map(|(k, &[a, b])| if k % 2 == 0 { [a, b] } else { [b, a] }).collect();
    segments.extend(repeated);
    // a straight vertex, two squares touching at a corner
    segments.extend([[p(0.2, 0.7), p(0.3, 0.7)], [p(0.3, 0.7), p(0.4, 0.7)]]);
    let square = |x: f64, y: f64| {
        [
            [p(x, y), p(x + 0.1, y)],
            [p(x + 0.1, y), p(x + 0.1, y + 0.1)],
            [p(x + 0.1, y + 0.1), p(x, y + 0.1)],
            [p(x, y + 0.1), p(x, y)],
        ]
    };
    segments.extend(square(0.6, 0.6).into_iter().chain(square(0.7, 0.7)));
    let mut points: Vec<Point> = (0..600).map(|_| p(rng.unit(), rng.unit())).collect();
    points.extend([p(0.25, 0.5), p(0.5, 0.5), segments[3][0], segments[7][1]]);
    // mirrored far out; scaled by 2^-30; reversed (the list and each
    // segment) and shuffled
    let moved = |f: &dyn Fn(Point) -> Point| {
        (points.iter().map(|&q| f(q)).collect::<Vec<_>>(), segments.iter().map(|s| s.map(f)).collect::<Vec<_>>())
    };
    let mut reversed: Vec<[Point; 2]> = segments.iter().rev().map(|&[a, b]| [b, a]).collect();
    for k in (1..reversed.len()).rev() {
        reversed.swap(k, (rng.next_u64() % (k as u64 + 1)) as usize);
    }
    let variants = [
        (points.clone(), segments.clone()),
        moved(&|q| p(-q.x + 1e9, q.y - 1e9)),
        moved(&|q| p(q.x * 2f64.powi(-30), q.y * 2f64.powi(-30))),
        (points.iter().rev().copied().collect(), reversed),
    ];
    for (points, segments) in &variants {
        // (four threads: slabs of slabs)
        let [one, two, four] = [1, 2, 4]
            .map(|threads| crate::construct::threads::with_threads(threads, || split(points, segments).expect("splits")));
        let counts = |s: &SplitInput| (s.crossings, s.overlaps, s.touchings, s.rounds, s.max_displacement.to_bits());
        assert!(one.crossings > 10_000 && one.overlaps > 100 && one.touchings > 0, "{:?}", counts(&one));
        let pieces = |s: &SplitInput| s.pieces.iter().map(|q| (q.ends, q.origins.clone())).collect::<Vec<_>>();
        for other in [&two, &four] {
            assert_eq!(counts(&one), counts(other));
            assert_eq!(one.points, other.points);
            assert_eq!(pieces(&one), pieces(other));
        }
    }
}

/// A split's pieces and points, known free of contacts where they go back
/// exactly into the coordinates searched, need only normalising: the full
/// check of them (normalisation, then the search for conflicts and splits)
/// gives the same checked input. With what users have among random
/// crossings: repeated and zero-length segments, points on segments and
/// at their ends, a straight vertex; as made, tiny and huge.
#[test]
fn split_pieces_need_only_normalising() {
    use crate::construct::input_check::{check_segments, normalise_contact_free};
    let mut rng = SplitMix64(8);
    let mut segments = random_segments(&mut rng, 3000, 0.05);
    segments.extend([segments[5], [segments[6][1], segments[6][0]], [p(0.3, 0.3), p(0.3, 0.3)]]);
    segments.extend([[p(0.1, 0.9), p(0.2, 0.9)], [p(0.2, 0.9), p(0.3, 0.9)]]);
    let mut points: Vec<Point> = (0..300).map(|_| p(rng.unit(), rng.unit())).collect();
    points.extend([p(0.15, 0.9), segments[9][0], segments[9][0], p(0.3, 0.3)]);
    for factor in [1.0, 1e-200, 1e250] {
        let scaled: Vec<[Point; 2]> = segments.iter().map(|s| s.map(|q| p(q.x * factor, q.y * factor))).collect();
        let scaled_points: Vec<Point> = points.iter().map(|q| p(q.x * factor, q.y * factor)).collect();
        let out = split(&scaled_points, &scaled).expect("splits");
        let scale = out.contact_free_in.expect("every piece comes back exactly");
        let ends: Vec<[Point; 2]> = out.pieces.iter().map(|q| q.ends).collect();
        // (the build works in this scale, so it takes the light check)
        assert_eq!(Scale::for_points(out.points.iter().chain(ends.iter().flatten())), scale, "factor {factor}");
        let checked = check_segments(&out.points, &ends, &[], scale).expect("no conflict");
        assert!(checked.duplicate_points > 0 && checked.degenerate_segments > 0, "factor {factor}");
        assert_eq!(checked, normalise_contact_free(&out.points, &ends, scale), "factor {factor}");
    }
}

/// Where a point saturates at f64::MAX on its way back to input
/// coordinates, the pieces are not known free of contacts.
#[test]
fn a_point_past_f64_max_is_not_known_contact_free() {
    let near_max = Scale::to_unit(f64::MAX);
    let piece = |a: Point, b: Point| Piece { ends: [a, b], origins: vec![0] };
    // (the scale is 2^1022: internal coordinates up to f64::MAX / 2^1022, about 4)
    assert_eq!(near_max.to_input, 2f64.powi(1022));
    let inside = [p(3.5, -1.0), p(1.0, 3.999_999)];
    assert_eq!(contact_free_in(near_max, &inside, &[piece(inside[0], inside[1])]), Some(near_max));
    // (4 · 2^1022 is past f64::MAX: it comes back as f64::MAX, below 4)
    assert_eq!(contact_free_in(near_max, &[p(4.0, 0.0)], &[]), None);
    assert_eq!(contact_free_in(near_max, &inside, &[piece(inside[0], p(-1.0, -4.0))]), None);
}
