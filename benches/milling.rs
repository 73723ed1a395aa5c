//! Speed of the min-length algorithms of *Lawn mowing and milling*, single thread:
//! pixels per second at the sizes the issue names. Run with
//! `cargo bench --bench milling` (add `-- quick` for a 10× smaller run, and algorithm names to run only those).
//!
//! Every output also goes through the checker (untimed), so a fast but wrong run fails.

use mowmill::algorithms::{self, Cutter, Options};
use mowmill::checker;
use mowmill::lawn_check;
use mowmill::region::{Pixel, Region};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// A side × side square with rectangular bites out of its border: simple, no cut vertices.
fn bitten_square(side: i32, bites: usize, seed: u64) -> Vec<Pixel> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut keep = vec![true; (side * side) as usize];
    for _ in 0..bites {
        let (w, h) = (
            rng.random_range(2..side / 20),
            rng.random_range(2..side / 20),
        );
        let (x, y) = match rng.random_range(0..4) {
            0 => (rng.random_range(0..side - w), 0),
            1 => (rng.random_range(0..side - w), side - h),
            2 => (0, rng.random_range(0..side - h)),
            _ => (side - w, rng.random_range(0..side - h)),
        };
        // Keep bites two pixels apart, so that no thin part (cut vertex) appears.
        let clear = (x - 2..x + w + 2).all(|a| {
            (y - 2..y + h + 2)
                .all(|b| a < 0 || b < 0 || a >= side || b >= side || keep[(b * side + a) as usize])
        });
        if !clear {
            continue;
        }
        for dx in 0..w {
            for dy in 0..h {
                keep[((y + dy) * side + x + dx) as usize] = false;
            }
        }
    }
    (0..side * side)
        .filter(|&k| keep[k as usize])
        .map(|k| Pixel::new(k % side, k / side))
        .collect()
}

/// `holes` square holes of side 20 on a regular grid inside the square, far apart.
fn with_holes(pixels: Vec<Pixel>, side: i32, holes: usize) -> Vec<Pixel> {
    let per_row = (holes as f64).sqrt().ceil() as i32;
    let pitch = side / (per_row + 1);
    let mut hole = std::collections::HashSet::new();
    for k in 0..holes as i32 {
        let (cx, cy) = (pitch * (1 + k % per_row), pitch * (1 + k / per_row));
        for dx in 0..20 {
            for dy in 0..20 {
                hole.insert(Pixel::new(cx + dx, cy + dy));
            }
        }
    }
    pixels.into_iter().filter(|p| !hole.contains(p)).collect()
}

/// Grass in `parts` random blobs of `size` pixels scattered over a large field.
fn scattered(parts: usize, size: usize, seed: u64) -> Vec<Pixel> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut all = std::collections::HashSet::new();
    let field = 40 * ((parts * size) as f64).sqrt() as i32;
    for _ in 0..parts {
        let (ox, oy) = (rng.random_range(0..field), rng.random_range(0..field));
        let mut blob = vec![Pixel::new(ox, oy)];
        let mut set = std::collections::HashSet::from([Pixel::new(ox, oy)]);
        while blob.len() < size {
            let p = blob[rng.random_range(0..blob.len())];
            let q = p.step(mowmill::Dir::from_index(rng.random_range(0..4)));
            if set.insert(q) {
                blob.push(q);
            }
        }
        all.extend(blob);
    }
    all.into_iter().collect()
}

/// The largest grid component of a pixel set.
fn largest_component(pixels: Vec<Pixel>) -> Region {
    let r = Region::from_pixels(pixels).expect("fits");
    let labels = mowmill::topology::components(&r);
    let mut size = vec![0usize; labels.count];
    for &l in &labels.label {
        size[l as usize] += 1;
    }
    let big = (0..labels.count).max_by_key(|&l| size[l]).unwrap_or(0) as u32;
    Region::from_pixels(
        (0..r.len())
            .filter(|&i| labels.label[i] == big)
            .map(|i| r.pixel(i)),
    )
    .expect("fits")
}

fn bench(name: &str, region: &Region, cutter: Cutter, what: &str) {
    let only: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-') && a != "quick")
        .collect();
    if !only.is_empty() && !only.iter().any(|o| o == name) {
        return;
    }
    let algo = algorithms::find(name).expect("registered");
    (algo.precondition)(region).expect("precondition");
    let opts = Options {
        cutter,
        ..Options::default()
    };
    let start = Instant::now();
    let sol = (algo.run)(region, &opts).expect("runs");
    let secs = start.elapsed().as_secs_f64();
    let cover = &sol.outputs[0].cover;
    let (valid, length) = if sol.outputs[0].objective == algorithms::Objective::LawnLength
        && cutter != Cutter::Square
    {
        let r = lawn_check::check_lawn(region, cover, cutter);
        (r.valid, r.length)
    } else {
        let r = checker::check(region, cover, sol.outputs[0].objective.mode());
        (r.valid, r.length)
    };
    let n = region.len();
    println!(
        "{name:<18} {what:<34} N = {n:>8}  {secs:>7.3} s  {:>12.0} pixels/s  length {length}{}",
        n as f64 / secs,
        if valid { "" } else { "  INVALID" }
    );
    assert!(valid, "{name} produced an invalid tour");
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    let (side, lawn_big, lawn_small) = if quick {
        (316, 10_000, 1_000)
    } else {
        (1000, 100_000, 10_000)
    };
    let square = largest_component(bitten_square(side, 200, 1));
    let cuts = mowmill::topology::cut_vertices(&square)
        .iter()
        .filter(|&&c| c)
        .count();
    bench(
        "tsp65",
        &square,
        Cutter::Square,
        &format!("bitten square, {cuts} cut vertices"),
    );
    bench("milling25", &square, Cutter::Square, "bitten square");
    let holed = largest_component(with_holes(square.pixels().to_vec(), side, 100));
    bench(
        "milling25",
        &holed,
        Cutter::Square,
        "bitten square, 100 holes",
    );
    bench(
        "holes1325",
        &holed,
        Cutter::Square,
        "bitten square, 100 holes",
    );
    let big = Region::from_pixels(scattered(50, lawn_big / 50, 2)).expect("fits");
    for cutter in [Cutter::Square, Cutter::SquareFree, Cutter::Disk] {
        bench("lawn-mst", &big, cutter, &format!("50 blobs, {cutter:?}"));
    }
    let small = Region::from_pixels(scattered(20, lawn_small / 20, 3)).expect("fits");
    bench(
        "lawn-christofides",
        &small,
        Cutter::Square,
        "20 blobs, Square",
    );
    bench("lawn-2opt", &small, Cutter::Square, "20 blobs, Square");
    bench("lawn-box", &small, Cutter::Square, "20 blobs, Square");
}
