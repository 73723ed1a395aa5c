//! Orthogonal polygons with arbitrary coordinates in the one pipeline: the registry's
//! ortho runs through `evaluate` on a polygon (exact lengths over a common denominator), the integral
//! special case through the grid pipeline, the bench families and files, and the claims table.

mod common;

use common::{mowmill, temp_dir};
use mowmill::algorithms::{self, Objective, Options};
use mowmill::evaluate::{Reference, Subject, evaluate};
use mowmill::generate::{Family, GenParams, generate};
use mowmill::harness::rows::read_rows;
use mowmill::ortho::{self, Polygon, Rational};

fn ortho_algorithms() -> Vec<&'static algorithms::Algorithm> {
    algorithms::REGISTRY
        .iter()
        .filter(|a| a.ortho.is_some())
        .collect()
}

/// Exact values in units: value / unit is the checker's exact length, the lower bound is the
/// proven bound rounded down to the unit, and ratios follow.
#[test]
fn ortho_lengths_are_exact_in_their_unit() {
    let mut checked = 0;
    for family in ["ortho-perturbed", "ortho-sliver", "ortho-holed"] {
        for seed in 0..12 {
            let p = ortho::generate(family, 14, seed).unwrap();
            for algorithm in ortho_algorithms() {
                let eval = evaluate(
                    Subject::Registered(algorithm),
                    &p,
                    &Options::default(),
                    &[],
                    &Reference::default(),
                );
                if let Some(e) = &eval.error {
                    // Only the documented refusal: a hole's contour no straight link reaches.
                    assert!(
                        family == "ortho-holed" && e.contains("straight links"),
                        "{family} {seed} {}: {e}",
                        algorithm.name
                    );
                    continue;
                }
                for c in &eval.outputs {
                    assert!(c.valid, "{family} {seed} {}: {:?}", algorithm.name, c.error);
                    let report = ortho::check(&p, &c.cover).unwrap();
                    let unit = Rational::from(c.unit as i64);
                    assert_eq!(
                        Rational::from(c.length as i64),
                        report.length.checked_mul(unit).unwrap(),
                        "length in units"
                    );
                    assert_eq!(c.turns, report.turns);
                    let (bound, _) = mowmill::evaluate::ortho_bound(&p, c.objective).unwrap();
                    let lb = c.lower_bound.unwrap();
                    match c.objective {
                        Objective::Length => {
                            assert_eq!(c.value, c.length);
                            let scaled = bound.checked_mul(unit).unwrap();
                            assert_eq!(lb as i128, scaled.floor());
                        }
                        _ => {
                            assert_eq!(c.value, c.turns);
                            assert_eq!(lb as i128, bound.floor());
                        }
                    }
                    assert!(lb <= c.value, "a lower bound above a valid walk");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 30, "{checked}");
}

/// The integral special case: on a grid region, an ortho algorithm's grid run (walks mapped to
/// pixels, checked by the grid checker) and its ortho run on the region's polygon (checked
/// exactly) measure the same length and turns.
#[test]
fn grid_and_ortho_runs_agree_on_integral_polygons() {
    let mut compared = 0;
    for (family, holes) in [(Family::RandomSimple, None), (Family::RandomHoled, Some(1))] {
        for seed in 0..15 {
            let mut params = GenParams::new(family, seed);
            params.n = Some(16);
            params.holes = holes;
            let Ok(file) = generate(&params) else {
                continue;
            };
            let region = file.region;
            let polygon = Polygon::from_region(&region).unwrap();
            for algorithm in ortho_algorithms() {
                let grid = evaluate(
                    Subject::Registered(algorithm),
                    &region,
                    &Options::default(),
                    &[],
                    &Reference::default(),
                );
                let exact = evaluate(
                    Subject::Registered(algorithm),
                    &polygon,
                    &Options::default(),
                    &[],
                    &Reference::default(),
                );
                assert_eq!(grid.error, exact.error, "{seed} {}", algorithm.name);
                for (g, e) in grid.outputs.iter().zip(&exact.outputs) {
                    assert_eq!(g.objective, e.objective);
                    assert!(
                        g.valid && e.valid,
                        "{seed} {}: {:?}",
                        algorithm.name,
                        g.error
                    );
                    assert_eq!(g.turns, e.turns);
                    assert_eq!(g.length * e.unit, e.length);
                    assert_eq!(g.cycles, e.cycles);
                    compared += 1;
                }
            }
        }
    }
    assert!(compared >= 20, "{compared}");
}

/// A bench of an ortho family and a folder with a non-integral .wkt: rows of model `ortho`
/// with their unit, ratios in the unit, and the claims table decides Corollary 4 from them.
#[test]
fn bench_runs_ortho_families_and_files_and_claims_decide_them() {
    let dir = temp_dir("ortho-bench");
    let files = dir.join("files");
    std::fs::create_dir_all(&files).unwrap();
    std::fs::write(
        files.join("l.wkt"),
        "POLYGON ((0 0, 4.5 0, 4.5 1.25, 1.75 1.25, 1.75 3.5, 0 3.5, 0 0))\n",
    )
    .unwrap();
    let cfg = dir.join("o.toml");
    std::fs::write(
        &cfg,
        format!(
            r#"name = "ortho"
seed = 3
[[family]]
family = "ortho-perturbed"
n = [10]
count = 3
[[family]]
family = "ortho-narrow"
n = [10]
count = 1
[[files]]
dir = "{}"
family = "shapes"
"#,
            files.display()
        ),
    )
    .unwrap();
    let out = dir.join("run");
    let o = mowmill(&[
        "bench",
        "--config",
        cfg.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = read_rows(&out.join("results.csv")).unwrap();
    let names: Vec<&str> = ortho_algorithms().iter().map(|a| a.name).collect();
    for r in &rows {
        assert_eq!(r.model, "ortho", "{}", r.instance);
        if r.family == "ortho-narrow" {
            // Refused: an error row per algorithm objective, naming why.
            assert!(r.error.contains("cannot be milled"), "{}", r.error);
            continue;
        }
        assert!(names.contains(&r.algorithm.as_str()), "{}", r.algorithm);
        assert_eq!(
            r.valid,
            Some(true),
            "{} {}: {}",
            r.instance,
            r.algorithm,
            r.error
        );
        let unit = r.unit.expect("ortho rows carry their unit");
        if r.objective == "length" {
            let (v, lb) = (r.value.unwrap(), r.lower_bound.unwrap());
            let ratio = r.ratio_lb.unwrap().0;
            assert!((ratio - v as f64 / lb as f64).abs() < 1e-6);
            let per_n = r.ratio_n.unwrap().0;
            assert!((per_n - v as f64 / (unit * r.n) as f64).abs() < 1e-6);
        }
    }
    assert!(rows.iter().any(|r| r.instance == "shapes_l"));
    let claims = mowmill(&[
        "claims",
        "--from",
        out.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        claims.status.success(),
        "{}",
        String::from_utf8_lossy(&claims.stderr)
    );
    let table = std::fs::read_to_string(out.join("claims.csv")).unwrap();
    let cor4 = table
        .lines()
        .find(|l| l.contains("Corollary 4,"))
        .expect("a Corollary 4 row");
    assert!(cor4.contains("corollary4"), "{cor4}");
    // The gate takes the run as its own baseline.
    let gate = mowmill(&[
        "gate",
        "--baseline",
        out.join("stats.csv").to_str().unwrap(),
        "--current",
        out.to_str().unwrap(),
    ]);
    assert!(
        gate.status.success(),
        "{}",
        String::from_utf8_lossy(&gate.stdout)
    );
}

/// Config refusals for the ortho families, naming the key.
#[test]
fn ortho_families_take_n_only() {
    let dir = temp_dir("ortho-config");
    for (body, expected) in [
        ("family = \"ortho-sliver\"\ncount = 1\n", "needs n"),
        (
            "family = \"ortho-sliver\"\nn = 8\nholes = 1\ncount = 1\n",
            "does not apply",
        ),
        (
            "family = \"ortho-sliver\"\nn = 0\ncount = 1\n",
            "from 1 to 10000",
        ),
    ] {
        let cfg = dir.join("c.toml");
        std::fs::write(&cfg, format!("name = \"x\"\nseed = 1\n[[family]]\n{body}")).unwrap();
        let o = mowmill(&[
            "bench",
            "--config",
            cfg.to_str().unwrap(),
            "--out",
            dir.join("run").to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{body}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("family[0]") && err.contains(expected),
            "{body}: {err}"
        );
    }
}
