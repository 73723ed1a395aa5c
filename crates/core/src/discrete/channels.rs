//! The channels of a discrete instance (maximal straight trails) and the per-vertex turn
//! count β that the star cover's ratio is built from: facts of the instance, used by the star
//! cover (`mowmill_algorithms::discrete::star_cover`, whose module documentation has the
//! argument), by its exact rook bound and by Table 1's parameters ([`Discrete::params`]).
//!
//! A *channel* is a maximal straight trail: from an edge, go on through the collinear partner
//! at each end until an end has none. The collinear pairs form a matching at every vertex, so
//! the channels partition the edges, and each is *open* (two ends), a *loop* (open with both
//! ends at one vertex) or *closed* (a cycle of straight passes, a "ring").

use super::{Discrete, NONE};

/// One channel: its vertex sequence end to end (open and loop channels, `verts[0]` and the
/// last vertex are the ends, equal for a loop), or once around (closed, the first vertex not
/// repeated).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Channel {
    pub verts: Vec<u32>,
    pub closed: bool,
}

impl Channel {
    /// Whether the channel is open with both ends at one vertex.
    pub fn is_loop(&self) -> bool {
        !self.closed && self.verts.first() == self.verts.last()
    }

    /// The number of edges.
    pub fn edges(&self) -> usize {
        if self.closed {
            self.verts.len()
        } else {
            self.verts.len() - 1
        }
    }
}

/// The channels of an instance and, for every edge end (port), its channel and the position of
/// its vertex in the channel's sequence.
#[derive(Clone, Debug)]
pub struct Channels {
    pub list: Vec<Channel>,
    port_channel: Vec<u32>,
    port_pos: Vec<u32>,
}

impl Channels {
    /// The channel of port `p` (an index into the instance's port list, [`Discrete::ports`]).
    pub fn channel_of(&self, p: usize) -> u32 {
        self.port_channel[p]
    }

    /// The position of port `p`'s vertex in its channel's vertex sequence.
    pub fn position_of(&self, p: usize) -> u32 {
        self.port_pos[p]
    }

    /// The distinct channels through `v`, in the order of `v`'s neighbours.
    pub fn through(&self, inst: &Discrete, v: u32) -> Vec<u32> {
        let mut out: Vec<u32> = Vec::new();
        for p in inst.ports(v) {
            let c = self.port_channel[p];
            if !out.contains(&c) {
                out.push(c);
            }
        }
        out
    }
}

/// The channels of `inst` (maximal straight trails).
///
/// # Complexity
/// O(n + |E| log μ).
pub fn channels(inst: &Discrete) -> Channels {
    let ports = inst.nbr.len();
    let owner: Vec<u32> = (0..inst.len())
        .flat_map(|v| {
            let d = inst.degree(v as u32);
            std::iter::repeat_n(v as u32, d)
        })
        .collect();
    let rev: Vec<u32> = (0..ports)
        .map(|p| {
            inst.port(inst.nbr[p], owner[p])
                .expect("edges are symmetric") as u32
        })
        .collect();
    let mut port_channel = vec![NONE; ports];
    let mut port_pos = vec![NONE; ports];
    let mut list = Vec::new();
    // Open channels, traced from each unmatched end.
    for p0 in 0..ports {
        if inst.straight[p0] != NONE || port_channel[p0] != NONE {
            continue;
        }
        let id = list.len() as u32;
        let mut verts = vec![owner[p0]];
        let mut p = p0;
        loop {
            let e = verts.len() as u32 - 1;
            let q = rev[p] as usize;
            port_channel[p] = id;
            port_pos[p] = e;
            port_channel[q] = id;
            port_pos[q] = e + 1;
            verts.push(inst.nbr[p]);
            let s = inst.straight[q];
            if s == NONE {
                break;
            }
            p = s as usize;
        }
        list.push(Channel {
            verts,
            closed: false,
        });
    }
    // What is left are closed channels: every step goes on straight.
    for p0 in 0..ports {
        if port_channel[p0] != NONE {
            continue;
        }
        let id = list.len() as u32;
        let mut verts = vec![owner[p0]];
        let mut p = p0;
        loop {
            let e = verts.len() as u32 - 1;
            let q = rev[p] as usize;
            port_channel[p] = id;
            port_pos[p] = e;
            port_channel[q] = id;
            port_pos[q] = e + 1;
            let s = inst.straight[q];
            debug_assert_ne!(s, NONE, "an unmatched end was traced as open");
            if s as usize == p0 {
                // Back at the first vertex: its position is 0, not the sequence's length.
                port_pos[q] = 0;
                break;
            }
            verts.push(inst.nbr[p]);
            p = s as usize;
        }
        list.push(Channel {
            verts,
            closed: true,
        });
    }
    Channels {
        list,
        port_channel,
        port_pos,
    }
}

/// β(v) = dir(v) + 2·deg(v), plus 1 for a leaf and 4 for an isolated vertex: the most turns
/// the star walk of a rook at `v` can have (module documentation).
pub fn beta(inst: &Discrete, v: u32) -> u64 {
    let deg = inst.degree(v) as u64;
    let extra = match deg {
        0 => 4,
        1 => 1,
        _ => 0,
    };
    inst.directions_at(v) as u64 + 2 * deg + extra
}

/// The proven bound on the turns of the star cycle cover: Σ_rooks β(r).
///
/// # Guarantee
/// Star cycle cover turns ≤ this ≤ [`star_ratio`]·|rooks| ≤ [`star_ratio`]·OPT_cc (Theorem 5.1
/// of *Optimal covering tours with turn costs* with per-rook counts; Lemma 4.3 as restated in
/// the module documentation).
pub fn star_turn_bound(inst: &Discrete, rooks: &[u32]) -> u64 {
    rooks.iter().map(|&r| beta(inst, r)).sum()
}

/// The proven approximation ratio of the star cycle cover: max_v β(v) (≤ ρ_max + 2μ, with
/// ρ_max the most directions at a vertex; 10 on grid regions with a vertex of degree 4).
pub fn star_ratio(inst: &Discrete) -> u64 {
    (0..inst.len() as u32)
        .map(|v| beta(inst, v))
        .max()
        .unwrap_or(0)
}
