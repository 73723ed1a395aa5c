//! Scaling benchmark of the exact baselines: solve time against N per objective, on random
//! simple and holed regions (the `random-simple` and `random-holed` generator families,
//! several seeds per size), one HiGHS thread per solve.
//!
//! ```sh
//! cargo run --release --example exact_scaling -- [--objectives length,cc-turns,tour-turns]
//!     [--sizes 50,100,150,200] [--seeds 5] [--time-limit 120] [--jobs 1] [--turn-cost 1]
//!     [--families random-simple,random-holed] [--rows FILE.jsonl]
//! ```
//!
//! Prints one line per solve and a table per objective and N: solved/total, median and
//! maximum seconds (time-limited solves count at the limit). `--jobs` runs solves in parallel
//! (the goals are measured with `--jobs 1` on an otherwise idle machine). Strip-cover timing
//! on 10⁶ pixels is printed with `--strip-cover`.

use mowmill::exact::{ExactOptions, Objective, Status, solve};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::{Pixel, Region};
use std::io::Write;
use std::sync::Mutex;
use std::time::Instant;

struct Args {
    objectives: Vec<Objective>,
    sizes: Vec<usize>,
    seeds: u64,
    time_limit: f64,
    jobs: usize,
    families: Vec<Family>,
    rows: Option<String>,
    strip_cover: bool,
    verbose: bool,
}

fn parse_args() -> Result<Args, String> {
    let mut a = Args {
        objectives: vec![Objective::Length, Objective::CcTurns, Objective::Turns],
        sizes: vec![50, 100, 150, 200],
        seeds: 5,
        time_limit: 120.0,
        jobs: 1,
        families: vec![Family::RandomSimple, Family::RandomHoled],
        rows: None,
        strip_cover: false,
        verbose: false,
    };
    let mut turn_cost = 1u32;
    let mut objective_names: Option<String> = None;
    let argv: Vec<String> = std::env::args().skip(1).collect();
    let mut i = 0;
    let value = |i: usize| {
        argv.get(i + 1)
            .cloned()
            .ok_or(format!("{} needs a value", argv[i]))
    };
    while i < argv.len() {
        match argv[i].as_str() {
            "--objectives" => objective_names = Some(value(i)?),
            "--sizes" => {
                a.sizes = value(i)?
                    .split(',')
                    .map(|s| s.parse().map_err(|e| format!("--sizes: {e}")))
                    .collect::<Result<_, _>>()?
            }
            "--seeds" => a.seeds = value(i)?.parse().map_err(|e| format!("--seeds: {e}"))?,
            "--time-limit" => {
                a.time_limit = value(i)?
                    .parse()
                    .map_err(|e| format!("--time-limit: {e}"))?
            }
            "--jobs" => a.jobs = value(i)?.parse().map_err(|e| format!("--jobs: {e}"))?,
            "--turn-cost" => {
                turn_cost = value(i)?.parse().map_err(|e| format!("--turn-cost: {e}"))?
            }
            "--families" => {
                a.families = value(i)?
                    .split(',')
                    .map(|s| s.parse::<Family>().map_err(|e| e.to_string()))
                    .collect::<Result<_, _>>()?
            }
            "--rows" => a.rows = Some(value(i)?),
            "--strip-cover" => {
                a.strip_cover = true;
                i += 1;
                continue;
            }
            "--verbose" => {
                a.verbose = true;
                i += 1;
                continue;
            }
            other => return Err(format!("unknown argument {other}")),
        }
        i += 2;
    }
    if let Some(names) = objective_names {
        a.objectives = names
            .split(',')
            .map(|s| match s {
                "weighted" => Ok(Objective::Weighted(turn_cost)),
                _ => s.parse::<Objective>(),
            })
            .collect::<Result<_, _>>()?;
    }
    Ok(a)
}

fn instance(family: Family, n: usize, seed: u64) -> Region {
    let mut p = GenParams::new(family, seed);
    p.n = Some(n);
    if family == Family::RandomHoled {
        p.holes = Some(1 + (seed as usize % 3));
    }
    generate(&p)
        .expect("generator accepts the benchmark parameters")
        .region
}

fn median(xs: &mut [f64]) -> f64 {
    xs.sort_by(f64::total_cmp);
    let m = xs.len();
    if m == 0 {
        f64::NAN
    } else if m % 2 == 1 {
        xs[m / 2]
    } else {
        (xs[m / 2 - 1] + xs[m / 2]) / 2.0
    }
}

struct Row {
    objective: String,
    family: &'static str,
    n: usize,
    seed: u64,
    status: Status,
    seconds: f64,
    value: Option<u64>,
    lower: u64,
    rounds: u32,
}

fn main() {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("exact_scaling: {e}");
            std::process::exit(2);
        }
    };
    if args.strip_cover {
        strip_cover_timing();
    }
    let mut tasks = Vec::new();
    for &objective in &args.objectives {
        for &n in &args.sizes {
            for &family in &args.families {
                for seed in 1..=args.seeds {
                    tasks.push((objective, n, family, seed));
                }
            }
        }
    }
    let rows: Mutex<Vec<Row>> = Mutex::new(Vec::new());
    let next = Mutex::new(0usize);
    let sink = args
        .rows
        .as_ref()
        .map(|p| Mutex::new(std::fs::File::create(p).expect("create --rows file")));
    std::thread::scope(|scope| {
        for _ in 0..args.jobs.max(1) {
            scope.spawn(|| loop {
                let k = {
                    let mut g = next.lock().expect("task counter");
                    *g += 1;
                    *g - 1
                };
                let Some(&(objective, n, family, seed)) = tasks.get(k) else { break };
                let region = instance(family, n, seed);
                let opts = ExactOptions { time_limit: Some(args.time_limit), verbose: args.verbose, ..mowmill::warm_start::exact_options() };
                let t = Instant::now();
                let r = solve(&region, objective, &opts);
                let seconds = t.elapsed().as_secs_f64();
                let line = format!(
                    "{:<11} {:<13} n={:<4} seed={:<3} {:<10} value={:<6} lb={:<6} rounds={:<4} {:7.2} s{}",
                    objective.to_string(),
                    family.name(),
                    region.len(),
                    seed,
                    r.status.to_string(),
                    r.value.map_or("-".into(), |v| v.to_string()),
                    r.lower_bound,
                    r.rounds,
                    seconds,
                    r.message.as_deref().map_or(String::new(), |m| format!("  ({m})"))
                );
                println!("{line}");
                if let Some(s) = &sink {
                    let json = serde_json::json!({
                        "objective": r.objective, "family": family.name(), "n": region.len(), "seed": seed,
                        "status": r.status, "value": r.value, "lower_bound": r.lower_bound, "rounds": r.rounds,
                        "seconds": seconds, "lb_source": r.lb_source, "lp_bound": r.lp_bound,
                    });
                    writeln!(s.lock().expect("rows file"), "{json}").expect("write --rows");
                }
                rows.lock().expect("rows").push(Row {
                    objective: objective.to_string(),
                    family: family.name(),
                    n,
                    seed,
                    status: r.status,
                    seconds,
                    value: r.value,
                    lower: r.lower_bound,
                    rounds: r.rounds,
                });
            });
        }
    });
    let rows = rows.into_inner().expect("rows");
    println!();
    println!(
        "objective    N     solved   median s    max s   (time limit {} s, {} job(s))",
        args.time_limit, args.jobs
    );
    for objective in &args.objectives {
        for &n in &args.sizes {
            let sel: Vec<&Row> = rows
                .iter()
                .filter(|r| r.objective == objective.to_string() && r.n == n)
                .collect();
            let solved = sel.iter().filter(|r| r.status == Status::Optimal).count();
            let mut times: Vec<f64> = sel.iter().map(|r| r.seconds).collect();
            let max = times.iter().copied().fold(0.0, f64::max);
            println!(
                "{:<11} {:<5} {:>3}/{:<3}  {:>9.2} {:>8.2}",
                objective.to_string(),
                n,
                solved,
                sel.len(),
                median(&mut times),
                max
            );
        }
    }
    let unsolved: Vec<&Row> = rows
        .iter()
        .filter(|r| r.status != Status::Optimal)
        .collect();
    if !unsolved.is_empty() {
        println!();
        println!("not proven optimal:");
        for r in unsolved {
            println!(
                "  {} {} n={} seed={}: {} value {:?} bound {} ({} rounds)",
                r.objective, r.family, r.n, r.seed, r.status, r.value, r.lower, r.rounds
            );
        }
    }
}

/// Minimum strip cover on about 10⁶ pixels: a disk with a sieve of holes (long strips) and a
/// random 60 % fill of a square (short strips, many augmenting paths).
fn strip_cover_timing() {
    use rand::{RngExt, SeedableRng};
    let side = 1130i32;
    let disk = Region::from_pixels(
        (0..side)
            .flat_map(|y| (0..side).map(move |x| Pixel::new(x, y)))
            .filter(|p| {
                let (dx, dy) = (p.x - side / 2, p.y - side / 2);
                dx * dx + dy * dy <= side * side / 4 && !(p.x % 9 == 4 && p.y % 7 == 3)
            }),
    )
    .expect("fits");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let side = 1290i32;
    let fill = Region::from_pixels(
        (0..side)
            .flat_map(|y| (0..side).map(move |x| Pixel::new(x, y)))
            .filter(|_| rng.random_range(0..10u32) < 6)
            .collect::<Vec<_>>(),
    )
    .expect("fits");
    for (name, r) in [("disk with sieve", disk), ("random 60% fill", fill)] {
        let t = Instant::now();
        let c = mowmill::strip_cover::strip_cover(&r);
        println!(
            "strip cover, {name}: N = {}, {} strips = {} rooks, {:.3} s",
            r.len(),
            c.strips.len(),
            c.rooks.len(),
            t.elapsed().as_secs_f64()
        );
    }
}
