//! mowmill: a benchmark and experiment harness for the approximation algorithms of
//! Arkin, Fekete, Mitchell, *Approximation algorithms for lawn mowing and milling*, and
//! Arkin, Bender, Demaine, Fekete, Mitchell, Sethia, *Optimal covering tours with turn costs*.
//!
//! Data flows one way: instance file → [`Region`] → algorithm → [`CycleCover`] →
//! [`checker`] → result row → statistics → CSV and plots. [`evaluate`] is the one place that
//! runs an algorithm and judges its output; the command line, the benchmark runner and the
//! tight families all call it.
//!
//! This crate is the top of a workspace of four (docs/layout.md): the science core
//! `mowmill-core` (the three models: regions, discrete instances, orthogonal polygons; readers,
//! families, walks, checkers, bounds), the exact models `mowmill-exact` (the only crate that
//! links HiGHS) and the algorithms `mowmill-algorithms` sit below it and cannot reach up; their
//! modules are re-exported here under the paths below.
//!
//! # Public surface
//!
//! Only what a library user (and the `mowmill` binary, the tests, examples and benches) needs:
//!
//! - [`region`]: the pixel set [`Region`], with [`Pixel`], [`Dir`] and [`Symmetry`].
//! - [`instance`], [`gridfile`], [`wkt`], [`pixel_list`]: reading regions (`.grid` text, WKT,
//!   `.poly` rings, pixel lists) and writing them back ([`gridfile::GridFile`],
//!   [`wkt::to_wkt`], [`pixel_list::to_pixel_list`]); [`tsplib`]: the pixels as a TSPLIB
//!   instance for Concorde or LKH.
//! - [`generate`]: deterministic instance families ([`generate::generate`]).
//! - [`tour`]: closed walks and cycle covers ([`CycleCover`], [`Walk`]) and tour files.
//! - [`algorithms`]: the one registry ([`algorithms::REGISTRY`], [`algorithms::find`]), what its
//!   entries declare (objectives, guarantees, options) and [`algorithms::theorems`], the papers'
//!   theorems they claim. The algorithms themselves are run through [`evaluate`].
//! - [`evaluate`]: run a registered or outside algorithm and judge its outputs.
//! - [`checker`], [`lawn_check`]: the independent checkers of milling and lawn-mowing walks.
//! - [`exact`]: exact optima by integer programming and their lower bounds; [`bounds`]: the
//!   cheap proven lower bounds.
//! - [`topology`], [`strip_cover`]: facts about a region (components, holes, cut vertices,
//!   strips, the minimum strip cover).
//! - [`outside`]: programs in any language run as algorithms.
//! - [`draw`]: SVG and PNG pictures of a region and its walks.
//! - [`tight`]: the papers' tight families, measured.
//! - [`harness`]: the benchmark runner, its statistics, plots and regression gate.
//! - [`error`]: the library's [`Error`] type.
//!
//! A few algorithm internals that the integration tests drive directly (the boundary cycle
//! cover, the endpoint matching, turn distances, cycle merging, the coverage-4 rewrite) are
//! public but hidden from the documentation; they are not part of the supported surface.
//!
//! # Example
//!
//! Read a region, run a registered algorithm through the evaluation pipeline, and look at the
//! checker's recount and the guarantee's verdict:
//!
//! ```
//! use mowmill::algorithms::{self, Objective, Options};
//! use mowmill::evaluate::{evaluate, Reference, Subject};
//! use mowmill::gridfile::GridFile;
//!
//! let file = GridFile::parse("####\n####\n###.\n", "example.grid")?;
//! let tsp65 = algorithms::find("tsp65").expect("registered");
//! let eval = evaluate(
//!     Subject::Registered(tsp65),
//!     &file.region,
//!     &Options::default(),
//!     &[Objective::Length],
//!     &Reference::default(),
//! );
//! let tour = eval.output(Objective::Length).expect("tsp65 reports a length tour");
//! assert!(tour.valid);
//! // Theorem 5 of the milling paper: length <= (6N - 4)/5, decided against N.
//! assert_eq!(tour.within_guarantee, Some(true));
//! // The checker is independent of the algorithm: recount the walk directly.
//! let report = mowmill::checker::check(&file.region, &tour.cover, mowmill::checker::Mode::Milling);
//! assert_eq!(report.length, tour.length);
//! # Ok::<(), mowmill::Error>(())
//! ```

pub mod claims;
pub mod discrete;
pub mod draw;
pub mod evaluate;
pub mod harness;
pub mod hunt;
pub mod model;
pub mod ortho;
pub mod outside;
pub mod report;
pub mod tight;
pub mod warm_start;

pub use error::{Error, Result};
/// The algorithms with their theorems and the registry's list (their own crate,
/// `mowmill-algorithms`: the core and the exact crate's LP layer, no harness).
pub use mowmill_algorithms as algorithms;
pub use mowmill_core::{
    bounds, checker, error, generate, gridfile, input, instance, lawn_check, objective, pixel_list,
    region, strip_cover, topology, tour, tsplib, wkt,
};
/// The exact models (their own crate, `mowmill-exact`: HiGHS and the core, no algorithm).
pub use mowmill_exact as exact;
pub use region::{Dir, Pixel, Region, Symmetry};
pub use tour::{CycleCover, Walk};
