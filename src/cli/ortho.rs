//! Orthogonal polygons with arbitrary (exact) coordinates at the command line: a
//! `.wkt` file with a non-integral coordinate is read by [`mowmill::ortho`], checked for
//! feasibility first (can a unit square cutter mill it at all?), and `validate` runs the exact
//! milling checker on an ortho tour. Integral `.wkt` files keep the pixel path.

use anyhow::Result;
use mowmill::error::Error;
use mowmill::ortho::{self, Polygon};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;

/// Reads the polygon and refuses it (exit 2, the message naming where) when no tour of the unit
/// square cutter can mill it.
fn feasible(path: &Path) -> Result<(Polygon, ortho::Erosion)> {
    let polygon = Polygon::read(path)?;
    match ortho::feasibility(&polygon) {
        Ok(erosion) => Ok((polygon, erosion)),
        Err(why) => Err(Error::invalid(format!("{}: {why}", path.display())).into()),
    }
}

/// `solve --algo A` on an ortho polygon, for every registered algorithm with an ortho run
/// (`corollary4`, `strips-contour`): its outputs go through the one pipeline
/// ([`mowmill::evaluate::evaluate`]): checked by the exact checker, each against its proven
/// lower bound. `--tour-out` writes the tour (the first tour output). For `corollary4` the JSON
/// also carries the length bounds of Corollary 4's proof (the contour bound as the paper claims
/// it, unproven here: docs/ortho.md). Exit 1 when an output is invalid.
pub fn solve(path: &Path, algo: &str, tour_out: Option<&Path>, as_json: bool) -> Result<ExitCode> {
    let ortho_names: Vec<&str> = mowmill::algorithms::REGISTRY
        .iter()
        .filter(|a| a.ortho.is_some())
        .map(|a| a.name)
        .collect();
    let Some(algorithm) = mowmill::algorithms::find(algo).filter(|a| a.ortho.is_some()) else {
        return Err(Error::invalid(format!(
            "{}: a polygon with non-integral coordinates is milled by {} (not {algo})",
            path.display(),
            ortho_names.join(" or ")
        ))
        .into());
    };
    let (polygon, erosion) = feasible(path)?;
    let eval = mowmill::evaluate::evaluate(
        mowmill::evaluate::Subject::Registered(algorithm),
        &polygon,
        &mowmill::algorithms::Options::default(),
        &[],
        &mowmill::evaluate::Reference::default(),
    );
    if let Some(e) = &eval.error {
        return Err(Error::invalid(format!("{}: {algo}: {e}", path.display())).into());
    }
    if let Some((objective, why)) = eval.missing.first() {
        return Err(
            Error::invalid(format!("{}: {algo}: {objective}: {why}", path.display())).into(),
        );
    }
    let exact = |units: u64, unit: u64| {
        ortho::Rational::new(i128::from(units), i128::from(unit))
            .map_or_else(|| format!("{units}/{unit}"), |r| r.to_string())
    };
    let outputs: Vec<serde_json::Value> = eval
        .outputs
        .iter()
        .map(|c| {
            let length = exact(c.length, c.unit);
            let (value, bound) = if c.objective == mowmill::algorithms::Objective::Length {
                (length.clone(), c.lower_bound.map(|b| exact(b, c.unit)))
            } else {
                (c.value.to_string(), c.lower_bound.map(|b| b.to_string()))
            };
            json!({
                "objective": c.objective,
                "valid": c.valid,
                "error": c.error,
                "value": value,
                "length": length,
                "turns": c.turns,
                "cycles": c.cycles,
                "lower_bound": bound,
                "lb_source": c.lb_source,
                "ratio_lb": c.lower_bound.filter(|&b| b > 0).map(|b| c.value as f64 / b as f64),
                "verdicts": c.verdicts,
                "within_guarantee": c.within_guarantee,
            })
        })
        .collect();
    let tour = eval.outputs.iter().find(|c| c.objective.is_tour());
    if let (Some(out), Some(t)) = (tour_out, tour) {
        t.cover.write(out)?;
    }
    let valid = eval.outputs.iter().all(|c| c.valid);
    let mut v = json!({
        "algorithm": algorithm.name,
        "model": "ortho",
        "valid": valid,
        "seconds": eval.seconds,
        "outputs": outputs,
        "certificates": eval.certificates,
    });
    // The tour's own figures at the top level (as `solve` reports a tour on pixels).
    if let Some(t) = tour {
        v["length"] = json!(exact(t.length, t.unit));
        v["turns"] = json!(t.turns);
        v["cycles"] = json!(t.cycles);
        v["error"] = json!(t.error);
    }
    let mut contour_note = String::new();
    if algorithm.name == "corollary4" {
        let bounds = ortho::lower_bounds(&polygon, &erosion)?;
        v["lower_bound_proven"] = json!(bounds.proven().to_string());
        v["lower_bound_with_contour"] = json!(bounds.best().to_string());
        if let Some(t) = tour {
            let length = ortho::Rational::new(i128::from(t.length), i128::from(t.unit));
            let ratio = |b: ortho::Rational| {
                length.filter(|_| b.numer() != 0).map(|l| {
                    (l.numer() as f64 / l.denom() as f64) / (b.numer() as f64 / b.denom() as f64)
                })
            };
            v["ratio_proven_bound"] = json!(ratio(bounds.proven()));
            v["ratio_with_contour"] = json!(ratio(bounds.best()));
        }
        contour_note = format!(
            "; {} with the paper's contour bound (unproven here)",
            bounds.best()
        );
    }
    if as_json {
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        for c in &eval.outputs {
            let (value, bound) = if c.objective == mowmill::algorithms::Objective::Length {
                (
                    exact(c.length, c.unit),
                    c.lower_bound.map(|b| exact(b, c.unit)),
                )
            } else {
                (c.value.to_string(), c.lower_bound.map(|b| b.to_string()))
            };
            println!(
                "{}: {} {} (length {}, turns {}, {} cycle(s)) | {} | lower bound {} ({})",
                algorithm.name,
                c.objective,
                value,
                exact(c.length, c.unit),
                c.turns,
                c.cycles,
                if c.valid { "valid" } else { "INVALID" },
                bound.unwrap_or_else(|| "-".into()),
                c.lb_source,
            );
        }
        if !contour_note.is_empty() {
            println!("corollary4: lower bounds{contour_note}");
        }
    }
    Ok(if valid {
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
