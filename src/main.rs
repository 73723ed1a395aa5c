//! The `mowmill` command line. Exit codes: 0 success, 1 a checked property failed (an invalid
//! tour), 2 bad input or usage.

use anyhow::{Context, Result};
use clap::{Args, Parser, Subcommand};
use mowmill::algorithms::{self, Cutter, Merge, Options};
use mowmill::checker::{self, Mode};
use mowmill::draw::{self, DrawOptions};
use mowmill::error::Error;
use mowmill::exact;
use mowmill::generate::{self, Family, GenParams, Style};
use mowmill::harness::{self, config::Config, run::RunOptions};
use mowmill::instance::Instance;
use mowmill::topology;
use mowmill::tour::CycleCover;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
        /// Instance file (.grid or WKT).
        file: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Check a tour or cycle cover with the independent checker (exit 1 if invalid).
    Validate {
        /// Instance file (.grid or WKT).
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
    /// List the registered algorithms with their objectives and guarantees.
    Algos {
        #[arg(long)]
        json: bool,
    },
    /// Solve an instance exactly (MILP with HiGHS) with a proven lower bound.
    Exact(ExactArgs),
    /// Run a benchmark suite: instances x algorithms x exact objectives -> CSV, stats, plots.
    Bench(BenchArgs),
    /// Redraw the plots of a run directory from its CSV files.
    Plot {
        /// Run directory (holding results.csv).
        dir: PathBuf,
    },
    /// Combine shard output directories into one run.
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
        /// Baseline stats.csv (or a run directory holding one).
        #[arg(long)]
        baseline: PathBuf,
        /// Run directory to check (holding results.csv).
        #[arg(long)]
        current: PathBuf,
        /// Relative tolerance on ratio means and maxima.
        #[arg(long, default_value_t = 0.005)]
        tolerance: f64,
    },
    /// Draw an instance, optionally with a tour over it, to SVG or PNG.
    Draw {
        /// Instance file (.grid or WKT).
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
        /// Results directory holding results.csv (a `mowmill bench` run).
        #[arg(long, default_value = "results/default")]
        from: PathBuf,
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
    },
}

#[derive(Args)]
struct TightArgs {
    /// Output directory: tight.csv, tight.md, claims.csv, claims.md, figures/.
    #[arg(long, default_value = "results/tight")]
    out: PathBuf,
    /// Results directory for the claims table (skipped with a note if it has no results.csv).
    #[arg(long, default_value = "results/default")]
    from: PathBuf,
    /// Small ranges (donut k = 2..4, band k = 1..6, thin43 s = 0..2) for a quick look.
    #[arg(long)]
    quick: bool,
    /// Time limit of each exact solve, in seconds.
    #[arg(long, default_value_t = 120.0)]
    time_limit: f64,
    /// Skip the figures.
    #[arg(long)]
    no_figures: bool,
}

#[derive(Args)]
struct ExactArgs {
    /// Instance file (.grid or WKT).
    file: PathBuf,
    /// length, cc-turns, tour-turns, weighted or lawn-tsp.
    #[arg(long)]
    objective: String,
    /// Weight C of turns for `weighted` (length + C * turns).
    #[arg(long)]
    turn_cost: Option<u32>,
    /// Wall-clock limit in seconds; the answer is then labelled time_limit with its bound.
    #[arg(long)]
    time_limit: Option<f64>,
    /// HiGHS threads for this solve.
    #[arg(long, default_value_t = 1)]
    threads: usize,
    #[arg(long)]
    json: bool,
    /// Write the optimal (or best) walk(s) to this tour file.
    #[arg(long)]
    tour_out: Option<PathBuf>,
    /// Show the solver's log.
    #[arg(long)]
    verbose: bool,
    /// Turn objectives: visit every pixel at most this many times (the optimum under this
    /// cap; Theorem 5.6 of the turn-cost paper says a cap of 4 costs no turns).
    #[arg(long)]
    max_coverage: Option<u32>,
}

#[derive(Args)]
struct BenchArgs {
    /// Suite config (TOML); default: the built-in default suite.
    #[arg(long)]
    config: Option<PathBuf>,
    /// Output directory (default: results/<run-id>/).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Parallel jobs (default: all cores); each solve uses one thread.
    #[arg(long)]
    jobs: Option<usize>,
    /// Continue the run in this directory, skipping rows already in its results.csv.
    #[arg(long, conflicts_with = "out")]
    resume: Option<PathBuf>,
    /// Run the I-th (0-based) of N deterministic slices of the instance list, e.g. 0/4.
    /// Defaults to SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT when those are set.
    #[arg(long, value_parser = parse_shard)]
    shard: Option<(usize, usize)>,
}

fn parse_shard(s: &str) -> Result<(usize, usize), String> {
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
fn slurm_shard() -> Option<(usize, usize)> {
    let var = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<usize>().ok());
    let (id, count) = (var("SLURM_ARRAY_TASK_ID")?, var("SLURM_ARRAY_TASK_COUNT")?);
    let i = id.checked_sub(var("SLURM_ARRAY_TASK_MIN").unwrap_or(0))?;
    (i < count).then_some((i, count))
}

#[derive(Args)]
struct SolveArgs {
    /// Instance file (.grid or WKT).
    file: PathBuf,
    /// Algorithm name (see `mowmill algos`).
    #[arg(long)]
    algo: String,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
    /// Write the walk(s) of the printed output to this tour file.
    #[arg(long)]
    tour_out: Option<PathBuf>,
    /// Print the unmerged cycle cover instead of the merged tour.
    #[arg(long)]
    cycle_cover: bool,
    /// Merging strategy for cycle covers: naive or smart.
    #[arg(long, default_value = "smart", value_parser = parse_merge)]
    merge: Merge,
    /// Lawn-mowing cutter and motion: square, square-free or disk.
    #[arg(long, default_value = "square", value_parser = parse_cutter)]
    cutter: Cutter,
    /// Rewrite tours to cover each pixel at most 4 times (Theorem 5.6 of the turn-cost paper).
    #[arg(long)]
    coverage4: bool,
}

fn parse_merge(s: &str) -> Result<Merge, String> {
    match s {
        "naive" => Ok(Merge::Naive),
        "smart" => Ok(Merge::Smart),
        _ => Err(format!("expected naive or smart, got {s:?}")),
    }
}

fn parse_cutter(s: &str) -> Result<Cutter, String> {
    match s {
        "square" => Ok(Cutter::Square),
        "square-free" => Ok(Cutter::SquareFree),
        "disk" => Ok(Cutter::Disk),
        _ => Err(format!("expected square, square-free or disk, got {s:?}")),
    }
}

#[derive(Args)]
struct GenArgs {
    /// Family: rect, random-simple, random-holed, thin, lawn-scattered, donut, band, thin43,
    /// boundary, thin-arms, pinholes.
    family: Family,
    /// Number of pixels.
    #[arg(long)]
    n: Option<usize>,
    /// Number of holes.
    #[arg(long)]
    holes: Option<usize>,
    /// Width (rect).
    #[arg(long)]
    width: Option<usize>,
    /// Height (rect).
    #[arg(long)]
    height: Option<usize>,
    /// Width of the annulus (donut), or the index of the band B_k (band).
    #[arg(long)]
    k: Option<usize>,
    /// Outer side (donut).
    #[arg(long)]
    side: Option<usize>,
    /// Parameter s of the 4/3 thin example (thin43).
    #[arg(long)]
    s: Option<usize>,
    /// Number of grass components (lawn-scattered).
    #[arg(long)]
    parts: Option<usize>,
    /// Shape style of random families: mixed (default), blob, rectangles, snake, rooms.
    #[arg(long)]
    style: Option<Style>,
    /// Compactness of blob growth in [0, 1] (1 round, 0 ragged).
    #[arg(long)]
    compactness: Option<f64>,
    /// No cut vertices (random-simple) or no local cut vertices (random-holed).
    #[arg(long)]
    no_cut: bool,
    /// Seed of the portable ChaCha generator.
    #[arg(long)]
    seed: u64,
    /// Output .grid file.
    #[arg(long)]
    out: PathBuf,
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
            eprintln!("mowmill: error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Gen(args) => gen_command(args),
        Command::Info { file, json } => {
            let inst = Instance::read(&file)?;
            let mut v = serde_json::to_value(topology::summary(&inst.region))?;
            // The minimum strip cover: the turn lower bound of Lemmas 4.2-4.4 (turn-cost paper).
            v["strip_cover"] = mowmill::strip_cover::min_strip_cover_size(&inst.region).into();
            if json {
                println!("{}", serde_json::to_string_pretty(&v)?);
            } else {
                for (k, val) in v.as_object().context("summary is an object")? {
                    println!("{k:<20} {val}");
                }
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Validate {
            file,
            tour,
            mode,
            json,
        } => {
            let inst = Instance::read(&file)?;
            let cover = CycleCover::read(&tour)?;
            let report = checker::check(&inst.region, &cover, mode);
            if json {
                println!("{}", serde_json::to_string_pretty(&report)?);
            } else if report.valid {
                println!(
                    "valid: length {}, turns {}, {} cycle(s), max coverage {}",
                    report.length, report.turns, report.cycles, report.max_coverage
                );
            } else {
                println!("invalid: {}", report.error.as_deref().unwrap_or("?"));
            }
            Ok(if report.valid {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            })
        }
        Command::Solve(args) => solve_command(args),
        Command::Tight(args) => tight_command(args),
        Command::Claims {
            from,
            tight,
            out,
            findings,
        } => {
            let findings = findings.or_else(|| out.as_ref().map(|o| o.join("findings")));
            claims_command(&from, &tight, out.as_deref(), findings.as_deref())
        }
        Command::Bench(args) => bench_command(args),
        Command::Exact(args) => exact_command(args),
        Command::Plot { dir } => {
            let rows = harness::rows::read_rows(&dir.join("results.csv"))?;
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
        Command::Algos { json } => {
            let list: Vec<serde_json::Value> = algorithms::REGISTRY
                .iter()
                .map(|a| {
                    serde_json::json!({
                        "name": a.name,
                        "summary": a.summary,
                        "objectives": a.objectives,
                        "guarantees": a.guarantees.iter().map(ToString::to_string).collect::<Vec<_>>(),
                    })
                })
                .collect();
            if json {
                println!("{}", serde_json::to_string_pretty(&list)?);
            } else {
                for a in algorithms::REGISTRY {
                    println!("{:<18} {}", a.name, a.summary);
                    for g in a.guarantees {
                        println!("{:<18}   guarantee: {g}", "");
                    }
                }
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Draw {
            file,
            tour,
            out,
            title,
        } => {
            let inst = Instance::read(&file)?;
            let cover = tour.as_deref().map(CycleCover::read).transpose()?;
            let mut caption = format!("N = {}", inst.region.len());
            if let Some(c) = &cover {
                let r = checker::check(&inst.region, c, Mode::Milling);
                caption += &format!(
                    ", length {}, turns {}, {} cycle(s)",
                    r.length, r.turns, r.cycles
                );
                if !r.valid {
                    caption += " (not a valid milling cover)";
                }
            }
            let opts = DrawOptions {
                title: Some(title.unwrap_or_else(|| inst.name.clone())),
                caption: Some(caption),
                ..DrawOptions::default()
            };
            draw::draw(&inst.region, cover.as_ref(), &out, &opts)?;
            eprintln!("wrote {}", out.display());
            Ok(ExitCode::SUCCESS)
        }
    }
}

fn exact_command(a: ExactArgs) -> Result<ExitCode> {
    let objective =
        exact::Objective::parse(&a.objective, a.turn_cost).map_err(mowmill::Error::Invalid)?;
    let inst = Instance::read(&a.file)?;
    // A milling tour of a disconnected region does not exist: that is bad input for this
    // objective (exit 2, like `solve`), not a solver failure.
    if objective.is_tour() && objective != exact::Objective::LawnTsp {
        let parts = topology::components(&inst.region).count;
        if parts != 1 {
            return Err(mowmill::Error::Invalid(format!(
                "{}: the region has {parts} connected components; objective {} is a tour, \
                 which needs one (cc-turns and lawn-tsp accept several)",
                a.file.display(),
                objective
            ))
            .into());
        }
    }
    let opts = exact::ExactOptions {
        time_limit: a.time_limit,
        threads: a.threads,
        verbose: a.verbose,
        warm_start: None,
        max_coverage: a.max_coverage,
    };
    let result = exact::solve(&inst.region, objective, &opts);
    if let (Some(path), Some(cover)) = (&a.tour_out, &result.cover) {
        cover.write(path)?;
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&result)?);
    } else {
        println!(
            "{} {}: value {} lower bound {} ({}) in {:.2}s, {} rounds{}",
            result.objective,
            result.status,
            result.value.map_or("-".to_string(), |v| v.to_string()),
            result.lower_bound,
            result.lb_source,
            result.seconds,
            result.rounds,
            result
                .message
                .as_deref()
                .map(|m| format!(" — {m}"))
                .unwrap_or_default()
        );
    }
    let ok = result.valid && !matches!(result.status, exact::Status::Error);
    Ok(if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn bench_command(a: BenchArgs) -> Result<ExitCode> {
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
            Config::parse(&toml_text, &path.display().to_string())?
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
    Ok(ExitCode::SUCCESS)
}

fn solve_command(a: SolveArgs) -> Result<ExitCode> {
    let algo = algorithms::find(&a.algo).with_context(|| {
        format!(
            "unknown algorithm {:?}: expected one of {}",
            a.algo,
            algorithms::names().join(", ")
        )
    })?;
    let inst = Instance::read(&a.file)?;
    (algo.precondition)(&inst.region)
        .with_context(|| format!("{} does not apply to {}", algo.name, a.file.display()))?;
    let opts = Options {
        merge: a.merge,
        cutter: a.cutter,
        coverage4: a.coverage4,
    };
    let start = std::time::Instant::now();
    let solution = (algo.run)(&inst.region, &opts)?;
    let seconds = start.elapsed().as_secs_f64();
    // The merged tour by default; the cycle cover with --cycle-cover.
    let pick = |want_cc: bool| {
        solution
            .outputs
            .iter()
            .find(|o| (o.objective == algorithms::Objective::CcTurns) == want_cc)
    };
    let output = pick(a.cycle_cover)
        .or_else(|| solution.outputs.first())
        .context("the algorithm returned no output")?;
    let mut report = checker::check(&inst.region, &output.cover, output.objective.mode());
    // Lawn tours with free motion or the disk are lattice polygons: the lawn checker recounts
    // their Euclidean length (milli-units, rounded up) and the cells they must visit.
    if output.objective == algorithms::Objective::LawnLength
        && mowmill::lawn_check::is_milli(opts.cutter)
    {
        let lawn = mowmill::lawn_check::check_lawn(&inst.region, &output.cover, opts.cutter);
        report = checker::Report {
            valid: lawn.valid,
            length: lawn.length,
            turns: 0,
            cycles: lawn.cycles,
            max_coverage: 0,
            error: lawn.error,
            coverage: Vec::new(),
            violation: None,
        };
    }
    let valid = report.valid && (!output.objective.is_tour() || output.cover.is_tour());
    let value = match output.objective {
        algorithms::Objective::Length | algorithms::Objective::LawnLength => report.length,
        _ => report.turns,
    };
    let n = inst.region.len() as u64;
    let guarantees: Vec<serde_json::Value> = algo
        .guarantees
        .iter()
        .filter(|g| g.objective == output.objective && g.when.applies(&inst.region))
        .map(|g| {
            let measured = algorithms::Measured {
                value,
                length: report.length,
                max_coverage: u64::from(report.max_coverage),
            };
            let holds = g.decide(&measured, n, None, None);
            serde_json::json!({ "bound": g.to_string(), "factor": g.factor(), "holds": holds })
        })
        .collect();
    if let Some(path) = &a.tour_out {
        output.cover.write(path)?;
    }
    let mut json = serde_json::json!({
        "algorithm": algo.name,
        "objective": output.objective,
        "length": report.length,
        "turns": report.turns,
        "cycles": report.cycles,
        "max_coverage": report.max_coverage,
        "valid": valid,
        "error": report.error,
        "guarantee": guarantees,
        "n": n,
        "seconds": seconds,
    });
    for (k, v) in &solution.certificates {
        json[k] = serde_json::json!(v);
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        println!(
            "{}: {} {} | length {}, turns {}, {} cycle(s), max coverage {} | {}",
            algo.name,
            output.objective,
            value,
            report.length,
            report.turns,
            report.cycles,
            report.max_coverage,
            if valid {
                "valid".to_string()
            } else {
                format!("INVALID: {}", report.error.unwrap_or_default())
            }
        );
        for (k, v) in &solution.certificates {
            println!("  {k}: {v}");
        }
    }
    let violated = guarantees
        .iter()
        .any(|g| g["holds"] == serde_json::Value::Bool(false));
    Ok(if valid && !violated {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn tight_command(a: TightArgs) -> Result<ExitCode> {
    use mowmill::tight;
    let mut opts = tight::TightOptions {
        time_limit: a.time_limit,
        ..tight::TightOptions::default()
    };
    if a.quick {
        opts.donut_k = (2..=4).collect();
        opts.band_k = (1..=6).collect();
        opts.thin43_s = (0..=2).collect();
    }
    std::fs::create_dir_all(&a.out).map_err(|e| Error::io(&a.out, e))?;
    let started = std::time::Instant::now();
    let run = tight::run(&opts)?;
    let csv = a.out.join("tight.csv");
    tight::write_csv(&run, &csv)?;
    let md = tight::markdown(&run);
    let md_path = a.out.join("tight.md");
    std::fs::write(&md_path, &md).map_err(|e| Error::io(&md_path, e))?;
    println!("{md}");
    if !a.no_figures {
        tight::figures::draw_all(&run, &a.out)?;
    }
    let tight_rows: Vec<tight::TightRow> = run.rows().cloned().collect();
    let results = a.from.join("results.csv");
    if results.exists() {
        let rows = harness::rows::read_rows(&results)?;
        let table = tight::claims::table(&rows, &tight_rows);
        write_claims(&table, &a.from, &a.out)?;
    } else {
        eprintln!(
            "no {}: the claims table is skipped (run `mowmill bench --out {}` first)",
            results.display(),
            a.from.display()
        );
    }
    let bad = run.contradictions();
    eprintln!(
        "tight: {} rows in {:.1} s; wrote {} and {}",
        run.rows().count(),
        started.elapsed().as_secs_f64(),
        csv.display(),
        md_path.display()
    );
    for r in &bad {
        eprintln!(
            "CONTRADICTED: {} {} {}: claimed {}, measured {:?} ({})",
            r.family, r.member, r.quantity, r.claim, r.measured, r.how
        );
    }
    Ok(if bad.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Writes claims.csv and claims.md into `out`, prints the table; returns the contradictions.
fn write_claims(
    table: &[mowmill::tight::claims::ClaimRow],
    from: &Path,
    out: &Path,
) -> Result<usize> {
    use mowmill::tight::claims;
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    claims::write_csv(table, &out.join("claims.csv"))?;
    let md = claims::markdown(table, &from.display().to_string());
    let path = out.join("claims.md");
    std::fs::write(&path, &md).map_err(|e| Error::io(&path, e))?;
    println!("{md}");
    Ok(table.iter().filter(|c| c.verdict == "violated").count())
}

/// Exits 1 when any claim is violated (the table says whether by the paper's algorithm or by
/// our reading of it).
fn claims_command(
    from: &Path,
    tight: &Path,
    out: Option<&Path>,
    findings: Option<&Path>,
) -> Result<ExitCode> {
    use mowmill::tight::claims;
    let rows = harness::rows::read_rows(&from.join("results.csv"))?;
    let tight_rows = if tight.exists() {
        claims::read_tight(tight)?
    } else {
        eprintln!(
            "no {}: the tight-family column stays empty",
            tight.display()
        );
        Vec::new()
    };
    let table = claims::table(&rows, &tight_rows);
    let bad = match out {
        Some(out) => write_claims(&table, from, out)?,
        None => {
            println!("{}", claims::markdown(&table, &from.display().to_string()));
            table.iter().filter(|c| c.verdict == "violated").count()
        }
    };
    if let Some(dir) = findings {
        let files = claims::save_findings(&table, from, dir)?;
        if !files.is_empty() {
            eprintln!("saved {} finding file(s) in {}", files.len(), dir.display());
        }
    }
    Ok(if bad == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn gen_command(a: GenArgs) -> Result<ExitCode> {
    let params = GenParams {
        family: a.family,
        n: a.n,
        holes: a.holes,
        width: a.width,
        height: a.height,
        k: a.k,
        side: a.side,
        parts: a.parts,
        no_cut: a.no_cut,
        style: a.style,
        compactness: a.compactness,
        s: a.s,
        seed: a.seed,
    };
    let file = generate::generate(&params)?;
    file.write(&a.out)?;
    eprintln!(
        "wrote {}: {} pixels, {} holes",
        a.out.display(),
        file.region.len(),
        topology::holes(&file.region).count
    );
    Ok(ExitCode::SUCCESS)
}
