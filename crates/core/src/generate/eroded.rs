//! `eroded`: a full square eroded pixel by pixel down to exactly N pixels, keeping the region
//! 4-connected (the instances of a published CPLEX study of minimum-turn cycle covers and
//! tours, a Master's thesis of 2016).
//!
//! **What the study says.** Instances are a full square of side about 3√N from which pixels are
//! deleted at random, more likely where neighbours are already missing, while keeping the
//! region connected, in a *dense* and a *sparse* variant (the sparse one with a rougher
//! boundary and many small holes), 100 to 2900 pixels, five seeds per size and variant. It
//! does not give the probabilities; what follows is our choice.
//!
//! **What we do.** Start from the s × s square, s = ⌈3√N⌉ (about 9N pixels, so about 8/9 of
//! them go). Repeatedly draw a pixel with probability proportional to its weight, `b^(m−1)`
//! for a pixel with m ≥ 1 of its 4-neighbours already missing (outside the square counts as
//! missing) and `w₀` for an inner pixel, and delete it unless that would disconnect the
//! region, until N pixels remain. A deleted inner pixel opens a hole; holes grow, merge with
//! one another and open to the outside as erosion goes on. The weights set the variant:
//! * `dense`: w₀ = 10⁻⁴, b = 8: erosion almost only from the outside, the shape stays a
//!   compact blob (with the odd corridor where erosion went around a part) and keeps few
//!   holes (seed 4: 3 at N = 1000, 19 at N = 2900);
//! * `sparse`: w₀ = 10⁻², b = 2: many inner deletions early, whose holes grow and merge, so
//!   that the result is a rough network of corridors one or two pixels wide around many holes
//!   (seed 4: 37 at N = 1000, 85 at N = 2900).
//!
//! The values were picked by eye from the pictures of a few seeds at N = 100 and 1000
//! (`mowmill gen eroded ... && mowmill draw`) and by the hole counts (tests/generate.rs).
//!
//! **Keeping connectivity.** Deleting a pixel keeps a 4-connected region 4-connected exactly
//! when the pixel is not a cut vertex. The cheap local test (the present pixels of its 8-ring
//! that touch its 4-neighbours form one run around it) is sufficient but not necessary: the
//! pixels of a loop around a hole fail it. A drawn pixel that fails it moves to a second pool
//! and comes back when a pixel of its 8-ring goes. Only when no pixel passes the local test
//! (the region is all corridors and junctions) is a pixel of the second pool, drawn with the
//! same weights, tested exactly: breadth-first searches from its present neighbours run in
//! lockstep until they all meet (not a cut vertex: deleted) or one group runs out (a cut
//! vertex, which stays one until a pixel of its ring goes: it leaves the pool till then).
//! This order is our reading of the study's process and is what makes holes: loops survive
//! while anything else can be eroded, so the holes opened early stay until the end. (With
//! the exact test first, the sparse variant ends as a tree without holes.)
//!
//! # Complexity
//! O(s²) = O(N) space; time O(N) for the local steps plus the exact tests, each about the
//! smaller side of the tested pixel. Measured (release build, a loaded 2-core machine):
//! N = 2900 in 0.04 s, N = 10⁵ in 1.8 s (dense) and 4.6 s (sparse).

use super::growth::Frontier;
use super::rng::Rng;
use super::styles::Style;
use crate::region::Pixel;

/// Scratch space of [`Grid::removable`]: cells stamped with the current search.
struct Search {
    epoch: u32,
    stamp: Vec<u32>,
    colour: Vec<u8>,
}

/// The weights of a style (`dense` or `sparse`): (w₀, b), a pixel with m ≥ 1 missing
/// 4-neighbours is drawn with weight b^(m−1), an inner pixel with weight w₀. b is a power of
/// two (b^(m−1) exact) and w₀ a constant, so every machine draws the same pixels.
fn base(style: Style) -> (f64, f64) {
    match style {
        Style::Sparse => (0.01, 2.0),
        _ => (0.0001, 8.0),
    }
}

/// The side of the starting square for N pixels: ⌈3√N⌉, computed in integers.
pub(super) fn eroded_side(n: usize) -> usize {
    // The smallest s with s² ≥ 9N.
    let target = 9 * n;
    let mut s = (target as f64).sqrt() as usize;
    while s * s < target {
        s += 1;
    }
    while s > 1 && (s - 1) * (s - 1) >= target {
        s -= 1;
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

    fn missing4(&self, k: usize) -> u8 {
        self.neighbours4(k)
            .iter()
            .filter(|&&q| !self.present[q])
            .count() as u8
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
    let (w0, b) = base(style);
    let weights: [f64; 5] = std::array::from_fn(|m| if m == 0 { w0 } else { b.powi(m as i32 - 1) });
    let mut pool = Frontier::new(w * w);
    let fill = |g: &Grid, pool: &mut Frontier| {
        pool.clear();
        for k in 0..g.present.len() {
            if g.present[k] {
                pool.set(k, Some(g.missing4(k)));
            }
        }
    };
    fill(&g, &mut pool);
    let mut search = Search {
        epoch: 0,
        stamp: vec![0; w * w],
        colour: vec![0; w * w],
    };
    // Pixels that failed the local test, waiting for the exact one.
    let mut failed = Frontier::new(w * w);
    while g.count > n {
        let k = match pool.sample(rng, &weights) {
            Some(k) if g.locally_removable(k) => k,
            Some(k) => {
                pool.set(k, None);
                failed.set(k, Some(g.missing4(k)));
                continue;
            }
            // Stuck: a pixel that failed the local test, tested exactly.
            None => match failed.sample(rng, &weights) {
                Some(k) if g.removable(k, &mut search) => k,
                Some(k) => {
                    // A cut vertex stays one until a pixel of its ring goes.
                    failed.set(k, None);
                    continue;
                }
                // Never: a connected region of two or more pixels has a pixel that is not a
                // cut vertex, and a pixel leaves both pools only while it is one.
                None => break,
            },
        };
        g.delete(k);
        pool.set(k, None);
        failed.set(k, None);
        for q in g.ring(k) {
            if g.present[q] {
                failed.set(q, None);
                pool.set(q, Some(g.missing4(q)));
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
    fn side_is_the_ceiling_of_three_root_n() {
        assert_eq!(eroded_side(1), 3);
        assert_eq!(eroded_side(100), 30);
        assert_eq!(eroded_side(101), 31);
        assert_eq!(eroded_side(2900), 162);
        for n in 1..2000 {
            let s = eroded_side(n);
            assert!(s * s >= 9 * n && (s - 1) * (s - 1) < 9 * n, "n {n}");
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
