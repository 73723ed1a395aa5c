//! Writing a region as WKT: one polygon per 4-connected component, its holes as inner rings.

use super::doubled_area;
use crate::region::{Dir, Pixel, Region};
use crate::topology::components;
use std::fmt::Write as _;

/// Writes a region as WKT, the boundary of its pixel set.
///
/// Each 4-connected component becomes one polygon: its outer ring counter-clockwise, then its
/// holes clockwise, each ring starting at its lowest, then leftmost, corner, with collinear
/// vertices dropped. Polygons come in the order of their first pixel (bottom row first, then
/// left to right) and holes in the order of their first corner, so equal regions give equal
/// strings. Where region pixels touch only diagonally, the boundary passes the shared corner
/// twice; there two rings touch without crossing (two polygons when the pixels lie in different
/// components, else an outer ring and a hole, or two holes), and no ring passes a point twice,
/// as OGC requires.
///
/// # Returns
///
/// `POLYGON (...)` when the region is one 4-connected component (with or without holes),
/// `MULTIPOLYGON (...)` when it has several, on one line without a trailing newline, and
/// `POLYGON EMPTY` for an empty region (which [`parse_wkt`] refuses, as it refuses every empty
/// region).
///
/// # Complexity
///
/// O(N + P) time and O(N) extra space for N pixels and P unit boundary edges.
///
/// # Examples
///
/// ```
/// use mowmill::wkt::to_wkt;
/// use mowmill::Region;
///
/// // Two pixels touching at a corner are two polygons meeting at the point (1, 1).
/// let r = Region::from_ascii(".#\n#.\n");
/// assert_eq!(
///     to_wkt(&r),
///     "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))"
/// );
/// ```
pub fn to_wkt(region: &Region) -> String {
    if region.is_empty() {
        return "POLYGON EMPTY".to_string();
    }
    let labels = components(region);
    let (component, count) = (&labels.label, labels.count);
    let mut outer: Vec<Vec<(i64, i64)>> = vec![Vec::new(); count];
    let mut holes: Vec<Vec<Vec<(i64, i64)>>> = vec![Vec::new(); count];
    let mut visited = vec![false; 4 * region.len()];
    for i in 0..region.len() {
        for side in Dir::ALL {
            if region.neighbor(i, side).is_none() && !visited[4 * i + side.index()] {
                let ring = trace_ring(region, component, &mut visited, i, side);
                // Traced with the region on the left: outer rings turn counter-clockwise.
                if doubled_area(&ring) > 0 {
                    outer[component[i] as usize] = ring;
                } else {
                    holes[component[i] as usize].push(ring);
                }
            }
        }
    }
    let mut out = String::new();
    if count == 1 {
        out.push_str("POLYGON ");
        write_polygon(&mut out, &outer[0], &mut holes[0]);
    } else {
        out.push_str("MULTIPOLYGON (");
        for c in 0..count {
            if c > 0 {
                out.push_str(", ");
            }
            write_polygon(&mut out, &outer[c], &mut holes[c]);
        }
        out.push(')');
    }
    out
}

/// Walks the boundary ring through the unit edge on side `side` of pixel `start`, keeping the
/// region on the left, and returns its corners from the lowest, then leftmost, one.
///
/// A unit edge is named by the pixel on its left and the side of that pixel it lies on. At a
/// corner where the region's pixels touch only diagonally (a saddle), the walk turns around the
/// empty pixel when the two region pixels are in the same component, and around its own pixel
/// otherwise: components stay apart, and no ring passes a point twice.
fn trace_ring(
    region: &Region,
    component: &[u32],
    visited: &mut [bool],
    start: usize,
    start_side: Dir,
) -> Vec<(i64, i64)> {
    let mut corners = Vec::new();
    let (mut i, mut side) = (start, start_side);
    // Every step visits a new unit edge, so the walk is back at the start after at most 4N.
    for _ in 0..visited.len() {
        visited[4 * i + side.index()] = true;
        let heading = side.left();
        let pixel = region.pixel(i);
        let ahead_left = pixel.step(heading);
        let ahead_right = region.index_of(ahead_left.step(side));
        let (next, next_side) = match (region.index_of(ahead_left), ahead_right) {
            (Some(a), None) => (a, side),
            (None, None) => (i, heading),
            (None, Some(b)) if component[b] != component[i] => (i, heading),
            (_, Some(b)) => (b, heading.opposite()),
        };
        if next_side != side {
            corners.push(edge_end(pixel, side));
        }
        (i, side) = (next, next_side);
        if (i, side) == (start, start_side) {
            break;
        }
    }
    let first = (0..corners.len())
        .min_by_key(|&k| (corners[k].1, corners[k].0))
        .unwrap_or(0);
    corners.rotate_left(first);
    corners
}

/// The corner where the unit edge on side `side` of `pixel` ends, walking with the pixel on
/// the left.
fn edge_end(pixel: Pixel, side: Dir) -> (i64, i64) {
    let (sx, sy) = side.delta();
    let (hx, hy) = side.left().delta();
    // Exactly one of sx, hx is non-zero, so (sx + hx + 1) / 2 is 0 or 1; likewise for y.
    (
        i64::from(pixel.x) + i64::from((sx + hx + 1) / 2),
        i64::from(pixel.y) + i64::from((sy + hy + 1) / 2),
    )
}

fn write_polygon(out: &mut String, outer: &[(i64, i64)], holes: &mut [Vec<(i64, i64)>]) {
    holes.sort_unstable_by_key(|h| h.first().map(|&(x, y)| (y, x)));
    out.push('(');
    write_ring(out, outer);
    for hole in holes.iter() {
        out.push_str(", ");
        write_ring(out, hole);
    }
    out.push(')');
}

pub(super) fn write_ring(out: &mut String, corners: &[(i64, i64)]) {
    out.push('(');
    for (k, (x, y)) in corners.iter().chain(corners.first()).enumerate() {
        if k > 0 {
            out.push_str(", ");
        }
        let _ = write!(out, "{x} {y}");
    }
    out.push(')');
}
