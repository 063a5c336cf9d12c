//! The state of a construction: the half-edge store, the table of sites
//! with their kinds (point or open segment), and the marks and scratch
//! space that the deletion tree of every insertion uses
//! (`deletion_tree.rs`).
//!
//! Site ids: 0 is the point at infinity, then the point sites, then the
//! open segments. The construction inserts every point before any segment
//! (DESIGN §2.2; the collinear ladder too), so the kind of a site is the
//! range its id falls in, `first_segment` on: one comparison in the
//! hottest question of both insertions (`is_separator`, asked of every edge
//! the deletion tree looks at), where a per-site table would cost a load.
//! Every question about kinds goes through `ends_of` / `is_segment` here.
//!
//! This file does no arithmetic on coordinates: positions come from
//! `geometry::segments::vertex_placement`.

use crate::diagram::Store;
use crate::diagram::{HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::segments::vertex_placement;
use crate::geometry::site::Site;
use crate::geometry::{CircularArc, Point};

/// The id of the point at infinity inside the construction.
pub(crate) const INFINITE: SiteId = SiteId(0);

/// What a finished construction hands on.
pub(crate) struct Parts {
    pub store: Store,
    pub sites: Vec<Point>,
    /// Per segment site, in id order after the points: its endpoint sites.
    pub segment_ends: Vec<[SiteId; 2]>,
}

/// The diagram under construction: the store, the sites, and the scratch
/// space of the insertions.
pub(crate) struct Construction {
    pub(super) store: Store,
    /// Coordinates per site id; entry 0 (the point at infinity) is unused.
    pub(super) sites: Vec<Point>,
    pub(super) vertex_mark: Vec<u32>,
    pub(super) cell_mark: Vec<u32>,
    pub(super) epoch: u32,
    pub(super) tree: Vec<VertexId>,
    /// Per cut: the leaving half-edge and the cells on its right and left.
    pub(super) cuts: Vec<(HalfEdgeId, SiteId, SiteId)>,
    pub(super) new_vertices: Vec<VertexId>,
    /// Edges between two tree vertices that are cut at both ends, their
    /// middle kept (one half-edge of each): where a segment's cell wraps
    /// around part of a cell (see `deletion_tree.rs`).
    pub(super) twice_cut: Vec<HalfEdgeId>,
    /// Site ids from here on are open segments (`u32::MAX`: none yet).
    first_segment: u32,
    /// Per segment site (id minus `first_segment`): its two endpoint sites;
    /// arcs' too, after the segments'.
    segment_ends: Vec<[SiteId; 2]>,
    /// Site ids from here on are open arcs (`u32::MAX`: none yet); they go
    /// in after every segment.
    first_arc: u32,
    /// Per arc site (id minus `first_arc`): its geometry.
    arcs: Vec<CircularArc>,
    /// The arc being inserted: the insertion's questions go to the arcs'
    /// predicates (`insert_segment/arc_questions.rs`) while it is set.
    pub(super) inserting_arc: Option<CircularArc>,
    /// While points go in (`insert_point::insert_points`), new vertices are
    /// not placed: two in three are deleted again by later points, and
    /// placing them took a sixth of the build. Every vertex is placed once
    /// the points are in (`place_deferred`), from its sites alone, as it
    /// would have been at its creation.
    pub(super) placement_deferred: bool,
}

impl Construction {
    /// A diagram of the point at infinity alone, with room for `n` points.
    pub(super) fn new(n: usize) -> Construction {
        let mut store = Store::new(1, INFINITE, 2 * n + 2);
        store.cell_edge.reserve(n);
        let mut sites = Vec::with_capacity(n + 1);
        sites.push(Point::new(f64::NAN, f64::NAN));
        Construction {
            store,
            sites,
            vertex_mark: Vec::with_capacity(2 * n + 2),
            cell_mark: Vec::with_capacity(n + 1),
            epoch: 0,
            tree: Vec::new(),
            cuts: Vec::new(),
            new_vertices: Vec::new(),
            twice_cut: Vec::new(),
            first_segment: u32::MAX,
            segment_ends: Vec::new(),
            first_arc: u32::MAX,
            arcs: Vec::new(),
            inserting_arc: None,
            placement_deferred: false,
        }
        .with_marks()
    }

    fn with_marks(mut self) -> Self {
        self.cell_mark.push(0);
        self
    }

    /// The store and the site coordinates, scratch space dropped.
    pub(super) fn into_parts(self) -> Parts {
        Parts { store: self.store, sites: self.sites, segment_ends: self.segment_ends }
    }

    /// A construction over a store assembled elsewhere (the parallel
    /// build's glued halves, `halves/`): `sites` per site id (entry 0 the
    /// point at infinity, segments `NaN`), the segments from
    /// `first_segment` on (`u32::MAX`: none) with their endpoint sites.
    pub(super) fn assembled(store: Store, sites: Vec<Point>, first_segment: u32, segment_ends: Vec<[SiteId; 2]>) -> Construction {
        let mut c = Construction::new(0);
        c.vertex_mark = vec![0; store.vertex_count()];
        c.cell_mark = vec![0; sites.len()];
        c.store = store;
        c.sites = sites;
        c.first_segment = first_segment;
        c.segment_ends = segment_ends;
        c
    }

    /// The coordinates of site `s` (a point site's, or a segment's two
    /// ends; arcs are not asked), read by the parallel build's checks.
    pub(super) fn site_points(&self, s: SiteId) -> ([Point; 2], usize) {
        match self.ends_of(s) {
            Some([a, b]) => ([self.sites[a.index()], self.sites[b.index()]], 2),
            None => ([self.sites[s.index()]; 2], 1),
        }
    }

    /// The store, read by the parallel build's checks.
    pub(super) fn store(&self) -> &Store {
        &self.store
    }

    /// Adds the open arc between its endpoint sites `a` (its start) and
    /// `b` (its end), after every segment.
    pub(super) fn add_arc_site(&mut self, a: SiteId, b: SiteId, arc: CircularArc) -> SiteId {
        let s = self.add_segment_site(a, b);
        if self.first_arc == u32::MAX {
            self.first_arc = s.0;
        }
        self.arcs.push(arc);
        s
    }

    /// Adds a point site (before any segment: see the module doc).
    pub(super) fn add_site(&mut self, p: Point) -> SiteId {
        debug_assert!(self.first_segment == u32::MAX, "every point goes in before any segment");
        let s = SiteId::from_index(self.sites.len());
        self.sites.push(p);
        self.store.cell_edge.push(crate::diagram::NONE);
        self.cell_mark.push(0);
        s
    }

    /// Adds the open segment between the point sites `a` and `b`.
    pub(super) fn add_segment_site(&mut self, a: SiteId, b: SiteId) -> SiteId {
        let s = SiteId::from_index(self.sites.len());
        if self.first_segment == u32::MAX {
            self.first_segment = s.0;
        }
        self.segment_ends.push([a, b]);
        self.sites.push(Point::new(f64::NAN, f64::NAN));
        self.store.cell_edge.push(NONE);
        self.cell_mark.push(0);
        s
    }

    pub(super) fn push_vertex(&mut self) -> VertexId {
        self.vertex_mark.push(0);
        self.store.push_vertex()
    }

    pub(super) fn set_sites(&mut self, v: VertexId, sites: [SiteId; 3]) {
        let b = 3 * v.index();
        self.store.right[b..b + 3].copy_from_slice(&sites);
    }

    /// Computes the position and clearance of `v` from its three sites
    /// (`geometry::segments::vertex_placement`): a vertex at infinity stores the
    /// direction of its edge and an infinite clearance.
    pub(super) fn place_vertex(&mut self, v: VertexId) {
        self.place_vertex_on(v, None);
    }

    /// Places every vertex and ends the deferral (`placement_deferred`).
    pub(super) fn place_deferred(&mut self) {
        self.placement_deferred = false;
        for v in (0..self.store.vertex_count()).map(VertexId::from_index) {
            self.place_vertex(v);
        }
    }

    /// `place_vertex` for a vertex cut into the edge between `on` (its two
    /// ends, one far out for an end at infinity): where its sites have
    /// more than one circle in the order asked (an arc among them), the
    /// one on that edge.
    pub(super) fn place_vertex_on(&mut self, v: VertexId, on: Option<[Point; 2]>) {
        let sites = self.store.sites_of(v);
        let (pos, clearance) = match infinite_rotation(sites) {
            Some((x, y)) => {
                let direction = vertex_placement::direction_at_infinity(self.site_geometry(x), self.site_geometry(y));
                (direction, f64::INFINITY)
            }
            None if self.has_segment(sites) => {
                // (built in place: `array::map` moved the three sites, each as
                // large as an arc, through a copy per vertex)
                let [a, b, c] = sites;
                vertex_placement::circle_of_sites_on(&[self.site_geometry(a), self.site_geometry(b), self.site_geometry(c)], on)
            }
            None => {
                let [a, b, c] = sites.map(|s| self.sites[s.index()]);
                vertex_placement::circle_of_points(a, b, c)
            }
        };
        self.store.position[v.index()] = vertex_placement::as_stored(pos);
        self.store.clearance[v.index()] = clearance;
    }

    /// Whether any of the sites is an open segment.
    #[inline]
    pub(super) fn has_segment(&self, sites: [SiteId; 3]) -> bool {
        sites.iter().any(|&s| self.is_segment(s))
    }

    #[inline]
    fn is_segment(&self, s: SiteId) -> bool {
        s.0 >= self.first_segment
    }

    /// The endpoint sites of `s`, if it is a segment.
    #[inline]
    pub(super) fn ends_of(&self, s: SiteId) -> Option<[SiteId; 2]> {
        self.is_segment(s).then(|| self.segment_ends[(s.0 - self.first_segment) as usize])
    }

    /// The other endpoint of `s`, if it is a segment ending at `end`.
    pub(super) fn far_end(&self, s: SiteId, end: SiteId) -> Option<SiteId> {
        match self.ends_of(s)? {
            [x, y] if x == end => Some(y),
            [x, y] if y == end => Some(x),
            _ => None,
        }
    }

    /// The geometry of a real site (not the point at infinity).
    pub(super) fn site_geometry(&self, s: SiteId) -> Site {
        if s.0 >= self.first_arc {
            return Site::Arc(self.arcs[(s.0 - self.first_arc) as usize]);
        }
        match self.ends_of(s) {
            Some([a, b]) => Site::Segment { a: self.sites[a.index()], b: self.sites[b.index()] },
            None => Site::Point(self.sites[s.index()]),
        }
    }

    /// The coordinates of the endpoint sites `a` and `b` of a new segment.
    #[inline]
    pub(super) fn segment_between(&self, a: SiteId, b: SiteId) -> (Point, Point) {
        (self.sites[a.index()], self.sites[b.index()])
    }

    /// Every segment site so far with its endpoint sites (tests).
    #[cfg(all(test, feature = "fault-injection"))]
    pub(super) fn segment_sites(&self) -> impl Iterator<Item = (SiteId, [SiteId; 2])> + '_ {
        self.segment_ends.iter().enumerate().map(|(k, &ends)| (SiteId(self.first_segment + k as u32), ends))
    }
}

/// For a vertex with the point at infinity among its sites `[a, b, c]`
/// (counter-clockwise), the other two `(x, y)` rotated so that the point at
/// infinity lies to the left of `x → y`.
#[inline]
pub(super) fn infinite_rotation([a, b, c]: [SiteId; 3]) -> Option<(SiteId, SiteId)> {
    if c == INFINITE {
        Some((a, b))
    } else if a == INFINITE {
        Some((b, c))
    } else if b == INFINITE {
        Some((c, a))
    } else {
        None
    }
}
