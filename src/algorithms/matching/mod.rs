//! Minimum-weight perfect matching of endpoints under the turn distance (Theorem 4.1 and the
//! proof of Theorem 5.5 of *Optimal covering tours with turn costs*).
//!
//! # Which pairs are candidates, and what is proven
//! - Up to [`COMPLETE_LIMIT`] endpoints every reachable pair is a candidate and rustworkx-core's
//!   blossom algorithm (`max_weight_matching`, maximum cardinality, weights `BIG − w`) finds
//!   the exact minimum (certificates `matching_complete = 1`, `matching_optimal = 1`).
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

pub mod join;
pub mod turn_distance;

pub use join::join_links;

use crate::error::{Error, Result};
use crate::region::{Dir, Region};
use fusion_blossom::dual_module::DualNodeClass;
use fusion_blossom::mwpm_solver::{PrimalDualSolver, SolverParallel, SolverSerial};
use fusion_blossom::util::{PartitionConfig, SolverInitializer, SyndromePattern, VertexRange};
use highs::{ColProblem, HighsModelStatus, Model, Sense};
use rustworkx_core::max_weight_matching::max_weight_matching;
use rustworkx_core::petgraph::graph::UnGraph;
use std::collections::HashMap;
use turn_distance::{Port, TurnSearch, bit, cheapest_sources};

/// Up to this many endpoints, the candidate graph is complete (the matching is exact).
pub const COMPLETE_LIMIT: usize = 600;

/// Larger instances start from, per endpoint, at least this many nearest endpoints (in turns).
pub const NEAR: usize = 6;

/// ... at most this many turns away; pricing adds whatever farther pair the duals ask for.
pub const MAX_TURNS: u32 = 4;

/// Pricing keeps, per endpoint, this many cheapest absent partners per round.
const PRICE_K: usize = 8;

/// At most this many rounds of odd-set cuts on the LP: [`CUT_BUDGET`] / P rounds for P
/// endpoints, clamped to [`CUT_ROUNDS_LARGE`]..=[`CUT_ROUNDS`] (a round costs about 10 µs
/// per endpoint, more on large instances).
const CUT_ROUNDS: usize = 60;

/// See [`CUT_ROUNDS`].
const CUT_BUDGET: usize = 45_000;

/// See [`CUT_ROUNDS`].
const CUT_ROUNDS_LARGE: usize = 3;

/// Above this many endpoints: one pricing round, [`CUT_ROUNDS_LARGE`] cut rounds, and the
/// matching from tiles ([`tiled_matching`]) rather than from the LP (blossom on what the LP
/// leaves fractional takes minutes there).
const LARGE: usize = 10_000;

/// Tiles of about this many endpoints (above [`LARGE`]).
const TILE: usize = 1000;

/// Per endpoint at least this many candidates in its tile (above [`LARGE`]).
const TILE_NEAR: usize = 12;

/// ... at most this many turns away.
const TILE_TURNS: u32 = 6;

/// The cut rounds stop when the last this many raised the LP by less than 1.
const STALL: usize = 10;

/// At most this many pricing rounds (each followed by a re-solve).
const PRICE_ROUNDS: usize = 2;

/// The search of its own for an endpoint the joint pricing search may have cut short goes
/// this many turns deep; farther pairs enter the bound by their least possible cost.
const FALLBACK_TURNS: u32 = 12;

/// Fractional components up to this size are separated exactly (Gomory–Hu).
const GOMORY_HU_LIMIT: usize = 400;

/// Tolerance on reduced costs and on integrality of HiGHS's answers.
const TOL: f64 = 1e-6;

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

/// A candidate pair (smaller endpoint, larger endpoint, weight).
type Pair = (usize, usize, u32);

/// The matching used above [`LARGE`] endpoints (and where [`repair`] fails), where blossom after the LP is too slow: the
/// endpoint pairs (an endpoint and its partner) in Z-order, cut into tiles of [`TILE`]
/// endpoints, each tile matched by blossom over, per endpoint, the endpoints of its tile met
/// by its 0-1 BFS up to the end of the first turn level with [`TILE_NEAR`] of them (at most
/// [`TILE_TURNS`] turns), plus its partner. Returns the mates and the candidate pairs.
fn tiled_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Result<(Vec<usize>, Vec<Pair>)> {
    let tile = tiles(region, ports, partner);
    let edges = candidate_edges(
        region,
        ports,
        partner,
        floor,
        Some((TILE_NEAR, TILE_TURNS)),
        Some(&tile),
    )?;
    let mate = min_weight_perfect_matching(ports.len(), &edges)
        .ok_or_else(|| Error::invalid("the endpoints have no perfect matching"))?;
    Ok((mate, edges))
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
/// for strip ends: O(N) for the run graph, fusion-blossom on it (roughly quadratic in P
/// serially, hence a partition above [`SERIAL_LIMIT`] endpoints: measured 0.3 s for 4,458
/// ends, 3 s for 18,420 and 16 s for 30,828), and one bounded 0-1 search per matched pair
/// for the recount. For link ends: the ray graph has O(N + Σ ray lengths + pairs of rays
/// sharing a pixel) edges, solved serially up to [`RAY_SERIAL_LIMIT`] ends (measured 0.5 s
/// for 6,566 ends and 5 s for 24,672 on thin pockets). Other endpoints: O(P · A) for the initial candidates (A the area a BFS
/// explores before meeting [`NEAR`] endpoints), then per round one HiGHS dual simplex
/// re-solve and one O(N log N) pricing search; blossom only where the LP is fractional.
pub fn match_ports(
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

/// [`match_ports`] with the candidate pairs chosen as asked.
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
            .ok_or_else(|| Error::invalid("the endpoints have no perfect matching"))?;
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

/// The matching LP over the candidate pairs, kept alive in HiGHS between rounds: columns x_e
/// ≥ 0, rows x(δ(v)) = 1 and odd-set cuts x(δ(S)) ≥ 1.
struct MatchingLp {
    /// HiGHS numbers rows as endpoints, then cuts, and columns as `edges`.
    model: Option<Model>,
    /// The vertex set of every cut.
    cuts: Vec<Vec<usize>>,
    /// The endpoints at each pixel.
    at_pixel: HashMap<usize, Vec<usize>>,
    /// The cuts containing each endpoint, increasing.
    cuts_of: Vec<Vec<u32>>,
    edges: Vec<(usize, usize, u32)>,
    index: HashMap<(usize, usize), usize>,
    /// Candidate edges at each endpoint (indices into `edges`).
    incident: Vec<Vec<u32>>,
}

/// One LP optimum: primal x per edge, duals y per endpoint and z per cut.
struct LpPoint {
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
}

impl MatchingLp {
    fn new(ports: &[Port], edges: Vec<(usize, usize, u32)>) -> MatchingLp {
        let p = ports.len();
        let mut at_pixel: HashMap<usize, Vec<usize>> = HashMap::new();
        for (i, port) in ports.iter().enumerate() {
            at_pixel.entry(port.pixel).or_default().push(i);
        }
        let mut pb = ColProblem::default();
        let degree_rows: Vec<highs::Row> = (0..p).map(|_| pb.add_row(1.0..=1.0)).collect();
        let mut incident = vec![Vec::new(); p];
        for (k, &(a, b, w)) in edges.iter().enumerate() {
            pb.add_column(
                f64::from(w),
                0.0..,
                [(degree_rows[a], 1.0), (degree_rows[b], 1.0)],
            );
            incident[a].push(k as u32);
            incident[b].push(k as u32);
        }
        let mut model = pb.optimise(Sense::Minimise);
        model.make_quiet();
        model.set_option("threads", 1);
        model.set_option("presolve", "off");
        model.set_option("solver", "simplex");
        let index = edges
            .iter()
            .enumerate()
            .map(|(k, &(a, b, _))| ((a, b), k))
            .collect();
        MatchingLp {
            model: Some(model),
            cuts: Vec::new(),
            at_pixel,
            cuts_of: vec![Vec::new(); p],
            edges,
            index,
            incident,
        }
    }

    /// The cuts with exactly one of `a`, `b` inside (both lists are sorted).
    fn crossing(&self, a: usize, b: usize) -> impl Iterator<Item = u32> + '_ {
        let (ca, cb) = (&self.cuts_of[a], &self.cuts_of[b]);
        ca.iter()
            .filter(|c| cb.binary_search(c).is_err())
            .chain(cb.iter().filter(|c| ca.binary_search(c).is_err()))
            .copied()
    }

    fn add_edge(&mut self, a: usize, b: usize, w: u32) -> Result<()> {
        let (a, b) = (a.min(b), a.max(b));
        if self.index.contains_key(&(a, b)) {
            return Ok(());
        }
        let p = self.cuts_of.len();
        let mut rows = vec![a as i32, b as i32];
        rows.extend(self.crossing(a, b).map(|c| (p + c as usize) as i32));
        let ones = vec![1.0; rows.len()];
        let model = self.model.as_mut().expect("the model is alive");
        // SAFETY: the pointer is the live HiGHS instance owned by `model`; `rows` and `ones`
        // hold `rows.len()` entries, and every row index exists (degree rows, then cuts).
        let status = unsafe {
            highs_sys::Highs_addCol(
                model.as_mut_ptr(),
                f64::from(w),
                0.0,
                f64::INFINITY,
                rows.len() as i32,
                rows.as_ptr(),
                ones.as_ptr(),
            )
        };
        if status == highs_sys::STATUS_ERROR {
            return Err(Error::invalid("HiGHS refused a matching column"));
        }
        let k = self.edges.len();
        self.edges.push((a, b, w));
        self.index.insert((a, b), k);
        self.incident[a].push(k as u32);
        self.incident[b].push(k as u32);
        Ok(())
    }

    /// The candidate edges with exactly one end in `set`, increasing.
    fn crossing_edges(&self, set: &[usize]) -> Vec<i32> {
        let mut cols: Vec<i32> = Vec::new();
        for &v in set {
            for &k in &self.incident[v] {
                let (a, b, _) = self.edges[k as usize];
                if set.binary_search(&a).is_ok() != set.binary_search(&b).is_ok() {
                    cols.push(k as i32);
                }
            }
        }
        cols.sort_unstable();
        cols.dedup();
        cols
    }

    /// Adds x(δ(S)) ≥ 1 for the sorted set S.
    fn add_cut(&mut self, set: Vec<usize>) -> Result<()> {
        let cols = self.crossing_edges(&set);
        let ones = vec![1.0; cols.len()];
        let model = self.model.as_mut().expect("the model is alive");
        // SAFETY: as in `add_edge`; every column index is an existing column.
        let status = unsafe {
            highs_sys::Highs_addRow(
                model.as_mut_ptr(),
                1.0,
                f64::INFINITY,
                cols.len() as i32,
                cols.as_ptr(),
                ones.as_ptr(),
            )
        };
        if status == highs_sys::STATUS_ERROR {
            return Err(Error::invalid("HiGHS refused an odd-set cut"));
        }
        let c = self.cuts.len() as u32;
        for &v in &set {
            self.cuts_of[v].push(c);
        }
        self.cuts.push(set);
        Ok(())
    }

    /// Y_v = y_v + Σ_{S∋v} z_S: Y_u + Y_v bounds what the duals take off any pair's weight.
    fn big_y(&self, point: &LpPoint) -> Vec<f64> {
        (0..self.cuts_of.len())
            .map(|v| {
                point.y[v]
                    + self.cuts_of[v]
                        .iter()
                        .map(|&c| point.z[c as usize])
                        .sum::<f64>()
            })
            .collect()
    }

    /// The reduced cost w − y_a − y_b − Σ_{S: exactly one of a, b in S} z_S of a pair.
    fn reduced_cost(&self, point: &LpPoint, a: usize, b: usize, w: u32) -> f64 {
        f64::from(w)
            - point.y[a]
            - point.y[b]
            - self
                .crossing(a, b)
                .map(|c| point.z[c as usize])
                .sum::<f64>()
    }

    /// The lower bound Σy + Σz + ½·Σ_v m_v on every perfect matching M of all pairs, where
    /// m_v ≤ min(0, rc(u, v)) for every u (`absent[v]` covers the absent pairs): each pair
    /// of M has rc ≥ min(0, rc) ≥ (m_u + m_v)/2.
    fn bound(&self, point: &LpPoint, absent: &[f64]) -> f64 {
        let mut m = absent.to_vec();
        for &(a, b, w) in &self.edges {
            let rc = self.reduced_cost(point, a, b, w);
            m[a] = m[a].min(rc);
            m[b] = m[b].min(rc);
        }
        point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>() + 0.5 * m.iter().sum::<f64>()
    }

    fn solve(&mut self) -> Result<LpPoint> {
        let model = self.model.take().expect("the model is alive");
        let solved = model
            .try_solve()
            .map_err(|e| Error::invalid(format!("HiGHS failed on the matching LP: {e:?}")))?;
        if solved.status() != HighsModelStatus::Optimal {
            return Err(Error::invalid(format!(
                "HiGHS ended the matching LP with status {:?}",
                solved.status()
            )));
        }
        let sol = solved.get_solution();
        let p = self.cuts_of.len();
        let duals = sol.dual_rows();
        let point = LpPoint {
            x: sol.columns().to_vec(),
            y: duals[..p].to_vec(),
            z: duals[p..].iter().map(|&z| z.max(0.0)).collect(),
        };
        self.model = Some(Model::from(solved));
        Ok(point)
    }
}

/// A minimum-weight perfect matching over ALL endpoint pairs, proven by LP duality.
///
/// 1. The LP is solved over the candidate pairs. Its duals y_v (degree rows) and z_S ≥ 0
///    (odd-set cuts) bound the reduced cost of any pair from below by
///    w(u, v) − Y_u − Y_v, with Y_v = y_v + Σ_{S∋v} z_S; [`cheapest_sources`] finds every
///    absent pair where that is negative, and those become candidates. Odd components of the
///    edges with fractional x become cuts. For every perfect matching M,
///    w(M) = Σy + Σ_S z_S·|M ∩ δ(S)| + Σ_{e∈M} rc_e ≥ Σy + Σz + ½·Σ_v m_v, where m_v ≤ 0
///    bounds the reduced costs at v: that is the proven lower bound LB (best over rounds).
/// 2. The matching is the LP's where it is integral; otherwise the edges at 1 are kept and
///    blossom matches the endpoints the LP left fractional over their candidate pairs
///    ([`repair`]). It is proven minimum over all pairs when its weight is ⌈LB⌉; otherwise
///    LB is reported and the gap is w(M) − LB.
fn priced_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    edges: Vec<(usize, usize, u32)>,
) -> Result<PortMatching> {
    let p = ports.len();
    let log = std::env::var_os("MOWMILL_MATCHING_LOG").is_some();
    let started = std::time::Instant::now();
    let mut lp = MatchingLp::new(ports, edges);
    // The best proven bound and the duals Y that give it.
    let mut best: Option<(f64, Vec<f64>)> = None;
    let mut last_x;
    let (mut round, mut pricings) = (0, 0);
    let mut history: Vec<f64> = Vec::new();
    loop {
        round += 1;
        let point = lp.solve()?;
        let cuts = violated_odd_sets(p, &lp.edges, &point.x);
        let value = point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>();
        history.push(value);
        // Tailing off: the cuts of the last STALL rounds raised the LP by less than 1.
        let stalled = history.len() > STALL && value < history[history.len() - 1 - STALL] + 1.0;
        let rounds = (CUT_BUDGET / p).clamp(CUT_ROUNDS_LARGE, CUT_ROUNDS);
        if !cuts.is_empty() && round < rounds && !stalled {
            if log {
                eprintln!(
                    "round {round}: {} cuts, lp {:.3}, new cuts {}, t {:.2}",
                    lp.cuts.len(),
                    point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>(),
                    cuts.len(),
                    started.elapsed().as_secs_f64()
                );
            }
            for set in cuts {
                lp.add_cut(set)?;
            }
            continue;
        }
        // The cuts have converged (or the rounds are spent): price every absent pair.
        let big_y = lp.big_y(&point);
        let (priced, deficit) = price(region, ports, &point, &big_y, &lp, 0.0);
        let bound = lp.bound(&point, &deficit);
        if log {
            let open: f64 = deficit.iter().sum();
            let neg_z = point.z.iter().filter(|&&z| z == 0.0).count();
            eprintln!("  absent deficits {open:.3}, zero z {neg_z}");
        }
        if best.as_ref().is_none_or(|b| bound > b.0) {
            best = Some((bound, big_y));
        }
        if log {
            eprintln!(
                "round {round}: {} edges, {} cuts, bound {bound:.3}, priced {}, t {:.2}",
                lp.edges.len(),
                lp.cuts.len(),
                priced.len(),
                started.elapsed().as_secs_f64()
            );
        }
        last_x = point.x;
        pricings += 1;
        let price_rounds = if p > LARGE { 1 } else { PRICE_ROUNDS };
        if priced.is_empty() || pricings == price_rounds {
            break;
        }
        for (a, b, w) in priced {
            lp.add_edge(a, b, w)?;
        }
    }
    let (bound, _) = best.expect("one round ran");
    // Pairs not priced have reduced cost above −TOL each: allow for that, and for round-off.
    let lower = (bound - 0.5 * p as f64 * TOL - 1e-7).ceil().max(0.0) as u64;
    let mut m = if p > LARGE {
        let (mate, tiled) = tiled_matching(region, ports, partner, floor)?;
        matching_of(mate, &tiled)
    } else {
        match lp_matching(p, &lp.edges, &last_x).or_else(|| repair(p, &lp.edges, &last_x, partner))
        {
            Some(mate) => matching_of(mate, &lp.edges),
            // The repair found no perfect matching around an odd piece: tiles always do.
            None => {
                let (mate, tiled) = tiled_matching(region, ports, partner, floor)?;
                matching_of(mate, &tiled)
            }
        }
    };
    let lower_bound = lower;
    if log {
        eprintln!(
            "matching {} lower bound {lower_bound}, t {:.2}",
            m.total,
            started.elapsed().as_secs_f64()
        );
    }
    m.lower_bound = lower_bound.min(m.total);
    m.optimal = m.total <= lower_bound;
    m.candidates = lp.edges.len();
    Ok(m)
}

/// Absent pairs with reduced cost below `slack` (at most [`PRICE_K`] per endpoint from the
/// joint search, all within [`FALLBACK_TURNS`] from a search of its own where the joint one
/// may have missed some), and per endpoint v a proven lower bound, at most 0, on the reduced
/// cost of every absent pair at v.
fn price(
    region: &Region,
    ports: &[Port],
    point: &LpPoint,
    big_y: &[f64],
    lp: &MatchingLp,
    slack: f64,
) -> (Vec<(usize, usize, u32)>, Vec<f64>) {
    let y_max = big_y.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mut deficit = vec![0.0f64; ports.len()];
    let limit = slack - TOL;
    let found = cheapest_sources(region, ports, big_y, PRICE_K, y_max + limit);
    let absent = |u: usize, v: usize| !lp.index.contains_key(&(u.min(v), u.max(v)));
    let mut priced = Vec::new();
    let mut opened = 0usize;
    let mut search = TurnSearch::new(region);
    for (v, list) in found.iter().enumerate() {
        let mut open = list.len() == PRICE_K;
        for e in list {
            let rc = e.key - big_y[v];
            if rc >= limit {
                open = false;
                break;
            }
            if absent(e.port, v) {
                let rc = lp.reduced_cost(point, e.port, v, e.turns);
                if rc < limit {
                    priced.push((e.port.min(v), e.port.max(v), e.turns));
                    deficit[v] = deficit[v].min(rc);
                    deficit[e.port] = deficit[e.port].min(rc);
                }
            }
        }
        if open {
            opened += 1;
            // Every listed source is a candidate and more may follow: search from v alone, as
            // far as a reduced cost below the limit reaches (w is symmetric).
            let reach = (big_y[v] + y_max + limit).floor().max(0.0) as u32;
            // Beyond FALLBACK_TURNS a pair costs at least that + 1 turns, which bounds its
            // reduced cost from below.
            if reach > FALLBACK_TURNS {
                let beyond = f64::from(FALLBACK_TURNS + 1) - big_y[v] - y_max;
                deficit[v] = deficit[v].min(beyond);
            }
            let reach = reach.min(FALLBACK_TURNS);
            search.run(region, ports[v], reach, |pixel, heading, d| {
                if let Some(here) = lp.at_pixel.get(&pixel) {
                    for &u in here {
                        if u != v
                            && ports[u].arrive() & bit(heading) != 0
                            && f64::from(d) - big_y[u] - big_y[v] < limit
                            && absent(u, v)
                        {
                            let rc = lp.reduced_cost(point, u, v, d);
                            if rc < limit {
                                priced.push((u.min(v), u.max(v), d));
                                deficit[v] = deficit[v].min(rc);
                                deficit[u] = deficit[u].min(rc);
                            }
                        }
                    }
                }
                false
            });
        }
    }
    // A pair met twice keeps its least weight (the search settles each state once, so the
    // first met is the least; sorting puts it first).
    priced.sort_unstable();
    priced.dedup_by_key(|e| (e.0, e.1));
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        eprintln!("  pricing: {opened} endpoints searched alone");
    }
    (priced, deficit)
}

/// Odd sets S with x(δ(S)) < 1 (sorted, each once): per connected component C of the edges
/// with fractional x, C itself when |C| is odd, otherwise the violated odd sides of the
/// minimum cuts of a Gomory–Hu tree of C (Padberg–Rao: if some odd set inside C is
/// violated, one of those is). A vertex of C has no edge at 1, so x(δ(S)) for S ⊆ C counts
/// only edges inside C, and a violated odd set anywhere has a violated odd part in one C.
fn violated_odd_sets(p: usize, edges: &[(usize, usize, u32)], x: &[f64]) -> Vec<Vec<usize>> {
    let mut root: Vec<usize> = (0..p).collect();
    let fractional: Vec<usize> = (0..edges.len())
        .filter(|&k| x[k] > TOL && x[k] < 1.0 - TOL)
        .collect();
    for &k in &fractional {
        let (a, b, _) = edges[k];
        let (ra, rb) = (find(&mut root, a), find(&mut root, b));
        if ra != rb {
            root[ra] = rb;
        }
    }
    let mut members: HashMap<usize, Vec<usize>> = HashMap::new();
    let mut arcs: HashMap<usize, Vec<(usize, usize, f64)>> = HashMap::new();
    for &k in &fractional {
        let (a, b, _) = edges[k];
        let r = find(&mut root, a);
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
fn odd_min_cuts(vertices: &[usize], arcs: &[(usize, usize, f64)]) -> Vec<Vec<usize>> {
    let n = vertices.len();
    let local = |v: usize| vertices.binary_search(&v).expect("a member");
    let mut adj: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
    for &(a, b, c) in arcs {
        let (a, b) = (local(a), local(b));
        adj[a].push((b, c));
        adj[b].push((a, c));
    }
    let mut parent = vec![0usize; n];
    let mut value = vec![0.0f64; n];
    for s in 1..n {
        let t = parent[s];
        let (f, side) = min_cut(&adj, s, t);
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

/// A minimum s-t cut (Edmonds–Karp on a small graph): its value and the source side.
fn min_cut(adj: &[Vec<(usize, f64)>], s: usize, t: usize) -> (f64, Vec<bool>) {
    let n = adj.len();
    // Residual capacities, keyed by ordered vertex pair.
    let mut residual: HashMap<(usize, usize), f64> = HashMap::new();
    for (a, list) in adj.iter().enumerate() {
        for &(b, c) in list {
            *residual.entry((a, b)).or_insert(0.0) += c;
        }
    }
    let mut flow = 0.0;
    loop {
        let mut prev = vec![usize::MAX; n];
        prev[s] = s;
        let mut queue = std::collections::VecDeque::from([s]);
        while let Some(a) = queue.pop_front() {
            for &(b, _) in &adj[a] {
                if prev[b] == usize::MAX && residual[&(a, b)] > 1e-9 {
                    prev[b] = a;
                    queue.push_back(b);
                }
            }
        }
        if prev[t] == usize::MAX {
            let side = prev.iter().map(|&q| q != usize::MAX).collect();
            return (flow, side);
        }
        let mut push = f64::INFINITY;
        let mut b = t;
        while b != s {
            push = push.min(residual[&(prev[b], b)]);
            b = prev[b];
        }
        let mut b = t;
        while b != s {
            *residual.get_mut(&(prev[b], b)).expect("an arc") -= push;
            *residual.get_mut(&(b, prev[b])).expect("an arc") += push;
            b = prev[b];
        }
        flow += push;
    }
}

fn find(root: &mut [usize], mut x: usize) -> usize {
    while root[x] != x {
        root[x] = root[root[x]];
        x = root[x];
    }
    x
}

/// The LP's matching, when x is integral.
fn lp_matching(p: usize, edges: &[(usize, usize, u32)], x: &[f64]) -> Option<Vec<usize>> {
    let mut mate = vec![usize::MAX; p];
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] > TOL && x[k] < 1.0 - TOL {
            return None;
        }
        if x[k] > 0.5 {
            if mate[a] != usize::MAX || mate[b] != usize::MAX {
                return None;
            }
            mate[a] = b;
            mate[b] = a;
        }
    }
    mate.iter().all(|&m| m != usize::MAX).then_some(mate)
}

/// A perfect matching from a fractional LP point: the edges at 1 are kept, blossom matches
/// each component of the fractional edges over the candidate pairs inside it, then the rest
/// piece by piece, opening kept pairs next to a piece without a perfect matching.
fn repair(
    p: usize,
    edges: &[(usize, usize, u32)],
    x: &[f64],
    partner: &[usize],
) -> Option<Vec<usize>> {
    let mut fixed = vec![usize::MAX; p];
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] >= 1.0 - TOL {
            fixed[a] = b;
            fixed[b] = a;
        }
    }
    // First each component of the fractional edges alone, over the candidate pairs inside it.
    let mut root: Vec<usize> = (0..p).collect();
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] > TOL && x[k] < 1.0 - TOL {
            let (ra, rb) = (find(&mut root, a), find(&mut root, b));
            if ra != rb {
                root[ra] = rb;
            }
        }
    }
    let mut inside: HashMap<usize, Vec<(usize, usize, u32)>> = HashMap::new();
    let mut members: HashMap<usize, Vec<usize>> = HashMap::new();
    for v in (0..p).filter(|&v| fixed[v] == usize::MAX) {
        let r = find(&mut root, v);
        members.entry(r).or_default().push(v);
    }
    for &(a, b, w) in edges {
        if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
            let (ra, rb) = (find(&mut root, a), find(&mut root, b));
            if ra == rb {
                inside.entry(ra).or_default().push((a, b, w));
            }
        }
    }
    let mut pieces: Vec<(usize, Vec<usize>)> = members.into_iter().collect();
    pieces.sort_unstable();
    let log = std::env::var_os("MOWMILL_MATCHING_LOG").is_some();
    if log {
        let largest = pieces.iter().map(|p| p.1.len()).max().unwrap_or(0);
        eprintln!(
            "repair: {} fractional components, largest {largest}",
            pieces.len()
        );
    }
    for (r, piece) in pieces {
        if piece.len() % 2 == 1 {
            continue;
        }
        let local = |v: usize| piece.binary_search(&v).expect("a member");
        let sub: Vec<(usize, usize, u32)> = inside
            .get(&r)
            .map(|es| {
                es.iter()
                    .map(|&(a, b, w)| (local(a), local(b), w))
                    .collect()
            })
            .unwrap_or_default();
        if let Some(m) = min_weight_perfect_matching(piece.len(), &sub) {
            for (i, &v) in piece.iter().enumerate() {
                fixed[v] = piece[m[i]];
            }
        }
    }
    // Then the pieces of the candidate graph on the open endpoints; a piece without a perfect
    // matching opens the kept pairs next to it (by a candidate edge or a partner), and again.
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); p];
    for &(a, b, _) in edges {
        adjacent[a].push(b);
        adjacent[b].push(a);
    }
    for v in 0..p {
        adjacent[v].push(partner[v]);
    }
    loop {
        let open: Vec<usize> = (0..p).filter(|&v| fixed[v] == usize::MAX).collect();
        if open.is_empty() {
            return Some(fixed);
        }
        let mut root: Vec<usize> = (0..p).collect();
        let mut sub: HashMap<usize, Vec<(usize, usize, u32)>> = HashMap::new();
        for &(a, b, _) in edges {
            if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
                let (ra, rb) = (find(&mut root, a), find(&mut root, b));
                if ra != rb {
                    root[ra] = rb;
                }
            }
        }
        let mut pieces: HashMap<usize, Vec<usize>> = HashMap::new();
        for &v in &open {
            let r = find(&mut root, v);
            pieces.entry(r).or_default().push(v);
        }
        for &(a, b, w) in edges {
            if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
                let r = find(&mut root, a);
                sub.entry(r).or_default().push((a, b, w));
            }
        }
        let mut pieces: Vec<(usize, Vec<usize>)> = pieces.into_iter().collect();
        pieces.sort_unstable();
        let mut failed_pieces: Vec<Vec<usize>> = Vec::new();
        for (r, piece) in pieces {
            let local = |v: usize| piece.binary_search(&v).expect("a member");
            let es: Vec<(usize, usize, u32)> = sub
                .get(&r)
                .map(|es| {
                    es.iter()
                        .map(|&(a, b, w)| (local(a), local(b), w))
                        .collect()
                })
                .unwrap_or_default();
            let matched = if piece.len() % 2 == 0 {
                min_weight_perfect_matching(piece.len(), &es)
            } else {
                None
            };
            match matched {
                Some(m) => {
                    for (i, &v) in piece.iter().enumerate() {
                        fixed[v] = piece[m[i]];
                    }
                }
                None => failed_pieces.push(piece),
            }
        }
        if log {
            let failed: usize = failed_pieces.iter().map(Vec::len).sum();
            eprintln!("repair: {} open, {failed} failed", open.len());
        }
        if failed_pieces.is_empty() {
            return Some(fixed);
        }
        let mut released = false;
        // Open the kept pairs next to every piece without a perfect matching (an odd piece
        // grows until it meets another).
        for piece in &failed_pieces {
            for &v in piece {
                for &t in &adjacent[v] {
                    if fixed[t] != usize::MAX {
                        let u = fixed[t];
                        fixed[t] = usize::MAX;
                        fixed[u] = usize::MAX;
                        released = true;
                    }
                }
            }
        }
        if !released {
            return None;
        }
    }
}

/// A minimum-weight perfect matching of the graph on `0..n` with weighted `edges` (each
/// pair at most once), solved per connected component; `None` when none is perfect.
pub fn min_weight_perfect_matching(n: usize, edges: &[(usize, usize, u32)]) -> Option<Vec<usize>> {
    // Connected components by union-find.
    let mut root: Vec<usize> = (0..n).collect();
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

/// Above this many endpoints in the run graph, fusion-blossom runs on a partition of it
/// (still exact, one thread): its serial solver grows quadratically with the endpoints.
const SERIAL_LIMIT: usize = 8000;

/// Partition leaves of about this many run-graph vertices (above [`SERIAL_LIMIT`]).
const LEAF: usize = 4000;

/// Extents (x0, x1, y0, y1) of run-graph vertices, for the partition.
type Extent = (i32, i32, i32, i32);

/// The empty extent.
const NO_EXTENT: Extent = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);

/// Widens `e` to cover `o`.
fn widen(e: &mut Extent, o: Extent) {
    *e = (e.0.min(o.0), e.1.max(o.1), e.2.min(o.2), e.3.max(o.3));
}

/// `vertices` extents, the first ones those of the runs of `graph`, the rest empty.
fn run_extents(region: &Region, graph: &RunGraph, vertices: usize) -> Vec<Extent> {
    let mut extent = vec![NO_EXTENT; vertices];
    for (r, px) in graph.pixels.iter().enumerate() {
        for &q in px {
            let at = region.pixel(q);
            widen(&mut extent[r], (at.x, at.x, at.y, at.y));
        }
    }
    extent
}

/// The run graph of a region: its maximal horizontal and vertical runs of pixels, joined by
/// an edge where they cross (one turn). For two strip ends, the turn distance is the
/// distance between their runs in this graph (see [`run_graph_matching`]).
struct RunGraph {
    /// The horizontal and the vertical run through every pixel.
    hrun: Vec<usize>,
    vrun: Vec<usize>,
    /// The pixels of every run, in order.
    pixels: Vec<Vec<usize>>,
    /// Whether a run is vertical.
    vertical: Vec<bool>,
}

impl RunGraph {
    fn new(region: &Region) -> RunGraph {
        let n = region.len();
        let mut g = RunGraph {
            hrun: vec![usize::MAX; n],
            vrun: vec![usize::MAX; n],
            pixels: Vec::new(),
            vertical: Vec::new(),
        };
        for s in 0..n {
            for (vertical, back, fwd) in [(false, Dir::W, Dir::E), (true, Dir::S, Dir::N)] {
                let run = if vertical { &mut g.vrun } else { &mut g.hrun };
                if run[s] != usize::MAX {
                    continue;
                }
                let mut q = s;
                while let Some(b) = region.neighbor(q, back) {
                    q = b;
                }
                let mut px = vec![q];
                while let Some(f) = region.neighbor(q, fwd) {
                    q = f;
                    px.push(q);
                }
                for &q in &px {
                    run[q] = g.pixels.len();
                }
                g.pixels.push(px);
                g.vertical.push(vertical);
            }
        }
        g
    }

    /// The run a strip end leaves along, if its headings are exactly one axis.
    fn run_of(&self, port: Port) -> Option<usize> {
        let v = bit(Dir::N) | bit(Dir::S);
        let h = bit(Dir::E) | bit(Dir::W);
        match port.leave {
            l if l == v => Some(self.vrun[port.pixel]),
            l if l == h => Some(self.hrun[port.pixel]),
            _ => None,
        }
    }

    /// The run crossing run `r` at pixel `px`.
    fn crossing(&self, r: usize, px: usize) -> usize {
        if self.vertical[r] {
            self.hrun[px]
        } else {
            self.vrun[px]
        }
    }
}

/// An exact minimum-weight perfect matching of strip ends over ALL pairs, as a minimum-weight
/// perfect matching of vertices in a graph metric, solved by fusion-blossom (an exact
/// primal–dual blossom algorithm on the graph itself, so no pair needs to be listed).
///
/// The graph: the [`RunGraph`] (crossing runs at weight 2 = one turn), and per endpoint a
/// vertex hanging from its run at weight 2. Two endpoints are then at distance 4 + 2·w,
/// w their turn distance: every perfect matching costs 2P + 2·w(M), the same order. A
/// path of the 0-1 search maps to a walk in the run graph with one edge per turn and back
/// (a strip end leaves in both headings of its axis, so the first and last run may be
/// walked either way).
///
/// A one-pixel strip (`floor` 2, both ends the same port) costs 2 when matched to itself,
/// not its turn distance 0; the metric cannot say that directly, so:
/// - if its run R carries another endpoint, or another such strip, the strip is taken out
///   and put back afterwards at no cost: a path u – a₁b₁ – … – a_kb_k – v through strips on R
///   costs at least w(u, R) + w(R, v) ≥ w(u, v), so leaving them out loses nothing, and
///   threading them into the pair of an endpoint x on R (x – a₁, b₁ – a₂, …, b_k – mate(x)),
///   or closing them among themselves, costs exactly that much again;
/// - otherwise (every other endpoint is at least one turn from R) its two ends hang from the
///   runs crossing R at weight 4 (one turn more), which keeps their distance 4 + 2w to every
///   other endpoint and makes theirs 8 (= 2 turns); two such strips on crossing runs get a
///   direct edge of weight 6 (1 turn).
///
/// The matching's weights are then recounted by 0-1 searches, and the lower bound is the
/// solver's dual objective (Σ of its dual variables, (Σ − 2P')/2 turns for P' endpoints in
/// the graph), a lower bound by weak LP duality: `optimal` exactly when the recount
/// reaches it. `None` when the endpoints are not all strip ends with floors as above, or the
/// solver fails (the caller falls back to [`priced_matching`]).
fn run_graph_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Option<Result<PortMatching>> {
    let p = ports.len();
    let graph = RunGraph::new(region);
    let mut run = Vec::with_capacity(p);
    for (i, &port) in ports.iter().enumerate() {
        run.push(graph.run_of(port)?);
        let one_pixel = floor[i] == 2 && ports[partner[i]] == port && floor[partner[i]] == 2;
        if floor[i] != 0 && !one_pixel {
            return None;
        }
    }
    let one_pixel = |i: usize| floor[i] != 0;
    let runs = graph.pixels.len();
    let (mut others, mut singles) = (vec![0usize; runs], vec![0usize; runs]);
    for i in 0..p {
        if !one_pixel(i) {
            others[run[i]] += 1;
        } else if i < partner[i] {
            singles[run[i]] += 1;
        }
    }
    let removed = |i: usize| one_pixel(i) && (others[run[i]] > 0 || singles[run[i]] >= 2);
    // Vertices: runs, then the endpoints kept.
    let mut edges: Vec<(usize, usize, isize)> = (0..region.len())
        .map(|px| (graph.hrun[px], graph.vrun[px], 2))
        .collect();
    let mut kept: Vec<usize> = Vec::new();
    let mut vertex_of = vec![usize::MAX; p];
    for i in (0..p).filter(|&i| !removed(i)) {
        vertex_of[i] = runs + kept.len();
        kept.push(i);
        if one_pixel(i) {
            let r = run[i];
            for &px in &graph.pixels[r] {
                edges.push((graph.crossing(r, px), vertex_of[i], 4));
            }
        } else {
            edges.push((run[i], vertex_of[i], 2));
        }
    }
    // Lone one-pixel strips on crossing runs: one turn apart.
    let mut lone: HashMap<usize, Vec<usize>> = HashMap::new();
    for &i in kept.iter().filter(|&&i| one_pixel(i)) {
        lone.entry(run[i]).or_default().push(i);
    }
    for (&r, ends) in &lone {
        for &px in &graph.pixels[r] {
            let c = graph.crossing(r, px);
            if let Some(theirs) = lone.get(&c).filter(|_| r < c) {
                for &a in ends {
                    for &b in theirs {
                        edges.push((vertex_of[a], vertex_of[b], 6));
                    }
                }
            }
        }
    }
    let vertices = runs + kept.len();
    let (mut mate, dual) = mates_of(p, || {
        solve_graph_matching(SERIAL_LIMIT, vertices, edges, &kept, &vertex_of, |edges| {
            // A run spans its pixels; an endpoint the runs it hangs from.
            let mut extent = run_extents(region, &graph, vertices);
            for &(a, b, _) in edges {
                if a < runs && b >= runs {
                    let o = extent[a];
                    widen(&mut extent[b], o);
                }
            }
            extent
        })
    })?;
    if kept.iter().any(|&i| mate[i] == usize::MAX) {
        return None;
    }
    // Put the one-pixel strips taken out back in, run by run.
    let mut taken: HashMap<usize, Vec<usize>> = HashMap::new();
    for i in (0..p).filter(|&i| removed(i) && i < partner[i]) {
        taken.entry(run[i]).or_default().push(i);
    }
    let mut taken: Vec<(usize, Vec<usize>)> = taken.into_iter().collect();
    taken.sort_unstable();
    let mut on_run: HashMap<usize, usize> = HashMap::new();
    for &i in &kept {
        if !one_pixel(i) {
            on_run.entry(run[i]).or_insert(i);
        }
    }
    let pair = |mate: &mut [usize], a: usize, b: usize| {
        mate[a] = b;
        mate[b] = a;
    };
    for (r, strips) in taken {
        match on_run.get(&r) {
            // Threaded between x and its mate: x – a₁, b₁ – a₂, …, b_k – mate(x).
            Some(&x) => {
                let y = mate[x];
                let mut prev = x;
                for &a in &strips {
                    pair(&mut mate, prev, a);
                    prev = partner[a];
                }
                pair(&mut mate, prev, y);
            }
            // Closed among themselves (at least two): b₁ – a₂, …, b_k – a₁.
            None => {
                for k in 0..strips.len() {
                    pair(
                        &mut mate,
                        partner[strips[k]],
                        strips[(k + 1) % strips.len()],
                    );
                }
            }
        }
    }
    // Every pair of the graph costs 4 + 2w, over the P' endpoints kept.
    Some(recount(region, ports, partner, floor, mate).map(|m| certified(m, dual, kept.len())))
}

/// Above this many edges in the ray graph of [`link_graph_matching`] (its pairs of rays
/// sharing a pixel grow quadratically where many rays cross), the LP route is taken instead.
const RAY_GRAPH_EDGES: usize = 4_000_000;

/// Above this many link ends, fusion-blossom runs on a partition of the ray graph (its
/// partitioned solver panicked on a ray graph of 8,274 ends; serially that takes 1 s).
const RAY_SERIAL_LIMIT: usize = 40_000;

/// An exact minimum-weight perfect matching of boundary link ends (one heading each) over ALL
/// pairs, as a minimum-weight perfect matching of vertices in a graph metric, solved by
/// fusion-blossom (see [`run_graph_matching`] for strip ends).
///
/// # The turn distance of one-heading ends
/// The ray F_u of an end u is the part of its run (the maximal run through its pixel along
/// its heading) from its pixel on in its heading: the pixels a path leaving u reaches before
/// its first turn; symmetrically a path arriving at v ends with a piece of F_v. Let A_u be
/// the runs crossing F_u. Then
///
/// - if F_u and F_v share a pixel q, w(u, v) = the quarter turns from u's heading to the
///   reverse of v's (turn in place at q; no path does better): 0 for facing rays on one run,
///   1 for crossing rays, 2 for rays of one heading;
/// - otherwise w(u, v) = 2 + min over C ∈ A_u, D ∈ A_v of dist(C, D), the distance in the
///   run graph ([`RunGraph`], one edge per turn). A path with k ≥ 2 turns runs along F_u,
///   turns onto C ∈ A_u, then along whole runs, and turns from D ∈ A_v onto F_v; after its
///   first turn it may walk its run either way (it could have turned the other way at the
///   same cost), so its middle runs form a walk C … D with k − 2 edges. Conversely every such
///   walk is a path. With k ≤ 1 turns the rays share a pixel.
///
/// Unlike strip ends, w is no metric: two ends facing a third (w = 0) may be 2 apart.
/// But w(u, v) ≤ w(u, x) + w(x, v) + 2 (join the paths with a U-turn at x), so
/// W = 2w + 4 is one, and every perfect matching costs 2P + 2·w(M), the same order.
///
/// # The graph
/// Its vertices are the runs, the endpoints, and clones of some runs (below); crossing runs
/// are joined at weight 2 (a turn), an end hangs from every run of A_u at weight 4 (a turn
/// plus its offset), so the path u – C … D – v costs exactly W for the second case. Pairs
/// whose rays share a pixel get an edge of their own, W = 4 (facing) or 6 (crossing); rays of
/// one heading sharing a pixel meet at the run crossing there (W = 8). Any path of the graph
/// splits at the ends it passes into such pieces, each a path of the region of its weight,
/// and by the inequality above it costs at least W: distances are exactly W. (The facing and
/// crossing pairs cannot share gadgets: the midpoints of their shortest paths are distinct for
/// distinct pairs, so their count is inherent.)
///
/// # One-pixel links
/// The two ends a (heading W or S) and b (E or N) of a one-pixel link at pixel p cost
/// `floor` = 4 when matched together, not their w = 0. W stays a metric with W(a, b) = 12:
/// for every other end x, w(a, x) + w(b, x) ≥ 2 (x facing a has b's heading, and x one turn
/// from a is an odd number of turns from b). In the graph, the facing edge a – b is left out,
/// a hangs from the run C crossing at p and b from a clone C' of C (joined to every copy of
/// C's crossing runs, and hung from by every other end that hangs from C); crossing runs are
/// copied both ways. Then a – b costs 12 (C and C' are at least two edges apart, other runs
/// of A_a and A_b too, being parallel to C), and the ends a', b' of other one-pixel links
/// crossing C, 2 turns from b, a, get direct edges a – b', a' – b of weight 8.
///
/// The matching's weights are recounted by 0-1 searches, and the lower bound is the
/// solver's dual objective, as in [`run_graph_matching`]. `None` when an end has other than
/// one heading, a floor is not of a one-pixel link as above, the graph exceeds
/// [`RAY_GRAPH_EDGES`] edges, or the solver fails (the caller falls back to
/// [`priced_matching`]).
fn link_graph_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Option<Result<PortMatching>> {
    let p = ports.len();
    let heading: Vec<Dir> = ports
        .iter()
        .map(|port| Dir::ALL.into_iter().find(|&d| port.leave == bit(d)))
        .collect::<Option<_>>()?;
    for i in 0..p {
        let j = partner[i];
        let one_pixel = ports[j].pixel == ports[i].pixel
            && heading[j] == heading[i].opposite()
            && floor[j] == 4;
        if floor[i] != 0 && !(floor[i] == 4 && one_pixel) {
            return None;
        }
    }
    let one_pixel = |i: usize| floor[i] != 0;
    let forward = |i: usize| matches!(heading[i], Dir::E | Dir::N);
    let graph = RunGraph::new(region);
    let runs = graph.pixels.len();
    // The position of every pixel in its horizontal (even slots) and vertical run.
    let mut pos = vec![0usize; 2 * region.len()];
    for (r, px) in graph.pixels.iter().enumerate() {
        for (k, &q) in px.iter().enumerate() {
            pos[2 * q + usize::from(graph.vertical[r])] = k;
        }
    }
    let along: Vec<usize> = (0..p)
        .map(|i| match heading[i] {
            Dir::E | Dir::W => graph.hrun[ports[i].pixel],
            Dir::N | Dir::S => graph.vrun[ports[i].pixel],
        })
        .collect();
    let at = |i: usize| pos[2 * ports[i].pixel + usize::from(graph.vertical[along[i]])];
    let ray = |i: usize| {
        let px = &graph.pixels[along[i]];
        if forward(i) {
            &px[at(i)..]
        } else {
            &px[..=at(i)]
        }
    };
    // Clones (vertices runs..) of the runs crossing one-pixel links.
    let mut clone: HashMap<usize, usize> = HashMap::new();
    let mut origin: Vec<usize> = Vec::new();
    for i in (0..p).filter(|&i| one_pixel(i)) {
        let c = graph.crossing(along[i], ports[i].pixel);
        clone.entry(c).or_insert_with(|| {
            origin.push(c);
            runs + origin.len() - 1
        });
    }
    let copies = |r: usize| std::iter::once(r).chain(clone.get(&r).copied());
    let first_end = runs + origin.len();
    let vertex_of: Vec<usize> = (0..p).map(|i| first_end + i).collect();
    let full = |edges: &Vec<(usize, usize, isize)>| edges.len() > RAY_GRAPH_EDGES;
    let mut edges: Vec<(usize, usize, isize)> = Vec::new();
    for px in 0..region.len() {
        for a in copies(graph.hrun[px]) {
            for b in copies(graph.vrun[px]) {
                edges.push((a, b, 2));
            }
        }
    }
    // Ends hang from the runs crossing their rays; (pixel, vertical, end) along every ray.
    let mut through: Vec<(usize, bool, usize)> = Vec::new();
    for i in 0..p {
        for &q in ray(i) {
            let c = graph.crossing(along[i], q);
            if one_pixel(i) && q == ports[i].pixel {
                let v = if forward(i) { clone[&c] } else { c };
                edges.push((v, vertex_of[i], 4));
            } else {
                for v in copies(c) {
                    edges.push((v, vertex_of[i], 4));
                }
            }
            through.push((q, graph.vertical[along[i]], i));
        }
        if full(&edges) {
            return None;
        }
    }
    // Rays crossing at a pixel: one turn.
    through.sort_unstable();
    for group in through.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for a in &group[..split] {
            for b in &group[split..] {
                edges.push((vertex_of[a.2], vertex_of[b.2], 6));
            }
        }
        if full(&edges) {
            return None;
        }
    }
    // Rays facing each other on one run: no turn (not the two ends of a one-pixel link).
    let mut on_run: Vec<(usize, bool, usize, usize)> =
        (0..p).map(|i| (along[i], !forward(i), at(i), i)).collect();
    on_run.sort_unstable();
    for group in on_run.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for &(_, _, x, u) in &group[..split] {
            for &(_, _, y, v) in &group[split..] {
                if x <= y && !(one_pixel(u) && partner[u] == v) {
                    edges.push((vertex_of[u], vertex_of[v], 4));
                }
            }
        }
        if full(&edges) {
            return None;
        }
    }
    // Ends of different one-pixel links crossing one run, hung from C and C': two turns.
    let mut lone: Vec<(usize, bool, usize)> = (0..p)
        .filter(|&i| one_pixel(i))
        .map(|i| (graph.crossing(along[i], ports[i].pixel), forward(i), i))
        .collect();
    lone.sort_unstable();
    for group in lone.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for &(_, _, a) in &group[..split] {
            for &(_, _, b) in &group[split..] {
                if partner[a] != b {
                    edges.push((vertex_of[a], vertex_of[b], 8));
                }
            }
        }
        if full(&edges) {
            return None;
        }
    }
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        eprintln!(
            "ray graph: {p} ends, {runs} runs, {} clones, {} edges",
            origin.len(),
            edges.len()
        );
    }
    let kept: Vec<usize> = (0..p).collect();
    let vertices = first_end + p;
    let (mate, dual) = mates_of(p, || {
        solve_graph_matching(
            RAY_SERIAL_LIMIT,
            vertices,
            edges,
            &kept,
            &vertex_of,
            |edges| {
                // A run spans its pixels, a clone its run's, an end its own run and those it
                // hangs from (so that every edge joins vertices whose extents meet).
                let mut extent = run_extents(region, &graph, vertices);
                for (k, &c) in origin.iter().enumerate() {
                    extent[runs + k] = extent[c];
                }
                for i in 0..p {
                    let o = extent[along[i]];
                    widen(&mut extent[vertex_of[i]], o);
                }
                for &(a, b, _) in edges {
                    if a < first_end && b >= first_end {
                        let o = extent[a];
                        widen(&mut extent[b], o);
                    }
                }
                extent
            },
        )
    })?;
    if mate.contains(&usize::MAX) {
        return None;
    }
    let m = recount(region, ports, partner, floor, mate).map(|m| certified(m, dual, p));
    if let Ok(m) = &m
        && std::env::var_os("MOWMILL_MATCHING_LOG").is_some()
    {
        eprintln!("ray graph: w(M) {}, bound {}", m.total, m.lower_bound);
    }
    Some(m)
}

/// The certificates of a graph-metric matching `m` of `p` endpoints whose every pair cost
/// 4 + 2w in the graph, the solver's dual objective `dual`: Σ duals ≤ 2P + 2·w(M) for every
/// perfect matching M, so ⌈(dual − 2P)/2⌉ is a lower bound on w(M).
fn certified(mut m: PortMatching, dual: i64, p: usize) -> PortMatching {
    let lower = (dual - 2 * p as i64 + 1).div_euclid(2).max(0) as u64;
    m.complete = true;
    m.optimal = m.total <= lower;
    m.lower_bound = lower.min(m.total);
    m.candidates = m.mate.len() * (m.mate.len() - 1) / 2;
    m
}

/// Runs a fusion-blossom solve (a panic of the library counts as a failure) and turns its
/// pairs into partners over `p` ports (`usize::MAX` where unmatched), with the dual sum.
fn mates_of(
    p: usize,
    solve: impl FnOnce() -> Option<(Vec<(usize, usize)>, i64)>,
) -> Option<(Vec<usize>, i64)> {
    let (pairs, dual) = std::panic::catch_unwind(std::panic::AssertUnwindSafe(solve)).ok()??;
    let mut mate = vec![usize::MAX; p];
    for (a, b) in pairs {
        mate[a] = b;
        mate[b] = a;
    }
    Some((mate, dual))
}

/// Solves the run-graph matching with fusion-blossom: the matched endpoint pairs and the sum
/// of the dual variables. One thread; above [`SERIAL_LIMIT`] endpoints on a recursive
/// bisection of the graph (fusion-blossom's partitioned solver, still exact).
///
/// `extent` gives every vertex's extent (only called above [`SERIAL_LIMIT`] endpoints): the
/// extents of two vertices joined by an edge must meet.
fn solve_graph_matching(
    serial_limit: usize,
    vertices: usize,
    edges: Vec<(usize, usize, isize)>,
    kept: &[usize],
    vertex_of: &[usize],
    extent: impl FnOnce(&[(usize, usize, isize)]) -> Vec<Extent>,
) -> Option<(Vec<(usize, usize)>, i64)> {
    let defect_port: HashMap<usize, usize> = kept.iter().map(|&i| (vertex_of[i], i)).collect();
    let (perm, partitions, fusions) = if kept.len() <= serial_limit {
        (
            (0..vertices).collect::<Vec<usize>>(),
            Vec::new(),
            Vec::new(),
        )
    } else {
        bisection(&extent(&edges))
    };
    let mut position = vec![0usize; vertices];
    for (k, &v) in perm.iter().enumerate() {
        position[v] = k;
    }
    let init = SolverInitializer::new(
        vertices,
        edges
            .iter()
            .map(|&(a, b, w)| (position[a], position[b], w))
            .collect(),
        Vec::new(),
    );
    let mut defects: Vec<usize> = kept.iter().map(|&i| position[vertex_of[i]]).collect();
    defects.sort_unstable();
    let syndrome = SyndromePattern::new_vertices(defects);
    let matching = if partitions.is_empty() {
        let mut solver = SolverSerial::new(&init);
        solver.solve(&syndrome);
        (solver.perfect_matching(), solver.sum_dual_variables())
    } else {
        let mut config = PartitionConfig::new(vertices);
        config.partitions = partitions
            .iter()
            .map(|&(a, b)| VertexRange::new(a, b))
            .collect();
        config.fusions = fusions;
        let one_thread = serde_json::json!({
            "dual": { "thread_pool_size": 1 },
            "primal": { "thread_pool_size": 1 },
        });
        let mut solver = SolverParallel::new(&init, &config.info(), one_thread);
        solver.solve(&syndrome);
        (solver.perfect_matching(), solver.sum_dual_variables())
    };
    let (perfect, dual) = matching;
    if !perfect.virtual_matchings.is_empty() {
        return None;
    }
    let port_of =
        |node: &fusion_blossom::dual_module::DualNodePtr| match node.read_recursive().class {
            DualNodeClass::DefectVertex { defect_index } => {
                defect_port.get(&perm[defect_index]).copied()
            }
            DualNodeClass::Blossom { .. } => None,
        };
    let mut pairs = Vec::with_capacity(kept.len() / 2);
    for (a, b) in &perfect.peer_matchings {
        pairs.push((port_of(a)?, port_of(b)?));
    }
    Some((pairs, dual as i64))
}

/// A recursive bisection of the run graph for fusion-blossom's partitioned solver: an order
/// of the vertices in which every unit is a range (left part, separator, right part), the
/// leaf ranges, and the fusions (pairs of units, children before parents). A separator is
/// every vertex whose extent meets the cut line; edges join vertices whose extents meet, so
/// none joins the two sides.
#[allow(clippy::type_complexity)]
fn bisection(extent: &[Extent]) -> (Vec<usize>, Vec<(usize, usize)>, Vec<(usize, usize)>) {
    enum Tree {
        Leaf(usize, usize),
        Node(Box<Tree>, Box<Tree>),
    }
    fn build(set: Vec<usize>, extent: &[Extent], order: &mut Vec<usize>) -> Tree {
        let leaf = |set: &[usize], order: &mut Vec<usize>| {
            let start = order.len();
            order.extend_from_slice(set);
            Tree::Leaf(start, order.len())
        };
        if set.len() <= LEAF {
            return leaf(&set, order);
        }
        let b = set
            .iter()
            .fold((i32::MAX, i32::MIN, i32::MAX, i32::MIN), |a, &v| {
                let e = extent[v];
                (a.0.min(e.0), a.1.max(e.1), a.2.min(e.2), a.3.max(e.3))
            });
        let across = b.1 - b.0 >= b.3 - b.2;
        let span = |v: usize| {
            let e = extent[v];
            if across { (e.0, e.1) } else { (e.2, e.3) }
        };
        let mut keys: Vec<i32> = set.iter().map(|&v| span(v).0 + span(v).1).collect();
        keys.sort_unstable();
        // Twice the cut line.
        let cut = keys[keys.len() / 2];
        let (mut left, mut middle, mut right) = (Vec::new(), Vec::new(), Vec::new());
        for &v in &set {
            let (lo, hi) = span(v);
            if 2 * hi < cut {
                left.push(v);
            } else if 2 * lo > cut {
                right.push(v);
            } else {
                middle.push(v);
            }
        }
        if left.is_empty() || right.is_empty() {
            return leaf(&set, order);
        }
        let l = build(left, extent, order);
        order.extend_from_slice(&middle);
        let r = build(right, extent, order);
        Tree::Node(Box::new(l), Box::new(r))
    }
    fn leaves(t: &Tree, out: &mut Vec<(usize, usize)>) {
        match t {
            Tree::Leaf(a, b) => out.push((*a, *b)),
            Tree::Node(l, r) => {
                leaves(l, out);
                leaves(r, out);
            }
        }
    }
    fn fuse(t: &Tree, next: &mut usize, base: usize, out: &mut Vec<(usize, usize)>) -> usize {
        match t {
            Tree::Leaf(..) => {
                *next += 1;
                *next - 1
            }
            Tree::Node(l, r) => {
                let a = fuse(l, next, base, out);
                let b = fuse(r, next, base, out);
                out.push((a, b));
                base + out.len() - 1
            }
        }
    }
    let mut order = Vec::with_capacity(extent.len());
    let tree = build((0..extent.len()).collect(), extent, &mut order);
    let mut parts = Vec::new();
    leaves(&tree, &mut parts);
    let mut fusions = Vec::new();
    fuse(&tree, &mut 0, parts.len(), &mut fusions);
    (order, parts, fusions)
}

/// The matching `mate` with every pair's turn distance (at least the floor for partners)
/// recounted by a 0-1 search.
fn recount(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    mate: Vec<usize>,
) -> Result<PortMatching> {
    let p = ports.len();
    let mut search = TurnSearch::new(region);
    let mut weight = vec![0u32; p];
    let mut total = 0u64;
    for i in 0..p {
        let j = mate[i];
        if mate[j] != i || i == j {
            return Err(Error::invalid(
                "the run-graph matching is not a perfect matching",
            ));
        }
        if i < j {
            let target = ports[j];
            search.run(region, ports[i], u32::MAX, |px, h, _| {
                px == target.pixel && target.arrive() & bit(h) != 0
            });
            let mut d = search.distance_to(target).ok_or_else(|| {
                Error::invalid(format!("matched endpoints {i} and {j} are not connected"))
            })?;
            if j == partner[i] {
                d = d.max(floor[i]);
            }
            weight[i] = d;
            total += u64::from(d);
        }
    }
    Ok(PortMatching {
        mate,
        weight,
        total,
        complete: false,
        optimal: false,
        lower_bound: 0,
        candidates: 0,
    })
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
