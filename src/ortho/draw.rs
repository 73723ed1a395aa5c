//! Pictures of an orthogonal polygon with exact coordinates and a tour of the unit square
//! cutter over it (the ortho figures), as SVG or PNG, in the conventions of [`crate::draw`]:
//! title above, caption below, the same palette, fills and turn marks.
//!
//! - **Polygon.** Outer rings filled light grey, holes white, every ring outlined dark.
//! - **Swept area.** The union of the boxes the cutter sweeps, one per move (the move's segment
//!   grown by ½ on every side), translucent blue with a thin outline. The union is computed
//!   exactly on the grid the boxes' coordinates span, so overlaps do not darken it.
//! - **δB.** The contour of the erosion (the centre positions), dashed green, when given.
//! - **Tour.** Each closed walk a polyline in its own colour; a 90° turn is a dot, a U-turn a
//!   ring, a walk of one point a circle.
//! - **Witnesses.** When the checker refuses the tour, a red cross in a ring at its witness
//!   points: a point of the polygon not milled, a point outside it swept.
//! - A legend of what is shown, between the picture and the caption.
//!
//! Coordinates are converted to `f64` ([`Rational::to_f64`]) only here, for drawing; the
//! verdict in the caption is the exact checker's.

use super::cover::Rect;
use super::{Erosion, Point, Polygon, Rational, Report, Tour, check, heading};
use crate::draw::{
    AUTO_SIDE_PX, CAPTION_COLOUR, CAPTION_PX, DrawOptions, DrawResult, FONT_FAMILY, Format,
    MARGIN_PX, MAX_AUTO_PIXEL_SIZE, OUTLINE, PALETTE, Picture, REGION_FILL, Strokes, TITLE_COLOUR,
    TITLE_PX, canvas, ensure_fonts, stroke_closed, stroke_segment, svg_string, text_width,
    write_picture,
};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::{
    Circle, Color, DrawingArea, DrawingBackend, PathElement, RGBColor, Rectangle, Text, WHITE,
};
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontDesc, FontFamily, FontStyle};
use std::path::Path;

/// The swept area's fill (drawn at [`SWEPT_OPACITY`]) and outline.
const SWEPT: RGBColor = RGBColor(0x56, 0xb4, 0xe9);
const SWEPT_OPACITY: f64 = 0.35;
/// δB, dashed.
const CONTOUR: RGBColor = RGBColor(0x00, 0x9e, 0x73);
/// The checker's witness points.
const WITNESS: RGBColor = RGBColor(0xd6, 0x27, 0x28);
/// Walk colours: the palette without the swept area's and δB's colours.
const WALK_COLOURS: [RGBColor; 6] = [
    PALETTE[0], PALETTE[1], PALETTE[3], PALETTE[4], PALETTE[6], PALETTE[7],
];
/// The union of the swept boxes is computed on a grid of at most this many cells; beyond it
/// the boxes are drawn one by one (overlaps then look darker) and without an outline.
const MAX_UNION_CELLS: usize = 4_000_000;
/// Tours with more points than this are drawn without turn marks.
const MARK_LIMIT: usize = 20_000;
/// The legend's text size and its swatches' width, in output pixels.
const LEGEND_PX: f64 = 15.0;
const SWATCH_PX: f64 = 22.0;

/// The caption of a figure: the checker's length (exact, and as a decimal when it is a
/// fraction), turns and cycles, and `valid` or `INVALID: ` and the first violation.
pub fn figure_caption(report: &Report) -> String {
    let exact = report.length.to_string();
    // A fraction gets its decimal value too; a decimal is shown as it is.
    let length = if exact.contains('/') {
        format!("{exact} ≈ {:.3}", report.length.to_f64())
    } else {
        exact
    };
    let verdict = match &report.error {
        None => "valid".to_string(),
        Some(e) => format!("INVALID: {e}"),
    };
    format!(
        "length {length}, turns {}, {} cycle(s), {verdict}",
        report.turns, report.cycles
    )
}

/// Draws `polygon`, and over it the area `tour` sweeps, `erosion`'s contour δB and the tour,
/// to `out`: an SVG or a PNG file, chosen by the extension of `out`.
///
/// # Arguments
///
/// * `polygon` — the polygon, filled, holes white.
/// * `tour` — closed walks of the cutter's centre; checked exactly ([`check`]), and when they
///   do not mill the polygon, the checker's witness points are marked in red.
/// * `erosion` — the centre positions ([`feasibility`](super::feasibility)); its contour is
///   drawn dashed.
/// * `out` — the file to write; its extension (`svg` or `png`, any case) picks the format.
/// * `opts` — title and caption (without a caption and with a tour, [`figure_caption`] of the
///   checker's report), scale (`pixel_size`: output pixels per unit) and `mark_turns`.
///
/// # Returns
///
/// `Error::Invalid` for an unknown extension or when the exact checker cannot decide (see
/// [`check`]); `Error::Io` when the file cannot be written.
///
/// # Complexity
///
/// O(n log n + X·Y) time for n tour points and polygon corners, and the X × Y grid the swept
/// boxes span (at most [`MAX_UNION_CELLS`] cells are used), plus the cost of filling the image.
///
/// # Examples
///
/// ```no_run
/// use mowmill::draw::DrawOptions;
/// use mowmill::ortho::{self, Polygon, Tour};
///
/// let p = Polygon::parse("POLYGON ((0 0, 3 0, 3 1.5, 0 1.5, 0 0))", "p.wkt")?;
/// let t = Tour::from_json(
///     r#"{"model":"ortho","tour":[["0.5","0.5"],["2.5","0.5"],["2.5","1"],["0.5","1"]]}"#,
///     "t",
/// )?;
/// let b = ortho::feasibility(&p).ok();
/// let opts = DrawOptions { title: Some("3 × 1.5".into()), ..DrawOptions::default() };
/// ortho::draw(&p, Some(&t), b.as_ref(), std::path::Path::new("sliver.svg"), &opts)?;
/// # Ok::<(), mowmill::Error>(())
/// ```
pub fn draw(
    polygon: &Polygon,
    tour: Option<&Tour>,
    erosion: Option<&Erosion>,
    out: &Path,
    opts: &DrawOptions,
) -> Result<()> {
    let format = Format::of(out)?;
    let figure = Figure::new(polygon, tour, erosion, opts)?;
    write_picture(&figure, format, out)
}

/// The figure of [`draw`] as SVG text.
pub fn draw_svg(
    polygon: &Polygon,
    tour: Option<&Tour>,
    erosion: Option<&Erosion>,
    opts: &DrawOptions,
) -> Result<String> {
    svg_string(&Figure::new(polygon, tour, erosion, opts)?)
}

type Xy = (f64, f64);

fn xy(p: Point) -> Xy {
    (p.x.to_f64(), p.y.to_f64())
}

/// One closed walk, ready to draw.
#[derive(Clone, Debug, Default)]
struct WalkShape {
    /// The corners of the closed polyline (consecutive repeats dropped).
    line: Vec<Xy>,
    turns: Vec<Xy>,
    u_turns: Vec<Xy>,
    /// The point of a walk that never moves.
    single: Option<Xy>,
}

fn walk_shape(walk: &[Point]) -> WalkShape {
    let mut points: Vec<Point> = Vec::with_capacity(walk.len());
    for &p in walk {
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    let mut shape = WalkShape {
        line: points.iter().map(|&p| xy(p)).collect(),
        ..WalkShape::default()
    };
    let m = points.len();
    if m == 1 {
        shape.single = Some(xy(points[0]));
    }
    if m < 2 || walk.len() > MARK_LIMIT {
        return shape;
    }
    for j in 0..m {
        let (a, p, b) = (points[(j + m - 1) % m], points[j], points[(j + 1) % m]);
        if let (Ok(Some(da)), Ok(Some(db))) = (heading(a, p), heading(p, b)) {
            match da.turn_to(db) {
                1 => shape.turns.push(xy(p)),
                2 => shape.u_turns.push(xy(p)),
                _ => {}
            }
        }
    }
    shape
}

/// The area the cutter sweeps along `tour`'s rectilinear moves.
struct Swept {
    /// Disjoint rectangles `[x0, x1, y0, y1]` whose union it is (or, beyond
    /// [`MAX_UNION_CELLS`], the overlapping boxes themselves).
    rects: Vec<[f64; 4]>,
    /// Its boundary as axis-parallel segments (empty beyond [`MAX_UNION_CELLS`]).
    outline: Vec<[Xy; 2]>,
}

impl Swept {
    fn of(tour: &Tour) -> Swept {
        let mut boxes: Vec<Rect> = Vec::new();
        for walk in &tour.cycles {
            let m = walk.len();
            for i in 0..m {
                let (a, b) = (walk[i], walk[(i + 1) % m]);
                // A diagonal move sweeps nothing for the checker; overflow cannot happen
                // within the input limits.
                if heading(a, b).is_ok()
                    && let Some(r) = Rect::swept(a.x, b.x, a.y, b.y)
                {
                    boxes.push(r);
                }
            }
        }
        let f = |r: &Rect| [r.x0.to_f64(), r.x1.to_f64(), r.y0.to_f64(), r.y1.to_f64()];
        let (xs, ys) = lines(&boxes);
        let (cols, rows) = (xs.len().saturating_sub(1), ys.len().saturating_sub(1));
        if cols.saturating_mul(rows) > MAX_UNION_CELLS {
            return Swept {
                rects: boxes.iter().map(f).collect(),
                outline: Vec::new(),
            };
        }
        // How many boxes cover each cell: a 2-D difference array, summed.
        let width = cols + 1;
        let mut count = vec![0i32; width * (rows + 1)];
        let at = |v: &[Rational], c: Rational| v.partition_point(|&w| w < c);
        for r in &boxes {
            let (i0, i1, j0, j1) = (at(&xs, r.x0), at(&xs, r.x1), at(&ys, r.y0), at(&ys, r.y1));
            count[j0 * width + i0] += 1;
            count[j0 * width + i1] -= 1;
            count[j1 * width + i0] -= 1;
            count[j1 * width + i1] += 1;
        }
        for j in 0..=rows {
            for i in 0..=cols {
                let left = if i > 0 { count[j * width + i - 1] } else { 0 };
                let below = if j > 0 { count[(j - 1) * width + i] } else { 0 };
                let diagonal = if i > 0 && j > 0 {
                    count[(j - 1) * width + i - 1]
                } else {
                    0
                };
                count[j * width + i] += left + below - diagonal;
            }
        }
        let covered = |i: usize, j: usize| i < cols && j < rows && count[j * width + i] > 0;
        let (fx, fy): (Vec<f64>, Vec<f64>) = (
            xs.iter().map(|v| v.to_f64()).collect(),
            ys.iter().map(|v| v.to_f64()).collect(),
        );
        let mut rects = Vec::new();
        for j in 0..rows {
            for (a, b) in runs(cols, |i| covered(i, j)) {
                rects.push([fx[a], fx[b], fy[j], fy[j + 1]]);
            }
        }
        let mut outline = Vec::new();
        // A side of a cell is on the boundary when exactly one of its two cells is covered.
        for (j, &y) in fy.iter().enumerate() {
            let differs = |i: usize| covered(i, j) != (j > 0 && covered(i, j - 1));
            for (a, b) in runs(cols, differs) {
                outline.push([(fx[a], y), (fx[b], y)]);
            }
        }
        for (i, &x) in fx.iter().enumerate() {
            let differs = |j: usize| covered(i, j) != (i > 0 && covered(i - 1, j));
            for (a, b) in runs(rows, differs) {
                outline.push([(x, fy[a]), (x, fy[b])]);
            }
        }
        Swept { rects, outline }
    }
}

/// The distinct x and the distinct y coordinates of the boxes' sides, each sorted.
fn lines(boxes: &[Rect]) -> (Vec<Rational>, Vec<Rational>) {
    let mut xs: Vec<Rational> = boxes.iter().flat_map(|r| [r.x0, r.x1]).collect();
    let mut ys: Vec<Rational> = boxes.iter().flat_map(|r| [r.y0, r.y1]).collect();
    for v in [&mut xs, &mut ys] {
        v.sort_unstable();
        v.dedup();
    }
    (xs, ys)
}

/// The maximal runs `a..b` of indices in `0..n` where `inside` holds.
fn runs(n: usize, inside: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for i in 0..=n {
        match (start, i < n && inside(i)) {
            (None, true) => start = Some(i),
            (Some(a), false) => {
                out.push((a, i));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// What the legend can show.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Key {
    Polygon,
    Swept,
    Contour,
    Tour,
    Turn,
    Witness,
}

impl Key {
    fn label(self) -> &'static str {
        match self {
            Key::Polygon => "polygon",
            Key::Swept => "swept area",
            Key::Contour => "δB (contour of the centres)",
            Key::Tour => "tour",
            Key::Turn => "turn (dot), U-turn (ring)",
            Key::Witness => "checker's witness",
        }
    }
}

/// The figure, in the polygon's coordinates until [`Figure::at`] maps them to the canvas.
struct Figure {
    /// `[min_x, min_y, max_x, max_y]` of everything drawn.
    bounds: [f64; 4],
    /// Output pixels per unit.
    pixel_size: f64,
    left: f64,
    top: f64,
    width: u32,
    height: u32,
    outer: Vec<Vec<Xy>>,
    holes: Vec<Vec<Xy>>,
    swept: Option<Swept>,
    contour: Vec<Vec<Xy>>,
    walks: Vec<WalkShape>,
    witnesses: Vec<Xy>,
    legend: Vec<Key>,
    mark_turns: bool,
    title: Option<String>,
    caption: Option<String>,
}

impl Figure {
    fn new(
        polygon: &Polygon,
        tour: Option<&Tour>,
        erosion: Option<&Erosion>,
        opts: &DrawOptions,
    ) -> Result<Figure> {
        let report = tour.map(|t| check(polygon, t)).transpose()?;
        let ring = |corners: &[Point]| corners.iter().map(|&p| xy(p)).collect::<Vec<Xy>>();
        let (holes, outer): (Vec<_>, Vec<_>) = polygon.rings().iter().partition(|r| r.hole);
        let outer: Vec<Vec<Xy>> = outer.iter().map(|r| ring(&r.corners)).collect();
        let holes: Vec<Vec<Xy>> = holes.iter().map(|r| ring(&r.corners)).collect();
        let contour: Vec<Vec<Xy>> =
            erosion.map_or_else(Vec::new, |b| b.contour().iter().map(|w| ring(w)).collect());
        let walks: Vec<WalkShape> = tour.map_or_else(Vec::new, |t| {
            t.cycles.iter().map(|w| walk_shape(w)).collect()
        });
        let witnesses: Vec<Xy> = report
            .iter()
            .flat_map(|r| [r.uncovered, r.outside])
            .flatten()
            .map(xy)
            .collect();
        let swept = tour.map(Swept::of);

        let mut bounds = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        let mut grow = |(x, y): Xy, r: f64| {
            bounds = [
                bounds[0].min(x - r),
                bounds[1].min(y - r),
                bounds[2].max(x + r),
                bounds[3].max(y + r),
            ];
        };
        for &p in outer.iter().flatten().chain(&witnesses) {
            grow(p, 0.0);
        }
        // The cutter reaches ½ beyond its centre.
        for w in &walks {
            for &p in &w.line {
                grow(p, 0.5);
            }
        }
        let (w, h) = (bounds[2] - bounds[0], bounds[3] - bounds[1]);
        let pixel_size = match opts.pixel_size {
            Some(0) => return Err(Error::invalid("pixel size must be at least 1")),
            Some(s) => f64::from(s),
            None => {
                let s = (AUTO_SIDE_PX / w.max(h).max(f64::MIN_POSITIVE)).min(MAX_AUTO_PIXEL_SIZE);
                if s >= 1.0 { s.floor() } else { s }
            }
        };

        let mut legend = vec![Key::Polygon];
        if tour.is_some() {
            legend.push(Key::Swept);
        }
        if !contour.is_empty() {
            legend.push(Key::Contour);
        }
        if tour.is_some() {
            legend.push(Key::Tour);
        }
        let mark_turns = opts.mark_turns;
        if mark_turns
            && walks
                .iter()
                .any(|w| !w.turns.is_empty() || !w.u_turns.is_empty())
        {
            legend.push(Key::Turn);
        }
        if !witnesses.is_empty() {
            legend.push(Key::Witness);
        }
        let caption = opts
            .caption
            .clone()
            .or_else(|| report.as_ref().map(figure_caption));

        ensure_fonts();
        let (grid_w, grid_h) = (w * pixel_size, h * pixel_size);
        let c = canvas(
            (grid_w, grid_h),
            opts.title.as_deref(),
            caption.as_deref(),
            (legend_width(&legend), LEGEND_PX * 2.2),
        )?;
        Ok(Figure {
            bounds,
            pixel_size,
            left: c.left,
            top: c.top,
            width: c.width,
            height: c.height,
            outer,
            holes,
            swept,
            contour,
            walks,
            witnesses,
            legend,
            mark_turns,
            title: opts.title.clone(),
            caption,
        })
    }

    /// Canvas position of the point (x, y), on a canvas `k` times the figure's size.
    fn at(&self, (x, y): Xy, k: f64) -> (i32, i32) {
        let px = self.left + (x - self.bounds[0]) * self.pixel_size;
        let py = self.top + (self.bounds[3] - y) * self.pixel_size;
        ((px * k).round() as i32, (py * k).round() as i32)
    }
}

/// The legend's width in output pixels: each entry a swatch, a gap, its label and a space.
fn legend_width(keys: &[Key]) -> f64 {
    keys.iter()
        .map(|k| SWATCH_PX + 6.0 + text_width(Some(k.label()), LEGEND_PX) + 18.0)
        .sum()
}

impl Picture for Figure {
    fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    fn render<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: f64,
        strokes: Strokes,
    ) -> DrawResult<DB> {
        let ps = self.pixel_size;
        let at = |p: Xy| self.at(p, k);
        let width = |w: f64| ((w * k).round() as u32).max(1);
        let line_px = (0.05 * ps).clamp(1.5, 3.0);

        area.fill(&WHITE)?;
        let fill = |ring: &[Xy], colour: RGBColor| {
            area.draw(&plotters::element::Polygon::new(
                ring.iter().map(|&p| at(p)).collect::<Vec<_>>(),
                colour.filled(),
            ))
        };
        for ring in &self.outer {
            fill(ring, REGION_FILL)?;
        }
        for ring in &self.holes {
            fill(ring, WHITE)?;
        }
        if let Some(swept) = &self.swept {
            let style = SWEPT.mix(SWEPT_OPACITY).filled();
            for &[x0, x1, y0, y1] in &swept.rects {
                area.draw(&Rectangle::new([at((x0, y1)), at((x1, y0))], style))?;
            }
            for &[a, b] in &swept.outline {
                stroke_segment(area, strokes, (at(a), at(b)), SWEPT, width(1.5))?;
            }
        }
        // Over the swept area's outline: where they agree (a valid tour), the polygon's shows.
        for ring in self.outer.iter().chain(&self.holes) {
            let corners = ring.iter().map(|&p| at(p));
            stroke_closed(area, strokes, corners, OUTLINE, width(2.0))?;
        }
        for (i, walk) in self.walks.iter().enumerate() {
            let colour = WALK_COLOURS[i % WALK_COLOURS.len()];
            let corners = walk.line.iter().map(|&p| at(p));
            stroke_closed(area, strokes, corners, colour, width(line_px))?;
            if let Some(p) = walk.single {
                let r = width((0.22 * ps).max(3.0));
                area.draw(&Circle::new(at(p), r, colour.stroke_width(width(line_px))))?;
            }
        }
        // Over the tour, which often runs along δB (Corollary 4 walks it).
        let (dash, gap) = ((6.0 * k) as i32, (4.0 * k) as i32);
        for walk in &self.contour {
            let mut path: Vec<(i32, i32)> = walk.iter().map(|&p| at(p)).collect();
            path.extend(path.first().copied());
            let style = CONTOUR.stroke_width(width(1.5));
            if path.len() == 2 {
                area.draw(&Circle::new(path[0], width(3.0), CONTOUR.filled()))?;
            } else {
                area.draw(&DashedPathElement::new(path, dash, gap, style))?;
            }
        }
        if self.mark_turns {
            let ring = width((0.12 * ps).clamp(4.0, 12.0));
            let dot = width((0.07 * ps).clamp(2.5, 5.0));
            for (i, walk) in self.walks.iter().enumerate() {
                let colour = WALK_COLOURS[i % WALK_COLOURS.len()];
                for &p in &walk.u_turns {
                    area.draw(&Circle::new(at(p), ring, colour.stroke_width(width(1.5))))?;
                }
                for &p in &walk.turns {
                    area.draw(&Circle::new(at(p), dot, colour.filled()))?;
                }
            }
        }
        for &p in &self.witnesses {
            witness_mark(area, at(p), k)?;
        }

        let font =
            |size: f64| FontDesc::new(FontFamily::from(FONT_FAMILY), size * k, FontStyle::Normal);
        let centre_x = (f64::from(self.width) / 2.0 * k).round() as i32;
        if let Some(title) = &self.title {
            let style = font(TITLE_PX)
                .color(&TITLE_COLOUR)
                .pos(Pos::new(HPos::Center, VPos::Top));
            let y = (MARGIN_PX * k).round() as i32;
            area.draw(&Text::new(title.as_str(), (centre_x, y), style))?;
        }
        let caption_band = if self.caption.is_some() {
            CAPTION_PX * 1.6
        } else {
            0.0
        };
        let legend_y = f64::from(self.height) - MARGIN_PX - caption_band - LEGEND_PX * 1.1;
        let mut x = (f64::from(self.width) - legend_width(&self.legend)) / 2.0;
        let px = |v: f64| (v * k).round() as i32;
        for &key in &self.legend {
            let (x0, x1, y) = (px(x), px(x + SWATCH_PX), px(legend_y));
            let half = px(LEGEND_PX * 0.4);
            match key {
                Key::Polygon => {
                    let corners = [(x0, y - half), (x1, y + half)];
                    area.draw(&Rectangle::new(corners, REGION_FILL.filled()))?;
                    area.draw(&Rectangle::new(corners, OUTLINE.stroke_width(width(1.5))))?;
                }
                Key::Swept => {
                    let corners = [(x0, y - half), (x1, y + half)];
                    let style = SWEPT.mix(SWEPT_OPACITY).filled();
                    area.draw(&Rectangle::new(corners, style))?;
                    area.draw(&Rectangle::new(corners, SWEPT.stroke_width(width(1.0))))?;
                }
                Key::Contour => {
                    let style = CONTOUR.stroke_width(width(1.5));
                    let (dash, gap) = ((5.0 * k) as i32, (3.0 * k) as i32);
                    let path = vec![(x0, y), (x1, y)];
                    area.draw(&DashedPathElement::new(path, dash, gap, style))?;
                }
                Key::Tour => {
                    let style = WALK_COLOURS[0].stroke_width(width(line_px));
                    area.draw(&PathElement::new(vec![(x0, y), (x1, y)], style))?;
                }
                Key::Turn => {
                    let colour = WALK_COLOURS[0];
                    let r = px(4.0);
                    area.draw(&Circle::new((x0 + r, y), width(3.0), colour.filled()))?;
                    let ring = colour.stroke_width(width(1.5));
                    area.draw(&Circle::new((x1 - r, y), width(5.0), ring))?;
                }
                Key::Witness => witness_mark(area, ((x0 + x1) / 2, y), k)?,
            }
            let style = font(LEGEND_PX)
                .color(&CAPTION_COLOUR)
                .pos(Pos::new(HPos::Left, VPos::Center));
            area.draw(&Text::new(key.label(), (px(x + SWATCH_PX + 6.0), y), style))?;
            x += SWATCH_PX + 6.0 + text_width(Some(key.label()), LEGEND_PX) + 18.0;
        }
        if let Some(caption) = &self.caption {
            let style = font(CAPTION_PX)
                .color(&CAPTION_COLOUR)
                .pos(Pos::new(HPos::Center, VPos::Bottom));
            let y = ((f64::from(self.height) - MARGIN_PX) * k).round() as i32;
            area.draw(&Text::new(caption.as_str(), (centre_x, y), style))?;
        }
        area.present()
    }
}

/// A red cross in a red ring at canvas point `c`.
fn witness_mark<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (cx, cy): (i32, i32),
    k: f64,
) -> DrawResult<DB> {
    let r = (7.0 * k).round() as i32;
    let style = WITNESS.stroke_width(((2.0 * k).round() as u32).max(1));
    area.draw(&Circle::new((cx, cy), r as u32, style))?;
    let d = r * 2 / 3;
    area.draw(&PathElement::new(
        vec![(cx - d, cy - d), (cx + d, cy + d)],
        style,
    ))?;
    area.draw(&PathElement::new(
        vec![(cx - d, cy + d), (cx + d, cy - d)],
        style,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon(text: &str) -> Polygon {
        Polygon::parse(text, "p.wkt").unwrap()
    }

    fn tour(points: &[(&str, &str)]) -> Tour {
        let q = |s: &str| Rational::parse_coordinate(s).unwrap();
        Tour::new(
            points
                .iter()
                .map(|&(x, y)| Point::new(q(x), q(y)))
                .collect(),
        )
    }

    #[test]
    fn the_union_of_overlapping_boxes_is_disjoint_with_its_outline() {
        // Two passes of a 4 × 1.5 sliver: boxes [0, 4] × [0, 1] and [0, 4] × [0.5, 1.5], and
        // the two vertical moves' boxes [3, 4] × [0, 1.5] and [0, 1] × [0, 1.5].
        let t = tour(&[("0.5", "0.5"), ("3.5", "0.5"), ("3.5", "1"), ("0.5", "1")]);
        let swept = Swept::of(&t);
        let area: f64 = swept
            .rects
            .iter()
            .map(|r| (r[1] - r[0]) * (r[3] - r[2]))
            .sum();
        assert_eq!(area, 6.0);
        // The outline of the 4 × 1.5 rectangle: its four sides, each merged into one segment.
        let length: f64 = swept
            .outline
            .iter()
            .map(|[a, b]| (b.0 - a.0).abs() + (b.1 - a.1).abs())
            .sum();
        assert_eq!((swept.outline.len(), length), (4, 11.0));
    }

    #[test]
    fn turns_and_u_turns_are_found_with_repeats_dropped() {
        let t = tour(&[("0.5", "0.5"), ("2", "0.5"), ("2", "0.5"), ("2", "1")]);
        let shape = walk_shape(&t.cycles[0]);
        assert_eq!(shape.line.len(), 3);
        // At (2, 0.5) a 90° turn; at (2, 1) and (0.5, 0.5) the closing diagonal: no marks.
        assert_eq!(shape.turns, vec![(2.0, 0.5)]);
        let back = walk_shape(&tour(&[("0.5", "0.5"), ("2.75", "0.5")]).cycles[0]);
        assert_eq!(back.u_turns.len(), 2);
        let one = walk_shape(&tour(&[("0.5", "0.5"), ("0.5", "0.5")]).cycles[0]);
        assert_eq!(one.single, Some((0.5, 0.5)));
    }

    #[test]
    fn the_frame_holds_the_polygon_and_the_cutter_beyond_it() {
        // A pass at height 1.25 of a 3 × 1.5 rectangle sweeps up to 1.75, outside it.
        let p = polygon("POLYGON ((0 0, 3 0, 3 1.5, 0 1.5, 0 0))");
        let t = tour(&[("0.5", "1.25"), ("2.5", "1.25")]);
        let f = Figure::new(&p, Some(&t), None, &DrawOptions::default()).unwrap();
        assert_eq!(f.bounds, [0.0, 0.0, 3.0, 1.75]);
        assert_eq!(f.pixel_size, MAX_AUTO_PIXEL_SIZE);
        assert_eq!(f.witnesses.len(), 2, "unmilled below, swept outside above");
        assert!(f.legend.contains(&Key::Witness) && !f.legend.contains(&Key::Contour));
    }

    #[test]
    fn the_caption_is_the_checkers() {
        let p = polygon("POLYGON ((0 0, 3 0, 3 1.5, 0 1.5, 0 0))");
        let t = tour(&[("0.5", "0.5"), ("2.5", "0.5"), ("2.5", "1"), ("0.5", "1")]);
        let r = check(&p, &t).unwrap();
        assert_eq!(figure_caption(&r), "length 5, turns 4, 1 cycle(s), valid");
        let low = tour(&[("0.5", "0.5"), ("2.5", "0.5")]);
        let r = check(&p, &low).unwrap();
        assert!(
            figure_caption(&r)
                .ends_with("INVALID: the point (1.5, 1.25) of the polygon is not milled"),
            "{}",
            figure_caption(&r)
        );
    }
}
