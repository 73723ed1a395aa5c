//! The structured families: exact pixel and hole formulas, connectivity, the promised
//! properties (Q = 0, even degrees, thinness), determinism, refusals and scaling.

use super::checks::grid_degree;
use super::corridor_star::star_overlap;
use super::{Family, GenParams, Pattern, generate};
use crate::error::Error;
use crate::gridfile::GridFile;
use crate::region::{Pixel, Region};
use crate::topology;

fn p(family: Family, n: usize) -> GenParams {
    GenParams {
        n: Some(n),
        ..GenParams::new(family, 0)
    }
}

fn lattice(n: usize, pattern: Pattern) -> GenParams {
    GenParams {
        pattern: Some(pattern),
        ..p(Family::HoleLattice, n)
    }
}

fn with(mut g: GenParams, k: Option<usize>, width: Option<usize>, seed: u64) -> GenParams {
    g.k = k;
    g.width = width;
    g.seed = seed;
    g
}

/// Generates, checks the file's counts against a recount and connectivity; returns the file.
fn gen_connected(g: &GenParams) -> GridFile {
    let f = generate(g).unwrap_or_else(|e| panic!("{g:?}: {e}"));
    let s = topology::summary(&f.region);
    assert_eq!(s.components, 1, "{g:?} connected");
    assert_eq!(f.meta("n"), Some(s.n.to_string().as_str()));
    assert_eq!(f.meta("holes"), Some(s.holes.to_string().as_str()));
    f
}

/// (N, h) of a generated instance.
fn counts(g: &GenParams) -> (usize, usize) {
    let f = gen_connected(g);
    (f.region.len(), topology::holes(&f.region).count)
}

/// The number of full 2 × 2 blocks (Q of the milling paper).
fn full_blocks(r: &Region) -> usize {
    let has = |x: i32, y: i32| r.index_of(Pixel::new(x, y)).is_some();
    r.pixels()
        .iter()
        .filter(|q| has(q.x + 1, q.y) && has(q.x, q.y + 1) && has(q.x + 1, q.y + 1))
        .count()
}

#[test]
fn hole_lattice_staggered_has_no_full_block_and_the_documented_counts() {
    // Side 2m + 1; a = ⌈m/2⌉, b = ⌊m/2⌋ hole rows of the two kinds.
    for (n, m) in [
        (20usize, 2usize),
        (93, 5),
        (728, 15),
        (1271, 20),
        (3000, 31),
    ] {
        let (a, b) = (m.div_ceil(2), m / 2);
        let f = gen_connected(&lattice(n, Pattern::Staggered));
        let r = &f.region;
        assert_eq!(
            r.len(),
            (m + 1) * (2 * m + 1) + a * m + b * (m + 1),
            "N, n = {n}"
        );
        assert_eq!(topology::holes(r).count, a * (m - 1) + b * m, "h, n = {n}");
        assert_eq!(full_blocks(r), 0, "Q = 0, n = {n}");
        assert_eq!(r.bbox().max_x as usize, 2 * m, "square of side 2m + 1");
        assert!(topology::summary(r).thin);
    }
    // The lead's measured instances: 41 × 41 (N = 1271, h = 390), 31 × 31 (N = 728).
    assert_eq!(counts(&lattice(1271, Pattern::Staggered)), (1271, 390));
    assert_eq!(counts(&lattice(728, Pattern::Staggered)).0, 728);
    // The 11 × 11 staggered lattice (N = 93), row by row from the top.
    let f = gen_connected(&lattice(93, Pattern::Staggered));
    let text = f.to_text().unwrap();
    let rows: Vec<&str> = text.lines().filter(|l| !l.starts_with(';')).collect();
    assert_eq!(rows.len(), 11);
    assert_eq!(
        &rows[..4],
        ["###########", ".#.#.#.#.#.", "###########", "#.#.#.#.#.#"]
    );
}

#[test]
fn hole_lattice_other_patterns_have_their_formulas() {
    for (n, m) in [(30, 2), (500, 12), (2500, 28)] {
        let s = 2 * m + 1;
        assert_eq!(
            counts(&lattice(n, Pattern::Square)),
            (s * s - m * m, m * m),
            "square {n}"
        );
    }
    // diagonal: inner cells with x + 2y ≡ 0 (mod 5), counted here by brute force.
    for (n, m) in [(24, 2), (200, 7), (3000, 30)] {
        let s = 2 * m + 1;
        let h = (1..s - 1)
            .flat_map(|y| (1..s - 1).map(move |x| (x, y)))
            .filter(|(x, y)| (x + 2 * y) % 5 == 0)
            .count();
        assert_eq!(
            counts(&lattice(n, Pattern::Diagonal)),
            (s * s - h, h),
            "diagonal {n}"
        );
    }
    // 15 × 15 diagonal: 34 holes (printed in the docs' example run).
    assert_eq!(counts(&lattice(200, Pattern::Diagonal)), (191, 34));
    // sparse: rows alternate 5 and 4 holes at side 15 (inner x ≡ 1 or 2 mod 3).
    assert_eq!(
        counts(&lattice(200, Pattern::Sparse)),
        (225 - 4 * 5 - 3 * 4, 32)
    );
    for n in [20, 700, 3000] {
        let f = gen_connected(&lattice(n, Pattern::Sparse));
        let cells = topology::holes(&f.region).hole_cells();
        assert!(cells.iter().all(|h| h.len() == 1), "one-pixel holes");
    }
}

#[test]
fn combs_have_their_formulas_and_are_thin_trees() {
    // N = 2k − 1 + kL (comb), 2k − 1 + 2kL (double-comb).
    for (n, k, len) in [(20, 3, 5), (59, 5, 10), (3000, 39, 75)] {
        assert_eq!(
            counts(&p(Family::Comb, n)),
            (2 * k - 1 + k * len, 0),
            "comb {n}"
        );
        let f = gen_connected(&p(Family::Comb, n));
        assert_eq!(f.meta("params"), Some(format!("n={n} k={k}").as_str()));
    }
    assert_eq!(
        counts(&with(p(Family::Comb, 100), Some(4), None, 0)),
        (7 + 4 * 23, 0)
    );
    for (n, k) in [(20, 3), (60, 5), (3000, 39)] {
        let f = gen_connected(&p(Family::DoubleComb, n));
        let len = (f.region.len() - (2 * k - 1)) / (2 * k);
        assert_eq!(f.region.len(), 2 * k - 1 + 2 * k * len, "double-comb {n}");
        assert!(topology::summary(&f.region).thin);
    }
    assert_eq!(counts(&p(Family::DoubleComb, 60)), (59, 0));
}

#[test]
fn spirals_are_paths_with_the_documented_count() {
    for n in [20, 64, 500, 3000] {
        let f = gen_connected(&p(Family::Spiral, n));
        let r = &f.region;
        // Width 1: a Hamiltonian path (two ends, every other pixel of degree 2), no hole.
        let degrees: Vec<usize> = r.pixels().iter().map(|&q| grid_degree(r, q)).collect();
        assert_eq!(degrees.iter().filter(|&&d| d == 1).count(), 2, "{n}");
        assert!(degrees.iter().all(|&d| d == 1 || d == 2), "{n}");
        assert_eq!(topology::holes(r).count, 0);
        assert!(r.len().abs_diff(n) <= n / 5 + 4, "{n}: {}", r.len());
    }
    // Side 10 at width 1: M = 9·3 + 7·2 + 5·2 + 3·2 + 1 = 58 (the last segment is the
    // first shorter than 2), N = 1 + 58.
    assert_eq!(counts(&p(Family::Spiral, 59)), (59, 0));
    // Width 2 in a 10 × 10 square: T = 9, p = 3, segments 8, 8, 8, 5, 5, 2: N = 4 + 2·36.
    assert_eq!(
        counts(&with(p(Family::Spiral, 76), None, Some(2), 0)),
        (76, 0)
    );
    for n in [30, 800, 3000] {
        let (count, holes) = counts(&with(p(Family::Spiral, n), None, Some(2), 0));
        assert_eq!(holes, 0);
        assert!(count.abs_diff(n) <= n / 5 + 8, "{n}: {count}");
    }
}

#[test]
fn windows_and_rings_have_their_formulas() {
    // windows: S = m(k + w) + w, N = S² − m²k², h = m².
    assert_eq!(counts(&p(Family::Windows, 100)), (13 * 13 - 16 * 4, 16));
    assert_eq!(
        counts(&with(p(Family::Windows, 100), None, Some(2), 0)),
        (100 - 16, 4)
    );
    // k = 3, w = 1: S = 4m + 1, N = S² − 9m² = 7m² + 8m + 1, nearest to 3000 at m = 20.
    assert_eq!(
        counts(&with(p(Family::Windows, 3000), Some(3), Some(1), 0)),
        (2961, 400)
    );
    // ring: N = 2w(a + b) − 4w², one hole.
    assert_eq!(counts(&p(Family::Ring, 40)), (40, 1));
    assert_eq!(counts(&p(Family::Ring, 41)), (42, 1));
    assert_eq!(
        counts(&with(p(Family::Ring, 60), None, Some(2), 0)),
        (60, 1)
    );
    assert_eq!(
        counts(&with(p(Family::Ring, 3001), None, Some(2), 0)),
        (3000, 1)
    );
    let f = gen_connected(&p(Family::Ring, 20));
    assert!(
        f.region
            .pixels()
            .iter()
            .all(|&q| grid_degree(&f.region, q) == 2)
    );
}

#[test]
fn outlines_are_thin_eulerian_and_have_the_documented_count() {
    for (n, seed) in [(20, 0), (200, 1), (200, 2), (1000, 3), (3000, 4)] {
        let g = with(p(Family::Outlines, n), None, None, seed);
        let f = gen_connected(&g);
        let r = &f.region;
        assert!(
            r.pixels()
                .iter()
                .all(|&q| grid_degree(r, q).is_multiple_of(2)),
            "even degrees {n} {seed}"
        );
        assert!(
            r.pixels().iter().any(|&q| grid_degree(r, q) == 4),
            "outlines cross {n} {seed}"
        );
        assert!(topology::summary(r).thin, "thin {n} {seed}");
        assert_eq!(full_blocks(r), 0);
        assert!(r.len().abs_diff(n) <= n / 4 + 8, "{n}: {}", r.len());
    }
    // Seed 1, n = 200: K = 2, printed in the docs (N = 190 = 2sD − C).
    assert_eq!(
        counts(&with(p(Family::Outlines, 200), None, None, 1)),
        (190, 3)
    );
    let a = generate(&with(p(Family::Outlines, 1000), Some(6), None, 7)).unwrap();
    let b = generate(&with(p(Family::Outlines, 1000), Some(6), None, 8)).unwrap();
    assert_ne!(
        a.to_text().unwrap(),
        b.to_text().unwrap(),
        "the seed matters"
    );
}

#[test]
fn corridor_star_counts() {
    let table = [
        (1, 1, 0),
        (2, 1, 1),
        (3, 1, 4),
        (4, 1, 7),
        (1, 2, 0),
        (2, 2, 4),
        (3, 2, 14),
        (4, 2, 23),
    ];
    for (k, w, c) in table {
        assert_eq!(star_overlap(k, w), c, "c({k}, {w})");
        for n in [20, 300, 3000] {
            let g = with(p(Family::CorridorStar, n), Some(k), Some(w), 0);
            let f = gen_connected(&g);
            let len = f.region.len();
            let rate = k.min(2) * w + (k - k.min(2)) * (w + 1);
            // N = (2L + w)·rate − c for an integer L.
            assert_eq!((len + c) % rate, 0, "k {k} w {w} n {n}");
            assert_eq!(((len + c) / rate - w) % 2, 0, "k {k} w {w} n {n}");
        }
    }
    assert_eq!(counts(&p(Family::CorridorStar, 60)), (59, 0));
}

#[test]
fn structured_families_are_deterministic_and_scale() {
    let all = [
        lattice(20_000, Pattern::Staggered),
        lattice(20_000, Pattern::Square),
        lattice(20_000, Pattern::Diagonal),
        lattice(20_000, Pattern::Sparse),
        p(Family::Comb, 20_000),
        p(Family::DoubleComb, 20_000),
        p(Family::Spiral, 20_000),
        with(p(Family::Spiral, 20_000), None, Some(2), 0),
        p(Family::Windows, 20_000),
        with(p(Family::Windows, 20_000), Some(1), Some(2), 0),
        with(p(Family::Outlines, 20_000), None, None, 5),
        p(Family::Ring, 20_000),
        with(p(Family::Ring, 20_000), None, Some(2), 0),
        p(Family::CorridorStar, 20_000),
        with(p(Family::CorridorStar, 20_000), Some(3), Some(2), 0),
    ];
    for g in &all {
        let f = gen_connected(g);
        let again = generate(g).unwrap();
        assert_eq!(f.to_text().unwrap(), again.to_text().unwrap(), "{g:?}");
        let n = f.region.len();
        assert!(n.abs_diff(20_000) <= 2_000, "{g:?}: {n}");
    }
}

#[test]
fn structured_refusals_are_clear() {
    let refused = |g: GenParams| match generate(&g) {
        Err(Error::Invalid(m)) => m,
        other => panic!("expected a refusal for {g:?}, got {other:?}"),
    };
    assert!(refused(with(p(Family::Ring, 100), None, Some(3), 0)).contains("width 1 or 2"));
    assert!(refused(with(p(Family::Spiral, 100), None, Some(3), 0)).contains("width 1 or 2"));
    assert!(refused(with(p(Family::CorridorStar, 100), Some(5), None, 0)).contains("k = 1 to 4"));
    assert!(refused(with(p(Family::Comb, 10), Some(5), None, 0)).contains("needs n ≥ 14"));
    assert!(refused(with(p(Family::Outlines, 20), Some(3), None, 0)).contains("needs n ≥ 24"));
    assert!(
        refused(GenParams {
            holes: Some(2),
            ..p(Family::HoleLattice, 100)
        })
        .contains("does not apply")
    );
}
