//! `Builder::threads`: the same diagram for every thread count, on inputs
//! large enough that a build runs work on a second thread (the input
//! check beside the point insertions from 20k segments, the sort of the
//! insertion order from 100k points, the check of the arcs' vertices from
//! 50k vertices), and the same error for an input that is refused.

use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, Diagram, SiteId, TopologyOptions};
use segvoronoi_testgen::arcs::random_arc;
use segvoronoi_testgen::bench::{float_points, generate, Method};

/// The canonical topology and every vertex's position and clearance, bit
/// for bit, by its sites (a build in halves numbers vertices otherwise).
fn fingerprint(d: &Diagram) -> (String, Vec<([SiteId; 3], [u64; 3])>) {
    let mut vertices: Vec<_> = d
        .vertices()
        .map(|v| (site_key(v.sites), [v.position.x.to_bits(), v.position.y.to_bits(), v.clearance.to_bits()]))
        .collect();
    vertices.sort();
    (d.topology(TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true)), vertices)
}

/// The canonical topology and every vertex's position and clearance, bit
/// for bit, in order: [`fingerprint`] for inputs with degenerate vertices
/// (four sites or more on one circle), which a build in halves may cut
/// into vertices of three sites otherwise than one thread does, at the
/// same place.
fn fingerprint_of_places(d: &Diagram) -> (String, Vec<[u64; 3]>) {
    let mut places: Vec<[u64; 3]> =
        d.vertices().map(|v| [v.position.x.to_bits(), v.position.y.to_bits(), v.clearance.to_bits()]).collect();
    places.sort();
    (d.topology(TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true)), places)
}

/// A vertex's sites rotated to start at the least (the counter-clockwise
/// order kept): the same for the same vertex however it is numbered.
fn site_key(mut sites: [SiteId; 3]) -> [SiteId; 3] {
    let k = (0..3).min_by_key(|&k| sites[k]).unwrap_or(0);
    sites.rotate_left(k);
    sites
}

fn same_for_every_thread_count(what: &str, b: &mut Builder) {
    let one = fingerprint(&b.threads(1).build().unwrap_or_else(|e| panic!("{what}: {e}")));
    for n in [2, 3, 4, 0] {
        let other = fingerprint(&b.threads(n).build().unwrap_or_else(|e| panic!("{what} at {n} threads: {e}")));
        assert!(one == other, "{what}: another diagram at {n} threads than at one");
    }
}

#[test]
fn segments_and_points_the_same_at_every_thread_count() {
    let mut b = Builder::new();
    let segments = generate(Method::Short, 25_000, 7).segments;
    b.add_segments(segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]])).unwrap();
    same_for_every_thread_count("25k short segments", &mut b);
    let mut b = Builder::new();
    b.add_points(float_points(120_000, 11)).unwrap();
    same_for_every_thread_count("120k points", &mut b);
}

#[test]
fn arcs_the_same_at_every_thread_count() {
    let mut rng = SplitMix64(31);
    let mut b = Builder::new();
    for k in 0..12_000 {
        b.add_arc(random_arc(&mut rng, (k % 120) as f64, (k / 120) as f64)).unwrap();
    }
    same_for_every_thread_count("12k random arcs", &mut b);
}

#[test]
fn the_same_error_at_every_thread_count() {
    // 25k short segments and one more crossing the first
    let segments = generate(Method::Short, 25_000, 7).segments;
    let mut b = Builder::new();
    b.add_segments(segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]])).unwrap();
    let s = segments[0];
    let (mx, my) = (0.5 * f64::from(s[0] + s[2]), 0.5 * f64::from(s[1] + s[3]));
    let (dx, dy) = (f64::from(s[2] - s[0]), f64::from(s[3] - s[1]));
    b.add_segment([[mx - 0.1 * dy, my + 0.1 * dx], [mx + 0.1 * dy, my - 0.1 * dx]]).unwrap();
    let errors: Vec<String> = [1, 2, 0].into_iter().map(|n| b.threads(n).build().unwrap_err().to_string()).collect();
    assert!(errors.iter().all(|e| *e == errors[0]), "{errors:?}");
    assert!(errors[0].contains("25000"), "{}", errors[0]);
}

/// Builds in halves on two threads (`diagnostics::set_halves_from`, here
/// from 64 sites on, so that the families' small inputs run so too) give
/// the diagram of one thread: the canonical topology text byte for byte,
/// and every vertex (named by its three sites) at the same position and
/// clearance, bit for bit. On every generated family (degenerate ones
/// included: lattices, cocircular points, collinear runs), every chain
/// family with straight and nudged (an ulp off) joints, every ring family
/// (rings touching at a point, the glyphs of DejaVu Sans), each as made and
/// one of: reversed, shuffled, mirrored, scaled, moved far from the origin.
/// Where the halves cannot be glued (a degenerate vertex cut two ways
/// across the cut) the build runs again on one thread: the answer is the
/// same, and the test counts how often that happens.
#[test]
fn builds_in_halves_give_the_one_thread_diagram_on_every_family() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    use segvoronoi_testgen::{generate, straight::VARIANTS, Input, CHAIN_FAMILIES, FAMILIES};
    let mut names: Vec<String> = FAMILIES.iter().map(|(f, _)| f.to_string()).collect();
    for f in CHAIN_FAMILIES {
        names.extend(VARIANTS.iter().map(|(v, _)| format!("{f}{v}")));
    }
    names.extend(segvoronoi_testgen::rings::RING_FAMILIES.iter().map(|f| f.to_string()));
    let transforms: [(&str, fn(&mut Input)); 6] = [
        ("as made", |_| {}),
        ("reversed", |i| {
            i.points.reverse();
            i.segments.reverse();
            i.segments.iter_mut().for_each(|s| s.reverse());
        }),
        ("shuffled", |i| {
            let mut rng = segvoronoi_testgen::Rng(99);
            segvoronoi_testgen::shuffle(&mut i.points, &mut rng);
            segvoronoi_testgen::shuffle(&mut i.segments, &mut rng);
        }),
        ("mirrored", |i| {
            i.points.iter_mut().for_each(|p| p[0] = -p[0]);
            i.segments.iter_mut().flatten().for_each(|p| p[0] = -p[0]);
        }),
        ("scaled by 2^-40", |i| {
            let f = 2f64.powi(-40);
            i.points.iter_mut().flatten().for_each(|c| *c *= f);
            i.segments.iter_mut().flatten().flatten().for_each(|c| *c *= f);
        }),
        ("2^30 from the origin", |i| {
            let o = 2f64.powi(30);
            i.points.iter_mut().for_each(|p| *p = [p[0] + o, p[1] - o]);
            i.segments.iter_mut().flatten().for_each(|p| *p = [p[0] + o, p[1] - o]);
        }),
    ];
    let canonical = TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true);
    let (mut glued, mut again, mut compared) = (0, 0, 0);
    let (mut nested, mut again_nested) = (0, 0);
    set_halves_from(Some(64));
    // (debug builds, CI's, validate every build and run some five times
    // slower: they take every other family)
    let stride = if cfg!(debug_assertions) { 2 } else { 1 };
    for (k, name) in names.iter().enumerate().step_by(stride) {
        for seed in [1] {
            // ring families as their segments: rings touching at a point,
            // and the glyphs of DejaVu Sans (Debian's fonts-dejavu)
            let rings = segvoronoi_testgen::rings::generate_rings(name, 240, seed);
            let made = match rings {
                // (inscribed rings are cocircular: degenerate vertices may be cut otherwise)
                Some(rings) => {
                    Input { segments: segvoronoi_testgen::rings::ring_segments(&rings), degenerate: true, ..Input::default() }
                }
                None => match generate(name, 240, seed) {
                    Some(made) => made,
                    None => continue,
                },
            };
            // each family as made and one other way, in turn (all six ways
            // for every family take minutes)
            for (how, transform) in [&transforms[0], &transforms[1 + k % 5]] {
                let mut input = made.clone();
                transform(&mut input);
                let what = format!("{name} seed {seed}, {how}");
                let mut b = Builder::new();
                b.add_points(input.points.iter().copied()).unwrap();
                b.add_segments(input.segments.iter().copied()).unwrap();
                let one = b.threads(1).build();
                assert!(take_halves_report().is_none(), "{what}: one thread ran halves");
                // in halves, and (as made) each half in halves in turn
                let counts: &[usize] = if *how == "as made" { &[2, 4] } else { &[2] };
                for &threads in counts {
                    let many = b.threads(threads).build();
                    let report = take_halves_report();
                    let what = format!("{what}, {threads} threads");
                    let (one, many) = match (&one, many) {
                        (Ok(one), Ok(many)) => (one, many),
                        (Err(a), Err(b)) => {
                            assert_eq!(a.to_string(), b.to_string(), "{what}");
                            continue;
                        }
                        (a, b) => panic!("{what}: one thread {:?}, many {:?}", a.as_ref().err(), b.err()),
                    };
                    if !cfg!(debug_assertions) {
                        // (debug builds validate every diagram they return)
                        many.validate().unwrap_or_else(|e| panic!("{what}: {e:?}"));
                    }
                    assert!(one.topology(canonical) == many.topology(canonical), "{what}: another topology in halves");
                    let key = |v: &segvoronoi::Vertex| site_key(v.sites);
                    let at: std::collections::HashMap<_, _> = one.vertices().map(|v| (key(&v), v)).collect();
                    assert_eq!(one.vertex_count(), many.vertex_count(), "{what}");
                    for v in many.vertices() {
                        // (a degenerate vertex may be cut another way: its parts are elsewhere named)
                        if let Some(w) = at.get(&key(&v)) {
                            assert_eq!(
                                (v.position.x.to_bits(), v.position.y.to_bits(), v.clearance.to_bits()),
                                (w.position.x.to_bits(), w.position.y.to_bits(), w.clearance.to_bits()),
                                "{what}: vertex {:?} moved",
                                v.sites
                            );
                        } else {
                            assert!(made.degenerate, "{what}: vertex {:?} only in halves", v.sites);
                        }
                    }
                    let (glued, again) = if threads == 2 { (&mut glued, &mut again) } else { (&mut nested, &mut again_nested) };
                    *glued += usize::from(report.is_some_and(|r| r.glued && (threads == 2 || r.nested == [true, true])));
                    *again += usize::from(report.is_some_and(|r| !r.glued));
                }
                compared += 1;
            }
        }
    }
    set_halves_from(None);
    eprintln!("{compared} inputs compared: {glued} glued from halves, {again} built again on one thread");
    eprintln!("at 4 threads: {nested} glued from halves built in halves, {again_nested} built again on one thread");
    assert!(glued * 4 > compared * 3, "only {glued} of {compared} glued");
    assert!(nested * 4 > compared, "only {nested} of {compared} glued from halves built in halves");
}

/// Found by the test above: a fan of segments with straight joints moved
/// 2^30 from the origin, where an edge's zero length is decided in
/// floating point. The topology text asked it from whichever end the
/// diagram numbered first, so the halves' numbering gave another
/// `VVERTICES`; it now asks from the end whose sites come first.
#[test]
fn a_straight_fan_far_out_has_one_text_however_its_vertices_are_numbered() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    let mut input = segvoronoi_testgen::generate("fan+straight", 300, 1).unwrap();
    let o = 2f64.powi(30);
    input.segments.iter_mut().flatten().for_each(|p| *p = [p[0] + o, p[1] - o]);
    let mut b = Builder::new();
    b.add_segments(input.segments.iter().copied()).unwrap();
    set_halves_from(Some(64));
    let (one, two) = (fingerprint(&b.threads(1).build().unwrap()), fingerprint(&b.threads(2).build().unwrap()));
    let glued = take_halves_report().is_some_and(|r| r.glued);
    set_halves_from(None);
    assert!(glued);
    assert!(one == two);
}

/// A point exactly on a segment (the build cuts the segment there): that
/// build does not run in halves, and gives the one-thread diagram, on two
/// threads and on four (where halves would be built in halves).
#[test]
fn a_point_exactly_on_a_segment_builds_as_one_thread_does() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    let mut b = Builder::new();
    b.add_segments((0..200).map(|k| [[k as f64, 0.0], [k as f64 + 0.5, 1.0]])).unwrap();
    b.add_point([0.25, 0.5]).unwrap(); // on segment 0, exactly
    set_halves_from(Some(64));
    let one = fingerprint(&b.threads(1).build().unwrap());
    for threads in [2, 4] {
        let many = fingerprint(&b.threads(threads).build().unwrap());
        let glued = take_halves_report().is_some_and(|r| r.glued);
        assert!(!glued, "{threads} threads");
        assert!(one == many, "{threads} threads");
    }
    set_halves_from(None);
}

/// Real outlines in halves: the countries of Debian's gmt-dcw and the
/// Aegean islands of GSHHG (`tests/data`: straight and nearly straight
/// vertices, enclaves, islands, stretches two countries share) as
/// polygons, as given and mirrored 2^30 from the origin, each built in
/// halves from 64 sites on: the one-thread diagram (canonical text, every
/// vertex bit for bit) with the same place against the polygons for every
/// vertex. All twenty glue, each along its skyline (`HalvesReport::skyline`:
/// a rim of even depth would hold too much of a coast or a border).
#[test]
fn real_outlines_in_halves_give_the_one_thread_diagram() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    let (mut glued, mut nested, mut compared, mut skyline) = (0, 0, 0, 0);
    set_halves_from(Some(64));
    for (name, rings) in segvoronoi_testgen::rings::real_outlines() {
        let o = 2f64.powi(30);
        let far: Vec<Vec<[f64; 2]>> = rings.iter().map(|r| r.iter().map(|p| [o - p[0], p[1] - o]).collect()).collect();
        for (how, rings) in [("as given", &rings), ("mirrored 2^30 out", &far)] {
            let mut b = Builder::new();
            b.add_polygon(rings).unwrap_or_else(|e| panic!("{name}: {e}"));
            let one = b.threads(1).build().unwrap_or_else(|e| panic!("{name} {how}: {e}"));
            let two = b.threads(2).build().unwrap_or_else(|e| panic!("{name} {how} in halves: {e}"));
            let report = take_halves_report();
            glued += usize::from(report.is_some_and(|r| r.glued));
            skyline += usize::from(report.is_some_and(|r| r.glued && r.skyline));
            compared += 1;
            assert!(fingerprint(&one) == fingerprint(&two), "{name} {how}: another diagram in halves");
            // and each half in halves in turn
            let four = b.threads(4).build().unwrap_or_else(|e| panic!("{name} {how} in quarters: {e}"));
            nested += usize::from(take_halves_report().is_some_and(|r| r.glued && r.nested == [true, true]));
            assert!(fingerprint(&one) == fingerprint(&four), "{name} {how}: another diagram in quarters");
            let places = |d: &Diagram| {
                let mut p: Vec<_> = d.vertices().map(|v| (site_key(v.sites), d.vertex_location(v.id))).collect();
                p.sort_by_key(|(k, _)| *k);
                p
            };
            assert!(places(&one) == places(&two), "{name} {how}: vertices placed otherwise against the polygons");
        }
    }
    set_halves_from(None);
    eprintln!("{compared} real outlines compared: {glued} glued from halves ({skyline} along their skyline), {nested} from halves built in halves");
    assert!(glued * 2 > compared, "only {glued} of {compared} glued");
    // (a rim of even depth holds too much of a coast or a border)
    assert!(skyline * 2 > compared, "only {skyline} of {compared} glued along their skyline");
    assert!(nested * 4 > compared, "only {nested} of {compared} glued from halves built in halves");
}

/// Lattices, where every vertex is degenerate and each half cuts those on
/// the cut in its own insertion order: the halves pair up by their edges
/// across and are glued (a build of a raster on two threads once took
/// longer than on one: the halves were built, failed to pair by vertex,
/// and the build started over). Points on a square lattice, and the
/// outline of a random raster (unit edges between filled and empty
/// pixels: collinear runs, rings touching at corners): the canonical
/// text (degenerate vertices cut one way) and the vertex count of one
/// thread, and a valid diagram.
#[test]
fn lattices_glue_from_halves() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    let mut points = Builder::new();
    points.add_points((0..120 * 100).map(|i| [f64::from(i % 120), f64::from(i / 120)])).unwrap();
    let mut raster = Builder::new();
    let mut rng = SplitMix64(5);
    let (w, h) = (90, 80);
    let filled: Vec<bool> = (0..w * h).map(|_| rng.unit() < 0.5).collect();
    let at = |x: i32, y: i32| x >= 0 && y >= 0 && x < w && y < h && filled[(y * w + x) as usize];
    let mut edges = Vec::new();
    for y in 0..=h {
        for x in 0..=w {
            let (fx, fy) = (f64::from(x), f64::from(y));
            if at(x, y) != at(x, y - 1) && x < w {
                edges.push([[fx, fy], [fx + 1.0, fy]]);
            }
            if at(x, y) != at(x - 1, y) && y < h {
                edges.push([[fx, fy], [fx, fy + 1.0]]);
            }
        }
    }
    raster.add_segments(edges).unwrap();
    set_halves_from(Some(64));
    let canonical = TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true);
    for (what, b) in [("a square lattice of points", &mut points), ("a raster's outline", &mut raster)] {
        let one = b.threads(1).build().unwrap_or_else(|e| panic!("{what}: {e}"));
        let two = b.threads(2).build().unwrap_or_else(|e| panic!("{what} in halves: {e}"));
        let report = take_halves_report();
        assert!(report.is_some_and(|r| r.glued), "{what}: not glued from halves: {report:?}");
        two.validate().unwrap_or_else(|e| panic!("{what}: {e:?}"));
        assert_eq!(one.vertex_count(), two.vertex_count(), "{what}");
        assert!(one.topology(canonical) == two.topology(canonical), "{what}: another topology in halves");
    }
    set_halves_from(None);
}

/// Points and short segments a million wide, as made, mirrored 2^30 out,
/// 7.8 km wide at a UTM zone's northing (five million: each input scaled
/// by 2^-7, exactly) and 2^30 out (a spread of 7e-6 of the magnitude), and
/// 15 m wide at the northing: the plan takes them all unforced, the halves
/// glue at once and give the one-thread diagram. The plan's hull test
/// once took its margin from the coordinates' magnitude, not their spread
/// (2^30 out it counted every point as a possible vertex of the hull, and
/// the build ran on one thread), and the seam's margins were 1e-7 of the
/// magnitude (the halves of the 7.8 km 2^30 out failed their checks, and
/// were built for nothing). Points a millimetre apart 2^30 out (a spacing
/// of 1e-12 of the magnitude, below the margins): the plan refuses them
/// before building halves, and one thread builds them.
#[test]
fn inputs_far_from_the_origin_build_in_halves_unforced() {
    use segvoronoi::diagnostics::take_halves_report;
    let o = 2f64.powi(30);
    let placements: [(&str, &dyn Fn([f64; 2]) -> [f64; 2]); 5] = [
        ("as made", &|p| p),
        ("mirrored 2^30 out", &|p| [o - p[0], p[1] - o]),
        ("at a UTM northing", &|p| [500_000.0 + p[0] / 128.0, 5_000_000.0 + p[1] / 128.0]),
        ("7.8 km wide 2^30 out", &|p| [o + p[0] / 128.0, p[1] / 128.0 - o]),
        ("15 m wide at a UTM northing", &|p| [500_000.0 + p[0] / 65536.0, 5_000_000.0 + p[1] / 65536.0]),
    ];
    let points = float_points(80_000, 13);
    let segments: Vec<[[f64; 2]; 2]> = generate(Method::Short, 70_000, 17)
        .segments
        .iter()
        .map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]])
        .collect();
    for (how, place) in placements {
        let mut with_points = Builder::new();
        with_points.add_points(points.iter().map(|&p| place(p))).unwrap();
        let mut with_segments = Builder::new();
        with_segments.add_segments(segments.iter().map(|s| s.map(place))).unwrap();
        for (what, b) in [("80k points", &mut with_points), ("70k short segments", &mut with_segments)] {
            let one = b.threads(1).build().unwrap_or_else(|e| panic!("{what} {how}: {e}"));
            let two = b.threads(2).build().unwrap_or_else(|e| panic!("{what} {how} in halves: {e}"));
            let report = take_halves_report();
            assert!(report.is_some_and(|r| r.glued && r.attempts == 1), "{what} {how}: not glued at once: {report:?}");
            assert!(fingerprint(&one) == fingerprint(&two), "{what} {how}: another diagram in halves");
        }
    }
    let mut dense = Builder::new();
    dense.add_points(points.iter().map(|p| [o + p[0] / 1_048_576.0, p[1] / 1_048_576.0 - o])).unwrap();
    let one = dense.threads(1).build().unwrap();
    let two = dense.threads(2).build().unwrap();
    let report = take_halves_report();
    assert!(report.is_some_and(|r| r.attempts == 0), "points a millimetre apart 2^30 out: halves tried: {report:?}");
    assert!(fingerprint(&one) == fingerprint(&two), "points a millimetre apart 2^30 out: another diagram");
}

/// Short segments on a grid whose last row is partial, as the benchmarks
/// lay out any count that is not a square: the cells along the top near
/// the step have huge circles that reach over the step, deeper into the
/// input than a side of its enclosure allows, and round its corners.
/// Each size once took longer on two threads than on one: the halves
/// were built, their checks asked a band as wide as the input, and the
/// build started over on one thread. They glue, and give the one-thread
/// diagram.
#[test]
fn grids_with_a_step_glue_from_halves() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    set_halves_from(Some(64));
    for n in [2_000, 4_700, 9_950] {
        let mut rng = SplitMix64(n as u64);
        let k = (n as f64).sqrt().ceil() as usize;
        let segments: Vec<[[f64; 2]; 2]> = (0..n)
            .map(|i| {
                let (x, y) = ((i % k) as f64 + 0.3 * rng.unit(), (i / k) as f64 + 0.3 * rng.unit());
                let a = rng.unit() * std::f64::consts::TAU;
                [[x, y], [x + 0.3 * a.cos(), y + 0.3 * a.sin()]]
            })
            .collect();
        // as made, and mirrored 2^30 out (the step then on the bottom right)
        let o = 2f64.powi(30);
        let far: Vec<[[f64; 2]; 2]> = segments.iter().map(|s| s.map(|p| [o - p[0], -o - p[1]])).collect();
        for (how, segments) in [("as made", segments), ("mirrored 2^30 out", far)] {
            let mut b = Builder::new();
            b.add_segments(segments).unwrap();
            let one = b.threads(1).build().unwrap_or_else(|e| panic!("{n} segments {how}: {e}"));
            let two = b.threads(2).build().unwrap_or_else(|e| panic!("{n} segments {how} in halves: {e}"));
            let report = take_halves_report();
            assert!(report.is_some_and(|r| r.glued && r.attempts == 1), "{n} segments {how}: not glued at once: {report:?}");
            assert!(fingerprint(&one) == fingerprint(&two), "{n} segments {how}: another diagram in halves");
        }
    }
    set_halves_from(None);
}

/// Crossing segments five to ten spacings long, split: their ends stick
/// out of the dense middle, so the input thins out toward each side, and
/// the huge circles through the sparse ends there dip deeper into it than
/// three mean spacings. With a rim of three spacings, every size failed
/// its first attempt (and a build of 30,000 such segments took 1.3 times
/// as long on two threads as on one); the rim now reaches as deep as the
/// input thins. Segments twenty spacings long (a dozen crossings each)
/// have pieces reaching further across the cut than the first band:
/// their cells are the left half's and reach as far, and the band now
/// does too. With a straight vertex, two squares touching at a corner and
/// a point exactly on a segment among them, as made and mirrored 2^20
/// out, they glue at once, and give the one-thread diagram. (A unit-wide
/// input 2^30 out has a spacing below the seam's margins, which follow
/// the magnitude: the plan refuses it unless forced; see
/// `inputs_far_from_the_origin_build_in_halves_unforced`.)
#[test]
fn crossing_segments_split_glue_from_halves_at_once() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    set_halves_from(Some(64));
    for (n, length) in [(3_000, 0.04), (6_000, 0.025), (2_000, 0.1)] {
        let mut rng = SplitMix64(n as u64 + 7);
        let mut segments: Vec<[[f64; 2]; 2]> = (0..n)
            .map(|_| {
                let (x, y) = (rng.unit(), rng.unit());
                let a = rng.unit() * std::f64::consts::TAU;
                [[x, y], [x + length * a.cos(), y + length * a.sin()]]
            })
            .collect();
        // a straight (180-degree) vertex, two squares touching at a corner,
        // and (below) a point exactly on a segment, among the crossings
        segments.extend([[[0.2, 0.5], [0.5, 0.5]], [[0.5, 0.5], [0.8, 0.5]]]);
        let square = |x: f64, y: f64| {
            [
                [[x, y], [x + 0.1, y]],
                [[x + 0.1, y], [x + 0.1, y + 0.1]],
                [[x + 0.1, y + 0.1], [x, y + 0.1]],
                [[x, y + 0.1], [x, y]],
            ]
        };
        segments.extend(square(0.3, 0.2).into_iter().chain(square(0.4, 0.3)));
        let on_a_segment = [0.25, 0.5];
        // as made, and mirrored 2^20 out
        let o = 2f64.powi(20);
        let far: Vec<[[f64; 2]; 2]> = segments.iter().map(|s| s.map(|p| [o - p[0], -o - p[1]])).collect();
        for (how, segments, point) in [("as made", segments, on_a_segment), ("mirrored 2^20 out", far, [o - 0.25, -o - 0.5])] {
            let mut b = Builder::new();
            b.split_crossings(true).add_segments(segments).unwrap();
            b.add_points([point]).unwrap();
            let one = b.threads(1).build().unwrap_or_else(|e| panic!("{n} segments {how}: {e}"));
            let two = b.threads(2).build().unwrap_or_else(|e| panic!("{n} segments {how} in halves: {e}"));
            let report = take_halves_report();
            assert!(one.stats().pieces > 2 * n, "{n} segments {how}: too few crossings to test");
            assert!(report.is_some_and(|r| r.glued && r.attempts == 1), "{n} segments {how}: not glued at once: {report:?}");
            assert!(fingerprint(&one) == fingerprint(&two), "{n} segments {how}: another diagram in halves");
        }
    }
    set_halves_from(None);
}

/// A real outline split on two and four threads: GSHHG's coasts and
/// borders of Europe (`tests/data/`, from Debian's gmt-gshhg), tiled 6x6
/// with the tiles overlapping (their coasts and borders cross), with a
/// straight (180-degree) vertex, a point exactly on a segment and two
/// squares touching at a corner, 2^30 from the origin. Large enough for
/// the contact search in slabs (and slabs of slabs at four threads) and
/// the routing in halves (the plan takes it unforced; 2^30 out it once
/// refused every input, see `inputs_far_from_the_origin_build_in_halves_unforced`):
/// the pieces, their counts and the diagram of one thread (the canonical
/// text, and every vertex at the same place bit for bit: the squares'
/// centres are degenerate vertices, which the halves may cut otherwise).
#[test]
fn real_coasts_tiled_split_the_same_at_every_thread_count() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/gshhg_coast_borders_c_europe.txt");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let coast = segvoronoi::boost_text::parse(&text).unwrap_or_else(|e| panic!("{path}: {e}")).segments;
    let xs = coast.iter().flat_map(|s| [s[0], s[2]]);
    let ys = coast.iter().flat_map(|s| [s[1], s[3]]);
    let (x0, x1) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    let (y0, y1) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
    // (steps of nine tenths of the extent, whole numbers: every coordinate
    // stays an exact integer 2^30 out)
    let (dx, dy) = ((0.9 * (x1 - x0)).round(), (0.9 * (y1 - y0)).round());
    let o = 2f64.powi(30);
    let mut segments: Vec<[[f64; 2]; 2]> = Vec::new();
    for (i, j) in (0..6).flat_map(|i| (0..6).map(move |j| (i as f64, j as f64))) {
        segments.extend(coast.iter().map(|s| [[o + s[0] + i * dx, o + s[1] + j * dy], [o + s[2] + i * dx, o + s[3] + j * dy]]));
    }
    // below the tiles: a straight vertex with a point exactly on one of
    // its segments, and two squares touching at a corner
    let (px, py) = (o + x0, o + y0 - 20_000.0);
    segments.extend([[[px, py], [px + 5_000.0, py]], [[px + 5_000.0, py], [px + 10_000.0, py]]]);
    let square = |x: f64, y: f64| {
        [
            [[x, y], [x + 4_000.0, y]],
            [[x + 4_000.0, y], [x + 4_000.0, y + 4_000.0]],
            [[x + 4_000.0, y + 4_000.0], [x, y + 4_000.0]],
            [[x, y + 4_000.0], [x, y]],
        ]
    };
    segments.extend(square(px + 20_000.0, py).into_iter().chain(square(px + 24_000.0, py + 4_000.0)));
    let mut b = Builder::new();
    b.split_crossings(true).add_segments(segments.iter().copied()).unwrap();
    b.add_points([[px + 1_250.0, py]]).unwrap();
    let one = b.threads(1).build().unwrap_or_else(|e| panic!("tiled coasts: {e}"));
    let split = |d: &Diagram| {
        let s = d.stats();
        (s.pieces, s.crossings, s.overlaps, s.touchings, s.snap_rounds)
    };
    eprintln!("tiled coasts: {} segments; pieces, crossings, overlaps, touchings, rounds: {:?}", segments.len(), split(&one));
    assert!(one.stats().crossings > 1_000 && one.stats().pieces > 40_000, "too few crossings to test: {:?}", split(&one));
    assert!(one.stats().touchings > 0, "the point on a segment was not met");
    for n in [2, 4] {
        let other = b.threads(n).build().unwrap_or_else(|e| panic!("tiled coasts at {n} threads: {e}"));
        let report = segvoronoi::diagnostics::take_halves_report();
        assert!(report.is_some_and(|r| r.glued), "tiled coasts at {n} threads: not glued from halves: {report:?}");
        assert_eq!(split(&one), split(&other), "tiled coasts at {n} threads");
        assert!(fingerprint_of_places(&one) == fingerprint_of_places(&other), "tiled coasts: another diagram at {n} threads");
    }
}

/// With four threads or more, each half is built in halves in turn on the
/// threads its own thread may start (vertical strips, glued pairwise):
/// the one-thread diagram, bit for bit, at 4 and 8 threads (on this
/// machine's cores or more: the budget, not the cores, decides), for
/// points, segments, a lattice (ties on every cut) and mirrored far out.
#[test]
fn halves_built_in_halves_give_the_one_thread_diagram() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    set_halves_from(Some(500));
    let o = 2f64.powi(30);
    let mut rng = SplitMix64(12);
    let points: Vec<[f64; 2]> = (0..6_000).map(|_| [rng.unit(), rng.unit()]).collect();
    let lattice: Vec<[f64; 2]> = (0..90 * 70).map(|i| [f64::from(i % 90), f64::from(i / 90)]).collect();
    let segments: Vec<[[f64; 2]; 2]> = generate(Method::Short, 5_000, 3)
        .segments
        .iter()
        .map(|s| [[s[0], s[1]], [s[2], s[3]]].map(|p| p.map(f64::from)))
        .collect();
    let far = |p: [f64; 2]| [o - 1e3 * p[0], -o - 1e3 * p[1]];
    // (a lattice's degenerate vertices are cut as the half that keeps them
    // inserted its sites: its canonical text is the one thread's, the
    // vertices' sites need not be)
    let canonical = TopologyOptions::default().with_canonical_cuts(true).with_voronoi_pairs(true);
    let inputs: Vec<(&str, Builder)> = vec![
        ("uniform points", builder_of(&points, &[])),
        ("a lattice of points", builder_of(&lattice, &[])),
        ("short segments", builder_of(&[], &segments)),
        ("points mirrored far out", builder_of(&points.iter().map(|&p| far(p)).collect::<Vec<_>>(), &[])),
        ("segments mirrored far out", builder_of(&[], &segments.iter().map(|s| s.map(far)).collect::<Vec<_>>())),
    ];
    for (what, mut b) in inputs {
        let one = b.threads(1).build().unwrap_or_else(|e| panic!("{what}: {e}"));
        let degenerate = what.contains("lattice");
        let one = if degenerate { (one.topology(canonical), Vec::new()) } else { fingerprint(&one) };
        for threads in [4, 8] {
            let many = b.threads(threads).build().unwrap_or_else(|e| panic!("{what} at {threads} threads: {e}"));
            let report = take_halves_report();
            assert!(
                report.is_some_and(|r| r.glued && r.nested == [true, true]),
                "{what} at {threads} threads: halves not built in halves and glued: {report:?}"
            );
            many.validate().unwrap_or_else(|e| panic!("{what} at {threads} threads: {e:?}"));
            let many = if degenerate { (many.topology(canonical), Vec::new()) } else { fingerprint(&many) };
            assert!(one == many, "{what}: another diagram at {threads} threads");
        }
    }
    set_halves_from(None);
}

fn builder_of(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Builder {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    b
}

/// The sites' coordinates, bit for bit (a `-0` shows here where the
/// topology and the vertices would not tell).
fn site_bits(d: &Diagram) -> Vec<[u64; 2]> {
    let bits = |p: segvoronoi::Point| [p.x.to_bits(), p.y.to_bits()];
    (0..d.site_count())
        .filter_map(|s| match d.site(SiteId::from_index(s))? {
            segvoronoi::Site::Point(p) => Some(bits(p)),
            _ => None,
        })
        .collect()
}

/// A build takes its input as the construction's coordinates where
/// scaling changes nothing, and a copy with `+0` for `-0` where an input
/// has one: a `-0` builds as `+0` does (a repeat of its `+0` twin, and a
/// site at `+0`), on one thread and in halves, for points and segments.
#[test]
fn negative_zero_builds_as_positive_zero() {
    let with_zero = |zero: f64| {
        // uniform points with some on the axes, one of them twice
        let mut points = float_points(120_000, 5);
        for (k, p) in points.iter_mut().enumerate().step_by(997) {
            p[k % 2] = zero;
        }
        points.extend([[zero, 0.5], [0.0, 0.5], [0.25, zero]]);
        let mut b = Builder::new();
        b.add_points(points).unwrap();
        // and short segments, with one along the y-axis below them all
        let segments = generate(Method::Short, 25_000, 9).segments;
        let mut s = Builder::new();
        s.add_segments(segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]]))
            .unwrap();
        s.add_segment([[zero, -20.0], [zero, -10.0]]).unwrap();
        s.add_points([[zero, -30.0]]).unwrap();
        // points all on the y-axis (a collinear build sorts them)
        let mut c = Builder::new();
        c.add_points([[zero, 2.0], [0.0, 1.0], [zero, 3.0], [0.0, 0.5], [zero, -1.0]]).unwrap();
        [b, s, c]
    };
    let (mut negative, mut positive) = (with_zero(-0.0), with_zero(0.0));
    for (what, (n, p)) in ["points", "segments", "points on the y-axis"].iter().zip(negative.iter_mut().zip(positive.iter_mut()))
    {
        for threads in [1, 2] {
            let (dn, dp) = (n.threads(threads).build().unwrap(), p.threads(threads).build().unwrap());
            assert!(fingerprint(&dn) == fingerprint(&dp), "{what} at {threads} threads: -0 builds another diagram than +0");
            assert_eq!(site_bits(&dn), site_bits(&dp), "{what} at {threads} threads: a site keeps its -0");
            assert_eq!(dn.stats().duplicate_points, dp.stats().duplicate_points, "{what}");
        }
    }
}

/// A sheet of star-shaped parts with a hole each (the headline's
/// polygons): along its lumpy boundary the circles of the cells by the
/// hull dip between the parts far deeper than a rim the halves could both
/// hold, and such a rim held too many points: the plan refused the sheet,
/// and forced, it took a second attempt with each half holding the whole.
/// Both halves now hold the skyline and a shallow rim, and ask the disks
/// the seam's tests cannot clear of the left-out sites themselves. With a
/// straight vertex (an edge of a part cut in two), one an ulp off
/// straight, and two squares touching at a corner among them; as made,
/// mirrored 2^30 out, and reversed and shuffled: the halves glue at once,
/// and give the one-thread diagram (the canonical text, and every vertex
/// at the same place bit for bit: the squares' centres are degenerate
/// vertices, which a half may cut otherwise). With a point exactly on an
/// edge too, the one-thread diagram (such a build does not run in
/// halves). At the headline's size (200 parts, 100k
/// segments) the plan takes the sheet without being forced, and glues it
/// at once wherever the cut falls (shares of 0.40 to 0.60).
#[test]
fn a_sheet_of_parts_glues_from_halves_at_once() {
    use segvoronoi::diagnostics::{set_halves_from, take_halves_report};
    use segvoronoi_testgen::shapes::star_sheet;
    // (rounded to 1/32768, as the headline does)
    let sheet = |parts: usize, outer: usize, hole: usize| {
        let mut segments: Vec<[[f64; 2]; 2]> = Vec::new();
        for ring in star_sheet(parts, outer, hole, 1).iter().flatten() {
            let ring: Vec<[f64; 2]> = ring.iter().map(|p| p.map(|v| (v * 32768.0).round() / 32768.0)).collect();
            segments.extend((0..ring.len()).map(|i| [ring[i], ring[(i + 1) % ring.len()]]));
        }
        segments
    };
    let mut segments = sheet(36, 120, 30);
    // two squares touching at a corner, in the gap between four parts
    let square = |x: f64, y: f64| {
        let c = [[x, y], [x + 0.125, y], [x + 0.125, y + 0.125], [x, y + 0.125]];
        (0..4).map(move |i| [c[i], c[(i + 1) % 4]])
    };
    segments.extend(square(1.1 - 0.125, 1.1 - 0.125).chain(square(1.1, 1.1)));
    // a straight vertex, one an ulp off straight, and a point on an edge
    let [a, b] = segments[5];
    let middle = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    segments.splice(5..6, [[a, middle], [middle, b]]);
    let [a, b] = segments[200];
    let middle = [0.5 * (a[0] + b[0]), f64::from_bits((0.5 * (a[1] + b[1])).to_bits() + 1)];
    segments.splice(200..201, [[a, middle], [middle, b]]);
    let [a, b] = segments[400];
    let on_edge = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let o = 2f64.powi(30);
    let far: Vec<[[f64; 2]; 2]> = segments.iter().map(|s| s.map(|p| [o - p[0], -o - p[1]])).collect();
    let mut shuffled: Vec<[[f64; 2]; 2]> = segments.iter().map(|&[a, b]| [b, a]).rev().collect();
    let mut rng = SplitMix64(6);
    for i in (1..shuffled.len()).rev() {
        shuffled.swap(i, (rng.unit() * (i + 1) as f64) as usize % (i + 1));
    }
    set_halves_from(Some(64));
    let mut with_point = Builder::new();
    with_point.add_segments(segments.iter().copied()).unwrap();
    with_point.add_point(on_edge).unwrap();
    let (one, two) = (with_point.threads(1).build().unwrap(), with_point.threads(2).build().unwrap());
    assert!(fingerprint_of_places(&one) == fingerprint_of_places(&two), "sheet with a point on an edge: another diagram");
    for (how, segments) in [("as made", segments), ("mirrored 2^30 out", far), ("reversed and shuffled", shuffled)] {
        let mut b = Builder::new();
        b.add_segments(segments).unwrap();
        let one = b.threads(1).build().unwrap_or_else(|e| panic!("sheet {how}: {e}"));
        let two = b.threads(2).build().unwrap_or_else(|e| panic!("sheet {how} in halves: {e}"));
        let report = take_halves_report();
        assert!(report.is_some_and(|r| r.skyline && r.glued && r.attempts == 1), "sheet {how}: not glued at once: {report:?}");
        // (the squares' centres are degenerate vertices)
        assert!(fingerprint_of_places(&one) == fingerprint_of_places(&two), "sheet {how}: another diagram in halves");
    }
    set_halves_from(None);
    let mut b = Builder::new();
    b.add_segments(sheet(200, 400, 100)).unwrap();
    let one = b.threads(1).build().unwrap();
    let two = b.threads(2).build().unwrap();
    let report = take_halves_report();
    assert!(report.is_some_and(|r| r.skyline && r.glued && r.attempts == 1), "the headline's sheet: {report:?}");
    let one = fingerprint(&one);
    assert!(one == fingerprint(&two), "the headline's sheet: another diagram in halves");
    // Wherever the cut falls: beside a column of parts or a gap between
    // two, the band reaches as far as the empty disks between the parts.
    // (A band of spacings took a second attempt at five of these shares,
    // and two threads took longer than one.)
    for share in [0.40, 0.42, 0.48, 0.54, 0.56, 0.60] {
        segvoronoi::diagnostics::set_halves_left_share(Some(share));
        let two = b.threads(2).build().unwrap();
        let report = take_halves_report();
        assert!(report.is_some_and(|r| r.glued && r.attempts == 1), "the headline's sheet cut at {share}: {report:?}");
        assert!(one == fingerprint(&two), "the headline's sheet cut at {share}: another diagram in halves");
    }
    segvoronoi::diagnostics::set_halves_left_share(None);
}
