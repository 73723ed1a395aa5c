//! Tests of the discrete drawings: hex and voxel tours, an edge walked twice, PNG output, and
//! the refusal of instances without coordinates or of walks outside the instance.

use super::*;
use crate::discrete::lattice::{HexRegion, VoxelRegion};

fn temp_path(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("mowmill-ddraw-{}-{name}", std::process::id()))
}

fn count(haystack: &str, needle: &str) -> usize {
    haystack.matches(needle).count()
}

fn draw_svg(inst: &Discrete, walks: &[Vec<u32>], name: &str) -> String {
    let out = temp_path(name);
    let opts = DrawOptions {
        title: Some(name.into()),
        caption: Some(caption(inst, Some(walks))),
        ..DrawOptions::default()
    };
    draw(inst, Some(walks), &out, &opts).unwrap();
    let svg = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).ok();
    svg
}

const BLUE_LINE: &str = "<polyline fill=\"none\" opacity=\"1\" stroke=\"#0072B2\"";
const BLUE_FILL: &str = "fill=\"#0072B2\"";

/// A flower of 7 hexagonal cells: a centre and its ring of 6.
fn flower() -> (Discrete, Vec<u32>) {
    let ring = [[1, 0], [0, 1], [-1, 1], [-1, 0], [0, -1], [1, -1]];
    let region = HexRegion::from_cells(std::iter::once([0, 0]).chain(ring)).unwrap();
    let idx = |c| region.index_of(c).unwrap() as u32;
    // The centre, then once around the ring.
    let mut walk = vec![idx([0, 0])];
    walk.extend(ring.iter().map(|&c| idx(c)));
    (region.to_discrete(), walk)
}

#[test]
fn a_hex_tour_is_one_polyline_over_seven_hexagons_with_a_dot_per_turn() {
    let (inst, walk) = flower();
    let walks = vec![walk.clone()];
    let report = check::check(&inst, &walks);
    assert!(report.valid, "{report:?}");
    let n = walk.len();
    let turns = (0..n)
        .filter(|&i| inst.turn(walk[(i + n - 1) % n], walk[i], walk[(i + 1) % n]) == 1)
        .count();
    assert_eq!(turns as u64, report.turns, "no U-turns in this walk");
    let svg = draw_svg(&inst, &walks, "flower.svg");
    assert_eq!(count(&svg, BLUE_LINE), 1);
    assert_eq!(count(&svg, "<circle"), turns);
    assert_eq!(count(&svg, BLUE_FILL), turns);
    // Seven hexagons, and the flower's outline: each ring cell has 3 sides outside.
    assert_eq!(count(&svg, "<polygon"), 7);
    assert_eq!(count(&svg, "stroke=\"#333333\""), 18);
    assert!(svg.contains(&format!("n = 7, length 7, turns {turns}, 1 cycle(s)")));
}

#[test]
fn an_edge_walked_twice_is_two_strands_with_u_turn_rings() {
    let (inst, _) = flower();
    let walks = vec![vec![0, 1]];
    let svg = draw_svg(&inst, &walks, "hairpin.svg");
    assert_eq!(count(&svg, BLUE_LINE), 1);
    // Two U-turns: a ring (filled, then stroked) at each end; no turn dots.
    assert_eq!(count(&svg, "<circle"), 4);
    assert_eq!(count(&svg, BLUE_FILL), 0);
    assert!(svg.contains("(not a valid cover)"));
    // The two strands are apart: the polyline has four distinct corners.
    let line = svg.lines().find(|l| l.contains(BLUE_LINE)).unwrap();
    let points: std::collections::HashSet<&str> = line
        .split("points=\"")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .filter(|p| p.contains(','))
        .collect();
    assert_eq!(points.len(), 4, "{line}");
}

#[test]
fn a_voxel_tour_is_drawn_as_two_layer_panels_joined_by_triangles() {
    // A 2 × 2 × 2 cube, toured around the lower layer, up, around the upper, down.
    let cube = VoxelRegion::from_voxels((0..8).map(|i| [i & 1, (i >> 1) & 1, i >> 2])).unwrap();
    let idx = |x, y, z| cube.index_of([x, y, z]).unwrap() as u32;
    let walk = vec![
        idx(0, 0, 0),
        idx(1, 0, 0),
        idx(1, 1, 0),
        idx(0, 1, 0),
        idx(0, 1, 1),
        idx(1, 1, 1),
        idx(1, 0, 1),
        idx(0, 0, 1),
    ];
    let inst = cube.to_discrete();
    let walks = vec![walk];
    assert!(check::check(&inst, &walks).valid);
    let svg = draw_svg(&inst, &walks, "cube.svg");
    assert!(
        svg.contains("\nz = 0\n") && svg.contains("\nz = 1\n"),
        "{svg}"
    );
    // One run per layer, four squares per layer, four triangle ends of the two moves
    // between layers.
    assert_eq!(count(&svg, BLUE_LINE), 2);
    assert_eq!(count(&svg, "<polygon"), 8 + 4);
    assert_eq!(
        count(&svg, &format!("<polygon opacity=\"1\" {BLUE_FILL}")),
        4
    );
    // Every pass turns (8 turns, no U-turns): one dot each.
    assert_eq!(count(&svg, "<circle"), 8);
    assert!(
        svg.contains("n = 8, length 8, turns 8, 1 cycle(s)"),
        "{svg}"
    );
}

#[test]
fn pngs_are_pngs() {
    let (inst, walk) = flower();
    let out = temp_path("flower.png");
    draw(&inst, Some(&[walk]), &out, &DrawOptions::default()).unwrap();
    let bytes = std::fs::read(&out).unwrap();
    std::fs::remove_file(&out).ok();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn an_instance_without_coordinates_or_a_walk_outside_it_is_refused() {
    let bare = Discrete::new(3, &[(0, 1), (1, 2)], &[(1, 0, 2)], None).unwrap();
    let out = temp_path("bare.svg");
    let err = draw(&bare, None, &out, &DrawOptions::default()).unwrap_err();
    assert!(matches!(err, Error::Invalid(_)), "{err}");
    assert!(err.to_string().contains("no coordinates to draw"), "{err}");
    assert!(!out.exists());
    let (inst, _) = flower();
    let err = draw(&inst, Some(&[vec![0, 7]]), &out, &DrawOptions::default()).unwrap_err();
    assert!(err.to_string().contains("vertex 7"), "{err}");
    let err = draw(&inst, None, &temp_path("x.jpg"), &DrawOptions::default()).unwrap_err();
    assert!(err.to_string().contains(".svg or .png"), "{err}");
    assert!(!out.exists());
}
