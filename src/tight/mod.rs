//! The papers' tight families, measured: `mowmill tight`.
//!
//! Three families, each over a range of its parameter; for every member, every quantity the
//! papers (or issue 7's reconstruction) state is set beside what mowmill measures, with how it
//! was measured (the exact solver, an explicit construction run through the checker, or a
//! registered algorithm):
//! - **donut** (turn-cost paper, Fig. 5): the square annulus of width k and outer side L ≥ 3k.
//! - **band** B_k (milling paper, the tight class of the 6/5 bound of Theorem 5 and Fig. 16).
//! - **thin43** (turn-cost paper, Fig. 6 and Theorem 5.9), as reconstructed in issue 7.
//!
//! A claim is *established* when it is a proven fact about the instance (a theorem, a count, a
//! value the exact solver or a closed-form bound proves); `tight` exits 1 when a measurement
//! contradicts one. The numbers the papers give for one particular run of an algorithm on
//! their figure (which optimal matching, which merges) are *examples*: a different value is
//! reported as `differs`, a finding, not a failure. Ratios are *reported* (the plots show
//! their convergence). A *construction* is ours, for a claim the paper proves only in outline
//! (the `--coverage4` rewrite of Theorem 5.6): where it falls short the row says `not
//! reached`, a gap of our construction and not evidence against the theorem.

pub mod claims;
pub mod figures;

use crate::algorithms::merge::merge_cycles;
use crate::algorithms::{self, Merge, Objective as AlgoObjective, Options};
use crate::checker::{Mode, Report, check};
use crate::error::{Error, Result};
use crate::evaluate::{self, Reference, Subject};
use crate::exact::{self, ExactOptions, Objective as ExactObjective, Status};
use crate::generate::{Family, GenParams, generate, thin43_gadgets};
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
const FIG16: &str = "milling paper, Theorem 5 and Fig. 16 (B_k of issue 7)";
const FIG6: &str = "turn-cost paper, Fig. 6 and Theorem 5.9 (reconstruction of issue 7)";

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
        ..ExactOptions::default()
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

// ---------------------------------------------------------------------------------------------
// Donut (Fig. 5 of the turn-cost paper)
// ---------------------------------------------------------------------------------------------

/// The 4k concentric rings of the donut: an optimal cycle cover (4 turns each).
pub fn donut_rings(side: usize, k: usize) -> CycleCover {
    let l = side as i32;
    CycleCover::new(
        (0..k as i32)
            .map(|i| rectangle_walk(i, i, l - 1 - i, l - 1 - i))
            .collect(),
    )
}

/// The boundary walk of the rectangle with corners (x0, y0) and (x1, y1), counter-clockwise
/// from (x0, y0).
fn rectangle_walk(x0: i32, y0: i32, x1: i32, y1: i32) -> Walk {
    let mut w = Vec::new();
    w.extend((x0..x1).map(|x| Pixel::new(x, y0)));
    w.extend((y0..y1).map(|y| Pixel::new(x1, y)));
    w.extend((x0 + 1..=x1).rev().map(|x| Pixel::new(x, y1)));
    w.extend((y0 + 1..=y1).rev().map(|y| Pixel::new(x0, y)));
    w
}

/// The spiral tour of the donut with 4k + 2 turns (Fig. 5(b)), for k ≥ 2: ring i (the
/// boundary of the square [i, L−1−i]²) is run counter-clockwise from (i, i) and left at
/// (i, i+1) eastwards into ring i + 1 (4 turns per ring); the innermost ring continues down
/// column k−1 to row 0 and west back to (0, 0), where a U-turn closes the tour:
/// 4(k−1) + 3 + 1 + 2 = 4k + 2 turns.
pub fn donut_spiral(side: usize, k: usize) -> CycleCover {
    let (l, k) = (side as i32, k as i32);
    let mut w: Walk = Vec::new();
    for i in 0..k {
        let (lo, hi) = (i, l - 1 - i);
        w.extend((lo..hi).map(|x| Pixel::new(x, lo)));
        w.extend((lo..hi).map(|y| Pixel::new(hi, y)));
        w.extend((lo + 1..=hi).rev().map(|x| Pixel::new(x, hi)));
        if i + 1 < k {
            // Down column i to row i + 1, then east into ring i + 1 at (i + 1, i + 1).
            w.extend((lo + 2..=hi).rev().map(|y| Pixel::new(lo, y)));
            w.push(Pixel::new(lo, lo + 1));
        } else {
            // Down column k − 1 to row 0, then west along row 0 to (1, 0).
            w.extend((1..=hi).rev().map(|y| Pixel::new(lo, y)));
            w.extend((1..=lo).rev().map(|x| Pixel::new(x, 0)));
        }
    }
    CycleCover::tour(w)
}

/// All measurements of the donut of width k and outer side `side`.
pub fn donut(side: usize, k: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        side: Some(side),
        k: Some(k),
        ..GenParams::new(Family::Donut, 0)
    })?;
    let member = format!("k={k} L={side}");
    let kk = k as u64;
    let mut r = Rows {
        family: "donut",
        member: &member,
        param: kk,
        n: region.len() as u64,
        rows: Vec::new(),
    };
    let s = min_strip_cover_size(&region) as u64;
    r.claim(
        "strip_cover",
        format!("4k = {}", 4 * kk),
        (4 * kk) as f64,
        f(s),
        Standing::Established,
        "Hopcroft-Karp + König (Lemma 4.4)",
        FIG5,
    );
    // The optimal cycle cover: 4k concentric rings, each 4 turns.
    let rings = checked(&region, &donut_rings(side, k), "the donut rings")?;
    let (opt_cc, _, _) = exact_solve(&region, ExactObjective::CcTurns, opts.time_limit);
    r.claim(
        "rings_cc_turns",
        format!("k rings of 4 turns = {}", 4 * kk),
        (4 * kk) as f64,
        f(rings.turns),
        Standing::Established,
        "explicit concentric rings (checker)",
        FIG5,
    );
    r.claim(
        "opt_cc_turns",
        format!("4k = {}", 4 * kk),
        (4 * kk) as f64,
        opt_cc.map(|v| v as f64),
        Standing::Established,
        "exact cc-turns (proven optimal)",
        FIG5,
    );
    // The optimal tour: a spiral with 4k + 2 turns; the exact solver for small k.
    let spiral_cover = donut_spiral(side, k);
    let spiral = checked(&region, &spiral_cover, "the donut spiral")?;
    r.claim(
        "spiral_turns",
        format!("4k + 2 = {}", 4 * kk + 2),
        (4 * kk + 2) as f64,
        f(spiral.turns),
        Standing::Established,
        "explicit spiral (checker)",
        FIG5,
    );
    let mut opt_tour_cover = spiral_cover.clone();
    let opt_tour = if k <= opts.donut_exact_k {
        let (value, lb, cover) = exact_solve(&region, ExactObjective::TourTurns, opts.time_limit);
        match value {
            Some(v) => {
                r.claim(
                    "opt_tour_turns",
                    format!("4k + 2 = {}", 4 * kk + 2),
                    (4 * kk + 2) as f64,
                    f(v),
                    Standing::Established,
                    "exact turns (proven optimal)",
                    FIG5,
                );
                if let Some(c) = cover {
                    opt_tour_cover = c;
                }
                v
            }
            None => {
                let verdict = if lb > 4 * kk + 2 {
                    "contradicted"
                } else {
                    "upper bound met"
                };
                r.push(
                    "opt_tour_turns",
                    format!("4k + 2 = {}", 4 * kk + 2),
                    Some((4 * kk + 2) as f64),
                    f(spiral.turns),
                    Standing::Established,
                    verdict,
                    &format!("spiral; exact turns hit the time limit with lower bound {lb}"),
                    FIG5,
                );
                spiral.turns
            }
        }
    } else {
        r.push(
            "opt_tour_turns",
            format!("4k + 2 = {}", 4 * kk + 2),
            Some((4 * kk + 2) as f64),
            f(spiral.turns),
            Standing::Established,
            "upper bound met",
            &format!(
                "spiral (upper bound); exact turns not run (k > {})",
                opts.donut_exact_k
            ),
            FIG5,
        );
        spiral.turns
    };
    // The algorithm: strips-matching, its cycle cover and both merges.
    let (_, cc) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Smart,
        AlgoObjective::CcTurns,
    )?;
    r.claim(
        "strips_matching_cc_turns",
        format!("8k + 2 = {}", 8 * kk + 2),
        (8 * kk + 2) as f64,
        f(cc.turns),
        Standing::Example,
        "strips-matching cycle cover (checker)",
        FIG5,
    );
    r.claim(
        "strips_matching_cc_cycles",
        format!("2k = {}", 2 * kk),
        (2 * kk) as f64,
        Some(cc.cycles as f64),
        Standing::Example,
        "strips-matching cycle cover (checker)",
        FIG5,
    );
    let (naive_cover, naive) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Naive,
        AlgoObjective::Turns,
    )?;
    let (_, smart) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Smart,
        AlgoObjective::Turns,
    )?;
    r.claim(
        "naive_tour_turns",
        format!("12k = {}", 12 * kk),
        (12 * kk) as f64,
        f(naive.turns),
        Standing::Example,
        "strips-matching --merge naive (checker)",
        FIG5,
    );
    // Theorem 5.6 on the naive tour: no more turns, coverage at most 4.
    if naive.length <= opts.coverage4_max_length {
        let (rewritten, stuck) = crate::algorithms::coverage4::coverage4(&region, &naive_cover);
        let c4 = checked(&region, &rewritten, "coverage4 of the naive tour")?;
        r.claim_at_most(
            "coverage4_turns",
            format!("at most the naive tour's {}", naive.turns),
            naive.turns as f64,
            f(c4.turns),
            &format!(
                "--coverage4 on the naive tour (max coverage {} before)",
                naive.max_coverage
            ),
            "turn-cost paper, Theorem 5.6",
        );
        let reached = c4.max_coverage <= 4;
        r.push(
            "coverage4_max_coverage",
            "at most 4".to_string(),
            Some(4.0),
            Some(f64::from(c4.max_coverage)),
            Standing::Construction,
            if reached { "holds" } else { "not reached" },
            &format!("--coverage4 on the naive tour (checker; {stuck} pixels left above 4)"),
            "turn-cost paper, Theorem 5.6",
        );
    }
    let worst = cc.turns + 2 * (cc.cycles as u64).saturating_sub(1);
    r.report(
        "crossing_merge_turns",
        "t + 2(c - 1): every merge at a crossing (+2)".to_string(),
        f(worst),
        "from the strips-matching cycle cover (Theorem 4.2 with +2 per merge)",
        FIG5,
    );
    r.report(
        "smart_tour_turns",
        "what smart merging achieves".to_string(),
        f(smart.turns),
        "strips-matching --merge smart (checker)",
        FIG5,
    );
    r.report(
        "ratio_cc",
        "cycle cover / optimal cycle cover -> 2".to_string(),
        ratio(cc.turns, rings.turns),
        "strips_matching_cc_turns / rings_cc_turns",
        FIG5,
    );
    r.report(
        "ratio_naive",
        "naive tour / optimal tour -> 3".to_string(),
        ratio(naive.turns, opt_tour),
        "naive_tour_turns / opt_tour_turns",
        FIG5,
    );
    r.report(
        "ratio_crossing",
        "crossing merges / optimal tour -> 3".to_string(),
        ratio(worst, opt_tour),
        "crossing_merge_turns / opt_tour_turns",
        FIG5,
    );
    r.report(
        "ratio_smart",
        "smart tour / optimal tour".to_string(),
        ratio(smart.turns, opt_tour),
        "smart_tour_turns / opt_tour_turns",
        FIG5,
    );
    let rows = r.rows;
    Ok(Member {
        family: "donut",
        member,
        param: kk,
        region,
        rows,
        drawings: vec![
            (
                format!("strips-matching, naive merge: {} turns", naive.turns),
                naive_cover,
            ),
            (format!("optimal tour: {opt_tour} turns"), opt_tour_cover),
        ],
    })
}

// ---------------------------------------------------------------------------------------------
// Band B_k (the 6/5 bound of Theorem 5 of the milling paper)
// ---------------------------------------------------------------------------------------------

/// All measurements of the band B_k.
pub fn band(k: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        k: Some(k),
        ..GenParams::new(Family::Band, 0)
    })?;
    let member = format!("k={k}");
    let kk = k as u64;
    let n = region.len() as u64;
    let mut r = Rows {
        family: "band",
        member: &member,
        param: kk,
        n,
        rows: Vec::new(),
    };
    let bound = (6 * n - 4) / 5;
    r.claim(
        "n",
        format!("5k + 4 = {}", 5 * kk + 4),
        (5 * kk + 4) as f64,
        f(n),
        Standing::Established,
        "pixel count",
        FIG16,
    );
    let (black, _) = crate::topology::colour_counts(&region);
    r.claim(
        "black_pixels",
        format!("3k + 2 = {}", 3 * kk + 2),
        (3 * kk + 2) as f64,
        f(black as u64),
        Standing::Established,
        "pixels with x + y even",
        FIG16,
    );
    let (tour, tsp) = run_algorithm(&region, "tsp65", Merge::Smart, AlgoObjective::Length)?;
    r.claim(
        "tsp65_length",
        format!("(6N - 4)/5 = {bound}"),
        bound as f64,
        f(tsp.length),
        Standing::Established,
        "tsp65 (checker)",
        FIG16,
    );
    // Every closed walk alternates colours, so it has length ≥ 2·#black: when tsp65 meets
    // that bound, it is optimal whatever the exact solver says.
    let colour_bound = 2 * black as u64;
    let mut opt_cover = tour.clone();
    let (opt, how) = if k <= opts.band_exact_k {
        let (value, lb, cover) = exact_solve(&region, ExactObjective::Length, opts.time_limit);
        if let Some(c) = cover.filter(|_| value.is_some()) {
            opt_cover = c;
        }
        match value {
            Some(v) => (Some(v), "exact length (proven optimal)".to_string()),
            None => (
                (tsp.length == colour_bound).then_some(tsp.length),
                format!("tsp65 = 2 #black (exact hit the time limit, bound {lb})"),
            ),
        }
    } else {
        (
            (tsp.length == colour_bound).then_some(tsp.length),
            "tsp65 meets the colour bound 2 #black (proven optimal)".to_string(),
        )
    };
    r.claim(
        "opt_length",
        format!("(6N - 4)/5 = {bound}"),
        bound as f64,
        opt.map(|v| v as f64),
        Standing::Established,
        &how,
        FIG16,
    );
    r.report(
        "ratio_opt_n",
        "OPT / N -> 6/5".to_string(),
        opt.and_then(|v| ratio(v, n)),
        "opt_length / n",
        FIG16,
    );
    r.report(
        "ratio_tsp65_opt",
        "tsp65 / OPT (Corollary 3: <= 6/5)".to_string(),
        opt.and_then(|v| ratio(tsp.length, v)),
        "tsp65_length / opt_length",
        FIG16,
    );
    let rows = r.rows;
    Ok(Member {
        family: "band",
        member,
        param: kk,
        region,
        rows,
        drawings: vec![
            (format!("tsp65: length {}", tsp.length), tour),
            (
                format!("optimal tour: length {}", opt.unwrap_or(tsp.length)),
                opt_cover,
            ),
        ],
    })
}

// ---------------------------------------------------------------------------------------------
// thin43 (Fig. 6 and Theorem 5.9 of the turn-cost paper)
// ---------------------------------------------------------------------------------------------

/// The gadget cycle cover of `thin43`: each gadget's own minimum-turn cycle cover (exact
/// `cc-turns` on the gadget alone), all together. Where a gadget's optimal cover has several
/// cycles (Y_j: the two rectangles on either side of its chord), they are merged within the
/// gadget when that is free, so that each gadget is one cycle as in issue 7.
pub fn thin43_gadget_cover(s: usize, time_limit: f64) -> Result<CycleCover> {
    let mut cycles = Vec::new();
    for (name, pixels) in thin43_gadgets(s) {
        let gadget = Region::from_pixels(pixels)?;
        let (value, _, cover) = exact_solve(&gadget, ExactObjective::CcTurns, time_limit);
        match (value, cover) {
            (Some(_), Some(c)) => {
                let (merged, _) = merge_cycles(&gadget, &c, Merge::Smart);
                let free = check(&gadget, &merged, Mode::Milling).turns
                    == check(&gadget, &c, Mode::Milling).turns;
                cycles.extend(if free { merged.cycles } else { c.cycles });
            }
            _ => {
                return Err(Error::invalid(format!(
                    "thin43 gadget {name}: the exact cycle cover was not proven in {time_limit} s"
                )));
            }
        }
    }
    Ok(CycleCover::new(cycles))
}

/// All measurements of `thin43` with parameter s.
pub fn thin43(s: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        s: Some(s),
        ..GenParams::new(Family::Thin43, 0)
    })?;
    let member = format!("s={s}");
    let ss = s as u64;
    let n = region.len() as u64;
    let (opt_value, heur_value) = (12 * ss + 32, 16 * ss + 38);
    let mut r = Rows {
        family: "thin43",
        member: &member,
        param: ss,
        n,
        rows: Vec::new(),
    };
    r.claim(
        "n",
        format!("222 + 77s = {}", 222 + 77 * ss),
        (222 + 77 * ss) as f64,
        f(n),
        Standing::Established,
        "pixel count",
        FIG6,
    );
    let (opt_cc, _, _) = exact_solve(&region, ExactObjective::CcTurns, opts.time_limit);
    r.claim(
        "opt_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        opt_cc.map(|v| v as f64),
        Standing::Established,
        "exact cc-turns (proven optimal)",
        FIG6,
    );
    let (opt_tour, tour_lb, opt_cover) =
        exact_solve(&region, ExactObjective::TourTurns, opts.time_limit);
    r.claim(
        "opt_tour_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        opt_tour.map(|v| v as f64),
        Standing::Established,
        &if opt_tour.is_some() {
            "exact turns (proven optimal)".to_string()
        } else {
            format!("exact turns hit the time limit (lower bound {tour_lb})")
        },
        FIG6,
    );
    let (_, thin_cc) = run_algorithm(&region, "thin-cc", Merge::Smart, AlgoObjective::CcTurns)?;
    r.claim(
        "thin_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        f(thin_cc.turns),
        Standing::Established,
        "thin-cc (Corollary 5.3; checker)",
        FIG6,
    );
    let gadget_cover = thin43_gadget_cover(s, opts.time_limit)?;
    let gadgets = checked(&region, &gadget_cover, "the thin43 gadget cover")?;
    r.claim(
        "gadget_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        f(gadgets.turns),
        Standing::Established,
        "each gadget's exact cycle cover (checker)",
        FIG6,
    );
    r.claim(
        "gadget_cc_cycles",
        format!("2s + 4 = {}", 2 * ss + 4),
        (2 * ss + 4) as f64,
        Some(gadgets.cycles as f64),
        Standing::Established,
        "each gadget's exact cycle cover (checker)",
        FIG6,
    );
    let (naive_cover, naive_stats) = merge_cycles(&region, &gadget_cover, Merge::Naive);
    let naive = checked(&region, &naive_cover, "the naive merge of the gadget cover")?;
    r.claim(
        "gadget_naive_turns",
        format!("16s + 38 = {heur_value}"),
        heur_value as f64,
        f(naive.turns),
        Standing::Example,
        &format!(
            "gadget cover, --merge naive ({} of {} merges free)",
            naive_stats.free_merges, naive_stats.merges
        ),
        FIG6,
    );
    let (smart_cover, smart_stats) = merge_cycles(&region, &gadget_cover, Merge::Smart);
    let smart = checked(&region, &smart_cover, "the smart merge of the gadget cover")?;
    r.report(
        "gadget_smart_turns",
        "what smart merging achieves from the gadget cover".to_string(),
        f(smart.turns),
        &format!(
            "gadget cover, --merge smart ({} of {} merges free)",
            smart_stats.free_merges, smart_stats.merges
        ),
        FIG6,
    );
    let (_, default_merge) =
        run_algorithm(&region, "thin-merge", Merge::Smart, AlgoObjective::Turns)?;
    r.report(
        "thin_merge_turns",
        "thin-merge as registered (from thin-cc's cover)".to_string(),
        f(default_merge.turns),
        "thin-merge (checker)",
        FIG6,
    );
    let opt = opt_tour.unwrap_or(opt_value);
    r.report(
        "ratio_gadget_naive",
        "gadget naive merge / OPT -> 4/3".to_string(),
        ratio(naive.turns, opt),
        "gadget_naive_turns / opt_tour_turns",
        FIG6,
    );
    r.report(
        "ratio_thin_merge",
        "thin-merge / OPT (Theorem 5.9: <= 4/3)".to_string(),
        ratio(default_merge.turns, opt),
        "thin_merge_turns / opt_tour_turns",
        FIG6,
    );
    let rows = r.rows;
    Ok(Member {
        family: "thin43",
        member,
        param: ss,
        region,
        rows,
        drawings: vec![
            (
                format!("gadget cover, naive merge: {} turns", naive.turns),
                naive_cover,
            ),
            (
                format!("optimal tour: {} turns", opt_tour.unwrap_or(opt_value)),
                opt_cover.unwrap_or_default(),
            ),
        ],
    })
}

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
        let back = claims::read_tight(&path).unwrap();
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
