//! `lp-lns`: an LP-based heuristic for minimum-turn and weighted cycle covers and tours, in the
//! spirit of the LP-based approximation of the 2018 turn-cost study (solve the fractional
//! cycle-cover relaxation, round it, improve locally), built on the exact solver's passage
//! model and driver ([`mowmill_exact::ExactOptions::heuristic`]).
//!
//! # Construction
//! For each objective it reports (`cc-turns`, `turns`, and the study's `weighted-cc` and
//! `weighted` with turn cost C = 50):
//! 1. Solve the LP relaxation of the objective's passage model (with the connectivity cuts of
//!    the tour objectives) and read, per pixel, how much of its fractional passages runs
//!    horizontally and how much vertically ([`lp_orientation`]).
//! 2. Round it to a strip cover ([`lp_strips`]): the maximal strip through each pixel in each
//!    orientation carrying at least half of the pixel's passages, then the redundant strips
//!    dropped, lightest first.
//! 3. Join the strips' ends by a minimum-weight perfect matching under the turn distance (the
//!    matching of `strips-matching`, Theorem 5.5, on this cover instead of a minimum one) and,
//!    for the tour objectives, merge the cycles (Theorem 4.2's merging, smart).
//! 4. Large-neighbourhood search ([`mowmill_exact::ExactOptions::heuristic`]) from the cheapest
//!    of that walk, the walks already found for the objectives before it (in the order
//!    `cc-turns`, `turns`, `weighted-cc`, `weighted`: a weighted search from the turn-minimal
//!    tour took 9 s where its own rounding took 29 s, on the thesis's fc_1000_dense_1) and the
//!    exact model's own start (every strip of a minimum strip cover
//!    walked there and back, 4 turns per strip): every passage outside a breadth-first window
//!    of 100 to 200 pixels is fixed to the incumbent and a MIP re-optimises the window,
//!    windows centred in a scattered order until windows holding 2N pixels in all bring no
//!    improvement. A window that breaks a tour's connectivity is repaired by the model's
//!    merging moves. Every walk goes through the checker.
//!
//! 5. Each output then takes the cheapest walk, under its objective, of all the outputs it may
//!    use (a tour is a cycle cover; the weighted walks often have fewer turns).
//!
//! Options: `merge` chooses how step 3 merges the rounding's cycles; `coverage4` rewrites every
//! tour output by Theorem 5.6 at the end, as for the other tours.
//!
//! Every window's MIP stops after 200 branch-and-bound nodes, and the windows grow or shrink
//! by whether they were solved, not by the clock; a safety limit of [`SAFETY_SECONDS`] +
//! N / 100 s per objective ends a runaway search (and only then may the walk depend on the
//! machine). HiGHS runs on one thread.
//!
//! Choices where the study is open or differs: the study rounds fractional "atomic strips" and
//! connects them by a matching of neighbouring ends; we round to maximal strips and match their
//! ends under the turn distance, then search neighbourhoods, which the study does not do. The
//! weighted objectives use the study's C = 50 only (an algorithm's outputs do not know a
//! bench's other turn costs; those are measured on the `cc-turns` and `turns` outputs, as for
//! every algorithm).
//!
//! # Guarantee
//! Cycle cover: at most 4·OPT_cc turns. The exact model's start has 4s turns, s the size of a
//! minimum strip cover, and s ≤ OPT_cc (Lemma 4.2 of *Optimal covering tours with turn
//! costs*); the search starts from the cheapest of it and the other walks and replaces its
//! incumbent only by a cheaper checked one. Nothing is proven for the tour (merging may cost
//! turns no bound here controls) or for the weighted objectives.
//!
//! # Complexity
//! Not polynomial in the worst case (MIPs), bounded in practice by the node limits and the
//! stop rule; measured times are in docs/measured.md.

use crate::checker::{Mode, Report, check};
use crate::error::{Error, Result};
use crate::exact::{ExactOptions, lp_orientation, solve};
use crate::merge::merge_cycles;
use crate::region::Region;
use crate::strips_matching::matched_strips;
use crate::topology::{Strip, strips};
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Merge, Objective, Options, Output, Solution};

/// The turn cost of the weighted outputs: the 2018 study's C = 50.
pub const STUDY_TURN_COST: u32 = 50;

/// The safety time limit per objective, seconds (plus N / 100).
pub const SAFETY_SECONDS: f64 = 30.0;

const OBJECTIVES: &[Objective] = &[
    Objective::CcTurns,
    Objective::Turns,
    Objective::WeightedCc(STUDY_TURN_COST),
    Objective::Weighted(STUDY_TURN_COST),
];

/// The walk of `objective` by the construction above, the search started from the cheapest
/// of the rounding and the `earlier` walks it may use (checked; a tour objective only takes a
/// single closed walk).
pub fn lp_lns(
    region: &Region,
    objective: Objective,
    earlier: &[CycleCover],
    merge: Merge,
) -> Result<Output> {
    let limit = SAFETY_SECONDS + region.len() as f64 / 100.0;
    let rounded = lp_rounded(region, objective, limit / 4.0, merge);
    let start = rounded
        .into_iter()
        .chain(earlier.iter().cloned())
        .filter_map(|c| {
            let rep = check(region, &c, Mode::Milling);
            let fits = rep.valid && (!objective.is_tour() || rep.cycles == 1);
            fits.then(|| (objective.value_of(&rep), c))
        })
        .min_by_key(|(v, _)| *v)
        .map(|(_, c)| c);
    let opts = ExactOptions {
        time_limit: Some(limit),
        heuristic: true,
        warm_start: start,
        ..ExactOptions::default()
    };
    let res = solve(region, objective, &opts);
    match res.cover {
        Some(cover) if res.valid => Ok(Output { objective, cover }),
        _ => Err(Error::invalid(format!(
            "lp-lns found no {objective} walk: {}",
            res.message.as_deref().unwrap_or("the solver gave none")
        ))),
    }
}

/// Steps 1 to 3: the LP's strips joined by a minimum-weight matching of their ends, merged
/// into a tour for the tour objectives by `merge`; `None` when the LP does not converge in `seconds`.
fn lp_rounded(
    region: &Region,
    objective: Objective,
    seconds: f64,
    merge: Merge,
) -> Option<CycleCover> {
    let weights = lp_orientation(region, objective, Some(seconds))?;
    let cover = matched_strips(region, &lp_strips(region, &weights))
        .ok()?
        .cover;
    Some(if objective.is_tour() {
        merge_cycles(region, &cover, merge).0
    } else {
        cover
    })
}

/// A strip cover rounded from the LP's orientation weights ([`lp_orientation`]): the maximal
/// strips through each pixel in each orientation carrying at least half of the pixel's LP
/// passages (both on a tie, both where the LP passes none), then, lightest first (the LP
/// weight along the strip), every strip whose pixels all lie on another kept strip dropped.
pub fn lp_strips(region: &Region, weights: &[[f64; 2]]) -> Vec<Strip> {
    let n = region.len();
    // The candidate strips with their pixels.
    let mut candidates: Vec<(Strip, Vec<usize>)> = Vec::new();
    for (o, horizontal) in [(0, true), (1, false)] {
        for s in strips(region, horizontal) {
            let pixels: Vec<usize> = s
                .pixels()
                .map(|p| region.index_of(p).expect("strips lie in the region"))
                .collect();
            let wanted = pixels.iter().any(|&i| {
                let [h, v] = weights[i];
                let w = [h, v][o];
                h + v < 1e-9 || w >= 0.5 * (h + v) - 1e-9
            });
            if wanted {
                candidates.push((s, pixels));
            }
        }
    }
    let mut count = vec![0u32; n];
    for (_, m) in &candidates {
        for &i in m {
            count[i] += 1;
        }
    }
    let mass: Vec<f64> = candidates
        .iter()
        .map(|(s, m)| {
            m.iter()
                .map(|&i| weights[i][usize::from(!s.horizontal)])
                .sum()
        })
        .collect();
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &b| mass[a].total_cmp(&mass[b]).then(a.cmp(&b)));
    let mut keep = vec![true; candidates.len()];
    for k in order {
        let m = &candidates[k].1;
        if m.iter().all(|&i| count[i] >= 2) {
            keep[k] = false;
            for &i in m {
                count[i] -= 1;
            }
        }
    }
    candidates
        .into_iter()
        .zip(keep)
        .filter_map(|((s, _), k)| k.then_some(s))
        .collect()
}

fn run(region: &Region, options: &Options) -> Result<Solution> {
    let mut solution: Solution = Solution::default();
    for &objective in OBJECTIVES.iter().filter(|&&o| options.wants(o, OBJECTIVES)) {
        let earlier: Vec<CycleCover> = solution.outputs.iter().map(|o| o.cover.clone()).collect();
        solution
            .outputs
            .push(lp_lns(region, objective, &earlier, options.merge)?);
    }
    share(region, &mut solution.outputs);
    if options.coverage4 {
        // Theorem 5.6's rewrite of every tour output (as for the other tours), after sharing.
        let mut stuck = 0;
        for out in solution
            .outputs
            .iter_mut()
            .filter(|o| o.objective.is_tour())
        {
            let (rewritten, s) = crate::coverage4::coverage4(region, &out.cover);
            out.cover = rewritten;
            stuck += s;
        }
        solution
            .certificates
            .insert("coverage4_stuck".to_string(), stuck as i64);
    }
    Ok(solution)
}

/// Step 5: each output takes the cheapest, under its own objective, of the walks computed for
/// all of them that it may use (a tour objective only a single closed walk; every tour is a
/// cycle cover), recounted by the checker. The weighted tour's walk, for one, often has fewer
/// turns than the turn-minimal search found.
fn share(region: &Region, outputs: &mut [Output]) {
    let reports: Vec<Report> = outputs
        .iter()
        .map(|o| check(region, &o.cover, Mode::Milling))
        .collect();
    let chosen: Vec<usize> = (0..outputs.len())
        .map(|i| {
            let objective = outputs[i].objective;
            (0..outputs.len())
                .filter(|&j| reports[j].valid && (!objective.is_tour() || reports[j].cycles == 1))
                .min_by_key(|&j| (objective.value_of(&reports[j]), j != i))
                .unwrap_or(i)
        })
        .collect();
    let covers: Vec<CycleCover> = chosen.iter().map(|&j| outputs[j].cover.clone()).collect();
    for (out, cover) in outputs.iter_mut().zip(covers) {
        out.cover = cover;
    }
}

pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "lp-lns",
    summary: "LP relaxation of the passage model rounded to a strip cover joined by a matching, then node-limited large-neighbourhood search (cc-turns, turns, weighted C=50)",
    objectives: OBJECTIVES,
    guarantees: &[Guarantee::vs_opt(
        Objective::CcTurns,
        4,
        1,
        &crate::theorems::TURNS_LEMMA_4_2,
        "start: a minimum strip cover's strips walked there and back (4s turns), s <= OPT by Lemma 4.2 of Optimal covering tours with turn costs; the search only improves",
    )],
    claims: &[],
    requires: "a connected region",
    precondition: crate::precondition::connected,
    run,
    discrete: None,
    ortho: None,
    by_default: false,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{Family, GenParams, Style, generate};
    use crate::strip_cover::min_strip_cover_size;

    fn regions() -> Vec<Region> {
        let mut out = vec![
            Region::rectangle(1, 1),
            Region::rectangle(5, 1),
            Region::rectangle(6, 4),
        ];
        for seed in 0..4 {
            for (family, n, style) in [
                (Family::RandomSimple, 40, None),
                (Family::RandomHoled, 50, None),
                (Family::Eroded, 60, Some(Style::Sparse)),
            ] {
                let mut p = GenParams::new(family, seed);
                p.n = Some(n);
                p.style = style;
                out.push(generate(&p).unwrap().region);
            }
        }
        out
    }

    /// Every pixel lies on a kept strip, and no kept strip could be dropped (each has a pixel
    /// no other kept strip covers), for the LP's weights and for arbitrary ones.
    #[test]
    fn lp_strips_are_an_irredundant_cover() {
        for region in regions() {
            let lp = lp_orientation(&region, Objective::CcTurns, None);
            let skewed: Vec<[f64; 2]> = (0..region.len())
                .map(|i| if i % 3 == 0 { [0.2, 0.8] } else { [0.5, 0.5] })
                .collect();
            for weights in lp
                .into_iter()
                .chain([skewed, vec![[0.0, 0.0]; region.len()]])
            {
                let strips = lp_strips(&region, &weights);
                let mut count = vec![0u32; region.len()];
                let members: Vec<Vec<usize>> = strips
                    .iter()
                    .map(|s| s.pixels().map(|p| region.index_of(p).unwrap()).collect())
                    .collect();
                for m in &members {
                    m.iter().for_each(|&i| count[i] += 1);
                }
                assert!(
                    count.iter().all(|&c| c >= 1),
                    "{region:?}: a pixel is uncovered"
                );
                for m in &members {
                    assert!(
                        m.iter().any(|&i| count[i] == 1),
                        "{region:?}: a redundant strip"
                    );
                }
                assert!(strips.len() >= min_strip_cover_size(&region));
            }
        }
    }

    /// The walks are checker-valid, tours are one closed walk, and the cycle cover has at most
    /// 4s turns (the guarantee's argument), s recomputed here.
    #[test]
    fn outputs_are_valid_and_the_cycle_cover_within_4s() {
        for region in regions() {
            let sol = run(&region, &Options::default()).unwrap();
            assert_eq!(
                sol.outputs.iter().map(|o| o.objective).collect::<Vec<_>>(),
                OBJECTIVES
            );
            for out in &sol.outputs {
                let rep = check(&region, &out.cover, Mode::Milling);
                assert!(rep.valid, "{:?} {:?}", out.objective, rep.error);
                if out.objective.is_tour() {
                    assert_eq!(rep.cycles, 1, "{:?}", out.objective);
                }
                if out.objective == Objective::CcTurns {
                    assert!(rep.turns <= 4 * min_strip_cover_size(&region) as u64);
                }
            }
        }
    }

    /// `coverage4` is honoured: every tour output covers each pixel at most 4 times.
    #[test]
    fn coverage4_rewrites_the_tours() {
        let options = Options {
            coverage4: true,
            ..Options::default()
        };
        for region in regions().into_iter().take(8) {
            let sol = run(&region, &options).unwrap();
            assert!(sol.certificates.contains_key("coverage4_stuck"));
            let stuck = sol.certificates["coverage4_stuck"];
            for out in sol.outputs.iter().filter(|o| o.objective.is_tour()) {
                let rep = check(&region, &out.cover, Mode::Milling);
                assert!(rep.valid && rep.cycles == 1);
                assert!(stuck > 0 || rep.max_coverage <= 4, "{:?}", out.objective);
            }
        }
    }

    /// Only the wanted objectives are solved; a wanted weighted objective of another turn cost
    /// asks for its carriers.
    #[test]
    fn solves_only_what_is_wanted() {
        let region = Region::rectangle(4, 3);
        let only = |only: Vec<Objective>| {
            let options = Options {
                only,
                ..Options::default()
            };
            run(&region, &options)
                .unwrap()
                .outputs
                .iter()
                .map(|o| o.objective)
                .collect::<Vec<_>>()
        };
        assert_eq!(only(vec![Objective::Turns]), [Objective::Turns]);
        assert_eq!(only(vec![Objective::Weighted(2)]), [Objective::Turns]);
        assert_eq!(
            only(vec![Objective::WeightedCc(STUDY_TURN_COST)]),
            [Objective::WeightedCc(STUDY_TURN_COST)]
        );
        assert_eq!(
            only(vec![Objective::WeightedCc(3)]),
            [Objective::CcTurns, Objective::Turns]
        );
        assert_eq!(only(vec![]), OBJECTIVES);
    }
}
