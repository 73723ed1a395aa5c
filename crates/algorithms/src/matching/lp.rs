//! The LP route: the matching LP over candidate pairs solved by HiGHS, odd-set cutting planes,
//! pricing over all pairs by the duals (a proven lower bound), and the matching read off the LP
//! where integral, repaired by blossom where not.

use super::*;
use crate::exact::lp::GrowingLp;
use petgraph::unionfind::UnionFind;

/// Pricing keeps, per endpoint, this many cheapest absent partners per round.
pub(super) const PRICE_K: usize = 8;

/// At most this many rounds of odd-set cuts on the LP: [`CUT_BUDGET`] / P rounds for P
/// endpoints, clamped to [`CUT_ROUNDS_LARGE`]..=[`CUT_ROUNDS`] (a round costs about 10 µs
/// per endpoint, more on large instances).
pub(super) const CUT_ROUNDS: usize = 60;

/// See [`CUT_ROUNDS`].
pub(super) const CUT_BUDGET: usize = 45_000;

/// See [`CUT_ROUNDS`].
pub(super) const CUT_ROUNDS_LARGE: usize = 3;

/// The cut rounds stop when the last this many raised the LP by less than 1.
pub(super) const STALL: usize = 10;

/// At most this many pricing rounds (each followed by a re-solve).
pub(super) const PRICE_ROUNDS: usize = 2;

/// The search of its own for an endpoint the joint pricing search may have cut short goes
/// this many turns deep; farther pairs enter the bound by their least possible cost.
pub(super) const FALLBACK_TURNS: u32 = 12;

/// Tolerance on reduced costs and on integrality of HiGHS's answers.
pub(super) const TOL: f64 = 1e-6;

/// The matching LP over the candidate pairs, kept alive in HiGHS between rounds: columns x_e
/// ≥ 0, rows x(δ(v)) = 1 and odd-set cuts x(δ(S)) ≥ 1.
pub(super) struct MatchingLp {
    /// Rows are the endpoints' x(δ(v)) = 1, then the cuts in order; columns are `edges`.
    lp: GrowingLp,
    /// The vertex set of every cut.
    cuts: Vec<Vec<usize>>,
    /// The endpoints at each pixel.
    at_pixel: HashMap<usize, Vec<usize>>,
    /// The cuts containing each endpoint, increasing.
    cuts_of: Vec<Vec<u32>>,
    edges: Vec<(usize, usize, u32)>,
    index: HashMap<(usize, usize), usize>,
    /// Candidate edges at each endpoint (indices into `edges`).
    incident: Vec<Vec<u32>>,
}

/// One LP optimum: primal x per edge, duals y per endpoint and z per cut.
pub(super) struct LpPoint {
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
}

impl MatchingLp {
    fn new(ports: &[Port], edges: Vec<(usize, usize, u32)>) -> Result<MatchingLp> {
        let p = ports.len();
        let mut at_pixel: HashMap<usize, Vec<usize>> = HashMap::new();
        for (i, port) in ports.iter().enumerate() {
            at_pixel.entry(port.pixel).or_default().push(i);
        }
        let mut lp = MatchingLp {
            lp: GrowingLp::new(&vec![(1.0, 1.0); p]),
            cuts: Vec::new(),
            at_pixel,
            cuts_of: vec![Vec::new(); p],
            edges: Vec::with_capacity(edges.len()),
            index: HashMap::with_capacity(edges.len()),
            incident: vec![Vec::new(); p],
        };
        // The candidate pairs are distinct and ordered (smaller endpoint first).
        for (a, b, w) in edges {
            lp.add_edge(a, b, w)?;
        }
        Ok(lp)
    }

    /// The cuts with exactly one of `a`, `b` inside (both lists are sorted).
    fn crossing(&self, a: usize, b: usize) -> impl Iterator<Item = u32> + '_ {
        let (ca, cb) = (&self.cuts_of[a], &self.cuts_of[b]);
        ca.iter()
            .filter(|c| cb.binary_search(c).is_err())
            .chain(cb.iter().filter(|c| ca.binary_search(c).is_err()))
            .copied()
    }

    fn add_edge(&mut self, a: usize, b: usize, w: u32) -> Result<()> {
        let (a, b) = (a.min(b), a.max(b));
        if self.index.contains_key(&(a, b)) {
            return Ok(());
        }
        let p = self.cuts_of.len();
        let mut rows = vec![(a, 1.0), (b, 1.0)];
        rows.extend(self.crossing(a, b).map(|c| (p + c as usize, 1.0)));
        let k = self
            .lp
            .add_col(f64::from(w), 0.0, &rows)
            .map_err(|e| Error::solver(format!("the matching LP: {e}")))?;
        debug_assert_eq!(k, self.edges.len());
        self.edges.push((a, b, w));
        self.index.insert((a, b), k);
        self.incident[a].push(k as u32);
        self.incident[b].push(k as u32);
        Ok(())
    }

    /// The candidate edges with exactly one end in `set`, increasing.
    fn crossing_edges(&self, set: &[usize]) -> Vec<u32> {
        let mut cols: Vec<u32> = Vec::new();
        for &v in set {
            for &k in &self.incident[v] {
                let (a, b, _) = self.edges[k as usize];
                if set.binary_search(&a).is_ok() != set.binary_search(&b).is_ok() {
                    cols.push(k);
                }
            }
        }
        cols.sort_unstable();
        cols.dedup();
        cols
    }

    /// Adds x(δ(S)) ≥ 1 for the sorted set S.
    fn add_cut(&mut self, set: Vec<usize>) -> Result<()> {
        let cols = self.crossing_edges(&set);
        let factors: Vec<(usize, f64)> = cols.iter().map(|&k| (k as usize, 1.0)).collect();
        self.lp
            .add_row_at_least(1.0, &factors)
            .map_err(|e| Error::solver(format!("the matching LP, an odd-set cut: {e}")))?;
        let c = self.cuts.len() as u32;
        for &v in &set {
            self.cuts_of[v].push(c);
        }
        self.cuts.push(set);
        Ok(())
    }

    /// Y_v = y_v + Σ_{S∋v} z_S: Y_u + Y_v bounds what the duals take off any pair's weight.
    fn big_y(&self, point: &LpPoint) -> Vec<f64> {
        (0..self.cuts_of.len())
            .map(|v| {
                point.y[v]
                    + self.cuts_of[v]
                        .iter()
                        .map(|&c| point.z[c as usize])
                        .sum::<f64>()
            })
            .collect()
    }

    /// The reduced cost w − y_a − y_b − Σ_{S: exactly one of a, b in S} z_S of a pair.
    fn reduced_cost(&self, point: &LpPoint, a: usize, b: usize, w: u32) -> f64 {
        f64::from(w)
            - point.y[a]
            - point.y[b]
            - self
                .crossing(a, b)
                .map(|c| point.z[c as usize])
                .sum::<f64>()
    }

    /// The lower bound Σy + Σz + ½·Σ_v m_v on every perfect matching M of all pairs, where
    /// m_v ≤ min(0, rc(u, v)) for every u (`absent[v]` covers the absent pairs): each pair
    /// of M has rc ≥ min(0, rc) ≥ (m_u + m_v)/2.
    fn bound(&self, point: &LpPoint, absent: &[f64]) -> f64 {
        let mut m = absent.to_vec();
        for &(a, b, w) in &self.edges {
            let rc = self.reduced_cost(point, a, b, w);
            m[a] = m[a].min(rc);
            m[b] = m[b].min(rc);
        }
        point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>() + 0.5 * m.iter().sum::<f64>()
    }

    fn solve(&mut self) -> Result<LpPoint> {
        let sol = self
            .lp
            .solve()
            .map_err(|e| Error::solver(format!("the matching LP: {e}")))?;
        let p = self.cuts_of.len();
        Ok(LpPoint {
            y: sol.row_dual[..p].to_vec(),
            z: sol.row_dual[p..].iter().map(|&z| z.max(0.0)).collect(),
            x: sol.x,
        })
    }
}

/// A minimum-weight perfect matching over ALL endpoint pairs, proven by LP duality.
///
/// 1. The LP is solved over the candidate pairs. Its duals y_v (degree rows) and z_S ≥ 0
///    (odd-set cuts) bound the reduced cost of any pair from below by
///    w(u, v) − Y_u − Y_v, with Y_v = y_v + Σ_{S∋v} z_S; [`cheapest_sources`] finds every
///    absent pair where that is negative, and those become candidates. Odd components of the
///    edges with fractional x become cuts. For every perfect matching M,
///    w(M) = Σy + Σ_S z_S·|M ∩ δ(S)| + Σ_{e∈M} rc_e ≥ Σy + Σz + ½·Σ_v m_v, where m_v ≤ 0
///    bounds the reduced costs at v: that is the proven lower bound LB (best over rounds).
/// 2. The matching is the LP's where it is integral; otherwise the edges at 1 are kept and
///    blossom matches the endpoints the LP left fractional over their candidate pairs
///    ([`repair`]). It is proven minimum over all pairs when its weight is ⌈LB⌉; otherwise
///    LB is reported and the gap is w(M) − LB.
pub(super) fn priced_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
    edges: Vec<(usize, usize, u32)>,
) -> Result<PortMatching> {
    let p = ports.len();
    let log = std::env::var_os("MOWMILL_MATCHING_LOG").is_some();
    let started = std::time::Instant::now();
    let mut lp = MatchingLp::new(ports, edges)?;
    // The best proven bound and the duals Y that give it.
    let mut best: Option<(f64, Vec<f64>)> = None;
    let mut last_x;
    let (mut round, mut pricings) = (0, 0);
    let mut history: Vec<f64> = Vec::new();
    loop {
        round += 1;
        let point = lp.solve()?;
        let cuts = violated_odd_sets(p, &lp.edges, &point.x);
        let value = point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>();
        history.push(value);
        // Tailing off: the cuts of the last STALL rounds raised the LP by less than 1.
        let stalled = history.len() > STALL && value < history[history.len() - 1 - STALL] + 1.0;
        let rounds = (CUT_BUDGET / p).clamp(CUT_ROUNDS_LARGE, CUT_ROUNDS);
        if !cuts.is_empty() && round < rounds && !stalled {
            if log {
                eprintln!(
                    "round {round}: {} cuts, lp {:.3}, new cuts {}, t {:.2}",
                    lp.cuts.len(),
                    point.y.iter().sum::<f64>() + point.z.iter().sum::<f64>(),
                    cuts.len(),
                    started.elapsed().as_secs_f64()
                );
            }
            for set in cuts {
                lp.add_cut(set)?;
            }
            continue;
        }
        // The cuts have converged (or the rounds are spent): price every absent pair.
        let big_y = lp.big_y(&point);
        let (priced, deficit) = price(region, ports, &point, &big_y, &lp, 0.0);
        let bound = lp.bound(&point, &deficit);
        if log {
            let open: f64 = deficit.iter().sum();
            let neg_z = point.z.iter().filter(|&&z| z == 0.0).count();
            eprintln!("  absent deficits {open:.3}, zero z {neg_z}");
        }
        if best.as_ref().is_none_or(|b| bound > b.0) {
            best = Some((bound, big_y));
        }
        if log {
            eprintln!(
                "round {round}: {} edges, {} cuts, bound {bound:.3}, priced {}, t {:.2}",
                lp.edges.len(),
                lp.cuts.len(),
                priced.len(),
                started.elapsed().as_secs_f64()
            );
        }
        last_x = point.x;
        pricings += 1;
        let price_rounds = if p > LARGE { 1 } else { PRICE_ROUNDS };
        if priced.is_empty() || pricings == price_rounds {
            break;
        }
        for (a, b, w) in priced {
            lp.add_edge(a, b, w)?;
        }
    }
    let (bound, _) = best.expect("one round ran");
    // Pairs not priced have reduced cost above −TOL each: allow for that, and for round-off.
    let lower = (bound - 0.5 * p as f64 * TOL - 1e-7).ceil().max(0.0) as u64;
    let mut m = if p > LARGE {
        let (mate, tiled) = tiled_matching(region, ports, partner, floor)?;
        matching_of(mate, &tiled)
    } else {
        match lp_matching(p, &lp.edges, &last_x).or_else(|| repair(p, &lp.edges, &last_x, partner))
        {
            Some(mate) => matching_of(mate, &lp.edges),
            // The repair found no perfect matching around an odd piece: tiles always do.
            None => {
                let (mate, tiled) = tiled_matching(region, ports, partner, floor)?;
                matching_of(mate, &tiled)
            }
        }
    };
    let lower_bound = lower;
    if log {
        eprintln!(
            "matching {} lower bound {lower_bound}, t {:.2}",
            m.total,
            started.elapsed().as_secs_f64()
        );
    }
    m.lower_bound = lower_bound.min(m.total);
    m.optimal = m.total <= lower_bound;
    m.candidates = lp.edges.len();
    Ok(m)
}

/// Absent pairs with reduced cost below `slack` (at most [`PRICE_K`] per endpoint from the
/// joint search, all within [`FALLBACK_TURNS`] from a search of its own where the joint one
/// may have missed some), and per endpoint v a proven lower bound, at most 0, on the reduced
/// cost of every absent pair at v.
pub(super) fn price(
    region: &Region,
    ports: &[Port],
    point: &LpPoint,
    big_y: &[f64],
    lp: &MatchingLp,
    slack: f64,
) -> (Vec<(usize, usize, u32)>, Vec<f64>) {
    let y_max = big_y.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mut deficit = vec![0.0f64; ports.len()];
    let limit = slack - TOL;
    let found = cheapest_sources(region, ports, big_y, PRICE_K, y_max + limit);
    let absent = |u: usize, v: usize| !lp.index.contains_key(&(u.min(v), u.max(v)));
    let mut priced = Vec::new();
    let mut opened = 0usize;
    let mut search = TurnSearch::new(region);
    for (v, list) in found.iter().enumerate() {
        let mut open = list.len() == PRICE_K;
        for e in list {
            let rc = e.key - big_y[v];
            if rc >= limit {
                open = false;
                break;
            }
            if absent(e.port, v) {
                let rc = lp.reduced_cost(point, e.port, v, e.turns);
                if rc < limit {
                    priced.push((e.port.min(v), e.port.max(v), e.turns));
                    deficit[v] = deficit[v].min(rc);
                    deficit[e.port] = deficit[e.port].min(rc);
                }
            }
        }
        if open {
            opened += 1;
            // Every listed source is a candidate and more may follow: search from v alone, as
            // far as a reduced cost below the limit reaches (w is symmetric).
            let reach = (big_y[v] + y_max + limit).floor().max(0.0) as u32;
            // Beyond FALLBACK_TURNS a pair costs at least that + 1 turns, which bounds its
            // reduced cost from below.
            if reach > FALLBACK_TURNS {
                let beyond = f64::from(FALLBACK_TURNS + 1) - big_y[v] - y_max;
                deficit[v] = deficit[v].min(beyond);
            }
            let reach = reach.min(FALLBACK_TURNS);
            search.run(region, ports[v], reach, |pixel, heading, d| {
                if let Some(here) = lp.at_pixel.get(&pixel) {
                    for &u in here {
                        if u != v
                            && ports[u].arrive() & bit(heading) != 0
                            && f64::from(d) - big_y[u] - big_y[v] < limit
                            && absent(u, v)
                        {
                            let rc = lp.reduced_cost(point, u, v, d);
                            if rc < limit {
                                priced.push((u.min(v), u.max(v), d));
                                deficit[v] = deficit[v].min(rc);
                                deficit[u] = deficit[u].min(rc);
                            }
                        }
                    }
                }
                false
            });
        }
    }
    // A pair met twice keeps its least weight (the search settles each state once, so the
    // first met is the least; sorting puts it first).
    priced.sort_unstable();
    priced.dedup_by_key(|e| (e.0, e.1));
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        eprintln!("  pricing: {opened} endpoints searched alone");
    }
    (priced, deficit)
}

/// The LP's matching, when x is integral.
pub(super) fn lp_matching(
    p: usize,
    edges: &[(usize, usize, u32)],
    x: &[f64],
) -> Option<Vec<usize>> {
    let mut mate = vec![usize::MAX; p];
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] > TOL && x[k] < 1.0 - TOL {
            return None;
        }
        if x[k] > 0.5 {
            if mate[a] != usize::MAX || mate[b] != usize::MAX {
                return None;
            }
            mate[a] = b;
            mate[b] = a;
        }
    }
    mate.iter().all(|&m| m != usize::MAX).then_some(mate)
}

/// A perfect matching from a fractional LP point: the edges at 1 are kept, blossom matches
/// each component of the fractional edges over the candidate pairs inside it, then the rest
/// piece by piece, opening kept pairs next to a piece without a perfect matching.
pub(super) fn repair(
    p: usize,
    edges: &[(usize, usize, u32)],
    x: &[f64],
    partner: &[usize],
) -> Option<Vec<usize>> {
    let mut fixed = vec![usize::MAX; p];
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] >= 1.0 - TOL {
            fixed[a] = b;
            fixed[b] = a;
        }
    }
    // First each component of the fractional edges alone, over the candidate pairs inside it.
    let mut uf = UnionFind::<usize>::new(p);
    for (k, &(a, b, _)) in edges.iter().enumerate() {
        if x[k] > TOL && x[k] < 1.0 - TOL {
            uf.union(a, b);
        }
    }
    let mut inside: HashMap<usize, Vec<(usize, usize, u32)>> = HashMap::new();
    let mut members: HashMap<usize, Vec<usize>> = HashMap::new();
    for v in (0..p).filter(|&v| fixed[v] == usize::MAX) {
        let r = uf.find_mut(v);
        members.entry(r).or_default().push(v);
    }
    for &(a, b, w) in edges {
        if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
            let (ra, rb) = (uf.find_mut(a), uf.find_mut(b));
            if ra == rb {
                inside.entry(ra).or_default().push((a, b, w));
            }
        }
    }
    let mut pieces: Vec<(usize, Vec<usize>)> = members.into_iter().collect();
    pieces.sort_unstable();
    let log = std::env::var_os("MOWMILL_MATCHING_LOG").is_some();
    if log {
        let largest = pieces.iter().map(|p| p.1.len()).max().unwrap_or(0);
        eprintln!(
            "repair: {} fractional components, largest {largest}",
            pieces.len()
        );
    }
    for (r, piece) in pieces {
        if piece.len() % 2 == 1 {
            continue;
        }
        let local = |v: usize| piece.binary_search(&v).expect("a member");
        let sub: Vec<(usize, usize, u32)> = inside
            .get(&r)
            .map(|es| {
                es.iter()
                    .map(|&(a, b, w)| (local(a), local(b), w))
                    .collect()
            })
            .unwrap_or_default();
        if let Some(m) = min_weight_perfect_matching(piece.len(), &sub) {
            for (i, &v) in piece.iter().enumerate() {
                fixed[v] = piece[m[i]];
            }
        }
    }
    // Then the pieces of the candidate graph on the open endpoints; a piece without a perfect
    // matching opens the kept pairs next to it (by a candidate edge or a partner), and again.
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); p];
    for &(a, b, _) in edges {
        adjacent[a].push(b);
        adjacent[b].push(a);
    }
    for v in 0..p {
        adjacent[v].push(partner[v]);
    }
    loop {
        let open: Vec<usize> = (0..p).filter(|&v| fixed[v] == usize::MAX).collect();
        if open.is_empty() {
            return Some(fixed);
        }
        let mut uf = UnionFind::<usize>::new(p);
        let mut sub: HashMap<usize, Vec<(usize, usize, u32)>> = HashMap::new();
        for &(a, b, _) in edges {
            if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
                uf.union(a, b);
            }
        }
        let mut pieces: HashMap<usize, Vec<usize>> = HashMap::new();
        for &v in &open {
            let r = uf.find_mut(v);
            pieces.entry(r).or_default().push(v);
        }
        for &(a, b, w) in edges {
            if fixed[a] == usize::MAX && fixed[b] == usize::MAX {
                let r = uf.find_mut(a);
                sub.entry(r).or_default().push((a, b, w));
            }
        }
        let mut pieces: Vec<(usize, Vec<usize>)> = pieces.into_iter().collect();
        pieces.sort_unstable();
        let mut failed_pieces: Vec<Vec<usize>> = Vec::new();
        for (r, piece) in pieces {
            let local = |v: usize| piece.binary_search(&v).expect("a member");
            let es: Vec<(usize, usize, u32)> = sub
                .get(&r)
                .map(|es| {
                    es.iter()
                        .map(|&(a, b, w)| (local(a), local(b), w))
                        .collect()
                })
                .unwrap_or_default();
            let matched = if piece.len() % 2 == 0 {
                min_weight_perfect_matching(piece.len(), &es)
            } else {
                None
            };
            match matched {
                Some(m) => {
                    for (i, &v) in piece.iter().enumerate() {
                        fixed[v] = piece[m[i]];
                    }
                }
                None => failed_pieces.push(piece),
            }
        }
        if log {
            let failed: usize = failed_pieces.iter().map(Vec::len).sum();
            eprintln!("repair: {} open, {failed} failed", open.len());
        }
        if failed_pieces.is_empty() {
            return Some(fixed);
        }
        let mut released = false;
        // Open the kept pairs next to every piece without a perfect matching (an odd piece
        // grows until it meets another).
        for piece in &failed_pieces {
            for &v in piece {
                for &t in &adjacent[v] {
                    if fixed[t] != usize::MAX {
                        let u = fixed[t];
                        fixed[t] = usize::MAX;
                        fixed[u] = usize::MAX;
                        released = true;
                    }
                }
            }
        }
        if !released {
            return None;
        }
    }
}
