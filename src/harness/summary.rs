//! The summary `bench` prints when a run ends: per (algorithm, objective) the instances, the
//! median and worst ratio, and every count a user must not miss (guarantee violations, invalid
//! results, error rows, time limits); then where the run's files are.
//!
//! The ratio shown is the ratio to the proven optimum where the group has one (`opt`), else to
//! the best lower bound (`lb`, which over-estimates the true ratio); exact rows show none.

use super::rows::{EXACT, Row};
use super::stats::Summary;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// One line of the summary.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Line {
    pub algorithm: String,
    pub objective: String,
    pub instances: usize,
    /// `opt`, `lb` or empty: what the ratios below divide by.
    pub ratio_of: &'static str,
    pub median: Option<f64>,
    pub worst: Option<f64>,
    pub violations: usize,
    pub invalid: usize,
    pub errors: usize,
    pub time_limits: usize,
}

/// The summary lines, sorted by algorithm (exact first) and objective.
pub fn lines(rows: &[Row]) -> Vec<Line> {
    let mut groups: BTreeMap<(bool, &str, &str), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        let key = (
            r.algorithm != EXACT,
            r.algorithm.as_str(),
            r.objective.as_str(),
        );
        groups.entry(key).or_default().push(r);
    }
    groups
        .into_iter()
        .map(|((_, algorithm, objective), rs)| {
            let ratios = |f: fn(&Row) -> Option<f64>| {
                let mut v: Vec<f64> = rs.iter().filter_map(|r| f(r)).collect();
                Summary::of(&mut v)
            };
            let opt = ratios(|r| r.ratio_opt.map(|x| x.0));
            let lb = ratios(|r| r.ratio_lb.map(|x| x.0));
            let (ratio_of, ratio) = if algorithm == EXACT {
                ("", Summary::default())
            } else if opt.count > 0 {
                ("opt", opt)
            } else if lb.count > 0 {
                ("lb", lb)
            } else {
                ("", Summary::default())
            };
            Line {
                algorithm: algorithm.to_string(),
                objective: objective.to_string(),
                instances: rs.len(),
                ratio_of,
                median: ratio.median,
                worst: ratio.max,
                violations: rs
                    .iter()
                    .filter(|r| r.within_guarantee == Some(false))
                    .count(),
                invalid: rs.iter().filter(|r| r.valid == Some(false)).count(),
                errors: rs.iter().filter(|r| !r.error.is_empty()).count(),
                time_limits: rs.iter().filter(|r| is_time_limit(r)).count(),
            }
        })
        .collect()
}

/// A row whose exact solve (its own, or its reference optimum's) or whose outside program
/// stopped at a time limit.
fn is_time_limit(r: &Row) -> bool {
    r.opt_status == "time_limit" || r.error.contains("time limit")
}

/// Whether the run must exit 1: an invalid result or a violated guarantee.
pub fn failed(lines: &[Line]) -> bool {
    lines.iter().any(|l| l.invalid > 0 || l.violations > 0)
}

/// The printed summary: the table, a totals line, and the run's files.
pub fn text(lines: &[Line], out: &Path) -> String {
    let mut s = String::new();
    let num = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.3}"));
    let _ = writeln!(
        s,
        "{:<22} {:<12} {:>9} {:>5} {:>7} {:>7} {:>10} {:>7} {:>6} {:>10}",
        "algorithm",
        "objective",
        "instances",
        "ratio",
        "median",
        "worst",
        "violations",
        "invalid",
        "errors",
        "time-limit"
    );
    for l in lines {
        let _ = writeln!(
            s,
            "{:<22} {:<12} {:>9} {:>5} {:>7} {:>7} {:>10} {:>7} {:>6} {:>10}",
            l.algorithm,
            l.objective,
            l.instances,
            if l.ratio_of.is_empty() {
                "-"
            } else {
                l.ratio_of
            },
            num(l.median),
            num(l.worst),
            l.violations,
            l.invalid,
            l.errors,
            l.time_limits
        );
    }
    let total = |f: fn(&Line) -> usize| lines.iter().map(f).sum::<usize>();
    let _ = writeln!(
        s,
        "{} violations, {} invalid results, {} error rows, {} time limits{}",
        total(|l| l.violations),
        total(|l| l.invalid),
        total(|l| l.errors),
        total(|l| l.time_limits),
        if failed(lines) {
            " -> FAILED (exit 1)"
        } else {
            ""
        }
    );
    let _ = writeln!(
        s,
        "ratio: to the proven optimum (opt) or, where the group has none, to the best lower bound (lb, an over-estimate)"
    );
    let path = |name: &str| out.join(name).display().to_string();
    let _ = writeln!(s, "rows:     {}", path("results.csv"));
    let _ = writeln!(s, "stats:    {}", path("stats.csv"));
    let _ = writeln!(s, "plots:    {}", path("plots"));
    let _ = writeln!(s, "manifest: {}", path("manifest.json"));
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::harness::rows::Ratio;

    fn row(algorithm: &str, value: u64, opt: Option<u64>) -> Row {
        let mut r = Row {
            algorithm: algorithm.into(),
            objective: "length".into(),
            n: 10,
            value: Some(value),
            opt,
            lower_bound: Some(10),
            valid: Some(true),
            ..Row::default()
        };
        r.compute_ratios();
        r
    }

    #[test]
    fn groups_count_and_fail_on_invalid_or_violated() {
        let mut rows = vec![
            row("a", 12, Some(10)),
            row("a", 15, Some(10)),
            row("b", 20, None),
        ];
        rows[1].within_guarantee = Some(false);
        rows.push(Row {
            algorithm: EXACT.into(),
            objective: "length".into(),
            opt_status: "time_limit".into(),
            ..Row::default()
        });
        let l = lines(&rows);
        assert_eq!(l[0].algorithm, EXACT);
        assert_eq!(l[0].time_limits, 1);
        assert_eq!((l[1].instances, l[1].ratio_of), (2, "opt"));
        assert_eq!((l[1].median, l[1].worst), (Some(1.2), Some(1.5)));
        assert_eq!(l[1].violations, 1);
        assert_eq!(
            (l[2].ratio_of, l[2].worst),
            ("lb", Some(Ratio::of(20, 10).0))
        );
        assert!(failed(&l));
        rows[1].within_guarantee = None;
        assert!(!failed(&lines(&rows)));
        rows[2].valid = Some(false);
        assert!(failed(&lines(&rows)));
    }
}
