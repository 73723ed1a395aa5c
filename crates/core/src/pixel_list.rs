//! Pixel lists: one `x y` pair per line, the `.gg` / `.csv` files of the published turn-cost
//! studies.
//!
//! Text, one pixel per line, y growing upward (as in [`Region`], so nothing is mirrored). `#`
//! starts a comment that runs to the end of the line; blank lines are skipped. The two integers
//! are separated by whitespace or by one comma (with optional whitespace around it), and a first
//! line of two fields that are not numbers, such as `x,y`, is taken as a header and skipped.
//! Coordinates are written as in WKT (`3`, `-2`, `+3`, `3.0`, `1e1`), must be integers and lie
//! within ±[`MAX_COORD`](crate::region::MAX_COORD) (|x|, |y| < 2^30); negative coordinates are
//! allowed.
//!
//! Coordinates are kept as written, not moved to the origin: [`Region`] stores any such
//! coordinates (as the WKT reader keeps its own), so tours and drawings of a pixel list speak of
//! the pixels the file names, and a tour another program computed for the file is checked
//! against it as it is. Writing ([`to_pixel_list`]) lists the pixels of a region in index order,
//! so reading a list and writing it gives the same pairs.
//!
//! Refused, with the file, line and column: a line without exactly two fields, a coordinate
//! that is not an integer or lies beyond the coordinate limit, a pixel listed twice (the message names
//! both lines: a repeated pixel is more likely a mistake in the file than a request), a file
//! without pixels, and more than [`MAX_PIXELS`] lines of pixels (before the list grows past
//! the limit). A disconnected pixel set is read as the `.grid` reader reads one: as it is,
//! for the algorithms to accept or refuse.

use crate::error::{Error, Result};
use crate::region::{MAX_PIXELS, Pixel, Region};
use std::fmt::Write as _;

/// Parses a pixel list into a region; `file` names the source in error messages.
///
/// # Complexity
///
/// O(T + N log N) time and O(N) space for T characters and N pixels.
///
/// # Examples
///
/// ```
/// use mowmill_core::pixel_list::parse_pixel_list;
/// use mowmill_core::{Pixel, Region};
///
/// let r = parse_pixel_list("x,y\n0,0\n1, 0 # right of it\n0 1\n", "l.csv").unwrap();
/// assert_eq!(r.pixels(), &[Pixel::new(0, 0), Pixel::new(1, 0), Pixel::new(0, 1)]);
///
/// let e = parse_pixel_list("0 0\n1 0\n0 0\n", "l.gg").unwrap_err();
/// assert_eq!(e.to_string(), "l.gg:3:1: pixel (0, 0) is also on line 1; expected each pixel once");
/// ```
pub fn parse_pixel_list(text: &str, file: &str) -> Result<Region> {
    let error =
        |line: usize, column: usize, message: String| Error::parse(file, line, column, message);
    let mut pixels: Vec<(Pixel, usize)> = Vec::new();
    let mut first_data = true;
    let mut last_line = 1;
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        last_line = line_no;
        let data = line.split('#').next().unwrap_or("");
        let Some(fields) = fields(data) else {
            continue;
        };
        let header = first_data && fields.len() == 2 && fields.iter().all(|f| !looks_numeric(f.1));
        first_data = false;
        if header {
            continue;
        }
        let column = |byte: usize| data[..byte].chars().count() + 1;
        match fields.len() {
            2 => {}
            1 => {
                let (at, word) = fields[0];
                return Err(error(
                    line_no,
                    column(at + word.len()),
                    format!(
                        "missing y after x = {}; expected two integers x y",
                        shorten(word)
                    ),
                ));
            }
            _ => {
                let (at, word) = fields[2];
                return Err(error(
                    line_no,
                    column(at),
                    format!(
                        "unexpected third field {}; expected exactly two integers x y per line",
                        quote(word)
                    ),
                ));
            }
        }
        let mut xy = [0i32; 2];
        for (slot, &(at, word)) in xy.iter_mut().zip(&fields) {
            *slot = coordinate(word).map_err(|m| error(line_no, column(at), m))?;
        }
        if pixels.len() == MAX_PIXELS {
            return Err(error(
                line_no,
                1,
                format!(
                    "more than {MAX_PIXELS} pixels; expected at most {MAX_PIXELS} (the pixel limit)"
                ),
            ));
        }
        pixels.push((Pixel::new(xy[0], xy[1]), line_no));
    }
    if pixels.is_empty() {
        return Err(error(
            last_line,
            1,
            "empty region: expected at least one line x y".to_string(),
        ));
    }
    // A repeated pixel is reported at its earliest repetition, naming the line it repeats.
    pixels.sort_unstable_by_key(|&(p, line)| (p.y, p.x, line));
    if let Some((p, first, again)) = pixels
        .windows(2)
        .filter(|w| w[0].0 == w[1].0)
        .map(|w| (w[0].0, w[0].1, w[1].1))
        .min_by_key(|&(_, _, again)| again)
    {
        return Err(error(
            again,
            1,
            format!("pixel {p} is also on line {first}; expected each pixel once"),
        ));
    }
    Region::from_pixels(pixels.into_iter().map(|(p, _)| p))
}

/// Writes a region as a pixel list: two comment lines, then one `x y` line per pixel in index
/// order (bottom row first, left to right), which [`parse_pixel_list`] reads back to `region`.
///
/// # Examples
///
/// ```
/// use mowmill_core::pixel_list::to_pixel_list;
/// use mowmill_core::Region;
///
/// let text = to_pixel_list(&Region::from_ascii("#.\n##\n"));
/// assert!(text.ends_with("\n0 0\n1 0\n0 1\n"));
/// ```
pub fn to_pixel_list(region: &Region) -> String {
    let mut out = String::with_capacity(16 * region.len() + 100);
    out.push_str("# mowmill pixel list: one pixel \"x y\" per line, y grows upward\n");
    let _ = writeln!(out, "# {} pixels", region.len());
    for p in region.pixels() {
        let _ = writeln!(out, "{} {}", p.x, p.y);
    }
    out
}

/// The first three fields of a line (byte offset, text), enough to judge it: split at commas
/// if the line has one, else at whitespace; `None` for a blank line. Empty fields are kept, to
/// be refused as numbers.
fn fields(data: &str) -> Option<Vec<(usize, &str)>> {
    if data.trim().is_empty() {
        return None;
    }
    let mut out = Vec::new();
    if data.contains(',') {
        let mut start = 0;
        for part in data.split(',').take(3) {
            let lead = part.len() - part.trim_start().len();
            out.push((start + lead, part.trim()));
            start += part.len() + 1;
        }
    } else {
        let mut rest = data;
        let mut start = 0;
        loop {
            let lead = rest.len() - rest.trim_start().len();
            start += lead;
            rest = &rest[lead..];
            if rest.is_empty() || out.len() == 3 {
                break;
            }
            let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
            out.push((start, &rest[..len]));
            start += len;
            rest = &rest[len..];
        }
    }
    Some(out)
}

/// Whether a field starts like a number (a header line has none).
fn looks_numeric(field: &str) -> bool {
    field
        .trim_start_matches(['+', '-'])
        .starts_with(|c: char| c.is_ascii_digit() || c == '.')
}

/// A pixel coordinate, or the message saying what is wrong with it.
fn coordinate(word: &str) -> std::result::Result<i32, String> {
    use crate::wkt::lexer::{NumberValue, number_value};
    if word.is_empty() {
        return Err("empty field; expected an integer coordinate".to_string());
    }
    match number_value(word) {
        NumberValue::Integer(v) => {
            crate::region::pixel_coordinate(v).map_err(|_| out_of_range(word))
        }
        NumberValue::OutOfRange => Err(out_of_range(word)),
        NumberValue::Fraction => Err(format!(
            "coordinate {} is not an integer; expected integer pixel coordinates",
            shorten(word)
        )),
        NumberValue::Malformed => Err(format!(
            "{} is not a number; expected an integer coordinate",
            quote(word)
        )),
    }
}

fn out_of_range(word: &str) -> String {
    crate::region::coordinate_out_of_range(&shorten(word))
}

fn shorten(s: &str) -> String {
    let mut short: String = s.chars().take(24).collect();
    if short.len() < s.len() {
        short.push('…');
    }
    short
}

fn quote(s: &str) -> String {
    format!("'{}'", shorten(s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separators_headers_and_comments() {
        let want =
            Region::from_pixels([Pixel::new(-1, 0), Pixel::new(0, 0), Pixel::new(0, 1)]).unwrap();
        for text in [
            "-1 0\n0 0\n0 1\n",
            "# comment\n\n-1\t0\r\n 0  0 \n0 1 # note\n",
            "x,y\n-1,0\n0 , 0\n0,1\n",
            "X Y\n-1 0\n0 0\n0 1",
            "-1.0 0\n0 0e0\n+0 1\n",
        ] {
            assert_eq!(parse_pixel_list(text, "t.gg").unwrap(), want, "{text:?}");
        }
        let text = to_pixel_list(&want);
        assert!(text.ends_with("# 3 pixels\n-1 0\n0 0\n0 1\n"), "{text}");
        assert_eq!(parse_pixel_list(&text, "t.gg").unwrap(), want);
    }

    #[test]
    fn errors_name_line_and_column() {
        let cases = [
            ("0 0\n1\n", "2:2: missing y after x = 1"),
            ("0 0\n1,\n", "2:3: empty field"),
            ("0 0\n1 2 3\n", "2:5: unexpected third field '3'"),
            ("0 0\n1 0.5\n", "2:3: coordinate 0.5 is not an integer"),
            ("0 0\n1 y\n", "2:3: 'y' is not a number"),
            ("x,y\nx,y\n", "2:1: 'x' is not a number"),
            (
                "0 0\n2147483648 0\n",
                "2:1: coordinate 2147483648 is out of range",
            ),
            ("0 0\n1 1e40\n", "2:3: coordinate 1e40 is out of range"),
            // The coordinate limit, where a step or a difference would wrap an i32.
            (
                "0 0\n1073741824 0\n",
                "2:1: coordinate 1073741824 is out of range",
            ),
            (
                "0 0\n0 -1073741824\n",
                "2:3: coordinate -1073741824 is out of range",
            ),
            ("# none\n\n", "2:1: empty region"),
            (
                "5 5\n0 0\n1 1\n0 0\n5 5\n",
                "4:1: pixel (0, 0) is also on line 2",
            ),
        ];
        for (text, expected) in cases {
            let e = parse_pixel_list(text, "p.gg").unwrap_err().to_string();
            assert!(e.starts_with(&format!("p.gg:{expected}")), "{text:?}: {e}");
        }
    }
}
