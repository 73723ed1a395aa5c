//! Milling orthogonal polygons with arbitrary (non-integral) coordinates by a unit square
//! cutter, gathered in one place: the model of the core (`mowmill_core::ortho`: exact
//! coordinates, WKT input, tours, the exact checker, the erosion and the turn bound), the
//! algorithms (`mowmill_algorithms::ortho`: Corollary 4 of *Lawn mowing and milling*, our
//! reading of Theorem 5.7 of *Optimal covering tours with turn costs*) and the figures
//! ([`draw`], [`draw_svg`], drawn here with plotters). docs/ortho.md has the file formats, the
//! checker's argument and the limits.

mod draw;

pub use draw::{draw, draw_svg, figure_caption};
pub use mowmill_algorithms::ortho::*;
