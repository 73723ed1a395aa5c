//! `hole-lattice`: a square of odd side riddled with one-pixel holes in a lattice.
//!
//! The region is the s × s square, s = 2m + 1 (m ≥ 1 chosen so that N is nearest to the
//! requested n), minus the cells of one of four lattices ([`Pattern`]). Rows and columns are
//! numbered from 0 at the bottom left.
//!
//! * `staggered` (the default): the even rows y = 0, 2, …, 2m are full; odd row y = 2j + 1
//!   lacks every cell x ≡ 0 (mod 2) when j is even and every cell x ≡ 1 (mod 2) when j is
//!   odd (cells x = 0 and x = 2m of the first kind are notches of the boundary, not holes).
//!   No 2 × 2 block is full (Q = 0) and h ≈ N/3, so the contour walks of `milling25`
//!   (length 2N − 2Q + 2h − 2) cost about 8N/3, while a tour of length about N exists (a
//!   zig-zag through the hole rows): the family drives milling25 towards 8/3 > 5/2
//!   (Theorem 4 of the milling paper). With a = ⌈m/2⌉ rows of the first kind and b = ⌊m/2⌋ of
//!   the second: **N = (m + 1)(2m + 1) + a·m + b·(m + 1)** and **h = a(m − 1) + b·m**.
//! * `square`: the holes are the cells (odd, odd): a mesh of width-1 bars.
//!   **N = (2m + 1)² − m²**, **h = m²**.
//! * `diagonal`: the holes are the inner cells (1 ≤ x, y ≤ 2m − 1) with x + 2y ≡ 0 (mod 5);
//!   no two of them are 8-adjacent (the 8 steps change x + 2y by ±1, ±2 or ±3), so each is a
//!   hole of its own. **h = #{1 ≤ x, y ≤ 2m − 1 : x + 2y ≡ 0 (mod 5)}**, **N = (2m + 1)² − h**.
//! * `sparse`: the staggered pattern with holes every third cell: odd row y = 2j + 1 lacks
//!   the inner cells 1 ≤ x ≤ 2m − 1 with x ≡ 1 + (j mod 2) (mod 3).
//!   **h = Σ_j #{1 ≤ x ≤ 2m − 1 : x ≡ 1 + (j mod 2) (mod 3)}** over j = 0..m − 1,
//!   **N = (2m + 1)² − h**.
//!
//! Every pattern is connected (each missing cell of an odd row has full rows above and
//! below it; `square` and `diagonal` remove cells whose 8-ring is full).

use crate::error::{Error, Result};
use crate::region::Pixel;
use std::fmt;
use std::str::FromStr;

/// The lattice of holes of `hole-lattice` (module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Pattern {
    Staggered,
    Square,
    Diagonal,
    Sparse,
}

impl Pattern {
    pub const ALL: [Pattern; 4] = [
        Pattern::Staggered,
        Pattern::Square,
        Pattern::Diagonal,
        Pattern::Sparse,
    ];
    pub const NAMES: [&'static str; 4] = ["staggered", "square", "diagonal", "sparse"];

    pub fn name(self) -> &'static str {
        Pattern::NAMES[self as usize]
    }
}

impl fmt::Display for Pattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Pattern {
    type Err = Error;

    fn from_str(s: &str) -> Result<Pattern> {
        Pattern::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                Error::invalid(format!(
                    "unknown pattern {s:?}: expected one of {}",
                    Pattern::NAMES.join(", ")
                ))
            })
    }
}

/// Whether cell (x, y) of the square of side 2m + 1 is a lattice cell (missing).
fn missing(pattern: Pattern, m: usize, x: usize, y: usize) -> bool {
    let inner = (1..2 * m).contains(&x) && (1..2 * m).contains(&y);
    match pattern {
        Pattern::Staggered => y % 2 == 1 && x % 2 == (y / 2) % 2,
        Pattern::Square => x % 2 == 1 && y % 2 == 1,
        Pattern::Diagonal => inner && (x + 2 * y).is_multiple_of(5),
        Pattern::Sparse => y % 2 == 1 && inner && x % 3 == 1 + (y / 2) % 2,
    }
}

/// The pixel count for half-side m (the module's formulas, by counting rows in O(m)).
pub(super) fn lattice_pixels_count(pattern: Pattern, m: usize) -> usize {
    let s = 2 * m + 1;
    let missing_in_row = |y: usize| (0..s).filter(|&x| missing(pattern, m, x, y)).count();
    match pattern {
        // Rows repeat with period 4 (staggered, sparse) or 2 (square): count two odd rows.
        Pattern::Staggered | Pattern::Sparse | Pattern::Square => {
            let (a, b) = (m.div_ceil(2), m / 2);
            s * s - a * missing_in_row(1) - b * missing_in_row(3)
        }
        Pattern::Diagonal => s * s - (0..s).map(missing_in_row).sum::<usize>(),
    }
}

/// The half-side m ≥ 1 whose pixel count is nearest to n (the smaller on a tie).
pub(super) fn lattice_half_side(pattern: Pattern, n: usize) -> usize {
    let mut best = (usize::MAX, 1);
    for m in 1.. {
        let count = lattice_pixels_count(pattern, m);
        let d = count.abs_diff(n);
        if d < best.0 {
            best = (d, m);
        }
        if count >= n {
            break;
        }
    }
    best.1
}

/// The pixels of the pattern in the square of side 2m + 1, row by row.
pub(super) fn hole_lattice_pixels(pattern: Pattern, m: usize) -> Vec<Pixel> {
    let s = 2 * m + 1;
    (0..s)
        .flat_map(|y| {
            (0..s)
                .filter(move |&x| !missing(pattern, m, x, y))
                .map(move |x| Pixel::new(x as i32, y as i32))
        })
        .collect()
}
