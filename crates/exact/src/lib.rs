//! Exact baselines: proven optima (or proven bounds) of the six objectives, the ground truth
//! the harness divides by.
//!
//! Every objective is solved with embedded HiGHS (through the `highs` crate; module `lp` says
//! why not through good_lp) by the same loop (module `driver`): an LP cutting-plane phase with
//! exact minimum-cut separation on fractional solutions, reduced-cost fixing against the
//! incumbent, a quick capped MIP for a good incumbent, and MIP rounds that keep the whole cut
//! pool, cut off infeasible integer solutions and repair them into incumbents. Cheap bounds
//! ([`crate::bounds`]) and a warm start (an approximation's tour, or a constructive
//! heuristic) stop the loop early when the incumbent meets a bound: then no MIP is solved.
//!
//! # Formulations
//!
//! * **`length`** (module `milling`): integer edge multiplicities `x_e ∈ {0, 1, 2}` on the
//!   grid graph and `z_v >= 1` with `Σ_{e ∋ v} x_e = 2 z_v` (even degree, every pixel
//!   visited); `x(δ(S)) >= 2` for all proper pixel sets `S` (connectivity); minimize
//!   `Σ x_e`. The walk is an Euler tour of `x`. (Milling paper, Section 6: TSP on the grid
//!   graph with revisits.)
//! * **`cc-turns`** (module `turns`): integer passage counts `p_{v,ab}` for every pixel `v`
//!   and pair of its sides `{a, b}` (`a = b` a U-turn); coverage `Σ_ab p_{v,ab} >= 1`; on each
//!   grid edge the passage ends at both sides agree (the edge's multiplicity); minimize
//!   `Σ turn(ab) p` with turn 0 straight, 1 perpendicular, 2 U-turn; an isolated pixel is a
//!   one-pixel walk of 4 turns. U-turns are only offered at the end of their strip (pushing a
//!   U-turn along its strip keeps the turns). (Turn-cost paper, Sections 2 and 4.)
//! * **`turns`** (also spelled `tour-turns`): the passage model plus connectivity cuts on the graph of pixel sides
//!   (passages join sides of a pixel, edges join facing sides): `Σ_{edges across S} x_e +
//!   Σ_{passages across S} p >= 2` for side sets `S` holding all sides of one pixel and none of
//!   another. Plain edge connectivity would allow walks that only cross each other, which no
//!   free splice can join (a plus of five pixels: 8 turns as two crossing strips, 10 as a tour).
//! * **`weighted`** with turn cost `C`: the tour model minimizing `Σ (1 + C turn(ab)) p`, i.e.
//!   length + C · turns (turn-cost paper, Section 5.6); the length of a walk is its number of
//!   passages. Every U-turn is offered (pushing one costs length).
//! * **`weighted-cc`** with turn cost `C`: the cycle-cover model minimizing
//!   `Σ (1 + C turn(ab)) p` over passages (every U-turn offered) plus, for every pixel with a
//!   neighbour, a binary column `s_v` of cost 4C in its coverage row: the one-pixel walk that
//!   the checker counts as length 0 and 4 turns. The 2018 CPLEX study whose main table uses
//!   this objective (C = 50) has no such walks; see docs/exact.md for the difference.
//! * **`lawn-tsp`** (module `lawn`): binary `y_ij` on all pairs of grass pixels with L1 costs,
//!   degree 2, subtour elimination `Σ_{i,j ∈ S} y_ij <= |S| - 1` on the smaller side of each
//!   violated cut. (Milling paper, Section 4, the αTSP = 1 reference.)
//!
//! # Proofs
//!
//! Every objective is even on every integer solution: a closed walk in the bipartite grid has
//! even length, and it returns to its heading, so it makes an even number of quarter turns (a
//! U-turn counts 2). Real bounds (LP values, HiGHS's dual bounds) are therefore rounded up to
//! the next even integer after subtracting 10⁻⁶ for round-off, and a MIP gap below 2 is a
//! proof. Models restricted by bounds that only hold for solutions better than the incumbent
//! `U` (reduced-cost fixing; the turn budget bounding passage counts) yield `min(opt, U)` as
//! the bound. The returned tour or cycle cover always goes through [`crate::checker::check`],
//! its recounted cost is `value`, and `status` is `optimal` only when `value` equals the
//! proven `lower_bound`.
//!
//! `weighted-cc`: every cycle cover the checker accepts (milling mode) is an integer
//! solution of its model of the same cost, and conversely. A walk of two or more pixels
//! gives one passage per visit (its length) with the turn of each visit, and the passages
//! balance on every edge; a one-pixel walk at a pixel with a neighbour is `s_v = 1` (a second
//! one at the same pixel only adds cost, hence the bound 1); at an isolated pixel it is the
//! constant 4C outside the model. Conversely the balanced passages decompose into closed
//! walks (`walks::passage_walks`) of that length and turn count, and `s_v = 1` is a one-pixel
//! walk. So the model's optimum is the optimum over checker-valid cycle covers, and its
//! LP and MIP bounds (plus the constant) bound it. Every integer solution has an even value
//! (each closed walk has even length and an even number of turns, a one-pixel walk costs
//! 4C), so rounding bounds up to even is sound. The reduced-cost and budget bounds
//! (`PassageModel::tighten`) use only: turns ≤ value / C (length ≥ 0), every other pixel
//! costs at least 1 (a passage costs 1 + C·turn, a one-pixel walk 4C ≥ 4 for C ≥ 1; with
//! C = 0 nothing is assumed), and the link argument of `cc-turns` for straight passes. The
//! cheap bound is C times the turn bound of cycle covers (length ≥ 0). `optimal` is then set,
//! as for every objective, only when the checker's recount of the returned cover equals the
//! proven bound.

// The building blocks below are public for the matching LP of the algorithms crate; the
// discrete exact models ([`discrete`]) assemble their formulations from them too. They are not
// part of the documented surface.
#[doc(hidden)]
pub mod cuts;
pub mod discrete;
#[doc(hidden)]
pub mod driver;
mod goal;
mod lawn;
#[doc(hidden)]
pub mod lp;
pub mod matching;
mod milling;
mod turns;
#[doc(hidden)]
pub mod walks;

// The core's modules under the paths the models use (this crate is built on the core alone:
// it cannot reach an algorithm, the registry or the harness).
pub(crate) use mowmill_core::{bounds, checker, euler, flow, region, strip_cover, topology, tour};

use crate::bounds::LowerBound;
use crate::region::Region;
use crate::tour::CycleCover;
use driver::{CutModel, Solved, Stop};
use lp::{Deadline, Settings, as_columns};
use serde::Serialize;
use std::fmt;

/// The HiGHS version linked into this binary.
pub fn highs_version() -> String {
    // SAFETY: the HiGHS version getters take no arguments and only return constants.
    let (major, minor, patch) = unsafe {
        (
            highs_sys::Highs_versionMajor(),
            highs_sys::Highs_versionMinor(),
            highs_sys::Highs_versionPatch(),
        )
    };
    format!("{major}.{minor}.{patch}")
}

/// The objective of an exact solve: the one objective type of the core (the exact solver
/// takes `length`, `cc-turns`, `turns`, `weighted`, `weighted-cc` and `lawn-tsp`:
/// [`Objective::EXACT_NAMES`]; a lawn tour's `lawn-length` is refused).
pub use mowmill_core::objective::Objective;

/// Options of an exact solve.
#[derive(Clone, Debug)]
pub struct ExactOptions {
    /// Wall-clock limit in seconds for the whole solve (None: no limit).
    pub time_limit: Option<f64>,
    /// HiGHS threads per solve (default 1: parallelism comes from running many solves).
    pub threads: usize,
    /// Print HiGHS's log and the cut loop's progress to stderr.
    pub verbose: bool,
    /// A known cover to start from (e.g. an approximation's tour); used when the checker
    /// accepts it for the objective.
    pub warm_start: Option<CycleCover>,
    /// Turn objectives only: visit every pixel at most this many times (Theorem 5.6 of the
    /// turn-cost paper says 4 costs no turns). The optimum is then the optimum under the cap.
    pub max_coverage: Option<u32>,
    /// Without a `warm_start`, ask this source for one (its time counts in the solve's). The
    /// exact solver knows no algorithm: the caller passes the source, usually
    /// `mowmill::warm_start::from_registry` (the best cover of the registered approximation
    /// algorithms). `None`: no warm start unless `warm_start` is given.
    pub starts: Option<StartFn>,
    /// The primal side only ([`driver::run_or_improve`] with `primal_only`): the LP phase and a large-neighbourhood
    /// search from the best start, its MIPs stopped after a number of nodes; no proof. The
    /// status is `optimal` only when the walk meets the proven bound (then it is optimal);
    /// otherwise `time_limit`. The heuristic algorithm `lp-lns` runs this from its rounding.
    pub heuristic: bool,
}

/// What a warm-start source is asked for: a checker-valid cover of `region` for `objective`
/// (a tour for the tour objectives), visiting no pixel more than `max_coverage` times when
/// set, found before `stop_after` (half of the solve's time) when there is a limit.
#[derive(Clone, Copy, Debug)]
pub struct StartRequest<'a> {
    pub region: &'a Region,
    pub objective: Objective,
    pub max_coverage: Option<u32>,
    /// Start no further work after this instant.
    pub stop_after: Option<std::time::Instant>,
}

/// A source of warm starts (see [`ExactOptions::starts`]).
pub type StartFn = fn(&StartRequest<'_>) -> Option<CycleCover>;

impl Default for ExactOptions {
    fn default() -> Self {
        ExactOptions {
            time_limit: None,
            threads: 1,
            verbose: false,
            warm_start: None,
            max_coverage: None,
            starts: None,
            heuristic: false,
        }
    }
}

/// How an exact solve ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// `value` equals the proven `lower_bound`.
    Optimal,
    /// Out of time: `value` is the best incumbent (if any), `lower_bound` the best proven bound.
    TimeLimit,
    /// No cover of this kind exists (e.g. a tour of a disconnected region).
    Infeasible,
    /// Something went wrong; see `message`.
    Error,
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Status::Optimal => "optimal",
            Status::TimeLimit => "time_limit",
            Status::Infeasible => "infeasible",
            Status::Error => "error",
        })
    }
}

/// The answer of an exact solve, on any model: `W` is the model's walks (a grid
/// [`CycleCover`], or the vertex walks of a discrete instance). The JSON keys `objective, value,
/// lower_bound, status, seconds, rounds, length, turns, cycles, valid` are a stable contract.
#[derive(Clone, Debug, Serialize)]
pub struct ExactResult<W = CycleCover> {
    pub objective: String,
    /// The checker's recount of the objective for `cover`.
    pub value: Option<u64>,
    /// A proven lower bound on the optimum.
    pub lower_bound: u64,
    pub status: Status,
    pub seconds: f64,
    /// Rounds of cut separation (LP and MIP).
    pub rounds: u32,
    pub length: Option<u64>,
    pub turns: Option<u64>,
    pub cycles: Option<usize>,
    /// Whether the checker accepted `cover`.
    pub valid: bool,
    pub message: Option<String>,
    /// Which bound `lower_bound` is.
    pub lb_source: String,
    /// The LP relaxation bound with all cuts, when the LP phase ran.
    pub lp_bound: Option<u64>,
    /// The turn cost C of `weighted`.
    pub turn_cost: Option<u32>,
    /// Number of pixels (vertices).
    pub n: usize,
    /// The cap on visits per pixel the optimum is taken under (`--max-coverage`), if any.
    pub coverage_cap: Option<u32>,
    /// The checker's largest number of visits of one pixel (vertex) in `cover`.
    pub max_coverage: Option<u32>,
    /// `(value − lower_bound) / value` at a time limit with a walk (the MIP's relative gap;
    /// `None` when optimal or without a walk).
    pub gap: Option<f64>,
    #[serde(skip)]
    pub cover: Option<W>,
}

impl<W> ExactResult<W> {
    /// The result before its walks are checked: no value, status `error` until
    /// [`certify`].
    fn unchecked(objective: Objective, lower: (u64, &str), rounds: u32) -> Self {
        ExactResult {
            objective: objective.name().to_string(),
            value: None,
            lower_bound: lower.0,
            status: Status::Error,
            seconds: 0.0,
            rounds,
            length: None,
            turns: None,
            cycles: None,
            valid: false,
            message: None,
            lb_source: lower.1.to_string(),
            lp_bound: None,
            turn_cost: objective.turn_cost(),
            n: 0,
            coverage_cap: None,
            max_coverage: None,
            gap: None,
            cover: None,
        }
    }

    /// Takes `cover` with the checker's `report` of it when the report is a valid answer to
    /// `objective` (valid, one walk for a tour, within the coverage cap, not below the proven
    /// bound); otherwise the message says why not, prefixed `internal:` (a solver defect).
    fn accept<V>(
        &mut self,
        objective: Objective,
        cover: W,
        report: &checker::Report<V>,
    ) -> Option<String> {
        let value = objective.value_of(report);
        if !report.valid {
            Some(format!(
                "internal: the checker rejected the cover: {}",
                report.error.clone().unwrap_or_default()
            ))
        } else if objective.is_tour() && report.cycles != 1 {
            Some(format!(
                "internal: a tour with {} closed walks",
                report.cycles
            ))
        } else if self.coverage_cap.is_some_and(|c| report.max_coverage > c) {
            Some(format!(
                "internal: a pixel visited {} times, above the cap",
                report.max_coverage
            ))
        } else if value < self.lower_bound {
            Some(format!(
                "internal: value {value} below the proven bound {}",
                self.lower_bound
            ))
        } else {
            self.value = Some(value);
            self.length = Some(report.length);
            self.turns = Some(report.turns);
            self.cycles = Some(report.cycles);
            self.max_coverage = Some(report.max_coverage);
            self.valid = true;
            self.cover = Some(cover);
            None
        }
    }
}

/// What an objective's solver hands back before its walks are checked, on any model (`W`: a
/// grid cover, or the vertex walks of a discrete instance).
#[doc(hidden)]
pub struct Answer<W = CycleCover> {
    pub stop: Stop,
    pub cover: Option<W>,
    pub lower: LowerBound,
    pub lp_bound: Option<u64>,
    pub rounds: u32,
}

impl<W> Answer<W> {
    /// An optimum known without a solve (a one-pixel instance).
    pub fn trivial(cover: W, lower: LowerBound) -> Self {
        Answer {
            stop: Stop::Optimal,
            cover: Some(cover),
            lower,
            lp_bound: None,
            rounds: 0,
        }
    }

    /// No walks: the solve stopped (infeasible, an error) before it began.
    pub fn stopped(stop: Stop, lower: LowerBound) -> Self {
        Answer {
            stop,
            cover: None,
            lower,
            lp_bound: None,
            rounds: 0,
        }
    }

    /// The driver's answer with the walks decoded from its solution; the bound is the better
    /// of the driver's and the cheap one.
    pub fn from_solved(s: Solved, cover: Option<W>, cheap: LowerBound) -> Self {
        let lower = if s.lower > cheap.value {
            LowerBound {
                value: s.lower,
                source: s.lower_source,
            }
        } else {
            cheap
        };
        Answer {
            stop: s.stop,
            cover,
            lower,
            lp_bound: s.lp_bound,
            rounds: s.rounds,
        }
    }

    /// The checked result: the walks recounted by the model's `check`er, the status `optimal`
    /// only when the recount equals the proven bound. `n` is the instance's size, `cap` the
    /// coverage cap, `infeasible` the message of an infeasible model.
    pub fn into_result<V>(
        self,
        objective: Objective,
        (seconds, n, cap): (f64, usize, Option<u32>),
        infeasible: &str,
        check: impl FnOnce(&W) -> checker::Report<V>,
    ) -> ExactResult<W> {
        let mut r = ExactResult::unchecked(
            objective,
            (self.lower.value, self.lower.source),
            self.rounds,
        );
        r.seconds = seconds;
        r.lp_bound = self.lp_bound;
        r.n = n;
        r.coverage_cap = cap;
        let mut message = match &self.stop {
            Stop::Error(m) => Some(m.clone()),
            Stop::Infeasible => Some(infeasible.to_string()),
            _ => None,
        };
        if let Some(cover) = self.cover {
            let report = check(&cover);
            message = r.accept(objective, cover, &report).or(message);
        }
        r.status = certify(&self.stop, r.value, r.lower_bound, &mut message);
        r.gap = relative_gap(r.status == Status::TimeLimit, r.value, r.lower_bound);
        r.message = message;
        r
    }
}

/// The relative gap `(value − bound) / value` of a solve stopped at its time limit with a walk
/// of value `value > 0` (`None` otherwise).
pub fn relative_gap(time_limit: bool, value: Option<u64>, lower_bound: u64) -> Option<f64> {
    value
        .filter(|&v| time_limit && v > 0)
        .map(|v| v.saturating_sub(lower_bound) as f64 / v as f64)
}

/// The status of a solve, the one rule for both models' certificates: `optimal` only when the
/// checker's recount of the walk (`value`) equals the proven lower bound and nothing went
/// wrong (`message` holds the first problem found, e.g. a walk the checker rejects); a time
/// limit without any walk says so in `message`.
pub(crate) fn certify(
    stop: &Stop,
    value: Option<u64>,
    lower_bound: u64,
    message: &mut Option<String>,
) -> Status {
    let status = match (stop, value) {
        _ if message.is_some() && !matches!(stop, Stop::Infeasible) => Status::Error,
        (Stop::Infeasible, _) => Status::Infeasible,
        (_, Some(v)) if v == lower_bound => Status::Optimal,
        (Stop::Error(_), _) => Status::Error,
        _ => Status::TimeLimit,
    };
    if status == Status::TimeLimit && value.is_none() {
        message.get_or_insert_with(|| "time limit before any feasible cover".into());
    }
    status
}

/// Solves `objective` on `region` exactly, within `opts.time_limit`.
///
/// # Arguments
/// * `region` — the pixels (the grass, for `lawn-tsp`).
/// * `objective` — one of the six objectives.
/// * `opts` — time limit, threads, verbosity and an optional warm start.
///
/// # Returns
/// An [`ExactResult`] whose cover has passed the checker with recounted cost `value`, a proven
/// `lower_bound`, and `status` `optimal` exactly when the two are equal.
///
/// # Complexity
/// Exponential in the worst case (all six problems are NP-hard); see the `exact_scaling`
/// benchmark and docs/measured.md and docs/exact.md for measured times.
///
/// # Guarantee
/// `status == optimal` implies `value` is the optimum; otherwise `lower_bound <= OPT <= value`.
///
/// # Examples
/// ```
/// use mowmill_exact::{solve, ExactOptions, Objective, Status};
/// use mowmill_core::Region;
/// let r = Region::rectangle(3, 3);
/// let res = solve(&r, Objective::Length, &ExactOptions::default());
/// assert_eq!(res.status, Status::Optimal);
/// assert_eq!(res.value, Some(10));
/// ```
pub fn solve(region: &Region, objective: Objective, opts: &ExactOptions) -> ExactResult {
    let deadline = Deadline::new(opts.time_limit);
    let started;
    let opts = if let (None, Some(source)) = (&opts.warm_start, opts.starts) {
        let request = StartRequest {
            region,
            objective,
            max_coverage: opts.max_coverage,
            stop_after: opts.time_limit.and_then(|t| {
                let half = std::time::Duration::try_from_secs_f64(t / 2.0).ok()?;
                std::time::Instant::now().checked_add(half)
            }),
        };
        started = ExactOptions {
            warm_start: source(&request),
            ..opts.clone()
        };
        &started
    } else {
        opts
    };
    let settings = Settings {
        threads: opts.threads.max(1),
        verbose: opts.verbose,
        ..Settings::default()
    };
    let answer = if region.is_empty() {
        Answer::stopped(
            Stop::Error("the region is empty".into()),
            LowerBound {
                value: 0,
                source: "empty region",
            },
        )
    } else if opts.max_coverage.is_some() && !objective.counts_turns() {
        Answer::stopped(
            Stop::Error(
                "a coverage cap applies to cc-turns, turns, weighted and weighted-cc only".into(),
            ),
            LowerBound {
                value: 0,
                source: "none",
            },
        )
    } else {
        match objective {
            Objective::Length => solve_length(region, opts, &deadline, &settings),
            Objective::CcTurns
            | Objective::Turns
            | Objective::Weighted(_)
            | Objective::WeightedCc(_) => {
                solve_turns(region, objective, opts, &deadline, &settings)
            }
            Objective::LawnTsp => solve_lawn(region, opts, &deadline, &settings),
            Objective::LawnLength => Answer::stopped(
                Stop::Error(
                    "the exact solver has no lawn-length objective (a lawn tour in its \
                     cutter's metric); its lawn objective is lawn-tsp"
                        .into(),
                ),
                LowerBound {
                    value: 0,
                    source: "none",
                },
            ),
        }
    };
    assemble(
        region,
        objective,
        answer,
        deadline.elapsed(),
        opts.max_coverage,
    )
}

/// The checked result: the cover is recounted, and the status is `optimal` only when the
/// recount equals the proven bound.
fn assemble(
    region: &Region,
    objective: Objective,
    a: Answer,
    seconds: f64,
    cap: Option<u32>,
) -> ExactResult {
    let infeasible = if objective.is_tour() && objective != Objective::LawnTsp {
        "no covering tour exists: the region is not connected"
    } else {
        "the model is infeasible"
    };
    a.into_result(
        objective,
        (seconds, region.len(), cap),
        infeasible,
        |cover| checker::check(region, cover, objective.mode()),
    )
}

fn not_connected(region: &Region) -> bool {
    topology::components(region).count > 1
}

/// A warm-start cover accepted by the checker for this objective.
fn checked_warm_start<'c>(
    region: &Region,
    objective: Objective,
    opts: &'c ExactOptions,
) -> Option<&'c CycleCover> {
    let c = opts.warm_start.as_ref()?;
    let rep = checker::check(region, c, objective.mode());
    (rep.valid && (!objective.is_tour() || rep.cycles == 1)).then_some(c)
}

fn solve_length(
    region: &Region,
    opts: &ExactOptions,
    deadline: &Deadline,
    settings: &Settings,
) -> Answer {
    let lower = bounds::length_lower_bound(region);
    if not_connected(region) {
        return Answer::stopped(Stop::Infeasible, lower);
    }
    if region.len() <= 2 {
        return Answer::trivial(CycleCover::tour(region.pixels().to_vec()), lower);
    }
    let model = milling::MillingModel::new(region);
    let mut start = model.columns(&milling::tree_tour(&model));
    if let Some(mult) = checked_warm_start(region, Objective::Length, opts)
        .and_then(|c| model.walk_multiplicities(&c.cycles[0]))
    {
        let x = model.columns(&mult);
        if model.formulation().objective(&x) < model.formulation().objective(&start) {
            start = x;
        }
    }
    let s = driver::run_or_improve(
        &model,
        Some(start),
        (lower.value, lower.source),
        deadline,
        settings,
        opts.heuristic,
    );
    let cover = s
        .best
        .as_ref()
        .map(|x| CycleCover::tour(model.walk(&model.multiplicities(x))));
    Answer::from_solved(s, cover, lower)
}

fn solve_turns(
    region: &Region,
    objective: Objective,
    opts: &ExactOptions,
    deadline: &Deadline,
    settings: &Settings,
) -> Answer {
    let lower = cheap_lower_bound(region, objective);
    let goal = goal::TurnGoal::of(objective).expect("solve_turns is called for turn objectives");
    if objective.is_tour() {
        if not_connected(region) {
            return Answer::stopped(Stop::Infeasible, lower);
        }
        if region.len() == 1 {
            return Answer::trivial(CycleCover::tour(region.pixels().to_vec()), lower);
        }
    }
    let model = turns::PassageModel::new(region, goal, opts.max_coverage);
    // Isolated pixels are one-pixel walks outside the model: 4 turns each.
    let constant = model.isolated_cost();
    let value = |counts: &Vec<u32>| model.formulation().objective(&as_columns(counts));
    let warm = checked_warm_start(region, objective, opts)
        .and_then(|c| model.walk_counts(&c.cycles))
        .filter(|counts| model.is_feasible_counts(counts));
    let start = [warm, model.strip_solution()]
        .into_iter()
        .flatten()
        .min_by(|a, b| value(a).total_cmp(&value(b)))
        .map(|counts| as_columns(&counts));
    let s = driver::run_with_constant(
        &model,
        start,
        (lower.value, lower.source),
        constant,
        deadline,
        settings,
        opts.heuristic,
    );
    let cover = s
        .best
        .as_ref()
        .map(|x| CycleCover::new(model.walks(&model.counts(x))));
    Answer::from_solved(s, cover, lower)
}

fn solve_lawn(
    region: &Region,
    opts: &ExactOptions,
    deadline: &Deadline,
    settings: &Settings,
) -> Answer {
    let lower = bounds::lawn_tsp_lower_bound(region);
    let n = region.len();
    if n <= 3 {
        // One cyclic order only (up to reversal).
        return Answer::trivial(CycleCover::tour(lawn::lawn_walk(region.pixels())), lower);
    }
    let model = lawn::LawnModel::new(region);
    let mut order = model.heuristic_tour();
    if let Some(c) = checked_warm_start(region, Objective::LawnTsp, opts) {
        // The first visits of the grass pixels in the warm walk, improved.
        let mut seen = vec![false; n];
        let mut warm: Vec<usize> = Vec::new();
        for p in &c.cycles[0] {
            if let Some(i) = region.index_of(*p)
                && !std::mem::replace(&mut seen[i], true)
            {
                warm.push(i);
            }
        }
        model.improve(&mut warm);
        let cost = |o: &[usize]| model.formulation().objective(&model.columns(o));
        if warm.len() == n && cost(&warm) < cost(&order) {
            order = warm;
        }
    }
    let s = driver::run_or_improve(
        &model,
        Some(model.columns(&order)),
        (lower.value, lower.source),
        deadline,
        settings,
        opts.heuristic,
    );
    let cover = s
        .best
        .as_ref()
        .map(|x| CycleCover::tour(model.walk(&model.order(x))));
    Answer::from_solved(s, cover, lower)
}

/// The best cheap bound for an objective (no LP; the bounds of [`crate::bounds`]).
pub fn cheap_lower_bound(region: &Region, objective: Objective) -> LowerBound {
    match objective {
        Objective::Length => bounds::length_lower_bound(region),
        Objective::CcTurns | Objective::Turns => bounds::turn_lower_bound(region),
        Objective::Weighted(turn_cost) => {
            // Both bounds hold for the same tour.
            let l = bounds::length_lower_bound(region).value;
            let t = bounds::turn_lower_bound(region).value;
            LowerBound::new(
                l + u64::from(turn_cost) * t,
                "length bound + C * turn bound",
            )
        }
        Objective::WeightedCc(turn_cost) => {
            // A one-pixel walk has length 0, so only the turns bound a cycle cover.
            let t = bounds::turn_lower_bound(region).value;
            LowerBound::new(u64::from(turn_cost) * t, "C * turn bound")
        }
        Objective::LawnTsp => bounds::lawn_tsp_lower_bound(region),
        // Not an exact objective: no cheap bound is claimed for it here.
        Objective::LawnLength => LowerBound::new(0, "none"),
    }
}

/// The LP relaxation of the exact model with all its connectivity cuts, rounded up to even;
/// `None` if it did not converge within `time_limit` seconds (or the problem is infeasible).
pub fn lp_lower_bound(
    region: &Region,
    objective: Objective,
    time_limit: Option<f64>,
) -> Option<LowerBound> {
    lp_relaxation_bound(region, objective, time_limit)
        .map(|v| LowerBound::new(v, "lp relaxation with cuts"))
}

/// The largest available bound: the cheap ones and, when `lp_time_limit` is given, the LP
/// relaxation.
pub fn best_lower_bound(
    region: &Region,
    objective: Objective,
    lp_time_limit: Option<f64>,
) -> LowerBound {
    let cheap = cheap_lower_bound(region, objective);
    match lp_time_limit.and_then(|t| lp_lower_bound(region, objective, Some(t))) {
        Some(lp) => cheap.max(lp),
        None => cheap,
    }
}

/// The LP relaxation of a turn objective's passage model with all its connectivity cuts, as
/// orientation weights per pixel (index as in `region`): `[horizontal, vertical]`, how much of
/// the pixel's fractional passages run each way (a straight pass counts 1 for its
/// orientation, a 90° turn 1/2 for each, a U-turn 1 for the orientation of its side). `None`
/// for other objectives, a region of fewer than 2 pixels, a disconnected region for a tour,
/// or an LP that does not converge within `time_limit` seconds. The heuristic `lp-lns`
/// rounds these weights to a strip cover.
pub fn lp_orientation(
    region: &Region,
    objective: Objective,
    time_limit: Option<f64>,
) -> Option<Vec<[f64; 2]>> {
    let goal = goal::TurnGoal::of(objective)?;
    if region.len() < 2 || (objective.is_tour() && not_connected(region)) {
        return None;
    }
    let model = turns::PassageModel::new(region, goal, None);
    if model.formulation().num_cols() == 0 {
        return None;
    }
    let deadline = Deadline::new(time_limit);
    let settings = Settings {
        threads: 1,
        ..Settings::default()
    };
    let x = driver::lp_solution(&model, &deadline, &settings)?;
    Some(model.orientation(&x))
}

/// The LP relaxation bound of an objective's exact model with all its connectivity cuts
/// (rounded up to even), or `None` if it does not converge in time or does not apply.
pub(crate) fn lp_relaxation_bound(
    region: &Region,
    objective: Objective,
    time_limit: Option<f64>,
) -> Option<u64> {
    let deadline = Deadline::new(time_limit);
    let settings = Settings {
        threads: 1,
        verbose: false,
        ..Settings::default()
    };
    if region.len() < 3
        || (objective.is_tour() && objective != Objective::LawnTsp && not_connected(region))
    {
        return None;
    }
    match objective {
        Objective::Length => {
            driver::lp_bound(&milling::MillingModel::new(region), &deadline, &settings)
        }
        Objective::CcTurns
        | Objective::Turns
        | Objective::Weighted(_)
        | Objective::WeightedCc(_) => {
            let goal = goal::TurnGoal::of(objective)?;
            let model = turns::PassageModel::new(region, goal, None);
            let constant = model.isolated_cost();
            if model.formulation().num_cols() == 0 {
                return None;
            }
            driver::lp_bound(&model, &deadline, &settings).map(|b| b + constant)
        }
        Objective::LawnTsp => driver::lp_bound(&lawn::LawnModel::new(region), &deadline, &settings),
        Objective::LawnLength => None,
    }
}
