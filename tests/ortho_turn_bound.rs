//! The turn lower bound of `ortho::turn_lower_bound`: known answers, never above the exact
//! minimum-turn cycle cover of small integral regions, never above the turns of a checked
//! milling (Corollary 4's tour) of generated non-integral polygons.

use mowmill::Region;
use mowmill::exact::{self, Status};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::ortho::{self, Polygon, TurnBound, check, corollary4, feasibility, turn_lower_bound};

fn bound_of(polygon: &Polygon) -> TurnBound {
    let erosion = feasibility(polygon).expect("millable");
    turn_lower_bound(polygon, &erosion).unwrap()
}

fn wkt(text: &str) -> TurnBound {
    bound_of(&Polygon::parse(text, "t.wkt").unwrap())
}

fn grid(text: &str) -> TurnBound {
    bound_of(&Polygon::from_region(&Region::from_ascii(text)).unwrap())
}

/// The exact minimum-turn cycle cover of a small region (pixel walks, which are millings).
fn cc_turns(region: &Region) -> u64 {
    let result = exact::solve(
        region,
        exact::Objective::CcTurns,
        &mowmill::warm_start::exact_options(),
    );
    assert_eq!(
        result.status,
        Status::Optimal,
        "the exact solver must settle\n{}",
        region.to_ascii()
    );
    result.value.unwrap()
}

#[test]
fn known_answers() {
    // A unit square: the one centre, a walk that never moves, 4 turns.
    let b = wkt("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))");
    assert_eq!((b.convex_corners, b.best()), (4, 4));
    // The 4 × 1.5 sliver: four convex corners; its contour tour has 4 turns.
    let b = wkt("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))");
    assert_eq!((b.convex_corners, b.best()), (4, 4));
    // A unit-wide corridor: two dead ends, a U-turn each; one horizontal link sees everything.
    let b = grid("#####\n");
    assert_eq!((b.convex_corners, b.rooks, b.best()), (4, 1, 4));
    // A unit-wide L: two dead ends and the outer corner of the bend, 5, even: 6 = OPT.
    let l = "#..\n#..\n###\n";
    let b = grid(l);
    assert_eq!((b.convex_corners, b.best()), (5, 6));
    assert_eq!(cc_turns(&Region::from_ascii(l)), 6);
    // A unit-wide U: dead ends (2 + 2) and two outer corners: 6, the walk there and back has 8.
    let u = "#.#\n#.#\n###\n";
    let b = grid(u);
    assert_eq!(b.convex_corners, 6);
    assert!(b.best() <= cc_turns(&Region::from_ascii(u)));
    // A square with a hole: the ring of width 1; the hole's corners are reflex for P.
    let b = grid("###\n#.#\n###\n");
    assert_eq!((b.convex_corners, b.best()), (4, 4));
    // A 5 × 5 square: five points more than 1 apart in both coordinates are independent.
    let b = grid("#####\n#####\n#####\n#####\n#####\n");
    assert_eq!(b.convex_corners, 4);
    assert!(b.rooks >= 5, "{b:?}");
    // A non-integral dead end of width exactly 1 (x from 0.25 to 1.25): a U-turn at its end,
    // and three convex corners.
    let b = wkt("POLYGON ((0.25 0, 1.25 0, 1.25 2.5, 3.5 2.5, 3.5 4, 0.25 4, 0.25 0))");
    assert_eq!(b.convex_corners, 2 + 3, "{b:?}");
    // Two holes pinched at a corner: the two quadrants of P between them are isolated, so
    // 4 outer corners + 2.
    let pinch = "####\n#.##\n##.#\n####\n";
    let b = grid(pinch);
    assert_eq!(b.convex_corners, 6);
    assert!(b.best() <= cc_turns(&Region::from_ascii(pinch)));
}

#[test]
fn best_is_even_and_at_least_four() {
    let b = TurnBound {
        convex_corners: 5,
        rooks: 2,
    };
    assert_eq!(b.best(), 6);
    let b = TurnBound {
        convex_corners: 0,
        rooks: 1,
    };
    assert_eq!(b.best(), 4);
}

/// Small integral regions of several families, with the parameters the family needs.
fn small_regions(count_per_family: u64) -> Vec<(String, Region)> {
    let mut out = Vec::new();
    let families = [
        (Family::RandomSimple, 4usize, 0usize),
        (Family::RandomHoled, 8, 1),
        (Family::Thin, 6, 0),
        (Family::Thin, 8, 1),
        (Family::ThinArms, 5, 0),
        (Family::Pinholes, 9, 1),
        (Family::Boundary, 4, 0),
    ];
    for (family, smallest, holes) in families {
        for seed in 0..count_per_family {
            let mut params = GenParams::new(family, 7_000 + seed);
            params.n = Some(smallest + seed as usize % (15 - smallest));
            if holes > 0 {
                params.holes = Some(holes);
            }
            match generate(&params) {
                Ok(g) => out.push((format!("{family:?} seed {}", params.seed), g.region)),
                Err(e) => panic!("{family:?} seed {}: {e}", params.seed),
            }
        }
    }
    out
}

fn soak(count_per_family: u64) -> (usize, f64, f64) {
    let (mut compared, mut worst, mut sum) = (0usize, 0f64, 0f64);
    for (what, region) in small_regions(count_per_family) {
        let polygon = Polygon::from_region(&region).unwrap();
        let bound = bound_of(&polygon);
        let opt = cc_turns(&region);
        assert!(
            bound.best() <= opt,
            "{what}: bound {bound:?} (best {}) > OPT {opt}\n{}",
            bound.best(),
            region.to_ascii()
        );
        let ratio = bound.best() as f64 / opt as f64;
        worst = worst.max(ratio);
        sum += ratio;
        compared += 1;
    }
    (compared, worst, sum / compared as f64)
}

#[test]
fn never_above_the_exact_minimum_turn_cycle_cover() {
    let (compared, worst, mean) = soak(40);
    eprintln!("{compared} regions: bound / OPT max {worst:.3}, mean {mean:.3}");
    assert_eq!(compared, 7 * 40);
    assert!(worst <= 1.0);
}

/// The bigger run: `cargo test --release --test ortho_turn_bound -- --ignored --nocapture`.
#[test]
#[ignore]
fn soak_thousands_of_regions() {
    let (compared, worst, mean) = soak(300);
    eprintln!("{compared} regions: bound / OPT max {worst:.3}, mean {mean:.3}");
    assert!(worst <= 1.0);
}

#[test]
fn never_above_a_checked_milling_of_generated_polygons() {
    for family in ["ortho-perturbed", "ortho-holed", "ortho-sliver"] {
        let (mut polygons, mut sum, mut worst) = (0usize, 0f64, 0f64);
        for seed in 0..100u64 {
            let n = 8 + (seed as usize * 7) % 23;
            let polygon = ortho::generate(family, n, seed).unwrap();
            let Ok((tour, _)) = corollary4(&polygon) else {
                // Corollary 4 cannot always join the pieces of a holed polygon (its docs); the
                // bound is still computed, against no upper bound.
                bound_of(&polygon);
                continue;
            };
            let report = check(&polygon, &tour).unwrap();
            assert!(report.valid, "{family} n {n} seed {seed}");
            let bound = bound_of(&polygon);
            assert!(
                bound.best() <= report.turns,
                "{family} n {n} seed {seed}: {bound:?} > {} turns\n{}",
                report.turns,
                polygon.to_wkt()
            );
            let ratio = report.turns as f64 / bound.best() as f64;
            sum += ratio;
            worst = worst.max(ratio);
            polygons += 1;
        }
        eprintln!(
            "{family}: {polygons} polygons, corollary4 turns / bound: mean {:.3}, worst {worst:.3}",
            sum / polygons as f64
        );
        assert!(polygons >= 80, "{family}: {polygons}");
    }
}
