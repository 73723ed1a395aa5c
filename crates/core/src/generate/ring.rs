//! `ring`: a rectangular annulus of width w ∈ {1, 2}.
//!
//! The a × b rectangle minus its centred (a − 2w) × (b − 2w) rectangle, with b ∈ {a, a + 1}
//! (about square) and a + b = t chosen so that **N = 2w·t − 4w²** is nearest to n; a ≥ 2w + 1,
//! so there is exactly one hole. For w = 1 this is every even N ≥ 8.
//!
//! Why it is hard: the simplest region with a hole, on which the lower bounds are nearly
//! tight, so any slack of an algorithm shows. Width 1 is a cycle (optimum length N, 4 turns);
//! width 2 makes a tour choose between two concentric loops (8 turns) and one loop with
//! detours, which is where the contour walks of the milling paper (Theorems 4, 7) and the
//! strip covers of the turn paper (Section 5) pay for the hole.

use crate::region::Pixel;

/// The outer sides (a, b), b ∈ {a, a + 1}, for about n pixels at width w.
pub(super) fn ring_sides(n: usize, w: usize) -> (usize, usize) {
    // N = 2w t − 4w², so t = (n + 4w²) / 2w rounded, and t ≥ 2(2w + 1).
    let t = ((n + 4 * w * w) + w) / (2 * w);
    let t = t.max(2 * (2 * w + 1));
    (t / 2, t - t / 2)
}

/// The ring's pixel count: 2w(a + b) − 4w².
pub(super) fn ring_count(a: usize, b: usize, w: usize) -> usize {
    2 * w * (a + b) - 4 * w * w
}

pub(super) fn ring_pixels(a: usize, b: usize, w: usize) -> Vec<Pixel> {
    (0..b)
        .flat_map(|y| {
            (0..a)
                .filter(move |&x| x < w || x >= a - w || y < w || y >= b - w)
                .map(move |x| Pixel::new(x as i32, y as i32))
        })
        .collect()
}
