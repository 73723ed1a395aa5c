//! The registry entries of the algorithms for orthogonal polygons with arbitrary coordinates
//! (Table 1's row "Orthogonal"): each runs on a [`Polygon`] (its `ortho` run) and, through
//! [`Polygon::from_region`], on grid regions (its `run`, whose walks are mapped back to pixels
//! and checked by the grid checker: the integral special case, against exact optima).
//!
//! No guarantee is registered for them: a registered guarantee is a proven one, and what the
//! implementation proves is written in each module (Corollary 4 leans on the paper's contour
//! bound, which is unproven here; `strips-contour`'s Theorem 5.7 factors lean on bounds of
//! the interior's and the contour's turns against OPT that are unproven here). The claims table measures the papers' factors against the
//! proven lower bounds, and against exact optima on grid regions.

use super::corollary4::corollary4;
use super::strips_contour::{StripsContour, star_contour, strips_contour};
use crate::error::{Error, Result};
use crate::region::Region;
use crate::theorems::{self, Claim};
use crate::{Algorithm, Objective, Options, Output, Solution};
use mowmill_core::ortho::Polygon;
use mowmill_core::ortho::Tour;
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
    requires: "a polygon a unit square can mill (feasibility); on grid regions, a connected one",
    precondition: crate::precondition::connected,
    run: grid_corollary4,
    discrete: None,
    ortho: Some(ortho_corollary4),
    by_default: true,
};

/// Our reading of Theorem 5.7 of *Optimal covering tours with turn costs*:
/// [`strips_contour`].
pub const STRIPS_CONTOUR: Algorithm = Algorithm {
    name: "strips-contour",
    summary: "Theorem 5.7 (our reading): strips-matching on the integer pixels inside plus the contour of the erosion, unneeded parts dropped by the exact checker, joined by straight links ranked by added turns (milling turns, arbitrary coordinates)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[],
    claims: &[
        Claim::reading(
            &theorems::TURNS_THM_5_7,
            &[Objective::CcTurns],
            STRIPS_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_THM_5_7_TOUR,
            &[Objective::Turns],
            STRIPS_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_THM_5_7_LENGTH,
            &[Objective::Turns],
            STRIPS_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_THM_5_7_COVERAGE,
            &[Objective::Turns],
            STRIPS_CONTOUR_NOTE,
        ),
    ],
    requires: "a polygon a unit square can mill (feasibility); on grid regions, a connected one",
    precondition: crate::precondition::connected,
    run: grid_strips_contour,
    discrete: None,
    ortho: Some(ortho_strips_contour),
    by_default: true,
};

/// Table 1's star-cover line for orthogonal polygons: [`star_contour`].
pub const STAR_CONTOUR: Algorithm = Algorithm {
    name: "star-contour",
    summary: "Table 1's star-cover line (our reading): star-cover on the integer pixels inside plus the contour of the erosion, unneeded parts dropped by the exact checker, joined by straight links ranked by added turns (milling turns, arbitrary coordinates)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[],
    claims: &[
        Claim::reading(
            &theorems::TURNS_ORTHO_STAR,
            &[Objective::CcTurns],
            STAR_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_ORTHO_STAR_TOUR,
            &[Objective::Turns],
            STAR_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_ORTHO_STAR_LENGTH,
            &[Objective::Turns],
            STAR_CONTOUR_NOTE,
        ),
        Claim::reading(
            &theorems::TURNS_ORTHO_STAR_COVERAGE,
            &[Objective::CcTurns],
            STAR_CONTOUR_NOTE,
        ),
    ],
    requires: "a polygon a unit square can mill (feasibility); on grid regions, a connected one",
    precondition: crate::precondition::connected,
    run: grid_star_contour,
    discrete: None,
    ortho: Some(ortho_star_contour),
    by_default: true,
};

/// Where `star-contour` departs from the paper (module docs of `strips_contour`).
const STAR_CONTOUR_NOTE: &str = "the paper proves the star cover on pixels only; on arbitrary coordinates we star-cover the integer pixels inside and add the contour of the erosion (as strips-contour), which no star argument bounds: a rook is attacked from a whole unit box of centre positions, not by two strips";

/// Where the implementation departs from the paper's one-line proof idea (module docs of
/// `strips_contour`).
const STRIPS_CONTOUR_NOTE: &str = "the paper's \"boundary tour modified to cover subpixels near reflex vertices\" is our contour of the erosion, with unneeded parts dropped by the exact checker, and its \"combine\" our straight links walked both ways; its 4.5 and 6.25 rest on sum OPT_cc(R_i) <= OPT_cc(P) and on the contour's turns against OPT, neither proven here";

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

fn ortho_strips_contour(polygon: &Polygon, options: &Options) -> Result<Solution<Tour>> {
    Ok(contour_solution(strips_contour(polygon, options)?, true))
}

fn ortho_star_contour(polygon: &Polygon, options: &Options) -> Result<Solution<Tour>> {
    Ok(contour_solution(star_contour(polygon, options)?, false))
}

/// The outputs and certificates of `strips-contour` (`strips`: with the strip cover's
/// certificates) or `star-contour` (with the rooks).
fn contour_solution(out: StripsContour, strips: bool) -> Solution<Tour> {
    let c = out.certificates;
    let mut certificates = BTreeMap::from([
        ("pixels".to_string(), c.pixels as i64),
        ("components".to_string(), c.components as i64),
        ("components_kept".to_string(), c.components_kept as i64),
        ("interior_cycles".to_string(), c.interior_cycles as i64),
        ("interior_cc_turns".to_string(), c.interior_cc_turns as i64),
        (
            "interior_tour_turns".to_string(),
            c.interior_tour_turns as i64,
        ),
        ("contour_walks".to_string(), c.contour_walks as i64),
        ("contour_kept".to_string(), c.contour_kept as i64),
        ("contour_turns".to_string(), c.contour_turns as i64),
        (
            "tour_contour_turns".to_string(),
            c.tour_contour_turns as i64,
        ),
        ("rejoined".to_string(), c.rejoined as i64),
        ("links".to_string(), c.links as i64),
        ("link_turns".to_string(), c.link_turns),
        ("turn_lower_bound".to_string(), c.lower_bound as i64),
    ]);
    if strips {
        certificates.insert("strips".to_string(), c.strips as i64);
        certificates.insert("matching_turns".to_string(), c.matching_turns as i64);
        certificates.insert(
            "matching_optimal".to_string(),
            i64::from(c.matching_optimal),
        );
    } else {
        certificates.insert("rooks".to_string(), c.rooks as i64);
    }
    Solution {
        outputs: vec![
            Output {
                objective: Objective::CcTurns,
                cover: out.cycle_cover,
            },
            Output {
                objective: Objective::Turns,
                cover: out.tour,
            },
        ],
        certificates,
    }
}

fn grid_strips_contour(region: &Region, options: &Options) -> Result<Solution> {
    on_grid(region, options, ortho_strips_contour)
}

fn grid_star_contour(region: &Region, options: &Options) -> Result<Solution> {
    on_grid(region, options, ortho_star_contour)
}

fn grid_corollary4(region: &Region, options: &Options) -> Result<Solution> {
    on_grid(region, options, ortho_corollary4)
}
