//! `strips-contour` (our reading of Theorem 5.7 of *Optimal covering tours with turn costs* on
//! orthogonal polygons with arbitrary coordinates): every output on generated orthogonal polygons
//! passes the exact checker, the proven decomposition bounds of the module docs hold, the corner
//! lower bound never exceeds an exact optimum, and infeasible polygons are refused with the reason.
//!
//! Run with `--nocapture` for the measured ratios to the corner lower bound (and to exact
//! optima on small integral regions).

use mowmill::algorithms::{self, Objective, Options};
use mowmill::checker::{self, Mode};
use mowmill::exact::{self, ExactOptions, Status};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::ortho::{
    self, Polygon, STAR_CONTOUR, STRIPS_CONTOUR, StripsContour, check, star_contour, strips_contour,
};
use mowmill::region::Region;

/// The proven turn lower bound (`ortho::turn_lower_bound`).
fn turn_bound(polygon: &Polygon) -> u64 {
    let erosion = ortho::feasibility(polygon).unwrap();
    ortho::turn_lower_bound(polygon, &erosion).unwrap().best()
}

#[derive(Default)]
struct Stats {
    polygons: usize,
    unjoined: usize,
    cc: Vec<f64>,
    tour: Vec<f64>,
    contour_kept: usize,
    components_dropped: usize,
    rejoined: usize,
}

impl Stats {
    fn line(&self, name: &str) -> String {
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
        let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
        format!(
            "{name}: {} polygons ({} holed not joined); cc turns / turn bound mean {:.3} max \
             {:.3}; tour turns / turn bound mean {:.3} max {:.3}; contour kept in {}, \
             components dropped {}, rejoined {}",
            self.polygons,
            self.unjoined,
            mean(&self.cc),
            max(&self.cc),
            mean(&self.tour),
            max(&self.tour),
            self.contour_kept,
            self.components_dropped,
            self.rejoined
        )
    }
}

/// Runs `strips-contour`, checks both outputs exactly and the module's proven bounds; returns
/// (cc turns, tour turns), or `None` for a holed polygon the links cannot join.
fn run(polygon: &Polygon, what: &str, stats: &mut Stats) -> Option<(u64, u64)> {
    run_with(strips_contour, polygon, what, stats)
}

type Construction = fn(&Polygon, &Options) -> mowmill::Result<StripsContour>;

/// [`run`] for `strips-contour` or `star-contour`.
fn run_with(
    construction: Construction,
    polygon: &Polygon,
    what: &str,
    stats: &mut Stats,
) -> Option<(u64, u64)> {
    let out = match construction(polygon, &Options::default()) {
        Ok(out) => out,
        Err(e) if polygon.has_holes() && e.to_string().contains("cannot join") => {
            stats.unjoined += 1;
            return None;
        }
        Err(e) => panic!("{what}: {e}\n{}", polygon.to_wkt()),
    };
    let c = &out.certificates;
    let cc = check(polygon, &out.cycle_cover).unwrap();
    assert!(
        cc.valid,
        "{what}: cycle cover {:?}\n{}",
        cc.violation,
        polygon.to_wkt()
    );
    let tour = check(polygon, &out.tour).unwrap();
    assert!(
        tour.valid && out.tour.is_tour(),
        "{what}: tour {:?}\n{}\n{}",
        tour.violation,
        polygon.to_wkt(),
        out.tour.to_json()
    );
    // The cycle cover is the kept items' cycles.
    assert_eq!(cc.turns, c.interior_cc_turns + c.contour_turns, "{what}");
    // Proven: each link adds at most 4 turns (module docs of strips_contour and join).
    let bound = c.interior_tour_turns + c.tour_contour_turns + 4 * c.links as u64;
    assert!(tour.turns <= bound, "{what}: {} > {bound}", tour.turns);
    // Proven lower bound.
    assert_eq!(c.lower_bound, turn_bound(polygon));
    assert!(
        cc.turns >= c.lower_bound && tour.turns >= c.lower_bound,
        "{what}"
    );
    let lb = c.lower_bound as f64;
    stats.polygons += 1;
    stats.cc.push(cc.turns as f64 / lb);
    stats.tour.push(tour.turns as f64 / lb);
    stats.contour_kept += usize::from(c.contour_kept > 0);
    stats.components_dropped += c.components - c.components_kept;
    stats.rejoined += usize::from(c.rejoined > 0);
    Some((cc.turns, tour.turns))
}

#[test]
fn strips_contour_mills_generated_polygons() {
    for family in ["ortho-perturbed", "ortho-holed", "ortho-sliver"] {
        let mut stats = Stats::default();
        for seed in 0..100u64 {
            let n = 8 + (seed as usize * 7) % 23;
            let polygon = ortho::generate(family, n, seed).unwrap();
            run(&polygon, &format!("{family} n {n} seed {seed}"), &mut stats);
        }
        eprintln!("{}", stats.line(family));
        assert!(stats.polygons >= 90, "{}", stats.line(family));
        if family == "ortho-sliver" {
            // Slivers are milled by their contour: it is never dropped.
            assert_eq!(stats.contour_kept, stats.polygons);
        }
    }
}

fn random_simple(seed: u64, n: usize) -> Region {
    random(Family::RandomSimple, seed, n)
}

fn random(family: Family, seed: u64, n: usize) -> Region {
    let mut params = GenParams::new(family, seed);
    params.n = Some(n);
    generate(&params).unwrap().region
}

/// On integral polygons the pixels mill P, so the output is `strips-matching`'s (or the
/// contour, when that mills P with fewer turns): never more turns, and the registered grid run
/// agrees with the pixel checker.
#[test]
fn integral_polygons_agree_with_the_grid() {
    let strips_matching = algorithms::find("strips-matching").unwrap();
    for (name, family, n0) in [
        ("random-simple", Family::RandomSimple, 4),
        ("random-holed", Family::RandomHoled, 8),
    ] {
        let mut stats = Stats::default();
        let mut same = 0;
        for seed in 0..100u64 {
            let n = n0 + seed as usize % 40;
            let region = random(family, seed, n);
            let polygon = Polygon::from_region(&region).unwrap();
            let what = format!("{name} n {n} seed {seed}");
            let (cc, tour) = run(&polygon, &what, &mut stats).unwrap();
            let grid = (STRIPS_CONTOUR.run)(&region, &Options::default()).unwrap();
            let reference = (strips_matching.run)(&region, &Options::default()).unwrap();
            for (objective, turns) in [(Objective::CcTurns, cc), (Objective::Turns, tour)] {
                let cover = &grid
                    .outputs
                    .iter()
                    .find(|o| o.objective == objective)
                    .unwrap()
                    .cover;
                let report = checker::check(&region, cover, Mode::Milling);
                assert!(report.valid, "{what}: {objective} {:?}", report.error);
                assert_eq!(report.turns, turns, "{what}: {objective}");
                if objective == Objective::Turns {
                    assert_eq!(report.cycles, 1, "{what}");
                }
                let theirs = &reference
                    .outputs
                    .iter()
                    .find(|o| o.objective == objective)
                    .unwrap()
                    .cover;
                let theirs = checker::check(&region, theirs, Mode::Milling).turns;
                assert!(turns <= theirs, "{what}: {objective} {turns} > {theirs}");
                same += usize::from(turns == theirs);
            }
        }
        eprintln!(
            "{}; equal to strips-matching in {same} of 200 outputs",
            stats.line(&format!("integral {name}"))
        );
    }
}

/// Small integral regions: the turn bound never exceeds the exact optima; the measured
/// ratios to them.
#[test]
fn against_exact_optima_on_small_regions() {
    let opts = ExactOptions {
        time_limit: Some(10.0),
        ..mowmill::warm_start::exact_options()
    };
    let mut stats = Stats::default();
    let (mut cc_ratios, mut tour_ratios, mut lb_ratios) = (Vec::new(), Vec::new(), Vec::new());
    for seed in 0..40u64 {
        let n = 8 + seed as usize % 17;
        let region = random_simple(200 + seed, n);
        let polygon = Polygon::from_region(&region).unwrap();
        let what = format!("random-simple n {n} seed {}", 200 + seed);
        let (cc, tour) = run(&polygon, &what, &mut stats).unwrap();
        let opt_cc = exact::solve(&region, exact::Objective::CcTurns, &opts);
        let opt_tour = exact::solve(&region, exact::Objective::Turns, &opts);
        // Every instance is decided: none skipped (n <= 24 solves in well under the limit).
        assert!(
            opt_cc.status == Status::Optimal && opt_tour.status == Status::Optimal,
            "{what}: the exact solver did not prove an optimum"
        );
        let (opt_cc, opt_tour) = (opt_cc.value.unwrap(), opt_tour.value.unwrap());
        let lb = turn_bound(&polygon);
        assert!(
            lb <= opt_cc && opt_cc <= opt_tour,
            "{what}: {lb} {opt_cc} {opt_tour}"
        );
        assert!(opt_cc <= cc && opt_tour <= tour, "{what}");
        cc_ratios.push(cc as f64 / opt_cc as f64);
        tour_ratios.push(tour as f64 / opt_tour as f64);
        lb_ratios.push(opt_cc as f64 / lb as f64);
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    eprintln!(
        "exact optima on {} small integral regions: cc / OPT_cc mean {:.3} max {:.3}; tour / \
         OPT mean {:.3} max {:.3}; OPT_cc / turn bound mean {:.3} max {:.3}",
        cc_ratios.len(),
        mean(&cc_ratios),
        max(&cc_ratios),
        mean(&tour_ratios),
        max(&tour_ratios),
        mean(&lb_ratios),
        max(&lb_ratios)
    );
    assert_eq!(cc_ratios.len(), 40);
}

#[test]
fn infeasible_polygons_are_refused() {
    for seed in 0..30 {
        let polygon = ortho::generate("ortho-narrow", 10, seed).unwrap();
        let e = strips_contour(&polygon, &Options::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("cannot be milled"), "{e}");
        let e = (STRIPS_CONTOUR.ortho.unwrap())(&polygon, &Options::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("cannot be milled"), "{e}");
    }
    // Two unit squares sharing half an edge: each can be milled, not both by one tour.
    let pair = Polygon::parse(
        "POLYGON ((0 0, 1 0, 1 0.5, 2 0.5, 2 1.5, 1 1.5, 1 1, 0 1, 0 0))",
        "pair.wkt",
    )
    .unwrap();
    let e = strips_contour(&pair, &Options::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("fall into 2 pieces"), "{e}");
}

/// `star-contour` (Table 1's star-cover line, our reading): both outputs valid on every
/// generated family, and on integral regions never more turns than the grid `star-cover`.
#[test]
fn star_contour_mills_generated_and_integral_polygons() {
    for family in ["ortho-perturbed", "ortho-holed", "ortho-sliver"] {
        let mut stats = Stats::default();
        for seed in 0..60u64 {
            let n = 8 + (seed as usize * 7) % 23;
            let polygon = ortho::generate(family, n, seed).unwrap();
            let what = format!("star-contour {family} n {n} seed {seed}");
            run_with(star_contour, &polygon, &what, &mut stats);
        }
        eprintln!("{}", stats.line(&format!("star-contour {family}")));
        assert!(stats.polygons >= 55, "{}", stats.line(family));
    }
    let star_cover = algorithms::find("star-cover").unwrap();
    for seed in 0..60u64 {
        let n = 4 + seed as usize % 40;
        let region = random_simple(seed, n);
        let what = format!("star-contour random-simple n {n} seed {seed}");
        let grid = (STAR_CONTOUR.run)(&region, &Options::default()).unwrap();
        let reference = (star_cover.run)(&region, &Options::default()).unwrap();
        for objective in [Objective::CcTurns, Objective::Turns] {
            let turns = |solution: &mowmill::algorithms::Solution| {
                let cover = &solution
                    .outputs
                    .iter()
                    .find(|o| o.objective == objective)
                    .unwrap()
                    .cover;
                let report = checker::check(&region, cover, Mode::Milling);
                assert!(report.valid, "{what}: {objective} {:?}", report.error);
                report.turns
            };
            let (ours, theirs) = (turns(&grid), turns(&reference));
            assert!(ours <= theirs, "{what}: {objective} {ours} > {theirs}");
        }
    }
}
