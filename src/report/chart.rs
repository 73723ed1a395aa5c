//! The report's charts, drawn as inline SVG from numbers: ratio boxes per family and size
//! band, and scatter plots on linear or logarithmic axes with a hover text per point.
//!
//! Every text that comes from a results folder is escaped ([`esc`]), so a planted family or
//! instance name stays text.

use super::html::esc;
use std::fmt::Write;

/// The colours of series, in order (the Tableau 10 palette).
pub const PALETTE: [&str; 10] = [
    "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1", "#ff9da7",
    "#9c755f", "#bab0ac",
];

/// One row of a box chart: a label and the five numbers it draws. A row from `stats.csv`
/// only has median, p95 and max; it is drawn as a bar from median to p95 and a whisker to max.
#[derive(Clone, Debug)]
pub struct BoxRow {
    pub label: String,
    pub count: usize,
    pub min: Option<f64>,
    pub q1: Option<f64>,
    pub median: f64,
    pub q3: Option<f64>,
    pub p95: Option<f64>,
    pub max: f64,
    pub mean: Option<f64>,
}

/// A horizontal box chart, one row per `rows` entry; `bound` draws a dashed line at a proven
/// factor when it is within the axis.
pub fn boxes(label: &str, rows: &[BoxRow], bound: Option<f64>) -> String {
    let row_h = 18.0;
    let left = 210.0;
    let width = 680.0;
    let plot_w = width - left - 20.0;
    let height = 30.0 + row_h * rows.len() as f64 + 28.0;
    let lo = rows
        .iter()
        .map(|r| r.min.unwrap_or(r.median))
        .fold(f64::INFINITY, f64::min)
        .min(1.0);
    let mut hi = rows.iter().map(|r| r.max).fold(1.0f64, f64::max);
    if let Some(b) = bound.filter(|b| *b <= 2.0 * hi) {
        hi = hi.max(b);
    }
    let hi = if hi - lo < 1e-9 {
        lo + 0.1
    } else {
        hi + 0.03 * (hi - lo)
    };
    let x = |v: f64| left + (v - lo) / (hi - lo) * plot_w;
    let mut s = svg_open(label, width, height);
    axis_ticks(&mut s, lo, hi, false, &|v| x(v), 24.0, height - 26.0);
    if let Some(b) = bound.filter(|b| *b <= hi) {
        let _ = write!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="24" y2="{1:.1}" stroke="#e15759" stroke-dasharray="4 3"><title>proven factor {b}</title></line>"##,
            x(b),
            height - 26.0
        );
    }
    for (i, r) in rows.iter().enumerate() {
        let y = 30.0 + row_h * i as f64 + row_h / 2.0;
        let mut tip = format!("{} ({} rows)\nmedian {:.4}", r.label, r.count, r.median);
        let _ = write!(
            s,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
            left - 6.0,
            y + 4.0,
            esc(&format!("{} ({})", r.label, r.count))
        );
        let _ = write!(s, "<g>");
        let (from, to) = match (r.q1, r.q3) {
            (Some(q1), Some(q3)) => {
                let _ = write!(tip, ", quartiles {q1:.4}–{q3:.4}");
                (q1, q3)
            }
            _ => (r.median, r.p95.unwrap_or(r.median)),
        };
        if let Some(p95) = r.p95 {
            let _ = write!(tip, ", p95 {p95:.4}");
        }
        let _ = write!(tip, ", max {:.4}", r.max);
        if let Some(m) = r.mean {
            let _ = write!(tip, ", mean {m:.4}");
        }
        let wlo = r.min.unwrap_or(r.median);
        let _ = write!(
            s,
            r##"<line x1="{:.1}" x2="{:.1}" y1="{y:.1}" y2="{y:.1}" stroke="#555"/>"##,
            x(wlo),
            x(r.max)
        );
        let _ = write!(
            s,
            r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="#a9c4e2" stroke="#4e79a7"/>"##,
            x(from),
            y - 6.0,
            (x(to) - x(from)).max(1.5),
            12.0
        );
        let _ = write!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{1:.1}" y2="{2:.1}" stroke="#1d2a44" stroke-width="2"/>"##,
            x(r.median),
            y - 7.0,
            y + 7.0
        );
        let _ = write!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{1:.1}" y2="{2:.1}" stroke="#555"/>"##,
            x(r.max),
            y - 4.0,
            y + 4.0
        );
        if let Some(m) = r.mean {
            let _ = write!(
                s,
                r##"<circle cx="{:.1}" cy="{y:.1}" r="2.5" fill="#e15759"/>"##,
                x(m)
            );
        }
        // The hover target: the whole row.
        let _ = write!(
            s,
            r#"<rect x="{left}" y="{:.1}" width="{plot_w}" height="{row_h}" fill="transparent"><title>{}</title></rect></g>"#,
            y - row_h / 2.0,
            esc(&tip)
        );
    }
    s.push_str("</svg>");
    s
}

/// One point of a scatter plot, with its hover text.
#[derive(Clone, Debug)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub tip: String,
}

/// A named series of points, drawn in its own colour, with an optional fitted line
/// `y = c · x^slope` (log-log charts).
#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<Point>,
    pub fit: Option<(f64, f64)>,
}

/// A scatter chart of `series`; `log_x` and `log_y` choose logarithmic axes (points at or below
/// zero are left out of a logarithmic axis).
pub fn scatter(
    label: &str,
    series: &[Series],
    log_x: bool,
    log_y: bool,
    x_name: &str,
    y_name: &str,
) -> String {
    let (width, height) = (500.0, 320.0);
    let (left, right, top, bottom) = (58.0, 140.0, 16.0, 40.0);
    let tx = |v: f64| if log_x { v.log10() } else { v };
    let ty = |v: f64| if log_y { v.log10() } else { v };
    let ok = |p: &Point| {
        (!log_x || p.x > 0.0) && (!log_y || p.y > 0.0) && p.x.is_finite() && p.y.is_finite()
    };
    let pts = || {
        series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|p| ok(p))
    };
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for p in pts() {
        x0 = x0.min(tx(p.x));
        x1 = x1.max(tx(p.x));
        y0 = y0.min(ty(p.y));
        y1 = y1.max(ty(p.y));
    }
    let mut s = svg_open(label, width, height);
    if !x0.is_finite() {
        let _ = write!(s, r#"<text x="20" y="40">no points to draw</text></svg>"#);
        return s;
    }
    let pad = |a: f64, b: f64| {
        if b - a < 1e-9 {
            (a - 0.5, b + 0.5)
        } else {
            (a - 0.04 * (b - a), b + 0.04 * (b - a))
        }
    };
    let (x0, x1) = pad(x0, x1);
    let (y0, y1) = pad(y0, y1);
    let pw = width - left - right;
    let ph = height - top - bottom;
    let px = |v: f64| left + (v - x0) / (x1 - x0) * pw;
    let py = |v: f64| top + ph - (v - y0) / (y1 - y0) * ph;
    axis_ticks(&mut s, x0, x1, log_x, &|v| px(v), top, top + ph);
    y_ticks(&mut s, y0, y1, log_y, &|v| py(v), left, left + pw);
    let _ = write!(
        s,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text><text transform="translate(12 {:.1}) rotate(-90)" text-anchor="middle">{}</text>"#,
        left + pw / 2.0,
        height - 6.0,
        esc(x_name),
        top + ph / 2.0,
        esc(y_name)
    );
    for (i, se) in series.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        if let Some((c, slope)) = se.fit {
            // The fitted line over the series' own x range.
            let xs: Vec<f64> = se.points.iter().filter(|p| ok(p)).map(|p| p.x).collect();
            let (a, b) = xs
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
            if a.is_finite() && a > 0.0 && c > 0.0 {
                let f = |v: f64| c * v.powf(slope);
                let _ = write!(
                    s,
                    r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-dasharray="5 3"/>"#,
                    px(tx(a)),
                    py(ty(f(a))),
                    px(tx(b)),
                    py(ty(f(b)))
                );
            }
        }
        for p in se.points.iter().filter(|p| ok(p)) {
            let _ = write!(
                s,
                r#"<circle cx="{:.1}" cy="{:.1}" r="3.2" fill="{colour}" fill-opacity="0.8"><title>{}</title></circle>"#,
                px(tx(p.x)),
                py(ty(p.y)),
                esc(&p.tip)
            );
        }
        let ly = top + 12.0 + 15.0 * i as f64;
        if ly < height - bottom {
            let name = match se.fit {
                Some((_, slope)) => format!("{} (n^{slope:.2})", se.name),
                None => se.name.clone(),
            };
            let _ = write!(
                s,
                r#"<circle cx="{:.1}" cy="{:.1}" r="4" fill="{colour}"/><text x="{:.1}" y="{:.1}">{}</text>"#,
                left + pw + 12.0,
                ly - 4.0,
                left + pw + 20.0,
                ly,
                esc(&truncate(&name, 22))
            );
        }
    }
    s.push_str("</svg>");
    s
}

/// The least-squares line through `(log x, log y)` of the points with both positive:
/// `(c, slope)` with `y ≈ c · x^slope`; `None` for fewer than two distinct x.
pub fn fit_power(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    let n = logs.len() as f64;
    if logs.len() < 2 {
        return None;
    }
    let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
    let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx < 1e-12 {
        return None;
    }
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let slope = sxy / sxx;
    Some(((my - slope * mx).exp(), slope))
}

fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        format!("{}…", s.chars().take(n - 1).collect::<String>())
    }
}

fn svg_open(label: &str, width: f64, height: f64) -> String {
    format!(
        r#"<svg class="chart" role="img" aria-label="{}" xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#,
        esc(label)
    )
}

/// Round tick values between `lo` and `hi` (in axis units: log10 on a logarithmic axis).
fn ticks(lo: f64, hi: f64, log: bool) -> Vec<(f64, String)> {
    if log {
        let (a, b) = (lo.ceil() as i64, hi.floor() as i64);
        return (a..=b)
            .map(|e| {
                (
                    e as f64,
                    if (-3..=4).contains(&e) {
                        format!("{}", 10f64.powi(e as i32))
                    } else {
                        format!("1e{e}")
                    },
                )
            })
            .collect();
    }
    let span = hi - lo;
    let raw = span / 5.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| span / s <= 6.0)
        .unwrap_or(10.0 * mag);
    let mut v = (lo / step).ceil() * step;
    let mut out = Vec::new();
    while v <= hi + 1e-12 && out.len() < 12 {
        out.push((v, format!("{}", (v * 1e6).round() / 1e6)));
        v += step;
    }
    out
}

fn axis_ticks(
    s: &mut String,
    lo: f64,
    hi: f64,
    log: bool,
    x: &dyn Fn(f64) -> f64,
    top: f64,
    bottom: f64,
) {
    let _ = write!(
        s,
        r##"<line x1="{:.1}" x2="{:.1}" y1="{bottom:.1}" y2="{bottom:.1}" stroke="#888"/>"##,
        x(lo),
        x(hi)
    );
    for (v, text) in ticks(lo, hi, log) {
        let _ = write!(
            s,
            r##"<line x1="{0:.1}" x2="{0:.1}" y1="{top:.1}" y2="{bottom:.1}" stroke="#eceff4"/><text x="{0:.1}" y="{1:.1}" text-anchor="middle">{2}</text>"##,
            x(v),
            bottom + 14.0,
            esc(&text)
        );
    }
}

fn y_ticks(
    s: &mut String,
    lo: f64,
    hi: f64,
    log: bool,
    y: &dyn Fn(f64) -> f64,
    left: f64,
    right: f64,
) {
    let _ = write!(
        s,
        r##"<line x1="{left:.1}" x2="{left:.1}" y1="{:.1}" y2="{:.1}" stroke="#888"/>"##,
        y(lo),
        y(hi)
    );
    for (v, text) in ticks(lo, hi, log) {
        let _ = write!(
            s,
            r##"<line x1="{left:.1}" x2="{right:.1}" y1="{0:.1}" y2="{0:.1}" stroke="#eceff4"/><text x="{1:.1}" y="{2:.1}" text-anchor="end">{3}</text>"##,
            y(v),
            left - 4.0,
            y(v) + 4.0,
            esc(&text)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_the_exponent_of_a_power_law() {
        let pts: Vec<(f64, f64)> = [10.0, 100.0, 1000.0, 1e4]
            .iter()
            .map(|&x| (x, 3.0 * x * x))
            .collect();
        let (c, slope) = fit_power(&pts).unwrap();
        assert!((slope - 2.0).abs() < 1e-9, "{slope}");
        assert!((c - 3.0).abs() < 1e-6, "{c}");
        assert_eq!(fit_power(&[(5.0, 1.0), (5.0, 2.0)]), None);
    }

    #[test]
    fn escapes_labels_and_tips() {
        let s = scatter(
            "<x>",
            &[Series {
                name: "<b>".into(),
                points: vec![Point {
                    x: 1.0,
                    y: 2.0,
                    tip: "<script>".into(),
                }],
                fit: None,
            }],
            false,
            false,
            "n",
            "r",
        );
        assert!(!s.contains("<script>") && !s.contains("<b>") && s.contains("&lt;script&gt;"));
    }
}
