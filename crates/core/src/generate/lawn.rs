//! `lawn-scattered`: grass in P components, 8-separated from one another.

use super::checks::{CutRule, Promise, verify};
use super::random_simple::simple_canvas;
use super::rng::{Rng, below, between, unit};
use super::spec::MAX_ATTEMPTS;
use super::staircase::rows_pixels;
use super::styles::ShapeOpts;
use crate::region::Pixel;
use crate::region::Region;

/// Random part sizes ≥ 1 summing to n.
pub(super) fn part_sizes(n: usize, parts: usize, rng: &mut Rng) -> Vec<usize> {
    let raw: Vec<f64> = (0..parts).map(|_| 0.15 + unit(rng)).collect();
    let sum: f64 = raw.iter().sum();
    let spare = n - parts;
    let mut sizes: Vec<usize> = raw
        .iter()
        .map(|r| 1 + (spare as f64 * r / sum) as usize)
        .collect();
    let mut rest = n - sizes.iter().sum::<usize>();
    while rest > 0 {
        let i = below(rng, parts);
        sizes[i] += 1;
        rest -= 1;
    }
    sizes
}

/// One hole-free connected part of exactly `size` pixels, translated to start at (0, 0).
pub(super) fn lawn_part(size: usize, o: &ShapeOpts, rng: &mut Rng) -> Vec<Pixel> {
    let promise = Promise {
        n: size,
        n_slack: 0,
        components: 1,
        holes: 0,
        cut: CutRule::Any,
        thin: false,
        separated: false,
        any_holes: false,
        boundary_only: false,
        even_degrees: false,
    };
    for _ in 0..MAX_ATTEMPTS {
        if let Some((c, _)) = simple_canvas(size, o, rng)
            && let Ok(region) = Region::from_pixels(c.pixels())
            && verify(&region, &promise).is_ok()
        {
            return region.normalized().pixels().to_vec();
        }
    }
    rows_pixels(size, 0, false, rng).expect("a staircase without constraints always exists")
}

/// P parts laid out on shelves with gaps of 1 to 3 empty cells, then pulled towards the
/// middle by random moves that keep every part two cells (Chebyshev) from the others.
pub(super) fn lawn_pixels(n: usize, parts: usize, o: &ShapeOpts, rng: &mut Rng) -> Vec<Pixel> {
    let sizes = part_sizes(n, parts, rng);
    let shapes: Vec<Vec<Pixel>> = sizes.iter().map(|&s| lawn_part(s, o, rng)).collect();
    let dims: Vec<(i64, i64)> = shapes
        .iter()
        .map(|s| {
            let w = s.iter().map(|p| p.x).max().unwrap_or(0) as i64 + 1;
            let h = s.iter().map(|p| p.y).max().unwrap_or(0) as i64 + 1;
            (w, h)
        })
        .collect();
    // Shelves.
    let footprint: i64 = dims.iter().map(|&(w, h)| (w + 2) * (h + 2)).sum();
    let widest = dims.iter().map(|d| d.0).max().unwrap_or(1);
    let limit = widest.max(((footprint as f64).sqrt() * (1.0 + 0.6 * unit(rng))) as i64);
    let mut pos = Vec::with_capacity(parts);
    let (mut x, mut y, mut row_h) = (0i64, 0i64, 0i64);
    for &(w, h) in &dims {
        if x > 0 && x + w > limit {
            y += row_h + between(rng, 1, 3) as i64;
            (x, row_h) = (0, 0);
        }
        let dy = below(rng, 3) as i64;
        pos.push((x, y + dy));
        x += w + between(rng, 1, 3) as i64;
        row_h = row_h.max(h + dy);
    }
    let width = pos
        .iter()
        .zip(&dims)
        .map(|(p, d)| p.0 + d.0)
        .max()
        .unwrap_or(1);
    let height = pos
        .iter()
        .zip(&dims)
        .map(|(p, d)| p.1 + d.1)
        .max()
        .unwrap_or(1);
    // Owner grid with a frame of 1, for the separation test.
    let gw = (width + 2) as usize;
    let gh = (height + 2) as usize;
    let mut owner = vec![u32::MAX; gw * gh];
    let cell = |x: i64, y: i64| (y + 1) as usize * gw + (x + 1) as usize;
    for (i, s) in shapes.iter().enumerate() {
        for p in s {
            owner[cell(pos[i].0 + i64::from(p.x), pos[i].1 + i64::from(p.y))] = i as u32;
        }
    }
    // Compaction, with a work budget linear in n.
    let mut budget = 8 * n as i64 + 1000;
    let (cx, cy) = (width / 2, height / 2);
    while budget > 0 && parts > 1 {
        let i = below(rng, parts);
        let (w, h) = dims[i];
        let (dx, dy) = (
            between(rng, 0, w as usize) as i64 - w / 2,
            between(rng, 0, h as usize) as i64 - h / 2,
        );
        let (nx, ny) = (pos[i].0 + dx, pos[i].1 + dy);
        let centre = |x: i64, y: i64| (x + w / 2 - cx).abs() + (y + h / 2 - cy).abs();
        budget -= 1;
        if nx < 0
            || ny < 0
            || nx + w > width
            || ny + h > height
            || centre(nx, ny) >= centre(pos[i].0, pos[i].1)
        {
            continue;
        }
        let mut ok = true;
        for p in &shapes[i] {
            budget -= 1;
            let (px, py) = (nx + i64::from(p.x), ny + i64::from(p.y));
            if (py - 1..=py + 1).any(|qy| {
                (px - 1..=px + 1).any(|qx| {
                    qx >= -1 && qy >= -1 && qx <= width && qy <= height && {
                        let o = owner[cell(qx, qy)];
                        o != u32::MAX && o != i as u32
                    }
                })
            }) {
                ok = false;
                break;
            }
        }
        if !ok {
            continue;
        }
        for p in &shapes[i] {
            owner[cell(pos[i].0 + i64::from(p.x), pos[i].1 + i64::from(p.y))] = u32::MAX;
        }
        pos[i] = (nx, ny);
        for p in &shapes[i] {
            owner[cell(nx + i64::from(p.x), ny + i64::from(p.y))] = i as u32;
        }
        budget -= shapes[i].len() as i64;
    }
    shapes
        .iter()
        .zip(&pos)
        .flat_map(|(s, &(px, py))| {
            s.iter()
                .map(move |p| Pixel::new(p.x + px as i32, p.y + py as i32))
        })
        .collect()
}
