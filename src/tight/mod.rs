//! The papers' tight families, measured: `mowmill tight`.
//!
//! Three families, each over a range of its parameter; for every member, every quantity the
//! papers (or mowmill's reconstruction of the thin example) state is set beside what mowmill measures, with how it
//! was measured (the exact solver, an explicit construction run through the checker, or a
//! registered algorithm):
//! - **donut** (turn-cost paper, Fig. 5): the square annulus of width k and outer side L ≥ 3k.
//! - **band** B_k (milling paper, the tight class of the 6/5 bound of Theorem 5 and Fig. 16).
//! - **thin43** (turn-cost paper, Fig. 6 and Theorem 5.9), as mowmill reconstructs it (the paper's figure is lost in extraction).
//!
//! A claim is *established* when it is a proven fact about the instance (a theorem, a count, a
//! value the exact solver or a closed-form bound proves); `tight` exits 1 when a measurement
//! contradicts one. The numbers the papers give for one particular run of an algorithm on
//! their figure (which optimal matching, which merges) are *examples*: a different value is
//! reported as `differs`, a finding, not a failure. Ratios are *reported* (the plots show
//! their convergence). A *construction* is ours, for a claim the paper proves only in outline
//! (the `--coverage4` rewrite of Theorem 5.6): where it falls short the row says `not
//! reached`, a gap of our construction and not evidence against the theorem.

pub mod figures;

use crate::algorithms::{self, Merge, Objective as AlgoObjective, Options};
use crate::checker::{Mode, Report, check};
use crate::error::{Error, Result};
use crate::evaluate::{self, Reference, Subject};
use crate::exact::{self, ExactOptions, Objective as ExactObjective, Status};
use crate::generate::{Family, GenParams, generate};
use crate::region::{Pixel, Region};
use crate::strip_cover::min_strip_cover_size;
use crate::tour::{CycleCover, Walk};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::Path;

/// How a claim is held: what a mismatch means.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Standing {
    /// A proven fact about the instance: a mismatch is a contradiction (exit 1).
    Established,
    /// The paper's description of one run on its figure: a mismatch is a finding.
    Example,
    /// Only reported (no value is claimed for this member, e.g. a ratio tending to a limit).
    Report,
    /// Our construction for a claim the paper proves only in outline (Theorem 5.6): a miss is
    /// a gap of our construction, reported as `not reached`, not a contradiction of the paper.
    Construction,
}

/// One line of the tight table.
#[derive(Clone, Debug, Serialize)]
pub struct TightRow {
    pub family: String,
    /// The member, e.g. `k=3 L=9`.
    pub member: String,
    /// The family parameter (k or s), the x axis of the plots.
    pub param: u64,
    pub n: u64,
    /// What is measured, e.g. `opt_tour_turns`.
    pub quantity: String,
    /// The claim as stated, with its value here, e.g. `4k + 2 = 14`.
    pub claim: String,
    /// The claimed value (empty for reported quantities).
    pub claimed: Option<f64>,
    pub measured: Option<f64>,
    pub standing: Standing,
    /// `reproduced`, `contradicted`, `differs`, `upper bound met`, `reported` or `not measured`.
    pub verdict: String,
    /// How `measured` was obtained.
    pub how: String,
    /// Where the claim is made.
    pub source: String,
}

/// CSV header of `tight.csv` (a contract for scripts).
pub const TIGHT_COLUMNS: [&str; 12] = [
    "family", "member", "param", "n", "quantity", "claim", "claimed", "measured", "standing",
    "verdict", "how", "source",
];

/// The parameter ranges and exact-solver limits of a `tight` run.
#[derive(Clone, Debug)]
pub struct TightOptions {
    /// Donut widths k (each with L = 3k and L = 4k).
    pub donut_k: Vec<usize>,
    /// The exact `turns` solver runs on donuts with k up to this.
    pub donut_exact_k: usize,
    pub band_k: Vec<usize>,
    /// The exact `length` solver runs on bands with k up to this.
    pub band_exact_k: usize,
    pub thin43_s: Vec<usize>,
    /// Time limit of each exact solve, in seconds.
    pub time_limit: f64,
    /// `--coverage4` is measured on donut tours up to this length (every member's naive
    /// tour by default: the longest, k = 10 and L = 40, takes about 0.2 s).
    pub coverage4_max_length: u64,
}

impl Default for TightOptions {
    fn default() -> Self {
        TightOptions {
            donut_k: (2..=10).collect(),
            donut_exact_k: 6,
            band_k: (1..=30).collect(),
            band_exact_k: 12,
            thin43_s: (0..=8).collect(),
            time_limit: 120.0,
            coverage4_max_length: 100_000,
        }
    }
}

/// One member of a family with its measured rows and the walks worth drawing: pairs of
/// (label, cover) shown side by side (the algorithm's, then the optimal one).
pub struct Member {
    pub family: &'static str,
    pub member: String,
    pub param: u64,
    pub region: Region,
    pub rows: Vec<TightRow>,
    pub drawings: Vec<(String, CycleCover)>,
}

/// Everything a `tight` run measured.
pub struct TightRun {
    pub members: Vec<Member>,
}

impl TightRun {
    pub fn rows(&self) -> impl Iterator<Item = &TightRow> {
        self.members.iter().flat_map(|m| m.rows.iter())
    }

    /// The established claims that a measurement contradicts.
    pub fn contradictions(&self) -> Vec<&TightRow> {
        self.rows()
            .filter(|r| r.verdict == "contradicted")
            .collect()
    }
}

/// Builds rows of one member (keeps family, member, param and n in one place).
struct Rows<'a> {
    family: &'static str,
    member: &'a str,
    param: u64,
    n: u64,
    rows: Vec<TightRow>,
}

impl Rows<'_> {
    /// A claimed value against a measured one.
    #[allow(clippy::too_many_arguments)]
    fn claim(
        &mut self,
        quantity: &str,
        claim: String,
        claimed: f64,
        measured: Option<f64>,
        standing: Standing,
        how: &str,
        source: &str,
    ) {
        let verdict = match measured {
            None => "not measured",
            Some(m) if (m - claimed).abs() < 1e-9 => "reproduced",
            Some(_) if standing == Standing::Established => "contradicted",
            Some(_) => "differs",
        };
        self.push(
            quantity,
            claim,
            Some(claimed),
            measured,
            standing,
            verdict,
            how,
            source,
        );
    }

    /// A claimed upper bound against a measured value.
    fn claim_at_most(
        &mut self,
        quantity: &str,
        claim: String,
        bound: f64,
        measured: Option<f64>,
        how: &str,
        source: &str,
    ) {
        let verdict = match measured {
            None => "not measured",
            Some(m) if m <= bound + 1e-9 => "holds",
            Some(_) => "contradicted",
        };
        self.push(
            quantity,
            claim,
            Some(bound),
            measured,
            Standing::Established,
            verdict,
            how,
            source,
        );
    }

    /// A reported value (no claim for this member).
    fn report(
        &mut self,
        quantity: &str,
        claim: String,
        measured: Option<f64>,
        how: &str,
        source: &str,
    ) {
        let verdict = if measured.is_some() {
            "reported"
        } else {
            "not measured"
        };
        self.push(
            quantity,
            claim,
            None,
            measured,
            Standing::Report,
            verdict,
            how,
            source,
        );
    }

    #[allow(clippy::too_many_arguments)]
    fn push(
        &mut self,
        quantity: &str,
        claim: String,
        claimed: Option<f64>,
        measured: Option<f64>,
        standing: Standing,
        verdict: &str,
        how: &str,
        source: &str,
    ) {
        self.rows.push(TightRow {
            family: self.family.to_string(),
            member: self.member.to_string(),
            param: self.param,
            n: self.n,
            quantity: quantity.to_string(),
            claim,
            claimed,
            measured,
            standing,
            verdict: verdict.to_string(),
            how: how.to_string(),
            source: source.to_string(),
        });
    }
}

const FIG5: &str = "turn-cost paper, Fig. 5 and Section 5.3";
const FIG16: &str =
    "milling paper, Theorem 5 and Fig. 16 (the band B_k stands in for the figure: docs/claims.md)";
const FIG6: &str = "turn-cost paper, Fig. 6 and Theorem 5.9 (as reconstructed in docs/claims.md)";

fn family_region(p: &GenParams) -> Result<Region> {
    Ok(generate(p)?.region)
}

/// Checks a cover and insists that it is valid (our constructions must be).
fn checked(region: &Region, cover: &CycleCover, what: &str) -> Result<Report> {
    let r = check(region, cover, Mode::Milling);
    if r.valid {
        Ok(r)
    } else {
        Err(Error::invalid(format!(
            "internal error: {what} fails the checker: {}",
            r.error.unwrap_or_default()
        )))
    }
}

/// An exact solve within the time limit: (value if proven optimal, lower bound, cover).
fn exact_solve(
    region: &Region,
    objective: ExactObjective,
    time_limit: f64,
) -> (Option<u64>, u64, Option<CycleCover>) {
    let opts = ExactOptions {
        time_limit: Some(time_limit),
        ..crate::warm_start::exact_options()
    };
    let r = exact::solve(region, objective, &opts);
    let value = if r.status == Status::Optimal && r.valid {
        r.value
    } else {
        None
    };
    (value, r.lower_bound, r.cover)
}

/// Runs a registered algorithm through the [evaluation pipeline](crate::evaluate) and returns
/// its output for `objective` with the checker's recount, insisting that it is valid.
fn run_algorithm(
    region: &Region,
    name: &str,
    merge: Merge,
    objective: AlgoObjective,
) -> Result<(CycleCover, Report)> {
    let algo =
        algorithms::find(name).ok_or_else(|| Error::invalid(format!("no algorithm {name}")))?;
    let opts = Options {
        merge,
        ..Options::default()
    };
    let eval = evaluate::evaluate(
        Subject::Registered(algo),
        region,
        &opts,
        &[objective],
        &Reference::default(),
    );
    if let Some(e) = eval.error {
        return Err(Error::solver(format!("{name}: {e}")));
    }
    let out = eval
        .output(objective)
        .ok_or_else(|| Error::invalid(format!("{name} has no {objective} output")))?;
    let report = checked(region, &out.cover, name)?;
    Ok((out.cover.clone(), report))
}

fn f(v: u64) -> Option<f64> {
    Some(v as f64)
}

fn ratio(a: u64, b: u64) -> Option<f64> {
    (b > 0).then(|| a as f64 / b as f64)
}

mod band;
mod donut;
mod thin43;
pub use band::band;
pub use donut::{donut, donut_rings, donut_spiral};
pub use thin43::thin43;

/// Runs every family over its range (in parallel over members).
pub fn run(opts: &TightOptions) -> Result<TightRun> {
    use rayon::prelude::*;
    enum Job {
        Donut(usize, usize),
        Band(usize),
        Thin43(usize),
    }
    let mut jobs = Vec::new();
    for &k in &opts.donut_k {
        jobs.push(Job::Donut(3 * k, k));
        jobs.push(Job::Donut(4 * k, k));
    }
    jobs.extend(opts.band_k.iter().map(|&k| Job::Band(k)));
    jobs.extend(opts.thin43_s.iter().map(|&s| Job::Thin43(s)));
    let members: Result<Vec<Member>> = jobs
        .par_iter()
        .map(|job| match *job {
            Job::Donut(side, k) => donut(side, k, opts),
            Job::Band(k) => band(k, opts),
            Job::Thin43(s) => thin43(s, opts),
        })
        .collect();
    Ok(TightRun { members: members? })
}

/// A value for the Markdown table (4 decimals) or the CSV (6, like `results.csv`).
fn cell_with(v: Option<f64>, decimals: usize) -> String {
    match v {
        None => String::new(),
        Some(x) if x.fract() == 0.0 && x.abs() < 1e15 => format!("{}", x as i64),
        Some(x) => format!("{x:.decimals$}"),
    }
}

fn cell(v: Option<f64>) -> String {
    cell_with(v, 4)
}

/// Writes `tight.csv` (columns [`TIGHT_COLUMNS`]).
pub fn write_csv(run: &TightRun, path: &Path) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| Error::invalid(e.to_string()))?;
    let err = |e: csv::Error| Error::invalid(format!("{}: {e}", path.display()));
    w.write_record(TIGHT_COLUMNS).map_err(err)?;
    for r in run.rows() {
        let standing = match r.standing {
            Standing::Established => "established",
            Standing::Example => "example",
            Standing::Report => "report",
            Standing::Construction => "construction",
        };
        w.write_record([
            r.family.as_str(),
            &r.member,
            &r.param.to_string(),
            &r.n.to_string(),
            &r.quantity,
            &r.claim,
            &cell_with(r.claimed, 6),
            &cell_with(r.measured, 6),
            standing,
            &r.verdict,
            &r.how,
            &r.source,
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| Error::invalid(e.to_string()))?;
    Ok(())
}

/// The table as Markdown: one section per family, one line per member and quantity.
pub fn markdown(run: &TightRun) -> String {
    let mut out = String::from(
        "Tight families, claimed against measured (`mowmill tight`). Standing: *established* \
         (a proven fact; a mismatch is `contradicted` and `tight` exits 1), *example* (the \
         paper's numbers for one run on its figure; a mismatch `differs`, a finding), \
         *construction* (ours, for a claim proven only in outline; a miss is `not reached`); \
         ratios are reported. `how` says what measured each value.\n",
    );
    let mut family = "";
    for m in &run.members {
        if m.family != family {
            family = m.family;
            let source = m.rows.first().map(|r| r.source.as_str()).unwrap_or("");
            let _ = writeln!(out, "\n### {family} ({source})\n");
            out.push_str(
                "| member | N | quantity | claim | measured | standing | verdict | how |\n",
            );
            out.push_str("|---|---|---|---|---|---|---|---|\n");
        }
        for r in &m.rows {
            let standing = match r.standing {
                Standing::Established => "established",
                Standing::Example => "example",
                Standing::Report => "",
                Standing::Construction => "construction",
            };
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} | {} | {} | {} | {} |",
                r.member,
                r.n,
                r.quantity,
                r.claim,
                cell(r.measured),
                standing,
                r.verdict,
                r.how
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows() -> Rows<'static> {
        Rows {
            family: "donut",
            member: "k=2 L=6",
            param: 2,
            n: 32,
            rows: Vec::new(),
        }
    }

    #[test]
    fn verdicts_follow_the_standing() {
        let mut r = rows();
        r.claim(
            "a",
            "4k = 8".into(),
            8.0,
            Some(8.0),
            Standing::Established,
            "",
            "",
        );
        r.claim(
            "b",
            "4k = 8".into(),
            8.0,
            Some(9.0),
            Standing::Established,
            "",
            "",
        );
        r.claim(
            "c",
            "8k + 2 = 18".into(),
            18.0,
            Some(16.0),
            Standing::Example,
            "",
            "",
        );
        r.claim(
            "d",
            "4k = 8".into(),
            8.0,
            None,
            Standing::Established,
            "",
            "",
        );
        r.claim_at_most("e", "at most 4".into(), 4.0, Some(3.0), "", "");
        r.claim_at_most("f", "at most 4".into(), 4.0, Some(5.0), "", "");
        r.report("g", "ratio".into(), Some(2.0), "", "");
        let verdicts: Vec<&str> = r.rows.iter().map(|x| x.verdict.as_str()).collect();
        assert_eq!(
            verdicts,
            [
                "reproduced",
                "contradicted",
                "differs",
                "not measured",
                "holds",
                "contradicted",
                "reported"
            ]
        );
        let run = TightRun {
            members: vec![Member {
                family: "donut",
                member: "k=2 L=6".into(),
                param: 2,
                region: Region::rectangle(1, 1),
                rows: r.rows,
                drawings: Vec::new(),
            }],
        };
        let bad: Vec<&str> = run
            .contradictions()
            .iter()
            .map(|x| x.quantity.as_str())
            .collect();
        assert_eq!(bad, ["b", "f"]);
    }

    #[test]
    fn csv_round_trips_through_read_tight() {
        let m = band(2, &TightOptions::default()).unwrap();
        let run = TightRun { members: vec![m] };
        let path = std::env::temp_dir().join(format!("mowmill-tight-{}.csv", std::process::id()));
        write_csv(&run, &path).unwrap();
        let back = crate::claims::read_tight(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        assert_eq!(back.len(), run.rows().count());
        for (a, b) in back.iter().zip(run.rows()) {
            assert_eq!((&a.quantity, &a.verdict), (&b.quantity, &b.verdict));
            let close = match (a.measured, b.measured) {
                (Some(x), Some(y)) => (x - y).abs() < 1e-6,
                (x, y) => x == y,
            };
            assert!(
                close,
                "{}: {:?} vs {:?}",
                a.quantity, a.measured, b.measured
            );
        }
    }
}
