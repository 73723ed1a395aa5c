//! `mowmill sample`: draw a fixed random sample of runs' rows, or re-run one and compare.

use anyhow::Result;
use clap::Args;
use mowmill::harness::sample::{self, DrawOptions};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct SampleArgs {
    /// Re-run the sample in this directory and compare every row with it (exit 1 on any
    /// difference).
    #[arg(long, conflicts_with_all = ["from", "out"], required_unless_present = "from")]
    pub check: Option<PathBuf>,
    /// Run directory to sample (holding results.csv, manifest.json, instances/); repeat it
    /// to merge several runs into one sample.
    #[arg(long, requires = "out")]
    pub from: Vec<PathBuf>,
    /// Sample directory to write (sample.csv, sample.json, manifests/, instances/).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// About this many rows (each sampled instance's exact rows included).
    #[arg(long, default_value_t = 2000)]
    pub count: usize,
    /// Seed of the draw.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The most recorded seconds the sampled rows may add up to.
    #[arg(long, default_value_t = 120.0)]
    pub max_seconds: f64,
    /// Parallel instances of --check (default: all cores).
    #[arg(long, value_parser = super::bench::parse_jobs)]
    pub jobs: Option<usize>,
}

pub fn sample_command(a: SampleArgs) -> Result<ExitCode> {
    if let Some(dir) = a.check {
        let report = sample::check(&dir, a.jobs)?;
        for d in &report.differences {
            println!("differs: {d}");
        }
        println!(
            "{}: {} row(s) of {} instance(s) re-run in {:.1}s: {}",
            dir.display(),
            report.rows,
            report.instances,
            report.seconds,
            if report.passed() {
                "all equal to the committed rows".to_string()
            } else {
                format!(
                    "{} difference(s); if the change is meant, regenerate the runs and draw the \
                     sample again",
                    report.differences.len()
                )
            }
        );
        return Ok(if report.passed() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let Some(out) = a.out else {
        anyhow::bail!("--from needs --out");
    };
    let opts = DrawOptions {
        count: a.count,
        seed: a.seed,
        max_seconds: a.max_seconds,
    };
    let index = sample::draw(&a.from, &out, &opts)?;
    println!(
        "{}: {} row(s) of {} instance(s), {:.1} recorded seconds",
        out.display(),
        index.rows,
        index.instances,
        index.estimated_seconds
    );
    for (why, n) in &index.excluded {
        println!("  excluded {n} row(s): {why}");
    }
    Ok(ExitCode::SUCCESS)
}
