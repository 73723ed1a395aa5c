//! The claims table (`mowmill claims [--from DIR]`, also written by `mowmill tight`): one row
//! per theorem of the two papers, with the claimed bound, which registered algorithm realizes
//! it and how faithfully, the instances of a results directory that exercise it, how many of
//! them decide it, the largest N decided and the families, the largest measured ratio, the
//! tight family's value, and a verdict.
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
//! - `not implemented`: no registered algorithm realizes the claim (e.g. Corollary 4 of the
//!   milling paper, which is about polygons with non-integral vertices).
//! - `untested`: implemented, but no row decides it.
//!
//! A claim against OPT is decided on a row when the exact optimum is known, or when the value is
//! within the bound of the row's proven lower bound (value ≤ f·LB ≤ f·OPT); otherwise it is
//! undecided, never counted as holding.

use super::{Standing, TightRow};
use crate::algorithms::{Against, Quantity, When};
use crate::error::{Error, Result};
use crate::harness::rows::{EXACT, Row};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

/// A claimed upper bound `q ≤ (num · X + add) / den` on a quantity of a row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Bound {
    quantity: Quantity,
    num: i64,
    den: i64,
    add: i64,
    against: Against,
}

const fn bound(quantity: Quantity, num: i64, den: i64, add: i64, against: Against) -> Bound {
    Bound {
        quantity,
        num,
        den,
        add,
        against,
    }
}

impl Bound {
    fn holds(&self, q: u64, x: u64) -> bool {
        i128::from(self.den) * i128::from(q)
            <= i128::from(self.num) * i128::from(x) + i128::from(self.add)
    }
}

/// How a claim is measured on result rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Measure {
    /// The paper's bound, on each row of the claim's (algorithm, objective) pairs.
    Bound(Bound),
    /// Lemma 4.4: the strip cover bound s ≤ OPT (ratio s / OPT on exact turn rows).
    StripBound,
    /// Theorem 4.2: merged tour turns ≤ t + 2c − 2 of the algorithm's cycle cover.
    Merge,
    /// Corollary 4.1: merged tour turns ≤ 3/2 · t of the algorithm's cycle cover.
    MergeHalf,
    /// Only the tight families measure it (no result rows carry it).
    TightOnly,
    /// Nothing measures it: the claim is not implemented.
    Nothing,
}

/// How faithfully the registered algorithms realize a claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Implementation {
    /// The paper's algorithm, as the paper states it (on the paper's own setting).
    Paper,
    /// Our reading of the paper's proof on pixels; the note says where it departs.
    Reading(&'static str),
    /// No registered algorithm realizes it; the note says why.
    None(&'static str),
}

/// One claim of the table.
struct Claim {
    paper: &'static str,
    id: &'static str,
    statement: &'static str,
    /// The claimed factor, as the paper states it.
    factor: &'static str,
    /// The (algorithm, objective) pairs whose rows exercise it.
    rows: &'static [(&'static str, &'static str)],
    measure: Measure,
    /// The instances the claim is stated for, beyond the algorithm's preconditions. A row
    /// applies when the harness recorded (in its `guarantee` column) the algorithm's registered
    /// guarantee with the same condition, i.e. the condition held on the instance.
    when: When,
    implementation: Implementation,
    /// The tight family and the quantities of `tight.csv` that carry its value.
    tight: Option<(&'static str, &'static [&'static str])>,
}

const MILLING: &str = "Lawn mowing and milling";
const TURNS: &str = "Optimal covering tours with turn costs";
const MERGED: &[(&str, &str)] = &[
    ("star-cover", "turns"),
    ("strips-double", "turns"),
    ("strips-matching", "turns"),
    ("thin-cc", "turns"),
    ("thin-merge", "turns"),
];
const V: Quantity = Quantity::Value;
const OPT: Against = Against::Opt;

const CLAIMS: &[Claim] = &[
    Claim {
        paper: MILLING,
        id: "Theorem 2",
        statement: "a TSP tour of the pixel centres is a lawn mowing tour within alpha_TSP (3 l* + 6); decided only where the area bound suffices (no exact lawn optimum)",
        factor: "alpha_TSP (3 OPT + 6)",
        rows: &[("lawn-mst", "lawn-length"), ("lawn-2opt", "lawn-length")],
        measure: Measure::Bound(bound(V, 6, 1, 12, OPT)),
        when: When::Always,
        implementation: Implementation::Reading(
            "alpha_TSP = 2 (doubled MST; 2-opt starts from it), square cutter, rectilinear motion",
        ),
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 2 (Christofides)",
        statement: "Theorem 2 with Christofides, alpha_TSP = 3/2",
        factor: "3/2 (3 OPT + 6)",
        rows: &[("lawn-christofides", "lawn-length")],
        measure: Measure::Bound(bound(V, 9, 2, 18, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 3",
        statement: "constant-factor lawn mowing without the additive term: the shorter of the bounding-box tour and Christofides",
        factor: "3 alpha_TSP + alpha_TSP 3/10 = 99/20 OPT",
        rows: &[("lawn-box", "lawn-length")],
        measure: Measure::Bound(bound(V, 99, 20, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 4",
        statement: "milling tour of length at most 2.5 OPT (regions with holes)",
        factor: "5/2 OPT",
        rows: &[("milling25", "length")],
        measure: Measure::Bound(bound(V, 5, 2, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Reading(
            "contours and strips on pixels: L_dB <= OPT and L_str <= OPT fail on one-pixel-thick parts (module docs of milling25)",
        ),
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 5",
        statement: "a tour of a simple grid graph without cut vertices of length at most (6N - 4)/5",
        factor: "(6 N - 4)/5",
        rows: &[("tsp65", "length")],
        measure: Measure::Bound(bound(V, 6, 5, -4, Against::N)),
        when: When::Biconnected,
        implementation: Implementation::Paper,
        tight: Some(("band", &["tsp65_length", "opt_length"])),
    },
    Claim {
        paper: MILLING,
        id: "Corollary 3",
        statement: "milling simple integral rectilinear polygons within 6/5",
        factor: "6/5 OPT",
        rows: &[("tsp65", "length")],
        measure: Measure::Bound(bound(V, 6, 5, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("band", &["ratio_tsp65_opt", "ratio_opt_n"])),
    },
    Claim {
        paper: MILLING,
        id: "Corollary 4",
        statement: "milling simple rectilinear polygons (arbitrary vertices) within 11/5",
        factor: "11/5 OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "needs polygons with non-integral vertices and the contour tour; mowmill reads integral regions only",
        ),
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 7",
        statement: "a tour of a grid graph without local cut vertices of length at most 1.325 N",
        factor: "53/40 N",
        rows: &[("holes1325", "length")],
        measure: Measure::Bound(bound(V, 53, 40, 0, Against::N)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Lemma 4.4",
        statement: "minimum strip cover = maximum rook placement, a lower bound s <= OPT on turns",
        factor: "s <= OPT",
        rows: &[],
        measure: Measure::StripBound,
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("donut", &["strip_cover", "opt_cc_turns"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 4.1",
        statement: "a min-turn cycle cover of the boundary in polynomial time (optimal when every pixel is a boundary pixel)",
        factor: "OPT (exact on the boundary)",
        rows: &[("boundary-cc", "cc-turns")],
        measure: Measure::Bound(bound(V, 1, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Reading(
            "boundary links on pixels, collinear links sharing a pixel united (module docs of boundary_cc)",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 4.2",
        statement: "a cycle cover with t turns and c cycles merges into a tour with at most t + 2c - 2 turns",
        factor: "t + 2c - 2",
        rows: MERGED,
        measure: Measure::Merge,
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("thin43", &["gadget_naive_turns"])),
    },
    Claim {
        paper: TURNS,
        id: "Corollary 4.1",
        statement: "a cycle cover with t turns of a connected region merges into a tour with at most 3/2 t turns",
        factor: "3/2 t",
        rows: MERGED,
        measure: Measure::MergeHalf,
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.1",
        statement: "star cover: a linear-time (rho + 2 delta) cycle cover, here 10 OPT",
        factor: "10 OPT",
        rows: &[("star-cover", "cc-turns")],
        measure: Measure::Bound(bound(V, 10, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.2",
        statement: "a linear-time 12-approximation on turns (star cover, merged)",
        factor: "12 OPT",
        rows: &[("star-cover", "turns")],
        measure: Measure::Bound(bound(V, 12, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.2 (coverage)",
        statement: "the star-cover tour covers each pixel at most 4 times",
        factor: "coverage <= 4",
        rows: &[("star-cover", "turns"), ("star-cover", "cc-turns")],
        measure: Measure::Bound(bound(Quantity::MaxCoverage, 4, 1, 0, Against::One)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.2 (length)",
        statement: "the star-cover tour is a 4-approximation on length",
        factor: "length <= 4 OPT_length",
        rows: &[("star-cover", "turns")],
        measure: Measure::Bound(bound(Quantity::Length, 4, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.4",
        statement: "doubled optimal strip cover, merged: at most 6 OPT turns",
        factor: "6 OPT",
        rows: &[("strips-double", "turns")],
        measure: Measure::Bound(bound(V, 6, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.4 (length)",
        statement: "the doubled strip cover tour has length within 4 times the optimal",
        factor: "length <= 4 OPT_length",
        rows: &[("strips-double", "turns")],
        measure: Measure::Bound(bound(Quantity::Length, 4, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.5",
        statement: "strips + minimum matching: cycle cover 2.5 OPT",
        factor: "5/2 OPT_cc",
        rows: &[("strips-matching", "cc-turns")],
        measure: Measure::Bound(bound(V, 5, 2, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("donut", &["ratio_cc"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.5 (tour)",
        statement: "strips + minimum matching, merged: tour 3.75 OPT",
        factor: "15/4 OPT",
        rows: &[("strips-matching", "turns")],
        measure: Measure::Bound(bound(V, 15, 4, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("donut", &["ratio_naive", "ratio_crossing"])),
    },
    Claim {
        paper: TURNS,
        id: "Table 1 (length 4, coverage 4)",
        statement: "integral orthogonal and thin rows: the tours rewritten by Theorem 5.6 are 4-approximations on length and cover each pixel at most 4 times",
        factor: "length <= 4 OPT_length, coverage <= 4",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "realized by --coverage4 (strips-matching, thin-cc, thin-merge), which bench configs cannot select yet (issue 13); without it strips-matching tours reach coverage 18 and thin-cc cycle covers 5; Theorem 5.6 is measured on the tight donuts",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.6",
        statement: "any tour rewrites into one with the same turns covering each pixel at most 4 times",
        factor: "coverage <= 4, same turns",
        rows: &[],
        measure: Measure::TightOnly,
        when: When::Always,
        implementation: Implementation::Reading(
            "the paper proves it in outline; --coverage4 is our construction of the local modifications",
        ),
        tight: Some(("donut", &["coverage4_turns", "coverage4_max_coverage"])),
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.3",
        statement: "thin pockets: a min-turn cycle cover in polynomial time",
        factor: "OPT_cc (exact)",
        rows: &[("thin-cc", "cc-turns"), ("thin-merge", "cc-turns")],
        measure: Measure::Bound(bound(V, 1, 1, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Reading(
            "boundary cover of the thin pocket plus centres inserted (module docs of thin)",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.3 (tour)",
        statement: "thin pockets: a 1.5-approximation for min-turn tours",
        factor: "3/2 OPT",
        rows: &[("thin-cc", "turns")],
        measure: Measure::Bound(bound(V, 3, 2, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.8",
        statement: "thin Eulerian pockets: a linear-time 6/5-approximation",
        factor: "6/5 OPT",
        rows: &[("thin-euler", "turns")],
        measure: Measure::Bound(bound(V, 6, 5, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.9",
        statement: "thin pockets: optimal cycle cover merged into a tour of at most 4/3 OPT turns",
        factor: "4/3 OPT",
        rows: &[("thin-merge", "turns")],
        measure: Measure::Bound(bound(V, 4, 3, 0, OPT)),
        when: When::Always,
        implementation: Implementation::Paper,
        tight: Some(("thin43", &["gadget_naive_turns", "ratio_gadget_naive"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.2",
        statement: "restricted-direction milling (d directions, e.g. 3-D): 5d cycle cover, 5d + 2 tour, coverage 2d",
        factor: "5d OPT_cc, (5d + 2) OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "mowmill has no instances beyond the square grid (issue 17)",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.1",
        statement: "discrete milling: (rho + 2 delta + 2) tour, coverage mu",
        factor: "(rho + 2 delta + 2) OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "mowmill has no discrete (graph) instances (issue 17)",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.3",
        statement: "regions bounded by n integral segments, implicit encoding: 10 cycle cover, 12 tour in O(n log n)",
        factor: "10 OPT_cc, 12 OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "mowmill's star-cover runs on the pixels (Theorem 5.1), not on the n-segment encoding",
        ),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.7",
        statement: "nonintegral orthogonal milling: 4.5 cycle cover, 6.25 tour",
        factor: "9/2 OPT_cc, 25/4 OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None("needs non-integral orthogonal polygons (issue 18)"),
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.10",
        statement: "PTAS for length plus C times turns, O(2^h N^O(C))",
        factor: "(1 + eps) OPT",
        rows: &[],
        measure: Measure::Nothing,
        when: When::Always,
        implementation: Implementation::None(
            "not implemented (exponential in the number of holes)",
        ),
        tight: None,
    },
];

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
    /// The violating rows, for saving findings.
    #[serde(skip)]
    pub violating: Vec<(String, String, String)>,
}

/// How many violating instances `findings` lists per claim.
pub const FINDINGS_LISTED: usize = 10;

/// CSV header of `claims.csv` (a contract for scripts; columns after `verdict` were added by
/// issue 12).
pub const CLAIM_COLUMNS: [&str; 18] = [
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
    let mut m = Measured::default();
    let applies = |r: &Row| {
        claim.when == When::Always
            || crate::algorithms::find(&r.algorithm).is_some_and(|a| {
                a.guarantees
                    .iter()
                    .filter(|g| g.when == claim.when)
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
            if claim.measure == Measure::StripBound {
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
    match claim.measure {
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
                let q = match b.quantity {
                    Quantity::Value => r.value,
                    Quantity::Length => r.length,
                    Quantity::MaxCoverage => r.max_coverage,
                };
                let Some(q) = q else { continue };
                // (x for the bound, proven?) where x is OPT, N or 1; a lower bound only decides
                // when the claim holds against it.
                let (x, lower) = match (b.against, b.quantity) {
                    (Against::N, _) => (Some(r.n), None),
                    (Against::One, _) => (Some(1), None),
                    (Against::Opt, Quantity::Length) => (
                        exact_opt.get(&(r.instance.as_str(), "length")).copied(),
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
            m.ratio_of = match claim.measure {
                Measure::Merge => "t + 2c - 2 of the algorithm's cycle cover",
                _ => "3/2 t of the algorithm's cycle cover",
            }
            .to_string();
            let cc: BTreeMap<(&str, &str), &Row> = rows
                .iter()
                .filter(|r| r.objective == "cc-turns" && r.error.is_empty())
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
                    let (bound2, ok) = match claim.measure {
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
    CLAIMS
        .iter()
        .map(|c| {
            let m = measure(c, rows);
            let (tight_family, (tv, tight_ok, tight_bad)) = match c.tight {
                Some((family, qs)) => (family.to_string(), tight_value(family, qs, tight)),
                None => (String::new(), (String::new(), false, false)),
            };
            let decided = m.decided.len();
            let verdict = if let Implementation::None(_) = c.implementation {
                "not implemented"
            } else if m.violations > 0 || tight_bad {
                "violated"
            } else if tight_ok && c.measure != Measure::TightOnly && decided > 0 {
                "tight reproduced"
            } else if decided > 0 || (c.measure == Measure::TightOnly && !tv.is_empty()) {
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
                paper: c.paper.to_string(),
                claim: c.id.to_string(),
                statement: c.statement.to_string(),
                factor: c.factor.to_string(),
                algorithms: algos.join(" "),
                instances: m.instances.len(),
                decided,
                max_ratio: m.max_ratio,
                ratio_of: m.ratio_of,
                violations: m.violations,
                tight_family,
                tight_value: tv,
                verdict: verdict.to_string(),
                implementation: match c.implementation {
                    Implementation::Paper => "paper".to_string(),
                    Implementation::Reading(note) => format!("reading: {note}"),
                    Implementation::None(note) => format!("none: {note}"),
                },
                max_n_decided: m.decided.values().map(|v| v.0).max(),
                families: families.into_iter().collect::<Vec<_>>().join(" "),
                errors: m.errors,
                findings: findings.join(" "),
                violating: m.violating,
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
    out.push_str("| paper | claim | factor | algorithms | impl. | instances | decided | max N | families | max ratio (of) | violations | tight family | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for c in table {
        let paper = if c.paper == MILLING {
            "milling"
        } else {
            "turn-cost"
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
            "| {paper} | {} | {} | {} | {implementation} | {} | {} | {} | {} | {ratio} | {} | {tight} | **{verdict}** |",
            c.claim,
            c.factor,
            c.algorithms,
            c.instances,
            c.decided,
            c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            c.families,
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
pub fn save_findings(
    table: &[ClaimRow],
    from: &Path,
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
            let claim_slug: String = c
                .claim
                .chars()
                .map(|ch| {
                    if ch.is_ascii_alphanumeric() {
                        ch.to_ascii_lowercase()
                    } else {
                        '-'
                    }
                })
                .collect();
            let stem = format!("{claim_slug}-{algo}-{instance}");
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
