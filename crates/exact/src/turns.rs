//! `cc-turns`, `tour-turns` and `weighted`: the passage formulation (after Fekete and Krupke's
//! integer programs for cycle covers and tours with turn costs).
//!
//! **Variables.** For every pixel `v` and every unordered pair `{a, b}` of its sides that have a
//! neighbour (including `a = b`), an integer `p_{v,ab} >= 0`: how many times a walk passes
//! through `v` entering from side `a` and leaving through side `b`. Its turn cost is 0 when `a`
//! and `b` are opposite (straight), 1 when they are perpendicular, 2 when `a = b` (U-turn).
//!
//! With turn costs only (`cc-turns`, `tour-turns`), U-turn variables exist only where the
//! strip ends (no neighbour beyond): a U-turn at `v` with a neighbour `w` beyond it can be
//! replaced by two straight passes through `v` and the U-turn at `w`, same turns and the same
//! walks (only longer), and repeating this reaches the strip's end. This removes equivalent
//! optima; `weighted` counts length and keeps every U-turn.
//!
//! **Constraints.** Coverage: `Σ_{ab} p_{v,ab} >= 1` for every pixel. Consistency: for every
//! grid edge `{v, w}` (w on side `d` of v), the passage ends using side `d` of `v` equal those
//! using the facing side of `w` (a U-turn counts twice): this is the edge's multiplicity
//! `x_vw`. Any integer solution decomposes into closed walks whose turn count is the
//! passages' total and whose length is the number of passages.
//!
//! **Objectives.** `cc-turns` minimizes `Σ turn(ab) · p` (turn-cost paper, Sections 2 and 4);
//! an isolated pixel is a one-pixel walk of cost 4 (the checker's convention) and has no
//! variables. `tour-turns` adds connectivity; `weighted` minimizes `Σ (1 + C · turn(ab)) · p`
//! (length + C · turns, Section 5.6) with connectivity.
//!
//! **Connectivity.** Two closed walks may cross at a pixel without sharing an edge, so edge
//! connectivity alone is not enough. Split every pixel into its four sides: passages join
//! sides of one pixel, grid edges join facing sides of neighbours. The walks can be spliced
//! into one at no cost exactly when the used part of this side graph is connected (two walks
//! through the same side traverse the same grid edge). Valid cuts: for a set `S` of sides
//! containing all sides of some pixel and none of another, every tour crosses `S` at least
//! twice: `Σ_{grid edges across S} x_e + Σ_{passages across S} p >= 2`. Cuts with `S` a union
//! of whole pixels (plain `x(δ(S)) >= 2`) are separated exactly by minimum cuts; cuts between
//! side components (crossing walks) from the components of the support.

use super::cuts::{used_components, violated_cuts};
use super::driver::CutModel;
use super::goal::{TurnGoal, tighten_columns};
use super::lp::{Deadline, Formulation, Row};
use super::walks::{Passage, passage_walks, splice_walks};
use crate::region::{Dir, Pixel, Region};
use petgraph::unionfind::UnionFind;

const NONE: u32 = u32::MAX;

/// Turn cost of a passage between sides `a` and `b` (Dir indices).
pub(crate) fn passage_turns(a: u8, b: u8) -> u32 {
    if a == b {
        2
    } else if (a + 2) % 4 == b {
        0
    } else {
        1
    }
}

/// A merging move of [`PassageModel::connect`]: passages removed and added, and the cost
/// change.
struct Move {
    delta: i64,
    /// Columns losing one passage.
    rem: Vec<usize>,
    /// Passages gained, as (pixel, side, side).
    add: Vec<(usize, u8, u8)>,
    /// The two side components it joins.
    joins: (u32, u32),
}

pub(crate) struct PassageModel<'a> {
    region: &'a Region,
    goal: TurnGoal,
    /// Neighbour on each side (or NONE).
    nb: Vec<[u32; 4]>,
    /// Column k is a passage at `vars[k].pixel` between sides a <= b.
    vars: Vec<Passage>,
    /// Columns of pixel v: first[v]..first[v + 1].
    first: Vec<usize>,
    /// Grid edges (v, side d in {E, N}, w).
    edges: Vec<(usize, u8, usize)>,
    /// Pixels without neighbours (one-pixel walks, cost 4 each in cycle covers).
    pub isolated: usize,
    /// `weighted-cc`: the column of the one-pixel walk at each pixel with a neighbour (NONE
    /// elsewhere and for other goals).
    stay: Vec<u32>,
    formulation: Formulation,
}

impl<'a> PassageModel<'a> {
    /// The model for `goal`; with `cap`, every pixel is visited at most `cap` times.
    pub(crate) fn new(region: &'a Region, goal: TurnGoal, cap: Option<u32>) -> PassageModel<'a> {
        let n = region.len();
        let nb: Vec<[u32; 4]> = (0..n)
            .map(|v| Dir::ALL.map(|d| region.neighbor(v, d).map_or(NONE, |w| w as u32)))
            .collect();
        let mut f = Formulation::default();
        let mut vars = Vec::new();
        let mut first = Vec::with_capacity(n + 1);
        for (v, around) in nb.iter().enumerate() {
            first.push(vars.len());
            for a in 0..4u8 {
                for b in a..4u8 {
                    // With turn costs only, a U-turn can move on to the end of its strip
                    // (see `add_passage`): no U-turn columns where the strip goes on.
                    let inner_uturn = a == b && around[(a as usize + 2) % 4] != NONE;
                    // Under a coverage cap that move adds visits, so every U-turn stays.
                    if inner_uturn && goal.turn_cost().is_none() && cap.is_none() {
                        continue;
                    }
                    if around[a as usize] != NONE && around[b as usize] != NONE {
                        let t = f64::from(passage_turns(a, b));
                        let cost = match goal.turn_cost() {
                            Some(c) => 1.0 + f64::from(c) * t,
                            None => t,
                        };
                        f.add_col(cost, 0.0, f64::INFINITY, true);
                        vars.push(Passage { pixel: v, a, b });
                    }
                }
            }
        }
        first.push(vars.len());
        let mut edges = Vec::new();
        for (v, around) in nb.iter().enumerate() {
            for d in [Dir::E, Dir::N] {
                let w = around[d.index()];
                if w != NONE {
                    edges.push((v, d.index() as u8, w as usize));
                }
            }
        }
        let mut m = PassageModel {
            region,
            goal,
            nb,
            vars,
            first,
            edges,
            isolated: 0,
            stay: vec![NONE; n],
            formulation: Formulation::default(),
        };
        if let TurnGoal::WeightedCycleCover(c) = goal {
            // The checker's one-pixel walk: length 0, 4 turns; it covers its pixel alone.
            for v in 0..n {
                if m.first[v] < m.first[v + 1] {
                    m.stay[v] = f.num_cols() as u32;
                    f.add_col(4.0 * f64::from(c), 0.0, 1.0, true);
                }
            }
        }
        for &(v, d, w) in &m.edges {
            let terms = m
                .side_terms(v, d)
                .chain(m.side_terms(w, (d + 2) % 4).map(|(k, c)| (k, -c)));
            f.rows.push(Row::range(terms, 0.0, 0.0));
        }
        for v in 0..n {
            if m.first[v] == m.first[v + 1] {
                m.isolated += 1;
            } else {
                let hi = cap.map_or(f64::INFINITY, f64::from);
                let stay = (m.stay[v] != NONE).then_some((m.stay[v] as usize, 1.0));
                f.rows.push(Row::range(
                    (m.first[v]..m.first[v + 1]).map(|k| (k, 1.0)).chain(stay),
                    1.0,
                    hi,
                ));
            }
        }
        m.formulation = f;
        m
    }

    /// The edge usage at side `d` of `v` as (column, coefficient) terms.
    fn side_terms(&self, v: usize, d: u8) -> impl Iterator<Item = (usize, f64)> + '_ {
        (self.first[v]..self.first[v + 1]).filter_map(move |k| {
            let p = self.vars[k];
            let c = u8::from(p.a == d) + u8::from(p.b == d);
            (c > 0).then_some((k, f64::from(c)))
        })
    }

    fn side_usage(&self, x: &[f64], v: usize, d: u8) -> f64 {
        self.side_terms(v, d).map(|(k, c)| c * x[k]).sum()
    }

    fn needs_connectivity(&self) -> bool {
        self.goal.is_tour()
    }

    /// The cost of the isolated pixels' one-pixel walks (4 turns, length 0 each), which are
    /// outside the model.
    pub(crate) fn isolated_cost(&self) -> u64 {
        let per_turn = self.goal.turn_cost().map_or(1, u64::from);
        4 * per_turn * self.isolated as u64
    }

    fn cost(&self, k: usize) -> u64 {
        self.formulation.cost[k] as u64
    }

    /// Extended nodes (pixel sides) in use and their components: label per node v*4+d
    /// (u32::MAX when unused) and the number of components.
    fn side_components(&self, x: &[f64], eps: f64) -> (Vec<u32>, usize) {
        let n = self.region.len();
        let mut joined = Vec::new();
        let mut used = vec![false; 4 * n];
        for (k, p) in self.vars.iter().enumerate() {
            if x[k] > eps {
                used[p.pixel * 4 + p.a as usize] = true;
                used[p.pixel * 4 + p.b as usize] = true;
                joined.push((p.pixel * 4 + p.a as usize, p.pixel * 4 + p.b as usize));
            }
        }
        for &(v, d, w) in &self.edges {
            if self.side_usage(x, v, d) > eps {
                joined.push((v * 4 + d as usize, w * 4 + ((d + 2) % 4) as usize));
            }
        }
        used_components(4 * n, joined, &used)
    }

    /// A cut row `Σ_{edges across S} x_e + Σ_{passages across S} p >= 2` for a side set `S`.
    fn side_cut(&self, s: &[bool]) -> Row {
        let mut terms: Vec<(usize, f64)> = Vec::new();
        for &(v, d, w) in &self.edges {
            if s[v * 4 + d as usize] != s[w * 4 + ((d + 2) % 4) as usize] {
                terms.extend(self.side_terms(v, d));
            }
        }
        for (k, p) in self.vars.iter().enumerate() {
            if s[p.pixel * 4 + p.a as usize] != s[p.pixel * 4 + p.b as usize] {
                terms.push((k, 1.0));
            }
        }
        Row::at_least(terms, 2.0)
    }

    /// Cuts between side components: S = the sides of a set Q of components plus every side of
    /// the pixels only Q touches; valid when some pixel is touched only by Q and some not at
    /// all. Components are taken of the support and, for fractional solutions, of the parts
    /// heavier than a few thresholds; a candidate is kept when `x` violates it.
    fn crossing_cuts(&self, x: &[f64]) -> Vec<Row> {
        let mut out = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for threshold in [1e-6, 0.3, 0.6, 0.9] {
            for s in self.component_side_sets(x, threshold) {
                if seen.insert(s.clone()) {
                    let row = self.side_cut(&s);
                    if row.activity(x) < 2.0 - 1e-6 {
                        out.push(row);
                    }
                }
            }
        }
        out
    }

    /// Candidate side sets from the components of the side graph restricted to weights above
    /// `threshold` (see [`Self::crossing_cuts`]).
    fn component_side_sets(&self, x: &[f64], threshold: f64) -> Vec<Vec<bool>> {
        let n = self.region.len();
        let (label, count) = self.side_components(x, threshold);
        if count <= 1 {
            return Vec::new();
        }
        // Components touching each pixel, as bit sets over the first 64 components (pixels
        // touched only by later ones count as untouched, which keeps every set valid).
        let count = count.min(64);
        let touch: Vec<u64> = (0..n)
            .map(|v| {
                (0..4)
                    .filter(|&d| {
                        label[v * 4 + d] != u32::MAX && (label[v * 4 + d] as usize) < count
                    })
                    .fold(0u64, |m, d| m | 1u64 << label[v * 4 + d])
            })
            .collect();
        let try_q = |q: u64| -> Option<Vec<bool>> {
            let private = (0..n).any(|v| touch[v] != 0 && touch[v] & !q == 0);
            let untouched = (0..n).any(|v| touch[v] & q == 0);
            (private && untouched).then(|| {
                (0..4 * n)
                    .map(|i| {
                        let v = i / 4;
                        let l = label[i];
                        (l != u32::MAX && (l as usize) < 64 && q >> l & 1 == 1)
                            || (touch[v] != 0 && touch[v] & !q == 0)
                    })
                    .collect()
            })
        };
        let mut out: Vec<Vec<bool>> = (0..count).filter_map(|c| try_q(1u64 << c)).collect();
        if out.is_empty() {
            // Unions: the components touching one pixel (valid whenever two pixels are
            // touched by disjoint sets of components).
            let mut qs: Vec<u64> = touch.clone();
            qs.sort_unstable();
            qs.dedup();
            out.extend(qs.into_iter().filter_map(try_q).take(8));
        }
        out
    }

    /// Passage counts of a solution vector.
    pub(crate) fn counts(&self, x: &[f64]) -> Vec<u32> {
        x.iter().map(|&v| v.round().max(0.0) as u32).collect()
    }

    /// The closed walks of integer passage counts (spliced into as few walks as possible),
    /// plus the one-pixel walks of isolated pixels.
    pub(crate) fn walks(&self, counts: &[u32]) -> Vec<Vec<Pixel>> {
        let mut passages = Vec::new();
        for (k, &c) in counts.iter().enumerate().take(self.vars.len()) {
            for _ in 0..c {
                passages.push(self.vars[k]);
            }
        }
        let walks = passage_walks(self.region.len(), &passages, |v, d| {
            self.nb[v][d as usize] as usize
        });
        let mut out: Vec<Vec<Pixel>> = splice_walks(walks)
            .into_iter()
            .map(|w| w.into_iter().map(|v| self.region.pixel(v)).collect())
            .collect();
        for v in 0..self.region.len() {
            let stays = self.stay[v] != NONE && counts[self.stay[v] as usize] > 0;
            if self.first[v] == self.first[v + 1] || stays {
                out.push(vec![self.region.pixel(v)]);
            }
        }
        out
    }

    fn column(&self, v: usize, a: u8, b: u8) -> Option<usize> {
        let (a, b) = (a.min(b), a.max(b));
        (self.first[v]..self.first[v + 1]).find(|&k| self.vars[k].a == a && self.vars[k].b == b)
    }

    /// Adds one passage at `v` between sides `a` and `b`. A U-turn without a column (the strip
    /// goes on beyond `v`) becomes two straight passages through `v` and a U-turn one pixel
    /// further: same turns, two more moves. False if the passage is not possible at `v`.
    fn add_passage(&self, counts: &mut [u32], v: usize, a: u8, b: u8) -> bool {
        if let Some(k) = self.column(v, a, b) {
            counts[k] += 1;
            return true;
        }
        let beyond = self.nb[v][((a + 2) % 4) as usize];
        if a != b || beyond == NONE || self.nb[v][a as usize] == NONE {
            return false;
        }
        match self.column(v, a, (a + 2) % 4) {
            Some(k) => counts[k] += 2,
            None => return false,
        }
        self.add_passage(counts, beyond as usize, a, a)
    }

    /// The cost of a passage as `add_passage` realises it (i64::MAX / 4 if impossible).
    fn passage_cost(&self, v: usize, a: u8, b: u8) -> i64 {
        match self.column(v, a, b) {
            Some(k) => self.cost(k) as i64,
            None if a == b && self.nb[v][((a + 2) % 4) as usize] != NONE => {
                self.passage_cost(self.nb[v][((a + 2) % 4) as usize] as usize, a, a)
            }
            None => i64::MAX / 4,
        }
    }

    /// Passage counts of closed walks (a one-pixel walk becomes a step to a neighbour and
    /// back, same turn count); `None` when a walk is not a walk of this region.
    pub(crate) fn walk_counts(&self, walks: &[Vec<Pixel>]) -> Option<Vec<u32>> {
        let mut counts = vec![0u32; self.formulation.num_cols()];
        for walk in walks {
            let idx: Vec<usize> = walk
                .iter()
                .map(|&p| self.region.index_of(p))
                .collect::<Option<_>>()?;
            if idx.len() == 1 {
                let v = idx[0];
                if self.first[v] == self.first[v + 1] {
                    continue;
                }
                if self.stay[v] != NONE && counts[self.stay[v] as usize] == 0 {
                    counts[self.stay[v] as usize] = 1;
                    continue;
                }
                let d = (0..4u8).find(|&d| self.nb[v][d as usize] != NONE)?;
                let w = self.nb[v][d as usize] as usize;
                let back = (d + 2) % 4;
                if !self.add_passage(&mut counts, v, d, d)
                    || !self.add_passage(&mut counts, w, back, back)
                {
                    return None;
                }
                continue;
            }
            let m = idx.len();
            for i in 0..m {
                let (prev, cur, next) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
                let side = |w: usize| (0..4u8).find(|&d| self.nb[cur][d as usize] == w as u32);
                if !self.add_passage(&mut counts, cur, side(prev)?, side(next)?) {
                    return None;
                }
            }
        }
        Some(counts)
    }

    /// Whether integer counts form a feasible solution (covering; one side component for
    /// tours).
    pub(crate) fn is_feasible_counts(&self, counts: &[u32]) -> bool {
        let x: Vec<f64> = counts.iter().map(|&c| f64::from(c)).collect();
        self.formulation.is_feasible(&x, &[])
            && (!self.needs_connectivity() || self.side_components(&x, 0.5).1 == 1)
    }

    /// Merges the side components of integer counts into one, greedily by cheapest move:
    /// re-pairing two passages at a pixel both components cross, swapping two parallel edges
    /// of a unit square onto its other two sides, or a doubled edge between adjacent pixels.
    ///
    /// Each round lists every move once (O(N)) and applies them cheapest first (ties in
    /// scan order), skipping a move that joins components already joined this round or
    /// touches a pixel an applied move touched (its cost may have changed): the first move of
    /// a round is the single cheapest, as in a one-move-per-round greedy, and a round joins
    /// many components, so the rounds are few even with thousands of components.
    pub(crate) fn connect(&self, mut counts: Vec<u32>) -> Vec<u32> {
        let mut touched = vec![false; self.region.len()];
        loop {
            let x: Vec<f64> = counts.iter().map(|&c| f64::from(c)).collect();
            let (label, count) = self.side_components(&x, 0.5);
            if count <= 1 {
                return counts;
            }
            let comp = |v: usize, d: u8| label[v * 4 + d as usize];
            let mut moves: Vec<Move> = Vec::new();
            let mut consider =
                |delta: i64, rem: Vec<usize>, add: Vec<(usize, u8, u8)>, joins: (u32, u32)| {
                    moves.push(Move {
                        delta,
                        rem,
                        add,
                        joins,
                    });
                };
            let cost_of = |v: usize, a: u8, b: u8| self.passage_cost(v, a, b);
            for v in 0..self.region.len() {
                let here: Vec<usize> = (self.first[v]..self.first[v + 1])
                    .filter(|&k| counts[k] > 0)
                    .collect();
                // Re-pair two passages of different components at v.
                for &k1 in &here {
                    for &k2 in &here {
                        let (p, q) = (self.vars[k1], self.vars[k2]);
                        if k1 >= k2 || comp(v, p.a) == comp(v, q.a) {
                            continue;
                        }
                        let old = self.cost(k1) as i64 + self.cost(k2) as i64;
                        for (s1, s2) in [((p.a, q.a), (p.b, q.b)), ((p.a, q.b), (p.b, q.a))] {
                            let delta = cost_of(v, s1.0, s1.1) + cost_of(v, s2.0, s2.1) - old;
                            consider(
                                delta,
                                vec![k1, k2],
                                vec![(v, s1.0, s1.1), (v, s2.0, s2.1)],
                                (comp(v, p.a), comp(v, q.a)),
                            );
                        }
                    }
                }
                // A doubled edge from a passage at v to a passage at its neighbour w.
                for s in 0..4u8 {
                    let w = self.nb[v][s as usize];
                    if w == NONE {
                        continue;
                    }
                    let w = w as usize;
                    let t = (s + 2) % 4;
                    for &k in &here {
                        for j in (self.first[w]..self.first[w + 1]).filter(|&j| counts[j] > 0) {
                            let (p, q) = (self.vars[k], self.vars[j]);
                            if comp(v, p.a) == comp(w, q.a) {
                                continue;
                            }
                            let delta = cost_of(v, p.a, s)
                                + cost_of(v, s, p.b)
                                + cost_of(w, q.a, t)
                                + cost_of(w, t, q.b)
                                - self.cost(k) as i64
                                - self.cost(j) as i64;
                            consider(
                                delta,
                                vec![k, j],
                                vec![(v, p.a, s), (v, s, p.b), (w, q.a, t), (w, t, q.b)],
                                (comp(v, p.a), comp(w, q.a)),
                            );
                        }
                    }
                }
            }
            // Square swaps: edge v1-v2 (side d) and w1-w2 parallel to it on side s.
            for &(v1, d, v2) in &self.edges {
                let e = (d + 2) % 4;
                for s in [(d + 1) % 4, (d + 3) % 4] {
                    let (w1, w2) = (self.nb[v1][s as usize], self.nb[v2][s as usize]);
                    if w1 == NONE || w2 == NONE {
                        continue;
                    }
                    let (w1, w2) = (w1 as usize, w2 as usize);
                    if self.nb[w1][d as usize] != w2 as u32 {
                        continue;
                    }
                    if self.side_usage(&x, v1, d) < 0.5 || self.side_usage(&x, w1, d) < 0.5 {
                        continue;
                    }
                    if comp(v1, d) == comp(w1, d) {
                        continue;
                    }
                    let t = (s + 2) % 4;
                    // Replace one end of a passage at each corner.
                    let pick = |v: usize, side: u8| {
                        (self.first[v]..self.first[v + 1])
                            .filter(|&k| {
                                counts[k] > 0 && (self.vars[k].a == side || self.vars[k].b == side)
                            })
                            .min_by_key(|&k| self.cost(k))
                    };
                    let (Some(k1), Some(k2), Some(k3), Some(k4)) =
                        (pick(v1, d), pick(v2, e), pick(w1, d), pick(w2, e))
                    else {
                        continue;
                    };
                    let swap_end = |k: usize, from: u8, to: u8| {
                        let p = self.vars[k];
                        if p.a == from {
                            (p.pixel, to, p.b)
                        } else {
                            (p.pixel, p.a, to)
                        }
                    };
                    let add = vec![
                        swap_end(k1, d, s),
                        swap_end(k2, e, s),
                        swap_end(k3, d, t),
                        swap_end(k4, e, t),
                    ];
                    let rem = vec![k1, k2, k3, k4];
                    let delta: i64 = add.iter().map(|&(v, a, b)| cost_of(v, a, b)).sum::<i64>()
                        - rem.iter().map(|&k| self.cost(k) as i64).sum::<i64>();
                    consider(delta, rem, add, (comp(v1, d), comp(w1, d)));
                }
            }
            if moves.is_empty() {
                return counts;
            }
            moves.sort_by_key(|m| m.delta);
            let mut joined = UnionFind::<u32>::new(count);
            let mut applied: Vec<usize> = Vec::new();
            for m in moves {
                let pixels = m.rem.iter().map(|&k| self.vars[k].pixel);
                let pixels: Vec<usize> = pixels.chain(m.add.iter().map(|a| a.0)).collect();
                if joined.equiv(m.joins.0, m.joins.1) || pixels.iter().any(|&v| touched[v]) {
                    continue;
                }
                for &k in &m.rem {
                    counts[k] -= 1;
                }
                for &(v, a, b) in &m.add {
                    if !self.add_passage(&mut counts, v, a, b) {
                        return counts;
                    }
                }
                joined.union(m.joins.0, m.joins.1);
                for v in pixels {
                    touched[v] = true;
                    applied.push(v);
                }
            }
            for v in applied {
                touched[v] = false;
            }
        }
    }
}

impl CutModel for PassageModel<'_> {
    fn formulation(&self) -> &Formulation {
        &self.formulation
    }

    fn separate(&self, x: &[f64], _integral: bool, deadline: &Deadline) -> Vec<Row> {
        if !self.needs_connectivity() {
            return Vec::new();
        }
        let weighted: Vec<(usize, usize, f64)> = self
            .edges
            .iter()
            .map(|&(v, d, w)| (v, w, self.side_usage(x, v, d)))
            .collect();
        let cuts = violated_cuts(self.region.len(), &weighted, 2.0 - 1e-6, deadline);
        if !cuts.is_empty() {
            return cuts
                .into_iter()
                .map(|s| {
                    let sides: Vec<bool> = (0..4 * self.region.len()).map(|i| s[i / 4]).collect();
                    self.side_cut(&sides)
                })
                .collect();
        }
        self.crossing_cuts(x)
    }

    fn is_feasible(&self, x: &[f64]) -> bool {
        self.is_feasible_counts(&self.counts(x))
    }

    fn repair(&self, x: &[f64]) -> Option<Vec<f64>> {
        let counts = self.connect(self.counts(x));
        self.is_feasible_counts(&counts)
            .then(|| counts.iter().map(|&c| f64::from(c)).collect())
    }

    /// In a solution with at most T turns, a passage of turn cost c is used at most T / c times
    /// at a pixel, and a straight passage at most T / 2 times: each straight pass belongs to a
    /// different link (maximal straight piece) of that orientation, every link has two ends,
    /// and each end takes one unit of turn cost (a 90° turn ends one horizontal and one
    /// vertical link, a U-turn two links of one orientation). With weights, every other pixel
    /// costs at least 1 and the length is at least N. For weighted cycle covers a pixel may be
    /// a one-pixel walk of length 0 and cost 4C: the length is only at least 0, and every
    /// other pixel costs at least min(1, 4C).
    fn tighten(&self, f: &mut Formulation, target: u64) {
        let n = (self.region.len() - self.isolated) as f64;
        let target = target as f64;
        let (turn_budget, rest) = self.goal.turn_budget(n, target);
        tighten_columns(f, self.vars.len(), (target, rest), |k| {
            let p = self.vars[k];
            (passage_turns(p.a, p.b) == 0).then_some(turn_budget / 2.0)
        });
    }

    fn heuristic_caps(&self) -> Option<Vec<f64>> {
        Some(vec![2.0; self.formulation.num_cols()])
    }

    fn elements(&self) -> usize {
        self.region.len()
    }

    /// The pixels first reached by a breadth-first search from `centre` (at most `size`),
    /// with their passage columns and one-pixel walks.
    fn window(&self, centre: usize, size: usize) -> Vec<usize> {
        let mut seen = std::collections::HashSet::from([centre]);
        let mut queue = std::collections::VecDeque::from([centre]);
        let mut columns = Vec::new();
        while let Some(v) = queue.pop_front() {
            columns.extend(self.first[v]..self.first[v + 1]);
            if self.stay[v] != NONE {
                columns.push(self.stay[v] as usize);
            }
            for &w in &self.nb[v] {
                if w != NONE && seen.len() < size && seen.insert(w as usize) {
                    queue.push_back(w as usize);
                }
            }
        }
        columns
    }
}

impl PassageModel<'_> {
    /// How much of each pixel's passages at `x` runs horizontally and vertically: a passage
    /// gives each of its two sides half its value, to the orientation of the side (a straight
    /// pass 1 to its own, a turn 1/2 to each, a U-turn 1 to the side's). One-pixel walks of
    /// `weighted-cc` count for neither.
    pub(crate) fn orientation(&self, x: &[f64]) -> Vec<[f64; 2]> {
        let mut out = vec![[0.0; 2]; self.region.len()];
        for (k, p) in self.vars.iter().enumerate() {
            for side in [p.a, p.b] {
                // E = 0 and W = 2 are horizontal sides.
                out[p.pixel][usize::from(side % 2)] += 0.5 * x[k];
            }
        }
        out
    }

    /// A simple feasible solution: every strip of a minimum strip cover walked there and back
    /// (4 turns each; a one-pixel strip becomes a step to a neighbour and back), merged into a
    /// tour when the goal asks for one.
    pub(crate) fn strip_solution(&self) -> Option<Vec<u32>> {
        let cover = crate::strip_cover::strip_cover(self.region);
        let mut walks: Vec<Vec<Pixel>> = Vec::new();
        for s in &cover.strips {
            let pixels: Vec<Pixel> = s.pixels().collect();
            let mut walk = pixels.clone();
            if pixels.len() >= 2 {
                walk.extend(pixels[1..pixels.len() - 1].iter().rev());
            }
            walks.push(walk);
        }
        let counts = self.walk_counts(&walks)?;
        let counts = if self.needs_connectivity() {
            self.connect(counts)
        } else {
            counts
        };
        self.is_feasible_counts(&counts).then_some(counts)
    }
}
