//! The minimum-weight perfect matching as an integer program (x_ij ∈ {0, 1}, Σ_j x_ij = 1 for
//! every vertex), solved by HiGHS: an independent solver for audits of matching certificates,
//! deliberately not the blossom, fusion-blossom or LP code the algorithms use.

use crate::lp::{Deadline, Formulation, Outcome, Row, Settings, solve_mip};

/// The minimum weight of a perfect matching of vertices `0..n` over `pairs` (a, b, weight),
/// or `None` when none exists or HiGHS does not prove the optimum within `time_limit`
/// seconds. Weights are integers, so a gap below 1 proves the integer optimum.
pub fn min_perfect_matching(
    n: usize,
    pairs: &[(usize, usize, u32)],
    time_limit: f64,
) -> Option<i64> {
    let mut f = Formulation::default();
    let mut at: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
    for &(a, b, w) in pairs {
        let x = f.add_col(f64::from(w), 0.0, 1.0, true);
        at[a].push((x, 1.0));
        at[b].push((x, 1.0));
    }
    f.rows = at.into_iter().map(|t| Row::range(t, 1.0, 1.0)).collect();
    let settings = Settings {
        threads: 1,
        verbose: false,
        ..Settings::default()
    };
    let m = solve_mip(
        &f,
        &[],
        None,
        &Deadline::new(Some(time_limit)),
        &settings,
        Some(0.5),
    );
    (m.outcome == Outcome::Optimal && m.x.is_some()).then(|| m.objective.round() as i64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_and_infeasible() {
        // A 4-cycle 0-1-2-3 with one heavy side: the light perfect matching is {01, 23}.
        let pairs = [(0, 1, 1), (1, 2, 5), (2, 3, 2), (3, 0, 5), (0, 2, 1)];
        assert_eq!(min_perfect_matching(4, &pairs, 10.0), Some(3));
        // A triangle has no perfect matching.
        assert_eq!(
            min_perfect_matching(3, &[(0, 1, 1), (1, 2, 1), (0, 2, 1)], 10.0),
            None
        );
    }
}
