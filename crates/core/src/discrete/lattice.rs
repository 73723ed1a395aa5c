//! Lattice regions as discrete milling instances: voxel regions (3-D orthogonal milling),
//! hexagonal cells, honeycomb vertices, and plane graphs with their nearly straight pairs.
//!
//! Section 2.1 of *Optimal covering tours with turn costs* calls integral orthogonal milling
//! "the special case of discrete milling in a grid graph", and Theorem 5.2 extends its
//! approximation to milling with a bounded number d of allowed directions, "e.g., orthogonal
//! milling in 3-D". The converters here build those special cases, each a [`Discrete`] with
//! coordinates (for drawing) and `d` set:
//!
//! - [`VoxelRegion`]: unit cubes, the 6-neighbour graph, the ±x, ±y and ±z pairs collinear at
//!   every voxel (d = 3). Text form: the `.vox` format below.
//! - [`HexRegion`]: the cells of the hexagonal tiling, that is the points of the triangular
//!   lattice; 6 neighbours, the 3 pairs of opposite neighbours collinear (d = 3).
//! - [`HoneycombRegion`]: the vertices of the hexagonal lattice (the honeycomb); degree at most
//!   3, and no collinear pairs, since the edges at a vertex are 120° apart (d = 3: the edges
//!   run in three directions).
//! - [`geometric`]: any graph with points, each vertex pairing its most nearly straight edges.
//!
//! # Which lattice regions
//!
//! Discrete milling asks for "regions of the triangular and hexagonal lattices (d = 3 in the plane)";
//! the paper names no such family. We read a *triangular-lattice region* as a set of points of
//! the triangular lattice, i.e. hexagonal cells ([`HexRegion`]), and a *hexagonal-lattice
//! region* as a set of honeycomb vertices ([`HoneycombRegion`]). The triangular *cells* (the
//! faces of the triangular lattice, adjacent across an edge) do not fit discrete milling: a
//! triangle has three neighbours at 120°, and a straight row of triangles alternates up and
//! down ones, so each of the three pairs of a triangle's edges is "straight" for some row and
//! the collinear pairs would not form a matching. (As a graph, the triangles are the honeycomb
//! vertices, which we model with no straight pairs.)
//!
//! # The `.vox` text format
//!
//! UTF-8 text. Lines starting with `;` are comments. A line `---` ends one z-layer and starts
//! the next; the first layer is z = 0. Every other line is a row of cells of its layer, as in
//! the `.grid` format ([`crate::gridfile`]): `#` a voxel, `.` an empty cell, x the column index
//! from 0, the first row of a layer the highest y and its last row y = 0; rows may differ in
//! length and a layer may have no rows. A trailing `\r` is ignored. We separate layers by
//! `---` and not by a blank line because a blank line is already a row of empty cells in
//! `.grid` pictures. Refused, with the file, line and column: any other character and more than
//! [`MAX_VERTICES`] voxels (counted before any voxel is stored).
//!
//! Writing puts one comment line first, then every layer from z = 0 up, each with the rows of
//! the bounding box from its highest y down to 0, padded with `.` to its width, so a written
//! file reads back and writes again byte for byte.
//!
//! # The hexagonal-cell text form
//!
//! A `.grid` picture ([`crate::gridfile`]) read in the *odd-r offset* layout: the character in
//! column c of the row at height r (r = 0 the last row) is the cell of axial coordinates
//! (q, r) = (c − ⌊r/2⌋, r); the odd rows sit half a cell to the right of the even ones, so the
//! picture
//!
//! ```text
//! ###
//! ###
//! ```
//!
//! is the 6 cells (0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (2, 1), of which (0, 1) touches
//! (0, 0), (1, 0) and (1, 1). The `.grid` reader's rules, limit ([`crate::region::MAX_PIXELS`]
//! cells) and error messages apply. Writing puts one comment line first, then the picture of
//! the offset bounding box. The drawing coordinates are those of pointy-top hexagons with unit
//! centre spacing: (q + r/2, r·√3/2).

use super::Discrete;
use super::format::MAX_VERTICES;
use crate::error::{Error, Result};
use crate::gridfile::{GridFile, MAX_PICTURE_BYTES, utf8_text};
use crate::region::{Pixel, Region};
use std::path::Path;

/// √3/2, the height of a row of the triangular lattice of unit spacing.
const ROW_HEIGHT: f64 = 0.866_025_403_784_438_6;

/// Pairs of sites opposite each other across a site.
type OppositePairs<K> = Vec<(K, K)>;

/// The instance of sites on a lattice: vertex `i` is `sites[i]` (sorted, distinct), joined to
/// each neighbour that `forward` lists (every lattice edge listed from one of its ends), with
/// the opposite pairs that `opposite` lists collinear where both ends are sites.
fn lattice_instance<K: Ord + Copy>(
    sites: &[K],
    forward: &dyn Fn(K, &mut Vec<K>),
    opposite: &dyn Fn(K, &mut OppositePairs<K>),
    coords: &dyn Fn(K) -> [f64; 3],
    d: u32,
) -> Discrete {
    let index = |k: K| sites.binary_search(&k).ok().map(|i| i as u32);
    let mut edges = Vec::new();
    let mut collinear = Vec::new();
    let mut near = Vec::new();
    let mut pairs = Vec::new();
    for (i, &s) in sites.iter().enumerate() {
        near.clear();
        forward(s, &mut near);
        edges.extend(near.iter().filter_map(|&t| index(t)).map(|j| (i as u32, j)));
        pairs.clear();
        opposite(s, &mut pairs);
        for &(a, b) in &pairs {
            if let (Some(a), Some(b)) = (index(a), index(b)) {
                collinear.push((i as u32, a, b));
            }
        }
    }
    let points = sites.iter().map(|&s| coords(s)).collect();
    let mut inst = Discrete::new(sites.len(), &edges, &collinear, Some(points))
        .expect("distinct lattice neighbours and opposite pairs form a valid instance");
    inst.set_directions(Some(d));
    inst
}

/// Sorts and deduplicates sites, refusing more than [`MAX_VERTICES`].
fn sorted_sites<K: Ord>(mut sites: Vec<K>, what: &str) -> Result<Vec<K>> {
    sites.sort_unstable();
    sites.dedup();
    if sites.len() > MAX_VERTICES {
        return Err(Error::invalid(format!(
            "{} {what}; expected at most {MAX_VERTICES}",
            sites.len()
        )));
    }
    Ok(sites)
}

// ---------------------------------------------------------------------------------------------
// Voxels

/// A voxel `[x, y, z]`: the unit cube with that corner.
pub type Voxel = [i32; 3];

/// A finite set of voxels, numbered in (z, y, x) order: layer by layer from the lowest, each
/// layer in the row-major order of a [`Region`] (so one layer is numbered as its region).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VoxelRegion {
    voxels: Vec<Voxel>,
}

/// The sort key of a voxel: z, then y, then x.
fn zyx(v: Voxel) -> [i32; 3] {
    [v[2], v[1], v[0]]
}

impl VoxelRegion {
    /// The region of these voxels (duplicates merged).
    ///
    /// # Errors
    /// [`Error::Invalid`] for more than [`MAX_VERTICES`] distinct voxels.
    pub fn from_voxels<I: IntoIterator<Item = Voxel>>(voxels: I) -> Result<VoxelRegion> {
        let keyed = voxels.into_iter().map(zyx).collect();
        let voxels = sorted_sites(keyed, "voxels")?
            .into_iter()
            .map(zyx)
            .collect();
        Ok(VoxelRegion { voxels })
    }

    /// The voxels in index order.
    pub fn voxels(&self) -> &[Voxel] {
        &self.voxels
    }

    pub fn len(&self) -> usize {
        self.voxels.len()
    }

    pub fn is_empty(&self) -> bool {
        self.voxels.is_empty()
    }

    /// The index of voxel `v`, if it is in the region.
    pub fn index_of(&self, v: Voxel) -> Option<usize> {
        self.voxels.binary_search_by_key(&zyx(v), |&w| zyx(w)).ok()
    }

    pub fn contains(&self, v: Voxel) -> bool {
        self.index_of(v).is_some()
    }

    /// 3-D orthogonal milling as discrete milling: the 6-neighbour graph of the voxels, the
    /// ±x, ±y and ±z pairs collinear at every voxel that has both, voxel corners as
    /// coordinates, d = 3. Vertex `i` is voxel `i`.
    ///
    /// # Complexity
    /// O(N log N) time, O(N) space.
    pub fn to_discrete(&self) -> Discrete {
        let step = |v: Voxel, axis: usize, by: i32| -> Option<Voxel> {
            let mut w = v;
            w[axis] = w[axis].checked_add(by)?;
            Some(w)
        };
        let keyed: Vec<[i32; 3]> = self.voxels.iter().map(|&v| zyx(v)).collect();
        lattice_instance(
            &keyed,
            &|k, out| {
                let v = zyx(k);
                out.extend((0..3).filter_map(|axis| step(v, axis, 1)).map(zyx));
            },
            &|k, out| {
                let v = zyx(k);
                for axis in 0..3 {
                    if let (Some(a), Some(b)) = (step(v, axis, -1), step(v, axis, 1)) {
                        out.push((zyx(a), zyx(b)));
                    }
                }
            },
            &|k| [k[2] as f64, k[1] as f64, k[0] as f64],
            3,
        )
    }

    /// Parses `.vox` text (module documentation); `file` names the source in error messages.
    /// An empty region is an error.
    pub fn parse(text: &str, file: &str) -> Result<VoxelRegion> {
        // Check every character and count the voxels before storing any.
        let mut count = 0usize;
        let mut last = 1;
        for (k, line) in text.lines().enumerate() {
            last = k + 1;
            let line = line.strip_suffix('\r').unwrap_or(line);
            if line.starts_with(';') || line == "---" {
                continue;
            }
            if let Some(at) = line.bytes().position(|b| b != b'#' && b != b'.') {
                let other = line[at..].chars().next().unwrap_or(' ');
                return Err(Error::parse(
                    file,
                    k + 1,
                    at + 1,
                    format!(
                        "unexpected character {other:?}: expected '#' (voxel), '.' (empty), a \
                         line '---' between layers or a comment line starting with ';'"
                    ),
                ));
            }
            count += line.bytes().filter(|&b| b == b'#').count();
            if count > MAX_VERTICES {
                return Err(Error::parse(
                    file,
                    k + 1,
                    1,
                    format!("more than {MAX_VERTICES} voxels; expected at most {MAX_VERTICES}"),
                ));
            }
        }
        if count == 0 {
            return Err(Error::parse(
                file,
                last,
                1,
                "empty region: expected at least one '#' voxel",
            ));
        }
        let mut voxels = Vec::with_capacity(count);
        let mut layer: Vec<(usize, &str)> = Vec::new();
        let mut z = 0i32;
        let lines = text.lines().map(|l| l.strip_suffix('\r').unwrap_or(l));
        for (k, line) in lines.chain(["---"]).enumerate() {
            if line.starts_with(';') {
                continue;
            }
            if line != "---" {
                layer.push((k + 1, line));
                continue;
            }
            for (y, (line_no, row)) in layer.iter().rev().enumerate() {
                let y = i32::try_from(y).map_err(|_| {
                    Error::parse(file, *line_no, 1, "more rows than an i32 numbers")
                })?;
                for (x, _) in row.bytes().enumerate().filter(|&(_, b)| b == b'#') {
                    let x = i32::try_from(x).map_err(|_| {
                        Error::parse(file, *line_no, x + 1, "a row longer than an i32 numbers")
                    })?;
                    voxels.push([x, y, z]);
                }
            }
            layer.clear();
            z = z
                .checked_add(1)
                .ok_or_else(|| Error::parse(file, k + 1, 1, "more layers than an i32 numbers"))?;
        }
        VoxelRegion::from_voxels(voxels)
    }

    /// Reads a `.vox` file.
    pub fn read(path: &Path) -> Result<VoxelRegion> {
        let bytes = crate::input::read_bytes(path, "a lattice instance file")?;
        let name = path.display().to_string();
        VoxelRegion::parse(&utf8_text(bytes, &name)?, &name)
    }

    /// The `.vox` text. Fails when a voxel has a negative coordinate or when the picture of the
    /// bounding box would be far larger than the region (more than
    /// [`MAX_PICTURE_BYTES`] bytes and 64 per voxel).
    pub fn to_text(&self) -> Result<String> {
        let mut s = String::from(
            "; mowmill voxel region: '#' voxel, '.' empty; layers z = 0, 1, ... separated by \
             '---', each from its highest row y down to y = 0\n",
        );
        if self.is_empty() {
            return Ok(s);
        }
        let mut max = [0i32; 3];
        for v in &self.voxels {
            for a in 0..3 {
                if v[a] < 0 {
                    return Err(Error::invalid(format!(
                        "the .vox format needs non-negative coordinates, but the region has \
                         voxel ({}, {}, {})",
                        v[0], v[1], v[2]
                    )));
                }
                max[a] = max[a].max(v[a]);
            }
        }
        let bytes = (max[0] as usize + 2) * (max[1] as usize + 1) * (max[2] as usize + 1);
        if bytes > MAX_PICTURE_BYTES.max(64 * self.len()) {
            return Err(Error::invalid(format!(
                "the .vox picture of this region would take {bytes} bytes for {} voxels",
                self.len()
            )));
        }
        s.reserve(bytes + 4 * max[2] as usize);
        let mut next = self.voxels.iter().peekable();
        for z in 0..=max[2] {
            if z > 0 {
                s.push_str("---\n");
            }
            let mut rows = vec![vec![b'.'; max[0] as usize + 1]; max[1] as usize + 1];
            while let Some(v) = next.next_if(|v| v[2] == z) {
                rows[v[1] as usize][v[0] as usize] = b'#';
            }
            for row in rows.iter().rev() {
                s.extend(row.iter().map(|&b| b as char));
                s.push('\n');
            }
        }
        Ok(s)
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_text()?).map_err(|e| Error::io(path, e))
    }

    /// The region translated so that its smallest x, y and z are 0.
    pub fn normalized(&self) -> VoxelRegion {
        let mut min = [i32::MAX; 3];
        for v in &self.voxels {
            for a in 0..3 {
                min[a] = min[a].min(v[a]);
            }
        }
        let voxels = self
            .voxels
            .iter()
            .map(|v| [v[0] - min[0], v[1] - min[1], v[2] - min[2]])
            .collect();
        VoxelRegion { voxels }
    }
}

// ---------------------------------------------------------------------------------------------
// Hexagonal cells

/// A cell of the hexagonal tiling in axial coordinates `[q, r]`: the triangular-lattice point
/// q·(1, 0) + r·(1/2, √3/2).
pub type Axial = [i32; 2];

/// The axial steps to the 6 neighbours, opposite ones at `k` and `k + 3`: east, north-east,
/// north-west, west, south-west, south-east.
pub const HEX_STEPS: [[i32; 2]; 6] = [[1, 0], [0, 1], [-1, 1], [-1, 0], [0, -1], [1, -1]];

fn hex_step(c: Axial, k: usize) -> Option<Axial> {
    Some([
        c[0].checked_add(HEX_STEPS[k][0])?,
        c[1].checked_add(HEX_STEPS[k][1])?,
    ])
}

/// The odd-r offset column of a cell: c = q + ⌊r/2⌋.
fn offset_column(c: Axial) -> i64 {
    c[0] as i64 + c[1].div_euclid(2) as i64
}

/// A finite set of hexagonal cells, numbered in (r, q) order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HexRegion {
    cells: Vec<Axial>,
}

/// The sort key of a cell: r, then q.
fn rq(c: Axial) -> Axial {
    [c[1], c[0]]
}

impl HexRegion {
    /// The region of these cells (duplicates merged).
    ///
    /// # Errors
    /// [`Error::Invalid`] for more than [`MAX_VERTICES`] distinct cells.
    pub fn from_cells<I: IntoIterator<Item = Axial>>(cells: I) -> Result<HexRegion> {
        let keyed = cells.into_iter().map(rq).collect();
        let cells = sorted_sites(keyed, "cells")?.into_iter().map(rq).collect();
        Ok(HexRegion { cells })
    }

    /// The cells in index order.
    pub fn cells(&self) -> &[Axial] {
        &self.cells
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }

    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    pub fn index_of(&self, c: Axial) -> Option<usize> {
        self.cells.binary_search_by_key(&rq(c), |&d| rq(d)).ok()
    }

    pub fn contains(&self, c: Axial) -> bool {
        self.index_of(c).is_some()
    }

    /// Milling hexagonal cells as discrete milling: the 6-neighbour graph, the 3 pairs of
    /// opposite neighbours collinear (a straight row of hexagons), cell centres as coordinates,
    /// d = 3. Vertex `i` is cell `i`.
    ///
    /// # Complexity
    /// O(N log N) time, O(N) space.
    pub fn to_discrete(&self) -> Discrete {
        let keyed: Vec<Axial> = self.cells.iter().map(|&c| rq(c)).collect();
        lattice_instance(
            &keyed,
            &|k, out| out.extend((0..3).filter_map(|s| hex_step(rq(k), s)).map(rq)),
            &|k, out| {
                for s in 0..3 {
                    if let (Some(a), Some(b)) = (hex_step(rq(k), s + 3), hex_step(rq(k), s)) {
                        out.push((rq(a), rq(b)));
                    }
                }
            },
            &|k| {
                let (q, r) = (k[1] as f64, k[0] as f64);
                [q + r / 2.0, r * ROW_HEIGHT, 0.0]
            },
            3,
        )
    }

    /// Parses the hexagonal-cell text (a `.grid` picture in the odd-r offset layout, module
    /// documentation); `file` names the source in error messages.
    pub fn parse(text: &str, file: &str) -> Result<HexRegion> {
        let grid = GridFile::parse(text, file)?;
        HexRegion::from_cells(
            grid.region
                .pixels()
                .iter()
                .map(|p| [p.x - p.y.div_euclid(2), p.y]),
        )
    }

    /// Reads a hexagonal-cell text file.
    pub fn read(path: &Path) -> Result<HexRegion> {
        let bytes = crate::input::read_bytes(path, "a lattice instance file")?;
        let name = path.display().to_string();
        HexRegion::parse(&utf8_text(bytes, &name)?, &name)
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_text()?).map_err(|e| Error::io(path, e))
    }

    /// The hexagonal-cell text: a comment line, then the offset picture. Fails when a cell has
    /// r < 0 or an offset column below 0 (see [`HexRegion::normalized`]).
    pub fn to_text(&self) -> Result<String> {
        let mut pixels = Vec::with_capacity(self.len());
        for &c in &self.cells {
            let col = offset_column(c);
            if c[1] < 0 || col < 0 {
                return Err(Error::invalid(format!(
                    "the hexagonal-cell text needs rows r ≥ 0 and offset columns q + ⌊r/2⌋ ≥ 0, \
                     but the region has cell (q, r) = ({}, {})",
                    c[0], c[1]
                )));
            }
            let x = i32::try_from(col)
                .map_err(|_| Error::invalid(format!("offset column {col} beyond an i32")))?;
            pixels.push(Pixel::new(x, c[1]));
        }
        let meta = " mowmill hexagonal cells, odd-r offset rows: column c of row r is the cell \
                    (q, r) = (c - floor(r/2), r); odd rows sit half a cell to the right";
        GridFile {
            comments: vec![meta.to_string()],
            region: Region::from_pixels(pixels)?,
        }
        .to_text()
    }

    /// The region translated so that its lowest row is r = 0 and its leftmost offset column 0.
    pub fn normalized(&self) -> HexRegion {
        let min_r = self.cells.first().map_or(0, |c| c[1]);
        let lifted = self.cells.iter().map(|c| [c[0], c[1] - min_r]);
        let min_c = lifted.clone().map(offset_column).min().unwrap_or(0);
        let cells = lifted.map(|c| [c[0] - min_c as i32, c[1]]).collect();
        HexRegion { cells }
    }
}

// ---------------------------------------------------------------------------------------------
// Honeycomb

/// A vertex of the honeycomb (the hexagonal lattice): the centre of a triangle of the
/// triangular lattice. The up triangle (q, r) has corners p(q, r), p(q + 1, r), p(q, r + 1), the
/// down triangle (q, r) has corners p(q + 1, r), p(q, r + 1), p(q + 1, r + 1), with
/// p(q, r) = q·(1, 0) + r·(1/2, √3/2). Two vertices are adjacent when their triangles share an
/// edge. (Field order gives the numbering order: r, then q, up before down.)
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct HoneycombVertex {
    pub r: i32,
    pub q: i32,
    pub down: bool,
}

impl HoneycombVertex {
    pub fn new(q: i32, r: i32, down: bool) -> HoneycombVertex {
        HoneycombVertex { r, q, down }
    }

    /// The three neighbours: an up triangle (q, r) touches the down triangles (q, r),
    /// (q, r − 1) and (q − 1, r); a down triangle (q, r) the up triangles (q, r), (q, r + 1)
    /// and (q + 1, r). `None` where a coordinate would overflow.
    pub fn neighbors(self) -> [Option<HoneycombVertex>; 3] {
        let (q, r, to) = (self.q, self.r, !self.down);
        let s = if self.down { 1 } else { -1 };
        [
            Some(HoneycombVertex::new(q, r, to)),
            r.checked_add(s).map(|r| HoneycombVertex::new(q, r, to)),
            q.checked_add(s).map(|q| HoneycombVertex::new(q, r, to)),
        ]
    }

    /// The centre of the triangle.
    pub fn point(self) -> [f64; 2] {
        let (q, r) = (self.q as f64, self.r as f64);
        if self.down {
            [q + r / 2.0 + 1.0, (r + 2.0 / 3.0) * ROW_HEIGHT]
        } else {
            [q + r / 2.0 + 0.5, (r + 1.0 / 3.0) * ROW_HEIGHT]
        }
    }
}

/// A finite set of honeycomb vertices, numbered in (r, q, up before down) order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HoneycombRegion {
    vertices: Vec<HoneycombVertex>,
}

impl HoneycombRegion {
    /// The region of these vertices (duplicates merged).
    ///
    /// # Errors
    /// [`Error::Invalid`] for more than [`MAX_VERTICES`] distinct vertices.
    pub fn from_vertices<I: IntoIterator<Item = HoneycombVertex>>(
        vertices: I,
    ) -> Result<HoneycombRegion> {
        let vertices = sorted_sites(vertices.into_iter().collect(), "honeycomb vertices")?;
        Ok(HoneycombRegion { vertices })
    }

    pub fn vertices(&self) -> &[HoneycombVertex] {
        &self.vertices
    }

    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    pub fn index_of(&self, v: HoneycombVertex) -> Option<usize> {
        self.vertices.binary_search(&v).ok()
    }

    /// Milling honeycomb vertices as discrete milling: the honeycomb graph (degree ≤ 3) with no
    /// collinear pairs (the edges at a vertex are 120° apart, so every pass through a vertex
    /// turns), triangle centres as coordinates, d = 3. Hence ρ equals the degree at every
    /// vertex. Vertex `i` is vertex `i` of the region.
    pub fn to_discrete(&self) -> Discrete {
        lattice_instance(
            &self.vertices,
            // Every honeycomb edge has one up end: list it from there.
            &|v, out| {
                if !v.down {
                    out.extend(v.neighbors().into_iter().flatten());
                }
            },
            &|_, _| {},
            &|v| {
                let [x, y] = v.point();
                [x, y, 0.0]
            },
            3,
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Plane graphs

/// A graph drawn in the plane as a discrete instance, each vertex pairing its most nearly
/// straight edges: the pairs whose angle at the vertex is at least arccos(−`straightness`)
/// (`straightness` = √½: at most a 45° bend) are matched greedily, straightest first (ties by
/// neighbour indices), so each edge is in at most one pair.
///
/// The paper leaves open where "collinear channels" come from in a general graph; pairing by
/// angle is our reading for graphs with a drawing. The angles are compared by their cosines
/// (dot products and square roots), so the pairs do not depend on the platform's `atan2`. `d`
/// is left unset: the edges of a general drawing have no bounded set of directions.
///
/// # Errors
/// [`Error::Invalid`] when the graph is not simple, an edge names a vertex without a point, or
/// a point is not finite.
pub fn geometric(points: &[[f64; 2]], edges: &[(u32, u32)], straightness: f64) -> Result<Discrete> {
    if let Some(k) = points
        .iter()
        .position(|p| !p[0].is_finite() || !p[1].is_finite())
    {
        return Err(Error::invalid(format!("point {k} is not finite")));
    }
    let coords = points.iter().map(|p| [p[0], p[1], 0.0]).collect();
    let plain = Discrete::new(points.len(), edges, &[], Some(coords))?;
    let mut collinear = Vec::new();
    let mut candidates: Vec<(f64, u32, u32)> = Vec::new();
    let mut used: Vec<u32> = Vec::new();
    for v in 0..points.len() as u32 {
        let p = points[v as usize];
        let nbrs = plain.neighbors(v);
        candidates.clear();
        for (i, &a) in nbrs.iter().enumerate() {
            for &b in &nbrs[i + 1..] {
                let pa = points[a as usize];
                let pb = points[b as usize];
                let u = [pa[0] - p[0], pa[1] - p[1]];
                let w = [pb[0] - p[0], pb[1] - p[1]];
                let norm = ((u[0] * u[0] + u[1] * u[1]) * (w[0] * w[0] + w[1] * w[1])).sqrt();
                if norm == 0.0 {
                    continue;
                }
                let cos = (u[0] * w[0] + u[1] * w[1]) / norm;
                if cos <= -straightness {
                    candidates.push((cos, a, b));
                }
            }
        }
        candidates.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
        used.clear();
        for &(_, a, b) in &candidates {
            if !used.contains(&a) && !used.contains(&b) {
                used.extend([a, b]);
                collinear.push((v, a, b));
            }
        }
    }
    let coords = points.iter().map(|p| [p[0], p[1], 0.0]).collect();
    Discrete::new(points.len(), edges, &collinear, Some(coords))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// The edges and collinear pairs of an instance, by coordinates (for comparing numberings).
    type Shape = (BTreeSet<[[i64; 3]; 2]>, BTreeSet<([i64; 3], [[i64; 3]; 2])>);

    fn shape(g: &Discrete) -> Shape {
        let at = |v: u32| g.coords(v).unwrap().map(|x| (x * 1000.0).round() as i64);
        let sorted = |a: [i64; 3], b: [i64; 3]| if a < b { [a, b] } else { [b, a] };
        let edges = g.edges().map(|(a, b)| sorted(at(a), at(b))).collect();
        let pairs = (0..g.len() as u32)
            .flat_map(|v| g.collinear_pairs(v).map(move |(a, b)| (v, a, b)))
            .map(|(v, a, b)| (at(v), sorted(at(a), at(b))))
            .collect();
        (edges, pairs)
    }

    #[test]
    fn one_voxel_layer_is_its_grid_region() {
        let picture = "##.##\n#####\n.#.#.\n###..\n";
        let grid = Discrete::from_region(&GridFile::parse(picture, "p.grid").unwrap().region);
        let vox = VoxelRegion::parse(picture, "p.vox").unwrap().to_discrete();
        assert_eq!(vox.len(), grid.len());
        assert_eq!(shape(&vox), shape(&grid));
        assert!(!shape(&vox).1.is_empty());
        assert_eq!(vox.directions(), Some(3));
    }

    #[test]
    fn voxel_text_round_trips_and_layers_stack() {
        let text = "; a 2-layer region\n##\n#.\n---\n.\n#\n";
        let r = VoxelRegion::parse(text, "t.vox").unwrap();
        assert_eq!(
            r.voxels(),
            &[[0, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1]],
            "rows from the top, layers from z = 0"
        );
        let g = r.to_discrete();
        assert_eq!(g.edge_count(), 3);
        assert_eq!(g.coords(3), Some([0.0, 0.0, 1.0]));
        let out = r.to_text().unwrap();
        assert!(out.ends_with("\n##\n#.\n---\n..\n#.\n"), "{out}");
        let back = VoxelRegion::parse(&out, "t.vox").unwrap();
        assert_eq!(back, r);
        assert_eq!(back.to_text().unwrap(), out);
        // A 3x3x3 cube: the centre has degree 6 and 3 straight pairs.
        let cube = VoxelRegion::from_voxels((0..27).map(|k| [k % 3, k / 3 % 3, k / 9]))
            .unwrap()
            .to_discrete();
        let centre = 13;
        assert_eq!(cube.degree(centre), 6);
        assert_eq!(cube.directions_at(centre), 3);
        assert_eq!(
            cube.turn(4, centre, 22),
            0,
            "straight up through the centre"
        );
        assert_eq!(cube.edge_count(), 54);
    }

    #[test]
    fn voxel_text_errors_name_line_and_column() {
        for (text, expected) in [
            ("#.\n---\n#x\n", "v.vox:3:2: unexpected character 'x'"),
            ("#\n--\n", "v.vox:2:1: unexpected character '-'"),
            ("; none\n..\n---\n", "v.vox:3:1: empty region"),
        ] {
            let e = VoxelRegion::parse(text, "v.vox").unwrap_err().to_string();
            assert!(e.starts_with(expected), "{text:?}: {e}");
        }
        let e = VoxelRegion::from_voxels([[-1, 0, 0]]).unwrap().to_text();
        assert!(e.unwrap_err().to_string().contains("non-negative"));
    }

    #[test]
    fn hex_cells_have_six_neighbours_in_three_directions() {
        // A hexagon of radius 2 around (0, 0): 19 cells.
        let cells = (-2..=2)
            .flat_map(|q: i32| (-2..=2).map(move |r: i32| [q, r]))
            .filter(|&[q, r]| (q + r).abs() <= 2);
        let h = HexRegion::from_cells(cells).unwrap();
        assert_eq!(h.len(), 19);
        let g = h.to_discrete();
        let centre = h.index_of([0, 0]).unwrap() as u32;
        assert_eq!(g.degree(centre), 6);
        assert_eq!(g.directions_at(centre), 3);
        let p = g.params();
        assert_eq!(p.mu, 6);
        assert_eq!(p.d, Some(3));
        // Interior cells (radius ≤ 1) have 6 neighbours and 3 directions; every edge has
        // length 1 in the drawing.
        for &[q, r] in h.cells() {
            let v = h.index_of([q, r]).unwrap() as u32;
            if (q.abs() + r.abs() + (q + r).abs()) / 2 <= 1 {
                assert_eq!((g.degree(v), g.directions_at(v)), (6, 3), "({q}, {r})");
            }
        }
        for (a, b) in g.edges() {
            let (pa, pb) = (g.coords(a).unwrap(), g.coords(b).unwrap());
            let len = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2)).sqrt();
            assert!((len - 1.0).abs() < 1e-12);
        }
        // A hexagon of radius R has 9R² + 3R edges.
        assert_eq!(g.edge_count(), 42);
        // The straight line east through the centre.
        let w = h.index_of([-1, 0]).unwrap() as u32;
        let e = h.index_of([1, 0]).unwrap() as u32;
        assert_eq!(g.turn(w, centre, e), 0);
    }

    #[test]
    fn hex_text_is_an_offset_picture() {
        let h = HexRegion::parse("###\n###\n", "h.hex").unwrap();
        assert_eq!(h.cells(), &[[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]]);
        let g = h.to_discrete();
        let top_left = h.index_of([0, 1]).unwrap() as u32;
        let mut nbrs: Vec<Axial> = g
            .neighbors(top_left)
            .iter()
            .map(|&v| h.cells()[v as usize])
            .collect();
        nbrs.sort();
        assert_eq!(nbrs, [[0, 0], [1, 0], [1, 1]]);
        let text = h.to_text().unwrap();
        assert!(text.ends_with("\n###\n###\n"), "{text}");
        assert_eq!(HexRegion::parse(&text, "h.hex").unwrap(), h);
        // Row 2 is shifted back by one in axial q: column 0 of row 2 is q = −1.
        let h = HexRegion::parse("#\n.\n.\n", "h.hex").unwrap();
        assert_eq!(h.cells(), &[[-1, 2]]);
        let moved = HexRegion::from_cells([[-5, -3], [-4, -3], [-5, -2]]).unwrap();
        let n = moved.normalized();
        let again = HexRegion::parse(&n.to_text().unwrap(), "h.hex").unwrap();
        assert_eq!(again, n);
        assert_eq!(again.to_discrete().edge_count(), 3);
        let path = std::env::temp_dir().join(format!("mowmill-hex-{}.hex", std::process::id()));
        n.write(&path).unwrap();
        assert_eq!(HexRegion::read(&path).unwrap(), n);
        std::fs::remove_file(&path).unwrap();
        let e = HexRegion::parse("#\n#?\n", "h.hex")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("h.hex:2:2: unexpected character '?'"), "{e}");
    }

    #[test]
    fn honeycomb_vertices_have_no_straight_pairs() {
        // One hexagon of the honeycomb: the six triangles around the lattice point (1, 1).
        let ring = [
            HoneycombVertex::new(1, 1, false),
            HoneycombVertex::new(0, 1, true),
            HoneycombVertex::new(0, 1, false),
            HoneycombVertex::new(0, 0, true),
            HoneycombVertex::new(1, 0, false),
            HoneycombVertex::new(1, 0, true),
        ];
        for v in ring {
            for w in v.neighbors().into_iter().flatten() {
                assert!(w.neighbors().contains(&Some(v)), "{v:?} {w:?}");
            }
        }
        let h = HoneycombRegion::from_vertices(ring).unwrap();
        let g = h.to_discrete();
        assert_eq!(g.edge_count(), 6, "a hexagon");
        for v in 0..6 {
            assert_eq!(g.degree(v), 2);
            assert_eq!(g.directions_at(v), 2);
        }
        // A patch with a vertex of degree 3: ρ is the degree everywhere.
        let patch: Vec<HoneycombVertex> = (0..4)
            .flat_map(|q| {
                (0..4).flat_map(move |r| [false, true].map(|d| HoneycombVertex::new(q, r, d)))
            })
            .collect();
        let h = HoneycombRegion::from_vertices(patch).unwrap();
        let g = h.to_discrete();
        assert_eq!(g.params().mu, 3);
        for v in 0..g.len() as u32 {
            assert_eq!(g.directions_at(v), g.degree(v));
            assert_eq!(g.collinear_pairs(v).count(), 0);
        }
        let p = g.params();
        assert!((p.rho - p.delta).abs() < 1e-12);
        assert_eq!(p.d, Some(3));
        // Edges have length 1/√3 in the drawing.
        for (a, b) in g.edges() {
            let (pa, pb) = (g.coords(a).unwrap(), g.coords(b).unwrap());
            let len2 = (pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2);
            assert!((len2 - 1.0 / 3.0).abs() < 1e-12);
        }
    }

    #[test]
    fn geometric_pairs_the_straightest_edges() {
        // A plus sign with a diagonal arm: the horizontal and vertical pairs are straight, the
        // diagonal (45° off the vertical) stays unmatched.
        let points = [
            [0.0, 0.0],
            [1.0, 0.0],
            [-1.0, 0.05],
            [0.0, 1.0],
            [0.0, -1.0],
            [-1.0, -1.0],
        ];
        let edges = [(0, 1), (0, 2), (0, 3), (0, 4), (0, 5)];
        let g = geometric(&points, &edges, 0.5f64.sqrt()).unwrap();
        let pairs: Vec<(u32, u32)> = g.collinear_pairs(0).collect();
        assert_eq!(pairs.len(), 2, "{pairs:?}");
        assert_eq!(g.straight_on(1, 0), Some(2));
        assert_eq!(g.straight_on(3, 0), Some(4));
        assert_eq!(g.straight_on(5, 0), None);
        assert!(geometric(&points, &[(0, 9)], 0.7).is_err());
    }
}
