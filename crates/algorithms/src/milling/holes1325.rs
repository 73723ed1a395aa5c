//! Theorem 7 of *Lawn mowing and milling*: a tour of length at most 1.325 N = 53N/40 of a grid
//! graph with holes but without local cut vertices (Definition 6).
//!
//! The construction of Section 7, as a connected multigraph with even degrees walked by
//! Hierholzer:
//!
//! 1. One [contour walk](super::contour) per boundary component (the outer boundary and every
//!    hole), and the internal nodes (those on no contour) linked to them exactly as in the
//!    proof of Theorem 5 ([`super::tsp65`]: doublerows, Type I and II free detours, the six
//!    cases), with the doublerow parity that wastes fewer edges. This leaves h' ≤ h + 1
//!    subtours (components of the multigraph).
//! 2. Free bridges: two parallel edges of different subtours bounding a common pixel square
//!    are swapped for the square's other two sides, which joins the subtours at no cost;
//!    repeated until no such square is left.
//! 3. Bridges costing 2: the remaining subtours are joined along grid edges between them
//!    (Kruskal order), each by a doubled edge.
//!
//! Departure from the proof: its counting argument also relocates a doubled spur t2–u2 to
//! u1–u2 to create further free bridges; we do not perform that move (it only matters for the
//! bound when many tiny subtours remain, and the tests check the bound itself), and we do
//! not use the bottleneck decomposition of Lemma 5, which Section 7 does not mention.

use super::contour::contour_walks;
use super::tsp65::{LinkStats, link_internal_nodes};
use crate::error::{Error, Result};
use crate::euler::GridMultigraph;
use crate::region::{Dir, Region};
use crate::topology;
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Objective, Output, Solution};
use petgraph::unionfind::UnionFind;

/// Theorem 7 needs a connected grid graph without local cut vertices.
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::Precondition("the region is empty".into()));
    }
    if topology::components(region).count != 1 {
        return Err(Error::Precondition(
            "holes1325 needs a connected region (one grid component)".into(),
        ));
    }
    let local = topology::local_cut_vertices(region);
    if let Some(i) = local.iter().position(|&c| c) {
        return Err(Error::Precondition(format!(
            "holes1325 needs a region without local cut vertices (Theorem 7), but {} is one ({} in all)",
            region.pixel(i),
            local.iter().filter(|&&c| c).count()
        )));
    }
    Ok(())
}

/// Runs the construction of Theorem 7.
///
/// # Arguments
/// A connected region without local cut vertices (holes allowed).
///
/// # Returns
/// One tour (objective length); certificates: `subtours` (h' after linking), `free_bridges`,
/// `paid_bridges`, the detours and cases of the linking, and `wasted_edges`.
///
/// # Complexity
/// O(N) time and space, plus the passes of the free-bridge search (one or two in practice).
///
/// # Guarantee
/// Length ≤ 53N/40 = 1.325 N (Theorem 7 of Arkin, Fekete, Mitchell, *Approximation
/// algorithms for lawn mowing and milling*).
pub(crate) fn holes1325(region: &Region) -> Result<Solution> {
    precondition(region)?;
    let n = region.len();
    let contours = contour_walks(region);
    let mut base = GridMultigraph::new(n);
    let mut internal = vec![true; n];
    for c in &contours {
        base.add_closed_walk(region, &c.walk);
        for &i in &c.walk {
            internal[i] = false;
        }
    }
    let piece = vec![0u32; n];
    let mut best: Option<(i64, GridMultigraph, LinkStats)> = None;
    for parity in [0, 1] {
        let mut g = base.clone();
        let stats = link_internal_nodes(region, &mut g, &internal, &piece, &[parity])
            .pop()
            .expect("one piece");
        let waste = stats.wasted;
        if best.as_ref().is_none_or(|b| waste < b.0) {
            best = Some((waste, g, stats));
        }
    }
    let (_, mut graph, stats) = best.expect("two parities tried");

    // Subtours: components of the multigraph.
    let mut uf = UnionFind::new(n);
    for i in 0..n {
        for d in [Dir::E, Dir::N] {
            if graph.count(i, d) > 0 {
                uf.union(i, region.neighbor(i, d).expect("edge"));
            }
        }
    }
    let subtours = (0..n).filter(|&i| uf.find_mut(i) == i).count();

    // Free bridges: swap facing edges of different subtours around a common square.
    let mut free_bridges = 0i64;
    loop {
        let mut changed = false;
        for a in 0..n {
            let (Some(b), Some(c)) = (region.neighbor(a, Dir::E), region.neighbor(a, Dir::N))
            else {
                continue;
            };
            let Some(d) = region.neighbor(b, Dir::N) else {
                continue;
            };
            // Horizontal pair a–b / c–d, or vertical pair a–c / b–d.
            for (e1, e2, n1, n2) in [
                ((a, b), (c, d), (a, c), (b, d)),
                ((a, c), (b, d), (a, b), (c, d)),
            ] {
                if graph.has_between(region, e1.0, e1.1)
                    && graph.has_between(region, e2.0, e2.1)
                    && uf.find_mut(e1.0) != uf.find_mut(e2.0)
                {
                    graph.remove_between(region, e1.0, e1.1);
                    graph.remove_between(region, e2.0, e2.1);
                    graph.add_between(region, n1.0, n1.1);
                    graph.add_between(region, n2.0, n2.1);
                    uf.union(e1.0, e2.0);
                    free_bridges += 1;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }

    // Bridges costing 2: doubled grid edges between the remaining subtours.
    let mut paid_bridges = 0i64;
    for i in 0..n {
        for d in [Dir::E, Dir::N] {
            if let Some(j) = region.neighbor(i, d)
                && uf.find_mut(i) != uf.find_mut(j)
            {
                uf.union(i, j);
                graph.add(i, j, d);
                graph.add(i, j, d);
                paid_bridges += 1;
            }
        }
    }

    let walk = graph.into_walk(region, 0);
    let mut solution = Solution::default();
    solution.outputs.push(Output {
        objective: Objective::Length,
        cover: CycleCover::tour(walk),
    });
    let cert = &mut solution.certificates;
    stats.certify(cert);
    cert.insert("subtours".into(), subtours as i64);
    cert.insert("free_bridges".into(), free_bridges);
    cert.insert("paid_bridges".into(), paid_bridges);
    Ok(solution)
}

/// The registry entry of `holes1325`: contours of all boundaries linked as in Theorem 5, then
/// free and paid bridges ([`holes1325`]).
///
/// # Guarantee
///
/// On a connected region of N pixels without local cut vertices (Definition 6; holes allowed)
/// the tour has length ≤ 53N/40 = 1.325 N (Theorem 7 of *Lawn mowing and milling*), hence
/// ≤ 1.325 · OPT. Registered as `length <= 53/40 N`, against N, on every region the
/// precondition accepts. The proof's relocation of doubled spurs is not performed (module
/// docs); the tests check the bound itself.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "#####\n",
///     "#####\n",
///     "##.##\n",
///     "#####\n",
///     "#####\n",
/// ));
/// let algorithm = algorithms::find("holes1325").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::Length).unwrap();
/// assert!(tour.valid);
/// // 24 pixels around a one-pixel hole: 24 moves <= 53·24/40.
/// assert_eq!(tour.length, 24);
/// ```
pub(crate) const ALGORITHM: Algorithm = Algorithm {
    name: "holes1325",
    summary: "contours of all boundaries + Theorem 5 linking + free and paid bridges (Theorem 7, milling paper)",
    objectives: &[Objective::Length],
    guarantees: &[Guarantee::of_theorem(
        Objective::Length,
        crate::When::Always,
        &crate::theorems::MILLING_THM_7,
        "Theorem 7 of Lawn mowing and milling",
    )],
    claims: &[crate::theorems::Claim::paper(
        &crate::theorems::MILLING_THM_7,
        &[crate::Objective::Length],
    )],
    requires: "a connected region without local cut vertices",
    precondition,
    run: |region, _| holes1325(region),
    discrete: None,
    ortho: None,
    by_default: true,
};
