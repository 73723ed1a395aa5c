//! Warm starts for the exact solver, from the registry: the solver itself knows no algorithm
//! ([`crate::exact::ExactOptions::starts`]); its callers (the harness, `exact`, `solve
//! --exact`, `hunt`, `tight`) pass [`from_registry`], which runs the registered milling
//! approximation algorithms and keeps the cheapest checker-valid cover.

use crate::algorithms::{Options, REGISTRY};
use crate::checker::{self, Mode};
use crate::exact::{ExactOptions, Objective, StartRequest};
use crate::tour::CycleCover;

/// Above this many pixels, [`from_registry`] leaves out [`MATCHING_ALGORITHMS`].
const START_MATCHING_LIMIT: usize = 20_000;

/// The algorithms built on an endpoint matching, whose time grows fastest (minutes at 10^6
/// pixels).
const MATCHING_ALGORITHMS: [&str; 4] = ["strips-matching", "thin-cc", "thin-merge", "boundary-cc"];

/// Exact options that start from [`from_registry`] (the defaults otherwise).
pub fn exact_options() -> ExactOptions {
    ExactOptions {
        starts: Some(from_registry),
        ..ExactOptions::default()
    }
}

/// The cheapest cover the registered milling approximation algorithms find for the request's
/// objective (each output recounted by the checker; a tour for the tour objectives; at most
/// `max_coverage` visits per pixel when set), to start the exact solver from: the 2016 CPLEX
/// study of minimum-turn covers fed its approximations as start solutions, and a good
/// incumbent from the start lets reduced-cost fixing remove more of the model. `None` for
/// `lawn-tsp` or when no algorithm gives one.
///
/// No algorithm starts after `stop_after` (half of the solve's time), above
/// [`START_MATCHING_LIMIT`] pixels the algorithms built on an endpoint matching are left out,
/// and so are the ones not run by default. Each is asked for the requested objective only
/// ([`Options::only`]).
pub fn from_registry(request: &StartRequest<'_>) -> Option<CycleCover> {
    let StartRequest {
        region,
        objective,
        max_coverage,
        stop_after,
    } = *request;
    if objective == Objective::LawnTsp || region.is_empty() {
        return None;
    }
    let cost = |rep: &checker::Report| match objective {
        Objective::Length => rep.length,
        Objective::Weighted(turn_cost) | Objective::WeightedCc(turn_cost) => {
            rep.length + u64::from(turn_cost) * rep.turns
        }
        _ => rep.turns,
    };
    // Only the requested objective: `lp-lns` then solves that one alone.
    let options = Options {
        only: vec![objective],
        ..Options::default()
    };
    let mut best: Option<(u64, CycleCover)> = None;
    for algorithm in REGISTRY {
        let milling = algorithm
            .objectives
            .iter()
            .any(|o| o.mode() == Mode::Milling);
        let half_spent = stop_after.is_some_and(|t| std::time::Instant::now() > t);
        let slow =
            region.len() > START_MATCHING_LIMIT && MATCHING_ALGORITHMS.contains(&algorithm.name);
        // Not the algorithms left out of default runs (`lp-lns`, itself the exact solver's
        // search: starting the solver from it would repeat that search first).
        if !milling
            || !algorithm.by_default
            || half_spent
            || slow
            || (algorithm.precondition)(region).is_err()
        {
            continue;
        }
        // An algorithm that fails or panics only gives no start.
        let run = std::panic::catch_unwind(|| (algorithm.run)(region, &options));
        let Ok(Ok(solution)) = run else { continue };
        for output in solution.outputs {
            let rep = checker::check(region, &output.cover, Mode::Milling);
            let fits = rep.valid
                && (!objective.is_tour() || rep.cycles == 1)
                && max_coverage.is_none_or(|cap| rep.max_coverage <= cap);
            if fits && best.as_ref().is_none_or(|(c, _)| cost(&rep) < *c) {
                best = Some((cost(&rep), output.cover));
            }
        }
    }
    best.map(|(_, cover)| cover)
}
