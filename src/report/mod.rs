//! `mowmill report`: one self-contained HTML page per run (docs/report.md).
//!
//! The page is assembled from what the run folder holds, read as data: `manifest.json` (the
//! provenance), `claims.csv` (else the claims table is computed from `results.csv`, as
//! `mowmill claims --from RUN` computes it), `stats.csv` (else computed from `results.csv`),
//! `results.csv` when kept (per-instance points, times, errors and time limits, the worst
//! instances), `findings/` (the violations' witnesses), and when given a `tight` and a `hunt`
//! folder. Nothing in the folder is run: the walks drawn are the run's kept walks or a
//! registered algorithm re-run by its registry name, recounted by the checker and compared
//! with the row's value.
//!
//! Sections, in order: provenance, claims, ratios, worst instances, tight families, findings,
//! time, errors and time limits, hunt.

pub mod chart;
mod compare;
mod drawings;
pub mod html;
mod sections;

pub use compare::compare;

use crate::error::{Error, Result};
use crate::harness::rows::{Row, read_results};
use crate::harness::stats::{self, StatRow};
use crate::tight::TightRow;
use std::path::{Path, PathBuf};

/// What a report is made from, besides the run folder.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// A `mowmill tight` folder (its `tight.csv` and `figures/`), for the tight-family section.
    pub tight: Option<PathBuf>,
    /// A `mowmill hunt` folder (its `summary.csv` and per-hunt `best.svg`), for the hunt section.
    pub hunt: Option<PathBuf>,
}

/// A CSV file read as text: its header and records, for the tables shown as they are.
#[derive(Clone, Debug, Default)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Reads `path` (an error names the file and the line).
    pub fn read(path: &Path) -> Result<Table> {
        let file = crate::input::open_regular(path, crate::input::MAX_INPUT_BYTES, "a CSV file")?;
        let mut r = csv::Reader::from_reader(std::io::BufReader::new(file));
        let header = r
            .headers()
            .map_err(|e| Error::parse(&path.display().to_string(), 1, 1, e.to_string()))?
            .iter()
            .map(str::to_string)
            .collect();
        let mut rows = Vec::new();
        for (k, rec) in r.records().enumerate() {
            let rec = rec
                .map_err(|e| Error::parse(&path.display().to_string(), k + 2, 1, e.to_string()))?;
            rows.push(rec.iter().map(str::to_string).collect());
        }
        Ok(Table { header, rows })
    }

    /// The column named `name`, if any.
    pub fn col(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// The value of column `name` in `row` (empty when the column is missing).
    pub fn get<'a>(&self, row: &'a [String], name: &str) -> &'a str {
        self.col(name)
            .and_then(|i| row.get(i))
            .map_or("", String::as_str)
    }
}

/// A run folder read for a report.
pub struct Run {
    pub dir: PathBuf,
    /// `manifest.json` and the sha256 of its bytes.
    pub manifest: Option<(serde_json::Value, String)>,
    pub claims: Option<Table>,
    /// Where the claims table came from (`claims.csv`, or computed).
    pub claims_source: String,
    pub stats: Vec<StatRow>,
    /// `results.csv`, when the folder keeps it.
    pub rows: Option<Vec<Row>>,
    pub tight: Option<Table>,
    pub tight_dir: Option<PathBuf>,
    pub hunt: Option<(PathBuf, Table)>,
}

impl Run {
    /// Reads what `dir` holds; an error when it holds neither `stats.csv` nor `results.csv`.
    pub fn read(dir: &Path, opts: &Options) -> Result<Run> {
        if !dir.is_dir() {
            return Err(Error::invalid(format!(
                "{}: expected a run folder (a `mowmill bench` output)",
                dir.display()
            )));
        }
        let manifest_path = dir.join("manifest.json");
        let manifest = match manifest_path.exists().then(|| read_regular(&manifest_path)) {
            Some(bytes) => {
                let bytes = bytes?;
                let value: serde_json::Value = serde_json::from_slice(&bytes).map_err(|e| {
                    Error::parse(
                        &dir.join("manifest.json").display().to_string(),
                        e.line(),
                        e.column(),
                        e.to_string(),
                    )
                })?;
                Some((value, crate::harness::run::sha256_hex(&bytes)))
            }
            None => None,
        };
        let results = dir.join("results.csv");
        let rows = if results.is_file() {
            Some(read_results(&results)?)
        } else {
            None
        };
        let stats_path = dir.join("stats.csv");
        let stats = match (&rows, stats_path.is_file()) {
            (_, true) => stats::read(&stats_path)?,
            (Some(rows), false) => stats::compute(rows),
            (None, false) => {
                return Err(Error::invalid(format!(
                    "{}: expected stats.csv or results.csv in a run folder",
                    dir.display()
                )));
            }
        };
        let tight_dir = match &opts.tight {
            Some(t) => Some(t.clone()),
            None if dir.join("tight.csv").is_file() => Some(dir.to_path_buf()),
            None => None,
        };
        let tight = match &tight_dir {
            Some(t) => Some(Table::read(&t.join("tight.csv"))?),
            None => None,
        };
        let (claims, claims_source) = if dir.join("claims.csv").is_file() {
            (
                Some(Table::read(&dir.join("claims.csv"))?),
                "claims.csv".to_string(),
            )
        } else if let Some(rows) = &rows {
            let tight_rows: Vec<TightRow> = match &tight_dir {
                Some(t) => crate::claims::read_tight(&t.join("tight.csv"))?,
                None => Vec::new(),
            };
            (
                Some(computed_claims(rows, &tight_rows, dir)?),
                "computed from results.csv (as `mowmill claims --from RUN`)".to_string(),
            )
        } else {
            (None, String::new())
        };
        let hunt = match &opts.hunt {
            Some(h) => Some((h.clone(), Table::read(&h.join("summary.csv"))?)),
            None => None,
        };
        Ok(Run {
            dir: dir.to_path_buf(),
            manifest,
            claims,
            claims_source,
            stats,
            rows,
            tight,
            tight_dir,
            hunt,
        })
    }
}

/// The bytes of the regular file `path` (a FIFO or a device is refused, not waited on).
fn read_regular(path: &Path) -> Result<Vec<u8>> {
    use std::io::Read;
    let mut file =
        crate::input::open_regular(path, crate::input::MAX_INPUT_BYTES, "a manifest.json")?;
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes)
        .map_err(|e| Error::io(path, e))?;
    Ok(bytes)
}

/// The claims table of `rows`, as `mowmill claims` writes it, read back as a [`Table`].
fn computed_claims(rows: &[Row], tight: &[TightRow], dir: &Path) -> Result<Table> {
    let mut table = crate::claims::table(rows, tight);
    if let Ok(sources) = crate::claims::Sources::new(&[dir.to_path_buf()]) {
        crate::claims::add_choice_evidence(&mut table, &sources);
    }
    let tmp = tempfile::tempdir().map_err(|e| Error::io(Path::new("a temporary folder"), e))?;
    let path = tmp.path().join("claims.csv");
    crate::claims::write_csv(&table, &path)?;
    Table::read(&path)
}

/// The report of `run` as one HTML page.
pub fn render(run: &Run) -> Result<String> {
    let title = match &run.manifest {
        Some((m, _)) => format!(
            "mowmill report: {}",
            m.get("run_id").and_then(|v| v.as_str()).unwrap_or("run")
        ),
        None => format!("mowmill report: {}", run.dir.display()),
    };
    let subtitle = format!(
        "{}: do the papers' claims hold, by how much, where is each worst case",
        run.dir.display()
    );
    Ok(html::page(&title, &subtitle, &sections::all(run)?))
}

/// Reads `dir` and writes its report to `out`; returns the page's size in bytes.
pub fn write(dir: &Path, opts: &Options, out: &Path) -> Result<usize> {
    let run = Run::read(dir, opts)?;
    let page = render(&run)?;
    std::fs::write(out, &page).map_err(|e| Error::io(out, e))?;
    Ok(page.len())
}
