//! Corollary 4 (orthogonal polygons with arbitrary coordinates): every output on generated
//! orthogonal polygons passes the exact checker, the stated length bound holds, and the lower
//! bounds never exceed exact optima on small integral regions.

use mowmill::exact::{self, Status};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::ortho::{self, Polygon, Rational, check, corollary4};

fn ratio(a: Rational, b: Rational) -> f64 {
    let f = |r: Rational| r.numer() as f64 / r.denom() as f64;
    f(a) / f(b)
}

fn times(k: i128, den: i128, r: Rational) -> Rational {
    r.checked_mul(Rational::new(k, den).unwrap()).unwrap()
}

#[derive(Default)]
struct Stats {
    polygons: usize,
    worst: f64,
    sum: f64,
    unjoined: usize,
}

fn run(polygon: &Polygon, what: &str, stats: &mut Stats) {
    let (tour, cert) = match corollary4(polygon) {
        Ok(out) => out,
        Err(e)
            if polygon.rings().iter().any(|r| r.hole) && e.to_string().contains("cannot join") =>
        {
            stats.unjoined += 1;
            return;
        }
        Err(e) => panic!("{what}: {e}\n{}", polygon.to_wkt()),
    };
    assert!(tour.is_tour(), "{what}");
    let report = check(polygon, &tour).unwrap();
    assert!(
        report.valid,
        "{what}: {:?}\n{}\n{}",
        report.violation,
        polygon.to_wkt(),
        tour.to_json()
    );
    let lb = cert.bounds.best();
    // The length decomposes as the module docs say: pixel tours + contour + links twice.
    assert!(report.length >= cert.contour_length, "{what}");
    if cert.bounds.contour.is_some() && cert.milling25 == 0 {
        // Corollary 4 with its additive constant, OPT replaced by its lower bound, and each
        // extra component of R_N allowed its own constant (module docs of ortho::corollary4).
        let extra = Rational::integer(12 * cert.components.max(1) as i64);
        let bound = times(11, 5, lb).checked_add(times(1, 5, extra)).unwrap();
        assert!(
            report.length <= bound,
            "{what}: {} > {bound}",
            report.length
        );
    }
    let r = if lb > Rational::ZERO {
        ratio(report.length, lb)
    } else {
        1.0
    };
    stats.polygons += 1;
    stats.sum += r;
    stats.worst = stats.worst.max(r);
}

#[test]
fn corollary4_mills_generated_polygons() {
    let mut all = Vec::new();
    for family in ["ortho-perturbed", "ortho-holed", "ortho-sliver"] {
        let mut stats = Stats::default();
        for seed in 0..120u64 {
            let n = match family {
                "ortho-sliver" => 1 + seed as usize % 8,
                _ => 4 + (seed as usize * 13) % 60,
            };
            let polygon = ortho::generate(family, n, seed).unwrap();
            run(&polygon, &format!("{family} n {n} seed {seed}"), &mut stats);
        }
        eprintln!(
            "{family}: {} polygons milled ({} holed ones not joined), length / lower bound: mean {:.3}, worst {:.3}",
            stats.polygons,
            stats.unjoined,
            stats.sum / stats.polygons as f64,
            stats.worst
        );
        assert!(stats.polygons >= 100, "{family}: {}", stats.polygons);
        all.push(stats);
    }
    // Integral simple regions: the same pipeline on polygons without fractions.
    let mut stats = Stats::default();
    for seed in 0..60 {
        let mut params = GenParams::new(Family::RandomSimple, seed);
        params.n = Some(4 + seed as usize % 40);
        let region = generate(&params).unwrap().region;
        let polygon = Polygon::from_region(&region).unwrap();
        run(&polygon, &format!("random-simple seed {seed}"), &mut stats);
    }
    eprintln!(
        "integral random-simple: {} polygons, mean {:.3}, worst {:.3}",
        stats.polygons,
        stats.sum / stats.polygons as f64,
        stats.worst
    );
}

#[test]
fn narrow_polygons_are_refused() {
    for seed in 0..30 {
        let polygon = ortho::generate("ortho-narrow", 10, seed).unwrap();
        let e = corollary4(&polygon).unwrap_err().to_string();
        assert!(e.contains("cannot be milled"), "{e}");
    }
}

#[test]
fn lower_bounds_never_exceed_exact_optima() {
    let mut compared = 0;
    for seed in 0..40 {
        let mut params = GenParams::new(Family::RandomSimple, 100 + seed);
        params.n = Some(3 + seed as usize % 10);
        let region = generate(&params).unwrap().region;
        let polygon = Polygon::from_region(&region).unwrap();
        let erosion = ortho::feasibility(&polygon).unwrap();
        let bounds = ortho::lower_bounds(&polygon, &erosion).unwrap();
        let result = exact::solve(
            &region,
            exact::Objective::Length,
            &mowmill::warm_start::exact_options(),
        );
        assert_eq!(result.status, Status::Optimal, "seed {seed}");
        let opt = Rational::integer(result.value.unwrap() as i64);
        let contour = bounds.contour.expect("a simple region");
        for (name, value) in [
            ("area", bounds.area),
            ("extent", bounds.extent),
            ("contour", contour),
        ] {
            assert!(
                value <= opt,
                "seed {seed}: {name} bound {value} > OPT {opt}\n{}",
                region.to_ascii()
            );
        }
        compared += 1;
    }
    assert_eq!(compared, 40);
}

#[test]
fn the_contour_is_not_a_lower_bound_with_holes() {
    let region = mowmill::Region::from_ascii("###\n#.#\n###\n");
    let polygon = Polygon::from_region(&region).unwrap();
    let erosion = ortho::feasibility(&polygon).unwrap();
    let contour: Rational = erosion
        .contour()
        .iter()
        .map(|w| ortho::walk_length(w).unwrap())
        .fold(Rational::ZERO, |a, b| a.checked_add(b).unwrap());
    assert_eq!(contour, Rational::integer(16));
    let bounds = ortho::lower_bounds(&polygon, &erosion).unwrap();
    assert_eq!(bounds.contour, None);
    let (tour, _) = corollary4(&polygon).unwrap();
    assert!(check(&polygon, &tour).unwrap().valid);
}
