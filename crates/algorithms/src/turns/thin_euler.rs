//! `thin-euler`: milling a thin Eulerian pocket (Theorem 5.8 of *Optimal covering tours with
//! turn costs*): a thin region whose grid graph has only even degrees (2 or 4), so that it can
//! be milled traversing every edge exactly once.
//!
//! # Construction (the abstract gives only the statement; this is our reading)
//! An Euler tour is fixed by how it pairs the four edges at every crossing (degree-4 pixel):
//! straight through both ways (0 turns), or turning twice (1 + 1 turns); at a degree-2 pixel
//! the turn is forced. Pairing every crossing straight decomposes the edges into c closed
//! walks with the fewest turns t of any edge-once cover. Re-pairing a crossing of two
//! different walks joins them and costs 2 turns; doing so along a spanning tree of the
//! walks' crossing graph gives a tour with t + 2(c − 1) turns, the fewest of any Euler tour
//! (every tour through all edges re-pairs at least c − 1 crossings). In linear time: the
//! straight decomposition is a walk over the edges, the joins are
//! [`merge_cycles`](super::merge::merge_cycles) at crossings.
//!
//! # Guarantee
//! At most 6/5·OPT turns (Theorem 5.8; OPT over all milling tours, which need not traverse
//! every edge once). The tests check it against the exact optimum on small Eulerian pockets.

use crate::checker::{Mode, check};
use crate::error::{Error, Result};
use crate::merge::merge_cycles;
use crate::precondition::connected;
use crate::region::{Dir, Region};
use crate::topology::is_thin;
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Merge, Objective, Options, Output, Solution};

/// Precondition: connected, thin, and every pixel of even degree (or a single pixel).
pub(crate) fn precondition(region: &Region) -> Result<()> {
    connected(region)?;
    if !is_thin(region) {
        return Err(Error::precondition(
            "the region is not thin: it contains a 2x2 block of pixels",
        ));
    }
    if region.len() > 1
        && let Some(i) = (0..region.len()).find(|&i| region.degree(i) % 2 == 1)
    {
        return Err(Error::precondition(format!(
            "the region is not Eulerian: pixel {} has {} neighbours",
            region.pixel(i),
            region.degree(i)
        )));
    }
    Ok(())
}

/// The straight decomposition: every edge once, straight through every crossing.
///
/// # Complexity
/// O(N).
pub(crate) fn straight_decomposition(region: &Region) -> CycleCover {
    if region.len() == 1 {
        return CycleCover::tour(vec![region.pixel(0)]);
    }
    // used[4i + d]: the edge leaving pixel i in direction d has been walked.
    let mut used = vec![false; 4 * region.len()];
    let mut cycles = Vec::new();
    for start in 0..region.len() {
        for d0 in Dir::ALL {
            if used[4 * start + d0.index()] || region.neighbor(start, d0).is_none() {
                continue;
            }
            let mut walk = Vec::new();
            let (mut i, mut d) = (start, d0);
            loop {
                walk.push(region.pixel(i));
                let j = region.neighbor(i, d).expect("walks follow edges");
                used[4 * i + d.index()] = true;
                used[4 * j + d.opposite().index()] = true;
                i = j;
                // Straight on at a crossing; the only other edge at a degree-2 pixel.
                d = if region.degree(i) == 4 {
                    d
                } else {
                    Dir::ALL
                        .into_iter()
                        .find(|&e| e != d.opposite() && region.neighbor(i, e).is_some())
                        .expect("even degree")
                };
                if i == start && d == d0 {
                    break;
                }
            }
            cycles.push(walk);
        }
    }
    CycleCover::new(cycles)
}

/// Runs `thin-euler`: the straight decomposition (objective `cc-turns`, no guarantee of its
/// own) and the Euler tour joined at crossings (objective `turns`), rewritten by
/// [`coverage4`](crate::coverage4) under `--coverage4` (certificate
/// `coverage4_stuck`, as for the merged tours of [`cover_and_tour`](super::merge::cover_and_tour)).
pub(crate) fn run(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    let cover = straight_decomposition(region);
    let (mut tour, stats) = merge_cycles(region, &cover, Merge::Naive);
    let mut sol = Solution::default();
    if opts.coverage4 {
        let (rewritten, stuck) = crate::coverage4::coverage4(region, &tour);
        tour = rewritten;
        sol.certificates
            .insert("coverage4_stuck".to_string(), stuck as i64);
    }
    let before = check(region, &cover, Mode::Milling);
    sol.certificates
        .insert("cc_cycles".to_string(), before.cycles as i64);
    sol.certificates
        .insert("cc_turns".to_string(), before.turns as i64);
    sol.certificates
        .insert("merges".to_string(), stats.merges as i64);
    sol.outputs.push(Output {
        objective: Objective::CcTurns,
        cover,
    });
    sol.outputs.push(Output {
        objective: Objective::Turns,
        cover: tour,
    });
    Ok(sol)
}

/// The registry entry of `thin-euler`: the straight-through Euler decomposition of a thin
/// Eulerian pocket, joined at crossings ([`run`]).
///
/// # Guarantee
///
/// On a connected thin region whose pixels all have even degree the tour has at most 6/5·OPT
/// turns (Theorem 5.8 of *Optimal covering tours with turn costs*; OPT over all milling tours,
/// which need not traverse every edge once; our reading of the construction in the module
/// docs). Registered as `turns <= 6/5 OPT` (Theorem 5.8); the cycle cover it also reports
/// (`cc-turns`) has no registered bound.
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
/// let algorithm = algorithms::find("thin-euler").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 4);
/// assert_eq!(value(Objective::Turns), 4);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "thin-euler",
    summary: "thin Eulerian pocket: straight-through Euler decomposition joined at crossings (+2 turns each)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[Guarantee::vs_opt(
        Objective::Turns,
        6,
        5,
        &crate::theorems::TURNS_THM_5_8,
        "Theorem 5.8 of Optimal covering tours with turn costs",
    )],
    // The paper states Theorem 5.8 without its algorithm (the full version [4] has it): the
    // straight-through Euler decomposition joined at crossings is our construction.
    claims: &[crate::theorems::Claim::reading(
        &crate::theorems::TURNS_THM_5_8,
        &[crate::Objective::Turns],
        "the paper gives no algorithm for Theorem 5.8 (it is in the full version [4]); the straight-through Euler decomposition joined at crossings is our construction",
    )],
    requires: "a connected thin region whose pixels all have even degree",
    precondition,
    run,
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_eight_of_two_rings() {
        // Two width-1 square rings crossing at two pixels.
        let r = Region::from_ascii(
            "..#####\n\
             ..#...#\n\
             #####.#\n\
             #.#.#.#\n\
             #.#####\n\
             #...#..\n\
             #####..\n",
        );
        precondition(&r).unwrap();
        let cover = straight_decomposition(&r);
        let cc = check(&r, &cover, Mode::Milling);
        assert!(cc.valid, "{:?}", cc.error);
        assert_eq!((cc.cycles, cc.turns), (2, 8));
        let sol = run(&r, &Options::default()).unwrap();
        let tour = check(&r, &sol.outputs[1].cover, Mode::Milling);
        assert!(tour.valid && tour.cycles == 1);
        assert_eq!(tour.turns, 10);
        assert!(precondition(&Region::rectangle(3, 1)).is_err());
    }
}
