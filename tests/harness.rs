//! The experiment harness end to end on a tiny suite: determinism, resume after a kill, shards
//! merged equal the unsharded run, the regression gate, malformed configs.

use mowmill::harness::config::Config;
use mowmill::harness::gate::gate;
use mowmill::harness::rows::{Row, read_rows};
use mowmill::harness::run::{RunOptions, run};
use std::path::{Path, PathBuf};
use std::process::Command;

const SUITE: &str = r#"
name = "tiny"
seed = 7

[[family]]
family = "rect"
width = [2, 3]
height = [3, 4]

[[family]]
family = "random-simple"
n = [10, 14]
no_cut = true
count = 2

[[family]]
family = "thin"
n = 11
count = 2

[[exact]]
objective = "length"
max_n = 16
time_limit = 30

[[exact]]
objective = "cc-turns"
max_n = 12
time_limit = 30
"#;

fn temp(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mowmill-harness-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn opts(out: &Path, shard: Option<(usize, usize)>, resume: bool) -> RunOptions {
    RunOptions {
        out: out.to_path_buf(),
        jobs: Some(2),
        resume,
        shard,
        run_id: "test".into(),
        command_line: "test".into(),
    }
}

/// Rows without the columns that legitimately differ between runs.
fn comparable(dir: &Path) -> Vec<Row> {
    read_rows(&dir.join("results.csv"))
        .unwrap()
        .into_iter()
        .map(|r| Row {
            seconds: 0.0,
            run_id: String::new(),
            ..r
        })
        .collect()
}

fn config() -> Config {
    Config::parse(SUITE, "tiny.toml").unwrap()
}

#[test]
fn same_seed_same_results_and_every_row_checked() {
    let (a, b) = (temp("det-a"), temp("det-b"));
    run(&config(), &opts(&a, None, false)).unwrap();
    run(&config(), &opts(&b, None, false)).unwrap();
    let rows = comparable(&a);
    assert_eq!(rows, comparable(&b));
    // 4 rects + 4 random + 2 thin instances, each with at least the exact length row.
    let instances: std::collections::BTreeSet<&str> =
        rows.iter().map(|r| r.instance.as_str()).collect();
    assert_eq!(instances.len(), 10);
    assert!(
        rows.iter().all(|r| r.error.is_empty()),
        "{:?}",
        rows.iter().find(|r| !r.error.is_empty())
    );
    let exact_len: Vec<&Row> = rows
        .iter()
        .filter(|r| r.algorithm == "exact" && r.objective == "length")
        .collect();
    assert_eq!(exact_len.len(), 10);
    // The 2 x 3 rectangle has a Hamiltonian cycle.
    let r23 = exact_len
        .iter()
        .find(|r| r.instance == "rect_width2_height3_i000")
        .unwrap();
    assert_eq!(
        (r23.value, r23.opt, r23.opt_status.as_str()),
        (Some(6), Some(6), "optimal")
    );
    // Instance files and their hashes are saved.
    for r in &rows {
        let f = a.join("instances").join(format!("{}.grid", r.instance));
        let bytes = std::fs::read(&f).unwrap();
        assert_eq!(mowmill::harness::run::sha256_hex(&bytes), r.sha256);
    }
    for f in [
        "stats.csv",
        "manifest.json",
        "plots/exact-time.png",
        "plots/exact-time.svg",
    ] {
        assert!(a.join(f).exists(), "{f} missing");
    }
}

#[test]
fn killed_and_resumed_run_equals_an_uninterrupted_one() {
    let full = temp("full");
    run(&config(), &opts(&full, None, false)).unwrap();
    let killed = temp("killed");
    run(&config(), &opts(&killed, None, false)).unwrap();
    // Simulate a kill: keep the header and the first rows, plus half a line.
    let text = std::fs::read_to_string(killed.join("results.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let keep = lines.len() / 3;
    let mut cut = lines[..keep].join("\n");
    cut.push('\n');
    cut.push_str(&lines[keep][..lines[keep].len() / 2]);
    std::fs::write(killed.join("results.csv"), cut).unwrap();
    run(&config(), &opts(&killed, None, true)).unwrap();
    assert_eq!(comparable(&killed), comparable(&full));
}

#[test]
fn merged_shards_equal_the_unsharded_run() {
    let full = temp("unsharded");
    run(&config(), &opts(&full, None, false)).unwrap();
    let shards: Vec<PathBuf> = (0..3).map(|i| temp(&format!("shard{i}"))).collect();
    for (i, d) in shards.iter().enumerate() {
        run(&config(), &opts(d, Some((i, 3)), false)).unwrap();
    }
    let merged = temp("merged");
    mowmill::harness::merge::merge(&shards, &merged).unwrap();
    assert_eq!(comparable(&merged), comparable(&full));
    assert_eq!(
        std::fs::read_to_string(merged.join("stats.csv")).unwrap(),
        std::fs::read_to_string(full.join("stats.csv")).unwrap()
    );
}

#[test]
fn gate_passes_a_rerun_and_catches_a_planted_regression() {
    let base = temp("gate-base");
    run(&config(), &opts(&base, None, false)).unwrap();
    let cur = temp("gate-cur");
    run(&config(), &opts(&cur, None, false)).unwrap();
    let report = gate(&base.join("stats.csv"), &cur, 0.005).unwrap();
    assert!(report.passed(), "{}", report.table());
    assert!(report.groups_compared > 0);

    // Plant a regression: a baseline whose ratios are better than what the code achieves.
    let text = std::fs::read_to_string(base.join("stats.csv")).unwrap();
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    let headers = rdr.headers().unwrap().clone();
    let col = headers.iter().position(|h| h == "ratio_n_max").unwrap();
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(&headers).unwrap();
    for rec in rdr.records() {
        let rec = rec.unwrap();
        let fields: Vec<String> = rec
            .iter()
            .enumerate()
            .map(|(i, f)| match f.parse::<f64>() {
                Ok(x) if i == col => format!("{:.6}", x * 0.9),
                _ => f.to_string(),
            })
            .collect();
        w.write_record(&fields).unwrap();
    }
    // The gate reads the baseline's results.csv and manifest.json beside its stats.csv, and
    // refuses a stats.csv that is not the statistics of those rows.
    let planted = temp("gate-planted");
    std::fs::create_dir_all(&planted).unwrap();
    for f in ["results.csv", "manifest.json"] {
        std::fs::copy(base.join(f), planted.join(f)).unwrap();
    }
    std::fs::write(planted.join("stats.csv"), w.into_inner().unwrap()).unwrap();
    let err = gate(&planted.join("stats.csv"), &cur, 0.005).unwrap_err();
    assert!(err.to_string().contains("results.csv beside it"), "{err}");

    // A baseline instance that the current run lacks is a failure: the current run loses
    // its rows of one family.
    let rows = std::fs::read_to_string(cur.join("results.csv")).unwrap();
    let gone = temp("gate-gone");
    std::fs::create_dir_all(&gone).unwrap();
    std::fs::copy(cur.join("manifest.json"), gone.join("manifest.json")).unwrap();
    let kept: Vec<&str> = rows.lines().filter(|l| !l.contains(",rect,")).collect();
    std::fs::write(gone.join("results.csv"), kept.join("\n") + "\n").unwrap();
    let report = gate(&base.join("stats.csv"), &gone, 0.005).unwrap();
    assert!(!report.passed());
    assert!(
        report.table().contains("missing in current run"),
        "{}",
        report.table()
    );

    // The CLI exits 1 on the regression and 0 on the rerun.
    let bin = env!("CARGO_BIN_EXE_mowmill");
    let st = Command::new(bin)
        .args(["gate", "--baseline"])
        .arg(base.join("stats.csv"))
        .arg("--current")
        .arg(&cur)
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(0));
    let st = Command::new(bin)
        .args(["gate", "--baseline"])
        .arg(base.join("stats.csv"))
        .arg("--current")
        .arg(&gone)
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(1));
    let st = Command::new(bin)
        .args(["gate", "--baseline"])
        .arg(planted.join("stats.csv"))
        .arg("--current")
        .arg(&cur)
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(2));
}

#[test]
fn malformed_config_is_refused_before_any_job() {
    let dir = temp("badcfg");
    std::fs::create_dir_all(&dir).unwrap();
    let cfg = dir.join("bad.toml");
    std::fs::write(
        &cfg,
        "name = \"x\"\n[[family]]\nfamily = \"rect\"\nwidth = 3\nheigth = 4\n",
    )
    .unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(["bench", "--config"])
        .arg(&cfg)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("bad.toml:5:1") && err.contains("heigth"),
        "{err}"
    );
    assert!(!out.exists(), "no job may run");
}

/// `[options]` in a config: each algorithm runs once per distinct combination of the options
/// that concern it, rows record the options, and variants are named apart so statistics never
/// mix them. The naive merge never beats the smart one's cycle cover turns (same cover).
#[test]
fn config_options_run_every_variant_and_rows_record_them() {
    let out = temp("options");
    let config = Config::parse(
        r#"
name = "options"
seed = 3
[options]
merge = ["smart", "naive"]
coverage4 = [false, true]
cutter = ["square", "disk"]
[[family]]
family = "random-simple"
n = 16
count = 2
algorithms = ["strips-matching", "tsp65", "lawn-mst"]
"#,
        "options.toml",
    )
    .unwrap();
    run(&config, &opts(&out, None, false)).unwrap();
    let rows = read_rows(&out.join("results.csv")).unwrap();
    let names: std::collections::BTreeSet<&str> =
        rows.iter().map(|r| r.algorithm.as_str()).collect();
    let expect = [
        "lawn-mst",
        "lawn-mst[cutter=disk]",
        "strips-matching",
        "strips-matching[coverage4]",
        "strips-matching[merge=naive,coverage4]",
        "strips-matching[merge=naive]",
        "tsp65",
    ];
    assert_eq!(names.into_iter().collect::<Vec<_>>(), expect);
    for r in &rows {
        assert!(
            r.error.is_empty(),
            "{} {}: {}",
            r.instance,
            r.algorithm,
            r.error
        );
        assert_eq!(r.valid, Some(true), "{} {}", r.instance, r.algorithm);
        match r.algorithm.as_str() {
            "strips-matching[merge=naive]" => {
                assert_eq!((r.merge.as_str(), r.coverage4), ("naive", Some(false)))
            }
            "strips-matching[coverage4]" if r.objective == "turns" => {
                assert_eq!((r.merge.as_str(), r.coverage4), ("smart", Some(true)));
                assert!(r.max_coverage.unwrap() <= 4);
            }
            "lawn-mst[cutter=disk]" => {
                assert_eq!(r.cutter, "disk");
                // No registered guarantee covers the disk: measured, not judged.
                assert!(r.guarantee.is_empty() && r.within_guarantee.is_none());
            }
            "tsp65" => assert!(r.merge.is_empty() && r.cutter.is_empty() && r.coverage4.is_none()),
            _ => {}
        }
    }
    // Same cycle cover whatever the merge.
    let cc = |name: &str, inst: &str| {
        rows.iter()
            .find(|r| r.algorithm == name && r.instance == inst && r.objective == "cc-turns")
            .and_then(|r| r.value)
    };
    for inst in rows.iter().map(|r| r.instance.as_str()) {
        assert_eq!(
            cc("strips-matching", inst),
            cc("strips-matching[merge=naive]", inst)
        );
    }
    // Statistics keep the variants apart.
    let stats = std::fs::read_to_string(out.join("stats.csv")).unwrap();
    assert!(stats.contains("strips-matching[merge=naive]"));
    let _ = std::fs::remove_dir_all(&out);
}

/// A `[[exact]]` table of `weighted-cc` with a turn cost makes the milling algorithms report
/// `weighted-cc-c50` (length + 50 · turns of their cycle cover) on every instance, divided by
/// the exact optimum where it was solved (max_n) and by the cheap bound elsewhere.
#[test]
fn weighted_exact_tables_make_algorithms_report_the_weighted_value() {
    let suite = r#"
name = "weighted"
seed = 3

[[family]]
family = "rect"
width = 2
height = [3, 5]
algorithms = ["strips-double", "lawn-mst"]

[[exact]]
objective = "weighted-cc"
turn_cost = 50
max_n = 6
time_limit = 30
"#;
    let dir = temp("weighted");
    run(
        &Config::parse(suite, "w.toml").unwrap(),
        &opts(&dir, None, false),
    )
    .unwrap();
    let rows = comparable(&dir);
    let weighted: Vec<&Row> = rows
        .iter()
        .filter(|r| r.objective == "weighted-cc-c50")
        .collect();
    // One exact row (2 x 3 only) and one strips-double row per instance; no lawn row.
    assert_eq!(weighted.len(), 3, "{weighted:?}");
    for r in &weighted {
        assert!(r.error.is_empty(), "{r:?}");
        let (value, length, turns) = (r.value.unwrap(), r.length.unwrap(), r.turns.unwrap());
        assert_eq!(value, length + 50 * turns, "{r:?}");
    }
    // The 2 x 3 rectangle: its boundary cycle, 6 + 50 * 4.
    let exact = weighted.iter().find(|r| r.algorithm == "exact").unwrap();
    assert_eq!((exact.value, exact.opt), (Some(206), Some(206)));
    let algo = |instance: &str| {
        weighted
            .iter()
            .find(|r| r.algorithm == "strips-double" && r.instance == instance)
            .unwrap()
    };
    let small = algo("rect_width2_height3_i000");
    assert_eq!(small.opt, Some(206));
    assert!(small.value.unwrap() >= 206 && small.guarantee.is_empty());
    let large = algo("rect_width2_height5_i000");
    assert_eq!(large.opt, None);
    // The cheap bound: C times the turn bound of cycle covers.
    assert_eq!(large.lower_bound, Some(200));
    let _ = std::fs::remove_dir_all(&dir);
}
