//! The cut loop shared by every model: an LP cutting-plane phase, reduced-cost fixing, then
//! MIP rounds with the whole cut pool, each integer solution either accepted (feasible) or cut
//! off and repaired into a feasible incumbent.
//!
//! HiGHS has no lazy-constraint callback, so connectivity is enforced outside the solver:
//!
//! 1. **LP phase.** The LP relaxation is re-solved from its previous basis after each round of
//!    cuts separated on the fractional solution (exact minimum cuts, see [`super::cuts`]),
//!    until no cut is violated. Every LP optimum, rounded up to the next even integer, is a
//!    proven bound: every objective here is even on every integer solution (closed walks in
//!    the bipartite grid have even length and an even number of quarter turns).
//! 2. **Reduced-cost fixing.** With an incumbent of value U, a better solution costs at most
//!    U − 2; an integer column whose LP reduced cost `d` would lift the LP bound above U − 2
//!    when moved `k` units off its bound is restricted to fewer than `k` units. The restricted
//!    model R contains every solution better than U, so `min(opt(R), U)` is a proven bound.
//! 3. **MIP rounds.** HiGHS solves R with the whole pool, started from the incumbent. A
//!    feasible MIP optimum is optimal. Otherwise the cuts it violates join the pool (and the
//!    LP, which is separated again), the solution is repaired into a feasible candidate
//!    incumbent, and the MIP is solved again. The MIP's optimum, and on a time limit its dual
//!    bound, are proven bounds.
//!
//! The loop stops as soon as the incumbent meets the best bound; nothing else is optimal.
//!
//! Between the first LP phase and the MIP rounds, a **large-neighbourhood search** improves
//! the incumbent (models with windows only, [`CutModel::window`]): every integer column
//! outside a window of a few hundred pixels is fixed to the incumbent's value and a short MIP
//! re-optimises the window (with the cut pool; a solution that breaks connectivity is
//! repaired). It is a primal heuristic only: its solutions are checked like every other
//! incumbent, and nothing it solves is used as a bound (a window's optimum bounds nothing
//! but the window).
//!
//! [`run_or_improve`] with `primal_only` runs the primal side alone (LP phase, then the
//! search from the caller's start), each window's MIP stopped after a number of
//! branch-and-bound nodes rather than seconds: the heuristic algorithm `lp-lns` of the registry, which rounds the LP to its start itself. Its
//! answer's bound is still proven (the LP phase is the exact solver's). Rounding the LP inside
//! the model (fixing the columns the LP leaves integral, or every column outside the LP's
//! support, and solving the rest) was tried and dropped: on the thesis's 1000-pixel instances
//! both restricted MIPs were infeasible.
//!
//! "Even" above is the grid's case: a model whose integer values are only known to be
//! integers (discrete milling on general graphs) says so through [`CutModel::step`], and the
//! rounding, the target `U − step` and the MIP's proof gap follow it.

use super::lp::{
    Deadline, Formulation, IncrementalLp, LpSolution, Outcome, Row, Settings, ceil_bound, solve_mip,
};
use std::collections::HashSet;

/// What a model gives the driver.
pub trait CutModel {
    fn formulation(&self) -> &Formulation;
    /// Cuts violated by `x` (fractional or integral), as rows of the formulation.
    /// Cuts violated by `x`; past `deadline` a separation may stop early with the cuts found.
    fn separate(&self, x: &[f64], integral: bool, deadline: &Deadline) -> Vec<Row>;
    /// Whether an integral `x` satisfying the formulation is feasible for the problem.
    fn is_feasible(&self, x: &[f64]) -> bool;
    /// A feasible solution built from an integer solution of a relaxation, if the model can.
    fn repair(&self, x: &[f64]) -> Option<Vec<f64>>;
    /// Bounds valid for every integer solution of value at most `target` (tightened in place).
    fn tighten(&self, _f: &mut Formulation, _target: u64) {}
    /// Upper bounds on columns for a quick heuristic MIP (not valid restrictions: its
    /// solutions only become incumbents).
    fn heuristic_caps(&self) -> Option<Vec<f64>> {
        None
    }
    /// The spacing of the objective's values on integer solutions: every integer solution's
    /// value is a multiple of `step` (2 on the grid, where closed walks have even length and an
    /// even number of quarter turns; 1 where nothing is known). Bounds are rounded up to a
    /// multiple of it, and a MIP gap below it is a proof.
    fn step(&self) -> u64 {
        2
    }
    /// How many elements (pixels) the large-neighbourhood search can centre a window on; 0:
    /// the model has no windows and the search is skipped.
    fn elements(&self) -> usize {
        0
    }
    /// The integer columns of a window of about `size` elements around element `centre` (the
    /// large-neighbourhood search re-optimises them with every other column fixed).
    fn window(&self, _centre: usize, _size: usize) -> Vec<usize> {
        Vec::new()
    }
}

/// The share of the remaining time the large-neighbourhood search may take.
const LNS_SHARE: f64 = 0.5;
/// The time limit of one window's MIP, in seconds.
const LNS_WINDOW_SECONDS: f64 = 3.0;
/// The first window's size, in elements; it grows while windows solve fast and shrinks
/// when they run out of time.
const LNS_FIRST_SIZE: usize = 150;

/// The heuristic's node limit of a window's MIP ([`run_or_improve`] with `primal_only`): most
/// windows solve in the root or a few nodes.
const WINDOW_NODES: u32 = 200;
/// The heuristic's first window size: smaller than [`LNS_FIRST_SIZE`], more windows in the
/// same time (measured on the thesis's 1000-pixel instances: 100 reached the values of 150 in
/// half the time).
const IMPROVE_FIRST_SIZE: usize = 100;

/// Why the driver stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum Stop {
    Optimal,
    TimeLimit,
    Infeasible,
    Error(String),
}

/// The driver's answer: the best feasible solution, its value and the proven bound.
#[derive(Clone, Debug)]
pub struct Solved {
    pub stop: Stop,
    pub best: Option<Vec<f64>>,
    pub upper: Option<u64>,
    pub lower: u64,
    pub lower_source: &'static str,
    pub lp_bound: Option<u64>,
    pub rounds: u32,
}

/// Rounds a proven real bound up to the next multiple of `step` (the spacing of the
/// objective's values on integer solutions, [`CutModel::step`]).
pub fn step_bound(b: f64, step: u64) -> Option<u64> {
    let step = step.max(1);
    ceil_bound(b).map(|v| v.div_ceil(step) * step)
}

struct Loop<'m, M: CutModel> {
    model: &'m M,
    deadline: &'m Deadline,
    settings: &'m Settings,
    s: Solved,
    pool: Vec<Row>,
    seen: HashSet<(Vec<u32>, Vec<u64>)>,
    lp: IncrementalLp,
    last_lp: Option<LpSolution>,
}

impl<'m, M: CutModel> Loop<'m, M> {
    /// A fresh loop: nothing found yet, `lower` the bound known before it starts (one
    /// constructor for the full solve and the LP phase alone).
    fn new(
        model: &'m M,
        lower: (u64, &'static str),
        deadline: &'m Deadline,
        settings: &'m Settings,
    ) -> Self {
        Loop {
            model,
            deadline,
            settings,
            s: Solved {
                stop: Stop::TimeLimit,
                best: None,
                upper: None,
                lower: lower.0,
                lower_source: lower.1,
                lp_bound: None,
                rounds: 0,
            },
            pool: Vec::new(),
            seen: HashSet::new(),
            lp: IncrementalLp::new(model.formulation(), *settings),
            last_lp: None,
        }
    }

    fn f(&self) -> &'m Formulation {
        self.model.formulation()
    }

    fn log(&self, msg: impl FnOnce() -> String) {
        if self.settings.verbose {
            eprintln!("exact [{:7.2} s] {}", self.deadline.elapsed(), msg());
        }
    }

    fn value(&self, x: &[f64]) -> u64 {
        self.f().objective(x).round().max(0.0) as u64
    }

    fn offer(&mut self, x: Vec<f64>, from: &str) {
        let v = self.value(&x);
        if self.s.upper.is_none_or(|u| v < u) {
            self.log(|| format!("incumbent {v} from {from}"));
            self.s.upper = Some(v);
            self.s.best = Some(x);
        }
    }

    fn raise(&mut self, b: u64, source: &'static str) {
        let b = self.s.upper.map_or(b, |u| b.min(u));
        if b > self.s.lower {
            self.log(|| format!("bound {b} from {source}"));
            self.s.lower = b;
            self.s.lower_source = source;
        }
    }

    fn done(&self) -> bool {
        self.s.upper.is_some_and(|u| u <= self.s.lower)
    }

    fn round_integers(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(&self.f().integer)
            .map(|(&v, &int)| if int { v.round() } else { v })
            .collect()
    }

    fn accepts(&self, xi: &[f64]) -> bool {
        self.f().is_feasible(xi, &[]) && self.model.is_feasible(xi)
    }

    /// New cuts only (the pool never holds a row twice).
    fn add_cuts(&mut self, cuts: Vec<Row>) -> Vec<Row> {
        let fresh: Vec<Row> = cuts
            .into_iter()
            .filter(|r| {
                self.seen
                    .insert((r.idx.clone(), r.val.iter().map(|v| v.to_bits()).collect()))
            })
            .collect();
        self.pool.extend(fresh.iter().cloned());
        self.lp.add_rows(&fresh);
        fresh
    }

    /// Re-solves and separates the LP until no cut is violated, or (unless `converge`) until
    /// the LP value has stalled for a few rounds: the MIP rounds separate what is left.
    fn lp_phase(&mut self, converge: bool) -> Result<(), Stop> {
        const STALL_ROUNDS: u32 = 3;
        let mut stalled = 0;
        let mut last = f64::NEG_INFINITY;
        for _ in 0..1000 {
            if self.deadline.expired() {
                return Err(Stop::TimeLimit);
            }
            let sol = self.lp.solve(self.deadline);
            match &sol.outcome {
                Outcome::Optimal => {}
                Outcome::TimeLimit => return Err(Stop::TimeLimit),
                Outcome::Infeasible => return Err(Stop::Infeasible),
                Outcome::Failed(m) => return Err(Stop::Error(m.clone())),
            }
            if let Some(b) = step_bound(sol.objective, self.model.step()) {
                self.s.lp_bound = Some(self.s.lp_bound.map_or(b, |old| old.max(b)));
                self.raise(b, "lp relaxation with cuts");
            }
            let cuts = self.model.separate(&sol.x, false, self.deadline);
            let objective = sol.objective;
            self.last_lp = Some(sol);
            let fresh = self.add_cuts(cuts);
            if fresh.is_empty() {
                return Ok(());
            }
            stalled = if objective > last + 1e-6 {
                0
            } else {
                stalled + 1
            };
            last = last.max(objective);
            if !converge && stalled >= STALL_ROUNDS {
                self.log(|| format!("LP stalled at {objective:.3}"));
                return Ok(());
            }
            self.s.rounds += 1;
            self.log(|| {
                format!(
                    "LP round {}: value {objective:.3}, {} new cuts",
                    self.s.rounds,
                    fresh.len()
                )
            });
        }
        Ok(())
    }

    /// The model R: every solution better than the incumbent, with bounds from the model's
    /// own argument and from reduced costs.
    fn restricted(&self) -> Formulation {
        let Some(u) = self.s.upper else {
            return self.f().clone();
        };
        let target = u.saturating_sub(self.model.step());
        let mut g = self.f().clone();
        self.model.tighten(&mut g, target);
        match &self.last_lp {
            Some(sol) => fix_by_reduced_cost(&g, sol, target as f64),
            None => g,
        }
    }

    /// An integral LP optimum that is feasible is an incumbent (and then optimal).
    fn offer_integral_lp(&mut self) {
        if let Some(sol) = &self.last_lp {
            let xi = self.round_integers(&sol.x);
            if self.accepts(&xi) && self.pool.iter().all(|r| r.violation(&xi) < 1e-6) {
                self.offer(xi, "integral LP");
            }
        }
    }

    /// A quick MIP with the model's heuristic caps, for an incumbent.
    fn heuristic_phase(&mut self) {
        let Some(caps) = self.model.heuristic_caps() else {
            return;
        };
        let mut g = self.restricted();
        for (h, c) in g.hi.iter_mut().zip(&caps) {
            *h = h.min(*c);
        }
        for j in 0..g.num_cols() {
            g.lo[j] = g.lo[j].min(g.hi[j]);
        }
        let budget = self.deadline.remaining().map_or(30.0, |r| r * 0.25);
        let cap = Deadline::new(Some(budget));
        let start = self.s.best.clone().filter(|x| g.is_feasible(x, &self.pool));
        // Stop within three even steps of the capped model's bound: the proof MIP that follows
        // improves the incumbent if it can, and proving the capped model is wasted work.
        let mip = solve_mip(
            &g,
            &self.pool,
            start.as_deref(),
            &cap,
            self.settings,
            Some(3.0 * self.model.step() as f64 - 0.01),
        );
        self.s.rounds += 1;
        if let Some(x) = &mip.x {
            let xi = self.round_integers(x);
            self.take(xi, ("heuristic mip", "heuristic mip, repaired"));
        }
    }

    /// Offers an integer solution of a heuristic MIP: as it is when the model accepts it,
    /// else its repair, keeping the cuts it violates. `from` names the two cases in the log.
    fn take(&mut self, xi: Vec<f64>, from: (&str, &str)) {
        if self.accepts(&xi) {
            self.offer(xi, from.0);
        } else {
            let cuts = self.model.separate(&xi, true, self.deadline);
            if let Some(r) = self.model.repair(&xi) {
                self.offer(r, from.1);
            }
            self.add_cuts(cuts);
        }
    }

    /// The large-neighbourhood search (module docs): windows centred on the model's elements
    /// in a fixed scattered order, until its share of the time is spent, the incumbent meets
    /// the bound, or the windows since the last improvement hold 2n elements in all.
    ///
    /// With a node limit (`nodes`, the heuristic of [`run_or_improve`]) each window's MIP
    /// stops after that many nodes instead of [`LNS_WINDOW_SECONDS`], the window grows after a solved window and shrinks
    /// after a stopped one, and the search may take all of the remaining time: its course
    /// then depends on the work done, not on the clock (the clock only stops it at the
    /// deadline).
    fn lns_phase(&mut self, nodes: Option<u32>) {
        let n = self.model.elements();
        if n == 0 || self.done() || self.s.best.is_none() {
            return;
        }
        let share = if nodes.is_some() { 1.0 } else { LNS_SHARE };
        let budget = self.deadline.remaining().map_or(120.0, |r| r * share);
        let phase = Deadline::new(Some(budget));
        let settings = Settings {
            node_limit: nodes,
            ..*self.settings
        };
        // A stride coprime to n visits every element once per n windows, far apart.
        let gcd = |mut a: usize, mut b: usize| {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            a
        };
        let mut stride = (n as f64 * 0.618) as usize | 1;
        while gcd(stride, n) != 1 {
            stride += 1;
        }
        let first = if nodes.is_some() {
            IMPROVE_FIRST_SIZE
        } else {
            LNS_FIRST_SIZE
        };
        // Node-limited windows grow at most to twice the first size and, above the first
        // size, half the region: a node of a larger window's MIP costs more, and the node
        // limit alone would not bound it (a window of the whole region is the whole MIP again
        // and again: 7 windows in 30 s on a 200-pixel weighted tour). A region of at most the
        // first size is one window, the whole node-limited MIP.
        let max_size = match nodes {
            Some(_) if n <= first => n,
            Some(_) => (2 * first).min(n / 2),
            None => n,
        };
        let mut size = first.min(max_size);
        // Elements in the windows since the last improvement.
        let mut covered = 0usize;
        let mut i = 0usize;
        while !phase.expired() && !self.deadline.expired() && !self.done() {
            let Some(x) = self.s.best.clone() else { return };
            let centre = (i * stride) % n;
            i += 1;
            let mut free = vec![false; x.len()];
            for j in self.model.window(centre, size) {
                free[j] = true;
            }
            let mut g = self.f().clone();
            for j in 0..g.num_cols() {
                if g.integer[j] && !free[j] {
                    g.lo[j] = x[j];
                    g.hi[j] = x[j];
                }
            }
            let remaining = phase.remaining().unwrap_or(LNS_WINDOW_SECONDS);
            let limit = if nodes.is_some() {
                remaining
            } else {
                remaining.min(LNS_WINDOW_SECONDS)
            };
            let window = Deadline::new(Some(limit.max(0.05)));
            let before = self.s.upper;
            let mip = solve_mip(&g, &self.pool, Some(&x), &window, &settings, None);
            if let Some(y) = &mip.x {
                let yi = self.round_integers(y);
                if self.value(&yi) < before.unwrap_or(u64::MAX) {
                    self.take(
                        yi,
                        ("neighbourhood search", "neighbourhood search, repaired"),
                    );
                }
            }
            covered = if self.s.upper < before {
                0
            } else {
                covered + size
            };
            if covered >= 2 * n {
                break;
            }
            // Grow a window that solved in a fraction of its time, shrink one that did not.
            let quick = nodes.is_some() || window.elapsed() < 0.3 * limit;
            size = match mip.outcome {
                Outcome::Optimal if quick => (size + size / 4).min(n).min(max_size),
                Outcome::TimeLimit => (size * 3 / 4).max(20.min(n)),
                _ => size,
            };
        }
        self.log(|| format!("neighbourhood search: {i} windows, last size {size}"));
    }

    fn finish(mut self, stop: Stop) -> Solved {
        if let Some(u) = self.s.upper
            && self.s.lower >= u
        {
            self.s.lower = u;
            self.s.stop = Stop::Optimal;
            return self.s;
        }
        self.s.stop = match stop {
            Stop::Optimal => Stop::Error("internal: optimal without matching bounds".into()),
            other => other,
        };
        self.s
    }

    fn run(mut self) -> Solved {
        if self.done() {
            return self.finish(Stop::Optimal);
        }
        if let Err(stop) = self.lp_phase(false) {
            return self.finish(stop);
        }
        // An integral LP optimum that is feasible is optimal.
        self.offer_integral_lp();
        if !self.done() {
            // The capped MIP only where the model has no windows: on the passage models the
            // windows found better incumbents in the capped MIP's time (eroded sparse 1500,
            // cc-turns: 15 s of capped MIP found nothing, 17 s of windows 794 -> 740).
            if self.model.elements() == 0 {
                self.heuristic_phase();
            } else {
                self.lns_phase(None);
            }
            if let Err(stop) = self.lp_phase(false) {
                return self.finish(stop);
            }
        }
        loop {
            if self.done() {
                return self.finish(Stop::Optimal);
            }
            if self.deadline.expired() {
                return self.finish(Stop::TimeLimit);
            }
            let restricted = self.restricted();
            let mip = solve_mip(
                &restricted,
                &self.pool,
                self.s.best.as_deref(),
                self.deadline,
                self.settings,
                Some(self.model.step() as f64 - 0.01),
            );
            self.s.rounds += 1;
            match &mip.outcome {
                Outcome::Failed(m) => return self.finish(Stop::Error(m.clone())),
                Outcome::Infeasible => {
                    // No solution better than the incumbent exists (or none at all).
                    return match self.s.upper {
                        Some(u) => {
                            self.raise(u, "mip");
                            self.finish(Stop::Optimal)
                        }
                        None => self.finish(Stop::Infeasible),
                    };
                }
                Outcome::TimeLimit => {
                    if let Some(b) = step_bound(mip.dual_bound, self.model.step()) {
                        self.raise(b, "mip dual bound");
                    }
                    if let Some(x) = &mip.x {
                        let xi = self.round_integers(x);
                        if self.accepts(&xi) {
                            self.offer(xi, "mip");
                        } else if let Some(r) = self.model.repair(&xi) {
                            self.offer(r, "repair");
                        }
                    }
                    let stop = if self.done() {
                        Stop::Optimal
                    } else {
                        Stop::TimeLimit
                    };
                    return self.finish(stop);
                }
                Outcome::Optimal => {}
            }
            let Some(x) = &mip.x else {
                return self.finish(Stop::Error(
                    "HiGHS reported an optimal MIP without a solution".into(),
                ));
            };
            // Optimal within an absolute gap below 2 on an even objective: the optimum of R.
            let step = self.model.step() as f64;
            if let Some(b) = step_bound(
                mip.dual_bound.max(mip.objective - (step - 0.01)),
                self.model.step(),
            ) {
                self.raise(b, "mip");
            }
            let xi = self.round_integers(x);
            if self.accepts(&xi) {
                self.offer(xi, "mip");
                let stop = if self.done() {
                    Stop::Optimal
                } else {
                    Stop::Error("MIP optimum and bound disagree".into())
                };
                return self.finish(stop);
            }
            let cuts = self.model.separate(&xi, true, self.deadline);
            self.log(|| {
                format!(
                    "MIP round {}: value {:.1}, {} violated cuts",
                    self.s.rounds,
                    mip.objective,
                    cuts.len()
                )
            });
            if let Some(r) = self.model.repair(&xi) {
                self.offer(r, "repair");
            }
            if self.done() {
                return self.finish(Stop::Optimal);
            }
            if self.add_cuts(cuts).is_empty() {
                return self.finish(Stop::Error(
                    "separation found no cut for an infeasible integer solution".into(),
                ));
            }
            if let Err(stop) = self.lp_phase(false) {
                return self.finish(stop);
            }
        }
    }
    /// The primal side alone ([`run_or_improve`] with `primal_only`): LP phase, node-limited
    /// search.
    fn improve(mut self) -> Solved {
        if self.done() {
            return self.finish(Stop::Optimal);
        }
        if let Err(stop) = self.lp_phase(false) {
            return self.finish(stop);
        }
        self.offer_integral_lp();
        self.lns_phase(Some(WINDOW_NODES));
        let stop = if self.done() {
            Stop::Optimal
        } else {
            Stop::TimeLimit
        };
        self.finish(stop)
    }
}

/// Runs the loop. `start` is a feasible solution (the caller validated it), `lower` a proven
/// bound with its source.
pub fn run<M: CutModel>(
    model: &M,
    start: Option<Vec<f64>>,
    lower: (u64, &'static str),
    deadline: &Deadline,
    settings: &Settings,
) -> Solved {
    run_or_improve(model, start, lower, deadline, settings, false)
}

/// [`run`] (to prove) or, with `primal_only`, the heuristic: the LP phase and the
/// large-neighbourhood search with node-limited MIPs (module docs), no proof. The heuristic's
/// `lower` is still proven (the cheap bound or the LP's), and its `stop` is `Optimal` only
/// when the incumbent meets it, otherwise `TimeLimit`, whether the deadline or the search's
/// own end stopped it.
pub fn run_or_improve<M: CutModel>(
    model: &M,
    start: Option<Vec<f64>>,
    lower: (u64, &'static str),
    deadline: &Deadline,
    settings: &Settings,
    primal_only: bool,
) -> Solved {
    let mut l = Loop::new(model, lower, deadline, settings);
    if let Some(x) = start
        && l.accepts(&x)
    {
        l.offer(x, "start");
    }
    if primal_only { l.improve() } else { l.run() }
}

/// [`run_or_improve`] on a model whose objective leaves out a `constant` (parts of the
/// instance outside it, such as isolated vertices' one-vertex walks): `lower` bounds the whole value, and the
/// answer's values include the constant. A model without columns has one solution, the empty
/// one, of value `constant`.
pub fn run_with_constant<M: CutModel>(
    model: &M,
    start: Option<Vec<f64>>,
    (lower, source): (u64, &'static str),
    constant: u64,
    deadline: &Deadline,
    settings: &Settings,
    primal_only: bool,
) -> Solved {
    if model.formulation().num_cols() == 0 {
        return Solved {
            stop: Stop::Optimal,
            best: Some(Vec::new()),
            upper: Some(constant),
            lower: constant,
            lower_source: source,
            lp_bound: None,
            rounds: 0,
        };
    }
    let inner = lower.saturating_sub(constant);
    let mut s = run_or_improve(
        model,
        start,
        (inner, source),
        deadline,
        settings,
        primal_only,
    );
    s.upper = s.upper.map(|u| u + constant);
    s.lower += constant;
    s.lp_bound = s.lp_bound.map(|b| b + constant);
    s
}

/// The LP relaxation's bound with all its cuts (the LP phase alone), if it converges in time.
pub fn lp_bound<M: CutModel>(model: &M, deadline: &Deadline, settings: &Settings) -> Option<u64> {
    let mut l = Loop::new(model, (0, ""), deadline, settings);
    let _ = l.lp_phase(true);
    l.s.lp_bound
}

/// The LP relaxation's optimal solution with all its cuts (the LP phase alone), if it
/// converges in time.
pub fn lp_solution<M: CutModel>(
    model: &M,
    deadline: &Deadline,
    settings: &Settings,
) -> Option<Vec<f64>> {
    let mut l = Loop::new(model, (0, ""), deadline, settings);
    l.lp_phase(true).ok()?;
    l.last_lp.map(|sol| sol.x)
}

/// Restricts integer columns that cannot move away from their LP bound in any solution of
/// value at most `target` (reduced-cost fixing).
fn fix_by_reduced_cost(f: &Formulation, sol: &LpSolution, target: f64) -> Formulation {
    let mut g = f.clone();
    if sol.reduced_cost.len() != f.num_cols() {
        return g;
    }
    let slack = target - sol.objective;
    if slack < -1e-6 && f.num_cols() > 0 {
        // Even the LP cannot reach the target: R is empty.
        g.lo[0] = 1.0;
        g.hi[0] = 0.0;
        return g;
    }
    for j in 0..f.num_cols() {
        if !f.integer[j] {
            continue;
        }
        let d = sol.reduced_cost[j];
        let x = sol.x[j];
        if d > 1e-7 && (x - f.lo[j]).abs() < 1e-7 {
            let k = ((slack + 1e-6) / d).floor();
            if f.lo[j] + k < g.hi[j] {
                g.hi[j] = f.lo[j] + k;
            }
        } else if d < -1e-7 && f.hi[j].is_finite() && (x - f.hi[j]).abs() < 1e-7 {
            let k = ((slack + 1e-6) / -d).floor();
            if f.hi[j] - k > g.lo[j] {
                g.lo[j] = f.hi[j] - k;
            }
        }
    }
    g
}
