//! The core geometric types: [`Pixel`], [`Dir`], [`Region`] and its grid graph.
//!
//! A region is a finite set of unit pixels with integer coordinates (x to the right, y up);
//! its grid graph joins pixels that share a side (4-neighbours). This is the integral
//! orthogonal setting of both papers: the milling paper's grid graph G (Section 6) and the
//! turn-cost paper's integral orthogonal milling (Section 2).

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A unit pixel, named by the integer coordinates of its lower-left corner.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(from = "[i32; 2]", into = "[i32; 2]")]
pub struct Pixel {
    pub x: i32,
    pub y: i32,
}

impl Pixel {
    pub const fn new(x: i32, y: i32) -> Self {
        Pixel { x, y }
    }

    /// The neighbouring pixel one step in direction `d`.
    pub fn step(self, d: Dir) -> Pixel {
        let (dx, dy) = d.delta();
        Pixel::new(self.x + dx, self.y + dy)
    }

    /// Colour class of the checkerboard: black when x + y is even.
    pub fn is_black(self) -> bool {
        (self.x + self.y).rem_euclid(2) == 0
    }

    /// The direction of a unit move from `self` to `other`, if they are 4-adjacent.
    pub fn dir_to(self, other: Pixel) -> Option<Dir> {
        match (other.x - self.x, other.y - self.y) {
            (1, 0) => Some(Dir::E),
            (0, 1) => Some(Dir::N),
            (-1, 0) => Some(Dir::W),
            (0, -1) => Some(Dir::S),
            _ => None,
        }
    }

    /// L1 (Manhattan) distance.
    pub fn l1(self, other: Pixel) -> u64 {
        u64::from(self.x.abs_diff(other.x)) + u64::from(self.y.abs_diff(other.y))
    }
}

impl From<[i32; 2]> for Pixel {
    fn from(a: [i32; 2]) -> Self {
        Pixel::new(a[0], a[1])
    }
}

impl From<Pixel> for [i32; 2] {
    fn from(p: Pixel) -> Self {
        [p.x, p.y]
    }
}

impl From<(i32, i32)> for Pixel {
    fn from((x, y): (i32, i32)) -> Self {
        Pixel::new(x, y)
    }
}

impl fmt::Display for Pixel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

/// One of the four axis-parallel headings, in counter-clockwise order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Dir {
    E = 0,
    N = 1,
    W = 2,
    S = 3,
}

impl Dir {
    pub const ALL: [Dir; 4] = [Dir::E, Dir::N, Dir::W, Dir::S];

    pub fn delta(self) -> (i32, i32) {
        match self {
            Dir::E => (1, 0),
            Dir::N => (0, 1),
            Dir::W => (-1, 0),
            Dir::S => (0, -1),
        }
    }

    pub fn index(self) -> usize {
        self as usize
    }

    pub fn from_index(i: usize) -> Dir {
        Dir::ALL[i % 4]
    }

    pub fn opposite(self) -> Dir {
        Dir::from_index(self.index() + 2)
    }

    /// Counter-clockwise quarter turn.
    pub fn left(self) -> Dir {
        Dir::from_index(self.index() + 1)
    }

    /// Clockwise quarter turn.
    pub fn right(self) -> Dir {
        Dir::from_index(self.index() + 3)
    }

    pub fn is_horizontal(self) -> bool {
        matches!(self, Dir::E | Dir::W)
    }

    /// Turn cost of changing heading from `self` to `next`: 0 straight, 1 for 90°, 2 for a
    /// U-turn (turn-cost paper, Section 2).
    pub fn turn_to(self, next: Dir) -> u32 {
        match (next.index() + 4 - self.index()) % 4 {
            0 => 0,
            2 => 2,
            _ => 1,
        }
    }
}

/// The 8 symmetries of the square (the dihedral group D4), acting on pixels.
///
/// Index `i` in 0..8: rotate by `i % 4` quarter turns counter-clockwise, then mirror in the
/// y-axis when `i >= 4`. Pixels are unit squares, so the map acts on pixel centres.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Symmetry(pub u8);

impl Symmetry {
    pub fn all() -> impl Iterator<Item = Symmetry> {
        (0..8).map(Symmetry)
    }

    pub fn apply(self, p: Pixel) -> Pixel {
        // Work with doubled centre coordinates so that rotations stay integral.
        let (mut cx, mut cy) = (2 * p.x + 1, 2 * p.y + 1);
        for _ in 0..(self.0 % 4) {
            (cx, cy) = (-cy, cx);
        }
        if self.0 >= 4 {
            cx = -cx;
        }
        Pixel::new((cx - 1) / 2, (cy - 1) / 2)
    }
}

/// An axis-parallel bounding box of pixels, inclusive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BBox {
    pub min_x: i32,
    pub min_y: i32,
    pub max_x: i32,
    pub max_y: i32,
}

impl BBox {
    pub fn width(&self) -> usize {
        (i64::from(self.max_x) - i64::from(self.min_x) + 1) as usize
    }

    pub fn height(&self) -> usize {
        (i64::from(self.max_y) - i64::from(self.min_y) + 1) as usize
    }
}

const NONE: u32 = u32::MAX;

/// The largest bounding-box area a region may span (the dense index holds one `u32` per cell).
pub const MAX_BBOX_CELLS: usize = 1 << 30;

/// The most pixels a region may have; larger inputs are refused with an error (exit 2) before
/// anything proportional to them is allocated.
pub const MAX_PIXELS: usize = 20_000_000;

/// A finite set of unit pixels and its grid graph (4-neighbour adjacency).
///
/// Pixels are numbered `0..len()` in row-major order from the bottom row (y ascending, then
/// x ascending); every algorithm refers to pixels by these indices. A dense index over the
/// bounding box answers "which pixel is at (x, y)" in O(1).
#[derive(Clone, PartialEq, Eq)]
pub struct Region {
    pixels: Vec<Pixel>,
    bbox: BBox,
    index: Vec<u32>,
}

impl fmt::Debug for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Region({} pixels)\n{}", self.len(), self.to_ascii())
    }
}

impl Region {
    /// Builds a region from pixels (duplicates are merged). Fails only when the bounding box
    /// is too large for the dense index.
    pub fn from_pixels<I: IntoIterator<Item = Pixel>>(pixels: I) -> Result<Region> {
        let mut pixels: Vec<Pixel> = pixels.into_iter().collect();
        pixels.sort_unstable_by_key(|p| (p.y, p.x));
        pixels.dedup();
        if pixels.is_empty() {
            return Ok(Region {
                pixels,
                bbox: BBox {
                    min_x: 0,
                    min_y: 0,
                    max_x: -1,
                    max_y: -1,
                },
                index: Vec::new(),
            });
        }
        let bbox = BBox {
            min_x: pixels.iter().map(|p| p.x).min().unwrap_or(0),
            max_x: pixels.iter().map(|p| p.x).max().unwrap_or(0),
            min_y: pixels[0].y,
            max_y: pixels[pixels.len() - 1].y,
        };
        let cells = bbox.width().saturating_mul(bbox.height());
        if cells > MAX_BBOX_CELLS || pixels.len() >= NONE as usize {
            return Err(Error::Invalid(format!(
                "region's bounding box {}x{} is too large (at most {} cells)",
                bbox.width(),
                bbox.height(),
                MAX_BBOX_CELLS
            )));
        }
        let mut index = vec![NONE; cells];
        let w = bbox.width();
        for (i, p) in pixels.iter().enumerate() {
            index[(p.y - bbox.min_y) as usize * w + (p.x - bbox.min_x) as usize] = i as u32;
        }
        Ok(Region {
            pixels,
            bbox,
            index,
        })
    }

    /// A `w` × `h` rectangle with lower-left pixel (0, 0).
    pub fn rectangle(w: i32, h: i32) -> Region {
        Region::from_pixels((0..h).flat_map(|y| (0..w).map(move |x| Pixel::new(x, y))))
            .expect("rectangle fits the index")
    }

    /// Number of pixels, N.
    pub fn len(&self) -> usize {
        self.pixels.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pixels.is_empty()
    }

    /// All pixels, in index order.
    pub fn pixels(&self) -> &[Pixel] {
        &self.pixels
    }

    pub fn pixel(&self, i: usize) -> Pixel {
        self.pixels[i]
    }

    /// Bounding box (meaningless for an empty region).
    pub fn bbox(&self) -> BBox {
        self.bbox
    }

    /// Index of the pixel at `p`, if `p` is in the region.
    pub fn index_of(&self, p: Pixel) -> Option<usize> {
        let b = &self.bbox;
        if p.x < b.min_x || p.x > b.max_x || p.y < b.min_y || p.y > b.max_y {
            return None;
        }
        let k = (p.y - b.min_y) as usize * b.width() + (p.x - b.min_x) as usize;
        match self.index[k] {
            NONE => None,
            i => Some(i as usize),
        }
    }

    pub fn contains(&self, p: Pixel) -> bool {
        self.index_of(p).is_some()
    }

    /// Index of the neighbour of pixel `i` in direction `d`, if present.
    pub fn neighbor(&self, i: usize, d: Dir) -> Option<usize> {
        self.index_of(self.pixels[i].step(d))
    }

    /// The 4-neighbours of pixel `i` in the region (its grid-graph neighbours), in the order
    /// E, N, W, S.
    pub fn neighbors(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        Dir::ALL
            .into_iter()
            .filter_map(move |d| self.neighbor(i, d))
    }

    /// Number of grid-graph neighbours of pixel `i`.
    pub fn degree(&self, i: usize) -> usize {
        self.neighbors(i).count()
    }

    /// The edges of the grid graph, each once as `(i, j)` with `i < j`.
    pub fn edges(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        (0..self.len()).flat_map(move |i| {
            [Dir::E, Dir::N]
                .into_iter()
                .filter_map(move |d| self.neighbor(i, d).map(|j| (i, j)))
        })
    }

    /// The region moved by (dx, dy).
    pub fn translated(&self, dx: i32, dy: i32) -> Result<Region> {
        Region::from_pixels(self.pixels.iter().map(|p| Pixel::new(p.x + dx, p.y + dy)))
    }

    /// The region moved so that its bounding box starts at (0, 0).
    pub fn normalized(&self) -> Region {
        if self.is_empty() || (self.bbox.min_x == 0 && self.bbox.min_y == 0) {
            return self.clone();
        }
        self.translated(-self.bbox.min_x, -self.bbox.min_y)
            .expect("translation keeps the bounding box size")
    }

    /// The image of the region under a symmetry of the square.
    pub fn transformed(&self, s: Symmetry) -> Region {
        Region::from_pixels(self.pixels.iter().map(|&p| s.apply(p)))
            .expect("symmetry keeps the bounding box size")
    }

    /// A `#`/`.` picture of the region, highest row first (the `.grid` body).
    pub fn to_ascii(&self) -> String {
        let mut s = String::new();
        if self.is_empty() {
            return s;
        }
        let b = self.bbox;
        for y in (b.min_y..=b.max_y).rev() {
            for x in b.min_x..=b.max_x {
                s.push(if self.contains(Pixel::new(x, y)) {
                    '#'
                } else {
                    '.'
                });
            }
            s.push('\n');
        }
        s
    }

    /// Parses a `#`/`.` picture (highest row first, last line y = 0); for tests and fixtures.
    pub fn from_ascii(text: &str) -> Region {
        let rows: Vec<&str> = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with(';'))
            .collect();
        let h = rows.len() as i32;
        let pixels = rows.iter().enumerate().flat_map(|(r, row)| {
            row.chars()
                .enumerate()
                .filter(|&(_, c)| c == '#')
                .map(move |(x, _)| Pixel::new(x as i32, h - 1 - r as i32))
        });
        Region::from_pixels(pixels).expect("ascii fixture fits the index")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turn_costs() {
        assert_eq!(Dir::E.turn_to(Dir::E), 0);
        assert_eq!(Dir::E.turn_to(Dir::N), 1);
        assert_eq!(Dir::E.turn_to(Dir::S), 1);
        assert_eq!(Dir::E.turn_to(Dir::W), 2);
        assert_eq!(Dir::N.turn_to(Dir::S), 2);
    }

    #[test]
    fn symmetries_form_the_dihedral_group() {
        let p = Pixel::new(3, -2);
        let images: std::collections::HashSet<Pixel> =
            Symmetry::all().map(|s| s.apply(p)).collect();
        assert_eq!(images.len(), 8);
        // Rotating four times is the identity.
        let mut q = p;
        for _ in 0..4 {
            q = Symmetry(1).apply(q);
        }
        assert_eq!(q, p);
        // Adjacent pixels stay adjacent.
        for s in Symmetry::all() {
            assert!(s.apply(p).dir_to(s.apply(p.step(Dir::E))).is_some());
        }
    }

    #[test]
    fn index_and_neighbors() {
        let r = Region::from_ascii("##.\n.##\n");
        assert_eq!(r.len(), 4);
        assert_eq!(r.pixels()[0], Pixel::new(1, 0));
        let i = r.index_of(Pixel::new(1, 1)).unwrap();
        let nb: Vec<Pixel> = r.neighbors(i).map(|j| r.pixel(j)).collect();
        assert_eq!(nb, vec![Pixel::new(0, 1), Pixel::new(1, 0)]);
        assert_eq!(r.edges().count(), 3);
        assert_eq!(r.to_ascii(), "##.\n.##\n");
    }
}
