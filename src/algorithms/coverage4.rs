//! `--coverage4`: rewriting a covering tour by local modifications so that it covers pixels at
//! most 4 times without more turns (Theorem 5.6 of *Optimal covering tours with turn costs*).
//!
//! # Construction (the abstract states only the theorem; this is our reading, and partial)
//! The one modification we use is the excision of a redundant sub-loop: when the tour passes a
//! pixel p twice and every pixel the tour visits in between is visited elsewhere as well, the
//! part in between is cut out. The tour stays a closed walk covering every pixel, and it does
//! not gain turns: the heading changes by at most the turns of the removed part, so the new
//! turn at p costs at most the two old turns at p plus the removed turns (triangle inequality
//! of the turn cost); each excision is also checked by recounting. We repeat it at the most
//! covered pixel until every pixel is covered at most 4 times or no excision at an
//! over-covered pixel is possible.
//!
//! The paper's proof needs further modifications that the abstract does not describe: where
//! excision is not enough a pixel stays covered more than 4 times, and [`coverage4`] says how
//! many such pixels remain (certificate `coverage4_stuck`), rather than hiding it.
//!
//! # Complexity
//! O(c² · L) per excision attempt at a pixel visited c times, on a tour of L moves.

use crate::checker::walk_cost;
use crate::region::Region;
use crate::tour::{CycleCover, Walk};

/// Cuts `walk[start..start + len]` (cyclically) out of the walk.
fn excise(walk: &Walk, start: usize, len: usize) -> Walk {
    let m = walk.len();
    (0..m - len).map(|k| walk[(start + len + k) % m]).collect()
}

/// One excision at pixel `p` (region index) that removes a redundant sub-loop without adding
/// turns, if there is one: the shortest such loop.
fn excise_at(region: &Region, walk: &Walk, count: &[u32], p: usize) -> Option<Walk> {
    let m = walk.len();
    let target = region.pixel(p);
    let at: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    let (_, turns) = walk_cost(walk).ok()?;
    let mut inside = vec![0u32; region.len()];
    let mut best: Option<(usize, usize)> = None;
    for &i in &at {
        for &j in &at {
            if i == j {
                continue;
            }
            // The loop walk[i + 1 ..= j] (cyclically); it ends at p, which stays at i.
            let len = (j + m - i) % m;
            if len >= m || best.is_some_and(|(_, l)| l <= len) {
                continue;
            }
            let positions = (1..=len).map(|k| (i + k) % m);
            let mut redundant = true;
            let mut touched = Vec::new();
            for k in positions {
                let q = region.index_of(walk[k]).expect("tours stay in the region");
                inside[q] += 1;
                touched.push(q);
                if inside[q] >= count[q] {
                    redundant = false;
                }
            }
            for q in touched {
                inside[q] = 0;
            }
            if redundant {
                best = Some(((i + 1) % m, len));
            }
        }
    }
    let (start, len) = best?;
    let out = excise(walk, start, len);
    match walk_cost(&out) {
        Ok((_, t)) if t <= turns && !out.is_empty() => Some(out),
        _ => None,
    }
}

/// Rewrites every walk of `tour` by redundant-loop excisions until no pixel is covered more
/// than 4 times or none applies. Returns the rewritten tour and the number of pixels still
/// covered more than 4 times.
pub fn coverage4(region: &Region, tour: &CycleCover) -> (CycleCover, usize) {
    let mut cycles = tour.cycles.clone();
    let mut stuck = vec![false; region.len()];
    loop {
        let mut count = vec![0u32; region.len()];
        for p in cycles.iter().flatten() {
            if let Some(i) = region.index_of(*p) {
                count[i] += 1;
            }
        }
        let Some(p) = (0..region.len())
            .filter(|&i| count[i] > 4 && !stuck[i])
            .max_by_key(|&i| count[i])
        else {
            let left = count.iter().filter(|&&c| c > 4).count();
            return (CycleCover::new(cycles), left);
        };
        let mut done = false;
        for walk in cycles.iter_mut() {
            if let Some(shorter) = excise_at(region, walk, &count, p) {
                *walk = shorter;
                done = true;
                break;
            }
        }
        if !done {
            stuck[p] = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};
    use crate::region::Pixel;

    #[test]
    fn redundant_loops_are_cut() {
        // A 1x3 row walked back and forth three times: the middle pixel is visited 6 times.
        let r = Region::rectangle(3, 1);
        let p = |x| Pixel::new(x, 0);
        let walk = vec![
            p(0),
            p(1),
            p(2),
            p(1),
            p(0),
            p(1),
            p(2),
            p(1),
            p(0),
            p(1),
            p(2),
            p(1),
        ];
        let before = check(&r, &CycleCover::tour(walk.clone()), Mode::Milling);
        assert_eq!(before.max_coverage, 6);
        let (after, stuck) = coverage4(&r, &CycleCover::tour(walk));
        let rep = check(&r, &after, Mode::Milling);
        assert!(rep.valid && after.is_tour());
        assert_eq!(stuck, 0);
        assert!(rep.max_coverage <= 4 && rep.turns <= before.turns);
    }
}
