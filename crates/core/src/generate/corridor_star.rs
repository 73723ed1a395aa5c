//! `corridor-star`: k ∈ 1..=4 straight corridors of width w ∈ {1, 2} crossing at a centre.
//!
//! With arm length L ≥ w + 1 (each corridor runs L cells beyond the centre on both sides):
//! corridor 1 is horizontal, cells −L ≤ x ≤ L + w − 1, 0 ≤ y ≤ w − 1 (w(2L + w) cells);
//! corridor 2 vertical (the same, transposed); corridor 3 the diagonal staircase of rows
//! −L ≤ y ≤ L + w − 1 with 0 ≤ x − y ≤ w ((w + 1)(2L + w) cells, 4-connected, width w); corridor
//! 4 its mirror image x ↦ w − 1 − x (−1 ≤ x + y ≤ w − 1). The corridors overlap only near the
//! centre, in c(k, w) cells independent of L, so
//! **N = (2L + w)·(a·w + d·(w + 1)) − c(k, w)**, with a = min(k, 2) axis corridors and
//! d = k − a diagonal ones, and c(1, w) = 0, c(2, 1) = 1, c(3, 1) = 4, c(4, 1) = 7,
//! c(2, 2) = 4, c(3, 2) = 14, c(4, 2) = 23 (test `corridor_star_counts`). L is the length nearest
//! to the requested n. The union of the four has holes (the cells between a diagonal and an
//! axis corridor near the centre), counted in the file's `holes` line.
//!
//! Why it is hard: 2k dead-end arms of width 1 or 2 around one junction: every arm is walked
//! out and back (length about 2N, two U-turns per arm), the diagonal arms are staircases that
//! turn at every cell, and the junction is the only place where strips from different arms
//! can be merged: it stresses the strip-cover turn bounds and the thin algorithms of the
//! turn paper (Section 5), and the contour walks of the milling paper (Q = 0 for w = 1).

use crate::region::Pixel;
use std::collections::BTreeSet;

/// The smallest arm length.
pub(super) fn star_min_arm(w: usize) -> usize {
    w + 1
}

/// Whether (x, y) lies on corridor `line` (0 horizontal, 1 vertical, 2 diagonal, 3 mirrored).
fn on_line(line: usize, l: i64, w: i64, x: i64, y: i64) -> bool {
    let span = |v: i64| -l <= v && v < l + w;
    match line {
        0 => span(x) && (0..w).contains(&y),
        1 => span(y) && (0..w).contains(&x),
        2 => span(y) && (0..=w).contains(&(x - y)),
        _ => span(y) && (-1..w).contains(&(x + y)),
    }
}

/// The star's pixels, each once, row by row.
pub(super) fn star_pixels(k: usize, l: usize, w: usize) -> Vec<Pixel> {
    let (li, wi) = (l as i64, w as i64);
    let mut set = BTreeSet::new();
    for y in -li - wi..=li + wi {
        for x in -li - wi..=li + wi {
            if (0..k).any(|line| on_line(line, li, wi, x, y)) {
                set.insert((y, x));
            }
        }
    }
    set.into_iter()
        .map(|(y, x)| Pixel::new(x as i32, y as i32))
        .collect()
}

/// The cells per unit of 2L + w: a·w + d·(w + 1).
fn star_rate(k: usize, w: usize) -> usize {
    let a = k.min(2);
    a * w + (k - a) * (w + 1)
}

/// The centre's overlap c(k, w) (module documentation), counted at the smallest arm length.
pub(super) fn star_overlap(k: usize, w: usize) -> usize {
    let l = star_min_arm(w);
    (2 * l + w) * star_rate(k, w) - star_pixels(k, l, w).len()
}

/// The pixel count for arm length l: (2l + w)(a·w + d(w + 1)) − c(k, w).
pub(super) fn star_count(k: usize, l: usize, w: usize) -> usize {
    (2 * l + w) * star_rate(k, w) - star_overlap(k, w)
}

/// The arm length ≥ w + 1 whose star is nearest to n pixels (the smaller on a tie).
pub(super) fn star_arm(n: usize, k: usize, w: usize) -> usize {
    let rate = star_rate(k, w);
    let c = star_overlap(k, w);
    let min = star_min_arm(w);
    // N = (2l + w)·rate − c: l ≈ ((n + c)/rate − w)/2; look at its neighbours.
    let guess = ((n + c) / rate).saturating_sub(w) / 2;
    let mut best = (usize::MAX, min);
    for l in guess.saturating_sub(1)..=guess + 1 {
        let l = l.max(min);
        let d = star_count(k, l, w).abs_diff(n);
        if d < best.0 {
            best = (d, l);
        }
    }
    best.1
}
