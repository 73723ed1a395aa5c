//! `strips-matching`: an optimal strip cover whose strip ends are joined by a minimum-weight
//! perfect matching under the turn distance (Theorem 5.5 of *Optimal covering tours with turn
//! costs*), then merged into a tour (Corollary 4.1).
//!
//! # Construction
//! Each strip of a minimum strip cover S (|S| = s) contributes its two end pixels as ports
//! leaving orthogonally to the strip. A minimum-weight perfect matching M of the 2s ports
//! under the turn distance w ([`turn_distance`](crate::turn_distance)) together with the
//! strips forms a 2-regular structure, i.e. cycles alternating strip, connecting path, strip,
//! and so on. Each strip costs at most 2 turns (turning off it at one end, onto it at the
//! other), each connecting path w(u, v) turns: the cycle cover has at most 2s + w(M) turns.
//!
//! A one-pixel strip whose two ends are matched to each other would close a walk that never
//! moves (4 turns by the checker's convention, 2 + 0 in this count): we price that pair at 2,
//! our choice for a case the paper does not discuss, which keeps the count an upper bound.
//!
//! # Guarantee
//! Cycle cover: 2s + w(M) ≤ 2.5·OPT_cc, since s ≤ OPT (Lemma 4.2) and w(M) ≤ OPT/2 (every
//! tour crosses each strip end orthogonally; Theorem 5.5). Tour: ≤ 3/2 of that, 3.75·OPT
//! (Corollary 4.1). The bound on w(M) needs M to be a minimum matching over all pairs: it is
//! proven so when `matching_optimal = 1` (always up to
//! `COMPLETE_LIMIT` ports, where the candidate
//! graph is complete; beyond, when the matching reaches the LP bound). Otherwise
//! `matching_lower_bound` is a proven lower bound on the minimum, and the guarantee holds
//! with w(M) − `matching_lower_bound` added; see [`endpoint_matching`](crate::endpoint_matching).

use crate::error::Result;
use crate::matching::turn_distance::Port;
use crate::matching::{PortMatching, join_links, match_ports};
use crate::merge::cover_and_tour;
use crate::region::Region;
use crate::strip_cover::strip_cover;
use crate::topology::Strip;
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Objective, Options, Solution};
use std::collections::BTreeMap;

/// The cycle cover of Theorem 5.5, with s, w(M) and the matching.
#[derive(Clone, Debug)]
pub(crate) struct StripMatchingCover {
    pub(crate) cover: CycleCover,
    pub(crate) s: usize,
    pub(crate) matching: PortMatching,
}

/// The ports of strips: port `2k` at strip k's start, `2k + 1` at its end.
pub fn strip_ports(region: &Region, strips: &[Strip]) -> (Vec<(usize, usize)>, Vec<Port>) {
    let mut links = Vec::with_capacity(strips.len());
    let mut ports = Vec::with_capacity(2 * strips.len());
    for s in strips {
        let a = region.index_of(s.start).expect("strips lie in the region");
        let b = region.index_of(s.end()).expect("strips lie in the region");
        links.push((a, b));
        ports.push(Port::strip_end(a, s.horizontal));
        ports.push(Port::strip_end(b, s.horizontal));
    }
    (links, ports)
}

/// The least turn distance of every strip end to its partner (the other end of its strip): a
/// one-pixel strip closed on itself is a still walk of 4 turns, 2 for the strip and 2 here.
pub fn strip_floors(links: &[(usize, usize)]) -> Vec<u32> {
    (0..2 * links.len())
        .map(|i| {
            if links[i / 2].0 == links[i / 2].1 {
                2
            } else {
                0
            }
        })
        .collect()
}

/// Computes the strips-matching cycle cover of Theorem 5.5.
///
/// # Complexity
/// O(N √N) for the strip cover; the matching dominates (see
/// [`match_ports`](crate::endpoint_matching::match_ports)).
pub(crate) fn strips_matching_cover(region: &Region) -> Result<StripMatchingCover> {
    matched_strips(region, &strip_cover(region).strips)
}

/// Any strips covering the region joined by a minimum-weight perfect matching of their ends
/// under the turn distance (the construction above, for a strip cover that need not be
/// minimum: `lp-lns` rounds its LP to one).
pub(crate) fn matched_strips(region: &Region, strips: &[Strip]) -> Result<StripMatchingCover> {
    let (links, ports) = strip_ports(region, strips);
    let partner: Vec<usize> = (0..ports.len()).map(|i| i ^ 1).collect();
    let floor = strip_floors(&links);
    let matching = match_ports(region, &ports, &partner, &floor)?;
    let cc = join_links(region, &links, &ports, &matching)?;
    Ok(StripMatchingCover {
        cover: cc,
        s: strips.len(),
        matching,
    })
}

/// Runs `strips-matching`: the cycle cover and its merged tour, with certificates s, w(M)
/// (`w_m`), `matching_complete` (complete candidate graph), `matching_optimal` (w(M) proven
/// minimum over all pairs), `matching_lower_bound` (proven) and `matching_candidates`.
pub(crate) fn run(region: &Region, opts: &Options) -> Result<Solution> {
    let smc = strips_matching_cover(region)?;
    let mut certificates = BTreeMap::new();
    certificates.insert("s".to_string(), smc.s as i64);
    certificates.insert("w_m".to_string(), smc.matching.total as i64);
    certificates.extend(smc.matching.certificates());
    cover_and_tour(region, smc.cover, opts, certificates)
}

/// The registry entry of `strips-matching`: a minimum strip cover joined by a minimum-weight
/// perfect matching of the strip ends under the turn distance, merged ([`run`]).
///
/// # Guarantee
///
/// The cycle cover has 2s + w(M) ≤ 5/2·OPT turns, since s ≤ OPT (Lemma 4.2) and w(M) ≤ OPT/2
/// (Theorem 5.5 of *Optimal covering tours with turn costs*); the merged tour at most 3/2 of
/// that, 15/4·OPT (Corollary 4.1). The bound on w(M) needs a matching proven minimum
/// (`matching_optimal = 1`, module docs). Registered as `cc-turns <= 5/2 OPT` (Theorem 5.5)
/// and `turns <= 15/4 OPT` (Theorem 5.5, tour) on every connected region.
///
/// No coverage or length bound is registered: the paper notes that this algorithm gives no immediate length bound (Fig. 5), and Table 1's 4 and 4 for integral
/// orthogonal milling come from the Theorem 5.6 rewrite (`--coverage4`), not from the
/// algorithm (its tours reach coverage 8 on random regions: `examples/coverage_search.rs`).
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
/// let algorithm = algorithms::find("strips-matching").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 8);
/// assert_eq!(value(Objective::Turns), 8);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "strips-matching",
    summary: "minimum strip cover joined by a minimum-weight perfect matching of strip ends under turn distance, merged",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        Guarantee::vs_opt(
            Objective::CcTurns,
            5,
            2,
            &crate::theorems::TURNS_THM_5_5,
            "Theorem 5.5 of Optimal covering tours with turn costs",
        ),
        Guarantee::vs_opt(
            Objective::Turns,
            15,
            4,
            &crate::theorems::TURNS_THM_5_5_TOUR,
            "Theorem 5.5 and Corollary 4.1 of Optimal covering tours with turn costs",
        ),
    ],
    claims: crate::theorems::merged_tour_claims![
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_THM_5_5,
            &[crate::Objective::CcTurns],
        ),
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_THM_5_5_TOUR,
            &[crate::Objective::Turns],
        ),
        crate::theorems::COVERAGE4_CLAIMS[0],
        crate::theorems::COVERAGE4_CLAIMS[1],
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
    use crate::Merge;
    use crate::checker::{Mode, check};
    use crate::region::Pixel;

    /// The square donut of Fig. 5: outer side `l`, width `k`.
    fn donut(l: i32, k: i32) -> Region {
        Region::from_pixels(
            (0..l)
                .flat_map(|y| (0..l).map(move |x| Pixel::new(x, y)))
                .filter(|p| p.x < k || p.y < k || p.x >= l - k || p.y >= l - k),
        )
        .unwrap()
    }

    #[test]
    fn rectangle_cover_has_2s_plus_w_turns() {
        let r = Region::rectangle(6, 4);
        let smc = strips_matching_cover(&r).unwrap();
        assert_eq!(smc.s, 4);
        let rep = check(&r, &smc.cover, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert!(rep.turns <= 2 * smc.s as u64 + smc.matching.total);
        // The boustrophedon pairing: consecutive rows' ends face each other (w = 0).
        assert_eq!(smc.matching.total, 0);
        assert_eq!(rep.turns, 8);
    }

    #[test]
    fn donut_separates_naive_and_smart_merging() {
        for k in 1..=3 {
            let l = 3 * k + 2;
            let r = donut(l, k);
            let smc = strips_matching_cover(&r).unwrap();
            assert_eq!(smc.s, 4 * k as usize);
            let cc = check(&r, &smc.cover, Mode::Milling);
            assert!(cc.valid);
            eprintln!(
                "k {k}: cc turns {} cycles {} w {}",
                cc.turns, cc.cycles, smc.matching.total
            );
            let mut turns = Vec::new();
            for merge in [Merge::Naive, Merge::Smart] {
                let sol = run(
                    &r,
                    &Options {
                        merge,
                        ..Options::default()
                    },
                )
                .unwrap();
                let rep = check(&r, &sol.outputs[1].cover, Mode::Milling);
                assert!(rep.valid && rep.cycles == 1);
                turns.push(rep.turns);
            }
            eprintln!("k {k}: naive {} smart {}", turns[0], turns[1]);
        }
    }
}
