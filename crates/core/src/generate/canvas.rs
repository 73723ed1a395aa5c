//! The occupancy canvas on which the random families draw, grow and erode their shapes.

use crate::region::Pixel;
use crate::topology;

use super::rng::{Rng, between, chance};

/// Pixels the style drawings keep from the canvas edge (room for the 2 × 2 dilation and the
/// later growth).
pub(super) const STYLE_MARGIN: usize = 6;

/// Pixels every occupied cell keeps from the canvas edge, so that 5 × 5 neighbourhoods of
/// pixels and of their 4-neighbours never leave the canvas.
pub(super) const ADJ_MARGIN: usize = 3;

/// A mutable occupancy bitmap with a fixed frame of empty cells.
pub(super) struct Canvas {
    pub(super) w: usize,
    pub(super) h: usize,
    pub(super) occ: Vec<bool>,
    pub(super) count: usize,
    /// While drawing a `no_cut` shape S: how many pixels of S cover each cell of S ⊕ 2 × 2.
    pub(super) cover: Vec<u8>,
    pub(super) dcount: usize,
    /// Hole labels (1-based) while carving holes; empty otherwise.
    pub(super) hole: Vec<u32>,
    /// Index offsets of the 8 neighbours in the order of `topology::ring`.
    pub(super) ring: [isize; 8],
}

impl Canvas {
    pub(super) fn new(w: usize, h: usize) -> Canvas {
        let wi = w as isize;
        Canvas {
            w,
            h,
            occ: vec![false; w * h],
            count: 0,
            cover: Vec::new(),
            dcount: 0,
            hole: Vec::new(),
            ring: [1, 1 + wi, wi, wi - 1, -1, -1 - wi, -wi, 1 - wi],
        }
    }

    /// A canvas with room for a shape of `target` pixels spread over `factor` times its area,
    /// of random aspect ratio between 1 and 2.5.
    pub(super) fn for_target(target: usize, factor: usize, rng: &mut Rng) -> Canvas {
        let inner = target * factor + 64;
        let aspect = between(rng, 100, 250);
        let mut a = (inner * aspect / 100).isqrt() + 1;
        let mut b = inner / a + 1;
        if chance(rng, 0.5) {
            std::mem::swap(&mut a, &mut b);
        }
        Canvas::new(a + 2 * STYLE_MARGIN + 2, b + 2 * STYLE_MARGIN + 2)
    }

    pub(super) fn area(&self) -> usize {
        self.w * self.h
    }

    pub(super) fn idx(&self, x: usize, y: usize) -> usize {
        y * self.w + x
    }

    pub(super) fn nb(&self, k: usize, i: usize) -> usize {
        (k as isize + self.ring[i]) as usize
    }

    pub(super) fn in_zone(&self, k: usize, margin: usize) -> bool {
        let (x, y) = (k % self.w, k / self.w);
        x >= margin && y >= margin && x + margin < self.w && y + margin < self.h
    }

    pub(super) fn zone_xy(&self, x: i64, y: i64, margin: usize) -> bool {
        let m = margin as i64;
        x >= m && y >= m && x + m < self.w as i64 && y + m < self.h as i64
    }

    /// The size that drawing aims at: |S ⊕ 2 × 2| while dilating, else the pixel count.
    pub(super) fn size(&self) -> usize {
        if self.cover.is_empty() {
            self.count
        } else {
            self.dcount
        }
    }

    pub(super) fn set(&mut self, k: usize, v: bool) {
        if self.occ[k] == v {
            return;
        }
        self.occ[k] = v;
        if v {
            self.count += 1;
            if !self.hole.is_empty() {
                self.hole[k] = 0;
            }
        } else {
            self.count -= 1;
        }
        if !self.cover.is_empty() {
            for c in [k, k + 1, k + self.w, k + self.w + 1] {
                if v {
                    self.dcount += usize::from(self.cover[c] == 0);
                    self.cover[c] += 1;
                } else {
                    self.cover[c] -= 1;
                    self.dcount -= usize::from(self.cover[c] == 0);
                }
            }
        }
    }

    pub(super) fn ring_occ(&self, k: usize) -> [bool; 8] {
        std::array::from_fn(|i| self.occ[self.nb(k, i)])
    }

    /// Yokoi's 4-connectivity number of cell `k` (occupied or not).
    pub(super) fn yokoi(&self, k: usize) -> u32 {
        topology::connectivity_number(self.ring_occ(k))
    }

    /// Number of occupied 4-neighbours.
    pub(super) fn nb4(&self, k: usize) -> usize {
        (0..4).filter(|&i| self.occ[self.nb(k, 2 * i)]).count()
    }

    /// Whether the (2r + 1) × (2r + 1) square around `k` is fully occupied.
    pub(super) fn full(&self, k: usize, r: usize) -> bool {
        let (x, y) = (k % self.w, k / self.w);
        (y - r..=y + r).all(|yy| (x - r..=x + r).all(|xx| self.occ[self.idx(xx, yy)]))
    }

    pub(super) fn begin_dilation(&mut self) {
        self.cover = vec![0; self.area()];
        self.dcount = 0;
    }

    /// Replaces the drawn shape S by S ⊕ 2 × 2.
    pub(super) fn finish_dilation(&mut self) {
        for (o, &c) in self.occ.iter_mut().zip(&self.cover) {
            *o = c > 0;
        }
        self.count = self.dcount;
        self.cover = Vec::new();
    }

    /// Removes every 4-component but the largest (the first in scan order on ties).
    pub(super) fn keep_largest_component(&mut self) {
        let mut label = vec![0u32; self.area()];
        let mut stack = Vec::new();
        let (mut best, mut best_size, mut next) = (0u32, 0usize, 0u32);
        for s in 0..self.area() {
            if !self.occ[s] || label[s] != 0 {
                continue;
            }
            next += 1;
            label[s] = next;
            stack.push(s);
            let mut size = 0;
            while let Some(k) = stack.pop() {
                size += 1;
                for i in 0..4 {
                    let q = self.nb(k, 2 * i);
                    if self.occ[q] && label[q] == 0 {
                        label[q] = next;
                        stack.push(q);
                    }
                }
            }
            if size > best_size {
                (best, best_size) = (next, size);
            }
        }
        for (k, &l) in label.iter().enumerate() {
            if self.occ[k] && l != best {
                self.set(k, false);
            }
        }
    }

    /// The empty cells connected to the canvas frame (8-connected): the outside.
    pub(super) fn outside(&self) -> Vec<bool> {
        let mut outside = vec![false; self.area()];
        let mut stack = vec![0usize];
        outside[0] = true;
        let (w, h) = (self.w as i64, self.h as i64);
        while let Some(k) = stack.pop() {
            let (x, y) = ((k % self.w) as i64, (k / self.w) as i64);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (nx, ny) = (x + dx, y + dy);
                    if nx < 0 || ny < 0 || nx >= w || ny >= h {
                        continue;
                    }
                    let q = self.idx(nx as usize, ny as usize);
                    if !self.occ[q] && !outside[q] {
                        outside[q] = true;
                        stack.push(q);
                    }
                }
            }
        }
        outside
    }

    /// Fills every hole (bounded 8-component of the empty cells), or with `was_outside` only
    /// the pockets closed since that picture of the outside.
    pub(super) fn fill_holes(&mut self, was_outside: Option<&[bool]>) {
        let outside = self.outside();
        for k in 0..self.area() {
            if !self.occ[k] && !outside[k] && was_outside.is_none_or(|o| o[k]) {
                self.set(k, true);
            }
        }
    }

    pub(super) fn pixels(&self) -> Vec<Pixel> {
        (0..self.area())
            .filter(|&k| self.occ[k])
            .map(|k| Pixel::new((k % self.w) as i32, (k / self.w) as i32))
            .collect()
    }
}
