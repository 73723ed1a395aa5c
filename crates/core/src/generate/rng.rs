//! Randomness: seed-derived ChaCha8 streams and platform-independent draws.

use rand::RngExt;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

pub type Rng = ChaCha8Rng;

pub(super) fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// An independent ChaCha8 stream for (`seed`, `tag`).
pub fn rng_for(seed: u64, tag: u64) -> Rng {
    Rng::seed_from_u64(splitmix(seed ^ splitmix(tag)))
}

/// Uniform in `0..n` (n ≥ 1), through u64 so that 32- and 64-bit machines agree.
pub fn below(rng: &mut Rng, n: usize) -> usize {
    rng.random_range(0..n as u64) as usize
}

/// Uniform in `lo..=hi` (hi ≥ lo).
pub(super) fn between(rng: &mut Rng, lo: usize, hi: usize) -> usize {
    lo + below(rng, hi - lo + 1)
}

pub fn unit(rng: &mut Rng) -> f64 {
    rng.random::<f64>()
}

pub(super) fn chance(rng: &mut Rng, p: f64) -> bool {
    unit(rng) < p
}

pub(super) fn shuffle<T>(v: &mut [T], rng: &mut Rng) {
    for i in (1..v.len()).rev() {
        v.swap(i, below(rng, i + 1));
    }
}
