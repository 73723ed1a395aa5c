//! Feasibility first (the proof of Corollary 4 of *Lawn mowing and milling*): can the unit
//! square cutter mill the polygon at all? The erosion B of P (the centre positions whose square
//! lies in P), whether the squares centred in B make up P, whether one connected piece of B
//! does, and the contour δB of that piece.
//!
//! # The face grid
//!
//! Whether the square centred at c lies in P changes only where a side of the square meets a
//! line through an edge of P, that is where cx or cy is a coordinate of P plus or minus ½. The
//! lines x = x' ± ½, y = y' ± ½ (inside P's bounding box shrunk by ½) cut the plane into faces:
//! grid points, open segments between them and open cells; on each face the answer is the
//! same, so B is a union of faces, exactly computed from one representative point each. We
//! number the faces of one axis 0, 1, 2, ...: face 2k is the line through the k-th coordinate,
//! face 2k + 1 the open interval after it (the "doubled" index), and store B as runs of
//! consecutive faces along each doubled row. B is closed, so a face of B brings its boundary
//! along; pieces of B are then the 4-connected groups of faces, and the boundary of the faces,
//! collapsed back onto the lines, is δB (a degenerate piece, a segment or a point, gets a walk
//! along it and back, or a single point).

use super::cover::{Rect, compare};
use super::polygon::{Point, Polygon};
use super::rational::Rational;
use super::tour::Tour;
use petgraph::unionfind::UnionFind;
use std::collections::HashMap;
use std::fmt;

/// Why a polygon cannot be milled by a tour of the unit square cutter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Infeasible {
    /// The cutter fits nowhere inside the polygon: every part of it is narrower than 1.
    /// `point` is a point of the polygon.
    NoRoom { point: Point },
    /// No position of the cutter inside the polygon covers `point`: a feature narrower than
    /// the cutter (a thin spike, a corner pocket) that can only be milled by leaving the
    /// polygon.
    Uncoverable { point: Point },
    /// The squares centred in the erosion cover the polygon, but the centre positions fall
    /// into `pieces` pieces that no motion inside the polygon joins (a neck narrower than the
    /// cutter), and no single piece covers the polygon: the piece containing `from` misses
    /// `point`, which the piece containing `to` covers.
    Disconnected {
        pieces: usize,
        from: Point,
        to: Point,
        point: Point,
    },
}

impl fmt::Display for Infeasible {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Infeasible::NoRoom { point } => write!(
                f,
                "the polygon cannot be milled: the unit square cutter fits nowhere inside it \
                 (every part is narrower than 1; for instance around {point})"
            ),
            Infeasible::Uncoverable { point } => write!(
                f,
                "the polygon cannot be milled: no position of the unit square cutter inside the \
                 polygon covers the point {point} (a feature narrower than the cutter)"
            ),
            Infeasible::Disconnected {
                pieces,
                from,
                to,
                point,
            } => write!(
                f,
                "the polygon cannot be milled by one tour: the cutter's centre positions fall \
                 into {pieces} pieces that no motion inside the polygon joins (a neck narrower \
                 than the cutter); the piece containing {from} cannot mill {point}, which the \
                 piece containing {to} mills"
            ),
        }
    }
}

impl std::error::Error for Infeasible {}

/// A run of faces `start..end` (doubled indices) of one doubled row.
type Run = (u32, u32);

/// The piece of the erosion a tour of the cutter's centre can use: a connected set of centre
/// positions whose squares lie in the polygon and together make up all of it.
///
/// When the erosion has several pieces and one of them alone mills the polygon, that one is
/// kept (the squares of the others add nothing); [`pieces`](Erosion::pieces) says how many
/// there were.
#[derive(Clone, Debug)]
pub struct Erosion {
    /// The lines x = x' ± ½ that bound faces, sorted.
    xs: Vec<Rational>,
    ys: Vec<Rational>,
    /// Runs of faces per doubled row (row r: the line through ys[r / 2] for even r, the open
    /// interval above it for odd r).
    rows: Vec<Vec<Run>>,
    contour: Vec<Vec<Point>>,
    pieces: usize,
}

impl Erosion {
    /// Whether the square centred at `p` lies in the polygon (and `p` in this piece).
    pub fn contains(&self, p: Point) -> bool {
        let (Some(r), Some(a)) = (face(&self.ys, p.y), face(&self.xs, p.x)) else {
            return false;
        };
        let runs = &self.rows[r];
        let a = a as u32;
        let k = runs.partition_point(|&(_, end)| end <= a);
        runs.get(k).is_some_and(|&(start, _)| start <= a)
    }

    /// The piece as closed axis-parallel boxes (lower-left and upper-right corners; a box may
    /// be a segment or a point) whose union it is.
    pub fn rectangles(&self) -> Vec<(Point, Point)> {
        let mut boxes = Vec::new();
        for (r, runs) in self.rows.iter().enumerate() {
            let (y0, y1) = (self.ys[r / 2], self.ys[r.div_ceil(2)]);
            for &(start, end) in runs {
                let (x0, x1) = (self.xs[start as usize / 2], self.xs[end as usize / 2]);
                boxes.push((Point::new(x0, y0), Point::new(x1, y1)));
            }
        }
        boxes
    }

    /// δB: the boundary of the piece as closed rectilinear walks of the cutter's centre, one
    /// per boundary component (outer boundaries counter-clockwise, holes clockwise), each from
    /// its lowest, then leftmost, corner; collinear points dropped. A part of zero width is
    /// walked along and back, an isolated point is a walk of one point.
    pub fn contour(&self) -> &[Vec<Point>] {
        &self.contour
    }

    /// The contour as a cycle cover of the cutter's centre, for [`check`](super::check).
    pub fn contour_tour(&self) -> Tour {
        Tour {
            cycles: self.contour.clone(),
        }
    }

    /// How many pieces the whole erosion has (1 when it is connected).
    pub fn pieces(&self) -> usize {
        self.pieces
    }
}

/// The doubled index of the face of sorted `lines` containing `v`: 2k on line k, 2k + 1
/// strictly between lines k and k + 1, `None` outside.
fn face(lines: &[Rational], v: Rational) -> Option<usize> {
    let k = lines.partition_point(|&l| l < v);
    if lines.get(k) == Some(&v) {
        Some(2 * k)
    } else if k == 0 || k == lines.len() {
        None
    } else {
        Some(2 * k - 1)
    }
}

/// The coordinates c ± ½ of `coords` that lie in [first + ½, last - ½], sorted.
fn shifted_lines(coords: &[Rational]) -> Vec<Rational> {
    let (Some(&first), Some(&last)) = (coords.first(), coords.last()) else {
        return Vec::new();
    };
    let half = |v: Rational, up: bool| {
        if up {
            v.checked_add(Rational::HALF)
        } else {
            v.checked_sub(Rational::HALF)
        }
        .expect("a coordinate within the input limits plus a half fits")
    };
    let (lo, hi) = (half(first, true), half(last, false));
    let mut lines: Vec<Rational> = coords
        .iter()
        .flat_map(|&c| [half(c, false), half(c, true)])
        .filter(|&v| lo <= v && v <= hi)
        .collect();
    lines.sort_unstable();
    lines.dedup();
    lines
}

/// A representative coordinate of face `f` (doubled index) of `lines`.
fn representative(lines: &[Rational], f: usize) -> Rational {
    if f.is_multiple_of(2) {
        lines[f / 2]
    } else {
        lines[f / 2]
            .midpoint(lines[f / 2 + 1])
            .expect("midpoints of coordinates within the input limits fit")
    }
}

/// Decides whether the unit square cutter can mill `polygon` with one closed tour, and returns
/// the piece of the erosion such a tour uses.
///
/// # Returns
///
/// The [`Erosion`] when some connected set of centre positions has squares inside the polygon
/// that together cover it; otherwise why not ([`Infeasible`]), with a witness point: a point
/// no square inside the polygon covers, or a point one piece of the erosion cannot reach.
///
/// A tour exists exactly then: the tour's centre stays in one piece (it is connected, and
/// every square it sweeps lies in the polygon), and conversely a piece is a finite union of
/// closed boxes, which a closed rectilinear walk can sweep whole (back and forth along each
/// box, joined inside the piece).
///
/// # Complexity
///
/// O(X·Y + R log R) time and O(X·Y) space for X distinct x and Y distinct y coordinates of
/// the polygon and R runs of faces (R = O(X·Y), usually O(X + Y)).
///
/// # Examples
///
/// ```
/// use mowmill_core::ortho::{Polygon, feasibility};
///
/// // A 4 × 1.5 sliver: centres on the 3 × 0.5 box [0.5, 3.5] × [0.5, 1].
/// let sliver = Polygon::parse("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))", "s.wkt")?;
/// let b = feasibility(&sliver).expect("millable");
/// assert_eq!(b.contour()[0].len(), 4);
///
/// // Two unit squares sharing half an edge: each can be milled, but not both by one tour.
/// let pair = Polygon::parse(
///     "POLYGON ((0 0, 1 0, 1 0.5, 2 0.5, 2 1.5, 1 1.5, 1 1, 0 1, 0 0))",
///     "pair.wkt",
/// )?;
/// let e = feasibility(&pair).unwrap_err();
/// assert!(e.to_string().contains("fall into 2 pieces"), "{e}");
/// # Ok::<(), mowmill_core::Error>(())
/// ```
// The error carries three witness points; it is made once per polygon, never in a loop.
#[allow(clippy::result_large_err)]
pub fn feasibility(polygon: &Polygon) -> Result<Erosion, Infeasible> {
    let edges = polygon.vertical_edges();
    let Faces { xs, ys, rows } = faces(polygon);
    let run_box = |r: usize, (start, end): Run| {
        let (y0, y1) = (ys[r / 2], ys[r.div_ceil(2)]);
        let (x0, x1) = (xs[start as usize / 2], xs[end as usize / 2]);
        (x0, x1, y0, y1)
    };
    let runs: Vec<(usize, Run)> = rows
        .iter()
        .enumerate()
        .flat_map(|(r, runs)| runs.iter().map(move |&run| (r, run)))
        .collect();
    let swept: Vec<Rect> = runs
        .iter()
        .map(|&(r, run)| {
            let (x0, x1, y0, y1) = run_box(r, run);
            Rect::swept(x0, x1, y0, y1).expect("coordinates within the input limits fit")
        })
        .collect();
    if runs.is_empty() {
        let point = compare(&edges, &[])
            .uncovered
            .expect("a valid polygon has a cell of positive area");
        return Err(Infeasible::NoRoom { point });
    }
    if let Some(point) = compare(&edges, &swept).uncovered {
        return Err(Infeasible::Uncoverable { point });
    }
    let (label, pieces) = run_components(&rows);
    let label = &label;
    let members = |piece: usize| (0..runs.len()).filter(move |&k| label[k] == piece);
    let mut first_miss = None;
    for piece in 0..pieces {
        let rects: Vec<Rect> = members(piece).map(|k| swept[k]).collect();
        match compare(&edges, &rects).uncovered {
            None => {
                let mut kept: Vec<Vec<Run>> = vec![Vec::new(); rows.len()];
                for k in members(piece) {
                    kept[runs[k].0].push(runs[k].1);
                }
                let contour = contour(&kept, &xs, &ys);
                return Ok(Erosion {
                    xs,
                    ys,
                    rows: kept,
                    contour,
                    pieces,
                });
            }
            Some(point) => {
                first_miss.get_or_insert(point);
            }
        }
    }
    // Piece 0 misses `point`; some other piece's squares cover it (the union does).
    let point = first_miss.expect("there is at least one piece");
    let corner = |k: usize| {
        let (x0, _, y0, _) = run_box(runs[k].0, runs[k].1);
        Point::new(x0, y0)
    };
    let from = corner(members(0).next().expect("piece 0 has a run"));
    let k = (0..runs.len())
        .find(|&k| label[k] != 0 && swept[k].contains_inside(point))
        .expect("the union of all pieces covers every point");
    let (x0, x1, y0, y1) = run_box(runs[k].0, runs[k].1);
    // The centre of that run nearest to `point`: within ½ of it, so its square mills it.
    let to = Point::new(point.x.clamp(x0, x1), point.y.clamp(y0, y1));
    Err(Infeasible::Disconnected {
        pieces,
        from,
        to,
        point,
    })
}

/// The whole erosion, every piece (an [`Erosion`] keeps only the piece that mills): the face
/// lines x and y and, per doubled row, the maximal runs `start..end` of doubled x faces in B.
/// For bounds over cycle covers, whose walks may use any piece.
pub(crate) fn face_grid(polygon: &Polygon) -> Faces {
    faces(polygon)
}

/// The whole erosion (all pieces): the face lines and the runs of faces per doubled row.
pub(crate) struct Faces {
    pub(crate) xs: Vec<Rational>,
    pub(crate) ys: Vec<Rational>,
    pub(crate) rows: Vec<Vec<Run>>,
}

fn faces(polygon: &Polygon) -> Faces {
    let (pxs, pys) = polygon.coordinates();
    let (xs, ys) = (shifted_lines(&pxs), shifted_lines(&pys));
    let rows = if xs.is_empty() || ys.is_empty() {
        Vec::new()
    } else {
        face_runs(polygon, &pxs, &pys, &xs, &ys)
    };
    Faces { xs, ys, rows }
}

/// The integer pixels inside the polygon: pixel (x, y), the unit square [x, x+1] × [y, y+1],
/// belongs when it lies in the polygon, that is when its centre lies in the erosion. This is
/// R_N of Corollary 4's proof ("the union of all integer pixels"), the part milled by a tour
/// of the pixel grid graph; for an integral polygon it is the region itself.
///
/// The pixels come from every piece of the erosion; a tour can only use those whose centre
/// lies in the piece [`feasibility`] returns ([`Erosion::contains`]).
///
/// # Returns
///
/// The region (possibly empty), or [`Error::Invalid`](crate::Error) when it would have more
/// than [`MAX_PIXELS`](crate::region::MAX_PIXELS) pixels (counted before any is made).
///
/// # Complexity
///
/// As [`feasibility`]'s erosion, plus O(N) for N pixels.
///
/// # Examples
///
/// ```
/// use mowmill_core::ortho::{Polygon, interior_pixels};
///
/// // [0.5, 3] × [0.5, 3.25] holds the pixels with x and y in 1..=2.
/// let p = Polygon::parse("POLYGON ((0.5 0.5, 3 0.5, 3 3.25, 0.5 3.25, 0.5 0.5))", "p.wkt")?;
/// assert_eq!(interior_pixels(&p)?.to_ascii(), "##\n##\n");
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn interior_pixels(polygon: &Polygon) -> crate::Result<crate::Region> {
    use crate::region::{MAX_PIXELS, Pixel, Region};
    let Faces { xs, ys, rows } = faces(polygon);
    let (Some(&bottom), Some(&top)) = (ys.first(), ys.last()) else {
        return Region::from_pixels([]);
    };
    let centre_range = |lo: Rational, hi: Rational| {
        // Integers k with k + ½ in [lo, hi].
        let shift = |v: Rational| {
            v.checked_sub(Rational::HALF)
                .expect("coordinates within the input limits fit")
        };
        (shift(lo).ceil(), shift(hi).floor())
    };
    let (y_first, y_last) = centre_range(bottom, top);
    // Pixel rows and their runs of columns, counted before any pixel is made.
    let mut spans: Vec<(i128, i128, i128)> = Vec::new();
    let mut count: u128 = 0;
    for y in y_first..=y_last {
        let centre = Rational::new(2 * y + 1, 2).expect("a pixel centre is a rational");
        let Some(r) = face(&ys, centre) else {
            continue;
        };
        for &(start, end) in &rows[r] {
            let (x0, x1) = centre_range(xs[start as usize / 2], xs[end as usize / 2]);
            if x0 <= x1 {
                spans.push((y, x0, x1));
                count += (x1 - x0 + 1) as u128;
            }
        }
    }
    if count > MAX_PIXELS as u128 {
        return Err(crate::Error::invalid(format!(
            "the polygon holds {count} integer pixels; expected at most {MAX_PIXELS} (the pixel \
             limit)"
        )));
    }
    // Coordinates are at most 2^31 in magnitude, so every pixel inside has i32 coordinates.
    Region::from_pixels(
        spans
            .into_iter()
            .flat_map(|(y, x0, x1)| (x0..=x1).map(move |x| Pixel::new(x as i32, y as i32))),
    )
}

/// R_N of the kept piece: the integer pixels inside `polygon` whose centre lies in `erosion`
/// (the pixels a tour in that piece can use; Corollary 4's and Theorem 5.7's interior).
pub fn kept_interior_pixels(polygon: &Polygon, erosion: &Erosion) -> crate::Result<crate::Region> {
    crate::Region::from_pixels(
        interior_pixels(polygon)?
            .pixels()
            .iter()
            .copied()
            .filter(|p| erosion.contains(Point::pixel_centre(p.x, p.y))),
    )
}

/// The faces of the erosion, as runs per doubled row: a sweep upward over the doubled rows,
/// keeping for each column of the polygon's cell grid how many of its cells in the band of
/// rows the cutter's square spans lie outside the polygon.
fn face_runs(
    polygon: &Polygon,
    pxs: &[Rational],
    pys: &[Rational],
    xs: &[Rational],
    ys: &[Rational],
) -> Vec<Vec<Run>> {
    let (columns, cell_rows) = (pxs.len() - 1, pys.len() - 1);
    // inside[j * columns + i]: cell (i, j) = (pxs[i], pxs[i+1]) × (pys[j], pys[j+1]) lies in
    // the polygon: an odd number of vertical edges to its left.
    // Mark each edge at the cell to its right, then take running parities along each row.
    let mut inside = vec![false; columns * cell_rows];
    for e in polygon.vertical_edges() {
        let i = pxs.partition_point(|&v| v < e.x);
        if i == columns {
            continue; // the rightmost edges have no cell to their right
        }
        let (j0, j1) = (
            pys.partition_point(|&v| v < e.y0),
            pys.partition_point(|&v| v < e.y1),
        );
        for j in j0..j1 {
            inside[j * columns + i] ^= true;
        }
    }
    for row in inside.chunks_mut(columns) {
        let mut parity = false;
        for cell in row {
            parity ^= *cell;
            *cell = parity;
        }
    }
    let half = |v: Rational, up: bool| {
        if up {
            v.checked_add(Rational::HALF)
        } else {
            v.checked_sub(Rational::HALF)
        }
        .expect("coordinates within the input limits fit")
    };
    let mut blocked = vec![0u32; columns];
    // The band of cell rows lo..hi (exclusive) that the current square's interior meets.
    let (mut lo, mut hi) = (0usize, 0usize);
    let mut rows = Vec::with_capacity(2 * ys.len() - 1);
    for r in 0..2 * ys.len() - 1 {
        let cy = representative(ys, r);
        let (bottom, top) = (half(cy, false), half(cy, true));
        // Rows j with pys[j + 1] > bottom and pys[j] < top.
        let new_lo = pys.partition_point(|&v| v <= bottom) - 1;
        let new_hi = pys.partition_point(|&v| v < top);
        let add = |j: usize, delta: i32, blocked: &mut [u32]| {
            for (i, b) in blocked.iter_mut().enumerate() {
                if !inside[j * columns + i] {
                    *b = b.wrapping_add_signed(delta);
                }
            }
        };
        for j in hi..new_hi {
            add(j, 1, &mut blocked);
        }
        for j in lo..new_lo {
            add(j, -1, &mut blocked);
        }
        (lo, hi) = (new_lo, new_hi);
        // Maximal runs of free columns i0..=i1 give centres in [pxs[i0] + ½, pxs[i1+1] - ½].
        let mut runs = Vec::new();
        let mut i = 0;
        while i < columns {
            if blocked[i] > 0 {
                i += 1;
                continue;
            }
            let i0 = i;
            while i < columns && blocked[i] == 0 {
                i += 1;
            }
            let (left, right) = (half(pxs[i0], true), half(pxs[i], false));
            if left <= right {
                let p = xs.partition_point(|&v| v < left);
                let q = xs.partition_point(|&v| v < right);
                runs.push((2 * p as u32, 2 * q as u32 + 1));
            }
        }
        rows.push(runs);
    }
    rows
}

/// Pieces of the erosion: runs in consecutive doubled rows that overlap are 4-adjacent faces,
/// hence connected (B is closed). Labels in the order of the runs (row by row), numbered by
/// first run.
fn run_components(rows: &[Vec<Run>]) -> (Vec<usize>, usize) {
    let offsets: Vec<usize> = rows
        .iter()
        .scan(0, |total, runs| {
            let start = *total;
            *total += runs.len();
            Some(start)
        })
        .collect();
    let n = rows.iter().map(Vec::len).sum();
    let mut pieces = UnionFind::<usize>::new(n);
    for r in 1..rows.len() {
        let (below, above) = (&rows[r - 1], &rows[r]);
        let (mut a, mut b) = (0, 0);
        while a < below.len() && b < above.len() {
            let (s, t) = (below[a], above[b]);
            if s.0 < t.1 && t.0 < s.1 {
                pieces.union(offsets[r - 1] + a, offsets[r] + b);
            }
            if s.1 <= t.1 {
                a += 1;
            } else {
                b += 1;
            }
        }
    }
    let mut label = vec![usize::MAX; n];
    let mut count = 0;
    for k in 0..n {
        let r = pieces.find_mut(k);
        if label[r] == usize::MAX {
            label[r] = count;
            count += 1;
        }
        label[k] = label[r];
    }
    (label, count)
}

/// The parts of sorted disjoint runs `a` not covered by runs `b`.
fn minus(a: &[Run], b: &[Run]) -> Vec<Run> {
    let mut out = Vec::new();
    let mut k = 0;
    for &(mut start, end) in a {
        while k < b.len() && b[k].1 <= start {
            k += 1;
        }
        let mut j = k;
        while j < b.len() && b[j].0 < end {
            if b[j].0 > start {
                out.push((start, b[j].0));
            }
            start = start.max(b[j].1);
            j += 1;
        }
        if start < end {
            out.push((start, end));
        }
    }
    out
}

/// The boundary of the faces as closed walks, collapsed onto the face lines and simplified.
///
/// In the doubled lattice (face (a, r) is the unit square [a, a+1] × [r, r+1]) the boundary is
/// traced with the faces on the left: along a horizontal lattice line eastward where faces lie
/// above only, westward where below only; up the right end of each run, down its left end. A
/// closed set of faces never touches itself diagonally (two faces meeting at a lattice point
/// only would need the faces between them), so each lattice point has at most one boundary
/// edge leaving it and the walk is unambiguous. Lattice line k lies on face line k / 2.
fn contour(rows: &[Vec<Run>], xs: &[Rational], ys: &[Rational]) -> Vec<Vec<Point>> {
    type Lattice = (u32, u32);
    let mut edges: Vec<(Lattice, Lattice)> = Vec::new();
    let empty = Vec::new();
    for r in 0..=rows.len() {
        let below = if r == 0 { &empty } else { &rows[r - 1] };
        let above = rows.get(r).unwrap_or(&empty);
        let y = r as u32;
        for (a, b) in minus(above, below) {
            edges.push(((a, y), (b, y)));
        }
        for (a, b) in minus(below, above) {
            edges.push(((b, y), (a, y)));
        }
        for &(start, end) in above {
            edges.push(((start, y + 1), (start, y)));
            edges.push(((end, y), (end, y + 1)));
        }
    }
    let leaving: HashMap<Lattice, usize> = edges
        .iter()
        .enumerate()
        .map(|(k, &(from, _))| (from, k))
        .collect();
    debug_assert_eq!(
        leaving.len(),
        edges.len(),
        "one boundary edge leaves each point"
    );
    let mut used = vec![false; edges.len()];
    let mut walks = Vec::new();
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        let mut walk = Vec::new();
        let mut k = first;
        while !used[k] {
            used[k] = true;
            let ((x, y), to) = edges[k];
            walk.push(Point::new(xs[x as usize / 2], ys[y as usize / 2]));
            k = leaving[&to];
        }
        walks.push(simplify(walk));
    }
    walks.sort_by_key(|w| w.first().map(|p| (p.y, p.x)));
    walks
}

/// A closed walk without repeated consecutive points or points where it goes straight on,
/// from its lowest, then leftmost, point; U-turns are kept.
pub(crate) fn simplify(mut walk: Vec<Point>) -> Vec<Point> {
    walk.dedup();
    while walk.len() > 1 && walk.first() == walk.last() {
        walk.pop();
    }
    let n = walk.len();
    if n > 2 {
        let straight = |k: usize| {
            let (a, b, c) = (walk[(k + n - 1) % n], walk[k], walk[(k + 1) % n]);
            (a.x == b.x && b.x == c.x && (a.y < b.y) == (b.y < c.y))
                || (a.y == b.y && b.y == c.y && (a.x < b.x) == (b.x < c.x))
        };
        let keep: Vec<bool> = (0..n).map(|k| !straight(k)).collect();
        walk = (0..n).filter(|&k| keep[k]).map(|k| walk[k]).collect();
    }
    if let Some(first) = (0..walk.len()).min_by_key(|&k| (walk[k].y, walk[k].x)) {
        walk.rotate_left(first);
    }
    walk
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ortho::check;

    fn polygon(text: &str) -> Polygon {
        Polygon::parse(text, "p.wkt").unwrap()
    }

    fn q(text: &str) -> Rational {
        Rational::parse_coordinate(text).unwrap()
    }

    fn pt(x: &str, y: &str) -> Point {
        Point::new(q(x), q(y))
    }

    fn contour_text(b: &Erosion) -> Vec<String> {
        b.contour()
            .iter()
            .map(|w| {
                w.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect()
    }

    #[test]
    fn sliver_of_width_one_and_a_half() {
        let b = feasibility(&polygon("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))")).unwrap();
        assert_eq!(
            contour_text(&b),
            vec!["(0.5, 0.5) (3.5, 0.5) (3.5, 1) (0.5, 1)"]
        );
        assert_eq!(b.pieces(), 1);
        assert!(b.contains(pt("2", "0.75")) && b.contains(pt("0.5", "1")));
        assert!(!b.contains(pt("0.25", "0.75")) && !b.contains(pt("2", "1.01")));
        assert_eq!(b.rectangles().len(), 3);
        // The contour mills the sliver: it is the optimal tour here.
        let r = check(
            &polygon("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))"),
            &b.contour_tour(),
        );
        assert!(r.unwrap().valid);
    }

    #[test]
    fn unit_wide_corridors_erode_to_segments() {
        // An L of width 1: the erosion is the L's centre line, walked there and back.
        let l = polygon("POLYGON ((0 0, 3 0, 3 1, 1 1, 1 2.5, 0 2.5, 0 0))");
        let b = feasibility(&l).unwrap();
        assert_eq!(
            contour_text(&b),
            vec!["(0.5, 0.5) (2.5, 0.5) (0.5, 0.5) (0.5, 2)"]
        );
        let r = check(&l, &b.contour_tour()).unwrap();
        assert!(r.valid, "{:?}", r.error);
        assert_eq!((r.length.to_string(), r.turns), ("7".to_string(), 6));
        // A unit square: a single point.
        let b = feasibility(&polygon("POLYGON ((2 2, 3 2, 3 3, 2 3, 2 2))")).unwrap();
        assert_eq!(contour_text(&b), vec!["(2.5, 2.5)"]);
    }

    #[test]
    fn a_neck_narrower_than_the_cutter_cannot_be_milled() {
        // Two unit squares joined by a corridor 0.5 high: no square inside covers the corridor.
        let neck = polygon(
            "POLYGON ((0 0, 1 0, 1 0.25, 2 0.25, 2 0, 3 0, 3 1, 2 1, 2 0.75, 1 0.75, 1 1, 0 1, \
             0 0))",
        );
        assert_eq!(
            feasibility(&neck).unwrap_err(),
            Infeasible::Uncoverable {
                point: pt("1.5", "0.5")
            }
        );
    }

    #[test]
    fn a_neck_of_length_zero_splits_the_erosion() {
        // Two 2 × 2 squares sharing the segment x = 2, 1.5 <= y <= 2: each is millable, the
        // squares of both make up the polygon, but the cutter cannot pass from one to the other.
        let pair = polygon("POLYGON ((0 0, 2 0, 2 1.5, 4 1.5, 4 3.5, 2 3.5, 2 2, 0 2, 0 0))");
        let e = feasibility(&pair).unwrap_err();
        assert_eq!(
            e,
            Infeasible::Disconnected {
                pieces: 2,
                from: pt("0.5", "0.5"),
                to: pt("3", "2"),
                point: pt("3", "1.75"),
            }
        );
        assert_eq!(
            e.to_string(),
            "the polygon cannot be milled by one tour: the cutter's centre positions fall into 2 \
             pieces that no motion inside the polygon joins (a neck narrower than the cutter); \
             the piece containing (0.5, 0.5) cannot mill (3, 1.75), which the piece \
             containing (3, 2) mills"
        );
        // Each half alone is a square, millable.
        let half = polygon("POLYGON ((2 1.5, 4 1.5, 4 3.5, 2 3.5, 2 1.5))");
        assert_eq!(feasibility(&half).unwrap().contour()[0].len(), 4);
    }

    #[test]
    fn a_frame_erodes_to_a_frame() {
        // A 4 × 4 square with a centred unit hole: the erosion is [0.5, 3.5]² less the open
        // square (1, 3)², a frame of width 0.5 with an outer and an inner contour, which
        // together mill the polygon.
        let frame = polygon(
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1.5 1.5, 1.5 2.5, 2.5 2.5, 2.5 1.5, 1.5 1.5))",
        );
        let b = feasibility(&frame).unwrap();
        assert_eq!(b.pieces(), 1);
        let r = check(&frame, &b.contour_tour()).unwrap();
        assert_eq!(
            contour_text(&b),
            vec![
                "(0.5, 0.5) (3.5, 0.5) (3.5, 3.5) (0.5, 3.5)",
                "(1, 1) (1, 3) (3, 3) (3, 1)"
            ]
        );
        assert!(r.valid, "{:?}", r.error);
    }

    #[test]
    fn interior_pixels_are_the_unit_squares_inside() {
        let frame = polygon(
            "POLYGON ((-0.5 0, 4.25 0, 4.25 3, -0.5 3, -0.5 0), (1 1, 1 2, 2.5 2, 2.5 1, 1 1))",
        );
        assert_eq!(
            interior_pixels(&frame).unwrap(),
            Region::from_pixels(
                [
                    (0, 0),
                    (1, 0),
                    (2, 0),
                    (3, 0),
                    (0, 1),
                    (3, 1),
                    (0, 2),
                    (1, 2),
                    (2, 2),
                    (3, 2)
                ]
                .map(|(x, y)| Pixel::new(x, y))
            )
            .unwrap()
        );
        // Too thin for any pixel.
        let thin = polygon("POLYGON ((0.5 0, 1.5 0, 1.5 3, 0.5 3, 0.5 0))");
        assert!(interior_pixels(&thin).unwrap().is_empty());
        let huge = polygon("POLYGON ((0 0, 100000 0, 100000 100000, 0 100000, 0 0))");
        let e = interior_pixels(&huge).unwrap_err().to_string();
        assert!(e.contains("10000000000 integer pixels"), "{e}");
    }

    #[test]
    fn features_narrower_than_the_cutter_are_refused() {
        // A 3 × 3 square with a spike 0.5 wide.
        let spike = polygon("POLYGON ((0 0, 3 0, 3 3, 1.75 3, 1.75 4, 1.25 4, 1.25 3, 0 3, 0 0))");
        let e = feasibility(&spike).unwrap_err();
        assert_eq!(
            e,
            Infeasible::Uncoverable {
                point: pt("1.5", "3.5")
            }
        );
        assert!(e.to_string().contains("covers the point (1.5, 3.5)"), "{e}");
        // Too thin everywhere.
        let thin = polygon("POLYGON ((0 0, 5 0, 5 0.9, 0 0.9, 0 0))");
        assert!(matches!(feasibility(&thin), Err(Infeasible::NoRoom { .. })));
        let e = feasibility(&thin).unwrap_err().to_string();
        assert!(e.contains("fits nowhere"), "{e}");
    }

    use crate::region::{Pixel, Region};
    use proptest::prelude::*;

    /// The polygon of `region` shrunk 4 times: pixel (x, y) becomes [x/4, (x+1)/4] × [y/4, (y+1)/4].
    fn quarter_polygon(region: &Region) -> Polygon {
        let wkt = crate::wkt::to_wkt(region);
        let mut scaled = String::new();
        let mut number = String::new();
        for c in wkt.chars().chain(std::iter::once(' ')) {
            if c.is_ascii_digit() || c == '-' {
                number.push(c);
                continue;
            }
            if !number.is_empty() {
                scaled.push_str(&format!("{number}/4"));
                number.clear();
            }
            scaled.push(c);
        }
        Polygon::parse(scaled.trim_end(), "quarters").unwrap()
    }

    /// Brute force on eighths: every face of the erosion of a polygon with coordinates in
    /// quarters has a point with coordinates in eighths (faces lie between the lines of
    /// quarters), the squares centred at those points of the erosion cover what the whole
    /// erosion covers, and two such points 1/8 apart in the erosion are joined inside it.
    fn brute_force(region: &Region, side: i32) -> Brute {
        // Eighth-cell (u, v) is [u/8, (u+1)/8] × [v/8, (v+1)/8].
        let inside = |u: i32, v: i32| region.contains(Pixel::new(u.div_euclid(2), v.div_euclid(2)));
        let n = (8 * side / 4 + 1) as usize; // centres k/8 for k in 0..n
        // The square centred at (a/8, b/8) spans eighth-cells a - 4 ..= a + 3.
        let fits = |a: i32, b: i32| (a - 4..a + 4).all(|u| (b - 4..b + 4).all(|v| inside(u, v)));
        let e: Vec<Vec<bool>> = (0..n as i32)
            .map(|a| (0..n as i32).map(|b| fits(a, b)).collect())
            .collect();
        let mut label = vec![vec![usize::MAX; n]; n];
        let mut pieces = 0;
        for a in 0..n {
            for b in 0..n {
                if !e[a][b] || label[a][b] != usize::MAX {
                    continue;
                }
                let mut stack = vec![(a, b)];
                label[a][b] = pieces;
                while let Some((x, y)) = stack.pop() {
                    for (dx, dy) in [(1i32, 0i32), (-1, 0), (0, 1), (0, -1)] {
                        let (u, v) = (x as i32 + dx, y as i32 + dy);
                        if u < 0 || v < 0 || u >= n as i32 || v >= n as i32 {
                            continue;
                        }
                        let (u, v) = (u as usize, v as usize);
                        if e[u][v] && label[u][v] == usize::MAX {
                            label[u][v] = pieces;
                            stack.push((u, v));
                        }
                    }
                }
                pieces += 1;
            }
        }
        // Which pieces cover every eighth-cell of the polygon.
        let covers: Vec<bool> = (0..pieces)
            .map(|piece| {
                (0..2 * side).all(|u| {
                    (0..2 * side).all(|v| {
                        !inside(u, v)
                            || (0..n).any(|a| {
                                (0..n).any(|b| {
                                    label[a][b] == piece
                                        && (a as i32 - 4..a as i32 + 4).contains(&u)
                                        && (b as i32 - 4..b as i32 + 4).contains(&v)
                                })
                            })
                    })
                })
            })
            .collect();
        Brute {
            e,
            label,
            pieces,
            covers,
        }
    }

    /// The brute force's answer: erosion membership and piece label of each centre (a/8, b/8),
    /// the number of pieces, and which pieces' squares cover the polygon.
    struct Brute {
        e: Vec<Vec<bool>>,
        label: Vec<Vec<usize>>,
        pieces: usize,
        covers: Vec<bool>,
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]

        #[test]
        fn erosion_agrees_with_brute_force(
            boxes in proptest::collection::vec((0i32..12, 0i32..12, 3i32..12, 3i32..12), 1..5),
        ) {
            let side = 12; // quarters
            let pixels = boxes.iter().flat_map(|&(x, y, w, h)| {
                (x..(x + w).min(side)).flat_map(move |i| (y..(y + h).min(side)).map(move |j| Pixel::new(i, j)))
            });
            let region = Region::from_pixels(pixels).unwrap();
            let polygon = quarter_polygon(&region);
            let Brute { e, label, pieces, covers } = brute_force(&region, side);
            let result = feasibility(&polygon);
            let eighth = |k: usize| Rational::new(k as i128, 8).unwrap();
            match &result {
                Ok(b) => {
                    let kept = covers.iter().position(|&c| c);
                    prop_assert!(kept.is_some(), "feasible, but no piece covers");
                    prop_assert_eq!(b.pieces(), pieces);
                    for (a, column) in e.iter().enumerate() {
                        for (c, &member) in column.iter().enumerate() {
                            let p = Point::new(eighth(a), eighth(c));
                            prop_assert_eq!(b.contains(p), member && label[a][c] == kept.unwrap(), "at {}", p);
                        }
                    }
                    // The contour stays in the erosion: its sweep never leaves the polygon.
                    let r = check(&polygon, &b.contour_tour()).unwrap();
                    prop_assert_eq!(r.outside, None);
                }
                Err(Infeasible::NoRoom { .. }) => prop_assert_eq!(pieces, 0),
                Err(Infeasible::Uncoverable { point }) => {
                    prop_assert!(pieces > 0);
                    prop_assert!(!covers.iter().any(|&c| c));
                    // No square of the erosion covers the witness.
                    for (a, column) in e.iter().enumerate() {
                        for (c, &member) in column.iter().enumerate() {
                            if member {
                                let near = (point.x.checked_sub(eighth(a)).unwrap().abs() < Rational::HALF)
                                    && (point.y.checked_sub(eighth(c)).unwrap().abs() < Rational::HALF);
                                prop_assert!(!near, "{} covers {}", Point::new(eighth(a), eighth(c)), point);
                            }
                        }
                    }
                }
                Err(Infeasible::Disconnected { pieces: k, from, to, .. }) => {
                    prop_assert_eq!(*k, pieces);
                    prop_assert!(pieces > 1 && !covers.iter().any(|&c| c));
                    let at = |p: &Point| {
                        let (a, c) = ((p.x.numer() * 8 / p.x.denom()) as usize, (p.y.numer() * 8 / p.y.denom()) as usize);
                        label[a][c]
                    };
                    prop_assert_ne!(at(from), at(to));
                }
            }
        }
    }
}
