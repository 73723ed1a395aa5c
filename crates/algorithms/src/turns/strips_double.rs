//! `strips-double`: an optimal strip cover, each strip doubled into a closed walk with two
//! U-turns, then merged (Theorem 5.4 of *Optimal covering tours with turn costs*).
//!
//! # Guarantee
//! The cycle cover has 4s ≤ 4·OPT turns in s cycles (s = minimum strip cover size ≤ OPT,
//! Lemma 4.2); merging adds at most 2 per merge (Theorem 4.2, as [`merge`](super::merge)
//! states it): at most 6s − 2 ≤ 6·OPT turns.
//!
//! Coverage ≤ 4 and length ≤ 4N ≤ 4·OPT_length (Theorem 5.4), cycle cover and tour, proven
//! for our construction by counting visits per axis of a pixel p (at most 2 each):
//! - p's strip along the axis is in the cover: its doubled walk visits p at most twice (a
//!   one-pixel strip once) and uses the edges to both neighbours along the axis.
//! - It is not: no doubled walk visits p along this axis. The merge turns a one-pixel walk
//!   [o] into [o, q] with q a neighbour of o (4 turns either way); o's strip along the other
//!   axis is a single pixel, so q lies along o's strip that is not in the cover (a minimum
//!   cover has no redundant strip), i.e. the extra visit lands on q's uncovered axis and uses
//!   the edge o–q. A detour adds one visit at p only across an edge p–q to a pixel of another
//!   merged cycle, both settled (see [`merge`](super::merge)), hence across an edge no input
//!   walk uses, at most once per such edge. So each of p's (at most 2) neighbours along the
//!   axis adds at most one visit.
//!
//! Length: a closed walk of m ≥ 2 positions has m moves (a one-pixel walk none), so length ≤
//! visits ≤ 4N, and N ≤ OPT_length for N ≥ 2 (N = 1: both are 0).

use crate::error::Result;
use crate::merge::cover_and_tour;
use crate::region::Region;
use crate::strip_cover::strip_cover;
use crate::topology::Strip;
use crate::tour::{CycleCover, Walk};
use crate::walks::{close_walk, extend_walk, straight};
use crate::{Algorithm, Guarantee, Objective, Options, Solution};
use std::collections::BTreeMap;

/// The doubled strip: out along the strip and back, two U-turns (one pixel: 4 turns too).
pub(crate) fn doubled(strip: &Strip) -> Walk {
    let (a, b) = (strip.start, strip.end());
    let mut walk = Vec::new();
    extend_walk(&mut walk, straight(a, b));
    extend_walk(&mut walk, straight(b, a));
    close_walk(walk)
}

/// The cycle cover of doubled strips of a minimum strip cover, and the cover's size s.
///
/// # Complexity
/// O(N √N) for the strip cover (Hopcroft–Karp), O(N) for the walks.
pub(crate) fn doubled_strip_cover(region: &Region) -> (CycleCover, usize) {
    let cover = strip_cover(region);
    (
        CycleCover::new(cover.strips.iter().map(doubled).collect()),
        cover.size(),
    )
}

/// Runs `strips-double`: the doubled-strip cycle cover and its merged tour.
pub(crate) fn run(region: &Region, opts: &Options) -> Result<Solution> {
    let (cover, s) = doubled_strip_cover(region);
    let mut certificates = BTreeMap::new();
    certificates.insert("s".to_string(), s as i64);
    cover_and_tour(region, cover, opts, certificates)
}

/// The registry entry of `strips-double`: a minimum strip cover, each strip doubled into a
/// closed walk with two U-turns, merged ([`run`]).
///
/// # Guarantee
///
/// The cycle cover has 4s ≤ 4·OPT turns (s = the minimum strip cover size ≤ OPT, Lemma 4.2 of
/// *Optimal covering tours with turn costs*), the merged tour at most 6s − 2 ≤ 6·OPT
/// (Theorem 5.4, with +2 per merge as Theorem 4.2 states it); both cover every pixel at most 4
/// times and have length ≤ 4N (Theorem 5.4, proven for our construction in the module docs).
/// Registered as `cc-turns <= 4 OPT`, `turns <= 6 OPT`, and `max-coverage <= 4` and
/// `length <= 4 N` on both objectives, on every connected region.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "####\n",
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("strips-double").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 12);
/// assert_eq!(value(Objective::Turns), 12);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "strips-double",
    summary: "minimum strip cover, each strip doubled with two U-turns, merged (also at most 4x the optimal length)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        Guarantee::vs_opt(
            Objective::CcTurns,
            4,
            1,
            &crate::theorems::TURNS_THM_5_4,
            "Theorem 5.4 of Optimal covering tours with turn costs (4 turns per strip, Lemma 4.2)",
        ),
        Guarantee::vs_opt(
            Objective::Turns,
            6,
            1,
            &crate::theorems::TURNS_THM_5_4,
            "Theorem 5.4 of Optimal covering tours with turn costs",
        ),
        Guarantee::max_coverage(
            Objective::CcTurns,
            4,
            &crate::theorems::TURNS_THM_5_4,
            "Theorem 5.4 (its cycle cover: two visits per strip) of Optimal covering tours with turn costs",
        ),
        Guarantee::length_vs_n(
            Objective::CcTurns,
            4,
            &crate::theorems::TURNS_THM_5_4_LENGTH,
            "Theorem 5.4 (its cycle cover; N <= OPT length) of Optimal covering tours with turn costs",
        ),
        Guarantee::max_coverage(
            Objective::Turns,
            4,
            &crate::theorems::TURNS_THM_5_4,
            "Theorem 5.4 (coverage, our merge) of Optimal covering tours with turn costs",
        ),
        Guarantee::length_vs_n(
            Objective::Turns,
            4,
            &crate::theorems::TURNS_THM_5_4_LENGTH,
            "Theorem 5.4 (length; N <= OPT length) of Optimal covering tours with turn costs",
        ),
    ],
    claims: crate::theorems::merged_tour_claims![
        crate::theorems::Claim::paper(&crate::theorems::TURNS_THM_5_4, &[crate::Objective::Turns],),
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_THM_5_4_LENGTH,
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
    fn rectangle_3x5() {
        let r = Region::rectangle(5, 3);
        let (cover, s) = doubled_strip_cover(&r);
        assert_eq!(s, 3);
        let rep = check(&r, &cover, Mode::Milling);
        assert!(rep.valid);
        assert_eq!((rep.turns, rep.cycles, rep.max_coverage), (12, 3, 2));
        let sol = run(&r, &Options::default()).unwrap();
        let tour = &sol.outputs[1].cover;
        let rep = check(&r, tour, Mode::Milling);
        assert!(rep.valid && tour.is_tour());
        assert!(rep.turns <= 6 * 3 - 2, "{}", rep.turns);
    }
}
