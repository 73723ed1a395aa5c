//! The regression gate cannot be fooled: every way found to slip a regression past it (NaN
//! tolerances and ratios, empty baselines, vanished instances, error rows in new groups,
//! tampered values) makes it fail (exit 1) or refuse (exit 2). The fixture is one tiny real
//! bench run; each test gates a mutated copy of its `results.csv` or `stats.csv`.

mod common;

use common::{mowmill, temp_dir};
use std::path::{Path, PathBuf};
use std::process::Output;
use std::sync::OnceLock;

/// Two small generated families, one exact objective, and a `twins` family of two identical
/// instance files (appended by [`fixture`]): removing one twin leaves every mean and max of its
/// groups unchanged, so only the row counts can tell.
const SUITE: &str = r#"
name = "gate-tiny"
seed = 11

[[family]]
family = "rect"
width = [2, 3]
height = [3, 4]

[[family]]
family = "random-simple"
n = [12, 16]
no_cut = true
count = 2

[[exact]]
objective = "length"
max_n = 16
time_limit = 30
"#;

/// The fixture run directory (`results.csv`, `stats.csv`), benched once per test binary.
fn fixture() -> &'static Path {
    static RUN: OnceLock<PathBuf> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = temp_dir("gate-fixture");
        let twins = dir.join("twins");
        std::fs::create_dir_all(&twins).unwrap();
        for name in ["a.grid", "b.grid"] {
            std::fs::write(twins.join(name), "####\n####\n##..\n").unwrap();
        }
        let config = dir.join("suite.toml");
        let files = format!(
            "\n[[files]]\ndir = {:?}\nfamily = \"twins\"\n",
            twins.display().to_string()
        );
        std::fs::write(&config, format!("{SUITE}{files}")).unwrap();
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
        assert!(
            out.status.success(),
            "bench failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        run
    })
}

/// A CSV file as a header and string records, for mutation.
struct Csv {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Csv {
    fn read(path: &Path) -> Csv {
        let mut r = csv::Reader::from_path(path).unwrap();
        let header = r.headers().unwrap().iter().map(String::from).collect();
        let rows = r
            .records()
            .map(|rec| rec.unwrap().iter().map(String::from).collect())
            .collect();
        Csv { header, rows }
    }

    fn write(&self, path: &Path) {
        let mut w = csv::Writer::from_path(path).unwrap();
        w.write_record(&self.header).unwrap();
        for r in &self.rows {
            w.write_record(r).unwrap();
        }
        w.flush().unwrap();
    }

    fn col(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    }

    fn get<'a>(&self, row: &'a [String], name: &str) -> &'a str {
        &row[self.col(name)]
    }

    fn set(&self, row: &mut [String], name: &str, value: &str) {
        row[self.col(name)] = value.to_string();
    }
}

/// A copy of the fixture's `results.csv`, mutated, in a fresh run directory (with the
/// fixture's manifest, so that the run is of the baseline's suite).
fn current(tag: &str, mutate: impl FnOnce(&mut Csv)) -> PathBuf {
    let dir = temp_dir(tag);
    let mut csv = Csv::read(&fixture().join("results.csv"));
    mutate(&mut csv);
    csv.write(&dir.join("results.csv"));
    std::fs::copy(fixture().join("manifest.json"), dir.join("manifest.json")).unwrap();
    dir
}

/// A mutated copy of the fixture's `stats.csv`, beside the fixture's `results.csv` and
/// `manifest.json` (the per-instance baseline the gate reads next to it).
fn baseline(tag: &str, mutate: impl FnOnce(&mut Csv)) -> PathBuf {
    baseline_run(tag, mutate, |_| {}, |_| {})
}

/// A baseline run directory from the fixture's three files, each mutated; returns its
/// `stats.csv`.
fn baseline_run(
    tag: &str,
    stats: impl FnOnce(&mut Csv),
    results: impl FnOnce(&mut Csv),
    manifest: impl FnOnce(&mut serde_json::Value),
) -> PathBuf {
    let dir = temp_dir(tag);
    let mut csv = Csv::read(&fixture().join("stats.csv"));
    stats(&mut csv);
    csv.write(&dir.join("stats.csv"));
    let mut csv = Csv::read(&fixture().join("results.csv"));
    results(&mut csv);
    csv.write(&dir.join("results.csv"));
    let text = std::fs::read_to_string(fixture().join("manifest.json")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    manifest(&mut json);
    std::fs::write(dir.join("manifest.json"), json.to_string()).unwrap();
    dir.join("stats.csv")
}

fn run_gate(baseline: &Path, current: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "gate",
        "--baseline",
        baseline.to_str().unwrap(),
        "--current",
        current.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    mowmill(&args)
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Exit 1 with a FAIL summary and a FAIL line containing each of `needles`.
fn assert_fails(out: &Output, needles: &[&str]) {
    let text = stdout(out);
    assert_eq!(out.status.code(), Some(1), "{text}{}", stderr(out));
    assert!(text.contains("gate: FAIL"), "{text}");
    for needle in needles {
        assert!(
            text.lines()
                .any(|l| l.starts_with("FAIL") && l.contains(needle)),
            "no FAIL line with {needle:?}:\n{text}"
        );
    }
}

/// Exit 2 with a message containing each of `needles` on stderr and no verdict on stdout.
fn assert_refused(out: &Output, needles: &[&str]) {
    let err = stderr(out);
    assert_eq!(out.status.code(), Some(2), "{}{err}", stdout(out));
    assert!(!stdout(out).contains("gate: PASS"), "{}", stdout(out));
    for needle in needles {
        assert!(err.contains(needle), "no {needle:?} in: {err}");
    }
}

/// The ratio as `results.csv` writes it (rounded to 6 decimals).
fn ratio(num: u64, den: u64) -> String {
    format!("{:.6}", (num as f64 / den as f64 * 1e6).round() / 1e6)
}

/// Sets `value` and the three ratios consistently with the row's integers.
fn set_value(csv: &Csv, row: &mut [String], value: u64) {
    csv.set(row, "value", &value.to_string());
    for (r, den) in [
        ("ratio_opt", "opt"),
        ("ratio_lb", "lower_bound"),
        ("ratio_n", "n"),
    ] {
        let d = csv.get(row, den).parse::<u64>().ok().filter(|&d| d > 0);
        let text = d.map_or(String::new(), |d| ratio(value, d));
        csv.set(row, r, &text);
    }
}

/// The row the bench writes when an instance cannot be generated or read.
fn generation_error_row(csv: &Csv, template: &[String], instance: &str) -> Vec<String> {
    let mut row = template.to_vec();
    for c in [
        "sha256",
        "value",
        "length",
        "turns",
        "cycles",
        "max_coverage",
        "opt",
        "opt_status",
        "lower_bound",
        "lb_source",
        "ratio_opt",
        "ratio_lb",
        "ratio_n",
        "guarantee",
        "within_guarantee",
        "valid",
        "merge",
        "cutter",
        "coverage4",
    ] {
        csv.set(&mut row, c, "");
    }
    csv.set(&mut row, "instance", instance);
    csv.set(&mut row, "n", "0");
    csv.set(&mut row, "holes", "0");
    csv.set(&mut row, "algorithm", "instance");
    csv.set(&mut row, "objective", "-");
    csv.set(
        &mut row,
        "error",
        "generation failed: no region after 1000 attempts",
    );
    row
}

/// Rows of an approximation algorithm (not exact) with a value, in the order of the file.
fn algorithm_rows(csv: &Csv) -> Vec<usize> {
    (0..csv.rows.len())
        .filter(|&i| {
            let r = &csv.rows[i];
            csv.get(r, "algorithm") != "exact"
                && csv.get(r, "error").is_empty()
                && !csv.get(r, "value").is_empty()
                && !csv.get(r, "ratio_opt").is_empty()
        })
        .collect()
}

#[test]
fn an_untouched_copy_passes() {
    let cur = current("gate-clean", |_| {});
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    let text = stdout(&out);
    assert_eq!(out.status.code(), Some(0), "{text}{}", stderr(&out));
    assert!(text.contains("gate: PASS"), "{text}");
    let groups: usize = text
        .split(" — ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    assert!(groups >= 4, "{text}");
}

#[test]
fn a_nan_negative_infinite_or_huge_tolerance_is_refused() {
    let cur = current("gate-tol", |_| {});
    for t in ["NaN", "nan", "-0.01", "inf", "1", "1e9", "x"] {
        let out = run_gate(&fixture().join("stats.csv"), &cur, &["--tolerance", t]);
        assert_refused(&out, &["--tolerance", "expected"]);
    }
    let out = run_gate(&fixture().join("stats.csv"), &cur, &["--tolerance=-inf"]);
    assert_refused(&out, &["--tolerance", "expected"]);
    // The library refuses too, as bad input.
    let err =
        mowmill::harness::gate::gate(&fixture().join("stats.csv"), &cur, f64::NAN).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(err.to_string().contains("tolerance"), "{err}");
    // A sane tolerance still works.
    let out = run_gate(&fixture().join("stats.csv"), &cur, &["--tolerance", "0"]);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
}

#[test]
fn a_nan_ratio_cannot_hide_a_ten_percent_regression() {
    let cur = current("gate-nan-row", |csv| {
        let rows = algorithm_rows(csv);
        let first = &csv.rows[rows[0]];
        let group = ["family", "algorithm", "objective"].map(|c| csv.get(first, c).to_string());
        let members: Vec<usize> = rows
            .into_iter()
            .filter(|&i| {
                ["family", "algorithm", "objective"]
                    .iter()
                    .zip(&group)
                    .all(|(c, g)| csv.get(&csv.rows[i], c) == g)
            })
            .collect();
        // Every row of the group 10% worse, consistently with its integers ...
        for &i in &members {
            let mut row = csv.rows[i].clone();
            let v: u64 = csv.get(&row, "value").parse().unwrap();
            set_value(csv, &mut row, (v * 11).div_ceil(10).max(v + 1));
            csv.rows[i] = row;
        }
        // ... and one NaN in each ratio column, which made every comparison false.
        let mut row = csv.rows[members[0]].clone();
        for c in ["ratio_opt", "ratio_lb", "ratio_n"] {
            csv.set(&mut row, c, "NaN");
        }
        csv.rows[members[0]] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(
        &out,
        &[
            "row ratio does not match its integers",
            "ratio_opt mean",
            "ratio_n mean",
        ],
    );
}

#[test]
fn a_nan_or_infinite_baseline_ratio_is_refused() {
    for (tag, bad) in [("nan", "NaN"), ("inf", "inf"), ("neg", "-1.0")] {
        let mut line = 0;
        let base = baseline(&format!("gate-base-{tag}"), |csv| {
            let i = csv
                .rows
                .iter()
                .position(|r| csv.get(r, "size_bin") == "all")
                .unwrap();
            let mut row = csv.rows[i].clone();
            csv.set(&mut row, "ratio_n_mean", bad);
            csv.rows[i] = row;
            line = i + 2;
        });
        let out = run_gate(&base, fixture(), &[]);
        assert_refused(
            &out,
            &[
                &format!("stats.csv:{line}:"),
                "ratio_n_mean",
                "expected a finite ratio",
            ],
        );
    }
    // A ratio whose count says it exists but whose mean is empty is malformed too.
    let base = baseline("gate-base-blank", |csv| {
        let i = csv
            .rows
            .iter()
            .position(|r| csv.get(r, "size_bin") == "all" && csv.get(r, "ratio_opt_count") != "0")
            .unwrap();
        let mut row = csv.rows[i].clone();
        csv.set(&mut row, "ratio_opt_mean", "");
        csv.rows[i] = row;
    });
    assert_refused(
        &run_gate(&base, fixture(), &[]),
        &["ratio_opt_mean is empty"],
    );
}

#[test]
fn an_empty_or_header_only_baseline_is_refused() {
    let dir = temp_dir("gate-base-empty");
    let empty = dir.join("empty.csv");
    std::fs::write(&empty, "").unwrap();
    let header_only = baseline("gate-base-header", |csv| csv.rows.clear());
    for base in [&empty, &header_only] {
        let out = run_gate(base, fixture(), &[]);
        assert_refused(&out, &["no groups", &base.display().to_string()]);
    }
}

#[test]
fn an_error_row_in_a_group_the_baseline_lacks_fails() {
    let cur = current("gate-new-error", |csv| {
        let row = generation_error_row(csv, &csv.rows[0], "extra_instance_i000");
        csv.rows.push(row);
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["error rows in a group the baseline does not have"]);
}

#[test]
fn an_instance_replaced_by_a_generation_error_fails() {
    let cur = current("gate-vanished", |csv| {
        // One twin's rows vanish and one error row appears; the other twin keeps every
        // group's ratios where they were.
        let victim = "twins_b".to_string();
        let template = csv
            .rows
            .iter()
            .find(|r| csv.get(r, "instance") == victim)
            .unwrap()
            .clone();
        let col = csv.col("instance");
        csv.rows.retain(|r| r[col] != victim);
        let row = generation_error_row(csv, &template, &victim);
        csv.rows.push(row);
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(
        &out,
        &[
            "twins / exact / length: fewer rows than the baseline",
            "error rows in a group the baseline does not have",
        ],
    );
}

#[test]
fn a_ratio_that_vanishes_fails() {
    // An exact row loses its proven optimum (ratio_opt 1.0 of every exact row): the group's
    // mean and max do not move, only the count does.
    let cur = current("gate-ratio-gone", |csv| {
        let i = csv
            .rows
            .iter()
            .position(|r| csv.get(r, "algorithm") == "exact" && !csv.get(r, "opt").is_empty())
            .unwrap();
        let mut row = csv.rows[i].clone();
        csv.set(&mut row, "opt", "");
        csv.set(&mut row, "ratio_opt", "");
        csv.rows[i] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["fewer rows with ratio_opt"]);
}

#[test]
fn a_doubled_value_with_its_ratios_left_alone_fails() {
    let cur = current("gate-doubled", |csv| {
        // The row with the largest ratio_n: doubling it raises its group's maximum.
        let i = algorithm_rows(csv)
            .into_iter()
            .max_by(|&a, &b| {
                let r = |i: usize| csv.get(&csv.rows[i], "ratio_n").parse::<f64>().unwrap();
                r(a).total_cmp(&r(b))
            })
            .unwrap();
        let mut row = csv.rows[i].clone();
        let v: u64 = csv.get(&row, "value").parse().unwrap();
        csv.set(&mut row, "value", &(2 * v).to_string());
        csv.rows[i] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    // Both: the row is flagged, and the recomputed ratios (not the stored ones) are compared.
    assert_fails(
        &out,
        &[
            "row ratio does not match its integers",
            "ratio_n max",
            "ratio_opt max",
        ],
    );
}

#[test]
fn duplicated_rows_and_blanked_verdicts_fail() {
    // Copies of a group's best row would pull its mean down.
    let cur = current("gate-dup", |csv| {
        let i = algorithm_rows(csv)[0];
        let row = csv.rows[i].clone();
        for _ in 0..5 {
            csv.rows.push(row.clone());
        }
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["duplicate row"]);

    // A result whose checker verdict was removed.
    let cur = current("gate-no-verdict", |csv| {
        let i = algorithm_rows(csv)[0];
        let mut row = csv.rows[i].clone();
        csv.set(&mut row, "valid", "");
        csv.rows[i] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["result without a validity verdict"]);
}

/// Sets `value` and the column its objective counts (`length` or `turns`), and the ratios, so
/// that the row agrees with itself.
fn set_counted_value(csv: &Csv, row: &mut [String], value: u64) {
    let column = match csv.get(row, "objective") {
        "turns" | "cc-turns" | "tour-turns" => "turns",
        _ => "length",
    };
    csv.set(row, column, &value.to_string());
    set_value(csv, row, value);
}

/// The proven floor of a row: the largest of its `lower_bound` and `opt`.
fn floor(csv: &Csv, row: &[String]) -> u64 {
    ["lower_bound", "opt"]
        .iter()
        .filter_map(|c| csv.get(row, c).parse::<u64>().ok())
        .max()
        .unwrap_or(0)
}

/// A row below its own proven bound is not an improvement: a value halved or zeroed (with its own
/// count and its ratios kept consistent, so only the bound can tell) was reported as an
/// improvement; it is an invalid result, and so is one whose bound and optimum were lowered with it
/// (the baseline's bounds of the same instance still hold).
#[test]
fn halved_or_zeroed_values_are_invalid_not_improvements() {
    for (tag, lower_bounds_too) in [("halved", false), ("halved-lb", true)] {
        let mut name = String::new();
        let cur = current(&format!("gate-{tag}"), |csv| {
            for i in algorithm_rows(csv) {
                let mut row = csv.rows[i].clone();
                let v: u64 = csv.get(&row, "value").parse().unwrap();
                if v < 4 || floor(csv, &row) <= v / 2 {
                    continue;
                }
                if lower_bounds_too {
                    for c in ["lower_bound", "opt"] {
                        if !csv.get(&row, c).is_empty() {
                            csv.set(&mut row, c, &(v / 2).to_string());
                        }
                    }
                }
                set_counted_value(csv, &mut row, v / 2);
                name = format!(
                    "{} {} {}",
                    csv.get(&row, "instance"),
                    csv.get(&row, "algorithm"),
                    csv.get(&row, "objective")
                );
                csv.rows[i] = row;
                break;
            }
        });
        assert!(!name.is_empty());
        let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
        assert_fails(&out, &["invalid result", &name]);
        assert!(
            !stdout(&out)
                .lines()
                .any(|l| l.starts_with("improved") && l.contains(&name)),
            "{}",
            stdout(&out)
        );
    }
    // Every value of every row zeroed, consistently: nothing passes, nothing improves.
    let cur = current("gate-zeroed", |csv| {
        for i in algorithm_rows(csv) {
            let mut row = csv.rows[i].clone();
            set_counted_value(csv, &mut row, 0);
            csv.rows[i] = row;
        }
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["below its proven lower bound"]);
    assert!(!stdout(&out).contains("improved"), "{}", stdout(&out));
}

/// Probes item 2: one instance 1 worse and another of the same group 1 better keeps the
/// group's mean; the per-instance comparison fails the worse one and reports the better one.
#[test]
fn one_instance_worse_and_one_better_fails_per_instance() {
    let (mut worse, mut better) = (String::new(), String::new());
    let cur = current("gate-swap", |csv| {
        let rows = algorithm_rows(csv);
        // Two rows of one (family, algorithm, objective) group, the better one with room
        // above its proven floor.
        let group = |i: usize| {
            ["family", "algorithm", "objective"].map(|c| csv.get(&csv.rows[i], c).to_string())
        };
        let value = |i: usize| csv.get(&csv.rows[i], "value").parse::<u64>().unwrap();
        let (a, b) = rows
            .iter()
            .flat_map(|&a| rows.iter().map(move |&b| (a, b)))
            .find(|&(a, b)| a != b && group(a) == group(b) && value(b) > floor(csv, &csv.rows[b]))
            .expect("two rows of one group");
        let (va, vb) = (value(a), value(b));
        for (i, v) in [(a, va + 1), (b, vb - 1)] {
            let mut row = csv.rows[i].clone();
            set_counted_value(csv, &mut row, v);
            csv.rows[i] = row;
        }
        let id = |i: usize| {
            let r = &csv.rows[i];
            format!(
                "{} {} {}: value",
                csv.get(r, "instance"),
                csv.get(r, "algorithm"),
                csv.get(r, "objective")
            )
        };
        worse = id(a);
        better = id(b);
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &["--tolerance", "0.5"]);
    assert_fails(&out, &[&worse]);
    assert!(
        stdout(&out)
            .lines()
            .any(|l| l.starts_with("improved") && l.contains(&better)),
        "{}",
        stdout(&out)
    );
}

/// Probes item 2: copies of a good row under instance names that differ only by whitespace or
/// case (same sha256) were new rows that pulled their group's mean down; they are duplicates.
#[test]
fn copies_renamed_by_whitespace_or_case_are_duplicates() {
    for (tag, rename) in [
        ("space", (|s: &str| format!(" {s}")) as fn(&str) -> String),
        ("case", |s: &str| s.to_uppercase()),
    ] {
        let cur = current(&format!("gate-rename-{tag}"), |csv| {
            let i = algorithm_rows(csv)[0];
            let mut row = csv.rows[i].clone();
            let renamed = rename(csv.get(&row, "instance"));
            csv.set(&mut row, "instance", &renamed);
            for _ in 0..5 {
                csv.rows.push(row.clone());
            }
        });
        let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
        assert_fails(&out, &["only by whitespace or case"]);
    }
}

/// Probes item 1: a `turns` (or `length`) column that disagrees with the row's `value` was
/// accepted; the row is inconsistent.
#[test]
fn a_count_column_that_disagrees_with_value_fails() {
    let cur = current("gate-turns-off", |csv| {
        let i = (0..csv.rows.len())
            .find(|&i| {
                let r = &csv.rows[i];
                csv.get(r, "objective") == "turns" && !csv.get(r, "turns").is_empty()
            })
            .expect("a turns row");
        let mut row = csv.rows[i].clone();
        let t: u64 = csv.get(&row, "turns").parse().unwrap();
        csv.set(&mut row, "turns", &(t + 2).to_string());
        csv.rows[i] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["disagrees with its turns column"]);
}

/// Probes item 2: `n` or `sha256` altered (the baseline carried no instance identity, so other
/// instances compared as the same suite) fail per instance.
#[test]
fn an_altered_n_or_sha256_fails() {
    let cur = current("gate-n", |csv| {
        let i = algorithm_rows(csv)[0];
        let mut row = csv.rows[i].clone();
        let n: u64 = csv.get(&row, "n").parse().unwrap();
        csv.set(&mut row, "n", &(n + 1).to_string());
        let v: u64 = csv.get(&row, "value").parse().unwrap();
        set_value(csv, &mut row, v);
        csv.rows[i] = row;
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["n differs from the baseline's"]);

    let cur = current("gate-sha", |csv| {
        let col = csv.col("sha256");
        for r in &mut csv.rows {
            if !r[col].is_empty() {
                r[col] = format!("{:0>64}", "f");
            }
        }
    });
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_fails(&out, &["missing in current run"]);
}

/// Probes item 2: a run of another suite (its manifest's config digest) is refused, as is a
/// run without a manifest and a baseline without a digest.
#[test]
fn a_run_of_another_suite_is_refused() {
    let cur = current("gate-other-suite", |_| {});
    let text = std::fs::read_to_string(cur.join("manifest.json")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["config_sha256"] = serde_json::json!("0".repeat(64));
    std::fs::write(cur.join("manifest.json"), json.to_string()).unwrap();
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_refused(&out, &["config_sha256", "baseline's suite"]);

    std::fs::remove_file(cur.join("manifest.json")).unwrap();
    let out = run_gate(&fixture().join("stats.csv"), &cur, &[]);
    assert_refused(&out, &["manifest.json"]);

    let base = baseline_run(
        "gate-base-nodigest",
        |_| {},
        |_| {},
        |m| {
            m.as_object_mut().unwrap().remove("config_sha256");
        },
    );
    let out = run_gate(&base, fixture(), &[]);
    assert_refused(&out, &["no config_sha256"]);
}

/// Probes item 2: a baseline listing a group twice, cut after one group, or whose
/// results.csv is cut or repeats a row is refused (it passed as "1 groups compared").
#[test]
fn a_doubled_or_cut_baseline_is_refused() {
    let base = baseline("gate-base-twice", |csv| {
        let row = csv.rows[0].clone();
        csv.rows.insert(1, row);
    });
    assert_refused(&run_gate(&base, fixture(), &[]), &["listed twice"]);

    let base = baseline("gate-base-cut", |csv| {
        let first =
            ["family", "algorithm", "objective"].map(|c| csv.get(&csv.rows[0], c).to_string());
        let keep: Vec<Vec<String>> = csv
            .rows
            .iter()
            .filter(|r| {
                ["family", "algorithm", "objective"]
                    .iter()
                    .zip(&first)
                    .all(|(c, f)| csv.get(r, c) == f)
            })
            .cloned()
            .collect();
        csv.rows = keep;
    });
    assert_refused(
        &run_gate(&base, fixture(), &[]),
        &["groups", "results.csv beside it"],
    );

    let base = baseline_run(
        "gate-base-rows-cut",
        |_| {},
        |csv| csv.rows.truncate(3),
        |_| {},
    );
    assert_refused(&run_gate(&base, fixture(), &[]), &["records"]);

    let base = baseline_run(
        "gate-base-rows-twice",
        |_| {},
        |csv| {
            let row = csv.rows[0].clone();
            csv.rows[1] = row;
        },
        |_| {},
    );
    assert_refused(&run_gate(&base, fixture(), &[]), &["repeats row"]);
}

/// Probes item 2: the exact command `.ci/run` calls (`--baseline results/baseline/stats.csv`)
/// reads the committed per-instance baseline beside it, which is whole and consistent.
#[test]
fn the_committed_baseline_passes_against_itself() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = root.join("results/baseline/stats.csv");
    let out = run_gate(&base, &root.join("results/baseline"), &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        stdout(&out),
        stderr(&out)
    );
    let text = stdout(&out);
    let compared: usize = text
        .split("gate: PASS — ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let rows = Csv::read(&root.join("results/baseline/results.csv"))
        .rows
        .len();
    assert_eq!(compared, rows, "{text}");
}
