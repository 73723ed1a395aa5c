//! `thin-eulerian`: large thin regions whose pixels all have even degree (the precondition of
//! `thin-euler`), in linear time.
//!
//! # What it guarantees
//! 4-connected, thin (no 2 × 2 block of pixels), every pixel of degree 2 or 4, any number of
//! holes, and N within [`slack`]`(n)` = n/50 + 32 pixels of the requested n (not exact: the
//! size is that of a random component); checked again by the family's promise.
//!
//! # How
//! A coarse lattice of a × b nodes whose columns (rows) are 2, 3 or 4 pixels apart at random
//! (corridors of 1 to 3 pixels between nodes: one-pixel links and longer ones). R random
//! rectangles of lattice faces, 1 to L faces a side (L from `compactness`), are added modulo 2
//! (a two-dimensional difference array, O(ab + R)); the region is the lattice boundary of that
//! face set: a lattice edge is drawn, as its corridor pixels and its two end nodes, when the
//! faces on its two sides differ. Around a node the faces change an even number of times, so
//! every node has degree 0, 2 or 4 (4 where rectangles cross, or at a saddle of two diagonal
//! faces); corridor pixels have degree 2, because rows and columns between lattice lines hold
//! only corridors across them. No 2 × 2 block is full: two adjacent pixel columns are never
//! both lattice columns, and a column between lattice columns has pixels only on lattice rows,
//! which are at least 2 apart. The largest connected component (by pixels) is kept, which
//! changes no degree. Its size is measured and the lattice rescaled by n/N until N is within
//! the slack (two or three rounds at large n: the share of the largest component is stable).
//! The result is the union of rectangle outlines with stairs where they overlap, crossings,
//! saddles and holes, at the scale the `outlines` family cannot reach (its K ≤ 40 outlines).
//! Time and memory O(N).

use super::rng::{Rng, below, between};
use crate::region::Pixel;

/// How far from n the pixel count may lie.
pub(super) fn slack(n: usize) -> usize {
    n / 50 + 32
}

/// Rounds of rescaling before the attempt gives up.
const ROUNDS: usize = 8;

/// Rectangles per lattice face, times the mean rectangle area: about 3 rectangles cover a
/// face. Below about 1 the outlines fall apart into many components (the largest one's share
/// then jumps from draw to draw); at 3 the largest component holds most of the outlines for
/// every side limit, so one rescaling round hits n.
const COVER: f64 = 3.0;

/// A built lattice: node coordinates, the face set, and the kept component.
struct Lattice {
    xs: Vec<usize>,
    ys: Vec<usize>,
    /// Face (i, j) in the set, for i < a − 1, j < b − 1.
    face: Vec<bool>,
}

impl Lattice {
    fn a(&self) -> usize {
        self.xs.len()
    }
    fn b(&self) -> usize {
        self.ys.len()
    }
    /// Whether face (i, j) is in the set; faces outside the lattice are not.
    fn f(&self, i: isize, j: isize) -> bool {
        let (fa, fb) = (self.a() as isize - 1, self.b() as isize - 1);
        i >= 0 && j >= 0 && i < fa && j < fb && self.face[(j * fa + i) as usize]
    }
    /// The horizontal edge from node (i, j) to (i + 1, j) is drawn.
    fn east(&self, i: usize, j: usize) -> bool {
        let (i, j) = (i as isize, j as isize);
        i + 1 < self.a() as isize && self.f(i, j - 1) != self.f(i, j)
    }
    /// The vertical edge from node (i, j) to (i, j + 1) is drawn.
    fn north(&self, i: usize, j: usize) -> bool {
        let (i, j) = (i as isize, j as isize);
        j + 1 < self.b() as isize && self.f(i - 1, j) != self.f(i, j)
    }
}

/// Gaps of 2, 3 or 4 pixels between consecutive lattice lines, from 0.
fn lines(count: usize, rng: &mut Rng) -> Vec<usize> {
    let mut at = 0;
    (0..count)
        .map(|_| {
            let here = at;
            at += between(rng, 2, 4);
            here
        })
        .collect()
}

fn build(a: usize, b: usize, side: usize, rng: &mut Rng) -> Lattice {
    let (xs, ys) = (lines(a, rng), lines(b, rng));
    let (fa, fb) = (a - 1, b - 1);
    // toggles[(j, i)] over (fa + 1) × (fb + 1): the corners of each rectangle.
    let stride = fa + 1;
    let mut toggles = vec![false; stride * (fb + 1)];
    let lo = side.div_ceil(2);
    let mean_area = ((side + lo) as f64 / 2.0).powi(2);
    let count = ((fa * fb) as f64 * COVER / mean_area).ceil() as usize;
    for _ in 0..count {
        let (w, h) = (between(rng, lo, side), between(rng, lo, side));
        let (x0, y0) = (below(rng, fa), below(rng, fb));
        let (x1, y1) = ((x0 + w).min(fa), (y0 + h).min(fb));
        for (x, y) in [(x0, y0), (x1, y0), (x0, y1), (x1, y1)] {
            let t = &mut toggles[y * stride + x];
            *t = !*t;
        }
    }
    // Prefix sums modulo 2 in both directions turn the corner toggles into the face set.
    for y in 0..=fb {
        for x in 1..=fa {
            toggles[y * stride + x] ^= toggles[y * stride + x - 1];
        }
    }
    for y in 1..=fb {
        for x in 0..=fa {
            toggles[y * stride + x] ^= toggles[(y - 1) * stride + x];
        }
    }
    let mut face = vec![false; fa * fb];
    for y in 0..fb {
        face[y * fa..(y + 1) * fa].copy_from_slice(&toggles[y * stride..y * stride + fa]);
    }
    Lattice { xs, ys, face }
}

/// The nodes of the largest component (by pixels) and its pixel count.
fn largest(l: &Lattice) -> (Vec<u32>, usize) {
    let (a, b) = (l.a(), l.b());
    let mut label = vec![0u32; a * b];
    let mut stack = Vec::new();
    let (mut best, mut best_pixels, mut next) = (0u32, 0usize, 0u32);
    for s in 0..a * b {
        let (i, j) = (s % a, s / a);
        let lonely = !l.east(i, j)
            && !l.north(i, j)
            && (i == 0 || !l.east(i - 1, j))
            && (j == 0 || !l.north(i, j - 1));
        if label[s] != 0 || lonely {
            continue;
        }
        next += 1;
        label[s] = next;
        stack.push(s);
        let mut pixels = 0;
        while let Some(u) = stack.pop() {
            let (i, j) = (u % a, u / a);
            pixels += 1;
            // Each edge's corridor is counted at its west or south node.
            if l.east(i, j) {
                pixels += l.xs[i + 1] - l.xs[i] - 1;
            }
            if l.north(i, j) {
                pixels += l.ys[j + 1] - l.ys[j] - 1;
            }
            let mut visit = |v: usize| {
                if label[v] == 0 {
                    label[v] = next;
                    stack.push(v);
                }
            };
            if l.east(i, j) {
                visit(u + 1);
            }
            if l.north(i, j) {
                visit(u + a);
            }
            if i > 0 && l.east(i - 1, j) {
                visit(u - 1);
            }
            if j > 0 && l.north(i, j - 1) {
                visit(u - a);
            }
        }
        if pixels > best_pixels {
            (best, best_pixels) = (next, pixels);
        }
    }
    let nodes = (0..a * b)
        .filter(|&u| label[u] == best && best != 0)
        .map(|u| u as u32)
        .collect();
    (nodes, best_pixels)
}

/// The rectangle side limit L (in faces) for a compactness: 4 (a dense mesh of small outlines
/// and saddles) to 16 (long outlines crossing); sides are drawn from ⌈L/2⌉ to L, since a
/// smaller rectangle is mostly an isolated little loop.
fn max_side(compactness: f64) -> usize {
    4 + (compactness * 12.0).round() as usize
}

/// A thin region with every degree even and within [`slack`]`(n)` of n pixels (module docs);
/// `None` when the rescaling does not settle within [`ROUNDS`].
pub(super) fn thin_eulerian_pixels(
    n: usize,
    compactness: f64,
    rng: &mut Rng,
) -> Option<Vec<Pixel>> {
    let side = max_side(compactness);
    let aspect = between(rng, 100, 200) as f64 / 100.0;
    // Pixels of the kept component per lattice node; a first guess, then measured.
    let mut per_node = 1.5;
    for _ in 0..ROUNDS {
        let nodes = (n as f64 / per_node).max(9.0);
        let a = ((nodes * aspect).sqrt().round() as usize).max(3);
        let b = ((nodes / a as f64).round() as usize).max(3);
        let l = build(a, b, side, rng);
        let (kept, count) = largest(&l);
        if count.abs_diff(n) <= slack(n) {
            return Some(pixels(&l, &kept, count));
        }
        if count == 0 {
            continue;
        }
        // Clamped, so that one unlucky draw cannot ask for a huge lattice.
        per_node = (count as f64 / (a * b) as f64).clamp(0.5, 4.0);
    }
    None
}

fn pixels(l: &Lattice, kept: &[u32], count: usize) -> Vec<Pixel> {
    let a = l.a();
    let mut out = Vec::with_capacity(count);
    for &u in kept {
        let (i, j) = (u as usize % a, u as usize / a);
        let (x, y) = (l.xs[i], l.ys[j]);
        out.push(Pixel::new(x as i32, y as i32));
        if l.east(i, j) {
            out.extend((x + 1..l.xs[i + 1]).map(|xx| Pixel::new(xx as i32, y as i32)));
        }
        if l.north(i, j) {
            out.extend((y + 1..l.ys[j + 1]).map(|yy| Pixel::new(x as i32, yy as i32)));
        }
    }
    out
}

/// The fallback: the outline of a near-square rectangle with n or n + 1 pixels (an outline
/// has an even number, 2(w + h) − 4, of pixels); needs n ≥ 7.
pub(super) fn ring_outline_pixels(n: usize) -> Vec<Pixel> {
    let half = n.div_ceil(2) + 2;
    let w = (half / 2).max(3);
    let h = (half - w).max(3);
    let mut out = Vec::with_capacity(2 * (w + h));
    for x in 0..w {
        out.push(Pixel::new(x as i32, 0));
        out.push(Pixel::new(x as i32, h as i32 - 1));
    }
    for y in 1..h - 1 {
        out.push(Pixel::new(0, y as i32));
        out.push(Pixel::new(w as i32 - 1, y as i32));
    }
    out
}
