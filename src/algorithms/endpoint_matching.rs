//! Minimum-weight perfect matching of endpoints under the turn distance (Theorem 4.1 and the
//! proof of Theorem 5.5 of *Optimal covering tours with turn costs*).
//!
//! The matching itself is rustworkx-core's blossom algorithm (`max_weight_matching` with
//! maximum cardinality and weights `BIG − w`, so that among perfect matchings the heaviest is
//! the lightest under `w`), run separately on each connected piece of the candidate graph.
//!
//! # Candidate pairs
//! With at most [`COMPLETE_LIMIT`] endpoints every reachable pair is a candidate: the matching
//! is then the exact minimum over all perfect matchings, which is what Theorems 4.1 and 5.5
//! need (certificate `matching_complete = 1`).
//!
//! Larger instances are our choice for speed, and lose the proof of minimality: blossom is
//! cubic, so one piece of 10⁴ endpoints already takes minutes. The endpoint pairs (an
//! endpoint and its partner, the other end of its strip or link) are sorted along a Z-order
//! curve of their pixels and cut into tiles of [`TILE`] endpoints; each tile is matched on
//! its own, with, for each endpoint, the endpoints of its tile met by its 0-1 BFS up to the end
//! of the first turn level at which [`NEAR`] of them were found (at most [`MAX_TURNS`] turns),
//! plus its partner, so that a perfect matching always exists. It misses pairs across tiles
//! and pairs farther than an endpoint's nearest; the tests measure the loss against the
//! complete graph.

use crate::algorithms::turn_distance::{Port, TurnSearch, bit};
use crate::error::{Error, Result};
use crate::region::Region;
use rustworkx_core::max_weight_matching::max_weight_matching;
use rustworkx_core::petgraph::graph::UnGraph;
use std::collections::HashMap;

/// Up to this many endpoints, the candidate graph is complete (the matching is exact).
pub const COMPLETE_LIMIT: usize = 600;

/// Larger instances keep, per endpoint, at least this many nearest endpoints (in turns).
pub const NEAR: usize = 12;

/// Larger instances are matched in tiles of about this many endpoints.
pub const TILE: usize = 1000;

/// Larger instances look for candidates at most this many turns away.
pub const MAX_TURNS: u32 = 6;

/// Interleaves the bits of two 32-bit coordinates (a Z-order key).
fn z_order(x: u32, y: u32) -> u64 {
    let spread = |v: u32| {
        let mut v = u64::from(v);
        v = (v | (v << 16)) & 0x0000_ffff_0000_ffff;
        v = (v | (v << 8)) & 0x00ff_00ff_00ff_00ff;
        v = (v | (v << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
        v = (v | (v << 2)) & 0x3333_3333_3333_3333;
        (v | (v << 1)) & 0x5555_5555_5555_5555
    };
    spread(x) | (spread(y) << 1)
}

/// The tile of every endpoint: pairs (i, partner\[i\]) in Z-order, cut every [`TILE`] endpoints.
fn tiles(region: &Region, ports: &[Port], partner: &[usize]) -> Vec<u32> {
    let b = region.bbox();
    let key = |i: usize| {
        let p = region.pixel(ports[i].pixel.min(ports[partner[i]].pixel));
        z_order((p.x - b.min_x) as u32, (p.y - b.min_y) as u32)
    };
    let mut pairs: Vec<usize> = (0..ports.len()).filter(|&i| i < partner[i]).collect();
    pairs.sort_by_key(|&i| (key(i), i));
    let mut tile = vec![0u32; ports.len()];
    for (k, &i) in pairs.iter().enumerate() {
        let t = (2 * k / TILE) as u32;
        tile[i] = t;
        tile[partner[i]] = t;
    }
    tile
}

/// A perfect matching of endpoints.
#[derive(Clone, Debug)]
pub struct PortMatching {
    /// `mate[i]` is the endpoint matched to endpoint `i`.
    pub mate: Vec<usize>,
    /// The turn distance of every matched pair, by its smaller endpoint (`weight[i]` for
    /// `i < mate[i]`).
    pub weight: Vec<u32>,
    /// Total weight w(M).
    pub total: u64,
    /// Whether the candidate graph was complete (the matching is then provably minimum).
    pub complete: bool,
}

/// A minimum-weight perfect matching of `ports` under the turn distance.
///
/// `partner[i]` is an endpoint that `i` can always be matched to (the other end of its strip
/// or link; `partner` is an involution without fixed points). `floor[i]` is a least weight for
/// the pair (i, partner\[i\]): a one-pixel strip or link matched to itself closes a walk that
/// never moves, which the turn distance prices below the 4 turns such a walk counts.
///
/// # Complexity
/// Candidate search: O(P · N) for P ≤ [`COMPLETE_LIMIT`] endpoints, otherwise O(P · A) where
/// A is the area a BFS explores before meeting [`NEAR`] endpoints. Matching: O(P³) worst case
/// per connected piece of the candidate graph.
pub fn match_ports(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Result<PortMatching> {
    match_ports_with(region, ports, partner, floor, ports.len() <= COMPLETE_LIMIT)
}

/// [`match_ports`] with the candidate graph complete or tiled as asked.
pub fn match_ports_with(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    complete: bool,
) -> Result<PortMatching> {
    let p = ports.len();
    let mut at_pixel: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, port) in ports.iter().enumerate() {
        at_pixel.entry(port.pixel).or_default().push(i);
    }
    let tile = if complete {
        vec![0; p]
    } else {
        tiles(region, ports, partner)
    };
    let max_turns = if complete { u32::MAX } else { MAX_TURNS };
    let mut edges: HashMap<(usize, usize), u32> = HashMap::new();
    let mut search = TurnSearch::new(region);
    for (i, &port) in ports.iter().enumerate() {
        let mut found = 0usize;
        let add = |j: usize, d: u32, edges: &mut HashMap<(usize, usize), u32>| {
            let key = (i.min(j), i.max(j));
            let e = edges.entry(key).or_insert(d);
            *e = (*e).min(d);
        };
        search.run(region, port, max_turns, |pixel, heading, d| {
            if let Some(here) = at_pixel.get(&pixel) {
                for &j in here {
                    if j != i && tile[j] == tile[i] && ports[j].arrive() & bit(heading) != 0 {
                        add(j, d, &mut edges);
                        found += 1;
                    }
                }
            }
            !complete && found >= NEAR
        });
        let j = partner[i];
        let target = ports[j];
        if search.distance_to(target).is_none() {
            // Beyond where the search stopped: search again for the partner alone.
            search.run(region, port, u32::MAX, |p, h, _| {
                p == target.pixel && target.arrive() & bit(h) != 0
            });
        }
        let d = search.distance_to(target).ok_or_else(|| {
            Error::invalid(format!(
                "endpoint {i} cannot reach its partner {j}: the region is not connected there"
            ))
        })?;
        add(j, d, &mut edges);
        let e = edges.get_mut(&(i.min(j), i.max(j))).expect("just added");
        *e = (*e).max(floor[i]);
    }
    // Sorted, so that ties between minimum matchings are broken the same way on every run.
    let mut edges: Vec<(usize, usize, u32)> =
        edges.into_iter().map(|((a, b), w)| (a, b, w)).collect();
    edges.sort_unstable();
    let mate = min_weight_perfect_matching(p, &edges)
        .ok_or_else(|| Error::invalid("the endpoints have no perfect matching"))?;
    let lookup: HashMap<(usize, usize), u32> = edges.iter().map(|&(a, b, w)| ((a, b), w)).collect();
    let mut weight = vec![0; p];
    let mut total = 0u64;
    for i in 0..p {
        if i < mate[i] {
            weight[i] = lookup[&(i, mate[i])];
            total += u64::from(weight[i]);
        }
    }
    Ok(PortMatching {
        mate,
        weight,
        total,
        complete,
    })
}

/// A minimum-weight perfect matching of the graph on `0..n` with weighted `edges` (each
/// pair at most once), solved per connected component; `None` when none is perfect.
pub fn min_weight_perfect_matching(n: usize, edges: &[(usize, usize, u32)]) -> Option<Vec<usize>> {
    // Connected components by union-find.
    let mut root: Vec<usize> = (0..n).collect();
    fn find(root: &mut [usize], mut x: usize) -> usize {
        while root[x] != x {
            root[x] = root[root[x]];
            x = root[x];
        }
        x
    }
    for &(a, b, _) in edges {
        let (ra, rb) = (find(&mut root, a), find(&mut root, b));
        if ra != rb {
            root[ra] = rb;
        }
    }
    let mut piece_of_root: HashMap<usize, usize> = HashMap::new();
    let mut local = vec![0usize; n];
    let mut pieces: Vec<Vec<usize>> = Vec::new();
    for (v, slot) in local.iter_mut().enumerate() {
        let r = find(&mut root, v);
        let k = *piece_of_root.entry(r).or_insert_with(|| {
            pieces.push(Vec::new());
            pieces.len() - 1
        });
        *slot = pieces[k].len();
        pieces[k].push(v);
    }
    let mut piece_edges: Vec<Vec<(u32, u32, i128)>> = vec![Vec::new(); pieces.len()];
    let big = i128::from(edges.iter().map(|e| e.2).max().unwrap_or(0)) + 1;
    for &(a, b, w) in edges {
        let k = piece_of_root[&find(&mut root, a)];
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matching_is_minimum_and_perfect() {
        // A 4-cycle 0-1-2-3 with one heavy edge, and a separate pair 4-5.
        let edges = [(0, 1, 5), (1, 2, 1), (2, 3, 5), (3, 0, 1), (4, 5, 7)];
        let mate = min_weight_perfect_matching(6, &edges).unwrap();
        assert_eq!(mate, vec![3, 2, 1, 0, 5, 4]);
        // An odd piece has no perfect matching.
        assert!(min_weight_perfect_matching(3, &[(0, 1, 1), (1, 2, 1)]).is_none());
    }

    /// Brute force over all perfect matchings of a small weighted complete graph.
    fn brute(n: usize, w: &dyn Fn(usize, usize) -> u32) -> u32 {
        fn rec(left: &mut Vec<usize>, w: &dyn Fn(usize, usize) -> u32) -> u32 {
            if left.is_empty() {
                return 0;
            }
            let a = left.remove(0);
            let mut best = u32::MAX;
            for k in 0..left.len() {
                let b = left.remove(k);
                best = best.min(w(a, b) + rec(left, w));
                left.insert(k, b);
            }
            left.insert(0, a);
            best
        }
        rec(&mut (0..n).collect(), w)
    }

    /// How much the tiled candidate graph loses against the complete one (run with
    /// `cargo test --release --lib tiled_matching_loss -- --ignored --nocapture`).
    #[test]
    #[ignore = "a measurement, takes a minute"]
    fn tiled_matching_loss() {
        use crate::algorithms::strips_matching::strip_ports;
        use crate::generate::{Family, GenParams, generate};
        for (family, n) in [(Family::RandomSimple, 6000), (Family::RandomHoled, 4000)] {
            let mut params = GenParams::new(family, 3);
            params.n = Some(n);
            let region = generate(&params).unwrap().region;
            let cover = crate::strip_cover::strip_cover(&region);
            let (links, ports) = strip_ports(&region, &cover.strips);
            let partner: Vec<usize> = (0..ports.len()).map(|i| i ^ 1).collect();
            let floor: Vec<u32> = (0..ports.len())
                .map(|i| {
                    if links[i / 2].0 == links[i / 2].1 {
                        2
                    } else {
                        0
                    }
                })
                .collect();
            let tiled = match_ports_with(&region, &ports, &partner, &floor, false).unwrap();
            let full = match_ports_with(&region, &ports, &partner, &floor, true).unwrap();
            eprintln!(
                "{family:?} N = {}: {} ports, w(M) tiled {} vs complete {}",
                region.len(),
                ports.len(),
                tiled.total,
                full.total
            );
            assert!(full.total <= tiled.total);
        }
    }

    #[test]
    fn agrees_with_brute_force() {
        for seed in 0..30u64 {
            let n = 8;
            let w = |a: usize, b: usize| {
                let (a, b) = (a.min(b) as u64, a.max(b) as u64);
                ((a * 31 + b * 17 + seed * 13) % 7) as u32
            };
            let edges: Vec<(usize, usize, u32)> = (0..n)
                .flat_map(|a| (a + 1..n).map(move |b| (a, b, w(a, b))))
                .collect();
            let mate = min_weight_perfect_matching(n, &edges).unwrap();
            let total: u32 = (0..n).filter(|&i| i < mate[i]).map(|i| w(i, mate[i])).sum();
            assert_eq!(total, brute(n, &w), "seed {seed}");
        }
    }
}
