//! Benchmark configs are checked before any job runs: every refused value names the file, line
//! and column, the key and what was expected; `mowmill bench` then exits with code 2 without
//! writing anything. Relative `[[files]]` folders are relative to the config file.

mod common;

use common::{mowmill, mowmill_within, temp_dir};
use mowmill::harness::config::Config;
use std::path::Path;

/// Runs `mowmill bench` on `config` written to `dir/name` and returns (exit code, stderr,
/// whether the output folder exists).
fn bench(dir: &Path, name: &str, config: &str) -> (Option<i32>, String, bool) {
    let cfg = dir.join(name);
    std::fs::write(&cfg, config).unwrap();
    let out = dir.join(format!("{name}.out"));
    // A refused config stops at once; on a config that is not refused a run may not end.
    let o = mowmill_within(
        &[
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--jobs",
            "1",
        ],
        60,
    );
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        out.exists(),
    )
}

/// Each config must be refused with exit code 2, before any job, with `file:line:col` and the
/// message parts given.
fn assert_refused(tag: &str, cases: &[(&str, &str, &[&str])]) {
    let dir = temp_dir(tag);
    for (i, (text, place, needles)) in cases.iter().enumerate() {
        let name = format!("c{i}.toml");
        let (code, err, wrote) = bench(&dir, &name, text);
        assert_eq!(code, Some(2), "case {i}: {text}\n{err}");
        assert!(
            !wrote,
            "case {i}: a job ran or the output folder was made: {err}"
        );
        assert!(
            err.contains(&format!("{name}:{place}: ")),
            "case {i}: expected {name}:{place}\n{err}"
        );
        for needle in *needles {
            assert!(err.contains(needle), "case {i}: expected {needle:?}\n{err}");
        }
    }
}

const HEAD: &str = "name = \"t\"\n[[family]]\n";

#[test]
fn out_of_range_parameters_are_refused_at_their_key_before_any_job() {
    let cases: Vec<(String, &str, &[&str])> = vec![
        (
            "family = \"random-simple\"\nn = 0\n".into(),
            "4:5",
            &["family[0].n", "expected n ≥ 1, got 0"],
        ),
        (
            "family = \"random-simple\"\nn = [10, 1000000000000]\n".into(),
            "4:10",
            &["family[0].n[1]", "limit of 20000000"],
        ),
        (
            "family = \"rect\"\nwidth = 0\nheight = 3\n".into(),
            "4:9",
            &["family[0].width", "width ≥ 1"],
        ),
        (
            "family = \"random-simple\"\nn = 10\ncompactness = nan\n".into(),
            "5:15",
            &["family[0].compactness", "between 0 and 1, got NaN"],
        ),
        (
            "family = \"random-simple\"\nn = 10\ncompactness = [0.5, 2]\n".into(),
            "5:21",
            &["family[0].compactness[1]", "between 0 and 1, got 2"],
        ),
        (
            "family = \"random-simple\"\nn = []\n".into(),
            "4:5",
            &["family[0].n", "needs parameter `n`", "`[]` gives no value"],
        ),
        (
            "family = \"rect\"\nwidth = 2\nheight = 2\nholes = 1\n".into(),
            "6:1",
            &[
                "family[0].holes",
                "`holes` does not apply to family rect (it takes: width, height)",
            ],
        ),
        (
            "family = \"rect\"\nwidth = 2\nheight = 2\ncount = 1000000000000\n".into(),
            "6:9",
            &["family[0].count", "from 1 to 1000000"],
        ),
        (
            "family = \"rect\"\nwidth = 2\nheight = 2\ncount = 0\n".into(),
            "6:9",
            &["family[0].count"],
        ),
        // Each value is in range, their combination is not: refused as `gen` refuses it, at
        // the table.
        (
            "family = \"random-holed\"\nn = 20\nholes = [1, 30]\n".into(),
            "2:1",
            &[
                "family[0]",
                "n=20 holes=30",
                "30 holes do not fit in 20 pixels",
            ],
        ),
        (
            "family = \"rect\"\nwidth = 100000\nheight = 100000\n".into(),
            "2:1",
            &["family[0]", "limit"],
        ),
        (
            "family = \"donut\"\nside = 4\nk = [1, 2]\n".into(),
            "2:1",
            &["family[0]", "k=2 side=4", "side ≥ 2k + 1"],
        ),
        // The structured discrete families take `k`, checked as `gen` checks it; others not.
        (
            "family = \"hub-path\"\nn = 10\nk = [2, 0]\n".into(),
            "2:1",
            &["family[0]", "n=10 k=0", "need k >= 1 hubs"],
        ),
        (
            "family = \"collinear-bridges\"\nn = 10\n".into(),
            "2:1",
            &["family[0]", "family collinear-bridges needs k"],
        ),
        (
            "family = \"hex\"\nn = 10\nk = 2\n".into(),
            "5:1",
            &[
                "family[0].k",
                "`k` does not apply to family hex (it takes: n)",
            ],
        ),
        // The whole suite is bounded, not only each count.
        (
            format!(
                "family = \"rect\"\nwidth = [{}]\nheight = 2\ncount = 1000\n",
                {
                    let w: Vec<String> = (1..=1001).map(|w| w.to_string()).collect();
                    w.join(", ")
                }
            ),
            "2:1",
            &["family[0]", "more than 1000000 instances"],
        ),
    ];
    let cases: Vec<(String, &str, &[&str])> = cases
        .into_iter()
        .map(|(body, place, needles)| (format!("{HEAD}{body}"), place, needles))
        .collect();
    let cases: Vec<(&str, &str, &[&str])> =
        cases.iter().map(|(t, p, n)| (t.as_str(), *p, *n)).collect();
    assert_refused("config-ranges", &cases);
}

/// `mowmill gen` and configs refuse a parameter with the same check and the same words.
#[test]
fn gen_and_configs_share_one_parameter_check() {
    let dir = temp_dir("config-gen");
    let grid = dir.join("x.grid");
    let grid = grid.to_str().unwrap();
    for (flags, key, value) in [
        (&["random-simple", "--seed", "1", "--n", "0"][..], "n", "0"),
        (
            &[
                "random-simple",
                "--seed",
                "1",
                "--n",
                "20",
                "--compactness",
                "2",
            ][..],
            "compactness",
            "2",
        ),
        (&["band", "--k", "0"][..], "k", "0"),
        (&["thin43", "--s", "1000000"][..], "s", "1000000"),
    ] {
        let o = mowmill(&[&["gen"], flags, &["--out", grid]].concat());
        assert_eq!(o.status.code(), Some(2), "{flags:?}");
        let gen_err = String::from_utf8_lossy(&o.stderr).into_owned();
        let message = gen_err
            .trim()
            .rsplit(": ")
            .next()
            .unwrap_or_default()
            .to_string();
        let family = flags[0];
        let mut config = format!("{HEAD}family = \"{family}\"\n");
        // The other parameters of the gen call, then the refused one.
        for pair in flags[1..].chunks(2) {
            let k = pair[0].trim_start_matches("--");
            if k != "seed" && k != key {
                config.push_str(&format!("{k} = {}\n", pair[1]));
            }
        }
        config.push_str(&format!("{key} = {value}\n"));
        let (code, err, wrote) = bench(&dir, "c.toml", &config);
        assert_eq!(code, Some(2), "{config}\n{err}");
        assert!(!wrote);
        assert!(
            message.len() > 10 && err.contains(&message),
            "gen said {gen_err:?}, bench said {err:?}"
        );
        assert!(err.contains(&format!("family[0].{key}")), "{err}");
    }
}

#[test]
fn other_values_that_would_break_a_run_are_refused() {
    let rect = "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n";
    let cases: Vec<(String, &str, &[&str])> = vec![
        (
            format!("{rect}[[exact]]\nobjective = \"length\"\nmax_n = 5\ntime_limit = inf\n"),
            "9:14",
            &["exact[0].time_limit", "positive number of seconds", "inf"],
        ),
        (
            format!("{rect}[[exact]]\nobjective = \"length\"\nmax_n = 5\ntime_limit = 0\n"),
            "9:14",
            &["exact[0].time_limit"],
        ),
        (
            format!("{rect}[[exact]]\nobjective = \"length\"\nmax_n = 0\ntime_limit = 1\n"),
            "8:9",
            &["exact[0].max_n", "at least 1"],
        ),
        (
            format!("{rect}[[exact]]\nobjective = \"weighted\"\nmax_n = 5\ntime_limit = 1\n"),
            "6:1",
            &["exact[0]", "turn_cost = C"],
        ),
        (
            format!(
                "{rect}[[exact]]\nobjective = \"turns\"\nmax_n = 5\ntime_limit = 1\n\
                 [[exact]]\nobjective = \"tour-turns\"\nmax_n = 9\ntime_limit = 1\n"
            ),
            "10:1",
            &["exact[1]", "also solved by exact[0]"],
        ),
        (
            format!("{rect}[[exact]]\nobjective = \"lenght\"\nmax_n = 5\ntime_limit = 1\n"),
            "7:13",
            &[
                "exact[0].objective",
                "length, cc-turns, turns, weighted, weighted-cc, lawn-tsp",
            ],
        ),
        // Beyond ~1.8e19 s the timer of an outside algorithm overflowed (a panic mid-run).
        (
            format!(
                "{rect}[[algorithm]]\nname = \"a\"\ncommand = [\"sh\", \"a.sh\", \"{{tour_out}}\"]\n\
                 objectives = [\"length\"]\ntime_limit = 1e300\n"
            ),
            "10:14",
            &["algorithm[0].time_limit", "1e300"],
        ),
        (
            format!(
                "{rect}algorithms = [\"tsp65\", \"my-algo\"]\n[[algorithm]]\nname = \"mine\"\n\
                 command = [\"sh\", \"a.sh\", \"{{tour_out}}\"]\nobjectives = [\"length\"]\n"
            ),
            "6:24",
            &[
                "family[0].algorithms[1]",
                "unknown algorithm \"my-algo\"",
                "tsp65",
                "mine",
            ],
        ),
        (
            "name = \"../up\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n".into(),
            "1:8",
            &["name", "file names"],
        ),
        (
            format!("{rect}[options]\nmerge = [\"smart\", \"clever\"]\n"),
            "7:19",
            &["options.merge[1]"],
        ),
    ];
    let cases: Vec<(&str, &str, &[&str])> =
        cases.iter().map(|(t, p, n)| (t.as_str(), *p, *n)).collect();
    assert_refused("config-other", &cases);
}

#[test]
fn careless_suites_are_refused_with_line_and_column() {
    let dir = temp_dir("config-careless");
    std::fs::create_dir_all(dir.join("empty")).unwrap();
    std::fs::create_dir_all(dir.join("inst")).unwrap();
    std::fs::write(dir.join("inst/sq.grid"), "##\n##\n").unwrap();
    std::fs::write(
        dir.join("inst/sq.wkt"),
        "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n",
    )
    .unwrap();
    let cases: [(&str, &str, &[&str]); 7] = [
        // A misspelled key, at the top and in a table.
        (
            "name = \"t\"\nsed = 3\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n",
            "2:1",
            &["unknown field `sed`"],
        ),
        (
            "name = \"t\"\n[[family]]\nfamly = \"rect\"\n",
            "3:1",
            &["unknown field `famly`"],
        ),
        // The same family twice is fine, the same combination twice is not.
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n\
             [[family]]\nfamily = \"rect\"\nwidth = [3, 2]\nheight = 2\n",
            "6:1",
            &["family[1]", "width=2 height=2 is also in family[0]"],
        ),
        // Files named like a generated family would mix into its statistics.
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n\
             [[files]]\ndir = \"inst\"\nfamily = \"rect\"\n",
            "8:10",
            &["files[0].family", "also a [[family]]"],
        ),
        // A folder without instances is an empty suite part.
        (
            "name = \"t\"\n[[files]]\ndir = \"empty\"\n",
            "3:7",
            &[
                "files[0].dir",
                "no instance file (.grid, .wkt, .poly, .gg, .csv)",
            ],
        ),
        // Two files of one folder, or two folders of one family, with the same name.
        (
            "name = \"t\"\n[[files]]\ndir = \"inst\"\n",
            "3:7",
            &["files[0].dir", "instance name files_sq a second time"],
        ),
        (
            "name = \"t\"\n[[files]]\ndir = \"missing\"\n",
            "3:7",
            &["files[0].dir", "cannot read folder", "config file's folder"],
        ),
    ];
    for (i, (text, place, needles)) in cases.iter().enumerate() {
        let name = format!("c{i}.toml");
        let (code, err, wrote) = bench(&dir, &name, text);
        assert_eq!(code, Some(2), "case {i}: {err}");
        assert!(!wrote, "case {i}: {err}");
        assert!(
            err.contains(&format!("{name}:{place}: ")),
            "case {i}: {err}"
        );
        for needle in *needles {
            assert!(err.contains(needle), "case {i}: {needle:?}: {err}");
        }
    }
    // No instances at all.
    let (code, err, wrote) = bench(&dir, "none.toml", "name = \"t\"\n");
    assert_eq!(code, Some(2));
    assert!(!wrote && err.contains("none.toml: no instances"), "{err}");
}

/// `[[files]] dir` is relative to the config file's folder, not to where `mowmill` runs (the
/// test binary runs it from the repository root); the `params` column keeps the path as given.
#[test]
fn files_dir_is_relative_to_the_config_file() {
    let dir = temp_dir("config-files-dir");
    std::fs::create_dir_all(dir.join("inst")).unwrap();
    std::fs::write(dir.join("inst/sq.grid"), "###\n###\n").unwrap();
    let (code, err, wrote) = bench(
        &dir,
        "suite.toml",
        "name = \"t\"\n[[files]]\ndir = \"inst\"\nfamily = \"mine\"\nalgorithms = [\"tsp65\"]\n",
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(wrote);
    let results = std::fs::read_to_string(dir.join("suite.toml.out/results.csv")).unwrap();
    let rows: Vec<&str> = results.lines().skip(1).collect();
    assert!(!rows.is_empty(), "{results}");
    assert!(
        rows.iter()
            .all(|r| r.contains("mine") && r.contains("file=inst/sq.grid")),
        "{results}"
    );
}

/// Every shipped suite and the built-in default parse and expand, and survive the round trip
/// through the manifest that `bench --resume` reads (parameters not given recorded as `[]`).
#[test]
fn shipped_configs_parse_expand_and_round_trip_through_the_manifest() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut configs =
        vec![Config::parse(mowmill::harness::DEFAULT_CONFIG, "built-in default suite").unwrap()];
    let mut paths: Vec<_> = std::fs::read_dir(root.join("experiments"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 4, "{paths:?}");
    // The thesis's instances are fetched, not committed (instances/thesis/README.md): in a
    // clone without them, its config is read from a copy beside a stand-in instance file, the
    // same parse, expansion and round trip.
    let staged = tempfile::tempdir().unwrap();
    let fetched = root.join("instances/thesis");
    let has_gg = |dir: &Path| {
        std::fs::read_dir(dir)
            .map(|d| {
                d.flatten()
                    .any(|e| e.path().extension().is_some_and(|x| x == "gg"))
            })
            .unwrap_or(false)
    };
    for path in &paths {
        let path = if path.ends_with("thesis-sample.toml") && !has_gg(&fetched) {
            let copy = staged.path().join("experiments/thesis-sample.toml");
            std::fs::create_dir_all(copy.parent().unwrap()).unwrap();
            std::fs::create_dir_all(staged.path().join("instances/thesis")).unwrap();
            std::fs::copy(path, &copy).unwrap();
            std::fs::copy(
                root.join("instances/fixtures/peers/l-shape.gg"),
                staged.path().join("instances/thesis/fc_100_dense_0.gg"),
            )
            .unwrap();
            copy
        } else {
            path.clone()
        };
        configs.push(Config::read(&path).unwrap_or_else(|e| panic!("{e}")));
    }
    for config in configs {
        let instances = config.instances().unwrap_or_else(|e| panic!("{e}"));
        assert!(!instances.is_empty(), "{}", config.name);
        let recorded = toml::to_string(&serde_json::to_value(&config).unwrap()).unwrap();
        let mut again = Config::parse(&recorded, "manifest.json")
            .unwrap_or_else(|e| panic!("{}: {e}\n{recorded}", config.name));
        again.dir = config.dir.clone();
        let names = |c: &Config| -> Vec<String> {
            c.instances()
                .unwrap()
                .into_iter()
                .map(|s| format!("{} {} {}", s.name, s.params, s.seed))
                .collect()
        };
        assert_eq!(names(&again), names(&config), "{}", config.name);
    }
}

/// `bench --resume` re-reads the config recorded in the manifest: keys not given (no
/// `algorithms`, no `turn_cost`) must survive that round trip, since TOML has no null.
#[test]
fn a_finished_run_resumes_from_its_manifest() {
    let dir = temp_dir("config-resume");
    let (code, err, wrote) = bench(
        &dir,
        "suite.toml",
        "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 3\n\
         [[exact]]\nobjective = \"length\"\nmax_n = 6\ntime_limit = 10\n",
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(wrote);
    let out = dir.join("suite.toml.out");
    let rows = std::fs::read_to_string(out.join("results.csv")).unwrap();
    let o = mowmill_within(
        &["bench", "--resume", out.to_str().unwrap(), "--jobs", "1"],
        60,
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("0 rows written"), "{err}");
    assert_eq!(
        std::fs::read_to_string(out.join("results.csv")).unwrap(),
        rows
    );
}
