//! Running fusion-blossom on a graph metric: serially, or on a recursive bisection of the
//! graph (its partitioned solver, still exact).

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
/// metric of a graph with fusion-blossom: the matched vertex pairs and the sum of the dual
/// variables. One thread; above `serial_limit` defects on a recursive bisection of the graph
/// (fusion-blossom's partitioned solver, still exact).
///
/// `extent` gives every vertex's extent (only called above `serial_limit` defects): the
/// extents of two vertices joined by an edge must meet.
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
    let (perm, partitions, fusions) = if defects.len() <= serial_limit {
        (
            (0..vertices).collect::<Vec<usize>>(),
            Vec::new(),
            Vec::new(),
        )
    } else {
        bisection(&extent(&edges))
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
