//! Structural moves of the hunt: changes to a whole sub-rectangle of a region, for the shapes
//! local moves reach only by chance at large N (lattices of one-pixel holes, width-1 parts,
//! repeated motifs).
//!
//! Each move is a plain function of a region and an explicit [`Rect`] (so that a test can
//! assert what it does); [`random`] draws the move and its rectangle. A move may leave the
//! family's constraint (disconnect the region, fill its last hole): the hunt checks every
//! neighbour and redraws the rejected ones.

use crate::region::{Pixel, Region};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeSet;

/// An axis-parallel rectangle of cells: `x0..x0 + w` × `y0..y0 + h`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x0: i32,
    pub y0: i32,
    pub w: i32,
    pub h: i32,
}

impl Rect {
    fn cells(self) -> impl Iterator<Item = (i32, i32)> {
        (0..self.h).flat_map(move |j| (0..self.w).map(move |i| (i, j)))
    }

    fn at(self, i: i32, j: i32) -> Pixel {
        Pixel::new(self.x0 + i, self.y0 + j)
    }
}

/// Where the one-pixel holes of a lattice go, at offset (i, j) from the rectangle's corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lattice {
    /// Every other cell of every other row and column: (i, j) both odd.
    Square,
    /// Rows alternate between full rows and rows with a hole at every other cell, the holed
    /// rows' offsets alternating: j odd and i + ⌊j/2⌋ odd (no full 2×2 block inside).
    Staggered,
    /// A knight's-move lattice: i + 2j ≡ 0 (mod 5) (no two holes touch, even at a corner).
    Diagonal,
    /// One hole per 3×3 block: i ≡ j ≡ 1 (mod 3).
    Sparse,
}

impl Lattice {
    pub const ALL: [Lattice; 4] = [
        Lattice::Square,
        Lattice::Staggered,
        Lattice::Diagonal,
        Lattice::Sparse,
    ];

    /// Whether the cell at offset (i, j) is a hole.
    pub fn hole(self, i: i32, j: i32) -> bool {
        match self {
            Lattice::Square => i % 2 == 1 && j % 2 == 1,
            Lattice::Staggered => j % 2 == 1 && (i + j / 2) % 2 == 1,
            Lattice::Diagonal => (i + 2 * j) % 5 == 0,
            Lattice::Sparse => i % 3 == 1 && j % 3 == 1,
        }
    }
}

fn region_of(set: BTreeSet<Pixel>) -> Option<Region> {
    if set.is_empty() {
        return None;
    }
    Region::from_pixels(set).ok().map(|r| r.normalized())
}

fn set_of(r: &Region) -> BTreeSet<Pixel> {
    r.pixels().iter().copied().collect()
}

/// Removes the lattice's cells inside `rect` from `r` (cells of `rect` not in `r` stay out).
pub fn hole_lattice(r: &Region, rect: Rect, lattice: Lattice) -> Option<Region> {
    let mut set = set_of(r);
    for (i, j) in rect.cells() {
        if lattice.hole(i, j) {
            set.remove(&rect.at(i, j));
        }
    }
    region_of(set)
}

/// Makes `rect` exactly the lattice's pattern: every cell of `rect` becomes a pixel except the
/// lattice's holes (cells outside `rect` stay as they are). Unlike [`hole_lattice`], which only
/// removes, this fills a ragged part first, so a lattice over most of a random region stays
/// connected.
pub fn lattice_fill(r: &Region, rect: Rect, lattice: Lattice) -> Option<Region> {
    let mut set = set_of(r);
    for (i, j) in rect.cells() {
        if lattice.hole(i, j) {
            set.remove(&rect.at(i, j));
        } else {
            set.insert(rect.at(i, j));
        }
    }
    region_of(set)
}

/// Keeps only the part of `r` inside `rect`, and of it the largest 4-connected piece (ties: the
/// one with the smallest pixel), so that a region's ragged border can be cut away.
pub fn crop(r: &Region, rect: Rect) -> Option<Region> {
    let inside = |p: &Pixel| {
        (rect.x0..rect.x0 + rect.w).contains(&p.x) && (rect.y0..rect.y0 + rect.h).contains(&p.y)
    };
    let kept = Region::from_pixels(r.pixels().iter().copied().filter(inside)).ok()?;
    let comps = crate::topology::components(&kept);
    let mut size = vec![0usize; comps.count];
    for &c in &comps.label {
        size[c as usize] += 1;
    }
    let best = (0..comps.count).max_by_key(|&c| (size[c], std::cmp::Reverse(c)))?;
    region_of(
        (0..kept.len())
            .filter(|&i| comps.label[i] as usize == best)
            .map(|i| kept.pixel(i))
            .collect(),
    )
}

/// Thins the part of `r` inside `rect` to width 1: a comb whose spine is the rectangle's left
/// column and whose teeth are its even rows (offset j even); the other cells are removed.
pub fn thin_comb(r: &Region, rect: Rect) -> Option<Region> {
    let mut set = set_of(r);
    for (i, j) in rect.cells() {
        if i != 0 && j % 2 == 1 {
            set.remove(&rect.at(i, j));
        }
    }
    region_of(set)
}

/// Widens the part of `r` inside `rect` by one cell in direction (dx, dy): every pixel of `r`
/// in `rect` gets its neighbour in that direction.
pub fn widen(r: &Region, rect: Rect, (dx, dy): (i32, i32)) -> Option<Region> {
    let mut set = set_of(r);
    let grown: Vec<Pixel> = rect
        .cells()
        .map(|(i, j)| rect.at(i, j))
        .filter(|p| set.contains(p))
        .map(|p| Pixel::new(p.x + dx, p.y + dy))
        .collect();
    set.extend(grown);
    region_of(set)
}

/// Copies the motif of `r` inside `rect` onto the rectangle next to it (to the right when
/// `right`, else above: offset (w, 0) or (0, h)); the target rectangle is cleared first, so
/// that it becomes an exact copy.
pub fn copy_motif(r: &Region, rect: Rect, right: bool) -> Option<Region> {
    let mut set = set_of(r);
    let (ox, oy) = if right { (rect.w, 0) } else { (0, rect.h) };
    let motif: Vec<Pixel> = rect
        .cells()
        .map(|(i, j)| rect.at(i, j))
        .filter(|p| set.contains(p))
        .collect();
    for (i, j) in rect.cells() {
        set.remove(&rect.at(i + ox, j + oy));
    }
    set.extend(motif.iter().map(|p| Pixel::new(p.x + ox, p.y + oy)));
    region_of(set)
}

/// Duplicates the band of `k` columns (`vertical` false) or rows (`vertical` true) starting at
/// `at`: the part beyond the band moves by `k`, so the region grows by the band's pixels.
pub fn copy_band(r: &Region, at: i32, k: i32, vertical: bool) -> Option<Region> {
    let set: BTreeSet<Pixel> = r
        .pixels()
        .iter()
        .flat_map(|&q| {
            let c = if vertical { q.y } else { q.x };
            let moved = |d| {
                if vertical {
                    Pixel::new(q.x, q.y + d)
                } else {
                    Pixel::new(q.x + d, q.y)
                }
            };
            if c < at {
                vec![q]
            } else if c < at + k {
                vec![q, moved(k)]
            } else {
                vec![moved(k)]
            }
        })
        .collect();
    region_of(set)
}

/// A random sub-rectangle of `r`'s bounding box, of each side at least 2 (when it fits); a
/// quarter of the time the whole bounding box, so that a move's scale grows with the region (a
/// lattice over all of it, a copy of all of it).
fn random_rect(r: &Region, rng: &mut ChaCha8Rng) -> Rect {
    let b = r.bbox();
    let (bw, bh) = (b.width() as i32, b.height() as i32);
    if rng.random_bool(0.25) {
        return Rect {
            x0: b.min_x,
            y0: b.min_y,
            w: bw,
            h: bh,
        };
    }
    let w = rng.random_range(1..=bw).max(2.min(bw));
    let h = rng.random_range(1..=bh).max(2.min(bh));
    Rect {
        x0: b.min_x + rng.random_range(0..=bw - w),
        y0: b.min_y + rng.random_range(0..=bh - h),
        w,
        h,
    }
}

/// One structural move drawn at random (its kind, lattice, rectangle and direction).
pub fn random(r: &Region, rng: &mut ChaCha8Rng) -> Option<Region> {
    let rect = random_rect(r, rng);
    let lattice = Lattice::ALL[rng.random_range(0..Lattice::ALL.len())];
    match rng.random_range(0..7u32) {
        0 => hole_lattice(r, rect, lattice),
        5 => lattice_fill(r, rect, lattice),
        6 => crop(r, rect),
        1 => thin_comb(r, rect),
        2 => {
            let d = [(1, 0), (-1, 0), (0, 1), (0, -1)][rng.random_range(0..4usize)];
            widen(r, rect, d)
        }
        3 => copy_motif(r, rect, rng.random_bool(0.5)),
        _ => {
            let vertical = rng.random_bool(0.5);
            let (at, k) = if vertical {
                (rect.y0, rect.h.min(8))
            } else {
                (rect.x0, rect.w.min(8))
            };
            copy_band(r, at, k, vertical)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topology;

    fn connected(r: &Region) -> bool {
        topology::components(r).count == 1
    }

    /// Each lattice on the 5×5 interior of a 7×7 square removes its documented cells: square
    /// (1,1),(1,3),(3,1),(3,3); staggered 2 + 3; diagonal one per row; sparse (1|4, 1|4).
    #[test]
    fn hole_lattices_remove_the_documented_cells() {
        let square = Region::rectangle(7, 7);
        let inner = Rect {
            x0: 1,
            y0: 1,
            w: 5,
            h: 5,
        };
        for (lattice, holes) in [
            (Lattice::Square, 4),
            (Lattice::Staggered, 5),
            (Lattice::Diagonal, 5),
            (Lattice::Sparse, 4),
        ] {
            let r = hole_lattice(&square, inner, lattice).unwrap();
            assert_eq!(r.len(), 49 - holes, "{lattice:?}");
            assert_eq!(topology::holes(&r).count, holes, "{lattice:?}");
            assert!(connected(&r), "{lattice:?}");
        }
        // The staggered lattice leaves no full 2×2 block inside a 9×9 one.
        let r = hole_lattice(&Region::rectangle(9, 9), inner, Lattice::Staggered).unwrap();
        let c = Region::from_pixels(
            r.pixels()
                .iter()
                .copied()
                .filter(|p| (1..=5).contains(&p.x) && (1..=5).contains(&p.y)),
        )
        .unwrap();
        assert!(topology::summary(&c).thin);
    }

    /// A lattice fill over a ragged region's whole bounding box makes the box exactly the
    /// lattice (a 7×7 staggered fill of an L: every lattice cell empty, the inner ones holes,
    /// connected); a crop keeps
    /// the largest piece inside the rectangle.
    #[test]
    fn lattice_fill_and_crop_do_as_documented() {
        let l =
            Region::from_ascii("#......\n#......\n#......\n#......\n#......\n#......\n#######\n");
        let all = Rect {
            x0: 0,
            y0: 0,
            w: 7,
            h: 7,
        };
        let r = lattice_fill(&l, all, Lattice::Staggered).unwrap();
        let holes = (0..7)
            .flat_map(|j| (0..7).map(move |i| (i, j)))
            .filter(|&(i, j)| Lattice::Staggered.hole(i, j))
            .count();
        let inner = (0..7)
            .flat_map(|j| (0..7).map(move |i| (i, j)))
            .filter(|&(i, j)| Lattice::Staggered.hole(i, j) && (1..6).contains(&i))
            .count();
        assert_eq!(r.len(), 49 - holes);
        assert_eq!(topology::holes(&r).count, inner);
        assert!(connected(&r));
        // Cropping a U to its top two rows leaves two pieces; the larger one is kept.
        let u = Region::from_ascii("#.##\n#..#\n####\n");
        let r = crop(
            &u,
            Rect {
                x0: 0,
                y0: 1,
                w: 4,
                h: 2,
            },
        )
        .unwrap();
        assert_eq!(r.len(), 3);
        assert!(connected(&r));
    }

    /// The comb keeps the left column and the even rows: 5 + 2 · 4 + ... = 17 of 25 pixels,
    /// connected and of width 1.
    #[test]
    fn thin_comb_leaves_a_width_one_comb() {
        let r = thin_comb(
            &Region::rectangle(5, 5),
            Rect {
                x0: 0,
                y0: 0,
                w: 5,
                h: 5,
            },
        )
        .unwrap();
        assert_eq!(r.len(), 17);
        assert!(connected(&r));
        assert!(topology::summary(&r).thin);
    }

    /// Widening a row of 5 upwards gives a 5×2 rectangle; copying a 3×3 ring to its right
    /// gives two rings (16 pixels, 2 holes); copying a band of 2 columns of a 4×3 rectangle
    /// gives a 6×3 one.
    #[test]
    fn widen_and_copies_grow_the_region_as_documented() {
        let all = |w, h| Rect { x0: 0, y0: 0, w, h };
        let r = widen(&Region::rectangle(5, 1), all(5, 1), (0, 1)).unwrap();
        assert_eq!(r.len(), 10);
        assert_eq!(r.bbox().height(), 2);
        let ring = Region::from_ascii("###\n#.#\n###\n");
        let r = copy_motif(&ring, all(3, 3), true).unwrap();
        assert_eq!(r.len(), 16);
        assert_eq!(topology::holes(&r).count, 2);
        assert!(connected(&r));
        let r = copy_motif(&ring, all(3, 3), false).unwrap();
        assert_eq!((r.len(), r.bbox().height()), (16, 6));
        let r = copy_band(&Region::rectangle(4, 3), 1, 2, false).unwrap();
        assert_eq!((r.len(), r.bbox().width()), (18, 6));
        // A copy over existing pixels replaces them: the target becomes the motif exactly.
        let r = copy_motif(&Region::rectangle(6, 3), all(3, 3), true).unwrap();
        assert_eq!(r.len(), 18);
        let r = copy_motif(
            &Region::from_ascii("######\n#.####\n######\n"),
            all(3, 3),
            true,
        )
        .unwrap();
        assert_eq!((r.len(), topology::holes(&r).count), (16, 2));
    }
}
