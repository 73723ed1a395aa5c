//! A fixed random sample of a run's rows, committed beside the claims table and re-run by CI
//! (`mowmill sample`, docs/outputs.md "Sample"): a change that moves any sampled number fails
//! the check until the sample is drawn again from a regenerated run.
//!
//! [`draw`] picks rows of one or more run directories: first one row for every (run, family)
//! and every (model, algorithm, objective) not yet represented, then more rows at random, each
//! weighted by 1 / (0.25 s + the recorded seconds it adds), until `count` rows or
//! `max_seconds` recorded seconds. Every exact row of a sampled instance comes with it (the
//! algorithm rows divide by them). Never sampled, and counted in `sample.json` under
//! `excluded`: error rows, rows of outside algorithms (the check runs no command), and every
//! row of an instance whose exact solve failed, hit its time limit or used more than a quarter
//! of it (its incumbent and bound depend on the machine's speed, and so do the algorithm rows
//! dividing by them).
//!
//! [`check`] recomputes every sampled row from the copied instance file through the bench's
//! own code ([`super::run::run_loaded`]) with the run's recorded config, and compares every
//! column but `run_id` and `seconds` with the committed row.
//!
//! The sample directory holds `sample.csv` (the rows, in the columns of `results.csv`),
//! `sample.json` (how it was drawn, which run each `run_id` belongs to, what was excluded),
//! `manifests/RUN.json` (each run's manifest, whose `config_toml` the check runs with) and
//! `instances/RUN/` (the sampled instance files, their sha256 checked against the rows).

use super::config::{Config, InstanceSpec, Source};
use super::manifest::Recorded;
use super::rows::{EXACT, Row, read_rows};
use super::run::{Loaded, exact_objective_name, run_loaded, sha256_hex};
use crate::algorithms;
use crate::error::{Error, Result};
use crate::evaluate::parse_variant;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The rows of a sample directory.
pub const SAMPLE_CSV: &str = "sample.csv";
/// How the sample was drawn and which run each row belongs to.
pub const INDEX: &str = "sample.json";

/// Columns the check does not compare: they name the run and time it.
pub const NOT_COMPARED: &[&str] = &["run_id", "seconds"];

/// Columns not compared on exact rows: an optimum is one of possibly several optimal walks, and
/// which one HiGHS returns depends on its warm start (the best registered algorithm's walk, which
/// a new algorithm changes); the value, OPT, lower bound and status are compared.
pub const NOT_COMPARED_EXACT: &[&str] = &["length", "turns", "cycles", "max_coverage"];

/// The weight floor of the random draws (seconds): rows that add nothing are not infinitely
/// likely, so a sample spreads over many instances.
const COST_FLOOR: f64 = 0.25;

/// How to draw a sample.
#[derive(Clone, Debug)]
pub struct DrawOptions {
    /// About this many rows (the exact rows of the sampled instances included).
    pub count: usize,
    pub seed: u64,
    /// The most recorded seconds the sampled rows may add up to (each instance's exact solves
    /// and each algorithm run counted once).
    pub max_seconds: f64,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            count: 2000,
            seed: 1,
            max_seconds: 120.0,
        }
    }
}

/// `sample.json`.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Index {
    pub count: usize,
    pub seed: u64,
    pub max_seconds: f64,
    /// The recorded seconds of the sampled rows (each instance's exact solves and each
    /// algorithm run counted once).
    pub estimated_seconds: f64,
    pub rows: usize,
    pub instances: usize,
    pub runs: Vec<RunEntry>,
    /// Rows never sampled, by reason.
    pub excluded: BTreeMap<String, usize>,
}

/// One run a sample was drawn from.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunEntry {
    /// The run directory's name: `manifests/NAME.json`, `instances/NAME/`.
    pub name: String,
    /// The directory the rows were read from.
    pub from: String,
    /// The `run_id` of its rows.
    pub run_id: String,
    /// Rows of its results.csv, and how many of them are in the sample.
    pub rows: usize,
    pub sampled: usize,
}

/// A run directory as the draw reads it.
struct Run {
    entry: RunEntry,
    dir: PathBuf,
    rows: Vec<Row>,
}

/// Reasons a row is never sampled (the keys of `excluded`).
const EXCLUDED_ERROR: &str = "error row";
const EXCLUDED_OUTSIDE: &str = "outside algorithm (the check runs no command)";
const EXCLUDED_TIME: &str =
    "instance whose exact solve failed, hit its time limit or used over a quarter of it";

/// The base name of a row's `algorithm` column (`NAME[options]` → `NAME`).
fn base_name(algorithm: &str) -> &str {
    algorithm.split_once('[').map_or(algorithm, |(n, _)| n)
}

fn is_registered(algorithm: &str) -> bool {
    algorithm == EXACT || algorithms::find(base_name(algorithm)).is_some()
}

/// Draws a sample of the rows of the runs `from` into `out` (see the module's documentation).
/// `out` must be new, empty or an earlier sample directory (whose files are replaced).
pub fn draw(from: &[PathBuf], out: &Path, opts: &DrawOptions) -> Result<Index> {
    if from.is_empty() {
        return Err(Error::invalid(
            "expected at least one run directory (--from)",
        ));
    }
    if opts.count == 0 {
        return Err(Error::invalid("--count 0: expected at least 1 row"));
    }
    if !(opts.max_seconds.is_finite() && opts.max_seconds > 0.0) {
        return Err(Error::invalid(format!(
            "--max-seconds {}: expected a positive number of seconds",
            opts.max_seconds
        )));
    }
    let mut runs = Vec::new();
    for dir in from {
        runs.push(read_run(dir)?);
    }
    let mut names = BTreeSet::new();
    for r in &runs {
        if !names.insert(r.entry.name.clone()) {
            return Err(Error::invalid(format!(
                "two run directories are named {:?}: their files would share instances/{}/",
                r.entry.name, r.entry.name
            )));
        }
    }

    // Every row as (run, index), with the instance it belongs to and its eligibility.
    let mut excluded: BTreeMap<String, usize> = BTreeMap::new();
    let mut candidates: Vec<(usize, usize)> = Vec::new();
    for (ri, run) in runs.iter().enumerate() {
        let limits = time_limits(&run.dir)?;
        // Instances whose exact rows are not reproducible on another machine.
        let mut unstable: BTreeSet<&str> = BTreeSet::new();
        for r in run.rows.iter().filter(|r| r.algorithm == EXACT) {
            let limit = limits.get(&r.objective).copied().unwrap_or(0.0);
            if !r.error.is_empty()
                || r.opt_status == "time_limit"
                || r.opt_status == "error"
                || r.seconds > limit / 4.0
            {
                unstable.insert(&r.instance);
            }
        }
        for (k, r) in run.rows.iter().enumerate() {
            let reason = if unstable.contains(r.instance.as_str()) {
                Some(EXCLUDED_TIME)
            } else if !r.error.is_empty() {
                Some(EXCLUDED_ERROR)
            } else if !is_registered(&r.algorithm) {
                Some(EXCLUDED_OUTSIDE)
            } else {
                None
            };
            match reason {
                Some(why) => *excluded.entry(why.to_string()).or_default() += 1,
                None => candidates.push((ri, k)),
            }
        }
    }

    let mut sampler = Sampler::new(&runs, &candidates);
    let mut rng = ChaCha8Rng::seed_from_u64(opts.seed);
    // First every stratum, then random rows under the budget.
    for members in sampler.strata.clone() {
        if !members.iter().any(|&c| sampler.chosen[c])
            && let Some(pick) = sampler.pick(&members, f64::INFINITY, &mut rng)
        {
            sampler.add(pick);
        }
    }
    let all: Vec<usize> = (0..candidates.len()).collect();
    while sampler.count < opts.count {
        let left = opts.max_seconds - sampler.seconds;
        match sampler.pick(&all, left, &mut rng) {
            Some(pick) => sampler.add(pick),
            None => break,
        }
    }
    let mut chosen: Vec<(usize, usize)> = (0..candidates.len())
        .filter(|&c| sampler.chosen[c])
        .map(|c| candidates[c])
        .collect();

    // Write: rows, manifests, instance files, index.
    prepare_out(out)?;
    chosen.sort_by(|a, b| {
        let (x, y) = (&runs[a.0].rows[a.1], &runs[b.0].rows[b.1]);
        (a.0, x.key()).cmp(&(b.0, y.key()))
    });
    let mut instances: BTreeSet<(usize, &str)> = BTreeSet::new();
    for &(ri, k) in &chosen {
        instances.insert((ri, runs[ri].rows[k].instance.as_str()));
    }
    for (ri, run) in runs.iter().enumerate() {
        let dest = out.join("instances").join(&run.entry.name);
        std::fs::create_dir_all(&dest).map_err(|e| Error::io(&dest, e))?;
        let manifest = run.dir.join("manifest.json");
        let copy = out
            .join("manifests")
            .join(format!("{}.json", run.entry.name));
        std::fs::copy(&manifest, &copy).map_err(|e| Error::io(&manifest, e))?;
        for &(_, name) in instances.iter().filter(|(i, _)| *i == ri) {
            let sha = &run
                .rows
                .iter()
                .find(|r| r.instance == name)
                .map(|r| r.sha256.clone())
                .unwrap_or_default();
            let source = instance_file(&run.dir.join("instances"), name)?;
            let bytes = crate::input::read_bytes(&source, "an instance file")?;
            let got = sha256_hex(&bytes);
            if &got != sha {
                return Err(Error::invalid(format!(
                    "{}: sha256 {got}, but the rows of {} record {sha:?}: the instance file is \
                     not the one the run used (rerun the bench)",
                    source.display(),
                    name
                )));
            }
            let target = dest.join(source.file_name().unwrap_or_default());
            std::fs::write(&target, &bytes).map_err(|e| Error::io(&target, e))?;
        }
    }
    let path = out.join(SAMPLE_CSV);
    let mut w = csv::Writer::from_path(&path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    for &(ri, k) in &chosen {
        w.serialize(&runs[ri].rows[k])
            .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    }
    w.flush().map_err(|e| Error::io(&path, e))?;

    let mut entries: Vec<RunEntry> = runs.iter().map(|r| r.entry.clone()).collect();
    for &(ri, _) in &chosen {
        entries[ri].sampled += 1;
    }
    let index = Index {
        count: opts.count,
        seed: opts.seed,
        max_seconds: opts.max_seconds,
        estimated_seconds: (sampler.seconds * 1000.0).round() / 1000.0,
        rows: chosen.len(),
        instances: instances.len(),
        runs: entries,
        excluded,
    };
    let text = serde_json::to_string_pretty(&index).map_err(|e| Error::invalid(e.to_string()))?;
    let path = out.join(INDEX);
    std::fs::write(&path, text + "\n").map_err(|e| Error::io(&path, e))?;
    Ok(index)
}

/// Reads a run directory: its manifest and rows.
fn read_run(dir: &Path) -> Result<Run> {
    let manifest = Recorded::read(dir)?;
    let run_id = manifest
        .run_id()
        .ok_or_else(|| Error::invalid(format!("{}: no run_id", manifest.path.display())))?
        .to_string();
    let rows = read_rows(&dir.join("results.csv"))?;
    if let Some(r) = rows.iter().find(|r| r.run_id != run_id) {
        return Err(Error::invalid(format!(
            "{}: a row of {} has run_id {:?}, the manifest {:?}: expected one run",
            dir.join("results.csv").display(),
            r.instance,
            r.run_id,
            run_id
        )));
    }
    let name = std::fs::canonicalize(dir)
        .unwrap_or_else(|_| dir.to_path_buf())
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "run".into());
    Ok(Run {
        entry: RunEntry {
            name,
            from: dir.display().to_string(),
            run_id,
            rows: rows.len(),
            sampled: 0,
        },
        dir: dir.to_path_buf(),
        rows,
    })
}

/// The time limit of each exact objective of the run's recorded config.
fn time_limits(dir: &Path) -> Result<HashMap<String, f64>> {
    let config = recorded_config(&Recorded::read(dir)?)?;
    Ok(config
        .exact
        .iter()
        .map(|e| (exact_objective_name(e), e.time_limit))
        .collect())
}

/// The config a manifest records, without its outside algorithms: nothing in a sample makes
/// mowmill run a command.
fn recorded_config(manifest: &Recorded) -> Result<Config> {
    let text = manifest.config_toml()?;
    let mut config = Config::parse(&text, &format!("{} (config_toml)", manifest.path.display()))?;
    config.algorithm.clear();
    Ok(config)
}

/// The strata a row represents: its run's family, and its model's algorithm and objective.
fn strata_of(run: &Run, row: &Row) -> [String; 2] {
    [
        format!("family {}/{}", run.entry.name, row.family),
        format!(
            "algorithm {}/{}/{}",
            row.model, row.algorithm, row.objective
        ),
    ]
}

/// The file of instance `name` in a run's `instances/` folder.
fn instance_file(dir: &Path, name: &str) -> Result<PathBuf> {
    let exts = ["grid", "wkt"]
        .iter()
        .chain(crate::discrete::generate::EXTENSIONS.iter());
    exts.map(|e| dir.join(format!("{name}.{e}")))
        .find(|p| p.is_file())
        .ok_or_else(|| {
            Error::invalid(format!(
                "{}: no instance file {name}.grid/.wkt/.dm/.json/.vox/.hex",
                dir.display()
            ))
        })
}

/// Makes `out` ready for a sample: new, empty or an earlier sample (its files replaced).
fn prepare_out(out: &Path) -> Result<()> {
    if out.exists() {
        let empty = std::fs::read_dir(out)
            .map_err(|e| Error::io(out, e))?
            .next()
            .is_none();
        if !empty && !out.join(INDEX).exists() {
            return Err(Error::invalid(format!(
                "{} exists and is not a sample directory (no {INDEX}): choose another --out",
                out.display()
            )));
        }
        for sub in ["instances", "manifests"] {
            let p = out.join(sub);
            if p.exists() {
                std::fs::remove_dir_all(&p).map_err(|e| Error::io(&p, e))?;
            }
        }
    }
    let manifests = out.join("manifests");
    std::fs::create_dir_all(&manifests).map_err(|e| Error::io(&manifests, e))
}

/// One candidate row as the draw sees it: integer ids of its instance and algorithm variant.
struct Candidate {
    instance: usize,
    /// The (instance, algorithm column) run it belongs to; `None` for an exact row.
    variant: Option<usize>,
}

/// The draw's state over the candidate rows (indices into the draw's candidate list): which
/// are chosen and what the chosen ones cost.
struct Sampler {
    candidates: Vec<Candidate>,
    /// Per instance: its exact rows and their recorded seconds.
    exact: Vec<(Vec<usize>, f64)>,
    /// Per variant: the recorded seconds of one run of it (every objective records them).
    variant_seconds: Vec<f64>,
    /// Per stratum (in the order of their names): its candidates.
    strata: Vec<Vec<usize>>,
    chosen: Vec<bool>,
    instance_chosen: Vec<bool>,
    variant_chosen: Vec<bool>,
    count: usize,
    seconds: f64,
}

impl Sampler {
    fn new(runs: &[Run], candidates: &[(usize, usize)]) -> Sampler {
        let mut instance_ids: HashMap<(usize, &str), usize> = HashMap::new();
        let mut variant_ids: HashMap<(usize, &str, &str), usize> = HashMap::new();
        let mut strata: BTreeMap<String, Vec<usize>> = BTreeMap::new();
        let mut exact: Vec<(Vec<usize>, f64)> = Vec::new();
        let mut variant_seconds: Vec<f64> = Vec::new();
        let mut out = Vec::with_capacity(candidates.len());
        for (c, &(ri, k)) in candidates.iter().enumerate() {
            let r = &runs[ri].rows[k];
            let next = instance_ids.len();
            let instance = *instance_ids.entry((ri, &r.instance)).or_insert(next);
            if instance == exact.len() {
                exact.push((Vec::new(), 0.0));
            }
            let variant = if r.algorithm == EXACT {
                exact[instance].0.push(c);
                exact[instance].1 += r.seconds;
                None
            } else {
                let next = variant_ids.len();
                let v = *variant_ids
                    .entry((ri, &r.instance, &r.algorithm))
                    .or_insert(next);
                if v == variant_seconds.len() {
                    variant_seconds.push(0.0);
                }
                variant_seconds[v] = variant_seconds[v].max(r.seconds);
                Some(v)
            };
            for stratum in strata_of(&runs[ri], r) {
                strata.entry(stratum).or_default().push(c);
            }
            out.push(Candidate { instance, variant });
        }
        Sampler {
            chosen: vec![false; out.len()],
            instance_chosen: vec![false; exact.len()],
            variant_chosen: vec![false; variant_seconds.len()],
            candidates: out,
            exact,
            variant_seconds,
            strata: strata.into_values().collect(),
            count: 0,
            seconds: 0.0,
        }
    }

    /// The recorded seconds adding candidate `c` costs.
    fn cost(&self, c: usize) -> f64 {
        let cand = &self.candidates[c];
        let mut cost = 0.0;
        if !self.instance_chosen[cand.instance] {
            cost += self.exact[cand.instance].1;
        }
        if let Some(v) = cand.variant.filter(|&v| !self.variant_chosen[v]) {
            cost += self.variant_seconds[v];
        }
        cost
    }

    /// An unchosen candidate of `pool` costing at most `left`, drawn with weight
    /// 1 / (floor + cost).
    fn pick(&self, pool: &[usize], left: f64, rng: &mut ChaCha8Rng) -> Option<usize> {
        let weight = |c: usize| {
            let cost = self.cost(c);
            (!self.chosen[c] && cost <= left).then(|| 1.0 / (COST_FLOOR + cost))
        };
        let total: f64 = pool.iter().filter_map(|&c| weight(c)).sum();
        if total <= 0.0 {
            return None;
        }
        let mut t = rng.random::<f64>() * total;
        let mut last = None;
        for &c in pool {
            if let Some(w) = weight(c) {
                if t < w {
                    return Some(c);
                }
                t -= w;
                last = Some(c);
            }
        }
        last
    }

    /// Adds a candidate, with the exact rows of its instance.
    fn add(&mut self, c: usize) {
        self.seconds += self.cost(c);
        let (instance, variant) = (self.candidates[c].instance, self.candidates[c].variant);
        let mut added = vec![c];
        if !self.instance_chosen[instance] {
            self.instance_chosen[instance] = true;
            added.extend(self.exact[instance].0.iter().copied());
        }
        if let Some(v) = variant {
            self.variant_chosen[v] = true;
        }
        for c in added {
            if !self.chosen[c] {
                self.chosen[c] = true;
                self.count += 1;
            }
        }
    }
}

/// A sampled row whose recomputed value differs from the committed one (or that could not be
/// recomputed).
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    pub run: String,
    pub instance: String,
    pub algorithm: String,
    pub objective: String,
    /// The column, or `(row)` for a row the re-run did not produce or refused to run.
    pub column: String,
    pub committed: String,
    pub now: String,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}/{} {} {}: {}: committed {:?}, now {:?}",
            self.run,
            self.instance,
            self.algorithm,
            self.objective,
            self.column,
            self.committed,
            self.now
        )
    }
}

/// What [`check`] found.
#[derive(Clone, Debug, Default)]
pub struct CheckReport {
    /// Sampled rows and instances re-run.
    pub rows: usize,
    pub instances: usize,
    pub differences: Vec<Difference>,
    /// Wall-clock seconds of the re-run.
    pub seconds: f64,
}

impl CheckReport {
    pub fn passed(&self) -> bool {
        self.differences.is_empty()
    }
}

/// One sampled instance, ready to re-run.
struct Job<'a> {
    run: &'a str,
    config: Config,
    spec: InstanceSpec,
    loaded: Loaded,
    sha: String,
    base: Row,
    rows: Vec<&'a Row>,
}

/// Re-runs every row of the sample directory `dir` and compares it with the committed row
/// (every column but [`NOT_COMPARED`]). Rows the check refuses to run (an outside algorithm,
/// an error row, an exact row that hit its time limit) are differences too, never run.
/// `jobs`: parallel instances (`None`: all cores).
///
/// # Errors
/// A missing or malformed file of the sample (naming the file and line), an instance file
/// whose sha256 differs from its rows'.
pub fn check(dir: &Path, jobs: Option<usize>) -> Result<CheckReport> {
    let start = Instant::now();
    let index_path = dir.join(INDEX);
    let text = crate::input::read_text(&index_path, "a sample index")?;
    let index: Index = serde_json::from_str(&text).map_err(|e| {
        Error::parse(
            &index_path.display().to_string(),
            e.line(),
            e.column(),
            format!("expected a sample index ({INDEX} of `mowmill sample`): {e}"),
        )
    })?;
    let rows = read_rows(&dir.join(SAMPLE_CSV))?;
    let mut configs: HashMap<&str, (&str, Config)> = HashMap::new();
    for run in &index.runs {
        // A name is a folder of the sample, never a path out of it.
        if run.name.is_empty() || run.name.starts_with('.') || run.name.contains(['/', '\\']) {
            return Err(Error::invalid(format!(
                "{}: run name {:?}: expected a folder name (no `/`, `\\`, leading `.`)",
                index_path.display(),
                run.name
            )));
        }
        let path = dir.join("manifests").join(format!("{}.json", run.name));
        let manifest = Recorded::read_path(&path)?;
        configs.insert(&run.run_id, (&run.name, recorded_config(&manifest)?));
    }

    let mut differences = Vec::new();
    let refuse = |r: &Row, run: &str, why: &str| Difference {
        run: run.to_string(),
        instance: r.instance.clone(),
        algorithm: r.algorithm.clone(),
        objective: r.objective.clone(),
        column: "(row)".into(),
        committed: "a sampled row".into(),
        now: format!("not run: {why}"),
    };
    // Group the rows by (run, instance), refusing what must not or cannot be re-run.
    let mut groups: BTreeMap<(&str, &str), Vec<&Row>> = BTreeMap::new();
    for (line, r) in rows.iter().enumerate() {
        let Some((run, _)) = configs.get(r.run_id.as_str()) else {
            return Err(Error::parse(
                &dir.join(SAMPLE_CSV).display().to_string(),
                line + 2,
                1,
                format!(
                    "run_id {:?}: expected one of the runs of {}",
                    r.run_id,
                    index_path.display()
                ),
            ));
        };
        if !is_registered(&r.algorithm) {
            differences.push(refuse(
                r,
                run,
                "not a registered algorithm (an outside algorithm runs a command; a sample never does)",
            ));
        } else if !r.error.is_empty() {
            differences.push(refuse(r, run, "an error row (samples hold none)"));
        } else if r.algorithm == EXACT && r.opt_status == "time_limit" {
            differences.push(refuse(
                r,
                run,
                "an exact row that hit its time limit depends on the machine's speed",
            ));
        } else {
            groups
                .entry((run, r.instance.as_str()))
                .or_default()
                .push(r);
        }
    }

    let mut jobs_list = Vec::new();
    for ((run, instance), group) in groups {
        let (_, config) = &configs[group[0].run_id.as_str()];
        jobs_list.push(prepare_job(dir, run, instance, config, group)?);
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.unwrap_or(0))
        .build()
        .map_err(|e| Error::invalid(e.to_string()))?;
    let instances = jobs_list.len();
    let checked: usize = jobs_list.iter().map(|j| j.rows.len()).sum();
    let found: Vec<Vec<Difference>> = pool.install(|| {
        jobs_list
            .into_par_iter()
            .map(|job| {
                let produced = run_loaded(
                    &job.loaded,
                    job.sha.clone(),
                    job.base.clone(),
                    &job.spec,
                    &job.config,
                    &HashMap::new(),
                );
                compare(job.run, &job.rows, &produced.rows)
            })
            .collect()
    });
    differences.extend(found.into_iter().flatten());
    Ok(CheckReport {
        rows: checked,
        instances,
        differences,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Loads one sampled instance and names the algorithms its rows need (every exact objective
/// of the config runs, as in the bench: the algorithm rows divide by them).
fn prepare_job<'a>(
    dir: &Path,
    run: &'a str,
    instance: &str,
    config: &Config,
    rows: Vec<&'a Row>,
) -> Result<Job<'a>> {
    let first = rows[0];
    let folder = dir.join("instances").join(run);
    let path = instance_file(&folder, instance)?;
    let bytes = crate::input::read_bytes(&path, "a sample file")?;
    let sha = sha256_hex(&bytes);
    if let Some(r) = rows.iter().find(|r| r.sha256 != sha) {
        return Err(Error::invalid(format!(
            "{}: sha256 {sha}, but its row {} {} records {:?}",
            path.display(),
            r.algorithm,
            r.objective,
            r.sha256
        )));
    }
    // The model the bench loaded it as (a generated ortho polygon may have integral
    // coordinates, which the file alone would read as a grid region).
    let loaded = match first.model.as_str() {
        "discrete" => Loaded::Discrete(crate::discrete::generate::read(&path)?),
        "ortho" => Loaded::Ortho(crate::ortho::Polygon::read(&path)?),
        "grid" | "" => Loaded::Grid(crate::instance::Instance::read(&path)?.region),
        other => {
            return Err(Error::invalid(format!(
                "{}: row {} {} has model {other:?}: expected grid, discrete or ortho",
                dir.join(SAMPLE_CSV).display(),
                first.algorithm,
                first.objective
            )));
        }
    };
    // The run's config, its option sets included (each variant is one of them); only the
    // sampled rows' algorithms run.
    let mut names: Vec<String> = Vec::new();
    for r in rows.iter().filter(|r| r.algorithm != EXACT) {
        let (name, _) = parse_variant(&r.algorithm)?;
        if !names.iter().any(|n| n == name) {
            names.push(name.to_string());
        }
    }
    let spec = InstanceSpec {
        name: instance.to_string(),
        family: first.family.clone(),
        params: first.params.clone(),
        seed: first.seed,
        source: Source::File(path),
        algorithms: Some(names),
    };
    let base = Row {
        run_id: first.run_id.clone(),
        instance: first.instance.clone(),
        family: first.family.clone(),
        params: first.params.clone(),
        seed: first.seed,
        ..Row::default()
    };
    Ok(Job {
        run,
        config: config.clone(),
        spec,
        loaded,
        sha,
        base,
        rows,
    })
}

/// The differences between the committed rows and the rows the re-run produced.
fn compare(run: &str, committed: &[&Row], produced: &[Row]) -> Vec<Difference> {
    let header: Vec<String> = super::rows::header()
        .unwrap_or_default()
        .split(',')
        .map(str::to_string)
        .collect();
    let by_key: HashMap<_, &Row> = produced.iter().map(|r| (r.key(), r)).collect();
    let mut out = Vec::new();
    for old in committed {
        let diff = |column: &str, committed: String, now: String| Difference {
            run: run.to_string(),
            instance: old.instance.clone(),
            algorithm: old.algorithm.clone(),
            objective: old.objective.clone(),
            column: column.to_string(),
            committed,
            now,
        };
        let Some(new) = by_key.get(&old.key()) else {
            out.push(diff(
                "(row)",
                "a row".into(),
                "no row: the re-run did not produce it".into(),
            ));
            continue;
        };
        let (a, b) = (fields(old), fields(new));
        for (i, column) in header.iter().enumerate() {
            if NOT_COMPARED.contains(&column.as_str())
                || (old.algorithm == crate::harness::rows::EXACT
                    && NOT_COMPARED_EXACT.contains(&column.as_str()))
            {
                continue;
            }
            let (x, y) = (a.get(i).cloned(), b.get(i).cloned());
            if x != y {
                out.push(diff(column, x.unwrap_or_default(), y.unwrap_or_default()));
            }
        }
    }
    out
}

/// A row's fields as `results.csv` writes them.
fn fields(row: &Row) -> Vec<String> {
    let mut w = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    if w.serialize(row).is_err() {
        return Vec::new();
    }
    let bytes = w.into_inner().unwrap_or_default();
    let mut r = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(&bytes[..]);
    r.records()
        .next()
        .and_then(|rec| rec.ok())
        .map(|rec| rec.iter().map(str::to_string).collect())
        .unwrap_or_default()
}
