//! Speed of the min-turn algorithms of *Optimal covering tours with turn costs*,
//! single thread: the strip cover and `star-cover` on 10^6 pixels, `strips-matching` and
//! `strips-double` on 10^4 and 10^5 pixels, `boundary-cc`, `thin-cc` and `thin-merge` on thin
//! pockets of 10^3 and 10^4 pixels, `thin-euler` on a thin Eulerian pocket, and the
//! `--coverage4` rewrite of the `strips-matching` tour. Run with `cargo bench --bench turns`
//! (add `-- quick` to skip 10^6 and 10^5, `-- star` for star-cover on 10^6 pixels only, e.g.
//! under a profiler, `-- thin` for the boundary and thin algorithms only). Each line
//! ends with the solution's certificates; for `strips-matching` these say whether w(M) is
//! proven minimum over all endpoint pairs (`matching_optimal`) and the proven
//! `matching_lower_bound` (set `MOWMILL_MATCHING_LOG=1` for the LP rounds on stderr).

use mowmill::algorithms::{self, Objective, Options};
use mowmill::checker::{self, Mode};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::Pixel;
use mowmill::region::Region;
use mowmill::strip_cover::strip_cover;
use rand::{RngExt, SeedableRng};
use std::time::Instant;

fn region(family: Family, n: usize, seed: u64) -> Region {
    let mut p = GenParams::new(family, seed);
    p.n = Some(n);
    generate(&p)
        .expect("the generator accepts these parameters")
        .region
}

fn time<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}

/// A thin Eulerian pocket: the symmetric difference of `rects` random rectangle outlines on a
/// `w` × `w` lattice of junctions at even coordinates (every junction keeps an even degree),
/// its largest component.
fn eulerian_thin(seed: u64, w: i32, rects: usize) -> Region {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut edges = std::collections::BTreeSet::new();
    for _ in 0..rects {
        let (a, b) = (rng.random_range(0..w), rng.random_range(0..w));
        let (c, d) = (rng.random_range(0..w), rng.random_range(0..w));
        let (x0, x1, y0, y1) = (a.min(b), a.max(b), c.min(d), c.max(d));
        if x0 == x1 || y0 == y1 {
            continue;
        }
        let mut toggle = |e| {
            if !edges.remove(&e) {
                edges.insert(e);
            }
        };
        for x in x0..x1 {
            toggle((x, y0, true));
            toggle((x, y1, true));
        }
        for y in y0..y1 {
            toggle((x0, y, false));
            toggle((x1, y, false));
        }
    }
    let pixels = edges.into_iter().flat_map(|(x, y, horizontal)| {
        let (dx, dy) = if horizontal { (1, 0) } else { (0, 1) };
        (0..3).map(move |t| Pixel::new(2 * x + t * dx, 2 * y + t * dy))
    });
    largest_component(&Region::from_pixels(pixels).expect("fits"))
}

fn bench_algorithm(name: &str, r: &Region) {
    let algo = algorithms::find(name).expect("registered");
    if let Err(e) = (algo.precondition)(r) {
        println!("{name:16} N={:8} refused: {e}", r.len());
        return;
    }
    let (sol, secs) = match time(|| (algo.run)(r, &Options::default())) {
        (Ok(sol), secs) => (sol, secs),
        (Err(e), _) => {
            println!("{name:16} N={:8} refused: {e}", r.len());
            return;
        }
    };
    let tour = sol.outputs.last().expect("a tour");
    let rep = checker::check(r, &tour.cover, Mode::Milling);
    let certs: Vec<String> = sol
        .certificates
        .iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect();
    println!(
        "{name:16} N={:8} {secs:8.3} s  valid={} turns={} {}",
        r.len(),
        rep.valid && (tour.objective != Objective::Turns || tour.cover.is_tour()),
        rep.turns,
        certs.join(" ")
    );
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    if std::env::args().any(|a| a == "thin") {
        thin_section();
        return;
    }
    if std::env::args().any(|a| a == "star") {
        bench_algorithm("star-cover", &region(Family::RandomSimple, 1_000_000, 1));
        return;
    }
    let sizes_fast: &[usize] = if quick {
        &[100_000]
    } else {
        &[100_000, 1_000_000]
    };
    let sizes_matching: &[usize] = if quick { &[10_000] } else { &[10_000, 100_000] };
    for family in [Family::RandomSimple, Family::RandomHoled] {
        for &n in sizes_fast {
            let r = region(family, n, 1);
            let (cover, secs) = time(|| strip_cover(&r));
            println!(
                "{:16} N={:8} {secs:8.3} s  s={} ({family:?})",
                "strip-cover",
                r.len(),
                cover.size()
            );
            bench_algorithm("star-cover", &r);
        }
        for &n in sizes_matching {
            let r = region(family, n, 1);
            bench_algorithm("strips-matching", &r);
            bench_algorithm("strips-double", &r);
            bench_coverage4(&r);
        }
    }
    thin_section();
}

/// `boundary-cc` on regions of boundary pixels only, `thin-cc` and `thin-merge` on thin
/// pockets, `thin-euler` on a thin Eulerian pocket.
fn thin_section() {
    for n in [1_000, 10_000] {
        bench_algorithm("boundary-cc", &boundary_only(n, 1));
        let r = region(Family::Thin, n, 1);
        for name in ["thin-cc", "thin-merge"] {
            bench_algorithm(name, &r);
        }
    }
    bench_algorithm("thin-euler", &eulerian_thin(1, 150, 400));
}

/// A region whose pixels are all boundary pixels: a random simple region of about `n / 0.8`
/// pixels without those with x + 2y ≡ 0 (mod 5) (every pixel then misses a neighbour), its
/// largest component.
fn boundary_only(n: usize, seed: u64) -> Region {
    let r = region(Family::RandomSimple, n * 5 / 4, seed);
    let kept = Region::from_pixels(
        r.pixels()
            .iter()
            .copied()
            .filter(|p| (p.x + 2 * p.y).rem_euclid(5) != 0),
    )
    .expect("fits");
    largest_component(&kept)
}

fn largest_component(region: &Region) -> Region {
    let labels = mowmill::topology::components(region);
    let mut size = vec![0usize; labels.count];
    labels.label.iter().for_each(|&l| size[l as usize] += 1);
    let big = (0..labels.count)
        .max_by_key(|&l| size[l])
        .expect("a component");
    Region::from_pixels(
        (0..region.len())
            .filter(|&i| labels.label[i] as usize == big)
            .map(|i| region.pixel(i)),
    )
    .expect("fits")
}

/// `--coverage4` on the naive `strips-matching` tour (the one with most overlap).
fn bench_coverage4(r: &Region) {
    let algo = algorithms::find("strips-matching").expect("registered");
    let opts = Options {
        merge: algorithms::Merge::Naive,
        ..Options::default()
    };
    let sol = (algo.run)(r, &opts).expect("the algorithm runs");
    let tour = &sol
        .outputs
        .iter()
        .find(|o| o.objective == Objective::Turns)
        .expect("a tour")
        .cover;
    let before = checker::check(r, tour, Mode::Milling);
    let ((after, stuck), secs) = time(|| mowmill::algorithms::coverage4::coverage4(r, tour));
    let rep = checker::check(r, &after, Mode::Milling);
    println!(
        "{:16} N={:8} {secs:8.3} s  turns {} -> {}, max coverage {} -> {}, stuck {stuck}, valid {}",
        "coverage4",
        r.len(),
        before.turns,
        rep.turns,
        before.max_coverage,
        rep.max_coverage,
        rep.valid
    );
}
