//! Tries to break milling25's registered guarantee (and the paper's 5/2 of Theorem 4) against
//! proven optima of `mowmill exact --objective length`.
//!
//! ```sh
//! # random holed regions of every style, hole count and no_cut setting
//! cargo run --release --example milling25_search -- random [--seeds 40] [--sizes 8,12,...]
//!     [--holes 0,1,2,3,4,6,8] [--styles blob,rectangles,snake,rooms] [--time-limit 5]
//!     [--save instances/findings]
//! # hill climb maximizing length / OPT from random starts
//! cargo run --release --example milling25_search -- climb [--starts 20] [--steps 300]
//!     [--max-n 80] [--time-limit 3] [--save instances/findings] [--from START.grid]
//! ```
//!
//! Every tour goes through the checker. An exact solve that ends without a proven optimum is
//! counted as skipped (never dropped silently), as is a generator refusal (e.g. more holes than
//! N allows). Prints the counts, the worst ratios length / OPT and length / N, the worst ratios
//! of the proof's quantities (L_δB / OPT, L_str / OPT) and the instances reaching them. An
//! instance violating a registered guarantee or 5/2 is saved under `--save` as
//! `milling25-<tag>.grid` with its tour (`.tour.json`); draw it with
//! `mowmill draw FILE --tour TOUR --out PNG`.

use mowmill::algorithms::{self, Measured, Options};
use mowmill::checker::{Mode, check};
use mowmill::exact::{self, ExactOptions, Status};
use mowmill::generate::{Family, GenParams, Style, generate};
use mowmill::gridfile::GridFile;
use mowmill::region::{Pixel, Region};
use mowmill::topology;
use mowmill::tour::CycleCover;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashSet;
use std::path::PathBuf;

fn list<T>(text: &str, parse: impl Fn(&str) -> T) -> Vec<T> {
    text.split(',').map(|s| parse(s.trim())).collect()
}

/// One measured instance.
struct Row {
    n: u64,
    opt: u64,
    length: u64,
    l_db: u64,
    l_str: u64,
    cover: CycleCover,
}

/// What went wrong with one instance, if anything; `Ok(None)` when the optimum is unproven.
fn measure(region: &Region, time_limit: f64) -> Result<Option<Row>, String> {
    let algo = algorithms::find("milling25").expect("registered");
    (algo.precondition)(region).map_err(|e| e.to_string())?;
    let sol = (algo.run)(region, &Options::default()).map_err(|e| e.to_string())?;
    let cover = sol.outputs[0].cover.clone();
    let rep = check(region, &cover, Mode::Milling);
    if !rep.valid || !cover.is_tour() {
        return Err(format!("checker: {:?}\n{}", rep.error, region.to_ascii()));
    }
    let res = exact::solve(
        region,
        exact::Objective::Length,
        &ExactOptions {
            time_limit: Some(time_limit),
            ..mowmill::warm_start::exact_options()
        },
    );
    if res.status != Status::Optimal {
        return Ok(None);
    }
    let opt = res.value.expect("an optimal solve has a value");
    Ok(Some(Row {
        n: region.len() as u64,
        opt,
        length: rep.length,
        l_db: sol.certificates["l_db"] as u64,
        l_str: sol.certificates["l_str"] as u64,
        cover,
    }))
}

/// The registered guarantees of milling25 that `row` breaks (as text).
fn broken(region: &Region, row: &Row) -> Vec<String> {
    let algo = algorithms::find("milling25").expect("registered");
    let m = Measured {
        value: row.length,
        length: row.length,
        max_coverage: 0,
    };
    algo.guarantees
        .iter()
        .filter(|g| g.when.applies(region))
        .filter(|g| g.decide(&m, row.n, Some(row.opt), None) == Some(false))
        .map(|g| g.to_string())
        .collect()
}

/// Worst ratios seen, with the instance reaching each.
#[derive(Default)]
struct Worst {
    count: u64,
    skipped: u64,
    refused: u64,
    over_25: u64,
    violations: u64,
    by_opt: (f64, String),
    by_n: (f64, String),
    db_by_opt: (f64, String),
    str_by_opt: (f64, String),
}

impl Worst {
    fn add(&mut self, tag: &str, region: &Region, row: &Row, save: &Option<PathBuf>) {
        self.count += 1;
        let r = row.length as f64 / row.opt.max(1) as f64;
        for (slot, v) in [
            (&mut self.by_opt, r),
            (&mut self.by_n, row.length as f64 / row.n as f64),
            (&mut self.db_by_opt, row.l_db as f64 / row.opt.max(1) as f64),
            (
                &mut self.str_by_opt,
                row.l_str as f64 / row.opt.max(1) as f64,
            ),
        ] {
            if v > slot.0 {
                *slot = (v, format!("{tag} (N {}, OPT {})", row.n, row.opt));
            }
        }
        let bad = broken(region, row);
        let over = 2 * row.length > 5 * row.opt;
        self.over_25 += u64::from(over);
        self.violations += u64::from(!bad.is_empty());
        if over || !bad.is_empty() {
            eprintln!(
                "{tag}: length {} OPT {} N {} breaks {:?}{}\n{}",
                row.length,
                row.opt,
                row.n,
                bad,
                if over { " and 5/2" } else { "" },
                region.to_ascii()
            );
            if let Some(dir) = save {
                let stem = dir.join(format!("milling25-{tag}"));
                let file = GridFile::with_meta(
                    region.clone(),
                    &[
                        (
                            "finding",
                            format!("milling25 length {} vs OPT {}", row.length, row.opt),
                        ),
                        ("opt_length", row.opt.to_string()),
                    ],
                );
                file.write(&stem.with_extension("grid"))
                    .expect("write grid");
                row.cover
                    .write(&stem.with_extension("tour.json"))
                    .expect("write tour");
            }
        }
    }

    fn print(&self, what: &str) {
        println!(
            "{what}: {} decided, {} skipped (optimum unproven), {} refused by the generator; \
             {} above 5/2 OPT, {} breaking a registered guarantee",
            self.count, self.skipped, self.refused, self.over_25, self.violations
        );
        println!(
            "  worst length / OPT  {:.4}  {}",
            self.by_opt.0, self.by_opt.1
        );
        println!("  worst length / N    {:.4}  {}", self.by_n.0, self.by_n.1);
        println!(
            "  worst L_dB / OPT    {:.4}  {}",
            self.db_by_opt.0, self.db_by_opt.1
        );
        println!(
            "  worst L_str / OPT   {:.4}  {}",
            self.str_by_opt.0, self.str_by_opt.1
        );
    }
}

fn random(args: &[String], value: &dyn Fn(&str) -> Option<String>) {
    let _ = args;
    let seeds: u64 = value("--seeds").map_or(40, |s| s.parse().expect("--seeds N"));
    let sizes = list(
        &value("--sizes").unwrap_or("8,12,16,20,25,30,36,42,50,60".into()),
        |s| s.parse::<usize>().expect("--sizes N,N,..."),
    );
    let holes = list(&value("--holes").unwrap_or("0,1,2,3,4,6,8".into()), |s| {
        s.parse::<usize>().expect("--holes H,H,...")
    });
    let limit: f64 = value("--time-limit").map_or(5.0, |s| s.parse().expect("--time-limit S"));
    let save = value("--save").map(PathBuf::from);
    let mut total = Worst::default();
    let styles = list(
        &value("--styles").unwrap_or("blob,rectangles,snake,rooms".into()),
        |s| {
            s.parse::<Style>()
                .expect("--styles blob,rectangles,snake,rooms")
        },
    );
    for style in styles {
        let mut w = Worst::default();
        for &n in &sizes {
            for &h in &holes {
                for no_cut in [false, true] {
                    for seed in 1..=seeds {
                        let p = GenParams {
                            n: Some(n),
                            holes: Some(h),
                            no_cut,
                            style: Some(style),
                            ..GenParams::new(Family::RandomHoled, seed)
                        };
                        let Ok(file) = generate(&p) else {
                            w.refused += 1;
                            continue;
                        };
                        let tag = format!("{style}-n{n}-h{h}-c{}-s{seed}", u8::from(no_cut));
                        match measure(&file.region, limit) {
                            Ok(Some(row)) => w.add(&tag, &file.region, &row, &save),
                            Ok(None) => w.skipped += 1,
                            Err(e) => panic!("{tag}: {e}"),
                        }
                    }
                }
            }
        }
        w.print(&format!("random-holed style {style}"));
        total.count += w.count;
        total.skipped += w.skipped;
        total.refused += w.refused;
        total.over_25 += w.over_25;
        total.violations += w.violations;
        for (a, b) in [
            (&mut total.by_opt, &w.by_opt),
            (&mut total.by_n, &w.by_n),
            (&mut total.db_by_opt, &w.db_by_opt),
            (&mut total.str_by_opt, &w.str_by_opt),
        ] {
            if b.0 > a.0 {
                *a = b.clone();
            }
        }
    }
    total.print("all styles");
}

/// The region is connected and non-empty.
fn connected(pixels: &HashSet<Pixel>) -> bool {
    let Some(&start) = pixels.iter().next() else {
        return false;
    };
    let mut seen = HashSet::from([start]);
    let mut stack = vec![start];
    while let Some(p) = stack.pop() {
        for d in mowmill::Dir::ALL {
            let q = p.step(d);
            if pixels.contains(&q) && seen.insert(q) {
                stack.push(q);
            }
        }
    }
    seen.len() == pixels.len()
}

/// A random local move: add a pixel next to the region, remove a pixel, open a one-pixel
/// hole (remove a pixel with four neighbours) or close a hole (add a pixel with four).
fn mutate(rng: &mut ChaCha8Rng, pixels: &HashSet<Pixel>, max_n: usize) -> Option<HashSet<Pixel>> {
    let mut list: Vec<Pixel> = pixels.iter().copied().collect();
    list.sort_unstable_by_key(|p| (p.y, p.x));
    let four = |p: Pixel| {
        mowmill::Dir::ALL
            .iter()
            .all(|&d| pixels.contains(&p.step(d)))
    };
    let mut next = pixels.clone();
    match rng.random_range(0..4) {
        0 if pixels.len() < max_n => {
            let p = list[rng.random_range(0..list.len())];
            let q = p.step(mowmill::Dir::from_index(rng.random_range(0..4)));
            if !next.insert(q) {
                return None;
            }
        }
        1 => {
            let p = list[rng.random_range(0..list.len())];
            next.remove(&p);
        }
        2 => {
            let inner: Vec<Pixel> = list.iter().copied().filter(|&p| four(p)).collect();
            if inner.is_empty() {
                return None;
            }
            next.remove(&inner[rng.random_range(0..inner.len())]);
        }
        _ => {
            let holes: Vec<Pixel> = list
                .iter()
                .flat_map(|p| mowmill::Dir::ALL.map(|d| p.step(d)))
                .filter(|&q| !pixels.contains(&q) && four(q))
                .collect();
            if holes.is_empty() {
                return None;
            }
            next.insert(holes[rng.random_range(0..holes.len())]);
        }
    }
    (next.len() >= 2 && connected(&next)).then_some(next)
}

fn climb(value: &dyn Fn(&str) -> Option<String>) {
    let starts: u64 = value("--starts").map_or(20, |s| s.parse().expect("--starts N"));
    let steps: u64 = value("--steps").map_or(300, |s| s.parse().expect("--steps N"));
    let max_n: usize = value("--max-n").map_or(80, |s| s.parse().expect("--max-n N"));
    let limit: f64 = value("--time-limit").map_or(3.0, |s| s.parse().expect("--time-limit S"));
    let save = value("--save").map(PathBuf::from);
    let from = value("--from")
        .map(|f| GridFile::read(std::path::Path::new(&f)).expect("--from FILE.grid"));
    let mut w = Worst::default();
    for start in 1..=starts {
        let mut rng = ChaCha8Rng::seed_from_u64(start);
        let style =
            [Style::Blob, Style::Rectangles, Style::Snake, Style::Rooms][start as usize % 4];
        let p = GenParams {
            n: Some(rng.random_range(20..=max_n.min(60))),
            holes: Some(rng.random_range(1..=4)),
            no_cut: start % 2 == 0,
            style: Some(style),
            ..GenParams::new(Family::RandomHoled, start)
        };
        let file = match (&from, generate(&p)) {
            (Some(f), _) => f.clone(),
            (None, Ok(f)) => f,
            (None, Err(_)) => {
                w.refused += 1;
                continue;
            }
        };
        let mut pixels: HashSet<Pixel> = file.region.pixels().iter().copied().collect();
        let region = file.region.clone();
        let Ok(Some(row)) = measure(&region, limit) else {
            w.skipped += 1;
            continue;
        };
        let mut best = row.length as f64 / row.opt as f64;
        w.add(&format!("climb{start}-0"), &region, &row, &save);
        for step in 1..=steps {
            let Some(next) = mutate(&mut rng, &pixels, max_n) else {
                continue;
            };
            let region = Region::from_pixels(next.iter().copied()).expect("small region");
            match measure(&region, limit) {
                Ok(Some(row)) => {
                    let r = row.length as f64 / row.opt as f64;
                    w.add(&format!("climb{start}-{step}"), &region, &row, &save);
                    if r >= best {
                        best = r;
                        pixels = next;
                    }
                }
                Ok(None) => w.skipped += 1,
                Err(e) => panic!("climb {start} step {step}: {e}"),
            }
        }
        let region = Region::from_pixels(pixels.iter().copied()).expect("small region");
        println!(
            "start {start} ({style}): best length / OPT {best:.4} at N {}, holes {}",
            region.len(),
            topology::holes(&region).count
        );
        println!("{}", region.to_ascii());
    }
    w.print("hill climb");
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    match args.first().map(String::as_str) {
        Some("random") => random(&args, &value),
        Some("climb") => climb(&value),
        _ => eprintln!("usage: milling25_search (random|climb) [options]; see the source"),
    }
}
