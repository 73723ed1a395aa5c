//! `mowmill bench`: a suite of instances x algorithms x exact objectives.

use anyhow::{Context, Result};
use clap::Args;
use mowmill::harness::{self, config::Config, run::RunOptions};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct BenchArgs {
    /// Suite config (TOML); default: the built-in default suite.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Output directory (default: results/<run-id>/).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Parallel jobs (default: all cores); each solve uses one thread.
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Continue the run in this directory, skipping rows already in its results.csv.
    #[arg(long, conflicts_with = "out")]
    pub resume: Option<PathBuf>,
    /// Run the I-th (0-based) of N deterministic slices of the instance list, e.g. 0/4.
    /// Defaults to SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT when those are set.
    #[arg(long, value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
}

pub fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let (i, n) = s
        .split_once('/')
        .ok_or_else(|| format!("expected I/N, got {s:?}"))?;
    let (i, n): (usize, usize) = (
        i.parse().map_err(|_| format!("bad shard index {i:?}"))?,
        n.parse().map_err(|_| format!("bad shard count {n:?}"))?,
    );
    if n == 0 || i >= n {
        return Err(format!("shard {i}/{n}: expected 0 <= I < N"));
    }
    Ok((i, n))
}

/// The shard from Slurm's job-array variables (task ids are made 0-based with
/// SLURM_ARRAY_TASK_MIN).
pub fn slurm_shard() -> Option<(usize, usize)> {
    let var = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<usize>().ok());
    let (id, count) = (var("SLURM_ARRAY_TASK_ID")?, var("SLURM_ARRAY_TASK_COUNT")?);
    let i = id.checked_sub(var("SLURM_ARRAY_TASK_MIN").unwrap_or(0))?;
    (i < count).then_some((i, count))
}

pub fn bench_command(a: BenchArgs) -> Result<ExitCode> {
    let resume = a.resume.is_some();
    let config = match (&a.config, &a.resume) {
        (Some(path), _) => Config::read(path)?,
        // A resumed run continues with the config it recorded.
        (None, Some(dir)) => {
            let path = dir.join("manifest.json");
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("reading {}", path.display()))?;
            let v: serde_json::Value = serde_json::from_str(&text)
                .with_context(|| format!("parsing {}", path.display()))?;
            let toml_text =
                toml::to_string(&v["config"]).context("re-encoding the recorded config")?;
            let mut config = Config::parse(&toml_text, &path.display().to_string())?;
            if let Some(d) = v["config_dir"].as_str() {
                config.dir = PathBuf::from(d);
            }
            config
        }
        (None, None) => Config::parse(harness::DEFAULT_CONFIG, "built-in default suite")?,
    };
    let shard = a.shard.or_else(slurm_shard);
    let run_id = match &a.resume {
        Some(dir) => harness::manifest::read_run_id(dir).unwrap_or_else(|| config.name.clone()),
        None => match std::env::var("SLURM_ARRAY_JOB_ID") {
            Ok(job) => format!("{}-slurm{job}", config.name),
            Err(_) => format!(
                "{}-{}",
                config.name,
                harness::manifest::now().replace([':', '-'], "")
            ),
        },
    };
    let out = a.resume.clone().or(a.out.clone()).unwrap_or_else(|| {
        let mut dir = PathBuf::from("results").join(&run_id);
        if let Some((i, n)) = shard {
            dir = dir.join(format!("shard-{i}-of-{n}"));
        }
        dir
    });
    let opts = RunOptions {
        out: out.clone(),
        jobs: a.jobs,
        resume,
        shard,
        run_id,
        command_line: std::env::args().collect::<Vec<_>>().join(" "),
    };
    let summary = harness::run::run(&config, &opts)?;
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
    Ok(if harness::summary::failed(&lines) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
