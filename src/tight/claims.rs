//! The claims table (`mowmill claims [--from DIR]`, also written by `mowmill tight`): one row
//! per theorem of the two papers, with the claimed bound, which registered algorithm realizes
//! it and how faithfully, the instances of a results directory that exercise it, how many of
//! them decide it, the largest N decided and the families, the largest measured ratio, the
//! tight family's value, and a verdict.
//!
//! Nothing here lists theorems or algorithms: the rows are the entries of
//! [`THEOREMS`](crate::algorithms::theorems::THEOREMS) in order, each with the registered
//! algorithms whose `claims` name it ([`REGISTRY`](crate::algorithms::REGISTRY)).
//!
//! # Verdicts
//! - `holds`: decided on `decided` instances, none violated.
//! - `tight reproduced`: holds, and the tight family meets every claimed value.
//! - `violated`: some row breaks the paper's bound (computed here from the integer columns, not
//!   from the row's registered-guarantee column) or an output was invalid. The `implementation`
//!   column says whether the violating algorithm is exactly the paper's (`paper`: the paper is
//!   contradicted) or our reading of its proof (`reading`: a finding about our reading, never
//!   printed as the paper being contradicted). The violating instances are listed in
//!   `findings` and saved by `mowmill claims --findings DIR` with their tours and figures.
//! - `not implemented`: nothing realizes the claim: the theorem is declared
//!   [`Realized::Not`](crate::algorithms::theorems::Realized::Not), or no registered algorithm
//!   claims it.
//! - `untested`: implemented, but no row decides it.
//!
//! A claim against OPT is decided on a row when the exact optimum is known, or when the value is
//! within the bound of the row's proven lower bound (value ≤ f·LB ≤ f·OPT); otherwise it is
//! undecided, never counted as holding.

use super::evidence::{Attribution, Cost, Evidence};
use super::{Standing, TightRow};
use crate::algorithms::theorems::{
    Bound, Implementation, Measure, Paper, Realized, THEOREMS, Theorem, TightBy,
};
use crate::algorithms::{Against, Algorithm, Objective, Quantity, REGISTRY, When};
use crate::error::{Error, Result};
use crate::harness::rows::{EXACT, Row};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

/// One claim of the table: a declared theorem and the registered algorithms claiming it.
struct Claim<'r> {
    theorem: &'static Theorem,
    /// The (algorithm, objective) pairs whose rows exercise it, in registry order, with how
    /// faithfully that algorithm realizes the theorem.
    rows: Vec<(&'r str, &'static str, Implementation)>,
    /// How faithfully it is realized; `Err(note)` when nothing realizes it.
    implementation: std::result::Result<Vec<Implementation>, String>,
}

/// The claim of `theorem` over `registry`: every algorithm whose claims name it.
fn claim<'r>(theorem: &'static Theorem, registry: &'r [Algorithm]) -> Claim<'r> {
    let mut rows = Vec::new();
    let mut implementations = Vec::new();
    for a in registry {
        for c in a.claims.iter().filter(|c| std::ptr::eq(c.theorem, theorem)) {
            rows.extend(
                c.objectives
                    .iter()
                    .map(|o| (a.name, o.name(), c.implementation)),
            );
            if !implementations.contains(&c.implementation) {
                implementations.push(c.implementation);
            }
        }
    }
    let implementation = match theorem.realized {
        Realized::Not(note) => Err(note.to_string()),
        Realized::Elsewhere(i) => Ok(vec![i]),
        Realized::ByAlgorithms if implementations.is_empty() => {
            Err("no registered algorithm claims it".to_string())
        }
        Realized::ByAlgorithms => Ok(implementations),
    };
    Claim {
        theorem,
        rows,
        implementation,
    }
}

/// The `implementation` column: `paper` when every claiming algorithm is the paper's, else
/// `reading: ` and the notes of our readings.
fn implementation_text(
    implementation: &std::result::Result<Vec<Implementation>, String>,
) -> String {
    match implementation {
        Err(note) => format!("none: {note}"),
        Ok(list) => {
            let notes: Vec<&str> = list
                .iter()
                .filter_map(|i| match i {
                    Implementation::Reading(note) => Some(*note),
                    Implementation::Paper => None,
                })
                .collect();
            if notes.is_empty() {
                "paper".to_string()
            } else {
                format!("reading: {}", notes.join("; "))
            }
        }
    }
}

/// One line of the claims table.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ClaimRow {
    pub paper: String,
    pub claim: String,
    pub statement: String,
    pub factor: String,
    pub algorithms: String,
    /// Distinct instances with a valid row exercising the claim.
    pub instances: usize,
    /// Of those, instances on which the claim could be decided.
    pub decided: usize,
    pub max_ratio: Option<f64>,
    /// What `max_ratio` divides by.
    pub ratio_of: String,
    /// Rows breaking the claim (or invalid outputs).
    pub violations: usize,
    pub tight_family: String,
    pub tight_value: String,
    /// `holds`, `tight reproduced`, `violated`, `not implemented` or `untested`.
    pub verdict: String,
    /// `paper`, `reading: ...` or `none: ...` (see the module docs).
    pub implementation: String,
    /// The largest N among decided instances.
    pub max_n_decided: Option<u64>,
    /// The families of the decided instances.
    pub families: String,
    /// Error rows of the claim's algorithms (failed runs; not counted as instances).
    pub errors: usize,
    /// Violating instances (algorithm:instance), at most [`FINDINGS_LISTED`].
    pub findings: String,
    /// The worst ratio to OPT that `mowmill hunt` found for the claim's algorithms and
    /// objectives (see [`add_hunts`]); empty where no hunt applies.
    pub worst_found_by_search: String,
    /// The witness of the verdict: the violating instance of the strongest attribution with the
    /// largest ratio (`algorithm objective instance`), empty when nothing is violated.
    pub witness: String,
    /// Why the verdict is what it is: the rule that decided it, the witness's numbers, whether
    /// mowmill's registered guarantee held there, whether the violation depends on a choice the
    /// paper leaves open; for a hold, how broad its evidence is.
    pub note: String,
    /// The largest value / best checked walk on rows without a proven optimum (a lower bound on
    /// the true ratio), with its instance.
    pub max_ratio_best: String,
    /// The structured families (the shapes proofs find hardest) among the decided instances' families.
    pub structured_families: String,
    /// The violating rows, for saving findings.
    #[serde(skip)]
    pub violating: Vec<(String, String, String)>,
    /// The violations with their evidence.
    #[serde(skip)]
    pub violations_detail: Vec<Violation>,
    /// The (algorithm, objective) pairs a hunt's worst ratio to OPT measures this claim on:
    /// only for claims of a factor on the objective's own value against OPT that hold on every
    /// region (a hunt does not keep
    /// a theorem's extra condition, such as "no cut vertices").
    #[serde(skip)]
    pub search_pairs: Vec<(String, String)>,
}

/// How many violating instances `findings` lists per claim.
pub const FINDINGS_LISTED: usize = 10;

/// How many decided instances a "holds" needs (fewer: "holds on few instances (n)").
pub const HOLDS_MIN_DECIDED: usize = 1000;

/// CSV header of `claims.csv` (a contract for scripts: columns are only ever added at the end).
pub const CLAIM_COLUMNS: [&str; 23] = [
    "paper",
    "claim",
    "statement",
    "factor",
    "algorithms",
    "instances",
    "decided",
    "max_ratio",
    "ratio_of",
    "violations",
    "tight_family",
    "tight_value",
    "verdict",
    "implementation",
    "max_n_decided",
    "families",
    "errors",
    "findings",
    "worst_found_by_search",
    "witness",
    "note",
    "max_ratio_best",
    "structured_families",
];

/// One violating row: who, where, the numbers, and how it is attributed.
#[derive(Clone, Debug)]
pub struct Violation {
    pub algorithm: String,
    pub objective: String,
    pub instance: String,
    pub family: String,
    pub n: u64,
    pub attribution: Attribution,
    /// The evidence in words: the value, the bound and what the bound was computed from.
    pub detail: String,
    /// value / (what the bound multiplies), for ranking witnesses; 0 where not a ratio.
    pub ratio: f64,
    /// The row's registered-guarantee verdict (`within_guarantee`): `Some(true)` when mowmill's
    /// own proven bound held on the row while the paper's was broken.
    pub registered_held: Option<bool>,
    /// The row's registered guarantees (its `guarantee` column).
    pub guarantee: String,
    /// The bound as broken on the row (resolved to constants) and what it multiplies (OPT, U,
    /// N or 1), for re-deciding it under other choices of the algorithm; `None` for the
    /// relative measures (merges, coverage rewrites).
    pub bound: Option<(Bound, u64)>,
}

/// What the rows say about one claim.
#[derive(Default)]
struct Measured<'a> {
    instances: BTreeSet<&'a str>,
    decided: BTreeMap<&'a str, (u64, &'a str)>,
    max_ratio: Option<f64>,
    /// The largest value / lower bound on rows where OPT is unknown (reported only when no row
    /// has a proven optimum).
    max_ratio_lb: Option<f64>,
    /// The largest value / best checked walk on rows without a proven optimum (a lower bound on
    /// the true ratio).
    max_ratio_best: Option<(f64, &'a str)>,
    ratio_of: String,
    violations: Vec<Violation>,
    errors: usize,
}

impl<'a> Measured<'a> {
    fn bump(&mut self, x: f64) {
        self.max_ratio = Some(self.max_ratio.map_or(x, |m| m.max(x)));
    }

    fn bump_best(&mut self, x: f64, instance: &'a str) {
        if self.max_ratio_best.is_none_or(|(m, _)| x > m) {
            self.max_ratio_best = Some((x, instance));
        }
    }

    fn decide(&mut self, r: &'a Row) {
        self.decided
            .insert(r.instance.as_str(), (r.n, r.family.as_str()));
    }

    fn violate(&mut self, r: &Row, attribution: Attribution, detail: String, ratio: f64) {
        self.violations.push(Violation {
            algorithm: r.algorithm.clone(),
            objective: r.objective.clone(),
            instance: r.instance.clone(),
            family: r.family.clone(),
            n: r.n,
            attribution,
            detail,
            ratio,
            registered_held: r.within_guarantee,
            guarantee: r.guarantee.clone(),
            bound: None,
        });
    }
}

/// The algorithm's name without its option suffix: `strips-matching[coverage4]` →
/// `strips-matching`.
fn base_name(algorithm: &str) -> &str {
    algorithm.split('[').next().unwrap_or(algorithm)
}

/// `(num · x + add) / den` as text, with the factor's own numbers.
fn bound_text(b: &Bound, x: u64) -> String {
    let v = (b.num as f64 * x as f64 + b.add as f64) / b.den as f64;
    format!("{v:.2}")
}

fn measure<'a>(claim: &Claim, rows: &'a [Row], ev: &Evidence) -> Measured<'a> {
    let theorem = claim.theorem;
    let mut m = Measured::default();
    let applies = |r: &Row| {
        theorem.when == When::Always
            // A lattice instance: the row carries its number of directions d.
            || (theorem.when == When::Lattice && r.d.is_some())
            || (theorem.when == When::NonTrivial && r.n >= 2)
            // A simple polygon: a grid region or orthogonal polygon without holes.
            || (theorem.when == When::Simple
                && r.holes == 0
                && matches!(r.model.as_str(), "" | "grid" | "ortho"))
            || crate::algorithms::find(&r.algorithm).is_some_and(|a| {
                a.guarantees
                    .iter()
                    .filter(|g| g.when == theorem.when)
                    .any(|g| r.guarantee.contains(&g.to_string()))
            })
    };
    let coverage4 = matches!(
        theorem.measure,
        Measure::Coverage4SameTurns | Measure::Coverage4LengthCoverage
    );
    // The claim's (algorithm, objective) pair of a row and its implementation. Rows of
    // `--coverage4` runs (named `NAME[coverage4]`) belong to the Theorem 5.6 measures only.
    let implementation_of = |r: &Row| -> Option<Implementation> {
        let name = if coverage4 {
            if r.coverage4 != Some(true) {
                return None;
            }
            base_name(&r.algorithm)
        } else {
            r.algorithm.as_str()
        };
        claim
            .rows
            .iter()
            .find(|(a, o, _)| name == *a && r.objective == *o)
            .map(|(_, _, i)| *i)
            .filter(|_| applies(r))
    };
    let of_claim = |r: &Row| implementation_of(r).is_some();
    m.errors = rows
        .iter()
        .filter(|r| !r.error.is_empty() && r.valid != Some(false) && of_claim(r))
        .count();
    let picked: Vec<&Row> = rows
        .iter()
        .filter(|r| r.error.is_empty() || r.valid == Some(false))
        .filter(|r| {
            if theorem.measure == Measure::StripBound {
                r.lb_source.contains("strip cover") && r.algorithm != EXACT
            } else {
                of_claim(r)
            }
        })
        .collect();
    // Exact optima of the instances, per exact objective (for bounds on another quantity).
    let exact_opt: BTreeMap<(&str, &str), u64> = rows
        .iter()
        .filter(|r| r.algorithm == EXACT && r.error.is_empty())
        .filter_map(|r| Some(((r.instance.as_str(), r.objective.as_str()), r.opt?)))
        .collect();
    for r in &picked {
        if r.valid != Some(false) {
            m.instances.insert(r.instance.as_str());
        }
    }
    let invalid = |m: &mut Measured, r: &Row, i: Implementation| {
        m.violate(
            r,
            Attribution::of(i),
            "the checker found the output invalid".to_string(),
            0.0,
        );
    };
    match theorem.measure {
        Measure::Bound(b) => {
            m.ratio_of = match (b.against, b.quantity) {
                (Against::N, _) => "the bound in N (value / bound)".to_string(),
                (Against::One, _) => "the constant (value / bound)".to_string(),
                (Against::Opt, Quantity::Length) => "OPT of length (exact), else N".to_string(),
                (Against::Opt, _) => "OPT (instances with a proven optimum)".to_string(),
            };
            for r in &picked {
                let Some(implementation) = implementation_of(r) else {
                    continue;
                };
                if r.valid == Some(false) {
                    invalid(&mut m, r, implementation);
                    continue;
                }
                // A factor in the instance's parameters (Table 1's discrete rows) is put in from
                // the row's columns; a row without them, or off the bound's instances (d off
                // lattices), does not decide it.
                let Some(b) = r
                    .params()
                    .and_then(|p| b.on(&p))
                    .or_else(|| (b.scale == crate::algorithms::Scale::One).then_some(b))
                else {
                    continue;
                };
                let q = match b.quantity {
                    Quantity::Value => r.value,
                    Quantity::Length => r.length,
                    Quantity::MaxCoverage => r.max_coverage,
                };
                let Some(q) = q else { continue };
                // Lengths of orthogonal polygons are in units of 1/unit: so is the bound's
                // constant (and N).
                let on_length = b.quantity == Quantity::Length
                    || (b.quantity == Quantity::Value && r.objective == Objective::Length.name());
                let unit = r.unit.filter(|_| on_length).unwrap_or(1) as i64;
                let b = Bound {
                    add: b.add.saturating_mul(unit),
                    num: if b.against == Against::N {
                        b.num.saturating_mul(unit)
                    } else {
                        b.num
                    },
                    ..b
                };
                let ortho = r.model == "ortho";
                // The cost the bound's OPT is of: the row's objective, or length.
                let cost = match b.quantity {
                    Quantity::Length => Some(Cost::TourLength),
                    _ => Cost::of_objective(&r.objective),
                };
                // (OPT if proven, a proven lower bound, a valid upper bound: the best checked
                // walk). Against N or 1 the bound's x is known exactly.
                let (x, lower, upper) = match (b.against, b.quantity) {
                    (Against::N, _) => (Some(r.n), None, None),
                    (Against::One, _) => (Some(1), None, None),
                    // No exact optimum of length, and N is no bound in the units of an ortho row.
                    (Against::Opt, Quantity::Length) if ortho => (None, None, None),
                    (Against::Opt, Quantity::Length) => (
                        exact_opt
                            .get(&(r.instance.as_str(), Objective::Length.name()))
                            .copied(),
                        Some(r.n),
                        ev.best(r, Cost::TourLength).map(|w| w.value),
                    ),
                    (Against::Opt, _) => (
                        r.opt,
                        r.lower_bound.max(cost.and_then(|c| ev.lower(r, c))),
                        cost.and_then(|c| ev.best(r, c)).map(|w| w.value),
                    ),
                };
                match (x, lower, upper) {
                    (Some(x), _, _) => {
                        m.decide(r);
                        // Against OPT the ratio to OPT; against N or 1 the fraction of the bound.
                        let scale = match b.against {
                            Against::Opt => x as f64,
                            _ => (b.num as f64 * x as f64 + b.add as f64) / b.den as f64,
                        };
                        let ratio = if scale > 0.0 { q as f64 / scale } else { 0.0 };
                        if scale > 0.0 {
                            m.bump(ratio);
                        }
                        if !b.holds(q, x) {
                            // Against N: the statement itself fails when even the proven lower
                            // bound on every tour's length exceeds the bound.
                            let statement = b.against == Against::N
                                && b.quantity == Quantity::Value
                                && cost
                                    .and_then(|c| ev.lower(r, c))
                                    .is_some_and(|lb| !b.holds(lb, x));
                            let what = match b.against {
                                Against::Opt => format!(" with OPT = {x}"),
                                Against::N => format!(" with N = {}", r.n),
                                Against::One => String::new(),
                            };
                            let mut detail = format!(
                                "value {q} > {} ({}{what})",
                                bound_text(&b, x),
                                theorem.factor
                            );
                            let attribution = if statement {
                                let lb = cost.and_then(|c| ev.lower(r, c)).unwrap_or(0);
                                let _ = write!(
                                    detail,
                                    "; every walk has at least {lb} (the exact solver's proven lower bound)"
                                );
                                Attribution::Statement
                            } else {
                                Attribution::of(implementation)
                            };
                            m.violate(r, attribution, detail, ratio);
                            if let Some(v) = m.violations.last_mut() {
                                v.bound = Some((b, x));
                            }
                        }
                    }
                    (None, lower, upper) => {
                        if let Some(lb) = lower.filter(|&lb| lb > 0) {
                            let x = q as f64 / lb as f64;
                            m.max_ratio_lb = Some(m.max_ratio_lb.map_or(x, |y: f64| y.max(x)));
                        }
                        if let Some(u) = upper.filter(|&u| u > 0) {
                            m.bump_best(q as f64 / u as f64, r.instance.as_str());
                        }
                        if let Some(u) = upper
                            && !b.holds(q, u)
                        {
                            // OPT ≤ u, so q > f · u ≥ f · OPT: a proven violation.
                            m.decide(r);
                            let best = cost.and_then(|c| ev.best(r, c));
                            let from = best.map_or(String::new(), |w| {
                                format!(" {} {}", w.algorithm, w.objective)
                            });
                            let detail = format!(
                                "value {q} > {} ({} with OPT <= {u}, the best checked walk{from}; no proven optimum)",
                                bound_text(&b, u),
                                theorem.factor
                            );
                            m.violate(
                                r,
                                Attribution::of(implementation),
                                detail,
                                q as f64 / u.max(1) as f64,
                            );
                            if let Some(v) = m.violations.last_mut() {
                                v.bound = Some((b, u));
                            }
                        } else if lower.is_some_and(|lb| b.holds(q, lb)) {
                            m.decide(r);
                        }
                    }
                }
            }
        }
        Measure::StripBound => {
            m.ratio_of = "OPT (s / OPT, turn rows with a proven optimum)".to_string();
            for r in &picked {
                if let (Some(lb), Some(opt)) = (r.lower_bound, r.opt)
                    && opt > 0
                {
                    m.decide(r);
                    m.bump(lb as f64 / opt as f64);
                    if lb > opt {
                        let detail = format!("strip cover s = {lb} > OPT = {opt}");
                        m.violate(r, Attribution::Statement, detail, lb as f64 / opt as f64);
                    }
                }
            }
        }
        Measure::Merge | Measure::MergeHalf => {
            m.ratio_of = match theorem.measure {
                Measure::Merge => "t + 2c - 2 of the algorithm's cycle cover",
                _ => "3/2 t of the algorithm's cycle cover",
            }
            .to_string();
            let cc: BTreeMap<(&str, &str), &Row> = rows
                .iter()
                .filter(|r| r.objective == Objective::CcTurns.name() && r.error.is_empty())
                .map(|r| ((r.instance.as_str(), r.algorithm.as_str()), r))
                .collect();
            for r in &picked {
                let Some(implementation) = implementation_of(r) else {
                    continue;
                };
                if r.valid == Some(false) {
                    invalid(&mut m, r, implementation);
                    continue;
                }
                let Some(c) = cc.get(&(r.instance.as_str(), r.algorithm.as_str())) else {
                    continue;
                };
                if let (Some(tour), Some(t), Some(cycles)) = (r.turns, c.turns, c.cycles) {
                    // Both bounds doubled to stay in integers.
                    let (bound2, ok) = match theorem.measure {
                        Measure::Merge => {
                            let b = (t + 2 * cycles).saturating_sub(2);
                            (2 * b, tour <= b)
                        }
                        _ => (3 * t, 2 * tour <= 3 * t),
                    };
                    m.decide(r);
                    let ratio = if bound2 > 0 {
                        2.0 * tour as f64 / bound2 as f64
                    } else {
                        0.0
                    };
                    if bound2 > 0 {
                        m.bump(ratio);
                    }
                    if !ok {
                        // Every tour has at least the exact solver's proven lower bound: when
                        // that exceeds the bound, no merge of this cover (no tour at all) meets
                        // it.
                        let lb = ev.lower(r, Cost::TourTurns);
                        let mut detail = format!(
                            "tour turns {tour} > {} ({} of the cycle cover: t = {t}, c = {cycles})",
                            bound2 as f64 / 2.0,
                            theorem.factor
                        );
                        let attribution = match lb {
                            Some(lb) if 2 * lb > bound2 => {
                                let _ = write!(
                                    detail,
                                    "; every tour has at least {lb} turns (the exact solver's proven lower bound)"
                                );
                                Attribution::Statement
                            }
                            _ => Attribution::of(implementation),
                        };
                        m.violate(r, attribution, detail, ratio);
                    }
                }
            }
        }
        Measure::Coverage4SameTurns | Measure::Coverage4LengthCoverage => {
            m.ratio_of = match theorem.measure {
                Measure::Coverage4SameTurns => "turns with / without --coverage4",
                _ => "OPT of length (exact), else N; coverage against 4",
            }
            .to_string();
            // The same algorithm's row without --coverage4: same instance, objective, merge.
            let plain: BTreeMap<(&str, &str, &str, &str), &Row> = rows
                .iter()
                .filter(|r| r.coverage4 != Some(true) && r.error.is_empty())
                .map(|r| {
                    (
                        (
                            r.instance.as_str(),
                            base_name(&r.algorithm),
                            r.objective.as_str(),
                            r.merge.as_str(),
                        ),
                        r,
                    )
                })
                .collect();
            for r in &picked {
                let Some(implementation) = implementation_of(r) else {
                    continue;
                };
                if r.valid == Some(false) {
                    invalid(&mut m, r, implementation);
                    continue;
                }
                let (Some(turns), Some(cov), Some(len)) = (r.turns, r.max_coverage, r.length)
                else {
                    continue;
                };
                let attribution = Attribution::of(implementation);
                if theorem.measure == Measure::Coverage4SameTurns {
                    let key = (
                        r.instance.as_str(),
                        base_name(&r.algorithm),
                        r.objective.as_str(),
                        r.merge.as_str(),
                    );
                    let Some(before) = plain.get(&key).and_then(|p| p.turns) else {
                        continue;
                    };
                    m.decide(r);
                    if before > 0 {
                        m.bump(turns as f64 / before as f64);
                    }
                    // Fewer turns than before is no violation: the theorem promises no more.
                    if turns > before || cov > 4 {
                        let detail = format!(
                            "turns {turns} with --coverage4, {before} without; max coverage {cov}"
                        );
                        m.violate(r, attribution, detail, turns as f64 / before.max(1) as f64);
                    }
                    continue;
                }
                let opt = exact_opt
                    .get(&(r.instance.as_str(), Objective::Length.name()))
                    .copied();
                let upper = ev.best(r, Cost::TourLength).map(|w| w.value);
                let ratio_to = |x: u64| len as f64 / x.max(1) as f64;
                match (opt, upper) {
                    (Some(opt), _) => {
                        m.decide(r);
                        m.bump(ratio_to(opt));
                        if len > 4 * opt || cov > 4 {
                            let detail = format!(
                                "length {len} (4 OPT_length = {}), max coverage {cov}",
                                4 * opt
                            );
                            m.violate(r, attribution, detail, ratio_to(opt));
                        }
                    }
                    (None, upper) => {
                        if let Some(u) = upper {
                            m.bump_best(ratio_to(u), r.instance.as_str());
                        }
                        if cov > 4 || upper.is_some_and(|u| len > 4 * u) {
                            m.decide(r);
                            let detail = format!(
                                "length {len} (best checked tour {}), max coverage {cov}",
                                upper.map_or("-".into(), |u| u.to_string())
                            );
                            m.violate(r, attribution, detail, upper.map_or(0.0, ratio_to));
                        } else if len <= 4 * r.n {
                            // N ≤ OPT_length: within 4 N is within 4 OPT.
                            m.decide(r);
                        }
                    }
                }
            }
        }
        Measure::TightOnly => m.ratio_of = "(tight families only)".to_string(),
        Measure::Nothing => m.ratio_of = "(not implemented)".to_string(),
    }
    if m.max_ratio.is_none() && m.max_ratio_lb.is_some() {
        m.max_ratio = m.max_ratio_lb;
        m.ratio_of = "the lower bound (no proven optimum; over-estimates)".to_string();
    }
    m
}

/// The tight family's value for a claim: (text, reproduced, contradicted). Reproduced means
/// every claimed (not merely reported) value of the family was met.
fn tight_value(family: &str, quantities: &[&str], tight: &[TightRow]) -> (String, bool, bool) {
    let mut parts = Vec::new();
    let (mut reproduced, mut contradicted, mut missed) = (true, false, 0);
    let mut any = false; // a claimed (not reported) quantity
    for q in quantities {
        let rows: Vec<&TightRow> = tight
            .iter()
            .filter(|r| r.family == family && r.quantity == *q)
            .collect();
        if rows.is_empty() {
            continue;
        }
        let last = rows
            .iter()
            .max_by_key(|r| (r.param, r.n))
            .expect("non-empty");
        match rows[0].standing {
            Standing::Report => {
                let max = rows
                    .iter()
                    .filter_map(|r| r.measured)
                    .fold(f64::NAN, f64::max);
                parts.push(format!(
                    "{q}: {:.4} at {} (max {max:.4}; {})",
                    last.measured.unwrap_or(f64::NAN),
                    last.member,
                    last.claim
                ));
            }
            _ => {
                any = true;
                let ok = rows
                    .iter()
                    .filter(|r| {
                        matches!(
                            r.verdict.as_str(),
                            "reproduced" | "upper bound met" | "holds"
                        )
                    })
                    .count();
                if ok < rows.len() {
                    reproduced = false;
                }
                if rows.iter().any(|r| r.verdict == "contradicted") {
                    contradicted = true;
                }
                missed += rows.iter().filter(|r| r.verdict == "not reached").count();
                parts.push(format!("{q}: {ok}/{} members as claimed", rows.len()));
            }
        }
    }
    if missed > 0 {
        parts.push(format!(
            "our construction did not reach the claim on {missed} member(s)"
        ));
    }
    (parts.join("; "), any && reproduced, contradicted)
}

/// The claims table from result rows and (optionally) a tight run's rows.
pub fn table(rows: &[Row], tight: &[TightRow]) -> Vec<ClaimRow> {
    let mut table = table_of(THEOREMS, REGISTRY, rows, tight);
    cross_reference(&mut table);
    table.extend(outside_claims(rows));
    table
}

/// Adds to each violated claim's note the other claims its witness (same algorithm and
/// instance) violates: a tour claim "violated by our reading" whose cycle cover already breaks
/// a claim of the paper's algorithm says so.
fn cross_reference(table: &mut [ClaimRow]) {
    let mut by_witness: BTreeMap<(String, String), Vec<(String, String)>> = BTreeMap::new();
    for c in table.iter() {
        for v in &c.violations_detail {
            let list = by_witness
                .entry((v.algorithm.clone(), v.instance.clone()))
                .or_default();
            let entry = (c.claim.clone(), v.attribution.verdict().to_string());
            if !list.contains(&entry) {
                list.push(entry);
            }
        }
    }
    for c in table.iter_mut() {
        let Some(w) = c
            .violations_detail
            .iter()
            .find(|v| format!("{} {} {}", v.algorithm, v.objective, v.instance) == c.witness)
        else {
            continue;
        };
        let others: Vec<String> = by_witness
            .get(&(w.algorithm.clone(), w.instance.clone()))
            .into_iter()
            .flatten()
            .filter(|(claim, _)| *claim != c.claim)
            .map(|(claim, verdict)| format!("{claim} ({verdict})"))
            .collect();
        if !others.is_empty() {
            let _ = write!(
                c.note,
                " The same algorithm ({}) on {} also violates: {}.",
                w.algorithm,
                w.instance,
                others.join(", ")
            );
        }
    }
}

/// The marker the harness writes into the `guarantee` column of an outside algorithm's rows
/// (see [`crate::outside`]).
const OUTSIDE_MARK: &str = "claimed in the config of ";

/// One row per claim a config made for an outside algorithm, decided from the rows' own
/// verdicts (`within_guarantee`, computed by the evaluation pipeline against the proven optimum
/// or a lower bound).
fn outside_claims(rows: &[Row]) -> Vec<ClaimRow> {
    let mut by_claim: BTreeMap<(String, String), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        if r.guarantee.contains(OUTSIDE_MARK) {
            by_claim
                .entry((r.algorithm.clone(), r.guarantee.clone()))
                .or_default()
                .push(r);
        }
    }
    by_claim
        .into_iter()
        .map(|((algorithm, statement), rs)| {
            let valid: Vec<&&Row> = rs.iter().filter(|r| r.valid == Some(true)).collect();
            let decided: Vec<&&Row> = valid
                .iter()
                .filter(|r| r.within_guarantee.is_some())
                .copied()
                .collect();
            let violating: Vec<&&Row> = rs
                .iter()
                .filter(|r| r.within_guarantee == Some(false) || r.valid == Some(false))
                .collect();
            let verdict = if !violating.is_empty() {
                "violated"
            } else if !decided.is_empty() {
                "holds"
            } else {
                "untested"
            };
            let instances: BTreeSet<&str> = valid.iter().map(|r| r.instance.as_str()).collect();
            let families: BTreeSet<&str> = decided.iter().map(|r| r.family.as_str()).collect();
            let mut findings: Vec<String> = violating
                .iter()
                .map(|r| format!("{}:{}", r.algorithm, r.instance))
                .collect();
            findings.dedup();
            findings.truncate(FINDINGS_LISTED);
            ClaimRow {
                paper: Paper::Outside.title().to_string(),
                claim: format!("claim of {algorithm}"),
                statement: statement.clone(),
                factor: String::new(),
                algorithms: algorithm.clone(),
                instances: instances.len(),
                decided: decided
                    .iter()
                    .map(|r| &r.instance)
                    .collect::<BTreeSet<_>>()
                    .len(),
                max_ratio: decided
                    .iter()
                    .filter_map(|r| r.ratio_opt.or(r.ratio_lb).map(|x| x.0))
                    .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m| m.max(x)))),
                ratio_of: "OPT (else the lower bound)".into(),
                violations: violating.len(),
                tight_family: String::new(),
                tight_value: String::new(),
                verdict: verdict.into(),
                implementation: "outside".into(),
                max_n_decided: decided.iter().map(|r| r.n).max(),
                families: families.into_iter().collect::<Vec<_>>().join(" "),
                errors: rs
                    .iter()
                    .filter(|r| !r.error.is_empty() && r.valid.is_none())
                    .count(),
                findings: findings.join(" "),
                worst_found_by_search: String::new(),
                witness: violating
                    .first()
                    .map(|r| format!("{} {} {}", r.algorithm, r.objective, r.instance))
                    .unwrap_or_default(),
                note: String::new(),
                max_ratio_best: String::new(),
                structured_families: String::new(),
                violations_detail: Vec::new(),
                search_pairs: Vec::new(),
                violating: violating
                    .iter()
                    .map(|r| (r.algorithm.clone(), r.objective.clone(), r.instance.clone()))
                    .collect(),
            }
        })
        .collect()
}

/// The claims table of `theorems` as the algorithms of `registry` claim them: one row per
/// theorem, in order.
fn table_of(
    theorems: &[&'static Theorem],
    registry: &[Algorithm],
    rows: &[Row],
    tight: &[TightRow],
) -> Vec<ClaimRow> {
    let ev = Evidence::from_rows(rows);
    theorems
        .iter()
        .map(|&t| {
            let c = claim(t, registry);
            let m = measure(&c, rows, &ev);
            let (tight_family, (tv, tight_ok, tight_bad)) = match t.tight {
                Some(tf) => (
                    tf.family.to_string(),
                    tight_value(tf.family, tf.quantities, tight),
                ),
                None => (String::new(), (String::new(), false, false)),
            };
            let decided = m.decided.len();
            let families: BTreeSet<&str> = m.decided.values().map(|v| v.1).collect();
            let structured: Vec<&str> = families
                .iter()
                .copied()
                .filter(|f| crate::generate::is_structured(f))
                .collect();
            let strongest = m.violations.iter().map(|v| v.attribution).min();
            let witness = strongest.and_then(|a| {
                m.violations
                    .iter()
                    .filter(|v| v.attribution == a)
                    .max_by(|x, y| x.ratio.total_cmp(&y.ratio))
            });
            let broad = decided >= HOLDS_MIN_DECIDED && !structured.is_empty();
            let verdict = if c.implementation.is_err() {
                "not implemented".to_string()
            } else if let Some(a) = strongest {
                a.verdict().to_string()
            } else if tight_bad {
                "statement contradicted".to_string()
            } else if decided == 0 {
                "untested".to_string()
            } else if !broad {
                format!("holds on few instances ({decided})")
            } else if tight_ok {
                match t.tight.map(|tf| tf.by) {
                    Some(TightBy::Constructed) => "tight reproduced (constructed)".to_string(),
                    _ => "tight reproduced (by the registered algorithm)".to_string(),
                }
            } else {
                "holds".to_string()
            };
            let mut note = String::new();
            if let (Some(a), Some(w)) = (strongest, witness) {
                let _ = write!(
                    note,
                    "{}: {}. Witness {} ({} {}, family {}, N = {}): {}.",
                    a.verdict(),
                    a.rule(),
                    w.instance,
                    w.algorithm,
                    w.objective,
                    w.family,
                    w.n,
                    w.detail
                );
                if w.registered_held == Some(true) {
                    let _ = write!(
                        note,
                        " mowmill's registered (proven) guarantee held on this row ({}): only the paper's form of the bound fails.",
                        w.guarantee
                    );
                }
                let mut by: BTreeMap<Attribution, usize> = BTreeMap::new();
                for v in &m.violations {
                    *by.entry(v.attribution).or_default() += 1;
                }
                let counts: Vec<String> = by
                    .iter()
                    .map(|(a, k)| format!("{k} {}", a.verdict()))
                    .collect();
                let _ = write!(note, " Violating rows: {}.", counts.join(", "));
            } else if tight_bad {
                note.push_str("the tight family contradicts a claimed value (tight.csv).");
            } else if decided > 0 && !broad {
                let _ = write!(
                    note,
                    "decided on {decided} instances{}{}",
                    if decided < HOLDS_MIN_DECIDED {
                        format!(" (a hold needs {HOLDS_MIN_DECIDED})")
                    } else {
                        String::new()
                    },
                    if structured.is_empty() {
                        "; no structured family among them"
                    } else {
                        ""
                    }
                );
                note.push('.');
            }
            if tight_ok && t.tight.map(|tf| tf.by) == Some(TightBy::Constructed) {
                note.push_str(
                    " The tight value is reproduced by a construction of mowmill's (tight.csv, column how), not by the registered algorithm.",
                );
            }
            let mut algos: Vec<&str> = c.rows.iter().map(|r| r.0).collect();
            algos.dedup();
            let mut findings: Vec<String> = m
                .violations
                .iter()
                .map(|v| format!("{}:{}", v.algorithm, v.instance))
                .collect();
            findings.dedup();
            findings.truncate(FINDINGS_LISTED);
            ClaimRow {
                paper: t.paper.title().to_string(),
                claim: t.id.to_string(),
                statement: t.statement.to_string(),
                factor: t.factor.to_string(),
                algorithms: algos.join(" "),
                instances: m.instances.len(),
                decided,
                max_ratio: m.max_ratio,
                ratio_of: m.ratio_of,
                violations: m.violations.len(),
                tight_family,
                tight_value: tv,
                verdict,
                implementation: implementation_text(&c.implementation),
                max_n_decided: m.decided.values().map(|v| v.0).max(),
                families: families.iter().copied().collect::<Vec<_>>().join(" "),
                errors: m.errors,
                findings: findings.join(" "),
                violating: m
                    .violations
                    .iter()
                    .map(|v| (v.algorithm.clone(), v.objective.clone(), v.instance.clone()))
                    .collect(),
                witness: witness
                    .map(|w| format!("{} {} {}", w.algorithm, w.objective, w.instance))
                    .unwrap_or_default(),
                note: note.trim().to_string(),
                max_ratio_best: m
                    .max_ratio_best
                    .map(|(x, i)| format!("{x:.3} ({i})"))
                    .unwrap_or_default(),
                structured_families: structured.join(" "),
                violations_detail: m.violations,
                worst_found_by_search: String::new(),
                search_pairs: match t.measure {
                    Measure::Bound(b)
                        if b.against == Against::Opt
                            && b.quantity == Quantity::Value
                            && t.when == When::Always =>
                    {
                        c.rows
                            .iter()
                            .map(|(a, o, _)| (a.to_string(), o.to_string()))
                            .collect()
                    }
                    _ => Vec::new(),
                },
            }
        })
        .collect()
}

/// Whether a claim is violated (any attribution).
pub fn is_violated(c: &ClaimRow) -> bool {
    matches!(
        c.verdict.as_str(),
        "statement contradicted"
            | "paper's algorithm contradicted"
            | "violated by our reading"
            | "violated"
    )
}

/// Whether a row's violation contradicts the paper (the violating algorithm is exactly the
/// paper's), as opposed to a finding about our reading.
pub fn contradicts_paper(c: &ClaimRow) -> bool {
    matches!(
        c.verdict.as_str(),
        "statement contradicted" | "paper's algorithm contradicted"
    )
}

/// Reads `tight.csv` back (the rows `mowmill tight` wrote).
pub fn read_tight(path: &Path) -> Result<Vec<TightRow>> {
    let mut reader = csv::Reader::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    let mut out = Vec::new();
    for (i, rec) in reader.records().enumerate() {
        let line = i + 2;
        let rec = rec.map_err(|e| Error::invalid(format!("{}:{line}: {e}", path.display())))?;
        let get = |k: usize| rec.get(k).unwrap_or("").to_string();
        let num = |k: usize| -> Result<Option<f64>> {
            let s = get(k);
            if s.is_empty() {
                return Ok(None);
            }
            s.parse().map(Some).map_err(|_| {
                Error::invalid(format!(
                    "{}:{line}: column {} should be a number, got {s:?}",
                    path.display(),
                    super::TIGHT_COLUMNS[k]
                ))
            })
        };
        let int = |k: usize| -> Result<u64> {
            get(k).parse().map_err(|_| {
                Error::invalid(format!(
                    "{}:{line}: column {} should be an integer, got {:?}",
                    path.display(),
                    super::TIGHT_COLUMNS[k],
                    get(k)
                ))
            })
        };
        let standing = match get(8).as_str() {
            "established" => Standing::Established,
            "example" => Standing::Example,
            "report" => Standing::Report,
            "construction" => Standing::Construction,
            other => {
                return Err(Error::invalid(format!(
                    "{}:{line}: column standing should be established, example or report, got {other:?}",
                    path.display()
                )));
            }
        };
        out.push(TightRow {
            family: get(0),
            member: get(1),
            param: int(2)?,
            n: int(3)?,
            quantity: get(4),
            claim: get(5),
            claimed: num(6)?,
            measured: num(7)?,
            standing,
            verdict: get(9),
            how: get(10),
            source: get(11),
        });
    }
    Ok(out)
}

/// One line of a hunt suite's `summary.csv` (`mowmill hunt --suite`), as far as the claims
/// table reads it.
#[derive(Clone, Debug, serde::Deserialize)]
pub struct HuntWorst {
    pub algorithm: String,
    pub objective: String,
    pub family: String,
    pub against: String,
    pub worst_ratio: Option<f64>,
    pub worst_n: Option<u64>,
}

/// Reads a hunt suite's `summary.csv`.
pub fn read_hunts(path: &Path) -> Result<Vec<HuntWorst>> {
    let mut r = csv::Reader::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    r.deserialize()
        .enumerate()
        .map(|(k, rec)| {
            rec.map_err(|e| {
                Error::parse(
                    &path.display().to_string(),
                    k + 2,
                    1,
                    format!("expected a hunt summary row: {e}"),
                )
            })
        })
        .collect()
}

/// Fills the column "worst found by search": for each claim against OPT that holds on every
/// region, the largest ratio to OPT a hunt found for one of its (algorithm, objective) pairs,
/// with the pair, the family and N. A hunt against the bound does not count (it over-estimates).
pub fn add_hunts(table: &mut [ClaimRow], hunts: &[HuntWorst]) {
    for c in table.iter_mut() {
        let worst = hunts
            .iter()
            .filter(|h| h.against == "opt")
            .filter(|h| {
                c.search_pairs
                    .iter()
                    .any(|(a, o)| *a == h.algorithm && *o == h.objective)
            })
            .filter_map(|h| h.worst_ratio.map(|r| (r, h)))
            .max_by(|x, y| x.0.total_cmp(&y.0));
        if let Some((r, h)) = worst {
            c.worst_found_by_search = format!(
                "{r:.3} ({} {}, {}, N = {})",
                h.algorithm,
                h.objective,
                h.family,
                h.worst_n.map_or("-".into(), |n| n.to_string())
            );
        }
    }
}

/// Writes `claims.csv`.
pub fn write_csv(table: &[ClaimRow], path: &Path) -> Result<()> {
    let err = |e: csv::Error| Error::invalid(format!("{}: {e}", path.display()));
    let mut w = csv::Writer::from_path(path).map_err(err)?;
    w.write_record(CLAIM_COLUMNS).map_err(err)?;
    for c in table {
        w.write_record([
            c.paper.as_str(),
            &c.claim,
            &c.statement,
            &c.factor,
            &c.algorithms,
            &c.instances.to_string(),
            &c.decided.to_string(),
            &c.max_ratio.map(|x| format!("{x:.4}")).unwrap_or_default(),
            &c.ratio_of,
            &c.violations.to_string(),
            &c.tight_family,
            &c.tight_value,
            &c.verdict,
            &c.implementation,
            &c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            &c.families,
            &c.errors.to_string(),
            &c.findings,
            &c.worst_found_by_search,
            &c.witness,
            &c.note,
            &c.max_ratio_best,
            &c.structured_families,
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

/// The claims table as Markdown: the table, then a note per claim that is violated, holds on
/// few instances, or is realized by our reading.
pub fn markdown(table: &[ClaimRow], source: &str) -> String {
    let mut out = format!(
        "Claims against {source}. Generated by `mowmill claims` from the rows alone (docs/claims.md, \
         \"Verdicts\", states every rule): instances = distinct instances with a valid row, \
         decided = those where the claim could be checked (a proven optimum, a proven lower \
         bound that the value meets, or a best checked walk the value exceeds), max N, families \
         and structured families of the decided ones. A hold needs {HOLDS_MIN_DECIDED} decided \
         instances including a structured family; a violation is attributed to the statement \
         (no walk meets the bound), the paper's algorithm (`impl.` paper) or our reading \
         (`impl.` reading).\n\n"
    );
    out.push_str("| paper | claim | factor | algorithms | impl. | instances | decided | max N | families | structured | max ratio (of) | worst vs best walk | worst found by search | violations | witness | tight family | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for c in table {
        let paper: &str = match Paper::ALL.into_iter().find(|p| p.title() == c.paper) {
            Some(p) => p.short(),
            None => &c.paper,
        };
        let ratio = c
            .max_ratio
            .map(|x| format!("{x:.3} ({})", c.ratio_of))
            .unwrap_or_else(|| c.ratio_of.clone());
        let tight = if c.tight_value.is_empty() {
            String::new()
        } else {
            format!("{}: {}", c.tight_family, c.tight_value)
        };
        let implementation = c.implementation.split(':').next().unwrap_or("");
        let _ = writeln!(
            out,
            "| {paper} | {} | {} | {} | {implementation} | {} | {} | {} | {} | {} | {ratio} | {} | {} | {} | {} | {tight} | **{}** |",
            c.claim,
            c.factor,
            c.algorithms,
            c.instances,
            c.decided,
            c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            c.families,
            c.structured_families,
            c.max_ratio_best,
            c.worst_found_by_search,
            c.violations,
            c.witness,
            c.verdict,
        );
    }
    let notes: Vec<&ClaimRow> = table
        .iter()
        .filter(|c| {
            c.implementation != "paper"
                || !c.note.is_empty()
                || !c.findings.is_empty()
                || c.errors > 0
        })
        .collect();
    if !notes.is_empty() {
        out.push_str("\nNotes:\n\n");
        for c in notes {
            let _ = write!(out, "- **{}**: ", c.claim);
            if !c.note.is_empty() {
                let _ = write!(out, "{} ", c.note);
            }
            let _ = write!(out, "Implementation {}", c.implementation);
            if c.errors > 0 {
                let _ = write!(out, "; {} error rows", c.errors);
            }
            if !c.findings.is_empty() {
                let _ = write!(out, "; violating: {}", c.findings);
            }
            out.push('\n');
        }
    }
    out
}

/// README's findings: one line per violated claim (what mowmill found against the papers),
/// with its attribution, witness and numbers; generated from the table, never written by hand.
pub fn findings_markdown(table: &[ClaimRow]) -> String {
    let mut out = String::new();
    for c in table.iter().filter(|c| is_violated(c)) {
        let paper = Paper::ALL
            .into_iter()
            .find(|p| p.title() == c.paper)
            .map_or(c.paper.as_str(), |p| p.short());
        let witness = c
            .violations_detail
            .iter()
            .find(|v| format!("{} {} {}", v.algorithm, v.objective, v.instance) == c.witness);
        let _ = write!(
            out,
            "- **{} ({paper} paper, {}): {}.**",
            c.claim, c.factor, c.verdict
        );
        if let Some(w) = witness {
            let _ = write!(
                out,
                " `{}` ({} {}, family {}, N = {}): {}.",
                w.instance, w.algorithm, w.objective, w.family, w.n, w.detail
            );
            if w.registered_held == Some(true) {
                out.push_str(" mowmill's own proven bound held there.");
            }
        }
        let _ = write!(out, " {} violating rows.", c.violations);
        // Whether the violation depends on a choice the paper leaves open (add_choice_evidence).
        for key in [
            "Greedy order on the witness:",
            "Violated by every order of the greedy",
        ] {
            if let Some(k) = c.note.find(key) {
                let sentence = c.note[k..].split(". ").next().unwrap_or_default();
                let _ = write!(out, " {}.", sentence.trim_end_matches('.'));
            }
        }
        out.push('\n');
    }
    if out.is_empty() {
        out.push_str("- No claim is violated in the committed table.\n");
    }
    out
}

/// Saves the violating instances of every violated claim into `dir`: for each (at most
/// [`FINDINGS_LISTED`] per claim) the instance file copied from `from/instances/`, the
/// algorithm's output re-run on it (algorithms are deterministic) as tour JSON, its figure
/// (PNG) and a note naming the claim, the values and whether the violating algorithm is the
/// paper's or our reading. Returns the files written.
/// The results directories a claims table is computed from. With more than one, each row's
/// instance is named `RUN/INSTANCE` (RUN the directory's name), so that equal instance names of
/// different runs (the same family, parameters and index under another master seed) never meet.
pub struct Sources {
    dirs: Vec<(String, std::path::PathBuf)>,
}

impl Sources {
    /// # Errors
    /// [`Error::Invalid`] when no directory is given or two have the same name.
    pub fn new(dirs: &[std::path::PathBuf]) -> Result<Sources> {
        if dirs.is_empty() {
            return Err(Error::invalid("claims: no results directory (--from DIR)"));
        }
        let named: Vec<(String, std::path::PathBuf)> = dirs
            .iter()
            .map(|d| {
                let name = d
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_else(|| d.display().to_string());
                (name, d.clone())
            })
            .collect();
        let mut names: Vec<&str> = named.iter().map(|(n, _)| n.as_str()).collect();
        names.sort_unstable();
        if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
            return Err(Error::invalid(format!(
                "claims: two results directories are both named {}: their instances could not be told apart",
                w[0]
            )));
        }
        Ok(Sources { dirs: named })
    }

    /// Every row of every directory's `results.csv`, instances prefixed with `RUN/` when there
    /// are several.
    pub fn read_rows(&self) -> Result<Vec<Row>> {
        let mut rows = Vec::new();
        for (name, dir) in &self.dirs {
            let mut read = crate::harness::rows::read_results(&dir.join("results.csv"))?;
            // An inconsistent row (below its proven bound, or a value that is not its own
            // count) is an invalid result: it is evidence of nothing and breaks its claims.
            for r in &mut read {
                r.mark_inconsistent();
            }
            if self.dirs.len() > 1 {
                for r in &mut read {
                    r.instance = format!("{name}/{}", r.instance);
                }
            }
            rows.extend(read);
        }
        Ok(rows)
    }

    /// The directories as the table's source line names them.
    pub fn describe(&self) -> String {
        self.dirs
            .iter()
            .map(|(_, d)| d.display().to_string())
            .collect::<Vec<_>>()
            .join(" + ")
    }

    /// The directory holding an instance of [`Sources::read_rows`], and its name there.
    fn locate<'a>(&'a self, instance: &'a str) -> Option<(&'a Path, &'a str)> {
        if self.dirs.len() == 1 {
            return Some((&self.dirs[0].1, instance));
        }
        let (run, name) = instance.split_once('/')?;
        self.dirs
            .iter()
            .find(|(n, _)| n == run)
            .map(|(_, d)| (d.as_path(), name))
    }
}

/// Adds to each violated claim whose witness is a star cover (the greedy order of its rooks
/// is a choice the paper leaves open, Lemma 4.5) whether the violation depends on that order
/// or survives every one: [`crate::discrete::choices::order_evidence`] re-runs the star cover
/// on the witness over every rook set (exhaustive up to its cap, else sampled orders) and
/// re-decides the same bound. Merge orders are not enumerated: a violation of Theorem 4.2 that
/// survives every merge order is the statement contradicted (a lower bound on every tour).
pub fn add_choice_evidence(table: &mut [ClaimRow], sources: &Sources) {
    use crate::discrete::choices::{ChoiceValue, order_evidence};
    for c in table.iter_mut().filter(|c| is_violated(c)) {
        // The witness first, then the other violating instances (at most FINDINGS_LISTED).
        let mut rows: Vec<Violation> = c
            .violations_detail
            .iter()
            .filter(|v| matches!(v.algorithm.as_str(), "star-cover" | "discrete-star-cover"))
            .cloned()
            .collect();
        rows.sort_by_key(|v| {
            format!("{} {} {}", v.algorithm, v.objective, v.instance) != c.witness
        });
        rows.dedup_by(|a, b| a.instance == b.instance && a.objective == b.objective);
        rows.truncate(FINDINGS_LISTED);
        let mut every_order = Vec::new();
        for (k, w) in rows.iter().enumerate() {
            let Some((from, name)) = sources.locate(&w.instance) else {
                continue;
            };
            let Some(inst) = load_as_discrete(from, name) else {
                continue;
            };
            let evidence = match (w.bound, w.objective.as_str()) {
                (Some((b, x)), "cc-turns") => {
                    order_evidence(&w.algorithm, &inst, ChoiceValue::CcTurns, |v| {
                        !b.holds(v, x)
                    })
                }
                (Some((b, x)), "turns") => {
                    order_evidence(&w.algorithm, &inst, ChoiceValue::TourTurns, |v| {
                        !b.holds(v, x)
                    })
                }
                _ => continue,
            };
            match evidence {
                Ok(e) => {
                    if k == 0 {
                        let _ = write!(c.note, " Greedy order on the witness: {}.", e.summary());
                    }
                    if e.every_order_violates() {
                        every_order.push(format!("{} ({} rook sets)", w.instance, e.tried));
                    }
                }
                Err(e) if k == 0 => {
                    let _ = write!(c.note, " Greedy order: not evaluated ({e}).");
                }
                Err(_) => {}
            }
        }
        if !every_order.is_empty() {
            let _ = write!(
                c.note,
                " Violated by every order of the greedy choices (exhaustive) on: {}.",
                every_order.join(", ")
            );
        }
    }
}

/// The instance `name` of the results directory `from` as a discrete instance (a grid region
/// through [`crate::discrete::Discrete::from_region`]); `None` when not saved there.
fn load_as_discrete(from: &Path, name: &str) -> Option<crate::discrete::Discrete> {
    let dir = from.join("instances");
    for ext in ["dm", "vox", "hex"] {
        let p = dir.join(format!("{name}.{ext}"));
        if p.exists() {
            return crate::discrete::generate::read(&p).ok();
        }
    }
    let p = dir.join(format!("{name}.grid"));
    let inst = crate::instance::Instance::read(&p).ok()?;
    Some(crate::discrete::Discrete::from_region(&inst.region))
}

/// A claim's name in file names: lower-case letters and digits, anything else `-`.
fn claim_slug(claim: &str) -> String {
    claim
        .chars()
        .map(|ch| {
            if ch.is_ascii_alphanumeric() {
                ch.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}

/// [`save_findings`] for a discrete instance: the instance file, the algorithm's walk of the
/// objective (run again on the instance, recounted by the discrete checker), a note and, where
/// the instance has coordinates, an SVG.
fn save_discrete_finding(
    c: &ClaimRow,
    algo: &str,
    objective: &str,
    instance: &str,
    src: &Path,
    dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
    use crate::discrete::{check, draw};
    let mut written = Vec::new();
    let stem = format!("{}-{algo}-{instance}", claim_slug(&c.claim));
    let ext = src.extension().and_then(|e| e.to_str()).unwrap_or("dm");
    let copy = dir.join(format!("{stem}.{ext}"));
    std::fs::copy(src, &copy).map_err(|e| Error::io(&copy, e))?;
    written.push(copy);
    let inst = crate::discrete::generate::read(src)?;
    let mut note = format!(
        "# {} ({}) violated\n\nalgorithm: {algo}, objective: {objective}, instance: {instance}, n = {}\n\
         claim: {} ({})\nimplementation: {}\n",
        c.claim,
        c.paper,
        inst.len(),
        c.factor,
        c.statement,
        c.implementation
    );
    let run = crate::algorithms::find(algo).and_then(|a| a.discrete);
    if let Some(run) = run {
        match run(&inst, &crate::algorithms::Options::default()) {
            Ok(sol) => {
                if let Some(out) = sol.outputs.iter().find(|o| o.objective.name() == objective) {
                    let rep = check::check(&inst, &out.cover.cycles);
                    let walk = dir.join(format!("{stem}.tour.json"));
                    out.cover.write(&walk)?;
                    written.push(walk);
                    let _ = writeln!(
                        note,
                        "checked output: valid {}, length {}, turns {}, cycles {}, max coverage {}",
                        rep.valid, rep.length, rep.turns, rep.cycles, rep.max_coverage
                    );
                    let svg = dir.join(format!("{stem}.svg"));
                    let opts = crate::draw::DrawOptions {
                        title: Some(format!("{}: {algo} on {instance}", c.claim)),
                        caption: Some(draw::caption(&inst, Some(&out.cover.cycles))),
                        ..crate::draw::DrawOptions::default()
                    };
                    match draw::draw(&inst, Some(&out.cover.cycles), &svg, &opts) {
                        Ok(()) => written.push(svg),
                        Err(e) => {
                            let _ = writeln!(note, "not drawn: {e}");
                        }
                    }
                }
            }
            Err(e) => {
                let _ = writeln!(note, "the algorithm failed on it: {e}");
            }
        }
    }
    let md = dir.join(format!("{stem}.md"));
    std::fs::write(&md, note).map_err(|e| Error::io(&md, e))?;
    written.push(md);
    Ok(written)
}

pub fn save_findings(
    table: &[ClaimRow],
    sources: &Sources,
    dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
    use crate::algorithms::{self, Objective, Options};
    use crate::checker;
    let mut written = Vec::new();
    for c in table.iter().filter(|c| is_violated(c)) {
        let mut seen = BTreeSet::new();
        for (algo, objective, instance) in &c.violating {
            if !seen.insert((algo, instance)) || seen.len() > FINDINGS_LISTED {
                continue;
            }
            std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
            let Some((from, instance)) = sources.locate(instance) else {
                continue;
            };
            if let Some(src) = ["dm", "vox", "hex"]
                .iter()
                .map(|ext| from.join("instances").join(format!("{instance}.{ext}")))
                .find(|p| p.exists())
            {
                written.extend(save_discrete_finding(
                    c, algo, objective, instance, &src, dir,
                )?);
                continue;
            }
            let Some(src) = ["grid", "wkt"]
                .iter()
                .map(|ext| from.join("instances").join(format!("{instance}.{ext}")))
                .find(|p| p.exists())
            else {
                eprintln!(
                    "claims: {}: instance {instance} (a violation of {}) is not saved under instances/; \
                     no finding written for it",
                    from.display(),
                    c.claim
                );
                continue;
            };
            let stem = format!("{}-{algo}-{instance}", claim_slug(&c.claim));
            let ext = src.extension().and_then(|e| e.to_str()).unwrap_or("grid");
            let copy = dir.join(format!("{stem}.{ext}"));
            std::fs::copy(&src, &copy).map_err(|e| Error::io(&copy, e))?;
            written.push(copy);
            let inst = crate::instance::Instance::read(&src)?;
            let mut note = format!(
                "# {} ({}) violated\n\nalgorithm: {algo}, objective: {objective}, instance: {instance}, N = {}\n\
                 claim: {} ({})\nimplementation: {}\n",
                c.claim,
                c.paper,
                inst.region.len(),
                c.factor,
                c.statement,
                c.implementation
            );
            let Some(a) = algorithms::find(algo) else {
                continue;
            };
            match (a.run)(&inst.region, &Options::default()) {
                Ok(sol) => {
                    if let Some(out) = sol.outputs.iter().find(|o| o.objective.name() == objective)
                    {
                        let rep = checker::check(&inst.region, &out.cover, out.objective.mode());
                        let tour = dir.join(format!("{stem}.tour.json"));
                        out.cover.write(&tour)?;
                        written.push(tour);
                        let _ = writeln!(
                            note,
                            "checked output: valid {}, length {}, turns {}, cycles {}, max coverage {}",
                            rep.valid, rep.length, rep.turns, rep.cycles, rep.max_coverage
                        );
                        if out.objective != Objective::LawnLength {
                            let png = dir.join(format!("{stem}.png"));
                            let opts = crate::draw::DrawOptions {
                                title: Some(format!("{}: {algo} on {instance}", c.claim)),
                                caption: Some(format!(
                                    "N = {}, length {}, turns {}",
                                    inst.region.len(),
                                    rep.length,
                                    rep.turns
                                )),
                                ..crate::draw::DrawOptions::default()
                            };
                            crate::draw::draw(&inst.region, Some(&out.cover), &png, &opts)?;
                            written.push(png);
                        }
                    }
                }
                Err(e) => {
                    let _ = writeln!(note, "re-run failed: {e}");
                }
            }
            let path = dir.join(format!("{stem}.md"));
            std::fs::write(&path, note).map_err(|e| Error::io(&path, e))?;
            written.push(path);
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithms::theorems::{self, Claim as AlgoClaim, Tight, is_declared};

    #[test]
    fn every_theorem_an_algorithm_references_is_declared() {
        for a in REGISTRY {
            for g in a.guarantees {
                assert!(
                    is_declared(g.theorem),
                    "{}: guarantee {g} names {}, which is not in THEOREMS",
                    a.name,
                    g.theorem.cite()
                );
                assert!(
                    g.source.contains(g.theorem.paper.title()),
                    "{}: guarantee {g} cites another paper than its theorem {}",
                    a.name,
                    g.theorem.cite()
                );
                assert!(a.objectives.contains(&g.objective), "{}: {g}", a.name);
            }
            for c in a.claims {
                assert!(
                    is_declared(c.theorem),
                    "{}: claims {}, which is not in THEOREMS",
                    a.name,
                    c.theorem.cite()
                );
                assert!(
                    matches!(c.theorem.realized, Realized::ByAlgorithms),
                    "{}: claims {}, which is declared as realized elsewhere or not at all",
                    a.name,
                    c.theorem.cite()
                );
                assert!(
                    c.objectives.iter().all(|o| a.objectives.contains(o)),
                    "{}: claims {} on an objective it does not report",
                    a.name,
                    c.theorem.cite()
                );
            }
        }
    }

    #[test]
    fn every_claims_row_comes_from_the_registry() {
        let table = table(&[], &[]);
        assert_eq!(table.len(), THEOREMS.len());
        for (row, t) in table.iter().zip(THEOREMS) {
            assert_eq!(
                (
                    row.paper.as_str(),
                    row.claim.as_str(),
                    row.statement.as_str()
                ),
                (t.paper.title(), t.id, t.statement)
            );
            assert_eq!(row.factor, t.factor);
            // The algorithms column: exactly the registered algorithms claiming the theorem.
            let claiming: Vec<&str> = REGISTRY
                .iter()
                .filter(|a| a.claims.iter().any(|c| std::ptr::eq(c.theorem, *t)))
                .map(|a| a.name)
                .collect();
            assert_eq!(row.algorithms, claiming.join(" "), "{}", t.id);
            // Without rows nothing is decided: implemented claims are untested.
            let expected = match t.realized {
                Realized::Not(_) => "not implemented",
                _ => "untested",
            };
            assert_eq!(row.verdict, expected, "{}", t.id);
            assert_eq!(row.decided, 0);
        }
    }

    #[test]
    fn a_theorem_no_algorithm_claims_is_not_implemented() {
        static UNCLAIMED: Theorem = Theorem {
            paper: Paper::Milling,
            id: "Theorem 99",
            statement: "a theorem that no registered algorithm claims",
            factor: "OPT",
            measure: Measure::Bound(theorems::Bound {
                quantity: Quantity::Value,
                num: 1,
                den: 1,
                add: 0,
                against: Against::Opt,
                scale: crate::algorithms::Scale::One,
            }),
            when: When::Always,
            realized: Realized::ByAlgorithms,
            tight: Some(Tight {
                family: "band",
                quantities: &["tsp65_length"],
                by: theorems::TightBy::Registered,
            }),
        };
        let [row] = &table_of(&[&UNCLAIMED], REGISTRY, &[], &[])[..] else {
            panic!("one theorem, one row");
        };
        assert_eq!(row.verdict, "not implemented");
        assert_eq!(
            row.implementation,
            "none: no registered algorithm claims it"
        );
        assert_eq!(row.algorithms, "");
        // The same theorem claimed by an algorithm is implemented (untested without rows).
        static CLAIMS: [AlgoClaim; 1] = [AlgoClaim::paper(&UNCLAIMED, &[Objective::Length])];
        let claimed = [Algorithm {
            claims: &CLAIMS,
            ..crate::algorithms::tsp65::ALGORITHM
        }];
        let [row] = &table_of(&[&UNCLAIMED], &claimed, &[], &[])[..] else {
            panic!("one theorem, one row");
        };
        assert_eq!(
            (row.verdict.as_str(), row.implementation.as_str()),
            ("untested", "paper")
        );
        assert_eq!(row.algorithms, crate::algorithms::tsp65::ALGORITHM.name);
    }

    #[test]
    fn readings_are_reported_with_their_notes() {
        let table = table(&[], &[]);
        let row = |id: &str| table.iter().find(|r| r.claim == id).unwrap();
        assert!(
            row(theorems::MILLING_THM_4.id)
                .implementation
                .starts_with("reading: ")
        );
        assert_eq!(row(theorems::MILLING_THM_5.id).implementation, "paper");
        assert!(
            row(theorems::MILLING_COR_4.id)
                .implementation
                .starts_with("reading: ")
        );
        assert!(
            row(theorems::TURNS_THM_5_10.id)
                .implementation
                .starts_with("none: ")
        );
    }
}

#[cfg(test)]
mod hunt_column {
    use super::*;

    fn hunt(algorithm: &str, objective: &str, against: &str, ratio: f64) -> HuntWorst {
        HuntWorst {
            algorithm: algorithm.into(),
            objective: objective.into(),
            family: "random-simple".into(),
            against: against.into(),
            worst_ratio: Some(ratio),
            worst_n: Some(20),
        }
    }

    /// A hunt's worst ratio to OPT fills the claims on the same (algorithm, objective) value
    /// against OPT, never a length or coverage claim, a conditional theorem, or a hunt against
    /// the bound.
    #[test]
    fn worst_found_by_search_goes_where_it_measures_the_claim() {
        let mut t = table(&[], &[]);
        add_hunts(
            &mut t,
            &[
                hunt("strips-matching", "turns", "opt", 1.75),
                hunt("strips-matching", "turns", "opt", 1.5),
                hunt("star-cover", "turns", "bound", 9.0),
                hunt("tsp65", "length", "opt", 1.1),
            ],
        );
        let col = |claim: &str| {
            t.iter()
                .find(|c| c.claim == claim)
                .map(|c| c.worst_found_by_search.clone())
                .unwrap()
        };
        assert!(col("Theorem 5.5 (tour)").starts_with("1.750 (strips-matching turns"));
        assert_eq!(col("Corollary 5.2"), "", "a hunt against the bound");
        assert_eq!(col("Corollary 5.2 (length)"), "", "a length claim");
        assert_eq!(col("Theorem 5"), "", "a bound in N");
        assert!(col("Corollary 3").starts_with("1.100 (tsp65 length"));
    }
}

#[cfg(test)]
mod evidence_rules {
    use super::*;

    fn row(instance: &str, algorithm: &str, objective: &str) -> Row {
        Row {
            instance: instance.into(),
            family: "random-holed".into(),
            algorithm: algorithm.into(),
            objective: objective.into(),
            n: 100,
            valid: Some(true),
            cycles: Some(1),
            ..Row::default()
        }
    }

    fn walk(instance: &str, algorithm: &str, objective: &str, length: u64, turns: u64) -> Row {
        let value = if objective == "length" { length } else { turns };
        Row {
            value: Some(value),
            length: Some(length),
            turns: Some(turns),
            ..row(instance, algorithm, objective)
        }
    }

    fn verdict<'t>(table: &'t [ClaimRow], id: &str) -> &'t ClaimRow {
        table.iter().find(|c| c.claim == id).unwrap()
    }

    /// Without a proven optimum, a value above 5/2 of the best checked walk (here a turn tour's
    /// length) is a proven violation of Theorem 4, attributed to our reading (milling25 is
    /// declared a reading); at 5/2 exactly it is undecided, not a violation.
    #[test]
    fn a_violation_is_decided_against_the_best_checked_walk() {
        let mut rows = vec![
            walk("a", "milling25", "length", 251, 300),
            walk("a", "strips-matching", "turns", 100, 40),
        ];
        let mut exact = walk("a", EXACT, "length", 130, 90);
        exact.opt_status = "time_limit".into();
        exact.lower_bound = Some(100);
        rows.push(exact);
        let t = table(&rows, &[]);
        let c = verdict(&t, "Theorem 4");
        assert_eq!(c.verdict, "violated by our reading", "{}", c.note);
        assert_eq!(c.witness, "milling25 length a");
        assert!(c.note.contains("OPT <= 100"), "{}", c.note);
        assert!(c.note.contains("strips-matching turns"), "{}", c.note);
        rows[0].value = Some(250);
        rows[0].length = Some(250);
        let t = table(&rows, &[]);
        let c = verdict(&t, "Theorem 4");
        assert_eq!(c.violations, 0);
        // 250 <= 5/2 of the exact solver's proven lower bound 100: decided, and it holds.
        assert_eq!(c.decided, 1);
    }

    /// Theorem 4.2: when the exact solver's proven lower bound on every tour exceeds
    /// t + 2c - 2 of the algorithm's cycle cover, the statement itself is contradicted; when it
    /// does not, the violation is the algorithm's.
    #[test]
    fn theorem_4_2_below_the_tour_lower_bound_contradicts_the_statement() {
        let mut cc = walk("b", "strips-matching", "cc-turns", 40, 8);
        cc.cycles = Some(2);
        let tour = walk("b", "strips-matching", "turns", 40, 12);
        let mut exact = walk("b", EXACT, "turns", 40, 12);
        exact.opt = Some(12);
        exact.lower_bound = Some(12);
        let t = table(&[cc.clone(), tour.clone(), exact.clone()], &[]);
        let c = verdict(&t, "Theorem 4.2");
        assert_eq!(c.verdict, "statement contradicted", "{}", c.note);
        assert!(c.note.contains("at least 12 turns"), "{}", c.note);
        // A tour optimum of 10 = t + 2c - 2: the bound can be met; the algorithm broke it.
        exact.opt = Some(10);
        exact.lower_bound = Some(10);
        exact.turns = Some(10);
        exact.value = Some(10);
        let t = table(&[cc, tour, exact], &[]);
        assert_eq!(
            verdict(&t, "Theorem 4.2").verdict,
            "paper's algorithm contradicted"
        );
    }

    /// A hold needs HOLDS_MIN_DECIDED decided instances including a structured family.
    #[test]
    fn holds_needs_a_thousand_decided_instances_and_a_structured_family() {
        let rows_of = |k: usize, family: &str| -> Vec<Row> {
            (0..k)
                .flat_map(|i| {
                    let name = format!("{family}{i}");
                    let mut a = walk(&name, "milling25", "length", 120, 50);
                    a.family = family.into();
                    a.opt = Some(100);
                    vec![a]
                })
                .collect()
        };
        let few = table(&rows_of(999, "random-holed"), &[]);
        assert_eq!(
            verdict(&few, "Theorem 4").verdict,
            "holds on few instances (999)"
        );
        let unstructured = table(&rows_of(1000, "random-holed"), &[]);
        let c = verdict(&unstructured, "Theorem 4");
        assert_eq!(c.verdict, "holds on few instances (1000)");
        assert!(c.note.contains("no structured family"), "{}", c.note);
        let mut rows = rows_of(999, "random-holed");
        rows.extend(rows_of(1, "hole-lattice"));
        let broad = table(&rows, &[]);
        let c = verdict(&broad, "Theorem 4");
        assert_eq!(c.verdict, "holds");
        assert_eq!(c.structured_families, "hole-lattice");
    }

    /// Theorem 5.6 and Table 1's cell are decided on --coverage4 rows against the same
    /// algorithm's rows without it.
    #[test]
    fn coverage4_rows_decide_theorem_5_6_and_the_table_1_cell() {
        let plain = walk("c", "strips-matching", "turns", 60, 20);
        let mut c4 = walk("c", "strips-matching[coverage4]", "turns", 60, 20);
        c4.coverage4 = Some(true);
        c4.max_coverage = Some(4);
        let mut exact = walk("c", EXACT, "length", 50, 20);
        exact.opt = Some(50);
        let t = table(&[plain.clone(), c4.clone(), exact.clone()], &[]);
        assert_eq!(verdict(&t, "Theorem 5.6").decided, 1);
        assert_eq!(verdict(&t, "Theorem 5.6").violations, 0);
        assert_eq!(verdict(&t, "Table 1 (length 4, coverage 4)").decided, 1);
        c4.turns = Some(22);
        c4.max_coverage = Some(5);
        let t = table(&[plain, c4, exact], &[]);
        assert_eq!(
            verdict(&t, "Theorem 5.6").verdict,
            "violated by our reading"
        );
        assert_eq!(
            verdict(&t, "Table 1 (length 4, coverage 4)").verdict,
            "violated by our reading"
        );
    }
}
