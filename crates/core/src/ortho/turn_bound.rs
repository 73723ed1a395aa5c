//! A proven lower bound on the turns of every milling of an orthogonal polygon with arbitrary
//! coordinates: the turns forced at convex corners, and pairwise independent witness points
//! ("rooks", Lemma 4.3 of *Optimal covering tours with turn costs*, read for a continuous
//! cutter). Both bound every **cycle cover** (a set of closed walks), so also every tour.
//!
//! Turns are counted as [`check`](super::check) counts them: 1 for 90°, 2 for a reversal, 4 for
//! a walk that never moves.
//!
//! # What a milling gives
//!
//! Let the walks of a cycle cover mill P. Every swept box lies in P, so every centre position
//! on every walk lies in B, the erosion (every piece of it: a cycle cover may use several, so
//! the rook test below uses all of B, not only the piece an [`Erosion`] keeps). The swept area
//! is a finite union of closed boxes equal to P up to measure zero; it is closed and P is the
//! closure of its interior, so it contains every point of P.
//!
//! # Every walk turns at least 4 times
//!
//! A walk that never moves counts 4. A walk that moves splits cyclically into k links (maximal
//! straight parts; consecutive links, the last and the first included, have different
//! headings), and each change of heading costs at least 1, so it turns at least k times. k = 1
//! cannot close; for k = 2 the second link reverses the first, two reversals, 4 turns; k = 3 is
//! impossible: along each axis the walk moves both ways or not at all, so with one axis the
//! headings alternate around an odd cycle, and two axes need four headings. So
//! [`TurnBound::best`] is at least 4 (a polygon has positive area, so a milling has a walk).
//!
//! *Every walk turns an even number of times:* the axis of the heading changes exactly at the
//! 90° turns, and it is the same after going round, so those are even in number; a reversal
//! costs 2 and a point walk 4. So any lower bound on a cycle cover's turns rounds up to even.
//!
//! # Forced convex corners
//!
//! Let v be a corner of any ring, and look at the four open cells of the grid of P's
//! coordinates that have v as a corner. No edge of P crosses a cell, so each lies inside or
//! outside P (decided exactly by the even–odd rule at its centre). Quadrant q = (s_x, s_y) is
//! **isolated** at v when its cell is in P and the two cells sharing a side with it,
//! (−s_x, s_y) and (s_x, −s_y), are not: a convex corner of an outer ring or of a hole,
//! wherever the rings touch (two rings pinching at v give two isolated quadrants). Let
//! c = v + ½(s_x, s_y) and δ > 0 smaller than ½ and than every side of the four cells.
//!
//! (a) *Near c, B lies in the closed quadrant s_x(x − c_x) ≥ 0, s_y(y − c_y) ≥ 0.* Take a
//! centre c′ with |c′ − c|∞ < δ and s_x(c′_x − c_x) < 0. Its square reaches across the line
//! x = v_x, and its heights [c′_y − ½, c′_y + ½] contain heights within δ of v_y on the s_y side;
//! so it contains points of the open cell (−s_x, s_y), outside P: c′ ∉ B. Likewise in y.
//!
//! (b) *Every milling passes through c.* The points w = v + ε(s_x, s_y), 0 < ε < δ, lie in P,
//! so each lies in the square of some centre c′ on a walk. By the argument of (a), with w's
//! height in place of c′'s, s_x(c′_x − c_x) ≥ 0, and |c′_x − w_x| ≤ ½ gives
//! s_x(c′_x − c_x) ≤ ε; likewise in y. The walks have finitely many moves, each a closed
//! segment, so one of them has such centres for arbitrarily small ε: it contains c.
//!
//! (c) *What is forced at c.* By (a), c is not inside a move (the move would leave the
//! quadrant on one side), so a walk through c either never moves (4 turns) or arrives at c
//! from a direction d and leaves in a direction d′, both allowed by (a): the turn at c costs
//! cost(−d → d′) ≥ 1. Several isolated quadrants (of one or several corners) can share one c;
//! each forbids its two directions, and all hold at once. We count at c the minimum over the
//! allowed d, d′ (4 when none is allowed): 1 when one x and one y direction remain (a convex
//! corner), 2 when one direction remains (a dead end of width exactly 1: a U-turn), 4 when none
//! does (a unit square: a point walk). The turns at distinct points c happen at distinct visits
//! of the walks, so `convex_corners` = Σ_c (turns forced at c) is a lower bound.
//!
//! # Rooks
//!
//! Every point p ∈ P lies in the box of some move, hence in the **band** s ⊕ [−½, ½]² of the
//! link s containing that move (a point walk: the square of its point, a link of length 0).
//! A link is an axis-parallel segment in B. Call p, q **independent** when no axis-parallel
//! segment in B has a band containing both. Pairwise independent points need pairwise
//! distinct links, and a walk has at least as many turns as links (4 ≥ 1 for a point walk),
//! so `rooks`, the size of such a set, is a lower bound.
//!
//! *The exact test.* A horizontal segment [a, b] × {y} has a band containing p and q iff
//! |y − p_y| ≤ ½, |y − q_y| ≤ ½, a ≤ L = min(p_x, q_x) + ½ and b ≥ R = max(p_x, q_x) − ½.
//! Segments in B only shrink to segments in B, so for L ≤ R it is enough to ask whether
//! [L, R] × {y} ⊆ B for some y ∈ [max(p_y, q_y) − ½, min(p_y, q_y) + ½], and for L > R
//! whether some point of B has x ∈ [R, L] and y in that interval. B is a union of faces of its
//! face grid (module `erosion`): membership is constant on each line and open interval of each
//! axis, and B's rows are maximal runs of faces. So the question is answered row by row over
//! the rows of faces meeting the y interval: one run must hold every face meeting [L, R] (or
//! some run must meet the faces meeting [R, L]). Vertical segments use the transposed grid.
//! The same test with p = q decides p ∈ P (for a millable P, the squares of B make up P).
//!
//! *Choice of points.* The bound holds for any independent set; we pick one greedily (least
//! attacked candidate first, minimum degree in the attack graph). Candidates are the points of
//! P on a grid whose lines along each axis are P's coordinates c, c ± ½, c ± 1, the midpoints
//! between consecutive ones, and a fill at spacing ¼ in the gaps between them. At most
//! `MAX_CANDIDATES` (1000) are tried: when there are more, the fill is dropped, then the midpoints,
//! and finally the first candidates in lexicographic (y, x) order are kept; fewer candidates
//! only weaken the bound, never invalidate it.
//!
//! # Complexity
//!
//! O(n·v) for the corners (v corners, n vertical edges), O(F) to transpose B's face grid (F
//! faces in B, O(X·Y) as for [`feasibility`](super::feasibility)), and O(C²·r) for the attack
//! graph of C ≤ `MAX_CANDIDATES` (1000) candidates (r: the face rows within a unit interval).

use super::erosion::{Erosion, Faces, face_grid};
use super::polygon::{Point, Polygon, VerticalEdge};
use super::rational::Rational;
use crate::error::{Error, Result};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// The most candidate witness points [`turn_lower_bound`] tries for rooks (module docs).
const MAX_CANDIDATES: usize = 1000;

/// Lower bounds on the turns of any cycle cover (hence any tour) milling a polygon, each proven
/// in the module docs.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct TurnBound {
    /// Σ over the points c(v) next to convex corners of the turns forced there (1 at a convex
    /// corner, 2 at a dead end of width 1, 4 at a unit square).
    pub convex_corners: u64,
    /// The size of a set of pairwise independent points of P (no link covers two).
    pub rooks: u64,
}

impl TurnBound {
    /// The best proven bound: the larger of the two, at least 4 (a closed walk turns at least 4
    /// times), rounded up to even (every closed walk turns an even number of times; module
    /// docs).
    pub fn best(&self) -> u64 {
        let best = self.convex_corners.max(self.rooks).max(4);
        best + best % 2
    }
}

/// Lower bounds on the turns of every cycle cover that mills `polygon`, whose erosion (from
/// [`feasibility`](super::feasibility)) is `erosion`.
///
/// # Arguments
///
/// `polygon`, and `erosion`, the kept piece of its erosion (proof that it is millable).
///
/// # Returns
///
/// The [`TurnBound`]; [`TurnBound::best`] is the bound to compare with.
///
/// # Errors
///
/// [`Error::Invalid`](crate::Error) when a point c(v) next to a convex corner is not in
/// `erosion`: then `erosion` is not the erosion of a millable `polygon` (every milling passes
/// through c(v)).
///
/// # Guarantee
///
/// Every cycle cover milling `polygon` has at least [`TurnBound::best`] turns, as counted by
/// [`check`](super::check): the proofs are in the module docs. The rook bound is the
/// continuous reading of Lemma 4.3 of *Optimal covering tours with turn costs* (rooks attack
/// along links of the cutter's centre inside B, not along grid rows).
///
/// # Complexity
///
/// Module docs.
///
/// # Examples
///
/// ```
/// use mowmill_core::ortho::{Polygon, feasibility, turn_lower_bound};
///
/// // A 4 × 1.5 sliver: its contour is a rectangle, 4 turns, and no milling does better.
/// let sliver = Polygon::parse("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))", "s.wkt")?;
/// let bound = turn_lower_bound(&sliver, &feasibility(&sliver).unwrap())?;
/// assert_eq!(bound.convex_corners, 4);
/// assert_eq!(bound.best(), 4);
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn turn_lower_bound(polygon: &Polygon, erosion: &Erosion) -> Result<TurnBound> {
    let convex_corners = forced_corner_turns(polygon, erosion)?;
    let Faces { xs, ys, rows } = face_grid(polygon);
    let horizontal = Lines {
        along: xs,
        across: ys,
        runs: rows,
    };
    let vertical = horizontal.transposed();
    let candidates = candidates(polygon, &horizontal);
    let rooks = rook_placement(&candidates, &horizontal, &vertical).len() as u64;
    Ok(TurnBound {
        convex_corners,
        rooks,
    })
}

fn add(a: Rational, b: Rational) -> Rational {
    a.checked_add(b)
        .expect("coordinates within the input limits plus one fit")
}

fn sub(a: Rational, b: Rational) -> Rational {
    a.checked_sub(b)
        .expect("coordinates within the input limits minus one fit")
}

fn mid(a: Rational, b: Rational) -> Rational {
    a.midpoint(b)
        .expect("midpoints of coordinates within the input limits fit")
}

/// The four headings E, N, W, S as unit steps; heading k + 2 (mod 4) is the opposite of k.
const HEADINGS: [(i8, i8); 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];

fn heading(step: (i8, i8)) -> usize {
    HEADINGS
        .iter()
        .position(|&h| h == step)
        .expect("a unit axis step")
}

/// The checker's cost of changing heading `a` into heading `b`.
fn turn(a: usize, b: usize) -> u64 {
    if a == b {
        0
    } else if (a + 2) % 4 == b {
        2
    } else {
        1
    }
}

/// The turns forced at a point a walk must visit and may enter and leave only through the
/// directions in `allowed` (bit k: heading k): arriving from direction d means heading −d.
fn forced_turns(allowed: u8) -> u64 {
    let dirs: Vec<usize> = (0..4).filter(|&k| allowed & (1 << k) != 0).collect();
    dirs.iter()
        .flat_map(|&d| dirs.iter().map(move |&e| turn((d + 2) % 4, e)))
        .min()
        .unwrap_or(4)
}

/// Whether `p`, on no line of P's coordinates, lies in P: the even–odd rule over the vertical
/// edges to its left.
fn inside(edges: &[VerticalEdge], p: Point) -> bool {
    edges
        .iter()
        .filter(|e| e.x < p.x && e.y0 < p.y && p.y < e.y1)
        .count()
        % 2
        == 1
}

/// `convex_corners` of the module docs.
fn forced_corner_turns(polygon: &Polygon, erosion: &Erosion) -> Result<u64> {
    let (pxs, pys) = polygon.coordinates();
    let edges = polygon.vertical_edges();
    let corners: BTreeSet<Point> = polygon
        .rings()
        .iter()
        .flat_map(|r| r.corners.iter().copied())
        .collect();
    // The coordinate after (sign > 0) or before `at` among `lines`.
    let beside = |lines: &[Rational], at: Rational, sign: i8| {
        if sign > 0 {
            lines.get(lines.partition_point(|&l| l <= at)).copied()
        } else {
            lines
                .partition_point(|&l| l < at)
                .checked_sub(1)
                .map(|k| lines[k])
        }
    };
    let half = |v: Rational, sign: i8| {
        if sign > 0 {
            add(v, Rational::HALF)
        } else {
            sub(v, Rational::HALF)
        }
    };
    // Forbidden headings (bits) at each point c(v).
    let mut forbidden: BTreeMap<Point, u8> = BTreeMap::new();
    for v in corners {
        const QUADRANTS: [(i8, i8); 4] = [(1, 1), (-1, 1), (-1, -1), (1, -1)];
        let cells =
            QUADRANTS.map(
                |(sx, sy)| match (beside(&pxs, v.x, sx), beside(&pys, v.y, sy)) {
                    (Some(x), Some(y)) => inside(&edges, Point::new(mid(v.x, x), mid(v.y, y))),
                    _ => false,
                },
            );
        let cell_in = |sx: i8, sy: i8| {
            cells[QUADRANTS
                .iter()
                .position(|&q| q == (sx, sy))
                .expect("a quadrant")]
        };
        for (sx, sy) in QUADRANTS {
            if !cell_in(sx, sy) || cell_in(-sx, sy) || cell_in(sx, -sy) {
                continue;
            }
            let c = Point::new(half(v.x, sx), half(v.y, sy));
            if !erosion.contains(c) {
                return Err(Error::invalid(format!(
                    "the erosion does not mill the polygon: the square at {c}, the only one \
                     covering the corner {v}, is not in it"
                )));
            }
            *forbidden.entry(c).or_default() |= (1 << heading((-sx, 0))) | (1 << heading((0, -sy)));
        }
    }
    Ok(forbidden.values().map(|&f| forced_turns(!f & 0b1111)).sum())
}

/// B as runs of faces along one axis: `runs[r]`, for the doubled index r of a face of the
/// `across` lines (2k: line k; 2k + 1: the open interval after it), holds the maximal runs
/// `start..end` of doubled faces of the `along` lines that lie in B.
struct Lines {
    along: Vec<Rational>,
    across: Vec<Rational>,
    runs: Vec<Vec<(u32, u32)>>,
}

/// Where a value w falls among sorted lines: `first`, the first doubled face meeting
/// [w, ∞), `last`, the last one meeting (−∞, w] (`None` when there is none), and whether w lies
/// within the outer lines (then `first` = `last` is w's own face).
#[derive(Clone, Copy, Debug)]
struct End {
    first: Option<usize>,
    last: Option<usize>,
    within: bool,
}

fn end(lines: &[Rational], w: Rational) -> End {
    let n = lines.len();
    let k = lines.partition_point(|&l| l < w);
    let first = if k == n {
        None
    } else if k == 0 || lines[k] == w {
        Some(2 * k)
    } else {
        Some(2 * k - 1)
    };
    let m = lines.partition_point(|&l| l <= w);
    let last = if m == 0 {
        None
    } else if lines[m - 1] == w || m == n {
        Some(2 * (m - 1))
    } else {
        Some(2 * m - 1)
    };
    End {
        first,
        last,
        within: k < n && m > 0,
    }
}

/// The doubled indices `first..=last` of the faces of sorted `lines` that meet [lo, hi]
/// (lo ≤ hi), or `None`.
#[cfg(test)]
fn faces_meeting(lines: &[Rational], lo: Rational, hi: Rational) -> Option<(usize, usize)> {
    let (first, last) = (end(lines, lo).first?, end(lines, hi).last?);
    (first <= last).then_some((first, last))
}

/// One coordinate v of a witness point: where v − ½ and v + ½ fall among the face lines of its
/// axis, and the ranks of v and v + 1 among all such values of the points compared (so the
/// pair tests compare integers; see [`rank`]).
#[derive(Clone, Copy, Debug)]
struct Coord {
    v: Rational,
    minus: End,
    plus: End,
    at: u32,
    at_plus_one: u32,
}

/// The coordinate `v` placed among `lines`, not yet ranked.
fn coord(lines: &[Rational], v: Rational) -> Coord {
    Coord {
        v,
        minus: end(lines, sub(v, Rational::HALF)),
        plus: end(lines, add(v, Rational::HALF)),
        at: 0,
        at_plus_one: 0,
    }
}

/// Ranks v and v + 1 of `coords` (one axis) among all of them, so that comparisons between
/// them and with each other's v + 1 are exact integer comparisons.
fn rank(coords: &mut [Coord]) {
    let mut values: Vec<Rational> = coords
        .iter()
        .flat_map(|c| [c.v, add(c.v, Rational::ONE)])
        .collect();
    values.sort_unstable();
    values.dedup();
    let at = |v: Rational| values.partition_point(|&w| w < v) as u32;
    for c in coords {
        (c.at, c.at_plus_one) = (at(c.v), at(add(c.v, Rational::ONE)));
    }
}

/// A candidate witness point with its coordinates placed among the face lines.
#[derive(Clone, Copy, Debug)]
struct Witness {
    point: Point,
    x: Coord,
    y: Coord,
}

impl Lines {
    /// The same B with the axes swapped.
    fn transposed(&self) -> Lines {
        let mut columns: Vec<Vec<u32>> = vec![Vec::new(); (2 * self.along.len()).saturating_sub(1)];
        for (r, runs) in self.runs.iter().enumerate() {
            for &(start, end) in runs {
                for f in start..end {
                    columns[f as usize].push(r as u32);
                }
            }
        }
        let runs = columns
            .into_iter()
            .map(|rows| {
                let mut runs: Vec<(u32, u32)> = Vec::new();
                for r in rows {
                    match runs.last_mut() {
                        Some(last) if last.1 == r => last.1 = r + 1,
                        _ => runs.push((r, r + 1)),
                    }
                }
                runs
            })
            .collect();
        Lines {
            along: self.across.clone(),
            across: self.along.clone(),
            runs,
        }
    }

    /// Whether some row of faces r0..=r1 has B on all the faces a..=b (`segment`), or on
    /// some face of a..=b (not `segment`). Runs are maximal, so "all" means within one run.
    fn holds(&self, (r0, r1): (usize, usize), (a, b): (usize, usize), segment: bool) -> bool {
        let rows = self.runs.get(r0..=r1).unwrap_or(&[]);
        rows.iter().any(|runs| {
            // The first run ending after face a.
            let k = runs.partition_point(|&(_, end)| end as usize <= a);
            runs.get(k).is_some_and(|&(start, end)| {
                if segment {
                    start as usize <= a && b < end as usize
                } else {
                    start as usize <= b
                }
            })
        })
    }
}

/// Whether one segment of B along `lines`' axis has a band containing p and q, given by their
/// along (`pa`, `qa`) and across (`pc`, `qc`) coordinates (module docs, the exact test).
fn shared_band(lines: &Lines, (pa, pc): (&Coord, &Coord), (qa, qc): (&Coord, &Coord)) -> bool {
    // The across interval [max − ½, min + ½] must be non-empty: |p_c − q_c| ≤ 1.
    let (low, high) = if pc.at <= qc.at { (pc, qc) } else { (qc, pc) };
    if high.at > low.at_plus_one {
        return false;
    }
    let (Some(r0), Some(r1)) = (high.minus.first, low.plus.last) else {
        return false;
    };
    let (left, right) = if pa.at <= qa.at { (pa, qa) } else { (qa, pa) };
    // L = left + ½ ≤ R = right − ½: the segment [L, R] must lie in B (within the outer lines,
    // where each end has its own face); otherwise some point with along coordinate in [R, L].
    let segment = left.at_plus_one <= right.at;
    let faces = if segment {
        if !(left.plus.within && right.minus.within) {
            return false;
        }
        (left.plus.first, right.minus.first)
    } else {
        (right.minus.first, left.plus.last)
    };
    let (Some(a), Some(b)) = faces else {
        return false;
    };
    r0 <= r1 && a <= b && lines.holds((r0, r1), (a, b), segment)
}

/// Whether some axis-parallel segment in B has a band containing both p and q.
fn attacks(horizontal: &Lines, vertical: &Lines, p: &Witness, q: &Witness) -> bool {
    shared_band(horizontal, (&p.x, &p.y), (&q.x, &q.y))
        || shared_band(vertical, (&p.y, &p.x), (&q.y, &q.x))
}

/// Candidate values along one axis with P's coordinates `coords` (module docs): `level` 2
/// with the ¼ fill and the midpoints, 1 with the midpoints, 0 with neither.
fn axis_values(coords: &[Rational], level: u8) -> Vec<Rational> {
    let (Some(&lo), Some(&hi)) = (coords.first(), coords.last()) else {
        return Vec::new();
    };
    let quarter = Rational::new(1, 4).expect("a quarter");
    let offsets = [
        Rational::ZERO,
        Rational::HALF,
        Rational::ONE,
        sub(Rational::ZERO, Rational::HALF),
        sub(Rational::ZERO, Rational::ONE),
    ];
    let mut values: Vec<Rational> = coords
        .iter()
        .flat_map(|&c| offsets.iter().map(move |&o| add(c, o)))
        .filter(|&v| lo <= v && v <= hi)
        .collect();
    values.sort_unstable();
    values.dedup();
    if level >= 1 {
        let mut more = Vec::new();
        for w in values.windows(2) {
            more.push(mid(w[0], w[1]));
            if level >= 2 {
                let mut v = add(w[0], quarter);
                while v < w[1] {
                    more.push(v);
                    v = add(v, quarter);
                }
            }
        }
        values.extend(more);
        values.sort_unstable();
        values.dedup();
    }
    values
}

/// The candidate witness points of P (module docs), at most `MAX_CANDIDATES` (1000).
fn candidates(polygon: &Polygon, horizontal: &Lines) -> Vec<Witness> {
    let (pxs, pys) = polygon.coordinates();
    for level in [2, 1, 0] {
        let (xs, ys) = (axis_values(&pxs, level), axis_values(&pys, level));
        // Too large a grid to scan: try a coarser one (level 0 is always scanned).
        if level > 0 && xs.len() * ys.len() > 64 * MAX_CANDIDATES {
            continue;
        }
        // x is placed among the x lines (horizontal.along), y among the y lines.
        let mut xs: Vec<Coord> = xs.iter().map(|&x| coord(&horizontal.along, x)).collect();
        let mut ys: Vec<Coord> = ys.iter().map(|&y| coord(&horizontal.across, y)).collect();
        rank(&mut xs);
        rank(&mut ys);
        let mut points = Vec::new();
        'scan: for y in &ys {
            for x in &xs {
                // p ∈ P: the band of some point of B (a link of length 0) contains p.
                if shared_band(horizontal, (x, y), (x, y)) {
                    points.push(Witness {
                        point: Point::new(x.v, y.v),
                        x: *x,
                        y: *y,
                    });
                    if points.len() > MAX_CANDIDATES {
                        break 'scan;
                    }
                }
            }
        }
        if points.len() <= MAX_CANDIDATES || level == 0 {
            points.truncate(MAX_CANDIDATES);
            return points;
        }
    }
    unreachable!("level 0 always returns")
}

/// A set of pairwise independent candidates: repeatedly the one attacked by the fewest
/// remaining candidates, dropping those it attacks.
fn rook_placement(candidates: &[Witness], horizontal: &Lines, vertical: &Lines) -> Vec<Point> {
    let n = candidates.len();
    let mut attacked_by: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, p) in candidates.iter().enumerate() {
        for (j, q) in candidates.iter().enumerate().skip(i + 1) {
            if attacks(horizontal, vertical, p, q) {
                attacked_by[i].push(j);
                attacked_by[j].push(i);
            }
        }
    }
    let mut degree: Vec<usize> = attacked_by.iter().map(Vec::len).collect();
    let mut alive = vec![true; n];
    let mut rooks = Vec::new();
    while let Some(i) = (0..n).filter(|&i| alive[i]).min_by_key(|&i| (degree[i], i)) {
        rooks.push(candidates[i].point);
        alive[i] = false;
        for &j in &attacked_by[i] {
            if alive[j] {
                alive[j] = false;
                for &k in &attacked_by[j] {
                    degree[k] = degree[k].saturating_sub(1);
                }
            }
        }
    }
    rooks
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(v: i128, d: i128) -> Rational {
        Rational::new(v, d).unwrap()
    }

    #[test]
    fn faces_meeting_an_interval() {
        let lines = [r(0, 1), r(1, 1), r(2, 1)];
        assert_eq!(faces_meeting(&lines, r(0, 1), r(0, 1)), Some((0, 0)));
        assert_eq!(faces_meeting(&lines, r(1, 2), r(1, 2)), Some((1, 1)));
        assert_eq!(faces_meeting(&lines, r(-1, 1), r(1, 2)), Some((0, 1)));
        assert_eq!(faces_meeting(&lines, r(1, 2), r(3, 1)), Some((1, 4)));
        assert_eq!(faces_meeting(&lines, r(1, 1), r(3, 2)), Some((2, 3)));
        assert_eq!(faces_meeting(&lines, r(3, 1), r(4, 1)), None);
        assert_eq!(faces_meeting(&lines, r(-2, 1), r(-1, 1)), None);
    }

    #[test]
    fn forced_turns_by_allowed_directions() {
        assert_eq!(forced_turns(0b0011), 1); // E and N: a convex corner
        assert_eq!(forced_turns(0b0010), 2); // N only: a dead end
        assert_eq!(forced_turns(0), 4); // nothing: a point walk
        assert_eq!(forced_turns(0b0101), 0); // E and W: straight through
    }

    /// B's face grid both ways, and a witness at `p`.
    fn grids(polygon: &Polygon) -> (Lines, Lines) {
        let Faces { xs, ys, rows } = face_grid(polygon);
        let h = Lines {
            along: xs,
            across: ys,
            runs: rows,
        };
        let v = h.transposed();
        (h, v)
    }

    /// Witnesses at `points`, ranked together.
    fn witnesses(h: &Lines, points: &[Point]) -> Vec<Witness> {
        let mut xs: Vec<Coord> = points.iter().map(|p| coord(&h.along, p.x)).collect();
        let mut ys: Vec<Coord> = points.iter().map(|p| coord(&h.across, p.y)).collect();
        rank(&mut xs);
        rank(&mut ys);
        (0..points.len())
            .map(|k| Witness {
                point: points[k],
                x: xs[k],
                y: ys[k],
            })
            .collect()
    }

    #[test]
    fn diagonal_neighbours_share_a_band_in_open_space() {
        let p = Polygon::parse("POLYGON ((0 0, 5 0, 5 5, 0 5, 0 0))", "t").unwrap();
        let (h, v) = grids(&p);
        let quarters = [(2, 2), (6, 6), (0, 0), (5, 5), (18, 3), (24, 4)];
        let points: Vec<Point> = quarters
            .iter()
            .map(|&(x, y)| Point::new(r(x, 4), r(y, 4)))
            .collect();
        let w = witnesses(&h, &points);
        // (½, ½) and (1½, 1½): the square centred at (1, 1) touches both.
        assert!(attacks(&h, &v, &w[0], &w[1]));
        // More than 1 apart in both coordinates: independent.
        assert!(!attacks(&h, &v, &w[2], &w[3]));
        // Same row, far apart: one horizontal link covers both.
        assert!(attacks(&h, &v, &w[0], &w[4]));
        // Outside P.
        assert!(!shared_band(&h, (&w[5].x, &w[5].y), (&w[5].x, &w[5].y)));
    }

    /// Whether the closed box [x0, x1] × [y0, y1] (of positive area) lies in P: every cell of
    /// P's coordinate grid meeting its interior is inside P (checked at the cell's centre).
    fn box_in(
        polygon: &Polygon,
        (x0, x1): (Rational, Rational),
        (y0, y1): (Rational, Rational),
    ) -> bool {
        let (pxs, pys) = polygon.coordinates();
        let edges = polygon.vertical_edges();
        if x0 < pxs[0] || y0 < pys[0] || x1 > *pxs.last().unwrap() || y1 > *pys.last().unwrap() {
            return false;
        }
        pxs.windows(2).filter(|w| w[0] < x1 && w[1] > x0).all(|wx| {
            pys.windows(2)
                .filter(|w| w[0] < y1 && w[1] > y0)
                .all(|wy| inside(&edges, Point::new(mid(wx[0], wx[1]), mid(wy[0], wy[1]))))
        })
    }

    /// lo, hi, the `lines` between them and the midpoints of consecutive ones: a point of each
    /// face of `lines` meeting [lo, hi].
    fn samples(lines: &[Rational], lo: Rational, hi: Rational) -> Vec<Rational> {
        let mut v: Vec<Rational> = lines
            .iter()
            .copied()
            .filter(|&l| lo <= l && l <= hi)
            .collect();
        v.extend([lo, hi]);
        v.sort_unstable();
        v.dedup();
        let mids: Vec<Rational> = v.windows(2).map(|w| mid(w[0], w[1])).collect();
        v.extend(mids);
        v
    }

    /// The module docs' definition of a shared band, by brute force over the faces, with the
    /// boxes checked against the polygon itself (not the face grid); `swap` for vertical.
    fn brute_band(polygon: &Polygon, h: &Lines, p: Point, q: Point, swap: bool) -> bool {
        let (pa, pc, qa, qc) = if swap {
            (p.y, p.x, q.y, q.x)
        } else {
            (p.x, p.y, q.x, q.y)
        };
        let (along, across) = if swap {
            (&h.across, &h.along)
        } else {
            (&h.along, &h.across)
        };
        let (c0, c1) = (
            sub(pc.max(qc), Rational::HALF),
            add(pc.min(qc), Rational::HALF),
        );
        if c0 > c1 {
            return false;
        }
        let (left, right) = (
            add(pa.min(qa), Rational::HALF),
            sub(pa.max(qa), Rational::HALF),
        );
        let spans: Vec<(Rational, Rational)> = if left <= right {
            vec![(left, right)]
        } else {
            samples(along, right, left)
                .into_iter()
                .map(|x| (x, x))
                .collect()
        };
        samples(across, c0, c1).into_iter().any(|c| {
            spans.iter().any(|&(a, b)| {
                let (sa, sc) = (
                    (sub(a, Rational::HALF), add(b, Rational::HALF)),
                    (sub(c, Rational::HALF), add(c, Rational::HALF)),
                );
                if swap {
                    box_in(polygon, sc, sa)
                } else {
                    box_in(polygon, sa, sc)
                }
            })
        })
    }

    #[test]
    fn shared_bands_agree_with_brute_force() {
        let polygons = [
            "POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))",
            "POLYGON ((0.25 0, 1.25 0, 1.25 2.5, 3.5 2.5, 3.5 4, 0.25 4, 0.25 0))",
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1), (2 2, 3 2, 3 3, 2 3, 2 2))",
            "POLYGON ((0 0, 5 0, 5 3.5, 3.75 3.5, 3.75 1.2, 2.7 1.2, 2.7 3, 1.3 3, 1.3 1.2, 0 1.2, 0 0))",
        ];
        for text in polygons {
            let polygon = Polygon::parse(text, "t").unwrap();
            let (h, v) = grids(&polygon);
            let (pxs, pys) = polygon.coordinates();
            let grid = |c: &[Rational]| -> Vec<Rational> {
                let (lo, hi) = (c[0].floor(), c.last().unwrap().ceil());
                (4 * lo..=4 * hi)
                    .map(|k| r(k, 4))
                    .chain(c.iter().copied())
                    .collect()
            };
            let points: Vec<Point> = grid(&pys)
                .into_iter()
                .step_by(2)
                .flat_map(|y| {
                    grid(&pxs)
                        .into_iter()
                        .step_by(3)
                        .map(move |x| Point::new(x, y))
                })
                .collect();
            let mut attacked = 0;
            let all = witnesses(&h, &points);
            for (i, (&p, wp)) in points.iter().zip(&all).enumerate() {
                for (&q, wq) in points[i..].iter().zip(&all[i..]) {
                    let fast = (
                        shared_band(&h, (&wp.x, &wp.y), (&wq.x, &wq.y)),
                        shared_band(&v, (&wp.y, &wp.x), (&wq.y, &wq.x)),
                    );
                    let slow = (
                        brute_band(&polygon, &h, p, q, false),
                        brute_band(&polygon, &h, p, q, true),
                    );
                    assert_eq!(fast, slow, "{text}: {p} {q}");
                    attacked += usize::from(fast.0 || fast.1);
                }
            }
            assert!(attacked > 0, "{text}");
        }
    }
}
