//! Theorem 5 of *Lawn mowing and milling*: a tour of a simple grid graph without cut vertices
//! of length at most (6N − 4)/5, hence a 6/5-approximation of milling simple integral
//! rectilinear polygons with a unit square (Corollary 3).
//!
//! The construction of Section 6, as a connected multigraph with even degrees walked by
//! Hierholzer ([`crate::euler`]):
//!
//! 1. The contour C: the [contour walk](super::contour) of the block, a simple cycle through
//!    the boundary nodes. Grid reading: a boundary node is a pixel with a side *or a corner* on
//!    the region's boundary (some of its eight neighbours missing), since only then does C
//!    exist as the paper states (at a reflex corner it passes the diagonal pixel); the other
//!    pixels are the internal nodes V_I.
//! 2. Lemma 5, the bottleneck decomposition: a unit square whose two opposite sides e, f are
//!    edges of C and whose other two sides are not splits the graph into pieces H1, H2. Gluing
//!    the pieces' tours removes e, f and the two far sides again, so the glued tour is C with
//!    every piece's detours applied; what the decomposition changes is that each piece
//!    chooses its own doublerow parity. We compute the pieces (components of G without the
//!    bottleneck edges e, f) and, per piece, keep the parity that wastes fewer edges (the
//!    proof only needs one of the two).
//! 3. Doublerows: rows y ≡ p, p + 1 (mod 2) paired, p being the piece's parity.
//! 4. Free detours until none applies: Type I (a doubleton column next to an empty column
//!    whose vertical edge is in C' pushes that edge through it, repeatedly) and Type II (a
//!    maximal run of singleton columns with their internal nodes in one row opposite a path
//!    of C' edges is zig-zagged from its left end, pairing columns, so that all but at most
//!    one node are visited).
//! 5. The remaining components H of each doublerow, by the six cases of Fig. 15. The figure
//!    is not in the text; from the proof's counts we construct (s = singleton node, t = the
//!    other node of its column, a boundary node, D = the 2 × w block of doubleton columns
//!    l..r, rows A (the row of the left singleton, else the bottom row) and B):
//!    - (a) one node: the edge s–t doubled (waste 1);
//!    - (b) two singletons in one row: the 4-cycle t1 s1 s2 t2 (waste 2; t1 t2 is not in C',
//!      or Type II would have applied);
//!    - (c) only doubleton columns: the cycle around D (for w = 1 the edge doubled), tied to
//!      its visited west neighbour by a doubled edge (waste 2);
//!    - (d) D plus one singleton: the cycle t s, along D's row of s to the far end, back along
//!      the other row, t (waste 1);
//!    - (e), (f) D plus singletons at both ends, in the same row (e) or not (f): the cycle
//!      t1 s1, row A of D, (r + 1, A), (r + 1, B), row B of D back, t1 (waste 2).
//!
//!    A component of any other shape would contradict the proof; it is linked by a doubled
//!    spanning tree and counted in the certificate `unexpected_components`.
//!
//! Regions with cut vertices are split into blocks (biconnected components): a bridge is
//! walked twice, every other block is solved as above, and since the blocks' edge sets are
//! disjoint and meet at cut vertices, one Euler circuit of their union splices the tours.

use super::contour::contour_walks;
use crate::error::{Error, Result};
use crate::euler::GridMultigraph;
use crate::region::{Dir, Pixel, Region};
use crate::topology;
use crate::tour::CycleCover;
use crate::{Algorithm, Guarantee, Objective, Output, Solution};
use std::collections::BTreeMap;

/// Theorem 5 needs a simple (hole-free), connected, non-empty grid graph.
pub(crate) fn precondition(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::Precondition("the region is empty".into()));
    }
    if topology::components(region).count != 1 {
        return Err(Error::Precondition(
            "tsp65 needs a connected region (one grid component)".into(),
        ));
    }
    let h = topology::holes(region).count;
    if h > 0 {
        return Err(Error::Precondition(format!(
            "tsp65 needs a simple region (Theorem 5), but this one has {h} hole(s); use holes1325 or milling25"
        )));
    }
    Ok(())
}

/// Counts of what the construction did (the certificates).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct LinkStats {
    pub type1: i64,
    pub type2: i64,
    pub cases: [i64; 6],
    pub unexpected: i64,
    pub wasted: i64,
}

impl LinkStats {
    fn add(&mut self, o: &LinkStats) {
        self.type1 += o.type1;
        self.type2 += o.type2;
        for k in 0..6 {
            self.cases[k] += o.cases[k];
        }
        self.unexpected += o.unexpected;
        self.wasted += o.wasted;
    }

    pub(super) fn certify(&self, cert: &mut BTreeMap<String, i64>) {
        cert.insert("detours_type1".into(), self.type1);
        cert.insert("detours_type2".into(), self.type2);
        for (k, name) in ["a", "b", "c", "d", "e", "f"].iter().enumerate() {
            cert.insert(format!("case_{name}"), self.cases[k]);
        }
        cert.insert("unexpected_components".into(), self.unexpected);
        cert.insert("wasted_edges".into(), self.wasted);
    }
}

/// Runs the construction of Theorem 5 on a simple region.
///
/// # Arguments
/// A connected region without holes (cut vertices allowed).
///
/// # Returns
/// One tour (objective length); certificates: blocks, bridges, bottlenecks, pieces, the
/// detours and cases applied, the wasted edges, and `bound_6n_4_5` = ⌊(6N − 4)/5⌋ when the
/// region has no cut vertices and N ≥ 3 (the bound of Theorem 5 that the length must meet).
///
/// # Complexity
/// O(N) time and space for a region without cut vertices (three passes of the linear
/// detour procedure, for the two parities and the final choice); with cut vertices, O(N)
/// plus the bounding boxes of the blocks.
///
/// # Guarantee
/// Without cut vertices: length ≤ (6N − 4)/5 (Theorem 5 of Arkin, Fekete, Mitchell,
/// *Approximation algorithms for lawn mowing and milling*). For every simple region: length
/// ≤ 6/5 · OPT, because a block's tour is at most 6/5 of its N_b ≤ OPT_b nodes, a bridge
/// costs 2 = OPT_b, and OPT is the sum of the blocks' optima (Corollary 3).
pub(crate) fn tsp65(region: &Region) -> Result<Solution> {
    let mut blocks = checked_blocks(region)?;
    let n = region.len();
    let mut solution = Solution::default();
    let mut stats = LinkStats::default();
    let mut bottlenecks = 0i64;
    let mut pieces = 0i64;
    let mut bridges = 0i64;
    let mut graph;
    if blocks.len() == 1 && blocks[0].len() == n && n >= 3 {
        let b;
        (graph, b) = block_tour(region, &mut stats)?;
        bottlenecks += b.0;
        pieces += b.1;
    } else {
        graph = GridMultigraph::new(n);
        for block in &mut blocks {
            if block.len() == 2 {
                graph.add_between(region, block[0], block[1]);
                graph.add_between(region, block[0], block[1]);
                bridges += 1;
                continue;
            }
            // Sorted region indices are sorted pixels: sub-region index i is block[i].
            sort_indices(block, n);
            let sub = Region::from_pixels(block.iter().map(|&i| region.pixel(i)))?;
            let (sub_graph, b) = block_tour(&sub, &mut stats)?;
            bottlenecks += b.0;
            pieces += b.1;
            // The block's edges are region edges, and blocks share no edge.
            graph.add_rows_mapped(&sub_graph, block);
        }
    }
    let walk = graph.into_walk(region, 0);
    solution.outputs.push(Output {
        objective: Objective::Length,
        cover: CycleCover::tour(walk),
    });
    let cert = &mut solution.certificates;
    stats.certify(cert);
    cert.insert("blocks".into(), blocks.len() as i64);
    cert.insert("bridges".into(), bridges);
    cert.insert("bottlenecks".into(), bottlenecks);
    cert.insert("pieces".into(), pieces);
    // Theorem 5 speaks of graphs with a cycle: a single edge (N = 2) is walked twice.
    if blocks.len() == 1 && n >= 3 {
        cert.insert("bound_6n_4_5".into(), (6 * n as i64 - 4).div_euclid(5));
    }
    Ok(solution)
}

/// Sorts distinct indices below `n`: by marking them when they are a large share of `n` (the
/// main block of a region: O(n) instead of O(k log k)), else by comparison.
fn sort_indices(indices: &mut [usize], n: usize) {
    if indices.len() * 8 < n {
        indices.sort_unstable();
        return;
    }
    let mut mark = vec![false; n];
    for &i in indices.iter() {
        mark[i] = true;
    }
    let sorted = mark.iter().enumerate().filter(|(_, m)| **m).map(|(i, _)| i);
    for (slot, i) in indices.iter_mut().zip(sorted) {
        *slot = i;
    }
}

/// [`precondition`] (same errors), with the region's blocks, which also count its components:
/// every component has one pixel more than the sum of its blocks' sizes minus one.
fn checked_blocks(region: &Region) -> Result<Vec<Vec<usize>>> {
    if region.is_empty() {
        return precondition(region).map(|()| Vec::new());
    }
    let blocks = topology::biconnected_blocks(region);
    let spanned: usize = blocks.iter().map(|b| b.len() - 1).sum();
    if region.len() - spanned != 1 {
        precondition(region)?;
    }
    if topology::holes(region).count > 0 {
        precondition(region)?;
    }
    Ok(blocks)
}

/// The construction of Theorem 5 on a 2-connected simple region with at least 3 pixels:
/// the tour's edges (indexed like `region`) and (bottlenecks, pieces).
fn block_tour(region: &Region, stats: &mut LinkStats) -> Result<(GridMultigraph, (i64, i64))> {
    let mut block = Block::new(region)?;
    if block.pieces == 0 {
        // Every node on C (a ring, a 2 × k block, ...): C is the tour, nothing to link.
        return Ok((block.base, (block.bottlenecks, 0)));
    }
    // Try both parities everywhere and keep the better one per piece; pieces do not interact
    // (see link_internal_nodes), so each piece's edges are taken from its trial.
    let (g1, s1) = block.link(block.base.clone(), region, &vec![1; block.pieces]);
    let base = std::mem::replace(&mut block.base, GridMultigraph::new(0));
    let (g0, s0) = block.link(base, region, &vec![0; block.pieces]);
    let odd: Vec<bool> = (0..block.pieces)
        .map(|k| s1[k].wasted < s0[k].wasted)
        .collect();
    for k in 0..block.pieces {
        stats.add(if odd[k] { &s1[k] } else { &s0[k] });
    }
    let mut g = g0;
    g.copy_rows_from(&g1, |i| odd[block.piece[i] as usize]);
    Ok((g, (block.bottlenecks, block.pieces_with_internal_nodes())))
}

/// A block ready for linking: its contour C, the bottleneck squares of Lemma 5 and the
/// pieces they cut the graph into.
struct Block {
    /// The contour C as a multigraph.
    base: GridMultigraph,
    /// The nodes not on C.
    internal: Vec<bool>,
    bottlenecks: i64,
    /// The piece of every node (pieces in order of their smallest pixel) and their number.
    piece: Vec<u32>,
    pieces: usize,
}

impl Block {
    fn new(region: &Region) -> Result<Block> {
        let contours = contour_walks(region);
        if contours.len() != 1 {
            return Err(Error::Invalid(
                "tsp65: a block of the region has holes".into(),
            ));
        }
        let c = &contours[0].walk;
        let n = region.len();
        let mut internal = vec![true; n];
        for &i in c {
            if !internal[i] {
                return Err(Error::Invalid(format!(
                    "tsp65: the contour passes {} twice, so the block is not 2-connected",
                    region.pixel(i)
                )));
            }
            internal[i] = false;
        }
        let mut base = GridMultigraph::new(n);
        base.add_closed_walk(region, c);

        // Lemma 5: a unit square with two opposite sides on C and the other two not.
        let mut cut = vec![[false; 4]; n];
        let mut bottlenecks = 0;
        for a in 0..n {
            let (Some(b), Some(cc)) = (region.neighbor(a, Dir::E), region.neighbor(a, Dir::N))
            else {
                continue;
            };
            if region.neighbor(b, Dir::N).is_none() {
                continue;
            }
            let bottom = base.count(a, Dir::E) > 0;
            let top = base.count(cc, Dir::E) > 0;
            let left = base.count(a, Dir::N) > 0;
            let right = base.count(b, Dir::N) > 0;
            let pairs: &[(usize, Dir)] = if bottom && top && !left && !right {
                &[(a, Dir::E), (cc, Dir::E)]
            } else if left && right && !bottom && !top {
                &[(a, Dir::N), (b, Dir::N)]
            } else {
                &[]
            };
            if !pairs.is_empty() {
                bottlenecks += 1;
            }
            for &(u, dir) in pairs {
                let v = region.neighbor(u, dir).expect("square corner");
                cut[u][dir.index()] = true;
                cut[v][dir.opposite().index()] = true;
            }
        }
        // The crate's one labelling of a plain graph (not needed when nothing is linked).
        let (piece, pieces) = if internal.contains(&true) {
            let uncut = (0..n).flat_map(|a| {
                let cut = &cut;
                [Dir::E, Dir::N]
                    .into_iter()
                    .filter(move |d| !cut[a][d.index()])
                    .filter_map(move |d| region.neighbor(a, d).map(|b| (a, b)))
            });
            crate::topology::graph_components(n, uncut)
        } else {
            (Vec::new(), 0)
        };
        Ok(Block {
            base,
            internal,
            bottlenecks,
            piece,
            pieces,
        })
    }

    /// `g` (C) with the internal nodes linked in, doublerow parity `parity[piece]`, and what
    /// was done per piece.
    fn link(
        &self,
        mut g: GridMultigraph,
        region: &Region,
        parity: &[i32],
    ) -> (GridMultigraph, Vec<LinkStats>) {
        let s = link_internal_nodes(region, &mut g, &self.internal, &self.piece, parity);
        (g, s)
    }

    /// The number of pieces that hold an internal node (the certificate `pieces`).
    fn pieces_with_internal_nodes(&self) -> i64 {
        let mut seen = vec![false; self.pieces];
        for (i, &inside) in self.internal.iter().enumerate() {
            if inside {
                seen[self.piece[i] as usize] = true;
            }
        }
        seen.iter().filter(|&&b| b).count() as i64
    }
}

/// Steps 3–5 of the proof of Theorem 5: links every `internal` node into the closed walks of
/// `graph` (which must visit every other node), with doublerow parity `parity[piece[i]]`.
/// Returns what was done per piece, with its wasted edges (edges added beyond one per newly
/// visited node).
///
/// Pieces do not interact: every edge the linker adds, removes or reads the count of joins two
/// pixels of one piece (an internal node is never the end of a bottleneck edge, so each
/// detour, cycle or tree lies in the piece of its internal nodes), and a piece's loop of
/// detours and cases reads only its own nodes. So a piece's edges and counts depend on its own
/// parity only, which lets [`block_tour`] take each piece from either trial.
///
/// Also used by Theorem 7 ([`super::holes1325`]), whose graph holds one contour per
/// boundary component.
pub(super) fn link_internal_nodes(
    region: &Region,
    graph: &mut GridMultigraph,
    internal: &[bool],
    piece: &[u32],
    parity: &[i32],
) -> Vec<LinkStats> {
    let mut linker = Linker {
        region,
        graph,
        unvisited: internal.to_vec(),
        piece,
        parity,
        stats: vec![LinkStats::default(); parity.len()],
    };
    linker.free_detours();
    linker.remaining_components();
    linker.stats
}

struct Linker<'a> {
    region: &'a Region,
    graph: &'a mut GridMultigraph,
    unvisited: Vec<bool>,
    piece: &'a [u32],
    parity: &'a [i32],
    /// What was done, per piece.
    stats: Vec<LinkStats>,
}

impl Linker<'_> {
    /// The stats of the piece of a remaining component.
    fn stats_of(&mut self, comp: &[usize]) -> &mut LinkStats {
        &mut self.stats[self.piece[comp[0]] as usize]
    }

    fn at(&self, x: i32, y: i32) -> Option<usize> {
        self.region.index_of(Pixel::new(x, y))
    }

    /// Bottom row of the doublerow of internal node `i`.
    fn bottom_row(&self, i: usize) -> i32 {
        let y = self.region.pixel(i).y;
        y - (y - self.parity[self.piece[i] as usize]).rem_euclid(2)
    }

    /// Replaces edge u–v of C' by the path u, a, b, v (a free detour through a and b).
    fn detour(&mut self, u: usize, a: usize, b: usize, v: usize) {
        let ok = self.graph.remove_between(self.region, u, v);
        debug_assert!(ok, "detours replace an edge of C'");
        self.graph.add_path(self.region, &[u, a, b, v]);
        self.unvisited[a] = false;
        self.unvisited[b] = false;
    }

    /// Type I detour into the doubleton column whose bottom node is `a`, from the side
    /// `dx` (−1 west, +1 east); true if applied.
    fn try_type1(&mut self, a: usize, dx: i32) -> bool {
        let side = if dx < 0 { Dir::W } else { Dir::E };
        let Some(b) = self.region.neighbor(a, Dir::N) else {
            return false;
        };
        if !self.unvisited[a] || !self.unvisited[b] || self.bottom_row(a) != self.region.pixel(a).y
        {
            return false;
        }
        let Some(u) = self.region.neighbor(a, side) else {
            return false;
        };
        let Some(v) = self.region.neighbor(u, Dir::N) else {
            return false;
        };
        if self.unvisited[u] || self.unvisited[v] || self.graph.count(u, Dir::N) == 0 {
            return false;
        }
        self.detour(u, a, b, v);
        self.stats[self.piece[a] as usize].type1 += 1;
        true
    }

    /// Pushes a vertical edge as far as it goes from column of `a` away from side `dx`.
    fn push_type1(&mut self, mut a: usize, dx: i32) -> bool {
        let mut any = false;
        while self.try_type1(a, dx) {
            any = true;
            let back = if dx < 0 { Dir::E } else { Dir::W };
            match self.region.neighbor(a, back) {
                Some(next) => a = next,
                None => break,
            }
        }
        any
    }

    /// Tries Type I on the doubleton column at `a` (bottom node) from both sides.
    fn type1_at(&mut self, a: usize) {
        if !self.push_type1(a, -1) {
            self.push_type1(a, 1);
        }
    }

    /// Whether the column of pixel `a` (in its doublerow) is a singleton with its node at `a`,
    /// `to_other` pointing to the other row of the doublerow.
    fn singleton_at(&self, a: usize, to_other: Dir) -> bool {
        self.unvisited[a]
            && self
                .region
                .neighbor(a, to_other)
                .is_some_and(|o| !self.unvisited[o])
    }

    /// Whether the edge of C' from the pixel across the doublerow from `a` to its neighbour in
    /// direction `d` is there.
    fn other_row_edge(&self, a: usize, to_other: Dir, d: Dir) -> bool {
        self.region
            .neighbor(a, to_other)
            .is_some_and(|u| self.graph.count(u, d) > 0)
    }

    fn free_detours(&mut self) {
        let n = self.region.len();
        // Type I everywhere, then Type II runs, then Type I next to what Type II opened.
        for a in 0..n {
            if self.unvisited[a] {
                self.type1_at(a);
            }
        }
        loop {
            let mut opened = Vec::new();
            for a in 0..n {
                if !self.unvisited[a] {
                    continue;
                }
                let p = self.region.pixel(a);
                let yb = self.bottom_row(a);
                let to_other = if p.y == yb { Dir::N } else { Dir::S };
                if !self.singleton_at(a, to_other) {
                    continue;
                }
                // Start of a maximal run: the west column does not continue it.
                if let Some(w) = self.region.neighbor(a, Dir::W)
                    && self.singleton_at(w, to_other)
                    && self.piece[w] == self.piece[a]
                    && self.other_row_edge(a, to_other, Dir::W)
                {
                    continue;
                }
                let mut x = p.x;
                let mut cur = Some(a);
                while let Some(a0) = cur
                    && self.singleton_at(a0, to_other)
                    && let Some(a1) = self.region.neighbor(a0, Dir::E)
                    && self.singleton_at(a1, to_other)
                    && self.piece[a1] == self.piece[a]
                    && self.other_row_edge(a0, to_other, Dir::E)
                {
                    let u = self.region.neighbor(a0, to_other).expect("edge");
                    let v = self.region.neighbor(a1, to_other).expect("edge");
                    self.detour(u, a0, a1, v);
                    self.stats[self.piece[a] as usize].type2 += 1;
                    opened.extend([(x - 1, yb), (x + 2, yb)]);
                    x += 2;
                    cur = self.region.neighbor(a1, Dir::E);
                }
            }
            if opened.is_empty() {
                break;
            }
            for (x, yb) in opened {
                if let Some(a) = self.at(x, yb)
                    && self.unvisited[a]
                {
                    self.type1_at(a);
                }
            }
        }
    }

    /// Step 5: the components left in each doublerow, by the cases of Fig. 15.
    fn remaining_components(&mut self) {
        let n = self.region.len();
        let mut stack = Vec::new();
        let mut comp = Vec::new();
        // mark[w] == s + 1: w is in the component of s.
        let mut mark = vec![0u32; n];
        for s in 0..n {
            if !self.unvisited[s] {
                continue;
            }
            // The component of s within its doublerow.
            let yb = self.bottom_row(s);
            comp.clear();
            comp.push(s);
            let stamp = s as u32 + 1;
            mark[s] = stamp;
            stack.push(s);
            while let Some(v) = stack.pop() {
                let y = self.region.pixel(v).y;
                for d in Dir::ALL {
                    let qy = y + d.delta().1;
                    if qy != yb && qy != yb + 1 {
                        continue;
                    }
                    if let Some(w) = self.region.neighbor(v, d)
                        && self.unvisited[w]
                        && mark[w] != stamp
                    {
                        mark[w] = stamp;
                        comp.push(w);
                        stack.push(w);
                    }
                }
            }
            let w = self.link_component(&comp, yb);
            self.stats[self.piece[s] as usize].wasted += w;
            for &v in &comp {
                self.unvisited[v] = false;
            }
        }
    }

    /// Adds a closed walk (pixel coordinates) to the graph.
    fn add_cycle(&mut self, cycle: &[(i32, i32)]) {
        let idx: Vec<usize> = cycle
            .iter()
            .map(|&(x, y)| self.at(x, y).expect("cycle pixels are region pixels"))
            .collect();
        self.graph.add_closed_walk(self.region, &idx);
    }

    /// Links one remaining component H (rows yb, yb + 1); returns the wasted edges.
    fn link_component(&mut self, comp: &[usize], yb: i32) -> i64 {
        let mut cols: BTreeMap<i32, (bool, bool)> = BTreeMap::new();
        for &v in comp {
            let p = self.region.pixel(v);
            let e = cols.entry(p.x).or_default();
            if p.y == yb {
                e.0 = true;
            } else {
                e.1 = true;
            }
        }
        let cols: Vec<(i32, bool, bool)> = cols.into_iter().map(|(x, (b, t))| (x, b, t)).collect();
        let row_of = |c: &(i32, bool, bool)| if c.1 { yb } else { yb + 1 };
        let other = |r: i32| if r == yb { yb + 1 } else { yb };
        let doubles: Vec<i32> = cols.iter().filter(|c| c.1 && c.2).map(|c| c.0).collect();
        if doubles.is_empty() {
            if cols.len() == 1 {
                // (a): the edge s–t doubled.
                let (x, r) = (cols[0].0, row_of(&cols[0]));
                self.add_cycle(&[(x, r), (x, other(r))]);
                self.stats_of(comp).cases[0] += 1;
                return 1;
            }
            if cols.len() == 2 && row_of(&cols[0]) == row_of(&cols[1]) {
                // (b): the 4-cycle t1 s1 s2 t2.
                let (x, r) = (cols[0].0, row_of(&cols[0]));
                self.add_cycle(&[(x, other(r)), (x, r), (x + 1, r), (x + 1, other(r))]);
                self.stats_of(comp).cases[1] += 1;
                return 2;
            }
            return self.link_unexpected(comp);
        }
        let (l, r) = (doubles[0], doubles[doubles.len() - 1]);
        let contiguous = doubles.len() as i32 == r - l + 1;
        let left = cols.iter().find(|c| c.0 == l - 1).copied();
        let right = cols.iter().find(|c| c.0 == r + 1).copied();
        let singles = cols.len() - doubles.len();
        if !contiguous || singles != usize::from(left.is_some()) + usize::from(right.is_some()) {
            return self.link_unexpected(comp);
        }
        let row = |x0: i32, x1: i32, y: i32| -> Vec<(i32, i32)> {
            if x0 <= x1 {
                (x0..=x1).map(|x| (x, y)).collect()
            } else {
                (x1..=x0).rev().map(|x| (x, y)).collect()
            }
        };
        match (left, right) {
            (None, None) => {
                // (c): the cycle around D, tied to its west neighbour by a doubled edge.
                let mut cycle = row(l, r, yb);
                cycle.extend(row(r, l, yb + 1));
                self.add_cycle(&cycle);
                self.add_cycle(&[(l - 1, yb), (l, yb)]);
                self.stats_of(comp).cases[2] += 1;
                2
            }
            (Some(s), None) => {
                // (d), singleton on the left in row A.
                let a = row_of(&s);
                let mut cycle = vec![(l - 1, other(a)), (l - 1, a)];
                cycle.extend(row(l, r, a));
                cycle.extend(row(r, l, other(a)));
                self.add_cycle(&cycle);
                self.stats_of(comp).cases[3] += 1;
                1
            }
            (None, Some(s)) => {
                // (d), singleton on the right in row A.
                let a = row_of(&s);
                let mut cycle = vec![(r + 1, other(a)), (r + 1, a)];
                cycle.extend(row(r, l, a));
                cycle.extend(row(l, r, other(a)));
                self.add_cycle(&cycle);
                self.stats_of(comp).cases[3] += 1;
                1
            }
            (Some(s1), Some(s2)) => {
                // (e) same row, (f) different rows: t1 s1, row A, (r+1, A), (r+1, B), row B.
                let a = row_of(&s1);
                let mut cycle = vec![(l - 1, other(a)), (l - 1, a)];
                cycle.extend(row(l, r, a));
                cycle.extend([(r + 1, a), (r + 1, other(a))]);
                cycle.extend(row(r, l, other(a)));
                self.add_cycle(&cycle);
                let k = if row_of(&s2) == a { 4 } else { 5 };
                self.stats_of(comp).cases[k] += 1;
                2
            }
        }
    }

    /// A component the case analysis does not foresee: a doubled spanning tree hung from a
    /// visited neighbour. Returns its waste (|H|).
    fn link_unexpected(&mut self, comp: &[usize]) -> i64 {
        self.stats_of(comp).unexpected += 1;
        let inside: std::collections::HashSet<usize> = comp.iter().copied().collect();
        let mut done = std::collections::HashSet::new();
        // Hang the first node with a visited neighbour, then grow a tree through comp.
        let root = comp
            .iter()
            .copied()
            .find(|&v| self.region.neighbors(v).any(|w| !inside.contains(&w)))
            .expect("a component has a neighbour outside it");
        let anchor = self
            .region
            .neighbors(root)
            .find(|w| !inside.contains(w))
            .expect("found above");
        self.graph.add_between(self.region, anchor, root);
        self.graph.add_between(self.region, anchor, root);
        done.insert(root);
        let mut stack = vec![root];
        while let Some(v) = stack.pop() {
            let next: Vec<usize> = self
                .region
                .neighbors(v)
                .filter(|w| inside.contains(w))
                .collect();
            for w in next {
                if done.insert(w) {
                    self.graph.add_between(self.region, v, w);
                    self.graph.add_between(self.region, v, w);
                    stack.push(w);
                }
            }
        }
        comp.len() as i64
    }
}

/// The registry entry of `tsp65`: the construction of Theorem 5, blocks spliced at cut
/// vertices ([`tsp65`]).
///
/// # Guarantee
///
/// On a simple (hole-free) connected region without cut vertices and with N ≥ 3 pixels the tour
/// has length ≤ (6N − 4)/5 (Theorem 5 of *Lawn mowing and milling*); since OPT ≥ N, it is a
/// 6/5-approximation (Corollary 3). Registered as two guarantees: `length <= (6 N - 4)/5` against
/// N, on regions without cut vertices and N ≥ 3 ([`When::Biconnected`](crate::When)),
/// and `length <= 6/5 OPT` on every region the precondition accepts (decided where OPT, or a
/// lower bound strong enough, is known).
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
///     "####\n",
/// ));
/// let algorithm = algorithms::find("tsp65").unwrap();
/// let tour = algorithm.run_checked(&region, &Options::default(), Objective::Length).unwrap();
/// assert!(tour.valid);
/// // A 4 x 3 rectangle has a Hamiltonian tour: 12 moves <= (6·12 - 4)/5.
/// assert_eq!(tour.length, 12);
/// ```
pub const ALGORITHM: Algorithm = Algorithm {
    name: "tsp65",
    summary: "contour + free detours + the six cases, blocks spliced (Theorem 5, milling paper); \
              length <= (6N-4)/5 without cut vertices (certificate bound_6n_4_5)",
    objectives: &[Objective::Length],
    guarantees: &[
        Guarantee::vs_opt(
            Objective::Length,
            6,
            5,
            &crate::theorems::MILLING_COR_3,
            "Theorem 5 and Corollary 3 of Lawn mowing and milling",
        ),
        Guarantee::of_theorem(
            Objective::Length,
            crate::When::Biconnected,
            &crate::theorems::MILLING_THM_5,
            "Theorem 5 of Lawn mowing and milling",
        ),
    ],
    claims: &[
        crate::theorems::Claim::paper(&crate::theorems::MILLING_THM_5, &[crate::Objective::Length]),
        crate::theorems::Claim::paper(&crate::theorems::MILLING_COR_3, &[crate::Objective::Length]),
    ],
    requires: "a connected region without holes",
    precondition,
    run: |region, _| tsp65(region),
    discrete: None,
    ortho: None,
    by_default: true,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_of_two_squares_and_a_bridge() {
        // Two 2×2 squares joined by a one-pixel corridor: blocks 2×2, three bridges, 2×2.
        let r = Region::from_ascii("##..##\n######\n");
        let blocks = crate::topology::biconnected_blocks(&r);
        let mut sizes: Vec<usize> = blocks.iter().map(Vec::len).collect();
        sizes.sort_unstable();
        assert_eq!(sizes, vec![2, 2, 2, 4, 4]);
        let sol = tsp65(&r).unwrap();
        let rep = crate::checker::check(&r, &sol.outputs[0].cover, crate::checker::Mode::Milling);
        assert!(rep.valid);
        // Each square 4, each bridge twice.
        assert_eq!(rep.length, 14);
        assert!(!sol.certificates.contains_key("bound_6n_4_5"));
    }

    #[test]
    fn bottleneck_splits_a_dumbbell() {
        // Two 4×4 squares joined by a 2-wide corridor: the corridor's squares are bottlenecks.
        let r = Region::from_ascii("####..####\n##########\n##########\n####..####\n");
        let sol = tsp65(&r).unwrap();
        assert!(sol.certificates["bottlenecks"] >= 1);
        let rep = crate::checker::check(&r, &sol.outputs[0].cover, crate::checker::Mode::Milling);
        assert!(rep.valid);
        assert!(5 * rep.length + 4 <= 6 * r.len() as u64);
    }

    /// Taking each piece's edges from the trial of its parity gives what one run with the
    /// mixed parities gives (pieces do not interact), on the blocks of random regions.
    #[test]
    fn pieces_link_independently() {
        use crate::generate::{Family, GenParams, generate};
        let mut mixed = 0;
        for seed in 0..60 {
            for (family, n, no_cut) in [
                (Family::RandomSimple, 400, false),
                (Family::RandomSimple, 3000, true),
                (Family::RandomHoled, 2000, true),
            ] {
                let mut p = GenParams::new(family, seed);
                p.n = Some(n);
                p.no_cut = no_cut;
                let region = generate(&p).unwrap().region;
                for block in crate::topology::biconnected_blocks(&region) {
                    let sub = Region::from_pixels(block.iter().map(|&i| region.pixel(i))).unwrap();
                    let b = match Block::new(&sub) {
                        Ok(b) => b,
                        // A block around a hole: not tsp65's input.
                        Err(_) if family == Family::RandomHoled => continue,
                        Err(e) => panic!("seed {seed} {family:?}: {e}"),
                    };
                    if b.pieces == 0 {
                        continue;
                    }
                    let mut merged_stats = LinkStats::default();
                    let (merged, _) = block_tour(&sub, &mut merged_stats).unwrap();
                    let [(_, s0), (_, s1)] =
                        [0, 1].map(|q| b.link(b.base.clone(), &sub, &vec![q; b.pieces]));
                    let parity: Vec<i32> = (0..b.pieces)
                        .map(|k| i32::from(s1[k].wasted < s0[k].wasted))
                        .collect();
                    if parity.iter().any(|&q| q != parity[0]) {
                        mixed += 1;
                    }
                    let (full, per_piece) = b.link(b.base.clone(), &sub, &parity);
                    let mut full_stats = LinkStats::default();
                    per_piece.iter().for_each(|s| full_stats.add(s));
                    assert_eq!(merged, full, "seed {seed} {family:?}");
                    assert_eq!(merged_stats, full_stats, "seed {seed} {family:?}");
                }
            }
        }
        assert!(mixed >= 20, "only {mixed} blocks with mixed parities");
    }

    #[test]
    fn case_a_on_the_three_by_three_square() {
        let sol = tsp65(&Region::rectangle(3, 3)).unwrap();
        assert_eq!(sol.certificates["case_a"], 1);
        assert_eq!(sol.certificates["wasted_edges"], 1);
    }
}
