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
