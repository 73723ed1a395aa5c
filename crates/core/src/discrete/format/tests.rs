//! Tests of the discrete file formats: round trips, the documented text form, error sites.

use super::json::json_site;
use super::*;
use crate::region::Region;

fn sample() -> Discrete {
    let mut g = Discrete::new(
        4,
        &[(0, 1), (1, 2), (2, 3), (3, 0), (1, 3)],
        &[(1, 0, 2), (3, 2, 0)],
        Some(vec![
            [0.0, 0.0, 0.0],
            [1.5, 0.0, 0.0],
            [1.0, -2.25, 0.0],
            [1e-7, 3.0, 0.0],
        ]),
    )
    .unwrap();
    g.set_directions(Some(3));
    g
}

#[test]
fn both_forms_round_trip() {
    let mut z = sample();
    z.set_coords(Some(vec![[0.0, 0.0, 1.0]; 4])).unwrap();
    let mut bare = Discrete::new(2, &[(0, 1)], &[], None).unwrap();
    bare.set_directions(None);
    let region = Discrete::from_region(&Region::from_ascii("###\n#.#\n###\n"));
    for g in [sample(), z, bare, region] {
        let j = to_json(&g);
        let back = parse_json(&j, "g.json").unwrap();
        assert_eq!(back, g, "{j}");
        assert_eq!(to_json(&back), j);
        let t = to_text(&g);
        let back = parse_text(&t, "g.dm").unwrap();
        assert_eq!(back, g, "{t}");
        assert_eq!(to_text(&back), t);
        assert_eq!(parse_discrete(&j, "x").unwrap(), g);
        assert_eq!(parse_discrete(&t, "x").unwrap(), g);
    }
}

#[test]
fn generated_instances_round_trip() {
    use crate::discrete::generate::*;
    for seed in 0..4 {
        let params = PlaneParams::default();
        for g in [
            random_voxels(60, seed, 1).unwrap().to_discrete(),
            random_hex(40, seed).unwrap().to_discrete(),
            random_honeycomb(40, seed).unwrap().to_discrete(),
            random_plane_graph(40, seed, &params).unwrap(),
        ] {
            let (j, t) = (to_json(&g), to_text(&g));
            assert_eq!(parse_json(&j, "g.json").unwrap(), g);
            assert_eq!(parse_text(&t, "g.dm").unwrap(), g);
        }
    }
}

#[test]
fn the_text_form_is_as_documented() {
    let t = to_text(&sample());
    let body: Vec<&str> = t.lines().skip(1).collect();
    assert_eq!(
        body,
        [
            "discrete 4",
            "d 3",
            "e 0 1",
            "e 0 3",
            "e 1 2",
            "e 1 3",
            "e 2 3",
            "c 1 0 2",
            "c 3 0 2",
            "p 0 0 0",
            "p 1 1.5 0",
            "p 2 1 -2.25",
            "p 3 0.0000001 3",
        ]
    );
    let j = to_json(&sample());
    assert_eq!(
        j,
        "{\"vertices\": 4,\n \"edges\": [[0,1],[0,3],[1,2],[1,3],[2,3]],\n \"collinear\": \
         [[1,0,2],[3,0,2]],\n \"coords\": [[0,0],[1.5,0],[1,-2.25],[0.0000001,3]],\n \
         \"directions\": 3}\n"
    );
    // Comments, blank lines, CRLF, any record order, 3-D points mixed with 2-D.
    let g = parse_text(
        "# c\n\r\n discrete 3 # three\r\nc 1 2 0\np 2 1 2 3\ne 1 2\ne 0 1\np 0 0 0\np 1 1 1\n",
        "t.dm",
    )
    .unwrap();
    assert_eq!(g.turn(0, 1, 2), 0);
    assert_eq!(g.coords(2), Some([1.0, 2.0, 3.0]));
    assert_eq!(g.directions(), None);
}

/// Each bad file gives `file:line:col: message-start`.
#[test]
fn text_errors_name_line_and_column() {
    let cases = [
        ("", "1:1: no header"),
        ("e 0 1\n", "1:1: 'e' before the header"),
        ("discrete\n", "1:9: missing N"),
        ("discrete x\n", "1:10: 'x' is not a number of vertices"),
        (
            "discrete 0\n",
            "1:10: 0 vertices; expected from 1 to 50000000",
        ),
        ("discrete 50000001\n", "1:10: 50000001 vertices"),
        ("discrete 3 4\n", "1:12: unexpected field '4'"),
        ("discrete 3\ndiscrete 3\n", "2:1: a second header"),
        ("discrete 3\nf 0 1\n", "2:1: unknown record 'f'"),
        ("discrete 3\ne 0\n", "2:4: missing b; expected 'e a b'"),
        ("discrete 3\ne 0 1 2\n", "2:7: unexpected field '2'"),
        ("discrete 3\ne 0 -1\n", "2:5: '-1' is not a vertex index"),
        ("discrete 3\n\ne  0 3\n", "3:6: vertex 3 is outside 0..3"),
        ("discrete 3\ne 1 1\n", "2:5: edge 1 1 is a loop"),
        (
            "discrete 3\ne 0 1\ne 1 2\ne 2 1\n",
            "4:3: edge 2 1 is also at line 3",
        ),
        ("discrete 3\nc 1 0 2\n", "2:5: 1 0 is not an edge"),
        ("discrete 3\ne 0 1\nc 1 0 2\n", "3:7: 1 2 is not an edge"),
        (
            "discrete 3\ne 0 1\ne 1 2\nc 1 0 0\n",
            "4:7: collinear pair 0 0 at vertex 1 names one edge twice",
        ),
        (
            "discrete 3\ne 0 1\ne 1 2\nc 1 0 2\n# again\nc 1 2 0\n",
            "6:5: edge 1 2 is also in the collinear pair at line 4",
        ),
        ("discrete 3\nc 1 0\n", "2:6: missing b; expected 'c v a b'"),
        (
            "discrete 3\np 0 1\n",
            "2:6: missing y; expected 'p v x y [z]'",
        ),
        ("discrete 3\np 0 1 inf\n", "2:7: 'inf' is not a coordinate"),
        ("discrete 3\np 0 1 2 3 4\n", "2:11: unexpected field '4'"),
        (
            "discrete 2\np 0 1 2\np 0 1 2\n",
            "3:3: vertex 0 already has coordinates on line 2",
        ),
        (
            "discrete 3\ne 0 1\np 2 0 0\np 0 0 0\n",
            "3:1: 'p' lines for 2 of 3 vertices (vertex 1 has none)",
        ),
        (
            "discrete 3\nd 0\n",
            "2:3: '0' is not a number of directions",
        ),
        (
            "discrete 3\nd 2\nd 2\n",
            "3:1: a second 'd' line (the first is line 2)",
        ),
    ];
    let wrong: Vec<String> = cases
        .iter()
        .map(|(text, expected)| {
            (
                text,
                expected,
                parse_text(text, "t.dm").unwrap_err().to_string(),
            )
        })
        .filter(|(_, expected, e)| !e.starts_with(&format!("t.dm:{expected}")))
        .map(|(text, _, e)| format!("{text:?}: {e}"))
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn json_errors_name_line_and_column() {
    let cases = [
        (
            "{\"vertices\": 3, \"edges\": []",
            "1:27: expected a discrete instance",
        ),
        ("{\"vertices\": 3}", "1:15: expected a discrete instance"),
        (
            "{\"vertices\": 3, \"edges\": [], \"extra\": 1}",
            "1:36: expected a discrete instance",
        ),
        ("{\"vertices\": 0, \"edges\": []}", "1:14: 0 vertices"),
        (
            "{\"edges\": [[0, 1],\n  [1, 5]], \"vertices\": 3}",
            "2:7: vertex 5 is outside 0..3",
        ),
        (
            "{\"vertices\": 3,\n \"edges\": [[0, 1], [1, 2],\n  [2, 1]]}",
            "3:4: edge 2 1 is also at edges[1] (line 2)",
        ),
        (
            "{\"vertices\": 3, \"edges\": [[0,1],[1,2]], \"collinear\": [[1, 0, 2], [1, 2, 0]]}",
            "1:70: edge 1 2 is also in the collinear pair at collinear[0] (line 1)",
        ),
        (
            "{\"vertices\": 3, \"edges\": [[0,1]], \"collinear\": [[1, 0, 2]]}",
            "1:56: 1 2 is not an edge",
        ),
        (
            "{\"vertices\": 2, \"edges\": [[0,1]], \"coords\": [[0, 0]]}",
            "1:45: 1 coordinates for 2 vertices",
        ),
        (
            "{\"vertices\": 2, \"edges\": [[0,1]], \"coords\": [[0, 0], [1]]}",
            "1:54: a point of 1 numbers",
        ),
        (
            "{\"vertices\": 2, \"edges\": [[0,1]], \"directions\": 0}",
            "1:49: 0 directions",
        ),
        (
            "{\"vertices\": 3, \"edges\": [[0, 1], [2, 2]]}",
            "1:39: edge 2 2 is a loop",
        ),
    ];
    let wrong: Vec<String> = cases
        .iter()
        .map(|(text, expected)| {
            (
                text,
                expected,
                parse_json(text, "t.json").unwrap_err().to_string(),
            )
        })
        .filter(|(_, expected, e)| !e.starts_with(&format!("t.json:{expected}")))
        .map(|(text, _, e)| format!("{text}: {e}"))
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn json_sites_are_found_past_strings_and_nesting() {
    let text = r#"{"a": {"edges": [1]}, "s": "x\"]}", "edges" : [ [0, 1] , [2,  3] ]}"#;
    let at = json_site(text, Site::at("edges", 1, 1)).unwrap();
    assert_eq!(&text[at..at + 1], "3");
    let at = json_site(text, Site::key("edges")).unwrap();
    assert_eq!(&text[at..at + 3], "[ [");
}

#[test]
fn walk_files_round_trip_and_refuse_other_models() {
    let c = DiscreteCover::new(vec![vec![0, 1, 2], vec![3]]);
    let s = c.to_json();
    assert_eq!(s, r#"{"model":"discrete","cycles":[[0,1,2],[3]]}"#);
    assert_eq!(DiscreteCover::from_json(&s, "w.json").unwrap(), c);
    for (text, expected) in [
        (
            r#"{"cycles": [[0]]}"#,
            "w.json:1:17: expected discrete walks",
        ),
        (r#"{"model": "grid", "cycles": []}"#, "w.json:1:16:"),
        (
            r#"{"model": "discrete", "cycles": [[0, -1]]}"#,
            "w.json:1:39:",
        ),
        (
            r#"{"model": "discrete", "cycles": [], "x": 0}"#,
            "w.json:1:39:",
        ),
    ] {
        let e = DiscreteCover::from_json(text, "w.json")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(expected), "{text}: {e}");
    }
}

#[test]
fn files_are_told_apart_by_extension_and_content() {
    let dir = std::env::temp_dir().join(format!("mowmill-dm-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let g = sample();
    for name in ["g.json", "g.dm", "g.txt"] {
        let path = dir.join(name);
        write_discrete(&g, &path).unwrap();
        assert_eq!(read_discrete(&path).unwrap(), g, "{name}");
    }
    // A .dm file holding JSON is read as text, and says so.
    std::fs::write(dir.join("j.dm"), to_json(&g)).unwrap();
    let e = read_discrete(&dir.join("j.dm")).unwrap_err().to_string();
    assert!(
        e.contains("j.dm:1:1: '{\"vertices\":' before the header"),
        "{e}"
    );
    let w = DiscreteCover::new(vec![vec![0, 1, 2, 3]]);
    w.write(&dir.join("w.json")).unwrap();
    assert_eq!(DiscreteCover::read(&dir.join("w.json")).unwrap(), w);
    std::fs::remove_dir_all(&dir).unwrap();
}
