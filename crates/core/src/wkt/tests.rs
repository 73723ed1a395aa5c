//! Tests of WKT import and export.

use super::lexer::{NumberValue, number_value};
use super::writer::write_ring;
use super::*;
use crate::error::Result;
use crate::region::{Pixel, Region};
use proptest::prelude::*;

fn parse(text: &str) -> Result<Region> {
    parse_wkt(text, "t.wkt")
}

/// The error message of a refused input.
fn refusal(text: &str) -> String {
    match parse(text) {
        Ok(r) => panic!("accepted {text:?} as {r:?}"),
        Err(e) => e.to_string(),
    }
}

fn assert_refused(text: &str, location: &str, words: &str) {
    let message = refusal(text);
    assert!(
        message.starts_with(&format!("t.wkt:{location}: ")),
        "{text:?}: expected location {location}, got {message:?}"
    );
    assert!(
        message.contains(words),
        "{text:?}: expected {words:?} in {message:?}"
    );
}

#[test]
fn rectangle() {
    let r = parse("POLYGON((0 0, 3 0, 3 2, 0 2, 0 0))").unwrap();
    assert_eq!(r, Region::rectangle(3, 2));
    assert_eq!(r.len(), 6);
    assert_eq!(to_wkt(&r), "POLYGON ((0 0, 3 0, 3 2, 0 2, 0 0))");
}

#[test]
fn square_with_a_hole() {
    let text = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))";
    let r = parse(text).unwrap();
    assert_eq!(r, Region::from_ascii("####\n#..#\n#..#\n####\n"));
    // Holes are written clockwise, from their lowest-leftmost corner.
    assert_eq!(to_wkt(&r), text);
}

#[test]
fn multipolygon_of_two_squares() {
    let text = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((3 1, 4 1, 4 2, 3 2, 3 1)))";
    let r = parse(text).unwrap();
    assert_eq!(r, Region::from_ascii("##.#\n##..\n"));
    assert_eq!(to_wkt(&r), text);
}

#[test]
fn l_shape_with_collinear_and_repeated_vertices() {
    // Clockwise, a repeated vertex, a collinear one, numbers in several notations.
    let text = "polygon ((0 0, 0 3, 1 3, 1 1, 1 1, 2 1, 3.0 1, 3E0 0, +0 0))";
    let r = parse(text).unwrap();
    assert_eq!(r, Region::from_ascii("#..\n#..\n###\n"));
    assert_eq!(to_wkt(&r), "POLYGON ((0 0, 3 0, 3 1, 1 1, 1 3, 0 3, 0 0))");
}

#[test]
fn whitespace_case_and_negative_coordinates() {
    let text = "\n  MultiPolygon\t(\n ( (-2 -1,-1 -1,\n-1 0,-2 0,-2 -1) ) , EMPTY )\n\n";
    let r = parse(text).unwrap();
    assert_eq!(r.pixels(), &[Pixel::new(-2, -1)]);
    assert_eq!(number_value("1e1"), NumberValue::Integer(10));
    assert_eq!(number_value("-2.5e0"), NumberValue::Fraction);
    assert_eq!(number_value("-2.5e1"), NumberValue::Integer(-25));
    assert_eq!(number_value("-2.50e1"), NumberValue::Integer(-25));
    assert_eq!(number_value("-2.50e2"), NumberValue::Integer(-250));
    assert_eq!(number_value("3.0000000000000000001"), NumberValue::Fraction);
    assert_eq!(
        number_value("0.000e99999999999999999999"),
        NumberValue::Integer(0)
    );
    assert_eq!(number_value("1073741824"), NumberValue::Integer(MAX_COORD));
    assert_eq!(number_value("1073741825"), NumberValue::OutOfRange);
    assert_eq!(number_value("-1073741824"), NumberValue::OutOfRange);
    assert_eq!(number_value("2147483648"), NumberValue::OutOfRange);
    assert_eq!(
        number_value("1e99999999999999999999"),
        NumberValue::OutOfRange
    );
    assert_eq!(
        number_value("1e-99999999999999999999"),
        NumberValue::Fraction
    );
    assert_eq!(number_value("1-2"), NumberValue::Malformed);
    assert_eq!(number_value("."), NumberValue::Malformed);
    assert_eq!(number_value("1e"), NumberValue::Malformed);
}

#[test]
fn rings_may_touch_at_a_point() {
    // A hole touching the outer ring at (2, 1), as to_wkt writes it.
    let r = Region::from_ascii("###\n#.#\n##.\n");
    let text = to_wkt(&r);
    assert_eq!(
        text,
        "POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 0 3, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))"
    );
    assert_eq!(parse(&text).unwrap(), r);
    // Two holes touching at a corner.
    let r = Region::from_ascii("####\n#.##\n##.#\n####\n");
    let text = to_wkt(&r);
    assert_eq!(
        text,
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (2 1, 2 2, 3 2, 3 1, 2 1), \
         (1 2, 1 3, 2 3, 2 2, 1 2))"
    );
    assert_eq!(parse(&text).unwrap(), r);
    // A pixel in a plus-shaped hole touching it at its four corners: two polygons.
    let r = Region::from_ascii("#####\n##.##\n#.#.#\n##.##\n#####\n");
    let text = to_wkt(&r);
    assert!(text.starts_with("MULTIPOLYGON (((0 0, 5 0, 5 5, 0 5, 0 0), (2 1, 2 2, 1 2,"));
    assert!(text.ends_with("((2 2, 3 2, 3 3, 2 3, 2 2)))"), "{text}");
    assert_eq!(parse(&text).unwrap(), r);
}

#[test]
fn empty_region_writes_and_is_refused() {
    let empty = Region::from_pixels([]).unwrap();
    assert_eq!(to_wkt(&empty), "POLYGON EMPTY");
    assert_refused("POLYGON EMPTY", "1:9", "empty region");
    assert_refused("multipolygon empty", "1:14", "empty region");
    assert_refused("MULTIPOLYGON (EMPTY, EMPTY)", "1:1", "empty region");
}

#[test]
fn refuses_syntax_errors() {
    assert_refused(
        "LINESTRING (0 0, 1 0)",
        "1:1",
        "unknown geometry type 'LINESTRING'; expected POLYGON or MULTIPOLYGON",
    );
    assert_refused(
        "",
        "1:1",
        "expected POLYGON or MULTIPOLYGON, found end of input",
    );
    assert_refused("(0 0)", "1:1", "expected POLYGON or MULTIPOLYGON");
    assert_refused(
        "POLYGON Z ((0 0 0))",
        "1:9",
        "expected '(' to start a polygon",
    );
    assert_refused("POLYGON ((0 0 1, 1 0 1))", "1:15", "only 2-D vertices");
    assert_refused("POLYGON ((0 0, 1))", "1:17", "expected the y coordinate");
    assert_refused(
        "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0)",
        "1:35",
        "found end of input",
    );
    assert_refused("POLYGON ((0 0; 1 0))", "1:14", "unexpected character ';'");
    assert_refused(
        "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0) (",
        "1:36",
        "expected ',' or ')'",
    );
    assert_refused("POLYGON ((0 0, 1-1 0))", "1:16", "malformed number 1-1");
    assert_refused(
        "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\nPOLYGON",
        "2:1",
        "unexpected 'POLYGON' after the end of the geometry; expected end of input",
    );
    assert_refused(
        "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)) x",
        "1:43",
        "expected ',' or ')' after a polygon",
    );
}

#[test]
fn refuses_bad_coordinates() {
    assert_refused(
        "POLYGON ((0 0, 1.5 0, 1.5 1, 0 1, 0 0))",
        "1:16",
        "1.5 is not an integer",
    );
    assert_refused(
        "POLYGON ((0 0, 1 0, 1 1e-1, 0 1, 0 0))",
        "1:23",
        "not an integer",
    );
    assert_refused(
        "POLYGON ((0 0, 3e10 0, 3e10 1, 0 1, 0 0))",
        "1:16",
        "out of range",
    );
}

#[test]
fn refuses_diagonal_edges() {
    assert_refused(
        "POLYGON ((0 0, 2 0,\n  2 1, 0 1,\n    1 0, 0 0))",
        "3:5",
        "edge from (0,1) to (1,0) is not axis-parallel",
    );
    assert_refused(
        "POLYGON ((0 0, 2 1, 0 1, 0 0))",
        "1:16",
        "edge from (0,0) to (2,1) is not axis-parallel",
    );
}

#[test]
fn refuses_bad_rings() {
    assert_refused(
        "POLYGON ((0 0, 2 0, 2 2, 0 2))",
        "1:26",
        "ring is not closed: it starts at (0,0) and ends at (0,2)",
    );
    assert_refused("POLYGON ((0 0, 2 0, 0 0))", "1:11", "2 distinct corners");
    assert_refused("POLYGON ((5 5))", "1:11", "0 distinct corners");
    assert_refused("POLYGON ((0 0, 1 0, 2 0, 0 0))", "1:11", "encloses no area");
    assert_refused(
        "POLYGON ((0 0, 3 0, 2 0, 2 1, 0 1, 0 0))",
        "1:16",
        "ring turns back on itself at (3,0)",
    );
}

#[test]
fn refuses_crossing_and_overlapping_edges() {
    // A ring crossing itself: two loops joined in a figure eight.
    assert_refused(
        "POLYGON ((0 0, 2 0, 2 2, 1 2, 1 -1, 0 -1, 0 0))",
        "1:31",
        "edge from (1,2) to (1,-1) crosses edge from (0,0) to (2,0) at (1,0)",
    );
    // Two holes overlapping along part of an edge.
    assert_refused(
        "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1),\n\
         (3 2, 5 2, 5 4, 3 4, 3 2))",
        "2:22",
        "edge from (3,4) to (3,2) overlaps edge from (3,1) to (3,3) along (3,2)-(3,3)",
    );
    // Polygons sharing an edge segment.
    assert_refused(
        "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 0, 2 0, 2 1, 1 1, 1 0)))",
        "1:66",
        "edge from (1,1) to (1,0) overlaps edge from (1,0) to (1,1) along (1,0)-(1,1)",
    );
    // A hole touching the outer ring along a segment.
    assert_refused(
        "POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (0 1, 1 1, 1 2, 0 2, 0 1))",
        "1:58",
        "edge from (0,2) to (0,1) overlaps edge from (0,3) to (0,0) along (0,1)-(0,2)",
    );
    // A ring through the same point twice (a figure eight pinched at (1,1)).
    assert_refused(
        "POLYGON ((0 0, 1 0, 1 1, 2 1, 2 2, 1 2, 1 1, 0 1, 0 0))",
        "1:41",
        "ring passes through (1,1) twice",
    );
}

#[test]
fn refuses_bad_nesting() {
    assert_refused(
        "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0),\n (3 0, 4 0, 4 1, 3 1, 3 0))",
        "2:3",
        "hole is not inside its outer ring",
    );
    assert_refused(
        "POLYGON ((1 1, 2 1, 2 2, 1 2, 1 1), (0 0, 3 0, 3 3, 0 3, 0 0))",
        "1:38",
        "hole is not inside its outer ring",
    );
    assert_refused(
        "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 8 1, 8 8, 1 8, 1 1), \
         (2 2, 3 2, 3 3, 2 3, 2 2))",
        "1:65",
        "hole lies inside another hole",
    );
    assert_refused(
        "MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))",
        "1:46",
        "polygon 2 lies inside polygon 1",
    );
    // The first polygon inside the second: reported at the inner one.
    assert_refused(
        "MULTIPOLYGON (((1 1, 2 1, 2 2, 1 2, 1 1)), ((0 0, 9 0, 9 9, 0 9, 0 0)))",
        "1:17",
        "polygon 1 lies inside polygon 2",
    );
    // A polygon inside another one's hole is fine, and so is a hole in it.
    let r = parse(
        "MULTIPOLYGON (((0 0, 5 0, 5 5, 0 5, 0 0), (1 1, 4 1, 4 4, 1 4, 1 1)), \
         ((2 2, 3 2, 3 3, 2 3, 2 2)))",
    )
    .unwrap();
    assert_eq!(r, Region::from_ascii("#####\n#...#\n#.#.#\n#...#\n#####\n"));
}

#[test]
fn refuses_more_pixels_than_the_limit_from_the_area() {
    // 108 bytes asking for 10^18 pixels: refused from the area, before any pixel is filled.
    let huge = "POLYGON((0 0, 1000000000 0, 1000000000 1000000000, 0 1000000000, 0 0))";
    assert_refused(
        huge,
        "1:1",
        "encloses 1000000000000000000 pixels; expected at most",
    );
    // One pixel over the limit (a 20 000 001 × 1 strip).
    assert_refused(
        "POLYGON((0 0, 20000001 0, 20000001 1, 0 1, 0 0))",
        "1:1",
        "encloses 20000001 pixels",
    );
}

#[test]
fn a_huge_bounding_box_with_few_pixels_is_fine() {
    // Two pixels 10^9 apart, and a thin square frame whose holes take most of its box.
    let r = parse(
        "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1000000000 1000000000, 1000000001 \
         1000000000, 1000000001 1000000001, 1000000000 1000000001, 1000000000 1000000000)))",
    )
    .unwrap();
    assert_eq!(
        r.pixels(),
        &[Pixel::new(0, 0), Pixel::new(1_000_000_000, 1_000_000_000)]
    );
    let frame = parse(
        "POLYGON ((0 0, 100000 0, 100000 100000, 0 100000, 0 0), \
         (1 1, 1 99999, 99999 99999, 99999 1, 1 1))",
    )
    .unwrap();
    assert_eq!(frame.len(), 4 * 99_999);
    assert_eq!(parse(&to_wkt(&frame)).unwrap(), frame);
}

#[test]
fn extreme_coordinates() {
    let r = Region::from_pixels([
        Pixel::new(crate::region::MAX_COORD, -crate::region::MAX_COORD),
        Pixel::new(crate::region::MAX_COORD, 1 - crate::region::MAX_COORD),
    ])
    .unwrap();
    let text = to_wkt(&r);
    assert_eq!(
        text,
        "POLYGON ((1073741823 -1073741823, 1073741824 -1073741823, 1073741824 -1073741821, \
         1073741823 -1073741821, 1073741823 -1073741823))"
    );
    assert_eq!(parse(&text).unwrap(), r);
    // One past the limit (a pixel at x = 2^30) is refused with the line and column.
    let e = parse("POLYGON ((0 0, 1073741825 0, 1073741825 1, 0 1, 0 0))").unwrap_err();
    assert!(
        e.to_string()
            .contains(":1:16: coordinate 1073741825 is out of range"),
        "{e}"
    );
}

#[test]
fn large_random_region_round_trips() {
    // Many saddles, holes and components; quadratic checks would take minutes here.
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut pixels = Vec::new();
    for y in 0..400 {
        for x in 0..400 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            if state % 5 < 3 {
                pixels.push(Pixel::new(x, y));
            }
        }
    }
    let r = Region::from_pixels(pixels).unwrap();
    assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
}

#[test]
fn every_committed_instance_round_trips() {
    // parse_wkt refuses rings that touch themselves, so a round trip also shows the written
    // WKT valid.
    // The workspace root, two levels above this crate.
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let mut stack = vec![root.join("instances"), root.join("tests")];
    let mut read = 0;
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "grid" || e == "wkt")
                && let Ok(instance) = crate::instance::Instance::read(&path)
            {
                let r = instance.region;
                assert_eq!(parse(&to_wkt(&r)).unwrap(), r, "{}", path.display());
                read += 1;
            }
        }
    }
    assert!(read >= 10, "only {read} instance files found");
}

/// Reference rasterizer: even-odd rule at every pixel centre, edge by edge.
fn brute_force(rings: &[Vec<(i64, i64)>]) -> Vec<Pixel> {
    let mut pixels = Vec::new();
    for y in -2..14 {
        for x in -2..14 {
            let (cx, cy) = (2 * x + 1, 2 * y + 1);
            let mut inside = false;
            for ring in rings {
                for k in 0..ring.len() {
                    let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                    let (ay, by) = (2 * a.1, 2 * b.1);
                    if a.0 == b.0 && (ay < cy) != (by < cy) && 2 * a.0 > cx {
                        inside = !inside;
                    }
                }
            }
            if inside {
                pixels.push(Pixel::new(x as i32, y as i32));
            }
        }
    }
    pixels
}

fn rectangle_ring(r: (i64, i64, i64, i64)) -> Vec<(i64, i64)> {
    let (x0, y0, x1, y1) = r;
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
}

fn ring_text(ring: &[(i64, i64)]) -> String {
    let mut s = String::new();
    write_ring(&mut s, ring);
    s
}

fn rectangles(n: usize) -> impl Strategy<Value = Vec<(i64, i64, i64, i64)>> {
    prop::collection::vec((0..10i64, 0..10i64, 1..5i64, 1..5i64), 1..n).prop_map(|v| {
        v.into_iter()
            .map(|(x, y, w, h)| (x, y, x + w, y + h))
            .collect()
    })
}

/// Closed rectangles share interior points or a segment (not just a corner or nothing).
fn meet_in_more_than_a_point(a: (i64, i64, i64, i64), b: (i64, i64, i64, i64)) -> bool {
    let x = a.0.max(b.0) <= a.2.min(b.2);
    let y = a.1.max(b.1) <= a.3.min(b.3);
    let x_positive = a.0.max(b.0) < a.2.min(b.2);
    let y_positive = a.1.max(b.1) < a.3.min(b.3);
    x && y && (x_positive || y_positive)
}

/// Random pixel subsets of small boxes at random offsets, of random density.
fn regions() -> impl Strategy<Value = Region> {
    (1..9i32, 1..9i32, -20..20i32, -20..20i32, 1..10u8)
        .prop_flat_map(|(w, h, dx, dy, density)| {
            prop::collection::vec(0..10u8, (w * h) as usize).prop_map(move |cells| {
                let pixels = cells
                    .iter()
                    .enumerate()
                    .filter(|&(_, &c)| c < density)
                    .map(|(k, _)| Pixel::new(dx + k as i32 % w, dy + k as i32 / w));
                Region::from_pixels(pixels).unwrap()
            })
        })
        .prop_filter("non-empty", |r| !r.is_empty())
}

proptest! {
    #[test]
    fn round_trip(r in regions()) {
        let text = to_wkt(&r);
        prop_assert_eq!(parse(&text).unwrap(), r.clone(), "{}", text);
        for s in crate::region::Symmetry::all() {
            let image = r.transformed(s);
            prop_assert_eq!(parse(&to_wkt(&image)).unwrap(), image);
        }
    }

    #[test]
    fn round_trip_with_diagonal_touches(
        (w, cells) in (1..10i32, 1..10i32)
            .prop_flat_map(|(w, h)| (Just(w), prop::collection::vec(0..8u8, (w * h) as usize)))
    ) {
        // Mostly a checkerboard's black cells, a few white ones: saddles at most corners, within
        // a component and between components.
        let pixels = cells.iter().enumerate().filter_map(|(k, &c)| {
            let (x, y) = (k as i32 % w, k as i32 / w);
            ((x + y) % 2 == 0 && c > 0 || c == 0).then(|| Pixel::new(x, y))
        });
        let r = Region::from_pixels(pixels).unwrap();
        if !r.is_empty() {
            prop_assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
        }
    }

    #[test]
    fn multipolygon_of_rectangles(rects in rectangles(6)) {
        let text = format!(
            "MULTIPOLYGON ({})",
            rects.iter().map(|&r| format!("({})", ring_text(&rectangle_ring(r))))
                .collect::<Vec<_>>().join(", ")
        );
        let valid = (0..rects.len())
            .all(|i| (0..i).all(|j| !meet_in_more_than_a_point(rects[i], rects[j])));
        match parse(&text) {
            Ok(r) => {
                prop_assert!(valid, "accepted {}", text);
                let rings: Vec<_> = rects.iter().map(|&r| rectangle_ring(r)).collect();
                prop_assert_eq!(r, Region::from_pixels(brute_force(&rings)).unwrap());
            }
            Err(e) => prop_assert!(!valid, "refused {}: {}", text, e),
        }
    }

    #[test]
    fn polygon_with_rectangular_holes(holes in rectangles(5)) {
        let outer = (1, 1, 12, 12);
        let mut rings = vec![rectangle_ring(outer)];
        rings.extend(holes.iter().map(|&h| rectangle_ring(h)));
        let text = format!(
            "POLYGON ({})",
            rings.iter().map(|r| ring_text(r)).collect::<Vec<_>>().join(", ")
        );
        let strictly_inside = |h: (i64, i64, i64, i64)| {
            h.0 > outer.0 && h.1 > outer.1 && h.2 < outer.2 && h.3 < outer.3
        };
        let valid = holes.iter().all(|&h| strictly_inside(h))
            && (0..holes.len())
                .all(|i| (0..i).all(|j| !meet_in_more_than_a_point(holes[i], holes[j])));
        match parse(&text) {
            Ok(r) => {
                prop_assert!(valid, "accepted {}", text);
                prop_assert_eq!(r, Region::from_pixels(brute_force(&rings)).unwrap());
            }
            Err(e) => prop_assert!(!valid, "refused {}: {}", text, e),
        }
    }

    #[test]
    fn never_panics_on_arbitrary_text(text in any::<String>()) {
        let _ = parse(&text);
    }

    #[test]
    fn never_panics_on_wkt_like_text(
        text in "(POLYGON|MULTIPOLYGON|EMPTY|[()]|, |-?[0-9]{1,2}(\\.[05])?(e[+-]?1)? ){0,40}"
    ) {
        if let Ok(r) = parse(&text) {
            prop_assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
        }
    }

    #[test]
    fn never_panics_on_mutated_wkt(
        r in regions(),
        edits in prop::collection::vec((any::<prop::sample::Index>(), 0..4u8, 0..16usize), 1..4),
    ) {
        const ALPHABET: &[u8] = b"()(),, 0123-9.eE";
        let mut bytes = to_wkt(&r).into_bytes();
        for (at, kind, c) in edits {
            let k = at.index(bytes.len() + 1);
            match kind {
                0 if k < bytes.len() => { bytes.remove(k); }
                1 if k < bytes.len() => bytes[k] = ALPHABET[c],
                2 if k < bytes.len() => bytes.truncate(k),
                _ => bytes.insert(k, ALPHABET[c]),
            }
        }
        let text = String::from_utf8(bytes).unwrap();
        if let Ok(r) = parse(&text) {
            prop_assert_eq!(parse(&to_wkt(&r)).unwrap(), r);
        }
    }
}
