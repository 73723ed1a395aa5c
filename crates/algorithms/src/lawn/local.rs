//! `lawn-2opt`'s local search: the shared 2-opt / Or-opt / double-bridge search of
//! [`crate::tsp_local`] on the cell centres in the motion's metric, with
//! neighbour lists from a bucket grid.
//!
//! The kicks stay at [`tsp_local::default_kicks`] (20,000 at most): on gen lawn-scattered
//! --n 1000000 --seed 1, `solve --algo lawn-2opt` takes 8.1 s and 0.23 GB with them (length
//! 1,063,654 from the certified Christofides start; 1,057,348 from the exact one before, in
//! 54 s and 3.8 GB), while 10^6 kicks reach 1,047,928 but take 98 s (about 90 µs a kick).

use super::Points;
use crate::lawn_check::centre;
use crate::tsp_local::{self, Metric};
use std::collections::HashMap;

/// Neighbours per point in the candidate lists.
pub(super) const NEIGHBOURS: usize = 10;

/// The `k` nearest other points of every point in the motion's metric, sorted by (distance,
/// id): a bucket grid of about 2 points per bucket, searched ring by ring until the next
/// ring is farther than the k-th point found.
pub(super) fn nearest_neighbours(p: &Points, k: usize) -> Vec<Vec<usize>> {
    let n = p.len();
    let xy: Vec<(f64, f64)> = p.pts.iter().map(|&q| centre(p.cutter, q)).collect();
    if n == 0 {
        return Vec::new();
    }
    let (mut lo, mut hi) = (xy[0], xy[0]);
    for &(x, y) in &xy {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    let area = ((hi.0 - lo.0 + 1.0) * (hi.1 - lo.1 + 1.0)).max(1.0);
    let size = (2.0 * area / n as f64).sqrt().max(1.0);
    let cell = |i: usize| {
        (
            ((xy[i].0 - lo.0) / size).floor() as i64,
            ((xy[i].1 - lo.1) / size).floor() as i64,
        )
    };
    let mut map: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
    for i in 0..n {
        map.entry(cell(i)).or_default().push(i as u32);
    }
    let reach_max = (((hi.0 - lo.0).max(hi.1 - lo.1)) / size).ceil() as i64 + 1;
    let mut out = Vec::with_capacity(n);
    let mut best: Vec<(u64, usize)> = Vec::with_capacity(k + 1);
    for i in 0..n {
        best.clear();
        let (cx, cy) = cell(i);
        for ring in 0..=reach_max {
            // Points in ring r are farther than (r - 1) * size (in L2, hence in L1).
            if best.len() == k && (ring - 1) as f64 * size > p.dist(i, best[k - 1].1) {
                break;
            }
            for bx in cx - ring..=cx + ring {
                let step = if (bx - cx).abs() == ring {
                    1
                } else {
                    (2 * ring).max(1)
                };
                let mut by = cy - ring;
                while by <= cy + ring {
                    for &j in map.get(&(bx, by)).map_or(&[][..], |v| v.as_slice()) {
                        let j = j as usize;
                        if j == i {
                            continue;
                        }
                        let cand = (p.key(i, j), j);
                        if best.len() < k || cand < best[k - 1] {
                            let at = best.partition_point(|&b| b < cand);
                            best.insert(at, cand);
                            best.truncate(k);
                        }
                    }
                    by += step;
                }
            }
        }
        out.push(best.iter().map(|&(_, j)| j).collect());
    }
    out
}

impl Metric for Points {
    fn dist(&self, a: usize, b: usize) -> f64 {
        Points::dist(self, a, b)
    }

    fn tour_length(&self, tour: &[usize]) -> f64 {
        Points::tour_length(self, tour)
    }
}

/// The shared local search ([`tsp_local::improve`]) on the [`NEIGHBOURS`] nearest neighbours
/// of each point. Never longer than `start`.
pub(super) fn improve(p: &Points, start: Vec<usize>) -> Vec<usize> {
    if start.len() < 5 {
        return start;
    }
    let kicks = tsp_local::default_kicks(start.len());
    tsp_local::improve(p, &nearest_neighbours(p, NEIGHBOURS), kicks, start)
}
