//! The checked walks a run keeps in `RUN/walks/`: those of the rows the claims table could find
//! violated, so that `mowmill claims` saves its findings from the walks the run wrote and never
//! runs an algorithm again.
//!
//! Layout: `RUN/walks/<instance>/<variant>.<objective>.tour.json`, one file per kept row, in the
//! tour JSON of the row's model (grid [`CycleCover`](crate::tour::CycleCover), discrete
//! [`DiscreteCover`](crate::discrete::format::DiscreteCover), orthogonal
//! [`Tour`](crate::ortho::Tour)). `<instance>` is the row's instance name, as in `instances/`;
//! `<variant>` and `<objective>` are the row's `algorithm` and `objective` columns with every
//! byte outside `A-Z a-z 0-9 - _` written `%XX` (upper-case hex), so that a variant such as
//! `strips-matching[merge=naive,coverage4]` becomes
//! `strips-matching%5Bmerge%3Dnaive%2Ccoverage4%5D`: the mapping is injective (`.` and `%` are
//! encoded too, so the first `.` ends the variant) and the name never leaves the folder.

use super::rows::Row;
use crate::algorithms::theorems::{Decision, Known, Measure, Theorem};
use crate::algorithms::{Against, Objective, Quantity, Scale};
use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// The folder of a run that holds the kept walks.
pub const DIR: &str = "walks";

/// One checked walk the run keeps: the row it belongs to (its `algorithm` and `objective`
/// columns) and the walk in its model's tour JSON.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Kept {
    pub algorithm: String,
    pub objective: String,
    pub json: String,
}

/// `text` with every byte outside `A-Z a-z 0-9 - _` written `%XX`.
fn encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || b == b'-' || b == b'_' {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// The file name of the walk of the row (`variant`, `objective`) (module docs).
pub fn file_name(variant: &str, objective: &str) -> String {
    format!("{}.{}.tour.json", encode(variant), encode(objective))
}

/// Where the run in `run` keeps the walk of the row (`instance`, `variant`, `objective`).
pub fn path(run: &Path, instance: &str, variant: &str, objective: &str) -> PathBuf {
    run.join(DIR)
        .join(instance)
        .join(file_name(variant, objective))
}

/// Whether the claims table could find `row` violated, so that the run keeps its walk: the
/// row's output is invalid or inconsistent, or one of its `theorems` (those of its `theorems`
/// column) is not shown to hold by what the evaluation knows ([`shown_to_hold`]).
///
/// Why this covers every violation `claims` can find: the claims table decides a row's bound
/// with [`crate::algorithms::theorems::Bound::decide`] knowing at least what the evaluation knows
/// (the same X against N or 1, the same proven optimum, a lower bound at least as large) plus an
/// upper bound on OPT, the best checked walk `u ≥ OPT`. When the evaluation's knowledge shows
/// `q ≤ f·X` exactly, the claims table decides the same; when it shows `q ≤ f·lb` with a proven
/// `lb ≤ OPT ≤ u`, the bound also holds at `u` (it grows with X: its factors are positive), so
/// the upper bound can never show it violated and the larger lower bound shows it held. The
/// measures that compare a row with another row (Theorem 4.2 and Corollary 4.1 against the cycle
/// cover, Theorem 5.6 against the run without `--coverage4`) are not judged by the evaluation:
/// their rows are always kept. Lemma 4.4 is violated only by a row whose lower bound exceeds its
/// optimum, which is an inconsistent row.
pub fn claims_may_violate(row: &Row, theorems: &[&Theorem]) -> bool {
    row.valid != Some(true)
        || row.consistency_error().is_some()
        || !theorems.iter().all(|t| shown_to_hold(t, row))
}

/// Whether `theorem`'s measure is shown to hold on `row` from the row alone (its value, N, its
/// proven optimum and lower bound), as the claims table measures it.
fn shown_to_hold(theorem: &Theorem, row: &Row) -> bool {
    let bound = match theorem.measure {
        // Nothing is measured on rows.
        Measure::Nothing | Measure::TightOnly => return true,
        Measure::Bound(b) => b,
        Measure::StripBound
        | Measure::Merge
        | Measure::MergeHalf
        | Measure::Coverage4SameTurns
        | Measure::Coverage4LengthCoverage => return false,
    };
    let Some(b) = row
        .params()
        .and_then(|p| bound.on(&p))
        .or_else(|| (bound.scale == Scale::One).then_some(bound))
    else {
        return false;
    };
    let q = match b.quantity {
        Quantity::Value => row.value,
        Quantity::Length => row.length,
        Quantity::MaxCoverage => row.max_coverage,
    };
    let Some(q) = q else {
        return false;
    };
    let b = b.in_units(
        row.unit.unwrap_or(1),
        row.objective == Objective::Length.name(),
    );
    let known = match (b.against, b.quantity) {
        (Against::N | Against::One, _) => Known::default(),
        // A length against OPT of length: N ≤ OPT for N ≥ 2 (every pixel or vertex is left by
        // a step), as the claims table takes it; no bound in the units of an ortho row.
        (Against::Opt, Quantity::Length) if row.model == "ortho" || row.n < 2 => return false,
        (Against::Opt, Quantity::Length) => Known {
            opt: None,
            lower: Some(row.n),
            upper: None,
        },
        (Against::Opt, _) => Known {
            opt: row.opt,
            lower: row.lower_bound,
            upper: None,
        },
    };
    matches!(b.decide(q, row.n, known), Decision::Holds { .. })
}

/// Writes the kept walks of one instance into `out/walks/<instance>/`, each through a temporary
/// file renamed into place (a killed run leaves whole files or none). The runner writes them
/// before the instance's rows, so that every row in `results.csv` that needs a walk has it; a
/// resumed run writes those of the rows it runs again.
pub fn write(out: &Path, instance: &str, walks: &[Kept]) -> Result<()> {
    if walks.is_empty() {
        return Ok(());
    }
    let dir = out.join(DIR).join(instance);
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    for w in walks {
        let path = dir.join(file_name(&w.algorithm, &w.objective));
        write_atomic(&path, format!("{}\n", w.json).as_bytes())?;
    }
    Ok(())
}

fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, bytes).map_err(|e| Error::io(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e))
}

/// Copies the kept walks of the run `from` into the run `out` (a merge of shards); returns the
/// number of files. A walk `out` already holds with other bytes is refused: two shards that
/// disagree on a row's walk are not slices of one run.
pub fn merge_into(from: &Path, out: &Path) -> Result<usize> {
    let src = from.join(DIR);
    let Ok(instances) = std::fs::read_dir(&src) else {
        return Ok(0);
    };
    let mut copied = 0;
    for instance in instances.flatten() {
        if !instance.path().is_dir() {
            continue;
        }
        let to_dir = out.join(DIR).join(instance.file_name());
        std::fs::create_dir_all(&to_dir).map_err(|e| Error::io(&to_dir, e))?;
        let files =
            std::fs::read_dir(instance.path()).map_err(|e| Error::io(&instance.path(), e))?;
        for f in files.flatten() {
            let name = f.file_name();
            // A temporary file of a killed run is no walk.
            if !name.to_string_lossy().ends_with(".tour.json") {
                continue;
            }
            let bytes = std::fs::read(f.path()).map_err(|e| Error::io(&f.path(), e))?;
            let to = to_dir.join(&name);
            match std::fs::read(&to) {
                Ok(have) if have != bytes => {
                    return Err(Error::invalid(format!(
                        "merge refused: {} differs from the walk another shard wrote to {}",
                        f.path().display(),
                        to.display()
                    )));
                }
                Ok(_) => {}
                Err(_) => {
                    write_atomic(&to, &bytes)?;
                    copied += 1;
                }
            }
        }
    }
    Ok(copied)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_are_safe_and_injective() {
        assert_eq!(file_name("tsp65", "length"), "tsp65.length.tour.json");
        assert_eq!(
            file_name("strips-matching[merge=naive,coverage4]", "turns"),
            "strips-matching%5Bmerge%3Dnaive%2Ccoverage4%5D.turns.tour.json"
        );
        // A dot or a slash in a name cannot move the file or merge two names.
        assert_eq!(file_name("a.b", "c"), "a%2Eb.c.tour.json");
        assert_ne!(file_name("a.b", "c"), file_name("a", "b.c"));
        assert_eq!(file_name("../x", "y"), "%2E%2E%2Fx.y.tour.json");
        assert_eq!(file_name("%41", "y"), "%2541.y.tour.json");
    }
}
