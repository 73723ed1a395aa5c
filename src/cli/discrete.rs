//! Discrete milling at the command line (issue 17): the files of the general model (`.dm`,
//! `.json` instances, `.vox` voxel regions, `.hex` hexagonal cells) go through `info`,
//! `validate`, `exact` and `solve` here, and `gen` writes its families (`voxel`, `hex`,
//! `honeycomb`, `plane`). Grid files keep their own path; a grid region is the special case
//! `Discrete::from_region` of this model.

use anyhow::Result;
use mowmill::discrete::check::{self, Report};
use mowmill::discrete::exact::{self as dexact, DiscreteOptions};
use mowmill::discrete::format::{self, DiscreteCover};
use mowmill::discrete::generate::{self as dgen, PlaneParams};
use mowmill::discrete::merge::{self, proven_bound, theorem_4_2_bound};
use mowmill::discrete::star_cover::{self, star_cover};
use mowmill::discrete::VertexWalk;
use mowmill::error::Error;
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

pub use mowmill::discrete::generate::{FAMILIES, is_discrete, read};

/// The algorithms `solve` runs on a discrete instance: the star cover of Theorem 5.1 (merged
/// into a tour by Corollary 5.1), under the registered name of its grid case (Corollary 5.2).
pub const ALGORITHMS: &[&str] = &["star-cover"];

/// The instance's size and Table 1's parameters, with a rook placement (Lemma 4.3).
pub fn info(path: &Path, as_json: bool) -> Result<ExitCode> {
    let inst = read(path)?;
    let p = inst.params();
    let rooks = dexact::rook_placement(&inst, Some(10.0));
    let v = json!({
        "model": "discrete",
        "n": inst.len(),
        "edges": inst.edge_count(),
        "components": inst.components(),
        "delta": p.delta,
        "mu": p.mu,
        "rho": p.rho,
        "d": p.d,
        "rook_placement": rooks.size,
        "rook_placement_exact": rooks.exact,
    });
    print_object(&v, as_json)?;
    Ok(ExitCode::SUCCESS)
}

fn print_object(v: &serde_json::Value, as_json: bool) -> Result<()> {
    if as_json {
        println!("{}", serde_json::to_string_pretty(v)?);
    } else if let Some(map) = v.as_object() {
        for (k, val) in map {
            println!("{k:<22} {val}");
        }
    }
    Ok(())
}

/// `validate` on a discrete instance: the walk file `{"model": "discrete", "cycles": ...}`
/// through the discrete checker (exit 1 if invalid).
pub fn validate(path: &Path, tour: &Path, as_json: bool) -> Result<ExitCode> {
    let inst = read(path)?;
    let cover = DiscreteCover::read(tour)?;
    let report = check::check(&inst, &cover.cycles);
    super::print_validation(
        &report,
        &super::Checked {
            valid: report.valid,
            length: report.length,
            turns: report.turns,
            cycles: report.cycles,
            max_coverage: report.max_coverage,
            error: report.error.as_deref(),
        },
        as_json,
    )
}

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
    if let (Some(out), Some(walks)) = (tour_out, &result.walks) {
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

/// One verdict of `solve`: a proven bound on a recounted value.
fn verdict(name: &str, value: u64, bound: u64, source: &str) -> serde_json::Value {
    json!({ "bound": name, "value": value, "limit": bound, "holds": value <= bound, "source": source })
}

/// `solve --algo star-cover` on a discrete instance: the greedy star cover's cycle cover
/// (Theorem 5.1) and its merge into a tour (Corollary 5.1), both recounted by the checker,
/// with the bounds that are proven for this implementation (see `discrete::star_cover`'s
/// module documentation: the paper's averaged ρ + 2δ and Theorem 4.2's +2 per merge are not,
/// and are reported as figures) and a rook placement as the lower bound (Lemma 4.3, off
/// closed channels).
pub fn solve(
    path: &Path,
    algo: &str,
    cycle_cover: bool,
    tour_out: Option<&Path>,
    as_json: bool,
) -> Result<ExitCode> {
    if !ALGORITHMS.contains(&algo) {
        return Err(Error::invalid(format!(
            "{}: algorithm {algo} runs on grid regions only; on discrete instances: {}",
            path.display(),
            ALGORITHMS.join(", ")
        ))
        .into());
    }
    let inst = read(path)?;
    let params = inst.params();
    let star = star_cover(&inst);
    let cc = check::check(&inst, &star.cycles);
    let (tour, stats) = merge::merge(&inst, &star.cycles);
    let tr = check::check(&inst, &tour);
    let rooks = star.rooks.len();
    // The lower bound: the larger of the star cover's greedy rooks and a maximum rook
    // placement (exact by a small MILP where it finishes in a few seconds).
    let placement = dexact::rook_placement(&inst, Some(5.0));
    let lower_bound = rooks.max(placement.size as usize);
    let mut verdicts = vec![
        verdict(
            "cc-turns <= sum of beta over the rooks",
            cc.turns,
            star_cover::star_turn_bound(&inst, &star.rooks),
            "Theorem 5.1, proven with beta(v) = directions + 2 deg (discrete::star_cover)",
        ),
        verdict(
            "max-coverage <= mu",
            cc.max_coverage.max(tr.max_coverage).into(),
            star_cover::coverage_bound(params).into(),
            "Theorem 5.1 and Corollary 5.1",
        ),
        verdict(
            "length <= 2|E| = delta n",
            tr.length.max(cc.length),
            star_cover::length_bound(&inst),
            "Theorem 5.1 (delta-approximation on length)",
        ),
        verdict(
            "turns <= cc-turns + 4 (c - 1)",
            tr.turns,
            proven_bound(cc.turns, star.cycles.len()),
            "Corollary 5.1 with +4 per merge (discrete::merge)",
        ),
    ];
    if let Some(d) = params.d {
        verdicts.push(verdict(
            "cc-turns <= 5d rooks",
            cc.turns,
            star_cover::theorem_5_2_cc_bound(d, lower_bound),
            "Theorem 5.2",
        ));
    }
    let figures = json!({
        "theorem_5_1_averaged_bound": star_cover::theorem_5_1_bound(params, rooks),
        "corollary_5_1_averaged_bound": star_cover::corollary_5_1_bound(params, rooks),
        "theorem_4_2_bound": theorem_4_2_bound(cc.turns, star.cycles.len()),
        "theorem_5_2_tour_bound": params.d.map(|d| star_cover::theorem_5_2_tour_bound(d, rooks)),
    });
    let (shown, shown_report): (&Vec<VertexWalk>, &Report) = if cycle_cover {
        (&star.cycles, &cc)
    } else {
        (&tour, &tr)
    };
    if let Some(out) = tour_out {
        DiscreteCover::new(shown.clone()).write(out)?;
    }
    let valid = cc.valid && tr.valid && tr.cycles == inst.components();
    let all_hold = verdicts.iter().all(|v| v["holds"] == json!(true));
    let v = json!({
        "algorithm": algo,
        "model": "discrete",
        "n": inst.len(),
        "edges": inst.edge_count(),
        "delta": params.delta,
        "mu": params.mu,
        "rho": params.rho,
        "d": params.d,
        "rooks": rooks,
        "lower_bound": lower_bound,
        "lower_bound_source": if placement.size as usize > rooks {
            if placement.exact { "maximum rook placement (MILP)" } else { "rook placement (MILP, not proven maximum)" }
        } else {
            "the star cover's rooks (Lemma 4.3)"
        },
        "rings": star.rings,
        "cc": cc,
        "tour": tr,
        "merges": stats.merges,
        "free_merges": stats.free_merges,
        "verdicts": verdicts,
        "paper_figures": figures,
        "valid": valid,
    });
    if as_json {
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "{algo} (discrete): {} turns {} | length {}, {} cycle(s), max coverage {} | {}",
            if cycle_cover { "cycle cover" } else { "tour" },
            shown_report.turns,
            shown_report.length,
            shown_report.cycles,
            shown_report.max_coverage,
            if valid { "valid" } else { "INVALID" }
        );
        println!(
            "  n {}, edges {}, delta {:.3}, mu {}, rho {:.3}, d {}",
            inst.len(),
            inst.edge_count(),
            params.delta,
            params.mu,
            params.rho,
            params.d.map_or("-".to_string(), |d| d.to_string())
        );
        println!(
            "  lower bound {lower_bound} (rook placement, Lemma 4.3; the star cover has {rooks} rooks); cycle cover {} turns in {} cycles",
            cc.turns,
            star.cycles.len()
        );
        for x in &verdicts {
            println!(
                "  {}: {} <= {}: {} ({})",
                x["bound"].as_str().unwrap_or(""),
                x["value"],
                x["limit"],
                if x["holds"] == json!(true) {
                    "holds"
                } else {
                    "VIOLATED"
                },
                x["source"].as_str().unwrap_or("")
            );
        }
        if let Some(e) = tr.error.as_ref().or(cc.error.as_ref()) {
            println!("  checker: {e}");
        }
    }
    Ok(if valid && all_hold {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `gen FAMILY` for the discrete families: `voxel` (`--n`, `--holes` enclosed cavities),
/// `hex` and `honeycomb` (`--n` cells or vertices), `plane` (`--n` vertices). The output
/// format follows the extension: `.vox` (voxel), `.hex` (hex), `.json`, else `.dm`.
pub fn generate(
    family: &str,
    n: Option<usize>,
    holes: Option<usize>,
    seed: Option<u64>,
    out: &Path,
) -> Result<ExitCode> {
    let n = n.ok_or_else(|| Error::invalid(format!("family {family} needs --n")))?;
    let seed = seed.ok_or_else(|| {
        Error::invalid(format!(
            "family {family} is random: give --seed S (the same seed gives the same instance)"
        ))
    })?;
    if holes.is_some() && family != "voxel" {
        return Err(Error::invalid(format!(
            "parameter `holes` does not apply to family {family} (voxel takes it: enclosed cavities)"
        ))
        .into());
    }
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
    match ext.as_deref() {
        Some("vox") => return Err(wrong_ext("vox", "a voxel region (family voxel)").into()),
        Some("hex") => return Err(wrong_ext("hex", "hexagonal cells (family hex)").into()),
        _ => {}
    }
    format::write_discrete(&inst, out)?;
    eprintln!(
        "wrote {}: {} vertices, {} edges",
        out.display(),
        inst.len(),
        inst.edge_count()
    );
    Ok(ExitCode::SUCCESS)
}

/// `draw` on a discrete instance: its cells (or its graph) and, with `--tour`, the walk file's
/// walks, to SVG or PNG; one panel per z-layer for voxels. The caption carries the checker's
/// counts, as for grid regions.
pub fn draw(
    path: &Path,
    tour: Option<&Path>,
    out: &Path,
    title: Option<String>,
) -> Result<ExitCode> {
    let inst = read(path)?;
    let cover = tour.map(DiscreteCover::read).transpose()?;
    let walks = cover.as_ref().map(|c| c.cycles.as_slice());
    let name = path.file_stem().map_or_else(
        || path.display().to_string(),
        |s| s.to_string_lossy().into_owned(),
    );
    let opts = mowmill::draw::DrawOptions {
        title: Some(title.unwrap_or(name)),
        caption: Some(mowmill::discrete::draw::caption(&inst, walks)),
        ..mowmill::draw::DrawOptions::default()
    };
    mowmill::discrete::draw::draw(&inst, walks, out, &opts)?;
    eprintln!("wrote {}", out.display());
    Ok(ExitCode::SUCCESS)
}
