//! The experiment harness behind `mowmill bench`, `plot`, `merge` and `gate`.
//!
//! Data flows one way: [`config`] expands a suite into instances; [`run`] generates them, runs
//! the exact solvers and the registered algorithms, checks every output with the checker and
//! appends [`rows`] to `results.csv`; [`stats`] aggregates the rows into `stats.csv`; [`plots`]
//! draws them; [`gate`] compares a run with a committed baseline; [`sample`] draws and re-runs
//! a committed sample of a run's rows; [`merge`] joins shards;
//! [`walks`] keeps the checked walks the claims table could find violated; [`lock`] keeps two runs out of one output directory.

pub mod config;
pub mod gate;
pub mod lock;
pub mod manifest;
pub mod merge;
pub mod plots;
pub mod progress;
pub mod rows;
pub mod run;
pub mod sample;
pub mod stats;
pub mod summary;
pub mod walks;

/// The built-in default suite: every registered algorithm and every exact objective on small
/// cases (`experiments/default.toml`).
pub const DEFAULT_CONFIG: &str = include_str!("../../experiments/default.toml");
