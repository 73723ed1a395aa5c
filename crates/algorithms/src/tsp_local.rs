//! 2-opt and Or-opt on neighbour lists with don't-look bits, on an array tour with segment
//! reversal of the shorter side, then a short iterated local search (local double-bridge
//! kicks, fixed seed, undone when they do not pay), over any symmetric [`Metric`] of points
//! `0..n`: the local search of `lawn-2opt` (cell centres in the motion's metric) and of
//! `milling-2opt` (pixels in the region's shortest-path metric).
//!
//! Every applied move has a positive gain (or, for a kick that is kept, the tour is not
//! longer afterwards), so the result is never longer than the start.

use rand::{RngExt, SeedableRng};
use std::collections::VecDeque;

/// A symmetric distance between the points `0..n` of a tour.
pub(crate) trait Metric {
    fn dist(&self, a: usize, b: usize) -> f64;

    /// The length of the closed tour.
    fn tour_length(&self, tour: &[usize]) -> f64 {
        (0..tour.len())
            .map(|k| self.dist(tour[k], tour[(k + 1) % tour.len()]))
            .sum()
    }
}

/// The default number of kicks of the iterated local search: 30 per point, at most 20,000.
pub(crate) fn default_kicks(n: usize) -> usize {
    (30 * n).min(20_000)
}

/// Gains below this are treated as zero (lengths are sums of a few exact or rounded terms).
const EPS: f64 = 1e-9;

/// An array tour with positions, reversals of the shorter side and an optional journal of
/// the reversals (to undo a kick).
struct Tour<'a, M: Metric> {
    p: &'a M,
    order: Vec<usize>,
    pos: Vec<usize>,
    journal: Option<Vec<(usize, usize)>>,
    /// The sum of the gains of the moves applied so far.
    gained: f64,
}

impl<M: Metric> Tour<'_, M> {
    fn n(&self) -> usize {
        self.order.len()
    }

    fn next(&self, v: usize) -> usize {
        self.order[(self.pos[v] + 1) % self.n()]
    }

    fn prev(&self, v: usize) -> usize {
        self.order[(self.pos[v] + self.n() - 1) % self.n()]
    }

    /// The neighbour of `v` along direction `forward`.
    fn succ(&self, v: usize, forward: bool) -> usize {
        if forward { self.next(v) } else { self.prev(v) }
    }

    /// Reverses the array positions i..=j (cyclically), or the complement when shorter (the
    /// same cycle).
    fn reverse_positions(&mut self, i: usize, j: usize) {
        let n = self.n();
        let len = (j + n - i) % n + 1;
        let (lo, hi, len) = if 2 * len > n {
            ((j + 1) % n, (i + n - 1) % n, n - len)
        } else {
            (i, j, len)
        };
        if len < 2 {
            return;
        }
        if let Some(journal) = self.journal.as_mut() {
            journal.push((lo, hi));
        }
        self.swap_ends(lo, hi, len);
    }

    /// Reverses the `len` positions from `lo` to `hi` (cyclically), keeping `pos` in step.
    fn swap_ends(&mut self, mut lo: usize, mut hi: usize, len: usize) {
        let n = self.n();
        for _ in 0..len / 2 {
            self.order.swap(lo, hi);
            self.pos[self.order[lo]] = lo;
            self.pos[self.order[hi]] = hi;
            lo = (lo + 1) % n;
            hi = (hi + n - 1) % n;
        }
    }

    /// Replaces the tour edges (a, b) and (c, d), met in the order a, b, …, c, d along one
    /// direction of the tour, by (a, c) and (b, d): reverses the path b … c.
    fn move2(&mut self, a: usize, b: usize, c: usize) {
        if self.next(a) == b {
            self.reverse_positions(self.pos[b], self.pos[c]);
        } else {
            self.reverse_positions(self.pos[c], self.pos[b]);
        }
    }

    fn undo(&mut self, journal: &[(usize, usize)]) {
        let n = self.n();
        for &(i, j) in journal.iter().rev() {
            self.swap_ends(i, j, (j + n - i) % n + 1);
        }
    }

    fn d(&self, a: usize, b: usize) -> f64 {
        self.p.dist(a, b)
    }

    /// Tries a 2-opt move on the edge leaving `a` along `forward`; returns the touched nodes.
    fn try_two_opt(&mut self, nb: &[usize], a: usize, forward: bool) -> Option<[usize; 4]> {
        let an = self.succ(a, forward);
        let d_an = self.d(a, an);
        for &c in nb {
            let g1 = d_an - self.d(a, c);
            if g1 <= EPS {
                break;
            }
            let cn = self.succ(c, forward);
            if c == an || cn == a {
                continue;
            }
            let gain = g1 + self.d(c, cn) - self.d(an, cn);
            if gain > EPS {
                self.gained += gain;
                self.move2(a, an, c);
                return Some([a, an, c, cn]);
            }
        }
        None
    }

    /// Tries to move the segment of `len` points starting at `a` along `forward` between a
    /// neighbour c of its ends and c's successor or predecessor, either way round.
    fn try_or_opt(
        &mut self,
        nbs: &[Vec<usize>],
        a: usize,
        len: usize,
        forward: bool,
    ) -> Option<[usize; 6]> {
        let n = self.n();
        if n < len + 3 {
            return None;
        }
        let s0 = a;
        let mut s1 = a;
        for _ in 1..len {
            s1 = self.succ(s1, forward);
        }
        let p = self.succ(s0, !forward);
        let nx = self.succ(s1, forward);
        let removal = self.d(p, s0) + self.d(s1, nx) - self.d(p, nx);
        if removal <= EPS {
            return None;
        }
        let in_seg = |t: &Self, v: usize| {
            let off = if forward {
                (t.pos[v] + n - t.pos[s0]) % n
            } else {
                (t.pos[s0] + n - t.pos[v]) % n
            };
            off < len
        };
        for &end in &[s0, s1] {
            for &c in &nbs[end] {
                if removal - self.d(end, c) <= EPS {
                    break;
                }
                if c == p || in_seg(self, c) {
                    // c = p: only (p, s0) or (pp, p) edges; the latter is (c's pred, c).
                    if c != p {
                        continue;
                    }
                }
                for side in [true, false] {
                    // Insert between x and y = succ(x) (along `forward`).
                    let (x, y) = if side {
                        (c, self.succ(c, forward))
                    } else {
                        (self.succ(c, !forward), c)
                    };
                    if x == p || in_seg(self, x) || in_seg(self, y) {
                        continue;
                    }
                    // Reversed: x s1 … s0 y; kept: x s0 … s1 y.
                    let rev = self.d(x, s1) + self.d(s0, y);
                    let keep = self.d(x, s0) + self.d(s1, y);
                    let insert = rev.min(keep) - self.d(x, y);
                    if removal - insert > EPS {
                        self.gained += removal - insert;
                        // p S nx … x y  →  p x … nx S^R y  →  p nx … x S^R y.
                        self.move2(p, s0, x);
                        self.move2(p, x, nx);
                        if keep < rev {
                            self.move2(x, s1, s0);
                        }
                        return Some([p, nx, s0, s1, x, y]);
                    }
                }
            }
        }
        None
    }

    /// Local search until no node is active.
    fn optimise(&mut self, nbs: &[Vec<usize>], queue: &mut VecDeque<usize>, active: &mut [bool]) {
        while let Some(a) = queue.pop_front() {
            active[a] = false;
            let mut touched: Vec<usize> = Vec::new();
            'moves: for forward in [true, false] {
                if let Some(t) = self.try_two_opt(&nbs[a], a, forward) {
                    touched.extend_from_slice(&t);
                    break 'moves;
                }
                for len in 1..=3 {
                    if let Some(t) = self.try_or_opt(nbs, a, len, forward) {
                        touched.extend_from_slice(&t);
                        break 'moves;
                    }
                }
            }
            for v in touched {
                if !active[v] {
                    active[v] = true;
                    queue.push_back(v);
                }
            }
        }
    }
}

/// 2-opt and Or-opt (segments of 1 to 3 points) on the neighbour lists `nbs` (each sorted
/// nearest first) of each point with don't-look bits, then an iterated local search of `kicks` local double-bridge
/// kicks (seeded, kept when the tour does not get longer). Never longer than `start`.
pub(crate) fn improve<M: Metric>(
    p: &M,
    nbs: &[Vec<usize>],
    kicks: usize,
    start: Vec<usize>,
) -> Vec<usize> {
    let n = start.len();
    if n < 5 {
        return start;
    }
    let start_length = p.tour_length(&start);
    let start_copy = start.clone();
    let mut pos = vec![0usize; n];
    for (k, &v) in start.iter().enumerate() {
        pos[v] = k;
    }
    let mut t = Tour {
        p,
        order: start,
        pos,
        journal: None,
        gained: 0.0,
    };
    let mut queue: VecDeque<usize> = t.order.iter().copied().collect();
    let mut active = vec![true; n];
    t.optimise(nbs, &mut queue, &mut active);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x1a_e2_0b_7e);
    let kicks = if n < 8 { 0 } else { kicks };
    let span = 50.min(n / 3);
    for _ in 0..kicks {
        // A double bridge A B C D → A C B D on two short consecutive segments B, C from a
        // random position: B C becomes C B by three reversals, (B^R C^R)^R.
        let i = rng.random_range(0..n);
        let lb = rng.random_range(1..=span);
        let lc = rng.random_range(1..=span);
        let (b0, b1) = (i, (i + lb - 1) % n);
        let (c0, c1) = ((i + lb) % n, (i + lb + lc - 1) % n);
        let ends = [
            t.order[(i + n - 1) % n],
            t.order[b0],
            t.order[b1],
            t.order[c0],
            t.order[c1],
            t.order[(c1 + 1) % n],
        ];
        let [a, x0, x1, y0, y1, z] = ends;
        let before = t.d(a, x0) + t.d(x1, y0) + t.d(y1, z);
        let after = t.d(a, y0) + t.d(y1, x0) + t.d(x1, z);
        t.journal = Some(Vec::new());
        t.gained = before - after;
        t.reverse_positions(b0, b1);
        t.reverse_positions(c0, c1);
        t.reverse_positions(b0, c1);
        for &v in &ends {
            if !active[v] {
                active[v] = true;
                queue.push_back(v);
            }
        }
        t.optimise(nbs, &mut queue, &mut active);
        let journal = t.journal.take().unwrap_or_default();
        // Kept when the tour is not longer (ties let it drift across plateaus).
        if t.gained < -EPS {
            t.undo(&journal);
        }
    }
    // The gains are summed in floating point: a final exact comparison keeps the promise.
    if p.tour_length(&t.order) > start_length {
        return start_copy;
    }
    t.order
}
