//! `stats.csv`: per (family, size bin, algorithm, objective) the count, mean, median, p95 and
//! max of each ratio, the guarantee, and the numbers of guarantee violations and invalid
//! results. Size bins are powers of two of N (`8-15`, `16-31`, ...); the bin `all` aggregates
//! every size and is what the regression gate compares.

use super::rows::Row;
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// Summary of one ratio column over a group; empty when no row has the ratio.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub count: usize,
    pub mean: Option<f64>,
    pub median: Option<f64>,
    pub p95: Option<f64>,
    pub max: Option<f64>,
}

impl Summary {
    pub fn of(values: &mut [f64]) -> Summary {
        if values.is_empty() {
            return Summary::default();
        }
        values.sort_by(f64::total_cmp);
        let n = values.len();
        let round = |x: f64| (x * 1e6).round() / 1e6;
        // Nearest-rank percentiles: deterministic and always an observed value.
        let rank = |q: f64| values[((q * n as f64).ceil() as usize).clamp(1, n) - 1];
        Summary {
            count: n,
            mean: Some(round(values.iter().sum::<f64>() / n as f64)),
            median: Some(rank(0.5)),
            p95: Some(rank(0.95)),
            max: Some(values[n - 1]),
        }
    }
}

/// One row of `stats.csv`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StatRow {
    pub family: String,
    pub size_bin: String,
    pub algorithm: String,
    pub objective: String,
    pub count: usize,
    pub ratio_opt_count: usize,
    pub ratio_opt_mean: Option<f64>,
    pub ratio_opt_median: Option<f64>,
    pub ratio_opt_p95: Option<f64>,
    pub ratio_opt_max: Option<f64>,
    pub ratio_lb_count: usize,
    pub ratio_lb_mean: Option<f64>,
    pub ratio_lb_median: Option<f64>,
    pub ratio_lb_p95: Option<f64>,
    pub ratio_lb_max: Option<f64>,
    pub ratio_n_count: usize,
    pub ratio_n_mean: Option<f64>,
    pub ratio_n_median: Option<f64>,
    pub ratio_n_p95: Option<f64>,
    pub ratio_n_max: Option<f64>,
    pub guarantee: String,
    pub violations: usize,
    pub invalid: usize,
    pub errors: usize,
}

impl StatRow {
    /// The summary of ratio column `which` (`opt`, `lb` or `n`).
    pub fn summary(&self, which: &str) -> Summary {
        let (count, mean, median, p95, max) = match which {
            "opt" => (
                self.ratio_opt_count,
                self.ratio_opt_mean,
                self.ratio_opt_median,
                self.ratio_opt_p95,
                self.ratio_opt_max,
            ),
            "lb" => (
                self.ratio_lb_count,
                self.ratio_lb_mean,
                self.ratio_lb_median,
                self.ratio_lb_p95,
                self.ratio_lb_max,
            ),
            _ => (
                self.ratio_n_count,
                self.ratio_n_mean,
                self.ratio_n_median,
                self.ratio_n_p95,
                self.ratio_n_max,
            ),
        };
        Summary {
            count,
            mean,
            median,
            p95,
            max,
        }
    }
}

/// The power-of-two size bin of N, e.g. `16-31`.
pub fn size_bin(n: u64) -> String {
    if n == 0 {
        return "0".into();
    }
    let lo = 1u64 << (63 - n.leading_zeros());
    format!("{lo}-{}", 2 * lo - 1)
}

/// Aggregates rows into statistics, sorted by (family, bin, algorithm, objective), each group
/// also under the bin `all`.
pub fn compute(rows: &[Row]) -> Vec<StatRow> {
    let mut groups: BTreeMap<(String, String, String, String), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        for bin in [size_bin(r.n), "all".to_string()] {
            groups
                .entry((
                    r.family.clone(),
                    bin,
                    r.algorithm.clone(),
                    r.objective.clone(),
                ))
                .or_default()
                .push(r);
        }
    }
    groups
        .into_iter()
        .map(|((family, size_bin, algorithm, objective), rs)| {
            let col = |f: fn(&Row) -> Option<f64>| {
                let mut v: Vec<f64> = rs
                    .iter()
                    .filter(|r| r.error.is_empty())
                    .filter_map(|r| f(r))
                    .collect();
                Summary::of(&mut v)
            };
            let opt = col(|r| r.ratio_opt.map(|x| x.0));
            let lb = col(|r| r.ratio_lb.map(|x| x.0));
            let n = col(|r| r.ratio_n.map(|x| x.0));
            StatRow {
                family,
                size_bin,
                algorithm,
                objective,
                count: rs.len(),
                ratio_opt_count: opt.count,
                ratio_opt_mean: opt.mean,
                ratio_opt_median: opt.median,
                ratio_opt_p95: opt.p95,
                ratio_opt_max: opt.max,
                ratio_lb_count: lb.count,
                ratio_lb_mean: lb.mean,
                ratio_lb_median: lb.median,
                ratio_lb_p95: lb.p95,
                ratio_lb_max: lb.max,
                ratio_n_count: n.count,
                ratio_n_mean: n.mean,
                ratio_n_median: n.median,
                ratio_n_p95: n.p95,
                ratio_n_max: n.max,
                guarantee: rs
                    .iter()
                    .map(|r| r.guarantee.as_str())
                    .find(|g| !g.is_empty())
                    .unwrap_or("")
                    .to_string(),
                violations: rs
                    .iter()
                    .filter(|r| r.within_guarantee == Some(false))
                    .count(),
                invalid: rs.iter().filter(|r| r.valid == Some(false)).count(),
                errors: rs.iter().filter(|r| !r.error.is_empty()).count(),
            }
        })
        .collect()
}

pub fn write(path: &Path, stats: &[StatRow]) -> Result<()> {
    let mut w = csv::Writer::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    for s in stats {
        w.serialize(s).map_err(|e| Error::invalid(e.to_string()))?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

pub fn read(path: &Path) -> Result<Vec<StatRow>> {
    let file = crate::input::open_regular(path, crate::input::MAX_INPUT_BYTES, "a stats.csv")?;
    let mut r = csv::Reader::from_reader(std::io::BufReader::new(file));
    r.deserialize()
        .enumerate()
        .map(|(k, rec)| {
            let mut s: StatRow = rec.map_err(|e| {
                Error::parse(
                    &path.display().to_string(),
                    k + 2,
                    1,
                    format!("expected a stats.csv row: {e}"),
                )
            })?;
            // Baselines written before the objective names were unified say `tour-turns`.
            s.objective = crate::algorithms::canonical_objective(&s.objective).to_string();
            Ok(s)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_and_percentiles() {
        assert_eq!(size_bin(1), "1-1");
        assert_eq!(size_bin(16), "16-31");
        assert_eq!(size_bin(31), "16-31");
        let s = Summary::of(&mut [1.2, 1.0, 1.1, 1.5]);
        assert_eq!((s.count, s.median, s.max), (4, Some(1.1), Some(1.5)));
        assert_eq!(s.p95, Some(1.5));
        assert_eq!(s.mean, Some(1.2));
    }
}
