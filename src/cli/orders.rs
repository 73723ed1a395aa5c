//! `mowmill orders`: the star cover over the open choices of its greedy order, and how many of
//! them violate a bound ([`mowmill::discrete::choices`]; docs/discrete.md, "Orders").

use anyhow::Result;
use clap::Args;
use mowmill::discrete::Discrete;
use mowmill::discrete::choices::{self, ChoiceValue, EXHAUSTIVE_CAP, OrderSearch, SAMPLED_ORDERS};
use mowmill::error::Error;
use mowmill::instance::Instance;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct OrdersArgs {
    /// Instance file: discrete (.dm, .json, .vox, .hex) or a grid region (its grid graph).
    pub file: PathBuf,
    /// The algorithm whose greedy choices are enumerated.
    #[arg(long, default_value = "discrete-star-cover", value_parser = choices::ALGORITHMS)]
    pub algo: String,
    /// What is measured: the cycle cover's turns, the merged tour's turns, or Theorem 4.2's
    /// budget t + 2c - 2 of the cycle cover.
    #[arg(long, default_value = "cc-turns", value_parser = ChoiceValue::NAMES)]
    pub value: String,
    /// `all`: every rook set when at most --cap (else --samples seeded orders); K: K seeded
    /// random orders.
    #[arg(long, default_value = "all")]
    pub orders: String,
    #[arg(long, default_value_t = EXHAUSTIVE_CAP)]
    pub cap: u64,
    #[arg(long, default_value_t = SAMPLED_ORDERS)]
    pub samples: u64,
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// A value above X violates (e.g. a claimed upper bound).
    #[arg(long, allow_negative_numbers = true)]
    pub above: Option<f64>,
    /// A value below X violates (e.g. merge-budget against a lower bound on every tour).
    #[arg(long, allow_negative_numbers = true)]
    pub below: Option<f64>,
    /// Theorem 5.1's averaged claim against this OPT_cc: a value above (ρ + 2δ)·OPT violates.
    #[arg(long)]
    pub theorem_5_1_opt: Option<u64>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

pub fn orders_command(a: OrdersArgs) -> Result<ExitCode> {
    let inst: Discrete = if super::FileKind::of(&a.file) == super::FileKind::Discrete {
        super::discrete::read(&a.file)?
    } else {
        Discrete::from_region(&Instance::read(&a.file)?.region)
    };
    let value: ChoiceValue = a.value.parse().map_err(Error::Invalid)?;
    let search = if a.orders == "all" {
        OrderSearch::All {
            cap: a.cap,
            samples: a.samples,
            seed: a.seed,
        }
    } else {
        let orders = a.orders.parse().map_err(|_| {
            Error::invalid(format!(
                "--orders {}: expected all or a number of orders",
                a.orders
            ))
        })?;
        OrderSearch::Sampled {
            orders,
            seed: a.seed,
        }
    };
    let params = inst.params();
    let threshold = a
        .theorem_5_1_opt
        .map(|opt| (params.rho + 2.0 * params.delta) * opt as f64);
    let (above, below) = (a.above.or(threshold), a.below);
    if above.is_none() && below.is_none() {
        return Err(Error::invalid(
            "orders: give the bound, --above X, --below X or --theorem-5-1-opt OPT".to_string(),
        )
        .into());
    }
    let violates =
        |v: u64| above.is_some_and(|x| v as f64 > x) || below.is_some_and(|x| (v as f64) < x);
    let ev = choices::order_evidence_with(&a.algo, &inst, value, violates, search)
        .map_err(|e| Error::invalid(format!("{}: {e}", a.file.display())))?;
    if a.json {
        let mut j = serde_json::to_value(&ev)?;
        j["above"] = serde_json::json!(above);
        j["below"] = serde_json::json!(below);
        j["every_order_violates"] = serde_json::json!(ev.every_order_violates());
        j["summary"] = serde_json::json!(ev.summary());
        println!("{}", serde_json::to_string_pretty(&j)?);
    } else {
        println!(
            "{} {}: tried {} ({} distinct rook sets), exhaustive {}, violated {}, min {}, max {}, default {}{}",
            ev.algorithm,
            ev.value,
            ev.tried,
            ev.distinct,
            ev.exhaustive,
            ev.violated,
            ev.min,
            ev.max,
            ev.default_value,
            if ev.default_violates {
                " (violates)"
            } else {
                ""
            }
        );
        println!("{}", ev.summary());
    }
    Ok(ExitCode::SUCCESS)
}
