//! The exact comparison of a union of rectangles with a polygon, up to measure zero: the one
//! geometric decision behind the milling checker and the feasibility test.
//!
//! All x coordinates of the polygon's corners and of the rectangles cut the plane into slabs,
//! all y coordinates into rows; in each open cell of this (finite) grid both the polygon and
//! the union of rectangles are constant: each contains the whole open cell or none of it. So
//! the two sets are equal up to measure zero exactly when no cell lies in one and not the
//! other, and a cell where they differ gives a witness point, its centre. The cells are visited
//! slab by slab (a sweep in x); a segment tree over the rows keeps, for the current slab, how
//! many rectangles cover each row and whether the row is inside the polygon (the parity of the
//! polygon's vertical edges crossed so far), and counts the rows where the two disagree.

use super::polygon::{Point, VerticalEdge};
use super::rational::Rational;

/// A closed axis-parallel rectangle [x0, x1] × [y0, y1], `x0 < x1`, `y0 < y1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x0: Rational,
    pub x1: Rational,
    pub y0: Rational,
    pub y1: Rational,
}

impl Rect {
    /// The area the unit square cutter sweeps while its centre runs over [xa, xb] × [ya, yb]
    /// (a point, an axis-parallel segment or a rectangle): that box grown by ½ on every side.
    /// `None` only on arithmetic overflow, which the input limits rule out.
    pub fn swept(xa: Rational, xb: Rational, ya: Rational, yb: Rational) -> Option<Rect> {
        Some(Rect {
            x0: xa.min(xb).checked_sub(Rational::HALF)?,
            x1: xa.max(xb).checked_add(Rational::HALF)?,
            y0: ya.min(yb).checked_sub(Rational::HALF)?,
            y1: ya.max(yb).checked_add(Rational::HALF)?,
        })
    }

    /// Whether `p` lies in the open interior.
    pub fn contains_inside(&self, p: Point) -> bool {
        self.x0 < p.x && p.x < self.x1 && self.y0 < p.y && p.y < self.y1
    }
}

/// Where the union of rectangles and the polygon differ: a point of the polygon that no
/// rectangle covers, and a point covered outside the polygon, each the centre of an open cell
/// of the difference (the first such cell from the left, then from the bottom).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Difference {
    pub(crate) uncovered: Option<Point>,
    pub(crate) outside: Option<Point>,
}

/// Compares the union of `rects` with the polygon whose vertical edges are `edges` (every
/// vertical edge of every ring: the polygon is the set of points with an odd number of them to
/// the left, which holds for valid rings).
///
/// # Complexity
///
/// O((E + R) log(E + R)) time and O(E + R) space for E edges and R rectangles.
pub(crate) fn compare(edges: &[VerticalEdge], rects: &[Rect]) -> Difference {
    let mut xs: Vec<Rational> = Vec::with_capacity(edges.len() + 2 * rects.len());
    let mut ys: Vec<Rational> = Vec::with_capacity(2 * edges.len() + 2 * rects.len());
    for e in edges {
        xs.push(e.x);
        ys.extend([e.y0, e.y1]);
    }
    for r in rects {
        xs.extend([r.x0, r.x1]);
        ys.extend([r.y0, r.y1]);
    }
    for v in [&mut xs, &mut ys] {
        v.sort_unstable();
        v.dedup();
    }
    let mut difference = Difference::default();
    if ys.len() < 2 {
        return difference;
    }
    let row = |y: Rational| ys.partition_point(|&v| v < y);
    let column = |x: Rational| xs.partition_point(|&v| v < x);
    // Events at each x: (first row, end row, what), what = +1 / -1 (a rectangle starts or
    // ends) or 0 (a polygon edge flips inside and outside).
    let mut events: Vec<Vec<(usize, usize, i32)>> = vec![Vec::new(); xs.len()];
    for e in edges {
        events[column(e.x)].push((row(e.y0), row(e.y1), 0));
    }
    for r in rects {
        let (lo, hi) = (row(r.y0), row(r.y1));
        events[column(r.x0)].push((lo, hi, 1));
        events[column(r.x1)].push((lo, hi, -1));
    }
    let centre = |a: Rational, b: Rational| {
        a.midpoint(b)
            .expect("midpoints of coordinates within the input limits fit")
    };
    let mut tree = RowTree::new(ys.len() - 1);
    for (i, at) in events.iter().enumerate() {
        for &(lo, hi, what) in at {
            if what == 0 {
                tree.flip(1, 0, tree.rows, lo, hi);
            } else {
                tree.cover(1, 0, tree.rows, lo, hi, what);
            }
        }
        if i + 1 == xs.len() {
            break;
        }
        let x = || centre(xs[i], xs[i + 1]);
        if difference.outside.is_none() && tree.over[1] > 0 {
            let j = tree.find_over(1, 0, tree.rows, false);
            difference.outside = Some(Point::new(x(), centre(ys[j], ys[j + 1])));
        }
        if difference.uncovered.is_none() && tree.under[1] > 0 {
            let j = tree.find_under(1, 0, tree.rows);
            difference.uncovered = Some(Point::new(x(), centre(ys[j], ys[j + 1])));
        }
        if difference.outside.is_some() && difference.uncovered.is_some() {
            break;
        }
    }
    difference
}

/// A segment tree over the rows of the current slab. For each node (a range of rows): `count`,
/// the rectangles covering its whole range that were added at this node; `covered`, its rows
/// covered by some rectangle (counting this node's and its descendants' additions);
/// `inside`, its rows inside the polygon; `over`, rows covered but outside; `under`, rows
/// inside but not covered; `flipped`, an inside/outside flip not yet passed to the children.
struct RowTree {
    rows: usize,
    count: Vec<i32>,
    covered: Vec<u32>,
    inside: Vec<u32>,
    over: Vec<u32>,
    under: Vec<u32>,
    flipped: Vec<bool>,
}

impl RowTree {
    fn new(rows: usize) -> RowTree {
        let n = 4 * rows;
        RowTree {
            rows,
            count: vec![0; n],
            covered: vec![0; n],
            inside: vec![0; n],
            over: vec![0; n],
            under: vec![0; n],
            flipped: vec![false; n],
        }
    }

    /// Recomputes a node's counts from its own `count` and its children (or, for a leaf, its
    /// own `inside`); the children must carry no pending flip of this node.
    fn pull(&mut self, node: usize, lo: usize, hi: usize) {
        let size = (hi - lo) as u32;
        if hi - lo > 1 {
            let (l, r) = (2 * node, 2 * node + 1);
            self.inside[node] = self.inside[l] + self.inside[r];
            if self.count[node] == 0 {
                self.covered[node] = self.covered[l] + self.covered[r];
                self.over[node] = self.over[l] + self.over[r];
                self.under[node] = self.under[l] + self.under[r];
                return;
            }
        } else if self.count[node] == 0 {
            self.covered[node] = 0;
            self.over[node] = 0;
            self.under[node] = self.inside[node];
            return;
        }
        self.covered[node] = size;
        self.over[node] = size - self.inside[node];
        self.under[node] = 0;
    }

    /// Flips inside and outside for every row of the node: covered rows swap between inside
    /// and outside, and so do uncovered ones.
    fn apply_flip(&mut self, node: usize, lo: usize, hi: usize) {
        let size = (hi - lo) as u32;
        self.inside[node] = size - self.inside[node];
        self.over[node] = self.covered[node] - self.over[node];
        self.under[node] = (size - self.covered[node]) - self.under[node];
        if hi - lo > 1 {
            self.flipped[node] = !self.flipped[node];
        }
    }

    fn push(&mut self, node: usize, lo: usize, hi: usize) {
        if self.flipped[node] {
            let mid = (lo + hi) / 2;
            self.apply_flip(2 * node, lo, mid);
            self.apply_flip(2 * node + 1, mid, hi);
            self.flipped[node] = false;
        }
    }

    /// Flips rows `a..b`.
    fn flip(&mut self, node: usize, lo: usize, hi: usize, a: usize, b: usize) {
        if b <= lo || hi <= a {
            return;
        }
        if a <= lo && hi <= b {
            self.apply_flip(node, lo, hi);
            return;
        }
        self.push(node, lo, hi);
        let mid = (lo + hi) / 2;
        self.flip(2 * node, lo, mid, a, b);
        self.flip(2 * node + 1, mid, hi, a, b);
        self.pull(node, lo, hi);
    }

    /// Adds `delta` rectangles over rows `a..b`.
    fn cover(&mut self, node: usize, lo: usize, hi: usize, a: usize, b: usize, delta: i32) {
        if b <= lo || hi <= a {
            return;
        }
        if a <= lo && hi <= b {
            // The children must be current before the node is recomputed from them.
            if hi - lo > 1 {
                self.push(node, lo, hi);
            }
            self.count[node] += delta;
            self.pull(node, lo, hi);
            return;
        }
        self.push(node, lo, hi);
        let mid = (lo + hi) / 2;
        self.cover(2 * node, lo, mid, a, b, delta);
        self.cover(2 * node + 1, mid, hi, a, b, delta);
        self.pull(node, lo, hi);
    }

    /// The lowest row covered but outside, in a node with `over > 0` (or, when `covered_above`,
    /// with a row outside).
    fn find_over(&mut self, node: usize, lo: usize, hi: usize, covered_above: bool) -> usize {
        if hi - lo == 1 {
            return lo;
        }
        self.push(node, lo, hi);
        let covered = covered_above || self.count[node] > 0;
        let mid = (lo + hi) / 2;
        let (l, r) = (2 * node, 2 * node + 1);
        let has = |t: &RowTree, child: usize, size: usize| {
            if covered {
                (t.inside[child] as usize) < size
            } else {
                t.over[child] > 0
            }
        };
        if has(self, l, mid - lo) {
            self.find_over(l, lo, mid, covered)
        } else {
            self.find_over(r, mid, hi, covered)
        }
    }

    /// The lowest row inside but uncovered, in a node with `under > 0` (so no rectangle covers
    /// the node's range whole, at this node or above).
    fn find_under(&mut self, node: usize, lo: usize, hi: usize) -> usize {
        if hi - lo == 1 {
            return lo;
        }
        self.push(node, lo, hi);
        let mid = (lo + hi) / 2;
        if self.under[2 * node] > 0 {
            self.find_under(2 * node, lo, mid)
        } else {
            self.find_under(2 * node + 1, mid, hi)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ortho::Polygon;

    fn q(text: &str) -> Rational {
        Rational::parse_coordinate(text).unwrap()
    }

    fn rect(x0: &str, x1: &str, y0: &str, y1: &str) -> Rect {
        Rect {
            x0: q(x0),
            x1: q(x1),
            y0: q(y0),
            y1: q(y1),
        }
    }

    fn point(x: &str, y: &str) -> Option<Point> {
        Some(Point::new(q(x), q(y)))
    }

    #[test]
    fn rectangles_against_an_l_shape() {
        // The L: [0,2] × [0,1] and [0,1] × [1,2].
        let l = Polygon::parse("POLYGON ((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0))", "l").unwrap();
        let edges = l.vertical_edges();
        let exact = [rect("0", "2", "0", "1"), rect("0", "1", "0", "2")];
        assert_eq!(compare(&edges, &exact), Difference::default());
        // Overlapping rectangles and shared edges change nothing.
        let overlapping = [
            rect("0", "1.5", "0", "1"),
            rect("1", "2", "0", "1"),
            rect("0", "1", "0.5", "2"),
        ];
        assert_eq!(compare(&edges, &overlapping), Difference::default());
        let short = [rect("0", "2", "0", "1"), rect("0", "1", "0", "1.5")];
        let d = compare(&edges, &short);
        assert_eq!(d.uncovered, point("0.5", "1.75"));
        assert_eq!(d.outside, None);
        let over = [rect("0", "2", "0", "1"), rect("0", "1.25", "0", "2")];
        let d = compare(&edges, &over);
        assert_eq!((d.uncovered, d.outside), (None, point("1.125", "1.5")));
    }

    #[test]
    fn holes_are_outside() {
        let frame = Polygon::parse(
            "POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))",
            "f",
        )
        .unwrap();
        let edges = frame.vertical_edges();
        let ring = [
            rect("0", "3", "0", "1"),
            rect("0", "3", "2", "3"),
            rect("0", "1", "0", "3"),
            rect("2", "3", "0", "3"),
        ];
        assert_eq!(compare(&edges, &ring), Difference::default());
        let full = [rect("0", "3", "0", "3")];
        assert_eq!(compare(&edges, &full).outside, point("1.5", "1.5"));
        let gap = &ring[..3];
        assert_eq!(compare(&edges, gap).uncovered, point("2.5", "1.5"));
    }

    use crate::region::{Pixel, Region};
    use proptest::prelude::*;

    /// Brute force on a grid of eighths: every coordinate below is a multiple of ¼, so no
    /// eighth-cell is cut by an edge and its centre decides for the whole cell.
    fn brute_force(region: &Region, rects: &[Rect]) -> (bool, bool) {
        let (mut uncovered, mut outside) = (false, false);
        for i in -8..40 {
            for j in -8..40 {
                let p = Point::new(
                    Rational::new(2 * i + 1, 16).unwrap(),
                    Rational::new(2 * j + 1, 16).unwrap(),
                );
                let inside =
                    region.contains(Pixel::new(i.div_euclid(8) as i32, j.div_euclid(8) as i32));
                let covered = rects.iter().any(|r| r.contains_inside(p));
                uncovered |= inside && !covered;
                outside |= covered && !inside;
            }
        }
        (uncovered, outside)
    }

    proptest! {
        #[test]
        fn agrees_with_brute_force(
            cells in proptest::collection::vec(any::<bool>(), 16),
            quarters in proptest::collection::vec((0i128..16, 1i128..8, 0i128..16, 1i128..8), 0..6),
        ) {
            let pixels = (0..16).filter(|&k| cells[k]).map(|k| Pixel::new(k as i32 % 4, k as i32 / 4));
            let region = Region::from_pixels(pixels).unwrap();
            prop_assume!(!region.is_empty());
            let polygon = Polygon::from_region(&region).unwrap();
            let quarter = |k: i128| Rational::new(k, 4).unwrap();
            let rects: Vec<Rect> = quarters
                .iter()
                .map(|&(x, w, y, h)| Rect {
                    x0: quarter(x - 2),
                    x1: quarter(x - 2 + w),
                    y0: quarter(y - 2),
                    y1: quarter(y - 2 + h),
                })
                .collect();
            let d = compare(&polygon.vertical_edges(), &rects);
            let (uncovered, outside) = brute_force(&region, &rects);
            prop_assert_eq!(d.uncovered.is_some(), uncovered);
            prop_assert_eq!(d.outside.is_some(), outside);
            // The witnesses are what they claim (checked a little off the centre, inside the
            // same open cell, so that no pixel boundary is hit).
            let off = |p: Point| Point::new(
                p.x.checked_add(Rational::new(1, 64).unwrap()).unwrap(),
                p.y.checked_add(Rational::new(1, 64).unwrap()).unwrap(),
            );
            let pixel_of = |p: Point| Pixel::new(p.x.floor() as i32, p.y.floor() as i32);
            if let Some(w) = d.uncovered.map(off) {
                prop_assert!(region.contains(pixel_of(w)));
                prop_assert!(!rects.iter().any(|r| r.contains_inside(w)));
            }
            if let Some(w) = d.outside.map(off) {
                prop_assert!(!region.contains(pixel_of(w)));
                prop_assert!(rects.iter().any(|r| r.contains_inside(w)));
            }
        }
    }
}
