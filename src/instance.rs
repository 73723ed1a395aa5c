//! Reading instance files: `.grid` (the native format, see [`gridfile`](crate::gridfile)) and
//! WKT polygons (see [`wkt`](crate::wkt)), chosen by extension or, failing that, by content.

use crate::error::{Error, Result};
use crate::gridfile::GridFile;
use crate::region::Region;
use std::path::Path;

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

    /// Reads a `.grid` or WKT file. Files ending in `.wkt`, or whose first word is `POLYGON`
    /// or `MULTIPOLYGON`, are read as WKT; everything else as `.grid`.
    pub fn read(path: &Path) -> Result<Instance> {
        let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
        let file = path.display().to_string();
        let name = path
            .file_stem()
            .map_or_else(|| file.clone(), |s| s.to_string_lossy().into_owned());
        let is_wkt_ext = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("wkt"));
        let head = String::from_utf8_lossy(&bytes[..bytes.len().min(64)])
            .trim_start()
            .to_ascii_uppercase();
        if is_wkt_ext || head.starts_with("POLYGON") || head.starts_with("MULTIPOLYGON") {
            let text = String::from_utf8(bytes)
                .map_err(|_| Error::parse(&file, 1, 1, "invalid UTF-8: expected WKT text"))?;
            let region = crate::wkt::parse_wkt(&text, &file)?;
            return Ok(Instance {
                name,
                region,
                meta: Vec::new(),
            });
        }
        let grid = GridFile::from_bytes(bytes, &file)?;
        let meta = grid.meta_pairs();
        Ok(Instance {
            name,
            region: grid.region,
            meta,
        })
    }
}
