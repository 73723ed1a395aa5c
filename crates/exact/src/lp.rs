//! A thin layer over embedded HiGHS: a model in plain vectors ([`Formulation`]), an LP that
//! keeps its basis while cuts are added ([`IncrementalLp`]), and one-shot MIP solves
//! ([`solve_mip`]) that report the proven dual bound and take a start solution.
//!
//! This talks to the `highs` crate directly rather than through good_lp: good_lp rebuilds the
//! whole model on every solve and exposes neither adding rows to a solved model (the cutting
//! plane loop re-solves the LP from the previous basis, dual simplex, after each round of
//! cuts), nor the LP's reduced costs (used for reduced-cost fixing), nor the MIP's dual bound
//! (the proven `lower_bound` of a `time_limit` answer). `highs-sys` is used for one thing the
//! `highs` crate lacks: with `--verbose`, HiGHS's log goes through its logging callback to
//! stderr, so that stdout stays clean for `--json`.

use highs::{Col, HighsModelStatus, Model, RowProblem, Sense};
use std::ffi::{CStr, c_char, c_int, c_void};
use std::time::Instant;

/// One linear constraint `lo <= Σ val[k] · x[idx[k]] <= hi`.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub idx: Vec<u32>,
    pub val: Vec<f64>,
    pub lo: f64,
    pub hi: f64,
}

impl Row {
    /// `Σ terms >= lo`.
    pub fn at_least(terms: impl IntoIterator<Item = (usize, f64)>, lo: f64) -> Row {
        Row::range(terms, lo, f64::INFINITY)
    }

    /// `lo <= Σ terms <= hi`, merging repeated columns.
    pub fn range(terms: impl IntoIterator<Item = (usize, f64)>, lo: f64, hi: f64) -> Row {
        let mut t: Vec<(usize, f64)> = terms.into_iter().collect();
        t.sort_unstable_by_key(|&(i, _)| i);
        let mut idx: Vec<u32> = Vec::with_capacity(t.len());
        let mut val: Vec<f64> = Vec::with_capacity(t.len());
        for (i, v) in t {
            if idx.last() == Some(&(i as u32)) {
                *val.last_mut().expect("same length") += v;
            } else {
                idx.push(i as u32);
                val.push(v);
            }
        }
        let (idx, val) = idx.into_iter().zip(val).filter(|&(_, v)| v != 0.0).unzip();
        Row { idx, val, lo, hi }
    }

    /// The row's activity at `x`.
    pub fn activity(&self, x: &[f64]) -> f64 {
        self.idx
            .iter()
            .zip(&self.val)
            .map(|(&i, &v)| v * x[i as usize])
            .sum()
    }

    /// How far `x` violates the row (0 when satisfied).
    pub fn violation(&self, x: &[f64]) -> f64 {
        let a = self.activity(x);
        (self.lo - a).max(a - self.hi).max(0.0)
    }
}

/// Integer counts (passages, edge multiplicities) as the columns of an LP solution.
pub fn as_columns(counts: &[u32]) -> Vec<f64> {
    counts.iter().map(|&c| f64::from(c)).collect()
}

/// A minimization model: columns with costs, bounds and integrality, and rows.
#[derive(Clone, Debug, Default)]
pub struct Formulation {
    pub cost: Vec<f64>,
    pub lo: Vec<f64>,
    pub hi: Vec<f64>,
    pub integer: Vec<bool>,
    pub rows: Vec<Row>,
}

impl Formulation {
    pub fn add_col(&mut self, cost: f64, lo: f64, hi: f64, integer: bool) -> usize {
        self.cost.push(cost);
        self.lo.push(lo);
        self.hi.push(hi);
        self.integer.push(integer);
        self.cost.len() - 1
    }

    pub fn num_cols(&self) -> usize {
        self.cost.len()
    }

    pub fn objective(&self, x: &[f64]) -> f64 {
        self.cost.iter().zip(x).map(|(c, v)| c * v).sum()
    }

    /// Whether `x` satisfies bounds, integrality and every row (including `extra`).
    pub fn is_feasible(&self, x: &[f64], extra: &[Row]) -> bool {
        const TOL: f64 = 1e-6;
        x.len() == self.num_cols()
            && (0..x.len()).all(|j| {
                x[j] >= self.lo[j] - TOL
                    && x[j] <= self.hi[j] + TOL
                    && (!self.integer[j] || (x[j] - x[j].round()).abs() <= TOL)
            })
            && self.rows.iter().chain(extra).all(|r| r.violation(x) <= TOL)
    }

    fn to_problem(&self, integral: bool, extra: &[Row]) -> (RowProblem, Vec<Col>) {
        let mut pb = RowProblem::default();
        let cols: Vec<Col> = (0..self.num_cols())
            .map(|j| {
                pb.add_column_with_integrality(
                    self.cost[j],
                    self.lo[j]..=self.hi[j],
                    integral && self.integer[j],
                )
            })
            .collect();
        for r in self.rows.iter().chain(extra) {
            add_row_to_problem(&mut pb, &cols, r);
        }
        (pb, cols)
    }
}

fn add_row_to_problem(pb: &mut RowProblem, cols: &[Col], r: &Row) {
    let terms: Vec<(Col, f64)> = r
        .idx
        .iter()
        .zip(&r.val)
        .map(|(&i, &v)| (cols[i as usize], v))
        .collect();
    match (r.lo.is_finite(), r.hi.is_finite()) {
        (true, true) => pb.add_row(r.lo..=r.hi, terms),
        (true, false) => pb.add_row(r.lo.., terms),
        (false, true) => pb.add_row(..=r.hi, terms),
        (false, false) => pb.add_row(f64::NEG_INFINITY..=f64::INFINITY, terms),
    }
}

/// Wall-clock budget of one exact solve.
#[derive(Clone, Copy, Debug)]
pub struct Deadline {
    start: Instant,
    limit: Option<f64>,
}

impl Deadline {
    pub fn new(limit: Option<f64>) -> Deadline {
        Deadline {
            start: Instant::now(),
            limit,
        }
    }

    pub fn elapsed(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// Seconds left, `None` without a limit.
    pub fn remaining(&self) -> Option<f64> {
        self.limit.map(|l| (l - self.elapsed()).max(0.0))
    }

    pub fn expired(&self) -> bool {
        self.remaining().is_some_and(|r| r <= 0.0)
    }
}

/// Solver settings shared by every HiGHS call of one exact solve.
#[derive(Clone, Copy, Debug, Default)]
pub struct Settings {
    pub threads: usize,
    pub verbose: bool,
    /// A MIP stops after this many branch-and-bound nodes (HiGHS's `mip_max_nodes`): a work
    /// limit, unlike a time limit the same on every machine, for the heuristic searches whose
    /// answers must not depend on the machine's speed. `None`: no limit.
    pub node_limit: Option<u32>,
}

/// HiGHS's log, sent to stderr so that stdout stays clean for `--json`.
unsafe extern "C" fn log_to_stderr(
    _kind: c_int,
    message: *const c_char,
    _out: *const highs_sys::HighsCallbackDataOut,
    _in: *mut highs_sys::HighsCallbackDataIn,
    _user: *mut c_void,
) {
    if !message.is_null() {
        // SAFETY: HiGHS passes a NUL-terminated message that lives for the call.
        let text = unsafe { CStr::from_ptr(message) };
        eprint!("{}", text.to_string_lossy());
    }
}

fn configure(model: &mut Model, s: &Settings) {
    if s.verbose {
        model.set_option("output_flag", true);
        model.set_option("log_to_console", false);
        // SAFETY: the pointer is the live HiGHS instance owned by `model`; the callback is a
        // plain function without user data.
        unsafe {
            highs_sys::Highs_setCallback(
                model.as_mut_ptr(),
                Some(log_to_stderr),
                std::ptr::null_mut(),
            );
            highs_sys::Highs_startCallback(model.as_mut_ptr(), highs_sys::kHighsCallbackLogging);
        }
    } else {
        model.make_quiet();
    }
    model.set_option("threads", s.threads.max(1) as i32);
    // Every objective here takes even integer values on every integer solution (closed walks
    // in the bipartite grid), so an absolute gap below 2 proves optimality; no relative slack.
    model.set_option("mip_rel_gap", 0.0);
    model.set_option("mip_abs_gap", 1.99);
    if let Some(nodes) = s.node_limit {
        model.set_option("mip_max_nodes", nodes.min(i32::MAX as u32) as i32);
    }
}

/// How a HiGHS call ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    Optimal,
    /// Stopped at the time limit, or at a work limit (nodes, iterations, solutions).
    TimeLimit,
    Infeasible,
    Failed(String),
}

fn outcome(status: HighsModelStatus) -> Outcome {
    match status {
        HighsModelStatus::Optimal => Outcome::Optimal,
        HighsModelStatus::ReachedTimeLimit
        | HighsModelStatus::ReachedInterrupt
        | HighsModelStatus::ReachedSolutionLimit
        | HighsModelStatus::ReachedIterationLimit => Outcome::TimeLimit,
        HighsModelStatus::Infeasible => Outcome::Infeasible,
        s => Outcome::Failed(format!("HiGHS ended with status {s:?}")),
    }
}

/// An LP solution with reduced costs.
#[derive(Clone, Debug)]
pub struct LpSolution {
    pub outcome: Outcome,
    pub objective: f64,
    pub x: Vec<f64>,
    pub reduced_cost: Vec<f64>,
}

/// The LP relaxation of a formulation, kept alive between rounds of cuts so that each
/// re-solve starts from the previous optimal basis.
pub struct IncrementalLp {
    model: Option<Model>,
    cols: Vec<Col>,
    /// HiGHS's run clock accumulates over the runs of one model, and so does its time limit.
    spent: f64,
    pub rows: usize,
}

impl IncrementalLp {
    pub fn new(f: &Formulation, settings: Settings) -> IncrementalLp {
        let (pb, cols) = f.to_problem(false, &[]);
        let mut model = pb.optimise(Sense::Minimise);
        configure(&mut model, &settings);
        // Dual simplex re-solves from the previous basis after rows are added.
        model.set_option("presolve", "off");
        model.set_option("solver", "simplex");
        IncrementalLp {
            model: Some(model),
            cols,
            spent: 0.0,
            rows: f.rows.len(),
        }
    }

    pub fn add_rows(&mut self, rows: &[Row]) {
        let Some(model) = self.model.as_mut() else {
            return;
        };
        for r in rows {
            let terms = r
                .idx
                .iter()
                .zip(&r.val)
                .map(|(&i, &v)| (self.cols[i as usize], v));
            model.add_row(r.lo..=r.hi, terms);
        }
        self.rows += rows.len();
    }

    pub fn solve(&mut self, deadline: &Deadline) -> LpSolution {
        let failed = |m: String| LpSolution {
            outcome: Outcome::Failed(m),
            objective: f64::NAN,
            x: Vec::new(),
            reduced_cost: Vec::new(),
        };
        let Some(mut model) = self.model.take() else {
            return failed("the LP was lost after an earlier HiGHS error".into());
        };
        if let Some(r) = deadline.remaining() {
            model.set_option("time_limit", self.spent + r.max(1e-3));
        }
        let t = Instant::now();
        let solved = match model.try_solve() {
            Ok(s) => s,
            Err(e) => return failed(format!("HiGHS failed on the LP: {e:?}")),
        };
        self.spent += t.elapsed().as_secs_f64();
        let out = outcome(solved.status());
        let sol = solved.get_solution();
        let result = LpSolution {
            objective: solved.objective_value(),
            x: sol.columns().to_vec(),
            reduced_cost: sol.dual_columns().to_vec(),
            outcome: out,
        };
        self.model = Some(Model::from(solved));
        result
    }
}

/// An LP that grows by columns and by rows while HiGHS keeps its basis (column generation
/// with cutting planes: the matching LP of `strips-matching` prices pairs in and adds odd-set
/// cuts). Rows and columns are numbered in the order they are added; one thread, quiet, dual
/// simplex from the previous basis, no time limit (the caller bounds its rounds).
pub struct GrowingLp {
    model: Option<Model>,
    rows: Vec<highs::Row>,
    cols: Vec<Col>,
}

/// A [`GrowingLp`] optimum: primal values per column and duals per row.
#[derive(Clone, Debug)]
pub struct LpDuals {
    pub x: Vec<f64>,
    pub row_dual: Vec<f64>,
}

impl GrowingLp {
    /// A minimization LP with one row `lo <= · <= hi` per entry of `rows` and no columns.
    pub fn new(rows: &[(f64, f64)]) -> GrowingLp {
        let mut pb = highs::ColProblem::default();
        let handles = rows.iter().map(|&(lo, hi)| pb.add_row(lo..=hi)).collect();
        let mut model = pb.optimise(Sense::Minimise);
        model.make_quiet();
        model.set_option("threads", 1);
        model.set_option("presolve", "off");
        model.set_option("solver", "simplex");
        GrowingLp {
            model: Some(model),
            rows: handles,
            cols: Vec::new(),
        }
    }

    pub fn num_rows(&self) -> usize {
        self.rows.len()
    }

    /// Adds a column of cost `cost`, bounds `lo..`, and coefficients in existing rows.
    pub fn add_col(&mut self, cost: f64, lo: f64, terms: &[(usize, f64)]) -> Result<usize, String> {
        let model = self
            .model
            .as_mut()
            .ok_or("the LP was lost after a HiGHS error")?;
        let entries = terms.iter().map(|&(r, v)| (self.rows[r], v));
        let col = model
            .try_add_column(cost, lo.., entries)
            .map_err(|e| format!("HiGHS refused a column: {e:?}"))?;
        self.cols.push(col);
        Ok(self.cols.len() - 1)
    }

    /// Adds a row `lo <= Σ terms` over existing columns.
    pub fn add_row_at_least(&mut self, lo: f64, terms: &[(usize, f64)]) -> Result<usize, String> {
        let model = self
            .model
            .as_mut()
            .ok_or("the LP was lost after a HiGHS error")?;
        let entries = terms.iter().map(|&(c, v)| (self.cols[c], v));
        let row = model
            .try_add_row(lo.., entries)
            .map_err(|e| format!("HiGHS refused a row: {e:?}"))?;
        self.rows.push(row);
        Ok(self.rows.len() - 1)
    }

    /// Solves from the previous basis; an error unless HiGHS proves the LP optimal.
    pub fn solve(&mut self) -> Result<LpDuals, String> {
        let model = self
            .model
            .take()
            .ok_or("the LP was lost after a HiGHS error")?;
        let solved = model
            .try_solve()
            .map_err(|e| format!("HiGHS failed on the LP: {e:?}"))?;
        if solved.status() != HighsModelStatus::Optimal {
            return Err(format!(
                "HiGHS ended the LP with status {:?}",
                solved.status()
            ));
        }
        let sol = solved.get_solution();
        let duals = LpDuals {
            x: sol.columns().to_vec(),
            row_dual: sol.dual_rows().to_vec(),
        };
        self.model = Some(Model::from(solved));
        Ok(duals)
    }
}

/// A MIP answer: the best solution found (if any) and the proven dual bound.
#[derive(Clone, Debug)]
pub struct MipSolution {
    pub outcome: Outcome,
    pub x: Option<Vec<f64>>,
    pub objective: f64,
    /// A proven lower bound on the model's optimum (−∞ when HiGHS proved nothing).
    pub dual_bound: f64,
}

/// Solves `f` plus `extra` rows as a MIP from scratch, with an optional start solution.
/// `abs_gap`, when given, replaces the proof gap (for heuristic solves that may stop early).
pub fn solve_mip(
    f: &Formulation,
    extra: &[Row],
    start: Option<&[f64]>,
    deadline: &Deadline,
    settings: &Settings,
    abs_gap: Option<f64>,
) -> MipSolution {
    let (pb, _) = f.to_problem(true, extra);
    let mut model = pb.optimise(Sense::Minimise);
    configure(&mut model, settings);
    if let Some(g) = abs_gap {
        model.set_option("mip_abs_gap", g);
    }
    if let Some(r) = deadline.remaining() {
        model.set_option("time_limit", r.max(1e-3));
    }
    if let Some(x) = start
        && f.is_feasible(x, extra)
    {
        // A rejected start only costs HiGHS the search for its own first solution.
        let _ = model.try_set_solution(Some(x), None, None, None);
    }
    let solved = match model.try_solve() {
        Ok(s) => s,
        Err(e) => {
            return MipSolution {
                outcome: Outcome::Failed(format!("HiGHS failed on the MIP: {e:?}")),
                x: None,
                objective: f64::NAN,
                dual_bound: f64::NEG_INFINITY,
            };
        }
    };
    let out = outcome(solved.status());
    let has_solution = matches!(
        solved.primal_solution_status(),
        highs::HighsSolutionStatus::Feasible
    );
    let dual_bound = match out {
        Outcome::Infeasible => f64::INFINITY,
        _ => solved
            .double_info_value(c"mip_dual_bound")
            .unwrap_or(f64::NEG_INFINITY),
    };
    let x = has_solution.then(|| solved.get_solution().columns().to_vec());
    MipSolution {
        outcome: out,
        x,
        objective: solved.objective_value(),
        dual_bound,
    }
}

/// The smallest integer at least `b`, tolerating round-off of HiGHS's bounds.
pub fn ceil_bound(b: f64) -> Option<u64> {
    if !b.is_finite() || b <= 0.0 {
        return if b.is_finite() || b == f64::NEG_INFINITY {
            Some(0)
        } else {
            None
        };
    }
    Some((b - 1e-6).ceil().max(0.0) as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn growing_lp_prices_columns_and_cuts() {
        // min x + 2y + 3z, x + y = 1 (row 0), y + z = 1 (row 1): optimum y = 1, value 2.
        let mut lp = GrowingLp::new(&[(1.0, 1.0), (1.0, 1.0)]);
        let x = lp.add_col(1.0, 0.0, &[(0, 1.0)]).unwrap();
        let z = lp.add_col(3.0, 0.0, &[(1, 1.0)]).unwrap();
        let a = lp.solve().unwrap();
        assert_eq!((a.x[x], a.x[z]), (1.0, 1.0));
        let y = lp.add_col(2.0, 0.0, &[(0, 1.0), (1, 1.0)]).unwrap();
        let b = lp.solve().unwrap();
        assert!((b.x[y] - 1.0).abs() < 1e-9 && b.x[x].abs() < 1e-9);
        // Duals: y0 + y1 = 2 (y's reduced cost 0), y0 <= 1, y1 <= 3.
        assert!((b.row_dual[0] + b.row_dual[1] - 2.0).abs() < 1e-9);
        // A row x >= 1 forces x = 1 and then z = 1 (y = 0): value 4.
        lp.add_row_at_least(1.0, &[(x, 1.0)]).unwrap();
        let c = lp.solve().unwrap();
        assert!((c.x[x] - 1.0).abs() < 1e-9 && (c.x[z] - 1.0).abs() < 1e-9);
        assert_eq!(lp.num_rows(), 3);
    }

    #[test]
    fn incremental_lp_and_mip() {
        // min x + y, x + y >= 1.5, x, y in [0, 2]; MIP optimum 2, LP 1.5.
        let mut f = Formulation::default();
        let x = f.add_col(1.0, 0.0, 2.0, true);
        let y = f.add_col(1.0, 0.0, 2.0, true);
        f.rows.push(Row::at_least([(x, 1.0), (y, 1.0)], 1.5));
        let s = Settings {
            threads: 1,
            verbose: false,
            ..Settings::default()
        };
        let d = Deadline::new(Some(10.0));
        let mut lp = IncrementalLp::new(&f, s);
        let a = lp.solve(&d);
        assert_eq!(a.outcome, Outcome::Optimal);
        assert!((a.objective - 1.5).abs() < 1e-9);
        lp.add_rows(&[
            Row::at_least([(x, 1.0)], 1.0),
            Row::at_least([(y, 1.0)], 1.0),
        ]);
        let b = lp.solve(&d);
        assert!((b.objective - 2.0).abs() < 1e-9);
        let m = solve_mip(&f, &[], Some(&[2.0, 0.0]), &d, &s, None);
        assert_eq!(m.outcome, Outcome::Optimal);
        assert_eq!(ceil_bound(m.dual_bound), Some(2));
        assert!((m.objective - 2.0).abs() < 1e-9);
    }

    #[test]
    fn rows_merge_repeated_columns() {
        let r = Row::at_least([(3, 1.0), (1, 2.0), (3, 1.0), (2, 0.0)], 2.0);
        assert_eq!(r.idx, vec![1, 3]);
        assert_eq!(r.val, vec![2.0, 2.0]);
        assert_eq!(ceil_bound(3.0000000001), Some(3));
        assert_eq!(ceil_bound(2.4), Some(3));
    }
}
