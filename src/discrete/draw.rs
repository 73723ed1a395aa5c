//! Pictures of a discrete instance and closed walks over it, as SVG or PNG (the discrete
//! milling figures), in the conventions of [`crate::draw`]: title above, caption below, the same
//! palette, fills and marks, SVG or PNG by the extension of the output file.
//!
//! - **Cells.** When the coordinates are those of a lattice, each vertex is drawn as its cell:
//!   hexagons for hexagonal cells (d = 3, unit edges at multiples of 60°), squares for grid
//!   regions and voxel layers (unit edges along the axes), with the region's boundary as a dark
//!   outline. Any other instance (honeycomb vertices, plane graphs) is drawn as its graph: edges
//!   as thin grey lines and vertices as small dots.
//! - **Layers.** An instance whose vertices lie on more than one z is drawn as one panel per
//!   z-layer, side by side and labelled `z = …`. A walk's moves within a layer are polylines;
//!   a move between layers ends the polyline at the cell with a triangle pointing to the layer it
//!   goes to (▲ up, in the upper right of the cell; ▼ down, in the lower left).
//! - **Walks.** Each closed walk is a polyline through vertex positions in its own colour. An
//!   edge walked more than once is drawn as parallel strands offset sideways, so every
//!   traversal can be counted. A pass that costs a turn (`Discrete::turn` = 1, a change of
//!   channel) is a dot, a U-turn (2) a ring, and a single-vertex walk a circle.
//!
//! Instances more than [`DETAIL_LIMIT`] edge lengths across are drawn plainly: no strands, no
//! marks, no cell borders.

use crate::discrete::check;
use crate::discrete::{Discrete, VertexWalk};
use crate::draw::{
    AUTO_SIDE_PX, CAPTION_COLOUR, DETAIL_LIMIT, DrawOptions, DrawResult, FONT_FAMILY, Format,
    GRID_LINE, JOG, MAX_AUTO_PIXEL_SIZE, OUTLINE, PALETTE, Picture, REGION_FILL, STRAND_GAP,
    STRAND_SPREAD, Strokes, canvas, draw_title_and_caption, ensure_fonts, write_picture,
};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontDesc, FontFamily, FontStyle};
use std::collections::HashMap;
use std::path::Path;

/// The caption of a picture: `n`, and with walks the checker's length, turns and cycles, and
/// `(not a valid cover)` when the checker refuses them.
pub fn caption(inst: &Discrete, walks: Option<&[VertexWalk]>) -> String {
    let mut text = format!("n = {}", inst.len());
    if let Some(walks) = walks {
        let r = check::check(inst, walks);
        text += &format!(
            ", length {}, turns {}, {} cycle(s)",
            r.length, r.turns, r.cycles
        );
        if !r.valid {
            text += " (not a valid cover)";
        }
    }
    text
}

/// Draws `inst`, and `walks` over it when given, to `out`: an SVG or a PNG file, chosen by the
/// extension of `out`.
///
/// # Arguments
///
/// * `inst` — the instance; it must have coordinates.
/// * `walks` — closed walks (vertex indices) to draw, each in its own colour. They are drawn
///   as given: a step between non-adjacent vertices is a straight line (check them with
///   [`check::check`]; [`caption`] does).
/// * `out` — the file to write; its extension (`svg` or `png`, any case) picks the format.
/// * `opts` — title, caption, scale (`pixel_size`: output pixels per edge length) and what to
///   show (`show_grid`: cell borders; `mark_turns`: turn dots and U-turn rings).
///
/// # Returns
///
/// `Error::Invalid` for an unknown extension, an instance without coordinates or vertices, a
/// walk naming a vertex outside the instance, or a picture too large; `Error::Io` when the
/// file cannot be written.
///
/// # Complexity
///
/// O((n + m) log n + L) time for n vertices, m edges and total walk length L, plus the cost
/// of filling the image.
///
/// # Examples
///
/// ```no_run
/// use mowmill::discrete::draw::{caption, draw};
/// use mowmill::discrete::lattice::HexRegion;
/// use mowmill::draw::DrawOptions;
///
/// let inst = HexRegion::from_cells([[0, 0], [1, 0], [0, 1]])?.to_discrete();
/// let walks = vec![vec![0, 1, 2]];
/// let opts = DrawOptions {
///     title: Some("three cells".into()),
///     caption: Some(caption(&inst, Some(&walks))),
///     ..DrawOptions::default()
/// };
/// draw(&inst, Some(&walks), std::path::Path::new("three.svg"), &opts)?;
/// # Ok::<(), mowmill::Error>(())
/// ```
pub fn draw(
    inst: &Discrete,
    walks: Option<&[Vec<u32>]>,
    out: &Path,
    opts: &DrawOptions,
) -> Result<()> {
    let format = Format::of(out)?;
    let walks = walks.unwrap_or(&[]);
    let geometry = Geometry::of(inst)?;
    for (w, walk) in walks.iter().enumerate() {
        if let Some(&v) = walk.iter().find(|&&v| v as usize >= inst.len()) {
            return Err(Error::invalid(format!(
                "cannot draw walk {w}: vertex {v} is not one of the instance's {} vertices",
                inst.len()
            )));
        }
    }
    let detailed = geometry.span() <= DETAIL_LIMIT as f64;
    ensure_fonts();
    let layout = Layout::new(&geometry, opts)?;
    let scene = Scene {
        cells: cell_shapes(inst, &geometry, detailed && opts.show_grid),
        walks: walk_shapes(inst, &geometry, walks, detailed),
        geometry,
        layout,
        detailed,
        mark_turns: opts.mark_turns,
        title: opts.title.as_deref(),
        caption: opts.caption.as_deref(),
    };
    write_picture(&scene, format, out)
}

// ---------------------------------------------------------------------------------------------
// Geometry, in the instance's coordinates.
// ---------------------------------------------------------------------------------------------

/// How vertices are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cells {
    /// Squares of side `unit` (grid regions, voxel layers).
    Squares,
    /// Pointy-top hexagons, neighbours `unit` apart (hexagonal cells).
    Hexagons,
    /// The graph: dots and grey edges.
    Dots,
}

impl Cells {
    /// The number of sides of a cell.
    fn sides(self) -> usize {
        match self {
            Cells::Squares => 4,
            Cells::Hexagons => 6,
            Cells::Dots => 0,
        }
    }
}

/// Where every vertex is drawn: its panel (z-layer) and its point in the plane.
struct Geometry {
    points: Vec<[f64; 3]>,
    /// The distinct z values, ascending: one panel each.
    layers: Vec<f64>,
    layer_of: Vec<usize>,
    /// The median edge length (1 without edges): offsets and marks are measured in it.
    unit: f64,
    cells: Cells,
    /// The bounding box of the points in the plane, `[min_x, min_y, max_x, max_y]`.
    bbox: [f64; 4],
}

/// Relative tolerance when recognising lattice coordinates.
const LATTICE_EPS: f64 = 1e-6;

impl Geometry {
    fn of(inst: &Discrete) -> Result<Geometry> {
        if inst.is_empty() {
            return Err(Error::invalid(
                "nothing to draw: the instance has no vertices",
            ));
        }
        let points: Vec<[f64; 3]> = (0..inst.len() as u32)
            .map(|v| inst.coords(v))
            .collect::<Option<_>>()
            .ok_or_else(|| Error::invalid("this instance has no coordinates to draw"))?;
        if let Some(v) = points.iter().position(|p| p.iter().any(|c| !c.is_finite())) {
            return Err(Error::invalid(format!(
                "cannot draw vertex {v}: its coordinates are not finite"
            )));
        }
        let mut layers: Vec<f64> = points.iter().map(|p| p[2]).collect();
        layers.sort_by(f64::total_cmp);
        layers.dedup();
        let layer_of = points
            .iter()
            .map(|p| layers.partition_point(|&z| z < p[2]))
            .collect();
        let mut lengths: Vec<f64> = inst
            .edges()
            .map(|(a, b)| distance(points[a as usize], points[b as usize]))
            .filter(|&l| l > 0.0)
            .collect();
        lengths.sort_by(f64::total_cmp);
        let unit = lengths.get(lengths.len() / 2).copied().unwrap_or(1.0);
        let mut bbox = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in &points {
            bbox = [
                bbox[0].min(p[0]),
                bbox[1].min(p[1]),
                bbox[2].max(p[0]),
                bbox[3].max(p[1]),
            ];
        }
        let mut geometry = Geometry {
            points,
            layers,
            layer_of,
            unit,
            cells: Cells::Dots,
            bbox,
        };
        geometry.cells = geometry.recognise_cells(inst);
        Ok(geometry)
    }

    /// Hexagons when the instance is planar with d = 3 and every edge is a unit step at a
    /// multiple of 60°; squares when every edge is a unit step along an axis; dots otherwise.
    fn recognise_cells(&self, inst: &Discrete) -> Cells {
        if inst.edge_count() == 0 {
            return Cells::Dots;
        }
        let unit_step = |a: u32, b: u32, sides: usize| {
            let (p, q) = (self.points[a as usize], self.points[b as usize]);
            let (dx, dy, dz) = (q[0] - p[0], q[1] - p[1], q[2] - p[2]);
            let near = |x: f64, y: f64| (x - y).abs() <= LATTICE_EPS * self.unit;
            if dz != 0.0 {
                // Between layers: straight up or down, one unit (voxels).
                return sides == 4 && near(dx, 0.0) && near(dy, 0.0) && near(dz.abs(), self.unit);
            }
            if !near(dx.hypot(dy), self.unit) {
                return false;
            }
            let step = 360.0 / sides as f64;
            let angle = dy.atan2(dx).to_degrees();
            let k = (angle / step).round();
            (angle - k * step).abs() < 1e-4
        };
        let all = |sides| inst.edges().all(|(a, b)| unit_step(a, b, sides));
        if self.layers.len() == 1 && inst.directions() == Some(3) && all(6) {
            Cells::Hexagons
        } else if all(4) {
            Cells::Squares
        } else {
            Cells::Dots
        }
    }

    /// The larger side of the bounding box, in edge lengths.
    fn span(&self) -> f64 {
        (self.bbox[2] - self.bbox[0]).max(self.bbox[3] - self.bbox[1]) / self.unit
    }

    /// Room around the points inside a panel, for the cells and the strands.
    fn pad(&self) -> f64 {
        0.65 * self.unit
    }

    /// A panel's width and height, in coordinates.
    fn panel_size(&self) -> (f64, f64) {
        let pad = self.pad();
        (
            self.bbox[2] - self.bbox[0] + 2.0 * pad,
            self.bbox[3] - self.bbox[1] + 2.0 * pad,
        )
    }

    fn plane(&self, v: u32) -> (f64, f64) {
        let p = self.points[v as usize];
        (p[0], p[1])
    }

    fn panel(&self, v: u32) -> usize {
        self.layer_of[v as usize]
    }
}

fn distance(p: [f64; 3], q: [f64; 3]) -> f64 {
    ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2) + (q[2] - p[2]).powi(2)).sqrt()
}

type Point = (f64, f64);

fn add(a: Point, b: Point) -> Point {
    (a.0 + b.0, a.1 + b.1)
}

fn scale(a: Point, k: f64) -> Point {
    (a.0 * k, a.1 * k)
}

fn cross(a: Point, b: Point) -> f64 {
    a.0 * b.1 - a.1 * b.0
}

/// The cells of one panel, ready to draw, in coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
struct PanelCells {
    /// Cell polygons (empty for dots).
    polygons: Vec<Vec<Point>>,
    /// Sides of cells with no neighbour across them: the region's outline.
    outline: Vec<[Point; 2]>,
    /// Edges within the panel (dots only).
    edges: Vec<[Point; 2]>,
    /// Vertex positions (dots only).
    dots: Vec<Point>,
    /// Whether to stroke the borders between cells.
    borders: bool,
}

/// The cells, outline and (for dots) edges of every panel.
fn cell_shapes(inst: &Discrete, g: &Geometry, borders: bool) -> Vec<PanelCells> {
    let mut panels = vec![
        PanelCells {
            borders,
            ..PanelCells::default()
        };
        g.layers.len()
    ];
    let sides = g.cells.sides();
    for v in 0..inst.len() as u32 {
        let panel = &mut panels[g.panel(v)];
        let centre = g.plane(v);
        if g.cells == Cells::Dots {
            panel.dots.push(centre);
            for &w in inst.neighbors(v) {
                if v < w && g.panel(w) == g.panel(v) {
                    panel.edges.push([centre, g.plane(w)]);
                }
            }
            continue;
        }
        // A regular polygon whose sides face the neighbours: side k faces angle k·360°/sides.
        let step = std::f64::consts::TAU / sides as f64;
        let radius = g.unit / (2.0 * (step / 2.0).cos());
        let corner = |k: f64| {
            let a = (k - 0.5) * step;
            add(centre, (radius * a.cos(), radius * a.sin()))
        };
        panel
            .polygons
            .push((0..sides).map(|k| corner(k as f64)).collect());
        let mut faced = vec![false; sides];
        for &w in inst.neighbors(v) {
            if g.panel(w) == g.panel(v) {
                let (x, y) = g.plane(w);
                let a = (y - centre.1).atan2(x - centre.0);
                faced[(a / step).round().rem_euclid(sides as f64) as usize] = true;
            }
        }
        for k in (0..sides).filter(|&k| !faced[k]) {
            panel
                .outline
                .push([corner(k as f64), corner(k as f64 + 1.0)]);
        }
    }
    panels
}

/// How far from the centre of its cell a move between layers starts, along each axis, in edge
/// lengths (up to the upper right, down to the lower left).
const VERTICAL_SHIFT: f64 = 0.18;
/// Straight (or nearly): the sine of the angle between two moves is below this.
const STRAIGHT_SINE: f64 = 0.26;

/// How often an edge is walked from its lower-numbered end and from its higher.
#[derive(Clone, Copy, Debug, Default)]
struct Traffic {
    along: u32,
    against: u32,
}

/// The rightward offset (in edge lengths, seen heading from the lower-numbered end) of visit
/// `visit` of an edge with `traffic`, as [`crate::draw`] spreads its strands: traversals keep
/// to their right, earlier visits outermost, so going along a corridor and back makes a
/// hairpin with no crossing.
fn strand_offset(traffic: Traffic, canonical: bool, visit: u32) -> f64 {
    let m = traffic.along + traffic.against;
    if m <= 1 {
        return 0.0;
    }
    let gap = STRAND_GAP.min(STRAND_SPREAD / f64::from(m - 1));
    let lane = if canonical { m - 1 - visit } else { visit };
    (f64::from(lane) - f64::from(m - 1) / 2.0) * gap
}

/// Which way a move between layers goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Vertical {
    Up,
    Down,
}

/// One closed walk, ready to draw, in coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
struct WalkShape {
    /// Polylines `(panel, corners, closed)`: the whole walk when it stays in one layer, else
    /// its runs within a layer.
    lines: Vec<(usize, Vec<Point>, bool)>,
    /// Passes that cost one turn.
    turns: Vec<(usize, Point)>,
    /// U-turns (the middle of the hairpin).
    u_turns: Vec<(usize, Point)>,
    /// Ends of moves between layers, and where they go.
    verticals: Vec<(usize, Point, Vertical)>,
    /// A single-vertex walk.
    single: Option<(usize, Point)>,
}

/// One step of a walk, from `from` to `to`, as drawn.
#[derive(Clone, Copy, Debug)]
struct Step {
    from: u32,
    to: u32,
    /// Unit direction in the plane (within a layer).
    dir: Point,
    /// Sideways offset of this traversal.
    offset: Point,
    /// Between layers.
    vertical: bool,
}

impl Step {
    /// Where a move between layers leaves or enters `v` (one of its ends).
    fn vertical_end(&self, g: &Geometry, v: u32) -> (Point, Vertical) {
        let other = if v == self.from { self.to } else { self.from };
        let way = if g.points[other as usize][2] > g.points[v as usize][2] {
            Vertical::Up
        } else {
            Vertical::Down
        };
        let s = VERTICAL_SHIFT * g.unit * if way == Vertical::Up { 1.0 } else { -1.0 };
        (add(add(g.plane(v), (s, s)), self.offset), way)
    }
}

/// The steps `(from, to)` of a closed walk (none for a single vertex).
fn closed_steps(walk: &[u32]) -> impl Iterator<Item = (u32, u32)> + '_ {
    let n = if walk.len() >= 2 { walk.len() } else { 0 };
    (0..n).map(move |i| (walk[i], walk[(i + 1) % n]))
}

/// Polylines and marks of every walk. With `detailed`, repeated traversals of an edge are
/// spread into parallel strands and turns are marked.
fn walk_shapes(
    inst: &Discrete,
    g: &Geometry,
    walks: &[Vec<u32>],
    detailed: bool,
) -> Vec<WalkShape> {
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut traffic: HashMap<(u32, u32), Traffic> = HashMap::new();
    for walk in walks {
        for (a, b) in closed_steps(walk) {
            let t = traffic.entry(key(a, b)).or_default();
            if a < b {
                t.along += 1;
            } else {
                t.against += 1;
            }
        }
    }
    let mut seen: HashMap<(u32, u32), Traffic> = HashMap::new();
    let mut shapes = Vec::with_capacity(walks.len());
    for walk in walks {
        let mut shape = WalkShape::default();
        if walk.len() == 1 {
            shape.single = Some((g.panel(walk[0]), g.plane(walk[0])));
        }
        let steps: Vec<Step> = closed_steps(walk)
            .map(|(a, b)| {
                let (p, q) = (g.plane(a), g.plane(b));
                let (dx, dy) = (q.0 - p.0, q.1 - p.1);
                let len = dx.hypot(dy);
                let dir = if len > 0.0 {
                    (dx / len, dy / len)
                } else {
                    (1.0, 0.0)
                };
                let vertical = g.panel(a) != g.panel(b);
                let canonical = a < b;
                let visits = seen.entry(key(a, b)).or_default();
                let count = if canonical {
                    &mut visits.along
                } else {
                    &mut visits.against
                };
                *count += 1;
                let right = if detailed {
                    strand_offset(traffic[&key(a, b)], canonical, *count - 1) * g.unit
                } else {
                    0.0
                };
                // Right of the lower-numbered end's heading; between layers, along a diagonal.
                let normal = if vertical {
                    (
                        std::f64::consts::FRAC_1_SQRT_2,
                        -std::f64::consts::FRAC_1_SQRT_2,
                    )
                } else {
                    let c = if canonical { dir } else { scale(dir, -1.0) };
                    (c.1, -c.0)
                };
                Step {
                    from: a,
                    to: b,
                    dir,
                    offset: scale(normal, right),
                    vertical,
                }
            })
            .collect();
        let n = steps.len();
        if n == 0 {
            shapes.push(shape);
            continue;
        }
        // The corners at every pass, in the order walked; `breaks[j]`: the walk leaves the
        // layer after pass j.
        let mut corners: Vec<Vec<Point>> = Vec::with_capacity(n);
        for j in 0..n {
            let (a, b) = (&steps[(j + n - 1) % n], &steps[j]);
            let v = a.to;
            let panel = g.panel(v);
            let centre = g.plane(v);
            let mut pts = Vec::with_capacity(2);
            if a.vertical {
                let (p, way) = a.vertical_end(g, v);
                shape.verticals.push((panel, p, way));
                pts.push(p);
                if !b.vertical {
                    pts.push(add(centre, b.offset));
                }
            }
            if b.vertical {
                if !a.vertical {
                    pts.push(add(centre, a.offset));
                }
                let (p, way) = b.vertical_end(g, v);
                shape.verticals.push((panel, p, way));
                pts.push(p);
            }
            let turn = inst.turn(a.from, v, b.to);
            if !a.vertical && !b.vertical {
                let (pa, pb) = (add(centre, a.offset), add(centre, b.offset));
                let sine = cross(a.dir, b.dir);
                // Where the two offset lines meet: pa + t·a.dir = pb + s·b.dir.
                let t = cross((pb.0 - pa.0, pb.1 - pa.1), b.dir) / sine;
                if turn == 2 || sine.abs() < STRAIGHT_SINE || t.abs() > g.unit {
                    if pa == pb {
                        pts.push(pa);
                    } else if turn == 2 || a.dir.0 * b.dir.0 + a.dir.1 * b.dir.1 < 0.0 {
                        pts.extend([pa, pb]);
                    } else {
                        // Straight on, changing strand: a short slanted jog.
                        let jog = JOG * g.unit;
                        pts.push(add(pa, scale(a.dir, -jog)));
                        pts.push(add(pb, scale(b.dir, jog)));
                    }
                } else {
                    pts.push(add(pa, scale(a.dir, t)));
                }
            }
            // On the run within the layer where there is one; else between its two ends.
            let mark = match (a.vertical, b.vertical) {
                (true, false) => pts[1],
                (false, true) => pts[0],
                // Back to the layer it came from: the ring in the middle of the cell, clear of
                // the two triangles.
                (true, true) if turn == 2 => centre,
                _ => {
                    let (p, q) = (pts[0], pts[pts.len() - 1]);
                    ((p.0 + q.0) / 2.0, (p.1 + q.1) / 2.0)
                }
            };
            match turn {
                1 => shape.turns.push((panel, mark)),
                2 => shape.u_turns.push((panel, mark)),
                _ => {}
            }
            corners.push(pts);
        }
        match (0..n).find(|&j| steps[j].vertical) {
            None => {
                let panel = g.panel(walk[0]);
                shape
                    .lines
                    .push((panel, corners.into_iter().flatten().collect(), true));
            }
            Some(leave) => {
                // Start just after a move between layers, so every run is whole.
                let mut run: Vec<Point> = Vec::new();
                for j in (leave + 1..=leave + n).map(|j| j % n) {
                    run.extend(&corners[j]);
                    if steps[j].vertical {
                        shape
                            .lines
                            .push((g.panel(steps[j].from), std::mem::take(&mut run), false));
                    }
                }
            }
        }
        shapes.push(shape);
    }
    shapes
}

// ---------------------------------------------------------------------------------------------
// Layout and rendering, in output pixels (y down).
// ---------------------------------------------------------------------------------------------

const LABEL_PX: f64 = 15.0;
/// Gap between panels, in edge lengths.
const PANEL_GAP: f64 = 1.0;
/// At most this many panels in a row when there are few layers.
const SIDE_BY_SIDE: usize = 4;

const EDGE_LINE: RGBColor = RGBColor(0xb4, 0xb4, 0xb4);
const PANEL_FRAME: RGBColor = RGBColor(0xe0, 0xe0, 0xe0);
const VERTEX_DOT: RGBColor = RGBColor(0x80, 0x80, 0x80);

/// Where the panels go on the canvas.
#[derive(Clone, Debug)]
struct Layout {
    /// Output pixels per coordinate unit.
    scale: f64,
    /// Output pixels per edge length.
    pixel_size: f64,
    /// Canvas position of each panel's top-left corner.
    origins: Vec<Point>,
    /// The coordinates of a panel's top-left corner.
    corner: Point,
    /// Height of the band above each panel for its label (0 with one panel).
    label_band: f64,
    panel_px: Point,
    width: u32,
    height: u32,
}

impl Layout {
    fn new(g: &Geometry, opts: &DrawOptions) -> Result<Layout> {
        let panels = g.layers.len();
        let (pw, ph) = g.panel_size();
        let gap = PANEL_GAP * g.unit;
        let extent = |cols: usize| {
            let rows = panels.div_ceil(cols);
            (
                cols as f64 * pw + (cols - 1) as f64 * gap,
                rows as f64 * ph + (rows - 1) as f64 * gap,
            )
        };
        let cols = if panels <= SIDE_BY_SIDE {
            panels
        } else {
            // Close to 16:10 overall.
            (1..=panels)
                .min_by(|&a, &b| {
                    let off = |c| {
                        let (w, h) = extent(c);
                        (w / h / 1.6).ln().abs()
                    };
                    off(a).total_cmp(&off(b))
                })
                .unwrap_or(panels)
        };
        let rows = panels.div_ceil(cols);
        let (ew, eh) = extent(cols);
        let pixel_size = match opts.pixel_size {
            Some(0) => return Err(Error::invalid("pixel size must be at least 1")),
            Some(s) => f64::from(s),
            None => {
                let side = if panels > 1 { 1.25 } else { 1.0 } * AUTO_SIDE_PX;
                let s = (side * g.unit / ew.max(eh)).min(MAX_AUTO_PIXEL_SIZE);
                if s >= 1.0 { s.floor() } else { s }
            }
        };
        let scale = pixel_size / g.unit;
        let label_band = if panels > 1 { LABEL_PX * 1.6 } else { 0.0 };
        let (grid_w, grid_h) = (ew * scale, eh * scale + rows as f64 * label_band);
        let c = canvas(
            (grid_w, grid_h),
            opts.title.as_deref(),
            opts.caption.as_deref(),
            (0.0, 0.0),
        )?;
        let (left, top) = (c.left, c.top);
        let origins = (0..panels)
            .map(|p| {
                let (c, r) = ((p % cols) as f64, (p / cols) as f64);
                (
                    left + c * (pw + gap) * scale,
                    top + r * ((ph + gap) * scale + label_band) + label_band,
                )
            })
            .collect();
        let pad = g.pad();
        Ok(Layout {
            scale,
            pixel_size,
            origins,
            corner: (g.bbox[0] - pad, g.bbox[3] + pad),
            label_band,
            panel_px: (pw * scale, ph * scale),
            width: c.width,
            height: c.height,
        })
    }

    /// Canvas position of point `p` of panel `panel`.
    fn point(&self, panel: usize, p: Point) -> Point {
        let o = self.origins[panel];
        (
            o.0 + (p.0 - self.corner.0) * self.scale,
            o.1 + (self.corner.1 - p.1) * self.scale,
        )
    }
}

struct Scene<'a> {
    geometry: Geometry,
    layout: Layout,
    cells: Vec<PanelCells>,
    walks: Vec<WalkShape>,
    detailed: bool,
    mark_turns: bool,
    title: Option<&'a str>,
    caption: Option<&'a str>,
}

/// Strokes the polyline through `pts` (closed: back to the first), `w` backend pixels wide.
fn stroke<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    strokes: Strokes,
    pts: &[(i32, i32)],
    closed: bool,
    colour: RGBColor,
    w: u32,
) -> DrawResult<DB> {
    let mut path: Vec<(i32, i32)> = pts.to_vec();
    path.dedup();
    if path.is_empty() {
        return Ok(());
    }
    if closed && path.len() > 1 {
        while path.len() > 1 && path.first() == path.last() {
            path.pop();
        }
        path.push(path[0]);
    }
    match strokes {
        _ if path.len() == 1 => area.draw(&Circle::new(path[0], (w / 2).max(1), colour.filled())),
        Strokes::Polylines => area.draw(&PathElement::new(path, colour.stroke_width(w))),
        Strokes::Segments => {
            for pair in path.windows(2) {
                area.draw(&PathElement::new(pair.to_vec(), colour.stroke_width(w)))?;
            }
            if w > 2 {
                for &p in &path {
                    area.draw(&Circle::new(p, w / 2, colour.filled()))?;
                }
            }
            Ok(())
        }
    }
}

/// A triangle of half-size `r` at `at`, pointing up or down.
fn triangle(at: (i32, i32), r: i32, way: Vertical) -> Vec<(i32, i32)> {
    let s = if way == Vertical::Up { -1 } else { 1 };
    vec![
        (at.0, at.1 + s * r),
        (at.0 - r, at.1 - s * r * 2 / 3),
        (at.0 + r, at.1 - s * r * 2 / 3),
    ]
}

/// Draws the scene on `area`, whose size is the layout's times `k`.
fn render<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scene: &Scene,
    k: f64,
    strokes: Strokes,
) -> DrawResult<DB> {
    let l = &scene.layout;
    let ps = l.pixel_size;
    let at = |panel: usize, p: Point| {
        let (x, y) = l.point(panel, p);
        ((x * k).round() as i32, (y * k).round() as i32)
    };
    let px = |w: f64| ((w * k).round() as u32).max(1);
    let font =
        |size: f64| FontDesc::new(FontFamily::from(FONT_FAMILY), size * k, FontStyle::Normal);

    area.fill(&WHITE)?;
    for (panel, cells) in scene.cells.iter().enumerate() {
        for polygon in &cells.polygons {
            let pts: Vec<(i32, i32)> = polygon.iter().map(|&p| at(panel, p)).collect();
            area.draw(&Polygon::new(pts.clone(), REGION_FILL.filled()))?;
            if cells.borders {
                stroke(area, strokes, &pts, true, GRID_LINE, px(1.0))?;
            }
        }
        let edge_w = px(if scene.detailed { 1.0 } else { 0.5 });
        for &[a, b] in &cells.edges {
            stroke(
                area,
                strokes,
                &[at(panel, a), at(panel, b)],
                false,
                EDGE_LINE,
                edge_w,
            )?;
        }
        if scene.detailed || ps >= 2.0 {
            let w = px(if scene.detailed { 2.0 } else { 1.0 });
            for &[a, b] in &cells.outline {
                stroke(
                    area,
                    strokes,
                    &[at(panel, a), at(panel, b)],
                    false,
                    OUTLINE,
                    w,
                )?;
            }
        }
        let dot = px((0.05 * ps).clamp(1.0, 3.0));
        for &p in &cells.dots {
            area.draw(&Circle::new(at(panel, p), dot, VERTEX_DOT.filled()))?;
        }
        if l.label_band > 0.0 {
            // A faint frame, so that a cell can be found at the same place in every layer.
            let z = scene.geometry.layers[panel];
            let origin = l.origins[panel];
            let frame = [
                origin,
                (origin.0 + l.panel_px.0, origin.1),
                (origin.0 + l.panel_px.0, origin.1 + l.panel_px.1),
                (origin.0, origin.1 + l.panel_px.1),
            ]
            .map(|(x, y)| ((x * k).round() as i32, (y * k).round() as i32));
            stroke(area, strokes, &frame, true, PANEL_FRAME, px(1.0))?;
            let centre = (
                ((origin.0 + l.panel_px.0 / 2.0) * k).round() as i32,
                ((origin.1 - l.label_band * 0.2) * k).round() as i32,
            );
            let style = font(LABEL_PX)
                .color(&CAPTION_COLOUR)
                .pos(Pos::new(HPos::Center, VPos::Bottom));
            area.draw(&Text::new(format!("z = {z}"), centre, style))?;
        }
    }

    let line_px = if scene.detailed {
        (0.05 * ps).clamp(1.5, 3.0)
    } else {
        (0.25 * ps).clamp(1.0, 2.0)
    };
    for (i, walk) in scene.walks.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        for (panel, line, closed) in &walk.lines {
            let pts: Vec<(i32, i32)> = line.iter().map(|&p| at(*panel, p)).collect();
            stroke(area, strokes, &pts, *closed, colour, px(line_px))?;
        }
        if let Some((panel, p)) = walk.single {
            let r = px((0.22 * ps).max(3.0));
            area.draw(&Circle::new(
                at(panel, p),
                r,
                colour.stroke_width(px(line_px)),
            ))?;
        }
    }
    let marks = scene.detailed && scene.mark_turns;
    if marks {
        // Larger than half the strand gap, so the ring encloses the end of the hairpin.
        let ring = px((0.15 * ps).clamp(4.0, 14.0));
        let ring_line = px((line_px * 0.7).max(1.0));
        for (i, walk) in scene.walks.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            for &(panel, p) in &walk.u_turns {
                // Filled first, so the hairpin's end disappears into a clean ring.
                area.draw(&Circle::new(at(panel, p), ring, REGION_FILL.filled()))?;
                area.draw(&Circle::new(
                    at(panel, p),
                    ring,
                    colour.stroke_width(ring_line),
                ))?;
            }
        }
    }
    // Moves between layers are marked even in plain pictures, since without them the runs of
    // a walk would not join up; after the rings, which may surround them (a U-turn between
    // layers).
    let tri = (px((0.11 * ps).clamp(3.5, 10.0))) as i32;
    for (i, walk) in scene.walks.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        for &(panel, p, way) in &walk.verticals {
            let shape = triangle(at(panel, p), tri, way);
            area.draw(&Polygon::new(shape, colour.filled()))?;
        }
    }
    if marks {
        // Dots last, so that no ring hides a turn.
        let dot = px((0.07 * ps).clamp(2.5, 5.0));
        for (i, walk) in scene.walks.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            for &(panel, p) in &walk.turns {
                area.draw(&Circle::new(at(panel, p), dot, colour.filled()))?;
            }
        }
    }

    draw_title_and_caption(area, (l.width, l.height), k, scene.title, scene.caption)?;
    area.present()
}

impl Picture for Scene<'_> {
    fn size(&self) -> (u32, u32) {
        (self.layout.width, self.layout.height)
    }

    /// Below one output pixel per unit the SVG canvas is enlarged so that every vertex keeps
    /// whole-number coordinates.
    fn svg_scale(&self) -> f64 {
        (1.0 / self.layout.pixel_size).ceil().max(1.0)
    }

    fn render<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: f64,
        strokes: Strokes,
    ) -> DrawResult<DB> {
        render(area, self, k, strokes)
    }
}

#[cfg(test)]
mod tests;
