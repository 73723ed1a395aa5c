use crate::region::Pixel;

/// The diagonal band B_k: (x, y) with 0 ≤ x, y ≤ k + 1 and |x − y| ≤ 2.
pub(super) fn band_pixels(k: usize) -> Vec<Pixel> {
    let m = k as i32 + 1;
    (0..=m)
        .flat_map(|y| (0..=m).map(move |x| Pixel::new(x, y)))
        .filter(|p| (p.x - p.y).abs() <= 2)
        .collect()
}
