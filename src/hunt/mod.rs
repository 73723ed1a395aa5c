//! `mowmill hunt`: a search over regions for the instances where an algorithm is worst — the
//! largest ratio of its checked value to the exact optimum (`--against opt`) or to the best
//! lower bound (`--against bound`, an over-estimate of the true ratio), or to the best checked
//! walk known (`--against best`, an upper bound on OPT from every registered algorithm and the
//! exact incumbent: [`best`]).
//!
//! # The search
//! A small population of simulated-annealing chains ([`HuntOptions::chains`]), each with its own
//! seeded generator, proposes one neighbour per round; the proposals of a round are evaluated in
//! parallel and applied in chain order, so a seed and an evaluation count give the same
//! `hunt.csv` on any number of jobs. Neighbours come from local moves ([`Move`]): add or remove
//! a boundary pixel, flip a 2×2 block, open or close a hole, stretch a row or column, mirror
//! the region onto one of its sides; and structural moves on a sub-rectangle ([`moves`]: hole
//! lattices, a width-1 comb, widening, copying a motif or a band). A neighbour that leaves the family's constraint or the
//! algorithm's precondition is redrawn (it costs no evaluation). Chains start from the
//! generator of the family, from the papers' tight families when they fit, and from `--start`
//! files; a chain that has not improved on its own best for [`HuntOptions::patience`] evaluations
//! restarts from the best region found so far (half the time) or a fresh generated one.
//!
//! # What an evaluation costs
//! Every candidate runs through [`evaluate`](crate::evaluate::evaluate) (the algorithm, the
//! checker, the cheap bound). The exact solve — the expensive part — is spent only when the
//! result could matter: when value / bound (an upper bound on value / OPT) reaches the chain's
//! acceptance threshold (drawn before the solve, as simulated annealing would), or the global
//! best, or when a guarantee is undecided by the bound (so that a violation against OPT is never
//! missed). Exact optima are cached under the 8 symmetries of the square and translation.
//!
//! # Findings
//! An invalid walk, an algorithm error, a violated guarantee (exactness claims are guarantees
//! with factor 1, so a false "optimal" certificate is one) and a value below the proven optimum
//! (the exact solver or the checker is wrong) are findings: reported at once and saved.

mod audit;
pub mod best;
pub mod moves;
pub mod output;

use crate::algorithms::{self, Objective, Options};
use crate::evaluate::{self, Known, Reference, Subject};
use crate::exact;
use crate::generate::{Family, GenParams, generate};
use crate::region::{Pixel, Region, Symmetry};
use crate::topology;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use std::collections::{BTreeSet, HashMap};
use std::sync::Mutex;
use std::time::Instant;

/// What the ratio divides by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Against {
    Opt,
    Bound,
    /// The best checked walk known ([`best`]): every registered algorithm's walk that carries
    /// the objective and the exact solver's incumbent. OPT ≤ best, so a ratio above a
    /// guarantee's factor is a proven violation.
    Best,
}

impl std::fmt::Display for Against {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Against::Opt => "opt",
            Against::Bound => "bound",
            Against::Best => "best",
        })
    }
}

/// When the search stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop {
    /// After this many evaluations (reproducible).
    Evaluations(usize),
    /// After this many seconds of wall clock (not reproducible).
    Seconds(f64),
}

/// How candidates are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strategy {
    /// Simulated annealing over local moves (the hunt).
    Anneal,
    /// Independent regions from the family's generator: the baseline a hunt must beat.
    Random,
}

/// The shape constraint every candidate keeps, from the family.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Connected, no holes.
    Simple,
    /// Connected, at least one hole.
    Holed,
    /// Connected, no 2×2 block.
    Thin,
    /// Every pixel a boundary pixel.
    Boundary,
    /// Connected, any number of holes.
    Connected,
    /// Anything non-empty (lawns).
    Any,
}

impl Shape {
    /// The constraint of a generator family (the tight families keep the shape class they
    /// belong to).
    pub fn of(family: Family) -> Shape {
        match family {
            Family::RandomSimple | Family::Rect | Family::Band => Shape::Simple,
            Family::RandomHoled | Family::Pinholes | Family::Donut => Shape::Holed,
            Family::Thin | Family::ThinArms | Family::Thin43 => Shape::Thin,
            Family::Boundary => Shape::Boundary,
            Family::Eroded => Shape::Connected,
            Family::LawnScattered => Shape::Any,
            // A family the hunt has no class for keeps connectivity only.
            #[allow(unreachable_patterns)]
            _ => Shape::Connected,
        }
    }

    pub fn holds(self, r: &Region) -> bool {
        if r.is_empty() {
            return false;
        }
        let connected = || topology::components(r).count == 1;
        match self {
            Shape::Simple => connected() && topology::holes(r).count == 0,
            Shape::Holed => connected() && topology::holes(r).count >= 1,
            Shape::Thin => connected() && topology::summary(r).thin,
            Shape::Boundary => topology::summary(r).internal == 0,
            Shape::Connected => connected(),
            Shape::Any => true,
        }
    }
}

/// Everything a hunt needs.
#[derive(Clone, Debug)]
pub struct HuntOptions {
    pub objective: Objective,
    pub options: Options,
    pub family: Family,
    pub min_n: usize,
    pub max_n: usize,
    pub stop: Stop,
    pub seed: u64,
    pub against: Against,
    /// How many distinct worst instances to keep.
    pub keep: usize,
    /// Regions to start from (`--start`), besides generated ones.
    pub starts: Vec<Region>,
    /// Simulated-annealing chains; proposals of one round are evaluated in parallel.
    pub chains: usize,
    /// Evaluations without improvement after which a chain restarts.
    pub patience: usize,
    /// Seconds per exact solve; a solve that does not prove its optimum makes the candidate's
    /// ratio undecided (recorded, never accepted as a new best).
    pub exact_time_limit: f64,
    /// Above this many pixels no exact solve is made (`--against bound|best`; with `best` the
    /// registered algorithms' walks are the upper bound).
    pub exact_max_n: usize,
    pub strategy: Strategy,
}

/// One evaluated candidate (a line of `hunt.csv`).
#[derive(Clone, Debug)]
pub struct Record {
    pub evaluation: usize,
    pub elapsed: f64,
    pub chain: usize,
    /// value / OPT (or / bound); `None` when the exact solve was skipped or did not prove OPT.
    pub ratio: Option<f64>,
    /// value / cheap bound: an upper bound on the ratio to OPT.
    pub ratio_bound: Option<f64>,
    pub best_so_far: f64,
    pub n: usize,
    pub sha256: String,
    pub value: Option<u64>,
    pub opt: Option<u64>,
    pub lower_bound: Option<u64>,
    pub accepted: bool,
    /// Why the exact solve was skipped, or what went wrong; empty otherwise.
    pub note: String,
    /// `--against best`: the best checked walk's value and where it came from.
    pub best: Option<u64>,
    pub best_source: String,
}

/// A region with its score and walks, kept among the worst or as a finding.
#[derive(Clone, Debug)]
pub struct Found {
    pub region: Region,
    pub ratio: f64,
    pub value: u64,
    pub reference: Option<u64>,
    pub walk: Option<crate::tour::CycleCover>,
    pub optimal_walk: Option<crate::tour::CycleCover>,
    pub evaluation: usize,
    /// For findings: what is wrong.
    pub what: String,
    /// `--against best`: where the reference walk came from (`algorithm:objective` or
    /// `exact:status`); empty otherwise.
    pub best_source: String,
}

/// The outcome of a hunt.
#[derive(Clone, Debug, Default)]
pub struct HuntReport {
    pub records: Vec<Record>,
    /// The worst distinct instances, worst first.
    pub worst: Vec<Found>,
    pub findings: Vec<Found>,
    pub exact_solves: usize,
    pub cache_hits: usize,
    pub seconds: f64,
}

/// The longest time between two checkpoints of a running hunt ([`hunt`]), in seconds.
pub const CHECKPOINT_SECONDS: f64 = 60.0;

/// The share of the evaluations (or of the budget) spent sampling the generator before the
/// chains start.
const EXPLORE: f64 = 0.3;

/// The canonical key of a region up to the 8 symmetries of the square and translation.
pub fn canonical(r: &Region) -> String {
    Symmetry::all()
        .map(|s| r.transformed(s).normalized().to_ascii())
        .min()
        .unwrap_or_default()
}

/// Local moves of the search.
#[derive(Clone, Copy, Debug)]
enum Move {
    AddPixel,
    RemovePixel,
    Flip2x2,
    OpenHole,
    CloseHole,
    Stretch,
    Mirror,
    Arm,
    Cut,
    /// One of [`moves`]: a lattice of holes, a width-1 comb, a widened part, a copied motif or
    /// band, on a random sub-rectangle.
    Structural,
}

const MOVES: [(Move, u32); 10] = [
    (Move::AddPixel, 24),
    (Move::RemovePixel, 24),
    (Move::Arm, 8),
    (Move::Cut, 8),
    (Move::Flip2x2, 12),
    (Move::OpenHole, 6),
    (Move::CloseHole, 6),
    (Move::Stretch, 10),
    (Move::Mirror, 6),
    (Move::Structural, 26),
];

fn pick_move(rng: &mut ChaCha8Rng) -> Move {
    let total: u32 = MOVES.iter().map(|m| m.1).sum();
    let mut t = rng.random_range(0..total);
    for (m, w) in MOVES {
        if t < w {
            return m;
        }
        t -= w;
    }
    Move::AddPixel
}

/// A neighbour of `r` by one random move (possibly outside the constraint; the caller checks).
fn neighbour(r: &Region, rng: &mut ChaCha8Rng) -> Option<Region> {
    let mut set: BTreeSet<Pixel> = r.pixels().iter().copied().collect();
    let any = |rng: &mut ChaCha8Rng| r.pixel(rng.random_range(0..r.len()));
    // A local move changes a large region's ratio little: from N = 500 on, the structural
    // moves get a further half of the proposals.
    let mv = if r.len() >= 500 && rng.random_bool(0.5) {
        Move::Structural
    } else {
        pick_move(rng)
    };
    match mv {
        Move::Structural => return moves::random(r, rng),
        Move::AddPixel => {
            let p = any(rng);
            set.insert(topology::ring(p)[2 * rng.random_range(0..4usize)]);
        }
        Move::RemovePixel => {
            set.remove(&any(rng));
        }
        Move::Arm | Move::Cut => {
            // A straight run of 2..=5 cells from a pixel: added (a corridor grows out of the
            // region) or removed (a notch or a cut).
            let p = any(rng);
            let (dx, dy) = [(1, 0), (-1, 0), (0, 1), (0, -1)][rng.random_range(0..4usize)];
            for k in 1..=rng.random_range(2..=5) {
                let q = Pixel::new(p.x + k * dx, p.y + k * dy);
                if matches!(mv, Move::Arm) {
                    set.insert(q);
                } else {
                    set.remove(&Pixel::new(q.x - dx, q.y - dy));
                }
            }
        }
        Move::Flip2x2 => {
            let p = any(rng);
            let (dx, dy) = (rng.random_range(-1..=0), rng.random_range(-1..=0));
            for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let q = Pixel::new(p.x + dx + x, p.y + dy + y);
                if !set.remove(&q) {
                    set.insert(q);
                }
            }
        }
        Move::OpenHole => {
            // An internal pixel (all 8 neighbours present) becomes a one-pixel hole.
            let internal: Vec<Pixel> = (0..r.len())
                .filter(|&i| !topology::is_boundary(r, i))
                .map(|i| r.pixel(i))
                .collect();
            if internal.is_empty() {
                return None;
            }
            set.remove(&internal[rng.random_range(0..internal.len())]);
        }
        Move::CloseHole => {
            // Fill one empty cell inside the bounding box that has a pixel on every side.
            let b = r.bbox();
            let mut cells = Vec::new();
            for y in b.min_y..=b.max_y {
                for x in b.min_x..=b.max_x {
                    let p = Pixel::new(x, y);
                    if !set.contains(&p)
                        && [(1, 0), (-1, 0), (0, 1), (0, -1)]
                            .iter()
                            .all(|&(dx, dy)| set.contains(&Pixel::new(x + dx, y + dy)))
                    {
                        cells.push(p);
                    }
                }
            }
            if cells.is_empty() {
                return None;
            }
            set.insert(cells[rng.random_range(0..cells.len())]);
        }
        Move::Stretch => {
            // Duplicate one row (or column): the part above it moves up by one.
            let p = any(rng);
            let vertical = rng.random_bool(0.5);
            set = set
                .into_iter()
                .flat_map(|q| {
                    let (c, along) = if vertical { (q.y, p.y) } else { (q.x, p.x) };
                    let moved = |d| {
                        if vertical {
                            Pixel::new(q.x, q.y + d)
                        } else {
                            Pixel::new(q.x + d, q.y)
                        }
                    };
                    match c.cmp(&along) {
                        std::cmp::Ordering::Less => vec![q],
                        std::cmp::Ordering::Equal => vec![q, moved(1)],
                        std::cmp::Ordering::Greater => vec![moved(1)],
                    }
                })
                .collect();
        }
        Move::Mirror => {
            // Keep the part on one side of a column and reflect it onto the other side.
            let b = r.bbox();
            let axis = rng.random_range(b.min_x..=b.max_x);
            let left: Vec<Pixel> = set.iter().copied().filter(|q| q.x <= axis).collect();
            set = left
                .iter()
                .flat_map(|q| [*q, Pixel::new(2 * axis + 1 - q.x, q.y)])
                .collect();
        }
    }
    if set.is_empty() {
        return None;
    }
    Region::from_pixels(set).ok().map(|r| r.normalized())
}

/// Whether `r` may be a candidate: size, shape and the algorithm's precondition.
fn admissible(subject: Subject<'_>, shape: Shape, opts: &HuntOptions, r: &Region) -> bool {
    (opts.min_n..=opts.max_n).contains(&r.len())
        && shape.holds(r)
        && match subject {
            Subject::Registered(a) => (a.precondition)(r).is_ok(),
            Subject::Outside(_) => true,
        }
}

/// A generated start region of the family, admissible, from seed `seed`.
fn generated(
    subject: Subject<'_>,
    shape: Shape,
    opts: &HuntOptions,
    rng: &mut ChaCha8Rng,
) -> Option<Region> {
    // After 100 failed tries of the family's generator, the papers' tight family of the same
    // shape class (their members meet the preconditions the random ones rarely do).
    let fallback = match shape {
        Shape::Simple => Family::Band,
        Shape::Holed => Family::Donut,
        Shape::Thin => Family::Thin43,
        Shape::Boundary | Shape::Connected | Shape::Any => opts.family,
    };
    for attempt in 0..200 {
        let family = if attempt < 100 { opts.family } else { fallback };
        let mut p = GenParams::new(family, rng.random());
        p.no_cut =
            matches!(family, Family::RandomSimple | Family::RandomHoled) && rng.random_bool(0.5);
        let n = rng.random_range(opts.min_n..=opts.max_n);
        match family {
            Family::Rect => {
                let w = rng.random_range(1..=n.max(1));
                p.width = Some(w);
                p.height = Some((n / w).max(1));
            }
            Family::Donut => {
                p.k = Some(rng.random_range(1..=3));
                p.side = Some(2 * p.k.unwrap_or(1) + rng.random_range(1..=4));
            }
            Family::Band => p.k = Some(rng.random_range(1..=n.div_ceil(5).max(1))),
            Family::Thin43 => p.s = Some(rng.random_range(0..=3)),
            Family::RandomHoled | Family::Pinholes => {
                p.n = Some(n);
                p.holes = Some(rng.random_range(1..=(n / 12).clamp(1, 4)));
            }
            // Any other registered family: its generator at the drawn size when it takes one,
            // else its defaults.
            f if f.info().params.contains(&crate::generate::Param::N) => p.n = Some(n),
            _ => {}
        }
        if let Ok(g) = generate(&p) {
            let r = g.region.normalized();
            if admissible(subject, shape, opts, &r) {
                return Some(r);
            }
        }
    }
    None
}

/// An exact solve's outcome: OPT if proven, the walk found, the proven lower bound.
type Solved = (Option<u64>, Option<crate::tour::CycleCover>, u64);

/// The optimum of a region, cached by canonical form.
struct OptCache {
    map: Mutex<HashMap<String, Solved>>,
    best_map: Mutex<HashMap<String, BestKnown>>,
    solves: Mutex<(usize, usize)>,
}

impl OptCache {
    /// (OPT, lower bound, optimal walk of this very region when solved here).
    fn get(
        &self,
        r: &Region,
        objective: exact::Objective,
        limit: f64,
    ) -> (Option<u64>, u64, Option<crate::tour::CycleCover>) {
        let key = canonical(r);
        if let Some((opt, _, lb)) = self.map.lock().expect("cache").get(&key).cloned() {
            self.solves.lock().expect("count").1 += 1;
            return (opt, lb, None);
        }
        let res = exact::solve(
            r,
            objective,
            &exact::ExactOptions {
                time_limit: Some(limit),
                threads: 1,
                verbose: false,
                warm_start: None,
                max_coverage: None,
                starts: Some(crate::warm_start::from_registry),
                ..exact::ExactOptions::default()
            },
        );
        let opt = (res.status == exact::Status::Optimal)
            .then_some(res.value)
            .flatten();
        self.solves.lock().expect("count").0 += 1;
        self.map
            .lock()
            .expect("cache")
            .insert(key, (opt, res.cover.clone(), res.lower_bound));
        (opt, res.lower_bound, res.cover)
    }
}

/// What [`OptCache::best`] keeps per canonical region: the best walk's value and source,
/// whether the exact solver proved it optimal, and whether the exact solver was consulted.
type BestKnown = (Option<(u64, String, bool)>, bool);

impl OptCache {
    /// The best checked walk of `r` (value, source, the walk when computed here, proven
    /// optimal): the registered algorithms' walks, and the exact incumbent when `with_exact`.
    fn best(
        &self,
        r: &Region,
        opts: &HuntOptions,
        with_exact: bool,
    ) -> Option<(u64, String, Option<crate::tour::CycleCover>, bool)> {
        let key = canonical(r);
        if let Some((known, exact_done)) = self.best_map.lock().expect("cache").get(&key).cloned()
            && (exact_done || !with_exact)
        {
            self.solves.lock().expect("count").1 += 1;
            return known.map(|(v, s, p)| (v, s, None, p));
        }
        let algos = best::best_of_algorithms(r, opts.objective, &opts.options);
        let (walk, proven) = if with_exact {
            let (incumbent, _lb, proven) =
                best::exact_incumbent(r, opts.objective, &opts.options, opts.exact_time_limit);
            self.solves.lock().expect("count").0 += 1;
            let proven = proven
                && incumbent
                    .as_ref()
                    .is_some_and(|e| algos.as_ref().is_none_or(|a| e.value <= a.value));
            (best::better(algos, incumbent), proven)
        } else {
            (algos, false)
        };
        self.best_map.lock().expect("cache").insert(
            key,
            (
                walk.as_ref().map(|w| (w.value, w.source.clone(), proven)),
                with_exact,
            ),
        );
        walk.map(|w| (w.value, w.source, Some(w.cover), proven))
    }
}

/// One chain of the annealing.
struct Chain {
    rng: ChaCha8Rng,
    region: Region,
    ratio: f64,
    best: f64,
    since_best: usize,
}

/// What one proposal came to.
struct Outcome {
    region: Region,
    ratio: Option<f64>,
    ratio_bound: Option<f64>,
    value: Option<u64>,
    opt: Option<u64>,
    lower_bound: Option<u64>,
    walk: Option<crate::tour::CycleCover>,
    optimal_walk: Option<crate::tour::CycleCover>,
    note: String,
    findings: Vec<String>,
    best: Option<u64>,
    best_source: String,
}

/// Evaluates one candidate: the algorithm through the pipeline, then the exact optimum when the
/// screen says it may matter (`threshold`: the smallest ratio that could be accepted).
fn assess(
    subject: Subject<'_>,
    opts: &HuntOptions,
    cache: &OptCache,
    region: Region,
    threshold: f64,
) -> Outcome {
    let eval = evaluate::evaluate(
        subject,
        &region,
        &opts.options,
        &[opts.objective],
        &Reference::default(),
    );
    let mut out = Outcome {
        region,
        ratio: None,
        ratio_bound: None,
        value: None,
        opt: None,
        lower_bound: None,
        walk: None,
        optimal_walk: None,
        note: String::new(),
        findings: Vec::new(),
        best: None,
        best_source: String::new(),
    };
    if let Some(e) = &eval.error {
        out.note = format!("error: {e}");
        out.findings.push(format!("the algorithm failed: {e}"));
        return out;
    }
    let Some(c) = eval.output(opts.objective) else {
        out.note = "no output".into();
        out.findings.push(format!(
            "the algorithm returned no {} output",
            opts.objective
        ));
        return out;
    };
    out.walk = Some(c.cover.clone());
    out.lower_bound = c.lower_bound;
    if !c.valid {
        let why = c.error.clone().unwrap_or_default();
        out.note = format!("invalid: {why}");
        out.findings.push(format!("invalid walk: {why}"));
        return out;
    }
    out.value = Some(c.value);
    if let Subject::Registered(a) = subject {
        out.findings
            .extend(audit::certificates(a.name, &out.region, &eval.certificates));
    }
    out.ratio_bound = c
        .lower_bound
        .filter(|&b| b > 0)
        .map(|b| c.value as f64 / b as f64);
    let violated = c.verdicts.iter().any(|v| v.holds == Some(false));
    let undecided = c.verdicts.iter().any(|v| v.holds.is_none());
    if violated {
        out.findings.push(format!(
            "guarantee violated against the bound: value {}",
            c.value
        ));
    }
    if opts.against == Against::Best {
        // The exact incumbent is worth its time limit only where the screen lets the ratio
        // matter; above `exact_max_n` the algorithms' walks are the upper bound alone.
        let screened = out.ratio_bound.is_some_and(|rb| rb < threshold) && !undecided;
        let with_exact = !screened && out.region.len() <= opts.exact_max_n;
        let found = cache.best(&out.region, opts, with_exact);
        if !with_exact {
            out.note = if screened {
                "screened: value/bound below the acceptance threshold; best of the algorithms"
                    .into()
            } else {
                format!("N > {}: best of the algorithms", opts.exact_max_n)
            };
        }
        let Some((mut best, mut source, walk, proven)) = found else {
            out.note = "no checked walk carries the objective".into();
            return out;
        };
        if best == 0 {
            out.note = "best walk 0".into();
            return out;
        }
        if c.value < best && proven {
            out.findings.push(format!(
                "value {} below the proven optimum {best}: the exact solver or the checker is \
                 wrong",
                c.value
            ));
        }
        // The subject's own checked walk is a walk too (an outside program's may be the best).
        out.optimal_walk = walk;
        if c.value < best {
            best = c.value;
            source = subject.name().to_string();
            out.optimal_walk = Some(c.cover.clone());
        }
        out.best = Some(best);
        out.best_source = source.clone();
        if proven {
            out.opt = Some(best);
        }
        out.ratio = Some(c.value as f64 / best as f64);
        // OPT ≤ best: a value above the bound at `best` is above it at OPT.
        for g in subject.applicable(opts.objective, &out.region, &opts.options) {
            if g.bound.against == algorithms::Against::Opt
                && g.bound.quantity == algorithms::Quantity::Value
                && g.bound.scale == algorithms::Scale::One
                && !g.holds(c.value, best)
                && !violated
            {
                out.findings.push(format!(
                    "guarantee {g} violated: value {} against the best known walk {best} \
                     ({source}) >= OPT",
                    c.value
                ));
            }
        }
        return out;
    }
    let exact_obj = evaluate::exact_counterpart(opts.objective);
    let (Against::Opt, Some(exact_obj)) = (opts.against, exact_obj) else {
        out.ratio = out.ratio_bound;
        return out;
    };
    // The ratio to OPT is at most value / bound: skip the solve when even that cannot be
    // accepted and every guarantee is decided already.
    if out.ratio_bound.is_some_and(|rb| rb < threshold) && !undecided {
        out.note = "screened: value/bound below the acceptance threshold".into();
        return out;
    }
    let (opt, lb, walk) = cache.get(&out.region, exact_obj, opts.exact_time_limit);
    out.optimal_walk = walk;
    out.opt = opt;
    let Some(opt) = opt else {
        out.note = format!("exact solve unproven (bound {lb})");
        return out;
    };
    if opt == 0 {
        out.note = "optimum 0".into();
        return out;
    }
    if c.value < opt {
        out.findings.push(format!(
            "value {} below the proven optimum {opt}: the exact solver or the checker is wrong",
            c.value
        ));
    }
    out.ratio = Some(c.value as f64 / opt as f64);
    // Judge every guarantee against the proven optimum too.
    let mut reference = Reference::default();
    let known = Known {
        opt: Some(opt),
        lower_bound: Some(opt),
        status: "optimal".into(),
        source: format!("opt:{}", opts.objective),
    };
    reference.insert(opts.objective, known);
    let judged = evaluate::judge(
        subject,
        &out.region,
        &opts.options,
        opts.objective,
        c.cover.clone(),
        &reference,
    );
    for v in judged.verdicts.iter().filter(|v| v.holds == Some(false)) {
        if !violated {
            out.findings.push(format!(
                "guarantee {} violated: value {} against OPT {opt}",
                v.bound, c.value
            ));
        }
    }
    out
}

/// Runs the hunt. `report` receives one line per new worst ratio and finding; `checkpoint`
/// the report so far (records, the kept worst regions, the findings; no walk solved again)
/// after every round that found something and at least every [`CHECKPOINT_SECONDS`], so that
/// a caller can write it out and a killed hunt loses at most that much.
pub fn hunt(
    subject: Subject<'_>,
    opts: &HuntOptions,
    mut report: impl FnMut(&str),
    mut checkpoint: impl FnMut(&HuntReport) -> crate::error::Result<()>,
) -> crate::error::Result<HuntReport> {
    let start = Instant::now();
    let shape = Shape::of(opts.family);
    let cache = OptCache {
        map: Mutex::new(HashMap::new()),
        best_map: Mutex::new(HashMap::new()),
        solves: Mutex::new((0, 0)),
    };
    let chains_n = opts.chains.max(1);
    let mut chains: Vec<Chain> = Vec::new();
    for k in 0..chains_n {
        let mut rng =
            ChaCha8Rng::seed_from_u64(opts.seed.wrapping_mul(1_000_003).wrapping_add(k as u64));
        let region = match opts.starts.get(k) {
            Some(r) => r.normalized(),
            None => generated(subject, shape, opts, &mut rng).ok_or_else(|| {
                crate::Error::invalid(format!(
                    "no {} region with {}..={} pixels meets {}'s precondition \
                     (200 generated tries)",
                    opts.family.name(),
                    opts.min_n,
                    opts.max_n,
                    subject.name()
                ))
            })?,
        };
        chains.push(Chain {
            rng,
            region,
            ratio: 0.0,
            best: 0.0,
            since_best: 0,
        });
    }
    for (k, r) in opts.starts.iter().enumerate() {
        if !admissible(subject, shape, opts, &r.normalized()) {
            return Err(crate::Error::invalid(format!(
                "--start region {} does not meet the family's constraint, the size range or \
                 the algorithm's precondition",
                k + 1
            )));
        }
    }
    let mut rep = HuntReport::default();
    let mut best = 0.0f64;
    let mut worst: Vec<(String, Found)> = Vec::new();
    let mut seen_findings: BTreeSet<(String, String)> = BTreeSet::new();
    let mut evaluation = 0usize;
    let mut first_round = true;
    let mut seeded = false;
    let mut seen: std::collections::HashSet<String> = std::collections::HashSet::new();
    // The search keeps more distinct worst regions than it saves, to seed and restart chains.
    let pool = opts.keep.max(2 * chains_n);
    let mut last_checkpoint = Instant::now();
    loop {
        let found_before = (best, rep.findings.len());
        let remaining = match opts.stop {
            Stop::Evaluations(k) => k.saturating_sub(evaluation),
            Stop::Seconds(s) => {
                if start.elapsed().as_secs_f64() >= s {
                    0
                } else {
                    chains_n
                }
            }
        };
        if remaining == 0 {
            break;
        }
        let active = remaining.min(chains_n);
        // Each chain draws its proposal and its acceptance threshold (before the solve).
        let total = match opts.stop {
            Stop::Evaluations(k) => k as f64,
            Stop::Seconds(_) => 5000.0,
        };
        let progress = (evaluation as f64 / total).min(1.0);
        // The first part of the budget samples the generator widely; the chains then start
        // from the worst distinct regions it found.
        let exploring = opts.strategy == Strategy::Random
            || match opts.stop {
                Stop::Evaluations(k) => (evaluation as f64) < EXPLORE * k as f64,
                Stop::Seconds(s) => start.elapsed().as_secs_f64() < EXPLORE * s,
            };
        if !exploring && !seeded {
            seeded = true;
            for (k, ch) in chains.iter_mut().enumerate() {
                if k >= opts.starts.len()
                    && let Some((_, f)) = worst.get(k - opts.starts.len())
                {
                    ch.region = f.region.clone();
                    ch.ratio = f.ratio;
                    ch.best = f.ratio;
                }
                ch.since_best = 0;
            }
        }
        let temperature = 0.05 * (0.02f64).powf(progress);
        // (candidate, acceptance threshold, screen threshold)
        let proposals: Vec<(Region, f64, f64)> = chains[..active]
            .iter_mut()
            .map(|ch| {
                if first_round {
                    return (ch.region.clone(), f64::NEG_INFINITY, f64::NEG_INFINITY);
                }
                if exploring {
                    let r = generated(subject, shape, opts, &mut ch.rng)
                        .unwrap_or_else(|| ch.region.clone());
                    return (r, f64::NEG_INFINITY, best);
                }
                // A neighbour not evaluated before (up to symmetry): the algorithm is
                // deterministic, so a second evaluation of a region would teach nothing.
                let candidate = (0..200)
                    .find_map(|_| {
                        neighbour(&ch.region, &mut ch.rng)
                            .filter(|r| admissible(subject, shape, opts, r))
                            .filter(|r| !seen.contains(&canonical(r)))
                    })
                    .unwrap_or_else(|| ch.region.clone());
                // Metropolis: accept a ratio r with probability min(1, exp((r - current) / T)),
                // i.e. when r >= current + T ln u for u drawn now.
                let u: f64 = ch.rng.random_range(1e-12..1.0);
                let accept = ch.ratio + temperature * u.ln();
                (candidate, accept, accept.min(best))
            })
            .collect();
        first_round = false;
        let outcomes: Vec<(Outcome, f64)> = proposals
            .into_par_iter()
            .map(|(r, accept, screen)| (assess(subject, opts, &cache, r, screen), accept))
            .collect();
        for (k, (out, accept)) in outcomes.into_iter().enumerate() {
            evaluation += 1;
            let ch = &mut chains[k];
            let accepted = !exploring && out.ratio.is_some_and(|r| r >= accept);
            if accepted {
                ch.region = out.region.clone();
                ch.ratio = out.ratio.unwrap_or(0.0);
            }
            ch.since_best += 1;
            if let Some(r) = out.ratio
                && r > ch.best
            {
                ch.best = r;
                ch.since_best = 0;
            }
            let key = canonical(&out.region);
            seen.insert(key.clone());
            for what in &out.findings {
                if seen_findings.insert((key.clone(), what.clone())) {
                    report(&format!("FINDING at evaluation {evaluation}: {what}"));
                    rep.findings.push(Found {
                        region: out.region.clone(),
                        ratio: out.ratio.unwrap_or(f64::NAN),
                        value: out.value.unwrap_or(0),
                        reference: out.best.or(out.opt).or(out.lower_bound),
                        walk: out.walk.clone(),
                        optimal_walk: out.optimal_walk.clone(),
                        evaluation,
                        what: what.clone(),
                        best_source: out.best_source.clone(),
                    });
                }
            }
            if let Some(r) = out.ratio {
                if r > best {
                    best = r;
                    report(&format!(
                        "evaluation {evaluation}: new worst ratio {r:.4} (N = {})",
                        out.region.len()
                    ));
                }
                keep_worst(&mut worst, key, pool, || Found {
                    region: out.region.clone(),
                    ratio: r,
                    value: out.value.unwrap_or(0),
                    reference: match opts.against {
                        Against::Opt => out.opt,
                        Against::Bound => out.lower_bound,
                        Against::Best => out.best,
                    },
                    walk: out.walk.clone(),
                    optimal_walk: out.optimal_walk.clone(),
                    evaluation,
                    what: String::new(),
                    best_source: out.best_source.clone(),
                });
            }
            rep.records.push(Record {
                evaluation,
                elapsed: start.elapsed().as_secs_f64(),
                chain: k,
                ratio: out.ratio,
                ratio_bound: out.ratio_bound,
                best_so_far: best,
                n: out.region.len(),
                sha256: crate::harness::run::sha256_hex(out.region.to_ascii().as_bytes()),
                value: out.value,
                opt: out.opt,
                lower_bound: out.lower_bound,
                accepted,
                note: out.note,
                best: out.best,
                best_source: out.best_source,
            });
            // Restart a chain that has stalled: from the best region or a fresh one.
            if ch.since_best >= opts.patience {
                ch.since_best = 0;
                ch.best = 0.0;
                let from_best = ch.rng.random_bool(0.7);
                let pick = ch.rng.random_range(0..worst.len().max(1));
                match worst.get(pick) {
                    Some((_, f)) if from_best => {
                        ch.region = f.region.clone();
                        ch.ratio = f.ratio;
                    }
                    _ => {
                        if let Some(r) = generated(subject, shape, opts, &mut ch.rng) {
                            ch.region = r;
                            ch.ratio = 0.0;
                        }
                    }
                }
            }
        }
        if found_before != (best, rep.findings.len())
            || last_checkpoint.elapsed().as_secs_f64() >= CHECKPOINT_SECONDS
        {
            let (solves, hits) = *cache.solves.lock().expect("count");
            checkpoint(&HuntReport {
                records: rep.records.clone(),
                worst: worst
                    .iter()
                    .take(opts.keep)
                    .map(|(_, f)| f.clone())
                    .collect(),
                findings: rep.findings.clone(),
                exact_solves: solves,
                cache_hits: hits,
                seconds: start.elapsed().as_secs_f64(),
            })?;
            last_checkpoint = Instant::now();
        }
    }
    rep.worst = worst.into_iter().take(opts.keep).map(|(_, f)| f).collect();
    // A cache hit has no walk of this very region: solve the kept ones again for their figure.
    if let Some(exact_obj) = evaluate::exact_counterpart(opts.objective) {
        for f in rep.worst.iter_mut().chain(rep.findings.iter_mut()) {
            if f.optimal_walk.is_none() && opts.against == Against::Best {
                let exact = (f.region.len() <= opts.exact_max_n).then(|| {
                    best::exact_incumbent(
                        &f.region,
                        opts.objective,
                        &opts.options,
                        opts.exact_time_limit,
                    )
                    .0
                });
                let algos = best::best_of_algorithms(&f.region, opts.objective, &opts.options);
                f.optimal_walk = best::better(algos, exact.flatten()).map(|w| w.cover);
            } else if f.optimal_walk.is_none() && f.region.len() <= opts.exact_max_n {
                let res = exact::solve(
                    &f.region,
                    exact_obj,
                    &exact::ExactOptions {
                        time_limit: Some(opts.exact_time_limit),
                        threads: 1,
                        verbose: false,
                        warm_start: None,
                        max_coverage: None,
                        starts: Some(crate::warm_start::from_registry),
                        ..exact::ExactOptions::default()
                    },
                );
                f.optimal_walk = res.cover;
            }
        }
    }
    let (solves, hits) = *cache.solves.lock().expect("count");
    rep.exact_solves = solves;
    rep.cache_hits = hits;
    rep.seconds = start.elapsed().as_secs_f64();
    Ok(rep)
}

/// Keeps the `keep` worst distinct regions (by canonical key), worst first; ties keep the
/// earlier one.
fn keep_worst(
    worst: &mut Vec<(String, Found)>,
    key: String,
    keep: usize,
    found: impl FnOnce() -> Found,
) {
    if worst.iter().any(|(k, _)| *k == key) {
        return;
    }
    let f = found();
    let pos = worst.partition_point(|(_, w)| w.ratio >= f.ratio);
    if pos < keep {
        worst.insert(pos, (key, f));
        worst.truncate(keep);
    }
}

/// The registered algorithm or error.
pub fn registered(name: &str) -> crate::error::Result<&'static algorithms::Algorithm> {
    algorithms::find(name).ok_or_else(|| {
        crate::Error::invalid(format!(
            "unknown algorithm {name:?}: expected one of {}",
            algorithms::names().join(", ")
        ))
    })
}
