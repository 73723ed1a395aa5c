//! Reading instance files: `.grid` (the native format, see [`gridfile`](crate::gridfile)), WKT
//! polygons and `.poly` rings (see [`wkt`](crate::wkt)) and pixel lists (see
//! [`pixel_list`](crate::pixel_list)), chosen by extension or, failing that, by content.

use crate::error::Result;
use crate::gridfile::GridFile;
use crate::region::Region;
use std::path::Path;

/// The extensions [`Instance::read`] knows, each naming its format (matched in any case).
pub const EXTENSIONS: &[&str] = &["grid", "wkt", "poly", "gg", "csv"];

/// The formats of instance files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Grid,
    Wkt,
    Poly,
    PixelList,
}

impl Format {
    /// The format a file's extension names, if it names one.
    pub fn from_extension(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "grid" => Some(Format::Grid),
            "wkt" => Some(Format::Wkt),
            "poly" => Some(Format::Poly),
            "gg" | "csv" => Some(Format::PixelList),
            _ => None,
        }
    }

    /// The format of a text by its content: WKT when its first word is `POLYGON` or
    /// `MULTIPOLYGON`; else, looking at the first line that is neither blank nor a comment
    /// (starting with `#` or `;`), a pixel list when it holds two numbers (separated by
    /// whitespace or a comma) or is a header `x,y` followed by such a line, and `.poly` when it
    /// holds a count k and then 2k numbers; `.grid` otherwise. A `.grid` row is never taken for
    /// numbers: it holds only `#` and `.`.
    pub fn detect(text: &str) -> Format {
        let head = text.trim_start_matches(|c: char| c.is_whitespace() || c == '\u{feff}');
        let word: String = head
            .chars()
            .take_while(char::is_ascii_alphabetic)
            .collect::<String>()
            .to_ascii_uppercase();
        if word == "POLYGON" || word == "MULTIPOLYGON" {
            return Format::Wkt;
        }
        let mut data = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with(';'));
        let Some(first) = data.next() else {
            return Format::Grid;
        };
        let numeric = |w: &str| {
            !w.is_empty()
                && w.chars()
                    .all(|c| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'))
                && w.chars().any(|c| c.is_ascii_digit())
        };
        let pair = |line: &str| {
            let line = line.split('#').next().unwrap_or("");
            let mut fields: Box<dyn Iterator<Item = &str>> = if line.contains(',') {
                Box::new(line.split(',').map(str::trim))
            } else {
                Box::new(line.split_whitespace())
            };
            let (a, b, c) = (fields.next(), fields.next(), fields.next());
            match (a, b, c) {
                (Some(a), Some(b), None) => Some(numeric(a) && numeric(b)),
                _ => None,
            }
        };
        // Two numbers, or a header of two words and then two numbers.
        let header = pair(first) == Some(false) && first.chars().any(|c| c.is_ascii_alphabetic());
        if pair(first) == Some(true) || (header && data.next().and_then(pair) == Some(true)) {
            return Format::PixelList;
        }
        let mut words = first.split('#').next().unwrap_or("").split_whitespace();
        if let Some(k) = words.next().and_then(|w| w.parse::<u64>().ok()) {
            let mut numbers = 0u64;
            for w in words {
                if !numeric(w) {
                    return Format::Grid;
                }
                numbers += 1;
            }
            if k > 0 && numbers == k.saturating_mul(2) {
                return Format::Poly;
            }
        }
        Format::Grid
    }
}

/// A region read from a file, with its metadata (`; key: value` comments of `.grid` files).
#[derive(Clone, Debug)]
pub struct Instance {
    /// The file name without directory and extension.
    pub name: String,
    pub region: Region,
    pub meta: Vec<(String, String)>,
}

impl Instance {
    /// The value of metadata `key`, if present.
    pub fn meta(&self, key: &str) -> Option<&str> {
        self.meta
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    /// Reads an instance file in any of the [`Format`]s: by its extension (`.grid`, `.wkt`,
    /// `.poly`, `.gg` or `.csv`, in any case), else by its content ([`Format::detect`]).
    pub fn read(path: &Path) -> Result<Instance> {
        let bytes = crate::input::read_bytes(path, "an instance file")?;
        let file = path.display().to_string();
        let name = path
            .file_stem()
            .map_or_else(|| file.clone(), |s| s.to_string_lossy().into_owned());
        let text = crate::gridfile::utf8_text(bytes, &file)?;
        let format = Format::from_extension(path).unwrap_or_else(|| Format::detect(&text));
        let region = match format {
            Format::Grid => {
                let grid = GridFile::parse(&text, &file)?;
                let meta = grid.meta_pairs();
                return Ok(Instance {
                    name,
                    region: grid.region,
                    meta,
                });
            }
            Format::Wkt => crate::wkt::parse_wkt(&text, &file)?,
            Format::Poly => crate::wkt::parse_poly(&text, &file)?,
            Format::PixelList => crate::pixel_list::parse_pixel_list(&text, &file)?,
        };
        Ok(Instance {
            name,
            region,
            meta: Vec::new(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn detect_by_content() {
        let cases = [
            ("##\n#.\n", Format::Grid),
            ("; family: x\n###\n", Format::Grid),
            ("#\n", Format::Grid),
            ("", Format::Grid),
            ("  polygon ((0 0, 1 0, 1 1, 0 1, 0 0))", Format::Wkt),
            (
                "\u{feff}MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)))",
                Format::Wkt,
            ),
            ("# pixels\n0 0\n1 0\n", Format::PixelList),
            ("x,y\n0,0\n", Format::PixelList),
            ("-3, 4\n", Format::PixelList),
            ("4 0 0 1 0 1 1 0 1\n", Format::Poly),
            ("# ring\n\n4 0 0 1 0 1 1 0 1 # closed\n", Format::Poly),
            // Neither: read as .grid, which names the first character it cannot take.
            ("4 0 0 1 0 1 1\n", Format::Grid),
            ("1 2 3 4\n", Format::Grid),
            ("1 2 3\n", Format::Poly),
        ];
        for (text, want) in cases {
            assert_eq!(Format::detect(text), want, "{text:?}");
        }
    }
}
