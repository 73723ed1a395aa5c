//! Tests of the grid drawings: the bundled font, SVG and PNG output of a small tour, refused
//! extensions and unwritable files, U-turn rings and separate strands, merged rectangles,
//! contours, grid lines, and the plain drawing of large regions.

use super::*;

fn temp_path(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("mowmill-draw-{}-{name}", std::process::id()))
}

fn walk(points: &[(i32, i32)]) -> Vec<Pixel> {
    points.iter().map(|&p| Pixel::from(p)).collect()
}

/// A 2-wide L of 12 pixels and a tour around it with six 90° turns and no U-turn.
fn l_shape() -> (Region, CycleCover) {
    let region = Region::from_ascii(
        "##..
         ##..
         ####
         ####",
    );
    let tour = CycleCover::tour(walk(&[
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 0),
        (3, 1),
        (2, 1),
        (1, 1),
        (1, 2),
        (1, 3),
        (0, 3),
        (0, 2),
        (0, 1),
    ]));
    (region, tour)
}

fn count(haystack: &str, needle: &str) -> usize {
    haystack.matches(needle).count()
}

#[test]
fn the_bundled_font_registers_and_measures_text() {
    ensure_fonts();
    let font = FontDesc::new(FontFamily::from(FONT_FAMILY), 20.0, FontStyle::Normal);
    let (w, _) = font.box_size("N = 24").expect("font is registered");
    assert!(w > 20, "text width {w}");
}

#[test]
fn l_shape_to_svg_has_the_tour_and_one_dot_per_turn() {
    let (region, tour) = l_shape();
    let out = temp_path("l.svg");
    let opts = DrawOptions {
        title: Some("L shape".into()),
        caption: Some("N = 12, length 12, turns 6, 1 cycle".into()),
        ..DrawOptions::default()
    };
    draw(&region, Some(&tour), &out, &opts).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    let blue = "stroke=\"#0072B2\"";
    assert_eq!(
        count(
            &svg,
            &format!("<polyline fill=\"none\" opacity=\"1\" {blue}")
        ),
        1
    );
    // Six 90° turns, each a filled dot; no U-turn rings.
    assert_eq!(count(&svg, "<circle"), 6);
    assert_eq!(count(&svg, "fill=\"#0072B2\""), 6);
    assert!(svg.contains("L shape"));
    assert!(svg.contains("turns 6"));
    // The outline is one contour: the L has six corners, drawn closed with two repeats.
    let outline = svg
        .lines()
        .find(|l| l.contains("stroke=\"#333333\""))
        .unwrap();
    let points = outline.split("points=\"").nth(1).unwrap();
    assert_eq!(
        points
            .split_whitespace()
            .filter(|p| p.contains(','))
            .count(),
        8
    );
}

#[test]
fn l_shape_to_png_is_a_png() {
    let (region, tour) = l_shape();
    let out = temp_path("l.png");
    draw(&region, Some(&tour), &out, &DrawOptions::default()).unwrap();
    let bytes = std::fs::read(&out).unwrap();
    std::fs::remove_file(&out).ok();
    assert!(bytes.len() > 1000, "{} bytes", bytes.len());
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn unknown_extensions_are_refused_before_writing() {
    let (region, tour) = l_shape();
    for name in ["l.jpg", "l"] {
        let out = temp_path(name);
        let err = draw(&region, Some(&tour), &out, &DrawOptions::default()).unwrap_err();
        assert!(matches!(err, Error::Invalid(_)), "{err}");
        assert!(err.to_string().contains(".svg or .png"), "{err}");
        assert!(!out.exists());
    }
    let err = Format::of(Path::new("fig.JPG")).unwrap_err();
    assert!(err.to_string().contains(".jpg"), "{err}");
    assert_eq!(Format::of(Path::new("fig.SVG")).unwrap(), Format::Svg);
}

#[test]
fn unwritable_files_are_io_errors() {
    let (region, tour) = l_shape();
    for name in ["l.svg", "l.png"] {
        let out = temp_path("no-such-dir").join(name);
        let err = draw(&region, Some(&tour), &out, &DrawOptions::default()).unwrap_err();
        assert!(matches!(err, Error::Io { .. }), "{err}");
        assert!(
            err.to_string().starts_with(&out.display().to_string()),
            "{err}"
        );
    }
}

#[test]
fn a_walk_that_jumps_is_refused() {
    let region = Region::rectangle(3, 1);
    let cover = CycleCover::tour(walk(&[(0, 0), (2, 0)]));
    let err = draw(
        &region,
        Some(&cover),
        &temp_path("jump.svg"),
        &DrawOptions::default(),
    )
    .unwrap_err();
    assert!(err.to_string().contains("(0, 0) to (2, 0)"), "{err}");
}

#[test]
fn u_turns_get_rings_and_repeated_edges_separate_strands() {
    // Two pixels, walked there and back: the one edge twice, a U-turn at each end.
    let cover = CycleCover::tour(walk(&[(0, 0), (1, 0)]));
    let shapes = walk_shapes(&cover, true).unwrap();
    assert_eq!(shapes[0].turns.len(), 0);
    assert_eq!(shapes[0].u_turns.len(), 2);
    let ys: Vec<f64> = shapes[0].line.iter().map(|p| p.1).collect();
    assert_eq!(ys[..4], [0.6, 0.4, 0.4, 0.6]);
    // Plain drawing keeps both traversals on the centre line.
    let plain = walk_shapes(&cover, false).unwrap();
    assert!(plain[0].line.iter().all(|p| p.1 == 0.5));

    let region = Region::rectangle(2, 1);
    let out = temp_path("hairpin.svg");
    draw(&region, Some(&cover), &out, &DrawOptions::default()).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    // Each ring is a filled disc under a stroked circle.
    assert_eq!(count(&svg, "<circle"), 4);
    assert_eq!(count(&svg, "fill=\"none\" stroke=\"#0072B2\""), 2);
}

#[test]
fn single_pixel_walks_are_circles_in_their_own_colours() {
    let region = Region::rectangle(2, 1);
    let cover = CycleCover::new(vec![walk(&[(0, 0)]), walk(&[(1, 0)])]);
    let out = temp_path("singles.svg");
    draw(&region, Some(&cover), &out, &DrawOptions::default()).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    assert_eq!(count(&svg, "<circle"), 2);
    assert_eq!(count(&svg, "stroke=\"#0072B2\""), 1);
    assert_eq!(count(&svg, "stroke=\"#D55E00\""), 1);
}

#[test]
fn runs_merge_into_rectangles() {
    assert_eq!(
        region_rectangles(&Region::rectangle(5, 3)),
        vec![[0, 5, 0, 3]]
    );
    // A 4 × 3 rectangle with a hole at (1, 1): bottom row, two pieces, top row.
    let ring = Region::from_ascii(
        "####
         #.##
         ####",
    );
    let mut rects = region_rectangles(&ring);
    rects.sort();
    assert_eq!(
        rects,
        vec![[0, 1, 1, 2], [0, 4, 0, 1], [0, 4, 2, 3], [2, 4, 1, 2]]
    );
    let area: i32 = rects.iter().map(|r| (r[1] - r[0]) * (r[3] - r[2])).sum();
    assert_eq!(area as usize, ring.len());
    // Rows with an empty row between them do not merge.
    let mut rects = region_rectangles(&Region::from_ascii("##\n..\n##\n##"));
    rects.sort();
    assert_eq!(rects, vec![[0, 2, 0, 2], [0, 2, 3, 4]]);
}

#[test]
fn contours_separate_outer_boundary_holes_and_diagonal_touches() {
    let corners = |r: &Region| -> Vec<Vec<(i64, i64)>> {
        boundary_rings(r, Saddle::Apart)
            .into_iter()
            .map(|ring| ring.corners)
            .collect()
    };
    let ring = Region::from_ascii(
        "###
         #.#
         ###",
    );
    let contours = corners(&ring);
    assert_eq!(contours.len(), 2);
    let outer = contours.iter().find(|c| c.contains(&(0, 0))).unwrap();
    let hole = contours.iter().find(|c| c.contains(&(1, 1))).unwrap();
    assert_eq!(outer.len(), 4);
    assert!(outer.contains(&(3, 3)));
    assert_eq!(hole.len(), 4);
    assert!(hole.contains(&(2, 2)));
    // Two pixels touching at a corner are two squares.
    let diagonal = Region::from_ascii(
        ".#
         #.",
    );
    let contours = corners(&diagonal);
    assert_eq!(contours.len(), 2);
    assert!(contours.iter().all(|c| c.len() == 4));
}

#[test]
fn grid_lines_run_only_between_region_pixels() {
    let segments = grid_segments(&Region::rectangle(3, 2));
    // One horizontal line of length 3 and two vertical lines of length 2.
    let mut segments = segments;
    segments.sort();
    assert_eq!(
        segments,
        vec![[(0, 1), (3, 1)], [(1, 0), (1, 2)], [(2, 0), (2, 2)]]
    );
}

#[test]
fn large_regions_draw_plainly() {
    let region = Region::rectangle(300, 250);
    let cover = CycleCover::tour(walk(&[(0, 0), (1, 0), (1, 1), (0, 1)]));
    let out = temp_path("large.svg");
    draw(&region, Some(&cover), &out, &DrawOptions::default()).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    // One rectangle for the region (plus the background), no grid, no markers.
    assert_eq!(count(&svg, "<rect"), 2);
    assert_eq!(count(&svg, "<circle"), 0);
    assert_eq!(count(&svg, "#C8C8C8"), 0);
}
