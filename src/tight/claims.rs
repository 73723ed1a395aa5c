//! The claims table (`mowmill claims [--from DIR]`, also written by `mowmill tight`): one row
//! per theorem the harness exercises, with the claimed factor and what it multiplies, the
//! instances tested in a results directory, the largest measured ratio, the tight family's
//! value, and a verdict (`holds`, `tight reproduced`, `contradicted`, `untested`).
//!
//! A claim is contradicted when a row of the results breaks it (the harness's exact
//! `within_guarantee` test, an invalid output, a merge above t + 2c − 2, a lower bound above
//! the optimum, a coverage above 4) or when the tight run contradicts an established value.

use super::{Standing, TightRow};
use crate::algorithms::Against;
use crate::error::{Error, Result};
use crate::harness::rows::{EXACT, Row};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// How a claim is measured on result rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Measure {
    /// The registered guarantee: `within_guarantee`, ratio against OPT (else the lower bound).
    AgainstOpt,
    /// The registered guarantee against N: ratio value / N.
    AgainstN,
    /// Lemma 4.4: the strip cover bound s ≤ OPT (ratio s / OPT on exact turn rows).
    StripBound,
    /// Theorem 4.2: merged tour turns / (t + 2c − 2) of the algorithm's cycle cover.
    Merge,
    /// Corollary 5.2's coverage: max coverage / 4.
    Coverage,
    /// Only the tight families measure it (no result rows carry it).
    TightOnly,
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
    /// The tight family and the quantities of `tight.csv` that carry its value.
    tight: Option<(&'static str, &'static [&'static str])>,
}

const MILLING: &str = "Lawn mowing and milling";
const TURNS: &str = "Optimal covering tours with turn costs";
const LAWN: &[(&str, &str)] = &[
    ("lawn-mst", "lawn-length"),
    ("lawn-christofides", "lawn-length"),
    ("lawn-2opt", "lawn-length"),
    ("lawn-box", "lawn-length"),
];

const CLAIMS: &[Claim] = &[
    Claim {
        paper: MILLING,
        id: "Theorem 2",
        statement: "a TSP tour of the pixel centres is a lawn mowing tour within alpha_TSP (3 l* + 6)",
        factor: "alpha_TSP (3 OPT + 6)",
        rows: LAWN,
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 3",
        statement: "constant-factor lawn mowing: 3 alpha_TSP for the square cutter, rectilinear motion",
        factor: "3 alpha_TSP OPT (+ constant)",
        rows: LAWN,
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 4",
        statement: "milling tour of length at most 2.5 OPT",
        factor: "5/2 OPT",
        rows: &[("milling25", "length")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 5",
        statement: "a tour of a simple grid graph without cut vertices of length at most (6N - 4)/5",
        factor: "(6 N - 4)/5",
        rows: &[("tsp65", "length")],
        measure: Measure::AgainstN,
        tight: Some(("band", &["tsp65_length", "opt_length"])),
    },
    Claim {
        paper: MILLING,
        id: "Corollary 3",
        statement: "milling simple integral rectilinear polygons within 6/5",
        factor: "6/5 OPT",
        rows: &[("tsp65", "length")],
        measure: Measure::AgainstOpt,
        tight: Some(("band", &["ratio_tsp65_opt", "ratio_opt_n"])),
    },
    Claim {
        paper: MILLING,
        id: "Corollary 4",
        statement: "milling simple rectilinear polygons within 11/5 (on our integral instances it follows from Corollary 3)",
        factor: "11/5 OPT",
        rows: &[("tsp65", "length")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: MILLING,
        id: "Theorem 7",
        statement: "a tour of a grid graph without local cut vertices of length at most 1.325 N",
        factor: "53/40 N",
        rows: &[("holes1325", "length")],
        measure: Measure::AgainstN,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Lemma 4.4",
        statement: "minimum strip cover = maximum rook placement, a lower bound s <= OPT on turns",
        factor: "s <= OPT",
        rows: &[],
        measure: Measure::StripBound,
        tight: Some(("donut", &["strip_cover", "opt_cc_turns"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 4.1",
        statement: "a min-turn cycle cover of the boundary in polynomial time",
        factor: "OPT (exact on the boundary)",
        rows: &[("boundary-cc", "cc-turns")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 4.2",
        statement: "a cycle cover with t turns and c cycles merges into a tour with at most t + 2c - 2 turns",
        factor: "t + 2c - 2",
        rows: &[
            ("star-cover", "turns"),
            ("strips-double", "turns"),
            ("strips-matching", "turns"),
            ("boundary-cc", "turns"),
            ("thin-cc", "turns"),
            ("thin-merge", "turns"),
        ],
        measure: Measure::Merge,
        tight: Some(("thin43", &["gadget_naive_turns"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.1",
        statement: "star cover: a linear-time (rho + 2 delta) cycle cover, here 10 OPT",
        factor: "10 OPT",
        rows: &[("star-cover", "cc-turns")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.2",
        statement: "a linear-time 12-approximation covering each pixel at most 4 times",
        factor: "12 OPT, coverage <= 4",
        rows: &[("star-cover", "turns")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Corollary 5.2 (coverage)",
        statement: "the star-cover tour covers each pixel at most 4 times",
        factor: "coverage <= 4",
        rows: &[("star-cover", "turns"), ("star-cover", "cc-turns")],
        measure: Measure::Coverage,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.4",
        statement: "doubled optimal strip cover, merged: at most 6 OPT turns",
        factor: "6 OPT",
        rows: &[("strips-double", "turns")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.5",
        statement: "strips + minimum matching: cycle cover 2.5 OPT, tour 3.75 OPT",
        factor: "5/2 OPT_cc, 15/4 OPT",
        rows: &[
            ("strips-matching", "cc-turns"),
            ("strips-matching", "turns"),
        ],
        measure: Measure::AgainstOpt,
        tight: Some(("donut", &["ratio_cc", "ratio_naive", "ratio_crossing"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.6",
        statement: "any tour rewrites into one with the same turns covering each pixel at most 4 times",
        factor: "coverage <= 4, same turns",
        rows: &[],
        measure: Measure::TightOnly,
        tight: Some(("donut", &["coverage4_turns", "coverage4_max_coverage"])),
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.8",
        statement: "thin Eulerian pockets: a linear-time 6/5-approximation",
        factor: "6/5 OPT",
        rows: &[("thin-euler", "turns")],
        measure: Measure::AgainstOpt,
        tight: None,
    },
    Claim {
        paper: TURNS,
        id: "Theorem 5.9",
        statement: "thin pockets: optimal cycle cover merged into a tour of at most 4/3 OPT turns",
        factor: "4/3 OPT",
        rows: &[("thin-merge", "turns")],
        measure: Measure::AgainstOpt,
        tight: Some(("thin43", &["gadget_naive_turns", "ratio_gadget_naive"])),
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
    pub violations: usize,
    pub tight_family: String,
    pub tight_value: String,
    pub verdict: String,
}

/// CSV header of `claims.csv` (a contract for scripts).
pub const CLAIM_COLUMNS: [&str; 13] = [
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
];

/// What the rows say about one claim: (instances, decided, max ratio, ratio_of, violations).
fn measure(claim: &Claim, rows: &[Row]) -> (usize, usize, Option<f64>, String, usize) {
    let picked: Vec<&Row> = rows
        .iter()
        .filter(|r| r.error.is_empty())
        .filter(|r| {
            if claim.measure == Measure::StripBound {
                r.lb_source.contains("strip cover") && r.algorithm != EXACT
            } else {
                claim
                    .rows
                    .iter()
                    .any(|(a, o)| r.algorithm == *a && r.objective == *o)
            }
        })
        .collect();
    let mut instances: Vec<&str> = picked.iter().map(|r| r.instance.as_str()).collect();
    instances.sort_unstable();
    instances.dedup();
    let mut decided: Vec<&str> = Vec::new();
    let mut max: Option<f64> = None;
    let mut violations = 0;
    let mut bump = |v: f64| max = Some(max.map_or(v, |m: f64| m.max(v)));
    let ratio_of;
    match claim.measure {
        Measure::AgainstOpt | Measure::AgainstN => {
            let use_opt = claim.measure == Measure::AgainstOpt
                && picked.iter().any(|r| r.ratio_opt.is_some());
            ratio_of = match claim.measure {
                Measure::AgainstN => "the bound in N, where it applies",
                _ if use_opt => "OPT (instances with a proven optimum)",
                _ => "lower bound (OPT unknown)",
            }
            .to_string();
            for r in &picked {
                if r.valid == Some(false) || r.within_guarantee == Some(false) {
                    violations += 1;
                }
                let applies = match claim.measure {
                    Measure::AgainstN => n_bound(r).is_some(),
                    _ => r.within_guarantee.is_some(),
                };
                if applies {
                    decided.push(&r.instance);
                }
                let x = match claim.measure {
                    Measure::AgainstN => n_bound(r).map(|b| r.value.unwrap_or(0) as f64 / b),
                    _ if use_opt => r.ratio_opt.map(|x| x.0),
                    _ => r.ratio_lb.map(|x| x.0),
                };
                if let Some(x) = x {
                    bump(x);
                }
            }
        }
        Measure::StripBound => {
            ratio_of = "OPT (s / OPT, turn rows with a proven optimum)".to_string();
            for r in &picked {
                if let (Some(lb), Some(opt)) = (r.lower_bound, r.opt)
                    && opt > 0
                {
                    decided.push(&r.instance);
                    bump(lb as f64 / opt as f64);
                    if lb > opt {
                        violations += 1;
                    }
                }
            }
        }
        Measure::Merge => {
            ratio_of = "t + 2c - 2 of the algorithm's cycle cover".to_string();
            let cc: BTreeMap<(&str, &str), &Row> = rows
                .iter()
                .filter(|r| r.objective == "cc-turns" && r.error.is_empty())
                .map(|r| ((r.instance.as_str(), r.algorithm.as_str()), r))
                .collect();
            for r in &picked {
                let Some(c) = cc.get(&(r.instance.as_str(), r.algorithm.as_str())) else {
                    continue;
                };
                if let (Some(tour), Some(t), Some(cycles)) = (r.turns, c.turns, c.cycles) {
                    let bound = (t + 2 * cycles).saturating_sub(2);
                    decided.push(&r.instance);
                    if bound > 0 {
                        bump(tour as f64 / bound as f64);
                    }
                    if tour > bound {
                        violations += 1;
                    }
                }
            }
        }
        Measure::Coverage => {
            ratio_of = "4 (max coverage / 4)".to_string();
            for r in &picked {
                if let Some(c) = r.max_coverage {
                    decided.push(&r.instance);
                    bump(c as f64 / 4.0);
                    if c > 4 {
                        violations += 1;
                    }
                }
            }
        }
        Measure::TightOnly => {
            ratio_of = "(tight families only)".to_string();
        }
    }
    decided.sort_unstable();
    decided.dedup();
    (instances.len(), decided.len(), max, ratio_of, violations)
}

/// The registered bound in N of a row's algorithm and objective, where the harness decided it.
fn n_bound(r: &Row) -> Option<f64> {
    r.within_guarantee?;
    let algo = crate::algorithms::find(&r.algorithm)?;
    let g = algo
        .guarantees
        .iter()
        .find(|g| g.objective.name() == r.objective && g.against == Against::N)?;
    let b = g.bound(r.n);
    // Above the bound yet within every applicable guarantee: the bound in N does not apply to
    // this instance (e.g. Theorem 5 on a region with cut vertices).
    if b <= 0 || (r.value? as i64 > b && r.within_guarantee == Some(true)) {
        return None;
    }
    Some(b as f64)
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
            let (instances, decided, max_ratio, ratio_of, violations) = measure(c, rows);
            let (tight_family, (tv, tight_ok, tight_bad)) = match c.tight {
                Some((family, qs)) => (family.to_string(), tight_value(family, qs, tight)),
                None => (String::new(), (String::new(), false, false)),
            };
            let verdict = if violations > 0 || tight_bad {
                "contradicted"
            } else if tight_ok && c.measure != Measure::TightOnly {
                "tight reproduced"
            } else if tv.contains("did not reach") {
                "not reproduced by our construction"
            } else if decided > 0 || (c.measure == Measure::TightOnly && !tv.is_empty()) {
                "holds"
            } else {
                "untested"
            };
            let mut algos: Vec<&str> = c.rows.iter().map(|r| r.0).collect();
            algos.dedup();
            ClaimRow {
                paper: c.paper.to_string(),
                claim: c.id.to_string(),
                statement: c.statement.to_string(),
                factor: c.factor.to_string(),
                algorithms: algos.join(" "),
                instances,
                decided,
                max_ratio,
                ratio_of,
                violations,
                tight_family,
                tight_value: tv,
                verdict: verdict.to_string(),
            }
        })
        .collect()
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
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

/// The claims table as Markdown.
pub fn markdown(table: &[ClaimRow], source: &str) -> String {
    let mut out = format!(
        "Claims against {source}: instances = distinct instances with a valid row, decided = \
         those where the claim could be checked (OPT or a sufficient bound known).\n\n"
    );
    out.push_str("| paper | claim | factor | algorithms | instances | decided | max ratio (of) | violations | tight family | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|\n");
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
        let _ = writeln!(
            out,
            "| {paper} | {} | {} | {} | {} | {} | {ratio} | {} | {tight} | **{}** |",
            c.claim, c.factor, c.algorithms, c.instances, c.decided, c.violations, c.verdict
        );
    }
    out
}
