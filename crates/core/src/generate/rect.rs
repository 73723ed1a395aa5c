//! The deterministic `rect` and `donut` (a rectangle minus a centred rectangle).

use crate::region::Pixel;

pub(super) fn rect_pixels(w: usize, h: usize) -> Vec<Pixel> {
    (0..h)
        .flat_map(|y| (0..w).map(move |x| Pixel::new(x as i32, y as i32)))
        .collect()
}

pub(super) fn donut_pixels(side: usize, k: usize) -> Vec<Pixel> {
    rect_pixels(side, side)
        .into_iter()
        .filter(|p| {
            let inner = |v: i32| v as usize >= k && (v as usize) < side - k;
            !(inner(p.x) && inner(p.y))
        })
        .collect()
}
