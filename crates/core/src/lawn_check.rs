//! The independent checker for lawn-mowing tours with free motion (milling paper, Section 4).
//!
//! A lawn tour is a closed polygonal path through lattice points, stored as a
//! [`CycleCover`] whose "pixels" are lattice coordinates:
//!
//! - square lattice (`Cutter::Square`, `Cutter::SquareFree`): point (x, y) is the centre of
//!   pixel (x, y); its cell is that pixel;
//! - hexagonal lattice (`Cutter::Disk`): point (q, r) (axial coordinates) is the centre
//!   (1.5 q, √3 (r + q / 2)) of a flat-topped regular hexagon of circumradius 1 (diameter 2);
//!   neighbouring centres are √3 apart, and the unit disk at a centre contains its hexagon.
//!
//! The check recounts the length in the motion's metric from the points (L1 for the square
//! with rectilinear motion, Euclidean otherwise) and verifies that every lattice cell whose
//! interior meets the grass (the region's pixels) has its centre on the tour: the cutter
//! placed there mows the whole cell, so the tour is feasible (Lemma 1).
//!
//! Lengths in result tables are integers: L1 lengths are exact; Euclidean lengths are
//! reported in milli-units rounded up, `length_milli = ⌈1000 · L⌉`.

use crate::region::{Pixel, Region};
use crate::tour::CycleCover;
use serde::Serialize;
use std::collections::HashSet;

/// Cutter and motion for lawn mowing (milling paper, Section 4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cutter {
    /// Unit square, rectilinear motion (L1 lengths).
    #[default]
    Square,
    /// Unit square, free motion (the grid with diagonals).
    SquareFree,
    /// Unit disk (hexagonal lattice).
    Disk,
}

impl Cutter {
    pub const NAMES: [&'static str; 3] = ["square", "square-free", "disk"];
}

impl std::fmt::Display for Cutter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Cutter::Square => "square",
            Cutter::SquareFree => "square-free",
            Cutter::Disk => "disk",
        })
    }
}

impl std::str::FromStr for Cutter {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Cutter, String> {
        match s {
            "square" => Ok(Cutter::Square),
            "square-free" => Ok(Cutter::SquareFree),
            "disk" => Ok(Cutter::Disk),
            _ => Err(format!(
                "unknown cutter {s:?}: expected square, square-free or disk"
            )),
        }
    }
}

const SQRT3: f64 = 1.732_050_807_568_877_2;

/// What the lawn check recounted.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LawnReport {
    pub valid: bool,
    /// Exact L1 length for rectilinear motion; ⌈1000 · Euclidean length⌉ otherwise.
    pub length: u64,
    /// The length as a float, in units of the pixel side.
    pub length_units: f64,
    pub cycles: usize,
    /// Number of lattice cells that meet the grass.
    pub required: usize,
    pub error: Option<String>,
}

/// Whether lengths are reported in milli-units (Euclidean motion).
pub fn is_milli(cutter: Cutter) -> bool {
    cutter != Cutter::Square
}

/// Real coordinates of a lattice point (pixel-corner coordinates, x right, y up).
pub fn centre(cutter: Cutter, p: Pixel) -> (f64, f64) {
    match cutter {
        Cutter::Square | Cutter::SquareFree => (f64::from(p.x) + 0.5, f64::from(p.y) + 0.5),
        Cutter::Disk => (
            1.5 * f64::from(p.x),
            SQRT3 * (f64::from(p.y) + f64::from(p.x) / 2.0),
        ),
    }
}

/// The distance between two lattice points in the motion's metric, in units.
pub fn distance(cutter: Cutter, a: Pixel, b: Pixel) -> f64 {
    // In i64: a difference of two i32 coordinates may not fit an i32.
    let delta = |a: i32, b: i32| (i64::from(b) - i64::from(a)) as f64;
    let (dx, dy) = (delta(a.x, b.x), delta(a.y, b.y));
    match cutter {
        Cutter::Square => dx.abs() + dy.abs(),
        Cutter::SquareFree => (dx * dx + dy * dy).sqrt(),
        Cutter::Disk => (3.0 * (dx * dx + dx * dy + dy * dy)).sqrt(),
    }
}

/// The lattice cells (as lattice points) whose interiors meet the grass, sorted.
///
/// # Complexity
/// O(N) for the square lattice; O(N) with a constant of about 10 hexagon tests per pixel for
/// the hexagonal one.
pub fn required_cells(region: &Region, cutter: Cutter) -> Vec<Pixel> {
    match cutter {
        Cutter::Square | Cutter::SquareFree => region.pixels().to_vec(),
        Cutter::Disk => {
            let mut cells = HashSet::new();
            for &p in region.pixels() {
                let (x0, y0) = (f64::from(p.x), f64::from(p.y));
                let q_lo = ((x0 - 1.0) / 1.5).floor() as i32;
                let q_hi = ((x0 + 2.0) / 1.5).ceil() as i32;
                for q in q_lo..=q_hi {
                    let base = f64::from(q) / 2.0;
                    let r_lo = ((y0 - 1.0) / SQRT3 - base).floor() as i32;
                    let r_hi = ((y0 + 2.0) / SQRT3 - base).ceil() as i32;
                    for r in r_lo..=r_hi {
                        let c = Pixel::new(q, r);
                        if hexagon_meets_pixel(centre(Cutter::Disk, c), p) {
                            cells.insert(c);
                        }
                    }
                }
            }
            let mut v: Vec<Pixel> = cells.into_iter().collect();
            v.sort_unstable_by_key(|p| (p.y, p.x));
            v
        }
    }
}

/// Whether the open flat-topped hexagon of circumradius 1 centred at `c` meets the open pixel
/// `p` (separating axis theorem on the pixel's and the hexagon's edge normals).
fn hexagon_meets_pixel(c: (f64, f64), p: Pixel) -> bool {
    const EPS: f64 = 1e-9;
    let hex: Vec<(f64, f64)> = (0..6)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_3 * f64::from(k);
            (c.0 + a.cos(), c.1 + a.sin())
        })
        .collect();
    let (x0, y0) = (f64::from(p.x), f64::from(p.y));
    let square = [
        (x0, y0),
        (x0 + 1.0, y0),
        (x0 + 1.0, y0 + 1.0),
        (x0, y0 + 1.0),
    ];
    let s3 = SQRT3 / 2.0;
    let axes = [(1.0, 0.0), (0.0, 1.0), (s3, 0.5), (s3, -0.5)];
    axes.iter().all(|&(ax, ay)| {
        let proj = |pts: &[(f64, f64)]| {
            pts.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(x, y)| {
                    let v = x * ax + y * ay;
                    (lo.min(v), hi.max(v))
                })
        };
        let (a0, a1) = proj(&hex);
        let (b0, b1) = proj(&square);
        a0 < b1 - EPS && b0 < a1 - EPS
    })
}

/// Checks a lawn tour for `cutter` against the grass `region` and recounts its length.
///
/// # Complexity
/// O(N + tour length) (times the hexagon tests for the disk).
pub fn check_lawn(region: &Region, cover: &CycleCover, cutter: Cutter) -> LawnReport {
    let required = required_cells(region, cutter);
    let mut report = LawnReport {
        valid: false,
        length: 0,
        length_units: 0.0,
        cycles: cover.cycles.len(),
        required: required.len(),
        error: None,
    };
    if cover.cycles.is_empty() {
        report.error = Some("the cover has no closed walk".into());
        return report;
    }
    let mut visited = HashSet::new();
    let mut l1: u64 = 0;
    let mut l2 = 0.0;
    for (c, walk) in cover.cycles.iter().enumerate() {
        if walk.is_empty() {
            report.error = Some(format!("cycle {c} is empty"));
            return report;
        }
        for k in 0..walk.len() {
            let (a, b) = (walk[k], walk[(k + 1) % walk.len()]);
            l1 += a.l1(b);
            l2 += distance(cutter, a, b);
            visited.insert(a);
        }
    }
    report.length_units = if cutter == Cutter::Square {
        l1 as f64
    } else {
        l2
    };
    report.length = if cutter == Cutter::Square {
        l1
    } else {
        (1000.0 * l2 - 1e-6).ceil().max(0.0) as u64
    };
    let missing: Vec<&Pixel> = required.iter().filter(|p| !visited.contains(p)).collect();
    if let Some(first) = missing.first() {
        report.error = Some(format!(
            "lattice cell {first} meets the grass but is not visited ({} in all)",
            missing.len()
        ));
        return report;
    }
    report.valid = true;
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_pixel_meets_few_hexagons() {
        let r = Region::rectangle(1, 1);
        let cells = required_cells(&r, Cutter::Disk);
        // A unit square meets between 2 and 4 hexagons of diameter 2.
        assert!((2..=4).contains(&cells.len()), "{cells:?}");
        // Every required cell's centre is within distance 1 + √2/2 of the pixel centre.
        for c in &cells {
            let (x, y) = centre(Cutter::Disk, *c);
            assert!(((x - 0.5).powi(2) + (y - 0.5).powi(2)).sqrt() < 1.0 + 0.71);
        }
    }

    #[test]
    fn lengths_per_metric() {
        let a = Pixel::new(0, 0);
        let b = Pixel::new(3, 4);
        assert_eq!(distance(Cutter::Square, a, b), 7.0);
        assert_eq!(distance(Cutter::SquareFree, a, b), 5.0);
        // Axial neighbours are √3 apart.
        assert!((distance(Cutter::Disk, a, Pixel::new(1, 0)) - SQRT3).abs() < 1e-12);
        assert!((distance(Cutter::Disk, a, Pixel::new(1, -1)) - SQRT3).abs() < 1e-12);
    }

    #[test]
    fn free_motion_tour_is_checked() {
        let r = Region::from_ascii("#.#\n");
        let tour = CycleCover::tour(vec![Pixel::new(0, 0), Pixel::new(2, 0)]);
        let rep = check_lawn(&r, &tour, Cutter::SquareFree);
        assert!(rep.valid);
        assert_eq!(rep.length, 4000);
        let short = CycleCover::tour(vec![Pixel::new(0, 0)]);
        assert!(!check_lawn(&r, &short, Cutter::SquareFree).valid);
    }
}
