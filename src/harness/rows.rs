//! The rows of `results.csv`: one flat row per (instance, algorithm or exact objective).
//!
//! Values are integers; ratios are computed from them and written with 6 decimals, so the same
//! inputs give the same bytes. `ratio_opt` is empty where no proven optimum exists.

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::io::{BufReader, Write};
use std::path::Path;

/// The `algorithm` column of exact-solver rows.
pub const EXACT: &str = "exact";

/// The prefix of the `error` of a row whose failure came from the machine, not the instance
/// (an I/O error such as a full disk, a kill by a signal, memory exhausted): `bench --resume`
/// runs such rows again.
pub const MACHINE_ERROR: &str = "machine: ";

/// What in an error message says that the machine failed rather than the instance: the
/// messages of ENOSPC, EDQUOT, EIO, ENOMEM, an allocation failure and a kill by SIGKILL or
/// SIGTERM (the OOM killer, a preempting scheduler).
const MACHINE_CAUSES: &[&str] = &[
    "No space left on device",
    "(os error 28)",
    "Disk quota exceeded",
    "(os error 122)",
    "Input/output error",
    "(os error 5)",
    "Cannot allocate memory",
    "(os error 12)",
    "memory allocation of",
    "out of memory",
    "signal: 9",
    "signal: 15",
    "SIGKILL",
    "SIGTERM",
];

/// Whether an error message was caused by the machine (see [`MACHINE_ERROR`]): marked with
/// the prefix, or, in rows written before the prefix existed, one of the known messages.
pub fn machine_caused(error: &str) -> bool {
    error.starts_with(MACHINE_ERROR) || MACHINE_CAUSES.iter().any(|c| error.contains(c))
}

/// One row of `results.csv`; the field order is the column order (a contract).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Row {
    pub run_id: String,
    pub instance: String,
    pub sha256: String,
    pub family: String,
    pub params: String,
    pub seed: u64,
    pub n: u64,
    pub holes: u64,
    pub algorithm: String,
    pub objective: String,
    pub value: Option<u64>,
    pub length: Option<u64>,
    pub turns: Option<u64>,
    pub cycles: Option<u64>,
    pub max_coverage: Option<u64>,
    pub opt: Option<u64>,
    pub opt_status: String,
    pub lower_bound: Option<u64>,
    pub lb_source: String,
    pub ratio_opt: Option<Ratio>,
    pub ratio_lb: Option<Ratio>,
    pub ratio_n: Option<Ratio>,
    pub guarantee: String,
    /// `true`, `false`, or empty when it cannot be decided (no optimum, bound too weak).
    pub within_guarantee: Option<bool>,
    pub valid: Option<bool>,
    pub seconds: f64,
    pub error: String,
    /// The merge strategy the row's algorithm ran with (empty where merging does not apply).
    #[serde(default)]
    pub merge: String,
    /// The lawn cutter and motion (empty where it does not apply).
    #[serde(default)]
    pub cutter: String,
    /// Whether tours were rewritten to cover each pixel at most 4 times (empty where it does
    /// not apply).
    #[serde(default)]
    pub coverage4: Option<bool>,
    /// The instance's model: `grid` or `discrete` (empty in rows of older runs).
    #[serde(default)]
    pub model: String,
    /// Table 1's parameters of the instance (of its grid graph for a grid region): d the
    /// allowed directions (empty off lattices), δ the average degree, μ the maximum degree, ρ
    /// the average number of directions; and the exact counts behind δ and ρ (δ = 2·edges/n,
    /// ρ = direction_sum/n), from which claims are decided in integers.
    #[serde(default)]
    pub d: Option<u32>,
    #[serde(default)]
    pub delta: Option<Ratio>,
    #[serde(default)]
    pub mu: Option<u32>,
    #[serde(default)]
    pub rho: Option<Ratio>,
    #[serde(default)]
    pub edges: Option<u64>,
    #[serde(default)]
    pub direction_sum: Option<u64>,
    /// Lengths (`length`, and `value`, `opt`, `lower_bound` of a `length` row) are in units of
    /// 1/`unit`: empty means 1 (pixels, graphs); orthogonal polygons with arbitrary coordinates
    /// write their exact lengths over a common denominator (see `evaluate`).
    #[serde(default)]
    pub unit: Option<u64>,
    /// The ids ([`Theorem::key`](crate::algorithms::theorems::Theorem::key)) of the theorems the
    /// row's algorithm claims for its objective whose condition holds on the instance, joined by
    /// `; ` (an outside algorithm's: its config's claim, `outside:claim of NAME`; exact rows:
    /// none): the claims table joins on them.
    #[serde(default)]
    pub theorems: String,
}

impl Row {
    /// The key `--resume` and `merge` identify a row by.
    pub fn key(&self) -> (String, String, String) {
        (
            self.instance.clone(),
            self.algorithm.clone(),
            self.objective.clone(),
        )
    }

    /// Why the row contradicts itself, or `None` when it does not: the one check of a row's
    /// integers that `bench`, `claims` and `gate` share.
    ///
    /// A row is inconsistent when its `value` is below its own proven lower bound
    /// (`lower_bound`) or proven optimum (`opt`, set only when a solve proved it), when its
    /// `opt` is below its `lower_bound`, or when its `value` disagrees with the column the
    /// objective counts (`length` for `length`, `lawn-length`, `lawn-tsp`; `turns` for `turns`,
    /// `tour-turns`, `cc-turns`; `length + C·turns` for `weighted…-c<C>`). No walk can beat a
    /// proven bound, so such a row is never an improvement: it is an invalid result.
    pub fn consistency_error(&self) -> Option<String> {
        let value = self.value?;
        let own = match self.objective.as_str() {
            "length" | "lawn-length" | "lawn-tsp" => self.length.map(|l| ("length", Some(l))),
            "turns" | "tour-turns" | "cc-turns" => self.turns.map(|t| ("turns", Some(t))),
            o if o.starts_with("weighted") => o
                .rsplit_once("-c")
                .and_then(|(_, c)| c.parse::<u64>().ok())
                .zip(self.length.zip(self.turns))
                .map(|(c, (l, t))| {
                    (
                        "length + C*turns",
                        c.checked_mul(t).and_then(|ct| ct.checked_add(l)),
                    )
                }),
            _ => None,
        };
        if let Some((column, counted)) = own
            && counted != Some(value)
        {
            let counted = counted.map_or("overflow".to_string(), |c| c.to_string());
            return Some(format!(
                "value {value} disagrees with its {column} column ({counted}) for objective {}",
                self.objective
            ));
        }
        if let Some(lb) = self.lower_bound
            && value < lb
        {
            return Some(format!(
                "value {value} is below its proven lower bound {lb} ({})",
                self.lb_source
            ));
        }
        if let Some(opt) = self.opt {
            if value < opt {
                return Some(format!(
                    "value {value} is below its proven optimum {opt} (opt_status {})",
                    self.opt_status
                ));
            }
            if let Some(lb) = self.lower_bound
                && opt < lb
            {
                return Some(format!(
                    "proven optimum {opt} is below its proven lower bound {lb} ({})",
                    self.lb_source
                ));
            }
        }
        None
    }

    /// Marks an inconsistent row ([`Row::consistency_error`]) invalid, with the reason in its
    /// `error` column; returns whether it was.
    pub fn mark_inconsistent(&mut self) -> bool {
        let Some(why) = self.consistency_error() else {
            return false;
        };
        self.valid = Some(false);
        let why = format!("inconsistent row: {why}");
        if !self.error.contains(&why) {
            self.error = if self.error.is_empty() {
                why
            } else {
                format!("{}; {why}", self.error)
            };
        }
        true
    }

    /// Whether the row carries `theorem`'s id in its `theorems` column.
    pub fn cites(&self, theorem: &crate::algorithms::theorems::Theorem) -> bool {
        let key = theorem.key();
        self.theorems.split("; ").any(|k| k == key)
    }

    /// The row as messages name it: instance, algorithm, objective.
    pub fn describe(&self) -> String {
        format!("{} {} {}", self.instance, self.algorithm, self.objective)
    }

    /// Fills the model's parameter columns.
    pub fn set_params(&mut self, model: &str, p: &crate::discrete::Params) {
        self.model = model.to_string();
        self.d = p.d;
        self.mu = Some(p.mu);
        self.edges = Some(p.edges);
        self.direction_sum = Some(p.direction_sum);
        self.delta = Some(Ratio::of(2 * p.edges, p.n.max(1)));
        self.rho = Some(Ratio::of(p.direction_sum, p.n.max(1)));
    }

    /// The instance's parameters from the row's columns (`None` for rows without them). The
    /// star cover's β_max is not a column: it is 0 here.
    pub fn params(&self) -> Option<crate::discrete::Params> {
        let (edges, direction_sum, mu) = (self.edges?, self.direction_sum?, self.mu?);
        let n = self.n.max(1) as f64;
        Some(crate::discrete::Params {
            delta: 2.0 * edges as f64 / n,
            mu,
            rho: direction_sum as f64 / n,
            d: self.d,
            n: self.n,
            edges,
            direction_sum,
            beta_max: 0,
        })
    }

    /// Fills the three ratios from the integer columns.
    pub fn compute_ratios(&mut self) {
        let ratio = |num: Option<u64>, den: Option<u64>| match (num, den) {
            (Some(a), Some(b)) if b > 0 => Some(Ratio::of(a, b)),
            _ => None,
        };
        self.ratio_opt = ratio(self.value, self.opt);
        self.ratio_lb = ratio(self.value, self.lower_bound);
        // value / N in the value's units: a length in units of 1/unit is divided by unit·N.
        let unit = if self.objective == "length" {
            self.unit.unwrap_or(1)
        } else {
            1
        };
        self.ratio_n = ratio(self.value, self.n.checked_mul(unit));
    }
}

/// A ratio of integers, stored as its value rounded to 6 decimals so that CSV bytes are
/// reproducible.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Ratio(pub f64);

impl Ratio {
    pub fn of(a: u64, b: u64) -> Ratio {
        Ratio((a as f64 / b as f64 * 1e6).round() / 1e6)
    }
}

impl Serialize for Ratio {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(&format!("{:.6}", self.0))
    }
}

impl<'de> Deserialize<'de> for Ratio {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        f64::deserialize(d).map(Ratio)
    }
}

/// Appends rows to `results.csv`, writing the header when the file is new and flushing after
/// every batch, so that a killed run keeps every row it finished.
/// The header line of `results.csv` (the current columns, a contract), without its newline.
pub fn header() -> Result<String> {
    let mut w = csv::WriterBuilder::new()
        .has_headers(true)
        .from_writer(Vec::new());
    w.serialize(Row::default())
        .map_err(|e| Error::invalid(e.to_string()))?;
    let bytes = w.into_inner().map_err(|e| Error::invalid(e.to_string()))?;
    let text = String::from_utf8_lossy(&bytes).into_owned();
    Ok(text.lines().next().unwrap_or_default().to_string())
}

pub struct RowWriter {
    file: File,
}

impl RowWriter {
    pub fn open(path: &Path) -> Result<RowWriter> {
        let fresh = !path.exists()
            || std::fs::metadata(path)
                .map(|m| m.len() == 0)
                .unwrap_or(true);
        if !fresh {
            truncate_partial_line(path)?;
        }
        let mut file = OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
            .map_err(|e| Error::io(path, e))?;
        if fresh {
            file.write_all(format!("{}\n", header()?).as_bytes())
                .map_err(|e| Error::io(path, e))?;
        }
        Ok(RowWriter { file })
    }

    /// Writes a batch of rows and flushes it to disk.
    pub fn append(&mut self, rows: &[Row]) -> Result<()> {
        let mut w = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(Vec::new());
        for r in rows {
            w.serialize(r).map_err(|e| Error::invalid(e.to_string()))?;
        }
        let bytes = w.into_inner().map_err(|e| Error::invalid(e.to_string()))?;
        self.file
            .write_all(&bytes)
            .and_then(|_| self.file.sync_data())
            .map_err(|e| Error::Io {
                file: "results.csv".into(),
                source: e,
            })
    }
}

/// A run killed while writing may leave half a line: drop it so appending stays well-formed.
pub fn truncate_partial_line(path: &Path) -> Result<()> {
    let bytes = crate::input::read_bytes(path, "a results.csv")?;
    if bytes.last().is_some_and(|&b| b != b'\n') {
        let keep = bytes.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1);
        let f = OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(|e| Error::io(path, e))?;
        f.set_len(keep as u64).map_err(|e| Error::io(path, e))?;
    }
    Ok(())
}

/// The largest `results.csv` read (1 GiB, some 2·10^6 rows): a bound, so that a file that
/// never ends cannot exhaust the memory.
pub const MAX_RESULTS_BYTES: u64 = 1 << 30;

pub use crate::input::open_regular;

/// Reads every row of a `results.csv` (a regular file of at most [`MAX_RESULTS_BYTES`]; an
/// empty file or a header alone gives no rows, as a run that finished nothing has).
pub fn read_rows(path: &Path) -> Result<Vec<Row>> {
    let file = open_regular(path, MAX_RESULTS_BYTES, "a results.csv")?;
    let mut r = csv::Reader::from_reader(BufReader::new(file));
    let mut rows = Vec::new();
    for (k, rec) in r.deserialize::<Row>().enumerate() {
        let row = rec.map_err(|e| {
            let line = e.position().map_or(k + 2, |p| p.line() as usize);
            Error::parse(
                &path.display().to_string(),
                line,
                1,
                format!("expected a results.csv row: {e}"),
            )
        })?;
        // Files written before the objective names were unified say `tour-turns`.
        let mut row = row;
        row.objective = crate::algorithms::canonical_objective(&row.objective).to_string();
        rows.push(row);
    }
    Ok(rows)
}

/// The one reader of a finished run's `results.csv` that `claims`, `plot` and `gate` share:
/// [`read_rows`], refusing a file without rows (empty, or a header alone), since every
/// verdict drawn from it would be vacuous.
pub fn read_results(path: &Path) -> Result<Vec<Row>> {
    let rows = read_rows(path)?;
    if rows.is_empty() {
        return Err(Error::invalid(format!(
            "{}: no result rows (an empty file or a header alone): expected a results.csv \
             written by `mowmill bench`, with at least one row",
            path.display()
        )));
    }
    Ok(rows)
}

/// Writes rows to a fresh `results.csv` in canonical order (instance, algorithm, objective),
/// the order every run, resumed run and merge of shards ends with.
pub fn write_sorted(path: &Path, rows: &mut [Row]) -> Result<()> {
    rows.sort_by_key(Row::key);
    let tmp = path.with_extension("csv.tmp");
    {
        let mut w = csv::Writer::from_path(&tmp)
            .map_err(|e| Error::invalid(format!("{}: {e}", tmp.display())))?;
        for r in rows.iter() {
            w.serialize(r).map_err(|e| Error::invalid(e.to_string()))?;
        }
        w.flush().map_err(|e| Error::io(&tmp, e))?;
    }
    std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e))
}
