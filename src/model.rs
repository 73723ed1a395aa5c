//! The instance models behind one pipeline: a grid [`Region`], a [`Discrete`] instance and an
//! orthogonal [`Polygon`](crate::ortho::Polygon) with arbitrary coordinates. What differs
//! between them, and only that, is behind [`InstanceModel`]: how an algorithm runs on the
//! model, how its checker recounts a walk (mapped to one [`Recount`]), the cheap lower bound,
//! and the words a refusal uses. The evaluation ([`crate::evaluate::evaluate`]) and the
//! benchmark runner are written once over the trait.

use crate::algorithms::{Algorithm, Model, Objective, Options, Solution};
use crate::checker::Mode;
use crate::discrete::Discrete;
use crate::discrete::format::DiscreteCover;
use crate::draw::DrawOptions;
use crate::error::{Error, Result};
use crate::evaluate::{self, Subject};
use crate::exact;
use crate::ortho::{Polygon, Rational};
use crate::region::Region;
use crate::tour::CycleCover;
use std::path::Path;

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

impl Recount {
    /// The recount in a report of the core's checker (grid regions and discrete instances,
    /// whose lengths are whole units).
    fn of<V>(report: crate::checker::Report<V>, objective: Objective) -> Recount {
        Recount {
            valid: report.valid,
            error: report.error,
            value: milling_value(objective, report.length, report.turns),
            length: report.length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: u64::from(report.max_coverage),
            unit: 1,
        }
    }
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

    /// The extension of a finding's figure ([`InstanceModel::draw`] writes either; grids keep
    /// PNG, the vector models SVG).
    const FIGURE: &'static str;

    /// Reads an instance file of this model (an error names the file and what was expected).
    fn read(path: &Path) -> Result<Self>
    where
        Self: Sized;

    /// Reads a walk file in the model's tour JSON ([`InstanceModel::walk_json`] writes it).
    fn read_walk(path: &Path) -> Result<Self::Cover>;

    /// The instance's size as notes say it: `N = 12` pixels, `n = 7` vertices, `12 corners`.
    fn size(&self) -> String;

    /// What `mowmill info` prints: the model's facts about the instance, as one JSON object.
    fn info(&self) -> Result<serde_json::Value>;

    /// The column at which `info`'s text output starts the values (each model keeps the width
    /// its first `info` printed, which scripts grep: 20 for grids, 22 for the vector models).
    const INFO_WIDTH: usize;

    /// The model's checker on `cover` as `validate` prints it (`mode` says milling or lawn
    /// where the model has both).
    fn validation(&self, cover: &Self::Cover, mode: Mode) -> Result<Validation>;

    /// Draws the instance and, when given, `cover` into `out` (SVG or PNG by its extension),
    /// titled `title`, the caption carrying the checker's counts.
    fn draw(&self, cover: Option<&Self::Cover>, out: &Path, title: String) -> Result<()>;
}

/// Which model an instance file holds, by its name and, for `.wkt`, its coordinates: the one
/// place that every command, the benchmark runner and the claims table ask.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A grid region: `.grid`, WKT with integral coordinates, `.poly`, a `.gg`/`.csv` pixel
    /// list.
    Grid,
    /// A discrete instance: `.dm`, `.json`, `.vox`, `.hex`.
    Discrete,
    /// A `.wkt` polygon with a coordinate that is not an integer.
    Ortho,
}

impl Kind {
    /// The model of the instance file `path`.
    pub fn of(path: &Path) -> Kind {
        if crate::discrete::generate::is_discrete(path) {
            Kind::Discrete
        } else if Polygon::is_ortho_file(path) {
            Kind::Ortho
        } else {
            Kind::Grid
        }
    }
}

/// A checker's verdict as `validate` prints it.
#[derive(Clone, Debug)]
pub struct Validation {
    pub valid: bool,
    /// The model's whole report (`validate --json`).
    pub json: serde_json::Value,
    /// One line: `valid: length L, turns T, ...` or `invalid: why`.
    pub line: String,
}

/// The line `validate` prints for a count of length, turns, cycles and coverage.
fn validation_line(
    valid: bool,
    length: impl std::fmt::Display,
    turns: u64,
    cycles: usize,
    coverage: Option<u32>,
    error: Option<&str>,
) -> String {
    let coverage = coverage.map_or(String::new(), |c| format!(", max coverage {c}"));
    if valid {
        format!("valid: length {length}, turns {turns}, {cycles} cycle(s){coverage}")
    } else {
        format!("invalid: {}", error.unwrap_or("?"))
    }
}

/// The validation of a report of the core's checker (grid regions and discrete instances).
fn counted<V>(r: &crate::checker::Report<V>) -> Result<Validation>
where
    crate::checker::Report<V>: serde::Serialize,
{
    Ok(Validation {
        valid: r.valid,
        json: to_json(r)?,
        line: validation_line(
            r.valid,
            r.length,
            r.turns,
            r.cycles,
            Some(r.max_coverage),
            r.error.as_deref(),
        ),
    })
}

/// Reads an orthogonal polygon and refuses it (naming where) when no tour of the unit square
/// cutter mills it.
fn feasible(polygon: &Polygon) -> Result<crate::ortho::Erosion> {
    crate::ortho::feasibility(polygon).map_err(|why| Error::invalid(why.to_string()))
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

impl ExactOutcome {
    /// The outcome of an exact solve of the grid or discrete solver, with the found walks'
    /// largest coverage (`None` without walks).
    fn of<W>(res: exact::ExactResult<W>, max_coverage: Option<u64>) -> ExactOutcome {
        ExactOutcome {
            value: res.value,
            length: res.length,
            turns: res.turns,
            cycles: res.cycles,
            status: res.status,
            lower_bound: res.lower_bound,
            valid: res.cover.as_ref().map(|_| res.valid),
            max_coverage,
            message: res.message,
        }
    }
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
                let options = Options {
                    only: wanted.to_vec(),
                    ..options.clone()
                };
                (a.run)(self, &options)
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
        Ok(Recount::of(report, objective))
    }

    fn cheap_bound(&self, objective: Objective, options: &Options) -> Result<(u64, String)> {
        Ok(evaluate::cheap_bound(self, objective, options.cutter))
    }

    fn bound_in_units(bound: &u64, _: Objective, _: u64) -> Result<u64> {
        Ok(*bound)
    }

    fn runs_by_default(&self, algorithm: &Algorithm) -> bool {
        algorithm.by_default && (algorithm.precondition)(self).is_ok()
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
        Ok(ExactOutcome::of(res, max_coverage))
    }

    const FIGURE: &'static str = "png";
    const INFO_WIDTH: usize = 20;

    fn read(path: &Path) -> Result<Region> {
        Ok(crate::instance::Instance::read(path)?.region)
    }

    fn read_walk(path: &Path) -> Result<CycleCover> {
        CycleCover::read(path)
    }

    fn size(&self) -> String {
        format!("N = {}", self.len())
    }

    fn info(&self) -> Result<serde_json::Value> {
        let mut v = serde_json::to_value(crate::topology::summary(self))
            .map_err(|e| Error::invalid(format!("the summary: {e}")))?;
        // The minimum strip cover: the turn lower bound of Lemmas 4.2-4.4 (turn-cost paper).
        v["strip_cover"] = crate::strip_cover::min_strip_cover_size(self).into();
        // Pixels with exactly two side neighbours (corridor and corner pixels).
        let degree2 = (0..self.len())
            .filter(|&i| {
                crate::Dir::ALL
                    .iter()
                    .filter(|&&d| self.neighbor(i, d).is_some())
                    .count()
                    == 2
            })
            .count();
        v["degree2"] = degree2.into();
        Ok(v)
    }

    fn validation(&self, cover: &CycleCover, mode: Mode) -> Result<Validation> {
        counted(&crate::checker::check(self, cover, mode))
    }

    fn draw(&self, cover: Option<&CycleCover>, out: &Path, title: String) -> Result<()> {
        let mut caption = self.size();
        if let Some(c) = cover {
            let r = crate::checker::check(self, c, Mode::Milling);
            caption += &format!(
                ", length {}, turns {}, {} cycle(s)",
                r.length, r.turns, r.cycles
            );
            if !r.valid {
                caption += " (not a valid milling cover)";
            }
        }
        let opts = DrawOptions {
            title: Some(title),
            caption: Some(caption),
            ..DrawOptions::default()
        };
        crate::draw::draw(self, cover, out, &opts)
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
        wanted: &[Objective],
    ) -> Result<Solution<DiscreteCover>> {
        match subject {
            Subject::Registered(a) => match a.discrete {
                Some(run) => run(self, options),
                None => Err(Error::invalid(format!(
                    "{} runs on grid regions only",
                    a.name
                ))),
            },
            Subject::Outside(o) => o.run(self, wanted),
        }
    }

    fn walks(cover: &DiscreteCover) -> usize {
        cover.cycles.len()
    }

    fn walk_json(cover: &DiscreteCover) -> String {
        cover.to_json()
    }

    /// Lawn mowing has no discrete counterpart: an outside program that declares it gets an
    /// error (a row with `error`), not a milling length under the lawn objective's name.
    fn recount(&self, cover: &DiscreteCover, objective: Objective, _: &Options) -> Result<Recount> {
        if matches!(objective, Objective::LawnLength | Objective::LawnTsp) {
            return Err(Error::invalid(format!(
                "{objective} is not defined on discrete instances"
            )));
        }
        let report = crate::discrete::check::check(self, &cover.cycles);
        Ok(Recount::of(report, objective))
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

    const TAKES_OUTSIDE: bool = true;
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
        let max_coverage = res.max_coverage.map(u64::from);
        Ok(ExactOutcome::of(res, max_coverage))
    }

    const FIGURE: &'static str = "svg";
    const INFO_WIDTH: usize = 22;

    fn read(path: &Path) -> Result<Discrete> {
        crate::discrete::generate::read(path)
    }

    fn read_walk(path: &Path) -> Result<DiscreteCover> {
        DiscreteCover::read(path)
    }

    fn size(&self) -> String {
        format!("n = {}", self.len())
    }

    fn info(&self) -> Result<serde_json::Value> {
        let p = self.params();
        let rooks = crate::discrete::exact::rook_placement(self, Some(10.0));
        Ok(serde_json::json!({
            "model": "discrete",
            "n": self.len(),
            "edges": self.edge_count(),
            "components": self.components(),
            "delta": p.delta,
            "mu": p.mu,
            "rho": p.rho,
            "d": p.d,
            "rook_placement": rooks.size,
            "rook_placement_exact": rooks.exact,
        }))
    }

    fn validation(&self, cover: &DiscreteCover, _: Mode) -> Result<Validation> {
        counted(&crate::discrete::check::check(self, &cover.cycles))
    }

    fn draw(&self, cover: Option<&DiscreteCover>, out: &Path, title: String) -> Result<()> {
        let walks = cover.map(|c| c.cycles.as_slice());
        let opts = DrawOptions {
            title: Some(title),
            caption: Some(crate::discrete::draw::caption(self, walks)),
            ..DrawOptions::default()
        };
        crate::discrete::draw::draw(self, walks, out, &opts)
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

    const FIGURE: &'static str = "svg";
    const INFO_WIDTH: usize = 22;

    fn read(path: &Path) -> Result<Polygon> {
        Polygon::read(path)
    }

    fn read_walk(path: &Path) -> Result<crate::ortho::Tour> {
        crate::ortho::Tour::read(path)
    }

    fn size(&self) -> String {
        let corners: usize = self.rings().iter().map(|r| r.corners.len()).sum();
        format!("{corners} vertices")
    }

    fn info(&self) -> Result<serde_json::Value> {
        let erosion = feasible(self)?;
        let contour = crate::ortho::check(self, &erosion.contour_tour())?;
        let pixels = crate::ortho::interior_pixels(self)?;
        Ok(serde_json::json!({
            "model": "ortho",
            "rings": self.rings().len(),
            "holes": self.rings().iter().filter(|r| r.hole).count(),
            "corners": self.rings().iter().map(|r| r.corners.len()).sum::<usize>(),
            "feasible": true,
            "erosion_pieces": erosion.pieces(),
            "contour_walks": erosion.contour().len(),
            "contour_length": contour.length.to_string(),
            "contour_mills_polygon": contour.valid,
            "interior_pixels": pixels.len(),
        }))
    }

    fn validation(&self, cover: &crate::ortho::Tour, _: Mode) -> Result<Validation> {
        feasible(self)?;
        let r = crate::ortho::check(self, cover)?;
        Ok(Validation {
            valid: r.valid,
            json: to_json(&r)?,
            line: validation_line(
                r.valid,
                r.length,
                r.turns,
                r.cycles,
                None,
                r.error.as_deref(),
            ),
        })
    }

    fn draw(&self, cover: Option<&crate::ortho::Tour>, out: &Path, title: String) -> Result<()> {
        // The contour δB is drawn where the polygon is feasible; the caption is the exact
        // checker's verdict on the tour.
        let erosion = crate::ortho::feasibility(self).ok();
        let opts = DrawOptions {
            title: Some(title),
            ..DrawOptions::default()
        };
        crate::ortho::draw(self, cover, erosion.as_ref(), out, &opts)
    }
}

/// A report as a JSON value.
fn to_json(report: &impl serde::Serialize) -> Result<serde_json::Value> {
    serde_json::to_value(report).map_err(|e| Error::invalid(format!("the report: {e}")))
}
