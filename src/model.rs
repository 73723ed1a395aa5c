//! The instance models behind one pipeline: a grid [`Region`], a [`Discrete`] instance and an
//! orthogonal [`Polygon`](crate::ortho::Polygon) with arbitrary coordinates. What differs
//! between them, and only that, is behind [`InstanceModel`]: how an algorithm runs on the
//! model, how its checker recounts a walk (mapped to one [`Recount`]), the cheap lower bound,
//! and the words a refusal uses. The evaluation ([`crate::evaluate::evaluate`]) and the
//! benchmark runner are written once over the trait.

use crate::algorithms::{Algorithm, Model, Objective, Options, Solution};
use crate::discrete::Discrete;
use crate::discrete::format::DiscreteCover;
use crate::error::{Error, Result};
use crate::evaluate::{self, Subject};
use crate::exact;
use crate::ortho::{Polygon, Rational};
use crate::region::Region;
use crate::tour::CycleCover;

/// One checker's recount of an output, in the shape common to every model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Recount {
    /// The checker accepted the walks (whether a tour objective got one walk is decided by
    /// the evaluation).
    pub valid: bool,
    /// Why the checker refused them.
    pub error: Option<String>,
    /// The objective's value, in the units of `length` for a length objective.
    pub value: u64,
    /// The length, in units of 1/`unit`.
    pub length: u64,
    pub turns: u64,
    pub cycles: usize,
    /// The largest number of visits of one pixel or vertex (0 where the checker does not
    /// count visits).
    pub max_coverage: u64,
    /// Lengths are in units of 1/`unit`: 1 on pixels and graphs.
    pub unit: u64,
}

/// An instance of one model: what the one evaluation needs to know about it.
pub trait InstanceModel {
    /// The walks an algorithm returns on this model.
    type Cover: Clone;
    /// A lower bound in the model's exact numbers (an integer, or a rational on polygons).
    type LowerBound: Clone;

    /// The instance as the [`Model`] the guarantees and parameters are read from.
    fn model(&self) -> Model<'_>;

    /// Runs `subject` with `options` for the `wanted` objectives; an error when the subject
    /// has no run on this model (the message names the model).
    fn run(
        &self,
        subject: Subject<'_>,
        options: &Options,
        wanted: &[Objective],
    ) -> Result<Solution<Self::Cover>>;

    /// The number of closed walks of `cover`.
    fn walks(cover: &Self::Cover) -> usize;

    /// `cover` in the model's tour JSON (what `solve --tour-out` writes and `check` reads).
    fn walk_json(cover: &Self::Cover) -> String;

    /// The model's independent checker on `cover`, with the value of `objective`; an error
    /// when the objective is not measured on this model or the numbers cannot be written.
    fn recount(
        &self,
        cover: &Self::Cover,
        objective: Objective,
        options: &Options,
    ) -> Result<Recount>;

    /// The cheap lower bound on the optimum of `objective` (no exact solve), with its source.
    fn cheap_bound(
        &self,
        objective: Objective,
        options: &Options,
    ) -> Result<(Self::LowerBound, String)>;

    /// The objective whose cheap bound `objective` shares (computed once per evaluation).
    fn bound_shared_by(objective: Objective) -> Objective {
        objective
    }

    /// `bound` as an integer in the units of a recount with `unit` (rounded down: still a
    /// bound).
    fn bound_in_units(bound: &Self::LowerBound, objective: Objective, unit: u64) -> Result<u64>;

    /// Whether the benchmark runs `algorithm` on this instance when a family names none.
    fn runs_by_default(&self, algorithm: &Algorithm) -> bool;

    /// Whether `algorithm` has a run on this model at all.
    fn has_run(algorithm: &Algorithm) -> bool;

    /// The error row's message for a name a family lists that has no run on this model
    /// (`None`: the name is skipped, as the grid runner skips the outside algorithms it runs
    /// from the config's own list).
    fn not_run(name: &str) -> Option<String>;

    /// Outside algorithms (`[[algorithm]]` of a config) run on this model.
    const TAKES_OUTSIDE: bool;
    /// The config's option sets apply (else every algorithm runs once, with the defaults).
    const TAKES_OPTIONS: bool;
    /// The weighted objectives of the config's `[[exact]]` tables are also measured on the
    /// algorithms' outputs.
    const MEASURES_WEIGHTED: bool;

    /// Whether the exact solver of this model solves `objective` (`None`: an objective that
    /// does not parse, whose row then carries the parse error).
    fn has_exact(&self, objective: Option<exact::Objective>) -> bool;

    /// Solves `objective` exactly with one solver thread within `time_limit` seconds.
    fn solve_exact(&self, objective: exact::Objective, time_limit: f64) -> Result<ExactOutcome>;
}

/// An exact solve's outcome, in the shape common to every model.
#[derive(Clone, Debug)]
pub struct ExactOutcome {
    pub value: Option<u64>,
    pub length: Option<u64>,
    pub turns: Option<u64>,
    pub cycles: Option<usize>,
    pub status: exact::Status,
    /// A proven lower bound on the optimum.
    pub lower_bound: u64,
    /// The checker accepted the walks found; `None` without walks (infeasible, or none by the
    /// time limit), which is not an invalid result.
    pub valid: Option<bool>,
    pub max_coverage: Option<u64>,
    pub message: Option<String>,
}

/// The value of `objective` from a recount's length and turns.
fn milling_value(objective: Objective, length: u64, turns: u64) -> u64 {
    match objective {
        Objective::Length | Objective::LawnLength | Objective::LawnTsp => length,
        Objective::Turns | Objective::CcTurns => turns,
        Objective::Weighted(c) | Objective::WeightedCc(c) => length + u64::from(c) * turns,
    }
}

impl InstanceModel for Region {
    type Cover = CycleCover;
    type LowerBound = u64;

    fn model(&self) -> Model<'_> {
        Model::Grid(self)
    }

    fn run(
        &self,
        subject: Subject<'_>,
        options: &Options,
        wanted: &[Objective],
    ) -> Result<Solution> {
        match subject {
            Subject::Registered(a) => {
                (a.precondition)(self)?;
                (a.run)(self, options)
            }
            Subject::Outside(o) => o.run(self, wanted),
        }
    }

    fn walks(cover: &CycleCover) -> usize {
        cover.cycles.len()
    }

    fn walk_json(cover: &CycleCover) -> String {
        cover.to_json()
    }

    fn recount(
        &self,
        cover: &CycleCover,
        objective: Objective,
        options: &Options,
    ) -> Result<Recount> {
        let report = evaluate::recount(self, cover, objective, options.cutter);
        Ok(Recount {
            valid: report.valid,
            error: report.error,
            value: milling_value(objective, report.length, report.turns),
            length: report.length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: u64::from(report.max_coverage),
            unit: 1,
        })
    }

    fn cheap_bound(&self, objective: Objective, options: &Options) -> Result<(u64, String)> {
        Ok(evaluate::cheap_bound(self, objective, options.cutter))
    }

    fn bound_in_units(bound: &u64, _: Objective, _: u64) -> Result<u64> {
        Ok(*bound)
    }

    fn runs_by_default(&self, algorithm: &Algorithm) -> bool {
        (algorithm.precondition)(self).is_ok()
    }

    fn has_run(_: &Algorithm) -> bool {
        true
    }

    fn not_run(_: &str) -> Option<String> {
        None
    }

    const TAKES_OUTSIDE: bool = true;
    const TAKES_OPTIONS: bool = true;
    const MEASURES_WEIGHTED: bool = true;

    fn has_exact(&self, _: Option<exact::Objective>) -> bool {
        true
    }

    fn solve_exact(&self, objective: exact::Objective, time_limit: f64) -> Result<ExactOutcome> {
        let options = exact::ExactOptions {
            time_limit: Some(time_limit),
            threads: 1,
            ..crate::warm_start::exact_options()
        };
        let res = exact::solve(self, objective, &options);
        let max_coverage = res.cover.as_ref().map(|cover| {
            u64::from(
                crate::checker::check(self, cover, crate::checker::Mode::Milling).max_coverage,
            )
        });
        Ok(ExactOutcome {
            value: res.value,
            length: res.length,
            turns: res.turns,
            cycles: res.cycles,
            status: res.status,
            lower_bound: res.lower_bound,
            valid: res.cover.as_ref().map(|_| res.valid),
            max_coverage,
            message: res.message,
        })
    }
}

impl InstanceModel for Discrete {
    type Cover = DiscreteCover;
    type LowerBound = u64;

    fn model(&self) -> Model<'_> {
        Model::Discrete(self)
    }

    fn run(
        &self,
        subject: Subject<'_>,
        options: &Options,
        _: &[Objective],
    ) -> Result<Solution<DiscreteCover>> {
        match subject {
            Subject::Registered(a) => match a.discrete {
                Some(run) => run(self, options),
                None => Err(Error::invalid(format!(
                    "{} runs on grid regions only",
                    a.name
                ))),
            },
            Subject::Outside(o) => Err(Error::invalid(format!(
                "{} is an outside algorithm: those run on grid regions only",
                o.name
            ))),
        }
    }

    fn walks(cover: &DiscreteCover) -> usize {
        cover.cycles.len()
    }

    fn walk_json(cover: &DiscreteCover) -> String {
        cover.to_json()
    }

    fn recount(&self, cover: &DiscreteCover, objective: Objective, _: &Options) -> Result<Recount> {
        let report = crate::discrete::check::check(self, &cover.cycles);
        Ok(Recount {
            valid: report.valid,
            error: report.error,
            value: milling_value(objective, report.length, report.turns),
            length: report.length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: u64::from(report.max_coverage),
            unit: 1,
        })
    }

    fn cheap_bound(&self, objective: Objective, _: &Options) -> Result<(u64, String)> {
        Ok(evaluate::discrete_cheap_bound(self, objective))
    }

    fn bound_in_units(bound: &u64, _: Objective, _: u64) -> Result<u64> {
        Ok(*bound)
    }

    fn runs_by_default(&self, algorithm: &Algorithm) -> bool {
        Self::has_run(algorithm)
    }

    fn has_run(algorithm: &Algorithm) -> bool {
        algorithm.discrete.is_some()
    }

    fn not_run(name: &str) -> Option<String> {
        Some(format!("{name} does not run on discrete instances"))
    }

    const TAKES_OUTSIDE: bool = false;
    const TAKES_OPTIONS: bool = true;
    const MEASURES_WEIGHTED: bool = false;

    /// Lawn mowing (`lawn-tsp`) has no discrete counterpart.
    fn has_exact(&self, objective: Option<exact::Objective>) -> bool {
        objective != Some(exact::Objective::LawnTsp)
    }

    fn solve_exact(&self, objective: exact::Objective, time_limit: f64) -> Result<ExactOutcome> {
        use crate::discrete::exact as dexact;
        let options = dexact::DiscreteOptions {
            time_limit: Some(time_limit),
            threads: 1,
            verbose: false,
        };
        let res = dexact::solve(self, objective, &options);
        Ok(ExactOutcome {
            value: res.value,
            length: res.length,
            turns: res.turns,
            cycles: res.cycles,
            status: res.status,
            lower_bound: res.lower_bound,
            valid: res.cover.as_ref().map(|_| res.valid),
            max_coverage: res.max_coverage.map(u64::from),
            message: res.message,
        })
    }
}

/// The error of a length that cannot be written over a 64-bit denominator.
fn too_fine() -> Error {
    Error::invalid(
        "the common denominator of the polygon and the walk overflows 64 bits: the lengths \
         cannot be written exactly",
    )
}

/// An exact length in units of 1/`unit` (an integer when `unit` is a multiple of its
/// denominator), or a bound rounded down to them.
fn in_units(r: Rational, unit: u64) -> Result<u64> {
    let scaled = r
        .checked_mul(Rational::from(unit as i64))
        .ok_or_else(too_fine)?;
    u64::try_from(scaled.floor().max(0)).map_err(|_| too_fine())
}

/// Lengths are exact rationals; a recount writes them in units of 1/`unit`, a common
/// denominator of the polygon's coordinates (doubled: the cutter's centre is half a unit in)
/// and the walk's length, so that every column stays an integer and nothing is rounded but
/// the lower bound, which is rounded down (still a bound).
impl InstanceModel for Polygon {
    type Cover = crate::ortho::Tour;
    type LowerBound = Rational;

    fn model(&self) -> Model<'_> {
        Model::Ortho(self)
    }

    fn run(
        &self,
        subject: Subject<'_>,
        options: &Options,
        _: &[Objective],
    ) -> Result<Solution<crate::ortho::Tour>> {
        let refused = |name: &str| {
            Error::invalid(format!(
                "{name} does not run on orthogonal polygons with arbitrary coordinates"
            ))
        };
        match subject {
            Subject::Registered(a) => match a.ortho {
                Some(run) => run(self, options),
                None => Err(refused(a.name)),
            },
            Subject::Outside(o) => Err(refused(&o.name)),
        }
    }

    fn walks(cover: &crate::ortho::Tour) -> usize {
        cover.cycles.len()
    }

    fn walk_json(cover: &crate::ortho::Tour) -> String {
        cover.to_json()
    }

    fn recount(
        &self,
        cover: &crate::ortho::Tour,
        objective: Objective,
        _: &Options,
    ) -> Result<Recount> {
        let report = crate::ortho::check(self, cover)?;
        let unit = self
            .denominator()
            .and_then(|l| l.checked_mul(2))
            .and_then(|l| crate::ortho::lcm(l, report.length.denom()))
            .and_then(|u| u64::try_from(u).ok())
            .ok_or_else(too_fine)?;
        let length = in_units(report.length, unit)?;
        let value = match objective {
            Objective::Length => length,
            Objective::Turns | Objective::CcTurns => report.turns,
            other => {
                return Err(Error::invalid(format!(
                    "{other} is not measured on orthogonal polygons with arbitrary coordinates"
                )));
            }
        };
        Ok(Recount {
            valid: report.valid,
            error: report.error,
            value,
            length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: 0,
            unit,
        })
    }

    fn cheap_bound(&self, objective: Objective, _: &Options) -> Result<(Rational, String)> {
        evaluate::ortho_bound(self, objective)
    }

    /// One bound for length, one shared by the turn objectives.
    fn bound_shared_by(objective: Objective) -> Objective {
        match objective {
            Objective::Length => Objective::Length,
            _ => Objective::Turns,
        }
    }

    fn bound_in_units(bound: &Rational, objective: Objective, unit: u64) -> Result<u64> {
        match objective {
            Objective::Length => in_units(*bound, unit),
            _ => Ok(bound.floor().max(0) as u64),
        }
    }

    fn runs_by_default(&self, algorithm: &Algorithm) -> bool {
        Self::has_run(algorithm)
    }

    fn has_run(algorithm: &Algorithm) -> bool {
        algorithm.ortho.is_some()
    }

    fn not_run(name: &str) -> Option<String> {
        Some(format!(
            "{name} does not run on orthogonal polygons with arbitrary coordinates"
        ))
    }

    const TAKES_OUTSIDE: bool = false;
    /// Ortho runs take no options: one variant, under the plain name.
    const TAKES_OPTIONS: bool = false;
    const MEASURES_WEIGHTED: bool = false;

    /// No exact solver exists for such polygons (docs/ortho.md says why).
    fn has_exact(&self, _: Option<exact::Objective>) -> bool {
        false
    }

    fn solve_exact(&self, _: exact::Objective, _: f64) -> Result<ExactOutcome> {
        Err(Error::invalid(
            "no exact solver for orthogonal polygons with arbitrary coordinates",
        ))
    }
}
