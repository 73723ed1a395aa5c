//! Merging a cycle cover into one tour (Theorem 4.2 and Corollary 4.1 of *Optimal covering
//! tours with turn costs*): a cycle cover with t turns and c cycles becomes a tour with at most
//! t + 2c − 2 turns (at most 3t/2, every cycle having at least 4 turns).
//!
//! Every merge joins two cycles A and B by one local operation on their closed walks:
//! - **exchange**: remove one edge of A and one of B and reconnect their four ends crosswise
//!   by two unit moves (reversing B when needed). When the removed edges leave the same pixel
//!   this is the splice at a crossing; when they are facing parallel edges of a unit square it
//!   is the 2-opt move that is free when both cycles turn there;
//! - **detour**: from a pixel x of A step to an adjacent pixel of B, run around B and step
//!   back to x (two new visits); always possible between touching cycles.
//!
//! A detour is allowed only between two *settled* pixels: pixels all of whose visits already
//! lie in one merged cycle. Exchanges are always allowed. This is our rule (the paper's merge
//! extends links and says nothing on coverage); it bounds the visits a merge adds: a detour
//! between settled p and q in different cycles crosses an edge p–q that no input walk uses
//! (such a walk would put both pixels' visits in one cycle), and each such edge takes at most
//! one detour, after which p and q are settled in one cycle for good. So a pixel gains at most
//! one visit per neighbour joined to it by no input walk; the star and doubled-strip covers
//! keep coverage 4 by this count (their module docs). Merging never gets stuck: cycles sharing
//! a pixel can always be spliced there, and once no two merged cycles share a pixel every
//! pixel is settled.
//!
//! The cost of an operation is the change of the turn count at the at most four pixels whose
//! moves change (turns at a pixel depend only on its two neighbours on the walk), so it is
//! exact and local.
//!
//! Two strategies, both kept:
//! - [`Merge::Naive`]: merge at crossings: walk the pixels in index order and splice every
//!   pair of different cycles crossing there orthogonally (+2 turns each); then likewise at
//!   other shared pixels, then between adjacent pixels (each with its cheapest operation);
//! - [`Merge::Smart`]: free merges first (cost ≤ 0, one pass over all pairs in pixel order),
//!   then always the cheapest available merge, with lazily re-evaluated costs in a bucket
//!   queue.
//!
//! The paper proves +2 per merge for a suitable choice; our operations do not enumerate its
//! continuous "extend the end links" construction, so the tests assert t + 2c − 2 on every
//! instance instead of assuming it.

use super::visits::{NONE, Rings};
use crate::checker::{Mode, check};
use crate::error::Result;
use crate::region::{Pixel, Region};
use crate::tour::CycleCover;
use crate::{Merge, Objective, Options, Output, Solution};
use std::collections::BTreeMap;

/// What a merge did, for certificates.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MergeStats {
    /// Number of merges performed (cycles before − 1 on a connected region).
    pub merges: usize,
    /// Merges that did not increase the turn count.
    pub free_merges: usize,
}

/// One candidate operation joining the cycles of nodes `x` (in A) and `z` (in B).
#[derive(Clone, Copy, Debug)]
enum Op {
    /// Remove undirected edges `{a1, b1}` of A and `{a2, b2}` of B; add `{a1, b2}` and
    /// `{a2, b1}` (`crossed = false`) or `{a1, a2}` and `{b1, b2}` (`crossed = true`).
    Exchange {
        a1: u32,
        b1: u32,
        a2: u32,
        b2: u32,
        crossed: bool,
    },
    /// Insert, after `x`, a step to `z`, B walked forward (or backward) back to `z`, and a
    /// step back to `x`.
    Detour { x: u32, z: u32, backward: bool },
}

struct Walks<'a> {
    region: &'a Region,
    /// The walks' nodes, keyed by region pixel index.
    rings: Rings,
    /// The pixel of each node (`region.pixel(rings.key[node])`, kept at hand).
    xy: Vec<Pixel>,
    /// The turn at each node, kept up to date by [`apply`](Self::apply).
    turn: Vec<i32>,
    /// Visits per region pixel, kept up to date by detours (exchanges keep visits).
    coverage: Vec<u32>,
    stats: MergeStats,
}

fn turn3(a: Pixel, n: Pixel, b: Pixel) -> i32 {
    match (a.dir_to(n), n.dir_to(b)) {
        (Some(d), Some(e)) => d.turn_to(e) as i32,
        // Not a walk: never chosen.
        _ => 1000,
    }
}

impl<'a> Walks<'a> {
    fn new(region: &'a Region, cover: &CycleCover) -> Walks<'a> {
        let walks: Vec<Vec<u32>> = cover
            .cycles
            .iter()
            .map(|walk| {
                let mut walk: Vec<u32> = walk
                    .iter()
                    .map(|&p| {
                        region
                            .index_of(p)
                            .expect("merged walks stay inside the region")
                            as u32
                    })
                    .collect();
                if walk.len() == 1 {
                    // A one-pixel walk counts 4 turns, and so does the walk to a neighbour and
                    // back.
                    if let Some(q) = region.neighbors(walk[0] as usize).next() {
                        walk.push(q as u32);
                    }
                }
                walk
            })
            .collect();
        let rings = Rings::by_key(&walks, region.len());
        let mut coverage = vec![0; region.len()];
        for &p in &rings.key {
            coverage[p as usize] += 1;
        }
        let mut w = Walks {
            region,
            xy: rings
                .key
                .iter()
                .map(|&p| region.pixel(p as usize))
                .collect(),
            turn: vec![0; rings.len()],
            rings,
            coverage,
            stats: MergeStats::default(),
        };
        for n in 0..w.rings.len() as u32 {
            w.recount_turn(n);
        }
        w
    }

    fn visits(&self, p: usize) -> &[u32] {
        self.rings.visits(p)
    }

    /// Whether every visit of pixel `p` already lies in one merged cycle. Settledness only
    /// grows as cycles merge.
    fn settled(&mut self, p: usize) -> bool {
        self.rings.settled(p)
    }

    /// Whether detours between nodes `x` and `z` are allowed: only between settled pixels (see
    /// the module documentation: this keeps the coverage bound of star and doubled-strip
    /// covers).
    fn detours_allowed(&mut self, x: u32, z: u32) -> bool {
        let (p, q) = (
            self.rings.key[x as usize] as usize,
            self.rings.key[z as usize] as usize,
        );
        p != q && self.settled(p) && self.settled(q)
    }

    fn root_of(&mut self, node: u32) -> u32 {
        self.rings.root_of(node)
    }

    fn at(&self, node: u32) -> Pixel {
        self.xy[node as usize]
    }

    fn adjacent(&self, a: u32, b: u32) -> bool {
        self.at(a).dir_to(self.at(b)).is_some()
    }

    /// Turn at `n` between neighbours `a` and `b` on the walk.
    fn turn_between(&self, a: u32, n: u32, b: u32) -> i32 {
        turn3(self.at(a), self.at(n), self.at(b))
    }

    fn turn_at(&self, n: u32) -> i32 {
        self.turn[n as usize]
    }

    fn recount_turn(&mut self, n: u32) {
        self.turn[n as usize] =
            self.turn_between(self.rings.prev[n as usize], n, self.rings.next[n as usize]);
    }

    /// The new partners of the four nodes of an exchange: (node, removed partner, new partner).
    fn exchange_moves(a1: u32, b1: u32, a2: u32, b2: u32, crossed: bool) -> [(u32, u32, u32); 4] {
        if crossed {
            [(a1, b1, a2), (b1, a1, b2), (a2, b2, a1), (b2, a2, b1)]
        } else {
            [(a1, b1, b2), (b1, a1, a2), (a2, b2, b1), (b2, a2, a1)]
        }
    }

    /// The change in turns if `op` were applied now.
    fn delta(&self, op: Op) -> i32 {
        match op {
            Op::Exchange {
                a1,
                b1,
                a2,
                b2,
                crossed,
            } => {
                let mut d = 0;
                for (n, gone, new) in Self::exchange_moves(a1, b1, a2, b2, crossed) {
                    // The node keeps its other neighbour and gains `new`.
                    let keep = if self.rings.next[n as usize] == gone {
                        self.rings.prev[n as usize]
                    } else {
                        self.rings.next[n as usize]
                    };
                    d += self.turn_between(keep, n, new) - self.turn_at(n);
                }
                d
            }
            Op::Detour { x, z, backward } => {
                let xn = self.rings.next[x as usize];
                let (zn, zp) = if backward {
                    (self.rings.prev[z as usize], self.rings.next[z as usize])
                } else {
                    (self.rings.next[z as usize], self.rings.prev[z as usize])
                };
                let px = self.rings.prev[x as usize];
                let (x_p, z_p) = (self.at(x), self.at(z));
                self.turn_between(px, x, z)
                    + self.turn_between(x, z, zn)
                    + turn3(self.at(zp), z_p, x_p)
                    + turn3(z_p, x_p, self.at(xn))
                    - self.turn_at(x)
                    - self.turn_at(z)
            }
        }
    }

    /// The valid operations joining the cycles of `x` and `z` (different cycles): exchanges of
    /// an edge at `x` with an edge at `z` (at a shared pixel these are the splices), and, for
    /// adjacent pixels, detours.
    fn for_each_op(&self, x: u32, z: u32, detours: bool, mut out: impl FnMut(Op)) {
        let same = self.rings.key[x as usize] == self.rings.key[z as usize];
        if !same && !self.adjacent(x, z) {
            return;
        }
        let edges_x = [
            (x, self.rings.next[x as usize]),
            (x, self.rings.prev[x as usize]),
        ];
        let edges_z = [
            (z, self.rings.next[z as usize]),
            (z, self.rings.prev[z as usize]),
        ];
        for &(a1, b1) in &edges_x {
            for &(a2, b2) in &edges_z {
                for crossed in [false, true] {
                    let ok = if crossed {
                        self.adjacent(a1, a2) && self.adjacent(b1, b2)
                    } else {
                        self.adjacent(a1, b2) && self.adjacent(a2, b1)
                    };
                    if ok {
                        out(Op::Exchange {
                            a1,
                            b1,
                            a2,
                            b2,
                            crossed,
                        });
                    }
                }
            }
        }
        if !same && detours {
            for backward in [false, true] {
                out(Op::Detour { x, z, backward });
                out(Op::Detour {
                    x: z,
                    z: x,
                    backward,
                });
            }
        }
    }

    /// Whether `op` would bring a pixel above 4 visits (only detours add visits).
    fn exceeds_four(&self, op: Op) -> bool {
        match op {
            Op::Exchange { .. } => false,
            Op::Detour { x, z, .. } => [x, z]
                .iter()
                .any(|&n| self.coverage[self.rings.key[n as usize] as usize] >= 4),
        }
    }

    /// The cheapest operation joining the cycles of `x` and `z`; among equally cheap ones, one
    /// that keeps every pixel within 4 visits (Corollary 5.2's coverage) where there is one.
    fn best_op(&mut self, x: u32, z: u32) -> Option<(i32, Op)> {
        let detours = self.detours_allowed(x, z);
        let mut best: Option<(i32, bool, Op)> = None;
        self.for_each_op(x, z, detours, |op| {
            let d = self.delta(op);
            // The coverage test only where it can decide: cheaper, or as cheap as a best
            // that exceeds 4.
            if best.is_some_and(|(b, e, _)| d > b || (d == b && !e)) {
                return;
            }
            let e = self.exceeds_four(op);
            if best.is_none_or(|(b, be, _)| (d, e) < (b, be)) {
                best = Some((d, e, op));
            }
        });
        best.map(|(d, _, op)| (d, op))
    }

    fn link(&mut self, a: u32, b: u32) {
        if self.rings.next[a as usize] == NONE && self.rings.prev[b as usize] == NONE {
            self.rings.next[a as usize] = b;
            self.rings.prev[b as usize] = a;
        } else {
            debug_assert!(
                self.rings.next[b as usize] == NONE && self.rings.prev[a as usize] == NONE
            );
            self.rings.next[b as usize] = a;
            self.rings.prev[a as usize] = b;
        }
    }

    fn apply(&mut self, op: Op, delta: i32) {
        let (ra, rb) = match op {
            Op::Exchange { a1, a2, .. } => (self.root_of(a1), self.root_of(a2)),
            Op::Detour { x, z, .. } => (self.root_of(x), self.root_of(z)),
        };
        match op {
            Op::Exchange {
                a1,
                b1,
                a2,
                b2,
                crossed,
            } => {
                // Removing one edge opens each cycle into a path; the end whose successor was
                // removed must be joined to the start of the other path, else one cycle is
                // reversed first (the smaller one).
                // Directed edges to remove, in the current orientations.
                let mut edge_a = if self.rings.next[a1 as usize] == b1 {
                    (a1, b1)
                } else {
                    (b1, a1)
                };
                let mut edge_b = if self.rings.next[a2 as usize] == b2 {
                    (a2, b2)
                } else {
                    (b2, a2)
                };
                let (end_a, end_b) = (edge_a.0, edge_b.0);
                let joins_ends = Self::exchange_moves(a1, b1, a2, b2, crossed)
                    .iter()
                    .any(|&(n, _, new)| n == end_a && new == end_b);
                if joins_ends {
                    // Reversing a cycle reverses its edges (a 2-cycle has both directions).
                    if self.rings.size(rb) <= self.rings.size(ra) {
                        self.rings.reverse(a2);
                        edge_b = (edge_b.1, edge_b.0);
                    } else {
                        self.rings.reverse(a1);
                        edge_a = (edge_a.1, edge_a.0);
                    }
                }
                for (u, v) in [edge_a, edge_b] {
                    debug_assert_eq!(self.rings.next[u as usize], v);
                    self.rings.next[u as usize] = NONE;
                    self.rings.prev[v as usize] = NONE;
                }
                if crossed {
                    self.link(a1, a2);
                    self.link(b1, b2);
                } else {
                    self.link(a1, b2);
                    self.link(a2, b1);
                }
                for n in [a1, b1, a2, b2] {
                    self.recount_turn(n);
                }
            }
            Op::Detour { x, z, backward } => {
                if backward {
                    self.rings.reverse(z);
                }
                let (z2, x2) = self.rings.detour(x, z);
                for of in [z, x] {
                    self.xy.push(self.xy[of as usize]);
                    self.turn.push(0);
                }
                self.coverage[self.rings.key[x as usize] as usize] += 1;
                self.coverage[self.rings.key[z as usize] as usize] += 1;
                for n in [x, z, z2, x2] {
                    self.recount_turn(n);
                }
            }
        }
        let added = if matches!(op, Op::Detour { .. }) {
            2
        } else {
            0
        };
        self.rings.merged(ra, rb, added);
        self.stats.merges += 1;
        if delta <= 0 {
            self.stats.free_merges += 1;
        }
    }

    /// Whether the walk passes straight through node `n` horizontally (`Some(true)`),
    /// vertically (`Some(false)`), or turns there (`None`).
    fn straight_axis(&self, n: u32) -> Option<bool> {
        let (p, q, r) = (
            self.at(self.rings.prev[n as usize]),
            self.at(n),
            self.at(self.rings.next[n as usize]),
        );
        match (p.dir_to(q), q.dir_to(r)) {
            (Some(d), Some(e)) if d == e => Some(d.is_horizontal()),
            _ => None,
        }
    }

    /// Candidate node pairs (x, z) of different initial cycles at one pixel, each class in
    /// pixel order: orthogonal crossings (one walk straight through the pixel horizontally,
    /// the other vertically), and the other pairs at one pixel. The third class, pairs at
    /// adjacent pixels, is the largest by far (17 million at 10^6 pixels) and is walked by
    /// [`for_each_candidate`](Self::for_each_candidate) instead of being stored.
    fn shared_pixel_pairs(&self) -> [Vec<(u32, u32)>; 2] {
        let (mut crossing, mut same) = (Vec::new(), Vec::new());
        for p in 0..self.region.len() {
            for &x in self.visits(p) {
                for &z in self.visits(p) {
                    if self.rings.precedes(x, z) && !self.rings.same_input(x, z) {
                        let axes = (self.straight_axis(x), self.straight_axis(z));
                        if matches!(axes, (Some(a), Some(b)) if a != b) {
                            crossing.push((x, z));
                        } else {
                            same.push((x, z));
                        }
                    }
                }
            }
        }
        [crossing, same]
    }

    /// Calls `f` on every candidate pair of nodes of different merged cycles, class by class
    /// (crossings, other pairs at one pixel, pairs at adjacent pixels), each in pixel order.
    /// The adjacent pairs are those of input nodes of different initial cycles: an input
    /// node's pixel and initial cycle never change, so walking them now gives the same pairs
    /// in the same order as listing them up front.
    fn for_each_candidate(
        &mut self,
        shared: &[Vec<(u32, u32)>; 2],
        mut f: impl FnMut(&mut Self, u32, u32),
    ) {
        for &(x, z) in shared.iter().flatten() {
            if self.root_of(x) != self.root_of(z) {
                f(self, x, z);
            }
        }
        let region = self.region;
        for p in 0..region.len() {
            for k in self.rings.index().range(p) {
                let x = self.rings.index().node(k);
                for q in region.neighbors(p) {
                    for l in self.rings.index().range(q) {
                        let z = self.rings.index().node(l);
                        if self.rings.precedes(x, z)
                            && !self.rings.same_input(x, z)
                            && self.root_of(x) != self.root_of(z)
                        {
                            f(self, x, z);
                        }
                    }
                }
            }
        }
    }

    fn into_cover(self) -> CycleCover {
        let region = self.region;
        let pixels = |walk: Vec<u32>| walk.into_iter().map(|p| region.pixel(p as usize)).collect();
        CycleCover::new(self.rings.walks().into_iter().map(pixels).collect())
    }
}

/// Merges the cycles of `cover` into as few closed walks as the region's connectivity allows
/// (one per connected component), by `strategy`.
///
/// # Returns
/// The merged cover and what the merging did.
///
/// # Complexity
/// O(V log V) for V visits of the cover (each pixel has O(1) visits in our covers), plus
/// reversals of the smaller of two merged cycles, O(V log V) in all.
pub fn merge_cycles(
    region: &Region,
    cover: &CycleCover,
    strategy: Merge,
) -> (CycleCover, MergeStats) {
    if cover.cycles.len() <= 1 {
        return (cover.clone(), MergeStats::default());
    }
    let mut w = Walks::new(region, cover);
    let shared = w.shared_pixel_pairs();
    match strategy {
        Merge::Naive => {
            w.for_each_candidate(&shared, |w, x, z| {
                if let Some((d, op)) = w.best_op(x, z) {
                    w.apply(op, d);
                }
            });
        }
        Merge::Smart => {
            // Costs are small integers: a bucket queue, lowest cost first, with lazily
            // re-evaluated entries (an entry whose cost rose goes back to its new bucket).
            const LOW: i32 = -8;
            let mut buckets: Vec<Vec<(u32, u32)>> = vec![Vec::new(); 64];
            let slot = |d: i32| (d - LOW).clamp(0, 63) as usize;
            // Free merges first, in one pass in pixel order; then the remaining pairs by cost.
            w.for_each_candidate(&shared, |w, x, z| {
                if let Some((d, op)) = w.best_op(x, z)
                    && d <= 0
                    && !w.exceeds_four(op)
                {
                    w.apply(op, d);
                }
            });
            let mut blocked: Vec<(u32, u32)> = Vec::new();
            w.for_each_candidate(&shared, |w, x, z| match w.best_op(x, z) {
                Some((d, _)) => buckets[slot(d)].push((x, z)),
                None => blocked.push((x, z)),
            });
            // Within a bucket (one cost), pairs whose merge would bring a pixel above 4
            // visits wait until the bucket's other pairs are done: same turns, less coverage.
            // A pair with no allowed operation yet (only detours, at an unsettled pixel) is
            // kept for a later round; after a round every pixel is settled (every pair at a
            // shared pixel has a splice), so the second round merges everything left.
            loop {
                let mut b = 0;
                let mut deferred: Vec<(u32, u32)> = Vec::new();
                let mut last_chance = false;
                while b < buckets.len() {
                    let Some((x, z)) = buckets[b].pop() else {
                        if !deferred.is_empty() && !last_chance {
                            buckets[b].append(&mut deferred);
                            last_chance = true;
                            continue;
                        }
                        buckets[b].append(&mut deferred);
                        if buckets[b].is_empty() {
                            b += 1;
                            last_chance = false;
                        }
                        continue;
                    };
                    if w.root_of(x) == w.root_of(z) {
                        continue;
                    }
                    let Some((now, op)) = w.best_op(x, z) else {
                        blocked.push((x, z));
                        continue;
                    };
                    if slot(now) > b {
                        buckets[slot(now)].push((x, z));
                    } else if !last_chance && w.exceeds_four(op) {
                        deferred.push((x, z));
                    } else {
                        w.apply(op, now);
                    }
                }
                for (x, z) in std::mem::take(&mut blocked) {
                    if w.root_of(x) != w.root_of(z) {
                        match w.best_op(x, z) {
                            Some((d, _)) => buckets[slot(d)].push((x, z)),
                            None => blocked.push((x, z)),
                        }
                    }
                }
                // No pair left, or none can move (cannot happen: see above).
                if buckets.iter().all(Vec::is_empty) {
                    break;
                }
            }
        }
    }
    let stats = w.stats;
    (w.into_cover(), stats)
}

/// The two outputs of a cycle-cover algorithm: the cycle cover (objective `cc-turns`) and the
/// tour merged from it by `opts.merge` (objective `turns`), rewritten by
/// [`coverage4`](crate::coverage4) when `opts.coverage4` is set. Certificates
/// gain the checker's recount of the cover (`cc_cycles`, `cc_turns`), the merged tour's turns
/// (`tour_turns`) and the number of free merges.
pub(crate) fn cover_and_tour(
    region: &Region,
    cover: CycleCover,
    opts: &Options,
    mut certificates: BTreeMap<String, i64>,
) -> Result<Solution> {
    let (mut tour, stats) = merge_cycles(region, &cover, opts.merge);
    if opts.coverage4 {
        let (rewritten, stuck) = crate::coverage4::coverage4(region, &tour);
        tour = rewritten;
        certificates.insert("coverage4_stuck".to_string(), stuck as i64);
    }
    let before = check(region, &cover, Mode::Milling);
    let after = check(region, &tour, Mode::Milling);
    certificates.insert("cc_cycles".to_string(), before.cycles as i64);
    certificates.insert("cc_turns".to_string(), before.turns as i64);
    certificates.insert("tour_turns".to_string(), after.turns as i64);
    certificates.insert("free_merges".to_string(), stats.free_merges as i64);
    Ok(Solution {
        outputs: vec![
            Output {
                objective: Objective::CcTurns,
                cover,
            },
            Output {
                objective: Objective::Turns,
                cover: tour,
            },
        ],
        certificates,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::Dir;
    use crate::tour::Walk;

    fn rect_cycle(x0: i32, y0: i32, w: i32, h: i32) -> Walk {
        let mut out = Vec::new();
        for x in x0..x0 + w {
            out.push(Pixel::new(x, y0));
        }
        for y in y0 + 1..y0 + h {
            out.push(Pixel::new(x0 + w - 1, y));
        }
        for x in (x0..x0 + w - 1).rev() {
            out.push(Pixel::new(x, y0 + h - 1));
        }
        for y in (y0 + 1..y0 + h - 1).rev() {
            out.push(Pixel::new(x0, y));
        }
        out
    }

    #[test]
    fn splicing_at_a_pixel_costs_at_most_two() {
        // Over all in/out headings of two walks through one pixel, the cheaper orientation of
        // the splice adds at most 2 turns (the pixel form of Theorem 4.2's +2).
        for a1 in Dir::ALL {
            for b1 in Dir::ALL {
                for a2 in Dir::ALL {
                    for b2 in Dir::ALL {
                        let old = a1.turn_to(b1) + a2.turn_to(b2);
                        let fwd = a1.turn_to(b2) + a2.turn_to(b1);
                        let rev = a1.turn_to(a2.opposite()) + b2.opposite().turn_to(b1);
                        assert!(fwd.min(rev) <= old + 2);
                    }
                }
            }
        }
    }

    #[test]
    fn two_squares_side_by_side_merge_for_free() {
        let r = Region::rectangle(4, 2);
        let cover = CycleCover::new(vec![rect_cycle(0, 0, 2, 2), rect_cycle(2, 0, 2, 2)]);
        for strategy in [Merge::Naive, Merge::Smart] {
            let (tour, stats) = merge_cycles(&r, &cover, strategy);
            let rep = check(&r, &tour, Mode::Milling);
            assert!(rep.valid && tour.is_tour(), "{:?}", rep.error);
            assert_eq!(rep.turns, 4);
            assert_eq!(
                stats,
                MergeStats {
                    merges: 1,
                    free_merges: 1
                }
            );
        }
    }

    #[test]
    fn crossing_strips_merge_with_two_turns() {
        // A plus: the doubled horizontal and vertical strips cross at the centre.
        let r = Region::from_ascii(".#.\n###\n.#.\n");
        let h = vec![
            Pixel::new(0, 1),
            Pixel::new(1, 1),
            Pixel::new(2, 1),
            Pixel::new(1, 1),
        ];
        let v = vec![
            Pixel::new(1, 0),
            Pixel::new(1, 1),
            Pixel::new(1, 2),
            Pixel::new(1, 1),
        ];
        let cover = CycleCover::new(vec![h, v]);
        for strategy in [Merge::Naive, Merge::Smart] {
            let (tour, _) = merge_cycles(&r, &cover, strategy);
            let rep = check(&r, &tour, Mode::Milling);
            assert!(rep.valid && tour.is_tour(), "{:?}", rep.error);
            assert!(rep.turns <= 8 + 2, "{}", rep.turns);
        }
    }
}
