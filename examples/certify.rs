//! Certificates and guarantees of every registered algorithm against `mowmill exact`, at
//! scale: random regions of every generator family and style (N ≤ `--max-n`, 60 by default),
//! optional mid-size regions, then a hill climb from the hardest regions found (add or remove
//! one pixel, keeping the family's constraint) maximizing value − OPT on the exactness claims
//! and value / bound on the guarantees. The checks are those of `tests/certify/mod.rs`.
//!
//! ```text
//! cargo run --release --example certify -- --per-combo 100 --budget 1500 --out /tmp/findings
//! ```
//!
//! Prints, per algorithm and check, instances, decided, skipped (undecided), worst (value / OPT;
//! for exactness claims the largest value − OPT) and violations; writes each violating region
//! (one per check and shape) as a `.grid` file under `--out`. Unproven exact solves are
//! counted and printed.

#[path = "../tests/certify/mod.rs"]
mod certify;

use certify::{Score, Tally, check_algorithms, exact_options, optima, table};
use clap::Parser;
use mowmill::generate::{Family, GenParams, Style, generate};
use mowmill::gridfile::GridFile;
use mowmill::region::{Pixel, Region};
use mowmill::topology;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Parser)]
struct Args {
    /// Random regions per family/style combination (round-robin until the budget ends).
    #[arg(long, default_value_t = 1000)]
    per_combo: usize,
    /// Largest N of the random regions.
    #[arg(long, default_value_t = 60)]
    max_n: usize,
    /// Mid-size regions per combination (N from max-n to mid-n), after the small ones.
    #[arg(long, default_value_t = 0)]
    mid: usize,
    #[arg(long, default_value_t = 200)]
    mid_n: usize,
    /// Hill-climb steps from each of the `--starts` hardest regions.
    #[arg(long, default_value_t = 200)]
    climb: usize,
    #[arg(long, default_value_t = 12)]
    starts: usize,
    /// Seconds per exact solve.
    #[arg(long, default_value_t = 10.0)]
    time_limit: f64,
    /// Wall-clock budget in seconds for the random phase; the climb gets a third more.
    #[arg(long, default_value_t = 1800.0)]
    budget: f64,
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// What the climb maximizes: `excess` (value − OPT on exactness claims, then the ratio)
    /// or `ratio` (quantity / bound on the guarantees against OPT only).
    #[arg(long, default_value = "excess")]
    by: String,
    /// Folder for violating regions.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// A family with a style or parameter choice; `make` builds its parameters from (n, seed).
struct Combo {
    name: String,
    family: Family,
    style: Option<Style>,
    no_cut: bool,
    holes: Option<(usize, usize)>,
}

fn combos() -> Vec<Combo> {
    let mut v = Vec::new();
    let c = |name: String, family, style, no_cut, holes| Combo {
        name,
        family,
        style,
        no_cut,
        holes,
    };
    for f in [Family::Rect, Family::Donut, Family::Band] {
        v.push(c(f.name().into(), f, None, false, None));
    }
    for s in [Style::Blob, Style::Rectangles, Style::Snake, Style::Rooms] {
        for no_cut in [false, true] {
            let tag = if no_cut { " no_cut" } else { "" };
            v.push(c(
                format!("random-simple {s}{tag}"),
                Family::RandomSimple,
                Some(s),
                no_cut,
                None,
            ));
            v.push(c(
                format!("random-holed {s}{tag}"),
                Family::RandomHoled,
                Some(s),
                no_cut,
                Some((1, 3)),
            ));
        }
        v.push(c(
            format!("boundary {s}"),
            Family::Boundary,
            Some(s),
            false,
            None,
        ));
        v.push(c(
            format!("pinholes {s}"),
            Family::Pinholes,
            Some(s),
            false,
            Some((1, 6)),
        ));
    }
    v.push(c("thin".into(), Family::Thin, None, false, Some((0, 3))));
    v.push(c(
        "thin-arms".into(),
        Family::ThinArms,
        None,
        false,
        Some((0, 3)),
    ));
    v
}

fn params(co: &Combo, n: usize, rng: &mut ChaCha8Rng) -> GenParams {
    let seed = rng.random::<u64>();
    let mut p = GenParams::new(co.family, seed);
    match co.family {
        Family::Rect => {
            let w = rng.random_range(1..=n.isqrt().max(1));
            p.width = Some(w);
            p.height = Some((n / w).max(1));
        }
        Family::Donut => {
            let k = rng.random_range(1..=2);
            let side = (2 * k + 1..=12)
                .filter(|&l| l * l - (l - 2 * k) * (l - 2 * k) <= n)
                .max();
            p.k = Some(k);
            p.side = Some(side.unwrap_or(2 * k + 1));
        }
        Family::Band => p.k = Some(((n.saturating_sub(4)) / 5).max(1)),
        _ => {
            p.n = Some(n);
            p.style = co.style;
            p.no_cut = co.no_cut;
            p.holes = co.holes.map(|(lo, hi)| rng.random_range(lo..=hi));
            if co.family == Family::Pinholes && p.holes.is_none() {
                p.holes = Some(1);
            }
        }
    }
    p
}

/// Whether a climbed region keeps the constraint of its family.
fn keeps_constraint(co: &Combo, r: &Region, max_n: usize) -> bool {
    if r.is_empty() || r.len() > max_n || topology::components(r).count != 1 {
        return false;
    }
    match co.family {
        Family::Boundary => (0..r.len()).all(|i| topology::is_boundary(r, i)),
        Family::Thin | Family::ThinArms | Family::Thin43 => topology::is_thin(r),
        Family::RandomSimple => {
            topology::holes(r).count == 0
                && (!co.no_cut || !topology::cut_vertices(r).contains(&true))
        }
        Family::RandomHoled if co.no_cut => !topology::local_cut_vertices(r).contains(&true),
        _ => true,
    }
}

/// One random neighbour: a pixel added next to the region or removed from it.
fn mutate(r: &Region, rng: &mut ChaCha8Rng) -> Region {
    let mut set: BTreeSet<Pixel> = r.pixels().iter().copied().collect();
    if rng.random_bool(0.5) || set.len() <= 2 {
        let p = r.pixel(rng.random_range(0..r.len()));
        let q = topology::ring(p)[2 * rng.random_range(0..4usize)];
        set.insert(q);
    } else {
        let p = r.pixel(rng.random_range(0..r.len()));
        set.remove(&p);
    }
    Region::from_pixels(set)
        .expect("pixels of a region")
        .normalized()
}

/// The key the climb maximizes.
fn key(s: Score, by_ratio: bool) -> (f64, f64) {
    if by_ratio {
        (s.ratio, 0.0)
    } else {
        (s.excess as f64, s.ratio)
    }
}

fn save(out: &Option<PathBuf>, tally: &Tally, saved: &mut BTreeSet<String>) {
    let Some(dir) = out else { return };
    std::fs::create_dir_all(dir).expect("--out folder");
    for f in &tally.findings {
        let id = format!("{}\n{}", f.key, f.region.to_ascii());
        if !saved.insert(id) {
            continue;
        }
        let slug: String = f
            .key
            .split(" (")
            .next()
            .unwrap_or("")
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() || c == '-' {
                    c
                } else {
                    '_'
                }
            })
            .collect();
        let path = dir.join(format!("{slug}_{:04}.grid", saved.len()));
        let meta = [
            ("check", f.key.clone()),
            ("instance", f.label.clone()),
            ("violation", f.what.clone()),
            ("n", f.region.len().to_string()),
        ];
        GridFile::with_meta(f.region.clone(), &meta)
            .write(&path)
            .expect("write a finding");
    }
}

fn main() {
    let a = Args::parse();
    let by_ratio = a.by == "ratio";
    let opts = exact_options(a.time_limit);
    let mut rng = ChaCha8Rng::seed_from_u64(a.seed);
    let combos = combos();
    let mut tally = Tally::default();
    let mut saved = BTreeSet::new();
    // (score, combo, region) of the hardest regions, for the climb.
    let mut hardest: Vec<(Score, usize, Region)> = Vec::new();
    let mut done = vec![0usize; combos.len()];
    let start = Instant::now();
    let phases = [
        (4usize, a.max_n, a.per_combo),
        (a.max_n + 1, a.mid_n, a.mid),
    ];
    'phases: for (lo, hi, count) in phases {
        for round in 0..count {
            for (ci, co) in combos.iter().enumerate() {
                if start.elapsed().as_secs_f64() > a.budget {
                    eprintln!("budget reached in round {round} ({lo}..={hi})");
                    break 'phases;
                }
                let n = rng.random_range(lo..=hi.max(lo));
                let Ok(f) = generate(&params(co, n, &mut rng)) else {
                    continue;
                };
                if f.region.len() > hi {
                    continue;
                }
                let label = format!(
                    "{} {} seed {}",
                    co.name,
                    f.meta("params").unwrap_or(""),
                    f.meta("seed").unwrap_or("")
                );
                let opt = optima(&label, &f.region, &opts, &mut tally);
                let score = check_algorithms(&label, &f.region, &opt, &mut tally);
                done[ci] += 1;
                if hi == a.max_n {
                    hardest.push((score, ci, f.region));
                    if hardest.len() > 4 * a.starts {
                        hardest.sort_by(|x, y| {
                            key(y.0, by_ratio).partial_cmp(&key(x.0, by_ratio)).unwrap()
                        });
                        hardest.truncate(2 * a.starts);
                    }
                }
            }
            if round % 10 == 9 {
                save(&a.out, &tally, &mut saved);
                eprintln!(
                    "{:.0} s: round {} of {lo}..={hi}, {} regions, {} findings",
                    start.elapsed().as_secs_f64(),
                    round + 1,
                    done.iter().sum::<usize>(),
                    tally.findings.len()
                );
            }
        }
    }
    let random_regions: usize = done.iter().sum();
    println!(
        "== random regions: {random_regions} in {:.0} s",
        start.elapsed().as_secs_f64()
    );
    for (co, d) in combos.iter().zip(&done) {
        println!("  {:<32} {d}", co.name);
    }
    println!("{}", table(&tally));
    save(&a.out, &tally, &mut saved);
    // Hill climb: one start per combination first (the hardest of each), then the rest.
    hardest.sort_by(|x, y| {
        (y.0.excess, y.0.ratio)
            .partial_cmp(&(x.0.excess, x.0.ratio))
            .unwrap()
    });
    hardest.truncate(a.starts);
    let climb_budget = a.budget / 3.0;
    let climb_start = Instant::now();
    let mut climb_tally = Tally::default();
    let mut steps = 0;
    for (score0, ci, region0) in hardest {
        let co = &combos[ci];
        let (mut score, mut region) = (score0, region0);
        for step in 0..a.climb {
            if climb_start.elapsed().as_secs_f64() > climb_budget {
                break;
            }
            let cand = mutate(&region, &mut rng);
            if !keeps_constraint(co, &cand, a.max_n) {
                continue;
            }
            steps += 1;
            let label = format!("climb from {} step {step}", co.name);
            let opt = optima(&label, &cand, &opts, &mut climb_tally);
            let s = check_algorithms(&label, &cand, &opt, &mut climb_tally);
            if key(s, by_ratio) >= key(score, by_ratio) {
                (score, region) = (s, cand);
            }
        }
        println!(
            "climb {:<32} excess {:>2} ratio {:.3} (from {} / {:.3}) N = {}\n{}",
            co.name,
            score.excess,
            score.ratio,
            score0.excess,
            score0.ratio,
            region.len(),
            region.to_ascii()
        );
    }
    println!(
        "== hill climb: {steps} regions in {:.0} s",
        climb_start.elapsed().as_secs_f64()
    );
    println!("{}", table(&climb_tally));
    save(&a.out, &climb_tally, &mut saved);
    let unproven = tally.unproven.len() + climb_tally.unproven.len();
    println!("unproven exact solves: {unproven}");
    for u in tally.unproven.iter().chain(&climb_tally.unproven).take(20) {
        println!("  {u}");
    }
    for b in tally.bad_bounds.iter().chain(&climb_tally.bad_bounds) {
        println!("BAD BOUND {b}");
    }
    println!("findings saved: {}", saved.len());
}
