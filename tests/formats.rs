//! The peers' formats: pixel lists (`.gg` / `.csv`) and `.poly` rings read, and `mowmill export`
//! to TSPLIB, pixel lists and WKT, checked by round trips, hand-made cases and the binary.

mod common;

use common::{json, mowmill, temp_dir};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::instance::Instance;
use mowmill::region::{MAX_PIXELS, Pixel, Region};
use std::path::{Path, PathBuf};

/// Every `.grid` fixture, and random-simple and random-holed regions from the generator.
fn regions() -> Vec<(String, Region)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("instances/fixtures");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&root).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "grid") {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            out.push((name, Instance::read(&path).unwrap().region));
        }
    }
    assert!(out.len() >= 10, "only {} fixtures", out.len());
    for seed in 0..6 {
        let simple = GenParams {
            n: Some(60 + 40 * seed as usize),
            ..GenParams::new(Family::RandomSimple, seed)
        };
        let holed = GenParams {
            n: Some(80 + 40 * seed as usize),
            holes: Some(1 + seed as usize % 3),
            ..GenParams::new(Family::RandomHoled, seed)
        };
        for p in [simple, holed] {
            let name = format!("{} seed {seed}", p.family.name());
            out.push((name, generate(&p).unwrap().region));
        }
    }
    out
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Runs `mowmill export FILE --format F --out OUT`, checking that it succeeds.
fn export(file: &Path, format: &str, out: &Path) {
    let o = mowmill(&[
        "export",
        file.to_str().unwrap(),
        "--format",
        format,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}: {}", file.display(), stderr(&o));
}

/// Writes `region` as a `.grid` file (moved to non-negative coordinates).
fn write_grid(dir: &Path, k: usize, region: &Region) -> PathBuf {
    let path = dir.join(format!("r{k}.grid"));
    std::fs::write(&path, region.to_ascii()).unwrap();
    path
}

/// The pixel set up to translation: moved so that its bounding box starts at (0, 0).
fn shape(r: &Region) -> Region {
    r.normalized()
}

#[test]
fn grid_to_gg_and_wkt_and_back_gives_the_same_region() {
    let dir = temp_dir("formats-round-trip");
    for (k, (name, region)) in regions().iter().enumerate() {
        let grid = write_grid(&dir, k, region);
        let read = Instance::read(&grid).unwrap().region;
        assert_eq!(shape(&read), shape(region), "{name}: .grid");
        for (format, ext) in [("gg", "gg"), ("wkt", "wkt")] {
            let out = dir.join(format!("r{k}.{ext}"));
            export(&grid, format, &out);
            // Coordinates are kept, so the region comes back exactly, not only up to a shift.
            assert_eq!(
                Instance::read(&out).unwrap().region,
                read,
                "{name}: {format}"
            );
            // Also without the extension, found by content.
            let bare = dir.join(format!("r{k}-{format}"));
            std::fs::copy(&out, &bare).unwrap();
            assert_eq!(
                Instance::read(&bare).unwrap().region,
                read,
                "{name}: {format} detected"
            );
        }
    }
}

#[test]
fn pixel_lists_have_y_upward() {
    // The L of the fixture, read from its pairs and compared with its picture (y = 0 last).
    let l = Instance::read(Path::new("instances/fixtures/peers/l-shape.gg")).unwrap();
    assert_eq!(l.region, Region::from_ascii("#..\n#..\n###\n"));
    // Export writes pairs with y upward: the top pixel of a .grid column has the largest y.
    let dir = temp_dir("formats-y-up");
    let grid = dir.join("corner.grid");
    std::fs::write(&grid, "##\n#.\n#.\n").unwrap();
    let gg = dir.join("corner.gg");
    export(&grid, "gg", &gg);
    let text = std::fs::read_to_string(&gg).unwrap();
    let pairs: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(pairs, ["0 0", "0 1", "0 2", "1 2"]);
    // Negative coordinates and a CSV header: kept as written, and drawn as the same shape.
    let csv = dir.join("neg.csv");
    std::fs::write(&csv, "x,y\n-3,-2\n-2,-2\n-3,-1\n").unwrap();
    let r = Instance::read(&csv).unwrap().region;
    assert_eq!(r.bbox().min_x, -3);
    assert_eq!(r.bbox().min_y, -2);
    assert_eq!(r.normalized(), Region::from_ascii("#.\n##\n"));
}

#[test]
fn poly_files_enclose_the_expected_pixels() {
    let frame = Instance::read(Path::new("instances/fixtures/peers/notched-frame.poly")).unwrap();
    // 6 x 5 = 30, less the 2 x 1 notch and the 2 x 2 hole.
    assert_eq!(frame.region.len(), 24);
    assert!(!frame.region.contains(Pixel::new(0, 3)));
    assert!(!frame.region.contains(Pixel::new(1, 3)));
    assert!(frame.region.contains(Pixel::new(0, 4)));
    assert!(!frame.region.contains(Pixel::new(4, 2)));
    // The two-holes fixture written as rings, clockwise and counter-clockwise mixed, the last
    // ring closed explicitly.
    let dir = temp_dir("formats-poly");
    let poly = dir.join("two-holes.poly");
    std::fs::write(
        &poly,
        "4 0 0 0 5 7 5 7 0\n4 2 2 3 2 3 3 2 3\n5 4 2 4 3 5 3 5 2 4 2\n",
    )
    .unwrap();
    let two = Instance::read(Path::new("instances/fixtures/two-holes.grid")).unwrap();
    assert_eq!(Instance::read(&poly).unwrap().region, two.region);
    assert_eq!(two.region.len(), 33);
}

/// The TSPLIB text parsed by hand: DIMENSION and the node lines (id, x, y).
fn read_tsplib(text: &str) -> (usize, Vec<(usize, i64, i64)>) {
    let mut lines = text.lines();
    let mut dimension = None;
    for line in lines.by_ref() {
        if let Some(d) = line.strip_prefix("DIMENSION:") {
            dimension = Some(d.trim().parse().unwrap());
        }
        if line.starts_with("EDGE_WEIGHT_TYPE") {
            assert_eq!(line, "EDGE_WEIGHT_TYPE: MAN_2D");
        }
        if line == "NODE_COORD_SECTION" {
            break;
        }
    }
    let mut nodes = Vec::new();
    for line in lines.by_ref() {
        if line == "EOF" {
            break;
        }
        let f: Vec<i64> = line
            .split_whitespace()
            .map(|w| w.parse().unwrap())
            .collect();
        assert_eq!(f.len(), 3, "{line}");
        nodes.push((f[0] as usize, f[1], f[2]));
    }
    assert_eq!(lines.next(), None, "text after EOF");
    (dimension.expect("DIMENSION"), nodes)
}

#[test]
fn tsplib_has_one_node_per_pixel_at_manhattan_grid_distances() {
    let dir = temp_dir("formats-tsplib");
    for (k, (name, region)) in regions().iter().enumerate() {
        let grid = write_grid(&dir, k, region);
        let region = Instance::read(&grid).unwrap().region;
        let out = dir.join(format!("r{k}.tsp"));
        export(&grid, "tsplib", &out);
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(
            text.starts_with(&format!("NAME: r{k}\nTYPE: TSP\n")),
            "{name}"
        );
        let (dimension, nodes) = read_tsplib(&text);
        assert_eq!(dimension, region.len(), "{name}");
        assert_eq!(nodes.len(), region.len(), "{name}");
        let ids: Vec<usize> = nodes.iter().map(|n| n.0).collect();
        assert_eq!(ids, (1..=region.len()).collect::<Vec<_>>(), "{name}");
        let mut at: Vec<Pixel> = nodes
            .iter()
            .map(|&(_, x, y)| Pixel::new(x as i32, y as i32))
            .collect();
        // Manhattan distance 1 between consecutive nodes exactly when the pixels are
        // 4-adjacent in the region's grid graph.
        for w in 0..nodes.len().saturating_sub(1) {
            let (a, b) = (nodes[w], nodes[w + 1]);
            let d = (a.1 - b.1).abs() + (a.2 - b.2).abs();
            let adjacent = region.neighbors(w).any(|v| v == w + 1);
            assert_eq!(d == 1, adjacent, "{name}: nodes {} and {}", a.0, b.0);
        }
        // And every grid edge is at distance 1.
        for (i, j) in region.edges() {
            assert_eq!(at[i].l1(at[j]), 1, "{name}");
        }
        at.sort_unstable_by_key(|p| (p.y, p.x));
        assert_eq!(at, region.pixels(), "{name}: the nodes are the pixels");
    }
}

#[test]
fn export_writes_to_stdout_without_out() {
    let o = mowmill(&[
        "export",
        "instances/fixtures/rect-2x3.grid",
        "--format",
        "wkt",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        "POLYGON ((0 0, 2 0, 2 3, 0 3, 0 0))\n"
    );
    let o = mowmill(&[
        "export",
        "instances/fixtures/rect-2x3.grid",
        "--format",
        "svg",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn malformed_inputs_exit_2_with_file_line_column() {
    let dir = temp_dir("formats-bad");
    let big = format!("{}", 1u64 << 40);
    let side = (MAX_PIXELS as f64).sqrt() as u64 + 1;
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "frac.gg",
            "0 0\n1 0.5\n".into(),
            ":2:3: coordinate 0.5 is not an integer",
        ),
        (
            "word.csv",
            "x,y\n0,0\n1,a\n".into(),
            ":3:3: 'a' is not a number",
        ),
        ("missing-y.gg", "0 0\n# c\n1\n".into(), ":3:2: missing y"),
        (
            "dup.gg",
            "0 0\n1 0\n2 0\n1 0\n".into(),
            ":4:1: pixel (1, 0) is also on line 2",
        ),
        (
            "huge.gg",
            format!("0 0\n0 {big}\n"),
            ":2:3: coordinate 1099511627776 is out of range",
        ),
        (
            "third.csv",
            "0,0,0\n".into(),
            ":1:5: unexpected third field",
        ),
        (
            "odd.poly",
            "4 0 0 4 0 4 4 0\n".into(),
            ":1:15: the ring has 7 coordinates, an odd number",
        ),
        (
            "frac.poly",
            "4 0 0 4 0 4 4.5 0 4\n".into(),
            ":1:13: coordinate 4.5 is not an integer",
        ),
        (
            "short.poly",
            "4 0 0 4 0\n".into(),
            ":1:9: the ring has 2 points; expected 4 pairs",
        ),
        (
            "diagonal.poly",
            "4 0 0 4 0 5 4 0 4\n".into(),
            ":1:11: edge from (4,0) to (5,4) is not axis-parallel",
        ),
        (
            "area.poly",
            format!("# too big\n4 0 0 {side} 0 {side} {side} 0 {side}\n"),
            ":2:1: the geometry encloses",
        ),
        ("empty.gg", "# nothing\n".into(), ":1:1: empty region"),
    ];
    for (file, text, expected) in cases {
        let path = dir.join(file);
        std::fs::write(&path, &text).unwrap();
        let shown = path.display().to_string();
        for cmd in [
            vec!["info", &shown],
            vec!["export", &shown, "--format", "tsplib"],
        ] {
            let o = mowmill(&cmd);
            assert_eq!(o.status.code(), Some(2), "{file}: {}", stderr(&o));
            assert!(
                stderr(&o).contains(&format!("{shown}{expected}")),
                "{file}: {}",
                stderr(&o)
            );
            assert!(o.stdout.is_empty(), "{file}: output on a refusal");
        }
    }
}

#[test]
fn solve_and_exact_read_pixel_lists_and_poly_files() {
    // The 3 x 3 square as a pixel list at negative coordinates: the optimal milling tour has
    // length 10 (9 pixels, and a closed walk on a bipartite graph has even length).
    let dir = temp_dir("formats-solve");
    let square = dir.join("square.gg");
    let pairs: String = (0..9)
        .map(|k| format!("{} {}\n", k % 3 - 5, k / 3 - 7))
        .collect();
    std::fs::write(&square, pairs).unwrap();
    let square = square.to_str().unwrap();
    let o = mowmill(&["exact", square, "--objective", "length", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = json(&o);
    assert_eq!(v["value"], 10, "{v}");
    assert_eq!(v["status"], "optimal", "{v}");
    let o = mowmill(&["solve", square, "--algo", "tsp65", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = json(&o);
    assert_eq!(v["valid"], true, "{v}");
    assert_eq!(v["length"], 10, "{v}");

    // The notched frame (.poly, one hole): milling25's tour, checked again by validate.
    let frame = "instances/fixtures/peers/notched-frame.poly";
    let tour = dir.join("frame.tour.json");
    let o = mowmill(&[
        "solve",
        frame,
        "--algo",
        "milling25",
        "--tour-out",
        tour.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = mowmill(&[
        "validate",
        frame,
        "--tour",
        tour.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(json(&o)["valid"], true);
    let o = mowmill(&["exact", frame, "--objective", "cc-turns", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = json(&o);
    assert_eq!(v["status"], "optimal", "{v}");
    assert_eq!(v["valid"], true, "{v}");
}
