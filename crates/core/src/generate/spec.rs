//! Resolved parameters: defaults and seed-drawn values applied, refusals, promises, and the
//! dispatch to each family's construction with retries and fallback.

use super::band::band_pixels;
use super::boundary::{boundary_canvas, two_rows_pixels};
use super::boundary_rooms::boundary_rooms_canvas;
use super::checks::{CutRule, Promise, verify};
use super::comb::{comb_count, comb_default_teeth, comb_length, comb_pixels};
use super::corridor_star::{star_arm, star_count, star_pixels};
use super::eroded::eroded_pixels;
use super::hole_lattice::{Pattern, hole_lattice_pixels, lattice_half_side, lattice_pixels_count};
use super::lawn::lawn_pixels;
use super::outlines::{
    Layout, crossings, outlines_default_k, outlines_layout, outlines_pixels, outlines_spacing,
    slot_perimeter,
};
use super::pinholes::pinholes_canvas;
use super::random_holed::holed_canvas;
use super::random_simple::simple_canvas;
use super::rect::{donut_pixels, rect_pixels};
use super::registry::{Family, PARAMS, Param};
use super::ring::{ring_count, ring_pixels, ring_sides};
use super::rng::{Rng, below, between, rng_for};
use super::spiral::{spiral_count, spiral_pixels, spiral_side};
use super::staircase::{min_holed_pixels, rows_pixels, rows_plan};
use super::styles::{ShapeOpts, Style};
use super::thin::{min_thin_pixels, thin_pixels};
use super::thin_arms::thin_arms_pixels;
use super::thin_eulerian::{ring_outline_pixels, slack, thin_eulerian_pixels};
use super::thin43::{thin43_holes, thin43_pixels};
use super::windows::{windows_count, windows_panes, windows_pixels};
use super::{GenParams, MAX_PIXELS, Provenance};
use crate::error::Error;
use crate::error::Result;
use crate::region::Pixel;
use crate::region::Region;

/// The largest `eroded` instance: its square has about 3N cells.
pub(super) const MAX_ERODED: usize = 1_000_000;

/// Refuses a style the family does not draw: `dense` and `sparse` are `eroded`'s only, and
/// `eroded` takes no shape style (`mixed` draws one of its two).
fn check_style(family: Family, style: Option<Style>) -> Result<()> {
    let Some(style) = style else {
        return Ok(());
    };
    let erosion = Style::ERODED.contains(&style);
    let names = |list: &[Style]| list.iter().map(|s| s.name()).collect::<Vec<_>>().join(", ");
    if family == Family::Eroded && !erosion && style != Style::Mixed {
        Err(Error::invalid(format!(
            "style {style} does not apply to family eroded (it takes: {}, or mixed to draw one)",
            names(&Style::ERODED)
        )))
    } else if family != Family::Eroded && erosion {
        Err(Error::invalid(format!(
            "style {style} applies to family eroded only ({family} takes: {})",
            names(&Style::ALL)
        )))
    } else {
        Ok(())
    }
}

/// Random attempts before the deterministic fallback pub(super) construction.
pub(super) const MAX_ATTEMPTS: u64 = 8;

/// Fully resolved parameters: defaults applied, `Mixed` and compactness drawn from the seed.
#[derive(Clone, Debug)]
pub(super) struct Spec {
    pub(super) family: Family,
    pub(super) n: usize,
    pub(super) holes: usize,
    pub(super) width: usize,
    pub(super) height: usize,
    pub(super) side: usize,
    pub(super) k: usize,
    pub(super) parts: usize,
    pub(super) no_cut: bool,
    pub(super) style: Style,
    pub(super) compactness: f64,
    pub(super) s: usize,
    pub(super) pattern: Pattern,
    pub(super) seed: u64,
}

/// What a structured family derives from n: its two dimensions (family-specific: the
/// half-side m, tooth length and sides, spiral side, panes per side, spacing, ring sides, arm
/// length) and the exact pixel count.
#[derive(Clone, Copy, Debug)]
struct Dims {
    a: usize,
    b: usize,
    count: usize,
}

/// Stream tag of the `outlines` layout.
const TAG_OUTLINES: u64 = 0x0u64;

/// The structured families (modules `hole_lattice`, `comb`, `spiral`, `windows`, `outlines`,
/// `ring`, `corridor_star`): deterministic shapes sized from n.
pub(super) fn structured(family: Family) -> bool {
    matches!(
        family,
        Family::HoleLattice
            | Family::Comb
            | Family::DoubleComb
            | Family::Spiral
            | Family::Windows
            | Family::Outlines
            | Family::Ring
            | Family::CorridorStar
    )
}

/// Tags of the seed-derived random streams.
pub(super) const TAG_RESOLVE: u64 = u64::MAX;

pub(super) const TAG_FALLBACK: u64 = u64::MAX - 1;

impl Spec {
    pub(super) fn resolve(p: &GenParams) -> Result<Spec> {
        let info = p.family.info();
        for spec in &PARAMS {
            if let Some(value) = p.get(spec.param) {
                info.check_takes(spec.param)?;
                spec.check(value)?;
            }
        }
        info.check_required(|q| p.get(q).is_some())?;
        // Drawn values come from their own stream, so that giving them explicitly reproduces
        // the same instance.
        let mut rng = rng_for(p.seed, TAG_RESOLVE);
        let drawn_style = Style::CONCRETE[below(&mut rng, Style::CONCRETE.len())];
        let drawn_compactness = between(&mut rng, 0, 100) as f64 / 100.0;
        check_style(p.family, p.style)?;
        let style = match (p.style.unwrap_or(Style::Mixed), p.family) {
            // The same draw picks between the two erosion styles (its stream is eroded's own
            // through the seed, and other families keep their draws).
            (Style::Mixed, Family::Eroded) => Style::ERODED[below(&mut rng, 2)],
            (Style::Mixed, _) => drawn_style,
            (s, _) => s,
        };
        // Structured families' defaults of k and width (0 = not taken).
        let default_k = match p.family {
            Family::Comb | Family::DoubleComb => comb_default_teeth(p.n.unwrap_or(0)),
            Family::Windows => 2,
            Family::Outlines => outlines_default_k(p.n.unwrap_or(0)),
            Family::CorridorStar => 4,
            _ => 0,
        };
        let default_width = match p.family {
            Family::Spiral | Family::Windows | Family::Ring | Family::CorridorStar => 1,
            _ => 0,
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
            width: p.width.unwrap_or(default_width),
            height: p.height.unwrap_or(0),
            side: p.side.unwrap_or(0),
            k: p.k.unwrap_or(default_k),
            parts: p.parts.unwrap_or(3),
            no_cut: p.no_cut,
            style,
            compactness: p.compactness.unwrap_or(drawn_compactness),
            s: p.s.unwrap_or(0),
            pattern: p.pattern.unwrap_or(Pattern::Staggered),
            seed: p.seed,
        })
    }

    pub(super) fn value(&self, q: Param) -> String {
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
            Param::Pattern => self.pattern.to_string(),
        }
    }

    pub(super) fn params_line(&self) -> String {
        let info = self.family.info();
        let parts: Vec<String> = info
            .params
            .iter()
            .map(|&q| format!("{}={}", q.name(), self.value(q)))
            .collect();
        parts.join(" ")
    }

    pub(super) fn opts(&self) -> ShapeOpts {
        ShapeOpts {
            style: self.style,
            compactness: self.compactness,
            no_cut: self.no_cut,
        }
    }

    /// The number of pixels the request asks for.
    pub(super) fn pixels(&self) -> usize {
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
            f if structured(f) => self.structured_dims().map_or(0, |d| d.count),
            _ => self.n,
        }
    }

    /// The outlines layout of this seed and k.
    fn layout(&self) -> Layout {
        outlines_layout(self.k, &mut rng_for(self.seed, TAG_OUTLINES))
    }

    /// The shape dimensions a structured family derives from n, with the exact pixel count
    /// (each module's formula); `None` outside the structured families or when a refusal of
    /// [`Spec::check_structured`] applies.
    fn structured_dims(&self) -> Option<Dims> {
        let (n, k, w) = (self.n, self.k, self.width);
        if self.check_structured().is_err() {
            return None;
        }
        let d = match self.family {
            Family::HoleLattice => {
                let m = lattice_half_side(self.pattern, n);
                Dims {
                    a: m,
                    b: 0,
                    count: lattice_pixels_count(self.pattern, m),
                }
            }
            Family::Comb | Family::DoubleComb => {
                let sides = if self.family == Family::Comb { 1 } else { 2 };
                let len = comb_length(n, k, sides);
                Dims {
                    a: len,
                    b: sides,
                    count: comb_count(k, len, sides),
                }
            }
            Family::Spiral => {
                let s = spiral_side(n, w);
                Dims {
                    a: s,
                    b: 0,
                    count: spiral_count(s, w),
                }
            }
            Family::Windows => {
                let m = windows_panes(n, k, w);
                Dims {
                    a: m,
                    b: 0,
                    count: windows_count(m, k, w),
                }
            }
            Family::Outlines => {
                let layout = self.layout();
                let s = outlines_spacing(&layout, n);
                Dims {
                    a: s,
                    b: 0,
                    count: 2 * s * slot_perimeter(&layout) - crossings(&layout),
                }
            }
            Family::Ring => {
                let (a, b) = ring_sides(n, w);
                Dims {
                    a,
                    b,
                    count: ring_count(a, b, w),
                }
            }
            Family::CorridorStar => {
                let l = star_arm(n, k, w);
                Dims {
                    a: l,
                    b: 0,
                    count: star_count(k, l, w),
                }
            }
            _ => return None,
        };
        Some(d)
    }

    /// The structured families' refusals of k and width, before sizing.
    fn check_structured(&self) -> Result<()> {
        let (name, n, k, w) = (self.family.name(), self.n, self.k, self.width);
        let narrow = matches!(
            self.family,
            Family::Spiral | Family::Windows | Family::Ring | Family::CorridorStar
        );
        if narrow && !(1..=2).contains(&w) {
            return Err(Error::invalid(format!(
                "{name} needs width 1 or 2, got {w}"
            )));
        }
        if n == 0 {
            return Err(Error::invalid(format!("{name} needs n ≥ 1 pixels")));
        }
        let huge = |what: &str| {
            Err(Error::invalid(format!(
                "{name}: {what} is too large for n = {n} (more than the generator's limit of {MAX_PIXELS} pixels)"
            )))
        };
        match self.family {
            Family::Comb | Family::DoubleComb => {
                let sides = if self.family == Family::Comb { 1 } else { 2 };
                if n < comb_count(k, 1, sides) {
                    return Err(Error::invalid(format!(
                        "{name} with k = {k} teeth needs n ≥ {} (teeth of length 1), got {n}",
                        comb_count(k, 1, sides)
                    )));
                }
            }
            Family::Windows if k > MAX_PIXELS.isqrt() => return huge("the pane side k"),
            Family::Outlines if 8 * k > n => {
                return Err(Error::invalid(format!(
                    "outlines with k = {k} rectangles needs n ≥ {} (8 pixels per outline), got {n}",
                    8 * k
                )));
            }
            Family::CorridorStar if !(1..=4).contains(&k) => {
                return Err(Error::invalid(format!(
                    "corridor-star takes k = 1 to 4 corridors (horizontal, vertical, two diagonals), got {k}"
                )));
            }
            _ => {}
        }
        if n > MAX_PIXELS {
            return huge("n");
        }
        Ok(())
    }

    pub(super) fn check_feasible(&self) -> Result<()> {
        let name = self.family.name();
        if structured(self.family) {
            self.check_structured()?;
        }
        if self.family == Family::Eroded && self.n > MAX_ERODED {
            return Err(Error::invalid(format!(
                "eroded: n = {} is more than this family's limit of {MAX_ERODED} pixels (it erodes a square of \
                 about 3n cells)",
                self.n
            )));
        }
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
            Family::ThinEulerian if n < 8 || n + slack(n) > MAX_PIXELS => {
                Err(Error::invalid(format!(
                    "thin-eulerian needs 8 ≤ n ≤ {} (the smallest thin Eulerian region is the 3 x 3 ring; N may exceed n \
                 by n/50 + 32), got {n}",
                    MAX_PIXELS - slack(MAX_PIXELS) - 1
                )))
            }
            Family::LawnScattered if self.parts == 0 || self.parts > n => {
                Err(Error::invalid(format!(
                    "lawn-scattered needs 1 ≤ parts ≤ n (got parts {} and n {n})",
                    self.parts
                )))
            }
            _ => Ok(()),
        }
    }

    pub(super) fn promise(&self) -> Promise {
        let (components, holes) = match self.family {
            Family::Donut => (1, 1),
            Family::Thin43 => (1, thin43_holes(self.s)),
            Family::RandomHoled | Family::Thin | Family::ThinArms | Family::Pinholes => {
                (1, self.holes)
            }
            // Any number of holes (`any_holes`).
            Family::Eroded => (1, 0),
            Family::LawnScattered => (self.parts, 0),
            Family::HoleLattice => (1, self.structured_holes()),
            Family::Windows => (1, self.structured_dims().map_or(0, |d| d.a * d.a)),
            Family::Ring => (1, 1),
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
            n_slack: if self.family == Family::ThinEulerian {
                slack(self.n)
            } else {
                0
            },
            components,
            holes,
            cut,
            thin: matches!(
                self.family,
                Family::Thin
                    | Family::Thin43
                    | Family::ThinArms
                    | Family::Comb
                    | Family::DoubleComb
                    | Family::Outlines
                    | Family::ThinEulerian
            ) || (self.family == Family::HoleLattice && self.pattern == Pattern::Staggered)
                || (matches!(self.family, Family::Spiral | Family::Ring) && self.width == 1),
            separated: self.family == Family::LawnScattered,
            any_holes: matches!(
                self.family,
                Family::Boundary
                    | Family::Eroded
                    | Family::Outlines
                    | Family::CorridorStar
                    | Family::BoundaryRooms
                    | Family::ThinEulerian
            ),
            boundary_only: matches!(self.family, Family::Boundary | Family::BoundaryRooms),
            even_degrees: matches!(self.family, Family::Outlines | Family::ThinEulerian),
        }
    }

    /// The holes of `hole-lattice` (module `hole_lattice`): h = missing cells minus notches.
    fn structured_holes(&self) -> usize {
        let Some(d) = self.structured_dims() else {
            return 0;
        };
        let m = d.a;
        let s = 2 * m + 1;
        let missing = s * s - d.count;
        match self.pattern {
            // The staggered rows of the first kind lose x = 0 and x = 2m to the boundary.
            Pattern::Staggered => missing - 2 * m.div_ceil(2),
            _ => missing,
        }
    }

    /// Builds the region and checks its promise; returns it with its number of holes.
    pub(super) fn build(&self) -> Result<(Region, usize, Provenance)> {
        let o = self.opts();
        let (n, h) = (self.n, self.holes);
        let (pixels, provenance) = match self.family {
            Family::Rect => (rect_pixels(self.width, self.height), Provenance::Direct),
            Family::Donut => (donut_pixels(self.side, self.k), Provenance::Direct),
            Family::Band => (band_pixels(self.k), Provenance::Direct),
            Family::Thin43 => (thin43_pixels(self.s), Provenance::Direct),
            f @ (Family::HoleLattice
            | Family::Comb
            | Family::DoubleComb
            | Family::Spiral
            | Family::Windows
            | Family::Outlines
            | Family::Ring
            | Family::CorridorStar) => {
                let d = self
                    .structured_dims()
                    .ok_or_else(|| Error::invalid(format!("internal error: no {f} dimensions")))?;
                let (k, w) = (self.k, self.width);
                let pixels = match f {
                    Family::HoleLattice => hole_lattice_pixels(self.pattern, d.a),
                    Family::Comb | Family::DoubleComb => comb_pixels(k, d.a, d.b == 2),
                    Family::Spiral => spiral_pixels(d.a, w),
                    Family::Windows => windows_pixels(d.a, k, w),
                    Family::Outlines => outlines_pixels(&self.layout(), d.a),
                    Family::Ring => ring_pixels(d.a, d.b, w),
                    _ => star_pixels(k, d.a, w),
                };
                (pixels, Provenance::Direct)
            }
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
            Family::BoundaryRooms => {
                let compactness = o.compactness;
                return self.with_attempts(
                    |rng, _| boundary_rooms_canvas(n, compactness, rng).map(|c| c.pixels()),
                    |_| Some(two_rows_pixels(n)),
                );
            }
            Family::ThinEulerian => {
                let compactness = o.compactness;
                return self.with_attempts(
                    |rng, _| thin_eulerian_pixels(n, compactness, rng),
                    |_| Some(ring_outline_pixels(n)),
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
            Family::Eroded => {
                let style = self.style;
                return self.with_attempts(
                    |rng, _| Some(eroded_pixels(n, style, rng)),
                    |rng| rows_pixels(n, 0, false, rng),
                );
            }
        };
        self.checked(pixels, provenance)
    }

    pub(super) fn checked(
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
    pub(super) fn with_attempts(
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
