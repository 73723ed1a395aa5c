//! Instance generators: the families of grid regions that `mowmill gen` writes.
//!
//! Every generator is a pure function of its [`GenParams`]: the same family, parameters and
//! seed give the same `.grid` bytes on every machine (ChaCha8 seeded from the seed, no hash
//! iteration, integer arithmetic wherever a branch depends on a number). Regions follow the
//! conventions of [`crate::topology`]: pixels are 4-connected, holes are bounded 8-connected
//! components of the complement. Random families never return a region without checking it
//! again with the global functions of `topology`; a failed check retries with a seed derived
//! from the seed (at most 8 times) and then falls back to a plain deterministic construction
//! that meets the same promises, so a request that passes the refusals below always succeeds.
//!
//! # Families
//!
//! The families and their parameters are declared once, in [`PARAMS`] (name, `gen` flag,
//! kind, help) and the family registry ([`Family::info`]: parameters, required ones, summary,
//! whether the seed matters); `mowmill gen`'s flags and help, the keys of a config's
//! `[[family]]` tables, the `params` column and the manifest are derived from them. `rect`,
//! `donut`, `band` and `thin43` do not depend on the seed (`gen` defaults it to 0).
//!
//! | name | parameters (default) | what it is and what it guarantees |
//! |---|---|---|
//! | `rect` | `width`, `height` | the full `width` × `height` rectangle; N = width·height, no holes, no cut vertices unless a side is 1. |
//! | `donut` | `side` L, `k` | a square annulus: the L × L square minus the centred (L − 2k) × (L − 2k) square; needs k ≥ 1 and L ≥ 2k + 1; N = L² − (L − 2k)², one hole. |
//! | `random-simple` | `n`, `no_cut` (false), `style` (mixed), `compactness` (from the seed) | exactly N pixels, 4-connected, no holes (a simple grid graph); with `no_cut`, no cut vertex either (the precondition of Theorem 5 of the milling paper), which exists for N = 1, 2, 4, 6 and every N ≥ 8. |
//! | `random-holed` | `n`, `holes` H (1), `no_cut` (false), `style`, `compactness` | exactly N pixels, 4-connected, exactly H holes of varied sizes and shapes; with `no_cut`, no local cut vertex (Definition 6; the precondition of Theorem 7 of the milling paper). |
//! | `thin` | `n`, `holes` H (0), `compactness` | a thin pocket (no 2 × 2 block of pixels, turn-cost paper, Section 5.5): width-1 corridors, 4-connected, exactly N pixels and exactly H holes (independent cycles of corridors). |
//! | `band` | `k` | the diagonal band B_k, the tight class of the 6/5 bound of Theorem 5 of the milling paper: pixels (x, y) with 0 ≤ x, y ≤ k + 1 and \|x − y\| ≤ 2 (k = 1 is the 3 × 3 square); N = 5k + 4, no holes, no cut vertices. |
//! | `thin43` | `s` | the 4/3 thin example of the turn-cost paper (Fig. 6, Theorem 5.9), as reconstructed from the proof: width-1 corridors on rings and paths with even vertices (gadgets X1–X4, and Y_j, R_j for j = 1..s); N = 222 + 77s, thin. |
//! | `lawn-scattered` | `n`, `parts` P (3), `style`, `compactness` | grass in exactly P components, N pixels in all; each component is a random hole-free shape, and components are at least one empty cell apart in all 8 directions; no holes. |
//! | `boundary` | `n`, `style`, `compactness` | exactly N pixels, 4-connected, every pixel a boundary pixel (an empty 4-neighbour, [`topology::is_boundary`]; the precondition of `boundary-cc`), holes any number: a shape of the style whose inner pixels lose themselves (pinholes, notches) or a neighbour (stairs, one-pixel links and one-pixel-thick parts). Fallback: two rows. |
//! | `thin-arms` | `n`, `holes` H (0), `compactness` | a thin pocket grown pixel by pixel (corridors at any spacing, stairs, crossings with arms of one or two pixels; the more compact, the more branches), exactly N pixels and H holes. Fallback: the `thin` fallback. |
//! | `pinholes` | `n`, `holes` H (required), `style`, `compactness` | exactly N pixels, 4-connected, exactly H holes of one cell each, often in columns or rows 2–4 cells apart (hole contours tangent to the strips between them), walls down to one pixel. Fallback: the `random-holed` staircase. |
//! | `eroded` | `n` (at most 10⁶), `style` (`dense` or `sparse`; `mixed`, the default, draws one) | the instances of a published CPLEX study (a Master's thesis of 2016): the square of side round(√(3N)) eroded at random by the study's own process, pixel by pixel, to exactly N pixels, 4-connected, any number of holes (module `eroded`). Fallback: the staircase of full rows. |
//!
//! # Shape styles
//!
//! `dense` and `sparse` are the two styles of `eroded` only (see its module); the others
//! belong to the shape families and are refused for `eroded`.
//!
//! `random-simple`, `random-holed` and `lawn-scattered` draw a raw shape in one [`Style`] and
//! then normalise it: keep the largest component, fill its holes, and reach exactly the target
//! size by adding or removing *simple* pixels (Yokoi connectivity number 1, which changes
//! neither components nor holes). With `no_cut` the raw shape S is replaced by its Minkowski
//! sum with a 2 × 2 block with holes filled, which has no cut vertex (every pixel lies in a
//! block whose other three pixels stay connected, and blocks of 4-adjacent pixels of S share
//! two pixels), and every later addition or removal is accepted only if the pixel and its 8
//! neighbours keep Yokoi numbers ≤ 1, so no (local) cut vertex ever appears.
//!
//! * `blob`: growth from one pixel; a frontier cell is chosen with probability proportional
//!   to m^γ, m its number of region neighbours, γ from `compactness` (1 → compact and
//!   nearly convex, 1/3 → Eden growth, 0 → ragged, dendritic trees of width-1 branches).
//! * `rectangles`: a union of random rectangles (squares, slabs and width-1 or 2 bars), each
//!   overlapping the union so far: many reflex corners.
//! * `snake`: corridors of width 1 to 4 that turn left and right and branch from one another,
//!   never touching another corridor except where they branch, so that neighbouring corridors
//!   leave gaps one cell wide between them (two before the `no_cut` dilation): long narrow
//!   parts and bottlenecks.
//! * `rooms`: rectangular rooms joined by corridors of width 1 to 3.
//! * `mixed` (the default) picks one of the four per instance from the seed.
//!
//! `compactness` (0..=1) weights the growth of `blob` and the final growth or erosion of every
//! style to exactly N pixels. When the style or the compactness is not given, it is drawn
//! from the seed (compactness in steps of 0.01) and written to the file, so that passing the
//! written values back gives the same bytes.
//!
//! Holes of `random-holed` come from bridging and carving. Bridging (about a quarter of the
//! holes, never with `no_cut`) adds an empty cell with Yokoi number 2: it closes a loop of
//! the connected region and so adds exactly one hole, shaped like the fjord it closes.
//! Carving removes a pixel whose 5 × 5 block is full (without `no_cut` also 3 × 3), then
//! grows that hole by removing simple pixels next to it, each hole with its own random size
//! and compactness; when a narrow shape has too few such sites, a solid 5 × 5 pad is glued
//! on at a random pixel and carved. Without `no_cut` the shape is drawn with n pixels plus
//! the planned hole area and eroded to n at the end; with `no_cut` it is drawn with about n
//! pixels and grown back to n, because erosion that may not create cut vertices gets stuck
//! in corridors two pixels wide while growth at concave corners does not.
//!
//! `thin` builds a random spanning tree on the coarse lattice of nodes (2i, 2j) with a
//! corridor pixel between adjacent nodes (a mix of random depth-first growth, for long
//! snakes, and random Prim growth, for bushy trees, weighted by `compactness`), adds H extra
//! lattice edges (each closes one bounded face, one hole) and at most one dead-end stub pixel
//! to reach N exactly.
//!
//! The hard-shape families (the shapes the certificates of `boundary-cc`, `thin-cc` and
//! `milling25` find hardest) reuse this machinery. `boundary` draws a shape of
//! the style with about 4N/3 pixels; each pixel with four neighbours, in random order, then
//! loses itself or one of its neighbours (the pixel itself with a probability drawn per
//! instance between 0.2 and 0.8), the first of these whose removal leaves its 8-ring in one
//! run of pixels, so that connectivity is kept locally (a global check for the few stuck
//! ones); growth or erosion to exactly N then never makes a pixel inner again. `thin-arms`
//! grows a tree pixel by pixel (each new pixel completes no 2 × 2 block and touches one arc
//! of the region) and closes H loops with bridging cells. `pinholes` removes H pixels whose
//! 3 × 3 block is full from a hole-free shape of N + H pixels, often continuing a column.
//!
//! Near the smallest size that holds the requested holes (and for the tiniest `no_cut`
//! shapes) the random construction often fails, and the result is the deterministic
//! fallback: a staircase of full rows with one-pixel holes on a grid, or for `thin` a
//! spanning tree of a square block of lattice nodes.
//!
//! # Refusals
//!
//! Every given value is first checked against the range of its row of [`PARAMS`]
//! ([`ParamSpec::check`]; `n`, `width`, `height`, `k`, `parts` from 1, `side` from 3, up to
//! [`MAX_PIXELS`]); [`check`] makes every refusal below without generating, and configs use it
//! for each parameter combination before any job runs.
//!
//! [`Error::Invalid`] for a parameter that the family does not take, a missing parameter,
//! N = 0, N > [`MAX_PIXELS`], a rectangle side 0, k = 0 or L < 2k + 1, P = 0 or P > N,
//! `no_cut` for N = 3, 5 or 7 (every hole-free region of that size has a cut vertex), and H
//! holes in fewer pixels than the densest arrangement this generator builds (one-pixel holes
//! on a grid: `random-holed` needs N ≥ min over a of (2a + 1)(2⌈H/a⌉ + 1) − H, or with
//! `no_cut`, whose walls are two pixels thick, N ≥ min over a of (3a + 2)(3⌈H/a⌉ + 2) − H,
//! and then refuses the few sizes just above that minimum it cannot build, such as
//! N = 25 for H = 1; `thin` needs 2t − 1 + H pixels, t the fewest lattice nodes with H
//! independent cycles). `pinholes` refuses what `random-holed` without `no_cut` refuses, and
//! `thin-arms` what `thin` refuses: their fallbacks are those families' fallbacks.
//!
//! # Output
//!
//! The region is translated to start at (0, 0); its comments are, in this order,
//! `; family: NAME`, `; params: key=value ...` (the family's parameters in the fixed order of
//! [`FamilyInfo::params`], defaults and seed-drawn values included), `; seed: S`, and the
//! recounted `; n: N` and `; holes: H`.
//!
//! The papers define no random instances: the families' shapes, styles and hole constructions
//! are our choices.

mod band;
mod boundary;
mod boundary_rooms;
mod canvas;
mod checks;
mod comb;
mod corridor_star;
mod eroded;
mod growth;
mod hole_lattice;
mod lawn;
mod outlines;
mod pinholes;
mod random_holed;
mod random_simple;
mod rect;
mod registry;
mod ring;
// Shared with the discrete generators (`mowmill::discrete::generate`).
#[doc(hidden)]
pub mod rng;
mod spec;
mod spiral;
mod staircase;
mod styles;
mod thin;
mod thin43;
mod thin_arms;
mod thin_eulerian;
mod windows;

#[cfg(test)]
mod structured_tests;
#[cfg(test)]
mod tests;

pub use hole_lattice::Pattern;
pub use registry::{
    Family, FamilyInfo, PARAMS, Param, ParamKind, ParamSpec, ParamValue, families_help,
};
pub use styles::Style;
pub use thin43::thin43_gadgets;

use crate::error::Result;
use crate::gridfile::GridFile;
use spec::Spec;

/// The largest region (in pixels) any family generates: the limit of [`Region`](crate::region::Region).
pub use crate::region::MAX_PIXELS;

/// What to generate. `None` means "not given": the family's default, or a value drawn from
/// the seed (style, compactness); a parameter the family does not take must stay `None`
/// (and `no_cut` false).
#[derive(Clone, Debug, PartialEq)]
pub struct GenParams {
    pub family: Family,
    pub n: Option<usize>,
    pub holes: Option<usize>,
    pub width: Option<usize>,
    pub height: Option<usize>,
    pub side: Option<usize>,
    pub k: Option<usize>,
    pub parts: Option<usize>,
    pub no_cut: bool,
    pub style: Option<Style>,
    pub compactness: Option<f64>,
    /// The parameter s of `thin43`.
    pub s: Option<usize>,
    /// The hole lattice of `hole-lattice`.
    pub pattern: Option<Pattern>,
    pub seed: u64,
}

impl GenParams {
    /// Parameters of `family` with nothing set.
    pub fn new(family: Family, seed: u64) -> GenParams {
        GenParams {
            family,
            n: None,
            holes: None,
            width: None,
            height: None,
            side: None,
            k: None,
            parts: None,
            no_cut: false,
            style: None,
            compactness: None,
            s: None,
            pattern: None,
            seed,
        }
    }

    /// The value of `param` if it is set (`no_cut` counts as set when true).
    pub fn get(&self, param: Param) -> Option<ParamValue> {
        use ParamValue::{Count, Flag, Fraction};
        match param {
            Param::N => self.n.map(Count),
            Param::Holes => self.holes.map(Count),
            Param::Width => self.width.map(Count),
            Param::Height => self.height.map(Count),
            Param::K => self.k.map(Count),
            Param::Side => self.side.map(Count),
            Param::Parts => self.parts.map(Count),
            Param::Style => self.style.map(ParamValue::Style),
            Param::Compactness => self.compactness.map(Fraction),
            Param::S => self.s.map(Count),
            Param::NoCut => self.no_cut.then_some(Flag(true)),
            Param::Pattern => self.pattern.map(ParamValue::Pattern),
        }
    }

    /// Sets `param` to `value`.
    ///
    /// # Errors
    /// [`Error::Invalid`](crate::error::Error::Invalid) if the value is not of the
    /// parameter's [`ParamKind`].
    pub fn set(&mut self, param: Param, value: ParamValue) -> Result<()> {
        use ParamValue::{Count, Flag, Fraction};
        match (param, value) {
            (Param::N, Count(v)) => self.n = Some(v),
            (Param::Holes, Count(v)) => self.holes = Some(v),
            (Param::Width, Count(v)) => self.width = Some(v),
            (Param::Height, Count(v)) => self.height = Some(v),
            (Param::K, Count(v)) => self.k = Some(v),
            (Param::Side, Count(v)) => self.side = Some(v),
            (Param::Parts, Count(v)) => self.parts = Some(v),
            (Param::Style, ParamValue::Style(v)) => self.style = Some(v),
            (Param::Compactness, Fraction(v)) => self.compactness = Some(v),
            (Param::S, Count(v)) => self.s = Some(v),
            (Param::NoCut, Flag(v)) => self.no_cut = v,
            (Param::Pattern, ParamValue::Pattern(v)) => self.pattern = Some(v),
            _ => {
                return Err(crate::error::Error::invalid(format!(
                    "{}: expected {}, got {value}",
                    param.name(),
                    param.spec().kind.expected()
                )));
            }
        }
        Ok(())
    }
}

/// Generates one instance: the region (translated to start at (0, 0)) with its metadata
/// comments (see the module documentation).
///
/// # Errors
/// [`Error::Invalid`] for the refusals listed in the module documentation.
///
/// # Complexity
/// Near-linear in N: O(N) expected time and space for every family (plus O(N log N) to
/// build the [`Region`](crate::region::Region)).
///
/// # Examples
/// ```
/// use mowmill_core::generate::{generate, Family, GenParams};
/// let p = GenParams { side: Some(5), k: Some(1), ..GenParams::new(Family::Donut, 7) };
/// let f = generate(&p).unwrap();
/// assert_eq!(f.meta("n"), Some("16"));
/// assert_eq!(f.meta("holes"), Some("1"));
/// ```
pub fn generate(p: &GenParams) -> Result<GridFile> {
    generate_traced(p).map(|(file, _)| file)
}

/// Refuses what [`generate`] refuses, without generating: the parameter ranges of
/// [`PARAMS`], the parameters the family takes and needs, and every other refusal of the
/// module documentation. Configs check each parameter combination with it before any job runs.
///
/// # Errors
/// [`Error::Invalid`] as [`generate`].
pub fn check(p: &GenParams) -> Result<()> {
    Spec::resolve(p)?.check_feasible()
}

/// Which construction produced a region (for tests: the fallback must stay rare).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Provenance {
    /// A deterministic family (rect, donut) or a composite (lawn-scattered).
    Direct,
    /// The random construction, at this attempt (0 = first).
    Attempt(u64),
    /// The deterministic fallback after every attempt failed.
    Fallback,
}

fn generate_traced(p: &GenParams) -> Result<(GridFile, Provenance)> {
    let spec = Spec::resolve(p)?;
    spec.check_feasible()?;
    let (region, holes, provenance) = spec.build()?;
    let region = region.normalized();
    let meta = [
        ("family", spec.family.name().to_string()),
        ("params", spec.params_line()),
        ("seed", spec.seed.to_string()),
        ("n", region.len().to_string()),
        ("holes", holes.to_string()),
    ];
    Ok((GridFile::with_meta(region, &meta), provenance))
}

/// Whether `family` (the `family` column of a result row) is one of the structured families:
/// the shapes the papers' proofs find hardest, built to stress them (docs/claims.md,
/// "Structured families"). A claim "holds" only when some of its decided instances are of one.
/// Grid families say so in the registry ([`FamilyInfo::structured`]); the discrete and
/// orthogonal ones are the families built for a proof's hard case: slivers and narrow features
/// of polygons, hubs on a path and bridges between straight paths
/// (`mowmill_core::discrete::generate::STRUCTURED`).
pub fn is_structured(family: &str) -> bool {
    if let Ok(f) = family.parse::<Family>() {
        return f.info().structured;
    }
    matches!(
        family,
        "ortho-sliver" | "ortho-narrow" | "hub-path" | "collinear-bridges"
    )
}
