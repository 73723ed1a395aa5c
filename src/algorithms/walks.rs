//! Building closed walks from straight runs, shared by the turn-cost algorithms (doubled
//! strips, stars, links joined by a matching).

use crate::region::Pixel;
use crate::tour::Walk;

/// The pixels from `a` to `b` inclusive along a row or column.
pub(crate) fn straight(a: Pixel, b: Pixel) -> impl Iterator<Item = Pixel> {
    let (dx, dy) = ((b.x - a.x).signum(), (b.y - a.y).signum());
    let steps = (b.x - a.x).abs() + (b.y - a.y).abs();
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
