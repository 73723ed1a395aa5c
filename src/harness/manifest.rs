//! `manifest.json`: what produced a run — mowmill version, git commit and dirty flag, rustc and
//! HiGHS versions, the machine, the resolved config, start and end time, the command line.
//! Each `[[family]]` of the config is recorded with every generator parameter of
//! [`PARAMS`](crate::generate::PARAMS) (an empty list when not given), by `FamilySpec`'s
//! serialization.

use super::config::Config;
use super::run::RunOptions;
use crate::error::{Error, Result};
use serde_json::json;
use std::path::Path;
use std::process::Command;

/// The current UTC time, RFC 3339 to the second.
pub fn now() -> String {
    humantime::format_rfc3339_seconds(std::time::SystemTime::now()).to_string()
}

/// The HiGHS version linked into this binary.
pub fn highs_version() -> String {
    // SAFETY: the HiGHS version getters take no arguments and only return constants.
    let (major, minor, patch) = unsafe {
        (
            highs_sys::Highs_versionMajor(),
            highs_sys::Highs_versionMinor(),
            highs_sys::Highs_versionPatch(),
        )
    };
    format!("{major}.{minor}.{patch}")
}

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

/// Writes `out/manifest.json`; `end` is `None` while the run is going.
pub fn write(
    out: &Path,
    config: &Config,
    opts: &RunOptions,
    start: &str,
    end: Option<&str>,
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
        // Outside algorithms run here; a resumed run runs them here again.
        "config_dir": std::fs::canonicalize(&config.dir).unwrap_or_else(|_| config.dir.clone()),
        "jobs": opts.jobs,
        "shard": opts.shard.map(|(i, n)| format!("{i}/{n}")),
        "start": start,
        "end": end,
        "command_line": opts.command_line,
    });
    let path = out.join("manifest.json");
    let text =
        serde_json::to_string_pretty(&manifest).map_err(|e| Error::invalid(e.to_string()))?;
    std::fs::write(&path, text + "\n").map_err(|e| Error::io(&path, e))
}

/// The run id recorded in an existing manifest (to keep it when resuming).
pub fn read_run_id(out: &Path) -> Option<String> {
    let text = std::fs::read_to_string(out.join("manifest.json")).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    v["run_id"].as_str().map(str::to_string)
}
