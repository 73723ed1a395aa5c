//! Well-known text (WKT) import and export of regions.
//!
//! [`parse_wkt`] reads one `POLYGON` or `MULTIPOLYGON` (keywords in any case, free whitespace)
//! whose vertices are integers and whose edges are horizontal or vertical. Numbers may be
//! written `3`, `-2`, `+3`, `3.0` or `1e1` as long as their value is an integer. The region is
//! the set of pixels whose centre lies inside the geometry: inside the outer ring of a polygon
//! and inside none of its holes. Repeated and collinear consecutive vertices are merged, and ring
//! orientation is ignored.
//!
//! Refused, with the file, line and column of the offending token and what was expected:
//!
//! - a geometry other than `POLYGON` or `MULTIPOLYGON`, malformed syntax, 3-D or measured
//!   vertices, text after the geometry, and an `EMPTY` geometry (an empty region);
//! - a coordinate that is not an integer or lies outside `-2^31 ..= 2^31`;
//! - an edge that is neither horizontal nor vertical;
//! - a ring that is not closed (last vertex ≠ first), has fewer than 4 corners (no area) or turns
//!   back on itself;
//! - two edges (of one ring or of two rings) that cross or overlap along a segment, and a ring
//!   that touches itself;
//! - a hole that is not inside its outer ring or lies inside another hole, and polygons of a
//!   `MULTIPOLYGON` whose interiors overlap;
//! - a geometry whose bounding box exceeds [`MAX_BBOX_CELLS`] pixels.
//!
//! These are the OGC Simple Features validity rules restricted to rectilinear integer polygons:
//! an invalid geometry has no agreed meaning, so we refuse it rather than let a tie-breaking rule
//! of ours decide which pixels a benchmark instance contains. As OGC allows, distinct rings may
//! touch at single points (a hole touching its outer ring, two polygons meeting at a corner).
//! One OGC rule is not checked, that a polygon's interior be connected (holes touching in a
//! closed chain can cut it): the pixel set is well defined all the same.
//!
//! [`to_wkt`] writes a region back: one polygon per 4-connected component, its holes as inner
//! rings, so that `parse_wkt(&to_wkt(&r), _) == r` for every non-empty region `r`.

use crate::error::{Error, Result};
use crate::region::{Dir, MAX_BBOX_CELLS, Pixel, Region};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// Smallest and largest accepted coordinate: every pixel between them has `i32` coordinates.
const MIN_COORD: i64 = i32::MIN as i64;
const MAX_COORD: i64 = i32::MAX as i64 + 1;

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
/// use mowmill::wkt::parse_wkt;
/// use mowmill::Region;
///
/// let r = parse_wkt("POLYGON ((0 0, 3 0, 3 2, 0 2, 0 0))", "ex.wkt").unwrap();
/// assert_eq!(r, Region::rectangle(3, 2));
///
/// let e = parse_wkt("POLYGON ((0 0, 2 1, 0 1, 0 0))", "ex.wkt").unwrap_err();
/// assert_eq!(e.to_string(), "ex.wkt:1:16: edge from (0,0) to (2,1) is not axis-parallel; \
///     expected every edge to be horizontal or vertical");
/// ```
pub fn parse_wkt(text: &str, file: &str) -> Result<Region> {
    let mut parser = Parser {
        lexer: Lexer::new(text),
        peeked: None,
        file,
    };
    let (rings, keyword) = parser.geometry()?;
    let geometry = Geometry { rings, file };
    geometry.check_rings_meet_at_points()?;
    let parents = geometry.enclosing_rings()?;
    geometry.check_nesting(&parents)?;
    geometry.check_bounding_box(keyword)?;
    Region::from_pixels(geometry.fill())
}

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
    let component = components(region);
    let count = component.iter().max().map_or(0, |&c| c + 1);
    let mut outer: Vec<Vec<(i64, i64)>> = vec![Vec::new(); count];
    let mut holes: Vec<Vec<Vec<(i64, i64)>>> = vec![Vec::new(); count];
    let mut visited = vec![false; 4 * region.len()];
    for i in 0..region.len() {
        for side in Dir::ALL {
            if region.neighbor(i, side).is_none() && !visited[4 * i + side.index()] {
                let ring = trace_ring(region, &component, &mut visited, i, side);
                // Traced with the region on the left: outer rings turn counter-clockwise.
                if doubled_area(&ring) > 0 {
                    outer[component[i]] = ring;
                } else {
                    holes[component[i]].push(ring);
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

// ---------------------------------------------------------------------------------------------
// Export

/// Component number of every pixel (by index) under 4-adjacency, numbered in index order.
fn components(region: &Region) -> Vec<usize> {
    let mut component = vec![usize::MAX; region.len()];
    let mut count = 0;
    let mut stack = Vec::new();
    for seed in 0..region.len() {
        if component[seed] != usize::MAX {
            continue;
        }
        component[seed] = count;
        stack.push(seed);
        while let Some(i) = stack.pop() {
            for j in region.neighbors(i) {
                if component[j] == usize::MAX {
                    component[j] = count;
                    stack.push(j);
                }
            }
        }
        count += 1;
    }
    component
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
    component: &[usize],
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

fn write_ring(out: &mut String, corners: &[(i64, i64)]) {
    out.push('(');
    for (k, (x, y)) in corners.iter().chain(corners.first()).enumerate() {
        if k > 0 {
            out.push_str(", ");
        }
        let _ = write!(out, "{x} {y}");
    }
    out.push(')');
}

// ---------------------------------------------------------------------------------------------
// Lexing

/// A place in the input; line and column start at 1 and columns count characters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Pos {
    line: usize,
    column: usize,
}

#[derive(Clone, Debug, PartialEq)]
enum Token<'a> {
    Word(&'a str),
    Number(&'a str),
    Open,
    Close,
    Comma,
    End,
}

impl Token<'_> {
    /// The token as an error message names it.
    fn describe(&self) -> String {
        match self {
            Token::Word(w) => format!("'{}'", shorten(w)),
            Token::Number(n) => format!("number {}", shorten(n)),
            Token::Open => "'('".to_string(),
            Token::Close => "')'".to_string(),
            Token::Comma => "','".to_string(),
            Token::End => "end of input".to_string(),
        }
    }
}

/// A token's text cut to a length fit for an error message.
fn shorten(s: &str) -> String {
    let mut short: String = s.chars().take(24).collect();
    if short.len() < s.len() {
        short.push('…');
    }
    short
}

struct Lexer<'a> {
    text: &'a str,
    offset: usize,
    pos: Pos,
}

impl<'a> Lexer<'a> {
    fn new(text: &'a str) -> Self {
        Lexer {
            text,
            offset: 0,
            pos: Pos { line: 1, column: 1 },
        }
    }

    fn peek_char(&self) -> Option<char> {
        self.text[self.offset..].chars().next()
    }

    fn bump(&mut self) {
        if let Some(c) = self.peek_char() {
            self.offset += c.len_utf8();
            if c == '\n' {
                self.pos = Pos {
                    line: self.pos.line + 1,
                    column: 1,
                };
            } else {
                self.pos.column += 1;
            }
        }
    }

    fn bump_while(&mut self, keep: impl Fn(char) -> bool) -> &'a str {
        let start = self.offset;
        while self.peek_char().is_some_and(&keep) {
            self.bump();
        }
        &self.text[start..self.offset]
    }

    /// The next token and where it starts, or the position and text of a stray character.
    fn next(&mut self) -> std::result::Result<(Token<'a>, Pos), (Pos, char)> {
        self.bump_while(|c| c.is_whitespace() || c == '\u{feff}');
        let pos = self.pos;
        let Some(c) = self.peek_char() else {
            return Ok((Token::End, pos));
        };
        let token = if c.is_ascii_alphabetic() {
            Token::Word(self.bump_while(|c| c.is_ascii_alphanumeric() || c == '_'))
        } else if c.is_ascii_digit() || matches!(c, '+' | '-' | '.') {
            let number =
                self.bump_while(|c| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'));
            Token::Number(number)
        } else {
            self.bump();
            match c {
                '(' => Token::Open,
                ')' => Token::Close,
                ',' => Token::Comma,
                _ => return Err((pos, c)),
            }
        };
        Ok((token, pos))
    }
}

/// The value of a number token, computed exactly so that `3.0000000000000000001` is refused.
#[derive(Debug, PartialEq)]
enum NumberValue {
    Integer(i64),
    Fraction,
    OutOfRange,
    Malformed,
}

fn number_value(text: &str) -> NumberValue {
    // Fast path for plain integers such as `-12`, the common case.
    if text.len() <= 11
        && let Ok(value) = text.parse::<i64>()
    {
        return if (MIN_COORD..=MAX_COORD).contains(&value) {
            NumberValue::Integer(value)
        } else {
            NumberValue::OutOfRange
        };
    }
    let (negative, unsigned) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(k) => (&unsigned[..k], Some(&unsigned[k + 1..])),
        None => (unsigned, None),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if whole.len() + fraction.len() == 0 || !all_digits(whole) || !all_digits(fraction) {
        return NumberValue::Malformed;
    }
    let mut exp: i64 = 0;
    if let Some(e) = exponent {
        let (sign, digits) = match e.as_bytes().first() {
            Some(b'-') => (-1, &e[1..]),
            Some(b'+') => (1, &e[1..]),
            _ => (1, e),
        };
        if digits.is_empty() || !all_digits(digits) {
            return NumberValue::Malformed;
        }
        for b in digits.bytes() {
            exp = exp.saturating_mul(10).saturating_add(i64::from(b - b'0'));
        }
        exp *= sign;
    }
    // value = digits × 10^shift, with the digits stripped of leading zeros.
    let joined = format!("{whole}{fraction}");
    let mut digits = joined.trim_start_matches('0').to_string();
    if digits.is_empty() {
        return NumberValue::Integer(0);
    }
    let shift = exp.saturating_sub(fraction.len() as i64);
    if shift < 0 {
        let drop = shift.unsigned_abs();
        let zeros = (digits.len() - digits.trim_end_matches('0').len()) as u64;
        if zeros < drop {
            return NumberValue::Fraction;
        }
        digits.truncate(digits.len() - drop as usize);
    } else if (digits.len() as i64).saturating_add(shift) > 11 {
        return NumberValue::OutOfRange;
    } else {
        digits.extend(std::iter::repeat_n('0', shift as usize));
    }
    if digits.len() > 11 {
        return NumberValue::OutOfRange;
    }
    let Ok(magnitude) = digits.parse::<i64>() else {
        return NumberValue::Malformed;
    };
    let value = if negative { -magnitude } else { magnitude };
    if (MIN_COORD..=MAX_COORD).contains(&value) {
        NumberValue::Integer(value)
    } else {
        NumberValue::OutOfRange
    }
}

// ---------------------------------------------------------------------------------------------
// Parsing

/// A vertex as written, before collinear vertices are merged.
struct Vertex {
    x: i64,
    y: i64,
    pos: Pos,
}

/// A corner of a ring; edge k runs from corner k to corner k + 1 (cyclically).
#[derive(Clone, Copy, Debug)]
struct Corner {
    x: i64,
    y: i64,
    /// Heading of the edge that leaves this corner.
    dir: Dir,
    /// The vertex written at this corner.
    pos: Pos,
    /// The vertex that ends the edge leaving this corner (where a reader sees the edge whole).
    edge_end: Pos,
}

/// A ring with at least 4 corners, all right-angled turns.
struct Ring {
    corners: Vec<Corner>,
    polygon: usize,
    hole: bool,
}

struct Parser<'a> {
    lexer: Lexer<'a>,
    peeked: Option<(Token<'a>, Pos)>,
    file: &'a str,
}

impl<'a> Parser<'a> {
    fn error(&self, pos: Pos, message: impl Into<String>) -> Error {
        Error::parse(self.file, pos.line, pos.column, message)
    }

    fn peek(&mut self) -> Result<&(Token<'a>, Pos)> {
        if self.peeked.is_none() {
            let token = self.lexer.next().map_err(|(pos, c)| {
                self.error(
                    pos,
                    format!("unexpected character {c:?}; expected a WKT polygon"),
                )
            })?;
            self.peeked = Some(token);
        }
        Ok(self.peeked.get_or_insert((Token::End, self.lexer.pos)))
    }

    fn next(&mut self) -> Result<(Token<'a>, Pos)> {
        self.peek()?;
        Ok(self.peeked.take().unwrap_or((Token::End, self.lexer.pos)))
    }

    /// Consumes `(` or fails with a message saying what it should open.
    fn open(&mut self, what: &str) -> Result<Pos> {
        match self.next()? {
            (Token::Open, pos) => Ok(pos),
            (token, pos) => Err(self.error(
                pos,
                format!("expected '(' to start {what}, found {}", token.describe()),
            )),
        }
    }

    /// Whether the next token is the keyword EMPTY (consumed if so).
    fn empty_keyword(&mut self) -> Result<Option<Pos>> {
        match self.peek()? {
            (Token::Word(w), pos) if w.eq_ignore_ascii_case("EMPTY") => {
                let pos = *pos;
                self.peeked = None;
                Ok(Some(pos))
            }
            _ => Ok(None),
        }
    }

    /// The whole input: the rings of all polygons, and where the geometry keyword is.
    fn geometry(&mut self) -> Result<(Vec<Ring>, Pos)> {
        let (token, keyword) = self.next()?;
        let Token::Word(word) = token else {
            return Err(self.error(
                keyword,
                format!(
                    "expected POLYGON or MULTIPOLYGON, found {}",
                    token.describe()
                ),
            ));
        };
        let mut rings = Vec::new();
        if word.eq_ignore_ascii_case("POLYGON") {
            if let Some(pos) = self.empty_keyword()? {
                return Err(self.error(pos, "empty region: POLYGON EMPTY has no pixels"));
            }
            self.polygon(0, &mut rings)?;
        } else if word.eq_ignore_ascii_case("MULTIPOLYGON") {
            if let Some(pos) = self.empty_keyword()? {
                return Err(self.error(pos, "empty region: MULTIPOLYGON EMPTY has no pixels"));
            }
            self.open("the list of polygons")?;
            let mut polygons = 0;
            loop {
                // An EMPTY member adds nothing; the region still must not end up empty.
                if self.empty_keyword()?.is_none() {
                    self.polygon(polygons, &mut rings)?;
                    polygons += 1;
                }
                match self.next()? {
                    (Token::Comma, _) => {}
                    (Token::Close, _) => break,
                    (token, pos) => {
                        return Err(self.error(
                            pos,
                            format!(
                                "expected ',' or ')' after a polygon, found {}",
                                token.describe()
                            ),
                        ));
                    }
                }
            }
            if polygons == 0 {
                return Err(self.error(keyword, "empty region: every polygon is EMPTY"));
            }
        } else {
            return Err(self.error(
                keyword,
                format!(
                    "unknown geometry type {}; expected POLYGON or MULTIPOLYGON",
                    Token::Word(word).describe()
                ),
            ));
        }
        match self.next()? {
            (Token::End, _) => Ok((rings, keyword)),
            (token, pos) => Err(self.error(
                pos,
                format!(
                    "unexpected {} after the end of the geometry; expected end of input",
                    token.describe()
                ),
            )),
        }
    }

    /// `((x y, ...), (x y, ...), ...)`: an outer ring and its holes.
    fn polygon(&mut self, polygon: usize, rings: &mut Vec<Ring>) -> Result<()> {
        self.open("a polygon (or EMPTY)")?;
        let mut hole = false;
        loop {
            let corners = self.ring()?;
            rings.push(Ring {
                corners,
                polygon,
                hole,
            });
            hole = true;
            match self.next()? {
                (Token::Comma, _) => {}
                (Token::Close, _) => return Ok(()),
                (token, pos) => {
                    return Err(self.error(
                        pos,
                        format!(
                            "expected ',' or ')' after a ring, found {}",
                            token.describe()
                        ),
                    ));
                }
            }
        }
    }

    /// `(x y, x y, ...)`, checked on its own and reduced to its corners.
    fn ring(&mut self) -> Result<Vec<Corner>> {
        self.open("a ring")?;
        let mut vertices = Vec::new();
        loop {
            let (x, pos) = self.coordinate("x coordinate of a vertex")?;
            let (y, _) = self.coordinate("y coordinate of the vertex")?;
            vertices.push(Vertex { x, y, pos });
            match self.next()? {
                (Token::Comma, _) => {}
                (Token::Close, _) => break,
                (Token::Number(n), pos) => {
                    return Err(self.error(
                        pos,
                        format!(
                            "expected ',' or ')' after the vertex ({x} {y}), found number {n}; \
                             only 2-D vertices (x y) are accepted"
                        ),
                    ));
                }
                (token, pos) => {
                    return Err(self.error(
                        pos,
                        format!(
                            "expected ',' or ')' after the vertex ({x} {y}), found {}",
                            token.describe()
                        ),
                    ));
                }
            }
        }
        ring_corners(&vertices, self.file)
    }

    fn coordinate(&mut self, what: &str) -> Result<(i64, Pos)> {
        let (token, pos) = self.next()?;
        let Token::Number(text) = &token else {
            return Err(self.error(
                pos,
                format!("expected the {what}, found {}", token.describe()),
            ));
        };
        match number_value(text) {
            NumberValue::Integer(v) => Ok((v, pos)),
            NumberValue::Fraction => Err(self.error(
                pos,
                format!(
                    "coordinate {} is not an integer; expected integer vertices (pixel corners)",
                    shorten(text)
                ),
            )),
            NumberValue::OutOfRange => Err(self.error(
                pos,
                format!(
                    "coordinate {} is out of range; expected an integer from {MIN_COORD} to \
                     {MAX_COORD}",
                    shorten(text)
                ),
            )),
            NumberValue::Malformed => Err(self.error(
                pos,
                format!("malformed number {}; expected the {what}", shorten(text)),
            )),
        }
    }
}

fn point(x: i64, y: i64) -> String {
    format!("({x},{y})")
}

/// Checks one ring on its own (closed, axis-parallel, at least 4 corners, never turning back)
/// and returns its corners, with repeated and collinear vertices merged.
fn ring_corners(vertices: &[Vertex], file: &str) -> Result<Vec<Corner>> {
    let error = |pos: Pos, message: String| Error::parse(file, pos.line, pos.column, message);
    let (Some(first), Some(last)) = (vertices.first(), vertices.last()) else {
        return Ok(Vec::new()); // the grammar reads at least one vertex per ring
    };
    if (first.x, first.y) != (last.x, last.y) {
        return Err(error(
            last.pos,
            format!(
                "ring is not closed: it starts at {} and ends at {}; expected the last vertex to \
                 repeat the first",
                point(first.x, first.y),
                point(last.x, last.y)
            ),
        ));
    }
    // Non-zero steps as (heading, index of the vertex that ends them).
    let mut steps: Vec<(Dir, usize)> = Vec::with_capacity(vertices.len());
    for (k, pair) in vertices.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let dir = match (b.x.cmp(&a.x), b.y.cmp(&a.y)) {
            (Ordering::Equal, Ordering::Equal) => continue,
            (Ordering::Greater, Ordering::Equal) => Dir::E,
            (Ordering::Less, Ordering::Equal) => Dir::W,
            (Ordering::Equal, Ordering::Greater) => Dir::N,
            (Ordering::Equal, Ordering::Less) => Dir::S,
            _ => {
                return Err(error(
                    b.pos,
                    format!(
                        "edge from {} to {} is not axis-parallel; expected every edge to be \
                         horizontal or vertical",
                        point(a.x, a.y),
                        point(b.x, b.y)
                    ),
                ));
            }
        };
        steps.push((dir, k + 1));
    }
    // Start at a step whose heading differs from the previous one: a corner.
    let m = steps.len();
    let previous = |j: usize| steps[(j + m - 1) % m].0;
    let mut corners: Vec<Corner> = Vec::new();
    if let Some(start) = (0..m).find(|&j| steps[j].0 != previous(j)) {
        for k in 0..m {
            let j = (start + k) % m;
            let (dir, end) = steps[j];
            match corners.last_mut() {
                Some(corner) if dir == previous(j) => corner.edge_end = vertices[end].pos,
                _ => {
                    let at = &vertices[end - 1];
                    let edge_end = vertices[end].pos;
                    corners.push(Corner {
                        x: at.x,
                        y: at.y,
                        dir,
                        pos: at.pos,
                        edge_end,
                    });
                }
            }
        }
    }
    let n = corners.len();
    if n < 4 {
        return Err(error(
            first.pos,
            format!(
                "ring has {n} distinct corners and encloses no area; expected at least 4 corners"
            ),
        ));
    }
    for k in 0..n {
        let before = corners[(k + n - 1) % n];
        let c = corners[k];
        if c.dir == before.dir.opposite() {
            return Err(error(
                c.pos,
                format!(
                    "ring turns back on itself at {}, so its edges overlap; expected a simple ring",
                    point(c.x, c.y)
                ),
            ));
        }
    }
    Ok(corners)
}

// ---------------------------------------------------------------------------------------------
// Validity and filling

/// An edge as a segment: `fixed` is its y (horizontal) or x (vertical), `lo < hi` its extent.
#[derive(Clone, Copy, Debug)]
struct Segment {
    fixed: i64,
    lo: i64,
    hi: i64,
    ring: usize,
    edge: usize,
}

struct Geometry<'a> {
    rings: Vec<Ring>,
    file: &'a str,
}

impl Geometry<'_> {
    fn error(&self, pos: Pos, message: impl Into<String>) -> Error {
        Error::parse(self.file, pos.line, pos.column, message)
    }

    fn edge_ends(&self, ring: usize, edge: usize) -> (Corner, Corner) {
        let corners = &self.rings[ring].corners;
        (corners[edge], corners[(edge + 1) % corners.len()])
    }

    fn describe_edge(&self, ring: usize, edge: usize) -> String {
        let (a, b) = self.edge_ends(ring, edge);
        format!("edge from {} to {}", point(a.x, a.y), point(b.x, b.y))
    }

    /// An error about two edges, placed where the later one is complete: "`later` `verb`
    /// `earlier` `place`".
    fn edges_error(&self, a: &Segment, b: &Segment, verb: &str, place: String) -> Error {
        let pos_a = self.rings[a.ring].corners[a.edge].edge_end;
        let pos_b = self.rings[b.ring].corners[b.edge].edge_end;
        let (first, second) = if pos_a <= pos_b { (a, b) } else { (b, a) };
        self.error(
            pos_a.max(pos_b),
            format!(
                "{} {verb} {} {place}; expected rings that meet at most at single points",
                self.describe_edge(second.ring, second.edge),
                self.describe_edge(first.ring, first.edge)
            ),
        )
    }

    /// Horizontal and vertical edges of all rings.
    fn segments(&self) -> (Vec<Segment>, Vec<Segment>) {
        let (mut horizontal, mut vertical) = (Vec::new(), Vec::new());
        for (ring, r) in self.rings.iter().enumerate() {
            for edge in 0..r.corners.len() {
                let (a, b) = self.edge_ends(ring, edge);
                if a.y == b.y {
                    let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
                    horizontal.push(Segment {
                        fixed: a.y,
                        lo,
                        hi,
                        ring,
                        edge,
                    });
                } else {
                    let (lo, hi) = (a.y.min(b.y), a.y.max(b.y));
                    vertical.push(Segment {
                        fixed: a.x,
                        lo,
                        hi,
                        ring,
                        edge,
                    });
                }
            }
        }
        (horizontal, vertical)
    }

    /// Refuses edges that overlap or cross, and rings that touch themselves.
    ///
    /// Corners are right angles, so a corner lying inside another edge always makes one of its
    /// own edges overlap that edge; what remains are proper crossings and shared corners, and a
    /// shared corner is a crossing only if both rings go straight through it, which they don't.
    fn check_rings_meet_at_points(&self) -> Result<()> {
        let (mut horizontal, mut vertical) = self.segments();
        self.check_overlaps(&mut horizontal, point)?;
        self.check_overlaps(&mut vertical, |along, fixed| point(fixed, along))?;
        self.check_crossings(&horizontal, &vertical)?;
        let mut corners: Vec<(i64, i64, usize, Pos)> = Vec::new();
        for (ring, r) in self.rings.iter().enumerate() {
            corners.extend(r.corners.iter().map(|c| (c.x, c.y, ring, c.pos)));
        }
        corners.sort_unstable();
        for pair in corners.windows(2) {
            let ((x, y, ring, _), (x2, y2, ring2, pos)) = (pair[0], pair[1]);
            if (x, y, ring) == (x2, y2, ring2) {
                return Err(self.error(
                    pos,
                    format!(
                        "ring passes through {} twice; expected a simple ring (write the parts \
                         as separate polygons, or as an outer ring and a hole, touching there)",
                        point(x, y)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Refuses two parallel edges on one line whose extents share more than a point.
    fn check_overlaps(
        &self,
        segments: &mut [Segment],
        point: impl Fn(i64, i64) -> String,
    ) -> Result<()> {
        segments.sort_unstable_by_key(|s| (s.fixed, s.lo, s.hi));
        // The segment reaching farthest among those already seen on the current line.
        let mut reach: Option<Segment> = None;
        for s in segments.iter() {
            match reach {
                Some(r) if r.fixed == s.fixed && s.lo < r.hi => {
                    let shared = format!(
                        "along {}-{}",
                        point(s.lo, s.fixed),
                        point(s.hi.min(r.hi), s.fixed)
                    );
                    return Err(self.edges_error(s, &r, "overlaps", shared));
                }
                Some(r) if r.fixed == s.fixed && r.hi >= s.hi => {}
                _ => reach = Some(*s),
            }
        }
        Ok(())
    }

    /// Refuses a horizontal and a vertical edge whose interiors cross, by a sweep in x over
    /// the horizontal edges open at each vertical edge.
    fn check_crossings(&self, horizontal: &[Segment], vertical: &[Segment]) -> Result<()> {
        const CLOSE: u8 = 0;
        const QUERY: u8 = 1;
        const OPEN: u8 = 2;
        let mut events: Vec<(i64, u8, usize)> =
            Vec::with_capacity(2 * horizontal.len() + vertical.len());
        for (k, s) in horizontal.iter().enumerate() {
            events.push((s.lo, OPEN, k));
            events.push((s.hi, CLOSE, k));
        }
        events.extend(
            vertical
                .iter()
                .enumerate()
                .map(|(k, s)| (s.fixed, QUERY, k)),
        );
        events.sort_unstable();
        // Open horizontal edges by y: no two overlap, so a line holds at most one at a time.
        let mut open: BTreeMap<i64, usize> = BTreeMap::new();
        for (_, kind, k) in events {
            match kind {
                CLOSE => {
                    open.remove(&horizontal[k].fixed);
                }
                OPEN => {
                    open.insert(horizontal[k].fixed, k);
                }
                _ => {
                    let v = &vertical[k];
                    if let Some((&y, &h)) = open.range(v.lo + 1..v.hi).next() {
                        let at = format!("at {}", point(v.fixed, y));
                        return Err(self.edges_error(v, &horizontal[h], "crosses", at));
                    }
                }
            }
        }
        Ok(())
    }

    /// For each ring, the innermost ring that encloses it (rings no longer cross, so this is
    /// a tree). Found by a sweep in y: at the lowest row a ring occupies, the nearest vertical
    /// edge to its left belongs to its parent when the parent's interior lies to the right of
    /// that edge, and otherwise to a sibling, whose parent it shares.
    fn enclosing_rings(&self) -> Result<Vec<Option<usize>>> {
        let counter_clockwise: Vec<bool> = self
            .rings
            .iter()
            .map(|r| doubled_area(&r.corners.iter().map(|c| (c.x, c.y)).collect::<Vec<_>>()) > 0)
            .collect();
        let (_, vertical) = self.segments();
        // The lowest row of each ring and its leftmost edge there.
        let mut lowest: Vec<Option<(i64, i64)>> = vec![None; self.rings.len()];
        for v in &vertical {
            let slot = &mut lowest[v.ring];
            if slot.is_none_or(|low| (v.lo, v.fixed) < low) {
                *slot = Some((v.lo, v.fixed));
            }
        }
        const CLOSE: u8 = 0;
        const OPEN: u8 = 1;
        const QUERY: u8 = 2;
        let mut events: Vec<(i64, u8, i64, usize)> = Vec::with_capacity(3 * vertical.len());
        for (k, v) in vertical.iter().enumerate() {
            events.push((v.lo, OPEN, v.fixed, k));
            events.push((v.hi, CLOSE, v.fixed, k));
        }
        for (ring, low) in lowest.iter().enumerate() {
            if let Some((y, x)) = low {
                events.push((*y, QUERY, *x, ring));
            }
        }
        events.sort_unstable();
        // Vertical edges crossing the current row by x: (ring, its interior lies to the right).
        let mut open: BTreeMap<i64, (usize, bool)> = BTreeMap::new();
        let mut parent: Vec<Option<Option<usize>>> = vec![None; self.rings.len()];
        for (_, kind, x, k) in events {
            match kind {
                CLOSE => {
                    open.remove(&x);
                }
                OPEN => {
                    let v = &vertical[k];
                    let (a, _) = self.edge_ends(v.ring, v.edge);
                    let southward = a.y == v.hi;
                    open.insert(x, (v.ring, southward == counter_clockwise[v.ring]));
                }
                _ => {
                    parent[k] = match open.range(..x).next_back() {
                        None => Some(None),
                        Some((_, &(left, true))) => Some(Some(left)),
                        Some((_, &(left, false))) => parent[left],
                    };
                }
            }
        }
        parent
            .into_iter()
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| Error::invalid("internal error: a ring was missed by the nesting sweep"))
    }

    /// Refuses holes outside their outer ring or inside another hole, and polygons inside
    /// other polygons (their interiors would overlap).
    fn check_nesting(&self, parent: &[Option<usize>]) -> Result<()> {
        let mut outer_of = vec![usize::MAX; self.rings.len()];
        for (k, r) in self.rings.iter().enumerate().rev() {
            outer_of[r.polygon] = k;
        }
        for (k, r) in self.rings.iter().enumerate() {
            let at = r.corners[0].pos;
            let container = parent[k].map(|p| &self.rings[p]);
            if r.hole {
                match container {
                    _ if parent[k] == Some(outer_of[r.polygon]) => {}
                    Some(c) if c.hole && c.polygon == r.polygon => {
                        return Err(self.error(
                            at,
                            "hole lies inside another hole of its polygon; expected holes with \
                             disjoint interiors",
                        ));
                    }
                    _ => {
                        return Err(self.error(
                            at,
                            "hole is not inside its outer ring; expected every inner ring of a \
                             polygon to lie inside its first ring",
                        ));
                    }
                }
            } else if let Some(c) = container
                && !c.hole
            {
                return Err(self.error(
                    at,
                    format!(
                        "polygon {} lies inside polygon {}, so their interiors overlap; expected \
                         the polygons of a MULTIPOLYGON not to overlap",
                        r.polygon + 1,
                        c.polygon + 1
                    ),
                ));
            }
        }
        Ok(())
    }

    fn check_bounding_box(&self, keyword: Pos) -> Result<()> {
        let corners = || self.rings.iter().flat_map(|r| r.corners.iter());
        let span = |f: fn(&Corner) -> i64| {
            let (lo, hi) = (corners().map(f).min(), corners().map(f).max());
            lo.zip(hi).map_or(0, |(lo, hi)| (hi - lo) as u128)
        };
        let (w, h) = (span(|c| c.x), span(|c| c.y));
        if w * h > MAX_BBOX_CELLS as u128 {
            return Err(self.error(
                keyword,
                format!(
                    "the geometry spans a {w}×{h} bounding box; expected at most {MAX_BBOX_CELLS} \
                     pixels"
                ),
            ));
        }
        Ok(())
    }

    /// The enclosed pixels, row by row: on row y the vertical edges crossing y + ½, sorted by
    /// x, bound the region in pairs (even-odd rule, which the nesting checks make exact).
    fn fill(&self) -> Vec<Pixel> {
        let (_, vertical) = self.segments();
        const CLOSE: u8 = 0;
        const OPEN: u8 = 1;
        let mut events: Vec<(i64, u8, i64)> = Vec::with_capacity(2 * vertical.len());
        for v in &vertical {
            events.push((v.lo, OPEN, v.fixed));
            events.push((v.hi, CLOSE, v.fixed));
        }
        events.sort_unstable();
        let mut pixels = Vec::new();
        let mut open: BTreeSet<i64> = BTreeSet::new();
        let mut next = 0;
        let mut y = events.first().map_or(0, |e| e.0);
        while next < events.len() {
            while let Some(&(at, kind, x)) = events.get(next)
                && at <= y
            {
                if kind == OPEN {
                    open.insert(x);
                } else {
                    open.remove(&x);
                }
                next += 1;
            }
            if open.is_empty() {
                if let Some(&(at, _, _)) = events.get(next) {
                    y = at;
                }
                continue;
            }
            let mut xs = open.iter();
            while let (Some(&from), Some(&to)) = (xs.next(), xs.next()) {
                // Coordinates lie in MIN_COORD..=MAX_COORD, so every pixel fits in i32.
                pixels.extend((from..to).map(|x| Pixel::new(x as i32, y as i32)));
            }
            y += 1;
        }
        pixels
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn parse(text: &str) -> Result<Region> {
        parse_wkt(text, "t.wkt")
    }

    /// The error message of a refused input.
    fn refusal(text: &str) -> String {
        match parse(text) {
            Ok(r) => panic!("accepted {text:?} as {r:?}"),
            Err(e) => e.to_string(),
        }
    }

    fn assert_refused(text: &str, location: &str, words: &str) {
        let message = refusal(text);
        assert!(
            message.starts_with(&format!("t.wkt:{location}: ")),
            "{text:?}: expected location {location}, got {message:?}"
        );
        assert!(
            message.contains(words),
            "{text:?}: expected {words:?} in {message:?}"
        );
    }

    #[test]
    fn rectangle() {
        let r = parse("POLYGON((0 0, 3 0, 3 2, 0 2, 0 0))").unwrap();
        assert_eq!(r, Region::rectangle(3, 2));
        assert_eq!(r.len(), 6);
        assert_eq!(to_wkt(&r), "POLYGON ((0 0, 3 0, 3 2, 0 2, 0 0))");
    }

    #[test]
    fn square_with_a_hole() {
        let text = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))";
        let r = parse(text).unwrap();
        assert_eq!(r, Region::from_ascii("####\n#..#\n#..#\n####\n"));
        // Holes are written clockwise, from their lowest-leftmost corner.
        assert_eq!(to_wkt(&r), text);
    }

    #[test]
    fn multipolygon_of_two_squares() {
        let text = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((3 1, 4 1, 4 2, 3 2, 3 1)))";
        let r = parse(text).unwrap();
        assert_eq!(r, Region::from_ascii("##.#\n##..\n"));
        assert_eq!(to_wkt(&r), text);
    }

    #[test]
    fn l_shape_with_collinear_and_repeated_vertices() {
        // Clockwise, a repeated vertex, a collinear one, numbers in several notations.
        let text = "polygon ((0 0, 0 3, 1 3, 1 1, 1 1, 2 1, 3.0 1, 3E0 0, +0 0))";
        let r = parse(text).unwrap();
        assert_eq!(r, Region::from_ascii("#..\n#..\n###\n"));
        assert_eq!(to_wkt(&r), "POLYGON ((0 0, 3 0, 3 1, 1 1, 1 3, 0 3, 0 0))");
    }

    #[test]
    fn whitespace_case_and_negative_coordinates() {
        let text = "\n  MultiPolygon\t(\n ( (-2 -1,-1 -1,\n-1 0,-2 0,-2 -1) ) , EMPTY )\n\n";
        let r = parse(text).unwrap();
        assert_eq!(r.pixels(), &[Pixel::new(-2, -1)]);
        assert_eq!(number_value("1e1"), NumberValue::Integer(10));
        assert_eq!(number_value("-2.5e0"), NumberValue::Fraction);
        assert_eq!(number_value("-2.5e1"), NumberValue::Integer(-25));
        assert_eq!(number_value("-2.50e1"), NumberValue::Integer(-25));
        assert_eq!(number_value("-2.50e2"), NumberValue::Integer(-250));
        assert_eq!(number_value("3.0000000000000000001"), NumberValue::Fraction);
        assert_eq!(
            number_value("0.000e99999999999999999999"),
            NumberValue::Integer(0)
        );
        assert_eq!(number_value("2147483648"), NumberValue::Integer(MAX_COORD));
        assert_eq!(number_value("2147483649"), NumberValue::OutOfRange);
        assert_eq!(
            number_value("1e99999999999999999999"),
            NumberValue::OutOfRange
        );
        assert_eq!(
            number_value("1e-99999999999999999999"),
            NumberValue::Fraction
        );
        assert_eq!(number_value("1-2"), NumberValue::Malformed);
        assert_eq!(number_value("."), NumberValue::Malformed);
        assert_eq!(number_value("1e"), NumberValue::Malformed);
    }

    #[test]
    fn rings_may_touch_at_a_point() {
        // A hole touching the outer ring at (2, 1), as to_wkt writes it.
        let r = Region::from_ascii("###\n#.#\n##.\n");
        let text = to_wkt(&r);
        assert_eq!(
            text,
            "POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 0 3, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))"
        );
        assert_eq!(parse(&text).unwrap(), r);
        // Two holes touching at a corner.
        let r = Region::from_ascii("####\n#.##\n##.#\n####\n");
        let text = to_wkt(&r);
        assert_eq!(
            text,
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (2 1, 2 2, 3 2, 3 1, 2 1), \
             (1 2, 1 3, 2 3, 2 2, 1 2))"
        );
        assert_eq!(parse(&text).unwrap(), r);
        // A pixel in a plus-shaped hole touching it at its four corners: two polygons.
        let r = Region::from_ascii("#####\n##.##\n#.#.#\n##.##\n#####\n");
        let text = to_wkt(&r);
        assert!(text.starts_with("MULTIPOLYGON (((0 0, 5 0, 5 5, 0 5, 0 0), (2 1, 2 2, 1 2,"));
        assert!(text.ends_with("((2 2, 3 2, 3 3, 2 3, 2 2)))"), "{text}");
        assert_eq!(parse(&text).unwrap(), r);
    }

    #[test]
    fn empty_region_writes_and_is_refused() {
        let empty = Region::from_pixels([]).unwrap();
        assert_eq!(to_wkt(&empty), "POLYGON EMPTY");
        assert_refused("POLYGON EMPTY", "1:9", "empty region");
        assert_refused("multipolygon empty", "1:14", "empty region");
        assert_refused("MULTIPOLYGON (EMPTY, EMPTY)", "1:1", "empty region");
    }

    #[test]
    fn refuses_syntax_errors() {
        assert_refused(
            "LINESTRING (0 0, 1 0)",
            "1:1",
            "unknown geometry type 'LINESTRING'; expected POLYGON or MULTIPOLYGON",
        );
        assert_refused(
            "",
            "1:1",
            "expected POLYGON or MULTIPOLYGON, found end of input",
        );
        assert_refused("(0 0)", "1:1", "expected POLYGON or MULTIPOLYGON");
        assert_refused(
            "POLYGON Z ((0 0 0))",
            "1:9",
            "expected '(' to start a polygon",
        );
        assert_refused("POLYGON ((0 0 1, 1 0 1))", "1:15", "only 2-D vertices");
        assert_refused("POLYGON ((0 0, 1))", "1:17", "expected the y coordinate");
        assert_refused(
            "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0)",
            "1:35",
            "found end of input",
        );
        assert_refused("POLYGON ((0 0; 1 0))", "1:14", "unexpected character ';'");
        assert_refused(
            "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0) (",
            "1:36",
            "expected ',' or ')'",
        );
        assert_refused("POLYGON ((0 0, 1-1 0))", "1:16", "malformed number 1-1");
        assert_refused(
            "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\nPOLYGON",
            "2:1",
            "unexpected 'POLYGON' after the end of the geometry; expected end of input",
        );
        assert_refused(
            "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)) x",
            "1:43",
            "expected ',' or ')' after a polygon",
        );
    }

    #[test]
    fn refuses_bad_coordinates() {
        assert_refused(
            "POLYGON ((0 0, 1.5 0, 1.5 1, 0 1, 0 0))",
            "1:16",
            "1.5 is not an integer",
        );
        assert_refused(
            "POLYGON ((0 0, 1 0, 1 1e-1, 0 1, 0 0))",
            "1:23",
            "not an integer",
        );
        assert_refused(
            "POLYGON ((0 0, 3e10 0, 3e10 1, 0 1, 0 0))",
            "1:16",
            "out of range",
        );
    }

    #[test]
    fn refuses_diagonal_edges() {
        assert_refused(
            "POLYGON ((0 0, 2 0,\n  2 1, 0 1,\n    1 0, 0 0))",
            "3:5",
            "edge from (0,1) to (1,0) is not axis-parallel",
        );
        assert_refused(
            "POLYGON ((0 0, 2 1, 0 1, 0 0))",
            "1:16",
            "edge from (0,0) to (2,1) is not axis-parallel",
        );
    }

    #[test]
    fn refuses_bad_rings() {
        assert_refused(
            "POLYGON ((0 0, 2 0, 2 2, 0 2))",
            "1:26",
            "ring is not closed: it starts at (0,0) and ends at (0,2)",
        );
        assert_refused("POLYGON ((0 0, 2 0, 0 0))", "1:11", "2 distinct corners");
        assert_refused("POLYGON ((5 5))", "1:11", "0 distinct corners");
        assert_refused("POLYGON ((0 0, 1 0, 2 0, 0 0))", "1:11", "encloses no area");
        assert_refused(
            "POLYGON ((0 0, 3 0, 2 0, 2 1, 0 1, 0 0))",
            "1:16",
            "ring turns back on itself at (3,0)",
        );
    }

    #[test]
    fn refuses_crossing_and_overlapping_edges() {
        // A ring crossing itself: two loops joined in a figure eight.
        assert_refused(
            "POLYGON ((0 0, 2 0, 2 2, 1 2, 1 -1, 0 -1, 0 0))",
            "1:31",
            "edge from (1,2) to (1,-1) crosses edge from (0,0) to (2,0) at (1,0)",
        );
        // Two holes overlapping along part of an edge.
        assert_refused(
            "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1),\n\
             (3 2, 5 2, 5 4, 3 4, 3 2))",
            "2:22",
            "edge from (3,4) to (3,2) overlaps edge from (3,1) to (3,3) along (3,2)-(3,3)",
        );
        // Polygons sharing an edge segment.
        assert_refused(
            "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 0, 2 0, 2 1, 1 1, 1 0)))",
            "1:66",
            "edge from (1,1) to (1,0) overlaps edge from (1,0) to (1,1) along (1,0)-(1,1)",
        );
        // A hole touching the outer ring along a segment.
        assert_refused(
            "POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (0 1, 1 1, 1 2, 0 2, 0 1))",
            "1:58",
            "edge from (0,2) to (0,1) overlaps edge from (0,3) to (0,0) along (0,1)-(0,2)",
        );
        // A ring through the same point twice (a figure eight pinched at (1,1)).
        assert_refused(
            "POLYGON ((0 0, 1 0, 1 1, 2 1, 2 2, 1 2, 1 1, 0 1, 0 0))",
            "1:41",
            "ring passes through (1,1) twice",
        );
    }

    #[test]
    fn refuses_bad_nesting() {
        assert_refused(
            "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0),\n (3 0, 4 0, 4 1, 3 1, 3 0))",
            "2:3",
            "hole is not inside its outer ring",
        );
        assert_refused(
            "POLYGON ((1 1, 2 1, 2 2, 1 2, 1 1), (0 0, 3 0, 3 3, 0 3, 0 0))",
            "1:38",
            "hole is not inside its outer ring",
        );
        assert_refused(
            "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 8 1, 8 8, 1 8, 1 1), \
             (2 2, 3 2, 3 3, 2 3, 2 2))",
            "1:65",
            "hole lies inside another hole",
        );
        assert_refused(
            "MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))",
            "1:46",
            "polygon 2 lies inside polygon 1",
        );
        // The first polygon inside the second: reported at the inner one.
        assert_refused(
            "MULTIPOLYGON (((1 1, 2 1, 2 2, 1 2, 1 1)), ((0 0, 9 0, 9 9, 0 9, 0 0)))",
            "1:17",
            "polygon 1 lies inside polygon 2",
        );
        // A polygon inside another one's hole is fine, and so is a hole in it.
        let r = parse(
            "MULTIPOLYGON (((0 0, 5 0, 5 5, 0 5, 0 0), (1 1, 4 1, 4 4, 1 4, 1 1)), \
             ((2 2, 3 2, 3 3, 2 3, 2 2)))",
        )
        .unwrap();
        assert_eq!(r, Region::from_ascii("#####\n#...#\n#.#.#\n#...#\n#####\n"));
    }

    #[test]
    fn refuses_huge_bounding_box() {
        assert_refused(
            "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((100000 100000, 100001 100000, \
             100001 100001, 100000 100001, 100000 100000)))",
            "1:1",
            "bounding box",
        );
    }

    #[test]
    fn extreme_coordinates() {
        let r = Region::from_pixels([
            Pixel::new(i32::MAX, i32::MIN),
            Pixel::new(i32::MAX, i32::MIN + 1),
        ])
        .unwrap();
        let text = to_wkt(&r);
        assert_eq!(
            text,
            "POLYGON ((2147483647 -2147483648, 2147483648 -2147483648, 2147483648 -2147483646, \
             2147483647 -2147483646, 2147483647 -2147483648))"
        );
        assert_eq!(parse(&text).unwrap(), r);
    }

    #[test]
    fn large_random_region_round_trips() {
        // Many saddles, holes and components; quadratic checks would take minutes here.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut pixels = Vec::new();
        for y in 0..400 {
            for x in 0..400 {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                if state % 5 < 3 {
                    pixels.push(Pixel::new(x, y));
                }
            }
        }
        let r = Region::from_pixels(pixels).unwrap();
        assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
    }

    /// Reference rasterizer: even-odd rule at every pixel centre, edge by edge.
    fn brute_force(rings: &[Vec<(i64, i64)>]) -> Vec<Pixel> {
        let mut pixels = Vec::new();
        for y in -2..14 {
            for x in -2..14 {
                let (cx, cy) = (2 * x + 1, 2 * y + 1);
                let mut inside = false;
                for ring in rings {
                    for k in 0..ring.len() {
                        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                        let (ay, by) = (2 * a.1, 2 * b.1);
                        if a.0 == b.0 && (ay < cy) != (by < cy) && 2 * a.0 > cx {
                            inside = !inside;
                        }
                    }
                }
                if inside {
                    pixels.push(Pixel::new(x as i32, y as i32));
                }
            }
        }
        pixels
    }

    fn rectangle_ring(r: (i64, i64, i64, i64)) -> Vec<(i64, i64)> {
        let (x0, y0, x1, y1) = r;
        vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    }

    fn ring_text(ring: &[(i64, i64)]) -> String {
        let mut s = String::new();
        write_ring(&mut s, ring);
        s
    }

    fn rectangles(n: usize) -> impl Strategy<Value = Vec<(i64, i64, i64, i64)>> {
        prop::collection::vec((0..10i64, 0..10i64, 1..5i64, 1..5i64), 1..n).prop_map(|v| {
            v.into_iter()
                .map(|(x, y, w, h)| (x, y, x + w, y + h))
                .collect()
        })
    }

    /// Closed rectangles share interior points or a segment (not just a corner or nothing).
    fn meet_in_more_than_a_point(a: (i64, i64, i64, i64), b: (i64, i64, i64, i64)) -> bool {
        let x = a.0.max(b.0) <= a.2.min(b.2);
        let y = a.1.max(b.1) <= a.3.min(b.3);
        let x_positive = a.0.max(b.0) < a.2.min(b.2);
        let y_positive = a.1.max(b.1) < a.3.min(b.3);
        x && y && (x_positive || y_positive)
    }

    /// Random pixel subsets of small boxes at random offsets, of random density.
    fn regions() -> impl Strategy<Value = Region> {
        (1..9i32, 1..9i32, -20..20i32, -20..20i32, 1..10u8)
            .prop_flat_map(|(w, h, dx, dy, density)| {
                prop::collection::vec(0..10u8, (w * h) as usize).prop_map(move |cells| {
                    let pixels = cells
                        .iter()
                        .enumerate()
                        .filter(|&(_, &c)| c < density)
                        .map(|(k, _)| Pixel::new(dx + k as i32 % w, dy + k as i32 / w));
                    Region::from_pixels(pixels).unwrap()
                })
            })
            .prop_filter("non-empty", |r| !r.is_empty())
    }

    proptest! {
        #[test]
        fn round_trip(r in regions()) {
            let text = to_wkt(&r);
            prop_assert_eq!(parse(&text).unwrap(), r.clone(), "{}", text);
            for s in crate::region::Symmetry::all() {
                let image = r.transformed(s);
                prop_assert_eq!(parse(&to_wkt(&image)).unwrap(), image);
            }
        }

        #[test]
        fn multipolygon_of_rectangles(rects in rectangles(6)) {
            let text = format!(
                "MULTIPOLYGON ({})",
                rects.iter().map(|&r| format!("({})", ring_text(&rectangle_ring(r))))
                    .collect::<Vec<_>>().join(", ")
            );
            let valid = (0..rects.len())
                .all(|i| (0..i).all(|j| !meet_in_more_than_a_point(rects[i], rects[j])));
            match parse(&text) {
                Ok(r) => {
                    prop_assert!(valid, "accepted {}", text);
                    let rings: Vec<_> = rects.iter().map(|&r| rectangle_ring(r)).collect();
                    prop_assert_eq!(r, Region::from_pixels(brute_force(&rings)).unwrap());
                }
                Err(e) => prop_assert!(!valid, "refused {}: {}", text, e),
            }
        }

        #[test]
        fn polygon_with_rectangular_holes(holes in rectangles(5)) {
            let outer = (1, 1, 12, 12);
            let mut rings = vec![rectangle_ring(outer)];
            rings.extend(holes.iter().map(|&h| rectangle_ring(h)));
            let text = format!(
                "POLYGON ({})",
                rings.iter().map(|r| ring_text(r)).collect::<Vec<_>>().join(", ")
            );
            let strictly_inside = |h: (i64, i64, i64, i64)| {
                h.0 > outer.0 && h.1 > outer.1 && h.2 < outer.2 && h.3 < outer.3
            };
            let valid = holes.iter().all(|&h| strictly_inside(h))
                && (0..holes.len())
                    .all(|i| (0..i).all(|j| !meet_in_more_than_a_point(holes[i], holes[j])));
            match parse(&text) {
                Ok(r) => {
                    prop_assert!(valid, "accepted {}", text);
                    prop_assert_eq!(r, Region::from_pixels(brute_force(&rings)).unwrap());
                }
                Err(e) => prop_assert!(!valid, "refused {}: {}", text, e),
            }
        }

        #[test]
        fn never_panics_on_arbitrary_text(text in any::<String>()) {
            let _ = parse(&text);
        }

        #[test]
        fn never_panics_on_wkt_like_text(
            text in "(POLYGON|MULTIPOLYGON|EMPTY|[()]|, |-?[0-9]{1,2}(\\.[05])?(e[+-]?1)? ){0,40}"
        ) {
            if let Ok(r) = parse(&text) {
                prop_assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
            }
        }

        #[test]
        fn never_panics_on_mutated_wkt(
            r in regions(),
            edits in prop::collection::vec((any::<prop::sample::Index>(), 0..4u8, 0..16usize), 1..4),
        ) {
            const ALPHABET: &[u8] = b"()(),, 0123-9.eE";
            let mut bytes = to_wkt(&r).into_bytes();
            for (at, kind, c) in edits {
                let k = at.index(bytes.len() + 1);
                match kind {
                    0 if k < bytes.len() => { bytes.remove(k); }
                    1 if k < bytes.len() => bytes[k] = ALPHABET[c],
                    2 if k < bytes.len() => bytes.truncate(k),
                    _ => bytes.insert(k, ALPHABET[c]),
                }
            }
            let text = String::from_utf8(bytes).unwrap();
            if let Ok(r) = parse(&text) {
                prop_assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
            }
        }
    }
}
