//! `--coverage4` (Theorem 5.6 of *Optimal covering tours with turn costs*): on random small
//! regions and random covering tours with heavy overlap, the rewritten tour passes the
//! checker, has no more turns than the input and, unless `coverage4` reports stuck pixels,
//! covers every pixel at most 4 times.

use mowmill::algorithms::coverage4::coverage4;
use mowmill::algorithms::{self, Merge, Objective, Options};
use mowmill::checker::{Mode, check};
use mowmill::region::{Dir, Pixel, Region};
use mowmill::tour::CycleCover;
use proptest::prelude::*;
use std::collections::VecDeque;

/// A connected region grown from (0, 0) by the steps `grow` (pixel choice, direction).
fn grown_region(grow: &[(usize, u8)]) -> Region {
    let mut pixels = vec![Pixel::new(0, 0)];
    for &(k, d) in grow {
        let q = pixels[k % pixels.len()].step(Dir::from_index(usize::from(d)));
        if !pixels.contains(&q) {
            pixels.push(q);
        }
    }
    Region::from_pixels(pixels).expect("small region")
}

/// A shortest path from `a` to `b` in the region, both included.
fn path(region: &Region, a: usize, b: usize) -> Vec<usize> {
    let mut prev = vec![usize::MAX; region.len()];
    prev[a] = a;
    let mut queue = VecDeque::from([a]);
    while let Some(u) = queue.pop_front() {
        for v in region.neighbors(u) {
            if prev[v] == usize::MAX {
                prev[v] = u;
                queue.push_back(v);
            }
        }
    }
    let mut out = vec![b];
    while *out.last().unwrap() != a {
        out.push(prev[*out.last().unwrap()]);
    }
    out.reverse();
    out
}

/// A covering tour made of closed sub-walks through one hub pixel: random walks of the given
/// lengths, each closed by a shortest path back, then a detour to every pixel not yet visited.
/// With `straight`, a step goes on in the heading of the previous one where it can unless its
/// value is 0, so that the tour has long links and few turns.
fn overlapping_tour(region: &Region, hub: usize, loops: &[Vec<u8>], straight: bool) -> Vec<Pixel> {
    let mut walk = vec![hub];
    let close = |walk: &mut Vec<usize>, at: usize| {
        walk.extend(&path(region, at, hub)[1..]);
    };
    for steps in loops {
        let mut at = hub;
        let mut heading: Option<Dir> = None;
        for &s in steps {
            let ahead = heading.and_then(|d| region.neighbor(at, d));
            let next = match ahead {
                Some(q) if straight && s != 0 => q,
                _ => {
                    let nb: Vec<usize> = region.neighbors(at).collect();
                    nb[usize::from(s) % nb.len()]
                }
            };
            heading = region.pixel(at).dir_to(region.pixel(next));
            at = next;
            walk.push(at);
        }
        close(&mut walk, at);
    }
    for q in 0..region.len() {
        if !walk.contains(&q) {
            walk.extend(&path(region, hub, q)[1..]);
            close(&mut walk, q);
        }
    }
    walk.pop(); // the walk is closed: its last pixel is the hub again
    walk.into_iter().map(|q| region.pixel(q)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn heavy_overlap_is_reduced_to_four(
        grow in prop::collection::vec((0usize..100, 0u8..4), 1..24),
        hub in 0usize..100,
        loops in prop::collection::vec(prop::collection::vec(0u8..4, 1..12), 2..9),
        straight in any::<bool>(),
    ) {
        let region = grown_region(&grow);
        prop_assume!(region.len() >= 2);
        let walk = overlapping_tour(&region, hub % region.len(), &loops, straight);
        let before = check(&region, &CycleCover::tour(walk.clone()), Mode::Milling);
        prop_assert!(before.valid, "{:?}", before.error);
        let (after, stuck) = coverage4(&region, &CycleCover::tour(walk.clone()));
        let rep = check(&region, &after, Mode::Milling);
        prop_assert!(rep.valid && after.is_tour(), "{:?}", rep.error);
        prop_assert!(rep.turns <= before.turns, "{} > {}", rep.turns, before.turns);
        prop_assert_eq!(stuck > 0, rep.max_coverage > 4);
        prop_assert!(
            rep.max_coverage <= 4,
            "max coverage {} after (was {})\n{}\n{}",
            rep.max_coverage,
            before.max_coverage,
            region.to_ascii(),
            CycleCover::tour(walk).to_json()
        );
    }
}

/// Tours from `strips-matching` / `star-cover` on random regions (`tests/turns.rs`) where a
/// pixel stays covered 5 times by straight passes until a transplant or a reversal is used.
#[test]
fn straight_passes_are_reduced_to_four() {
    let tours = [
        // (2, 2): passes E>E W>W N>N S>S W>W.
        r#"{"cycles":[[[-2,2],[-1,2],[0,2],[1,2],[2,2],[3,2],[4,2],[3,2],[2,2],[1,2],[0,2],[-1,2],[-1,3],[-1,4],[-1,5],[-1,6],[-1,7],[-1,6],[-1,5],[-1,4],[-1,3],[-1,2],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0],[1,1],[1,2],[1,3],[1,4],[1,5],[1,6],[1,7],[0,7],[0,6],[0,5],[0,4],[0,3],[0,2],[0,1],[0,0],[0,-1],[1,-1],[2,-1],[2,0],[2,1],[2,2],[2,3],[2,4],[2,5],[2,6],[1,6],[0,6],[-1,6],[-2,6],[-2,5],[-2,4],[-1,4],[0,4],[1,4],[2,4],[3,4],[3,5],[2,5],[2,4],[2,3],[2,2],[2,1],[2,0],[3,0],[3,1],[3,2],[2,2],[1,2],[0,2],[-1,2]]]}"#,
        // (0, 4): passes N>N S>S N>N S>W E>E; a spike at (-1, 7) must move.
        r#"{"cycles":[[[2,-2],[2,-1],[2,0],[2,1],[3,1],[3,2],[3,3],[3,2],[4,2],[5,2],[5,1],[5,0],[4,0],[3,0],[2,0],[1,0],[0,0],[0,1],[0,2],[0,3],[0,4],[0,5],[0,6],[0,7],[0,8],[0,9],[0,8],[0,7],[0,6],[0,5],[0,4],[0,3],[0,2],[0,1],[0,0],[0,-1],[0,-2],[0,-1],[0,0],[-1,0],[-2,0],[-2,-1],[-2,0],[-2,1],[-1,1],[0,1],[1,1],[2,1],[3,1],[4,1],[5,1],[6,1],[5,1],[4,1],[4,0],[4,-1],[4,-2],[5,-2],[4,-2],[4,-1],[3,-1],[2,-1],[1,-1],[0,-1],[0,0],[0,1],[0,2],[0,3],[0,4],[0,5],[0,6],[0,7],[-1,7],[0,7],[0,6],[0,5],[0,4],[-1,4],[0,4],[1,4],[1,5],[1,4],[1,3],[1,2],[1,1],[1,0],[1,-1],[2,-1]]]}"#,
    ];
    for text in tours {
        let tour = CycleCover::from_json(text, "tour").unwrap();
        let region = Region::from_pixels(tour.cycles[0].clone()).unwrap();
        let before = check(&region, &tour, Mode::Milling);
        assert!(before.valid && before.max_coverage == 5);
        let (after, stuck) = coverage4(&region, &tour);
        let rep = check(&region, &after, Mode::Milling);
        assert!(rep.valid && after.is_tour(), "{:?}", rep.error);
        assert_eq!((stuck, rep.max_coverage <= 4), (0, true));
        assert!(
            rep.turns <= before.turns,
            "{} > {}",
            rep.turns,
            before.turns
        );
    }
}

/// The merged tours of the cycle-cover algorithms on random regions (other seeds than
/// `tests/turns.rs`): the over-covered ones are all brought down to coverage 4.
#[test]
fn algorithm_tours_are_reduced_to_four() {
    let (mut tours, mut over_before, mut over_after) = (0, 0, 0);
    for seed in 0..300usize {
        let grow: Vec<(usize, u8)> = (0..10 + seed % 60)
            .map(|k| {
                (
                    (seed * 7919 + k * 104_729) % 1000,
                    ((seed + k * k) % 4) as u8,
                )
            })
            .collect();
        let region = grown_region(&grow);
        for name in ["strips-matching", "strips-double", "star-cover"] {
            let algo = algorithms::find(name).unwrap();
            if (algo.precondition)(&region).is_err() {
                continue;
            }
            for merge in [Merge::Naive, Merge::Smart] {
                let opts = Options {
                    merge,
                    ..Options::default()
                };
                let solution = (algo.run)(&region, &opts).unwrap();
                let Some(out) = solution
                    .outputs
                    .iter()
                    .find(|o| o.objective == Objective::Turns)
                else {
                    continue;
                };
                let before = check(&region, &out.cover, Mode::Milling);
                let (after, stuck) = coverage4(&region, &out.cover);
                let rep = check(&region, &after, Mode::Milling);
                assert!(rep.valid && after.is_tour(), "{name}: {:?}", rep.error);
                assert!(
                    rep.turns <= before.turns,
                    "{name}: {} > {}",
                    rep.turns,
                    before.turns
                );
                assert_eq!(stuck > 0, rep.max_coverage > 4);
                tours += 1;
                over_before += usize::from(before.max_coverage > 4);
                over_after += usize::from(rep.max_coverage > 4);
            }
        }
    }
    eprintln!(
        "coverage4: {tours} tours, {over_before} covered a pixel > 4 times, {over_after} still do"
    );
    assert!(over_before > 0, "the test must see over-covered tours");
    assert_eq!(over_after, 0);
}

/// Generated regions of several families and styles (random-simple in every style,
/// random-holed, thin, band, donut), the merged tours of the cycle-cover algorithms with both
/// merges, plus the same tours walked twice: after `coverage4` the checker finds a valid tour
/// with no more turns than the input and every pixel covered at most 4 times (the stuck count
/// says exactly when not).
#[test]
fn generated_families_are_brought_to_four() {
    use mowmill::generate::{Family, GenParams, Style, generate};
    let (mut tours, mut over_before, mut over_after) = (0, 0, 0);
    let mut params = Vec::new();
    for seed in 1..=4u64 {
        for style in Style::ALL {
            params.push(GenParams {
                n: Some(150),
                style: Some(style),
                ..GenParams::new(Family::RandomSimple, seed)
            });
        }
        for (family, n) in [
            (Family::RandomHoled, 250),
            (Family::Thin, 100),
            (Family::Band, 200),
            (Family::Donut, 150),
        ] {
            params.push(GenParams {
                n: Some(n),
                ..GenParams::new(family, seed)
            });
        }
    }
    for gp in params {
        let Ok(g) = generate(&gp) else { continue };
        let region = g.region;
        for name in ["strips-matching", "strips-double", "star-cover"] {
            let algo = algorithms::find(name).unwrap();
            if (algo.precondition)(&region).is_err() {
                continue;
            }
            for merge in [Merge::Naive, Merge::Smart] {
                let opts = Options {
                    merge,
                    ..Options::default()
                };
                let Ok(solution) = (algo.run)(&region, &opts) else {
                    continue;
                };
                let Some(out) = solution
                    .outputs
                    .iter()
                    .find(|o| o.objective == Objective::Turns)
                else {
                    continue;
                };
                let twice: Vec<Pixel> = out.cover.cycles[0].repeat(2);
                for tour in [out.cover.clone(), CycleCover::tour(twice)] {
                    let before = check(&region, &tour, Mode::Milling);
                    assert!(before.valid, "{:?}", before.error);
                    let (after, stuck) = coverage4(&region, &tour);
                    let rep = check(&region, &after, Mode::Milling);
                    assert!(rep.valid && after.is_tour(), "{name}: {:?}", rep.error);
                    assert!(rep.turns <= before.turns, "{name}: turns grew");
                    assert_eq!(stuck, rep.coverage.iter().filter(|&&c| c > 4).count());
                    tours += 1;
                    over_before += usize::from(before.max_coverage > 4);
                    over_after += usize::from(rep.max_coverage > 4);
                }
            }
        }
    }
    eprintln!("coverage4: {tours} tours, {over_before} above 4 before, {over_after} after");
    assert!(
        tours >= 200 && over_before >= 100,
        "{tours} tours, {over_before} over"
    );
    assert_eq!(over_after, 0);
}

/// A former finding, kept as a regression (from a run of the tight families): on the Fig. 5
/// donut k = 9, L = 27 the naive strips-matching tour covers a pixel 13 times, and the local
/// search used to stop with one pixel at 5 visits (4 vertical passes crossed by a horizontal link
/// whose pixels only it covers). Pair drops now remove doubled stretches first (and, without
/// them, a chain of link slides also reaches 4).
#[test]
fn donut_k9_tour_is_brought_to_four() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("instances/regressions");
    let region = mowmill::instance::Instance::read(&dir.join("coverage4-donut-k9-L27.grid"))
        .unwrap()
        .region;
    let tour =
        mowmill::tour::CycleCover::read(&dir.join("coverage4-donut-k9-L27.tour.json")).unwrap();
    let before = check(&region, &tour, Mode::Milling);
    assert!(before.valid && before.max_coverage > 4);
    let (after_cover, stuck) = coverage4(&region, &tour);
    let after = check(&region, &after_cover, Mode::Milling);
    assert!(after.valid, "{:?}", after.error);
    assert!(after.turns <= before.turns);
    assert_eq!((stuck, after.max_coverage), (0, 4));
}

/// Theorem 5.6 implies that capping every pixel at 4 visits costs an optimal tour no turns.
/// The exact `tour-turns` solver with `max_coverage = 4` checks this on small random simple,
/// holed and thin regions, including the thin pocket where our local search stays above 4
/// (`thin --n 100 --seed 5`, the `thin-merge` tour: 88 turns, a pixel visited 6 times): the
/// capped optimum there is 88 too, so a tour as cheap with coverage 4 exists.
#[test]
fn capping_coverage_at_four_costs_optimal_tours_nothing() {
    use mowmill::exact::{ExactOptions, Objective, Status, solve};
    use mowmill::generate::{Family, GenParams, generate};
    let mut compared = 0;
    for (family, n, seed) in [
        (Family::Thin, 100, 5),
        (Family::Thin, 60, 1),
        (Family::Thin, 60, 2),
        (Family::RandomSimple, 40, 1),
        (Family::RandomSimple, 40, 2),
        (Family::RandomHoled, 50, 1),
    ] {
        let region = generate(&GenParams {
            n: Some(n),
            ..GenParams::new(family, seed)
        })
        .unwrap()
        .region;
        let opts = |cap| ExactOptions {
            time_limit: Some(60.0),
            max_coverage: cap,
            ..mowmill::warm_start::exact_options()
        };
        let free = solve(&region, Objective::Turns, &opts(None));
        let capped = solve(&region, Objective::Turns, &opts(Some(4)));
        assert!(capped.valid, "{family} {n} {seed}: {:?}", capped.message);
        assert!(capped.max_coverage.unwrap() <= 4);
        assert_eq!(capped.coverage_cap, Some(4));
        if free.status == Status::Optimal && capped.status == Status::Optimal {
            assert_eq!(capped.value, free.value, "{family} n={n} seed={seed}");
            compared += 1;
        } else {
            // Counted: an unproven pair decides nothing, and at most one may be unproven.
            eprintln!("{family} n={n} seed={seed}: not both proven within 60 s");
        }
    }
    assert!(
        compared >= 5,
        "only {compared} of 6 pairs solved to optimality"
    );
}

/// A cap of 1: the 2x2 square's 4-cycle visits each pixel once (optimal, 4 turns); a row of 3
/// pixels needs its middle pixel twice, so the capped model has no tour and the answer says
/// so; a cap on the length objective is refused.
#[test]
fn coverage_cap_is_enforced_by_the_exact_model() {
    use mowmill::exact::{ExactOptions, Objective, Status, solve};
    let opts = ExactOptions {
        max_coverage: Some(1),
        ..mowmill::warm_start::exact_options()
    };
    let square = solve(&Region::rectangle(2, 2), Objective::Turns, &opts);
    assert_eq!((square.status, square.value), (Status::Optimal, Some(4)));
    let row = solve(&Region::rectangle(3, 1), Objective::Turns, &opts);
    assert!(row.value.is_none(), "{row:?}");
    assert_ne!(row.status, Status::Optimal);
    let length = solve(&Region::rectangle(2, 2), Objective::Length, &opts);
    assert_eq!(length.status, Status::Error);
}

/// Corollary 5.2 promises a star-cover tour covering each pixel at most 4 times. Merging
/// detours add visits; detours are taken only between settled pixels, which proves 4 (see
/// `star_cover`; this instance reached 5 before the tie-break, random-simple 10^6 seed 1
/// before the settled rule, its cut-out in tests/guarantees.rs).
#[test]
fn star_cover_tour_keeps_coverage_four() {
    use mowmill::generate::{Family, GenParams, generate};
    let region = generate(&GenParams {
        n: Some(30_000),
        ..GenParams::new(Family::RandomHoled, 1)
    })
    .unwrap()
    .region;
    let algo = algorithms::find("star-cover").unwrap();
    let sol = (algo.run)(&region, &Options::default()).unwrap();
    for out in &sol.outputs {
        let r = check(&region, &out.cover, Mode::Milling);
        assert!(r.valid, "{:?}", r.error);
        assert!(
            r.max_coverage <= 4,
            "{}: coverage {}",
            out.objective,
            r.max_coverage
        );
    }
}
