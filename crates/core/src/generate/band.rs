//! The diagonal band B_k (`band`), the tight class of the 6/5 bound of Theorem 5 of the
//! milling paper.

use crate::region::Pixel;

/// The diagonal band B_k: (x, y) with 0 ≤ x, y ≤ k + 1 and |x − y| ≤ 2, row by row.
///
/// # Complexity
/// O(N) time and space, N = 5k + 4: each row visits only its at most five pixels, never the
/// (k + 2)² bounding box.
pub(super) fn band_pixels(k: usize) -> Vec<Pixel> {
    let m = k as i32 + 1;
    (0..=m)
        .flat_map(|y| ((y - 2).max(0)..=(y + 2).min(m)).map(move |x| Pixel::new(x, y)))
        .collect()
}
