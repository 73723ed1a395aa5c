//! The figures of `mowmill tight`, as SVG and PNG under `OUT/figures/`:
//! - `<family>_<member>`: the member drawn twice side by side, the algorithm's walk on the
//!   left and the optimal walk on the right (turns marked by [`draw`]);
//! - `ratio_<family>`: each measured ratio against the family parameter, with the limit the
//!   paper claims drawn as a dashed line.

use super::{Member, TightRun};
use crate::draw::{DrawOptions, FONT_FAMILY, draw, ensure_fonts};
use crate::error::{Error, Result};
use crate::harness::plots::{Figure, colour, file_safe, plot_err, render};
use crate::region::{Pixel, Region};
use crate::tour::CycleCover;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;

/// The members drawn side by side: (family, member).
pub(crate) const DRAWN: [(&str, &str); 7] = [
    ("donut", "k=2 L=8"),
    ("donut", "k=3 L=12"),
    ("donut", "k=4 L=12"),
    ("band", "k=3"),
    ("band", "k=8"),
    ("thin43", "s=0"),
    ("thin43", "s=2"),
];

/// The limit each family's ratios tend to, as the paper claims: (family, quantity, limit).
pub(crate) const LIMITS: [(&str, &str, f64, &str); 5] = [
    ("donut", "ratio_naive", 3.0, "3 (naive tour / OPT)"),
    ("donut", "ratio_cc", 2.0, "2 (cycle cover / OPT cc)"),
    ("band", "ratio_opt_n", 1.2, "6/5 (OPT / N)"),
    (
        "thin43",
        "ratio_gadget_naive",
        4.0 / 3.0,
        "4/3 (merge / OPT)",
    ),
    ("donut", "ratio_crossing", 3.0, "3 (crossing merges / OPT)"),
];

/// Draws `left` and `right` over two copies of `region`, side by side, into `out`.
pub(crate) fn side_by_side(
    region: &Region,
    left: &CycleCover,
    right: &CycleCover,
    title: &str,
    caption: &str,
    out: &Path,
) -> Result<()> {
    let b = region.bbox();
    let shift = b.width() as i32 + 3;
    let moved = |p: &Pixel| Pixel::new(p.x + shift, p.y);
    let pixels: Vec<Pixel> = region
        .pixels()
        .iter()
        .copied()
        .chain(region.pixels().iter().map(moved))
        .collect();
    let both = Region::from_pixels(pixels)?;
    let mut cycles = left.cycles.clone();
    cycles.extend(
        right
            .cycles
            .iter()
            .map(|w| w.iter().map(moved).collect::<Vec<_>>()),
    );
    let opts = DrawOptions {
        title: Some(title.to_string()),
        caption: Some(caption.to_string()),
        ..DrawOptions::default()
    };
    draw(&both, Some(&CycleCover::new(cycles)), out, &opts)
}

/// Draws one member's pair of walks (if it has two) as `figures/<family>_<member>.{svg,png}`.
fn draw_member(m: &Member, dir: &Path) -> Result<()> {
    let [(l_label, left), (r_label, right)] = &m.drawings[..] else {
        return Ok(());
    };
    let stem = dir.join(format!("{}_{}", m.family, file_safe(&m.member)));
    let title = format!("{} {} (N = {})", m.family, m.member, m.region.len());
    let caption = format!("left: {l_label}   |   right: {r_label}");
    for ext in ["svg", "png"] {
        side_by_side(
            &m.region,
            left,
            right,
            &title,
            &caption,
            &stem.with_extension(ext),
        )?;
    }
    Ok(())
}

/// One family's ratios against its parameter.
struct RatioPlot<'a> {
    family: &'a str,
    /// Series name → points (parameter, ratio).
    series: BTreeMap<String, Vec<(f64, f64)>>,
    limits: Vec<(f64, &'a str)>,
}

impl Figure for RatioPlot<'_> {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        let pts = self.series.values().flatten();
        let x_hi = pts.clone().map(|p| p.0).fold(1.0, f64::max);
        let x_lo = pts.clone().map(|p| p.0).fold(x_hi, f64::min);
        let y_hi = pts
            .clone()
            .map(|p| p.1)
            .chain(self.limits.iter().map(|l| l.0))
            .fold(1.0, f64::max)
            * 1.08;
        let y_lo = pts.map(|p| p.1).fold(1.0, f64::min).min(1.0) * 0.95;
        let x_name = if self.family == "thin43" { "s" } else { "k" };
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!("{}: measured ratios against {x_name}", self.family),
                (FONT_FAMILY, 24),
            )
            .margin(16)
            .x_label_area_size(50)
            .y_label_area_size(60)
            .build_cartesian_2d(x_lo - 0.5..x_hi + 0.5, y_lo..y_hi)
            .map_err(plot_err)?;
        let ticks = (x_hi - x_lo) as usize + 1;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_labels(ticks.min(16))
            .x_label_formatter(&|x| {
                if (x - x.round()).abs() < 1e-9 {
                    format!("{}", x.round() as i64)
                } else {
                    String::new()
                }
            })
            .x_desc(x_name)
            .y_desc("ratio")
            .label_style((FONT_FAMILY, 15))
            .axis_desc_style((FONT_FAMILY, 17))
            .draw()
            .map_err(plot_err)?;
        for (i, (name, points)) in self.series.iter().enumerate() {
            let c = colour(i);
            chart
                .draw_series(LineSeries::new(points.iter().copied(), c.stroke_width(2)))
                .map_err(plot_err)?
                .label(name.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 4, c.filled())))
                .map_err(plot_err)?;
        }
        for (j, &(limit, label)) in self.limits.iter().enumerate() {
            let c = RGBColor(90, 90, 90);
            let dashes: Vec<(f64, f64)> = {
                let steps = 60;
                let w = (x_hi - x_lo + 1.0) / steps as f64;
                (0..steps)
                    .step_by(2)
                    .flat_map(|i| {
                        let a = x_lo - 0.5 + i as f64 * w;
                        [(a, limit), (a + w, limit)]
                    })
                    .collect()
            };
            for seg in dashes.chunks(2) {
                chart
                    .draw_series(LineSeries::new(seg.iter().copied(), c.stroke_width(1)))
                    .map_err(plot_err)?;
            }
            chart
                .draw_series(std::iter::once(Text::new(
                    format!("limit {label}"),
                    (
                        x_lo - 0.3,
                        limit + (y_hi - y_lo) * (0.015 + 0.04 * j as f64),
                    ),
                    (FONT_FAMILY, 14).into_font().color(&c),
                )))
                .map_err(plot_err)?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT_FAMILY, 14))
            .draw()
            .map_err(plot_err)?;
        Ok(())
    }
}

/// The series of one family: every `ratio_*` quantity; donuts split by L/k.
fn ratio_series(run: &TightRun, family: &str) -> BTreeMap<String, Vec<(f64, f64)>> {
    let mut series: BTreeMap<String, Vec<(f64, f64)>> = BTreeMap::new();
    for r in run.rows().filter(|r| r.family == family) {
        let (Some(v), true) = (r.measured, r.quantity.starts_with("ratio_")) else {
            continue;
        };
        let mut name = r.quantity.trim_start_matches("ratio_").to_string();
        if family == "donut"
            && let Some(l) = r
                .member
                .split("L=")
                .nth(1)
                .and_then(|l| l.parse::<u64>().ok())
            && r.param > 0
        {
            name = format!("{name}, L = {}k", l / r.param);
        }
        series.entry(name).or_default().push((r.param as f64, v));
    }
    for points in series.values_mut() {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    series
}

/// Draws every figure of a run into `out/figures/`.
pub fn draw_all(run: &TightRun, out: &Path) -> Result<()> {
    ensure_fonts();
    let dir = out.join("figures");
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    for m in &run.members {
        if DRAWN.contains(&(m.family, m.member.as_str())) {
            draw_member(m, &dir)?;
        }
    }
    for family in ["donut", "band", "thin43"] {
        let series = ratio_series(run, family);
        if series.is_empty() {
            continue;
        }
        let limits = LIMITS
            .iter()
            .filter(|l| l.0 == family)
            .map(|l| (l.2, l.3))
            .collect();
        render(
            &dir.join(format!("ratio_{family}")),
            (900, 600),
            &RatioPlot {
                family,
                series,
                limits,
            },
        )?;
    }
    Ok(())
}
