//! The JSON form of a discrete instance: the serde reader, the writer, and the byte offsets
//! of a field for error messages (see the parent module for the format).

use super::{MAX_VERTICES, Site, Stated, assemble};
use crate::discrete::Discrete;
use crate::error::{Error, Result};
use serde::Deserialize;
use std::fmt::Write as _;

/// The JSON form as serde reads it (written by hand in [`to_json`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct InstanceJson {
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
/// use mowmill_core::discrete::format::parse_json;
///
/// let g = parse_json(r#"{"vertices": 3, "edges": [[0, 1], [1, 2]], "collinear": [[1, 0, 2]]}"#, "g.json")?;
/// assert_eq!(g.turn(0, 1, 2), 0);
/// let e = parse_json("{\"vertices\": 2,\n \"edges\": [[0, 1], [1, 2]]}", "g.json").unwrap_err();
/// assert_eq!(e.to_string(), "g.json:2:24: vertex 2 is outside 0..2; expected an index from 0 to 1");
/// # Ok::<(), mowmill_core::error::Error>(())
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
pub(super) fn exact_numbers(text: &str, points: &mut [Vec<f64>]) -> Option<()> {
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
pub(super) fn has_z(inst: &Discrete) -> bool {
    (0..inst.len() as u32).any(|v| inst.coords(v).is_some_and(|c| c[2] != 0.0))
}

/// A coordinate as the shortest decimal that reads back to the same `f64` (`-0` as `0`, so
/// that JSON readers that know no negative zero agree).
pub(super) fn num(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else {
        format!("{x}")
    }
}

/// The byte offset of a site's value in valid JSON text (the top-level object's member
/// `site.key`, its element `entry`, that element's element `field`).
pub(super) fn json_site(text: &str, site: Site) -> Option<usize> {
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

pub(super) fn skip_ws(b: &[u8], mut p: usize) -> usize {
    while p < b.len() && b[p].is_ascii_whitespace() {
        p += 1;
    }
    p
}

/// The end of the JSON value starting at `p` (the text is valid JSON).
pub(super) fn skip_value(b: &[u8], p: usize) -> Option<usize> {
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
pub(super) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}
