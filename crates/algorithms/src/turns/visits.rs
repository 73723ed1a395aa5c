//! The nodes of a cover's walks grouped by the pixel (or vertex) they visit, and which pixels
//! are settled (all their visits in one merged cycle): the index both cycle-merging stages
//! (grid regions in [`super::merge`], discrete instances in `crate::discrete::merge`) keep.

use std::ops::Range;

/// The input nodes at each key in compressed rows, with the keys known to be settled.
#[derive(Clone, Debug, Default)]
pub(crate) struct Visits {
    start: Vec<u32>,
    nodes: Vec<u32>,
    /// Keys known to be settled (settledness only grows as cycles merge, so a `true` is kept
    /// for good).
    known_settled: Vec<bool>,
}

impl Visits {
    /// The index of nodes `0..keys.len()`, node `i` at key `keys[i] < n`.
    pub(crate) fn of(keys: &[u32], n: usize) -> Visits {
        let mut start = vec![0u32; n + 1];
        for &p in keys {
            start[p as usize + 1] += 1;
        }
        for p in 0..n {
            start[p + 1] += start[p];
        }
        let mut fill = start.clone();
        let mut nodes = vec![0u32; keys.len()];
        for (node, &p) in keys.iter().enumerate() {
            nodes[fill[p as usize] as usize] = node as u32;
            fill[p as usize] += 1;
        }
        Visits {
            start,
            nodes,
            known_settled: vec![false; n],
        }
    }

    /// The nodes at key `p`.
    pub(crate) fn at(&self, p: usize) -> &[u32] {
        &self.nodes[self.range(p)]
    }

    /// The positions of key `p`'s nodes, for [`node`](Self::node) (a caller that mutates
    /// while it walks them).
    pub(crate) fn range(&self, p: usize) -> Range<usize> {
        self.start[p] as usize..self.start[p + 1] as usize
    }

    pub(crate) fn node(&self, k: usize) -> u32 {
        self.nodes[k]
    }

    /// Whether every visit of key `p` lies in one merged cycle, `root` giving a node's merged
    /// cycle.
    pub(crate) fn settled(&mut self, p: usize, mut root: impl FnMut(u32) -> u32) -> bool {
        if self.known_settled[p] {
            return true;
        }
        let range = self.range(p);
        let Some(&first) = self.nodes.get(range.start) else {
            return true;
        };
        let first = root(first);
        let settled = self.nodes[range].iter().all(|&node| root(node) == first);
        self.known_settled[p] = settled;
        settled
    }
}
