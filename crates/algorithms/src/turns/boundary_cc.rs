//! `boundary-cc`: the minimum-turn cycle cover of the boundary (Section 4.1 and Theorem 4.1 of
//! *Optimal covering tours with turn costs*).
//!
//! # Construction
//! A boundary link is the offset, half a pixel inwards, of a maximal boundary edge, shrunk by
//! half a pixel at each end: on the grid, a maximal run of pixels in one row (column) that all
//! have their south, or all their north (west, east) side on the boundary; see
//! [`boundary_links`] for links sharing a line, and for the one-pixel vertical links we leave
//! out. By Lemma 4.1 an optimal cycle cover of the boundary contains every link within one of
//! its own links, so it is the links joined end to end by connecting paths. A link's ports
//! leave it straight on, outwards (two collinear disjoint links are at turn distance 0); a
//! minimum-weight perfect matching of the ports under the turn distance (the partner pair of a
//! one-pixel link at least 4) joins the links into a cycle cover. Beyond a few hundred ports
//! the matching is still exact over all pairs: the ports' turn distance plus 2 is a graph
//! metric ([`link_graph_matching`](crate::endpoint_matching) has the argument).
//!
//! # Why the matching's minimum is the optimum
//! Say a *heading walk* is a closed sequence of states (pixel, heading), each step a move
//! forward (cost 0) or a quarter turn in place (cost 1). The checker's count of a closed walk
//! of m ≥ 2 pixels is the least cost of a heading walk through its pixels (at each pixel the
//! smaller rotation from the heading in to the heading out: 0, 1 or 2); a one-pixel walk counts
//! 4, the full rotation. A perfect matching M of the ports closes heading walks (links straight,
//! pairs by cheapest paths, each pair's price its turn distance, at least 4 for the partners of
//! a one-pixel link) whose costs add up to w(M).
//! - *The cover costs at most w(M).* A heading walk that moves costs at least the checker's
//!   count of its pixels. One that never moves consists of one-pixel links at one pixel p
//!   joined in place; at p there is at most one horizontal and one vertical link, and we keep
//!   both only when one of them has several pixels, which moves, so the walk is one one-pixel
//!   link joined to itself: priced at least 4, counted 4. (Before this rule, a one-pixel
//!   horizontal and a one-pixel vertical link at p could close a still walk priced 1 + 1 = 2
//!   and counted 4: a certified-optimal cover 2 turns above the optimum.) `drop_still_duplicates` may only lower the count.
//! - *Every cycle cover C costs at least the minimum.* By Lemma 4.1 (the paper's, with our
//!   grid reading of shared lines), C's walks can be taken to contain every link, kept or left
//!   out, as part of a straight stretch, without more turns; a one-pixel link at p is contained
//!   in any heading walk that has its orientation at p (every visit of p by a moving walk does:
//!   p lacks a neighbour on that axis, so a walk cannot pass it straight across). List, along
//!   each of C's heading walks, one occurrence of every kept link (each link once over all of
//!   C): consecutive listed links are joined by the heading walk between them, which costs at
//!   least their ports' turn distance; a walk that lists one link only costs at least 4 (every
//!   closed walk does), which covers the floor of a one-pixel link; a walk that lists none
//!   costs at least 0. Leaving a link out only drops a listing (the heading walk through it is
//!   one from its predecessor to its successor). So C costs at least the weight of a perfect
//!   matching of the kept ports, hence at least the minimum.
//!
//! So with a matching proven minimum (`matching_optimal = 1`) the cover is a minimum-turn cycle
//! cover of the boundary pixels, and both inequalities are tight: its checker count is w(M).
//! The links left out are still covered: a left-out link's pixel lies on the kept one-pixel
//! horizontal link. The step from Lemma 4.1 is the paper's and is not re-proven here; the tests
//! and `examples/boundary_search.rs` compare the cover with the exact `cc-turns` solver.
//!
//! # Guarantee
//! Exact for the boundary pixels P̄ (Theorem 4.1). When every pixel is a boundary pixel the
//! cover is a cycle cover of the whole region, and optimal: every cycle cover of the region is
//! one of its boundary. Only a matching proven minimum is used: otherwise `boundary-cc` fails
//! rather than certify.

use crate::error::{Error, Result};
use crate::matching::turn_distance::{Port, bit};
use crate::matching::{COMPLETE_LIMIT, PortMatching, join_links, match_ports};
use crate::region::{Dir, Region};
use crate::topology::is_boundary;
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Objective};

/// A boundary link: first and last pixel (west to east, or south to north).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoundaryLink {
    pub first: usize,
    pub last: usize,
    pub horizontal: bool,
}

/// The boundary links the matching joins, in pixel order of their first pixel, horizontal
/// first.
///
/// Links along the south and the north side of one row lie on the same line (the row's pixel
/// centres); where they share a pixel we take their union as one link, since a cycle link
/// covering one of them passes through the shared pixel and continues along the other (our
/// grid reading of Lemma 4.1; without it a width-1 ring would need two rounds).
///
/// A one-pixel vertical link at a pixel that also has a one-pixel horizontal link is left
/// out: the horizontal one covers its pixel, and kept, the two could be matched into a cycle
/// that never moves, priced 2 by the matching but 4 by the checker (the module docs prove
/// that leaving it out keeps the matching's minimum equal to the optimum).
///
/// # Complexity
/// O(N).
pub fn boundary_links(region: &Region) -> Vec<BoundaryLink> {
    let mut links = Vec::new();
    for horizontal in [true, false] {
        let (back, fwd) = if horizontal {
            (Dir::W, Dir::E)
        } else {
            (Dir::S, Dir::N)
        };
        let sides = if horizontal {
            [Dir::N, Dir::S]
        } else {
            [Dir::E, Dir::W]
        };
        let on_link = |j: usize| sides.iter().any(|&d| region.neighbor(j, d).is_none());
        for i in 0..region.len() {
            if !on_link(i) || region.neighbor(i, back).is_some_and(on_link) {
                continue;
            }
            let mut last = i;
            while let Some(j) = region.neighbor(last, fwd).filter(|&j| on_link(j)) {
                last = j;
            }
            links.push(BoundaryLink {
                first: i,
                last,
                horizontal,
            });
        }
    }
    let mut one_pixel_horizontal = vec![false; region.len()];
    for l in links.iter().filter(|l| l.horizontal && l.first == l.last) {
        one_pixel_horizontal[l.first] = true;
    }
    links.retain(|l| l.horizontal || l.first != l.last || !one_pixel_horizontal[l.first]);
    links
}

/// The ports of the boundary links (two per link, in link order: first pixel leaving
/// backwards, last pixel leaving forwards), each one's partner (the other end of its link),
/// and the floor of every port's pair with its partner.
pub fn boundary_ports(links: &[BoundaryLink]) -> (Vec<Port>, Vec<usize>, Vec<u32>) {
    let mut ports = Vec::with_capacity(2 * links.len());
    for l in links {
        let (back, fwd) = if l.horizontal {
            (Dir::W, Dir::E)
        } else {
            (Dir::S, Dir::N)
        };
        ports.push(Port {
            pixel: l.first,
            leave: bit(back),
        });
        ports.push(Port {
            pixel: l.last,
            leave: bit(fwd),
        });
    }
    let partner: Vec<usize> = (0..ports.len()).map(|i| i ^ 1).collect();
    // A one-pixel link closed on itself is a still walk of 4 turns.
    let floor: Vec<u32> = (0..ports.len())
        .map(|i| {
            if links[i / 2].first == links[i / 2].last {
                4
            } else {
                0
            }
        })
        .collect();
    (ports, partner, floor)
}

/// The minimum-turn cycle cover of the boundary links, with its matching.
///
/// # Complexity
/// The matching dominates: see `match_ports`. Beyond `COMPLETE_LIMIT` ends it is exact
/// over all pairs through the ray graph (measured for all of `thin-merge`: 0.06 s for 682
/// ends, 0.74 s for 8,274, 5.7 s for 24,672).
pub fn boundary_cycle_cover(region: &Region) -> Result<(CycleCover, PortMatching)> {
    let links = boundary_links(region);
    let (ports, partner, floor) = boundary_ports(&links);
    let matching = match_ports(region, &ports, &partner, &floor)?;
    if !matching.optimal {
        return Err(Error::solver(format!(
            "boundary-cc is exact only with a matching proven minimum: {} ports exceed {}, the \
             ray graph did not apply, and the LP bound {} stays below its weight {}",
            ports.len(),
            COMPLETE_LIMIT,
            matching.lower_bound,
            matching.total
        )));
    }
    let pairs: Vec<(usize, usize)> = links.iter().map(|l| (l.first, l.last)).collect();
    let cover = join_links(region, &pairs, &ports, &matching)?;
    Ok((drop_still_duplicates(cover), matching))
}

/// Removes closed walks of one pixel whose pixel another kept walk visits.
///
/// The only cycle the matching can close without moving is a one-pixel link joined to itself
/// (see [`boundary_links`]), priced 4 and counted 4. Such a walk covers nothing another walk
/// does not, so we drop it when its pixel is visited elsewhere (our treatment of a case the
/// paper does not discuss). This only lowers the count, and with a matching proven minimum it
/// never applies: the cover would then beat the minimum, which the module docs prove is a
/// lower bound.
pub(crate) fn drop_still_duplicates(cover: CycleCover) -> CycleCover {
    let mut visited: std::collections::HashSet<crate::region::Pixel> = cover
        .cycles
        .iter()
        .filter(|w| w.len() > 1)
        .flatten()
        .copied()
        .collect();
    let cycles = cover
        .cycles
        .into_iter()
        .filter(|w| w.len() > 1 || visited.insert(w[0]))
        .collect();
    CycleCover::new(cycles)
}

/// `boundary-cc` applies when every pixel is a boundary pixel (then it covers the region). A
/// cycle cover needs no connectivity: on a region of several components it is a cycle cover
/// of each (the matching never pairs ports of different components, which no path joins).
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::precondition("the region is empty"));
    }
    match (0..region.len()).find(|&i| !is_boundary(region, i)) {
        None => Ok(()),
        Some(i) => Err(Error::precondition(format!(
            "boundary-cc covers only boundary pixels, and pixel {} has all four neighbours",
            region.pixel(i)
        ))),
    }
}

/// Runs `boundary-cc`: the boundary cycle cover (objective `cc-turns`), certificates `w_m`,
/// `links` and the matching's (`matching_complete`, `matching_optimal`, always 1 here,
/// `matching_lower_bound`, `matching_candidates`).
pub(crate) fn run(region: &Region, opts: &crate::Options) -> Result<crate::Solution> {
    if opts.coverage4 {
        return Err(Error::precondition(
            "--coverage4 rewrites tours (Theorem 5.6 of the turn-cost paper); boundary-cc \
             outputs only a cycle cover, so there is no tour to rewrite",
        ));
    }
    let (cover, matching) = boundary_cycle_cover(region)?;
    let mut sol = crate::Solution::default();
    sol.outputs.push(crate::Output {
        objective: crate::Objective::CcTurns,
        cover,
    });
    sol.certificates
        .insert("w_m".to_string(), matching.total as i64);
    sol.certificates
        .insert("links".to_string(), (matching.mate.len() / 2) as i64);
    sol.certificates.extend(matching.certificates());
    Ok(sol)
}

/// The registry entry of `boundary-cc`: the minimum-turn cycle cover of the boundary links by a
/// minimum-weight perfect matching of their ports (`run`).
///
/// # Guarantee
///
/// When every pixel is a boundary pixel the cover of the boundary covers the region, and the
/// matching's minimum is the optimal cycle cover's turns (Theorem 4.1 and Lemma 4.1 of *Optimal
/// covering tours with turn costs*, in our grid reading: module docs, "Why the matching's
/// minimum is the optimum"). Registered as `cc-turns <= OPT` (Theorem 4.1, our reading) on every
/// region of boundary pixels only, several components allowed. When the matching cannot be
/// proven minimum the run fails with [`Error::Solver`] rather than
/// report an unproven cover.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("boundary-cc").unwrap();
/// let value = |objective: Objective| {
///     let report = algorithm.run_checked(&region, &Options::default(), objective).unwrap();
///     assert!(report.valid);
///     objective.value_of(&report)
/// };
/// assert_eq!(value(Objective::CcTurns), 4);
/// // Every pixel of a 4 x 2 rectangle is a boundary pixel; one rectangle walk, 4 turns, optimal.
/// ```
pub const ALGORITHM: Algorithm = Algorithm {
    name: "boundary-cc",
    summary: "minimum-turn cycle cover of the boundary links by a minimum-weight perfect matching (regions of boundary pixels only)",
    objectives: &[Objective::CcTurns],
    guarantees: &[Guarantee::vs_opt(
        Objective::CcTurns,
        1,
        1,
        &crate::theorems::TURNS_THM_4_1,
        "Theorem 4.1 of Optimal covering tours with turn costs",
    )],
    claims: &[crate::theorems::Claim::reading(
        &crate::theorems::TURNS_THM_4_1,
        &[crate::Objective::CcTurns],
        "boundary links on pixels, collinear links sharing a pixel united (module docs of boundary_cc)",
    )],
    requires: "every pixel a boundary pixel (several components allowed)",
    precondition,
    run,
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};

    #[test]
    fn links_of_a_rectangle_and_an_l() {
        assert_eq!(boundary_links(&Region::rectangle(3, 2)).len(), 4);
        // An L: six boundary edges, the two along the bottom row's sides one link.
        let l = Region::from_ascii("#.\n##\n");
        assert_eq!(boundary_links(&l).len(), 4);
    }

    #[test]
    fn ring_and_corridor_covers() {
        // A width-1 ring: one cycle with 4 turns.
        let ring = Region::from_ascii("####\n#..#\n#..#\n####\n");
        let (cover, m) = boundary_cycle_cover(&ring).unwrap();
        let rep = check(&ring, &cover, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!((rep.turns, m.total), (4, 4));
        // A corridor: out and back, 4 turns.
        let bar = Region::rectangle(5, 1);
        let (cover, _) = boundary_cycle_cover(&bar).unwrap();
        assert_eq!(check(&bar, &cover, Mode::Milling).turns, 4);
        // One pixel: a still walk, 4 turns.
        let dot = Region::rectangle(1, 1);
        let (cover, _) = boundary_cycle_cover(&dot).unwrap();
        assert_eq!(check(&dot, &cover, Mode::Milling).turns, 4);
    }
}
