//! Merging a cycle cover of a discrete instance into one tour per connected component (Theorem
//! 4.2 and Corollary 5.1 of *Optimal covering tours with turn costs*), by local operations
//! whose turn change is computed exactly from [`Discrete::turn`].
//!
//! # Operations
//! Each merge joins two cycles A and B, x a node (visit) of A and z one of B:
//! - **exchange**: remove an edge {x, x'} of A and an edge {z, z'} of B and reconnect the four
//!   ends crosswise, {x, z'} and {z, x'} or {x, z} and {x', z'}, where those are edges. With x
//!   and z at one vertex this is the *splice* (only the first pairing applies); with x, z
//!   adjacent it is the exchange across a 4-cycle of the graph. Visits are unchanged.
//! - **detour**: x and z adjacent: after x, step to z, walk around B back to z, step back to x
//!   (one new visit at each of the two vertices).
//!
//! Only the turns at the (at most four) nodes whose walk neighbours change can change, so the
//! cost of an operation is exact and local.
//!
//! # Turn cost of a merge
//! - A splice costs at most +2 (the discrete form of Theorem 4.2's +2): let A turn t₁ and B
//!   turn t₂ at the shared vertex. Each new turn is at most 2, so if t₁ + t₂ ≥ 2 any splice
//!   costs ≤ +2. If both pass straight, through the same pair, one of the two orientations
//!   goes straight twice (cost 0); through different pairs, the four edges are distinct and
//!   not collinear across pairs: 1 + 1. If t₁ = 0, t₂ = 1, a cost of +3 would need both new
//!   turns to be U-turns, which makes B's two edges A's collinear pair (t₂ = 0).
//! - Across an edge a merge can cost up to +4, and Theorem 4.2's t + 2c − 2 is **false** in
//!   discrete milling: two straight paths P₁, P₂ (ends are leaves) joined by one edge between
//!   inner vertices, unmatched at both ends. Doubling each path gives t = 8 with c = 2, but
//!   every tour has ≥ 12 turns: four leaves force U-turns (8), and the bridge is crossed at
//!   least twice, each crossing turning at both of its ends (4) (test
//!   `theorem_4_2_fails_across_a_bridge`). The proof idea "extend the end links" needs room
//!   that a graph does not give. What holds: tour ≤ t + 2·(splices) + 4·(other merges) ≤
//!   t + 4(c − 1) ([`proven_bound`]); [`MergeStats`] reports which merges happened.
//!
//! # Coverage rule
//! A detour between x (vertex p) and z (vertex q) is allowed only when both p and q are
//! *settled*: all their input visits already lie in one merged cycle (the grid merge's rule,
//! [`crate::merge`]). Exchanges are always allowed. Then a detour crosses an
//! edge pq whose channel no input cycle walks (such a cycle would hold visits of p and q, so
//! settled p and q would be in one cycle). For the star cover, whose input visits at v number
//! at most one per edge of a walked channel at v, each such edge takes at most one detour
//! (after it p and q are in one cycle for good), adding one visit at each end: the visits of v
//! stay at most deg(v) ≤ μ, Theorem 5.1's coverage. Merging never gets stuck: cycles sharing
//! a vertex can always be spliced there, and when no two merged cycles share a vertex every
//! vertex is settled, so any edge between two cycles takes a detour.
//!
//! # Strategy
//! Candidate pairs: visits of different input cycles at one vertex or at adjacent vertices.
//! Each is evaluated once in vertex order and merged at once if its cheapest operation is
//! free (≤ 0); the rest go to a bucket queue by cost and are merged cheapest first, with costs
//! re-evaluated lazily when popped (an exchange is preferred to a detour of the same cost).
//! That is [`Merge::Smart`], the default; [`Merge::Naive`] ([`merge_with`]) is the grid
//! merge's naive strategy on graphs: every candidate pair, in vertex order, is merged at once
//! by its cheapest allowed operation whatever it costs, in passes until one merges nothing.
//! Both apply only the operations above, so both keep the proven bound and the coverage rule.

use super::{Discrete, VertexWalk};
use crate::Merge;
use crate::visits::Rings;

/// What a merge did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MergeStats {
    /// Merges performed (cycles before − cycles after).
    pub merges: usize,
    /// Merges that did not raise the turn count.
    pub free_merges: usize,
    /// Merges by a splice at a shared vertex (each ≤ +2).
    pub splices: usize,
    /// Merges by an exchange across a 4-cycle.
    pub exchanges: usize,
    /// Merges by a detour across an edge.
    pub detours: usize,
    /// Merges that added more than 2 turns (each a violation of Theorem 4.2's per-merge +2).
    pub above_two: usize,
    /// The turns added in all (tour turns − cover turns).
    pub added_turns: i64,
}

#[derive(Clone, Copy, Debug)]
enum Op {
    /// Remove the walk edges (x, x2) and (z, z2); add {x, z2}, {z, x2} (`crossed = false`) or
    /// {x, z}, {x2, z2} (`crossed = true`).
    Exchange {
        x: u32,
        x2: u32,
        z: u32,
        z2: u32,
        crossed: bool,
    },
    /// After `x`, a step to `z`, B walked around back to `z`, a step back to `x`.
    Detour { x: u32, z: u32 },
}

struct Walks<'a> {
    inst: &'a Discrete,
    /// The walks' nodes, keyed by vertex.
    rings: Rings,
    stats: MergeStats,
}

impl<'a> Walks<'a> {
    fn new(inst: &'a Discrete, cycles: &[VertexWalk]) -> Walks<'a> {
        let walks: Vec<VertexWalk> = cycles
            .iter()
            .map(|walk| {
                let mut walk = walk.clone();
                if walk.len() == 1
                    && let Some(&q) = inst.neighbors(walk[0]).first()
                {
                    // A one-vertex walk counts 4 turns, as does the walk to a neighbour and back.
                    walk.push(q);
                }
                walk
            })
            .collect();
        Walks {
            inst,
            rings: Rings::new(&walks, inst.len()),
            stats: MergeStats::default(),
        }
    }

    fn root_of(&mut self, node: u32) -> u32 {
        self.rings.root_of(node)
    }

    /// The turn at `n` between walk neighbours `a` and `b`; 4 for a one-node walk.
    fn turn_between(&self, a: u32, n: u32, b: u32) -> i32 {
        if a == n {
            return 4;
        }
        self.inst.turn(
            self.rings.key[a as usize],
            self.rings.key[n as usize],
            self.rings.key[b as usize],
        ) as i32
    }

    fn turn_at(&self, n: u32) -> i32 {
        self.turn_between(self.rings.prev[n as usize], n, self.rings.next[n as usize])
    }

    fn adjacent(&self, a: u32, b: u32) -> bool {
        self.inst
            .adjacent(self.rings.key[a as usize], self.rings.key[b as usize])
    }

    /// The edge (x, x2) as a directed walk edge (from, to).
    fn directed(&self, x: u32, x2: u32) -> (u32, u32) {
        if self.rings.next[x as usize] == x2 {
            (x, x2)
        } else {
            (x2, x)
        }
    }

    fn delta(&self, op: Op) -> i32 {
        match op {
            Op::Exchange {
                x,
                x2,
                z,
                z2,
                crossed,
            } => {
                let (u1, v1) = self.directed(x, x2);
                let (u2, v2) = self.directed(z, z2);
                let partner = |n: u32| -> u32 {
                    let (a, b) = if crossed { (x, z) } else { (x, z2) };
                    let (c, d) = if crossed { (x2, z2) } else { (z, x2) };
                    match n {
                        _ if n == a => b,
                        _ if n == b => a,
                        _ if n == c => d,
                        _ => c,
                    }
                };
                // A removed edge's tail keeps its predecessor, its head its successor.
                let kept = [
                    (u1, self.rings.prev[u1 as usize]),
                    (v1, self.rings.next[v1 as usize]),
                    (u2, self.rings.prev[u2 as usize]),
                    (v2, self.rings.next[v2 as usize]),
                ];
                kept.iter()
                    .map(|&(n, k)| self.turn_between(k, n, partner(n)) - self.turn_at(n))
                    .sum()
            }
            Op::Detour { x, z } => {
                let (px, xn) = (self.rings.prev[x as usize], self.rings.next[x as usize]);
                let (pz, zn) = (self.rings.prev[z as usize], self.rings.next[z as usize]);
                self.turn_between(px, x, z)
                    + self.turn_between(x, z, zn)
                    + self.turn_between(pz, z, x)
                    + self.turn_between(z, x, xn)
                    - self.turn_at(x)
                    - self.turn_at(z)
            }
        }
    }

    /// The cheapest allowed operation joining the cycles of `x` and `z` (different merged
    /// cycles, at one vertex or adjacent), exchanges before detours of the same cost.
    fn best_op(&mut self, x: u32, z: u32) -> Option<(i32, Op)> {
        let same = self.rings.key[x as usize] == self.rings.key[z as usize];
        if !same && !self.adjacent(x, z) {
            return None;
        }
        // One-node walks (isolated vertices) have no edge to exchange.
        if self.rings.next[x as usize] == x || self.rings.next[z as usize] == z {
            return None;
        }
        let mut best: Option<(i32, bool, Op)> = None;
        let mut consider = |d: i32, detour: bool, op: Op| {
            if best.is_none_or(|(b, bd, _)| (d, detour) < (b, bd)) {
                best = Some((d, detour, op));
            }
        };
        for x2 in [self.rings.next[x as usize], self.rings.prev[x as usize]] {
            for z2 in [self.rings.next[z as usize], self.rings.prev[z as usize]] {
                for crossed in [false, true] {
                    let ok = if crossed {
                        !same && self.adjacent(x2, z2)
                    } else {
                        self.adjacent(x, z2) && self.adjacent(z, x2)
                    };
                    if ok {
                        let op = Op::Exchange {
                            x,
                            x2,
                            z,
                            z2,
                            crossed,
                        };
                        consider(self.delta(op), false, op);
                    }
                }
            }
        }
        if !same
            && self.rings.settled(self.rings.key[x as usize] as usize)
            && self.rings.settled(self.rings.key[z as usize] as usize)
        {
            let op = Op::Detour { x, z };
            consider(self.delta(op), true, op);
        }
        best.map(|(d, _, op)| (d, op))
    }

    /// Directed removed edges (u1, v1) of A and (u2, v2) of B such that linking u1 -> v2 and
    /// u2 -> v1 gives the wanted pairing, if the current orientations allow it.
    fn relinking(
        &self,
        x: u32,
        x2: u32,
        z: u32,
        z2: u32,
        want: &impl Fn(u32, u32) -> bool,
    ) -> Option<(u32, u32, u32, u32)> {
        let dirs = |a: u32, b: u32| {
            let mut out = Vec::with_capacity(2);
            if self.rings.next[a as usize] == b {
                out.push((a, b));
            }
            if self.rings.prev[a as usize] == b {
                out.push((b, a));
            }
            out
        };
        for &(u1, v1) in &dirs(x, x2) {
            for &(u2, v2) in &dirs(z, z2) {
                if want(u1, v2) && want(u2, v1) {
                    return Some((u1, v1, u2, v2));
                }
            }
        }
        None
    }

    fn apply(&mut self, op: Op, delta: i32) {
        let (ra, rb) = match op {
            Op::Exchange { x, z, .. } | Op::Detour { x, z } => (self.root_of(x), self.root_of(z)),
        };
        debug_assert_ne!(ra, rb);
        match op {
            Op::Exchange {
                x,
                x2,
                z,
                z2,
                crossed,
            } => {
                let want = |a: u32, b: u32| -> bool {
                    let pairs = if crossed {
                        [(x, z), (x2, z2)]
                    } else {
                        [(x, z2), (z, x2)]
                    };
                    pairs.contains(&(a, b)) || pairs.contains(&(b, a))
                };
                // Relinking u1 -> v2 and u2 -> v1 (each removed edge directed along its walk)
                // keeps both orientations; the other pairing needs one cycle reversed (the
                // smaller). A two-node cycle has its edge in both directions.
                let mut link = self.relinking(x, x2, z, z2, &want);
                if link.is_none() {
                    let smaller = if self.rings.size(ra) <= self.rings.size(rb) {
                        x
                    } else {
                        z
                    };
                    self.rings.reverse(smaller);
                    link = self.relinking(x, x2, z, z2, &want);
                }
                let (u1, v1, u2, v2) = link.expect("one orientation gives the pairing");
                self.rings.next[u1 as usize] = v2;
                self.rings.prev[v2 as usize] = u1;
                self.rings.next[u2 as usize] = v1;
                self.rings.prev[v1 as usize] = u2;
                if self.rings.key[x as usize] == self.rings.key[z as usize] {
                    self.stats.splices += 1;
                } else {
                    self.stats.exchanges += 1;
                }
            }
            Op::Detour { x, z } => {
                self.rings.detour(x, z);
                self.stats.detours += 1;
            }
        }
        let added = if matches!(op, Op::Detour { .. }) {
            2
        } else {
            0
        };
        self.rings.merged(ra, rb, added);
        self.stats.merges += 1;
        self.stats.added_turns += i64::from(delta);
        if delta <= 0 {
            self.stats.free_merges += 1;
        }
        if delta > 2 {
            self.stats.above_two += 1;
        }
    }

    /// Every pair of input nodes of different input cycles at one vertex or at
    /// adjacent vertices, in vertex order.
    fn candidates(&self) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for v in 0..self.inst.len() {
            let here = self.rings.visits(v);
            for (i, &x) in here.iter().enumerate() {
                for &z in &here[i + 1..] {
                    if !self.rings.same_input(x, z) {
                        out.push((x, z));
                    }
                }
            }
            for &w in self.inst.neighbors(v as u32) {
                if (w as usize) < v {
                    continue;
                }
                for &x in here {
                    for &z in self.rings.visits(w as usize) {
                        if !self.rings.same_input(x, z) {
                            out.push((x, z));
                        }
                    }
                }
            }
        }
        out
    }

    fn into_walks(self) -> Vec<VertexWalk> {
        self.rings.walks()
    }
}

/// Merges `cycles` (closed walks of `inst`) into as few closed walks as the instance's
/// connectivity allows: one per connected component that the walks cover.
///
/// # Returns
/// The merged walks and what the merging did.
///
/// # Complexity
/// O(P log V) for P candidate pairs (at most Σ_v cov(v)² + Σ_{uv ∈ E} cov(u)·cov(v), so
/// O(μ²·(n + |E|)) for a cover of coverage ≤ μ) and V visits, plus the reversals of the smaller
/// of two merged cycles (O(V log V) in all).
///
/// # Guarantee
/// Turns after ≤ turns before + 2·splices + 4·(other merges) ≤ t + 4(c − 1) (module
/// documentation; Theorem 4.2's t + 2(c − 1) holds when every merge is a splice, and fails in
/// discrete milling in general). Visits grow only by detours between settled vertices, which
/// keeps the star cover's coverage ≤ μ (Corollary 5.1).
pub fn merge(inst: &Discrete, cycles: &[VertexWalk]) -> (Vec<VertexWalk>, MergeStats) {
    if cycles.len() <= 1 {
        return (cycles.to_vec(), MergeStats::default());
    }
    let mut w = Walks::new(inst, cycles);
    // Costs lie in -8..=8: a bucket queue, lowest first, lazily re-evaluated.
    const LOW: i32 = -8;
    let slot = |d: i32| (d - LOW).clamp(0, 16) as usize;
    let mut buckets: Vec<Vec<(u32, u32)>> = vec![Vec::new(); 17];
    let mut blocked: Vec<(u32, u32)> = Vec::new();
    // Free merges at once, in vertex order.
    for (x, z) in w.candidates() {
        if w.root_of(x) == w.root_of(z) {
            continue;
        }
        match w.best_op(x, z) {
            Some((d, op)) if d <= 0 => w.apply(op, d),
            Some((d, _)) => buckets[slot(d)].push((x, z)),
            None => blocked.push((x, z)),
        }
    }
    // Pairs with no allowed operation (only detours, at an unsettled vertex) are retried
    // whenever a bucket is done: once no two merged cycles share a vertex (after the buckets
    // of cost <= 2, which hold every pair at one vertex) every vertex is settled.
    let mut b = 0;
    while b < buckets.len() {
        let Some((x, z)) = buckets[b].pop() else {
            let mut lowest = b + 1;
            for (x, z) in std::mem::take(&mut blocked) {
                if w.root_of(x) == w.root_of(z) {
                    continue;
                }
                match w.best_op(x, z) {
                    Some((d, _)) => {
                        buckets[slot(d)].push((x, z));
                        lowest = lowest.min(slot(d));
                    }
                    None => blocked.push((x, z)),
                }
            }
            b = lowest;
            continue;
        };
        if w.root_of(x) == w.root_of(z) {
            continue;
        }
        match w.best_op(x, z) {
            None => blocked.push((x, z)),
            Some((d, _)) if slot(d) > b => buckets[slot(d)].push((x, z)),
            Some((d, op)) => w.apply(op, d),
        }
    }
    let stats = w.stats;
    (w.into_walks(), stats)
}

/// [`merge`] with the given strategy: [`Merge::Smart`] is [`merge`] itself; [`Merge::Naive`]
/// merges each candidate pair, in vertex order, by its cheapest allowed operation at once
/// (module documentation).
///
/// # Complexity
/// Naive: O(P) operations per pass for P candidate pairs; a pass that leaves cycles apart
/// leaves only pairs whose detours waited for a vertex to settle, which the next pass merges,
/// so a few passes suffice (at most one per merge in the worst case).
///
/// # Guarantee
/// As for [`merge`]: turns ≤ t + 4(c − 1) ([`proven_bound`]), visits growing only by detours
/// between settled vertices; the operations are the same, only their order differs.
pub fn merge_with(
    inst: &Discrete,
    cycles: &[VertexWalk],
    strategy: Merge,
) -> (Vec<VertexWalk>, MergeStats) {
    if strategy == Merge::Smart || cycles.len() <= 1 {
        return merge(inst, cycles);
    }
    let mut w = Walks::new(inst, cycles);
    let candidates = w.candidates();
    loop {
        let before = w.stats.merges;
        for &(x, z) in &candidates {
            if w.root_of(x) == w.root_of(z) {
                continue;
            }
            if let Some((d, op)) = w.best_op(x, z) {
                w.apply(op, d);
            }
        }
        if w.stats.merges == before {
            break;
        }
    }
    let stats = w.stats;
    (w.into_walks(), stats)
}

/// Theorem 4.2's bound on the merged tour: t + 2(c − 1) for a cover of `cycles` cycles and
/// `turns` turns (not proven in discrete milling: see the module documentation).
pub fn theorem_4_2_bound(turns: u64, cycles: usize) -> u64 {
    turns + 2 * (cycles.max(1) as u64 - 1)
}

/// The proven bound on the merged tour: t + 4(c − 1).
///
/// # Guarantee
/// Pairs at one vertex always have a splice of cost ≤ +2 and sit in the buckets of cost ≤ 2,
/// so every merge made while two cycles still share a vertex costs ≤ +2. Afterwards (merged
/// cycles' vertex sets are unions, so no sharing comes back) an exchange or detour across an
/// edge makes four new turns each ≤ 1 (a U-turn would need a vertex in both cycles): ≤ +4.
pub fn proven_bound(turns: u64, cycles: usize) -> u64 {
    turns + 4 * (cycles.max(1) as u64 - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::discrete::check::check;

    /// Straight paths 0..=4 and 5..=9, bridge 2-7 unmatched at both ends, and the cover by
    /// the two back-and-forth walks of the paths.
    fn bridge() -> (Discrete, Vec<VertexWalk>) {
        let mut edges: Vec<(u32, u32)> = (0..4).map(|i| (i, i + 1)).collect();
        edges.extend((5..9).map(|i| (i, i + 1)));
        edges.push((2, 7));
        let mut collinear: Vec<(u32, u32, u32)> = (1..4).map(|i| (i, i - 1, i + 1)).collect();
        collinear.extend((6..9).map(|i| (i, i - 1, i + 1)));
        let inst = Discrete::new(10, &edges, &collinear, None).unwrap();
        let cover = vec![vec![0, 1, 2, 3, 4, 3, 2, 1], vec![5, 6, 7, 8, 9, 8, 7, 6]];
        (inst, cover)
    }

    #[test]
    fn theorem_4_2_fails_across_a_bridge() {
        let (inst, cover) = bridge();
        let rep = check(&inst, &cover);
        assert_eq!((rep.turns, rep.cycles), (8, 2));
        let (tour, stats) = merge(&inst, &cover);
        let t = check(&inst, &tour);
        assert!(t.valid && tour.len() == 1);
        // Every tour needs 12 (module documentation); Theorem 4.2 promises 10.
        assert_eq!(t.turns, 12);
        assert!(t.turns > theorem_4_2_bound(8, 2));
        assert_eq!(t.turns, proven_bound(8, 2));
        assert_eq!((stats.above_two, stats.detours), (1, 1));
        // The star cover finds the same two stars.
        let sc = crate::discrete::star_cover::star_cover(&inst);
        assert_eq!(sc.rooks, vec![0, 5]);
        assert_eq!(check(&inst, &sc.cycles).turns, 8);
    }

    #[test]
    fn naive_merge_gives_one_tour_within_the_proven_bound() {
        // The bridge instance: the naive order must also cross the bridge (a detour between
        // settled vertices) and stay within t + 4(c - 1); on the star cover of a 5 x 5 grid
        // graph both strategies give one valid tour within the proven bound.
        let (inst, cover) = bridge();
        let (tour, stats) = merge_with(&inst, &cover, Merge::Naive);
        let t = check(&inst, &tour);
        assert!(t.valid && tour.len() == 1);
        assert_eq!(t.turns, 12);
        assert_eq!(stats.merges, 1);
        let region = crate::region::Region::rectangle(5, 5);
        let grid = Discrete::from_region(&region);
        let sc = crate::discrete::star_cover::star_cover(&grid);
        let before = check(&grid, &sc.cycles);
        assert!(before.cycles > 1);
        for strategy in [Merge::Naive, Merge::Smart] {
            let (tour, stats) = merge_with(&grid, &sc.cycles, strategy);
            let after = check(&grid, &tour);
            assert!(after.valid && after.cycles == 1, "{strategy}");
            assert_eq!(stats.merges, before.cycles - 1, "{strategy}");
            assert!(after.turns <= proven_bound(before.turns, before.cycles));
        }
    }

    #[test]
    fn splicing_at_a_vertex_costs_at_most_two() {
        // All pairs of walks through the centre of a star of degree 4 with one or two
        // collinear pairs: the best splice adds at most 2 turns.
        for pairs in [vec![(0u32, 1u32, 2u32)], vec![(0, 1, 2), (0, 3, 4)]] {
            let edges = [(0, 1), (0, 2), (0, 3), (0, 4)];
            let inst = Discrete::new(5, &edges, &pairs, None).unwrap();
            for a in 1..5u32 {
                for b in 1..5u32 {
                    for c in 1..5u32 {
                        for d in 1..5u32 {
                            // a, 0, b, 0 is a closed walk through the centre.
                            let walks = vec![vec![a, 0, b, 0], vec![c, 0, d, 0]];
                            let before = check(&inst, &walks);
                            if !before.valid {
                                continue;
                            }
                            let (tour, stats) = merge(&inst, &walks);
                            let after = check(&inst, &tour);
                            assert!(after.valid);
                            assert!(after.turns <= before.turns + 2, "{walks:?}");
                            assert_eq!(stats.merges, 1);
                        }
                    }
                }
            }
        }
    }
}
