//! README's findings section is generated from the committed claims table
//! (`results/validate/findings.md`, written by `mowmill claims --out results/validate`):
//! `scripts/update-readme-tables.sh` splices it between the markers. Nothing there is
//! written by hand, so this fails when they differ.

#[test]
fn readme_findings_are_the_committed_claims_tables() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let findings = std::fs::read_to_string("results/validate/findings.md")
        .expect("results/validate/findings.md (scripts/validate.sh writes it)");
    let begin = "<!-- findings:begin -->\n";
    let end = "<!-- findings:end -->";
    let a = readme
        .find(begin)
        .expect("README has a findings:begin marker")
        + begin.len();
    let b = readme[a..]
        .find(end)
        .expect("README has a findings:end marker")
        + a;
    assert_eq!(
        &readme[a..b],
        findings,
        "README's findings differ from results/validate/findings.md: run scripts/update-readme-tables.sh"
    );
    // The claims table names each of them as violated.
    let claims = std::fs::read_to_string("results/validate/claims.csv").unwrap();
    for line in findings.lines().filter(|l| l.starts_with("- **")) {
        let claim = line[4..].split(" (").next().unwrap();
        assert!(
            claims.contains(&format!(",{claim},")),
            "{claim} not in claims.csv"
        );
    }
}
