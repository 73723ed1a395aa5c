//! Growth and erosion by simple pixels (Yokoi number 1): the frontier of candidate cells,
//! weighted by compactness, that brings every random shape to exactly N pixels.

use super::canvas::{ADJ_MARGIN, Canvas};
use super::rng::{Rng, below, unit};

/// Growth weights by bucket (bucket b = 1..=4, see `candidate`): b^γ with γ = −3 at
/// compactness 0 (prefer tips: ragged), 0 at 1/3 (uniform: Eden growth), 6 at 1 (prefer
/// concave cells: round). γ is a multiple of 1/4 and b^γ is computed from square roots and
/// products only, which IEEE 754 rounds the same everywhere.
pub(super) fn bucket_weights(compactness: f64) -> [f64; 5] {
    let q = (compactness * 36.0).round() as i32 - 12;
    let mut w = [0.0; 5];
    for (b, wb) in w.iter_mut().enumerate().skip(1) {
        let root = (b as f64).sqrt().sqrt();
        let mut x = 1.0;
        for _ in 0..q.unsigned_abs() {
            x *= root;
        }
        *wb = if q < 0 { 1.0 / x } else { x };
    }
    w
}

/// Candidate cells in 5 weight buckets, with O(1) insert, move, remove and weighted sampling.
pub(super) struct Frontier {
    pub(super) slot: Vec<u32>,
    pub(super) bucket: Vec<u8>,
    pub(super) items: [Vec<u32>; 5],
}

pub(super) const ABSENT: u32 = u32::MAX;

impl Frontier {
    pub(super) fn new(area: usize) -> Frontier {
        Frontier {
            slot: vec![ABSENT; area],
            bucket: vec![0; area],
            items: Default::default(),
        }
    }

    pub(super) fn clear(&mut self) {
        for items in &mut self.items {
            for &k in items.iter() {
                self.slot[k as usize] = ABSENT;
            }
            items.clear();
        }
    }

    /// Puts `k` in bucket `b`, or takes it out for `None`.
    pub(super) fn set(&mut self, k: usize, b: Option<u8>) {
        let s = self.slot[k];
        if s != ABSENT {
            let old = self.bucket[k];
            if b == Some(old) {
                return;
            }
            let items = &mut self.items[old as usize];
            let last = *items.last().expect("slot points into a non-empty bucket");
            items.swap_remove(s as usize);
            if last as usize != k {
                self.slot[last as usize] = s;
            }
            self.slot[k] = ABSENT;
        }
        if let Some(b) = b {
            self.slot[k] = self.items[b as usize].len() as u32;
            self.items[b as usize].push(k as u32);
            self.bucket[k] = b;
        }
    }

    /// A candidate drawn with probability proportional to its bucket's weight.
    pub(super) fn sample(&self, rng: &mut Rng, weights: &[f64; 5]) -> Option<usize> {
        let masses: [f64; 5] = std::array::from_fn(|b| self.items[b].len() as f64 * weights[b]);
        let total: f64 = masses.iter().sum();
        if total <= 0.0 {
            return None;
        }
        let mut r = unit(rng) * total;
        let mut chosen = None;
        for (b, &mass) in masses.iter().enumerate() {
            if mass > 0.0 {
                chosen = Some(b);
                if r < mass {
                    break;
                }
                r -= mass;
            }
        }
        let items = &self.items[chosen?];
        Some(items[below(rng, items.len())] as usize)
    }
}

/// A topology-preserving change of one cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Move {
    /// Add an empty cell next to the region.
    Grow,
    /// Remove a pixel of the region's boundary.
    Shrink,
    /// Remove a pixel next to hole `h`, enlarging that hole.
    Hole(u32),
}

/// The bucket of `k` as a candidate for `mv` (None: not a candidate). Grow: m ∈ 1..=4 region
/// 4-neighbours; Shrink: 4 − m (tips first when round); Hole: hole 4-neighbours, at least 1.
pub(super) fn candidate(c: &Canvas, k: usize, mv: Move, margin: usize) -> Option<u8> {
    if !c.in_zone(k, margin) {
        return None;
    }
    let m = c.nb4(k) as u8;
    match mv {
        Move::Grow => (!c.occ[k] && m > 0).then_some(m),
        Move::Shrink => (c.occ[k] && m < 4).then_some(4 - m),
        Move::Hole(h) => {
            if !c.occ[k] || !(0..8).any(|i| c.hole[c.nb(k, i)] == h) {
                return None;
            }
            let in_hole = (0..4).filter(|&i| c.hole[c.nb(k, 2 * i)] == h).count() as u8;
            Some(in_hole.max(1))
        }
    }
}

/// Whether flipping `k` keeps components and holes (k simple) and, with `no_cut`, leaves no
/// pixel of its 3 × 3 block with Yokoi number ≥ 2 (no new local cut vertex).
pub(super) fn acceptable(c: &mut Canvas, k: usize, no_cut: bool) -> bool {
    if c.yokoi(k) != 1 {
        return false;
    }
    if !no_cut {
        return true;
    }
    c.occ[k] = !c.occ[k];
    let ok = std::iter::once(k)
        .chain((0..8).map(|i| c.nb(k, i)))
        .all(|q| !c.occ[q] || c.yokoi(q) <= 1);
    c.occ[k] = !c.occ[k];
    ok
}

/// Re-buckets the cells within Chebyshev distance `r` of `k`.
pub(super) fn refresh(c: &Canvas, f: &mut Frontier, k: usize, r: usize, mv: Move, margin: usize) {
    let (x, y) = (k % c.w, k / c.w);
    for yy in y - r..=y + r {
        for xx in x - r..=x + r {
            let q = c.idx(xx, yy);
            f.set(q, candidate(c, q, mv, margin));
        }
    }
}

/// Puts every candidate of the canvas into `f`.
pub(super) fn scan(c: &Canvas, f: &mut Frontier, mv: Move, margin: usize) {
    f.clear();
    for y in margin..c.h - margin {
        for x in margin..c.w - margin {
            let k = c.idx(x, y);
            if let Some(b) = candidate(c, k, mv, margin) {
                f.set(k, Some(b));
            }
        }
    }
}

/// Applies moves drawn from `f` until `done`; false if the candidates run out first.
///
/// A rejected candidate leaves `f` and comes back only when a cell near it changes (the
/// acceptance of a cell depends on its 3 × 3 block, or 5 × 5 with `no_cut`), so every
/// call does O(initial candidates + moves) work.
#[allow(clippy::too_many_arguments)]
pub(super) fn evolve(
    c: &mut Canvas,
    f: &mut Frontier,
    mv: Move,
    weights: &[f64; 5],
    no_cut: bool,
    margin: usize,
    rng: &mut Rng,
    done: impl Fn(&Canvas) -> bool,
) -> bool {
    let r = if no_cut { 2 } else { 1 };
    while !done(c) {
        let Some(k) = f.sample(rng, weights) else {
            return false;
        };
        if acceptable(c, k, no_cut) {
            match mv {
                Move::Grow => c.set(k, true),
                Move::Shrink => c.set(k, false),
                Move::Hole(h) => {
                    c.set(k, false);
                    c.hole[k] = h;
                }
            }
            refresh(c, f, k, r, mv, margin);
        } else {
            f.set(k, None);
        }
    }
    true
}

/// Adds or removes simple pixels until the canvas has exactly `target` pixels.
pub(super) fn adjust(
    c: &mut Canvas,
    f: &mut Frontier,
    target: usize,
    weights: &[f64; 5],
    no_cut: bool,
    rng: &mut Rng,
) -> bool {
    if c.count < target {
        scan(c, f, Move::Grow, ADJ_MARGIN);
        evolve(c, f, Move::Grow, weights, no_cut, ADJ_MARGIN, rng, |c| {
            c.count >= target
        })
    } else if c.count > target {
        scan(c, f, Move::Shrink, ADJ_MARGIN);
        evolve(c, f, Move::Shrink, weights, no_cut, ADJ_MARGIN, rng, |c| {
            c.count <= target
        })
    } else {
        true
    }
}
