//! Topology of a region: components, holes, boundary and internal pixels, cut vertices, local
//! cut vertices, colour classes, thinness and maximal strips.
//!
//! Conventions are those of digital topology with a 4-connected region and an 8-connected
//! complement: pixels are adjacent in the grid graph when they share a side, and a hole is a
//! bounded 8-connected component of the complement. Boundary and internal pixels follow
//! Section 6 of the milling paper (a boundary pixel shares a side with the region's boundary;
//! an internal pixel has all 4 neighbours). Local cut vertices follow Definition 6 of the
//! milling paper. Everything here runs in time and space proportional to N (the number of
//! pixels), never to the area of the bounding box.

use crate::region::{Dir, Pixel, Region};
use petgraph::unionfind::UnionFind;
use serde::Serialize;

/// The counts `mowmill info` reports (its JSON keys are these field names).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Summary {
    pub n: usize,
    pub holes: usize,
    pub components: usize,
    pub boundary: usize,
    pub internal: usize,
    pub cut_vertices: usize,
    pub local_cut_vertices: usize,
    pub black: usize,
    pub white: usize,
    pub thin: bool,
    pub strips_h: usize,
    pub strips_v: usize,
}

/// Computes every count of [`Summary`] for `region`.
///
/// # Complexity
/// O(N α(N)) time and O(N) space.
pub fn summary(region: &Region) -> Summary {
    let cut = cut_vertices(region);
    let local = local_cut_vertices(region);
    let (black, white) = colour_counts(region);
    let boundary = (0..region.len())
        .filter(|&i| is_boundary(region, i))
        .count();
    Summary {
        n: region.len(),
        holes: holes(region).count,
        components: components(region).count,
        boundary,
        internal: region.len() - boundary,
        cut_vertices: cut.iter().filter(|&&c| c).count(),
        local_cut_vertices: local.iter().filter(|&&c| c).count(),
        black,
        white,
        thin: is_thin(region),
        strips_h: strips(region, true).len(),
        strips_v: strips(region, false).len(),
    }
}

/// A labelling of items into connected components.
#[derive(Clone, Debug)]
pub struct Labels {
    /// Component label of every item.
    pub label: Vec<u32>,
    /// Number of components.
    pub count: usize,
}

/// The connected components of the grid graph; labels indexed by pixel index, components
/// numbered in the order of their first pixel. The crate's one component labelling: callers
/// use this rather than a search of their own.
///
/// Found on the rows' maximal runs: runs of adjacent rows that overlap in x are joined in a
/// union-find, then every run writes its component into its pixels (a search pixel by pixel
/// was 40% of milling25's time at 10^6 pixels).
///
/// # Complexity
/// O(N + R α(R)) time and O(N) space for R runs.
pub fn components(region: &Region) -> Labels {
    // Every run as (x0, x1, first pixel), row after row; row r's runs are
    // runs[row_start[r]..row_start[r + 1]].
    let mut runs: Vec<(i32, i32, usize)> = Vec::new();
    let mut row_start = vec![0];
    let mut row_y = Vec::with_capacity(region.row_count());
    for r in 0..region.row_count() {
        let (y, row) = region.row_runs(r);
        runs.extend(row);
        row_start.push(runs.len());
        row_y.push(y);
    }
    let mut uf = UnionFind::<u32>::new(runs.len());
    for r in 1..row_y.len() {
        if i64::from(row_y[r]) - i64::from(row_y[r - 1]) != 1 {
            continue;
        }
        // The runs of two adjacent rows, both sorted by x, joined where they overlap.
        let (mut i, mut j) = (row_start[r - 1], row_start[r]);
        while i < row_start[r] && j < row_start[r + 1] {
            let (a, b) = (runs[i], runs[j]);
            if a.0 <= b.1 && b.0 <= a.1 {
                uf.union(i as u32, j as u32);
            }
            if a.1 < b.1 {
                i += 1;
            } else {
                j += 1;
            }
        }
    }
    // Runs come in pixel order, so numbering roots as they first appear numbers the
    // components in the order of their first pixel.
    let mut label = vec![u32::MAX; region.len()];
    let mut number = vec![u32::MAX; runs.len()];
    let mut count = 0;
    for (k, &(x0, x1, first)) in runs.iter().enumerate() {
        let root = uf.find_mut(k as u32) as usize;
        if number[root] == u32::MAX {
            number[root] = count;
            count += 1;
        }
        let len = (i64::from(x1) - i64::from(x0) + 1) as usize;
        label[first..first + len].fill(number[root]);
    }
    Labels {
        label,
        count: count as usize,
    }
}

/// The holes of a region: the bounded 8-connected components of its complement, found from
/// the gaps between the runs of each row (never from the cells of the bounding box).
#[derive(Clone, Debug)]
pub struct Holes {
    /// Number of holes (bounded 8-connected components of the complement).
    pub count: usize,
    /// The y of every non-empty row of the region, ascending.
    row_y: Vec<i32>,
    /// Leftmost and rightmost pixel of each row.
    row_span: Vec<(i32, i32)>,
    /// The gaps of row `r` are `gaps[row_gap[r]..row_gap[r + 1]]`.
    row_gap: Vec<u32>,
    gaps: Vec<Gap>,
}

/// The empty cells `x0..=x1` between two runs of a row, and their complement component.
#[derive(Clone, Copy, Debug)]
struct Gap {
    x0: i32,
    x1: i32,
    label: u32,
}

impl Holes {
    /// The complement component of cell `p`: `Some(0)` outside, `Some(h)` for hole `h` (1-based),
    /// `None` for a pixel of the region.
    ///
    /// # Complexity
    /// O(log rows + log r) for r runs in the row of `p`.
    pub fn label_at(&self, p: Pixel) -> Option<u32> {
        let Ok(r) = self.row_y.binary_search(&p.y) else {
            return Some(0);
        };
        let (lo, hi) = self.row_span[r];
        if p.x < lo || p.x > hi {
            return Some(0);
        }
        let gaps = &self.gaps[self.row_gap[r] as usize..self.row_gap[r + 1] as usize];
        let k = gaps.partition_point(|g| g.x1 < p.x);
        gaps.get(k).filter(|g| g.x0 <= p.x).map(|g| g.label)
    }

    /// The cells of each hole, indexed by hole number − 1, each in row-major order (y, then x).
    ///
    /// # Complexity
    /// O(number of gaps + total area of the holes).
    pub fn hole_cells(&self) -> Vec<Vec<Pixel>> {
        let mut cells = vec![Vec::new(); self.count];
        for (r, &y) in self.row_y.iter().enumerate() {
            for g in &self.gaps[self.row_gap[r] as usize..self.row_gap[r + 1] as usize] {
                if g.label > 0 {
                    cells[g.label as usize - 1].extend((g.x0..=g.x1).map(|x| Pixel::new(x, y)));
                }
            }
        }
        cells
    }
}

/// The holes of a region: bounded 8-connected components of its complement.
///
/// In every row the empty cells between two runs of pixels form a gap; the cells left of the
/// first run and right of the last one, and every row without pixels, belong to the outside.
/// Two gaps of adjacent rows are 8-connected when their x ranges overlap or touch diagonally,
/// so a union-find over the gaps of each pair of adjacent rows (a merge of two sorted lists)
/// labels the complement. Holes are numbered by their lowest, then leftmost, cell.
///
/// # Complexity
/// O(N α(N)) time and O(rows + runs) extra space.
pub fn holes(region: &Region) -> Holes {
    let rows = region.row_count();
    let mut row_y = Vec::with_capacity(rows);
    let mut row_span = Vec::with_capacity(rows);
    let mut row_gap = Vec::with_capacity(rows + 1);
    let mut gaps: Vec<Gap> = Vec::new();
    for r in 0..rows {
        let (y, runs) = region.row_runs(r);
        row_y.push(y);
        row_gap.push(gaps.len() as u32);
        let mut span: Option<(i32, i32)> = None;
        for (x0, x1, _) in runs {
            if let Some((_, last)) = span {
                gaps.push(Gap {
                    x0: last + 1,
                    x1: x0 - 1,
                    label: 0,
                });
            }
            span = Some((span.map_or(x0, |s| s.0), x1));
        }
        row_span.push(span.unwrap_or((0, -1)));
    }
    row_gap.push(gaps.len() as u32);

    // Node 0 is the outside, node k + 1 the gap k; petgraph's union-find, as elsewhere in the
    // crate (holes are renumbered below, so which root a union keeps does not matter).
    let mut sets = UnionFind::<u32>::new(gaps.len() + 1);
    // Row r's gaps with the outer cells on both ends, as (x0, x1, node), in i64 so that the
    // outer ends can be infinite.
    let extended = |r: usize| {
        let (lo, hi) = row_span[r];
        let inner = (row_gap[r]..row_gap[r + 1]).map(|k| {
            (
                i64::from(gaps[k as usize].x0),
                i64::from(gaps[k as usize].x1),
                k + 1,
            )
        });
        std::iter::once((i64::MIN, i64::from(lo) - 1, 0))
            .chain(inner)
            .chain(std::iter::once((i64::from(hi) + 1, i64::MAX, 0)))
    };
    for r in 0..rows {
        let inner = row_gap[r] + 1..row_gap[r + 1] + 1;
        let adjacent = |s: usize| row_y[s] - 1 == row_y[s - 1];
        // A row with no pixels below or above: its gaps open onto an empty row, the outside.
        if r == 0 || !adjacent(r) || r + 1 == rows || !adjacent(r + 1) {
            for node in inner {
                sets.union(node, 0);
            }
        }
        if r + 1 < rows && adjacent(r + 1) {
            // Cells of rows y and y + 1 are 8-adjacent when their x differ by at most 1: widen
            // the lower row's intervals by one cell on each side and merge by right ends.
            let lower: Vec<(i64, i64, u32)> = extended(r)
                .map(|(x0, x1, node)| (x0.saturating_sub(1), x1.saturating_add(1), node))
                .collect();
            let upper: Vec<(i64, i64, u32)> = extended(r + 1).collect();
            let (mut a, mut b) = (0, 0);
            while a < lower.len() && b < upper.len() {
                let (la, ua) = (lower[a], upper[b]);
                if la.0 <= ua.1 && ua.0 <= la.1 {
                    sets.union(la.2, ua.2);
                }
                // Widened intervals may touch their neighbours, so ties advance the lower row.
                if la.1 <= ua.1 {
                    a += 1;
                } else {
                    b += 1;
                }
            }
        }
    }
    // Number the holes in gap order: by lowest, then leftmost, cell.
    let outside = sets.find_mut(0);
    let mut hole_of_root = vec![0u32; gaps.len() + 1];
    let mut count = 0;
    for (k, gap) in gaps.iter_mut().enumerate() {
        let root = sets.find_mut(k as u32 + 1) as usize;
        if root != outside as usize {
            if hole_of_root[root] == 0 {
                count += 1;
                hole_of_root[root] = count;
            }
            gap.label = hole_of_root[root];
        }
    }
    Holes {
        count: count as usize,
        row_y,
        row_span,
        row_gap,
        gaps,
    }
}

/// A boundary pixel shares at least one side with the region's boundary (fewer than 4
/// neighbours); the others are internal (milling paper, Section 6).
pub fn is_boundary(region: &Region, i: usize) -> bool {
    region.degree(i) < 4
}

/// Articulation points of the grid graph (removal increases the number of components), by
/// an iterative Tarjan depth-first search: `cut[i]` tells whether pixel `i` is one. The
/// crate's one cut-vertex search: callers use this rather than a copy of their own.
///
/// # Complexity
/// O(N) time and space (no recursion, so no stack overflow on large regions).
pub fn cut_vertices(region: &Region) -> Vec<bool> {
    // A pixel is an articulation point exactly when it lies in two or more blocks.
    let mut blocks_of = vec![0u8; region.len()];
    for_each_block(region, |block| {
        for &v in block.iter() {
            blocks_of[v] = blocks_of[v].saturating_add(1);
        }
    });
    blocks_of.into_iter().map(|b| b >= 2).collect()
}

/// Local cut vertices (milling paper, Definition 6): pixels whose removal disconnects the
/// grid graph or reduces the number of holes.
///
/// Removing pixel v merges the complement components among its eight neighbours into one, so
/// it reduces the number of holes exactly when those neighbours touch two or more distinct
/// complement components; with the cut vertices, these are the pixels whose 8-neighbourhood
/// holds two or more 4-connected arcs of the region, that is whose Yokoi
/// `connectivity_number` is at least 2 (a closed path through two arcs separates the
/// complement cells between them). That local test needs no global pass.
///
/// # Complexity
/// O(N) time.
pub fn local_cut_vertices(region: &Region) -> Vec<bool> {
    (0..region.len())
        .map(|i| connectivity_number(ring_occupancy(region, i)) >= 2)
        .collect()
}

/// Which of the eight neighbours of pixel `i`, in the order of [`ring`], are in the region.
///
/// # Complexity
/// O(1) when pixel `i` has a side neighbour next to each diagonal, else O(log r) for r runs in
/// the row of that diagonal.
pub fn ring_occupancy(region: &Region, i: usize) -> [bool; 8] {
    let side = Dir::ALL.map(|d| region.neighbor(i, d));
    let p = region.pixel(i);
    let mut occupied = [false; 8];
    for k in 0..4 {
        let (d, next) = (Dir::from_index(k), Dir::from_index(k + 1));
        occupied[2 * k] = side[k].is_some();
        // The diagonal between sides d and next is next's neighbour of side d, or d's of next.
        occupied[2 * k + 1] = match (side[k], side[(k + 1) % 4]) {
            (Some(a), _) => region.neighbor(a, next).is_some(),
            (None, Some(b)) => region.neighbor(b, d).is_some(),
            (None, None) => region.contains(p.step(d).step(next)),
        };
    }
    occupied
}

/// The eight neighbours of `p` in counter-clockwise order starting east:
/// E, NE, N, NW, W, SW, S, SE.
pub fn ring(p: Pixel) -> [Pixel; 8] {
    const OFFSETS: [(i32, i32); 8] = [
        (1, 0),
        (1, 1),
        (0, 1),
        (-1, 1),
        (-1, 0),
        (-1, -1),
        (0, -1),
        (1, -1),
    ];
    OFFSETS.map(|(dx, dy)| Pixel::new(p.x + dx, p.y + dy))
}

/// Yokoi's 4-connectivity number of a pixel, from the occupancy of its 8-neighbourhood in the
/// order of [`ring`]: the number of distinct 4-connected arcs of the region around it that
/// touch its sides. 1 means the pixel is *simple* (adding or removing it changes neither the
/// components nor the holes); 2 or more means it is a local cut vertex when it belongs to the
/// region.
pub fn connectivity_number(occupied: [bool; 8]) -> u32 {
    (0..4)
        .map(|k| {
            let (a, b, c) = (
                occupied[2 * k],
                occupied[2 * k + 1],
                occupied[(2 * k + 2) % 8],
            );
            u32::from(a && !(b && c))
        })
        .sum()
}

/// [`connectivity_number`] of pixel `p` (in the region or not) with respect to `region`.
// Only the tests ask this of a single pixel; the crate's callers work on ring occupancies.
#[cfg(test)]
fn connectivity_number_at(region: &Region, p: Pixel) -> u32 {
    connectivity_number(ring(p).map(|q| region.contains(q)))
}

/// Colour classes of the checkerboard: (#black, #white), black when x + y is even.
pub fn colour_counts(region: &Region) -> (usize, usize) {
    let black = region.pixels().iter().filter(|p| p.is_black()).count();
    (black, region.len() - black)
}

/// A region is thin when it contains no 2×2 block of pixels (turn-cost paper, Section 5.5).
///
/// # Complexity
/// O(N) time.
pub fn is_thin(region: &Region) -> bool {
    !(0..region.len()).any(|i| {
        region.neighbor(i, Dir::N).is_some()
            && region
                .neighbor(i, Dir::E)
                .and_then(|e| region.neighbor(e, Dir::N))
                .is_some()
    })
}

/// A maximal run of pixels in one row (horizontal) or one column (vertical).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Strip {
    /// The lowest (vertical) or leftmost (horizontal) pixel.
    pub start: Pixel,
    /// Number of pixels.
    pub len: u32,
    pub horizontal: bool,
}

impl Strip {
    /// The last pixel of the strip.
    pub fn end(&self) -> Pixel {
        let k = self.len as i32 - 1;
        if self.horizontal {
            Pixel::new(self.start.x + k, self.start.y)
        } else {
            Pixel::new(self.start.x, self.start.y + k)
        }
    }

    pub fn pixels(&self) -> impl Iterator<Item = Pixel> + '_ {
        let d = if self.horizontal { Dir::E } else { Dir::N };
        (0..self.len as i32).map(move |k| {
            let (dx, dy) = d.delta();
            Pixel::new(self.start.x + k * dx, self.start.y + k * dy)
        })
    }
}

/// The maximal horizontal (`horizontal = true`) or vertical strips of the region, ordered by
/// their start pixel's index.
pub fn strips(region: &Region, horizontal: bool) -> Vec<Strip> {
    let (back, fwd) = if horizontal {
        (Dir::W, Dir::E)
    } else {
        (Dir::S, Dir::N)
    };
    let mut out = Vec::new();
    for i in 0..region.len() {
        if region.neighbor(i, back).is_some() {
            continue;
        }
        let mut len = 1;
        let mut j = i;
        while let Some(k) = region.neighbor(j, fwd) {
            len += 1;
            j = k;
        }
        out.push(Strip {
            start: region.pixel(i),
            len,
            horizontal,
        });
    }
    out
}

/// The biconnected components (blocks) of the grid graph, as pixel lists: iterative
/// Hopcroft–Tarjan with an edge stack. A bridge is a block of two pixels. Blocks come in the
/// order the search closes them (the order Theorem 5's tours of the blocks are built in).
pub fn biconnected_blocks(region: &Region) -> Vec<Vec<usize>> {
    let mut blocks = Vec::new();
    for_each_block(region, |block| blocks.push(std::mem::take(block)));
    blocks
}

/// The crate's one Tarjan search: calls `f` with the pixels of every block (biconnected
/// component, a bridge being two pixels) in the order the search closes them, each pixel once
/// per block, in the order the block's edges leave the edge stack. `f` may take the vector.
///
/// # Complexity
/// O(N) time and space (iterative, so no stack overflow on large regions).
fn for_each_block(region: &Region, mut f: impl FnMut(&mut Vec<usize>)) {
    let n = region.len();
    let mut disc = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut time = 0u32;
    // Pixel indices fit in u32 (at most MAX_PIXELS); edges as (tail, head).
    // A grid graph has at most 2N edges; reserved so that the stack never moves.
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(2 * n);
    let mut block = Vec::new();
    let mut closed = 0u32;
    let mut stamp = vec![u32::MAX; n];
    // Stack frames: (vertex, parent, next direction to try).
    let mut frames: Vec<(usize, usize, usize)> = Vec::new();
    for root in 0..n {
        if disc[root] != u32::MAX {
            continue;
        }
        disc[root] = time;
        low[root] = time;
        time += 1;
        frames.push((root, usize::MAX, 0));
        while let Some(frame) = frames.last_mut() {
            let (v, parent, d) = *frame;
            if d < 4 {
                frame.2 += 1;
                let Some(w) = region.neighbor(v, Dir::from_index(d)) else {
                    continue;
                };
                if disc[w] == u32::MAX {
                    disc[w] = time;
                    low[w] = time;
                    time += 1;
                    edges.push((v as u32, w as u32));
                    frames.push((w, v, 0));
                } else if w != parent && disc[w] < disc[v] {
                    edges.push((v as u32, w as u32));
                    low[v] = low[v].min(disc[w]);
                }
            } else {
                frames.pop();
                if parent != usize::MAX {
                    low[parent] = low[parent].min(low[v]);
                    if low[v] >= disc[parent] {
                        block.clear();
                        while let Some((a, b)) = edges.pop() {
                            for x in [a, b] {
                                if stamp[x as usize] != closed {
                                    stamp[x as usize] = closed;
                                    block.push(x as usize);
                                }
                            }
                            if (a as usize, b as usize) == (parent, v) {
                                break;
                            }
                        }
                        closed += 1;
                        f(&mut block);
                    }
                }
            }
        }
    }
}

/// What the boundary does at a saddle: a lattice point where two region pixels touch only
/// diagonally (the other two pixels around it are empty).
#[derive(Clone, Copy, Debug)]
pub enum Saddle<'a> {
    /// Each pixel keeps its own corner, as 4-adjacency has it: rings of different components
    /// stay apart, and a ring may pass a saddle twice (the drawn outline).
    Apart,
    /// Pixels with equal labels are joined around the empty pixel, others kept apart: no ring
    /// passes a point twice and rings only touch, as OGC requires of polygon rings (WKT).
    JoinSameLabel(&'a [u32]),
}

/// A closed boundary ring of a region.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ring {
    /// Corners (collinear points dropped, the first not repeated), traced with the region on
    /// the left (outer boundaries counter-clockwise, holes clockwise), from the lowest, then
    /// leftmost, one.
    pub corners: Vec<(i64, i64)>,
    /// Index of a pixel the ring bounds (one on its left).
    pub pixel: usize,
}

/// The region's boundary as closed rings, in the order of their first corner (lowest, then
/// leftmost); `saddle` decides what happens where pixels touch only diagonally. The crate's one
/// boundary tracer: the drawn outline and the WKT writer both use it.
///
/// A unit boundary edge is named by the pixel on its left and the side of that pixel it lies
/// on; the walk goes from edge to edge, turning left around its own pixel, going straight onto
/// the next pixel, or turning right around an empty pixel onto a diagonal one.
///
/// # Complexity
/// O(N + P log P) time and O(N) extra space for N pixels and P rings (i64 corners, so a pixel
/// at `i32::MAX` has its far corners), never the area of the bounding box.
pub fn boundary_rings(region: &Region, saddle: Saddle) -> Vec<Ring> {
    let mut visited = vec![false; 4 * region.len()];
    let mut rings = Vec::new();
    for i in 0..region.len() {
        for side in Dir::ALL {
            if region.neighbor(i, side).is_none() && !visited[4 * i + side.index()] {
                let corners = trace_ring(region, saddle, &mut visited, i, side);
                rings.push(Ring { corners, pixel: i });
            }
        }
    }
    // At most one ring has its lowest-leftmost corner at a given point (a saddle has one
    // outgoing edge west or south), so this order is total.
    rings.sort_unstable_by_key(|r| r.corners.first().map(|&(x, y)| (y, x)));
    rings
}

/// Walks the boundary ring through the unit edge on side `start_side` of pixel `start`,
/// keeping the region on the left, and returns its corners from the lowest, then leftmost, one.
fn trace_ring(
    region: &Region,
    saddle: Saddle,
    visited: &mut [bool],
    start: usize,
    start_side: Dir,
) -> Vec<(i64, i64)> {
    let apart = |a: usize, b: usize| match saddle {
        Saddle::Apart => true,
        Saddle::JoinSameLabel(label) => label[a] != label[b],
    };
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
            (None, Some(b)) if apart(i, b) => (i, heading),
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

/// Connected components of the graph on nodes `0..n` with the given edges: a label per node in
/// `0..count`, numbered in order of each component's smallest node, and the count.
///
/// # Complexity
/// O((n + edges) α(n)) (petgraph's union-find).
pub fn graph_components(
    n: usize,
    edges: impl IntoIterator<Item = (usize, usize)>,
) -> (Vec<u32>, usize) {
    let mut uf = UnionFind::<usize>::new(n);
    for (a, b) in edges {
        uf.union(a, b);
    }
    let mut label = vec![u32::MAX; n];
    let mut count = 0u32;
    let out = (0..n)
        .map(|v| {
            let r = uf.find_mut(v);
            if label[r] == u32::MAX {
                label[r] = count;
                count += 1;
            }
            label[r]
        })
        .collect();
    (out, count as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::Symmetry;
    use proptest::prelude::*;

    #[test]
    fn square_donut() {
        let r = Region::from_ascii(
            "#####\n\
             #...#\n\
             #...#\n\
             #####\n",
        );
        let s = summary(&r);
        assert_eq!(s.n, 14);
        assert_eq!(s.holes, 1);
        assert_eq!(s.components, 1);
        assert_eq!(s.boundary, 14);
        assert_eq!(s.internal, 0);
        assert_eq!(s.cut_vertices, 0);
        // Every pixel of a width-1 annulus is a local cut vertex: removing it opens the hole.
        assert_eq!(s.local_cut_vertices, 14);
        assert!(s.thin);
        assert_eq!(s.strips_h, 2 + 4);
        assert_eq!(s.strips_v, 2 + 6);
        assert_eq!((s.black, s.white), (7, 7));
    }

    #[test]
    fn cut_vertices_of_a_dumbbell() {
        let r = Region::from_ascii(
            "##...##\n\
             #######\n\
             ##...##\n",
        );
        let cut = cut_vertices(&r);
        let cuts: Vec<Pixel> = (0..r.len())
            .filter(|&i| cut[i])
            .map(|i| r.pixel(i))
            .collect();
        assert_eq!(
            cuts,
            vec![
                Pixel::new(1, 1),
                Pixel::new(2, 1),
                Pixel::new(3, 1),
                Pixel::new(4, 1),
                Pixel::new(5, 1)
            ]
        );
        let s = summary(&r);
        assert_eq!(s.cut_vertices, 5);
        assert_eq!(s.local_cut_vertices, 5);
        assert_eq!(s.holes, 0);
        // The two pixels where the bar meets the bells have all four neighbours.
        assert_eq!(s.internal, 2);
        assert!(!s.thin);
    }

    #[test]
    fn holes_are_8_connected_and_region_4_connected() {
        // Two diagonal empty cells form one hole; two diagonal pixels are two components.
        let r = Region::from_ascii(
            "####\n\
             #.##\n\
             ##.#\n\
             ####\n",
        );
        assert_eq!(holes(&r).count, 1);
        assert_eq!(holes(&r).hole_cells()[0].len(), 2);
        let d = Region::from_ascii("#.\n.#\n");
        assert_eq!(components(&d).count, 2);
        assert_eq!(holes(&d).count, 0);
    }

    #[test]
    fn local_cut_vertex_that_is_not_a_cut_vertex() {
        // Removing a pixel of the wall between the two holes merges them.
        let r = Region::from_ascii(
            "#######\n\
             #######\n\
             ##.#.##\n\
             #######\n\
             #######\n",
        );
        let s = summary(&r);
        assert_eq!(s.holes, 2);
        assert_eq!(s.cut_vertices, 0);
        let local = local_cut_vertices(&r);
        let walls: Vec<Pixel> = (0..r.len())
            .filter(|&i| local[i])
            .map(|i| r.pixel(i))
            .collect();
        assert_eq!(
            walls,
            vec![Pixel::new(3, 1), Pixel::new(3, 2), Pixel::new(3, 3)]
        );
        // In a thin frame every pixel touches both the hole and the outside.
        let frame = Region::from_ascii("#####\n#.#.#\n#####\n");
        assert_eq!(summary(&frame).local_cut_vertices, 13);
    }

    #[test]
    fn boundary_and_internal_of_a_square() {
        let r = Region::rectangle(5, 4);
        let s = summary(&r);
        assert_eq!((s.boundary, s.internal), (14, 6));
        assert_eq!((s.strips_h, s.strips_v), (4, 5));
        assert_eq!(s.local_cut_vertices, 0);
    }

    fn random_region() -> impl Strategy<Value = Region> {
        (1usize..8, 1usize..8)
            .prop_flat_map(|(w, h)| {
                proptest::collection::vec(proptest::bool::weighted(0.65), w * h).prop_map(
                    move |bits| {
                        Region::from_pixels(
                            bits.iter()
                                .enumerate()
                                .filter(|(_, b)| **b)
                                .map(|(k, _)| Pixel::new((k % w) as i32, (k / w) as i32)),
                        )
                        .unwrap()
                    },
                )
            })
            .prop_filter("non-empty", |r| !r.is_empty())
    }

    /// Removes pixel `i` and recounts, straight from Definition 6.
    fn is_local_cut_by_definition(r: &Region, i: usize) -> bool {
        let rest = Region::from_pixels(
            r.pixels()
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, &p)| p),
        )
        .unwrap();
        let before = components(r);
        // Removing v disconnects G: its own component splits (removing an isolated pixel does not).
        let comp_of_v = before.label[i];
        let size_v = before.label.iter().filter(|&&l| l == comp_of_v).count();
        let disconnects = components(&rest).count > before.count - usize::from(size_v == 1);
        disconnects || holes(&rest).count < holes(r).count
    }

    /// The bounded 8-connected components of the complement by flood fill over the bounding
    /// box grown by one cell: the simple dense reference for [`holes`].
    fn reference_hole_cells(r: &Region) -> Vec<Vec<Pixel>> {
        let b = r.bbox();
        let (x0, y0) = (b.min_x - 1, b.min_y - 1);
        let (w, h) = (b.width() as i32 + 2, b.height() as i32 + 2);
        let mut label = vec![u32::MAX; (w * h) as usize];
        let at = |x: i32, y: i32| ((y - y0) * w + (x - x0)) as usize;
        let mut next = 0;
        let mut cells: Vec<Vec<Pixel>> = Vec::new();
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                if label[at(x, y)] != u32::MAX || r.contains(Pixel::new(x, y)) {
                    continue;
                }
                let mut component = vec![];
                let mut stack = vec![Pixel::new(x, y)];
                label[at(x, y)] = next;
                while let Some(p) = stack.pop() {
                    component.push(p);
                    for q in ring(p) {
                        let inside = q.x >= x0 && q.y >= y0 && q.x < x0 + w && q.y < y0 + h;
                        if inside && label[at(q.x, q.y)] == u32::MAX && !r.contains(q) {
                            label[at(q.x, q.y)] = next;
                            stack.push(q);
                        }
                    }
                }
                component.sort_by_key(|p| (p.y, p.x));
                cells.push(component);
                next += 1;
            }
        }
        // Component 0 holds the frame's corner: the outside.
        cells.remove(0);
        cells
    }

    /// Components by breadth-first search over a hash set of pixels.
    fn reference_component_count(r: &Region) -> usize {
        let mut unseen: std::collections::HashSet<Pixel> = r.pixels().iter().copied().collect();
        let mut count = 0;
        while let Some(&s) = unseen.iter().next() {
            unseen.remove(&s);
            let mut stack = vec![s];
            while let Some(p) = stack.pop() {
                for d in Dir::ALL {
                    if unseen.remove(&p.step(d)) {
                        stack.push(p.step(d));
                    }
                }
            }
            count += 1;
        }
        count
    }

    /// Component labels by a search pixel by pixel through `Region::contains`, components
    /// numbered in the order of their first pixel.
    fn reference_labels(r: &Region) -> Vec<u32> {
        let mut label = vec![u32::MAX; r.len()];
        let mut count = 0;
        for s in 0..r.len() {
            if label[s] != u32::MAX {
                continue;
            }
            label[s] = count;
            let mut stack = vec![r.pixel(s)];
            while let Some(p) = stack.pop() {
                for d in Dir::ALL {
                    if let Some(j) = r.index_of(p.step(d))
                        && label[j] == u32::MAX
                    {
                        label[j] = count;
                        stack.push(p.step(d));
                    }
                }
            }
            count += 1;
        }
        label
    }

    /// Euler characteristic V − E + F of the pixel complex (pixels, 4-adjacent pairs and 2×2
    /// blocks); with a 4-connected region and an 8-connected complement it equals
    /// components − holes.
    fn euler_characteristic(r: &Region) -> i64 {
        let has = |p: Pixel| r.contains(p);
        let (mut v, mut e, mut f) = (0i64, 0i64, 0i64);
        for &p in r.pixels() {
            v += 1;
            e += i64::from(has(p.step(Dir::E))) + i64::from(has(p.step(Dir::N)));
            f += i64::from(
                has(p.step(Dir::E)) && has(p.step(Dir::N)) && has(Pixel::new(p.x + 1, p.y + 1)),
            );
        }
        v - e + f
    }

    /// Regions up to 24 × 24 with any density, placed anywhere (far from the origin too).
    fn wide_random_region() -> impl Strategy<Value = Region> {
        (
            1usize..24,
            1usize..24,
            0.2f64..0.95,
            -1000i32..1000,
            -1000i32..1000,
        )
            .prop_flat_map(|(w, h, density, dx, dy)| {
                proptest::collection::vec(proptest::bool::weighted(density), w * h).prop_map(
                    move |bits| {
                        Region::from_pixels(
                            bits.iter()
                                .enumerate()
                                .filter(|(_, b)| **b)
                                .map(|(k, _)| Pixel::new((k % w) as i32 + dx, (k / w) as i32 + dy)),
                        )
                        .unwrap()
                    },
                )
            })
            .prop_filter("non-empty", |r| !r.is_empty())
    }

    proptest! {
        #[test]
        fn holes_and_components_match_the_references(r in wide_random_region()) {
            let h = holes(&r);
            let cells = reference_hole_cells(&r);
            prop_assert_eq!(h.count, cells.len());
            prop_assert_eq!(h.hole_cells(), cells.clone());
            let labels = components(&r);
            prop_assert_eq!(&labels.label, &reference_labels(&r));
            let c = labels.count;
            prop_assert_eq!(c, reference_component_count(&r));
            prop_assert_eq!(c as i64 - h.count as i64, euler_characteristic(&r));
            // Every cell of the box grown by one gets its complement component.
            let b = r.bbox();
            for y in b.min_y - 1..=b.max_y + 1 {
                for x in b.min_x - 1..=b.max_x + 1 {
                    let p = Pixel::new(x, y);
                    let expect = if r.contains(p) {
                        None
                    } else {
                        Some(cells.iter().position(|c| c.contains(&p)).map_or(0, |k| k as u32 + 1))
                    };
                    prop_assert_eq!(h.label_at(p), expect, "cell {}", p);
                }
            }
        }

        #[test]
        fn thinness_and_ring_occupancy_match_lookups(r in wide_random_region()) {
            for i in 0..r.len() {
                prop_assert_eq!(ring_occupancy(&r, i), ring(r.pixel(i)).map(|q| r.contains(q)));
            }
            let blocks = r.pixels().iter().any(|p| {
                [(1, 0), (0, 1), (1, 1)].iter().all(|&(dx, dy)| r.contains(Pixel::new(p.x + dx, p.y + dy)))
            });
            prop_assert_eq!(is_thin(&r), !blocks);
        }

        #[test]
        fn local_cut_matches_definition_and_yokoi(r in random_region()) {
            let local = local_cut_vertices(&r);
            for (i, &is_local) in local.iter().enumerate() {
                prop_assert_eq!(is_local, is_local_cut_by_definition(&r, i), "pixel {}", r.pixel(i));
                prop_assert_eq!(is_local, connectivity_number_at(&r, r.pixel(i)) >= 2, "pixel {}", r.pixel(i));
            }
        }

        #[test]
        fn cut_vertices_match_definition(r in random_region()) {
            let cut = cut_vertices(&r);
            let base = components(&r).count;
            for (i, &is_cut) in cut.iter().enumerate() {
                let rest = Region::from_pixels(
                    r.pixels().iter().enumerate().filter(|&(j, _)| j != i).map(|(_, &p)| p),
                ).unwrap();
                let isolated = r.degree(i) == 0;
                let expect = components(&rest).count > base - usize::from(isolated);
                prop_assert_eq!(is_cut, expect, "pixel {}", r.pixel(i));
            }
        }

        #[test]
        fn symmetries_keep_every_count(r in random_region()) {
            let s = summary(&r);
            for sym in Symmetry::all() {
                let t = summary(&r.transformed(sym));
                prop_assert_eq!(t.n, s.n);
                prop_assert_eq!(t.holes, s.holes);
                prop_assert_eq!(t.components, s.components);
                prop_assert_eq!(t.boundary, s.boundary);
                prop_assert_eq!(t.internal, s.internal);
                prop_assert_eq!(t.cut_vertices, s.cut_vertices);
                prop_assert_eq!(t.local_cut_vertices, s.local_cut_vertices);
                prop_assert_eq!(t.thin, s.thin);
                prop_assert_eq!(t.strips_h + t.strips_v, s.strips_h + s.strips_v);
                // Quarter turns swap rows and columns; colour classes may swap under odd maps.
                if sym.0 % 2 == 0 {
                    prop_assert_eq!((t.strips_h, t.strips_v), (s.strips_h, s.strips_v));
                } else {
                    prop_assert_eq!((t.strips_h, t.strips_v), (s.strips_v, s.strips_h));
                }
                prop_assert_eq!(t.black.max(t.white), s.black.max(s.white));
            }
        }
    }

    #[test]
    fn connectivity_number_cases() {
        // Interior pixel: 0; end of a corridor: 1; middle of a corridor: 2; plus centre: 4.
        assert_eq!(connectivity_number([true; 8]), 0);
        assert_eq!(
            connectivity_number([true, false, false, false, false, false, false, false]),
            1
        );
        assert_eq!(
            connectivity_number([true, false, false, false, true, false, false, false]),
            2
        );
        assert_eq!(
            connectivity_number([true, false, true, false, true, false, true, false]),
            4
        );
    }
}
