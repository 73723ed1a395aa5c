//! The `length` model: edge multiplicities with even degrees and connectivity cuts, whose
//! optimum is the shortest closed walk visiting every vertex (see the parent module).

use super::{Answer, LowerBound, is_bipartite, is_connected, tree_walks};
use crate::cuts::subtour_rows;
use crate::driver::{self, CutModel, Stop};
use crate::lp::{Deadline, Formulation, Row, Settings};
use crate::topology::graph_components;
use crate::walks::euler_walk;
use mowmill_core::discrete::{Discrete, VertexWalk};

/// The `length` model (see the module documentation).
pub(super) struct LengthModel<'a> {
    inst: &'a Discrete,
    edges: Vec<(usize, usize)>,
    incident: Vec<Vec<usize>>,
    step: u64,
    formulation: Formulation,
}

impl<'a> LengthModel<'a> {
    fn new(inst: &'a Discrete) -> LengthModel<'a> {
        let n = inst.len();
        let edges: Vec<(usize, usize)> = inst
            .edges()
            .map(|(a, b)| (a as usize, b as usize))
            .collect();
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
            let z = f.add_col(0.0, 1.0, (at.len() as f64).max(1.0), true);
            let terms = at.iter().map(|&k| (k, 1.0)).chain([(z, -2.0)]);
            f.rows.push(Row::range(terms, 0.0, 0.0));
        }
        LengthModel {
            inst,
            edges,
            incident,
            step: if is_bipartite(inst) { 2 } else { 1 },
            formulation: f,
        }
    }

    fn columns(&self, mult: &[u32]) -> Vec<f64> {
        let mut x: Vec<f64> = mult.iter().map(|&m| f64::from(m)).collect();
        for at in &self.incident {
            let deg: u32 = at.iter().map(|&k| mult[k]).sum();
            x.push(f64::from(deg / 2));
        }
        x
    }

    fn multiplicities(&self, x: &[f64]) -> Vec<u32> {
        x[..self.edges.len()]
            .iter()
            .map(|&v| v.round().max(0.0) as u32)
            .collect()
    }

    fn labels(&self, mult: &[u32]) -> (Vec<u32>, usize) {
        let used = (0..self.edges.len())
            .filter(|&k| mult[k] > 0)
            .map(|k| self.edges[k]);
        graph_components(self.inst.len(), used)
    }

    /// Edge multiplicities of a closed walk, reduced to at most 2 per edge (same parity,
    /// still connected).
    fn walk_multiplicities(&self, walk: &[u32]) -> Vec<u32> {
        let index: std::collections::HashMap<(usize, usize), usize> = self
            .edges
            .iter()
            .enumerate()
            .map(|(k, &e)| (e, k))
            .collect();
        let mut mult = vec![0u32; self.edges.len()];
        let m = walk.len();
        for i in 0..m {
            let (a, b) = (walk[i] as usize, walk[(i + 1) % m] as usize);
            mult[index[&(a.min(b), a.max(b))]] += 1;
        }
        for x in &mut mult {
            while *x > 2 {
                *x -= 2;
            }
        }
        mult
    }

    fn walk(&self, mult: &[u32]) -> VertexWalk {
        let start = (0..self.edges.len())
            .find(|&k| mult[k] > 0)
            .map_or(0, |k| self.edges[k].0);
        euler_walk(self.inst.len(), &self.edges, mult, start)
            .into_iter()
            .map(|v| v as u32)
            .collect()
    }
}

impl CutModel for LengthModel<'_> {
    fn formulation(&self) -> &Formulation {
        &self.formulation
    }

    fn separate(&self, x: &[f64], _integral: bool, deadline: &Deadline) -> Vec<Row> {
        subtour_rows(self.inst.len(), &self.edges, x, deadline)
    }

    fn is_feasible(&self, x: &[f64]) -> bool {
        self.labels(&self.multiplicities(x)).1 == 1
    }

    /// Joins the components by doubling an edge between two of them (the graph is
    /// connected, so one exists) until one is left.
    fn repair(&self, x: &[f64]) -> Option<Vec<f64>> {
        let mut mult = self.multiplicities(x);
        loop {
            let (label, count) = self.labels(&mult);
            if count <= 1 {
                return Some(self.columns(&mult));
            }
            let k = (0..self.edges.len())
                .find(|&k| label[self.edges[k].0] != label[self.edges[k].1])?;
            mult[k] += 2;
        }
    }

    /// Every closed walk in a bipartite graph has even length.
    fn step(&self) -> u64 {
        self.step
    }
}

pub(super) fn solve_length(inst: &Discrete, deadline: &Deadline, settings: &Settings) -> Answer {
    let n = inst.len();
    let lower = LowerBound {
        value: if n >= 2 { n as u64 } else { 0 },
        source: "every vertex visited",
    };
    if !is_connected(inst) {
        return Answer::stopped(Stop::Infeasible, lower);
    }
    if n == 1 {
        let only = LowerBound {
            value: 0,
            source: "the only tour",
        };
        return Answer::trivial(vec![vec![0]], only);
    }
    let model = LengthModel::new(inst);
    let tree = tree_walks(inst);
    let start = model.columns(&model.walk_multiplicities(&tree[0]));
    let s = driver::run(
        &model,
        Some(start),
        (lower.value, lower.source),
        deadline,
        settings,
    );
    let walks = s
        .best
        .as_ref()
        .map(|x| vec![model.walk(&model.multiplicities(x))]);
    Answer::from_solved(s, walks, lower)
}
