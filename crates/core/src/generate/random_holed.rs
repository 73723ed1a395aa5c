//! `random-holed`: holes by bridging fjords and by carving full blocks.

use super::canvas::{ADJ_MARGIN, Canvas};
use super::growth::{Frontier, Move, adjust, bucket_weights, evolve, refresh};
use super::random_simple::simple_canvas;
use super::rng::{Rng, chance, shuffle, unit};
use super::styles::ShapeOpts;

/// A shape of exactly `n` pixels with exactly `holes` holes.
pub(super) fn holed_canvas(n: usize, holes: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<Canvas> {
    // Total hole area: between 2% and 30% of n, at least one cell per hole.
    let area = if holes == 0 {
        0
    } else {
        ((n as f64 * (0.02 + 0.28 * unit(rng))) as usize).max(holes)
    };
    // The shape is drawn with room for the holes and eroded to n at the end, except with
    // no_cut: eroding without creating cut vertices gets stuck in corridors two pixels wide,
    // while growing at concave corners does not, so the holes eat into a shape of about n
    // pixels that then grows back to n.
    let base = if o.no_cut { n + holes } else { n + area };
    let (mut c, mut f) = simple_canvas(base, o, rng)?;
    if !carve_holes(&mut c, &mut f, holes, area, o.no_cut, rng) {
        return None;
    }
    let weights = bucket_weights(o.compactness);
    adjust(&mut c, &mut f, n, &weights, o.no_cut, rng).then_some(c)
}

/// Random hole sizes, at least 1 each, summing to about `area`, skewed (a few large holes).
pub(super) fn hole_sizes(holes: usize, area: usize, rng: &mut Rng) -> Vec<usize> {
    let raw: Vec<f64> = (0..holes)
        .map(|_| {
            let u = unit(rng);
            u * u * u + 0.02
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    let spare = area.saturating_sub(holes) as f64;
    raw.iter().map(|r| 1 + (spare * r / sum) as usize).collect()
}

/// Creates exactly `holes` new holes in a connected hole-free canvas: one-cell holes carved
/// at interior sites (then grown to random sizes and shapes) and, without `no_cut`, holes
/// made by bridging.
pub(super) fn carve_holes(
    c: &mut Canvas,
    f: &mut Frontier,
    holes: usize,
    area: usize,
    no_cut: bool,
    rng: &mut Rng,
) -> bool {
    if holes == 0 {
        return true;
    }
    c.hole = vec![0; c.area()];
    // Bridges first: a quarter of the holes without no_cut, as many as the shape offers.
    let wanted = if no_cut {
        0
    } else {
        (0..holes).filter(|_| chance(rng, 0.25)).count()
    };
    let mut candidates = None;
    let bridges = (0..wanted)
        .take_while(|_| bridge(c, &mut candidates, rng))
        .count();
    // Carving sites: pixels whose 5 × 5 block is full (the new hole is two cells away from
    // everything empty, and with no_cut every pixel of its ring keeps Yokoi number 1), then,
    // without no_cut, pixels whose 3 × 3 block is full.
    let (mut wide, mut narrow) = (Vec::new(), Vec::new());
    for k in 0..c.area() {
        if c.occ[k] && c.in_zone(k, ADJ_MARGIN + 2) {
            if c.full(k, 2) {
                wide.push(k as u32);
            } else if !no_cut && c.full(k, 1) {
                narrow.push(k as u32);
            }
        }
    }
    shuffle(&mut wide, rng);
    shuffle(&mut narrow, rng);
    let mut carved = Vec::with_capacity(holes);
    let carve = |c: &mut Canvas, carved: &mut Vec<usize>, k: usize| {
        carved.push(k);
        c.set(k, false);
        c.hole[k] = carved.len() as u32;
    };
    for _ in bridges..holes {
        let Some(k) = pop_site(c, &mut wide, 2).or_else(|| pop_site(c, &mut narrow, 1)) else {
            break;
        };
        carve(c, &mut carved, k);
    }
    // Narrow shapes lack sites: glue solid 5 × 5 pads on and carve their centres.
    let missing = holes - bridges - carved.len();
    if missing > 0 {
        let pads = add_pads(c, missing, rng);
        if pads.len() < missing {
            return false;
        }
        for k in pads {
            carve(c, &mut carved, k);
        }
    }
    // Grow each carved hole to its size by removing simple pixels next to it.
    let sizes = hole_sizes(carved.len(), area.saturating_sub(bridges), rng);
    for (i, (&k, &size)) in carved.iter().zip(&sizes).enumerate() {
        let label = i as u32 + 1;
        f.clear();
        let r = if no_cut { 2 } else { 1 };
        refresh(c, f, k, r, Move::Hole(label), ADJ_MARGIN);
        let stop = c.count + 1 - size;
        let weights = bucket_weights(unit(rng));
        evolve(
            c,
            f,
            Move::Hole(label),
            &weights,
            no_cut,
            ADJ_MARGIN,
            rng,
            |c| c.count <= stop,
        );
    }
    f.clear();
    c.hole = Vec::new();
    true
}

/// Paints up to `wanted` solid 5 × 5 squares centred on random pixels, two cells away from
/// every hole and three cells apart from one another, fills the pockets they close, and
/// returns their centres (each a carving site). A pad shares at least two adjacent pixels
/// with the region, so a region without cut vertices keeps none (the union of two
/// 2-connected graphs that share two vertices is 2-connected), filling pockets adds no cut
/// vertex either, and the pixels next to the existing holes do not change.
pub(super) fn add_pads(c: &mut Canvas, wanted: usize, rng: &mut Rng) -> Vec<usize> {
    const R: usize = 2;
    let was_outside = c.outside();
    let mut spots: Vec<u32> = (0..c.area())
        .filter(|&k| c.occ[k] && c.in_zone(k, ADJ_MARGIN + R))
        .map(|k| k as u32)
        .collect();
    shuffle(&mut spots, rng);
    let mut centres: Vec<usize> = Vec::new();
    let w = c.w;
    let far = |a: usize, b: usize| (a % w).abs_diff(b % w).max((a / w).abs_diff(b / w)) >= 3;
    for k in spots {
        if centres.len() == wanted {
            break;
        }
        let k = k as usize;
        let (x, y) = (k % w, k / w);
        let near_hole = (y - R - 2..=y + R + 2).any(|yy| {
            (x - R - 2..=x + R + 2).any(|xx| {
                let q = c.idx(xx, yy);
                !c.occ[q] && !was_outside[q]
            })
        });
        if near_hole || !centres.iter().all(|&o| far(o, k)) {
            continue;
        }
        for yy in y - R..=y + R {
            for xx in x - R..=x + R {
                c.set(c.idx(xx, yy), true);
            }
        }
        centres.push(k);
    }
    if !centres.is_empty() {
        c.fill_holes(Some(&was_outside));
    }
    centres
}

pub(super) fn pop_site(c: &Canvas, sites: &mut Vec<u32>, r: usize) -> Option<usize> {
    while let Some(k) = sites.pop() {
        let k = k as usize;
        if c.occ[k] && c.full(k, r) {
            return Some(k);
        }
    }
    None
}

/// Adds one empty cell with Yokoi number 2: it joins two arcs of the (connected) region and
/// so closes a loop, adding exactly one hole.
pub(super) fn bridge(c: &mut Canvas, bridges: &mut Option<Vec<u32>>, rng: &mut Rng) -> bool {
    let list = bridges.get_or_insert_with(|| {
        let mut v: Vec<u32> = (0..c.area())
            .filter(|&k| !c.occ[k] && c.in_zone(k, ADJ_MARGIN) && c.nb4(k) > 0 && c.yokoi(k) == 2)
            .map(|k| k as u32)
            .collect();
        shuffle(&mut v, rng);
        v
    });
    while let Some(k) = list.pop() {
        let k = k as usize;
        if !c.occ[k] && c.yokoi(k) == 2 {
            c.set(k, true);
            return true;
        }
    }
    false
}
