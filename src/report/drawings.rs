//! The report's pictures of walks: the worst instance of each algorithm and objective beside
//! the best known walk there, and the findings' witnesses.
//!
//! A walk comes from the run's kept walks (`walks/`) when there, else from re-running the
//! registered algorithm the row names (looked up in the registry by name: an outside
//! algorithm is never run). Either way the model's checker recounts it, and a value other than
//! the row's is said under the picture rather than drawn as if it were the row's walk.

use super::Run;
use super::html::{anchor, data_image, esc};
use crate::algorithms::{Objective, find};
use crate::error::{Error, Result};
use crate::evaluate::{Subject, guarded, parse_variant};
use crate::harness::rows::Row;
use crate::harness::walks;
use crate::model::{InstanceModel, Kind};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// The most worst-instance pictures a page shows (the largest ratios first).
const MAX_WORST: usize = 16;

/// Instances larger than this are not drawn (the picture would outweigh the page).
const MAX_DRAWN_N: u64 = 3_000;

/// The most bytes of pictures a section puts in the page.
const MAX_SECTION_BYTES: usize = 1_800_000;

/// The instance files of the run's `instances/` folder, by instance name (the file stem).
fn instance_files(run: &Run) -> BTreeMap<String, PathBuf> {
    let mut out = BTreeMap::new();
    if let Ok(read) = std::fs::read_dir(run.dir.join("instances")) {
        for e in read.filter_map(|e| e.ok()) {
            let p = e.path();
            if let (true, Some(stem)) = (p.is_file(), p.file_stem()) {
                out.insert(stem.to_string_lossy().into_owned(), p);
            }
        }
    }
    out
}

/// Where a walk comes from.
enum WalkSource<'a> {
    /// A tour JSON file of the instance's model.
    File(PathBuf),
    /// The row's registered algorithm, run again.
    Rerun(&'a Row),
}

/// Draws `walk` over the instance in `file` as SVG, with the checker's value of `objective`.
fn picture(
    file: &Path,
    walk: &WalkSource<'_>,
    objective: &str,
    title: String,
) -> Result<(Vec<u8>, u64)> {
    fn on<M: InstanceModel>(
        file: &Path,
        walk: &WalkSource<'_>,
        objective: &str,
        title: String,
    ) -> Result<(Vec<u8>, u64)> {
        let inst = M::read(file)?;
        let wanted: Objective = objective.parse().map_err(Error::invalid)?;
        let (cover, options) = match walk {
            WalkSource::File(p) => (M::read_walk(p)?, crate::algorithms::Options::default()),
            WalkSource::Rerun(row) => {
                let (name, options) = parse_variant(&row.algorithm)?;
                let algorithm = find(name).ok_or_else(|| {
                    Error::invalid(format!(
                        "{name}: not a registered algorithm (an outside algorithm is not re-run)"
                    ))
                })?;
                let solution = inst.run(Subject::Registered(algorithm), &options, &[wanted])?;
                let output = solution
                    .outputs
                    .iter()
                    .find(|o| o.objective == wanted)
                    .or_else(|| {
                        wanted
                            .carriers()
                            .iter()
                            .find_map(|c| solution.outputs.iter().find(|o| o.objective == *c))
                    })
                    .ok_or_else(|| Error::invalid(format!("{name} gave no walk for {wanted}")))?;
                (output.cover.clone(), options)
            }
        };
        let recount = inst.recount(&cover, wanted, &options)?;
        let tmp = tempfile::Builder::new()
            .suffix(".svg")
            .tempfile()
            .map_err(|e| Error::io(Path::new("a temporary file"), e))?;
        inst.draw(Some(&cover), tmp.path(), title)?;
        let bytes = std::fs::read(tmp.path()).map_err(|e| Error::io(tmp.path(), e))?;
        Ok((bytes, recount.value))
    }
    match Kind::of(file) {
        Kind::Grid => on::<crate::region::Region>(file, walk, objective, title),
        Kind::Discrete => on::<crate::discrete::Discrete>(file, walk, objective, title),
        Kind::Ortho => on::<crate::ortho::Polygon>(file, walk, objective, title),
    }
}

/// The walk of `row`: its kept file, else a re-run.
fn source<'a>(run: &Run, row: &'a Row) -> WalkSource<'a> {
    let kept = walks::path(&run.dir, &row.instance, &row.algorithm, &row.objective);
    if kept.is_file() {
        WalkSource::File(kept)
    } else {
        WalkSource::Rerun(row)
    }
}

/// A figure: the picture or why there is none, and a caption.
fn figure(file: &Path, row: &Row, run: &Run, what: &str, used: &mut usize) -> String {
    let title = format!("{what}: {} {}", row.algorithm, row.objective);
    match guarded(|| picture(file, &source(run, row), &row.objective, title)) {
        Ok((bytes, value)) if *used + bytes.len() * 4 / 3 <= MAX_SECTION_BYTES => {
            *used += bytes.len() * 4 / 3;
            let check = match row.value {
                Some(v) if v == value => format!("checker: {value}, as in the row"),
                Some(v) => format!("checker: {value}, but the row says {v} (the re-run differs)"),
                None => format!("checker: {value}"),
            };
            format!(
                "<div class=\"fig\">{}<p>{}: {} · {}</p></div>",
                data_image(
                    &bytes,
                    "image/svg+xml",
                    &format!("{} {}", row.instance, row.algorithm),
                    Some(520)
                ),
                esc(what),
                esc(&row.algorithm),
                esc(&check)
            )
        }
        Ok(_) => format!(
            "<div class=\"fig\"><p>{}: {} not drawn (the page's picture budget is used)</p></div>",
            esc(what),
            esc(&row.algorithm)
        ),
        Err(e) => format!(
            "<div class=\"fig\"><p>{}: {} not drawn: {}</p></div>",
            esc(what),
            esc(&row.algorithm),
            esc(&e)
        ),
    }
}

/// The ratio a worst case is ranked by: to OPT when known, else to the bound.
fn rank(r: &Row) -> Option<(f64, &'static str)> {
    r.ratio_opt
        .map(|x| (x.0, "OPT"))
        .or(r.ratio_lb.map(|x| (x.0, "bound")))
}

pub fn worst(run: &Run) -> String {
    let Some(rows) = &run.rows else {
        return "<p>This folder does not keep results.csv and its instances: the worst instances cannot be found here. The claims table names each witness; Findings draws the violations.</p>".into();
    };
    let files = instance_files(run);
    let mut worst: BTreeMap<(&str, &str), &Row> = BTreeMap::new();
    for r in rows
        .iter()
        .filter(|r| r.error.is_empty() && r.algorithm != "exact" && r.n <= MAX_DRAWN_N)
    {
        let Some((x, _)) = rank(r) else { continue };
        let w = worst.entry((&r.algorithm, &r.objective)).or_insert(r);
        if rank(w).is_none_or(|(y, _)| y < x) {
            *w = r;
        }
    }
    let mut picked: Vec<&Row> = worst
        .into_values()
        .filter(|r| rank(r).is_some_and(|(x, _)| x > 1.0))
        .collect();
    picked.sort_by(|a, b| {
        rank(b)
            .map(|x| x.0)
            .unwrap_or(0.0)
            .total_cmp(&rank(a).map(|x| x.0).unwrap_or(0.0))
    });
    let total = picked.len();
    picked.truncate(MAX_WORST);
    let mut out = format!(
        "<p>Per algorithm and objective, its worst instance (largest ratio, N ≤ {MAX_DRAWN_N}), the walk beside the best walk another algorithm found there; dots mark 90° turns, rings U-turns. The {} largest of {total} are drawn.</p>",
        picked.len()
    );
    let mut used = 0;
    for r in picked {
        let (x, of) = rank(r).unwrap_or((0.0, ""));
        let _ = write!(
            out,
            "<h3 id=\"worst-{}\">{} · {}: {x:.4} × {of} on {} (N = {})</h3>",
            anchor(&format!("{} {}", r.algorithm, r.objective)),
            esc(&r.algorithm),
            esc(&r.objective),
            esc(&r.instance),
            r.n
        );
        let Some(file) = files.get(&r.instance) else {
            out.push_str("<p>The instance file is not in instances/.</p>");
            continue;
        };
        let best = rows
            .iter()
            .filter(|b| {
                b.instance == r.instance
                    && b.objective == r.objective
                    && b.error.is_empty()
                    && b.algorithm != "exact"
                    && b.value.is_some()
            })
            .min_by_key(|b| b.value);
        let opt = match (r.opt, r.opt_status.as_str()) {
            (Some(o), "optimal") => format!("proven optimum {o}"),
            (Some(o), s) => format!("best exact value {o} ({s})"),
            _ => format!(
                "lower bound {} ({})",
                r.lower_bound.map_or("-".into(), |b| b.to_string()),
                r.lb_source
            ),
        };
        let _ = write!(
            out,
            "<p class=\"note\">value {}, {}; best walk of a registered algorithm: {} ({})</p><div class=\"figs\">",
            r.value.map_or("-".into(), |v| v.to_string()),
            esc(&opt),
            best.map_or("-".into(), |b| b
                .value
                .map_or("-".into(), |v| v.to_string())),
            esc(best.map_or("", |b| b.algorithm.as_str()))
        );
        out.push_str(&figure(file, r, run, "worst", &mut used));
        if let Some(b) = best.filter(|b| b.algorithm != r.algorithm) {
            out.push_str(&figure(file, b, run, "best known", &mut used));
        }
        out.push_str("</div>");
    }
    out
}

/// The findings saved in `RUN/findings/` (from `mowmill claims --findings`): by stem, the
/// note, the instance file, the walk and an already drawn figure, as found.
struct Finding {
    stem: String,
    note: Option<PathBuf>,
    instance: Option<PathBuf>,
    walk: Option<PathBuf>,
    figure: Option<PathBuf>,
}

fn saved_findings(run: &Run) -> Vec<Finding> {
    let mut by_stem: BTreeMap<String, Finding> = BTreeMap::new();
    let Ok(read) = std::fs::read_dir(run.dir.join("findings")) else {
        return Vec::new();
    };
    for e in read.filter_map(|e| e.ok()) {
        let p = e.path();
        let Some(name) = p.file_name().map(|n| n.to_string_lossy().into_owned()) else {
            continue;
        };
        if !p.is_file() {
            continue;
        }
        let (stem, kind) = if let Some(s) = name.strip_suffix(".tour.json") {
            (s.to_string(), "walk")
        } else if let Some((s, ext)) = name.rsplit_once('.') {
            (
                s.to_string(),
                match ext {
                    "md" => "note",
                    "png" | "svg" => "figure",
                    _ => "instance",
                },
            )
        } else {
            continue;
        };
        let f = by_stem.entry(stem.clone()).or_insert(Finding {
            stem,
            note: None,
            instance: None,
            walk: None,
            figure: None,
        });
        match kind {
            "walk" => f.walk = Some(p),
            "note" => f.note = Some(p),
            "figure" => f.figure = Some(p),
            _ => f.instance = Some(p),
        }
    }
    by_stem.into_values().filter(|f| f.note.is_some()).collect()
}

/// The anchor of each witness's drawing (`algorithm objective instance`): the saved finding's,
/// else the witness's own in Findings when the rows are here, else the section's. The
/// findings folder is read once, however many claims ask.
pub fn witness_anchors(run: &Run) -> impl Fn(&str) -> String + '_ {
    let saved = saved_findings(run);
    move |witness| {
        let parts: Vec<&str> = witness.split_whitespace().collect();
        if let (Some(alg), Some(inst)) = (parts.first(), parts.last()) {
            if let Some(f) = saved
                .iter()
                .find(|f| f.stem.ends_with(inst) && f.stem.contains(alg))
            {
                return format!("finding-{}", anchor(&f.stem));
            }
            if run.rows.is_some() {
                return format!("witness-{}", anchor(witness));
            }
        }
        "findings".into()
    }
}

pub fn findings(run: &Run) -> String {
    let saved = saved_findings(run);
    let mut used = 0;
    let mut out = String::new();
    if !saved.is_empty() {
        let _ = write!(
            out,
            "<p>{} finding(s) saved in findings/ (each a violated claim's witness, with its note).</p>",
            saved.len()
        );
        for f in &saved {
            let note = f
                .note
                .as_ref()
                .and_then(|p| std::fs::read_to_string(p).ok())
                .unwrap_or_default();
            let _ = write!(
                out,
                "<h3 id=\"finding-{}\">{}</h3><div class=\"figs\">",
                anchor(&f.stem),
                esc(&f.stem)
            );
            let pic = match (&f.figure, &f.instance, &f.walk) {
                (Some(fig), _, _) => std::fs::read(fig).ok().map(|b| {
                    let mime = if fig.extension().is_some_and(|e| e == "png") {
                        "image/png"
                    } else {
                        "image/svg+xml"
                    };
                    (b, mime)
                }),
                (None, Some(inst), Some(walk)) => guarded(|| {
                    picture(
                        inst,
                        &WalkSource::File(walk.clone()),
                        objective_of(&note),
                        f.stem.clone(),
                    )
                })
                .ok()
                .map(|(b, _)| (b, "image/svg+xml")),
                _ => None,
            };
            match pic {
                Some((bytes, mime)) if used + bytes.len() * 4 / 3 <= MAX_SECTION_BYTES => {
                    used += bytes.len() * 4 / 3;
                    out.push_str(&format!(
                        "<div class=\"fig\">{}</div>",
                        data_image(&bytes, mime, &f.stem, Some(520))
                    ));
                }
                Some(_) => out
                    .push_str("<p class=\"note\">not drawn: the page's picture budget is used</p>"),
                None => out.push_str(
                    "<p class=\"note\">no picture could be made from the saved files</p>",
                ),
            }
            let _ = write!(
                out,
                "<div class=\"fig\"><pre>{}</pre></div></div>",
                esc(&note)
            );
        }
        return out;
    }
    let Some(claims) = &run.claims else {
        return "<p>No claims table.</p>".into();
    };
    let violated: Vec<&Vec<String>> = claims
        .rows
        .iter()
        .filter(|r| claims.get(r, "verdict") == "violated")
        .collect();
    if violated.is_empty() {
        return "<p>No claim is violated in this run.</p>".into();
    }
    let files = instance_files(run);
    let _ = write!(out, "<p>{} violated claim(s).</p>", violated.len());
    for r in violated {
        let witness = claims.get(r, "witness");
        let _ = write!(
            out,
            "<h3 id=\"witness-{}\">{} {}: {}</h3><p class=\"note\">{}</p><div class=\"figs\">",
            anchor(witness),
            esc(claims.get(r, "paper")),
            esc(claims.get(r, "claim")),
            esc(witness),
            esc(claims.get(r, "note"))
        );
        let parts: Vec<&str> = witness.split_whitespace().collect();
        let row = run.rows.as_ref().and_then(|rows| {
            rows.iter().find(|x| {
                parts.len() >= 3
                    && x.algorithm == parts[0]
                    && x.objective == parts[1]
                    && x.instance == parts[parts.len() - 1]
            })
        });
        match (row, row.and_then(|x| files.get(&x.instance))) {
            (Some(row), Some(file)) => out.push_str(&figure(file, row, run, "witness", &mut used)),
            _ => out.push_str(
                "<p class=\"note\">the witness's row or instance is not in this folder</p>",
            ),
        }
        out.push_str("</div>");
    }
    out
}

/// The objective a finding's note names (`objective: turns,` on its first line; cc-turns when
/// none).
fn objective_of(note: &str) -> &str {
    note.split_once("objective: ")
        .map(|(_, rest)| rest.split([',', '\n']).next().unwrap_or("").trim())
        .filter(|o| !o.is_empty())
        .unwrap_or("cc-turns")
}
