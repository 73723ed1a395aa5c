//! `milling-2opt`: a milling tour from a TSP tour of the pixels under the region's
//! shortest-path metric, improved by local search. A heuristic: it realizes no theorem of
//! the papers and is registered for the upper bounds it gives on OPT (the best checked walk
//! known), on regions where no registered algorithm builds short tours (holes with local cut
//! vertices, where `holes1325` and `tsp65` do not apply).
//!
//! 1. Start: the preorder of a depth-first spanning tree, read as a TSP tour of the pixels
//!    with d(a, b) = the length of a shortest path from a to b inside the region (BFS).
//! 2. The shared 2-opt / Or-opt local search with don't-look bits and a seeded iterated local
//!    search of double-bridge kicks ([`crate::tsp_local`], as `lawn-2opt`), on the
//!    [`NEIGHBOURS`] nearest pixels of every pixel in that metric (ties by pixel index).
//! 3. Every jump a → b of the tour is expanded into a shortest path inside the region, which
//!    gives a closed walk between 4-adjacent pixels of length exactly the tour's length.
//!
//! Distances come from an all-pairs `u16` matrix, one BFS per pixel, up to [`MATRIX_LIMIT`]
//! pixels (72 MB at the limit). Above it the module returns the doubled depth-first tree walk
//! (length 2N − 2) without local search: the moves need d(a, b) for arbitrary pairs in O(1).
//!
//! The exact solver's warm start tries every registered milling algorithm, this one included,
//! and keeps the shortest checked tour.

use crate::error::{Error, Result};
use crate::region::{Dir, Region};
use crate::topology;
use crate::tour::CycleCover;
use crate::tsp_local::{self, Metric};
use crate::{Against, Algorithm, Guarantee, Objective, Output, Solution};
use std::collections::VecDeque;

/// Nearest pixels per pixel in the candidate lists of the local search.
pub(crate) const NEIGHBOURS: usize = 10;

/// Kicks of the iterated local search: `KICKS_PER_PIXEL` per pixel, at most `MAX_KICKS`
/// (more than `lawn-2opt`'s 30 and 20,000: the path metric's plateaus of equal lengths need
/// more drifting).
const KICKS_PER_PIXEL: usize = 200;
const MAX_KICKS: usize = 400_000;

/// The largest N for which the all-pairs distance matrix is built (N² · 2 bytes).
pub(crate) const MATRIX_LIMIT: usize = 6_000;

/// A connected, non-empty region.
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::Precondition("the region is empty".into()));
    }
    if topology::components(region).count != 1 {
        return Err(Error::Precondition(
            "milling-2opt needs a connected region (one grid component)".into(),
        ));
    }
    Ok(())
}

/// Shortest-path distances inside the region between all pairs of pixels.
struct PathMetric {
    n: usize,
    dist: Vec<u16>,
}

impl PathMetric {
    /// One BFS per pixel: O(N²) time and N² · 2 bytes.
    fn new(region: &Region) -> PathMetric {
        let n = region.len();
        let mut dist = vec![u16::MAX; n * n];
        let mut queue = VecDeque::with_capacity(n);
        for s in 0..n {
            let row = &mut dist[s * n..(s + 1) * n];
            row[s] = 0;
            queue.push_back(s);
            while let Some(v) = queue.pop_front() {
                let dv = row[v];
                for w in region.neighbors(v) {
                    if row[w] == u16::MAX {
                        row[w] = dv + 1;
                        queue.push_back(w);
                    }
                }
            }
        }
        PathMetric { n, dist }
    }

    fn d(&self, a: usize, b: usize) -> u16 {
        self.dist[a * self.n + b]
    }
}

impl Metric for PathMetric {
    fn dist(&self, a: usize, b: usize) -> f64 {
        f64::from(self.d(a, b))
    }
}

/// The `k` nearest other pixels of every pixel by BFS distance inside the region, sorted by
/// (distance, index): a BFS from each pixel stopped after the layer that completes k.
fn neighbour_lists(region: &Region, k: usize) -> Vec<Vec<usize>> {
    let n = region.len();
    let mut seen = vec![usize::MAX; n];
    let mut layer: Vec<usize> = Vec::new();
    let mut next: Vec<usize> = Vec::new();
    (0..n)
        .map(|s| {
            let mut found: Vec<usize> = Vec::with_capacity(k + 8);
            seen[s] = s;
            layer.clear();
            layer.push(s);
            while found.len() < k && !layer.is_empty() {
                next.clear();
                for &v in &layer {
                    for w in region.neighbors(v) {
                        if seen[w] != s {
                            seen[w] = s;
                            next.push(w);
                        }
                    }
                }
                // One whole layer at a time, so that ties are broken by index, not BFS order.
                next.sort_unstable();
                found.extend_from_slice(&next);
                std::mem::swap(&mut layer, &mut next);
            }
            found.truncate(k);
            found
        })
        .collect()
}

/// The preorder of an iterative depth-first search from pixel 0 (neighbours in `Dir::ALL`
/// order) and the tree's parent of every pixel (`usize::MAX` at the root).
fn depth_first(region: &Region) -> (Vec<usize>, Vec<usize>) {
    let n = region.len();
    let mut parent = vec![usize::MAX; n];
    let mut visited = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let mut stack = vec![(0usize, usize::MAX)];
    while let Some((v, p)) = stack.pop() {
        if visited[v] {
            continue;
        }
        visited[v] = true;
        parent[v] = p;
        order.push(v);
        for d in Dir::ALL.iter().rev() {
            if let Some(w) = region.neighbor(v, *d)
                && !visited[w]
            {
                stack.push((w, v));
            }
        }
    }
    (order, parent)
}

/// The closed walk around the depth-first tree (each tree edge twice, 2N − 2 moves): its
/// first visits are the preorder.
fn doubled_tree_walk(order: &[usize], parent: &[usize]) -> Vec<usize> {
    let mut walk = Vec::with_capacity(2 * order.len());
    let mut path: Vec<usize> = Vec::new();
    for &v in order {
        // Climb back to v's parent (on the path: a depth-first tree), then step down to v.
        while let Some(&top) = path.last()
            && top != parent[v]
        {
            path.pop();
            walk.extend(path.last());
        }
        path.push(v);
        walk.push(v);
    }
    // Back up to the root's child; the closing move reaches the root.
    while path.len() > 2 {
        path.pop();
        walk.extend(path.last());
    }
    walk
}

/// The tour's jumps expanded into shortest paths inside the region: from a, always to the
/// first neighbour (in `Dir::ALL` order) one step closer to b.
fn expand(region: &Region, m: &PathMetric, tour: &[usize]) -> Vec<usize> {
    let mut walk = Vec::new();
    for k in 0..tour.len() {
        let (a, b) = (tour[k], tour[(k + 1) % tour.len()]);
        let mut cur = a;
        walk.push(cur);
        while m.d(cur, b) > 1 {
            let want = m.d(cur, b) - 1;
            cur = region
                .neighbors(cur)
                .find(|&w| m.d(w, b) == want)
                .expect("a BFS distance > 0 has a neighbour one step closer");
            walk.push(cur);
        }
    }
    walk
}

/// Runs `milling-2opt` (module docs).
///
/// # Arguments
/// A connected region (holes and cut vertices allowed).
///
/// # Returns
/// One tour (objective length); certificates `start_length` (the depth-first tour's length,
/// at most 2N − 2) and `local_search` (1 when the local search ran, 0 above
/// [`MATRIX_LIMIT`]).
///
/// # Complexity
/// O(N²) time and 2N² bytes for the distance matrix, O(N · k) for the neighbour lists, and
/// the local search: 200 kicks of local double bridges per pixel (at most 400,000), each
/// followed by a local search from the few touched pixels (about 4 s at N = 2,806, one
/// thread). Above [`MATRIX_LIMIT`]: O(N).
///
/// # Guarantee
/// Length ≤ 2N − 2. The depth-first preorder, as a tour in the shortest-path metric, is no
/// longer than the doubled tree walk (2N − 2 moves; each jump is shortcut by a shortest path,
/// the triangle inequality), every move of the local search shortens the tour or, for a kept
/// kick, does not lengthen it, and the final tour is compared with the start exactly; the
/// expansion into shortest paths keeps the length. Since every milling tour of N ≥ 2 pixels
/// visits N pixel centres in a closed walk of unit moves, OPT ≥ N, hence length ≤ 2 · OPT.
/// This is the "trivial bound 2N − 2, from doubling a spanning tree" of Section 1 of Arkin,
/// Fekete, Mitchell, *Approximation algorithms for lawn mowing and milling*; the
/// registry cites it as Theorem 2 (a TSP tour with αTSP = 2 from a doubled spanning tree),
/// here of the pixels in the region's path metric.
pub(crate) fn milling_two_opt(region: &Region) -> Result<Solution> {
    precondition(region)?;
    let n = region.len();
    let (order, parent) = depth_first(region);
    let (walk, start_length, searched) = if n <= MATRIX_LIMIT {
        let metric = PathMetric::new(region);
        let start_length = metric.tour_length(&order) as i64;
        let tour = if n < 5 {
            order
        } else {
            let kicks = (KICKS_PER_PIXEL * n).min(MAX_KICKS);
            tsp_local::improve(&metric, &neighbour_lists(region, NEIGHBOURS), kicks, order)
        };
        (expand(region, &metric, &tour), start_length, 1)
    } else {
        // The doubled tree walk is the preorder tour expanded: 2N − 2 exactly.
        let walk = doubled_tree_walk(&order, &parent);
        let len = walk.len() as i64;
        (walk, len, 0)
    };
    let mut solution = Solution::default();
    solution.outputs.push(Output {
        objective: Objective::Length,
        cover: CycleCover::tour(walk.into_iter().map(|i| region.pixel(i)).collect()),
    });
    solution
        .certificates
        .insert("start_length".into(), start_length);
    solution
        .certificates
        .insert("local_search".into(), searched);
    Ok(solution)
}

/// The registry entry of `milling-2opt`: a TSP tour of the pixels in the region's
/// shortest-path metric, from a depth-first tree, improved by 2-opt, Or-opt and double-bridge
/// kicks, expanded into shortest paths ([`milling_two_opt`]).
///
/// # Guarantee
///
/// Length ≤ 2N − 2 on every connected region (proof at [`milling_two_opt`]), hence
/// ≤ 2 · OPT for N ≥ 2. Registered as `length <= 2 N - 2`, against N. No theorem of the
/// papers is about this algorithm: the bound is the milling paper's trivial bound (Section 1,
/// "from doubling a spanning tree"), cited as Theorem 2's αTSP = 2 reading; it makes no claim
/// (no claims-table row).
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "######\n",
///     "######\n",
///     "######\n",
///     "######\n",
/// ));
/// let algorithm = algorithms::find("milling-2opt").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::Length).unwrap();
/// assert!(tour.valid);
/// // A 6 x 4 rectangle has a Hamiltonian cycle: 24 moves.
/// assert_eq!(tour.length, 24);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "milling-2opt",
    summary: "TSP tour of the pixels in the region's path metric: depth-first start, 2-opt/Or-opt and kicks, jumps expanded",
    objectives: &[Objective::Length],
    guarantees: &[Guarantee::new(
        Objective::Length,
        crate::theorems::Bound::new(crate::Quantity::Value, 2, 1, -2, Against::N),
        crate::When::Always,
        &crate::theorems::MILLING_THM_2,
        "doubled spanning tree, Theorem 2 of Lawn mowing and milling (alpha_TSP = 2, path metric)",
    )],
    claims: &[],
    requires: "a connected region",
    precondition,
    run: |region, _| milling_two_opt(region),
    discrete: None,
    ortho: None,
    by_default: true,
};
