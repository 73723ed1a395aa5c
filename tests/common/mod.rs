//! Helpers shared by the integration tests: run the binary, read its JSON, scratch folders.
//! Include with `mod common;` (each test binary uses a subset, hence the allow).
#![allow(dead_code)]

pub mod brute;

use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs the `mowmill` binary from the repository root.
pub fn mowmill(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run mowmill")
}

/// Its stdout as JSON; the panic shows stdout and stderr.
pub fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    })
}

/// A fresh scratch folder for one test (emptied first).
pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mowmill-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the `mowmill` binary from the repository root with the given environment variables
/// set and every other `SLURM_*` variable removed (so that the test's own environment cannot
/// shard the run).
pub fn mowmill_env(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_mowmill"));
    cmd.args(args).current_dir(env!("CARGO_MANIFEST_DIR"));
    for (k, _) in std::env::vars() {
        if k.starts_with("SLURM_") {
            cmd.env_remove(k);
        }
    }
    cmd.envs(env.iter().copied());
    cmd.output().expect("run mowmill")
}

/// Runs the `mowmill` binary from the repository root like [`mowmill`], but kills it after
/// `seconds` (then the exit code is `None`): for tests whose failure could be a run that never
/// ends.
pub fn mowmill_within(args: &[&str], seconds: u64) -> Output {
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run mowmill");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(seconds);
    while child.try_wait().expect("wait for mowmill").is_none() {
        if std::time::Instant::now() > deadline {
            let _ = child.kill();
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().expect("collect mowmill's output")
}
