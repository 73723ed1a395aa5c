//! Closed walks, cycle covers and tours, and their JSON file format.
//!
//! A closed walk is a sequence of pixels, consecutive ones 4-adjacent and the last adjacent to
//! the first; a single pixel is a walk of length 0. A cycle cover is a set of closed walks; a
//! tour is a cycle cover with one walk. Algorithms return these and never their own cost: the
//! [`checker`](crate::checker) recounts length, turns and coverage from the walk.
//!
//! File format: JSON `{"cycles": [[[x, y], ...], ...]}`.

use crate::error::{Error, Result};
use crate::region::Pixel;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A closed walk: `walk[i]` to `walk[i + 1]` is a unit move, and so is the last pixel back to
/// the first.
pub type Walk = Vec<Pixel>;

/// A set of closed walks; a tour when it has exactly one.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct CycleCover {
    pub cycles: Vec<Walk>,
}

impl CycleCover {
    pub fn new(cycles: Vec<Walk>) -> Self {
        CycleCover { cycles }
    }

    /// A tour: a cycle cover made of one closed walk.
    pub fn tour(walk: Walk) -> Self {
        CycleCover { cycles: vec![walk] }
    }

    pub fn is_tour(&self) -> bool {
        self.cycles.len() == 1
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a cycle cover always serializes")
    }

    /// Reads a tour file; `name` is used in error messages.
    pub fn from_json(text: &str, name: &str) -> Result<CycleCover> {
        serde_json::from_str(text).map_err(|e| {
            Error::parse(
                name,
                e.line(),
                e.column(),
                format!("expected a tour {{\"cycles\": [[[x, y], ...], ...]}}: {e}"),
            )
        })
    }

    pub fn read(path: &Path) -> Result<CycleCover> {
        let text = crate::input::read_text(path, "a tour JSON file")?;
        CycleCover::from_json(&text, &path.display().to_string())
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_json() + "\n").map_err(|e| Error::io(path, e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_round_trip() {
        let c = CycleCover::tour(vec![Pixel::new(0, 0), Pixel::new(1, 0)]);
        let s = c.to_json();
        assert_eq!(s, r#"{"cycles":[[[0,0],[1,0]]]}"#);
        assert_eq!(CycleCover::from_json(&s, "t.json").unwrap(), c);
    }

    #[test]
    fn json_errors_name_file_and_position() {
        let e = CycleCover::from_json("{\"cycles\": [[[0, 0], [1]]]}", "t.json").unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("t.json:1:"), "{msg}");
    }

    /// Probes the coordinate limit in tour files: a pixel at x = 2^31 − 1 (whose step to
    /// −2^31 once wrapped into a unit move) is refused with the line and column.
    #[test]
    fn json_pixels_beyond_the_coordinate_limit_are_refused() {
        let text = "{\"cycles\": [[[0, 0],\n [2147483647, 0]]]}";
        let msg = CycleCover::from_json(text, "t.json")
            .unwrap_err()
            .to_string();
        assert!(msg.starts_with("t.json:2:"), "{msg}");
        assert!(
            msg.contains("coordinate 2147483647 is out of range"),
            "{msg}"
        );
    }
}
