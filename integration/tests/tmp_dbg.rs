use segvoronoi::{Builder, CircularArc, Point};
#[test]
fn dbg() {
    let p = Point::new;
    let mut b = Builder::new();
    b.add_point([0.5, 3.0]).unwrap();
    b.add_arc(CircularArc::through(p(0.0, 0.0), p(0.5, 0.5), p(1.0, 0.0)).unwrap()).unwrap();
    match b.build() { Ok(d) => {
        for s in d.site_ids() { println!("site {s:?} {:?}", d.site(s)); }
        for v in d.vertices() { println!("v {:?} {:?} r {} {:?}", v.id, v.position, v.clearance, v.sites); } }
      Err(e) => println!("{e}") }
}
