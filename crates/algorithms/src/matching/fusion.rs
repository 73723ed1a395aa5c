//! Running fusion-blossom on a graph metric: serially, or on a recursive bisection of the
//! graph (its partitioned solver, still exact).

use super::blocks::{blocks_with_defects, join_block_matchings};
use super::*;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, Once};

/// Fusion-blossom solves running now: while there are any, a panic prints nothing (the
/// solve counts as failed and its caller falls back), so no backtrace reaches the user.
static QUIET: AtomicUsize = AtomicUsize::new(0);

/// The message of the last panic kept quiet, for `MOWMILL_MATCHING_LOG`.
static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

/// Installs (once) the panic hook that keeps panics quiet while a solve runs. A panic of
/// another thread during a solve is silenced too; it still fails its own job.
fn install_quiet_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if QUIET.load(Ordering::SeqCst) > 0 {
                if let Ok(mut last) = LAST_PANIC.lock() {
                    *last = Some(info.to_string());
                }
            } else {
                default(info);
            }
        }));
    });
}

/// Runs a fusion-blossom solve (a panic of the library counts as a failure, silently) and
/// turns its pairs into partners over `p` ports (`usize::MAX` where unmatched), with the
/// dual sum.
pub(super) fn mates_of(
    p: usize,
    solve: impl FnOnce() -> Option<(Vec<(usize, usize)>, i64)>,
) -> Option<(Vec<usize>, i64)> {
    install_quiet_hook();
    QUIET.fetch_add(1, Ordering::SeqCst);
    let solved = std::panic::catch_unwind(std::panic::AssertUnwindSafe(solve));
    QUIET.fetch_sub(1, Ordering::SeqCst);
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        let outcome = match &solved {
            Err(_) => format!(
                "panicked: {:?}",
                LAST_PANIC.lock().ok().and_then(|l| l.clone())
            ),
            Ok(None) => "failed".to_string(),
            Ok(Some(_)) => "solved".to_string(),
        };
        eprintln!("fusion-blossom: {outcome}");
    }
    let (pairs, dual) = solved.ok()??;
    let mut mate = vec![usize::MAX; p];
    for (a, b) in pairs {
        mate[a] = b;
        mate[b] = a;
    }
    Some((mate, dual))
}

/// The pairs of vertices `pairs` as pairs of the indices `index` gives them (`None` if a
/// vertex has none).
pub(super) fn renamed(
    pairs: Vec<(usize, usize)>,
    index: &HashMap<usize, usize>,
) -> Option<Vec<(usize, usize)>> {
    pairs
        .into_iter()
        .map(|(a, b)| Some((*index.get(&a)?, *index.get(&b)?)))
        .collect()
}

/// Solves a minimum-weight perfect matching of the vertices `defects` in the shortest-path
/// metric of a graph: the matched vertex pairs and a lower bound on every perfect matching's
/// weight (the sum of the blocks' dual sums). The graph is split at its cut vertices into
/// blocks solved one by one ([`super::blocks`], exact); a bridge is its own answer, and
/// every other block goes to fusion-blossom, one thread, above `serial_limit` of the
/// block's defects on a recursive bisection of it (the partitioned solver, still exact).
///
/// `extent` gives every vertex's extent (only called when a block has more than
/// `serial_limit` defects): the extents of two vertices joined by an edge must meet.
pub(super) fn solve_graph_matching(
    serial_limit: usize,
    vertices: usize,
    edges: Vec<(usize, usize, isize)>,
    defects: &[usize],
    extent: impl FnOnce(&[(usize, usize, isize)]) -> Vec<Extent>,
) -> Option<(Vec<(usize, usize)>, i64)> {
    if defects.is_empty() {
        return Some((Vec::new(), 0));
    }
    let mut is_defect = vec![false; vertices];
    for &v in defects {
        is_defect[v] = true;
    }
    let blocks = blocks_with_defects(vertices, &edges, &is_defect)?;
    if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
        let largest = blocks.iter().map(|b| b.defects.len()).max().unwrap_or(0);
        eprintln!(
            "blocks: {} with defects, the largest with {largest} of {} defects",
            blocks.len(),
            defects.len()
        );
    }
    let mut extent = Some(extent);
    let mut extents: Option<Vec<Extent>> = None;
    let mut local = vec![usize::MAX; vertices];
    let mut pairs = Vec::with_capacity(defects.len());
    let mut dual = 0i64;
    for block in &blocks {
        if let [a, b] = block.vertices[..] {
            // A bridge (or parallel edges): its one T-join is its lightest edge.
            let w = block.edges.iter().map(|&e| edges[e].2).min()?;
            pairs.push((a, b));
            dual += w as i64;
            continue;
        }
        for (k, &v) in block.vertices.iter().enumerate() {
            local[v] = k;
        }
        let own: Vec<(usize, usize, isize)> = block
            .edges
            .iter()
            .map(|&e| (local[edges[e].0], local[edges[e].1], edges[e].2))
            .collect();
        let own_defects: Vec<usize> = block.defects.iter().map(|&v| local[v]).collect();
        let own_extent: Vec<Extent> = if own_defects.len() > serial_limit {
            if extents.is_none() {
                extents = Some((extent.take()?)(&edges));
            }
            let all = extents.as_ref()?;
            block.vertices.iter().map(|&v| all[v]).collect()
        } else {
            Vec::new()
        };
        let partitioned = own_defects.len() > serial_limit;
        // The edges are kept for a serial retry only where the partitioned solver may fail.
        let retry = partitioned.then(|| own.clone());
        let attempt = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            solve_block(
                serial_limit,
                block.vertices.len(),
                own,
                &own_defects,
                own_extent,
            )
        }));
        let (found, d) = match attempt {
            Ok(Some(solved)) => solved,
            // The partitioned solver failed on this block: serially, it is only slower.
            _ if retry.is_some() => {
                if std::env::var_os("MOWMILL_MATCHING_LOG").is_some() {
                    eprintln!(
                        "fusion-blossom: partitioned solve of a block with {} defects failed ({}); serially",
                        own_defects.len(),
                        match &attempt {
                            Err(_) => LAST_PANIC
                                .lock()
                                .ok()
                                .and_then(|l| l.clone())
                                .unwrap_or_default(),
                            _ => "no perfect matching".to_string(),
                        }
                    );
                }
                solve_block(
                    usize::MAX,
                    block.vertices.len(),
                    retry?,
                    &own_defects,
                    Vec::new(),
                )?
            }
            _ => return None,
        };
        pairs.extend(
            found
                .into_iter()
                .map(|(a, b)| (block.vertices[a], block.vertices[b])),
        );
        dual += d;
    }
    Some((join_block_matchings(vertices, &pairs, &is_defect)?, dual))
}

/// One block of [`solve_graph_matching`] by fusion-blossom (`extent` is used above
/// `serial_limit` defects only).
///
/// The partitioned solver panicked on defects at vertices that many edges meet (a run crossed
/// by many runs), so there every defect v moves to a new pendant vertex v'
/// joined to v at weight 2: every matching then costs 2 per defect more, and the dual sum
/// is lowered by as much.
fn solve_block(
    serial_limit: usize,
    vertices: usize,
    mut edges: Vec<(usize, usize, isize)>,
    defects: &[usize],
    mut extent: Vec<Extent>,
) -> Option<(Vec<(usize, usize)>, i64)> {
    if defects.len() > serial_limit {
        let first = vertices;
        for (k, &v) in defects.iter().enumerate() {
            edges.push((v, first + k, 2));
            extent.push(extent[v]);
        }
        let pendants: Vec<usize> = (first..first + defects.len()).collect();
        let (pairs, dual) = solve_fusion(serial_limit, extent.len(), edges, &pendants, extent)?;
        let back = |v: usize| defects[v - first];
        let pairs = pairs.into_iter().map(|(a, b)| (back(a), back(b))).collect();
        return Some((pairs, dual - 2 * defects.len() as i64));
    }
    solve_fusion(serial_limit, vertices, edges, defects, extent)
}

/// fusion-blossom on one graph: serially up to `serial_limit` defects, else partitioned.
fn solve_fusion(
    serial_limit: usize,
    vertices: usize,
    edges: Vec<(usize, usize, isize)>,
    defects: &[usize],
    extent: Vec<Extent>,
) -> Option<(Vec<(usize, usize)>, i64)> {
    let (perm, partitions, fusions) = if defects.len() <= serial_limit {
        (
            (0..vertices).collect::<Vec<usize>>(),
            Vec::new(),
            Vec::new(),
        )
    } else {
        bisection(&extent)
    };
    let mut position = vec![0usize; vertices];
    for (k, &v) in perm.iter().enumerate() {
        position[v] = k;
    }
    let init = SolverInitializer::new(
        vertices,
        edges
            .iter()
            .map(|&(a, b, w)| (position[a], position[b], w))
            .collect(),
        Vec::new(),
    );
    let mut positions: Vec<usize> = defects.iter().map(|&v| position[v]).collect();
    positions.sort_unstable();
    let syndrome = SyndromePattern::new_vertices(positions);
    let matching = if partitions.is_empty() {
        let mut solver = SolverSerial::new(&init);
        solver.solve(&syndrome);
        (solver.perfect_matching(), solver.sum_dual_variables())
    } else {
        let mut config = PartitionConfig::new(vertices);
        config.partitions = partitions
            .iter()
            .map(|&(a, b)| VertexRange::new(a, b))
            .collect();
        config.fusions = fusions;
        let one_thread = serde_json::json!({
            "dual": { "thread_pool_size": 1 },
            "primal": { "thread_pool_size": 1 },
        });
        let mut solver = SolverParallel::new(&init, &config.info(), one_thread);
        solver.solve(&syndrome);
        (solver.perfect_matching(), solver.sum_dual_variables())
    };
    let (perfect, dual) = matching;
    if !perfect.virtual_matchings.is_empty() {
        return None;
    }
    let vertex_of =
        |node: &fusion_blossom::dual_module::DualNodePtr| match node.read_recursive().class {
            DualNodeClass::DefectVertex { defect_index } => Some(perm[defect_index]),
            DualNodeClass::Blossom { .. } => None,
        };
    let mut pairs = Vec::with_capacity(defects.len() / 2);
    for (a, b) in &perfect.peer_matchings {
        pairs.push((vertex_of(a)?, vertex_of(b)?));
    }
    Some((pairs, dual as i64))
}

/// A recursive bisection of the run graph for fusion-blossom's partitioned solver: an order
/// of the vertices in which every unit is a range (left part, separator, right part), the
/// leaf ranges, and the fusions (pairs of units, children before parents). A separator is
/// every vertex whose extent meets the cut line; edges join vertices whose extents meet, so
/// none joins the two sides.
#[allow(clippy::type_complexity)]
pub(super) fn bisection(
    extent: &[Extent],
) -> (Vec<usize>, Vec<(usize, usize)>, Vec<(usize, usize)>) {
    enum Tree {
        Leaf(usize, usize),
        Node(Box<Tree>, Box<Tree>),
    }
    fn build(set: Vec<usize>, extent: &[Extent], order: &mut Vec<usize>) -> Tree {
        let leaf = |set: &[usize], order: &mut Vec<usize>| {
            let start = order.len();
            order.extend_from_slice(set);
            Tree::Leaf(start, order.len())
        };
        if set.len() <= LEAF {
            return leaf(&set, order);
        }
        let b = set
            .iter()
            .fold((i32::MAX, i32::MIN, i32::MAX, i32::MIN), |a, &v| {
                let e = extent[v];
                (a.0.min(e.0), a.1.max(e.1), a.2.min(e.2), a.3.max(e.3))
            });
        let across = b.1 - b.0 >= b.3 - b.2;
        let span = |v: usize| {
            let e = extent[v];
            if across { (e.0, e.1) } else { (e.2, e.3) }
        };
        let mut keys: Vec<i32> = set.iter().map(|&v| span(v).0 + span(v).1).collect();
        keys.sort_unstable();
        // Twice the cut line.
        let cut = keys[keys.len() / 2];
        let (mut left, mut middle, mut right) = (Vec::new(), Vec::new(), Vec::new());
        for &v in &set {
            let (lo, hi) = span(v);
            if 2 * hi < cut {
                left.push(v);
            } else if 2 * lo > cut {
                right.push(v);
            } else {
                middle.push(v);
            }
        }
        if left.is_empty() || right.is_empty() {
            return leaf(&set, order);
        }
        let l = build(left, extent, order);
        order.extend_from_slice(&middle);
        let r = build(right, extent, order);
        Tree::Node(Box::new(l), Box::new(r))
    }
    fn leaves(t: &Tree, out: &mut Vec<(usize, usize)>) {
        match t {
            Tree::Leaf(a, b) => out.push((*a, *b)),
            Tree::Node(l, r) => {
                leaves(l, out);
                leaves(r, out);
            }
        }
    }
    fn fuse(t: &Tree, next: &mut usize, base: usize, out: &mut Vec<(usize, usize)>) -> usize {
        match t {
            Tree::Leaf(..) => {
                *next += 1;
                *next - 1
            }
            Tree::Node(l, r) => {
                let a = fuse(l, next, base, out);
                let b = fuse(r, next, base, out);
                out.push((a, b));
                base + out.len() - 1
            }
        }
    }
    let mut order = Vec::with_capacity(extent.len());
    let tree = build((0..extent.len()).collect(), extent, &mut order);
    let mut parts = Vec::new();
    leaves(&tree, &mut parts);
    let mut fusions = Vec::new();
    fuse(&tree, &mut 0, parts.len(), &mut fusions);
    (order, parts, fusions)
}
