//! The one evaluation pipeline: an algorithm, its options and an instance of any
//! [model](crate::model) → the checked walks,
//! their values, the best available lower bound and its source, the verdict of every guarantee,
//! and the certificates. `solve`, `bench`, `tight` and every later command call [`evaluate`];
//! nothing else runs an algorithm and judges its output.
//!
//! Steps, in order:
//! 1. check the algorithm's preconditions and run it (a registered algorithm in-process, an
//!    [outside](crate::outside) one as a child process); a panic becomes an error;
//! 2. recount every output with the independent [`checker`] (the [lawn
//!    checker](crate::lawn_check) for lawn tours in milli-units), insisting on one closed walk
//!    for tour objectives;
//! 3. take the best lower bound: the cheap bounds of [`bounds`] and whatever the caller knows
//!    from exact solves ([`Reference`]);
//! 4. decide every applicable guarantee: against OPT when it is known, against the lower bound
//!    when that suffices (value ≤ f·LB ≤ f·OPT), else undecided.

use crate::algorithms::{
    self, Algorithm, Cutter, Guarantee, Measured, Merge, Model, Objective, Options,
};
use crate::bounds;
use crate::checker::{self, Report};
use crate::discrete::Discrete;
use crate::error::{Error, Result};
use crate::lawn_check;
use crate::model::InstanceModel;
use crate::outside::OutsideAlgorithm;
use crate::region::Region;
use crate::tour::CycleCover;
use std::collections::BTreeMap;
use std::time::Instant;

/// What is evaluated: a registered algorithm or one declared in a config (`[[algorithm]]`).
#[derive(Clone, Copy, Debug)]
pub enum Subject<'a> {
    Registered(&'static Algorithm),
    Outside(&'a OutsideAlgorithm),
}

impl Subject<'_> {
    pub fn name(&self) -> &str {
        match self {
            Subject::Registered(a) => a.name,
            Subject::Outside(o) => &o.name,
        }
    }

    pub fn objectives(&self) -> &[Objective] {
        match self {
            Subject::Registered(a) => a.objectives,
            Subject::Outside(o) => &o.objectives,
        }
    }

    /// Whether the subject reports `objective` (a registered algorithm also reports the
    /// weighted objectives it has a [carrier](Objective::carriers) for).
    pub fn reports(&self, objective: Objective) -> bool {
        match self {
            Subject::Registered(a) => a.reports(objective),
            Subject::Outside(o) => o.objectives.contains(&objective),
        }
    }

    /// The objective to report: `wanted` if the subject produces it, else by default its tour
    /// (its first objective when it has no tour).
    pub fn pick_objective(&self, wanted: Option<Objective>) -> Result<Objective> {
        let have = self.objectives();
        match wanted {
            Some(o) if self.reports(o) => Ok(o),
            Some(o) => Err(Error::invalid(format!(
                "{} reports {}, not {o}",
                self.name(),
                have.iter().map(|o| o.name()).collect::<Vec<_>>().join(", ")
            ))),
            None => Ok(have
                .iter()
                .copied()
                .find(|o| o.is_tour())
                .unwrap_or(have[0])),
        }
    }

    /// The theorems the subject claims for `objective` on `model` (for an outside algorithm,
    /// the config's claim of its guarantee on that objective).
    pub fn theorems_on(
        &self,
        objective: Objective,
        model: Model<'_>,
    ) -> Vec<&'static crate::algorithms::theorems::Theorem> {
        match self {
            Subject::Registered(a) => a.theorems_on(objective, model),
            Subject::Outside(o) => o
                .guarantees
                .iter()
                .filter(|g| g.objective == objective)
                .map(|g| g.theorem)
                .collect(),
        }
    }

    pub fn guarantees(&self) -> &[Guarantee] {
        match self {
            Subject::Registered(a) => a.guarantees,
            Subject::Outside(o) => &o.guarantees,
        }
    }

    /// The guarantees that apply to `objective` on `region` with `options`. The lawn
    /// guarantees are proven for the square cutter with rectilinear motion only, so other
    /// cutters are measured without a guarantee.
    pub fn applicable(
        &self,
        objective: Objective,
        region: &Region,
        options: &Options,
    ) -> Vec<Guarantee> {
        self.applicable_to(objective, Model::Grid(region), options)
    }

    /// [`Subject::applicable`] on an instance of either model, each guarantee with the
    /// instance's parameters put in ([`Guarantee::on`]).
    pub fn applicable_to(
        &self,
        objective: Objective,
        model: Model<'_>,
        options: &Options,
    ) -> Vec<Guarantee> {
        // The instance's parameters are computed once, and only when a factor needs them.
        let params = std::cell::OnceCell::new();
        self.guarantees()
            .iter()
            .filter(|g| g.objective == objective)
            .filter(|_| objective != Objective::LawnLength || options.cutter == Cutter::Square)
            .filter_map(|g| g.on_with(model, || *params.get_or_init(|| model.params())))
            .collect()
    }

    /// Whether the subject accepts `region` (always true for outside algorithms: they say so
    /// by failing).
    pub fn accepts(&self, region: &Region) -> bool {
        match self {
            Subject::Registered(a) => (a.precondition)(region).is_ok(),
            Subject::Outside(_) => true,
        }
    }
}

/// What the caller knows about the optimum of each algorithm objective, from exact solves.
#[derive(Clone, Debug, Default)]
pub struct Reference {
    known: BTreeMap<Objective, Known>,
}

/// An exact solve's outcome for one objective.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Known {
    /// The proven optimum.
    pub opt: Option<u64>,
    /// A proven lower bound on the optimum (equal to `opt` when optimal).
    pub lower_bound: Option<u64>,
    /// The exact solver's status (`optimal`, `time_limit`, ...), for the `opt_status` column.
    pub status: String,
    /// Where the bound comes from, e.g. `opt:cc-turns` or `exact-bound:turns`.
    pub source: String,
}

impl Known {
    /// What an exact solve of the objective called `name` proved: its optimum `opt` when it
    /// found one (source `opt:NAME`), else only its lower bound (`exact-bound:NAME`).
    pub fn proven(name: &str, opt: Option<u64>, lower_bound: Option<u64>, status: String) -> Known {
        let source = match opt {
            Some(_) => format!("opt:{name}"),
            None => format!("exact-bound:{name}"),
        };
        Known {
            opt,
            lower_bound,
            status,
            source,
        }
    }
}

impl Reference {
    /// Records an exact solve of `objective`. A tour is a cycle cover, so a bound on the
    /// cycle-cover optimum also bounds the tour optimum: callers record both.
    pub fn insert(&mut self, objective: Objective, known: Known) {
        self.known.insert(objective, known);
    }

    pub fn get(&self, objective: Objective) -> Option<&Known> {
        self.known.get(&objective)
    }

    /// The proven optimum of `objective`, if an exact solve proved it.
    pub fn opt(&self, objective: Objective) -> Option<u64> {
        self.get(objective).and_then(|k| k.opt)
    }

    /// Exact lower bounds that bound `objective`: its own, and for tours also the cycle
    /// cover's (every tour is a cycle cover).
    fn exact_bounds(&self, objective: Objective) -> Vec<(u64, String)> {
        let sources: Vec<Objective> = match objective {
            Objective::Turns => vec![Objective::Turns, Objective::CcTurns],
            Objective::Weighted(c) => vec![Objective::Weighted(c), Objective::WeightedCc(c)],
            Objective::LawnLength => vec![],
            o => vec![o],
        };
        sources
            .iter()
            .filter_map(|o| self.get(*o))
            .filter_map(|k| Some((k.lower_bound?, k.source.clone())))
            .collect()
    }
}

/// The cheap lower bound on the optimum of `objective` (no exact solve), with its source.
/// Lawn tours: the larger of the area swept (milling paper, Section 4) and, for the square
/// cutters, the spread of the grass ([`algorithms::lawn::spread_lower_bound`]), in the units
/// the lawn checker reports for the cutter.
pub fn cheap_bound(region: &Region, objective: Objective, cutter: Cutter) -> (u64, String) {
    match objective {
        Objective::Length => {
            let b = bounds::length_lower_bound(region);
            (b.value, b.source.to_string())
        }
        Objective::Turns | Objective::CcTurns => {
            let b = bounds::turn_lower_bound(region);
            (b.value, b.source.to_string())
        }
        Objective::Weighted(_) | Objective::WeightedCc(_) | Objective::LawnTsp => {
            let b = crate::exact::cheap_lower_bound(region, objective);
            (b.value, b.source.to_string())
        }
        Objective::LawnLength => {
            let area = algorithms::lawn::area_lower_bound(region, cutter).max(0) as u64;
            match algorithms::lawn::spread_lower_bound(region, cutter) {
                Some(spread) if spread as u64 > area => (
                    spread as u64,
                    "spread: the cutter reaches the extreme pixels".to_string(),
                ),
                _ => (area, "area: N <= L*w + a".to_string()),
            }
        }
    }
}

/// The verdict on one guarantee.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Verdict {
    /// The guarantee as text, e.g. `turns <= 3/2 OPT (Corollary 5.3 ...)`.
    pub bound: String,
    pub factor: f64,
    /// `Some(true)` shown to hold, `Some(false)` violated, `None` undecided.
    pub holds: Option<bool>,
}

/// One checked output of an evaluation (its walks are pixels, or vertices of a discrete
/// instance).
#[derive(Clone, Debug)]
pub struct Checked<C = CycleCover> {
    pub objective: Objective,
    pub cover: C,
    /// The checker accepted it, and it is one closed walk where the objective is a tour.
    pub valid: bool,
    /// Why it is invalid.
    pub error: Option<String>,
    /// The objective's value (length or turns) as the checker recounted it.
    pub value: u64,
    pub length: u64,
    /// Lengths (`length`, and `value`, `opt`, `lower_bound` of a length objective) are in
    /// units of 1/`unit`: 1 on pixels and graphs; on orthogonal polygons with arbitrary
    /// coordinates a common denominator, so that exact lengths stay integers.
    pub unit: u64,
    pub turns: u64,
    pub cycles: usize,
    pub max_coverage: u64,
    /// The proven optimum, when known.
    pub opt: Option<u64>,
    pub opt_status: String,
    /// The best lower bound on the optimum and its source.
    pub lower_bound: Option<u64>,
    pub lb_source: String,
    pub verdicts: Vec<Verdict>,
    /// `Some(true)` when every applicable guarantee holds, `Some(false)` when one is
    /// violated, `None` when one is undecided or none applies.
    pub within_guarantee: Option<bool>,
}

/// Everything one run of one algorithm on one region gave.
#[derive(Clone, Debug)]
pub struct Evaluation<C = CycleCover> {
    pub algorithm: String,
    pub options: Options,
    /// Wall time of the run (the algorithm, its merge and its own certificates).
    pub seconds: f64,
    /// Wall time of the checker's recounts and the lower bounds of the outputs after the run.
    pub check_seconds: f64,
    /// Named integers the algorithm reports (strip cover size, matching weight, ...).
    pub certificates: BTreeMap<String, i64>,
    /// One entry per requested objective the algorithm produced.
    pub outputs: Vec<Checked<C>>,
    /// Requested objectives the algorithm did not produce, with why.
    pub missing: Vec<(Objective, String)>,
    /// The run failed: every requested objective is missing for this reason.
    pub error: Option<String>,
    /// The exit code of the error the run returned ([`Error::exit_code`]: 2 when it refused
    /// its input or options, 3 for a solver failure); `None` when it succeeded or panicked.
    pub error_exit_code: Option<u8>,
}

impl<C> Evaluation<C> {
    /// The checked output for `objective`.
    pub fn output(&self, objective: Objective) -> Option<&Checked<C>> {
        self.outputs.iter().find(|c| c.objective == objective)
    }
}

/// Runs `subject` on `instance` (a grid [`Region`], a [`Discrete`] instance or an orthogonal
/// [`Polygon`](crate::ortho::Polygon): any [`InstanceModel`]) with `options`, recounts every
/// output of the `objectives` asked for (all the subject's objectives when empty) with the
/// model's checker, takes the best lower bound (the model's cheap bound and the exact solves in
/// `reference`) and judges the subject's guarantees with the instance's parameters put in.
/// Never fails: errors and panics are recorded in the evaluation.
///
/// On a polygon with arbitrary coordinates the lengths are written in units of 1/`unit`
/// ([`Checked::unit`]) so that they stay exact integers; no exact optimum is known there (no
/// exact solver: docs/ortho.md says why), so OPT is never set.
pub fn evaluate<M: InstanceModel>(
    subject: Subject<'_>,
    instance: &M,
    options: &Options,
    objectives: &[Objective],
    reference: &Reference,
) -> Evaluation<M::Cover> {
    let run = |wanted: &[Objective]| instance.run(subject, options, wanted);
    let (mut eval, solution, wanted) = match begin(
        subject.name(),
        options,
        subject.objectives(),
        objectives,
        run,
    ) {
        Ok(started) => started,
        Err(failed) => return failed,
    };
    let checking = Instant::now();
    // The cheap bounds once per evaluation (the objectives of a model may share one).
    let mut bounds: BTreeMap<Objective, (M::LowerBound, String)> = BTreeMap::new();
    for objective in wanted {
        // A weighted objective is measured on the output it is carried by.
        let output = solution
            .outputs
            .iter()
            .find(|o| o.objective == objective)
            .or_else(|| {
                objective
                    .carriers()
                    .iter()
                    .find_map(|&c| solution.outputs.iter().find(|o| o.objective == c))
            });
        let Some(output) = output else {
            let why = format!("{} returned no {objective} output", subject.name());
            eval.missing.push((objective, why));
            continue;
        };
        let key = M::bound_shared_by(objective);
        let bound = match bounds.get(&key) {
            Some(known) => Ok(known.clone()),
            None => instance.cheap_bound(objective, options).inspect(|found| {
                bounds.insert(key, found.clone());
            }),
        };
        let judged = bound.and_then(|bound| {
            judge_on(
                subject,
                instance,
                options,
                objective,
                output.cover.clone(),
                bound,
                reference,
            )
        });
        match judged {
            Ok(checked) => eval.outputs.push(checked),
            Err(e) => eval.missing.push((objective, e.to_string())),
        }
    }
    eval.check_seconds = checking.elapsed().as_secs_f64();
    eval
}

/// The start of every evaluation: the objectives wanted (`objectives`, or `all` when it is
/// empty), the timed and guarded `run`, and then either `Err` with the finished evaluation when
/// the run failed (every wanted objective missing for its message), or the evaluation holding
/// the certificates, the solution whose outputs are to be checked, and the wanted objectives.
#[allow(clippy::type_complexity, clippy::result_large_err)]
fn begin<C, S>(
    name: &str,
    options: &Options,
    all: &[Objective],
    objectives: &[Objective],
    run: impl FnOnce(&[Objective]) -> Result<algorithms::Solution<S>>,
) -> std::result::Result<(Evaluation<C>, algorithms::Solution<S>, Vec<Objective>), Evaluation<C>> {
    let wanted: Vec<Objective> = if objectives.is_empty() {
        all.to_vec()
    } else {
        objectives.to_vec()
    };
    let start = Instant::now();
    let code = std::cell::Cell::new(None);
    let outcome = guarded(|| {
        run(&wanted).inspect_err(|e: &crate::error::Error| code.set(Some(e.exit_code())))
    });
    let mut eval = Evaluation {
        algorithm: name.to_string(),
        options: options.clone(),
        seconds: start.elapsed().as_secs_f64(),
        check_seconds: 0.0,
        certificates: BTreeMap::new(),
        outputs: Vec::new(),
        missing: Vec::new(),
        error: None,
        error_exit_code: None,
    };
    match outcome {
        Ok(mut solution) => {
            eval.certificates = std::mem::take(&mut solution.certificates);
            Ok((eval, solution, wanted))
        }
        Err(msg) => {
            eval.missing = wanted.iter().map(|&o| (o, msg.clone())).collect();
            eval.error = Some(msg);
            eval.error_exit_code = code.get();
            Err(eval)
        }
    }
}

/// Checks one cover of `objective` on a grid region and judges the subject's guarantees on it.
pub fn judge(
    subject: Subject<'_>,
    region: &Region,
    options: &Options,
    objective: Objective,
    cover: CycleCover,
    reference: &Reference,
) -> Checked {
    let bound = cheap_bound(region, objective, options.cutter);
    judge_on(subject, region, options, objective, cover, bound, reference)
        .expect("a grid region's recount and bounds are integers and never fail")
}

/// Checks one cover of `objective` with the model's checker and decides the subject's
/// guarantees on it, against the better of `cheap` (the model's cheap bound of the objective,
/// with its source) and the exact bounds in `reference`.
fn judge_on<M: InstanceModel>(
    subject: Subject<'_>,
    instance: &M,
    options: &Options,
    objective: Objective,
    cover: M::Cover,
    (cheap, cheap_source): (M::LowerBound, String),
    reference: &Reference,
) -> Result<Checked<M::Cover>> {
    let report = instance.recount(&cover, objective, options)?;
    let one_walk = !objective.is_tour() || M::walks(&cover) == 1;
    let valid = report.valid && one_walk;
    let error = if !report.valid {
        Some(report.error.clone().unwrap_or_default())
    } else if !one_walk {
        Some(format!("a tour objective got {} cycles", M::walks(&cover)))
    } else {
        None
    };
    let unit = report.unit;
    let opt = exact_counterpart(objective).and_then(|o| reference.opt(o));
    let opt_status = exact_counterpart(objective)
        .and_then(|o| reference.get(o))
        .map(|k| k.status.clone())
        .unwrap_or_default();
    // The largest lower bound; ties keep the first (cheapest) source.
    let mut best = (M::bound_in_units(&cheap, objective, unit)?, cheap_source);
    for (b, source) in reference.exact_bounds(objective) {
        if b > best.0 {
            best = (b, source);
        }
    }
    let (lower_bound, lb_source) = (Some(best.0), best.1);
    let measured = Measured {
        value: report.value,
        length: report.length,
        max_coverage: report.max_coverage,
    };
    let model = instance.model();
    let n = model.len() as u64;
    // A bound on a length is written in the units of the lengths (1 on pixels and graphs).
    let applicable: Vec<_> = subject
        .applicable_to(objective, model, options)
        .into_iter()
        .map(|g| Guarantee {
            bound: g.bound.in_units(unit, objective == Objective::Length),
            ..g
        })
        .collect();
    let (verdicts, within_guarantee) = verdicts(&applicable, &measured, n, opt, lower_bound);
    Ok(Checked {
        objective,
        cover,
        valid,
        error,
        value: report.value,
        length: report.length,
        unit,
        turns: report.turns,
        cycles: report.cycles,
        max_coverage: report.max_coverage,
        opt,
        opt_status,
        lower_bound,
        lb_source,
        verdicts,
        within_guarantee,
    })
}

/// The verdict of every applicable guarantee on one measured output, and their conjunction:
/// `Some(true)` when all hold, `Some(false)` when one is violated, else `None`.
fn verdicts(
    applicable: &[Guarantee],
    measured: &Measured,
    n: u64,
    opt: Option<u64>,
    lower_bound: Option<u64>,
) -> (Vec<Verdict>, Option<bool>) {
    let verdicts: Vec<Verdict> = applicable
        .iter()
        .map(|g| Verdict {
            bound: g.to_string(),
            factor: g.factor(),
            holds: g.decide(measured, n, opt, lower_bound),
        })
        .collect();
    let within_guarantee = if verdicts.is_empty() {
        None
    } else if verdicts.iter().any(|v| v.holds == Some(false)) {
        Some(false)
    } else if verdicts.iter().all(|v| v.holds == Some(true)) {
        Some(true)
    } else {
        None
    };
    (verdicts, within_guarantee)
}

/// The proven lower bound on the optimum of `objective` on an orthogonal polygon, exactly,
/// with its source. Length: the larger of area − 1 and the erosion's extent
/// ([`crate::ortho::lower_bounds`]; the paper's contour bound is not proven here and not
/// used). Turns (of a tour or a cycle cover): 4, the turns of any closed walk.
pub fn ortho_bound(
    polygon: &crate::ortho::Polygon,
    objective: Objective,
) -> Result<(crate::ortho::Rational, String)> {
    use crate::ortho::Rational;
    let erosion = crate::ortho::feasibility(polygon).map_err(|e| Error::invalid(e.to_string()))?;
    match objective {
        Objective::Length => {
            let b = crate::ortho::lower_bounds(polygon, &erosion)?;
            let source = if b.area >= b.extent {
                "area: L >= area - 1"
            } else {
                "extent: L >= 2 (w_B + h_B)"
            };
            Ok((b.proven(), source.to_string()))
        }
        _ => {
            let b = crate::ortho::turn_lower_bound(polygon, &erosion)?;
            let source = if b.convex_corners >= b.rooks {
                "forced convex-corner turns"
            } else {
                "independent points (rooks)"
            };
            Ok((Rational::from(b.best() as i64), source.to_string()))
        }
    }
}

/// The cheap lower bound on the optimum of `objective` on a discrete instance: the star
/// cover's greedy rooks for turns (every cycle cover, hence every tour, turns at least once
/// per rook), n for length (n ≥ 2: every vertex is left by an edge), the sum of both bounds for
/// the weighted objectives.
pub fn discrete_cheap_bound(inst: &Discrete, objective: Objective) -> (u64, String) {
    use crate::discrete::star_cover;
    let rooks = || {
        let ch = star_cover::channels(inst);
        star_cover::greedy_rooks(inst, &ch).0.len() as u64
    };
    let length = if inst.len() >= 2 {
        inst.len() as u64
    } else {
        0
    };
    match objective {
        Objective::Length => (length, "n: every vertex is visited".to_string()),
        Objective::Turns | Objective::CcTurns => (
            rooks(),
            "rooks: the greedy star cover's rooks (Lemma 4.3)".to_string(),
        ),
        Objective::Weighted(c) | Objective::WeightedCc(c) => {
            (length + u64::from(c) * rooks(), "n + C rooks".to_string())
        }
        Objective::LawnLength | Objective::LawnTsp => (0, "none".to_string()),
    }
}

/// The objective whose exact optimum is the optimum of an algorithm objective. Lawn mowing has
/// none: the exact `lawn-tsp` through the pixel centres is the αTSP = 1 reference of Theorem 2,
/// not the optimal lawn-mowing tour (which may be shorter), so dividing a guarantee against
/// OPT by it would be unsound.
pub fn exact_counterpart(objective: Objective) -> Option<Objective> {
    match objective {
        Objective::LawnLength => None,
        o => Some(o),
    }
}

/// The checker's recount of `cover` for `objective`: the milling checker, or for lawn tours the
/// lawn checker where the cutter's motion is Euclidean (lengths in milli-units).
pub fn recount(
    region: &Region,
    cover: &CycleCover,
    objective: Objective,
    cutter: Cutter,
) -> Report {
    if objective == Objective::LawnLength && lawn_check::is_milli(cutter) {
        let lawn = lawn_check::check_lawn(region, cover, cutter);
        return Report {
            valid: lawn.valid,
            length: lawn.length,
            turns: 0,
            cycles: lawn.cycles,
            max_coverage: 0,
            error: lawn.error,
            coverage: Vec::new(),
            violation: None,
        };
    }
    checker::check(region, cover, objective.mode())
}

/// Runs `f`, turning a panic into an error message.
pub fn guarded<T>(f: impl FnOnce() -> Result<T>) -> std::result::Result<T, String> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(x)) => Ok(x),
        Ok(Err(e)) => Err(e.to_string()),
        Err(panic) => Err(format!(
            "panic: {}",
            panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown".into())
        )),
    }
}

/// The option names that change what `subject` computes for its objectives: `merge` and
/// `coverage4` for algorithms that merge cycle covers into tours, `cutter` for lawn tours.
pub fn relevant_options(objectives: &[Objective]) -> (bool, bool, bool) {
    let merge = objectives.contains(&Objective::CcTurns) && objectives.contains(&Objective::Turns);
    let coverage4 = objectives.contains(&Objective::Turns);
    let cutter = objectives.contains(&Objective::LawnLength);
    (merge, cutter, coverage4)
}

/// The name of an algorithm run with `options` in the `algorithm` column: the plain name with
/// the default options, else the name with the non-default relevant options in brackets, e.g.
/// `strips-matching[merge=naive,coverage4]`, so that statistics never mix variants.
pub fn variant_name(name: &str, objectives: &[Objective], options: &Options) -> String {
    let (merge, cutter, coverage4) = relevant_options(objectives);
    let mut parts = Vec::new();
    if merge && options.merge != Merge::default() {
        parts.push(format!("merge={}", options.merge));
    }
    if cutter && options.cutter != Cutter::default() {
        parts.push(format!("cutter={}", options.cutter));
    }
    if coverage4 && options.coverage4 {
        parts.push("coverage4".to_string());
    }
    if parts.is_empty() {
        name.to_string()
    } else {
        format!("{name}[{}]", parts.join(","))
    }
}

/// Splits a variant name (see [`variant_name`]) into the algorithm name and its options.
pub fn parse_variant(s: &str) -> Result<(&str, Options)> {
    let Some((name, rest)) = s.split_once('[') else {
        return Ok((s, Options::default()));
    };
    let inner = rest
        .strip_suffix(']')
        .ok_or_else(|| Error::invalid(format!("{s:?}: expected NAME[option,...]")))?;
    let mut options = Options::default();
    for part in inner.split(',') {
        match part.split_once('=') {
            Some(("merge", v)) => options.merge = v.parse().map_err(Error::invalid)?,
            Some(("cutter", v)) => options.cutter = v.parse().map_err(Error::invalid)?,
            None if part == "coverage4" => options.coverage4 = true,
            _ => {
                return Err(Error::invalid(format!(
                    "{s:?}: unknown option {part:?} (expected merge=..., cutter=... or coverage4)"
                )));
            }
        }
    }
    Ok((name, options))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variant_names_round_trip() {
        let objectives = [Objective::CcTurns, Objective::Turns];
        let options = Options {
            merge: Merge::Naive,
            coverage4: true,
            ..Options::default()
        };
        let name = variant_name("strips-matching", &objectives, &options);
        assert_eq!(name, "strips-matching[merge=naive,coverage4]");
        let (base, back) = parse_variant(&name).unwrap();
        assert_eq!(base, "strips-matching");
        assert_eq!((back.merge, back.coverage4), (Merge::Naive, true));
        // Options that do not concern the algorithm leave its name alone.
        assert_eq!(
            variant_name("tsp65", &[Objective::Length], &options),
            "tsp65"
        );
        assert!(parse_variant("tsp65[speed=11]").is_err());
    }
}
