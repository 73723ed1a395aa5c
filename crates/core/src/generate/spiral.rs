//! `spiral`: a corridor of width w ∈ {1, 2} wound as a rectangular spiral in an S × S square.
//!
//! The centre line starts at the top left corner and runs right, down, left, up, right, …,
//! with segment lengths T − 1, T − 1, T − 1, then T − 1 − p, T − 1 − p, T − 1 − 2p,
//! T − 1 − 2p, … while positive and ending with the first segment shorter than p, where
//! T = S − w + 1 and p = w + 1 (so consecutive windings are one empty cell apart); every centre-line cell paints the w × w block to its lower
//! right. With M the sum of the segment lengths, **N = w² + w·M**; no holes (the walls
//! between windings are one spiral of empty cells reaching the outside). S is the side whose
//! N is nearest to n.
//!
//! Why it is hard: a width-1 spiral is a Hamiltonian path (length about N, but 2 turns per
//! winding and no 2 × 2 block: Q = 0, so milling25's contour walks cost about 2N), and a
//! closed tour must come back, doubling it; the width-2 spiral is the classic case where a
//! tour of length N exists but turns are forced at every corner of both lanes (turn
//! paper, Section 5: strip covers and the 6/5 and 4/3 thin constructions).

use crate::region::Pixel;

/// The centre-line segment lengths of the spiral in a square of side s at width w.
fn segments(s: usize, w: usize) -> Vec<usize> {
    let p = w + 1;
    let t = s + 1 - w;
    let mut out = Vec::new();
    if t < 2 {
        return out;
    }
    let mut lens = vec![t - 1; 3];
    let mut shrink = p;
    while let Some(len) = (t - 1).checked_sub(shrink).filter(|&l| l > 0) {
        lens.extend([len, len]);
        shrink += p;
    }
    // A segment shorter than p leaves no wall between the next one and the winding it came
    // from: the spiral ends with the first such segment.
    for len in lens {
        out.push(len);
        if len < p {
            break;
        }
    }
    out
}

/// The spiral's pixel count: w² + w·M.
pub(super) fn spiral_count(s: usize, w: usize) -> usize {
    w * w + w * segments(s, w).iter().sum::<usize>()
}

/// The side S ≥ w whose spiral is nearest to n pixels (the smaller on a tie).
pub(super) fn spiral_side(n: usize, w: usize) -> usize {
    let mut best = (usize::MAX, w);
    for s in w.. {
        let count = spiral_count(s, w);
        if count.abs_diff(n) < best.0 {
            best = (count.abs_diff(n), s);
        }
        if count >= n {
            break;
        }
    }
    best.1
}

/// The spiral's pixels (centre line traced with its blocks), without repetitions.
pub(super) fn spiral_pixels(s: usize, w: usize) -> Vec<Pixel> {
    let mut occ = vec![false; s * s];
    let mut paint = |x: i64, y: i64| {
        for dy in 0..w as i64 {
            for dx in 0..w as i64 {
                occ[(x + dx) as usize + s * (y + dy) as usize] = true;
            }
        }
    };
    // Screen coordinates while tracing (y down); flipped on output.
    let (mut x, mut y) = (0i64, 0i64);
    paint(x, y);
    let dirs = [(1i64, 0i64), (0, 1), (-1, 0), (0, -1)];
    for (i, &len) in segments(s, w).iter().enumerate() {
        let (dx, dy) = dirs[i % 4];
        for _ in 0..len {
            x += dx;
            y += dy;
            paint(x, y);
        }
    }
    (0..s * s)
        .filter(|&i| occ[i])
        .map(|i| Pixel::new((i % s) as i32, (s - 1 - i / s) as i32))
        .collect()
}
