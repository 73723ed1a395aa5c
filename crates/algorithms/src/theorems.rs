//! The theorems of the two papers, declared once: what each states, the paper's bound as data,
//! how it is measured on result rows, and whether anything realizes it.
//!
//! Registered algorithms point here: every [`Guarantee`](super::Guarantee) names the theorem it
//! comes from, and every [`Algorithm`](super::Algorithm) lists the [`Claim`]s its outputs are
//! measured against (which theorem, on which objectives, and whether it is the paper's
//! algorithm or our reading of its proof on pixels). The claims table
//! ([`crate::claims`]) has one row per entry of [`THEOREMS`] and takes the row's
//! algorithms from the registry; a theorem that no algorithm claims is "not implemented".
//!
//! An entry is one claim of a theorem: a theorem with several bounds (a cycle cover and a tour,
//! turns and length) has one entry per bound, e.g. "Theorem 5.5" and "Theorem 5.5 (tour)".

use super::{Against, Objective, Param, Quantity, Scale, When};
use crate::discrete::Params;
use serde::Serialize;

/// The two papers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Paper {
    /// E. M. Arkin, S. P. Fekete, J. S. B. Mitchell, *Approximation algorithms for lawn mowing
    /// and milling*.
    Milling,
    /// E. M. Arkin, M. A. Bender, E. D. Demaine, S. P. Fekete, J. S. B. Mitchell, S. Sethia,
    /// *Optimal covering tours with turn costs*.
    TurnCost,
    /// Not a paper: the claim a config makes for an outside algorithm (`[[algorithm]]`).
    Outside,
}

impl Paper {
    pub const ALL: [Paper; 2] = [Paper::Milling, Paper::TurnCost];

    /// The title as sources and the claims table cite it.
    pub fn title(self) -> &'static str {
        match self {
            Paper::Milling => "Lawn mowing and milling",
            Paper::TurnCost => "Optimal covering tours with turn costs",
            Paper::Outside => "a config's claim",
        }
    }

    /// The short name of the claims table's Markdown.
    pub fn short(self) -> &'static str {
        match self {
            Paper::Milling => "milling",
            Paper::TurnCost => "turn-cost",
            Paper::Outside => "outside",
        }
    }
}

/// A claimed upper bound `q ≤ (num · X + add) / den` on a quantity of a row, X being OPT (of
/// the row's objective; of length for [`Quantity::Length`]), N or 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Bound {
    pub quantity: Quantity,
    pub num: i64,
    pub den: i64,
    pub add: i64,
    pub against: Against,
    /// What `num` multiplies: 1, or an instance parameter (Table 1's discrete rows).
    pub scale: Scale,
}

impl Bound {
    /// `q ≤ (num · X + add) / den` with a constant factor.
    pub const fn new(quantity: Quantity, num: i64, den: i64, add: i64, against: Against) -> Bound {
        Bound {
            quantity,
            num,
            den,
            add,
            against,
            scale: Scale::One,
        }
    }

    /// `q ≤ (num · P + plus) · X`, P an instance parameter.
    pub const fn scaled(
        quantity: Quantity,
        num: i64,
        param: Param,
        plus: i64,
        against: Against,
    ) -> Bound {
        Bound {
            quantity,
            num,
            den: 1,
            add: 0,
            against,
            scale: Scale::Of { param, plus },
        }
    }

    /// Whether `q ≤ (num · x + add) / den`, in exact integer arithmetic (of a bound whose
    /// factor is a constant: see [`Bound::on`]).
    pub fn holds(&self, q: u64, x: u64) -> bool {
        i128::from(self.den) * i128::from(q)
            <= i128::from(self.num) * i128::from(x) + i128::from(self.add)
    }

    /// The bound's value for a given X, rounded down (values are integers).
    pub fn value_at(&self, x: u64) -> i64 {
        ((i128::from(self.num) * i128::from(x) + i128::from(self.add))
            .div_euclid(i128::from(self.den))) as i64
    }

    /// The bound on an instance with parameters `p` (a constant factor); `None` when the
    /// instance lacks the parameter (d off lattices).
    pub fn on(&self, p: &Params) -> Option<Bound> {
        let (num, den, add) = self.scale.resolve(self.num, self.den, self.add, p)?;
        Some(Bound {
            num,
            den,
            add,
            scale: Scale::One,
            ..*self
        })
    }

    /// The bound in the units of an output whose lengths are in units of 1/`unit` (orthogonal
    /// polygons with arbitrary coordinates; 1 on pixels and graphs): a bound on a length (the
    /// [`Quantity::Length`], or the value of a `length` output) scales its constant, and its
    /// factor when it is against N (N counts unit squares); a factor against OPT does not (OPT
    /// is in the same units).
    pub fn in_units(self, unit: u64, value_is_length: bool) -> Bound {
        let on_length = self.quantity == Quantity::Length
            || (self.quantity == Quantity::Value && value_is_length);
        if !on_length || unit == 1 {
            return self;
        }
        let unit = i64::try_from(unit).unwrap_or(i64::MAX);
        Bound {
            add: self.add.saturating_mul(unit),
            num: if self.against == Against::N {
                self.num.saturating_mul(unit)
            } else {
                self.num
            },
            ..self
        }
    }

    /// The one decision of a bound on one measured quantity `q`, used by the evaluation of every
    /// output and by the claims table alike; they differ only in what they know of X.
    ///
    /// Against N or 1, X is `n` or 1: decided. Against OPT: decided by the proven optimum when
    /// known; else violated when `q` exceeds the bound of a valid walk's value (OPT ≤ upper, so
    /// q > f·upper ≥ f·OPT), held when it is within the bound of a proven lower bound
    /// (q ≤ f·lower ≤ f·OPT), and undecided otherwise. A factor that is still an instance
    /// parameter ([`Bound::on`] not applied) decides nothing.
    pub fn decide(&self, q: u64, n: u64, known: Known) -> Decision {
        if self.scale != Scale::One {
            return Decision::Undecided;
        }
        let exact = match self.against {
            Against::N => Some(n),
            Against::One => Some(1),
            Against::Opt => known.opt,
        };
        if let Some(x) = exact {
            return if self.holds(q, x) {
                Decision::Holds { x: Some(x) }
            } else {
                Decision::Violated { x, exact: true }
            };
        }
        match (known.upper, known.lower) {
            (Some(u), _) if !self.holds(q, u) => Decision::Violated { x: u, exact: false },
            (_, Some(lb)) if self.holds(q, lb) => Decision::Holds { x: None },
            _ => Decision::Undecided,
        }
    }
}

/// What is known of a bound's OPT on one instance ([`Bound::decide`]): the proven optimum, a
/// proven lower bound, and the value of a valid walk (an upper bound).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Known {
    pub opt: Option<u64>,
    pub lower: Option<u64>,
    pub upper: Option<u64>,
}

/// The decision of a bound on one quantity ([`Bound::decide`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decision {
    /// Shown to hold: against X = `x` when X is known exactly (N, 1, the proven optimum), or
    /// `x = None` through a lower bound on OPT.
    Holds { x: Option<u64> },
    /// Violated against `x`: X itself (`exact`), or an upper bound on OPT (a valid walk).
    Violated { x: u64, exact: bool },
    /// Neither shown.
    Undecided,
}

impl Decision {
    /// `Some(true)` when shown to hold, `Some(false)` when violated, `None` when undecided.
    pub fn verdict(self) -> Option<bool> {
        match self {
            Decision::Holds { .. } => Some(true),
            Decision::Violated { .. } => Some(false),
            Decision::Undecided => None,
        }
    }
}

const fn bound(quantity: Quantity, num: i64, den: i64, add: i64, against: Against) -> Bound {
    Bound::new(quantity, num, den, add, against)
}

/// `q ≤ (num · P + plus) · X`, P an instance parameter.
const fn scaled(quantity: Quantity, num: i64, param: Param, plus: i64, against: Against) -> Bound {
    Bound::scaled(quantity, num, param, plus, against)
}

/// How a theorem is measured on result rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Measure {
    /// The paper's bound, on each row of the claiming (algorithm, objective) pairs.
    Bound(Bound),
    /// Lemma 4.4: the strip cover bound s ≤ OPT (ratio s / OPT on exact turn rows).
    StripBound,
    /// Theorem 4.2: merged tour turns ≤ t + 2c − 2 of the algorithm's cycle cover.
    Merge,
    /// Corollary 4.1: merged tour turns ≤ 3/2 · t of the algorithm's cycle cover.
    MergeHalf,
    /// Theorem 5.6: a tour rewritten by `--coverage4` (rows with `coverage4 = true`) keeps the
    /// turns of the same algorithm's tour without it (same instance, objective and merge) and
    /// covers each pixel at most 4 times.
    Coverage4SameTurns,
    /// Table 1's cell "length 4, coverage 4": on the `--coverage4` rows, length ≤ 4 · OPT of
    /// length (the exact optimum, else the best checked tour decides a violation and N ≤ OPT a
    /// hold) and max coverage ≤ 4.
    Coverage4LengthCoverage,
    /// Only the tight families measure it (no result rows carry it).
    TightOnly,
    /// Nothing measures it: the theorem is not implemented.
    Nothing,
}

/// How faithfully something realizes a theorem.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Implementation {
    /// The paper's algorithm, as the paper states it (on the paper's own setting).
    Paper,
    /// Our reading of the paper's proof on pixels; the note says where it departs.
    Reading(&'static str),
}

/// What realizes a theorem.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Realized {
    /// The registered algorithms whose [`Claim`]s name it; none: not implemented.
    ByAlgorithms,
    /// Something other than an algorithm (a lower bound, an option of `solve`).
    Elsewhere(Implementation),
    /// Nothing; the note says why.
    Not(&'static str),
}

/// What measured a tight family's values: a registered algorithm, or a construction of
/// mowmill's (an explicit cover, a hand-built gadget cover) standing in for the paper's example.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TightBy {
    /// The registered algorithm (or the registered lower bound) whose claim this is.
    Registered,
    /// A construction outside the registry; the registered algorithm may do better on the family.
    Constructed,
}

/// The tight family of a theorem and the quantities of `tight.csv` that carry its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Tight {
    pub family: &'static str,
    pub quantities: &'static [&'static str],
    pub by: TightBy,
}

/// One claim of a paper: a theorem, corollary or lemma (or one of its bounds).
#[derive(Debug, PartialEq, Eq, Serialize)]
pub struct Theorem {
    pub paper: Paper,
    /// As the paper numbers it, e.g. "Theorem 5.5"; a suffix names one of several bounds.
    pub id: &'static str,
    pub statement: &'static str,
    /// The claimed factor, as the paper states it.
    pub factor: &'static str,
    pub measure: Measure,
    /// The instances the claim is stated for, beyond the algorithm's preconditions. A row
    /// applies when the harness wrote the theorem's [`key`](Theorem::key) in its `theorems`
    /// column: the row's algorithm claims it and the condition held on the instance.
    pub when: When,
    pub realized: Realized,
    pub tight: Option<Tight>,
}

impl Theorem {
    /// "Theorem 5 of Lawn mowing and milling".
    pub fn cite(&self) -> String {
        format!("{} of {}", self.id, self.paper.title())
    }

    /// The theorem's id in result rows (their `theorems` column) and claims tables: the paper's
    /// short name and the theorem's number, e.g. `milling:Theorem 5`.
    pub fn key(&self) -> String {
        format!("{}:{}", self.paper.short(), self.id)
    }
}

/// An algorithm's claim to realize a theorem: its outputs of `objectives` are measured against
/// the theorem's bound in the claims table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Claim {
    pub theorem: &'static Theorem,
    pub objectives: &'static [Objective],
    pub implementation: Implementation,
}

impl Claim {
    /// A claim realized exactly as the paper states it.
    pub const fn paper(theorem: &'static Theorem, objectives: &'static [Objective]) -> Self {
        Claim {
            theorem,
            objectives,
            implementation: Implementation::Paper,
        }
    }

    /// A claim realized by our reading of the paper's proof; `note` says where it departs.
    pub const fn reading(
        theorem: &'static Theorem,
        objectives: &'static [Objective],
        note: &'static str,
    ) -> Self {
        Claim {
            theorem,
            objectives,
            implementation: Implementation::Reading(note),
        }
    }
}

use Against::{N, One, Opt};
use Paper::{Milling, TurnCost};
use Quantity::{Length, MaxCoverage, Value};

pub static MILLING_THM_2: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 2",
    statement: "a TSP tour of the pixel centres is a lawn mowing tour within alpha_TSP (3 l* + 6); decided only where the area bound suffices (no exact lawn optimum)",
    factor: "alpha_TSP (3 OPT + 6)",
    measure: Measure::Bound(bound(Value, 6, 1, 12, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static MILLING_THM_2_CHRISTOFIDES: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 2 (Christofides)",
    statement: "Theorem 2 with Christofides, alpha_TSP = 3/2",
    factor: "3/2 (3 OPT + 6)",
    measure: Measure::Bound(bound(Value, 9, 2, 18, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static MILLING_THM_3: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 3",
    statement: "constant-factor lawn mowing without the additive term: the shorter of the bounding-box tour and Christofides",
    factor: "3 alpha_TSP + alpha_TSP 3/10 = 99/20 OPT",
    measure: Measure::Bound(bound(Value, 99, 20, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static MILLING_THM_4: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 4",
    statement: "milling tour of length at most 2.5 OPT (regions with holes)",
    factor: "5/2 OPT",
    measure: Measure::Bound(bound(Value, 5, 2, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static MILLING_THM_5: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 5",
    statement: "a tour of a simple grid graph without cut vertices of length at most (6N - 4)/5",
    factor: "(6 N - 4)/5",
    measure: Measure::Bound(bound(Value, 6, 5, -4, N)),
    when: When::Biconnected,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "band",
        quantities: &["tsp65_length", "opt_length"],
        by: TightBy::Registered,
    }),
};

pub static MILLING_COR_3: Theorem = Theorem {
    paper: Milling,
    id: "Corollary 3",
    statement: "milling simple integral rectilinear polygons within 6/5",
    factor: "6/5 OPT",
    measure: Measure::Bound(bound(Value, 6, 5, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "band",
        quantities: &["ratio_tsp65_opt", "ratio_opt_n"],
        by: TightBy::Registered,
    }),
};

pub static MILLING_COR_4: Theorem = Theorem {
    paper: Milling,
    id: "Corollary 4",
    statement: "milling simple rectilinear polygons (arbitrary vertices) within 11/5",
    factor: "11/5 OPT",
    measure: Measure::Bound(bound(Value, 11, 5, 0, Opt)),
    when: When::Simple,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static MILLING_THM_7: Theorem = Theorem {
    paper: Milling,
    id: "Theorem 7",
    statement: "a tour of a grid graph without local cut vertices of length at most 1.325 N",
    factor: "53/40 N",
    measure: Measure::Bound(bound(Value, 53, 40, 0, N)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_LEMMA_4_2: Theorem = Theorem {
    paper: TurnCost,
    id: "Lemma 4.2",
    statement: "the size s of a minimum strip cover (computed as a maximum rook placement, Lemma 4.4) is a lower bound s <= OPT on the turns of every cycle cover and tour",
    factor: "s <= OPT",
    measure: Measure::StripBound,
    when: When::Always,
    // The lower bound of every turn row (`lb_source` "min strip cover"), not an algorithm.
    realized: Realized::Elsewhere(Implementation::Paper),
    tight: Some(Tight {
        family: "donut",
        quantities: &["strip_cover", "opt_cc_turns"],
        by: TightBy::Registered,
    }),
};

pub static TURNS_THM_4_1: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 4.1",
    statement: "a min-turn cycle cover of the boundary in polynomial time (optimal when every pixel is a boundary pixel)",
    factor: "OPT (exact on the boundary)",
    measure: Measure::Bound(bound(Value, 1, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_4_2: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 4.2",
    statement: "a cycle cover with t turns and c cycles merges into a tour with at most t + 2c - 2 turns",
    factor: "t + 2c - 2",
    measure: Measure::Merge,
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "thin43",
        quantities: &["gadget_naive_turns"],
        by: TightBy::Constructed,
    }),
};

pub static TURNS_COR_4_1: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 4.1",
    statement: "a cycle cover with t turns of a connected region merges into a tour with at most 3/2 t turns",
    factor: "3/2 t",
    measure: Measure::MergeHalf,
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

/// The claims of every entry whose tour is its cycle cover merged as in Section 4 (Theorem 4.2
/// and Corollary 4.1, measured on the tour's turns): written once, listed first by each entry
/// through [`merged_tour_claims!`].
pub(crate) const MERGED_TOUR_CLAIMS: [Claim; 2] = [
    Claim::paper(&TURNS_THM_4_2, &[Objective::Turns]),
    Claim::paper(&TURNS_COR_4_1, &[Objective::Turns]),
];

/// An entry's claims: [`MERGED_TOUR_CLAIMS`], then its own (a macro, because a static slice
/// cannot be concatenated in a const context).
macro_rules! merged_tour_claims {
    ($($own:expr),* $(,)?) => {
        &[
            $crate::theorems::MERGED_TOUR_CLAIMS[0],
            $crate::theorems::MERGED_TOUR_CLAIMS[1],
            $($own),*
        ]
    };
}
pub(crate) use merged_tour_claims;

pub static TURNS_THM_5_1: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.1",
    statement: "star cover: a linear-time (rho + 2 delta) cycle cover, here 10 OPT",
    factor: "10 OPT",
    measure: Measure::Bound(bound(Value, 10, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_2: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.2",
    statement: "a linear-time 12-approximation on turns (star cover, merged)",
    factor: "12 OPT",
    measure: Measure::Bound(bound(Value, 12, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_2_COVERAGE: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.2 (coverage)",
    statement: "the star-cover tour covers each pixel at most 4 times",
    factor: "coverage <= 4",
    measure: Measure::Bound(bound(MaxCoverage, 4, 1, 0, One)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_2_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.2 (length)",
    statement: "the star-cover tour is a 4-approximation on length",
    factor: "length <= 4 OPT_length",
    measure: Measure::Bound(bound(Length, 4, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_4: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.4",
    statement: "doubled optimal strip cover, merged: at most 6 OPT turns",
    factor: "6 OPT",
    measure: Measure::Bound(bound(Value, 6, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_4_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.4 (length)",
    statement: "the doubled strip cover tour has length within 4 times the optimal",
    factor: "length <= 4 OPT_length",
    measure: Measure::Bound(bound(Length, 4, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_5: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.5",
    statement: "strips + minimum matching: cycle cover 2.5 OPT",
    factor: "5/2 OPT_cc",
    measure: Measure::Bound(bound(Value, 5, 2, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "donut",
        quantities: &["ratio_cc"],
        by: TightBy::Registered,
    }),
};

pub static TURNS_THM_5_5_TOUR: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.5 (tour)",
    statement: "strips + minimum matching, merged: tour 3.75 OPT",
    factor: "15/4 OPT",
    measure: Measure::Bound(bound(Value, 15, 4, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "donut",
        quantities: &["ratio_naive", "ratio_crossing"],
        by: TightBy::Constructed,
    }),
};

pub static TURNS_TABLE_1: Theorem = Theorem {
    paper: TurnCost,
    id: "Table 1 (length 4, coverage 4)",
    statement: "integral orthogonal and thin rows: the tours rewritten by Theorem 5.6 (--coverage4 rows) are 4-approximations on length and cover each pixel at most 4 times",
    factor: "length <= 4 OPT_length, coverage <= 4",
    measure: Measure::Coverage4LengthCoverage,
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_6: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.6",
    statement: "any tour rewrites into one with the same turns covering each pixel at most 4 times (--coverage4 rows against the same algorithm's rows without it)",
    factor: "coverage <= 4, same turns",
    measure: Measure::Coverage4SameTurns,
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "donut",
        quantities: &["coverage4_turns", "coverage4_max_coverage"],
        by: TightBy::Registered,
    }),
};

/// The claims of every entry whose tours `--coverage4` rewrites (Theorem 5.6 and Table 1's
/// length-4 / coverage-4 cell, measured on its `coverage4 = true` rows).
pub(crate) const COVERAGE4_NOTE: &str = "the paper proves Theorem 5.6 in outline; --coverage4 is our construction of its local modifications";

/// [`TURNS_THM_5_6`] and [`TURNS_TABLE_1`] on the tour, as every entry whose tours
/// `--coverage4` rewrites claims them (written once, listed by each entry).
pub(crate) const COVERAGE4_CLAIMS: [Claim; 2] = [
    Claim::reading(&TURNS_THM_5_6, &[Objective::Turns], COVERAGE4_NOTE),
    Claim::reading(&TURNS_TABLE_1, &[Objective::Turns], COVERAGE4_NOTE),
];

pub static TURNS_COR_5_3: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.3",
    statement: "thin pockets: a min-turn cycle cover in polynomial time",
    factor: "OPT_cc (exact)",
    measure: Measure::Bound(bound(Value, 1, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_3_TOUR: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.3 (tour)",
    statement: "thin pockets: a 1.5-approximation for min-turn tours",
    factor: "3/2 OPT",
    measure: Measure::Bound(bound(Value, 3, 2, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_8: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.8",
    statement: "thin Eulerian pockets: a linear-time 6/5-approximation",
    factor: "6/5 OPT",
    measure: Measure::Bound(bound(Value, 6, 5, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_9: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.9",
    statement: "thin pockets: optimal cycle cover merged into a tour of at most 4/3 OPT turns",
    factor: "4/3 OPT",
    measure: Measure::Bound(bound(Value, 4, 3, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: Some(Tight {
        family: "thin43",
        quantities: &["gadget_naive_turns", "ratio_gadget_naive"],
        by: TightBy::Constructed,
    }),
};

pub static TURNS_THM_5_1_DISCRETE: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.1 (discrete)",
    statement: "discrete milling (Table 1, row Discrete): the star cover is a (rho + 2 delta) cycle cover, rho and delta the averages over the instance",
    factor: "(rho + 2 delta) OPT_cc",
    measure: Measure::Bound(scaled(Value, 1, Param::RhoPlus2Delta, 0, Opt)),
    when: When::NonTrivial,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_1: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.1",
    statement: "discrete milling (Table 1, row Discrete): the merged star cover is a (rho + 2 delta + 2) tour",
    factor: "(rho + 2 delta + 2) OPT",
    measure: Measure::Bound(scaled(Value, 1, Param::RhoPlus2Delta, 2, Opt)),
    when: When::NonTrivial,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_1_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.1 (length)",
    statement: "discrete milling (Table 1, row Discrete): simultaneously a delta-approximation on length",
    factor: "length <= delta OPT_length",
    measure: Measure::Bound(scaled(Length, 1, Param::Delta, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_COR_5_1_COVERAGE: Theorem = Theorem {
    paper: TurnCost,
    id: "Corollary 5.1 (coverage)",
    statement: "discrete milling (Table 1, row Discrete): every vertex visited at most mu times",
    factor: "coverage <= mu",
    measure: Measure::Bound(scaled(MaxCoverage, 1, Param::Mu, 0, One)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_2: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.2",
    statement: "restricted-direction milling (Table 1, row Restricted-direction; d directions: voxels d = 3, hexagonal cells d = 3, grids d = 2): a 5d cycle cover",
    factor: "5d OPT_cc",
    measure: Measure::Bound(scaled(Value, 5, Param::D, 0, Opt)),
    when: When::Lattice,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_2_TOUR: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.2 (tour)",
    statement: "restricted-direction milling: a (5d + 2) tour",
    factor: "(5d + 2) OPT",
    measure: Measure::Bound(scaled(Value, 5, Param::D, 2, Opt)),
    when: When::Lattice,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_2_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.2 (length)",
    statement: "restricted-direction milling: simultaneously a 2d-approximation on length",
    factor: "length <= 2d OPT_length",
    measure: Measure::Bound(scaled(Length, 2, Param::D, 0, Opt)),
    when: When::Lattice,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_2_COVERAGE: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.2 (coverage)",
    statement: "restricted-direction milling: every vertex visited at most 2d times",
    factor: "coverage <= 2d",
    measure: Measure::Bound(scaled(MaxCoverage, 2, Param::D, 0, One)),
    when: When::Lattice,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_3: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.3",
    statement: "regions bounded by n integral segments, implicit encoding: 10 cycle cover, 12 tour in O(n log n)",
    factor: "10 OPT_cc, 12 OPT",
    measure: Measure::Nothing,
    when: When::Always,
    realized: Realized::Not(
        "mowmill's star-cover runs on the pixels (Theorem 5.1), not on the n-segment encoding",
    ),
    tight: None,
};

pub static TURNS_THM_5_7: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.7",
    statement: "nonintegral orthogonal milling: cycle cover 4.5 OPT_cc",
    factor: "9/2 OPT_cc",
    measure: Measure::Bound(bound(Value, 9, 2, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_7_TOUR: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.7 (tour)",
    statement: "nonintegral orthogonal milling: tour 6.25 OPT",
    factor: "25/4 OPT",
    measure: Measure::Bound(bound(Value, 25, 4, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

/// Table 1's row "Orthogonal", simultaneous length column (the text states only the turn
/// factors of Theorem 5.7; the 8 is the table's).
pub static TURNS_THM_5_7_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.7 (length)",
    statement: "Table 1, Orthogonal: the min-turn tour is within 8 of the minimum length",
    factor: "8 OPT_length",
    measure: Measure::Bound(bound(Length, 8, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

/// Table 1's row "Orthogonal", maximum coverage column.
pub static TURNS_THM_5_7_COVERAGE: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.7 (coverage)",
    statement: "Table 1, Orthogonal: every point is milled at most 8 times",
    factor: "coverage <= 8",
    measure: Measure::Bound(bound(MaxCoverage, 8, 1, 0, One)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

/// Table 1's second line for orthogonal polygons: the star cover (Theorems 5.1–5.2 with d = 2)
/// on polygons with arbitrary coordinates. The text proves it only on pixels.
pub static TURNS_ORTHO_STAR: Theorem = Theorem {
    paper: TurnCost,
    id: "Table 1, Orthogonal (star cover)",
    statement: "nonintegral orthogonal milling by a star cover: cycle cover 10 OPT_cc",
    factor: "10 OPT_cc",
    measure: Measure::Bound(bound(Value, 10, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_ORTHO_STAR_TOUR: Theorem = Theorem {
    paper: TurnCost,
    id: "Table 1, Orthogonal (star cover, tour)",
    statement: "nonintegral orthogonal milling by a star cover: tour 12 OPT",
    factor: "12 OPT",
    measure: Measure::Bound(bound(Value, 12, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_ORTHO_STAR_LENGTH: Theorem = Theorem {
    paper: TurnCost,
    id: "Table 1, Orthogonal (star cover, length)",
    statement: "nonintegral orthogonal milling by a star cover: within 4 of the minimum length",
    factor: "4 OPT_length",
    measure: Measure::Bound(bound(Length, 4, 1, 0, Opt)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_ORTHO_STAR_COVERAGE: Theorem = Theorem {
    paper: TurnCost,
    id: "Table 1, Orthogonal (star cover, coverage)",
    statement: "nonintegral orthogonal milling by a star cover: every point milled at most 4 times",
    factor: "coverage <= 4",
    measure: Measure::Bound(bound(MaxCoverage, 4, 1, 0, One)),
    when: When::Always,
    realized: Realized::ByAlgorithms,
    tight: None,
};

pub static TURNS_THM_5_10: Theorem = Theorem {
    paper: TurnCost,
    id: "Theorem 5.10",
    statement: "PTAS for length plus C times turns, O(2^h N^O(C))",
    factor: "(1 + eps) OPT",
    measure: Measure::Nothing,
    when: When::Always,
    realized: Realized::Not("not implemented (exponential in the number of holes)"),
    tight: None,
};

/// Every declared theorem, in the order of the claims table.
pub static THEOREMS: &[&Theorem] = &[
    &MILLING_THM_2,
    &MILLING_THM_2_CHRISTOFIDES,
    &MILLING_THM_3,
    &MILLING_THM_4,
    &MILLING_THM_5,
    &MILLING_COR_3,
    &MILLING_COR_4,
    &MILLING_THM_7,
    &TURNS_LEMMA_4_2,
    &TURNS_THM_4_1,
    &TURNS_THM_4_2,
    &TURNS_COR_4_1,
    &TURNS_THM_5_1,
    &TURNS_COR_5_2,
    &TURNS_COR_5_2_COVERAGE,
    &TURNS_COR_5_2_LENGTH,
    &TURNS_THM_5_4,
    &TURNS_THM_5_4_LENGTH,
    &TURNS_THM_5_5,
    &TURNS_THM_5_5_TOUR,
    &TURNS_TABLE_1,
    &TURNS_THM_5_6,
    &TURNS_COR_5_3,
    &TURNS_COR_5_3_TOUR,
    &TURNS_THM_5_8,
    &TURNS_THM_5_9,
    &TURNS_THM_5_1_DISCRETE,
    &TURNS_COR_5_1,
    &TURNS_COR_5_1_LENGTH,
    &TURNS_COR_5_1_COVERAGE,
    &TURNS_THM_5_2,
    &TURNS_THM_5_2_TOUR,
    &TURNS_THM_5_2_LENGTH,
    &TURNS_THM_5_2_COVERAGE,
    &TURNS_THM_5_3,
    &TURNS_THM_5_7,
    &TURNS_THM_5_7_TOUR,
    &TURNS_THM_5_7_LENGTH,
    &TURNS_THM_5_7_COVERAGE,
    &TURNS_ORTHO_STAR,
    &TURNS_ORTHO_STAR_TOUR,
    &TURNS_ORTHO_STAR_LENGTH,
    &TURNS_ORTHO_STAR_COVERAGE,
    &TURNS_THM_5_10,
];

/// Whether `theorem` is one of [`THEOREMS`] (by address: every entry is a `static`).
pub fn is_declared(theorem: &Theorem) -> bool {
    THEOREMS.iter().any(|t| std::ptr::eq(*t, theorem))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_per_paper() {
        let mut keys: Vec<(Paper, &str)> = THEOREMS.iter().map(|t| (t.paper, t.id)).collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), n, "two theorems share a paper and an id");
    }

    #[test]
    fn unmeasured_theorems_are_exactly_the_unrealized_ones() {
        for t in THEOREMS {
            assert_eq!(
                t.measure == Measure::Nothing,
                matches!(t.realized, Realized::Not(_)),
                "{}: Measure::Nothing if and only if Realized::Not",
                t.cite()
            );
        }
    }
}
