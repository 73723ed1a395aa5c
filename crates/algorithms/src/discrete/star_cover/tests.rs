//! Tests of the star cover: hand-made instances, random ones through the whole pipeline
//! (cover, merge, checker, bounds), and helpers that the hill climb reuses.

use super::*;
use crate::discrete::check::check;
use crate::discrete::merge::{merge, proven_bound, theorem_4_2_bound};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeSet;

/// A random connected instance: a random tree plus extra edges, and at every vertex a
/// random matching of its edges into collinear pairs.
pub(crate) fn random_instance(rng: &mut ChaCha8Rng, n: usize, extra: usize) -> Discrete {
    let mut edges: BTreeSet<(u32, u32)> = BTreeSet::new();
    for v in 1..n as u32 {
        let u = rng.random_range(0..v);
        edges.insert((u, v));
    }
    for _ in 0..extra {
        let (a, b) = (rng.random_range(0..n as u32), rng.random_range(0..n as u32));
        if a != b {
            edges.insert((a.min(b), a.max(b)));
        }
    }
    let edges: Vec<(u32, u32)> = edges.into_iter().collect();
    let mut nbrs: Vec<Vec<u32>> = vec![Vec::new(); n];
    for &(a, b) in &edges {
        nbrs[a as usize].push(b);
        nbrs[b as usize].push(a);
    }
    let mut collinear = Vec::new();
    for (v, list) in nbrs.iter_mut().enumerate() {
        for i in (1..list.len()).rev() {
            let j = rng.random_range(0..=i);
            list.swap(i, j);
        }
        for pair in list.chunks(2) {
            if pair.len() == 2 && rng.random_bool(0.7) {
                collinear.push((v as u32, pair[0], pair[1]));
            }
        }
    }
    Discrete::new(n, &edges, &collinear, None).unwrap()
}

/// The vertices of a random subset of a box, 6-neighbour edges, axis pairs collinear
/// (d = 3); `None` if not connected.
pub(crate) fn random_voxels(rng: &mut ChaCha8Rng, dims: [i32; 3], p: f64) -> Option<Discrete> {
    lattice(rng, dims, p, &[[1, 0, 0], [0, 1, 0], [0, 0, 1]])
}

/// Hexagonal cells in axial coordinates (d = 3: three axes); `None` if not connected.
pub(crate) fn random_hex(rng: &mut ChaCha8Rng, w: i32, h: i32, p: f64) -> Option<Discrete> {
    lattice(rng, [w, h, 1], p, &[[1, 0, 0], [0, 1, 0], [1, -1, 0]])
}

fn lattice(rng: &mut ChaCha8Rng, dims: [i32; 3], p: f64, axes: &[[i32; 3]]) -> Option<Discrete> {
    let mut cells: Vec<[i32; 3]> = Vec::new();
    for x in 0..dims[0] {
        for y in 0..dims[1] {
            for z in 0..dims[2] {
                if rng.random_bool(p) {
                    cells.push([x, y, z]);
                }
            }
        }
    }
    let index = |c: [i32; 3]| cells.binary_search(&c).ok().map(|i| i as u32);
    let add =
        |a: [i32; 3], b: [i32; 3], s: i32| [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
    let (mut edges, mut collinear) = (Vec::new(), Vec::new());
    for (i, &c) in cells.iter().enumerate() {
        for &ax in axes {
            let (fwd, back) = (index(add(c, ax, 1)), index(add(c, ax, -1)));
            if let Some(j) = fwd {
                edges.push((i as u32, j));
            }
            if let (Some(a), Some(b)) = (fwd, back) {
                collinear.push((i as u32, a, b));
            }
        }
    }
    let coords = cells
        .iter()
        .map(|c| [c[0] as f64, c[1] as f64, c[2] as f64])
        .collect();
    let mut inst = Discrete::new(cells.len(), &edges, &collinear, Some(coords)).ok()?;
    inst.set_directions(Some(axes.len() as u32));
    (!inst.is_empty() && inst.components() == 1).then_some(inst)
}

/// Independently of [`channels`]: the vertices one straight link away from `r`, and
/// whether `r` lies on a straight closed walk, by following `straight_on`.
fn attack_set(inst: &Discrete, r: u32) -> (BTreeSet<u32>, bool) {
    let mut out = BTreeSet::from([r]);
    let mut on_ring = false;
    for &a in inst.neighbors(r) {
        let (mut u, mut v) = (r, a);
        let mut steps = 0;
        loop {
            out.insert(v);
            steps += 1;
            let Some(w) = inst.straight_on(u, v) else {
                break;
            };
            if (v, w) == (r, a) {
                on_ring = true;
                break;
            }
            (u, v) = (v, w);
            assert!(
                steps <= 2 * inst.edge_count() + 2,
                "a straight walk runs forever"
            );
        }
    }
    (out, on_ring)
}

/// What one instance gave, for the figures.
#[derive(Default, Debug)]
pub(crate) struct Figures {
    pub instances: usize,
    pub worst_cc_vs_paper: f64,
    pub worst_tour_vs_paper: f64,
    pub paper_cc_violations: usize,
    pub paper_tour_violations: usize,
    pub theorem_4_2_violations: usize,
    pub worst_cc_per_rook: f64,
    pub worst_tour_per_rook: f64,
    pub worst_coverage_ratio: f64,
}

/// Runs the star cover and the merge on `inst` (connected) and asserts every proven
/// property; returns (cc turns, tour turns, rooks).
pub(crate) fn assert_pipeline(inst: &Discrete, fig: &mut Figures) -> (u64, u64, usize) {
    let sc = star_cover(inst);
    let params = inst.params();
    let rep = check(inst, &sc.cycles);
    assert!(rep.valid, "{:?}", rep.error);
    assert_eq!(sc.cycles.len(), sc.rooks.len() + sc.rings);
    // Rooks: a rook placement off closed channels, attacking every vertex not on one.
    let mut attacked = vec![false; inst.len()];
    for &r in &sc.rooks {
        let (set, ring) = attack_set(inst, r);
        assert!(!ring, "rook {r} lies on a closed channel");
        for &s in &sc.rooks {
            assert!(
                s == r || !set.contains(&s),
                "rooks {r} and {s} attack each other"
            );
        }
        for v in set {
            attacked[v as usize] = true;
        }
    }
    for v in 0..inst.len() as u32 {
        assert!(
            attacked[v as usize] || attack_set(inst, v).1,
            "{v} neither attacked nor on a ring"
        );
    }
    // Per star, per vertex, in all.
    for (k, &r) in sc.rooks.iter().enumerate() {
        let one = check_one(inst, &sc.cycles[k]);
        assert!(
            one <= beta(inst, r),
            "star of {r}: {one} > beta {}",
            beta(inst, r)
        );
    }
    for w in &sc.cycles[sc.rooks.len()..] {
        assert_eq!(check_one(inst, w), 0, "a ring cycle turns");
    }
    assert!(rep.turns <= star_turn_bound(inst, &sc.rooks));
    assert!(
        rep.turns >= sc.rooks.len() as u64,
        "fewer turns than rooks: Lemma 4.3 broken"
    );
    for v in 0..inst.len() {
        assert!(rep.coverage[v] <= (inst.degree(v as u32) as u32).max(1));
    }
    assert!(rep.max_coverage <= coverage_bound(params));
    assert!(rep.length <= length_bound(inst));
    // The merge.
    let (tour, stats) = merge(inst, &sc.cycles);
    let trep = check(inst, &tour);
    assert!(trep.valid, "{:?}", trep.error);
    assert_eq!(tour.len(), 1, "a connected instance merges into one tour");
    assert_eq!(trep.turns as i64, rep.turns as i64 + stats.added_turns);
    assert_eq!(stats.merges, sc.cycles.len() - 1);
    assert!(trep.turns <= proven_bound(rep.turns, sc.cycles.len()));
    assert!(trep.turns >= sc.rooks.len() as u64);
    for v in 0..inst.len() {
        assert!(
            trep.coverage[v] <= (inst.degree(v as u32) as u32).max(1),
            "coverage of {v}"
        );
    }
    assert!(trep.length <= length_bound(inst));
    // Figures against the paper's forms.
    fig.instances += 1;
    let r = sc.rooks.len();
    if r > 0 && inst.edge_count() > 0 {
        let (p_cc, p_tour) = (theorem_5_1_bound(params, r), corollary_5_1_bound(params, r));
        fig.worst_cc_vs_paper = fig.worst_cc_vs_paper.max(rep.turns as f64 / p_cc);
        fig.worst_tour_vs_paper = fig.worst_tour_vs_paper.max(trep.turns as f64 / p_tour);
        fig.paper_cc_violations += usize::from(rep.turns as f64 > p_cc + 1e-9);
        fig.paper_tour_violations += usize::from(trep.turns as f64 > p_tour + 1e-9);
        fig.worst_cc_per_rook = fig.worst_cc_per_rook.max(rep.turns as f64 / r as f64);
        fig.worst_tour_per_rook = fig.worst_tour_per_rook.max(trep.turns as f64 / r as f64);
    }
    fig.worst_coverage_ratio = fig
        .worst_coverage_ratio
        .max(trep.max_coverage as f64 / params.mu.max(1) as f64);
    fig.theorem_4_2_violations +=
        usize::from(trep.turns > theorem_4_2_bound(rep.turns, sc.cycles.len()));
    (rep.turns, trep.turns, r)
}

fn check_one(inst: &Discrete, walk: &VertexWalk) -> u64 {
    // A walk alone does not cover the instance; count its turns the checker's way.
    let m = walk.len();
    if m == 1 {
        return 4;
    }
    (0..m)
        .map(|i| u64::from(inst.turn(walk[(i + m - 1) % m], walk[i], walk[(i + 1) % m])))
        .sum()
}

#[test]
fn random_discrete_instances_keep_the_proven_bounds() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut fig = Figures::default();
    let mut with_rings = 0;
    for _ in 0..1500 {
        let n = rng.random_range(1..14);
        let extra = rng.random_range(0..2 * n);
        let inst = random_instance(&mut rng, n, extra);
        with_rings += usize::from(star_cover(&inst).rings > 0);
        assert_pipeline(&inst, &mut fig);
    }
    eprintln!("random discrete: {fig:?}, {with_rings} with ring cycles");
    assert!(with_rings > 20, "rings must be exercised");
}

#[test]
fn lattice_instances_keep_theorem_5_2() {
    let mut rng = ChaCha8Rng::seed_from_u64(52);
    for (name, d) in [("voxels", 3u32), ("hex", 3)] {
        let mut fig = Figures::default();
        let mut tour_5d2_violations = 0;
        let mut tested = 0;
        while tested < 300 {
            let inst = if name == "voxels" {
                let dims = [
                    rng.random_range(1..5),
                    rng.random_range(1..5),
                    rng.random_range(1..4),
                ];
                random_voxels(&mut rng, dims, 0.75)
            } else {
                {
                    let (w, h) = (rng.random_range(1..7), rng.random_range(1..7));
                    random_hex(&mut rng, w, h, 0.75)
                }
            };
            let Some(inst) = inst else { continue };
            tested += 1;
            assert_eq!(inst.directions(), Some(d));
            for v in 0..inst.len() as u32 {
                assert!(inst.directions_at(v) <= d as usize && inst.degree(v) <= 2 * d as usize);
            }
            let (cc, tour, r) = assert_pipeline(&inst, &mut fig);
            assert_eq!(
                star_cover(&inst).rings,
                0,
                "a finite lattice has no closed channel"
            );
            assert!(cc <= theorem_5_2_cc_bound(d, r), "{name}: {cc} > 5d * {r}");
            assert!(tour <= theorem_5_2_tour_bound(d, r) + 2 * r as u64);
            tour_5d2_violations += usize::from(tour > theorem_5_2_tour_bound(d, r));
            let rep = check(&inst, &star_cover(&inst).cycles);
            assert!(rep.max_coverage <= 2 * d && rep.length <= 2 * d as u64 * inst.len() as u64);
        }
        eprintln!("{name}: {fig:?}, tour > (5d+2) rooks on {tour_5d2_violations}");
        assert_eq!(tour_5d2_violations, 0, "{name}: Theorem 5.2's tour bound");
    }
}

/// Grid regions: the discrete star cover is the grid star cover (same rooks, same turns,
/// same visits per pixel, Corollary 5.2); the tours come from different merges and are only
/// held to 12 per rook.
#[test]
fn grid_regions_agree_with_the_grid_star_cover() {
    use crate::checker::{Mode, check as check_grid};
    use crate::star_cover::{greedy_rooks, star_cycle_cover};
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let mut fig = Figures::default();
    let (mut ours_better, mut grid_better, mut equal) = (0, 0, 0);
    let mut tested = 0;
    while tested < 400 {
        let (w, h) = (rng.random_range(1..8), rng.random_range(1..8));
        let mut pixels = Vec::new();
        for x in 0..w {
            for y in 0..h {
                if rng.random_bool(0.75) {
                    pixels.push(crate::Pixel::new(x, y));
                }
            }
        }
        let Ok(region) = crate::Region::from_pixels(pixels) else {
            continue;
        };
        if region.is_empty() {
            continue;
        }
        let inst = Discrete::from_region(&region);
        if inst.components() != 1 {
            continue;
        }
        tested += 1;
        let (cc, tour, r) = assert_pipeline(&inst, &mut fig);
        let sc = star_cover(&inst);
        let grid_rooks: Vec<u32> = greedy_rooks(&region, &GreedyOrder::Index)
            .iter()
            .map(|&i| i as u32)
            .collect();
        assert_eq!(sc.rooks, grid_rooks);
        let (grid_cc, grid_r) = star_cycle_cover(&region, &GreedyOrder::Index);
        assert_eq!(grid_r, r);
        let a = check_grid(&region, &grid_cc, Mode::Milling);
        let b = check(&inst, &sc.cycles);
        assert_eq!(
            (a.turns, a.length, &a.coverage),
            (cc, b.length, &b.coverage)
        );
        let (grid_tour, _) = crate::merge::merge_cycles(&region, &grid_cc, crate::Merge::Smart);
        let gt = check_grid(&region, &grid_tour, Mode::Milling).turns;
        assert!(cc <= 10 * r as u64 && tour <= 12 * r as u64 && gt <= 12 * r as u64);
        match tour.cmp(&gt) {
            std::cmp::Ordering::Less => ours_better += 1,
            std::cmp::Ordering::Greater => grid_better += 1,
            std::cmp::Ordering::Equal => equal += 1,
        }
    }
    eprintln!(
        "grid: {fig:?}; tours: discrete merge better {ours_better}, grid merge better {grid_better}, equal {equal}"
    );
    assert_eq!(
        fig.theorem_4_2_violations, 0,
        "grid merges stay within +2 each"
    );
}

#[test]
fn paper_bound_with_averages_fails_for_a_hub_first() {
    // Hub 0 joined by unmatched edges to the p inner vertices of a straight path.
    let p = 30u32;
    let build = |hub: u32, path: &dyn Fn(u32) -> u32| {
        let mut edges = Vec::new();
        let mut collinear = Vec::new();
        for i in 0..=p {
            edges.push((path(i), path(i + 1)));
        }
        for i in 1..=p {
            edges.push((hub, path(i)));
            collinear.push((path(i), path(i - 1), path(i + 1)));
        }
        Discrete::new(p as usize + 3, &edges, &collinear, None).unwrap()
    };
    let hub_first = build(0, &|i| i + 1);
    let sc = star_cover(&hub_first);
    assert_eq!(sc.rooks, vec![0, 1]);
    let hub_turns = check(&hub_first, &sc.cycles).turns;
    assert_eq!(hub_turns, 3 * p as u64 + 4);
    // Path vertex x_1 first (index 0), the hub last: two stars, 8 turns; so OPT <= 8.
    let relabel = |i: u32| {
        if i == 1 {
            0
        } else if i == 0 {
            1
        } else {
            i
        }
    };
    let other = build(p + 2, &|i| relabel(i));
    let osc = star_cover(&other);
    let other_turns = check(&other, &osc.cycles).turns;
    assert_eq!((osc.rooks.len(), other_turns), (1, 8));
    let params = hub_first.params();
    assert!(params.rho + 2.0 * params.delta < 11.0);
    // Theorem 5.1 as stated: turns <= (rho + 2 delta) OPT <= (rho + 2 delta) 8. Violated.
    assert!(hub_turns as f64 > theorem_5_1_bound(params, other_turns as usize));
    // Our bound holds: sum of beta over the rooks.
    assert!(hub_turns <= star_turn_bound(&hub_first, &sc.rooks));
}

#[test]
fn rings_are_free_cycles_and_carry_no_rook() {
    // Two straight triangles crossing at vertex 0 (two pairs there): OPT_cc = 0.
    let edges = [(0, 1), (1, 2), (0, 2), (0, 3), (3, 4), (0, 4)];
    let collinear = [
        (0, 1, 2),
        (1, 0, 2),
        (2, 1, 0),
        (0, 3, 4),
        (3, 0, 4),
        (4, 3, 0),
    ];
    let inst = Discrete::new(5, &edges, &collinear, None).unwrap();
    let sc = star_cover(&inst);
    assert!(sc.rooks.is_empty());
    assert_eq!(sc.rings, 2);
    let rep = check(&inst, &sc.cycles);
    assert!(rep.valid);
    assert_eq!(rep.turns, 0);
    let (tour, stats) = merge(&inst, &sc.cycles);
    let t = check(&inst, &tour);
    assert!(t.valid && tour.len() == 1);
    // One merge at vertex 0 (a splice, or the equal exchange 0-3 / 1-0): +2.
    assert_eq!((t.turns, stats.merges, stats.added_turns), (2, 1, 2));
}

#[test]
fn full_plus_star_has_ten_turns_and_a_leaf_rook_four() {
    let r = crate::Region::from_ascii(".#.\n###\n.#.\n");
    let inst = Discrete::from_region(&r);
    let ch = channels(&inst);
    let centre = r.index_of(crate::Pixel::new(1, 1)).unwrap() as u32;
    let rep = check(&inst, &[star_walk(&inst, &ch, centre)]);
    assert_eq!((rep.turns, rep.max_coverage), (10, 4));
    // A path 0-1-2 with 1 straight: the leaf rook 0 doubles it, 4 turns (beta = 3 + 1).
    let path = Discrete::new(3, &[(0, 1), (1, 2)], &[(1, 0, 2)], None).unwrap();
    let sc = star_cover(&path);
    assert_eq!(sc.rooks, vec![0]);
    assert_eq!(check(&path, &sc.cycles).turns, 4);
    assert_eq!(beta(&path, 0), 4);
}
