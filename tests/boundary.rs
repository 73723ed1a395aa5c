//! The ray-graph matching of boundary link ends (`endpoint_matching`, one heading per end)
//! against blossom on the complete graph, on thin pockets and on regions of boundary pixels
//! only, and `boundary-cc` beyond the complete graph's limit.

use mowmill::algorithms::boundary_cc::{boundary_cycle_cover, boundary_links, boundary_ports};
use mowmill::algorithms::endpoint_matching::{Candidates, PortMatching, match_ports_with};
use mowmill::algorithms::turn_distance::{Port, turn_distance};
use mowmill::checker::{Mode, check};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::Region;
use mowmill::topology::is_boundary;

fn region(family: Family, n: usize, seed: u64) -> Region {
    let mut p = GenParams::new(family, seed);
    p.n = Some(n);
    generate(&p)
        .expect("the generator accepts these parameters")
        .region
}

/// A region of boundary pixels only: a random region less the pixels with x + 2y ≡ k
/// (mod 5), a perfect code of the grid (every other pixel has exactly one of them as a
/// neighbour), its largest component kept.
fn boundary_only(family: Family, n: usize, seed: u64) -> Region {
    let r = region(family, n, seed);
    let k = (seed % 5) as i32;
    let kept = r
        .pixels()
        .iter()
        .copied()
        .filter(|p| (p.x + 2 * p.y - k).rem_euclid(5) != 0);
    largest_component(&Region::from_pixels(kept).expect("pixels of a region"))
}

fn largest_component(r: &Region) -> Region {
    let mut comp = vec![usize::MAX; r.len()];
    let mut best = (0, 0);
    for s in 0..r.len() {
        if comp[s] != usize::MAX {
            continue;
        }
        let (mut stack, mut size) = (vec![s], 0);
        comp[s] = s;
        while let Some(i) = stack.pop() {
            size += 1;
            for j in r.neighbors(i) {
                if comp[j] == usize::MAX {
                    comp[j] = s;
                    stack.push(j);
                }
            }
        }
        best = best.max((size, s));
    }
    Region::from_pixels(
        (0..r.len())
            .filter(|&i| comp[i] == best.1)
            .map(|i| r.pixel(i)),
    )
    .expect("pixels of a region")
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

/// Ray graph against complete graph on `r`'s boundary link ends; returns (ends, one-pixel
/// links).
fn compare(r: &Region, name: &str) -> (usize, usize) {
    let links = boundary_links(r);
    let (ports, partner, floor) = boundary_ports(&links);
    let full = match_ports_with(r, &ports, &partner, &floor, Candidates::Complete)
        .expect("complete matching");
    let ray = match_ports_with(r, &ports, &partner, &floor, Candidates::RunGraph)
        .expect("ray-graph matching");
    check_matching(r, &ports, &floor, &ray);
    eprintln!(
        "{name}: {} pixels, {} ends, complete {}, ray graph {} (bound {})",
        r.len(),
        ports.len(),
        full.total,
        ray.total,
        ray.lower_bound
    );
    assert_eq!(ray.total, full.total, "{name}");
    assert!(ray.optimal && ray.complete, "{name}");
    assert_eq!(ray.lower_bound, ray.total, "{name}");
    (ports.len(), floor.iter().filter(|&&f| f > 0).count() / 2)
}

/// The ray-graph matching (every pair, fusion-blossom) is exactly the complete-graph minimum,
/// proven by its own bound, on thin pockets and boundary-only regions of 600–1000 link ends.
#[test]
fn ray_graph_matching_equals_the_complete_minimum() {
    let mut one_pixel_links = 0;
    for (n, seed) in [(900, 2), (1150, 3)] {
        let (ends, ones) = compare(
            &region(Family::Thin, n, seed),
            &format!("thin {n} seed {seed}"),
        );
        assert!((600..=1100).contains(&ends), "{ends} ends");
        one_pixel_links += ones;
    }
    for (family, n, seed) in [
        (Family::RandomSimple, 950, 1),
        (Family::RandomHoled, 1300, 3),
    ] {
        let r = boundary_only(family, n, seed);
        assert!((0..r.len()).all(|i| is_boundary(&r, i)));
        let (ends, ones) = compare(&r, &format!("boundary-only {family:?} {n} seed {seed}"));
        assert!((600..=1100).contains(&ends), "{ends} ends");
        one_pixel_links += ones;
    }
    // The boundary of a region with inner pixels: long rays crossing many runs.
    let r = region(Family::RandomSimple, 1700, 4);
    let (ends, ones) = compare(&r, "boundary of RandomSimple 1700 seed 4");
    assert!((600..=1100).contains(&ends), "{ends} ends");
    one_pixel_links += ones;
    assert!(
        one_pixel_links > 0,
        "the instances exercise one-pixel links"
    );
}

/// Hand-made: one-pixel links alone, several crossing one run (their ends need the clone and
/// the direct edges of the ray graph), and crossing each other; the ray graph agrees with the
/// complete graph.
#[test]
fn ray_graph_matching_handles_one_pixel_links() {
    for text in [
        "#.#.#\n#####\n",
        "#.#.#.#\n#######\n#.#.#.#\n",
        "##.##\n#...#\n##.##\n#...#\n##.##\n",
        ".#.#.\n#####\n.#.#.\n#####\n.#.#.\n",
        "#.#.#.#\n#######\n.#...#.\n#######\n#.#.#.#\n",
    ] {
        let r = Region::from_ascii(text);
        let links = boundary_links(&r);
        let (ports, partner, floor) = boundary_ports(&links);
        assert!(floor.contains(&4), "{text} has a one-pixel link");
        let full = match_ports_with(&r, &ports, &partner, &floor, Candidates::Complete).unwrap();
        let ray = match_ports_with(&r, &ports, &partner, &floor, Candidates::RunGraph).unwrap();
        check_matching(&r, &ports, &floor, &ray);
        assert_eq!(ray.total, full.total, "{text}");
        assert!(ray.optimal, "{text}");
    }
}

/// `boundary-cc` beyond the complete graph's limit: a thin pocket and a boundary-only region
/// of a few thousand ends get a valid cover whose matching is proven minimum.
#[test]
fn boundary_cover_is_proven_beyond_the_complete_limit() {
    for (name, r) in [
        ("thin 4000", region(Family::Thin, 4000, 1)),
        (
            "boundary-only 5000",
            boundary_only(Family::RandomSimple, 5000, 2),
        ),
    ] {
        let (cover, m) = boundary_cycle_cover(&r).expect("proven minimum");
        assert!(m.mate.len() > 2000, "{name}: {} ends", m.mate.len());
        assert!(
            m.optimal && m.complete && m.lower_bound == m.total,
            "{name}"
        );
        let rep = check(&r, &cover, Mode::Milling);
        assert!(rep.valid, "{name}: {:?}", rep.error);
        assert!(rep.turns >= m.total, "{name}");
    }
}
