//! Hostile inputs (malformed, huge or wrapping files of every format): each must end with a clear
//! error and exit code 2 (or 1 for an invalid walk), never a wrapped coordinate, a panic, an abort,
//! a hang or a huge allocation.

mod common;

use common::{mowmill, temp_dir};
use std::process::Output;

fn code(out: &Output) -> Option<i32> {
    out.status.code()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Probes the checker's wrap-around: two pixels 2^32 − 1 apart (x = 2^31 − 1 and −2^31) are
/// refused at the coordinate limit, and a tour stepping between two far pixels within the
/// limit is a non-unit move (exit 1), not `valid: length 2`.
#[test]
fn far_apart_pixels_do_not_wrap() {
    let d = temp_dir("hostile-wrap");
    let far = d.join("far.gg");
    std::fs::write(&far, "2147483647 0\n-2147483648 0\n").unwrap();
    let tour = d.join("far.json");
    std::fs::write(&tour, r#"{"cycles":[[[2147483647,0],[-2147483648,0]]]}"#).unwrap();
    let out = mowmill(&[
        "validate",
        far.to_str().unwrap(),
        "--tour",
        tour.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("far.gg:1:1: coordinate 2147483647 is out of range"));
    let ok = d.join("ok.gg");
    std::fs::write(&ok, "1073741823 0\n-1073741823 0\n").unwrap();
    let t2 = d.join("ok.json");
    std::fs::write(&t2, r#"{"cycles":[[[1073741823,0],[-1073741823,0]]]}"#).unwrap();
    let out = mowmill(&[
        "validate",
        ok.to_str().unwrap(),
        "--tour",
        t2.to_str().unwrap(),
    ]);
    assert_eq!(code(&out), Some(1), "{}", stderr(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("is not a unit move"));
}

/// Probes lawn-box on two far pixels (an out-of-bounds panic) and on a two-line list whose box
/// has 10^10 cells (a 16 GB allocation), and --cutter disk (exit 3 before): all exit 2.
#[test]
fn lawn_box_refuses_huge_boxes_and_the_disk() {
    let d = temp_dir("hostile-box");
    for (name, text) in [
        ("far.gg", "1073741823 0\n-1073741823 0\n"),
        ("two.gg", "0 0\n100000 100000\n"),
    ] {
        let f = d.join(name);
        std::fs::write(&f, text).unwrap();
        let out = mowmill(&["solve", f.to_str().unwrap(), "--algo", "lawn-box"]);
        assert_eq!(code(&out), Some(2), "{name}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("expected at most 20000000"),
            "{}",
            stderr(&out)
        );
    }
    let f = d.join("pair.gg");
    std::fs::write(&f, "0 0\n1 0\n").unwrap();
    let out = mowmill(&[
        "solve",
        f.to_str().unwrap(),
        "--algo",
        "lawn-box",
        "--cutter",
        "disk",
    ]);
    assert_eq!(code(&out), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("does not apply to lawn-box"));
}

/// Probes options out of range: --time-limit 1e300 (a Duration panic), exact --threads 100000
/// (HiGHS bad_alloc), hunt --jobs 0 and 100000 (accepted / a hang spawning threads).
#[test]
fn absurd_limits_are_usage_errors() {
    let d = temp_dir("hostile-limits");
    let f = d.join("pair.gg");
    std::fs::write(&f, "0 0\n1 0\n").unwrap();
    let f = f.to_str().unwrap();
    for args in [
        vec!["solve", f, "--command", "true", "--time-limit", "1e300"],
        vec!["solve", f, "--command", "true", "--time-limit", "inf"],
        vec!["exact", f, "--threads", "100000"],
        vec!["exact", f, "--threads", "0"],
        vec!["hunt", "--algo", "strips-matching", "--jobs", "0"],
        vec!["hunt", "--algo", "strips-matching", "--jobs", "100000"],
    ] {
        let out = mowmill(&args);
        assert_eq!(code(&out), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            !stderr(&out).contains("panic"),
            "{args:?}: {}",
            stderr(&out)
        );
    }
}

/// Probes options a model or algorithm ignores (exit 0 before, silently dropped): --coverage4
/// and --time-limit without --exact on a discrete instance, --exact on a non-integral WKT,
/// --cutter and --time-limit on a turn-cost algorithm without --exact.
#[test]
fn ignored_options_are_refused() {
    let d = temp_dir("hostile-options");
    let dm = d.join("path.dm");
    std::fs::write(&dm, "discrete 3\ne 0 1\ne 1 2\n").unwrap();
    let wkt = d.join("half.wkt");
    std::fs::write(&wkt, "POLYGON ((0 0, 4.5 0, 4.5 1.5, 0 1.5, 0 0))\n").unwrap();
    let gg = d.join("pair.gg");
    std::fs::write(&gg, "0 0\n1 0\n").unwrap();
    let (dm, wkt, gg) = (
        dm.to_str().unwrap(),
        wkt.to_str().unwrap(),
        gg.to_str().unwrap(),
    );
    for args in [
        vec!["solve", dm, "--algo", "discrete-star-cover", "--coverage4"],
        vec![
            "solve",
            dm,
            "--algo",
            "discrete-star-cover",
            "--time-limit",
            "5",
        ],
        vec![
            "solve",
            dm,
            "--algo",
            "discrete-star-cover",
            "--objective",
            "length",
        ],
        vec!["solve", wkt, "--algo", "corollary4", "--exact"],
        vec!["solve", gg, "--algo", "strips-matching", "--cutter", "disk"],
        vec![
            "solve",
            gg,
            "--algo",
            "strips-matching",
            "--time-limit",
            "5",
        ],
    ] {
        let out = mowmill(&args);
        assert_eq!(code(&out), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("does not apply"),
            "{args:?}: {}",
            stderr(&out)
        );
    }
    let out = mowmill(&["solve", dm, "--algo", "discrete-star-cover"]);
    assert_eq!(code(&out), Some(0), "{}", stderr(&out));
}

/// Probes the quadratic greedy rook placement of `info`: 10^5 isolated vertices (25 s
/// before) and a star of 10^5 edges (quadratic too) give their rook counts (every isolated
/// vertex, every leaf) in well under a second each.
#[test]
fn discrete_info_is_near_linear() {
    let d = temp_dir("hostile-info");
    let iso = d.join("iso.dm");
    std::fs::write(&iso, "discrete 100000\n").unwrap();
    let mut star = String::from("discrete 100001\n");
    for i in 1..=100_000 {
        star.push_str(&format!("e 0 {i}\n"));
    }
    let st = d.join("star.dm");
    std::fs::write(&st, star).unwrap();
    for (f, rooks) in [(iso, 100_000), (st, 100_000)] {
        let out = mowmill(&["info", f.to_str().unwrap(), "--json"]);
        assert_eq!(code(&out), Some(0), "{}", stderr(&out));
        let v = common::json(&out);
        assert_eq!(v["rook_placement"], rooks, "{v}");
    }
}

/// A FIFO (whose `open` blocks until a writer comes), `/dev/zero` (which never ends) and a
/// directory, given as an instance, a tour, a config or a results folder's file, are refused
/// with exit 2 before they are opened, instead of hanging or filling the memory.
#[test]
fn special_files_are_refused_not_read() {
    let d = temp_dir("hostile-fifo");
    let fifo = d.join("pipe.grid");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    let ok = d.join("ok.gg");
    std::fs::write(&ok, "0 0\n1 0\n").unwrap();
    let run = d.join("run");
    std::fs::create_dir_all(&run).unwrap();
    let csv = run.join("results.csv");
    let made = std::process::Command::new("mkfifo")
        .arg(&csv)
        .status()
        .unwrap();
    assert!(made.success());
    let (f, z, o) = (fifo.to_str().unwrap(), "/dev/zero", ok.to_str().unwrap());
    let dir = d.to_str().unwrap();
    let probes: Vec<Vec<&str>> = vec![
        vec!["info", f],
        vec!["info", z],
        vec!["info", dir],
        vec!["validate", o, "--tour", f],
        vec!["validate", o, "--tour", z],
        vec!["bench", "--config", f, "--out", dir],
        vec!["claims", "--from", run.to_str().unwrap()],
    ];
    for args in probes {
        let out = common::mowmill_within(&args, 20);
        assert_eq!(code(&out), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("regular file") || stderr(&out).contains("directory"),
            "{args:?}: {}",
            stderr(&out)
        );
    }
}

/// Two pixels 2^31 − 2 apart make a two-line file whose lawn tours would list four billion
/// pixels: the MST-based lawn algorithms refuse them (exit 2) instead of expanding the walk.
#[test]
fn lawn_tours_of_far_pixels_are_refused() {
    let d = temp_dir("hostile-lawn-far");
    let far = d.join("far.gg");
    std::fs::write(&far, "1073741823 0\n-1073741823 0\n").unwrap();
    for algo in ["lawn-mst", "lawn-christofides", "lawn-2opt"] {
        let out = common::mowmill_within(&["solve", far.to_str().unwrap(), "--algo", algo], 60);
        assert_eq!(code(&out), Some(2), "{algo}: {}", stderr(&out));
        assert!(
            stderr(&out).contains("unit moves; expected at most"),
            "{algo}: {}",
            stderr(&out)
        );
    }
}
