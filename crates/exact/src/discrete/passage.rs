//! The passage model of `cc-turns`, `turns`, `weighted` and `weighted-cc`: passage counts
//! per vertex and port pair, the port connectivity cuts of the tour objectives, the U-turn
//! reduction and the repair of integer solutions into walks (see the parent module for the
//! formulation and why it is exact).

use super::rooks::{channels, rook_placement};
use super::{Answer, LowerBound, NONE, is_connected, tree_walks};
use crate::Objective;
use crate::cuts::{used_components, violated_cuts};
use crate::driver::{self, CutModel, Stop};
use crate::goal::{TurnGoal, tighten_columns};
use crate::lp::{Deadline, Formulation, Row, Settings, as_columns};
use crate::walks::splice_walks;
use mowmill_core::discrete::{Discrete, VertexWalk};
use std::cell::Cell;

/// A merging move of [`PassageModel::connect`]: its cost change, the columns losing one
/// passage and the passages gained as (vertex, port, port).
pub(super) type Move = (i64, Vec<usize>, Vec<(u32, u32, u32)>);

/// A side term of a generalized subtour cut ([`PassageModel::side_term`]): a constant and
/// (column, coefficient) terms.
pub(super) type SideTerm = (f64, Vec<(usize, f64)>);

/// One passage column: at vertex `v` between its local ports `a <= b`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Pass {
    v: u32,
    a: u32,
    b: u32,
}

/// The passage model (see the module documentation).
pub(super) struct PassageModel<'a> {
    inst: &'a Discrete,
    goal: TurnGoal,
    /// Global index of local port 0 of every vertex (cumulative degrees).
    port_start: Vec<usize>,
    /// Whether each global port's edge lies on a cyclic channel.
    cyclic: Vec<bool>,
    vars: Vec<Pass>,
    /// Columns of vertex v: first[v]..first[v + 1].
    first: Vec<usize>,
    /// Edges (v, w) with v < w.
    edges: Vec<(u32, u32)>,
    isolated: usize,
    /// `weighted-cc`: the one-vertex walk column of every vertex with a neighbour (NONE
    /// elsewhere).
    stay: Vec<u32>,
    /// Tours: the column of the port-use indicator `z_g` of global port `g` is `zcol + g`
    /// (None for cycle covers).
    zcol: Option<usize>,
    /// Tours: the rows that link the indicators to the passages (module documentation),
    /// handed to the cut pool by the first separation that needs them.
    links: Vec<Row>,
    /// Whether `links` has been handed out (the cut loop keeps every row it is given).
    linked: Cell<bool>,
    formulation: Formulation,
}

impl<'a> PassageModel<'a> {
    fn new(inst: &'a Discrete, goal: TurnGoal) -> PassageModel<'a> {
        let n = inst.len();
        let mut port_start = Vec::with_capacity(n + 1);
        let mut total = 0;
        for v in 0..n as u32 {
            port_start.push(total);
            total += inst.degree(v);
        }
        port_start.push(total);
        let (chans, _) = channels(inst);
        let mut cyclic = vec![false; total];
        for c in chans.iter().filter(|c| c.closed) {
            let m = c.verts.len();
            for i in 0..m {
                let (x, y) = (c.verts[i], c.verts[(i + 1) % m]);
                let px = port_start[x as usize] + local_port(inst, x, y);
                let py = port_start[y as usize] + local_port(inst, y, x);
                cyclic[px] = true;
                cyclic[py] = true;
            }
        }
        let mut m = PassageModel {
            inst,
            goal,
            port_start,
            cyclic,
            vars: Vec::new(),
            first: Vec::with_capacity(n + 1),
            edges: inst.edges().collect(),
            isolated: 0,
            stay: vec![NONE; n],
            zcol: None,
            links: Vec::new(),
            linked: Cell::new(false),
            formulation: Formulation::default(),
        };
        let mut f = Formulation::default();
        for v in 0..n as u32 {
            m.first.push(m.vars.len());
            let d = inst.degree(v) as u32;
            for a in 0..d {
                for b in a..d {
                    if a == b && goal.turn_cost().is_none() && !m.has_uturn_column(v, a) {
                        continue;
                    }
                    let t = f64::from(m.turn(v, a, b));
                    let cost = match goal.turn_cost() {
                        Some(c) => 1.0 + f64::from(c) * t,
                        None => t,
                    };
                    f.add_col(cost, 0.0, f64::INFINITY, true);
                    m.vars.push(Pass { v, a, b });
                }
            }
        }
        m.first.push(m.vars.len());
        if let TurnGoal::WeightedCycleCover(c) = goal {
            for v in 0..n {
                if inst.degree(v as u32) > 0 {
                    m.stay[v] = f.num_cols() as u32;
                    f.add_col(4.0 * f64::from(c), 0.0, 1.0, true);
                }
            }
        }
        for &(v, w) in &m.edges {
            let pv = local_port(inst, v, w) as u32;
            let pw = local_port(inst, w, v) as u32;
            let terms = m
                .port_terms(v, pv)
                .chain(m.port_terms(w, pw).map(|(k, c)| (k, -c)));
            f.rows.push(Row::range(terms, 0.0, 0.0));
        }
        for v in 0..n {
            if inst.degree(v as u32) == 0 {
                m.isolated += 1;
            } else {
                let stay = (m.stay[v] != NONE).then_some((m.stay[v] as usize, 1.0));
                f.rows.push(Row::at_least(
                    (m.first[v]..m.first[v + 1]).map(|k| (k, 1.0)).chain(stay),
                    1.0,
                ));
            }
        }
        if goal.is_tour() {
            // Port-use indicators and their linking rows `z_g <= usage(g)` and
            // `Σ_{g ∈ P(v)} z_g >= 1`, kept out of the model until the first cut needs them.
            let zcol = f.num_cols();
            m.zcol = Some(zcol);
            for _ in 0..total {
                f.add_col(0.0, 0.0, 1.0, true);
            }
            for v in 0..n as u32 {
                for p in 0..inst.degree(v) as u32 {
                    let z = (zcol + m.global(v, p), 1.0);
                    let usage = m.port_terms(v, p).map(|(k, c)| (k, -c));
                    m.links
                        .push(Row::range(usage.chain([z]), f64::NEG_INFINITY, 0.0));
                }
                if inst.degree(v) > 0 {
                    let ports = m.port_start[v as usize]..m.port_start[v as usize + 1];
                    m.links
                        .push(Row::at_least(ports.map(|g| (zcol + g, 1.0)), 1.0));
                }
            }
        }
        m.formulation = f;
        m
    }

    /// Integer counts with the port-use indicators of tours set to "used" (`z_g = 1` exactly
    /// when port `g` carries a passage end): the indicators every tour satisfies every cut
    /// with.
    fn with_ports(&self, mut counts: Vec<u32>) -> Vec<u32> {
        if let Some(zcol) = self.zcol {
            let x = as_columns(&counts);
            for v in 0..self.inst.len() as u32 {
                for p in 0..self.inst.degree(v) as u32 {
                    counts[zcol + self.global(v, p)] = u32::from(self.port_usage(&x, v, p) > 0.5);
                }
            }
        }
        counts
    }

    /// Whether the U-turn at `v` back through local port `a` keeps its column: the channel
    /// does not continue straight beyond `v`, or it is cyclic (module documentation).
    fn has_uturn_column(&self, v: u32, a: u32) -> bool {
        let u = self.inst.neighbors(v)[a as usize];
        self.inst.straight_on(u, v).is_none()
            || self.cyclic[self.port_start[v as usize] + a as usize]
    }

    /// The turns of passing `v` between local ports `a` and `b`.
    fn turn(&self, v: u32, a: u32, b: u32) -> u32 {
        let nb = self.inst.neighbors(v);
        self.inst.turn(nb[a as usize], v, nb[b as usize])
    }

    /// The usage of local port `p` of `v` as (column, coefficient) terms.
    fn port_terms(&self, v: u32, p: u32) -> impl Iterator<Item = (usize, f64)> + '_ {
        (self.first[v as usize]..self.first[v as usize + 1]).filter_map(move |k| {
            let q = self.vars[k];
            let c = u8::from(q.a == p) + u8::from(q.b == p);
            (c > 0).then_some((k, f64::from(c)))
        })
    }

    fn port_usage(&self, x: &[f64], v: u32, p: u32) -> f64 {
        self.port_terms(v, p).map(|(k, c)| c * x[k]).sum()
    }

    /// The cost of the isolated vertices' one-vertex walks, outside the model.
    fn isolated_cost(&self) -> u64 {
        4 * self.goal.turn_cost().map_or(1, u64::from) * self.isolated as u64
    }

    fn global(&self, v: u32, p: u32) -> usize {
        self.port_start[v as usize] + p as usize
    }

    /// Labels of the used ports' components (u32::MAX for unused ports) and their number.
    fn port_components(&self, x: &[f64], eps: f64) -> (Vec<u32>, usize) {
        let total = *self.port_start.last().unwrap_or(&0);
        let mut used = vec![false; total];
        let mut joined = Vec::new();
        for (k, p) in self.vars.iter().enumerate() {
            if x[k] > eps {
                let (ga, gb) = (self.global(p.v, p.a), self.global(p.v, p.b));
                used[ga] = true;
                used[gb] = true;
                joined.push((ga, gb));
            }
        }
        for &(v, w) in &self.edges {
            let pv = local_port(self.inst, v, w) as u32;
            if self.port_usage(x, v, pv) > eps {
                let pw = local_port(self.inst, w, v) as u32;
                joined.push((self.global(v, pv), self.global(w, pw)));
            }
        }
        used_components(total, joined, &used)
    }

    /// The crossing of a port set `S` as terms: `Σ_{edges across S} x_e + Σ_{passages
    /// across S} p` (an edge's multiplicity is its passage ends at one of its ports).
    fn crossing_terms(&self, s: &[bool]) -> Vec<(usize, f64)> {
        let mut terms: Vec<(usize, f64)> = Vec::new();
        for &(v, w) in &self.edges {
            let pv = local_port(self.inst, v, w) as u32;
            let pw = local_port(self.inst, w, v) as u32;
            if s[self.global(v, pv)] != s[self.global(w, pw)] {
                terms.extend(self.port_terms(v, pv));
            }
        }
        for (k, p) in self.vars.iter().enumerate() {
            if s[self.global(p.v, p.a)] != s[self.global(p.v, p.b)] {
                terms.push((k, 1.0));
            }
        }
        terms
    }

    /// The strongest "the tour uses a port on this side" term for one side of a port set
    /// (the ports `g` with `s[g] == side`) at `x`, as (constant, terms): `z_p` for a port `p`
    /// on the side, or `1 − z(P(u) ∖ side)` for a vertex `u` (the tour uses a port of `u`, so
    /// if none off the side, one on it). Before the indicators are linked only the constant
    /// 1 of a vertex with every port on the side; None if there is none.
    fn side_term(&self, s: &[bool], side: bool, x: &[f64]) -> Option<SideTerm> {
        let zcol = self.zcol.expect("tours have port indicators");
        let linked = self.linked.get();
        // (value at x, the term)
        let mut best: Option<(f64, SideTerm)> = None;
        for v in 0..self.inst.len() {
            let ports = self.port_start[v]..self.port_start[v + 1];
            if ports.is_empty() {
                continue;
            }
            let off: Vec<(usize, f64)> = ports
                .clone()
                .filter(|&g| s[g] != side)
                .map(|g| (zcol + g, -1.0))
                .collect();
            if !linked {
                if off.is_empty() {
                    return Some((1.0, off));
                }
                continue;
            }
            let value = 1.0 - off.iter().map(|&(j, _)| x[j]).sum::<f64>();
            let better = |b: &(f64, SideTerm)| {
                value > b.0 + 1e-9 || (value > b.0 - 1e-9 && off.len() < b.1.1.len())
            };
            if best.as_ref().is_none_or(better) {
                best = Some((value, (1.0, off)));
            }
            for g in ports.filter(|&g| s[g] == side) {
                let value = x[zcol + g];
                if best.as_ref().is_none_or(|b| value > b.0 + 1e-9) {
                    best = Some((value, (0.0, vec![(zcol + g, 1.0)])));
                }
            }
        }
        best.map(|(_, term)| term)
    }

    /// The generalized subtour cut of a port set `S`, if `x` violates it:
    /// `crossing(S) >= 2 (A + B − 1)`, with `A` ([`Self::side_term`]) at most 1, and 1 only
    /// if the tour (with its indicators `z_g` = port `g` used) uses a port in `S`, and `B` the
    /// same outside `S`. A closed walk that uses ports on both sides crosses `S` at least
    /// twice.
    fn gsec(&self, s: &[bool], x: &[f64]) -> Option<Row> {
        let (ca, ta) = self.side_term(s, true, x)?;
        let (cb, tb) = self.side_term(s, false, x)?;
        let rhs = 2.0 * (ca + cb - 1.0);
        let terms = self
            .crossing_terms(s)
            .into_iter()
            .chain(ta.into_iter().chain(tb).map(|(j, c)| (j, -2.0 * c)));
        let row = Row::at_least(terms, rhs);
        (row.activity(x) < rhs - 1e-6).then_some(row)
    }

    /// Generalized subtour cuts between the port components of the support (and of its
    /// heavier parts): `S` = the ports of one component, with or without the other ports of
    /// the vertices only it touches, and, when these give nothing, unions of components.
    /// On an integer solution whose indicators mark used ports in two components, the
    /// component of either gives a violated cut (crossing 0 < 2).
    fn crossing_cuts(&self, x: &[f64]) -> Vec<Row> {
        const MAX_COMPONENTS: usize = 256;
        let zcol = self.zcol.expect("tours have port indicators");
        let n = self.inst.len();
        let total = *self.port_start.last().unwrap_or(&0);
        let mut out = Vec::new();
        let mut seen = std::collections::HashSet::new();
        let mut try_set = |s: Vec<bool>, out: &mut Vec<Row>| {
            if seen.insert(s.clone())
                && let Some(row) = self.gsec(&s, x)
            {
                out.push(row);
            }
        };
        for threshold in [1e-6, 0.3, 0.6, 0.9] {
            let (label, count) = self.port_components(x, threshold);
            if count <= 1 {
                continue;
            }
            let before = out.len();
            // Components with the most used indicators first.
            let mut zmax = vec![0.0f64; count];
            for g in 0..total {
                if label[g] != u32::MAX {
                    let z = &mut zmax[label[g] as usize];
                    *z = z.max(x[zcol + g]);
                }
            }
            let mut order: Vec<usize> = (0..count).collect();
            order.sort_by(|&a, &b| zmax[b].total_cmp(&zmax[a]));
            for &c in order.iter().take(MAX_COMPONENTS) {
                let own: Vec<bool> = label.iter().map(|&l| l as usize == c).collect();
                let mut widened = own.clone();
                for v in 0..n {
                    let ports = self.port_start[v]..self.port_start[v + 1];
                    let only = ports.clone().any(|g| own[g])
                        && ports.clone().all(|g| label[g] == u32::MAX || own[g]);
                    if only {
                        ports.for_each(|g| widened[g] = true);
                    }
                }
                try_set(own, &mut out);
                try_set(widened, &mut out);
            }
            if out.len() > before {
                continue;
            }
            // Unions: the components touching each vertex (of the first 64 components).
            let count = count.min(64);
            let comp = |g: usize| -> Option<u32> {
                (label[g] != u32::MAX && (label[g] as usize) < count).then_some(label[g])
            };
            let touch: Vec<u64> = (0..n)
                .map(|v| {
                    (self.port_start[v]..self.port_start[v + 1])
                        .filter_map(comp)
                        .fold(0u64, |m, l| m | 1u64 << l)
                })
                .collect();
            let mut qs = touch.clone();
            qs.sort_unstable();
            qs.dedup();
            for q in qs.into_iter().filter(|&q| q != 0).take(8) {
                let s: Vec<bool> = (0..n)
                    .flat_map(|v| {
                        let private = touch[v] != 0 && touch[v] & !q == 0;
                        (self.port_start[v]..self.port_start[v + 1])
                            .map(move |g| private || comp(g).is_some_and(|l| q >> l & 1 == 1))
                    })
                    .collect();
                try_set(s, &mut out);
            }
        }
        out
    }

    fn counts(&self, x: &[f64]) -> Vec<u32> {
        x.iter().map(|&v| v.round().max(0.0) as u32).collect()
    }

    fn column(&self, v: u32, a: u32, b: u32) -> Option<usize> {
        let (a, b) = (a.min(b), a.max(b));
        (self.first[v as usize]..self.first[v as usize + 1])
            .find(|&k| self.vars[k].a == a && self.vars[k].b == b)
    }

    /// Adds one passage at `v` between local ports `a` and `b`; a U-turn without a column
    /// becomes two straight passes and the U-turn one vertex further along the channel (same
    /// turns). False if impossible.
    fn add_passage(&self, counts: &mut [u32], v: u32, a: u32, b: u32) -> bool {
        let mut v = v;
        let mut a = a;
        let mut b = b;
        // A path channel has at most V vertices: the pushes end.
        for _ in 0..=self.inst.len() {
            if let Some(k) = self.column(v, a, b) {
                counts[k] += 1;
                return true;
            }
            if a != b {
                return false;
            }
            let u = self.inst.neighbors(v)[a as usize];
            let Some(w) = self.inst.straight_on(u, v) else {
                return false;
            };
            let s = local_port(self.inst, v, w) as u32;
            let Some(k) = self.column(v, a, s) else {
                return false;
            };
            counts[k] += 2;
            let back = local_port(self.inst, w, v) as u32;
            (v, a, b) = (w, back, back);
        }
        false
    }

    /// The cost of a passage as `add_passage` realises it (i64::MAX / 4 if impossible).
    fn passage_cost(&self, v: u32, a: u32, b: u32) -> i64 {
        let (mut v, mut a, mut b) = (v, a, b);
        let mut total = 0i64;
        for _ in 0..=self.inst.len() {
            if let Some(k) = self.column(v, a, b) {
                return total + self.formulation.cost[k] as i64;
            }
            if a != b {
                break;
            }
            let u = self.inst.neighbors(v)[a as usize];
            let Some(w) = self.inst.straight_on(u, v) else {
                break;
            };
            let s = local_port(self.inst, v, w) as u32;
            let Some(k) = self.column(v, a, s) else {
                break;
            };
            total += 2 * self.formulation.cost[k] as i64;
            let back = local_port(self.inst, w, v) as u32;
            (v, a, b) = (w, back, back);
        }
        i64::MAX / 4
    }

    /// Passage counts of closed walks (a one-vertex walk at a vertex with a neighbour is the
    /// stay column of `weighted-cc`, or else a step to a neighbour and back: same turns).
    fn walk_counts(&self, walks: &[VertexWalk]) -> Option<Vec<u32>> {
        let mut counts = vec![0u32; self.formulation.num_cols()];
        for walk in walks {
            if walk.len() == 1 {
                let v = walk[0];
                if self.inst.degree(v) == 0 {
                    continue;
                }
                let s = self.stay[v as usize];
                if s != NONE && counts[s as usize] == 0 {
                    counts[s as usize] = 1;
                    continue;
                }
                let w = self.inst.neighbors(v)[0];
                let (pv, pw) = (
                    local_port(self.inst, v, w) as u32,
                    local_port(self.inst, w, v) as u32,
                );
                if !self.add_passage(&mut counts, v, pv, pv)
                    || !self.add_passage(&mut counts, w, pw, pw)
                {
                    return None;
                }
                continue;
            }
            let m = walk.len();
            for i in 0..m {
                let (prev, cur, next) = (walk[(i + m - 1) % m], walk[i], walk[(i + 1) % m]);
                let nb = self.inst.neighbors(cur);
                let a = nb.binary_search(&prev).ok()? as u32;
                let b = nb.binary_search(&next).ok()? as u32;
                if !self.add_passage(&mut counts, cur, a, b) {
                    return None;
                }
            }
        }
        Some(counts)
    }

    /// Whether integer counts are feasible: the formulation's rows, and for tours one port
    /// component.
    fn is_feasible_counts(&self, counts: &[u32]) -> bool {
        let x = as_columns(counts);
        self.formulation.is_feasible(&x, &[])
            && (!self.goal.is_tour() || self.port_components(&x, 0.5).1 == 1)
    }

    /// Drops port components whose every vertex another kept component also visits (most
    /// expensive first), or, when some component visits every vertex, all but the cheapest
    /// such; coverage is kept and the cost does not grow.
    fn drop_redundant(&self, counts: &mut [u32]) {
        let x = as_columns(counts);
        let (label, count) = self.port_components(&x, 0.5);
        if count <= 1 {
            return;
        }
        let n = self.inst.len();
        let mut cost = vec![0.0; count];
        for (k, p) in self.vars.iter().enumerate() {
            if counts[k] > 0 {
                cost[label[self.global(p.v, p.a)] as usize] += self.formulation.cost[k] * x[k];
            }
        }
        // touching[v] = components visiting v.
        let touching: Vec<Vec<u32>> = (0..n)
            .map(|v| {
                let mut t: Vec<u32> = (self.port_start[v]..self.port_start[v + 1])
                    .map(|g| label[g])
                    .filter(|&l| l != u32::MAX)
                    .collect();
                t.sort_unstable();
                t.dedup();
                t
            })
            .collect();
        let mut dropped = vec![false; count];
        // A component that visits every vertex is a tour by itself: keep the cheapest.
        let covering = (0..count)
            .filter(|&c| {
                (0..n).all(|v| self.inst.degree(v as u32) == 0 || touching[v].contains(&(c as u32)))
            })
            .min_by(|&a, &b| cost[a].total_cmp(&cost[b]));
        let mut order: Vec<usize> = (0..count).collect();
        if let Some(keep) = covering {
            dropped.iter_mut().for_each(|d| *d = true);
            dropped[keep] = false;
            order.clear();
        }
        order.sort_by(|&a, &b| cost[b].total_cmp(&cost[a]));
        for c in order {
            let redundant = (0..n).all(|v| {
                !touching[v].contains(&(c as u32))
                    || touching[v]
                        .iter()
                        .any(|&o| o as usize != c && !dropped[o as usize])
            });
            if redundant {
                dropped[c] = true;
            }
        }
        for (k, p) in self.vars.iter().enumerate() {
            if counts[k] > 0 && dropped[label[self.global(p.v, p.a)] as usize] {
                counts[k] = 0;
            }
        }
    }

    /// Merges the port components of covering integer counts into one, greedily by the
    /// cheapest move: re-pairing two passages of different components at a vertex, or a
    /// doubled edge between passages of different components at its two ends. In a
    /// connected graph with every vertex covered one of them always applies.
    ///
    /// # Complexity
    /// O(components · (Σ_v passages_v² + Σ_vw passages_v · passages_w) · V) time.
    fn connect(&self, mut counts: Vec<u32>) -> Vec<u32> {
        loop {
            let x = as_columns(&counts);
            let (label, count) = self.port_components(&x, 0.5);
            if count <= 1 {
                return counts;
            }
            let comp = |v: u32, p: u32| label[self.global(v, p)];
            let cost = |k: usize| self.formulation.cost[k] as i64;
            // (delta, removed columns, added passages)
            let mut best: Option<Move> = None;
            let mut consider = |delta: i64, rem: Vec<usize>, add: Vec<(u32, u32, u32)>| {
                if best.as_ref().is_none_or(|b| delta < b.0) {
                    best = Some((delta, rem, add));
                }
            };
            for v in 0..self.inst.len() as u32 {
                let here: Vec<usize> = (self.first[v as usize]..self.first[v as usize + 1])
                    .filter(|&k| counts[k] > 0)
                    .collect();
                for &k1 in &here {
                    for &k2 in &here {
                        let (p, q) = (self.vars[k1], self.vars[k2]);
                        if k1 >= k2 || comp(v, p.a) == comp(v, q.a) {
                            continue;
                        }
                        let old = cost(k1) + cost(k2);
                        for (s1, s2) in [((p.a, q.a), (p.b, q.b)), ((p.a, q.b), (p.b, q.a))] {
                            let delta = self.passage_cost(v, s1.0, s1.1)
                                + self.passage_cost(v, s2.0, s2.1)
                                - old;
                            consider(delta, vec![k1, k2], vec![(v, s1.0, s1.1), (v, s2.0, s2.1)]);
                        }
                    }
                }
            }
            for &(v, w) in &self.edges {
                let s = local_port(self.inst, v, w) as u32;
                let t = local_port(self.inst, w, v) as u32;
                for k in
                    (self.first[v as usize]..self.first[v as usize + 1]).filter(|&k| counts[k] > 0)
                {
                    for j in (self.first[w as usize]..self.first[w as usize + 1])
                        .filter(|&j| counts[j] > 0)
                    {
                        let (p, q) = (self.vars[k], self.vars[j]);
                        if comp(v, p.a) == comp(w, q.a) {
                            continue;
                        }
                        let add = vec![(v, p.a, s), (v, s, p.b), (w, q.a, t), (w, t, q.b)];
                        let delta = add
                            .iter()
                            .map(|&(y, a, b)| self.passage_cost(y, a, b))
                            .sum::<i64>()
                            - cost(k)
                            - cost(j);
                        consider(delta, vec![k, j], add);
                    }
                }
            }
            let Some((_, rem, add)) = best else {
                return counts;
            };
            for k in rem {
                counts[k] -= 1;
            }
            for (v, a, b) in add {
                if !self.add_passage(&mut counts, v, a, b) {
                    return counts;
                }
            }
        }
    }

    /// The closed walks of integer passage counts, spliced into as few walks as possible,
    /// plus the one-vertex walks (isolated vertices and stay columns).
    fn walks(&self, counts: &[u32]) -> Vec<VertexWalk> {
        let mut passages: Vec<Pass> = Vec::new();
        for (k, &c) in counts.iter().enumerate().take(self.vars.len()) {
            for _ in 0..c {
                passages.push(self.vars[k]);
            }
        }
        let end_port = |k: usize, end: usize| {
            if end == 0 {
                passages[k].a
            } else {
                passages[k].b
            }
        };
        // slots[global port] = the passage ends at that port, in order.
        let total = *self.port_start.last().unwrap_or(&0);
        let mut slots: Vec<Vec<(u32, u8)>> = vec![Vec::new(); total];
        let mut pos = vec![[0u32; 2]; passages.len()];
        for (k, at) in pos.iter_mut().enumerate() {
            for (end, slot) in at.iter_mut().enumerate() {
                let g = self.global(passages[k].v, end_port(k, end));
                *slot = slots[g].len() as u32;
                slots[g].push((k as u32, end as u8));
            }
        }
        let mut used = vec![false; passages.len()];
        let mut walks: Vec<Vec<usize>> = Vec::new();
        for first in 0..passages.len() {
            if used[first] {
                continue;
            }
            let mut walk = Vec::new();
            let (mut k, mut enter) = (first, 0usize);
            loop {
                used[k] = true;
                let v = passages[k].v;
                walk.push(v as usize);
                let out = 1 - enter;
                let p = end_port(k, out);
                let w = self.inst.neighbors(v)[p as usize];
                let back = local_port(self.inst, w, v) as u32;
                let (j, e) = slots[self.global(w, back)][pos[k][out] as usize];
                k = j as usize;
                enter = e as usize;
                if k == first && enter == 0 {
                    break;
                }
            }
            walks.push(walk);
        }
        let mut out: Vec<VertexWalk> = splice_walks(walks)
            .into_iter()
            .map(|w| w.into_iter().map(|v| v as u32).collect())
            .collect();
        for v in 0..self.inst.len() {
            let stays = self.stay[v] != NONE && counts[self.stay[v] as usize] > 0;
            if self.inst.degree(v as u32) == 0 || stays {
                out.push(vec![v as u32]);
            }
        }
        out
    }

    /// The number of vertices with a neighbour.
    fn covered(&self) -> usize {
        self.inst.len() - self.isolated
    }
}

/// The local port of neighbour `w` at `v`.
pub(super) fn local_port(inst: &Discrete, v: u32, w: u32) -> usize {
    inst.neighbors(v)
        .binary_search(&w)
        .expect("w is a neighbour of v")
}

impl CutModel for PassageModel<'_> {
    fn formulation(&self) -> &Formulation {
        &self.formulation
    }

    fn separate(&self, x: &[f64], integral: bool, deadline: &Deadline) -> Vec<Row> {
        if !self.goal.is_tour() {
            return Vec::new();
        }
        let weighted: Vec<(usize, usize, f64)> = self
            .edges
            .iter()
            .map(|&(v, w)| {
                let pv = local_port(self.inst, v, w) as u32;
                (v as usize, w as usize, self.port_usage(x, v, pv))
            })
            .collect();
        let cuts = violated_cuts(self.inst.len(), &weighted, 2.0 - 1e-6, deadline);
        if !cuts.is_empty() {
            return cuts
                .into_iter()
                .map(|s| {
                    let ports: Vec<bool> = (0..self.inst.len())
                        .flat_map(|v| {
                            std::iter::repeat_n(s[v], self.port_start[v + 1] - self.port_start[v])
                        })
                        .collect();
                    Row::at_least(self.crossing_terms(&ports), 2.0)
                })
                .collect();
        }
        let cuts = self.crossing_cuts(x);
        if cuts.is_empty() && integral && !self.linked.get() {
            // Walks that share vertices but no port: link the indicators (their values in
            // `x` are arbitrary until then).
            self.linked.set(true);
            return self.links.clone();
        }
        cuts
    }

    fn is_feasible(&self, x: &[f64]) -> bool {
        self.is_feasible_counts(&self.counts(x))
    }

    fn repair(&self, x: &[f64]) -> Option<Vec<f64>> {
        let mut counts = self.counts(x);
        if self.goal.is_tour() {
            self.drop_redundant(&mut counts);
            counts = self.with_ports(self.connect(counts));
        }
        self.is_feasible_counts(&counts)
            .then(|| as_columns(&counts))
    }

    /// Bounds valid for every integer solution of model cost at most `target`:
    ///
    /// * a column of cost `c > 0` is used at most `(target − rest) / c` times, where `rest`
    ///   is what the other vertices cost at least: nothing with turn costs only, one passage
    ///   (cost >= 1) each with length counted (`weighted`; `weighted-cc` too when C >= 1,
    ///   where a one-vertex walk costs 4C >= 1);
    /// * a straight passage on a channel that is a path is used at most T times, T the turn
    ///   budget (`target`, or `(target − V') / C` for `weighted` whose tour has length at least
    ///   the V' vertices with a neighbour, or `target / C` for `weighted-cc`): each such pass
    ///   lies on a different link of the walks (a link passes a pair of a path channel at
    ///   most once), every link ends at both ends in a visit that is not straight (the
    ///   channel ends or is left), and such a visit of turn cost t ∈ {1, 2} ends at most 2 links,
    ///   so there are at most 2T link ends and T links. On a cyclic channel a closed walk may
    ///   go around without turning, so nothing is assumed there.
    fn tighten(&self, f: &mut Formulation, target: u64) {
        let n = self.covered() as f64;
        let target = target as f64;
        let (budget, rest) = self.goal.turn_budget(n, target);
        tighten_columns(f, self.vars.len(), (target, rest), |k| {
            let p = self.vars[k];
            (self.turn(p.v, p.a, p.b) == 0 && !self.cyclic[self.global(p.v, p.a)]).then_some(budget)
        });
    }

    fn heuristic_caps(&self) -> Option<Vec<f64>> {
        Some(vec![2.0; self.formulation.num_cols()])
    }

    /// Nothing is known about parity on a general graph.
    fn step(&self) -> u64 {
        1
    }
}

/// The cheap bound of a turn objective: a greedy rook placement (turns of any cycle cover,
/// [`rook_placement`]), plus the length bound `V` for `weighted` tours (every vertex visited;
/// both hold for the same tour).
pub(super) fn cheap_turn_bound(inst: &Discrete, goal: TurnGoal) -> LowerBound {
    let rooks = rook_placement(inst, Some(0.0)).size;
    match goal {
        TurnGoal::CycleCover | TurnGoal::Tour => LowerBound {
            value: rooks,
            source: "greedy rook placement",
        },
        TurnGoal::Weighted(c) => LowerBound {
            value: if inst.len() >= 2 {
                inst.len() as u64
            } else {
                0
            } + u64::from(c) * rooks,
            source: "V + C * greedy rook placement",
        },
        TurnGoal::WeightedCycleCover(c) => LowerBound {
            value: u64::from(c) * rooks,
            source: "C * greedy rook placement",
        },
    }
}

pub(super) fn solve_passages(
    inst: &Discrete,
    objective: Objective,
    deadline: &Deadline,
    settings: &Settings,
) -> Answer {
    let goal = TurnGoal::of(objective).expect("solve_passages is called for turn objectives");
    let lower = cheap_turn_bound(inst, goal);
    if goal.is_tour() {
        if !is_connected(inst) {
            return Answer::stopped(Stop::Infeasible, lower);
        }
        if inst.len() == 1 {
            // The one-vertex walk: length 0, 4 turns; the only tour.
            let only = LowerBound {
                value: 4 * goal.turn_cost().map_or(1, u64::from),
                source: "the only tour",
            };
            return Answer::trivial(vec![vec![0]], only);
        }
    }
    let model = PassageModel::new(inst, goal);
    let constant = model.isolated_cost();
    // The start: spanning-tree walks of the components, joined for tours.
    let tree: Vec<VertexWalk> = tree_walks(inst)
        .into_iter()
        .filter(|w| w.len() > 1 || inst.degree(w[0]) > 0)
        .collect();
    let start = model
        .walk_counts(&tree)
        .map(|c| {
            if goal.is_tour() {
                model.with_ports(model.connect(c))
            } else {
                c
            }
        })
        .filter(|c| model.is_feasible_counts(c))
        .map(|c| as_columns(&c));
    let s = driver::run_with_constant(
        &model,
        start,
        (lower.value, lower.source),
        constant,
        deadline,
        settings,
        false,
    );
    let walks = s.best.as_ref().map(|x| {
        let mut counts = model.counts(x);
        if goal.is_tour() {
            // A feasible tour solution may carry redundant components only if the driver
            // accepted it; dropping them keeps the cost or lowers it.
            model.drop_redundant(&mut counts);
        }
        model.walks(&counts)
    });
    Answer::from_solved(s, walks, lower)
}
