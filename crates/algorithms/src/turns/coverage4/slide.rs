//! Slide chains of the four-coverage repair: a walk read as pieces of a base walk ([`View`])
//! and the chains of run slides that push excess visits to where there is room.

use super::{Piece, PixelHash, Turns, Visits, run};
use crate::region::{Dir, Pixel, Region};
use crate::tour::Walk;

/// A walk made of pieces of a base walk, read by position (a chain of slides in
/// [`slide_chain`] is kept so, without copying the walk).
pub(super) struct View<'a> {
    base: &'a Walk,
    pieces: Vec<Piece>,
    /// Position after each piece.
    ends: Vec<usize>,
}

impl<'a> View<'a> {
    fn new(base: &'a Walk, pieces: Vec<Piece>) -> View<'a> {
        let pieces: Vec<Piece> = pieces.into_iter().filter(|q| piece_len(q) > 0).collect();
        let mut ends = Vec::with_capacity(pieces.len());
        let mut at = 0;
        for q in &pieces {
            at += piece_len(q);
            ends.push(at);
        }
        View { base, pieces, ends }
    }

    fn len(&self) -> usize {
        self.ends.last().copied().unwrap_or(0)
    }

    fn at(&self, k: usize) -> Pixel {
        let k = k % self.len();
        let x = self.ends.partition_point(|&e| e <= k);
        let off = k - if x == 0 { 0 } else { self.ends[x - 1] };
        match &self.pieces[x] {
            Piece::New(px) => px[off],
            &Piece::Run { start, len, rev } => {
                let t = if rev { len - 1 - off } else { off };
                self.base[(start + t) % self.base.len()]
            }
        }
    }

    /// Pieces of the `len` positions from `from` on (cyclically).
    fn sub(&self, from: usize, len: usize) -> Vec<Piece> {
        let m = self.len();
        let mut out = Vec::new();
        let (mut k, mut left) = (from % m, len);
        while left > 0 {
            let x = self.ends.partition_point(|&e| e <= k);
            let begin = if x == 0 { 0 } else { self.ends[x - 1] };
            let (off, take) = (k - begin, left.min(self.ends[x] - k));
            out.push(match &self.pieces[x] {
                Piece::New(px) => Piece::New(px[off..off + take].to_vec()),
                &Piece::Run { start, len, rev } => Piece::Run {
                    start: if rev {
                        start + (len - off - take)
                    } else {
                        start + off
                    },
                    len: take,
                    rev,
                },
            });
            left -= take;
            k = (k + take) % m;
        }
        out
    }

    /// Positions of the visits of pixel `q` (region index `i`), in walk order.
    fn visits(&self, q: Pixel, i: usize, index: &Visits) -> Vec<usize> {
        let bm = self.base.len();
        let mut out = Vec::new();
        let mut begin = 0;
        for (piece, &end) in self.pieces.iter().zip(&self.ends) {
            match piece {
                Piece::New(px) => {
                    out.extend((0..px.len()).filter(|&t| px[t] == q).map(|t| begin + t));
                }
                &Piece::Run { start, len, rev } => {
                    for &k in index.of_pixel(i) {
                        let t = (k + bm - start % bm) % bm;
                        if t < len {
                            out.push(begin + if rev { len - 1 - t } else { t });
                        }
                    }
                }
            }
            begin = end;
        }
        out.sort_unstable();
        out
    }
}

pub(super) fn piece_len(piece: &Piece) -> usize {
    match piece {
        Piece::New(px) => px.len(),
        Piece::Run { len, .. } => *len,
    }
}

/// Heading of the move from position `k` to `k + 1` of a view (cyclically).
pub(super) fn view_heading(walk: &View, k: usize) -> Dir {
    walk.at(k)
        .dir_to(walk.at(k + 1))
        .expect("walks move between 4-adjacent pixels")
}

/// The maximal straight runs of the walk through position `k`, as (first position, moves):
/// one for a straight pass, the incoming and the outgoing one at a turn.
pub(super) fn runs_at(walk: &View, k: usize) -> Vec<(usize, usize)> {
    let m = walk.len();
    let heading = view_heading;
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
/// slid run, as pieces of the view's base walk) and the pixels whose visits it removed and
/// added.
pub(super) fn slide(
    region: &Region,
    walk: &View,
    s: usize,
    len: usize,
    v: Dir,
) -> Option<SlideResult> {
    let m = walk.len();
    if len == 0 || m < len + 3 {
        return None;
    }
    let old: Vec<Pixel> = (0..=len).map(|t| walk.at(s + t)).collect();
    let moved: Vec<Pixel> = old.iter().map(|q| q.step(v)).collect();
    if !moved.iter().all(|&q| region.contains(q)) {
        return None;
    }
    let (before, after) = (walk.at(s + m - 1), walk.at(s + len + 1));
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
    let mut out = vec![Piece::New(added.clone())];
    out.extend(walk.sub(s + len + 1, m - len - 1));
    Some((out, old, added))
}

/// A slid walk with the pixels it stopped and started visiting (see [`slide`]).
pub(super) type SlideResult = (Vec<Piece>, Vec<Pixel>, Vec<Pixel>);
/// How many slides one chain of [`slide_chain`] may take.
pub(super) const SLIDE_DEPTH: usize = 8;

/// How many chains [`slide_chain`] extends before it gives up at one pixel.
pub(super) const SLIDE_EXPANSIONS: usize = 300;

/// A chain of at most [`SLIDE_DEPTH`] slides ([`slide`]): the first of a run through pixel
/// `p`, each later one of a run through a pixel the previous slide left above 4, ending with
/// the excess coverage Σ max(0, c − 4) lower than before, every pixel covered and the turns
/// within `budget`. A slide moves a whole link, so one slide often just passes the excess to
/// the next row or column; the chain pushes it on to where there is room. Chains are
/// extended best first (least excess, then fewest slides), at most [`SLIDE_EXPANSIONS`].
#[allow(clippy::too_many_arguments)]
pub(super) fn slide_chain(
    region: &Region,
    walk: &Walk,
    turns: &Turns,
    index: &mut Option<Visits>,
    count: &[u32],
    goal: u64,
    p: usize,
    budget: u64,
) -> Option<Vec<Piece>> {
    use std::cmp::Reverse;
    let excess = |c: u32| u64::from(c.saturating_sub(4));
    let idx = |q: Pixel| region.index_of(q).expect("slides stay in the region");
    // Chains by (excess, slides, order of discovery): walk, coverage where it changed,
    // pixels to slide from.
    type Changed = std::collections::HashMap<usize, u32, PixelHash>;
    let mut chains = vec![(vec![run(0, walk.len())], Changed::default(), vec![p])];
    let index = &*index.get_or_insert_with(|| Visits::of(region, walk));
    let base = walk;
    let mut heap = std::collections::BinaryHeap::from([Reverse((goal, 0usize, 0usize))]);
    let mut expansions = 0;
    while let Some(Reverse((now, depth, id))) = heap.pop() {
        if depth == SLIDE_DEPTH || expansions == SLIDE_EXPANSIONS {
            continue;
        }
        expansions += 1;
        let (pieces, changes, from) = chains[id].clone();
        let walk = View::new(base, pieces);
        let cov = |q: usize| changes.get(&q).copied().unwrap_or(count[q]);
        for &q in &from {
            let target = region.pixel(q);
            let mut tried = std::collections::HashSet::new();
            let visits = walk.visits(target, q, index);
            for k in visits {
                for (s, len) in runs_at(&walk, k) {
                    let h = view_heading(&walk, s);
                    for v in [h.left(), h.right()] {
                        if !tried.insert((s, v)) {
                            continue;
                        }
                        let Some((out, removed, added)) = slide(region, &walk, s, len, v) else {
                            continue;
                        };
                        let mut next = changes.clone();
                        removed
                            .iter()
                            .for_each(|&r| *next.entry(idx(r)).or_insert(cov(idx(r))) -= 1);
                        added
                            .iter()
                            .for_each(|&r| *next.entry(idx(r)).or_insert(cov(idx(r))) += 1);
                        if removed.iter().any(|&r| next[&idx(r)] == 0) {
                            continue;
                        }
                        let changed: std::collections::BTreeSet<usize> =
                            removed.iter().chain(&added).map(|&r| idx(r)).collect();
                        let after = now + changed.iter().map(|&r| excess(next[&r])).sum::<u64>()
                            - changed.iter().map(|&r| excess(cov(r))).sum::<u64>();
                        if turns.cost(base, &out).is_none_or(|(_, t)| t > budget) {
                            continue;
                        }
                        if after < goal {
                            return Some(out);
                        }
                        let over: Vec<usize> =
                            changed.into_iter().filter(|&r| next[&r] > 4).collect();
                        heap.push(Reverse((after, depth + 1, chains.len())));
                        chains.push((out, next, over));
                    }
                }
            }
        }
    }
    None
}
