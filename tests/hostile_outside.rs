//! Outside programs that misbehave on purpose (runaway outside programs): a tour
//! file that is a FIFO or a link to /dev/zero, children that outlive the run or escape the
//! process group with `setsid`, a kill of `bench` while a program runs, a memory hog, a flood
//! on stderr, links planted where the scratch folder writes. Each test checks that mowmill
//! ends, reports a clear error and leaves no process behind.

mod common;

use common::temp_dir;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A walk that mills the 2 x 1 rectangle of `instance` (length 2).
const GOOD: &str = r#"printf '{"cycles": [[[0, 0], [1, 0]]]}' > "$1""#;

fn write(path: &Path, text: &str) {
    std::fs::write(path, text).unwrap();
}

/// A folder for one test with the instance `two.grid` (a 2 x 1 rectangle) and `tmp/` (the
/// TMPDIR mowmill gets).
fn setup(tag: &str) -> PathBuf {
    let dir = temp_dir(&format!("hostile-{tag}"));
    write(&dir.join("two.grid"), "##\n");
    std::fs::create_dir(dir.join("tmp")).unwrap();
    dir
}

/// Runs mowmill with TMPDIR = `dir/tmp`; kills it after 60 s (then the code is `None`), as a
/// failure of these tests is often a run that never ends.
fn run(dir: &Path, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("TMPDIR", dir.join("tmp"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = Instant::now() + Duration::from_secs(60);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
            break;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// `mowmill solve two.grid --command "sh SCRIPT {tour_out}"` with `body` as the script.
fn solve(dir: &Path, body: &str, extra: &[&str]) -> Output {
    let script = dir.join("prog.sh");
    write(&script, body);
    let command = format!("sh {} {{tour_out}}", script.display());
    let grid = dir.join("two.grid");
    let mut args = vec![
        "solve",
        grid.to_str().unwrap(),
        "--command",
        &command,
        "--objective",
        "length",
    ];
    args.extend_from_slice(extra);
    run(dir, &args)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Whether process `pid` runs (a zombie counts as ended).
fn alive(pid: i32) -> bool {
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        Ok(stat) => {
            let state = stat.rsplit(')').next().unwrap_or("").trim_start();
            !state.starts_with('Z') && !state.starts_with('X')
        }
        Err(_) => false,
    }
}

/// The pid a script wrote to `dir/name`, waiting up to 20 s for it.
fn pid_in(dir: &Path, name: &str) -> i32 {
    let path = dir.join(name);
    let deadline = Instant::now() + Duration::from_secs(20);
    loop {
        if let Ok(text) = std::fs::read_to_string(&path)
            && let Ok(pid) = text.trim().parse()
        {
            return pid;
        }
        assert!(
            Instant::now() < deadline,
            "{} never written",
            path.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Asserts that each named process ended (allowing 3 s for the kill to land); kills the
/// survivors so that a failing test leaves nothing behind.
fn assert_all_ended(dir: &Path, names: &[&str]) {
    let pids: Vec<(&str, i32)> = names.iter().map(|n| (*n, pid_in(dir, n))).collect();
    let deadline = Instant::now() + Duration::from_secs(3);
    while pids.iter().any(|&(_, p)| alive(p)) && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    let survivors: Vec<_> = pids.iter().filter(|&&(_, p)| alive(p)).copied().collect();
    for &(_, p) in &survivors {
        // SAFETY: kill(2) of a process this test started.
        unsafe {
            libc::kill(p, libc::SIGKILL);
        }
    }
    assert!(survivors.is_empty(), "still running: {survivors:?}");
}

/// A script that starts a child in its group and one that leaves it with `setsid`, and
/// writes their pids (and its own) to `dir`.
fn spawner(dir: &Path) -> String {
    let d = dir.display();
    format!(
        "echo $$ > {d}/direct.tmp && mv {d}/direct.tmp {d}/direct\n\
         sleep 1000 &\necho $! > {d}/group.tmp && mv {d}/group.tmp {d}/group\n\
         setsid sleep 1000 &\necho $! > {d}/escaped.tmp && mv {d}/escaped.tmp {d}/escaped\n\
         sleep 0.3\n"
    )
}

/// Probes item 3: children of a program that exited 0, in its group or escaped with
/// `setsid`, are killed when the run ends (they used to outlive it).
#[test]
fn no_process_of_a_finished_run_survives() {
    let dir = setup("finished");
    let o = solve(&dir, &format!("{}{GOOD}\n", spawner(&dir)), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_all_ended(&dir, &["direct", "group", "escaped"]);
}

/// Probes item 3: the time-limit kill reaches a child that left the process group with
/// `setsid` (only the group was killed before).
#[test]
fn the_time_limit_kills_escaped_children_too() {
    let dir = setup("timeout");
    let o = solve(
        &dir,
        &format!("{}sleep 30\n", spawner(&dir)),
        &["--time-limit", "0.3"],
    );
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("time limit"), "{}", stderr(&o));
    assert_all_ended(&dir, &["direct", "group", "escaped"]);
}

fn bench_config(dir: &Path, body: &str, extra: &str) -> PathBuf {
    write(&dir.join("prog.sh"), body);
    let cfg = dir.join("suite.toml");
    write(
        &cfg,
        &format!(
            "name = \"hostile\"\nseed = 1\n[[algorithm]]\nname = \"prog\"\n\
             command = [\"sh\", \"prog.sh\", \"{{tour_out}}\"]\nobjectives = [\"length\"]\n\
             time_limit = 600\n{extra}\
             [[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 1\nalgorithms = [\"prog\"]\n"
        ),
    );
    cfg
}

fn spawn_bench(dir: &Path, cfg: &Path) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args([
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            dir.join("run").to_str().unwrap(),
            "--jobs",
            "1",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("TMPDIR", dir.join("tmp"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

fn wait_at_most(child: &mut std::process::Child, seconds: u64) -> bool {
    let deadline = Instant::now() + Duration::from_secs(seconds);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            return false;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    true
}

/// Probes item 3: a SIGTERM of `bench` kills the running outside program, its children and
/// the ones that escaped its group (they all ran on before).
#[test]
fn killing_bench_kills_its_outside_programs() {
    let dir = setup("sigterm");
    let cfg = bench_config(&dir, &format!("{}wait\n", spawner(&dir)), "");
    let mut bench = spawn_bench(&dir, &cfg);
    pid_in(&dir, "escaped");
    // SAFETY: kill(2) of the bench this test started.
    unsafe {
        libc::kill(bench.id() as i32, libc::SIGTERM);
    }
    assert!(wait_at_most(&mut bench, 20), "bench ignored SIGTERM");
    assert_all_ended(&dir, &["direct", "group", "escaped"]);
}

/// Probes item 3: even a SIGKILL of `bench` (no handler runs) kills the program it runs,
/// through the death signal (its own children are not reached: docs/outside.md).
#[test]
fn a_sigkill_of_bench_kills_the_program() {
    let dir = setup("sigkill");
    let d = dir.display();
    let cfg = bench_config(
        &dir,
        &format!("echo $$ > {d}/direct.tmp && mv {d}/direct.tmp {d}/direct\nexec sleep 1000\n"),
        "",
    );
    let mut bench = spawn_bench(&dir, &cfg);
    pid_in(&dir, "direct");
    let _ = bench.kill();
    let _ = bench.wait();
    assert_all_ended(&dir, &["direct"]);
}

/// Probes item 2: a program that makes `{tour_out}` a FIFO gets an error (exit 3); mowmill does not
/// wait forever for a writer.
#[test]
fn a_fifo_tour_file_is_refused_not_waited_on() {
    let dir = setup("fifo");
    let o = solve(&dir, "rm -f \"$1\"; mkfifo \"$1\"\n", &[]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("a FIFO, not a regular file"),
        "{}",
        stderr(&o)
    );
}

/// Probes item 2: a `{tour_out}` linked to /dev/zero is not read (it was read until memory
/// ran out: the size check followed the link).
#[test]
fn a_tour_file_linked_to_dev_zero_is_refused() {
    let dir = setup("zero");
    let o = solve(&dir, "rm -f \"$1\"; ln -s /dev/zero \"$1\"\n", &[]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("a symbolic link, not a regular file"),
        "{}",
        stderr(&o)
    );
}

/// Probes item 2: the size bound follows the instance (1 MiB + 1 KiB per pixel): a 3 MB tour
/// file for 2 pixels is refused unread (the bound was 1 GiB whatever the instance).
#[test]
fn a_tour_file_far_above_the_instance_bound_is_refused() {
    let dir = setup("huge");
    let o = solve(&dir, "head -c 3000000 /dev/zero > \"$1\"\n", &[]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("tour file of 3000000 bytes is above the limit of 1050624 bytes"),
        "{}",
        stderr(&o)
    );
}

/// Probes item 4: 50 MB on stderr are drained through a pipe and capped (the first and last
/// 64 KiB kept); they used to land whole in a file (the program sees how much of its stderr
/// is stored at that point).
#[test]
fn a_flood_on_stderr_is_capped() {
    let dir = setup("flood");
    let o = solve(
        &dir,
        "head -c 50000000 /dev/zero | tr '\\0' x >&2\n\
         echo \"stored=$(stat -L -c %s /proc/$$/fd/2)\" >&2\nexit 1\n",
        &[],
    );
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.len() < 10_000, "{} bytes of message", err.len());
    assert!(err.contains("only the first and last 64 KiB kept"), "{err}");
    let stored: u64 = err
        .split("stored=")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no stored= in {err}"));
    assert!(stored < 1 << 20, "{stored} bytes of stderr stored");
}

/// Probes item 3: a default memory limit (4 GiB of address space) is set on the program (it
/// had none).
#[test]
fn the_program_runs_under_the_default_memory_limit() {
    let dir = setup("ulimit");
    let o = solve(&dir, "echo \"limit=$(ulimit -v)\" >&2\nexit 1\n", &[]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("limit=4194304"), "{}", stderr(&o));
}

/// Probes item 3: `--memory-limit` and `memory_limit` cap the program; an allocation that
/// fails under it is reported as out of memory (exit 3 in solve, an error row in bench); a
/// bad value is refused with the option or key (exit 2).
#[test]
fn a_memory_hog_is_out_of_memory() {
    let hog = "awk 'BEGIN { s = \"x\"; while (1) s = s s }'\n";
    let dir = setup("hog");
    let o = solve(&dir, hog, &["--memory-limit", "64M"]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("out of memory (memory_limit 64 MiB)"),
        "{}",
        stderr(&o)
    );

    let o = solve(&dir, GOOD, &["--memory-limit", "lots"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--memory-limit \"lots\""),
        "{}",
        stderr(&o)
    );

    let cfg = bench_config(&dir, hog, "memory_limit = \"64 MiB\"\n");
    let out = dir.join("run");
    let o = run(
        &dir,
        &[
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--jobs",
            "1",
        ],
    );
    assert!(o.status.code().is_some(), "bench hung");
    let mut r = csv::Reader::from_path(out.join("results.csv")).unwrap();
    let error = r
        .headers()
        .unwrap()
        .iter()
        .position(|h| h == "error")
        .unwrap();
    let rows: Vec<_> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 1);
    assert!(
        rows[0][error].contains("out of memory"),
        "{:?}",
        &rows[0][error]
    );

    let bad = bench_config(&dir, GOOD, "memory_limit = -5\n");
    let o = run(
        &dir,
        &[
            "bench",
            "--config",
            bad.to_str().unwrap(),
            "--out",
            "/nonexistent/x",
        ],
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("algorithm[0].memory_limit"),
        "{}",
        stderr(&o)
    );
}

/// Probes item 1: links planted in the scratch folder (and in the next folder the old
/// predictable name `mowmill-<name>-<pid>-<k>` would use) are not followed, and the folder
/// is private (mode 0700). A planted `stderr-*.txt` link used to truncate its target.
#[test]
fn planted_links_in_the_scratch_folder_are_not_followed() {
    let dir = setup("planted");
    let victim = dir.join("victim.txt");
    write(&victim, "precious\n");
    let v = victim.display();
    let d = dir.display();
    let body = format!(
        "w=$(dirname \"$1\")\n\
         stat -c %a \"$w\" >> {d}/modes\n\
         ln -s {v} \"$w/stderr-turns.txt\" 2>/dev/null\n\
         base=${{w%-*}}; k=${{w##*-}}\n\
         case $k in *[!0-9]*|'') k=0 ;; esac\n\
         for i in 1 2 3 4; do n=\"$base-$((k + i))\"; mkdir \"$n\" 2>/dev/null; \
         ln -s {v} \"$n/stderr-all.txt\" 2>/dev/null; ln -s {v} \"$n/stderr-length.txt\" 2>/dev/null; \
         ln -s {v} \"$n/instance.grid\" 2>/dev/null; done\n\
         {GOOD}\n"
    );
    write(&dir.join("prog.sh"), &body);
    let cfg = dir.join("suite.toml");
    write(
        &cfg,
        "name = \"planted\"\nseed = 1\n[[algorithm]]\nname = \"prog\"\n\
         command = [\"sh\", \"prog.sh\", \"{tour_out}\", \"{objective}\"]\n\
         objectives = [\"length\", \"turns\"]\ntime_limit = 20\n\
         [[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 1\nalgorithms = [\"prog\"]\n\
         [[family]]\nfamily = \"rect\"\nwidth = 1\nheight = 2\nalgorithms = [\"prog\"]\n",
    );
    let o = run(
        &dir,
        &[
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            dir.join("run").to_str().unwrap(),
            "--jobs",
            "1",
        ],
    );
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious\n");
    let modes = std::fs::read_to_string(dir.join("modes")).unwrap();
    assert!(!modes.is_empty());
    assert!(
        modes.lines().all(|m| m == "700"),
        "scratch folder modes: {modes}"
    );
}
