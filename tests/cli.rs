//! End-to-end tests of the `mowmill` binary on the hand fixtures in `instances/fixtures/`.

mod common;

use common::{json, mowmill, temp_dir};
use serde_json::Value;

fn fixture(name: &str) -> String {
    format!("instances/fixtures/{name}")
}

#[test]
#[allow(clippy::type_complexity)]
fn info_reports_hand_checked_topology() {
    // name, n, holes, components, boundary, internal, cut, local cut, black, white, thin, strips h, v
    let cases: &[(
        &str,
        u64,
        u64,
        u64,
        u64,
        u64,
        u64,
        u64,
        u64,
        u64,
        bool,
        u64,
        u64,
    )] = &[
        ("rect-2x3.grid", 6, 0, 1, 6, 0, 0, 0, 3, 3, false, 3, 2),
        ("row-1x4.grid", 4, 0, 1, 4, 0, 2, 2, 2, 2, true, 1, 4),
        ("square-3x3.grid", 9, 0, 1, 8, 1, 0, 0, 5, 4, false, 3, 3),
        ("dumbbell.grid", 15, 0, 1, 13, 2, 5, 5, 7, 8, false, 5, 7),
        ("two-holes.grid", 33, 2, 1, 27, 6, 0, 3, 16, 17, false, 7, 9),
        (
            "tailed-frame.grid",
            17,
            2,
            1,
            16,
            1,
            4,
            16,
            8,
            9,
            true,
            7,
            9,
        ),
    ];
    for &(name, n, holes, comps, bnd, int, cut, local, black, white, thin, sh, sv) in cases {
        let out = mowmill(&["info", &fixture(name), "--json"]);
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json(&out);
        let got = |k: &str| {
            v[k].as_u64()
                .unwrap_or_else(|| panic!("{name}: key {k} missing"))
        };
        assert_eq!(got("n"), n, "{name} n");
        assert_eq!(got("holes"), holes, "{name} holes");
        assert_eq!(got("components"), comps, "{name} components");
        assert_eq!(got("boundary"), bnd, "{name} boundary");
        assert_eq!(got("internal"), int, "{name} internal");
        assert_eq!(got("cut_vertices"), cut, "{name} cut_vertices");
        assert_eq!(
            got("local_cut_vertices"),
            local,
            "{name} local_cut_vertices"
        );
        assert_eq!(got("black"), black, "{name} black");
        assert_eq!(got("white"), white, "{name} white");
        assert_eq!(v["thin"].as_bool(), Some(thin), "{name} thin");
        assert_eq!(got("strips_h"), sh, "{name} strips_h");
        assert_eq!(got("strips_v"), sv, "{name} strips_v");
    }
    // Minimum strip covers (turn-cost paper, Lemma 4.4): two columns, one row, three rows.
    for (name, cover) in [
        ("rect-2x3.grid", 2),
        ("row-1x4.grid", 1),
        ("square-3x3.grid", 3),
        ("square-5x5.grid", 5),
    ] {
        let v = json(&mowmill(&["info", &fixture(name), "--json"]));
        assert_eq!(v["strip_cover"].as_u64(), Some(cover), "{name} strip_cover");
    }
}

#[test]
fn validate_recounts_fixture_tours() {
    for (grid, tour, length, turns) in [
        ("rect-2x3.grid", "rect-2x3.tour.json", 6, 4),
        ("row-1x4.grid", "row-1x4.tour.json", 6, 4),
        ("square-3x3.grid", "square-3x3.tour.json", 10, 8),
    ] {
        let out = mowmill(&[
            "validate",
            &fixture(grid),
            "--tour",
            &fixture(tour),
            "--json",
        ]);
        assert!(
            out.status.success(),
            "{grid}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
        let v = json(&out);
        assert_eq!(v["valid"], Value::Bool(true));
        assert_eq!(v["length"].as_u64(), Some(length), "{grid}");
        assert_eq!(v["turns"].as_u64(), Some(turns), "{grid}");
        assert_eq!(v["cycles"].as_u64(), Some(1));
        assert!(v["error"].is_null());
    }
}

#[test]
fn validate_rejects_a_broken_tour_with_exit_1() {
    let out = mowmill(&[
        "validate",
        &fixture("square-3x3.grid"),
        "--tour",
        &fixture("square-3x3.bad-tour.json"),
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let v = json(&out);
    assert_eq!(v["valid"], Value::Bool(false));
    assert_eq!(
        v["error"].as_str(),
        Some("cycle 0, step 6: (2, 2) -> (0, 2) is not a unit move")
    );
    // Lawn mode on the same tour is still broken: the jump is not a unit move.
    let out = mowmill(&[
        "validate",
        &fixture("square-3x3.grid"),
        "--tour",
        &fixture("square-3x3.bad-tour.json"),
        "--mode",
        "lawn",
    ]);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn bad_input_names_file_line_column_and_exits_2() {
    let dir = temp_dir("bad");
    let bad = dir.join("bad.grid");
    std::fs::write(&bad, "; comment\n###\n#?#\n").unwrap();
    let out = mowmill(&["info", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.grid:3:2:") && err.contains("expected '#'"),
        "{err}"
    );

    let empty = dir.join("empty.grid");
    std::fs::write(&empty, "; nothing\n...\n").unwrap();
    let out = mowmill(&["info", empty.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("empty region"));

    let out = mowmill(&["info", "no/such/file.grid"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/file.grid"));

    let badtour = dir.join("t.json");
    std::fs::write(&badtour, "{\"cycles\": [[[0, 0], [1, \"a\"]]]}").unwrap();
    let out = mowmill(&[
        "validate",
        &fixture("rect-2x3.grid"),
        "--tour",
        badtour.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("t.json:1:"));

    let wkt = dir.join("diag.wkt");
    std::fs::write(&wkt, "POLYGON((0 0, 2 0, 2 2, 0 0))").unwrap();
    let out = mowmill(&["info", wkt.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("diag.wkt:1:"));
}

#[test]
fn wkt_instances_read_like_grid_files() {
    let dir = temp_dir("wkt");
    let f = dir.join("donut.wkt");
    std::fs::write(
        &f,
        "POLYGON((0 0, 5 0, 5 4, 0 4, 0 0), (1 1, 4 1, 4 3, 1 3, 1 1))\n",
    )
    .unwrap();
    let v = json(&mowmill(&["info", f.to_str().unwrap(), "--json"]));
    assert_eq!(v["n"].as_u64(), Some(14));
    assert_eq!(v["holes"].as_u64(), Some(1));
}

#[test]
fn gen_is_deterministic_and_info_agrees() {
    let dir = temp_dir("gen");
    let a = dir.join("a.grid");
    let b = dir.join("b.grid");
    for f in [&a, &b] {
        let out = mowmill(&[
            "gen",
            "random-holed",
            "--n",
            "300",
            "--holes",
            "3",
            "--seed",
            "11",
            "--out",
            f.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let (ta, tb) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    assert_eq!(ta, tb);
    let text = String::from_utf8(ta).unwrap();
    assert!(text.contains("; family: random-holed"), "{text}");
    assert!(text.contains("; seed: 11"), "{text}");
    let v = json(&mowmill(&["info", a.to_str().unwrap(), "--json"]));
    assert_eq!(v["n"].as_u64(), Some(300));
    assert_eq!(v["holes"].as_u64(), Some(3));
    assert_eq!(v["components"].as_u64(), Some(1));

    let c = dir.join("c.grid");
    let out = mowmill(&[
        "gen",
        "random-simple",
        "--n",
        "200",
        "--no-cut",
        "--seed",
        "5",
        "--out",
        c.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&mowmill(&["info", c.to_str().unwrap(), "--json"]));
    assert_eq!(
        (
            v["n"].as_u64(),
            v["holes"].as_u64(),
            v["cut_vertices"].as_u64()
        ),
        (Some(200), Some(0), Some(0))
    );

    let d = dir.join("d.grid");
    let out = mowmill(&[
        "gen",
        "donut",
        "--k",
        "2",
        "--side",
        "7",
        "--seed",
        "0",
        "--out",
        d.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&mowmill(&["info", d.to_str().unwrap(), "--json"]));
    assert_eq!(
        (v["n"].as_u64(), v["holes"].as_u64()),
        (Some(49 - 9), Some(1))
    );

    let out = mowmill(&[
        "gen",
        "random-simple",
        "--n",
        "3",
        "--no-cut",
        "--seed",
        "1",
        "--out",
        dir.join("x.grid").to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "no-cut on 3 pixels is impossible"
    );
}

#[test]
fn draw_writes_svg_and_png() {
    let dir = temp_dir("draw");
    for ext in ["svg", "png"] {
        let out_file = dir.join(format!("sq.{ext}"));
        let out = mowmill(&[
            "draw",
            &fixture("square-3x3.grid"),
            "--tour",
            &fixture("square-3x3.tour.json"),
            "--out",
            out_file.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let bytes = std::fs::read(&out_file).unwrap();
        assert!(bytes.len() > 500, "{ext} too small");
        if ext == "png" {
            assert_eq!(&bytes[1..4], b"PNG");
        } else {
            let s = String::from_utf8(bytes).unwrap();
            assert!(
                s.contains("<svg") && s.contains("length 10, turns 8"),
                "caption missing"
            );
        }
    }
    let out = mowmill(&[
        "draw",
        &fixture("square-3x3.grid"),
        "--out",
        dir.join("x.bmpx").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
}

/// A tour objective on a disconnected region is bad input (exit 2 with the reason),
/// not a solver failure (exit 1); the cycle-cover objective accepts it.
#[test]
fn exact_refuses_tours_of_disconnected_regions_with_exit_2() {
    let dir = temp_dir("disconnected");
    let path = dir.join("two.grid");
    std::fs::write(&path, "##.##\n##.##\n").unwrap();
    let file = path.to_str().unwrap();
    for objective in ["length", "tour-turns"] {
        let out = mowmill(&["exact", file, "--objective", objective]);
        assert_eq!(out.status.code(), Some(2), "{objective}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("2 connected components"), "{err}");
    }
    let out = mowmill(&["exact", file, "--objective", "cc-turns", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(json(&out)["value"], 8);
    let _ = std::fs::remove_dir_all(&dir);
}

/// lawn-box's factor is 3α + (3/10)α with α = 3/2 (the paper derives θ = 3/10 for
/// α = 1), i.e. 99/20, not 24/5.
#[test]
fn lawn_box_registers_99_over_20() {
    let out = mowmill(&["algos", "--json"]);
    let list = json(&out);
    let lawn_box = list
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["name"] == "lawn-box")
        .unwrap();
    let g = lawn_box["guarantees"][0].as_str().unwrap();
    assert!(g.starts_with("lawn-length <= 99/20 OPT"), "{g}");
}

/// `bench` ends with a summary on stdout (per algorithm and objective: instances, median and
/// worst ratio, violations, invalid results, errors, time limits; where the files are), prints
/// progress lines when stderr is not a terminal, and exits 1 when a guarantee is violated.
#[test]
fn bench_summarizes_reports_progress_and_exits_1_on_a_violation() {
    let dir = temp_dir("bench-summary");
    let run = |claim: &str, tag: &str| {
        // dfs_tour.py walks a DFS tree twice: length 2(N - 1), so a claim of N is violated.
        let config = format!(
            "name = \"summary\"\nseed = 1\n\
             [[algorithm]]\nname = \"dfs\"\n\
             command = [\"python3\", \"{}\", \"{{instance}}\", \"{{tour_out}}\"]\n\
             objectives = [\"length\"]\n\
             guarantee = {{ objective = \"length\", factor = \"{claim}\", against = \"n\" }}\n\
             [[family]]\nfamily = \"random-simple\"\nn = [10, 12]\ncount = 2\n\
             algorithms = [\"dfs\", \"tsp65\"]\n\
             [[exact]]\nobjective = \"length\"\nmax_n = 12\ntime_limit = 20\n",
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("examples/outside/dfs_tour.py")
                .display()
        );
        let cfg = dir.join(format!("{tag}.toml"));
        std::fs::write(&cfg, config).unwrap();
        let out = dir.join(tag);
        let o = mowmill(&[
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--jobs",
            "1",
        ]);
        (o, out)
    };
    let (o, out) = run("2", "holds");
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stdout}\n{stderr}");
    let line = |name: &str| {
        stdout
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no summary line for {name}:\n{stdout}"))
            .split_whitespace()
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    // algorithm objective instances ratio median worst violations invalid errors time-limit
    let tsp = line("tsp65");
    assert_eq!(&tsp[1..4], ["length", "4", "opt"], "{stdout}");
    assert!(tsp[5].parse::<f64>().unwrap() >= 1.0, "{stdout}");
    assert_eq!(&tsp[6..], ["0", "0", "0", "0"], "{stdout}");
    assert_eq!(line("exact")[2], "4");
    for file in ["results.csv", "stats.csv", "plots", "manifest.json"] {
        let path = out.join(file).display().to_string();
        assert!(stdout.contains(&path), "{file} not named:\n{stdout}");
    }
    // stderr is a pipe here: progress comes as lines, the last one with every instance done.
    assert!(
        stderr.contains("progress: 4/4 instances (100%)"),
        "{stderr}"
    );

    let (o, violated) = run("1", "violated");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}");
    assert_eq!(line_of(&stdout, "dfs")[6], "4", "{stdout}");
    assert!(stdout.contains("FAILED"), "{stdout}");

    // The claims table finds the config's claim by the rows' theorem id (`outside:claim of
    // dfs`): held by the run that claims 2 N, violated by the one that claims N.
    for (dir, verdict) in [(&out, "holds"), (&violated, "violated")] {
        let rows = std::fs::read_to_string(dir.join("results.csv")).unwrap();
        assert!(rows.contains("outside:claim of dfs"), "{rows}");
        let claims = dir.join("claims");
        mowmill(&[
            "claims",
            "--from",
            dir.to_str().unwrap(),
            "--out",
            claims.to_str().unwrap(),
        ]);
        let table = std::fs::read_to_string(claims.join("claims.csv")).unwrap();
        let row = table
            .lines()
            .find(|l| l.contains("claim of dfs"))
            .unwrap_or_else(|| panic!("no row for the claim of dfs:\n{table}"));
        assert!(row.contains(&format!(",{verdict},")), "{row}");
    }
}

fn line_of(text: &str, name: &str) -> Vec<String> {
    text.lines()
        .find(|l| l.split_whitespace().next() == Some(name))
        .unwrap_or_else(|| panic!("no line for {name}:\n{text}"))
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

/// `--help` lists the values `--algo`, `--objective`, `--merge`, `--cutter` and the families
/// accept, so a user never has to guess a name.
#[test]
fn help_lists_the_possible_values() {
    let solve = String::from_utf8_lossy(&mowmill(&["solve", "--help"]).stdout).to_string();
    for name in mowmill::algorithms::names() {
        assert!(solve.contains(name), "solve --help misses {name}");
    }
    for words in [
        "[possible values: length, cc-turns, turns, lawn-length, weighted, weighted-cc]",
        "[possible values: naive, smart]",
        "[possible values: square, square-free, disk]",
    ] {
        assert!(
            solve.contains(words),
            "solve --help misses {words}:\n{solve}"
        );
    }
    let exact = String::from_utf8_lossy(&mowmill(&["exact", "--help"]).stdout).to_string();
    assert!(
        exact.contains(
            "[possible values: length, cc-turns, turns, weighted, weighted-cc, lawn-tsp]"
        ),
        "{exact}"
    );
    let gen_help = String::from_utf8_lossy(&mowmill(&["gen", "--help"]).stdout).to_string();
    assert!(
        gen_help.contains("[possible values: rect, random-simple"),
        "{gen_help}"
    );
    // The old spelling still works.
    let o = mowmill(&[
        "exact",
        "instances/fixtures/rect-2x3.grid",
        "--objective",
        "tour-turns",
        "--json",
    ]);
    assert_eq!(json(&o)["objective"], "turns");
}

/// `exact` has a default time limit, and refuses a limit that is not a positive number.
#[test]
fn exact_time_limit_has_a_default_and_refuses_nan_and_non_positive() {
    let help = String::from_utf8_lossy(&mowmill(&["exact", "--help"]).stdout).to_string();
    assert!(help.contains("[default: 300]"), "{help}");
    for bad in ["NaN", "0", "-5", "inf"] {
        let o = mowmill(&[
            "exact",
            "instances/fixtures/rect-2x3.grid",
            "--objective",
            "length",
            "--time-limit",
            bad,
        ]);
        assert_eq!(o.status.code(), Some(2), "--time-limit {bad}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("--time-limit"), "{err}");
    }
    let o = mowmill(&[
        "exact",
        "instances/fixtures/rect-2x3.grid",
        "--objective",
        "length",
        "--no-time-limit",
        "--json",
    ]);
    assert_eq!(json(&o)["status"], "optimal");
}

/// `tight` writes to a fresh `results/tight-<run-id>/` by default, never to the committed
/// `results/tight`; that folder name is git-ignored.
#[test]
fn tight_defaults_to_a_fresh_git_ignored_folder() {
    let help = String::from_utf8_lossy(&mowmill(&["tight", "--help"]).stdout).to_string();
    assert!(help.contains("results/tight-<run-id>/"), "{help}");
    assert!(!help.contains("[default: results/tight]"), "{help}");
    let o = mowmill(&["tight", "--time-limit", "NaN"]);
    assert_eq!(o.status.code(), Some(2));
    let ignored = std::process::Command::new("git")
        .args([
            "check-ignore",
            "-q",
            "results/tight-20261201T235444Z/tight.csv",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .unwrap();
    assert!(
        ignored.success(),
        "results/tight-<stamp>/ must be git-ignored"
    );
    let committed = std::process::Command::new("git")
        .args(["check-ignore", "-q", "results/tight/tight.csv"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .unwrap();
    assert!(!committed.success(), "results/tight must stay committed");
}

/// README is one screen (what mowmill is, the two commands, a tour, where results land) and
/// every relative link of README and docs/ leads to a file that exists.
#[test]
fn readme_is_one_screen_and_links_resolve() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    // It opens with one screen (what mowmill is, the two commands, the tour, where to read
    // on); the hunt's measured figures follow it.
    let opening: String = readme
        .split("\n## Searching for worst cases")
        .next()
        .unwrap()
        .to_string();
    assert!(
        opening.lines().count() <= 60,
        "README.md's opening is longer than a screen"
    );
    // After it: the hunt's paragraph and the generated findings (the measured tables are in
    // docs/measured.md).
    assert!(readme.lines().count() <= 170, "README.md is too long");
    let readme = opening;
    for command in [
        "scripts/setup.sh && cargo run --release -- bench",
        "scripts/setup.sh && cargo test --release",
    ] {
        assert!(readme.contains(command), "README.md misses `{command}`");
    }
    for step in [
        "mowmill gen",
        "mowmill solve",
        "mowmill draw",
        "mowmill exact",
        "mowmill bench",
    ] {
        assert!(readme.contains(step), "README.md's tour misses `{step}`");
    }
    let mut files = vec![root.join("README.md")];
    for e in std::fs::read_dir(root.join("docs")).unwrap() {
        files.push(e.unwrap().path());
    }
    for file in files
        .iter()
        .filter(|f| f.extension().is_some_and(|x| x == "md"))
    {
        let text = std::fs::read_to_string(file).unwrap();
        for (k, _) in text.match_indices("](") {
            let target = text[k + 2..].split(')').next().unwrap();
            let path = target.split('#').next().unwrap();
            if path.is_empty() || path.contains("://") {
                continue;
            }
            let resolved = file.parent().unwrap().join(path);
            assert!(
                resolved.exists(),
                "{}: link {target} leads nowhere",
                file.display()
            );
        }
    }
}

/// Each cause of an error is printed once, and names the file.
#[test]
fn an_error_cause_is_printed_once() {
    for args in [
        &["info", "/nonexistent/x.grid"][..],
        &["solve", "/nonexistent/x.grid", "--algo", "tsp65"][..],
        &["exact", "/nonexistent/x.grid", "--objective", "length"][..],
    ] {
        let o = mowmill(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.matches("os error 2").count(), 1, "{args:?}: {err}");
        assert!(err.contains("/nonexistent/x.grid"), "{err}");
    }
}

/// `solve`'s text names every guarantee of the algorithm with its verdict, not just the value.
#[test]
fn solve_text_shows_guarantees_and_verdicts() {
    let o = mowmill(&[
        "solve",
        "instances/fixtures/rect-2x3.grid",
        "--algo",
        "tsp65",
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("guarantee length <= 6/5 OPT") && text.contains("): holds"),
        "{text}"
    );
    let o = mowmill(&[
        "solve",
        "instances/fixtures/rect-2x3.grid",
        "--algo",
        "strips-matching",
        "--exact",
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("optimum"), "{text}");
    assert!(text.contains("guarantee turns <= 15/4 OPT"), "{text}");
}

/// `exact --objective weighted-cc --turn-cost 50`: a spur on the middle of a strip of five is
/// best covered by the strip there and back (length 8, 4 turns) and the spur as a one-pixel
/// walk (length 0, 4 turns): 8 + 50 * 8 = 408 (a detour into the spur costs 2 more).
#[test]
fn exact_weighted_cycle_cover_json() {
    let dir = temp_dir("weighted-cc");
    let file = dir.join("spur.grid");
    std::fs::write(&file, "..#..\n#####\n").unwrap();
    let path = file.to_str().unwrap();
    let args = [
        "exact",
        path,
        "--objective",
        "weighted-cc",
        "--turn-cost",
        "50",
        "--json",
    ];
    let o = mowmill(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = json(&o);
    assert_eq!(v["objective"], "weighted-cc");
    assert_eq!(v["turn_cost"], 50);
    assert_eq!(v["status"], "optimal");
    assert_eq!(
        (v["value"].as_u64(), v["lower_bound"].as_u64()),
        (Some(408), Some(408))
    );
    assert_eq!(
        (
            v["length"].as_u64(),
            v["turns"].as_u64(),
            v["cycles"].as_u64()
        ),
        (Some(8), Some(8), Some(2))
    );
    assert_eq!(v["valid"], true);
    // Without a turn cost: bad input.
    let o = mowmill(&["exact", path, "--objective", "weighted-cc"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--turn-cost"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `solve --algo strips-double --objective weighted --turn-cost 50 --exact`: the value is the
/// recount length + 50 * turns, the exact optimum of the 2 x 3 rectangle is its boundary
/// cycle (length 6, four 90° turns: 206), and no guarantee is claimed.
#[test]
fn solve_weighted_with_exact() {
    let dir = temp_dir("solve-weighted");
    let file = dir.join("r23.grid");
    std::fs::write(&file, "###\n###\n").unwrap();
    let path = file.to_str().unwrap();
    let o = mowmill(&[
        "solve",
        path,
        "--algo",
        "strips-double",
        "--objective",
        "weighted",
        "--turn-cost",
        "50",
        "--exact",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = json(&o);
    assert_eq!(v["objective"], "weighted");
    assert_eq!(v["turn_cost"], 50);
    let (value, length, turns) = (
        v["value"].as_u64().unwrap(),
        v["length"].as_u64().unwrap(),
        v["turns"].as_u64().unwrap(),
    );
    assert_eq!(value, length + 50 * turns);
    assert_eq!(v["cycles"], 1);
    assert_eq!(v["exact"]["objective"], "weighted");
    assert_eq!(v["exact"]["status"], "optimal");
    assert_eq!(v["exact"]["value"], 206);
    assert_eq!(v["opt"], 206);
    assert!(value >= 206);
    assert_eq!(v["guarantee"], serde_json::json!([]));
    // weighted-cc measures the cycle cover, with the exact weighted-cc optimum.
    let o = mowmill(&[
        "solve",
        path,
        "--algo",
        "strips-double",
        "--objective",
        "weighted-cc",
        "--turn-cost",
        "50",
        "--exact",
        "--json",
    ]);
    let v = json(&o);
    assert_eq!(v["exact"]["objective"], "weighted-cc");
    assert_eq!(v["exact"]["value"], 206);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A sparse region (the diagonal band, 10^5 pixels in a 20,002² box) is not written as a
/// mostly empty `.grid` picture of 400 MB: exit 2 with the way out; `.gg` and `.wkt` are
/// written by extension and read back to the same region.
#[test]
fn gen_writes_sparse_regions_as_pixel_lists() {
    let dir = temp_dir("sparse-gen");
    let grid = dir.join("band.grid");
    let out = mowmill(&[
        "gen",
        "band",
        "--k",
        "20000",
        "--out",
        grid.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("mostly empty") && err.contains(".gg"), "{err}");
    assert!(!grid.exists());
    for ext in ["gg", "wkt"] {
        let f = dir.join(format!("band.{ext}"));
        let out = mowmill(&["gen", "band", "--k", "20000", "--out", f.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            std::fs::metadata(&f).unwrap().len() < 4_000_000,
            "a small file"
        );
        let info = json(&mowmill(&["info", f.to_str().unwrap(), "--json"]));
        assert_eq!(info["n"], 100_004);
        assert_eq!(info["holes"], 0);
    }
}

/// `exact --start FILE` takes a tour file as its start (the optimum is unchanged), and a start
/// file that is not a tour is refused with exit 2.
#[test]
fn exact_starts_from_a_given_tour() {
    let dir = temp_dir("exact-start");
    let tour = dir.join("tour.json");
    let grid = fixture("two-holes.grid");
    let first = json(&mowmill(&[
        "exact",
        &grid,
        "--objective",
        "turns",
        "--json",
        "--tour-out",
        tour.to_str().unwrap(),
    ]));
    assert_eq!(first["status"], "optimal");
    for objective in ["turns", "cc-turns"] {
        let again = json(&mowmill(&[
            "exact",
            &grid,
            "--objective",
            objective,
            "--json",
            "--start",
            tour.to_str().unwrap(),
        ]));
        assert_eq!(again["status"], "optimal");
        assert!(again["value"].as_u64() <= first["value"].as_u64());
    }
    let bad = dir.join("bad.json");
    std::fs::write(&bad, "{ not json").unwrap();
    let out = mowmill(&[
        "exact",
        &grid,
        "--objective",
        "turns",
        "--start",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
}

/// `claims --findings` saves a violating row's walk from the run folder (`RUN/walks/`), equal to
/// the walk the run wrote, without running the algorithm again (its program is gone by then);
/// a run folder without `walks/` (an older mowmill) or with a broken walk gets a note instead.
#[test]
fn claims_saves_findings_from_the_walks_the_run_kept() {
    let dir = temp_dir("findings-walks");
    // A private copy of the outside program, removed after the bench.
    let program = dir.join("dfs_tour.py");
    std::fs::copy(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/outside/dfs_tour.py"),
        &program,
    )
    .unwrap();
    // dfs_tour.py walks a DFS tree twice: length 2(N - 1) > N, so the claim of N is violated.
    let config = format!(
        "name = \"findings\"\nseed = 1\n\
         [[algorithm]]\nname = \"dfs\"\n\
         command = [\"python3\", \"{}\", \"{{instance}}\", \"{{tour_out}}\"]\n\
         objectives = [\"length\"]\n\
         guarantee = {{ objective = \"length\", factor = \"1\", against = \"n\" }}\n\
         [[family]]\nfamily = \"random-simple\"\nn = 10\ncount = 2\nalgorithms = [\"dfs\"]\n",
        program.display()
    );
    let cfg = dir.join("findings.toml");
    std::fs::write(&cfg, config).unwrap();
    let out = dir.join("run");
    let o = mowmill(&[
        "bench",
        "--config",
        cfg.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--jobs",
        "1",
    ]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let instances: Vec<String> = std::fs::read_dir(out.join("walks"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(instances.len(), 2, "{instances:?}");
    std::fs::remove_file(&program).unwrap();

    let claims = |tag: &str| {
        let findings = dir.join(tag);
        let o = mowmill(&[
            "claims",
            "--from",
            out.to_str().unwrap(),
            "--out",
            dir.join(format!("{tag}-table")).to_str().unwrap(),
            "--findings",
            findings.to_str().unwrap(),
        ]);
        // Exit 1: a claim is violated (not 2 or 3: nothing failed).
        assert_eq!(
            o.status.code(),
            Some(1),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        findings
    };
    let findings = claims("with-walks");
    for instance in &instances {
        let run_walk = out
            .join("walks")
            .join(instance)
            .join("dfs.length.tour.json");
        let stem = format!("claim-of-dfs-dfs-{instance}");
        let saved = std::fs::read(findings.join(format!("{stem}.tour.json")))
            .unwrap_or_else(|e| panic!("{stem}.tour.json: {e}"));
        assert_eq!(saved, std::fs::read(&run_walk).unwrap(), "{instance}");
        let note = std::fs::read_to_string(findings.join(format!("{stem}.md"))).unwrap();
        assert!(
            note.contains(&format!(
                "walk: as the run wrote it, walks/{instance}/dfs.length.tour.json"
            )),
            "{note}"
        );
        assert!(note.contains("checked output: valid: length 18,"), "{note}");
        assert!(findings.join(format!("{stem}.png")).exists());
    }

    // A broken walk file is data: a note, no panic.
    let broken = out
        .join("walks")
        .join(&instances[0])
        .join("dfs.length.tour.json");
    std::fs::write(&broken, "{\"cycles\": [[[0, 0]").unwrap();
    let findings = claims("broken-walk");
    let note =
        std::fs::read_to_string(findings.join(format!("claim-of-dfs-dfs-{}.md", instances[0])))
            .unwrap();
    assert!(note.contains("is unreadable"), "{note}");

    // A run of an older mowmill kept no walks: the note says so, and nothing is run.
    std::fs::remove_dir_all(out.join("walks")).unwrap();
    let findings = claims("older-run");
    for instance in &instances {
        let stem = format!("claim-of-dfs-dfs-{instance}");
        assert!(!findings.join(format!("{stem}.tour.json")).exists());
        let note = std::fs::read_to_string(findings.join(format!("{stem}.md"))).unwrap();
        assert!(note.contains("the run did not keep this walk"), "{note}");
        assert!(
            note.contains("mowmill solve --algo dfs --objective length"),
            "{note}"
        );
    }
}

/// Where `solve`'s time went: the JSON's `phases` (parse, precondition, run, check, each a
/// non-negative number of seconds, the run equal to `seconds`), the text's `time:` line with
/// `--timings`, and `--timings` refused where no phases are printed (exit 2).
#[test]
fn solve_reports_where_the_time_went() {
    let args = [
        "solve",
        "instances/fixtures/rect-2x3.grid",
        "--algo",
        "tsp65",
    ];
    let j = json(&mowmill(&[&args[..], &["--json"]].concat()));
    let phases = &j["phases"];
    for key in ["parse", "precondition", "run", "check"] {
        let s = phases[key].as_f64().unwrap_or(-1.0);
        assert!(s >= 0.0, "{key}: {phases}");
    }
    assert_eq!(phases["run"], j["seconds"]);
    let o = mowmill(&[&args[..], &["--timings"]].concat());
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text.lines().find(|l| l.trim_start().starts_with("time:"));
    let line = line.unwrap_or_else(|| panic!("no time line in {text}"));
    for part in ["parse ", "precondition ", "run ", "check "] {
        assert!(line.contains(part), "{line}");
    }
    let o = mowmill(&[
        "solve",
        "instances/fixtures/rect-2x3.grid",
        "--algo",
        "tsp65",
    ]);
    assert!(!String::from_utf8_lossy(&o.stdout).contains("time:"));
    let dir = temp_dir("timings");
    let wkt = dir.join("half.wkt");
    std::fs::write(&wkt, "POLYGON((0 0, 2.5 0, 2.5 2, 0 2, 0 0))\n").unwrap();
    let args = ["solve", wkt.to_str().unwrap(), "--algo", "corollary4"];
    let o = mowmill(&[&args[..], &["--timings"]].concat());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--timings does not apply"));
}
