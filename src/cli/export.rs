//! `mowmill export`: an instance in another program's format (TSPLIB for Concorde and LKH, a
//! pixel list, WKT, `.grid`).

use anyhow::Result;
use clap::{Args, ValueEnum};
use mowmill::error::Error;
use mowmill::gridfile::GridFile;
use mowmill::instance::Instance;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct ExportArgs {
    /// Instance file (.grid, WKT, .poly or a .gg/.csv pixel list).
    pub file: PathBuf,
    /// Output format: tsplib (MAN_2D instance of the pixels), gg (pixel list "x y", y up), wkt
    /// (POLYGON/MULTIPOLYGON of the union of the pixels), grid (moved to non-negative
    /// coordinates), or dm / dm-json (the region as a discrete-milling instance, its grid
    /// graph with the east-west and north-south pairs collinear; vertex i is pixel i).
    #[arg(long, value_enum)]
    pub format: ExportFormat,
    /// Write here instead of to standard output.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum ExportFormat {
    Tsplib,
    Gg,
    Wkt,
    Grid,
    Dm,
    DmJson,
}

pub fn export_command(a: ExportArgs) -> Result<ExitCode> {
    let inst = Instance::read(&a.file)?;
    let text = match a.format {
        ExportFormat::Tsplib => mowmill::tsplib::to_tsplib(&inst.region, &inst.name),
        ExportFormat::Gg => mowmill::pixel_list::to_pixel_list(&inst.region),
        ExportFormat::Wkt => mowmill::wkt::to_wkt(&inst.region) + "\n",
        ExportFormat::Dm => mowmill::discrete::format::to_text(
            &mowmill::discrete::Discrete::from_region(&inst.region),
        ),
        ExportFormat::DmJson => mowmill::discrete::format::to_json(
            &mowmill::discrete::Discrete::from_region(&inst.region),
        ),
        // .grid rows start at x = 0 and end at y = 0, so a region reaching below either is
        // moved up and right; its metadata comments come along.
        ExportFormat::Grid => GridFile {
            comments: inst
                .meta
                .iter()
                .map(|(k, v)| format!(" {k}: {v}"))
                .collect(),
            region: inst.region.normalized(),
        }
        .to_text()?,
    };
    match &a.out {
        Some(path) => {
            std::fs::write(path, text).map_err(|e| Error::io(path, e))?;
            eprintln!("wrote {}", path.display());
        }
        None => std::io::stdout().lock().write_all(text.as_bytes())?,
    }
    Ok(ExitCode::SUCCESS)
}
