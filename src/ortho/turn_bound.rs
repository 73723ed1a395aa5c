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
//! `MAX_CANDIDATES` (2000) are tried: when there are more, the fill is dropped, then the midpoints,
//! and finally the first candidates in lexicographic (y, x) order are kept; fewer candidates
//! only weaken the bound, never invalidate it.
//!
//! # Complexity
//!
//! O(n·v) for the corners (v corners, n vertical edges), O(F) to transpose B's face grid (F
//! faces in B, O(X·Y) as for [`feasibility`](super::feasibility)), and O(C²·r) for the attack
//! graph of C ≤ `MAX_CANDIDATES` (2000) candidates (r: the face rows within a unit interval).

use super::erosion::{Erosion, face_grid};
use super::polygon::{Point, Polygon, VerticalEdge};
use super::rational::Rational;
use crate::error::{Error, Result};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// The most candidate witness points [`turn_lower_bound`] tries for rooks (module docs).
const MAX_CANDIDATES: usize = 2000;

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
/// use mowmill::ortho::{Polygon, feasibility, turn_lower_bound};
///
/// // A 4 × 1.5 sliver: its contour is a rectangle, 4 turns, and no milling does better.
/// let sliver = Polygon::parse("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))", "s.wkt")?;
/// let bound = turn_lower_bound(&sliver, &feasibility(&sliver).unwrap())?;
/// assert_eq!(bound.convex_corners, 4);
/// assert_eq!(bound.best(), 4);
/// # Ok::<(), mowmill::Error>(())
/// ```
pub fn turn_lower_bound(polygon: &Polygon, erosion: &Erosion) -> Result<TurnBound> {
    let convex_corners = forced_corner_turns(polygon, erosion)?;
    let (xs, ys, rows) = face_grid(polygon);
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
        let cell_in = |sx: i8, sy: i8| match (beside(&pxs, v.x, sx), beside(&pys, v.y, sy)) {
            (Some(x), Some(y)) => inside(&edges, Point::new(mid(v.x, x), mid(v.y, y))),
            _ => false,
        };
        for (sx, sy) in [(1, 1), (-1, 1), (-1, -1), (1, -1)] {
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

/// The doubled indices `first..=last` of the faces of sorted `lines` that meet [lo, hi]
/// (lo ≤ hi), or `None`.
fn faces_meeting(lines: &[Rational], lo: Rational, hi: Rational) -> Option<(usize, usize)> {
    let n = lines.len();
    let k = lines.partition_point(|&l| l < lo);
    let first = if k == 0 {
        0
    } else if k == n {
        return None;
    } else if lines[k] == lo {
        2 * k
    } else {
        2 * k - 1
    };
    let m = lines.partition_point(|&l| l <= hi);
    let last = if m == 0 {
        return None;
    } else if lines[m - 1] == hi || m == n {
        2 * (m - 1)
    } else {
        2 * m - 1
    };
    (first <= last).then_some((first, last))
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

    /// For `left` ≤ `right`: whether [left, right] (along) × {c} lies in B for some c in
    /// [c0, c1] (across). For `left` > `right`: whether some point of B has its along
    /// coordinate in [right, left] and its across coordinate in [c0, c1].
    fn reaches(&self, left: Rational, right: Rational, c0: Rational, c1: Rational) -> bool {
        let Some((r0, r1)) = faces_meeting(&self.across, c0, c1) else {
            return false;
        };
        let segment = left <= right;
        let (lo, hi) = if segment {
            (left, right)
        } else {
            (right, left)
        };
        // B lies within the outer lines: a segment reaching beyond them is not in B.
        let within = |v: Rational| {
            self.along.first().is_some_and(|&f| f <= v)
                && self.along.last().is_some_and(|&l| v <= l)
        };
        if segment && !(within(lo) && within(hi)) {
            return false;
        }
        let Some((a, b)) = faces_meeting(&self.along, lo, hi) else {
            return false;
        };
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

/// Whether one link of B along `lines`' axis has a band containing p and q, given as (along,
/// across) coordinates (module docs, the exact test).
fn shared_band(lines: &Lines, p: (Rational, Rational), q: (Rational, Rational)) -> bool {
    let c0 = sub(p.1.max(q.1), Rational::HALF);
    let c1 = add(p.1.min(q.1), Rational::HALF);
    if c0 > c1 {
        return false;
    }
    let left = add(p.0.min(q.0), Rational::HALF);
    let right = sub(p.0.max(q.0), Rational::HALF);
    lines.reaches(left, right, c0, c1)
}

/// Whether some axis-parallel segment in B has a band containing both p and q.
fn attacks(horizontal: &Lines, vertical: &Lines, p: Point, q: Point) -> bool {
    shared_band(horizontal, (p.x, p.y), (q.x, q.y)) || shared_band(vertical, (p.y, p.x), (q.y, q.x))
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

/// The candidate witness points of P (module docs), at most `MAX_CANDIDATES` (2000).
fn candidates(polygon: &Polygon, horizontal: &Lines) -> Vec<Point> {
    let (pxs, pys) = polygon.coordinates();
    let in_p = |p: Point| shared_band(horizontal, (p.x, p.y), (p.x, p.y));
    for level in [2, 1, 0] {
        let (xs, ys) = (axis_values(&pxs, level), axis_values(&pys, level));
        // Too large a grid to scan: try a coarser one (level 0 is always scanned).
        if level > 0 && xs.len() * ys.len() > 64 * MAX_CANDIDATES {
            continue;
        }
        let mut points = Vec::new();
        'scan: for &y in &ys {
            for &x in &xs {
                let p = Point::new(x, y);
                if in_p(p) {
                    points.push(p);
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
fn rook_placement(candidates: &[Point], horizontal: &Lines, vertical: &Lines) -> Vec<Point> {
    let n = candidates.len();
    let mut attacked_by: Vec<Vec<usize>> = vec![Vec::new(); n];
    for i in 0..n {
        for j in i + 1..n {
            if attacks(horizontal, vertical, candidates[i], candidates[j]) {
                attacked_by[i].push(j);
                attacked_by[j].push(i);
            }
        }
    }
    let mut degree: Vec<usize> = attacked_by.iter().map(Vec::len).collect();
    let mut alive = vec![true; n];
    let mut rooks = Vec::new();
    while let Some(i) = (0..n).filter(|&i| alive[i]).min_by_key(|&i| (degree[i], i)) {
        rooks.push(candidates[i]);
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

    #[test]
    fn diagonal_neighbours_share_a_band_in_open_space() {
        let p = Polygon::parse("POLYGON ((0 0, 5 0, 5 5, 0 5, 0 0))", "t").unwrap();
        let (xs, ys, rows) = face_grid(&p);
        let h = Lines {
            along: xs,
            across: ys,
            runs: rows,
        };
        let v = h.transposed();
        let pt = |x: i128, y: i128| Point::new(r(x, 4), r(y, 4));
        // (½, ½) and (1½, 1½): the square centred at (1, 1) touches both.
        assert!(attacks(&h, &v, pt(2, 2), pt(6, 6)));
        // More than 1 apart in both coordinates: independent.
        assert!(!attacks(&h, &v, pt(0, 0), pt(5, 5)));
        // Same row, far apart: one horizontal link covers both.
        assert!(attacks(&h, &v, pt(2, 2), pt(18, 3)));
        // Outside P.
        assert!(!shared_band(&h, (r(6, 1), r(1, 1)), (r(6, 1), r(1, 1))));
    }
}
