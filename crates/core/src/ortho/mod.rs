//! Milling orthogonal polygons with arbitrary (non-integral) coordinates by a unit square
//! cutter: exact input, an exact checker, and the feasibility test. The foundation for
//! Corollary 4 of *Lawn mowing and milling* and Theorem 5.7 of *Optimal covering tours with
//! turn costs*.
//!
//! - [`Rational`]: exact coordinates (`i128` over `i128`, checked arithmetic, exact order).
//! - [`Polygon`]: WKT `POLYGON` / `MULTIPOLYGON` with holes, axis-parallel edges and decimal or
//!   `p/q` coordinates, read exactly by the crate's one WKT reader ([`crate::wkt`]).
//! - [`Tour`]: closed rectilinear walks of the cutter's centre, in JSON with exact numbers.
//! - [`check`]: whether the swept area equals the polygon (up to measure zero), decided
//!   exactly, with length and turns recounted; on integral inputs it agrees with the pixel
//!   checker [`crate::checker::check`] (tests/ortho.rs).
//! - [`feasibility`]: whether the polygon can be milled at all, the [`Erosion`] (the centre
//!   positions, B in the paper) and its contour δB; [`interior_pixels`], the integer pixels
//!   inside (R_N in Corollary 4's proof).
//!
//! Conventions: the cutter is the axis-parallel unit square centred on the walk; pixel (x, y)
//! of a [`Region`](crate::Region) is the unit square [x, x+1] × [y, y+1], its centre
//! (x + ½, y + ½) ([`Polygon::from_region`], [`Tour::from_cover`]).
//!
//! This is the model; the algorithms (`corollary4`, milling length, and `strips-contour` /
//! `star-contour`, our reading of Theorem 5.7 of *Optimal covering tours with turn costs*:
//! turns) are in `mowmill_algorithms::ortho`, the figures in `mowmill::ortho`, and all are
//! gathered under `mowmill::ortho`. docs/ortho.md has the file formats, the checker's argument
//! and the limits.

mod check;
// The erosion's face structure is drawn by `mowmill::ortho`'s figures.
#[doc(hidden)]
pub mod cover;
#[doc(hidden)]
pub mod erosion;
mod generate;
mod polygon;
mod rational;
mod tour;
mod turn_bound;

#[doc(hidden)]
pub use check::heading;
pub use check::{Report, Violation, check, turn_cost};
#[doc(hidden)]
pub use erosion::kept_interior_pixels;
pub use erosion::{Erosion, Infeasible, feasibility, interior_pixels};
pub use generate::{FAMILIES, generate};
#[doc(hidden)]
pub use polygon::lcm;
pub use polygon::{MAX_VERTICES, Point, Polygon, Ring};
pub use rational::{MAX_DENOMINATOR, MAX_MAGNITUDE, Rational};
pub use tour::{MAX_TOUR_POINTS, Tour};
pub use turn_bound::{TurnBound, turn_lower_bound};
