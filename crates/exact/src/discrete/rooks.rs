//! Channels and rook placements: the maximal straight channels of a discrete instance and a
//! maximum (MILP) or greedy rook placement on them, the cheap turn bound of Lemma 4.3 of
//! *Optimal covering tours with turn costs*.

use crate::lp::{Deadline, Formulation, Outcome, Row, Settings, solve_mip};
use mowmill_core::discrete::Discrete;
use mowmill_core::discrete::channels::{self as star_cover, Channel};
use serde::Serialize;

/// The maximal straight channels of an instance ([`star_cover::channels`], the one
/// computation of them) and, for every vertex, the indices of the channels through it.
pub fn channels(inst: &Discrete) -> (Vec<Channel>, Vec<Vec<u32>>) {
    let ch = star_cover::channels(inst);
    let through = (0..inst.len() as u32)
        .map(|v| ch.through(inst, v))
        .collect();
    (ch.list, through)
}

/// A rook placement: vertices no two of which lie on a common channel.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct RookPlacement {
    /// The number of rooks, a lower bound on the turns of every cycle cover (and tour).
    pub size: u64,
    /// The rooks, sorted.
    pub rooks: Vec<u32>,
    /// Whether `size` is proven maximum (by the MILP); otherwise the placement is greedy.
    pub exact: bool,
}

/// Above this many vertices [`rook_placement`] does not try the MILP.
pub const ROOK_MILP_LIMIT: usize = 20_000;

/// A maximum rook placement (Lemma 4.3 of *Optimal covering tours with turn costs*), by a
/// MILP when cheap, greedily otherwise.
///
/// A rook *attacks* every vertex it reaches by one link, i.e. every vertex on a maximal
/// straight channel through it ([`channels`]). Rooks are placed only on vertices that lie on
/// no cyclic channel (see the guarantee for why).
///
/// # Arguments
/// * `inst` — the instance.
/// * `time_limit` — seconds for the MILP; `Some(0.0)` (or more than [`ROOK_MILP_LIMIT`]
///   vertices) skips it.
///
/// # Returns
/// The placement; `exact` when the MILP `max Σ y_v` subject to `Σ_{v ∈ K} y_v <= 1` for every
/// channel `K` (each channel's vertices attack each other pairwise, and attack is exactly
/// sharing a channel, so these cliques are the whole attack graph) was solved to optimality.
/// Otherwise the greedy placement (repeatedly the free vertex attacking the fewest free
/// vertices), or the MILP's incumbent when it is larger, with `exact = false`.
///
/// # Complexity
/// Greedy: O(V · Σ_K |K|). MILP: exponential in the worst case, bounded by `time_limit`.
///
/// # Guarantee
/// Every cycle cover (hence every tour) has at least `size` turns. Proof: a closed walk of
/// one vertex costs 4 turns and visits one vertex. A closed walk `W` of two or more vertices
/// that passes straight everywhere stays on one channel, which then is cyclic; so it visits
/// no rook. Otherwise let `k >= 1` be the number of its visits that are not straight (a turn
/// of 1, or a U-turn of 2): they cut `W` into exactly `k` links (maximal straight runs), and
/// `turns(W) >= k`. A link runs along one channel, so the vertices it visits (its ends
/// included) attack each other pairwise, and it visits at most one rook. Every visit of `W`
/// lies on a link, so `W` visits at most `k <= turns(W)` rooks; summing over the walks of a
/// cover that visits every rook gives `turns >= size`. The paper's Lemma 4.3 places rooks on
/// every vertex; on a graph with a cyclic channel (a cycle of collinear pairs) that fails —
/// the cycle walked around once is a cover of 0 turns — hence the exclusion, which is void
/// on grid graphs (their channels are paths).
pub fn rook_placement(inst: &Discrete, time_limit: Option<f64>) -> RookPlacement {
    let (chans, through) = channels(inst);
    let n = inst.len();
    let eligible: Vec<bool> = (0..n)
        .map(|v| through[v].iter().all(|&c| !chans[c as usize].closed))
        .collect();
    let greedy = greedy_rooks(&chans, &through, &eligible);
    let try_milp = n <= ROOK_MILP_LIMIT && time_limit.is_none_or(|t| t > 0.0);
    if try_milp
        && let Some((rooks, exact)) = milp_rooks(&chans, &eligible, time_limit)
        && (exact || rooks.len() > greedy.len())
    {
        return RookPlacement {
            size: rooks.len() as u64,
            rooks,
            exact,
        };
    }
    RookPlacement {
        size: greedy.len() as u64,
        rooks: greedy,
        exact: false,
    }
}

/// Greedy rook placement: the free eligible vertex attacking the fewest free vertices first
/// (ties to the smallest index).
///
/// The attack counts are kept up to date in an ordered set instead of being recounted over
/// all vertices for every rook (which took O(V · Σ_K |K|): 25 s on 10^5 isolated vertices).
/// A vertex's count is the sum, over its channels, of the channel's free vertices; when a
/// vertex stops being free, the counts of the vertices on its channels drop. That update work
/// is bounded by [`GREEDY_WORK_PER_INCIDENCE`] per vertex-channel incidence: past it (long
/// channels losing vertices one by one, as on a 2000 × 2000 lattice) the remaining free
/// vertices are placed in index order, each still attacking no earlier rook, so the placement
/// stays valid and the total time near-linear.
pub(super) fn greedy_rooks(chans: &[Channel], through: &[Vec<u32>], eligible: &[bool]) -> Vec<u32> {
    let n = eligible.len();
    let mut free: Vec<bool> = eligible.to_vec();
    // holders[c]: the vertices with c among their channels (once per listing); members[w]: the
    // channels listing w among their vertices (once per listing).
    let mut holders: Vec<Vec<u32>> = vec![Vec::new(); chans.len()];
    for (v, cs) in through.iter().enumerate() {
        for &c in cs {
            holders[c as usize].push(v as u32);
        }
    }
    let mut members: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (c, ch) in chans.iter().enumerate() {
        for &w in &ch.verts {
            members[w as usize].push(c as u32);
        }
    }
    let mut free_in: Vec<usize> = chans
        .iter()
        .map(|ch| ch.verts.iter().filter(|&&w| free[w as usize]).count())
        .collect();
    let mut attacked: Vec<usize> = (0..n)
        .map(|v| through[v].iter().map(|&c| free_in[c as usize]).sum())
        .collect();
    let mut queue = RookQueue::new(&attacked, &free);
    let incidences: usize =
        holders.iter().map(Vec::len).sum::<usize>() + members.iter().map(Vec::len).sum::<usize>();
    let budget = GREEDY_WORK_PER_INCIDENCE.saturating_mul(incidences + n);
    let mut work = 0usize;
    let mut rooks = Vec::new();
    let mut dead = Vec::new();
    while let Some(v) = queue.pop(&attacked, &free) {
        rooks.push(v);
        free[v as usize] = false;
        dead.push(v);
        for &c in &through[v as usize] {
            for &w in &chans[c as usize].verts {
                if std::mem::replace(&mut free[w as usize], false) {
                    dead.push(w);
                }
            }
        }
        if work > budget {
            dead.clear();
            continue;
        }
        for w in dead.drain(..) {
            for &c in &members[w as usize] {
                free_in[c as usize] -= 1;
                work += holders[c as usize].len();
                for &u in &holders[c as usize] {
                    if free[u as usize] {
                        attacked[u as usize] -= 1;
                        queue.lowered(u, &attacked, &free);
                    }
                }
            }
        }
        if work > budget {
            // Index order from here on: the queue's order no longer follows the counts.
            queue.index_order();
        }
    }
    rooks.sort_unstable();
    rooks
}

/// The free vertices of [`greedy_rooks`] by (attack count, index), smallest first: a bucket
/// per count, each a min-heap of indices, with stale entries skipped when popped (an entry
/// `u` in bucket `a` is live while `u` is free and attacked by `a`). Counts only fall, by one
/// at a time, so a lowered vertex is pushed once per value and the lowest non-empty bucket
/// only moves down when a vertex is lowered below it: O(log n) per update, against the
/// ordered set's much larger constant (a 2000 × 2000 lattice took minutes). When the stale
/// entries outnumber the vertices four to one the buckets are rebuilt from the live ones, so
/// the memory stays O(n) (lazy entries alone reached 7 GB on that lattice).
pub(super) struct RookQueue {
    buckets: Vec<std::collections::BinaryHeap<std::cmp::Reverse<u32>>>,
    low: usize,
    /// Entries in the buckets, live or stale.
    entries: usize,
    /// In index order (after the work budget): the next index to look at.
    by_index: Option<usize>,
}

impl RookQueue {
    fn new(attacked: &[usize], free: &[bool]) -> Self {
        let top = attacked.iter().copied().max().unwrap_or(0);
        let mut queue = RookQueue {
            buckets: vec![std::collections::BinaryHeap::new(); top + 1],
            low: 0,
            entries: 0,
            by_index: None,
        };
        queue.rebuild(attacked, free);
        queue
    }

    /// The buckets of the free vertices only (stale entries dropped).
    fn rebuild(&mut self, attacked: &[usize], free: &[bool]) {
        let mut lists: Vec<Vec<std::cmp::Reverse<u32>>> = vec![Vec::new(); self.buckets.len()];
        self.entries = 0;
        for (v, &a) in attacked.iter().enumerate() {
            if free[v] {
                lists[a].push(std::cmp::Reverse(v as u32));
                self.entries += 1;
            }
        }
        self.buckets = lists.into_iter().map(Into::into).collect();
        self.low = 0;
    }

    /// `u`'s count fell by one (to `attacked[u]`).
    fn lowered(&mut self, u: u32, attacked: &[usize], free: &[bool]) {
        if self.by_index.is_none() {
            let a = attacked[u as usize];
            self.buckets[a].push(std::cmp::Reverse(u));
            self.low = self.low.min(a);
            self.entries += 1;
            if self.entries > 4 * free.len() + 1024 {
                self.rebuild(attacked, free);
            }
        }
    }

    /// From now on, the free vertices in index order.
    fn index_order(&mut self) {
        if self.by_index.is_none() {
            self.buckets.clear();
            self.by_index = Some(0);
        }
    }

    /// The free vertex with the smallest count (then index), or in index order.
    fn pop(&mut self, attacked: &[usize], free: &[bool]) -> Option<u32> {
        if let Some(next) = self.by_index.as_mut() {
            while *next < free.len() {
                *next += 1;
                if free[*next - 1] {
                    return Some((*next - 1) as u32);
                }
            }
            return None;
        }
        while self.low < self.buckets.len() {
            while let Some(std::cmp::Reverse(u)) = self.buckets[self.low].pop() {
                if free[u as usize] && attacked[u as usize] == self.low {
                    return Some(u);
                }
            }
            self.low += 1;
        }
        None
    }
}

/// The update work [`greedy_rooks`] may spend per vertex-channel incidence (and per vertex)
/// before it places the remaining rooks in index order.
pub(super) const GREEDY_WORK_PER_INCIDENCE: usize = 16;

/// The rook MILP (one clique row per channel); `None` if HiGHS gives no solution. The flag
/// says whether the solution is proven optimal.
pub(super) fn milp_rooks(
    chans: &[Channel],
    eligible: &[bool],
    time_limit: Option<f64>,
) -> Option<(Vec<u32>, bool)> {
    let mut f = Formulation::default();
    for &e in eligible {
        f.add_col(-1.0, 0.0, if e { 1.0 } else { 0.0 }, true);
    }
    for c in chans {
        let mut vs: Vec<usize> = c.verts.iter().map(|&v| v as usize).collect();
        vs.sort_unstable();
        vs.dedup();
        if vs.len() >= 2 {
            f.rows
                .push(Row::range(vs.into_iter().map(|v| (v, 1.0)), 0.0, 1.0));
        }
    }
    let settings = Settings {
        threads: 1,
        verbose: false,
        ..Settings::default()
    };
    // Values are integers: a gap below 1 proves optimality.
    let mip = solve_mip(
        &f,
        &[],
        None,
        &Deadline::new(time_limit),
        &settings,
        Some(0.99),
    );
    let x = mip.x?;
    let rooks: Vec<u32> = (0..x.len())
        .filter(|&v| x[v] > 0.5)
        .map(|v| v as u32)
        .collect();
    if !f.is_feasible(&x.iter().map(|v| v.round()).collect::<Vec<_>>(), &[]) {
        return None;
    }
    Some((rooks, mip.outcome == Outcome::Optimal))
}
