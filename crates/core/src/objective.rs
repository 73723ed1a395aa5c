//! The one objective type: what a walk is measured by, for algorithms, the exact solver,
//! result rows and the CLI alike (names are a contract: `length`, `cc-turns`, `turns`,
//! `lawn-length`, `lawn-tsp`, `weighted`, `weighted-cc`; the weighted ones carry their turn
//! cost C, written `weighted-c50` in results).

use crate::checker::Mode;
use serde::Serialize;
use std::fmt;

/// What a result is measured by. It serializes as its [`Display`](fmt::Display) text
/// (`turns`, `weighted-c50`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Objective {
    /// Length of a milling tour (one closed walk inside the region).
    Length,
    /// Total turns of a milling cycle cover.
    CcTurns,
    /// Turns of a milling tour.
    Turns,
    /// Length of a lawn-mowing tour (may leave the region), in the motion's metric.
    LawnLength,
    /// Length + C · turns of a milling tour, C the turn cost.
    Weighted(u32),
    /// Length + C · turns of a milling cycle cover.
    WeightedCc(u32),
    /// The exact TSP through the grass pixel centres with L1 distances (may leave the
    /// region): the exact solver's lawn objective, a lower bound's source for lawn tours.
    LawnTsp,
}

impl Objective {
    pub const ALL: [Objective; 4] = [
        Objective::Length,
        Objective::CcTurns,
        Objective::Turns,
        Objective::LawnLength,
    ];

    /// Every objective name the exact solver accepts (`mowmill exact --objective`).
    pub const EXACT_NAMES: [&'static str; 6] = [
        "length",
        "cc-turns",
        "turns",
        "weighted",
        "weighted-cc",
        "lawn-tsp",
    ];

    /// Every objective name the CLI accepts for algorithm outputs (`weighted` and
    /// `weighted-cc` need a turn cost).
    pub const NAMES: [&'static str; 6] = [
        "length",
        "cc-turns",
        "turns",
        "lawn-length",
        "weighted",
        "weighted-cc",
    ];

    /// The name without the turn cost.
    pub fn name(self) -> &'static str {
        match self {
            Objective::Length => "length",
            Objective::CcTurns => "cc-turns",
            Objective::Turns => "turns",
            Objective::LawnLength => "lawn-length",
            Objective::Weighted(_) => "weighted",
            Objective::WeightedCc(_) => "weighted-cc",
            Objective::LawnTsp => "lawn-tsp",
        }
    }

    /// The objective named `name` (or an alias); `turn_cost` is required by, and only
    /// accepted with, `weighted` and `weighted-cc`.
    pub fn parse(name: &str, turn_cost: Option<u32>) -> std::result::Result<Objective, String> {
        match (canonical_objective(name), turn_cost) {
            ("weighted", Some(c)) => Ok(Objective::Weighted(c)),
            ("weighted-cc", Some(c)) => Ok(Objective::WeightedCc(c)),
            (w @ ("weighted" | "weighted-cc"), None) => {
                Err(format!("objective {w} needs --turn-cost C"))
            }
            (_, Some(_)) => Err(format!(
                "--turn-cost applies to objectives weighted and weighted-cc, not {name}"
            )),
            (_, None) => name.parse(),
        }
    }

    /// The turn cost C of the weighted objectives.
    pub fn turn_cost(self) -> Option<u32> {
        match self {
            Objective::Weighted(c) | Objective::WeightedCc(c) => Some(c),
            _ => None,
        }
    }

    /// The outputs a weighted objective is measured on, in order of preference (a tour is a
    /// cycle cover); empty for the others, which are outputs of their own.
    pub fn carriers(self) -> &'static [Objective] {
        match self {
            Objective::Weighted(_) => &[Objective::Turns, Objective::Length],
            Objective::WeightedCc(_) => &[Objective::CcTurns, Objective::Turns, Objective::Length],
            _ => &[],
        }
    }

    /// The checker mode the outputs of this objective are validated in.
    pub fn mode(self) -> Mode {
        match self {
            Objective::LawnLength | Objective::LawnTsp => Mode::Lawn,
            _ => Mode::Milling,
        }
    }

    /// Whether the objective counts turns (the exact solver's passage model).
    pub fn counts_turns(self) -> bool {
        matches!(
            self,
            Objective::CcTurns
                | Objective::Turns
                | Objective::Weighted(_)
                | Objective::WeightedCc(_)
        )
    }

    /// The objective's value of a checked cover.
    pub fn value_of<V>(self, report: &crate::checker::Report<V>) -> u64 {
        match self {
            Objective::Length | Objective::LawnLength | Objective::LawnTsp => report.length,
            Objective::CcTurns | Objective::Turns => report.turns,
            Objective::Weighted(c) | Objective::WeightedCc(c) => {
                report.length + u64::from(c) * report.turns
            }
        }
    }

    /// The tour objective of a cycle-cover objective (`cc-turns`: `turns`; `weighted-cc C`:
    /// `weighted C`): every tour is a cycle cover of the same cost, so the tour's best walk
    /// bounds the cycle cover's optimum from above and the cycle cover's lower bound bounds
    /// the tour's from below. `None` for the others.
    pub fn tour_counterpart(self) -> Option<Objective> {
        match self {
            Objective::CcTurns => Some(Objective::Turns),
            Objective::WeightedCc(c) => Some(Objective::Weighted(c)),
            _ => None,
        }
    }

    /// Whether outputs must be a single closed walk.
    pub fn is_tour(self) -> bool {
        !matches!(self, Objective::CcTurns | Objective::WeightedCc(_))
    }
}

impl Serialize for Objective {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl std::str::FromStr for Objective {
    type Err = String;

    /// Parses an objective name or one of its [aliases](canonical_objective); the weighted
    /// ones as the results write them, with their turn cost: `weighted-c50`, `weighted-cc-c50`.
    fn from_str(s: &str) -> std::result::Result<Objective, String> {
        let name = canonical_objective(s);
        if let Some((w, c)) = name.rsplit_once("-c")
            && let Ok(c) = c.parse::<u32>()
            && matches!(w, "weighted" | "weighted-cc")
        {
            return Objective::parse(w, Some(c));
        }
        if matches!(name, "weighted" | "weighted-cc") {
            return Objective::parse(name, None);
        }
        if name == "lawn-tsp" {
            return Ok(Objective::LawnTsp);
        }
        Objective::ALL
            .into_iter()
            .find(|o| o.name() == name)
            .ok_or_else(|| {
                format!(
                    "unknown objective {s:?}: expected one of {}",
                    Objective::ALL.map(|o| o.name()).join(", ")
                )
            })
    }
}

/// The one spelling of an objective name in the CLI, JSON, CSV and configs. Old spellings
/// stay accepted: `tour-turns` (the exact solver's name for `turns` before the names were
/// unified). Other names come back unchanged.
pub fn canonical_objective(name: &str) -> &str {
    match name {
        "tour-turns" => "turns",
        other => other,
    }
}

/// The name, with the turn cost for the weighted objectives (`weighted-c50`, as the exact
/// rows of a bench name theirs).
impl fmt::Display for Objective {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.turn_cost() {
            Some(c) => write!(f, "{}-c{c}", self.name()),
            None => f.write_str(self.name()),
        }
    }
}
