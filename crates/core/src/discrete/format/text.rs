//! The compact text form (`.dm`) of a discrete instance: the line reader with line and column
//! errors, and the writer (see the parent module for the format).

use super::json::{has_z, num};
use super::{MAX_EDGES, MAX_VERTICES, Site, Stated, assemble, outside};
use crate::discrete::Discrete;
use crate::error::{Error, Result};
use std::fmt::Write as _;

/// The record keyword of each list, for the text form.
pub(super) fn keyword(key: &str) -> &'static str {
    match key {
        "edges" => "e",
        "collinear" => "c",
        "coords" => "p",
        "directions" => "d",
        _ => "discrete",
    }
}

/// The data part of a line (before `#`, without `\r`) and its fields with their byte offsets.
pub(super) fn fields(line: &str) -> (&str, Vec<(usize, &str)>) {
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
pub(super) fn column(data: &str, byte: usize) -> usize {
    data[..byte].chars().count() + 1
}

/// The line and column of a site in the text form, found by reading the text again (only
/// when reporting an error). `p` lines are found by their vertex, other records by their
/// order.
pub(super) fn text_site(text: &str, site: Site) -> (usize, usize) {
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
/// use mowmill_core::discrete::format::parse_text;
///
/// let g = parse_text("discrete 3\ne 0 1\ne 1 2 # the second edge\nc 1 0 2\n", "g.dm")?;
/// assert_eq!(g.edge_count(), 2);
/// let e = parse_text("discrete 3\ne 0 1\ne 1 0\n", "g.dm").unwrap_err();
/// assert_eq!(e.to_string(), "g.dm:3:3: edge 1 0 is also at line 2; expected each edge once");
/// # Ok::<(), mowmill_core::error::Error>(())
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
pub(super) fn header_value(
    f: &[(usize, &str)],
    data: &str,
) -> std::result::Result<u64, (usize, String)> {
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

pub(super) fn shorten(s: &str) -> String {
    let mut short: String = s.chars().take(24).collect();
    if short.len() < s.len() {
        short.push('…');
    }
    short
}
