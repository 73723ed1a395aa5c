//! A minimum-weight perfect matching of vertices in a graph metric, split at the graph's cut
//! vertices: one small solve per block instead of one large solve.
//!
//! # Why the split is exact
//! Let T be the vertices to match (the defects) in a graph G with nonnegative edge weights.
//! The minimum weight of a perfect matching of T in G's shortest-path metric equals the
//! minimum weight of a T-join of G (Edmonds–Johnson: the paths of a matching form a T-join,
//! and a minimum T-join is a forest that splits into |T|/2 edge-disjoint paths between the
//! vertices of T).
//!
//! A block of G is a maximal 2-connected subgraph or a bridge; two blocks share at most one
//! vertex, a cut vertex, and the blocks and cut vertices form a tree. For a block B with its
//! top cut vertex u (towards the root of that tree) and any other vertex w of B, let the
//! hang of w be the vertices of T that B's removal leaves with w (w itself and everything
//! below it). Every T-join J meets B in a T_B-join, where w ≠ u is in T_B exactly when its
//! hang holds an odd number of vertices of T (the edges of J leaving that part all leave
//! through w, inside B) and u is in T_B exactly when that makes |T_B| even. So
//! min T-join(G) = Σ_B min T_B-join(B), and a shortest path between two vertices of B stays
//! in B: each block is an independent matching problem in its own metric, and the sum of
//! the blocks' dual sums is a lower bound for G.
//!
//! # Putting the blocks' matchings together
//! The pairs of all blocks form a forest H on the vertices (a cycle of H would have to pass
//! a cut vertex twice within one block, where it has one pair), in which a vertex has odd
//! degree exactly when it is in T. Rooted, every subtree of H hanging from an edge holds an
//! odd number of vertices of T, so pairing, bottom up, the open vertices of T at each vertex
//! of H leaves exactly one to pass up each edge: the pairs' paths in H are edge-disjoint,
//! and by the triangle inequality the matching weighs at most Σ_B of the blocks' matchings.
//! With every block solved minimum, it is minimum; the caller recounts it in any case.

use std::cmp::Reverse;

/// One block of the graph: its edges (indices into the caller's edge list) and vertices,
/// and the vertices a T-join must have odd degree at within it.
pub(super) struct Block {
    pub(super) edges: Vec<usize>,
    pub(super) vertices: Vec<usize>,
    pub(super) defects: Vec<usize>,
}

/// The blocks of the graph on `0..vertices` with `edges` that have defects to match (loops
/// are left out; a loop is never on a shortest path). `None` when a connected component
/// holds an odd number of defects (no perfect matching exists).
pub(super) fn blocks_with_defects(
    vertices: usize,
    edges: &[(usize, usize, isize)],
    is_defect: &[bool],
) -> Option<Vec<Block>> {
    const UNSEEN: u32 = u32::MAX;
    let (start, adjacent) = adjacency(vertices, edges);
    let mut disc = vec![UNSEEN; vertices];
    let mut low = vec![0u32; vertices];
    let mut hang: Vec<u32> = is_defect.iter().map(|&d| u32::from(d)).collect();
    let mut stamp = vec![usize::MAX; vertices];
    let mut edge_stack: Vec<usize> = Vec::new();
    let mut blocks = Vec::new();
    let mut time = 0u32;
    let mut popped = 0usize;
    // Depth-first frames: vertex, the edge it was reached by, the next adjacency to try.
    let mut frames: Vec<(usize, usize, usize)> = Vec::new();
    for root in 0..vertices {
        if disc[root] != UNSEEN {
            continue;
        }
        disc[root] = time;
        low[root] = time;
        time += 1;
        frames.push((root, usize::MAX, start[root]));
        while let Some(frame) = frames.last_mut() {
            let (v, by, next) = *frame;
            if next < start[v + 1] {
                frame.2 += 1;
                let (w, e) = adjacent[next];
                if e == by {
                    continue;
                }
                if disc[w] == UNSEEN {
                    edge_stack.push(e);
                    disc[w] = time;
                    low[w] = time;
                    time += 1;
                    frames.push((w, e, start[w]));
                } else if disc[w] < disc[v] {
                    // A back edge, met first from its lower end.
                    edge_stack.push(e);
                    low[v] = low[v].min(disc[w]);
                }
                continue;
            }
            frames.pop();
            let Some(&(u, _, _)) = frames.last() else {
                if hang[v] % 2 == 1 {
                    return None;
                }
                continue;
            };
            low[u] = low[u].min(low[v]);
            if low[v] < disc[u] {
                continue;
            }
            // u separates the block ending with the edge `by` from the root.
            popped += 1;
            let id = popped;
            let mut block = Block {
                edges: Vec::new(),
                vertices: vec![u],
                defects: Vec::new(),
            };
            stamp[u] = id;
            while let Some(e) = edge_stack.pop() {
                block.edges.push(e);
                for x in [edges[e].0, edges[e].1] {
                    if stamp[x] != id {
                        stamp[x] = id;
                        block.vertices.push(x);
                    }
                }
                if e == by {
                    break;
                }
            }
            let mut below = 0u32;
            for &w in &block.vertices[1..] {
                below += hang[w];
                if hang[w] % 2 == 1 {
                    block.defects.push(w);
                }
            }
            hang[u] += below;
            if below % 2 == 1 {
                block.defects.push(u);
            }
            if !block.defects.is_empty() {
                blocks.push(block);
            }
        }
    }
    Some(blocks)
}

/// Compressed adjacency: the neighbours of v, with the edge to each, are
/// `adjacent[start[v]..start[v + 1]]`.
fn adjacency(
    vertices: usize,
    edges: &[(usize, usize, isize)],
) -> (Vec<usize>, Vec<(usize, usize)>) {
    let mut start = vec![0usize; vertices + 1];
    for &(a, b, _) in edges.iter().filter(|e| e.0 != e.1) {
        start[a + 1] += 1;
        start[b + 1] += 1;
    }
    for v in 0..vertices {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut adjacent = vec![(0, 0); start[vertices]];
    for (e, &(a, b, _)) in edges.iter().enumerate().filter(|(_, e)| e.0 != e.1) {
        adjacent[fill[a]] = (b, e);
        fill[a] += 1;
        adjacent[fill[b]] = (a, e);
        fill[b] += 1;
    }
    (start, adjacent)
}

/// Joins the blocks' matchings `pairs` (all blocks together, on the vertices `0..vertices`)
/// into one perfect matching of the defects (see the module docs). `None` if the pairs do
/// not form such a forest.
pub(super) fn join_block_matchings(
    vertices: usize,
    pairs: &[(usize, usize)],
    is_defect: &[bool],
) -> Option<Vec<(usize, usize)>> {
    let as_edges: Vec<(usize, usize, isize)> = pairs.iter().map(|&(a, b)| (a, b, 0)).collect();
    let (start, adjacent) = adjacency(vertices, &as_edges);
    let mut parent = vec![usize::MAX; vertices];
    let mut seen = vec![false; vertices];
    let mut order = Vec::new();
    let mut out = Vec::with_capacity(pairs.len());
    let mut carry: Vec<Option<usize>> = vec![None; vertices];
    let mut stack = Vec::new();
    for root in 0..vertices {
        if seen[root] || start[root] == start[root + 1] {
            continue;
        }
        order.clear();
        seen[root] = true;
        stack.push(root);
        while let Some(v) = stack.pop() {
            order.push(v);
            for &(w, _) in &adjacent[start[v]..start[v + 1]] {
                if w == parent[v] {
                    continue;
                }
                if seen[w] {
                    return None;
                }
                seen[w] = true;
                parent[w] = v;
                stack.push(w);
            }
        }
        // Children before parents.
        for &v in order.iter().rev() {
            let mut open: Vec<usize> = Vec::new();
            if is_defect[v] {
                open.push(v);
            }
            for &(w, _) in &adjacent[start[v]..start[v + 1]] {
                if parent[w] == v {
                    open.extend(carry[w]);
                }
            }
            // Deterministic: pair in order of vertex.
            open.sort_unstable_by_key(|&t| Reverse(t));
            while open.len() >= 2 {
                let (a, b) = (open.pop()?, open.pop()?);
                out.push((a, b));
            }
            carry[v] = open.pop();
            if v == root && carry[v].is_some() {
                return None;
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::matching::min_weight_perfect_matching;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// All-pairs shortest paths by Floyd–Warshall (small graphs only).
    fn distances(n: usize, edges: &[(usize, usize, isize)]) -> Vec<Vec<i64>> {
        let inf = i64::MAX / 4;
        let mut d = vec![vec![inf; n]; n];
        for (v, row) in d.iter_mut().enumerate() {
            row[v] = 0;
        }
        for &(a, b, w) in edges {
            d[a][b] = d[a][b].min(w as i64);
            d[b][a] = d[b][a].min(w as i64);
        }
        for k in 0..n {
            for i in 0..n {
                for j in 0..n {
                    d[i][j] = d[i][j].min(d[i][k] + d[k][j]);
                }
            }
        }
        d
    }

    /// A minimum perfect matching of `set` under the distances `d`, by blossom on the
    /// complete graph: its pairs and weight.
    fn minimum(set: &[usize], d: &[Vec<i64>]) -> (Vec<(usize, usize)>, i64) {
        let k = set.len();
        let mut complete = Vec::new();
        for i in 0..k {
            for j in i + 1..k {
                complete.push((i, j, d[set[i]][set[j]] as u32));
            }
        }
        let mate = min_weight_perfect_matching(k, &complete).expect("a perfect matching");
        let pairs: Vec<(usize, usize)> = (0..k)
            .filter(|&i| i < mate[i])
            .map(|i| (set[i], set[mate[i]]))
            .collect();
        let weight = pairs.iter().map(|&(a, b)| d[a][b]).sum();
        (pairs, weight)
    }

    /// A random connected graph of small cycles and trees glued at vertices, with a few
    /// chords: many blocks of every size.
    fn random_graph(rng: &mut ChaCha8Rng) -> (usize, Vec<(usize, usize, isize)>) {
        let n = rng.random_range(2..40);
        let mut edges = Vec::new();
        for v in 1..n {
            let u = rng.random_range(0..v);
            edges.push((u, v, 2 * rng.random_range(1..5i32) as isize));
        }
        for _ in 0..rng.random_range(0..n / 3 + 1) {
            let (a, b) = (rng.random_range(0..n), rng.random_range(0..n));
            edges.push((a, b, 2 * rng.random_range(1..5i32) as isize));
        }
        (n, edges)
    }

    #[test]
    fn blockwise_matching_weighs_the_complete_minimum() {
        let mut rng = ChaCha8Rng::seed_from_u64(16);
        let mut split = 0;
        for _ in 0..400 {
            let (n, edges) = random_graph(&mut rng);
            let mut defects: Vec<usize> = (0..n).filter(|_| rng.random_bool(0.5)).collect();
            if defects.len() % 2 == 1 {
                defects.pop();
            }
            let mut is_defect = vec![false; n];
            for &v in &defects {
                is_defect[v] = true;
            }
            let d = distances(n, &edges);
            let blocks = blocks_with_defects(n, &edges, &is_defect).expect("connected, even");
            split += usize::from(blocks.len() > 1);
            // Each block by brute force in its own metric (its own edges only).
            let mut pairs = Vec::new();
            let mut sum = 0i64;
            for b in &blocks {
                let own: Vec<(usize, usize, isize)> = b.edges.iter().map(|&e| edges[e]).collect();
                let (own_pairs, own_sum) = minimum(&b.defects, &distances(n, &own));
                pairs.extend(own_pairs);
                sum += own_sum;
            }
            let joined = join_block_matchings(n, &pairs, &is_defect).expect("a forest");
            let mut covered: Vec<usize> = joined.iter().flat_map(|&(a, b)| [a, b]).collect();
            covered.sort_unstable();
            assert_eq!(covered, defects, "every defect matched once");
            let weight: i64 = joined.iter().map(|&(a, b)| d[a][b]).sum();
            let (_, best) = minimum(&defects, &d);
            assert_eq!(sum, best, "the blocks' minima add up to the minimum");
            assert_eq!(weight, best, "the joined matching is minimum");
        }
        assert!(
            split > 200,
            "most graphs split into several blocks ({split})"
        );
    }

    #[test]
    fn an_odd_component_has_no_matching() {
        let edges = [(0, 1, 2), (2, 3, 2)];
        assert!(blocks_with_defects(4, &edges, &[true, true, true, false]).is_none());
        assert!(blocks_with_defects(4, &edges, &[true, true, true, true]).is_some());
    }
}
