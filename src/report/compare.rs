//! `mowmill report --compare A B`: two runs side by side, for a pull request review: the
//! gate's verdict (B against A's baseline, `mowmill gate --baseline A --current B`), what got
//! better or worse per group of `stats.csv`, and the claims' verdicts of both.

use super::html::{self, Cell, esc, table};
use super::{Options, Run};
use crate::error::Result;
use crate::harness::gate::{self, Verdict};
use crate::harness::stats::StatRow;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use std::path::Path;

/// A relative change below this is "same" (the gate's default tolerance).
const SAME: f64 = 0.005;

/// The comparison page of the runs in `a` (the baseline) and `b`.
pub fn compare(a: &Path, b: &Path, opts: &Options) -> Result<String> {
    let ra = Run::read(a, opts)?;
    let rb = Run::read(b, opts)?;
    let sections = vec![
        (
            "provenance".to_string(),
            "Provenance".to_string(),
            provenance(&ra, &rb),
        ),
        ("gate".into(), "Gate".into(), gate_section(a, b)),
        ("groups".into(), "Groups".into(), groups(&ra, &rb)),
        ("claims".into(), "Claims".into(), claims(&ra, &rb)),
    ];
    Ok(html::page(
        "mowmill report: comparison",
        &format!("A = {} (baseline), B = {}", a.display(), b.display()),
        &sections,
    ))
}

fn field(run: &Run, key: &str) -> String {
    run.manifest
        .as_ref()
        .and_then(|(m, _)| m.get(key))
        .map_or(String::new(), |v| {
            v.as_str().map_or(v.to_string(), str::to_string)
        })
}

fn provenance(a: &Run, b: &Run) -> String {
    let mut rows = Vec::new();
    for key in [
        "run_id",
        "git_commit",
        "git_dirty",
        "config_file",
        "config_sha256",
        "start",
        "end",
        "instances",
        "rows",
    ] {
        let (x, y) = (field(a, key), field(b, key));
        let class = if x == y { "" } else { "warn" };
        rows.push(vec![
            Cell::text(key),
            Cell::text(&x),
            Cell::text(&y).class(class),
        ]);
    }
    table("provenance-table", &["", "A", "B"], &rows)
}

fn gate_section(a: &Path, b: &Path) -> String {
    match gate::gate(a, b, SAME) {
        Ok(report) => {
            let verdict = if report.passed() { "passed" } else { "FAIL" };
            let rows: Vec<Vec<Cell>> = report
                .findings
                .iter()
                .map(|f| {
                    let v = match f.verdict {
                        Verdict::Fail => "FAIL",
                        Verdict::Improved => "improved",
                    };
                    vec![
                        Cell::text(v).class(match f.verdict {
                            Verdict::Fail => "bad",
                            Verdict::Improved => "good",
                        }),
                        Cell::text(f.baseline.map_or("-".into(), |x| format!("{x:.6}")))
                            .class("num"),
                        Cell::text(f.current.map_or("-".into(), |x| format!("{x:.6}")))
                            .class("num"),
                        Cell::text(&f.what),
                    ]
                })
                .collect();
            format!(
                "<p>The gate (<code>mowmill gate --baseline A --current B --tolerance {SAME}</code>): <span class=\"{}\">{verdict}</span>, {} group(s) and {} row(s) compared.</p>{}",
                html::verdict_class(verdict),
                report.groups_compared,
                report.rows_compared,
                table("gate-table", &["verdict", "A", "B", "what"], &rows)
            )
        }
        Err(e) => format!(
            "<p><span class=\"warn\">not comparable</span>: {}</p>",
            esc(&e.to_string())
        ),
    }
}

type Key<'a> = (&'a str, &'a str, &'a str, &'a str);

fn key(s: &StatRow) -> Key<'_> {
    (&s.family, &s.size_bin, &s.algorithm, &s.objective)
}

fn groups(a: &Run, b: &Run) -> String {
    let ia: BTreeMap<Key, &StatRow> = a.stats.iter().map(|s| (key(s), s)).collect();
    let ib: BTreeMap<Key, &StatRow> = b.stats.iter().map(|s| (key(s), s)).collect();
    let keys: BTreeSet<Key> = ia.keys().chain(ib.keys()).copied().collect();
    let mut rows = Vec::new();
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for k in keys {
        let (sa, sb) = (ia.get(&k), ib.get(&k));
        let measure = match (sa, sb) {
            (Some(x), _) | (None, Some(x)) if x.ratio_opt_count > 0 => "opt",
            _ => "lb",
        };
        let get = |s: Option<&&StatRow>| s.map(|s| s.summary(measure));
        let (ma, mb) = (get(sa), get(sb));
        let (xa, xb) = (ma.and_then(|m| m.max), mb.and_then(|m| m.max));
        let (da, db) = (ma.and_then(|m| m.mean), mb.and_then(|m| m.mean));
        let verdict = match (sa, sb, da, db) {
            (None, _, _, _) => "new",
            (_, None, _, _) => "gone",
            (_, _, Some(x), Some(y)) if y > x * (1.0 + SAME) => "worse",
            (_, _, Some(x), Some(y)) if y < x * (1.0 - SAME) => "better",
            _ => "same",
        };
        *counts.entry(verdict).or_default() += 1;
        let f =
            |x: Option<f64>| Cell::text(x.map_or("-".into(), |v| format!("{v:.4}"))).class("num");
        let class = match verdict {
            "worse" => "bad",
            "better" => "good",
            "new" | "gone" => "warn",
            _ => "",
        };
        rows.push(vec![
            Cell::text(k.0),
            Cell::text(k.1),
            Cell::text(k.2),
            Cell::text(k.3),
            Cell::text(measure),
            f(da),
            f(db),
            f(xa),
            f(xb),
            Cell::text(verdict).class(class),
        ]);
    }
    let mut out = format!(
        "<p>Per group of stats.csv (family, size band, algorithm, objective), the mean and maximum ratio of A and B; worse or better by the mean, beyond {SAME} relative: {}.</p>",
        esc(&counts
            .iter()
            .map(|(v, c)| format!("{c} {v}"))
            .collect::<Vec<_>>()
            .join(", "))
    );
    out.push_str(&table(
        "groups-table",
        &[
            "family",
            "size band",
            "algorithm",
            "objective",
            "ratio to",
            "mean A",
            "mean B",
            "max A",
            "max B",
            "change",
        ],
        &rows,
    ));
    out
}

fn claims(a: &Run, b: &Run) -> String {
    let (Some(ta), Some(tb)) = (&a.claims, &b.claims) else {
        return "<p>One of the runs has no claims table.</p>".into();
    };
    let index = |t: &super::Table| -> BTreeMap<(String, String), Vec<String>> {
        t.rows
            .iter()
            .map(|r| {
                (
                    (t.get(r, "paper").to_string(), t.get(r, "claim").to_string()),
                    r.clone(),
                )
            })
            .collect()
    };
    let (ia, ib) = (index(ta), index(tb));
    let keys: BTreeSet<&(String, String)> = ia.keys().chain(ib.keys()).collect();
    let mut rows = Vec::new();
    let mut changed = 0;
    for k in keys {
        let g = |t: &super::Table, r: Option<&Vec<String>>, c: &str| {
            r.map_or(String::new(), |r| t.get(r, c).to_string())
        };
        let (va, vb) = (g(ta, ia.get(k), "verdict"), g(tb, ib.get(k), "verdict"));
        if va != vb {
            changed += 1;
        }
        let verdict = |v: &str| {
            Cell::text(v).class(match html::verdict_class(v) {
                "good" => "good",
                "bad" => "bad",
                "warn" => "warn",
                _ => "",
            })
        };
        rows.push(vec![
            Cell::text(&k.0),
            Cell::text(&k.1),
            verdict(&va),
            verdict(&vb),
            Cell::text(g(ta, ia.get(k), "decided")).class("num"),
            Cell::text(g(tb, ib.get(k), "decided")).class("num"),
            Cell::text(g(ta, ia.get(k), "max_ratio")).class("num"),
            Cell::text(g(tb, ib.get(k), "max_ratio")).class("num"),
            Cell::text(if va == vb { "" } else { "changed" }).class(if va == vb {
                ""
            } else {
                "warn"
            }),
        ]);
    }
    let mut out = String::new();
    let _ = write!(
        out,
        "<p>{changed} claim verdict(s) differ between A and B.</p>"
    );
    out.push_str(&table(
        "claims-compare-table",
        &[
            "paper",
            "claim",
            "verdict A",
            "verdict B",
            "decided A",
            "decided B",
            "worst ratio A",
            "worst ratio B",
            "",
        ],
        &rows,
    ));
    out
}
