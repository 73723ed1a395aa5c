//! Turn distance between strip or link endpoints (proof of Theorem 5.5 and Section 4.1 of
//! *Optimal covering tours with turn costs*).
//!
//! A [`Port`] is a pixel together with the headings in which a connecting path may leave it.
//! The turn distance `w(u, v)` is the fewest turns of a path that leaves `u` in one of `u`'s
//! headings and arrives at `v` in the reverse of one of `v`'s headings (so that reversing the
//! path leaves `v` in one of its own headings: `w` is symmetric). It is one less than the link
//! distance. We compute it by a 0-1 breadth-first search over (pixel, heading) states: a step
//! forward costs 0, a quarter turn in place costs 1 (a U-turn is two quarter turns).
//!
//! For a strip endpoint the headings are the two orthogonal to the strip (Theorem 5.5); for a
//! boundary link endpoint it is the one heading continuing the link outward (Section 4.1), so
//! two collinear disjoint links are at distance 0.

use crate::region::{Dir, Region};
use std::collections::VecDeque;

/// A pixel and the headings (a bit mask over [`Dir::index`]) in which a path may leave it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Port {
    pub pixel: usize,
    pub leave: u8,
}

impl Port {
    /// A strip endpoint: paths leave orthogonally to the strip.
    pub(crate) fn strip_end(pixel: usize, horizontal: bool) -> Port {
        let leave = if horizontal {
            bit(Dir::N) | bit(Dir::S)
        } else {
            bit(Dir::E) | bit(Dir::W)
        };
        Port { pixel, leave }
    }

    /// The headings in which a path must arrive at this port: the reverses of its leaving
    /// headings.
    pub(crate) fn arrive(self) -> u8 {
        Dir::ALL
            .iter()
            .filter(|d| self.leave & bit(**d) != 0)
            .map(|d| bit(d.opposite()))
            .fold(0, |a, b| a | b)
    }
}

/// The bit of a heading in a heading mask.
pub(crate) fn bit(d: Dir) -> u8 {
    1 << d.index()
}

const UNSEEN: u32 = u32::MAX;

/// Reusable 0-1 BFS over (pixel, heading) states; resets only the states it touched, so that
/// many small searches on a large region stay cheap.
pub(crate) struct TurnSearch {
    dist: Vec<u32>,
    parent: Vec<u32>,
    touched: Vec<u32>,
    deque: VecDeque<(u32, u32)>,
}

impl TurnSearch {
    pub(crate) fn new(region: &Region) -> TurnSearch {
        TurnSearch {
            dist: vec![UNSEEN; 4 * region.len()],
            parent: vec![UNSEEN; 4 * region.len()],
            touched: Vec::new(),
            deque: VecDeque::new(),
        }
    }

    fn reset(&mut self) {
        for &s in &self.touched {
            self.dist[s as usize] = UNSEEN;
            self.parent[s as usize] = UNSEEN;
        }
        self.touched.clear();
        self.deque.clear();
    }

    fn relax(&mut self, s: u32, d: u32, from: u32, front: bool) {
        let k = s as usize;
        if d < self.dist[k] {
            if self.dist[k] == UNSEEN {
                self.touched.push(s);
            }
            self.dist[k] = d;
            self.parent[k] = from;
            if front {
                self.deque.push_front((s, d));
            } else {
                self.deque.push_back((s, d));
            }
        }
    }

    /// Searches from `from`, settling states in order of turns, up to `max_turns` turns.
    /// `visit(pixel, heading, turns)` is called once per settled state; returning `true` stops
    /// the search after the current turn level is complete.
    pub(crate) fn run(
        &mut self,
        region: &Region,
        from: Port,
        max_turns: u32,
        mut visit: impl FnMut(usize, Dir, u32) -> bool,
    ) {
        self.reset();
        for d in Dir::ALL {
            if from.leave & bit(d) != 0 {
                self.relax((4 * from.pixel + d.index()) as u32, 0, UNSEEN, true);
            }
        }
        let mut stop_after: Option<u32> = None;
        while let Some((s, d)) = self.deque.pop_front() {
            if d > self.dist[s as usize] {
                continue;
            }
            if d > max_turns || stop_after.is_some_and(|l| d > l) {
                break;
            }
            let (pixel, heading) = ((s / 4) as usize, Dir::from_index((s % 4) as usize));
            if visit(pixel, heading, d) && stop_after.is_none() {
                stop_after = Some(d);
            }
            if let Some(next) = region.neighbor(pixel, heading) {
                self.relax((4 * next + heading.index()) as u32, d, s, true);
            }
            for turned in [heading.left(), heading.right()] {
                self.relax((4 * pixel + turned.index()) as u32, d + 1, s, false);
            }
        }
    }

    /// The turn distance to `to` found by the last [`run`](Self::run), if it was reached.
    pub(crate) fn distance_to(&self, to: Port) -> Option<u32> {
        let arrive = to.arrive();
        Dir::ALL
            .iter()
            .filter(|d| arrive & bit(**d) != 0)
            .map(|d| self.dist[4 * to.pixel + d.index()])
            .filter(|&d| d != UNSEEN)
            .min()
    }

    /// The pixels of a cheapest path to `to` found by the last run, from the source's pixel to
    /// `to.pixel` (in-place turns collapse into one pixel).
    pub(crate) fn path_to(&self, to: Port) -> Option<Vec<usize>> {
        let arrive = to.arrive();
        let best = Dir::ALL
            .iter()
            .filter(|d| arrive & bit(**d) != 0)
            .map(|d| (4 * to.pixel + d.index()) as u32)
            .filter(|&s| self.dist[s as usize] != UNSEEN)
            .min_by_key(|&s| self.dist[s as usize])?;
        let mut pixels = Vec::new();
        let mut s = best;
        while s != UNSEEN {
            let p = (s / 4) as usize;
            if pixels.last() != Some(&p) {
                pixels.push(p);
            }
            s = self.parent[s as usize];
        }
        pixels.reverse();
        Some(pixels)
    }
}

/// The turn distance from `u` to `v`, if `v` is reachable.
///
/// # Complexity
/// O(N) time and space (one 0-1 BFS over 4N states).
pub fn turn_distance(region: &Region, u: Port, v: Port) -> Option<u32> {
    let mut search = TurnSearch::new(region);
    let arrive = v.arrive();
    search.run(region, u, u32::MAX, |p, h, _| {
        p == v.pixel && arrive & bit(h) != 0
    });
    search.distance_to(v)
}

/// A least source of [`cheapest_sources`]: `key = w(u, v) − offset[u]`, `turns = w(u, v)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Source {
    pub key: f64,
    pub turns: u32,
    pub port: usize,
}

/// A heap entry of [`cheapest_sources`], ordered by key (least first), then state and port.
#[derive(Clone, Copy, PartialEq)]
struct Entry(f64, u32, u32, u32);

impl Eq for Entry {}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other
            .0
            .total_cmp(&self.0)
            .then(other.2.cmp(&self.2))
            .then(other.3.cmp(&self.3))
            .then(other.1.cmp(&self.1))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// For every port v, the `k` least values of `w(u, v) − offset[u]` over the ports `u ≠ v`
/// (distinct ports, least first), keeping only values below `cutoff`.
///
/// One Dijkstra over (pixel, heading) states from all ports at once, each port starting at
/// `−offset[u]`; a state keeps its k + 1 least distinct sources (one may be v itself). This is
/// the k-nearest-distinct-sources search: if u is among the k + 1 least sources of a state,
/// it is among those of the state before it on its cheapest path, so nothing is lost.
///
/// # Complexity
/// O(k · N log N) time, O(k · N) space.
pub(crate) fn cheapest_sources(
    region: &Region,
    ports: &[Port],
    offset: &[f64],
    k: usize,
    cutoff: f64,
) -> Vec<Vec<Source>> {
    let slots = k + 1;
    let mut count = vec![0u8; 4 * region.len()];
    let mut kept: Vec<Source> = vec![
        Source {
            key: 0.0,
            turns: 0,
            port: 0,
        };
        4 * region.len() * slots
    ];
    let mut heap = std::collections::BinaryHeap::new();
    for (u, port) in ports.iter().enumerate() {
        for d in Dir::ALL {
            if port.leave & bit(d) != 0 && -offset[u] < cutoff {
                heap.push(Entry(
                    -offset[u],
                    0,
                    (4 * port.pixel + d.index()) as u32,
                    u as u32,
                ));
            }
        }
    }
    while let Some(Entry(key, turns, s, u)) = heap.pop() {
        let at = s as usize * slots;
        let n = count[s as usize] as usize;
        if n == slots || kept[at..at + n].iter().any(|e| e.port == u as usize) {
            continue;
        }
        kept[at + n] = Source {
            key,
            turns,
            port: u as usize,
        };
        count[s as usize] += 1;
        let (pixel, heading) = ((s / 4) as usize, Dir::from_index((s % 4) as usize));
        if let Some(next) = region.neighbor(pixel, heading) {
            heap.push(Entry(key, turns, (4 * next + heading.index()) as u32, u));
        }
        if key + 1.0 < cutoff {
            for turned in [heading.left(), heading.right()] {
                let t = (4 * pixel + turned.index()) as u32;
                if (count[t as usize] as usize) < slots {
                    heap.push(Entry(key + 1.0, turns + 1, t, u));
                }
            }
        }
    }
    ports
        .iter()
        .enumerate()
        .map(|(v, port)| {
            let mut best: Vec<Source> = Vec::new();
            let arrive = port.arrive();
            for d in Dir::ALL.iter().filter(|d| arrive & bit(**d) != 0) {
                let s = 4 * port.pixel + d.index();
                for e in &kept[s * slots..s * slots + count[s] as usize] {
                    if e.port == v {
                        continue;
                    }
                    match best.iter_mut().find(|b| b.port == e.port) {
                        Some(b) if b.key <= e.key => {}
                        Some(b) => *b = *e,
                        None => best.push(*e),
                    }
                }
            }
            best.sort_by(|a, b| a.key.total_cmp(&b.key).then(a.port.cmp(&b.port)));
            best.truncate(k);
            best
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::{Pixel, Region};

    fn port(r: &Region, x: i32, y: i32, horizontal: bool) -> Port {
        Port::strip_end(r.index_of(Pixel::new(x, y)).unwrap(), horizontal)
    }

    #[test]
    fn strip_ends_of_a_rectangle() {
        let r = Region::rectangle(5, 3);
        // The two ends of one horizontal strip: leave north, turn, run west, turn: 2 turns.
        assert_eq!(
            turn_distance(&r, port(&r, 4, 1, true), port(&r, 0, 1, true)),
            Some(2)
        );
        // Ends of two horizontal strips facing each other across a column: 0 turns.
        assert_eq!(
            turn_distance(&r, port(&r, 4, 0, true), port(&r, 4, 2, true)),
            Some(0)
        );
        // Horizontal strip end to vertical strip end at another pixel: one turn.
        assert_eq!(
            turn_distance(&r, port(&r, 4, 0, true), port(&r, 0, 2, false)),
            Some(1)
        );
        // Same pixel, the two ports of a length-one strip: no move, no turn.
        let one = Region::rectangle(1, 1);
        assert_eq!(
            turn_distance(&one, port(&one, 0, 0, true), port(&one, 0, 0, true)),
            Some(0)
        );
    }

    #[test]
    fn symmetric_and_path_consistent() {
        let r = Region::from_ascii(
            "####.\n\
             #..##\n\
             ##..#\n\
             .####\n",
        );
        let ports: Vec<Port> = (0..r.len())
            .flat_map(|i| [Port::strip_end(i, true), Port::strip_end(i, false)])
            .collect();
        let mut search = TurnSearch::new(&r);
        for &u in &ports {
            search.run(&r, u, u32::MAX, |_, _, _| false);
            for &v in &ports {
                let d = search.distance_to(v);
                assert_eq!(d, turn_distance(&r, v, u));
                let path = search.path_to(v).unwrap();
                assert_eq!((path[0], *path.last().unwrap()), (u.pixel, v.pixel));
                assert!(
                    path.windows(2)
                        .all(|w| r.pixel(w[0]).dir_to(r.pixel(w[1])).is_some())
                );
            }
        }
    }

    #[test]
    fn cheapest_sources_agree_with_single_searches() {
        let r = Region::from_ascii(
            "#####.\n\
             #..###\n\
             ##..##\n\
             .#####\n",
        );
        let ports: Vec<Port> = (0..r.len())
            .step_by(2)
            .flat_map(|i| [Port::strip_end(i, true), Port::strip_end(i, false)])
            .collect();
        let offset: Vec<f64> = (0..ports.len()).map(|i| (i % 5) as f64 * 0.5).collect();
        for k in [1, 3] {
            let found = cheapest_sources(&r, &ports, &offset, k, 2.5);
            for (v, list) in found.iter().enumerate() {
                let mut all: Vec<(f64, usize)> = (0..ports.len())
                    .filter(|&u| u != v)
                    .map(|u| {
                        let w = turn_distance(&r, ports[u], ports[v]).unwrap();
                        (f64::from(w) - offset[u], u)
                    })
                    .filter(|&(key, _)| key < 2.5)
                    .collect();
                all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
                let keys: Vec<f64> = list.iter().map(|e| e.key).collect();
                let want: Vec<f64> = all.iter().take(k).map(|e| e.0).collect();
                assert_eq!(keys, want, "port {v}, k {k}");
                for e in list {
                    let w = turn_distance(&r, ports[e.port], ports[v]).unwrap();
                    assert_eq!(e.turns, w);
                    assert_eq!(e.key, f64::from(w) - offset[e.port]);
                }
            }
        }
    }
}
