//! The registry entries of the algorithms for orthogonal polygons with arbitrary coordinates
//! (Table 1's row "Orthogonal"): each runs on a [`Polygon`] (its `ortho` run) and, through
//! [`Polygon::from_region`], on grid regions (its `run`, whose walks are mapped back to pixels
//! and checked by the grid checker: the integral special case, against exact optima).
//!
//! No guarantee is registered for them: a registered guarantee is a proven one, and what the
//! implementation proves is written in each module (Corollary 4 leans on the paper's contour
//! bound, which is unproven here). The claims table measures the papers' factors against the
//! proven lower bounds, and against exact optima on grid regions.

use super::corollary4::corollary4;
use super::polygon::Polygon;
use super::tour::Tour;
use crate::algorithms::theorems::{self, Claim};
use crate::algorithms::{Algorithm, Objective, Options, Output, Solution};
use crate::error::{Error, Result};
use crate::region::Region;
use std::collections::BTreeMap;

/// Corollary 4 of *Lawn mowing and milling*: [`corollary4`].
pub const COROLLARY4: Algorithm = Algorithm {
    name: "corollary4",
    summary: "Corollary 4: the integer pixels inside toured by tsp65 (milling25 with holes), joined to the contour of the erosion (milling length, arbitrary coordinates)",
    objectives: &[Objective::Length],
    guarantees: &[],
    claims: &[Claim::reading(
        &theorems::MILLING_COR_4,
        &[Objective::Length],
        "the paper's \"combining\" is our straight links walked both ways (a spanning tree); its 11/5 rests on the contour bound L_dB <= OPT, which the paper asserts and we have not proven",
    )],
    requires: "a polygon a unit square can mill (feasibility)",
    precondition: any_region,
    run: grid_corollary4,
    discrete: None,
    ortho: Some(ortho_corollary4),
};

fn any_region(_: &Region) -> Result<()> {
    Ok(())
}

fn ortho_corollary4(polygon: &Polygon, _: &Options) -> Result<Solution<Tour>> {
    let (tour, c) = corollary4(polygon)?;
    let certificates = BTreeMap::from([
        ("pixels".to_string(), c.pixels as i64),
        ("components".to_string(), c.components as i64),
        ("tsp65_components".to_string(), c.tsp65 as i64),
        ("milling25_components".to_string(), c.milling25 as i64),
        ("contour_walks".to_string(), c.contour_walks as i64),
        ("links".to_string(), c.links as i64),
    ]);
    Ok(Solution {
        outputs: vec![Output {
            objective: Objective::Length,
            cover: tour,
        }],
        certificates,
    })
}

/// An ortho run on a grid region: the region as a polygon, the walks back as pixel walks.
pub(crate) fn on_grid(
    region: &Region,
    options: &Options,
    run: fn(&Polygon, &Options) -> Result<Solution<Tour>>,
) -> Result<Solution> {
    let polygon = Polygon::from_region(region)?;
    let solution = run(&polygon, options)?;
    let outputs = solution
        .outputs
        .into_iter()
        .map(|o| {
            let cover = o.cover.to_pixel_cover().ok_or_else(|| {
                Error::invalid(format!(
                    "the {} walk on an integral polygon is not a walk of pixel centres",
                    o.objective
                ))
            })?;
            Ok(Output {
                objective: o.objective,
                cover,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Solution {
        outputs,
        certificates: solution.certificates,
    })
}

fn grid_corollary4(region: &Region, options: &Options) -> Result<Solution> {
    on_grid(region, options, ortho_corollary4)
}
