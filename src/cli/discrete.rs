//! Discrete milling at the command line: the files of the general model (`.dm`,
//! `.json` instances, `.vox` voxel regions, `.hex` hexagonal cells) go through `info`,
//! `validate`, `exact` and `solve` here, and `gen` writes its families (`voxel`, `hex`,
//! `honeycomb`, `plane`). Grid files keep their own path; a grid region is the special case
//! `Discrete::from_region` of this model.

use anyhow::Result;
use mowmill::algorithms::{self, Objective, Options};
use mowmill::discrete::Discrete;
use mowmill::discrete::exact::{self as dexact, DiscreteOptions};
use mowmill::discrete::format::{self, DiscreteCover};
use mowmill::discrete::generate::{self as dgen, PlaneParams};
use mowmill::discrete::merge::{proven_bound, theorem_4_2_bound};
use mowmill::discrete::star_cover;
use mowmill::error::Error;
use mowmill::evaluate::{self, Known, Reference};
use mowmill::model::InstanceModel;
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

pub use mowmill::discrete::generate::{FAMILIES, read};

/// `exact` on a discrete instance (the passage model of [`dexact`]).
pub fn exact(
    path: &Path,
    objective: mowmill::exact::Objective,
    opts: DiscreteOptions,
    tour_out: Option<&Path>,
    as_json: bool,
) -> Result<ExitCode> {
    let inst = read(path)?;
    if objective.is_tour() && inst.components() != 1 {
        return Err(Error::invalid(format!(
            "{}: the instance has {} connected components; objective {objective} is a tour, \
             which needs one (cc-turns accepts several)",
            path.display(),
            inst.components()
        ))
        .into());
    }
    let result = dexact::solve(&inst, objective, &opts);
    if let (Some(out), Some(walks)) = (tour_out, &result.cover) {
        DiscreteCover::new(walks.clone()).write(out)?;
    }
    if as_json {
        println!("{}", serde_json::to_string_pretty(&result)?);
    } else {
        super::print_exact_line(
            &result.objective,
            &result.status.to_string(),
            result.value,
            result.lower_bound,
            &result.lb_source,
            result.seconds,
            result.rounds,
            result.message.as_deref(),
        );
    }
    let ok = result.valid && !matches!(result.status, mowmill::exact::Status::Error);
    Ok(if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `solve --algo A` on a discrete instance, for a registered algorithm with a discrete run
/// (`discrete-star-cover`; `star-cover` names it too, the grid case of the same construction):
/// its outputs recounted by the discrete checker and every registered guarantee decided with
/// the instance's parameters (the one pipeline, [`evaluate::evaluate`]), against a
/// lower bound from the greedy rooks or a maximum rook placement (Lemma 4.3, off closed
/// channels). The paper's averaged forms (ρ + 2δ, Theorem 4.2's t + 2c − 2), which are not
/// proven for this implementation, are reported as figures. `options` carries the merge
/// strategy; with `exact` (a time limit), both turn objectives are also solved exactly and the
/// guarantees are decided against the proven optima (or the exact lower bounds, where larger
/// than the rook placement's). Exit 1 when a guarantee fails or an output is invalid.
pub fn solve(
    path: &Path,
    algo: &str,
    options: &Options,
    exact: Option<f64>,
    cycle_cover: bool,
    (tour_out, as_json): (Option<&Path>, bool),
) -> Result<ExitCode> {
    let name = if algo == "star-cover" {
        "discrete-star-cover"
    } else {
        algo
    };
    let Some(algorithm) = algorithms::find(name).filter(|a| a.discrete.is_some()) else {
        let runs: Vec<&str> = algorithms::REGISTRY
            .iter()
            .filter(|a| a.discrete.is_some())
            .map(|a| a.name)
            .collect();
        return Err(Error::invalid(format!(
            "{}: algorithm {algo} runs on grid regions only; on discrete instances: {}",
            path.display(),
            runs.join(", ")
        ))
        .into());
    };
    let inst = read(path)?;
    let params = inst.params();
    // A maximum rook placement (exact by a small MILP where it finishes in a few seconds) is a
    // lower bound on both turn objectives; the evaluation takes it where it beats the rooks.
    let placement = dexact::rook_placement(&inst, Some(5.0));
    let source = if placement.exact {
        "maximum rook placement (MILP)"
    } else {
        "rook placement (not proven maximum)"
    };
    let mut reference = Reference::default();
    let mut exact_json = serde_json::Map::new();
    for o in [Objective::CcTurns, Objective::Turns] {
        let rooks = Known {
            opt: None,
            lower_bound: Some(placement.size),
            status: String::new(),
            source: source.to_string(),
        };
        let known = match exact {
            None => rooks,
            Some(time_limit) => {
                let r = InstanceModel::solve_exact(&inst, o, time_limit)?;
                let optimal = r.status == mowmill::exact::Status::Optimal && r.valid == Some(true);
                exact_json.insert(
                    o.name().to_string(),
                    json!({"status": r.status.to_string(), "value": r.value,
                           "lower_bound": r.lower_bound, "message": r.message}),
                );
                let opt = if optimal { r.value } else { None };
                if opt.is_none() && r.lower_bound <= placement.size {
                    rooks
                } else {
                    Known::proven(o.name(), opt, Some(r.lower_bound), r.status.to_string())
                }
            }
        };
        reference.insert(o, known);
    }
    let eval = evaluate::evaluate(
        evaluate::Subject::Registered(algorithm),
        &inst,
        options,
        &[Objective::CcTurns, Objective::Turns],
        &reference,
    );
    if let Some(e) = &eval.error {
        return Err(Error::invalid(format!("{}: {e}", path.display())).into());
    }
    let (Some(cc), Some(tr)) = (
        eval.output(Objective::CcTurns),
        eval.output(Objective::Turns),
    ) else {
        return Err(Error::invalid(format!(
            "{}: {name} returned no cycle cover and tour",
            path.display()
        ))
        .into());
    };
    let cert = |k: &str| eval.certificates.get(k).copied().unwrap_or(0);
    let rooks = cert("rooks") as usize;
    let figures = json!({
        "theorem_5_1_averaged_bound": star_cover::theorem_5_1_bound(params, rooks),
        "corollary_5_1_averaged_bound": star_cover::corollary_5_1_bound(params, rooks),
        "theorem_4_2_bound": theorem_4_2_bound(cc.turns, cc.cycles),
        "proven_merge_bound": proven_bound(cc.turns, cc.cycles),
        "theorem_5_2_tour_bound": params.d.map(|d| star_cover::theorem_5_2_tour_bound(d, rooks)),
    });
    let shown = if cycle_cover { cc } else { tr };
    if let Some(out) = tour_out {
        shown.cover.write(out)?;
    }
    let valid = cc.valid && tr.valid;
    let verdicts: Vec<serde_json::Value> = [cc, tr]
        .iter()
        .flat_map(|c| {
            c.verdicts.iter().map(move |v| {
                json!({"objective": c.objective.to_string(), "bound": v.bound, "holds": v.holds})
            })
        })
        .collect();
    let all_hold = [cc, tr].iter().all(|c| c.within_guarantee != Some(false));
    let report = |c: &evaluate::Checked<_>| {
        json!({
            "valid": c.valid, "length": c.length, "turns": c.turns, "cycles": c.cycles,
            "max_coverage": c.max_coverage, "error": c.error,
            "lower_bound": c.lower_bound, "lb_source": c.lb_source,
            "within_guarantee": c.within_guarantee,
        })
    };
    let mut v = json!({
        "algorithm": algorithm.name,
        "model": "discrete",
        "n": inst.len(),
        "edges": inst.edge_count(),
        "delta": params.delta,
        "mu": params.mu,
        "rho": params.rho,
        "d": params.d,
        "beta_max": params.beta_max,
        "rooks": rooks,
        "lower_bound": cc.lower_bound,
        "lower_bound_source": cc.lb_source,
        "rings": cert("rings"),
        "rook_placement": placement.size,
        "rook_placement_exact": placement.exact,
        "cc": report(cc),
        "tour": report(tr),
        "merges": cert("merges"),
        "free_merges": cert("free_merges"),
        "certificates": eval.certificates,
        "verdicts": verdicts,
        "paper_figures": figures,
        "valid": valid,
    });
    v["options"] = json!({"merge": options.merge.to_string()});
    if exact.is_some() {
        v["exact"] = exact_json.clone().into();
    }
    if as_json {
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "{} (discrete): {} turns {} | length {}, {} cycle(s), max coverage {} | {}",
            algorithm.name,
            if cycle_cover { "cycle cover" } else { "tour" },
            shown.turns,
            shown.length,
            shown.cycles,
            shown.max_coverage,
            if valid { "valid" } else { "INVALID" }
        );
        println!(
            "  n {}, edges {}, delta {:.3}, mu {}, rho {:.3}, d {}, beta_max {}",
            inst.len(),
            inst.edge_count(),
            params.delta,
            params.mu,
            params.rho,
            params.d.map_or("-".to_string(), |d| d.to_string()),
            params.beta_max
        );
        println!(
            "  rooks {rooks} (lower bound {} from {}), rings {}, merges {} ({} free)",
            shown.lower_bound.unwrap_or(0),
            shown.lb_source,
            cert("rings"),
            cert("merges"),
            cert("free_merges")
        );
        for (objective, e) in &exact_json {
            println!(
                "  exact {objective}: {} {} (lower bound {})",
                e["status"].as_str().unwrap_or(""),
                e["value"],
                e["lower_bound"]
            );
        }
        for c in [cc, tr] {
            for v in &c.verdicts {
                let mark = match v.holds {
                    Some(true) => "holds",
                    Some(false) => "VIOLATED",
                    None => "undecided",
                };
                println!("  {}: {} {mark}", c.objective, v.bound);
            }
        }
    }
    Ok(if valid && all_hold {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `gen FAMILY` for the discrete families: `voxel` (`--n`, `--holes` enclosed cavities),
/// `hex` and `honeycomb` (`--n` cells or vertices), `plane` (`--n` vertices), and the
/// structured `hub-path` and `collinear-bridges` (`--n` path vertices, `--k` hubs or paths;
/// deterministic, a `--seed` is ignored). The output format follows the extension: `.vox`
/// (voxel), `.hex` (hex), `.json`, else `.dm`.
pub fn generate(
    family: &str,
    n: Option<usize>,
    holes: Option<usize>,
    k: Option<usize>,
    seed: Option<u64>,
    out: &Path,
) -> Result<ExitCode> {
    let n = n.ok_or_else(|| Error::invalid(format!("family {family} needs --n")))?;
    if holes.is_some() && family != "voxel" {
        return Err(Error::invalid(format!(
            "parameter `holes` does not apply to family {family} (voxel takes it: enclosed cavities)"
        ))
        .into());
    }
    if dgen::STRUCTURED.contains(&family) {
        dgen::check(family, Some(n), None, k)?;
        let inst = match family {
            "hub-path" => dgen::hub_path(n, k.unwrap_or(0))?,
            _ => dgen::collinear_bridges(n, k.unwrap_or(0))?,
        };
        return write_generated(&inst, family, out);
    }
    if k.is_some() {
        return Err(Error::invalid(format!(
            "parameter `k` does not apply to family {family} (it takes: {})",
            dgen::takes(family)
        ))
        .into());
    }
    let seed = seed.ok_or_else(|| {
        Error::invalid(format!(
            "family {family} is random: give --seed S (the same seed gives the same instance)"
        ))
    })?;
    let ext = out
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let inst = match family {
        "voxel" => {
            let region = dgen::random_voxels(n, seed, holes.unwrap_or(0))?;
            if ext.as_deref() == Some("vox") {
                region.write(out)?;
                eprintln!("wrote {}: {} voxels", out.display(), region.len());
                return Ok(ExitCode::SUCCESS);
            }
            region.to_discrete()
        }
        "hex" => {
            let region = dgen::random_hex(n, seed)?;
            if ext.as_deref() == Some("hex") {
                let text = region.to_text()?;
                std::fs::write(out, text).map_err(|e| Error::io(out, e))?;
                eprintln!("wrote {}: {} cells", out.display(), region.len());
                return Ok(ExitCode::SUCCESS);
            }
            region.to_discrete()
        }
        "honeycomb" => dgen::random_honeycomb(n, seed)?.to_discrete(),
        "plane" => dgen::random_plane_graph(n, seed, &PlaneParams::default())?,
        other => return Err(Error::invalid(format!("unknown discrete family {other}")).into()),
    };
    write_generated(&inst, family, out)
}

/// Writes a generated discrete instance as `.dm` or `.json` (by the extension of `out`;
/// `.vox` and `.hex` are refused: those families write them themselves).
fn write_generated(inst: &Discrete, family: &str, out: &Path) -> Result<ExitCode> {
    let ext = out
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let wrong_ext = |ext: &str, holds: &str| {
        Error::invalid(format!(
            "{}: a .{ext} file holds {holds}; write {family} as .dm or .json",
            out.display()
        ))
    };
    match ext.as_deref() {
        Some("vox") => return Err(wrong_ext("vox", "a voxel region (family voxel)").into()),
        Some("hex") => return Err(wrong_ext("hex", "hexagonal cells (family hex)").into()),
        _ => {}
    }
    format::write_discrete(inst, out)?;
    eprintln!(
        "wrote {}: {} vertices, {} edges",
        out.display(),
        inst.len(),
        inst.edge_count()
    );
    Ok(ExitCode::SUCCESS)
}
