//! One claim measured over the result rows (module docs of [`crate::claims`]), and the tight
//! family's value of a claim.

use super::*;
use crate::algorithms::theorems::{Decision, Known};

pub(super) fn measure<'a>(claim: &Claim, rows: &'a [Row], ev: &Evidence) -> Measured<'a> {
    let theorem = claim.theorem;
    let mut m = Measured::default();
    // The harness wrote the ids of the theorems whose condition held on the row's instance.
    let applies = |r: &Row| r.cites(theorem);
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
                // Lengths of orthogonal polygons are in units of 1/unit: so is the bound.
                let b = b.in_units(r.unit.unwrap_or(1), r.objective == Objective::Length.name());
                let ortho = r.model == "ortho";
                // The cost the bound's OPT is of: the row's objective, or length.
                let cost = match b.quantity {
                    Quantity::Length => Some(Cost::TourLength),
                    _ => Cost::of_objective(&r.objective),
                };
                // What is known of OPT: proven, a proven lower bound, a valid upper bound (the
                // best checked walk). Against N or 1 the bound's X is known exactly.
                let known = match (b.against, b.quantity) {
                    (Against::N | Against::One, _) => Known::default(),
                    // No exact optimum of length, and N is no bound in the units of an ortho row.
                    (Against::Opt, Quantity::Length) if ortho => Known::default(),
                    (Against::Opt, Quantity::Length) => Known {
                        opt: exact_opt
                            .get(&(r.instance.as_str(), Objective::Length.name()))
                            .copied(),
                        lower: Some(r.n),
                        upper: ev.best(r, Cost::TourLength).map(|w| w.value),
                    },
                    (Against::Opt, _) => Known {
                        opt: r.opt,
                        lower: r.lower_bound.max(cost.and_then(|c| ev.lower(r, c))),
                        upper: cost.and_then(|c| ev.best(r, c)).map(|w| w.value),
                    },
                };
                let decision = b.decide(q, r.n, known);
                match decision {
                    Decision::Holds { x: Some(x) } | Decision::Violated { x, exact: true } => {
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
                        if let Decision::Violated { .. } = decision {
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
                    _ => {
                        if let Some(lb) = known.lower.filter(|&lb| lb > 0) {
                            let x = q as f64 / lb as f64;
                            m.max_ratio_lb = Some(m.max_ratio_lb.map_or(x, |y: f64| y.max(x)));
                        }
                        if let Some(u) = known.upper.filter(|&u| u > 0) {
                            m.bump_best(q as f64 / u as f64, r.instance.as_str());
                        }
                        match decision {
                            Decision::Violated { x: u, .. } => {
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
                            }
                            Decision::Holds { .. } => m.decide(r),
                            Decision::Undecided => {}
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
pub(super) fn tight_value(
    family: &str,
    quantities: &[&str],
    tight: &[TightRow],
) -> (String, bool, bool) {
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
