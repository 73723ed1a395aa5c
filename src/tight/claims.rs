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

use super::{Standing, TightRow};
use crate::algorithms::theorems::{
    Bound, Implementation, Measure, Paper, Realized, THEOREMS, Theorem,
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
    /// The (algorithm, objective) pairs whose rows exercise it, in registry order.
    rows: Vec<(&'r str, &'static str)>,
    /// How faithfully it is realized; `Err(note)` when nothing realizes it.
    implementation: std::result::Result<Vec<Implementation>, String>,
}

/// The claim of `theorem` over `registry`: every algorithm whose claims name it.
fn claim<'r>(theorem: &'static Theorem, registry: &'r [Algorithm]) -> Claim<'r> {
    let mut rows = Vec::new();
    let mut implementations = Vec::new();
    for a in registry {
        for c in a.claims.iter().filter(|c| std::ptr::eq(c.theorem, theorem)) {
            rows.extend(c.objectives.iter().map(|o| (a.name, o.name())));
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
    /// The violating rows, for saving findings.
    #[serde(skip)]
    pub violating: Vec<(String, String, String)>,
    /// The (algorithm, objective) pairs a hunt's worst ratio to OPT measures this claim on:
    /// only for claims of a factor on the objective's own value against OPT that hold on every
    /// region (a hunt does not keep
    /// a theorem's extra condition, such as "no cut vertices").
    #[serde(skip)]
    pub search_pairs: Vec<(String, String)>,
}

/// How many violating instances `findings` lists per claim.
pub const FINDINGS_LISTED: usize = 10;

/// CSV header of `claims.csv` (a contract for scripts; columns after `verdict` were added by
/// issue 12).
pub const CLAIM_COLUMNS: [&str; 19] = [
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
];

/// What the rows say about one claim.
#[derive(Default)]
struct Measured<'a> {
    instances: BTreeSet<&'a str>,
    decided: BTreeMap<&'a str, (u64, &'a str)>,
    max_ratio: Option<f64>,
    /// The largest value / lower bound on rows where OPT is unknown (reported only when no row
    /// has a proven optimum).
    max_ratio_lb: Option<f64>,
    ratio_of: String,
    violations: usize,
    errors: usize,
    violating: Vec<(String, String, String)>,
}

impl<'a> Measured<'a> {
    fn bump(&mut self, x: f64) {
        self.max_ratio = Some(self.max_ratio.map_or(x, |m| m.max(x)));
    }

    fn decide(&mut self, r: &'a Row) {
        self.decided
            .insert(r.instance.as_str(), (r.n, r.family.as_str()));
    }

    fn violate(&mut self, r: &Row) {
        self.violations += 1;
        self.violating
            .push((r.algorithm.clone(), r.objective.clone(), r.instance.clone()));
    }
}

fn measure<'a>(claim: &Claim, rows: &'a [Row]) -> Measured<'a> {
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
    let of_claim = |r: &Row| {
        claim
            .rows
            .iter()
            .any(|(a, o)| r.algorithm == *a && r.objective == *o)
            && applies(r)
    };
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
    match theorem.measure {
        Measure::Bound(b) => {
            m.ratio_of = match (b.against, b.quantity) {
                (Against::N, _) => "the bound in N (value / bound)".to_string(),
                (Against::One, _) => "the constant (value / bound)".to_string(),
                (Against::Opt, Quantity::Length) => "OPT of length (exact), else N".to_string(),
                (Against::Opt, _) => "OPT (instances with a proven optimum)".to_string(),
            };
            for r in &picked {
                if r.valid == Some(false) {
                    m.violate(r);
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
                // (x for the bound, proven?) where x is OPT, N or 1; a lower bound only decides
                // when the claim holds against it.
                let (x, lower) = match (b.against, b.quantity) {
                    (Against::N, _) => (Some(r.n), None),
                    (Against::One, _) => (Some(1), None),
                    // No exact optimum of length, and N is no bound in the units of an ortho row.
                    (Against::Opt, Quantity::Length) if ortho => (None, None),
                    (Against::Opt, Quantity::Length) => (
                        exact_opt
                            .get(&(r.instance.as_str(), Objective::Length.name()))
                            .copied(),
                        Some(r.n),
                    ),
                    (Against::Opt, _) => (r.opt, r.lower_bound),
                };
                match (x, lower) {
                    (Some(x), _) => {
                        m.decide(r);
                        // Against OPT the ratio to OPT; against N or 1 the fraction of the bound.
                        let scale = match b.against {
                            Against::Opt => x as f64,
                            _ => (b.num as f64 * x as f64 + b.add as f64) / b.den as f64,
                        };
                        if scale > 0.0 {
                            m.bump(q as f64 / scale);
                        }
                        if !b.holds(q, x) {
                            m.violate(r);
                        }
                    }
                    (None, Some(lb)) => {
                        if lb > 0 {
                            let x = q as f64 / lb as f64;
                            m.max_ratio_lb = Some(m.max_ratio_lb.map_or(x, |y: f64| y.max(x)));
                        }
                        if b.holds(q, lb) {
                            m.decide(r);
                        }
                    }
                    (None, None) => {}
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
                        m.violate(r);
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
                if r.valid == Some(false) {
                    m.violate(r);
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
                    if bound2 > 0 {
                        m.bump(2.0 * tour as f64 / bound2 as f64);
                    }
                    if !ok {
                        m.violate(r);
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
    table.extend(outside_claims(rows));
    table
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
    theorems
        .iter()
        .map(|&t| {
            let c = claim(t, registry);
            let m = measure(&c, rows);
            let (tight_family, (tv, tight_ok, tight_bad)) = match t.tight {
                Some(tf) => (
                    tf.family.to_string(),
                    tight_value(tf.family, tf.quantities, tight),
                ),
                None => (String::new(), (String::new(), false, false)),
            };
            let decided = m.decided.len();
            let verdict = if c.implementation.is_err() {
                "not implemented"
            } else if m.violations > 0 || tight_bad {
                "violated"
            } else if tight_ok && t.measure != Measure::TightOnly && decided > 0 {
                "tight reproduced"
            } else if decided > 0 || (t.measure == Measure::TightOnly && !tv.is_empty()) {
                "holds"
            } else {
                "untested"
            };
            let mut algos: Vec<&str> = c.rows.iter().map(|r| r.0).collect();
            algos.dedup();
            let families: BTreeSet<&str> = m.decided.values().map(|v| v.1).collect();
            let mut findings: Vec<String> = m
                .violating
                .iter()
                .map(|(a, _, i)| format!("{a}:{i}"))
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
                violations: m.violations,
                tight_family,
                tight_value: tv,
                verdict: verdict.to_string(),
                implementation: implementation_text(&c.implementation),
                max_n_decided: m.decided.values().map(|v| v.0).max(),
                families: families.into_iter().collect::<Vec<_>>().join(" "),
                errors: m.errors,
                findings: findings.join(" "),
                violating: m.violating,
                worst_found_by_search: String::new(),
                search_pairs: match t.measure {
                    Measure::Bound(b)
                        if b.against == Against::Opt
                            && b.quantity == Quantity::Value
                            && t.when == When::Always =>
                    {
                        c.rows
                            .iter()
                            .map(|(a, o)| (a.to_string(), o.to_string()))
                            .collect()
                    }
                    _ => Vec::new(),
                },
            }
        })
        .collect()
}

/// Whether a row's violation contradicts the paper (the violating algorithm is exactly the
/// paper's), as opposed to a finding about our reading.
pub fn contradicts_paper(c: &ClaimRow) -> bool {
    c.verdict == "violated" && c.implementation == "paper"
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
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

/// The claims table as Markdown.
pub fn markdown(table: &[ClaimRow], source: &str) -> String {
    let mut out = format!(
        "Claims against {source}: instances = distinct instances with a valid row, decided = \
         those where the claim could be checked (OPT or a sufficient bound known), max N and \
         families of the decided ones. Implementation: `paper` = the paper's algorithm, \
         `reading` = our reading of its proof on pixels (a violation is then a finding about \
         our reading, not the paper contradicted), `none` = not implemented.\n\n"
    );
    out.push_str("| paper | claim | factor | algorithms | impl. | instances | decided | max N | families | max ratio (of) | worst found by search | violations | tight family | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
        let verdict = match (c.verdict.as_str(), implementation) {
            ("violated", "reading") => "violated (by our reading)".to_string(),
            ("violated", _) => "violated (paper contradicted)".to_string(),
            (v, _) => v.to_string(),
        };
        let _ = writeln!(
            out,
            "| {paper} | {} | {} | {} | {implementation} | {} | {} | {} | {} | {ratio} | {} | {} | {tight} | **{verdict}** |",
            c.claim,
            c.factor,
            c.algorithms,
            c.instances,
            c.decided,
            c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            c.families,
            c.worst_found_by_search,
            c.violations,
        );
    }
    let notes: Vec<&ClaimRow> = table
        .iter()
        .filter(|c| c.implementation != "paper" || !c.findings.is_empty() || c.errors > 0)
        .collect();
    if !notes.is_empty() {
        out.push_str("\nNotes:\n\n");
        for c in notes {
            let _ = write!(
                out,
                "- **{}**: implementation {}",
                c.claim, c.implementation
            );
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
            let mut read = crate::harness::rows::read_rows(&dir.join("results.csv"))?;
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
    for c in table.iter().filter(|c| c.verdict == "violated") {
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
