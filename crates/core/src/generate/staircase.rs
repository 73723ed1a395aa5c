//! The deterministic staircase of full rows with one-pixel holes on a grid: the fallback of
//! `random-simple`, `random-holed` and `pinholes`, and the bound on how many holes fit.

use super::rng::{Rng, shuffle};
use crate::region::Pixel;

/// A staircase of `total` pixels and width `w`, left-aligned, bottom up: `full` rows of `w`,
/// then the rows of `tail` (shorter, non-increasing). With `no_cut` no row is a single pixel
/// and there are at least two full rows below a shorter row, so the staircase has no cut
/// vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Staircase {
    pub(super) w: usize,
    pub(super) full: usize,
    pub(super) tail: Vec<usize>,
}

impl Staircase {
    pub(super) fn new(total: usize, w: usize, no_cut: bool) -> Option<Staircase> {
        let (q, r) = (total / w, total % w);
        let full = |full, tail| Some(Staircase { w, full, tail });
        match r {
            0 if !no_cut || total <= 2 || (w >= 2 && q >= 2) => full(q, vec![]),
            _ if !no_cut => full(q, vec![r]),
            // One full row and the extra pixel become rows of ⌈(w+1)/2⌉ and ⌊(w+1)/2⌋.
            1 if q >= 3 && w >= 3 => full(q - 1, vec![(w + 1).div_ceil(2), w.div_ceil(2)]),
            2.. if q >= 2 => full(q, vec![r]),
            // A line of three or more pixels, or a short row on a single row.
            _ => None,
        }
    }

    /// Capacity of the hole grid inside the full rows: one-pixel holes with walls of one
    /// pixel (period 2), or of two pixels with `no_cut` (period 3).
    pub(super) fn grid_axis(len: usize, no_cut: bool) -> impl Iterator<Item = usize> {
        let (start, step, edge) = if no_cut { (2, 3, 2) } else { (1, 2, 1) };
        (start..len.saturating_sub(edge)).step_by(step)
    }

    pub(super) fn hole_capacity(&self, no_cut: bool) -> usize {
        Self::grid_axis(self.w, no_cut).count() * Self::grid_axis(self.full, no_cut).count()
    }

    pub(super) fn hole_grid(&self, no_cut: bool) -> Vec<(usize, usize)> {
        let xs: Vec<usize> = Self::grid_axis(self.w, no_cut).collect();
        Self::grid_axis(self.full, no_cut)
            .flat_map(|y| xs.iter().map(move |&x| (x, y)))
            .collect()
    }

    pub(super) fn row_lengths(&self) -> impl Iterator<Item = usize> + '_ {
        std::iter::repeat_n(self.w, self.full).chain(self.tail.iter().copied())
    }
}

/// A staircase of n + holes pixels whose full rows hold `holes` grid holes, trying widths
/// near √(n + holes) first. O(n) time at worst.
pub(super) fn rows_plan(n: usize, holes: usize, no_cut: bool) -> Option<Staircase> {
    let total = n + holes;
    let s = total.isqrt().max(1);
    for d in 0..=total {
        if s + d > total && d >= s {
            break;
        }
        for w in [s + d, s.wrapping_sub(d)] {
            if w == 0 || w > total || (d == 0 && w != s + d) {
                continue;
            }
            if let Some(st) = Staircase::new(total, w, no_cut)
                && st.hole_capacity(no_cut) >= holes
            {
                return Some(st);
            }
        }
    }
    None
}

/// The staircase with `holes` grid holes chosen at random: n pixels in all.
pub(super) fn rows_pixels(
    n: usize,
    holes: usize,
    no_cut: bool,
    rng: &mut Rng,
) -> Option<Vec<Pixel>> {
    let st = rows_plan(n, holes, no_cut)?;
    let mut grid = st.hole_grid(no_cut);
    shuffle(&mut grid, rng);
    let mut holed: Vec<(usize, usize)> = grid[..holes].to_vec();
    holed.sort_unstable();
    let mut pixels = Vec::with_capacity(n);
    for (y, len) in st.row_lengths().enumerate() {
        for x in 0..len {
            if holed.binary_search(&(x, y)).is_err() {
                pixels.push(Pixel::new(x as i32, y as i32));
            }
        }
    }
    Some(pixels)
}

/// The smallest n for which `rows_plan(n, holes, no_cut)` holds a full rectangle: the hole
/// grid of a × ⌈H/a⌉ holes with its walls.
pub(super) fn min_holed_pixels(holes: usize, no_cut: bool) -> usize {
    if holes == 0 {
        return 1;
    }
    let (per, extra) = if no_cut { (3, 2) } else { (2, 1) };
    (1..=holes)
        .map(|a| (per * a + extra) * (per * holes.div_ceil(a) + extra) - holes)
        .min()
        .unwrap_or(usize::MAX)
}
