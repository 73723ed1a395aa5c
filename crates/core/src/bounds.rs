//! Proven lower bounds on the optimum of each exact objective, for sizes beyond exact reach.
//!
//! The cheap bounds run in near-linear time:
//!
//! * **Length of a milling tour** (closed walk visiting every pixel): at least N (every pixel is
//!   visited and each visit is one unit move of the closed walk); the grid graph is bipartite,
//!   so a closed walk has even length and alternates colours, giving N + 1 for odd N and
//!   2 · max(#black, #white). A single pixel needs length 0.
//! * **Lawn TSP** (closed walk on the infinite grid visiting every grass pixel): the same
//!   colour and parity bounds, and twice the width plus twice the height of the bounding box of
//!   the pixel centres (the walk reaches both extreme columns and both extreme rows).
//! * **Turns** of a cycle cover or tour: at least the minimum strip cover size (Lemma 4.2 of
//!   the turn-cost paper; computed exactly by König's theorem, Lemma 4.4), per component; and
//!   every closed walk turns through at least 360°, which is 4 turns (a U-turn is 2), so each
//!   component costs at least 4.
//!
//! The bound for an exact objective (`mowmill_exact::cheap_lower_bound`)
//! and the LP relaxations of the exact models (with all their connectivity cuts, stronger and
//! costing an LP solve: `mowmill_exact::lp_lower_bound`) live with the
//! exact models, which use the bounds here.

use crate::region::Region;
use crate::strip_cover::strip_cover;
use crate::topology::{colour_counts, components};
use serde::Serialize;

/// A proven lower bound and where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct LowerBound {
    pub value: u64,
    pub source: &'static str,
}

impl LowerBound {
    pub fn new(value: u64, source: &'static str) -> LowerBound {
        LowerBound { value, source }
    }

    /// The larger of two bounds (the first on ties).
    pub fn max(self, other: LowerBound) -> LowerBound {
        if other.value > self.value {
            other
        } else {
            self
        }
    }
}

/// Lower bound on the length of a closed walk visiting every pixel of a connected region.
///
/// # Complexity
/// O(N).
pub fn length_lower_bound(region: &Region) -> LowerBound {
    let n = region.len() as u64;
    if n <= 1 {
        return LowerBound::new(0, "single pixel");
    }
    let (black, white) = colour_counts(region);
    let parity = if n % 2 == 1 {
        LowerBound::new(n + 1, "n + 1 (odd n, even closed walks)")
    } else {
        LowerBound::new(n, "n")
    };
    parity.max(LowerBound::new(
        2 * black.max(white) as u64,
        "2 max(#black, #white)",
    ))
}

/// Lower bound on the L1 length of a tour through the centres of all pixels (lawn TSP).
///
/// # Complexity
/// O(N).
pub fn lawn_tsp_lower_bound(region: &Region) -> LowerBound {
    if region.len() <= 1 {
        return LowerBound::new(0, "single pixel");
    }
    let b = region.bbox();
    let bbox = 2 * (b.width() as u64 - 1) + 2 * (b.height() as u64 - 1);
    length_lower_bound(region).max(LowerBound::new(bbox, "bounding box perimeter"))
}

/// Lower bound on the turns of any cycle cover of the region (hence of any tour): per
/// component, the larger of its minimum strip cover size and 4.
///
/// # Complexity
/// O(N √N) worst case (Hopcroft–Karp), near-linear on grid regions.
pub fn turn_lower_bound(region: &Region) -> LowerBound {
    if region.is_empty() {
        return LowerBound::new(0, "empty region");
    }
    let labels = components(region);
    let cover = strip_cover(region);
    let mut per_component = vec![0u64; labels.count];
    for s in &cover.strips {
        let i = region.index_of(s.start).expect("strip start is a pixel");
        per_component[labels.label[i] as usize] += 1;
    }
    let strips: u64 = per_component.iter().sum();
    let total: u64 = per_component.iter().map(|&s| s.max(4)).sum();
    if total > strips {
        LowerBound::new(
            total,
            "min strip cover (Lemma 4.2), at least 4 per closed walk",
        )
    } else {
        LowerBound::new(total, "min strip cover (Lemma 4.2)")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixtures() {
        let r = Region::rectangle(2, 3);
        assert_eq!(length_lower_bound(&r).value, 6);
        assert_eq!(turn_lower_bound(&r).value, 4);
        let sq = Region::rectangle(3, 3);
        assert_eq!(length_lower_bound(&sq).value, 10);
        let row = Region::rectangle(4, 1);
        assert_eq!(length_lower_bound(&row).value, 4);
        assert_eq!(turn_lower_bound(&row).value, 4);
        assert_eq!(length_lower_bound(&Region::rectangle(1, 1)).value, 0);
        // A plus: 5 pixels, 4 white arms around a black centre (or the reverse).
        let plus = Region::from_ascii(".#.\n###\n.#.\n");
        assert_eq!(length_lower_bound(&plus).value, 8);
        // Two separate dominoes: 4 turns each.
        let two = Region::from_ascii("##.##\n");
        assert_eq!(turn_lower_bound(&two).value, 8);
        // Scattered lawn: bounding box 5 x 3 centres apart by 4 and 2.
        let lawn = Region::from_ascii("#...#\n.....\n..#..\n");
        assert_eq!(lawn_tsp_lower_bound(&lawn).value, 12);
    }
}
