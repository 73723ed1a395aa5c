//! Results folders, manifests and shards are data written by others: a resume never
//! runs a command it took from a results folder, merge never overwrites a run and checks the
//! shards' rows themselves against their config, a changed `[[files]]` folder is not resumed,
//! duplicates in configs are refused, rows that failed because of the machine are run again,
//! and FIFOs, huge configs and huge names are refused.

mod common;

use common::{mowmill, mowmill_env, mowmill_within, temp_dir};
use mowmill::harness::rows::{Row, read_rows, write_sorted};
use std::path::{Path, PathBuf};
use std::process::Output;

/// A suite of 7 small instances with one exact objective (as in tests/longrun.rs).
const TINY: &str = r#"name = "tiny"
seed = 7

[[family]]
family = "rect"
width = [2, 3]
height = [3, 4]

[[family]]
family = "thin"
n = 11
count = 3

[[exact]]
objective = "length"
max_n = 16
time_limit = 30
"#;

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn assert_ok(o: &Output) {
    assert!(
        o.status.success(),
        "expected success, got {:?}\n{}",
        o.status,
        stderr(o)
    );
}

fn assert_refused(o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "expected exit 2\n{err}");
    for n in needles {
        assert!(err.contains(n), "stderr does not mention {n:?}:\n{err}");
    }
}

fn bench(config: &Path, out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "bench",
        "--config",
        s(config),
        "--out",
        s(out),
        "--jobs",
        "1",
    ];
    args.extend_from_slice(extra);
    mowmill_env(&args, &[])
}

fn resume(dir: &Path, extra: &[&str]) -> Output {
    let mut args = vec!["bench", "--resume", s(dir), "--jobs", "1"];
    args.extend_from_slice(extra);
    mowmill_env(&args, &[])
}

fn manifest(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap()
}

fn set_manifest(dir: &Path, m: &serde_json::Value) {
    std::fs::write(dir.join("manifest.json"), m.to_string()).unwrap();
}

/// Keeps the header and the first `keep` rows of `dir/results.csv`.
fn keep_rows(dir: &Path, keep: usize) {
    let path = dir.join("results.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    std::fs::write(&path, lines[..=keep].join("\n") + "\n").unwrap();
}

fn merge(dirs: &[&Path], out: &Path) -> Output {
    let mut args = vec!["merge"];
    args.extend(dirs.iter().map(|d| s(d)));
    args.extend(["--out", s(out)]);
    mowmill(&args)
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for f in ["manifest.json", "results.csv"] {
        std::fs::copy(from.join(f), to.join(f)).unwrap();
    }
}

/// Item 1: an `[[algorithm]]` command planted into a results folder's manifest is never run
/// by `bench --resume DIR` (refused, exit 2, nothing executed); with `--config FILE` the
/// file's digest must equal the manifest's even before any row was written.
#[test]
fn resume_never_runs_a_command_planted_in_the_manifest() {
    let dir = temp_dir("hh-plant");
    let cfg = write(&dir, "tiny.toml", TINY);
    let out = dir.join("run");
    assert_ok(&bench(&cfg, &out, &[]));
    keep_rows(&out, 2);
    let marker = dir.join("planted-ran");
    let mut m = manifest(&out);
    let planted = format!(
        "{TINY}\n[[algorithm]]\nname = \"planted\"\ncommand = [\"sh\", \"-c\", \"touch {} #\", \"{{tour_out}}\"]\n\
         objectives = [\"length\"]\n",
        marker.display()
    );
    m["config_toml"] = planted.clone().into();
    m["config_sha256"] = mowmill::harness::run::sha256_hex(planted.as_bytes()).into();
    set_manifest(&out, &m);
    let o = resume(&out, &[]);
    assert_refused(
        &o,
        &["manifest.json", "outside programs", "planted", "--config"],
    );
    assert!(!marker.exists(), "the planted command ran");

    // With the user's own config the digest decides, also without a results.csv yet.
    std::fs::remove_file(out.join("results.csv")).unwrap();
    let o = resume(&out, &["--config", s(&cfg)]);
    assert_refused(&o, &["cannot resume", "sha256"]);
    assert!(!marker.exists(), "the planted command ran");
}

/// Item 2: `merge --out` refuses an out folder that is one of its input shards, and an
/// existing finished run, as `bench --out` does; nothing of either is changed.
#[test]
fn merge_never_overwrites_a_run_or_its_inputs() {
    let dir = temp_dir("hh-mergeout");
    let cfg = write(&dir, "tiny.toml", TINY);
    let (s0, s1, full) = (dir.join("s0"), dir.join("s1"), dir.join("full"));
    assert_ok(&bench(&cfg, &s0, &["--shard", "0/2"]));
    assert_ok(&bench(&cfg, &s1, &["--shard", "1/2"]));
    assert_ok(&bench(&cfg, &full, &[]));
    let before = std::fs::read(s0.join("results.csv")).unwrap();
    let o = merge(&[&s0, &s1], &s0);
    assert_refused(&o, &["is the input shard"]);
    // The same folder spelled differently is still the input.
    let o = merge(&[&s0, &s1], &dir.join(".").join("s1"));
    assert_refused(&o, &["is the input shard"]);
    assert_eq!(std::fs::read(s0.join("results.csv")).unwrap(), before);
    let full_before = std::fs::read(full.join("results.csv")).unwrap();
    let o = merge(&[&s0, &s1], &full);
    assert_refused(&o, &["not empty"]);
    assert_eq!(
        std::fs::read(full.join("results.csv")).unwrap(),
        full_before
    );
    assert_ok(&merge(&[&s0, &s1], &dir.join("merged")));
}

/// Item 3: merge checks the rows, not only their count: a shard whose results.csv holds the
/// rows of another config under this config's manifest, and a shard missing a row whose
/// manifest count was lowered to match, are refused naming the shard and the row.
#[test]
fn merge_checks_every_shards_rows_against_its_config() {
    let dir = temp_dir("hh-mergerows");
    let cfg = write(&dir, "tiny.toml", TINY);
    let other = write(&dir, "other.toml", &TINY.replace("seed = 7", "seed = 8"));
    let (s0, s1, x1) = (dir.join("s0"), dir.join("s1"), dir.join("x1"));
    assert_ok(&bench(&cfg, &s0, &["--shard", "0/2"]));
    assert_ok(&bench(&cfg, &s1, &["--shard", "1/2"]));
    assert_ok(&bench(&other, &x1, &["--shard", "1/2"]));

    let forged = dir.join("s1-forged");
    copy_dir(&s1, &forged);
    std::fs::copy(x1.join("results.csv"), forged.join("results.csv")).unwrap();
    let mut m = manifest(&forged);
    m["rows"] = (read_rows(&x1.join("results.csv")).unwrap().len() as u64).into();
    set_manifest(&forged, &m);
    let o = merge(&[&s0, &forged], &dir.join("m-forged"));
    assert_refused(&o, &["s1-forged", "row (", "seed"]);

    let short = dir.join("s1-short");
    copy_dir(&s1, &short);
    let mut rows = read_rows(&short.join("results.csv")).unwrap();
    let dropped = rows.remove(1);
    write_sorted(&short.join("results.csv"), &mut rows).unwrap();
    let mut m = manifest(&short);
    m["rows"] = (rows.len() as u64).into();
    set_manifest(&short, &m);
    let o = merge(&[&s0, &short], &dir.join("m-short"));
    assert_refused(
        &o,
        &[
            "s1-short",
            &format!(
                "missing row ({}, {}, {})",
                dropped.instance, dropped.algorithm, dropped.objective
            ),
        ],
    );
    assert_ok(&merge(&[&s0, &s1], &dir.join("m-ok")));
}

/// Item 4: `--resume` after a `[[files]]` folder changed (a file edited, a file added) is
/// refused with a message listing what changed; unchanged, it resumes.
#[test]
fn resume_refuses_a_changed_files_folder() {
    let dir = temp_dir("hh-files");
    let inst = dir.join("inst");
    std::fs::create_dir_all(&inst).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("instances/fixtures");
    for f in ["rect-2x3.grid", "row-1x4.grid"] {
        std::fs::copy(root.join(f), inst.join(f)).unwrap();
    }
    let cfg = write(
        &dir,
        "files.toml",
        "name = \"files\"\n[[files]]\ndir = \"inst\"\nfamily = \"fx\"\n",
    );
    let out = dir.join("run");
    assert_ok(&bench(&cfg, &out, &[]));
    assert_ok(&resume(&out, &[]));
    let original = std::fs::read(inst.join("row-1x4.grid")).unwrap();
    std::fs::copy(root.join("square-3x3.grid"), inst.join("row-1x4.grid"))
        .or_else(|_| std::fs::copy(root.join("dumbbell.grid"), inst.join("row-1x4.grid")))
        .unwrap();
    assert_refused(&resume(&out, &[]), &["fx_row-1x4", "edited"]);
    std::fs::write(inst.join("row-1x4.grid"), &original).unwrap();
    std::fs::copy(root.join("dumbbell.grid"), inst.join("dumbbell.grid")).unwrap();
    assert_refused(&resume(&out, &[]), &["added fx_dumbbell"]);
    std::fs::remove_file(inst.join("dumbbell.grid")).unwrap();
    assert_ok(&resume(&out, &[]));
}

/// Item 6: a row whose error the machine caused (here: "No space left on device", as a full
/// disk left it) is run again by `--resume`, while an error of the instance itself stays.
#[test]
fn resume_retries_rows_the_machine_failed() {
    let dir = temp_dir("hh-enospc");
    let cfg = write(&dir, "tiny.toml", TINY);
    let out = dir.join("run");
    assert_ok(&bench(&cfg, &out, &[]));
    let results = out.join("results.csv");
    let good = read_rows(&results).unwrap();
    let mut rows = good.clone();
    let full_disk = "writing instances/x.grid: No space left on device (os error 28)";
    rows[0] = Row {
        value: None,
        valid: None,
        error: full_disk.into(),
        ..rows[0].clone()
    };
    rows[1].error = "an error of the instance itself".into();
    write_sorted(&results, &mut rows).unwrap();
    assert_ok(&resume(&out, &[]));
    let after = read_rows(&results).unwrap();
    assert_eq!(after.len(), good.len(), "a row was written twice or lost");
    let again = after.iter().find(|r| r.key() == good[0].key()).unwrap();
    assert_eq!(again.error, "", "the machine's error row was not run again");
    assert_eq!(again.value, good[0].value);
    let kept = after.iter().find(|r| r.key() == good[1].key()).unwrap();
    assert_eq!(kept.error, "an error of the instance itself");
}

/// Item 6: an outside program killed by SIGKILL (as the OOM killer does) gives an error row
/// marked `machine: `, which tells a resume to run it again.
#[test]
fn a_row_killed_by_a_signal_is_marked_as_the_machines() {
    let dir = temp_dir("hh-signal");
    write(&dir, "killed.sh", "kill -9 $$\n");
    let cfg = write(
        &dir,
        "killed.toml",
        "name = \"killed\"\n[[algorithm]]\nname = \"killed\"\n\
         command = [\"sh\", \"killed.sh\", \"{tour_out}\"]\nobjectives = [\"length\"]\n\
         time_limit = 10\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 1\n\
         algorithms = [\"killed\"]\n",
    );
    let out = dir.join("run");
    let o = bench(&cfg, &out, &[]);
    assert!(o.status.code().is_some(), "{}", stderr(&o));
    let rows = read_rows(&out.join("results.csv")).unwrap();
    let row = rows.iter().find(|r| r.algorithm == "killed").unwrap();
    assert!(
        row.error.starts_with("machine: "),
        "not marked as the machine's: {:?}",
        row.error
    );
}

/// Items 5 and 7: duplicate algorithms and duplicate objectives, a config over 1 MB and a
/// name over 200 characters are refused with exit 2 naming the file (and line).
#[test]
fn duplicates_huge_configs_and_huge_names_are_refused() {
    let dir = temp_dir("hh-config");
    let dup = write(
        &dir,
        "dup.toml",
        "name = \"dup\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n\
         algorithms = [\"tsp65\", \"tsp65\"]\n",
    );
    assert_refused(
        &bench(&dup, &dir.join("o1"), &[]),
        &["dup.toml:6:", "algorithms[1]", "listed twice"],
    );
    write(&dir, "a.sh", "exit 1\n");
    let dup_obj = write(
        &dir,
        "dupobj.toml",
        "name = \"dupobj\"\n[[algorithm]]\nname = \"a\"\ncommand = [\"sh\", \"a.sh\", \"{tour_out}\"]\n\
         objectives = [\"length\", \"length\"]\n[[family]]\nfamily = \"rect\"\nwidth = 2\n\
         height = 2\n",
    );
    assert_refused(
        &bench(&dup_obj, &dir.join("o2"), &[]),
        &["dupobj.toml:5:", "objectives[1]", "listed twice"],
    );
    let long = write(
        &dir,
        "long.toml",
        &TINY.replace(
            "name = \"tiny\"",
            &format!("name = \"{}\"", "n".repeat(300)),
        ),
    );
    assert_refused(
        &bench(&long, &dir.join("o3"), &[]),
        &["long.toml:1:", "at most 200"],
    );
    let huge = write(
        &dir,
        "huge.toml",
        &format!("{TINY}# {}\n", "x".repeat(2 << 20)),
    );
    assert_refused(
        &bench(&huge, &dir.join("o4"), &[]),
        &["huge.toml", "larger than"],
    );
    assert!(!dir.join("o4").join("results.csv").exists());
}

/// Item 7: a FIFO named like an instance in a `[[files]]` folder is refused naming it (it used
/// to block `bench` for ever).
#[test]
fn a_fifo_in_a_files_folder_is_refused() {
    let dir = temp_dir("hh-fifo");
    let inst = dir.join("inst");
    std::fs::create_dir_all(&inst).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("instances/fixtures");
    std::fs::copy(root.join("rect-2x3.grid"), inst.join("rect-2x3.grid")).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(inst.join("pipe.grid"))
        .status()
        .unwrap();
    assert!(made.success());
    let cfg = write(
        &dir,
        "fifo.toml",
        "name = \"fifo\"\n[[files]]\ndir = \"inst\"\n",
    );
    let out = dir.join("run");
    let o = mowmill_within(
        &[
            "bench",
            "--config",
            s(&cfg),
            "--out",
            s(&out),
            "--jobs",
            "1",
        ],
        60,
    );
    assert_refused(&o, &["pipe.grid", "FIFO", "fifo.toml"]);
}
