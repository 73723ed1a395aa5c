//! `eroded`: a square eroded pixel by pixel down to exactly N pixels, keeping the region
//! 4-connected: the process of a published CPLEX study of minimum-turn cycle covers and tours
//! (a Master's thesis of 2016, whose instance files and generator are public: the repository
//! `d-krupke/mt`, `experiments/instances/gridgraph/fc/`, and its `random_instances.cpp`).
//!
//! **The study's process**, followed here step for step. Start from the s × s square,
//! s = round(√(3N)) (about 3N pixels, so about 2/3 of them go). Then go over the pixels in
//! passes, each in a fresh random order; a pixel still present is drawn with probability
//! `min(1, p · (1 + a)^m · (1 + b)^d)`, m of its 4 side neighbours and d of its 4 diagonal
//! neighbours missing (outside the square counts as missing; the counts are taken when the
//! pixel's turn comes, so deletions earlier in the pass count), and a drawn pixel is deleted
//! unless that disconnects the region (the study deletes it and puts it back). The process
//! stops as soon as N pixels remain, in the middle of a pass. The study's parameters:
//! * `dense`: p = 0.001, a = 5, b = 4: erosion mostly from the outside and from the few
//!   holes that open early, a compact blob with a rough boundary;
//! * `sparse`: p = 0.01, a = 3, b = 2: ten times as many inner deletions, whose holes grow
//!   and merge, so that the result is a network of corridors around many holes.
//!
//! What differs, and why it changes nothing in distribution: the study draws with `rand() %
//! 1000 < 1000 · p · v` (probabilities in steps of 1/1000, with the C library's generator) and
//! shuffles all cells of the square, absent ones included, where we draw a uniform real
//! against `p · v` with ChaCha8 and shuffle the present pixels only (the present pixels'
//! order is uniform either way). A drawn pixel known to be a cut vertex is rejected without a
//! search: a cut vertex stays one until one of its neighbours goes, and the study's test
//! would reject it too.
//!
//! **Until 2026-12-07** `eroded` used our own reading of the thesis's prose (a square of
//! side ⌈3√N⌉, weights by missing side neighbours only); its sparse regions were much easier
//! to solve than the thesis's (tours of 1,500–2,900 pixels proven in seconds against gaps of
//! 1–12% after 900 s). docs/measured.md compares the statistics of the two with the thesis's
//! own files.
//!
//! **Testing connectivity.** Deleting a pixel keeps a 4-connected region 4-connected exactly
//! when the pixel is not a cut vertex. The cheap local test (the present pixels of its 8-ring
//! that touch its 4-neighbours form one run around it) is sufficient; when it fails (a loop
//! around a hole, a corridor) breadth-first searches from the pixel's present neighbours run
//! in lockstep until they all meet (not a cut vertex) or one group runs out (a cut vertex).
//!
//! # Complexity
//! O(s²) = O(N) space; time O(N) per pass plus the exact tests, each about the smaller side
//! of the tested pixel (measured in docs/measured.md).

use super::rng::{Rng, shuffle};
use super::styles::Style;
use crate::region::Pixel;

/// Scratch space of [`Grid::removable`]: cells stamped with the current search.
struct Search {
    epoch: u32,
    stamp: Vec<u32>,
    colour: Vec<u8>,
}

/// The study's parameters of a style: (p, a, b), a present pixel drawn with probability
/// `min(1, p · (1 + a)^m · (1 + b)^d)` (m side and d diagonal neighbours missing).
fn parameters(style: Style) -> (f64, f64, f64) {
    match style {
        Style::Sparse => (0.01, 3.0, 2.0),
        _ => (0.001, 5.0, 4.0),
    }
}

/// The side of the starting square for N pixels: round(√(3N)), computed in integers (the
/// study's `std::round(std::sqrt(3 * size))`; a half rounds up, and 3N is never a square
/// plus a quarter, so the two agree).
pub(super) fn eroded_side(n: usize) -> usize {
    let target = 3 * n;
    // The largest s with s² ≤ 3N, then up when (s + 1/2)² ≤ 3N.
    let mut s = (target as f64).sqrt() as usize;
    while s * s > target {
        s -= 1;
    }
    while (s + 1) * (s + 1) <= target {
        s += 1;
    }
    if 4 * s * s + 4 * s < 4 * target {
        s += 1;
    }
    s
}

/// The grid of the erosion: the square with a margin of one missing cell on every side.
struct Grid {
    w: usize,
    present: Vec<bool>,
    count: usize,
}

impl Grid {
    fn neighbours4(&self, k: usize) -> [usize; 4] {
        [k + 1, k + self.w, k - 1, k - self.w]
    }

    /// The 8-ring of `k` in cyclic order (E, NE, N, NW, W, SW, S, SE).
    fn ring(&self, k: usize) -> [usize; 8] {
        let w = self.w;
        [
            k + 1,
            k + w + 1,
            k + w,
            k + w - 1,
            k - 1,
            k - w - 1,
            k - w,
            k - w + 1,
        ]
    }

    /// The missing side neighbours and the missing diagonal neighbours of `k`.
    fn missing(&self, k: usize) -> (usize, usize) {
        let ring = self.ring(k);
        let side = (0..8)
            .step_by(2)
            .filter(|&i| !self.present[ring[i]])
            .count();
        let diagonal = (1..8)
            .step_by(2)
            .filter(|&i| !self.present[ring[i]])
            .count();
        (side, diagonal)
    }

    /// The local test: the present 4-neighbours of `k` are joined within its 8-ring (a corner
    /// cell joins the two edge cells beside it only when present). Sufficient for `k` not to
    /// be a cut vertex.
    fn locally_removable(&self, k: usize) -> bool {
        let ring = self.ring(k).map(|q| self.present[q]);
        if ring.iter().all(|&b| b) {
            // An inner pixel: deleting it opens a hole.
            return true;
        }
        // Runs of consecutive present cells around the ring are 4-connected; a run of one
        // corner cell holds no neighbour of k and joins nothing, so it does not count.
        let mut runs = 0;
        for i in 0..8 {
            let starts = ring[i] && !ring[(i + 7) % 8];
            let lone_corner = i % 2 == 1 && !ring[(i + 1) % 8];
            if starts && !lone_corner {
                runs += 1;
            }
        }
        runs <= 1
    }

    /// The exact test: the present 4-neighbours of `k` stay joined without `k`. One
    /// breadth-first search per neighbour, run in lockstep; searches that meet merge. It stops
    /// when all have merged (not a cut vertex) or when a merged group runs out of cells (a
    /// cut vertex), so it costs about the smaller side of `k`, or the cells around the
    /// shortest loop through `k`.
    fn removable(&self, k: usize, search: &mut Search) -> bool {
        let targets: Vec<usize> = self
            .neighbours4(k)
            .into_iter()
            .filter(|&q| self.present[q])
            .collect();
        let m = targets.len();
        if m <= 1 {
            return true;
        }
        search.epoch += 1;
        let epoch = search.epoch;
        // group[c]: the search colour c has merged into (union by relabelling, m <= 4).
        let mut group: Vec<usize> = (0..m).collect();
        let mut queues: Vec<std::collections::VecDeque<usize>> = Vec::with_capacity(m);
        for (c, &t) in targets.iter().enumerate() {
            search.stamp[t] = epoch;
            search.colour[t] = c as u8;
            queues.push(std::collections::VecDeque::from([t]));
        }
        search.stamp[k] = epoch;
        search.colour[k] = u8::MAX;
        let groups = |group: &[usize]| {
            let mut g = group.to_vec();
            g.sort_unstable();
            g.dedup();
            g.len()
        };
        loop {
            for c in 0..m {
                let Some(v) = queues[c].pop_front() else {
                    continue;
                };
                for q in self.neighbours4(v) {
                    if !self.present[q] {
                        continue;
                    }
                    if search.stamp[q] != epoch {
                        search.stamp[q] = epoch;
                        search.colour[q] = c as u8;
                        queues[c].push_back(q);
                    } else if search.colour[q] != u8::MAX {
                        let (a, b) = (group[c], group[search.colour[q] as usize]);
                        if a != b {
                            for g in group.iter_mut() {
                                if *g == b {
                                    *g = a;
                                }
                            }
                            if groups(&group) == 1 {
                                return true;
                            }
                        }
                    }
                }
            }
            // A group whose searches have all run dry is cut off from the others.
            for c in 0..m {
                if (0..m)
                    .filter(|&d| group[d] == group[c])
                    .all(|d| queues[d].is_empty())
                {
                    return false;
                }
            }
        }
    }

    /// The cut vertices of the present cells (iterative Tarjan over the 4-neighbourhood), to
    /// test [`Grid::removable`] against.
    #[cfg(test)]
    fn cut_vertices(&self) -> Vec<bool> {
        let area = self.present.len();
        let mut cut = vec![false; area];
        let mut disc = vec![0u32; area];
        let mut low = vec![0u32; area];
        let Some(root) = (0..area).find(|&k| self.present[k]) else {
            return cut;
        };
        let mut time = 1u32;
        let mut stack: Vec<(usize, usize, u8)> = vec![(root, usize::MAX, 0)];
        disc[root] = time;
        low[root] = time;
        let mut root_children = 0;
        while let Some(&mut (v, parent, ref mut i)) = stack.last_mut() {
            if *i < 4 {
                let u = self.neighbours4(v)[*i as usize];
                *i += 1;
                if !self.present[u] || u == parent {
                    continue;
                }
                if disc[u] == 0 {
                    time += 1;
                    disc[u] = time;
                    low[u] = time;
                    if v == root {
                        root_children += 1;
                    }
                    stack.push((u, v, 0));
                } else {
                    low[v] = low[v].min(disc[u]);
                }
            } else {
                stack.pop();
                if let Some(&(p, _, _)) = stack.last() {
                    low[p] = low[p].min(low[v]);
                    if p != root && low[v] >= disc[p] {
                        cut[p] = true;
                    }
                }
            }
        }
        cut[root] = root_children > 1;
        cut
    }

    fn delete(&mut self, k: usize) {
        self.present[k] = false;
        self.count -= 1;
    }
}

/// The pixels of an eroded square with exactly `n` pixels (n ≥ 1), 4-connected.
pub(super) fn eroded_pixels(n: usize, style: Style, rng: &mut Rng) -> Vec<Pixel> {
    let s = eroded_side(n);
    let w = s + 2;
    let mut g = Grid {
        w,
        present: vec![false; w * w],
        count: s * s,
    };
    for y in 1..=s {
        for x in 1..=s {
            g.present[y * w + x] = true;
        }
    }
    let (p, a, b) = parameters(style);
    // chance[m][d] = min(1, p (1 + a)^m (1 + b)^d).
    let chance: [[f64; 5]; 5] = std::array::from_fn(|m| {
        std::array::from_fn(|d| (p * (1.0 + a).powi(m as i32) * (1.0 + b).powi(d as i32)).min(1.0))
    });
    let mut search = Search {
        epoch: 0,
        stamp: vec![0; w * w],
        colour: vec![0; w * w],
    };
    // Pixels found to be cut vertices since a pixel of their ring last went.
    let mut cut = vec![false; w * w];
    let mut order: Vec<usize> = (0..w * w).filter(|&k| g.present[k]).collect();
    while g.count > n {
        order.retain(|&k| g.present[k]);
        shuffle(&mut order, rng);
        for &k in &order {
            if !g.present[k] {
                continue;
            }
            let (m, d) = g.missing(k);
            if !super::rng::chance(rng, chance[m][d]) || cut[k] {
                continue;
            }
            if g.count > 1 && !g.locally_removable(k) && !g.removable(k, &mut search) {
                cut[k] = true;
                continue;
            }
            g.delete(k);
            for q in g.ring(k) {
                cut[q] = false;
            }
            if g.count <= n {
                break;
            }
        }
    }
    (0..g.present.len())
        .filter(|&k| g.present[k])
        .map(|k| Pixel::new((k % w) as i32 - 1, (k / w) as i32 - 1))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn side_is_three_n_rounded_to_the_nearest_integer() {
        assert_eq!(eroded_side(1), 2);
        assert_eq!(eroded_side(100), 17);
        assert_eq!(eroded_side(1000), 55);
        assert_eq!(eroded_side(2900), 93);
        for n in 1..20_000 {
            let s = eroded_side(n) as f64;
            let r = (3.0 * n as f64).sqrt();
            assert!((s - r).abs() <= 0.5, "n {n}: side {s}, sqrt(3n) {r}");
            assert!(s * s >= n as f64, "n {n}");
        }
    }

    /// The local test against the definition, on every 8-ring.
    #[test]
    fn local_test_implies_not_a_cut_vertex_of_the_block() {
        for mask in 0u32..256 {
            let w = 5;
            let mut g = Grid {
                w,
                present: vec![false; 25],
                count: 0,
            };
            let k = 2 * w + 2;
            g.present[k] = true;
            let ring = g.ring(k);
            for (i, &q) in ring.iter().enumerate() {
                // Lone corners are not joined to k inside the block: leave them out.
                let lone =
                    i % 2 == 1 && (mask >> (i - 1) & 1 == 0) && (mask >> ((i + 1) % 8) & 1 == 0);
                g.present[q] = mask >> i & 1 == 1 && !lone;
            }
            if g.neighbours4(k).iter().all(|&q| !g.present[q]) {
                continue;
            }
            g.count = g.present.iter().filter(|&&b| b).count();
            // Within the 3 x 3 block, the local test is exact.
            let cut = g.cut_vertices()[k];
            assert_eq!(
                g.locally_removable(k),
                !cut,
                "mask {mask:08b}: local test and block cut vertex disagree"
            );
        }
    }

    /// The exact test agrees with Tarjan's cut vertices on random connected pieces.
    #[test]
    fn exact_test_agrees_with_cut_vertices() {
        use rand::SeedableRng;
        let mut rng = Rng::seed_from_u64(3);
        for _ in 0..40 {
            let w = 14;
            let mut g = Grid {
                w,
                present: vec![false; w * w],
                count: 0,
            };
            for y in 1..w - 1 {
                for x in 1..w - 1 {
                    g.present[y * w + x] = super::super::rng::chance(&mut rng, 0.6);
                }
            }
            // Keep the component of the first pixel.
            let start = (0..w * w).find(|&k| g.present[k]).unwrap();
            let mut keep = vec![false; w * w];
            let mut stack = vec![start];
            keep[start] = true;
            while let Some(v) = stack.pop() {
                for q in g.neighbours4(v) {
                    if g.present[q] && !keep[q] {
                        keep[q] = true;
                        stack.push(q);
                    }
                }
            }
            g.present = keep;
            g.count = g.present.iter().filter(|&&b| b).count();
            let cut = g.cut_vertices();
            let mut search = Search {
                epoch: 0,
                stamp: vec![0; w * w],
                colour: vec![0; w * w],
            };
            for (k, &is_cut) in cut.iter().enumerate() {
                if g.present[k] && g.count > 1 {
                    assert_eq!(g.removable(k, &mut search), !is_cut, "cell {k}");
                    if g.locally_removable(k) {
                        assert!(!is_cut, "local test passed a cut vertex at {k}");
                    }
                }
            }
        }
    }
}
