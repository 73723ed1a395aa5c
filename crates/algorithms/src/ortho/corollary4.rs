//! Corollary 4 of *Lawn mowing and milling*: a milling tour of a rectilinear polygon with
//! arbitrary coordinates, within 11/5 of optimal (plus a constant) for simple polygons, by
//! combining the 6/5 tour of the integer pixels inside with a walk along the contour δB of
//! the erosion.
//!
//! # The construction
//!
//! 1. [`feasibility`]: the piece B of centre positions that mills P (or the refusal).
//! 2. R_N: the integer pixels whose centre lies in B ([`interior_pixels`], kept piece only),
//!    split into grid components. Each component gets the tour of the registered `tsp65`
//!    (Theorem 5, length ≤ (6N − 4)/5 for a hole-free component of N ≥ 2 pixels) when its
//!    precondition holds, else `milling25`; [`Certificates`] says how many took which.
//! 3. δB: the closed walks of [`Erosion::contour`].
//! 4. Joining (the paper says only "combining"): from pixel centres, straight axis-parallel
//!    links to the nearest contour point in each of the four directions are candidates; a
//!    minimum spanning tree of them (Kruskal, by length) ties every component tour and every
//!    contour walk together, and each tree link is walked there and back, splicing the walks
//!    at its ends (the `join` module, shared with `strips-contour`). A link lies in B: its
//!    pixel centre is in B, and if it is not on δB, it is an interior point of B and the open
//!    link meets no boundary point before its end.
//!
//! # Why the union mills P
//!
//! Every swept square is centred in B, so nothing leaves P. Let p ∈ P and S_p = p + [−½, ½]²,
//! the centres whose square covers p. The squares of B cover P, so S_p meets B. If S_p meets
//! δB, the contour walk covers p. Otherwise S_p, being connected, lies in the interior of B;
//! then the pixel centre in S_p (⌊p⌋ + ½, for p off the integer lines) is in B, its pixel is
//! in R_N and contains p, and the pixel tour covers it. (Points on integer lines follow by
//! closedness.) [`check`](super::check) confirms this exactly on every output in the tests.
//!
//! # Guarantee
//!
//! Lower bounds ([`LowerBounds`]), for any tour T milling P:
//!
//! - **Area:** L(T) ≥ area(P) − 1. The square starts with area 1, and a move of length ℓ sweeps
//!   a box of area ℓ + 1 that contains the square at its start, so adds at most ℓ.
//! - **Extent:** L(T) ≥ 2(w_B + h_B), w_B × h_B the bounding box of B. P's leftmost edge is
//!   covered only by centres on B's leftmost line (and so on for the other three sides), so the
//!   closed walk spans B's width twice and its height twice.
//! - **Contour (paper):** L(T) ≥ L_δB for simple P. The paper asserts it without proof. We
//!   have not proved it in general: the Crofton-style argument (each horizontal chord of the
//!   simply connected B separates it and must be crossed twice) needs that the tour visits
//!   both sides of every chord, which we could not derive from milling alone. It is tested
//!   against exact optima on small integral simple regions (tests/ortho_corollary4.rs). It is
//!   **false for polygons with holes**: for the 3 × 3 square with its centre pixel removed, B is
//!   a loop of zero width, L_δB = 16 (its outer and inner walk) and OPT = 8; there only the
//!   area and extent bounds are used.
//!
//! Length: L ≤ Σ_i L(tsp65 on component i) + L_δB + 2·Σ links, each link shorter than 1 (the
//! lowest pixel of a column sees δB straight below within distance < 1). For simple P and a
//! connected, hole-free R_N of N ≥ 2 pixels: L ≤ (6N − 4)/5 + L_δB + 2 and N ≤ area(P) ≤
//! OPT + 1, so with the paper's contour bound L ≤ 6/5·(OPT + 1) − 4/5 + OPT + 2 = 11/5·OPT + 12/5.
//! The paper's "11/5" is this, with its additive constant. Where it does not hold as stated:
//! R_N may split into k components (a non-integral neck holds no pixel), each with its own
//! tour and link: + O(k); a component with holes takes `milling25` (2.5, not 6/5); and
//! with holes in P the contour bound fails, so no ratio is claimed there.
//!
//! # Complexity
//! O(E·M) for the candidate links (E pixel sides on the edge of R_N, M contour segments) and
//! O(T + K log K) for the splicing (T tour points, K candidate links), plus the registered algorithms' time:
//! quadratic in the worst case, not the paper's O(n) (which works on trapezoids, not pixels).

use super::join::{Rank, add, distance, join, sub};
use crate as algorithms;
use crate::error::{Error, Result};
use crate::region::{Pixel, Region};
use crate::topology;
use mowmill_core::ortho::Rational;
use mowmill_core::ortho::Tour;
use mowmill_core::ortho::{Erosion, feasibility, kept_interior_pixels};
use mowmill_core::ortho::{Point, Polygon};
use serde::Serialize;

/// What the construction used (never the tour's own cost: [`check`](super::check) recounts it).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Certificates {
    /// Pixels of R_N with their centre in the kept piece of B.
    pub pixels: usize,
    /// Grid components of those pixels.
    pub components: usize,
    /// Components toured by `tsp65` (Theorem 5).
    pub tsp65: usize,
    /// Components toured by `milling25` (tsp65's precondition failed: a hole).
    pub milling25: usize,
    /// Walks of δB.
    pub contour_walks: usize,
    /// L_δB.
    pub contour_length: Rational,
    /// Links of the spanning tree, and their total length (each walked twice).
    pub links: usize,
    pub link_length: Rational,
    pub bounds: LowerBounds,
}

/// Lower bounds on the length of any tour milling the polygon (module docs).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct LowerBounds {
    /// area(P) − 1, at least 0.
    pub area: Rational,
    /// 2(w_B + h_B).
    pub extent: Rational,
    /// L_δB: a lower bound for simple polygons by the paper's claim; `None` with holes.
    pub contour: Option<Rational>,
}

impl LowerBounds {
    /// The largest of the bounds.
    pub fn best(&self) -> Rational {
        self.area
            .max(self.extent)
            .max(self.contour.unwrap_or(Rational::ZERO))
    }

    /// The largest of the proven ones (area, extent).
    pub fn proven(&self) -> Rational {
        self.area.max(self.extent)
    }
}

/// The length of a closed walk (closing move included).
pub fn walk_length(walk: &[Point]) -> Result<Rational> {
    let mut total = Rational::ZERO;
    for (i, &a) in walk.iter().enumerate() {
        total = add(total, distance(a, walk[(i + 1) % walk.len()])?)?;
    }
    Ok(total)
}

/// The lower bounds of `polygon`, whose kept erosion piece is `erosion`.
///
/// # Errors
/// Only if the area overflows the exact rationals.
pub fn lower_bounds(polygon: &Polygon, erosion: &Erosion) -> Result<LowerBounds> {
    let mut area = Rational::ZERO;
    for ring in polygon.rings() {
        let m = ring.corners.len();
        let mut twice = Rational::ZERO;
        for i in 0..m {
            let (a, b) = (ring.corners[i], ring.corners[(i + 1) % m]);
            let cross = sub(
                a.x.checked_mul(b.y)
                    .ok_or_else(|| Error::invalid("overflow"))?,
                b.x.checked_mul(a.y)
                    .ok_or_else(|| Error::invalid("overflow"))?,
            )?;
            twice = add(twice, cross)?;
        }
        let part = twice.abs().checked_mul(Rational::HALF).expect("halving");
        area = if ring.hole {
            sub(area, part)?
        } else {
            add(area, part)?
        };
    }
    let area = sub(area, Rational::ONE)?.max(Rational::ZERO);
    let boxes = erosion.rectangles();
    let extent = match (
        boxes.iter().map(|b| b.0.x).min(),
        boxes.iter().map(|b| b.1.x).max(),
        boxes.iter().map(|b| b.0.y).min(),
        boxes.iter().map(|b| b.1.y).max(),
    ) {
        (Some(x0), Some(x1), Some(y0), Some(y1)) => {
            let half = add(sub(x1, x0)?, sub(y1, y0)?)?;
            add(half, half)?
        }
        _ => Rational::ZERO,
    };
    let contour = if polygon.rings().iter().any(|r| r.hole) {
        None
    } else {
        let mut total = Rational::ZERO;
        for walk in erosion.contour() {
            total = add(total, walk_length(walk)?)?;
        }
        Some(total)
    };
    Ok(LowerBounds {
        area,
        extent,
        contour,
    })
}

/// Corollary 4's milling tour of `polygon` and what it used.
///
/// # Arguments
/// A polygon; with holes it still returns a valid tour (the bound is then not claimed, see
/// the module docs).
///
/// # Returns
/// One closed walk of the cutter's centre that mills the polygon, and its [`Certificates`].
///
/// # Errors
/// [`Error::Invalid`] with the [`feasibility`] refusal when the polygon cannot be milled;
/// when some contour walk cannot be linked to the rest (only possible with holes, when no
/// pixel centre sees that walk along a line); when neither `tsp65` nor `milling25` applies to a
/// component; when exact lengths overflow.
///
/// # Examples
/// ```
/// use mowmill_algorithms::ortho::{Polygon, check, corollary4};
/// let p = Polygon::parse("POLYGON ((0 0, 4.25 0, 4.25 2.5, 0 2.5, 0 0))", "p.wkt")?;
/// let (tour, certificates) = corollary4(&p)?;
/// assert!(check(&p, &tour)?.valid);
/// assert_eq!(certificates.tsp65, 1);
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn corollary4(polygon: &Polygon) -> Result<(Tour, Certificates)> {
    let erosion = feasibility(polygon).map_err(|e| Error::invalid(e.to_string()))?;
    let bounds = lower_bounds(polygon, &erosion)?;
    let region = kept_interior_pixels(polygon, &erosion)?;
    let labels = topology::components(&region);

    // Step 2: a tour per component.
    use algorithms::{milling25, tsp65};
    let (mut used65, mut used25) = (0, 0);
    let mut tours: Vec<Vec<Point>> = Vec::new();
    for k in 0..labels.count {
        let pixels = (0..region.len())
            .filter(|&i| labels.label[i] as usize == k)
            .map(|i| region.pixel(i));
        let component = Region::from_pixels(pixels)?;
        let (solution, name) = if tsp65::precondition(&component).is_ok() {
            used65 += 1;
            (tsp65::tsp65(&component)?, "tsp65")
        } else {
            milling25::precondition(&component)?;
            used25 += 1;
            (milling25::milling25(&component)?, "milling25")
        };
        let output = solution
            .outputs
            .iter()
            .find(|o| o.objective == algorithms::Objective::Length && o.cover.is_tour())
            .ok_or_else(|| Error::invalid(format!("{name} returned no tour")))?;
        tours.extend(Tour::from_cover(&output.cover).cycles);
    }

    // Step 3 and 4: the contour walks, linked to the tours by a minimum spanning tree.
    let component_of = |p: Pixel| labels.label[region.index_of(p).expect("a kept pixel")] as usize;
    let nw = erosion.contour().len();
    let joined = join(
        &region,
        &component_of,
        tours,
        erosion.contour().to_vec(),
        Rank::Length,
    )?;
    let mut link_length = Rational::ZERO;
    for link in &joined.links {
        link_length = add(link_length, link.length)?;
    }
    let contour_length = {
        let mut total = Rational::ZERO;
        for walk in erosion.contour() {
            total = add(total, walk_length(walk)?)?;
        }
        total
    };
    let certificates = Certificates {
        pixels: region.len(),
        components: labels.count,
        tsp65: used65,
        milling25: used25,
        contour_walks: nw,
        contour_length,
        links: joined.links.len(),
        link_length,
        bounds,
    };
    Ok((Tour::new(joined.walk), certificates))
}
