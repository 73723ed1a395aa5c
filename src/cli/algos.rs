//! `mowmill algos`: the registered algorithms, their guarantees and the theorems they come
//! from, as text, JSON or the Markdown tables of docs/algorithms.md (`--markdown`; docs/algorithms.md holds
//! them between `<!-- algos:begin -->` and `<!-- algos:end -->`, rewritten by
//! `scripts/update-readme-tables.sh`).

use anyhow::Result;
use clap::Args;
use mowmill::algorithms::theorems::{Implementation, Paper};
use mowmill::algorithms::{Algorithm, Guarantee, Objective, Quantity, REGISTRY};
use std::fmt::Write as _;
use std::process::ExitCode;

#[derive(Args)]
pub struct AlgosArgs {
    /// Print JSON instead of text.
    #[arg(long, conflicts_with = "markdown")]
    pub json: bool,
    /// Print the algorithm tables of docs/algorithms.md (one per paper) as Markdown.
    #[arg(long)]
    pub markdown: bool,
}

pub fn algos_command(a: AlgosArgs) -> Result<ExitCode> {
    if a.json {
        println!("{}", serde_json::to_string_pretty(&json()?)?);
    } else if a.markdown {
        print!("{}", markdown());
    } else {
        for a in REGISTRY {
            println!("{:<18} {}", a.name, a.summary);
            for g in a.guarantees {
                println!("{:<18}   guarantee: {g}", "");
            }
            let weighted = weighted_objectives(a);
            if !weighted.is_empty() {
                println!(
                    "{:<18}   also: {} (length + C * turns; no guarantee claimed)",
                    "",
                    weighted.join(", ")
                );
            }
            if !a.by_default {
                println!(
                    "{:<18}   not run by default: name it in a suite family's `algorithms`",
                    ""
                );
            }
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// The weighted objectives an algorithm reports on its outputs (none is guaranteed).
fn weighted_objectives(a: &Algorithm) -> Vec<&'static str> {
    [Objective::Weighted(0), Objective::WeightedCc(0)]
        .into_iter()
        .filter(|&o| a.reports(o))
        .map(Objective::name)
        .collect()
}

/// One object per algorithm: `name, summary, paper, objectives, requires`, `weighted_objectives`
/// (measured, never guaranteed), `guarantees` (their
/// text, as the results' `guarantee` column writes them), `guarantee_details` (each bound as
/// data with its theorem) and `claims` (the claims-table rows it is measured in).
fn json() -> Result<serde_json::Value> {
    let mut list = Vec::new();
    for a in REGISTRY {
        let mut details = Vec::new();
        for g in a.guarantees {
            let mut d = serde_json::to_value(g)?;
            d["guarantee"] = g.to_string().into();
            d["paper"] = g.theorem.paper.title().into();
            details.push(d);
        }
        let claims: Vec<serde_json::Value> = a
            .claims
            .iter()
            .map(|c| {
                serde_json::json!({
                    "theorem": c.theorem.id,
                    "paper": c.theorem.paper.title(),
                    "objectives": c.objectives,
                    "implementation": match c.implementation {
                        Implementation::Paper => "paper".to_string(),
                        Implementation::Reading(note) => format!("reading: {note}"),
                    },
                })
            })
            .collect();
        list.push(serde_json::json!({
            "name": a.name,
            "summary": a.summary,
            "paper": a.paper().title(),
            "objectives": a.objectives,
            "weighted_objectives": weighted_objectives(a),
            "requires": a.requires,
            "guarantees": a.guarantees.iter().map(ToString::to_string).collect::<Vec<_>>(),
            "guarantee_details": details,
            "claims": claims,
            "by_default": a.by_default,
        }));
    }
    Ok(serde_json::Value::Array(list))
}

/// The bound of a guarantee with its condition and theorem, e.g.
/// `` `length <= (6 N - 4)/5` without cut vertices, N >= 3: Theorem 5 ``; a bound on another
/// quantity than the objective's value names the output it bounds (`max-coverage <= 4` on
/// `cc-turns`).
fn guarantee_cell(a: &Algorithm, g: &Guarantee) -> String {
    // The Display text is "<bound> (<condition; ><source>)": keep the bound and condition,
    // name the theorem instead of the free-text source.
    let full = g.to_string();
    let head = full
        .strip_suffix(&format!("{})", g.source))
        .unwrap_or(&full);
    let (bound, condition) = match head.strip_suffix(" (") {
        Some(bound) => (bound, ""),
        None => match head.rsplit_once(" (") {
            Some((bound, condition)) => (bound, condition.trim_end_matches("; ")),
            None => (head, ""),
        },
    };
    let output = if g.bound.quantity == Quantity::Value {
        String::new()
    } else {
        format!(" on `{}`", g.objective)
    };
    let condition = if condition.is_empty() {
        String::new()
    } else {
        format!(" {condition}")
    };
    let reading = a.claims.iter().any(|c| {
        std::ptr::eq(c.theorem, g.theorem) && matches!(c.implementation, Implementation::Reading(_))
    });
    let how = if reading { ", our reading" } else { "" };
    format!("`{bound}`{output}{condition}: {}{how}", g.theorem.id)
}

/// The algorithm tables of docs/algorithms.md: one per paper, one row per registered algorithm.
pub fn markdown() -> String {
    let mut out = String::new();
    for paper in Paper::ALL {
        let algos: Vec<&Algorithm> = REGISTRY.iter().filter(|a| a.paper() == paper).collect();
        if algos.is_empty() {
            continue;
        }
        if !out.is_empty() {
            out.push('\n');
        }
        let _ = writeln!(out, "*{}*:\n", paper.title());
        out.push_str(
            "| `--algo` | what | objectives | registered guarantees (theorem) | claims table rows | requires |\n",
        );
        out.push_str("|---|---|---|---|---|---|\n");
        for a in algos {
            let objectives: Vec<String> = a.objectives.iter().map(|o| format!("`{o}`")).collect();
            let guarantees: Vec<String> =
                a.guarantees.iter().map(|g| guarantee_cell(a, g)).collect();
            let claims: Vec<String> = a
                .claims
                .iter()
                .map(|c| match c.implementation {
                    Implementation::Paper => c.theorem.id.to_string(),
                    Implementation::Reading(_) => format!("{} (our reading)", c.theorem.id),
                })
                .collect();
            let _ = writeln!(
                out,
                "| `{}` | {} | {} | {} | {} | {} |",
                a.name,
                a.summary,
                objectives.join(", "),
                guarantees.join("<br>"),
                claims.join(", "),
                a.requires
            );
        }
    }
    // A blank line ends the last table before the end marker.
    out.push('\n');
    out
}
