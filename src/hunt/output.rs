//! A hunt's files: `hunt.csv` (one line per evaluation), `worst/` (the top-K distinct
//! instances: `.grid`, the algorithm's walk, the optimal walk, a side-by-side figure with turns
//! marked), `findings/` (violations, invalid walks, errors, false certificates, each with a
//! note), `best.{png,svg}` (best ratio against evaluations) and `manifest.json`.
//!
//! All but `manifest.json` are also written while the hunt runs ([`write_all`] as the hunt's
//! checkpoint: after every new worst ratio or finding, and at least once a minute), so a killed
//! hunt keeps what it found; `manifest.json` is written last, when the hunt ends.

use super::{Found, HuntOptions, HuntReport, Record};
use crate::draw::{DrawOptions, draw_beside};
use crate::error::{Error, Result};
use crate::gridfile::GridFile;
use crate::harness::plots::{Figure, render};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::Path;

/// The columns of `hunt.csv` (a contract; the first six are the issue's).
pub const COLUMNS: [&str; 15] = [
    "evaluation",
    "elapsed",
    "ratio",
    "best_so_far",
    "n",
    "sha256",
    "chain",
    "ratio_bound",
    "value",
    "opt",
    "lower_bound",
    "accepted",
    "note",
    "best",
    "best_source",
];

fn opt<T: ToString>(x: Option<T>) -> String {
    x.map_or(String::new(), |v| v.to_string())
}

/// Writes `hunt.csv`; ratios with 6 decimals so that the same run gives the same bytes apart
/// from `elapsed`. Written beside and renamed over the old file, so that a hunt killed during a
/// checkpoint leaves the previous checkpoint's file whole.
pub fn write_csv(path: &Path, records: &[Record]) -> Result<()> {
    let tmp = path.with_extension("csv.tmp");
    write_csv_to(&tmp, records)?;
    std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e))
}

fn write_csv_to(path: &Path, records: &[Record]) -> Result<()> {
    let mut w = csv::Writer::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    let csv_err = |e: csv::Error| Error::invalid(format!("{}: {e}", path.display()));
    w.write_record(COLUMNS).map_err(csv_err)?;
    let r6 = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:.6}"));
    for r in records {
        w.write_record([
            r.evaluation.to_string(),
            format!("{:.3}", r.elapsed),
            r6(r.ratio),
            format!("{:.6}", r.best_so_far),
            r.n.to_string(),
            r.sha256.clone(),
            r.chain.to_string(),
            r6(r.ratio_bound),
            opt(r.value),
            opt(r.opt),
            opt(r.lower_bound),
            r.accepted.to_string(),
            r.note.clone(),
            opt(r.best),
            r.best_source.clone(),
        ])
        .map_err(csv_err)?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

/// Saves one instance with its walks and figure as `dir/stem.*`.
fn save(
    dir: &Path,
    stem: &str,
    f: &Found,
    algo: &str,
    opts: &HuntOptions,
    note: &str,
) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let meta = [
        ("algorithm", algo.to_string()),
        ("objective", opts.objective.to_string()),
        ("ratio", format!("{:.6}", f.ratio)),
        ("value", f.value.to_string()),
        ("reference", opt(f.reference)),
        ("evaluation", f.evaluation.to_string()),
        ("hunt_seed", opts.seed.to_string()),
        ("against", opts.against.to_string()),
        ("best_source", f.best_source.clone()),
    ];
    // Renamed into place: a hunt killed during a checkpoint leaves whole instance files.
    let (grid, tmp) = (
        dir.join(format!("{stem}.grid")),
        dir.join(format!(".{stem}.grid.tmp")),
    );
    GridFile::with_meta(f.region.clone(), &meta).write(&tmp)?;
    std::fs::rename(&tmp, &grid).map_err(|e| Error::io(&grid, e))?;
    // A checkpoint's files under the same stem may be another region's: none is left behind.
    for (walk, suffix) in [(&f.walk, "walk"), (&f.optimal_walk, "optimal")] {
        let path = dir.join(format!("{stem}.{suffix}.json"));
        match walk {
            Some(w) => w.write(&path)?,
            None => remove_stale(&path)?,
        }
    }
    let titled = |title: String| DrawOptions {
        title: Some(title),
        ..DrawOptions::default()
    };
    let left = titled(format!("{algo}: {} {}", opts.objective, f.value));
    let right = titled(match (f.optimal_walk.is_some(), f.reference) {
        (true, Some(r)) if !f.best_source.is_empty() => {
            format!("best known ({}): {} {r}", f.best_source, opts.objective)
        }
        (true, Some(r)) => format!("optimal: {} {r}", opts.objective),
        _ => "no optimal walk".to_string(),
    });
    draw_beside(
        (&f.region, f.walk.as_ref(), &left),
        (&f.region, f.optimal_walk.as_ref(), &right),
        &dir.join(format!("{stem}.svg")),
    )?;
    let path = dir.join(format!("{stem}.txt"));
    if note.is_empty() {
        remove_stale(&path)?;
    } else {
        std::fs::write(&path, format!("{note}\n")).map_err(|e| Error::io(&path, e))?;
    }
    Ok(())
}

/// Removes a file an earlier checkpoint wrote, if it is there.
fn remove_stale(path: &Path) -> Result<()> {
    match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(Error::io(path, e)),
        _ => Ok(()),
    }
}

/// The best ratio against evaluations.
struct BestCurve<'a> {
    records: &'a [Record],
    title: String,
}

impl Figure for BestCurve<'_> {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| Error::invalid(format!("plot: {e}"));
        let pts: Vec<(f64, f64)> = self
            .records
            .iter()
            .filter(|r| r.best_so_far > 0.0)
            .map(|r| (r.evaluation as f64, r.best_so_far))
            .collect();
        let x_hi = pts.last().map_or(1.0, |p| p.0).max(1.0);
        let y_lo = pts.first().map_or(1.0, |p| p.1).min(1.0) * 0.98;
        let y_hi = pts.last().map_or(1.0, |p| p.1).max(1.0) * 1.05;
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..x_hi, y_lo..y_hi)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("evaluations")
            .y_desc("worst ratio found")
            .draw()
            .map_err(err)?;
        chart
            .draw_series(LineSeries::new(pts, &BLUE))
            .map_err(err)?;
        Ok(())
    }
}

/// Writes every output of a hunt into `out`.
pub fn write_all(out: &Path, report: &HuntReport, algo: &str, opts: &HuntOptions) -> Result<()> {
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    write_csv(&out.join("hunt.csv"), &report.records)?;
    for (k, f) in report.worst.iter().enumerate() {
        let note = if f.best_source.is_empty() {
            String::new()
        } else {
            format!(
                "ratio {:.6} = value {} / best known walk {} from {} (OPT <= {})",
                f.ratio,
                f.value,
                opt(f.reference),
                f.best_source,
                opt(f.reference)
            )
        };
        save(
            &out.join("worst"),
            &format!("rank-{:02}", k + 1),
            f,
            algo,
            opts,
            &note,
        )?;
    }
    for (k, f) in report.findings.iter().enumerate() {
        let mut note = String::new();
        let _ = writeln!(note, "{}", f.what);
        let _ = writeln!(
            note,
            "algorithm {algo}, objective {}, evaluation {}, value {}, reference {}{}",
            opts.objective,
            f.evaluation,
            f.value,
            opt(f.reference),
            if f.best_source.is_empty() {
                String::new()
            } else {
                format!(" (best known walk, from {})", f.best_source)
            }
        );
        save(
            &out.join("findings"),
            &format!("finding-{:03}", k + 1),
            f,
            algo,
            opts,
            &note,
        )?;
    }
    crate::draw::ensure_fonts();
    render(
        &out.join("best"),
        (900, 500),
        &BestCurve {
            records: &report.records,
            title: format!("{algo} ({}): worst ratio found", opts.objective),
        },
    )?;
    Ok(())
}
