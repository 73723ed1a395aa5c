//! Writing a region as WKT: one polygon per 4-connected component, its holes as inner rings.

use super::doubled_area;
use crate::region::Region;
use crate::topology::{Saddle, boundary_rings, components};
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
/// use mowmill_core::wkt::to_wkt;
/// use mowmill_core::Region;
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
    // Saddles joined within a component and apart across components: every ring is simple and
    // rings only touch at points, so the written geometry is OGC-valid and parse_wkt takes it.
    for ring in boundary_rings(region, Saddle::JoinSameLabel(component)) {
        let c = component[ring.pixel] as usize;
        // Traced with the region on the left: outer rings turn counter-clockwise.
        if doubled_area(&ring.corners) > 0 {
            outer[c] = ring.corners;
        } else {
            holes[c].push(ring.corners);
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
