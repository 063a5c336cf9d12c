mod common;
use common::*;
use segvoronoi::{Builder, ErrorKind, Point, TopologyOptions};

#[test]
fn empty_one_and_two_points() {
    let d = build(&[]);
    assert_eq!((d.site_count(), d.vertex_count(), d.edge_count()), (0, 0, 0));
    let d = build(&[[1.0, 2.0]]);
    assert_eq!((d.site_count(), d.vertex_count(), d.edge_count()), (1, 0, 0));
    let d = build(&[[1.0, 2.0], [3.0, 2.0]]);
    assert_eq!((d.site_count(), d.vertex_count(), d.edge_count()), (2, 0, 1));
    assert!(d.edges().next().is_some());
}

#[test]
fn all_equal_points_are_one_site() {
    let d = build(&[[0.5, 0.5]; 7]);
    assert_eq!(d.site_count(), 1);
    assert_eq!(d.stats().duplicate_points, 6);
}

#[test]
fn collinear_points_give_parallel_lines() {
    let pts: Vec<[f64; 2]> = (0..20).map(|i| [(i * 7 % 20) as f64, 2.0 * (i * 7 % 20) as f64]).collect();
    let d = build(&pts);
    assert_eq!(d.vertex_count(), 0);
    assert_eq!(d.edge_count(), 19);
}

#[test]
fn square_lattice_is_degenerate_but_valid() {
    let mut pts = Vec::new();
    for i in 0..30 {
        for j in 0..30 {
            pts.push([i as f64, j as f64]);
        }
    }
    let d = build(&pts);
    check_empty_circles(&d, 1e-9);
    let t = d.topology(TopologyOptions { voronoi_pairs: true });
    // each interior lattice point has 4 Voronoi neighbours through positive-length edges
    let vpairs: usize = t.lines().find(|l| l.starts_with("VPAIRS")).unwrap()[7..].parse().unwrap();
    assert_eq!(vpairs, 2 * 30 * 29);
}

#[test]
fn random_points_match_brute_force() {
    for seed in 0..20 {
        let pts = uniform(200, seed);
        let d = build(&pts);
        assert_eq!(d.site_count(), 200);
        assert_eq!(d.vertex_count(), 2 * 200 - 2 - ray_count(&d));
        check_empty_circles(&d, 1e-9);
        let q: Vec<Point> = uniform(200, seed + 1000).into_iter().map(Point::from).collect();
        check_nearest_sites(&d, &q, 1e-12);
    }
}

#[test]
fn large_random_validates() {
    let d = build(&uniform(100_000, 7));
    assert_eq!(d.site_count(), 100_000);
}

#[test]
fn invalid_coordinate_names_index_and_keeps_builder() {
    let mut b = Builder::new();
    b.add_points([[0.0, 0.0], [1.0, 1.0]]).unwrap();
    let e = b.add_points([[2.0, 2.0], [f64::NAN, 0.0]]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidCoordinate);
    assert_eq!(e.indices(), &[3]);
    assert!(e.message().contains("point 3"), "{}", e.message());
    assert_eq!(b.point_count(), 2);
    let e = b.add_point(0.0, f64::INFINITY).unwrap_err();
    assert_eq!(e.indices(), &[2]);
    assert_eq!(b.point_count(), 2);
}
