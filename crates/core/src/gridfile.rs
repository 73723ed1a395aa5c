//! The `.grid` text format, mowmill's native instance format.
//!
//! UTF-8 text. Lines starting with `;` are comments; by convention `; key: value` comments
//! carry metadata (`; family: donut`, `; seed: 7`). Every other line is one row of pixels: the
//! first row is the highest y and the last row is y = 0; `#` is a pixel of the region and `.`
//! an empty cell; x is the column index from 0, and rows may differ in length (missing cells
//! are empty). A trailing `\r` is ignored, so files edited on Windows read the same. A file
//! with more than [`MAX_PIXELS`] pixels is refused before its pixels are collected.
//!
//! Writing puts the comments first, then every row from the highest y down to y = 0, each
//! padded with `.` to the width of the bounding box, so files the generator writes read back
//! and write again byte for byte.

use crate::error::{Error, Result};
use crate::region::{MAX_COORD, MAX_PIXELS, Pixel, Region};
use std::path::Path;

/// A `.grid` picture is written only up to this many bytes, or 64 per pixel if that is more:
/// a sparse region (a long diagonal band) would otherwise ask for gigabytes.
pub const MAX_PICTURE_BYTES: usize = 1 << 27;

/// A parsed `.grid` file: its comment lines (the text after `;`, verbatim) and its region.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridFile {
    pub comments: Vec<String>,
    pub region: Region,
}

impl GridFile {
    /// A file holding `region` with `; key: value` metadata comments, in order.
    pub fn with_meta(region: Region, meta: &[(&str, String)]) -> GridFile {
        let comments = meta.iter().map(|(k, v)| format!(" {k}: {v}")).collect();
        GridFile { comments, region }
    }

    /// The value of the first `; key: value` comment, trimmed.
    pub fn meta(&self, key: &str) -> Option<&str> {
        self.comments.iter().find_map(|c| {
            let (k, v) = c.split_once(':')?;
            (k.trim() == key).then(|| v.trim())
        })
    }

    /// All `; key: value` comments as pairs, in file order.
    pub fn meta_pairs(&self) -> Vec<(String, String)> {
        self.comments
            .iter()
            .filter_map(|c| c.split_once(':'))
            .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
            .collect()
    }

    /// Parses `.grid` text; `file` names the source in error messages. An empty region is an
    /// error.
    pub fn parse(text: &str, file: &str) -> Result<GridFile> {
        let mut comments = Vec::new();
        let mut rows: Vec<(usize, &str)> = Vec::new();
        for (k, line) in text.lines().enumerate() {
            let line = line.strip_suffix('\r').unwrap_or(line);
            match line.strip_prefix(';') {
                Some(c) => comments.push(c.to_string()),
                None => rows.push((k + 1, line)),
            }
        }
        // Check every character and refuse an over-large region before allocating anything
        // proportional to it.
        let mut count = 0usize;
        for (line_no, row) in &rows {
            if let Some(k) = row.bytes().position(|b| b != b'#' && b != b'.') {
                // Every byte before k is ASCII, so k + 1 is the character column.
                let other = row[k..].chars().next().unwrap_or(' ');
                return Err(Error::parse(
                    file,
                    *line_no,
                    k + 1,
                    format!(
                        "unexpected character {other:?}: expected '#' (pixel), '.' (empty) or a \
                         comment line starting with ';'"
                    ),
                ));
            }
            let in_row = row.bytes().filter(|&b| b == b'#').count();
            if count + in_row > MAX_PIXELS {
                let column = row
                    .bytes()
                    .enumerate()
                    .filter(|&(_, b)| b == b'#')
                    .nth(MAX_PIXELS - count)
                    .map_or(1, |(k, _)| k + 1);
                return Err(Error::parse(
                    file,
                    *line_no,
                    column,
                    format!(
                        "more than {MAX_PIXELS} pixels; expected at most {MAX_PIXELS} '#' (the \
                         pixel limit)"
                    ),
                ));
            }
            count += in_row;
        }
        // Bottom row first, so that the pixels come in index order.
        let mut pixels = Vec::with_capacity(count);
        for (y, (line_no, row)) in rows.iter().rev().enumerate() {
            let y = i32::try_from(y)
                .ok()
                .filter(|&y| y <= MAX_COORD)
                .ok_or_else(|| {
                    Error::parse(
                        file,
                        *line_no,
                        1,
                        format!(
                            "more than {MAX_COORD} rows; expected at most the coordinate limit"
                        ),
                    )
                })?;
            for (col, _) in row.bytes().enumerate().filter(|&(_, b)| b == b'#') {
                let x = i32::try_from(col)
                    .ok()
                    .filter(|&x| x <= MAX_COORD)
                    .ok_or_else(|| {
                        Error::parse(
                            file,
                            *line_no,
                            col + 1,
                            format!(
                                "column beyond {MAX_COORD} (the coordinate limit); expected a \
                                 narrower row"
                            ),
                        )
                    })?;
                pixels.push(Pixel::new(x, y));
            }
        }
        if pixels.is_empty() {
            return Err(Error::parse(
                file,
                rows.first().map_or(1, |r| r.0),
                1,
                "empty region: expected at least one '#' pixel",
            ));
        }
        let region =
            Region::from_pixels(pixels).map_err(|e| Error::parse(file, 1, 1, e.to_string()))?;
        Ok(GridFile { comments, region })
    }

    /// Reads a `.grid` file.
    pub fn read(path: &Path) -> Result<GridFile> {
        let bytes = crate::input::read_bytes(path, "an instance file")?;
        GridFile::from_bytes(bytes, &path.display().to_string())
    }

    /// Parses the bytes of a `.grid` file (which must be UTF-8); `name` names the source in
    /// error messages.
    pub fn from_bytes(bytes: Vec<u8>, name: &str) -> Result<GridFile> {
        GridFile::parse(&utf8_text(bytes, name)?, name)
    }

    /// The file's text. Fails when the region has pixels at negative coordinates (translate it
    /// with [`Region::normalized`] first).
    pub fn to_text(&self) -> Result<String> {
        let mut s = String::new();
        for c in &self.comments {
            s.push(';');
            s.push_str(c);
            s.push('\n');
        }
        if self.region.is_empty() {
            return Ok(s);
        }
        let b = self.region.bbox();
        if b.min_x < 0 || b.min_y < 0 {
            return Err(Error::invalid(format!(
                "the .grid format needs non-negative coordinates, but the region reaches ({}, {})",
                b.min_x, b.min_y
            )));
        }
        let bytes = (b.max_x as usize + 2) * (b.max_y as usize + 1);
        if bytes > MAX_PICTURE_BYTES.max(64 * self.region.len()) {
            return Err(Error::invalid(format!(
                "the .grid picture of this region would take {bytes} bytes for {} pixels (its \
                 bounding box, {} x {}, is mostly empty): write a pixel list (.gg) or WKT instead",
                self.region.len(),
                b.max_x + 1,
                b.max_y + 1
            )));
        }
        s.reserve(bytes);
        for y in (0..=b.max_y).rev() {
            for x in 0..=b.max_x {
                s.push(if self.region.contains(Pixel::new(x, y)) {
                    '#'
                } else {
                    '.'
                });
            }
            s.push('\n');
        }
        Ok(s)
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_text()?).map_err(|e| Error::io(path, e))
    }
}

/// The bytes of a text file as a string, or an error at the line and column of the first byte
/// that is not UTF-8 (the column counts bytes on that line).
pub fn utf8_text(bytes: Vec<u8>, name: &str) -> Result<String> {
    String::from_utf8(bytes).map_err(|e| {
        let upto = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = upto.iter().filter(|&&b| b == b'\n').count() + 1;
        let col = upto.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
        Error::parse(name, line, col, "invalid UTF-8: expected a UTF-8 text file")
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn parse_rows_from_the_top() {
        let f = GridFile::parse("; family: test\n; seed: 7\n#..\n##\n", "a.grid").unwrap();
        assert_eq!(f.meta("family"), Some("test"));
        assert_eq!(f.meta("seed"), Some("7"));
        assert_eq!(
            f.region.pixels(),
            &[Pixel::new(0, 0), Pixel::new(1, 0), Pixel::new(0, 1)]
        );
        assert_eq!(f.to_text().unwrap(), "; family: test\n; seed: 7\n#.\n##\n");
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = GridFile::parse("; c\n##\n#x#\n", "bad.grid").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("bad.grid:3:2: unexpected character 'x'"),
            "{e}"
        );
        let e = GridFile::parse("; only comments\n...\n", "empty.grid").unwrap_err();
        assert!(
            e.to_string().starts_with("empty.grid:2:1: empty region"),
            "{e}"
        );
        let e = GridFile::parse("", "void.grid").unwrap_err();
        assert!(e.to_string().contains("empty region"), "{e}");
    }

    #[test]
    fn empty_rows_keep_their_height() {
        let f = GridFile::parse("#\n\n", "a.grid").unwrap();
        assert_eq!(f.region.pixels(), &[Pixel::new(0, 1)]);
        assert_eq!(f.to_text().unwrap(), "#\n.\n");
    }

    proptest! {
        #[test]
        fn round_trip(bits in proptest::collection::vec(any::<bool>(), 1..80), w in 1usize..9, seed in 0u64..1000) {
            let pixels: Vec<Pixel> = bits.iter().enumerate().filter(|(_, b)| **b)
                .map(|(k, _)| Pixel::new((k % w) as i32, (k / w) as i32)).collect();
            prop_assume!(!pixels.is_empty());
            let f = GridFile::with_meta(Region::from_pixels(pixels).unwrap(), &[("seed", seed.to_string())]);
            let text = f.to_text().unwrap();
            let g = GridFile::parse(&text, "t.grid").unwrap();
            prop_assert_eq!(&g.region, &f.region);
            prop_assert_eq!(g.to_text().unwrap(), text);
        }
    }
}
