//! mowmill's core: what every other layer reads and nothing in it reads back. A grid
//! [`Region`] and the facts about it ([`topology`], [`strip_cover`]); its readers and writers
//! ([`instance`], [`gridfile`], [`wkt`], [`pixel_list`], [`tsplib`]); the instance families
//! ([`generate`]); walks and cycle covers ([`tour`]); and the independent checkers that recount
//! a walk ([`checker`], [`lawn_check`]); with them the cheap proven lower bounds ([`bounds`])
//! and the two graph routines every layer shares: Euler circuits ([`euler`]) and maximum flow
//! ([`flow`]). It has no algorithm, no exact model and no HiGHS: a
//! change to a checker rebuilds this crate and its tests alone (`cargo test -p mowmill-core`).
//! The `mowmill` crate re-exports every module under the same name.

pub mod bounds;
pub mod checker;
pub mod discrete;
pub mod error;
pub mod euler;
pub mod flow;
pub mod generate;
pub mod gridfile;
pub mod input;
pub mod instance;
pub mod lawn_check;
pub mod objective;
pub mod ortho;
pub mod pixel_list;
pub mod region;
pub mod strip_cover;
pub mod topology;
pub mod tour;
pub mod tsplib;
pub mod wkt;

pub use error::{Error, Result};
pub use region::{Dir, Pixel, Region, Symmetry};
pub use tour::{CycleCover, Walk};
