//! `pinholes`: one-pixel holes, often in columns or rows, in a hole-free shape.

use super::canvas::{ADJ_MARGIN, Canvas};
use super::random_holed::pop_site;
use super::random_simple::simple_canvas;
use super::rng::{Rng, between, chance, shuffle, unit};
use super::styles::ShapeOpts;

/// A shape of exactly n pixels with exactly `holes` one-pixel holes: a hole-free shape of
/// n + holes pixels of the given style, then pixels whose 3 × 3 block is full are removed
/// (each a new hole of one cell, so holes are at least one wall pixel apart); after a hole,
/// with a probability drawn per instance, the next one continues a column (or, less often, a
/// row) 2 to 4 cells further on, so that hole contours line up with one another and with the
/// strips between them.
pub(super) fn pinholes_canvas(
    n: usize,
    holes: usize,
    o: &ShapeOpts,
    rng: &mut Rng,
) -> Option<Canvas> {
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
