//! The matching above [`LARGE`] endpoints: Z-order tiles of endpoints, each matched by blossom
//! over its near candidates.

use super::*;

/// Above this many endpoints: one pricing round, [`CUT_ROUNDS_LARGE`] cut rounds, and the
/// matching from tiles ([`tiled_matching`]) rather than from the LP (blossom on what the LP
/// leaves fractional takes minutes there).
pub(super) const LARGE: usize = 10_000;

/// Tiles of about this many endpoints (above [`LARGE`]).
pub(super) const TILE: usize = 1000;

/// Per endpoint at least this many candidates in its tile (above [`LARGE`]).
pub(super) const TILE_NEAR: usize = 12;

/// ... at most this many turns away.
pub(super) const TILE_TURNS: u32 = 6;

/// Interleaves the bits of two 32-bit coordinates (a Z-order key).
pub(super) fn z_order(x: u32, y: u32) -> u64 {
    let spread = |v: u32| {
        let mut v = u64::from(v);
        v = (v | (v << 16)) & 0x0000_ffff_0000_ffff;
        v = (v | (v << 8)) & 0x00ff_00ff_00ff_00ff;
        v = (v | (v << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
        v = (v | (v << 2)) & 0x3333_3333_3333_3333;
        (v | (v << 1)) & 0x5555_5555_5555_5555
    };
    spread(x) | (spread(y) << 1)
}

/// The tile of every endpoint: pairs (i, partner\[i\]) in Z-order, cut every [`TILE`] endpoints.
pub(super) fn tiles(region: &Region, ports: &[Port], partner: &[usize]) -> Vec<u32> {
    let b = region.bbox();
    let key = |i: usize| {
        let p = region.pixel(ports[i].pixel.min(ports[partner[i]].pixel));
        z_order((p.x - b.min_x) as u32, (p.y - b.min_y) as u32)
    };
    let mut pairs: Vec<usize> = (0..ports.len()).filter(|&i| i < partner[i]).collect();
    pairs.sort_by_key(|&i| (key(i), i));
    let mut tile = vec![0u32; ports.len()];
    for (k, &i) in pairs.iter().enumerate() {
        let t = (2 * k / TILE) as u32;
        tile[i] = t;
        tile[partner[i]] = t;
    }
    tile
}

/// A candidate pair (smaller endpoint, larger endpoint, weight).
pub(super) type Pair = (usize, usize, u32);

/// The matching used above [`LARGE`] endpoints (and where [`repair`] fails), where blossom after the LP is too slow: the
/// endpoint pairs (an endpoint and its partner) in Z-order, cut into tiles of [`TILE`]
/// endpoints, each tile matched by blossom over, per endpoint, the endpoints of its tile met
/// by its 0-1 BFS up to the end of the first turn level with [`TILE_NEAR`] of them (at most
/// [`TILE_TURNS`] turns), plus its partner. Returns the mates and the candidate pairs.
pub(super) fn tiled_matching(
    region: &Region,
    ports: &[Port],
    partner: &[usize],
    floor: &[u32],
) -> Result<(Vec<usize>, Vec<Pair>)> {
    let tile = tiles(region, ports, partner);
    let edges = candidate_edges(
        region,
        ports,
        partner,
        floor,
        Some((TILE_NEAR, TILE_TURNS)),
        Some(&tile),
    )?;
    let mate = min_weight_perfect_matching(ports.len(), &edges)
        .ok_or_else(|| Error::solver("the endpoints have no perfect matching"))?;
    Ok((mate, edges))
}
