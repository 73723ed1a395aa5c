//! `boundary-rooms`: large regions in which every pixel is a boundary pixel (the precondition
//! of `boundary-cc`), in linear time.
//!
//! # What it guarantees
//! Exactly N pixels, 4-connected, every pixel with an empty 4-neighbour
//! ([`topology::is_boundary`](crate::topology::is_boundary)), any number of holes; checked
//! again by the promise of the family (`checks::verify`).
//!
//! # How
//! Rooms (rectangles of 1 to m pixels a side, m from `compactness`) sit in the cells of a
//! coarse lattice of pitch m + 2 and are joined along a random spanning tree of the lattice
//! (depth-first or Prim-like steps, weighted by `compactness`) by corridors of width 1 or 2,
//! straight or L-shaped; some steps also join the new room to a second neighbour, which closes
//! a loop around a hole. Each room and corridor is drawn and then made boundary-only at once,
//! so the pixel count is known while the tree grows and the growth stops at N: every pixel of
//! the new piece and its 4-neighbours that has four neighbours loses, in random order, itself
//! (a pinhole or a notch) or one of its neighbours (stairs, one-pixel links), the first of
//! these whose 8-ring is one run, so that connectivity is kept (the rule of `boundary`). A
//! pixel none of the five fits is removed if its neighbours stay connected within a small
//! window (a hole); the few that fail that too are removed at the end, the largest component
//! is kept, and `boundary::reach_size` grows or erodes to exactly N. Every step touches a
//! bounded neighbourhood, so the whole is O(N) time and O(N) memory (the canvas has about
//! 10 cells per pixel).

use super::boundary::{reach_size, ring_runs};
use super::canvas::{ADJ_MARGIN, Canvas};
use super::rng::{Rng, below, between, chance, shuffle};
use crate::region::Dir;

/// Half the side of the window in which a stuck pixel's neighbours must stay connected.
const WINDOW: usize = 6;

/// A room: its lower-left corner and size, in pixels.
#[derive(Clone, Copy, Default)]
struct Room {
    x: usize,
    y: usize,
    w: usize,
    h: usize,
}

impl Room {
    fn cx(&self) -> usize {
        self.x + self.w / 2
    }
    fn cy(&self) -> usize {
        self.y + self.h / 2
    }
}

/// The drawing state: the canvas, the pixels still to make boundary-only, and the rule's
/// parameters.
struct Drawing {
    c: Canvas,
    /// Pixels drawn since the last call of `settle`.
    fresh: Vec<u32>,
    /// Pixels with four neighbours that no local rule could fix.
    stuck: Vec<u32>,
    /// The probability that a pixel with four neighbours removes itself first.
    own: f64,
}

impl Drawing {
    fn fill(&mut self, x0: usize, y0: usize, x1: usize, y1: usize) {
        for y in y0..=y1 {
            for x in x0..=x1 {
                let k = self.c.idx(x, y);
                if !self.c.occ[k] {
                    self.c.set(k, true);
                    self.fresh.push(k as u32);
                }
            }
        }
    }

    /// Makes every fresh pixel and its 4-neighbours a boundary pixel (the module's rule).
    fn settle(&mut self, rng: &mut Rng) {
        let c = &self.c;
        let mut todo: Vec<u32> = Vec::with_capacity(5 * self.fresh.len());
        for &k in &self.fresh {
            todo.push(k);
            todo.extend((0..4).map(|i| c.nb(k as usize, 2 * i) as u32));
        }
        self.fresh.clear();
        // Duplicates are harmless: a pixel already fixed is skipped.
        shuffle(&mut todo, rng);
        for k in todo {
            let k = k as usize;
            if !self.c.occ[k] || self.c.nb4(k) < 4 {
                continue;
            }
            let c = &self.c;
            let mut options = [k, c.nb(k, 0), c.nb(k, 2), c.nb(k, 4), c.nb(k, 6)];
            shuffle(&mut options[1..], rng);
            if !chance(rng, self.own) {
                options.rotate_left(1);
            }
            let pick = options
                .iter()
                .copied()
                .find(|&r| c.in_zone(r, ADJ_MARGIN) && ring_runs(c.ring_occ(r)) <= 1);
            match pick {
                Some(r) => self.c.set(r, false),
                None if self.connected_nearby(k) => self.c.set(k, false),
                None => self.stuck.push(k as u32),
            }
        }
    }

    /// Whether the 4-neighbours of `k` stay connected to one another inside the window of
    /// half-side [`WINDOW`] around `k` without `k`: then removing `k` keeps the region
    /// connected (a path in the window is a path in the region).
    fn connected_nearby(&self, k: usize) -> bool {
        let c = &self.c;
        let (kx, ky) = (k % c.w, k / c.w);
        let side = 2 * WINDOW + 1;
        let local = |q: usize| -> Option<usize> {
            let dx = (q % c.w + WINDOW).checked_sub(kx)?;
            let dy = (q / c.w + WINDOW).checked_sub(ky)?;
            (dx < side && dy < side).then_some(dy * side + dx)
        };
        let mut seen = [false; (2 * WINDOW + 1) * (2 * WINDOW + 1)];
        seen[WINDOW * side + WINDOW] = true;
        let start = c.nb(k, 0);
        seen[local(start).expect("a neighbour lies in the window")] = true;
        let mut stack = vec![start];
        while let Some(q) = stack.pop() {
            for i in 0..4 {
                let r = c.nb(q, 2 * i);
                if let Some(l) = local(r)
                    && c.occ[r]
                    && !seen[l]
                {
                    seen[l] = true;
                    stack.push(r);
                }
            }
        }
        (0..4).all(|i| local(c.nb(k, 2 * i)).is_some_and(|l| seen[l]))
    }
}

/// The room side limit m for a compactness: 2 (ragged) to 7 (compact).
fn max_room_side(compactness: f64) -> usize {
    2 + (compactness * 5.0).round() as usize
}

/// A connected canvas of exactly `n` pixels, each a boundary pixel (module docs); `None` when
/// the coarse lattice fills up first or the final size cannot be reached.
pub(super) fn boundary_rooms_canvas(n: usize, compactness: f64, rng: &mut Rng) -> Option<Canvas> {
    let m = max_room_side(compactness);
    let pitch = m + 2;
    let own = between(rng, 20, 80) as f64 / 100.0;
    // Pixels a room and its corridor keep after the rule, at the least (the smallest rooms
    // and one-pixel corridors); the lattice holds twice the rooms that need.
    let per_room = (m * m / 6).max(2);
    let cap = 2 * n.div_ceil(per_room) + 16;
    let aspect = between(rng, 100, 200);
    let a = (cap * aspect / 100).isqrt().max(2);
    let b = cap.div_ceil(a).max(2);
    let margin = ADJ_MARGIN + 2;
    let canvas = Canvas::new(a * pitch + 2 * margin + 2, b * pitch + 2 * margin + 2);
    let mut d = Drawing {
        c: canvas,
        fresh: Vec::new(),
        stuck: Vec::new(),
        own,
    };
    let mut rooms = vec![Room::default(); a * b];
    let mut in_tree = vec![false; a * b];
    let nb = |u: usize, dir: Dir| -> Option<usize> {
        let (x, y) = (u % a, u / a);
        match dir {
            Dir::E if x + 1 < a => Some(u + 1),
            Dir::W if x > 0 => Some(u - 1),
            Dir::N if y + 1 < b => Some(u + a),
            Dir::S if y > 0 => Some(u - a),
            _ => None,
        }
    };
    let place = |u: usize, d: &mut Drawing, rng: &mut Rng| -> Room {
        let (w, h) = (between(rng, 1, m), between(rng, 1, m));
        let x = margin + (u % a) * pitch + below(rng, pitch - w);
        let y = margin + (u / a) * pitch + below(rng, pitch - h);
        let r = Room { x, y, w, h };
        d.fill(x, y, x + w - 1, y + h - 1);
        r
    };
    let root = (b / 2) * a + a / 2;
    rooms[root] = place(root, &mut d, rng);
    in_tree[root] = true;
    d.settle(rng);
    let (mut active, mut stack) = (vec![root], vec![root]);
    // Loops (holes) are rarer in compact shapes, whose rooms already hold pinholes.
    let p_loop = 0.25 - 0.15 * compactness;
    let mut free = Vec::with_capacity(4);
    while d.c.count < n {
        // Prim-like (a random tree room) with probability `compactness`, else depth-first
        // from the newest room: long snakes of rooms.
        let mut prim = chance(rng, compactness);
        let (u, v) = loop {
            prim |= stack.is_empty();
            if prim && active.is_empty() {
                return None;
            }
            let list = if prim { &mut active } else { &mut stack };
            let idx = if prim {
                below(rng, list.len())
            } else {
                list.len() - 1
            };
            let u = list[idx];
            free.clear();
            free.extend(Dir::ALL.into_iter().filter_map(|dir| nb(u, dir)));
            free.retain(|&v| !in_tree[v]);
            if free.is_empty() {
                list.swap_remove(idx);
                continue;
            }
            break (u, free[below(rng, free.len())]);
        };
        in_tree[v] = true;
        rooms[v] = place(v, &mut d, rng);
        corridor(&mut d, rooms[u], rooms[v], rng);
        if chance(rng, p_loop) {
            let others: Vec<usize> = Dir::ALL
                .into_iter()
                .filter_map(|dir| nb(v, dir))
                .filter(|&w| w != u && in_tree[w])
                .collect();
            if !others.is_empty() {
                let w = others[below(rng, others.len())];
                corridor(&mut d, rooms[w], rooms[v], rng);
            }
        }
        d.settle(rng);
        active.push(v);
        stack.push(v);
    }
    let mut c = d.c;
    let mut removed = false;
    for k in d.stuck {
        let k = k as usize;
        if c.occ[k] && c.nb4(k) == 4 {
            c.set(k, false);
            removed = true;
        }
    }
    // A stuck removal may have cut a piece off (rare: its neighbours were not connected
    // nearby); the largest component stays and the size is restored below.
    if removed {
        c.keep_largest_component();
    }
    reach_size(&mut c, n, rng).then_some(c)
}

/// Joins rooms `p` and `q` (in adjacent lattice cells) by a corridor of width 1 or 2: along
/// the row (column) of a random pixel of `p` to the centre column (row) of `q`, then
/// straight into `q`.
fn corridor(d: &mut Drawing, p: Room, q: Room, rng: &mut Rng) {
    let wide = usize::from(chance(rng, 0.3));
    let horizontal = p.y.abs_diff(q.y) < p.x.abs_diff(q.x);
    if horizontal {
        let y = p.y + below(rng, p.h);
        let (x0, x1) = (p.cx().min(q.cx()), p.cx().max(q.cx()));
        d.fill(x0, y, x1, y + wide);
        let (y0, y1) = (y.min(q.cy()), y.max(q.cy()));
        d.fill(q.cx(), y0, q.cx() + wide, y1);
    } else {
        let x = p.x + below(rng, p.w);
        let (y0, y1) = (p.cy().min(q.cy()), p.cy().max(q.cy()));
        d.fill(x, y0, x + wide, y1);
        let (x0, x1) = (x.min(q.cx()), x.max(q.cx()));
        d.fill(x0, q.cy(), x1, q.cy() + wide);
    }
}
