//! `mowmill report`: one self-contained HTML page of a run, or of two runs side by side.

use anyhow::Result;
use clap::Args;
use mowmill::report;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct ReportArgs {
    /// The run folder (a `mowmill bench` output).
    #[arg(required_unless_present = "compare")]
    pub run: Option<PathBuf>,
    /// The page to write (default: RUN/report.html; with --compare: B/compare.html).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Two runs side by side, A the baseline: per group better or worse, the claims of both,
    /// the gate's verdict.
    #[arg(long, num_args = 2, value_names = ["A", "B"], conflicts_with = "run")]
    pub compare: Option<Vec<PathBuf>>,
    /// A `mowmill tight` folder for the tight-family section (default: RUN/tight.csv if there).
    #[arg(long)]
    pub tight: Option<PathBuf>,
    /// A `mowmill hunt` folder for the hunt section.
    #[arg(long)]
    pub hunt: Option<PathBuf>,
}

pub fn report_command(a: ReportArgs) -> Result<ExitCode> {
    let opts = report::Options {
        tight: a.tight,
        hunt: a.hunt,
    };
    let start = std::time::Instant::now();
    let (out, bytes) = match (&a.compare, &a.run) {
        (Some(pair), _) => {
            let out = a.out.unwrap_or_else(|| pair[1].join("compare.html"));
            let page = report::compare(&pair[0], &pair[1], &opts)?;
            std::fs::write(&out, &page).map_err(|e| mowmill::Error::io(&out, e))?;
            (out, page.len())
        }
        (None, Some(run)) => {
            let out = a.out.unwrap_or_else(|| run.join("report.html"));
            let bytes = report::write(run, &opts, &out)?;
            (out, bytes)
        }
        (None, None) => {
            return Err(mowmill::Error::invalid("report: expected RUN or --compare A B").into());
        }
    };
    println!(
        "report: {} ({:.2} MB in {:.2} s)",
        out.display(),
        bytes as f64 / 1e6,
        start.elapsed().as_secs_f64()
    );
    Ok(ExitCode::SUCCESS)
}
