//! The merge tree of a graph whose nodes and links have levels, for
//! questions of the form "which component of the links present at level
//! `r` holds node `x`", each in `O(log n)` after one `O(n log n)` build.
//!
//! The offsets at distance `r` separate regions of the plane where the
//! distance to the sites is above `r` from regions where it is below, and
//! their nesting follows from which region each loop borders. The regions
//! above `r` are the components of the diagram's vertices and edges that
//! lie wholly above it; those below, of the cells joined across edges that
//! dip below it. Both are a sweep over levels: links are added in the
//! order of their level (Kruskal), each merge of two components becomes a
//! tree node at that level, so along the path from a leaf to the root the
//! levels are monotone, and the component at level `r` is the highest
//! ancestor still present at `r`. Jump pointers (the skew-binary scheme of
//! Myers, 1983) find it in logarithmic time with one pointer per node.

/// A merge tree (see the module doc). Leaves are `0..leaves`; merges
/// follow, each after both its children.
#[derive(Clone, Debug, Default)]
pub(crate) struct LevelTree {
    parent: Vec<u32>,
    jump: Vec<u32>,
    level: Vec<f64>,
}

const ROOT: u32 = u32::MAX;

impl LevelTree {
    /// The tree of `leaves` nodes with the levels `leaf_level`, merged by
    /// `links` (`(a, b, level)`) in the order of their level: descending
    /// when `descending` (components of what lies above a level), else
    /// ascending.
    pub(crate) fn new(leaf_level: Vec<f64>, mut links: Vec<(u32, u32, f64)>, descending: bool) -> LevelTree {
        if descending {
            links.sort_unstable_by(|a, b| b.2.total_cmp(&a.2));
        } else {
            links.sort_unstable_by(|a, b| a.2.total_cmp(&b.2));
        }
        let leaves = leaf_level.len();
        let mut tree = LevelTree { parent: vec![ROOT; leaves], jump: Vec::new(), level: leaf_level };
        // union-find over leaves, each set knowing its current tree node
        let mut set: Vec<u32> = (0..leaves as u32).collect();
        let mut node_of: Vec<u32> = (0..leaves as u32).collect();
        fn find(set: &mut [u32], mut x: u32) -> u32 {
            while set[x as usize] != x {
                let up = set[set[x as usize] as usize];
                set[x as usize] = up;
                x = up;
            }
            x
        }
        for (a, b, level) in links {
            let (ra, rb) = (find(&mut set, a), find(&mut set, b));
            if ra == rb {
                continue;
            }
            let merged = tree.level.len() as u32;
            tree.level.push(level);
            tree.parent.push(ROOT);
            tree.parent[node_of[ra as usize] as usize] = merged;
            tree.parent[node_of[rb as usize] as usize] = merged;
            set[rb as usize] = ra;
            node_of[ra as usize] = merged;
        }
        tree.set_jumps();
        tree
    }

    /// Depths and jump pointers, parents first (a parent's index is higher
    /// than its children's).
    fn set_jumps(&mut self) {
        let n = self.parent.len();
        let mut depth = vec![0u32; n];
        self.jump = (0..n as u32).collect();
        for v in (0..n).rev() {
            let p = self.parent[v];
            if p == ROOT {
                continue;
            }
            let p = p as usize;
            depth[v] = depth[p] + 1;
            let (j, jj) = (self.jump[p] as usize, self.jump[self.jump[p] as usize] as usize);
            self.jump[v] = if depth[p] - depth[j] == depth[j] - depth[jj] { jj as u32 } else { p as u32 };
        }
    }

    /// The highest ancestor of leaf `x` whose level is `present` (a
    /// predicate that holds from the leaf up to some ancestor and not
    /// beyond): the component holding `x`. `x` itself when it is not
    /// present.
    pub(crate) fn component(&self, x: usize, present: impl Fn(f64) -> bool) -> usize {
        let mut x = x as u32;
        if !present(self.level[x as usize]) {
            return x as usize;
        }
        loop {
            let j = self.jump[x as usize];
            if j != x && present(self.level[j as usize]) {
                x = j;
                continue;
            }
            let p = self.parent[x as usize];
            if p != ROOT && present(self.level[p as usize]) {
                x = p;
            } else {
                return x as usize;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// The components by brute force: union of the links at or above `r`.
    fn components(n: usize, links: &[(u32, u32, f64)], present: impl Fn(f64) -> bool) -> Vec<usize> {
        let mut label: Vec<usize> = (0..n).collect();
        let mut changed = true;
        while changed {
            changed = false;
            for &(a, b, _) in links.iter().filter(|l| present(l.2)) {
                let m = label[a as usize].min(label[b as usize]);
                for x in [a, b] {
                    if label[x as usize] != m {
                        label[x as usize] = m;
                        changed = true;
                    }
                }
            }
        }
        label
    }

    #[test]
    fn components_agree_with_brute_force() {
        let mut rng = SplitMix64(3);
        for round in 0..40 {
            let n = 2 + round % 30;
            let links: Vec<(u32, u32, f64)> = (0..2 * n)
                .map(|_| {
                    let a = (rng.unit() * n as f64) as u32;
                    let b = (rng.unit() * n as f64) as u32;
                    (a, b, (rng.unit() * 10.0).floor())
                })
                .collect();
            for descending in [true, false] {
                let tree = LevelTree::new(
                    vec![if descending { f64::INFINITY } else { f64::NEG_INFINITY }; n],
                    links.clone(),
                    descending,
                );
                for r in 0..11 {
                    let r = r as f64;
                    let present = |l: f64| if descending { l >= r } else { l < r };
                    let want = components(n, &links, present);
                    let got: Vec<usize> = (0..n).map(|x| tree.component(x, present)).collect();
                    for a in 0..n {
                        for b in 0..n {
                            assert_eq!(want[a] == want[b], got[a] == got[b], "round {round} r {r} {a} {b}");
                        }
                    }
                }
            }
        }
    }
}
