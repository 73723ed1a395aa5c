//! `mowmill exact`: an exact MILP optimum with a proven bound.

use anyhow::Result;
use clap::Args;
use mowmill::exact;
use mowmill::instance::Instance;
use mowmill::topology;
use mowmill::tour::CycleCover;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct ExactArgs {
    /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list).
    pub file: PathBuf,
    /// The exact objective (`turns` also accepted as `tour-turns`; `weighted` needs
    /// --turn-cost).
    #[arg(long, value_parser = super::one_of(exact::Objective::EXACT_NAMES))]
    pub objective: String,
    /// Weight C of turns for `weighted` (length + C * turns).
    #[arg(long)]
    pub turn_cost: Option<u32>,
    /// Wall-clock limit in seconds (a positive number); past it the best walk found is
    /// reported with status time_limit and its proven lower bound.
    #[arg(
        long,
        default_value_t = DEFAULT_TIME_LIMIT,
        conflicts_with = "no_time_limit",
        allow_negative_numbers = true
    )]
    pub time_limit: f64,
    /// Run until the optimum is proven, however long that takes.
    #[arg(long)]
    pub no_time_limit: bool,
    /// HiGHS threads for this solve.
    #[arg(long, default_value_t = 1, value_parser = super::parse_threads)]
    pub threads: usize,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Write the optimal (or best) walk(s) to this tour file.
    #[arg(long)]
    pub tour_out: Option<PathBuf>,
    /// Show the solver's log.
    #[arg(long)]
    pub verbose: bool,
    /// Turn objectives: visit every pixel at most this many times (the optimum under this
    /// cap; Theorem 5.6 of the turn-cost paper says a cap of 4 costs no turns).
    #[arg(long)]
    pub max_coverage: Option<u32>,
    /// Do not start from the best tour (or cycle cover) of the registered approximation
    /// algorithms.
    #[arg(long, conflicts_with = "start")]
    pub no_warm_start: bool,
    /// The primal side only (the search of the heuristic `lp-lns`: LP relaxation, then a
    /// node-limited neighbourhood search from the start), no proof: the status is optimal
    /// only when the walk meets the proven bound.
    #[arg(long)]
    pub heuristic: bool,
    /// Start from this tour file (a tour or cycle cover, as `--tour-out` writes); used when
    /// the checker accepts it for the objective.
    #[arg(long)]
    pub start: Option<PathBuf>,
}

/// `exact`'s default wall-clock limit: 5 minutes, long enough for every instance of the shipped
/// suites (their largest optimum is proven in under a minute), short enough that a too-large
/// instance answers with a bound instead of running for hours.
pub const DEFAULT_TIME_LIMIT: f64 = 300.0;

pub fn exact_command(a: ExactArgs) -> Result<ExitCode> {
    super::check_seconds("--time-limit", a.time_limit)?;
    let objective =
        exact::Objective::parse(&a.objective, a.turn_cost).map_err(mowmill::Error::Invalid)?;
    if super::FileKind::of(&a.file) == super::FileKind::Discrete {
        let opts = mowmill::discrete::exact::DiscreteOptions {
            time_limit: (!a.no_time_limit).then_some(a.time_limit),
            threads: a.threads,
            verbose: a.verbose,
        };
        return super::discrete::exact(&a.file, objective, opts, a.tour_out.as_deref(), a.json);
    }
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
        time_limit: (!a.no_time_limit).then_some(a.time_limit),
        threads: a.threads,
        verbose: a.verbose,
        warm_start: a.start.as_deref().map(CycleCover::read).transpose()?,
        max_coverage: a.max_coverage,
        starts: (!a.no_warm_start)
            .then_some(mowmill::warm_start::from_registry as mowmill::exact::StartFn),
        heuristic: a.heuristic,
    };
    let result = exact::solve(&inst.region, objective, &opts);
    if let (Some(path), Some(cover)) = (&a.tour_out, &result.cover) {
        cover.write(path)?;
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&result)?);
    } else {
        super::print_exact_line(
            &result.objective.to_string(),
            &result.status.to_string(),
            result.value,
            result.lower_bound,
            &result.lb_source,
            result.seconds,
            result.rounds,
            result.message.as_deref(),
        );
    }
    let ok = result.valid && !matches!(result.status, exact::Status::Error);
    Ok(if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
