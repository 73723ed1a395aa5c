//! Joining links (strips or boundary links) into closed walks along a perfect matching of
//! their ends, each matched pair by a cheapest connecting path (the cycle covers of Theorems
//! 4.1 and 5.5 of *Optimal covering tours with turn costs*).

use super::PortMatching;
use super::turn_distance::{Port, TurnSearch, bit};
use crate::error::{Error, Result};
use crate::region::Region;
use crate::tour::CycleCover;
use crate::walks::{close_walk, extend_walk, straight};

/// Joins `links` (strips or boundary links, given by their end pixels) into closed walks by
/// the perfect matching `mate` of their ports (port `2k` is link k's first pixel, `2k + 1` its
/// last), each matched pair by a cheapest connecting path.
pub(crate) fn join_links(
    region: &Region,
    links: &[(usize, usize)],
    ports: &[Port],
    matching: &PortMatching,
) -> Result<CycleCover> {
    let mut search = TurnSearch::new(region);
    let mut done = vec![false; links.len()];
    let mut cycles = Vec::new();
    for first in 0..links.len() {
        if done[first] {
            continue;
        }
        let mut walk = Vec::new();
        let mut port = 2 * first;
        loop {
            let k = port / 2;
            done[k] = true;
            let out = port ^ 1;
            let (a, b) = (
                region.pixel(ports[port].pixel),
                region.pixel(ports[out].pixel),
            );
            extend_walk(&mut walk, straight(a, b));
            let to = matching.mate[out];
            let target = ports[to];
            let w = matching.weight[out.min(to)];
            search.run(region, ports[out], w, |p, h, _| {
                p == target.pixel && target.arrive() & bit(h) != 0
            });
            let path = search.path_to(target).ok_or_else(|| {
                Error::invalid(format!("no path between matched ports {out} and {to}"))
            })?;
            extend_walk(&mut walk, path.into_iter().map(|p| region.pixel(p)));
            port = to;
            if port == 2 * first {
                break;
            }
        }
        cycles.push(close_walk(walk));
    }
    Ok(CycleCover::new(cycles))
}
