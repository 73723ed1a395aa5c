//! `mowmill tight` and `mowmill claims`: the tight families and the claims table.

use anyhow::Result;
use clap::Args;
use mowmill::error::Error;
use mowmill::harness;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Args)]
pub struct TightArgs {
    /// Output directory: tight.csv, tight.md, claims.csv, claims.md, figures/. Default: a new
    /// results/tight-<run-id>/ (git-ignored); the committed results/tight is written only when
    /// named here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Results directory for the claims table (skipped with a note if it has no results.csv).
    #[arg(long, default_value = "results/default")]
    pub from: PathBuf,
    /// Small ranges (donut k = 2..4, band k = 1..6, thin43 s = 0..2) for a quick look.
    #[arg(long)]
    pub quick: bool,
    /// Time limit of each exact solve, in seconds.
    #[arg(long, default_value_t = 120.0, allow_negative_numbers = true)]
    pub time_limit: f64,
    /// Skip the figures.
    #[arg(long)]
    pub no_figures: bool,
}

pub fn tight_command(a: TightArgs) -> Result<ExitCode> {
    use mowmill::tight;
    super::check_seconds("--time-limit", a.time_limit)?;
    let mut opts = tight::TightOptions {
        time_limit: a.time_limit,
        ..tight::TightOptions::default()
    };
    if a.quick {
        opts.donut_k = (2..=4).collect();
        opts.band_k = (1..=6).collect();
        opts.thin43_s = (0..=2).collect();
    }
    // A fresh folder per run, so that a run never overwrites committed results by default.
    let out = a.out.clone().unwrap_or_else(|| {
        let stamp = harness::manifest::now().replace([':', '-'], "");
        PathBuf::from("results").join(format!("tight-{stamp}"))
    });
    std::fs::create_dir_all(&out).map_err(|e| Error::io(&out, e))?;
    let started = std::time::Instant::now();
    let run = tight::run(&opts)?;
    let csv = out.join("tight.csv");
    tight::write_csv(&run, &csv)?;
    let md = tight::markdown(&run);
    let md_path = out.join("tight.md");
    std::fs::write(&md_path, &md).map_err(|e| Error::io(&md_path, e))?;
    println!("{md}");
    if !a.no_figures {
        tight::figures::draw_all(&run, &out)?;
    }
    let tight_rows: Vec<tight::TightRow> = run.rows().cloned().collect();
    let results = a.from.join("results.csv");
    if results.exists() {
        let rows = harness::rows::read_rows(&results)?;
        let mut table = mowmill::claims::table(&rows, &tight_rows);
        add_hunts(&mut table, Path::new("results/hunt"))?;
        write_claims(&table, &a.from, &out)?;
    } else {
        eprintln!(
            "no {}: the claims table is skipped (run `mowmill bench --out {}` first)",
            results.display(),
            a.from.display()
        );
    }
    let bad = run.contradictions();
    eprintln!(
        "tight: {} rows in {:.1} s; wrote {} and {}",
        run.rows().count(),
        started.elapsed().as_secs_f64(),
        csv.display(),
        md_path.display()
    );
    for r in &bad {
        eprintln!(
            "CONTRADICTED: {} {} {}: claimed {}, measured {:?} ({})",
            r.family, r.member, r.quantity, r.claim, r.measured, r.how
        );
    }
    Ok(if bad.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// Fills the claims table's column "worst found by search" from `dir/summary.csv` (a hunt
/// suite), or says why it stays empty.
fn add_hunts(table: &mut [mowmill::claims::ClaimRow], dir: &Path) -> Result<()> {
    let summary = dir.join("summary.csv");
    if summary.exists() {
        let hunts = mowmill::claims::read_hunts(&summary)?;
        mowmill::claims::add_hunts(table, &hunts);
    } else {
        eprintln!(
            "no {}: the column \"worst found by search\" stays empty (run `mowmill hunt --suite \
             experiments/hunt/suite.toml --out {}`)",
            summary.display(),
            dir.display()
        );
    }
    Ok(())
}

/// Writes claims.csv and claims.md into `out`, prints the table; returns the contradictions.
pub fn write_claims(table: &[mowmill::claims::ClaimRow], from: &Path, out: &Path) -> Result<usize> {
    use mowmill::claims;
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    claims::write_csv(table, &out.join("claims.csv"))?;
    let md = claims::markdown(table, &from.display().to_string());
    let path = out.join("claims.md");
    std::fs::write(&path, &md).map_err(|e| Error::io(&path, e))?;
    println!("{md}");
    let findings = out.join("findings.md");
    std::fs::write(&findings, claims::findings_markdown(table))
        .map_err(|e| Error::io(&findings, e))?;
    Ok(table.iter().filter(|c| claims::is_violated(c)).count())
}

/// Exits 1 when any claim is violated (the table says whether by the paper's algorithm or by
/// our reading of it).
pub fn claims_command(
    from: &[PathBuf],
    tight: &Path,
    hunt: &Path,
    out: Option<&Path>,
    findings: Option<&Path>,
) -> Result<ExitCode> {
    use mowmill::claims;
    let sources = claims::Sources::new(from)?;
    let rows = sources.read_rows()?;
    // Rows that contradict themselves fail the command whichever claim they belong to (an
    // exact row belongs to none, but its optimum decides others).
    let inconsistent: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            r.consistency_error()
                .map(|e| format!("{}: {e}", r.describe()))
        })
        .collect();
    for line in &inconsistent {
        eprintln!("invalid row: {line}");
    }
    let from_text = sources.describe();
    let from = &from_text;
    let tight_rows = if tight.exists() {
        claims::read_tight(tight)?
    } else {
        eprintln!(
            "no {}: the tight-family column stays empty",
            tight.display()
        );
        Vec::new()
    };
    let mut table = claims::table(&rows, &tight_rows);
    claims::add_choice_evidence(&mut table, &sources);
    add_hunts(&mut table, hunt)?;
    let bad = match out {
        Some(out) => write_claims(&table, Path::new(from), out)?,
        None => {
            println!("{}", claims::markdown(&table, from));
            table.iter().filter(|c| claims::is_violated(c)).count()
        }
    };
    if let Some(dir) = findings {
        let files = claims::save_findings(&table, &sources, dir)?;
        if !files.is_empty() {
            eprintln!("saved {} finding file(s) in {}", files.len(), dir.display());
        }
    }
    if !inconsistent.is_empty() {
        eprintln!(
            "claims: {} inconsistent row(s): invalid results, counted as broken claims",
            inconsistent.len()
        );
    }
    Ok(if bad == 0 && inconsistent.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
