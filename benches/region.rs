//! Time and memory proportional to N: `mowmill info`'s work (parse the instance,
//! `topology::summary`, the minimum strip cover) against `tsp65` (run and check), per pixel, on
//! the diagonal band and the random-simple and random-holed families at 10^4, 10^5 and 10^6
//! pixels. Single thread; every time is the median of 5 runs (3 at 10^6 pixels and for
//! parsing). Run with `cargo bench --bench region` (add `-- quick` to stop at 10^5 pixels); the
//! figures of record are in `docs/region-benchmark.md`.
//!
//! Every tour goes through the checker (timed: `mowmill solve` checks too), so a fast but
//! wrong run fails.
//!
//! The band B_k is built here row by row: the generator builds it over its k × k bounding box,
//! and its `.grid` file has k² characters (10^10 bytes at 10^6 pixels), so the band is parsed
//! from its WKT, which has O(N) characters. The random families are parsed from `.grid` text.

use mowmill::algorithms::{self, Options};
use mowmill::checker;
use mowmill::generate::{self, Family, GenParams};
use mowmill::gridfile::GridFile;
use mowmill::region::{Pixel, Region};
use mowmill::strip_cover::min_strip_cover_size;
use mowmill::{topology, wkt};
use std::time::Instant;

/// The diagonal band B_k of the milling paper (Theorem 5): (x, y) with 0 ≤ x, y ≤ k + 1 and
/// |x − y| ≤ 2, N = 5k + 4, built in O(N).
fn band(k: i32) -> Region {
    let m = k + 1;
    Region::from_pixels(
        (0..=m).flat_map(|y| ((y - 2).max(0)..=(y + 2).min(m)).map(move |x| Pixel::new(x, y))),
    )
    .expect("band within the pixel limit")
}

/// The text an instance is stored as, and how to parse it.
enum Stored {
    Grid(String),
    Wkt(String),
}

impl Stored {
    fn parse(&self) -> Region {
        match self {
            Stored::Grid(text) => GridFile::parse(text, "bench.grid").expect("parses").region,
            Stored::Wkt(text) => wkt::parse_wkt(text, "bench.wkt").expect("parses"),
        }
    }

    fn format(&self) -> &'static str {
        match self {
            Stored::Grid(_) => ".grid",
            Stored::Wkt(_) => "WKT",
        }
    }
}

fn seconds(start: Instant) -> f64 {
    start.elapsed().as_secs_f64()
}

/// Runs `f` `reps` times; its last result and the median time in seconds (one run on a shared
/// machine varies by ±30%).
fn timed<T>(reps: usize, mut f: impl FnMut() -> T) -> (T, f64) {
    let mut times = Vec::with_capacity(reps);
    let mut out = None;
    for _ in 0..reps {
        let t = Instant::now();
        out = Some(f());
        times.push(seconds(t));
    }
    times.sort_by(f64::total_cmp);
    (out.expect("reps >= 1"), times[times.len() / 2])
}

/// One line of the table: parse, summary, strip cover, info total; tour run, check, total; all
/// in seconds (each the median of `REPS` runs, 3 at 10^6 pixels and for parsing), then info and the tour in
/// microseconds per pixel.
fn measure(family: &str, stored: &Stored, algo: &str) {
    let (region, parse) = timed(PARSE_REPS, || stored.parse());
    let reps = if region.len() > 500_000 { 3 } else { REPS };
    let (summary, summarize) = timed(reps, || topology::summary(&region));
    let (cover, strips) = timed(reps, || min_strip_cover_size(&region));
    let info = parse + summarize + strips;
    let n = region.len();
    let per_pixel = |s: f64| s / n as f64 * 1e6;

    let a = algorithms::find(algo).expect("registered");
    let (sol, run) = timed(reps, || (a.run)(&region, &Options::default()));
    let sol = match sol {
        Ok(sol) => sol,
        Err(e) => {
            println!(
                "| {family} | {n} | {} | {cover} | {} | {parse:.3} | {summarize:.3} | {strips:.3} | {info:.3} | {algo} | refused: {e} |",
                summary.holes,
                stored.format()
            );
            return;
        }
    };
    let ((), check) = timed(reps, || {
        for out in &sol.outputs {
            let report = checker::check(&region, &out.cover, out.objective.mode());
            assert!(report.valid, "{algo} on {family}: {:?}", report.error);
        }
    });
    let tour = parse + run + check;
    println!(
        "| {family} | {n} | {} | {} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {algo} | {:.3} | {:.3} | {:.3} | {:.2} | {:.2} | {:.2} |",
        summary.holes,
        cover,
        stored.format(),
        parse,
        summarize,
        strips,
        info,
        run,
        check,
        tour,
        per_pixel(info),
        per_pixel(tour),
        tour / info,
    );
}

fn generated(family: Family, n: usize, no_cut: bool) -> Stored {
    let mut p = GenParams::new(family, 1);
    p.n = Some(n);
    p.no_cut = no_cut;
    let t = Instant::now();
    let file = generate::generate(&p).expect("generates");
    eprintln!("generated {} n={n} in {:.1} s", family.name(), seconds(t));
    Stored::Grid(file.to_text().expect("non-negative"))
}

/// Repetitions of every timed step (the median is reported); parsing, which comes before N is
/// known, is repeated 3 times at every size.
const REPS: usize = 5;
const PARSE_REPS: usize = 3;

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    let sizes: &[usize] = if quick {
        &[10_000, 100_000]
    } else {
        &[10_000, 100_000, 1_000_000]
    };
    println!(
        "| family | N | holes | strip cover | format | parse s | summary s | strip cover s | info s | tour | run s | check s | parse+run+check s | info µs/px | tour µs/px | tour/info |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &n in sizes {
        let k = (n as i32 - 4) / 5;
        measure("band", &Stored::Wkt(wkt::to_wkt(&band(k))), "tsp65");
        measure(
            "random-simple",
            &generated(Family::RandomSimple, n, false),
            "tsp65",
        );
        // tsp65 needs a simple region (Theorem 5); holes1325 is its counterpart with holes, and
        // needs no local cut vertices (Theorem 7), hence `--no-cut`.
        measure(
            "random-holed",
            &generated(Family::RandomHoled, n, false),
            "tsp65",
        );
        measure(
            "random-holed --no-cut",
            &generated(Family::RandomHoled, n, true),
            "holes1325",
        );
    }
}
