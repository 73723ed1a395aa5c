//! Discrete milling at the command line (issue 17): `gen` of the new families, `info`,
//! `solve --algo star-cover`, `exact` and `validate` on their files, bad input, and the grid
//! special case through both models.

mod common;
use common::{json, mowmill, temp_dir};
use std::path::Path;

fn ok(args: &[&str]) -> std::process::Output {
    let out = mowmill(args);
    assert!(
        out.status.success(),
        "mowmill {args:?}: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn every_family_generates_deterministically_and_solves_within_its_proven_bounds() {
    let dir = temp_dir("discrete-gen");
    for (family, ext, extra) in [
        ("voxel", "vox", &["--holes", "1"][..]),
        ("voxel", "dm", &[][..]),
        ("hex", "hex", &[][..]),
        ("honeycomb", "json", &[][..]),
        ("plane", "dm", &[][..]),
    ] {
        let a = dir.join(format!("{family}-a.{ext}"));
        let b = dir.join(format!("{family}-b.{ext}"));
        for f in [&a, &b] {
            let mut args = vec!["gen", family, "--n", "60", "--seed", "3", "--out", s(f)];
            args.extend_from_slice(extra);
            ok(&args);
        }
        assert_eq!(
            std::fs::read(&a).unwrap(),
            std::fs::read(&b).unwrap(),
            "{family}"
        );
        let info = json(&ok(&["info", s(&a), "--json"]));
        assert_eq!(info["model"], "discrete");
        assert_eq!(info["components"], 1, "{family}: connected");
        let solved = json(&ok(&["solve", "--algo", "star-cover", s(&a), "--json"]));
        assert_eq!(solved["valid"], true, "{family}");
        assert_eq!(solved["tour"]["cycles"], 1, "{family}: one tour");
        for v in solved["verdicts"].as_array().unwrap() {
            assert_eq!(v["holds"], true, "{family}: {v}");
        }
        // The rooks bound every cover's turns from below (Lemma 4.3).
        let rooks = solved["lower_bound"].as_u64().unwrap();
        assert!(solved["cc"]["turns"].as_u64().unwrap() >= rooks);
    }
}

#[test]
fn exact_optima_lie_between_the_rooks_and_the_star_cover_and_their_walks_validate() {
    let dir = temp_dir("discrete-exact");
    for (family, ext) in [("voxel", "vox"), ("hex", "hex"), ("plane", "dm")] {
        let f = dir.join(format!("{family}.{ext}"));
        ok(&["gen", family, "--n", "14", "--seed", "5", "--out", s(&f)]);
        let solved = json(&ok(&["solve", "--algo", "star-cover", s(&f), "--json"]));
        for (objective, approx) in [
            ("cc-turns", solved["cc"]["turns"].as_u64().unwrap()),
            ("turns", solved["tour"]["turns"].as_u64().unwrap()),
        ] {
            let tour = dir.join(format!("{family}-{objective}.json"));
            let ex = json(&ok(&[
                "exact",
                s(&f),
                "--objective",
                objective,
                "--time-limit",
                "60",
                "--tour-out",
                s(&tour),
                "--json",
            ]));
            assert_eq!(ex["status"], "optimal", "{family} {objective}: {ex}");
            let opt = ex["value"].as_u64().unwrap();
            assert!(
                opt <= approx,
                "{family} {objective}: exact {opt} > star cover {approx}"
            );
            assert!(opt >= solved["lower_bound"].as_u64().unwrap());
            let checked = json(&ok(&["validate", s(&f), "--tour", s(&tour), "--json"]));
            assert_eq!(checked["valid"], true);
            assert_eq!(checked["turns"].as_u64().unwrap(), opt);
        }
    }
}

#[test]
fn a_grid_region_gives_the_same_optima_and_star_cover_through_both_models() {
    let dir = temp_dir("discrete-grid");
    let grid = dir.join("r.grid");
    std::fs::write(&grid, "####.\n#..##\n#####\n##.#.\n").unwrap();
    let dm = dir.join("r.dm");
    ok(&["export", s(&grid), "--format", "dm", "--out", s(&dm)]);
    for objective in ["cc-turns", "turns", "length"] {
        let a = json(&ok(&[
            "exact",
            s(&grid),
            "--objective",
            objective,
            "--json",
        ]));
        let b = json(&ok(&["exact", s(&dm), "--objective", objective, "--json"]));
        assert_eq!(a["status"], "optimal");
        assert_eq!(b["status"], "optimal");
        assert_eq!(a["value"], b["value"], "{objective}");
    }
    let a = json(&ok(&[
        "solve",
        "--algo",
        "star-cover",
        s(&grid),
        "--cycle-cover",
        "--json",
    ]));
    let b = json(&ok(&["solve", "--algo", "star-cover", s(&dm), "--json"]));
    assert_eq!(a["turns"], b["cc"]["turns"], "{a}\n{b}");
    assert_eq!(a["length"], b["cc"]["length"]);
}

#[test]
fn bad_discrete_input_is_refused_with_its_line_and_exit_2() {
    let dir = temp_dir("discrete-bad");
    let f = dir.join("bad.dm");
    std::fs::write(&f, "discrete 3\ne 0 1\ne 1 7\n").unwrap();
    let out = mowmill(&["info", s(&f)]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.dm:3:"), "{err}");
    let v = dir.join("bad.vox");
    std::fs::write(&v, "##\n#x\n").unwrap();
    let out = mowmill(&["solve", "--algo", "star-cover", s(&v)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bad.vox:2:2"));
    let ok_file = dir.join("ok.dm");
    std::fs::write(&ok_file, "discrete 2\ne 0 1\n").unwrap();
    let out = mowmill(&["solve", "--algo", "tsp65", s(&ok_file)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("grid regions only"));
}
