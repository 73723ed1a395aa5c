//! The instance models behind one pipeline: a grid [`Region`], a [`Discrete`] instance and an
//! orthogonal [`Polygon`](crate::ortho::Polygon) with arbitrary coordinates. What differs
//! between them, and only that, is behind [`InstanceModel`]: how an algorithm runs on the
//! model, how its checker recounts a walk (mapped to one [`Recount`]), the cheap lower bound,
//! and the words a refusal uses. The evaluation ([`crate::evaluate::evaluate`]) and the
//! benchmark runner are written once over the trait.

use crate::algorithms::{Model, Objective, Options, Solution};
use crate::discrete::Discrete;
use crate::discrete::format::DiscreteCover;
use crate::error::{Error, Result};
use crate::evaluate::{self, Subject};
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
    type Bound: Clone;

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

    /// The model's independent checker on `cover`, with the value of `objective`; an error
    /// when the objective is not measured on this model or the numbers cannot be written.
    fn recount(
        &self,
        cover: &Self::Cover,
        objective: Objective,
        options: &Options,
    ) -> Result<Recount>;

    /// The cheap lower bound on the optimum of `objective` (no exact solve), with its source.
    fn cheap_bound(&self, objective: Objective, options: &Options)
    -> Result<(Self::Bound, String)>;

    /// The objective whose cheap bound `objective` shares (computed once per evaluation).
    fn bound_shared_by(objective: Objective) -> Objective {
        objective
    }

    /// `bound` as an integer in the units of a recount with `unit` (rounded down: still a
    /// bound).
    fn bound_in_units(bound: &Self::Bound, objective: Objective, unit: u64) -> Result<u64>;
}

/// The value of `objective` from a recount's length and turns.
fn milling_value(objective: Objective, length: u64, turns: u64) -> u64 {
    match objective {
        Objective::Length | Objective::LawnLength => length,
        Objective::Turns | Objective::CcTurns => turns,
        Objective::Weighted(c) | Objective::WeightedCc(c) => length + u64::from(c) * turns,
    }
}

impl InstanceModel for Region {
    type Cover = CycleCover;
    type Bound = u64;

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
}

impl InstanceModel for Discrete {
    type Cover = DiscreteCover;
    type Bound = u64;

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
    type Bound = Rational;

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
}
