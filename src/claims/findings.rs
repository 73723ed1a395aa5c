//! The violating instances of a claims table, saved with their tours and figures, and the
//! evidence of the discrete greedy choices (`mowmill orders`).

use super::*;

/// Whether the header line of the CSV file at `path` names `column`.
fn has_column(path: &Path, column: &str) -> Result<bool> {
    use std::io::{BufRead, Read};
    let file = crate::harness::rows::open_regular(
        path,
        crate::harness::rows::MAX_RESULTS_BYTES,
        "a results.csv",
    )?;
    let mut header = String::new();
    std::io::BufReader::new(file.take(1 << 16))
        .read_line(&mut header)
        .map_err(|e| Error::io(path, e))?;
    Ok(header.trim_end().split(',').any(|c| c == column))
}

/// Whether `r` is a registered algorithm's row without theorem ids although the algorithm
/// claims an unconditional theorem for its objective: a row of an older mowmill.
fn lacks_theorem_ids(r: &Row) -> bool {
    r.theorems.is_empty()
        && crate::algorithms::find(base_name(&r.algorithm)).is_some_and(|a| {
            a.claims.iter().any(|c| {
                c.theorem.when == When::Always
                    && c.objectives.iter().any(|o| o.name() == r.objective)
            })
        })
}

/// The results directories a claims table is computed from. With more than one, each row's
/// instance is named `RUN/INSTANCE` (RUN the directory's name), so that equal instance names of
/// different runs (the same family, parameters and index under another master seed) never meet.
pub struct Sources {
    dirs: Vec<(String, std::path::PathBuf)>,
}

impl Sources {
    /// # Errors
    /// [`Error::Invalid`] when no directory is given or two have the same name.
    pub fn new(dirs: &[std::path::PathBuf]) -> Result<Sources> {
        if dirs.is_empty() {
            return Err(Error::invalid("claims: no results directory (--from DIR)"));
        }
        let named: Vec<(String, std::path::PathBuf)> = dirs
            .iter()
            .map(|d| {
                let name = d
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_else(|| d.display().to_string());
                (name, d.clone())
            })
            .collect();
        let mut names: Vec<&str> = named.iter().map(|(n, _)| n.as_str()).collect();
        names.sort_unstable();
        if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
            return Err(Error::invalid(format!(
                "claims: two results directories are both named {}: their instances could not be told apart",
                w[0]
            )));
        }
        Ok(Sources { dirs: named })
    }

    /// Every row of every directory's `results.csv`, instances prefixed with `RUN/` when there
    /// are several.
    pub fn read_rows(&self) -> Result<Vec<Row>> {
        let mut rows = Vec::new();
        for (name, dir) in &self.dirs {
            let path = dir.join("results.csv");
            let mut read = crate::harness::rows::read_results(&path)?;
            // Claims join on the rows' theorem ids: rows written before the column existed
            // cannot say which conditioned theorems apply to them.
            if !has_column(&path, "theorems")? {
                return Err(Error::parse(
                    &path.display().to_string(),
                    1,
                    1,
                    "expected a header with the `theorems` column (this results.csv was written \
                     by an older mowmill, whose rows do not say which theorems apply to them: \
                     run its suite again)",
                ));
            }
            if let Some(r) = read.iter().find(|r| lacks_theorem_ids(r)) {
                return Err(Error::invalid(format!(
                    "{}: the row {} carries no theorem ids although its algorithm claims a \
                     theorem for {} on every instance: it was written by an older mowmill \
                     (a resumed run keeps such rows); run the suite again into a fresh folder",
                    path.display(),
                    r.describe(),
                    r.objective
                )));
            }
            // An inconsistent row (below its proven bound, or a value that is not its own
            // count) is an invalid result: it is evidence of nothing and breaks its claims.
            for r in &mut read {
                r.mark_inconsistent();
            }
            if self.dirs.len() > 1 {
                for r in &mut read {
                    r.instance = format!("{name}/{}", r.instance);
                }
            }
            rows.extend(read);
        }
        Ok(rows)
    }

    /// The directories as the table's source line names them.
    pub fn describe(&self) -> String {
        self.dirs
            .iter()
            .map(|(_, d)| d.display().to_string())
            .collect::<Vec<_>>()
            .join(" + ")
    }

    /// The directory holding an instance of [`Sources::read_rows`], and its name there.
    fn locate<'a>(&'a self, instance: &'a str) -> Option<(&'a Path, &'a str)> {
        if self.dirs.len() == 1 {
            return Some((&self.dirs[0].1, instance));
        }
        let (run, name) = instance.split_once('/')?;
        self.dirs
            .iter()
            .find(|(n, _)| n == run)
            .map(|(_, d)| (d.as_path(), name))
    }
}

/// Adds to each violated claim whose witness is a star cover (the greedy order of its rooks
/// is a choice the paper leaves open, Lemma 4.5) whether the violation depends on that order
/// or survives every one: [`crate::discrete::choices::order_evidence`] re-runs the star cover
/// on the witness over every rook set (exhaustive up to its cap, else sampled orders) and
/// re-decides the same bound. Merge orders are not enumerated: a violation of Theorem 4.2 that
/// survives every merge order is the statement contradicted (a lower bound on every tour).
pub fn add_choice_evidence(table: &mut [ClaimRow], sources: &Sources) {
    use crate::discrete::choices::{ChoiceValue, order_evidence};
    for c in table.iter_mut().filter(|c| is_violated(c)) {
        // The witness first, then the other violating instances (at most FINDINGS_LISTED).
        let mut rows: Vec<Violation> = c
            .violations_detail
            .iter()
            .filter(|v| matches!(v.algorithm.as_str(), "star-cover" | "discrete-star-cover"))
            .cloned()
            .collect();
        rows.sort_by_key(|v| {
            format!("{} {} {}", v.algorithm, v.objective, v.instance) != c.witness
        });
        rows.dedup_by(|a, b| a.instance == b.instance && a.objective == b.objective);
        rows.truncate(FINDINGS_LISTED);
        let mut every_order = Vec::new();
        for (k, w) in rows.iter().enumerate() {
            let Some((from, name)) = sources.locate(&w.instance) else {
                continue;
            };
            let Some(inst) = load_as_discrete(from, name) else {
                continue;
            };
            let evidence = match (w.bound, w.objective.as_str()) {
                (Some((b, x)), "cc-turns") => {
                    order_evidence(&w.algorithm, &inst, ChoiceValue::CcTurns, |v| {
                        !b.holds(v, x)
                    })
                }
                (Some((b, x)), "turns") => {
                    order_evidence(&w.algorithm, &inst, ChoiceValue::TourTurns, |v| {
                        !b.holds(v, x)
                    })
                }
                _ => continue,
            };
            match evidence {
                Ok(e) => {
                    if k == 0 {
                        let _ = write!(c.note, " Greedy order on the witness: {}.", e.summary());
                    }
                    if e.every_order_violates() {
                        every_order.push(format!("{} ({} rook sets)", w.instance, e.tried));
                    }
                }
                Err(e) if k == 0 => {
                    let _ = write!(c.note, " Greedy order: not evaluated ({e}).");
                }
                Err(_) => {}
            }
        }
        if !every_order.is_empty() {
            let _ = write!(
                c.note,
                " Violated by every order of the greedy choices (exhaustive) on: {}.",
                every_order.join(", ")
            );
        }
    }
}

/// The instance `name` of the results directory `from` as a discrete instance (a grid region
/// through [`crate::discrete::Discrete::from_region`]); `None` when not saved there.
fn load_as_discrete(from: &Path, name: &str) -> Option<crate::discrete::Discrete> {
    let dir = from.join("instances");
    for ext in ["dm", "vox", "hex"] {
        let p = dir.join(format!("{name}.{ext}"));
        if p.exists() {
            return crate::discrete::generate::read(&p).ok();
        }
    }
    let p = dir.join(format!("{name}.grid"));
    let inst = crate::instance::Instance::read(&p).ok()?;
    Some(crate::discrete::Discrete::from_region(&inst.region))
}

/// The registered algorithm and the options of a row's algorithm column (a variant name such
/// as `strips-matching[merge=naive,coverage4]` runs with its options, as the run did).
fn rerun_of(
    variant: &str,
) -> Result<(
    &'static crate::algorithms::Algorithm,
    crate::algorithms::Options,
)> {
    let (name, options) = crate::evaluate::parse_variant(variant)?;
    let a = crate::algorithms::find(name).ok_or_else(|| {
        Error::invalid(format!(
            "{name} is not a registered algorithm (an outside algorithm's walk is not kept)"
        ))
    })?;
    Ok((a, options))
}

/// A claim's name in file names: lower-case letters and digits, anything else `-`.
fn claim_slug(claim: &str) -> String {
    claim
        .chars()
        .map(|ch| {
            if ch.is_ascii_alphanumeric() {
                ch.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}

/// [`save_findings`] for a discrete instance: the instance file, the algorithm's walk of the
/// objective (run again on the instance, recounted by the discrete checker), a note and, where
/// the instance has coordinates, an SVG.
fn save_discrete_finding(
    c: &ClaimRow,
    algo: &str,
    objective: &str,
    instance: &str,
    src: &Path,
    dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
    use crate::discrete::{check, draw};
    let mut written = Vec::new();
    let stem = format!("{}-{algo}-{instance}", claim_slug(&c.claim));
    let ext = src.extension().and_then(|e| e.to_str()).unwrap_or("dm");
    let copy = dir.join(format!("{stem}.{ext}"));
    std::fs::copy(src, &copy).map_err(|e| Error::io(&copy, e))?;
    written.push(copy);
    let inst = crate::discrete::generate::read(src)?;
    let mut note = format!(
        "# {} ({}) violated\n\nalgorithm: {algo}, objective: {objective}, instance: {instance}, n = {}\n\
         claim: {} ({})\nimplementation: {}\n",
        c.claim,
        c.paper,
        inst.len(),
        c.factor,
        c.statement,
        c.implementation
    );
    let (run, options) = match rerun_of(algo) {
        Ok((a, options)) => (a.discrete, options),
        Err(e) => {
            let _ = writeln!(note, "not re-run: {e}");
            (None, crate::algorithms::Options::default())
        }
    };
    if let Some(run) = run {
        match run(&inst, &options) {
            Ok(sol) => {
                if let Some(out) = sol.outputs.iter().find(|o| o.objective.name() == objective) {
                    let rep = check::check(&inst, &out.cover.cycles);
                    let walk = dir.join(format!("{stem}.tour.json"));
                    out.cover.write(&walk)?;
                    written.push(walk);
                    let _ = writeln!(
                        note,
                        "checked output: valid {}, length {}, turns {}, cycles {}, max coverage {}",
                        rep.valid, rep.length, rep.turns, rep.cycles, rep.max_coverage
                    );
                    let svg = dir.join(format!("{stem}.svg"));
                    let opts = crate::draw::DrawOptions {
                        title: Some(format!("{}: {algo} on {instance}", c.claim)),
                        caption: Some(draw::caption(&inst, Some(&out.cover.cycles))),
                        ..crate::draw::DrawOptions::default()
                    };
                    match draw::draw(&inst, Some(&out.cover.cycles), &svg, &opts) {
                        Ok(()) => written.push(svg),
                        Err(e) => {
                            let _ = writeln!(note, "not drawn: {e}");
                        }
                    }
                }
            }
            Err(e) => {
                let _ = writeln!(note, "the algorithm failed on it: {e}");
            }
        }
    }
    let md = dir.join(format!("{stem}.md"));
    std::fs::write(&md, note).map_err(|e| Error::io(&md, e))?;
    written.push(md);
    Ok(written)
}

/// Saves the violating instances of every violated claim into `dir`: for each (at most
/// [`FINDINGS_LISTED`] per claim) the instance file copied from `from/instances/`, the
/// algorithm's output re-run on it with the row's variant options (algorithms are deterministic)
/// as tour JSON (a note says why where it cannot be re-run), its figure
/// (PNG) and a note naming the claim, the values and whether the violating algorithm is the
/// paper's or our reading. Returns the files written.
pub fn save_findings(
    table: &[ClaimRow],
    sources: &Sources,
    dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
    use crate::algorithms::Objective;
    use crate::checker;
    let mut written = Vec::new();
    for c in table.iter().filter(|c| is_violated(c)) {
        let mut seen = BTreeSet::new();
        for (algo, objective, instance) in &c.violating {
            if !seen.insert((algo, instance)) || seen.len() > FINDINGS_LISTED {
                continue;
            }
            std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
            let Some((from, instance)) = sources.locate(instance) else {
                continue;
            };
            if let Some(src) = ["dm", "vox", "hex"]
                .iter()
                .map(|ext| from.join("instances").join(format!("{instance}.{ext}")))
                .find(|p| p.exists())
            {
                written.extend(save_discrete_finding(
                    c, algo, objective, instance, &src, dir,
                )?);
                continue;
            }
            let Some(src) = ["grid", "wkt"]
                .iter()
                .map(|ext| from.join("instances").join(format!("{instance}.{ext}")))
                .find(|p| p.exists())
            else {
                eprintln!(
                    "claims: {}: instance {instance} (a violation of {}) is not saved under instances/; \
                     no finding written for it",
                    from.display(),
                    c.claim
                );
                continue;
            };
            let stem = format!("{}-{algo}-{instance}", claim_slug(&c.claim));
            let ext = src.extension().and_then(|e| e.to_str()).unwrap_or("grid");
            let copy = dir.join(format!("{stem}.{ext}"));
            std::fs::copy(&src, &copy).map_err(|e| Error::io(&copy, e))?;
            written.push(copy);
            let inst = crate::instance::Instance::read(&src)?;
            let mut note = format!(
                "# {} ({}) violated\n\nalgorithm: {algo}, objective: {objective}, instance: {instance}, N = {}\n\
                 claim: {} ({})\nimplementation: {}\n",
                c.claim,
                c.paper,
                inst.region.len(),
                c.factor,
                c.statement,
                c.implementation
            );
            let (a, options) = match rerun_of(algo) {
                Ok(found) => found,
                Err(e) => {
                    let _ = writeln!(note, "not re-run: {e}");
                    let path = dir.join(format!("{stem}.md"));
                    std::fs::write(&path, note).map_err(|e| Error::io(&path, e))?;
                    written.push(path);
                    continue;
                }
            };
            match (a.run)(&inst.region, &options) {
                Ok(sol) => {
                    if let Some(out) = sol.outputs.iter().find(|o| o.objective.name() == objective)
                    {
                        let rep = checker::check(&inst.region, &out.cover, out.objective.mode());
                        let tour = dir.join(format!("{stem}.tour.json"));
                        out.cover.write(&tour)?;
                        written.push(tour);
                        let _ = writeln!(
                            note,
                            "checked output: valid {}, length {}, turns {}, cycles {}, max coverage {}",
                            rep.valid, rep.length, rep.turns, rep.cycles, rep.max_coverage
                        );
                        if out.objective != Objective::LawnLength {
                            let png = dir.join(format!("{stem}.png"));
                            let opts = crate::draw::DrawOptions {
                                title: Some(format!("{}: {algo} on {instance}", c.claim)),
                                caption: Some(format!(
                                    "N = {}, length {}, turns {}",
                                    inst.region.len(),
                                    rep.length,
                                    rep.turns
                                )),
                                ..crate::draw::DrawOptions::default()
                            };
                            crate::draw::draw(&inst.region, Some(&out.cover), &png, &opts)?;
                            written.push(png);
                        }
                    }
                }
                Err(e) => {
                    let _ = writeln!(note, "re-run failed: {e}");
                }
            }
            let path = dir.join(format!("{stem}.md"));
            std::fs::write(&path, note).map_err(|e| Error::io(&path, e))?;
            written.push(path);
        }
    }
    Ok(written)
}
