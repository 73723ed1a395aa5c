//! `mowmill solve`: one algorithm (registered, or an outside program with `--command`) on one
//! instance, through the one evaluation pipeline: checked walk, bound, guarantee verdicts.

use anyhow::{Context, Result, bail};
use clap::Args;
use mowmill::algorithms::{self, Cutter, Merge, Objective, Options};
use mowmill::evaluate::{self, Checked, Known, Reference, Subject};
use mowmill::exact;
use mowmill::instance::Instance;
use mowmill::model::InstanceModel;
use mowmill::outside::{OutsideAlgorithm, OutsideSpec};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct SolveArgs {
    /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list).
    pub file: PathBuf,
    /// Algorithm name (`mowmill algos` lists their objectives and guarantees; `corollary4`
    /// mills a `.wkt` polygon with non-integral coordinates, docs/ortho.md).
    #[arg(
        long,
        required_unless_present = "command",
        conflicts_with = "command",
        value_parser = super::one_of(algorithms::names())
    )]
    pub algo: Option<String>,
    /// Run an outside program instead, e.g. "python3 examples/outside_greedy.py {instance}
    /// {tour_out}" (split on spaces; quotes group words). See README, "Outside algorithms".
    #[arg(long)]
    pub command: Option<String>,
    /// Memory (address-space) limit of the --command program: "512M", "4 GiB", bytes or
    /// "unlimited" (default 4 GiB; docs/outside.md).
    #[arg(long, requires = "command")]
    pub memory_limit: Option<String>,
    /// The objective to report (`turns` also accepted as `tour-turns`; `weighted` and
    /// `weighted-cc`, length + C * turns of the tour or of the cycle cover, need --turn-cost).
    /// Default: the algorithm's tour (its first objective for outside programs).
    #[arg(long, value_parser = super::one_of(Objective::NAMES))]
    pub objective: Option<String>,
    /// Weight C of turns for `weighted` and `weighted-cc` (length + C * turns).
    #[arg(long)]
    pub turn_cost: Option<u32>,
    /// Also solve exactly (MILP) to decide guarantees against the proven optimum.
    #[arg(long)]
    pub exact: bool,
    /// Time limit in seconds of the exact solve (--exact) and of an outside program (default
    /// 60); refused where neither runs.
    #[arg(long, allow_negative_numbers = true)]
    pub time_limit: Option<f64>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also print where the time went: parse, precondition, run, check (the JSON has it always,
    /// as `phases`).
    #[arg(long)]
    pub timings: bool,
    /// Write the walk(s) of the printed output to this tour file.
    #[arg(long)]
    pub tour_out: Option<PathBuf>,
    /// Print the unmerged cycle cover instead of the merged tour (same as --objective cc-turns).
    #[arg(long)]
    pub cycle_cover: bool,
    /// Merging strategy for cycle covers (default smart); refused for an algorithm that merges
    /// no cycle cover.
    #[arg(long, value_parser = Merge::NAMES)]
    pub merge: Option<String>,
    /// Lawn-mowing cutter and motion (default square); refused for an algorithm that computes
    /// no lawn tour.
    #[arg(long, value_parser = Cutter::NAMES)]
    pub cutter: Option<String>,
    /// Rewrite tours to cover each pixel at most 4 times (Theorem 5.6 of the turn-cost paper).
    #[arg(long)]
    pub coverage4: bool,
}

/// Splits a command line into words by POSIX shell rules (the `shlex` crate): blanks separate
/// words, single or double quotes group them, a backslash escapes the next character and a word
/// starting with `#` begins a comment. A quote left open closes at the end of the line, as it
/// always has here (shlex alone would refuse the line).
pub fn split_command(s: &str) -> Vec<String> {
    shlex::split(s)
        .or_else(|| shlex::split(&format!("{s}\"")))
        .or_else(|| shlex::split(&format!("{s}'")))
        .unwrap_or_default()
}

/// The outside program of `--command` as an algorithm with one objective (no claim).
fn outside_program(
    a: &SolveArgs,
    command: &str,
    objective: Objective,
    time_limit: f64,
) -> Result<OutsideAlgorithm> {
    let spec = OutsideSpec {
        name: "outside".into(),
        command: split_command(command),
        objectives: vec![objective.to_string()],
        guarantee: None,
        memory_limit: a
            .memory_limit
            .as_ref()
            .map(|m| mowmill::outside::MemoryLimit::Text(m.clone())),
        time_limit,
    };
    Ok(
        OutsideAlgorithm::from_spec(&spec, std::path::Path::new(".")).map_err(|e| {
            match e.strip_prefix("memory_limit: ") {
                Some(m) => mowmill::Error::invalid(format!("--memory-limit {m}")),
                None => mowmill::Error::invalid(format!("--command: {e}")),
            }
        })?,
    )
}

/// The default of `--time-limit`, in seconds.
const DEFAULT_TIME_LIMIT: f64 = 60.0;

/// Refuses, with exit 2, an option given on the command line that `model` would ignore (only
/// the options in `applies` do anything there): an ignored option is a run the user did not
/// ask for, never a silent default.
fn refuse_ignored(a: &SolveArgs, model: &str, applies: &[&str]) -> Result<()> {
    let given = [
        ("--exact", a.exact),
        ("--time-limit", a.time_limit.is_some()),
        ("--merge", a.merge.is_some()),
        ("--cutter", a.cutter.is_some()),
        ("--coverage4", a.coverage4),
        ("--turn-cost", a.turn_cost.is_some()),
        ("--objective", a.objective.is_some()),
        ("--cycle-cover", a.cycle_cover),
        ("--timings", a.timings),
    ];
    if let Some((option, _)) = given.iter().find(|(o, g)| *g && !applies.contains(o)) {
        let expected = if applies.is_empty() {
            "none of the solve options".to_string()
        } else {
            applies.join(", ")
        };
        bail!(mowmill::Error::invalid(format!(
            "{option} does not apply to {model}; expected only {expected} there"
        )));
    }
    Ok(())
}

pub fn solve_command(a: SolveArgs) -> Result<ExitCode> {
    if let Some(t) = a.time_limit {
        super::check_seconds("--time-limit", t)?;
    }
    let time_limit = a.time_limit.unwrap_or(DEFAULT_TIME_LIMIT);
    let wanted: Option<Objective> = match (&a.objective, a.cycle_cover) {
        (Some(o), _) => Some(Objective::parse(o, a.turn_cost).map_err(mowmill::Error::Invalid)?),
        (None, true) => Some(Objective::CcTurns),
        (None, false) => None,
    };
    if a.turn_cost.is_some() && a.objective.is_none() {
        bail!(mowmill::Error::invalid(
            "--turn-cost applies to --objective weighted or weighted-cc"
        ));
    }
    let kind = super::FileKind::of(&a.file);
    if kind == super::FileKind::Discrete {
        let model = format!("discrete instances ({})", a.file.display());
        let Some(algo) = &a.algo else {
            // An outside program on a discrete instance: the one pipeline, with the discrete
            // checker's recount and the greedy rooks' bound; --objective (or --cycle-cover),
            // --time-limit and --memory-limit apply to it.
            refuse_ignored(
                &a,
                &model,
                &["--objective", "--cycle-cover", "--time-limit", "--timings"],
            )?;
            let objective = wanted.unwrap_or(Objective::Length);
            if !matches!(
                objective,
                Objective::Length | Objective::Turns | Objective::CcTurns
            ) {
                bail!(mowmill::Error::invalid(format!(
                    "--objective {objective} does not apply to {model}; expected length, \
                     turns or cc-turns"
                )));
            }
            let command = a
                .command
                .as_deref()
                .expect("clap requires --algo or --command");
            let outside = outside_program(&a, command, objective, time_limit)?;
            let inst = mowmill::discrete::generate::read(&a.file)?;
            let subject = Subject::Outside(&outside);
            let eval = evaluate::evaluate(
                subject,
                &inst,
                &Options::default(),
                &[objective],
                &Reference::default(),
            );
            let phases = Phases {
                parse: None,
                precondition: None,
                run: eval.seconds,
                check: eval.check_seconds,
            };
            return report::<mowmill::discrete::Discrete>(
                &a,
                subject,
                &eval,
                objective,
                inst.len() as u64,
                (None, phases),
            );
        };
        let mut applies = vec!["--objective", "--cycle-cover", "--merge", "--exact"];
        if a.exact {
            applies.push("--time-limit");
        }
        refuse_ignored(&a, &model, &applies)?;
        if let Some(o) = wanted.filter(|o| !matches!(o, Objective::Turns | Objective::CcTurns)) {
            bail!(mowmill::Error::invalid(format!(
                "--objective {o} does not apply to {model}; expected turns or cc-turns"
            )));
        }
        let mut options = Options::default();
        if let Some(m) = &a.merge {
            options.merge = m.parse().map_err(mowmill::Error::Invalid)?;
        }
        return super::discrete::solve(
            &a.file,
            algo,
            &options,
            a.exact.then_some(time_limit),
            matches!(wanted, Some(Objective::CcTurns)),
            (a.tour_out.as_deref(), a.json),
        );
    }
    if kind == super::FileKind::Ortho {
        let model = format!(
            "polygons with non-integral coordinates ({})",
            a.file.display()
        );
        refuse_ignored(&a, &model, &[])?;
        if a.command.is_some() {
            // Their walks have rational coordinates, which no tour file of an outside program
            // carries.
            bail!(mowmill::Error::invalid(format!(
                "--command does not apply to {model}: outside programs run on grid regions and \
                 discrete instances"
            )));
        }
        let algo = a.algo.as_deref().unwrap_or("corollary4");
        return super::ortho::solve(&a.file, algo, a.tour_out.as_deref(), a.json);
    }
    let parsing = std::time::Instant::now();
    let inst = Instance::read(&a.file)?;
    let parse_seconds = parsing.elapsed().as_secs_f64();
    let mut precondition_seconds = 0.0;
    let mut options = Options {
        coverage4: a.coverage4,
        ..Options::default()
    };
    if let Some(m) = &a.merge {
        options.merge = m.parse().map_err(mowmill::Error::Invalid)?;
    }
    if let Some(c) = &a.cutter {
        options.cutter = c.parse().map_err(mowmill::Error::Invalid)?;
    }
    let outside;
    let subject = match (&a.algo, &a.command) {
        (Some(name), _) => {
            let algo = algorithms::find(name).ok_or_else(|| {
                mowmill::Error::invalid(format!(
                    "unknown algorithm {name:?}: expected one of {}",
                    algorithms::names().join(", ")
                ))
            })?;
            // A precondition the user's instance misses is bad input (exit 2).
            let checking = std::time::Instant::now();
            (algo.precondition)(&inst.region)
                .with_context(|| format!("{} does not apply to {}", algo.name, a.file.display()))?;
            precondition_seconds = checking.elapsed().as_secs_f64();
            Subject::Registered(algo)
        }
        (None, Some(command)) => {
            outside =
                outside_program(&a, command, wanted.unwrap_or(Objective::Length), time_limit)?;
            Subject::Outside(&outside)
        }
        (None, None) => unreachable!("clap requires --algo or --command"),
    };
    // Options the subject ignores are refused: --merge and --coverage4 act on merged tours,
    // --cutter on lawn tours, and only for registered algorithms (an outside program gets
    // none of them); --time-limit bounds the exact solve and outside programs.
    let (merge, cutter, coverage4) = match subject {
        Subject::Registered(_) => evaluate::relevant_options(subject.objectives()),
        Subject::Outside(_) => (false, false, false),
    };
    let mut applies = vec![
        "--objective",
        "--cycle-cover",
        "--turn-cost",
        "--exact",
        "--timings",
    ];
    for (option, relevant) in [
        ("--merge", merge),
        ("--cutter", cutter),
        ("--coverage4", coverage4),
        ("--time-limit", a.exact || a.command.is_some()),
    ] {
        if relevant {
            applies.push(option);
        }
    }
    refuse_ignored(&a, subject.name(), &applies)?;
    // The merged tour by default; the cycle cover with --cycle-cover.
    let objective = subject.pick_objective(wanted)?;
    let mut reference = Reference::default();
    let mut exact_json = serde_json::Value::Null;
    if a.exact {
        let Some(eo) = evaluate::exact_counterpart(objective) else {
            bail!(mowmill::Error::invalid(format!(
                "--exact: no exact solver computes the optimum of {objective} (lawn-tsp is a \
                 reference tour through the centres, not the optimal lawn tour)"
            )));
        };
        let opts = exact::ExactOptions {
            time_limit: Some(time_limit),
            ..mowmill::warm_start::exact_options()
        };
        let r = exact::solve(&inst.region, eo, &opts);
        let optimal = r.status == exact::Status::Optimal && r.valid;
        let opt = if optimal { r.value } else { None };
        let known = Known::proven(
            &eo.to_string(),
            opt,
            Some(r.lower_bound),
            r.status.to_string(),
        );
        reference.insert(eo, known);
        exact_json = serde_json::json!({
            "objective": eo.name(),
            "turn_cost": eo.turn_cost(),
            "status": r.status.to_string(),
            "value": r.value,
            "lower_bound": r.lower_bound,
            "seconds": r.seconds,
        });
    }
    let eval = evaluate::evaluate(subject, &inst.region, &options, &[objective], &reference);
    let exact_json = a.exact.then_some(exact_json);
    let phases = Phases {
        parse: Some(parse_seconds),
        precondition: Some(precondition_seconds),
        run: eval.seconds,
        check: eval.check_seconds,
    };
    report::<mowmill::region::Region>(
        &a,
        subject,
        &eval,
        objective,
        inst.region.len() as u64,
        (exact_json, phases),
    )
}

/// Where a run of `solve` spent its wall time, in seconds: reading the file (with the region's
/// indexes), the algorithm's precondition (component and hole counts), the run itself (with
/// its merge), and the checker's recount with the lower bounds. `None` where not timed.
#[derive(Clone, Copy, Debug, serde::Serialize)]
struct Phases {
    parse: Option<f64>,
    precondition: Option<f64>,
    run: f64,
    check: f64,
}

/// Prints an evaluated run of `solve` (text, or JSON with `--json`), writes `--tour-out`, and
/// gives the exit code: 1 when the output is invalid or a guarantee is violated, 2 when a
/// registered algorithm refused the instance or an option, 3 when the algorithm (or outside
/// program) failed. `n` is the instance's size (pixels or vertices); `exact` the exact
/// solve's summary when `--exact` ran one; `phases` where the time went (JSON key `phases`,
/// and a `time:` line of text with `--timings`).
fn report<M: InstanceModel>(
    a: &SolveArgs,
    subject: Subject<'_>,
    eval: &evaluate::Evaluation<M::Cover>,
    objective: Objective,
    n: u64,
    (exact, phases): (Option<serde_json::Value>, Phases),
) -> Result<ExitCode> {
    let options = &eval.options;
    if let Some(e) = &eval.error {
        // A registered algorithm that refused the region or an option (an error of exit code
        // 2, e.g. lawn-box with --cutter disk) is a usage error; any other failure of the
        // algorithm (or outside program) is not the input's fault.
        if matches!(subject, Subject::Registered(_)) && eval.error_exit_code == Some(2) {
            eprintln!("mowmill: error: {e}");
            return Ok(ExitCode::from(2));
        }
        eprintln!("mowmill: error: {} failed: {e}", subject.name());
        return Ok(ExitCode::from(3));
    }
    let Some(out) = eval.output(objective) else {
        let why = eval
            .missing
            .first()
            .map(|m| m.1.clone())
            .unwrap_or_default();
        eprintln!("mowmill: error: {why}");
        return Ok(ExitCode::from(3));
    };
    if let Some(path) = &a.tour_out {
        std::fs::write(path, M::walk_json(&out.cover) + "\n")
            .map_err(|e| mowmill::Error::io(path, e))?;
    }
    if a.json {
        let mut json = serde_json::json!({
            "algorithm": subject.name(),
            // The name bench rows give this run (options that differ from the defaults).
            "variant": evaluate::variant_name(subject.name(), subject.objectives(), options),
            "objective": out.objective.name(),
            "turn_cost": out.objective.turn_cost(),
            "value": out.value,
            "length": out.length,
            "turns": out.turns,
            "cycles": out.cycles,
            "max_coverage": out.max_coverage,
            "valid": out.valid,
            "error": out.error,
            "guarantee": out.verdicts,
            "within_guarantee": out.within_guarantee,
            "lower_bound": out.lower_bound,
            "lb_source": out.lb_source,
            "opt": out.opt,
            "opt_status": out.opt_status,
            "n": n,
            "seconds": eval.seconds,
            "phases": phases,
            "options": {
                "merge": options.merge.to_string(),
                "cutter": options.cutter.to_string(),
                "coverage4": options.coverage4,
            },
        });
        if let Some(exact) = exact {
            json["exact"] = exact;
        }
        for (k, v) in &eval.certificates {
            json[k] = serde_json::json!(v);
        }
        println!("{}", serde_json::to_string_pretty(&json)?);
    } else {
        print_text(subject.name(), out, &eval.certificates);
        if a.timings {
            let seconds = |s: Option<f64>| s.map_or("–".to_string(), |s| format!("{s:.3} s"));
            println!(
                "  time: parse {}, precondition {}, run {}, check {}",
                seconds(phases.parse),
                seconds(phases.precondition),
                seconds(Some(phases.run)),
                seconds(Some(phases.check)),
            );
        }
    }
    let violated = out.within_guarantee == Some(false);
    Ok(if out.valid && !violated {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn print_text<C>(
    name: &str,
    out: &Checked<C>,
    certificates: &std::collections::BTreeMap<String, i64>,
) {
    println!(
        "{name}: {} {} | length {}, turns {}, {} cycle(s), max coverage {} | {}",
        out.objective,
        out.value,
        out.length,
        out.turns,
        out.cycles,
        out.max_coverage,
        if out.valid {
            "valid".to_string()
        } else {
            format!("INVALID: {}", out.error.clone().unwrap_or_default())
        }
    );
    match (out.opt, out.lower_bound) {
        (Some(opt), _) => println!("  optimum {opt} (proven by the exact solver)"),
        (None, Some(lb)) => println!("  lower bound {lb} ({})", out.lb_source),
        _ => {}
    }
    if out.verdicts.is_empty() {
        println!("  guarantee: none registered for {}", out.objective);
    }
    for v in &out.verdicts {
        let verdict = match v.holds {
            Some(true) => "holds",
            Some(false) => "VIOLATED",
            None => "undecided (optimum unknown, lower bound too weak; try --exact)",
        };
        println!("  guarantee {}: {verdict}", v.bound);
    }
    for (k, v) in certificates {
        println!("  {k}: {v}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_split_on_spaces_and_quotes() {
        assert_eq!(
            split_command("python3 'my prog.py' {instance}  \"{tour_out}\" ''"),
            ["python3", "my prog.py", "{instance}", "{tour_out}", ""]
        );
        assert_eq!(split_command("run 'open quote"), ["run", "open quote"]);
        assert_eq!(split_command("run \"open 'quote"), ["run", "open 'quote"]);
    }
}
