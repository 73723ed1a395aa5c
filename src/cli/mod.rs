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
pub mod report;
pub mod sample;
pub mod solve;
pub mod tight;

use anyhow::Context;
use clap::builder::{PossibleValue, PossibleValuesParser};
use mowmill::checker::Mode;
use mowmill::discrete::Discrete;
use mowmill::model::InstanceModel;
use mowmill::ortho::Polygon;
use mowmill::region::Region;
use std::path::Path;
use std::process::ExitCode;

/// The model of an instance file ([`mowmill::model::Kind::of`], the one place that decides it).
pub use mowmill::model::Kind as FileKind;

/// A command over an instance file of any model, written once over [`InstanceModel`].
trait OnModel {
    fn run<M: InstanceModel>(self, file: &Path) -> anyhow::Result<ExitCode>;
}

/// Runs `command` on the model of `file`: the one dispatch of the commands that read an
/// instance and nothing model-specific besides.
fn on_model(file: &Path, command: impl OnModel) -> anyhow::Result<ExitCode> {
    match FileKind::of(file) {
        FileKind::Grid => command.run::<Region>(file),
        FileKind::Discrete => command.run::<Discrete>(file),
        FileKind::Ortho => command.run::<Polygon>(file),
    }
}

/// An error of the model about the instance in `file`, naming the file.
fn about(file: &Path, e: mowmill::Error) -> anyhow::Error {
    mowmill::Error::invalid(format!("{}: {e}", file.display())).into()
}

/// `info`: the instance's summary, for its model.
pub fn info(file: &Path, json: bool) -> anyhow::Result<ExitCode> {
    struct Info(bool);
    impl OnModel for Info {
        fn run<M: InstanceModel>(self, file: &Path) -> anyhow::Result<ExitCode> {
            let v = M::read(file)?.info().map_err(|e| about(file, e))?;
            if self.0 {
                println!("{}", serde_json::to_string_pretty(&v)?);
            } else {
                for (k, val) in v.as_object().context("a summary is an object")? {
                    println!("{k:<w$} {val}", w = M::INFO_WIDTH);
                }
            }
            Ok(ExitCode::SUCCESS)
        }
    }
    on_model(file, Info(json))
}

/// `validate`: the model's checker on a tour file (`mode` applies to grid regions, the only
/// model with lawn tours: `--mode lawn` elsewhere is refused). Exit 1 when invalid.
pub fn validate(file: &Path, tour: &Path, mode: Mode, json: bool) -> anyhow::Result<ExitCode> {
    struct Validate<'a> {
        tour: &'a Path,
        mode: Mode,
        json: bool,
    }
    impl OnModel for Validate<'_> {
        fn run<M: InstanceModel>(self, file: &Path) -> anyhow::Result<ExitCode> {
            let inst = M::read(file)?;
            let cover = M::read_walk(self.tour)?;
            let v = inst
                .validation(&cover, self.mode)
                .map_err(|e| about(file, e))?;
            if self.json {
                println!("{}", serde_json::to_string_pretty(&v.json)?);
            } else {
                println!("{}", v.line);
            }
            Ok(if v.valid {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            })
        }
    }
    if mode == Mode::Lawn && FileKind::of(file) != FileKind::Grid {
        anyhow::bail!(mowmill::Error::invalid(format!(
            "--mode lawn applies to grid regions only, not to {} ({:?} model)",
            file.display(),
            FileKind::of(file)
        )));
    }
    on_model(file, Validate { tour, mode, json })
}

/// `draw`: the instance and optionally a tour, as SVG or PNG, for its model.
pub fn draw(
    file: &Path,
    tour: Option<&Path>,
    out: &Path,
    title: Option<String>,
) -> anyhow::Result<ExitCode> {
    struct Draw<'a> {
        tour: Option<&'a Path>,
        out: &'a Path,
        title: Option<String>,
    }
    impl OnModel for Draw<'_> {
        fn run<M: InstanceModel>(self, file: &Path) -> anyhow::Result<ExitCode> {
            let inst = M::read(file)?;
            let cover = self.tour.map(M::read_walk).transpose()?;
            inst.draw(cover.as_ref(), self.out, title_or_stem(file, self.title))?;
            eprintln!("wrote {}", self.out.display());
            Ok(ExitCode::SUCCESS)
        }
    }
    on_model(file, Draw { tour, out, title })
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
    // At a time limit, the relative gap (value − bound) / value.
    let gap = mowmill::exact::relative_gap(status == "time_limit", value, lower_bound)
        .map_or(String::new(), |g| format!(", gap {:.2}%", 100.0 * g));
    println!(
        "{objective} {status}: value {} lower bound {lower_bound} ({lb_source}) in {seconds:.2}s, {rounds} rounds{gap}{}",
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
