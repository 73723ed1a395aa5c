//! `mowmill bench`: a suite of instances x algorithms x exact objectives.

use anyhow::Result;
use clap::Args;
use mowmill::error::Error;
use mowmill::harness::{
    self,
    config::Config,
    manifest::{ConfigRecord, Recorded},
    run::RunOptions,
};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// How a long run continues, shown by `mowmill bench --help`.
const CONTINUING: &str = "\
Continuing a run: `--resume DIR` skips the rows already in DIR/results.csv and continues with
the config recorded in DIR/manifest.json (its TOML text, `config_toml`) and its shard; a
recorded config with outside algorithms ([[algorithm]] commands) is refused: pass it with
--config. With --config, the file must be the recorded one (same sha256), else the resume is refused;
a --shard (or SLURM_ARRAY_TASK_*) other than the recorded one is refused too. Only one run at
a time may use a directory (DIR/.lock names the holder's pid; a lock whose holder is gone is
taken over).

Slurm: without --shard the shard is SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of
SLURM_ARRAY_TASK_COUNT (a contiguous array such as --array=0-3); set but invalid variables are
refused. A requeued task (SLURM_RESTART_COUNT > 0) that runs the same
`bench --config X --out DIR` again continues DIR as if given `--resume DIR --config X` when
DIR/manifest.json exists. scripts/slurm-array.sh runs, per task:
  mowmill bench --resume DIR --config X --jobs C   when DIR/manifest.json exists,
  mowmill bench --config X --out DIR --jobs C      otherwise.";

#[derive(Args)]
#[command(after_help = CONTINUING)]
pub struct BenchArgs {
    /// Suite config (TOML); default: the built-in default suite (with --resume: the recorded
    /// config, which a given --config must equal).
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Output directory (default: results/<run-id>/).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Parallel jobs, 1 to 16 per available core (default: all cores); each solve uses one
    /// thread.
    #[arg(long, value_parser = parse_jobs)]
    pub jobs: Option<usize>,
    /// Continue the run in this directory, skipping rows already in its results.csv.
    #[arg(long, conflicts_with = "out")]
    pub resume: Option<PathBuf>,
    /// Run the I-th (0-based) of N deterministic slices of the instance list, e.g. 0/4.
    /// Defaults to SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT when those are set.
    #[arg(long, value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// Write DIR/report.html at the end (the default; `mowmill report DIR` writes it again).
    #[arg(long, overrides_with = "no_report")]
    pub report: bool,
    /// Leave out DIR/report.html.
    #[arg(long)]
    pub no_report: bool,
}

pub fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    harness::manifest::parse_shard(s)
}

/// `--jobs`: 0 is refused (leaving --jobs out already means all cores) and so is more than 16
/// per available core, which would only spawn threads that wait.
pub fn parse_jobs(s: &str) -> Result<usize, String> {
    let jobs: usize = s
        .parse()
        .map_err(|_| format!("expected a number of jobs, got {s:?}"))?;
    harness::run::check_jobs(jobs)
}

/// A Slurm variable as a number: `Ok(None)` when unset, an error naming it when set but not a
/// non-negative integer.
fn slurm_var(name: &str) -> Result<Option<usize>, Error> {
    match std::env::var(name) {
        Err(std::env::VarError::NotPresent) => Ok(None),
        Err(std::env::VarError::NotUnicode(_)) => Err(Error::invalid(format!(
            "{name}: expected a non-negative integer, got a value that is not UTF-8"
        ))),
        Ok(v) => {
            v.trim().parse().map(Some).map_err(|_| {
                Error::invalid(format!("{name}={v:?}: expected a non-negative integer"))
            })
        }
    }
}

/// The shard from Slurm's job-array variables (task ids are made 0-based with
/// SLURM_ARRAY_TASK_MIN); `Ok(None)` outside a job array. Set but inconsistent variables are
/// refused rather than ignored, since ignoring them would run the full suite in every task.
pub fn slurm_shard() -> Result<Option<(usize, usize)>, Error> {
    let id = slurm_var("SLURM_ARRAY_TASK_ID")?;
    let count = slurm_var("SLURM_ARRAY_TASK_COUNT")?;
    let min = slurm_var("SLURM_ARRAY_TASK_MIN")?;
    let (id, count) = match (id, count) {
        (None, None) => return Ok(None),
        (Some(id), None) => {
            return Err(Error::invalid(format!(
                "SLURM_ARRAY_TASK_ID={id} is set but SLURM_ARRAY_TASK_COUNT is not: expected \
                 both (or pass --shard I/N)"
            )));
        }
        (None, Some(count)) => {
            return Err(Error::invalid(format!(
                "SLURM_ARRAY_TASK_COUNT={count} is set but SLURM_ARRAY_TASK_ID is not: \
                 expected both (or pass --shard I/N)"
            )));
        }
        (Some(id), Some(count)) => (id, count),
    };
    if count == 0 {
        return Err(Error::invalid(
            "SLURM_ARRAY_TASK_COUNT=0: expected at least 1 task",
        ));
    }
    let min = min.unwrap_or(0);
    let Some(i) = id.checked_sub(min) else {
        return Err(Error::invalid(format!(
            "SLURM_ARRAY_TASK_MIN={min} is larger than SLURM_ARRAY_TASK_ID={id}"
        )));
    };
    if i >= count {
        return Err(Error::invalid(format!(
            "SLURM_ARRAY_TASK_ID={id} (minus SLURM_ARRAY_TASK_MIN={min}) is not below \
             SLURM_ARRAY_TASK_COUNT={count}: expected a contiguous array such as \
             --array=0-{}, or pass --shard I/N",
            count - 1
        )));
    }
    Ok(Some((i, count)))
}

/// Whether this is a requeued Slurm task (SLURM_RESTART_COUNT > 0).
fn slurm_requeued() -> Result<bool, Error> {
    Ok(slurm_var("SLURM_RESTART_COUNT")?.is_some_and(|n| n > 0))
}

/// Reads a config file, keeping its text for the manifest.
fn read_config(path: &Path) -> Result<(Config, ConfigRecord), Error> {
    let text = harness::config::read_text(path)?;
    let file = path.display().to_string();
    // The config's folder: outside algorithms run there and `[[files]]` folders are resolved
    // (and checked, with the key's line and column) against it, as `Config::read` does.
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let config = Config::parse_in(&text, &file, Some(&dir))?;
    Ok((config, ConfigRecord::given(&text, &file)))
}

/// A results folder is data: whoever can write one must not be able to make `bench --resume`
/// run a program. A recorded config with outside algorithms (`[[algorithm]]` commands) is
/// therefore never run from the manifest; the user passes the config file, whose digest must
/// then equal the recorded one.
fn refuse_recorded_commands(config: &Config, rec: &Recorded) -> Result<(), Error> {
    if config.algorithm.is_empty() {
        return Ok(());
    }
    let names: Vec<&str> = config.algorithm.iter().map(|a| a.name.as_str()).collect();
    Err(Error::invalid(format!(
        "{}: the recorded config runs outside programs ([[algorithm]] {}): a resume never runs \
         a command taken from a results folder; pass your own config file with --config FILE \
         (its sha256 must equal the recorded config_sha256 {})",
        rec.path.display(),
        names.join(", "),
        rec.sha256().unwrap_or("(not recorded)")
    )))
}

pub fn bench_command(a: BenchArgs) -> Result<ExitCode> {
    // An explicit --shard wins over the Slurm variables, which are then not read.
    let given_shard = match a.shard {
        Some(s) => Some(s),
        None => slurm_shard()?,
    };
    // A requeued Slurm task reruns its command unchanged: it continues its directory.
    let resume_dir = match (&a.resume, &a.out) {
        (Some(dir), _) => Some(dir.clone()),
        (None, Some(out)) if out.join("manifest.json").exists() && slurm_requeued()? => {
            eprintln!(
                "mowmill: requeued Slurm task (SLURM_RESTART_COUNT > 0): continuing {}",
                out.display()
            );
            Some(out.clone())
        }
        _ => None,
    };
    let recorded = match &resume_dir {
        Some(dir) if a.config.is_none() => Some(Recorded::read(dir)?),
        Some(dir) => Recorded::read_if_exists(dir)?,
        None => None,
    };
    let (config, record) = match (&a.config, &recorded) {
        (Some(path), _) => read_config(path)?,
        // A resumed run continues with the config text it recorded.
        (None, Some(rec)) => {
            let text = rec.config_toml()?;
            let mut config =
                Config::parse(&text, &format!("{} (config_toml)", rec.path.display()))?;
            if let Some(d) = rec.config_dir() {
                config.dir = d;
            }
            refuse_recorded_commands(&config, rec)?;
            let record = ConfigRecord::given(&text, rec.config_file());
            (config, record)
        }
        (None, None) => {
            let file = "built-in default suite";
            let config = Config::parse(harness::DEFAULT_CONFIG, file)?;
            (config, ConfigRecord::given(harness::DEFAULT_CONFIG, file))
        }
    };
    // A resumed shard keeps its shard; a different one is refused by the run.
    let shard = match &recorded {
        Some(rec) if given_shard.is_none() => rec.shard()?,
        _ => given_shard,
    };
    let run_id = match recorded.as_ref().and_then(Recorded::run_id) {
        Some(id) => id.to_string(),
        None => match std::env::var("SLURM_ARRAY_JOB_ID") {
            Ok(job) => format!("{}-slurm{job}", config.name),
            Err(_) => format!(
                "{}-{}",
                config.name,
                harness::manifest::now().replace([':', '-'], "")
            ),
        },
    };
    let out = resume_dir.clone().or(a.out.clone()).unwrap_or_else(|| {
        let mut dir = PathBuf::from("results").join(&run_id);
        if let Some((i, n)) = shard {
            dir = dir.join(format!("shard-{i}-of-{n}"));
        }
        dir
    });
    let opts = RunOptions {
        out: out.clone(),
        jobs: a.jobs,
        resume: resume_dir.is_some(),
        shard,
        run_id,
        command_line: std::env::args().collect::<Vec<_>>().join(" "),
    };
    let summary = harness::run::run_recorded(&config, &record, &opts)?;
    eprintln!(
        "{} instances, {} rows written ({} with errors) -> {}",
        summary.instances,
        summary.rows_written,
        summary.errors,
        out.display()
    );
    // The summary covers every row in the directory, resumed ones included.
    let rows = harness::rows::read_rows(&out.join("results.csv"))?;
    let lines = harness::summary::lines(&rows);
    print!("{}", harness::summary::text(&lines, &out));
    if !a.no_report {
        // A report that cannot be made is said, not a failed run: the rows are what counts.
        let page = out.join("report.html");
        match mowmill::report::write(&out, &mowmill::report::Options::default(), &page) {
            Ok(bytes) => println!("report: {} ({:.1} MB)", page.display(), bytes as f64 / 1e6),
            Err(e) => eprintln!("report: not written: {e}"),
        }
    }
    Ok(if harness::summary::failed(&lines) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
