//! Pictures of a region and a cycle cover over it, as SVG or PNG, for papers and debugging.
//!
//! The picture shows the region's pixels filled in light grey with thin grid lines, holes and
//! the outside white, and the region's boundary as a dark outline. Each closed walk of the
//! cover is a polyline through pixel centres in its own colour; a 90° turn is marked with a
//! dot, a U-turn with a ring, and a single-pixel walk is a circle. An edge traversed more than
//! once (by one walk or by several) is drawn as parallel strands offset sideways, so that every
//! traversal can be seen and counted.
//!
//! Pictures wider or taller than [`DETAIL_LIMIT`] pixels are drawn plainly: no grid, no
//! markers, no strands, and the pixels filled as rectangles merged from horizontal runs (not
//! one per pixel), so that a 1000 × 1000 region draws in a fraction of a second.
//!
//! Text uses the bundled DejaVu Sans (`assets/fonts/`), so no system font is needed.

use crate::error::{Error, Result};
use crate::region::{Dir, Pixel, Region};
use crate::topology::{Saddle, boundary_rings};
use crate::tour::CycleCover;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontDesc, FontFamily, FontStyle, register_font};
use std::collections::HashMap;
use std::path::Path;
use std::sync::Once;

/// The font family name under which [`ensure_fonts`] registers the bundled DejaVu Sans.
///
/// It is the generic `sans-serif`, so that an SVG, which names the family rather than
/// embedding the font, still renders in a sans-serif face where DejaVu is not installed.
pub(crate) const FONT_FAMILY: &str = "sans-serif";

static DEJAVU_SANS: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");

/// Registers the bundled DejaVu Sans with plotters as [`FONT_FAMILY`] (once per process).
///
/// plotters' `ab_glyph` text renderer knows no system fonts: call this before drawing any
/// text with plotters. [`draw`] calls it itself.
pub(crate) fn ensure_fonts() {
    static REGISTER: Once = Once::new();
    REGISTER.call_once(|| {
        if register_font(FONT_FAMILY, FontStyle::Normal, DEJAVU_SANS).is_err() {
            panic!("the bundled assets/fonts/DejaVuSans.ttf is not a valid TrueType font");
        }
    });
}

/// Pictures with more than this many pixels across (or up) are drawn plainly: no grid lines,
/// no turn markers and no side-by-side strands for repeated edges.
pub const DETAIL_LIMIT: usize = 200;

/// The longer side of the grid, in output pixels, when the pixel size is chosen automatically.
pub const AUTO_SIDE_PX: f64 = 800.0;

/// The largest automatic pixel size, so that tiny regions do not turn into posters.
pub(crate) const MAX_AUTO_PIXEL_SIZE: f64 = 120.0;

/// The largest picture [`draw`] will make, in output pixels.
const MAX_IMAGE_PX: u64 = 64_000_000;

/// How to draw; `DrawOptions::default()` gives a figure ready for a paper.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DrawOptions {
    /// A line of text above the picture.
    pub title: Option<String>,
    /// A smaller line of text below the picture, such as
    /// `"N = 24, length 26, turns 12, 2 cycles"`.
    pub caption: Option<String>,
    /// Output pixels per grid unit. `None` chooses it so that the longer side of the grid is
    /// about [`AUTO_SIDE_PX`] pixels (at most 120 per unit; below 1 for very large regions).
    pub pixel_size: Option<u32>,
    /// Thin lines between neighbouring pixels of the region.
    pub show_grid: bool,
    /// Dots at 90° turns and rings at U-turns.
    pub mark_turns: bool,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            title: None,
            caption: None,
            pixel_size: None,
            show_grid: true,
            mark_turns: true,
        }
    }
}

/// Draws `region`, and `cover` over it when given, to `out`: an SVG or a PNG file, chosen by
/// the extension of `out`.
///
/// # Arguments
///
/// * `region` — the pixels to fill; may be empty when `cover` is not.
/// * `cover` — closed walks to draw over the region, each in its own colour. Walks that leave
///   the region are drawn too (the picture then extends beyond the region).
/// * `out` — the file to write; its extension (`svg` or `png`, any case) picks the format.
/// * `opts` — title, caption, scale and what to show.
///
/// # Returns
///
/// `Error::Invalid` for an unknown extension, a walk with a step that is not a unit move,
/// nothing to draw, or a picture too large; `Error::Io` when the file cannot be written.
///
/// # Complexity
///
/// O(N + L + B) time, for N pixels, total walk length L and bounding-box area B (the boundary
/// is traced on a grid over the region's bounding box), plus the cost of filling the image.
///
/// # Examples
///
/// ```no_run
/// use mowmill::draw::{DrawOptions, draw};
/// use mowmill::{CycleCover, Pixel, Region};
///
/// let region = Region::rectangle(2, 2);
/// let tour = CycleCover::tour(vec![
///     Pixel::new(0, 0),
///     Pixel::new(1, 0),
///     Pixel::new(1, 1),
///     Pixel::new(0, 1),
/// ]);
/// let opts = DrawOptions { title: Some("2 × 2".into()), ..DrawOptions::default() };
/// draw(&region, Some(&tour), std::path::Path::new("square.svg"), &opts)?;
/// # Ok::<(), mowmill::Error>(())
/// ```
pub fn draw(
    region: &Region,
    cover: Option<&CycleCover>,
    out: &Path,
    opts: &DrawOptions,
) -> Result<()> {
    let format = Format::of(out)?;
    write_picture(&scene(region, cover, opts)?, format, out)
}

/// Draws two pictures of [`draw`] next to each other into one file (`svg` or `png` by `out`'s
/// extension), each in its own half of the canvas: an algorithm's walk beside the best known.
pub fn draw_beside(
    left: (&Region, Option<&CycleCover>, &DrawOptions),
    right: (&Region, Option<&CycleCover>, &DrawOptions),
    out: &Path,
) -> Result<()> {
    let format = Format::of(out)?;
    let left = scene(left.0, left.1, left.2)?;
    let right = scene(right.0, right.1, right.2)?;
    write_picture(&Beside(left, right), format, out)
}

/// The scene [`draw`] renders.
fn scene<'a>(
    region: &Region,
    cover: Option<&CycleCover>,
    opts: &'a DrawOptions,
) -> Result<Scene<'a>> {
    let empty = CycleCover::default();
    let cover = cover.unwrap_or(&empty);
    let frame = Frame::of(region, cover)?;
    let detailed = frame.width().max(frame.height()) <= DETAIL_LIMIT as i64;
    let walks = walk_shapes(cover, detailed)?;
    ensure_fonts();
    let layout = Layout::new(frame, opts)?;
    let scene = Scene {
        rects: region_rectangles(region),
        grid: if detailed && opts.show_grid {
            grid_segments(region)
        } else {
            Vec::new()
        },
        // Saddles kept apart, as the outline has always been drawn (each pixel its own corner).
        contours: boundary_rings(region, Saddle::Apart)
            .into_iter()
            .map(|ring| ring.corners)
            .collect(),
        walks,
        detailed,
        mark_turns: opts.mark_turns,
        title: opts.title.as_deref(),
        caption: opts.caption.as_deref(),
        layout,
    };
    Ok(scene)
}

/// The picture formats, chosen by the output file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Format {
    Svg,
    Png,
}

impl Format {
    pub(crate) fn of(out: &Path) -> Result<Format> {
        let ext = out.extension().map(|e| e.to_string_lossy().to_lowercase());
        match ext.as_deref() {
            Some("svg") => Ok(Format::Svg),
            Some("png") => Ok(Format::Png),
            Some(other) => Err(Error::invalid(format!(
                "{}: cannot draw to a .{other} file; use .svg or .png",
                out.display()
            ))),
            None => Err(Error::invalid(format!(
                "{}: no file extension; use .svg or .png",
                out.display()
            ))),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Geometry, in grid units: pixel (x, y) is [x, x + 1] × [y, y + 1], its centre (x + .5, y + .5).
// ---------------------------------------------------------------------------------------------

/// The pixels shown: the region's bounding box grown to hold every walk (inclusive bounds).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Frame {
    min_x: i32,
    min_y: i32,
    max_x: i32,
    max_y: i32,
}

impl Frame {
    fn of(region: &Region, cover: &CycleCover) -> Result<Frame> {
        let mut frame = (!region.is_empty()).then(|| {
            let b = region.bbox();
            Frame {
                min_x: b.min_x,
                min_y: b.min_y,
                max_x: b.max_x,
                max_y: b.max_y,
            }
        });
        for &p in cover.cycles.iter().flatten() {
            let f = frame.get_or_insert(Frame {
                min_x: p.x,
                min_y: p.y,
                max_x: p.x,
                max_y: p.y,
            });
            f.min_x = f.min_x.min(p.x);
            f.min_y = f.min_y.min(p.y);
            f.max_x = f.max_x.max(p.x);
            f.max_y = f.max_y.max(p.y);
        }
        frame.ok_or_else(|| Error::invalid("nothing to draw: the region and the cover are empty"))
    }

    fn width(&self) -> i64 {
        i64::from(self.max_x) - i64::from(self.min_x) + 1
    }

    fn height(&self) -> i64 {
        i64::from(self.max_y) - i64::from(self.min_y) + 1
    }
}

/// The pixels of the region as few axis-parallel rectangles `[x0, x1, y0, y1]` (half-open):
/// the horizontal runs of each row, merged with identical runs in the rows above.
fn region_rectangles(region: &Region) -> Vec<[i32; 4]> {
    let mut done = Vec::new();
    // Open rectangles (x0, x1, first row), sorted by x0, all reaching up to the previous row.
    let mut open: Vec<(i32, i32, i32)> = Vec::new();
    let mut prev_row: Option<i32> = None;
    let pixels = region.pixels();
    let mut i = 0;
    while i < pixels.len() {
        let y = pixels[i].y;
        let mut runs: Vec<(i32, i32)> = Vec::new();
        while i < pixels.len() && pixels[i].y == y {
            let x0 = pixels[i].x;
            let mut x1 = x0 + 1;
            i += 1;
            while i < pixels.len() && pixels[i].y == y && pixels[i].x == x1 {
                x1 += 1;
                i += 1;
            }
            runs.push((x0, x1));
        }
        if let Some(prev) = prev_row.filter(|&prev| prev != y - 1) {
            // An empty row in between: nothing continues.
            done.extend(open.drain(..).map(|(x0, x1, y0)| [x0, x1, y0, prev + 1]));
        }
        let mut next = Vec::with_capacity(runs.len());
        let (mut a, mut b) = (0, 0);
        while a < open.len() || b < runs.len() {
            let take_open = b == runs.len() || (a < open.len() && open[a].0 < runs[b].0);
            let take_run = a == open.len() || (b < runs.len() && runs[b].0 < open[a].0);
            if take_open {
                let (x0, x1, y0) = open[a];
                done.push([x0, x1, y0, y]);
                a += 1;
            } else if take_run {
                next.push((runs[b].0, runs[b].1, y));
                b += 1;
            } else if open[a].1 == runs[b].1 {
                next.push(open[a]);
                a += 1;
                b += 1;
            } else {
                let (x0, x1, y0) = open[a];
                done.push([x0, x1, y0, y]);
                next.push((runs[b].0, runs[b].1, y));
                a += 1;
                b += 1;
            }
        }
        open = next;
        prev_row = Some(y);
    }
    if let Some(y) = prev_row {
        done.extend(open.drain(..).map(|(x0, x1, y0)| [x0, x1, y0, y + 1]));
    }
    done
}

/// Grid lines between two pixels of the region, merged into maximal segments, as pairs of
/// lattice points.
fn grid_segments(region: &Region) -> Vec<[(i32, i32); 2]> {
    let mut segments = Vec::new();
    if region.is_empty() {
        return segments;
    }
    let b = region.bbox();
    let both = |p: Pixel, d: Dir| region.contains(p) && region.contains(p.step(d));
    // Horizontal line at height y separates row y - 1 from row y.
    for y in b.min_y + 1..=b.max_y {
        let mut start = None;
        for x in b.min_x..=b.max_x + 1 {
            match (start, x <= b.max_x && both(Pixel::new(x, y), Dir::S)) {
                (None, true) => start = Some(x),
                (Some(x0), false) => {
                    segments.push([(x0, y), (x, y)]);
                    start = None;
                }
                _ => {}
            }
        }
    }
    // Vertical line at abscissa x separates column x - 1 from column x.
    for x in b.min_x + 1..=b.max_x {
        let mut start = None;
        for y in b.min_y..=b.max_y + 1 {
            match (start, y <= b.max_y && both(Pixel::new(x, y), Dir::W)) {
                (None, true) => start = Some(y),
                (Some(y0), false) => {
                    segments.push([(x, y0), (x, y)]);
                    start = None;
                }
                _ => {}
            }
        }
    }
    segments
}

/// Sideways distance between two strands of an edge traversed more than once, in grid units.
pub(crate) const STRAND_GAP: f64 = 0.2;
/// The widest the strands of one edge may spread, in grid units.
pub(crate) const STRAND_SPREAD: f64 = 0.5;
/// Half the length of the slanted jog where a straight walk changes strand, in grid units.
pub(crate) const JOG: f64 = 0.12;

/// One closed walk, ready to draw, in grid units.
#[derive(Clone, Debug, Default, PartialEq)]
struct WalkShape {
    /// Corners of the closed polyline (the first not repeated).
    line: Vec<(f64, f64)>,
    /// Points of 90° turns.
    turns: Vec<(f64, f64)>,
    /// Points of U-turns (the middle of the hairpin).
    u_turns: Vec<(f64, f64)>,
    /// Centre of a single-pixel walk.
    single: Option<(f64, f64)>,
}

/// The undirected grid edge of a step from `p` in direction `d`: its lower-left pixel and
/// whether it is horizontal.
fn edge_key(p: Pixel, d: Dir) -> (Pixel, bool) {
    match d {
        Dir::E => (p, true),
        Dir::W => (p.step(Dir::W), true),
        Dir::N => (p, false),
        Dir::S => (p.step(Dir::S), false),
    }
}

/// How often an edge is traversed in its canonical direction (east or north) and against it.
#[derive(Clone, Copy, Debug, Default)]
struct Traffic {
    along: u32,
    against: u32,
}

/// Sideways offset of a traversal of an edge, `+y` for a horizontal edge and `+x` for a
/// vertical one. Traversals keep to their right: of the `along + against` lanes, spread
/// evenly about the edge, those heading east or north take the lanes on their right, the
/// others the lanes on theirs, earlier visits outermost. A walk that goes along a corridor
/// and back thus makes a hairpin with no crossing.
fn strand_offset(traffic: Traffic, horizontal: bool, canonical: bool, visit: u32) -> f64 {
    let m = traffic.along + traffic.against;
    if m <= 1 {
        return 0.0;
    }
    let gap = STRAND_GAP.min(STRAND_SPREAD / f64::from(m - 1));
    // Lanes numbered from left to right as seen heading east or north.
    let lane = if canonical { m - 1 - visit } else { visit };
    let right = (f64::from(lane) - f64::from(m - 1) / 2.0) * gap;
    // Right of east is -y; right of north is +x.
    if horizontal { -right } else { right }
}

/// Polylines and turn markers for every walk of `cover`. With `detailed`, repeated traversals
/// of an edge are spread into parallel strands; otherwise every walk runs through centres.
fn walk_shapes(cover: &CycleCover, detailed: bool) -> Result<Vec<WalkShape>> {
    let mut dirs: Vec<Vec<Dir>> = Vec::with_capacity(cover.cycles.len());
    for (w, walk) in cover.cycles.iter().enumerate() {
        let n = walk.len();
        let mut steps = Vec::with_capacity(n);
        for i in 0..if n >= 2 { n } else { 0 } {
            let (p, q) = (walk[i], walk[(i + 1) % n]);
            let d = p.dir_to(q).ok_or_else(|| {
                Error::invalid(format!(
                    "cannot draw walk {w}: step {i} from {p} to {q} is not a unit move"
                ))
            })?;
            steps.push(d);
        }
        dirs.push(steps);
    }
    // How often each edge is traversed, by all walks together, in each direction.
    let mut traffic: HashMap<(Pixel, bool), Traffic> = HashMap::new();
    if detailed {
        for (walk, steps) in cover.cycles.iter().zip(&dirs) {
            for (&p, &d) in walk.iter().zip(steps) {
                let t = traffic.entry(edge_key(p, d)).or_default();
                match d {
                    Dir::E | Dir::N => t.along += 1,
                    Dir::W | Dir::S => t.against += 1,
                }
            }
        }
    }
    let mut seen: HashMap<(Pixel, bool), Traffic> = HashMap::new();
    let mut shapes = Vec::with_capacity(cover.cycles.len());
    for (walk, steps) in cover.cycles.iter().zip(&dirs) {
        let mut shape = WalkShape::default();
        let centre = |p: Pixel| (f64::from(p.x) + 0.5, f64::from(p.y) + 0.5);
        if walk.len() == 1 {
            shape.single = Some(centre(walk[0]));
        }
        if steps.is_empty() {
            shapes.push(shape);
            continue;
        }
        let offsets: Vec<f64> = walk
            .iter()
            .zip(steps)
            .map(|(&p, &d)| {
                if !detailed {
                    return 0.0;
                }
                let key = edge_key(p, d);
                let visits = seen.entry(key).or_default();
                let canonical = matches!(d, Dir::E | Dir::N);
                let count = if canonical {
                    &mut visits.along
                } else {
                    &mut visits.against
                };
                *count += 1;
                strand_offset(traffic[&key], key.1, canonical, *count - 1)
            })
            .collect();
        let n = steps.len();
        for j in 0..n {
            let prev = (j + n - 1) % n;
            let (da, db) = (steps[prev], steps[j]);
            let (sa, sb) = (offsets[prev], offsets[j]);
            let (cx, cy) = centre(walk[j]);
            // Moves a point sideways by `s` off a step in direction `d`.
            let side = |d: Dir, s: f64, (x, y): (f64, f64)| {
                if d.is_horizontal() {
                    (x, y + s)
                } else {
                    (x + s, y)
                }
            };
            match da.turn_to(db) {
                1 => {
                    let corner = side(db, sb, side(da, sa, (cx, cy)));
                    shape.line.push(corner);
                    shape.turns.push(corner);
                }
                2 => {
                    let a = side(da, sa, (cx, cy));
                    let b = side(db, sb, (cx, cy));
                    shape.line.push(a);
                    shape.line.push(b);
                    shape.u_turns.push(((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0));
                }
                _ if sa != sb => {
                    let (dx, dy) = da.delta();
                    let (jx, jy) = (f64::from(dx) * JOG, f64::from(dy) * JOG);
                    shape.line.push(side(da, sa, (cx - jx, cy - jy)));
                    shape.line.push(side(db, sb, (cx + jx, cy + jy)));
                }
                _ => {}
            }
        }
        shapes.push(shape);
    }
    Ok(shapes)
}

// ---------------------------------------------------------------------------------------------
// Layout and rendering, in output pixels (y down).
// ---------------------------------------------------------------------------------------------

pub(crate) const MARGIN_PX: f64 = 16.0;
pub(crate) const TITLE_PX: f64 = 22.0;
pub(crate) const CAPTION_PX: f64 = 17.0;

pub(crate) const REGION_FILL: RGBColor = RGBColor(0xe9, 0xe9, 0xe9);
const PLAIN_REGION_FILL: RGBColor = RGBColor(0xd6, 0xd6, 0xd6);
pub(crate) const GRID_LINE: RGBColor = RGBColor(0xc8, 0xc8, 0xc8);
pub(crate) const OUTLINE: RGBColor = RGBColor(0x33, 0x33, 0x33);
pub(crate) const TITLE_COLOUR: RGBColor = RGBColor(0x1a, 0x1a, 0x1a);
pub(crate) const CAPTION_COLOUR: RGBColor = RGBColor(0x4d, 0x4d, 0x4d);

/// Walk colours: the Okabe–Ito colour-blind-safe palette without its yellow and black (too
/// faint and too close to the outline), then two more; cycled when there are more walks. The
/// plots of `harness::plots` use it too.
pub(crate) const PALETTE: [RGBColor; 8] = [
    RGBColor(0x00, 0x72, 0xb2), // blue
    RGBColor(0xd5, 0x5e, 0x00), // vermillion
    RGBColor(0x00, 0x9e, 0x73), // bluish green
    RGBColor(0xcc, 0x79, 0xa7), // reddish purple
    RGBColor(0xe6, 0x9f, 0x00), // orange
    RGBColor(0x56, 0xb4, 0xe9), // sky blue
    RGBColor(0x8c, 0x56, 0x4b), // brown
    RGBColor(0x6a, 0x3d, 0x9a), // purple
];

/// The width of `text` in output pixels, in the bundled font at `size` px (0 without text;
/// call [`ensure_fonts`] first).
pub(crate) fn text_width(text: Option<&str>, size: f64) -> f64 {
    text.map_or(0.0, |t| {
        let font = FontDesc::new(FontFamily::from(FONT_FAMILY), size, FontStyle::Normal);
        font.box_size(t).map_or(0.0, |(w, _)| f64::from(w))
    })
}

/// Where a drawing goes on its canvas: the canvas size and the drawing's top-left corner, in
/// output pixels ([`canvas`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Canvas {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) left: f64,
    pub(crate) top: f64,
}

/// The canvas of every picture: a drawing of `inner` = (width, height) output pixels centred
/// within the margins, the title (if any) above it, then `below` = (least width, height) of a
/// band under it (a legend, or nothing), then the caption (if any); refused when the canvas
/// would exceed [`MAX_IMAGE_PX`] pixels. Call [`ensure_fonts`] first.
pub(crate) fn canvas(
    inner: (f64, f64),
    title: Option<&str>,
    caption: Option<&str>,
    below: (f64, f64),
) -> Result<Canvas> {
    let wide = inner
        .0
        .max(text_width(title, TITLE_PX))
        .max(text_width(caption, CAPTION_PX))
        .max(below.0);
    let title_band = if title.is_some() { TITLE_PX * 1.5 } else { 0.0 };
    let caption_band = if caption.is_some() {
        CAPTION_PX * 1.6
    } else {
        0.0
    };
    let width = (wide + 2.0 * MARGIN_PX).ceil();
    let height = (inner.1 + title_band + below.1 + caption_band + 2.0 * MARGIN_PX).ceil();
    if width * height > MAX_IMAGE_PX as f64 {
        return Err(Error::invalid(format!(
            "the picture would be {width} × {height} px; choose a smaller pixel size"
        )));
    }
    Ok(Canvas {
        width: width as u32,
        height: height as u32,
        left: ((width - inner.0) / 2.0).round(),
        top: (MARGIN_PX + title_band).round(),
    })
}

/// Where the grid goes on the canvas.
#[derive(Clone, Copy, Debug)]
struct Layout {
    frame: Frame,
    /// Output pixels per grid unit.
    pixel_size: f64,
    /// Canvas position of the frame's top-left corner, lattice point (min_x, max_y + 1).
    left: f64,
    top: f64,
    width: u32,
    height: u32,
}

impl Layout {
    fn new(frame: Frame, opts: &DrawOptions) -> Result<Layout> {
        let side = frame.width().max(frame.height()) as f64;
        let pixel_size = match opts.pixel_size {
            Some(0) => return Err(Error::invalid("pixel size must be at least 1")),
            Some(s) => f64::from(s),
            None => {
                let s = (AUTO_SIDE_PX / side).min(MAX_AUTO_PIXEL_SIZE);
                // Whole pixels keep grid lines crisp in a PNG.
                if s >= 1.0 { s.floor() } else { s }
            }
        };
        let (grid_w, grid_h) = (
            frame.width() as f64 * pixel_size,
            frame.height() as f64 * pixel_size,
        );
        let c = canvas(
            (grid_w, grid_h),
            opts.title.as_deref(),
            opts.caption.as_deref(),
            (0.0, 0.0),
        )?;
        Ok(Layout {
            frame,
            pixel_size,
            left: c.left,
            top: c.top,
            width: c.width,
            height: c.height,
        })
    }

    /// Canvas position of grid point (x, y).
    fn point(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.left + (x - f64::from(self.frame.min_x)) * self.pixel_size,
            self.top + (f64::from(self.frame.max_y) + 1.0 - y) * self.pixel_size,
        )
    }
}

struct Scene<'a> {
    layout: Layout,
    rects: Vec<[i32; 4]>,
    grid: Vec<[(i32, i32); 2]>,
    contours: Vec<Vec<(i64, i64)>>,
    walks: Vec<WalkShape>,
    detailed: bool,
    mark_turns: bool,
    title: Option<&'a str>,
    caption: Option<&'a str>,
}

/// How lines reach the backend.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Strokes {
    /// One polyline per line: small SVG files that stay editable.
    Polylines,
    /// One filled rectangle per axis-parallel segment, with square ends so that right-angle
    /// corners close. plotters fills a wide polyline as a single even-odd polygon, which
    /// would leave gaps wherever a walk crosses or retraces itself.
    Segments,
}

pub(crate) type DrawResult<DB> = std::result::Result<
    (),
    plotters::drawing::DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>,
>;

/// Strokes the segment from `a` to `b`, `w` backend pixels wide.
pub(crate) fn stroke_segment<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    strokes: Strokes,
    (a, b): ((i32, i32), (i32, i32)),
    colour: RGBColor,
    w: u32,
) -> DrawResult<DB> {
    let axis_parallel = a.0 == b.0 || a.1 == b.1;
    if strokes == Strokes::Segments && axis_parallel {
        let (lo, hi) = ((w / 2) as i32, (w - w / 2) as i32);
        let top_left = (a.0.min(b.0) - lo, a.1.min(b.1) - lo);
        let bottom_right = (a.0.max(b.0) + hi, a.1.max(b.1) + hi);
        area.draw(&Rectangle::new([top_left, bottom_right], colour.filled()))
    } else {
        area.draw(&PathElement::new(vec![a, b], colour.stroke_width(w)))
    }
}

/// Strokes the closed polyline through `corners`, `w` backend pixels wide.
pub(crate) fn stroke_closed<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    strokes: Strokes,
    corners: impl Iterator<Item = (i32, i32)>,
    colour: RGBColor,
    w: u32,
) -> DrawResult<DB> {
    let mut pts: Vec<(i32, i32)> = Vec::new();
    for p in corners {
        if pts.last() != Some(&p) {
            pts.push(p);
        }
    }
    while pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    let n = pts.len();
    match (strokes, n) {
        (_, 0) => Ok(()),
        (_, 1) => stroke_segment(area, strokes, (pts[0], pts[0]), colour, w),
        (Strokes::Polylines, _) => {
            // Start and end in the middle of the first side, so that every corner is a join.
            let mid = ((pts[0].0 + pts[1].0) / 2, (pts[0].1 + pts[1].1) / 2);
            let mut path = Vec::with_capacity(n + 2);
            path.push(mid);
            path.extend(pts[1..].iter().copied());
            path.push(pts[0]);
            path.push(mid);
            path.dedup();
            area.draw(&PathElement::new(path, colour.stroke_width(w)))
        }
        (Strokes::Segments, _) => (0..n)
            .try_for_each(|i| stroke_segment(area, strokes, (pts[i], pts[(i + 1) % n]), colour, w)),
    }
}

impl Picture for Scene<'_> {
    fn size(&self) -> (u32, u32) {
        (self.layout.width, self.layout.height)
    }

    /// Below one output pixel per grid unit the SVG canvas is enlarged so that every pixel
    /// keeps whole-number coordinates (SVG coordinates from plotters are integers).
    fn svg_scale(&self) -> f64 {
        (1.0 / self.layout.pixel_size).ceil().max(1.0)
    }

    /// Draws the scene on `area`, whose size is the layout's times `k`.
    fn render<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: f64,
        strokes: Strokes,
    ) -> DrawResult<DB> {
        let scene = self;
        let l = &scene.layout;
        let ps = l.pixel_size;
        let at = |x: f64, y: f64| {
            let (px, py) = l.point(x, y);
            ((px * k).round() as i32, (py * k).round() as i32)
        };
        let lattice = |(x, y): (i32, i32)| at(f64::from(x), f64::from(y));
        let width = |w: f64| ((w * k).round() as u32).max(1);

        area.fill(&WHITE)?;
        // Without grid lines (and, when small, without outline) the pixels need more contrast.
        let fill = if scene.detailed {
            REGION_FILL
        } else {
            PLAIN_REGION_FILL
        };
        for &[x0, x1, y0, y1] in &scene.rects {
            let corners = [lattice((x0, y1)), lattice((x1, y0))];
            area.draw(&Rectangle::new(corners, fill.filled()))?;
        }
        for &[a, b] in &scene.grid {
            stroke_segment(
                area,
                strokes,
                (lattice(a), lattice(b)),
                GRID_LINE,
                width(1.0),
            )?;
        }
        if scene.detailed || ps >= 2.0 {
            let w = width(if scene.detailed { 2.0 } else { 1.0 });
            for contour in &scene.contours {
                stroke_closed(
                    area,
                    strokes,
                    // Lattice corners of drawable regions are far below 2^53: exact in f64.
                    contour.iter().map(|&(x, y)| at(x as f64, y as f64)),
                    OUTLINE,
                    w,
                )?;
            }
        }

        let line_px = if scene.detailed {
            (0.05 * ps).clamp(1.5, 3.0)
        } else {
            (0.25 * ps).clamp(1.0, 2.0)
        };
        for (i, walk) in scene.walks.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            let corners = walk.line.iter().map(|&(x, y)| at(x, y));
            stroke_closed(area, strokes, corners, colour, width(line_px))?;
            if let Some((x, y)) = walk.single {
                let r = width((0.22 * ps).max(3.0));
                area.draw(&Circle::new(
                    at(x, y),
                    r,
                    colour.stroke_width(width(line_px)),
                ))?;
            }
        }
        if scene.detailed && scene.mark_turns {
            // Larger than half the strand gap, so the ring encloses the end of the hairpin.
            let ring = width((0.15 * ps).clamp(4.0, 14.0));
            let ring_line = width((line_px * 0.7).max(1.0));
            for (i, walk) in scene.walks.iter().enumerate() {
                let colour = PALETTE[i % PALETTE.len()];
                for &(x, y) in &walk.u_turns {
                    // Filled first, so the hairpin's end disappears into a clean ring.
                    area.draw(&Circle::new(at(x, y), ring, REGION_FILL.filled()))?;
                    area.draw(&Circle::new(at(x, y), ring, colour.stroke_width(ring_line)))?;
                }
            }
            // Dots last, so that no ring hides a turn.
            let dot = width((0.07 * ps).clamp(2.5, 5.0));
            for (i, walk) in scene.walks.iter().enumerate() {
                let colour = PALETTE[i % PALETTE.len()];
                for &(x, y) in &walk.turns {
                    area.draw(&Circle::new(at(x, y), dot, colour.filled()))?;
                }
            }
        }

        draw_title_and_caption(area, (l.width, l.height), k, scene.title, scene.caption)?;
        area.present()
    }
}

/// The title centred at the top and the caption centred at the bottom of a figure of
/// `size` (width, height) layout pixels, drawn at scale `k`; every figure's.
pub(crate) fn draw_title_and_caption<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    size: (u32, u32),
    k: f64,
    title: Option<&str>,
    caption: Option<&str>,
) -> DrawResult<DB> {
    let centre_x = (f64::from(size.0) / 2.0 * k).round() as i32;
    let font =
        |size: f64| FontDesc::new(FontFamily::from(FONT_FAMILY), size * k, FontStyle::Normal);
    if let Some(title) = title {
        let style = font(TITLE_PX)
            .color(&TITLE_COLOUR)
            .pos(Pos::new(HPos::Center, VPos::Top));
        let y = (MARGIN_PX * k).round() as i32;
        area.draw(&Text::new(title, (centre_x, y), style))?;
    }
    if let Some(caption) = caption {
        let style = font(CAPTION_PX)
            .color(&CAPTION_COLOUR)
            .pos(Pos::new(HPos::Center, VPos::Bottom));
        let y = ((f64::from(size.1) - MARGIN_PX) * k).round() as i32;
        area.draw(&Text::new(caption, (centre_x, y), style))?;
    }
    Ok(())
}

/// A picture drawn by plotters on any backend, written as SVG or PNG by [`write_picture`].
pub(crate) trait Picture {
    /// The canvas, in output pixels.
    fn size(&self) -> (u32, u32);

    /// How many times larger the SVG canvas is drawn (its coordinates are integers).
    fn svg_scale(&self) -> f64 {
        1.0
    }

    /// Draws the picture on `area`, whose size is [`size`](Picture::size) times `k`.
    fn render<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: f64,
        strokes: Strokes,
    ) -> DrawResult<DB>;
}

/// Two pictures side by side, tops aligned: one plotters area each.
struct Beside<A, B>(A, B);

impl<A: Picture, B: Picture> Picture for Beside<A, B> {
    fn size(&self) -> (u32, u32) {
        let ((wl, hl), (wr, hr)) = (self.0.size(), self.1.size());
        (wl + wr, hl.max(hr))
    }

    /// The finer of the two scales, so that both keep whole-number coordinates.
    fn svg_scale(&self) -> f64 {
        self.0.svg_scale().max(self.1.svg_scale())
    }

    fn render<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        k: f64,
        strokes: Strokes,
    ) -> DrawResult<DB> {
        area.fill(&WHITE)?;
        let split = (f64::from(self.0.size().0) * k).round() as i32;
        let (left, right) = area.split_horizontally(split);
        self.0.render(&left, k, strokes)?;
        self.1.render(&right, k, strokes)
    }
}

/// Writes `picture` to `out` in `format`.
pub(crate) fn write_picture(picture: &impl Picture, format: Format, out: &Path) -> Result<()> {
    match format {
        Format::Svg => std::fs::write(out, svg_string(picture)?).map_err(|e| Error::io(out, e)),
        Format::Png => write_png(picture, out),
    }
}

/// The picture as SVG text.
pub(crate) fn svg_string(picture: &impl Picture) -> Result<String> {
    let k = picture.svg_scale();
    let (w, h) = picture.size();
    let size = (w * k as u32, h * k as u32);
    let mut svg = String::new();
    {
        let area = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        picture
            .render(&area, k, Strokes::Polylines)
            .map_err(|e| Error::invalid(format!("drawing failed: {e}")))?;
    }
    Ok(svg)
}

/// Writes a PNG, drawn at up to 3× and scaled down, which smooths the lines and markers
/// (plotters draws shapes without anti-aliasing).
fn write_png(picture: &impl Picture, out: &Path) -> Result<()> {
    let (w, h) = picture.size();
    let (w, h) = (w as usize, h as usize);
    let k = [3, 2, 1]
        .into_iter()
        .find(|k| w * h * k * k <= 16_000_000)
        .unwrap_or(1);
    let (bw, bh) = (w * k, h * k);
    let mut big = vec![0u8; bw * bh * 3];
    {
        let area = BitMapBackend::with_buffer(&mut big, (bw as u32, bh as u32)).into_drawing_area();
        picture
            .render(&area, k as f64, Strokes::Segments)
            .map_err(|e| Error::invalid(format!("drawing failed: {e}")))?;
    }
    let small = if k == 1 {
        big
    } else {
        downsample(&big, w, h, k)
    };
    let mut backend = BitMapBackend::new(out, (w as u32, h as u32));
    backend
        .blit_bitmap((0, 0), (w as u32, h as u32), &small)
        .and_then(|()| backend.present())
        .map_err(|e| Error::io(out, std::io::Error::other(e.to_string())))
}

/// Averages each `k` × `k` block of an RGB image of `w * k` × `h * k` pixels.
pub(crate) fn downsample(big: &[u8], w: usize, h: usize, k: usize) -> Vec<u8> {
    let mut small = vec![0u8; w * h * 3];
    let mut sums = vec![0u32; w * 3];
    for y in 0..h {
        sums.fill(0);
        for row in big[y * k * w * k * 3..(y + 1) * k * w * k * 3].chunks_exact(w * k * 3) {
            for (x, px) in row.chunks_exact(3).enumerate() {
                let s = &mut sums[x / k * 3..x / k * 3 + 3];
                for c in 0..3 {
                    s[c] += u32::from(px[c]);
                }
            }
        }
        let area = (k * k) as u32;
        for (dst, &sum) in small[y * w * 3..(y + 1) * w * 3].iter_mut().zip(&sums) {
            *dst = ((sum + area / 2) / area) as u8;
        }
    }
    small
}

#[cfg(test)]
mod tests;
