//! Quality of `lawn-2opt` against the optimal TSP tour through the grass centres (L1, square
//! cutter): `exact --objective lawn-tsp` on small lawns of the `lawn-scattered` and
//! `random-simple` families, one HiGHS thread per solve, warm-started from lawn-2opt's tour
//! (the optimum is still proven by the solver's bound).
//!
//! ```sh
//! cargo run --release --example lawn_2opt_gap -- [--sizes 50,100,150,200,250,300]
//!     [--seeds 10] [--time-limit 60] [--families lawn-scattered,random-simple]
//! ```
//!
//! Prints one line per instance, then the gap (lawn-2opt / OPT − 1) over the instances
//! proven optimal (max and mean), and separately every instance not proven within the time
//! limit with its gap to the proven lower bound (an upper bound on its gap to OPT). Exits 1
//! when some proven gap exceeds 5%.

use mowmill::algorithms::{self, Objective as AlgObjective, Options};
use mowmill::evaluate::{Reference, Subject, evaluate};
use mowmill::exact::{ExactOptions, Objective, Status, solve};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::region::Region;
use std::time::Instant;

fn main() {
    let mut sizes = vec![50usize, 100, 150, 200, 250, 300];
    let mut seeds = 10u64;
    let mut time_limit = 60.0;
    let mut families = vec![Family::LawnScattered, Family::RandomSimple];
    let argv: Vec<String> = std::env::args().skip(1).collect();
    let fail = |m: String| -> ! {
        eprintln!("lawn_2opt_gap: {m}");
        std::process::exit(2)
    };
    let mut i = 0;
    while i < argv.len() {
        let v = argv
            .get(i + 1)
            .cloned()
            .unwrap_or_else(|| fail(format!("{} needs a value", argv[i])));
        match argv[i].as_str() {
            "--sizes" => {
                sizes = v
                    .split(',')
                    .map(|s| {
                        s.parse()
                            .unwrap_or_else(|_| fail(format!("bad size {s:?}")))
                    })
                    .collect()
            }
            "--seeds" => {
                seeds = v
                    .parse()
                    .unwrap_or_else(|_| fail(format!("bad --seeds {v:?}")))
            }
            "--time-limit" => {
                time_limit = v
                    .parse()
                    .unwrap_or_else(|_| fail(format!("bad --time-limit {v:?}")))
            }
            "--families" => {
                families = v
                    .split(',')
                    .map(|s| {
                        s.parse::<Family>()
                            .unwrap_or_else(|e| fail(format!("bad family {s:?}: {e}")))
                    })
                    .collect()
            }
            other => fail(format!("unknown option {other}")),
        }
        i += 2;
    }
    let algo = algorithms::find("lawn-2opt").expect("lawn-2opt is registered");
    let objective = Objective::parse("lawn-tsp", None).expect("lawn-tsp is an exact objective");
    let mut proven: Vec<(String, f64)> = Vec::new();
    let mut open: Vec<(String, u64, u64)> = Vec::new();
    println!("family n seed lawn-2opt opt-or-bound status gap% seconds");
    for &family in &families {
        for &n in &sizes {
            for seed in 1..=seeds {
                let mut p = GenParams::new(family, seed);
                p.n = Some(n);
                let region: Region = match generate(&p) {
                    Ok(g) => g.region,
                    Err(e) => fail(format!("{family} n={n} seed={seed}: {e}")),
                };
                let eval = evaluate(
                    Subject::Registered(algo),
                    &region,
                    &Options::default(),
                    &[AlgObjective::LawnLength],
                    &Reference::default(),
                );
                let out = eval
                    .output(AlgObjective::LawnLength)
                    .unwrap_or_else(|| fail("lawn-2opt gave no tour".into()));
                assert!(out.valid, "lawn-2opt tour rejected by the checker");
                let heuristic = out.length;
                let start = Instant::now();
                let r = solve(
                    &region,
                    objective,
                    &ExactOptions {
                        time_limit: Some(time_limit),
                        warm_start: Some(out.cover.clone()),
                        ..mowmill::warm_start::exact_options()
                    },
                );
                let name = format!("{family} n={n} seed={seed}");
                let secs = start.elapsed().as_secs_f64();
                match (r.status, r.value) {
                    (Status::Optimal, Some(opt)) => {
                        let gap = heuristic as f64 / opt as f64 - 1.0;
                        println!(
                            "{family} {n} {seed} {heuristic} {opt} optimal {:.2} {secs:.1}",
                            100.0 * gap
                        );
                        proven.push((name, gap));
                    }
                    _ => {
                        let lb = r.lower_bound.max(1);
                        println!(
                            "{family} {n} {seed} {heuristic} {lb} {} {:.2} {secs:.1}",
                            r.status,
                            100.0 * (heuristic as f64 / lb as f64 - 1.0)
                        );
                        open.push((name, heuristic, lb));
                    }
                }
            }
        }
    }
    let max = proven
        .iter()
        .cloned()
        .fold(None::<(String, f64)>, |m, x| match m {
            Some(m) if m.1 >= x.1 => Some(m),
            _ => Some(x),
        });
    let mean = proven.iter().map(|x| x.1).sum::<f64>() / proven.len().max(1) as f64;
    let at_opt = proven.iter().filter(|x| x.1 <= 0.0).count();
    println!(
        "proven optimal: {} of {}; lawn-2opt gap over them: max {:.2}% ({}), mean {:.2}%, equal to OPT on {}",
        proven.len(),
        proven.len() + open.len(),
        100.0 * max.as_ref().map_or(0.0, |m| m.1),
        max.as_ref().map_or("-", |m| m.0.as_str()),
        100.0 * mean,
        at_opt
    );
    if open.is_empty() {
        println!("not proven within {time_limit} s: none");
    } else {
        println!(
            "not proven within {time_limit} s (gap to the proven lower bound, an upper bound on the gap):"
        );
        for (name, h, lb) in &open {
            println!(
                "  {name}: lawn-2opt {h}, bound {lb}, {:.2}%",
                100.0 * (*h as f64 / *lb as f64 - 1.0)
            );
        }
    }
    if max.is_some_and(|m| m.1 > 0.05) {
        std::process::exit(1);
    }
}
