//! Certificates of a graph-metric matching: every pair's turn distance recounted by a 0-1
//! search, and the lower bound from the solver's dual objective.

use super::*;

/// The certificates of a graph-metric matching `m` of `p` endpoints whose every pair cost
/// 4 + 2w in the graph, the solver's dual objective `dual`: Σ duals ≤ 2P + 2·w(M) for every
/// perfect matching M, so ⌈(dual − 2P)/2⌉ is a lower bound on w(M).
pub(super) fn certified(mut m: PortMatching, dual: i64, p: usize) -> PortMatching {
    let lower = (dual - 2 * p as i64 + 1).div_euclid(2).max(0) as u64;
    m.complete = true;
    m.optimal = m.total <= lower;
    m.lower_bound = lower.min(m.total);
    m.candidates = m.mate.len() * (m.mate.len() - 1) / 2;
    m
}

/// The matching `mate` with every pair's turn distance (at least the floor for partners)
/// recounted by a 0-1 search.
pub(super) fn recount(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    mate: Vec<usize>,
) -> Result<PortMatching> {
    let p = ports.len();
    let mut search = TurnSearch::new(region);
    let mut weight = vec![0u32; p];
    let mut total = 0u64;
    for i in 0..p {
        let j = mate[i];
        if mate[j] != i || i == j {
            return Err(Error::solver(
                "the run-graph matching is not a perfect matching",
            ));
        }
        if i < j {
            let target = ports[j];
            search.run(region, ports[i], u32::MAX, |px, h, _| {
                px == target.pixel && target.arrive() & bit(h) != 0
            });
            let mut d = search.distance_to(target).ok_or_else(|| {
                Error::invalid(format!("matched endpoints {i} and {j} are not connected"))
            })?;
            if j == partner[i] {
                d = d.max(floor[i]);
            }
            weight[i] = d;
            total += u64::from(d);
        }
    }
    Ok(PortMatching {
        mate,
        weight,
        total,
        complete: false,
        optimal: false,
        lower_bound: 0,
        candidates: 0,
    })
}
