//! Deterministic random orthogonal polygons with non-integral coordinates (the
//! ortho generators): perturbed integer polygons, thin slivers, and polygons with a feature narrower
//! than the cutter.
//!
//! Every generator is a function of its family, size and seed only (ChaCha8 streams of
//! [`crate::generate::rng`], exact rational coordinates, no platform-dependent floats in the
//! output). The families:
//!
//! - `ortho-perturbed`, `ortho-holed`: a `random-simple` (resp. `random-holed`) region of `n`
//!   pixels, its polygon ([`Polygon::from_region`]), and every edge of every ring moved along
//!   its normal by k/8 with |k| ≤ 3. Draws that break validity (edges crossing) or feasibility
//!   ([`feasibility`]) are retried, with offsets limited to ±1/8 after a few attempts and,
//!   failing that, moved outward only (the polygon grows, its holes shrink); at least one
//!   offset is non-zero. Always feasible.
//! - `ortho-sliver`: a corridor of width w = 1 + a/b (0 < a < b ≤ 10) around a rectilinear
//!   path of `n` segments (a staircase, a square wave or a serpentine), segment lengths
//!   w + ½ + k/8. Always feasible: its erosion is the path's corridor of width w − 1.
//! - `ortho-narrow`: two rectangles joined by a neck of width s < 1, or a rectangle with a
//!   spike of width s < 1; sizes grow with `n`. Always infeasible: no unit square inside the
//!   polygon covers a point in the middle of the neck or spike, and [`feasibility`] says so.

use super::erosion::feasibility;
use super::polygon::{Point, Polygon, Ring};
use super::rational::Rational;
use crate::error::{Error, Result};
use crate::generate::rng::{Rng, below, rng_for};
use crate::generate::{Family, GenParams};

/// The families of [`generate`].
pub const FAMILIES: &[&str] = &[
    "ortho-perturbed",
    "ortho-holed",
    "ortho-sliver",
    "ortho-narrow",
];

/// Generates one polygon of `family` (one of [`FAMILIES`]) of size `n` (pixels for the
/// perturbed families, segments for slivers, the scale of the rectangles for narrow ones).
///
/// # Errors
/// [`Error::Invalid`] for an unknown family or n = 0 (or n above 10,000); whatever the
/// region generators refuse.
///
/// # Examples
/// ```
/// use mowmill_core::ortho::{feasibility, generate};
/// let p = generate("ortho-sliver", 3, 7)?;
/// assert!(feasibility(&p).is_ok());
/// assert!(feasibility(&generate("ortho-narrow", 3, 7)?).is_err());
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn generate(family: &str, n: usize, seed: u64) -> Result<Polygon> {
    if n == 0 || n > 10_000 {
        return Err(Error::invalid(format!("n = {n}; expected from 1 to 10000")));
    }
    match family {
        "ortho-perturbed" => perturbed(Family::RandomSimple, n, seed),
        "ortho-holed" => perturbed(Family::RandomHoled, n, seed),
        "ortho-sliver" => sliver(n, seed),
        "ortho-narrow" => narrow(n, seed).map(|(p, _)| p),
        _ => Err(Error::invalid(format!(
            "unknown orthogonal family {family}: expected one of {}",
            FAMILIES.join(", ")
        ))),
    }
}

/// p/q, for the small values the generators make.
fn q(p: i128, q: i128) -> Rational {
    Rational::new(p, q).expect("a small fraction")
}

fn add(a: Rational, b: Rational) -> Rational {
    a.checked_add(b).expect("small coordinates")
}

fn sub(a: Rational, b: Rational) -> Rational {
    a.checked_sub(b).expect("small coordinates")
}

fn mul(a: Rational, b: Rational) -> Rational {
    a.checked_mul(b).expect("small coordinates")
}

/// WKT of rings grouped by polygon, the outer ring of each first.
fn rings_wkt(rings: &[Ring]) -> String {
    let ring_text = |r: &Ring| {
        let points: Vec<String> = r
            .corners
            .iter()
            .chain(r.corners.first())
            .map(|p| format!("{} {}", p.x, p.y))
            .collect();
        format!("({})", points.join(", "))
    };
    let count = rings.iter().map(|r| r.polygon + 1).max().unwrap_or(0);
    let polygons: Vec<String> = (0..count)
        .map(|k| {
            let mut group: Vec<&Ring> = rings.iter().filter(|r| r.polygon == k).collect();
            group.sort_by_key(|r| r.hole);
            let texts: Vec<String> = group.into_iter().map(ring_text).collect();
            format!("({})", texts.join(", "))
        })
        .collect();
    if polygons.len() == 1 {
        format!("POLYGON {}", polygons[0])
    } else {
        format!("MULTIPOLYGON ({})", polygons.join(", "))
    }
}

fn polygon_of(corners: &[Point]) -> Result<Polygon> {
    let ring = Ring {
        corners: corners.to_vec(),
        polygon: 0,
        hole: false,
    };
    Polygon::parse(&rings_wkt(&[ring]), "generated")
}

/// Twice the signed area of a ring (positive when counter-clockwise).
fn orientation(corners: &[Point]) -> bool {
    let mut sum = Rational::ZERO;
    for (i, a) in corners.iter().enumerate() {
        let b = corners[(i + 1) % corners.len()];
        sum = add(sum, sub(mul(a.x, b.y), mul(b.x, a.y)));
    }
    sum > Rational::ZERO
}

/// `ortho-perturbed` and `ortho-holed`.
fn perturbed(family: Family, n: usize, seed: u64) -> Result<Polygon> {
    let mut params = GenParams::new(family, seed);
    params.n = Some(n.max(4));
    if family == Family::RandomHoled {
        params.n = Some(n.max(9));
        params.holes = Some((n / 40).clamp(1, 3));
    }
    let region = crate::generate::generate(&params)?.region;
    let base = Polygon::from_region(&region)?;
    let mut rng = rng_for(seed, 0x0_5e57);
    for attempt in 0..24 {
        let amplitude = if attempt < 8 { 3 } else { 1 };
        let outward_only = attempt >= 16;
        let Some(candidate) = perturb(&base, &mut rng, amplitude, outward_only) else {
            continue;
        };
        if feasibility(&candidate).is_ok() {
            return Ok(candidate);
        }
    }
    Err(Error::invalid(format!(
        "no feasible perturbation of the {} region of seed {seed} in 24 attempts",
        family.name()
    )))
}

/// Moves every edge of every ring of `base` by k/8, |k| ≤ `amplitude`, along its normal;
/// `None` if the result is not a valid polygon or nothing moved.
fn perturb(base: &Polygon, rng: &mut Rng, amplitude: usize, outward_only: bool) -> Option<Polygon> {
    let mut moved = false;
    let rings: Vec<Ring> = base
        .rings()
        .iter()
        .map(|ring| {
            let m = ring.corners.len();
            let ccw = orientation(&ring.corners);
            // Edge i runs from corner i to corner i + 1.
            let offsets: Vec<Rational> = (0..m)
                .map(|i| {
                    let (a, b) = (ring.corners[i], ring.corners[(i + 1) % m]);
                    let k = if outward_only {
                        below(rng, amplitude + 1) as i128
                    } else {
                        below(rng, 2 * amplitude + 1) as i128 - amplitude as i128
                    };
                    moved |= k != 0;
                    // Outward from the polygon: right of the edge for a counter-clockwise outer
                    // ring, left for a clockwise one; a hole's outside is the polygon.
                    let right_is_out = ccw != ring.hole;
                    // The right normal of heading (dx, dy) is (dy, −dx); its non-zero
                    // component is the one the edge moves along.
                    let sign = |u: Rational, v: Rational| if v > u { 1 } else { -1 };
                    let right = if a.y == b.y {
                        -sign(a.x, b.x)
                    } else {
                        sign(a.y, b.y)
                    };
                    let out_sign = if right_is_out { right } else { -right };
                    q(out_sign * k, 8)
                })
                .collect();
            let corners = (0..m)
                .map(|i| {
                    // Corner i joins edge i − 1 and edge i: one horizontal, one vertical.
                    let (before, after) = ((i + m - 1) % m, i);
                    let (a, b) = (ring.corners[i], ring.corners[(i + 1) % m]);
                    let (dx, dy) = if a.y == b.y {
                        (offsets[before], offsets[after])
                    } else {
                        (offsets[after], offsets[before])
                    };
                    Point::new(add(a.x, dx), add(a.y, dy))
                })
                .collect();
            Ring {
                corners,
                polygon: ring.polygon,
                hole: ring.hole,
            }
        })
        .collect();
    if !moved {
        return None;
    }
    Polygon::parse(&rings_wkt(&rings), "perturbed").ok()
}

/// A random rational in [lo, lo + span/8], in eighths.
fn eighths(rng: &mut Rng, lo: Rational, span: usize) -> Rational {
    add(lo, q(below(rng, span + 1) as i128, 8))
}

/// `ortho-sliver`: the corridor of width w around a rectilinear path of n segments.
fn sliver(n: usize, seed: u64) -> Result<Polygon> {
    let mut rng = rng_for(seed, 0x5_11fe);
    let b = 2 + below(&mut rng, 9) as i128;
    let a = 1 + below(&mut rng, (b - 1) as usize) as i128;
    let width = q(a + b, b);
    let half = mul(width, Rational::HALF);
    let shape = below(&mut rng, 3);
    // Directions as (dx, dy) unit steps.
    let dirs: Vec<(i128, i128)> = (0..n)
        .map(|i| match (shape, i % 4) {
            (0, k) if k % 2 == 0 => (1, 0),
            (0, _) => (0, 1),
            (1, 1) => (0, 1),
            (1, 3) => (0, -1),
            (1, _) => (1, 0),
            (_, 0) => (1, 0),
            (_, 2) => (-1, 0),
            _ => (0, 1),
        })
        .collect();
    let mut path = vec![Point::new(Rational::ZERO, Rational::ZERO)];
    // The serpentine's horizontal arms all have one length, so that they stack.
    let arm = eighths(&mut rng, add(width, q(9, 2)), 40);
    for &(dx, dy) in &dirs {
        let len = if shape == 2 && dy == 0 {
            arm
        } else {
            eighths(&mut rng, add(width, Rational::HALF), 24)
        };
        let p = *path.last().expect("the path starts at the origin");
        path.push(Point::new(
            add(p.x, mul(len, Rational::integer(dx as i64))),
            add(p.y, mul(len, Rational::integer(dy as i64))),
        ));
    }
    let scaled = |v: (i128, i128), s: Rational| {
        (
            mul(s, Rational::integer(v.0 as i64)),
            mul(s, Rational::integer(v.1 as i64)),
        )
    };
    let shift = |p: Point, d: (Rational, Rational)| Point::new(add(p.x, d.0), add(p.y, d.1));
    let left = |d: (i128, i128)| (-d.1, d.0);
    // One side of the corridor: offsets of the path by `side` · half along the left normals.
    let chain = |side: i64| -> Vec<Point> {
        let s = mul(half, Rational::integer(side));
        let mut points = Vec::new();
        let first = dirs[0];
        let start = shift(path[0], scaled(first, sub(Rational::ZERO, half)));
        points.push(shift(start, scaled(left(first), s)));
        for i in 1..n {
            let (l0, l1) = (left(dirs[i - 1]), left(dirs[i]));
            points.push(shift(shift(path[i], scaled(l0, s)), scaled(l1, s)));
        }
        let last = dirs[n - 1];
        let end = shift(path[n], scaled(last, half));
        points.push(shift(end, scaled(left(last), s)));
        points
    };
    let mut corners = chain(1);
    corners.extend(chain(-1).into_iter().rev());
    polygon_of(&corners)
}

/// `ortho-narrow`: the polygon and the box of its narrow feature (lower-left, upper-right).
pub(crate) fn narrow(n: usize, seed: u64) -> Result<(Polygon, (Point, Point))> {
    let mut rng = rng_for(seed, 0x0_4a44);
    let scale = 8 * (1 + (n as f64).sqrt() as usize).min(40);
    let size = |rng: &mut Rng| eighths(rng, Rational::integer(1), scale);
    // The feature: width s in (0, 1), length at least 1/8.
    let s = q(1 + below(&mut rng, 7) as i128, 8);
    let length = eighths(&mut rng, q(1, 8), scale);
    let (w1, h1) = (size(&mut rng), size(&mut rng));
    let zero = Rational::ZERO;
    // The feature leaves the first rectangle's right side at height y0 (inside its span).
    let room = sub(h1, s);
    let steps = (room.numer() * 8 / room.denom()).max(0) as usize;
    let y0 = q(below(&mut rng, steps + 1) as i128, 8);
    let (y1, x1) = (add(y0, s), add(w1, length));
    let feature = (Point::new(w1, y0), Point::new(x1, y1));
    let p = |x, y| Point::new(x, y);
    let corners = if below(&mut rng, 2) == 0 {
        // A spike.
        vec![
            p(zero, zero),
            p(w1, zero),
            p(w1, y0),
            p(x1, y0),
            p(x1, y1),
            p(w1, y1),
            p(w1, h1),
            p(zero, h1),
        ]
    } else {
        // A neck to a second rectangle [x1, x1 + w2] × [b, b + h2] that spans [y0, y1].
        let (w2, h2) = (size(&mut rng), size(&mut rng));
        let h2 = h2.max(s);
        let slack = sub(h2, s);
        let steps = (slack.numer() * 8 / slack.denom()).max(0) as usize;
        let b = sub(y0, q(below(&mut rng, steps + 1) as i128, 8));
        let (x2, top) = (add(x1, w2), add(b, h2));
        let mut c = vec![p(zero, zero), p(w1, zero), p(w1, y0), p(x1, y0)];
        c.extend([p(x1, b), p(x2, b), p(x2, top), p(x1, top), p(x1, y1)]);
        c.extend([p(w1, y1), p(w1, h1), p(zero, h1)]);
        dedup_ring(c)
    };
    let corners = dedup_ring(corners);
    Ok((polygon_of(&corners)?, feature))
}

/// Drops repeated and collinear corners of a closed ring.
fn dedup_ring(mut c: Vec<Point>) -> Vec<Point> {
    loop {
        let m = c.len();
        let bad = (0..m).find(|&i| {
            let (a, b, d) = (c[(i + m - 1) % m], c[i], c[(i + 1) % m]);
            a == b || (a.x == b.x && b.x == d.x) || (a.y == b.y && b.y == d.y)
        });
        match bad {
            Some(i) => {
                c.remove(i);
            }
            None => return c,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ortho::Infeasible;

    /// Whether `point` lies in the closed box `(lo, hi)`.
    fn in_box(point: Point, (lo, hi): (Point, Point)) -> bool {
        lo.x <= point.x && point.x <= hi.x && lo.y <= point.y && point.y <= hi.y
    }

    /// The witness point of a refusal.
    fn witness(why: &Infeasible) -> Point {
        match why {
            Infeasible::NoRoom { point } | Infeasible::Uncoverable { point } => *point,
            Infeasible::Disconnected { point, .. } => *point,
        }
    }

    #[test]
    fn deterministic_in_the_seed() {
        for family in FAMILIES {
            for seed in 0..5 {
                let a = generate(family, 20, seed).unwrap().to_wkt();
                let b = generate(family, 20, seed).unwrap().to_wkt();
                assert_eq!(a, b, "{family} seed {seed}");
            }
            let texts: std::collections::BTreeSet<String> = (0..8)
                .map(|seed| generate(family, 20, seed).unwrap().to_wkt())
                .collect();
            assert!(texts.len() >= 6, "{family}: {} distinct of 8", texts.len());
        }
    }

    fn non_integral(p: &Polygon) -> bool {
        p.rings()
            .iter()
            .flat_map(|r| &r.corners)
            .any(|c| !c.x.is_integer() || !c.y.is_integer())
    }

    #[test]
    fn feasible_families_pass_feasibility() {
        for family in ["ortho-perturbed", "ortho-holed", "ortho-sliver"] {
            for seed in 0..40 {
                let n = 1 + (seed as usize * 7) % 60;
                let p = generate(family, n, seed).unwrap();
                assert!(non_integral(&p), "{family} seed {seed}: {}", p.to_wkt());
                if let Err(e) = feasibility(&p) {
                    panic!("{family} n {n} seed {seed}: {e}\n{}", p.to_wkt());
                }
                if family == "ortho-holed" {
                    assert!(p.rings().iter().any(|r| r.hole), "{}", p.to_wkt());
                }
            }
        }
    }

    #[test]
    fn sliver_width_is_between_one_and_two() {
        for seed in 0..40 {
            let p = generate("ortho-sliver", 1, seed).unwrap();
            let c = &p.rings()[0].corners;
            let (lo, hi) = (c.iter().map(|p| p.y).min(), c.iter().map(|p| p.y).max());
            let width = sub(hi.unwrap(), lo.unwrap());
            assert!(
                Rational::ONE < width && width < Rational::integer(2),
                "{width}"
            );
        }
    }

    #[test]
    fn narrow_ones_are_refused_where_the_feature_is() {
        for seed in 0..60 {
            let n = 1 + seed as usize % 30;
            let (p, feature) = narrow(n, seed).unwrap();
            let why = feasibility(&p).expect_err(&p.to_wkt());
            let w = witness(&why);
            assert!(
                in_box(w, feature),
                "seed {seed}: {why} outside the feature {feature:?}\n{}",
                p.to_wkt()
            );
            assert!(why.to_string().contains(&w.to_string()), "{why}");
        }
    }

    #[test]
    fn unknown_family_and_zero_size_are_refused() {
        assert!(generate("ortho-round", 5, 1).is_err());
        assert!(generate("ortho-sliver", 0, 1).is_err());
    }
}
