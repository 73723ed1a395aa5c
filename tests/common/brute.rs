#![allow(dead_code)] // each test binary uses part of it
//! The brute-force oracle of the exact solvers (tests/exact.rs, tests/certificates.rs): optima
//! of tiny regions (N <= 8) by enumeration, independent of the MILP models.

use mowmill::region::{Dir, Region};
use std::collections::{BinaryHeap, HashMap};

/// The cheapest closed walk covering exactly each pixel set, for a cost of `w_len` per unit
/// move plus `w_turn` per quarter turn: Dijkstra over (pixel, heading, first heading, visited)
/// from the set's lowest pixel. Index: bit mask. One-pixel walks cost 4 turns, length 0.
pub fn cheapest_walks(r: &Region, w_len: u64, w_turn: u64) -> Vec<u64> {
    let n = r.len();
    assert!(n <= 8);
    let full = 1usize << n;
    let mut best = vec![u64::MAX; full];
    for v in 0..n {
        best[1 << v] = 4 * w_turn;
    }
    for s in 0..n {
        // State: (pixel, heading, first heading, mask); only masks whose lowest pixel is s.
        let idx = |v: usize, h: usize, h0: usize, m: usize| ((m * n + v) * 4 + h) * 4 + h0;
        let mut dist: HashMap<usize, u64> = HashMap::new();
        let mut heap = BinaryHeap::new();
        for d in Dir::ALL {
            if let Some(w) = r.neighbor(s, d) {
                if w < s {
                    continue;
                }
                let m = (1 << s) | (1 << w);
                let k = idx(w, d.index(), d.index(), m);
                dist.insert(k, w_len);
                heap.push(std::cmp::Reverse((w_len, w, d.index(), d.index(), m)));
            }
        }
        while let Some(std::cmp::Reverse((c, v, h, h0, m))) = heap.pop() {
            if dist.get(&idx(v, h, h0, m)).is_some_and(|&d| d < c) {
                continue;
            }
            if v == s {
                let close = c + w_turn * u64::from(Dir::from_index(h).turn_to(Dir::from_index(h0)));
                best[m] = best[m].min(close);
            }
            for d in Dir::ALL {
                let Some(w) = r.neighbor(v, d) else { continue };
                if w < s {
                    continue;
                }
                let nc = c + w_len + w_turn * u64::from(Dir::from_index(h).turn_to(d));
                let nm = m | (1 << w);
                let k = idx(w, d.index(), h0, nm);
                if dist.get(&k).is_none_or(|&old| nc < old) {
                    dist.insert(k, nc);
                    heap.push(std::cmp::Reverse((nc, w, d.index(), h0, nm)));
                }
            }
        }
    }
    best
}

/// Brute-force optimum of a tour objective (None when no tour exists).
pub fn brute_tour(r: &Region, w_len: u64, w_turn: u64) -> Option<u64> {
    let best = cheapest_walks(r, w_len, w_turn);
    let v = best[(1 << r.len()) - 1];
    (v != u64::MAX).then_some(v)
}

/// Brute-force minimum-turn cycle cover: subset DP over exact cover sets of closed walks.
pub fn brute_cc_turns(r: &Region) -> u64 {
    let best = cheapest_walks(r, 0, 1);
    let full = (1usize << r.len()) - 1;
    let mut f = vec![u64::MAX; full + 1];
    f[0] = 0;
    for m in 1..=full {
        let low = m & m.wrapping_neg();
        // Sets S containing the lowest pixel of m.
        let mut s = full;
        loop {
            if s & low != 0 && best[s] != u64::MAX && f[m & !s] != u64::MAX {
                f[m] = f[m].min(best[s] + f[m & !s]);
            }
            if s == 0 {
                break;
            }
            s = (s - 1) & full;
        }
    }
    f[full]
}

/// Brute-force lawn TSP: all cyclic orders from pixel 0.
pub fn brute_lawn(r: &Region) -> u64 {
    let n = r.len();
    if n <= 1 {
        return 0;
    }
    let mut rest: Vec<usize> = (1..n).collect();
    let mut best = u64::MAX;
    permute(&mut rest, 0, &mut |p| {
        let mut c = r.pixel(0).l1(r.pixel(p[0])) + r.pixel(p[p.len() - 1]).l1(r.pixel(0));
        for w in p.windows(2) {
            c += r.pixel(w[0]).l1(r.pixel(w[1]));
        }
        best = best.min(c);
    });
    best
}

pub fn permute(a: &mut Vec<usize>, k: usize, f: &mut dyn FnMut(&[usize])) {
    if k == a.len() {
        f(a);
        return;
    }
    for i in k..a.len() {
        a.swap(k, i);
        permute(a, k + 1, f);
        a.swap(k, i);
    }
}
