//! Figures of orthogonal polygons with non-integral coordinates: the SVG of a
//! polygon with a tour over it, the area it sweeps and δB, and `mowmill draw` on a `.wkt`.

mod common;

use common::{mowmill, temp_dir};
use mowmill::draw::DrawOptions;
use mowmill::ortho::{self, Polygon, Tour};

/// An L of width 1.5 with a notch of 0.75: non-integral, millable by one tour.
const L_SHAPE: &str = "POLYGON ((0 0, 4.5 0, 4.5 1.5, 1.5 1.5, 1.5 3.25, 0 3.25, 0 0))";
const BLUE: &str = "stroke=\"#0072B2\"";
const SWEPT_FILL: &str = "fill=\"#56B4E9\"";
const CONTOUR: &str = "stroke=\"#009E73\"";
const WITNESS: &str = "stroke=\"#D62728\"";

fn svg_of(polygon: &Polygon, tour: &Tour) -> String {
    let erosion = ortho::feasibility(polygon).expect("millable");
    let opts = DrawOptions {
        title: Some("corollary4".into()),
        ..DrawOptions::default()
    };
    ortho::draw_svg(polygon, Some(tour), Some(&erosion), &opts).unwrap()
}

#[test]
fn the_corollary4_figure_has_polygon_swept_area_contour_and_tour() {
    let p = Polygon::parse(L_SHAPE, "l.wkt").unwrap();
    let (tour, _) = ortho::corollary4(&p).unwrap();
    let report = ortho::check(&p, &tour).unwrap();
    assert!(report.valid, "{:?}", report.error);
    let svg = svg_of(&p, &tour);
    assert!(svg.starts_with("<svg"), "{}", &svg[..80.min(svg.len())]);
    assert!(!svg.contains("NaN"), "non-finite coordinates");
    // The polygon: its fill and its six-cornered outline.
    assert!(svg.contains("<polygon") && svg.contains("fill=\"#E9E9E9\""));
    let outline = svg
        .lines()
        .find(|l| l.contains("stroke=\"#333333\"") && l.contains("<polyline"))
        .expect("the polygon's outline");
    let corners = outline.split("points=\"").nth(1).unwrap();
    assert_eq!(
        corners
            .split_whitespace()
            .filter(|p| p.contains(','))
            .count(),
        8
    );
    // The swept area, translucent; δB dashed (many short pieces); the tour.
    assert!(svg.matches(SWEPT_FILL).count() >= 2, "swept area");
    assert!(svg.contains("opacity=\"0.35\""));
    assert!(svg.matches(CONTOUR).count() > 4, "δB dashed");
    assert!(svg.matches(BLUE).count() >= 2, "tour and legend");
    // A valid tour: no witness marks; the caption is the checker's.
    assert!(!svg.contains(WITNESS));
    assert!(
        svg.contains(&format!("length {}", report.length)),
        "length in the caption"
    );
    assert!(svg.contains("valid") && !svg.contains("INVALID"));
    for label in ["polygon", "swept area", "δB", "tour"] {
        assert!(svg.contains(label), "legend: {label}");
    }
}

#[test]
fn an_invalid_tour_gets_red_marks_at_the_witnesses() {
    // One pass at height 0.5 through a 3 × 1.5 rectangle leaves the top band unmilled; one at
    // 1.25 leaves the rectangle. Each witness is a ring and a cross.
    let p = Polygon::parse("POLYGON ((0 0, 3 0, 3 1.5, 0 1.5, 0 0))", "r.wkt").unwrap();
    let tour = |y: &str| {
        Tour::from_json(
            &format!(r#"{{"model":"ortho","tour":[["0.5","{y}"],["2.5","{y}"]]}}"#),
            "t",
        )
        .unwrap()
    };
    let low = svg_of(&p, &tour("0.5"));
    assert!(low.contains("INVALID: the point (1.5, 1.25) of the polygon is not milled"));
    // The ring and the two strokes of the cross, at the witness and in the legend.
    assert_eq!(low.matches(WITNESS).count(), 6, "{low}");
    assert!(low.contains("witness"), "the legend");
    let high = svg_of(&p, &tour("1.25"));
    assert!(high.contains("outside the polygon"));
    assert!(high.matches(WITNESS).count() >= 6);
}

#[test]
fn draw_on_a_non_integral_wkt_checks_and_draws_and_refuses_bad_tours() {
    let dir = temp_dir("ortho-draw");
    let wkt = dir.join("l.wkt");
    std::fs::write(&wkt, format!("{L_SHAPE}\n")).unwrap();
    let (wkt_s, tour, fig) = (
        wkt.to_str().unwrap(),
        dir.join("t.json"),
        dir.join("fig.svg"),
    );
    let out = mowmill(&[
        "solve",
        wkt_s,
        "--algo",
        "corollary4",
        "--tour-out",
        tour.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = mowmill(&[
        "draw",
        wkt_s,
        "--tour",
        tour.to_str().unwrap(),
        "--out",
        fig.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(&fig).unwrap();
    assert!(svg.contains(SWEPT_FILL) && svg.contains(CONTOUR) && svg.contains(BLUE));
    assert!(svg.contains(">\nl\n</text>"), "the title is the file stem");
    assert!(svg.contains("valid") && !svg.contains("INVALID"));

    // A tour file that is not a tour, and one that does not exist: exit 2, naming the file.
    let bad = dir.join("bad.json");
    // Floating-point numbers are not exact coordinates.
    std::fs::write(&bad, "{\"model\": \"ortho\", \"tour\": [[0.5, 0.5]]}\n").unwrap();
    let missing = dir.join("missing.json");
    for t in [&bad, &missing] {
        let out = mowmill(&[
            "draw",
            wkt_s,
            "--tour",
            t.to_str().unwrap(),
            "--out",
            dir.join("bad.svg").to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(t.to_str().unwrap()), "{err}");
        assert!(!dir.join("bad.svg").exists());
    }

    // An integral .wkt keeps the grid drawing (its caption counts pixels).
    let square = dir.join("square.wkt");
    std::fs::write(&square, "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n").unwrap();
    let grid = dir.join("grid.svg");
    let out = mowmill(&[
        "draw",
        square.to_str().unwrap(),
        "--out",
        grid.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&grid).unwrap().contains("N = 4"));
    std::fs::remove_dir_all(&dir).ok();
}
