//! `strips-double`: an optimal strip cover, each strip doubled into a closed walk with two
//! U-turns, then merged (Theorem 5.4 of *Optimal covering tours with turn costs*).
//!
//! # Guarantee
//! The cycle cover has 4s ≤ 4·OPT turns in s cycles (s = minimum strip cover size ≤ OPT,
//! Lemma 4.2); merging adds at most 2 per merge (Theorem 4.2): at most 6s − 2 ≤ 6·OPT turns.
//! Every pixel is covered at most 4 times (twice by each of its two strips), so the tour is
//! also within 4 times the optimal length (Theorem 5.4).

use crate::algorithms::merge::cover_and_tour;
use crate::algorithms::{Against, Algorithm, Guarantee, Objective, Options, Solution};
use crate::error::Result;
use crate::region::{Pixel, Region};
use crate::strip_cover::strip_cover;
use crate::topology::Strip;
use crate::tour::{CycleCover, Walk};
use std::collections::BTreeMap;

/// The pixels from `a` to `b` inclusive along a row or column.
pub fn straight(a: Pixel, b: Pixel) -> impl Iterator<Item = Pixel> {
    let (dx, dy) = ((b.x - a.x).signum(), (b.y - a.y).signum());
    let steps = (b.x - a.x).abs() + (b.y - a.y).abs();
    (0..=steps).map(move |k| Pixel::new(a.x + k * dx, a.y + k * dy))
}

/// Appends `pixels` to `walk`, skipping a pixel equal to the walk's last one.
pub fn extend_walk(walk: &mut Walk, pixels: impl IntoIterator<Item = Pixel>) {
    for p in pixels {
        if walk.last() != Some(&p) {
            walk.push(p);
        }
    }
}

/// Closes a walk built by [`extend_walk`]: a final copy of the first pixel is dropped.
pub fn close_walk(mut walk: Walk) -> Walk {
    if walk.len() > 1 && walk.first() == walk.last() {
        walk.pop();
    }
    walk
}

/// The doubled strip: out along the strip and back, two U-turns (one pixel: 4 turns too).
pub fn doubled(strip: &Strip) -> Walk {
    let (a, b) = (strip.start, strip.end());
    let mut walk = Vec::new();
    extend_walk(&mut walk, straight(a, b));
    extend_walk(&mut walk, straight(b, a));
    close_walk(walk)
}

/// The cycle cover of doubled strips of a minimum strip cover, and the cover's size s.
///
/// # Complexity
/// O(N √N) for the strip cover (Hopcroft–Karp), O(N) for the walks.
pub fn doubled_strip_cover(region: &Region) -> (CycleCover, usize) {
    let cover = strip_cover(region);
    (
        CycleCover::new(cover.strips.iter().map(doubled).collect()),
        cover.size(),
    )
}

/// Runs `strips-double`: the doubled-strip cycle cover and its merged tour.
pub fn run(region: &Region, opts: &Options) -> Result<Solution> {
    let (cover, s) = doubled_strip_cover(region);
    let mut certificates = BTreeMap::new();
    certificates.insert("s".to_string(), s as i64);
    cover_and_tour(region, cover, opts, certificates)
}

/// The registry entry.
pub const ALGORITHM: Algorithm = Algorithm {
    name: "strips-double",
    summary: "minimum strip cover, each strip doubled with two U-turns, merged (also at most 4x the optimal length)",
    objectives: &[Objective::CcTurns, Objective::Turns],
    guarantees: &[
        Guarantee {
            objective: Objective::CcTurns,
            quantity: crate::algorithms::Quantity::Value,
            num: 4,
            den: 1,
            add: 0,
            against: Against::Opt,
            when: super::When::Always,
            source: "Theorem 5.4 of Optimal covering tours with turn costs (4 turns per strip, Lemma 4.2)",
        },
        Guarantee {
            objective: Objective::Turns,
            quantity: crate::algorithms::Quantity::Value,
            num: 6,
            den: 1,
            add: 0,
            against: Against::Opt,
            when: super::When::Always,
            source: "Theorem 5.4 of Optimal covering tours with turn costs",
        },
    ],
    precondition: crate::algorithms::merge::connected,
    run,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};

    #[test]
    fn rectangle_3x5() {
        let r = Region::rectangle(5, 3);
        let (cover, s) = doubled_strip_cover(&r);
        assert_eq!(s, 3);
        let rep = check(&r, &cover, Mode::Milling);
        assert!(rep.valid);
        assert_eq!((rep.turns, rep.cycles, rep.max_coverage), (12, 3, 2));
        let sol = run(&r, &Options::default()).unwrap();
        let tour = &sol.outputs[1].cover;
        let rep = check(&r, tour, Mode::Milling);
        assert!(rep.valid && tour.is_tour());
        assert!(rep.turns <= 6 * 3 - 2, "{}", rep.turns);
    }
}
