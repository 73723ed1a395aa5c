//! Separating violated odd-set constraints x(δ(S)) ≥ 1 of the matching LP exactly
//! (Padberg–Rao: minimum odd cuts of a Gomory–Hu tree per fractional component).

use super::*;
use crate::flow::FlowGraph;
use petgraph::unionfind::UnionFind;

/// Fractional components up to this size are separated exactly (Gomory–Hu).
pub(super) const GOMORY_HU_LIMIT: usize = 400;

/// Odd sets S with x(δ(S)) < 1 (sorted, each once): per connected component C of the edges
/// with fractional x, C itself when |C| is odd, otherwise the violated odd sides of the
/// minimum cuts of a Gomory–Hu tree of C (Padberg–Rao: if some odd set inside C is
/// violated, one of those is). A vertex of C has no edge at 1, so x(δ(S)) for S ⊆ C counts
/// only edges inside C, and a violated odd set anywhere has a violated odd part in one C.
pub(super) fn violated_odd_sets(
    p: usize,
    edges: &[(usize, usize, u32)],
    x: &[f64],
) -> Vec<Vec<usize>> {
    let mut uf = UnionFind::<usize>::new(p);
    let fractional: Vec<usize> = (0..edges.len())
        .filter(|&k| x[k] > TOL && x[k] < 1.0 - TOL)
        .collect();
    for &k in &fractional {
        let (a, b, _) = edges[k];
        uf.union(a, b);
    }
    let mut members: HashMap<usize, Vec<usize>> = HashMap::new();
    let mut arcs: HashMap<usize, Vec<(usize, usize, f64)>> = HashMap::new();
    for &k in &fractional {
        let (a, b, _) = edges[k];
        let r = uf.find_mut(a);
        arcs.entry(r).or_default().push((a, b, x[k]));
        for v in [a, b] {
            members.entry(r).or_default().push(v);
        }
    }
    let mut sets: Vec<Vec<usize>> = Vec::new();
    for (r, mut c) in members {
        c.sort_unstable();
        c.dedup();
        if c.len() % 2 == 1 {
            sets.push(c);
        } else if c.len() <= GOMORY_HU_LIMIT {
            sets.extend(odd_min_cuts(&c, &arcs[&r]));
        }
    }
    for s in &mut sets {
        s.sort_unstable();
    }
    sets.sort_unstable();
    sets.dedup();
    sets
}

/// The odd shores of value below 1 of the fundamental cuts of a Gomory–Hu cut tree (Gusfield's
/// algorithm) of the graph on `vertices` with capacities `arcs`.
pub(super) fn odd_min_cuts(vertices: &[usize], arcs: &[(usize, usize, f64)]) -> Vec<Vec<usize>> {
    let n = vertices.len();
    let local = |v: usize| vertices.binary_search(&v).expect("a member");
    let local_arcs: Vec<(usize, usize, f64)> = arcs
        .iter()
        .map(|&(a, b, c)| (local(a), local(b), c))
        .collect();
    let mut graph = FlowGraph::new(n, &local_arcs);
    let mut side = vec![false; n];
    let mut parent = vec![0usize; n];
    let mut value = vec![0.0f64; n];
    for s in 1..n {
        let t = parent[s];
        let f = graph.max_flow(s, t, f64::INFINITY, &mut side);
        value[s] = f;
        for i in 0..n {
            if i != s && side[i] && parent[i] == t {
                parent[i] = s;
            }
        }
        if side[parent[t]] {
            parent[s] = parent[t];
            parent[t] = s;
            value[s] = value[t];
            value[t] = f;
        }
    }
    // The tree: edge (v, parent[v]) of value value[v] for every v but the root.
    let mut tree: Vec<Vec<usize>> = vec![Vec::new(); n];
    for v in 0..n {
        if parent[v] != v {
            tree[v].push(parent[v]);
            tree[parent[v]].push(v);
        }
    }
    let mut found = Vec::new();
    for v in 0..n {
        let u = parent[v];
        if u == v || value[v] >= 1.0 - TOL {
            continue;
        }
        // The shore of v: what v reaches in the tree without the edge (v, u).
        let mut shore = vec![false; n];
        shore[v] = true;
        let mut stack = vec![v];
        while let Some(a) = stack.pop() {
            for &b in &tree[a] {
                if !shore[b] && (a != v || b != u) {
                    shore[b] = true;
                    stack.push(b);
                }
            }
        }
        let size = shore.iter().filter(|&&b| b).count();
        if size % 2 == 1 {
            let small = 2 * size <= n;
            found.push(
                (0..n)
                    .filter(|&i| shore[i] == small)
                    .map(|i| vertices[i])
                    .collect(),
            );
        }
    }
    found
}
