//! Thin pockets (Section 5.5 of *Optimal covering tours with turn costs*): `thin-cc`, an
//! optimal min-turn cycle cover (Corollary 5.3), and `thin-merge`, the merging algorithm of
//! Theorem 5.9. A thin region has no 2×2 block of pixels.
//!
//! # thin-cc
//! In a thin region every pixel is a boundary pixel except the centres of plus shapes (a pixel
//! with four neighbours and no diagonal one). The boundary cycle cover
//! ([`boundary_cc`](super::boundary_cc)) is optimal for the boundary; Corollary 5.3 says it
//! can be turned into a cover of the whole region. Our construction of that step: each arm
//! pixel q next to an uncovered centre c has no neighbour but c and the rest of its arm, so a
//! walk visiting q either passes into c or turns back at q having arrived heading towards c;
//! there we insert the step into c and back, moving the U-turn from q to c (same turns).
//!
//! Why the result is optimal: every cycle cover of the region covers its boundary pixels, so it
//! has at least as many turns as the boundary cover, which is minimum when its matching is
//! (`matching_optimal = 1`; the proof, and the one-pixel links it needs left out, are in the
//! module docs of [`boundary_cc`](super::boundary_cc)); the insertions add no turn. So
//! `matching_optimal = 1` with `centre_fallbacks = 0` proves the cover a minimum-turn cycle
//! cover; a fallback detour (never seen: the tests assert 0) would void that proof.
//!
//! # thin-merge
//! Step 1 is thin-cc; step 2 repeats (a) a merge of two cycles at no extra cost when one
//! exists, else (c) a merge at a crossing with at most two more turns: this is the smart
//! strategy of [`merge`](super::merge) (cheapest merge first, free merges being the cheapest),
//! which thin-merge always uses, whatever `--merge` says.
//!
//! # Guarantee
//! thin-cc: the cycle cover is optimal (Corollary 5.3), its merged tour at most 3/2·OPT
//! (Corollary 4.1). thin-merge: at most 4/3·OPT turns (Theorem 5.9, tight by Fig. 6).

use crate::boundary_cc::boundary_cycle_cover;
use crate::error::{Error, Result};
use crate::matching::PortMatching;
use crate::merge::cover_and_tour;
use crate::region::Region;
use crate::topology::{components, is_thin};
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Merge, Objective, Options, Solution};
use std::collections::BTreeMap;

/// Precondition of the thin algorithms: thin (no 2×2 block) and connected. The cycle cover
/// alone would not need connectivity, but both algorithms also output the tour merged from it
/// (Corollary 5.3 and Theorem 5.9), which cannot leave a component: we refuse rather than
/// report a "tour" of several walks (`boundary-cc` gives the cycle cover of each component of
/// a thin region without plus centres).
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::precondition("the region is empty"));
    }
    if !is_thin(region) {
        return Err(Error::precondition(
            "the region is not thin: it contains a 2x2 block of pixels",
        ));
    }
    match components(region).count {
        1 => Ok(()),
        c => Err(Error::precondition(format!(
            "the region has {c} connected components, and thin-cc and thin-merge also output \
             a tour merged from their cycle cover, which cannot leave a component"
        ))),
    }
}

/// Inserts a step into every unvisited pixel `c` from a neighbour `q` where a walk turns back
/// heading towards `c`. Returns the number of pixels that could not be reached that way (each
/// then gets a plain detour, costing extra turns).
fn cover_plus_centres(region: &Region, cover: &mut CycleCover) -> usize {
    let mut visited = vec![false; region.len()];
    for p in cover.cycles.iter().flatten() {
        if let Some(i) = region.index_of(*p) {
            visited[i] = true;
        }
    }
    let mut fallbacks = 0;
    for (c, seen) in visited.iter_mut().enumerate() {
        if *seen {
            continue;
        }
        let cp = region.pixel(c);
        let mut done = false;
        'search: for walk in &mut cover.cycles {
            let m = walk.len();
            for i in 0..m {
                let (before, q, after) = (walk[(i + m - 1) % m], walk[i], walk[(i + 1) % m]);
                let towards = before.dir_to(q);
                if m >= 2 && before == after && towards.is_some() && towards == q.dir_to(cp) {
                    walk.splice(i + 1..i + 1, [cp, q]);
                    done = true;
                    break 'search;
                }
            }
        }
        if !done {
            // Not expected in a thin region (see the module docs); keep the cover valid.
            let q = region
                .neighbors(c)
                .map(|j| region.pixel(j))
                .find(|p| cover.cycles.iter().any(|w| w.contains(p)));
            if let Some(q) = q {
                for walk in &mut cover.cycles {
                    if let Some(i) = walk.iter().position(|p| *p == q) {
                        walk.splice(i + 1..i + 1, [cp, q]);
                        break;
                    }
                }
            }
            fallbacks += 1;
        }
        *seen = true;
    }
    fallbacks
}

/// The optimal cycle cover of a thin region (Corollary 5.3), the boundary matching it rests
/// on, and how many pixels needed the fallback detour (0 whenever the construction of the
/// module docs applies).
pub(crate) fn thin_cycle_cover(region: &Region) -> Result<(CycleCover, PortMatching, usize)> {
    let (mut cover, matching) = boundary_cycle_cover(region)?;
    let fallbacks = cover_plus_centres(region, &mut cover);
    Ok((cover, matching, fallbacks))
}

fn run_with(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    let (cover, matching, fallbacks) = thin_cycle_cover(region)?;
    let mut certificates: BTreeMap<String, i64> = matching.certificates().collect();
    certificates.insert("w_m".to_string(), matching.total as i64);
    certificates.insert("centre_fallbacks".to_string(), fallbacks as i64);
    cover_and_tour(region, cover, opts, certificates)
}

/// Runs `thin-cc`: the optimal cycle cover and its tour merged by `--merge`.
pub(crate) fn run_cc(region: &Region, opts: &Options) -> Result<Solution> {
    run_with(region, opts)
}

/// Runs `thin-merge`: the optimal cycle cover merged by Theorem 5.9's algorithm.
pub(crate) fn run_merge(region: &Region, opts: &Options) -> Result<Solution> {
    run_with(
        region,
        &Options {
            merge: Merge::Smart,
            ..opts.clone()
        },
    )
}

/// The guarantee of the cycle cover both thin entries build (the same optimal cover).
const CYCLE_COVER_GUARANTEE: Guarantee = Guarantee::vs_opt(
    Objective::CcTurns,
    1,
    1,
    &crate::theorems::TURNS_COR_5_3,
    "Corollary 5.3 of Optimal covering tours with turn costs",
);

/// The claim of the cycle cover both thin entries build, written once.
const CYCLE_COVER_CLAIM: crate::theorems::Claim = crate::theorems::Claim::reading(
    &crate::theorems::TURNS_COR_5_3,
    &[crate::Objective::CcTurns],
    "boundary cover of the thin pocket plus centres inserted (module docs of thin)",
);

/// The registry entry of `thin-cc`: the optimal cycle cover of a thin pocket, merged into a tour
/// by `--merge` ([`run_cc`]).
///
/// # Guarantee
///
/// A thin region has no 2 × 2 block of pixels. The boundary cycle cover with the plus centres
/// inserted is an optimal cycle cover (Corollary 5.3 of *Optimal covering tours with turn
/// costs*; our construction of the insertion step in the module docs). Merging adds at most half of it (Corollary 4.1). Registered as
/// `cc-turns <= OPT` (Corollary 5.3, our reading) and `turns <= 3/2 OPT` (Corollary 5.3, tour)
/// on every connected thin region.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "###\n",
///     "#.#\n",
///     "###\n",
/// ));
/// let algorithm = algorithms::find("thin-cc").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 4);
/// assert_eq!(value(Objective::Turns), 4);
/// ```
pub(crate) const ALGORITHM_CC: Algorithm = Algorithm {
    name: "thin-cc",
    summary: "optimal min-turn cycle cover of a thin pocket (boundary links matched, plus centres inserted), merged by --merge",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        CYCLE_COVER_GUARANTEE,
        Guarantee::vs_opt(
            Objective::Turns,
            3,
            2,
            &crate::theorems::TURNS_COR_5_3_TOUR,
            "Corollary 5.3 of Optimal covering tours with turn costs",
        ),
    ],
    claims: crate::theorems::merged_tour_claims![
        CYCLE_COVER_CLAIM,
        crate::theorems::Claim::paper(
            &crate::theorems::TURNS_COR_5_3_TOUR,
            &[crate::Objective::Turns],
        ),
        crate::theorems::COVERAGE4_CLAIMS[0],
        crate::theorems::COVERAGE4_CLAIMS[1],
    ],
    requires: "a connected thin region (no 2x2 block)",
    precondition,
    run: run_cc,
    discrete: None,
    ortho: None,
    by_default: true,
};

/// The registry entry of `thin-merge`: the optimal cycle cover of a thin pocket, merged free
/// merges first, then at crossings ([`run_merge`]).
///
/// # Guarantee
///
/// A thin region has no 2 × 2 block of pixels. The boundary cycle cover with the plus centres
/// inserted is an optimal cycle cover (Corollary 5.3 of *Optimal covering tours with turn
/// costs*; our construction of the insertion step in the module docs). Merging it this way gives a tour of at most 4/3·OPT turns
/// (Theorem 5.9, tight by Fig. 6). Registered as `cc-turns <= OPT` (Corollary 5.3, our reading)
/// and `turns <= 4/3 OPT` (Theorem 5.9) on every connected thin region.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "###\n",
///     "#.#\n",
///     "###\n",
/// ));
/// let algorithm = algorithms::find("thin-merge").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 4);
/// assert_eq!(value(Objective::Turns), 4);
/// ```
pub(crate) const ALGORITHM_MERGE: Algorithm = Algorithm {
    name: "thin-merge",
    summary: "optimal cycle cover of a thin pocket merged free merges first, then at crossings",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        CYCLE_COVER_GUARANTEE,
        Guarantee::vs_opt(
            Objective::Turns,
            4,
            3,
            &crate::theorems::TURNS_THM_5_9,
            "Theorem 5.9 of Optimal covering tours with turn costs",
        ),
    ],
    claims: crate::theorems::merged_tour_claims![
        CYCLE_COVER_CLAIM,
        crate::theorems::Claim::paper(&crate::theorems::TURNS_THM_5_9, &[crate::Objective::Turns],),
        crate::theorems::COVERAGE4_CLAIMS[0],
        crate::theorems::COVERAGE4_CLAIMS[1],
    ],
    requires: "a connected thin region (no 2x2 block)",
    precondition,
    run: run_merge,
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};

    #[test]
    fn plus_centre_is_covered_at_no_cost() {
        let r = Region::from_ascii(
            "..#..\n\
             ..#..\n\
             #####\n\
             ..#..\n\
             ..#..\n",
        );
        let (cover, _, fallbacks) = thin_cycle_cover(&r).unwrap();
        let rep = check(&r, &cover, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!(fallbacks, 0);
        // Two crossing corridors, each out and back: 8 turns.
        assert_eq!(rep.turns, 8);
    }

    #[test]
    fn refuses_thick_regions() {
        let e = precondition(&Region::rectangle(2, 2)).unwrap_err();
        assert!(e.to_string().contains("not thin"), "{e}");
    }
}
