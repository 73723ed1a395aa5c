//! Shape styles of the random families: blob, rectangles, snake corridors and rooms; and the
//! two erosion styles of `eroded`, dense and sparse.

use super::canvas::{Canvas, STYLE_MARGIN};
use super::growth::{Frontier, Move, bucket_weights, evolve, refresh};
use super::rng::{Rng, below, between, chance, unit};
use crate::error::Error;
use crate::error::Result;
use crate::region::Dir;
use std::fmt;
use std::str::FromStr;

/// The shape style of the random families (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Style {
    /// One of the other styles, drawn per instance from the seed.
    Mixed,
    Blob,
    Rectangles,
    Snake,
    Rooms,
    /// `eroded` only: erosion mostly from outside, few holes.
    Dense,
    /// `eroded` only: a rough boundary and many small holes.
    Sparse,
}

impl Style {
    /// The styles of the shape families (`random-simple`, `random-holed`, `lawn-scattered`,
    /// `boundary`, `pinholes`).
    pub const ALL: [Style; 5] = [
        Style::Mixed,
        Style::Blob,
        Style::Rectangles,
        Style::Snake,
        Style::Rooms,
    ];
    /// The styles `Mixed` draws from.
    pub(super) const CONCRETE: [Style; 4] =
        [Style::Blob, Style::Rectangles, Style::Snake, Style::Rooms];
    /// The styles of `eroded` (its `mixed` draws one of them).
    pub const ERODED: [Style; 2] = [Style::Dense, Style::Sparse];
    /// Every style name `--style` and configs accept.
    pub const NAMES: [&'static str; 7] = [
        "mixed",
        "blob",
        "rectangles",
        "snake",
        "rooms",
        "dense",
        "sparse",
    ];

    pub fn name(self) -> &'static str {
        match self {
            Style::Mixed => "mixed",
            Style::Blob => "blob",
            Style::Rectangles => "rectangles",
            Style::Snake => "snake",
            Style::Rooms => "rooms",
            Style::Dense => "dense",
            Style::Sparse => "sparse",
        }
    }
}

impl fmt::Display for Style {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Style {
    type Err = Error;

    fn from_str(s: &str) -> Result<Style> {
        Style::ALL
            .into_iter()
            .chain(Style::ERODED)
            .find(|st| st.name() == s)
            .ok_or_else(|| {
                Error::invalid(format!(
                    "unknown style {s:?}: expected one of {}",
                    Style::NAMES.join(", ")
                ))
            })
    }
}

pub(super) struct ShapeOpts {
    pub(super) style: Style,
    pub(super) compactness: f64,
    pub(super) no_cut: bool,
}

pub(super) fn center(c: &Canvas, rng: &mut Rng) -> (usize, usize) {
    let jx = c.w / 8;
    let jy = c.h / 8;
    (
        c.w / 2 - jx + between(rng, 0, 2 * jx),
        c.h / 2 - jy + between(rng, 0, 2 * jy),
    )
}

pub(super) fn draw_blob(
    c: &mut Canvas,
    f: &mut Frontier,
    target: usize,
    compactness: f64,
    rng: &mut Rng,
) {
    let (x, y) = center(c, rng);
    let k = c.idx(x, y);
    c.set(k, true);
    f.clear();
    refresh(c, f, k, 1, Move::Grow, STYLE_MARGIN);
    let weights = bucket_weights(compactness);
    evolve(c, f, Move::Grow, &weights, false, STYLE_MARGIN, rng, |c| {
        c.size() >= target
    });
}

/// An inclusive rectangle of cells (empty when x0 > x1).
#[derive(Clone, Copy, Debug)]
pub(super) struct Rect {
    pub(super) x0: i64,
    pub(super) y0: i64,
    pub(super) x1: i64,
    pub(super) y1: i64,
}

impl Rect {
    pub(super) const EMPTY: Rect = Rect {
        x0: 0,
        y0: 0,
        x1: -1,
        y1: -1,
    };

    pub(super) fn is_empty(&self) -> bool {
        self.x0 > self.x1 || self.y0 > self.y1
    }

    pub(super) fn union(self, o: Rect) -> Rect {
        if self.is_empty() {
            return o;
        }
        if o.is_empty() {
            return self;
        }
        Rect {
            x0: self.x0.min(o.x0),
            y0: self.y0.min(o.y0),
            x1: self.x1.max(o.x1),
            y1: self.y1.max(o.y1),
        }
    }

    pub(super) fn contains(&self, x: i64, y: i64) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    pub(super) fn shift(self, d: Dir) -> Rect {
        let (dx, dy) = d.delta();
        let (dx, dy) = (i64::from(dx), i64::from(dy));
        Rect {
            x0: self.x0 + dx,
            y0: self.y0 + dy,
            x1: self.x1 + dx,
            y1: self.y1 + dy,
        }
    }

    /// The row or column of cells just beyond the rectangle in direction `d`.
    pub(super) fn front(self, d: Dir) -> Rect {
        match d {
            Dir::E => Rect {
                x0: self.x1 + 1,
                x1: self.x1 + 1,
                ..self
            },
            Dir::W => Rect {
                x0: self.x0 - 1,
                x1: self.x0 - 1,
                ..self
            },
            Dir::N => Rect {
                y0: self.y1 + 1,
                y1: self.y1 + 1,
                ..self
            },
            Dir::S => Rect {
                y0: self.y0 - 1,
                y1: self.y0 - 1,
                ..self
            },
        }
    }
}

/// How far (Chebyshev) new corridor cells keep from other parts of the drawing: 1, or 2
/// while dilating, so that the 2 × 2 dilation does not close the gaps between corridors.
pub(super) fn clearance(c: &Canvas) -> i64 {
    if c.cover.is_empty() { 1 } else { 2 }
}

/// Whether every cell of `new` is empty and inside the drawing zone, and every occupied cell
/// within the clearance of it lies in `allowed`.
pub(super) fn clear_for(c: &Canvas, new: Rect, allowed: Rect) -> bool {
    let r = clearance(c);
    for y in new.y0..=new.y1 {
        for x in new.x0..=new.x1 {
            if !c.zone_xy(x, y, STYLE_MARGIN) || c.occ[c.idx(x as usize, y as usize)] {
                return false;
            }
            for (qx, qy) in (y - r..=y + r).flat_map(|qy| (x - r..=x + r).map(move |qx| (qx, qy))) {
                if c.occ[c.idx(qx as usize, qy as usize)] && !allowed.contains(qx, qy) {
                    return false;
                }
            }
        }
    }
    true
}

/// Paints `r` (clipped to the drawing zone) row by row outwards from row `from_y`, which
/// touches what the rectangle attaches to, stopping once the canvas reaches `target`: every
/// row touches the rows painted before it, so a partly painted rectangle stays attached.
/// Records the new pixels.
pub(super) fn paint(c: &mut Canvas, r: Rect, from_y: i64, target: usize, painted: &mut Vec<u32>) {
    let m = STYLE_MARGIN as i64;
    let (x0, x1) = (r.x0.max(m), r.x1.min(c.w as i64 - 1 - m));
    let (y0, y1) = (r.y0.max(m), r.y1.min(c.h as i64 - 1 - m));
    if x0 > x1 || y0 > y1 {
        return;
    }
    let from_y = from_y.clamp(y0, y1);
    let span = (y1 - from_y).max(from_y - y0);
    let rows = (0..=span).flat_map(|d| [from_y + d, from_y - d - 1]);
    for y in rows.filter(|&y| (y0..=y1).contains(&y)) {
        if c.size() >= target {
            return;
        }
        for x in x0..=x1 {
            let k = c.idx(x as usize, y as usize);
            if !c.occ[k] {
                c.set(k, true);
                painted.push(k as u32);
            }
        }
    }
}

/// A rectangle of about `area` cells whose aspect ratio is √2^e, e ∈ −6..=6 (up to 8:1).
pub(super) fn random_dims(area: usize, rng: &mut Rng) -> (i64, i64) {
    let e = between(rng, 0, 12) as i32 - 6;
    let mut ratio = 1.0;
    for _ in 0..e.unsigned_abs() {
        ratio *= std::f64::consts::SQRT_2;
    }
    if e < 0 {
        ratio = 1.0 / ratio;
    }
    let w = ((area as f64 * ratio).sqrt() as i64).max(1);
    let h = (area as i64 / w).max(1);
    (w, h)
}

pub(super) fn draw_rectangles(c: &mut Canvas, target: usize, rng: &mut Rng) {
    let mut painted = Vec::new();
    let pieces = between(rng, 3, 40);
    let mean = (target / pieces).max(1);
    let bar_p = unit(rng) * 0.4;
    let (x, y) = center(c, rng);
    let (w, h) = random_dims(mean, rng);
    let first = Rect {
        x0: x as i64,
        y0: y as i64,
        x1: x as i64 + w - 1,
        y1: y as i64 + h - 1,
    };
    paint(c, first, first.y0, target, &mut painted);
    if painted.is_empty() {
        c.set(c.idx(x, y), true);
        painted.push(c.idx(x, y) as u32);
    }
    let mut stalls = 0;
    while c.size() < target && stalls < 1000 {
        let before = c.size();
        let k = painted[below(rng, painted.len())] as usize;
        let (ax, ay) = ((k % c.w) as i64, (k / c.w) as i64);
        let (mut w, mut h) = if chance(rng, bar_p) {
            // A bar of width 1 or 2: a narrow part.
            let long = between(rng, 3, 3 + 2 * mean.isqrt()) as i64;
            (between(rng, 1, 2) as i64, long)
        } else {
            let area = ((mean as f64) * (0.2 + 1.8 * unit(rng))) as usize;
            random_dims(area.max(1), rng)
        };
        if chance(rng, 0.5) {
            std::mem::swap(&mut w, &mut h);
        }
        let x0 = ax - below(rng, w as usize) as i64;
        let y0 = ay - below(rng, h as usize) as i64;
        paint(
            c,
            Rect {
                x0,
                y0,
                x1: x0 + w - 1,
                y1: y0 + h - 1,
            },
            ay,
            target,
            &mut painted,
        );
        stalls = if c.size() == before { stalls + 1 } else { 0 };
    }
}

/// The head of a corridor being drawn: a w × w square moving in direction `d`. `trail`
/// holds its last positions (or the wall it starts from), which new cells may touch; it is
/// as long as the clearance needs (1 step, or 3 while dilating).
pub(super) struct Walker {
    pub(super) head: Rect,
    pub(super) trail: [Rect; 3],
    pub(super) d: Dir,
}

impl Walker {
    pub(super) fn new(head: Rect, behind: Rect, d: Dir) -> Walker {
        Walker {
            head,
            trail: [behind, Rect::EMPTY, Rect::EMPTY],
            d,
        }
    }

    /// The head and the cells behind it that new cells may touch.
    pub(super) fn neighbourhood(&self, c: &Canvas) -> Rect {
        let depth = (2 * clearance(c) - 1) as usize;
        self.trail[..depth]
            .iter()
            .fold(self.head, |a, &b| a.union(b))
    }

    pub(super) fn try_move(&mut self, c: &mut Canvas, d: Dir, painted: &mut Vec<u32>) -> bool {
        let slice = self.head.front(d);
        if !clear_for(c, slice, self.neighbourhood(c).union(slice)) {
            return false;
        }
        paint(c, slice, slice.y0, usize::MAX, painted);
        self.trail = [self.head, self.trail[0], self.trail[1]];
        self.head = self.head.shift(d);
        self.d = d;
        true
    }
}

pub(super) fn random_dir(rng: &mut Rng) -> Dir {
    Dir::ALL[below(rng, 4)]
}

/// Starts a corridor of width `w` from pixel `k`, leaving it in direction `d`.
pub(super) fn start_corridor(
    c: &mut Canvas,
    k: usize,
    d: Dir,
    w: i64,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) -> Option<Walker> {
    let (px, py) = ((k % c.w) as i64, (k / c.w) as i64);
    let j = below(rng, w as usize) as i64;
    // The square in front of the pixel, and the wall behind it (as deep as the clearance).
    let r = clearance(c);
    let (sq, wall) = match d {
        Dir::E => (
            Rect {
                x0: px + 1,
                x1: px + w,
                y0: py - j,
                y1: py - j + w - 1,
            },
            Rect {
                x0: px - r + 1,
                x1: px,
                y0: py - j - r,
                y1: py - j + w - 1 + r,
            },
        ),
        Dir::W => (
            Rect {
                x0: px - w,
                x1: px - 1,
                y0: py - j,
                y1: py - j + w - 1,
            },
            Rect {
                x0: px,
                x1: px + r - 1,
                y0: py - j - r,
                y1: py - j + w - 1 + r,
            },
        ),
        Dir::N => (
            Rect {
                y0: py + 1,
                y1: py + w,
                x0: px - j,
                x1: px - j + w - 1,
            },
            Rect {
                y0: py - r + 1,
                y1: py,
                x0: px - j - r,
                x1: px - j + w - 1 + r,
            },
        ),
        Dir::S => (
            Rect {
                y0: py - w,
                y1: py - 1,
                x0: px - j,
                x1: px - j + w - 1,
            },
            Rect {
                y0: py,
                y1: py + r - 1,
                x0: px - j - r,
                x1: px - j + w - 1 + r,
            },
        ),
    };
    if !clear_for(c, sq, sq.union(wall)) {
        return None;
    }
    paint(c, sq, sq.y0, usize::MAX, painted);
    Some(Walker::new(sq, wall, d))
}

/// Corridors of random widths that turn and branch without touching one another; with
/// `rooms`, rectangular rooms at their ends.
pub(super) fn draw_corridors(c: &mut Canvas, target: usize, rooms: bool, rng: &mut Rng) {
    let mut painted = Vec::new();
    let root = target.isqrt().max(2);
    let max_w = if rooms { 3 } else { 4 };
    let seg_max = between(rng, 3, (root / 2).max(4));
    let len_max = between(rng, root / 2 + 2, 4 * root + 4);
    let room_max = between(rng, 3, (root / 3).max(3)) as i64;
    let (x, y) = center(c, rng);
    let w0 = if rooms {
        between(rng, 2, room_max as usize) as i64
    } else {
        between(rng, 1, max_w) as i64
    };
    let h0 = if rooms {
        between(rng, 2, room_max as usize) as i64
    } else {
        w0
    };
    let first = Rect {
        x0: x as i64,
        y0: y as i64,
        x1: x as i64 + w0 - 1,
        y1: y as i64 + h0 - 1,
    };
    paint(c, first, first.y0, target, &mut painted);
    let mut walker = if rooms {
        None
    } else {
        Some(Walker::new(first, Rect::EMPTY, random_dir(rng)))
    };
    let mut fails = 0;
    while c.size() < target && fails < 200 {
        if let Some(mut wk) = walker.take() {
            run_corridor(
                c,
                &mut wk,
                between(rng, 2, len_max),
                seg_max,
                target,
                rng,
                &mut painted,
            );
            if rooms && c.size() < target && chance(rng, 0.85) {
                place_room(c, &wk, room_max, target, rng, &mut painted);
            }
        }
        let w = between(rng, 1, max_w) as i64;
        for _ in 0..40 {
            let k = painted[below(rng, painted.len())] as usize;
            let d = random_dir(rng);
            let (dx, dy) = d.delta();
            let next = (k as isize + dx as isize + dy as isize * c.w as isize) as usize;
            if c.occ[next] {
                continue;
            }
            if let Some(wk) = start_corridor(c, k, d, w, rng, &mut painted) {
                walker = Some(wk);
                break;
            }
        }
        if walker.is_none() {
            fails += 1;
        }
    }
}

pub(super) fn turn(d: Dir, rng: &mut Rng) -> Dir {
    if chance(rng, 0.5) {
        d.left()
    } else {
        d.right()
    }
}

pub(super) fn run_corridor(
    c: &mut Canvas,
    wk: &mut Walker,
    len: usize,
    seg_max: usize,
    target: usize,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) {
    let mut seg = between(rng, 1, seg_max);
    let mut left = len;
    while left > 0 && c.size() < target {
        let mut d = wk.d;
        if seg == 0 {
            if !chance(rng, 0.15) {
                d = turn(d, rng);
            }
            seg = between(rng, 1, seg_max);
        }
        if !wk.try_move(c, d, painted) {
            let a = turn(wk.d, rng);
            if !wk.try_move(c, a, painted) && !wk.try_move(c, a.opposite(), painted) {
                return;
            }
            seg = between(rng, 1, seg_max);
        }
        seg -= 1;
        left -= 1;
    }
}

/// A room in front of the corridor head, covering the head's width.
pub(super) fn place_room(
    c: &mut Canvas,
    wk: &Walker,
    room_max: i64,
    target: usize,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) {
    let h = wk.head;
    let w = h.x1 - h.x0 + 1;
    for shrink in 0..3 {
        let max = (room_max >> shrink).max(w.max(2));
        let along = between(rng, 2, max as usize) as i64;
        let across = between(rng, w.max(2) as usize, max as usize) as i64;
        let off = below(rng, (across - w + 1) as usize) as i64;
        let room = match wk.d {
            Dir::E => Rect {
                x0: h.x1 + 1,
                x1: h.x1 + along,
                y0: h.y0 - off,
                y1: h.y0 - off + across - 1,
            },
            Dir::W => Rect {
                x0: h.x0 - along,
                x1: h.x0 - 1,
                y0: h.y0 - off,
                y1: h.y0 - off + across - 1,
            },
            Dir::N => Rect {
                y0: h.y1 + 1,
                y1: h.y1 + along,
                x0: h.x0 - off,
                x1: h.x0 - off + across - 1,
            },
            Dir::S => Rect {
                y0: h.y0 - along,
                y1: h.y0 - 1,
                x0: h.x0 - off,
                x1: h.x0 - off + across - 1,
            },
        };
        if clear_for(c, room, wk.neighbourhood(c).union(room)) {
            let from_y = match wk.d {
                Dir::N => room.y0,
                Dir::S => room.y1,
                _ => h.y0,
            };
            paint(c, room, from_y, target, painted);
            return;
        }
    }
}
