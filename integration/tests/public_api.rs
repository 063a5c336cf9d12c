//! The shape of the public API: the adders' argument and return shapes,
//! `Option` from every id accessor, a segment site's endpoints and input
//! index, and the options type that may grow.

use segvoronoi::{Builder, EdgeId, ErrorKind, Point, Site, SiteId, TopologyOptions, VertexId};

#[test]
fn point_and_segment_adders_take_the_same_shapes() {
    let mut b = Builder::new();
    // One point: anything that converts into a Point.
    assert_eq!(b.add_point([0.0, 0.0]).unwrap(), 0);
    assert_eq!(b.add_point((4.0, 0.0)).unwrap(), 1);
    assert_eq!(b.add_point(Point::new(0.0, 4.0)).unwrap(), 2);
    // Many: the range of their input indices.
    assert_eq!(b.add_points([[4.0, 4.0], [2.0, 1.0]]).unwrap(), 3..5);
    assert_eq!(b.add_points(Vec::<[f64; 2]>::new()).unwrap(), 5..5);
    // One segment is a pair of such points; many are pairs too.
    assert_eq!(b.add_segment([[10.0, 0.0], [12.0, 0.0]]).unwrap(), 0);
    assert_eq!(b.add_segment([Point::new(10.0, 2.0), Point::new(12.0, 3.0)]).unwrap(), 1);
    assert_eq!(b.add_segments([[(10.0, 5.0), (12.0, 6.0)], [(10.0, 8.0), (11.0, 8.0)]]).unwrap(), 2..4);
    assert_eq!((b.point_count(), b.segment_count()), (5, 4));
    let d = b.build().unwrap();
    d.validate().unwrap();
    assert_eq!(d.site_count(), 5 + 3 * 4);

    // A rejected call of either kind leaves the builder as it was, and the
    // single adders name the index the item would have had.
    let e = b.add_point([f64::NAN, 0.0]).unwrap_err();
    assert_eq!((e.kind(), e.indices()), (ErrorKind::InvalidCoordinate, &[5][..]));
    let e = b.add_segment([[0.0, 0.0], [f64::INFINITY, 0.0]]).unwrap_err();
    assert_eq!((e.kind(), e.indices()), (ErrorKind::InvalidCoordinate, &[4][..]));
    let e = b.add_points([[1.0, 1.0], [f64::NAN, 1.0]]).unwrap_err();
    assert_eq!(e.indices(), &[6]);
    assert_eq!((b.point_count(), b.segment_count()), (5, 4));
    b.reserve_points(10).unwrap();
    b.reserve_segments(10).unwrap();
}

#[test]
fn every_id_accessor_returns_an_option() {
    let mut b = Builder::new();
    b.add_points([[0.0, 0.0], [2.0, 0.0], [1.0, 2.0]]).unwrap();
    let d = b.build().unwrap();
    let n = d.site_count();
    assert_eq!(d.site(SiteId::from_index(0)), Some(Site::Point(Point::new(0.0, 0.0))));
    assert_eq!(d.site(SiteId::from_index(n)), None);
    assert!(d.cell(SiteId::from_index(n)).is_none());
    assert!(d.vertex(VertexId::from_index(d.vertex_count())).is_none());
    assert!(d.edge(EdgeId::from_index(d.edge_count())).is_none());
}

#[test]
fn segment_endpoints_follow_the_site_and_lead_back_to_the_input() {
    let mut b = Builder::new();
    b.add_point([5.0, 5.0]).unwrap();
    // A polygon walked both ways, and a repeat reversed: whatever order the
    // construction keeps, the endpoints come in the order of the site's a, b.
    b.add_segments([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 3.0], [4.0, 0.0]], [[4.0, 3.0], [0.0, 0.0]]]).unwrap();
    b.add_segment([[4.0, 0.0], [0.0, 0.0]]).unwrap();
    b.add_segment([[8.0, 1.0], [6.0, 2.0]]).unwrap();
    let d = b.build().unwrap();
    for s in d.site_ids() {
        let site = d.site(s).unwrap();
        match site {
            Site::Segment { a, b } => {
                let [p, q] = d.segment_endpoints(s).unwrap();
                assert_eq!([d.site(p), d.site(q)], [Some(Site::Point(a)), Some(Site::Point(b))]);
                let j = d.segment_input_index(s).unwrap();
                assert_eq!(d.site_of_segment(j), Some(s));
            }
            _ => {
                assert!(site.is_point());
                assert_eq!((d.segment_endpoints(s), d.segment_input_index(s)), (None, None));
            }
        }
    }
    // The repeat (input 3) shares the first one's site, which names input 0.
    assert_eq!(d.site_of_segment(3), d.site_of_segment(0));
    assert_eq!(d.segment_input_index(d.site_of_segment(3).unwrap()), Some(0));
    assert_eq!(d.segment_endpoints(SiteId::from_index(d.site_count())), None);
}

#[test]
fn topology_options_are_built_from_the_default() {
    let options = TopologyOptions::default().with_voronoi_pairs(true).with_zero_length_tolerance(Some(1e-9));
    assert!(options.voronoi_pairs);
    assert_eq!(options.zero_length_tolerance, Some(1e-9));
    let mut b = Builder::new();
    b.add_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]).unwrap();
    let d = b.build().unwrap();
    assert!(d.topology(options).contains("\nVPAIRS 4\n"));
    assert!(!d.topology(TopologyOptions::default()).contains("VPAIRS"));
}
