//! The nodes of a cover's walks grouped by the pixel (or vertex) they visit, and which pixels
//! are settled (all their visits in one merged cycle): the index both cycle-merging stages
//! (grid regions in [`super::merge`], discrete instances in `crate::discrete::merge`) keep.

use petgraph::unionfind::UnionFind;
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

/// No node (an open end while an exchange relinks two rings).
pub(crate) const NONE: u32 = u32::MAX;

/// The walks of a cover as rings of nodes, the state both cycle-merging stages change: node
/// `i` visits key `key[i]` (a pixel's or a vertex's index), `next`/`prev` link each walk's
/// nodes in a ring, `cycle` is the input walk of each node and a union-find over input walks
/// tells which are merged, with the nodes of each merged walk counted at its root. The index of
/// the input nodes per key ([`Visits`]) leaves out detour copies: each belongs to the merged
/// walk of the node it copies.
#[derive(Clone, Debug)]
pub(crate) struct Rings {
    pub(crate) key: Vec<u32>,
    pub(crate) next: Vec<u32>,
    pub(crate) prev: Vec<u32>,
    /// Input walk of each node (detour copies inherit their copy's).
    cycle: Vec<u32>,
    /// Union-find over input walks: petgraph's (roots are only compared, so which one a
    /// union keeps does not matter).
    cycles: UnionFind<u32>,
    /// Nodes per merged walk, kept at its union-find root.
    size: Vec<usize>,
    index: Visits,
    /// The number each input node has in walk order when [`Rings::by_key`] numbered the nodes
    /// by key (empty otherwise); detour copies have their own number in both.
    walk_order: Vec<u32>,
}

impl Rings {
    /// The rings of `walks` (each a closed walk of keys below `n`, none empty).
    pub(crate) fn new(walks: &[Vec<u32>], n: usize) -> Rings {
        let nodes: usize = walks.iter().map(Vec::len).sum();
        let mut r = Rings {
            key: Vec::with_capacity(nodes),
            next: Vec::with_capacity(nodes),
            prev: Vec::with_capacity(nodes),
            cycle: Vec::with_capacity(nodes),
            cycles: UnionFind::new(walks.len()),
            size: Vec::with_capacity(walks.len()),
            index: Visits::default(),
            walk_order: Vec::new(),
        };
        for (c, walk) in walks.iter().enumerate() {
            let first = r.key.len() as u32;
            let m = walk.len() as u32;
            for (k, &key) in walk.iter().enumerate() {
                let k = k as u32;
                r.key.push(key);
                r.next.push(first + (k + 1) % m);
                r.prev.push(first + (k + m - 1) % m);
                r.cycle.push(c as u32);
            }
            r.size.push(walk.len());
        }
        r.index = Visits::of(&r.key, n);
        r
    }

    /// The rings of `walks` as [`Rings::new`] makes them, but numbered by key (and by walk
    /// order at one key), so that nodes at nearby keys lie near each other in memory: a merge
    /// that sweeps the keys in order then touches memory in order (at 10^7 pixels, walk order
    /// made most node accesses cache misses). The merge's results do not change:
    /// [`Rings::precedes`] and [`Rings::walks`] still follow walk order, and the nodes at one
    /// key keep their order.
    pub(crate) fn by_key(walks: &[Vec<u32>], n: usize) -> Rings {
        let nodes: usize = walks.iter().map(Vec::len).sum();
        // A counting sort by key: start[p] is the first number of key p's nodes.
        let mut start = vec![0u32; n + 1];
        for &p in walks.iter().flatten() {
            start[p as usize + 1] += 1;
        }
        for p in 0..n {
            start[p + 1] += start[p];
        }
        let mut fill = start.clone();
        let number: Vec<u32> = walks
            .iter()
            .flatten()
            .map(|&p| {
                fill[p as usize] += 1;
                fill[p as usize] - 1
            })
            .collect();
        drop(fill);
        let mut r = Rings {
            key: vec![0; nodes],
            next: vec![0; nodes],
            prev: vec![0; nodes],
            cycle: vec![0; nodes],
            cycles: UnionFind::new(walks.len()),
            size: walks.iter().map(Vec::len).collect(),
            index: Visits {
                start,
                nodes: (0..nodes as u32).collect(),
                known_settled: vec![false; n],
            },
            walk_order: vec![0; nodes],
        };
        let mut first = 0;
        for (c, walk) in walks.iter().enumerate() {
            let m = walk.len();
            for (k, &key) in walk.iter().enumerate() {
                let node = number[first + k] as usize;
                r.key[node] = key;
                r.next[node] = number[first + (k + 1) % m];
                r.prev[node] = number[first + (k + m - 1) % m];
                r.cycle[node] = c as u32;
                r.walk_order[node] = (first + k) as u32;
            }
            first += m;
        }
        r
    }

    /// The number node `n` has in walk order (its own number unless [`Rings::by_key`] numbered
    /// the nodes).
    fn walk_number(&self, n: u32) -> u32 {
        self.walk_order.get(n as usize).copied().unwrap_or(n)
    }

    /// Whether node `a` comes before node `b` in walk order (input walks one after the other,
    /// then detour copies as they are made): the order merges break ties by.
    pub(crate) fn precedes(&self, a: u32, b: u32) -> bool {
        self.walk_number(a) < self.walk_number(b)
    }

    /// The number of nodes (detour copies included).
    pub(crate) fn len(&self) -> usize {
        self.key.len()
    }

    /// The input nodes at key `p`.
    pub(crate) fn visits(&self, p: usize) -> &[u32] {
        self.index.at(p)
    }

    /// The index of the input nodes per key.
    pub(crate) fn index(&self) -> &Visits {
        &self.index
    }

    /// Whether nodes `a` and `b` belong to the same input walk.
    pub(crate) fn same_input(&self, a: u32, b: u32) -> bool {
        self.cycle[a as usize] == self.cycle[b as usize]
    }

    /// The merged walk of `node` (its union-find root).
    pub(crate) fn root_of(&mut self, node: u32) -> u32 {
        self.cycles.find_mut(self.cycle[node as usize])
    }

    /// The number of nodes of the merged walk whose root is `root`.
    pub(crate) fn size(&self, root: u32) -> usize {
        self.size[root as usize]
    }

    /// Whether every visit of key `p` already lies in one merged walk (settledness only grows
    /// as walks merge).
    pub(crate) fn settled(&mut self, p: usize) -> bool {
        let (cycles, cycle) = (&mut self.cycles, &self.cycle);
        self.index
            .settled(p, |node| cycles.find_mut(cycle[node as usize]))
    }

    /// Reverses the ring through `start`.
    pub(crate) fn reverse(&mut self, start: u32) {
        let mut n = start;
        loop {
            let k = n as usize;
            std::mem::swap(&mut self.next[k], &mut self.prev[k]);
            n = self.next[k];
            if n == start {
                break;
            }
        }
    }

    /// Inserts, after `x`, a step to `z`, `z`'s ring walked forward back to `z` (a copy of
    /// `z`), and a step back to `x` (a copy of `x`), which joins the two rings; returns the
    /// copies (of `z`, of `x`). The caller then records the merge with [`Rings::merged`].
    pub(crate) fn detour(&mut self, x: u32, z: u32) -> (u32, u32) {
        let (xn, zp) = (self.next[x as usize], self.prev[z as usize]);
        let z_copy = self.key.len() as u32;
        let x_copy = z_copy + 1;
        for of in [z, x] {
            self.key.push(self.key[of as usize]);
            self.cycle.push(self.cycle[of as usize]);
            self.next.push(NONE);
            self.prev.push(NONE);
        }
        for (a, b) in [(x, z), (zp, z_copy), (z_copy, x_copy), (x_copy, xn)] {
            self.next[a as usize] = b;
            self.prev[b as usize] = a;
        }
        (z_copy, x_copy)
    }

    /// Records that the merged walks with roots `ra` and `rb` are one now, with `added` more
    /// nodes than the two had (a detour's two copies).
    pub(crate) fn merged(&mut self, ra: u32, rb: u32, added: usize) {
        let nodes = self.size[ra as usize] + self.size[rb as usize] + added;
        self.cycles.union(ra, rb);
        let root = self.cycles.find_mut(ra);
        self.size[root as usize] = nodes;
    }

    /// The rings as walks of keys, each from its first node in walk order (nodes left unlinked
    /// skipped).
    pub(crate) fn walks(&self) -> Vec<Vec<u32>> {
        let mut seen = vec![false; self.len()];
        let mut out = Vec::new();
        let mut by_walk_order: Vec<u32> = (0..self.len() as u32).collect();
        for (new, &old) in self.walk_order.iter().enumerate() {
            by_walk_order[old as usize] = new as u32;
        }
        for start in by_walk_order {
            if seen[start as usize] || self.next[start as usize] == NONE {
                continue;
            }
            let mut walk = Vec::new();
            let mut n = start;
            loop {
                seen[n as usize] = true;
                walk.push(self.key[n as usize]);
                n = self.next[n as usize];
                if n == start {
                    break;
                }
            }
            out.push(walk);
        }
        out
    }
}
