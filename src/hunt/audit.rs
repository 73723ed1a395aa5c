//! Independent audits of certificates that no guarantee decides.
//!
//! A certificate implying an exact value (thin-cc's and boundary-cc's `matching_optimal = 1`
//! proves the cover a minimum) is a guarantee of factor 1, and the hunt judges it against the
//! exact optimum like any guarantee. `strips-matching`'s `matching_optimal = 1` says less: that
//! the matching of the strip ends, of weight `w_m`, is a minimum-weight perfect matching under
//! the turn distance (with `matching_lower_bound` a proven bound on that minimum). No tour
//! optimum decides it, so it is audited here with a different solver: the same ends and the
//! same pairwise distances (the inputs, not the claim), and the minimum perfect matching
//! solved as an integer program by HiGHS (x_ij ∈ {0, 1}, Σ_j x_ij = 1 for every end), not by
//! the blossom or fusion-blossom code the algorithm uses.

use crate::algorithms::strips_matching::{strip_floors, strip_ports};
use crate::algorithms::turn_distance::turn_distance;
use crate::region::Region;
use crate::strip_cover::strip_cover;
use std::collections::BTreeMap;

/// Above this many strip ends the audit is skipped (the integer program grows with the square).
pub(crate) const MAX_ENDS: usize = 120;

/// What the audits find wrong with `algorithm`'s certificates on `region` (empty when they hold
/// or none applies).
pub(crate) fn certificates(
    algorithm: &str,
    region: &Region,
    certs: &BTreeMap<String, i64>,
) -> Vec<String> {
    match algorithm {
        "strips-matching" => strip_matching(region, certs),
        _ => Vec::new(),
    }
}

fn strip_matching(region: &Region, certs: &BTreeMap<String, i64>) -> Vec<String> {
    let (Some(&w_m), Some(&lower)) = (certs.get("w_m"), certs.get("matching_lower_bound")) else {
        return vec!["strips-matching reported no w_m or matching_lower_bound".into()];
    };
    let optimal = certs.get("matching_optimal") == Some(&1);
    let Some(minimum) = minimum_strip_matching(region) else {
        return Vec::new();
    };
    let mut wrong = Vec::new();
    if optimal && w_m != minimum {
        wrong.push(format!(
            "false certificate: matching_optimal = 1 with w_m = {w_m}, but the minimum perfect \
             matching of the strip ends weighs {minimum} (integer program)"
        ));
    }
    if w_m < minimum {
        wrong.push(format!(
            "w_m = {w_m} is below the minimum perfect matching weight {minimum}"
        ));
    }
    if lower > minimum {
        wrong.push(format!(
            "false certificate: matching_lower_bound = {lower} above the minimum {minimum}"
        ));
    }
    wrong
}

/// The minimum weight of a perfect matching of the strip ends of `region` (as
/// `strips-matching` builds them: a minimum strip cover, partners' floors), by the integer
/// program of [`crate::exact::matching`]; `None`
/// when there are more than [`MAX_ENDS`] ends, none, or the solver does not prove it.
pub(crate) fn minimum_strip_matching(region: &Region) -> Option<i64> {
    let cover = strip_cover(region);
    let (links, ports) = strip_ports(region, &cover.strips);
    let floor = strip_floors(&links);
    let n = ports.len();
    if n == 0 || n > MAX_ENDS {
        return None;
    }
    let mut pairs = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            let Some(mut d) = turn_distance(region, ports[i], ports[j]) else {
                continue;
            };
            if j == (i ^ 1) {
                d = d.max(floor[i]);
            }
            pairs.push((i, j, d));
        }
    }
    crate::exact::matching::min_perfect_matching(n, &pairs, 30.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithms::{self, Options};
    use crate::generate::{Family, GenParams, generate};

    /// On random regions the audit agrees with the algorithm's certificate, and a forged
    /// certificate (two turns heavier, or an inflated lower bound) is caught. (Every hunt of
    /// strips-matching audits each candidate too: 1000 regions per committed hunt.)
    #[test]
    fn audit_agrees_and_catches_forgeries() {
        let algo = algorithms::find("strips-matching").unwrap();
        let mut audited = 0;
        for seed in 0..15 {
            for family in [Family::RandomSimple, Family::RandomHoled, Family::Thin] {
                let mut p = GenParams::new(family, seed);
                p.n = Some(10 + (seed as usize * 7) % 50);
                let region = generate(&p).unwrap().region;
                let sol = (algo.run)(&region, &Options::default()).unwrap();
                let certs = sol.certificates;
                assert_eq!(
                    certificates("strips-matching", &region, &certs),
                    Vec::<String>::new()
                );
                let min = minimum_strip_matching(&region).expect("at most 118 ends, solved");
                audited += 1;
                assert_eq!(certs["w_m"], min, "seed {seed} {family:?}");
                let mut forged = certs.clone();
                forged.insert("matching_optimal".into(), 1);
                forged.insert("w_m".into(), min + 2);
                assert_eq!(certificates("strips-matching", &region, &forged).len(), 1);
                let mut forged = certs.clone();
                forged.insert("matching_lower_bound".into(), min + 1);
                assert_eq!(certificates("strips-matching", &region, &forged).len(), 1);
            }
        }
        assert_eq!(audited, 45);
    }
}
