//! Rasterising a valid geometry: its pixel count from the rings' areas, checked against the
//! pixel limit before anything is filled, then the pixels row by row.

use super::doubled_area;
use super::lexer::Pos;
use super::parser::Ring;
use super::validate::Geometry;
use crate::error::Result;
use crate::region::{MAX_PIXELS, Pixel};
use std::collections::BTreeSet;

impl Geometry<'_, i64> {
    /// The number of pixels the geometry encloses: the area of the outer rings minus that of
    /// the holes. Rings no longer cross, holes lie inside their outer ring and polygons apart,
    /// and every corner is an integer point, so the area counts the enclosed pixels exactly.
    pub(super) fn pixel_count(&self) -> u128 {
        let area = |r: &Ring<i64>| {
            doubled_area(&r.corners.iter().map(|c| (c.x, c.y)).collect::<Vec<_>>()).unsigned_abs()
                / 2
        };
        let outer: u128 = self.rings.iter().filter(|r| !r.hole).map(area).sum();
        let holes: u128 = self.rings.iter().filter(|r| r.hole).map(area).sum();
        outer.saturating_sub(holes)
    }

    /// Refuses a geometry enclosing more than [`MAX_PIXELS`] pixels, before any is filled.
    pub(super) fn check_pixel_count(&self, keyword: Pos) -> Result<()> {
        let n = self.pixel_count();
        if n > MAX_PIXELS as u128 {
            return Err(self.error(
                keyword,
                format!(
                    "the geometry encloses {n} pixels; expected at most {MAX_PIXELS} (the pixel \
                     limit)"
                ),
            ));
        }
        Ok(())
    }

    /// The enclosed pixels, row by row: on row y the vertical edges crossing y + ½, sorted by
    /// x, bound the region in pairs (even-odd rule, which the nesting checks make exact).
    pub(super) fn fill(&self) -> Vec<Pixel> {
        let (_, vertical) = self.segments();
        const CLOSE: u8 = 0;
        const OPEN: u8 = 1;
        let mut events: Vec<(i64, u8, i64)> = Vec::with_capacity(2 * vertical.len());
        for v in &vertical {
            events.push((v.lo, OPEN, v.fixed));
            events.push((v.hi, CLOSE, v.fixed));
        }
        events.sort_unstable();
        let mut pixels = Vec::new();
        let mut open: BTreeSet<i64> = BTreeSet::new();
        let mut next = 0;
        let mut y = events.first().map_or(0, |e| e.0);
        while next < events.len() {
            while let Some(&(at, kind, x)) = events.get(next)
                && at <= y
            {
                if kind == OPEN {
                    open.insert(x);
                } else {
                    open.remove(&x);
                }
                next += 1;
            }
            if open.is_empty() {
                if let Some(&(at, _, _)) = events.get(next) {
                    y = at;
                }
                continue;
            }
            let mut xs = open.iter();
            while let (Some(&from), Some(&to)) = (xs.next(), xs.next()) {
                // Coordinates lie in MIN_COORD..=MAX_COORD, so every pixel fits in i32.
                pixels.extend((from..to).map(|x| Pixel::new(x as i32, y as i32)));
            }
            y += 1;
        }
        pixels
    }
}
