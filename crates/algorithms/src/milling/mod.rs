//! The milling algorithms of E. M. Arkin, S. P. Fekete, J. S. B. Mitchell, *Approximation
//! algorithms for lawn mowing and milling*: the contour walk they all start from, the
//! 2.5-approximation (Theorem 4 / Section 4), the 6/5 tour of simple grid graphs without cut
//! vertices (Theorem 5) and the 1.325 tour with holes (Theorem 7).

pub(crate) mod contour;
pub mod holes1325;
pub mod milling25;
pub mod tsp65;
pub mod two_opt;
