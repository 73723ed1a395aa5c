//! Which turn objective a passage model minimizes: one type for the grid's passage model
//! ([`crate::turns`]) and the discrete one (`discrete::passage`), with the facts both read
//! from it (the turn cost C, whether walks must join into one tour, and the turn budget a
//! target value leaves).

use crate::Objective;

/// The goal of a passage model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TurnGoal {
    /// `cc-turns`: turns of a cycle cover.
    CycleCover,
    /// `turns`: turns of one closed walk.
    Tour,
    /// Length + C · turns over tours.
    Weighted(u32),
    /// Length + C · turns over cycle covers.
    WeightedCycleCover(u32),
}

impl TurnGoal {
    /// The goal of a turn objective; `None` for the length objectives, which passage models
    /// do not minimize.
    pub(crate) fn of(objective: Objective) -> Option<TurnGoal> {
        match objective {
            Objective::CcTurns => Some(TurnGoal::CycleCover),
            Objective::Turns => Some(TurnGoal::Tour),
            Objective::Weighted(turn_cost) => Some(TurnGoal::Weighted(turn_cost)),
            Objective::WeightedCc(turn_cost) => Some(TurnGoal::WeightedCycleCover(turn_cost)),
            Objective::Length | Objective::LawnLength | Objective::LawnTsp => None,
        }
    }

    /// The turn cost C when length counts too.
    pub(crate) fn turn_cost(self) -> Option<u32> {
        match self {
            TurnGoal::Weighted(c) | TurnGoal::WeightedCycleCover(c) => Some(c),
            _ => None,
        }
    }

    /// Whether the walks must form one closed walk.
    pub(crate) fn is_tour(self) -> bool {
        matches!(self, TurnGoal::Tour | TurnGoal::Weighted(_))
    }

    /// For a solution of value at most `target` on `n` covered vertices (vertices with a
    /// neighbour): (the most turns it can have, the least value the rest of the solution adds
    /// beside one column). A weighted tour has length at least `n`, so its turns are at most
    /// `(target − n) / C`; a weighted cycle cover's only `target / C` (its length may be 0);
    /// with weights every other covered vertex adds at least 1 (at least min(1, 4C) in a cycle
    /// cover, where it may be a one-vertex walk), a plain turn count possibly 0; C = 0 bounds
    /// no turns.
    pub(crate) fn turn_budget(self, n: f64, target: f64) -> (f64, f64) {
        match self {
            TurnGoal::Weighted(c) if c > 0 => ((target - n).max(0.0) / f64::from(c), n - 1.0),
            TurnGoal::Weighted(_) => (f64::INFINITY, n - 1.0),
            TurnGoal::WeightedCycleCover(c) if c > 0 => (target / f64::from(c), n - 1.0),
            TurnGoal::WeightedCycleCover(_) => (f64::INFINITY, 0.0),
            TurnGoal::CycleCover | TurnGoal::Tour => (target, 0.0),
        }
    }
}
