//! The minimum-weight perfect matching of the odd-degree nodes of the MST (Christofides), at
//! any size.
//!
//! # Which matching is used, and what is proven
//! - Up to [`COMPLETE_LIMIT`] odd nodes, any cutter: rustworkx-core's blossom
//!   (`max_weight_matching`) on the complete graph, exact integer weights (L1, or Euclidean
//!   lengths in micro-units): the minimum over all pairs (`matching_optimal = 1`).
//! - Square cutter (L1 motion), more odd nodes: the L1 distance between two points is the
//!   shortest-path distance in their Hanan grid (the grid of the lines through the points,
//!   edges weighted by the coordinate gaps: a monotone staircase along it has exactly the L1
//!   length, and no path is shorter). So a minimum-weight perfect matching of the odd nodes
//!   in that graph's metric IS one over ALL pairs under L1, which fusion-blossom (an exact
//!   primal–dual blossom algorithm growing its dual regions on the graph) solves. Its dual sum
//!   is a lower bound on every perfect matching; the matching is certified
//!   (`matching_optimal = 1`) when its recounted L1 weight reaches that bound, and if it did
//!   not (never seen) or fusion-blossom failed, the complete-graph blossom runs instead, at any
//!   size. So the square cutter's matching is always a proven minimum, and the registered
//!   αTSP = 3/2 holds on every run. Above [`HANAN_LIMIT`] grid vertices (sparse lawns: few
//!   points in a large box) the graph is the O(M log M) Manhattan spanner of a recursive
//!   median split instead ([`l1_spanner`], also exact for every pair).
//! - Beyond the exact solver's reach ([`exact_within_reach`]: more than [`SPANNER_ODD_LIMIT`]
//!   odd nodes and a Hanan grid above [`EXACT_GRID_LIMIT`] vertices), any cutter: the greedy
//!   near-minimum matching of [`near_minimum`] (`matching_optimal = 0`). Measured on gen
//!   lawn-scattered --n 1000000 --seed 1 (103,438 odd nodes): exact 83,122 in about 20 s and
//!   3.5 GB, greedy 93,726 (+12.8%) in well under a second; random-simple (72,144 odd nodes):
//!   57,329 against 63,845 (+11.4%). The Christofides tour grows by 0.97% and 0.62%; for the
//!   square cutter its 3/2 is then certified on the tour itself (`christofides` in the parent
//!   module), with the exact matching as the fallback.
//! - Euclidean motion (square-free, disk), more odd nodes: the L1-minimum matching (solved
//!   as above, on the pixels for square-free, on the hexagon centres in milli-units for the
//!   disk), improved by exchanging partners between near pairs under the Euclidean metric
//!   ([`exchange_pairs`]). It is perfect but NOT proven minimum over all pairs
//!   (`matching_optimal = 0`): the registry registers no Euclidean guarantee (the factors β
//!   and γ are irrational), and no αTSP = 3/2 is claimed for those runs. Its weight is at
//!   most √2 times the minimum (Euclidean ≤ L1 ≤ √2·Euclidean, and exchanges only lower
//!   it); the proven lower bound `matching_lower_bound` is the L1 solver's dual divided by
//!   √2, which leaves a gap of up to about 29% that measures the bound as much as the
//!   matching. (A fusion-blossom run in the metric of a nearest-neighbour graph with
//!   Euclidean weights, tried first, found matchings about 1% lighter but took 240 s and 4 GB at
//!   10⁵ pixels.)

use super::Points;
use crate::lawn_check::{Cutter, centre};
use crate::matching::graph_metric_matching;

/// Weighted edges (a, b, w) of a graph for fusion-blossom.
type Edges = Vec<(usize, usize, isize)>;

/// Up to this many odd nodes, blossom on the complete graph.
pub(super) const COMPLETE_LIMIT: usize = 400;

/// Above this many Hanan-grid vertices, the Manhattan spanner instead.
pub(super) const HANAN_LIMIT: usize = 4_000_000;

/// The most Hanan-grid vertices for which [`odd_matching`] solves the exact matching unasked.
/// fusion-blossom keeps about 0.9 KB per grid vertex: `solve --algo lawn-christofides` on
/// lawn-scattered 10^6 (103,438 odd nodes, a 4-million-vertex grid) took 30 s user and
/// 3.8 GB, of which the matching 20 s and 3.5 GB; on lawn-scattered 10^5 (17,200 odd nodes)
/// 1.7 s and 0.35 GB, still exact under this limit.
pub(super) const EXACT_GRID_LIMIT: usize = 1_000_000;

/// Up to this many odd nodes the exact matching is solved whatever the grid: the spanner route
/// grows fast (measured 9.1 GB for 72,144 odd nodes of random-simple 10^6, and 24 GB for
/// lawn-scattered's 103,438), but is small for sparse lawns of few odd nodes.
pub(super) const SPANNER_ODD_LIMIT: usize = 4000;

/// Candidate partners per odd node in [`near_minimum`]'s greedy rounds.
const GREEDY_NEAR: usize = 8;

/// Above this many odd nodes, fusion-blossom's partitioned solver (one thread, still exact).
const SERIAL_LIMIT: usize = 4000;

/// A perfect matching of the odd nodes, with what is proven about it.
pub(super) struct OddMatching {
    /// Matched pairs of point ids.
    pub(super) pairs: Vec<(usize, usize)>,
    /// Its weight in the motion's metric, in units.
    pub(super) weight: f64,
    /// Whether it is proven a minimum over all pairs.
    pub(super) optimal: bool,
    /// A proven lower bound on the minimum over all pairs, in units.
    pub(super) lower_bound: f64,
}

/// Whether the exact solver is within reach for `odd`: the complete graph up to
/// [`COMPLETE_LIMIT`] nodes, the Hanan grid up to [`EXACT_GRID_LIMIT`] vertices, the spanner up
/// to [`SPANNER_ODD_LIMIT`] nodes. Beyond, [`near_minimum`].
pub(super) fn exact_within_reach(p: &Points, odd: &[usize]) -> bool {
    if odd.len() <= COMPLETE_LIMIT || odd.len() <= SPANNER_ODD_LIMIT {
        return true;
    }
    let distinct = |f: &dyn Fn(usize) -> i64| {
        let mut v: Vec<i64> = odd.iter().map(|&i| f(i)).collect();
        v.sort_unstable();
        v.dedup();
        v.len()
    };
    let (w, h) = match p.cutter {
        Cutter::Square | Cutter::SquareFree => (
            distinct(&|i| i64::from(p.pts[i].x)),
            distinct(&|i| i64::from(p.pts[i].y)),
        ),
        // The disk's L1 matching runs on the hexagon centres in milli-units.
        Cutter::Disk => (
            distinct(&|i| (centre(p.cutter, p.pts[i]).0 * 1000.0).floor() as i64),
            distinct(&|i| (centre(p.cutter, p.pts[i]).1 * 1000.0).floor() as i64),
        ),
    };
    w.checked_mul(h).is_some_and(|v| v <= EXACT_GRID_LIMIT)
}

/// A perfect matching of `odd`, an even set of point ids: the minimum when
/// [`exact_within_reach`] (square cutter: always proven; Euclidean: proven up to
/// [`COMPLETE_LIMIT`] odd nodes), else the near-minimum one of [`near_minimum`] (not proven;
/// the caller certifies the tour instead, see `christofides`).
pub(super) fn odd_matching(p: &Points, odd: &[usize]) -> OddMatching {
    if exact_within_reach(p, odd) {
        minimum_matching(p, odd)
    } else {
        near_minimum(p, odd)
    }
}

/// A minimum (square cutter: always proven; Euclidean: proven up to [`COMPLETE_LIMIT`] odd
/// nodes) perfect matching of `odd`, an even set of point ids, at any size.
pub(super) fn minimum_matching(p: &Points, odd: &[usize]) -> OddMatching {
    let weight_of = |pairs: &[(usize, usize)]| pairs.iter().map(|&(a, b)| p.dist(a, b)).sum();
    if odd.len() <= COMPLETE_LIMIT {
        return complete(p, odd);
    }
    match p.cutter {
        Cutter::Square => {
            let xy: Vec<(i64, i64)> = odd
                .iter()
                .map(|&i| (i64::from(p.pts[i].x), i64::from(p.pts[i].y)))
                .collect();
            if let Some((pairs, dual)) = l1_matching(&xy) {
                let pairs: Vec<(usize, usize)> =
                    pairs.into_iter().map(|(a, b)| (odd[a], odd[b])).collect();
                let weight: f64 = weight_of(&pairs);
                // Weights are twice the gaps: the dual sum bounds twice the minimum.
                let lower = ((dual + 1) / 2) as f64;
                if weight <= lower {
                    return OddMatching {
                        pairs,
                        weight,
                        optimal: true,
                        lower_bound: lower,
                    };
                }
            }
            complete(p, odd)
        }
        Cutter::SquareFree | Cutter::Disk => euclidean(p, odd).unwrap_or_else(|| complete(p, odd)),
    }
}

/// Blossom on the complete graph of the odd nodes: exact.
fn complete(p: &Points, odd: &[usize]) -> OddMatching {
    let mut graph =
        petgraph::graph::UnGraph::<(), i128>::with_capacity(odd.len(), odd.len() * odd.len() / 2);
    for _ in odd {
        graph.add_node(());
    }
    // Exact integer weights: L1 lengths, or Euclidean lengths in micro-units.
    let weight = |a: usize, b: usize| -> i128 {
        match p.cutter {
            Cutter::Square => i128::from(p.key(a, b) as i64),
            _ => (p.dist(a, b) * 1e6).round() as i128,
        }
    };
    let big: i128 = 1 << 60;
    for x in 0..odd.len() {
        for y in x + 1..odd.len() {
            graph.add_edge(
                petgraph::graph::NodeIndex::new(x),
                petgraph::graph::NodeIndex::new(y),
                big - weight(odd[x], odd[y]),
            );
        }
    }
    let mut pairs: Vec<(usize, usize)> = rustworkx_core::max_weight_matching::max_weight_matching(
        &graph,
        true,
        |e: petgraph::graph::EdgeReference<i128>| Ok::<i128, std::convert::Infallible>(*e.weight()),
        false,
    )
    .map(|set| {
        set.into_iter()
            .map(|(x, y)| (odd[x.min(y)], odd[x.max(y)]))
            .collect()
    })
    .unwrap_or_default();
    // Sorted, so that the tour does not depend on the hash set's iteration order.
    pairs.sort_unstable();
    let weight: f64 = pairs.iter().map(|&(a, b)| p.dist(a, b)).sum();
    OddMatching {
        pairs,
        weight,
        optimal: true,
        lower_bound: weight,
    }
}

/// A minimum-weight perfect matching of integer points under L1, over all pairs, by
/// fusion-blossom on their Hanan grid (or the Manhattan spanner when the grid is too large):
/// pairs of indices into `xy` and the dual sum (a lower bound on twice the minimum).
fn l1_matching(xy: &[(i64, i64)]) -> Option<(Vec<(usize, usize)>, i64)> {
    let mut xs: Vec<i64> = xy.iter().map(|q| q.0).collect();
    let mut ys: Vec<i64> = xy.iter().map(|q| q.1).collect();
    xs.sort_unstable();
    xs.dedup();
    ys.sort_unstable();
    ys.dedup();
    let (w, h) = (xs.len(), ys.len());
    let gap = |d: i64| isize::try_from(2 * d).ok();
    if w.checked_mul(h).is_some_and(|v| v <= HANAN_LIMIT) {
        let mut edges = Vec::with_capacity(2 * w * h);
        for iy in 0..h {
            for ix in 0..w {
                let v = iy * w + ix;
                if ix + 1 < w {
                    edges.push((v, v + 1, gap(xs[ix + 1] - xs[ix])?));
                }
                if iy + 1 < h {
                    edges.push((v, v + w, gap(ys[iy + 1] - ys[iy])?));
                }
            }
        }
        let defects: Vec<usize> = xy
            .iter()
            .map(|q| {
                let ix = xs.binary_search(&q.0).expect("listed");
                let iy = ys.binary_search(&q.1).expect("listed");
                iy * w + ix
            })
            .collect();
        graph_metric_matching(w * h, edges, &defects, SERIAL_LIMIT, |v| {
            ((v % w) as i32, (v / w) as i32)
        })
    } else {
        let (vertices, edges) = l1_spanner(xy)?;
        let defects: Vec<usize> = (0..xy.len()).collect();
        graph_metric_matching(vertices, edges, &defects, usize::MAX, |_| (0, 0))
    }
}

/// A graph on the points `0..M` of `xy` (distinct) plus Steiner points whose shortest-path
/// distance between any two of the points is twice their L1 distance (edge weights are twice
/// the lengths): split the points at the median x, hang every point horizontally from its
/// projection on the median line, chain the projections along it, and recurse on both
/// halves. Two points on either side of the line are joined by a monotone path through their
/// projections (exactly their L1 distance); two on one side, by the recursion. O(M log M)
/// vertices and edges.
pub(super) fn l1_spanner(xy: &[(i64, i64)]) -> Option<(usize, Edges)> {
    let mut order: Vec<usize> = (0..xy.len()).collect();
    order.sort_unstable_by_key(|&i| (xy[i], i));
    let mut edges: Vec<(usize, usize, isize)> = Vec::new();
    let mut vertices = xy.len();
    // Ranges of `order` to split, as an explicit stack.
    let mut stack = vec![(0usize, order.len())];
    while let Some((lo, hi)) = stack.pop() {
        if hi - lo < 2 {
            continue;
        }
        let mid = (lo + hi) / 2;
        let xm = xy[order[mid]].0;
        let mut by_y: Vec<usize> = order[lo..hi].to_vec();
        by_y.sort_unstable_by_key(|&i| (xy[i].1, (xy[i].0 - xm).abs(), i));
        let mut prev: Option<(usize, i64)> = None;
        let mut k = 0;
        while k < by_y.len() {
            let y = xy[by_y[k]].1;
            let mut end = k;
            while end < by_y.len() && xy[by_y[end]].1 == y {
                end += 1;
            }
            // The point on the line if any (sorted first), else a new Steiner point.
            let first = by_y[k];
            let (rep, from) = if xy[first].0 == xm {
                (first, k + 1)
            } else {
                vertices += 1;
                (vertices - 1, k)
            };
            for &i in &by_y[from..end] {
                edges.push((i, rep, isize::try_from(2 * (xy[i].0 - xm).abs()).ok()?));
            }
            if let Some((r, py)) = prev {
                edges.push((r, rep, isize::try_from(2 * (y - py)).ok()?));
            }
            prev = Some((rep, y));
            k = end;
        }
        stack.push((lo, mid));
        stack.push((mid, hi));
    }
    Some((vertices, edges))
}

/// Euclidean motion beyond [`COMPLETE_LIMIT`]: the L1-minimum matching (exact, as for the
/// square cutter; its dual divided by √2 is the proven bound), improved by pair exchanges
/// under the Euclidean metric ([`exchange_pairs`]). Not proven minimum.
fn euclidean(p: &Points, odd: &[usize]) -> Option<OddMatching> {
    // L1 on integer coordinates: the pixels themselves (square-free), or the hexagon centres
    // in milli-units, floored (disk), where every L1 distance is within 2 of 1000 times the
    // true one.
    let (xy, scale, slack): (Vec<(i64, i64)>, f64, f64) = match p.cutter {
        Cutter::SquareFree => (
            odd.iter()
                .map(|&i| (i64::from(p.pts[i].x), i64::from(p.pts[i].y)))
                .collect(),
            1.0,
            0.0,
        ),
        _ => (
            odd.iter()
                .map(|&i| {
                    let (x, y) = centre(p.cutter, p.pts[i]);
                    ((x * 1000.0).floor() as i64, (y * 1000.0).floor() as i64)
                })
                .collect(),
            1000.0,
            2.0,
        ),
    };
    let (pairs, dual) = l1_matching(&xy)?;
    // Σ over the pairs of 2·L1 (scaled) ≥ dual; each scaled L1 is at most scale·L1 + slack.
    let l1_min = ((dual as f64 / 2.0 - slack * odd.len() as f64 / 2.0) / scale).max(0.0);
    let lower = l1_min / std::f64::consts::SQRT_2;
    let mut mate = vec![usize::MAX; p.len()];
    for (a, b) in pairs {
        mate[odd[a]] = odd[b];
        mate[odd[b]] = odd[a];
    }
    let (pairs, weight) = improved_pairs(p, odd, &mut mate);
    Some(OddMatching {
        pairs,
        weight,
        optimal: weight <= lower,
        lower_bound: lower.min(weight),
    })
}

/// The pairs of `mate` after the pair exchanges of [`exchange_pairs`], sorted, and their weight.
fn improved_pairs(p: &Points, odd: &[usize], mate: &mut [usize]) -> (Vec<(usize, usize)>, f64) {
    exchange_pairs(p, odd, mate);
    let mut pairs: Vec<(usize, usize)> = odd
        .iter()
        .filter(|&&a| a < mate[a])
        .map(|&a| (a, mate[a]))
        .collect();
    pairs.sort_unstable();
    let weight = pairs.iter().map(|&(a, b)| p.dist(a, b)).sum();
    (pairs, weight)
}

/// A near-minimum perfect matching of `odd` for when the exact solver is out of reach: greedy
/// rounds over the [`GREEDY_NEAR`] nearest unmatched odd nodes (lightest candidate pair first,
/// ties by ids; every round matches at least the closest remaining pair), then the pair
/// exchanges of [`exchange_pairs`]. Not proven minimum (`optimal = false`); the lower bound is
/// half a unit per node (distinct lattice points lie at least one unit apart).
///
/// # Complexity
/// O(M log M) per round (bucket-grid neighbour lists), a few rounds (each keeps only the nodes
/// whose candidates were all taken).
pub(super) fn near_minimum(p: &Points, odd: &[usize]) -> OddMatching {
    let mut mate = vec![usize::MAX; p.len()];
    let mut left: Vec<usize> = odd.to_vec();
    while !left.is_empty() {
        let sub = Points {
            cutter: p.cutter,
            pts: left.iter().map(|&i| p.pts[i]).collect(),
        };
        let near = super::local::nearest_neighbours(&sub, GREEDY_NEAR.min(left.len() - 1));
        let mut candidates: Vec<(u64, usize, usize)> = near
            .iter()
            .enumerate()
            .flat_map(|(a, list)| list.iter().map(move |&b| (a.min(b), a.max(b))))
            .map(|(a, b)| (sub.key(a, b), a, b))
            .collect();
        candidates.sort_unstable();
        candidates.dedup();
        for (_, a, b) in candidates {
            let (a, b) = (left[a], left[b]);
            if mate[a] == usize::MAX && mate[b] == usize::MAX {
                mate[a] = b;
                mate[b] = a;
            }
        }
        left.retain(|&i| mate[i] == usize::MAX);
    }
    let (pairs, weight) = improved_pairs(p, odd, &mut mate);
    OddMatching {
        pairs,
        weight,
        optimal: false,
        lower_bound: (odd.len() / 2) as f64,
    }
}

/// Local improvement of a perfect matching of `odd` (`mate` over point ids) under the
/// motion's metric: for u and a near odd node v (8 nearest among the odd nodes), re-pair
/// {u, mate u, v, mate v} the cheapest of its three ways, until no exchange gains.
fn exchange_pairs(p: &Points, odd: &[usize], mate: &mut [usize]) {
    let sub = Points {
        cutter: p.cutter,
        pts: odd.iter().map(|&i| p.pts[i]).collect(),
    };
    let near = super::local::nearest_neighbours(&sub, 8);
    let mut local = vec![usize::MAX; p.len()];
    for (k, &i) in odd.iter().enumerate() {
        local[i] = k;
    }
    let mut queue: std::collections::VecDeque<usize> = (0..odd.len()).collect();
    let mut queued = vec![true; odd.len()];
    while let Some(k) = queue.pop_front() {
        queued[k] = false;
        let u = odd[k];
        for &l in &near[k] {
            let (v, u2) = (odd[l], mate[u]);
            let v2 = mate[v];
            if v == u2 {
                continue;
            }
            let now = p.dist(u, u2) + p.dist(v, v2);
            let a = p.dist(u, v) + p.dist(u2, v2);
            let b = p.dist(u, v2) + p.dist(v, u2);
            if a.min(b) < now - 1e-9 {
                let (x, y) = if a <= b { (v, v2) } else { (v2, v) };
                mate[u] = x;
                mate[x] = u;
                mate[u2] = y;
                mate[y] = u2;
                for w in [u, u2, v, v2] {
                    let kw = local[w];
                    if !queued[kw] {
                        queued[kw] = true;
                        queue.push_back(kw);
                    }
                }
                break;
            }
        }
    }
}

/// The complete-graph blossom, for tests.
#[cfg(test)]
pub(super) fn complete_for_tests(p: &Points, odd: &[usize]) -> OddMatching {
    complete(p, odd)
}

/// The L1 weights of the Hanan-grid and the spanner matchings of `odd`, for tests (each
/// checked perfect and certified by its dual).
#[cfg(test)]
pub(super) fn l1_routes_for_tests(p: &Points, odd: &[usize]) -> (f64, f64) {
    let xy: Vec<(i64, i64)> = odd
        .iter()
        .map(|&i| (i64::from(p.pts[i].x), i64::from(p.pts[i].y)))
        .collect();
    let weigh = |pairs: Vec<(usize, usize)>, dual: i64| {
        let mut seen = vec![false; odd.len()];
        for &(a, b) in &pairs {
            assert!(
                !std::mem::replace(&mut seen[a], true) && !std::mem::replace(&mut seen[b], true)
            );
        }
        assert!(seen.iter().all(|&s| s), "perfect");
        let w: f64 = pairs.iter().map(|&(a, b)| p.dist(odd[a], odd[b])).sum();
        assert!(w <= ((dual + 1) / 2) as f64, "certified by the dual");
        w
    };
    let (pairs, dual) = l1_matching(&xy).expect("Hanan route");
    let hanan = weigh(pairs, dual);
    let (vertices, edges) = l1_spanner(&xy).expect("spanner");
    let defects: Vec<usize> = (0..xy.len()).collect();
    let (pairs, dual) = graph_metric_matching(vertices, edges, &defects, usize::MAX, |_| (0, 0))
        .expect("spanner route");
    (hanan, weigh(pairs, dual))
}
