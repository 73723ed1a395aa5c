//! Long runs lose nothing: resume continues with the config recorded as given and
//! the recorded shard, a kill loses no row, one run at a time per output directory, merge only
//! joins the complete, finished shards of one config, invalid Slurm variables and `--jobs`
//! values are refused.

mod common;

use common::{mowmill, mowmill_env, temp_dir};
use mowmill::harness::rows::{Row, read_rows};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A suite of 7 small instances (rectangles and thin regions) with one exact objective.
const TINY: &str = r#"# a comment the digest sees
name = "tiny"
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

/// Writes `text` as a config file in `dir`.
fn config_file(dir: &Path, name: &str, text: &str) -> PathBuf {
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

/// Asserts exit 2 and that stderr mentions every one of `needles`.
fn assert_refused(o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "expected exit 2\n{err}");
    for n in needles {
        assert!(err.contains(n), "stderr does not mention {n:?}:\n{err}");
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

fn manifest(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap()
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

/// Keeps the header and the first `keep` rows of `dir/results.csv`, plus half of the next
/// line, as a kill in the middle of a write leaves it.
fn cut_results(dir: &Path, keep: usize) {
    let path = dir.join("results.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() > keep + 2, "too few rows to cut");
    let mut cut = lines[..=keep].join("\n");
    cut.push('\n');
    cut.push_str(&lines[keep + 1][..lines[keep + 1].len() / 2]);
    std::fs::write(&path, cut).unwrap();
}

/// Items 1 and 6: a shipped config, killed with SIGKILL mid-way (then half a line appended, as
/// a kill inside a write leaves), resumed with `--resume DIR` alone, gives exactly the rows of
/// an uninterrupted run; the manifest keeps the config text as given and its digest, and the
/// killed run's lock is taken over.
#[test]
fn killed_run_resumed_from_its_recorded_config_equals_an_uninterrupted_one() {
    let dir = temp_dir("lr-kill");
    let (full, killed) = (dir.join("full"), dir.join("killed"));
    let config = Path::new("experiments/ci.toml");
    assert_ok(&bench(config, &full, &[]));
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(config)).unwrap();
    let m = manifest(&full);
    assert_eq!(m["config_toml"].as_str(), Some(text.as_str()));
    assert_eq!(
        m["config_sha256"].as_str().unwrap(),
        mowmill::harness::run::sha256_hex(text.as_bytes())
    );
    assert_eq!(m["rows"].as_u64(), Some(comparable(&full).len() as u64));

    let mut child = Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args([
            "bench",
            "--config",
            s(config),
            "--out",
            s(&killed),
            "--jobs",
            "1",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let results = killed.join("results.csv");
    while std::fs::read_to_string(&results).map_or(0, |t| t.lines().count()) < 6 {
        assert!(
            start.elapsed() < Duration::from_secs(300),
            "no rows written"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        manifest(&killed)["end"].is_null(),
        "the run finished before the kill"
    );
    let written = std::fs::read_to_string(&results).unwrap().lines().count();
    assert!(
        written < comparable(&full).len(),
        "the run finished before the kill"
    );
    assert!(
        killed.join(".lock").exists(),
        "the killed run left its lock"
    );
    let mut f = std::fs::OpenOptions::new()
        .append(true)
        .open(&results)
        .unwrap();
    std::io::Write::write_all(&mut f, b"ci-20260101,random-simple_n20").unwrap();
    drop(f);

    let out = mowmill_env(&["bench", "--resume", s(&killed), "--jobs", "1"], &[]);
    assert_ok(&out);
    assert!(stderr(&out).contains("stale lock"), "{}", stderr(&out));
    assert_eq!(comparable(&killed), comparable(&full));
    assert!(!killed.join(".lock").exists(), "lock not released");
    let m = manifest(&killed);
    assert_eq!(m["config_toml"].as_str(), Some(text.as_str()));
    assert!(m["end"].is_string());
}

/// Item 1: a manifest from before `config_toml` (only the JSON `config`, with nulls) still
/// resumes, by re-encoding the JSON without its nulls and empty lists.
#[test]
fn resume_of_a_manifest_without_config_toml_works() {
    let dir = temp_dir("lr-legacy");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let (full, old) = (dir.join("full"), dir.join("old"));
    assert_ok(&bench(&cfg, &full, &[]));
    assert_ok(&bench(&cfg, &old, &[]));
    let mut m = manifest(&old);
    let obj = m.as_object_mut().unwrap();
    for k in [
        "config_toml",
        "config_sha256",
        "config_file",
        "rows",
        "instances",
    ] {
        obj.remove(k);
    }
    std::fs::write(old.join("manifest.json"), m.to_string()).unwrap();
    cut_results(&old, 5);
    assert_ok(&mowmill_env(&["bench", "--resume", s(&old)], &[]));
    assert_eq!(comparable(&old), comparable(&full));
}

/// Item 1: resuming with a --config whose text differs from the recorded one is refused,
/// naming both; the same file is accepted. The lock is released after the refusal too.
#[test]
fn resume_with_another_config_is_refused() {
    let dir = temp_dir("lr-other-config");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let other = config_file(&dir, "other.toml", &TINY.replace("seed = 7", "seed = 8"));
    let run = dir.join("run");
    assert_ok(&bench(&cfg, &run, &[]));
    cut_results(&run, 4);
    let refused = mowmill_env(&["bench", "--resume", s(&run), "--config", s(&other)], &[]);
    assert_refused(&refused, &["tiny.toml", "other.toml", "sha256"]);
    assert!(
        !run.join(".lock").exists(),
        "lock not released after an error"
    );
    // The file is untouched by the refused resume: still cut.
    assert!(
        !std::fs::read_to_string(run.join("results.csv"))
            .unwrap()
            .ends_with('\n')
    );
    assert_ok(&mowmill_env(
        &["bench", "--resume", s(&run), "--config", s(&cfg)],
        &[],
    ));
    let full = dir.join("full");
    assert_ok(&bench(&cfg, &full, &[]));
    assert_eq!(comparable(&run), comparable(&full));
}

/// Item 1: a resumed shard directory keeps its shard; an explicit other shard, or Slurm
/// variables meaning another one, are refused.
#[test]
fn resumed_shard_keeps_its_shard() {
    let dir = temp_dir("lr-shard-resume");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let (whole, cut) = (dir.join("whole"), dir.join("cut"));
    assert_ok(&bench(&cfg, &whole, &["--shard", "1/3"]));
    assert_ok(&bench(&cfg, &cut, &["--shard", "1/3"]));
    assert_eq!(manifest(&cut)["shard"].as_str(), Some("1/3"));
    cut_results(&cut, 2);
    let other = mowmill_env(&["bench", "--resume", s(&cut), "--shard", "0/3"], &[]);
    assert_refused(&other, &["1/3", "0/3"]);
    let slurm = mowmill_env(
        &["bench", "--resume", s(&cut)],
        &[
            ("SLURM_ARRAY_TASK_ID", "2"),
            ("SLURM_ARRAY_TASK_COUNT", "3"),
        ],
    );
    assert_refused(&slurm, &["1/3", "2/3"]);
    assert_ok(&mowmill_env(&["bench", "--resume", s(&cut)], &[]));
    assert_eq!(manifest(&cut)["shard"].as_str(), Some("1/3"));
    assert_eq!(comparable(&cut), comparable(&whole));
}

/// Item 1: a results.csv written before the `merge`, `cutter`, `coverage4` columns is
/// rewritten in the current header before rows are appended, so every line has every column.
#[test]
fn resume_of_an_old_results_csv_rewrites_its_header() {
    let dir = temp_dir("lr-old-header");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let (full, old) = (dir.join("full"), dir.join("old"));
    assert_ok(&bench(&cfg, &full, &[]));
    assert_ok(&bench(&cfg, &old, &[]));
    // Four older layouts: before the option columns (ending at `error`), before the model
    // columns (ending at `coverage4`) and before `unit` (ending at `direction_sum`). Drop the last columns (none of them holds a comma in a
    // quoted field: they are the last ones) and keep only the header and 6 rows.
    let path = old.join("results.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let cut_columns = |text: &str, k: usize| -> String {
        text.lines()
            .take(7)
            .map(|l| {
                let mut cut = l;
                for _ in 0..k {
                    cut = &cut[..cut.rfind(',').unwrap()];
                }
                format!("{cut}\n")
            })
            .collect()
    };
    let old_text = cut_columns(&text, 12);
    assert!(old_text.lines().next().unwrap().ends_with(",error"));
    let between = cut_columns(&text, 9);
    assert!(between.lines().next().unwrap().ends_with(",coverage4"));
    let before_unit = cut_columns(&text, 2);
    assert!(
        before_unit
            .lines()
            .next()
            .unwrap()
            .ends_with(",direction_sum")
    );
    // And before `theorems` (ending at `unit`).
    let before_theorems = cut_columns(&text, 1);
    assert!(before_theorems.lines().next().unwrap().ends_with(",unit"));
    let (old2, old3, old4) = (dir.join("old2"), dir.join("old3"), dir.join("old4"));
    for (copy, text) in [
        (&old2, &between),
        (&old3, &before_unit),
        (&old4, &before_theorems),
    ] {
        std::fs::create_dir_all(copy).unwrap();
        for f in std::fs::read_dir(&old).unwrap() {
            let f = f.unwrap().path();
            if f.is_file() {
                std::fs::copy(&f, copy.join(f.file_name().unwrap())).unwrap();
            }
        }
        std::fs::create_dir_all(copy.join("instances")).unwrap();
        std::fs::write(copy.join("results.csv"), text).unwrap();
    }
    std::fs::write(&path, &old_text).unwrap();

    for run in [&old, &old2, &old3, &old4] {
        assert_ok(&mowmill_env(
            &["bench", "--resume", s(run), "--config", s(&cfg)],
            &[],
        ));
    }
    let header = std::fs::read_to_string(&path).unwrap();
    let header = header.lines().next().unwrap().to_string();
    assert!(
        header.ends_with(
            ",error,merge,cutter,coverage4,model,d,delta,mu,rho,edges,direction_sum,unit,theorems"
        ),
        "{header}"
    );
    let rows = read_rows(&path).expect("every line has every column");
    let no_options = |rows: Vec<Row>| -> Vec<Row> {
        rows.into_iter()
            .map(|r| Row {
                merge: String::new(),
                cutter: String::new(),
                coverage4: None,
                model: String::new(),
                d: None,
                delta: None,
                mu: None,
                rho: None,
                edges: None,
                direction_sum: None,
                unit: None,
                theorems: String::new(),
                ..r
            })
            .collect()
    };
    assert_eq!(no_options(comparable(&old4)), no_options(comparable(&full)));
    assert_eq!(no_options(comparable(&old3)), no_options(comparable(&full)));
    assert_eq!(no_options(comparable(&old2)), no_options(comparable(&full)));
    assert_eq!(no_options(comparable(&old)), no_options(comparable(&full)));
    // The rows run after the resume record their options.
    assert!(rows.iter().any(|r| r.merge == "smart"));
    // The old rows carry no theorem ids: the claims table refuses the mixed folder rather than
    // count them as exercising nothing.
    for run in [&old, &old4] {
        let o = mowmill_env(
            &["claims", "--from", s(run), "--out", s(&dir.join("claims"))],
            &[],
        );
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains("older mowmill"), "{}", stderr(&o));
    }
    assert!(
        mowmill_env(
            &[
                "claims",
                "--from",
                s(&full),
                "--out",
                s(&dir.join("claims"))
            ],
            &[]
        )
        .status
        .code()
        .is_some_and(|c| c < 2)
    );
}

/// Item 2: a lock held by a running process refuses a second run naming its pid; once that
/// process is gone the lock is taken over (saying so) and released at the end.
#[test]
fn a_live_lock_refuses_and_a_stale_lock_is_taken_over() {
    let dir = temp_dir("lr-lock");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let out = dir.join("run");
    std::fs::create_dir_all(&out).unwrap();
    let mut holder = Command::new("sleep").arg("60").spawn().unwrap();
    let pid = holder.id().to_string();
    std::fs::write(out.join(".lock"), format!("{pid}\n")).unwrap();
    let refused = bench(&cfg, &out, &[]);
    assert_refused(&refused, &[&pid, ".lock"]);
    assert!(
        !out.join("results.csv").exists(),
        "the refused run wrote rows"
    );
    assert_eq!(
        std::fs::read_to_string(out.join(".lock")).unwrap(),
        format!("{pid}\n"),
        "the refused run touched the holder's lock"
    );
    // The test process itself is alive too.
    std::fs::write(out.join(".lock"), format!("{}\n", std::process::id())).unwrap();
    assert_refused(&bench(&cfg, &out, &[]), &[&std::process::id().to_string()]);

    std::fs::write(out.join(".lock"), format!("{pid}\n")).unwrap();
    holder.kill().unwrap();
    holder.wait().unwrap();
    let taken = bench(&cfg, &out, &[]);
    assert_ok(&taken);
    assert!(
        stderr(&taken).contains("stale lock") && stderr(&taken).contains(&pid),
        "{}",
        stderr(&taken)
    );
    assert!(!out.join(".lock").exists(), "lock not released");
    assert!(manifest(&out)["end"].is_string());
}

/// Copies the files merge reads (manifest and results) of a shard directory.
fn copy_shard(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for f in ["manifest.json", "results.csv"] {
        std::fs::copy(from.join(f), to.join(f)).unwrap();
    }
}

/// Item 3: merge refuses a missing shard, a duplicate shard, a truncated shard (half a line,
/// or whole lines missing), an unfinished shard and shards of different configs, listing what
/// is wrong; the complete set merges into the rows of the unsharded run.
#[test]
fn merge_takes_only_the_complete_finished_shards_of_one_config() {
    let dir = temp_dir("lr-merge");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let other = config_file(&dir, "other.toml", &TINY.replace("seed = 7", "seed = 8"));
    let full = dir.join("full");
    assert_ok(&bench(&cfg, &full, &[]));
    let shards: Vec<PathBuf> = (0..3).map(|i| dir.join(format!("s{i}"))).collect();
    for (i, d) in shards.iter().enumerate() {
        assert_ok(&bench(&cfg, d, &["--shard", &format!("{i}/3")]));
    }
    let merge = |dirs: &[&Path], out: &str| {
        let out = dir.join(out);
        let mut args = vec!["merge"];
        args.extend(dirs.iter().map(|d| s(d)));
        let out_s = out.to_str().unwrap().to_string();
        args.extend(["--out", &out_s]);
        (mowmill(&args), out)
    };
    let (s0, s1, s2) = (&shards[0], &shards[1], &shards[2]);

    let (missing, out) = merge(&[s0, s2], "m-missing");
    assert_refused(&missing, &["missing shard(s) 1/3"]);
    assert!(!out.join("results.csv").exists());

    let (dup, _) = merge(&[s0, s1, s1, s2], "m-dup");
    assert_refused(&dup, &["shard 1/3 given 2 times"]);

    let half = dir.join("s2-half");
    copy_shard(s2, &half);
    cut_results(&half, 2);
    let (truncated, _) = merge(&[s0, s1, &half], "m-half");
    assert_refused(&truncated, &["s2-half", "truncated"]);

    let short = dir.join("s2-short");
    copy_shard(s2, &short);
    let text = std::fs::read_to_string(short.join("results.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    std::fs::write(
        short.join("results.csv"),
        lines[..lines.len() - 1].join("\n") + "\n",
    )
    .unwrap();
    let (short_out, _) = merge(&[s0, s1, &short], "m-short");
    assert_refused(&short_out, &["s2-short", "manifest records"]);

    let unfinished = dir.join("s2-unfinished");
    copy_shard(s2, &unfinished);
    let mut m = manifest(&unfinished);
    m["end"] = serde_json::Value::Null;
    std::fs::write(unfinished.join("manifest.json"), m.to_string()).unwrap();
    let (unfinished_out, _) = merge(&[s0, s1, &unfinished], "m-unfinished");
    assert_refused(&unfinished_out, &["s2-unfinished", "not finished"]);
    assert!(!stderr(&unfinished_out).contains("missing"));

    let foreign = dir.join("x2");
    assert_ok(&bench(&other, &foreign, &["--shard", "2/3"]));
    let (mixed, _) = merge(&[s0, s1, &foreign], "m-mixed");
    assert_refused(&mixed, &["different configs", "other.toml", "tiny.toml"]);

    let (whole, _) = merge(&[s0, &dir.join("nowhere"), s1, s2], "m-nowhere");
    assert_refused(&whole, &["nowhere"]);

    let (ok, merged) = merge(&[s2, s0, s1], "m-ok");
    assert_ok(&ok);
    assert_eq!(comparable(&merged), comparable(&full));
    assert_eq!(
        manifest(&merged)["rows"].as_u64(),
        Some(comparable(&full).len() as u64)
    );
}

/// Item 4: set but invalid Slurm array variables are refused, naming the variable, before
/// anything runs; valid ones give the shard (0-based with SLURM_ARRAY_TASK_MIN).
#[test]
fn invalid_slurm_variables_are_refused() {
    let dir = temp_dir("lr-slurm");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let cases: &[(&[(&str, &str)], &str)] = &[
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "3"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
            ],
            "SLURM_ARRAY_TASK_ID=3",
        ),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "x1"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
            ],
            "SLURM_ARRAY_TASK_ID",
        ),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "1"),
                ("SLURM_ARRAY_TASK_COUNT", "four"),
            ],
            "SLURM_ARRAY_TASK_COUNT",
        ),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "0"),
                ("SLURM_ARRAY_TASK_COUNT", "0"),
            ],
            "SLURM_ARRAY_TASK_COUNT=0",
        ),
        (&[("SLURM_ARRAY_TASK_ID", "1")], "SLURM_ARRAY_TASK_COUNT"),
        (&[("SLURM_ARRAY_TASK_COUNT", "4")], "SLURM_ARRAY_TASK_ID"),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "2"),
                ("SLURM_ARRAY_TASK_COUNT", "4"),
                ("SLURM_ARRAY_TASK_MIN", "5"),
            ],
            "SLURM_ARRAY_TASK_MIN=5",
        ),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "2"),
                ("SLURM_ARRAY_TASK_COUNT", "4"),
                ("SLURM_ARRAY_TASK_MIN", "one"),
            ],
            "SLURM_ARRAY_TASK_MIN",
        ),
        (
            &[
                ("SLURM_ARRAY_TASK_ID", "12"),
                ("SLURM_ARRAY_TASK_COUNT", "4"),
                ("SLURM_ARRAY_TASK_MIN", "0"),
            ],
            "SLURM_ARRAY_TASK_ID=12",
        ),
    ];
    for (k, (env, needle)) in cases.iter().enumerate() {
        let out = dir.join(format!("bad{k}"));
        let o = mowmill_env(
            &[
                "bench",
                "--config",
                s(&cfg),
                "--out",
                s(&out),
                "--jobs",
                "1",
            ],
            env,
        );
        assert_refused(&o, &[needle]);
        assert!(!out.join("results.csv").exists(), "case {k} ran: {env:?}");
    }
    let good = dir.join("good");
    let o = mowmill_env(
        &[
            "bench",
            "--config",
            s(&cfg),
            "--out",
            s(&good),
            "--jobs",
            "1",
        ],
        &[
            ("SLURM_ARRAY_TASK_ID", "5"),
            ("SLURM_ARRAY_TASK_COUNT", "3"),
            ("SLURM_ARRAY_TASK_MIN", "4"),
        ],
    );
    assert_ok(&o);
    assert_eq!(manifest(&good)["shard"].as_str(), Some("1/3"));
}

/// The Slurm requeue: the same `bench --config X --out DIR` command with the same variables
/// and SLURM_RESTART_COUNT = 1 continues the killed attempt's directory (taking over the lock
/// it left on another node) and ends with the rows of an uninterrupted shard; without the
/// restart count the lock of the other node refuses it.
#[test]
fn requeued_slurm_task_continues_its_directory() {
    let dir = temp_dir("lr-requeue");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    let (whole, task) = (dir.join("whole"), dir.join("task"));
    let env0 = [
        ("SLURM_ARRAY_TASK_ID", "1"),
        ("SLURM_ARRAY_TASK_COUNT", "2"),
        ("SLURM_JOB_ID", "4242"),
        ("SLURM_RESTART_COUNT", "0"),
    ];
    let args = |out: &Path| -> Vec<String> {
        ["bench", "--config", s(&cfg), "--out", s(out), "--jobs", "1"]
            .map(String::from)
            .to_vec()
    };
    let run = |out: &Path, env: &[(&str, &str)]| {
        let a = args(out);
        mowmill_env(&a.iter().map(String::as_str).collect::<Vec<_>>(), env)
    };
    assert_ok(&run(&whole, &env0));
    assert_ok(&run(&task, &env0));
    // The first attempt was killed on another node: an unfinished manifest, a cut file, its
    // lock left behind.
    cut_results(&task, 3);
    let mut m = manifest(&task);
    m["end"] = serde_json::Value::Null;
    std::fs::write(task.join("manifest.json"), m.to_string()).unwrap();
    std::fs::write(
        task.join(".lock"),
        "999999\nhost=some-other-node\nslurm_job=4242\nrestart=0\n",
    )
    .unwrap();
    assert_refused(&run(&task, &env0), &["999999", "some-other-node"]);
    let mut env1 = env0;
    env1[3] = ("SLURM_RESTART_COUNT", "1");
    let o = run(&task, &env1);
    assert_ok(&o);
    assert!(stderr(&o).contains("requeued"), "{}", stderr(&o));
    assert!(stderr(&o).contains("stale lock"), "{}", stderr(&o));
    assert_eq!(comparable(&task), comparable(&whole));
    assert_eq!(manifest(&task)["shard"].as_str(), Some("1/2"));
}

/// Item 5: `--jobs 0` and `--jobs` beyond 16 per available core are refused naming `--jobs`.
#[test]
fn jobs_out_of_range_are_refused() {
    let dir = temp_dir("lr-jobs");
    let cfg = config_file(&dir, "tiny.toml", TINY);
    for jobs in ["0", "100000"] {
        let out = dir.join(format!("j{jobs}"));
        let o = mowmill(&[
            "bench",
            "--config",
            s(&cfg),
            "--out",
            s(&out),
            "--jobs",
            jobs,
        ]);
        assert_refused(&o, &["--jobs"]);
        assert!(!out.join("results.csv").exists());
    }
    let out = dir.join("j2");
    assert_ok(&mowmill(&[
        "bench",
        "--config",
        s(&cfg),
        "--out",
        s(&out),
        "--jobs",
        "2",
    ]));
}

/// `bench --help` says how a run is continued and what a Slurm task runs.
#[test]
fn bench_help_documents_continuing() {
    let o = mowmill(&["bench", "--help"]);
    let text = String::from_utf8_lossy(&o.stdout);
    for needle in ["SLURM_RESTART_COUNT", "--resume DIR --config X", ".lock"] {
        assert!(text.contains(needle), "{needle} not in:\n{text}");
    }
}
