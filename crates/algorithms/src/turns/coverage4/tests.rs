//! Tests of the four-coverage repair: hand-made walks, random tours against the reference
//! implementation, and the bound on visits.

use super::*;
use crate::checker::{Mode, check};

#[test]
fn redundant_loops_are_cut() {
    // A 1x3 row walked back and forth three times: the middle pixel is visited 6 times.
    let r = Region::rectangle(3, 1);
    let p = |x| Pixel::new(x, 0);
    let walk = vec![
        p(0),
        p(1),
        p(2),
        p(1),
        p(0),
        p(1),
        p(2),
        p(1),
        p(0),
        p(1),
        p(2),
        p(1),
    ];
    let before = check(&r, &CycleCover::tour(walk.clone()), Mode::Milling);
    assert_eq!(before.max_coverage, 6);
    let (after, stuck) = coverage4(&r, &CycleCover::tour(walk));
    let rep = check(&r, &after, Mode::Milling);
    assert!(rep.valid && after.is_tour());
    assert_eq!(stuck, 0);
    assert!(rep.max_coverage <= 4 && rep.turns <= before.turns);
}

/// Tours to rewrite: the merged tours (both merges) of the cycle-cover algorithms on
/// generated regions of several families and styles, and the same tours with heavy
/// overlap added (the tour walked twice, and straight spikes out and back at random
/// visits), which reach the rarer moves.
fn sample_tours(seeds: u64) -> Vec<(Region, CycleCover)> {
    use crate::generate::{Family, GenParams, Style, generate};
    use crate::{self as algorithms, Merge, Objective, Options};
    let mut out = Vec::new();
    for seed in 1..=seeds {
        let (family, style, n) = match seed % 6 {
            0 => (Family::RandomSimple, Some(Style::Blob), 120),
            1 => (Family::RandomHoled, None, 200),
            2 => (Family::Thin, None, 80),
            3 => (Family::Band, None, 150),
            4 => (Family::Donut, None, 100),
            _ => (
                Family::RandomSimple,
                Some(Style::ALL[(seed % 5) as usize]),
                60,
            ),
        };
        let Ok(g) = generate(&GenParams {
            n: Some(n),
            style,
            ..GenParams::new(family, seed)
        }) else {
            continue;
        };
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
                let Ok(sol) = (algo.run)(&region, &opts) else {
                    continue;
                };
                let Some(o) = sol.outputs.iter().find(|o| o.objective == Objective::Turns) else {
                    continue;
                };
                let walk = o.cover.cycles[0].clone();
                out.push((region.clone(), o.cover.clone()));
                // Walked twice, with spikes: at every 7th visit (shifted by the seed), out
                // and back along a straight line of up to 3 pixels in the region.
                let mut heavy = walk.clone();
                for (k, &q) in walk.iter().enumerate() {
                    heavy.push(q);
                    if (k as u64 + seed).is_multiple_of(7) {
                        let d = Dir::from_index((k + seed as usize) % 4);
                        let mut line = vec![q];
                        while line.len() < 4 && region.contains(line[line.len() - 1].step(d)) {
                            line.push(line[line.len() - 1].step(d));
                        }
                        heavy.extend(line[1..].iter().chain(line[..line.len() - 1].iter().rev()));
                    }
                }
                out.push((region.clone(), CycleCover::tour(heavy)));
                // Random loops from the tour's first pixel, each closed by a shortest path.
                let mut loops = walk.clone();
                let hub = region.index_of(walk[0]).unwrap();
                let mut rng = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
                for _ in 0..2 + seed % 5 {
                    loops.push(walk[0]);
                    let mut at = hub;
                    for _ in 0..3 + seed % 9 {
                        rng ^= rng << 13;
                        rng ^= rng >> 7;
                        rng ^= rng << 17;
                        let nb: Vec<usize> = region.neighbors(at).collect();
                        at = nb[(rng % nb.len() as u64) as usize];
                        loops.push(region.pixel(at));
                    }
                    // Back to the hub, which the next loop (or the closing move) visits.
                    let back = shortest_path(&region, at, hub);
                    loops.extend(back.iter().map(|&q| region.pixel(q)));
                    loops.pop();
                }
                out.push((region.clone(), CycleCover::tour(loops)));
            }
        }
    }
    out
}

/// A shortest path from `a` to `b` (region indices), `a` excluded.
fn shortest_path(region: &Region, a: usize, b: usize) -> Vec<usize> {
    let mut prev = vec![usize::MAX; region.len()];
    prev[a] = a;
    let mut queue = std::collections::VecDeque::from([a]);
    while let Some(u) = queue.pop_front() {
        for v in region.neighbors(u) {
            if prev[v] == usize::MAX {
                prev[v] = u;
                queue.push_back(v);
            }
        }
    }
    let mut out = vec![b];
    while prev[*out.last().unwrap()] != a {
        out.push(prev[*out.last().unwrap()]);
    }
    out.reverse();
    if a == b { Vec::new() } else { out }
}

/// The incremental search returns exactly the walks of the former implementation, which
/// recounted everything after every move (kept as `reference`).
#[test]
fn same_walks_as_the_reference() {
    let (mut tours, mut over) = (0, 0);
    for (region, tour) in sample_tours(60) {
        let before = check(&region, &tour, Mode::Milling);
        assert!(before.valid, "{:?}", before.error);
        let new = coverage4(&region, &tour);
        let old = reference::coverage4(&region, &tour);
        assert_eq!(new.1, old.1);
        assert!(new.0.cycles == old.0.cycles, "walks differ");
        tours += 1;
        over += usize::from(before.max_coverage > 4);
    }
    assert!(tours >= 300 && over >= 100, "{tours} tours, {over} over 4");
}

/// The tours of `tests/coverage4.rs` that need the rarer moves (transplants, reversals,
/// slide chains): the same walks as the former implementation too.
#[test]
fn rare_moves_give_the_reference_walks() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .join("instances/regressions");
    let donut = crate::instance::Instance::read(&dir.join("coverage4-donut-k9-L27.grid"))
        .unwrap()
        .region;
    let tour = CycleCover::read(&dir.join("coverage4-donut-k9-L27.tour.json")).unwrap();
    let mut cases = vec![(donut, tour)];
    for text in [
        r#"{"cycles":[[[-2,2],[-1,2],[0,2],[1,2],[2,2],[3,2],[4,2],[3,2],[2,2],[1,2],[0,2],[-1,2],[-1,3],[-1,4],[-1,5],[-1,6],[-1,7],[-1,6],[-1,5],[-1,4],[-1,3],[-1,2],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0],[1,1],[1,2],[1,3],[1,4],[1,5],[1,6],[1,7],[0,7],[0,6],[0,5],[0,4],[0,3],[0,2],[0,1],[0,0],[0,-1],[1,-1],[2,-1],[2,0],[2,1],[2,2],[2,3],[2,4],[2,5],[2,6],[1,6],[0,6],[-1,6],[-2,6],[-2,5],[-2,4],[-1,4],[0,4],[1,4],[2,4],[3,4],[3,5],[2,5],[2,4],[2,3],[2,2],[2,1],[2,0],[3,0],[3,1],[3,2],[2,2],[1,2],[0,2],[-1,2]]]}"#,
        r#"{"cycles":[[[2,-2],[2,-1],[2,0],[2,1],[3,1],[3,2],[3,3],[3,2],[4,2],[5,2],[5,1],[5,0],[4,0],[3,0],[2,0],[1,0],[0,0],[0,1],[0,2],[0,3],[0,4],[0,5],[0,6],[0,7],[0,8],[0,9],[0,8],[0,7],[0,6],[0,5],[0,4],[0,3],[0,2],[0,1],[0,0],[0,-1],[0,-2],[0,-1],[0,0],[-1,0],[-2,0],[-2,-1],[-2,0],[-2,1],[-1,1],[0,1],[1,1],[2,1],[3,1],[4,1],[5,1],[6,1],[5,1],[4,1],[4,0],[4,-1],[4,-2],[5,-2],[4,-2],[4,-1],[3,-1],[2,-1],[1,-1],[0,-1],[0,0],[0,1],[0,2],[0,3],[0,4],[0,5],[0,6],[0,7],[-1,7],[0,7],[0,6],[0,5],[0,4],[-1,4],[0,4],[1,4],[1,5],[1,4],[1,3],[1,2],[1,1],[1,0],[1,-1],[2,-1]]]}"#,
    ] {
        let tour = CycleCover::from_json(text, "tour").unwrap();
        let region = Region::from_pixels(tour.cycles[0].clone()).unwrap();
        cases.push((region, tour));
    }
    for (region, tour) in cases {
        let new = coverage4(&region, &tour);
        let old = reference::coverage4(&region, &tour);
        assert_eq!(new.1, old.1);
        assert!(new.0.cycles == old.0.cycles, "walks differ");
    }
}

/// Every move on its own, at every over-covered pixel of every state the search passes
/// through, gives the walk the former implementation's move gives (or none where it
/// gives none), so that the rarer moves are compared too.
#[test]
fn each_move_gives_the_reference_walk() {
    let mut found = [0usize; 6];
    for (region, tour) in sample_tours(6) {
        let mut search = Search::new(&region, &tour);
        loop {
            let over: Vec<usize> = search.queue.iter().rev().take(3).map(|e| e.1).collect();
            for p in over {
                for w in 0..search.cycles.len() {
                    let (walk, count, now) = (&search.cycles[w], &search.count, search.excess);
                    let (turns, budget) = (search.turns[w].as_ref().unwrap(), search.budgets[w]);
                    let mut index = None;
                    let new = [
                        excise_at(&region, walk, turns, count, p),
                        pair_drop_at(&region, walk, turns, &mut index, count, now, p, budget),
                        reroute_at(&region, walk, turns, count, p, budget),
                        excise_and_graft(&region, walk, count, now, p, budget),
                        reverse_then_reroute(&region, walk, count, p, budget),
                        slide_chain(&region, walk, turns, &mut index, count, now, p, budget),
                    ]
                    .map(|m| m.map(|pieces| rebuild(walk, &pieces)));
                    let old = [
                        reference::excise_at(&region, walk, count, p),
                        reference::pair_drop_at(&region, walk, count, p, budget),
                        reference::reroute_at(&region, walk, count, p, budget),
                        reference::excise_and_graft(&region, walk, count, p, budget),
                        reference::reverse_then_reroute(&region, walk, count, p, budget),
                        reference::slide_chain(&region, walk, count, p, budget),
                    ];
                    for k in 0..6 {
                        assert!(new[k] == old[k], "move {k} differs");
                        found[k] += usize::from(new[k].is_some());
                    }
                }
            }
            if !search.step() {
                break;
            }
        }
    }
    eprintln!("moves found (excise, pair drop, reroute, transplant, reversal, slides): {found:?}");
    assert!(found.iter().all(|&f| f > 0), "{found:?}");
}

/// After every move the coverage, the excess, the queue of pixels to treat and the turns
/// per position kept by the search equal a recount of the walks, and the checker finds
/// the walk valid with no more turns than the input.
#[test]
fn incremental_state_equals_a_recount() {
    let mut moves = 0;
    for (region, tour) in sample_tours(24) {
        let before = check(&region, &tour, Mode::Milling);
        let mut search = Search::new(&region, &tour);
        while search.step() {
            let cover = CycleCover::new(search.cycles.clone());
            let rep = check(&region, &cover, Mode::Milling);
            assert!(rep.valid, "{:?}", rep.error);
            assert!(rep.turns <= before.turns);
            assert_eq!(search.count, rep.coverage);
            let excess: u64 = rep
                .coverage
                .iter()
                .map(|&c| u64::from(c.saturating_sub(4)))
                .sum();
            assert_eq!(search.excess, excess);
            let queue: std::collections::BTreeSet<(u32, usize)> = (0..region.len())
                .filter(|&i| rep.coverage[i] > 4 && !search.stuck[i])
                .map(|i| (rep.coverage[i], i))
                .collect();
            assert_eq!(search.queue, queue);
            for (walk, turns) in search.cycles.iter().zip(&search.turns) {
                let fresh = Turns::of(walk).expect("valid walk");
                let t = turns.as_ref().expect("valid walk");
                assert_eq!(
                    (t.total, &t.prefix, &t.u_turns),
                    (fresh.total, &fresh.prefix, &fresh.u_turns)
                );
                assert_eq!(t.total, walk_cost(walk).unwrap().1);
            }
            moves += 1;
        }
    }
    assert!(moves >= 200, "only {moves} moves");
}

/// [`Turns::cost`] of pieces equals [`walk_cost`] of the rebuilt walk, and [`dropped`]
/// with the new pixels accounts for the change of coverage, on random cuts of a walk.
#[test]
fn piece_costs_equal_a_recount() {
    let walk: Walk = [
        (0, 0),
        (1, 0),
        (2, 0),
        (2, 1),
        (2, 2),
        (1, 2),
        (1, 1),
        (0, 1),
        (0, 2),
        (0, 3),
        (1, 3),
        (1, 2),
        (0, 2),
        (0, 1),
    ]
    .iter()
    .map(|&(x, y)| Pixel::new(x, y))
    .collect();
    let turns = Turns::of(&walk).unwrap();
    let m = walk.len();
    let mut seed = 7u64;
    let mut next = |k: usize| {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 33) as usize % k
    };
    for _ in 0..2000 {
        // Up to three runs over disjoint stretches, each forward or reversed, and new pixels.
        let mut cuts: Vec<usize> = (0..3).map(|_| next(m)).collect();
        cuts.sort_unstable();
        let mut pieces = Vec::new();
        for x in 0..cuts.len() {
            let (a, b) = (
                cuts[x],
                if x + 1 < cuts.len() {
                    cuts[x + 1]
                } else {
                    cuts[0] + m
                },
            );
            let len = next(b - a + 1);
            pieces.push(Piece::Run {
                start: a,
                len,
                rev: next(2) == 1,
            });
            if next(3) == 0 {
                pieces.push(Piece::New(vec![walk[next(m)]]));
            }
        }
        let out = rebuild(&walk, &pieces);
        let expect = walk_cost(&out).ok().map(|(_, t)| (out.len() as u64, t));
        assert_eq!(turns.cost(&walk, &pieces), expect, "{pieces:?}");
        let mut cov: std::collections::BTreeMap<Pixel, i64> = Default::default();
        walk.iter().for_each(|&q| *cov.entry(q).or_default() += 1);
        dropped(m, &pieces)
            .iter()
            .for_each(|&k| *cov.entry(walk[k]).or_default() -= 1);
        for p in &pieces {
            if let Piece::New(px) = p {
                px.iter().for_each(|&q| *cov.entry(q).or_default() += 1);
            }
        }
        let mut after: std::collections::BTreeMap<Pixel, i64> = Default::default();
        out.iter().for_each(|&q| *after.entry(q).or_default() += 1);
        cov.retain(|_, c| *c != 0);
        assert_eq!(cov, after);
    }
}
