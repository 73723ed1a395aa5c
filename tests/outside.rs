//! Outside algorithms through the whole harness: every failure mode of a program (crash,
//! time limit, malformed tour, invalid walk) becomes a row, and a good walk is judged like a
//! registered algorithm's (checker, exact optimum, claimed guarantee).

mod common;

use common::{mowmill, temp_dir};
use std::path::Path;
use std::process::Command;

fn write(path: &Path, text: &str) {
    std::fs::write(path, text).unwrap();
}

/// `mowmill bench` of the suite `cfg` into `out`, one job.
fn bench(cfg: &Path, out: &Path) -> std::process::Output {
    mowmill(&[
        "bench",
        "--config",
        cfg.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--jobs",
        "1",
    ])
}

fn rows(dir: &Path) -> Vec<csv::StringRecord> {
    let mut r = csv::Reader::from_path(dir.join("results.csv")).unwrap();
    r.records().map(|x| x.unwrap()).collect()
}

fn column(dir: &Path, name: &str) -> usize {
    let mut r = csv::Reader::from_path(dir.join("results.csv")).unwrap();
    r.headers().unwrap().iter().position(|h| h == name).unwrap()
}

#[test]
fn every_failure_of_an_outside_program_is_a_row() {
    let dir = temp_dir("outside-failures");
    // A 2 x 1 rectangle: the walk [(0,0), (1,0)] mills it (length 2, turns 4).
    let good = r#"printf '{"cycles": [[[0, 0], [1, 0]]]}' > "$1""#;
    let scripts = [
        ("good", good),
        ("crash", "echo 'something broke' >&2; exit 3"),
        ("slow", "sleep 30"),
        ("garbled", r#"printf '{"cycles": [[[0, 0], [1' > "$1""#),
        ("wrong", r#"printf '{"cycles": [[[0, 0]]]}' > "$1""#),
        ("silent", "exit 0"),
    ];
    let mut config = String::from("name = \"outside\"\nseed = 1\n");
    for (name, body) in scripts {
        write(&dir.join(format!("{name}.sh")), body);
        config += &format!(
            "[[algorithm]]\nname = \"{name}\"\ncommand = [\"sh\", \"{name}.sh\", \"{{tour_out}}\"]\n\
             objectives = [\"length\"]\nguarantee = {{ objective = \"length\", factor = \"1\" }}\n\
             time_limit = 1\n"
        );
    }
    config += "[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 1\nalgorithms = [\"good\", \"crash\", \"slow\", \"garbled\", \"wrong\", \"silent\"]\n\
               [[exact]]\nobjective = \"length\"\nmax_n = 10\ntime_limit = 20\n";
    let cfg = dir.join("suite.toml");
    write(&cfg, &config);
    let out = dir.join("run");
    let o = bench(&cfg, &out);
    // The invalid walk of `wrong` makes the run exit 1 once every row is written.
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let (algo, valid, error, within, value, opt) = (
        column(&out, "algorithm"),
        column(&out, "valid"),
        column(&out, "error"),
        column(&out, "within_guarantee"),
        column(&out, "value"),
        column(&out, "opt"),
    );
    let rows = rows(&out);
    let row = |name: &str| {
        rows.iter()
            .find(|r| &r[algo] == name)
            .unwrap_or_else(|| panic!("no row for {name}"))
    };
    // The good walk is checked, divided by the exact optimum and its claim decided.
    let g = row("good");
    assert_eq!(
        (&g[valid], &g[error], &g[value], &g[opt]),
        ("true", "", "2", "2")
    );
    assert_eq!(&g[within], "true");
    let expect_error = [
        ("crash", "something broke"),
        ("slow", "time limit"),
        ("garbled", "malformed tour"),
        ("silent", "wrote no tour file"),
    ];
    for (name, needle) in expect_error {
        let r = row(name);
        assert!(r[error].contains(needle), "{name}: {:?}", &r[error]);
        assert_eq!(&r[valid], "", "{name}: no walk, no validity");
    }
    // A walk that misses a pixel is a row with valid = false, never a lost row.
    let w = row("wrong");
    assert_eq!(&w[valid], "false");
    assert!(!w[error].is_empty());
}

#[test]
fn a_bad_outside_declaration_is_refused_with_the_key() {
    let dir = temp_dir("outside-bad");
    let cfg = dir.join("bad.toml");
    write(
        &cfg,
        "name = \"x\"\n[[algorithm]]\nname = \"a\"\ncommand = [\"sh\", \"{instance}\"]\n\
         objectives = [\"length\"]\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n",
    );
    let o = mowmill(&[
        "bench",
        "--config",
        cfg.to_str().unwrap(),
        "--out",
        "/nonexistent/x",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("algorithm[0]") && err.contains("{tour_out}"),
        "{err}"
    );
}

#[test]
fn solve_runs_the_python_example() {
    if Command::new("python3").arg("--version").output().is_err() {
        eprintln!("python3 is not installed: the Python example is not run (the sh tests are)");
        return;
    }
    let dir = temp_dir("outside-solve");
    let tour = dir.join("tour.json");
    let o = mowmill(&[
        "solve",
        "instances/fixtures/dumbbell.grid",
        "--command",
        "python3 examples/outside/dfs_tour.py {instance} {tour_out}",
        "--objective",
        "length",
        "--exact",
        "--json",
        "--tour-out",
        tour.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["valid"], true);
    assert_eq!(v["opt_status"], "optimal");
    // The doubled DFS tree has length 2(N - 1).
    assert_eq!(v["length"], 2 * (v["n"].as_u64().unwrap() - 1));
    let check = mowmill(&[
        "validate",
        "instances/fixtures/dumbbell.grid",
        "--tour",
        tour.to_str().unwrap(),
    ]);
    assert_eq!(check.status.code(), Some(0));
}

/// `solve FILE.dm --command`: an outside program on a discrete instance gets the `.dm` file and
/// answers in discrete tour JSON; its walk is recounted by the discrete checker, a walk that
/// misses a vertex is invalid (exit 1), and options that do not apply there are refused.
#[test]
fn solve_runs_an_outside_program_on_a_discrete_instance() {
    let dir = temp_dir("outside-discrete");
    // A straight path 0 - 1 - 2: there and back is length 4 with two U-turns (4 turns).
    let dm = dir.join("path.dm");
    write(&dm, "discrete 3\ne 0 1\ne 1 2\nc 1 0 2\n");
    let good = dir.join("good.sh");
    write(
        &good,
        r#"grep -q '^discrete 3' "$1" && printf '{"model": "discrete", "cycles": [[0, 1, 2, 1]]}' > "$2""#,
    );
    let short = dir.join("short.sh");
    write(
        &short,
        r#"printf '{"model": "discrete", "cycles": [[0, 1]]}' > "$2""#,
    );
    let (dm, tour) = (dm.to_str().unwrap(), dir.join("tour.json"));
    let command = |script: &Path| format!("sh {} {{instance}} {{tour_out}}", script.display());
    let o = mowmill(&[
        "solve",
        dm,
        "--command",
        &command(&good),
        "--objective",
        "turns",
        "--json",
        "--tour-out",
        tour.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        (&v["valid"], &v["value"], &v["length"], &v["turns"], &v["n"]),
        (&true.into(), &4.into(), &4.into(), &4.into(), &3.into())
    );
    let check = mowmill(&["validate", dm, "--tour", tour.to_str().unwrap()]);
    assert_eq!(check.status.code(), Some(0));
    let o = mowmill(&["solve", dm, "--command", &command(&short)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stdout).contains("INVALID"));
    for extra in [
        &["--merge", "naive"][..],
        &["--exact"][..],
        &["--objective", "lawn-length"][..],
    ] {
        let mut args = vec!["solve", dm, "--command", "sh x.sh {instance} {tour_out}"];
        args.extend_from_slice(extra);
        let o = mowmill(&args);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("does not apply"));
    }
    // Polygons with non-integral coordinates have no tour file an outside program could write.
    let wkt = dir.join("half.wkt");
    write(&wkt, "POLYGON ((0 0, 4.5 0, 4.5 1.5, 0 1.5, 0 0))\n");
    let o = mowmill(&["solve", wkt.to_str().unwrap(), "--command", &command(&good)]);
    assert_eq!(o.status.code(), Some(2));
}

/// A suite's `[[algorithm]]` runs on discrete families too: the Python example's doubled DFS
/// tree is a valid tour of length 2(n - 1) on every hexagonal instance, within its claim, and
/// the lawn objective it declares is an error row there.
#[test]
fn a_suite_runs_outside_programs_on_discrete_families() {
    if Command::new("python3").arg("--version").output().is_err() {
        eprintln!("python3 is not installed: the Python example is not run (the sh tests are)");
        return;
    }
    let dir = temp_dir("outside-discrete-suite");
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/outside/dfs_tour.py");
    let cfg = dir.join("suite.toml");
    write(
        &cfg,
        &format!(
            "name = \"outside-discrete\"\nseed = 3\n[[algorithm]]\nname = \"dfs-tour\"\n\
             command = [\"python3\", \"{}\", \"{{instance}}\", \"{{tour_out}}\"]\n\
             objectives = [\"length\", \"turns\", \"lawn-length\"]\n\
             guarantee = {{ objective = \"length\", factor = \"2\", against = \"opt\" }}\n\
             [[family]]\nfamily = \"hex\"\nn = [6, 12]\ncount = 2\n\
             [[exact]]\nobjective = \"length\"\nmax_n = 20\ntime_limit = 20\n",
            example.display()
        ),
    );
    let out = dir.join("run");
    let o = bench(&cfg, &out);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let (algo, objective, valid, error, within, length, n) = (
        column(&out, "algorithm"),
        column(&out, "objective"),
        column(&out, "valid"),
        column(&out, "error"),
        column(&out, "within_guarantee"),
        column(&out, "length"),
        column(&out, "n"),
    );
    let rows = rows(&out);
    let dfs: Vec<_> = rows.iter().filter(|r| &r[algo] == "dfs-tour").collect();
    assert_eq!(dfs.len(), 12, "4 instances, 3 objectives");
    // Lawn mowing has no discrete counterpart: an error row, never a milling length.
    let (lawn, dfs): (Vec<_>, Vec<_>) = dfs
        .into_iter()
        .partition(|r| &r[objective] == "lawn-length");
    assert_eq!(lawn.len(), 4);
    for r in lawn {
        assert!(
            r[error].contains("not defined on discrete instances"),
            "{r:?}"
        );
        assert_eq!((&r[valid], &r[length]), ("", ""), "{r:?}");
    }
    for r in dfs {
        assert_eq!((&r[valid], &r[error]), ("true", ""), "{r:?}");
        let n: u64 = r[n].parse().unwrap();
        assert_eq!(r[length].parse::<u64>().unwrap(), 2 * (n - 1), "{r:?}");
        if &r[objective] == "length" {
            assert_eq!(&r[within], "true", "{r:?}");
        }
    }
}
