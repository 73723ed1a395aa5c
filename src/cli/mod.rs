//! One module per command: its arguments and what it does.

pub mod algos;
pub mod bench;
pub mod discrete;
pub mod exact;
pub mod export;
pub mod generate;
pub mod hunt;
pub mod solve;
pub mod tight;

use clap::builder::{PossibleValue, PossibleValuesParser};

/// A clap parser that accepts exactly `names` and lists them in `--help`; the old objective
/// spelling `tour-turns` is accepted as an alias of `turns`.
pub fn one_of(names: impl IntoIterator<Item = &'static str>) -> PossibleValuesParser {
    PossibleValuesParser::new(names.into_iter().map(|name| {
        let value = PossibleValue::new(name);
        match name {
            "turns" => value.alias("tour-turns"),
            _ => value,
        }
    }))
}
