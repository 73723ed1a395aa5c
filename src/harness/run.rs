//! The benchmark runner: expands a config into instances, runs every exact objective and
//! algorithm on each in parallel (rayon, one solver thread per job), and appends rows to
//! `results.csv` as instances finish.
//!
//! A job is one instance: its exact solves run first so that the algorithm rows of the same
//! instance can divide by the proven optimum. Rows are flushed per instance, so a killed run
//! loses only the instances in flight; `--resume` skips rows already written. A panic or error
//! inside an algorithm or solver becomes a row with `error` filled in, and the run goes on.

use super::config::{Config, ExactSpec, InstanceSpec, Source};
use super::manifest::{ConfigRecord, Finished, Recorded};
use super::rows::{EXACT, Row, RowWriter, read_rows, write_sorted};
use super::walks::Kept;
use crate::algorithms::{self, Model, Objective};
use crate::discrete::Discrete;
use crate::error::{Error, Result};
use crate::evaluate::{self, Evaluation, Known, Reference, Subject};
use crate::exact;
use crate::instance::Instance;
use crate::model::{InstanceModel, Kind};
use crate::outside::OutsideAlgorithm;
use crate::region::Region;
use crate::topology;
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
/// end), `instances/`, then `stats.csv`, plots and `manifest.json`. The config is recorded by
/// its JSON encoding; [`run_recorded`] records the TOML text it was given.
pub fn run(config: &Config, opts: &RunOptions) -> Result<RunSummary> {
    run_recorded(config, &ConfigRecord::of_config(config), opts)
}

/// The most parallel jobs a run accepts: 16 per core this process may use (each job is a
/// thread with its own solver, so more only costs memory and switching).
pub fn max_jobs() -> usize {
    16 * std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// Checks a `--jobs` value: at least 1 (leave `--jobs` out for all cores) and at most
/// [`max_jobs`].
pub fn check_jobs(jobs: usize) -> std::result::Result<usize, String> {
    let max = max_jobs();
    if jobs == 0 {
        return Err("--jobs 0: expected at least 1 (omit --jobs to use all cores)".into());
    }
    if jobs > max {
        return Err(format!(
            "--jobs {jobs}: expected at most {max} (16 per available core)"
        ));
    }
    Ok(jobs)
}

/// [`run`] with the config as given (`record`), which the manifest stores so that a resumed
/// run continues with exactly this config and merge can tell shards of different configs
/// apart. The output directory is locked for the duration of the run (see [`super::lock`]).
pub fn run_recorded(
    config: &Config,
    record: &ConfigRecord,
    opts: &RunOptions,
) -> Result<RunSummary> {
    if let Some(jobs) = opts.jobs {
        check_jobs(jobs).map_err(Error::invalid)?;
    }
    let instances = shard_of(config.instances()?, opts.shard);
    let files = file_digests(&instances)?;
    let out = &opts.out;
    std::fs::create_dir_all(out.join("instances")).map_err(|e| Error::io(out, e))?;
    let _lock = super::lock::acquire(out)?;
    let results = out.join("results.csv");
    if !opts.resume && results.exists() {
        return Err(Error::invalid(format!(
            "{} already exists: pass --resume to continue that run, or choose another --out",
            results.display()
        )));
    }
    if opts.resume {
        check_same_run(out, config, record, opts, &files)?;
    }
    let existing: Vec<Row> = if opts.resume && results.exists() {
        super::rows::truncate_partial_line(&results)?;
        upgrade_header(&results)?;
        let rows = read_rows(&results)?;
        check_same_files(out, &instances, &rows)?;
        drop_machine_errors(&results, rows)?
    } else {
        Vec::new()
    };
    let done: HashMap<(String, String, String), Row> =
        existing.into_iter().map(|r| (r.key(), r)).collect();
    let started = super::manifest::now();
    super::manifest::write(out, config, record, opts, &started, None, &files)?;

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
            let Produced { mut rows, walks } = run_instance(spec, config, opts, &done);
            // A row below its own proven bound, or whose value is not its own count, is an
            // invalid result (never an improvement): the check `claims` and `gate` share.
            for r in &mut rows {
                r.mark_inconsistent();
            }
            let errors = rows.iter().filter(|r| !r.error.is_empty()).count();
            // The walks before their rows: a row in results.csv that needs its walk has it (a
            // run killed in between leaves walks whose rows the resume writes again).
            let kept = super::walks::write(out, &spec.name, &walks);
            if let Err(e) = kept {
                failure.lock().expect("failure lock").get_or_insert(e);
            } else if !rows.is_empty() {
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
    let rows = finish(out)?;
    let finished = Finished {
        end: &super::manifest::now(),
        instances: instances.len(),
        rows,
    };
    super::manifest::write(out, config, record, opts, &started, Some(finished), &files)?;
    Ok(RunSummary {
        instances: instances.len(),
        rows_written,
        errors,
    })
}

/// Sorts `results.csv` into canonical order and derives `stats.csv` and the plots from it;
/// returns the number of rows.
pub fn finish(out: &Path) -> Result<usize> {
    let results = out.join("results.csv");
    let mut rows = read_rows(&results)?;
    // Resumed or merged rows were written elsewhere: the same check as fresh rows.
    for r in &mut rows {
        r.mark_inconsistent();
    }
    write_sorted(&results, &mut rows)?;
    super::stats::write(&out.join("stats.csv"), &super::stats::compute(&rows))?;
    super::plots::draw_all(out, &rows)?;
    Ok(rows.len())
}

/// The sha256 of every `[[files]]` instance among `instances`, by instance name (pinned in the
/// manifest). A file that cannot be read is left out: its instance becomes an error row.
fn file_digests(instances: &[InstanceSpec]) -> Result<std::collections::BTreeMap<String, String>> {
    let mut files = std::collections::BTreeMap::new();
    for spec in instances {
        if let Source::File(path) = &spec.source
            && let Ok(bytes) = crate::input::read_bytes(path, "an instance file")
        {
            files.insert(spec.name.clone(), sha256_hex(&bytes));
        }
    }
    Ok(files)
}

/// Refuses to resume a run whose `[[files]]` instances changed since the rows were written: a
/// row whose `sha256` differs from its file's today (an edited file). The manifest's pins
/// ([`check_same_run`]) also catch added and removed files; this catches edits in runs
/// recorded before the pins.
fn check_same_files(out: &Path, instances: &[InstanceSpec], rows: &[Row]) -> Result<()> {
    let files: HashMap<&str, &Path> = instances
        .iter()
        .filter_map(|s| match &s.source {
            Source::File(p) => Some((s.name.as_str(), p.as_path())),
            _ => None,
        })
        .collect();
    let mut changed = std::collections::BTreeSet::new();
    let mut digests: HashMap<&str, Option<String>> = HashMap::new();
    for r in rows.iter().filter(|r| !r.sha256.is_empty()) {
        let Some(path) = files.get(r.instance.as_str()) else {
            continue;
        };
        let now = digests.entry(r.instance.as_str()).or_insert_with(|| {
            crate::input::read_bytes(path, "an instance file")
                .ok()
                .map(|b| sha256_hex(&b))
        });
        if now.as_deref().is_some_and(|sha| sha != r.sha256) {
            changed.insert(format!("{} (edited: {})", r.instance, path.display()));
        }
    }
    if changed.is_empty() {
        return Ok(());
    }
    Err(Error::invalid(format!(
        "cannot resume {}: [[files]] instances changed since their rows were written: {}; \
         their rows would sit beside rows of other instances: start a new run with another --out",
        out.display(),
        changed.into_iter().collect::<Vec<_>>().join(", ")
    )))
}

/// Drops from `results.csv` the rows whose error the machine caused ([`machine_caused`]: a
/// full disk, a kill, memory), rewriting it without them, so that the resume runs them again;
/// returns the rows kept.
fn drop_machine_errors(results: &Path, rows: Vec<Row>) -> Result<Vec<Row>> {
    let (mut kept, retried): (Vec<Row>, Vec<Row>) = rows
        .into_iter()
        .partition(|r| r.error.is_empty() || !super::rows::machine_caused(&r.error));
    if retried.is_empty() {
        return Ok(kept);
    }
    write_sorted(results, &mut kept)?;
    eprintln!(
        "mowmill: {} row(s) of {} failed because of the machine (I/O error, signal, memory), \
         not the instance: running them again",
        retried.len(),
        results.display()
    );
    Ok(kept)
}

/// Refuses to resume `out` with another config or another shard than the run recorded in
/// `out/manifest.json` (a directory without a manifest has nothing to compare), or when the
/// `[[files]]` instances pinned there changed (edited, added or removed).
fn check_same_run(
    out: &Path,
    config: &Config,
    record: &ConfigRecord,
    opts: &RunOptions,
    files: &std::collections::BTreeMap<String, String>,
) -> Result<()> {
    let Some(recorded) = Recorded::read_if_exists(out)? else {
        return Ok(());
    };
    if let Some(pinned) = recorded.json["files_sha256"].as_object() {
        let mut changes = Vec::new();
        for (name, sha) in files {
            match pinned.get(name).and_then(|v| v.as_str()) {
                None => changes.push(format!("added {name}")),
                Some(old) if old != sha => changes.push(format!("edited {name}")),
                Some(_) => {}
            }
        }
        for name in pinned.keys().filter(|n| !files.contains_key(*n)) {
            changes.push(format!("removed {name}"));
        }
        if !changes.is_empty() {
            return Err(Error::invalid(format!(
                "cannot resume {}: the [[files]] instances changed since {} pinned their sha256: \
                 {}; the old rows would sit beside the new instances: start a new run with \
                 another --out",
                out.display(),
                recorded.path.display(),
                changes.join(", ")
            )));
        }
    }
    let same_config = match recorded.sha256() {
        Some(sha) => sha == record.sha256,
        // Manifests from before the digest: compare the resolved configs.
        None => serde_json::to_value(config).ok().as_ref() == Some(&recorded.json["config"]),
    };
    if !same_config {
        return Err(Error::invalid(format!(
            "cannot resume {}: its manifest records config {} (sha256 {}), this run has \
             config {} (sha256 {}); resume without --config to continue with the recorded \
             one, or choose another --out",
            out.display(),
            recorded.config_file(),
            recorded.sha256().unwrap_or("not recorded"),
            record.file,
            record.sha256
        )));
    }
    let shard = recorded.shard()?;
    if shard != opts.shard {
        let show =
            |s: Option<(usize, usize)>| s.map_or("none".to_string(), |(i, n)| format!("{i}/{n}"));
        return Err(Error::invalid(format!(
            "cannot resume {}: its manifest records shard {}, this run asks for shard {} \
             (--shard or SLURM_ARRAY_TASK_*); resume a shard with its own shard",
            out.display(),
            show(shard),
            show(opts.shard)
        )));
    }
    Ok(())
}

/// A `results.csv` written by an older mowmill (without the option columns `merge`, `cutter`,
/// `coverage4` appended after `error`, or without the model columns `model`, `d`, `delta`,
/// `mu`, `rho`, `edges`, `direction_sum` appended after `coverage4`, without `unit`
/// appended after `direction_sum`, or without `theorems` appended after `unit`) is rewritten in the
/// current header before rows are appended to it, so that no row lands under the wrong column;
/// the old rows get empty columns (an old run did not record them). Any other header is
/// refused.
fn upgrade_header(results: &Path) -> Result<()> {
    let text = crate::input::read_text(results, "a results.csv")?;
    let header = text.lines().next().unwrap_or_default();
    let current = super::rows::header()?;
    if header.is_empty() || header == current {
        return Ok(());
    }
    let columns: Vec<&str> = current.split(',').collect();
    let given: Vec<&str> = header.split(',').collect();
    // Only a prefix of today's columns ending at `error` (before the option columns), at
    // `coverage4` (before the model columns), at `direction_sum` (before `unit`) or at `unit`
    // (before `theorems`) is a known older layout. Its rows keep no theorem ids: the claims
    // table refuses them (`claims::Sources::read_rows`), the run's own rows are counted anew.
    let known_old = given.len() < columns.len()
        && given[..] == columns[..given.len()]
        && matches!(
            given.last(),
            Some(&"error") | Some(&"coverage4") | Some(&"direction_sum") | Some(&"unit")
        );
    if !known_old {
        return Err(Error::parse(
            &results.display().to_string(),
            1,
            1,
            format!("expected the results.csv header {current:?}, got {header:?}"),
        ));
    }
    let mut rows = read_rows(results)?;
    write_sorted(results, &mut rows)?;
    eprintln!(
        "mowmill: {} had the header of an older mowmill: rewritten with the columns {}",
        results.display(),
        columns[given.len()..].join(", ")
    );
    Ok(())
}

/// The rows of one instance and the checked walks of those the claims table could find
/// violated ([`super::walks::claims_may_violate`]), which the run keeps in `walks/`.
pub(crate) struct Produced {
    pub rows: Vec<Row>,
    pub walks: Vec<Kept>,
}

impl Produced {
    fn rows(rows: Vec<Row>) -> Produced {
        Produced {
            rows,
            walks: Vec::new(),
        }
    }
}

/// Runs every exact objective and algorithm of one instance; never fails: problems become
/// error rows.
fn run_instance(
    spec: &InstanceSpec,
    config: &Config,
    opts: &RunOptions,
    done: &HashMap<(String, String, String), Row>,
) -> Produced {
    let mut produced = run_instance_unmarked(spec, config, opts, done);
    for r in &mut produced.rows {
        if !r.error.is_empty()
            && !r.error.starts_with(super::rows::MACHINE_ERROR)
            && super::rows::machine_caused(&r.error)
        {
            r.error = format!("{}{}", super::rows::MACHINE_ERROR, r.error);
        }
    }
    produced
}

/// [`run_instance`] before errors the machine caused are marked.
fn run_instance_unmarked(
    spec: &InstanceSpec,
    config: &Config,
    opts: &RunOptions,
    done: &HashMap<(String, String, String), Row>,
) -> Produced {
    let base = Row {
        run_id: opts.run_id.clone(),
        instance: spec.name.clone(),
        family: spec.family.clone(),
        params: spec.params.clone(),
        seed: spec.seed,
        ..Row::default()
    };
    let error = match materialize(spec, &opts.out) {
        Ok((loaded, sha)) => return run_loaded(&loaded, sha, base, spec, config, done),
        Err(e) => e,
    };
    let key = (spec.name.clone(), "instance".to_string(), "-".to_string());
    if done.contains_key(&key) {
        return Produced::rows(Vec::new());
    }
    Produced::rows(vec![Row {
        algorithm: "instance".into(),
        objective: "-".into(),
        error: error.to_string(),
        ..base
    }])
}

/// The rows of one loaded instance (`sha` the sha256 of its file, `base` the row's instance
/// columns): the config's exact objectives, then the algorithms of its model. Bench calls it
/// on every instance it generates or reads; `mowmill sample --check` on the committed copies
/// of sampled instances ([`super::sample`]), so that both go through the same code.
pub(crate) fn run_loaded(
    loaded: &Loaded,
    sha: String,
    base: Row,
    spec: &InstanceSpec,
    config: &Config,
    done: &HashMap<(String, String, String), Row>,
) -> Produced {
    match loaded {
        Loaded::Grid(region) => {
            let mut b = base;
            b.sha256 = sha;
            b.n = region.len() as u64;
            b.holes = topology::holes(region).count as u64;
            b.set_params("grid", &Model::Grid(region).params());
            run_on(region, b, spec, config, done)
        }
        Loaded::Discrete(inst) => {
            let mut b = base;
            b.sha256 = sha;
            b.n = inst.len() as u64;
            b.set_params("discrete", &inst.params());
            run_on(inst, b, spec, config, done)
        }
        Loaded::Ortho(polygon) => {
            let mut b = base;
            b.sha256 = sha;
            b.n = Model::Ortho(polygon).len() as u64;
            b.holes = polygon.rings().iter().filter(|r| r.hole).count() as u64;
            b.model = "ortho".to_string();
            run_on(polygon, b, spec, config, done)
        }
    }
}

/// An instance of one of the models, as read or generated.
pub(crate) enum Loaded {
    Grid(Region),
    Discrete(Discrete),
    Ortho(crate::ortho::Polygon),
}

/// Generates or reads the instance, saves it under `out/instances/` and returns it with the
/// sha256 of the saved bytes.
fn materialize(spec: &InstanceSpec, out: &Path) -> Result<(Loaded, String)> {
    let (bytes, ext, loaded) = load(spec)?;
    let path = out.join("instances").join(format!("{}.{ext}", spec.name));
    std::fs::write(&path, &bytes).map_err(|e| Error::io(&path, e))?;
    Ok((loaded, sha256_hex(&bytes)))
}

/// Generates or reads the instance: its file's bytes, the file's extension and the instance.
fn load(spec: &InstanceSpec) -> Result<(Vec<u8>, &'static str, Loaded)> {
    Ok(match &spec.source {
        Source::Generate(params) => {
            let file = crate::generate::generate(params)?;
            let text = file.to_text()?;
            (text.into_bytes(), "grid", Loaded::Grid(file.region))
        }
        Source::Discrete {
            family,
            n,
            holes,
            k,
        } => {
            let g = crate::discrete::generate::generate(family, *n, *holes, *k, spec.seed)?;
            (g.text.into_bytes(), g.ext, Loaded::Discrete(g.instance))
        }
        Source::Ortho { family, n } => {
            let polygon = crate::ortho::generate(family, *n, spec.seed)?;
            (
                format!("{}\n", polygon.to_wkt()).into_bytes(),
                "wkt",
                Loaded::Ortho(polygon),
            )
        }
        Source::File(path) if Kind::of(path) == Kind::Ortho => {
            let polygon = crate::ortho::Polygon::read(path)?;
            let bytes = crate::input::read_bytes(path, "an instance file")?;
            (bytes, "wkt", Loaded::Ortho(polygon))
        }
        Source::File(path) if Kind::of(path) == Kind::Discrete => {
            let inst = crate::discrete::generate::read(path)?;
            let bytes = crate::input::read_bytes(path, "an instance file")?;
            let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("dm");
            let ext = crate::discrete::generate::EXTENSIONS
                .iter()
                .find(|x| x.eq_ignore_ascii_case(ext))
                .copied()
                .unwrap_or("dm");
            (bytes, ext, Loaded::Discrete(inst))
        }
        Source::File(path) => {
            let inst = Instance::read(path)?;
            let bytes = crate::input::read_bytes(path, "an instance file")?;
            let ext = if path.extension().is_some_and(|e| e == "wkt") {
                "wkt"
            } else {
                "grid"
            };
            (bytes, ext, Loaded::Grid(inst.region))
        }
    })
}

/// The rows a run of `config` writes for instance `spec`, as (algorithm, objective) keys, and
/// the sha256 of its file (`None` when it cannot be generated or read: then its one row is the
/// `instance` error row). `merge` checks shards against it; it follows [`run_on`] key by key.
pub(crate) fn expected_keys(
    spec: &InstanceSpec,
    config: &Config,
) -> (Option<String>, std::collections::BTreeSet<(String, String)>) {
    let (bytes, loaded) = match load(spec) {
        Ok((bytes, _, loaded)) => (bytes, loaded),
        Err(_) => {
            let mut keys = std::collections::BTreeSet::new();
            keys.insert(("instance".to_string(), "-".to_string()));
            return (None, keys);
        }
    };
    let keys = match &loaded {
        Loaded::Grid(region) => keys_on(region, spec, config),
        Loaded::Discrete(inst) => keys_on(inst, spec, config),
        Loaded::Ortho(polygon) => keys_on(polygon, spec, config),
    };
    (Some(sha256_hex(&bytes)), keys)
}

/// The (algorithm, objective) keys [`run_on`] writes for `instance` of `spec`.
fn keys_on<M: InstanceModel>(
    instance: &M,
    spec: &InstanceSpec,
    config: &Config,
) -> std::collections::BTreeSet<(String, String)> {
    let mut keys = std::collections::BTreeSet::new();
    for e in config.exact.iter().filter(|e| exact_applies(instance, e)) {
        keys.insert((EXACT.to_string(), exact_objective_name(e)));
    }
    let outside = if M::TAKES_OUTSIDE {
        config.outside_algorithms()
    } else {
        Vec::new()
    };
    for planned in plan(instance, spec, config, &outside) {
        match planned {
            Planned::Refused { name, .. } => {
                keys.insert((name, "-".to_string()));
            }
            Planned::Variant {
                name, objectives, ..
            } => {
                for o in objectives {
                    keys.insert((name.clone(), o.to_string()));
                }
            }
        }
    }
    keys
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
    let name = crate::algorithms::canonical_objective(&e.objective);
    match e.turn_cost {
        Some(c) => format!("{name}-c{c}"),
        None => name.to_string(),
    }
}

/// One algorithm variant the runner evaluates on an instance, or a name it refuses.
enum Planned<'a> {
    /// An algorithm a family names that has no run on the instance's model: one error row.
    Refused { name: String, error: String },
    /// `subject` with `options`, under its variant `name`, for `objectives`.
    Variant {
        subject: Subject<'a>,
        name: String,
        options: algorithms::Options,
        objectives: Vec<Objective>,
    },
}

/// What the runner evaluates on `instance` of `spec`: the registered algorithms the family
/// names (or by default those that run on the instance), then, where the model takes them, the
/// config's `outside` algorithms; each once per distinct variant of the config's option sets
/// (where the model takes options), for its own objectives and the weighted ones of the
/// config's `[[exact]]` tables it reports (where the model measures them, on instances of any
/// size: their rows then divide by the cheap bound). [`run_on`] and [`expected_keys`] both
/// follow this plan.
fn plan<'a, M: InstanceModel>(
    instance: &M,
    spec: &InstanceSpec,
    config: &Config,
    outside: &'a [OutsideAlgorithm],
) -> Vec<Planned<'a>> {
    let weighted: Vec<Objective> = if M::MEASURES_WEIGHTED {
        config
            .exact
            .iter()
            .filter_map(|e| exact_objective_name(e).parse::<Objective>().ok())
            .filter(|o| o.turn_cost().is_some())
            .collect()
    } else {
        Vec::new()
    };
    let mut subjects: Vec<std::result::Result<Subject<'a>, (String, String)>> =
        match &spec.algorithms {
            Some(names) => names
                .iter()
                .filter_map(|n| match algorithms::find(n).filter(|a| M::has_run(a)) {
                    Some(a) => Some(Ok(Subject::Registered(a))),
                    None => M::not_run(n).map(|error| Err((n.clone(), error))),
                })
                .collect(),
            None => algorithms::REGISTRY
                .iter()
                .filter(|a| instance.runs_by_default(a))
                .map(|a| Ok(Subject::Registered(a)))
                .collect(),
        };
    if M::TAKES_OUTSIDE {
        subjects.extend(
            outside
                .iter()
                .filter(|o| {
                    spec.algorithms
                        .as_ref()
                        .is_none_or(|names| names.contains(&o.name))
                })
                .map(|o| Ok(Subject::Outside(o))),
        );
    }
    let option_sets = if M::TAKES_OPTIONS {
        config.option_sets()
    } else {
        vec![algorithms::Options::default()]
    };
    let mut planned = Vec::new();
    for subject in subjects {
        let subject = match subject {
            Ok(subject) => subject,
            Err((name, error)) => {
                planned.push(Planned::Refused { name, error });
                continue;
            }
        };
        let mut seen = std::collections::HashSet::new();
        for options in &option_sets {
            let name = evaluate::variant_name(subject.name(), subject.objectives(), options);
            if !seen.insert(name.clone()) {
                continue;
            }
            let objectives = subject
                .objectives()
                .iter()
                .copied()
                .chain(weighted.iter().copied().filter(|&o| {
                    // An algorithm that reports a weighted objective itself (lp-lns) has it
                    // once.
                    subject.reports(o) && !subject.objectives().contains(&o)
                }))
                .collect();
            planned.push(Planned::Variant {
                subject,
                name,
                options: options.clone(),
                objectives,
            });
        }
    }
    planned
}

/// The rows of one instance of any model: the config's exact objectives that apply (by the
/// model's exact solver, or their earlier results when resuming: the algorithms divide by
/// them), then every planned algorithm variant ([`plan`]), rows already in `done` skipped;
/// with the walks of the rows the claims table could find violated.
fn run_on<M: InstanceModel>(
    instance: &M,
    base: Row,
    spec: &InstanceSpec,
    config: &Config,
    done: &HashMap<(String, String, String), Row>,
) -> Produced {
    let mut rows = Vec::new();
    let mut walks = Vec::new();
    let reference = exact_rows(&mut rows, spec, config, done, |e| {
        exact_applies(instance, e).then(|| exact_row(instance, &base, e, &exact_objective_name(e)))
    });
    let outside = if M::TAKES_OUTSIDE {
        config.outside_algorithms()
    } else {
        Vec::new()
    };
    for planned in plan(instance, spec, config, &outside) {
        match planned {
            Planned::Refused { name, error } => {
                let key = (spec.name.clone(), name.clone(), "-".to_string());
                if !done.contains_key(&key) {
                    rows.push(Row {
                        algorithm: name,
                        objective: "-".into(),
                        error,
                        ..base.clone()
                    });
                }
            }
            Planned::Variant {
                subject,
                name,
                options,
                objectives,
            } => {
                let pending: Vec<Objective> = objectives
                    .into_iter()
                    .filter(|o| {
                        !done.contains_key(&(spec.name.clone(), name.clone(), o.to_string()))
                    })
                    .collect();
                if pending.is_empty() {
                    continue;
                }
                let eval = evaluate::evaluate(subject, instance, &options, &pending, &reference);
                let model = instance.model();
                let produced = algorithm_rows(model, &base, subject, &name, &eval);
                for (row, checked) in produced.iter().zip(&eval.outputs) {
                    let theorems = subject.theorems_on(checked.objective, model);
                    if super::walks::claims_may_violate(row, &theorems) {
                        walks.push(Kept {
                            algorithm: row.algorithm.clone(),
                            objective: row.objective.clone(),
                            json: M::walk_json(&checked.cover),
                        });
                    }
                }
                rows.extend(produced);
            }
        }
    }
    Produced { rows, walks }
}

/// Whether the `[[exact]]` objective `e` applies to `instance`: its model solves it exactly
/// and the instance has at most `max_n` pixels (vertices).
fn exact_applies<M: InstanceModel>(instance: &M, e: &ExactSpec) -> bool {
    let objective = exact::Objective::parse(&e.objective, e.turn_cost).ok();
    instance.has_exact(objective) && instance.model().len() <= e.max_n
}

/// The config's exact objectives on one instance: each row solved by `solve` (`None` where the
/// objective does not apply), or taken from `done` when resuming; new rows are pushed to
/// `rows`, after [`share_between_objectives`]. Returns what they prove, for the algorithm rows
/// to divide by.
fn exact_rows(
    rows: &mut Vec<Row>,
    spec: &InstanceSpec,
    config: &Config,
    done: &HashMap<(String, String, String), Row>,
    solve: impl Fn(&ExactSpec) -> Option<Row>,
) -> Reference {
    // (row, whether it is new in this run).
    let mut found: Vec<(Row, bool)> = Vec::new();
    for e in &config.exact {
        let name = exact_objective_name(e);
        let key = (spec.name.clone(), EXACT.to_string(), name.clone());
        match done.get(&key) {
            Some(r) => found.push((r.clone(), false)),
            None => {
                if let Some(row) = solve(e) {
                    found.push((row, true));
                }
            }
        }
    }
    share_between_objectives(&mut found);
    let mut reference = Reference::default();
    for (row, new) in found {
        if let Ok(objective) = row.objective.parse::<Objective>() {
            reference.insert(objective, known_from(&row, &row.objective));
        }
        if new {
            rows.push(row);
        }
    }
    reference
}

/// Shares what the exact rows of one instance know between a cycle-cover objective and its
/// tour ([`Objective::tour_counterpart`]: `cc-turns` and `turns`, `weighted-cc C` and
/// `weighted C`), in both directions: every tour is a cycle cover of the same cost, so
///
/// * the cycle cover's value becomes the tour's when the tour is cheaper (its walk, recounted
///   by the checker in the tour's row, is a valid cycle cover; the row's `cycles` becomes 1),
/// * the tour's lower bound becomes the cycle cover's when that is higher (OPT_tour ≥ OPT_cc),
///
/// and either row is `optimal` when its value then meets its bound. Only new rows change
/// (a resumed row is already written).
fn share_between_objectives(found: &mut [(Row, bool)]) {
    // Only solved rows share: an infeasible tour (a disconnected region) has no bound to lift.
    let usable = |r: &Row| {
        r.error.is_empty()
            && r.valid != Some(false)
            && [exact::Status::Optimal, exact::Status::TimeLimit]
                .iter()
                .any(|s| r.opt_status == s.to_string())
    };
    for c in 0..found.len() {
        let Some(tour) = found[c]
            .0
            .objective
            .parse::<Objective>()
            .ok()
            .and_then(Objective::tour_counterpart)
        else {
            continue;
        };
        let Some(t) = found
            .iter()
            .position(|(r, _)| r.objective.parse::<Objective>().ok() == Some(tour))
        else {
            continue;
        };
        let (cc, tr) = (found[c].0.clone(), found[t].0.clone());
        if !usable(&cc) || !usable(&tr) {
            continue;
        }
        if found[c].1
            && let Some(v) = tr.value
            && cc.value.is_none_or(|u| v < u)
        {
            let row = &mut found[c].0;
            row.value = Some(v);
            row.length = tr.length;
            row.turns = tr.turns;
            row.cycles = tr.cycles;
            row.max_coverage = tr.max_coverage;
            row.valid = tr.valid;
            settle(row);
        }
        if found[t].1
            && let Some(b) = cc.lower_bound
            && tr.lower_bound.is_none_or(|l| b > l)
        {
            let row = &mut found[t].0;
            row.lower_bound = Some(b);
            settle(row);
        }
    }
}

/// An exact row after its value or bound moved: `optimal` when they meet.
fn settle(row: &mut Row) {
    if let (Some(v), Some(b)) = (row.value, row.lower_bound)
        && v == b
    {
        row.opt_status = exact::Status::Optimal.to_string();
        row.opt = Some(v);
    }
    row.compute_ratios();
}

/// What an exact row says about the optimum of its objective.
fn known_from(row: &Row, name: &str) -> Known {
    Known::proven(name, row.opt, row.lower_bound, row.opt_status.clone())
}

/// The exact row of one `[[exact]]` objective on an instance, by its model's exact solver.
fn exact_row<M: InstanceModel>(instance: &M, base: &Row, e: &ExactSpec, name: &str) -> Row {
    let mut row = Row {
        algorithm: EXACT.into(),
        objective: name.to_string(),
        ..base.clone()
    };
    let start = Instant::now();
    let outcome = evaluate::guarded(|| {
        let objective =
            exact::Objective::parse(&e.objective, e.turn_cost).map_err(Error::invalid)?;
        instance.solve_exact(objective, e.time_limit)
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
            // No walks (infeasible, or none by the time limit) is not an invalid result.
            row.valid = res.valid;
            if res.status == exact::Status::Optimal {
                row.opt = res.value;
            }
            row.max_coverage = res.max_coverage;
            if let Some(m) = res.message.filter(|_| res.status == exact::Status::Error) {
                row.error = m;
            }
        }
    }
    row.compute_ratios();
    row
}

/// One row per objective of an evaluation, in the order of its outputs (then an error row for
/// each objective it did not produce).
fn algorithm_rows<C>(
    model: Model<'_>,
    base: &Row,
    subject: Subject<'_>,
    name: &str,
    eval: &Evaluation<C>,
) -> Vec<Row> {
    let (merge, cutter, coverage4) = evaluate::relevant_options(subject.objectives());
    let row_for = |objective: Objective| Row {
        algorithm: name.to_string(),
        objective: objective.to_string(),
        guarantee: subject
            .applicable_to(objective, model, &eval.options)
            .iter()
            .map(|g| g.to_string())
            .collect::<Vec<_>>()
            .join("; "),
        theorems: subject
            .theorems_on(objective, model)
            .iter()
            .map(|t| t.key())
            .collect::<Vec<_>>()
            .join("; "),
        seconds: eval.seconds,
        merge: if merge {
            eval.options.merge.to_string()
        } else {
            String::new()
        },
        cutter: if cutter {
            eval.options.cutter.to_string()
        } else {
            String::new()
        },
        coverage4: coverage4.then_some(eval.options.coverage4),
        ..base.clone()
    };
    let mut rows: Vec<Row> = eval
        .outputs
        .iter()
        .map(|c| {
            let mut row = row_for(c.objective);
            row.valid = Some(c.valid);
            row.error = c.error.clone().unwrap_or_default();
            row.length = Some(c.length);
            row.unit = (c.unit != 1).then_some(c.unit);
            row.turns = Some(c.turns);
            row.cycles = Some(c.cycles as u64);
            // The exact checker of orthogonal polygons does not count visits.
            row.max_coverage = (!matches!(model, Model::Ortho(_))).then_some(c.max_coverage);
            row.value = Some(c.value);
            row.opt = c.opt;
            row.opt_status = c.opt_status.clone();
            row.lower_bound = c.lower_bound;
            row.lb_source = c.lb_source.clone();
            row.within_guarantee = c.within_guarantee;
            row.compute_ratios();
            row
        })
        .collect();
    rows.extend(eval.missing.iter().map(|(objective, why)| Row {
        error: why.clone(),
        ..row_for(*objective)
    }));
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact_row(objective: &str, value: u64, lower_bound: u64) -> Row {
        let mut row = Row {
            algorithm: EXACT.into(),
            objective: objective.into(),
            value: Some(value),
            turns: Some(value),
            cycles: Some(3),
            lower_bound: Some(lower_bound),
            opt_status: exact::Status::TimeLimit.to_string(),
            valid: Some(true),
            ..Row::default()
        };
        row.compute_ratios();
        row
    }

    /// A cheaper tour lowers the cycle cover's value (and proves it when it meets the bound);
    /// the cycle cover's higher bound lifts the tour's.
    #[test]
    fn cycle_cover_and_tour_share_walks_and_bounds() {
        let mut found = vec![
            (exact_row("cc-turns", 446, 432), true),
            (exact_row("turns", 434, 420), true),
        ];
        share_between_objectives(&mut found);
        let (cc, tour) = (&found[0].0, &found[1].0);
        assert_eq!(
            (cc.value, cc.cycles, cc.lower_bound),
            (Some(434), Some(3), Some(432))
        );
        assert_eq!(cc.opt_status, "time_limit");
        assert_eq!(tour.lower_bound, Some(432));
        assert_eq!(tour.opt_status, "time_limit");

        // The tour meets the cycle cover's bound: both are optimal.
        let mut found = vec![
            (exact_row("turns", 432, 420), true),
            (exact_row("cc-turns", 440, 432), true),
        ];
        share_between_objectives(&mut found);
        for (row, _) in &found {
            assert_eq!(
                (row.value, row.opt),
                (Some(432), Some(432)),
                "{}",
                row.objective
            );
            assert_eq!(row.opt_status, "optimal");
        }

        // Weighted objectives pair by their turn cost only; resumed rows do not change, and a
        // row with an error gives nothing.
        let mut found = vec![
            (exact_row("weighted-cc-c50", 900, 800), true),
            (exact_row("weighted-c20", 600, 100), true),
            (exact_row("weighted-c50", 850, 700), false),
            (exact_row("cc-turns", 500, 400), true),
            (
                Row {
                    error: "boom".into(),
                    ..exact_row("turns", 10, 900)
                },
                true,
            ),
        ];
        let before = found.clone();
        share_between_objectives(&mut found);
        assert_eq!(found[0].0.value, Some(850));
        for k in 1..found.len() {
            assert_eq!(found[k], before[k], "row {k}");
        }

        // An infeasible tour (a disconnected region) takes no bound.
        let mut infeasible = exact_row("turns", 0, 0);
        infeasible.opt_status = exact::Status::Infeasible.to_string();
        infeasible.value = None;
        let mut found = vec![(exact_row("cc-turns", 30, 28), true), (infeasible, true)];
        let before = found.clone();
        share_between_objectives(&mut found);
        assert_eq!(found, before);
    }
}
