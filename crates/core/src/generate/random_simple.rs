//! `random-simple`: a shape of the style, normalised to exactly N pixels without holes
//! (and, with `no_cut`, without cut vertices). The other random families start from it.

use super::canvas::Canvas;
use super::growth::{Frontier, adjust, bucket_weights};
use super::rng::Rng;
use super::styles::{ShapeOpts, Style, draw_blob, draw_corridors, draw_rectangles};

/// A connected hole-free shape of exactly `target` pixels (no cut vertex with `no_cut`).
pub(super) fn simple_canvas(
    target: usize,
    o: &ShapeOpts,
    rng: &mut Rng,
) -> Option<(Canvas, Frontier)> {
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
        // The erosion styles are refused for shape families before anything is drawn.
        Style::Blob | Style::Mixed | Style::Dense | Style::Sparse => {
            draw_blob(&mut c, &mut f, target, o.compactness, rng)
        }
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
