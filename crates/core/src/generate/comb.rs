//! `comb` and `double-comb`: a horizontal spine with width-1 teeth at spacing 2.
//!
//! The spine is the row y = 0, x = 0..2k − 2; tooth i (i = 0..k − 1) is the column
//! x = 2i, y = 1..L (`comb`), or y = 1..L and y = −1..−L (`double-comb`, teeth on both sides).
//! **N = (2k − 1) + kL** (`comb`) and **N = (2k − 1) + 2kL** (`double-comb`); no holes.
//! k defaults to max(1, round(√(n/2))) (about square); L ≥ 1 is the length nearest to the
//! requested n for that k.
//!
//! Why it is hard: every tooth is a dead end of width 1 whose tip costs two U-turns (four
//! 90° turns) and whose length is walked twice, so the tour is about 2N long and turns about
//! 4k times, while the lower bounds that count pixels or strips see N and k: it stresses the
//! strip-based turn bounds and the doubling arguments (the milling paper's Theorem 4 sees
//! Q = 0 and no holes, so contour walks are long). `double-comb` puts a junction of degree 4
//! at every tooth.

use crate::region::Pixel;

/// The tooth length L ≥ 1 for which the comb with k teeth (on `sides` sides) is nearest to n.
pub(super) fn comb_length(n: usize, k: usize, sides: usize) -> usize {
    let spine = 2 * k - 1;
    let per = sides * k;
    let rest = n.saturating_sub(spine);
    // Nearest integer to rest / per (ties down), at least 1.
    ((2 * rest + per - 1) / (2 * per)).max(1)
}

/// The default number of teeth for about n pixels: max(1, round(√(n/2))).
pub(super) fn comb_default_teeth(n: usize) -> usize {
    let target = n / 2;
    let r = target.isqrt();
    // round(√t): r or r + 1, whichever square is nearer.
    let r = if (r + 1) * (r + 1) - target <= target - r * r {
        r + 1
    } else {
        r
    };
    r.max(1)
}

/// The pixel count of the comb: (2k − 1) + sides · k · L.
pub(super) fn comb_count(k: usize, len: usize, sides: usize) -> usize {
    2 * k - 1 + sides * k * len
}

/// The comb's pixels: spine, then the teeth.
pub(super) fn comb_pixels(k: usize, len: usize, double: bool) -> Vec<Pixel> {
    let len = len as i32;
    let mut out: Vec<Pixel> = (0..2 * k as i32 - 1).map(|x| Pixel::new(x, 0)).collect();
    for i in 0..k as i32 {
        out.extend((1..=len).map(|y| Pixel::new(2 * i, y)));
        if double {
            out.extend((1..=len).map(|y| Pixel::new(2 * i, -y)));
        }
    }
    out
}
