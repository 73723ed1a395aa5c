//! The `mowmill` command line. Exit codes: 0 success, 1 a checked property failed (an invalid
//! tour), 2 bad input or usage.

use anyhow::Result;
use clap::{Parser, Subcommand};
use mowmill::checker::Mode;
use mowmill::error::Error;
use mowmill::harness::{self};
use std::path::PathBuf;
use std::process::ExitCode;

mod cli;
use cli::{
    algos::*, bench::*, exact::*, export::*, generate::*, hunt::*, orders::*, report::*, sample::*,
    solve::*, tight::*,
};

#[derive(Parser)]
#[command(
    name = "mowmill",
    version,
    about = "Benchmark harness for covering tours of grid polygons"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate an instance deterministically from a family, parameters and a seed.
    Gen(GenArgs),
    /// Topology of an instance: N, holes, components, boundary/internal, cut vertices, ...
    Info {
        /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list).
        file: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Write an instance in another format: TSPLIB (for Concorde or LKH), a pixel list, WKT,
    /// .grid.
    Export(ExportArgs),
    /// Check a tour or cycle cover with the independent checker (exit 1 if invalid).
    Validate {
        /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list).
        file: PathBuf,
        /// Tour file: JSON {"cycles": [[[x, y], ...], ...]}.
        #[arg(long)]
        tour: PathBuf,
        /// milling: cover every pixel, stay inside; lawn: cover every grass pixel, may leave.
        #[arg(long, default_value = "milling")]
        mode: Mode,
        #[arg(long)]
        json: bool,
    },
    /// Run a registered approximation algorithm; its outputs go through the checker.
    Solve(SolveArgs),
    /// List the registered algorithms with their objectives, guarantees and theorems.
    Algos(AlgosArgs),
    /// Solve an instance exactly (MILP with HiGHS) with a proven lower bound.
    Exact(ExactArgs),
    /// The star cover over every order of its greedy choices: how many violate a bound.
    Orders(OrdersArgs),
    /// Search for the instances where an algorithm is worst (largest ratio to the optimum).
    Hunt(HuntArgs),
    /// Run a benchmark suite: instances x algorithms x exact objectives -> CSV, stats, plots.
    Bench(BenchArgs),
    /// One self-contained HTML page of a run (claims, ratios, worst instances, findings,
    /// time, errors), or of two runs side by side with --compare A B.
    Report(ReportArgs),
    /// Draw a fixed random sample of runs' rows (with their instance files), or re-run a
    /// sample and compare every row with it (--check; exit 1 on a difference).
    Sample(SampleArgs),
    /// Redraw the plots of a run directory from its CSV files.
    Plot {
        /// Run directory (holding results.csv).
        dir: PathBuf,
    },
    /// Combine shard output directories into one run (refused unless they are every shard
    /// I/N of one config, each finished and complete).
    Merge {
        /// Shard directories.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        /// Output directory of the merged run.
        #[arg(long)]
        out: PathBuf,
    },
    /// Regression gate: compare a run with a baseline (exit 1 on regression).
    Gate {
        /// Baseline stats.csv (or a run directory holding one); the results.csv and
        /// manifest.json of the same run must be beside it.
        #[arg(long)]
        baseline: PathBuf,
        /// Run directory to check (holding results.csv).
        #[arg(long)]
        current: PathBuf,
        /// Relative tolerance on ratio means and maxima: a finite number, 0 <= X < 1.
        // Checked by the parser so that NaN or a negative value is refused (exit 2) before
        // the gate runs, with clap naming --tolerance in the message (a negative number is
        // taken as the value, not as an unknown flag).
        #[arg(
            long,
            default_value_t = 0.005,
            value_parser = harness::gate::parse_tolerance,
            allow_negative_numbers = true
        )]
        tolerance: f64,
    },
    /// Draw an instance, optionally with a tour over it, to SVG or PNG.
    Draw {
        /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list; discrete: .dm, .json,
        /// .vox, .hex; a .wkt with non-integral coordinates: the polygon, the area the tour
        /// sweeps and δB).
        file: PathBuf,
        /// Tour file to draw over the region.
        #[arg(long)]
        tour: Option<PathBuf>,
        /// Output picture: .svg or .png.
        #[arg(long)]
        out: PathBuf,
        /// Title above the picture (default: the file name; the checker's counts go below it).
        #[arg(long)]
        title: Option<String>,
    },
    /// The papers' tight families (donut, band, thin43): claimed against measured values,
    /// tight.csv/tight.md, the claims table and the figures (exit 1 if an established claim is
    /// contradicted).
    Tight(TightArgs),
    /// The claims table: one row per theorem, over a results directory (exit 1 if a claim is
    /// contradicted).
    Claims {
        /// Results directory holding results.csv (a `mowmill bench` run). Repeat it to take
        /// the rows of several runs (e.g. the validate suite and its discrete part); their
        /// instances are then named `RUN/INSTANCE`, RUN the directory's name.
        #[arg(long, default_value = "results/default")]
        from: Vec<PathBuf>,
        /// tight.csv of a `mowmill tight` run, for the tight-family column.
        #[arg(long, default_value = "results/tight/tight.csv")]
        tight: PathBuf,
        /// Also write claims.csv and claims.md into this directory.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Save each violated claim's instances, tours and figures here (default: OUT/findings
        /// when --out is given).
        #[arg(long)]
        findings: Option<PathBuf>,
        /// A hunt suite's folder (`mowmill hunt --suite`), for the column "worst found by
        /// search" (skipped with a note when it has no summary.csv).
        #[arg(long, default_value = "results/hunt")]
        hunt: PathBuf,
    },
}

fn main() -> ExitCode {
    // Die quietly on a closed pipe (`mowmill ... | head`) instead of panicking in println!.
    // SAFETY: restoring the default disposition of SIGPIPE before any thread starts.
    #[cfg(unix)]
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("mowmill: error: {}", message(&e));
            // Bad input 2, solver failure 3, invalid output 1 (see `Error::exit_code`).
            ExitCode::from(e.downcast_ref::<Error>().map_or(2, Error::exit_code))
        }
    }
}

/// The error and its causes, each said once: a cause whose text the message already contains
/// (an I/O error inside "file: error") is not repeated.
fn message(e: &anyhow::Error) -> String {
    let mut out = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if !out.contains(&text) {
            if !out.is_empty() {
                out.push_str(": ");
            }
            out.push_str(&text);
        }
    }
    out
}

fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Gen(args) => gen_command(args),
        Command::Info { file, json } => cli::info(&file, json),
        Command::Validate {
            file,
            tour,
            mode,
            json,
        } => cli::validate(&file, &tour, mode, json),
        Command::Export(args) => export_command(args),
        Command::Solve(args) => solve_command(args),
        Command::Tight(args) => tight_command(args),
        Command::Claims {
            from,
            tight,
            out,
            findings,
            hunt,
        } => {
            let findings = findings.or_else(|| out.as_ref().map(|o| o.join("findings")));
            claims_command(&from, &tight, &hunt, out.as_deref(), findings.as_deref())
        }
        Command::Bench(args) => bench_command(args),
        Command::Report(args) => report_command(args),
        Command::Sample(args) => sample_command(args),
        Command::Hunt(args) => hunt_command(args),
        Command::Exact(args) => exact_command(args),
        Command::Orders(args) => orders_command(args),
        Command::Plot { dir } => {
            let rows = harness::rows::read_results(&dir.join("results.csv"))?;
            harness::plots::draw_all(&dir, &rows)?;
            eprintln!("plots redrawn in {}", dir.join("plots").display());
            Ok(ExitCode::SUCCESS)
        }
        Command::Merge { dirs, out } => {
            let n = harness::merge::merge(&dirs, &out)?;
            eprintln!(
                "merged {} shard(s), {n} rows, into {}",
                dirs.len(),
                out.display()
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Gate {
            baseline,
            current,
            tolerance,
        } => {
            let report = harness::gate::gate(&baseline, &current, tolerance)?;
            print!("{}", report.table());
            Ok(if report.passed() {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            })
        }
        Command::Algos(a) => algos_command(a),
        Command::Draw {
            file,
            tour,
            out,
            title,
        } => cli::draw(&file, tour.as_deref(), &out, title),
    }
}
