//! The priced LP matching of strip ends (`endpoint_matching`, `Candidates::Priced`) against
//! blossom on the complete graph: its lower bound is a true lower bound, its matching is a
//! perfect matching of the weight it reports, and it claims optimality only when it has it.

use mowmill::algorithms::endpoint_matching::{Candidates, PortMatching, match_ports_with};
use mowmill::algorithms::strips_matching::strip_ports;
use mowmill::algorithms::turn_distance::{Port, turn_distance};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::Region;
use mowmill::strip_cover::strip_cover;

fn region(family: Family, n: usize, seed: u64) -> Region {
    let mut p = GenParams::new(family, seed);
    p.n = Some(n);
    generate(&p)
        .expect("the generator accepts these parameters")
        .region
}

/// The strip ends of a minimum strip cover, with partners and floors as `strips-matching`
/// builds them.
fn strip_ends(r: &Region) -> (Vec<Port>, Vec<usize>, Vec<u32>) {
    let cover = strip_cover(r);
    let (links, ports) = strip_ports(r, &cover.strips);
    let partner: Vec<usize> = (0..ports.len()).map(|i| i ^ 1).collect();
    let floor = (0..ports.len())
        .map(|i| {
            if links[i / 2].0 == links[i / 2].1 {
                2
            } else {
                0
            }
        })
        .collect();
    (ports, partner, floor)
}

/// `m` is a perfect matching whose weights are the turn distances (floors for partners).
fn check_matching(r: &Region, ports: &[Port], floor: &[u32], m: &PortMatching) {
    let mut total = 0u64;
    for i in 0..ports.len() {
        let j = m.mate[i];
        assert_eq!(m.mate[j], i, "mate is an involution");
        assert_ne!(i, j);
        if i < j {
            let mut d = turn_distance(r, ports[i], ports[j]).expect("reachable");
            if j == (i ^ 1) {
                d = d.max(floor[i]);
            }
            assert_eq!(m.weight[i], d, "pair ({i}, {j})");
            total += u64::from(d);
        }
    }
    assert_eq!(total, m.total);
}

/// On random regions of a few hundred endpoints: lower bound ≤ the complete-graph minimum ≤
/// the priced matching, and a matching certified optimal has exactly the minimum weight.
#[test]
#[ignore = "slow tier (tens of seconds): .ci/run and scripts/validate.sh run it with --ignored"]
fn priced_matching_is_bounded_by_the_complete_minimum() {
    let mut certified = 0;
    let mut runs = 0;
    for (family, n, seed) in [
        (Family::RandomSimple, 1800, 2),
        (Family::RandomHoled, 1500, 2),
        (Family::RandomHoled, 1500, 1),
        (Family::Thin, 1500, 1),
    ] {
        {
            let r = region(family, n, seed);
            let (ports, partner, floor) = strip_ends(&r);
            let full = match_ports_with(&r, &ports, &partner, &floor, Candidates::Complete)
                .expect("complete matching");
            let priced = match_ports_with(&r, &ports, &partner, &floor, Candidates::Priced)
                .expect("priced matching");
            check_matching(&r, &ports, &floor, &priced);
            assert!(full.complete && full.optimal && !priced.complete);
            assert!(
                priced.lower_bound <= full.total && full.total <= priced.total,
                "{family:?} seed {seed}: bound {} min {} priced {}",
                priced.lower_bound,
                full.total,
                priced.total
            );
            if priced.optimal {
                assert_eq!(priced.total, full.total);
                certified += 1;
            }
            runs += 1;
            eprintln!(
                "{family:?} seed {seed}: {} ends, min {}, priced {} (bound {}, optimal {}, {} candidates)",
                ports.len(),
                full.total,
                priced.total,
                priced.lower_bound,
                priced.optimal,
                priced.candidates
            );
        }
    }
    eprintln!("certified optimal: {certified} of {runs}");
}

/// A thin region of ≈ 2000 strip ends: the priced matching is a valid perfect matching, its
/// bound is below it, and optimality is claimed only at the bound.
#[test]
fn priced_matching_certificate_is_consistent() {
    let r = region(Family::RandomSimple, 6500, 4);
    let (ports, partner, floor) = strip_ends(&r);
    assert!(ports.len() > 1500, "{} ends", ports.len());
    let m = match_ports_with(&r, &ports, &partner, &floor, Candidates::Priced).unwrap();
    check_matching(&r, &ports, &floor, &m);
    assert!(m.lower_bound <= m.total);
    assert_eq!(m.optimal, m.lower_bound == m.total);
    // The LP bound is far above the trivial one (every pair at least 0 turns).
    assert!(
        m.lower_bound * 10 >= m.total * 9,
        "{} vs {}",
        m.lower_bound,
        m.total
    );
}

/// The run-graph matching (every pair, fusion-blossom) is exactly the complete-graph minimum,
/// proven by its own bound, on random regions of 600–1100 strip ends, one-pixel
/// strips included (their floors are where the run graph needs care).
#[test]
fn run_graph_matching_equals_the_complete_minimum() {
    let mut one_pixel_strips = 0;
    for (family, n, seed) in [
        (Family::RandomSimple, 1800, 2),
        (Family::RandomHoled, 1500, 1),
        (Family::RandomHoled, 2500, 5),
        (Family::Thin, 1500, 1),
        (Family::Thin, 2500, 3),
    ] {
        let r = region(family, n, seed);
        let (ports, partner, floor) = strip_ends(&r);
        one_pixel_strips += floor.iter().filter(|&&f| f > 0).count() / 2;
        let full = match_ports_with(&r, &ports, &partner, &floor, Candidates::Complete)
            .expect("complete matching");
        let run = match_ports_with(&r, &ports, &partner, &floor, Candidates::RunGraph)
            .expect("run-graph matching");
        check_matching(&r, &ports, &floor, &run);
        eprintln!(
            "{family:?} n {n} seed {seed}: {} ends, complete {}, run graph {} (bound {})",
            ports.len(),
            full.total,
            run.total,
            run.lower_bound
        );
        assert_eq!(run.total, full.total, "{family:?} seed {seed}");
        assert!(run.optimal && run.complete, "{family:?} seed {seed}");
        assert_eq!(run.lower_bound, run.total);
    }
    assert!(
        one_pixel_strips > 0,
        "the instances exercise one-pixel strips"
    );
}

/// Hand-made: one-pixel strips alone on their run, on a run with other ends, and two on
/// crossing runs; the run graph agrees with the complete graph.
#[test]
fn run_graph_matching_handles_one_pixel_strips() {
    for text in [
        "#.#.#\n#####\n#.#.#\n",
        ".#.\n###\n.#.\n",
        "#...#\n#####\n..#..\n#####\n#...#\n",
        "#.#.#.#\n#######\n.#.#.#.\n#######\n#.#.#.#\n",
    ] {
        let r = Region::from_ascii(text);
        let (ports, partner, floor) = strip_ends(&r);
        let full = match_ports_with(&r, &ports, &partner, &floor, Candidates::Complete).unwrap();
        let run = match_ports_with(&r, &ports, &partner, &floor, Candidates::RunGraph).unwrap();
        check_matching(&r, &ports, &floor, &run);
        assert_eq!(run.total, full.total, "{text}");
        assert!(run.optimal, "{text}");
    }
}

/// The run-graph matching (odd runs only, see `run_graph_matching`) against blossom on the
/// complete graph, on many small regions of every family with strip ends and every style,
/// holes touching strips and one-pixel strips included: equal weights, certified optimal,
/// bound equal to the weight. Nothing is skipped. `MOWMILL_SOAK=K` runs K regions instead of
/// 240 (measured: 3,000 regions, see docs/measured.md).
#[test]
fn run_graph_matching_equals_the_complete_minimum_on_many_small_regions() {
    use mowmill::generate::Style;
    let count: u64 = std::env::var("MOWMILL_SOAK")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(240);
    let families = [
        Family::RandomSimple,
        Family::RandomHoled,
        Family::Thin,
        Family::Boundary,
        Family::Pinholes,
        Family::ThinArms,
    ];
    let (mut ends, mut one_pixel) = (0usize, 0usize);
    for k in 0..count {
        let family = families[(k % families.len() as u64) as usize];
        let mut p = GenParams::new(family, k);
        p.n = Some(12 + (k as usize * 37) % 260);
        if matches!(
            family,
            Family::RandomSimple | Family::RandomHoled | Family::Boundary | Family::Pinholes
        ) {
            p.style = Some(Style::ALL[(k / 6) as usize % Style::ALL.len()]);
        }
        if matches!(family, Family::RandomHoled | Family::Pinholes) {
            let holes = 1 + (k / 30) as usize % 4;
            p.holes = Some(holes);
            p.n = p.n.map(|n| n.max(8 * holes));
        }
        if family == Family::RandomSimple || family == Family::RandomHoled {
            p.no_cut = k % 4 == 0;
        }
        let r = match generate(&p) {
            Ok(g) => g.region,
            Err(e) => panic!("{family:?} seed {k}: the generator refused {p:?}: {e}"),
        };
        let (ports, partner, floor) = strip_ends(&r);
        if ports.is_empty() {
            continue;
        }
        ends += ports.len();
        one_pixel += floor.iter().filter(|&&f| f > 0).count() / 2;
        let full = match_ports_with(&r, &ports, &partner, &floor, Candidates::Complete)
            .expect("complete matching");
        let run = match_ports_with(&r, &ports, &partner, &floor, Candidates::RunGraph)
            .unwrap_or_else(|e| panic!("{family:?} seed {k}: run graph failed: {e}"));
        check_matching(&r, &ports, &floor, &run);
        assert_eq!(run.total, full.total, "{family:?} seed {k} {p:?}");
        assert!(run.optimal && run.complete, "{family:?} seed {k}");
        assert_eq!(run.lower_bound, run.total, "{family:?} seed {k}");
    }
    eprintln!("{count} regions, {ends} strip ends, {one_pixel} one-pixel strips");
    assert!(
        one_pixel > count as usize / 10,
        "one-pixel strips are exercised"
    );
}
