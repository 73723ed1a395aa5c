//! `length`: the minimum-length closed walk visiting every pixel (optimal milling tour; TSP on
//! the grid graph with revisits, Section 6 of the milling paper).
//!
//! Formulation (edge multiplicities): for each grid edge `e` an integer `x_e ∈ {0, 1, 2}` (an
//! optimal walk never uses an edge three times: removing two copies keeps the degrees even
//! and the walk connected); for each pixel `v` an integer `z_v >= 1` with
//! `Σ_{e ∋ v} x_e = 2 z_v` (even degree, visited); for every proper nonempty pixel set `S`,
//! `x(δ(S)) >= 2` (connectivity, separated by minimum cuts). Minimize `Σ x_e`. A feasible `x`
//! is a connected Eulerian multigraph on all pixels; its Euler tour (Hierholzer) is the walk.

use super::cuts::subtour_rows;
use super::driver::CutModel;
use super::lp::{Deadline, Formulation, Row};
use super::walks::euler_walk;
use crate::region::{Pixel, Region};
use crate::topology::graph_components;

pub(crate) struct MillingModel<'a> {
    region: &'a Region,
    edges: Vec<(usize, usize)>,
    /// Edges at each pixel.
    incident: Vec<Vec<usize>>,
    /// Unit squares of four pixels, as edge indices (bottom, top, left, right).
    squares: Vec<[usize; 4]>,
    formulation: Formulation,
}

impl<'a> MillingModel<'a> {
    pub(crate) fn new(region: &'a Region) -> MillingModel<'a> {
        let n = region.len();
        let edges: Vec<(usize, usize)> = region.edges().collect();
        let mut incident = vec![Vec::new(); n];
        for (k, &(a, b)) in edges.iter().enumerate() {
            incident[a].push(k);
            incident[b].push(k);
        }
        let mut f = Formulation::default();
        for _ in &edges {
            f.add_col(1.0, 0.0, 2.0, true);
        }
        for at in &incident {
            let deg = at.len() as f64;
            let z = f.add_col(0.0, 1.0, deg.max(1.0), true);
            let terms = at.iter().map(|&k| (k, 1.0)).chain([(z, -2.0)]);
            f.rows.push(Row::range(terms, 0.0, 0.0));
        }
        let edge_index: std::collections::HashMap<(usize, usize), usize> =
            edges.iter().enumerate().map(|(k, &e)| (e, k)).collect();
        let mut squares = Vec::new();
        for v in 0..n {
            let p = region.pixel(v);
            let at = |dx, dy| region.index_of(Pixel::new(p.x + dx, p.y + dy));
            if let (Some(r), Some(t), Some(tr)) = (at(1, 0), at(0, 1), at(1, 1)) {
                let e = |a: usize, b: usize| edge_index[&(a.min(b), a.max(b))];
                squares.push([e(v, r), e(t, tr), e(v, t), e(r, tr)]);
            }
        }
        MillingModel {
            region,
            edges,
            incident,
            squares,
            formulation: f,
        }
    }

    fn num_edges(&self) -> usize {
        self.edges.len()
    }

    /// The full column vector of an edge-multiplicity vector.
    pub(crate) fn columns(&self, mult: &[u32]) -> Vec<f64> {
        let mut x: Vec<f64> = mult.iter().map(|&m| f64::from(m)).collect();
        for v in 0..self.region.len() {
            let deg: u32 = self.incident[v].iter().map(|&k| mult[k]).sum();
            x.push(f64::from(deg / 2));
        }
        x
    }

    pub(crate) fn multiplicities(&self, x: &[f64]) -> Vec<u32> {
        x[..self.num_edges()]
            .iter()
            .map(|&v| v.round().max(0.0) as u32)
            .collect()
    }

    /// Edge multiplicities of a closed walk, reduced to at most 2 per edge (same parity).
    pub(crate) fn walk_multiplicities(&self, walk: &[Pixel]) -> Option<Vec<u32>> {
        let index: std::collections::HashMap<(usize, usize), usize> = self
            .edges
            .iter()
            .enumerate()
            .map(|(k, &e)| (e, k))
            .collect();
        let mut mult = vec![0u32; self.num_edges()];
        if walk.len() < 2 {
            return None;
        }
        for i in 0..walk.len() {
            let a = self.region.index_of(walk[i])?;
            let b = self.region.index_of(walk[(i + 1) % walk.len()])?;
            mult[*index.get(&(a.min(b), a.max(b)))?] += 1;
        }
        for m in &mut mult {
            while *m > 2 {
                *m -= 2;
            }
        }
        Some(mult)
    }

    /// The closed walk of a connected Eulerian multiplicity vector.
    pub(crate) fn walk(&self, mult: &[u32]) -> Vec<Pixel> {
        let start = (0..self.num_edges())
            .find(|&k| mult[k] > 0)
            .map_or(0, |k| self.edges[k].0);
        euler_walk(self.region.len(), &self.edges, mult, start)
            .into_iter()
            .map(|v| self.region.pixel(v))
            .collect()
    }

    fn labels(&self, mult: &[u32]) -> (Vec<u32>, usize) {
        let used = (0..self.num_edges())
            .filter(|&k| mult[k] > 0)
            .map(|k| self.edges[k]);
        graph_components(self.region.len(), used)
    }

    /// Makes an even, covering multiplicity vector connected: zero-cost swaps across unit
    /// squares first (two parallel edges of different components become the other two sides),
    /// else a doubled edge between adjacent components; then drops doubled edges that are not
    /// needed for connectivity.
    pub(crate) fn connect(&self, mut mult: Vec<u32>) -> Vec<u32> {
        loop {
            let (label, count) = self.labels(&mult);
            if count <= 1 {
                break;
            }
            let swap = self.squares.iter().find_map(|&[bot, top, left, right]| {
                let comp = |k: usize| label[self.edges[k].0];
                for (p, q, r, s) in [(bot, top, left, right), (left, right, bot, top)] {
                    if mult[p] > 0 && mult[q] > 0 && comp(p) != comp(q) {
                        return Some((p, q, r, s));
                    }
                }
                None
            });
            if let Some((p, q, r, s)) = swap {
                mult[p] -= 1;
                mult[q] -= 1;
                for k in [r, s] {
                    mult[k] += 1;
                    if mult[k] > 2 {
                        mult[k] -= 2;
                    }
                }
                continue;
            }
            let bridge = (0..self.num_edges())
                .find(|&k| label[self.edges[k].0] != label[self.edges[k].1])
                .expect("a connected region has an edge between any two parts");
            mult[bridge] += 2;
        }
        self.drop_redundant_doubles(&mut mult);
        mult
    }

    fn drop_redundant_doubles(&self, mult: &mut [u32]) {
        for k in 0..self.num_edges() {
            if mult[k] != 2 {
                continue;
            }
            let (a, b) = self.edges[k];
            // Removing both copies must leave a and b with degree >= 2 and the graph connected.
            let deg = |v: usize, m: &[u32]| -> u32 { self.incident[v].iter().map(|&j| m[j]).sum() };
            if deg(a, mult) < 4 || deg(b, mult) < 4 {
                continue;
            }
            mult[k] = 0;
            let used = self.edges.iter().zip(mult.iter()).filter(|&(_, &m)| m > 0);
            if graph_components(self.region.len(), used.map(|(&e, _)| e)).1 != 1 {
                mult[k] = 2;
            }
        }
    }
}

impl CutModel for MillingModel<'_> {
    fn formulation(&self) -> &Formulation {
        &self.formulation
    }

    fn separate(&self, x: &[f64], _integral: bool, deadline: &Deadline) -> Vec<Row> {
        subtour_rows(self.region.len(), &self.edges, x, deadline)
    }

    fn is_feasible(&self, x: &[f64]) -> bool {
        self.labels(&self.multiplicities(x)).1 == 1
    }

    fn repair(&self, x: &[f64]) -> Option<Vec<f64>> {
        let mult = self.connect(self.multiplicities(x));
        Some(self.columns(&mult))
    }
}

/// A quick feasible tour for the first incumbent: a spanning tree walked around (every tree
/// edge twice), length 2(N − 1). The LP and MIP rounds replace it within a round or two.
pub(crate) fn tree_tour(model: &MillingModel) -> Vec<u32> {
    let n = model.region.len();
    let mut mult = vec![0u32; model.num_edges()];
    let mut seen = vec![false; n];
    let mut stack = vec![0usize];
    seen[0] = true;
    while let Some(v) = stack.pop() {
        for &k in &model.incident[v] {
            let (a, b) = model.edges[k];
            let w = if a == v { b } else { a };
            if !seen[w] {
                seen[w] = true;
                mult[k] = 2;
                stack.push(w);
            }
        }
    }
    mult
}
