//! Writing a region's pixels as a TSPLIB instance, so that Concorde or LKH can be run on the
//! same instance.
//!
//! The instance is symmetric TSP (`TYPE: TSP`) with `EDGE_WEIGHT_TYPE: MAN_2D`: one node per
//! pixel, numbered from 1 in the region's index order (bottom row first, left to right), the
//! weight of a pair the Manhattan distance of their centres. Nodes are written at the pixels'
//! integer coordinates (x, y), their lower-left corners: every centre is (x + ½, y + ½), one
//! common offset, so the Manhattan distances are those of the centres and stay integers.
//!
//! A TSP tour may jump between pixels that are not adjacent, where a milling tour walks the
//! grid graph; by the triangle inequality of the Manhattan metric, the TSP optimum is a lower
//! bound on the length of a milling tour of the region (for N ≥ 2).

use crate::region::Region;
use std::fmt::Write as _;

/// The TSPLIB text of `region`, named `name` (whitespace and `:` in it become `_`).
///
/// # Examples
///
/// ```
/// use mowmill_core::tsplib::to_tsplib;
/// use mowmill_core::Region;
///
/// let text = to_tsplib(&Region::rectangle(2, 1), "pair");
/// assert!(text.starts_with("NAME: pair\nTYPE: TSP\n"));
/// assert!(text.ends_with("DIMENSION: 2\nEDGE_WEIGHT_TYPE: MAN_2D\nNODE_COORD_SECTION\n1 0 0\n2 1 0\nEOF\n"));
/// ```
pub fn to_tsplib(region: &Region, name: &str) -> String {
    let name: String = name
        .chars()
        .map(|c| {
            if c.is_whitespace() || c == ':' {
                '_'
            } else {
                c
            }
        })
        .collect();
    let mut out = String::with_capacity(24 * region.len() + 300);
    let _ = writeln!(out, "NAME: {name}");
    out.push_str("TYPE: TSP\n");
    let _ = writeln!(
        out,
        "COMMENT: {} pixel centres of a grid region, written by mowmill; node (x, y) is the \
         pixel [x, x+1] x [y, y+1], centre (x+1/2, y+1/2), so MAN_2D distances are those of \
         the centres",
        region.len()
    );
    let _ = writeln!(out, "DIMENSION: {}", region.len());
    out.push_str("EDGE_WEIGHT_TYPE: MAN_2D\n");
    out.push_str("NODE_COORD_SECTION\n");
    for (k, p) in region.pixels().iter().enumerate() {
        let _ = writeln!(out, "{} {} {}", k + 1, p.x, p.y);
    }
    out.push_str("EOF\n");
    out
}
