//! `lawn-tsp`: the travelling salesman tour through the centres of the grass pixels with L1
//! distances; the walk may leave the grass (milling paper, Section 4, αTSP = 1 reference).
//!
//! Formulation (symmetric TSP on the complete graph): a binary `y_ij` per pair of pixels with
//! cost `|x_i − x_j| + |y_i − y_j|`; degree `Σ_j y_ij = 2` per pixel; subtour elimination
//! `Σ_{i,j ∈ S} y_ij <= |S| − 1` for every proper subset `S` (written on the smaller side),
//! separated by minimum cuts of the support. No sparsification: reduced-cost fixing against
//! the incumbent (a 2-opt / Or-opt tour) removes most pairs from the MIP, with proof.
//! The walk visits the centres in tour order, moving horizontally then vertically between
//! consecutive ones.

use super::cuts::violated_cuts;
use super::driver::CutModel;
use super::lp::{Deadline, Formulation, Row};
use crate::region::{Pixel, Region};
use crate::topology::graph_components;

pub(crate) struct LawnModel<'a> {
    region: &'a Region,
    /// Column of pair (i, j), i < j: pairs are listed row by row.
    pairs: Vec<(u32, u32)>,
    formulation: Formulation,
}

impl<'a> LawnModel<'a> {
    pub(crate) fn new(region: &'a Region) -> LawnModel<'a> {
        let n = region.len();
        let mut f = Formulation::default();
        let mut pairs = Vec::with_capacity(n * n.saturating_sub(1) / 2);
        for i in 0..n {
            for j in i + 1..n {
                let d = region.pixel(i).l1(region.pixel(j)) as f64;
                f.add_col(d, 0.0, 1.0, true);
                pairs.push((i as u32, j as u32));
            }
        }
        let mut m = LawnModel {
            region,
            pairs,
            formulation: Formulation::default(),
        };
        for v in 0..n {
            f.rows.push(Row::range(
                (0..n).filter(|&w| w != v).map(|w| (m.col(v, w), 1.0)),
                2.0,
                2.0,
            ));
        }
        m.formulation = f;
        m
    }

    fn n(&self) -> usize {
        self.region.len()
    }

    fn col(&self, a: usize, b: usize) -> usize {
        let (i, j) = (a.min(b), a.max(b));
        let n = self.n();
        // Pairs before row i: Σ_{r < i} (n − 1 − r).
        i * (2 * n - i - 1) / 2 + (j - i - 1)
    }

    fn dist(&self, a: usize, b: usize) -> u64 {
        self.region.pixel(a).l1(self.region.pixel(b))
    }

    /// Column vector of a cyclic order of all pixels.
    pub(crate) fn columns(&self, order: &[usize]) -> Vec<f64> {
        let mut x = vec![0.0; self.pairs.len()];
        for i in 0..order.len() {
            x[self.col(order[i], order[(i + 1) % order.len()])] = 1.0;
        }
        x
    }

    /// The cycles of a 2-regular integer solution, as vertex orders.
    fn cycles(&self, x: &[f64]) -> Vec<Vec<usize>> {
        let n = self.n();
        let mut adj: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, &(i, j)) in self.pairs.iter().enumerate() {
            if x[k] > 0.5 {
                adj[i as usize].push(j as usize);
                adj[j as usize].push(i as usize);
            }
        }
        let mut seen = vec![false; n];
        let mut out = Vec::new();
        for s in 0..n {
            if seen[s] {
                continue;
            }
            let mut cycle = vec![s];
            seen[s] = true;
            let (mut prev, mut cur) = (usize::MAX, s);
            while let Some(&next) = adj[cur].iter().find(|&&w| w != prev && !seen[w]) {
                seen[next] = true;
                cycle.push(next);
                prev = cur;
                cur = next;
            }
            out.push(cycle);
        }
        out
    }

    /// A tour from a solution: subtours merged greedily (cheapest exchange of one edge of each),
    /// then 2-opt and Or-opt.
    pub(crate) fn merge_and_improve(&self, mut cycles: Vec<Vec<usize>>) -> Vec<usize> {
        while cycles.len() > 1 {
            let mut best: Option<(i64, usize, usize, usize, bool)> = None;
            let a = &cycles[0];
            for (ci, b) in cycles.iter().enumerate().skip(1) {
                for i in 0..a.len() {
                    let (a1, a2) = (a[i], a[(i + 1) % a.len()]);
                    for j in 0..b.len() {
                        let (b1, b2) = (b[j], b[(j + 1) % b.len()]);
                        let old = (self.dist(a1, a2) + self.dist(b1, b2)) as i64;
                        let straight = (self.dist(a1, b1) + self.dist(a2, b2)) as i64 - old;
                        let crossed = (self.dist(a1, b2) + self.dist(a2, b1)) as i64 - old;
                        for (delta, rev) in [(straight, true), (crossed, false)] {
                            if best.is_none_or(|bb| delta < bb.0) {
                                best = Some((delta, ci, i, j, rev));
                            }
                        }
                    }
                }
            }
            let (_, ci, i, j, rev) = best.expect("two cycles have an exchange");
            let b = cycles.swap_remove(ci);
            let lb = b.len();
            // a[..=i], then b from b[j] backwards (a1-b1 ... b2-a2) or from b[j+1] forwards.
            let mut walk: Vec<usize> = if rev {
                (0..lb).map(|t| b[(j + lb - t) % lb]).collect()
            } else {
                (0..lb).map(|t| b[(j + 1 + t) % lb]).collect()
            };
            let a = &cycles[0];
            let mut merged = a[..=i].to_vec();
            merged.append(&mut walk);
            merged.extend_from_slice(&a[i + 1..]);
            cycles[0] = merged;
        }
        let mut tour = cycles.pop().unwrap_or_default();
        self.improve(&mut tour);
        tour
    }

    /// 2-opt and Or-opt (segments of 1 to 3) until no improving move is left.
    pub(crate) fn improve(&self, tour: &mut Vec<usize>) {
        let n = tour.len();
        if n < 4 {
            return;
        }
        let d = |a: usize, b: usize| self.dist(a, b) as i64;
        loop {
            let mut improved = false;
            for i in 0..n - 1 {
                for j in i + 2..n {
                    if i == 0 && j == n - 1 {
                        continue;
                    }
                    let (a, b, c, e) = (tour[i], tour[i + 1], tour[j], tour[(j + 1) % n]);
                    if d(a, c) + d(b, e) < d(a, b) + d(c, e) {
                        tour[i + 1..=j].reverse();
                        improved = true;
                    }
                }
            }
            for len in 1..=3.min(n - 3) {
                'outer: for i in 0..n {
                    // Segment tour[i..i+len] (cyclic) moved between two other neighbours.
                    let seg: Vec<usize> = (0..len).map(|t| tour[(i + t) % n]).collect();
                    let prev = tour[(i + n - 1) % n];
                    let next = tour[(i + len) % n];
                    let gain = d(prev, seg[0]) + d(seg[len - 1], next) - d(prev, next);
                    let rest: Vec<usize> = (0..n - len).map(|t| tour[(i + len + t) % n]).collect();
                    for k in 0..rest.len() {
                        let (p, q) = (rest[k], rest[(k + 1) % rest.len()]);
                        if k + 1 == rest.len() {
                            continue; // that is where the segment came from
                        }
                        for rev in [false, true] {
                            let (s0, s1) = if rev {
                                (seg[len - 1], seg[0])
                            } else {
                                (seg[0], seg[len - 1])
                            };
                            if d(p, s0) + d(s1, q) - d(p, q) < gain {
                                let mut t: Vec<usize> = rest[..=k].to_vec();
                                if rev {
                                    t.extend(seg.iter().rev());
                                } else {
                                    t.extend(seg.iter());
                                }
                                t.extend_from_slice(&rest[k + 1..]);
                                *tour = t;
                                improved = true;
                                break 'outer;
                            }
                        }
                    }
                }
            }
            if !improved {
                break;
            }
        }
    }

    /// Nearest-neighbour tour, improved.
    pub(crate) fn heuristic_tour(&self) -> Vec<usize> {
        let n = self.n();
        let mut seen = vec![false; n];
        let mut tour = vec![0usize];
        seen[0] = true;
        for _ in 1..n {
            let cur = *tour.last().expect("non-empty");
            let next = (0..n)
                .filter(|&w| !seen[w])
                .min_by_key(|&w| (self.dist(cur, w), w))
                .expect("unvisited");
            seen[next] = true;
            tour.push(next);
        }
        self.improve(&mut tour);
        tour
    }

    /// The unit-step walk of a cyclic order of pixels.
    pub(crate) fn walk(&self, order: &[usize]) -> Vec<Pixel> {
        lawn_walk(
            &order
                .iter()
                .map(|&v| self.region.pixel(v))
                .collect::<Vec<_>>(),
        )
    }

    /// The cyclic pixel order of an integer solution with one cycle.
    pub(crate) fn order(&self, x: &[f64]) -> Vec<usize> {
        self.cycles(x).into_iter().next().unwrap_or_default()
    }
}

/// Unit moves through consecutive points of a cyclic sequence: horizontally, then vertically.
pub(crate) fn lawn_walk(points: &[Pixel]) -> Vec<Pixel> {
    let mut out = Vec::new();
    for i in 0..points.len() {
        let (a, b) = (points[i], points[(i + 1) % points.len()]);
        let mut p = a;
        out.push(p);
        while p.x != b.x {
            p.x += b.x.cmp(&p.x) as i32;
            if p != b {
                out.push(p);
            }
        }
        while p.y != b.y {
            p.y += b.y.cmp(&p.y) as i32;
            if p != b {
                out.push(p);
            }
        }
    }
    out
}

impl CutModel for LawnModel<'_> {
    fn formulation(&self) -> &Formulation {
        &self.formulation
    }

    fn separate(&self, x: &[f64], _integral: bool, deadline: &Deadline) -> Vec<Row> {
        let n = self.n();
        let weighted: Vec<(usize, usize, f64)> = self
            .pairs
            .iter()
            .enumerate()
            .filter(|&(k, _)| x[k] > 1e-9)
            .map(|(k, &(i, j))| (i as usize, j as usize, x[k]))
            .collect();
        violated_cuts(n, &weighted, 2.0 - 1e-6, deadline)
            .into_iter()
            .map(|s| {
                let inside = s.iter().filter(|&&b| b).count();
                let side = inside * 2 <= n;
                let members: Vec<usize> = (0..n).filter(|&v| s[v] == side).collect();
                let mut terms = Vec::new();
                for (a, &i) in members.iter().enumerate() {
                    for &j in &members[a + 1..] {
                        terms.push((self.col(i, j), 1.0));
                    }
                }
                Row::range(terms, f64::NEG_INFINITY, members.len() as f64 - 1.0)
            })
            .collect()
    }

    fn is_feasible(&self, x: &[f64]) -> bool {
        let used = self
            .pairs
            .iter()
            .enumerate()
            .filter(|&(k, _)| x[k] > 0.5)
            .map(|(_, &(i, j))| (i as usize, j as usize));
        graph_components(self.n(), used).1 == 1
    }

    fn repair(&self, x: &[f64]) -> Option<Vec<f64>> {
        let tour = self.merge_and_improve(self.cycles(x));
        (tour.len() == self.n()).then(|| self.columns(&tour))
    }
}
