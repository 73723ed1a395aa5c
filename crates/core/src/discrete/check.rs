//! The one checker of discrete milling walks: recounts length (edges walked), turns (0 straight
//! through a collinear pair, 1 for any other change of channel, 2 for a U-turn) and coverage
//! from the walks themselves, and reports the first violation.
//!
//! The conventions are the grid checker's ([`crate::checker`]), so that a grid region and its
//! discrete instance ([`Discrete::from_region`]) get the same counts for the same walks: a walk
//! of one vertex has length 0 and counts 4 turns (the two U-turns of a doubled edge of length
//! zero); a walk of two vertices goes there and back (length 2, two U-turns).

use super::{Discrete, VertexWalk};
use std::fmt;

/// The first thing wrong with a set of walks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    NoCycles,
    EmptyCycle {
        cycle: usize,
    },
    /// A vertex index that is not a vertex of the instance.
    NoSuchVertex {
        cycle: usize,
        position: usize,
        vertex: u32,
    },
    /// Step from position `step` to the next (the last step closes the walk) is not an edge.
    NotAnEdge {
        cycle: usize,
        step: usize,
        from: u32,
        to: u32,
    },
    NotVisited {
        vertex: u32,
        missing: usize,
    },
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Violation::NoCycles => write!(f, "the cover has no closed walk"),
            Violation::EmptyCycle { cycle } => write!(f, "cycle {cycle} is empty"),
            Violation::NoSuchVertex {
                cycle,
                position,
                vertex,
            } => write!(
                f,
                "cycle {cycle}, position {position}: {vertex} is not a vertex of the instance"
            ),
            Violation::NotAnEdge {
                cycle,
                step,
                from,
                to,
            } => write!(
                f,
                "cycle {cycle}, step {step}: {from} -> {to} is not an edge"
            ),
            Violation::NotVisited { vertex, missing } => write!(
                f,
                "vertex {vertex} is not visited ({missing} vertices unvisited in all)"
            ),
        }
    }
}

/// What the checker recounted: the grid checker's report type, with this checker's violations.
pub type Report = crate::checker::Report<Violation>;

/// Checks that `walks` are closed walks of `inst` visiting every vertex, and recounts them.
///
/// # Complexity
/// O(V + total walk length · log μ).
pub fn check(inst: &Discrete, walks: &[VertexWalk]) -> Report {
    let mut report = Report {
        valid: false,
        length: 0,
        turns: 0,
        cycles: walks.len(),
        max_coverage: 0,
        error: None,
        coverage: vec![0; inst.len()],
        violation: None,
    };
    let violation = recount(inst, walks, &mut report);
    report.max_coverage = report.coverage.iter().copied().max().unwrap_or(0);
    report.valid = violation.is_none();
    report.error = violation.as_ref().map(ToString::to_string);
    report.violation = violation;
    report
}

fn recount(inst: &Discrete, walks: &[VertexWalk], report: &mut Report) -> Option<Violation> {
    if walks.is_empty() {
        return Some(Violation::NoCycles);
    }
    for (c, walk) in walks.iter().enumerate() {
        if walk.is_empty() {
            return Some(Violation::EmptyCycle { cycle: c });
        }
        for (position, &v) in walk.iter().enumerate() {
            if v as usize >= inst.len() {
                return Some(Violation::NoSuchVertex {
                    cycle: c,
                    position,
                    vertex: v,
                });
            }
            report.coverage[v as usize] += 1;
        }
        let m = walk.len();
        if m == 1 {
            report.turns += 4;
            continue;
        }
        for i in 0..m {
            let (a, b) = (walk[i], walk[(i + 1) % m]);
            if !inst.adjacent(a, b) {
                return Some(Violation::NotAnEdge {
                    cycle: c,
                    step: i,
                    from: a,
                    to: b,
                });
            }
        }
        report.length += m as u64;
        report.turns += (0..m)
            .map(|i| u64::from(inst.turn(walk[(i + m - 1) % m], walk[i], walk[(i + 1) % m])))
            .sum::<u64>();
    }
    let missing = report.coverage.iter().filter(|&&k| k == 0).count();
    let first = report.coverage.iter().position(|&k| k == 0)?;
    Some(Violation::NotVisited {
        vertex: first as u32,
        missing,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check as check_grid};
    use crate::region::Region;
    use crate::tour::CycleCover;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The same walks through the grid checker and through this one, on the region's
    /// discrete instance: identical verdicts and counts, valid or not.
    #[test]
    fn agrees_with_the_grid_checker_on_random_walks_of_random_regions() {
        let mut rng = ChaCha8Rng::seed_from_u64(17);
        let mut valid = 0;
        for _ in 0..2000 {
            let (w, h) = (rng.random_range(1..6), rng.random_range(1..6));
            let mut pixels: Vec<crate::Pixel> = Vec::new();
            for x in 0..w {
                for y in 0..h {
                    if rng.random_bool(0.8) {
                        pixels.push(crate::Pixel::new(x, y));
                    }
                }
            }
            let Ok(region) = Region::from_pixels(pixels) else {
                continue;
            };
            if region.is_empty() {
                continue;
            }
            let inst = Discrete::from_region(&region);
            // Random walks: mostly along edges (a random neighbour), sometimes a jump.
            let mut walks = Vec::new();
            for _ in 0..rng.random_range(1..4) {
                let mut v = rng.random_range(0..region.len());
                let mut walk = vec![v];
                for _ in 0..rng.random_range(0..6 * region.len()) {
                    let nb: Vec<usize> = region.neighbors(v).collect();
                    v = if nb.is_empty() || rng.random_bool(0.02) {
                        rng.random_range(0..region.len())
                    } else {
                        nb[rng.random_range(0..nb.len())]
                    };
                    walk.push(v);
                }
                // Mostly closed by walking back (the closing step is then an edge).
                if walk.len() > 2 && rng.random_bool(0.9) {
                    let back: Vec<usize> = walk[1..walk.len().saturating_sub(1)]
                        .iter()
                        .rev()
                        .copied()
                        .collect();
                    walk.extend(back);
                }
                walks.push(walk);
            }
            let grid = CycleCover::new(
                walks
                    .iter()
                    .map(|w| w.iter().map(|&v| region.pixel(v)).collect())
                    .collect(),
            );
            let vertex: Vec<VertexWalk> = walks
                .iter()
                .map(|w| w.iter().map(|&v| v as u32).collect())
                .collect();
            let a = check_grid(&region, &grid, Mode::Milling);
            let b = check(&inst, &vertex);
            assert_eq!(a.valid, b.valid, "{:?} vs {:?}", a.error, b.error);
            if a.valid {
                valid += 1;
                assert_eq!(
                    (a.length, a.turns, a.cycles, a.max_coverage),
                    (b.length, b.turns, b.cycles, b.max_coverage)
                );
                assert_eq!(a.coverage, b.coverage);
            }
        }
        assert!(
            valid > 500,
            "only {valid} valid walks: the test would prove little"
        );
    }

    #[test]
    fn counts_turns_from_the_collinear_pairs() {
        // A triangle 0-1-2 with 0-1-2 collinear at 1: the cycle turns at 0 and 2 only.
        let inst = Discrete::new(3, &[(0, 1), (1, 2), (0, 2)], &[(1, 0, 2)], None).unwrap();
        let r = check(&inst, &[vec![0, 1, 2]]);
        assert!(r.valid);
        assert_eq!((r.length, r.turns), (3, 2));
        // There and back along 0-1: two U-turns.
        let r = check(&inst, &[vec![0, 1], vec![2]]);
        assert!(r.valid);
        assert_eq!((r.length, r.turns, r.max_coverage), (2, 8, 1));
        let r = check(&inst, &[vec![0, 1]]);
        assert_eq!(
            r.violation,
            Some(Violation::NotVisited {
                vertex: 2,
                missing: 1
            })
        );
        let r = check(&inst, &[vec![0, 1, 2, 5]]);
        assert!(matches!(r.violation, Some(Violation::NoSuchVertex { .. })));
        let path = Discrete::new(3, &[(0, 1), (1, 2)], &[], None).unwrap();
        let r = check(&path, &[vec![0, 1, 2]]);
        assert!(matches!(
            r.violation,
            Some(Violation::NotAnEdge { step: 2, .. })
        ));
    }
}
