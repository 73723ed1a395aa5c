//! The one independent checker. Every tour and cycle cover that an algorithm or a solver
//! produces goes through [`check`], which recounts length, turns and coverage from the walks
//! themselves and reports the first violation precisely. Algorithms never report their own
//! cost.
//!
//! Counting rules (turn-cost paper, Section 2): length is the number of unit moves of each
//! closed walk, wrap-around included; at every vertex of a closed walk the turn between the
//! incoming and the outgoing move costs 0 (straight), 1 (90°) or 2 (U-turn). A walk of one
//! pixel has length 0; we count it as 4 turns, the two U-turns of a doubled strip of length
//! zero (a closed walk must turn through 360°, and free one-pixel cycles would make every
//! min-turn cycle cover trivial).

use crate::region::{Pixel, Region};
use crate::tour::CycleCover;
use serde::Serialize;
use std::fmt;

/// What a cover must do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    /// Milling: every pixel visited, and no visited pixel outside the region.
    #[default]
    Milling,
    /// Lawn mowing: every grass pixel visited; the walk may leave the region.
    Lawn,
}

impl std::str::FromStr for Mode {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "milling" => Ok(Mode::Milling),
            "lawn" => Ok(Mode::Lawn),
            _ => Err(format!("unknown mode {s:?}: expected milling or lawn")),
        }
    }
}

/// The first thing wrong with a cover.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    NoCycles,
    EmptyCycle {
        cycle: usize,
    },
    /// Step from position `step` to the next (the last step closes the walk).
    NotUnitMove {
        cycle: usize,
        step: usize,
        from: Pixel,
        to: Pixel,
    },
    OutsideRegion {
        cycle: usize,
        position: usize,
        pixel: Pixel,
    },
    NotVisited {
        pixel: Pixel,
        missing: usize,
    },
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Violation::NoCycles => write!(f, "the cover has no closed walk"),
            Violation::EmptyCycle { cycle } => write!(f, "cycle {cycle} is empty"),
            Violation::NotUnitMove {
                cycle,
                step,
                from,
                to,
            } => {
                write!(
                    f,
                    "cycle {cycle}, step {step}: {from} -> {to} is not a unit move"
                )
            }
            Violation::OutsideRegion {
                cycle,
                position,
                pixel,
            } => {
                write!(
                    f,
                    "cycle {cycle}, position {position}: pixel {pixel} is outside the region"
                )
            }
            Violation::NotVisited { pixel, missing } => {
                write!(
                    f,
                    "pixel {pixel} is not visited ({missing} pixels unvisited in all)"
                )
            }
        }
    }
}

/// What a checker recounted: the grid checker's report, and (with its own `V`) the discrete
/// checker's, one type for both. The JSON keys of `mowmill validate` are these field names.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Report<V = Violation> {
    pub valid: bool,
    /// Total number of unit moves (edges walked) over all walks.
    pub length: u64,
    /// Total turn cost over all walks (90° = 1, U-turn = 2).
    pub turns: u64,
    pub cycles: usize,
    /// The largest number of visits of one pixel (vertex) of the instance.
    pub max_coverage: u32,
    /// The first violation, if any.
    pub error: Option<String>,
    /// Visits per pixel (vertex) of the instance, by index.
    #[serde(skip)]
    pub coverage: Vec<u32>,
    #[serde(skip)]
    pub violation: Option<V>,
}

/// Length and turn cost of one closed walk, or the first bad step.
pub fn walk_cost(walk: &[Pixel]) -> Result<(u64, u64), (usize, Pixel, Pixel)> {
    let m = walk.len();
    if m == 1 {
        return Ok((0, 4));
    }
    let mut dirs = Vec::with_capacity(m);
    for i in 0..m {
        let (a, b) = (walk[i], walk[(i + 1) % m]);
        dirs.push(a.dir_to(b).ok_or((i, a, b))?);
    }
    let turns = (0..m)
        .map(|i| u64::from(dirs[(i + m - 1) % m].turn_to(dirs[i])))
        .sum();
    Ok((m as u64, turns))
}

/// Checks `cover` against `region` in the given mode and recounts its costs.
///
/// # Complexity
/// O(N + total walk length).
pub fn check(region: &Region, cover: &CycleCover, mode: Mode) -> Report {
    let mut report = Report {
        valid: false,
        length: 0,
        turns: 0,
        cycles: cover.cycles.len(),
        max_coverage: 0,
        error: None,
        coverage: vec![0; region.len()],
        violation: None,
    };
    let violation = recount(region, cover, mode, &mut report);
    report.max_coverage = report.coverage.iter().copied().max().unwrap_or(0);
    report.valid = violation.is_none();
    report.error = violation.as_ref().map(ToString::to_string);
    report.violation = violation;
    report
}

fn recount(
    region: &Region,
    cover: &CycleCover,
    mode: Mode,
    report: &mut Report,
) -> Option<Violation> {
    if cover.cycles.is_empty() {
        return Some(Violation::NoCycles);
    }
    for (c, walk) in cover.cycles.iter().enumerate() {
        if walk.is_empty() {
            return Some(Violation::EmptyCycle { cycle: c });
        }
        match walk_cost(walk) {
            Ok((length, turns)) => {
                report.length += length;
                report.turns += turns;
            }
            Err((step, from, to)) => {
                return Some(Violation::NotUnitMove {
                    cycle: c,
                    step,
                    from,
                    to,
                });
            }
        }
        for (position, &pixel) in walk.iter().enumerate() {
            match region.index_of(pixel) {
                Some(i) => report.coverage[i] += 1,
                None if mode == Mode::Milling => {
                    return Some(Violation::OutsideRegion {
                        cycle: c,
                        position,
                        pixel,
                    });
                }
                None => {}
            }
        }
    }
    let missing = report.coverage.iter().filter(|&&k| k == 0).count();
    let first = report.coverage.iter().position(|&k| k == 0)?;
    Some(Violation::NotVisited {
        pixel: region.pixel(first),
        missing,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::Region;
    use proptest::prelude::*;

    fn walk(pts: &[(i32, i32)]) -> Vec<Pixel> {
        pts.iter().map(|&p| p.into()).collect()
    }

    #[test]
    fn rectangle_2x3_hamiltonian_cycle() {
        let r = Region::rectangle(2, 3);
        let c = CycleCover::tour(walk(&[(0, 0), (1, 0), (1, 1), (1, 2), (0, 2), (0, 1)]));
        let rep = check(&r, &c, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!(
            (rep.length, rep.turns, rep.cycles, rep.max_coverage),
            (6, 4, 1, 1)
        );
    }

    #[test]
    fn row_back_and_forth() {
        let r = Region::rectangle(4, 1);
        let c = CycleCover::tour(walk(&[(0, 0), (1, 0), (2, 0), (3, 0), (2, 0), (1, 0)]));
        let rep = check(&r, &c, Mode::Milling);
        assert!(rep.valid);
        assert_eq!((rep.length, rep.turns, rep.max_coverage), (6, 4, 2));
    }

    #[test]
    fn square_3x3_boustrophedon() {
        let r = Region::rectangle(3, 3);
        // Up the left column's neighbour rows in a zig-zag, back down column 0.
        let c = CycleCover::tour(walk(&[
            (0, 0),
            (1, 0),
            (2, 0),
            (2, 1),
            (1, 1),
            (1, 2),
            (2, 2),
            (1, 2),
            (0, 2),
            (0, 1),
        ]));
        let rep = check(&r, &c, Mode::Milling);
        assert!(rep.valid, "{:?}", rep.error);
        assert_eq!((rep.length, rep.turns), (10, 8));
    }

    #[test]
    fn violations_are_precise() {
        let r = Region::rectangle(2, 2);
        let jump = CycleCover::tour(walk(&[(0, 0), (1, 1), (0, 1)]));
        assert_eq!(
            check(&r, &jump, Mode::Milling).error.unwrap(),
            "cycle 0, step 0: (0, 0) -> (1, 1) is not a unit move"
        );
        let out = CycleCover::tour(walk(&[(0, 0), (1, 0), (2, 0), (1, 0)]));
        assert_eq!(
            check(&r, &out, Mode::Milling).error.unwrap(),
            "cycle 0, position 2: pixel (2, 0) is outside the region"
        );
        let partial = CycleCover::tour(walk(&[(0, 0), (1, 0)]));
        let rep = check(&r, &partial, Mode::Milling);
        assert!(!rep.valid);
        assert_eq!(
            rep.error.unwrap(),
            "pixel (0, 1) is not visited (2 pixels unvisited in all)"
        );
        assert_eq!(
            check(&r, &CycleCover::default(), Mode::Milling).violation,
            Some(Violation::NoCycles)
        );
        let closing = CycleCover::tour(walk(&[(0, 0), (1, 0), (1, 1)]));
        assert_eq!(
            check(&r, &closing, Mode::Milling).violation,
            Some(Violation::NotUnitMove {
                cycle: 0,
                step: 2,
                from: Pixel::new(1, 1),
                to: Pixel::new(0, 0)
            })
        );
    }

    #[test]
    fn lawn_mode_may_leave_the_region() {
        let r = Region::from_ascii("#.#\n");
        let c = CycleCover::tour(walk(&[(0, 0), (1, 0), (2, 0), (1, 0)]));
        assert!(!check(&r, &c, Mode::Milling).valid);
        let rep = check(&r, &c, Mode::Lawn);
        assert!(rep.valid);
        assert_eq!((rep.length, rep.turns, rep.max_coverage), (4, 4, 1));
    }

    #[test]
    fn single_pixel_walk() {
        let r = Region::rectangle(1, 1);
        let rep = check(&r, &CycleCover::tour(walk(&[(0, 0)])), Mode::Milling);
        assert!(rep.valid);
        assert_eq!((rep.length, rep.turns), (0, 4));
    }

    /// A boustrophedon tour of a w × h rectangle with even h: rows zig-zag right/left, back
    /// down column 0.
    fn snake(w: i32, h: i32) -> Vec<Pixel> {
        let mut out = Vec::new();
        for y in 0..h {
            let xs: Vec<i32> = if y % 2 == 0 {
                (1..w).collect()
            } else {
                (1..w).rev().collect()
            };
            out.extend(xs.into_iter().map(|x| Pixel::new(x, y)));
        }
        out.extend((0..h).rev().map(|y| Pixel::new(0, y)));
        out
    }

    proptest! {
        #[test]
        fn snake_tours_are_valid(w in 2i32..9, hh in 1i32..5) {
            let r = Region::rectangle(w, 2 * hh);
            let rep = check(&r, &CycleCover::tour(snake(w, 2 * hh)), Mode::Milling);
            prop_assert!(rep.valid);
            prop_assert_eq!(rep.length, (w * 2 * hh) as u64);
        }

        #[test]
        fn mutated_walks_are_rejected(w in 2i32..9, hh in 1i32..5, k in 0usize..100, kind in 0u8..4) {
            let h = 2 * hh;
            let r = Region::rectangle(w, h);
            let mut t = snake(w, h);
            let k = k % t.len();
            match kind {
                // Drop a pixel: either a gap in the walk or an unvisited pixel.
                0 => { t.remove(k); }
                // Move a pixel diagonally: breaks adjacency.
                1 => { t[k] = Pixel::new(t[k].x + 1, t[k].y + 1); }
                // Leave the region.
                2 => { let p = t[k]; t.insert(k + 1, Pixel::new(p.x, h)); t.insert(k + 2, p); }
                // Repeat a pixel in place: a zero-length move.
                _ => { let p = t[k]; t.insert(k, p); }
            }
            let rep = check(&r, &CycleCover::tour(t), Mode::Milling);
            prop_assert!(!rep.valid);
            prop_assert!(rep.error.is_some());
        }

        #[test]
        fn turns_are_invariant_under_symmetries(w in 2i32..7, hh in 1i32..4, s in 0u8..8, rot in 0usize..50) {
            let r = Region::rectangle(w, 2 * hh);
            let mut t = snake(w, 2 * hh);
            let rot = rot % t.len();
            t.rotate_left(rot);
            let base = check(&r, &CycleCover::tour(t.clone()), Mode::Milling);
            let sym = crate::region::Symmetry(s);
            let rt = r.transformed(sym);
            let tt: Vec<Pixel> = t.iter().map(|&p| sym.apply(p)).collect();
            let rep = check(&rt, &CycleCover::tour(tt.clone()), Mode::Milling);
            prop_assert!(rep.valid);
            prop_assert_eq!((rep.length, rep.turns), (base.length, base.turns));
            let mut rev = tt;
            rev.reverse();
            let back = check(&rt, &CycleCover::tour(rev), Mode::Milling);
            prop_assert_eq!((back.length, back.turns), (base.length, base.turns));
        }
    }
}
