//! The regression gate: compares a run with a committed baseline, deterministically (it never
//! compares timings).
//!
//! The gate does not trust the ratio columns of `results.csv`: it recomputes every ratio from
//! the row's integers (`value / opt`, `value / lower_bound`, `value / n`, as
//! [`Row::compute_ratios`] defines them) and builds the current statistics from the recomputed
//! ratios. Ratios are all of minimization objectives, so larger is worse.
//!
//! The baseline is a run directory: beside its `stats.csv` the gate reads that run's
//! `results.csv` and `manifest.json`, and compares **per instance** (rows keyed by sha256,
//! instance name up to whitespace and case, algorithm, objective and variant columns; this
//! decides) and per group (a summary). Only runs of the baseline's suite (its config digest)
//! compare, and every row is checked with [`Row::consistency_error`]: a value below a proven
//! bound is an invalid result, never an improvement. `docs/outputs.md` lists every rule; the
//! list below is the group summary's.
//!
//! It **refuses** (an error, exit 2) when
//! - the tolerance is not a finite number in `[0, 1)` (NaN, negative, infinite, or so large
//!   that a doubled ratio would pass);
//! - the baseline has no group of bin `all` (an empty file, a header only);
//! - a ratio of the baseline is not a finite number `>= 0` (NaN, `inf`, negative), or a ratio
//!   column has a positive count but an empty mean, median, p95 or max (or the reverse).
//!
//! It **fails** (exit 1) when
//! - a stored ratio of a current row disagrees with the ratio recomputed from its integers
//!   (including a NaN or infinite stored ratio, or a ratio where the integers give none);
//! - a row appears twice (same instance, algorithm and objective);
//! - a current result is invalid (`valid` is `false`), or has a value but no validity verdict;
//! - a guarantee is violated (`within_guarantee` is `false`);
//! - a group has more error rows than the baseline's, or error rows in a group the baseline
//!   does not have (e.g. an instance that failed to generate: algorithm `instance`);
//! - a (family, algorithm, objective) group of the baseline is missing from the current run;
//! - a group has fewer rows than the baseline's (an instance vanished), or lost more ratios
//!   of one of the columns `opt`, `lb`, `n` than rows (a ratio vanished from a kept row);
//! - the mean or max of a ratio of a group (bin `all`) is worse than the baseline's by more
//!   than the relative tolerance, or is missing where the baseline has one; a comparison that
//!   cannot be decided (NaN) counts as worse.

use super::manifest::Recorded;
use super::rows::{Row, read_results};
use super::stats::{self, StatRow};
use crate::error::{Error, Result};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// The ratio columns, by the names [`StatRow::summary`] takes.
const RATIOS: [&str; 3] = ["opt", "lb", "n"];

/// How far a stored ratio may be from the one recomputed from its row's integers: one unit in
/// the sixth decimal, the precision `results.csv` stores (honest files agree exactly, since
/// both round the same way; a tampered or NaN value is off by far more).
const RATIO_EPS: f64 = 1e-6;

/// One line of the gate's table.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    pub verdict: Verdict,
    pub what: String,
    pub baseline: Option<f64>,
    pub current: Option<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verdict {
    Fail,
    Improved,
}

/// The gate's outcome.
#[derive(Clone, Debug, Default)]
pub struct GateReport {
    pub findings: Vec<Finding>,
    pub groups_compared: usize,
    /// Baseline rows found in the current run and compared instance by instance.
    pub rows_compared: usize,
}

impl GateReport {
    pub fn passed(&self) -> bool {
        !self.findings.iter().any(|f| f.verdict == Verdict::Fail)
    }

    /// A readable table of failures and improvements, then a one-line summary.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let fmt = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.6}"));
        if !self.findings.is_empty() {
            let _ = writeln!(
                s,
                "{:<9} {:>10} {:>10} {:>9}  what",
                "verdict", "baseline", "current", "change"
            );
            for f in &self.findings {
                let change = match (f.baseline, f.current) {
                    (Some(b), Some(c)) if b != 0.0 => format!("{:+.2}%", (c - b) / b * 100.0),
                    _ => "-".to_string(),
                };
                let v = match f.verdict {
                    Verdict::Fail => "FAIL",
                    Verdict::Improved => "improved",
                };
                let _ = writeln!(
                    s,
                    "{v:<9} {:>10} {:>10} {change:>9}  {}",
                    fmt(f.baseline),
                    fmt(f.current),
                    f.what
                );
            }
        }
        let fails = self
            .findings
            .iter()
            .filter(|f| f.verdict == Verdict::Fail)
            .count();
        let better = self.findings.len() - fails;
        let _ = writeln!(
            s,
            "gate: {} — {} rows compared per instance, {} groups compared, {fails} failure(s), {better} improvement(s)",
            if self.passed() { "PASS" } else { "FAIL" },
            self.rows_compared,
            self.groups_compared
        );
        s
    }
}

/// Checks a relative tolerance: finite and in `[0, 1)`.
///
/// NaN would make every comparison false (so everything passes), a negative tolerance flags
/// unchanged ratios, and a tolerance of 1 or more lets a ratio double unnoticed.
pub fn check_tolerance(tolerance: f64) -> std::result::Result<f64, String> {
    if tolerance.is_finite() && (0.0..1.0).contains(&tolerance) {
        Ok(tolerance)
    } else {
        Err(format!(
            "expected a finite relative tolerance with 0 <= tolerance < 1 (e.g. 0.005), got \
             {tolerance}"
        ))
    }
}

/// Parses `--tolerance` for clap, which names the option in its error and exits 2.
pub fn parse_tolerance(text: &str) -> std::result::Result<f64, String> {
    let t: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("expected a number (e.g. 0.005), got {text:?}"))?;
    check_tolerance(t)
}

/// The baseline's statistics file: a `stats.csv` file, or a run directory holding one.
fn baseline_file(path: &Path) -> PathBuf {
    if path.is_dir() {
        path.join("stats.csv")
    } else {
        path.to_path_buf()
    }
}

/// Refuses a baseline the gate cannot compare against: one without groups (every run would
/// pass against it), or with a ratio that is not a finite number >= 0 (a NaN makes every
/// comparison false) or whose count disagrees with its presence.
fn check_baseline(file: &Path, base: &[StatRow]) -> Result<()> {
    let name = file.display().to_string();
    if !base.iter().any(|s| s.size_bin == "all") {
        return Err(Error::invalid(format!(
            "{name}: baseline has no groups (no row of size_bin `all`): expected a stats.csv \
             written by `mowmill bench`, with a header and at least one group"
        )));
    }
    // Column numbers for the error message, from the file's own header.
    let header: Vec<String> = csv::Reader::from_path(file)
        .and_then(|mut r| r.headers().cloned())
        .map(|h| h.iter().map(String::from).collect())
        .unwrap_or_default();
    let column = |col: &str| header.iter().position(|h| h == col).map_or(1, |p| p + 1);
    for (k, s) in base.iter().enumerate() {
        // `stats::read` numbers its records the same way: header on line 1.
        let line = k + 2;
        for which in RATIOS {
            let sum = s.summary(which);
            let stats = [
                ("mean", sum.mean),
                ("median", sum.median),
                ("p95", sum.p95),
                ("max", sum.max),
            ];
            for (stat, value) in stats {
                let col = format!("ratio_{which}_{stat}");
                let problem = match value {
                    Some(x) if !(x.is_finite() && x >= 0.0) => {
                        format!("{col} is {x}: expected a finite ratio >= 0")
                    }
                    None if sum.count > 0 => format!(
                        "{col} is empty but ratio_{which}_count is {}: expected a ratio",
                        sum.count
                    ),
                    Some(x) if sum.count == 0 => {
                        format!("{col} is {x} but ratio_{which}_count is 0: expected it empty")
                    }
                    _ => continue,
                };
                return Err(Error::parse(&name, line, column(&col), problem));
            }
        }
    }
    Ok(())
}

/// `x <= limit`, false when either is NaN: every check is written as "fail unless at most",
/// so that a NaN fails it instead of passing it.
fn at_most(x: f64, limit: f64) -> bool {
    matches!(
        x.partial_cmp(&limit),
        Some(Ordering::Less | Ordering::Equal)
    )
}

/// The ratio columns of `row` that disagree with the ratios its integers give, as (column,
/// stored, recomputed).
fn ratio_mismatches(row: &Row) -> Vec<(&'static str, Option<f64>, Option<f64>)> {
    let mut recomputed = row.clone();
    recomputed.compute_ratios();
    let pairs = [
        ("ratio_opt", row.ratio_opt, recomputed.ratio_opt),
        ("ratio_lb", row.ratio_lb, recomputed.ratio_lb),
        ("ratio_n", row.ratio_n, recomputed.ratio_n),
    ];
    pairs
        .into_iter()
        .map(|(col, s, c)| (col, s.map(|x| x.0), c.map(|x| x.0)))
        .filter(|(_, s, c)| match (s, c) {
            (None, None) => false,
            (Some(s), Some(c)) => !at_most((s - c).abs(), RATIO_EPS),
            _ => true,
        })
        .collect()
}

/// The identity of a result row across runs: the instance's content (`sha256`) and its name
/// with whitespace removed and letters lowercased (so that two identical instance files stay
/// two instances, while a copy renamed by whitespace or case is the same one), the algorithm,
/// the objective and the variant columns (`merge`, `cutter`, `coverage4`, `unit`).
type InstanceKey = (
    String,
    String,
    String,
    String,
    String,
    String,
    Option<bool>,
    Option<u64>,
);

/// An instance name as the gate compares it: without whitespace, lowercase.
fn normalized_name(name: &str) -> String {
    name.chars()
        .filter(|c| !c.is_whitespace())
        .flat_map(char::to_lowercase)
        .collect()
}

fn instance_key(r: &Row) -> InstanceKey {
    (
        r.sha256.clone(),
        normalized_name(&r.instance),
        r.algorithm.clone(),
        r.objective.clone(),
        r.merge.clone(),
        r.cutter.clone(),
        r.coverage4,
        r.unit,
    )
}

/// The baseline's rows, one per [`InstanceKey`], and its config digest.
struct Baseline {
    rows: BTreeMap<InstanceKey, Row>,
    all: Vec<Row>,
    config_sha256: String,
}

/// Reads the per-instance baseline beside `stats.csv`: `results.csv` and `manifest.json` of
/// the same run directory. Refuses (exit 2) a baseline without either, without a config
/// digest, not finished, with a row count other than its manifest's, with a row twice (or two
/// instance names that differ only by whitespace or case), or with a row that is invalid or
/// inconsistent ([`Row::consistency_error`]).
fn read_baseline(dir: &Path) -> Result<Baseline> {
    let results = dir.join("results.csv");
    let manifest = Recorded::read(dir)?;
    let mpath = manifest.path.display().to_string();
    let config_sha256 = manifest
        .sha256()
        .ok_or_else(|| {
            Error::invalid(format!(
                "{mpath}: no config_sha256: expected the manifest of the baseline's run, which \
                 names the suite the baseline belongs to"
            ))
        })?
        .to_string();
    if manifest.json["end"].is_null() {
        return Err(Error::invalid(format!(
            "{mpath}: the baseline's run did not finish (end is null): expected a finished run"
        )));
    }
    let all = read_results(&results)?;
    let name = results.display().to_string();
    match manifest.json["rows"].as_u64() {
        Some(n) if n == all.len() as u64 => {}
        recorded => {
            return Err(Error::invalid(format!(
                "{name}: {} rows, but {mpath} records {}: expected the baseline's results.csv \
                 whole",
                all.len(),
                recorded.map_or("no row count".to_string(), |n| n.to_string())
            )));
        }
    }
    let mut rows: BTreeMap<InstanceKey, Row> = BTreeMap::new();
    for (k, r) in all.iter().enumerate() {
        let line = k + 2;
        let refuse = |what: String| Error::parse(&name, line, 1, what);
        if let Some(why) = r.consistency_error() {
            return Err(refuse(format!(
                "inconsistent baseline row {}: {why}: expected rows of a valid run",
                r.describe()
            )));
        }
        if r.valid == Some(false) || r.within_guarantee == Some(false) {
            return Err(refuse(format!(
                "baseline row {} is invalid or violates its guarantee: expected rows of a \
                 passing run",
                r.describe()
            )));
        }
        if let Some(first) = rows.get(&instance_key(r)) {
            return Err(refuse(format!(
                "baseline row {} repeats row {} (same sha256, instance name up to whitespace \
                 and case, algorithm, objective and variant): expected each once",
                r.describe(),
                first.describe()
            )));
        }
        rows.insert(instance_key(r), r.clone());
    }
    Ok(Baseline {
        rows,
        all,
        config_sha256,
    })
}

/// `a` and `b` equal up to the 6 decimals the files store.
fn same_ratio(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => at_most((a - b).abs(), RATIO_EPS),
        _ => false,
    }
}

/// Refuses a `stats.csv` that is not the statistics of its own `results.csv` (a group cut,
/// listed twice, added or altered): the summary comparison would rest on numbers no run
/// produced.
fn check_stats_match(file: &Path, stored: &[StatRow], computed: &[StatRow]) -> Result<()> {
    let name = file.display().to_string();
    let key = |s: &StatRow| {
        (
            s.family.clone(),
            s.size_bin.clone(),
            s.algorithm.clone(),
            s.objective.clone(),
        )
    };
    let mut seen = BTreeSet::new();
    for (k, s) in stored.iter().enumerate() {
        if !seen.insert(key(s)) {
            return Err(Error::parse(
                &name,
                k + 2,
                1,
                format!(
                    "group {} / {} / {} / {} is listed twice: expected each group once",
                    s.family, s.size_bin, s.algorithm, s.objective
                ),
            ));
        }
    }
    let by_key: BTreeMap<_, &StatRow> = computed.iter().map(|s| (key(s), s)).collect();
    for (k, s) in stored.iter().enumerate() {
        let same = by_key.get(&key(s)).is_some_and(|c| {
            c.count == s.count
                && c.violations == s.violations
                && c.invalid == s.invalid
                && c.errors == s.errors
                && RATIOS.iter().all(|w| {
                    let (a, b) = (c.summary(w), s.summary(w));
                    a.count == b.count
                        && same_ratio(a.mean, b.mean)
                        && same_ratio(a.median, b.median)
                        && same_ratio(a.p95, b.p95)
                        && same_ratio(a.max, b.max)
                })
        });
        if !same {
            return Err(Error::parse(
                &name,
                k + 2,
                1,
                format!(
                    "group {} / {} / {} / {} is not what the rows of results.csv beside it \
                     give: expected the stats.csv of the same run",
                    s.family, s.size_bin, s.algorithm, s.objective
                ),
            ));
        }
    }
    if stored.len() != computed.len() {
        return Err(Error::invalid(format!(
            "{name}: {} groups, but the results.csv beside it gives {}: expected the whole \
             stats.csv of the same run",
            stored.len(),
            computed.len()
        )));
    }
    Ok(())
}

/// Compares the run in `current` (a directory with `results.csv` and `manifest.json`) against
/// the baseline run whose `stats.csv` is `baseline` (or the directory holding it), instance by
/// instance, then group by group.
pub fn gate(baseline: &Path, current: &Path, tolerance: f64) -> Result<GateReport> {
    let tolerance =
        check_tolerance(tolerance).map_err(|m| Error::invalid(format!("tolerance: {m}")))?;
    let base_file = baseline_file(baseline);
    let stored_stats = stats::read(&base_file)?;
    check_baseline(&base_file, &stored_stats)?;
    let base_dir = match base_file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let base_run = read_baseline(&base_dir)?;
    let base = stats::compute(&base_run.all);
    check_stats_match(&base_file, &stored_stats, &base)?;
    // Only runs of the baseline's suite compare: a run of other instances would be compared
    // as if it were the same one.
    let current_manifest = Recorded::read(current)?;
    match current_manifest.sha256() {
        Some(sha) if sha == base_run.config_sha256 => {}
        other => {
            return Err(Error::invalid(format!(
                "{}: config_sha256 {}, the baseline's ({}) is {}: expected a run of the \
                 baseline's suite (rerun it with the baseline's config, or update the \
                 baseline on purpose: scripts/update-baseline.sh)",
                current_manifest.path.display(),
                other.unwrap_or("not recorded"),
                base_dir.join("manifest.json").display(),
                base_run.config_sha256
            )));
        }
    }
    let stored: Vec<Row> = read_results(&current.join("results.csv"))?;
    let mut report = GateReport::default();
    let fail = |what: String, b: Option<f64>, c: Option<f64>| Finding {
        verdict: Verdict::Fail,
        what,
        baseline: b,
        current: c,
    };
    let id = |r: &Row| r.describe();
    let mut by_key: BTreeMap<InstanceKey, &Row> = BTreeMap::new();
    for r in &stored {
        for (col, s, c) in ratio_mismatches(r) {
            let show = |x: Option<f64>| x.map_or("empty".to_string(), |v| format!("{v:.6}"));
            report.findings.push(fail(
                format!(
                    "row ratio does not match its integers: {}: {col} is {}, value {} / \
                     (opt {}, lower_bound {}, n {}) gives {}",
                    id(r),
                    show(s),
                    r.value.map_or("empty".into(), |v| v.to_string()),
                    r.opt.map_or("empty".into(), |v| v.to_string()),
                    r.lower_bound.map_or("empty".into(), |v| v.to_string()),
                    r.n,
                    show(c)
                ),
                None,
                None,
            ));
        }
        if let Some(why) = r.consistency_error() {
            report.findings.push(fail(
                format!("invalid result (inconsistent row): {}: {why}", id(r)),
                None,
                r.value.map(|v| v as f64),
            ));
        }
        // A repeated row would weigh twice in the means (or dilute a regression); a copy
        // renamed by whitespace or case is the same row.
        match by_key.get(&instance_key(r)) {
            Some(first) if first.instance == r.instance => {
                report
                    .findings
                    .push(fail(format!("duplicate row: {}", id(r)), None, None))
            }
            Some(first) => report.findings.push(fail(
                format!(
                    "duplicate row: {}: instance name {:?} differs from {:?} only by \
                     whitespace or case (same sha256)",
                    id(r),
                    r.instance,
                    first.instance
                ),
                None,
                None,
            )),
            None => {
                by_key.insert(instance_key(r), r);
            }
        }
        if r.valid == Some(false) {
            report.findings.push(fail(
                format!("invalid result: {}: {}", id(r), r.error),
                None,
                None,
            ));
        }
        // Every value is the checker's recount of a cover, so it always comes with a verdict.
        if r.error.is_empty() && r.value.is_some() && r.valid.is_none() {
            report.findings.push(fail(
                format!("result without a validity verdict: {}", id(r)),
                None,
                None,
            ));
        }
        if r.within_guarantee == Some(false) {
            report.findings.push(fail(
                format!(
                    "guarantee violated: {} value {} ({})",
                    id(r),
                    r.value.unwrap_or(0),
                    r.guarantee
                ),
                None,
                None,
            ));
        }
    }
    compare_instances(&base_run, &by_key, &mut report);
    // Statistics from the recomputed ratios only: the stored ones were checked above, and are
    // not what the comparison rests on.
    let rows: Vec<Row> = stored
        .into_iter()
        .map(|mut r| {
            r.compute_ratios();
            r
        })
        .collect();
    let now = stats::compute(&rows);
    // A group holding an inconsistent row has no improvement to report: its ratios fell
    // because a row went below what is provable.
    let tainted: BTreeSet<(String, String, String)> = rows
        .iter()
        .filter(|r| r.consistency_error().is_some())
        .map(|r| (r.family.clone(), r.algorithm.clone(), r.objective.clone()))
        .collect();
    compare_groups(&base, &now, tolerance, &tainted, &mut report);
    report.findings.sort_by_key(|f| f.verdict);
    Ok(report)
}

/// The per-instance comparison, which decides: every baseline row must be in the current run
/// with the same `n`, a result where the baseline has one, the proven optimum and bound it
/// had, and a value no worse. A lower value is an improvement only if the row is consistent
/// and not below a proven bound of the instance (its own or the baseline's); below one, it is
/// an invalid result.
fn compare_instances(
    base: &Baseline,
    current: &BTreeMap<InstanceKey, &Row>,
    report: &mut GateReport,
) {
    let fail = |what: String, b: Option<u64>, c: Option<u64>| Finding {
        verdict: Verdict::Fail,
        what,
        baseline: b.map(|x| x as f64),
        current: c.map(|x| x as f64),
    };
    for (key, b) in &base.rows {
        let what = b.describe();
        let Some(c) = current.get(key) else {
            report.findings.push(fail(
                format!(
                    "missing in current run: {what} (sha256 {})",
                    b.sha256.get(..12).unwrap_or(&b.sha256)
                ),
                b.value,
                None,
            ));
            continue;
        };
        report.rows_compared += 1;
        if c.n != b.n {
            report.findings.push(fail(
                format!("{what}: n differs from the baseline's for the same sha256"),
                Some(b.n),
                Some(c.n),
            ));
        }
        if b.error.is_empty() && !c.error.is_empty() {
            report.findings.push(fail(
                format!("{what}: error where the baseline has a result: {}", c.error),
                b.value,
                c.value,
            ));
        }
        for (col, bv, cv) in [
            ("opt", b.opt, c.opt),
            ("lower_bound", b.lower_bound, c.lower_bound),
        ] {
            match (bv, cv) {
                (Some(_), None) => report.findings.push(fail(
                    format!("{what}: lost its {col} (the baseline has one)"),
                    bv,
                    None,
                )),
                (Some(x), Some(y)) if col == "opt" && x != y => report.findings.push(fail(
                    format!("{what}: proven optimum differs from the baseline's"),
                    bv,
                    cv,
                )),
                (Some(x), Some(y)) if y < x => report.findings.push(fail(
                    format!("{what}: lower_bound weaker than the baseline's"),
                    bv,
                    cv,
                )),
                _ => {}
            }
        }
        let (Some(bv), Some(cv)) = (b.value, c.value) else {
            if b.value.is_some() {
                report.findings.push(fail(
                    format!("{what}: no value (the baseline has one)"),
                    b.value,
                    None,
                ));
            }
            continue;
        };
        // The instance's proven bounds, from both runs: no walk is below them.
        let floor = [b.lower_bound, b.opt, c.lower_bound, c.opt]
            .into_iter()
            .flatten()
            .max();
        if let Some(floor) = floor
            && cv < floor
        {
            report.findings.push(fail(
                format!(
                    "invalid result: {what}: value {cv} is below the proven bound {floor} of \
                     this instance"
                ),
                Some(bv),
                Some(cv),
            ));
            continue;
        }
        // An exact row's value is a proof only when optimal; a time-limited incumbent depends
        // on the machine's speed.
        if b.algorithm == super::rows::EXACT {
            let optimal = |r: &Row| r.opt_status == "optimal";
            if optimal(b) && !optimal(c) {
                report.findings.push(fail(
                    format!("{what}: optimum no longer proven ({})", c.opt_status),
                    Some(bv),
                    Some(cv),
                ));
            }
            if !(optimal(b) && optimal(c)) {
                continue;
            }
        }
        if cv > bv {
            report
                .findings
                .push(fail(format!("{what}: value"), Some(bv), Some(cv)));
        } else if cv < bv && c.consistency_error().is_none() {
            report.findings.push(Finding {
                verdict: Verdict::Improved,
                what: format!("{what}: value"),
                baseline: Some(bv as f64),
                current: Some(cv as f64),
            });
        }
    }
}

/// The group summary: per (family, algorithm, objective) of bin `all`, error rows, row counts
/// and the mean and max of each ratio against the baseline's, within the tolerance.
fn compare_groups(
    base: &[StatRow],
    now: &[StatRow],
    tolerance: f64,
    tainted: &BTreeSet<(String, String, String)>,
    report: &mut GateReport,
) {
    let fail = |what: String, b: Option<f64>, c: Option<f64>| Finding {
        verdict: Verdict::Fail,
        what,
        baseline: b,
        current: c,
    };
    let key = |s: &StatRow| (s.family.clone(), s.algorithm.clone(), s.objective.clone());
    let current: BTreeMap<_, &StatRow> = now
        .iter()
        .filter(|s| s.size_bin == "all")
        .map(|s| (key(s), s))
        .collect();
    let base_all: BTreeMap<_, &StatRow> = base
        .iter()
        .filter(|s| s.size_bin == "all")
        .map(|s| (key(s), s))
        .collect();
    // A group the baseline does not know is not compared, but its error rows still fail.
    for (k, c) in &current {
        if c.errors > 0 && !base_all.contains_key(k) {
            report.findings.push(fail(
                format!(
                    "{} / {} / {}: error rows in a group the baseline does not have",
                    c.family, c.algorithm, c.objective
                ),
                Some(0.0),
                Some(c.errors as f64),
            ));
        }
    }
    for b in base_all.values() {
        let group = format!("{} / {} / {}", b.family, b.algorithm, b.objective);
        let Some(c) = current.get(&key(b)) else {
            report
                .findings
                .push(fail(format!("missing in current run: {group}"), None, None));
            continue;
        };
        report.groups_compared += 1;
        if c.errors > b.errors {
            report.findings.push(fail(
                format!("{group}: error rows"),
                Some(b.errors as f64),
                Some(c.errors as f64),
            ));
        }
        // Fewer rows means instances vanished: their ratios would silently leave the means.
        if c.count < b.count {
            report.findings.push(fail(
                format!("{group}: fewer rows than the baseline"),
                Some(b.count as f64),
                Some(c.count as f64),
            ));
        }
        for which in RATIOS {
            let (bs, cs) = (b.summary(which), c.summary(which));
            // Only ratios lost beyond the lost rows, which are reported once above.
            if bs.count.saturating_sub(cs.count) > b.count.saturating_sub(c.count) {
                report.findings.push(fail(
                    format!("{group}: fewer rows with ratio_{which}"),
                    Some(bs.count as f64),
                    Some(cs.count as f64),
                ));
            }
            for (stat, bv, cv) in [("mean", bs.mean, cs.mean), ("max", bs.max, cs.max)] {
                let what = format!("{group}: ratio_{which} {stat}");
                match (bv, cv) {
                    (Some(bv), Some(cv)) if !at_most(cv, bv * (1.0 + tolerance) + 1e-12) => {
                        report.findings.push(fail(what, Some(bv), Some(cv)))
                    }
                    (Some(bv), Some(cv))
                        if cv < bv * (1.0 - tolerance) - 1e-12 && !tainted.contains(&key(b)) =>
                    {
                        report.findings.push(Finding {
                            verdict: Verdict::Improved,
                            what,
                            baseline: Some(bv),
                            current: Some(cv),
                        })
                    }
                    (Some(bv), None) => {
                        report
                            .findings
                            .push(fail(format!("{what} missing"), Some(bv), None))
                    }
                    _ => {}
                }
            }
        }
    }
}
