//! `mowmill merge`: combines the output directories of shards into one run whose
//! `results.csv`, `stats.csv` and plots are those an unsharded run would have written.
//!
//! Before anything is written the shards are checked to be the complete, disjoint slices of
//! one run: every manifest records the same config digest and the same shard count N, every
//! shard index 0..N appears exactly once, every shard has finished (`end` set), and every
//! `results.csv` ends on a complete line and holds the number of rows its manifest recorded.
//! Then the rows themselves: each shard must hold exactly the rows its shard index of the
//! recorded config prescribes (instances, sha256, algorithms, objectives, options).
//! The merged run carries the shards' `instances/` and kept `walks/` ([`super::walks`]).
//! Otherwise the merge is refused with the list of what is wrong or missing. The output folder
//! must be new (or empty) and not one of the shards.

use super::manifest::Recorded;
use super::rows::{Row, read_rows, write_sorted};
use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// What the manifest of one shard says, once checked.
struct Shard {
    dir: PathBuf,
    manifest: Recorded,
    index: usize,
    count: usize,
    sha256: String,
}

/// Reads and checks one shard directory; problems are pushed onto `problems`.
fn check_shard(dir: &Path, problems: &mut Vec<String>) -> Option<Shard> {
    let manifest = match Recorded::read(dir) {
        Ok(m) => m,
        Err(e) => {
            problems.push(format!("{}: not a finished run: {e}", dir.display()));
            return None;
        }
    };
    let at = manifest.path.display().to_string();
    // An unsharded run is the one slice of itself.
    let (index, count) = match manifest.shard() {
        Ok(s) => s.unwrap_or((0, 1)),
        Err(e) => {
            problems.push(e.to_string());
            return None;
        }
    };
    let Some(sha256) = manifest.sha256().map(str::to_string) else {
        problems.push(format!(
            "{at}: records no config_sha256 (written by an older mowmill): resume it with \
             this version to record it"
        ));
        return None;
    };
    let shard = Shard {
        dir: dir.to_path_buf(),
        manifest,
        index,
        count,
        sha256,
    };
    // An unfinished or unreadable shard still counts as given, so it is not also reported
    // missing.
    if shard.manifest.json["end"].is_null() {
        problems.push(format!(
            "{at}: shard {index}/{count} has not finished (end is null): continue it with \
             `mowmill bench --resume {}`",
            dir.display()
        ));
        return Some(shard);
    }
    let Some(rows) = shard.manifest.json["rows"].as_u64() else {
        problems.push(format!(
            "{at}: records no rows count (written by an older mowmill)"
        ));
        return Some(shard);
    };
    let results = dir.join("results.csv");
    match crate::input::read_bytes(&results, "a results.csv") {
        Err(e) => problems.push(format!("{}: {e}", results.display())),
        Ok(bytes) if bytes.last().is_some_and(|&b| b != b'\n') => problems.push(format!(
            "{}: truncated (does not end on a complete line)",
            results.display()
        )),
        Ok(_) => match read_rows(&results) {
            Err(e) => problems.push(e.to_string()),
            Ok(r) if r.len() as u64 != rows => problems.push(format!(
                "{}: {} rows, but its manifest records {rows}: truncated or changed after \
                 the run",
                results.display(),
                r.len()
            )),
            Ok(_) => {}
        },
    }
    Some(shard)
}

/// Checks that `shards` are the complete, disjoint slices of one config; the error lists
/// every problem found.
fn check_complete(dirs: &[PathBuf]) -> Result<Vec<Shard>> {
    let mut problems = Vec::new();
    let shards: Vec<Shard> = dirs
        .iter()
        .filter_map(|d| check_shard(d, &mut problems))
        .collect();
    if let Some(first) = shards.first() {
        for s in &shards[1..] {
            if s.sha256 != first.sha256 {
                problems.push(format!(
                    "{} has config {} (sha256 {}), but {} has config {} (sha256 {}): shards \
                     of different configs",
                    s.dir.display(),
                    s.manifest.config_file(),
                    s.sha256,
                    first.dir.display(),
                    first.manifest.config_file(),
                    first.sha256
                ));
            }
            if s.count != first.count {
                problems.push(format!(
                    "{} is a shard of {}, but {} is a shard of {}",
                    s.dir.display(),
                    s.count,
                    first.dir.display(),
                    first.count
                ));
            }
        }
        let n = first.count;
        let mut by_index: BTreeMap<usize, Vec<&Path>> = BTreeMap::new();
        for s in shards.iter().filter(|s| s.count == n) {
            by_index.entry(s.index).or_default().push(&s.dir);
        }
        for (i, ds) in &by_index {
            if ds.len() > 1 {
                let names: Vec<String> = ds.iter().map(|d| d.display().to_string()).collect();
                problems.push(format!(
                    "shard {i}/{n} given {} times: {}",
                    ds.len(),
                    names.join(", ")
                ));
            }
        }
        let missing: Vec<String> = (0..n)
            .filter(|i| !by_index.contains_key(i))
            .map(|i| format!("{i}/{n}"))
            .collect();
        if !missing.is_empty() {
            problems.push(format!("missing shard(s) {}", missing.join(", ")));
        }
    }
    if problems.is_empty() {
        Ok(shards)
    } else {
        Err(Error::invalid(format!(
            "merge refused: the shards are not the complete, finished slices of one run:\n  {}",
            problems.join("\n  ")
        )))
    }
}

/// Refuses an `out` that is one of the shards (same canonical path) or an existing folder
/// that is not empty: a merge never overwrites a run, as `bench --out` does not.
fn check_out(shards: &[PathBuf], out: &Path) -> Result<()> {
    if let Ok(out_c) = std::fs::canonicalize(out) {
        for d in shards {
            if std::fs::canonicalize(d).is_ok_and(|c| c == out_c) {
                return Err(Error::invalid(format!(
                    "merge refused: --out {} is the input shard {}: choose a new folder",
                    out.display(),
                    d.display()
                )));
            }
        }
    }
    match std::fs::read_dir(out) {
        Ok(mut entries) => match entries.next() {
            Some(_) => Err(Error::invalid(format!(
                "merge refused: --out {} already exists and is not empty: merge never \
                 overwrites a run; choose a new folder",
                out.display()
            ))),
            None => Ok(()),
        },
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) if out.exists() && !out.is_dir() => Err(Error::invalid(format!(
            "merge refused: --out {} exists and is not a folder ({e})",
            out.display()
        ))),
        Err(e) => Err(Error::io(out, e)),
    }
}

/// The most problems listed per shard by [`check_rows`].
const MAX_LISTED: usize = 10;

/// Checks that every shard holds exactly the rows its shard index of the recorded config
/// prescribes: the config is recomputed from the first shard's `config_toml` (the digests are
/// equal, [`check_complete`]), its instance list sliced as the shard was, and each instance
/// generated (or read) again for its sha256 and the (algorithm, objective) rows a run writes
/// for it ([`super::run::expected_keys`]). A row of another config, of another instance or
/// with another sha256, family, parameters or seed, and a missing row are refused, naming the
/// shard and the row.
fn check_rows(shards: &[Shard]) -> Result<()> {
    let first = &shards[0].manifest;
    let text = first.config_toml()?;
    let mut config =
        super::config::Config::parse(&text, &format!("{} (config_toml)", first.path.display()))?;
    if let Some(d) = first.config_dir() {
        config.dir = d;
    }
    let instances = config.instances().map_err(|e| {
        Error::invalid(format!(
            "merge refused: cannot recompute the instance list of {} to check the shards' rows: {e}",
            first.path.display()
        ))
    })?;
    let mut problems = Vec::new();
    for shard in shards {
        let mut listed = Vec::new();
        let rows = read_rows(&shard.dir.join("results.csv"))?;
        let specs = super::run::shard_of(instances.clone(), Some((shard.index, shard.count)));
        let mut by_instance: BTreeMap<&str, Vec<&Row>> = BTreeMap::new();
        for r in &rows {
            by_instance.entry(r.instance.as_str()).or_default().push(r);
        }
        for spec in &specs {
            let got = by_instance.remove(spec.name.as_str()).unwrap_or_default();
            let (sha, expected) = super::run::expected_keys(spec, &config);
            for r in &got {
                let key = (r.algorithm.clone(), r.objective.clone());
                let bad = if !expected.contains(&key) {
                    Some("is not a row the config prescribes for this instance".to_string())
                } else if r.family != spec.family || r.params != spec.params || r.seed != spec.seed
                {
                    Some(format!(
                        "has family {:?}, params {:?}, seed {}, but the config gives {:?}, {:?}, {}",
                        r.family, r.params, r.seed, spec.family, spec.params, spec.seed
                    ))
                } else {
                    match &sha {
                        Some(sha) if !r.sha256.is_empty() && &r.sha256 != sha => Some(format!(
                            "has sha256 {}, but the config's instance has {sha}",
                            r.sha256
                        )),
                        _ => None,
                    }
                };
                if let Some(why) = bad {
                    listed.push(format!(
                        "row ({}, {}, {}) {why}",
                        r.instance, r.algorithm, r.objective
                    ));
                }
            }
            let have: std::collections::BTreeSet<(String, String)> = got
                .iter()
                .map(|r| (r.algorithm.clone(), r.objective.clone()))
                .collect();
            for (a, o) in expected.difference(&have) {
                listed.push(format!("missing row ({}, {a}, {o})", spec.name));
            }
        }
        for (instance, rs) in by_instance {
            for r in rs {
                listed.push(format!(
                    "row ({instance}, {}, {}): instance {instance} is not in shard {}/{} of the config",
                    r.algorithm, r.objective, shard.index, shard.count
                ));
            }
        }
        let total = listed.len();
        for l in listed.into_iter().take(MAX_LISTED) {
            problems.push(format!("{}: {l}", shard.dir.display()));
        }
        if total > MAX_LISTED {
            problems.push(format!(
                "{}: and {} more row problem(s)",
                shard.dir.display(),
                total - MAX_LISTED
            ));
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(Error::invalid(format!(
            "merge refused: shard rows differ from what their config prescribes:\n  {}",
            problems.join("\n  ")
        )))
    }
}

/// Merges shard directories into `out`. Rows are keyed by (instance, algorithm, objective); a
/// key present in two shards must agree apart from timing, else the merge is refused.
pub fn merge(shards: &[PathBuf], out: &Path) -> Result<usize> {
    if shards.is_empty() {
        return Err(Error::invalid("merge needs at least one shard directory"));
    }
    check_out(shards, out)?;
    let checked = check_complete(shards)?;
    check_rows(&checked)?;
    let run_id = checked[0]
        .manifest
        .run_id()
        .map_or_else(|| "merged".to_string(), str::to_string);
    let mut rows: BTreeMap<(String, String, String), Row> = BTreeMap::new();
    std::fs::create_dir_all(out.join("instances")).map_err(|e| Error::io(out, e))?;
    let _lock = super::lock::acquire(out)?;
    for dir in shards {
        for mut r in read_rows(&dir.join("results.csv"))? {
            r.run_id = run_id.clone();
            match rows.get(&r.key()) {
                Some(prev) if !same_apart_from_timing(prev, &r) => {
                    return Err(Error::invalid(format!(
                        "{}: row {:?} disagrees with another shard",
                        dir.display(),
                        r.key()
                    )));
                }
                Some(_) => {}
                None => {
                    rows.insert(r.key(), r);
                }
            }
        }
        let inst = dir.join("instances");
        if let Ok(entries) = std::fs::read_dir(&inst) {
            for e in entries.flatten() {
                let to = out.join("instances").join(e.file_name());
                std::fs::copy(e.path(), &to).map_err(|err| Error::io(&to, err))?;
            }
        }
        // The shards' kept walks (disjoint instances: a file two shards hold must agree).
        super::walks::merge_into(dir, out)?;
    }
    let mut rows: Vec<Row> = rows.into_values().collect();
    let n = rows.len();
    write_sorted(&out.join("results.csv"), &mut rows)?;
    super::run::finish(out)?;
    let first = &checked[0].manifest.json;
    let instances: Option<u64> = checked
        .iter()
        .map(|s| s.manifest.json["instances"].as_u64())
        .sum();
    let manifest = serde_json::json!({
        "run_id": run_id,
        "merged_from": shards.iter().map(|d| d.display().to_string()).collect::<Vec<_>>(),
        "shard_manifests": checked.iter().map(|s| &s.manifest.json).collect::<Vec<_>>(),
        "config": first["config"],
        "config_toml": first["config_toml"],
        "config_file": first["config_file"],
        "config_sha256": first["config_sha256"],
        "shard": null,
        "instances": instances,
        "rows": n,
        "end": super::manifest::now(),
    });
    super::manifest::write_json(out, &manifest)?;
    Ok(n)
}

fn same_apart_from_timing(a: &Row, b: &Row) -> bool {
    let strip = |r: &Row| Row {
        seconds: 0.0,
        run_id: String::new(),
        ..r.clone()
    };
    strip(a) == strip(b)
}
