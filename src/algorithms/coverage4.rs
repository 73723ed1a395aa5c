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
use crate::region::{Dir, Region};
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

/// Heading of the move from `walk[k]` to `walk[k + 1]` (cyclically).
fn heading(walk: &Walk, k: usize) -> Dir {
    let m = walk.len();
    walk[k % m]
        .dir_to(walk[(k + 1) % m])
        .expect("walks move between 4-adjacent pixels")
}

/// Longest stretch of the walk, on either side of a visit, that one reroute replaces.
const WINDOW: usize = 40;

/// One reroute at pixel `p`: a stretch `walk[i..=j]` around a visit of `p` is replaced by a
/// min-turn path from `walk[i]` to `walk[j]` whose interior avoids `p`. Accepted when every
/// pixel stays covered, the excess coverage Σ max(0, c − 4) drops and the walk's turns stay
/// within `budget`.
fn reroute_at(region: &Region, walk: &Walk, count: &[u32], p: usize, budget: u64) -> Option<Walk> {
    let m = walk.len();
    if m < 3 {
        return None;
    }
    let (_, turns) = walk_cost(walk).ok()?;
    let target = region.pixel(p);
    let idx = |k: usize| {
        region
            .index_of(walk[k % m])
            .expect("tours stay in the region")
    };
    let excess = |c: u32| u64::from(c.saturating_sub(4));
    let visits: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    let window = WINDOW.min((m - 1) / 2);
    for &k in &visits {
        for a in 1..=window {
            let i = (k + m - a) % m;
            let h_in = heading(walk, i + m - 1);
            let (dist, prev) = min_turn_paths(region, idx(i), h_in, p);
            // Turns of the old stretch: at walk[i], ..., walk[j]; grown one step at a time.
            let mut old_turns: u64 = (0..a)
                .map(|s| u64::from(heading(walk, i + s + m - 1).turn_to(heading(walk, i + s))))
                .sum();
            for b in 1..=window.min(m - 1 - a) {
                let j = (k + b) % m;
                old_turns += u64::from(heading(walk, j + m - 1).turn_to(heading(walk, j)));
                let h_out = heading(walk, j);
                let q = idx(j);
                let Some((d, _)) = Dir::ALL
                    .iter()
                    .filter_map(|&d| {
                        dist[q * 4 + d.index()].map(|c| (d, c.0 + u64::from(d.turn_to(h_out))))
                    })
                    .min_by_key(|&(_, c)| c)
                else {
                    continue;
                };
                let new_turns =
                    dist[q * 4 + d.index()].expect("reached").0 + u64::from(d.turn_to(h_out));
                if turns - old_turns + new_turns > budget {
                    continue;
                }
                let path = trace(region, &prev, q, d);
                // Coverage after the replacement of the interior walk[i+1..j].
                let mut delta: std::collections::BTreeMap<usize, i64> = Default::default();
                for s in 1..a + b {
                    *delta.entry(idx(i + s)).or_default() -= 1;
                }
                for &r in &path[1..path.len() - 1] {
                    *delta.entry(r).or_default() += 1;
                }
                let mut gain: i64 = 0;
                let mut ok = true;
                for (&r, &dl) in &delta {
                    let c = i64::from(count[r]) + dl;
                    if c < 1 {
                        ok = false;
                        break;
                    }
                    gain += excess(c as u32) as i64 - excess(count[r]) as i64;
                }
                if !ok || gain >= 0 {
                    continue;
                }
                let mut out: Walk = Vec::with_capacity(m);
                out.extend(path[..path.len() - 1].iter().map(|&r| region.pixel(r)));
                out.extend((0..m - a - b).map(|s| walk[(j + s) % m]));
                match walk_cost(&out) {
                    Ok((_, t)) if t <= budget && out.len() >= 2 => return Some(out),
                    _ => continue,
                }
            }
        }
    }
    None
}

/// Min-turn paths (ties: fewer moves) from `start`, entered with heading `h_in`, over states
/// (pixel, heading); pixel `avoid` may end a path but is never passed through.
#[allow(clippy::type_complexity)]
fn min_turn_paths(
    region: &Region,
    start: usize,
    h_in: Dir,
    avoid: usize,
) -> (Vec<Option<(u64, u64)>>, Vec<usize>) {
    let n = region.len();
    let mut dist: Vec<Option<(u64, u64)>> = vec![None; 4 * n];
    let mut prev = vec![usize::MAX; 4 * n];
    let mut heap = std::collections::BinaryHeap::new();
    // A virtual state: at `start` with heading h_in, before any move; not stored in `dist` so
    // that paths have at least one move.
    let push = |heap: &mut std::collections::BinaryHeap<_>,
                dist: &mut Vec<Option<(u64, u64)>>,
                prev: &mut Vec<usize>,
                s: usize,
                c: (u64, u64),
                from: usize| {
        if dist[s].is_none_or(|d| c < d) {
            dist[s] = Some(c);
            prev[s] = from;
            heap.push(std::cmp::Reverse((c, s)));
        }
    };
    for d in Dir::ALL {
        if let Some(r) = region.neighbor(start, d) {
            push(
                &mut heap,
                &mut dist,
                &mut prev,
                r * 4 + d.index(),
                (u64::from(h_in.turn_to(d)), 1),
                usize::MAX - start,
            );
        }
    }
    while let Some(std::cmp::Reverse((c, s))) = heap.pop() {
        if dist[s] != Some(c) {
            continue;
        }
        let (r, h) = (s / 4, Dir::from_index(s % 4));
        if r == avoid {
            continue;
        }
        for d in Dir::ALL {
            if let Some(t) = region.neighbor(r, d) {
                let nc = (c.0 + u64::from(h.turn_to(d)), c.1 + 1);
                push(&mut heap, &mut dist, &mut prev, t * 4 + d.index(), nc, s);
            }
        }
    }
    (dist, prev)
}

/// The pixels of the path found by [`min_turn_paths`] ending at pixel `q` with heading `d`,
/// start included.
fn trace(region: &Region, prev: &[usize], q: usize, d: Dir) -> Vec<usize> {
    let _ = region;
    let mut out = vec![q];
    let mut s = q * 4 + d.index();
    loop {
        let p = prev[s];
        if p > usize::MAX / 2 {
            out.push(usize::MAX - p);
            break;
        }
        out.push(p / 4);
        s = p;
    }
    out.reverse();
    out
}

/// Rewrites every walk of `tour` by redundant-loop excisions and reroutes until no pixel is
/// covered more than 4 times or none applies. Returns the rewritten tour and the number of
/// pixels still covered more than 4 times.
pub fn coverage4(region: &Region, tour: &CycleCover) -> (CycleCover, usize) {
    let mut cycles = tour.cycles.clone();
    let budgets: Vec<u64> = cycles
        .iter()
        .map(|w| walk_cost(w).map_or(0, |(_, t)| t))
        .collect();
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
            if left > 0 && std::env::var("C4DEBUG").is_ok() {
                eprintln!("STUCK\n{}", region.to_ascii());
                for w in &cycles {
                    eprintln!(
                        "walk turns {:?} {}",
                        walk_cost(w),
                        CycleCover::tour(w.clone()).to_json()
                    );
                    for (i, c) in count.iter().enumerate() {
                        if *c > 4 {
                            let pp = region.pixel(i);
                            let m = w.len();
                            let v: Vec<String> = (0..m)
                                .filter(|&k| w[k] == pp)
                                .map(|k| format!("{:?}>{:?}", heading(w, k + m - 1), heading(w, k)))
                                .collect();
                            eprintln!("  pixel {pp} x{c}: {}", v.join(" "));
                        }
                    }
                }
            }
            return (CycleCover::new(cycles), left);
        };
        let mut done = false;
        for (walk, &budget) in cycles.iter_mut().zip(&budgets) {
            if let Some(shorter) = excise_at(region, walk, &count, p)
                .or_else(|| reroute_at(region, walk, &count, p, budget))
            {
                *walk = shorter;
                done = true;
                break;
            }
        }
        if done {
            stuck.iter_mut().for_each(|s| *s = false);
        } else {
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
