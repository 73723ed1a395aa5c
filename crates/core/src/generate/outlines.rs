//! `outlines`: the union of the width-1 outlines of K rectangles that cross one another.
//!
//! Rectangle i has its vertical sides at x-slots X[2i], X[2i + 1] and its horizontal sides at
//! y-slots Y[2i], Y[2i + 1], where X and Y are random permutations of 0..2K (ChaCha from the
//! seed), redrawn (at most 1000 times) until the outlines form one connected region; then the
//! chain layout (rectangle i on slots 2i and 2i + 3 of both axes, each crossing the next) is
//! used. A slot j lies at coordinate s·j, with the spacing s even; so every side lies on an
//! even row or column and no two sides share a row or a column. Hence every pixel lies on at
//! most one vertical and one horizontal side, the grid graph has degree 2 on sides and corners
//! and degree 4 at crossings (**every vertex has even degree: the region is Eulerian**), and
//! no 2 × 2 block is full (**thin**: a pixel at (odd, odd) lies on no side).
//!
//! With D = Σ_i (width_i + height_i) in slots and C the number of crossings (pairs of a
//! vertical side of one rectangle and a horizontal side of another that cross strictly
//! inside both), **N = 2sD − C**; s ≥ 2 is the even spacing nearest to the requested n.
//! K defaults to min(40, max(2, round(√n / 6))) and must satisfy 8K ≤ n (each outline has at
//! least 8 pixels); N may exceed n when the crossings leave no smaller spacing.
//!
//! Why it is hard: a thin Eulerian region whose Euler tours turn at every crossing they
//! do not go straight through: it is built to stress `thin-euler` (Theorem 5.8, 6/5) and
//! `thin-merge` (Theorem 5.9, 4/3) of the turn-cost paper, which reviewers report reach 1.15
//! on such unions.

use super::rng::{Rng, shuffle};
use crate::region::Pixel;

/// A layout: per rectangle, its x-slots and y-slots (low, high).
pub(super) type Layout = Vec<([usize; 2], [usize; 2])>;

/// Draws attempts this many times before the chain layout.
const LAYOUT_ATTEMPTS: usize = 1000;

/// The default number of rectangles for about n pixels.
pub(super) fn outlines_default_k(n: usize) -> usize {
    ((n.isqrt() + 3) / 6).clamp(2, 40)
}

fn sorted(a: usize, b: usize) -> [usize; 2] {
    [a.min(b), a.max(b)]
}

/// Whether the vertical sides of `a` cross the horizontal sides of `b`: the number of such
/// crossings (0 to 4).
fn crossings_one_way(a: &([usize; 2], [usize; 2]), b: &([usize; 2], [usize; 2])) -> usize {
    let (ax, ay) = a;
    let (bx, by) = b;
    let mut c = 0;
    for &xv in ax {
        for &yh in by {
            if bx[0] < xv && xv < bx[1] && ay[0] < yh && yh < ay[1] {
                c += 1;
            }
        }
    }
    c
}

/// The number of crossings C of a layout.
pub(super) fn crossings(layout: &Layout) -> usize {
    let mut c = 0;
    for (i, a) in layout.iter().enumerate() {
        for (j, b) in layout.iter().enumerate() {
            if i != j {
                c += crossings_one_way(a, b);
            }
        }
    }
    c
}

/// D: the sum of the rectangles' widths and heights in slots.
pub(super) fn slot_perimeter(layout: &Layout) -> usize {
    layout
        .iter()
        .map(|(x, y)| (x[1] - x[0]) + (y[1] - y[0]))
        .sum()
}

fn connected(layout: &Layout) -> bool {
    let k = layout.len();
    let mut seen = vec![false; k];
    let mut stack = vec![0];
    seen[0] = true;
    while let Some(i) = stack.pop() {
        for j in 0..k {
            if !seen[j]
                && (crossings_one_way(&layout[i], &layout[j]) > 0
                    || crossings_one_way(&layout[j], &layout[i]) > 0)
            {
                seen[j] = true;
                stack.push(j);
            }
        }
    }
    seen.iter().all(|&s| s)
}

/// The chain layout: rectangle i on slots 2i and 2i + 3 of both axes.
pub(super) fn chain_layout(k: usize) -> Layout {
    (0..k)
        .map(|i| ([2 * i, 2 * i + 3], [2 * i, 2 * i + 3]))
        .collect()
}

/// A connected random layout of k rectangles (the chain layout if none is found).
pub(super) fn outlines_layout(k: usize, rng: &mut Rng) -> Layout {
    for _ in 0..LAYOUT_ATTEMPTS {
        let mut xs: Vec<usize> = (0..2 * k).collect();
        let mut ys: Vec<usize> = (0..2 * k).collect();
        shuffle(&mut xs, rng);
        shuffle(&mut ys, rng);
        let layout: Layout = (0..k)
            .map(|i| {
                (
                    sorted(xs[2 * i], xs[2 * i + 1]),
                    sorted(ys[2 * i], ys[2 * i + 1]),
                )
            })
            .collect();
        if connected(&layout) {
            return layout;
        }
    }
    chain_layout(k)
}

/// The even spacing s ≥ 2 for which N = 2sD − C is nearest to n (the smaller on a tie).
pub(super) fn outlines_spacing(layout: &Layout, n: usize) -> usize {
    let d = slot_perimeter(layout);
    let c = crossings(layout);
    let count = |s: usize| 2 * s * d - c;
    // count is increasing in s: start from the estimate and look at its even neighbours.
    let guess = ((n + c) / (2 * d)).max(2) & !1;
    let mut best = (usize::MAX, 2);
    for s in [guess.saturating_sub(2), guess, guess + 2] {
        if s >= 2 && count(s).abs_diff(n) < best.0 {
            best = (count(s).abs_diff(n), s);
        }
    }
    best.1
}

/// The outline pixels of the layout at spacing s (each pixel once).
pub(super) fn outlines_pixels(layout: &Layout, s: usize) -> Vec<Pixel> {
    let mut out = Vec::new();
    for (x, y) in layout {
        let (x0, x1, y0, y1) = (s * x[0], s * x[1], s * y[0], s * y[1]);
        for xx in x0..=x1 {
            out.push(Pixel::new(xx as i32, y0 as i32));
            out.push(Pixel::new(xx as i32, y1 as i32));
        }
        for yy in y0 + 1..y1 {
            out.push(Pixel::new(x0 as i32, yy as i32));
            out.push(Pixel::new(x1 as i32, yy as i32));
        }
    }
    out.sort_by_key(|p| (p.y, p.x));
    out.dedup();
    out
}
