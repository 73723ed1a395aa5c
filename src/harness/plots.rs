//! Plots of a run, drawn from its rows alone (so `mowmill plot DIR` can redraw them from
//! `results.csv`), each as PNG and SVG under `DIR/plots/`:
//!
//! - `ratio-vs-n_<algorithm>_<objective>`: the ratio of every result against N, one colour per
//!   family, with the guarantee drawn as a line (a constant factor against OPT, or the curve
//!   (num·N + add)/(den·N) for bounds against N);
//! - `ratio-dist_<objective>`: the distribution of the ratio per algorithm and family (box and
//!   whiskers: quartiles, 5th and 95th percentiles, and the maximum as a cross);
//! - `exact-time`: exact solve time against N on a log scale, one colour per objective, time-outs
//!   drawn hollow.
//!
//! Which ratio a plot shows: against N for guarantees in N, else against the proven optimum
//! where every row has one, else against the best lower bound (axis labels say which).

use super::rows::{EXACT, Row};
use crate::algorithms::{self, Against, Guarantee, Quantity};
use crate::draw::PALETTE;
use crate::draw::{FONT_FAMILY, ensure_fonts};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;

/// The `k`-th series colour (the walk palette of the figures, cycled).
pub(crate) fn colour(k: usize) -> RGBColor {
    PALETTE[k % PALETTE.len()]
}

/// Which ratio of a row a plot shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Opt,
    Lb,
    N,
}

impl Kind {
    fn of(self, r: &Row) -> Option<f64> {
        match self {
            Kind::Opt => r.ratio_opt.map(|x| x.0),
            Kind::Lb => r.ratio_lb.map(|x| x.0),
            Kind::N => r.ratio_n.map(|x| x.0),
        }
    }

    fn label(self, objective: &str) -> String {
        match self {
            Kind::Opt => format!("{objective} / OPT"),
            Kind::Lb => format!("{objective} / lower bound"),
            Kind::N => format!("{objective} / N"),
        }
    }

    /// The ratio to show for a group of rows of one algorithm and objective.
    fn choose(rows: &[&Row], guarantee: Option<&Guarantee>) -> Kind {
        if guarantee.is_some_and(|g| g.bound.against == Against::N) {
            Kind::N
        } else if !rows.is_empty() && rows.iter().all(|r| r.ratio_opt.is_some()) {
            Kind::Opt
        } else if rows.iter().any(|r| r.ratio_lb.is_some()) {
            Kind::Lb
        } else {
            Kind::N
        }
    }
}

pub(crate) fn file_safe(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

pub(crate) fn plot_err<E: std::fmt::Display>(e: E) -> Error {
    Error::invalid(format!("plot: {e}"))
}

/// Draws every plot of a run into `out/plots/`.
pub fn draw_all(out: &Path, rows: &[Row]) -> Result<()> {
    ensure_fonts();
    let dir = out.join("plots");
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    let ok: Vec<&Row> = rows.iter().filter(|r| r.error.is_empty()).collect();
    let mut by_algo: BTreeMap<(&str, &str), Vec<&Row>> = BTreeMap::new();
    for r in ok
        .iter()
        .filter(|r| r.algorithm != EXACT && r.algorithm != "instance")
    {
        by_algo
            .entry((r.algorithm.as_str(), r.objective.as_str()))
            .or_default()
            .push(r);
    }
    for ((algo, objective), group) in &by_algo {
        let guarantee = algorithms::find(algo).and_then(|a| {
            a.guarantees
                .iter()
                .find(|g| g.objective.name() == *objective && g.bound.quantity == Quantity::Value)
        });
        let stem = dir.join(format!(
            "ratio-vs-n_{}_{}",
            file_safe(algo),
            file_safe(objective)
        ));
        render(
            &stem,
            (900, 600),
            &RatioVsN {
                algo,
                objective,
                rows: group,
                guarantee,
            },
        )?;
    }
    let mut by_objective: BTreeMap<&str, Vec<&Row>> = BTreeMap::new();
    for r in ok
        .iter()
        .filter(|r| r.algorithm != EXACT && r.algorithm != "instance")
    {
        by_objective
            .entry(r.objective.as_str())
            .or_default()
            .push(r);
    }
    for (objective, group) in &by_objective {
        let stem = dir.join(format!("ratio-dist_{}", file_safe(objective)));
        let groups = distribution_groups(group).1.len() as u32;
        render(
            &stem,
            (1000, 140 + 30 * groups.max(3)),
            &RatioDist {
                objective,
                rows: group,
            },
        )?;
    }
    let exact: Vec<&Row> = ok.into_iter().filter(|r| r.algorithm == EXACT).collect();
    if !exact.is_empty() {
        render(
            &dir.join("exact-time"),
            (900, 600),
            &ExactTime { rows: &exact },
        )?;
    }
    Ok(())
}

/// A plot that can be drawn on any plotters backend (SVG and PNG share one routine).
pub(crate) trait Figure {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()>;
}

/// Draws a figure to `stem.png` and `stem.svg`.
pub(crate) fn render(stem: &Path, size: (u32, u32), figure: &impl Figure) -> Result<()> {
    let svg = stem.with_extension("svg");
    {
        let area = SVGBackend::new(&svg, size).into_drawing_area();
        area.fill(&WHITE).map_err(plot_err)?;
        figure.draw(&area)?;
        area.present().map_err(plot_err)?;
    }
    let png = stem.with_extension("png");
    let area = BitMapBackend::new(&png, size).into_drawing_area();
    area.fill(&WHITE).map_err(plot_err)?;
    figure.draw(&area)?;
    area.present().map_err(plot_err)
}

struct RatioVsN<'a> {
    algo: &'a str,
    objective: &'a str,
    rows: &'a [&'a Row],
    guarantee: Option<&'a Guarantee>,
}

impl Figure for RatioVsN<'_> {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        ratio_vs_n(area, self.algo, self.objective, self.rows, self.guarantee)
    }
}

struct RatioDist<'a> {
    objective: &'a str,
    rows: &'a [&'a Row],
}

impl Figure for RatioDist<'_> {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        ratio_distribution(area, self.objective, self.rows)
    }
}

struct ExactTime<'a> {
    rows: &'a [&'a Row],
}

impl Figure for ExactTime<'_> {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        exact_time(area, self.rows)
    }
}

fn ratio_vs_n<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    algo: &str,
    objective: &str,
    rows: &[&Row],
    g: Option<&Guarantee>,
) -> Result<()> {
    let kind = Kind::choose(rows, g);
    let pts: Vec<(&str, f64, f64)> = rows
        .iter()
        .filter_map(|r| kind.of(r).map(|y| (r.family.as_str(), r.n as f64, y)))
        .collect();
    let max_n = pts.iter().map(|p| p.1).fold(1.0, f64::max) * 1.05;
    let min_n = pts.iter().map(|p| p.1).fold(max_n, f64::min).min(max_n) * 0.95;
    let g_at = |n: f64| {
        g.and_then(|g| match g.bound.against {
            Against::Opt => Some(g.factor()),
            Against::N => {
                Some((g.bound.num as f64 * n + g.bound.add as f64) / (g.bound.den as f64 * n))
            }
            Against::One => None,
        })
    };
    // Head room above the guarantee line for the legend.
    let y_hi = pts
        .iter()
        .map(|p| p.2)
        .chain(g_at(max_n))
        .fold(1.0, f64::max)
        * 1.25;
    let y_lo = pts.iter().map(|p| p.2).fold(1.0, f64::min).min(1.0) * 0.97;
    let mut chart = ChartBuilder::on(area)
        .caption(
            format!("{algo}: {}", kind.label(objective)),
            (FONT_FAMILY, 26),
        )
        .margin(16)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(min_n..max_n, y_lo..y_hi)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .x_desc("N (pixels)")
        .y_desc(kind.label(objective))
        .label_style((FONT_FAMILY, 16))
        .axis_desc_style((FONT_FAMILY, 18))
        .draw()
        .map_err(plot_err)?;
    let families: Vec<&str> = {
        let mut f: Vec<&str> = pts.iter().map(|p| p.0).collect();
        f.sort_unstable();
        f.dedup();
        f
    };
    for (k, fam) in families.iter().enumerate() {
        let c = colour(k);
        chart
            .draw_series(
                pts.iter()
                    .filter(|p| p.0 == *fam)
                    .map(|p| Circle::new((p.1, p.2), 4, c.filled())),
            )
            .map_err(plot_err)?
            .label(*fam)
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
    }
    if let Some(gg) = g {
        let steps = 200;
        let line: Vec<(f64, f64)> = (0..=steps)
            .map(|i| {
                let n = min_n + (max_n - min_n) * i as f64 / steps as f64;
                (n, g_at(n.max(1.0)).unwrap_or(0.0))
            })
            .collect();
        chart
            .draw_series(LineSeries::new(line, BLACK.stroke_width(2)))
            .map_err(plot_err)?
            .label(format!("guarantee: {}", gg))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT_FAMILY, 15))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(plot_err)
}

/// The groups of a distribution figure: (label, sorted ratios), and the ratio shown.
fn distribution_groups(rows: &[&Row]) -> (Kind, Vec<(String, Vec<f64>)>) {
    let mut groups: BTreeMap<(String, String), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        groups
            .entry((r.algorithm.clone(), r.family.clone()))
            .or_default()
            .push(r);
    }
    // One ratio kind for the whole figure so that boxes are comparable.
    let kind = if rows.iter().all(|r| r.ratio_opt.is_some()) {
        Kind::Opt
    } else if rows.iter().all(|r| r.ratio_lb.is_some()) {
        Kind::Lb
    } else {
        Kind::N
    };
    let boxes = groups
        .into_iter()
        .map(|((a, f), rs)| {
            let mut v: Vec<f64> = rs.iter().filter_map(|r| kind.of(r)).collect();
            v.sort_by(f64::total_cmp);
            (format!("{a} / {f} ({})", v.len()), v)
        })
        .filter(|(_, v)| !v.is_empty())
        .collect();
    (kind, boxes)
}

/// Horizontal box plots, one row per (algorithm, family), labelled on the left.
fn ratio_distribution<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    objective: &str,
    rows: &[&Row],
) -> Result<()> {
    let (kind, boxes) = distribution_groups(rows);
    let x_hi = boxes
        .iter()
        .flat_map(|b| b.1.iter().copied())
        .fold(1.0, f64::max)
        * 1.05;
    let x_lo = boxes
        .iter()
        .flat_map(|b| b.1.iter().copied())
        .fold(1.0, f64::min)
        .min(1.0)
        * 0.98;
    let count = boxes.len().max(1);
    let mut chart = ChartBuilder::on(area)
        .caption(
            format!("Distribution of {}", kind.label(objective)),
            (FONT_FAMILY, 24),
        )
        .margin(16)
        .x_label_area_size(50)
        .y_label_area_size(300)
        .build_cartesian_2d(x_lo..x_hi, -0.5f64..(count as f64 - 0.5))
        .map_err(plot_err)?;
    let labels: Vec<String> = boxes.iter().map(|b| b.0.clone()).collect();
    chart
        .configure_mesh()
        .disable_y_mesh()
        .light_line_style(WHITE)
        .y_labels(count)
        .y_label_formatter(&|y| {
            let k = y.round();
            if (y - k).abs() < 1e-6 && k >= 0.0 && (k as usize) < labels.len() {
                labels[labels.len() - 1 - k as usize].clone()
            } else {
                String::new()
            }
        })
        .x_desc(kind.label(objective))
        .label_style((FONT_FAMILY, 15))
        .axis_desc_style((FONT_FAMILY, 17))
        .draw()
        .map_err(plot_err)?;
    let q = |v: &[f64], p: f64| v[((p * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1];
    for (k, (_, v)) in boxes.iter().enumerate() {
        // The first group is drawn at the top.
        let y = (count - 1 - k) as f64;
        let c = colour(k);
        let (p5, q1, med, q3, p95, max) = (
            q(v, 0.05),
            q(v, 0.25),
            q(v, 0.5),
            q(v, 0.75),
            q(v, 0.95),
            v[v.len() - 1],
        );
        let h = 0.3;
        chart
            .draw_series([Rectangle::new(
                [(q1, y - h), (q3, y + h)],
                c.mix(0.35).filled(),
            )])
            .map_err(plot_err)?;
        chart
            .draw_series([Rectangle::new(
                [(q1, y - h), (q3, y + h)],
                c.stroke_width(2),
            )])
            .map_err(plot_err)?;
        chart
            .draw_series([
                PathElement::new(vec![(med, y - h), (med, y + h)], BLACK.stroke_width(2)),
                PathElement::new(vec![(q3, y), (p95, y)], c.stroke_width(1)),
                PathElement::new(vec![(p5, y), (q1, y)], c.stroke_width(1)),
                PathElement::new(
                    vec![(p95, y - h / 2.0), (p95, y + h / 2.0)],
                    c.stroke_width(1),
                ),
                PathElement::new(
                    vec![(p5, y - h / 2.0), (p5, y + h / 2.0)],
                    c.stroke_width(1),
                ),
            ])
            .map_err(plot_err)?;
        chart
            .draw_series([Cross::new((max, y), 5, BLACK.stroke_width(1))])
            .map_err(plot_err)?;
    }
    Ok(())
}

fn exact_time<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, rows: &[&Row]) -> Result<()> {
    let pts: Vec<(&str, f64, f64, bool)> = rows
        .iter()
        .map(|r| {
            (
                r.objective.as_str(),
                r.n as f64,
                r.seconds.max(1e-3),
                r.opt_status == "optimal",
            )
        })
        .collect();
    let max_n = pts.iter().map(|p| p.1).fold(1.0, f64::max) * 1.05;
    // Head room for the legend above the slowest solve.
    let max_t = pts.iter().map(|p| p.2).fold(1.0, f64::max) * 30.0;
    let mut chart = ChartBuilder::on(area)
        .caption(
            "Exact solve time (one thread per solve; hollow: not proven optimal)",
            (FONT_FAMILY, 22),
        )
        .margin(16)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..max_n, (1e-3f64..max_t).log_scale())
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .x_desc("N (pixels)")
        .y_desc("seconds (log scale)")
        .label_style((FONT_FAMILY, 16))
        .axis_desc_style((FONT_FAMILY, 18))
        .draw()
        .map_err(plot_err)?;
    let mut objectives: Vec<&str> = pts.iter().map(|p| p.0).collect();
    objectives.sort_unstable();
    objectives.dedup();
    for (k, o) in objectives.iter().enumerate() {
        let c = colour(k);
        chart
            .draw_series(pts.iter().filter(|p| p.0 == *o).map(|p| {
                let style = if p.3 { c.filled() } else { c.stroke_width(2) };
                Circle::new((p.1, p.2), 4, style)
            }))
            .map_err(plot_err)?
            .label(o.to_string())
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT_FAMILY, 15))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(plot_err)
}
