//! `star-cover`: a greedy rook placement, its star cover, one closed walk touring each star,
//! merged into a tour (Lemmas 4.5–4.6, Theorem 5.1 and Corollary 5.2 of *Optimal covering
//! tours with turn costs*).
//!
//! # Construction
//! Pixels are scanned in index order; a rook is placed on every pixel whose horizontal and
//! vertical maximal strips hold no rook yet. Then every pixel shares a strip with a rook, the
//! rooks attack no one another, and r rooks ≤ the maximum rook placement = the minimum strip
//! cover ≤ OPT (Lemmas 4.3–4.5). The star of a rook is its two strips; its walk runs from the
//! rook to the east end, back to the west end, back to the rook, then likewise north, south and
//! back: two U-turns per strip and a quarter turn at the rook between the two strips, at most
//! 10 turns. Where a strip ends at the rook, or has one pixel, the walk simply has fewer turns.
//!
//! # Guarantee
//! Cycle cover: ≤ 10r ≤ 10·OPT turns (ρ + 2δ = 2 + 8 in Theorem 5.1); tour: ≤ 10r + 2(r − 1)
//! ≤ 12·OPT turns (Corollary 5.2), with the merge's +2 per merge as
//! [`merge`](super::merge) states it (asserted on every tested instance, as there).
//!
//! Coverage and length (Theorem 5.1 and Corollary 5.2: coverage μ = 4, length δ = 4), proven
//! for our construction, cycle cover and tour:
//! - *Cycle cover.* A pixel lies in at most one rook's row strip and one rook's column strip
//!   (rooks attack no one another). A star walk visits each pixel of each of its strips at
//!   most twice (out and back; the strip's far ends once, the rook twice per strip), so each
//!   axis of a pixel contributes at most 2 visits: coverage ≤ 4.
//! - *Tour.* Exchanges keep every pixel's visits; a detour adds one visit at each of two
//!   adjacent pixels p, q and is taken only when both are *settled* (all their visits already
//!   in one merged cycle) and in different merged cycles (see [`merge`](super::merge)). Then
//!   the strip through p and q holds no rook: a rook there would put p's and q's visits on its
//!   star, in one cycle. So p's visits along that axis are 0 before merging, and the axis gets
//!   at most one detour per neighbour (after it p and q are settled in one cycle for good): at
//!   most 2 visits per axis again, coverage ≤ 4. A merge never gets stuck: two merged cycles
//!   sharing a pixel can always be spliced there, and when no two share one every pixel is
//!   settled, so adjacent cycles can take a detour.
//! - *Length.* A closed walk of m ≥ 2 positions has m moves, a one-pixel walk none: length ≤
//!   total visits ≤ 4N, and N ≤ OPT_length for N ≥ 2 (OPT_length = 0 = our length for N = 1),
//!   so length ≤ 4N ≤ 4·OPT_length (registered against N, the stronger form).
//!
//! The paper gives no argument for coverage after merging (Theorem 4.2's merge "extends the
//! end links", which adds visits); ours is the settled-pixel rule above. Before it, the smart
//! merge took detours between unsettled pixels and reached coverage 5 (random-simple 10^6 seed
//! 1; a 123-pixel cut-out is the regression test in `tests/guarantees.rs`).

use crate::error::Result;
use crate::merge::cover_and_tour;
use crate::region::{Dir, Pixel, Region};
use crate::tour::{CycleCover, Walk};
use crate::walks::{close_walk, extend_walk, straight};
use crate::{Algorithm, GreedyOrder, Guarantee, Objective, Options, Solution};
use std::collections::BTreeMap;

/// The greedy rook placement of Lemma 4.5: rooks in the scan `order` (pixel index order by
/// default; the paper fixes no order, see [`GreedyOrder`]), none attacking another.
///
/// # Returns
/// The rooks in pixel index order, whatever the scan order.
///
/// # Complexity
/// O(N) time and space.
pub(crate) fn greedy_rooks(region: &Region, order: &GreedyOrder) -> Vec<usize> {
    let n = region.len();
    // Strip ids: a pixel takes the id of its west (south) neighbour, or a new one.
    let mut row = vec![0u32; n];
    let mut col = vec![0u32; n];
    let (mut rows, mut cols) = (0u32, 0u32);
    for i in 0..n {
        row[i] = match region.neighbor(i, Dir::W) {
            Some(j) => row[j],
            None => {
                rows += 1;
                rows - 1
            }
        };
        col[i] = match region.neighbor(i, Dir::S) {
            Some(j) => col[j],
            None => {
                cols += 1;
                cols - 1
            }
        };
    }
    let mut row_taken = vec![false; rows as usize];
    let mut col_taken = vec![false; cols as usize];
    let mut rooks = Vec::new();
    for i in order.permutation(n) {
        let i = i as usize;
        let (r, c) = (row[i] as usize, col[i] as usize);
        if !row_taken[r] && !col_taken[c] {
            row_taken[r] = true;
            col_taken[c] = true;
            rooks.push(i);
        }
    }
    rooks.sort_unstable();
    rooks
}

/// The last pixel reached from `i` going straight in direction `d`.
fn far_end(region: &Region, mut i: usize, d: Dir) -> Pixel {
    while let Some(j) = region.neighbor(i, d) {
        i = j;
    }
    region.pixel(i)
}

/// The closed walk touring the star of the rook at pixel `i` (at most 10 turns).
pub(crate) fn star_walk(region: &Region, i: usize) -> Walk {
    let rook = region.pixel(i);
    let (e, w) = (far_end(region, i, Dir::E), far_end(region, i, Dir::W));
    let (n, s) = (far_end(region, i, Dir::N), far_end(region, i, Dir::S));
    let mut walk = Vec::new();
    for (a, b) in [(rook, e), (e, w), (w, rook), (rook, n), (n, s), (s, rook)] {
        extend_walk(&mut walk, straight(a, b));
    }
    close_walk(walk)
}

/// The star cycle cover: one walk per greedy rook, and the number of rooks r.
pub(crate) fn star_cycle_cover(region: &Region, order: &GreedyOrder) -> (CycleCover, usize) {
    let rooks = greedy_rooks(region, order);
    (
        CycleCover::new(rooks.iter().map(|&i| star_walk(region, i)).collect()),
        rooks.len(),
    )
}

/// Runs `star-cover`: the star cycle cover and its merged tour, certificate `rooks` = r.
pub(crate) fn run(region: &Region, opts: &Options) -> Result<Solution> {
    let (cover, r) = star_cycle_cover(region, &opts.greedy_order);
    let mut certificates = BTreeMap::new();
    certificates.insert("rooks".to_string(), r as i64);
    cover_and_tour(region, cover, opts, certificates)
}

/// The registry entry of `star-cover`: a greedy rook placement, one walk of at most 10 turns
/// per star, merged ([`run`]).
///
/// # Guarantee
///
/// With r rooks ≤ the minimum strip cover ≤ OPT (Lemmas 4.3–4.5 of *Optimal covering tours with
/// turn costs*): the cycle cover has ≤ 10r ≤ 10·OPT turns (Theorem 5.1), the merged tour
/// ≤ 10r + 2(r − 1) ≤ 12·OPT (Corollary 5.2); both cover every pixel at most 4 times and have
/// length ≤ 4N (Theorem 5.1, Corollary 5.2; proven for our merge in the module docs, since
/// detours run only between settled pixels). Registered as `cc-turns <= 10 OPT`,
/// `turns <= 12 OPT`, and `max-coverage <= 4` and `length <= 4 N` on both objectives, on every
/// connected region.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "##..\n",
///     "##..\n",
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("star-cover").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 16);
/// assert_eq!(value(Objective::Turns), 16);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "star-cover",
    summary: "greedy rook placement, one 10-turn walk per star, merged (linear time; each pixel covered at most 4 times)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        Guarantee::vs_opt(
            Objective::CcTurns,
            10,
            1,
            &crate::theorems::TURNS_THM_5_1,
            "Theorem 5.1 / Corollary 5.2 of Optimal covering tours with turn costs",
        ),
        Guarantee::vs_opt(
            Objective::Turns,
            12,
            1,
            &crate::theorems::TURNS_COR_5_2,
            "Corollary 5.2 of Optimal covering tours with turn costs",
        ),
        Guarantee::max_coverage(
            Objective::CcTurns,
            4,
            &crate::theorems::TURNS_THM_5_1,
            "Theorem 5.1 (coverage mu = 4) of Optimal covering tours with turn costs",
        ),
        Guarantee::length_vs_n(
            Objective::CcTurns,
            4,
            &crate::theorems::TURNS_THM_5_1,
            "Theorem 5.1 (length delta = 4; N <= OPT length) of Optimal covering tours with turn costs",
        ),
        Guarantee::max_coverage(
            Objective::Turns,
            4,
            &crate::theorems::TURNS_COR_5_2_COVERAGE,
            "Corollary 5.2 (coverage) of Optimal covering tours with turn costs",
        ),
        Guarantee::length_vs_n(
            Objective::Turns,
            4,
            &crate::theorems::TURNS_COR_5_2_LENGTH,
            "Corollary 5.2 (length; N <= OPT length) of Optimal covering tours with turn costs",
        ),
    ],
    claims: crate::theorems::merged_tour_claims![
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_THM_5_1,
            &[crate::Objective::CcTurns],
        ),
        crate::theorems::Claim::paper(&crate::theorems::TURNS_COR_5_2, &[crate::Objective::Turns],),
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_COR_5_2_COVERAGE,
            &[crate::Objective::Turns, crate::Objective::CcTurns,],
        ),
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_COR_5_2_LENGTH,
            &[crate::Objective::Turns],
        ),
    ],
    requires: "a connected region",
    precondition: crate::precondition::connected,
    run,
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};

    #[test]
    fn plus_is_one_star_of_ten_turns() {
        let r = Region::from_ascii(".#.\n###\n.#.\n");
        // Rooks in index order: (1, 0) takes the column and its one-pixel row, then (0, 1)
        // takes the middle row (the minimum strip cover is 2 as well).
        let (cover, rooks) = star_cycle_cover(&r, &GreedyOrder::Index);
        let rep = check(&r, &cover, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!(rooks, 2);
        assert!(rep.turns <= 10 * rooks as u64);
        assert!(rep.max_coverage <= 4);
    }

    #[test]
    fn full_star_has_ten_turns() {
        let r = Region::from_ascii(".#.\n###\n.#.\n");
        let rep = check(&r, &CycleCover::tour(star_walk(&r, 2)), Mode::Milling);
        assert!(rep.valid);
        assert_eq!((rep.turns, rep.max_coverage), (10, 4));
    }
}
