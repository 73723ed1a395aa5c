//! `mowmill report`: the page a bench run ends with, read back as text (the browser test,
//! scripts/report-browser-test.sh, renders it in Chromium in CI).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const MINI: &str = r#"
name = "mini"
seed = 5

[[family]]
family = "random-simple"
n = [12, 20]
count = 2

[[family]]
family = "thin"
n = [11, 15]
holes = 0
count = 2

[[exact]]
objective = "cc-turns"
max_n = 30
time_limit = 20

[[exact]]
objective = "length"
max_n = 30
time_limit = 20
"#;

fn mowmill(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(args)
        .output()
        .unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A small bench run in a fresh folder: (the temp dir holding it, the run folder).
fn bench(report: bool) -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let config = tmp.path().join("mini.toml");
    std::fs::write(&config, MINI).unwrap();
    let out = tmp.path().join("run");
    let mut args = vec![
        "bench",
        "--config",
        s(&config),
        "--out",
        s(&out),
        "--jobs",
        "2",
    ];
    if !report {
        args.push("--no-report");
    }
    let o = mowmill(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (tmp, out)
}

/// The verdicts of a claims.csv, in order.
fn verdicts(path: &Path) -> Vec<String> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let i = r
        .headers()
        .unwrap()
        .iter()
        .position(|h| h == "verdict")
        .unwrap();
    r.records().map(|rec| rec.unwrap()[i].to_string()).collect()
}

/// The text of the verdict cells of the page's claims table, in order.
fn page_verdicts(page: &str) -> Vec<String> {
    let table = &page[page.find(r#"id="claims-table""#).unwrap()..];
    let table = &table[..table.find("</table>").unwrap()];
    table
        .split(r#"<td class="verdict "#)
        .skip(1)
        .map(|cell| {
            let start = cell.find('>').unwrap() + 1;
            let end = cell.find("</td>").unwrap();
            cell[start..end].replace("&amp;", "&")
        })
        .collect()
}

#[test]
fn bench_ends_with_a_self_contained_report() {
    let (tmp, run) = bench(true);
    let page = std::fs::read_to_string(run.join("report.html")).unwrap();
    // Nothing fetched: a policy forbidding it, and no outside URL in a src or href.
    assert!(page.contains("Content-Security-Policy\" content=\"default-src 'none'"));
    for bad in [
        "src=\"http",
        "href=\"http",
        "src='http",
        "@import",
        "url(http",
    ] {
        assert!(!page.contains(bad), "the page refers outside: {bad}");
    }
    // The sections in the issue's order.
    let at = |id: &str| {
        page.find(&format!("<section id=\"{id}\">"))
            .unwrap_or_else(|| panic!("no section {id}"))
    };
    let order = [
        "provenance",
        "claims",
        "ratios",
        "worst",
        "findings",
        "time",
        "errors",
    ];
    for w in order.windows(2) {
        assert!(at(w[0]) < at(w[1]), "{} after {}", w[0], w[1]);
    }
    // The claims table: one row per claim of the table `mowmill claims` computes, same verdicts.
    let claims_dir = tmp.path().join("claims");
    let o = mowmill(&[
        "claims",
        "--from",
        s(&run),
        "--tight",
        "/nonexistent",
        "--hunt",
        "/nonexistent",
        "--out",
        s(&claims_dir),
    ]);
    assert!(
        o.status.code().is_some_and(|c| c <= 1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let want = verdicts(&claims_dir.join("claims.csv"));
    assert!(want.len() > 10, "{} claims", want.len());
    assert_eq!(page_verdicts(&page), want);
    // The worst instances are drawn, every walk recounted to its row's value.
    let drawn = page.matches(", as in the row").count();
    assert!(drawn >= 4, "{drawn} worst-instance walks drawn");
    assert!(!page.contains("the re-run differs"));
    assert!(page.contains("data:image/svg+xml;base64,"));
    // The manifest's digest is the file's.
    let manifest = std::fs::read(run.join("manifest.json")).unwrap();
    assert!(page.contains(&mowmill::harness::run::sha256_hex(&manifest)));
    // Time against N with a fitted exponent per algorithm.
    assert!(page.contains("fitted exponent"));

    // --no-report writes none.
    let (_tmp2, quiet) = bench(false);
    assert!(!quiet.join("report.html").exists());

    // Two runs of one suite side by side: the gate passes, no verdict changed.
    let cmp = tmp.path().join("cmp.html");
    let o = mowmill(&["report", "--compare", s(&run), s(&quiet), "--out", s(&cmp)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let cmp = std::fs::read_to_string(cmp).unwrap();
    assert!(
        cmp.contains(r#"<span class="good">passed</span>"#),
        "gate verdict missing"
    );
    assert!(cmp.contains("0 claim verdict(s) differ"));
}

#[test]
fn a_planted_results_folder_stays_text() {
    let (tmp, run) = bench(false);
    // An instance name that is markup, in the rows (and the walk re-run finds no file for it).
    let rows = std::fs::read_to_string(run.join("results.csv")).unwrap();
    let name = rows
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(1)
        .unwrap()
        .to_string();
    let planted = rows.replace(
        &name,
        "<script>alert(1)</script><img src=http://x.invalid/a>",
    );
    std::fs::write(run.join("results.csv"), planted).unwrap();
    std::fs::remove_file(run.join("stats.csv")).unwrap();
    let out = tmp.path().join("p.html");
    let o = mowmill(&["report", s(&run), "--out", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = std::fs::read_to_string(out).unwrap();
    assert_eq!(
        page.matches("<script>").count(),
        1,
        "only the page's own script"
    );
    assert!(!page.contains("<img src=http"));
    assert!(page.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
}

#[test]
fn bad_folders_are_refused_with_exit_2() {
    let tmp = tempfile::tempdir().unwrap();
    let o = mowmill(&["report", s(&tmp.path().join("missing"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("expected a run folder"));
    let empty = tmp.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    let o = mowmill(&["report", s(&empty)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("expected stats.csv or results.csv"));
    // A broken stats.csv: the file and line are named.
    std::fs::write(
        empty.join("stats.csv"),
        "family,size_bin\nrect,\"unterminated\n",
    )
    .unwrap();
    let o = mowmill(&["report", s(&empty)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("stats.csv"), "{err}");
    // A manifest.json that is a FIFO is refused, not waited on.
    let fifo = tmp.path().join("fifo");
    std::fs::create_dir(&fifo).unwrap();
    std::fs::write(
        fifo.join("stats.csv"),
        "family,size_bin,algorithm,objective\n",
    )
    .unwrap();
    let made = Command::new("mkfifo")
        .arg(fifo.join("manifest.json"))
        .status()
        .unwrap();
    assert!(made.success());
    let o = mowmill(&["report", s(&fifo)]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("manifest.json"));
}
