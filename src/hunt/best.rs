//! The best checked walk known for an instance (`hunt --against best`): an upper bound on OPT
//! from every registered algorithm and the exact solver's incumbent, each walk recounted by
//! the one checker before its value counts.
//!
//! An output carries an objective if the checker accepts it in that objective's mode and it is
//! one closed walk where the objective asks for a tour: for milling `length` and `turns`, any
//! tour (a turn algorithm's tour is a milling tour); for `cc-turns`, cycle covers and tours.
//!
//! The algorithms registered for orthogonal polygons with arbitrary coordinates (an `ortho`
//! run: `corollary4`, `strips-contour`, `star-contour`) are not run: on a grid region they
//! rebuild a grid algorithm's walk (tsp65's, strips-matching's, star-cover's, all run here) and
//! then drop the erosion's contour by exact coverage checks, which at N in the thousands with
//! hundreds of holes takes 20 s where the grid algorithm takes 10 ms (measured on
//! `hole-lattice --n 3000`: the same length and turns). Any subset of the registry gives an
//! upper bound on OPT; this one keeps `hunt --against best` at a few seconds per evaluation.

use crate::algorithms::{self, Objective, Options};
use crate::evaluate;
use crate::exact;
use crate::region::Region;
use crate::tour::CycleCover;

/// A checked walk and where it came from.
#[derive(Clone, Debug)]
pub struct BestWalk {
    /// The checker's value of the walk for the objective.
    pub value: u64,
    /// The registered algorithm's name and its output (`strips-matching:turns`), or
    /// `exact:<status>`.
    pub source: String,
    pub cover: CycleCover,
}

/// Whether outputs of objective `output` may carry `objective` (before the checker decides).
fn carries(output: Objective, objective: Objective) -> bool {
    output.mode() == objective.mode() && (!objective.is_tour() || output.is_tour())
}

/// The objective's value of `cover` if the checker accepts it for `objective`.
pub fn checked_value(
    region: &Region,
    cover: &CycleCover,
    objective: Objective,
    options: &Options,
) -> Option<u64> {
    let report = evaluate::recount(region, cover, objective, options.cutter);
    if !report.valid || (objective.is_tour() && !cover.is_tour()) {
        return None;
    }
    Some(objective.value_of(&report))
}

/// Keeps `candidate` if it is strictly better than `best` (ties keep the earlier).
fn keep(best: &mut Option<BestWalk>, candidate: BestWalk) {
    if best.as_ref().is_none_or(|b| candidate.value < b.value) {
        *best = Some(candidate);
    }
}

/// The best checked walk of every registered grid algorithm run by default (no `ortho` run:
/// module docs; not `lp-lns`, whose MIPs would dominate a hunt's time) whose precondition
/// `region` meets, in registry order (ties keep the first).
pub fn best_of_algorithms(
    region: &Region,
    objective: Objective,
    options: &Options,
) -> Option<BestWalk> {
    let mut best = None;
    for a in algorithms::REGISTRY {
        if a.ortho.is_some()
            || !a.by_default
            || !a.objectives.iter().any(|&o| carries(o, objective))
            || (a.precondition)(region).is_err()
        {
            continue;
        }
        let Ok(solution) = evaluate::guarded(|| (a.run)(region, options)) else {
            continue;
        };
        for out in solution.outputs {
            if !carries(out.objective, objective) {
                continue;
            }
            if let Some(value) = checked_value(region, &out.cover, objective, options) {
                keep(
                    &mut best,
                    BestWalk {
                        value,
                        source: format!("{}:{}", a.name, out.objective),
                        cover: out.cover,
                    },
                );
            }
        }
    }
    best
}

/// The exact solver's walk under `time_limit` seconds (warm-started from the registered
/// algorithms), checked; with the solver's proven lower bound and whether it proved OPT.
pub fn exact_incumbent(
    region: &Region,
    objective: Objective,
    options: &Options,
    time_limit: f64,
) -> (Option<BestWalk>, u64, bool) {
    let Some(exact_obj) = evaluate::exact_counterpart(objective) else {
        return (None, 0, false);
    };
    let res = exact::solve(
        region,
        exact_obj,
        &exact::ExactOptions {
            time_limit: Some(time_limit),
            threads: 1,
            verbose: false,
            warm_start: None,
            max_coverage: None,
            starts: Some(crate::warm_start::from_registry),
            ..exact::ExactOptions::default()
        },
    );
    let proven = res.status == exact::Status::Optimal;
    let walk = res.cover.and_then(|cover| {
        checked_value(region, &cover, objective, options).map(|value| BestWalk {
            value,
            source: format!("exact:{}", res.status),
            cover,
        })
    });
    (walk, res.lower_bound, proven)
}

/// The better of two walks (ties keep `a`).
pub fn better(a: Option<BestWalk>, b: Option<BestWalk>) -> Option<BestWalk> {
    let mut best = a;
    if let Some(b) = b {
        keep(&mut best, b);
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a ring of 16 pixels (6×4, 2×4 hole), milling25's tour has length 32 but the thin
    /// algorithms' tours walk the ring once (16): the best walk is theirs, not milling25's.
    #[test]
    fn best_takes_the_shortest_checked_walk_of_any_algorithm() {
        let ring = Region::from_ascii("######\n#....#\n#....#\n######\n");
        let opts = Options::default();
        let m25 = algorithms::find("milling25").unwrap();
        let own = (m25.run)(&ring, &opts).unwrap();
        let own = own
            .outputs
            .iter()
            .find(|o| o.objective == Objective::Length)
            .unwrap();
        assert_eq!(
            checked_value(&ring, &own.cover, Objective::Length, &opts),
            Some(32)
        );
        let best = best_of_algorithms(&ring, Objective::Length, &opts).unwrap();
        assert_eq!(best.value, 16);
        // milling-2opt, thin-cc, thin-merge and thin-euler tie; the first in registry order
        // (milling-2opt) is kept.
        assert_eq!(best.source, "milling-2opt:length");
        assert_eq!(
            checked_value(&ring, &best.cover, Objective::Length, &opts),
            Some(16)
        );
        // For turns the same tour's 4 turns are the best (milling25's has 12).
        let best = best_of_algorithms(&ring, Objective::Turns, &opts).unwrap();
        assert_eq!(best.value, 4);
        // A cycle cover of two cycles is not a tour: it never carries `length`.
        let mut two = best.cover.clone();
        two.cycles.push(two.cycles[0].clone());
        assert_eq!(checked_value(&ring, &two, Objective::Length, &opts), None);
    }
}
