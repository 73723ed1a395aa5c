//! Strip ends matched over ALL pairs in the graph metric of the region's maximal runs (one
//! edge per turn), solved by fusion-blossom.

use super::*;

/// Above this many defects in a block of the run graph, fusion-blossom runs on a partition
/// of it (still exact, one thread): its serial solver grows quadratically with the defects.
/// Measured on random-simple 10^5 (largest block 5,784 defects): 6.4 s at 1,000, 6.7 s at
/// 2,000 and 4,000, 12 s serially.
pub(super) const SERIAL_LIMIT: usize = 1000;

/// Partition leaves of about this many run-graph vertices (above [`SERIAL_LIMIT`]).
pub(super) const LEAF: usize = 4000;

/// Extents (x0, x1, y0, y1) of run-graph vertices, for the partition.
pub(super) type Extent = (i32, i32, i32, i32);

/// The empty extent.
pub(super) const NO_EXTENT: Extent = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);

/// Widens `e` to cover `o`.
pub(super) fn widen(e: &mut Extent, o: Extent) {
    *e = (e.0.min(o.0), e.1.max(o.1), e.2.min(o.2), e.3.max(o.3));
}

/// `vertices` extents, the first ones those of the runs of `graph`, the rest empty.
pub(super) fn run_extents(region: &Region, graph: &RunGraph, vertices: usize) -> Vec<Extent> {
    let mut extent = vec![NO_EXTENT; vertices];
    for (r, px) in graph.pixels.iter().enumerate() {
        for &q in px {
            let at = region.pixel(q);
            widen(&mut extent[r], (at.x, at.x, at.y, at.y));
        }
    }
    extent
}

/// The run graph of a region: its maximal horizontal and vertical runs of pixels, joined by
/// an edge where they cross (one turn). For two strip ends, the turn distance is the
/// distance between their runs in this graph (see [`run_graph_matching`]).
pub(super) struct RunGraph {
    /// The horizontal and the vertical run through every pixel.
    pub(super) hrun: Vec<usize>,
    pub(super) vrun: Vec<usize>,
    /// The pixels of every run, in order.
    pub(super) pixels: Vec<Vec<usize>>,
    /// Whether a run is vertical.
    pub(super) vertical: Vec<bool>,
}

impl RunGraph {
    pub(super) fn new(region: &Region) -> RunGraph {
        let n = region.len();
        let mut g = RunGraph {
            hrun: vec![usize::MAX; n],
            vrun: vec![usize::MAX; n],
            pixels: Vec::new(),
            vertical: Vec::new(),
        };
        for s in 0..n {
            for (vertical, back, fwd) in [(false, Dir::W, Dir::E), (true, Dir::S, Dir::N)] {
                let run = if vertical { &mut g.vrun } else { &mut g.hrun };
                if run[s] != usize::MAX {
                    continue;
                }
                let mut q = s;
                while let Some(b) = region.neighbor(q, back) {
                    q = b;
                }
                let mut px = vec![q];
                while let Some(f) = region.neighbor(q, fwd) {
                    q = f;
                    px.push(q);
                }
                for &q in &px {
                    run[q] = g.pixels.len();
                }
                g.pixels.push(px);
                g.vertical.push(vertical);
            }
        }
        g
    }

    /// The run a strip end leaves along, if its headings are exactly one axis.
    pub(super) fn run_of(&self, port: Port) -> Option<usize> {
        let v = bit(Dir::N) | bit(Dir::S);
        let h = bit(Dir::E) | bit(Dir::W);
        match port.leave {
            l if l == v => Some(self.vrun[port.pixel]),
            l if l == h => Some(self.hrun[port.pixel]),
            _ => None,
        }
    }

    /// The run crossing run `r` at pixel `px`.
    pub(super) fn crossing(&self, r: usize, px: usize) -> usize {
        if self.vertical[r] {
            self.hrun[px]
        } else {
            self.vrun[px]
        }
    }
}

/// An exact minimum-weight perfect matching of strip ends over ALL pairs, as a minimum-weight
/// perfect matching of vertices in a graph metric, solved by fusion-blossom (an exact
/// primal–dual blossom algorithm on the graph itself, so no pair needs to be listed).
///
/// The graph: the [`RunGraph`] (crossing runs at weight 2 = one turn), and per endpoint a
/// vertex hanging from its run at weight 2. Two endpoints are then at distance 4 + 2·w,
/// w their turn distance: every perfect matching costs 2P + 2·w(M), the same order. A
/// path of the 0-1 search maps to a walk in the run graph with one edge per turn and back
/// (a strip end leaves in both headings of its axis, so the first and last run may be
/// walked either way).
///
/// A one-pixel strip (`floor` 2, both ends the same port) costs 2 when matched to itself,
/// not its turn distance 0; the metric cannot say that directly, so:
/// - if its run R carries another endpoint, or another such strip, the strip is taken out
///   and put back afterwards at no cost: a path u – a₁b₁ – … – a_kb_k – v through strips on R
///   costs at least w(u, R) + w(R, v) ≥ w(u, v), so leaving them out loses nothing, and
///   threading them into the pair of an endpoint x on R (x – a₁, b₁ – a₂, …, b_k – mate(x)),
///   or closing them among themselves, costs exactly that much again;
/// - otherwise (every other endpoint is at least one turn from R) its two ends hang from the
///   runs crossing R at weight 4 (one turn more), which keeps their distance 4 + 2w to every
///   other endpoint and makes theirs 8 (= 2 turns); two such strips on crossing runs get a
///   direct edge of weight 6 (1 turn).
///
/// **Only the odd runs go to the solver** (the T-join reduction). Write G' for the graph
/// without the hanging endpoints. A path from a hanging endpoint leaves by its edge of weight
/// 2 to its run, so a pair costs d' between the pair's images (the run of a hanging end, a lone
/// end itself) plus 2 per hanging end in it; every perfect matching M of the P' endpoints kept
/// costs 2P' + 2·w(M) = 2H + Σ_M d'(images), H the number of hanging ends. Pairing the images of M is a pairing of the multiset of
/// images, and the union of shortest paths of any such pairing, taken mod 2, is a T'-join of
/// G', where T' holds the runs with an odd number of hanging ends and the lone ends: so
/// Σ_M d' ≥ the minimum T'-join, which equals the minimum perfect matching of T' in the
/// metric of G' (Edmonds–Johnson: a minimum T-join with non-negative weights splits into
/// |T|/2 paths). Conversely a matching of T' (an odd run giving up one of its ends) plus the
/// other ends paired on their own runs (distance 4, turn distance 0) costs exactly that. The
/// solver therefore matches T' only: each odd run gets a pendant vertex at weight 2 (a defect
/// on the run vertex itself made the partitioned solver panic), so its dual sum D bounds
/// 2|T'| + the minimum over matchings of T', and 2H + D − 2|T'| bounds 2P' + 2·w(M) for every M.
/// On random-holed 10^5 this halves the solver's defects (12,514 odd runs for 27,952 ends).
///
/// The matching's weights are then recounted by 0-1 searches, and the lower bound is
/// ⌈(bound − 2P')/2⌉ turns from the bound above (weak LP duality): `optimal` exactly when the
/// recount reaches it. `None` when the endpoints are not all strip ends with floors as above, or the
/// solver fails (the caller falls back to [`priced_matching`]).
pub(super) fn run_graph_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Option<Result<PortMatching>> {
    let p = ports.len();
    let graph = RunGraph::new(region);
    let mut run = Vec::with_capacity(p);
    for (i, &port) in ports.iter().enumerate() {
        run.push(graph.run_of(port)?);
        let one_pixel = floor[i] == 2 && ports[partner[i]] == port && floor[partner[i]] == 2;
        if floor[i] != 0 && !one_pixel {
            return None;
        }
    }
    let one_pixel = |i: usize| floor[i] != 0;
    let runs = graph.pixels.len();
    let (mut others, mut singles) = (vec![0usize; runs], vec![0usize; runs]);
    for i in 0..p {
        if !one_pixel(i) {
            others[run[i]] += 1;
        } else if i < partner[i] {
            singles[run[i]] += 1;
        }
    }
    let removed = |i: usize| one_pixel(i) && (others[run[i]] > 0 || singles[run[i]] >= 2);
    // Vertices: runs, then the lone one-pixel strip ends kept. The other ends kept hang from
    // their runs and are not vertices (see the reduction above).
    let mut edges: Vec<(usize, usize, isize)> = (0..region.len())
        .map(|px| (graph.hrun[px], graph.vrun[px], 2))
        .collect();
    let mut kept: Vec<usize> = Vec::new();
    let mut vertex_of = vec![usize::MAX; p];
    let mut hanging: Vec<Vec<usize>> = vec![Vec::new(); runs];
    let mut lone_ends = 0;
    for i in (0..p).filter(|&i| !removed(i)) {
        kept.push(i);
        if one_pixel(i) {
            vertex_of[i] = runs + lone_ends;
            lone_ends += 1;
            let r = run[i];
            for &px in &graph.pixels[r] {
                edges.push((graph.crossing(r, px), vertex_of[i], 4));
            }
        } else {
            vertex_of[i] = run[i];
            hanging[run[i]].push(i);
        }
    }
    // Lone one-pixel strips on crossing runs: one turn apart.
    let mut lone: HashMap<usize, Vec<usize>> = HashMap::new();
    for &i in kept.iter().filter(|&&i| one_pixel(i)) {
        lone.entry(run[i]).or_default().push(i);
    }
    for (&r, ends) in &lone {
        for &px in &graph.pixels[r] {
            let c = graph.crossing(r, px);
            if let Some(theirs) = lone.get(&c).filter(|_| r < c) {
                for &a in ends {
                    for &b in theirs {
                        edges.push((vertex_of[a], vertex_of[b], 6));
                    }
                }
            }
        }
    }
    // The odd runs and the lone ends: the set T' of the reduction. Every odd run gets a
    // pendant vertex at weight 2 that stands for it (fusion-blossom's partitioned solver
    // was seen to panic with defects on high-degree vertices).
    let odd: Vec<usize> = (0..runs).filter(|&r| hanging[r].len() % 2 == 1).collect();
    let first_pendant = runs + lone_ends;
    for (k, &r) in odd.iter().enumerate() {
        edges.push((r, first_pendant + k, 2));
    }
    let vertices = first_pendant + odd.len();
    let defects: Vec<usize> = (runs..vertices).collect();
    let hung = kept.len() - lone_ends;
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        eprintln!(
            "run graph: {p} ends, {} kept, {runs} runs, {} odd runs, {lone_ends} lone ends, {} edges",
            kept.len(),
            odd.len(),
            edges.len()
        );
    }
    let end_of_lone: HashMap<usize, usize> = kept
        .iter()
        .filter(|&&i| one_pixel(i))
        .map(|&i| (vertex_of[i], i))
        .collect();
    let (mut mate, dual) = mates_of(p, || {
        let (pairs, dual) =
            solve_graph_matching(SERIAL_LIMIT, vertices, edges, &defects, |edges| {
                // A run spans its pixels; a lone end the runs it hangs from.
                let mut extent = run_extents(region, &graph, vertices);
                for &(a, b, _) in edges {
                    if a < runs && b >= runs {
                        let o = extent[a];
                        widen(&mut extent[b], o);
                    }
                }
                extent
            })?;
        // A matched odd run gives up its last hanging end to the pair; the others pair up
        // on their run (turn distance 0).
        let mut out = Vec::with_capacity(kept.len() / 2);
        let mut spare: Vec<Option<usize>> = vec![None; runs];
        for (r, ends) in hanging.iter().enumerate() {
            let mut ends = &ends[..];
            if ends.len() % 2 == 1 {
                spare[r] = Some(ends[ends.len() - 1]);
                ends = &ends[..ends.len() - 1];
            }
            out.extend(ends.chunks_exact(2).map(|c| (c[0], c[1])));
        }
        let mut end = |v: usize| {
            if v >= first_pendant {
                spare[odd[v - first_pendant]].take()
            } else {
                end_of_lone.get(&v).copied()
            }
        };
        for (a, b) in pairs {
            out.push((end(a)?, end(b)?));
        }
        Some((out, dual - 2 * odd.len() as i64 + 2 * hung as i64))
    })?;
    if kept.iter().any(|&i| mate[i] == usize::MAX) {
        return None;
    }
    // Put the one-pixel strips taken out back in, run by run.
    let mut taken: HashMap<usize, Vec<usize>> = HashMap::new();
    for i in (0..p).filter(|&i| removed(i) && i < partner[i]) {
        taken.entry(run[i]).or_default().push(i);
    }
    let mut taken: Vec<(usize, Vec<usize>)> = taken.into_iter().collect();
    taken.sort_unstable();
    let mut on_run: HashMap<usize, usize> = HashMap::new();
    for &i in &kept {
        if !one_pixel(i) {
            on_run.entry(run[i]).or_insert(i);
        }
    }
    let pair = |mate: &mut [usize], a: usize, b: usize| {
        mate[a] = b;
        mate[b] = a;
    };
    for (r, strips) in taken {
        match on_run.get(&r) {
            // Threaded between x and its mate: x – a₁, b₁ – a₂, …, b_k – mate(x).
            Some(&x) => {
                let y = mate[x];
                let mut prev = x;
                for &a in &strips {
                    pair(&mut mate, prev, a);
                    prev = partner[a];
                }
                pair(&mut mate, prev, y);
            }
            // Closed among themselves (at least two): b₁ – a₂, …, b_k – a₁.
            None => {
                for k in 0..strips.len() {
                    pair(
                        &mut mate,
                        partner[strips[k]],
                        strips[(k + 1) % strips.len()],
                    );
                }
            }
        }
    }
    // Every pair of the graph costs 4 + 2w, over the P' endpoints kept.
    Some(recount(region, ports, partner, floor, mate).map(|m| certified(m, dual, kept.len())))
}
