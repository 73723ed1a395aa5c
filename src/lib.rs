//! mowmill: a benchmark and experiment harness for the approximation algorithms of
//! Arkin, Fekete, Mitchell, *Approximation algorithms for lawn mowing and milling*, and
//! Arkin, Bender, Demaine, Fekete, Mitchell, Sethia, *Optimal covering tours with turn costs*.
//!
//! Data flows one way: instance file → [`Region`] → algorithm → [`CycleCover`] →
//! [`checker`] → result row → statistics → CSV and plots.

pub mod algorithms;
pub mod bounds;
pub mod checker;
pub mod draw;
pub mod error;
pub mod exact;
pub mod flow;
pub mod generate;
pub mod gridfile;
pub mod harness;
pub mod instance;
pub mod lawn_check;
pub mod region;
pub mod strip_cover;
pub mod tight;
pub mod topology;
pub mod tour;
pub mod wkt;

pub use error::{Error, Result};
pub use region::{Dir, Pixel, Region, Symmetry};
pub use tour::{CycleCover, Walk};
