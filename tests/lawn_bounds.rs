//! The lawn tours' cheap lower bound (area, and the spread of the grass for the square cutters)
//! never exceeds a checked tour: every registered lawn algorithm, both square cutters, on random
//! scattered lawns and on lawns spread far apart (where the spread bound is the larger one and a
//! hunt once reported ratios of 1,036 against the area bound alone).

use mowmill::algorithms::{self, Cutter, Objective, Options};
use mowmill::evaluate::{Reference, Subject, cheap_bound, evaluate};
use mowmill::generate::{self, Family, GenParams};
use mowmill::region::{Pixel, Region};
use rand::{RngExt, SeedableRng};

fn lawns() -> Vec<Region> {
    let mut out = Vec::new();
    for seed in 0..40 {
        let mut p = GenParams::new(Family::LawnScattered, seed);
        p.n = Some(4 + seed as usize % 20);
        out.push(generate::generate(&p).unwrap().region);
    }
    // A few pixels spread over up to 300 columns and 60 rows.
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for _ in 0..40 {
        let k = rng.random_range(2..8);
        let pixels: Vec<Pixel> = (0..k)
            .map(|_| Pixel::new(rng.random_range(0..300), rng.random_range(0..60)))
            .collect();
        out.push(Region::from_pixels(pixels).unwrap());
    }
    out
}

#[test]
fn lawn_bounds_never_exceed_a_checked_tour() {
    let lawn_algos: Vec<&str> = algorithms::names()
        .into_iter()
        .filter(|n| n.starts_with("lawn-"))
        .collect();
    assert!(lawn_algos.len() >= 4, "{lawn_algos:?}");
    let mut spread_larger = 0;
    for region in lawns() {
        for cutter in [Cutter::Square, Cutter::SquareFree] {
            let (bound, source) = cheap_bound(&region, Objective::LawnLength, cutter);
            spread_larger += usize::from(source.starts_with("spread"));
            for name in &lawn_algos {
                let options = Options {
                    cutter,
                    ..Options::default()
                };
                let eval = evaluate(
                    Subject::Registered(algorithms::find(name).unwrap()),
                    &region,
                    &options,
                    &[Objective::LawnLength],
                    &Reference::default(),
                );
                assert!(eval.error.is_none(), "{name} {cutter}: {:?}", eval.error);
                assert!(
                    eval.missing.is_empty(),
                    "{name} {cutter}: {:?}",
                    eval.missing
                );
                let tour = eval.output(Objective::LawnLength).unwrap();
                assert!(tour.valid, "{name} {cutter}: {:?}", tour.error);
                assert!(
                    tour.value >= bound,
                    "{name} with the {cutter} cutter: tour {} below the bound {bound} ({source}) on\n{}",
                    tour.value,
                    region.to_ascii()
                );
            }
        }
    }
    assert!(
        spread_larger >= 40,
        "the spread bound decided only {spread_larger} cases"
    );
}
