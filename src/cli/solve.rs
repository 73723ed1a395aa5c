//! `mowmill solve`: one registered algorithm on one instance, through the checker.

use anyhow::{Context, Result};
use clap::Args;
use mowmill::algorithms::{self, Cutter, Merge, Options};
use mowmill::checker;
use mowmill::instance::Instance;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct SolveArgs {
    /// Instance file (.grid or WKT).
    pub file: PathBuf,
    /// Algorithm name (see `mowmill algos`).
    #[arg(long)]
    pub algo: String,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Write the walk(s) of the printed output to this tour file.
    #[arg(long)]
    pub tour_out: Option<PathBuf>,
    /// Print the unmerged cycle cover instead of the merged tour.
    #[arg(long)]
    pub cycle_cover: bool,
    /// Merging strategy for cycle covers: naive or smart.
    #[arg(long, default_value = "smart", value_parser = parse_merge)]
    pub merge: Merge,
    /// Lawn-mowing cutter and motion: square, square-free or disk.
    #[arg(long, default_value = "square", value_parser = parse_cutter)]
    pub cutter: Cutter,
    /// Rewrite tours to cover each pixel at most 4 times (Theorem 5.6 of the turn-cost paper).
    #[arg(long)]
    coverage4: bool,
}

pub fn parse_merge(s: &str) -> Result<Merge, String> {
    match s {
        "naive" => Ok(Merge::Naive),
        "smart" => Ok(Merge::Smart),
        _ => Err(format!("expected naive or smart, got {s:?}")),
    }
}

pub fn parse_cutter(s: &str) -> Result<Cutter, String> {
    match s {
        "square" => Ok(Cutter::Square),
        "square-free" => Ok(Cutter::SquareFree),
        "disk" => Ok(Cutter::Disk),
        _ => Err(format!("expected square, square-free or disk, got {s:?}")),
    }
}

pub fn solve_command(a: SolveArgs) -> Result<ExitCode> {
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
