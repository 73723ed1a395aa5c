//! `mowmill gen`: one instance of a family, deterministically. The parameter flags, their help
//! and the list of families come from the generator's registry
//! ([`PARAMS`](mowmill::generate::PARAMS), [`Family::info`]).

use anyhow::Result;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{ArgAction, ArgMatches, Args, FromArgMatches};
use mowmill::error::Error;
use mowmill::generate::{
    self, Family, GenParams, PARAMS, Param, ParamKind, ParamValue, Pattern, Style,
};
use mowmill::topology;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct GenArgs {
    /// Instance family (see the list below; `voxel`, `hex`, `honeycomb`, `plane`, `hub-path`
    /// and `collinear-bridges` are discrete-milling instances, written as `.dm`, `.json`,
    /// `.vox` or `.hex`).
    #[arg(value_parser = family_parser())]
    pub family: String,
    #[command(flatten)]
    pub params: ParamArgs,
    /// Seed of the portable ChaCha generator; required by the random families.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Output file: `.grid`, or by its extension a pixel list (`.gg`, `.csv`) or `.wkt`
    /// (for sparse regions, whose `.grid` picture would be mostly empty).
    #[arg(long)]
    pub out: PathBuf,
}

fn family_parser() -> PossibleValuesParser {
    PossibleValuesParser::new(
        Family::ALL
            .map(Family::name)
            .into_iter()
            .chain(super::discrete::FAMILIES.iter().copied())
            .chain(mowmill::ortho::FAMILIES.iter().copied()),
    )
}

fn pattern_parser() -> impl TypedValueParser<Value = Pattern> {
    PossibleValuesParser::new(Pattern::NAMES).try_map(|s| s.parse::<Pattern>())
}

fn style_parser() -> impl TypedValueParser<Value = Style> {
    PossibleValuesParser::new(Style::NAMES).try_map(|s| s.parse::<Style>())
}

/// The values of the parameter flags given on the command line: one flag per row of
/// [`PARAMS`], in its order.
pub struct ParamArgs(pub Vec<(Param, ParamValue)>);

impl Args for ParamArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        let cmd = PARAMS.iter().fold(cmd, |cmd, spec| {
            let families: Vec<&str> = spec.param.families().map(Family::name).collect();
            let arg = clap::Arg::new(spec.name).long(spec.flag).help(format!(
                "{} [{}]",
                spec.help,
                families.join(", ")
            ));
            cmd.arg(match spec.kind {
                ParamKind::Count => arg.value_parser(clap::value_parser!(usize)),
                ParamKind::Flag => arg.action(ArgAction::SetTrue),
                ParamKind::Style => arg.value_parser(style_parser()),
                ParamKind::Fraction => arg.value_parser(clap::value_parser!(f64)),
                ParamKind::Pattern => arg.value_parser(pattern_parser()),
            })
        });
        cmd.after_help(format!(
            "{}\n\n{}",
            generate::families_help(),
            mowmill::discrete::generate::families_help()
        ))
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl FromArgMatches for ParamArgs {
    fn from_arg_matches(m: &ArgMatches) -> std::result::Result<Self, clap::Error> {
        let values = PARAMS
            .iter()
            .filter_map(|spec| {
                let value = match spec.kind {
                    ParamKind::Count => m
                        .get_one::<usize>(spec.name)
                        .copied()
                        .map(ParamValue::Count),
                    ParamKind::Flag => m.get_flag(spec.name).then_some(ParamValue::Flag(true)),
                    ParamKind::Style => m
                        .get_one::<Style>(spec.name)
                        .copied()
                        .map(ParamValue::Style),
                    ParamKind::Fraction => m
                        .get_one::<f64>(spec.name)
                        .copied()
                        .map(ParamValue::Fraction),
                    ParamKind::Pattern => m
                        .get_one::<Pattern>(spec.name)
                        .copied()
                        .map(ParamValue::Pattern),
                };
                value.map(|v| (spec.param, v))
            })
            .collect();
        Ok(ParamArgs(values))
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> std::result::Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

pub fn gen_command(a: GenArgs) -> Result<ExitCode> {
    if super::discrete::FAMILIES.contains(&a.family.as_str()) {
        let (mut n, mut holes, mut k) = (None, None, None);
        for &(param, value) in &a.params.0 {
            match (param, value) {
                (Param::N, ParamValue::Count(v)) => n = Some(v),
                (Param::Holes, ParamValue::Count(v)) => holes = Some(v),
                (Param::K, ParamValue::Count(v)) => k = Some(v),
                _ => {
                    return Err(Error::invalid(format!(
                        "parameter `{}` does not apply to family {} (it takes: {})",
                        param.name(),
                        a.family,
                        mowmill::discrete::generate::takes(&a.family)
                    ))
                    .into());
                }
            }
        }
        return super::discrete::generate(&a.family, n, holes, k, a.seed, &a.out);
    }
    if mowmill::ortho::FAMILIES.contains(&a.family.as_str()) {
        return super::ortho::generate(&a.family, &a.params.0, a.seed, &a.out);
    }
    let family: Family = a.family.parse()?;
    let info = family.info();
    let seed = match a.seed {
        Some(seed) => seed,
        None if info.random => {
            return Err(Error::invalid(format!(
                "family {} is random: give --seed S (the same seed gives the same instance)",
                info.name
            ))
            .into());
        }
        None => 0,
    };
    let mut params = GenParams::new(family, seed);
    for &(param, value) in &a.params.0 {
        params.set(param, value)?;
    }
    let file = generate::generate(&params)?;
    // The format follows the extension: a pixel list or WKT for sparse regions (a long band),
    // whose .grid picture would be mostly empty; .grid otherwise.
    let text = match a.out.extension().and_then(|e| e.to_str()) {
        Some("gg" | "csv") => {
            let meta: String = file.comments.iter().map(|c| format!("#{c}\n")).collect();
            meta + &mowmill::pixel_list::to_pixel_list(&file.region)
        }
        Some("wkt") => mowmill::wkt::to_wkt(&file.region) + "\n",
        _ => file.to_text()?,
    };
    std::fs::write(&a.out, text).map_err(|e| Error::io(&a.out, e))?;
    eprintln!(
        "wrote {}: {} pixels, {} holes",
        a.out.display(),
        file.region.len(),
        topology::holes(&file.region).count
    );
    Ok(ExitCode::SUCCESS)
}
