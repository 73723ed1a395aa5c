//! `boundary`: regions in which every pixel is a boundary pixel (the precondition of
//! `boundary-cc`), and their fallback of two rows.

use super::canvas::{ADJ_MARGIN, Canvas};
use super::random_simple::simple_canvas;
use super::rng::{Rng, between, chance, shuffle};
use super::styles::ShapeOpts;
use crate::region::Pixel;

/// The number of maximal runs of occupied cells around the ring (cyclically; a full ring is
/// one run). Consecutive ring cells are 4-adjacent, so at most one run means that removing
/// the centre keeps its pixel neighbours connected to one another: connectivity is kept.
pub(super) fn ring_runs(ring: [bool; 8]) -> usize {
    if ring.iter().all(|&o| o) {
        return 1;
    }
    (0..8).filter(|&i| ring[i] && !ring[(i + 7) % 8]).count()
}

/// Whether the occupied cells stay 4-connected without `k` (breadth-first search).
pub(super) fn connected_without(c: &Canvas, k: usize) -> bool {
    let Some(start) = (0..4).map(|i| c.nb(k, 2 * i)).find(|&q| c.occ[q]) else {
        return c.count <= 1;
    };
    let mut seen = vec![false; c.area()];
    seen[k] = true;
    seen[start] = true;
    let (mut stack, mut reached) = (vec![start], 1);
    while let Some(q) = stack.pop() {
        for i in 0..4 {
            let r = c.nb(q, 2 * i);
            if c.occ[r] && !seen[r] {
                seen[r] = true;
                reached += 1;
                stack.push(r);
            }
        }
    }
    reached + 1 == c.count
}

/// Inner pixels (all four neighbours present) the local rule may leave behind before an
/// attempt gives up; each costs a global connectivity check.
pub(super) const MAX_STUCK: usize = 64;

/// A connected region of exactly `n` pixels, every one with an empty 4-neighbour: a shape of
/// the given style, then every inner pixel k in random order loses k itself (a pinhole or a
/// notch) or one of its four neighbours (stairs, one-pixel links and parts), whichever first
/// keeps the region connected, then simple growth or erosion to n that never makes a pixel
/// inner again.
pub(super) fn boundary_canvas(n: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<Canvas> {
    let (mut c, _) = simple_canvas(n + n / 3 + 1, o, rng)?;
    let own = between(rng, 20, 80) as f64 / 100.0;
    let mut inner: Vec<u32> = (0..c.area())
        .filter(|&k| c.occ[k] && c.nb4(k) == 4)
        .map(|k| k as u32)
        .collect();
    shuffle(&mut inner, rng);
    let mut stuck = Vec::new();
    for k in inner {
        let k = k as usize;
        if !c.occ[k] || c.nb4(k) < 4 {
            continue;
        }
        let mut options = [k, c.nb(k, 0), c.nb(k, 2), c.nb(k, 4), c.nb(k, 6)];
        shuffle(&mut options[1..], rng);
        if !chance(rng, own) {
            options.rotate_left(1);
        }
        match options
            .iter()
            .find(|&&r| c.in_zone(r, ADJ_MARGIN) && ring_runs(c.ring_occ(r)) <= 1)
        {
            Some(&r) => c.set(r, false),
            None => stuck.push(k),
        }
    }
    if stuck.len() > MAX_STUCK {
        return None;
    }
    for k in stuck {
        if !c.occ[k] || c.nb4(k) < 4 {
            continue;
        }
        let options = [k, c.nb(k, 0), c.nb(k, 2), c.nb(k, 4), c.nb(k, 6)];
        let &r = options.iter().find(|&&r| connected_without(&c, r))?;
        c.set(r, false);
    }
    reach_size(&mut c, n, rng).then_some(c)
}

/// Grows or erodes a connected canvas of boundary pixels to exactly `n` pixels, keeping both
/// properties: add an empty cell only if it and its pixel neighbours keep an empty
/// 4-neighbour; remove a pixel only if its ring is one run (connectivity kept). False when a
/// pass over the candidates changes nothing.
pub(super) fn reach_size(c: &mut Canvas, n: usize, rng: &mut Rng) -> bool {
    while c.count != n {
        let grow = c.count < n;
        let mut cells: Vec<u32> = (0..c.area())
            .filter(|&k| c.in_zone(k, ADJ_MARGIN) && c.occ[k] != grow && c.nb4(k) > 0)
            .map(|k| k as u32)
            .collect();
        shuffle(&mut cells, rng);
        let before = c.count;
        for k in cells {
            let k = k as usize;
            if c.count == n {
                break;
            }
            let ok = if grow {
                !c.occ[k]
                    && c.nb4(k) < 4
                    && (0..4).all(|i| {
                        let q = c.nb(k, 2 * i);
                        !c.occ[q] || c.nb4(q) <= 2
                    })
            } else {
                c.occ[k] && ring_runs(c.ring_occ(k)) == 1
            };
            if ok {
                c.set(k, grow);
            }
        }
        if c.count == before {
            return false;
        }
    }
    true
}

/// The fallback of `boundary`: two rows, the upper one shorter by at most one pixel.
pub(super) fn two_rows_pixels(n: usize) -> Vec<Pixel> {
    (0..n)
        .map(|i| Pixel::new((i / 2) as i32, (i % 2) as i32))
        .collect()
}
