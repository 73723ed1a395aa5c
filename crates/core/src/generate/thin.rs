//! `thin`: thin pockets from random spanning trees of the coarse lattice, plus one cycle per
//! hole.

use super::rng::{Rng, below, between, chance, shuffle};
use crate::region::Dir;
use crate::region::Pixel;

pub(super) fn ceil_sqrt(n: usize) -> usize {
    let s = n.isqrt();
    if s * s < n { s + 1 } else { s }
}

/// The number of independent cycles the row-by-row filling of t lattice nodes (rows of
/// ⌈√t⌉) offers: its lattice edges minus the t − 1 of a spanning tree. It equals the
/// Harary–Harborth maximum ⌊2t − 2√t⌋ − (t − 1) over all sets of t lattice nodes.
pub(super) fn thin_capacity(t: usize) -> usize {
    let w = ceil_sqrt(t).max(1);
    let (q, r) = (t / w, t % w);
    let horizontal = q * (w - 1) + r.saturating_sub(1);
    let vertical = q.saturating_sub(1) * w + if q >= 1 { r } else { 0 };
    (horizontal + vertical + 1).saturating_sub(t)
}

/// Lattice nodes needed for `holes` cycles.
pub(super) fn thin_nodes_for(holes: usize) -> usize {
    (1..)
        .find(|&t| thin_capacity(t) >= holes)
        .unwrap_or(usize::MAX)
}

/// The fewest pixels of a thin region with `holes` holes in this construction.
pub(super) fn min_thin_pixels(holes: usize) -> usize {
    2 * thin_nodes_for(holes) - 1 + holes
}

/// A thin region of exactly n pixels and `holes` holes: a random spanning tree of t nodes on
/// the coarse lattice (nodes at even coordinates, a corridor pixel per tree edge), `holes`
/// extra lattice edges and at most one stub pixel. `attempt` None is the fallback: the nodes
/// fill rows of ⌈√t⌉, which offer the most cycles.
pub(super) fn thin_pixels(
    n: usize,
    holes: usize,
    compactness: f64,
    attempt: Option<u64>,
    rng: &mut Rng,
) -> Option<Vec<Pixel>> {
    let stub = (n - 1 - holes) % 2;
    let t = (n - 1 - holes - stub) / 2 + 1;
    // The coarse canvas: a × b nodes of which `allowed` may be used.
    let (a, b, allowed) = match attempt {
        None => {
            let a = ceil_sqrt(t);
            (a, t.div_ceil(a), t)
        }
        Some(k) => {
            // Node density of the canvas: sparse for sprawling trees, denser on later
            // attempts when holes need adjacent nodes.
            let mut density = 30 + below(rng, 61);
            if holes > 0 {
                density = density.max(50 + 10 * k as usize);
            }
            let cells = (t * 100).div_ceil(density.min(100));
            let aspect = between(rng, 100, 200);
            let mut a = (cells * aspect / 100).isqrt().max(1);
            let mut b = cells.div_ceil(a);
            if chance(rng, 0.5) {
                std::mem::swap(&mut a, &mut b);
            }
            (a, b, a * b)
        }
    };
    let node_ok = |u: usize| u < allowed;
    let nb = |u: usize, d: Dir| -> Option<usize> {
        let (x, y) = (u % a, u / a);
        let v = match d {
            Dir::E if x + 1 < a => u + 1,
            Dir::W if x > 0 => u - 1,
            Dir::N if y + 1 < b => u + a,
            Dir::S if y > 0 => u - a,
            _ => return None,
        };
        node_ok(v).then_some(v)
    };
    let mut in_tree = vec![false; a * b];
    // parent[v]: the direction from v to its parent (4 = root).
    let mut parent = vec![4u8; a * b];
    let root = if attempt.is_none() {
        below(rng, t)
    } else {
        (b / 2) * a + a / 2
    };
    in_tree[root] = true;
    let (mut active, mut stack) = (vec![root], vec![root]);
    let mut came = vec![4u8; a * b];
    let mut size = 1;
    let mut free = Vec::with_capacity(4);
    while size < t {
        // Prim-like (a random tree node) with probability `compactness`, else depth-first
        // from the newest node, preferring to go straight.
        let mut prim = chance(rng, compactness);
        let (u, d) = loop {
            prim |= stack.is_empty();
            let (list, idx) = if prim {
                if active.is_empty() {
                    return None;
                }
                let i = below(rng, active.len());
                (&mut active, i)
            } else {
                let i = stack.len() - 1;
                (&mut stack, i)
            };
            let u = list[idx];
            free.clear();
            free.extend(
                Dir::ALL
                    .into_iter()
                    .filter(|&d| nb(u, d).is_some_and(|v| !in_tree[v])),
            );
            if free.is_empty() {
                list.swap_remove(idx);
                continue;
            }
            let straight = came[u] < 4 && free.contains(&Dir::from_index(came[u] as usize));
            let d = if !prim && straight && chance(rng, 0.65) {
                Dir::from_index(came[u] as usize)
            } else {
                free[below(rng, free.len())]
            };
            break (u, d);
        };
        let v = nb(u, d).expect("free direction has a node");
        in_tree[v] = true;
        parent[v] = d.opposite().index() as u8;
        came[v] = d.index() as u8;
        active.push(v);
        stack.push(v);
        size += 1;
    }
    let is_tree_edge = |u: usize, d: Dir, v: usize| {
        parent[u] == d.index() as u8 || parent[v] == d.opposite().index() as u8
    };
    let mut extra = Vec::new();
    for u in (0..a * b).filter(|&u| in_tree[u]) {
        for d in [Dir::E, Dir::N] {
            if let Some(v) = nb(u, d)
                && in_tree[v]
                && !is_tree_edge(u, d, v)
            {
                extra.push((u, d));
            }
        }
    }
    if extra.len() < holes {
        return None;
    }
    shuffle(&mut extra, rng);
    extra.truncate(holes);
    let node_pixel = |u: usize| Pixel::new(2 * (u % a) as i32, 2 * (u / a) as i32);
    let mut pixels = Vec::with_capacity(n);
    for u in (0..a * b).filter(|&u| in_tree[u]) {
        pixels.push(node_pixel(u));
        if parent[u] < 4 {
            pixels.push(node_pixel(u).step(Dir::from_index(parent[u] as usize)));
        }
    }
    pixels.extend(extra.iter().map(|&(u, d)| node_pixel(u).step(d)));
    if stub == 1 {
        let mut ends = Vec::new();
        for u in (0..a * b).filter(|&u| in_tree[u]) {
            for d in Dir::ALL {
                if nb(u, d).is_none_or(|v| !in_tree[v]) {
                    ends.push((u, d));
                }
            }
        }
        let (u, d) = ends[below(rng, ends.len())];
        pixels.push(node_pixel(u).step(d));
    }
    Some(pixels)
}
