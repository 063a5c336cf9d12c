//! All points on one line: the diagram is a ladder of parallel bisectors,
//! every vertex at infinity, laid out directly (no insertion can start
//! from fewer than three points in general position); segments, which can
//! only join consecutive points, are rungs of the ladder too.

use super::state::{Construction, INFINITE};
use crate::diagram::{SiteId, VertexId};
use crate::geometry::Point;

impl Construction {
    /// The diagram of points that all lie on one line, given in order along
    /// it (at least two, all distinct): a ladder of parallel bisectors,
    /// every vertex at infinity. Returns the new site ids in the same order.
    pub(super) fn start_collinear(&mut self, chain: &[Point]) -> Vec<SiteId> {
        debug_assert!(chain.len() >= 2 && self.sites.len() == 1);
        let ids: Vec<SiteId> = chain.iter().map(|&p| self.add_site(p)).collect();
        self.build_ladder(&ids);
        ids
    }

    /// The ladder of parallel bisectors between consecutive sites of `ids`
    /// (added already, at least two), every vertex at infinity.
    fn build_ladder(&mut self, ids: &[SiteId]) {
        let m = ids.len();
        // U_i = (q_i, q_(i+1), inf) on the left of the chain, D_i = (q_(i+1), q_i, inf) on the right.
        let ups: Vec<VertexId> = (0..m - 1).map(|_| self.push_vertex()).collect();
        let downs: Vec<VertexId> = (0..m - 1).map(|_| self.push_vertex()).collect();
        for i in 0..m - 1 {
            self.set_sites(ups[i], [ids[i], ids[i + 1], INFINITE]);
            self.set_sites(downs[i], [ids[i + 1], ids[i], INFINITE]);
        }
        let st = &mut self.store;
        for i in 0..m - 1 {
            let (u, d) = (ups[i], downs[i]);
            st.link(u.half_edge(0), d.half_edge(0));
            if i + 1 < m - 1 {
                st.link(u.half_edge(1), ups[i + 1].half_edge(2));
                st.link(d.half_edge(2), downs[i + 1].half_edge(1));
            } else {
                st.link(u.half_edge(1), d.half_edge(2));
            }
        }
        st.link(ups[0].half_edge(2), downs[0].half_edge(1));
        for i in 0..m - 1 {
            st.cell_edge[ids[i].index()] = ups[i].half_edge(2).0;
        }
        st.cell_edge[ids[m - 1].index()] = ups[m - 2].half_edge(0).0;
        st.cell_edge[INFINITE.index()] = ups[0].half_edge(1).0;
        for v in ups.into_iter().chain(downs) {
            self.place_vertex(v);
        }
    }

    /// The diagram of points on one line, given in order along it (at least
    /// two, distinct), and segments each joining chain points `k` and `k + 1`
    /// for `k` in `between`: a ladder in which every segment is one more rung
    /// between its endpoints (its separators are the perpendiculars there).
    /// Returns the point sites in chain order and the segment sites in the
    /// order of `between`.
    pub(super) fn start_collinear_with_segments(&mut self, chain: &[Point], between: &[usize]) -> (Vec<SiteId>, Vec<SiteId>) {
        let ids: Vec<SiteId> = chain.iter().map(|&p| self.add_site(p)).collect();
        let mut after: Vec<Option<SiteId>> = vec![None; chain.len()];
        let mut segment_sites = Vec::with_capacity(between.len());
        for &k in between {
            let e = self.add_segment_site(ids[k], ids[(k + 1).min(ids.len() - 1)]);
            segment_sites.push(e);
            if let Some(slot @ None) = after.get_mut(k) {
                *slot = Some(e);
            }
        }
        let mut sequence = Vec::with_capacity(ids.len() + between.len());
        for (k, &id) in ids.iter().enumerate() {
            sequence.push(id);
            sequence.extend(after[k]);
        }
        self.build_ladder(&sequence);
        (ids, segment_sites)
    }
}

/// All points on one line (at least two distinct): sort along the line,
/// merge repeats, and lay out the ladder of parallel bisectors directly, with
/// each segment (which joins two consecutive points: nothing lies inside a
/// segment) as one more rung between its endpoints. Returns the segments'
/// sites.
pub(super) fn start_all_collinear(
    points: &[Point],
    segments: &[[usize; 2]],
    diagram: &mut Construction,
    site_of: &mut [SiteId],
) -> Vec<SiteId> {
    let mut by_position: Vec<u32> = (0..points.len() as u32).collect();
    // Lexicographic order is an order along any line.
    by_position.sort_unstable_by(|&i, &j| {
        let (p, q) = (points[i as usize], points[j as usize]);
        p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
    });
    let mut chain: Vec<Point> = Vec::new();
    let mut chain_index = vec![0usize; points.len()];
    for &i in &by_position {
        let p = points[i as usize];
        if chain.last() != Some(&p) {
            chain.push(p);
        }
        chain_index[i as usize] = chain.len() - 1;
    }
    let between: Vec<usize> = segments.iter().map(|&[i, j]| chain_index[i].min(chain_index[j])).collect();
    let (ids, segment_sites) = diagram.start_collinear_with_segments(&chain, &between);
    for (i, s) in site_of.iter_mut().enumerate() {
        *s = ids[chain_index[i]];
    }
    segment_sites
}
