//! From integer solutions to closed walks: Euler tours of edge multisets (Hierholzer, shared
//! with the approximations in [`crate::euler`]), walks of passage multisets, and
//! splicing of walks that traverse a common grid edge.

use std::collections::HashMap;

pub use crate::euler::euler_walk;

/// One passage through a pixel: the walk enters from side `a` and leaves through side `b`
/// (unordered; `a == b` is a U-turn). Sides are [`crate::region::Dir`] indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Passage {
    pub pixel: usize,
    pub a: u8,
    pub b: u8,
}

/// The closed walks formed by a multiset of passages whose edge usages agree on both sides of
/// every grid edge. `neighbor(v, d)` is the pixel on side `d` of `v`.
///
/// The passages at each side of a pixel are paired with those at the facing side of the
/// neighbour in order; any pairing gives walks with the same total cost.
pub fn passage_walks(
    n: usize,
    passages: &[Passage],
    neighbor: impl Fn(usize, u8) -> usize,
) -> Vec<Vec<usize>> {
    // slots[v * 4 + d] = (passage, end) using side d of v, in order.
    let mut slots: Vec<Vec<(u32, u8)>> = vec![Vec::new(); 4 * n];
    let mut pos = vec![[0u32; 2]; passages.len()];
    for (k, p) in passages.iter().enumerate() {
        for (end, side) in [(0u8, p.a), (1u8, p.b)] {
            let list = &mut slots[p.pixel * 4 + side as usize];
            pos[k][end as usize] = list.len() as u32;
            list.push((k as u32, end));
        }
    }
    let side_of = |k: usize, end: u8| {
        if end == 0 {
            passages[k].a
        } else {
            passages[k].b
        }
    };
    let mut used = vec![false; passages.len()];
    let mut walks = Vec::new();
    for first in 0..passages.len() {
        if used[first] {
            continue;
        }
        let mut walk = Vec::new();
        let (mut k, mut enter) = (first, 0u8);
        loop {
            used[k] = true;
            let v = passages[k].pixel;
            walk.push(v);
            let out = 1 - enter;
            let d = side_of(k, out);
            let w = neighbor(v, d);
            let back = (d + 2) % 4;
            let (j, e) = slots[w * 4 + back as usize][pos[k][out as usize] as usize];
            k = j as usize;
            enter = e;
            if k == first && enter == 0 {
                break;
            }
        }
        walks.push(walk);
    }
    walks
}

fn edge_key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

/// Merges closed walks that traverse a common grid edge into one, keeping every passage (so
/// length and turns are unchanged): walk B is cut open at its traversal of the edge and
/// inserted into walk A at A's traversal of it.
pub fn splice_walks(mut walks: Vec<Vec<usize>>) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    while let Some(mut a) = walks.pop() {
        loop {
            if a.len() < 2 {
                break;
            }
            let mut at: HashMap<(usize, usize), usize> = HashMap::new();
            for i in 0..a.len() {
                at.entry(edge_key(a[i], a[(i + 1) % a.len()])).or_insert(i);
            }
            let found = walks.iter().enumerate().find_map(|(bi, b)| {
                (0..b.len()).find_map(|j| {
                    let key = edge_key(b[j], b[(j + 1) % b.len()]);
                    (b.len() >= 2).then_some(())?;
                    at.get(&key).map(|&i| (bi, i))
                })
            });
            let Some((bi, i)) = found else { break };
            let mut b = walks.swap_remove(bi);
            let (u, w) = (a[i], a[(i + 1) % a.len()]);
            let lb = b.len();
            let same = |b: &Vec<usize>| (0..lb).find(|&j| b[j] == u && b[(j + 1) % lb] == w);
            let j = match same(&b) {
                Some(j) => j,
                None => {
                    b.reverse();
                    same(&b).expect("the walk traverses the edge in one direction or the other")
                }
            };
            let mut merged = Vec::with_capacity(a.len() + lb);
            merged.extend_from_slice(&a[..=i]);
            merged.extend((1..=lb).map(|t| b[(j + t) % lb]));
            merged.extend_from_slice(&a[i + 1..]);
            a = merged;
        }
        out.push(a);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_walk_of_a_doubled_path_and_a_square() {
        // Path 0-1-2 doubled.
        let w = euler_walk(3, &[(0, 1), (1, 2)], &[2, 2], 0);
        assert_eq!(w.len(), 4);
        assert_eq!(w[0], 0);
        // Square 0-1-3-2-0.
        let w = euler_walk(4, &[(0, 1), (1, 3), (3, 2), (2, 0)], &[1, 1, 1, 1], 0);
        assert_eq!(w.len(), 4);
        for i in 0..4 {
            let (a, b) = (w[i], w[(i + 1) % 4]);
            assert!(
                [(0, 1), (1, 3), (3, 2), (2, 0)]
                    .iter()
                    .any(|&e| e == (a, b) || e == (b, a))
            );
        }
    }

    #[test]
    fn splicing_keeps_every_step() {
        // Two back-and-forth walks over the edge 1-2 of a path 0-1-2-3.
        let walks = vec![vec![0, 1, 2, 1], vec![2, 3, 2, 1]];
        let merged = splice_walks(walks);
        assert_eq!(merged.len(), 1);
        let m = &merged[0];
        assert_eq!(m.len(), 8);
        for i in 0..m.len() {
            assert_eq!(m[i].abs_diff(m[(i + 1) % m.len()]), 1);
        }
    }
}
