//! Reading CGAL-style `.poly` polygons, as the lawn-mowing studies write them: one ring per
//! line, the number of its points and then their coordinates, the first ring the outer boundary
//! and the others its holes.

use super::lexer::{NumberValue, Pos, number_value, shorten};
use super::parser::{Ring, Vertex, ring_corners};
use super::validate::Geometry;
use super::{MAX_COORD, MIN_COORD};
use crate::error::{Error, Result};
use crate::region::Region;

/// Parses a `.poly` polygon with holes into the region of the pixels it encloses.
///
/// Each line that is not blank holds one ring: `k x1 y1 x2 y2 ... xk yk`, the number of points
/// and then their coordinates, separated by whitespace. The ring closes by itself from the last
/// point back to the first (as CGAL writes polygons); a last point equal to the first is also
/// accepted. The first ring is the outer boundary, every later one a hole of it. `#` starts a
/// comment running to the end of the line. Coordinates are written as in WKT (`3`, `-2`, `3.0`,
/// `1e1`) and must be integers.
///
/// The rings then go through the checks of [`parse_wkt`](super::parse_wkt), so a `.poly` file
/// and the WKT `POLYGON` with the same rings give the same region or the same refusal:
/// axis-parallel edges, simple rings, holes inside the outer ring and apart, at most
/// [`MAX_PIXELS`](crate::region::MAX_PIXELS) pixels (found from the areas before any pixel is
/// filled). Pixel (x, y) belongs to the region when its centre (x + ½, y + ½) lies inside.
///
/// # Returns
///
/// The non-empty region, or [`Error::Parse`] naming `file`, the line and column (from 1) of
/// the offending number or vertex, and what was expected.
///
/// # Complexity
///
/// As [`parse_wkt`](super::parse_wkt): O(T + A + V log V) time for T characters, V vertices
/// and A pixels.
///
/// # Examples
///
/// ```
/// use mowmill_core::wkt::parse_poly;
///
/// // A 4 x 4 square with a 2 x 2 hole: 12 pixels.
/// let r = parse_poly("4 0 0 4 0 4 4 0 4\n4 1 1 1 3 3 3 3 1\n", "frame.poly").unwrap();
/// assert_eq!(r.len(), 12);
///
/// let e = parse_poly("4 0 0 4 0 4 4 0\n", "bad.poly").unwrap_err();
/// assert_eq!(e.to_string(), "bad.poly:1:15: the ring has 7 coordinates, an odd number; \
///     expected 4 pairs x y after the point count 4");
/// ```
pub fn parse_poly(text: &str, file: &str) -> Result<Region> {
    let error = |pos: Pos, message: String| Error::parse(file, pos.line, pos.column, message);
    let mut rings = Vec::new();
    let mut first_count: Option<Pos> = None;
    let mut last_line = 1;
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        last_line = line_no;
        let data = line.split('#').next().unwrap_or("");
        let mut tokens = words(data, line_no);
        let Some((count_text, count_pos)) = tokens.next() else {
            continue;
        };
        let count = match count_text.parse::<u64>() {
            Ok(0) => {
                return Err(error(
                    count_pos,
                    "ring with 0 points; expected the number of points of a ring (at least 4)"
                        .to_string(),
                ));
            }
            Ok(count) => count,
            Err(_) => {
                return Err(error(
                    count_pos,
                    format!(
                        "{} is not a point count; expected the number of points of a ring (a \
                         positive integer), then its coordinates",
                        describe(count_text)
                    ),
                ));
            }
        };
        let mut vertices: Vec<Vertex<i64>> = Vec::new();
        let mut numbers = 0u64;
        let mut pending: Option<(i64, Pos)> = None;
        let mut end = Pos {
            line: line_no,
            column: data.chars().count() + 1,
        };
        for (word, pos) in tokens {
            numbers += 1;
            if numbers > count.saturating_mul(2) {
                return Err(error(
                    pos,
                    format!(
                        "more than {count} points on the line; expected exactly {count} pairs x \
                         y after the point count (one ring per line)"
                    ),
                ));
            }
            let value = coordinate(word, pos, file)?;
            match pending.take() {
                None => pending = Some((value, pos)),
                Some((x, at)) => vertices.push(Vertex {
                    x,
                    y: value,
                    pos: at,
                }),
            }
            end = pos;
        }
        if numbers % 2 == 1 {
            return Err(error(
                end,
                format!(
                    "the ring has {numbers} coordinates, an odd number; expected {count} pairs x y \
                     after the point count {count}"
                ),
            ));
        }
        if numbers < count.saturating_mul(2) {
            return Err(error(
                end,
                format!(
                    "the ring has {} points; expected {count} pairs x y after the point count \
                     {count} (one ring per line)",
                    numbers / 2
                ),
            ));
        }
        // Close the ring as CGAL does, unless the file repeats the first point itself.
        if let (Some(first), Some(last)) = (vertices.first(), vertices.last())
            && (first.x, first.y) != (last.x, last.y)
        {
            let (x, y, pos) = (first.x, first.y, first.pos);
            vertices.push(Vertex { x, y, pos });
        }
        let corners = ring_corners(&vertices, file)?;
        first_count.get_or_insert(count_pos);
        rings.push(Ring {
            corners,
            polygon: 0,
            hole: !rings.is_empty(),
        });
    }
    let Some(keyword) = first_count else {
        return Err(error(
            Pos {
                line: last_line,
                column: 1,
            },
            "empty region: expected a ring line (the number of points, then x y for each)"
                .to_string(),
        ));
    };
    super::rasterise(Geometry { rings, file }, keyword)
}

/// The whitespace-separated words of one line with their positions (columns count characters).
fn words(line: &str, line_no: usize) -> impl Iterator<Item = (&str, Pos)> {
    let mut column = 1;
    let mut rest = line;
    std::iter::from_fn(move || {
        let skipped = rest.len() - rest.trim_start().len();
        column += rest[..skipped].chars().count();
        rest = &rest[skipped..];
        if rest.is_empty() {
            return None;
        }
        let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let (word, after) = rest.split_at(len);
        let pos = Pos {
            line: line_no,
            column,
        };
        column += word.chars().count();
        rest = after;
        Some((word, pos))
    })
}

fn describe(word: &str) -> String {
    format!("'{}'", shorten(word))
}

/// A vertex coordinate, with the messages of the WKT reader.
fn coordinate(word: &str, pos: Pos, file: &str) -> Result<i64> {
    let error = |message: String| Error::parse(file, pos.line, pos.column, message);
    match number_value(word) {
        NumberValue::Integer(v) => Ok(v),
        NumberValue::Fraction => Err(error(format!(
            "coordinate {} is not an integer; expected integer vertices (pixel corners)",
            shorten(word)
        ))),
        NumberValue::OutOfRange => Err(error(format!(
            "coordinate {} is out of range; expected an integer from {MIN_COORD} to {MAX_COORD}",
            shorten(word)
        ))),
        NumberValue::Malformed => Err(error(format!(
            "{} is not a number; expected a vertex coordinate",
            describe(word)
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wkt::parse_wkt;

    #[test]
    fn same_region_as_the_wkt_polygon() {
        let poly = "# a frame\n8 0 0 5 0 5 4 0 4 0 3 2 3 2 2 0 2\n4 3 1 4 1 4 3 3 3\n";
        let wkt =
            "POLYGON ((0 0, 5 0, 5 4, 0 4, 0 3, 2 3, 2 2, 0 2, 0 0), (3 1, 4 1, 4 3, 3 3, 3 1))";
        let r = parse_poly(poly, "a.poly").unwrap();
        assert_eq!(r, parse_wkt(wkt, "a.wkt").unwrap());
        // 20 - 2 (the notch) - 2 (the hole)
        assert_eq!(r.len(), 16);
        // An explicit closing point, blank lines, CRLF and a trailing comment change nothing.
        let closed = "\r\n5 0 0 5 0 5 4 0 4 0 0  # closed\r\n";
        assert_eq!(
            parse_poly(closed, "b.poly").unwrap(),
            Region::rectangle(5, 4)
        );
    }

    #[test]
    fn errors_name_line_and_column() {
        let cases = [
            ("4 0 0 1 0 1 1 0\n", "1:15: the ring has 7 coordinates"),
            (
                "4 0 0 1 0 1 1\n",
                "1:13: the ring has 3 points; expected 4 pairs",
            ),
            (
                "3 0 0 1 0 1 1 0 1\n",
                "1:15: more than 3 points on the line",
            ),
            (
                "4 0 0 1.5 0 1 1 0 1\n",
                "1:7: coordinate 1.5 is not an integer",
            ),
            ("4 0 0 x 0 1 1 0 1\n", "1:7: 'x' is not a number"),
            ("four 0 0\n", "1:1: 'four' is not a point count"),
            ("0\n", "1:1: ring with 0 points"),
            ("# nothing\n\n", "2:1: empty region"),
            (
                "4 0 0 2 1 2 2 0 2\n",
                "1:7: edge from (0,0) to (2,1) is not axis-parallel",
            ),
            (
                "4 0 0 4 0 4 4 0 4\n4 5 5 6 5 6 6 5 6\n",
                "2:3: hole is not inside its outer ring",
            ),
            (
                "4 0 0 99999999999 0 99999999999 1 0 1\n",
                "1:7: coordinate 99999999999 is out of range",
            ),
            (
                "4 0 0 100000 0 100000 100000 0 100000\n",
                "1:1: the geometry encloses 10000000000 pixels; expected at most",
            ),
        ];
        for (text, expected) in cases {
            let e = parse_poly(text, "p.poly").unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("p.poly:{expected}")),
                "{text:?}: {e}"
            );
        }
    }
}
