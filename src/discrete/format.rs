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

use super::{Discrete, VertexWalk};
use crate::error::{Error, Result};
use crate::gridfile::utf8_text;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
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

// ---------------------------------------------------------------------------------------------
// JSON

/// The JSON form as serde reads it (written by hand in [`to_json`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InstanceJson {
    vertices: u64,
    edges: Vec<[u32; 2]>,
    #[serde(default)]
    collinear: Vec<[u32; 3]>,
    #[serde(default)]
    coords: Option<Vec<Vec<f64>>>,
    #[serde(default)]
    directions: Option<u32>,
}

/// Parses the JSON form; `file` names the source in error messages.
///
/// # Examples
///
/// ```
/// use mowmill::discrete::format::parse_json;
///
/// let g = parse_json(r#"{"vertices": 3, "edges": [[0, 1], [1, 2]], "collinear": [[1, 0, 2]]}"#, "g.json")?;
/// assert_eq!(g.turn(0, 1, 2), 0);
/// let e = parse_json("{\"vertices\": 2,\n \"edges\": [[0, 1], [1, 2]]}", "g.json").unwrap_err();
/// assert_eq!(e.to_string(), "g.json:2:24: vertex 2 is outside 0..2; expected an index from 0 to 1");
/// # Ok::<(), mowmill::error::Error>(())
/// ```
pub fn parse_json(text: &str, file: &str) -> Result<Discrete> {
    let raw: InstanceJson = serde_json::from_str(text).map_err(|e| {
        Error::parse(
            file,
            e.line(),
            e.column(),
            format!(
                "expected a discrete instance {{\"vertices\": N, \"edges\": [[a, b], ...], \
                 \"collinear\": [[v, a, b], ...], \"coords\": [[x, y], ...], \"directions\": d}}: {e}"
            ),
        )
    })?;
    let at = |site: Site| {
        let offset = json_site(text, site).unwrap_or(0);
        line_column(text, offset)
    };
    let describe = |site: Site| match site.entry {
        Some(k) => format!("{}[{k}] (line {})", site.key, at(site).0),
        None => site.key.to_string(),
    };
    let coords = match raw.coords {
        None => None,
        Some(mut points) => {
            exact_numbers(text, &mut points);
            let mut out = Vec::with_capacity(points.len().min(MAX_VERTICES + 1));
            for (k, p) in points.iter().enumerate() {
                match p[..] {
                    [x, y] => out.push([x, y, 0.0]),
                    [x, y, z] => out.push([x, y, z]),
                    _ => {
                        let (line, column) = at(Site {
                            key: "coords",
                            entry: Some(k),
                            field: None,
                        });
                        return Err(Error::parse(
                            file,
                            line,
                            column,
                            format!(
                                "a point of {} numbers; expected [x, y] or [x, y, z]",
                                p.len()
                            ),
                        ));
                    }
                }
            }
            Some(out)
        }
    };
    let stated = Stated {
        vertices: raw.vertices,
        edges: raw.edges,
        collinear: raw.collinear,
        coords,
        directions: raw.directions,
    };
    assemble(stated, &describe).map_err(|f| {
        let (line, column) = at(f.site);
        Error::parse(file, line, column, f.message)
    })
}

/// Reads the numbers of the `coords` list (already checked by serde to be lists of numbers)
/// again from the text with Rust's correctly rounded parser: serde_json's default float
/// parser (without its `float_roundtrip` feature) may miss by an ulp, and coordinates must
/// read back as the `f64` they were written from.
fn exact_numbers(text: &str, points: &mut [Vec<f64>]) -> Option<()> {
    let b = text.as_bytes();
    let mut p = json_site(text, Site::key("coords"))?;
    p = skip_ws(b, p + 1);
    for point in points.iter_mut() {
        let mut q = skip_ws(b, p + 1);
        for x in point.iter_mut() {
            let end = skip_value(b, q)?;
            if let Ok(exact) = text[q..end].parse::<f64>() {
                *x = exact;
            }
            q = skip_ws(b, end);
            if b.get(q) == Some(&b',') {
                q = skip_ws(b, q + 1);
            }
        }
        p = skip_ws(b, skip_value(b, p)?);
        if b.get(p) == Some(&b',') {
            p = skip_ws(b, p + 1);
        }
    }
    Some(())
}

/// The JSON form, on one line per list entry group: `vertices`, `edges`, `collinear`, then
/// `coords` and `directions` when the instance has them.
pub fn to_json(inst: &Discrete) -> String {
    let n = inst.len();
    let mut s = String::with_capacity(24 * inst.edge_count() + 40 * n + 100);
    let _ = write!(s, "{{\"vertices\": {n},\n \"edges\": [");
    for (k, (a, b)) in inst.edges().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        let _ = write!(s, "{sep}[{a},{b}]");
    }
    s.push_str("],\n \"collinear\": [");
    let mut first = true;
    for v in 0..n as u32 {
        for (a, b) in inst.collinear_pairs(v) {
            let sep = if first { "" } else { "," };
            first = false;
            let _ = write!(s, "{sep}[{v},{a},{b}]");
        }
    }
    s.push(']');
    if !inst.is_empty() && inst.coords(0).is_some() {
        let three = has_z(inst);
        s.push_str(",\n \"coords\": [");
        for v in 0..n as u32 {
            let [x, y, z] = inst.coords(v).unwrap_or([0.0; 3]);
            let sep = if v == 0 { "" } else { "," };
            if three {
                let _ = write!(s, "{sep}[{},{},{}]", num(x), num(y), num(z));
            } else {
                let _ = write!(s, "{sep}[{},{}]", num(x), num(y));
            }
        }
        s.push(']');
    }
    if let Some(d) = inst.directions() {
        let _ = write!(s, ",\n \"directions\": {d}");
    }
    s.push_str("}\n");
    s
}

/// Whether some vertex has a z coordinate other than 0.
fn has_z(inst: &Discrete) -> bool {
    (0..inst.len() as u32).any(|v| inst.coords(v).is_some_and(|c| c[2] != 0.0))
}

/// A coordinate as the shortest decimal that reads back to the same `f64` (`-0` as `0`, so
/// that JSON readers that know no negative zero agree).
fn num(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else {
        format!("{x}")
    }
}

/// The byte offset of a site's value in valid JSON text (the top-level object's member
/// `site.key`, its element `entry`, that element's element `field`).
fn json_site(text: &str, site: Site) -> Option<usize> {
    let b = text.as_bytes();
    let mut p = skip_ws(b, 0);
    if b.get(p) != Some(&b'{') {
        return None;
    }
    p = skip_ws(b, p + 1);
    let mut value = None;
    while b.get(p) == Some(&b'"') {
        let end = skip_value(b, p)?;
        let key: String = serde_json::from_str(&text[p..end]).ok()?;
        p = skip_ws(b, end);
        p = skip_ws(b, p + 1); // the ':'
        if key == site.key {
            value = Some(p);
            break;
        }
        p = skip_ws(b, skip_value(b, p)?);
        if b.get(p) == Some(&b',') {
            p = skip_ws(b, p + 1);
        }
    }
    let mut p = value?;
    for index in [site.entry, site.field].into_iter().flatten() {
        if b.get(p) != Some(&b'[') {
            return Some(p);
        }
        p = skip_ws(b, p + 1);
        for _ in 0..index {
            p = skip_ws(b, skip_value(b, p)?);
            if b.get(p) != Some(&b',') {
                return Some(p);
            }
            p = skip_ws(b, p + 1);
        }
    }
    Some(p)
}

fn skip_ws(b: &[u8], mut p: usize) -> usize {
    while p < b.len() && b[p].is_ascii_whitespace() {
        p += 1;
    }
    p
}

/// The end of the JSON value starting at `p` (the text is valid JSON).
fn skip_value(b: &[u8], p: usize) -> Option<usize> {
    match *b.get(p)? {
        b'"' => {
            let mut q = p + 1;
            loop {
                match *b.get(q)? {
                    b'\\' => q += 2,
                    b'"' => return Some(q + 1),
                    _ => q += 1,
                }
            }
        }
        b'[' | b'{' => {
            let mut depth = 0usize;
            let mut q = p;
            loop {
                match *b.get(q)? {
                    b'"' => {
                        q = skip_value(b, q)?;
                        continue;
                    }
                    b'[' | b'{' => depth += 1,
                    b']' | b'}' => {
                        depth -= 1;
                        if depth == 0 {
                            return Some(q + 1);
                        }
                    }
                    _ => {}
                }
                q += 1;
            }
        }
        _ => {
            let mut q = p;
            while q < b.len() && !matches!(b[q], b',' | b']' | b'}') && !b[q].is_ascii_whitespace()
            {
                q += 1;
            }
            Some(q)
        }
    }
}

/// The line and column (characters, both from 1) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}

// ---------------------------------------------------------------------------------------------
// Compact text

/// The record keyword of each list, for the text form.
fn keyword(key: &str) -> &'static str {
    match key {
        "edges" => "e",
        "collinear" => "c",
        "coords" => "p",
        "directions" => "d",
        _ => "discrete",
    }
}

/// The data part of a line (before `#`, without `\r`) and its fields with their byte offsets.
fn fields(line: &str) -> (&str, Vec<(usize, &str)>) {
    let line = line.strip_suffix('\r').unwrap_or(line);
    let data = line.split('#').next().unwrap_or("");
    let mut out = Vec::new();
    let mut start = None;
    for (k, c) in data.char_indices() {
        match (c.is_whitespace(), start) {
            (false, None) => start = Some(k),
            (true, Some(s)) => {
                out.push((s, &data[s..k]));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, &data[s..]));
    }
    (data, out)
}

/// The character column (from 1) of a byte offset in a line.
fn column(data: &str, byte: usize) -> usize {
    data[..byte].chars().count() + 1
}

/// The line and column of a site in the text form, found by reading the text again (only
/// when reporting an error). `p` lines are found by their vertex, other records by their
/// order.
fn text_site(text: &str, site: Site) -> (usize, usize) {
    let word = keyword(site.key);
    let mut seen = 0usize;
    for (k, line) in text.lines().enumerate() {
        let (data, f) = fields(line);
        if f.first().map(|x| x.1) != Some(word) {
            continue;
        }
        let hit = match site.entry {
            None => true,
            Some(e) if word == "p" => f.get(1).and_then(|x| x.1.parse::<usize>().ok()) == Some(e),
            Some(e) => {
                seen += 1;
                seen == e + 1
            }
        };
        if hit {
            // The header's and `d`'s value is field 1; an entry's field j is field j + 1, a
            // point's coordinate j is field j + 2.
            let shift = if word == "p" { 2 } else { 1 };
            let at = match (site.entry, site.field) {
                (_, Some(j)) => f.get(j + shift),
                (None, None) => f.get(1),
                (Some(_), None) => f.first(),
            };
            return (k + 1, at.map_or(1, |x| column(data, x.0)));
        }
    }
    (1, 1)
}

/// Parses the compact text form; `file` names the source in error messages.
///
/// # Examples
///
/// ```
/// use mowmill::discrete::format::parse_text;
///
/// let g = parse_text("discrete 3\ne 0 1\ne 1 2 # the second edge\nc 1 0 2\n", "g.dm")?;
/// assert_eq!(g.edge_count(), 2);
/// let e = parse_text("discrete 3\ne 0 1\ne 1 0\n", "g.dm").unwrap_err();
/// assert_eq!(e.to_string(), "g.dm:3:3: edge 1 0 is also at line 2; expected each edge once");
/// # Ok::<(), mowmill::error::Error>(())
/// ```
pub fn parse_text(text: &str, file: &str) -> Result<Discrete> {
    let err = |line: usize, col: usize, msg: String| Error::parse(file, line, col, msg);
    let mut n: Option<u64> = None;
    let mut edges: Vec<[u32; 2]> = Vec::new();
    let mut collinear: Vec<[u32; 3]> = Vec::new();
    let mut coords: Option<Vec<[f64; 3]>> = None;
    let mut coord_count = 0usize;
    let mut first_p_line = 0usize;
    let mut directions: Option<(u32, usize)> = None;
    let mut last_line = 1;
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        last_line = line_no;
        let (data, f) = fields(line);
        let Some(&(_, word)) = f.first() else {
            continue;
        };
        let col = |byte: usize| column(data, byte);
        let Some(n) = n else {
            // The header.
            if word != "discrete" {
                return Err(err(
                    line_no,
                    1,
                    format!(
                        "'{}' before the header; expected the header 'discrete N' (N the \
                         number of vertices) first",
                        shorten(word)
                    ),
                ));
            }
            let value = header_value(&f, data).map_err(|(c, m)| err(line_no, c, m))?;
            if value == 0 || value > MAX_VERTICES as u64 {
                return Err(err(
                    line_no,
                    col(f[1].0),
                    format!(
                        "{value} vertices; expected from 1 to {MAX_VERTICES} (the vertex limit)"
                    ),
                ));
            }
            let _ = n.insert(value);
            continue;
        };
        let (form, arity): (&str, &[&str]) = match word {
            "e" => ("e a b", &["a", "b"]),
            "c" => ("c v a b", &["v", "a", "b"]),
            "p" => ("p v x y [z]", &["v", "x", "y", "z"]),
            "d" => ("d D", &["D"]),
            "discrete" => {
                return Err(err(
                    line_no,
                    1,
                    "a second header; expected one 'discrete N' line, at the top".to_string(),
                ));
            }
            other => {
                return Err(err(
                    line_no,
                    1,
                    format!(
                        "unknown record '{}'; expected 'e a b', 'c v a b', 'p v x y [z]' or 'd D'",
                        shorten(other)
                    ),
                ));
            }
        };
        let min = if word == "p" { 3 } else { arity.len() };
        if f.len() - 1 < min {
            return Err(err(
                line_no,
                col(data.trim_end().len()),
                format!("missing {}; expected '{form}'", arity[f.len() - 1]),
            ));
        }
        if f.len() - 1 > arity.len() {
            let (at, extra) = f[arity.len() + 1];
            return Err(err(
                line_no,
                col(at),
                format!("unexpected field '{}'; expected '{form}'", shorten(extra)),
            ));
        }
        let vertex = |j: usize| -> Result<u32> {
            let (at, w) = f[j];
            let v: u64 = w.parse().map_err(|_| {
                err(
                    line_no,
                    col(at),
                    format!(
                        "'{}' is not a vertex index; expected an integer from 0 to {}",
                        shorten(w),
                        n - 1
                    ),
                )
            })?;
            if v >= n {
                return Err(err(line_no, col(at), outside(v, n)));
            }
            Ok(v as u32)
        };
        match word {
            "e" => {
                if edges.len() == MAX_EDGES {
                    return Err(err(
                        line_no,
                        1,
                        format!("more than {MAX_EDGES} edges; expected at most {MAX_EDGES}"),
                    ));
                }
                edges.push([vertex(1)?, vertex(2)?]);
            }
            "c" => {
                if collinear.len() == MAX_EDGES {
                    return Err(err(
                        line_no,
                        1,
                        format!(
                            "more than {MAX_EDGES} collinear pairs; expected at most {MAX_EDGES}"
                        ),
                    ));
                }
                collinear.push([vertex(1)?, vertex(2)?, vertex(3)?]);
            }
            "p" => {
                let v = vertex(1)?;
                let mut point = [0.0; 3];
                for (j, &(at, w)) in f[2..].iter().enumerate() {
                    point[j] = match w.parse::<f64>() {
                        Ok(x) if x.is_finite() => x,
                        _ => {
                            return Err(err(
                                line_no,
                                col(at),
                                format!(
                                    "'{}' is not a coordinate; expected a finite decimal number",
                                    shorten(w)
                                ),
                            ));
                        }
                    };
                }
                if coords.is_none() {
                    first_p_line = line_no;
                }
                // n was checked against the limit at the header.
                let c = coords.get_or_insert_with(|| vec![[f64::NAN; 3]; n as usize]);
                if !c[v as usize][0].is_nan() {
                    let (earlier, _) = text_site(text, Site::at("coords", v as usize, 0));
                    return Err(err(
                        line_no,
                        col(f[1].0),
                        format!(
                            "vertex {v} already has coordinates on line {earlier}; expected one \
                             'p' line per vertex"
                        ),
                    ));
                }
                c[v as usize] = point;
                coord_count += 1;
            }
            _ => {
                let (at, w) = f[1];
                let d = match w.parse::<u32>() {
                    Ok(d) if d >= 1 => d,
                    _ => {
                        return Err(err(
                            line_no,
                            col(at),
                            format!(
                                "'{}' is not a number of directions; expected an integer d ≥ 1",
                                shorten(w)
                            ),
                        ));
                    }
                };
                if let Some((_, earlier)) = directions {
                    return Err(err(
                        line_no,
                        1,
                        format!("a second 'd' line (the first is line {earlier}); expected one"),
                    ));
                }
                directions = Some((d, line_no));
            }
        }
    }
    let Some(n) = n else {
        return Err(err(
            last_line,
            1,
            "no header; expected 'discrete N' (N the number of vertices)".to_string(),
        ));
    };
    if let Some(c) = &coords
        && coord_count < c.len()
    {
        let missing = c.iter().position(|p| p[0].is_nan()).unwrap_or(0);
        return Err(err(
            first_p_line,
            1,
            format!(
                "'p' lines for {coord_count} of {n} vertices (vertex {missing} has none); \
                 expected a 'p' line for every vertex or none"
            ),
        ));
    }
    let stated = Stated {
        vertices: n,
        edges,
        collinear,
        coords,
        directions: directions.map(|d| d.0),
    };
    let describe = |site: Site| format!("line {}", text_site(text, site).0);
    assemble(stated, &describe).map_err(|f| {
        let (line, column) = text_site(text, f.site);
        Error::parse(file, line, column, f.message)
    })
}

/// The N of a header line `discrete N`, or the column and message of what is wrong.
fn header_value(f: &[(usize, &str)], data: &str) -> std::result::Result<u64, (usize, String)> {
    match f {
        [_] => Err((
            column(data, data.trim_end().len()),
            "missing N; expected 'discrete N' (N the number of vertices)".to_string(),
        )),
        [_, (at, w)] => w.parse::<u64>().map_err(|_| {
            (
                column(data, *at),
                format!(
                    "'{}' is not a number of vertices; expected 'discrete N' with N from 1 to \
                     {MAX_VERTICES}",
                    shorten(w)
                ),
            )
        }),
        [_, _, (at, w), ..] => Err((
            column(data, *at),
            format!("unexpected field '{}'; expected 'discrete N'", shorten(w)),
        )),
        [] => Err((1, "expected 'discrete N'".to_string())),
    }
}

/// The compact text form (see the module documentation).
pub fn to_text(inst: &Discrete) -> String {
    let n = inst.len();
    let mut s = String::with_capacity(14 * inst.edge_count() + 40 * n + 200);
    let _ = writeln!(
        s,
        "# mowmill discrete milling instance: 'e a b' edge, 'c v a b' collinear at v, \
         'p v x y [z]' coordinates, 'd D' directions"
    );
    let _ = writeln!(s, "discrete {n}");
    if let Some(d) = inst.directions() {
        let _ = writeln!(s, "d {d}");
    }
    for (a, b) in inst.edges() {
        let _ = writeln!(s, "e {a} {b}");
    }
    for v in 0..n as u32 {
        for (a, b) in inst.collinear_pairs(v) {
            let _ = writeln!(s, "c {v} {a} {b}");
        }
    }
    if !inst.is_empty() && inst.coords(0).is_some() {
        let three = has_z(inst);
        for v in 0..n as u32 {
            let [x, y, z] = inst.coords(v).unwrap_or([0.0; 3]);
            if three {
                let _ = writeln!(s, "p {v} {} {} {}", num(x), num(y), num(z));
            } else {
                let _ = writeln!(s, "p {v} {} {}", num(x), num(y));
            }
        }
    }
    s
}

fn shorten(s: &str) -> String {
    let mut short: String = s.chars().take(24).collect();
    if short.len() < s.len() {
        short.push('…');
    }
    short
}

// ---------------------------------------------------------------------------------------------
// Walks

/// A set of closed walks of a discrete instance (a tour when it has one walk), and its file.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DiscreteCover {
    pub cycles: Vec<VertexWalk>,
}

#[derive(Serialize, Deserialize)]
enum Model {
    #[serde(rename = "discrete")]
    Discrete,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct CoverJson {
    model: Model,
    cycles: Vec<VertexWalk>,
}

impl DiscreteCover {
    pub fn new(cycles: Vec<VertexWalk>) -> DiscreteCover {
        DiscreteCover { cycles }
    }

    /// The walk file's JSON, `{"model":"discrete","cycles":[[v,...],...]}`.
    pub fn to_json(&self) -> String {
        let file = CoverJson {
            model: Model::Discrete,
            cycles: self.cycles.clone(),
        };
        serde_json::to_string(&file).expect("walks always serialize")
    }

    /// Reads a walk file; `name` names the source in error messages.
    pub fn from_json(text: &str, name: &str) -> Result<DiscreteCover> {
        let file: CoverJson = serde_json::from_str(text).map_err(|e| {
            Error::parse(
                name,
                e.line(),
                e.column(),
                format!(
                    "expected discrete walks {{\"model\": \"discrete\", \"cycles\": [[v, ...], \
                     ...]}}: {e}"
                ),
            )
        })?;
        Ok(DiscreteCover {
            cycles: file.cycles,
        })
    }

    pub fn read(path: &Path) -> Result<DiscreteCover> {
        let bytes = crate::input::read_bytes(path, "a discrete instance or tour file")?;
        let name = path.display().to_string();
        DiscreteCover::from_json(&utf8_text(bytes, &name)?, &name)
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_json() + "\n").map_err(|e| Error::io(path, e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::Region;

    fn sample() -> Discrete {
        let mut g = Discrete::new(
            4,
            &[(0, 1), (1, 2), (2, 3), (3, 0), (1, 3)],
            &[(1, 0, 2), (3, 2, 0)],
            Some(vec![
                [0.0, 0.0, 0.0],
                [1.5, 0.0, 0.0],
                [1.0, -2.25, 0.0],
                [1e-7, 3.0, 0.0],
            ]),
        )
        .unwrap();
        g.set_directions(Some(3));
        g
    }

    #[test]
    fn both_forms_round_trip() {
        let mut z = sample();
        z.set_coords(Some(vec![[0.0, 0.0, 1.0]; 4])).unwrap();
        let mut bare = Discrete::new(2, &[(0, 1)], &[], None).unwrap();
        bare.set_directions(None);
        let region = Discrete::from_region(&Region::from_ascii("###\n#.#\n###\n"));
        for g in [sample(), z, bare, region] {
            let j = to_json(&g);
            let back = parse_json(&j, "g.json").unwrap();
            assert_eq!(back, g, "{j}");
            assert_eq!(to_json(&back), j);
            let t = to_text(&g);
            let back = parse_text(&t, "g.dm").unwrap();
            assert_eq!(back, g, "{t}");
            assert_eq!(to_text(&back), t);
            assert_eq!(parse_discrete(&j, "x").unwrap(), g);
            assert_eq!(parse_discrete(&t, "x").unwrap(), g);
        }
    }

    #[test]
    fn generated_instances_round_trip() {
        use crate::discrete::generate::*;
        for seed in 0..4 {
            let params = PlaneParams::default();
            for g in [
                random_voxels(60, seed, 1).unwrap().to_discrete(),
                random_hex(40, seed).unwrap().to_discrete(),
                random_honeycomb(40, seed).unwrap().to_discrete(),
                random_plane_graph(40, seed, &params).unwrap(),
            ] {
                let (j, t) = (to_json(&g), to_text(&g));
                assert_eq!(parse_json(&j, "g.json").unwrap(), g);
                assert_eq!(parse_text(&t, "g.dm").unwrap(), g);
            }
        }
    }

    #[test]
    fn the_text_form_is_as_documented() {
        let t = to_text(&sample());
        let body: Vec<&str> = t.lines().skip(1).collect();
        assert_eq!(
            body,
            [
                "discrete 4",
                "d 3",
                "e 0 1",
                "e 0 3",
                "e 1 2",
                "e 1 3",
                "e 2 3",
                "c 1 0 2",
                "c 3 0 2",
                "p 0 0 0",
                "p 1 1.5 0",
                "p 2 1 -2.25",
                "p 3 0.0000001 3",
            ]
        );
        let j = to_json(&sample());
        assert_eq!(
            j,
            "{\"vertices\": 4,\n \"edges\": [[0,1],[0,3],[1,2],[1,3],[2,3]],\n \"collinear\": \
             [[1,0,2],[3,0,2]],\n \"coords\": [[0,0],[1.5,0],[1,-2.25],[0.0000001,3]],\n \
             \"directions\": 3}\n"
        );
        // Comments, blank lines, CRLF, any record order, 3-D points mixed with 2-D.
        let g = parse_text(
            "# c\n\r\n discrete 3 # three\r\nc 1 2 0\np 2 1 2 3\ne 1 2\ne 0 1\np 0 0 0\np 1 1 1\n",
            "t.dm",
        )
        .unwrap();
        assert_eq!(g.turn(0, 1, 2), 0);
        assert_eq!(g.coords(2), Some([1.0, 2.0, 3.0]));
        assert_eq!(g.directions(), None);
    }

    /// Each bad file gives `file:line:col: message-start`.
    #[test]
    fn text_errors_name_line_and_column() {
        let cases = [
            ("", "1:1: no header"),
            ("e 0 1\n", "1:1: 'e' before the header"),
            ("discrete\n", "1:9: missing N"),
            ("discrete x\n", "1:10: 'x' is not a number of vertices"),
            (
                "discrete 0\n",
                "1:10: 0 vertices; expected from 1 to 50000000",
            ),
            ("discrete 50000001\n", "1:10: 50000001 vertices"),
            ("discrete 3 4\n", "1:12: unexpected field '4'"),
            ("discrete 3\ndiscrete 3\n", "2:1: a second header"),
            ("discrete 3\nf 0 1\n", "2:1: unknown record 'f'"),
            ("discrete 3\ne 0\n", "2:4: missing b; expected 'e a b'"),
            ("discrete 3\ne 0 1 2\n", "2:7: unexpected field '2'"),
            ("discrete 3\ne 0 -1\n", "2:5: '-1' is not a vertex index"),
            ("discrete 3\n\ne  0 3\n", "3:6: vertex 3 is outside 0..3"),
            ("discrete 3\ne 1 1\n", "2:5: edge 1 1 is a loop"),
            (
                "discrete 3\ne 0 1\ne 1 2\ne 2 1\n",
                "4:3: edge 2 1 is also at line 3",
            ),
            ("discrete 3\nc 1 0 2\n", "2:5: 1 0 is not an edge"),
            ("discrete 3\ne 0 1\nc 1 0 2\n", "3:7: 1 2 is not an edge"),
            (
                "discrete 3\ne 0 1\ne 1 2\nc 1 0 0\n",
                "4:7: collinear pair 0 0 at vertex 1 names one edge twice",
            ),
            (
                "discrete 3\ne 0 1\ne 1 2\nc 1 0 2\n# again\nc 1 2 0\n",
                "6:5: edge 1 2 is also in the collinear pair at line 4",
            ),
            ("discrete 3\nc 1 0\n", "2:6: missing b; expected 'c v a b'"),
            (
                "discrete 3\np 0 1\n",
                "2:6: missing y; expected 'p v x y [z]'",
            ),
            ("discrete 3\np 0 1 inf\n", "2:7: 'inf' is not a coordinate"),
            ("discrete 3\np 0 1 2 3 4\n", "2:11: unexpected field '4'"),
            (
                "discrete 2\np 0 1 2\np 0 1 2\n",
                "3:3: vertex 0 already has coordinates on line 2",
            ),
            (
                "discrete 3\ne 0 1\np 2 0 0\np 0 0 0\n",
                "3:1: 'p' lines for 2 of 3 vertices (vertex 1 has none)",
            ),
            (
                "discrete 3\nd 0\n",
                "2:3: '0' is not a number of directions",
            ),
            (
                "discrete 3\nd 2\nd 2\n",
                "3:1: a second 'd' line (the first is line 2)",
            ),
        ];
        let wrong: Vec<String> = cases
            .iter()
            .map(|(text, expected)| {
                (
                    text,
                    expected,
                    parse_text(text, "t.dm").unwrap_err().to_string(),
                )
            })
            .filter(|(_, expected, e)| !e.starts_with(&format!("t.dm:{expected}")))
            .map(|(text, _, e)| format!("{text:?}: {e}"))
            .collect();
        assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    }

    #[test]
    fn json_errors_name_line_and_column() {
        let cases = [
            (
                "{\"vertices\": 3, \"edges\": []",
                "1:27: expected a discrete instance",
            ),
            ("{\"vertices\": 3}", "1:15: expected a discrete instance"),
            (
                "{\"vertices\": 3, \"edges\": [], \"extra\": 1}",
                "1:36: expected a discrete instance",
            ),
            ("{\"vertices\": 0, \"edges\": []}", "1:14: 0 vertices"),
            (
                "{\"edges\": [[0, 1],\n  [1, 5]], \"vertices\": 3}",
                "2:7: vertex 5 is outside 0..3",
            ),
            (
                "{\"vertices\": 3,\n \"edges\": [[0, 1], [1, 2],\n  [2, 1]]}",
                "3:4: edge 2 1 is also at edges[1] (line 2)",
            ),
            (
                "{\"vertices\": 3, \"edges\": [[0,1],[1,2]], \"collinear\": [[1, 0, 2], [1, 2, 0]]}",
                "1:70: edge 1 2 is also in the collinear pair at collinear[0] (line 1)",
            ),
            (
                "{\"vertices\": 3, \"edges\": [[0,1]], \"collinear\": [[1, 0, 2]]}",
                "1:56: 1 2 is not an edge",
            ),
            (
                "{\"vertices\": 2, \"edges\": [[0,1]], \"coords\": [[0, 0]]}",
                "1:45: 1 coordinates for 2 vertices",
            ),
            (
                "{\"vertices\": 2, \"edges\": [[0,1]], \"coords\": [[0, 0], [1]]}",
                "1:54: a point of 1 numbers",
            ),
            (
                "{\"vertices\": 2, \"edges\": [[0,1]], \"directions\": 0}",
                "1:49: 0 directions",
            ),
            (
                "{\"vertices\": 3, \"edges\": [[0, 1], [2, 2]]}",
                "1:39: edge 2 2 is a loop",
            ),
        ];
        let wrong: Vec<String> = cases
            .iter()
            .map(|(text, expected)| {
                (
                    text,
                    expected,
                    parse_json(text, "t.json").unwrap_err().to_string(),
                )
            })
            .filter(|(_, expected, e)| !e.starts_with(&format!("t.json:{expected}")))
            .map(|(text, _, e)| format!("{text}: {e}"))
            .collect();
        assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    }

    #[test]
    fn json_sites_are_found_past_strings_and_nesting() {
        let text = r#"{"a": {"edges": [1]}, "s": "x\"]}", "edges" : [ [0, 1] , [2,  3] ]}"#;
        let at = json_site(text, Site::at("edges", 1, 1)).unwrap();
        assert_eq!(&text[at..at + 1], "3");
        let at = json_site(text, Site::key("edges")).unwrap();
        assert_eq!(&text[at..at + 3], "[ [");
    }

    #[test]
    fn walk_files_round_trip_and_refuse_other_models() {
        let c = DiscreteCover::new(vec![vec![0, 1, 2], vec![3]]);
        let s = c.to_json();
        assert_eq!(s, r#"{"model":"discrete","cycles":[[0,1,2],[3]]}"#);
        assert_eq!(DiscreteCover::from_json(&s, "w.json").unwrap(), c);
        for (text, expected) in [
            (
                r#"{"cycles": [[0]]}"#,
                "w.json:1:17: expected discrete walks",
            ),
            (r#"{"model": "grid", "cycles": []}"#, "w.json:1:16:"),
            (
                r#"{"model": "discrete", "cycles": [[0, -1]]}"#,
                "w.json:1:39:",
            ),
            (
                r#"{"model": "discrete", "cycles": [], "x": 0}"#,
                "w.json:1:39:",
            ),
        ] {
            let e = DiscreteCover::from_json(text, "w.json")
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(expected), "{text}: {e}");
        }
    }

    #[test]
    fn files_are_told_apart_by_extension_and_content() {
        let dir = std::env::temp_dir().join(format!("mowmill-dm-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let g = sample();
        for name in ["g.json", "g.dm", "g.txt"] {
            let path = dir.join(name);
            write_discrete(&g, &path).unwrap();
            assert_eq!(read_discrete(&path).unwrap(), g, "{name}");
        }
        // A .dm file holding JSON is read as text, and says so.
        std::fs::write(dir.join("j.dm"), to_json(&g)).unwrap();
        let e = read_discrete(&dir.join("j.dm")).unwrap_err().to_string();
        assert!(
            e.contains("j.dm:1:1: '{\"vertices\":' before the header"),
            "{e}"
        );
        let w = DiscreteCover::new(vec![vec![0, 1, 2, 3]]);
        w.write(&dir.join("w.json")).unwrap();
        assert_eq!(DiscreteCover::read(&dir.join("w.json")).unwrap(), w);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
