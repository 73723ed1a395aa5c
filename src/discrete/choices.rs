//! The choices the paper leaves open in the greedy star cover, and evidence over all of them:
//! does a violated bound depend on the order of the greedy choices, or survive every order?
//!
//! # Which choices are open
//! Lemma 4.5 of *Optimal covering tours with turn costs* places rooks "greedily" and Theorem 5.1
//! tours their stars; neither fixes
//! 1. the **scan order** of the greedy rook placement (which unattacked vertex becomes the next
//!    rook; ties in it are the same choice) — [`GreedyOrder`], `Options::greedy_order`;
//! 2. which closed channel an unattacked ring vertex takes (0 turns whichever: it changes no
//!    turn count), and where each petal is cut open (the cut saves the most turns; ties give
//!    equal turns);
//! 3. the **merge order** of Theorem 4.2 / Corollary 5.1 (which cycles are joined first).
//!
//! Only choice 1 changes the cycle cover's turns. Choice 3 changes the tour; it is not
//! enumerated here: [`ChoiceValue::TourTurns`] runs the one merge of
//! [`merge`](super::merge::merge) on each cover, so its evidence is over rook orders only.
//! A bound *on every merge order* is decided by a lower bound on every tour instead (the exact
//! tour optimum, as for Theorem 4.2 on `bridge.dm`).
//!
//! # Why the rook sets are the choices that matter
//! A scan order yields a set S of rooks: pairwise non-attacking (no channel holds two),
//! off closed channels, and attacking every vertex off closed channels, i.e. a *maximal*
//! independent set of the attack graph A (vertices off closed channels, adjacent when they share
//! a channel). Conversely every maximal independent set S is the outcome of every order that
//! scans S first (each vertex of S is unattacked when reached; after S every candidate is
//! attacked). The cycle cover depends only on S ([`star_cover_of_rooks`], rooks in index
//! order). So enumerating the maximal independent sets of A (Bron–Kerbosch with pivoting) is
//! enumerating the outcomes of all n! scan orders; [`OrderEvidence::exhaustive`] says it was
//! done completely (at most [`EXHAUSTIVE_CAP`] sets). Beyond the cap, `tried` seeded random
//! orders (ChaCha8) are run, and the evidence says only "all / v of k sampled orders".
//!
//! # A proof for every order: hubs on one path
//! The family of [`hub_path`]: a straight path v_0 … v_{P−1} (collinear at every inner
//! vertex) and K hubs, hub h_j joined by unmatched edges to its own run R_j of p_j inner path
//! vertices (runs disjoint). For **every** scan order, the rook set S is:
//! - exactly one path vertex x: v_0 lies only on the path's channel, so a rook attacking it lies
//!   on the path, and the path holds at most one rook;
//! - every hub h_i with x ∉ R_i: h_i's channels are its spokes h_i–v (v ∈ R_i), a spoke is taken
//!   only by a rook at h_i or at v, and no v ∈ R_i is a rook, so h_i is unattacked unless it is a
//!   rook; and h_j is not a rook when x ∈ R_j (the spoke x–h_j).
//!
//! The star walks cost (module docs of [`star_cover`](super::star_cover)): a hub with p ≥ 2
//! spokes 3p (each spoke ends at the hub: a doubled edge, one U-turn left, one join), with one
//! spoke 4; x in R_j costs 5 + 3 = 8 (the path passes straight, plus its spoke); x in no run 4.
//! So every order gives at least 8 + 3·(Σ_i p_i − max_j p_j) turns (all p_i ≥ 2), attained by
//! x in a largest run. The tests check this formula against the exhaustive enumeration.
//!
//! # Complexity
//! Exhaustive: O(|S-sets| · (n + |E|)) after an O(n²/64)-word attack matrix (only when at most
//! [`EXHAUSTIVE_MAX_VERTICES`] vertices are candidates); sampled: O(k · (n + |E|)).

use super::Discrete;
use super::check::check;
use super::merge::merge;
use super::star_cover::{Channels, channels, channels_at, on_closed_channel, star_cover_of_rooks};
use crate::algorithms::GreedyOrder;
use crate::error::{Error, Result};
use serde::Serialize;
use std::collections::BTreeSet;

/// At most this many rook sets are enumerated; more, and orders are sampled instead (7!).
pub const EXHAUSTIVE_CAP: u64 = 5040;
/// Sampled orders when the enumeration exceeds the cap ([`order_evidence`]).
pub const SAMPLED_ORDERS: u64 = 1000;
/// The attack matrix is built only up to this many candidate vertices.
pub const EXHAUSTIVE_MAX_VERTICES: usize = 4096;

/// The algorithms whose open choices this module enumerates (`star-cover` on a discrete
/// instance is the same construction).
pub const ALGORITHMS: [&str; 2] = ["discrete-star-cover", "star-cover"];

/// The value measured for each choice sequence.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum ChoiceValue {
    /// The cycle cover's turns, recounted by the checker (Theorem 5.1).
    CcTurns,
    /// The merged tour's turns, recounted (Corollary 5.1; the merge in its one order).
    TourTurns,
    /// Theorem 4.2's budget for the cycle cover, t + 2c − 2 (t its turns, c its cycles): a tour
    /// "at most t + 2c − 2" exists by the theorem, so a lower bound on every tour above it
    /// contradicts the statement for every merge order.
    MergeBudget,
}

impl ChoiceValue {
    pub const NAMES: [&'static str; 3] = ["cc-turns", "turns", "merge-budget"];

    pub fn name(self) -> &'static str {
        match self {
            ChoiceValue::CcTurns => "cc-turns",
            ChoiceValue::TourTurns => "turns",
            ChoiceValue::MergeBudget => "merge-budget",
        }
    }
}

impl std::str::FromStr for ChoiceValue {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<ChoiceValue, String> {
        match s {
            "cc-turns" => Ok(ChoiceValue::CcTurns),
            "turns" | "tour-turns" => Ok(ChoiceValue::TourTurns),
            "merge-budget" => Ok(ChoiceValue::MergeBudget),
            _ => Err(format!(
                "unknown value {s:?}: expected cc-turns, turns or merge-budget"
            )),
        }
    }
}

/// Which choice sequences to try.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrderSearch {
    /// Every rook set when there are at most `cap`; else `samples` seeded orders.
    All { cap: u64, samples: u64, seed: u64 },
    /// `orders` seeded random scan orders (seeds `seed`, `seed + 1`, …).
    Sampled { orders: u64, seed: u64 },
}

impl Default for OrderSearch {
    fn default() -> Self {
        OrderSearch::All {
            cap: EXHAUSTIVE_CAP,
            samples: SAMPLED_ORDERS,
            seed: 0,
        }
    }
}

/// What the greedy choices gave on one instance.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct OrderEvidence {
    pub algorithm: String,
    pub value: &'static str,
    /// Choice sequences evaluated: rook sets when `exhaustive` (each stands for every scan order
    /// that yields it), else sampled scan orders.
    pub tried: u64,
    /// Distinct rook sets among them.
    pub distinct: u64,
    /// Whether every rook set (every scan order's outcome) was evaluated.
    pub exhaustive: bool,
    /// How many of `tried` violate the bound.
    pub violated: u64,
    pub min: u64,
    pub max: u64,
    /// The value of the default order (index order), and whether it violates.
    pub default_value: u64,
    pub default_violates: bool,
    /// A rook set that violates, and one that does not (when some exist).
    pub violating_rooks: Option<Vec<u32>>,
    pub meeting_rooks: Option<Vec<u32>>,
}

impl OrderEvidence {
    /// Whether every order of the greedy choices violates, as established (exhaustively).
    pub fn every_order_violates(&self) -> bool {
        self.exhaustive && self.tried > 0 && self.violated == self.tried
    }

    /// One sentence for a claims note: "violated by every order (all 31 rook sets)", "violated
    /// by 30 of 31 rook sets (exhaustive)", "violated by all 1000 sampled orders", ….
    pub fn summary(&self) -> String {
        let what = if self.exhaustive {
            "rook sets, exhaustive"
        } else {
            "sampled orders"
        };
        if self.every_order_violates() {
            format!(
                "violated by every order of the greedy choices (all {} rook sets)",
                self.tried
            )
        } else if self.violated == self.tried && self.tried > 0 {
            format!(
                "violated by all {} sampled orders (not exhaustive)",
                self.tried
            )
        } else if self.violated == 0 {
            format!("violated by no order ({} {what})", self.tried)
        } else {
            format!(
                "depends on the order: violated by {} of {} {what}",
                self.violated, self.tried
            )
        }
    }
}

/// Runs the star cover over the open choices of its greedy order and counts the violations of
/// a bound: [`order_evidence_with`] with [`OrderSearch::default`] (exhaustive up to
/// [`EXHAUSTIVE_CAP`] rook sets, else [`SAMPLED_ORDERS`] seeded orders).
///
/// # Arguments
/// * `algorithm` — `discrete-star-cover` (or `star-cover`, the same construction); others are
///   an error. A grid region enters as [`Discrete::from_region`] (same rooks and cycle cover
///   as the grid `star-cover`; the tour is the discrete merge's).
/// * `value` — what is measured per choice sequence ([`ChoiceValue`]).
/// * `violates` — whether a value violates the claim, e.g. `|v| v as f64 > (ρ + 2δ)·OPT_cc`, or
///   `|budget| budget < opt_tour_lower_bound` for [`ChoiceValue::MergeBudget`].
///
/// # Returns
/// The [`OrderEvidence`]; "every order" may be claimed only from
/// [`OrderEvidence::every_order_violates`] (exhaustive), or from a proof (module docs).
///
/// # Errors
/// An unknown algorithm, or an instance that is not connected.
pub fn order_evidence(
    algorithm: &str,
    inst: &Discrete,
    value: ChoiceValue,
    violates: impl Fn(u64) -> bool,
) -> Result<OrderEvidence> {
    order_evidence_with(algorithm, inst, value, violates, OrderSearch::default())
}

/// [`order_evidence`] with the search chosen.
pub fn order_evidence_with(
    algorithm: &str,
    inst: &Discrete,
    value: ChoiceValue,
    violates: impl Fn(u64) -> bool,
    search: OrderSearch,
) -> Result<OrderEvidence> {
    if !ALGORITHMS.contains(&algorithm) {
        return Err(Error::invalid(format!(
            "order evidence: algorithm {algorithm} has no enumerated choices (expected {})",
            ALGORITHMS.join(" or ")
        )));
    }
    if inst.is_empty() || inst.components() != 1 {
        return Err(Error::invalid(
            "order evidence: the instance is not connected".to_string(),
        ));
    }
    let ch = channels(inst);
    let measure = |rooks: &[u32]| measure(inst, &ch, rooks, value);
    let default_rooks = super::star_cover::star_cover(inst).rooks;
    let default_value = measure(&default_rooks);
    let mut ev = OrderEvidence {
        algorithm: algorithm.to_string(),
        value: value.name(),
        tried: 0,
        distinct: 0,
        exhaustive: false,
        violated: 0,
        min: u64::MAX,
        max: 0,
        default_value,
        default_violates: violates(default_value),
        violating_rooks: None,
        meeting_rooks: None,
    };
    let record = |ev: &mut OrderEvidence, rooks: &[u32], v: u64| {
        ev.tried += 1;
        ev.min = ev.min.min(v);
        ev.max = ev.max.max(v);
        if violates(v) {
            ev.violated += 1;
            if ev.violating_rooks.is_none() {
                ev.violating_rooks = Some(rooks.to_vec());
            }
        } else if ev.meeting_rooks.is_none() {
            ev.meeting_rooks = Some(rooks.to_vec());
        }
    };
    let (samples, seed) = match search {
        OrderSearch::All { cap, samples, seed } => {
            if let Some(sets) = rook_sets(inst, &ch, cap) {
                ev.exhaustive = true;
                ev.distinct = sets.len() as u64;
                for rooks in &sets {
                    let v = measure(rooks);
                    record(&mut ev, rooks, v);
                }
                return Ok(ev);
            }
            (samples, seed)
        }
        OrderSearch::Sampled { orders, seed } => (orders, seed),
    };
    let mut seen: BTreeSet<Vec<u32>> = BTreeSet::new();
    for i in 0..samples {
        let order = GreedyOrder::Seeded(seed.wrapping_add(i)).permutation(inst.len());
        let (rooks, _) = super::star_cover::greedy_rooks_in(inst, &ch, &order);
        let v = measure(&rooks);
        record(&mut ev, &rooks, v);
        seen.insert(rooks);
    }
    ev.distinct = seen.len() as u64;
    if ev.tried == 0 {
        ev.min = 0;
    }
    Ok(ev)
}

/// The checked value of the star cover with these rooks.
fn measure(inst: &Discrete, ch: &Channels, rooks: &[u32], value: ChoiceValue) -> u64 {
    let cover = star_cover_of_rooks(inst, ch, rooks.to_vec());
    let report = check(inst, &cover.cycles);
    debug_assert!(report.valid, "{:?}", report.error);
    match value {
        ChoiceValue::CcTurns => report.turns,
        ChoiceValue::MergeBudget => report.turns + 2 * (report.cycles as u64).saturating_sub(1),
        ChoiceValue::TourTurns => {
            let (tour, _) = merge(inst, &cover.cycles);
            check(inst, &tour).turns
        }
    }
}

/// Every rook set the greedy rule can produce (the maximal independent sets of the attack
/// graph, module docs), each in index order, sorted; `None` when there are more than `cap` or
/// more than [`EXHAUSTIVE_MAX_VERTICES`] candidate vertices.
pub fn rook_sets(inst: &Discrete, ch: &Channels, cap: u64) -> Option<Vec<Vec<u32>>> {
    let on_closed = on_closed_channel(inst, ch);
    let cand: Vec<u32> = (0..inst.len() as u32)
        .filter(|&v| !on_closed[v as usize])
        .collect();
    let m = cand.len();
    if m > EXHAUSTIVE_MAX_VERTICES {
        return None;
    }
    let words = m.div_ceil(64).max(1);
    // Closed neighbourhoods N[v] in the attack graph (v and every candidate sharing a channel).
    let at = channels_at(inst, ch);
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); ch.list.len()];
    for (i, &v) in cand.iter().enumerate() {
        for &c in &at[v as usize] {
            members[c as usize].push(i);
        }
    }
    let mut closed_nbhd = vec![vec![0u64; words]; m];
    for (i, &v) in cand.iter().enumerate() {
        set(&mut closed_nbhd[i], i);
        for &c in &at[v as usize] {
            for &j in &members[c as usize] {
                set(&mut closed_nbhd[i], j);
            }
        }
    }
    let mut p = vec![0u64; words];
    for i in 0..m {
        set(&mut p, i);
    }
    let mut out = Vec::new();
    let mut current = Vec::new();
    let complete = bron_kerbosch(
        &closed_nbhd,
        &mut current,
        p,
        vec![0u64; words],
        cap,
        &mut out,
    );
    if !complete {
        return None;
    }
    let mut sets: Vec<Vec<u32>> = out
        .into_iter()
        .map(|s: Vec<usize>| {
            let mut r: Vec<u32> = s.into_iter().map(|i| cand[i]).collect();
            r.sort_unstable();
            r
        })
        .collect();
    sets.sort();
    Some(sets)
}

fn set(bits: &mut [u64], i: usize) {
    bits[i / 64] |= 1 << (i % 64);
}

fn ones(bits: &[u64]) -> impl Iterator<Item = usize> + '_ {
    bits.iter().enumerate().flat_map(|(w, &b)| {
        (0..64)
            .filter(move |k| b >> k & 1 == 1)
            .map(move |k| w * 64 + k)
    })
}

fn and_count(a: &[u64], b: &[u64]) -> u32 {
    a.iter().zip(b).map(|(x, y)| (x & y).count_ones()).sum()
}

/// Bron–Kerbosch with pivoting for the maximal independent sets (the maximal cliques of the
/// complement): `p` the candidates independent of `current`, `x` those already enumerated.
/// Branches on P ∩ N[u] for the pivot u of P ∪ X with the fewest such. Returns false once more
/// than `cap` sets are found.
fn bron_kerbosch(
    nbhd: &[Vec<u64>],
    current: &mut Vec<usize>,
    mut p: Vec<u64>,
    mut x: Vec<u64>,
    cap: u64,
    out: &mut Vec<Vec<usize>>,
) -> bool {
    if p.iter().all(|&w| w == 0) {
        if x.iter().all(|&w| w == 0) {
            out.push(current.clone());
            return out.len() as u64 <= cap;
        }
        return true;
    }
    let pivot = ones(&p)
        .chain(ones(&x))
        .min_by_key(|&u| and_count(&p, &nbhd[u]))
        .expect("P is not empty");
    let branch: Vec<usize> = ones(&p)
        .filter(|&v| nbhd[pivot][v / 64] >> (v % 64) & 1 == 1)
        .collect();
    for v in branch {
        let np: Vec<u64> = p.iter().zip(&nbhd[v]).map(|(a, b)| a & !b).collect();
        let nx: Vec<u64> = x.iter().zip(&nbhd[v]).map(|(a, b)| a & !b).collect();
        current.push(v);
        let ok = bron_kerbosch(nbhd, current, np, nx, cap, out);
        current.pop();
        if !ok {
            return false;
        }
        p[v / 64] &= !(1 << (v % 64));
        set(&mut x, v);
    }
    true
}

/// The hub-path instance of the module docs: the `gen` family `hub-path`, built in
/// [`crate::discrete::generate::hub_path`] (path vertices 0..P, then K hubs P..P+K, hub j
/// joined to the j-th of K consecutive runs of inner path vertices).
pub use crate::discrete::generate::hub_path;

/// The run sizes p_j of [`hub_path`] (P − 2 inner vertices in K runs).
pub fn hub_path_runs(p: usize, k: usize) -> Vec<u64> {
    let inner = p.saturating_sub(2);
    (0..k)
        .map(|j| (inner / k + usize::from(j < inner % k)) as u64)
        .collect()
}

/// The fewest cycle-cover turns of the star cover over every scan order on [`hub_path`]`(P, K)`,
/// by the argument of the module docs: 8 + 3·(Σ p_j − max p_j) (every run of at least 2).
pub fn hub_path_min_cc_turns(p: usize, k: usize) -> u64 {
    let runs = hub_path_runs(p, k);
    8 + 3 * (runs.iter().sum::<u64>() - runs.iter().copied().max().unwrap_or(0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::discrete::exact::{self, DiscreteOptions};
    use crate::discrete::star_cover::{star_cover, star_cover_in};
    use crate::exact::{Objective, Status};
    use std::path::Path;

    fn instance(name: &str) -> Discrete {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("instances/discrete")
            .join(name);
        crate::discrete::generate::read(&path).unwrap()
    }

    /// The proven optimum of `objective` (the solver must finish).
    fn opt(inst: &Discrete, objective: Objective) -> u64 {
        let r = exact::solve(inst, objective, &DiscreteOptions::default());
        assert_eq!(r.status, Status::Optimal, "{:?}", r.message);
        r.value.unwrap()
    }

    /// Theorem 5.1's averaged bound (ρ + 2δ)·OPT_cc.
    fn averaged_bound(inst: &Discrete, opt_cc: u64) -> f64 {
        let p = inst.params();
        (p.rho + 2.0 * p.delta) * opt_cc as f64
    }

    #[test]
    fn default_order_keeps_todays_values() {
        let hub = instance("hub-first.dm");
        let sc = star_cover(&hub);
        assert_eq!(sc.rooks, vec![0, 1]);
        assert_eq!(check(&hub, &sc.cycles).turns, 94);
        assert_eq!(star_cover_in(&hub, &GreedyOrder::Index), sc);
        let bridge = instance("bridge.dm");
        let sc = star_cover(&bridge);
        assert_eq!(sc.rooks, vec![0, 5]);
        let rep = check(&bridge, &sc.cycles);
        assert_eq!((rep.turns, rep.cycles), (8, 2));
        // Another order: the path vertex 2 first is one star of 8 turns on hub-first.
        let other = star_cover_in(&hub, &GreedyOrder::Sequence(vec![2]));
        assert_eq!(other.rooks, vec![2]);
        assert_eq!(check(&hub, &other.cycles).turns, 8);
    }

    #[test]
    fn seeded_orders_are_deterministic_permutations() {
        let a = GreedyOrder::Seeded(7).permutation(50);
        assert_eq!(a, GreedyOrder::Seeded(7).permutation(50));
        assert_ne!(a, GreedyOrder::Seeded(8).permutation(50));
        let mut sorted = a.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..50).collect::<Vec<u32>>());
        assert_eq!(
            GreedyOrder::Sequence(vec![3, 3, 99, 1]).permutation(4),
            vec![3, 1, 0, 2]
        );
    }

    #[test]
    fn hub_first_violation_depends_on_the_order() {
        let hub = instance("hub-first.dm");
        let opt_cc = opt(&hub, Objective::CcTurns);
        assert_eq!(opt_cc, 7);
        let bound = averaged_bound(&hub, opt_cc);
        let ev = order_evidence("discrete-star-cover", &hub, ChoiceValue::CcTurns, |v| {
            v as f64 > bound
        })
        .unwrap();
        // 32 rook sets: the hub with a path end ({0, 1}, {0, 32}: 94 turns), or one inner
        // path vertex alone (30 sets, 8 turns).
        assert!(ev.exhaustive);
        assert_eq!((ev.tried, ev.violated, ev.min, ev.max), (32, 2, 8, 94));
        assert!(ev.default_violates && !ev.every_order_violates());
        assert_eq!(ev.violating_rooks, Some(vec![0, 1]));
        // Sampling agrees in kind: random orders rarely put the hub before every spoke end.
        let sampled = order_evidence_with(
            "discrete-star-cover",
            &hub,
            ChoiceValue::CcTurns,
            |v| v as f64 > bound,
            OrderSearch::Sampled {
                orders: 200,
                seed: 0,
            },
        )
        .unwrap();
        assert!(!sampled.exhaustive);
        assert_eq!(sampled.tried, 200);
        assert!(sampled.violated < 200 && sampled.min == 8);
    }

    #[test]
    fn several_hubs_violate_theorem_5_1_for_every_order() {
        // (P, K, OPT_cc, violating rook sets): below the threshold some orders meet the bound,
        // from it on every order violates (all P rook sets, exhaustive).
        for (p, k, opt_cc, violated) in [
            (67, 2, 10, 34),
            (68, 2, 10, 68),
            (64, 3, 13, 22),
            (65, 3, 13, 65),
            (71, 4, 16, 53),
            (72, 4, 16, 72),
        ] {
            let inst = hub_path(p, k).unwrap();
            assert_eq!(opt(&inst, Objective::CcTurns), opt_cc, "P {p} K {k}");
            let bound = averaged_bound(&inst, opt_cc);
            let ev = order_evidence("discrete-star-cover", &inst, ChoiceValue::CcTurns, |v| {
                v as f64 > bound
            })
            .unwrap();
            assert!(ev.exhaustive);
            assert_eq!((ev.tried, ev.violated), (p as u64, violated), "P {p} K {k}");
            assert_eq!(ev.every_order_violates(), violated == p as u64);
            // The proof's formula is the enumeration's minimum.
            assert_eq!(ev.min, hub_path_min_cc_turns(p, k), "P {p} K {k}");
        }
    }

    #[test]
    fn bridge_defeats_theorem_4_2_whatever_the_merge() {
        let bridge = instance("bridge.dm");
        let opt_tour = opt(&bridge, Objective::Turns);
        assert_eq!(opt_tour, 12);
        // The default cover: t = 8, c = 2, budget t + 2c − 2 = 10 < 12 ≤ every tour.
        let ev = order_evidence(
            "discrete-star-cover",
            &bridge,
            ChoiceValue::MergeBudget,
            |b| b < opt_tour,
        )
        .unwrap();
        assert_eq!(ev.default_value, 10);
        assert!(ev.default_violates);
        // 24 rook sets (a vertex of each path, not both bridge ends): the 16 avoiding the
        // bridge have budget 10, the 8 with a bridge end 12 + 2 = 14.
        assert!(ev.exhaustive);
        assert_eq!((ev.tried, ev.violated, ev.min, ev.max), (24, 16, 10, 14));
    }

    #[test]
    fn unknown_algorithms_are_refused() {
        let hub = instance("hub-first.dm");
        assert!(order_evidence("strips-matching", &hub, ChoiceValue::CcTurns, |_| false).is_err());
    }
}
