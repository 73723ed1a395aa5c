//! Every registered algorithm's certificates and guarantees against `mowmill::exact::solve`
//! on one region; shared by `tests/certificates.rs` (a fast sample) and `examples/certify.rs`
//! (thousands of regions and a hill climb).
//!
//! What is checked, per region and registered algorithm whose precondition holds:
//! * every output passes the checker (and a tour objective gets one closed walk);
//! * no output beats the proven optimum of its objective (`length`, `cc-turns`, `tour-turns`);
//! * every registered guarantee ([`Guarantee::decide`]) against the exact optimum, or against
//!   the exact solver's proven lower bound when the optimum is not proven (then it may stay
//!   undecided, which is counted);
//! * exactness claims: a guarantee `value <= 1 OPT` is a claim that the output is optimal; it
//!   is checked as `value == OPT` (kind `exact`), and an algorithm reporting
//!   `matching_optimal = 0` does not make it (counted as `withdrawn`).
//!
//! Lawn objectives are not checked: their OPT is the lawn-mowing optimum, which no exact
//! solver here computes (`lawn-tsp` is the TSP through the cell centres, only an upper bound).
//! A solve that is not proven optimal, or an algorithm that errs on a region it accepts, is
//! counted, never dropped.

#![allow(dead_code)]

use mowmill::algorithms::{
    Against, Algorithm, Guarantee, Measured, Objective, Options, Quantity, REGISTRY,
};
use mowmill::checker::{Mode, check};
use mowmill::exact::{self, ExactOptions, Status};
use mowmill::region::Region;
use std::collections::BTreeMap;

/// The exact optima of the three milling objectives (None: not proven), with the proven
/// lower bounds.
#[derive(Clone, Debug)]
pub struct Optima {
    pub length: Option<u64>,
    pub cc: Option<u64>,
    pub tour: Option<u64>,
    pub lower: [u64; 3],
}

impl Optima {
    fn of(&self, o: Objective) -> (Option<u64>, u64) {
        match o {
            Objective::Length => (self.length, self.lower[0]),
            Objective::CcTurns => (self.cc, self.lower[1]),
            Objective::Turns => (self.tour, self.lower[2]),
            // Lawn tours have no optimum here; weighted objectives are never outputs.
            Objective::LawnLength
            | Objective::LawnTsp
            | Objective::Weighted(_)
            | Objective::WeightedCc(_) => (None, 0),
        }
    }
}

/// Figures per algorithm and check.
#[derive(Clone, Debug, Default)]
pub struct Stat {
    pub instances: usize,
    pub decided: usize,
    pub skipped: usize,
    /// Largest value / OPT over decided instances (exact claims: largest value − OPT).
    pub worst: f64,
    pub violations: usize,
}

/// One violated check, with its region.
#[derive(Clone, Debug)]
pub struct Finding {
    pub key: String,
    pub label: String,
    pub what: String,
    pub region: Region,
}

/// Everything counted over a run.
#[derive(Debug, Default)]
pub struct Tally {
    /// Keys `KIND ALGO CHECK`: kind `exact`, `guarantee`, `above-opt` or `run`.
    pub stats: BTreeMap<String, Stat>,
    pub findings: Vec<Finding>,
    /// Exact solves by objective: (proven optimal, not proven).
    pub exact: BTreeMap<&'static str, (usize, usize)>,
    /// Exact solves that ended in an error or time limit, with the region label.
    pub unproven: Vec<String>,
    /// Lower bounds (cheap and exact's own) above a proven optimum.
    pub bad_bounds: Vec<String>,
}

/// How hard a region is for the checks (the hill climb maximizes it).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Score {
    /// Largest value − OPT over exactness claims.
    pub excess: i64,
    /// Largest quantity / bound over guarantees against OPT (above 1: violated).
    pub ratio: f64,
}

pub fn exact_options(time_limit: f64) -> ExactOptions {
    ExactOptions {
        time_limit: Some(time_limit),
        ..mowmill::warm_start::exact_options()
    }
}

/// Solves the three milling objectives; counts unproven solves and checks the lower bounds.
pub fn optima(label: &str, region: &Region, opts: &ExactOptions, tally: &mut Tally) -> Optima {
    let objectives = [
        ("length", exact::Objective::Length),
        ("cc-turns", exact::Objective::CcTurns),
        ("tour-turns", exact::Objective::Turns),
    ];
    let mut values = [None; 3];
    let mut lower = [0; 3];
    for (k, (name, o)) in objectives.into_iter().enumerate() {
        let r = exact::solve(region, o, opts);
        let e = tally.exact.entry(name).or_default();
        lower[k] = r.lower_bound;
        if r.status == Status::Optimal {
            e.0 += 1;
            let v = r.value.expect("an optimal solve has a value");
            values[k] = Some(v);
            let cheap = mowmill::exact::cheap_lower_bound(region, o).value;
            if cheap > v {
                tally
                    .bad_bounds
                    .push(format!("{label}: {name} cheap bound {cheap} > OPT {v}"));
            }
        } else {
            e.1 += 1;
            tally.unproven.push(format!(
                "{label}: {name} {} ({})",
                r.status,
                r.message.unwrap_or_default()
            ));
        }
        if let Some(v) = r.value
            && r.lower_bound > v
        {
            tally.bad_bounds.push(format!(
                "{label}: {name} bound {} > value {v}",
                r.lower_bound
            ));
        }
    }
    Optima {
        length: values[0],
        cc: values[1],
        tour: values[2],
        lower,
    }
}

/// Whether `g` claims that the output is optimal.
pub fn is_exact_claim(g: &Guarantee) -> bool {
    g.bound.against == Against::Opt
        && g.bound.quantity == Quantity::Value
        && g.bound.num == g.bound.den
        && g.bound.add == 0
}

/// Whether the algorithm is checked here (milling objectives only).
pub fn checked_algorithm(a: &Algorithm) -> bool {
    !a.objectives.contains(&Objective::LawnLength)
}

fn bump(tally: &mut Tally, key: String) -> &mut Stat {
    let s = tally.stats.entry(key).or_default();
    s.instances += 1;
    s
}

fn violate(tally: &mut Tally, key: &str, label: &str, what: String, region: &Region) {
    tally.stats.get_mut(key).expect("counted").violations += 1;
    tally.findings.push(Finding {
        key: key.to_string(),
        label: label.to_string(),
        what,
        region: region.clone(),
    });
}

/// Runs every checked registered algorithm whose precondition holds on `region` and checks
/// it against `opt`; returns the region's score.
pub fn check_algorithms(label: &str, region: &Region, opt: &Optima, tally: &mut Tally) -> Score {
    let mut score = Score::default();
    let n = region.len() as u64;
    for a in REGISTRY.iter().filter(|a| checked_algorithm(a)) {
        if (a.precondition)(region).is_err() {
            continue;
        }
        let key = format!("run {}", a.name);
        bump(tally, key.clone());
        let sol = match (a.run)(region, &Options::default()) {
            Ok(s) => s,
            Err(e) => {
                violate(
                    tally,
                    &key,
                    label,
                    format!("error on an accepted region: {e}"),
                    region,
                );
                continue;
            }
        };
        let withdrawn = sol.certificates.get("matching_optimal") == Some(&0);
        for out in &sol.outputs {
            let rep = check(region, &out.cover, Mode::Milling);
            if !rep.valid || (out.objective.is_tour() && rep.cycles != 1) {
                violate(
                    tally,
                    &key,
                    label,
                    format!(
                        "{} output rejected: {:?}, {} walks",
                        out.objective, rep.error, rep.cycles
                    ),
                    region,
                );
                continue;
            }
            let value = match out.objective {
                Objective::Length => rep.length,
                _ => rep.turns,
            };
            let (o, lb) = opt.of(out.objective);
            let k = format!("above-opt {} {}", a.name, out.objective);
            let s = bump(tally, k.clone());
            match o {
                None => s.skipped += 1,
                Some(o) => {
                    s.decided += 1;
                    s.worst = s.worst.max(value as f64 / o.max(1) as f64);
                    if value < o {
                        violate(
                            tally,
                            &k,
                            label,
                            format!("{} {value} below the proven optimum {o}", out.objective),
                            region,
                        );
                    }
                }
            }
            let m = Measured {
                value,
                length: rep.length,
                max_coverage: u64::from(rep.max_coverage),
            };
            for g in a.guarantees.iter().filter(|g| g.objective == out.objective) {
                // Keyed by the registered text; decided with the region's parameters put in
                // (the discrete rows' factors in delta, mu, rho, d, beta_max).
                let Some(on) = g.on_region(region) else {
                    continue;
                };
                let exact_claim = is_exact_claim(g);
                let kind = if exact_claim { "exact" } else { "guarantee" };
                let k = format!("{kind} {} {}", a.name, g);
                if exact_claim && withdrawn {
                    bump(tally, k).skipped += 1;
                    continue;
                }
                // A bound on another quantity than the value against OPT is against that
                // quantity's optimum: the length optimum for `length`; none for coverage.
                let (o, lb) = match (g.bound.quantity, g.bound.against) {
                    (Quantity::Length, Against::Opt) => opt.of(Objective::Length),
                    (Quantity::MaxCoverage, Against::Opt) => (None, 0),
                    _ => (o, lb),
                };
                let verdict = on.decide(&m, n, o, Some(lb));
                let q = match g.bound.quantity {
                    Quantity::Value => value,
                    Quantity::Length => rep.length,
                    Quantity::MaxCoverage => u64::from(rep.max_coverage),
                };
                let x = match g.bound.against {
                    Against::Opt => o,
                    Against::N => Some(n),
                    Against::One => Some(1),
                };
                let s = bump(tally, k.clone());
                match verdict {
                    None => s.skipped += 1,
                    Some(_) => s.decided += 1,
                }
                if let Some(x) = x.filter(|_| verdict.is_some()) {
                    if exact_claim {
                        let excess = q as i64 - x as i64;
                        s.worst = s.worst.max(excess as f64);
                        score.excess = score.excess.max(excess);
                    } else {
                        let bound = on.bound(x).max(1) as f64;
                        if g.bound.against == Against::Opt {
                            s.worst = s.worst.max(q as f64 / x.max(1) as f64);
                            score.ratio = score.ratio.max(q as f64 / bound);
                        } else {
                            s.worst = s.worst.max(q as f64 / bound);
                        }
                    }
                }
                if verdict == Some(false) {
                    let what = format!(
                        "{} = {q} breaks `{g}` with {} = {}",
                        g.bound.quantity.label(g.objective),
                        match g.bound.against {
                            Against::Opt => "OPT",
                            Against::N => "N",
                            Against::One => "1",
                        },
                        x.map_or("?".into(), |x| x.to_string())
                    );
                    violate(tally, &k, label, what, region);
                }
            }
        }
    }
    score
}

/// The table of a tally: per check, instances, decided, skipped, worst, violations.
pub fn table(tally: &Tally) -> String {
    let mut s = format!(
        "{:<88} {:>7} {:>7} {:>7} {:>8} {:>5}\n",
        "check", "inst", "decided", "skipped", "worst", "viol"
    );
    for (k, st) in &tally.stats {
        s += &format!(
            "{k:<88} {:>7} {:>7} {:>7} {:>8.3} {:>5}\n",
            st.instances, st.decided, st.skipped, st.worst, st.violations
        );
    }
    for (o, (proven, not)) in &tally.exact {
        s += &format!("exact {o}: {proven} proven optimal, {not} not proven\n");
    }
    s
}
