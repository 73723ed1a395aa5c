//! `thin-arms`: thin pockets grown pixel by pixel, with short arms at crossings.

use super::canvas::{ADJ_MARGIN, Canvas};
use super::rng::{Rng, below, chance, shuffle};
use super::styles::center;
use crate::region::Pixel;

/// Whether adding cell `k` would complete a 2 × 2 block of occupied cells.
pub(super) fn makes_block(c: &Canvas, k: usize) -> bool {
    let r = c.ring_occ(k);
    (0..4).any(|q| r[2 * q] && r[2 * q + 1] && r[(2 * q + 2) % 8])
}

/// A thin region of exactly n pixels and `holes` holes grown pixel by pixel: a tree grown
/// from one pixel by cells with one region neighbour that complete no 2 × 2 block (a cell
/// next to a pixel that already has two or more neighbours, i.e. a new branch, is accepted
/// with a probability rising with `compactness`, so crossings with short arms and stairs are
/// common), then `holes` bridging cells (Yokoi number 2, no 2 × 2 block), each closing one
/// loop.
pub(super) fn thin_arms_pixels(
    n: usize,
    holes: usize,
    compactness: f64,
    rng: &mut Rng,
) -> Option<Vec<Pixel>> {
    let tree = n - holes;
    let mut c = Canvas::for_target(n, 4, rng);
    let (x, y) = center(&c, rng);
    let k0 = c.idx(x, y);
    c.set(k0, true);
    let mut front: Vec<u32> = (0..4).map(|i| c.nb(k0, 2 * i) as u32).collect();
    let branchy = 0.15 + 0.7 * compactness;
    let mut budget = 400 * n + 1000;
    while c.count < tree {
        if front.is_empty() || budget == 0 {
            return None;
        }
        budget -= 1;
        let i = below(rng, front.len());
        let k = front[i] as usize;
        if c.occ[k] || !c.in_zone(k, ADJ_MARGIN) || c.yokoi(k) != 1 || makes_block(&c, k) {
            front.swap_remove(i);
            continue;
        }
        let branch = (0..4)
            .map(|d| c.nb(k, 2 * d))
            .any(|q| c.occ[q] && c.nb4(q) >= 2);
        let p = if branch { branchy } else { 1.0 - branchy / 2.0 };
        if chance(rng, p) {
            c.set(k, true);
            front.swap_remove(i);
            front.extend(
                (0..4)
                    .map(|d| c.nb(k, 2 * d))
                    .filter(|&q| !c.occ[q])
                    .map(|q| q as u32),
            );
        }
    }
    let mut bridges: Vec<u32> = (0..c.area())
        .filter(|&k| !c.occ[k] && c.in_zone(k, ADJ_MARGIN) && c.yokoi(k) == 2)
        .map(|k| k as u32)
        .collect();
    shuffle(&mut bridges, rng);
    let mut made = 0;
    while made < holes {
        let k = bridges.pop()? as usize;
        if !c.occ[k] && c.yokoi(k) == 2 && !makes_block(&c, k) {
            c.set(k, true);
            made += 1;
        }
    }
    Some(c.pixels())
}
