//! Separation of connectivity cuts `x(δ(S)) >= 2` on a weighted support graph.
//!
//! Integer and fractional solutions are treated alike: first the connected components of the
//! support (a disconnected support violates the cut of each component by 2), then, on a
//! connected support, all minimum cuts of a Gomory–Hu tree by Gusfield's algorithm (n − 1
//! maximum flows, Dinic's algorithm in [`crate::flow`]), keeping every tree cut lighter than 2. On a
//! few thousand nodes exact separation is cheap next to an LP re-solve; on larger graphs it
//! stops at the solve's deadline with the cuts found so far.

use super::lp::{Deadline, Row};
use crate::flow::FlowGraph;
use crate::topology::graph_components;

/// The violated subtour cuts `x(δ(S)) >= 2` of a closed walk's edge multiplicities: column
/// `k` is the multiplicity of edge `edges[k]` of a graph on `n` nodes, `x` its LP value (the
/// length models of grids and of discrete instances, whose first columns are their edges).
pub fn subtour_rows(
    n: usize,
    edges: &[(usize, usize)],
    x: &[f64],
    deadline: &Deadline,
) -> Vec<Row> {
    let weighted: Vec<(usize, usize, f64)> =
        edges.iter().zip(x).map(|(&(a, b), &w)| (a, b, w)).collect();
    violated_cuts(n, &weighted, 2.0 - 1e-6, deadline)
        .into_iter()
        .map(|s| {
            let terms = (0..edges.len())
                .filter(|&k| s[edges[k].0] != s[edges[k].1])
                .map(|k| (k, 1.0));
            Row::at_least(terms, 2.0)
        })
        .collect()
}

/// The components of the nodes in `used` (of `n`) joined by `joined`, labelled 0, 1, ... in
/// the order of their first node, with their number; a node not in use is labelled
/// `u32::MAX`. The passage models' side (or port) graphs: a walk's support is one component.
pub fn used_components(n: usize, joined: Vec<(usize, usize)>, used: &[bool]) -> (Vec<u32>, usize) {
    let (raw, _) = graph_components(n, joined);
    let mut map = std::collections::HashMap::new();
    let label = (0..n)
        .map(|i| {
            if used[i] {
                let next = map.len() as u32;
                *map.entry(raw[i]).or_insert(next)
            } else {
                u32::MAX
            }
        })
        .collect();
    (label, map.len())
}

/// Node sets `S` (as membership vectors, never containing node 0 and never empty) whose cut
/// weight is below `threshold`, for a graph on `n` nodes with weighted edges.
///
/// Components of the positive-weight support come first; on a connected support, Gusfield's
/// algorithm yields a minimum cut for every pair of nodes (through the Gomory–Hu tree), and
/// each tree cut below the threshold is returned once.
pub fn violated_cuts(
    n: usize,
    edges: &[(usize, usize, f64)],
    threshold: f64,
    deadline: &Deadline,
) -> Vec<Vec<bool>> {
    if n < 2 {
        return Vec::new();
    }
    let support: Vec<(usize, usize, f64)> = edges.iter().copied().filter(|e| e.2 > 1e-9).collect();
    let (label, count) = graph_components(n, support.iter().map(|&(a, b, _)| (a, b)));
    let mut out: Vec<Vec<bool>> = Vec::new();
    if count > 1 {
        for c in 0..count as u32 {
            if c == label[0] {
                continue;
            }
            out.push(label.iter().map(|&l| l == c).collect());
        }
        if count > 2 {
            // The component of node 0 is cut too: its complement as S.
            out.push(label.iter().map(|&l| l != label[0]).collect());
        }
        return out;
    }
    let mut g = FlowGraph::new(n, &support);
    let mut parent = vec![0usize; n];
    let mut side = vec![false; n];
    let mut seen = std::collections::HashSet::new();
    for s in 1..n {
        // Up to N maximum flows (37 s at 20,000 pixels): past the deadline the cuts found so
        // far are returned. A partial separation only weakens the LP; every cut is valid.
        if s % 64 == 0 && deadline.expired() {
            break;
        }
        let t = parent[s];
        let f = g.max_flow(s, t, f64::INFINITY, &mut side);
        // Gusfield: later nodes on s's side with the same parent now hang below s.
        for v in s + 1..n {
            if side[v] && parent[v] == t {
                parent[v] = s;
            }
        }
        if f < threshold {
            // Normalize so that S excludes node 0.
            let cut: Vec<bool> = if side[0] {
                side.iter().map(|&b| !b).collect()
            } else {
                side.clone()
            };
            if seen.insert(cut.clone()) {
                out.push(cut);
            }
        }
    }
    out
}

/// The weight of the cut `S` in the given graph.
#[cfg(test)]
pub fn cut_weight(edges: &[(usize, usize, f64)], s: &[bool]) -> f64 {
    edges
        .iter()
        .filter(|&&(a, b, _)| s[a] != s[b])
        .map(|e| e.2)
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_give_zero_cuts() {
        let edges = [(0, 1, 1.0), (1, 2, 1.0), (2, 0, 1.0), (3, 4, 2.0)];
        let cuts = violated_cuts(5, &edges, 2.0 - 1e-6, &Deadline::new(None));
        assert_eq!(cuts, vec![vec![false, false, false, true, true]]);
    }

    #[test]
    fn min_cuts_of_two_triangles_joined_by_a_light_edge() {
        // Two triangles of weight-1 edges joined by two half edges: the cut between them is 1.
        let edges = [
            (0, 1, 1.0),
            (1, 2, 1.0),
            (2, 0, 1.0),
            (3, 4, 1.0),
            (4, 5, 1.0),
            (5, 3, 1.0),
            (0, 3, 0.5),
            (2, 5, 0.5),
        ];
        let cuts = violated_cuts(6, &edges, 2.0 - 1e-6, &Deadline::new(None));
        assert!(!cuts.is_empty());
        for c in &cuts {
            assert!(cut_weight(&edges, c) < 2.0 - 1e-6);
            assert!(!c[0]);
        }
        assert!(cuts.contains(&vec![false, false, false, true, true, true]));
        // A 2-edge-connected graph with all cuts >= 2 yields nothing.
        let ring: Vec<(usize, usize, f64)> = (0..6).map(|i| (i, (i + 1) % 6, 1.0)).collect();
        assert!(violated_cuts(6, &ring, 2.0 - 1e-6, &Deadline::new(None)).is_empty());
    }
}
