//! Section 4 of *Lawn mowing and milling* (Theorems 2 and 3): lawn mowing by a TSP tour of
//! the lattice cells that meet the grass, and the bounding-box method of Fig. 9.
//!
//! S is the set of lattice points whose cells meet the grass ([`required_cells`]): pixel
//! centres for the unit square, hexagon centres (diameter-2 hexagons) for the unit disk. Any
//! tour of S mows the lawn (Lemma 1). The TSP heuristics here run on S in the motion's metric
//! (L1 for the square under rectilinear motion, Euclidean otherwise):
//!
//! - `lawn-mst`: double a minimum spanning tree and shortcut (preorder), αTSP = 2;
//! - `lawn-christofides`: MST plus a minimum-weight perfect matching of its odd-degree nodes,
//!   Euler circuit, shortcut, αTSP = 3/2. The matching: blossom on the complete graph up to
//!   400 odd nodes; beyond, for the square cutter, fusion-blossom on the Hanan grid of the odd
//!   nodes, whose graph metric is exactly L1, so still a minimum over ALL pairs, certified by
//!   its dual; for Euclidean motion a fusion-blossom matching on a nearest-neighbour graph,
//!   not proven minimum (`matching_optimal = 0`, with a proven lower bound). Where that exact
//!   solver is out of reach (a Hanan grid above a million vertices, e.g. 10^6 grass pixels:
//!   30 s and 3.8 GB of fusion-blossom), a greedy near-minimum matching, and the tour is
//!   certified within 3/2 of TSP(S) by the lower bound max(N, MST) instead (else the exact
//!   matching runs after all), so αTSP = 3/2 still holds on every run. Details and proofs in
//!   [`matching`];
//! - `lawn-2opt`: 2-opt and Or-opt (segments of 1 to 3) on 10-nearest-neighbour lists with
//!   don't-look bits, then a seeded iterated local search of local double-bridge kicks
//!   ([`local`]), started from the better of the two tours above;
//! - `lawn-box`: the concentric rectangles of Fig. 9 over the bounding box, joined by edge
//!   swaps, and the shorter of that and the Christofides tour, which removes the additive term
//!   of Theorem 2 (the paper's θ; see [`lawn_box`]).
//!
//! Theorem 2/3: a TSP tour with factor αTSP is at most αTSP (3ℓ* + 6) for the square with
//! rectilinear motion, times β = 2/√(2 + √2) ≈ 1.08 under free motion and γ = 2/√3 ≈ 1.15
//! for the disk. The registry states the rectilinear bounds (the default cutter); the others
//! are irrational factors and are in the docs of each function.
//!
//! Outputs: for the square with rectilinear motion every hop is expanded into a staircase of
//! unit moves (same L1 length), so the tour goes through the core [`checker`](crate::checker)
//! in lawn mode; for free motion and the disk the tour is the list of lattice points, checked
//! by [`crate::lawn_check`] with Euclidean lengths in milli-units.

use super::euler::{GridMultigraph, euler_shortcut};
use super::{Against, Algorithm, Cutter, Guarantee, Objective, Options, Output, Solution};
use crate::error::{Error, Result};
use crate::lawn_check::{centre, distance, required_cells};
use crate::region::{Pixel, Region};
use crate::tour::{CycleCover, Walk};
use petgraph::unionfind::UnionFind;
use std::collections::HashMap;

mod local;
mod matching;

/// The grass must be non-empty.
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::Precondition("the lawn has no grass".into()));
    }
    Ok(())
}

/// Points of S with their metric.
struct Points {
    cutter: Cutter,
    pts: Vec<Pixel>,
}

impl Points {
    fn new(region: &Region, cutter: Cutter) -> Points {
        Points {
            cutter,
            pts: required_cells(region, cutter),
        }
    }

    fn len(&self) -> usize {
        self.pts.len()
    }

    fn dist(&self, i: usize, j: usize) -> f64 {
        distance(self.cutter, self.pts[i], self.pts[j])
    }

    /// An exact integer key, monotone in the distance (L1, or the squared norm).
    fn key(&self, i: usize, j: usize) -> u64 {
        let (a, b) = (self.pts[i], self.pts[j]);
        // In i128: coordinates within ±MAX_COORD keep every key below 2^64, with no wrap.
        let delta = |a: i32, b: i32| i128::from(b) - i128::from(a);
        let (dx, dy) = (delta(a.x, b.x), delta(a.y, b.y));
        let key = match self.cutter {
            Cutter::Square => dx.abs() + dy.abs(),
            Cutter::SquareFree => dx * dx + dy * dy,
            Cutter::Disk => dx * dx + dx * dy + dy * dy,
        };
        u64::try_from(key).unwrap_or(u64::MAX)
    }

    /// The lattice neighbours at the smallest distance (4 on the square, 6 on the hexagons).
    fn unit_steps(&self) -> &'static [(i32, i32)] {
        match self.cutter {
            Cutter::Square | Cutter::SquareFree => &[(1, 0), (0, 1), (-1, 0), (0, -1)],
            Cutter::Disk => &[(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)],
        }
    }

    fn tour_length(&self, tour: &[usize]) -> f64 {
        (0..tour.len())
            .map(|k| self.dist(tour[k], tour[(k + 1) % tour.len()]))
            .sum()
    }
}

/// A static k-d tree over a subset of the points, for nearest *foreign* neighbours: every
/// node knows whether all its points lie in one component, so whole subtrees of the query's
/// own component are skipped.
struct KdTree {
    /// Point ids, permuted so that every node owns a contiguous range.
    ids: Vec<u32>,
    nodes: Vec<KdNode>,
    xy: Vec<(f64, f64)>,
}

#[derive(Clone, Copy)]
struct KdNode {
    lo: usize,
    hi: usize,
    min: (f64, f64),
    max: (f64, f64),
    /// The component of all points below, or `u32::MAX` when mixed.
    comp: u32,
    children: Option<(usize, usize)>,
}

impl KdTree {
    const LEAF: usize = 8;

    fn new(p: &Points, ids: Vec<usize>) -> KdTree {
        let xy: Vec<(f64, f64)> = p.pts.iter().map(|&q| centre(p.cutter, q)).collect();
        let mut t = KdTree {
            ids: ids.into_iter().map(|i| i as u32).collect(),
            nodes: Vec::new(),
            xy,
        };
        if !t.ids.is_empty() {
            t.build(0, t.ids.len(), 0);
        }
        t
    }

    fn build(&mut self, lo: usize, hi: usize, depth: usize) -> usize {
        let (mut min, mut max) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for &i in &self.ids[lo..hi] {
            let (x, y) = self.xy[i as usize];
            min = (min.0.min(x), min.1.min(y));
            max = (max.0.max(x), max.1.max(y));
        }
        let at = self.nodes.len();
        self.nodes.push(KdNode {
            lo,
            hi,
            min,
            max,
            comp: u32::MAX,
            children: None,
        });
        if hi - lo > Self::LEAF {
            let mid = (lo + hi) / 2;
            let xy = &self.xy;
            let by_x = (max.0 - min.0) >= (max.1 - min.1) || depth > 64;
            self.ids[lo..hi].select_nth_unstable_by(mid - lo, |&a, &b| {
                let (pa, pb) = (xy[a as usize], xy[b as usize]);
                let (ka, kb) = if by_x { (pa.0, pb.0) } else { (pa.1, pb.1) };
                ka.total_cmp(&kb)
            });
            let l = self.build(lo, mid, depth + 1);
            let r = self.build(mid, hi, depth + 1);
            self.nodes[at].children = Some((l, r));
        }
        at
    }

    /// Recomputes every node's component from `root` labels (bottom-up, children first).
    fn label(&mut self, root: &[usize]) {
        for k in (0..self.nodes.len()).rev() {
            let node = self.nodes[k];
            self.nodes[k].comp = match node.children {
                Some((l, r)) if self.nodes[l].comp == self.nodes[r].comp => self.nodes[l].comp,
                Some(_) => u32::MAX,
                None => {
                    let first = root[self.ids[node.lo] as usize] as u32;
                    if self.ids[node.lo..node.hi]
                        .iter()
                        .all(|&i| root[i as usize] as u32 == first)
                    {
                        first
                    } else {
                        u32::MAX
                    }
                }
            };
        }
    }

    /// Nearest point (by (key, id)) to point `i` in a component other than `own`, among those
    /// at distance at most `limit` (the best its component has found so far: without it, the
    /// queries from a large component's border searched far and took 6 s of the MST at 10^6).
    fn nearest_foreign(
        &self,
        p: &Points,
        root: &[usize],
        i: usize,
        own: usize,
        limit: f64,
    ) -> Option<(u64, usize)> {
        let mut best: Option<(u64, usize, f64)> = None;
        let mut stack = vec![0usize];
        let q = self.xy[i];
        while let Some(k) = stack.pop() {
            let node = &self.nodes[k];
            if node.comp == own as u32 {
                continue;
            }
            // Lower bound on the distance from q to the node's box (L2 ≤ L1, so L2 bounds both).
            let dx = (node.min.0 - q.0).max(0.0).max(q.0 - node.max.0);
            let dy = (node.min.1 - q.1).max(0.0).max(q.1 - node.max.1);
            let bound = (dx * dx + dy * dy).sqrt();
            if bound > best.map_or(limit, |b| b.2) + 1e-9 {
                continue;
            }
            match node.children {
                Some((l, r)) => {
                    // Visit the nearer child first (pushed last).
                    let centre_of = |n: &KdNode| {
                        ((n.min.0 + n.max.0) / 2.0 - q.0).abs()
                            + ((n.min.1 + n.max.1) / 2.0 - q.1).abs()
                    };
                    if centre_of(&self.nodes[l]) < centre_of(&self.nodes[r]) {
                        stack.extend([r, l]);
                    } else {
                        stack.extend([l, r]);
                    }
                }
                None => {
                    for &j in &self.ids[node.lo..node.hi] {
                        let j = j as usize;
                        if root[j] == own {
                            continue;
                        }
                        let cand = (p.key(i, j), j);
                        if best.is_none_or(|b| cand < (b.0, b.1)) {
                            best = Some((cand.0, cand.1, p.dist(i, j)));
                        }
                    }
                }
            }
        }
        best.map(|(k, j, _)| (k, j))
    }
}

/// The id of a lattice point of S: a dense array over the bounding box when it has at most
/// [`PointIndex::DENSE_CELLS`] cells per point (a lookup is one load; the SipHash map it
/// replaced took about 1 s of the MST at 10^6 points), else a hash map.
enum PointIndex {
    Dense {
        min: (i64, i64),
        width: i64,
        height: i64,
        ids: Vec<u32>,
    },
    Sparse(HashMap<Pixel, usize>),
}

impl PointIndex {
    /// Cells of the bounding box per point up to which the dense array is used (4 bytes a cell).
    const DENSE_CELLS: i64 = 16;

    fn new(pts: &[Pixel]) -> PointIndex {
        let (mut lo, mut hi) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
        for q in pts {
            let (x, y) = (i64::from(q.x), i64::from(q.y));
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        let (width, height) = (hi.0 - lo.0 + 1, hi.1 - lo.1 + 1);
        let dense = !pts.is_empty()
            && pts.len() < u32::MAX as usize
            && width
                .checked_mul(height)
                .is_some_and(|c| c <= Self::DENSE_CELLS * pts.len() as i64);
        if !dense {
            return PointIndex::Sparse(pts.iter().enumerate().map(|(i, &q)| (q, i)).collect());
        }
        let mut ids = vec![u32::MAX; (width * height) as usize];
        for (i, q) in pts.iter().enumerate() {
            ids[((i64::from(q.y) - lo.1) * width + i64::from(q.x) - lo.0) as usize] = i as u32;
        }
        PointIndex::Dense {
            min: lo,
            width,
            height,
            ids,
        }
    }

    fn get(&self, q: Pixel) -> Option<usize> {
        match self {
            PointIndex::Dense {
                min,
                width,
                height,
                ids,
            } => {
                let (x, y) = (i64::from(q.x) - min.0, i64::from(q.y) - min.1);
                if x < 0 || y < 0 || x >= *width || y >= *height {
                    return None;
                }
                let id = ids[(y * width + x) as usize];
                (id != u32::MAX).then_some(id as usize)
            }
            PointIndex::Sparse(map) => map.get(&q).copied(),
        }
    }
}

/// An exact minimum spanning tree of S: Kruskal on the unit lattice edges (the smallest
/// possible distance), then Borůvka rounds joining components by their nearest foreign
/// points, searched only from points with a lattice neighbour outside their component (a
/// closest pair between components always has such an endpoint: stepping towards the other
/// point along a lattice direction gets strictly closer). Ties are broken by (key, i, j).
fn minimum_spanning_tree(p: &Points) -> Vec<(usize, usize)> {
    let n = p.len();
    let index = PointIndex::new(&p.pts);
    let mut uf = UnionFind::new(n);
    let mut edges = Vec::with_capacity(n.saturating_sub(1));
    // All unit edges weigh the minimum, so any spanning forest of them belongs to an MST; a
    // depth-first forest is path-like and leaves few odd-degree nodes for Christofides.
    let mut stack: Vec<(usize, usize)> = Vec::new();
    let mut seen = vec![false; n];
    for s in 0..n {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        stack.push((s, 0));
        while let Some(top) = stack.last_mut() {
            let (v, k) = *top;
            let Some(&(dx, dy)) = p.unit_steps().get(k) else {
                stack.pop();
                continue;
            };
            top.1 += 1;
            let q = Pixel::new(p.pts[v].x + dx, p.pts[v].y + dy);
            if let Some(w) = index.get(q)
                && !seen[w]
            {
                seen[w] = true;
                uf.union(v, w);
                edges.push((v, w));
                stack.push((w, 0));
            }
        }
    }
    // After the unit edges every lattice neighbour in S shares the point's component, so the
    // points with a lattice neighbour outside S are the border of every later round too:
    // computed once (recomputing it each round took most of lawn-mst's 5.4 s at 10^6).
    let border: Vec<usize> = (0..n)
        .filter(|&i| {
            p.unit_steps().iter().any(|&(dx, dy)| {
                index
                    .get(Pixel::new(p.pts[i].x + dx, p.pts[i].y + dy))
                    .is_none()
            })
        })
        .collect();
    // The tree's geometry does not change between rounds: built once, relabelled per round.
    let mut tree = KdTree::new(p, border.clone());
    while edges.len() + 1 < n {
        let root: Vec<usize> = (0..n).map(|i| uf.find_mut(i)).collect();
        tree.label(&root);
        let mut best: HashMap<usize, (u64, usize, usize)> = HashMap::new();
        for &i in &border {
            let limit = best
                .get(&root[i])
                .map_or(f64::INFINITY, |&(_, a, b)| p.dist(a, b));
            if let Some((k, j)) = tree.nearest_foreign(p, &root, i, root[i], limit) {
                let cand = (k, i.min(j), i.max(j));
                let e = best.entry(root[i]).or_insert(cand);
                if cand < *e {
                    *e = cand;
                }
            }
        }
        let mut chosen: Vec<(u64, usize, usize)> = best.into_values().collect();
        chosen.sort_unstable();
        for (_, i, j) in chosen {
            if uf.union(i, j) {
                edges.push((i, j));
            }
        }
    }
    edges
}

/// Preorder of a tree given by its edges, from node 0 (the doubled tree, shortcut).
fn preorder(n: usize, edges: &[(usize, usize)]) -> Vec<usize> {
    let mut adj = vec![Vec::new(); n];
    for &(a, b) in edges {
        adj[a].push(b);
        adj[b].push(a);
    }
    let mut seen = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let mut stack = vec![0];
    while let Some(v) = stack.pop() {
        if seen[v] {
            continue;
        }
        seen[v] = true;
        order.push(v);
        for &w in adj[v].iter().rev() {
            if !seen[w] {
                stack.push(w);
            }
        }
    }
    order
}

/// Christofides: MST + minimum-weight perfect matching on the odd-degree nodes (see
/// [`matching`] for which matching at which size, and what is proven), Euler circuit,
/// shortcut. Returns the tour and the matching.
///
/// When the exact matching is out of reach ([`matching::exact_within_reach`]), the
/// near-minimum one is used and, for the square cutter, the tour is certified instead: αTSP =
/// 3/2 holds when 2·length ≤ 3·max(N, MST weight), both lower bounds on TSP(S) (N distinct
/// lattice points, every hop at least one unit); when it does not, the exact matching is
/// solved after all. So the registered 3/2 holds on every run. (lawn-scattered 10^6: tour
/// 1.09 N, far inside 3/2 N.)
fn christofides(p: &Points, mst: &[(usize, usize)]) -> (Vec<usize>, matching::OddMatching) {
    let n = p.len();
    let mut deg = vec![0u32; n];
    for &(a, b) in mst {
        deg[a] += 1;
        deg[b] += 1;
    }
    let odd: Vec<usize> = (0..n).filter(|&i| deg[i] % 2 == 1).collect();
    let tour_with = |m: &matching::OddMatching| {
        let mut edges: Vec<(usize, usize)> = mst.to_vec();
        edges.extend_from_slice(&m.pairs);
        euler_shortcut(n, &edges)
    };
    let m = matching::odd_matching(p, &odd);
    let tour = tour_with(&m);
    if m.optimal || p.cutter != Cutter::Square || three_halves_certified(p, mst, &tour) {
        return (tour, m);
    }
    let exact = matching::minimum_matching(p, &odd);
    (tour_with(&exact), exact)
}

/// Whether 2·length(tour) ≤ 3·max(N, MST weight) under L1 (square cutter, N ≥ 2): both are
/// lower bounds on the shortest tour of S, so the tour is within 3/2 of it.
fn three_halves_certified(p: &Points, mst: &[(usize, usize)], tour: &[usize]) -> bool {
    let l1 = |a: usize, b: usize| p.key(a, b);
    let length: u64 = (0..tour.len())
        .map(|k| l1(tour[k], tour[(k + 1) % tour.len()]))
        .sum();
    let mst_weight: u64 = mst.iter().map(|&(a, b)| l1(a, b)).sum();
    let lower = (p.len() as u64).max(mst_weight);
    p.len() >= 2 && 2 * length <= 3 * lower
}

/// Fig. 9: concentric rectangles of pixel centres over the bounding box, each joined to the
/// next by swapping two facing edges of a common unit square (free); the innermost, when it
/// is a single row or column, is joined by a doubled edge (the paper's extra two units).
///
/// Refused when the bounding box has more than [`MAX_PIXELS`](crate::region::MAX_PIXELS)
/// cells: the tour visits every cell of the box, so two pixels far apart would otherwise ask
/// for a box of 10^10 cells (16 GB) or more.
fn box_tour(region: &Region) -> Result<Walk> {
    let b = region.bbox();
    let cells = b.width().saturating_mul(b.height());
    if cells > crate::region::MAX_PIXELS {
        return Err(Error::Precondition(format!(
            "lawn-box: the bounding box is {} x {} = {cells} cells; expected at most {} (the \
             box tour visits every cell of the box)",
            b.width(),
            b.height(),
            crate::region::MAX_PIXELS
        )));
    }
    // Both sides are at most MAX_PIXELS, so they fit an i32.
    let (w, h) = (b.width() as i32, b.height() as i32);
    let rect = Region::rectangle(w, h);
    let mut g = GridMultigraph::new(rect.len());
    let at = |x: i32, y: i32| rect.index_of(Pixel::new(x, y)).expect("inside the box");
    let mut k = 0;
    while 2 * k < w && 2 * k < h {
        let (x0, y0, x1, y1) = (k, k, w - 1 - k, h - 1 - k);
        // The ring as a closed walk (degenerate rings are back-and-forth paths).
        let mut ring = Vec::new();
        for x in x0..=x1 {
            ring.push(at(x, y0));
        }
        for y in y0 + 1..=y1 {
            ring.push(at(x1, y));
        }
        if y1 > y0 {
            for x in (x0..x1).rev() {
                ring.push(at(x, y1));
            }
        } else {
            for x in (x0 + 1..x1).rev() {
                ring.push(at(x, y0));
            }
        }
        // Down the left side (for a single column, back down the same column).
        for y in (y0 + 1..y1).rev() {
            ring.push(at(x0, y));
        }
        g.add_closed_walk(&rect, &ring);
        if k > 0 {
            // Join to ring k - 1 by swapping the two left sides of square (k-1..k, y0..y0+1).
            let (a, b2, c, d) = (at(k - 1, y0), at(k - 1, y0 + 1), at(k, y0), at(k, y0 + 1));
            if y1 > y0 && x1 > x0 && g.has_between(&rect, a, b2) && g.has_between(&rect, c, d) {
                g.remove_between(&rect, a, b2);
                g.remove_between(&rect, c, d);
                g.add_between(&rect, a, c);
                g.add_between(&rect, b2, d);
            } else {
                g.add_between(&rect, a, c);
                g.add_between(&rect, a, c);
            }
        }
        k += 1;
    }
    let walk = g.into_walk(&rect, 0);
    Ok(walk
        .into_iter()
        .map(|q| Pixel::new(q.x + b.min_x, q.y + b.min_y))
        .collect())
}

/// Turns a tour of S into the output walk: staircases of unit moves for rectilinear motion,
/// the lattice points themselves otherwise.
fn output_walk(p: &Points, tour: &[usize]) -> Walk {
    if p.cutter != Cutter::Square {
        return tour.iter().map(|&i| p.pts[i]).collect();
    }
    let mut walk = Vec::new();
    for k in 0..tour.len() {
        let (a, b) = (p.pts[tour[k]], p.pts[tour[(k + 1) % tour.len()]]);
        let mut q = a;
        walk.push(q);
        while q.x != b.x {
            q.x += b.x.cmp(&q.x) as i32;
            if q != b {
                walk.push(q);
            }
        }
        while q.y != b.y {
            q.y += b.y.cmp(&q.y) as i32;
            if q != b {
                walk.push(q);
            }
        }
    }
    walk
}

/// A lower bound on the optimal lawn tour from the area swept (covered area ≤ L·w + a), in
/// the reported units (exact L1 units, or milli-units for Euclidean motion), rounded down.
pub fn area_lower_bound(region: &Region, cutter: Cutter) -> i64 {
    let area = region.len() as f64;
    let (w, a, scale) = match cutter {
        Cutter::Square => (1.0, 1.0, 1.0),
        Cutter::SquareFree => (std::f64::consts::SQRT_2, 1.0, 1000.0),
        Cutter::Disk => (2.0, std::f64::consts::PI, 1000.0),
    };
    ((area - a).max(0.0) / w * scale).floor() as i64
}

/// A lower bound on the optimal lawn tour from the spread of the grass, in the reported units,
/// for the unit square cutters (`None` for the disk).
///
/// The square cutter covers [c − 1/2, c + 1/2] in x around its centre c, so covering the left
/// side of the leftmost pixel (centre x_min) needs a centre with x ≤ x_min, and the rightmost
/// pixel one with x ≥ x_max; likewise in y. A closed path through points that far apart in x
/// and y (ΔX = W − 1, ΔY = H − 1 for the W × H bounding box of the pixels) has L1 length at
/// least 2ΔX + 2ΔY, and Euclidean length at least 2√(ΔX² + ΔY²) (the shortest convex set with
/// those extents is the diagonal segment, walked there and back). For the disk, whose walks lie
/// on a hexagonal lattice, the bound is not made.
pub fn spread_lower_bound(region: &Region, cutter: Cutter) -> Option<i64> {
    if region.is_empty() {
        return Some(0);
    }
    let b = region.bbox();
    let (dx, dy) = (b.width() as i64 - 1, b.height() as i64 - 1);
    match cutter {
        Cutter::Square => Some(2 * dx + 2 * dy),
        // Milli-units, rounded down (the i64 -> f64 conversion is exact below 2^53).
        Cutter::SquareFree => Some((2000.0 * ((dx * dx + dy * dy) as f64).sqrt()).floor() as i64),
        Cutter::Disk => None,
    }
}

/// The most unit moves an output walk of the square cutter may have: a tour of few pixels far
/// apart is short to describe but expands to one pixel per unit move, so a two-line pixel
/// list could ask for billions ([`crate::region::MAX_PIXELS`], as for regions).
pub const MAX_WALK_MOVES: u64 = crate::region::MAX_PIXELS as u64;

fn solution(region: &Region, p: &Points, tour: &[usize], mst: Option<f64>) -> Result<Solution> {
    if p.cutter == Cutter::Square {
        let moves: u64 = (0..tour.len())
            .map(|k| {
                let (a, b) = (p.pts[tour[k]], p.pts[tour[(k + 1) % tour.len()]]);
                u64::from(a.x.abs_diff(b.x)) + u64::from(a.y.abs_diff(b.y))
            })
            .sum();
        if moves > MAX_WALK_MOVES {
            return Err(crate::error::Error::invalid(format!(
                "the lawn tour has {moves} unit moves; expected at most {MAX_WALK_MOVES} (the \
                 walk lists one pixel per move: the pixels lie too far apart)"
            )));
        }
    }
    let mut s = Solution::default();
    s.outputs.push(Output {
        objective: Objective::LawnLength,
        cover: CycleCover::tour(output_walk(p, tour)),
    });
    s.certificates.insert("points".into(), p.len() as i64);
    s.certificates.insert(
        "area_lower_bound".into(),
        area_lower_bound(region, p.cutter),
    );
    if let Some(w) = mst {
        let scale = if p.cutter == Cutter::Square {
            1.0
        } else {
            1000.0
        };
        s.certificates
            .insert("mst_weight".into(), (w * scale).floor() as i64);
    }
    Ok(s)
}

fn mst_weight(p: &Points, mst: &[(usize, usize)]) -> f64 {
    mst.iter().map(|&(a, b)| p.dist(a, b)).sum()
}

/// `lawn-mst`: doubled minimum spanning tree, shortcut. Length ≤ 2 · TSP(S) ≤ 2 (3ℓ* + 6)
/// for the square with rectilinear motion (Theorem 2), × β (free motion), × γ (disk).
///
/// # Complexity
/// O(N log N) expected for lawns of few components (Borůvka rounds over component borders).
pub(crate) fn lawn_mst(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    let p = Points::new(region, opts.cutter);
    let mst = minimum_spanning_tree(&p);
    let tour = preorder(p.len(), &mst);
    solution(region, &p, &tour, Some(mst_weight(&p, &mst)))
}

/// `lawn-christofides`: length ≤ 3/2 · TSP(S) ≤ 3/2 (3ℓ* + 6) for the square with rectilinear
/// motion (Theorem 2), × β (free motion), × γ (disk). Certificates `matching_weight`,
/// `matching_optimal` (1 when the matching is proven minimum over all pairs: always for the
/// square cutter, see [`matching`]), `matching_lower_bound` (proven) and `odd_nodes`, in the
/// reported units (L1, or milli-units rounded down).
///
/// # Complexity
/// O(N log N) for the MST; the matching of the M odd-degree nodes: O(M³) blossom up to
/// [`matching::COMPLETE_LIMIT`], beyond it fusion-blossom on a graph of O(bounding box) or
/// O(M log M) vertices, and beyond [`matching::EXACT_GRID_LIMIT`] grid vertices the
/// O(M log M) greedy matching with an O(N) certificate. Measured (`/usr/bin/time mowmill
/// solve --algo lawn-christofides`, gen lawn-scattered --n 1000000 --seed 1, 2026-12-07): 36 s
/// wall, 30 s user, 3.8 GB with the exact matching; 1.4 s, 1.2 s user, 0.21 GB with the
/// certified one (tour 1,092,982 against 1,082,522, +0.97%; random-simple +0.62%).
pub(crate) fn lawn_christofides(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    let p = Points::new(region, opts.cutter);
    let mst = minimum_spanning_tree(&p);
    let (tour, m) = christofides(&p, &mst);
    let mut s = solution(region, &p, &tour, Some(mst_weight(&p, &mst)))?;
    let scale = if p.cutter == Cutter::Square {
        1.0
    } else {
        1000.0
    };
    s.certificates
        .insert("matching_weight".into(), (m.weight * scale).floor() as i64);
    s.certificates
        .insert("matching_optimal".into(), i64::from(m.optimal));
    s.certificates.insert(
        "matching_lower_bound".into(),
        (m.lower_bound * scale).floor() as i64,
    );
    s.certificates
        .insert("odd_nodes".into(), (2 * m.pairs.len()) as i64);
    Ok(s)
}

/// `lawn-2opt`: 2-opt and Or-opt with neighbour lists and don't-look bits, then a short
/// iterated local search ([`local`]), from the better of the MST and Christofides tours;
/// never longer than its start.
pub(crate) fn lawn_two_opt(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    let p = Points::new(region, opts.cutter);
    let mst = minimum_spanning_tree(&p);
    let mut start = preorder(p.len(), &mst);
    let (c, _) = christofides(&p, &mst);
    if p.tour_length(&c) < p.tour_length(&start) {
        start = c;
    }
    let tour = local::improve(&p, start);
    solution(region, &p, &tour, Some(mst_weight(&p, &mst)))
}

/// `lawn-box`: the shorter of the Fig. 9 bounding-box tour and the Christofides tour (the
/// paper's way to remove the additive term, square cutter, rectilinear motion). Square cutters
/// only: the disk variant (concentric circles in the smallest enclosing disk) is not
/// implemented.
///
/// # Guarantee
/// The paper: when the box's short side a exceeds 6, ℓ* ≥ 2(a + b − 2) > 20, so the additive
/// term 6·αTSP of Theorem 2 is below (6/20)·αTSP·ℓ*; otherwise the box tour is within 3αTSP.
/// The factor is therefore 3αTSP + (3/10)·αTSP: θ = 3/10 is the paper's value for αTSP = 1,
/// and for Christofides (αTSP = 3/2) it is 9/20, giving 9/2 + 9/20 = 99/20 (not 3α + 3/10 =
/// 24/5, which this registry stated before).
pub(crate) fn lawn_box(region: &Region, opts: &Options) -> Result<Solution> {
    precondition(region)?;
    if opts.cutter == Cutter::Disk {
        return Err(Error::Invalid(
            "--cutter disk does not apply to lawn-box: it implements the bounding-box method \
             for square cutters only"
                .into(),
        ));
    }
    // The box tour first: it refuses a box too large to walk before any other work.
    let boxed = box_tour(region)?;
    let p = Points::new(region, opts.cutter);
    let mst = minimum_spanning_tree(&p);
    let (tour, _) = christofides(&p, &mst);
    let box_len: f64 = (0..boxed.len())
        .map(|k| distance(p.cutter, boxed[k], boxed[(k + 1) % boxed.len()]))
        .sum();
    let mut s = solution(region, &p, &tour, Some(mst_weight(&p, &mst)))?;
    let chose_box = box_len < p.tour_length(&tour) - 1e-9;
    if chose_box {
        s.outputs[0].cover = CycleCover::tour(boxed);
    }
    s.certificates
        .insert("chose_box".into(), i64::from(chose_box));
    Ok(s)
}

const fn rectilinear(
    num: i64,
    den: i64,
    add: i64,
    theorem: &'static super::theorems::Theorem,
    source: &'static str,
) -> Guarantee {
    Guarantee::new(
        Objective::LawnLength,
        super::theorems::Bound::new(super::Quantity::Value, num, den, add, Against::Opt),
        super::When::Always,
        theorem,
        source,
    )
}

/// The registry entry of `lawn-mst`: a doubled minimum spanning tree of the cell centres,
/// shortcut ([`lawn_mst`]).
///
/// # Guarantee
///
/// Theorem 2 of *Lawn mowing and milling*: a TSP tour of the lattice cells that meet the grass,
/// with factor αTSP, has length ≤ αTSP (3ℓ* + 6), ℓ* the optimal lawn-mowing length, for the
/// unit square under rectilinear motion (the default cutter); free motion and the disk multiply
/// it by β ≈ 1.08 and γ ≈ 1.15 (Theorem 3), irrational factors that are not registered. Here αTSP = 2, registered as `lawn-length <= 6 OPT + 12` (Theorem 2,
/// our reading), square cutter, rectilinear motion.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("lawn-mst").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::LawnLength).unwrap();
/// assert!(tour.valid);
/// // A 4 x 2 lawn: the 8 pixel centres in a ring.
/// assert_eq!(tour.length, 8);
/// ```
pub(crate) const LAWN_MST: Algorithm = Algorithm {
    name: "lawn-mst",
    summary: "lawn mowing: doubled MST of the cell centres, shortcut (Theorems 2-3, alpha = 2)",
    objectives: &[Objective::LawnLength],
    guarantees: &[rectilinear(
        6,
        1,
        12,
        &crate::theorems::MILLING_THM_2,
        "Theorem 2 of Lawn mowing and milling, square cutter, rectilinear",
    )],
    claims: &[crate::theorems::Claim::reading(
        &crate::theorems::MILLING_THM_2,
        &[crate::Objective::LawnLength],
        "alpha_TSP = 2 (doubled MST; 2-opt starts from it), square cutter, rectilinear motion",
    )],
    requires: "some grass",
    precondition,
    run: lawn_mst,
    discrete: None,
    ortho: None,
    by_default: true,
};

/// The registry entry of `lawn-christofides`: Christofides on the cell centres
/// ([`lawn_christofides`]).
///
/// # Guarantee
///
/// Theorem 2 of *Lawn mowing and milling*: a TSP tour of the lattice cells that meet the grass,
/// with factor αTSP, has length ≤ αTSP (3ℓ* + 6), ℓ* the optimal lawn-mowing length, for the
/// unit square under rectilinear motion (the default cutter); free motion and the disk multiply
/// it by β ≈ 1.08 and γ ≈ 1.15 (Theorem 3), irrational factors that are not registered. Here αTSP = 3/2, registered as `lawn-length <= (9 OPT + 18)/2`
/// (Theorem 2 with Christofides), square cutter, rectilinear motion. αTSP = 3/2 holds on
/// every run: by the minimum matching (proven, `matching_optimal = 1`) while the exact solver
/// is within reach, beyond it by the certificate 2·length ≤ 3·max(N, MST) ≤ 3·TSP(S) on the
/// tour of a near-minimum matching (`matching_optimal = 0`), the exact matching being solved
/// whenever that certificate fails.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("lawn-christofides").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::LawnLength).unwrap();
/// assert!(tour.valid);
/// // A 4 x 2 lawn: the 8 pixel centres in a ring.
/// assert_eq!(tour.length, 8);
/// ```
pub(crate) const LAWN_CHRISTOFIDES: Algorithm = Algorithm {
    name: "lawn-christofides",
    summary: "lawn mowing: Christofides on the cell centres (Theorems 2-3, alpha = 3/2)",
    objectives: &[Objective::LawnLength],
    guarantees: &[rectilinear(
        9,
        2,
        18,
        &crate::theorems::MILLING_THM_2_CHRISTOFIDES,
        "Theorem 2 of Lawn mowing and milling, square cutter, rectilinear",
    )],
    claims: &[crate::theorems::Claim::paper(
        &crate::theorems::MILLING_THM_2_CHRISTOFIDES,
        &[crate::Objective::LawnLength],
    )],
    requires: "some grass",
    precondition,
    run: lawn_christofides,
    discrete: None,
    ortho: None,
    by_default: true,
};

/// The registry entry of `lawn-2opt`: 2-opt and Or-opt started from the better of the MST and
/// Christofides tours ([`lawn_two_opt`]).
///
/// # Guarantee
///
/// Theorem 2 of *Lawn mowing and milling*: a TSP tour of the lattice cells that meet the grass,
/// with factor αTSP, has length ≤ αTSP (3ℓ* + 6), ℓ* the optimal lawn-mowing length, for the
/// unit square under rectilinear motion (the default cutter); free motion and the disk multiply
/// it by β ≈ 1.08 and γ ≈ 1.15 (Theorem 3), irrational factors that are not registered. The local search only shortens its start, which is at most the
/// doubled-MST tour (αTSP = 2): registered as `lawn-length <= 6 OPT + 12` (Theorem 2, our
/// reading), square cutter, rectilinear motion.
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "####\n",
///     "####\n",
/// ));
/// let algorithm = algorithms::find("lawn-2opt").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::LawnLength).unwrap();
/// assert!(tour.valid);
/// // A 4 x 2 lawn: the 8 pixel centres in a ring.
/// assert_eq!(tour.length, 8);
/// ```
pub(crate) const LAWN_TWO_OPT: Algorithm = Algorithm {
    name: "lawn-2opt",
    summary: "lawn mowing: 2-opt/Or-opt from the better of the MST and Christofides tours",
    objectives: &[Objective::LawnLength],
    guarantees: &[rectilinear(
        6,
        1,
        12,
        &crate::theorems::MILLING_THM_2,
        "Theorem 2 of Lawn mowing and milling (its start), square, rectilinear",
    )],
    claims: &[crate::theorems::Claim::reading(
        &crate::theorems::MILLING_THM_2,
        &[crate::Objective::LawnLength],
        "alpha_TSP = 2 (doubled MST; 2-opt starts from it), square cutter, rectilinear motion",
    )],
    requires: "some grass",
    precondition,
    run: lawn_two_opt,
    discrete: None,
    ortho: None,
    by_default: true,
};

/// The registry entry of `lawn-box`: the shorter of the bounding-box rings of Fig. 9 and the
/// Christofides tour ([`lawn_box`]).
///
/// # Guarantee
///
/// The bounding-box method removes the additive term of Theorem 2: with Christofides
/// (αTSP = 3/2) and the paper's θ read as 9/20 ([`lawn_box`] derives it), the tour has length
/// ≤ 3αTSP + (3/10)·αTSP = 99/20 times the optimum (Theorem 3 of *Lawn mowing and milling*).
/// Registered as `lawn-length <= 99/20 OPT`, square cutter, rectilinear motion; `--cutter disk`
/// is refused (a precondition of this method).
///
/// # Example
///
/// ```
/// use mowmill_algorithms::{self as algorithms, Objective, Options};
/// use mowmill_core::region::Region;
///
/// let region = Region::from_ascii(concat!(
///     "#####\n",
///     "#####\n",
///     "##.##\n",
///     "#####\n",
///     "#####\n",
/// ));
/// let algorithm = algorithms::find("lawn-box").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::LawnLength).unwrap();
/// assert!(tour.valid);
/// // A 5 x 5 lawn with a one-pixel hole: a ring through its 24 pixels.
/// assert_eq!(tour.length, 24);
/// ```
pub(crate) const LAWN_BOX: Algorithm = Algorithm {
    name: "lawn-box",
    summary: "lawn mowing: shorter of the bounding-box rings (Fig. 9) and Christofides",
    objectives: &[Objective::LawnLength],
    guarantees: &[rectilinear(
        99,
        20,
        0,
        &crate::theorems::MILLING_THM_3,
        "Section 4 of Lawn mowing and milling (3 alpha + alpha 3/10, alpha = 3/2), square, rectilinear",
    )],
    claims: &[crate::theorems::Claim::paper(
        &crate::theorems::MILLING_THM_3,
        &[crate::Objective::LawnLength],
    )],
    requires: "some grass",
    precondition,
    run: lawn_box,
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// Prim's algorithm on the complete graph, for comparison.
    fn brute_mst_weight(p: &Points) -> f64 {
        let n = p.len();
        let mut in_tree = vec![false; n];
        let mut best = vec![f64::INFINITY; n];
        best[0] = 0.0;
        let mut total = 0.0;
        for _ in 0..n {
            let v = (0..n)
                .filter(|&i| !in_tree[i])
                .min_by(|&a, &b| best[a].total_cmp(&best[b]))
                .unwrap();
            in_tree[v] = true;
            total += best[v];
            for w in 0..n {
                if !in_tree[w] {
                    best[w] = best[w].min(p.dist(v, w));
                }
            }
        }
        total
    }

    #[test]
    fn spanning_tree_is_minimum_for_every_metric() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        for trial in 0..60i32 {
            let k = 2 + trial % 40;
            let spread = 3 + trial;
            let pixels: Vec<Pixel> = (0..k)
                .map(|_| Pixel::new(rng.random_range(0..spread), rng.random_range(0..spread)))
                .collect();
            let region = Region::from_pixels(pixels).unwrap();
            for cutter in [Cutter::Square, Cutter::SquareFree, Cutter::Disk] {
                let p = Points::new(&region, cutter);
                let mst = minimum_spanning_tree(&p);
                assert_eq!(mst.len() + 1, p.len());
                let w = mst_weight(&p, &mst);
                assert!((w - brute_mst_weight(&p)).abs() < 1e-6, "{cutter:?}: {w}");
            }
        }
    }

    fn random_points(rng: &mut rand_chacha::ChaCha8Rng, k: i32, spread: i32) -> Region {
        let pixels: Vec<Pixel> = (0..k)
            .map(|_| Pixel::new(rng.random_range(0..spread), rng.random_range(0..spread)))
            .collect();
        Region::from_pixels(pixels).unwrap()
    }

    #[test]
    fn neighbour_lists_equal_brute_force() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        for trial in 0..40i32 {
            let region = random_points(&mut rng, 2 + 3 * trial, 4 + 2 * trial);
            for cutter in [Cutter::Square, Cutter::SquareFree, Cutter::Disk] {
                let p = Points::new(&region, cutter);
                let got = local::nearest_neighbours(&p, local::NEIGHBOURS);
                for (i, list) in got.iter().enumerate() {
                    let mut all: Vec<(u64, usize)> = (0..p.len())
                        .filter(|&j| j != i)
                        .map(|j| (p.key(i, j), j))
                        .collect();
                    all.sort_unstable();
                    let want: Vec<usize> = all
                        .iter()
                        .take(local::NEIGHBOURS)
                        .map(|&(_, j)| j)
                        .collect();
                    assert_eq!(list, &want, "{cutter:?} trial {trial} point {i}");
                }
            }
        }
    }

    #[test]
    fn local_search_never_lengthens_its_start() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(12);
        for trial in 0..30i32 {
            let region = random_points(&mut rng, 3 + 4 * trial, 5 + 2 * trial);
            for cutter in [Cutter::Square, Cutter::SquareFree, Cutter::Disk] {
                let p = Points::new(&region, cutter);
                // A random start, and the MST tour.
                let mut random: Vec<usize> = (0..p.len()).collect();
                for k in (1..random.len()).rev() {
                    random.swap(k, rng.random_range(0..=k));
                }
                let mst = minimum_spanning_tree(&p);
                for start in [random, preorder(p.len(), &mst)] {
                    let before = p.tour_length(&start);
                    let tour = local::improve(&p, start);
                    let mut sorted = tour.clone();
                    sorted.sort_unstable();
                    assert_eq!(sorted, (0..p.len()).collect::<Vec<_>>(), "a permutation");
                    assert!(p.tour_length(&tour) <= before, "{cutter:?} trial {trial}");
                }
            }
        }
    }

    #[test]
    fn l1_matching_at_scale_equals_the_complete_blossom() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(13);
        for trial in 0..12i32 {
            let region = random_points(&mut rng, 40 + 20 * trial, 12 + 4 * trial);
            let p = Points::new(&region, Cutter::Square);
            let mut odd: Vec<usize> = (0..p.len()).collect();
            odd.truncate(p.len() & !1);
            let exact = matching::complete_for_tests(&p, &odd).weight;
            let (hanan, spanner) = matching::l1_routes_for_tests(&p, &odd);
            assert_eq!(hanan, exact, "trial {trial}: Hanan grid");
            assert_eq!(spanner, exact, "trial {trial}: spanner");
        }
    }

    #[test]
    fn near_minimum_matching_is_perfect_and_not_below_the_minimum() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(14);
        for trial in 0..20i32 {
            let region = random_points(&mut rng, 10 + 10 * trial, 8 + 3 * trial);
            for cutter in [Cutter::Square, Cutter::SquareFree, Cutter::Disk] {
                let p = Points::new(&region, cutter);
                let mut odd: Vec<usize> = (0..p.len()).collect();
                odd.truncate(p.len() & !1);
                // Small inputs keep the exact matching.
                assert!(matching::exact_within_reach(&p, &odd));
                let near = matching::near_minimum(&p, &odd);
                let mut seen: Vec<usize> = near.pairs.iter().flat_map(|&(a, b)| [a, b]).collect();
                seen.sort_unstable();
                assert_eq!(
                    seen, odd,
                    "{cutter:?} trial {trial}: perfect on the odd nodes"
                );
                let exact = matching::complete_for_tests(&p, &odd).weight;
                assert!(near.weight >= exact - 1e-6, "{cutter:?} trial {trial}");
                assert!(near.lower_bound <= exact + 1e-6, "{cutter:?} trial {trial}");
                assert!(!near.optimal);
            }
        }
    }

    /// The shortest tour by trying every order (n ≤ 7).
    fn brute_tsp(p: &Points) -> f64 {
        fn extend(p: &Points, tour: &mut Vec<usize>, used: &mut [bool], best: &mut f64) {
            if tour.len() == p.len() {
                *best = best.min(p.tour_length(tour));
                return;
            }
            for v in 1..p.len() {
                if !used[v] {
                    used[v] = true;
                    tour.push(v);
                    extend(p, tour, used, best);
                    tour.pop();
                    used[v] = false;
                }
            }
        }
        let mut best = f64::INFINITY;
        let mut used = vec![false; p.len()];
        used[0] = true;
        extend(p, &mut vec![0], &mut used, &mut best);
        best
    }

    #[test]
    fn three_halves_certificate_is_sound() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(15);
        let mut certified = 0;
        for trial in 0..200i32 {
            let region = random_points(&mut rng, 2 + trial % 6, 2 + trial % 5);
            let p = Points::new(&region, Cutter::Square);
            if p.len() < 2 {
                continue;
            }
            let mst = minimum_spanning_tree(&p);
            let opt = brute_tsp(&p);
            // A certified tour is within 3/2 of the optimum, whatever the tour.
            for tour in [preorder(p.len(), &mst), (0..p.len()).collect()] {
                if three_halves_certified(&p, &mst, &tour) {
                    certified += 1;
                    assert!(
                        2.0 * p.tour_length(&tour) <= 3.0 * opt + 1e-9,
                        "trial {trial}"
                    );
                }
            }
        }
        assert!(certified > 0, "the test must exercise the certificate");
    }

    #[test]
    fn box_tour_covers_the_bounding_box() {
        for (w, h) in [
            (1, 1),
            (1, 5),
            (5, 1),
            (2, 7),
            (3, 3),
            (4, 6),
            (7, 5),
            (8, 8),
        ] {
            let r = Region::rectangle(w, h);
            let walk = box_tour(&r).unwrap();
            let rep =
                crate::checker::check(&r, &CycleCover::tour(walk), crate::checker::Mode::Milling);
            assert!(rep.valid, "{w}x{h}: {:?}", rep.error);
            if w.min(h) <= 2 {
                // The rectangular tour 2(a + b - 2) is optimal here (Section 4).
                assert_eq!(rep.length as i32, 2 * (w + h - 2), "{w}x{h}");
            } else {
                // Rings join for free; a thin innermost ring costs at most its doubling + 2.
                assert!(
                    rep.length as i32 <= w * h + w.max(h),
                    "{w}x{h}: {}",
                    rep.length
                );
            }
        }
    }
}
