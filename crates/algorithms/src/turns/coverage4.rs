//! `--coverage4`: rewriting a covering tour by local modifications so that it covers pixels at
//! most 4 times without more turns (Theorem 5.6 of *Optimal covering tours with turn costs*).
//!
//! # Construction (the abstract gives only the statement; this is our reading)
//! A local search at the most covered pixel p. Every move below keeps one closed walk that
//! covers every pixel, keeps the walk's turns within those of the input, and strictly lowers
//! the excess Σ max(0, c − 4) over the pixel coverages c; so the search stops after at most
//! that many moves (the input's excess is at most its length L, as in the theorem). Each move
//! is recounted with [`walk_cost`] before it is taken.
//! 1. *Excision*: a sub-loop between two visits of p whose pixels are all visited elsewhere is
//!    cut out; the new turn at p costs at most the two old turns plus the removed ones
//!    (triangle inequality of the turn cost), so turns do not grow.
//! 2. *Pair drop*: two traversals of one path P through p are both cut out and the pieces
//!    rejoined (same direction: u P w A u P w B becomes w A u B⁻¹; opposite directions: the
//!    two closed walks left are spliced at a shared pixel). Why it is free for a maximal
//!    common path P walked twice in the same direction: only the passages at u and w change.
//!    At w the two traversals arrive through one side a and leave through different sides
//!    b₁ ≠ b₂ (P is maximal), and the two passages (a, b₁), (a, b₂) become one passage
//!    (b₁, b₂). With dist the angle between sides (0, 1, 2 quarter turns), a passage costs
//!    2 − dist, so the change is dist(a, b₁) + dist(a, b₂) − dist(b₁, b₂) − 2 ≤ 0 for
//!    b₁ ≠ b₂ (checked over the cases: 0 or −2); the same at u. So dropping P never adds turns;
//!    it removes a visit of each of P's pixels (two of each inner one) and fails only where a
//!    pixel of P has no other visit.
//! 3. *Reroute*: a stretch `walk[i..=j]` around a visit of p is replaced by a min-turn path
//!    whose interior avoids p (a bounded search over pixel × heading), if that costs no extra
//!    turns.
//! 4. *Transplant*: a sub-loop at p whose only unique pixels are a few spike tips u is cut out
//!    and each u is grafted back as a spike (q, u, q) at a neighbour q ≠ p; a spike costs 0
//!    extra turns at a U-turn, 2 at a corner, 4 on a straight pass, which the removed loop
//!    (a U-turn and two corners at least) pays for.
//! 5. *Reversal*: the part between two visits of one pixel near p is reversed (its own turns
//!    are unchanged) and 1 and 3 are tried on the result.
//! 6. *Slide chain*: a whole link through p is moved one pixel sideways; the links before and
//!    after it grow or shrink by one, so with perpendicular neighbours no turn is added. A
//!    chain of such slides (best first) pushes the excess on to where there is room.
//!
//! Why a pair usually exists (a heuristic count, not a proof): 5 visits of p use 10 side
//! slots on 4 sides, so some edge at p is traversed at least 3 times, two of them in the same
//! direction. Dropping their maximal common path is free (2.); it is blocked only when a
//! pixel of the path is visited by these two traversals alone, and then 3–6 are tried.
//!
//! That some move always applies is the theorem's claim, which we have not proved for this
//! move set: where none applies a pixel stays covered more than 4 times, and [`coverage4`]
//! says how many such pixels remain (certificate `coverage4_stuck`) rather than hiding it.
//! Measured: none remained on any tour tested (`tests/coverage4.rs`, `tests/turns.rs`, the
//! Fig. 5 donuts, and `examples/coverage4_stress.rs`: the merged tours of four algorithms on
//! random simple, holed and thin regions; docs/measured.md). Independently, the exact `tour-turns`
//! solver with `--max-coverage 4` finds the capped optimum equal to the optimum on the small
//! regions tested, as the theorem implies.
//!
//! # Incremental bookkeeping
//! The search keeps, under every accepted move, the coverage of every pixel, the excess, the
//! pixels still to treat ordered by coverage, and per walk the turns at each position as
//! prefix sums (with the positions of U-turns) and, once needed, where each pixel is visited.
//! A move describes its result as pieces of the current walk (runs of positions, forward or
//! reversed, and new pixels): a candidate's turns are counted from the runs' ends and the
//! prefix sums, the coverage changes only at the positions it drops and the pixels it adds,
//! and only the accepted move rebuilds the walk. Slide chains keep their walks as pieces too.
//! The moves, their order and their tie-breaks are those of the former implementation,
//! which recounted everything after every move and rebuilt the walk for every candidate; it
//! is kept for the unit tests (`coverage4/reference.rs`), which check that both return the
//! same walks, move by move and in whole searches, and that the kept state equals a recount.
//! The checker still recounts the final tour (`merge::cover_and_tour`).
//!
//! # Complexity
//! Per accepted move O(N + L) for a walk of L moves on N pixels (rebuilding the walk, its
//! turn sums and, when a splice needs it, its visit index), O(log N) per coverage change.
//! Per attempt at a pixel visited c times: excision O(c² · ℓ) for loops of ℓ moves until
//! the first pixel they alone cover; a pair drop O(c² · R) candidates for common paths of up
//! to R = [`PAIR_REACH`] moves, each O(R) plus, for a splice, the shared pixels of the
//! shorter closed walk (only its U-turns when only a splice at two U-turns fits the budget);
//! a reroute O(c · W · S log S) for windows of W moves over the S states its bounds allow; a
//! transplant and a reversal O(L) per pair of visits tried; a slide chain at most
//! [`SLIDE_EXPANSIONS`](slide::SLIDE_EXPANSIONS) extensions of O(L) each (finding the
//! visits from the index).
//! Measured in docs/measured.md (`--coverage4` at 10^5 and 10^6 pixels).

use crate::checker::walk_cost;
use crate::region::{Dir, Pixel, Region};
use crate::tour::{CycleCover, Walk};
use slide::slide_chain;

/// A piece of a rewritten walk: `len` positions of the current walk from `start` on
/// (cyclically), in walk order or reversed, or new pixels. A move describes its result as
/// pieces, so that its cost is counted in time proportional to the pieces' ends
/// ([`Turns::cost`]) and the coverage updated from the positions it drops and the pixels it
/// adds ([`dropped`]) without rebuilding or recounting the walk.
#[derive(Clone, Debug)]
enum Piece {
    Run { start: usize, len: usize, rev: bool },
    New(Vec<Pixel>),
}

fn run(start: usize, len: usize) -> Piece {
    Piece::Run {
        start,
        len,
        rev: false,
    }
}

fn rev_run(start: usize, len: usize) -> Piece {
    Piece::Run {
        start,
        len,
        rev: true,
    }
}

/// The turns of a closed walk at each position, as prefix sums, and in total (as
/// [`walk_cost`]); `None` for a walk with a non-move.
struct Turns {
    total: u64,
    prefix: Vec<u64>,
    /// Positions of U-turns, in walk order.
    u_turns: Vec<usize>,
}

impl Turns {
    fn of(walk: &Walk) -> Option<Turns> {
        let m = walk.len();
        if m <= 1 {
            let total = walk_cost(walk).ok()?.1;
            return Some(Turns {
                total,
                prefix: vec![0; m + 1],
                u_turns: Vec::new(),
            });
        }
        let dirs: Option<Vec<Dir>> = (0..m).map(|k| walk[k].dir_to(walk[(k + 1) % m])).collect();
        let dirs = dirs?;
        let mut prefix = Vec::with_capacity(m + 1);
        prefix.push(0);
        let mut total = 0;
        let mut u_turns = Vec::new();
        for k in 0..m {
            let t = dirs[(k + m - 1) % m].turn_to(dirs[k]);
            if t == 2 {
                u_turns.push(k);
            }
            total += u64::from(t);
            prefix.push(total);
        }
        Some(Turns {
            total,
            prefix,
            u_turns,
        })
    }

    /// Turns at the `count` positions from `start` on (cyclically).
    fn range(&self, start: usize, count: usize) -> u64 {
        let m = self.prefix.len() - 1;
        if count == 0 {
            return 0;
        }
        let start = start % m;
        let end = start + count;
        if end <= m {
            self.prefix[end] - self.prefix[start]
        } else {
            self.prefix[m] - self.prefix[start] + self.prefix[end - m]
        }
    }

    /// (pixels, turns) of the closed walk made of `pieces` of `walk`, the turns exactly as
    /// [`walk_cost`] of the rebuilt walk (`None` where it would fail): a run's inner positions
    /// keep their neighbours and so their turns; only the two pixels at each end of a run are
    /// looked at.
    fn cost(&self, walk: &Walk, pieces: &[Piece]) -> Option<(u64, u64)> {
        let m = walk.len();
        // (pixel, whether its turn is counted here), and whether hidden positions follow.
        let mut items: Vec<(Pixel, bool, bool)> = Vec::new();
        let mut hidden = 0;
        let mut n = 0;
        for piece in pieces {
            match piece {
                Piece::New(px) => {
                    n += px.len();
                    items.extend(px.iter().map(|&q| (q, true, false)));
                }
                &Piece::Run { start, len, rev } => {
                    n += len;
                    let at = |t: usize| walk[(start + t) % m];
                    let order = |t: usize| if rev { len - 1 - t } else { t };
                    if len <= 4 {
                        items.extend((0..len).map(|t| (at(order(t)), true, false)));
                    } else {
                        hidden += self.range(start + 1, len - 2);
                        items.push((at(order(0)), true, false));
                        items.push((at(order(1)), false, true));
                        items.push((at(order(len - 2)), false, false));
                        items.push((at(order(len - 1)), true, false));
                    }
                }
            }
        }
        if n <= 1 {
            return Some((n as u64, if n == 1 { 4 } else { 0 }));
        }
        let k = items.len();
        let mut dirs = Vec::with_capacity(k);
        for x in 0..k {
            let (q, _, gap) = items[x];
            dirs.push(if gap {
                None
            } else {
                Some(q.dir_to(items[(x + 1) % k].0)?)
            });
        }
        let mut turns = hidden;
        for x in 0..k {
            if items[x].1 {
                let (a, b) = (dirs[(x + k - 1) % k], dirs[x]);
                turns += u64::from(a.expect("beside a gap").turn_to(b.expect("beside a gap")));
            }
        }
        Some((n as u64, turns))
    }
}

/// The walk made of `pieces` of `walk`.
fn rebuild(walk: &Walk, pieces: &[Piece]) -> Walk {
    let m = walk.len();
    let mut out = Vec::with_capacity(m);
    for piece in pieces {
        match piece {
            Piece::New(px) => out.extend_from_slice(px),
            &Piece::Run { start, len, rev } => {
                if rev {
                    out.extend((0..len).rev().map(|t| walk[(start + t) % m]));
                } else {
                    out.extend((0..len).map(|t| walk[(start + t) % m]));
                }
            }
        }
    }
    out
}

/// The positions of a walk of `m` moves that no run of `pieces` keeps (runs never overlap).
fn dropped(m: usize, pieces: &[Piece]) -> Vec<usize> {
    let mut spans: Vec<(usize, usize)> = Vec::new();
    for piece in pieces {
        if let &Piece::Run { start, len, .. } = piece {
            let s = start % m;
            if s + len <= m {
                spans.push((s, s + len));
            } else {
                spans.push((s, m));
                spans.push((0, s + len - m));
            }
        }
    }
    spans.sort_unstable();
    let mut out = Vec::new();
    let mut at = 0;
    for (s, e) in spans {
        debug_assert!(s >= at, "runs overlap");
        out.extend(at..s);
        at = at.max(e);
    }
    out.extend(at..m);
    out
}

/// One excision at pixel `p` (region index) that removes a redundant sub-loop without adding
/// turns, if there is one: the shortest such loop.
fn excise_at(
    region: &Region,
    walk: &Walk,
    turns: &Turns,
    count: &[u32],
    p: usize,
) -> Option<Vec<Piece>> {
    let m = walk.len();
    let target = region.pixel(p);
    let at: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    let mut inside = vec![0u32; region.len()];
    let mut best: Option<(usize, usize)> = None;
    let mut touched = Vec::new();
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
            let mut redundant = true;
            for k in (1..=len).map(|k| (i + k) % m) {
                let q = region.index_of(walk[k]).expect("tours stay in the region");
                inside[q] += 1;
                touched.push(q);
                if inside[q] >= count[q] {
                    redundant = false;
                    break;
                }
            }
            for q in touched.drain(..) {
                inside[q] = 0;
            }
            if redundant {
                best = Some(((i + 1) % m, len));
            }
        }
    }
    let (start, len) = best?;
    let out = vec![run(start + len, m - len)];
    match turns.cost(walk, &out) {
        Some((moves, t)) if t <= turns.total && moves > 0 => Some(out),
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
#[allow(clippy::too_many_arguments)]
fn pair_drop_at(
    region: &Region,
    walk: &Walk,
    turns: &Turns,
    index: &mut Option<Visits>,
    count: &[u32],
    now: u64,
    p: usize,
    budget: u64,
) -> Option<Vec<Piece>> {
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
        let out = if same {
            // u P w A u P w B becomes w A u B⁻¹.
            vec![
                run(s1 + k, d - k),
                run(s1 + d, 1),
                rev_run(s1 + d + k + 1, m - d - k - 1),
            ]
        } else {
            // The closed walks w A and u B.
            // The spliced walk has the turns of the two closed walks, less at most 4 at the
            // splice (two passes of 0 to 2): no splice can fit the budget below that.
            let closed = |s: usize, n: usize| turns.cost(walk, &[run(s, n)]).map(|c| c.1);
            let (Some(ta), Some(tb)) = (closed(s1 + k, d - 2 * k), closed(s1 + d, m - d)) else {
                continue;
            };
            if ta.min(tb) > budget || (d - 2 * k > 1 && m - d > 1 && ta + tb > budget + 4) {
                continue;
            }
            let index = index.get_or_insert_with(|| Visits::of(region, walk));
            // Spliced at two U-turns that become straight passes only (4 turns less), if
            // nothing else fits: the others are not looked at.
            let only_u_turns =
                (d - 2 * k > 1 && m - d > 1 && ta + tb == budget + 4).then_some(turns);
            let (a, b) = ((s1 + k, d - 2 * k), (s1 + d, m - d));
            match splice(region, walk, index, only_u_turns, a, b) {
                Some(out) => out,
                None => continue,
            }
        };
        if turns
            .cost(walk, &out)
            .is_some_and(|(n, t)| n >= 2 && t <= budget)
        {
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
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
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

/// Where each pixel (region index) is visited on a walk: positions in walk order.
struct Visits {
    start: Vec<usize>,
    at: Vec<usize>,
}

impl Visits {
    fn of(region: &Region, walk: &Walk) -> Visits {
        let mut start = vec![0usize; region.len() + 1];
        let idx: Vec<usize> = walk
            .iter()
            .map(|&q| region.index_of(q).expect("tours stay in the region"))
            .collect();
        idx.iter().for_each(|&i| start[i + 1] += 1);
        for i in 0..region.len() {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut at = vec![0; walk.len()];
        for (k, &i) in idx.iter().enumerate() {
            at[fill[i]] = k;
            fill[i] += 1;
        }
        Visits { start, at }
    }

    fn of_pixel(&self, i: usize) -> &[usize] {
        &self.at[self.start[i]..self.start[i + 1]]
    }
}

/// Two closed walks, runs `(start, len)` of `walk`, joined into one at a pixel both visit,
/// where and in the orientation of the second that costs fewest turns (ties: the first
/// position in the longer walk, then in the shorter, forward before reversed); a one-pixel
/// walk whose pixel the other visits is dropped. `None` if they share no pixel. The shared
/// pixels are found from the shorter walk's pixels through `visits`.
///
/// With `only_u_turns` (the walk's turns), only splices that lower the turns by 4 are
/// considered: at a U-turn of both walks; the shorter walk's U-turns are its two ends and
/// those the walk has inside it.
fn splice(
    region: &Region,
    walk: &Walk,
    visits: &Visits,
    only_u_turns: Option<&Turns>,
    a: (usize, usize),
    b: (usize, usize),
) -> Option<Vec<Piece>> {
    let m = walk.len();
    let (a, b) = if a.1 <= b.1 { (a, b) } else { (b, a) };
    let ((sa, na), (sb, nb)) = (a, b);
    let pa = |x: usize| walk[(sa + x) % m];
    let pb = |y: usize| walk[(sb + y) % m];
    // Positions of b that visit the pixel of a's position x.
    let in_b = |x: usize| {
        let i = region.index_of(pa(x)).expect("tours stay in the region");
        visits
            .of_pixel(i)
            .iter()
            .map(move |&k| (k + m - sb % m) % m)
            .filter(move |&y| y < nb)
    };
    if na == 1 {
        return in_b(0).next().map(|_| vec![run(sb, nb)]);
    }
    let pass = |at: &dyn Fn(usize) -> Pixel, n: usize, x: usize| {
        let h = at((x + n - 1) % n).dir_to(at(x)).expect("walk");
        let g = at(x).dir_to(at((x + 1) % n)).expect("walk");
        (h, g)
    };
    // (turn change, position in b, position in a, b reversed): the least.
    let mut best: Option<(i64, usize, usize, bool)> = None;
    let xs: Vec<usize> = match only_u_turns {
        None => (0..na).collect(),
        Some(turns) => {
            // Inner positions of a: U-turns of the walk in the cyclic range sa+1 ..= sa+na-2.
            let (lo, hi) = ((sa + 1) % m, (sa + na - 1) % m);
            let u = &turns.u_turns;
            let from = |s: usize| u.partition_point(|&k| k < s);
            let inner: Vec<usize> = if lo <= hi {
                u[from(lo)..from(hi)].to_vec()
            } else {
                u[from(lo)..]
                    .iter()
                    .chain(&u[..from(hi)])
                    .copied()
                    .collect()
            };
            let mut xs = vec![0];
            xs.extend(inner.into_iter().map(|k| (k + m - sa % m) % m));
            xs.push(na - 1);
            xs
        }
    };
    for x in xs {
        for y in in_b(x) {
            let ((h1, g1), (h2, g2)) = (pass(&pa, na, x), pass(&pb, nb, y));
            let old = i64::from(h1.turn_to(g1) + h2.turn_to(g2));
            let forward = i64::from(h2.turn_to(g1) + h1.turn_to(g2));
            let backward = i64::from(g2.opposite().turn_to(g1) + h1.turn_to(h2.opposite()));
            if only_u_turns.is_some() && old < 4 {
                continue;
            }
            for (cost, rev) in [(forward, false), (backward, true)] {
                let key = (cost - old, y, x, rev);
                if best.is_none_or(|b| key < b) {
                    best = Some(key);
                }
            }
        }
    }
    let (_, y, x, rev) = best?;
    let mut out = vec![run(sa + x, na - x), run(sa, x)];
    if rev {
        out.extend([rev_run(sb, y + 1), rev_run(sb + y + 1, nb - y - 1)]);
    } else {
        out.extend([run(sb + y, nb - y), run(sb, y)]);
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
fn reroute_at(
    region: &Region,
    walk: &Walk,
    cur: &Turns,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Vec<Piece>> {
    let m = walk.len();
    if m < 3 {
        return None;
    }
    let turns = cur.total;
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
                        dist.get(&(q * 4 + d.index()))
                            .map(|c| (d, c.0 + u64::from(d.turn_to(h_out))))
                    })
                    .min_by_key(|&(_, c)| c)
                else {
                    continue;
                };
                let new_turns = dist[&(q * 4 + d.index())].0 + u64::from(d.turn_to(h_out));
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
                let new = path[..path.len() - 1].iter().map(|&r| region.pixel(r));
                let out = vec![Piece::New(new.collect()), run(j, m - a - b)];
                match cur.cost(walk, &out) {
                    Some((n, t)) if t <= budget && n >= 2 => return Some(out),
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
fn excise_and_graft(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    before: u64,
    p: usize,
    budget: u64,
) -> Option<Vec<Piece>> {
    let m = walk.len();
    let target = region.pixel(p);
    let idx = |q: Pixel| region.index_of(q).expect("tours stay in the region");
    let at: Vec<usize> = (0..m).filter(|&k| walk[k] == target).collect();
    let excess = |c: u32| u64::from(c.saturating_sub(4));
    for &i in &at {
        for &j in &at {
            let len = (j + m - i) % m;
            if i == j || len + 2 > m {
                continue;
            }
            // Coverage left where it changes (every pixel is covered before the move).
            let mut left: std::collections::HashMap<usize, u32, PixelHash> = Default::default();
            for k in 1..=len {
                let q = idx(walk[(i + k) % m]);
                *left.entry(q).or_insert(count[q]) -= 1;
            }
            let mut lost: Vec<usize> = left.iter().filter(|e| *e.1 == 0).map(|e| *e.0).collect();
            if lost.len() > GRAFTS {
                continue;
            }
            lost.sort_unstable();
            let mut out = rebuild(walk, &[run((i + 1 + len) % m, m - len)]);
            for &u in &lost {
                if left[&u] > 0 {
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
                *left.entry(u).or_insert(count[u]) += 1;
                *left.entry(idx(q)).or_insert(count[idx(q)]) += 1;
            }
            if left.values().any(|&c| c == 0) {
                continue;
            }
            let after = before + left.values().map(|&c| excess(c)).sum::<u64>()
                - left.keys().map(|&q| excess(count[q])).sum::<u64>();
            if after >= before {
                continue;
            }
            match walk_cost(&out) {
                Ok((_, t)) if t <= budget => return Some(vec![Piece::New(out)]),
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
fn reverse_then_reroute(
    region: &Region,
    walk: &Walk,
    count: &[u32],
    p: usize,
    budget: u64,
) -> Option<Vec<Piece>> {
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
                let Some(turns) = Turns::of(&out) else {
                    continue;
                };
                if turns.total > budget || j - i < 2 {
                    continue;
                }
                let fits = |w: &Vec<Piece>| turns.cost(&out, w).is_some_and(|(_, t)| t <= budget);
                if let Some(w) = excise_at(region, &out, &turns, count, p)
                    .filter(fits)
                    .or_else(|| reroute_at(region, &out, &turns, count, p, budget))
                {
                    return Some(vec![Piece::New(rebuild(&out, &w))]);
                }
            }
        }
    }
    None
}

/// Min-turn paths (ties: fewer moves) from `start`, entered with heading `h_in`, over states
/// (pixel, heading) = `4 * pixel + heading`, of at most `limit` (turns, moves); pixel `avoid`
/// may end a path but is never passed through. The states reached are kept in maps, so the
/// search costs only what its bounds let it reach.
#[allow(clippy::type_complexity)]
fn min_turn_paths(
    region: &Region,
    start: usize,
    h_in: Dir,
    avoid: usize,
    limit: (u64, u64),
) -> (StateMap<(u64, u64)>, StateMap<usize>) {
    let mut dist: StateMap<(u64, u64)> = Default::default();
    let mut prev: StateMap<usize> = Default::default();
    let mut heap = std::collections::BinaryHeap::new();
    // A virtual state: at `start` with heading h_in, before any move; not stored in `dist` so
    // that paths have at least one move.
    let push = |heap: &mut std::collections::BinaryHeap<_>,
                dist: &mut StateMap<(u64, u64)>,
                prev: &mut StateMap<usize>,
                s: usize,
                c: (u64, u64),
                from: usize| {
        if c.0 <= limit.0 && c.1 <= limit.1 && dist.get(&s).is_none_or(|&d| c < d) {
            dist.insert(s, c);
            prev.insert(s, from);
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
        if dist.get(&s) != Some(&c) {
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

/// States (pixel, heading) of [`min_turn_paths`] mapped to their values.
type StateMap<T> = std::collections::HashMap<usize, T, PixelHash>;

/// The pixels of the path found by [`min_turn_paths`] ending at pixel `q` with heading `d`,
/// start included.
fn trace(prev: &StateMap<usize>, q: usize, d: Dir) -> Vec<usize> {
    let mut out = vec![q];
    let mut s = q * 4 + d.index();
    loop {
        let p = prev[&s];
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
///
/// A tour that misses a pixel of the region, or has a walk with a non-move, is not a covering
/// tour (the checker rejects it): it is returned unchanged, resp. that walk is left alone.
pub fn coverage4(region: &Region, tour: &CycleCover) -> (CycleCover, usize) {
    let mut search = Search::new(region, tour);
    while search.step() {}
    search.finish()
}

/// The state of the local search of [`coverage4`], kept up to date by every move: the walks
/// with their turns per position, the coverage of every pixel, the excess Σ max(0, c − 4),
/// and the pixels still to treat (covered more than 4 times and not found stuck), by coverage.
struct Search<'a> {
    region: &'a Region,
    cycles: Vec<Walk>,
    turns: Vec<Option<Turns>>,
    /// Built when first needed, dropped when the walk changes.
    visits: Vec<Option<Visits>>,
    budgets: Vec<u64>,
    count: Vec<u32>,
    excess: u64,
    queue: std::collections::BTreeSet<(u32, usize)>,
    stuck: Vec<bool>,
    stuck_list: Vec<usize>,
}

impl<'a> Search<'a> {
    fn new(region: &'a Region, tour: &CycleCover) -> Search<'a> {
        let cycles = tour.cycles.clone();
        let budgets = cycles
            .iter()
            .map(|w| walk_cost(w).map_or(0, |(_, t)| t))
            .collect();
        let mut count = vec![0u32; region.len()];
        for p in cycles.iter().flatten() {
            if let Some(i) = region.index_of(*p) {
                count[i] += 1;
            }
        }
        let covering = !count.contains(&0);
        let queue = (0..region.len())
            .filter(|&i| covering && count[i] > 4)
            .map(|i| (count[i], i))
            .collect();
        Search {
            region,
            turns: cycles.iter().map(Turns::of).collect(),
            visits: cycles.iter().map(|_| None).collect(),
            cycles,
            budgets,
            excess: count.iter().map(|&c| u64::from(c.saturating_sub(4))).sum(),
            count,
            queue,
            stuck: vec![false; region.len()],
            stuck_list: Vec::new(),
        }
    }

    /// One round at the most covered pixel left (ties: the last in region order): the first
    /// move that applies on the first walk where one does. `false` when no pixel is left.
    fn step(&mut self) -> bool {
        let Some(&(_, p)) = self.queue.last() else {
            return false;
        };
        let (region, count, now) = (self.region, &self.count, self.excess);
        let mut moved = None;
        for (w, (walk, visits)) in self.cycles.iter().zip(&mut self.visits).enumerate() {
            let (Some(turns), budget) = (&self.turns[w], self.budgets[w]) else {
                continue;
            };
            moved = excise_at(region, walk, turns, count, p)
                .or_else(|| pair_drop_at(region, walk, turns, visits, count, now, p, budget))
                .or_else(|| reroute_at(region, walk, turns, count, p, budget))
                .or_else(|| excise_and_graft(region, walk, count, now, p, budget))
                .or_else(|| reverse_then_reroute(region, walk, count, p, budget))
                .or_else(|| slide_chain(region, walk, turns, visits, count, now, p, budget))
                .map(|pieces| (w, pieces));
            if moved.is_some() {
                break;
            }
        }
        match moved {
            Some((w, pieces)) => {
                self.apply(w, &pieces);
                for s in std::mem::take(&mut self.stuck_list) {
                    self.stuck[s] = false;
                    if self.count[s] > 4 {
                        self.queue.insert((self.count[s], s));
                    }
                }
            }
            None => {
                self.stuck[p] = true;
                self.stuck_list.push(p);
                self.queue.remove(&(self.count[p], p));
            }
        }
        true
    }

    /// Walk `w` rewritten as `pieces`: the coverage, the excess and the queue change only at
    /// the positions dropped and the pixels added; the turns per position are recounted.
    fn apply(&mut self, w: usize, pieces: &[Piece]) {
        let walk = &self.cycles[w];
        let gone: Vec<Pixel> = dropped(walk.len(), pieces)
            .into_iter()
            .map(|k| walk[k])
            .collect();
        let new = rebuild(walk, pieces);
        for q in gone {
            self.change(q, -1);
        }
        for piece in pieces {
            if let Piece::New(px) = piece {
                px.iter().for_each(|&q| self.change(q, 1));
            }
        }
        self.turns[w] = Turns::of(&new);
        self.visits[w] = None;
        self.cycles[w] = new;
    }

    fn change(&mut self, q: Pixel, delta: i32) {
        let Some(i) = self.region.index_of(q) else {
            return;
        };
        let old = self.count[i];
        let new = old
            .checked_add_signed(delta)
            .expect("a dropped visit was counted");
        self.count[i] = new;
        self.excess =
            self.excess + u64::from(new.saturating_sub(4)) - u64::from(old.saturating_sub(4));
        if !self.stuck[i] {
            if old > 4 {
                self.queue.remove(&(old, i));
            }
            if new > 4 {
                self.queue.insert((new, i));
            }
        }
    }

    fn finish(self) -> (CycleCover, usize) {
        let left = self.count.iter().filter(|&&c| c > 4).count();
        (CycleCover::new(self.cycles), left)
    }
}

mod slide;

#[cfg(test)]
mod reference;
#[cfg(test)]
mod tests;
