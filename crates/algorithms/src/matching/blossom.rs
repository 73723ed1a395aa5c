//! Exact minimum-weight perfect matching by the blossom algorithm (rustworkx-core), per
//! connected component.

use super::*;

/// A minimum-weight perfect matching of the graph on `0..n` with weighted `edges` (each
/// pair at most once), solved per connected component; `None` when none is perfect.
pub(crate) fn min_weight_perfect_matching(
    n: usize,
    edges: &[(usize, usize, u32)],
) -> Option<Vec<usize>> {
    // The crate's one component labelling of a plain graph (pieces in order of smallest node).
    let (piece, count) =
        crate::topology::graph_components(n, edges.iter().map(|&(a, b, _)| (a, b)));
    let mut local = vec![0usize; n];
    let mut pieces: Vec<Vec<usize>> = vec![Vec::new(); count];
    for (v, &k) in piece.iter().enumerate() {
        local[v] = pieces[k as usize].len();
        pieces[k as usize].push(v);
    }
    let mut piece_edges: Vec<Vec<(u32, u32, i128)>> = vec![Vec::new(); pieces.len()];
    let big = i128::from(edges.iter().map(|e| e.2).max().unwrap_or(0)) + 1;
    for &(a, b, w) in edges {
        let k = piece[a] as usize;
        piece_edges[k].push((local[a] as u32, local[b] as u32, big - i128::from(w)));
    }
    let mut mate = vec![usize::MAX; n];
    for (k, members) in pieces.iter().enumerate() {
        if members.len() % 2 == 1 {
            return None;
        }
        let mut g: UnGraph<(), i128> = UnGraph::with_capacity(members.len(), piece_edges[k].len());
        for _ in members {
            g.add_node(());
        }
        for &(a, b, w) in &piece_edges[k] {
            g.add_edge(a.into(), b.into(), w);
        }
        let pairs = max_weight_matching(&g, true, |e| Ok::<i128, ()>(*e.weight()), false).ok()?;
        for (a, b) in pairs {
            mate[members[a]] = members[b];
            mate[members[b]] = members[a];
        }
    }
    mate.iter().all(|&m| m != usize::MAX).then_some(mate)
}
