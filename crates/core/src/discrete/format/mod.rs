//! The file formats of discrete milling instances and of their walks.
//!
//! An instance ([`Discrete`]) is stored in one of two forms, read by [`read_discrete`] (by the
//! extension `.json` or `.dm`, else by the first non-space character: `{` means JSON) and
//! written by [`to_json`] and [`to_text`]. Both forms say the same thing: the number of
//! vertices N (numbered `0..N`), the undirected edges, the collinear pairs (the edges `va` and
//! `vb` are collinear at `v`), optionally one coordinate per vertex (2-D or 3-D, for drawing)
//! and optionally `d`, the number of allowed directions of a lattice instance (Theorem 5.2).
//!
//! # JSON
//!
//! ```json
//! {"vertices": 3, "edges": [[0, 1], [1, 2]], "collinear": [[1, 0, 2]],
//!  "coords": [[0, 0], [1, 0], [2, 0]], "directions": 2}
//! ```
//!
//! `vertices` and `edges` are required; `collinear` defaults to none; `coords` (a list of N
//! points, each `[x, y]` or `[x, y, z]`, z = 0 when left out) and `directions` (d ≥ 1) may be
//! left out. Other keys are refused. Syntax errors get serde_json's line and column; an
//! entry that is well-formed but wrong (a vertex outside `0..N`, a loop, an edge given twice,
//! a collinear pair that is not two distinct edges at its vertex or that breaks the matching,
//! a wrong number of coordinates) is reported at the line and column of the offending number.
//!
//! # Compact text (`.dm`)
//!
//! ```text
//! # a path of three vertices, straight through the middle
//! discrete 3
//! e 0 1
//! e 1 2
//! c 1 0 2
//! p 0 0 0
//! p 1 1 0
//! p 2 2 0
//! d 2
//! ```
//!
//! `#` starts a comment that runs to the end of the line; blank lines are skipped, fields are
//! separated by whitespace and a trailing `\r` is ignored. The first record is the header
//! `discrete N`; after it, in any order: `e a b` (an edge), `c v a b` (edges `va` and `vb`
//! collinear at `v`), `p v x y [z]` (the coordinates of `v`; either every vertex has one `p`
//! line or none has) and at most one `d D` (the allowed directions). Vertex indices are
//! decimal integers; coordinates are finite decimal numbers (`1`, `-0.5`, `2e3`). Every
//! malformed line is reported at its line and the column of the field that is wrong, saying
//! what was expected; an edge given twice or an edge in two collinear pairs at one vertex is
//! reported at the later line, naming the earlier one.
//!
//! Writing puts a comment line first, then the header, `d`, the edges (each once as `e a b`
//! with `a < b`, in the order of [`Discrete::edges`]), the collinear pairs vertex by vertex and
//! the coordinates in vertex order. Both forms write z only when some vertex has z ≠ 0, and
//! write numbers as Rust's shortest round-trip decimal, so reading a written file gives the
//! same instance and writing that again gives the same bytes.
//!
//! # Limits
//!
//! N is at most [`MAX_VERTICES`] and the edges (and the collinear pairs) at most
//! [`MAX_EDGES`]; both are checked before anything proportional to them is allocated (the
//! text form checks N at its header, before the first `p` line allocates N coordinates). A
//! file of a few bytes may still declare N = 50,000,000 vertices without edges, which costs
//! the instance its 4 bytes per vertex (200 MB at the limit, 24 more per vertex with
//! coordinates); the limit bounds that. At the limits an instance takes about 3 GB.
//!
//! # Walks
//!
//! A set of closed walks of a discrete instance ([`DiscreteCover`]) is the JSON
//! `{"model": "discrete", "cycles": [[v, ...], ...]}`: each cycle lists vertex indices,
//! consecutive ones adjacent and the last adjacent to the first (a single vertex is a walk of
//! length 0). `model` must be `"discrete"` (it tells these files from the grid's
//! `{"cycles": [[[x, y], ...]]}`); other keys are refused. Whether the walks are walks of the
//! instance is the checker's business ([`super::check::check`]), not the reader's.

mod json;
#[cfg(test)]
mod tests;
mod text;
mod walks;

pub use json::{parse_json, to_json};
pub use text::{parse_text, to_text};
pub use walks::DiscreteCover;

use super::Discrete;
use crate::error::{Error, Result};
use crate::gridfile::utf8_text;
use std::path::Path;

/// The most vertices an instance file may declare (checked before any allocation of N).
pub const MAX_VERTICES: usize = 50_000_000;

/// The most edges (and, separately, collinear pairs) an instance file may list; it keeps the
/// instance's 2 ports per edge well inside its `u32` port indices.
pub const MAX_EDGES: usize = 200_000_000;

/// Reads an instance file in either form: `.json` and `.dm` by extension, anything else by
/// its content (JSON when the first non-space character is `{`).
///
/// # Errors
/// [`Error::Io`] when the file cannot be read, [`Error::Parse`] (file, line, column, what was
/// expected) when it is not a valid instance.
pub fn read_discrete(path: &Path) -> Result<Discrete> {
    let bytes = crate::input::read_bytes(path, "a discrete instance or tour file")?;
    let name = path.display().to_string();
    let text = utf8_text(bytes, &name)?;
    match path.extension().and_then(|e| e.to_str()) {
        Some("json") => parse_json(&text, &name),
        Some("dm") => parse_text(&text, &name),
        _ => parse_discrete(&text, &name),
    }
}

/// Parses an instance in either form, told apart by the first non-space character (`{` for
/// JSON); `file` names the source in error messages.
pub fn parse_discrete(text: &str, file: &str) -> Result<Discrete> {
    if text.trim_start().starts_with('{') {
        parse_json(text, file)
    } else {
        parse_text(text, file)
    }
}

/// Writes an instance: JSON when the path ends in `.json`, else the compact text.
pub fn write_discrete(inst: &Discrete, path: &Path) -> Result<()> {
    let text = if path.extension().is_some_and(|e| e == "json") {
        to_json(inst)
    } else {
        to_text(inst)
    };
    std::fs::write(path, text).map_err(|e| Error::io(path, e))
}

/// A place in an instance, for the readers to turn into a line and column: the list (by its
/// JSON key), the entry in it and the field in the entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Site {
    key: &'static str,
    entry: Option<usize>,
    field: Option<usize>,
}

impl Site {
    fn key(key: &'static str) -> Site {
        Site {
            key,
            entry: None,
            field: None,
        }
    }

    fn at(key: &'static str, entry: usize, field: usize) -> Site {
        Site {
            key,
            entry: Some(entry),
            field: Some(field),
        }
    }
}

/// What is wrong with an instance and where.
#[derive(Debug)]
struct Fault {
    site: Site,
    message: String,
}

fn fault(site: Site, message: String) -> Fault {
    Fault { site, message }
}

/// An instance as a file states it, before validation.
struct Stated {
    vertices: u64,
    edges: Vec<[u32; 2]>,
    collinear: Vec<[u32; 3]>,
    coords: Option<Vec<[f64; 3]>>,
    directions: Option<u32>,
}

fn outside(v: u64, n: u64) -> String {
    format!(
        "vertex {v} is outside 0..{n}; expected an index from 0 to {}",
        n.saturating_sub(1)
    )
}

/// Validates a stated instance entry by entry and builds it; `describe` names an earlier entry
/// in a message ("line 4", "edges[2]").
fn assemble(s: Stated, describe: &dyn Fn(Site) -> String) -> std::result::Result<Discrete, Fault> {
    let n64 = s.vertices;
    if n64 == 0 || n64 > MAX_VERTICES as u64 {
        return Err(fault(
            Site::key("vertices"),
            format!("{n64} vertices; expected from 1 to {MAX_VERTICES} (the vertex limit)"),
        ));
    }
    let n = n64 as usize;
    for (key, len) in [("edges", s.edges.len()), ("collinear", s.collinear.len())] {
        if len > MAX_EDGES {
            return Err(fault(
                Site::key(key),
                format!("{len} {key} entries; expected at most {MAX_EDGES}"),
            ));
        }
    }
    for (k, &[a, b]) in s.edges.iter().enumerate() {
        for (f, v) in [(0, a), (1, b)] {
            if v as u64 >= n64 {
                return Err(fault(Site::at("edges", k, f), outside(v as u64, n64)));
            }
        }
        if a == b {
            return Err(fault(
                Site::at("edges", k, 1),
                format!("edge {a} {b} is a loop; expected two different vertices"),
            ));
        }
    }
    // Edges sorted by their ends: a repeat is reported at its earliest repetition.
    let mut keyed: Vec<(u32, u32, u32)> = s
        .edges
        .iter()
        .enumerate()
        .map(|(k, &[a, b])| (a.min(b), a.max(b), k as u32))
        .collect();
    keyed.sort_unstable();
    if let Some((first, again)) = keyed
        .windows(2)
        .filter(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1))
        .map(|w| (w[0].2 as usize, w[1].2 as usize))
        .min_by_key(|&(_, again)| again)
    {
        let [a, b] = s.edges[again];
        return Err(fault(
            Site::at("edges", again, 0),
            format!(
                "edge {a} {b} is also at {}; expected each edge once",
                describe(Site::at("edges", first, 0))
            ),
        ));
    }
    let is_edge = |a: u32, b: u32| {
        let (lo, hi) = (a.min(b), a.max(b));
        keyed
            .binary_search_by(|&(x, y, _)| (x, y).cmp(&(lo, hi)))
            .is_ok()
    };
    let mut ends: Vec<(u32, u32, u32, u8)> = Vec::with_capacity(2 * s.collinear.len());
    for (k, &[v, a, b]) in s.collinear.iter().enumerate() {
        for (f, x) in [(0, v), (1, a), (2, b)] {
            if x as u64 >= n64 {
                return Err(fault(Site::at("collinear", k, f), outside(x as u64, n64)));
            }
        }
        if a == b {
            return Err(fault(
                Site::at("collinear", k, 2),
                format!(
                    "collinear pair {a} {b} at vertex {v} names one edge twice; expected two \
                     different neighbours of {v}"
                ),
            ));
        }
        for (f, x) in [(1, a), (2, b)] {
            if !is_edge(v, x) {
                return Err(fault(
                    Site::at("collinear", k, f),
                    format!("{v} {x} is not an edge; expected a neighbour of vertex {v}"),
                ));
            }
            ends.push((v, x, k as u32, f as u8));
        }
    }
    ends.sort_unstable();
    if let Some((first, (again, f))) = ends
        .windows(2)
        .filter(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1))
        .map(|w| (w[0].2 as usize, (w[1].2 as usize, w[1].3 as usize)))
        .min_by_key(|&(_, again)| again)
    {
        let [v, a, b] = s.collinear[again];
        let x = if f == 1 { a } else { b };
        return Err(fault(
            Site::at("collinear", again, f),
            format!(
                "edge {v} {x} is also in the collinear pair at {}; expected the pairs at vertex \
                 {v} to form a matching (each edge in at most one pair)",
                describe(Site::at("collinear", first, 0))
            ),
        ));
    }
    drop(ends);
    drop(keyed);
    if let Some(c) = &s.coords {
        if c.len() != n {
            return Err(fault(
                Site::key("coords"),
                format!(
                    "{} coordinates for {n} vertices; expected one point per vertex",
                    c.len()
                ),
            ));
        }
        for (k, p) in c.iter().enumerate() {
            if let Some(j) = p.iter().position(|x| !x.is_finite()) {
                return Err(fault(
                    Site::at("coords", k, j),
                    format!("coordinate {} is not a finite number", p[j]),
                ));
            }
        }
    }
    if s.directions == Some(0) {
        return Err(fault(
            Site::key("directions"),
            "0 directions; expected at least 1".to_string(),
        ));
    }
    let edges: Vec<(u32, u32)> = s.edges.iter().map(|&[a, b]| (a, b)).collect();
    let collinear: Vec<(u32, u32, u32)> = s.collinear.iter().map(|&[v, a, b]| (v, a, b)).collect();
    let mut inst = Discrete::new(n, &edges, &collinear, s.coords)
        .map_err(|e| fault(Site::key("vertices"), e.to_string()))?;
    inst.set_directions(s.directions);
    Ok(inst)
}
