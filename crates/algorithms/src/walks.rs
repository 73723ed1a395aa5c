//! Building closed walks from straight runs, shared by the turn-cost algorithms (doubled
//! strips, stars, links joined by a matching).

use crate::region::Pixel;
use crate::tour::Walk;

/// The pixels from `a` to `b` inclusive along a row or column.
pub(crate) fn straight(a: Pixel, b: Pixel) -> impl Iterator<Item = Pixel> {
    // Along a row or a column, so one difference is 0 and the other fits an i32 (coordinates
    // lie within ±MAX_COORD).
    let (dx, dy) = (b.x.cmp(&a.x) as i32, b.y.cmp(&a.y) as i32);
    let steps = a.x.abs_diff(b.x).max(a.y.abs_diff(b.y)) as i32;
    (0..=steps).map(move |k| Pixel::new(a.x + k * dx, a.y + k * dy))
}

/// Appends `pixels` to `walk`, skipping a pixel equal to the walk's last one.
pub(crate) fn extend_walk(walk: &mut Walk, pixels: impl IntoIterator<Item = Pixel>) {
    for p in pixels {
        if walk.last() != Some(&p) {
            walk.push(p);
        }
    }
}

/// Closes a walk built by [`extend_walk`]: a final copy of the first pixel is dropped.
pub(crate) fn close_walk(mut walk: Walk) -> Walk {
    if walk.len() > 1 && walk.first() == walk.last() {
        walk.pop();
    }
    walk
}
