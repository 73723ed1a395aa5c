//! Joining pixel walks and contour walks into one closed walk (Corollary 4 of *Lawn mowing and
//! milling* and our reading of Theorem 5.7 of *Optimal covering tours with turn costs*): both
//! say only "combine".
//!
//! Candidate links are straight axis-parallel moves from a pixel centre to the nearest point
//! of the contour δB in each of the four directions (only where the neighbouring pixel is
//! missing: elsewhere a nearer pixel sees the same walk along the same line). A spanning tree
//! of them (Kruskal, by [`Rank`]) ties every walk together, and each tree link is walked there
//! and back, the walks spliced at its ends.
//!
//! # Why a link stays in B
//!
//! Its pixel centre is in B, and if it is not on δB it is an interior point of B, and the open
//! link meets no boundary point before its end: it lies in B.
//!
//! # What a link adds in turns
//!
//! Splicing a there-and-back detour with heading L at a vertex where the walk arrives with
//! heading a and leaves with heading b replaces the turn t(a, b) by t(a, L) + t(−L, b), with t
//! the turn cost (0, 1, 2: the angle in quarter turns, a metric). Since t(−L, b) = 2 − t(L, b),
//! the change is 2 + t(a, L) − t(L, b) − t(a, b) ≤ 2 by the triangle inequality. The far end is
//! the same with −L. A walk that never moves (4 turns by the checker's convention) spliced
//! in by k links turns at most 2 per link end there instead. A link of length 0 (a pixel
//! centre on δB) joins the two walks at one point, replacing t(a, b) + t(c, d) by t(a, d) +
//! t(c, b) ≤ 4. Several links at one vertex are spliced one after another, each at a vertex
//! occurrence with its own arriving and leaving heading. So the joined walk has at most
//! Σ turns(walks) + 4·(links) turns.

use crate::error::{Error, Result};
use crate::region::{Dir, Pixel, Region};
use mowmill_core::ortho::Point;
use mowmill_core::ortho::Rational;
use petgraph::unionfind::UnionFind;
use std::collections::HashMap;

/// How the candidate links are ranked for the spanning tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Rank {
    /// By length (Corollary 4).
    Length,
    /// By the turns the link adds (as if alone at its ends), then length (Theorem 5.7).
    Turns,
}

/// A link of the spanning tree: from vertex `from.1` of walk `from.0` (a pixel walk) to
/// vertex `to.1` of walk `to.0` (a contour walk, numbered after the pixel walks).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Link {
    pub(crate) length: Rational,
    /// The turns it adds, counted as if it were alone at both its ends.
    pub(crate) turns: i64,
    from: (usize, usize),
    to: (usize, usize),
}

/// The joined walk and the tree links used.
#[derive(Clone, Debug)]
pub(crate) struct Joined {
    pub(crate) walk: Vec<Point>,
    pub(crate) links: Vec<Link>,
}

pub(crate) fn add(a: Rational, b: Rational) -> Result<Rational> {
    a.checked_add(b)
        .ok_or_else(|| Error::invalid("length overflows the exact rationals"))
}

pub(crate) fn sub(a: Rational, b: Rational) -> Result<Rational> {
    a.checked_sub(b)
        .ok_or_else(|| Error::invalid("length overflows the exact rationals"))
}

pub(crate) fn distance(a: Point, b: Point) -> Result<Rational> {
    add(sub(a.x, b.x)?.abs(), sub(a.y, b.y)?.abs())
}

/// The heading of the move from `a` to `b`, `None` when they are equal (or diagonal, which
/// the walks joined here never are).
fn heading(a: Point, b: Point) -> Option<Dir> {
    use std::cmp::Ordering::*;
    match (b.x.cmp(&a.x), b.y.cmp(&a.y)) {
        (Greater, Equal) => Some(Dir::E),
        (Less, Equal) => Some(Dir::W),
        (Equal, Greater) => Some(Dir::N),
        (Equal, Less) => Some(Dir::S),
        _ => None,
    }
}

/// The headings arriving at and leaving vertex `i` of a closed walk (zero-length moves
/// skipped); `None` when the walk never moves.
fn headings_at(walk: &[Point], i: usize) -> Option<(Dir, Dir)> {
    let m = walk.len();
    let arriving = (1..=m).find_map(|k| {
        let j = (i + m - k) % m;
        heading(walk[j], walk[(j + 1) % m])
    })?;
    let leaving = (0..m).find_map(|k| {
        let j = (i + k) % m;
        heading(walk[j], walk[(j + 1) % m])
    })?;
    Some((arriving, leaving))
}

fn t(a: Dir, b: Dir) -> i64 {
    i64::from(a.turn_to(b))
}

/// The turns added by splicing, at a vertex with headings `at`, a detour leaving with heading
/// `l` and coming back (module docs); a still walk (`None`) loses its 4 and turns 2 there.
fn added_at(at: Option<(Dir, Dir)>, l: Dir) -> i64 {
    match at {
        Some((a, b)) => t(a, l) + t(l.opposite(), b) - t(a, b),
        None => 2 - 4,
    }
}

/// The turns a link from vertex headings `from` to `to` adds, as if alone at both ends.
fn added_turns(from: Option<(Dir, Dir)>, to: Option<(Dir, Dir)>, l: Option<Dir>) -> i64 {
    match l {
        Some(l) => added_at(from, l) + added_at(to, l.opposite()),
        // Length 0: the walks cross at one point, a → d and c → b.
        None => match (from, to) {
            (Some((a, b)), Some((c, d))) => t(a, d) + t(c, b) - t(a, b) - t(c, d),
            (Some(_), None) | (None, Some(_)) => -4,
            (None, None) => -4,
        },
    }
}

/// The nearest points of the contour walks from `c` along direction `d` (including `c`
/// itself), with their walks: one per walk that attains the least distance (walks of zero-width
/// parts of B may share points).
fn nearest_on_contour(contour: &[Vec<Point>], c: Point, d: (i32, i32)) -> Vec<(Point, usize)> {
    let mut best: Vec<(Rational, Point, usize)> = Vec::new();
    for (w, walk) in contour.iter().enumerate() {
        for i in 0..walk.len() {
            let (a, b) = (walk[i], walk[(i + 1) % walk.len()]);
            // The point of segment a–b on the ray's line, nearest c ahead.
            let hit = if d.0 == 0 {
                // Vertical ray x = c.x.
                let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
                if c.x < lo || c.x > hi {
                    continue;
                }
                let (ylo, yhi) = (a.y.min(b.y), a.y.max(b.y));
                let y = if d.1 > 0 {
                    if yhi < c.y { continue } else { ylo.max(c.y) }
                } else if ylo > c.y {
                    continue;
                } else {
                    yhi.min(c.y)
                };
                Point::new(c.x, y)
            } else {
                let (lo, hi) = (a.y.min(b.y), a.y.max(b.y));
                if c.y < lo || c.y > hi {
                    continue;
                }
                let (xlo, xhi) = (a.x.min(b.x), a.x.max(b.x));
                let x = if d.0 > 0 {
                    if xhi < c.x { continue } else { xlo.max(c.x) }
                } else if xlo > c.x {
                    continue;
                } else {
                    xhi.min(c.x)
                };
                Point::new(x, c.y)
            };
            let Ok(length) = distance(c, hit) else {
                continue;
            };
            match best.first() {
                Some(&(l, _, _)) if length > l => {}
                Some(&(l, _, _)) if length == l => {
                    if !best.iter().any(|b| b.2 == w) {
                        best.push((length, hit, w));
                    }
                }
                _ => best = vec![(length, hit, w)],
            }
        }
    }
    best.into_iter().map(|(_, p, w)| (p, w)).collect()
}

/// Inserts `p` into the closed walk as a vertex (on the first segment containing it), unless it
/// is one already. A collinear vertex changes neither turns nor the swept area.
fn insert_vertex(walk: &mut Vec<Point>, p: Point) {
    if walk.contains(&p) {
        return;
    }
    let m = walk.len();
    for i in 0..m {
        let (a, b) = (walk[i], walk[(i + 1) % m]);
        let on = (a.x == b.x && p.x == a.x && a.y.min(b.y) <= p.y && p.y <= a.y.max(b.y))
            || (a.y == b.y && p.y == a.y && a.x.min(b.x) <= p.x && p.x <= a.x.max(b.x));
        if on {
            walk.insert(i + 1, p);
            return;
        }
    }
    unreachable!("a link ends on its contour walk")
}

/// Joins `pixel_walks` (closed walks of pixel centres; `component_of` says which walk visits
/// pixel centre of a pixel of `region`, and that walk visits every such centre) and the
/// `contour` walks into one closed walk by a spanning tree of straight links ranked by `rank`.
///
/// # Errors
/// When some walk cannot be linked to the rest (only possible with holes, when no pixel centre
/// sees that walk along a line).
///
/// # Complexity
/// O(E·M) for the candidate links (E pixel sides on the edge of the region, M contour
/// segments), O(T + K log K) for the splicing (T walk points, K candidates).
pub(crate) fn join(
    region: &Region,
    component_of: &dyn Fn(Pixel) -> usize,
    pixel_walks: Vec<Vec<Point>>,
    mut contour: Vec<Vec<Point>>,
    rank: Rank,
) -> Result<Joined> {
    let nt = pixel_walks.len();
    let nw = contour.len();
    let dirs = [
        ((0, -1), Dir::S),
        ((0, 1), Dir::N),
        ((-1, 0), Dir::W),
        ((1, 0), Dir::E),
    ];
    // The hits first, then their points become contour vertices, so vertex indices are final.
    let mut hits = Vec::new();
    for &p in region.pixels() {
        let c = Point::pixel_centre(p.x, p.y);
        for (d, _) in dirs {
            if region.contains(Pixel::new(p.x + d.0, p.y + d.1)) {
                continue;
            }
            for (to, walk) in nearest_on_contour(&contour, c, d) {
                hits.push((p, c, to, walk));
            }
        }
    }
    for &(_, _, to, walk) in &hits {
        insert_vertex(&mut contour[walk], to);
    }
    let occurrences = |walk: &[Point], p: Point| -> Vec<usize> {
        (0..walk.len()).filter(|&i| walk[i] == p).collect()
    };
    let mut candidates = Vec::with_capacity(hits.len());
    for (p, c, to, w) in hits {
        let k = component_of(p);
        let length = distance(c, to)?;
        let l = heading(c, to);
        let mut best: Option<Link> = None;
        for i in occurrences(&pixel_walks[k], c) {
            for j in occurrences(&contour[w], to) {
                let turns = added_turns(
                    headings_at(&pixel_walks[k], i),
                    headings_at(&contour[w], j),
                    l,
                );
                if best.is_none_or(|b| turns < b.turns) {
                    best = Some(Link {
                        length,
                        turns,
                        from: (k, i),
                        to: (nt + w, j),
                    });
                }
            }
        }
        candidates.push(best.ok_or_else(|| {
            Error::invalid(format!("pixel centre {c} is not on its component's walk"))
        })?);
    }
    let point = |(item, i): (usize, usize)| {
        if item < nt {
            pixel_walks[item][i]
        } else {
            contour[item - nt][i]
        }
    };
    match rank {
        Rank::Length => {
            candidates.sort_by_key(|l| (l.length, point(l.from), point(l.to), l.to.0));
        }
        Rank::Turns => {
            candidates.sort_by_key(|l| (l.turns, l.length, point(l.from), point(l.to), l.to.0));
        }
    }
    let mut groups = UnionFind::<usize>::new(nt + nw);
    let mut tree: Vec<Link> = Vec::new();
    for link in candidates {
        if groups.union(link.from.0, link.to.0) {
            tree.push(link);
        }
    }
    let roots = (0..nt + nw).filter(|&i| groups.find_mut(i) == i).count();
    if roots > 1 {
        return Err(Error::invalid(format!(
            "cannot join the {nt} pixel walk(s) and {nw} contour walk(s) into one tour by \
             straight links from pixel centres ({roots} groups remain)"
        )));
    }
    let mut items = pixel_walks;
    items.extend(contour);
    let mut at: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (l, link) in tree.iter().enumerate() {
        at.entry(link.from).or_default().push(l);
        at.entry(link.to).or_default().push(l);
    }
    let mut used = vec![false; tree.len()];
    let mut walk = Vec::new();
    if !items.is_empty() {
        emit(&items, &tree, &at, &mut used, (0, 0), &mut walk);
    }
    Ok(Joined { walk, links: tree })
}

/// Appends item `start.0`'s closed walk from vertex `start.1` (not the return to it), detouring
/// along every unused tree link at each of its vertices.
fn emit(
    items: &[Vec<Point>],
    tree: &[Link],
    at: &HashMap<(usize, usize), Vec<usize>>,
    used: &mut [bool],
    start: (usize, usize),
    out: &mut Vec<Point>,
) {
    let (item, first) = start;
    let walk = &items[item];
    for k in 0..walk.len() {
        let i = (first + k) % walk.len();
        out.push(walk[i]);
        for &l in at.get(&(item, i)).map_or(&[][..], Vec::as_slice) {
            if used[l] {
                continue;
            }
            used[l] = true;
            let link = tree[l];
            let (here, there) = if link.from == (item, i) {
                (link.from, link.to)
            } else {
                (link.to, link.from)
            };
            emit(items, tree, at, used, there, out);
            out.push(items[there.0][there.1]);
            out.push(items[here.0][here.1]);
        }
    }
}
