//! The report's sections, each a function of the run read as data.

use super::chart::{self, BoxRow, Point, Series};
use super::html::{Cell, anchor, data_image, esc, table};
use super::{Run, Table, drawings};
use crate::error::Result;
use crate::harness::rows::Row;
use crate::harness::stats::{StatRow, size_bin};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// The most points a ratio-against-N chart draws; beyond it, one point per family and size band.
const MAX_POINTS: usize = 400;

/// The most bytes of figures read from a tight or hunt folder into the page.
const MAX_FOLDER_FIGURES: usize = 1_500_000;

/// Every section, in the issue's order: (anchor, heading, HTML).
pub fn all(run: &Run) -> Result<Vec<(String, String, String)>> {
    let mut out = vec![
        ("provenance".into(), "Provenance".into(), provenance(run)),
        ("claims".into(), "Claims".into(), claims(run)),
        ("ratios".into(), "Ratios".into(), ratios(run)),
        (
            "worst".into(),
            "Worst instances".into(),
            drawings::worst(run),
        ),
    ];
    if run.tight.is_some() {
        out.push(("tight".into(), "Tight families".into(), tight(run)));
    }
    out.push((
        "findings".into(),
        "Findings".into(),
        drawings::findings(run),
    ));
    out.push(("time".into(), "Time".into(), time(run)));
    out.push((
        "errors".into(),
        "Errors and time limits".into(),
        errors(run),
    ));
    if run.hunt.is_some() {
        out.push(("hunt".into(), "Hunt".into(), hunt(run)));
    }
    Ok(out)
}

fn num(x: f64) -> Cell {
    let mut c = Cell::text(format!("{}", (x * 1e4).round() / 1e4)).class("num");
    c.sort = Some(x.to_string());
    c
}

fn provenance(run: &Run) -> String {
    let Some((m, digest)) = &run.manifest else {
        return "<p>No manifest.json in this folder: the provenance is unknown.</p>".into();
    };
    let s = |k: &str| match m.get(k) {
        Some(serde_json::Value::String(v)) => v.clone(),
        Some(serde_json::Value::Null) | None => String::new(),
        Some(v) => v.to_string(),
    };
    let seed = m
        .get("config")
        .and_then(|c| c.get("seed"))
        .map_or(String::new(), |v| v.to_string());
    let machine = match m.get("machine") {
        Some(serde_json::Value::Object(o)) => o
            .iter()
            .map(|(k, v)| format!("{k}: {}", v.as_str().map_or(v.to_string(), str::to_string)))
            .collect::<Vec<_>>()
            .join(", "),
        _ => s("machine"),
    };
    let duration = match (
        humantime::parse_rfc3339(&s("start")),
        humantime::parse_rfc3339(&s("end")),
    ) {
        (Ok(a), Ok(b)) => b
            .duration_since(a)
            .map_or(String::new(), |d| humantime::format_duration(d).to_string()),
        _ => String::new(),
    };
    let dirty = if s("git_dirty") == "true" {
        " (uncommitted changes)"
    } else {
        ""
    };
    let kv: Vec<(&str, String)> = vec![
        ("run", s("run_id")),
        ("command", s("command_line")),
        (
            "config",
            format!("{} (sha256 {})", s("config_file"), s("config_sha256")),
        ),
        ("seed", seed),
        (
            "code",
            format!(
                "mowmill {} at {}{dirty}",
                s("mowmill_version"),
                s("git_commit")
            ),
        ),
        (
            "toolchain",
            format!("{}; HiGHS {}", s("rustc_version"), s("highs_version")),
        ),
        ("machine", machine),
        ("jobs", s("jobs")),
        ("shard", s("shard")),
        ("started", s("start")),
        ("ended", s("end")),
        ("duration", duration),
        (
            "instances / rows",
            format!("{} / {}", s("instances"), s("rows")),
        ),
        ("manifest sha256", digest.clone()),
        (
            "results.csv",
            if run.rows.is_some() {
                "kept".into()
            } else {
                "not kept in this folder (the per-instance sections use stats.csv)".into()
            },
        ),
    ];
    let mut out = String::from(r#"<div class="kv">"#);
    for (k, v) in kv {
        let _ = write!(out, "<div><b>{}</b>{}</div>", esc(k), esc(&v));
    }
    out.push_str("</div>");
    let toml = s("config_toml");
    if !toml.is_empty() {
        let _ = write!(
            out,
            "<details><summary>config</summary><pre>{}</pre></details>",
            esc(&toml)
        );
    }
    out
}

/// The verdict cell's classes: `verdict` (the self-test finds it) and the colour.
fn verdict_cell(verdict: &str) -> Cell {
    let class = match super::html::verdict_class(verdict) {
        "good" => "verdict good",
        "bad" => "verdict bad",
        "warn" => "verdict warn",
        _ => "verdict plain",
    };
    Cell::text(verdict).class(class)
}

fn claims(run: &Run) -> String {
    let Some(t) = &run.claims else {
        return "<p>No claims table: the folder has neither claims.csv nor results.csv.</p>".into();
    };
    let witness_anchor = drawings::witness_anchors(run);
    let mut rows = Vec::new();
    for r in &t.rows {
        let g = |k: &str| t.get(r, k);
        let families = g("families");
        let nf = families.split_whitespace().count();
        let witness = g("witness");
        let witness_cell = if witness.is_empty() {
            Cell::text("")
        } else {
            let target = witness_anchor(witness);
            Cell::html(format!(
                r##"<a href="#{}">{}</a>"##,
                esc(&target),
                esc(witness)
            ))
        };
        let note = g("note");
        rows.push(vec![
            Cell::text(g("paper")),
            Cell::text(g("claim")),
            Cell::text(g("statement")),
            verdict_cell(g("verdict")),
            Cell::text(g("decided")).class("num"),
            Cell::text(g("instances")).class("num"),
            Cell::html(format!(r#"<span title="{}">{nf}</span>"#, esc(families))),
            Cell::text(g("max_n_decided")).class("num"),
            Cell::text(g("max_ratio")).class("num"),
            Cell::text(g("ratio_of")),
            Cell::text(g("violations")).class("num"),
            Cell::text(g("errors")).class("num"),
            witness_cell,
            if note.is_empty() {
                Cell::text("")
            } else {
                Cell::html(format!(
                    "<details><summary>note</summary>{}</details>",
                    esc(note)
                ))
            },
        ]);
    }
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for r in &t.rows {
        // `holds on few instances (14)` counts as `holds on few instances`.
        let v = t.get(r, "verdict");
        *counts.entry(v.split(" (").next().unwrap_or(v)).or_default() += 1;
    }
    let summary = counts
        .iter()
        .map(|(v, c)| format!("{c} {v}"))
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "<p>{} claims: {}. Source: {}. <span class=\"note\">decided = instances on which the claim could be decided; the families cell lists them on hover; the witness links to its drawing in Findings.</span></p>{}",
        t.rows.len(),
        esc(&summary),
        esc(&run.claims_source),
        table(
            "claims-table",
            &[
                "paper",
                "claim",
                "statement",
                "verdict",
                "decided",
                "instances",
                "families",
                "largest N",
                "worst ratio",
                "ratio of",
                "violations",
                "errors",
                "witness",
                "note"
            ],
            &rows
        )
    )
}

/// Which ratio a group is read by: to OPT where any row has one, else to the lower bound.
fn measure_of(stats: &[&StatRow]) -> &'static str {
    if stats.iter().any(|s| s.ratio_opt_count > 0) {
        "opt"
    } else {
        "lb"
    }
}

fn ratio_of(r: &Row, measure: &str) -> Option<f64> {
    let ratio = if measure == "opt" {
        r.ratio_opt
    } else {
        r.ratio_lb
    };
    ratio.map(|x| x.0)
}

/// Nearest-rank quantile of sorted `v`.
fn quantile(v: &[f64], q: f64) -> f64 {
    let n = v.len();
    v[((q * n as f64).ceil() as usize).clamp(1, n) - 1]
}

fn ratios(run: &Run) -> String {
    let mut groups: BTreeMap<(&str, &str), Vec<&StatRow>> = BTreeMap::new();
    for s in run
        .stats
        .iter()
        .filter(|s| s.size_bin != "all" && s.algorithm != "exact")
    {
        groups
            .entry((&s.algorithm, &s.objective))
            .or_default()
            .push(s);
    }
    let mut by_group: BTreeMap<(&str, &str), Vec<&Row>> = BTreeMap::new();
    if let Some(rows) = &run.rows {
        for r in rows
            .iter()
            .filter(|r| r.error.is_empty() && r.algorithm != "exact")
        {
            by_group
                .entry((&r.algorithm, &r.objective))
                .or_default()
                .push(r);
        }
    }
    let mut out = format!(
        "<p>Per algorithm and objective: the ratio's distribution per family and size band (N in powers of two), and the ratio against N. {}</p>",
        if run.rows.is_some() {
            "Boxes are quartiles, whiskers the minimum and maximum, the red dot the mean; a point per family and N is its worst instance (hover for its name, N, value and bound)."
        } else {
            "This folder keeps stats.csv only: each bar runs from the median to the 95th percentile, the whisker to the maximum, the red dot is the mean; points are per size band (median and maximum)."
        }
    );
    for ((algorithm, objective), stats) in &groups {
        let measure = measure_of(stats);
        let name = format!("{algorithm} · {objective}");
        let against = if measure == "opt" {
            "OPT"
        } else {
            "the lower bound"
        };
        let rows = by_group.get(&(*algorithm, *objective));
        let (boxes, series) = match rows {
            Some(rows) => from_rows(rows, measure),
            None => from_stats(stats, measure),
        };
        if boxes.is_empty() {
            continue;
        }
        let guarantee = stats
            .iter()
            .map(|s| s.guarantee.as_str())
            .find(|g| !g.is_empty())
            .unwrap_or("");
        let violations: usize = stats.iter().map(|s| s.violations).sum();
        let _ = write!(
            out,
            "<h3 id=\"ratio-{}\">{}</h3><p class=\"note\">ratio to {against}; guarantee: {}; {} violation(s) of it</p><details open><summary>distribution and ratio against N</summary><div class=\"figs\">{}{}</div></details>",
            anchor(&name),
            esc(&name),
            esc(if guarantee.is_empty() {
                "none registered"
            } else {
                guarantee
            }),
            violations,
            chart::boxes(&format!("{name}: ratio distribution"), &boxes, None),
            chart::scatter(
                &format!("{name}: ratio against N"),
                &series,
                true,
                false,
                "N (pixels, log)",
                &format!("ratio to {against}")
            )
        );
    }
    out
}

fn from_rows(rows: &[&Row], measure: &str) -> (Vec<BoxRow>, Vec<Series>) {
    let mut bands: BTreeMap<(&str, u64), Vec<f64>> = BTreeMap::new();
    let mut worst: BTreeMap<(&str, u64), &Row> = BTreeMap::new();
    for r in rows {
        let Some(x) = ratio_of(r, measure) else {
            continue;
        };
        let lo = if r.n == 0 {
            0
        } else {
            1u64 << (63 - r.n.leading_zeros())
        };
        bands.entry((&r.family, lo)).or_default().push(x);
        let w = worst.entry((&r.family, r.n)).or_insert(r);
        if ratio_of(w, measure) < Some(x) {
            *w = r;
        }
    }
    let boxes = bands
        .into_iter()
        .map(|((family, lo), mut v)| {
            v.sort_by(f64::total_cmp);
            BoxRow {
                label: format!("{family} {}", size_bin(lo.max(1))),
                count: v.len(),
                min: Some(v[0]),
                q1: Some(quantile(&v, 0.25)),
                median: quantile(&v, 0.5),
                q3: Some(quantile(&v, 0.75)),
                p95: Some(quantile(&v, 0.95)),
                max: v[v.len() - 1],
                mean: Some(v.iter().sum::<f64>() / v.len() as f64),
            }
        })
        .collect();
    // One point per family and N (its worst instance); too many: one per family and band.
    let mut picked: Vec<&Row> = worst.values().copied().collect();
    if picked.len() > MAX_POINTS {
        let mut per_band: BTreeMap<(&str, String), &Row> = BTreeMap::new();
        for r in picked {
            let w = per_band.entry((&r.family, size_bin(r.n))).or_insert(r);
            if ratio_of(w, measure) < ratio_of(r, measure) {
                *w = r;
            }
        }
        picked = per_band.into_values().collect();
    }
    let mut series: BTreeMap<&str, Vec<Point>> = BTreeMap::new();
    for r in picked {
        let reference = if measure == "opt" {
            r.opt
        } else {
            r.lower_bound
        };
        series.entry(&r.family).or_default().push(Point {
            x: r.n as f64,
            y: ratio_of(r, measure).unwrap_or(0.0),
            tip: format!(
                "{}\nN = {}, value {}, {} {}",
                r.instance,
                r.n,
                r.value.map_or("-".into(), |v| v.to_string()),
                if measure == "opt" { "OPT" } else { "bound" },
                reference.map_or("-".into(), |v| v.to_string())
            ),
        });
    }
    (boxes, named_series(series))
}

/// One series per family, without a fitted line.
fn named_series(by_family: BTreeMap<&str, Vec<Point>>) -> Vec<Series> {
    by_family
        .into_iter()
        .map(|(name, points)| Series {
            name: name.to_string(),
            points,
            fit: None,
        })
        .collect()
}

fn from_stats(stats: &[&StatRow], measure: &str) -> (Vec<BoxRow>, Vec<Series>) {
    let mut boxes = Vec::new();
    let mut series: BTreeMap<&str, Vec<Point>> = BTreeMap::new();
    for s in stats {
        let sum = s.summary(measure);
        let (Some(median), Some(max)) = (sum.median, sum.max) else {
            continue;
        };
        boxes.push(BoxRow {
            label: format!("{} {}", s.family, s.size_bin),
            count: sum.count,
            min: None,
            q1: None,
            median,
            q3: None,
            p95: sum.p95,
            max,
            mean: sum.mean,
        });
        let lo: f64 = s
            .size_bin
            .split('-')
            .next()
            .and_then(|x| x.parse().ok())
            .unwrap_or(0.0);
        for (what, y) in [("median", median), ("max", max)] {
            series.entry(&s.family).or_default().push(Point {
                x: lo.max(1.0),
                y,
                tip: format!(
                    "{} N in {}: {what} {y:.4} over {} rows",
                    s.family, s.size_bin, sum.count
                ),
            });
        }
    }
    (boxes, named_series(series))
}

fn csv_table(id: &str, t: &Table) -> String {
    let header: Vec<&str> = t.header.iter().map(String::as_str).collect();
    let rows: Vec<Vec<Cell>> = t
        .rows
        .iter()
        .map(|r| {
            t.header
                .iter()
                .zip(r)
                .map(|(h, v)| {
                    if h == "verdict" {
                        verdict_cell(v)
                    } else {
                        Cell::text(v)
                    }
                })
                .collect()
        })
        .collect();
    table(id, &header, &rows)
}

/// The SVG figures of `dir` (sorted by name) as images, within [`MAX_FOLDER_FIGURES`] bytes.
pub fn folder_figures(dirs: &[&Path]) -> String {
    let mut files: Vec<std::path::PathBuf> = Vec::new();
    for d in dirs {
        if let Ok(read) = std::fs::read_dir(d) {
            files.extend(
                read.filter_map(|e| e.ok())
                    .map(|e| e.path())
                    .filter(|p| p.extension().is_some_and(|e| e == "svg") && p.is_file()),
            );
        }
    }
    files.sort();
    let mut out = String::from("<div class=\"figs\">");
    let mut used = 0;
    let mut left = 0;
    for f in &files {
        let Ok(bytes) = std::fs::read(f) else {
            continue;
        };
        if used + bytes.len() > MAX_FOLDER_FIGURES {
            left += 1;
            continue;
        }
        used += bytes.len();
        let name = f
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        let _ = write!(
            out,
            "<div class=\"fig\">{}<p>{}</p></div>",
            data_image(&bytes, "image/svg+xml", &name, Some(420)),
            esc(&name)
        );
    }
    out.push_str("</div>");
    if left > 0 {
        let _ = write!(
            out,
            "<p class=\"note\">{left} more figure(s) left out to keep the page small.</p>"
        );
    }
    out
}

fn tight(run: &Run) -> String {
    let (Some(t), Some(dir)) = (&run.tight, &run.tight_dir) else {
        return String::new();
    };
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for r in &t.rows {
        *counts.entry(t.get(r, "verdict")).or_default() += 1;
    }
    format!(
        "<p>{}: the papers' tight families, claimed against measured ({}).</p>{}{}",
        esc(&dir.display().to_string()),
        esc(&counts
            .iter()
            .map(|(v, c)| format!("{c} {v}"))
            .collect::<Vec<_>>()
            .join(", ")),
        csv_table("tight-table", t),
        folder_figures(&[&dir.join("figures")])
    )
}

/// The median seconds per N of `rows`, as (N, seconds).
fn median_times(rows: &[&Row]) -> Vec<(f64, f64)> {
    let mut by_n: BTreeMap<u64, Vec<f64>> = BTreeMap::new();
    for r in rows {
        by_n.entry(r.n).or_default().push(r.seconds);
    }
    by_n.into_iter()
        .map(|(n, mut v)| {
            v.sort_by(f64::total_cmp);
            (n as f64, quantile(&v, 0.5))
        })
        .collect()
}

fn time(run: &Run) -> String {
    let memory = "<p class=\"note\">Memory per solve is not recorded by <code>bench</code>: the solves of a run share one process. The speed table (docs/speed.csv, <code>scripts/speed-table.sh</code>) measures peak memory per algorithm, one process per solve.</p>";
    let Some(rows) = &run.rows else {
        return format!(
            "<p>This folder does not keep results.csv: no per-solve times.</p>{memory}"
        );
    };
    let mut groups: BTreeMap<String, Vec<&Row>> = BTreeMap::new();
    for r in rows.iter().filter(|r| r.error.is_empty()) {
        let name = if r.algorithm == "exact" {
            format!("exact {}", r.objective)
        } else {
            r.algorithm.clone()
        };
        groups.entry(name).or_default().push(r);
    }
    let mut table_rows = Vec::new();
    let mut series = Vec::new();
    for (name, rs) in &groups {
        let pts = median_times(rs);
        // Fitted on N >= 16 where there are enough sizes: tiny instances measure overhead.
        let big: Vec<(f64, f64)> = pts.iter().copied().filter(|(n, _)| *n >= 16.0).collect();
        let fit = chart::fit_power(if big.len() >= 3 { &big } else { &pts });
        let mut secs: Vec<f64> = rs.iter().map(|r| r.seconds).collect();
        secs.sort_by(f64::total_cmp);
        table_rows.push(vec![
            Cell::text(name),
            Cell::text(rs.len().to_string()).class("num"),
            Cell::text(rs.iter().map(|r| r.n).max().unwrap_or(0).to_string()).class("num"),
            num(secs.iter().sum()),
            num(quantile(&secs, 0.5)),
            num(secs[secs.len() - 1]),
            fit.map_or(Cell::text("-"), |(_, s)| num(s)),
        ]);
        series.push(Series {
            name: name.clone(),
            points: pts
                .iter()
                .map(|&(n, s)| Point {
                    x: n,
                    y: s,
                    tip: format!("{name}\nN = {n}: median {s:.6} s"),
                })
                .collect(),
            fit,
        });
    }
    let mut charts = String::from("<div class=\"figs\">");
    for (i, chunk) in series.chunks(8).enumerate() {
        charts.push_str(&chart::scatter(
            &format!("time against N, part {}", i + 1),
            chunk,
            true,
            true,
            "N (log)",
            "median seconds (log)",
        ));
    }
    charts.push_str("</div>");
    format!(
        "<p>Median seconds per solve against N, log-log, with the least-squares exponent (dashed; fitted on N ≥ 16 when three sizes or more are there). Times are wall-clock per solve under the run's parallel jobs.</p>{charts}{}{memory}",
        table(
            "time-table",
            &[
                "algorithm",
                "rows",
                "largest N",
                "total s",
                "median s",
                "max s",
                "fitted exponent"
            ],
            &table_rows
        )
    )
}

fn errors(run: &Run) -> String {
    let Some(rows) = &run.rows else {
        let failed: Vec<&StatRow> = run
            .stats
            .iter()
            .filter(|s| s.size_bin == "all" && (s.errors > 0 || s.invalid > 0))
            .collect();
        if failed.is_empty() {
            return "<p>No error and no invalid result in stats.csv (time limits of the exact solver are not in stats.csv).</p>".into();
        }
        let t: Vec<Vec<Cell>> = failed
            .iter()
            .map(|s| {
                vec![
                    Cell::text(&s.family),
                    Cell::text(&s.algorithm),
                    Cell::text(&s.objective),
                    Cell::text(s.errors.to_string()).class("num"),
                    Cell::text(s.invalid.to_string()).class("num"),
                ]
            })
            .collect();
        return table(
            "errors-table",
            &["family", "algorithm", "objective", "errors", "invalid"],
            &t,
        );
    };
    const LISTED: usize = 500;
    let failed: Vec<&Row> = rows
        .iter()
        .filter(|r| !r.error.is_empty() || r.valid == Some(false))
        .collect();
    let limits: Vec<&Row> = rows
        .iter()
        .filter(|r| r.opt_status == "time_limit")
        .collect();
    let mut out = format!(
        "<p>{} error or invalid row(s), {} exact solve(s) stopped at the time limit (their bound and incumbent stand in for the optimum).</p>",
        failed.len(),
        limits.len()
    );
    let line = |r: &&Row| {
        vec![
            Cell::text(&r.instance),
            Cell::text(r.n.to_string()).class("num"),
            Cell::text(&r.algorithm),
            Cell::text(&r.objective),
            Cell::text(r.value.map_or("-".into(), |v| v.to_string())).class("num"),
            Cell::text(r.lower_bound.map_or("-".into(), |v| v.to_string())).class("num"),
            Cell::text(format!("{:.2}", r.seconds)).class("num"),
            Cell::text(if r.error.is_empty() {
                &r.opt_status
            } else {
                &r.error
            }),
        ]
    };
    let header = [
        "instance",
        "N",
        "algorithm",
        "objective",
        "value",
        "bound",
        "seconds",
        "error or status",
    ];
    if !failed.is_empty() {
        let t: Vec<Vec<Cell>> = failed.iter().take(LISTED).map(line).collect();
        out.push_str("<h3>Errors</h3>");
        out.push_str(&table("errors-table", &header, &t));
    }
    if !limits.is_empty() {
        let t: Vec<Vec<Cell>> = limits.iter().take(LISTED).map(line).collect();
        out.push_str("<h3>Time limits</h3>");
        out.push_str(&table("limits-table", &header, &t));
    }
    if failed.len().max(limits.len()) > LISTED {
        let _ = write!(
            out,
            "<p class=\"note\">The first {LISTED} of each are listed.</p>"
        );
    }
    out
}

fn hunt(run: &Run) -> String {
    let Some((dir, t)) = &run.hunt else {
        return String::new();
    };
    let subdirs: Vec<std::path::PathBuf> = std::fs::read_dir(dir)
        .map(|r| {
            r.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.is_dir())
                .collect()
        })
        .unwrap_or_default();
    let mut subdirs = subdirs;
    subdirs.sort();
    let refs: Vec<&Path> = subdirs.iter().map(|p| p.as_path()).collect();
    format!(
        "<p>{}: the worst ratios the searches found (summary.csv), and each hunt's best instance drawn.</p>{}{}",
        esc(&dir.display().to_string()),
        csv_table("hunt-table", t),
        folder_figures(&refs)
    )
}
