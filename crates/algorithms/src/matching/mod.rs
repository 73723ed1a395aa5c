//! Minimum-weight perfect matching of endpoints under the turn distance (Theorem 4.1 and the
//! proof of Theorem 5.5 of *Optimal covering tours with turn costs*).
//!
//! # Which pairs are candidates, and what is proven
//! - Up to `COMPLETE_LIMIT` endpoints every reachable pair is a candidate and rustworkx-core's
//!   blossom algorithm (`max_weight_matching`, maximum cardinality, weights `BIG − w`) finds
//!   the exact minimum (certificates `matching_complete = 1`, `matching_optimal = 1`).
//! - Every graph-metric route below splits its graph at cut vertices first and solves each
//!   block on its own (exact: a minimum matching in a graph metric is a minimum T-join, which
//!   splits over blocks; proof in `blocks`); a bridge needs no solver at all.
//! - Beyond that, for strip ends (`strips-matching`), no pair is listed at all
//!   ([`run_graph_matching`]): the turn distance between two strip ends is a shortest-path
//!   distance in the graph of the region's maximal horizontal and vertical runs (one edge per
//!   turn), so the matching is a minimum-weight perfect matching of vertices in a graph
//!   metric, which fusion-blossom (an exact primal–dual blossom algorithm that grows its dual
//!   regions on the graph) solves over ALL pairs at once. One-pixel strips, whose floor the
//!   metric cannot express, are taken out or given a gadget, with a proof that the minimum
//!   is unchanged (see [`run_graph_matching`]). The matching's weights are recounted by 0-1
//!   searches; the solver's dual objective is the lower bound (`matching_lower_bound`), and
//!   `matching_optimal = 1` exactly when the recount reaches it. `matching_complete = 1`
//!   (every pair is priced by the graph), `matching_candidates` = P(P − 1)/2. Measured: the
//!   bound is reached on every instance tried (random-simple and random-holed, 10⁴ and 10⁵
//!   pixels); the integration tests compare it with blossom on the complete graph.
//! - Beyond that, for boundary link ends (`boundary-cc`, one heading each), likewise over ALL
//!   pairs ([`link_graph_matching`]): their turn distance w is no metric (two ends facing a
//!   third may be two turns apart), but 2w + 4 is, and it is the shortest-path metric of the
//!   "ray graph": the runs, each end hung from the runs crossing its ray (the part of its run
//!   ahead of it) at weight 4, and a direct edge for each pair of rays sharing a pixel
//!   (facing: 4, crossing: 6); one-pixel links (floor 4) get a clone of their crossing run.
//!   Certificates as for strip ends. Measured on thin pockets and boundary-only regions of
//!   600–2,600 ends: equal to blossom on the complete graph, bound reached every time.
//! - Other endpoints, a graph too large ([`RAY_GRAPH_EDGES`]), or a solver that fails, use
//!   the LP route ([`priced_matching`]):
//!   - candidates: per endpoint the endpoints its 0-1 BFS meets up to the end of the first
//!     turn level with [`NEAR`] of them (at most [`MAX_TURNS`] turns), plus its partner;
//!   - HiGHS solves the matching LP over them, with odd-set cuts found exactly (Padberg–Rao,
//!     a Gomory–Hu tree per fractional component) for a bounded number of rounds;
//!   - pricing over ALL pairs: one multi-source Dijkstra ([`cheapest_sources`]) finds every
//!     absent pair whose reduced cost may be negative; they join, and the LP is solved again;
//!   - the duals give a proven lower bound over all pairs (`matching_lower_bound`);
//!   - the matching is the LP's where integral, otherwise blossom (rustworkx) on the
//!     endpoints the LP left fractional ([`repair`]); above [`LARGE`] endpoints it comes from
//!     Z-order tiles of [`TILE`] endpoints ([`tiled_matching`]);
//!   - it is certified minimum exactly when its weight reaches the bound. The cut rounds
//!     tail off long before the LP reaches the integer optimum (on random-holed 10⁴ the LP
//!     still gains a fraction of a turn per round after 300 rounds), so this route's bound
//!     is usually several percent short: that is why strip ends no longer take it.
//!
//! `MOWMILL_MATCHING_LOG=1` prints the LP rounds to stderr.

mod blocks;
mod blossom;
mod certificate;
mod fusion;
pub(crate) mod join;
mod lp;
mod odd_sets;
mod ray_graph;
mod run_graph;
mod tiles;
pub mod turn_distance;

pub(crate) use blossom::min_weight_perfect_matching;
pub(crate) use join::join_links;

use certificate::*;
use fusion::*;
use lp::*;
use odd_sets::*;
use ray_graph::*;
use run_graph::*;
use tiles::*;

use crate::error::{Error, Result};
use crate::region::{Dir, Region};
use fusion_blossom::dual_module::DualNodeClass;
use fusion_blossom::mwpm_solver::{PrimalDualSolver, SolverParallel, SolverSerial};
use fusion_blossom::util::{PartitionConfig, SolverInitializer, SyndromePattern, VertexRange};
use rustworkx_core::max_weight_matching::max_weight_matching;
use rustworkx_core::petgraph::graph::UnGraph;
use std::collections::HashMap;
use turn_distance::{Port, TurnSearch, bit, cheapest_sources};
/// Up to this many endpoints, the candidate graph is complete (the matching is exact).
pub(crate) const COMPLETE_LIMIT: usize = 600;

/// Larger instances start from, per endpoint, at least this many nearest endpoints (in turns).
pub(crate) const NEAR: usize = 6;

/// ... at most this many turns away; pricing adds whatever farther pair the duals ask for.
pub(crate) const MAX_TURNS: u32 = 4;

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
    /// Whether the candidate graph was complete.
    pub complete: bool,
    /// Whether `total` is proven minimum over all perfect matchings of all pairs (complete
    /// candidate graph, or `total == lower_bound`).
    pub optimal: bool,
    /// A proven lower bound on the minimum weight over all pairs.
    pub lower_bound: u64,
    /// The number of candidate pairs at the end.
    pub candidates: usize,
}

impl PortMatching {
    /// The certificates every algorithm built on a port matching reports:
    /// `matching_complete`, `matching_optimal`, `matching_lower_bound`, `matching_candidates`.
    pub fn certificates(&self) -> impl Iterator<Item = (String, i64)> + use<> {
        [
            ("matching_complete", i64::from(self.complete)),
            ("matching_optimal", i64::from(self.optimal)),
            ("matching_lower_bound", self.lower_bound as i64),
            ("matching_candidates", self.candidates as i64),
        ]
        .into_iter()
        .map(|(name, value)| (name.to_string(), value))
    }
}

/// How candidate pairs are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Candidates {
    /// Every pair: blossom on the complete graph.
    Complete,
    /// Near pairs, grown by LP pricing until the LP bound holds over all pairs.
    Priced,
    /// Every pair through a graph metric: the run graph for strip ends
    /// ([`run_graph_matching`]), the ray graph for one-heading link ends
    /// ([`link_graph_matching`]); where neither applies or the solver fails,
    /// [`Candidates::Priced`].
    RunGraph,
}

/// A minimum-weight perfect matching of `defects` (distinct vertices of the graph on
/// `0..vertices` with positive even integer edge `weights`) in the graph's shortest-path
/// metric, over ALL pairs, by fusion-blossom: the matched pairs (indices into `defects`) and
/// the solver's dual sum, a lower bound on every perfect matching's weight in that metric.
/// One thread; above `serial_limit` defects on fusion-blossom's partitioned solver over a
/// bisection by the vertices' positions `at` (each vertex's extent is widened to the
/// positions of its neighbours, so the extents of two adjacent vertices meet).
/// `None` when the solver fails (a panic of the library counts as a failure).
pub(crate) fn graph_metric_matching(
    vertices: usize,
    edges: Vec<(usize, usize, isize)>,
    defects: &[usize],
    serial_limit: usize,
    at: impl Fn(usize) -> (i32, i32),
) -> Option<(Vec<(usize, usize)>, i64)> {
    let index: HashMap<usize, usize> = defects.iter().enumerate().map(|(i, &v)| (v, i)).collect();
    let (mate, dual) = mates_of(defects.len(), || {
        let (pairs, dual) =
            solve_graph_matching(serial_limit, vertices, edges, defects, |edges| {
                let point: Vec<Extent> = (0..vertices)
                    .map(|v| {
                        let (x, y) = at(v);
                        (x, x, y, y)
                    })
                    .collect();
                let mut extent = point.clone();
                for &(a, b, _) in edges {
                    widen(&mut extent[a], point[b]);
                    widen(&mut extent[b], point[a]);
                }
                extent
            })?;
        Some((renamed(pairs, &index)?, dual))
    })?;
    let mut pairs = Vec::with_capacity(defects.len() / 2);
    for (i, &j) in mate.iter().enumerate() {
        if j == usize::MAX {
            return None;
        }
        if i < j {
            pairs.push((i, j));
        }
    }
    Some((pairs, dual))
}

/// A minimum-weight perfect matching of `ports` under the turn distance.
///
/// `partner[i]` is an endpoint that `i` can always be matched to (the other end of its strip
/// or link; `partner` is an involution without fixed points). `floor[i]` is a least weight for
/// the pair (i, partner\[i\]): a one-pixel strip or link matched to itself closes a walk that
/// never moves, which the turn distance prices below the 4 turns such a walk counts.
///
/// # Returns
/// The matching with its certificates: `optimal` when it is proven minimum over all pairs,
/// otherwise the proven `lower_bound` measures the gap.
///
/// # Complexity
/// Up to [`COMPLETE_LIMIT`] endpoints: O(P · N) candidate search and O(P³) blossom. Beyond,
/// for strip ends: O(N) for the run graph, split into its blocks at cut vertices (O(N),
/// exact, see `blocks`), fusion-blossom on each block (roughly quadratic in its defects
/// serially, hence a partition above [`SERIAL_LIMIT`] defects; measured 6.4 s in all for
/// random-simple 10^5, whose largest block has 5,784 of 8,516 defects, and 490 s and 12 GB
/// for random-simple 10^6, largest block 35,268 of 47,436), and one bounded 0-1 search per
/// matched pair for the recount. For link ends: the ray graph has O(N + Σ ray lengths +
/// pairs of rays sharing a pixel) edges; on thin pockets its blocks are small (10^5 pixels:
/// 14,136 blocks with defects, the largest with 202 of 66,916), so thin-cc takes 1.2 s at
/// 10^5 and 12 s at 10^6 pixels. Other endpoints: O(P · A) for the initial candidates (A the area a BFS
/// explores before meeting [`NEAR`] endpoints), then per round one HiGHS dual simplex
/// re-solve and one O(N log N) pricing search; blossom only where the LP is fractional.
pub(crate) fn match_ports(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Result<PortMatching> {
    let how = if ports.len() <= COMPLETE_LIMIT {
        Candidates::Complete
    } else {
        Candidates::RunGraph
    };
    match_ports_with(region, ports, partner, floor, how)
}

/// `match_ports` with the candidate pairs chosen as asked.
pub fn match_ports_with(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    how: Candidates,
) -> Result<PortMatching> {
    if how == Candidates::RunGraph {
        if let Some(m) = run_graph_matching(region, ports, partner, floor) {
            return m;
        }
        if let Some(m) = link_graph_matching(region, ports, partner, floor) {
            return m;
        }
    }
    let complete = how == Candidates::Complete;
    let edges = if complete {
        candidate_edges(region, ports, partner, floor, None, None)?
    } else {
        candidate_edges(region, ports, partner, floor, Some((NEAR, MAX_TURNS)), None)?
    };
    if complete {
        let mate = min_weight_perfect_matching(ports.len(), &edges)
            .ok_or_else(|| Error::solver("the endpoints have no perfect matching"))?;
        let mut m = matching_of(mate, &edges);
        m.complete = true;
        m.optimal = true;
        m.lower_bound = m.total;
        return Ok(m);
    }
    priced_matching(region, ports, partner, floor, edges)
}

/// Candidate pairs (sorted, each once, weight at least the floor for partners): every
/// reachable pair, or per endpoint the endpoints its 0-1 BFS meets up to the end of the first
/// turn level with `near.0` of them (at most `near.1` turns), plus its partner. With `tile`,
/// only endpoints of the same tile count (partners share a tile).
fn candidate_edges(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    near: Option<(usize, u32)>,
    tile: Option<&[u32]>,
) -> Result<Vec<(usize, usize, u32)>> {
    let mut at_pixel: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, port) in ports.iter().enumerate() {
        at_pixel.entry(port.pixel).or_default().push(i);
    }
    let (enough, max_turns) = near.unwrap_or((usize::MAX, u32::MAX));
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
                    let same_tile = tile.is_none_or(|t| t[j] == t[i]);
                    if j != i && same_tile && ports[j].arrive() & bit(heading) != 0 {
                        add(j, d, &mut edges);
                        found += 1;
                    }
                }
            }
            found >= enough
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
    Ok(edges)
}

/// The matching `mate` with its weights looked up in `edges`.
fn matching_of(mate: Vec<usize>, edges: &[(usize, usize, u32)]) -> PortMatching {
    let lookup: HashMap<(usize, usize), u32> = edges.iter().map(|&(a, b, w)| ((a, b), w)).collect();
    let p = mate.len();
    let mut weight = vec![0; p];
    let mut total = 0u64;
    for i in 0..p {
        if i < mate[i] {
            weight[i] = lookup[&(i, mate[i])];
            total += u64::from(weight[i]);
        }
    }
    PortMatching {
        mate,
        weight,
        total,
        complete: false,
        optimal: false,
        lower_bound: 0,
        candidates: edges.len(),
    }
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

    /// The priced matching and its bound against the complete graph (run with
    /// `cargo test --release --lib priced_matching_gap -- --ignored --nocapture`).
    #[test]
    #[ignore = "a measurement, takes a minute"]
    fn priced_matching_gap() {
        use crate::generate::{Family, GenParams, generate};
        use crate::strips_matching::{strip_floors, strip_ports};
        for (family, n) in [(Family::RandomSimple, 6000), (Family::RandomHoled, 4000)] {
            let mut params = GenParams::new(family, 3);
            params.n = Some(n);
            let region = generate(&params).unwrap().region;
            let cover = crate::strip_cover::strip_cover(&region);
            let (links, ports) = strip_ports(&region, &cover.strips);
            let partner: Vec<usize> = (0..ports.len()).map(|i| i ^ 1).collect();
            let floor = strip_floors(&links);
            let priced =
                match_ports_with(&region, &ports, &partner, &floor, Candidates::Priced).unwrap();
            let full =
                match_ports_with(&region, &ports, &partner, &floor, Candidates::Complete).unwrap();
            eprintln!(
                "{family:?} N = {}: {} ports, w(M) priced {} (bound {}) vs complete {}",
                region.len(),
                ports.len(),
                priced.total,
                priced.lower_bound,
                full.total
            );
            assert!(priced.lower_bound <= full.total && full.total <= priced.total);
        }
    }

    #[test]
    fn separation_finds_an_odd_set_inside_an_even_component() {
        // Two triangles at about 1/2, joined by two edges at 0.1: one even fractional
        // component of six endpoints, in which each triangle is a violated odd set
        // (x(δ(S)) = 0.2 < 1).
        let edges = [
            (0, 1, 0),
            (1, 2, 0),
            (0, 2, 0),
            (2, 3, 0),
            (0, 4, 0),
            (3, 4, 0),
            (4, 5, 0),
            (3, 5, 0),
        ];
        let x = [0.5, 0.5, 0.4, 0.1, 0.1, 0.4, 0.5, 0.5];
        let sets = violated_odd_sets(6, &edges, &x);
        assert!(!sets.is_empty());
        for s in &sets {
            assert!(s == &vec![0, 1, 2] || s == &vec![3, 4, 5], "{s:?}");
        }
        // An odd component is its own violated set.
        let sets = violated_odd_sets(4, &[(0, 1, 1), (1, 2, 1), (0, 2, 1)], &[0.5, 0.5, 0.5]);
        assert_eq!(sets, vec![vec![0, 1, 2]]);
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
