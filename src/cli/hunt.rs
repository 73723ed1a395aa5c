//! `mowmill hunt`: search for the instances where an algorithm is worst (see
//! [`mowmill::hunt`]).

use anyhow::Result;
use clap::Args;
use mowmill::algorithms::{self, Objective, Options};
use mowmill::evaluate::Subject;
use mowmill::generate::Family;
use mowmill::hunt::{self, Against, HuntOptions, Stop};
use mowmill::instance::Instance;
use mowmill::outside::{OutsideAlgorithm, OutsideSpec};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct HuntArgs {
    /// The algorithm to hunt.
    #[arg(
        long,
        required_unless_present = "command",
        conflicts_with = "command",
        value_parser = super::one_of(algorithms::names())
    )]
    pub algo: Option<String>,
    /// Hunt an outside program instead (see `solve --command`).
    #[arg(long)]
    pub command: Option<String>,
    /// The objective whose ratio is maximized. Default: the algorithm's tour.
    #[arg(long, value_parser = super::one_of(Objective::ALL.map(Objective::name)))]
    pub objective: Option<String>,
    /// The family whose constraint every candidate keeps (connected, holes, thin, boundary
    /// only) and whose generator gives starting regions. Default: from the algorithm
    /// (thin-* thin, boundary-cc boundary, holes1325 random-holed, lawn-* lawn-scattered,
    /// else random-simple).
    #[arg(long)]
    pub family: Option<Family>,
    /// Smallest number of pixels of a candidate.
    #[arg(long, default_value_t = 8)]
    pub min_n: usize,
    /// Largest number of pixels of a candidate.
    #[arg(long, default_value_t = 40)]
    pub max_n: usize,
    /// Stop after this many seconds (not reproducible).
    #[arg(long, conflicts_with = "evaluations")]
    pub budget: Option<f64>,
    /// Stop after this many evaluations (reproducible with --seed). Default 400.
    #[arg(long)]
    pub evaluations: Option<usize>,
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Parallel jobs (default: all cores). The result does not depend on it.
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Output directory. Default: results/hunt-<algorithm>-<UTC stamp>/ (git-ignored).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Regions to start from (.grid or WKT), one chain each.
    #[arg(long, num_args = 1..)]
    pub start: Vec<PathBuf>,
    /// Divide by the exact optimum (default where an exact objective exists) or by the best
    /// cheap lower bound (for larger N; over-estimates the ratio).
    #[arg(long, value_parser = ["opt", "bound"])]
    pub against: Option<String>,
    /// How many distinct worst instances to save.
    #[arg(long, default_value_t = 5)]
    pub keep: usize,
    /// Simulated-annealing chains (each proposal round evaluates one candidate per chain).
    #[arg(long, default_value_t = 4)]
    pub chains: usize,
    /// Evaluations without improvement after which a chain restarts.
    #[arg(long, default_value_t = 150)]
    pub patience: usize,
    /// Seconds per exact solve.
    #[arg(long, default_value_t = 20.0, allow_negative_numbers = true)]
    pub exact_time_limit: f64,
    /// `anneal` (the search) or `random` (independent generated regions, the baseline a
    /// search must beat).
    #[arg(long, default_value = "anneal", value_parser = ["anneal", "random"])]
    pub strategy: String,
    /// Merge strategy of cycle covers.
    #[arg(long, default_value = "smart", value_parser = algorithms::Merge::NAMES)]
    pub merge: String,
    /// Lawn cutter.
    #[arg(long, default_value = "square", value_parser = algorithms::Cutter::NAMES)]
    pub cutter: String,
    /// Rewrite tours to cover each pixel at most 4 times.
    #[arg(long)]
    pub coverage4: bool,
}

/// The family a hunt of `algo` searches by default: the one its precondition is made for.
fn default_family(algo: &str) -> Family {
    match algo {
        a if a.starts_with("thin-") => Family::Thin,
        "boundary-cc" => Family::Boundary,
        "holes1325" => Family::RandomHoled,
        a if a.starts_with("lawn-") => Family::LawnScattered,
        _ => Family::RandomSimple,
    }
}

pub fn hunt_command(a: HuntArgs) -> Result<ExitCode> {
    let bad = |m: String| -> anyhow::Error { mowmill::Error::invalid(m).into() };
    if a.min_n == 0 || a.min_n > a.max_n || a.max_n > 100_000 {
        return Err(bad(format!(
            "--min-n {} --max-n {}: expected 1 <= min-n <= max-n <= 100000",
            a.min_n, a.max_n
        )));
    }
    if !(a.exact_time_limit.is_finite() && a.exact_time_limit > 0.0) {
        return Err(bad(format!(
            "--exact-time-limit {}: expected a positive number of seconds",
            a.exact_time_limit
        )));
    }
    if let Some(b) = a.budget
        && !(b.is_finite() && b > 0.0)
    {
        return Err(bad(format!(
            "--budget {b}: expected a positive number of seconds"
        )));
    }
    if a.evaluations == Some(0) || a.keep == 0 || a.chains == 0 || a.chains > 256 {
        return Err(bad(
            "--evaluations, --keep and --chains must be positive (--chains at most 256)".into(),
        ));
    }
    let objective: Option<Objective> = a
        .objective
        .as_deref()
        .map(str::parse)
        .transpose()
        .map_err(mowmill::Error::Invalid)?;
    let outside;
    let (subject, name) = match (&a.algo, &a.command) {
        (Some(n), _) => (Subject::Registered(hunt::registered(n)?), n.clone()),
        (None, Some(c)) => {
            let spec = OutsideSpec {
                name: "outside".into(),
                command: super::solve::split_command(c),
                objectives: vec![objective.unwrap_or(Objective::Length).to_string()],
                guarantee: None,
                time_limit: a.exact_time_limit,
            };
            outside = OutsideAlgorithm::from_spec(&spec, std::path::Path::new("."))
                .map_err(|e| mowmill::Error::invalid(format!("--command: {e}")))?;
            (Subject::Outside(&outside), "outside".to_string())
        }
        (None, None) => unreachable!("clap requires --algo or --command"),
    };
    let objective = match objective {
        Some(o) if subject.objectives().contains(&o) => o,
        Some(o) => {
            return Err(bad(format!(
                "{name} has no {o} output (it has {})",
                subject
                    .objectives()
                    .iter()
                    .map(|o| o.name())
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
        None => subject
            .objectives()
            .iter()
            .copied()
            .find(|o| o.is_tour())
            .unwrap_or(subject.objectives()[0]),
    };
    let against = match (a.against.as_deref(), objective) {
        (Some("bound"), _) | (None, Objective::LawnLength) => Against::Bound,
        (Some(_), Objective::LawnLength) => {
            return Err(bad(
                "--against opt: lawn-length has no exact solver; use --against bound".into(),
            ));
        }
        _ => Against::Opt,
    };
    let mut starts = Vec::new();
    for f in &a.start {
        starts.push(Instance::read(f)?.region);
    }
    let opts = HuntOptions {
        objective,
        options: Options {
            merge: a.merge.parse().map_err(mowmill::Error::Invalid)?,
            cutter: a.cutter.parse().map_err(mowmill::Error::Invalid)?,
            coverage4: a.coverage4,
        },
        family: a.family.unwrap_or_else(|| default_family(&name)),
        min_n: a.min_n,
        max_n: a.max_n,
        stop: match a.budget {
            Some(s) => Stop::Seconds(s),
            None => Stop::Evaluations(a.evaluations.unwrap_or(400)),
        },
        seed: a.seed,
        against,
        keep: a.keep,
        starts,
        chains: a.chains,
        patience: a.patience,
        exact_time_limit: a.exact_time_limit,
        strategy: if a.strategy == "random" {
            hunt::Strategy::Random
        } else {
            hunt::Strategy::Anneal
        },
    };
    let out = a.out.clone().unwrap_or_else(|| {
        let stamp = mowmill::harness::manifest::now().replace([':', '-'], "");
        PathBuf::from("results").join(format!("hunt-{name}-{stamp}"))
    });
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(a.jobs.unwrap_or(0))
        .build()
        .map_err(|e| mowmill::Error::invalid(format!("--jobs: {e}")))?;
    let started = mowmill::harness::manifest::now();
    eprintln!(
        "hunt: {name} ({objective}) on {} regions of {}..={} pixels, ratio against {against}{}",
        opts.family.name(),
        opts.min_n,
        opts.max_n,
        if against == Against::Bound {
            " (an over-estimate of the ratio to OPT)"
        } else {
            ""
        }
    );
    let report = pool.install(|| hunt::hunt(subject, &opts, |line| eprintln!("hunt: {line}")))?;
    hunt::output::write_all(&out, &report, &name, &opts)?;
    let best = report.worst.first();
    let manifest = serde_json::json!({
        "algorithm": name,
        "objective": objective.name(),
        "family": opts.family.name(),
        "min_n": opts.min_n,
        "max_n": opts.max_n,
        "against": against.to_string(),
        "stop": match opts.stop {
            Stop::Evaluations(k) => format!("evaluations {k}"),
            Stop::Seconds(s) => format!("budget {s} s"),
        },
        "seed": opts.seed,
        "chains": opts.chains,
        "strategy": a.strategy,
        "patience": opts.patience,
        "exact_time_limit": opts.exact_time_limit,
        "options": evaluate_options(&opts.options),
        "evaluations": report.records.len(),
        "exact_solves": report.exact_solves,
        "exact_cache_hits": report.cache_hits,
        "worst_ratio": best.map(|f| f.ratio),
        "worst_n": best.map(|f| f.region.len()),
        "findings": report.findings.len(),
        "mowmill_version": env!("CARGO_PKG_VERSION"),
        "highs_version": mowmill::harness::manifest::highs_version(),
        "start": started,
        "end": mowmill::harness::manifest::now(),
        "seconds": report.seconds,
        "command_line": std::env::args().collect::<Vec<_>>().join(" "),
    });
    let path = out.join("manifest.json");
    std::fs::write(&path, serde_json::to_string_pretty(&manifest)? + "\n")
        .map_err(|e| mowmill::Error::io(&path, e))?;
    match best {
        Some(f) => println!(
            "{name} ({objective}): worst ratio {:.4} against {against} (value {} / {}) at N = {}, \
             after {} evaluations ({} exact solves, {} cache hits) in {:.1} s",
            f.ratio,
            f.value,
            f.reference.map_or("-".into(), |r| r.to_string()),
            f.region.len(),
            report.records.len(),
            report.exact_solves,
            report.cache_hits,
            report.seconds
        ),
        None => println!(
            "{name} ({objective}): no ratio decided in {} evaluations",
            report.records.len()
        ),
    }
    println!(
        "{} finding(s); wrote {} (hunt.csv, worst/, findings/, best.png, manifest.json)",
        report.findings.len(),
        out.display()
    );
    Ok(if report.findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn evaluate_options(o: &Options) -> serde_json::Value {
    serde_json::json!({
        "merge": o.merge.to_string(),
        "cutter": o.cutter.to_string(),
        "coverage4": o.coverage4,
    })
}
