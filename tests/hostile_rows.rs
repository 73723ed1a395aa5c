//! Hostile `results.csv` files: a row below its own proven bound or whose value is
//! not its own count is an invalid result in `bench`, `claims` and `gate` (exit 1), never an
//! improvement; an empty `results.csv`, a directory or a link to a device is refused by
//! `claims`, `plot` and `gate` (exit 2) with a message naming the file.

mod common;

use common::{mowmill, temp_dir};
use std::path::{Path, PathBuf};
use std::process::Output;
use std::sync::OnceLock;

const SUITE: &str = r#"
name = "hostile-tiny"
seed = 3

[[family]]
family = "rect"
width = [2, 3]
height = [3]

[[exact]]
objective = "length"
max_n = 16
time_limit = 30
"#;

/// One tiny real bench run, benched once per test binary.
fn fixture() -> &'static Path {
    static RUN: OnceLock<PathBuf> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = temp_dir("hostile-fixture");
        let config = dir.join("suite.toml");
        std::fs::write(&config, SUITE).unwrap();
        let run = dir.join("run");
        let out = mowmill(&[
            "bench",
            "--config",
            config.to_str().unwrap(),
            "--out",
            run.to_str().unwrap(),
            "--jobs",
            "1",
        ]);
        assert!(out.status.success(), "bench failed: {}", text(&out));
        run
    })
}

fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// A copy of the fixture run (results.csv, stats.csv, manifest.json) whose results.csv is
/// `edit`ed as lines of text.
fn copy_run(
    tag: &str,
    edit: impl FnOnce(&mut Vec<csv::StringRecord>, &csv::StringRecord),
) -> PathBuf {
    let dir = temp_dir(tag);
    for f in ["stats.csv", "manifest.json"] {
        std::fs::copy(fixture().join(f), dir.join(f)).unwrap();
    }
    let mut r = csv::Reader::from_path(fixture().join("results.csv")).unwrap();
    let header = r.headers().unwrap().clone();
    let mut rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    edit(&mut rows, &header);
    let mut w = csv::Writer::from_path(dir.join("results.csv")).unwrap();
    w.write_record(&header).unwrap();
    for row in &rows {
        w.write_record(row).unwrap();
    }
    w.flush().unwrap();
    dir
}

/// Sets column `name` of `row`.
fn set(row: &mut csv::StringRecord, header: &csv::StringRecord, name: &str, value: &str) {
    let col = header.iter().position(|h| h == name).unwrap();
    let mut fields: Vec<String> = row.iter().map(String::from).collect();
    fields[col] = value.to_string();
    *row = csv::StringRecord::from(fields);
}

fn get<'a>(row: &'a csv::StringRecord, header: &csv::StringRecord, name: &str) -> &'a str {
    &row[header.iter().position(|h| h == name).unwrap()]
}

/// The fixture with one algorithm `length` row set one below its proven lower bound, its
/// `length` column and ratios following (so only the bound can tell).
fn below_bound(tag: &str) -> PathBuf {
    copy_run(tag, |rows, h| {
        let row = rows
            .iter_mut()
            .find(|r| {
                get(r, h, "algorithm") != "exact"
                    && get(r, h, "objective") == "length"
                    && !get(r, h, "lower_bound").is_empty()
                    && get(r, h, "error").is_empty()
            })
            .expect("a length row with a bound");
        let lb: u64 = get(row, h, "lower_bound").parse().unwrap();
        let v = (lb - 1).to_string();
        set(row, h, "value", &v);
        set(row, h, "length", &v);
        let n: u64 = get(row, h, "n").parse().unwrap();
        let ratio = |a: u64, b: u64| format!("{:.6}", (a as f64 / b as f64 * 1e6).round() / 1e6);
        set(row, h, "ratio_lb", &ratio(lb - 1, lb));
        set(row, h, "ratio_n", &ratio(lb - 1, n));
        if let Ok(opt) = get(row, h, "opt").parse::<u64>() {
            set(row, h, "ratio_opt", &ratio(lb - 1, opt));
        }
    })
}

/// Probes item 1 in `bench`: a resumed run whose results.csv holds a row below its proven
/// lower bound counted it as a valid result (exit 0); it is invalid (exit 1).
#[test]
fn bench_counts_a_row_below_its_bound_as_invalid() {
    let run = below_bound("hostile-bench");
    let out = mowmill(&["bench", "--resume", run.to_str().unwrap(), "--jobs", "1"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let rows = std::fs::read_to_string(run.join("results.csv")).unwrap();
    assert!(rows.contains("is below its proven lower bound"), "{rows}");
}

/// Probes item 1 in `claims`: the same row was evidence of a claim (exit 0); it is an invalid
/// result (exit 1, the row named).
#[test]
fn claims_fails_on_a_row_below_its_bound() {
    let clean = mowmill(&["claims", "--from", fixture().to_str().unwrap()]);
    assert_eq!(clean.status.code(), Some(0), "{}", text(&clean));
    let run = below_bound("hostile-claims");
    let out = mowmill(&["claims", "--from", run.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("is below its proven lower bound"),
        "{}",
        text(&out)
    );
}

/// Probes item 1 in `claims`: a value that disagrees with its own count column is invalid.
#[test]
fn claims_fails_on_a_value_that_is_not_its_count() {
    let run = copy_run("hostile-claims-count", |rows, h| {
        let row = rows
            .iter_mut()
            .find(|r| get(r, h, "objective") == "length" && !get(r, h, "length").is_empty())
            .unwrap();
        let l: u64 = get(row, h, "length").parse().unwrap();
        set(row, h, "length", &(l + 2).to_string());
    });
    let out = mowmill(&["claims", "--from", run.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("disagrees with its length column"),
        "{}",
        text(&out)
    );
}

/// Probes item 3: `claims`, `plot` and `gate` exited 0 on an empty or header-only results.csv,
/// a directory in its place, or aborted on a link to /dev/zero; each is refused with exit 2
/// and a message naming the file.
#[test]
fn empty_directory_and_device_results_are_refused() {
    let header = std::fs::read_to_string(fixture().join("results.csv"))
        .unwrap()
        .lines()
        .next()
        .unwrap()
        .to_string();
    type Plant = Box<dyn Fn(&Path)>;
    let cases: Vec<(&str, Plant, &str)> = vec![
        (
            "empty",
            Box::new(|p| std::fs::write(p, "").unwrap()),
            "no result rows",
        ),
        (
            "header",
            Box::new(move |p| std::fs::write(p, format!("{header}\n")).unwrap()),
            "no result rows",
        ),
        (
            "dir",
            Box::new(|p| std::fs::create_dir(p).unwrap()),
            "is a directory",
        ),
        (
            "zero",
            Box::new(|p| std::os::unix::fs::symlink("/dev/zero", p).unwrap()),
            "not a regular file",
        ),
    ];
    for (tag, make, needle) in &cases {
        let run = temp_dir(&format!("hostile-file-{tag}"));
        for f in ["stats.csv", "manifest.json"] {
            std::fs::copy(fixture().join(f), run.join(f)).unwrap();
        }
        let results = run.join("results.csv");
        make(&results);
        let r = run.to_str().unwrap();
        let base = fixture().join("stats.csv");
        for args in [
            vec!["claims", "--from", r],
            vec!["plot", r],
            vec!["gate", "--baseline", base.to_str().unwrap(), "--current", r],
        ] {
            let out = mowmill(&args);
            assert_eq!(out.status.code(), Some(2), "{tag} {args:?}: {}", text(&out));
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(err.contains(needle), "{tag} {args:?}: {err}");
            assert!(err.contains("results.csv"), "{tag} {args:?}: {err}");
        }
    }
}
