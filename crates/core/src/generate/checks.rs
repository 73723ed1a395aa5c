//! The promise of a generated region and its independent check with the global functions of
//! [`crate::topology`].

use crate::region::Region;
use crate::topology;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum CutRule {
    Any,
    /// No cut vertex (Theorem 5 of the milling paper).
    NoCut,
    /// No local cut vertex (Definition 6, Theorem 7 of the milling paper).
    NoLocalCut,
}

/// What a generated region must satisfy, checked with the global functions of `topology`.
#[derive(Clone, Debug)]
pub(super) struct Promise {
    pub(super) n: usize,
    /// How far the pixel count may lie from `n` (0: exactly n).
    pub(super) n_slack: usize,
    pub(super) components: usize,
    pub(super) holes: usize,
    pub(super) cut: CutRule,
    pub(super) thin: bool,
    /// Components pairwise at Chebyshev distance ≥ 2 (no 8-adjacency between components).
    pub(super) separated: bool,
    /// Any number of holes (`holes` is then ignored).
    pub(super) any_holes: bool,
    /// Every pixel a boundary pixel (`topology::is_boundary`).
    pub(super) boundary_only: bool,
    /// Every pixel of even degree in the grid graph (an Eulerian region).
    pub(super) even_degrees: bool,
}

/// Checks `promise`; returns the number of holes.
pub(super) fn verify(region: &Region, promise: &Promise) -> std::result::Result<usize, String> {
    if region.len().abs_diff(promise.n) > promise.n_slack {
        return Err(format!(
            "{} pixels instead of {} (± {})",
            region.len(),
            promise.n,
            promise.n_slack
        ));
    }
    let comps = topology::components(region);
    if comps.count != promise.components {
        return Err(format!(
            "{} components instead of {}",
            comps.count, promise.components
        ));
    }
    let holes = topology::holes(region).count;
    if holes != promise.holes && !promise.any_holes {
        return Err(format!("{holes} holes instead of {}", promise.holes));
    }
    let bad = match promise.cut {
        CutRule::Any => 0,
        CutRule::NoCut => topology::cut_vertices(region)
            .iter()
            .filter(|&&c| c)
            .count(),
        CutRule::NoLocalCut => topology::local_cut_vertices(region)
            .iter()
            .filter(|&&c| c)
            .count(),
    };
    if bad > 0 {
        return Err(format!("{bad} forbidden (local) cut vertices"));
    }
    if promise.thin && !topology::is_thin(region) {
        return Err("a 2x2 block in a thin region".to_string());
    }
    if promise.boundary_only
        && let Some(i) = (0..region.len()).find(|&i| !topology::is_boundary(region, i))
    {
        return Err(format!("inner pixel {}", region.pixel(i)));
    }
    if promise.even_degrees
        && let Some(&p) = region
            .pixels()
            .iter()
            .find(|&&p| grid_degree(region, p) % 2 == 1)
    {
        return Err(format!("pixel {p} of odd degree"));
    }
    if promise.separated {
        for (i, &p) in region.pixels().iter().enumerate() {
            for q in topology::ring(p) {
                if let Some(j) = region.index_of(q)
                    && comps.label[j] != comps.label[i]
                {
                    return Err(format!("components touch at {p} and {q}"));
                }
            }
        }
    }
    Ok(holes)
}

/// The number of 4-neighbours of `p` in the region.
pub(super) fn grid_degree(region: &Region, p: crate::region::Pixel) -> usize {
    [(1, 0), (-1, 0), (0, 1), (0, -1)]
        .iter()
        .filter(|&&(dx, dy)| {
            region
                .index_of(crate::region::Pixel::new(p.x + dx, p.y + dy))
                .is_some()
        })
        .count()
}
