//! Discrete milling (Section 2.1 of *Optimal covering tours with turn costs*): the general
//! model that grid regions, voxel regions and the other planar lattices are special cases of.
//!
//! An instance is a simple graph whose vertices are the "pixels" to cover. Every vertex has a
//! set of *collinear* pairs of incident edges, forming a matching (each incident edge is in at
//! most one pair). A closed walk pays, at every vertex it passes, 0 turns for going straight
//! through a collinear pair, 1 for any other change of channel and 2 for a U-turn (leaving by
//! the edge it came in on). Its length is the number of edges walked. A grid region is the
//! special case of its 4-neighbour grid graph with the east–west and north–south pairs
//! collinear ([`Discrete::from_region`]).
//!
//! The instance parameters of Table 1: δ the average degree, μ the maximum degree and ρ the
//! average number of distinct directions at a vertex (pairs of its matching plus its unmatched
//! edges) ([`Discrete::params`]). Instances built from a lattice with `d` allowed directions
//! (restricted-direction milling, Theorem 5.2) also carry `d`.
//!
//! Walks are sequences of vertex indices ([`VertexWalk`]); the one checker for this model is
//! [`check::check`].
//!
//! This is the model (instances, formats, generators, the checker); the star cover and the
//! merge are in `mowmill_algorithms::discrete`, the exact models in `mowmill_exact::discrete`,
//! and all of them are gathered under `mowmill::discrete`.

pub mod channels;
pub mod check;
pub mod format;
pub mod generate;
pub mod lattice;

use crate::error::{Error, Result};
use crate::region::{Dir, Region};
use serde::Serialize;

/// A closed walk of a discrete instance: consecutive vertices adjacent, the last adjacent to the
/// first; a single vertex is a walk of length 0.
pub type VertexWalk = Vec<u32>;

const NONE: u32 = u32::MAX;

/// A discrete milling instance: a simple graph with a collinear matching at every vertex and
/// optional coordinates for drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Discrete {
    /// Neighbours of vertex `v`: `nbr[start[v]..start[v + 1]]`, sorted (its *ports*).
    start: Vec<u32>,
    nbr: Vec<u32>,
    /// For every port, the port of the same vertex it is collinear with (an index into `nbr`),
    /// or `NONE`.
    straight: Vec<u32>,
    /// Coordinates of every vertex (x, y, z; z = 0 in the plane), if known.
    coords: Option<Vec<[f64; 3]>>,
    /// The number of allowed directions when the instance comes from a lattice (Theorem 5.2).
    directions: Option<u32>,
}

/// The parameters of Table 1 of the turn-cost paper, computed per instance.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Params {
    /// δ: the average degree.
    pub delta: f64,
    /// μ: the maximum degree.
    pub mu: u32,
    /// ρ: the average number of distinct directions at a vertex.
    pub rho: f64,
    /// d: the allowed directions of a lattice instance.
    pub d: Option<u32>,
    /// The exact counts behind the averages: n vertices, |E| edges (δ = 2|E|/n) and the sum of
    /// the directions at the vertices (ρ = direction_sum/n).
    pub n: u64,
    pub edges: u64,
    pub direction_sum: u64,
    /// max_v β(v), the star cover's proven ratio ([`channels::star_ratio`]).
    pub beta_max: u64,
}

impl Params {
    /// No parameters: an instance that is not a graph (an orthogonal polygon with arbitrary
    /// coordinates). n = 0 and no d, so that no factor in them resolves to a number that means
    /// anything: callers do not resolve scaled guarantees on such instances.
    pub fn none() -> Params {
        Params {
            delta: 0.0,
            mu: 0,
            rho: 0.0,
            d: None,
            n: 0,
            edges: 0,
            direction_sum: 0,
            beta_max: 0,
        }
    }
}

impl Discrete {
    /// An instance on vertices `0..n` with the undirected `edges` and, for every triple
    /// `(v, a, b)` of `collinear`, the edges `va` and `vb` collinear at `v`.
    ///
    /// # Errors
    /// [`Error::Invalid`] when an edge is a loop, repeated or names a vertex `>= n`, when a
    /// collinear pair is not two distinct edges at its vertex, or when an edge is in two pairs
    /// at one vertex (the pairs must form a matching), or when `coords` has the wrong length.
    pub fn new(
        n: usize,
        edges: &[(u32, u32)],
        collinear: &[(u32, u32, u32)],
        coords: Option<Vec<[f64; 3]>>,
    ) -> Result<Discrete> {
        if n >= NONE as usize {
            return Err(Error::invalid(format!("{n} vertices: too many")));
        }
        let mut degree = vec![0u32; n + 1];
        for (k, &(a, b)) in edges.iter().enumerate() {
            if a as usize >= n || b as usize >= n {
                return Err(Error::invalid(format!(
                    "edge {k} ({a}, {b}) names a vertex outside 0..{n}"
                )));
            }
            if a == b {
                return Err(Error::invalid(format!("edge {k} ({a}, {b}) is a loop")));
            }
            degree[a as usize + 1] += 1;
            degree[b as usize + 1] += 1;
        }
        for v in 0..n {
            degree[v + 1] += degree[v];
        }
        let start = degree;
        let mut fill = start.clone();
        let mut nbr = vec![0u32; start[n] as usize];
        for &(a, b) in edges {
            for (u, w) in [(a, b), (b, a)] {
                nbr[fill[u as usize] as usize] = w;
                fill[u as usize] += 1;
            }
        }
        for v in 0..n {
            let ports = &mut nbr[start[v] as usize..start[v + 1] as usize];
            ports.sort_unstable();
            if let Some(w) = ports.windows(2).find(|w| w[0] == w[1]) {
                return Err(Error::invalid(format!(
                    "edge ({v}, {}) is given twice",
                    w[0]
                )));
            }
        }
        let mut inst = Discrete {
            straight: vec![NONE; nbr.len()],
            start,
            nbr,
            coords: None,
            directions: None,
        };
        for &(v, a, b) in collinear {
            if v as usize >= n {
                return Err(Error::invalid(format!(
                    "collinear pair at vertex {v} outside 0..{n}"
                )));
            }
            let (Some(pa), Some(pb)) = (inst.port(v, a), inst.port(v, b)) else {
                return Err(Error::invalid(format!(
                    "collinear pair ({a}, {b}) at vertex {v}: both must be neighbours of {v}"
                )));
            };
            if pa == pb {
                return Err(Error::invalid(format!(
                    "collinear pair ({a}, {b}) at vertex {v}: the two edges must differ"
                )));
            }
            for p in [pa, pb] {
                if inst.straight[p] != NONE {
                    return Err(Error::invalid(format!(
                        "edge ({v}, {}) is in two collinear pairs at vertex {v}: the pairs must form a matching",
                        inst.nbr[p]
                    )));
                }
            }
            inst.straight[pa] = pb as u32;
            inst.straight[pb] = pa as u32;
        }
        inst.set_coords(coords)?;
        Ok(inst)
    }

    /// The grid graph of a region, east–west and north–south pairs collinear, pixel centres
    /// as coordinates: integral orthogonal milling as discrete milling (Section 2.1). Vertex
    /// `i` is pixel `i` of the region.
    pub fn from_region(region: &Region) -> Discrete {
        let edges: Vec<(u32, u32)> = region.edges().map(|(a, b)| (a as u32, b as u32)).collect();
        let mut collinear = Vec::new();
        for v in 0..region.len() {
            for (a, b) in [(Dir::W, Dir::E), (Dir::S, Dir::N)] {
                if let (Some(x), Some(y)) = (region.neighbor(v, a), region.neighbor(v, b)) {
                    collinear.push((v as u32, x as u32, y as u32));
                }
            }
        }
        let coords = region
            .pixels()
            .iter()
            .map(|p| [p.x as f64, p.y as f64, 0.0])
            .collect();
        let mut inst = Discrete::new(region.len(), &edges, &collinear, Some(coords))
            .expect("a region's grid graph is a valid discrete instance");
        inst.directions = Some(2);
        inst
    }

    /// Sets the coordinates (one triple per vertex).
    pub fn set_coords(&mut self, coords: Option<Vec<[f64; 3]>>) -> Result<()> {
        if let Some(c) = &coords
            && c.len() != self.len()
        {
            return Err(Error::invalid(format!(
                "{} coordinates for {} vertices",
                c.len(),
                self.len()
            )));
        }
        self.coords = coords;
        Ok(())
    }

    /// Records that the instance comes from a lattice with `d` allowed directions.
    pub fn set_directions(&mut self, d: Option<u32>) {
        self.directions = d;
    }

    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.start.len() - 1
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of edges.
    pub fn edge_count(&self) -> usize {
        self.nbr.len() / 2
    }

    /// The neighbours of `v`, sorted.
    pub fn neighbors(&self, v: u32) -> &[u32] {
        &self.nbr[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    pub fn degree(&self, v: u32) -> usize {
        self.neighbors(v).len()
    }

    /// The undirected edges, each once as `(a, b)` with `a < b`.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        (0..self.len() as u32).flat_map(move |a| {
            self.neighbors(a)
                .iter()
                .filter(move |&&b| a < b)
                .map(move |&b| (a, b))
        })
    }

    /// The number of connected components.
    pub fn components(&self) -> usize {
        let edges = self.edges().map(|(a, b)| (a as usize, b as usize));
        crate::topology::graph_components(self.len(), edges).1
    }

    /// Whether `a` and `b` are joined by an edge.
    pub fn adjacent(&self, a: u32, b: u32) -> bool {
        (a as usize) < self.len() && self.port(a, b).is_some()
    }

    /// The global port index of neighbour `w` at `v`.
    /// The ports of `v` (indices into the port list, one per incident edge, in the order of
    /// [`Discrete::neighbors`]).
    pub fn ports(&self, v: u32) -> std::ops::Range<usize> {
        self.start[v as usize] as usize..self.start[v as usize + 1] as usize
    }

    fn port(&self, v: u32, w: u32) -> Option<usize> {
        let s = self.start[v as usize] as usize;
        self.neighbors(v).binary_search(&w).ok().map(|k| s + k)
    }

    /// The neighbour collinear with `u` at `v` (where a walk from `u` through `v` goes on
    /// straight), if any.
    pub fn straight_on(&self, u: u32, v: u32) -> Option<u32> {
        let p = self.port(v, u)?;
        let q = self.straight[p];
        (q != NONE).then(|| self.nbr[q as usize])
    }

    /// The collinear pairs at `v`, each once.
    pub fn collinear_pairs(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + '_ {
        let s = self.start[v as usize] as usize;
        self.neighbors(v)
            .iter()
            .enumerate()
            .filter_map(move |(k, &a)| {
                let q = self.straight[s + k];
                (q != NONE && (q as usize) > s + k).then(|| (a, self.nbr[q as usize]))
            })
    }

    /// The turns of passing through `v` from `u` to `w` (both neighbours of `v`): 2 for a
    /// U-turn, 0 through a collinear pair, 1 otherwise.
    pub fn turn(&self, u: u32, v: u32, w: u32) -> u32 {
        if u == w {
            2
        } else if self.straight_on(u, v) == Some(w) {
            0
        } else {
            1
        }
    }

    /// The coordinates of `v`, if the instance has coordinates.
    pub fn coords(&self, v: u32) -> Option<[f64; 3]> {
        self.coords.as_ref().map(|c| c[v as usize])
    }

    /// The number of allowed directions of a lattice instance.
    pub fn directions(&self) -> Option<u32> {
        self.directions
    }

    /// The number of distinct directions at `v`: its collinear pairs plus its unmatched edges.
    pub fn directions_at(&self, v: u32) -> usize {
        let s = self.start[v as usize] as usize;
        let e = self.start[v as usize + 1] as usize;
        let matched = (s..e).filter(|&p| self.straight[p] != NONE).count();
        matched / 2 + (e - s - matched)
    }

    /// δ, μ, ρ (and d) of Table 1.
    pub fn params(&self) -> Params {
        let n = self.len().max(1) as f64;
        let mu = (0..self.len() as u32)
            .map(|v| self.degree(v))
            .max()
            .unwrap_or(0) as u32;
        let direction_sum = (0..self.len() as u32)
            .map(|v| self.directions_at(v))
            .sum::<usize>();
        Params {
            delta: self.nbr.len() as f64 / n,
            mu,
            rho: direction_sum as f64 / n,
            d: self.directions,
            n: self.len() as u64,
            edges: self.edge_count() as u64,
            direction_sum: direction_sum as u64,
            beta_max: channels::star_ratio(self),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_region_has_the_parameters_of_corollary_5_2_inside() {
        // A 3x3 square: the centre has degree 4 and two directions.
        let r = Region::rectangle(3, 3);
        let g = Discrete::from_region(&r);
        assert_eq!(g.len(), 9);
        assert_eq!(g.edge_count(), 12);
        let centre = r.index_of(crate::Pixel::new(1, 1)).unwrap() as u32;
        assert_eq!(g.degree(centre), 4);
        assert_eq!(g.directions_at(centre), 2);
        // A corner: two perpendicular edges, two directions.
        let corner = r.index_of(crate::Pixel::new(0, 0)).unwrap() as u32;
        assert_eq!(g.directions_at(corner), 2);
        let p = g.params();
        assert_eq!(p.mu, 4);
        assert!((p.delta - 24.0 / 9.0).abs() < 1e-12);
        assert!((p.rho - 2.0).abs() < 1e-12, "{p:?}");
        let west = r.index_of(crate::Pixel::new(0, 1)).unwrap() as u32;
        let east = r.index_of(crate::Pixel::new(2, 1)).unwrap() as u32;
        let north = r.index_of(crate::Pixel::new(1, 2)).unwrap() as u32;
        assert_eq!(g.turn(west, centre, east), 0);
        assert_eq!(g.turn(west, centre, north), 1);
        assert_eq!(g.turn(west, centre, west), 2);
    }

    #[test]
    fn invalid_instances_are_refused_with_a_reason() {
        let bad = |edges: &[(u32, u32)], col: &[(u32, u32, u32)]| {
            Discrete::new(3, edges, col, None).unwrap_err().to_string()
        };
        assert!(bad(&[(0, 3)], &[]).contains("outside"));
        assert!(bad(&[(1, 1)], &[]).contains("loop"));
        assert!(bad(&[(0, 1), (1, 0)], &[]).contains("twice"));
        assert!(bad(&[(0, 1), (1, 2)], &[(1, 0, 0)]).contains("must differ"));
        assert!(bad(&[(0, 1), (1, 2)], &[(1, 0, 2), (1, 2, 0)]).contains("matching"));
        assert!(bad(&[(0, 1)], &[(1, 0, 2)]).contains("neighbours"));
        let ok = Discrete::new(3, &[(0, 1), (1, 2)], &[(1, 0, 2)], None).unwrap();
        assert_eq!(ok.turn(0, 1, 2), 0);
        assert_eq!(ok.turn(2, 1, 0), 0);
        assert_eq!(ok.collinear_pairs(1).collect::<Vec<_>>(), vec![(0, 2)]);
    }
}
