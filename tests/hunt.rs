//! `mowmill hunt`: a planted bug is found, the same seed gives the same `hunt.csv`, every saved
//! instance keeps the family's constraint and the algorithm's precondition, and symmetric
//! duplicates are saved once.

mod common;

use common::{mowmill, temp_dir};
use mowmill::gridfile::GridFile;
use mowmill::hunt::{Shape, canonical};
use std::collections::BTreeSet;
use std::path::Path;

/// The worst instances a hunt saved, best first.
fn worst(dir: &Path) -> Vec<GridFile> {
    let mut files: Vec<_> = std::fs::read_dir(dir.join("worst"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "grid"))
        .collect();
    files.sort();
    files.iter().map(|p| GridFile::read(p).unwrap()).collect()
}

/// `hunt.csv` without its `elapsed` column.
fn csv_without_time(dir: &Path) -> Vec<String> {
    std::fs::read_to_string(dir.join("hunt.csv"))
        .unwrap()
        .lines()
        .map(|l| {
            let mut f: Vec<&str> = l.split(',').collect();
            f.remove(1);
            f.join(",")
        })
        .collect()
}

/// A planted bug: an outside "algorithm" that returns the exact optimum, except on regions
/// with a row of 6 or more consecutive pixels, where it walks one step out and back (+2).
/// Seed 4: with the lattice-fill and crop moves, seeds 1, 4 and 5 find the class within 60
/// evaluations, seeds 2 and 3 do not (a search is a sample, not a guarantee).
#[test]
fn a_short_hunt_finds_a_planted_bug() {
    let dir = temp_dir("hunt-planted");
    let script = dir.join("planted.py");
    std::fs::write(
        &script,
        format!(
            r##"import json, subprocess, sys
inst, out = sys.argv[1], sys.argv[2]
subprocess.run(["{bin}", "exact", inst, "--objective", "length", "--tour-out", out],
               check=True, capture_output=True)
rows = [l.strip() for l in open(inst) if l.strip() and not l.startswith(";")]
if any("#" * 6 in r for r in rows):
    tour = json.load(open(out))
    c = tour["cycles"][0]
    if len(c) > 1:
        tour["cycles"][0] = [c[0], c[1]] + c
    json.dump(tour, open(out, "w"))
"##,
            bin = env!("CARGO_BIN_EXE_mowmill")
        ),
    )
    .unwrap();
    let out = dir.join("run");
    let command = format!("python3 {} {{instance}} {{tour_out}}", script.display());
    let o = mowmill(&[
        "hunt",
        "--command",
        &command,
        "--objective",
        "length",
        "--family",
        "random-simple",
        "--min-n",
        "8",
        "--max-n",
        "14",
        "--evaluations",
        "60",
        "--seed",
        "4",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let found = worst(&out);
    let top = &found[0];
    assert!(
        top.region.to_ascii().lines().any(|r| r.contains("######")),
        "the worst instance is not of the planted class:\n{}\n{stdout}",
        top.region.to_ascii()
    );
    let ratio: f64 = top.meta("ratio").unwrap().parse().unwrap();
    assert!(ratio > 1.0, "{stdout}");
}

/// Same seed and evaluation count, same `hunt.csv` (whatever the number of jobs); saved
/// instances keep the constraint and the precondition; no two are symmetric images.
#[test]
fn hunts_are_reproducible_and_keep_their_constraints() {
    let dir = temp_dir("hunt-repro");
    let run = |tag: &str, jobs: &str| {
        let out = dir.join(tag);
        let o = mowmill(&[
            "hunt",
            "--algo",
            "tsp65",
            "--min-n",
            "8",
            "--max-n",
            "24",
            "--evaluations",
            "80",
            "--seed",
            "5",
            "--keep",
            "6",
            "--jobs",
            jobs,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        out
    };
    let (a, b) = (run("a", "1"), run("b", "2"));
    assert_eq!(csv_without_time(&a), csv_without_time(&b));
    assert_eq!(
        csv_without_time(&a).len(),
        81,
        "a header and 80 evaluations"
    );
    let algo = mowmill::algorithms::find("tsp65").unwrap();
    let found = worst(&a);
    assert_eq!(found.len(), 6);
    let mut keys = BTreeSet::new();
    for f in &found {
        let r = &f.region;
        assert!((8..=24).contains(&r.len()));
        assert!(Shape::Simple.holds(r), "{}", r.to_ascii());
        assert!((algo.precondition)(r).is_ok(), "{}", r.to_ascii());
        assert!(
            keys.insert(canonical(r)),
            "a symmetric duplicate:\n{}",
            r.to_ascii()
        );
        // Every image under the symmetries has the same key.
        for s in mowmill::region::Symmetry::all() {
            assert_eq!(canonical(&r.transformed(s)), canonical(r));
        }
    }
    for file in [
        "manifest.json",
        "best.png",
        "worst/rank-01.svg",
        "worst/rank-01.walk.json",
    ] {
        assert!(a.join(file).exists(), "{file}");
    }
}

/// A hunt suite runs every `[[hunt]]` table into its own folder and writes `summary.csv`; a
/// table naming an unknown algorithm is refused before any hunt runs.
#[test]
fn a_suite_runs_each_hunt_and_summarizes() {
    let dir = temp_dir("hunt-suite");
    let suite = dir.join("suite.toml");
    std::fs::write(
        &suite,
        "evaluations = 12\nseed = 4\n[[hunt]]\nalgo = \"tsp65\"\nmax_n = 16\n\
         [[hunt]]\nalgo = \"strips-matching\"\nobjective = \"cc-turns\"\nmax_n = 16\n",
    )
    .unwrap();
    let out = dir.join("run");
    let o = mowmill(&[
        "hunt",
        "--suite",
        suite.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut r = csv::Reader::from_path(out.join("summary.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    assert_eq!(&header[..3], ["algorithm", "objective", "family"]);
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 2);
    assert_eq!((&rows[0][0], &rows[0][1]), ("tsp65", "length"));
    assert_eq!((&rows[1][0], &rows[1][1]), ("strips-matching", "cc-turns"));
    let instance = header.iter().position(|h| h == "worst_instance").unwrap();
    for row in &rows {
        assert!(out.join(&row[instance]).exists(), "{}", &row[instance]);
    }
    std::fs::write(
        &suite,
        "evaluations = 12\nseed = 4\n[[hunt]]\nalgo = \"nope\"\n",
    )
    .unwrap();
    let o = mowmill(&[
        "hunt",
        "--suite",
        suite.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("hunt[0].algo"));
}

/// `seeds` and `strategies` run every hunt once per seed and strategy, each in its own folder,
/// with the strategy in the summary; the random strategy is what the search is compared with.
#[test]
fn a_suite_compares_the_search_with_random_sampling() {
    let dir = temp_dir("hunt-suite-vs-random");
    let suite = dir.join("suite.toml");
    std::fs::write(
        &suite,
        "evaluations = 10\nseeds = [1, 2]\nstrategies = [\"anneal\", \"random\"]\n\
         [[hunt]]\nalgo = \"tsp65\"\nmax_n = 14\n",
    )
    .unwrap();
    let out = dir.join("run");
    let args = [
        "hunt",
        "--suite",
        suite.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    let o = mowmill(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut r = csv::Reader::from_path(out.join("summary.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(str::to_string).collect();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    let runs: Vec<(String, String)> = rows
        .iter()
        .map(|row| {
            (
                row[col("strategy")].to_string(),
                row[col("seed")].to_string(),
            )
        })
        .collect();
    let expected = [
        ("anneal", "1"),
        ("anneal", "2"),
        ("random", "1"),
        ("random", "2"),
    ];
    assert_eq!(runs, expected.map(|(s, k)| (s.to_string(), k.to_string())));
    for (strategy, seed) in expected {
        let manifest = out
            .join("tsp65")
            .join(format!("{strategy}-seed{seed}/manifest.json"));
        let m: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&manifest).unwrap()).unwrap();
        assert_eq!(m["strategy"], strategy);
        assert_eq!(m["seed"], seed.parse::<u64>().unwrap());
    }
    // Both `seed` and `seeds`, or an unknown strategy: exit 2 before any hunt runs.
    for bad in [
        "evaluations = 10\nseed = 1\nseeds = [1]\n[[hunt]]\nalgo = \"tsp65\"\n",
        "evaluations = 10\nseed = 1\nstrategies = [\"greedy\"]\n[[hunt]]\nalgo = \"tsp65\"\n",
    ] {
        std::fs::write(&suite, bad).unwrap();
        let o = mowmill(&args);
        assert_eq!(o.status.code(), Some(2), "{bad}");
    }
}

/// `hunt.csv` rows as maps from column to value.
fn rows(dir: &Path) -> Vec<std::collections::HashMap<String, String>> {
    let mut r = csv::Reader::from_path(dir.join("hunt.csv")).unwrap();
    let head = r.headers().unwrap().clone();
    r.records()
        .map(|rec| {
            head.iter()
                .zip(rec.unwrap().iter())
                .map(|(h, v)| (h.to_string(), v.to_string()))
                .collect()
        })
        .collect()
}

/// `--against best` at N in the hundreds (with the structural moves, exact incumbents under
/// a 2 s limit): the hunt finishes, every decided ratio is value / best with a named source,
/// and a best walk is never above the algorithm's own.
#[test]
fn a_hunt_against_best_at_n_in_the_hundreds_finishes() {
    let dir = temp_dir("hunt-best");
    let o = mowmill(&[
        "hunt",
        "--algo",
        "milling25",
        "--objective",
        "length",
        "--against",
        "best",
        "--family",
        "random-holed",
        "--min-n",
        "200",
        "--max-n",
        "400",
        "--evaluations",
        "16",
        "--exact-time-limit",
        "2",
        "--seed",
        "3",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = rows(&dir);
    assert_eq!(rows.len(), 16);
    let mut decided = 0;
    for r in &rows {
        let n: usize = r["n"].parse().unwrap();
        assert!((200..=400).contains(&n), "N = {n}");
        if r["ratio"].is_empty() {
            continue;
        }
        decided += 1;
        let (value, best): (f64, f64) = (r["value"].parse().unwrap(), r["best"].parse().unwrap());
        assert!(best <= value, "best {best} above the algorithm's {value}");
        let ratio: f64 = r["ratio"].parse().unwrap();
        assert!((ratio - value / best).abs() < 1e-6);
        assert!(!r["best_source"].is_empty());
    }
    assert_eq!(decided, 16);
    let w = worst(&dir);
    assert_eq!(w[0].meta("against"), Some("best"));
    assert!(!w[0].meta("best_source").unwrap_or("").is_empty());
    assert!(dir.join("worst/rank-01.txt").exists());
}

/// Same seed and `--evaluations` give the same `hunt.csv` against best (no exact solve:
/// `--exact-max-n` below the range, so no time limit decides an incumbent), and a different
/// seed a different one.
#[test]
fn hunts_against_best_are_reproducible() {
    let run = |seed: &str, tag: &str| {
        let dir = temp_dir(tag);
        let o = mowmill(&[
            "hunt",
            "--algo",
            "milling25",
            "--objective",
            "length",
            "--against",
            "best",
            "--family",
            "random-holed",
            "--min-n",
            "60",
            "--max-n",
            "160",
            "--exact-max-n",
            "10",
            "--evaluations",
            "40",
            "--seed",
            seed,
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        csv_without_time(&dir)
    };
    let a = run("5", "hunt-best-a");
    assert_eq!(a.len(), 41);
    assert_eq!(a, run("5", "hunt-best-b"));
    assert_ne!(a, run("6", "hunt-best-c"));
}

/// A hunt killed while it runs keeps what it found: `hunt.csv` and the worst instances are
/// written at every checkpoint (the first round always sets a worst ratio), only
/// `manifest.json`, written when the hunt ends, is missing (an earlier one is removed first).
#[test]
fn a_killed_hunt_keeps_its_checkpoint() {
    let dir = temp_dir("hunt-killed");
    // An earlier run's manifest in the same folder is removed before the hunt starts.
    std::fs::write(dir.join("manifest.json"), "{}").unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args([
            "hunt",
            "--algo",
            "milling25",
            "--objective",
            "length",
            "--against",
            "bound",
            "--family",
            "random-simple",
            "--min-n",
            "20",
            "--max-n",
            "40",
            "--budget",
            "600",
            "--seed",
            "1",
            "--out",
            dir.to_str().unwrap(),
        ])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let grid = dir.join("worst/rank-01.grid");
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while !grid.exists() && std::time::Instant::now() < deadline {
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    // A checkpoint may be half written when the kill lands: wait for the next round's.
    std::thread::sleep(std::time::Duration::from_millis(500));
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(grid.exists(), "no checkpoint within 60 s");
    assert!(!dir.join("manifest.json").exists());
    let rows = rows(&dir);
    assert!(!rows.is_empty());
    let w = worst(&dir);
    let n = w[0].region.len();
    assert!((20..=40).contains(&n), "N = {n}");
}
