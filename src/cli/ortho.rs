//! Orthogonal polygons with arbitrary (exact) coordinates at the command line (issue 18): a
//! `.wkt` file with a non-integral coordinate is read by [`mowmill::ortho`], checked for
//! feasibility first (can a unit square cutter mill it at all?), and `validate` runs the exact
//! milling checker on an ortho tour. Integral `.wkt` files keep the pixel path.

use anyhow::Result;
use mowmill::error::Error;
use mowmill::ortho::{self, Polygon, Tour};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

/// Whether `path` is a `.wkt` polygon with a coordinate that is not an integer (read exactly).
pub fn is_ortho(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("wkt"))
        && Polygon::read(path).is_ok_and(|p| {
            p.rings()
                .iter()
                .flat_map(|r| &r.corners)
                .any(|c| !c.x.is_integer() || !c.y.is_integer())
        })
}

/// Reads the polygon and refuses it (exit 2, the message naming where) when no tour of the unit
/// square cutter can mill it.
fn feasible(path: &Path) -> Result<(Polygon, ortho::Erosion)> {
    let polygon = Polygon::read(path)?;
    match ortho::feasibility(&polygon) {
        Ok(erosion) => Ok((polygon, erosion)),
        Err(why) => Err(Error::invalid(format!("{}: {why}", path.display())).into()),
    }
}

/// `info` on an ortho polygon: its rings and corners, and the erosion by the cutter (the
/// centre positions: pieces, the contour δB's length, the integer pixels inside).
pub fn info(path: &Path, as_json: bool) -> Result<ExitCode> {
    let (polygon, erosion) = feasible(path)?;
    let contour = ortho::check(&polygon, &erosion.contour_tour())?;
    let pixels = ortho::interior_pixels(&polygon)?;
    let v = json!({
        "model": "ortho",
        "rings": polygon.rings().len(),
        "holes": polygon.rings().iter().filter(|r| r.hole).count(),
        "corners": polygon.rings().iter().map(|r| r.corners.len()).sum::<usize>(),
        "feasible": true,
        "erosion_pieces": erosion.pieces(),
        "contour_walks": erosion.contour().len(),
        "contour_length": contour.length.to_string(),
        "contour_mills_polygon": contour.valid,
        "interior_pixels": pixels.len(),
    });
    if as_json {
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        for (k, val) in v.as_object().expect("an object") {
            println!("{k:<22} {val}");
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `validate` on an ortho polygon and tour: the exact checker's verdict (exit 1 when the tour
/// does not mill the polygon exactly).
pub fn validate(path: &Path, tour: &Path, as_json: bool) -> Result<ExitCode> {
    let (polygon, _) = feasible(path)?;
    let walk = Tour::read(tour)?;
    let report = ortho::check(&polygon, &walk)?;
    if as_json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        println!(
            "{}: length {}, turns {}, {} cycle(s){}",
            if report.valid { "valid" } else { "INVALID" },
            report.length,
            report.turns,
            report.cycles,
            report
                .error
                .as_deref()
                .map(|e| format!(" | {e}"))
                .unwrap_or_default()
        );
    }
    Ok(if report.valid {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `solve --algo corollary4` on an ortho polygon: Corollary 4's tour (the pixels inside toured
/// by `tsp65` or `milling25`, joined to the contour of the erosion), checked by the exact
/// checker, with its length against the lower bounds (area and extent proven; the contour bound
/// as the paper claims it, unproven here: docs/ortho.md). Exit 1 when the tour is invalid.
pub fn solve(path: &Path, algo: &str, tour_out: Option<&Path>, as_json: bool) -> Result<ExitCode> {
    if algo != "corollary4" {
        return Err(Error::invalid(format!(
            "{}: a polygon with non-integral coordinates is milled by corollary4 only (not {algo})",
            path.display()
        ))
        .into());
    }
    let (polygon, _) = feasible(path)?;
    let (tour, certificates) = ortho::corollary4(&polygon)?;
    let report = ortho::check(&polygon, &tour)?;
    if let Some(out) = tour_out {
        tour.write(out)?;
    }
    let proven = certificates.bounds.proven();
    let best = certificates.bounds.best();
    let ratio = |b: ortho::Rational| {
        (b.numer() != 0).then(|| {
            (report.length.numer() as f64 / report.length.denom() as f64)
                / (b.numer() as f64 / b.denom() as f64)
        })
    };
    let v = json!({
        "algorithm": "corollary4",
        "model": "ortho",
        "valid": report.valid,
        "length": report.length.to_string(),
        "turns": report.turns,
        "cycles": report.cycles,
        "error": report.error,
        "lower_bound_proven": proven.to_string(),
        "lower_bound_with_contour": best.to_string(),
        "ratio_proven_bound": ratio(proven),
        "ratio_with_contour": ratio(best),
        "certificates": certificates,
    });
    if as_json {
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "corollary4: length {} (turns {}, {} cycle(s)) | {} | lower bound {} (area, extent), {} with the paper's contour bound",
            report.length,
            report.turns,
            report.cycles,
            if report.valid { "valid" } else { "INVALID" },
            proven,
            best
        );
    }
    Ok(if report.valid {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `gen ortho-perturbed|ortho-holed|ortho-sliver|ortho-narrow --n N --seed S --out F.wkt`: a
/// polygon with non-integral coordinates (`ortho-narrow` is infeasible on purpose: a feature
/// narrower than the cutter, for testing refusals).
pub fn generate(
    family: &str,
    params: &[(mowmill::generate::Param, mowmill::generate::ParamValue)],
    seed: Option<u64>,
    out: &Path,
) -> Result<ExitCode> {
    use mowmill::generate::{Param, ParamValue};
    let mut n = None;
    for &(param, value) in params {
        match (param, value) {
            (Param::N, ParamValue::Count(v)) => n = Some(v),
            _ => {
                return Err(Error::invalid(format!(
                    "parameter `{}` does not apply to family {family} (it takes: n)",
                    param.name()
                ))
                .into());
            }
        }
    }
    let n = n.ok_or_else(|| Error::invalid(format!("family {family} needs --n")))?;
    let seed = seed.ok_or_else(|| {
        Error::invalid(format!(
            "family {family} is random: give --seed S (the same seed gives the same instance)"
        ))
    })?;
    let polygon = ortho::generate(family, n, seed)?;
    std::fs::write(out, polygon.to_wkt() + "\n").map_err(|e| Error::io(out, e))?;
    eprintln!(
        "wrote {}: {} corners, {} ring(s)",
        out.display(),
        polygon
            .rings()
            .iter()
            .map(|r| r.corners.len())
            .sum::<usize>(),
        polygon.rings().len()
    );
    Ok(ExitCode::SUCCESS)
}
