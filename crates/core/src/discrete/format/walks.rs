//! The walk files of a discrete instance: [`DiscreteCover`] and its JSON form.

use crate::discrete::VertexWalk;
use crate::error::{Error, Result};
use crate::gridfile::utf8_text;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A set of closed walks of a discrete instance (a tour when it has one walk), and its file.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DiscreteCover {
    pub cycles: Vec<VertexWalk>,
}

#[derive(Serialize, Deserialize)]
pub(super) enum Model {
    #[serde(rename = "discrete")]
    Discrete,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CoverJson {
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
