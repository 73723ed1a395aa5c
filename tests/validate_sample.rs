//! The committed sample of the validate rows (results/validate/sample/, `mowmill sample`)
//! re-run through the bench's code: any value, bound or verdict that moved fails.
//!
//! `committed_validate_sample_is_reproduced` is the slow tier (`-- --ignored`, about two
//! minutes); the fast tests build a tiny run, sample it, check it, and perturb it.

mod common;

use common::{mowmill, temp_dir};
use mowmill::harness::config::Config;
use mowmill::harness::rows::read_rows;
use mowmill::harness::run::{RunOptions, run};
use mowmill::harness::sample::{self, DrawOptions};
use std::path::{Path, PathBuf};

/// The committed sample: every row re-run equals the committed one.
#[test]
#[ignore = "slow tier: re-runs the committed validate sample (about two minutes)"]
fn committed_validate_sample_is_reproduced() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/validate/sample");
    assert!(
        dir.join(sample::INDEX).exists(),
        "{} holds no sample: run scripts/validate.sh (it draws one)",
        dir.display()
    );
    let report = sample::check(&dir, Some(2)).expect("the committed sample reads");
    assert!(report.rows > 0, "the committed sample has no rows");
    let listing: Vec<String> = report.differences.iter().map(|d| d.to_string()).collect();
    assert!(
        report.passed(),
        "{} of {} sampled rows differ from the committed ones (regenerate with \
         scripts/validate.sh if the change is meant):\n{}",
        listing.len(),
        report.rows,
        listing.join("\n")
    );
}

/// A tiny run of every model, with exact objectives and an outside algorithm whose command
/// appends a line to `marker` each time it runs.
fn tiny_run(root: &Path, marker: &Path) -> PathBuf {
    let text = format!(
        r#"
name = "tiny"
seed = 5

[[family]]
family = "random-simple"
n = [8, 12]
count = 3

[[family]]
family = "random-holed"
n = 16
holes = 1
count = 2

[[family]]
family = "voxel"
n = 8
count = 2

[[family]]
family = "ortho-perturbed"
n = 8
count = 2

[[exact]]
objective = "length"
max_n = 20
time_limit = 60

[[exact]]
objective = "cc-turns"
max_n = 20
time_limit = 60

[[algorithm]]
name = "marker"
command = ["sh", "-c", "echo ran >> {marker}; exit 3", "{{tour_out}}"]
objectives = ["length"]
time_limit = 10
"#,
        marker = marker.display()
    );
    let config = Config::parse_in(&text, "tiny.toml", Some(root)).expect("config parses");
    let out = root.join("run");
    let opts = RunOptions {
        out: out.clone(),
        jobs: Some(2),
        resume: false,
        shard: None,
        run_id: "tiny-test".into(),
        command_line: "test".into(),
    };
    run(&config, &opts).expect("the tiny run runs");
    out
}

fn lines(path: &Path) -> usize {
    std::fs::read_to_string(path).map_or(0, |t| t.lines().count())
}

/// Rewrites one field of the first row of `sample.csv` that `pick` accepts; returns the
/// row's (instance, algorithm, objective) and the field's old value.
fn perturb(
    csv_path: &Path,
    column: &str,
    pick: impl Fn(&csv::StringRecord, &csv::StringRecord) -> bool,
    new_value: impl Fn(&str) -> String,
) -> (String, String, String, String) {
    let mut r = csv::Reader::from_path(csv_path).unwrap();
    let header = r.headers().unwrap().clone();
    let col = header.iter().position(|h| h == column).unwrap();
    let mut records: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    let k = records
        .iter()
        .position(|rec| pick(&header, rec))
        .expect("a row to perturb");
    let old = records[k][col].to_string();
    let mut fields: Vec<String> = records[k].iter().map(str::to_string).collect();
    fields[col] = new_value(&old);
    records[k] = csv::StringRecord::from(fields);
    let mut w = csv::Writer::from_path(csv_path).unwrap();
    w.write_record(&header).unwrap();
    for rec in &records {
        w.write_record(rec).unwrap();
    }
    w.flush().unwrap();
    let get = |name: &str| records[k][header.iter().position(|h| h == name).unwrap()].to_string();
    (get("instance"), get("algorithm"), get("objective"), old)
}

fn field<'a>(header: &csv::StringRecord, rec: &'a csv::StringRecord, name: &str) -> &'a str {
    &rec[header.iter().position(|h| h == name).unwrap()]
}

#[test]
fn a_tiny_sample_passes_and_every_perturbation_fails() {
    let root = temp_dir("sample-tiny");
    let marker = root.join("marker.txt");
    let run_dir = tiny_run(&root, &marker);
    let ran = lines(&marker);
    assert!(ran > 0, "the bench ran the outside algorithm");

    let out = root.join("sample");
    let opts = DrawOptions {
        count: 60,
        seed: 3,
        max_seconds: 30.0,
    };
    let index = sample::draw(std::slice::from_ref(&run_dir), &out, &opts).expect("draw");
    let rows = read_rows(&out.join(sample::SAMPLE_CSV)).unwrap();
    assert_eq!(index.rows, rows.len());
    assert!(rows.len() >= 30, "{} rows sampled", rows.len());
    // Every model, exact rows, no error row, no outside row.
    for model in ["grid", "discrete", "ortho"] {
        assert!(rows.iter().any(|r| r.model == model), "no {model} row");
    }
    assert!(rows.iter().any(|r| r.algorithm == "exact"));
    assert!(
        rows.iter()
            .all(|r| r.error.is_empty() && r.algorithm != "marker")
    );
    assert!(
        index.excluded.values().sum::<usize>() > 0,
        "the marker's error rows are counted as excluded: {:?}",
        index.excluded
    );
    // Each sampled instance's exact rows come with it.
    let all = read_rows(&run_dir.join("results.csv")).unwrap();
    for r in &rows {
        for e in all
            .iter()
            .filter(|e| e.instance == r.instance && e.algorithm == "exact")
        {
            assert!(
                rows.contains(e),
                "{} lacks its exact row {}",
                r.instance,
                e.objective
            );
        }
    }
    // The same seed draws the same rows.
    let again = root.join("sample-again");
    sample::draw(std::slice::from_ref(&run_dir), &again, &opts).unwrap();
    assert_eq!(
        std::fs::read(out.join(sample::SAMPLE_CSV)).unwrap(),
        std::fs::read(again.join(sample::SAMPLE_CSV)).unwrap()
    );

    let report = sample::check(&out, Some(2)).expect("check");
    assert_eq!(report.rows, rows.len());
    assert!(report.passed(), "{:?}", report.differences);

    // A moved value fails, naming the row and the column.
    let bad = root.join("sample-bad");
    copy_dir(&out, &bad);
    let (instance, algorithm, objective, old) = perturb(
        &bad.join(sample::SAMPLE_CSV),
        "value",
        |h, rec| field(h, rec, "algorithm") != "exact" && !field(h, rec, "value").is_empty(),
        |v| (v.parse::<u64>().unwrap() + 1).to_string(),
    );
    let report = sample::check(&bad, Some(2)).unwrap();
    assert_eq!(report.differences.len(), 1, "{:?}", report.differences);
    let d = &report.differences[0];
    assert_eq!(
        (&d.instance, &d.algorithm, &d.objective, d.column.as_str()),
        (&instance, &algorithm, &objective, "value")
    );
    assert_eq!(d.now, old);
    assert_eq!(d.committed, (old.parse::<u64>().unwrap() + 1).to_string());
    // The command says so and exits 1.
    let cli = mowmill(&["sample", "--check", bad.to_str().unwrap(), "--jobs", "2"]);
    let stdout = String::from_utf8_lossy(&cli.stdout);
    assert_eq!(cli.status.code(), Some(1), "{stdout}");
    assert!(
        stdout.contains(&format!("{instance} {algorithm} {objective}: value")),
        "{stdout}"
    );

    // A moved verdict fails too.
    copy_dir(&out, &bad);
    perturb(
        &bad.join(sample::SAMPLE_CSV),
        "within_guarantee",
        |h, rec| !field(h, rec, "within_guarantee").is_empty(),
        |v| {
            if v == "true" {
                "false".into()
            } else {
                "true".into()
            }
        },
    );
    let report = sample::check(&bad, Some(2)).unwrap();
    assert_eq!(
        report
            .differences
            .iter()
            .map(|d| d.column.as_str())
            .collect::<Vec<_>>(),
        ["within_guarantee"]
    );

    // A row naming the outside algorithm is refused, and its command never runs.
    copy_dir(&out, &bad);
    perturb(
        &bad.join(sample::SAMPLE_CSV),
        "algorithm",
        |h, rec| field(h, rec, "algorithm") != "exact" && field(h, rec, "model") == "grid",
        |_| "marker".into(),
    );
    let report = sample::check(&bad, Some(2)).unwrap();
    assert_eq!(lines(&marker), ran, "the check ran the outside command");
    assert!(
        report
            .differences
            .iter()
            .any(|d| d.algorithm == "marker" && d.now.contains("not a registered algorithm")),
        "{:?}",
        report.differences
    );

    // A malformed sample.csv is bad input: exit 2, naming the file and line.
    copy_dir(&out, &bad);
    let path = bad.join(sample::SAMPLE_CSV);
    let mut text = std::fs::read_to_string(&path).unwrap();
    text.push_str("not,a,row\n");
    std::fs::write(&path, text).unwrap();
    let cli = mowmill(&["sample", "--check", bad.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&cli.stderr);
    assert_eq!(cli.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(&format!("{}:{}", path.display(), rows.len() + 2)),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&root);
}

fn copy_dir(from: &Path, to: &Path) {
    let _ = std::fs::remove_dir_all(to);
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}
