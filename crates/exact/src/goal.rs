//! Which turn objective a passage model minimizes: one type for the grid's passage model
//! ([`crate::turns`]) and the discrete one (`discrete::passage`), with the facts both read
//! from it (the turn cost C, whether walks must join into one tour, and the turn budget a
//! target value leaves).

use crate::Objective;
use crate::lp::Formulation;

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

/// Lowers the upper bounds of the first `columns` columns of a passage model for solutions of
/// value at most `target`, where the rest of a solution adds at least `rest` beside one column
/// ([`TurnGoal::turn_budget`]): a column of cost c > 0 is used at most (target − rest) / c
/// times, and a column `straight_cap` caps (a straight passage, at most so many per turn
/// budget) at most that often. A bound never drops below the column's lower bound.
pub(crate) fn tighten_columns(
    f: &mut Formulation,
    columns: usize,
    (target, rest): (f64, f64),
    straight_cap: impl Fn(usize) -> Option<f64>,
) {
    for k in 0..columns {
        let c = f.cost[k];
        let mut hi = if c > 0.0 {
            ((target - rest).max(0.0) / c).floor()
        } else {
            f64::INFINITY
        };
        if let Some(cap) = straight_cap(k) {
            hi = hi.min(cap.floor());
        }
        f.hi[k] = f.hi[k].min(hi).max(f.lo[k]);
    }
}
