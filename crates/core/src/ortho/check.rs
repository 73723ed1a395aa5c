//! The exact milling checker for polygons with arbitrary coordinates.

use super::cover::{Rect, compare};
use super::polygon::{Point, Polygon};
use super::rational::Rational;
use super::tour::Tour;
use crate::error::{Error, Result};
use crate::region::Dir;
use serde::Serialize;
use std::fmt;

/// The first thing wrong with a tour.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Violation {
    NoCycles,
    EmptyCycle {
        cycle: usize,
    },
    /// The move from point `step` to the next (the last move closes the walk) is diagonal.
    NotRectilinear {
        cycle: usize,
        step: usize,
        from: Point,
        to: Point,
    },
    /// The cutter, moving from `from` to `to` (point `step` of `cycle` to the next), sweeps
    /// `point`, which lies outside the polygon (with a neighbourhood of positive area).
    LeavesPolygon {
        cycle: usize,
        step: usize,
        from: Point,
        to: Point,
        point: Point,
    },
    /// `point` of the polygon (with a neighbourhood of positive area) is never swept.
    NotMilled {
        point: Point,
    },
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Violation::NoCycles => write!(f, "the tour has no closed walk"),
            Violation::EmptyCycle { cycle } => write!(f, "cycle {cycle} is empty"),
            Violation::NotRectilinear {
                cycle,
                step,
                from,
                to,
            } => write!(
                f,
                "cycle {cycle}, step {step}: {from} -> {to} is neither horizontal nor vertical"
            ),
            Violation::LeavesPolygon {
                cycle,
                step,
                from,
                to,
                point,
            } => write!(
                f,
                "cycle {cycle}, step {step}: moving {from} -> {to} the cutter sweeps {point}, \
                 outside the polygon"
            ),
            Violation::NotMilled { point } => {
                write!(f, "the point {point} of the polygon is not milled")
            }
        }
    }
}

/// What the checker recounted and decided. The JSON keys are these field names; `length` is
/// an exact number written as a string.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Report {
    /// The walks mill the polygon exactly: rectilinear, the swept area covers the polygon and
    /// never leaves it (both up to measure zero).
    pub valid: bool,
    pub cycles: usize,
    /// Total Euclidean (= rectilinear) length of all walks, wrap-around moves included; 0 when
    /// a walk is not rectilinear.
    pub length: Rational,
    /// Total turn cost: at each vertex where the heading changes, 1 for 90° and 2 for a
    /// reversal, zero-length moves skipped; a walk that never moves counts 4. 0 when a walk is
    /// not rectilinear.
    pub turns: u64,
    /// A point of the polygon that is not swept, if any (`None` also when a walk is not
    /// rectilinear: then nothing is swept).
    pub uncovered: Option<Point>,
    /// A point outside the polygon that is swept, if any (likewise).
    pub outside: Option<Point>,
    /// The first violation, as text.
    pub error: Option<String>,
    #[serde(skip)]
    pub violation: Option<Violation>,
}

/// The heading of the move from `a` to `b`: `Ok(None)` when they are equal, `Err` when the
/// move is diagonal.
#[allow(clippy::result_unit_err)] // Err(()): not axis-parallel; each caller words its own error.
pub fn heading(a: Point, b: Point) -> std::result::Result<Option<Dir>, ()> {
    use std::cmp::Ordering::*;
    match (b.x.cmp(&a.x), b.y.cmp(&a.y)) {
        (Equal, Equal) => Ok(None),
        (Greater, Equal) => Ok(Some(Dir::E)),
        (Less, Equal) => Ok(Some(Dir::W)),
        (Equal, Greater) => Ok(Some(Dir::N)),
        (Equal, Less) => Ok(Some(Dir::S)),
        _ => Err(()),
    }
}

/// The turn cost of a closed walk whose non-zero moves have these headings, in order: the
/// turns between consecutive headings (wrap-around included), 4 when there are none.
///
/// The 4 for a walk that never moves follows the pixel checker
/// ([`crate::checker::walk_cost`]): a closed walk turns through 360°, and free one-point
/// cycles would make every minimum-turn cycle cover trivial.
pub fn turn_cost(headings: &[Dir]) -> u64 {
    let m = headings.len();
    if m == 0 {
        return 4;
    }
    (0..m)
        .map(|i| u64::from(headings[(i + m - 1) % m].turn_to(headings[i])))
        .sum()
}

/// Checks that `tour` mills `polygon` exactly with the unit square cutter (axis-parallel,
/// centred on the walk) and recounts its length and turns.
///
/// The swept area of a move from a to b is the box spanned by a and b grown by ½ on every
/// side (a unit square for a move of length 0, and for a walk of one point), so the area the
/// walks sweep is a finite union of rectangles; it must equal the polygon up to measure zero
/// (cover it, and leave it nowhere in a set of positive area: touching the boundary from
/// inside is fine). The comparison is exact, on the finite grid that all the coordinates
/// involved span (see the `cover` module); no floating point is involved anywhere.
///
/// # Returns
///
/// The [`Report`]; a tour that does not mill the polygon is a report with `valid: false` and
/// its first [`Violation`] (a diagonal move first, then leaving the polygon, then an unmilled
/// point). `Err` only when the exact total length does not fit the rational type (a sum of
/// lengths with very many distinct denominators): the checker then refuses to decide rather
/// than round.
///
/// # Complexity
///
/// O((n + v) log(n + v)) time and O(n + v) space for n tour points and v polygon corners.
///
/// # Examples
///
/// ```
/// use mowmill_core::ortho::{self, Polygon, Tour};
///
/// // A 3 × 1.5 rectangle: one pass at mid-height sweeps a band of height 1 only.
/// let p = Polygon::parse("POLYGON ((0 0, 3 0, 3 1.5, 0 1.5, 0 0))", "p.wkt")?;
/// let line = Tour::from_json(r#"{"model":"ortho","tour":[["0.5","0.75"],["2.5","0.75"]]}"#, "t")?;
/// let report = ortho::check(&p, &line)?;
/// assert!(!report.valid);
/// assert_eq!(report.error.unwrap(), "the point (1.5, 0.125) of the polygon is not milled");
/// // Two passes, at y = 0.5 and y = 1: 2 + 0.5 + 2 + 0.5 = 5, four turns.
/// let two = Tour::from_json(
///     r#"{"model":"ortho","tour":[["0.5","0.5"],["2.5","0.5"],["2.5","1"],["0.5","1"]]}"#,
///     "t",
/// )?;
/// let report = ortho::check(&p, &two)?;
/// assert!(report.valid);
/// assert_eq!((report.length.to_string(), report.turns), ("5".to_string(), 4));
/// # Ok::<(), mowmill_core::Error>(())
/// ```
pub fn check(polygon: &Polygon, tour: &Tour) -> Result<Report> {
    let mut report = Report {
        valid: false,
        cycles: tour.cycles.len(),
        length: Rational::ZERO,
        turns: 0,
        uncovered: None,
        outside: None,
        error: None,
        violation: None,
    };
    let violation = recount(polygon, tour, &mut report)?;
    report.valid = violation.is_none();
    report.error = violation.as_ref().map(ToString::to_string);
    report.violation = violation;
    Ok(report)
}

fn recount(polygon: &Polygon, tour: &Tour, report: &mut Report) -> Result<Option<Violation>> {
    if tour.cycles.is_empty() {
        return Ok(Some(Violation::NoCycles));
    }
    let overflow = || {
        Error::invalid(
            "the tour's exact length does not fit the checker's rational numbers (i128 over \
             i128); it cannot be decided exactly",
        )
    };
    let (mut length, mut turns) = (Rational::ZERO, 0u64);
    // The swept rectangle of every move, with its cycle and step.
    let mut swept: Vec<(Rect, usize, usize)> = Vec::new();
    for (c, walk) in tour.cycles.iter().enumerate() {
        if walk.is_empty() {
            return Ok(Some(Violation::EmptyCycle { cycle: c }));
        }
        let m = walk.len();
        let mut headings = Vec::with_capacity(m);
        for i in 0..m {
            let (a, b) = (walk[i], walk[(i + 1) % m]);
            match heading(a, b) {
                Ok(h) => headings.extend(h),
                Err(()) => {
                    return Ok(Some(Violation::NotRectilinear {
                        cycle: c,
                        step: i,
                        from: a,
                        to: b,
                    }));
                }
            }
            let step = b.x.checked_sub(a.x).ok_or_else(overflow)?.abs();
            let step = step.checked_add(b.y.checked_sub(a.y).ok_or_else(overflow)?.abs());
            length = length
                .checked_add(step.ok_or_else(overflow)?)
                .ok_or_else(overflow)?;
            let rect = Rect::swept(a.x, b.x, a.y, b.y).ok_or_else(overflow)?;
            swept.push((rect, c, i));
        }
        turns += turn_cost(&headings);
    }
    report.length = length;
    report.turns = turns;
    let rects: Vec<Rect> = swept.iter().map(|s| s.0).collect();
    let difference = compare(&polygon.vertical_edges(), &rects);
    report.uncovered = difference.uncovered;
    report.outside = difference.outside;
    if let Some(point) = difference.outside {
        let &(_, cycle, step) = swept
            .iter()
            .find(|s| s.0.contains_inside(point))
            .expect("a point swept outside lies inside some swept rectangle");
        let walk = &tour.cycles[cycle];
        return Ok(Some(Violation::LeavesPolygon {
            cycle,
            step,
            from: walk[step],
            to: walk[(step + 1) % walk.len()],
            point,
        }));
    }
    Ok(difference
        .uncovered
        .map(|point| Violation::NotMilled { point }))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// A polygon from WKT text (the unit tests of `ortho` share these two helpers).
    pub(in crate::ortho) fn polygon(text: &str) -> Polygon {
        Polygon::parse(text, "p.wkt").unwrap()
    }

    /// A walk from decimal or `p/q` coordinate pairs.
    pub(in crate::ortho) fn tour(points: &[(&str, &str)]) -> Tour {
        let q = |s: &str| Rational::parse_coordinate(s).unwrap();
        Tour::new(
            points
                .iter()
                .map(|&(x, y)| Point::new(q(x), q(y)))
                .collect(),
        )
    }

    fn checked(p: &Polygon, t: &Tour) -> Report {
        check(p, t).unwrap()
    }

    #[test]
    fn sliver_of_width_one_and_a_half() {
        // 4 × 1.5: two passes at heights 0.5 and 1 overlap in a band of width 1/2.
        let p = polygon("POLYGON ((0 0, 4 0, 4 1.5, 0 1.5, 0 0))");
        let t = tour(&[("0.5", "0.5"), ("3.5", "0.5"), ("3.5", "1"), ("0.5", "1")]);
        let r = checked(&p, &t);
        assert!(r.valid, "{:?}", r.error);
        assert_eq!((r.length.to_string(), r.turns), ("7".to_string(), 4));
        // One pass too low leaves the top band; one too high leaves the polygon.
        let low = tour(&[("0.5", "0.5"), ("3.5", "0.5")]);
        let r = checked(&p, &low);
        assert_eq!(
            r.violation,
            Some(Violation::NotMilled {
                point: Point::new(Rational::integer(2), Rational::new(5, 4).unwrap())
            })
        );
        assert_eq!((r.length.to_string(), r.turns), ("6".to_string(), 4));
        let high = tour(&[
            ("0.5", "0.5"),
            ("3.5", "0.5"),
            ("3.5", "1.25"),
            ("0.5", "1.25"),
        ]);
        let r = checked(&p, &high);
        assert_eq!(
            r.error.as_deref(),
            Some(
                "cycle 0, step 2: moving (3.5, 1.25) -> (0.5, 1.25) the cutter sweeps \
                 (0.5, 1.625), outside the polygon"
            )
        );
    }

    #[test]
    fn turns_and_length_conventions() {
        let square = polygon("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))");
        // One point: length 0, 4 turns (as the pixel checker).
        let r = checked(&square, &tour(&[("0.5", "0.5")]));
        assert!(r.valid);
        assert_eq!((r.length, r.turns), (Rational::ZERO, 4));
        // Repeated points are zero-length moves: skipped.
        let r = checked(&square, &tour(&[("0.5", "0.5"), ("0.5", "0.5")]));
        assert!(r.valid);
        assert_eq!(r.turns, 4);
        let strip = polygon("POLYGON ((0 0, 3.25 0, 3.25 1, 0 1, 0 0))");
        // There and back: two U-turns; collinear points in between cost nothing.
        let t = tour(&[
            ("0.5", "0.5"),
            ("1.5", "0.5"),
            ("2.75", "0.5"),
            ("2.75", "0.5"),
        ]);
        let r = checked(&strip, &t);
        assert!(r.valid, "{:?}", r.error);
        assert_eq!((r.length.to_string(), r.turns), ("4.5".to_string(), 4));
    }

    #[test]
    fn diagonal_moves_and_empty_tours_are_refused() {
        let square = polygon("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))");
        let r = checked(&square, &tour(&[("0.5", "0.5"), ("1.5", "1.5")]));
        assert_eq!(
            r.error.as_deref(),
            Some("cycle 0, step 0: (0.5, 0.5) -> (1.5, 1.5) is neither horizontal nor vertical")
        );
        assert_eq!((r.length, r.turns, r.uncovered), (Rational::ZERO, 0, None));
        assert_eq!(
            checked(&square, &Tour::default()).violation,
            Some(Violation::NoCycles)
        );
        let empty = Tour {
            cycles: vec![vec![]],
        };
        assert_eq!(
            checked(&square, &empty).violation,
            Some(Violation::EmptyCycle { cycle: 0 })
        );
    }

    #[test]
    fn holes_must_be_avoided_and_touching_is_fine() {
        // A 3 × 3 square with a unit hole in the middle: the ring of centres at 0.5 and 2.5.
        let frame = polygon("POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))");
        let ring = tour(&[
            ("0.5", "0.5"),
            ("2.5", "0.5"),
            ("2.5", "2.5"),
            ("0.5", "2.5"),
        ]);
        let r = checked(&frame, &ring);
        assert!(r.valid, "{:?}", r.error);
        assert_eq!((r.length.to_string(), r.turns), ("8".to_string(), 4));
        let through = tour(&[
            ("0.5", "0.5"),
            ("2.5", "0.5"),
            ("2.5", "1.5"),
            ("0.5", "1.5"),
        ]);
        let r = checked(&frame, &through);
        assert!(!r.valid);
        assert_eq!(
            r.outside,
            Some(Point::new(
                Rational::new(3, 2).unwrap(),
                Rational::new(3, 2).unwrap()
            ))
        );
        // The hole's witness is reported even though the top row is also unmilled.
        assert!(r.uncovered.is_some());
    }

    #[test]
    fn cycle_covers_are_checked_together() {
        // Two unit squares meeting at a corner: two one-point cycles mill them.
        let p = polygon("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))");
        let q = |s: &str| Rational::parse_coordinate(s).unwrap();
        let cover = Tour {
            cycles: vec![
                vec![Point::new(q("0.5"), q("0.5"))],
                vec![Point::new(q("1.5"), q("1.5"))],
            ],
        };
        let r = checked(&p, &cover);
        assert!(r.valid, "{:?}", r.error);
        assert_eq!((r.cycles, r.turns), (2, 8));
    }
}
