//! The benchmark runner: expands a config into instances, runs every exact objective and
//! algorithm on each in parallel (rayon, one solver thread per job), and appends rows to
//! `results.csv` as instances finish.
//!
//! A job is one instance: its exact solves run first so that the algorithm rows of the same
//! instance can divide by the proven optimum. Rows are flushed per instance, so a killed run
//! loses only the instances in flight; `--resume` skips rows already written. A panic or error
//! inside an algorithm or solver becomes a row with `error` filled in, and the run goes on.

use super::config::{Config, ExactSpec, InstanceSpec, Source};
use super::rows::{EXACT, Row, RowWriter, read_rows, write_sorted};
use crate::algorithms::{self, Algorithm, Objective, Options};
use crate::checker;
use crate::error::{Error, Result};
use crate::exact::{self, ExactOptions};
use crate::instance::Instance;
use crate::region::Region;
use crate::{bounds, topology};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

/// How to run a suite.
#[derive(Clone, Debug)]
pub struct RunOptions {
    pub out: PathBuf,
    /// Parallel jobs; `None` = all cores.
    pub jobs: Option<usize>,
    /// Skip rows already in `out/results.csv`.
    pub resume: bool,
    /// Run only slice `i` of `n` (0-based) of the instance list.
    pub shard: Option<(usize, usize)>,
    pub run_id: String,
    pub command_line: String,
}

/// What a run did.
#[derive(Clone, Debug)]
pub struct RunSummary {
    pub instances: usize,
    pub rows_written: usize,
    pub errors: usize,
}

/// The instances of shard `i` of `n`: every n-th instance starting at i, so that each shard
/// gets a mix of families and sizes.
pub fn shard_of(instances: Vec<InstanceSpec>, shard: Option<(usize, usize)>) -> Vec<InstanceSpec> {
    match shard {
        None => instances,
        Some((i, n)) => instances
            .into_iter()
            .enumerate()
            .filter(|(k, _)| k % n == i)
            .map(|(_, s)| s)
            .collect(),
    }
}

/// Runs a suite into `opts.out`: `results.csv` (appended as instances finish, sorted at the
/// end), `instances/`, then `stats.csv`, plots and `manifest.json`.
pub fn run(config: &Config, opts: &RunOptions) -> Result<RunSummary> {
    let instances = shard_of(config.instances()?, opts.shard);
    let out = &opts.out;
    std::fs::create_dir_all(out.join("instances")).map_err(|e| Error::io(out, e))?;
    let results = out.join("results.csv");
    let existing: Vec<Row> = if opts.resume && results.exists() {
        super::rows::truncate_partial_line(&results)?;
        read_rows(&results)?
    } else {
        Vec::new()
    };
    if !opts.resume && results.exists() {
        return Err(Error::invalid(format!(
            "{} already exists: pass --resume to continue that run, or choose another --out",
            results.display()
        )));
    }
    let done: HashMap<(String, String, String), Row> =
        existing.into_iter().map(|r| (r.key(), r)).collect();
    let started = super::manifest::now();
    super::manifest::write(out, config, opts, &started, None)?;

    let writer = Mutex::new(RowWriter::open(&results)?);
    let progress = super::progress::bar(instances.len() as u64);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(opts.jobs.unwrap_or(0))
        .build()
        .map_err(|e| Error::invalid(e.to_string()))?;
    let counts = Mutex::new((0usize, 0usize));
    let failure: Mutex<Option<Error>> = Mutex::new(None);
    pool.install(|| {
        instances.par_iter().for_each(|spec| {
            let rows = run_instance(spec, config, opts, &done);
            let errors = rows.iter().filter(|r| !r.error.is_empty()).count();
            if !rows.is_empty() {
                let mut w = writer.lock().expect("writer lock");
                if let Err(e) = w.append(&rows) {
                    failure.lock().expect("failure lock").get_or_insert(e);
                }
            }
            let mut c = counts.lock().expect("count lock");
            c.0 += rows.len();
            c.1 += errors;
            progress.inc(1);
        });
    });
    progress.finish_and_clear();
    if let Some(e) = failure.into_inner().expect("failure lock") {
        return Err(e);
    }
    let (rows_written, errors) = counts.into_inner().expect("count lock");
    finish(out)?;
    super::manifest::write(out, config, opts, &started, Some(&super::manifest::now()))?;
    Ok(RunSummary {
        instances: instances.len(),
        rows_written,
        errors,
    })
}

/// Sorts `results.csv` into canonical order and derives `stats.csv` and the plots from it.
pub fn finish(out: &Path) -> Result<()> {
    let results = out.join("results.csv");
    let mut rows = read_rows(&results)?;
    write_sorted(&results, &mut rows)?;
    super::stats::write(&out.join("stats.csv"), &super::stats::compute(&rows))?;
    super::plots::draw_all(out, &rows)
}

/// Runs every exact objective and algorithm of one instance; never fails: problems become
/// error rows.
fn run_instance(
    spec: &InstanceSpec,
    config: &Config,
    opts: &RunOptions,
    done: &HashMap<(String, String, String), Row>,
) -> Vec<Row> {
    let base = Row {
        run_id: opts.run_id.clone(),
        instance: spec.name.clone(),
        family: spec.family.clone(),
        params: spec.params.clone(),
        seed: spec.seed,
        ..Row::default()
    };
    let region = match materialize(spec, &opts.out) {
        Ok((region, sha)) => {
            let mut b = base.clone();
            b.sha256 = sha;
            b.n = region.len() as u64;
            b.holes = topology::holes(&region).count as u64;
            return run_on_region(&region, b, spec, config, done);
        }
        Err(e) => e,
    };
    let key = (spec.name.clone(), "instance".to_string(), "-".to_string());
    if done.contains_key(&key) {
        return Vec::new();
    }
    vec![Row {
        algorithm: "instance".into(),
        objective: "-".into(),
        error: region.to_string(),
        ..base
    }]
}

/// Generates or reads the instance, saves it under `out/instances/` and returns it with the
/// sha256 of the saved bytes.
fn materialize(spec: &InstanceSpec, out: &Path) -> Result<(Region, String)> {
    let (bytes, ext, region) = match &spec.source {
        Source::Generate(params) => {
            let file = crate::generate::generate(params)?;
            let text = file.to_text()?;
            (text.into_bytes(), "grid", file.region)
        }
        Source::File(path) => {
            let inst = Instance::read(path)?;
            let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
            let ext = if path.extension().is_some_and(|e| e == "wkt") {
                "wkt"
            } else {
                "grid"
            };
            (bytes, ext, inst.region)
        }
    };
    let path = out.join("instances").join(format!("{}.{ext}", spec.name));
    std::fs::write(&path, &bytes).map_err(|e| Error::io(&path, e))?;
    Ok((region, sha256_hex(&bytes)))
}

pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::{Digest, Sha256};
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The name of an exact objective in the `objective` column.
pub fn exact_objective_name(e: &ExactSpec) -> String {
    match e.turn_cost {
        Some(c) => format!("{}-c{c}", e.objective),
        None => e.objective.clone(),
    }
}

/// The exact objective whose optimum is the optimum of an algorithm's objective. Lawn mowing
/// has none: the exact `lawn-tsp` through the pixel centres is the αTSP = 1 reference of
/// Theorem 2, not the optimal lawn-mowing tour (which may be shorter), so dividing a guarantee
/// against OPT by it would be unsound; its rows stand on their own.
pub fn exact_for(objective: Objective) -> Option<&'static str> {
    match objective {
        Objective::Length => Some("length"),
        Objective::CcTurns => Some("cc-turns"),
        Objective::Turns => Some("tour-turns"),
        Objective::LawnLength => None,
    }
}

/// The area lower bound on a lawn-mowing tour with the unit square cutter and rectilinear
/// motion (milling paper, Section 4): a tour of length L sweeps area at most L·w + a with
/// sweep width w = 1 and cutter area a = 1, so L ≥ N − 1.
fn lawn_area_lower_bound(region: &Region) -> u64 {
    (region.len() as u64).saturating_sub(1)
}

fn run_on_region(
    region: &Region,
    base: Row,
    spec: &InstanceSpec,
    config: &Config,
    done: &HashMap<(String, String, String), Row>,
) -> Vec<Row> {
    let mut rows = Vec::new();
    // Exact rows first (or their earlier results when resuming): the algorithms divide by them.
    let mut exact_rows: HashMap<String, Row> = HashMap::new();
    for e in &config.exact {
        if region.len() > e.max_n {
            continue;
        }
        let name = exact_objective_name(e);
        let key = (spec.name.clone(), EXACT.to_string(), name.clone());
        if let Some(r) = done.get(&key) {
            exact_rows.insert(name, r.clone());
            continue;
        }
        let row = exact_row(region, &base, e, &name);
        exact_rows.insert(name, row.clone());
        rows.push(row);
    }
    let algos: Vec<&'static Algorithm> = match &spec.algorithms {
        Some(names) => names.iter().filter_map(|n| algorithms::find(n)).collect(),
        None => algorithms::REGISTRY
            .iter()
            .filter(|a| (a.precondition)(region).is_ok())
            .collect(),
    };
    for algo in algos {
        let pending: Vec<Objective> = algo
            .objectives
            .iter()
            .copied()
            .filter(|o| {
                !done.contains_key(&(
                    spec.name.clone(),
                    algo.name.to_string(),
                    o.name().to_string(),
                ))
            })
            .collect();
        if pending.is_empty() {
            continue;
        }
        rows.extend(algorithm_rows(region, &base, algo, &pending, &exact_rows));
    }
    rows
}

/// Runs `f`, turning a panic into an error message.
fn guarded<T>(f: impl FnOnce() -> Result<T>) -> std::result::Result<T, String> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(x)) => Ok(x),
        Ok(Err(e)) => Err(e.to_string()),
        Err(panic) => Err(format!(
            "panic: {}",
            panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown".into())
        )),
    }
}

fn exact_row(region: &Region, base: &Row, e: &ExactSpec, name: &str) -> Row {
    let mut row = Row {
        algorithm: EXACT.into(),
        objective: name.to_string(),
        ..base.clone()
    };
    let start = Instant::now();
    let outcome = guarded(|| {
        let objective =
            exact::Objective::parse(&e.objective, e.turn_cost).map_err(Error::invalid)?;
        let options = ExactOptions {
            time_limit: Some(e.time_limit),
            threads: 1,
            ..ExactOptions::default()
        };
        Ok(exact::solve(region, objective, &options))
    });
    row.seconds = start.elapsed().as_secs_f64();
    match outcome {
        Err(msg) => row.error = msg,
        Ok(res) => {
            row.value = res.value;
            row.length = res.length;
            row.turns = res.turns;
            row.cycles = res.cycles.map(|c| c as u64);
            row.opt_status = res.status.to_string();
            row.lower_bound = Some(res.lower_bound);
            row.lb_source = "exact".into();
            // No cover (infeasible, or no incumbent by the time limit) is not an invalid cover.
            row.valid = res.cover.as_ref().map(|_| res.valid);
            if res.status == exact::Status::Optimal {
                row.opt = res.value;
            }
            if let Some(cover) = &res.cover {
                row.max_coverage = Some(u64::from(
                    checker::check(region, cover, checker::Mode::Milling).max_coverage,
                ));
            }
            if let Some(m) = res.message.filter(|_| res.status == exact::Status::Error) {
                row.error = m;
            }
        }
    }
    row.compute_ratios();
    row
}

/// The best known lower bound for an algorithm objective, and its source.
fn lower_bound(
    region: &Region,
    objective: Objective,
    exact_rows: &HashMap<String, Row>,
) -> (Option<u64>, String) {
    let mut candidates: Vec<(u64, String)> = Vec::new();
    match objective {
        Objective::Length => {
            let b = bounds::length_lower_bound(region);
            candidates.push((b.value, b.source.to_string()));
        }
        Objective::Turns | Objective::CcTurns => {
            let b = bounds::turn_lower_bound(region);
            candidates.push((b.value, b.source.to_string()));
        }
        Objective::LawnLength => {
            candidates.push((
                lawn_area_lower_bound(region),
                "area: N <= L*w + a".to_string(),
            ));
        }
    }
    let exact_names: &[&str] = match objective {
        Objective::Length => &["length"],
        Objective::CcTurns => &["cc-turns"],
        // A tour is a cycle cover, so cycle-cover bounds bound tours too.
        Objective::Turns => &["tour-turns", "cc-turns"],
        Objective::LawnLength => &[],
    };
    for name in exact_names {
        if let Some(lb) = exact_rows.get(*name).and_then(|r| r.lower_bound) {
            let src = if exact_rows[*name].opt.is_some() {
                format!("opt:{name}")
            } else {
                format!("exact-bound:{name}")
            };
            candidates.push((lb, src));
        }
    }
    // The largest bound wins; ties keep the first (cheapest) source.
    let best = candidates
        .into_iter()
        .fold(None::<(u64, String)>, |acc, c| match acc {
            Some(a) if a.0 >= c.0 => Some(a),
            _ => Some(c),
        });
    match best {
        Some((b, s)) => (Some(b), s),
        None => (None, String::new()),
    }
}

fn algorithm_rows(
    region: &Region,
    base: &Row,
    algo: &Algorithm,
    objectives: &[Objective],
    exact_rows: &HashMap<String, Row>,
) -> Vec<Row> {
    let start = Instant::now();
    let outcome = guarded(|| {
        (algo.precondition)(region)?;
        (algo.run)(region, &Options::default())
    });
    let seconds = start.elapsed().as_secs_f64();
    let row_for = |objective: Objective| Row {
        algorithm: algo.name.into(),
        objective: objective.name().into(),
        guarantee: algo
            .guarantees
            .iter()
            .filter(|g| g.objective == objective && g.when.applies(region))
            .map(|g| g.to_string())
            .collect::<Vec<_>>()
            .join("; "),
        seconds,
        ..base.clone()
    };
    let solution = match outcome {
        Ok(s) => s,
        Err(msg) => {
            return objectives
                .iter()
                .map(|&o| Row {
                    error: msg.clone(),
                    ..row_for(o)
                })
                .collect();
        }
    };
    objectives
        .iter()
        .map(|&objective| {
            let mut row = row_for(objective);
            let Some(output) = solution.outputs.iter().find(|o| o.objective == objective) else {
                row.error = format!("{} returned no {} output", algo.name, objective);
                return row;
            };
            let report = checker::check(region, &output.cover, objective.mode());
            let is_tour_ok = !objective.is_tour() || output.cover.is_tour();
            row.valid = Some(report.valid && is_tour_ok);
            if !report.valid {
                row.error = report.error.clone().unwrap_or_default();
            } else if !is_tour_ok {
                row.error = format!("a tour objective got {} cycles", output.cover.cycles.len());
            }
            row.length = Some(report.length);
            row.turns = Some(report.turns);
            row.cycles = Some(report.cycles as u64);
            row.max_coverage = Some(u64::from(report.max_coverage));
            let value = match objective {
                Objective::Length | Objective::LawnLength => report.length,
                Objective::Turns | Objective::CcTurns => report.turns,
            };
            row.value = Some(value);
            if let Some(ex) = exact_for(objective).and_then(|name| exact_rows.get(name)) {
                row.opt = ex.opt;
                row.opt_status = ex.opt_status.clone();
            }
            let (lb, src) = lower_bound(region, objective, exact_rows);
            row.lower_bound = lb;
            row.lb_source = src;
            let measured = algorithms::Measured {
                value,
                length: report.length,
                max_coverage: u64::from(report.max_coverage),
            };
            row.within_guarantee =
                within_guarantee(algo, objective, &measured, region, row.opt, lb);
            row.compute_ratios();
            row
        })
        .collect()
}

/// `Some(true)` when every guarantee of the objective is shown to hold, `Some(false)` when one
/// is violated, `None` when it cannot be decided (a guarantee against OPT, OPT unknown, and the
/// lower bound too weak to show it).
pub fn within_guarantee(
    algo: &Algorithm,
    objective: Objective,
    measured: &algorithms::Measured,
    region: &Region,
    opt: Option<u64>,
    lb: Option<u64>,
) -> Option<bool> {
    let n = region.len() as u64;
    let mut all = Some(true);
    let applicable: Vec<_> = algo
        .guarantees
        .iter()
        .filter(|g| g.objective == objective && g.when.applies(region))
        .collect();
    for g in &applicable {
        match g.decide(measured, n, opt, lb) {
            Some(false) => return Some(false),
            None => all = None,
            Some(true) => {}
        }
    }
    if applicable.is_empty() { None } else { all }
}
