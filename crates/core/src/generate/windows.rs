//! `windows`: a square with an m × m lattice of square window panes (holes).
//!
//! Bars of width w ∈ {1, 2} frame m × m panes, each a hole of side p (`k`, default 2):
//! the square of side S = m(p + w) + w minus the panes.
//! **N = S² − m²p²**, **h = m²**; m ≥ 1 is chosen so that N is nearest to n.
//!
//! Why it is hard: every bar crossing is a junction of degree 4 (w = 1) and every pane a hole
//! whose contour costs 4 turns in the contour-based bounds, while good tours run straight
//! along whole bars: the hole-count terms of the milling paper's bounds (2h) and the
//! turn paper's strip and boundary bounds are far from the optimum here; with p = 1, w = 1
//! it is `hole-lattice --pattern square`.

use crate::region::Pixel;

/// The side of the square for m panes of side p and bars of width w.
pub(super) fn windows_side(m: usize, p: usize, w: usize) -> usize {
    m * (p + w) + w
}

/// The pixel count: S² − m²p².
pub(super) fn windows_count(m: usize, p: usize, w: usize) -> usize {
    let s = windows_side(m, p, w);
    s * s - m * m * p * p
}

/// The number of panes per side m ≥ 1 nearest to n pixels (the smaller on a tie).
pub(super) fn windows_panes(n: usize, p: usize, w: usize) -> usize {
    let mut best = (usize::MAX, 1);
    for m in 1.. {
        let count = windows_count(m, p, w);
        if count.abs_diff(n) < best.0 {
            best = (count.abs_diff(n), m);
        }
        if count >= n {
            break;
        }
    }
    best.1
}

pub(super) fn windows_pixels(m: usize, p: usize, w: usize) -> Vec<Pixel> {
    let s = windows_side(m, p, w);
    // Cell c along an axis is a bar cell iff c mod (p + w) < w.
    let bar = move |c: usize| c % (p + w) < w;
    (0..s)
        .flat_map(|y| {
            (0..s)
                .filter(move |&x| bar(x) || bar(y))
                .map(move |x| Pixel::new(x as i32, y as i32))
        })
        .collect()
}
