//! Topology of a region: components, holes, boundary and internal pixels, cut vertices, local
//! cut vertices, colour classes, thinness and maximal strips.
//!
//! Conventions are those of digital topology with a 4-connected region and an 8-connected
//! complement: pixels are adjacent in the grid graph when they share a side, and a hole is a
//! bounded 8-connected component of the complement. Boundary and internal pixels follow
//! Section 6 of the milling paper (a boundary pixel shares a side with the region's boundary;
//! an internal pixel has all 4 neighbours). Local cut vertices follow Definition 6 of the
//! milling paper. Everything here runs in linear time in the size of the bounding box.

use crate::region::{Dir, Pixel, Region};
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
/// O(N + area of the bounding box) time and space.
pub fn summary(region: &Region) -> Summary {
    let cut = cut_vertices(region);
    let local = local_cut_vertices_with(region, &cut);
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

/// The connected components of the grid graph; labels indexed by pixel index.
pub fn components(region: &Region) -> Labels {
    let n = region.len();
    let mut label = vec![u32::MAX; n];
    let mut count = 0;
    let mut stack = Vec::new();
    for s in 0..n {
        if label[s] != u32::MAX {
            continue;
        }
        label[s] = count;
        stack.push(s);
        while let Some(i) = stack.pop() {
            for j in region.neighbors(i) {
                if label[j] == u32::MAX {
                    label[j] = count;
                    stack.push(j);
                }
            }
        }
        count += 1;
    }
    Labels {
        label,
        count: count as usize,
    }
}

/// The complement of a region inside its bounding box grown by one cell on every side,
/// labelled into 8-connected components. Component 0 is the unbounded outside (it contains
/// the frame); every other component is a hole.
#[derive(Clone, Debug)]
pub struct Holes {
    /// Number of holes (bounded 8-connected components of the complement).
    pub count: usize,
    origin: Pixel,
    width: usize,
    height: usize,
    /// Label per frame cell, `u32::MAX` on region pixels.
    label: Vec<u32>,
}

impl Holes {
    /// The complement component of cell `p`: `Some(0)` outside, `Some(h)` for hole `h` (1-based),
    /// `None` for a pixel of the region.
    pub fn label_at(&self, p: Pixel) -> Option<u32> {
        let (dx, dy) = (p.x - self.origin.x, p.y - self.origin.y);
        if dx < 0 || dy < 0 || dx as usize >= self.width || dy as usize >= self.height {
            return Some(0);
        }
        match self.label[dy as usize * self.width + dx as usize] {
            u32::MAX => None,
            l => Some(l),
        }
    }

    /// The cells of each hole, indexed by hole number − 1.
    pub fn hole_cells(&self) -> Vec<Vec<Pixel>> {
        let mut cells = vec![Vec::new(); self.count];
        for (k, &l) in self.label.iter().enumerate() {
            if l != u32::MAX && l > 0 {
                let (x, y) = ((k % self.width) as i32, (k / self.width) as i32);
                cells[l as usize - 1].push(Pixel::new(self.origin.x + x, self.origin.y + y));
            }
        }
        cells
    }
}

/// The holes of a region: bounded 8-connected components of its complement.
pub fn holes(region: &Region) -> Holes {
    if region.is_empty() {
        return Holes {
            count: 0,
            origin: Pixel::new(0, 0),
            width: 0,
            height: 0,
            label: vec![],
        };
    }
    let b = region.bbox();
    let origin = Pixel::new(b.min_x - 1, b.min_y - 1);
    let (width, height) = (b.width() + 2, b.height() + 2);
    let mut label = vec![u32::MAX - 1; width * height];
    for p in region.pixels() {
        label[(p.y - origin.y) as usize * width + (p.x - origin.x) as usize] = u32::MAX;
    }
    const UNSEEN: u32 = u32::MAX - 1;
    let mut next = 0u32;
    let mut stack = Vec::new();
    // Cell 0 is a frame corner, so the outside gets label 0.
    for s in 0..label.len() {
        if label[s] != UNSEEN {
            continue;
        }
        label[s] = next;
        stack.push(s);
        while let Some(k) = stack.pop() {
            let (x, y) = ((k % width) as i64, (k / width) as i64);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (nx, ny) = (x + dx, y + dy);
                    if nx < 0 || ny < 0 || nx >= width as i64 || ny >= height as i64 {
                        continue;
                    }
                    let m = ny as usize * width + nx as usize;
                    if label[m] == UNSEEN {
                        label[m] = next;
                        stack.push(m);
                    }
                }
            }
        }
        next += 1;
    }
    Holes {
        count: next as usize - 1,
        origin,
        width,
        height,
        label,
    }
}

/// A boundary pixel shares at least one side with the region's boundary (fewer than 4
/// neighbours); the others are internal (milling paper, Section 6).
pub fn is_boundary(region: &Region, i: usize) -> bool {
    region.degree(i) < 4
}

/// Articulation points of the grid graph (removal increases the number of components), by
/// an iterative Tarjan depth-first search.
pub fn cut_vertices(region: &Region) -> Vec<bool> {
    let n = region.len();
    let mut disc = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut cut = vec![false; n];
    let mut time = 0u32;
    // Stack frames: (vertex, parent, next direction to try).
    let mut stack: Vec<(usize, usize, usize)> = Vec::new();
    for root in 0..n {
        if disc[root] != u32::MAX {
            continue;
        }
        disc[root] = time;
        low[root] = time;
        time += 1;
        let mut root_children = 0;
        stack.push((root, usize::MAX, 0));
        while let Some(frame) = stack.last_mut() {
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
                    if v == root {
                        root_children += 1;
                    }
                    stack.push((w, v, 0));
                } else if w != parent {
                    low[v] = low[v].min(disc[w]);
                }
            } else {
                stack.pop();
                if parent != usize::MAX {
                    low[parent] = low[parent].min(low[v]);
                    if parent != root && low[v] >= disc[parent] {
                        cut[parent] = true;
                    }
                }
            }
        }
        cut[root] = root_children >= 2;
    }
    cut
}

/// Local cut vertices (milling paper, Definition 6): pixels whose removal disconnects the
/// grid graph or reduces the number of holes.
///
/// Removing pixel v merges the complement components among its eight neighbours into one, so
/// it reduces the number of holes exactly when those neighbours touch two or more distinct
/// complement components.
pub fn local_cut_vertices(region: &Region) -> Vec<bool> {
    local_cut_vertices_with(region, &cut_vertices(region))
}

fn local_cut_vertices_with(region: &Region, cut: &[bool]) -> Vec<bool> {
    let holes = holes(region);
    (0..region.len())
        .map(|i| {
            if cut[i] {
                return true;
            }
            let p = region.pixel(i);
            let mut first: Option<u32> = None;
            for q in ring(p) {
                if let Some(l) = holes.label_at(q) {
                    match first {
                        None => first = Some(l),
                        Some(f) if f != l => return true,
                        _ => {}
                    }
                }
            }
            false
        })
        .collect()
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
pub fn connectivity_number_at(region: &Region, p: Pixel) -> u32 {
    connectivity_number(ring(p).map(|q| region.contains(q)))
}

/// Colour classes of the checkerboard: (#black, #white), black when x + y is even.
pub fn colour_counts(region: &Region) -> (usize, usize) {
    let black = region.pixels().iter().filter(|p| p.is_black()).count();
    (black, region.len() - black)
}

/// A region is thin when it contains no 2×2 block of pixels (turn-cost paper, Section 5.5).
pub fn is_thin(region: &Region) -> bool {
    !region.pixels().iter().any(|&p| {
        [Dir::E, Dir::N].iter().all(|&d| region.contains(p.step(d)))
            && region.contains(Pixel::new(p.x + 1, p.y + 1))
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
    let n = region.len();
    let mut disc = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut time = 0u32;
    let mut edges: Vec<(usize, usize)> = Vec::new();
    let mut blocks = Vec::new();
    let mut stamp = vec![usize::MAX; n];
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
                    edges.push((v, w));
                    frames.push((w, v, 0));
                } else if w != parent && disc[w] < disc[v] {
                    edges.push((v, w));
                    low[v] = low[v].min(disc[w]);
                }
            } else {
                frames.pop();
                if parent != usize::MAX {
                    low[parent] = low[parent].min(low[v]);
                    if low[v] >= disc[parent] {
                        let id = blocks.len();
                        let mut block = Vec::new();
                        while let Some((a, b)) = edges.pop() {
                            for x in [a, b] {
                                if stamp[x] != id {
                                    stamp[x] = id;
                                    block.push(x);
                                }
                            }
                            if (a, b) == (parent, v) {
                                break;
                            }
                        }
                        blocks.push(block);
                    }
                }
            }
        }
    }
    blocks
}

/// The region's boundary as closed lattice polygons (corners only, the first not repeated),
/// traced with the region on the left: outer boundaries counter-clockwise, holes clockwise.
///
/// Where two region pixels touch only at a corner, the tracing turns left (towards the
/// region), so they end up on separate contours, as 4-adjacency has it.
pub fn boundary_polygons(region: &Region) -> Vec<Vec<(i32, i32)>> {
    if region.is_empty() {
        return Vec::new();
    }
    let b = region.bbox();
    let (w1, h1) = (b.width() + 1, b.height() + 1);
    let vertex = |x: i32, y: i32| (y - b.min_y) as usize * w1 + (x - b.min_x) as usize;
    // out[v]: bit d set when a boundary edge leaves lattice point v in direction d.
    let mut out = vec![0u8; w1 * h1];
    let mut edges = 0usize;
    for &p in region.pixels() {
        let (x, y) = (p.x, p.y);
        for (side, start, d) in [
            (Dir::S, (x, y), Dir::E),
            (Dir::E, (x + 1, y), Dir::N),
            (Dir::N, (x + 1, y + 1), Dir::W),
            (Dir::W, (x, y + 1), Dir::S),
        ] {
            if !region.contains(p.step(side)) {
                out[vertex(start.0, start.1)] |= 1 << d.index();
                edges += 1;
            }
        }
    }
    let next_dir = |v: usize, arriving: Dir| {
        [arriving.left(), arriving, arriving.right()]
            .into_iter()
            .find(|d| out[v] & (1 << d.index()) != 0)
    };
    let mut left = out.clone();
    let mut contours = Vec::new();
    for v0 in 0..left.len() {
        while left[v0] != 0 {
            let d0 = Dir::from_index(left[v0].trailing_zeros() as usize);
            let mut steps: Vec<(usize, Dir)> = Vec::new();
            let (mut v, mut d) = (v0, d0);
            loop {
                steps.push((v, d));
                left[v] &= !(1 << d.index());
                let (x, y) = ((v % w1) as i32, (v / w1) as i32);
                let (dx, dy) = d.delta();
                v = (y + dy) as usize * w1 + (x + dx) as usize;
                match next_dir(v, d) {
                    Some(nd) if (v, nd) != (v0, d0) && steps.len() <= edges => d = nd,
                    _ => break,
                }
            }
            let corners = (0..steps.len())
                .filter(|&i| steps[(i + steps.len() - 1) % steps.len()].1 != steps[i].1)
                .map(|i| {
                    let v = steps[i].0;
                    ((v % w1) as i32 + b.min_x, (v / w1) as i32 + b.min_y)
                })
                .collect();
            contours.push(corners);
        }
    }
    contours
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
    let mut uf = petgraph::unionfind::UnionFind::<usize>::new(n);
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

    proptest! {
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
