//! `mowmill gen`: one instance of a family, deterministically.

use anyhow::Result;
use clap::Args;
use mowmill::generate::{self, Family, GenParams, Style};
use mowmill::topology;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct GenArgs {
    /// Family: rect, random-simple, random-holed, thin, lawn-scattered, donut, band, thin43,
    /// boundary, thin-arms, pinholes.
    pub family: Family,
    /// Number of pixels.
    #[arg(long)]
    pub n: Option<usize>,
    /// Number of holes.
    #[arg(long)]
    pub holes: Option<usize>,
    /// Width (rect).
    #[arg(long)]
    pub width: Option<usize>,
    /// Height (rect).
    #[arg(long)]
    pub height: Option<usize>,
    /// Width of the annulus (donut), or the index of the band B_k (band).
    #[arg(long)]
    pub k: Option<usize>,
    /// Outer side (donut).
    #[arg(long)]
    pub side: Option<usize>,
    /// Parameter s of the 4/3 thin example (thin43).
    #[arg(long)]
    pub s: Option<usize>,
    /// Number of grass components (lawn-scattered).
    #[arg(long)]
    pub parts: Option<usize>,
    /// Shape style of random families: mixed (default), blob, rectangles, snake, rooms.
    #[arg(long)]
    pub style: Option<Style>,
    /// Compactness of blob growth in [0, 1] (1 round, 0 ragged).
    #[arg(long)]
    pub compactness: Option<f64>,
    /// No cut vertices (random-simple) or no local cut vertices (random-holed).
    #[arg(long)]
    pub no_cut: bool,
    /// Seed of the portable ChaCha generator.
    #[arg(long)]
    pub seed: u64,
    /// Output .grid file.
    #[arg(long)]
    pub out: PathBuf,
}

pub fn gen_command(a: GenArgs) -> Result<ExitCode> {
    let params = GenParams {
        family: a.family,
        n: a.n,
        holes: a.holes,
        width: a.width,
        height: a.height,
        k: a.k,
        side: a.side,
        parts: a.parts,
        no_cut: a.no_cut,
        style: a.style,
        compactness: a.compactness,
        s: a.s,
        seed: a.seed,
    };
    let file = generate::generate(&params)?;
    file.write(&a.out)?;
    eprintln!(
        "wrote {}: {} pixels, {} holes",
        a.out.display(),
        file.region.len(),
        topology::holes(&file.region).count
    );
    Ok(ExitCode::SUCCESS)
}
