//! `strips-contour`: our reading of Theorem 5.7 of *Optimal covering tours with turn costs*
//! (min-turn milling of orthogonal polygons with arbitrary coordinates; the paper: a 4.5-approx
//! cycle cover and a 6.25-approx tour), built like Corollary 4 of *Lawn mowing and milling*
//! ([`corollary4`](super::corollary4)) with the turn algorithm of Theorem 5.5 inside.
//!
//! The paper's proof idea is one sentence: "Combine the 3.75-approximation (for covering the
//! interior) with a boundary tour modified to cover subpixels near reflex vertices." We read
//! the boundary tour as the contour δB of the erosion, which covers every point the interior
//! pixels miss (near reflex vertices and along non-integral edges alike).
//!
//! # The construction
//!
//! 1. [`feasibility`]: the piece B of centre positions that mills P (or the refusal).
//! 2. Interior: R_N, the integer pixels whose centre lies in B, split into grid components
//!    R_1, …, R_k. Each gets the registered `strips-matching` (Theorem 5.5: a minimum strip
//!    cover of s_i strips whose ends are joined by a minimum-weight matching M_i under the turn
//!    distance; a cycle cover of at most 2s_i + w(M_i) turns, and its merged tour).
//! 3. Boundary: the closed walks of δB ([`Erosion::contour`]).
//! 4. Pruning (our addition): the items, each component's cycle cover and each δB walk, are
//!    tried one by one, and one is dropped when the other kept items still mill P, decided by
//!    the exact checker. Three orders are tried: decreasing cycle-cover turns, the δB walks
//!    first, decreasing tour turns. On integral polygons R_N mills P, and the second order
//!    drops δB, so the output is never worse than Theorem 5.5's; on slivers (B narrower than
//!    1) the contour often mills P alone and the pixels go.
//! 5. Cycle cover (objective `cc-turns`): the cycles of the kept set with the fewest turns.
//! 6. Tour (objective `turns`): for each kept set, the kept components' merged tours and the
//!    kept δB walks joined by a spanning tree of straight links from pixel centres to δB, each
//!    walked there and back (the `join` module, shared with Corollary 4), ranked by the turns
//!    a link adds, then by length. When the kept items cannot be joined that way (a dropped item was the only
//!    way between them), dropped items are added back, fewest turns first, until they can
//!    (certificate `rejoined`); the joined walk with the fewest turns is the tour.
//!
//! # Why the outputs mill P
//!
//! Every swept square is centred in B (pixel centres of R_N by definition, δB ⊆ B, links by
//! the `join` module's argument), so nothing leaves P. Coverage is Corollary 4's argument: for
//! p ∈ P the centres whose square covers p form S_p = p + [−½, ½]², which meets B. If S_p
//! meets δB, the contour covers p; otherwise S_p lies in B's interior, so the pixel centre in
//! S_p is in B and its pixel, in R_N, is covered by the interior cycles. An item is dropped
//! only when the exact checker says the rest mills P. The tour visits every pixel of the
//! components it joins (each one's merged tour does) and walks every δB walk it joins, a
//! superset of a kept set, so it mills P too.
//!
//! # What is proven, and what is not
//!
//! Proven (and asserted on every output in tests/ortho_strips_contour.rs):
//!
//! - Both outputs mill P exactly ([`check`](super::check)).
//! - Cycle cover: turns = Σ_{kept i} cc_i + Σ turns(kept δB walks) ≤ Σ_i cc_i + turns(δB),
//!   with cc_i ≤ 2s_i + w(M_i).
//! - Tour: turns ≤ Σ_i tour_i + Σ turns(δB walks) + 4·links, over the joined items, tour_i the
//!   merged tour of R_i. Splicing a there-and-back link at a vertex reached with heading a and left with b
//!   replaces t(a, b) by t(a, L) + t(−L, b) = 2 + t(a, L) − t(L, b), at most t(a, b) + 2 by the
//!   triangle inequality of the turn metric t; the same at the far end; see the `join` module
//!   for still walks and links of length 0.
//! - Lower bound (certificate `lower_bound`): [`turn_lower_bound`](super::turn_lower_bound),
//!   the forced convex-corner turns and independent points of `crates/core/src/ortho/turn_bound.rs`.
//!
//! Not proven: any ratio against the optimum. The paper's 4.5 and 6.25 would need
//! Σ_i OPT_cc(R_i) ≤ OPT_cc(P) (a cover of P restricted to the pixels of R_i is not a cover
//! of R_i in the grid model: it may turn between pixel centres) and turns(δB) ≤ 2·OPT_cc(P)
//! (the paper's boundary cover is a minimum one, Theorem 4.1; δB may turn at corners of B no
//! cover needs, and Lemma 4.1 does not cover the reflex subpixels the paper mentions). So no
//! guarantee is registered; the claims rows measure the paper's factors against the proven
//! lower bounds, and against exact optima on integral regions, where the output is Theorem
//! 5.5's (whose 2.5 and 3.75 are proven when `matching_optimal = 1`).
//!
//! # `star-contour`: Table 1's star-cover line (10 / 12 / 4 / 4)
//!
//! Table 1 of the paper lists a second line for orthogonal polygons, 10 for cycle covers, 12 for
//! tours, 4 on length and coverage: the star cover of Theorems 5.1–5.2 (d = 2). The text gives
//! no construction for non-integral polygons. [`star_contour`] is the same construction as
//! above with the registered `star-cover` in step 2. On integral polygons it is `star-cover`
//! (the pruning drops δB) and its claims there are the grid theorems'. On non-integral ones
//! nothing is proven: the star argument needs the rook's star (its two strips) to cover every
//! point the rook attacks, and a rook in the continuum is attacked from a whole unit box of
//! centre positions, whose strips are not two (a star is not a bounded number of strips); so
//! the rows measure the table's factors against the proven lower bounds.
//!
//! # Complexity
//! `strips-matching` on each component (O(N^2.5) for the strip cover, plus its matching), one
//! exact check per item (O((N + n) log(N + n)) each), and the joining (O(E·M) for the
//! candidate links, E pixel sides on the edge of R_N, M contour segments).

use super::join::{Joined, Rank, join};
use crate::error::{Error, Result};
use crate::region::{Dir, Pixel, Region};
use crate::topology;
use crate::{self as algorithms, Objective, Options};
use mowmill_core::ortho::Tour;
use mowmill_core::ortho::turn_lower_bound;
use mowmill_core::ortho::{Point, Polygon};
use mowmill_core::ortho::{check, turn_cost};
use mowmill_core::ortho::{feasibility, kept_interior_pixels};
use serde::Serialize;
use std::collections::HashMap;

/// What the construction used (never the outputs' own cost: [`check`] recounts it).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Certificates {
    /// Pixels of R_N (centre in the kept piece of B).
    pub pixels: usize,
    /// Grid components of R_N, and how many of them the cycle cover keeps.
    pub components: usize,
    pub components_kept: usize,
    /// Σ s_i, the strips of the components' minimum strip covers.
    pub strips: usize,
    /// Σ w(M_i), the components' matching weights.
    pub matching_turns: u64,
    /// Whether every component's matching is proven minimum (`strips-matching`'s
    /// `matching_optimal`; `strips-contour` only, as are `strips` and `matching_turns`).
    pub matching_optimal: bool,
    /// Cycles and turns of the kept components' cycle covers.
    pub interior_cycles: usize,
    pub interior_cc_turns: u64,
    /// Turns of the merged tours of the components the tour joins.
    pub interior_tour_turns: u64,
    /// Walks of δB, and how many of them were kept (the others were not needed).
    pub contour_walks: usize,
    pub contour_kept: usize,
    /// Turns of the kept δB walks, and of the δB walks the tour joins.
    pub contour_turns: u64,
    pub tour_contour_turns: u64,
    /// How many dropped items the tour joins again (step 6).
    pub rejoined: u64,
    /// Links of the spanning tree, and the turns they add counted as if each were alone at its
    /// ends (at most 4 each).
    pub links: usize,
    pub link_turns: i64,
    /// [`turn_lower_bound`](super::turn_lower_bound)`.best()`: a proven lower bound on the
    /// turns of any cycle cover or tour.
    pub lower_bound: u64,
    /// Σ rooks of the components' star covers (`star-contour` only; 0 for `strips-contour`).
    pub rooks: usize,
}

/// The outputs of [`strips_contour`].
#[derive(Clone, Debug)]
pub struct StripsContour {
    /// The cycle cover (interior cycle covers and kept contour walks).
    pub cycle_cover: Tour,
    /// One closed walk.
    pub tour: Tour,
    pub certificates: Certificates,
}

/// A grid component of R_N with `strips-matching`'s cycle cover and merged tour of it.
struct Component {
    pixels: Vec<Pixel>,
    cover: Vec<Vec<Point>>,
    tour: Vec<Point>,
}

/// The turn cost of a closed walk, counted as the checker counts it.
pub fn walk_turns(walk: &[Point]) -> u64 {
    let m = walk.len();
    let headings: Vec<Dir> = (0..m)
        .filter_map(|i| {
            let (a, b) = (walk[i], walk[(i + 1) % m]);
            use std::cmp::Ordering::*;
            match (b.x.cmp(&a.x), b.y.cmp(&a.y)) {
                (Greater, Equal) => Some(Dir::E),
                (Less, Equal) => Some(Dir::W),
                (Equal, Greater) => Some(Dir::N),
                (Equal, Less) => Some(Dir::S),
                _ => None,
            }
        })
        .collect();
    turn_cost(&headings)
}

/// Our reading of Theorem 5.7's cycle cover and tour of `polygon` (module docs).
///
/// # Arguments
/// A polygon (holes allowed); `options` go to `strips-matching` on each component.
///
/// # Returns
/// The cycle cover, the tour and the [`Certificates`].
///
/// # Errors
/// [`Error::Invalid`] with the [`feasibility`] refusal when the polygon cannot be milled;
/// when some contour walk cannot be linked to the rest by a straight link from a pixel centre
/// (only with holes); when exact coordinates overflow.
///
/// # Examples
/// ```
/// use mowmill_algorithms::Options;
/// use mowmill_algorithms::ortho::{Polygon, check, strips_contour};
/// let p = Polygon::parse("POLYGON ((0 0, 4.25 0, 4.25 2.5, 0 2.5, 0 0))", "p.wkt")?;
/// let out = strips_contour(&p, &Options::default())?;
/// assert!(check(&p, &out.cycle_cover)?.valid);
/// let report = check(&p, &out.tour)?;
/// assert!(report.valid && out.tour.is_tour());
/// assert!(report.turns >= out.certificates.lower_bound);
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn strips_contour(polygon: &Polygon, options: &Options) -> Result<StripsContour> {
    contour_construction(polygon, options, &algorithms::strips_matching::ALGORITHM)
}

/// Table 1's star-cover line for orthogonal polygons, our reading: the same construction as
/// [`strips_contour`] with the registered `star-cover` (Theorem 5.1 on pixels: greedy rooks,
/// one walk of at most 10 turns per star, merged) on each component of R_N instead of
/// `strips-matching` (module docs; the paper gives no proof for this line).
///
/// # Errors
/// As [`strips_contour`].
pub fn star_contour(polygon: &Polygon, options: &Options) -> Result<StripsContour> {
    contour_construction(polygon, options, &algorithms::star_cover::ALGORITHM)
}

/// Steps 1–6 of the module docs with the grid algorithm `interior` (which outputs a cycle cover
/// and a tour; called directly, not looked up in the registry) on each component of R_N.
fn contour_construction(
    polygon: &Polygon,
    options: &Options,
    interior: &algorithms::Algorithm,
) -> Result<StripsContour> {
    let erosion = feasibility(polygon).map_err(|e| Error::invalid(e.to_string()))?;
    let region = kept_interior_pixels(polygon, &erosion)?;
    let labels = topology::components(&region);

    // Step 2: the interior algorithm on each component.
    let interior_algorithm = interior;
    let interior = interior.name;
    let (mut strips, mut matching_turns, mut matching_optimal) = (0usize, 0u64, true);
    let mut rooks = 0usize;
    let mut components: Vec<Component> = Vec::new();
    for k in 0..labels.count {
        let pixels: Vec<Pixel> = (0..region.len())
            .filter(|&i| labels.label[i] as usize == k)
            .map(|i| region.pixel(i))
            .collect();
        let component = Region::from_pixels(pixels.iter().copied())?;
        (interior_algorithm.precondition)(&component)?;
        let solution = (interior_algorithm.run)(&component, options)?;
        let output = |objective: Objective| {
            solution
                .outputs
                .iter()
                .find(|o| o.objective == objective)
                .map(|o| Tour::from_cover(&o.cover))
                .ok_or_else(|| Error::invalid(format!("{interior} returned no {objective}")))
        };
        let certificate = |key: &str| solution.certificates.get(key).copied().unwrap_or(0);
        strips += certificate("s") as usize;
        matching_turns += certificate("w_m") as u64;
        matching_optimal &= certificate("matching_optimal") == 1;
        rooks += certificate("rooks") as usize;
        let cover = output(Objective::CcTurns)?.cycles;
        let mut tour = output(Objective::Turns)?.cycles;
        if tour.len() != 1 {
            return Err(Error::invalid(format!(
                "{interior} returned no single tour"
            )));
        }
        components.push(Component {
            pixels,
            cover,
            tour: tour.remove(0),
        });
    }

    // Steps 3 and 4: drop what the rest makes unnecessary, in three orders.
    let contour = erosion.contour();
    let nc = components.len();
    let items = nc + contour.len();
    let cc_turns_of = |item: usize| -> u64 {
        if item < nc {
            components[item].cover.iter().map(|w| walk_turns(w)).sum()
        } else {
            walk_turns(&contour[item - nc])
        }
    };
    let tour_turns_of = |item: usize| -> u64 {
        if item < nc {
            walk_turns(&components[item].tour)
        } else {
            walk_turns(&contour[item - nc])
        }
    };
    let cycles_of = |item: usize| -> Vec<Vec<Point>> {
        if item < nc {
            components[item].cover.clone()
        } else {
            vec![contour[item - nc].clone()]
        }
    };
    let prune = |order: &[usize]| -> Result<Vec<bool>> {
        let mut keep = vec![true; items];
        for &item in order {
            keep[item] = false;
            let cycles: Vec<Vec<Point>> = (0..items)
                .filter(|&i| keep[i])
                .flat_map(cycles_of)
                .collect();
            if cycles.is_empty() || !check(polygon, &Tour { cycles })?.valid {
                keep[item] = true;
            }
        }
        Ok(keep)
    };
    let by = |key: &dyn Fn(usize) -> (bool, u64)| -> Vec<usize> {
        let mut order: Vec<usize> = (0..items).collect();
        order.sort_by_key(|&item| (key(item), item));
        order
    };
    let mut kept_sets = Vec::new();
    for order in [
        by(&|i| (false, u64::MAX - cc_turns_of(i))),
        by(&|i| (i < nc, u64::MAX - cc_turns_of(i))),
        by(&|i| (false, u64::MAX - tour_turns_of(i))),
    ] {
        let keep = prune(&order)?;
        if !kept_sets.contains(&keep) {
            kept_sets.push(keep);
        }
    }
    let cc_total =
        |keep: &[bool]| -> u64 { (0..items).filter(|&i| keep[i]).map(cc_turns_of).sum() };

    // Step 5: the cycle cover, from the kept set with the fewest turns.
    let keep = kept_sets
        .iter()
        .min_by_key(|keep| cc_total(keep))
        .expect("three orders")
        .clone();
    let cycle_cover = Tour {
        cycles: (0..items)
            .filter(|&i| keep[i])
            .flat_map(cycles_of)
            .collect(),
    };

    // Step 6: the tour over a kept set; where its items cannot be joined (a dropped item was
    // the only way between them), dropped items are added back, fewest turns first, until
    // they can.
    let tour_over = |keep: &[bool]| -> Result<(Joined, Vec<bool>, usize)> {
        let mut used = keep.to_vec();
        let mut back: Vec<usize> = (0..items).filter(|&i| !keep[i]).collect();
        back.sort_by_key(|&item| (tour_turns_of(item), item));
        let mut back = back.into_iter();
        let mut rejoined = 0;
        loop {
            let kept_components: Vec<usize> = (0..nc).filter(|&k| used[k]).collect();
            let kept_region = Region::from_pixels(
                kept_components
                    .iter()
                    .flat_map(|&k| components[k].pixels.iter().copied()),
            )?;
            let walk_of: HashMap<Pixel, usize> = kept_components
                .iter()
                .enumerate()
                .flat_map(|(j, &k)| components[k].pixels.iter().map(move |&p| (p, j)))
                .collect();
            let component_of = |p: Pixel| walk_of[&p];
            let walks: Vec<Vec<Point>> = (0..contour.len())
                .filter(|&w| used[nc + w])
                .map(|w| contour[w].clone())
                .collect();
            let tours: Vec<Vec<Point>> = kept_components
                .iter()
                .map(|&k| components[k].tour.clone())
                .collect();
            match join(&kept_region, &component_of, tours, walks, Rank::Turns) {
                Ok(joined) => return Ok((joined, used, rejoined)),
                Err(e) => match back.next() {
                    Some(item) => {
                        used[item] = true;
                        rejoined += 1;
                    }
                    None => return Err(e),
                },
            }
        }
    };
    // The joined walk with the fewest turns over the kept sets.
    let mut best: Option<(Joined, Vec<bool>, usize)> = None;
    let mut failure = None;
    for keep in &kept_sets {
        match tour_over(keep) {
            Ok(found) => {
                if best
                    .as_ref()
                    .is_none_or(|b| walk_turns(&found.0.walk) < walk_turns(&b.0.walk))
                {
                    best = Some(found);
                }
            }
            Err(e) => failure = Some(e),
        }
    }
    let (joined, used, rejoined) = match (best, failure) {
        (Some(best), _) => best,
        (None, Some(e)) => return Err(e),
        (None, None) => unreachable!("at least one kept set"),
    };
    let sum = |range: std::ops::Range<usize>, set: &[bool], f: &dyn Fn(usize) -> u64| -> u64 {
        range.filter(|&i| set[i]).map(f).sum()
    };
    let certificates = Certificates {
        pixels: region.len(),
        components: nc,
        components_kept: (0..nc).filter(|&k| keep[k]).count(),
        strips,
        matching_turns,
        matching_optimal,
        interior_cycles: (0..nc)
            .filter(|&k| keep[k])
            .map(|k| components[k].cover.len())
            .sum(),
        interior_cc_turns: sum(0..nc, &keep, &cc_turns_of),
        interior_tour_turns: sum(0..nc, &used, &tour_turns_of),
        contour_walks: contour.len(),
        contour_kept: (nc..items).filter(|&i| keep[i]).count(),
        contour_turns: sum(nc..items, &keep, &cc_turns_of),
        tour_contour_turns: sum(nc..items, &used, &tour_turns_of),
        rejoined: rejoined as u64,
        links: joined.links.len(),
        link_turns: joined.links.iter().map(|l| l.turns).sum(),
        lower_bound: turn_lower_bound(polygon, &erosion)?.best(),
        rooks,
    };
    Ok(StripsContour {
        cycle_cover,
        tour: Tour::new(joined.walk),
        certificates,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sliver_is_its_contour() {
        // Width 1.5: no pixel centre at height ½ + k lies in B = [½, 3½] × [½, 1] except on
        // y = ½; the contour alone must go.
        let p = Polygon::parse("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))", "s").unwrap();
        let out = strips_contour(&p, &Options::default()).unwrap();
        assert!(check(&p, &out.cycle_cover).unwrap().valid);
        let report = check(&p, &out.tour).unwrap();
        assert!(report.valid && out.tour.is_tour());
        assert_eq!(out.certificates.contour_kept, 1);
        assert_eq!(report.turns, 4);
    }
}
