//! Euler circuits (Hierholzer's algorithm), once for every multigraph of the crate: the
//! grid multigraph on the pixels of a region, and multigraphs given by an edge list.
//!
//! The milling constructions of Sections 5–7 of *Lawn mowing and milling* build a connected
//! multigraph with even degrees (contours, strips, matchings, detours, doubled edges) and walk
//! it once: the closed walk visits every pixel that has an edge and uses every edge once, so
//! its length is the number of edges. The exact solvers walk the edge multiset of an integer
//! solution the same way, and Christofides' lawn tour shortcuts the circuit of its tree plus
//! matching.

use crate::region::{Dir, Pixel, Region};
use crate::tour::Walk;

/// Hierholzer's algorithm on any multigraph: `take(v)` removes one unused edge at `v` and
/// returns its other end, or `None` when `v` has none left. Returns the closed trail through
/// the edges reachable from `start` in the order the algorithm finishes its vertices: the trail
/// reversed, `start` at both ends (just `[start]` when `start` has no edge).
///
/// # Complexity
/// O(number of edges) calls of `take`; O(number of edges) extra space.
pub fn hierholzer(start: usize, mut take: impl FnMut(usize) -> Option<usize>) -> Vec<usize> {
    let mut finished = Vec::new();
    let mut stack = vec![start];
    while let Some(&v) = stack.last() {
        match take(v) {
            Some(w) => stack.push(w),
            None => {
                finished.push(v);
                stack.pop();
            }
        }
    }
    finished
}

/// Hierholzer's order on an edge-list multigraph: `edges[k] = (a, b)` has `mult[k]` copies and
/// each vertex tries its edges in list order. Returns what [`hierholzer`] returns.
fn edge_list_trail(n: usize, edges: &[(usize, usize)], mult: &[u32], start: usize) -> Vec<usize> {
    let mut adj: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    let mut left: Vec<u32> = mult.to_vec();
    for (k, &(a, b)) in edges.iter().enumerate() {
        if mult[k] > 0 {
            adj[a].push((b, k));
            adj[b].push((a, k));
        }
    }
    let mut next = vec![0usize; n];
    hierholzer(start, |v| {
        while next[v] < adj[v].len() && left[adj[v][next[v]].1] == 0 {
            next[v] += 1;
        }
        let &(w, k) = adj[v].get(next[v])?;
        left[k] -= 1;
        Some(w)
    })
}

/// A closed walk through every edge copy of a connected multigraph (Hierholzer's algorithm).
///
/// `edges[k] = (a, b)` appears `mult[k]` times. Returns the vertex sequence of the closed walk
/// (its length is the total multiplicity), starting at `start`. Every vertex must have even
/// degree and the edges with positive multiplicity must form one connected graph containing
/// `start`.
pub fn euler_walk(n: usize, edges: &[(usize, usize)], mult: &[u32], start: usize) -> Vec<usize> {
    let mut walk = edge_list_trail(n, edges, mult, start);
    walk.reverse();
    walk.pop();
    walk
}

/// The Euler circuit from node 0 of a connected multigraph with even degrees (given by its
/// edges), shortcut to a Hamiltonian tour by skipping repeated nodes.
pub fn euler_shortcut(n: usize, edges: &[(usize, usize)]) -> Vec<usize> {
    let mut seen = vec![false; n];
    edge_list_trail(n, edges, &vec![1; edges.len()], 0)
        .into_iter()
        .filter(|&v| !std::mem::replace(&mut seen[v], true))
        .collect()
}

/// Edge multiplicities of a multigraph on the grid graph of a region: `mult[i][d]` copies of
/// the edge from pixel `i` in direction `d` (kept symmetric).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridMultigraph {
    mult: Vec<[u32; 4]>,
}

impl GridMultigraph {
    /// The empty multigraph on `n` pixels.
    pub fn new(n: usize) -> Self {
        GridMultigraph {
            mult: vec![[0; 4]; n],
        }
    }

    /// Copies of the edge from `i` in direction `d`.
    pub fn count(&self, i: usize, d: Dir) -> u32 {
        self.mult[i][d.index()]
    }

    /// Adds one copy of the edge from `i` to its neighbour `j` in direction `d`.
    pub fn add(&mut self, i: usize, j: usize, d: Dir) {
        self.mult[i][d.index()] += 1;
        self.mult[j][d.opposite().index()] += 1;
    }

    /// Removes one copy of the edge from `i` to `j` (direction `d`); false if there is none.
    pub fn remove(&mut self, i: usize, j: usize, d: Dir) -> bool {
        if self.mult[i][d.index()] == 0 {
            return false;
        }
        self.mult[i][d.index()] -= 1;
        self.mult[j][d.opposite().index()] -= 1;
        true
    }

    /// Replaces the edges at every pixel `i` with `pick(i)` by those of `other` (a multigraph
    /// on the same pixels). Stays symmetric when every edge between a picked and an unpicked
    /// pixel has the same count in both.
    pub fn copy_rows_from(&mut self, other: &GridMultigraph, pick: impl Fn(usize) -> bool) {
        for (i, (mine, theirs)) in self.mult.iter_mut().zip(&other.mult).enumerate() {
            if pick(i) {
                *mine = *theirs;
            }
        }
    }

    /// Adds the edges of `sub`, a multigraph on a sub-region whose pixel `i` is pixel `map[i]`
    /// here and whose edges are edges here too (a block of the region).
    pub fn add_rows_mapped(&mut self, sub: &GridMultigraph, map: &[usize]) {
        for (row, &g) in sub.mult.iter().zip(map) {
            for (mine, theirs) in self.mult[g].iter_mut().zip(row) {
                *mine += theirs;
            }
        }
    }

    /// Adds the edge between two adjacent pixels, looked up in `region`.
    pub fn add_between(&mut self, region: &Region, a: usize, b: usize) {
        let d = region
            .pixel(a)
            .dir_to(region.pixel(b))
            .expect("pixels are 4-adjacent");
        self.add(a, b, d);
    }

    /// Removes one copy of the edge between two adjacent pixels; false if there is none.
    pub fn remove_between(&mut self, region: &Region, a: usize, b: usize) -> bool {
        let d = region
            .pixel(a)
            .dir_to(region.pixel(b))
            .expect("pixels are 4-adjacent");
        self.remove(a, b, d)
    }

    /// Whether the edge between two adjacent pixels has at least one copy.
    pub fn has_between(&self, region: &Region, a: usize, b: usize) -> bool {
        let d = region
            .pixel(a)
            .dir_to(region.pixel(b))
            .expect("pixels are 4-adjacent");
        self.count(a, d) > 0
    }

    /// Adds every step of a closed walk of region pixels (wrap-around included).
    pub fn add_closed_walk(&mut self, region: &Region, walk: &[usize]) {
        if walk.len() < 2 {
            return;
        }
        for k in 0..walk.len() {
            self.add_between(region, walk[k], walk[(k + 1) % walk.len()]);
        }
    }

    /// Adds every step of an open path of region pixels.
    pub fn add_path(&mut self, region: &Region, path: &[usize]) {
        for w in path.windows(2) {
            self.add_between(region, w[0], w[1]);
        }
    }

    /// Degree of pixel `i` (with multiplicities); the tests' check of a multigraph.
    #[cfg(test)]
    fn degree(&self, i: usize) -> u32 {
        self.mult[i].iter().sum()
    }

    /// Total number of edges (with multiplicities); the tests' check of a multigraph.
    #[cfg(test)]
    fn edge_count(&self) -> u64 {
        self.mult.iter().map(|m| u64::from(m[0] + m[1])).sum()
    }

    /// An Euler circuit starting at `start` (Hierholzer's algorithm), as pixel indices
    /// without the closing repeat of `start`. Uses up the edges reachable from `start`; the
    /// caller guarantees even degrees and connectivity.
    ///
    /// # Complexity
    /// O(number of edges + N).
    pub fn euler_circuit(&mut self, region: &Region, start: usize) -> Vec<usize> {
        let mut circuit = hierholzer(start, |v| {
            let d = Dir::ALL.into_iter().find(|d| self.mult[v][d.index()] > 0)?;
            let w = region
                .neighbor(v, d)
                .expect("edges join pixels of the region");
            self.remove(v, w, d);
            Some(w)
        });
        if circuit.len() > 1 {
            circuit.pop();
        }
        circuit
    }

    /// The Euler circuit as a walk of pixels; a single pixel when there are no edges.
    pub fn into_walk(mut self, region: &Region, start: usize) -> Walk {
        self.euler_circuit(region, start)
            .into_iter()
            .map(|i| region.pixel(i))
            .collect::<Vec<Pixel>>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};
    use crate::tour::CycleCover;

    #[test]
    fn euler_circuit_of_two_squares_sharing_a_pixel() {
        let r = Region::from_ascii("##.\n###\n.##\n");
        let idx = |x, y| r.index_of(Pixel::new(x, y)).unwrap();
        let mut g = GridMultigraph::new(r.len());
        g.add_closed_walk(&r, &[idx(0, 1), idx(1, 1), idx(1, 2), idx(0, 2)]);
        g.add_closed_walk(&r, &[idx(1, 0), idx(2, 0), idx(2, 1), idx(1, 1)]);
        assert_eq!(g.edge_count(), 8);
        let walk = g.clone().into_walk(&r, idx(0, 1));
        let rep = check(&r, &CycleCover::tour(walk), Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!(rep.length, 8);
    }

    #[test]
    fn doubled_edge_is_a_back_and_forth() {
        let r = Region::rectangle(2, 1);
        let mut g = GridMultigraph::new(2);
        g.add(0, 1, Dir::E);
        g.add(0, 1, Dir::E);
        assert_eq!(g.degree(0), 2);
        assert_eq!(g.into_walk(&r, 0), vec![Pixel::new(0, 0), Pixel::new(1, 0)]);
    }
}
