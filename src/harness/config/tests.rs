//! Tests of the run configuration: list expansion, validation messages and digests.

use super::*;

#[test]
fn lists_expand_into_every_combination() {
    let c = Config::parse(
        "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = [2, 3]\nheight = [4, 5, 6]\ncount = 2\n",
        "t.toml",
    )
    .unwrap();
    let inst = c.instances().unwrap();
    assert_eq!(inst.len(), 12);
    assert_eq!(inst[0].params, "width=2 height=4");
    assert_eq!(inst[0].name, "rect_width2_height4_i000");
    // Seeds depend on parameters and index only.
    assert_ne!(inst[0].seed, inst[1].seed);
    assert_eq!(inst[0].seed, derive_seed(1, "rect", "width=2 height=4", 0));
}

#[test]
fn malformed_configs_name_the_key() {
    let bad = [
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidht = 3\n",
            "widht",
        ),
        (
            "name = \"t\"\n[[family]]\nfamily = \"blob\"\n",
            "family[0].family",
        ),
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nn = \"x\"\n",
            "expected a usize or a list",
        ),
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\nalgorithms = [\"nope\"]\n",
            "family[0].algorithms",
        ),
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n[[exact]]\nobjective = \"len\"\nmax_n = 3\ntime_limit = 1\n",
            "exact[0].objective",
        ),
        (
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidth = 2\nheight = 2\n[[exact]]\nobjective = \"length\"\ntime_limit = 1\n",
            "max_n",
        ),
        ("name = \"t\"\n", "no instances"),
    ];
    for (text, needle) in bad {
        let e = Config::parse(text, "bad.toml").unwrap_err().to_string();
        assert!(
            e.contains(needle) && e.contains("bad.toml"),
            "{needle}: {e}"
        );
    }
}

#[test]
fn params_keep_their_order_and_serialize_for_the_manifest() {
    let c = Config::parse(
        "name = \"t\"\n[[family]]\nfamily = \"random-holed\"\nno_cut = true\nstyle = [\"blob\", \"snake\"]\ncompactness = 1\nn = 40\n",
        "t.toml",
    )
    .unwrap();
    let inst = c.instances().unwrap();
    assert_eq!(inst.len(), 2);
    assert_eq!(inst[0].params, "n=40 style=blob compactness=1 no_cut=true");
    let v = serde_json::to_value(&c.family[0]).unwrap();
    assert_eq!(v["n"], serde_json::json!([40]));
    assert_eq!(v["style"], serde_json::json!(["blob", "snake"]));
    assert_eq!(v["no_cut"], serde_json::json!([true]));
    assert_eq!(v["holes"], serde_json::json!([]));
    assert_eq!(v["count"], serde_json::json!(1));
}
