//! The registry is the one source of the algorithm tables in docs/algorithms.md and of
//! `mowmill algos`.

use std::process::Command;

fn algos(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .arg("algos")
        .args(args)
        .output()
        .expect("run mowmill");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// docs/algorithms.md's lines between `<!-- algos:begin -->` and `<!-- algos:end -->`.
fn readme_block() -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/algorithms.md");
    let readme = std::fs::read_to_string(path).expect("read docs/algorithms.md");
    let (_, rest) = readme
        .split_once("<!-- algos:begin -->\n")
        .expect("docs/algorithms.md has a line <!-- algos:begin -->");
    let (block, _) = rest
        .split_once("<!-- algos:end -->")
        .expect("docs/algorithms.md has a line <!-- algos:end --> after <!-- algos:begin -->");
    block.to_string()
}

#[test]
fn readme_algorithm_tables_are_the_registry() {
    let generated = algos(&["--markdown"]);
    let readme = readme_block();
    if readme != generated {
        let first = readme
            .lines()
            .zip(generated.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(readme.lines().count().min(generated.lines().count()));
        panic!(
            "docs/algorithms.md's algorithm tables (between <!-- algos:begin --> and <!-- algos:end -->) \
             differ from `mowmill algos --markdown` from line {} of the block on:\n  docs:      {:?}\n  generated: {:?}\n\
             Run scripts/update-readme-tables.sh to rewrite them from the registry.",
            first + 1,
            readme.lines().nth(first),
            generated.lines().nth(first),
        );
    }
}

#[test]
fn markdown_has_one_table_per_paper_and_a_row_per_algorithm() {
    let md = algos(&["--markdown"]);
    let registry = mowmill::algorithms::REGISTRY;
    for paper in mowmill::algorithms::theorems::Paper::ALL {
        assert!(md.contains(&format!("*{}*:", paper.title())), "{md}");
    }
    for a in registry {
        let rows = md
            .lines()
            .filter(|l| l.starts_with(&format!("| `{}` |", a.name)))
            .count();
        assert_eq!(rows, 1, "{}: one row", a.name);
    }
    // thin-cc's tour guarantee (missing from the hand-written tables before).
    let thin_cc = md.lines().find(|l| l.starts_with("| `thin-cc` |")).unwrap();
    assert!(
        thin_cc.contains("`turns <= 3/2 OPT`: Corollary 5.3 (tour)"),
        "{thin_cc}"
    );
}

#[test]
fn json_names_the_theorem_of_every_guarantee() {
    let list: serde_json::Value = serde_json::from_str(&algos(&["--json"])).unwrap();
    let list = list.as_array().unwrap();
    assert_eq!(list.len(), mowmill::algorithms::REGISTRY.len());
    for a in list {
        let name = a["name"].as_str().unwrap();
        assert!(
            a["paper"].is_string() && a["requires"].is_string(),
            "{name}"
        );
        assert!(!a["objectives"].as_array().unwrap().is_empty(), "{name}");
        let details = a["guarantee_details"].as_array().unwrap();
        assert_eq!(details.len(), a["guarantees"].as_array().unwrap().len());
        for (d, text) in details.iter().zip(a["guarantees"].as_array().unwrap()) {
            assert_eq!(&d["guarantee"], text);
            let theorem = d["theorem"].as_str().unwrap();
            assert!(
                theorem.ends_with(d["paper"].as_str().unwrap()),
                "{name}: {theorem}"
            );
        }
        for c in a["claims"].as_array().unwrap() {
            let imp = c["implementation"].as_str().unwrap();
            assert!(
                imp == "paper" || imp.starts_with("reading: "),
                "{name}: {imp}"
            );
        }
    }
}
