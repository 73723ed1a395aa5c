//! `manifest.json`: what produced a run — mowmill version, git commit and dirty flag, rustc and
//! HiGHS versions, the machine, the resolved config, start and end time, the command line.
//! Each `[[family]]` of the config is recorded with every generator parameter of
//! [`PARAMS`](crate::generate::PARAMS) (an empty list when not given), by `FamilySpec`'s
//! serialization.
//!
//! For resuming and merging it also records the config as given (`config_toml`, the TOML text,
//! with `config_file` naming where it came from and `config_sha256` its digest), the `shard`
//! as `"I/N"` (null for an unsharded run), and once the run has finished (`end` set) the number
//! of `instances` of its slice and of `rows` in its `results.csv`; `files_sha256` pins the
//! sha256 of every `[[files]]` instance of the slice (by instance name).

use super::config::Config;
use super::run::RunOptions;
use crate::error::{Error, Result};
use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The current UTC time, RFC 3339 to the second.
pub fn now() -> String {
    humantime::format_rfc3339_seconds(std::time::SystemTime::now()).to_string()
}

pub use crate::exact::highs_version;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn os_name() -> String {
    std::fs::read_to_string("/etc/os-release")
        .ok()
        .and_then(|t| {
            t.lines().find_map(|l| {
                l.strip_prefix("PRETTY_NAME=")
                    .map(|v| v.trim_matches('"').to_string())
            })
        })
        .unwrap_or_else(|| std::env::consts::OS.to_string())
}

/// The config of a run as recorded: its TOML text as given (when it was given as text), where
/// it came from, and the digest that resume and merge compare.
#[derive(Clone, Debug)]
pub struct ConfigRecord {
    /// The TOML text as given; `None` for a config built through the library API.
    pub toml: Option<String>,
    /// The file the text was read from (or "built-in default suite").
    pub file: String,
    /// sha256 of `toml`, or of the JSON encoding of the config when there is no text.
    pub sha256: String,
}

impl ConfigRecord {
    /// The record of a config given as TOML text read from `file`.
    pub fn given(text: &str, file: &str) -> ConfigRecord {
        ConfigRecord {
            toml: Some(text.to_string()),
            file: file.to_string(),
            sha256: super::run::sha256_hex(text.as_bytes()),
        }
    }

    /// The record of a config that has no text (built through the library API): the digest is
    /// that of its JSON encoding, which is deterministic for equal configs.
    pub fn of_config(config: &Config) -> ConfigRecord {
        let json = serde_json::to_string(config).unwrap_or_default();
        ConfigRecord {
            toml: None,
            file: "(library API)".into(),
            sha256: super::run::sha256_hex(json.as_bytes()),
        }
    }
}

/// What a finished run adds to its manifest.
#[derive(Clone, Copy, Debug)]
pub struct Finished<'a> {
    pub end: &'a str,
    /// Instances of the run's slice.
    pub instances: usize,
    /// Rows of the sorted `results.csv`.
    pub rows: usize,
}

/// Writes `out/manifest.json`; `finished` is `None` while the run is going (`end` is null).
pub fn write(
    out: &Path,
    config: &Config,
    record: &ConfigRecord,
    opts: &RunOptions,
    start: &str,
    finished: Option<Finished<'_>>,
    files: &std::collections::BTreeMap<String, String>,
) -> Result<()> {
    let manifest = json!({
        "run_id": opts.run_id,
        "mowmill_version": env!("CARGO_PKG_VERSION"),
        "git_commit": git(&["rev-parse", "HEAD"]),
        "git_dirty": git(&["status", "--porcelain", "--untracked-files=no"]).map(|s| !s.is_empty()),
        "rustc_version": env!("MOWMILL_RUSTC_VERSION"),
        "highs_version": highs_version(),
        "machine": {
            "cores": std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1),
            "os": os_name(),
            "arch": std::env::consts::ARCH,
        },
        "config": config,
        "config_toml": record.toml,
        "config_file": record.file,
        "config_sha256": record.sha256,
        // Outside algorithms run here; a resumed run runs them here again.
        "config_dir": std::fs::canonicalize(&config.dir).unwrap_or_else(|_| config.dir.clone()),
        "jobs": opts.jobs,
        "shard": opts.shard.map(|(i, n)| format!("{i}/{n}")),
        // The sha256 of each `[[files]]` instance of the slice, by instance name: a resume
        // refuses a folder whose files changed.
        "files_sha256": files,
        "start": start,
        "end": finished.map(|f| f.end),
        "instances": finished.map(|f| f.instances),
        "rows": finished.map(|f| f.rows),
        "command_line": opts.command_line,
    });
    write_json(out, &manifest)
}

/// Writes `out/manifest.json` through a temporary file, so that a kill never leaves half a
/// manifest behind.
pub fn write_json(out: &Path, manifest: &Value) -> Result<()> {
    let path = out.join("manifest.json");
    let tmp = out.join("manifest.json.tmp");
    let text = serde_json::to_string_pretty(manifest).map_err(|e| Error::invalid(e.to_string()))?;
    std::fs::write(&tmp, text + "\n").map_err(|e| Error::io(&tmp, e))?;
    std::fs::rename(&tmp, &path).map_err(|e| Error::io(&path, e))
}

/// The run id recorded in an existing manifest (to keep it when resuming).
pub fn read_run_id(out: &Path) -> Option<String> {
    let text = crate::input::read_text(&out.join("manifest.json"), "a manifest.json").ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    v["run_id"].as_str().map(str::to_string)
}

/// A manifest read back: the raw JSON and the path it came from (for messages).
#[derive(Clone, Debug)]
pub struct Recorded {
    pub path: PathBuf,
    pub json: Value,
}

impl Recorded {
    /// Reads `dir/manifest.json`; errors name the file.
    pub fn read(dir: &Path) -> Result<Recorded> {
        Recorded::read_path(&dir.join("manifest.json"))
    }

    /// Reads a manifest from a file of any name (a sample keeps its runs' manifests as
    /// `manifests/RUN.json`); errors name the file.
    pub fn read_path(path: &Path) -> Result<Recorded> {
        let path = path.to_path_buf();
        let text = crate::input::read_text(&path, "a manifest.json")?;
        let json = serde_json::from_str(&text).map_err(|e| {
            Error::parse(
                &path.display().to_string(),
                e.line(),
                e.column(),
                format!("expected a mowmill manifest (JSON): {e}"),
            )
        })?;
        Ok(Recorded { path, json })
    }

    /// `dir/manifest.json` when the file exists.
    pub fn read_if_exists(dir: &Path) -> Result<Option<Recorded>> {
        if dir.join("manifest.json").exists() {
            Recorded::read(dir).map(Some)
        } else {
            Ok(None)
        }
    }

    pub fn sha256(&self) -> Option<&str> {
        self.json["config_sha256"].as_str()
    }

    pub fn config_file(&self) -> &str {
        self.json["config_file"]
            .as_str()
            .unwrap_or("an unnamed config")
    }

    pub fn run_id(&self) -> Option<&str> {
        self.json["run_id"].as_str()
    }

    /// The recorded shard: `Ok(None)` for an unsharded run (null or absent).
    pub fn shard(&self) -> Result<Option<(usize, usize)>> {
        match &self.json["shard"] {
            Value::Null => Ok(None),
            Value::String(s) => parse_shard(s)
                .map(Some)
                .map_err(|m| Error::invalid(format!("{}: shard: {m}", self.path.display()))),
            other => Err(Error::invalid(format!(
                "{}: shard: expected \"I/N\" or null, got {other}",
                self.path.display()
            ))),
        }
    }

    /// The recorded config as TOML text: `config_toml` when recorded; for manifests written
    /// before it existed, the JSON `config` re-encoded as TOML without its nulls and empty
    /// lists (which the manifest writes for keys that were not given).
    pub fn config_toml(&self) -> Result<String> {
        if let Some(text) = self.json["config_toml"].as_str() {
            return Ok(text.to_string());
        }
        let config = &self.json["config"];
        if config.is_null() {
            return Err(Error::invalid(format!(
                "{}: records no config (neither config_toml nor config): pass --config",
                self.path.display()
            )));
        }
        toml::to_string(&without_empty(config)).map_err(|e| {
            Error::invalid(format!(
                "{}: cannot re-encode the recorded config as TOML ({e}): pass --config",
                self.path.display()
            ))
        })
    }

    /// The folder outside algorithms ran in.
    pub fn config_dir(&self) -> Option<PathBuf> {
        self.json["config_dir"].as_str().map(PathBuf::from)
    }
}

/// `value` without nulls and empty lists in its objects (TOML has no null).
fn without_empty(value: &Value) -> Value {
    match value {
        Value::Object(map) => Value::Object(
            map.iter()
                .filter(|(_, v)| !v.is_null() && v.as_array().is_none_or(|a| !a.is_empty()))
                .map(|(k, v)| (k.clone(), without_empty(v)))
                .collect(),
        ),
        Value::Array(items) => Value::Array(items.iter().map(without_empty).collect()),
        other => other.clone(),
    }
}

/// Parses a shard `I/N` (0-based, `I < N`).
pub fn parse_shard(s: &str) -> std::result::Result<(usize, usize), String> {
    let (i, n) = s
        .split_once('/')
        .ok_or_else(|| format!("expected I/N, got {s:?}"))?;
    let (i, n): (usize, usize) = (
        i.parse().map_err(|_| format!("bad shard index {i:?}"))?,
        n.parse().map_err(|_| format!("bad shard count {n:?}"))?,
    );
    if n == 0 || i >= n {
        return Err(format!("shard {i}/{n}: expected 0 <= I < N"));
    }
    Ok((i, n))
}
