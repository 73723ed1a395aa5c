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
///
/// Read from JSON (tours) as `[x, y]` with |x|, |y| ≤ [`MAX_COORD`]; a pair beyond the limit is
/// refused with the file's line and column.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(try_from = "[i64; 2]", into = "[i32; 2]")]
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
    ///
    /// Computed in `i64`, so that pixels 2^32 − 1 apart are never taken for neighbours.
    #[inline]
    pub fn dir_to(self, other: Pixel) -> Option<Dir> {
        let delta = |a: i32, b: i32| i64::from(b) - i64::from(a);
        match (delta(self.x, other.x), delta(self.y, other.y)) {
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

impl TryFrom<[i64; 2]> for Pixel {
    type Error = String;

    fn try_from(a: [i64; 2]) -> std::result::Result<Self, String> {
        Ok(Pixel::new(pixel_coordinate(a[0])?, pixel_coordinate(a[1])?))
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
    #[inline]
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

/// The largest absolute value of a pixel coordinate: every reader (`.grid`, pixel lists, WKT and
/// `.poly`, tour JSON) refuses a pixel with |x| or |y| above it, and [`Region::from_pixels`]
/// refuses one too. With |x|, |y| < 2^30 a step (x ± 1), a difference of two coordinates and the
/// doubled centres of [`Symmetry::apply`] all fit an `i32`, so no arithmetic on coordinates
/// wraps around (a wrapped step from x = 2^31 − 1 to −2^31 would count as one unit move).
pub const MAX_COORD: i32 = (1 << 30) - 1;

/// A pixel coordinate within ±[`MAX_COORD`], or the message saying it is out of range (the
/// reader adds the file and line).
pub fn pixel_coordinate(v: i64) -> std::result::Result<i32, String> {
    if (-i64::from(MAX_COORD)..=i64::from(MAX_COORD)).contains(&v) {
        Ok(v as i32)
    } else {
        Err(coordinate_out_of_range(&v.to_string()))
    }
}

/// The message for a pixel coordinate (as written) outside ±[`MAX_COORD`].
pub fn coordinate_out_of_range(written: &str) -> String {
    format!(
        "coordinate {written} is out of range; expected an integer from -{MAX_COORD} to \
         {MAX_COORD} (the coordinate limit, |x|, |y| < 2^30)"
    )
}

/// The most pixels a region may have; larger inputs are refused with an error (exit 2) before
/// anything proportional to them is allocated. At 16 to 32 bytes per pixel plus the runs, a
/// region at the limit takes at most about 700 MB.
pub const MAX_PIXELS: usize = 20_000_000;

/// A maximal run of pixels in one row: `x0..=x1`, the first of which has index `first`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Run {
    x0: i32,
    x1: i32,
    first: u32,
}

/// A finite set of unit pixels and its grid graph (4-neighbour adjacency).
///
/// Pixels are numbered `0..len()` in row-major order from the bottom row (y ascending, then
/// x ascending); every algorithm refers to pixels by these indices.
///
/// The index is sparse, so memory and every pass over a region are proportional to N (plus the
/// number of rows), never to the area of the bounding box: the pixels' rows, each row's maximal
/// runs, and the indices of the pixels above and below each pixel (16 bytes per pixel in all),
/// plus, when the bounding box has at most 4N cells, a dense table over it (at most 16 more).
/// A pixel's 4-neighbours are found in O(1); [`Region::index_of`] of an arbitrary point takes
/// O(1) with the dense table, else O(log r) for r runs in its row.
#[derive(Clone, PartialEq, Eq)]
pub struct Region {
    pixels: Vec<Pixel>,
    bbox: BBox,
    /// The y of every non-empty row, ascending.
    row_y: Vec<i32>,
    /// The runs of row `r` are `runs[row_run[r]..row_run[r + 1]]`.
    row_run: Vec<u32>,
    runs: Vec<Run>,
    /// Index of the pixel above (`[0]`) and below (`[1]`) each pixel, `NONE` when absent.
    vertical: Vec<[u32; 2]>,
    /// When the bounding box has at most [`DENSE_CELLS_PER_PIXEL`] cells per pixel: the index
    /// of every cell (`NONE` for empty ones), row by row; else empty.
    dense: Vec<u32>,
}

/// A region whose bounding box has at most this many cells per pixel also gets a dense table
/// over its box (at most 16 bytes per pixel), for O(1) [`Region::index_of`]: algorithms look
/// up arbitrary points often (tsp65 on a 10^6-pixel random-simple region spent 22% of its time
/// in the binary search of the runs).
const DENSE_CELLS_PER_PIXEL: usize = 4;

/// Pictures of regions with a larger bounding box are left out of `Debug`.
const DEBUG_PICTURE_CELLS: usize = 1 << 16;

impl fmt::Debug for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let b = self.bbox;
        if self.is_empty() || b.width().saturating_mul(b.height()) <= DEBUG_PICTURE_CELLS {
            write!(f, "Region({} pixels)\n{}", self.len(), self.to_ascii())
        } else {
            write!(
                f,
                "Region({} pixels in a {}x{} box from ({}, {}))",
                self.len(),
                b.width(),
                b.height(),
                b.min_x,
                b.min_y
            )
        }
    }
}

impl Region {
    /// Builds a region from pixels (duplicates are merged). Fails when there are more than
    /// [`MAX_PIXELS`] distinct pixels or a coordinate lies outside ±[`MAX_COORD`].
    ///
    /// # Complexity
    /// O(N log N) time (O(N) when the pixels come in index order), O(N) space.
    pub fn from_pixels<I: IntoIterator<Item = Pixel>>(pixels: I) -> Result<Region> {
        let mut pixels: Vec<Pixel> = pixels.into_iter().collect();
        if let Some(p) = pixels
            .iter()
            .find(|p| p.x.unsigned_abs().max(p.y.unsigned_abs()) > MAX_COORD as u32)
        {
            let v = if p.x.unsigned_abs() > MAX_COORD as u32 {
                p.x
            } else {
                p.y
            };
            return Err(Error::Invalid(format!(
                "pixel {p}: {}",
                coordinate_out_of_range(&v.to_string())
            )));
        }
        let key = |p: &Pixel| (p.y, p.x);
        if !pixels.is_sorted_by(|a, b| key(a) < key(b)) {
            pixels.sort_unstable_by_key(key);
            pixels.dedup();
        }
        if pixels.len() > MAX_PIXELS {
            return Err(Error::Invalid(format!(
                "the region has {} pixels; expected at most {MAX_PIXELS}",
                pixels.len()
            )));
        }
        Ok(Region::from_sorted(pixels))
    }

    /// Builds the index over pixels sorted by (y, x) without duplicates.
    fn from_sorted(pixels: Vec<Pixel>) -> Region {
        let n = pixels.len();
        let mut bbox = BBox {
            min_x: 0,
            min_y: 0,
            max_x: -1,
            max_y: -1,
        };
        if let (Some(first), Some(last)) = (pixels.first(), pixels.last()) {
            bbox = BBox {
                min_x: pixels.iter().map(|p| p.x).min().unwrap_or(0),
                max_x: pixels.iter().map(|p| p.x).max().unwrap_or(0),
                min_y: first.y,
                max_y: last.y,
            };
        }
        let mut row_y = Vec::new();
        let mut row_run = Vec::new();
        let mut runs: Vec<Run> = Vec::new();
        for (i, p) in pixels.iter().enumerate() {
            let new_row = row_y.last() != Some(&p.y);
            if new_row {
                row_y.push(p.y);
                row_run.push(runs.len() as u32);
            }
            match runs.last_mut() {
                Some(run) if !new_row && p.x - 1 == run.x1 => run.x1 = p.x,
                _ => runs.push(Run {
                    x0: p.x,
                    x1: p.x,
                    first: i as u32,
                }),
            }
        }
        row_run.push(runs.len() as u32);
        // Above and below: merge each row with the next one when they are adjacent.
        let mut vertical = vec![[NONE; 2]; n];
        for r in 1..row_y.len() {
            if row_y[r] - 1 != row_y[r - 1] {
                continue;
            }
            let (lower, upper) = (
                row_run[r - 1] as usize..row_run[r] as usize,
                row_run[r] as usize..row_run[r + 1] as usize,
            );
            let (mut a, mut b) = (lower.start, upper.start);
            while a < lower.end && b < upper.end {
                let (ra, rb) = (runs[a], runs[b]);
                let (lo, hi) = (ra.x0.max(rb.x0), ra.x1.min(rb.x1));
                for x in lo..=hi {
                    let below = ra.first + (x - ra.x0) as u32;
                    let above = rb.first + (x - rb.x0) as u32;
                    vertical[below as usize][0] = above;
                    vertical[above as usize][1] = below;
                }
                if ra.x1 < rb.x1 {
                    a += 1;
                } else {
                    b += 1;
                }
            }
        }
        let cells = bbox.width().saturating_mul(bbox.height());
        let mut dense = Vec::new();
        if n > 0 && cells <= DENSE_CELLS_PER_PIXEL.saturating_mul(n) {
            dense = vec![NONE; cells];
            let w = bbox.width();
            for (i, p) in pixels.iter().enumerate() {
                dense[(p.y - bbox.min_y) as usize * w + (p.x - bbox.min_x) as usize] = i as u32;
            }
        }
        Region {
            pixels,
            bbox,
            row_y,
            row_run,
            runs,
            vertical,
            dense,
        }
    }

    /// A `w` × `h` rectangle with lower-left pixel (0, 0).
    pub fn rectangle(w: i32, h: i32) -> Region {
        Region::from_pixels((0..h).flat_map(|y| (0..w).map(move |x| Pixel::new(x, y))))
            .expect("rectangle within the pixel limit")
    }

    /// Number of pixels, N.
    #[inline]
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

    #[inline]
    pub fn pixel(&self, i: usize) -> Pixel {
        self.pixels[i]
    }

    /// Bounding box (meaningless for an empty region).
    pub fn bbox(&self) -> BBox {
        self.bbox
    }

    /// Number of non-empty rows.
    pub fn row_count(&self) -> usize {
        self.row_y.len()
    }

    /// The maximal horizontal runs of row `r` (0 ≤ r < [`Region::row_count`], rows by
    /// ascending y): its y and, per run, its leftmost x, rightmost x and the index of its
    /// leftmost pixel.
    pub fn row_runs(&self, r: usize) -> (i32, impl Iterator<Item = (i32, i32, usize)> + '_) {
        let runs = &self.runs[self.row_run[r] as usize..self.row_run[r + 1] as usize];
        (
            self.row_y[r],
            runs.iter().map(|run| (run.x0, run.x1, run.first as usize)),
        )
    }

    /// The row of height `y`, if it has pixels.
    fn row_of(&self, y: i32) -> Option<usize> {
        let first = *self.row_y.first()?;
        let offset = i64::from(y) - i64::from(first);
        // Rows without gaps are found directly.
        if self.row_y.len() as i64 == i64::from(self.bbox.max_y) - i64::from(first) + 1 {
            return (0..self.row_y.len() as i64)
                .contains(&offset)
                .then_some(offset as usize);
        }
        self.row_y.binary_search(&y).ok()
    }

    /// Index of the pixel at `p`, if `p` is in the region.
    ///
    /// # Complexity
    /// O(1) when the bounding box has at most 4N cells; else O(log r) for r runs in the row of
    /// `p` (plus O(log rows) when some rows between the lowest and the highest are empty).
    #[inline]
    pub fn index_of(&self, p: Pixel) -> Option<usize> {
        if !self.dense.is_empty() {
            let b = &self.bbox;
            if p.x < b.min_x || p.x > b.max_x || p.y < b.min_y || p.y > b.max_y {
                return None;
            }
            let k = (p.y - b.min_y) as usize * b.width() + (p.x - b.min_x) as usize;
            return Some(self.dense[k])
                .filter(|&i| i != NONE)
                .map(|i| i as usize);
        }
        let r = self.row_of(p.y)?;
        let runs = &self.runs[self.row_run[r] as usize..self.row_run[r + 1] as usize];
        let k = if runs.len() == 1 {
            0
        } else {
            runs.partition_point(|run| run.x1 < p.x)
        };
        let run = runs.get(k)?;
        (run.x0 <= p.x && p.x <= run.x1).then(|| run.first as usize + (p.x - run.x0) as usize)
    }

    pub fn contains(&self, p: Pixel) -> bool {
        self.index_of(p).is_some()
    }

    /// Index of the neighbour of pixel `i` in direction `d`, if present. O(1).
    #[inline]
    pub fn neighbor(&self, i: usize, d: Dir) -> Option<usize> {
        let p = self.pixels[i];
        match d {
            // Row neighbours are adjacent indices; the comparisons cannot overflow because
            // pixels are sorted.
            Dir::E => self
                .pixels
                .get(i + 1)
                .filter(|q| q.y == p.y && q.x - 1 == p.x)
                .map(|_| i + 1),
            Dir::W => i
                .checked_sub(1)
                .filter(|&j| self.pixels[j].y == p.y && self.pixels[j].x + 1 == p.x),
            Dir::N => Some(self.vertical[i][0])
                .filter(|&j| j != NONE)
                .map(|j| j as usize),
            Dir::S => Some(self.vertical[i][1])
                .filter(|&j| j != NONE)
                .map(|j| j as usize),
        }
    }

    /// The 4-neighbours of pixel `i` in the region (its grid-graph neighbours), in the order
    /// E, N, W, S.
    #[inline]
    pub fn neighbors(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        Dir::ALL
            .into_iter()
            .filter_map(move |d| self.neighbor(i, d))
    }

    /// Number of grid-graph neighbours of pixel `i`.
    #[inline]
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
            .expect("translation keeps the pixel count")
    }

    /// The image of the region under a symmetry of the square.
    pub fn transformed(&self, s: Symmetry) -> Region {
        Region::from_pixels(self.pixels.iter().map(|&p| s.apply(p)))
            .expect("a symmetry keeps the pixel count")
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
        Region::from_pixels(pixels).expect("ascii fixture within the pixel limit")
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
    fn far_apart_pixels_take_no_box() {
        // A box of 4·10^18 cells: the sparse index holds the three pixels and three rows.
        let far = [
            Pixel::new(-MAX_COORD, -MAX_COORD),
            Pixel::new(1_000_000_000, MAX_COORD),
            Pixel::new(MAX_COORD, MAX_COORD),
            Pixel::new(-MAX_COORD, 0),
        ];
        let r = Region::from_pixels(far).unwrap();
        assert_eq!(r.len(), 4);
        assert_eq!(r.row_count(), 3);
        for (i, &p) in r.pixels().iter().enumerate() {
            assert_eq!(r.index_of(p), Some(i));
        }
        let top = r.index_of(Pixel::new(MAX_COORD, MAX_COORD)).unwrap();
        assert_eq!(r.neighbor(top, Dir::W), None);
        assert_eq!(r.neighbor(top - 1, Dir::E), None);
        assert!(!r.contains(Pixel::new(0, 0)));
        assert!(format!("{r:?}").starts_with("Region(4 pixels in a"));
    }

    /// Probes the coordinate limit: a pixel one past ±MAX_COORD (where x + 1 or a difference of
    /// two coordinates would wrap an i32) is refused, one at the limit accepted.
    #[test]
    fn coordinates_beyond_the_limit_are_refused() {
        assert!(Region::from_pixels([Pixel::new(MAX_COORD, -MAX_COORD)]).is_ok());
        for p in [
            Pixel::new(MAX_COORD + 1, 0),
            Pixel::new(0, -MAX_COORD - 1),
            Pixel::new(i32::MIN, 0),
        ] {
            let e = Region::from_pixels([p]).unwrap_err().to_string();
            assert!(
                e.contains("out of range") && e.contains("coordinate limit"),
                "{e}"
            );
        }
        assert_eq!(pixel_coordinate(-i64::from(MAX_COORD)), Ok(-MAX_COORD));
        assert!(pixel_coordinate(1 << 30).is_err());
    }

    proptest::proptest! {
        #[test]
        fn sparse_index_matches_a_hash_map(
            points in proptest::collection::vec((-30i32..30, -30i32..30), 0..200),
            stride in 1i32..5,
            span in 2i32..31,
        ) {
            // Small spans give dense tables, large ones and strides sparse indices.
            let pixels: Vec<Pixel> =
                points.iter().map(|&(x, y)| Pixel::new(x % span * stride, y % span)).collect();
            let r = Region::from_pixels(pixels.clone()).unwrap();
            let mut sorted = pixels.clone();
            sorted.sort_by_key(|p| (p.y, p.x));
            sorted.dedup();
            proptest::prop_assert_eq!(r.pixels(), &sorted[..]);
            let at: std::collections::HashMap<Pixel, usize> =
                sorted.iter().enumerate().map(|(i, &p)| (p, i)).collect();
            for y in -32..32 {
                for x in -32 * stride..32 * stride {
                    let p = Pixel::new(x, y);
                    proptest::prop_assert_eq!(r.index_of(p), at.get(&p).copied());
                }
            }
            for (i, &p) in sorted.iter().enumerate() {
                for d in Dir::ALL {
                    proptest::prop_assert_eq!(r.neighbor(i, d), at.get(&p.step(d)).copied());
                }
            }
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
