//! The violating instances of a claims table, saved with their tours and figures, and the
//! evidence of the discrete greedy choices (`mowmill orders`).

use super::*;
use crate::algorithms::Objective;
use crate::checker::Mode;
use crate::model::{InstanceModel, Kind};

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

/// A claim's name in file names: lower-case letters and digits, anything else `-`.
pub(crate) fn claim_slug(claim: &str) -> String {
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

/// The walk a run kept for a violating row ([`crate::harness::walks`]), as the note tells it.
enum KeptWalk<C> {
    /// Read from `path`.
    Read { walk: C, path: std::path::PathBuf },
    /// The run folder has no walk for the row: a run of an older mowmill.
    Missing,
    /// The file is there but does not parse: data, told in the note.
    Unreadable(String),
}

/// The walk the run in `from` kept for the row (`instance`, `algo`, `objective`), read by the
/// model's tour reader `read`.
fn kept_walk<C>(
    from: &Path,
    instance: &str,
    algo: &str,
    objective: &str,
    read: impl FnOnce(&Path) -> Result<C>,
) -> KeptWalk<C> {
    let path = crate::harness::walks::path(from, instance, algo, objective);
    if !path.exists() {
        return KeptWalk::Missing;
    }
    match read(&path) {
        Ok(walk) => KeptWalk::Read { walk, path },
        Err(e) => KeptWalk::Unreadable(format!(
            "the run's walk {} is unreadable: {e}",
            path.display()
        )),
    }
}

/// The note's line for a row whose run kept no walk: how to see it (a `solve` of the row's
/// variant), since claims never runs an algorithm.
fn missing_walk_line(algo: &str, objective: &str, instance_file: &Path) -> String {
    let (name, flags) = match crate::evaluate::parse_variant(algo) {
        Ok((name, o)) => {
            // The options the variant name carries: those that differ from the defaults.
            let default = crate::algorithms::Options::default();
            let mut flags = String::new();
            if o.merge != default.merge {
                let _ = write!(flags, " --merge {}", o.merge);
            }
            if o.cutter != default.cutter {
                let _ = write!(flags, " --cutter {}", o.cutter);
            }
            if o.coverage4 {
                flags.push_str(" --coverage4");
            }
            (name, flags)
        }
        Err(_) => (algo, String::new()),
    };
    format!(
        "walk: the run did not keep this walk (a run of an older mowmill, from before `walks/`); \
         re-run `mowmill solve --algo {name}{flags} --objective {objective} --tour-out WALK.tour.json {}` \
         (an outside algorithm: `--command` with its config's command) to see it",
        instance_file.display()
    )
}

/// Copies the run's walk at `path` (in the run folder `from`) to `to`, and adds the note's line
/// naming it (relative to the run folder, so that the note does not depend on where it lies).
fn copy_walk(path: &Path, from: &Path, to: &Path, note: &mut String) -> Result<()> {
    std::fs::copy(path, to).map_err(|e| Error::io(to, e))?;
    let shown = path.strip_prefix(from).unwrap_or(path);
    let _ = writeln!(note, "walk: as the run wrote it, {}", shown.display());
    Ok(())
}

/// Draws a figure with `draw`, a panic or error becoming the note's "not drawn" line (a walk
/// read from a file may not fit the instance).
fn draw_figure(
    path: std::path::PathBuf,
    note: &mut String,
    written: &mut Vec<std::path::PathBuf>,
    draw: impl FnOnce(&Path) -> Result<()>,
) {
    match crate::evaluate::guarded(|| draw(&path)) {
        Ok(()) => written.push(path),
        Err(e) => {
            let _ = writeln!(note, "not drawn: {e}");
        }
    }
}

/// The note's first lines, common to every model.
fn note_head(c: &ClaimRow, algo: &str, objective: &str, instance: &str, size: &str) -> String {
    format!(
        "# {} ({}) violated\n\nalgorithm: {algo}, objective: {objective}, instance: {instance}, {size}\n\
         claim: {} ({})\nimplementation: {}\n",
        c.claim, c.paper, c.factor, c.statement, c.implementation
    )
}

/// One violating row of a claim: its run folder `from`, its instance's name there and the
/// instance file `src` (under `from/instances/`).
struct Finding<'a> {
    claim: &'a ClaimRow,
    algo: &'a str,
    objective: &'a str,
    instance: &'a str,
    from: &'a Path,
    src: &'a Path,
}

impl Finding<'_> {
    fn stem(&self) -> String {
        format!(
            "{}-{}-{}",
            claim_slug(&self.claim.claim),
            self.algo,
            self.instance
        )
    }

    /// Copies the instance file into `dir`.
    fn copy_instance(&self, dir: &Path) -> Result<std::path::PathBuf> {
        // The instance was found under `instances/` by its extension.
        let ext = self.src.extension().and_then(|e| e.to_str()).unwrap_or("");
        let copy = dir.join(format!("{}.{ext}", self.stem()));
        std::fs::copy(self.src, &copy).map_err(|e| Error::io(&copy, e))?;
        Ok(copy)
    }

    fn title(&self) -> String {
        format!("{}: {} on {}", self.claim.claim, self.algo, self.instance)
    }
}

/// [`save_findings`] for one violating row of an instance of model `M`: the instance file,
/// the walk the run kept for the row, recounted by the model's checker (its `validate`
/// line), its figure (none for lawn tours, which no figure draws) and a note.
fn save_finding<M: InstanceModel>(f: &Finding<'_>, dir: &Path) -> Result<Vec<std::path::PathBuf>> {
    let mut written = vec![f.copy_instance(dir)?];
    let inst = M::read(f.src)?;
    let mut note = note_head(f.claim, f.algo, f.objective, f.instance, &inst.size());
    let walk = match kept_walk(f.from, f.instance, f.algo, f.objective, M::read_walk) {
        KeptWalk::Read { walk, path } => Some((walk, path)),
        KeptWalk::Missing => {
            let _ = writeln!(note, "{}", missing_walk_line(f.algo, f.objective, f.src));
            None
        }
        KeptWalk::Unreadable(why) => {
            let _ = writeln!(note, "walk: {why}");
            None
        }
    };
    if let Some((walk, path)) = walk {
        let tour = dir.join(format!("{}.tour.json", f.stem()));
        copy_walk(&path, f.from, &tour, &mut note)?;
        written.push(tour);
        let checked = f
            .objective
            .parse::<Objective>()
            .map_err(Error::invalid)
            .and_then(|objective| Ok((objective, inst.validation(&walk, objective.mode())?)));
        match checked {
            Ok((objective, v)) => {
                let _ = writeln!(note, "checked output: {}", v.line);
                if objective.mode() != Mode::Lawn {
                    draw_figure(
                        dir.join(format!("{}.{}", f.stem(), M::FIGURE)),
                        &mut note,
                        &mut written,
                        |out| inst.draw(Some(&walk), out, f.title()),
                    );
                }
            }
            Err(e) => {
                let _ = writeln!(note, "not checked: objective {}: {e}", f.objective);
            }
        }
    }
    let md = dir.join(format!("{}.md", f.stem()));
    std::fs::write(&md, note).map_err(|e| Error::io(&md, e))?;
    written.push(md);
    Ok(written)
}

/// Saves the violating instances of every violated claim into `dir`: for each (at most
/// [`FINDINGS_LISTED`] per claim) the instance file copied from `from/instances/`, the walk the
/// run kept for the row in `from/walks/` ([`crate::harness::walks`]) as tour JSON, recounted by
/// the model's checker, its figure and a note naming the claim, the values and whether the
/// violating algorithm is the paper's or our reading. No algorithm is run: where the run kept no
/// walk (a run of an older mowmill) or the file does not parse, the note says so. Returns the
/// files written.
pub fn save_findings(
    table: &[ClaimRow],
    sources: &Sources,
    dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
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
            let Some(src) = ["dm", "json", "vox", "hex", "grid", "wkt"]
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
            let finding = Finding {
                claim: c,
                algo,
                objective,
                instance,
                from,
                src: &src,
            };
            written.extend(match Kind::of(&src) {
                Kind::Grid => save_finding::<crate::region::Region>(&finding, dir)?,
                Kind::Discrete => save_finding::<crate::discrete::Discrete>(&finding, dir)?,
                Kind::Ortho => save_finding::<crate::ortho::Polygon>(&finding, dir)?,
            });
        }
    }
    Ok(written)
}
