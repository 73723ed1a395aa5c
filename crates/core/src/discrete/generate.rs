//! Deterministic random discrete instances: voxel regions (with or without cavities),
//! hexagonal-cell and honeycomb regions, and plane graphs with nearly straight pairs; and two
//! structured families without randomness, the shapes of the paper's failing statements
//! (the shapes the proofs find hardest): hubs on a straight path ([`hub_path`], Theorem 5.1's averaged bound) and
//! straight paths joined by bridges ([`collinear_bridges`], Theorem 4.2's t + 2c − 2).
//!
//! Every generator is a function of its size, its seed and its parameters only: the same
//! arguments give the same instance, vertex for vertex, on every platform (ChaCha8 streams
//! seeded as in [`crate::generate`], integer box sizes, no platform-dependent float
//! functions). Every output is connected.
//!
//! The lattice regions grow by *Eden growth* in a box of about 2N cells: from the box's centre
//! cell, a random cell adjacent to the region (chosen uniformly among the adjacencies
//! found so far) joins it, until it has N cells. The result is a connected, compact blob with
//! a ragged boundary. The paper prescribes no instance families for these models; these are
//! ours.

use super::Discrete;
use super::format::MAX_VERTICES;
use super::lattice::{HEX_STEPS, HexRegion, HoneycombRegion, HoneycombVertex, VoxelRegion};
use crate::error::{Error, Result};
use std::collections::VecDeque;

use crate::generate::rng::{Rng, below, rng_for, unit};

/// The discrete families of `mowmill gen` and of configs' `[[family]]` tables: random voxel
/// regions (`n`, `holes` enclosed cavities), hexagonal cells, honeycomb vertices, plane graphs;
/// the structured [`STRUCTURED`] ones (`n`, `k`).
pub const FAMILIES: &[&str] = &[
    "voxel",
    "hex",
    "honeycomb",
    "plane",
    "hub-path",
    "collinear-bridges",
];

/// The structured discrete families: deterministic, parameters `n` and `k`, no seed
/// (one given is ignored). [`crate::generate::is_structured`] counts them as structured.
pub const STRUCTURED: &[&str] = &["hub-path", "collinear-bridges"];

/// What `mowmill gen --help` says of the discrete families (after the grid families).
pub fn families_help() -> String {
    [
        "Discrete families (written as .dm or .json; voxel also .vox, hex also .hex):",
        "  voxel           --n [--holes] --seed",
        "                    random connected voxel region of about n voxels, `holes` enclosed cavities",
        "  hex             --n --seed",
        "                    random connected region of n hexagonal cells",
        "  honeycomb       --n --seed",
        "                    random connected region of n honeycomb vertices",
        "  plane           --n --seed",
        "                    random connected plane graph of about n vertices, nearly straight pairs collinear",
        "  hub-path        --n --k",
        "                    structured: a straight path of n vertices, its n - 2 inner vertices cut into k runs,",
        "                    hub j joined to run j by edges collinear with nothing (n + k vertices; k >= 1, n >= k + 2)",
        "  collinear-bridges --n --k",
        "                    structured: k >= 2 parallel straight paths of n >= 5 vertices, neighbouring paths",
        "                    joined every 4 columns by bridge edges collinear with nothing (n k vertices)",
    ]
    .join("\n")
}

/// A generated discrete instance with the text of its file: `.vox` for voxel regions, `.hex`
/// for hexagonal cells, else the `.dm` text form.
#[derive(Clone, Debug)]
pub struct Generated {
    pub instance: Discrete,
    pub text: String,
    pub ext: &'static str,
}

/// The parameters a discrete family takes, as `gen` and configs name them.
pub fn takes(family: &str) -> &'static str {
    match family {
        "voxel" => "n, holes",
        f if STRUCTURED.contains(&f) => "n, k",
        _ => "n",
    }
}

/// Refuses what [`generate`] refuses, without generating: an unknown family, a missing `n`,
/// `holes` off the voxel family, `k` off (or missing from) the structured families, sizes
/// outside 1..=[`MAX_VERTICES`] vertices, and the structured families' own limits
/// ([`check_hub_path`], [`check_collinear_bridges`]).
///
/// # Errors
/// [`Error::Invalid`] naming the parameter.
pub fn check(family: &str, n: Option<usize>, holes: Option<usize>, k: Option<usize>) -> Result<()> {
    if !FAMILIES.contains(&family) {
        return Err(Error::invalid(format!(
            "unknown discrete family {family}: expected one of {}",
            FAMILIES.join(", ")
        )));
    }
    let n = n.ok_or_else(|| Error::invalid(format!("family {family} needs n")))?;
    let off = |param: &str| {
        Error::invalid(format!(
            "parameter `{param}` does not apply to family {family} (it takes: {})",
            takes(family)
        ))
    };
    if holes.is_some() && family != "voxel" {
        return Err(off("holes"));
    }
    let structured = STRUCTURED.contains(&family);
    if k.is_some() && !structured {
        return Err(off("k"));
    }
    if structured {
        let k = k.ok_or_else(|| Error::invalid(format!("family {family} needs k")))?;
        return match family {
            "hub-path" => check_hub_path(n, k),
            _ => check_collinear_bridges(n, k),
        };
    }
    check_size(n)
}

/// Generates one instance of a discrete family (deterministic in `seed`; the structured
/// families ignore it).
///
/// # Errors
/// As [`check`], and the generators' own refusals (too many cavities for n voxels).
pub fn generate(
    family: &str,
    n: usize,
    holes: Option<usize>,
    k: Option<usize>,
    seed: u64,
) -> Result<Generated> {
    check(family, Some(n), holes, k)?;
    let with_text = |instance: Discrete| Generated {
        text: super::format::to_text(&instance),
        instance,
        ext: "dm",
    };
    Ok(match family {
        "voxel" => {
            let region = random_voxels(n, seed, holes.unwrap_or(0))?;
            Generated {
                text: region.to_text()?,
                instance: region.to_discrete(),
                ext: "vox",
            }
        }
        "hex" => {
            let region = random_hex(n, seed)?;
            Generated {
                text: region.to_text()?,
                instance: region.to_discrete(),
                ext: "hex",
            }
        }
        "honeycomb" => with_text(random_honeycomb(n, seed)?.to_discrete()),
        "hub-path" => with_text(hub_path(n, k.unwrap_or(0))?),
        "collinear-bridges" => with_text(collinear_bridges(n, k.unwrap_or(0))?),
        _ => with_text(random_plane_graph(n, seed, &PlaneParams::default())?),
    })
}

/// Reads a discrete instance file: `.vox` voxel regions, `.hex` hexagonal cells, `.dm` / `.json`
/// instances.
///
/// # Errors
/// [`Error::Io`] when it cannot be read, [`Error::Parse`] (file:line:col) when it is invalid.
pub fn read(path: &std::path::Path) -> Result<Discrete> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("vox") => Ok(VoxelRegion::read(path)?.to_discrete()),
        Some("hex") => Ok(super::lattice::HexRegion::read(path)?.to_discrete()),
        _ => super::format::read_discrete(path),
    }
}

/// The extensions of discrete instance files.
pub const EXTENSIONS: &[&str] = &["dm", "json", "vox", "hex"];

/// Whether `path` names a discrete instance (by its extension).
pub fn is_discrete(path: &std::path::Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

/// Stream tags: one independent stream per family.
const TAG_VOXELS: u64 = 0xD17_0001;
const TAG_HEX: u64 = 0xD17_0002;
const TAG_HONEYCOMB: u64 = 0xD17_0003;
const TAG_PLANE: u64 = 0xD17_0004;

/// The smallest k with k^power ≥ m (integers, so no platform's `cbrt` decides a box size).
fn root_ceil(m: usize, power: u32) -> usize {
    let mut k = 1usize;
    while k.pow(power) < m {
        k += 1;
    }
    k
}

fn check_size(n: usize) -> Result<()> {
    if n == 0 || n > MAX_VERTICES {
        return Err(Error::invalid(format!(
            "n = {n}; expected from 1 to {MAX_VERTICES}"
        )));
    }
    Ok(())
}

/// Eden growth: a connected set of `target` cells (fewer if the box runs out) of a box of
/// `cells` cells, grown from `start`; `neighbours` lists a cell's neighbours in the box.
fn grow(
    cells: usize,
    start: usize,
    target: usize,
    neighbours: &dyn Fn(usize, &mut Vec<usize>),
    rng: &mut Rng,
) -> Vec<bool> {
    let mut inside = vec![false; cells];
    let mut frontier = vec![start];
    let mut count = 0;
    let mut near = Vec::new();
    while count < target && !frontier.is_empty() {
        let c = frontier.swap_remove(below(rng, frontier.len()));
        if inside[c] {
            continue;
        }
        inside[c] = true;
        count += 1;
        near.clear();
        neighbours(c, &mut near);
        frontier.extend(near.iter().filter(|&&d| !inside[d]));
    }
    inside
}

/// A random connected voxel region of about `n` voxels in a box of about 2n cells, with
/// `cavities` cavities (as many as fit; 0 for none), translated to start at (0, 0, 0).
///
/// Eden growth to n voxels, then every enclosed empty cell is filled (so without cavities the
/// region is solid and may have a few more than n voxels); then each cavity, a 1×1×1 or
/// 2×2×2 block chosen at random, is emptied where the block and its whole one-voxel shell
/// lie in the region. Emptying a block inside a full shell keeps the region connected (paths
/// go round through the shell) and leaves the block enclosed, apart from earlier cavities.
///
/// # Errors
/// [`Error::Invalid`] unless 1 ≤ n ≤ [`MAX_VERTICES`].
pub fn random_voxels(n: usize, seed: u64, cavities: usize) -> Result<VoxelRegion> {
    check_size(n)?;
    let mut rng = rng_for(seed, TAG_VOXELS);
    let a = root_ceil(2 * n, 3).max(2);
    let at = |x: usize, y: usize, z: usize| x + a * (y + a * z);
    let xyz = |i: usize| (i % a, i / a % a, i / (a * a));
    let neighbours = |i: usize, out: &mut Vec<usize>| {
        let (x, y, z) = xyz(i);
        let p = [x, y, z];
        for axis in 0..3 {
            if p[axis] > 0 {
                out.push(i - [1, a, a * a][axis]);
            }
            if p[axis] + 1 < a {
                out.push(i + [1, a, a * a][axis]);
            }
        }
    };
    let centre = at(a / 2, a / 2, a / 2);
    let mut inside = grow(a * a * a, centre, n, &neighbours, &mut rng);
    // Fill the enclosed empty cells: those the box's empty border cells do not reach.
    let mut outside = vec![false; inside.len()];
    let mut queue: VecDeque<usize> = (0..inside.len())
        .filter(|&i| {
            let (x, y, z) = xyz(i);
            !inside[i] && [x, y, z].iter().any(|&c| c == 0 || c + 1 == a)
        })
        .collect();
    for &i in &queue {
        outside[i] = true;
    }
    let mut near = Vec::new();
    while let Some(i) = queue.pop_front() {
        near.clear();
        neighbours(i, &mut near);
        for &j in &near {
            if !inside[j] && !outside[j] {
                outside[j] = true;
                queue.push_back(j);
            }
        }
    }
    for (cell, out) in inside.iter_mut().zip(&outside) {
        *cell = !out;
    }
    drop(outside);
    let mut carved = 0;
    for _ in 0..50 * cavities {
        if carved == cavities {
            break;
        }
        let side = 1 + below(&mut rng, 2);
        if a < side + 2 {
            continue;
        }
        // The block starts at 1..=a−1−side on each axis, so its shell is in the box.
        let span = a - 1 - side;
        let c = [0; 3].map(|_| 1 + below(&mut rng, span));
        let cube = move |lo: usize, hi: usize| {
            (lo..hi).flat_map(move |dz| {
                (lo..hi)
                    .flat_map(move |dy| (lo..hi).map(move |dx| (c[0] + dx, c[1] + dy, c[2] + dz)))
            })
        };
        // The shell is the block grown by one on every side: offsets −1..side+1, shifted by 1.
        let shell_full = cube(0, side + 2).all(|(x, y, z)| inside[at(x - 1, y - 1, z - 1)]);
        if shell_full {
            for (x, y, z) in cube(1, side + 1) {
                inside[at(x - 1, y - 1, z - 1)] = false;
            }
            carved += 1;
        }
    }
    let voxels = (0..inside.len()).filter(|&i| inside[i]).map(|i| {
        let (x, y, z) = xyz(i);
        [x as i32, y as i32, z as i32]
    });
    Ok(VoxelRegion::from_voxels(voxels)?.normalized())
}

/// A random connected region of `n` hexagonal cells, grown in a box of about 2n cells in
/// odd-r offset layout and normalized ([`HexRegion::normalized`]).
///
/// # Errors
/// [`Error::Invalid`] unless 1 ≤ n ≤ [`MAX_VERTICES`].
pub fn random_hex(n: usize, seed: u64) -> Result<HexRegion> {
    check_size(n)?;
    let mut rng = rng_for(seed, TAG_HEX);
    let w = root_ceil(2 * n, 2).max(2);
    // Offset (c, r) to axial (q, r) and back.
    let axial = |i: usize| {
        let (c, r) = ((i % w) as i64, (i / w) as i64);
        (c - r.div_euclid(2), r)
    };
    let neighbours = |i: usize, out: &mut Vec<usize>| {
        let (q, r) = axial(i);
        for [dq, dr] in HEX_STEPS {
            let (q, r) = (q + dq as i64, r + dr as i64);
            let c = q + r.div_euclid(2);
            if (0..w as i64).contains(&c) && (0..w as i64).contains(&r) {
                out.push(c as usize + w * r as usize);
            }
        }
    };
    let inside = grow(w * w, w / 2 + w * (w / 2), n, &neighbours, &mut rng);
    let cells = (0..inside.len()).filter(|&i| inside[i]).map(|i| {
        let (q, r) = axial(i);
        [q as i32, r as i32]
    });
    Ok(HexRegion::from_cells(cells)?.normalized())
}

/// A random connected region of `n` honeycomb vertices, grown in a box of about 2n triangles
/// (rows of up and down triangles in odd-r offset layout).
///
/// # Errors
/// [`Error::Invalid`] unless 1 ≤ n ≤ [`MAX_VERTICES`].
pub fn random_honeycomb(n: usize, seed: u64) -> Result<HoneycombRegion> {
    check_size(n)?;
    let mut rng = rng_for(seed, TAG_HONEYCOMB);
    let w = root_ceil(n, 2).max(2);
    let vertex = |i: usize| {
        let (c, r) = ((i / 2 % w) as i32, (i / 2 / w) as i32);
        HoneycombVertex::new(c - r.div_euclid(2), r, i % 2 == 1)
    };
    let neighbours = |i: usize, out: &mut Vec<usize>| {
        for v in vertex(i).neighbors().into_iter().flatten() {
            let c = v.q as i64 + v.r.div_euclid(2) as i64;
            if (0..w as i64).contains(&c) && (0..w as i64).contains(&(v.r as i64)) {
                out.push(2 * (c as usize + w * v.r as usize) + v.down as usize);
            }
        }
    };
    let inside = grow(
        2 * w * w,
        2 * (w / 2 + w * (w / 2)),
        n,
        &neighbours,
        &mut rng,
    );
    HoneycombRegion::from_vertices((0..inside.len()).filter(|&i| inside[i]).map(vertex))
}

/// The parameters of [`random_plane_graph`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneParams {
    /// The chance that a cell of the grid gets a diagonal (of random orientation).
    pub diagonal: f64,
    /// The chance that an edge outside the random spanning tree is dropped.
    pub drop: f64,
    /// How far a point moves from its grid position, at most, along each axis (below 0.25,
    /// which keeps every cell convex and the drawing plane).
    pub jitter: f64,
    /// Which pairs count as nearly straight ([`super::lattice::geometric`]): the cosine of
    /// their angle at most −`straightness`.
    pub straightness: f64,
}

impl Default for PlaneParams {
    /// Half the cells with a diagonal, a fifth of the spare edges dropped, points moved by up
    /// to 0.2, bends up to 45° straight.
    fn default() -> PlaneParams {
        PlaneParams {
            diagonal: 0.5,
            drop: 0.2,
            jitter: 0.2,
            straightness: 0.5f64.sqrt(),
        }
    }
}

/// A random connected plane graph on about `n` vertices with its nearly straight pairs
/// collinear: a w × h grid (w = ⌈√n⌉, h = ⌈n / w⌉) of points each moved at random by up to
/// `jitter` per axis, its grid edges plus a diagonal in a random share of the cells, minus a
/// random share of the edges outside a random spanning tree (so it stays connected); at each
/// vertex the nearly straight pairs are matched by [`super::lattice::geometric`].
///
/// The paper's discrete milling has no random model; this one is a planar graph (δ < 6, the
/// case of the remark after Corollary 5.1) whose straight pairs come from its drawing.
///
/// # Errors
/// [`Error::Invalid`] unless 1 ≤ n ≤ [`MAX_VERTICES`], the chances are in [0, 1] and
/// 0 ≤ jitter < 0.25.
pub fn random_plane_graph(n: usize, seed: u64, params: &PlaneParams) -> Result<Discrete> {
    check_size(n)?;
    let p = params;
    let chance_ok = |x: f64| (0.0..=1.0).contains(&x);
    if !chance_ok(p.diagonal) || !chance_ok(p.drop) || !(0.0..0.25).contains(&p.jitter) {
        return Err(Error::invalid(format!(
            "plane graph parameters {p:?}: expected diagonal and drop in [0, 1] and jitter in \
             [0, 0.25)"
        )));
    }
    let mut rng = rng_for(seed, TAG_PLANE);
    let w = root_ceil(n, 2);
    let h = n.div_ceil(w);
    let id = |x: usize, y: usize| (x + w * y) as u32;
    let mut points = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let dx = p.jitter * (2.0 * unit(&mut rng) - 1.0);
            let dy = p.jitter * (2.0 * unit(&mut rng) - 1.0);
            points.push([x as f64 + dx, y as f64 + dy]);
        }
    }
    let mut edges = Vec::new();
    for y in 0..h {
        for x in 0..w {
            if x + 1 < w {
                edges.push((id(x, y), id(x + 1, y)));
            }
            if y + 1 < h {
                edges.push((id(x, y), id(x, y + 1)));
            }
            if x + 1 < w && y + 1 < h && unit(&mut rng) < p.diagonal {
                edges.push(if below(&mut rng, 2) == 0 {
                    (id(x, y), id(x + 1, y + 1))
                } else {
                    (id(x + 1, y), id(x, y + 1))
                });
            }
        }
    }
    // A random spanning tree (Kruskal in random order) is kept; the other edges may go.
    let mut order: Vec<usize> = (0..edges.len()).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, below(&mut rng, i + 1));
    }
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    fn root(parent: &mut [u32], mut v: u32) -> u32 {
        while parent[v as usize] != v {
            parent[v as usize] = parent[parent[v as usize] as usize];
            v = parent[v as usize];
        }
        v
    }
    let mut keep = vec![false; edges.len()];
    for &k in &order {
        let (a, b) = edges[k];
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        if ra != rb {
            parent[ra as usize] = rb;
            keep[k] = true;
        }
    }
    for kept in keep.iter_mut() {
        if !*kept && unit(&mut rng) >= p.drop {
            *kept = true;
        }
    }
    let edges: Vec<(u32, u32)> = edges
        .into_iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(e, _)| e)
        .collect();
    super::lattice::geometric(&points, &edges, p.straightness)
}

/// Refuses the parameters [`hub_path`] refuses: K = 0, P < K + 2 (a run would be empty), or
/// more than [`MAX_VERTICES`] vertices (P + K).
///
/// # Errors
/// [`Error::Invalid`] naming `n` (P) and `k` (K).
pub fn check_hub_path(p: usize, k: usize) -> Result<()> {
    if k == 0 || p < k.saturating_add(2) {
        return Err(Error::invalid(format!(
            "hub-path: need k >= 1 hubs and n >= k + 2 path vertices (n = {p}, k = {k})"
        )));
    }
    if p.saturating_add(k) > MAX_VERTICES {
        return Err(Error::invalid(format!(
            "hub-path: n + k = {} vertices; expected at most {MAX_VERTICES}",
            p.saturating_add(k)
        )));
    }
    Ok(())
}

/// Hubs on a straight path (the family of the star cover's order study, `mowmill_core::discrete::choices`, proof for every order): path
/// vertices 0..P (collinear at every inner vertex), then K hubs P..P+K; the P − 2 inner path
/// vertices are cut into K consecutive runs as equal as possible (the first runs one longer),
/// and hub j is joined by unmatched edges (collinear with nothing) to every vertex of run j.
/// P + K vertices, 2P − 3 edges, no coordinates.
///
/// On it the greedy star cover violates Theorem 5.1's averaged bound (ρ + 2δ)·OPT_cc for every
/// scan order from P ≈ 70 (K = 2..4): docs/discrete.md, Findings 2.
///
/// # Errors
/// As [`check_hub_path`].
pub fn hub_path(p: usize, k: usize) -> Result<Discrete> {
    check_hub_path(p, k)?;
    let inner = p - 2;
    let mut edges: Vec<(u32, u32)> = (0..p as u32 - 1).map(|i| (i, i + 1)).collect();
    let collinear: Vec<(u32, u32, u32)> = (1..p as u32 - 1).map(|i| (i, i - 1, i + 1)).collect();
    let mut next = 1u32;
    for j in 0..k {
        let len = inner / k + usize::from(j < inner % k);
        for _ in 0..len {
            edges.push(((p + j) as u32, next));
            next += 1;
        }
    }
    Discrete::new(p + k, &edges, &collinear, None)
}

/// Refuses the parameters [`collinear_bridges`] refuses: K < 2 paths, P < 5 vertices a path
/// (the odd pairs' first bridge is at column 3, which must be at most P − 2), or more than
/// [`MAX_VERTICES`] vertices (P·K).
///
/// # Errors
/// [`Error::Invalid`] naming `n` (P) and `k` (K).
pub fn check_collinear_bridges(p: usize, k: usize) -> Result<()> {
    if k < 2 || p < 5 {
        return Err(Error::invalid(format!(
            "collinear-bridges: need k >= 2 paths of n >= 5 vertices (n = {p}, k = {k})"
        )));
    }
    match p.checked_mul(k) {
        Some(total) if total <= MAX_VERTICES => Ok(()),
        _ => Err(Error::invalid(format!(
            "collinear-bridges: n k = {p} x {k} vertices; expected at most {MAX_VERTICES}"
        ))),
    }
}

/// Straight paths joined by bridges, `instances/discrete/bridge.dm` scaled: K straight paths of
/// P vertices side by side, path i the vertices iP..iP+P (collinear at every inner vertex),
/// and between paths i and i + 1 bridge edges iP + j — (i+1)P + j, collinear with nothing, at
/// the columns j = 2, 6, 10, … ≤ P − 2 for even i and j = 3, 7, 11, … ≤ P − 2 for odd i (so no
/// vertex has two bridges, and the path ends none). P·K vertices, no coordinates.
/// (P, K) = (5, 2) is bridge.dm, vertex for vertex.
///
/// Why Theorem 4.2 fails on it: the greedy star cover (index order) puts one rook at the start
/// of each path and doubles each path, t = 4K turns in c = K cycles, budget t + 2c − 2 = 6K − 2.
/// Every tour U-turns at each of the 2K path ends (degree 1: 2 turns each), and crosses each
/// of the K − 1 cuts between neighbouring paths at least twice; at a bridge's end it turns at
/// least once (no vertex has two bridges: it goes on along the path, 1 turn, or back over the
/// same bridge, 2 turns for two bridge ends). So every tour has at least 4K + 4(K − 1) = 8K − 4
/// turns, above the budget for every K ≥ 2.
///
/// # Errors
/// As [`check_collinear_bridges`].
pub fn collinear_bridges(p: usize, k: usize) -> Result<Discrete> {
    check_collinear_bridges(p, k)?;
    let v = |i: usize, j: usize| (i * p + j) as u32;
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(k * p + (k - 1) * (p / 4 + 1));
    let mut collinear: Vec<(u32, u32, u32)> = Vec::with_capacity(k * (p - 2));
    for i in 0..k {
        edges.extend((0..p - 1).map(|j| (v(i, j), v(i, j + 1))));
        collinear.extend((1..p - 1).map(|j| (v(i, j), v(i, j - 1), v(i, j + 1))));
    }
    for i in 0..k - 1 {
        edges.extend(
            (2 + i % 2..=p - 2)
                .step_by(4)
                .map(|j| (v(i, j), v(i + 1, j))),
        );
    }
    Discrete::new(p * k, &edges, &collinear, None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::discrete::format::to_text;

    fn connected(g: &Discrete) -> bool {
        g.components() == 1
    }

    /// The enclosed empty components of a voxel region (6-connected empties that the outside
    /// of its bounding box does not reach).
    fn cavities(r: &VoxelRegion) -> usize {
        let mut max = [0usize; 3];
        for v in r.voxels() {
            for a in 0..3 {
                max[a] = max[a].max(v[a] as usize + 3);
            }
        }
        let at = |p: [usize; 3]| p[0] + max[0] * (p[1] + max[1] * p[2]);
        let mut full = vec![false; max[0] * max[1] * max[2]];
        for v in r.voxels() {
            full[at(v.map(|c| c as usize + 1))] = true;
        }
        let mut label = vec![0u32; full.len()];
        let mut components = 0;
        for start in 0..full.len() {
            if full[start] || label[start] != 0 {
                continue;
            }
            components += 1;
            label[start] = components;
            let mut stack = vec![start];
            while let Some(i) = stack.pop() {
                let p = [i % max[0], i / max[0] % max[1], i / (max[0] * max[1])];
                for axis in 0..3 {
                    for up in [false, true] {
                        let mut q = p;
                        if up {
                            q[axis] += 1;
                        } else if q[axis] > 0 {
                            q[axis] -= 1;
                        } else {
                            continue;
                        }
                        if q[axis] >= max[axis] {
                            continue;
                        }
                        let j = at(q);
                        if !full[j] && label[j] == 0 {
                            label[j] = components;
                            stack.push(j);
                        }
                    }
                }
            }
        }
        // Cell 0 is in the padding: its component is the outside.
        components as usize - 1
    }

    /// Every collinear pair `c v a b` is two distinct edges at v, and each edge end is in at
    /// most one pair (a matching).
    fn collinear_pairs_valid(g: &Discrete) {
        let edges: std::collections::BTreeSet<(u32, u32)> =
            g.edges().map(|(a, b)| (a.min(b), a.max(b))).collect();
        let has = |a: u32, b: u32| edges.contains(&(a.min(b), a.max(b)));
        let mut used = std::collections::BTreeSet::new();
        let text = to_text(g);
        for line in text.lines().filter(|l| l.starts_with("c ")) {
            let f: Vec<u32> = line[2..].split(' ').map(|x| x.parse().unwrap()).collect();
            let (v, a, b) = (f[0], f[1], f[2]);
            assert!(a != b && has(v, a) && has(v, b), "{line}");
            assert!(
                used.insert((v, a)) && used.insert((v, b)),
                "{line}: not a matching"
            );
        }
    }

    #[test]
    fn hub_paths_are_connected_deterministic_and_as_promised() {
        for (p, k) in [(3, 1), (20, 1), (20, 4), (68, 2), (2000, 3)] {
            let g = hub_path(p, k).unwrap();
            assert_eq!(g.len(), p + k);
            assert_eq!(g.edge_count(), 2 * p - 3);
            assert!(connected(&g));
            collinear_pairs_valid(&g);
            assert_eq!(to_text(&g), to_text(&hub_path(p, k).unwrap()));
            let made = generate("hub-path", p, None, Some(k), 7).unwrap();
            assert_eq!(made.text, to_text(&g), "the seed is ignored");
            assert_eq!(made.ext, "dm");
        }
        for (p, k) in [(10, 0), (3, 2), (2, 1), (MAX_VERTICES, 1), (usize::MAX, 3)] {
            assert!(hub_path(p, k).is_err(), "{p} {k}");
            assert!(
                check("hub-path", Some(p), None, Some(k)).is_err(),
                "{p} {k}"
            );
        }
        assert!(check("hub-path", Some(10), None, None).is_err());
        assert!(check("hub-path", Some(10), Some(1), Some(2)).is_err());
        assert!(check("hex", Some(10), None, Some(2)).is_err());
    }

    #[test]
    fn collinear_bridges_are_connected_deterministic_and_as_promised() {
        for (p, k) in [(5, 2), (5, 5), (6, 3), (9, 2), (101, 4), (5000, 4)] {
            let g = collinear_bridges(p, k).unwrap();
            assert_eq!(g.len(), p * k);
            let bridges = |i: usize| (2 + i % 2..=p - 2).step_by(4).count();
            let b: usize = (0..k - 1).map(bridges).sum();
            assert!((0..k - 1).all(|i| bridges(i) >= 1));
            assert_eq!(g.edge_count(), k * (p - 1) + b);
            assert!(connected(&g));
            collinear_pairs_valid(&g);
            assert_eq!(g.params().mu, 3);
            let made = generate("collinear-bridges", p, None, Some(k), 3).unwrap();
            assert_eq!(made.text, to_text(&g));
        }
        // (5, 2) is instances/discrete/bridge.dm.
        let bridge = read(
            &std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
                .join("instances/discrete/bridge.dm"),
        )
        .unwrap();
        assert_eq!(to_text(&collinear_bridges(5, 2).unwrap()), to_text(&bridge));
        for (p, k) in [(4, 2), (10, 1), (10, 0), (MAX_VERTICES, 2), (usize::MAX, 2)] {
            assert!(collinear_bridges(p, k).is_err(), "{p} {k}");
        }
    }

    #[test]
    fn voxel_regions_are_connected_deterministic_and_hollow_on_request() {
        for (n, seed) in [(1, 0), (2, 5), (50, 1), (3000, 2)] {
            let solid = random_voxels(n, seed, 0).unwrap();
            assert!(
                solid.len() >= n && solid.len() <= n + n / 4 + 1,
                "{n}: {}",
                solid.len()
            );
            assert_eq!(cavities(&solid), 0, "{n}");
            assert!(connected(&solid.to_discrete()));
            let again = random_voxels(n, seed, 0).unwrap();
            assert_eq!(again.to_text().unwrap(), solid.to_text().unwrap());
        }
        let hollow = random_voxels(3000, 2, 6).unwrap();
        assert_eq!(cavities(&hollow), 6);
        assert!(connected(&hollow.to_discrete()));
        assert_ne!(hollow, random_voxels(3000, 3, 6).unwrap());
        let v = hollow.voxels();
        assert_eq!(
            (0..3).map(|a| v.iter().map(|p| p[a]).min().unwrap()).max(),
            Some(0)
        );
        assert_eq!(hollow.to_discrete().directions(), Some(3));
    }

    #[test]
    fn hex_and_honeycomb_regions_are_connected_and_deterministic() {
        for (n, seed) in [(1, 0), (7, 3), (400, 1), (2000, 9)] {
            let h = random_hex(n, seed).unwrap();
            assert_eq!(h.len(), n);
            let g = h.to_discrete();
            assert!(connected(&g));
            assert_eq!(
                h.to_text().unwrap(),
                random_hex(n, seed).unwrap().to_text().unwrap()
            );
            if n >= 400 {
                assert_eq!(g.params().mu, 6);
            }
            let c = random_honeycomb(n, seed).unwrap();
            assert_eq!(c.len(), n);
            let g = c.to_discrete();
            assert!(connected(&g));
            assert_eq!(
                to_text(&g),
                to_text(&random_honeycomb(n, seed).unwrap().to_discrete())
            );
            if n >= 400 {
                assert_eq!(g.params().mu, 3);
            }
        }
        assert_ne!(random_hex(400, 1).unwrap(), random_hex(400, 2).unwrap());
        assert_ne!(
            random_honeycomb(400, 1).unwrap(),
            random_honeycomb(400, 2).unwrap()
        );
        assert!(random_hex(0, 1).is_err());
    }

    /// Whether segments ab and cd cross at a point inside both (sharing an end is allowed).
    fn cross(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> bool {
        let orient = |p: [f64; 3], q: [f64; 3], r: [f64; 3]| {
            (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
        };
        let (o1, o2) = (orient(a, b, c), orient(a, b, d));
        let (o3, o4) = (orient(c, d, a), orient(c, d, b));
        o1 * o2 < 0.0 && o3 * o4 < 0.0
    }

    #[test]
    fn plane_graphs_are_connected_plane_and_deterministic() {
        let params = PlaneParams::default();
        for (n, seed) in [(1, 0), (2, 0), (30, 4), (300, 7)] {
            let g = random_plane_graph(n, seed, &params).unwrap();
            assert!(
                g.len() >= n && g.len() < n + n.isqrt() + 2,
                "{n}: {}",
                g.len()
            );
            assert!(connected(&g));
            assert_eq!(
                to_text(&g),
                to_text(&random_plane_graph(n, seed, &params).unwrap())
            );
            let edges: Vec<(u32, u32)> = g.edges().collect();
            let at = |v: u32| g.coords(v).unwrap();
            for (i, &(a, b)) in edges.iter().enumerate() {
                for &(c, d) in &edges[i + 1..] {
                    assert!(
                        !cross(at(a), at(b), at(c), at(d)),
                        "{a}-{b} crosses {c}-{d}"
                    );
                }
            }
            let p = g.params();
            assert!(p.delta < 6.0);
            if n >= 300 {
                assert!(p.rho < p.delta, "some pairs are straight: {p:?}");
                assert!(p.mu >= 5);
            }
        }
        assert_ne!(
            random_plane_graph(300, 7, &params).unwrap(),
            random_plane_graph(300, 8, &params).unwrap()
        );
        let bad = PlaneParams {
            jitter: 0.3,
            ..params
        };
        assert!(random_plane_graph(10, 0, &bad).is_err());
    }
}
