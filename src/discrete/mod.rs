//! Discrete milling (Section 2.1 of *Optimal covering tours with turn costs*), gathered in one
//! place: the model of the core (`mowmill_core::discrete`: instances, formats, generators,
//! lattices, channels and the one checker), the algorithms (`mowmill_algorithms::discrete`:
//! the star cover and the merge), the exact models (`mowmill_exact::discrete`, as [`exact`]),
//! the study of the star cover's rook orders ([`choices`], which needs the exact solver) and
//! the figures ([`draw`]).

pub mod choices;
pub mod draw;

pub use mowmill_algorithms::discrete::*;
pub use mowmill_exact::discrete as exact;
