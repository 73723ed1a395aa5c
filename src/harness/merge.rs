//! `mowmill merge`: combines the output directories of shards into one run whose
//! `results.csv`, `stats.csv` and plots are those an unsharded run would have written.

use super::rows::{Row, read_rows, write_sorted};
use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Merges shard directories into `out`. Rows are keyed by (instance, algorithm, objective); a
/// key present in two shards must agree apart from timing, else the merge is refused.
pub fn merge(shards: &[PathBuf], out: &Path) -> Result<usize> {
    if shards.is_empty() {
        return Err(Error::invalid("merge needs at least one shard directory"));
    }
    let run_id = super::manifest::read_run_id(&shards[0]).unwrap_or_else(|| "merged".into());
    let mut rows: BTreeMap<(String, String, String), Row> = BTreeMap::new();
    std::fs::create_dir_all(out.join("instances")).map_err(|e| Error::io(out, e))?;
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
    }
    let mut rows: Vec<Row> = rows.into_values().collect();
    let n = rows.len();
    write_sorted(&out.join("results.csv"), &mut rows)?;
    super::run::finish(out)?;
    let manifest = serde_json::json!({
        "run_id": run_id,
        "merged_from": shards.iter().map(|d| d.display().to_string()).collect::<Vec<_>>(),
        "shard_manifests": shards.iter().map(|d| {
            std::fs::read_to_string(d.join("manifest.json")).ok()
                .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
        }).collect::<Vec<_>>(),
        "end": super::manifest::now(),
    });
    let path = out.join("manifest.json");
    std::fs::write(
        &path,
        serde_json::to_string_pretty(&manifest).unwrap_or_default() + "\n",
    )
    .map_err(|e| Error::io(&path, e))?;
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
