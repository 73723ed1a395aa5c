//! The one registry of approximation algorithms.
//!
//! Each entry has a stable name (the CLI's `--algo`), the objective it targets, the guarantees
//! it proves and the theorem they come from. The CLI, the benchmark runner, the plots and the
//! regression gate all read [`REGISTRY`]; nothing lists the algorithms a second time.
//!
//! An algorithm takes a region and returns closed walks ([`Output`]s): never its own cost. The
//! caller runs every output through the [`checker`](crate::checker), which recounts length,
//! turns and coverage; [`Guarantee::holds`] then compares the recount with the proven bound.
//!
//! # Weighted objectives
//!
//! `weighted` (a tour) and `weighted-cc` (a cycle cover) measure length + C · turns, C the
//! turn cost (`solve --turn-cost C`; in a bench config, the `turn_cost` of an `[[exact]]`
//! table of that objective), the objective of a published CPLEX study of tours and cycle
//! covers with turn costs (2018; there C = 50: a 90° turn costs 50, a U-turn 100, a move 1).
//! They are not outputs of their own: every milling algorithm reports them on the outputs it
//! has ([`Objective::carriers`]: its tour for `weighted`, its cycle cover, else its tour, for
//! `weighted-cc`; any covering tour or cycle cover is feasible for them), so that the
//! algorithms can be compared with `exact --objective weighted(-cc)`. No paper proves a
//! ratio for any of them under these objectives, and none is claimed: their rows carry no
//! guarantee.

// The core's modules under the paths the algorithms use (this crate is built on the core and
// the exact crate's LP layer: it cannot reach the registry's readers, the harness or the CLI).
#[cfg(test)]
pub(crate) use mowmill_core::{Pixel, generate, instance};
pub(crate) use mowmill_core::{
    checker, error, flow, lawn_check, objective, region, strip_cover, topology, tour,
};
pub(crate) use mowmill_exact as exact;

/// The discrete model of the core with its algorithms: the star cover and the merge.
pub mod discrete {
    pub use mowmill_core::discrete::*;
    pub mod merge;
    pub mod star_cover;
}

/// The orthogonal-polygon model of the core with its algorithms: Corollary 4 of *Lawn mowing
/// and milling* and the strips/star contour of Theorem 5.7 of the turn-cost paper.
pub mod ortho {
    pub use mowmill_core::ortho::*;
    mod corollary4;
    mod join;
    mod registered;
    mod strips_contour;
    pub use corollary4::{Certificates, LowerBounds, corollary4, lower_bounds, walk_length};
    pub use registered::{COROLLARY4, STAR_CONTOUR, STRIPS_CONTOUR};
    pub use strips_contour::{
        Certificates as StripsContourCertificates, StripsContour, star_contour, strips_contour,
        walk_turns,
    };
}

use crate::discrete::format::DiscreteCover;
use crate::discrete::{Discrete, Params};
use crate::error::Result;
use crate::region::Region;
use crate::tour::CycleCover;
use num_integer::Integer;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt;
use theorems::{Bound, Claim, Paper, Theorem};

pub use crate::objective::{Objective, canonical_objective};

// Shared pieces (no algorithm of their own): implementation detail.
pub(crate) use mowmill_core::euler;
pub(crate) mod precondition;
pub(crate) mod tsp_local;
pub(crate) mod walks;
// The algorithms are run through the registry and `evaluate`, so their modules are crate-private;
// the few entry points the integration tests drive directly are re-exported, hidden from docs.
// Lawn mowing and milling (Arkin, Fekete, Mitchell).
#[doc(hidden)]
pub mod lawn;
mod milling;
#[doc(hidden)]
pub use milling::{holes1325, milling25, tsp65, two_opt as milling_two_opt};
// Optimal covering tours with turn costs.
#[doc(hidden)]
pub mod matching;
pub mod theorems;
mod turns;
#[doc(hidden)]
pub use matching::{self as endpoint_matching, turn_distance};
#[doc(hidden)]
pub use turns::{boundary_cc, coverage4, lp_lns, merge, strips_matching};
pub(crate) use turns::{star_cover, strips_double, thin, thin_euler, visits};

/// What a guarantee's factor multiplies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Against {
    /// The optimum of the objective (known only where an exact solver proved it).
    Opt,
    /// The number of pixels N.
    N,
    /// The constant 1 (a bound such as "max coverage <= 4").
    One,
}

/// What a guarantee bounds on an output of its objective.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Quantity {
    /// The objective's value (length or turns, as the objective says).
    Value,
    /// The walk's length, whatever the objective (e.g. "a 4-approximation on length" of a
    /// min-turn tour).
    Length,
    /// The largest number of visits of one pixel.
    MaxCoverage,
}

impl Quantity {
    /// The name used in messages and tables: the objective's name for `Value`.
    pub fn label(self, objective: Objective) -> &'static str {
        match self {
            Quantity::Value => objective.name(),
            Quantity::Length => "length",
            Quantity::MaxCoverage => "max-coverage",
        }
    }
}

/// The instances a guarantee is proven for, beyond the algorithm's preconditions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum When {
    /// Every instance the algorithm accepts.
    Always,
    /// Regions without cut vertices and with at least 3 pixels (Theorem 5 of the milling
    /// paper: a 2-pixel region needs a tour of length 2 > (6·2 − 4)/5).
    Biconnected,
    /// Instances of a lattice with d allowed directions (restricted-direction milling,
    /// Theorem 5.2 of the turn-cost paper): voxel regions, hexagonal cells, honeycombs, and
    /// grid regions (d = 2).
    Lattice,
    /// Instances without closed channels ("rings"): every grid region and lattice region.
    /// The star cover's ring cycles are merged at up to 4 turns each, which no rook pays for.
    NoRings,
    /// At least two pixels (vertices). Table 1's factors in δ and ρ are 0 on a one-vertex
    /// instance, whose one-vertex walk the checker counts as 4 turns (turning in place): the
    /// paper's bounds are read for instances with an edge.
    NonTrivial,
    /// Simple polygons: no holes (Corollary 4 of the milling paper). Grid regions without
    /// holes, orthogonal polygons without inner rings; never discrete instances.
    Simple,
}

impl When {
    pub fn applies(self, region: &Region) -> bool {
        self.applies_to(Model::Grid(region))
    }

    /// Whether the condition holds on an instance of either model.
    pub fn applies_to(self, model: Model<'_>) -> bool {
        match (self, model) {
            (When::Always, _) => true,
            (When::Biconnected, Model::Grid(region)) => {
                // A pixel of degree 1 makes its neighbour a cut vertex once there are 3 pixels:
                // that cheap scan answers most regions before the block search.
                region.len() >= 3
                    && (0..region.len()).all(|i| region.degree(i) >= 2)
                    && !crate::topology::cut_vertices(region).into_iter().any(|c| c)
            }
            // Theorem 5 of the milling paper is about grid graphs.
            (When::Biconnected, Model::Discrete(_)) => false,
            (When::Lattice, Model::Grid(_)) => true,
            (When::Lattice, Model::Discrete(inst)) => inst.directions().is_some(),
            (When::NonTrivial, m) => m.len() >= 2,
            (When::NoRings, Model::Grid(_)) => true,
            (When::NoRings, Model::Discrete(inst)) => !crate::discrete::star_cover::channels(inst)
                .list
                .iter()
                .any(|c| c.closed),
            (When::Simple, Model::Grid(region)) => crate::topology::holes(region).count == 0,
            (When::Simple, Model::Ortho(p)) => !p.rings().iter().any(|r| r.hole),
            (When::Simple, Model::Discrete(_)) => false,
            // Orthogonal polygons with arbitrary coordinates are none of these.
            (When::Biconnected | When::Lattice | When::NoRings, Model::Ortho(_)) => false,
        }
    }
}

/// An instance of one of the three models: a grid region, a discrete milling instance (a graph
/// with collinear pairs; [`crate::discrete`]), or an orthogonal polygon with arbitrary
/// coordinates ([`crate::ortho`]). A grid region is the special case
/// [`Discrete::from_region`](crate::discrete::Discrete::from_region) of the second and
/// [`Polygon::from_region`](crate::ortho::Polygon::from_region) of the third.
#[derive(Clone, Copy, Debug)]
pub enum Model<'a> {
    Grid(&'a Region),
    Discrete(&'a Discrete),
    Ortho(&'a crate::ortho::Polygon),
}

impl Model<'_> {
    /// The `model` column of results: `grid`, `discrete` or `ortho`.
    pub fn name(self) -> &'static str {
        match self {
            Model::Grid(_) => "grid",
            Model::Discrete(_) => "discrete",
            Model::Ortho(_) => "ortho",
        }
    }

    /// The number of pixels (vertices) to cover; for an orthogonal polygon its area rounded up
    /// (the pixel count of an integral one).
    pub fn len(self) -> usize {
        match self {
            Model::Grid(r) => r.len(),
            Model::Discrete(d) => d.len(),
            Model::Ortho(p) => p.area().map_or(0, |a| a.ceil().max(0) as usize),
        }
    }

    /// Whether there is nothing to cover.
    pub fn is_empty(self) -> bool {
        self.len() == 0
    }

    /// Table 1's parameters (δ, μ, ρ, d and the exact counts behind them); a grid region's are
    /// those of its grid graph.
    /// An orthogonal polygon has none of them (no graph): its factors are constants, and a
    /// scaled guarantee does not apply to it ([`Params::none`]).
    pub fn params(self) -> Params {
        match self {
            Model::Grid(r) => Discrete::from_region(r).params(),
            Model::Discrete(d) => d.params(),
            Model::Ortho(_) => Params::none(),
        }
    }
}

/// An instance parameter that a factor of Table 1 is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Param {
    /// ρ + 2δ with ρ, δ the averages (Theorem 5.1 as the paper states it).
    RhoPlus2Delta,
    /// δ, the average degree.
    Delta,
    /// μ, the maximum degree; at least 1 (a one-vertex instance has μ = 0 and its one-vertex
    /// walk visits the vertex once: we read Table 1's "coverage μ" as max(μ, 1)).
    Mu,
    /// d, the allowed directions of a lattice instance (none: the bound does not apply).
    D,
    /// max_v β(v) = dir(v) + 2·deg(v) (+1 at a leaf, +4 when isolated): the star cover's
    /// proven per-rook turns ([`crate::discrete::star_cover::beta`]).
    StarRatio,
}

impl Param {
    /// Its value on an instance as a fraction (numerator, denominator > 0); `None` when the
    /// instance has no such parameter (d of a non-lattice instance).
    pub fn value(self, p: &Params) -> Option<(i64, i64)> {
        let n = p.n.max(1) as i64;
        Some(match self {
            Param::RhoPlus2Delta => (p.direction_sum as i64 + 4 * p.edges as i64, n),
            Param::Delta => (2 * p.edges as i64, n),
            Param::Mu => (i64::from(p.mu.max(1)), 1),
            Param::D => (i64::from(p.d?), 1),
            Param::StarRatio => (p.beta_max as i64, 1),
        })
    }

    /// Its name in bounds' texts.
    pub fn symbol(self) -> &'static str {
        match self {
            Param::RhoPlus2Delta => "rho + 2 delta",
            Param::Delta => "delta",
            Param::Mu => "mu",
            Param::D => "d",
            Param::StarRatio => "beta_max",
        }
    }
}

/// What a bound's `num` multiplies: 1, or an instance parameter P (the factor is then
/// `num · P + plus`, e.g. 5d + 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scale {
    One,
    Of { param: Param, plus: i64 },
}

impl Scale {
    /// `(num, den, add)` of `q ≤ (num·X + add)/den` with the parameter's value put in; `None`
    /// when the instance lacks the parameter.
    pub fn resolve(self, num: i64, den: i64, add: i64, p: &Params) -> Option<(i64, i64, i64)> {
        match self {
            Scale::One => Some((num, den, add)),
            Scale::Of { param, plus } => {
                let (pn, pd) = param.value(p)?;
                let (num, den, add) = (num * pn + plus * pd, den * pd, add * pd);
                let g = num.gcd(&den).gcd(&add).max(1);
                Some((num / g, den / g, add / g))
            }
        }
    }

    /// The factor's text for `num` (`5 d + 2`, `(rho + 2 delta)`), or `None` for a constant.
    pub fn text(self, num: i64) -> Option<String> {
        let Scale::Of { param, plus } = self else {
            return None;
        };
        let times = if num == 1 {
            String::new()
        } else {
            format!("{num} ")
        };
        let plus = match plus {
            0 => String::new(),
            a if a > 0 => format!(" + {a}"),
            a => format!(" - {}", -a),
        };
        let sym = param.symbol();
        let text = format!("{times}{sym}{plus}");
        // Parenthesized where it is a sum, so that "X" multiplies all of it.
        Some(if sym.contains(' ') || !plus.is_empty() {
            format!("({text})")
        } else {
            text
        })
    }
}

/// A proven upper bound ([`Bound`]: `q ≤ (num · X + add) / den` on the quantity `q`, X being
/// OPT, N or 1) on the outputs of `objective`, on the instances `when` names, citing the
/// theorem it comes from. Quantities other than the value are bounded against N or 1 only (no
/// optimum of theirs is computed per row). With a [`Scale`] other than one, `num` multiplies
/// an instance parameter (Table 1's discrete rows): [`Guarantee::on`] puts the instance's value
/// in before deciding. It may be the theorem's own bound or a weaker one we prove (its
/// `source` says which).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Guarantee {
    pub objective: Objective,
    #[serde(flatten)]
    pub bound: Bound,
    pub when: When,
    /// Where it is proven, e.g. "Theorem 5 of Lawn mowing and milling" (the text of the
    /// results' `guarantee` column; it may add the detail of our proof on pixels).
    pub source: &'static str,
    /// The theorem it comes from (the one [`source`](Self::source) cites).
    #[serde(serialize_with = "cite")]
    pub theorem: &'static Theorem,
}

fn cite<S: serde::Serializer>(t: &&'static Theorem, s: S) -> std::result::Result<S::Ok, S::Error> {
    s.serialize_str(&t.cite())
}

impl Guarantee {
    /// A guarantee of `bound` on the outputs of `objective`.
    pub const fn new(
        objective: Objective,
        bound: Bound,
        when: When,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        Guarantee {
            objective,
            bound,
            when,
            source,
            theorem,
        }
    }

    /// The theorem's own bound as a guarantee of `objective` on the instances `when` names (the
    /// paper's bound, proven as stated: written once, in the theorem).
    pub const fn of_theorem(
        objective: Objective,
        when: When,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        let theorems::Measure::Bound(bound) = theorem.measure else {
            panic!("a guarantee of a theorem whose measure is not a bound")
        };
        Guarantee::new(objective, bound, when, theorem, source)
    }

    /// `value ≤ num/den · OPT` on every instance the algorithm accepts.
    pub const fn vs_opt(
        objective: Objective,
        num: i64,
        den: i64,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        let bound = Bound::new(Quantity::Value, num, den, 0, Against::Opt);
        Guarantee::new(objective, bound, When::Always, theorem, source)
    }

    /// `q ≤ (num · P + plus) · X`, P a parameter of the instance and X OPT, N or 1, on the
    /// instances `when` names.
    #[allow(clippy::too_many_arguments)]
    pub const fn scaled(
        objective: Objective,
        quantity: Quantity,
        against: Against,
        num: i64,
        param: Param,
        plus: i64,
        when: When,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        let bound = Bound::scaled(quantity, num, param, plus, against);
        Guarantee::new(objective, bound, when, theorem, source)
    }

    /// Every pixel visited at most `max` times by the outputs of `objective`.
    pub const fn max_coverage(
        objective: Objective,
        max: i64,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        let bound = Bound::new(Quantity::MaxCoverage, max, 1, 0, Against::One);
        Guarantee::new(objective, bound, When::Always, theorem, source)
    }

    /// The walks of `objective` have length at most `factor · N` (hence at most `factor` times
    /// the optimal milling length, which is at least N for N ≥ 2).
    pub const fn length_vs_n(
        objective: Objective,
        factor: i64,
        theorem: &'static Theorem,
        source: &'static str,
    ) -> Self {
        let bound = Bound::new(Quantity::Length, factor, 1, 0, Against::N);
        Guarantee::new(objective, bound, When::Always, theorem, source)
    }

    /// The guarantee on one instance: its condition holds there and the instance's parameters
    /// are put into its factor (a [`Scale::One`] copy); `None` when it does not apply.
    pub fn on(&self, model: Model<'_>) -> Option<Guarantee> {
        self.on_with(model, || model.params())
    }

    /// [`Guarantee::on`] with the instance's parameters from `params` (called only when the
    /// factor needs them), for callers that resolve several guarantees on one instance.
    pub fn on_with(&self, model: Model<'_>, params: impl FnOnce() -> Params) -> Option<Guarantee> {
        if !self.when.applies_to(model) {
            return None;
        }
        match self.bound.scale {
            Scale::One => Some(*self),
            _ => Some(Guarantee {
                bound: self.bound.on(&params())?,
                ..*self
            }),
        }
    }

    /// [`Guarantee::on`] for a region.
    pub fn on_region(&self, region: &Region) -> Option<Guarantee> {
        self.on(Model::Grid(region))
    }

    /// The factor as a float, for tables and plots (of the unresolved guarantee: its `num`).
    pub fn factor(&self) -> f64 {
        self.bound.num as f64 / self.bound.den as f64
    }

    /// Whether `value ≤ (num · x + add) / den`, in exact integer arithmetic.
    pub fn holds(&self, value: u64, x: u64) -> bool {
        self.bound.holds(value, x)
    }

    /// The verdict on one checked output ([`Bound::decide`] with what the evaluation knows):
    /// `Some(true)` when shown to hold, `Some(false)` when violated, `None` when undecided (a
    /// bound against OPT, OPT unknown, and the lower bound `lb` on OPT too weak to show it:
    /// value ≤ f·LB ≤ f·OPT). A guarantee whose factor is still an instance parameter is
    /// undecided: resolve it with [`Guarantee::on`] first.
    pub fn decide(&self, m: &Measured, n: u64, opt: Option<u64>, lb: Option<u64>) -> Option<bool> {
        let q = match self.bound.quantity {
            Quantity::Value => m.value,
            Quantity::Length => m.length,
            Quantity::MaxCoverage => m.max_coverage,
        };
        let known = theorems::Known {
            opt,
            lower: lb,
            upper: None,
        };
        self.bound.decide(q, n, known).verdict()
    }

    /// The bound's value for a given X, rounded down (values are integers).
    pub fn bound(&self, x: u64) -> i64 {
        self.bound.value_at(x)
    }
}

/// What the checker recounted on one output, as guarantees read it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Measured {
    /// The objective's value (length or turns).
    pub value: u64,
    pub length: u64,
    pub max_coverage: u64,
}

impl fmt::Display for Guarantee {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let b = &self.bound;
        let x = match b.against {
            Against::Opt => "OPT",
            Against::N => "N",
            Against::One => "1",
        };
        let num = match b.scale.text(b.num) {
            Some(t) => format!("{t} "),
            None if b.num == 1 => String::new(),
            None => format!("{} ", b.num),
        };
        let add = match b.add {
            0 => String::new(),
            a if a > 0 => format!(" + {a}"),
            a => format!(" - {}", -a),
        };
        let source = match self.when {
            When::Always => self.source.to_string(),
            When::Biconnected => format!("without cut vertices, N >= 3; {}", self.source),
            When::Lattice => format!("lattice instances; {}", self.source),
            When::NoRings => format!("no closed channels; {}", self.source),
            When::NonTrivial => format!("N >= 2; {}", self.source),
            When::Simple => format!("simple polygons; {}", self.source),
        };
        let source = source.as_str();
        let q = b.quantity.label(self.objective);
        if let (Against::One, Some(t)) = (b.against, b.scale.text(b.num)) {
            write!(f, "{q} <= {t} ({source})")
        } else if b.against == Against::One && b.den == 1 {
            write!(f, "{q} <= {} ({source})", b.num + b.add)
        } else if b.den == 1 {
            write!(f, "{q} <= {num}{x}{add} ({source})")
        } else if add.is_empty() {
            write!(f, "{q} <= {}/{} {x} ({source})", b.num, b.den)
        } else {
            write!(f, "{q} <= ({num}{x}{add})/{} ({source})", b.den)
        }
    }
}

/// How cycle covers are merged into tours (turn-cost paper, Theorem 4.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Merge {
    /// Merge at crossings, +2 turns each.
    Naive,
    /// Free merges first, then the cheapest merge.
    #[default]
    Smart,
}

pub use crate::lawn_check::Cutter;

impl Merge {
    pub const NAMES: [&'static str; 2] = ["naive", "smart"];
}

impl fmt::Display for Merge {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Merge::Naive => "naive",
            Merge::Smart => "smart",
        })
    }
}

impl std::str::FromStr for Merge {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Merge, String> {
        match s {
            "naive" => Ok(Merge::Naive),
            "smart" => Ok(Merge::Smart),
            _ => Err(format!("unknown merge {s:?}: expected naive or smart")),
        }
    }
}

/// The order in which a greedy star cover scans the candidates for a rook (`star-cover` on
/// pixels, `discrete-star-cover` on vertices).
///
/// The paper leaves it open: Lemma 4.5 places rooks "greedily", in no stated order and with no
/// tie-break, so every scan order is the paper's algorithm; the rook *set* it yields is a
/// maximal set of pairwise non-attacking rooks, and every such set is the outcome of some order
/// (put it first). See [`crate::discrete::choices`] for the evidence over all orders.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum GreedyOrder {
    /// Index order (pixel or vertex index): the default, and the order of every committed result.
    #[default]
    Index,
    /// Scan these indices first, in this order, then the others in index order (out-of-range
    /// and repeated indices are skipped).
    Sequence(Vec<u32>),
    /// A uniformly random permutation, shuffled by ChaCha8 from this seed.
    Seeded(u64),
}

impl GreedyOrder {
    /// The scan order over `0..n` as a permutation.
    pub fn permutation(&self, n: usize) -> Vec<u32> {
        match self {
            GreedyOrder::Index => (0..n as u32).collect(),
            GreedyOrder::Sequence(first) => {
                let mut seen = vec![false; n];
                let mut out = Vec::with_capacity(n);
                for &v in first.iter().chain(&(0..n as u32).collect::<Vec<u32>>()) {
                    if (v as usize) < n && !seen[v as usize] {
                        seen[v as usize] = true;
                        out.push(v);
                    }
                }
                out
            }
            GreedyOrder::Seeded(seed) => {
                use rand::{RngExt, SeedableRng};
                // Fisher–Yates by hand, so that the permutation of a seed does not depend on
                // the rand crate's shuffle.
                let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(*seed);
                let mut order: Vec<u32> = (0..n as u32).collect();
                for i in (1..n).rev() {
                    order.swap(i, rng.random_range(0..=i));
                }
                order
            }
        }
    }
}

/// Options every algorithm receives; each uses the ones that concern it.
#[derive(Clone, Debug, Default)]
pub struct Options {
    pub merge: Merge,
    pub cutter: Cutter,
    /// The objectives wanted of this run (empty: all of the algorithm's). An algorithm that
    /// computes each objective's walk separately skips the others ([`Options::wants`]);
    /// the rest ignore it.
    pub only: Vec<Objective>,
    /// Post-process tours into ones covering each pixel at most 4 times (Theorem 5.6).
    pub coverage4: bool,
    /// The scan order of the greedy rook placement of the star covers (a choice the paper
    /// leaves open, [`GreedyOrder`]); other algorithms ignore it.
    pub greedy_order: GreedyOrder,
}

impl Options {
    /// Whether a run of an algorithm that produces `produced` is to compute `objective`:
    /// [`only`](Self::only) is empty or names it, or names a weighted objective the algorithm
    /// does not produce and `objective` carries ([`Objective::carriers`]).
    pub fn wants(&self, objective: Objective, produced: &[Objective]) -> bool {
        self.only.is_empty()
            || self.only.iter().any(|o| {
                *o == objective || (!produced.contains(o) && o.carriers().contains(&objective))
            })
    }
}

/// One result of an algorithm: closed walks for one objective (of pixels, or of the vertices
/// of a discrete instance).
#[derive(Clone, Debug)]
pub struct Output<C = CycleCover> {
    pub objective: Objective,
    pub cover: C,
}

/// What an algorithm returns: one output per objective it reports (a cycle-cover algorithm
/// reports the cycle cover and the merged tour), and its certificates (named integers such as
/// a strip cover size or a matching weight; never its own cost).
#[derive(Clone, Debug)]
pub struct Solution<C = CycleCover> {
    pub outputs: Vec<Output<C>>,
    pub certificates: BTreeMap<String, i64>,
}

impl<C> Default for Solution<C> {
    fn default() -> Self {
        Solution {
            outputs: Vec::new(),
            certificates: BTreeMap::new(),
        }
    }
}

/// How an algorithm runs on discrete instances (its `run` takes grid regions).
pub type DiscreteRun = fn(&Discrete, &Options) -> Result<Solution<DiscreteCover>>;

/// How an algorithm runs on orthogonal polygons with arbitrary coordinates: walks of the
/// cutter's centre with exact coordinates ([`crate::ortho::Tour`], one per output; a cycle
/// cover is a `Tour` with several cycles).
pub type OrthoRun = fn(&crate::ortho::Polygon, &Options) -> Result<Solution<crate::ortho::Tour>>;

/// A registered algorithm.
pub struct Algorithm {
    /// Stable name: the CLI's `--algo`, the `algorithm` column of results.
    pub name: &'static str,
    /// One line on what it computes.
    pub summary: &'static str,
    /// The objectives it reports, in output order.
    pub objectives: &'static [Objective],
    /// Its proven guarantees (possibly several objectives), each naming its theorem.
    pub guarantees: &'static [Guarantee],
    /// The theorems of [`theorems::THEOREMS`] its outputs are measured against in the claims
    /// table, and how faithfully it realizes each.
    pub claims: &'static [Claim],
    /// The preconditions [`precondition`](Self::precondition) checks, in a few words.
    pub requires: &'static str,
    /// Checks the theorem's preconditions; the error says which one fails.
    pub precondition: fn(&Region) -> Result<()>,
    pub run: fn(&Region, &Options) -> Result<Solution>,
    /// Its run on discrete instances, for the algorithms of discrete milling (they run on grid
    /// regions through [`Discrete::from_region`]); `None` for the grid-only ones.
    pub discrete: Option<DiscreteRun>,
    /// Its run on orthogonal polygons with arbitrary coordinates; `None` for the
    /// others.
    pub ortho: Option<OrthoRun>,
    /// Whether a suite family without an `algorithms` list runs it (and `hunt`'s best known
    /// walks and the exact solver's warm starts use it): false for `lp-lns`, whose MIPs would
    /// multiply the time of the large suites; name it in `algorithms`.
    pub by_default: bool,
}

impl Algorithm {
    /// Runs it on a grid region (precondition first) and recounts its output of `objective`
    /// with the core's one checker: the walk's own length, turns and coverage. This is what a
    /// doc example or a quick script needs; `mowmill::evaluate` also decides the guarantees.
    pub fn run_checked(
        &self,
        region: &Region,
        options: &Options,
        objective: Objective,
    ) -> Result<crate::checker::Report> {
        (self.precondition)(region)?;
        let solution = (self.run)(region, options)?;
        let out = solution
            .outputs
            .iter()
            .find(|o| o.objective == objective)
            .ok_or_else(|| {
                crate::error::Error::invalid(format!("{} gave no {objective} output", self.name))
            })?;
        Ok(crate::checker::check(region, &out.cover, objective.mode()))
    }

    /// Whether it reports `objective`: one of its [`objectives`](Self::objectives), or a
    /// weighted one it has a [carrier](Objective::carriers) for.
    pub fn reports(&self, objective: Objective) -> bool {
        self.objectives.contains(&objective)
            || objective
                .carriers()
                .iter()
                .any(|c| self.objectives.contains(c))
    }

    /// The theorems it claims for its outputs of `objective` whose condition holds on the
    /// instance (the ids a result row carries in its `theorems` column), in claim order.
    pub fn theorems_on(&self, objective: Objective, model: Model<'_>) -> Vec<&'static Theorem> {
        let mut list: Vec<&'static Theorem> = Vec::new();
        for c in self
            .claims
            .iter()
            .filter(|c| c.objectives.contains(&objective))
        {
            if c.theorem.when.applies_to(model) && !list.iter().any(|t| std::ptr::eq(*t, c.theorem))
            {
                list.push(c.theorem);
            }
        }
        list
    }

    /// The paper it comes from: that of its guarantees' and claims' theorems.
    pub fn paper(&self) -> Paper {
        self.guarantees
            .iter()
            .map(|g| g.theorem)
            .chain(self.claims.iter().map(|c| c.theorem))
            .map(|t| t.paper)
            .next()
            .expect("a registered algorithm has a guarantee or a claim")
    }
}

impl fmt::Debug for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Algorithm")
            .field("name", &self.name)
            .finish()
    }
}

/// Every registered algorithm. Add an entry here when a module lands.
pub static REGISTRY: &[Algorithm] = &[
    milling25::ALGORITHM,
    tsp65::ALGORITHM,
    holes1325::ALGORITHM,
    milling_two_opt::ALGORITHM,
    lawn::LAWN_MST,
    lawn::LAWN_CHRISTOFIDES,
    lawn::LAWN_TWO_OPT,
    lawn::LAWN_BOX,
    // Turn-cost paper.
    star_cover::ALGORITHM,
    strips_double::ALGORITHM,
    strips_matching::ALGORITHM,
    lp_lns::ALGORITHM,
    boundary_cc::ALGORITHM,
    thin::ALGORITHM_CC,
    thin::ALGORITHM_MERGE,
    thin_euler::ALGORITHM,
    // Discrete milling, Table 1's rows Discrete and Restricted-direction.
    crate::discrete::star_cover::ALGORITHM,
    // Orthogonal polygons with arbitrary coordinates, Table 1's row Orthogonal.
    crate::ortho::COROLLARY4,
    crate::ortho::STRIPS_CONTOUR,
    crate::ortho::STAR_CONTOUR,
];

/// The registered algorithm called `name`.
pub fn find(name: &str) -> Option<&'static Algorithm> {
    REGISTRY.iter().find(|a| a.name == name)
}

/// The registered names, for error messages.
pub fn names() -> Vec<&'static str> {
    REGISTRY.iter().map(|a| a.name).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guarantee_arithmetic_is_exact() {
        let g = Guarantee::new(
            Objective::Length,
            Bound::new(Quantity::Value, 6, 5, -4, Against::N),
            When::Always,
            &theorems::MILLING_THM_5,
            "Theorem 5",
        );
        // N = 9: (54 - 4) / 5 = 10.
        assert!(g.holds(10, 9));
        assert!(!g.holds(11, 9));
        assert_eq!(g.bound(9), 10);
        assert_eq!(g.to_string(), "length <= (6 N - 4)/5 (Theorem 5)");
        let h = Guarantee {
            bound: Bound::new(Quantity::Value, 5, 2, 0, Against::Opt),
            ..g
        };
        assert!(h.holds(25, 10) && !h.holds(26, 10));
        assert_eq!(h.to_string(), "length <= 5/2 OPT (Theorem 5)");
    }

    #[test]
    fn one_decision_from_what_is_known_of_opt() {
        use theorems::{Decision, Known};
        // value <= 3/2 OPT.
        let b = Bound::new(Quantity::Value, 3, 2, 0, Against::Opt);
        let known = |opt, lower, upper| Known { opt, lower, upper };
        // The optimum decides, whatever else is known.
        assert_eq!(
            b.decide(15, 0, known(Some(10), None, None)),
            Decision::Holds { x: Some(10) }
        );
        assert_eq!(
            b.decide(16, 0, known(Some(10), Some(11), Some(9))),
            Decision::Violated { x: 10, exact: true }
        );
        // A walk of value 9 proves OPT <= 9: 14 > 27/2 is a violation.
        assert_eq!(
            b.decide(14, 0, known(None, Some(6), Some(9))),
            Decision::Violated { x: 9, exact: false }
        );
        // A lower bound 6 proves 9 <= 3/2 · 6 <= 3/2 OPT; 10 is undecided.
        assert_eq!(
            b.decide(9, 0, known(None, Some(6), Some(9))),
            Decision::Holds { x: None }
        );
        assert_eq!(
            b.decide(10, 0, known(None, Some(6), Some(9))),
            Decision::Undecided
        );
        // Against N, N decides; an unresolved parameter factor decides nothing.
        let n = Bound::new(Quantity::Value, 6, 5, -4, Against::N);
        assert_eq!(
            n.decide(10, 9, Known::default()),
            Decision::Holds { x: Some(9) }
        );
        assert_eq!(
            n.decide(11, 9, Known::default()),
            Decision::Violated { x: 9, exact: true }
        );
        let g = Guarantee::scaled(
            Objective::Turns,
            Quantity::Value,
            Against::Opt,
            1,
            Param::Mu,
            0,
            When::Always,
            &theorems::TURNS_COR_5_1,
            "Corollary 5.1",
        );
        assert_eq!(
            g.bound.decide(1, 9, known(Some(5), None, None)),
            Decision::Undecided
        );
        // Lengths in units of 1/4: the constant and the factor against N scale, against OPT not.
        let u = n.in_units(4, true);
        assert_eq!((u.num, u.den, u.add), (24, 5, -16));
        let o = b.in_units(4, true);
        assert_eq!((o.num, o.den, o.add), (3, 2, 0));
        assert_eq!(b.in_units(4, false), b);
    }

    #[test]
    fn factors_in_instance_parameters_are_put_in_exactly() {
        // A 3x3 square: n = 9, |E| = 12 (delta = 24/9), mu = 4, rho = 2, d = 2.
        let r = Region::rectangle(3, 3);
        let g = Guarantee::scaled(
            Objective::Turns,
            Quantity::Value,
            Against::Opt,
            1,
            Param::RhoPlus2Delta,
            2,
            When::Always,
            &theorems::TURNS_COR_5_1,
            "Corollary 5.1",
        );
        assert_eq!(
            g.to_string(),
            "turns <= (rho + 2 delta + 2) OPT (Corollary 5.1)"
        );
        // Unresolved, nothing is decided.
        let m = Measured {
            value: 1,
            length: 1,
            max_coverage: 1,
        };
        assert_eq!(g.decide(&m, 9, Some(1), None), None);
        // rho + 2 delta + 2 = 2 + 48/9 + 2 = 84/9 = 28/3.
        let on = g.on_region(&r).unwrap();
        assert_eq!(
            (on.bound.num, on.bound.den, on.bound.add, on.bound.scale),
            (28, 3, 0, Scale::One)
        );
        assert!(on.holds(28, 3) && !on.holds(29, 3));
        assert_eq!(on.to_string(), "turns <= 28/3 OPT (Corollary 5.1)");
        // 5d + 2 on a grid (d = 2) is 12; a discrete instance without d is not a lattice.
        let t = Guarantee::scaled(
            Objective::Turns,
            Quantity::Value,
            Against::Opt,
            5,
            Param::D,
            2,
            When::Lattice,
            &theorems::TURNS_THM_5_2_TOUR,
            "Theorem 5.2",
        );
        assert_eq!(t.on_region(&r).unwrap().bound.num, 12);
        let path = Discrete::new(3, &[(0, 1), (1, 2)], &[(1, 0, 2)], None).unwrap();
        assert!(t.on(Model::Discrete(&path)).is_none());
        // Coverage <= mu against the constant 1.
        let c = Guarantee::scaled(
            Objective::Turns,
            Quantity::MaxCoverage,
            Against::One,
            1,
            Param::Mu,
            0,
            When::Always,
            &theorems::TURNS_COR_5_1_COVERAGE,
            "Corollary 5.1",
        );
        assert_eq!(c.to_string(), "max-coverage <= mu (Corollary 5.1)");
        let c = c.on(Model::Discrete(&path)).unwrap();
        assert_eq!(c.to_string(), "max-coverage <= 2 (Corollary 5.1)");
    }

    #[test]
    fn names_are_unique() {
        let mut names = names();
        let n = names.len();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), n);
    }

    /// `When::Biconnected` against its definition (N >= 3, connected, and connected after
    /// removing any one pixel), on every region of a 3 x 3 box and random ones of a 5 x 4 box.
    #[test]
    fn biconnected_matches_its_definition() {
        use crate::region::{Pixel, Region};
        let connected = |pixels: &[Pixel]| {
            Region::from_pixels(pixels.iter().copied())
                .is_ok_and(|r| crate::topology::components(&r).count == 1)
        };
        let by_definition = |r: &Region| {
            let pixels = r.pixels().to_vec();
            pixels.len() >= 3
                && connected(&pixels)
                && (0..pixels.len()).all(|k| {
                    let rest: Vec<Pixel> = (0..pixels.len())
                        .filter(|&j| j != k)
                        .map(|j| pixels[j])
                        .collect();
                    connected(&rest)
                })
        };
        let mut seed = 12345u64;
        let masks = (1u32..512).map(|m| (m, 3)).chain((0..3000).map(|_| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (((seed >> 33) as u32 & 0xFFFFF) | 1, 5)
        }));
        let mut both = [0; 2];
        for (mask, w) in masks {
            let pixels: Vec<Pixel> = (0..20)
                .filter(|&k| mask >> k & 1 == 1 && k < w * if w == 3 { 3 } else { 4 })
                .map(|k| Pixel::new(k % w, k / w))
                .collect();
            let Ok(r) = Region::from_pixels(pixels) else {
                continue;
            };
            let expect = by_definition(&r);
            assert_eq!(When::Biconnected.applies(&r), expect, "\n{}", r.to_ascii());
            both[usize::from(expect)] += 1;
        }
        assert!(both[0] > 100 && both[1] >= 15, "{both:?}");
    }
}
