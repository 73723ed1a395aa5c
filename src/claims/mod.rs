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
//!
//! # Where things are
//! - here: the claims of the registry, the table and its verdicts ([`table`]);
//! - `measure`: one claim measured over the rows (the decided instances, the worst ratio, the
//!   violations) and the tight family's value;
//! - [`evidence`]: the best known walk and the proven bounds a verdict is decided from;
//! - `report`: reading tight and hunt outputs, writing the CSV and the Markdown tables;
//! - `findings`: the violating instances saved with their tours and figures.

use crate::algorithms::theorems::{
    Bound, Implementation, Measure, Paper, Realized, THEOREMS, Theorem, TightBy,
};
use crate::algorithms::{Against, Algorithm, Objective, Quantity, REGISTRY, When};
use crate::error::{Error, Result};
use crate::harness::rows::{EXACT, Row};
use crate::tight::{Standing, TightRow};
use evidence::{Attribution, Cost, Evidence};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

pub mod evidence;
pub(crate) mod findings;
mod measure;
mod report;
#[cfg(test)]
mod tests;

pub use findings::{Sources, add_choice_evidence, save_findings};
use measure::{measure, tight_value};
pub use report::{
    HuntWorst, add_hunts, findings_markdown, markdown, read_hunts, read_tight, write_csv,
};

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

/// The prefix of the theorem id of a config's claim for an outside algorithm in the rows'
/// `theorems` column ([`Paper::Outside`]'s short name; see [`crate::outside`]).
const OUTSIDE_KEY: &str = "outside:";

/// One row per claim a config made for an outside algorithm, decided from the rows' own
/// verdicts (`within_guarantee`, computed by the evaluation pipeline against the proven optimum
/// or a lower bound).
fn outside_claims(rows: &[Row]) -> Vec<ClaimRow> {
    let mut by_claim: BTreeMap<(String, String), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        if r.theorems.split("; ").any(|k| k.starts_with(OUTSIDE_KEY)) {
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
