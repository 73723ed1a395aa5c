//! Reading tight and hunt outputs and writing the claims table as CSV and Markdown.

use super::*;

/// Reads `tight.csv` back (the rows `mowmill tight` wrote).
pub fn read_tight(path: &Path) -> Result<Vec<TightRow>> {
    let mut reader = csv::Reader::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    let mut out = Vec::new();
    for (i, rec) in reader.records().enumerate() {
        let line = i + 2;
        let rec = rec.map_err(|e| Error::invalid(format!("{}:{line}: {e}", path.display())))?;
        let get = |k: usize| rec.get(k).unwrap_or("").to_string();
        let num = |k: usize| -> Result<Option<f64>> {
            let s = get(k);
            if s.is_empty() {
                return Ok(None);
            }
            s.parse().map(Some).map_err(|_| {
                Error::invalid(format!(
                    "{}:{line}: column {} should be a number, got {s:?}",
                    path.display(),
                    crate::tight::TIGHT_COLUMNS[k]
                ))
            })
        };
        let int = |k: usize| -> Result<u64> {
            get(k).parse().map_err(|_| {
                Error::invalid(format!(
                    "{}:{line}: column {} should be an integer, got {:?}",
                    path.display(),
                    crate::tight::TIGHT_COLUMNS[k],
                    get(k)
                ))
            })
        };
        let standing = match get(8).as_str() {
            "established" => Standing::Established,
            "example" => Standing::Example,
            "report" => Standing::Report,
            "construction" => Standing::Construction,
            other => {
                return Err(Error::invalid(format!(
                    "{}:{line}: column standing should be established, example or report, got {other:?}",
                    path.display()
                )));
            }
        };
        out.push(TightRow {
            family: get(0),
            member: get(1),
            param: int(2)?,
            n: int(3)?,
            quantity: get(4),
            claim: get(5),
            claimed: num(6)?,
            measured: num(7)?,
            standing,
            verdict: get(9),
            how: get(10),
            source: get(11),
        });
    }
    Ok(out)
}

/// One line of a hunt suite's `summary.csv` (`mowmill hunt --suite`), as far as the claims
/// table reads it.
#[derive(Clone, Debug, serde::Deserialize)]
pub struct HuntWorst {
    pub algorithm: String,
    pub objective: String,
    pub family: String,
    pub against: String,
    pub worst_ratio: Option<f64>,
    pub worst_n: Option<u64>,
}

/// Reads a hunt suite's `summary.csv`.
pub fn read_hunts(path: &Path) -> Result<Vec<HuntWorst>> {
    let mut r = csv::Reader::from_path(path)
        .map_err(|e| Error::invalid(format!("{}: {e}", path.display())))?;
    r.deserialize()
        .enumerate()
        .map(|(k, rec)| {
            rec.map_err(|e| {
                Error::parse(
                    &path.display().to_string(),
                    k + 2,
                    1,
                    format!("expected a hunt summary row: {e}"),
                )
            })
        })
        .collect()
}

/// Fills the column "worst found by search": for each claim against OPT that holds on every
/// region, the largest ratio to OPT a hunt found for one of its (algorithm, objective) pairs,
/// with the pair, the family and N. A hunt against the bound does not count (it over-estimates).
pub fn add_hunts(table: &mut [ClaimRow], hunts: &[HuntWorst]) {
    for c in table.iter_mut() {
        let worst = hunts
            .iter()
            .filter(|h| h.against == "opt")
            .filter(|h| {
                c.search_pairs
                    .iter()
                    .any(|(a, o)| *a == h.algorithm && *o == h.objective)
            })
            .filter_map(|h| h.worst_ratio.map(|r| (r, h)))
            .max_by(|x, y| x.0.total_cmp(&y.0));
        if let Some((r, h)) = worst {
            c.worst_found_by_search = format!(
                "{r:.3} ({} {}, {}, N = {})",
                h.algorithm,
                h.objective,
                h.family,
                h.worst_n.map_or("-".into(), |n| n.to_string())
            );
        }
    }
}

/// Writes `claims.csv`.
pub fn write_csv(table: &[ClaimRow], path: &Path) -> Result<()> {
    let err = |e: csv::Error| Error::invalid(format!("{}: {e}", path.display()));
    let mut w = csv::Writer::from_path(path).map_err(err)?;
    w.write_record(CLAIM_COLUMNS).map_err(err)?;
    for c in table {
        w.write_record([
            c.paper.as_str(),
            &c.claim,
            &c.statement,
            &c.factor,
            &c.algorithms,
            &c.instances.to_string(),
            &c.decided.to_string(),
            &c.max_ratio.map(|x| format!("{x:.4}")).unwrap_or_default(),
            &c.ratio_of,
            &c.violations.to_string(),
            &c.tight_family,
            &c.tight_value,
            &c.verdict,
            &c.implementation,
            &c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            &c.families,
            &c.errors.to_string(),
            &c.findings,
            &c.worst_found_by_search,
            &c.witness,
            &c.note,
            &c.max_ratio_best,
            &c.structured_families,
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| Error::io(path, e))
}

/// The claims table as Markdown: the table, then a note per claim that is violated, holds on
/// few instances, or is realized by our reading.
pub fn markdown(table: &[ClaimRow], source: &str) -> String {
    let mut out = format!(
        "Claims against {source}. Generated by `mowmill claims` from the rows alone (docs/claims.md, \
         \"Verdicts\", states every rule): instances = distinct instances with a valid row, \
         decided = those where the claim could be checked (a proven optimum, a proven lower \
         bound that the value meets, or a best checked walk the value exceeds), max N, families \
         and structured families of the decided ones. A hold needs {HOLDS_MIN_DECIDED} decided \
         instances including a structured family; a violation is attributed to the statement \
         (no walk meets the bound), the paper's algorithm (`impl.` paper) or our reading \
         (`impl.` reading).\n\n"
    );
    out.push_str("| paper | claim | factor | algorithms | impl. | instances | decided | max N | families | structured | max ratio (of) | worst vs best walk | worst found by search | violations | witness | tight family | verdict |\n");
    out.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for c in table {
        let paper: &str = match Paper::ALL.into_iter().find(|p| p.title() == c.paper) {
            Some(p) => p.short(),
            None => &c.paper,
        };
        let ratio = c
            .max_ratio
            .map(|x| format!("{x:.3} ({})", c.ratio_of))
            .unwrap_or_else(|| c.ratio_of.clone());
        let tight = if c.tight_value.is_empty() {
            String::new()
        } else {
            format!("{}: {}", c.tight_family, c.tight_value)
        };
        let implementation = c.implementation.split(':').next().unwrap_or("");
        let _ = writeln!(
            out,
            "| {paper} | {} | {} | {} | {implementation} | {} | {} | {} | {} | {} | {ratio} | {} | {} | {} | {} | {tight} | **{}** |",
            c.claim,
            c.factor,
            c.algorithms,
            c.instances,
            c.decided,
            c.max_n_decided.map(|n| n.to_string()).unwrap_or_default(),
            c.families,
            c.structured_families,
            c.max_ratio_best,
            c.worst_found_by_search,
            c.violations,
            c.witness,
            c.verdict,
        );
    }
    let notes: Vec<&ClaimRow> = table
        .iter()
        .filter(|c| {
            c.implementation != "paper"
                || !c.note.is_empty()
                || !c.findings.is_empty()
                || c.errors > 0
        })
        .collect();
    if !notes.is_empty() {
        out.push_str("\nNotes:\n\n");
        for c in notes {
            let _ = write!(out, "- **{}**: ", c.claim);
            if !c.note.is_empty() {
                let _ = write!(out, "{} ", c.note);
            }
            let _ = write!(out, "Implementation {}", c.implementation);
            if c.errors > 0 {
                let _ = write!(out, "; {} error rows", c.errors);
            }
            if !c.findings.is_empty() {
                let _ = write!(out, "; violating: {}", c.findings);
            }
            out.push('\n');
        }
    }
    out
}

/// README's findings: one line per violated claim (what mowmill found against the papers),
/// with its attribution, witness and numbers; generated from the table, never written by hand.
pub fn findings_markdown(table: &[ClaimRow]) -> String {
    let mut out = String::new();
    for c in table.iter().filter(|c| is_violated(c)) {
        let paper = Paper::ALL
            .into_iter()
            .find(|p| p.title() == c.paper)
            .map_or(c.paper.as_str(), |p| p.short());
        let witness = c
            .violations_detail
            .iter()
            .find(|v| format!("{} {} {}", v.algorithm, v.objective, v.instance) == c.witness);
        let _ = write!(
            out,
            "- **{} ({paper} paper, {}): {}.**",
            c.claim, c.factor, c.verdict
        );
        if let Some(w) = witness {
            let _ = write!(
                out,
                " `{}` ({} {}, family {}, N = {}): {}.",
                w.instance, w.algorithm, w.objective, w.family, w.n, w.detail
            );
            if w.registered_held == Some(true) {
                out.push_str(" mowmill's own proven bound held there.");
            }
        }
        let _ = write!(out, " {} violating rows.", c.violations);
        // Whether the violation depends on a choice the paper leaves open (add_choice_evidence).
        for key in [
            "Greedy order on the witness:",
            "Violated by every order of the greedy",
        ] {
            if let Some(k) = c.note.find(key) {
                let sentence = c.note[k..].split(". ").next().unwrap_or_default();
                let _ = write!(out, " {}.", sentence.trim_end_matches('.'));
            }
        }
        out.push('\n');
    }
    if out.is_empty() {
        out.push_str("- No claim is violated in the committed table.\n");
    }
    out
}
