//! The former `coverage4` (before the incremental rewrite), kept for tests only: the new
//! implementation must return exactly the same walks.
#![allow(dead_code)]

use crate::checker::walk_cost;
use crate::region::{Dir, Pixel, Region};
use crate::tour::{CycleCover, Walk};

/// Cuts `walk[start..start + len]` (cyclically) out of the walk.
fn excise(walk: &Walk, start: usize, len: usize) -> Walk {
    let m = walk.len();
    (0..m - len).map(|k| walk[(start + len + k) % m]).collect()
}

/// One excision at pixel `p` (region index) that removes a redundant sub-loop without adding
/// turns, if there is one: the shortest such loop.
pub(super) fn excise_at(region: &Region, walk: &Walk, count: &[u32], p: usize) -> Option<Walk> {
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

/// Longest common stretch of two traversals that [`pair_drop_at`] follows on either side of
/// the over-covered pixel.
const PAIR_REACH: usize = 64;

/// One pair drop at pixel `p`: two traversals of one path P through or from `p` (the walk
/// passes P twice, in the same or in opposite directions) are both cut out, which removes a
/// visit of every pixel of P (two of its inner pixels), and the pieces are joined again:
/// - same direction: the walk is u P w A u P w B; without P it is the closed walk
///   w A u B⁻¹ (B reversed keeps its turns);
/// - opposite directions: u P w A w P⁻¹ u B falls into the closed walks w A and u B, which
///   are spliced at a pixel they share, in the orientation with fewer turns ([`splice`]).
///
/// Accepted when every pixel stays covered, the excess coverage drops and the turns stay
/// within `budget`. Only the ends u, w and the splice change turns.
pub(super) fn pair_drop_at(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Walk> {
    let m = walk.len();
    let target = region.pixel(p);
    let at = |t: usize| walk[t % m];
    let idx = |q: Pixel| region.index_of(q).expect("tours stay in the region");
    let excess = |c: u32| u64::from(c.saturating_sub(4));
    let visits: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    // Candidates (first position of P, position of the other traversal's copy of it, moves
    // of P, same direction).
    let mut candidates: Vec<(usize, usize, usize, bool)> = Vec::new();
    for (x, &i) in visits.iter().enumerate() {
        for &j in &visits[x + 1..] {
            for same in [true, false] {
                // Reach of the common path back (lo) and on (hi) from the two visits.
                let matches = |t: usize, back: bool| {
                    let a = if back { i + m * PAIR_REACH - t } else { i + t };
                    let b = match (same, back) {
                        (true, true) => j + m * PAIR_REACH - t,
                        (true, false) => j + t,
                        (false, true) => j + t,
                        (false, false) => j + m * PAIR_REACH - t,
                    };
                    at(a) == at(b)
                };
                let lo = (1..PAIR_REACH).take_while(|&t| matches(t, true)).count();
                let hi = (1..PAIR_REACH).take_while(|&t| matches(t, false)).count();
                let mut spans: Vec<(usize, usize)> = (1..=hi).map(|h| (0, h)).collect();
                spans.extend((1..=lo).map(|l| (l, 0)));
                spans.extend((1..=hi).map(|h| (lo, h)));
                spans.extend((1..=lo).map(|l| (l, hi)));
                spans.sort_unstable();
                spans.dedup();
                for (l, h) in spans {
                    let s1 = (i + m - l % m) % m;
                    let s2 = if same {
                        (j + m - l % m) % m
                    } else {
                        (j + l) % m
                    };
                    candidates.push((s1, s2, l + h, same));
                }
            }
        }
    }
    // Shortest paths first: they disturb least.
    candidates.sort_by_key(|&(_, _, k, _)| k);
    let now: u64 = count.iter().map(|&c| excess(c)).sum();
    for (s1, s2, k, same) in candidates {
        let d = (s2 + m - s1) % m;
        // Positions relative to s1: P1 = 0..=k; P2 = d..=d+k (same) or d-k..=d (opposite,
        // where A = k+1..d-k and B = d+1..m are the closed walks left at w and at u).
        let p2 = if same { d } else { d.wrapping_sub(k) };
        let fits = if same {
            d > k && m > d + k
        } else {
            d > 2 * k && d < m
        };
        if !fits {
            continue;
        }
        let (u, w) = (at(s1), at(s1 + k));
        // A one-pixel walk left over is dropped by the splice: its pixel loses that visit.
        let (a_len, b_len) = (d - 2 * k - 1, m - d - 1);
        if !same && a_len == 0 && b_len == 0 {
            continue;
        }
        let mut delta: std::collections::BTreeMap<usize, i64> = Default::default();
        for t in (0..=k).chain(p2..=p2 + k) {
            *delta.entry(idx(at(s1 + t))).or_default() -= 1;
        }
        if same || a_len > 0 {
            *delta.entry(idx(w)).or_default() += 1;
        }
        if same || b_len > 0 {
            *delta.entry(idx(u)).or_default() += 1;
        }
        let mut after = now;
        let mut ok = true;
        for (&q, &dl) in &delta {
            let c = i64::from(count[q]) + dl;
            if c < 1 {
                ok = false;
                break;
            }
            after = after + excess(c as u32) - excess(count[q]);
        }
        if !ok || after >= now {
            continue;
        }
        let r: Walk = (0..m).map(|t| at(s1 + t)).collect();
        let out = if same {
            // u P w A u P w B becomes w A u B⁻¹.
            let mut out = vec![w];
            out.extend_from_slice(&r[k + 1..d]);
            out.push(u);
            out.extend(r[d + k + 1..].iter().rev());
            out
        } else {
            let first: Walk = std::iter::once(w)
                .chain(r[k + 1..d - k].iter().copied())
                .collect();
            let second: Walk = std::iter::once(u)
                .chain(r[d + 1..].iter().copied())
                .collect();
            match splice(&first, &second) {
                Some(out) => out,
                None => continue,
            }
        };
        if out.len() >= 2 && walk_cost(&out).is_ok_and(|(_, t)| t <= budget) {
            return Some(out);
        }
    }
    None
}

/// A cheap multiplicative hash for pixel keys (the standard SipHash dominated [`splice`]).
#[derive(Clone, Copy, Default)]
struct PixelHash(u64);

impl std::hash::Hasher for PixelHash {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    fn write_i32(&mut self, i: i32) {
        self.write_u64(u64::from(i as u32));
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

impl std::hash::BuildHasher for PixelHash {
    type Hasher = PixelHash;
    fn build_hasher(&self) -> PixelHash {
        PixelHash(0)
    }
}

/// Two closed walks joined into one at a pixel both visit, where and in the orientation of
/// the second that costs fewest turns; a one-pixel walk whose pixel the other visits is
/// dropped. `None` if they share no pixel.
fn splice(a: &Walk, b: &Walk) -> Option<Walk> {
    let (a, b) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    if a.len() == 1 {
        return b.contains(&a[0]).then(|| b.clone());
    }
    let mut where_a: std::collections::HashMap<Pixel, Vec<usize>, PixelHash> = Default::default();
    for (x, &q) in a.iter().enumerate() {
        where_a.entry(q).or_default().push(x);
    }
    let pass = |w: &Walk, x: usize| {
        let n = w.len();
        let h = w[(x + n - 1) % n].dir_to(w[x]).expect("walk");
        let g = w[x].dir_to(w[(x + 1) % n]).expect("walk");
        (h, g)
    };
    // (turn change, position in a, position in b, b reversed)
    let mut best: Option<(i64, usize, usize, bool)> = None;
    for (y, q) in b.iter().enumerate() {
        let Some(xs) = where_a.get(q) else { continue };
        for &x in xs {
            let ((h1, g1), (h2, g2)) = (pass(a, x), pass(b, y));
            let old = i64::from(h1.turn_to(g1) + h2.turn_to(g2));
            let forward = i64::from(h2.turn_to(g1) + h1.turn_to(g2));
            let backward = i64::from(g2.opposite().turn_to(g1) + h1.turn_to(h2.opposite()));
            for (cost, rev) in [(forward, false), (backward, true)] {
                if best.is_none_or(|(c, ..)| cost - old < c) {
                    best = Some((cost - old, x, y, rev));
                }
            }
        }
    }
    let (_, x, y, rev) = best?;
    let (na, nb) = (a.len(), b.len());
    let mut out: Walk = (0..na).map(|t| a[(x + t) % na]).collect();
    if rev {
        out.extend((0..nb).map(|t| b[(y + nb - t) % nb]));
    } else {
        out.extend((0..nb).map(|t| b[(y + t) % nb]));
    }
    Some(out)
}

/// Heading of the move from `walk[k]` to `walk[k + 1]` (cyclically).
fn heading(walk: &Walk, k: usize) -> Dir {
    let m = walk.len();
    walk[k % m]
        .dir_to(walk[(k + 1) % m])
        .expect("walks move between 4-adjacent pixels")
}

/// Longest stretch of the walk, on either side of a visit, that one reroute replaces.
const WINDOW: usize = 12;

/// One reroute at pixel `p`: a stretch `walk[i..=j]` around a visit of `p` is replaced by a
/// min-turn path from `walk[i]` to `walk[j]` whose interior avoids `p`. Accepted when every
/// pixel stays covered, the excess coverage Σ max(0, c − 4) drops and the walk's turns stay
/// within `budget`.
pub(super) fn reroute_at(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Walk> {
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
            // No replacement may cost more turns than the longest stretch from i plus the
            // slack, nor take more than twice the moves of the longest window: a bounded search.
            let longest: u64 = (0..=a + window.min(m - 1 - a))
                .map(|s| u64::from(heading(walk, i + s + m - 1).turn_to(heading(walk, i + s))))
                .sum();
            let limit = (longest + budget.saturating_sub(turns), 4 * window as u64);
            let (dist, prev) = min_turn_paths(region, idx(i), h_in, p, limit);
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
                let path = trace(&prev, q, d);
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

/// Pixels left uncovered by an excision are at most this many for [`excise_and_graft`].
const GRAFTS: usize = 3;

/// One transplant at pixel `p`: a sub-loop between two visits of `p` is cut out although a
/// few pixels are covered only there, and each such pixel u is covered again by a spike
/// (q, u, q) grafted at the cheapest visit of a neighbour q ≠ p. A spike costs 0 extra turns
/// at a U-turn, 2 at a corner and 4 on a straight pass; accepted when the walk's turns stay
/// within `budget` and the excess coverage Σ max(0, c − 4) drops.
pub(super) fn excise_and_graft(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Walk> {
    let m = walk.len();
    let target = region.pixel(p);
    let idx = |q: Pixel| region.index_of(q).expect("tours stay in the region");
    let at: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    let excess = |c: &[u32]| -> u64 { c.iter().map(|&x| u64::from(x.saturating_sub(4))).sum() };
    let before = excess(count);
    for &i in &at {
        for &j in &at {
            let len = (j + m - i) % m;
            if i == j || len + 2 > m {
                continue;
            }
            let mut left = count.to_vec();
            for k in 1..=len {
                left[idx(walk[(i + k) % m])] -= 1;
            }
            let lost: Vec<usize> = (0..region.len()).filter(|&q| left[q] == 0).collect();
            if lost.len() > GRAFTS {
                continue;
            }
            let mut out = excise(walk, (i + 1) % m, len);
            for &u in &lost {
                if left[u] > 0 {
                    continue; // covered by an earlier spike
                }
                let n = out.len();
                let best = (0..n)
                    .filter_map(|k| {
                        let q = out[k];
                        let d = q.dir_to(region.pixel(u))?;
                        if q == target || n < 2 {
                            return None;
                        }
                        let a = out[(k + n - 1) % n].dir_to(q)?;
                        let b = q.dir_to(out[(k + 1) % n])?;
                        let extra = a.turn_to(d) + 2 + d.opposite().turn_to(b) - a.turn_to(b);
                        Some((extra, k))
                    })
                    .min();
                let Some((_, k)) = best else { break };
                let q = out[k];
                out.splice(k + 1..k + 1, [region.pixel(u), q]);
                left[u] += 1;
                left[idx(q)] += 1;
            }
            if left.contains(&0) || excess(&left) >= before {
                continue;
            }
            match walk_cost(&out) {
                Ok((_, t)) if t <= budget => return Some(out),
                _ => continue,
            }
        }
    }
    None
}

/// Reversals are tried at pixels within this L1 distance of the over-covered pixel.
const REVERSAL_RADIUS: u64 = 2;

/// Reverses the part of the walk between two visits of one pixel near `p` (a closed walk again, with
/// the same turns except at that pixel) and then tries [`excise_at`] and [`reroute_at`].
pub(super) fn reverse_then_reroute(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Walk> {
    let mut by_pixel: std::collections::BTreeMap<Pixel, Vec<usize>> = Default::default();
    let target = region.pixel(p);
    // Local: only pixels near p, which also keeps this to O(1) pairs per pixel of the tour.
    for (k, &q) in walk.iter().enumerate() {
        if q.l1(target) <= REVERSAL_RADIUS {
            by_pixel.entry(q).or_default().push(k);
        }
    }
    for visits in by_pixel.values() {
        for (x, &i) in visits.iter().enumerate() {
            for &j in &visits[x + 1..] {
                // walk[i + 1..j] reversed; walk[i] == walk[j] stay.
                let mut out = walk.clone();
                out[i + 1..j].reverse();
                let Ok((_, t)) = walk_cost(&out) else {
                    continue;
                };
                if t > budget || j - i < 2 {
                    continue;
                }
                if let Some(w) = excise_at(region, &out, count, p)
                    .filter(|w| walk_cost(w).is_ok_and(|(_, t)| t <= budget))
                    .or_else(|| reroute_at(region, &out, count, p, budget))
                {
                    return Some(w);
                }
            }
        }
    }
    None
}

/// The maximal straight runs of the walk through position `k`, as (first position, moves):
/// one for a straight pass, the incoming and the outgoing one at a turn.
fn runs_at(walk: &Walk, k: usize) -> Vec<(usize, usize)> {
    let m = walk.len();
    let (h_in, h_out) = (heading(walk, k + m - 1), heading(walk, k));
    let run = |mut s: usize, h: Dir| {
        // Back to the run's first position, then forward over its moves.
        let mut steps = 0;
        while heading(walk, s + m - 1) == h && steps < m {
            s = (s + m - 1) % m;
            steps += 1;
        }
        let mut len = 0;
        while heading(walk, s + len) == h && len < m {
            len += 1;
        }
        (s, len)
    };
    let mut out = vec![run(k, h_out)];
    if h_in != h_out {
        out.push(run((k + m - 1) % m, h_in));
    }
    out
}

/// The walk with the straight run `walk[s..=s + len]` slid one pixel sideways (`v`
/// perpendicular to it): the links before and after it grow or shrink by one (a link shrunk
/// to nothing disappears), so its corners move with it. With perpendicular links on both
/// sides no turn is added; the caller recounts anyway. Returns the new walk (starting at the
/// slid run) and the pixels whose visits it removed and added.
fn slide(region: &Region, walk: &Walk, s: usize, len: usize, v: Dir) -> Option<SlideResult> {
    let m = walk.len();
    if len == 0 || m < len + 3 {
        return None;
    }
    let old: Vec<Pixel> = (0..=len).map(|t| walk[(s + t) % m]).collect();
    let moved: Vec<Pixel> = old.iter().map(|q| q.step(v)).collect();
    if !moved.iter().all(|&q| region.contains(q)) {
        return None;
    }
    let (before, after) = (walk[(s + m - 1) % m], walk[(s + len + 1) % m]);
    let (a, b) = (old[0], old[len]);
    let mut added = Vec::with_capacity(len + 3);
    if before != moved[0] {
        added.push(a);
        added.push(moved[0]);
    }
    added.extend_from_slice(&moved[1..len]);
    if after != moved[len] {
        added.push(moved[len]);
        added.push(b);
    }
    let mut out = added.clone();
    out.extend((0..m - len - 1).map(|t| walk[(s + len + 1 + t) % m]));
    Some((out, old, added))
}

/// A slid walk with the pixels it stopped and started visiting (see [`slide`]).
type SlideResult = (Walk, Vec<Pixel>, Vec<Pixel>);

/// How many slides one chain of [`slide_chain`] may take.
const SLIDE_DEPTH: usize = 8;

/// How many chains [`slide_chain`] extends before it gives up at one pixel.
const SLIDE_EXPANSIONS: usize = 300;

/// A chain of at most [`SLIDE_DEPTH`] slides ([`slide`]): the first of a run through pixel
/// `p`, each later one of a run through a pixel the previous slide left above 4, ending with
/// the excess coverage Σ max(0, c − 4) lower than before, every pixel covered and the turns
/// within `budget`. A slide moves a whole link, so one slide often just passes the excess to
/// the next row or column; the chain pushes it on to where there is room. Chains are
/// extended best first (least excess, then fewest slides), at most [`SLIDE_EXPANSIONS`].
pub(super) fn slide_chain(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Walk> {
    use std::cmp::Reverse;
    let excess = |c: u32| u64::from(c.saturating_sub(4));
    let goal: u64 = count.iter().map(|&c| excess(c)).sum();
    let idx = |q: Pixel| region.index_of(q).expect("slides stay in the region");
    // Chains by (excess, slides, order of discovery): walk, coverage, pixels to slide from.
    let mut chains = vec![(walk.clone(), count.to_vec(), vec![p])];
    let mut heap = std::collections::BinaryHeap::from([Reverse((goal, 0usize, 0usize))]);
    let mut expansions = 0;
    while let Some(Reverse((now, depth, id))) = heap.pop() {
        if depth == SLIDE_DEPTH || expansions == SLIDE_EXPANSIONS {
            continue;
        }
        expansions += 1;
        let (walk, count, from) = chains[id].clone();
        for &q in &from {
            let target = region.pixel(q);
            let mut tried = std::collections::HashSet::new();
            let visits: Vec<usize> = (0..walk.len()).filter(|&k| walk[k] == target).collect();
            for k in visits {
                for (s, len) in runs_at(&walk, k) {
                    let h = heading(&walk, s);
                    for v in [h.left(), h.right()] {
                        if !tried.insert((s, v)) {
                            continue;
                        }
                        let Some((out, removed, added)) = slide(region, &walk, s, len, v) else {
                            continue;
                        };
                        let mut next = count.clone();
                        removed.iter().for_each(|&r| next[idx(r)] -= 1);
                        added.iter().for_each(|&r| next[idx(r)] += 1);
                        if removed.iter().any(|&r| next[idx(r)] == 0) {
                            continue;
                        }
                        let changed: std::collections::BTreeSet<usize> =
                            removed.iter().chain(&added).map(|&r| idx(r)).collect();
                        let after = now + changed.iter().map(|&r| excess(next[r])).sum::<u64>()
                            - changed.iter().map(|&r| excess(count[r])).sum::<u64>();
                        if !walk_cost(&out).is_ok_and(|(_, t)| t <= budget) {
                            continue;
                        }
                        if after < goal {
                            return Some(out);
                        }
                        let over: Vec<usize> =
                            changed.into_iter().filter(|&r| next[r] > 4).collect();
                        heap.push(Reverse((after, depth + 1, chains.len())));
                        chains.push((out, next, over));
                    }
                }
            }
        }
    }
    None
}

/// Min-turn paths (ties: fewer moves) from `start`, entered with heading `h_in`, over states
/// (pixel, heading), of at most `limit` (turns, moves); pixel `avoid` may end a path but is
/// never passed through.
#[allow(clippy::type_complexity)]
fn min_turn_paths(
    region: &Region,
    start: usize,
    h_in: Dir,
    avoid: usize,
    limit: (u64, u64),
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
        if c.0 <= limit.0 && c.1 <= limit.1 && dist[s].is_none_or(|d| c < d) {
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
fn trace(prev: &[usize], q: usize, d: Dir) -> Vec<usize> {
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
            return (CycleCover::new(cycles), left);
        };
        let mut done = false;
        for (walk, &budget) in cycles.iter_mut().zip(&budgets) {
            if let Some(shorter) = excise_at(region, walk, &count, p)
                .or_else(|| pair_drop_at(region, walk, &count, p, budget))
                .or_else(|| reroute_at(region, walk, &count, p, budget))
                .or_else(|| excise_and_graft(region, walk, &count, p, budget))
                .or_else(|| reverse_then_reroute(region, walk, &count, p, budget))
                .or_else(|| slide_chain(region, walk, &count, p, budget))
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
