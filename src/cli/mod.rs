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

use anyhow::Context;
use clap::builder::{PossibleValue, PossibleValuesParser};
use mowmill::checker::{self, Mode};
use mowmill::draw::DrawOptions;
use mowmill::instance::Instance;
use mowmill::tour::CycleCover;
use std::path::Path;
use std::process::ExitCode;

/// The model of an instance file. The one place the command line decides it: every command
/// that reads an instance dispatches on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// A grid region: `.grid`, WKT with integral coordinates, `.poly`, a `.gg`/`.csv` pixel list.
    Grid,
    /// A discrete instance ([`discrete::is_discrete`]: by its extension).
    Discrete,
    /// An orthogonal polygon with a non-integral coordinate ([`ortho::is_ortho`]).
    Ortho,
}

impl FileKind {
    /// The model of the instance file `path`.
    pub fn of(path: &Path) -> FileKind {
        if discrete::is_discrete(path) {
            FileKind::Discrete
        } else if ortho::is_ortho(path) {
            FileKind::Ortho
        } else {
            FileKind::Grid
        }
    }
}

/// `info`: the instance's summary, for its model.
pub fn info(file: &Path, json: bool) -> anyhow::Result<ExitCode> {
    match FileKind::of(file) {
        FileKind::Discrete => discrete::info(file, json),
        FileKind::Ortho => ortho::info(file, json),
        FileKind::Grid => grid_info(file, json),
    }
}

/// `validate`: the model's checker on a tour file (`mode` applies to grid regions).
pub fn validate(file: &Path, tour: &Path, mode: Mode, json: bool) -> anyhow::Result<ExitCode> {
    match FileKind::of(file) {
        FileKind::Discrete => discrete::validate(file, tour, json),
        FileKind::Ortho => ortho::validate(file, tour, json),
        FileKind::Grid => grid_validate(file, tour, mode, json),
    }
}

/// `draw`: the instance and optionally a tour, as SVG or PNG, for its model.
pub fn draw(
    file: &Path,
    tour: Option<&Path>,
    out: &Path,
    title: Option<String>,
) -> anyhow::Result<ExitCode> {
    match FileKind::of(file) {
        FileKind::Discrete => discrete::draw(file, tour, out, title),
        FileKind::Ortho => ortho::draw(file, tour, out, title),
        FileKind::Grid => grid_draw(file, tour, out, title),
    }
}

/// `info` on a grid region: its topology and the minimum strip cover.
fn grid_info(file: &Path, json: bool) -> anyhow::Result<ExitCode> {
    let inst = Instance::read(file)?;
    let mut v = serde_json::to_value(mowmill::topology::summary(&inst.region))?;
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

/// `validate` on a grid region: the milling (or lawn) checker on a cycle cover.
fn grid_validate(file: &Path, tour: &Path, mode: Mode, json: bool) -> anyhow::Result<ExitCode> {
    let inst = Instance::read(file)?;
    let cover = CycleCover::read(tour)?;
    let report = checker::check(&inst.region, &cover, mode);
    print_validation(&report, &Checked::from(&report), json)
}

/// `draw` on a grid region, the caption recounting the tour by the milling checker.
fn grid_draw(
    file: &Path,
    tour: Option<&Path>,
    out: &Path,
    title: Option<String>,
) -> anyhow::Result<ExitCode> {
    let inst = Instance::read(file)?;
    let cover = tour.map(CycleCover::read).transpose()?;
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
    mowmill::draw::draw(&inst.region, cover.as_ref(), out, &opts)?;
    eprintln!("wrote {}", out.display());
    Ok(ExitCode::SUCCESS)
}

/// The title `draw` gives a picture: `title`, else the file's stem.
pub fn title_or_stem(path: &Path, title: Option<String>) -> String {
    title.unwrap_or_else(|| {
        path.file_stem().map_or_else(
            || path.display().to_string(),
            |s| s.to_string_lossy().into_owned(),
        )
    })
}

/// What a checker recounted, as `validate` prints it (both models' reports have these).
pub struct Checked<'a> {
    pub valid: bool,
    pub length: u64,
    pub turns: u64,
    pub cycles: usize,
    pub max_coverage: u32,
    pub error: Option<&'a str>,
}

impl<'a, V> From<&'a checker::Report<V>> for Checked<'a> {
    fn from(report: &'a checker::Report<V>) -> Checked<'a> {
        Checked {
            valid: report.valid,
            length: report.length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: report.max_coverage,
            error: report.error.as_deref(),
        }
    }
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
