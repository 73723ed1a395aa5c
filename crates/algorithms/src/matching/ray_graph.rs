//! Boundary link ends matched over ALL pairs in the "ray graph" metric 2w + 4, solved by
//! fusion-blossom.

use super::*;

/// Above this many edges in the ray graph of [`link_graph_matching`] (its pairs of rays
/// sharing a pixel grow quadratically where many rays cross), the LP route is taken instead.
pub(super) const RAY_GRAPH_EDGES: usize = 4_000_000;

/// Above this many link ends, fusion-blossom would run on a partition of the ray graph: never.
/// Its partitioned solver panicked on every ray-graph block above 40,000 ends that we measured
/// (pointers.rs:143; first on 8,274 ends), and the serial retry then solved it again from the
/// start, so the partitioned attempt only cost time (boundary-cc on boundary-rooms at 10^5
/// pixels, `scripts/speed-table.sh`: 16.25 s and 1720 MB with it, 6.86 s and 1052 MB without;
/// the same matching).
pub(super) const RAY_SERIAL_LIMIT: usize = usize::MAX;

/// An exact minimum-weight perfect matching of boundary link ends (one heading each) over ALL
/// pairs, as a minimum-weight perfect matching of vertices in a graph metric, solved by
/// fusion-blossom (see [`run_graph_matching`] for strip ends).
///
/// # The turn distance of one-heading ends
/// The ray F_u of an end u is the part of its run (the maximal run through its pixel along
/// its heading) from its pixel on in its heading: the pixels a path leaving u reaches before
/// its first turn; symmetrically a path arriving at v ends with a piece of F_v. Let A_u be
/// the runs crossing F_u. Then
///
/// - if F_u and F_v share a pixel q, w(u, v) = the quarter turns from u's heading to the
///   reverse of v's (turn in place at q; no path does better): 0 for facing rays on one run,
///   1 for crossing rays, 2 for rays of one heading;
/// - otherwise w(u, v) = 2 + min over C ∈ A_u, D ∈ A_v of dist(C, D), the distance in the
///   run graph ([`RunGraph`], one edge per turn). A path with k ≥ 2 turns runs along F_u,
///   turns onto C ∈ A_u, then along whole runs, and turns from D ∈ A_v onto F_v; after its
///   first turn it may walk its run either way (it could have turned the other way at the
///   same cost), so its middle runs form a walk C … D with k − 2 edges. Conversely every such
///   walk is a path. With k ≤ 1 turns the rays share a pixel.
///
/// Unlike strip ends, w is no metric: two ends facing a third (w = 0) may be 2 apart.
/// But w(u, v) ≤ w(u, x) + w(x, v) + 2 (join the paths with a U-turn at x), so
/// W = 2w + 4 is one, and every perfect matching costs 2P + 2·w(M), the same order.
///
/// # The graph
/// Its vertices are the runs, the endpoints, and clones of some runs (below); crossing runs
/// are joined at weight 2 (a turn), an end hangs from every run of A_u at weight 4 (a turn
/// plus its offset), so the path u – C … D – v costs exactly W for the second case. Pairs
/// whose rays share a pixel get an edge of their own, W = 4 (facing) or 6 (crossing); rays of
/// one heading sharing a pixel meet at the run crossing there (W = 8). Any path of the graph
/// splits at the ends it passes into such pieces, each a path of the region of its weight,
/// and by the inequality above it costs at least W: distances are exactly W. (The facing and
/// crossing pairs cannot share gadgets: the midpoints of their shortest paths are distinct for
/// distinct pairs, so their count is inherent.)
///
/// # One-pixel links
/// The two ends a (heading W or S) and b (E or N) of a one-pixel link at pixel p cost
/// `floor` = 4 when matched together, not their w = 0. W stays a metric with W(a, b) = 12:
/// for every other end x, w(a, x) + w(b, x) ≥ 2 (x facing a has b's heading, and x one turn
/// from a is an odd number of turns from b). In the graph, the facing edge a – b is left out,
/// a hangs from the run C crossing at p and b from a clone C' of C (joined to every copy of
/// C's crossing runs, and hung from by every other end that hangs from C); crossing runs are
/// copied both ways. Then a – b costs 12 (C and C' are at least two edges apart, other runs
/// of A_a and A_b too, being parallel to C), and the ends a', b' of other one-pixel links
/// crossing C, 2 turns from b, a, get direct edges a – b', a' – b of weight 8.
///
/// The matching's weights are recounted by 0-1 searches, and the lower bound is the
/// solver's dual objective, as in [`run_graph_matching`]. `None` when an end has other than
/// one heading, a floor is not of a one-pixel link as above, the graph exceeds
/// [`RAY_GRAPH_EDGES`] edges, or the solver fails (the caller falls back to
/// [`priced_matching`]).
pub(super) fn link_graph_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Option<Result<PortMatching>> {
    let p = ports.len();
    let heading: Vec<Dir> = ports
        .iter()
        .map(|port| Dir::ALL.into_iter().find(|&d| port.leave == bit(d)))
        .collect::<Option<_>>()?;
    for i in 0..p {
        let j = partner[i];
        let one_pixel = ports[j].pixel == ports[i].pixel
            && heading[j] == heading[i].opposite()
            && floor[j] == 4;
        if floor[i] != 0 && !(floor[i] == 4 && one_pixel) {
            return None;
        }
    }
    let one_pixel = |i: usize| floor[i] != 0;
    let forward = |i: usize| matches!(heading[i], Dir::E | Dir::N);
    let graph = RunGraph::new(region);
    let runs = graph.pixels.len();
    // The position of every pixel in its horizontal (even slots) and vertical run.
    let mut pos = vec![0usize; 2 * region.len()];
    for (r, px) in graph.pixels.iter().enumerate() {
        for (k, &q) in px.iter().enumerate() {
            pos[2 * q + usize::from(graph.vertical[r])] = k;
        }
    }
    let along: Vec<usize> = (0..p)
        .map(|i| match heading[i] {
            Dir::E | Dir::W => graph.hrun[ports[i].pixel],
            Dir::N | Dir::S => graph.vrun[ports[i].pixel],
        })
        .collect();
    let at = |i: usize| pos[2 * ports[i].pixel + usize::from(graph.vertical[along[i]])];
    let ray = |i: usize| {
        let px = &graph.pixels[along[i]];
        if forward(i) {
            &px[at(i)..]
        } else {
            &px[..=at(i)]
        }
    };
    // Clones (vertices runs..) of the runs crossing one-pixel links.
    let mut clone: HashMap<usize, usize> = HashMap::new();
    let mut origin: Vec<usize> = Vec::new();
    for i in (0..p).filter(|&i| one_pixel(i)) {
        let c = graph.crossing(along[i], ports[i].pixel);
        clone.entry(c).or_insert_with(|| {
            origin.push(c);
            runs + origin.len() - 1
        });
    }
    let copies = |r: usize| std::iter::once(r).chain(clone.get(&r).copied());
    let first_end = runs + origin.len();
    let vertex_of: Vec<usize> = (0..p).map(|i| first_end + i).collect();
    let full = |edges: &Vec<(usize, usize, isize)>| edges.len() > RAY_GRAPH_EDGES;
    let mut edges: Vec<(usize, usize, isize)> = Vec::new();
    for px in 0..region.len() {
        for a in copies(graph.hrun[px]) {
            for b in copies(graph.vrun[px]) {
                edges.push((a, b, 2));
            }
        }
    }
    // Ends hang from the runs crossing their rays; (pixel, vertical, end) along every ray.
    let mut through: Vec<(usize, bool, usize)> = Vec::new();
    for i in 0..p {
        for &q in ray(i) {
            let c = graph.crossing(along[i], q);
            if one_pixel(i) && q == ports[i].pixel {
                let v = if forward(i) { clone[&c] } else { c };
                edges.push((v, vertex_of[i], 4));
            } else {
                for v in copies(c) {
                    edges.push((v, vertex_of[i], 4));
                }
            }
            through.push((q, graph.vertical[along[i]], i));
        }
        if full(&edges) {
            return None;
        }
    }
    // Rays crossing at a pixel: one turn.
    through.sort_unstable();
    for group in through.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for a in &group[..split] {
            for b in &group[split..] {
                edges.push((vertex_of[a.2], vertex_of[b.2], 6));
            }
        }
        if full(&edges) {
            return None;
        }
    }
    // Rays facing each other on one run: no turn (not the two ends of a one-pixel link).
    let mut on_run: Vec<(usize, bool, usize, usize)> =
        (0..p).map(|i| (along[i], !forward(i), at(i), i)).collect();
    on_run.sort_unstable();
    for group in on_run.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for &(_, _, x, u) in &group[..split] {
            for &(_, _, y, v) in &group[split..] {
                if x <= y && !(one_pixel(u) && partner[u] == v) {
                    edges.push((vertex_of[u], vertex_of[v], 4));
                }
            }
        }
        if full(&edges) {
            return None;
        }
    }
    // Ends of different one-pixel links crossing one run, hung from C and C': two turns.
    let mut lone: Vec<(usize, bool, usize)> = (0..p)
        .filter(|&i| one_pixel(i))
        .map(|i| (graph.crossing(along[i], ports[i].pixel), forward(i), i))
        .collect();
    lone.sort_unstable();
    for group in lone.chunk_by(|a, b| a.0 == b.0) {
        let split = group.partition_point(|e| !e.1);
        for &(_, _, a) in &group[..split] {
            for &(_, _, b) in &group[split..] {
                if partner[a] != b {
                    edges.push((vertex_of[a], vertex_of[b], 8));
                }
            }
        }
        if full(&edges) {
            return None;
        }
    }
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        eprintln!(
            "ray graph: {p} ends, {runs} runs, {} clones, {} edges",
            origin.len(),
            edges.len()
        );
    }
    let defects: Vec<usize> = (0..p).map(|i| vertex_of[i]).collect();
    let port_of: HashMap<usize, usize> = (0..p).map(|i| (vertex_of[i], i)).collect();
    let vertices = first_end + p;
    let (mate, dual) = mates_of(p, || {
        let (pairs, dual) =
            solve_graph_matching(RAY_SERIAL_LIMIT, vertices, edges, &defects, |edges| {
                // A run spans its pixels, a clone its run's, an end its own run and those it
                // hangs from (so that every edge joins vertices whose extents meet).
                let mut extent = run_extents(region, &graph, vertices);
                for (k, &c) in origin.iter().enumerate() {
                    extent[runs + k] = extent[c];
                }
                for i in 0..p {
                    let o = extent[along[i]];
                    widen(&mut extent[vertex_of[i]], o);
                }
                for &(a, b, _) in edges {
                    if a < first_end && b >= first_end {
                        let o = extent[a];
                        widen(&mut extent[b], o);
                    }
                }
                extent
            })?;
        Some((renamed(pairs, &port_of)?, dual))
    })?;
    if mate.contains(&usize::MAX) {
        return None;
    }
    let m = recount(region, ports, partner, floor, mate).map(|m| certified(m, dual, p));
    if let Ok(m) = &m
        && std::env::var_os("MOWMILL_MATCHING_LOG").is_some()
    {
        eprintln!("ray graph: w(M) {}, bound {}", m.total, m.lower_bound);
    }
    Some(m)
}
