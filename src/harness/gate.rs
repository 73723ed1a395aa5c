//! The regression gate: compares a run with a committed baseline, deterministically (it never
//! compares timings).
//!
//! It fails when any result of the current run is invalid, when any guarantee is violated, when
//! an error row appears, when a (family, algorithm, objective) group of the baseline is
//! missing, or when the mean or max of any ratio of a group (bin `all` of `stats.csv`) is worse
//! than the baseline's by more than the relative tolerance. Ratios are all of minimization
//! objectives, so larger is worse.

use super::rows::{Row, read_rows};
use super::stats::{self, StatRow};
use crate::error::Result;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::{Path, PathBuf};

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
            "gate: {} — {} groups compared, {fails} failure(s), {better} improvement(s)",
            if self.passed() { "PASS" } else { "FAIL" },
            self.groups_compared
        );
        s
    }
}

/// The baseline's statistics: a `stats.csv` file, or a run directory holding one.
fn baseline_stats(path: &Path) -> Result<Vec<StatRow>> {
    let file: PathBuf = if path.is_dir() {
        path.join("stats.csv")
    } else {
        path.to_path_buf()
    };
    stats::read(&file)
}

/// Compares the run in `current` (a directory with `results.csv`) against `baseline`.
pub fn gate(baseline: &Path, current: &Path, tolerance: f64) -> Result<GateReport> {
    let base = baseline_stats(baseline)?;
    let rows: Vec<Row> = read_rows(&current.join("results.csv"))?;
    let now = stats::compute(&rows);
    let mut report = GateReport::default();
    let fail = |what: String, b: Option<f64>, c: Option<f64>| Finding {
        verdict: Verdict::Fail,
        what,
        baseline: b,
        current: c,
    };
    for r in rows.iter().filter(|r| r.valid == Some(false)) {
        report.findings.push(fail(
            format!(
                "invalid result: {} {} {}: {}",
                r.instance, r.algorithm, r.objective, r.error
            ),
            None,
            None,
        ));
    }
    for r in rows.iter().filter(|r| r.within_guarantee == Some(false)) {
        report.findings.push(fail(
            format!(
                "guarantee violated: {} {} {} value {} ({})",
                r.instance,
                r.algorithm,
                r.objective,
                r.value.unwrap_or(0),
                r.guarantee
            ),
            None,
            None,
        ));
    }
    let key = |s: &StatRow| (s.family.clone(), s.algorithm.clone(), s.objective.clone());
    let current: BTreeMap<_, &StatRow> = now
        .iter()
        .filter(|s| s.size_bin == "all")
        .map(|s| (key(s), s))
        .collect();
    for b in base.iter().filter(|s| s.size_bin == "all") {
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
        for which in ["opt", "lb", "n"] {
            let (bs, cs) = (b.summary(which), c.summary(which));
            for (stat, bv, cv) in [("mean", bs.mean, cs.mean), ("max", bs.max, cs.max)] {
                let what = format!("{group}: ratio_{which} {stat}");
                match (bv, cv) {
                    (Some(bv), Some(cv)) if cv > bv * (1.0 + tolerance) + 1e-12 => {
                        report.findings.push(fail(what, Some(bv), Some(cv)))
                    }
                    (Some(bv), Some(cv)) if cv < bv * (1.0 - tolerance) - 1e-12 => {
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
    report.findings.sort_by_key(|f| f.verdict);
    Ok(report)
}
