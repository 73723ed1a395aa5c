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

#[derive(Args, Clone)]
pub struct HuntArgs {
    /// The algorithm to hunt.
    #[arg(
        long,
        required_unless_present_any = ["command", "suite"],
        conflicts_with = "command",
        value_parser = super::one_of(algorithms::names())
    )]
    pub algo: Option<String>,
    /// Run a hunt suite (TOML: `evaluations`, `seed` or `seeds = [..]`, optionally
    /// `strategies = ["anneal", "random"]`, and one `[[hunt]]` table per hunt with `algo` and
    /// optionally `objective`, `family`, `min_n`, `max_n`, `against`) into `--out`: one folder
    /// per hunt (`<hunt>/<strategy>-seed<S>/` when there are several seeds or strategies) and
    /// `summary.csv`.
    #[arg(long, conflicts_with_all = ["algo", "command", "start"])]
    pub suite: Option<PathBuf>,
    /// Hunt an outside program instead (see `solve --command`).
    #[arg(long)]
    pub command: Option<String>,
    /// Memory (address-space) limit of the --command program: "512M", "4 GiB", bytes or
    /// "unlimited" (default 4 GiB; docs/outside.md).
    #[arg(long, requires = "command")]
    pub memory_limit: Option<String>,
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
    #[arg(long, value_parser = super::bench::parse_jobs)]
    pub jobs: Option<usize>,
    /// Output directory. Default: results/hunt-<algorithm>-<UTC stamp>/ (git-ignored).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Regions to start from (.grid, WKT, .poly or .gg/.csv), one chain each.
    #[arg(long, num_args = 1..)]
    pub start: Vec<PathBuf>,
    /// Divide by the exact optimum (default where an exact objective exists), by the best
    /// cheap lower bound (for larger N; over-estimates the ratio), or by the best checked walk
    /// known (`best`: every registered algorithm's walk that carries the objective and the
    /// exact solver's incumbent; OPT <= best, so a ratio above a factor is a proven violation).
    #[arg(long, value_parser = ["opt", "bound", "best"])]
    pub against: Option<String>,
    /// How many distinct worst instances to save.
    #[arg(long, default_value_t = 5)]
    pub keep: usize,
    /// Simulated-annealing chains (each proposal round evaluates one candidate per chain).
    /// Two: over 1000 evaluations, two longer chains found worse ratios than four shorter
    /// ones (docs/hunt.md).
    #[arg(long, default_value_t = 2)]
    pub chains: usize,
    /// Evaluations without improvement after which a chain restarts.
    #[arg(long, default_value_t = 150)]
    pub patience: usize,
    /// Seconds per exact solve (default 20; 30 with `--against best`, where the incumbent
    /// is an upper bound whether or not it is proven).
    #[arg(long, allow_negative_numbers = true)]
    pub exact_time_limit: Option<f64>,
    /// With `--against bound|best`: no exact solve on candidates above this many pixels.
    #[arg(long, default_value_t = 2000)]
    pub exact_max_n: usize,
    /// `anneal` (the search) or `random` (independent generated regions, the baseline a
    /// search must beat).
    #[arg(long, default_value = "anneal", value_parser = STRATEGIES)]
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

/// The values of `--strategy` and of a suite's `strategies`.
const STRATEGIES: [&str; 2] = ["anneal", "random"];

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

/// What one hunt found, for the suite's `summary.csv` (a contract: the column order).
#[derive(serde::Serialize)]
pub struct Done {
    pub algorithm: String,
    pub objective: String,
    pub family: String,
    pub min_n: usize,
    pub max_n: usize,
    pub evaluations: usize,
    pub seed: u64,
    pub against: String,
    pub worst_ratio: Option<f64>,
    pub worst_value: Option<u64>,
    pub worst_reference: Option<u64>,
    pub worst_n: Option<usize>,
    /// The worst instance's file, relative to the suite's folder.
    pub worst_instance: String,
    pub findings: usize,
    /// `anneal` or `random` (appended: the columns before it keep their order).
    pub strategy: String,
}

/// One `[[hunt]]` table of a suite.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SuiteHunt {
    algo: String,
    objective: Option<String>,
    family: Option<String>,
    min_n: Option<usize>,
    max_n: Option<usize>,
    against: Option<String>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Suite {
    evaluations: usize,
    /// One seed, or `seeds` for several (every hunt runs once per seed).
    seed: Option<u64>,
    seeds: Option<Vec<u64>>,
    /// `anneal` and/or `random` (default: `--strategy`): every hunt runs once per strategy, so
    /// that a suite can compare the search with random sampling on equal terms.
    strategies: Option<Vec<String>>,
    hunt: Vec<SuiteHunt>,
}

pub fn hunt_command(a: HuntArgs) -> Result<ExitCode> {
    let Some(path) = a.suite.clone() else {
        return Ok(run_one(&a)?.1);
    };
    let file = path.display().to_string();
    let text = mowmill::input::read_text(&path, "a hunt suite config")?;
    let suite: Suite = toml::from_str(&text).map_err(|e| {
        let (line, column) =
            mowmill::harness::config::line_column(&text, e.span().map_or(0, |s| s.start));
        mowmill::Error::parse(&file, line, column, e.message().to_string())
    })?;
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("results/hunt"));
    let seeds = match (&suite.seeds, suite.seed) {
        (Some(seeds), None) if !seeds.is_empty() => seeds.clone(),
        (None, Some(seed)) => vec![seed],
        _ => {
            return Err(mowmill::Error::invalid(format!(
                "{file}: expected either `seed = S` or a non-empty `seeds = [S, ...]`"
            ))
            .into());
        }
    };
    let strategies = suite
        .strategies
        .clone()
        .unwrap_or_else(|| vec![a.strategy.clone()]);
    if strategies.is_empty() || strategies.iter().any(|s| !STRATEGIES.contains(&s.as_str())) {
        return Err(mowmill::Error::invalid(format!(
            "{file}: strategies = {strategies:?}: expected a non-empty list of {STRATEGIES:?}"
        ))
        .into());
    }
    // One seed and one strategy keep the folder per hunt that earlier suites wrote.
    let nested = seeds.len() > 1 || strategies.len() > 1;
    // Every table is checked before the first hunt runs.
    let mut runs = Vec::new();
    for (k, h) in suite.hunt.iter().enumerate() {
        let mut one = a.clone();
        one.suite = None;
        one.algo = Some(h.algo.clone());
        if algorithms::find(&h.algo).is_none() {
            return Err(mowmill::Error::invalid(format!(
                "{file}: hunt[{k}].algo: unknown algorithm {:?}: expected one of {}",
                h.algo,
                algorithms::names().join(", ")
            ))
            .into());
        }
        one.objective = h.objective.clone().or(a.objective.clone());
        one.family =
            match &h.family {
                Some(f) => Some(f.parse().map_err(|e| {
                    mowmill::Error::invalid(format!("{file}: hunt[{k}].family: {e}"))
                })?),
                None => a.family,
            };
        one.min_n = h.min_n.unwrap_or(a.min_n);
        one.max_n = h.max_n.unwrap_or(a.max_n);
        one.against = h.against.clone().or(a.against.clone());
        one.evaluations = Some(suite.evaluations);
        one.budget = None;
        let tag = match &one.objective {
            Some(o) => format!("{}-{o}", h.algo),
            None => h.algo.clone(),
        };
        for strategy in &strategies {
            for &seed in &seeds {
                let mut run = one.clone();
                run.seed = seed;
                run.strategy = strategy.clone();
                run.out = Some(if nested {
                    out.join(&tag).join(format!("{strategy}-seed{seed}"))
                } else {
                    out.join(&tag)
                });
                runs.push(run);
            }
        }
    }
    let mut summary = Vec::new();
    let mut code = ExitCode::SUCCESS;
    for one in &runs {
        let (done, c) = run_one(one)?;
        if c != ExitCode::SUCCESS {
            code = c;
        }
        summary.push(done);
    }
    let csv_path = out.join("summary.csv");
    let mut w = csv::Writer::from_path(&csv_path)
        .map_err(|e| mowmill::Error::invalid(format!("{}: {e}", csv_path.display())))?;
    for mut d in summary {
        if let Some(rest) = d.worst_instance.strip_prefix(&out.display().to_string()) {
            d.worst_instance = rest.trim_start_matches('/').to_string();
        }
        w.serialize(d)?;
    }
    w.flush()?;
    println!("hunt suite: wrote {}", csv_path.display());
    Ok(code)
}

/// Runs one hunt: its summary line and exit code.
fn run_one(a: &HuntArgs) -> Result<(Done, ExitCode)> {
    let bad = |m: String| -> anyhow::Error { mowmill::Error::invalid(m).into() };
    if a.min_n == 0 || a.min_n > a.max_n || a.max_n > 100_000 {
        return Err(bad(format!(
            "--min-n {} --max-n {}: expected 1 <= min-n <= max-n <= 100000",
            a.min_n, a.max_n
        )));
    }
    let exact_time_limit = a
        .exact_time_limit
        .unwrap_or(if a.against.as_deref() == Some("best") {
            30.0
        } else {
            20.0
        });
    super::check_seconds("--exact-time-limit", exact_time_limit)?;
    if let Some(b) = a.budget {
        super::check_seconds("--budget", b)?;
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
                memory_limit: a
                    .memory_limit
                    .as_ref()
                    .map(|m| mowmill::outside::MemoryLimit::Text(m.clone())),
                time_limit: exact_time_limit,
            };
            outside = OutsideAlgorithm::from_spec(&spec, std::path::Path::new(".")).map_err(
                |e| match e.strip_prefix("memory_limit: ") {
                    Some(m) => mowmill::Error::invalid(format!("--memory-limit {m}")),
                    None => mowmill::Error::invalid(format!("--command: {e}")),
                },
            )?;
            (Subject::Outside(&outside), "outside".to_string())
        }
        (None, None) => unreachable!("clap requires --algo or --command"),
    };
    let objective = subject.pick_objective(objective)?;
    let against = match (a.against.as_deref(), objective) {
        (Some("bound"), _) | (None, Objective::LawnLength) => Against::Bound,
        (Some("best"), Objective::LawnLength) => {
            return Err(bad(
                "--against best: lawn-length has no exact solver and the registered lawn \
                 tours are the algorithms themselves; use --against bound"
                    .into(),
            ));
        }
        (Some("best"), _) => Against::Best,
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
            ..Options::default()
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
        exact_time_limit,
        exact_max_n: a.exact_max_n,
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
        match against {
            Against::Bound => " (an over-estimate of the ratio to OPT)",
            Against::Best =>
                " (the best checked walk known: an under-estimate of the ratio to OPT)",
            Against::Opt => "",
        }
    );
    // The files but the manifest are written at every checkpoint: a killed hunt keeps them, and
    // a missing manifest says it did not end (so an earlier run's manifest goes first).
    match std::fs::remove_file(out.join("manifest.json")) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            return Err(mowmill::Error::io(&out.join("manifest.json"), e).into());
        }
        _ => {}
    }
    let report = pool.install(|| {
        hunt::hunt(
            subject,
            &opts,
            |line| eprintln!("hunt: {name}: {line}"),
            |so_far| hunt::output::write_all(&out, so_far, &name, &opts),
        )
    })?;
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
        "exact_max_n": opts.exact_max_n,
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
    let done = Done {
        algorithm: name.clone(),
        objective: objective.name().to_string(),
        family: opts.family.name().to_string(),
        min_n: opts.min_n,
        max_n: opts.max_n,
        evaluations: report.records.len(),
        seed: opts.seed,
        against: against.to_string(),
        worst_ratio: best.map(|f| (f.ratio * 1e6).round() / 1e6),
        worst_value: best.map(|f| f.value),
        worst_reference: best.and_then(|f| f.reference),
        worst_n: best.map(|f| f.region.len()),
        worst_instance: if best.is_some() {
            out.join("worst").join("rank-01.grid").display().to_string()
        } else {
            String::new()
        },
        findings: report.findings.len(),
        strategy: a.strategy.clone(),
    };
    let code = if report.findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    };
    Ok((done, code))
}

fn evaluate_options(o: &Options) -> serde_json::Value {
    serde_json::json!({
        "merge": o.merge.to_string(),
        "cutter": o.cutter.to_string(),
        "coverage4": o.coverage4,
    })
}
