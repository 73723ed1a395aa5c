//! Well-known text (WKT) import and export of regions.
//!
//! [`parse_wkt`] reads one `POLYGON` or `MULTIPOLYGON` (keywords in any case, free whitespace)
//! whose vertices are integers and whose edges are horizontal or vertical. Numbers may be
//! written `3`, `-2`, `+3`, `3.0`, `1e1` or `6/2` as long as their value is an integer (the
//! polygons of `mowmill::ortho` take any such number, integral or not, by the same syntax). The region is
//! the set of pixels whose centre lies inside the geometry: inside the outer ring of a polygon
//! and inside none of its holes. Repeated and collinear consecutive vertices are merged, and ring
//! orientation is ignored.
//!
//! Refused, with the file, line and column of the offending token and what was expected:
//!
//! - a geometry other than `POLYGON` or `MULTIPOLYGON`, malformed syntax, 3-D or measured
//!   vertices, text after the geometry, and an `EMPTY` geometry (an empty region);
//! - a coordinate that is not an integer or lies outside `-(2^30 - 1) ..= 2^30` (the pixels'
//!   coordinate limit [`MAX_COORD`](crate::region::MAX_COORD));
//! - an edge that is neither horizontal nor vertical;
//! - a ring that is not closed (last vertex ≠ first), has fewer than 4 corners (no area) or turns
//!   back on itself;
//! - two edges (of one ring or of two rings) that cross or overlap along a segment, and a ring
//!   that touches itself;
//! - a hole that is not inside its outer ring or lies inside another hole, and polygons of a
//!   `MULTIPOLYGON` whose interiors overlap;
//! - a geometry enclosing more than [`MAX_PIXELS`](crate::region::MAX_PIXELS) pixels, found
//!   from the rings' areas before a single pixel is filled.
//!
//! These are the OGC Simple Features validity rules restricted to rectilinear integer polygons:
//! an invalid geometry has no agreed meaning, so we refuse it rather than let a tie-breaking rule
//! of ours decide which pixels a benchmark instance contains. As OGC allows, distinct rings may
//! touch at single points (a hole touching its outer ring, two polygons meeting at a corner).
//! One OGC rule is not checked, that a polygon's interior be connected (holes touching in a
//! closed chain can cut it): the pixel set is well defined all the same.
//!
//! [`parse_poly`] reads the same polygons written as CGAL-style `.poly` rings (one ring per line)
//! and checks them by the same rules.
//!
//! [`to_wkt`] writes a region back: one polygon per 4-connected component, its holes as inner
//! rings, so that `parse_wkt(&to_wkt(&r), _) == r` for every non-empty region `r`.

use crate::error::Result;
use crate::region::Region;
use parser::Parser;
use validate::Geometry;

#[doc(hidden)]
pub mod lexer;
mod parser;
mod poly;
mod raster;
mod validate;
mod writer;

#[cfg(test)]
mod tests;

pub use parser::Coordinate;
pub use poly::parse_poly;
pub use writer::to_wkt;

/// Smallest and largest accepted vertex coordinate: every pixel between them has coordinates
/// within ±[`region::MAX_COORD`](crate::region::MAX_COORD) (a pixel's far corner is one more).
const MIN_COORD: i64 = -(crate::region::MAX_COORD as i64);
const MAX_COORD: i64 = crate::region::MAX_COORD as i64 + 1;

/// Parses a WKT `POLYGON` or `MULTIPOLYGON` into the region of the pixels it encloses.
///
/// Pixel (x, y) is the unit square [x, x+1] × [y, y+1]; it belongs to the region when its
/// centre (x + ½, y + ½) lies inside the outer ring of some polygon and inside none of that
/// polygon's holes. The geometry must be valid in the OGC sense; the module documentation lists
/// what is refused.
///
/// # Arguments
///
/// - `text`: the WKT, a single geometry optionally surrounded by whitespace.
/// - `file`: the name used in error messages.
///
/// # Returns
///
/// The non-empty region, or [`Error::Parse`] naming `file`, the line and column (both from 1)
/// of the offending token or vertex, and what was expected.
///
/// # Complexity
///
/// O(T + A + V log V) time and O(A + V) extra space for T characters of text, V vertices and
/// A pixels: validity is checked by sorting and by sweeps over the edges (never by comparing
/// all pairs), and pixels are filled row by row between the crossings of vertical edges.
///
/// # Examples
///
/// ```
/// use mowmill_core::wkt::parse_wkt;
/// use mowmill_core::Region;
///
/// let r = parse_wkt("POLYGON ((0 0, 3 0, 3 2, 0 2, 0 0))", "ex.wkt").unwrap();
/// assert_eq!(r, Region::rectangle(3, 2));
///
/// let e = parse_wkt("POLYGON ((0 0, 2 1, 0 1, 0 0))", "ex.wkt").unwrap_err();
/// assert_eq!(e.to_string(), "ex.wkt:1:16: edge from (0,0) to (2,1) is not axis-parallel; \
///     expected every edge to be horizontal or vertical");
/// ```
pub fn parse_wkt(text: &str, file: &str) -> Result<Region> {
    let (rings, keyword) = Parser::<i64>::new(text, file).geometry()?;
    rasterise(Geometry { rings, file }, keyword)
}

/// A ring of a valid geometry: its corners (repeated and collinear vertices merged, the first
/// not repeated), the index of its polygon in the geometry, and whether it is a hole.
pub struct ValidRing<C> {
    pub corners: Vec<(C, C)>,
    pub polygon: usize,
    pub hole: bool,
}

/// Parses a WKT `POLYGON` or `MULTIPOLYGON` with coordinates of type `C` and checks it by the
/// rules of [`parse_wkt`] (all but the pixel limit): the one reader of exact polygons
/// (`mowmill_core::ortho`) and of pixel regions.
pub fn parse_valid_rings<C: Coordinate>(text: &str, file: &str) -> Result<Vec<ValidRing<C>>> {
    let (rings, _) = Parser::<C>::new(text, file).geometry()?;
    let geometry = Geometry { rings, file };
    geometry.check_rings_meet_at_points()?;
    let parents = geometry.enclosing_rings()?;
    geometry.check_nesting(&parents)?;
    Ok(geometry
        .rings
        .into_iter()
        .map(|r| ValidRing {
            corners: r.corners.iter().map(|c| (c.x, c.y)).collect(),
            polygon: r.polygon,
            hole: r.hole,
        })
        .collect())
}

/// Checks a geometry whose rings are each valid on their own (no crossings, rings meeting at
/// points only, holes inside their outer ring, polygons apart, at most
/// [`MAX_PIXELS`](crate::region::MAX_PIXELS) pixels, the last error placed at `keyword`) and
/// fills its pixels: the one path of WKT and `.poly` input.
fn rasterise(geometry: Geometry<'_, i64>, keyword: lexer::Pos) -> Result<Region> {
    geometry.check_rings_meet_at_points()?;
    let parents = geometry.enclosing_rings()?;
    geometry.check_nesting(&parents)?;
    geometry.check_pixel_count(keyword)?;
    Region::from_pixels(geometry.fill())
}

/// Twice the signed area of a ring (positive when counter-clockwise).
fn doubled_area(ring: &[(i64, i64)]) -> i128 {
    let n = ring.len();
    (0..n)
        .map(|k| {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            i128::from(a.0) * i128::from(b.1) - i128::from(b.0) * i128::from(a.1)
        })
        .sum()
}
