//! Stress run of `--coverage4` (Theorem 5.6 of the turn-cost paper): the merged tours of the
//! min-turn algorithms on random regions, rewritten to cover each pixel at most 4 times.
//!
//! ```sh
//! cargo run --release --example coverage4_stress -- [--seeds 20] [--sizes 100,300,1000]
//!     [--families random-simple,random-holed,thin]
//! ```
//!
//! Every rewritten tour goes through the checker: it must be a valid tour with no more turns
//! than its input (a violation panics). Prints one line per family and size: tours, how many
//! covered some pixel more than 4 times before, how many still do after (`stuck`, with the
//! instances named so that they can be kept as fixtures), and the total rewrite time. An
//! algorithm that refuses an instance is reported on stderr and skipped.

use mowmill::algorithms::coverage4::coverage4;
use mowmill::algorithms::{self, Merge, Objective, Options};
use mowmill::checker::{Mode, check};
use mowmill::generate::{Family, GenParams, generate};
use std::time::Instant;

fn list<T>(text: &str, parse: impl Fn(&str) -> T) -> Vec<T> {
    text.split(',').map(|s| parse(s.trim())).collect()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let seeds: u64 = value("--seeds").map_or(20, |s| s.parse().expect("--seeds N"));
    let sizes = list(&value("--sizes").unwrap_or("100,300,1000".into()), |s| {
        s.parse::<usize>().expect("--sizes N,N,...")
    });
    let families = list(
        &value("--families").unwrap_or("random-simple,random-holed,thin".into()),
        |s| s.parse::<Family>().expect("--families: known family names"),
    );
    println!("family\tn\ttours\tover4_before\tstuck_after\tseconds");
    for &family in &families {
        for &n in &sizes {
            let (mut tours, mut over, mut stuck_tours, mut seconds) = (0, 0, 0, 0.0);
            for seed in 1..=seeds {
                let region = match generate(&GenParams {
                    n: Some(n),
                    ..GenParams::new(family, seed)
                }) {
                    Ok(g) => g.region,
                    Err(e) => {
                        eprintln!("{family} n={n} seed={seed}: {e}");
                        continue;
                    }
                };
                for name in [
                    "strips-matching",
                    "strips-double",
                    "star-cover",
                    "thin-merge",
                ] {
                    let algo = algorithms::find(name).expect("registered");
                    if (algo.precondition)(&region).is_err() {
                        continue;
                    }
                    for merge in [Merge::Naive, Merge::Smart] {
                        let opts = Options {
                            merge,
                            ..Options::default()
                        };
                        let solution = match (algo.run)(&region, &opts) {
                            Ok(s) => s,
                            Err(e) => {
                                eprintln!("refused: {family} n={n} seed={seed} {name}: {e}");
                                continue;
                            }
                        };
                        let Some(out) = solution
                            .outputs
                            .iter()
                            .find(|o| o.objective == Objective::Turns)
                        else {
                            continue;
                        };
                        let before = check(&region, &out.cover, Mode::Milling);
                        let start = Instant::now();
                        let (after, stuck) = coverage4(&region, &out.cover);
                        seconds += start.elapsed().as_secs_f64();
                        let rep = check(&region, &after, Mode::Milling);
                        assert!(rep.valid && after.is_tour(), "{:?}", rep.error);
                        assert!(rep.turns <= before.turns, "turns grew");
                        assert_eq!(stuck > 0, rep.max_coverage > 4);
                        tours += 1;
                        over += usize::from(before.max_coverage > 4);
                        if stuck > 0 {
                            stuck_tours += 1;
                            eprintln!(
                                "stuck: {family} n={n} seed={seed} {name} {merge:?}: \
                                 {stuck} pixels above 4"
                            );
                        }
                    }
                }
            }
            println!("{family}\t{n}\t{tours}\t{over}\t{stuck_tours}\t{seconds:.2}");
        }
    }
}
