//! One module per command: its arguments and what it does.

pub mod algos;
pub mod bench;
pub mod discrete;
pub mod exact;
pub mod export;
pub mod generate;
pub mod hunt;
pub mod orders;
pub mod ortho;
pub mod sample;
pub mod solve;
pub mod tight;

use clap::builder::{PossibleValue, PossibleValuesParser};
use std::process::ExitCode;

/// What a checker recounted, as `validate` prints it (both models' reports have these).
pub struct Checked<'a> {
    pub valid: bool,
    pub length: u64,
    pub turns: u64,
    pub cycles: usize,
    pub max_coverage: u32,
    pub error: Option<&'a str>,
}

/// Prints `validate`'s answer, the whole report as JSON or one line, and gives its exit code
/// (1 when invalid).
pub fn print_validation(
    report: &impl serde::Serialize,
    c: &Checked,
    json: bool,
) -> anyhow::Result<ExitCode> {
    if json {
        println!("{}", serde_json::to_string_pretty(report)?);
    } else if c.valid {
        println!(
            "valid: length {}, turns {}, {} cycle(s), max coverage {}",
            c.length, c.turns, c.cycles, c.max_coverage
        );
    } else {
        println!("invalid: {}", c.error.unwrap_or("?"));
    }
    Ok(if c.valid {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The one line `exact` prints for a solve of either model.
#[allow(clippy::too_many_arguments)]
pub fn print_exact_line(
    objective: &str,
    status: &str,
    value: Option<u64>,
    lower_bound: u64,
    lb_source: &str,
    seconds: f64,
    rounds: u32,
    message: Option<&str>,
) {
    println!(
        "{objective} {status}: value {} lower bound {lower_bound} ({lb_source}) in {seconds:.2}s, {rounds} rounds{}",
        value.map_or("-".to_string(), |v| v.to_string()),
        message.map(|m| format!(" — {m}")).unwrap_or_default()
    );
}

/// A clap parser that accepts exactly `names` and lists them in `--help`; the old objective
/// spelling `tour-turns` is accepted as an alias of `turns`.
/// Refuses a time limit (or budget) in seconds outside (0, 30 days] with exit 2, naming the
/// option: the shared check of every seconds-valued option.
pub fn check_seconds(option: &str, seconds: f64) -> mowmill::Result<f64> {
    mowmill::harness::config::check_time_limit(seconds)
        .map(|()| seconds)
        .map_err(|m| mowmill::Error::invalid(format!("{option}: {m}")))
}

/// `exact --threads`: at least 1 and at most 4 per available core (HiGHS allocates per thread;
/// `--threads 100000` made it abort with bad_alloc).
pub fn parse_threads(s: &str) -> Result<usize, String> {
    let threads: usize = s
        .parse()
        .map_err(|_| format!("expected a number of threads, got {s:?}"))?;
    let max = 4 * std::thread::available_parallelism().map_or(1, |n| n.get());
    if threads == 0 || threads > max {
        return Err(format!(
            "--threads {threads}: expected 1 to {max} (4 per available core)"
        ));
    }
    Ok(threads)
}

pub fn one_of(names: impl IntoIterator<Item = &'static str>) -> PossibleValuesParser {
    PossibleValuesParser::new(names.into_iter().map(|name| {
        let value = PossibleValue::new(name);
        match name {
            "turns" => value.alias("tour-turns"),
            _ => value,
        }
    }))
}
