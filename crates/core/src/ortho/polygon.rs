//! Orthogonal polygons (with holes, possibly several) with exact coordinates, read from WKT.

use super::rational::Rational;
use crate::error::{Error, Result};
use crate::region::Region;
use crate::wkt::{Coordinate, parse_valid_rings, to_wkt};
use num_integer::Integer;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::path::Path;

/// The most vertices a polygon file may have (all rings together, as written). The checker and
/// the erosion take time quadratic in the number of distinct coordinates in the worst case
/// (a staircase), so the limit keeps them to seconds.
pub const MAX_VERTICES: usize = 10_000;

/// A point with exact coordinates; in JSON the pair `["x", "y"]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(from = "(Rational, Rational)", into = "(Rational, Rational)")]
pub struct Point {
    pub x: Rational,
    pub y: Rational,
}

impl Point {
    pub fn new(x: Rational, y: Rational) -> Point {
        Point { x, y }
    }

    /// The centre of pixel (x, y), the unit square [x, x+1] × [y, y+1].
    pub fn pixel_centre(x: i32, y: i32) -> Point {
        let half = |v: i32| {
            Rational::new(2 * i128::from(v) + 1, 2).expect("an i32 plus a half is a rational")
        };
        Point::new(half(x), half(y))
    }
}

impl From<(Rational, Rational)> for Point {
    fn from((x, y): (Rational, Rational)) -> Point {
        Point { x, y }
    }
}

impl From<Point> for (Rational, Rational) {
    fn from(p: Point) -> (Rational, Rational) {
        (p.x, p.y)
    }
}

impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

impl Coordinate for Rational {
    const MAX_VERTICES: usize = MAX_VERTICES;
    const REFUSE_REPEATS: bool = true;

    fn read(text: &str, what: &str) -> std::result::Result<Rational, String> {
        Rational::parse_coordinate(text).map_err(|e| format!("{e} (the {what})"))
    }
}

/// One ring of a polygon: its corners in order (collinear vertices merged, the first not
/// repeated), every edge horizontal or vertical.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ring {
    pub corners: Vec<Point>,
    /// Which polygon of a `MULTIPOLYGON` it belongs to (0 for a `POLYGON`).
    pub polygon: usize,
    /// An inner ring (a hole) rather than the outer boundary of its polygon.
    pub hole: bool,
}

/// A vertical edge of a ring: at `x`, from `y0` to `y1` (`y0 < y1`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct VerticalEdge {
    pub(crate) x: Rational,
    pub(crate) y0: Rational,
    pub(crate) y1: Rational,
}

/// A closed orthogonal polygon with holes, or several with disjoint interiors, with exact
/// coordinates: the closure of the points inside an outer ring and inside none of its holes.
///
/// Valid by construction: the rings are simple, meet at most at single points, holes lie
/// inside their outer ring and apart, polygons apart (the OGC rules that
/// [`parse_wkt`](crate::wkt::parse_wkt) checks), and every coordinate is within the input limits
/// of [`Rational::parse_coordinate`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Polygon {
    rings: Vec<Ring>,
}

impl Polygon {
    /// Parses a WKT `POLYGON` or `MULTIPOLYGON` with exact coordinates.
    ///
    /// Numbers are decimals (`3`, `-0.35`, `2.5e-1`) or fractions `p/q` (`7/3`), read exactly;
    /// each coordinate has magnitude at most 2^31 and, in lowest terms, a denominator at most
    /// 10^12; at most [`MAX_VERTICES`] vertices. Refused as by
    /// [`parse_wkt`](crate::wkt::parse_wkt) (edges not axis-parallel, crossing or overlapping
    /// edges, rings touching themselves, holes outside their ring, overlapping polygons, empty
    /// geometries), and also a vertex equal to the one before it (a zero-length edge). Errors
    /// name `file`, the line and column, and what was expected.
    ///
    /// # Examples
    ///
    /// ```
    /// use mowmill_core::ortho::Polygon;
    ///
    /// let p = Polygon::parse("POLYGON ((0 0, 2.5 0, 2.5 1.5, 0 1.5, 0 0))", "p.wkt")?;
    /// assert_eq!(p.to_wkt(), "POLYGON ((0 0, 2.5 0, 2.5 1.5, 0 1.5, 0 0))");
    /// let e = Polygon::parse("POLYGON ((0 0, 1 0, 1 0, 0 1, 0 0))", "p.wkt").unwrap_err();
    /// assert!(e.to_string().starts_with("p.wkt:1:21: zero-length edge"));
    /// # Ok::<(), mowmill_core::Error>(())
    /// ```
    pub fn parse(text: &str, file: &str) -> Result<Polygon> {
        let rings = parse_valid_rings::<Rational>(text, file)?
            .into_iter()
            .map(|r| Ring {
                corners: r
                    .corners
                    .into_iter()
                    .map(|(x, y)| Point::new(x, y))
                    .collect(),
                polygon: r.polygon,
                hole: r.hole,
            })
            .collect();
        Ok(Polygon { rings })
    }

    /// Reads a WKT file; see [`Polygon::parse`].
    pub fn read(path: &Path) -> Result<Polygon> {
        let text = crate::input::read_text(path, "a polygon file")?;
        Polygon::parse(&text, &path.display().to_string())
    }

    /// The polygon of a pixel region: pixel (x, y) is the unit square [x, x+1] × [y, y+1].
    /// Fails only for an empty region or one with more than [`MAX_VERTICES`] boundary corners.
    pub fn from_region(region: &Region) -> Result<Polygon> {
        Polygon::parse(&to_wkt(region), "region")
    }

    pub fn rings(&self) -> &[Ring] {
        &self.rings
    }

    /// Whether a coordinate is not an integer (a polygon that pixels cannot describe).
    pub fn is_non_integral(&self) -> bool {
        self.rings
            .iter()
            .flat_map(|r| &r.corners)
            .any(|c| !c.x.is_integer() || !c.y.is_integer())
    }

    /// Whether `path` is a `.wkt` polygon with a coordinate that is not an integer (read
    /// exactly): a file of this model rather than a pixel region.
    pub fn is_ortho_file(path: &Path) -> bool {
        path.extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("wkt"))
            && Polygon::read(path).is_ok_and(|p| p.is_non_integral())
    }

    /// Whether it has a hole (an inner ring).
    pub fn has_holes(&self) -> bool {
        self.rings.iter().any(|r| r.hole)
    }

    /// The exact area: outer rings' shoelace areas minus the holes'.
    ///
    /// # Errors
    /// [`Error::Invalid`] when the exact value overflows the rationals.
    pub fn area(&self) -> Result<Rational> {
        let overflow = || Error::invalid("the polygon's exact area overflows i128 rationals");
        let mut area = Rational::ZERO;
        for ring in &self.rings {
            let m = ring.corners.len();
            let mut twice = Rational::ZERO;
            for i in 0..m {
                let (a, b) = (ring.corners[i], ring.corners[(i + 1) % m]);
                let cross =
                    a.x.checked_mul(b.y)
                        .zip(b.x.checked_mul(a.y))
                        .and_then(|(p, q)| p.checked_sub(q))
                        .ok_or_else(overflow)?;
                twice = twice.checked_add(cross).ok_or_else(overflow)?;
            }
            let part = twice
                .abs()
                .checked_mul(Rational::HALF)
                .ok_or_else(overflow)?;
            area = if ring.hole {
                area.checked_sub(part)
            } else {
                area.checked_add(part)
            }
            .ok_or_else(overflow)?;
        }
        Ok(area)
    }

    /// The least common multiple of the denominators of all coordinates (1 for an integral
    /// polygon); `None` when it overflows.
    pub fn denominator(&self) -> Option<i128> {
        let mut l: i128 = 1;
        for p in self.rings.iter().flat_map(|r| &r.corners) {
            for d in [p.x.denom(), p.y.denom()] {
                l = lcm(l, d)?;
            }
        }
        Some(l)
    }

    /// The polygon as WKT (coordinates as [`Rational`] displays them, which
    /// [`Polygon::parse`] reads back exactly).
    pub fn to_wkt(&self) -> String {
        let ring = |r: &Ring| {
            let points: Vec<String> = r
                .corners
                .iter()
                .chain(r.corners.first())
                .map(|p| format!("{} {}", p.x, p.y))
                .collect();
            format!("({})", points.join(", "))
        };
        let polygons = self
            .rings
            .iter()
            .map(|r| r.polygon)
            .max()
            .map_or(0, |p| p + 1);
        let polygon = |k: usize| {
            let rings: Vec<String> = self
                .rings
                .iter()
                .filter(|r| r.polygon == k)
                .map(ring)
                .collect();
            format!("({})", rings.join(", "))
        };
        if polygons == 1 {
            format!("POLYGON {}", polygon(0))
        } else {
            let all: Vec<String> = (0..polygons).map(polygon).collect();
            format!("MULTIPOLYGON ({})", all.join(", "))
        }
    }

    /// Every vertical edge of every ring.
    pub(crate) fn vertical_edges(&self) -> Vec<VerticalEdge> {
        let mut edges = Vec::new();
        for r in &self.rings {
            let n = r.corners.len();
            for k in 0..n {
                let (a, b) = (r.corners[k], r.corners[(k + 1) % n]);
                if a.x == b.x {
                    edges.push(VerticalEdge {
                        x: a.x,
                        y0: a.y.min(b.y),
                        y1: a.y.max(b.y),
                    });
                }
            }
        }
        edges
    }

    /// The distinct x and the distinct y coordinates of the corners, each sorted.
    pub(crate) fn coordinates(&self) -> (Vec<Rational>, Vec<Rational>) {
        let corners = self.rings.iter().flat_map(|r| r.corners.iter());
        let mut xs: Vec<Rational> = corners.clone().map(|p| p.x).collect();
        let mut ys: Vec<Rational> = corners.map(|p| p.y).collect();
        for v in [&mut xs, &mut ys] {
            v.sort_unstable();
            v.dedup();
        }
        (xs, ys)
    }
}

/// The least common multiple of two positive integers; `None` on overflow.
pub fn lcm(a: i128, b: i128) -> Option<i128> {
    (a / a.gcd(&b)).checked_mul(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refusal(text: &str) -> String {
        Polygon::parse(text, "t.wkt").unwrap_err().to_string()
    }

    #[test]
    fn reads_exact_coordinates_and_writes_them_back() {
        let text = "POLYGON ((0 0, 7/3 0, 7/3 1.35, 0 1.35, 0 0), (0.5 0.25, 0.5 1, 1 1, 1 0.25, \
                    0.5 0.25))";
        let p = Polygon::parse(text, "t.wkt").unwrap();
        assert_eq!(p.rings().len(), 2);
        assert_eq!(p.rings()[0].corners[1].x, Rational::new(7, 3).unwrap());
        assert_eq!(p.rings()[0].corners[2].y, Rational::new(27, 20).unwrap());
        assert!(p.rings()[1].hole);
        assert_eq!(p.to_wkt(), text.replace("                    ", ""));
        assert_eq!(Polygon::parse(&p.to_wkt(), "again").unwrap(), p);
        let multi = "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 1, 2.5 1, 2.5 2, 1 2, 1 1)))";
        assert_eq!(Polygon::parse(multi, "m").unwrap().to_wkt(), multi);
    }

    #[test]
    fn refusals_name_place_and_expectation() {
        let cases = [
            (
                "POLYGON ((0 0, 1.5 0.5, 0 1, 0 0))",
                "t.wkt:1:16: edge from (0,0) to (1.5,0.5) is not axis-parallel",
            ),
            (
                "POLYGON ((0 0, 2 0, 2 0, 2 1, 0 1, 0 0))",
                "t.wkt:1:21: zero-length edge: vertex (2,0) repeats the vertex before it",
            ),
            (
                "POLYGON ((0 0, 2 0, 2 2, 1.5 2, 1.5 -1, 0.5 -1, 0.5 2, 0 2, 0 0))",
                "crosses",
            ),
            (
                "POLYGON ((0 0, 1/0 0, 1 1, 0 1, 0 0))",
                "t.wkt:1:16: malformed number 1/0",
            ),
            (
                "POLYGON ((0 0, 0.0000000000001 0, 1 1, 0 1, 0 0))",
                "t.wkt:1:16: coordinate 0.0000000000001 is out of range",
            ),
            (
                "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0.5))",
                "t.wkt:1:31: ring is not closed",
            ),
            (
                "POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (4 4, 5 4, 5 5, 4 5, 4 4))",
                "hole is not inside its outer ring",
            ),
        ];
        for (text, expected) in cases {
            let e = refusal(text);
            assert!(e.contains(expected), "{text}: {e}");
        }
        let many: Vec<String> = (0..=MAX_VERTICES / 2)
            .flat_map(|k| [format!("{k} 0"), format!("{k} 1")])
            .collect();
        let e = refusal(&format!("POLYGON (({}))", many.join(", ")));
        assert!(e.contains("more than 10000 vertices"), "{e}");
    }

    #[test]
    fn regions_become_their_pixel_squares() {
        let r = Region::from_ascii("##\n#.\n");
        let p = Polygon::from_region(&r).unwrap();
        assert_eq!(p.to_wkt(), "POLYGON ((0 0, 1 0, 1 1, 2 1, 2 2, 0 2, 0 0))");
        assert_eq!(Point::pixel_centre(-1, 2).to_string(), "(-0.5, 2.5)");
    }
}
