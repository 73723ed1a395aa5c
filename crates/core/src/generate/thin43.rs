//! `thin43`: the 4/3 thin example of the turn-cost paper (Fig. 6, Theorem 5.9).

use crate::region::Pixel;

/// The gadgets of `thin43` with parameter s, by name (X1, Y1, R1, …, X2, X3, X4): the lattice
/// points on each gadget's polylines as reconstructed from the paper's proof (rings are closed
/// rectangles given by two corners; all vertices have even coordinates). The family's pixels are
/// their union.
pub fn thin43_gadgets(s: usize) -> Vec<(String, Vec<Pixel>)> {
    let u = 8 * s as i32;
    let ring = |a: i32, b: i32, c: i32, d: i32| vec![(a, b), (c, b), (c, d), (a, d), (a, b)];
    type Polyline = Vec<(i32, i32)>;
    let mut gadgets: Vec<(String, Vec<Polyline>)> = Vec::new();
    gadgets.push((
        "X1".into(),
        vec![ring(4, 2, 14, 10), vec![(4, 4), (6, 4), (6, 2)]],
    ));
    for j in 1..=s as i32 {
        gadgets.push((
            format!("Y{j}"),
            vec![
                ring(8 * j + 4, 0, 8 * j + 10, 14),
                vec![(8 * j + 4, 12), (8 * j + 10, 12)],
            ],
        ));
        gadgets.push((format!("R{j}"), vec![ring(8 * j + 8, 4, 8 * j + 14, 8)]));
    }
    gadgets.push((
        "X2".into(),
        vec![
            ring(u + 12, 0, u + 20, 20),
            vec![(u + 12, 18), (u + 16, 18), (u + 16, 20)],
        ],
    ));
    gadgets.push((
        "X3".into(),
        vec![
            ring(8, 16, u + 18, 24),
            vec![(u + 18, 22), (u + 16, 22), (u + 16, 24)],
        ],
    ));
    gadgets.push((
        "X4".into(),
        vec![ring(0, 6, 10, 28), vec![(10, 26), (2, 26), (2, 6)]],
    ));
    gadgets
        .into_iter()
        .map(|(name, lines)| {
            let mut pixels: Vec<Pixel> = Vec::new();
            for line in &lines {
                for w in line.windows(2) {
                    let ((x0, y0), (x1, y1)) = (w[0], w[1]);
                    let steps = (x1 - x0).abs().max((y1 - y0).abs());
                    for t in 0..=steps {
                        pixels.push(Pixel::new(
                            x0 + (x1 - x0).signum() * t,
                            y0 + (y1 - y0).signum() * t,
                        ));
                    }
                }
            }
            pixels.sort_unstable_by_key(|p| (p.y, p.x));
            pixels.dedup();
            (name, pixels)
        })
        .collect()
}

/// The pixels of `thin43` with parameter s: the union of its [gadgets](thin43_gadgets).
pub(super) fn thin43_pixels(s: usize) -> Vec<Pixel> {
    let mut pixels: Vec<Pixel> = thin43_gadgets(s).into_iter().flat_map(|(_, p)| p).collect();
    pixels.sort_unstable_by_key(|p| (p.y, p.x));
    pixels.dedup();
    pixels
}

/// Holes of `thin43` at s = 0, and per step of s (counted once, checked by every generation).
pub(super) const THIN43_HOLES_BASE: usize = 13;

pub(super) const THIN43_HOLES_STEP: usize = 5;

/// The number of holes of `thin43` with parameter s (bounded faces of its corridor network).
pub(super) fn thin43_holes(s: usize) -> usize {
    THIN43_HOLES_BASE + THIN43_HOLES_STEP * s
}
