//! Exact baselines for discrete milling: proven optima of `cc-turns`, `turns`
//! (tour), `length`, `weighted` and `weighted-cc` on a [`Discrete`] instance, and the
//! maximum rook placement of Lemma 4.3 of *Optimal covering tours with turn costs*.
//!
//! The models are the grid models of [`crate`] with a pixel's four sides replaced by a
//! vertex's *ports* (its incident edges), and they run in the same cut loop
//! (`crate::driver`), with the same LP/MIP layer.
//!
//! # Formulations
//!
//! * **Passage model** (`cc-turns`, `turns`, `weighted`, `weighted-cc`): for every vertex `v`
//!   and unordered pair `{a, b}` of its ports (`a = b` a U-turn) an integer `p_{v,ab} >= 0`,
//!   the number of times a walk passes through `v` between the edges `va` and `vb`, of turn
//!   cost [`Discrete::turn`] (0 through a collinear pair, 1 otherwise, 2 for a U-turn).
//!   Coverage: `Σ_ab p_{v,ab} >= 1` at every vertex with a neighbour. Consistency: on every
//!   edge `{v, w}` the passage ends at port `w` of `v` equal those at port `v` of `w` (a
//!   U-turn counts twice): the edge's multiplicity. An isolated vertex is a one-vertex walk
//!   (length 0, 4 turns: the checker's convention) outside the model.
//!   `cc-turns` minimizes `Σ turn · p`; `weighted-cc` minimizes `Σ (1 + C turn) p` plus a
//!   binary column of cost 4C per vertex with a neighbour, the one-vertex walk; `turns` and
//!   `weighted` minimize the same as their cover versions with connectivity cuts (below).
//! * **Length** (`length`): edge multiplicities `x_e ∈ {0, 1, 2}`, `z_v >= 1` with
//!   `Σ_{e ∋ v} x_e = 2 z_v` and `x(δ(S)) >= 2` for every proper vertex set `S`; minimize
//!   `Σ x_e`. An optimal closed walk never uses an edge three times (removing two copies keeps
//!   every degree even and the multigraph connected), and a connected even multigraph on all
//!   vertices is walked by an Euler tour: the model's optimum is the shortest closed walk
//!   visiting every vertex.
//!
//! # Why the passage model is exact
//!
//! A closed walk of two or more vertices gives one passage per visit, with the turn of that
//! visit, and its passages balance on every edge; a one-vertex walk at a vertex with a
//! neighbour `w` costs what the walk `v, w` costs in turns (two U-turns, 4) and is the stay
//! column of `weighted-cc`. Conversely, balanced passages decompose into closed walks by
//! pairing, on every edge, the passage ends at its two ports (any pairing): each passage is
//! one visit with its turn, so length and turns are kept.
//!
//! **Tours.** Split every vertex into its ports: a passage joins two ports of its vertex, a
//! used edge joins its two ports. Two closed walks through one port both traverse that
//! port's edge and are spliced there into one with the same passages
//! (`crate::walks::splice_walks`), so the walks of a solution whose used ports form
//! one connected graph are one tour. Walks that meet at a vertex through different ports
//! are not joined: on a general graph every vertex may be visited by two port components.
//!
//! For every port `g` a binary indicator `z_g` means "the tour uses `g`", linked by
//! `z_g <= usage(g)` (the passage ends at `g`) and `Σ_{g ∈ P(v)} z_g >= 1` at every vertex
//! `v`. For a port set `S` let `crossing(S) = Σ_{edges across S} x_e + Σ_{passages across
//! S} p`. The connectivity cuts are the generalized subtour cuts
//! `crossing(S) >= 2 (A + B − 1)`, where `A` is `z_p` for a port `p ∈ S` or
//! `1 − Σ_{g ∈ P(u) ∖ S} z_g` for a vertex `u`, and `B` the same with the outside of `S`
//! (a vertex with every port in `S` gives `A = 1`: with `B = 1` too, this is the plain
//! `crossing(S) >= 2`). *Validity*: take any tour with `z_g = 1` exactly on its used ports;
//! the links hold (usages are integers, every vertex is visited). `A <= 1`, and `A >= 1`
//! only if the tour uses a port in `S`: for `z_p` by definition; for `u`, if the tour used
//! no port of `S` then its used ports at `u` (there is one) all lie outside `S` and
//! `A <= 0`. Likewise `B`. If the tour uses ports on both sides, its closed walk, which
//! alternates passages and edge traversals, crosses `S` an even number of times, at least
//! twice, and each crossing is counted once in `crossing(S)`: the cut holds. Otherwise
//! `A + B − 1 <= 0 <= crossing(S)`. *Completeness*: let an integer solution with its
//! indicators satisfy every row, the links included, and still have several port
//! components. The ports with `z = 1` are used and meet every vertex. If they lie in two
//! components, `S` = the ports of one of them has `crossing(S) = 0` with `A = B = 1`: a
//! violated cut. Otherwise they lie in one component, which visits every vertex and is a
//! tour by itself; with the same indicators it satisfies every row and bound the solution
//! does, at no greater cost, so when the solution is a MIP optimum the repair (which keeps
//! it, below) meets the MIP's bound. So every MIP round of the cut loop either ends or adds
//! a new row (the links, the first time), and there are finitely many.
//!
//! Separation: cuts with `S` a union of whole vertices (`A = B = 1`) exactly by minimum cuts;
//! then `S` from the port components of the support and of its heavier parts. The
//! indicators' links are rows of the cut pool, added by the first integer solution that no
//! cut of constant sides (`A = B = 1`) separates; until then the indicators are free and
//! only those cuts are separated, which keeps the MIPs of grid-like instances as small as
//! without indicators. An integer solution whose port components include one that touches
//! every vertex is repaired by keeping the cheapest such component, otherwise by dropping
//! components whose vertices others visit and merging the rest.
//!
//! **U-turn reduction** (`cc-turns` and `turns` only, where length is free). A U-turn at `v`
//! back onto the edge from `u`, when `u, v` continue straight onto `w = straight_on(u, v)`,
//! can be replaced by `u → v → w → v → u`: two straight passes through `v` (0 turns each;
//! collinearity is symmetric) and a U-turn at `w` back onto `wv` (2 turns). Turns are kept,
//! every vertex visited stays visited, and the walks stay one walk where they were one.
//! Repeating the move walks along the channel of the edge `uv`; since the collinear pairs
//! form a matching, that channel is either a path, whose far end is reached (no straight
//! continuation there), or a cycle, on which the move never ends. So a U-turn column exists
//! only where the channel does not continue straight, or where the channel is cyclic. With
//! length counted (`weighted`, `weighted-cc`) every U-turn is kept.
//!
//! # Bounds
//!
//! On a general graph neither length nor turns have a known parity (a triangle without
//! collinear pairs is a closed walk of length 3 and 3 turns), so real bounds are rounded up to
//! the next integer (the cut loop's `step` 1), except `length` on a bipartite graph, where
//! every closed walk has even length (step 2). The reduced-cost fixing of the cut loop, the
//! cheap bounds and the budget bounds of `tighten` are argued at their definitions. The cheap
//! bound of the turn objectives is a greedy [`rook_placement`]; of `length` the number of
//! vertices (for two or more).
//!
//! The returned walks always go through [`check::check`]; the reported value is the
//! checker's recount, and the status is `optimal` only when it equals the proven bound.

mod length;
mod passage;
mod rooks;
#[cfg(test)]
mod tests;

use crate::bounds::LowerBound;
use crate::driver::Stop;
use crate::lp::{Deadline, Settings};
use crate::topology::graph_components;
use crate::{ExactResult, Objective};
use length::solve_length;
use mowmill_core::discrete::check;
use mowmill_core::discrete::{Discrete, VertexWalk};
use passage::solve_passages;
pub use rooks::{ROOK_MILP_LIMIT, RookPlacement, channels, rook_placement};

const NONE: u32 = u32::MAX;

/// Options of an exact discrete solve.
#[derive(Clone, Debug)]
pub struct DiscreteOptions {
    /// Wall-clock limit in seconds for the whole solve (None: no limit).
    pub time_limit: Option<f64>,
    /// HiGHS threads per solve.
    pub threads: usize,
    /// Print HiGHS's log and the cut loop's progress to stderr.
    pub verbose: bool,
}

impl Default for DiscreteOptions {
    fn default() -> Self {
        DiscreteOptions {
            time_limit: None,
            threads: 1,
            verbose: false,
        }
    }
}

/// The answer of an exact discrete solve: the grid solver's result type, with vertex walks in
/// place of a grid cover (`cover`) and no coverage cap.
pub type DiscreteExactResult = ExactResult<Vec<VertexWalk>>;

/// What a solver hands back before checking: the exact crate's answer with vertex walks.
type Answer = crate::Answer<Vec<VertexWalk>>;

/// Solves `objective` on a discrete instance exactly, within `opts.time_limit`.
///
/// # Arguments
/// * `inst` — the graph with its collinear pairs.
/// * `objective` — `length`, `cc-turns`, `turns`, `weighted` or `weighted-cc` (`lawn-tsp` has
///   no discrete meaning and is an error).
/// * `opts` — time limit, threads and verbosity.
///
/// # Returns
/// A [`DiscreteExactResult`] whose walks have passed [`check::check`] with recounted cost
/// `value`, a proven `lower_bound`, and `status` `optimal` exactly when the two are equal;
/// `infeasible` for a tour objective on a disconnected graph.
///
/// # Complexity
/// Exponential in the worst case (the problems are NP-hard); LP rounds with O(V) maximum
/// flows of separation each, then MIP rounds.
///
/// # Guarantee
/// `status == optimal` implies `value` is the optimum; otherwise `lower_bound <= OPT <= value`
/// (see the module documentation for the models and the arguments).
pub fn solve(inst: &Discrete, objective: Objective, opts: &DiscreteOptions) -> DiscreteExactResult {
    let deadline = Deadline::new(opts.time_limit);
    let settings = Settings {
        threads: opts.threads.max(1),
        verbose: opts.verbose,
        ..Settings::default()
    };
    let none = LowerBound {
        value: 0,
        source: "none",
    };
    let answer = if inst.is_empty() {
        Answer::stopped(Stop::Error("the instance has no vertex".into()), none)
    } else {
        match objective {
            Objective::LawnTsp | Objective::LawnLength => Answer::stopped(
                Stop::Error(format!("{objective} is not defined on discrete instances")),
                none,
            ),
            Objective::Length => solve_length(inst, &deadline, &settings),
            _ => solve_passages(inst, objective, &deadline, &settings),
        }
    };
    assemble(inst, objective, answer, deadline.elapsed())
}

/// The checked result: the walks are recounted, and the status is `optimal` only when the
/// recount equals the proven bound.
fn assemble(inst: &Discrete, objective: Objective, a: Answer, seconds: f64) -> DiscreteExactResult {
    let infeasible = "no covering tour exists: the graph is not connected";
    a.into_result(
        objective,
        (seconds, inst.len(), None),
        infeasible,
        |walks| check::check(inst, walks),
    )
}

fn is_connected(inst: &Discrete) -> bool {
    graph_components(
        inst.len(),
        inst.edges().map(|(a, b)| (a as usize, b as usize)),
    )
    .1 <= 1
}

fn is_bipartite(inst: &Discrete) -> bool {
    let mut colour = vec![u8::MAX; inst.len()];
    for s in 0..inst.len() as u32 {
        if colour[s as usize] != u8::MAX {
            continue;
        }
        colour[s as usize] = 0;
        let mut stack = vec![s];
        while let Some(v) = stack.pop() {
            for &w in inst.neighbors(v) {
                if colour[w as usize] == u8::MAX {
                    colour[w as usize] = 1 - colour[v as usize];
                    stack.push(w);
                } else if colour[w as usize] == colour[v as usize] {
                    return false;
                }
            }
        }
    }
    true
}

/// For every component of the graph, a closed walk around a spanning tree (every tree edge
/// twice; a one-vertex component is the one-vertex walk).
fn tree_walks(inst: &Discrete) -> Vec<VertexWalk> {
    let n = inst.len();
    let mut seen = vec![false; n];
    let mut out = Vec::new();
    for root in 0..n as u32 {
        if seen[root as usize] {
            continue;
        }
        seen[root as usize] = true;
        let mut walk = vec![root];
        // Iterative DFS recording the walk down and back up: (vertex, next neighbour index).
        let mut stack: Vec<(u32, usize)> = vec![(root, 0)];
        while let Some(top) = stack.len().checked_sub(1) {
            let (v, next) = stack[top];
            if let Some(&w) = inst.neighbors(v).get(next) {
                stack[top].1 += 1;
                if !seen[w as usize] {
                    seen[w as usize] = true;
                    walk.push(w);
                    stack.push((w, 0));
                }
            } else {
                stack.pop();
                if let Some(&(parent, _)) = stack.last() {
                    walk.push(parent);
                }
            }
        }
        // The walk ends back at the root: drop that repeat (walks are cyclic).
        if walk.len() > 1 {
            walk.pop();
        }
        out.push(walk);
    }
    out
}
