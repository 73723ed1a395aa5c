//! The algorithms of E. M. Arkin, M. A. Bender, E. D. Demaine, S. P. Fekete, J. S. B. Mitchell,
//! S. Sethia, *Optimal covering tours with turn costs*, one file per theorem: merging a cycle
//! cover into a tour (`merge`, Theorem 4.2), the boundary cycle cover (`boundary_cc`, Theorem
//! 4.1), star covers (`star_cover`, Theorem 5.1), doubled strips (`strips_double`, Theorem 5.4),
//! the strips matching (`strips_matching`, Theorem 5.5), the coverage-4 rewriting (`coverage4`,
//! Theorem 5.6), thin Eulerian pockets (`thin_euler`, Theorem 5.8) and thin pockets (`thin`,
//! Corollary 5.3 and Theorem 5.9). The endpoint matching they share is in
//! [`matching`](super::matching).

// `pub` only where algorithms/mod.rs re-exports a module for the integration tests.
pub mod boundary_cc;
pub mod coverage4;
pub mod lp_lns;
pub mod merge;
pub(crate) mod star_cover;
pub(crate) mod strips_double;
pub mod strips_matching;
pub(crate) mod thin;
pub(crate) mod thin_euler;
pub(crate) mod visits;
