//! Parsing WKT tokens into rings of corners, each ring checked on its own.

use super::lexer::{Lexer, NumberValue, Pos, Token, number_value, shorten};
use super::{MAX_COORD, MIN_COORD};
use crate::error::{Error, Result};
use crate::region::Dir;
use std::cmp::Ordering;
use std::fmt;
use std::marker::PhantomData;

/// What the reader makes of a number: integers for pixel regions ([`parse_wkt`](super::parse_wkt)),
/// exact rationals for the polygons of `mowmill_core::ortho`. The syntax and the validity rules are
/// the same for both.
pub trait Coordinate: Copy + Ord + fmt::Display {
    /// The most vertices (as written, closing ones included) a geometry may have.
    const MAX_VERTICES: usize = usize::MAX;
    /// Whether a vertex equal to the one before is refused as a zero-length edge rather than
    /// merged.
    const REFUSE_REPEATS: bool = false;
    /// The value of a number token, or what is wrong with it (`what` names the coordinate; the
    /// reader adds where it is).
    fn read(text: &str, what: &str) -> std::result::Result<Self, String>;
}

impl Coordinate for i64 {
    fn read(text: &str, what: &str) -> std::result::Result<i64, String> {
        match number_value(text) {
            NumberValue::Integer(v) => Ok(v),
            NumberValue::Fraction => Err(format!(
                "coordinate {} is not an integer; expected integer vertices (pixel corners)",
                shorten(text)
            )),
            NumberValue::OutOfRange => Err(format!(
                "coordinate {} is out of range; expected an integer from {MIN_COORD} to \
                 {MAX_COORD}",
                shorten(text)
            )),
            NumberValue::Malformed => Err(format!(
                "malformed number {}; expected the {what}",
                shorten(text)
            )),
        }
    }
}

/// A vertex as written, before collinear vertices are merged.
pub(super) struct Vertex<C> {
    pub(super) x: C,
    pub(super) y: C,
    pub(super) pos: Pos,
}

/// A corner of a ring; edge k runs from corner k to corner k + 1 (cyclically).
#[derive(Clone, Copy, Debug)]
pub(super) struct Corner<C> {
    pub(super) x: C,
    pub(super) y: C,
    /// Heading of the edge that leaves this corner.
    pub(super) dir: Dir,
    /// The vertex written at this corner.
    pub(super) pos: Pos,
    /// The vertex that ends the edge leaving this corner (where a reader sees the edge whole).
    pub(super) edge_end: Pos,
}

/// A ring with at least 4 corners, all right-angled turns.
pub(super) struct Ring<C> {
    pub(super) corners: Vec<Corner<C>>,
    pub(super) polygon: usize,
    pub(super) hole: bool,
}

pub(super) struct Parser<'a, C> {
    pub(super) lexer: Lexer<'a>,
    pub(super) peeked: Option<(Token<'a>, Pos)>,
    pub(super) file: &'a str,
    /// Vertices read so far, against [`Coordinate::MAX_VERTICES`].
    vertices: usize,
    coordinate: PhantomData<C>,
}

impl<'a, C: Coordinate> Parser<'a, C> {
    pub(super) fn new(text: &'a str, file: &'a str) -> Self {
        Parser {
            lexer: Lexer::new(text),
            peeked: None,
            file,
            vertices: 0,
            coordinate: PhantomData,
        }
    }

    pub(super) fn error(&self, pos: Pos, message: impl Into<String>) -> Error {
        Error::parse(self.file, pos.line, pos.column, message)
    }

    pub(super) fn peek(&mut self) -> Result<&(Token<'a>, Pos)> {
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

    pub(super) fn next(&mut self) -> Result<(Token<'a>, Pos)> {
        self.peek()?;
        Ok(self.peeked.take().unwrap_or((Token::End, self.lexer.pos)))
    }

    /// Consumes `(` or fails with a message saying what it should open.
    pub(super) fn open(&mut self, what: &str) -> Result<Pos> {
        match self.next()? {
            (Token::Open, pos) => Ok(pos),
            (token, pos) => Err(self.error(
                pos,
                format!("expected '(' to start {what}, found {}", token.describe()),
            )),
        }
    }

    /// Whether the next token is the keyword EMPTY (consumed if so).
    pub(super) fn empty_keyword(&mut self) -> Result<Option<Pos>> {
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
    pub(super) fn geometry(&mut self) -> Result<(Vec<Ring<C>>, Pos)> {
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
    pub(super) fn polygon(&mut self, polygon: usize, rings: &mut Vec<Ring<C>>) -> Result<()> {
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
    pub(super) fn ring(&mut self) -> Result<Vec<Corner<C>>> {
        self.open("a ring")?;
        let mut vertices = Vec::new();
        loop {
            let (x, pos) = self.coordinate("x coordinate of a vertex")?;
            let (y, _) = self.coordinate("y coordinate of the vertex")?;
            self.vertices += 1;
            if self.vertices > C::MAX_VERTICES {
                return Err(self.error(
                    pos,
                    format!(
                        "more than {} vertices; expected at most {} (the vertex limit)",
                        C::MAX_VERTICES,
                        C::MAX_VERTICES
                    ),
                ));
            }
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

    pub(super) fn coordinate(&mut self, what: &str) -> Result<(C, Pos)> {
        let (token, pos) = self.next()?;
        let Token::Number(text) = &token else {
            return Err(self.error(
                pos,
                format!("expected the {what}, found {}", token.describe()),
            ));
        };
        C::read(text, what)
            .map(|value| (value, pos))
            .map_err(|message| self.error(pos, message))
    }
}

pub(super) fn point<C: fmt::Display>(x: C, y: C) -> String {
    format!("({x},{y})")
}

/// Checks one ring on its own (closed, axis-parallel, at least 4 corners, never turning back)
/// and returns its corners, with repeated and collinear vertices merged.
pub(super) fn ring_corners<C: Coordinate>(
    vertices: &[Vertex<C>],
    file: &str,
) -> Result<Vec<Corner<C>>> {
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
            (Ordering::Equal, Ordering::Equal) if C::REFUSE_REPEATS => {
                return Err(error(
                    b.pos,
                    format!(
                        "zero-length edge: vertex {} repeats the vertex before it; expected \
                         consecutive vertices to differ",
                        point(b.x, b.y)
                    ),
                ));
            }
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
    let mut corners: Vec<Corner<C>> = Vec::new();
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
