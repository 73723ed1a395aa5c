//! Integration tests of the min-length milling algorithms of *Lawn mowing and milling*:
//! every output passes the independent checker and meets its proven bound.

use mowmill::algorithms::{self, Objective, Options, Solution};
use mowmill::checker::{self, Mode};
use mowmill::region::{Pixel, Region};
use mowmill::topology;
use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A random polyomino of about `n` pixels grown from (0, 0); holes are filled when `simple`.
fn random_region(seed: u64, n: usize, simple: bool) -> Region {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut pixels = vec![Pixel::new(0, 0)];
    let mut set = std::collections::HashSet::from([Pixel::new(0, 0)]);
    // Mix thin growth and rectangle stamps so that both cut vertices and fat parts occur.
    while pixels.len() < n {
        let p = pixels[rng.random_range(0..pixels.len())];
        if rng.random_range(0..3) == 0 {
            let (w, h) = (rng.random_range(1..4), rng.random_range(1..4));
            for dx in 0..w {
                for dy in 0..h {
                    let q = Pixel::new(p.x + dx, p.y + dy);
                    if set.insert(q) {
                        pixels.push(q);
                    }
                }
            }
        } else {
            let d = mowmill::Dir::from_index(rng.random_range(0..4));
            let q = p.step(d);
            if set.insert(q) {
                pixels.push(q);
            }
        }
    }
    let region = Region::from_pixels(pixels).unwrap();
    if !simple {
        return region;
    }
    let holes = topology::holes(&region);
    let mut all: Vec<Pixel> = region.pixels().to_vec();
    for cells in holes.hole_cells() {
        all.extend(cells);
    }
    Region::from_pixels(all).unwrap()
}

/// A random union of rectangles at least 2 wide, so that cut vertices are rare.
fn random_fat_region(seed: u64, k: usize) -> Region {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut pixels = Vec::new();
    let (mut x, mut y) = (0i32, 0i32);
    for _ in 0..k {
        let (w, h) = (rng.random_range(2..7), rng.random_range(2..7));
        for dx in 0..w {
            for dy in 0..h {
                pixels.push(Pixel::new(x + dx, y + dy));
            }
        }
        x += rng.random_range(-(w - 1)..w);
        y += rng.random_range(-(h - 1)..h);
    }
    let region = Region::from_pixels(pixels).unwrap();
    let holes = topology::holes(&region);
    let mut all: Vec<Pixel> = region.pixels().to_vec();
    for cells in holes.hole_cells() {
        all.extend(cells);
    }
    Region::from_pixels(all).unwrap()
}

fn run(name: &str, region: &Region) -> (Solution, checker::Report) {
    let algo = algorithms::find(name).unwrap();
    (algo.precondition)(region).unwrap();
    let sol = (algo.run)(region, &Options::default()).unwrap();
    let out = &sol.outputs[0];
    assert_eq!(out.objective, Objective::Length);
    let rep = checker::check(region, &out.cover, Mode::Milling);
    assert!(rep.valid, "{name}: {:?}\n{}", rep.error, region.to_ascii());
    assert!(out.cover.is_tour());
    (sol, rep)
}

#[test]
fn tsp65_fixtures() {
    for k in 2..9 {
        let r = Region::rectangle(2, k);
        assert_eq!(run("tsp65", &r).1.length, 2 * k as u64, "2 x {k}");
        let r = Region::rectangle(k, 2);
        assert_eq!(run("tsp65", &r).1.length, 2 * k as u64, "{k} x 2");
    }
    assert_eq!(run("tsp65", &Region::rectangle(3, 3)).1.length, 10);
    // Even rectangles are Hamiltonian: Type I detours push the contour through the interior.
    assert_eq!(run("tsp65", &Region::rectangle(4, 4)).1.length, 16);
    assert_eq!(run("tsp65", &Region::rectangle(3, 4)).1.length, 12);
    assert_eq!(run("tsp65", &Region::rectangle(6, 5)).1.length, 30);
    // An odd grid graph has no Hamiltonian cycle (bipartite): 26 is optimal for 5 x 5.
    assert_eq!(run("tsp65", &Region::rectangle(5, 5)).1.length, 26);
    assert_eq!(run("tsp65", &Region::rectangle(1, 1)).1.length, 0);
    assert_eq!(run("tsp65", &Region::rectangle(5, 1)).1.length, 8);
    // A single edge has no cut vertex but no cycle either: walked twice, no N-bound claimed.
    let (sol, rep) = run("tsp65", &Region::rectangle(2, 1));
    assert_eq!(rep.length, 2);
    assert!(!sol.certificates.contains_key("bound_6n_4_5"));
}

#[test]
fn tsp65_rejects_holes() {
    let r = Region::from_ascii("###\n#.#\n###\n");
    let algo = algorithms::find("tsp65").unwrap();
    assert!((algo.precondition)(&r).is_err());
    assert!((algo.run)(&r, &Options::default()).is_err());
}

/// Checks tsp65 on `r`; for regions without cut vertices returns (length, N, cases a–f).
fn check_tsp65(r: &Region) -> Option<(u64, u64, [i64; 6])> {
    if topology::components(r).count != 1 {
        return None;
    }
    let (sol, rep) = run("tsp65", r);
    let n = r.len() as u64;
    assert!(rep.length >= n.min(2 * n.saturating_sub(1)).min(n));
    assert_eq!(
        sol.certificates["unexpected_components"],
        0,
        "{}",
        r.to_ascii()
    );
    let no_cut = !topology::cut_vertices(r).iter().any(|&c| c);
    if no_cut && n >= 3 {
        assert!(
            5 * rep.length + 4 <= 6 * n,
            "length {} > (6N-4)/5, N = {n}\n{}",
            rep.length,
            r.to_ascii()
        );
        assert_eq!(sol.certificates["bound_6n_4_5"] as u64, (6 * n - 4) / 5);
        let cases = ["a", "b", "c", "d", "e", "f"].map(|k| sol.certificates[&format!("case_{k}")]);
        return Some((rep.length, n, cases));
    }
    None
}

/// Summary of a batch: (regions bound-checked, max length / ((6N - 4) / 5), cases used).
fn summarize(name: &str, results: impl Iterator<Item = Option<(u64, u64, [i64; 6])>>) -> usize {
    let (mut count, mut worst, mut cases) = (0, 0.0f64, [0i64; 6]);
    for (len, n, c) in results.flatten() {
        count += 1;
        worst = worst.max(5.0 * len as f64 / (6 * n - 4) as f64);
        for k in 0..6 {
            cases[k] += c[k];
        }
    }
    eprintln!(
        "{name}: {count} regions without cut vertices, max length/bound = {worst:.3}, cases a-f {cases:?}"
    );
    count
}

#[test]
fn tsp65_random_fat_regions() {
    let n = summarize(
        "tsp65 fat",
        (0..3000).map(|seed| check_tsp65(&random_fat_region(seed, 1 + (seed as usize % 6)))),
    );
    assert!(n > 1000);
}

#[test]
fn tsp65_random_simple_regions() {
    summarize(
        "tsp65 simple",
        (0..3000).map(|seed| check_tsp65(&random_region(seed, 3 + (seed as usize % 40), true))),
    );
}

#[test]
fn milling25_random_regions() {
    let (mut worst, mut odd) = (0.0f64, 0);
    for seed in 0..1500 {
        let r = random_region(seed, 3 + (seed as usize % 60), false);
        if topology::components(&r).count != 1 {
            continue;
        }
        let (sol, rep) = run("milling25", &r);
        let c = &sol.certificates;
        assert_eq!(
            rep.length as i64,
            c["l_db"] + c["l_str"] + c["l_match"] + c["l_connect"]
        );
        if c["odd_contours"] == 0 {
            assert!(2 * c["l_match"] <= c["l_db"]);
        } else {
            odd += 1;
        }
        // OPT >= N: the ratio to N bounds the ratio to OPT from above.
        worst = worst.max(rep.length as f64 / r.len() as f64);
    }
    eprintln!("milling25: max length / N = {worst:.3}; {odd} regions needed a parity repair");
}

/// Finding (Theorem 4's "clearly, this graph is connected"): a hole two pixels from the
/// outer boundary all around gets no strip, so its contour is a separate component; the
/// construction joins it with one doubled edge.
#[test]
fn milling25_joins_a_hole_contour_that_no_strip_reaches() {
    let r = Region::from_ascii(include_str!(
        "../instances/fixtures/milling25-unreached-hole.grid"
    ));
    let (sol, rep) = run("milling25", &r);
    let c = &sol.certificates;
    assert_eq!((c["strips"], c["l_connect"]), (0, 2));
    assert_eq!(rep.length, 20 + 12 + 2);
}

/// Grid reading of Theorem 4: the hole's contour runs along row 3, tangent to the strip row,
/// so it receives a single strip endpoint (the continuous parity argument does not
/// transfer); the construction repairs the parity with a path between lone endpoints.
#[test]
fn milling25_tangent_hole_contour_needs_a_repair() {
    let r = Region::from_ascii(include_str!(
        "../instances/fixtures/milling25-tangent-hole.grid"
    ));
    let (sol, rep) = run("milling25", &r);
    let c = &sol.certificates;
    assert_eq!(c["odd_contours"], 2);
    assert_eq!(
        rep.length as i64,
        c["l_db"] + c["l_str"] + c["l_match"] + c["l_connect"]
    );
}

/// A fat region with single-pixel holes punched where the 8-neighbourhood is full; kept only
/// without local cut vertices.
fn random_holed_region(seed: u64, k: usize, holes: usize) -> Option<Region> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    let base = random_fat_region(seed, k);
    let mut set: std::collections::HashSet<Pixel> = base.pixels().iter().copied().collect();
    for _ in 0..holes {
        // A w × h hole whose surrounding ring is still full region (so holes stay apart).
        let p = base.pixels()[rng.random_range(0..base.len())];
        let (w, h) = (rng.random_range(1..3), rng.random_range(1..3));
        let ring_full = (-1..=w)
            .all(|dx| (-1..=h).all(|dy| set.contains(&Pixel::new(p.x + dx, p.y + dy))))
            && (-2..=w + 1).all(|dx| {
                (-2..=h + 1).all(|dy| {
                    let inner = (-1..=w).contains(&dx) && (-1..=h).contains(&dy);
                    inner || set.contains(&Pixel::new(p.x + dx, p.y + dy))
                })
            });
        if ring_full {
            for dx in 0..w {
                for dy in 0..h {
                    set.remove(&Pixel::new(p.x + dx, p.y + dy));
                }
            }
        }
    }
    let r = Region::from_pixels(set).unwrap();
    let ok =
        topology::components(&r).count == 1 && !topology::local_cut_vertices(&r).iter().any(|&c| c);
    ok.then_some(r)
}

#[test]
fn holes1325_random_holed_regions() {
    let (mut count, mut worst, mut holes, mut paid) = (0, 0.0f64, 0, 0);
    for seed in 0..3000 {
        let Some(r) = random_holed_region(seed, 4 + seed as usize % 10, 2 + seed as usize % 10)
        else {
            continue;
        };
        let (sol, rep) = run("holes1325", &r);
        let n = r.len() as u64;
        assert!(
            40 * rep.length <= 53 * n,
            "length {} > 53N/40, N = {n}\n{}",
            rep.length,
            r.to_ascii()
        );
        assert_eq!(
            sol.certificates["unexpected_components"],
            0,
            "{}",
            r.to_ascii()
        );
        count += 1;
        holes += topology::holes(&r).count;
        paid += sol.certificates["paid_bridges"];
        worst = worst.max(40.0 * rep.length as f64 / (53 * n) as f64);
    }
    eprintln!(
        "holes1325: {count} regions, {holes} holes, {paid} paid bridges, max length/bound = {worst:.3}"
    );
    assert!(count > 500);
}

#[test]
fn holes1325_rejects_local_cut_vertices() {
    // The pixel between the two holes is a local cut vertex.
    let r = Region::from_ascii("#####\n#.#.#\n#####\n");
    let algo = algorithms::find("holes1325").unwrap();
    let e = (algo.precondition)(&r).unwrap_err().to_string();
    assert!(e.contains("local cut vertices"), "{e}");
    assert!((algo.run)(&r, &Options::default()).is_err());
    // A donut of width 2 is fine: two contours, joined by a free bridge.
    let d = Region::from_ascii("######\n######\n##..##\n##..##\n######\n######\n");
    let (sol, rep) = run("holes1325", &d);
    assert_eq!(rep.length, 32);
    assert_eq!(sol.certificates["paid_bridges"], 0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn symmetric_images_keep_the_bound(seed in 0u64..1_000_000, s in 0u8..8) {
        let r = random_fat_region(seed, 3).transformed(mowmill::Symmetry(s));
        check_tsp65(&r);
    }
}

pub mod lawn {
    use super::*;
    use mowmill::algorithms::Cutter;
    use mowmill::lawn_check;

    /// Runs a lawn algorithm and checks its tour with the checker of its cutter; returns the
    /// checked length (L1 units, or milli-units for Euclidean motion).
    pub fn run_lawn(name: &str, region: &Region, cutter: Cutter) -> (Solution, u64) {
        let algo = algorithms::find(name).unwrap();
        let opts = Options {
            cutter,
            ..Options::default()
        };
        let sol = (algo.run)(region, &opts).unwrap();
        let out = &sol.outputs[0];
        assert_eq!(out.objective, Objective::LawnLength);
        assert!(out.cover.is_tour());
        let length = if cutter == Cutter::Square {
            let rep = checker::check(region, &out.cover, Mode::Lawn);
            assert!(rep.valid, "{name}: {:?}", rep.error);
            rep.length
        } else {
            let rep = lawn_check::check_lawn(region, &out.cover, cutter);
            assert!(rep.valid, "{name} {cutter:?}: {:?}", rep.error);
            rep.length
        };
        (sol, length)
    }

    /// Grass in scattered parts: several random polyominoes far apart.
    fn scattered(seed: u64, parts: usize, n: usize) -> Region {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut pixels = Vec::new();
        for k in 0..parts {
            let part = random_region(seed * 31 + k as u64, n, false);
            let (dx, dy) = (rng.random_range(-20..20), rng.random_range(-20..20));
            pixels.extend(part.pixels().iter().map(|p| Pixel::new(p.x + dx, p.y + dy)));
        }
        Region::from_pixels(pixels).unwrap()
    }

    #[test]
    fn lawn_tours_are_valid_and_ordered() {
        let cutters = [Cutter::Square, Cutter::SquareFree, Cutter::Disk];
        for seed in 0..60 {
            let r = scattered(seed, 1 + seed as usize % 4, 3 + seed as usize % 25);
            for cutter in cutters {
                let (mst_sol, mst) = run_lawn("lawn-mst", &r, cutter);
                let (_, chr) = run_lawn("lawn-christofides", &r, cutter);
                let (_, opt2) = run_lawn("lawn-2opt", &r, cutter);
                // Tour ≤ 2 · MST (doubling), Christofides ≤ 3/2 · TSP ≤ 3/2 · 2 MST, and 2-opt
                // never lengthens the better start. (+1 per hop absorbs the rounding up.)
                let w = mst_sol.certificates["mst_weight"] as u64;
                let pts = mst_sol.certificates["points"] as u64;
                assert!(mst <= 2 * w + pts + 1, "{cutter:?}: {mst} > 2 * {w}");
                assert!(chr <= 3 * w + pts + 1);
                assert!(
                    opt2 <= mst.min(chr) + 1,
                    "{cutter:?}: 2-opt {opt2} vs {mst}, {chr}"
                );
                if cutter != Cutter::Disk {
                    let (_, bx) = run_lawn("lawn-box", &r, cutter);
                    assert!(bx <= chr);
                }
                // The area lower bound never exceeds a valid tour.
                assert!(mst_sol.certificates["area_lower_bound"] as u64 <= opt2);
            }
        }
    }

    #[test]
    fn box_method_mows_rectangles_optimally_when_thin() {
        // 2 × k: the rectangular tour of length 2(a + b - 2) is optimal (Section 4).
        for k in 2..10 {
            let r = Region::rectangle(2, k);
            let algo = algorithms::find("lawn-box").unwrap();
            let sol = (algo.run)(&r, &Options::default()).unwrap();
            let rep = checker::check(&r, &sol.outputs[0].cover, Mode::Lawn);
            assert!(rep.valid);
            assert_eq!(rep.length, 2 * (2 + k as u64 - 2));
        }
        // A hollow square of grass: the box rings beat any tour of the corner pixels? No:
        // both are checked, the shorter one is kept.
        let r = Region::from_ascii("#......#\n........\n........\n#......#\n");
        let (_, len) = run_lawn("lawn-box", &r, Cutter::Square);
        assert_eq!(len, 20);
    }

    #[test]
    fn disk_is_rejected_by_lawn_box() {
        let algo = algorithms::find("lawn-box").unwrap();
        let opts = Options {
            cutter: Cutter::Disk,
            ..Options::default()
        };
        assert!((algo.run)(&Region::rectangle(3, 3), &opts).is_err());
    }
}

/// Against proven optima (exact MILP, small regions): the OPT-relative guarantees and the
/// lower-bound claims of the proof of Theorem 4 (L_δB ≤ OPT, L_str ≤ OPT), counted rather
/// than asserted where the grid reading may differ from the continuous proof.
mod against_exact {
    use super::*;
    use mowmill::exact::{self, ExactOptions, Status};

    fn opt(r: &Region, objective: exact::Objective) -> Option<u64> {
        let opts = ExactOptions {
            time_limit: Some(5.0),
            ..mowmill::warm_start::exact_options()
        };
        let res = exact::solve(r, objective, &opts);
        (res.status == Status::Optimal)
            .then_some(res.value)
            .flatten()
    }

    /// Every registered length guarantee of milling25 and tsp65 against exact optima; the
    /// paper's 5/2 (Theorem 4) is measured and reported (milling25's registered guarantee is
    /// what our grid reading proves; see its module docs). A solve that does not prove its
    /// optimum within the limit is counted, and the count must stay small.
    #[test]
    fn milling_guarantees_hold_against_opt() {
        let (mut solved, mut unsolved, mut db_over, mut str_over, mut worst25, mut worst65) =
            (0, 0, 0, 0, 0.0f64, 0.0f64);
        for seed in 0..300u64 {
            let r = random_region(seed, 6 + seed as usize % 28, seed % 2 == 0);
            if topology::components(&r).count != 1 {
                continue;
            }
            let Some(opt) = opt(&r, exact::Objective::Length) else {
                unsolved += 1;
                continue;
            };
            solved += 1;
            let (sol, rep) = run("milling25", &r);
            assert_registered("milling25", &r, rep.length, opt);
            assert!(rep.length >= opt, "milling25 below OPT\n{}", r.to_ascii());
            worst25 = worst25.max(rep.length as f64 / opt as f64);
            db_over += usize::from(sol.certificates["l_db"] as u64 > opt);
            str_over += usize::from(sol.certificates["l_str"] as u64 > opt);
            if topology::holes(&r).count == 0 {
                let (_, rep) = run("tsp65", &r);
                assert!(
                    5 * rep.length <= 6 * opt,
                    "tsp65 {} > 6/5 * {opt}\n{}",
                    rep.length,
                    r.to_ascii()
                );
                assert_registered("tsp65", &r, rep.length, opt);
                worst65 = worst65.max(rep.length as f64 / opt as f64);
            }
        }
        eprintln!(
            "exact: {solved} optima, {unsolved} unproven; milling25 max ratio {worst25:.3} \
             (paper: 2.5; L_dB > OPT in {db_over}, L_str > OPT in {str_over}); tsp65 max ratio \
             {worst65:.3}"
        );
        assert!(solved > 40);
        assert!(unsolved * 50 <= solved, "{unsolved} exact solves unproven");
    }

    /// Asserts every registered length guarantee of `name` that applies to `r`.
    fn assert_registered(name: &str, r: &Region, length: u64, opt: u64) {
        let algo = mowmill::algorithms::find(name).unwrap();
        let m = mowmill::algorithms::Measured {
            value: length,
            length,
            max_coverage: 0,
        };
        for g in algo.guarantees.iter().filter(|g| g.when.applies(r)) {
            if g.bound.quantity == mowmill::algorithms::Quantity::MaxCoverage {
                continue;
            }
            assert_eq!(
                g.decide(&m, r.len() as u64, Some(opt), None),
                Some(true),
                "{name}: length {length} breaks {g} (OPT {opt})\n{}",
                r.to_ascii()
            );
        }
    }

    /// Finding (grid reading of Theorem 4): on a one-pixel-thick ring both contours run
    /// through the same 8 pixels, so L_δB = 16 > OPT = 8; the tour (16) still meets 2.5 OPT.
    #[test]
    fn thin_ring_contours_exceed_opt() {
        let r = Region::from_ascii(include_str!(
            "../instances/fixtures/milling25-thin-ring.grid"
        ));
        assert_eq!(opt(&r, exact::Objective::Length), Some(8));
        let (sol, rep) = run("milling25", &r);
        assert_eq!(sol.certificates["l_db"], 16);
        assert_eq!(rep.length, 16);
    }

    #[test]
    fn lawn_tours_against_the_exact_tsp() {
        let (mut solved, mut unsolved) = (0, 0);
        for seed in 0..40u64 {
            let r = random_region(seed, 4 + seed as usize % 10, false);
            let Some(tsp) = opt(&r, exact::Objective::LawnTsp) else {
                unsolved += 1;
                continue;
            };
            solved += 1;
            let (_, mst) = lawn::run_lawn("lawn-mst", &r, mowmill::algorithms::Cutter::Square);
            let (_, chr) =
                lawn::run_lawn("lawn-christofides", &r, mowmill::algorithms::Cutter::Square);
            let (_, two) = lawn::run_lawn("lawn-2opt", &r, mowmill::algorithms::Cutter::Square);
            assert!(
                tsp <= two && mst <= 2 * tsp && 2 * chr <= 3 * tsp,
                "{tsp} {mst} {chr}\n{}",
                r.to_ascii()
            );
        }
        assert!(solved > 20);
        assert_eq!(unsolved, 0, "exact lawn-tsp solves unproven");
    }
}

/// The densest holes without local cut vertices: 1 × 1 holes on a lattice of pitch 3 or 4
/// (h ≈ N/8), the case where bridges dominate the bound of Theorem 7.
#[test]
fn holes1325_hole_lattices() {
    for pitch in [3, 4, 5] {
        for k in 1..8 {
            let side = pitch * (k + 1) + 1;
            let pixels = (0..side)
                .flat_map(|y| (0..side).map(move |x| Pixel::new(x, y)))
                .filter(|p| {
                    !(p.x % pitch == 0
                        && p.y % pitch == 0
                        && p.x > 0
                        && p.y > 0
                        && p.x < side - 1
                        && p.y < side - 1)
                });
            let r = Region::from_pixels(pixels).unwrap();
            assert!(!topology::local_cut_vertices(&r).iter().any(|&c| c));
            let (sol, rep) = run("holes1325", &r);
            let n = r.len() as u64;
            eprintln!(
                "pitch {pitch}, k {k}: N {n}, holes {}, length {} (bound {}), free {}, paid {}",
                topology::holes(&r).count,
                rep.length,
                53 * n / 40,
                sol.certificates["free_bridges"],
                sol.certificates["paid_bridges"]
            );
            assert!(
                40 * rep.length <= 53 * n,
                "pitch {pitch}, k {k}: {} > 53N/40",
                rep.length
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    /// The theorems' bounds hold on every image of a holed region under the symmetries of
    /// the square.
    #[test]
    fn holed_images_keep_the_bounds(seed in 0u64..1_000_000, s in 0u8..8) {
        if let Some(r) = random_holed_region(seed, 6, 6) {
            let r = r.transformed(mowmill::Symmetry(s));
            let (_, rep) = run("holes1325", &r);
            prop_assert!(40 * rep.length <= 53 * r.len() as u64);
            let (sol, rep) = run("milling25", &r);
            let c = &sol.certificates;
            prop_assert_eq!(rep.length as i64, c["l_db"] + c["l_str"] + c["l_match"] + c["l_connect"]);
        }
    }
}

/// The CLI runs the lawn algorithms with every cutter and checks them with the lawn checker
/// (Euclidean lengths in milli-units for free motion and the disk).
#[test]
fn cli_solves_lawns_with_every_cutter() {
    let dir = std::env::temp_dir().join(format!("mowmill-milling-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("lawn.grid");
    let r = Region::from_ascii("##...##\n##...##\n.......\n...#...\n");
    std::fs::write(&file, r.to_ascii()).unwrap();
    for (cutter, algo) in [
        ("square", "lawn-box"),
        ("square-free", "lawn-2opt"),
        ("disk", "lawn-christofides"),
    ] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_mowmill"))
            .args([
                "solve",
                file.to_str().unwrap(),
                "--algo",
                algo,
                "--cutter",
                cutter,
                "--json",
            ])
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{cutter}: {stdout} {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        assert_eq!(v["valid"], true, "{cutter}: {v}");
        // `algorithm` is the registered name; a non-default cutter names the variant as bench
        // rows do (`evaluate::variant_name`).
        assert_eq!(v["algorithm"], algo);
        let variant = if cutter == "square" {
            algo.to_string()
        } else {
            format!("{algo}[cutter={cutter}]")
        };
        assert_eq!(v["variant"], variant);
        assert!(v["length"].as_u64().unwrap() > 0);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `milling-2opt` on one region: a checked tour no longer than 2N − 2 (its guarantee) and no
/// shorter than N.
fn run_two_opt(region: &Region) -> (Solution, checker::Report) {
    let (sol, rep) = run("milling-2opt", region);
    let n = region.len() as u64;
    assert!(
        rep.length + 2 <= 2 * n.max(1),
        "length {} > 2N - 2, N = {n}\n{}",
        rep.length,
        region.to_ascii()
    );
    assert!(n < 2 || rep.length >= n, "{}", region.to_ascii());
    let g = algorithms::find("milling-2opt").unwrap().guarantees[0];
    assert!(g.holds(rep.length, n));
    (sol, rep)
}

#[test]
fn milling_2opt_tours_pass_the_checker_on_every_family() {
    use mowmill::generate::{Family, GenParams, generate};
    let mut count = 0;
    for family in Family::ALL {
        for seed in 1..=3u64 {
            let mut p = GenParams::new(family, seed);
            p.n = Some(150);
            let Ok(g) = generate(&p) else { continue };
            let region = g.region;
            if region.is_empty() || topology::components(&region).count != 1 {
                continue;
            }
            run_two_opt(&region);
            count += 1;
        }
    }
    for seed in 0..60 {
        let region = random_region(900 + seed, 5 + seed as usize * 3, seed % 2 == 0);
        run_two_opt(&region);
        count += 1;
    }
    // 6 families take `--n` alone (18 regions), plus the 60 random polyominoes.
    assert!(count >= 75, "{count} regions");
}

#[test]
fn milling_2opt_finds_hamiltonian_cycles() {
    // 4 x 6: a Hamiltonian cycle of 24 moves, the optimum.
    let (_, rep) = run_two_opt(&Region::rectangle(6, 4));
    assert_eq!(rep.length, 24);
    // A 5 x 5 ring around a 3 x 3 hole: 16 pixels, 16 moves.
    let ring = Region::from_ascii("#####\n#...#\n#...#\n#...#\n#####\n");
    assert_eq!(run_two_opt(&ring).1.length, 16);
    // An 8 x 4 rectangle (even area): Hamiltonian.
    assert_eq!(run_two_opt(&Region::rectangle(8, 4)).1.length, 32);
    // Tiny regions: one pixel (no move), a domino (there and back).
    assert_eq!(run_two_opt(&Region::rectangle(1, 1)).1.length, 0);
    assert_eq!(run_two_opt(&Region::rectangle(2, 1)).1.length, 2);
    // A path of 5 pixels: every tour walks it twice, 2N - 2 = 8.
    assert_eq!(run_two_opt(&Region::rectangle(5, 1)).1.length, 8);
}

#[test]
fn milling_2opt_is_deterministic() {
    let region = random_region(77, 300, false);
    let algo = algorithms::find("milling-2opt").unwrap();
    let a = (algo.run)(&region, &Options::default()).unwrap();
    let b = (algo.run)(&region, &Options::default()).unwrap();
    assert_eq!(a.outputs[0].cover, b.outputs[0].cover);
    assert_eq!(a.certificates, b.certificates);
}

#[test]
fn milling_2opt_above_the_matrix_limit_walks_the_doubled_tree() {
    // 6,400 pixels: no distance matrix, the depth-first tree walked around, 2N - 2 moves.
    let region = Region::rectangle(80, 80);
    let (sol, rep) = run_two_opt(&region);
    assert_eq!(sol.certificates["local_search"], 0);
    assert_eq!(rep.length, 2 * 6400 - 2);
}
