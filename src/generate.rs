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
//! | name | parameters (default) | what it is and what it guarantees |
//! |---|---|---|
//! | `rect` | `width`, `height` | the full `width` × `height` rectangle; N = width·height, no holes, no cut vertices unless a side is 1. |
//! | `donut` | `side` L, `k` | a square annulus: the L × L square minus the centred (L − 2k) × (L − 2k) square; needs k ≥ 1 and L ≥ 2k + 1; N = L² − (L − 2k)², one hole. |
//! | `random-simple` | `n`, `no_cut` (false), `style` (mixed), `compactness` (from the seed) | exactly N pixels, 4-connected, no holes (a simple grid graph); with `no_cut`, no cut vertex either (the precondition of Theorem 5 of the milling paper), which exists for N = 1, 2, 4, 6 and every N ≥ 8. |
//! | `random-holed` | `n`, `holes` H (1), `no_cut` (false), `style`, `compactness` | exactly N pixels, 4-connected, exactly H holes of varied sizes and shapes; with `no_cut`, no local cut vertex (Definition 6; the precondition of Theorem 7 of the milling paper). |
//! | `thin` | `n`, `holes` H (0), `compactness` | a thin pocket (no 2 × 2 block of pixels, turn-cost paper, Section 5.5): width-1 corridors, 4-connected, exactly N pixels and exactly H holes (independent cycles of corridors). |
//! | `band` | `k` | the diagonal band B_k, the tight class of the 6/5 bound of Theorem 5 of the milling paper: pixels (x, y) with 0 ≤ x, y ≤ k + 1 and \|x − y\| ≤ 2 (k = 1 is the 3 × 3 square); N = 5k + 4, no holes, no cut vertices. |
//! | `thin43` | `s` | the 4/3 thin example of the turn-cost paper (Fig. 6, Theorem 5.9), as reconstructed in issue 7: width-1 corridors on rings and paths with even vertices (gadgets X1–X4, and Y_j, R_j for j = 1..s); N = 222 + 77s, thin. |
//! | `lawn-scattered` | `n`, `parts` P (3), `style`, `compactness` | grass in exactly P components, N pixels in all; each component is a random hole-free shape, and components are at least one empty cell apart in all 8 directions; no holes. |
//! | `boundary` | `n`, `style`, `compactness` | exactly N pixels, 4-connected, every pixel a boundary pixel (an empty 4-neighbour, [`topology::is_boundary`]; the precondition of `boundary-cc`), holes any number: a shape of the style whose inner pixels lose themselves (pinholes, notches) or a neighbour (stairs, one-pixel links and one-pixel-thick parts). Fallback: two rows. |
//! | `thin-arms` | `n`, `holes` H (0), `compactness` | a thin pocket grown pixel by pixel (corridors at any spacing, stairs, crossings with arms of one or two pixels; the more compact, the more branches), exactly N pixels and H holes. Fallback: the `thin` fallback. |
//! | `pinholes` | `n`, `holes` H (required), `style`, `compactness` | exactly N pixels, 4-connected, exactly H holes of one cell each, often in columns or rows 2–4 cells apart (hole contours tangent to the strips between them), walls down to one pixel. Fallback: the `random-holed` staircase. |
//!
//! # Shape styles
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
//! The hard-shape families (issue 12: the shapes the certificates of `boundary-cc`,
//! `thin-cc` and `milling25` find hardest) reuse this machinery. `boundary` draws a shape of
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

use crate::error::{Error, Result};
use crate::gridfile::GridFile;
use crate::region::{Dir, Pixel, Region};
use crate::topology;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::fmt;
use std::str::FromStr;

type Rng = ChaCha8Rng;

/// The largest region (in pixels) any family generates.
pub const MAX_PIXELS: usize = 20_000_000;

/// Random attempts before the deterministic fallback construction.
const MAX_ATTEMPTS: u64 = 8;

// ---------------------------------------------------------------------------------------------
// Families, styles and parameters
// ---------------------------------------------------------------------------------------------

/// An instance family; its stable name is the CLI's `mowmill gen FAMILY`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Family {
    Rect,
    RandomSimple,
    RandomHoled,
    Thin,
    LawnScattered,
    Donut,
    Band,
    Thin43,
    Boundary,
    ThinArms,
    Pinholes,
}

/// A generator parameter (the field of [`GenParams`] of the same name).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Param {
    N,
    Holes,
    Width,
    Height,
    Side,
    K,
    Parts,
    NoCut,
    Style,
    Compactness,
    S,
}

impl Param {
    pub const ALL: [Param; 11] = [
        Param::N,
        Param::Holes,
        Param::Width,
        Param::Height,
        Param::Side,
        Param::K,
        Param::Parts,
        Param::NoCut,
        Param::Style,
        Param::Compactness,
        Param::S,
    ];

    /// The key used in the `; params:` line and in messages.
    pub fn name(self) -> &'static str {
        match self {
            Param::N => "n",
            Param::Holes => "holes",
            Param::Width => "width",
            Param::Height => "height",
            Param::Side => "side",
            Param::K => "k",
            Param::Parts => "parts",
            Param::NoCut => "no_cut",
            Param::Style => "style",
            Param::Compactness => "compactness",
            Param::S => "s",
        }
    }
}

/// One row of the family registry: name, one-line summary, and the parameters it takes.
#[derive(Debug)]
pub struct FamilyInfo {
    pub family: Family,
    /// Stable name (CLI and `; family:` line).
    pub name: &'static str,
    pub summary: &'static str,
    /// The parameters the family takes, in the order of the `; params:` line.
    pub params: &'static [Param],
    /// The parameters without a default.
    pub required: &'static [Param],
}

/// The registry, indexed by `Family as usize`. A new family adds a variant, a row here and an
/// arm in `build`.
const FAMILY_TABLE: [FamilyInfo; 11] = [
    FamilyInfo {
        family: Family::Rect,
        name: "rect",
        summary: "the full width x height rectangle",
        params: &[Param::Width, Param::Height],
        required: &[Param::Width, Param::Height],
    },
    FamilyInfo {
        family: Family::RandomSimple,
        name: "random-simple",
        summary: "exactly n pixels, 4-connected, no holes; no_cut: no cut vertices",
        params: &[Param::N, Param::NoCut, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::RandomHoled,
        name: "random-holed",
        summary: "exactly n pixels, 4-connected, exactly `holes` holes; no_cut: no local cut vertices",
        params: &[
            Param::N,
            Param::Holes,
            Param::NoCut,
            Param::Style,
            Param::Compactness,
        ],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Thin,
        name: "thin",
        summary: "thin pocket: width-1 corridors, no 2x2 block, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::LawnScattered,
        name: "lawn-scattered",
        summary: "n pixels of grass in `parts` components, 8-separated from one another",
        params: &[Param::N, Param::Parts, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Donut,
        name: "donut",
        summary: "square annulus of outer side `side` and width k",
        params: &[Param::Side, Param::K],
        required: &[Param::Side, Param::K],
    },
    FamilyInfo {
        family: Family::Band,
        name: "band",
        summary: "diagonal band B_k: 0 <= x, y <= k + 1, |x - y| <= 2 (tight for 6/5, milling paper)",
        params: &[Param::K],
        required: &[Param::K],
    },
    FamilyInfo {
        family: Family::Thin43,
        name: "thin43",
        summary: "the 4/3 thin example (turn-cost paper, Fig. 6) with parameter s >= 0",
        params: &[Param::S],
        required: &[Param::S],
    },
    FamilyInfo {
        family: Family::Boundary,
        name: "boundary",
        summary: "every pixel a boundary pixel (the precondition of boundary-cc): stairs, one-pixel links and parts, holes",
        params: &[Param::N, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::ThinArms,
        name: "thin-arms",
        summary: "thin pocket grown pixel by pixel: stairs, crossings with short arms, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Pinholes,
        name: "pinholes",
        summary: "exactly n pixels, exactly `holes` one-pixel holes, often in columns, walls down to one pixel",
        params: &[Param::N, Param::Holes, Param::Style, Param::Compactness],
        required: &[Param::N, Param::Holes],
    },
];

impl Family {
    pub const ALL: [Family; 11] = [
        Family::Rect,
        Family::RandomSimple,
        Family::RandomHoled,
        Family::Thin,
        Family::LawnScattered,
        Family::Donut,
        Family::Band,
        Family::Thin43,
        Family::Boundary,
        Family::ThinArms,
        Family::Pinholes,
    ];

    /// The family's registry row.
    pub fn info(self) -> &'static FamilyInfo {
        &FAMILY_TABLE[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.info().name
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Family {
    type Err = Error;

    fn from_str(s: &str) -> Result<Family> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                Error::invalid(format!(
                    "unknown family {s:?}: expected one of {}",
                    names.join(", ")
                ))
            })
    }
}

/// The shape style of the random families (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Style {
    /// One of the other styles, drawn per instance from the seed.
    Mixed,
    Blob,
    Rectangles,
    Snake,
    Rooms,
}

impl Style {
    pub const ALL: [Style; 5] = [
        Style::Mixed,
        Style::Blob,
        Style::Rectangles,
        Style::Snake,
        Style::Rooms,
    ];
    /// The styles `Mixed` draws from.
    const CONCRETE: [Style; 4] = [Style::Blob, Style::Rectangles, Style::Snake, Style::Rooms];

    pub fn name(self) -> &'static str {
        match self {
            Style::Mixed => "mixed",
            Style::Blob => "blob",
            Style::Rectangles => "rectangles",
            Style::Snake => "snake",
            Style::Rooms => "rooms",
        }
    }
}

impl fmt::Display for Style {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Style {
    type Err = Error;

    fn from_str(s: &str) -> Result<Style> {
        Style::ALL
            .into_iter()
            .find(|st| st.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Style::ALL.iter().map(|st| st.name()).collect();
                Error::invalid(format!(
                    "unknown style {s:?}: expected one of {}",
                    names.join(", ")
                ))
            })
    }
}

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
            seed,
        }
    }

    fn is_set(&self, p: Param) -> bool {
        match p {
            Param::N => self.n.is_some(),
            Param::Holes => self.holes.is_some(),
            Param::Width => self.width.is_some(),
            Param::Height => self.height.is_some(),
            Param::Side => self.side.is_some(),
            Param::K => self.k.is_some(),
            Param::Parts => self.parts.is_some(),
            Param::NoCut => self.no_cut,
            Param::Style => self.style.is_some(),
            Param::Compactness => self.compactness.is_some(),
            Param::S => self.s.is_some(),
        }
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
/// build the [`Region`]).
///
/// # Examples
/// ```
/// use mowmill::generate::{generate, Family, GenParams};
/// let p = GenParams { side: Some(5), k: Some(1), ..GenParams::new(Family::Donut, 7) };
/// let f = generate(&p).unwrap();
/// assert_eq!(f.meta("n"), Some("16"));
/// assert_eq!(f.meta("holes"), Some("1"));
/// ```
pub fn generate(p: &GenParams) -> Result<GridFile> {
    generate_traced(p).map(|(file, _)| file)
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

/// Fully resolved parameters: defaults applied, `Mixed` and compactness drawn from the seed.
#[derive(Clone, Debug)]
struct Spec {
    family: Family,
    n: usize,
    holes: usize,
    width: usize,
    height: usize,
    side: usize,
    k: usize,
    parts: usize,
    no_cut: bool,
    style: Style,
    compactness: f64,
    s: usize,
    seed: u64,
}

/// Tags of the seed-derived random streams.
const TAG_RESOLVE: u64 = u64::MAX;
const TAG_FALLBACK: u64 = u64::MAX - 1;

impl Spec {
    fn resolve(p: &GenParams) -> Result<Spec> {
        let info = p.family.info();
        let takes: Vec<&str> = info.params.iter().map(|q| q.name()).collect();
        for q in Param::ALL {
            if p.is_set(q) && !info.params.contains(&q) {
                return Err(Error::invalid(format!(
                    "parameter `{}` does not apply to family {} (it takes: {})",
                    q.name(),
                    info.name,
                    takes.join(", ")
                )));
            }
        }
        for &q in info.required {
            if !p.is_set(q) {
                return Err(Error::invalid(format!(
                    "family {} needs parameter `{}`",
                    info.name,
                    q.name()
                )));
            }
        }
        if let Some(c) = p.compactness
            && !(0.0..=1.0).contains(&c)
        {
            return Err(Error::invalid(format!(
                "compactness must be between 0 and 1, got {c}"
            )));
        }
        // Drawn values come from their own stream, so that giving them explicitly reproduces
        // the same instance.
        let mut rng = rng_for(p.seed, TAG_RESOLVE);
        let drawn_style = Style::CONCRETE[below(&mut rng, Style::CONCRETE.len())];
        let drawn_compactness = between(&mut rng, 0, 100) as f64 / 100.0;
        let style = match p.style.unwrap_or(Style::Mixed) {
            Style::Mixed => drawn_style,
            s => s,
        };
        let default_holes = if p.family == Family::RandomHoled {
            1
        } else {
            0
        };
        Ok(Spec {
            family: p.family,
            n: p.n.unwrap_or(0),
            holes: p.holes.unwrap_or(default_holes),
            width: p.width.unwrap_or(0),
            height: p.height.unwrap_or(0),
            side: p.side.unwrap_or(0),
            k: p.k.unwrap_or(0),
            parts: p.parts.unwrap_or(3),
            no_cut: p.no_cut,
            style,
            compactness: p.compactness.unwrap_or(drawn_compactness),
            s: p.s.unwrap_or(0),
            seed: p.seed,
        })
    }

    fn value(&self, q: Param) -> String {
        match q {
            Param::N => self.n.to_string(),
            Param::Holes => self.holes.to_string(),
            Param::Width => self.width.to_string(),
            Param::Height => self.height.to_string(),
            Param::Side => self.side.to_string(),
            Param::K => self.k.to_string(),
            Param::Parts => self.parts.to_string(),
            Param::NoCut => self.no_cut.to_string(),
            Param::Style => self.style.to_string(),
            Param::Compactness => self.compactness.to_string(),
            Param::S => self.s.to_string(),
        }
    }

    fn params_line(&self) -> String {
        let info = self.family.info();
        let parts: Vec<String> = info
            .params
            .iter()
            .map(|&q| format!("{}={}", q.name(), self.value(q)))
            .collect();
        parts.join(" ")
    }

    fn opts(&self) -> ShapeOpts {
        ShapeOpts {
            style: self.style,
            compactness: self.compactness,
            no_cut: self.no_cut,
        }
    }

    /// The number of pixels the request asks for.
    fn pixels(&self) -> usize {
        match self.family {
            Family::Rect => self.width.saturating_mul(self.height),
            Family::Donut => {
                let inner = self.side.saturating_sub(2 * self.k);
                self.side
                    .saturating_mul(self.side)
                    .saturating_sub(inner * inner)
            }
            Family::Band => self.k.saturating_mul(5).saturating_add(4),
            Family::Thin43 => self.s.saturating_mul(77).saturating_add(222),
            _ => self.n,
        }
    }

    fn check_feasible(&self) -> Result<()> {
        let name = self.family.name();
        match self.family {
            Family::Rect if self.width == 0 || self.height == 0 => {
                return Err(Error::invalid("rect needs width ≥ 1 and height ≥ 1"));
            }
            Family::Donut if self.k == 0 || self.side < 2 * self.k + 1 => {
                return Err(Error::invalid(format!(
                    "donut needs k ≥ 1 and side ≥ 2k + 1 (got side {} and k {})",
                    self.side, self.k
                )));
            }
            Family::Band if self.k == 0 => {
                return Err(Error::invalid("band needs k ≥ 1 (k = 1 is the 3x3 square)"));
            }
            _ => {}
        }
        let n = self.pixels();
        if n == 0 {
            return Err(Error::invalid(format!("{name} needs n ≥ 1 pixels")));
        }
        if n > MAX_PIXELS {
            return Err(Error::invalid(format!(
                "{name}: {n} pixels is more than the generator's limit of {MAX_PIXELS}"
            )));
        }
        if self.holes > n {
            // Every hole owns at least three pixels (those west, south-west and south of its
            // lowest, leftmost cell); this also bounds the work of the checks below.
            return Err(Error::invalid(format!(
                "{name}: {} holes do not fit in {n} pixels",
                self.holes
            )));
        }
        let holes = self.holes;
        match self.family {
            Family::RandomSimple if self.no_cut && rows_plan(n, 0, true).is_none() => {
                Err(Error::invalid(format!(
                    "random-simple with no_cut cannot have {n} pixels: every hole-free region of 3, 5 or 7 pixels \
                 has a cut vertex (possible sizes: 1, 2, 4, 6 and every n ≥ 8)"
                )))
            }
            Family::RandomHoled if n < min_holed_pixels(holes, self.no_cut) => {
                Err(Error::invalid(format!(
                    "random-holed: {holes} holes do not fit in {n} pixels: this generator needs n ≥ {} (one-pixel holes \
                 on a grid{})",
                    min_holed_pixels(holes, self.no_cut),
                    if self.no_cut {
                        ", with walls 2 pixels thick so that no pixel is a local cut vertex"
                    } else {
                        ""
                    }
                )))
            }
            Family::RandomHoled if rows_plan(n, holes, self.no_cut).is_none() => {
                Err(Error::invalid(format!(
                    "random-holed with no_cut: cannot build exactly {holes} holes in exactly {n} pixels without local \
                 cut vertices (the smallest such region this generator builds has {} pixels, and a few sizes just \
                 above it are impossible; try a slightly larger n)",
                    min_holed_pixels(holes, self.no_cut)
                )))
            }
            Family::Pinholes if n < min_holed_pixels(holes, false) => Err(Error::invalid(format!(
                "pinholes: {holes} one-pixel holes do not fit in {n} pixels: this generator needs n ≥ {} (one-pixel \
                 holes on a grid)",
                min_holed_pixels(holes, false)
            ))),
            Family::ThinArms if n < min_thin_pixels(self.holes) => Err(Error::invalid(format!(
                "thin-arms: {} holes need n ≥ {} pixels (each hole is a cycle of width-1 corridors around at least \
                 one empty cell), got {n}",
                self.holes,
                min_thin_pixels(self.holes)
            ))),
            Family::Thin if n < min_thin_pixels(self.holes) => Err(Error::invalid(format!(
                "thin: {} holes need n ≥ {} pixels (each hole is a cycle of width-1 corridors around at least one \
                 empty cell), got {n}",
                self.holes,
                min_thin_pixels(self.holes)
            ))),
            Family::LawnScattered if self.parts == 0 || self.parts > n => {
                Err(Error::invalid(format!(
                    "lawn-scattered needs 1 ≤ parts ≤ n (got parts {} and n {n})",
                    self.parts
                )))
            }
            _ => Ok(()),
        }
    }

    fn promise(&self) -> Promise {
        let (components, holes) = match self.family {
            Family::Donut => (1, 1),
            Family::Thin43 => (1, thin43_holes(self.s)),
            Family::RandomHoled | Family::Thin | Family::ThinArms | Family::Pinholes => {
                (1, self.holes)
            }
            Family::LawnScattered => (self.parts, 0),
            _ => (1, 0),
        };
        let cut = match self.family {
            Family::RandomSimple if self.no_cut => CutRule::NoCut,
            Family::Band => CutRule::NoCut,
            Family::RandomHoled if self.no_cut => CutRule::NoLocalCut,
            _ => CutRule::Any,
        };
        Promise {
            n: self.pixels(),
            components,
            holes,
            cut,
            thin: matches!(
                self.family,
                Family::Thin | Family::Thin43 | Family::ThinArms
            ),
            separated: self.family == Family::LawnScattered,
            any_holes: self.family == Family::Boundary,
            boundary_only: self.family == Family::Boundary,
        }
    }

    /// Builds the region and checks its promise; returns it with its number of holes.
    fn build(&self) -> Result<(Region, usize, Provenance)> {
        let o = self.opts();
        let (n, h) = (self.n, self.holes);
        let (pixels, provenance) = match self.family {
            Family::Rect => (rect_pixels(self.width, self.height), Provenance::Direct),
            Family::Donut => (donut_pixels(self.side, self.k), Provenance::Direct),
            Family::Band => (band_pixels(self.k), Provenance::Direct),
            Family::Thin43 => (thin43_pixels(self.s), Provenance::Direct),
            Family::LawnScattered => {
                let mut rng = rng_for(self.seed, 0);
                (lawn_pixels(n, self.parts, &o, &mut rng), Provenance::Direct)
            }
            Family::RandomSimple => {
                return self.with_attempts(
                    |rng, _| simple_canvas(n, &o, rng).map(|(c, _)| c.pixels()),
                    |rng| rows_pixels(n, 0, o.no_cut, rng),
                );
            }
            Family::RandomHoled => {
                return self.with_attempts(
                    |rng, _| holed_canvas(n, h, &o, rng).map(|c| c.pixels()),
                    |rng| rows_pixels(n, h, o.no_cut, rng),
                );
            }
            Family::Thin => {
                return self.with_attempts(
                    |rng, attempt| thin_pixels(n, h, o.compactness, Some(attempt), rng),
                    |rng| thin_pixels(n, h, o.compactness, None, rng),
                );
            }
            Family::Boundary => {
                return self.with_attempts(
                    |rng, _| boundary_canvas(n, &o, rng).map(|c| c.pixels()),
                    |_| Some(two_rows_pixels(n)),
                );
            }
            Family::ThinArms => {
                return self.with_attempts(
                    |rng, _| thin_arms_pixels(n, h, o.compactness, rng),
                    |rng| thin_pixels(n, h, o.compactness, None, rng),
                );
            }
            Family::Pinholes => {
                return self.with_attempts(
                    |rng, _| pinholes_canvas(n, h, &o, rng).map(|c| c.pixels()),
                    |rng| rows_pixels(n, h, false, rng),
                );
            }
        };
        self.checked(pixels, provenance)
    }

    fn checked(
        &self,
        pixels: Vec<Pixel>,
        provenance: Provenance,
    ) -> Result<(Region, usize, Provenance)> {
        let region = Region::from_pixels(pixels)?;
        let holes = verify(&region, &self.promise()).map_err(|e| {
            Error::invalid(format!(
                "internal error: the generated {} region breaks its promise: {e}",
                self.family
            ))
        })?;
        Ok((region, holes, provenance))
    }

    /// Runs the random construction with seed-derived streams until its result keeps the
    /// promise, then the deterministic fallback.
    fn with_attempts(
        &self,
        mut attempt: impl FnMut(&mut Rng, u64) -> Option<Vec<Pixel>>,
        fallback: impl FnOnce(&mut Rng) -> Option<Vec<Pixel>>,
    ) -> Result<(Region, usize, Provenance)> {
        let promise = self.promise();
        for a in 0..MAX_ATTEMPTS {
            let mut rng = rng_for(self.seed, a);
            if let Some(pixels) = attempt(&mut rng, a) {
                let region = Region::from_pixels(pixels)?;
                if let Ok(holes) = verify(&region, &promise) {
                    return Ok((region, holes, Provenance::Attempt(a)));
                }
            }
        }
        let mut rng = rng_for(self.seed, TAG_FALLBACK);
        let pixels = fallback(&mut rng).ok_or_else(|| {
            Error::invalid(format!(
                "internal error: no {} construction for these parameters",
                self.family
            ))
        })?;
        self.checked(pixels, Provenance::Fallback)
    }
}

// ---------------------------------------------------------------------------------------------
// Verification
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CutRule {
    Any,
    /// No cut vertex (Theorem 5 of the milling paper).
    NoCut,
    /// No local cut vertex (Definition 6, Theorem 7 of the milling paper).
    NoLocalCut,
}

/// What a generated region must satisfy, checked with the global functions of `topology`.
#[derive(Clone, Debug)]
struct Promise {
    n: usize,
    components: usize,
    holes: usize,
    cut: CutRule,
    thin: bool,
    /// Components pairwise at Chebyshev distance ≥ 2 (no 8-adjacency between components).
    separated: bool,
    /// Any number of holes (`holes` is then ignored).
    any_holes: bool,
    /// Every pixel a boundary pixel (`topology::is_boundary`).
    boundary_only: bool,
}

/// Checks `promise`; returns the number of holes.
fn verify(region: &Region, promise: &Promise) -> std::result::Result<usize, String> {
    if region.len() != promise.n {
        return Err(format!("{} pixels instead of {}", region.len(), promise.n));
    }
    let comps = topology::components(region);
    if comps.count != promise.components {
        return Err(format!(
            "{} components instead of {}",
            comps.count, promise.components
        ));
    }
    let holes = topology::holes(region).count;
    if holes != promise.holes && !promise.any_holes {
        return Err(format!("{holes} holes instead of {}", promise.holes));
    }
    let bad = match promise.cut {
        CutRule::Any => 0,
        CutRule::NoCut => topology::cut_vertices(region)
            .iter()
            .filter(|&&c| c)
            .count(),
        CutRule::NoLocalCut => topology::local_cut_vertices(region)
            .iter()
            .filter(|&&c| c)
            .count(),
    };
    if bad > 0 {
        return Err(format!("{bad} forbidden (local) cut vertices"));
    }
    if promise.thin && !topology::is_thin(region) {
        return Err("a 2x2 block in a thin region".to_string());
    }
    if promise.boundary_only
        && let Some(i) = (0..region.len()).find(|&i| !topology::is_boundary(region, i))
    {
        return Err(format!("inner pixel {}", region.pixel(i)));
    }
    if promise.separated {
        for (i, &p) in region.pixels().iter().enumerate() {
            for q in topology::ring(p) {
                if let Some(j) = region.index_of(q)
                    && comps.label[j] != comps.label[i]
                {
                    return Err(format!("components touch at {p} and {q}"));
                }
            }
        }
    }
    Ok(holes)
}

// ---------------------------------------------------------------------------------------------
// Randomness
// ---------------------------------------------------------------------------------------------

fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// An independent ChaCha8 stream for (`seed`, `tag`).
fn rng_for(seed: u64, tag: u64) -> Rng {
    Rng::seed_from_u64(splitmix(seed ^ splitmix(tag)))
}

/// Uniform in `0..n` (n ≥ 1), through u64 so that 32- and 64-bit machines agree.
fn below(rng: &mut Rng, n: usize) -> usize {
    rng.random_range(0..n as u64) as usize
}

/// Uniform in `lo..=hi` (hi ≥ lo).
fn between(rng: &mut Rng, lo: usize, hi: usize) -> usize {
    lo + below(rng, hi - lo + 1)
}

fn unit(rng: &mut Rng) -> f64 {
    rng.random::<f64>()
}

fn chance(rng: &mut Rng, p: f64) -> bool {
    unit(rng) < p
}

fn shuffle<T>(v: &mut [T], rng: &mut Rng) {
    for i in (1..v.len()).rev() {
        v.swap(i, below(rng, i + 1));
    }
}

fn ceil_sqrt(n: usize) -> usize {
    let s = n.isqrt();
    if s * s < n { s + 1 } else { s }
}

/// Growth weights by bucket (bucket b = 1..=4, see `candidate`): b^γ with γ = −3 at
/// compactness 0 (prefer tips: ragged), 0 at 1/3 (uniform: Eden growth), 6 at 1 (prefer
/// concave cells: round). γ is a multiple of 1/4 and b^γ is computed from square roots and
/// products only, which IEEE 754 rounds the same everywhere.
fn bucket_weights(compactness: f64) -> [f64; 5] {
    let q = (compactness * 36.0).round() as i32 - 12;
    let mut w = [0.0; 5];
    for (b, wb) in w.iter_mut().enumerate().skip(1) {
        let root = (b as f64).sqrt().sqrt();
        let mut x = 1.0;
        for _ in 0..q.unsigned_abs() {
            x *= root;
        }
        *wb = if q < 0 { 1.0 / x } else { x };
    }
    w
}

// ---------------------------------------------------------------------------------------------
// The occupancy canvas
// ---------------------------------------------------------------------------------------------

/// Pixels the style drawings keep from the canvas edge (room for the 2 × 2 dilation and the
/// later growth).
const STYLE_MARGIN: usize = 6;
/// Pixels every occupied cell keeps from the canvas edge, so that 5 × 5 neighbourhoods of
/// pixels and of their 4-neighbours never leave the canvas.
const ADJ_MARGIN: usize = 3;

/// A mutable occupancy bitmap with a fixed frame of empty cells.
struct Canvas {
    w: usize,
    h: usize,
    occ: Vec<bool>,
    count: usize,
    /// While drawing a `no_cut` shape S: how many pixels of S cover each cell of S ⊕ 2 × 2.
    cover: Vec<u8>,
    dcount: usize,
    /// Hole labels (1-based) while carving holes; empty otherwise.
    hole: Vec<u32>,
    /// Index offsets of the 8 neighbours in the order of `topology::ring`.
    ring: [isize; 8],
}

impl Canvas {
    fn new(w: usize, h: usize) -> Canvas {
        let wi = w as isize;
        Canvas {
            w,
            h,
            occ: vec![false; w * h],
            count: 0,
            cover: Vec::new(),
            dcount: 0,
            hole: Vec::new(),
            ring: [1, 1 + wi, wi, wi - 1, -1, -1 - wi, -wi, 1 - wi],
        }
    }

    /// A canvas with room for a shape of `target` pixels spread over `factor` times its area,
    /// of random aspect ratio between 1 and 2.5.
    fn for_target(target: usize, factor: usize, rng: &mut Rng) -> Canvas {
        let inner = target * factor + 64;
        let aspect = between(rng, 100, 250);
        let mut a = (inner * aspect / 100).isqrt() + 1;
        let mut b = inner / a + 1;
        if chance(rng, 0.5) {
            std::mem::swap(&mut a, &mut b);
        }
        Canvas::new(a + 2 * STYLE_MARGIN + 2, b + 2 * STYLE_MARGIN + 2)
    }

    fn area(&self) -> usize {
        self.w * self.h
    }

    fn idx(&self, x: usize, y: usize) -> usize {
        y * self.w + x
    }

    fn nb(&self, k: usize, i: usize) -> usize {
        (k as isize + self.ring[i]) as usize
    }

    fn in_zone(&self, k: usize, margin: usize) -> bool {
        let (x, y) = (k % self.w, k / self.w);
        x >= margin && y >= margin && x + margin < self.w && y + margin < self.h
    }

    fn zone_xy(&self, x: i64, y: i64, margin: usize) -> bool {
        let m = margin as i64;
        x >= m && y >= m && x + m < self.w as i64 && y + m < self.h as i64
    }

    /// The size that drawing aims at: |S ⊕ 2 × 2| while dilating, else the pixel count.
    fn size(&self) -> usize {
        if self.cover.is_empty() {
            self.count
        } else {
            self.dcount
        }
    }

    fn set(&mut self, k: usize, v: bool) {
        if self.occ[k] == v {
            return;
        }
        self.occ[k] = v;
        if v {
            self.count += 1;
            if !self.hole.is_empty() {
                self.hole[k] = 0;
            }
        } else {
            self.count -= 1;
        }
        if !self.cover.is_empty() {
            for c in [k, k + 1, k + self.w, k + self.w + 1] {
                if v {
                    self.dcount += usize::from(self.cover[c] == 0);
                    self.cover[c] += 1;
                } else {
                    self.cover[c] -= 1;
                    self.dcount -= usize::from(self.cover[c] == 0);
                }
            }
        }
    }

    fn ring_occ(&self, k: usize) -> [bool; 8] {
        std::array::from_fn(|i| self.occ[self.nb(k, i)])
    }

    /// Yokoi's 4-connectivity number of cell `k` (occupied or not).
    fn yokoi(&self, k: usize) -> u32 {
        topology::connectivity_number(self.ring_occ(k))
    }

    /// Number of occupied 4-neighbours.
    fn nb4(&self, k: usize) -> usize {
        (0..4).filter(|&i| self.occ[self.nb(k, 2 * i)]).count()
    }

    /// Whether the (2r + 1) × (2r + 1) square around `k` is fully occupied.
    fn full(&self, k: usize, r: usize) -> bool {
        let (x, y) = (k % self.w, k / self.w);
        (y - r..=y + r).all(|yy| (x - r..=x + r).all(|xx| self.occ[self.idx(xx, yy)]))
    }

    fn begin_dilation(&mut self) {
        self.cover = vec![0; self.area()];
        self.dcount = 0;
    }

    /// Replaces the drawn shape S by S ⊕ 2 × 2.
    fn finish_dilation(&mut self) {
        for (o, &c) in self.occ.iter_mut().zip(&self.cover) {
            *o = c > 0;
        }
        self.count = self.dcount;
        self.cover = Vec::new();
    }

    /// Removes every 4-component but the largest (the first in scan order on ties).
    fn keep_largest_component(&mut self) {
        let mut label = vec![0u32; self.area()];
        let mut stack = Vec::new();
        let (mut best, mut best_size, mut next) = (0u32, 0usize, 0u32);
        for s in 0..self.area() {
            if !self.occ[s] || label[s] != 0 {
                continue;
            }
            next += 1;
            label[s] = next;
            stack.push(s);
            let mut size = 0;
            while let Some(k) = stack.pop() {
                size += 1;
                for i in 0..4 {
                    let q = self.nb(k, 2 * i);
                    if self.occ[q] && label[q] == 0 {
                        label[q] = next;
                        stack.push(q);
                    }
                }
            }
            if size > best_size {
                (best, best_size) = (next, size);
            }
        }
        for (k, &l) in label.iter().enumerate() {
            if self.occ[k] && l != best {
                self.set(k, false);
            }
        }
    }

    /// The empty cells connected to the canvas frame (8-connected): the outside.
    fn outside(&self) -> Vec<bool> {
        let mut outside = vec![false; self.area()];
        let mut stack = vec![0usize];
        outside[0] = true;
        let (w, h) = (self.w as i64, self.h as i64);
        while let Some(k) = stack.pop() {
            let (x, y) = ((k % self.w) as i64, (k / self.w) as i64);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (nx, ny) = (x + dx, y + dy);
                    if nx < 0 || ny < 0 || nx >= w || ny >= h {
                        continue;
                    }
                    let q = self.idx(nx as usize, ny as usize);
                    if !self.occ[q] && !outside[q] {
                        outside[q] = true;
                        stack.push(q);
                    }
                }
            }
        }
        outside
    }

    /// Fills every hole (bounded 8-component of the empty cells), or with `was_outside` only
    /// the pockets closed since that picture of the outside.
    fn fill_holes(&mut self, was_outside: Option<&[bool]>) {
        let outside = self.outside();
        for k in 0..self.area() {
            if !self.occ[k] && !outside[k] && was_outside.is_none_or(|o| o[k]) {
                self.set(k, true);
            }
        }
    }

    fn pixels(&self) -> Vec<Pixel> {
        (0..self.area())
            .filter(|&k| self.occ[k])
            .map(|k| Pixel::new((k % self.w) as i32, (k / self.w) as i32))
            .collect()
    }
}

// ---------------------------------------------------------------------------------------------
// Growth and erosion by simple pixels
// ---------------------------------------------------------------------------------------------

/// Candidate cells in 5 weight buckets, with O(1) insert, move, remove and weighted sampling.
struct Frontier {
    slot: Vec<u32>,
    bucket: Vec<u8>,
    items: [Vec<u32>; 5],
}

const ABSENT: u32 = u32::MAX;

impl Frontier {
    fn new(area: usize) -> Frontier {
        Frontier {
            slot: vec![ABSENT; area],
            bucket: vec![0; area],
            items: Default::default(),
        }
    }

    fn clear(&mut self) {
        for items in &mut self.items {
            for &k in items.iter() {
                self.slot[k as usize] = ABSENT;
            }
            items.clear();
        }
    }

    /// Puts `k` in bucket `b`, or takes it out for `None`.
    fn set(&mut self, k: usize, b: Option<u8>) {
        let s = self.slot[k];
        if s != ABSENT {
            let old = self.bucket[k];
            if b == Some(old) {
                return;
            }
            let items = &mut self.items[old as usize];
            let last = *items.last().expect("slot points into a non-empty bucket");
            items.swap_remove(s as usize);
            if last as usize != k {
                self.slot[last as usize] = s;
            }
            self.slot[k] = ABSENT;
        }
        if let Some(b) = b {
            self.slot[k] = self.items[b as usize].len() as u32;
            self.items[b as usize].push(k as u32);
            self.bucket[k] = b;
        }
    }

    /// A candidate drawn with probability proportional to its bucket's weight.
    fn sample(&self, rng: &mut Rng, weights: &[f64; 5]) -> Option<usize> {
        let masses: [f64; 5] = std::array::from_fn(|b| self.items[b].len() as f64 * weights[b]);
        let total: f64 = masses.iter().sum();
        if total <= 0.0 {
            return None;
        }
        let mut r = unit(rng) * total;
        let mut chosen = None;
        for (b, &mass) in masses.iter().enumerate() {
            if mass > 0.0 {
                chosen = Some(b);
                if r < mass {
                    break;
                }
                r -= mass;
            }
        }
        let items = &self.items[chosen?];
        Some(items[below(rng, items.len())] as usize)
    }
}

/// A topology-preserving change of one cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Move {
    /// Add an empty cell next to the region.
    Grow,
    /// Remove a pixel of the region's boundary.
    Shrink,
    /// Remove a pixel next to hole `h`, enlarging that hole.
    Hole(u32),
}

/// The bucket of `k` as a candidate for `mv` (None: not a candidate). Grow: m ∈ 1..=4 region
/// 4-neighbours; Shrink: 4 − m (tips first when round); Hole: hole 4-neighbours, at least 1.
fn candidate(c: &Canvas, k: usize, mv: Move, margin: usize) -> Option<u8> {
    if !c.in_zone(k, margin) {
        return None;
    }
    let m = c.nb4(k) as u8;
    match mv {
        Move::Grow => (!c.occ[k] && m > 0).then_some(m),
        Move::Shrink => (c.occ[k] && m < 4).then_some(4 - m),
        Move::Hole(h) => {
            if !c.occ[k] || !(0..8).any(|i| c.hole[c.nb(k, i)] == h) {
                return None;
            }
            let in_hole = (0..4).filter(|&i| c.hole[c.nb(k, 2 * i)] == h).count() as u8;
            Some(in_hole.max(1))
        }
    }
}

/// Whether flipping `k` keeps components and holes (k simple) and, with `no_cut`, leaves no
/// pixel of its 3 × 3 block with Yokoi number ≥ 2 (no new local cut vertex).
fn acceptable(c: &mut Canvas, k: usize, no_cut: bool) -> bool {
    if c.yokoi(k) != 1 {
        return false;
    }
    if !no_cut {
        return true;
    }
    c.occ[k] = !c.occ[k];
    let ok = std::iter::once(k)
        .chain((0..8).map(|i| c.nb(k, i)))
        .all(|q| !c.occ[q] || c.yokoi(q) <= 1);
    c.occ[k] = !c.occ[k];
    ok
}

/// Re-buckets the cells within Chebyshev distance `r` of `k`.
fn refresh(c: &Canvas, f: &mut Frontier, k: usize, r: usize, mv: Move, margin: usize) {
    let (x, y) = (k % c.w, k / c.w);
    for yy in y - r..=y + r {
        for xx in x - r..=x + r {
            let q = c.idx(xx, yy);
            f.set(q, candidate(c, q, mv, margin));
        }
    }
}

/// Puts every candidate of the canvas into `f`.
fn scan(c: &Canvas, f: &mut Frontier, mv: Move, margin: usize) {
    f.clear();
    for y in margin..c.h - margin {
        for x in margin..c.w - margin {
            let k = c.idx(x, y);
            if let Some(b) = candidate(c, k, mv, margin) {
                f.set(k, Some(b));
            }
        }
    }
}

/// Applies moves drawn from `f` until `done`; false if the candidates run out first.
///
/// A rejected candidate leaves `f` and comes back only when a cell near it changes (the
/// acceptance of a cell depends on its 3 × 3 block, or 5 × 5 with `no_cut`), so every
/// call does O(initial candidates + moves) work.
#[allow(clippy::too_many_arguments)]
fn evolve(
    c: &mut Canvas,
    f: &mut Frontier,
    mv: Move,
    weights: &[f64; 5],
    no_cut: bool,
    margin: usize,
    rng: &mut Rng,
    done: impl Fn(&Canvas) -> bool,
) -> bool {
    let r = if no_cut { 2 } else { 1 };
    while !done(c) {
        let Some(k) = f.sample(rng, weights) else {
            return false;
        };
        if acceptable(c, k, no_cut) {
            match mv {
                Move::Grow => c.set(k, true),
                Move::Shrink => c.set(k, false),
                Move::Hole(h) => {
                    c.set(k, false);
                    c.hole[k] = h;
                }
            }
            refresh(c, f, k, r, mv, margin);
        } else {
            f.set(k, None);
        }
    }
    true
}

/// Adds or removes simple pixels until the canvas has exactly `target` pixels.
fn adjust(
    c: &mut Canvas,
    f: &mut Frontier,
    target: usize,
    weights: &[f64; 5],
    no_cut: bool,
    rng: &mut Rng,
) -> bool {
    if c.count < target {
        scan(c, f, Move::Grow, ADJ_MARGIN);
        evolve(c, f, Move::Grow, weights, no_cut, ADJ_MARGIN, rng, |c| {
            c.count >= target
        })
    } else if c.count > target {
        scan(c, f, Move::Shrink, ADJ_MARGIN);
        evolve(c, f, Move::Shrink, weights, no_cut, ADJ_MARGIN, rng, |c| {
            c.count <= target
        })
    } else {
        true
    }
}

// ---------------------------------------------------------------------------------------------
// Shape styles
// ---------------------------------------------------------------------------------------------

struct ShapeOpts {
    style: Style,
    compactness: f64,
    no_cut: bool,
}

/// A connected hole-free shape of exactly `target` pixels (no cut vertex with `no_cut`).
fn simple_canvas(target: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<(Canvas, Frontier)> {
    let factor = match o.style {
        Style::Snake | Style::Rooms => 5,
        _ => 3,
    };
    let mut c = Canvas::for_target(target, factor, rng);
    let mut f = Frontier::new(c.area());
    if o.no_cut {
        c.begin_dilation();
    }
    match o.style {
        Style::Blob | Style::Mixed => draw_blob(&mut c, &mut f, target, o.compactness, rng),
        Style::Rectangles => draw_rectangles(&mut c, target, rng),
        Style::Snake => draw_corridors(&mut c, target, false, rng),
        Style::Rooms => draw_corridors(&mut c, target, true, rng),
    }
    if o.no_cut {
        c.finish_dilation();
    }
    c.keep_largest_component();
    c.fill_holes(None);
    let weights = bucket_weights(o.compactness);
    adjust(&mut c, &mut f, target, &weights, o.no_cut, rng).then_some((c, f))
}

fn center(c: &Canvas, rng: &mut Rng) -> (usize, usize) {
    let jx = c.w / 8;
    let jy = c.h / 8;
    (
        c.w / 2 - jx + between(rng, 0, 2 * jx),
        c.h / 2 - jy + between(rng, 0, 2 * jy),
    )
}

fn draw_blob(c: &mut Canvas, f: &mut Frontier, target: usize, compactness: f64, rng: &mut Rng) {
    let (x, y) = center(c, rng);
    let k = c.idx(x, y);
    c.set(k, true);
    f.clear();
    refresh(c, f, k, 1, Move::Grow, STYLE_MARGIN);
    let weights = bucket_weights(compactness);
    evolve(c, f, Move::Grow, &weights, false, STYLE_MARGIN, rng, |c| {
        c.size() >= target
    });
}

/// An inclusive rectangle of cells (empty when x0 > x1).
#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: i64,
    y0: i64,
    x1: i64,
    y1: i64,
}

impl Rect {
    const EMPTY: Rect = Rect {
        x0: 0,
        y0: 0,
        x1: -1,
        y1: -1,
    };

    fn is_empty(&self) -> bool {
        self.x0 > self.x1 || self.y0 > self.y1
    }

    fn union(self, o: Rect) -> Rect {
        if self.is_empty() {
            return o;
        }
        if o.is_empty() {
            return self;
        }
        Rect {
            x0: self.x0.min(o.x0),
            y0: self.y0.min(o.y0),
            x1: self.x1.max(o.x1),
            y1: self.y1.max(o.y1),
        }
    }

    fn contains(&self, x: i64, y: i64) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    fn shift(self, d: Dir) -> Rect {
        let (dx, dy) = d.delta();
        let (dx, dy) = (i64::from(dx), i64::from(dy));
        Rect {
            x0: self.x0 + dx,
            y0: self.y0 + dy,
            x1: self.x1 + dx,
            y1: self.y1 + dy,
        }
    }

    /// The row or column of cells just beyond the rectangle in direction `d`.
    fn front(self, d: Dir) -> Rect {
        match d {
            Dir::E => Rect {
                x0: self.x1 + 1,
                x1: self.x1 + 1,
                ..self
            },
            Dir::W => Rect {
                x0: self.x0 - 1,
                x1: self.x0 - 1,
                ..self
            },
            Dir::N => Rect {
                y0: self.y1 + 1,
                y1: self.y1 + 1,
                ..self
            },
            Dir::S => Rect {
                y0: self.y0 - 1,
                y1: self.y0 - 1,
                ..self
            },
        }
    }
}

/// How far (Chebyshev) new corridor cells keep from other parts of the drawing: 1, or 2
/// while dilating, so that the 2 × 2 dilation does not close the gaps between corridors.
fn clearance(c: &Canvas) -> i64 {
    if c.cover.is_empty() { 1 } else { 2 }
}

/// Whether every cell of `new` is empty and inside the drawing zone, and every occupied cell
/// within the clearance of it lies in `allowed`.
fn clear_for(c: &Canvas, new: Rect, allowed: Rect) -> bool {
    let r = clearance(c);
    for y in new.y0..=new.y1 {
        for x in new.x0..=new.x1 {
            if !c.zone_xy(x, y, STYLE_MARGIN) || c.occ[c.idx(x as usize, y as usize)] {
                return false;
            }
            for (qx, qy) in (y - r..=y + r).flat_map(|qy| (x - r..=x + r).map(move |qx| (qx, qy))) {
                if c.occ[c.idx(qx as usize, qy as usize)] && !allowed.contains(qx, qy) {
                    return false;
                }
            }
        }
    }
    true
}

/// Paints `r` (clipped to the drawing zone) row by row outwards from row `from_y`, which
/// touches what the rectangle attaches to, stopping once the canvas reaches `target`: every
/// row touches the rows painted before it, so a partly painted rectangle stays attached.
/// Records the new pixels.
fn paint(c: &mut Canvas, r: Rect, from_y: i64, target: usize, painted: &mut Vec<u32>) {
    let m = STYLE_MARGIN as i64;
    let (x0, x1) = (r.x0.max(m), r.x1.min(c.w as i64 - 1 - m));
    let (y0, y1) = (r.y0.max(m), r.y1.min(c.h as i64 - 1 - m));
    if x0 > x1 || y0 > y1 {
        return;
    }
    let from_y = from_y.clamp(y0, y1);
    let span = (y1 - from_y).max(from_y - y0);
    let rows = (0..=span).flat_map(|d| [from_y + d, from_y - d - 1]);
    for y in rows.filter(|&y| (y0..=y1).contains(&y)) {
        if c.size() >= target {
            return;
        }
        for x in x0..=x1 {
            let k = c.idx(x as usize, y as usize);
            if !c.occ[k] {
                c.set(k, true);
                painted.push(k as u32);
            }
        }
    }
}

/// A rectangle of about `area` cells whose aspect ratio is √2^e, e ∈ −6..=6 (up to 8:1).
fn random_dims(area: usize, rng: &mut Rng) -> (i64, i64) {
    let e = between(rng, 0, 12) as i32 - 6;
    let mut ratio = 1.0;
    for _ in 0..e.unsigned_abs() {
        ratio *= std::f64::consts::SQRT_2;
    }
    if e < 0 {
        ratio = 1.0 / ratio;
    }
    let w = ((area as f64 * ratio).sqrt() as i64).max(1);
    let h = (area as i64 / w).max(1);
    (w, h)
}

fn draw_rectangles(c: &mut Canvas, target: usize, rng: &mut Rng) {
    let mut painted = Vec::new();
    let pieces = between(rng, 3, 40);
    let mean = (target / pieces).max(1);
    let bar_p = unit(rng) * 0.4;
    let (x, y) = center(c, rng);
    let (w, h) = random_dims(mean, rng);
    let first = Rect {
        x0: x as i64,
        y0: y as i64,
        x1: x as i64 + w - 1,
        y1: y as i64 + h - 1,
    };
    paint(c, first, first.y0, target, &mut painted);
    if painted.is_empty() {
        c.set(c.idx(x, y), true);
        painted.push(c.idx(x, y) as u32);
    }
    let mut stalls = 0;
    while c.size() < target && stalls < 1000 {
        let before = c.size();
        let k = painted[below(rng, painted.len())] as usize;
        let (ax, ay) = ((k % c.w) as i64, (k / c.w) as i64);
        let (mut w, mut h) = if chance(rng, bar_p) {
            // A bar of width 1 or 2: a narrow part.
            let long = between(rng, 3, 3 + 2 * mean.isqrt()) as i64;
            (between(rng, 1, 2) as i64, long)
        } else {
            let area = ((mean as f64) * (0.2 + 1.8 * unit(rng))) as usize;
            random_dims(area.max(1), rng)
        };
        if chance(rng, 0.5) {
            std::mem::swap(&mut w, &mut h);
        }
        let x0 = ax - below(rng, w as usize) as i64;
        let y0 = ay - below(rng, h as usize) as i64;
        paint(
            c,
            Rect {
                x0,
                y0,
                x1: x0 + w - 1,
                y1: y0 + h - 1,
            },
            ay,
            target,
            &mut painted,
        );
        stalls = if c.size() == before { stalls + 1 } else { 0 };
    }
}

/// The head of a corridor being drawn: a w × w square moving in direction `d`. `trail`
/// holds its last positions (or the wall it starts from), which new cells may touch; it is
/// as long as the clearance needs (1 step, or 3 while dilating).
struct Walker {
    head: Rect,
    trail: [Rect; 3],
    d: Dir,
}

impl Walker {
    fn new(head: Rect, behind: Rect, d: Dir) -> Walker {
        Walker {
            head,
            trail: [behind, Rect::EMPTY, Rect::EMPTY],
            d,
        }
    }

    /// The head and the cells behind it that new cells may touch.
    fn neighbourhood(&self, c: &Canvas) -> Rect {
        let depth = (2 * clearance(c) - 1) as usize;
        self.trail[..depth]
            .iter()
            .fold(self.head, |a, &b| a.union(b))
    }

    fn try_move(&mut self, c: &mut Canvas, d: Dir, painted: &mut Vec<u32>) -> bool {
        let slice = self.head.front(d);
        if !clear_for(c, slice, self.neighbourhood(c).union(slice)) {
            return false;
        }
        paint(c, slice, slice.y0, usize::MAX, painted);
        self.trail = [self.head, self.trail[0], self.trail[1]];
        self.head = self.head.shift(d);
        self.d = d;
        true
    }
}

fn random_dir(rng: &mut Rng) -> Dir {
    Dir::ALL[below(rng, 4)]
}

/// Starts a corridor of width `w` from pixel `k`, leaving it in direction `d`.
fn start_corridor(
    c: &mut Canvas,
    k: usize,
    d: Dir,
    w: i64,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) -> Option<Walker> {
    let (px, py) = ((k % c.w) as i64, (k / c.w) as i64);
    let j = below(rng, w as usize) as i64;
    // The square in front of the pixel, and the wall behind it (as deep as the clearance).
    let r = clearance(c);
    let (sq, wall) = match d {
        Dir::E => (
            Rect {
                x0: px + 1,
                x1: px + w,
                y0: py - j,
                y1: py - j + w - 1,
            },
            Rect {
                x0: px - r + 1,
                x1: px,
                y0: py - j - r,
                y1: py - j + w - 1 + r,
            },
        ),
        Dir::W => (
            Rect {
                x0: px - w,
                x1: px - 1,
                y0: py - j,
                y1: py - j + w - 1,
            },
            Rect {
                x0: px,
                x1: px + r - 1,
                y0: py - j - r,
                y1: py - j + w - 1 + r,
            },
        ),
        Dir::N => (
            Rect {
                y0: py + 1,
                y1: py + w,
                x0: px - j,
                x1: px - j + w - 1,
            },
            Rect {
                y0: py - r + 1,
                y1: py,
                x0: px - j - r,
                x1: px - j + w - 1 + r,
            },
        ),
        Dir::S => (
            Rect {
                y0: py - w,
                y1: py - 1,
                x0: px - j,
                x1: px - j + w - 1,
            },
            Rect {
                y0: py,
                y1: py + r - 1,
                x0: px - j - r,
                x1: px - j + w - 1 + r,
            },
        ),
    };
    if !clear_for(c, sq, sq.union(wall)) {
        return None;
    }
    paint(c, sq, sq.y0, usize::MAX, painted);
    Some(Walker::new(sq, wall, d))
}

/// Corridors of random widths that turn and branch without touching one another; with
/// `rooms`, rectangular rooms at their ends.
fn draw_corridors(c: &mut Canvas, target: usize, rooms: bool, rng: &mut Rng) {
    let mut painted = Vec::new();
    let root = target.isqrt().max(2);
    let max_w = if rooms { 3 } else { 4 };
    let seg_max = between(rng, 3, (root / 2).max(4));
    let len_max = between(rng, root / 2 + 2, 4 * root + 4);
    let room_max = between(rng, 3, (root / 3).max(3)) as i64;
    let (x, y) = center(c, rng);
    let w0 = if rooms {
        between(rng, 2, room_max as usize) as i64
    } else {
        between(rng, 1, max_w) as i64
    };
    let h0 = if rooms {
        between(rng, 2, room_max as usize) as i64
    } else {
        w0
    };
    let first = Rect {
        x0: x as i64,
        y0: y as i64,
        x1: x as i64 + w0 - 1,
        y1: y as i64 + h0 - 1,
    };
    paint(c, first, first.y0, target, &mut painted);
    let mut walker = if rooms {
        None
    } else {
        Some(Walker::new(first, Rect::EMPTY, random_dir(rng)))
    };
    let mut fails = 0;
    while c.size() < target && fails < 200 {
        if let Some(mut wk) = walker.take() {
            run_corridor(
                c,
                &mut wk,
                between(rng, 2, len_max),
                seg_max,
                target,
                rng,
                &mut painted,
            );
            if rooms && c.size() < target && chance(rng, 0.85) {
                place_room(c, &wk, room_max, target, rng, &mut painted);
            }
        }
        let w = between(rng, 1, max_w) as i64;
        for _ in 0..40 {
            let k = painted[below(rng, painted.len())] as usize;
            let d = random_dir(rng);
            let (dx, dy) = d.delta();
            let next = (k as isize + dx as isize + dy as isize * c.w as isize) as usize;
            if c.occ[next] {
                continue;
            }
            if let Some(wk) = start_corridor(c, k, d, w, rng, &mut painted) {
                walker = Some(wk);
                break;
            }
        }
        if walker.is_none() {
            fails += 1;
        }
    }
}

fn turn(d: Dir, rng: &mut Rng) -> Dir {
    if chance(rng, 0.5) {
        d.left()
    } else {
        d.right()
    }
}

fn run_corridor(
    c: &mut Canvas,
    wk: &mut Walker,
    len: usize,
    seg_max: usize,
    target: usize,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) {
    let mut seg = between(rng, 1, seg_max);
    let mut left = len;
    while left > 0 && c.size() < target {
        let mut d = wk.d;
        if seg == 0 {
            if !chance(rng, 0.15) {
                d = turn(d, rng);
            }
            seg = between(rng, 1, seg_max);
        }
        if !wk.try_move(c, d, painted) {
            let a = turn(wk.d, rng);
            if !wk.try_move(c, a, painted) && !wk.try_move(c, a.opposite(), painted) {
                return;
            }
            seg = between(rng, 1, seg_max);
        }
        seg -= 1;
        left -= 1;
    }
}

/// A room in front of the corridor head, covering the head's width.
fn place_room(
    c: &mut Canvas,
    wk: &Walker,
    room_max: i64,
    target: usize,
    rng: &mut Rng,
    painted: &mut Vec<u32>,
) {
    let h = wk.head;
    let w = h.x1 - h.x0 + 1;
    for shrink in 0..3 {
        let max = (room_max >> shrink).max(w.max(2));
        let along = between(rng, 2, max as usize) as i64;
        let across = between(rng, w.max(2) as usize, max as usize) as i64;
        let off = below(rng, (across - w + 1) as usize) as i64;
        let room = match wk.d {
            Dir::E => Rect {
                x0: h.x1 + 1,
                x1: h.x1 + along,
                y0: h.y0 - off,
                y1: h.y0 - off + across - 1,
            },
            Dir::W => Rect {
                x0: h.x0 - along,
                x1: h.x0 - 1,
                y0: h.y0 - off,
                y1: h.y0 - off + across - 1,
            },
            Dir::N => Rect {
                y0: h.y1 + 1,
                y1: h.y1 + along,
                x0: h.x0 - off,
                x1: h.x0 - off + across - 1,
            },
            Dir::S => Rect {
                y0: h.y0 - along,
                y1: h.y0 - 1,
                x0: h.x0 - off,
                x1: h.x0 - off + across - 1,
            },
        };
        if clear_for(c, room, wk.neighbourhood(c).union(room)) {
            let from_y = match wk.d {
                Dir::N => room.y0,
                Dir::S => room.y1,
                _ => h.y0,
            };
            paint(c, room, from_y, target, painted);
            return;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Holes
// ---------------------------------------------------------------------------------------------

/// A shape of exactly `n` pixels with exactly `holes` holes.
fn holed_canvas(n: usize, holes: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<Canvas> {
    // Total hole area: between 2% and 30% of n, at least one cell per hole.
    let area = if holes == 0 {
        0
    } else {
        ((n as f64 * (0.02 + 0.28 * unit(rng))) as usize).max(holes)
    };
    // The shape is drawn with room for the holes and eroded to n at the end, except with
    // no_cut: eroding without creating cut vertices gets stuck in corridors two pixels wide,
    // while growing at concave corners does not, so the holes eat into a shape of about n
    // pixels that then grows back to n.
    let base = if o.no_cut { n + holes } else { n + area };
    let (mut c, mut f) = simple_canvas(base, o, rng)?;
    if !carve_holes(&mut c, &mut f, holes, area, o.no_cut, rng) {
        return None;
    }
    let weights = bucket_weights(o.compactness);
    adjust(&mut c, &mut f, n, &weights, o.no_cut, rng).then_some(c)
}

/// Random hole sizes, at least 1 each, summing to about `area`, skewed (a few large holes).
fn hole_sizes(holes: usize, area: usize, rng: &mut Rng) -> Vec<usize> {
    let raw: Vec<f64> = (0..holes)
        .map(|_| {
            let u = unit(rng);
            u * u * u + 0.02
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    let spare = area.saturating_sub(holes) as f64;
    raw.iter().map(|r| 1 + (spare * r / sum) as usize).collect()
}

/// Creates exactly `holes` new holes in a connected hole-free canvas: one-cell holes carved
/// at interior sites (then grown to random sizes and shapes) and, without `no_cut`, holes
/// made by bridging.
fn carve_holes(
    c: &mut Canvas,
    f: &mut Frontier,
    holes: usize,
    area: usize,
    no_cut: bool,
    rng: &mut Rng,
) -> bool {
    if holes == 0 {
        return true;
    }
    c.hole = vec![0; c.area()];
    // Bridges first: a quarter of the holes without no_cut, as many as the shape offers.
    let wanted = if no_cut {
        0
    } else {
        (0..holes).filter(|_| chance(rng, 0.25)).count()
    };
    let mut candidates = None;
    let bridges = (0..wanted)
        .take_while(|_| bridge(c, &mut candidates, rng))
        .count();
    // Carving sites: pixels whose 5 × 5 block is full (the new hole is two cells away from
    // everything empty, and with no_cut every pixel of its ring keeps Yokoi number 1), then,
    // without no_cut, pixels whose 3 × 3 block is full.
    let (mut wide, mut narrow) = (Vec::new(), Vec::new());
    for k in 0..c.area() {
        if c.occ[k] && c.in_zone(k, ADJ_MARGIN + 2) {
            if c.full(k, 2) {
                wide.push(k as u32);
            } else if !no_cut && c.full(k, 1) {
                narrow.push(k as u32);
            }
        }
    }
    shuffle(&mut wide, rng);
    shuffle(&mut narrow, rng);
    let mut carved = Vec::with_capacity(holes);
    let carve = |c: &mut Canvas, carved: &mut Vec<usize>, k: usize| {
        carved.push(k);
        c.set(k, false);
        c.hole[k] = carved.len() as u32;
    };
    for _ in bridges..holes {
        let Some(k) = pop_site(c, &mut wide, 2).or_else(|| pop_site(c, &mut narrow, 1)) else {
            break;
        };
        carve(c, &mut carved, k);
    }
    // Narrow shapes lack sites: glue solid 5 × 5 pads on and carve their centres.
    let missing = holes - bridges - carved.len();
    if missing > 0 {
        let pads = add_pads(c, missing, rng);
        if pads.len() < missing {
            return false;
        }
        for k in pads {
            carve(c, &mut carved, k);
        }
    }
    // Grow each carved hole to its size by removing simple pixels next to it.
    let sizes = hole_sizes(carved.len(), area.saturating_sub(bridges), rng);
    for (i, (&k, &size)) in carved.iter().zip(&sizes).enumerate() {
        let label = i as u32 + 1;
        f.clear();
        let r = if no_cut { 2 } else { 1 };
        refresh(c, f, k, r, Move::Hole(label), ADJ_MARGIN);
        let stop = c.count + 1 - size;
        let weights = bucket_weights(unit(rng));
        evolve(
            c,
            f,
            Move::Hole(label),
            &weights,
            no_cut,
            ADJ_MARGIN,
            rng,
            |c| c.count <= stop,
        );
    }
    f.clear();
    c.hole = Vec::new();
    true
}

/// Paints up to `wanted` solid 5 × 5 squares centred on random pixels, two cells away from
/// every hole and three cells apart from one another, fills the pockets they close, and
/// returns their centres (each a carving site). A pad shares at least two adjacent pixels
/// with the region, so a region without cut vertices keeps none (the union of two
/// 2-connected graphs that share two vertices is 2-connected), filling pockets adds no cut
/// vertex either, and the pixels next to the existing holes do not change.
fn add_pads(c: &mut Canvas, wanted: usize, rng: &mut Rng) -> Vec<usize> {
    const R: usize = 2;
    let was_outside = c.outside();
    let mut spots: Vec<u32> = (0..c.area())
        .filter(|&k| c.occ[k] && c.in_zone(k, ADJ_MARGIN + R))
        .map(|k| k as u32)
        .collect();
    shuffle(&mut spots, rng);
    let mut centres: Vec<usize> = Vec::new();
    let w = c.w;
    let far = |a: usize, b: usize| (a % w).abs_diff(b % w).max((a / w).abs_diff(b / w)) >= 3;
    for k in spots {
        if centres.len() == wanted {
            break;
        }
        let k = k as usize;
        let (x, y) = (k % w, k / w);
        let near_hole = (y - R - 2..=y + R + 2).any(|yy| {
            (x - R - 2..=x + R + 2).any(|xx| {
                let q = c.idx(xx, yy);
                !c.occ[q] && !was_outside[q]
            })
        });
        if near_hole || !centres.iter().all(|&o| far(o, k)) {
            continue;
        }
        for yy in y - R..=y + R {
            for xx in x - R..=x + R {
                c.set(c.idx(xx, yy), true);
            }
        }
        centres.push(k);
    }
    if !centres.is_empty() {
        c.fill_holes(Some(&was_outside));
    }
    centres
}

fn pop_site(c: &Canvas, sites: &mut Vec<u32>, r: usize) -> Option<usize> {
    while let Some(k) = sites.pop() {
        let k = k as usize;
        if c.occ[k] && c.full(k, r) {
            return Some(k);
        }
    }
    None
}

/// Adds one empty cell with Yokoi number 2: it joins two arcs of the (connected) region and
/// so closes a loop, adding exactly one hole.
fn bridge(c: &mut Canvas, bridges: &mut Option<Vec<u32>>, rng: &mut Rng) -> bool {
    let list = bridges.get_or_insert_with(|| {
        let mut v: Vec<u32> = (0..c.area())
            .filter(|&k| !c.occ[k] && c.in_zone(k, ADJ_MARGIN) && c.nb4(k) > 0 && c.yokoi(k) == 2)
            .map(|k| k as u32)
            .collect();
        shuffle(&mut v, rng);
        v
    });
    while let Some(k) = list.pop() {
        let k = k as usize;
        if !c.occ[k] && c.yokoi(k) == 2 {
            c.set(k, true);
            return true;
        }
    }
    false
}

// ---------------------------------------------------------------------------------------------
// Deterministic constructions: rows (fallback of random-simple and random-holed), rect, donut
// ---------------------------------------------------------------------------------------------

/// A staircase of `total` pixels and width `w`, left-aligned, bottom up: `full` rows of `w`,
/// then the rows of `tail` (shorter, non-increasing). With `no_cut` no row is a single pixel
/// and there are at least two full rows below a shorter row, so the staircase has no cut
/// vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Staircase {
    w: usize,
    full: usize,
    tail: Vec<usize>,
}

impl Staircase {
    fn new(total: usize, w: usize, no_cut: bool) -> Option<Staircase> {
        let (q, r) = (total / w, total % w);
        let full = |full, tail| Some(Staircase { w, full, tail });
        match r {
            0 if !no_cut || total <= 2 || (w >= 2 && q >= 2) => full(q, vec![]),
            _ if !no_cut => full(q, vec![r]),
            // One full row and the extra pixel become rows of ⌈(w+1)/2⌉ and ⌊(w+1)/2⌋.
            1 if q >= 3 && w >= 3 => full(q - 1, vec![(w + 1).div_ceil(2), w.div_ceil(2)]),
            2.. if q >= 2 => full(q, vec![r]),
            // A line of three or more pixels, or a short row on a single row.
            _ => None,
        }
    }

    /// Capacity of the hole grid inside the full rows: one-pixel holes with walls of one
    /// pixel (period 2), or of two pixels with `no_cut` (period 3).
    fn grid_axis(len: usize, no_cut: bool) -> impl Iterator<Item = usize> {
        let (start, step, edge) = if no_cut { (2, 3, 2) } else { (1, 2, 1) };
        (start..len.saturating_sub(edge)).step_by(step)
    }

    fn hole_capacity(&self, no_cut: bool) -> usize {
        Self::grid_axis(self.w, no_cut).count() * Self::grid_axis(self.full, no_cut).count()
    }

    fn hole_grid(&self, no_cut: bool) -> Vec<(usize, usize)> {
        let xs: Vec<usize> = Self::grid_axis(self.w, no_cut).collect();
        Self::grid_axis(self.full, no_cut)
            .flat_map(|y| xs.iter().map(move |&x| (x, y)))
            .collect()
    }

    fn row_lengths(&self) -> impl Iterator<Item = usize> + '_ {
        std::iter::repeat_n(self.w, self.full).chain(self.tail.iter().copied())
    }
}

/// A staircase of n + holes pixels whose full rows hold `holes` grid holes, trying widths
/// near √(n + holes) first. O(n) time at worst.
fn rows_plan(n: usize, holes: usize, no_cut: bool) -> Option<Staircase> {
    let total = n + holes;
    let s = total.isqrt().max(1);
    for d in 0..=total {
        if s + d > total && d >= s {
            break;
        }
        for w in [s + d, s.wrapping_sub(d)] {
            if w == 0 || w > total || (d == 0 && w != s + d) {
                continue;
            }
            if let Some(st) = Staircase::new(total, w, no_cut)
                && st.hole_capacity(no_cut) >= holes
            {
                return Some(st);
            }
        }
    }
    None
}

/// The staircase with `holes` grid holes chosen at random: n pixels in all.
fn rows_pixels(n: usize, holes: usize, no_cut: bool, rng: &mut Rng) -> Option<Vec<Pixel>> {
    let st = rows_plan(n, holes, no_cut)?;
    let mut grid = st.hole_grid(no_cut);
    shuffle(&mut grid, rng);
    let mut holed: Vec<(usize, usize)> = grid[..holes].to_vec();
    holed.sort_unstable();
    let mut pixels = Vec::with_capacity(n);
    for (y, len) in st.row_lengths().enumerate() {
        for x in 0..len {
            if holed.binary_search(&(x, y)).is_err() {
                pixels.push(Pixel::new(x as i32, y as i32));
            }
        }
    }
    Some(pixels)
}

/// The smallest n for which `rows_plan(n, holes, no_cut)` holds a full rectangle: the hole
/// grid of a × ⌈H/a⌉ holes with its walls.
fn min_holed_pixels(holes: usize, no_cut: bool) -> usize {
    if holes == 0 {
        return 1;
    }
    let (per, extra) = if no_cut { (3, 2) } else { (2, 1) };
    (1..=holes)
        .map(|a| (per * a + extra) * (per * holes.div_ceil(a) + extra) - holes)
        .min()
        .unwrap_or(usize::MAX)
}

fn rect_pixels(w: usize, h: usize) -> Vec<Pixel> {
    (0..h)
        .flat_map(|y| (0..w).map(move |x| Pixel::new(x as i32, y as i32)))
        .collect()
}

fn donut_pixels(side: usize, k: usize) -> Vec<Pixel> {
    rect_pixels(side, side)
        .into_iter()
        .filter(|p| {
            let inner = |v: i32| v as usize >= k && (v as usize) < side - k;
            !(inner(p.x) && inner(p.y))
        })
        .collect()
}

/// The diagonal band B_k: (x, y) with 0 ≤ x, y ≤ k + 1 and |x − y| ≤ 2.
fn band_pixels(k: usize) -> Vec<Pixel> {
    let m = k as i32 + 1;
    (0..=m)
        .flat_map(|y| (0..=m).map(move |x| Pixel::new(x, y)))
        .filter(|p| (p.x - p.y).abs() <= 2)
        .collect()
}

/// The gadgets of `thin43` with parameter s, by name (X1, Y1, R1, …, X2, X3, X4): the lattice
/// points on each gadget's polylines of issue 7 (rings are closed rectangles given by two
/// corners; all vertices have even coordinates). The family's pixels are their union.
pub fn thin43_gadgets(s: usize) -> Vec<(String, Vec<Pixel>)> {
    let u = 8 * s as i32;
    let ring = |a: i32, b: i32, c: i32, d: i32| vec![(a, b), (c, b), (c, d), (a, d), (a, b)];
    type Polyline = Vec<(i32, i32)>;
    let mut gadgets: Vec<(String, Vec<Polyline>)> = Vec::new();
    gadgets.push((
        "X1".into(),
        vec![ring(4, 2, 14, 10), vec![(4, 4), (6, 4), (6, 2)]],
    ));
    for j in 1..=s as i32 {
        gadgets.push((
            format!("Y{j}"),
            vec![
                ring(8 * j + 4, 0, 8 * j + 10, 14),
                vec![(8 * j + 4, 12), (8 * j + 10, 12)],
            ],
        ));
        gadgets.push((format!("R{j}"), vec![ring(8 * j + 8, 4, 8 * j + 14, 8)]));
    }
    gadgets.push((
        "X2".into(),
        vec![
            ring(u + 12, 0, u + 20, 20),
            vec![(u + 12, 18), (u + 16, 18), (u + 16, 20)],
        ],
    ));
    gadgets.push((
        "X3".into(),
        vec![
            ring(8, 16, u + 18, 24),
            vec![(u + 18, 22), (u + 16, 22), (u + 16, 24)],
        ],
    ));
    gadgets.push((
        "X4".into(),
        vec![ring(0, 6, 10, 28), vec![(10, 26), (2, 26), (2, 6)]],
    ));
    gadgets
        .into_iter()
        .map(|(name, lines)| {
            let mut pixels: Vec<Pixel> = Vec::new();
            for line in &lines {
                for w in line.windows(2) {
                    let ((x0, y0), (x1, y1)) = (w[0], w[1]);
                    let steps = (x1 - x0).abs().max((y1 - y0).abs());
                    for t in 0..=steps {
                        pixels.push(Pixel::new(
                            x0 + (x1 - x0).signum() * t,
                            y0 + (y1 - y0).signum() * t,
                        ));
                    }
                }
            }
            pixels.sort_unstable_by_key(|p| (p.y, p.x));
            pixels.dedup();
            (name, pixels)
        })
        .collect()
}

/// The pixels of `thin43` with parameter s: the union of its [gadgets](thin43_gadgets).
fn thin43_pixels(s: usize) -> Vec<Pixel> {
    let mut pixels: Vec<Pixel> = thin43_gadgets(s).into_iter().flat_map(|(_, p)| p).collect();
    pixels.sort_unstable_by_key(|p| (p.y, p.x));
    pixels.dedup();
    pixels
}

/// Holes of `thin43` at s = 0, and per step of s (counted once, checked by every generation).
const THIN43_HOLES_BASE: usize = 13;
const THIN43_HOLES_STEP: usize = 5;

/// The number of holes of `thin43` with parameter s (bounded faces of its corridor network).
fn thin43_holes(s: usize) -> usize {
    THIN43_HOLES_BASE + THIN43_HOLES_STEP * s
}

// ---------------------------------------------------------------------------------------------
// Thin pockets
// ---------------------------------------------------------------------------------------------

/// The number of independent cycles the row-by-row filling of t lattice nodes (rows of
/// ⌈√t⌉) offers: its lattice edges minus the t − 1 of a spanning tree. It equals the
/// Harary–Harborth maximum ⌊2t − 2√t⌋ − (t − 1) over all sets of t lattice nodes.
fn thin_capacity(t: usize) -> usize {
    let w = ceil_sqrt(t).max(1);
    let (q, r) = (t / w, t % w);
    let horizontal = q * (w - 1) + r.saturating_sub(1);
    let vertical = q.saturating_sub(1) * w + if q >= 1 { r } else { 0 };
    (horizontal + vertical + 1).saturating_sub(t)
}

/// Lattice nodes needed for `holes` cycles.
fn thin_nodes_for(holes: usize) -> usize {
    (1..)
        .find(|&t| thin_capacity(t) >= holes)
        .unwrap_or(usize::MAX)
}

/// The fewest pixels of a thin region with `holes` holes in this construction.
fn min_thin_pixels(holes: usize) -> usize {
    2 * thin_nodes_for(holes) - 1 + holes
}

/// A thin region of exactly n pixels and `holes` holes: a random spanning tree of t nodes on
/// the coarse lattice (nodes at even coordinates, a corridor pixel per tree edge), `holes`
/// extra lattice edges and at most one stub pixel. `attempt` None is the fallback: the nodes
/// fill rows of ⌈√t⌉, which offer the most cycles.
fn thin_pixels(
    n: usize,
    holes: usize,
    compactness: f64,
    attempt: Option<u64>,
    rng: &mut Rng,
) -> Option<Vec<Pixel>> {
    let stub = (n - 1 - holes) % 2;
    let t = (n - 1 - holes - stub) / 2 + 1;
    // The coarse canvas: a × b nodes of which `allowed` may be used.
    let (a, b, allowed) = match attempt {
        None => {
            let a = ceil_sqrt(t);
            (a, t.div_ceil(a), t)
        }
        Some(k) => {
            // Node density of the canvas: sparse for sprawling trees, denser on later
            // attempts when holes need adjacent nodes.
            let mut density = 30 + below(rng, 61);
            if holes > 0 {
                density = density.max(50 + 10 * k as usize);
            }
            let cells = (t * 100).div_ceil(density.min(100));
            let aspect = between(rng, 100, 200);
            let mut a = (cells * aspect / 100).isqrt().max(1);
            let mut b = cells.div_ceil(a);
            if chance(rng, 0.5) {
                std::mem::swap(&mut a, &mut b);
            }
            (a, b, a * b)
        }
    };
    let node_ok = |u: usize| u < allowed;
    let nb = |u: usize, d: Dir| -> Option<usize> {
        let (x, y) = (u % a, u / a);
        let v = match d {
            Dir::E if x + 1 < a => u + 1,
            Dir::W if x > 0 => u - 1,
            Dir::N if y + 1 < b => u + a,
            Dir::S if y > 0 => u - a,
            _ => return None,
        };
        node_ok(v).then_some(v)
    };
    let mut in_tree = vec![false; a * b];
    // parent[v]: the direction from v to its parent (4 = root).
    let mut parent = vec![4u8; a * b];
    let root = if attempt.is_none() {
        below(rng, t)
    } else {
        (b / 2) * a + a / 2
    };
    in_tree[root] = true;
    let (mut active, mut stack) = (vec![root], vec![root]);
    let mut came = vec![4u8; a * b];
    let mut size = 1;
    let mut free = Vec::with_capacity(4);
    while size < t {
        // Prim-like (a random tree node) with probability `compactness`, else depth-first
        // from the newest node, preferring to go straight.
        let mut prim = chance(rng, compactness);
        let (u, d) = loop {
            prim |= stack.is_empty();
            let (list, idx) = if prim {
                if active.is_empty() {
                    return None;
                }
                let i = below(rng, active.len());
                (&mut active, i)
            } else {
                let i = stack.len() - 1;
                (&mut stack, i)
            };
            let u = list[idx];
            free.clear();
            free.extend(
                Dir::ALL
                    .into_iter()
                    .filter(|&d| nb(u, d).is_some_and(|v| !in_tree[v])),
            );
            if free.is_empty() {
                list.swap_remove(idx);
                continue;
            }
            let straight = came[u] < 4 && free.contains(&Dir::from_index(came[u] as usize));
            let d = if !prim && straight && chance(rng, 0.65) {
                Dir::from_index(came[u] as usize)
            } else {
                free[below(rng, free.len())]
            };
            break (u, d);
        };
        let v = nb(u, d).expect("free direction has a node");
        in_tree[v] = true;
        parent[v] = d.opposite().index() as u8;
        came[v] = d.index() as u8;
        active.push(v);
        stack.push(v);
        size += 1;
    }
    let is_tree_edge = |u: usize, d: Dir, v: usize| {
        parent[u] == d.index() as u8 || parent[v] == d.opposite().index() as u8
    };
    let mut extra = Vec::new();
    for u in (0..a * b).filter(|&u| in_tree[u]) {
        for d in [Dir::E, Dir::N] {
            if let Some(v) = nb(u, d)
                && in_tree[v]
                && !is_tree_edge(u, d, v)
            {
                extra.push((u, d));
            }
        }
    }
    if extra.len() < holes {
        return None;
    }
    shuffle(&mut extra, rng);
    extra.truncate(holes);
    let node_pixel = |u: usize| Pixel::new(2 * (u % a) as i32, 2 * (u / a) as i32);
    let mut pixels = Vec::with_capacity(n);
    for u in (0..a * b).filter(|&u| in_tree[u]) {
        pixels.push(node_pixel(u));
        if parent[u] < 4 {
            pixels.push(node_pixel(u).step(Dir::from_index(parent[u] as usize)));
        }
    }
    pixels.extend(extra.iter().map(|&(u, d)| node_pixel(u).step(d)));
    if stub == 1 {
        let mut ends = Vec::new();
        for u in (0..a * b).filter(|&u| in_tree[u]) {
            for d in Dir::ALL {
                if nb(u, d).is_none_or(|v| !in_tree[v]) {
                    ends.push((u, d));
                }
            }
        }
        let (u, d) = ends[below(rng, ends.len())];
        pixels.push(node_pixel(u).step(d));
    }
    Some(pixels)
}

// ---------------------------------------------------------------------------------------------
// Hard shapes: boundary-only regions, thin pockets grown pixel by pixel, one-pixel holes
// ---------------------------------------------------------------------------------------------

/// The number of maximal runs of occupied cells around the ring (cyclically; a full ring is
/// one run). Consecutive ring cells are 4-adjacent, so at most one run means that removing
/// the centre keeps its pixel neighbours connected to one another: connectivity is kept.
fn ring_runs(ring: [bool; 8]) -> usize {
    if ring.iter().all(|&o| o) {
        return 1;
    }
    (0..8).filter(|&i| ring[i] && !ring[(i + 7) % 8]).count()
}

/// Whether adding cell `k` would complete a 2 × 2 block of occupied cells.
fn makes_block(c: &Canvas, k: usize) -> bool {
    let r = c.ring_occ(k);
    (0..4).any(|q| r[2 * q] && r[2 * q + 1] && r[(2 * q + 2) % 8])
}

/// Whether the occupied cells stay 4-connected without `k` (breadth-first search).
fn connected_without(c: &Canvas, k: usize) -> bool {
    let Some(start) = (0..4).map(|i| c.nb(k, 2 * i)).find(|&q| c.occ[q]) else {
        return c.count <= 1;
    };
    let mut seen = vec![false; c.area()];
    seen[k] = true;
    seen[start] = true;
    let (mut stack, mut reached) = (vec![start], 1);
    while let Some(q) = stack.pop() {
        for i in 0..4 {
            let r = c.nb(q, 2 * i);
            if c.occ[r] && !seen[r] {
                seen[r] = true;
                reached += 1;
                stack.push(r);
            }
        }
    }
    reached + 1 == c.count
}

/// Inner pixels (all four neighbours present) the local rule may leave behind before an
/// attempt gives up; each costs a global connectivity check.
const MAX_STUCK: usize = 64;

/// A connected region of exactly `n` pixels, every one with an empty 4-neighbour: a shape of
/// the given style, then every inner pixel k in random order loses k itself (a pinhole or a
/// notch) or one of its four neighbours (stairs, one-pixel links and parts), whichever first
/// keeps the region connected, then simple growth or erosion to n that never makes a pixel
/// inner again.
fn boundary_canvas(n: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<Canvas> {
    let (mut c, _) = simple_canvas(n + n / 3 + 1, o, rng)?;
    let own = between(rng, 20, 80) as f64 / 100.0;
    let mut inner: Vec<u32> = (0..c.area())
        .filter(|&k| c.occ[k] && c.nb4(k) == 4)
        .map(|k| k as u32)
        .collect();
    shuffle(&mut inner, rng);
    let mut stuck = Vec::new();
    for k in inner {
        let k = k as usize;
        if !c.occ[k] || c.nb4(k) < 4 {
            continue;
        }
        let mut options = [k, c.nb(k, 0), c.nb(k, 2), c.nb(k, 4), c.nb(k, 6)];
        shuffle(&mut options[1..], rng);
        if !chance(rng, own) {
            options.rotate_left(1);
        }
        match options
            .iter()
            .find(|&&r| c.in_zone(r, ADJ_MARGIN) && ring_runs(c.ring_occ(r)) <= 1)
        {
            Some(&r) => c.set(r, false),
            None => stuck.push(k),
        }
    }
    if stuck.len() > MAX_STUCK {
        return None;
    }
    for k in stuck {
        if !c.occ[k] || c.nb4(k) < 4 {
            continue;
        }
        let options = [k, c.nb(k, 0), c.nb(k, 2), c.nb(k, 4), c.nb(k, 6)];
        let &r = options.iter().find(|&&r| connected_without(&c, r))?;
        c.set(r, false);
    }
    // Exactly n: add an empty cell only if it and its pixel neighbours keep an empty
    // 4-neighbour; remove a pixel only if its ring is one run (connectivity kept).
    while c.count != n {
        let grow = c.count < n;
        let mut cells: Vec<u32> = (0..c.area())
            .filter(|&k| c.in_zone(k, ADJ_MARGIN) && c.occ[k] != grow && c.nb4(k) > 0)
            .map(|k| k as u32)
            .collect();
        shuffle(&mut cells, rng);
        let before = c.count;
        for k in cells {
            let k = k as usize;
            if c.count == n {
                break;
            }
            let ok = if grow {
                !c.occ[k]
                    && c.nb4(k) < 4
                    && (0..4).all(|i| {
                        let q = c.nb(k, 2 * i);
                        !c.occ[q] || c.nb4(q) <= 2
                    })
            } else {
                c.occ[k] && ring_runs(c.ring_occ(k)) == 1
            };
            if ok {
                c.set(k, grow);
            }
        }
        if c.count == before {
            return None;
        }
    }
    Some(c)
}

/// The fallback of `boundary`: two rows, the upper one shorter by at most one pixel.
fn two_rows_pixels(n: usize) -> Vec<Pixel> {
    (0..n)
        .map(|i| Pixel::new((i / 2) as i32, (i % 2) as i32))
        .collect()
}

/// A thin region of exactly n pixels and `holes` holes grown pixel by pixel: a tree grown
/// from one pixel by cells with one region neighbour that complete no 2 × 2 block (a cell
/// next to a pixel that already has two or more neighbours, i.e. a new branch, is accepted
/// with a probability rising with `compactness`, so crossings with short arms and stairs are
/// common), then `holes` bridging cells (Yokoi number 2, no 2 × 2 block), each closing one
/// loop.
fn thin_arms_pixels(n: usize, holes: usize, compactness: f64, rng: &mut Rng) -> Option<Vec<Pixel>> {
    let tree = n - holes;
    let mut c = Canvas::for_target(n, 4, rng);
    let (x, y) = center(&c, rng);
    let k0 = c.idx(x, y);
    c.set(k0, true);
    let mut front: Vec<u32> = (0..4).map(|i| c.nb(k0, 2 * i) as u32).collect();
    let branchy = 0.15 + 0.7 * compactness;
    let mut budget = 400 * n + 1000;
    while c.count < tree {
        if front.is_empty() || budget == 0 {
            return None;
        }
        budget -= 1;
        let i = below(rng, front.len());
        let k = front[i] as usize;
        if c.occ[k] || !c.in_zone(k, ADJ_MARGIN) || c.yokoi(k) != 1 || makes_block(&c, k) {
            front.swap_remove(i);
            continue;
        }
        let branch = (0..4)
            .map(|d| c.nb(k, 2 * d))
            .any(|q| c.occ[q] && c.nb4(q) >= 2);
        let p = if branch { branchy } else { 1.0 - branchy / 2.0 };
        if chance(rng, p) {
            c.set(k, true);
            front.swap_remove(i);
            front.extend(
                (0..4)
                    .map(|d| c.nb(k, 2 * d))
                    .filter(|&q| !c.occ[q])
                    .map(|q| q as u32),
            );
        }
    }
    let mut bridges: Vec<u32> = (0..c.area())
        .filter(|&k| !c.occ[k] && c.in_zone(k, ADJ_MARGIN) && c.yokoi(k) == 2)
        .map(|k| k as u32)
        .collect();
    shuffle(&mut bridges, rng);
    let mut made = 0;
    while made < holes {
        let k = bridges.pop()? as usize;
        if !c.occ[k] && c.yokoi(k) == 2 && !makes_block(&c, k) {
            c.set(k, true);
            made += 1;
        }
    }
    Some(c.pixels())
}

/// A shape of exactly n pixels with exactly `holes` one-pixel holes: a hole-free shape of
/// n + holes pixels of the given style, then pixels whose 3 × 3 block is full are removed
/// (each a new hole of one cell, so holes are at least one wall pixel apart); after a hole,
/// with a probability drawn per instance, the next one continues a column (or, less often, a
/// row) 2 to 4 cells further on, so that hole contours line up with one another and with the
/// strips between them.
fn pinholes_canvas(n: usize, holes: usize, o: &ShapeOpts, rng: &mut Rng) -> Option<Canvas> {
    let (mut c, _) = simple_canvas(n + holes, o, rng)?;
    let mut sites: Vec<u32> = (0..c.area())
        .filter(|&k| c.occ[k] && c.in_zone(k, ADJ_MARGIN + 1) && c.full(k, 1))
        .map(|k| k as u32)
        .collect();
    shuffle(&mut sites, rng);
    let column = unit(rng);
    let mut last: Option<(usize, (i64, i64))> = None;
    for _ in 0..holes {
        let next = last
            .filter(|_| chance(rng, column))
            .and_then(|(k, (dx, dy))| {
                let step = between(rng, 2, 4) as i64;
                let (x, y) = ((k % c.w) as i64 + step * dx, (k / c.w) as i64 + step * dy);
                if !c.zone_xy(x, y, ADJ_MARGIN + 1) {
                    return None;
                }
                let q = c.idx(x as usize, y as usize);
                (c.occ[q] && c.full(q, 1)).then_some((q, (dx, dy)))
            });
        let (k, dir) = match next {
            Some(found) => found,
            None => {
                let k = pop_site(&c, &mut sites, 1)?;
                let dir = match (chance(rng, 0.7), chance(rng, 0.5)) {
                    (true, true) => (0, 1),
                    (true, false) => (0, -1),
                    (false, true) => (1, 0),
                    (false, false) => (-1, 0),
                };
                (k, dir)
            }
        };
        c.set(k, false);
        last = Some((k, dir));
    }
    Some(c)
}

// ---------------------------------------------------------------------------------------------
// Scattered lawns
// ---------------------------------------------------------------------------------------------

/// Random part sizes ≥ 1 summing to n.
fn part_sizes(n: usize, parts: usize, rng: &mut Rng) -> Vec<usize> {
    let raw: Vec<f64> = (0..parts).map(|_| 0.15 + unit(rng)).collect();
    let sum: f64 = raw.iter().sum();
    let spare = n - parts;
    let mut sizes: Vec<usize> = raw
        .iter()
        .map(|r| 1 + (spare as f64 * r / sum) as usize)
        .collect();
    let mut rest = n - sizes.iter().sum::<usize>();
    while rest > 0 {
        let i = below(rng, parts);
        sizes[i] += 1;
        rest -= 1;
    }
    sizes
}

/// One hole-free connected part of exactly `size` pixels, translated to start at (0, 0).
fn lawn_part(size: usize, o: &ShapeOpts, rng: &mut Rng) -> Vec<Pixel> {
    let promise = Promise {
        n: size,
        components: 1,
        holes: 0,
        cut: CutRule::Any,
        thin: false,
        separated: false,
        any_holes: false,
        boundary_only: false,
    };
    for _ in 0..MAX_ATTEMPTS {
        if let Some((c, _)) = simple_canvas(size, o, rng)
            && let Ok(region) = Region::from_pixels(c.pixels())
            && verify(&region, &promise).is_ok()
        {
            return region.normalized().pixels().to_vec();
        }
    }
    rows_pixels(size, 0, false, rng).expect("a staircase without constraints always exists")
}

/// P parts laid out on shelves with gaps of 1 to 3 empty cells, then pulled towards the
/// middle by random moves that keep every part two cells (Chebyshev) from the others.
fn lawn_pixels(n: usize, parts: usize, o: &ShapeOpts, rng: &mut Rng) -> Vec<Pixel> {
    let sizes = part_sizes(n, parts, rng);
    let shapes: Vec<Vec<Pixel>> = sizes.iter().map(|&s| lawn_part(s, o, rng)).collect();
    let dims: Vec<(i64, i64)> = shapes
        .iter()
        .map(|s| {
            let w = s.iter().map(|p| p.x).max().unwrap_or(0) as i64 + 1;
            let h = s.iter().map(|p| p.y).max().unwrap_or(0) as i64 + 1;
            (w, h)
        })
        .collect();
    // Shelves.
    let footprint: i64 = dims.iter().map(|&(w, h)| (w + 2) * (h + 2)).sum();
    let widest = dims.iter().map(|d| d.0).max().unwrap_or(1);
    let limit = widest.max(((footprint as f64).sqrt() * (1.0 + 0.6 * unit(rng))) as i64);
    let mut pos = Vec::with_capacity(parts);
    let (mut x, mut y, mut row_h) = (0i64, 0i64, 0i64);
    for &(w, h) in &dims {
        if x > 0 && x + w > limit {
            y += row_h + between(rng, 1, 3) as i64;
            (x, row_h) = (0, 0);
        }
        let dy = below(rng, 3) as i64;
        pos.push((x, y + dy));
        x += w + between(rng, 1, 3) as i64;
        row_h = row_h.max(h + dy);
    }
    let width = pos
        .iter()
        .zip(&dims)
        .map(|(p, d)| p.0 + d.0)
        .max()
        .unwrap_or(1);
    let height = pos
        .iter()
        .zip(&dims)
        .map(|(p, d)| p.1 + d.1)
        .max()
        .unwrap_or(1);
    // Owner grid with a frame of 1, for the separation test.
    let gw = (width + 2) as usize;
    let gh = (height + 2) as usize;
    let mut owner = vec![u32::MAX; gw * gh];
    let cell = |x: i64, y: i64| (y + 1) as usize * gw + (x + 1) as usize;
    for (i, s) in shapes.iter().enumerate() {
        for p in s {
            owner[cell(pos[i].0 + i64::from(p.x), pos[i].1 + i64::from(p.y))] = i as u32;
        }
    }
    // Compaction, with a work budget linear in n.
    let mut budget = 8 * n as i64 + 1000;
    let (cx, cy) = (width / 2, height / 2);
    while budget > 0 && parts > 1 {
        let i = below(rng, parts);
        let (w, h) = dims[i];
        let (dx, dy) = (
            between(rng, 0, w as usize) as i64 - w / 2,
            between(rng, 0, h as usize) as i64 - h / 2,
        );
        let (nx, ny) = (pos[i].0 + dx, pos[i].1 + dy);
        let centre = |x: i64, y: i64| (x + w / 2 - cx).abs() + (y + h / 2 - cy).abs();
        budget -= 1;
        if nx < 0
            || ny < 0
            || nx + w > width
            || ny + h > height
            || centre(nx, ny) >= centre(pos[i].0, pos[i].1)
        {
            continue;
        }
        let mut ok = true;
        for p in &shapes[i] {
            budget -= 1;
            let (px, py) = (nx + i64::from(p.x), ny + i64::from(p.y));
            if (py - 1..=py + 1).any(|qy| {
                (px - 1..=px + 1).any(|qx| {
                    qx >= -1 && qy >= -1 && qx <= width && qy <= height && {
                        let o = owner[cell(qx, qy)];
                        o != u32::MAX && o != i as u32
                    }
                })
            }) {
                ok = false;
                break;
            }
        }
        if !ok {
            continue;
        }
        for p in &shapes[i] {
            owner[cell(pos[i].0 + i64::from(p.x), pos[i].1 + i64::from(p.y))] = u32::MAX;
        }
        pos[i] = (nx, ny);
        for p in &shapes[i] {
            owner[cell(nx + i64::from(p.x), ny + i64::from(p.y))] = i as u32;
        }
        budget -= shapes[i].len() as i64;
    }
    shapes
        .iter()
        .zip(&pos)
        .flat_map(|(s, &(px, py))| {
            s.iter()
                .map(move |p| Pixel::new(p.x + px as i32, p.y + py as i32))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::collections::BTreeSet;

    fn params(family: Family, seed: u64) -> GenParams {
        GenParams::new(family, seed)
    }

    fn simple(n: usize, seed: u64) -> GenParams {
        GenParams {
            n: Some(n),
            ..params(Family::RandomSimple, seed)
        }
    }

    fn holed(n: usize, holes: usize, seed: u64) -> GenParams {
        GenParams {
            n: Some(n),
            holes: Some(holes),
            ..params(Family::RandomHoled, seed)
        }
    }

    fn thin(n: usize, holes: usize, seed: u64) -> GenParams {
        GenParams {
            n: Some(n),
            holes: Some(holes),
            ..params(Family::Thin, seed)
        }
    }

    fn lawn(n: usize, parts: usize, seed: u64) -> GenParams {
        GenParams {
            n: Some(n),
            parts: Some(parts),
            ..params(Family::LawnScattered, seed)
        }
    }

    /// Every promise of a generated file, recounted independently of `verify`.
    fn assert_promises(f: &GridFile, p: &GenParams) {
        let r = &f.region;
        let s = topology::summary(r);
        assert_eq!(r.bbox().min_x, 0, "normalized");
        assert_eq!(r.bbox().min_y, 0, "normalized");
        assert_eq!(f.meta("n"), Some(s.n.to_string().as_str()));
        assert_eq!(f.meta("holes"), Some(s.holes.to_string().as_str()));
        assert_eq!(f.meta("family"), Some(p.family.name()));
        assert_eq!(f.meta("seed"), Some(p.seed.to_string().as_str()));
        if let Some(n) = p.n {
            assert_eq!(s.n, n, "exact n\n{r:?}");
        }
        match p.family {
            Family::RandomSimple => {
                assert_eq!((s.components, s.holes), (1, 0), "{r:?}");
                if p.no_cut {
                    assert_eq!(s.cut_vertices, 0, "no cut vertex\n{r:?}");
                }
            }
            Family::RandomHoled => {
                assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(1)), "{r:?}");
                if p.no_cut {
                    assert_eq!(s.local_cut_vertices, 0, "no local cut vertex\n{r:?}");
                }
            }
            Family::Thin => {
                assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(0)), "{r:?}");
                assert!(s.thin, "thin\n{r:?}");
            }
            Family::LawnScattered => {
                let parts = p.parts.unwrap_or(3);
                assert_eq!((s.components, s.holes), (parts, 0), "{r:?}");
                // 8-separation: dilating each component by one cell meets no other component.
                let comps = topology::components(r);
                for (i, &px) in r.pixels().iter().enumerate() {
                    for q in topology::ring(px) {
                        if let Some(j) = r.index_of(q) {
                            assert_eq!(
                                comps.label[i], comps.label[j],
                                "parts touch at {px} and {q}\n{r:?}"
                            );
                        }
                    }
                }
            }
            Family::Boundary => {
                assert_eq!(s.components, 1, "{r:?}");
                assert!(
                    (0..r.len()).all(|i| topology::is_boundary(r, i)),
                    "every pixel a boundary pixel\n{r:?}"
                );
            }
            Family::ThinArms => {
                assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(0)), "{r:?}");
                assert!(s.thin, "thin\n{r:?}");
            }
            Family::Pinholes => {
                assert_eq!((s.components, s.holes), (1, p.holes.unwrap()), "{r:?}");
                let cells = topology::holes(r).hole_cells();
                assert!(cells.iter().all(|h| h.len() == 1), "one-pixel holes\n{r:?}");
            }
            Family::Rect | Family::Donut | Family::Band | Family::Thin43 => {}
        }
    }

    fn gen_ok(p: &GenParams) -> GridFile {
        let f = generate(p).unwrap_or_else(|e| panic!("{p:?}: {e}"));
        assert_promises(&f, p);
        f
    }

    fn refused(p: &GenParams) -> String {
        match generate(p) {
            Err(Error::Invalid(m)) => m,
            other => panic!("expected a refusal for {p:?}, got {other:?}"),
        }
    }

    #[test]
    fn registry_rows_match_the_enum_and_names_round_trip() {
        for (i, f) in Family::ALL.into_iter().enumerate() {
            assert_eq!(FAMILY_TABLE[i].family, f);
            assert_eq!(f.to_string().parse::<Family>().unwrap(), f);
            for q in f.info().required {
                assert!(
                    f.info().params.contains(q),
                    "{f}: required {q:?} is a parameter"
                );
            }
        }
        for s in Style::ALL {
            assert_eq!(s.to_string().parse::<Style>().unwrap(), s);
        }
        let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
        assert_eq!(
            names,
            [
                "rect",
                "random-simple",
                "random-holed",
                "thin",
                "lawn-scattered",
                "donut",
                "band",
                "thin43",
                "boundary",
                "thin-arms",
                "pinholes"
            ]
        );
        let e = "disc".parse::<Family>().unwrap_err().to_string();
        assert!(e.contains("expected one of rect, random-simple"), "{e}");
        assert!("round".parse::<Style>().is_err());
    }

    #[test]
    fn metadata_lines_are_fixed() {
        let p = GenParams {
            style: Some(Style::Blob),
            compactness: Some(0.5),
            ..simple(50, 9)
        };
        let f = gen_ok(&p);
        assert_eq!(
            f.comments,
            [
                " family: random-simple",
                " params: n=50 no_cut=false style=blob compactness=0.5",
                " seed: 9",
                " n: 50",
                " holes: 0"
            ]
        );
        let f = gen_ok(&GenParams {
            no_cut: true,
            ..holed(200, 2, 4)
        });
        let line = f.meta("params").unwrap();
        assert!(
            line.starts_with("n=200 holes=2 no_cut=true style="),
            "{line}"
        );
        let f = gen_ok(&GenParams {
            width: Some(3),
            height: Some(2),
            ..params(Family::Rect, 1)
        });
        assert_eq!(
            f.to_text().unwrap(),
            "; family: rect\n; params: width=3 height=2\n; seed: 1\n; n: 6\n; holes: 0\n###\n###\n"
        );
        let f = gen_ok(&GenParams {
            n: Some(40),
            ..params(Family::Thin, 3)
        });
        assert!(
            f.meta("params")
                .unwrap()
                .starts_with("n=40 holes=0 compactness=")
        );
        let f = gen_ok(&GenParams {
            n: Some(40),
            ..params(Family::LawnScattered, 3)
        });
        assert!(f.meta("params").unwrap().starts_with("n=40 parts=3 style="));
    }

    #[test]
    fn same_seed_same_bytes_other_seed_other_bytes() {
        let cases = [
            simple(300, 0),
            holed(400, 3, 0),
            thin(300, 2, 0),
            lawn(300, 4, 0),
        ];
        for p in cases {
            let a = generate(&p).unwrap().to_text().unwrap();
            let b = generate(&p).unwrap().to_text().unwrap();
            assert_eq!(a, b, "{p:?}");
            let other = GenParams {
                seed: 1,
                ..p.clone()
            };
            let c = generate(&other).unwrap().to_text().unwrap();
            assert_ne!(
                a.lines().skip(5).collect::<Vec<_>>(),
                c.lines().skip(5).collect::<Vec<_>>(),
                "{p:?}"
            );
        }
    }

    #[test]
    fn written_style_and_compactness_reproduce_the_instance() {
        for seed in 0..6 {
            for p in [
                simple(250, seed),
                holed(400, 2, seed),
                lawn(200, 3, seed),
                thin(150, 1, seed),
            ] {
                let f = gen_ok(&p);
                let line = f.meta("params").unwrap().to_string();
                let mut q = p.clone();
                for kv in line.split(' ') {
                    let (k, v) = kv.split_once('=').unwrap();
                    match k {
                        "style" => q.style = Some(v.parse().unwrap()),
                        "compactness" => q.compactness = Some(v.parse().unwrap()),
                        _ => {}
                    }
                }
                assert_eq!(
                    generate(&q).unwrap().to_text().unwrap(),
                    f.to_text().unwrap(),
                    "{line}"
                );
            }
        }
    }

    #[test]
    fn rect_and_donut_counts() {
        let f = gen_ok(&GenParams {
            width: Some(7),
            height: Some(3),
            ..params(Family::Rect, 0)
        });
        assert_eq!(f.region, Region::rectangle(7, 3));
        for side in 3..14usize {
            for k in 1..=(side - 1) / 2 {
                let f = gen_ok(&GenParams {
                    side: Some(side),
                    k: Some(k),
                    ..params(Family::Donut, 0)
                });
                let inner = side - 2 * k;
                assert_eq!(f.region.len(), side * side - inner * inner);
                assert_eq!(topology::holes(&f.region).count, 1);
                assert_eq!(topology::components(&f.region).count, 1);
                assert_eq!(f.region.bbox().width(), side);
                // The hole is the centred square.
                let cells = topology::holes(&f.region).hole_cells();
                assert_eq!(cells[0].len(), inner * inner);
                assert!(cells[0].contains(&Pixel::new(k as i32, k as i32)));
            }
        }
        assert_eq!(
            gen_ok(&GenParams {
                side: Some(5),
                k: Some(1),
                ..params(Family::Donut, 0)
            })
            .region,
            Region::from_ascii("#####\n#...#\n#...#\n#...#\n#####\n")
        );
    }

    #[test]
    fn refusals_are_clear() {
        assert!(refused(&simple(0, 0)).contains("n ≥ 1"));
        for n in [3, 5, 7] {
            let m = refused(&GenParams {
                no_cut: true,
                ..simple(n, 0)
            });
            assert!(m.contains("cut vertex"), "{m}");
        }
        let m = refused(&holed(7, 1, 0));
        assert!(m.contains("needs n ≥ 8"), "{m}");
        let m = refused(&holed(12, 2, 0));
        assert!(m.contains("needs n ≥ 13"), "{m}");
        let m = refused(&GenParams {
            no_cut: true,
            ..holed(23, 1, 0)
        });
        assert!(m.contains("needs n ≥ 24"), "{m}");
        let m = refused(&GenParams {
            no_cut: true,
            ..holed(25, 1, 0)
        });
        assert!(
            m.contains("cannot build exactly 1 holes in exactly 25"),
            "{m}"
        );
        assert!(refused(&holed(10, 11, 0)).contains("do not fit"));
        assert!(refused(&holed(10, usize::MAX, 0)).contains("do not fit"));
        assert!(refused(&thin(7, 1, 0)).contains("n ≥ 8"));
        assert!(refused(&thin(12, 2, 0)).contains("n ≥ 13"));
        assert!(refused(&lawn(3, 4, 0)).contains("parts ≤ n"));
        assert!(refused(&lawn(3, 0, 0)).contains("parts"));
        let m = refused(&GenParams {
            no_cut: true,
            ..thin(30, 0, 0)
        });
        assert!(m.contains("`no_cut` does not apply to family thin"), "{m}");
        let m = refused(&GenParams {
            holes: Some(2),
            ..simple(30, 0)
        });
        assert!(m.contains("`holes` does not apply to family random-simple (it takes: n, no_cut, style, compactness)"), "{m}");
        let m = refused(&GenParams {
            n: Some(30),
            ..params(Family::Rect, 0)
        });
        assert!(m.contains("`n` does not apply"), "{m}");
        assert!(
            refused(&GenParams {
                width: Some(3),
                ..params(Family::Rect, 0)
            })
            .contains("needs parameter `height`")
        );
        assert!(refused(&params(Family::RandomHoled, 0)).contains("needs parameter `n`"));
        assert!(
            refused(&GenParams {
                width: Some(0),
                height: Some(3),
                ..params(Family::Rect, 0)
            })
            .contains("width ≥ 1")
        );
        assert!(
            refused(&GenParams {
                side: Some(4),
                k: Some(2),
                ..params(Family::Donut, 0)
            })
            .contains("side ≥ 2k + 1")
        );
        assert!(
            refused(&GenParams {
                side: Some(4),
                k: Some(0),
                ..params(Family::Donut, 0)
            })
            .contains("k ≥ 1")
        );
        assert!(
            refused(&GenParams {
                compactness: Some(1.5),
                ..simple(30, 0)
            })
            .contains("between 0 and 1")
        );
        assert!(
            refused(&GenParams {
                compactness: Some(f64::NAN),
                ..simple(30, 0)
            })
            .contains("between 0 and 1")
        );
        assert!(refused(&simple(MAX_PIXELS + 1, 0)).contains("limit"));
        let big = GenParams {
            width: Some(1 << 40),
            height: Some(1 << 40),
            ..params(Family::Rect, 0)
        };
        assert!(refused(&big).contains("limit"));
    }

    /// All fixed polyominoes with up to `max` cells, as sorted pixel sets at the origin.
    fn polyominoes(max: usize) -> Vec<Vec<BTreeSet<(i32, i32)>>> {
        let mut by_size = vec![Vec::new()];
        let mut layer: BTreeSet<Vec<(i32, i32)>> = BTreeSet::from([vec![(0, 0)]]);
        for _ in 1..=max {
            by_size.push(layer.iter().map(|v| v.iter().copied().collect()).collect());
            let mut next = BTreeSet::new();
            for cells in &layer {
                for &(x, y) in cells {
                    for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
                        let c = (x + dx, y + dy);
                        if cells.contains(&c) {
                            continue;
                        }
                        let mut v: Vec<(i32, i32)> = cells.iter().copied().chain([c]).collect();
                        let (mx, my) = (
                            v.iter().map(|p| p.0).min().unwrap(),
                            v.iter().map(|p| p.1).min().unwrap(),
                        );
                        v.iter_mut().for_each(|p| *p = (p.0 - mx, p.1 - my));
                        v.sort_unstable();
                        next.insert(v);
                    }
                }
            }
            layer = next;
        }
        by_size
    }

    #[test]
    fn no_cut_sizes_match_an_exhaustive_search() {
        let all = polyominoes(9);
        assert_eq!(all[7].len(), 760, "fixed heptominoes");
        for (n, polys) in all.iter().enumerate().skip(1) {
            let exists = polys.iter().any(|cells| {
                let r = Region::from_pixels(cells.iter().map(|&(x, y)| Pixel::new(x, y))).unwrap();
                topology::holes(&r).count == 0 && !topology::cut_vertices(&r).contains(&true)
            });
            let p = GenParams {
                no_cut: true,
                ..simple(n, 1)
            };
            assert_eq!(generate(&p).is_ok(), exists, "n = {n}");
            if exists {
                gen_ok(&p);
            }
        }
    }

    #[test]
    fn staircases_keep_their_promises() {
        let mut rng = rng_for(0, 0);
        for no_cut in [false, true] {
            for holes in 0..6 {
                for n in 1..400 {
                    let Some(pixels) = rows_pixels(n, holes, no_cut, &mut rng) else {
                        if !no_cut {
                            assert!(n < min_holed_pixels(holes, false), "n {n} holes {holes}");
                        }
                        continue;
                    };
                    assert!(n >= min_holed_pixels(holes, no_cut), "n {n} holes {holes}");
                    let region = Region::from_pixels(pixels).unwrap();
                    let cut = if no_cut {
                        CutRule::NoLocalCut
                    } else {
                        CutRule::Any
                    };
                    let promise = Promise {
                        n,
                        components: 1,
                        holes,
                        cut,
                        thin: false,
                        separated: false,
                        any_holes: false,
                        boundary_only: false,
                    };
                    assert_eq!(
                        verify(&region, &promise),
                        Ok(holes),
                        "n {n} holes {holes} no_cut {no_cut}\n{region:?}"
                    );
                }
            }
        }
        // Every size from the minimum up is possible without no_cut.
        for holes in 0..30 {
            let min = min_holed_pixels(holes, false);
            assert!(
                (min..min + 200).all(|n| rows_plan(n, holes, false).is_some()),
                "holes {holes}"
            );
        }
    }

    #[test]
    fn thin_capacity_is_the_harary_harborth_bound() {
        for t in 1..5000 {
            // At most ⌊2t − 2√t⌋ = 2t − ⌈2√t⌉ = 2t − ⌈√(4t)⌉ lattice edges among t nodes.
            let max_edges = 2 * t - ceil_sqrt(4 * t);
            assert_eq!(thin_capacity(t), max_edges + 1 - t, "t = {t}");
        }
        assert_eq!(min_thin_pixels(0), 1);
        assert_eq!(min_thin_pixels(1), 8);
        assert_eq!(min_thin_pixels(2), 13);
    }

    #[test]
    fn thin_fallback_keeps_its_promises() {
        let mut rng = rng_for(0, 0);
        for holes in 0..12 {
            for n in min_thin_pixels(holes)..min_thin_pixels(holes) + 60 {
                let pixels =
                    thin_pixels(n, holes, 0.5, None, &mut rng).expect("fallback always succeeds");
                let region = Region::from_pixels(pixels).unwrap();
                let promise = Promise {
                    n,
                    components: 1,
                    holes,
                    cut: CutRule::Any,
                    thin: true,
                    separated: false,
                    any_holes: false,
                    boundary_only: false,
                };
                assert_eq!(
                    verify(&region, &promise),
                    Ok(holes),
                    "n {n} holes {holes}\n{region:?}"
                );
            }
        }
    }

    /// The random constructions never return a region that breaks its promise: the retry in
    /// `with_attempts` is a safety net, not a filter.
    #[test]
    fn random_constructions_return_only_valid_regions() {
        let (mut made, mut none) = (0, 0);
        for seed in 0..6u64 {
            for style in Style::CONCRETE {
                for no_cut in [false, true] {
                    let o = ShapeOpts {
                        style,
                        compactness: seed as f64 / 5.0,
                        no_cut,
                    };
                    let cut = |holed: bool| match (no_cut, holed) {
                        (false, _) => CutRule::Any,
                        (true, false) => CutRule::NoCut,
                        (true, true) => CutRule::NoLocalCut,
                    };
                    for n in [8usize, 30, 100, 400, 1500] {
                        let mut rng = rng_for(seed, n as u64);
                        let promise = Promise {
                            n,
                            components: 1,
                            holes: 0,
                            cut: cut(false),
                            thin: false,
                            separated: false,
                            any_holes: false,
                            boundary_only: false,
                        };
                        match simple_canvas(n, &o, &mut rng) {
                            Some((c, _)) => {
                                let r = Region::from_pixels(c.pixels()).unwrap();
                                assert_eq!(
                                    verify(&r, &promise),
                                    Ok(0),
                                    "{style} no_cut {no_cut} n {n}\n{r:?}"
                                );
                                made += 1;
                            }
                            None => none += 1,
                        }
                        let holes = 1 + (seed as usize + n) % 4;
                        if n < min_holed_pixels(holes, no_cut) {
                            continue;
                        }
                        let promise = Promise {
                            holes,
                            cut: cut(true),
                            ..promise
                        };
                        match holed_canvas(n, holes, &o, &mut rng) {
                            Some(c) => {
                                let r = Region::from_pixels(c.pixels()).unwrap();
                                assert_eq!(
                                    verify(&r, &promise),
                                    Ok(holes),
                                    "{style} no_cut {no_cut} n {n}\n{r:?}"
                                );
                                made += 1;
                            }
                            None => none += 1,
                        }
                    }
                }
            }
        }
        for seed in 0..40u64 {
            let (n, holes) = (20 + 23 * seed as usize, seed as usize % 6);
            let mut rng = rng_for(seed, 0);
            if let Some(pixels) =
                thin_pixels(n, holes, seed as f64 / 40.0, Some(seed % 3), &mut rng)
            {
                let r = Region::from_pixels(pixels).unwrap();
                let promise = Promise {
                    n,
                    components: 1,
                    holes,
                    cut: CutRule::Any,
                    thin: true,
                    separated: false,
                    any_holes: false,
                    boundary_only: false,
                };
                assert_eq!(verify(&r, &promise), Ok(holes), "thin n {n}\n{r:?}");
            }
        }
        assert!(
            none * 5 <= made,
            "{none} failed constructions for {made} successes"
        );
    }

    /// The random constructions, not the fallbacks, make the instances of ordinary sizes.
    #[test]
    fn fallback_stays_rare() {
        let mut fallbacks = Vec::new();
        let mut later = 0;
        let mut total = 0;
        for seed in 0..12 {
            for style in Style::ALL {
                for no_cut in [false, true] {
                    let st = Some(style);
                    let cases = [
                        GenParams {
                            style: st,
                            no_cut,
                            ..simple(60 + 97 * seed as usize, seed)
                        },
                        GenParams {
                            style: st,
                            no_cut,
                            ..holed(300 + 211 * seed as usize, 1 + seed as usize % 5, seed)
                        },
                    ];
                    for p in cases {
                        let (_, provenance) = generate_traced(&p).unwrap();
                        total += 1;
                        match provenance {
                            Provenance::Fallback => fallbacks.push(p),
                            Provenance::Attempt(a) if a > 0 => later += 1,
                            _ => {}
                        }
                    }
                }
            }
        }
        assert!(fallbacks.is_empty(), "fallbacks: {fallbacks:?}");
        assert!(
            later * 10 <= total,
            "{later} of {total} needed a second attempt"
        );
        for seed in 0..20 {
            let (_, provenance) =
                generate_traced(&thin(100 + 37 * seed as usize, seed as usize % 7, seed)).unwrap();
            assert!(
                matches!(provenance, Provenance::Attempt(_)),
                "thin seed {seed}"
            );
        }
    }

    /// The hard-shape families come from their random constructions, not their fallbacks,
    /// and show the features they are for.
    #[test]
    fn hard_shapes_are_random_and_show_their_features() {
        let (mut total, mut fallbacks) = (0, Vec::new());
        let (mut holed, mut links, mut crossings, mut columns) = (0, 0, 0, 0);
        for seed in 0..40u64 {
            let n = 12 + 7 * seed as usize;
            let cases = [
                GenParams {
                    n: Some(n),
                    ..params(Family::Boundary, seed)
                },
                GenParams {
                    n: Some(n),
                    holes: Some(seed as usize % 3),
                    ..params(Family::ThinArms, seed)
                },
                GenParams {
                    n: Some(n + 30),
                    holes: Some(1 + seed as usize % 6),
                    ..params(Family::Pinholes, seed)
                },
            ];
            for p in cases {
                let (f, provenance) = generate_traced(&p).unwrap();
                assert_promises(&f, &p);
                total += 1;
                if provenance == Provenance::Fallback {
                    fallbacks.push(p.clone());
                }
                let r = &f.region;
                match p.family {
                    Family::Boundary => {
                        holed += usize::from(topology::holes(r).count > 0);
                        // A pixel without its north and south neighbours: a one-pixel link.
                        links += usize::from((0..r.len()).any(|i| {
                            r.neighbor(i, Dir::N).is_none()
                                && r.neighbor(i, Dir::S).is_none()
                                && r.degree(i) == 2
                        }));
                    }
                    Family::ThinArms => {
                        crossings += usize::from((0..r.len()).any(|i| r.degree(i) == 4));
                    }
                    _ => {
                        let cells: BTreeSet<(i32, i32)> = topology::holes(r)
                            .hole_cells()
                            .iter()
                            .flatten()
                            .map(|p| (p.x, p.y))
                            .collect();
                        columns += usize::from(cells.iter().any(|&(x, y)| {
                            (2..=4)
                                .any(|d| cells.contains(&(x, y + d)) || cells.contains(&(x + d, y)))
                        }));
                    }
                }
            }
        }
        assert!(fallbacks.len() * 20 <= total, "fallbacks: {fallbacks:?}");
        assert!(
            holed >= 10 && links >= 20,
            "boundary: {holed} holed, {links} with links"
        );
        assert!(crossings >= 10, "thin-arms: {crossings} with a crossing");
        assert!(columns >= 10, "pinholes: {columns} with holes in line");
    }

    fn boundary_fraction(f: &GridFile) -> f64 {
        let s = topology::summary(&f.region);
        s.boundary as f64 / s.n as f64
    }

    #[test]
    fn compactness_and_style_change_the_shape() {
        for seed in 0..5 {
            let blob = |c: f64| GenParams {
                style: Some(Style::Blob),
                compactness: Some(c),
                ..simple(3000, seed)
            };
            let round = boundary_fraction(&gen_ok(&blob(1.0)));
            let ragged = boundary_fraction(&gen_ok(&blob(0.0)));
            assert!(
                round < 0.2 && ragged > 0.6,
                "seed {seed}: round {round}, ragged {ragged}"
            );
            let snake = GenParams {
                style: Some(Style::Snake),
                ..simple(3000, seed)
            };
            let snake = boundary_fraction(&gen_ok(&snake));
            assert!(
                snake > 2.0 * round,
                "seed {seed}: snake {snake}, round {round}"
            );
        }
        // Mixed draws every style.
        let drawn: BTreeSet<String> = (0..40)
            .map(|s| {
                gen_ok(&simple(50, s))
                    .meta("params")
                    .unwrap()
                    .split(' ')
                    .nth(2)
                    .unwrap()
                    .to_string()
            })
            .collect();
        assert_eq!(drawn.len(), 4, "{drawn:?}");
    }

    #[test]
    fn holes_vary_in_size() {
        let mut sizes = BTreeSet::new();
        for seed in 0..4 {
            let f = gen_ok(&GenParams {
                style: Some(Style::Blob),
                compactness: Some(0.8),
                ..holed(4000, 6, seed)
            });
            sizes.extend(topology::holes(&f.region).hole_cells().iter().map(Vec::len));
        }
        assert!(
            sizes.len() >= 8 && *sizes.last().unwrap() >= 20,
            "hole sizes {sizes:?}"
        );
    }

    fn style_strategy() -> impl Strategy<Value = Option<Style>> {
        proptest::option::of(proptest::sample::select(Style::ALL.to_vec()))
    }

    fn compactness_strategy() -> impl Strategy<Value = Option<f64>> {
        proptest::option::of((0u32..=20).prop_map(|k| f64::from(k) / 20.0))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn random_simple_keeps_its_promises(n in 1usize..400, seed: u64, no_cut: bool,
                                            style in style_strategy(), c in compactness_strategy()) {
            prop_assume!(!(no_cut && [3, 5, 7].contains(&n)));
            gen_ok(&GenParams { no_cut, style, compactness: c, ..simple(n, seed) });
        }

        #[test]
        fn random_holed_keeps_its_promises(n in 1usize..500, holes in 0usize..7, seed: u64, no_cut: bool,
                                           style in style_strategy(), c in compactness_strategy()) {
            let p = GenParams { no_cut, style, compactness: c, ..holed(n, holes, seed) };
            if n < min_holed_pixels(holes, no_cut) || (no_cut && rows_plan(n, holes, true).is_none()) {
                refused(&p);
            } else {
                gen_ok(&p);
            }
        }

        #[test]
        fn thin_keeps_its_promises(n in 1usize..500, holes in 0usize..10, seed: u64, c in compactness_strategy()) {
            let p = GenParams { compactness: c, ..thin(n, holes, seed) };
            if n < min_thin_pixels(holes) {
                refused(&p);
            } else {
                gen_ok(&p);
            }
        }

        #[test]
        fn boundary_keeps_its_promises(n in 1usize..400, seed: u64, style in style_strategy(), c in compactness_strategy()) {
            gen_ok(&GenParams { n: Some(n), style, compactness: c, ..params(Family::Boundary, seed) });
        }

        #[test]
        fn thin_arms_keeps_its_promises(n in 1usize..400, holes in 0usize..8, seed: u64, c in compactness_strategy()) {
            let p = GenParams { n: Some(n), holes: Some(holes), compactness: c, ..params(Family::ThinArms, seed) };
            if n < min_thin_pixels(holes) {
                refused(&p);
            } else {
                gen_ok(&p);
            }
        }

        #[test]
        fn pinholes_keeps_its_promises(n in 1usize..400, holes in 0usize..12, seed: u64, style in style_strategy()) {
            let p = GenParams { n: Some(n), holes: Some(holes), style, ..params(Family::Pinholes, seed) };
            if n < min_holed_pixels(holes, false) {
                refused(&p);
            } else {
                gen_ok(&p);
            }
        }

        #[test]
        fn lawn_keeps_its_promises(n in 1usize..400, parts in 1usize..9, seed: u64, style in style_strategy()) {
            prop_assume!(parts <= n);
            gen_ok(&GenParams { style, ..lawn(n, parts, seed) });
        }
    }
}
