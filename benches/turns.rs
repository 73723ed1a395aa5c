//! Speed of the min-turn algorithms of *Optimal covering tours with turn costs* (issue 5),
//! single thread: the strip cover and `star-cover` on 10^6 pixels, `strips-matching` on 10^4
//! and 10^5 pixels. Run with `cargo bench --bench turns` (add `-- quick` to skip 10^6 and
//! 10^5, `-- star` for star-cover on 10^6 pixels only, e.g. under a profiler). Each line
//! ends with the solution's certificates; for `strips-matching` these say whether w(M) is
//! proven minimum over all endpoint pairs (`matching_optimal`) and the proven
//! `matching_lower_bound` (set `MOWMILL_MATCHING_LOG=1` for the LP rounds on stderr).

use mowmill::algorithms::{self, Options};
use mowmill::checker::{self, Mode};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::Region;
use mowmill::strip_cover::strip_cover;
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

fn bench_algorithm(name: &str, r: &Region) {
    let algo = algorithms::find(name).expect("registered");
    let (sol, secs) = time(|| (algo.run)(r, &Options::default()).expect("the algorithm runs"));
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
        rep.valid && tour.cover.is_tour(),
        rep.turns,
        certs.join(" ")
    );
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
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
        }
    }
}
