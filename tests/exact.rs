//! Tests of the exact baselines: hand fixtures with known optima, a brute-force oracle on tiny
//! regions (shortest paths over (pixel, heading, visited set) states), and properties on small
//! random regions: every result passes the checker with `value` equal to its recount, the
//! optimum lies between every lower bound and every valid tour (the approximations included),
//! cc-turns <= tour-turns, the 8 symmetries of the square keep the optimum, and `weighted`
//! with C = 0 is the length optimum. Every solve has a time limit; instances stay tiny.

use mowmill::algorithms::{self, Objective as AlgoObjective};
use mowmill::checker::{self, Mode};
use mowmill::exact::{ExactOptions, ExactResult, Objective, Status, solve};
use mowmill::gridfile::GridFile;
use mowmill::region::{Pixel, Region, Symmetry};
use mowmill::tour::CycleCover;
use proptest::prelude::*;

#[path = "common/brute.rs"]
mod brute;
use brute::{brute_cc_turns, brute_lawn, brute_tour};
use std::collections::HashMap;
use std::path::Path;

const LIMIT: f64 = 20.0;

fn opts() -> ExactOptions {
    ExactOptions {
        time_limit: Some(LIMIT),
        ..mowmill::warm_start::exact_options()
    }
}

fn fixture(name: &str) -> Region {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("instances/fixtures")
        .join(name);
    GridFile::read(&path).expect("fixture reads").region
}

/// Solves and checks everything a result promises about itself.
fn solved(region: &Region, objective: Objective) -> ExactResult {
    let r = solve(region, objective, &opts());
    assert_eq!(
        r.status,
        Status::Optimal,
        "{objective} on\n{}{r:?}",
        region.to_ascii()
    );
    let cover = r
        .cover
        .as_ref()
        .expect("an optimal result carries its cover");
    let rep = checker::check(region, cover, objective.mode());
    assert!(rep.valid, "{objective}: {:?}", rep.error);
    assert!(r.valid);
    assert_eq!(
        Some(objective.value_of(&rep)),
        r.value,
        "{objective}: recount equals value"
    );
    assert_eq!(r.value, Some(r.lower_bound));
    assert_eq!(
        (r.length, r.turns, r.cycles),
        (Some(rep.length), Some(rep.turns), Some(rep.cycles))
    );
    if objective.is_tour() {
        assert_eq!(rep.cycles, 1, "{objective}: a tour is one closed walk");
    }
    r
}

fn value(region: &Region, objective: Objective) -> u64 {
    solved(region, objective).value.expect("optimal value")
}

#[test]
fn hand_fixtures_have_their_known_optima() {
    let rect = fixture("rect-2x3.grid");
    assert_eq!(value(&rect, Objective::Length), 6);
    assert_eq!(value(&rect, Objective::CcTurns), 4);
    assert_eq!(value(&rect, Objective::Turns), 4);
    let row = fixture("row-1x4.grid");
    assert_eq!(value(&row, Objective::Length), 6);
    assert_eq!(value(&row, Objective::CcTurns), 4);
    assert_eq!(value(&row, Objective::Turns), 4);
    let sq3 = fixture("square-3x3.grid");
    assert_eq!(value(&sq3, Objective::Length), 10);
    assert_eq!(value(&sq3, Objective::CcTurns), 8);
    assert_eq!(value(&sq3, Objective::Turns), 8);
    assert_eq!(value(&fixture("square-5x5.grid"), Objective::Length), 26);
}

#[test]
fn small_special_cases() {
    let one = Region::rectangle(1, 1);
    for o in [
        Objective::Length,
        Objective::CcTurns,
        Objective::Turns,
        Objective::LawnTsp,
    ] {
        let r = solved(&one, o);
        assert_eq!(r.length, Some(0));
    }
    assert_eq!(value(&one, Objective::Turns), 4);
    assert_eq!(value(&one, Objective::Weighted(3)), 12);
    let two = Region::rectangle(2, 1);
    assert_eq!(value(&two, Objective::Length), 2);
    assert_eq!(value(&two, Objective::Turns), 4);
    assert_eq!(value(&two, Objective::Weighted(2)), 10);
    // A plus: two doubled strips cover it with 8 turns, but one tour needs 10 (they only
    // cross at the centre, which no free splice can join).
    let plus = Region::from_ascii(".#.\n###\n.#.\n");
    assert_eq!(value(&plus, Objective::CcTurns), 8);
    assert_eq!(value(&plus, Objective::Turns), 10);
    assert_eq!(value(&plus, Objective::Length), 8);
}

/// `weighted-cc` by hand. A walk there and back along a strip of k pixels has length
/// 2(k − 1) and two U-turns (4 turns); a closed walk around a 2 × 2 block has length 4 and
/// four 90° turns; a one-pixel walk has length 0 and 4 turns (the checker's convention).
#[test]
fn weighted_cycle_covers_by_hand() {
    let cases = [
        // 1 x 2: there and back, 2 + 4C (two one-pixel walks cost 8C).
        ("##\n", 202, 6),
        // 2 x 2: around the block, 4 + 4C.
        ("##\n##\n", 204, 8),
        // 1 x 3: there and back, 4 + 4C.
        ("###\n", 204, 8),
        // A plus: two crossing strips of 3, 2 (4 + 4C) (its tour needs 10 turns).
        (".#.\n###\n.#.\n", 408, 16),
        // A spur on the middle of a strip of 5: the strip there and back (8 + 4C) and the
        // spur alone (4C) beat a detour into the spur (10 + 8C) and a strip of 2 there and
        // back (2 + 4C) by 2: the one-pixel walk pays off.
        ("..#..\n#####\n", 408, 16),
    ];
    for (ascii, at_50, at_1) in cases {
        let r = Region::from_ascii(ascii);
        assert_eq!(value(&r, Objective::WeightedCc(50)), at_50, "{ascii}");
        assert_eq!(value(&r, Objective::WeightedCc(1)), at_1, "{ascii}");
        // With C = 0 every pixel is a free one-pixel walk.
        assert_eq!(value(&r, Objective::WeightedCc(0)), 0);
    }
    let spur = solved(
        &Region::from_ascii("..#..\n#####\n"),
        Objective::WeightedCc(50),
    );
    assert_eq!(
        (spur.length, spur.turns, spur.cycles),
        (Some(8), Some(8), Some(2))
    );
    assert_eq!(spur.turn_cost, Some(50));
}

#[test]
fn disconnected_regions_have_cycle_covers_but_no_tours() {
    let r = Region::from_ascii("##.#\n##..\n");
    for o in [Objective::Length, Objective::Turns, Objective::Weighted(1)] {
        let res = solve(&r, o, &opts());
        assert_eq!(res.status, Status::Infeasible, "{o}");
        assert!(res.value.is_none() && !res.valid && res.message.is_some());
    }
    // A 2x2 block (4 turns) and an isolated pixel (4 turns).
    assert_eq!(value(&r, Objective::CcTurns), 8);
    // Weighted: the block (4 + 4C) and the isolated pixel (4C).
    assert_eq!(value(&r, Objective::WeightedCc(5)), 44);
    // The lawn tour may leave the grass.
    assert_eq!(value(&r, Objective::LawnTsp), 8);
}

#[test]
fn lawn_tsp_of_a_scattered_lawn() {
    // Corners of a 5 x 4 box and a point on its bottom side: the box perimeter, 2 (4 + 3).
    let r = Region::from_ascii("#...#\n.....\n.....\n#.#.#\n");
    assert_eq!(value(&r, Objective::LawnTsp), 14);
    // An interior point costs a detour of 2.
    let r = Region::from_ascii("#...#\n.....\n..#..\n#...#\n");
    assert_eq!(value(&r, Objective::LawnTsp), 16);
}

#[test]
fn json_has_the_contract_keys() {
    let r = solve(&Region::rectangle(3, 2), Objective::Turns, &opts());
    let v = serde_json::to_value(&r).expect("serializes");
    for k in [
        "objective",
        "value",
        "lower_bound",
        "status",
        "seconds",
        "rounds",
        "length",
        "turns",
        "cycles",
        "valid",
    ] {
        assert!(v.get(k).is_some(), "key {k}");
    }
    assert_eq!(v["status"], "optimal");
    assert_eq!(v["objective"], "turns");
    assert!(v.get("cover").is_none());
}

#[test]
fn objective_names_round_trip() {
    for name in Objective::EXACT_NAMES {
        let cost = name.starts_with("weighted").then_some(50);
        let o = Objective::parse(name, cost).expect("known name");
        assert_eq!(o.name(), name);
        // The results spell the weighted ones with their cost, and read them back.
        assert_eq!(o.to_string().parse::<Objective>(), Ok(o));
    }
    assert_eq!(
        Objective::parse("weighted", Some(5)),
        Ok(Objective::Weighted(5))
    );
    assert_eq!(
        Objective::parse("weighted-cc", Some(50)),
        Ok(Objective::WeightedCc(50))
    );
    assert!(Objective::parse("weighted", None).is_err());
    assert!(Objective::parse("weighted-cc", None).is_err());
    assert!(Objective::parse("length", Some(1)).is_err());
    assert!("bogus".parse::<Objective>().is_err());
}

#[test]
fn time_limit_gives_a_checked_incumbent_and_a_bound() {
    // Too large for a tenth of a second: the answer is an incumbent and a bound, not a claim.
    let r = Region::rectangle(14, 13);
    let res = solve(
        &r,
        Objective::Turns,
        &ExactOptions {
            time_limit: Some(0.1),
            ..mowmill::warm_start::exact_options()
        },
    );
    assert!(
        matches!(res.status, Status::TimeLimit | Status::Optimal),
        "{res:?}"
    );
    if let Some(v) = res.value {
        assert!(res.valid && res.lower_bound <= v);
        let rep = checker::check(&r, res.cover.as_ref().expect("cover"), Mode::Milling);
        assert_eq!(rep.turns, v);
    }
    if res.status == Status::TimeLimit {
        assert!(res.value.is_none_or(|v| v > res.lower_bound));
    }
}

#[test]
fn warm_start_is_used_and_checked() {
    let r = Region::rectangle(4, 4);
    // The boundary ring plus the inner 2x2 is not one walk: a bad warm start is ignored.
    let ring: Vec<Pixel> = [
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 0),
        (3, 1),
        (3, 2),
        (3, 3),
        (2, 3),
        (1, 3),
        (0, 3),
        (0, 2),
        (0, 1),
    ]
    .iter()
    .map(|&p| p.into())
    .collect();
    let bad = CycleCover::tour(ring);
    let res = solve(
        &r,
        Objective::Length,
        &ExactOptions {
            warm_start: Some(bad),
            ..opts()
        },
    );
    assert_eq!(res.value, Some(16));
    // A snake is optimal for length: accepted, and the answer is still 16.
    let snake: Vec<Pixel> = [
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 0),
        (3, 1),
        (2, 1),
        (1, 1),
        (1, 2),
        (2, 2),
        (3, 2),
        (3, 3),
        (2, 3),
        (1, 3),
        (0, 3),
        (0, 2),
        (0, 1),
    ]
    .iter()
    .map(|&p| p.into())
    .collect();
    let res = solve(
        &r,
        Objective::Length,
        &ExactOptions {
            warm_start: Some(CycleCover::tour(snake)),
            ..opts()
        },
    );
    assert_eq!(
        (res.status, res.value, res.rounds),
        (Status::Optimal, Some(16), 0)
    );
}

/// The number of proptest cases: `PROPTEST_CASES` when set (for long soak runs), else `default`.
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Random regions of up to `max_n` pixels in a small box (holes and several components
/// included); `connected` keeps only 4-connected ones.
fn tiny_region(max_n: usize, connected: bool) -> impl Strategy<Value = Region> {
    (2usize..5, 1usize..5).prop_flat_map(move |(w, h)| {
        proptest::collection::vec(proptest::bool::weighted(0.7), w * h).prop_filter_map(
            "size",
            move |bits| {
                let r = Region::from_pixels(
                    bits.iter()
                        .enumerate()
                        .filter(|(_, b)| **b)
                        .map(|(k, _)| Pixel::new((k % w) as i32, (k / w) as i32)),
                )
                .ok()?;
                let ok = !r.is_empty()
                    && r.len() <= max_n
                    && (!connected || mowmill::topology::components(&r).count == 1);
                ok.then_some(r)
            },
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(48), ..ProptestConfig::default() })]

    #[test]
    fn tours_match_brute_force(r in tiny_region(8, true)) {
        prop_assert_eq!(value(&r, Objective::Length), brute_tour(&r, 1, 0).expect("connected"));
        prop_assert_eq!(value(&r, Objective::Turns), brute_tour(&r, 0, 1).expect("connected"));
        prop_assert_eq!(value(&r, Objective::Weighted(2)), brute_tour(&r, 1, 2).expect("connected"));
    }

    #[test]
    fn cycle_covers_and_lawn_match_brute_force(r in tiny_region(8, false)) {
        prop_assert_eq!(value(&r, Objective::CcTurns), brute_cc_turns(&r));
        prop_assert_eq!(value(&r, Objective::LawnTsp), brute_lawn(&r));
    }
}

// ---------------------------------------------------------------------------------------------
// Properties on small random regions (simple and holed)
// ---------------------------------------------------------------------------------------------

fn small_region() -> impl Strategy<Value = Region> {
    (3usize..7, 3usize..6).prop_flat_map(|(w, h)| {
        proptest::collection::vec(proptest::bool::weighted(0.75), w * h).prop_filter_map(
            "connected",
            move |bits| {
                let r = Region::from_pixels(
                    bits.iter()
                        .enumerate()
                        .filter(|(_, b)| **b)
                        .map(|(k, _)| Pixel::new((k % w) as i32, (k / w) as i32)),
                )
                .ok()?;
                (r.len() >= 2 && mowmill::topology::components(&r).count == 1).then_some(r)
            },
        )
    })
}

/// The exact objective an approximation's output is compared with.
fn exact_objective(o: AlgoObjective) -> Objective {
    match o {
        // One objective type: a milling objective is its own exact objective.
        AlgoObjective::LawnLength => Objective::LawnTsp,
        other => other,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(24), ..ProptestConfig::default() })]

    #[test]
    fn optimum_lies_between_bounds_and_every_valid_tour(r in small_region()) {
        let mut opt = HashMap::new();
        for o in [Objective::Length, Objective::CcTurns, Objective::Turns, Objective::LawnTsp] {
            let v = value(&r, o);
            let cheap = mowmill::exact::cheap_lower_bound(&r, o).value;
            prop_assert!(cheap <= v, "{o}: cheap bound {cheap} > optimum {v}");
            if let Some(lp) = mowmill::exact::lp_lower_bound(&r, o, Some(LIMIT)) {
                prop_assert!(lp.value <= v, "{o}: LP bound {} > optimum {v}", lp.value);
            }
            opt.insert(o, v);
        }
        prop_assert!(opt[&Objective::CcTurns] <= opt[&Objective::Turns]);
        prop_assert!(opt[&Objective::LawnTsp] <= opt[&Objective::Length]);
        prop_assert_eq!(value(&r, Objective::Weighted(0)), opt[&Objective::Length]);
        // Every approximation that applies gives a valid cover no better than the optimum.
        for alg in algorithms::REGISTRY {
            if (alg.precondition)(&r).is_err() {
                continue;
            }
            // An algorithm whose preconditions hold must run and return valid outputs: an error
            // or an invalid walk fails the property (never skipped).
            let sol = (alg.run)(&r, &algorithms::Options::default());
            prop_assert!(sol.is_ok(), "{} failed: {:?}", alg.name, sol.err());
            for out in sol.unwrap().outputs {
                let o = exact_objective(out.objective);
                let rep = checker::check(&r, &out.cover, o.mode());
                prop_assert!(rep.valid, "{}: invalid {o} output: {:?}", alg.name, rep.error);
                prop_assert!(
                    !o.is_tour() || rep.cycles == 1,
                    "{}: a {o} output of {} cycles",
                    alg.name,
                    rep.cycles
                );
                let v = o.value_of(&rep);
                // The weighted objectives an algorithm reports itself (lp-lns: C = 50) are
                // solved here when first met.
                let best = *opt.entry(o).or_insert_with(|| value(&r, o));
                prop_assert!(v >= best, "{}: {o} {v} below the optimum {best}", alg.name);
            }
        }
    }

    /// `weighted-cc` against independent facts: a tour is a cycle cover (≤ `weighted`); the
    /// min-turn cycle cover is a cycle cover (≤ its length + C · its turns); every cover has at
    /// least the optimal number of turns, and for C ≥ 1 its length is at least N minus its k
    /// one-pixel walks, with 4k ≤ turns, so the value is at least N − ⌊cc/4⌋ + C · cc.
    #[test]
    fn weighted_cycle_cover_lies_between_independent_bounds(r in small_region(), c in 0u32..60) {
        let wcc = value(&r, Objective::WeightedCc(c));
        let tour = value(&r, Objective::Weighted(c));
        let cc = solved(&r, Objective::CcTurns);
        let (cc_opt, cc_len) = (cc.value.unwrap(), cc.length.unwrap());
        let c64 = u64::from(c);
        prop_assert!(wcc <= tour, "weighted-cc {wcc} > weighted {tour}");
        prop_assert!(wcc <= cc_len + c64 * cc_opt, "weighted-cc {wcc} above the min-turn cover");
        prop_assert!(wcc >= c64 * cc_opt, "weighted-cc {wcc} < C * cc-turns {cc_opt}");
        if c >= 1 {
            let n = r.len() as u64;
            prop_assert!(wcc + cc_opt / 4 >= n + c64 * cc_opt, "weighted-cc {wcc}, N {n}, cc {cc_opt}");
        }
        let cheap = mowmill::exact::cheap_lower_bound(&r, Objective::WeightedCc(c)).value;
        prop_assert!(cheap <= wcc);
    }

    #[test]
    fn symmetries_keep_the_optimum(r in small_region(), s in 1u8..8) {
        let t = r.transformed(Symmetry(s));
        for o in [Objective::Length, Objective::CcTurns, Objective::Turns, Objective::Weighted(1), Objective::WeightedCc(3)] {
            prop_assert_eq!(value(&r, o), value(&t, o), "{}", o);
        }
    }
}
