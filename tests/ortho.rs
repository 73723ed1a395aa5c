//! The exact checker of `mowmill::ortho` against the pixel checker on integral inputs: on
//! every region fixture and on random regions, the walks of the registered algorithms and
//! mutations of them (valid and invalid) get identical verdicts, lengths and turn counts.
//!
//! A pixel walk is a polyline of pixel centres; where the two models differ, the difference is
//! one of notation, and the test states it: the pixel checker refuses any move that is not a
//! unit move, while a polyline may move any distance along a line (a longer straight move
//! means the unit moves along it) and may repeat a point (a move of length 0, skipped). Such
//! walks are compared with the pixel checker on the walk written out in unit moves; a
//! diagonal move is refused by both.

use mowmill::algorithms::{self, Options};
use mowmill::checker::{self, Mode, Violation, walk_cost};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::instance::Instance;
use mowmill::ortho::{self, Point, Polygon, Rational, Tour};
use mowmill::region::{Dir, Pixel, Region};
use mowmill::tour::CycleCover;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::Path;

/// What the comparison of one walk found, for the tallies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Verdict {
    Valid,
    Outside,
    NotMilled,
    Diagonal,
}

/// The walk written out in unit moves: straight moves longer than 1 cut into unit moves,
/// repeated pixels dropped. `None` when a move is diagonal.
fn unit_moves(walk: &[Pixel]) -> Option<Vec<Pixel>> {
    let m = walk.len();
    let mut out: Vec<Pixel> = Vec::with_capacity(m);
    for i in 0..m {
        let (a, b) = (walk[i], walk[(i + 1) % m]);
        if a.x != b.x && a.y != b.y {
            return None;
        }
        let (dx, dy) = ((b.x - a.x).signum(), (b.y - a.y).signum());
        let mut p = a;
        while p != b {
            out.push(p);
            p = Pixel::new(p.x + dx, p.y + dy);
        }
        if a == b {
            out.push(a);
        }
    }
    out.dedup();
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    Some(out)
}

fn pixel_of(p: Point) -> Pixel {
    Pixel::new(p.x.floor() as i32, p.y.floor() as i32)
}

/// Checks `cover` with both checkers and asserts that they agree; returns the verdict.
fn agree(region: &Region, polygon: &Polygon, cover: &CycleCover, what: &str) -> Verdict {
    let tour = Tour::from_cover(cover);
    let exact = ortho::check(polygon, &tour).expect("integral tours never overflow");
    let context = || format!("{what}\n{}\n{:?}", region.to_ascii(), cover.cycles);
    let written: Option<Vec<Vec<Pixel>>> = cover.cycles.iter().map(|w| unit_moves(w)).collect();
    let Some(written) = written else {
        // A diagonal move: both refuse it.
        assert!(
            !checker::check(region, cover, Mode::Milling).valid,
            "{}",
            context()
        );
        assert!(
            matches!(
                exact.violation,
                Some(ortho::Violation::NotRectilinear { .. })
            ),
            "{:?}: {}",
            exact.error,
            context()
        );
        return Verdict::Diagonal;
    };
    if written != cover.cycles {
        // A long or zero move: the pixel checker refuses the walk as written...
        let as_written = checker::check(region, cover, Mode::Milling);
        assert!(
            matches!(as_written.violation, Some(Violation::NotUnitMove { .. })),
            "{}",
            context()
        );
    }
    // ... and judges it written out in unit moves, as the polyline means it.
    let unit = CycleCover::new(written);
    let pixel = checker::check(region, &unit, Mode::Milling);
    assert_eq!(
        exact.valid,
        pixel.valid,
        "{:?} vs {:?}: {}",
        exact.error,
        pixel.error,
        context()
    );
    let (mut length, mut turns) = (0, 0);
    for w in &unit.cycles {
        let (l, t) = walk_cost(w).expect("unit moves");
        length += l;
        turns += t;
    }
    assert_eq!(
        exact.length,
        Rational::integer(length as i64),
        "{}",
        context()
    );
    assert_eq!(exact.turns, turns, "{}", context());
    let visited: std::collections::HashSet<Pixel> = unit.cycles.iter().flatten().copied().collect();
    let outside = matches!(pixel.violation, Some(Violation::OutsideRegion { .. }));
    assert_eq!(exact.outside.is_some(), outside, "{}", context());
    if let Some(w) = exact.outside {
        let p = pixel_of(w);
        assert!(
            visited.contains(&p) && !region.contains(p),
            "{w}: {}",
            context()
        );
        return Verdict::Outside;
    }
    let unvisited = matches!(pixel.violation, Some(Violation::NotVisited { .. }));
    assert_eq!(exact.uncovered.is_some(), unvisited, "{}", context());
    if let Some(w) = exact.uncovered {
        let p = pixel_of(w);
        assert!(
            region.contains(p) && !visited.contains(&p),
            "{w}: {}",
            context()
        );
        return Verdict::NotMilled;
    }
    Verdict::Valid
}

/// The closed walks a region's algorithms produce: every registered algorithm whose
/// precondition holds, every output (lawn tours may leave the region: invalid for milling).
fn algorithm_covers(region: &Region) -> Vec<(String, CycleCover)> {
    let mut covers = Vec::new();
    for algo in algorithms::REGISTRY {
        if (algo.precondition)(region).is_err() {
            continue;
        }
        if let Ok(solution) = (algo.run)(region, &Options::default()) {
            for (k, output) in solution.outputs.into_iter().enumerate() {
                covers.push((format!("{} output {k}", algo.name), output.cover));
            }
        }
    }
    covers
}

/// Mutations of a walk: valid ones (reversed, rotated, an inner detour) and invalid ones
/// (a dropped pixel, a detour outside, a diagonal shift, a repeated pixel, a cut chunk).
fn mutations(region: &Region, walk: &[Pixel], rng: &mut ChaCha8Rng) -> Vec<(String, Vec<Pixel>)> {
    let m = walk.len();
    let mut out = Vec::new();
    let k = rng.random_range(0..m);
    let p = walk[k];
    let mut reversed = walk.to_vec();
    reversed.reverse();
    out.push(("reversed".to_string(), reversed));
    let mut rotated = walk.to_vec();
    rotated.rotate_left(k);
    out.push(("rotated".to_string(), rotated));
    if m > 1 {
        let mut dropped = walk.to_vec();
        dropped.remove(k);
        out.push((format!("dropped {k}"), dropped));
    }
    let neighbours: Vec<Pixel> = Dir::ALL.iter().map(|&d| p.step(d)).collect();
    if let Some(&q) = neighbours.iter().find(|&&q| !region.contains(q)) {
        let mut detour = walk.to_vec();
        detour.splice(k + 1..k + 1, [q, p]);
        out.push((format!("detour outside at {k}"), detour));
    }
    if let Some(&q) = neighbours.iter().find(|&&q| region.contains(q)) {
        let mut detour = walk.to_vec();
        detour.splice(k + 1..k + 1, [q, p]);
        out.push((format!("detour inside at {k}"), detour));
    }
    let mut diagonal = walk.to_vec();
    diagonal[k] = Pixel::new(p.x + 1, p.y + 1);
    out.push((format!("diagonal at {k}"), diagonal));
    let mut repeated = walk.to_vec();
    repeated.insert(k, p);
    out.push((format!("repeated {k}"), repeated));
    if m > 3 {
        let len = rng.random_range(2..=m / 2);
        let mut cut = walk.to_vec();
        let start = rng.random_range(0..m - len);
        cut.drain(start..start + len);
        out.push((format!("cut {start}..{}", start + len), cut));
    }
    out
}

#[derive(Default)]
struct Tally {
    regions: usize,
    walks: usize,
    verdicts: std::collections::BTreeMap<Verdict, usize>,
}

impl Tally {
    fn add(&mut self, v: Verdict) {
        self.walks += 1;
        *self.verdicts.entry(v).or_default() += 1;
    }
}

fn compare_region(region: &Region, rng: &mut ChaCha8Rng, tally: &mut Tally) {
    let polygon = Polygon::from_region(region).expect("a small region is a polygon");
    // The integer pixels inside the polygon of a region are the region.
    assert_eq!(&ortho::interior_pixels(&polygon).unwrap(), region);
    tally.regions += 1;
    for (name, cover) in algorithm_covers(region) {
        tally.add(agree(region, &polygon, &cover, &name));
        if let Some(walk) = cover.cycles.first() {
            for (how, mutated) in mutations(region, walk, rng) {
                let tour = CycleCover::tour(mutated);
                tally.add(agree(region, &polygon, &tour, &format!("{name}, {how}")));
            }
        }
    }
}

#[test]
fn agrees_with_the_pixel_checker_on_every_fixture() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("instances");
    let mut files = Vec::new();
    for dir in ["fixtures", "fixtures/peers", "regressions"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
            if matches!(ext, "grid" | "poly" | "gg") {
                files.push(path);
            }
        }
    }
    files.sort();
    let mut rng = ChaCha8Rng::seed_from_u64(18);
    let mut tally = Tally::default();
    let mut fixture_tours = 0;
    for path in &files {
        let instance = Instance::read(path).unwrap();
        let region = &instance.region;
        compare_region(region, &mut rng, &mut tally);
        // The committed tours next to the instance (`x.grid` with `x.tour.json`, ...).
        let stem = path.with_extension("");
        for suffix in ["tour.json", "bad-tour.json"] {
            let tour_path = stem.with_extension(suffix);
            if tour_path.exists() {
                let cover = CycleCover::read(&tour_path).unwrap();
                let polygon = Polygon::from_region(region).unwrap();
                tally.add(agree(
                    region,
                    &polygon,
                    &cover,
                    &tour_path.display().to_string(),
                ));
                fixture_tours += 1;
            }
        }
    }
    eprintln!(
        "fixtures: {} regions, {} walks ({fixture_tours} committed tours), verdicts {:?}",
        tally.regions, tally.walks, tally.verdicts
    );
    assert!(files.len() >= 14, "{} fixtures", files.len());
    assert!(fixture_tours >= 5);
}

#[test]
fn agrees_with_the_pixel_checker_on_random_regions() {
    let families = [
        Family::RandomSimple,
        Family::RandomHoled,
        Family::Thin,
        Family::Pinholes,
        Family::ThinArms,
    ];
    let mut rng = ChaCha8Rng::seed_from_u64(1818);
    let mut tally = Tally::default();
    let mut seed = 0;
    while tally.regions < 520 {
        seed += 1;
        let family = families[seed as usize % families.len()];
        let mut params = GenParams::new(family, seed);
        params.n = Some(rng.random_range(6..=48));
        if matches!(family, Family::RandomHoled | Family::Pinholes) {
            params.holes = Some(rng.random_range(1..=2));
        }
        let Ok(file) = generate(&params) else {
            continue;
        };
        compare_region(&file.region, &mut rng, &mut tally);
    }
    eprintln!(
        "random: {} regions, {} walks, verdicts {:?}",
        tally.regions, tally.walks, tally.verdicts
    );
    // Every kind of verdict occurs often, so that each comparison is exercised.
    for v in [
        Verdict::Valid,
        Verdict::Outside,
        Verdict::NotMilled,
        Verdict::Diagonal,
    ] {
        assert!(
            tally.verdicts.get(&v).copied().unwrap_or(0) >= 100,
            "{v:?}: {:?}",
            tally.verdicts
        );
    }
}

#[test]
fn one_pixel_and_two_pixel_walks() {
    // The conventions at the small end: a one-pixel walk has length 0 and 4 turns, a
    // there-and-back walk two U-turns.
    for (ascii, walk) in [
        ("#\n", vec![Pixel::new(0, 0)]),
        ("##\n", vec![Pixel::new(0, 0), Pixel::new(1, 0)]),
        ("###\n", vec![Pixel::new(0, 0), Pixel::new(2, 0)]),
    ] {
        let region = Region::from_ascii(ascii);
        let polygon = Polygon::from_region(&region).unwrap();
        let v = agree(&region, &polygon, &CycleCover::tour(walk), ascii);
        assert_eq!(v, Verdict::Valid);
    }
}

/// The command line on non-integral polygons: `info` reports the erosion and refuses (exit 2,
/// naming the point) a polygon with a feature narrower than the cutter; `validate` runs the
/// exact checker (exit 0 for a tour that mills the polygon, 1 for one that misses a strip).
#[test]
fn cli_refuses_infeasible_polygons_and_checks_tours_exactly() {
    use std::process::Command;
    let bin = env!("CARGO_BIN_EXE_mowmill");
    let dir = std::env::temp_dir().join(format!("mowmill-ortho-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ok = dir.join("ok.wkt");
    std::fs::write(&ok, "POLYGON ((0 0, 4.5 0, 4.5 1.5, 0 1.5, 0 0))\n").unwrap();
    let spike = dir.join("spike.wkt");
    std::fs::write(
        &spike,
        "POLYGON ((0 0, 5 0, 5 2, 2.7 2, 2.7 3, 2.2 3, 2.2 2, 0 2, 0 0))\n",
    )
    .unwrap();
    let run = |args: &[&str]| Command::new(bin).args(args).output().unwrap();
    let info = run(&["info", ok.to_str().unwrap(), "--json"]);
    assert!(info.status.success());
    let v: serde_json::Value = serde_json::from_slice(&info.stdout).unwrap();
    assert_eq!(v["model"], "ortho");
    assert_eq!(v["erosion_pieces"], 1);
    let refused = run(&["info", spike.to_str().unwrap()]);
    assert_eq!(refused.status.code(), Some(2));
    let err = String::from_utf8_lossy(&refused.stderr);
    assert!(
        err.contains("cannot be milled") && err.contains("(2.45, 2.5)"),
        "{err}"
    );
    // A 4.5 x 1.5 bar: the centre line y = 0.75 from x = 0.5 to 4 and back... misses the rows
    // 0..0.25 and 1.25..1.5; the two lines y = 0.5 and y = 1 mill it.
    let good = dir.join("good.json");
    std::fs::write(
        &good,
        r#"{"model":"ortho","tour":[["0.5","0.5"],["4","0.5"],["4","1"],["0.5","1"]]}"#,
    )
    .unwrap();
    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"model":"ortho","tour":[["0.5","0.75"],["4","0.75"]]}"#,
    )
    .unwrap();
    let checked = run(&[
        "validate",
        ok.to_str().unwrap(),
        "--tour",
        good.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        checked.status.success(),
        "{}",
        String::from_utf8_lossy(&checked.stdout)
    );
    let v: serde_json::Value = serde_json::from_slice(&checked.stdout).unwrap();
    assert_eq!(
        (v["valid"].clone(), v["turns"].clone()),
        (true.into(), 4.into())
    );
    assert_eq!(v["length"], "8");
    let missed = run(&[
        "validate",
        ok.to_str().unwrap(),
        "--tour",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(missed.status.code(), Some(1));
    let refused = run(&[
        "validate",
        spike.to_str().unwrap(),
        "--tour",
        good.to_str().unwrap(),
    ]);
    assert_eq!(refused.status.code(), Some(2));
}

/// `gen` of the ortho families and `solve --algo corollary4`: a perturbed polygon gets a tour
/// the exact checker accepts (also through `validate`), a narrow one is refused with exit 2.
#[test]
fn cli_generates_and_mills_non_integral_polygons() {
    use std::process::Command;
    let bin = env!("CARGO_BIN_EXE_mowmill");
    let dir = std::env::temp_dir().join(format!("mowmill-ortho-gen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let run = |args: &[&str]| Command::new(bin).args(args).output().unwrap();
    let p = dir.join("p.wkt");
    let t = dir.join("p.json");
    let p_s = p.to_str().unwrap();
    let made = run(&[
        "gen",
        "ortho-perturbed",
        "--n",
        "30",
        "--seed",
        "4",
        "--out",
        p_s,
    ]);
    assert!(
        made.status.success(),
        "{}",
        String::from_utf8_lossy(&made.stderr)
    );
    let solved = run(&[
        "solve",
        p_s,
        "--algo",
        "corollary4",
        "--tour-out",
        t.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        solved.status.success(),
        "{}",
        String::from_utf8_lossy(&solved.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&solved.stdout).unwrap();
    assert_eq!(v["valid"], true);
    assert_eq!(v["cycles"], 1);
    assert!(
        run(&["validate", p_s, "--tour", t.to_str().unwrap()])
            .status
            .success()
    );
    let narrow = dir.join("n.wkt");
    let n_s = narrow.to_str().unwrap();
    assert!(
        run(&[
            "gen",
            "ortho-narrow",
            "--n",
            "30",
            "--seed",
            "4",
            "--out",
            n_s
        ])
        .status
        .success()
    );
    let refused = run(&["solve", n_s, "--algo", "corollary4"]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("cannot be milled"));
}
