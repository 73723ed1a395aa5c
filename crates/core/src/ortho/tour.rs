//! Tours of the cutter's centre with exact coordinates, and their JSON files.

use super::polygon::Point;
use crate::error::{Error, Result};
use crate::tour::CycleCover;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The most points a tour file may hold (all cycles together).
pub const MAX_TOUR_POINTS: usize = 1 << 22;

/// Closed rectilinear walks of the centre of the unit square cutter: in each cycle, consecutive
/// points (and the last and the first) differ in at most one coordinate, and the cutter moves
/// along the straight segment between them. A tour is a cover with one cycle.
///
/// File format (JSON): `{"model": "ortho", "tour": [["1/2", "3/2"], ["5/2", "3/2"], ...]}`
/// for a tour, `{"model": "ortho", "cycles": [[...], [...]]}` for several cycles; each
/// coordinate a string read exactly as in WKT (`"0.35"`, `"7/3"`, `"-2"`) or a JSON integer.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tour {
    pub cycles: Vec<Vec<Point>>,
}

#[derive(Serialize, Deserialize)]
enum Model {
    #[serde(rename = "ortho")]
    Ortho,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct TourFile {
    model: Model,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    tour: Option<Vec<Point>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    cycles: Option<Vec<Vec<Point>>>,
}

impl Tour {
    /// A tour: one closed walk.
    pub fn new(walk: Vec<Point>) -> Tour {
        Tour { cycles: vec![walk] }
    }

    pub fn is_tour(&self) -> bool {
        self.cycles.len() == 1
    }

    /// The walks of a pixel cycle cover as walks of the cutter's centre: pixel (x, y) becomes
    /// its centre (x + ½, y + ½).
    pub fn from_cover(cover: &CycleCover) -> Tour {
        Tour {
            cycles: cover
                .cycles
                .iter()
                .map(|walk| walk.iter().map(|p| Point::pixel_centre(p.x, p.y)).collect())
                .collect(),
        }
    }

    /// The JSON text: the `tour` form for one cycle, the `cycles` form otherwise.
    /// The walks as pixel walks, when every point is a pixel centre (x + ½, y + ½): each move
    /// written out in unit moves, repeated points dropped, the closing move implied (the inverse
    /// of [`Tour::from_cover`]). `None` when a point is not a pixel centre, a move is diagonal,
    /// or a walk has more than [`MAX_TOUR_POINTS`] unit moves.
    pub fn to_pixel_cover(&self) -> Option<CycleCover> {
        use crate::region::Pixel;
        let pixel = |p: Point| {
            let cell = |v: super::Rational| {
                let twice = v.checked_mul(super::Rational::from(2))?;
                (twice.is_integer() && twice.numer().rem_euclid(2) == 1)
                    .then(|| {
                        i64::try_from(v.floor())
                            .ok()
                            .and_then(|c| crate::region::pixel_coordinate(c).ok())
                    })
                    .flatten()
            };
            Some(Pixel::new(cell(p.x)?, cell(p.y)?))
        };
        let mut cycles = Vec::with_capacity(self.cycles.len());
        for walk in &self.cycles {
            let pixels: Vec<Pixel> = walk.iter().map(|&p| pixel(p)).collect::<Option<_>>()?;
            let mut out: Vec<Pixel> = Vec::new();
            for &to in &pixels {
                let Some(&from) = out.last() else {
                    out.push(to);
                    continue;
                };
                if from.x != to.x && from.y != to.y {
                    return None;
                }
                let steps = (to.x - from.x).abs().max((to.y - from.y).abs());
                if out.len() + steps as usize > MAX_TOUR_POINTS {
                    return None;
                }
                let (dx, dy) = ((to.x - from.x).signum(), (to.y - from.y).signum());
                for k in 1..=steps {
                    out.push(Pixel::new(from.x + k * dx, from.y + k * dy));
                }
            }
            // The closing move back to the first point, written out too (without repeating it).
            if let (Some(&last), Some(&first)) = (out.last(), out.first()) {
                if last.x != first.x && last.y != first.y {
                    return None;
                }
                let steps = (first.x - last.x).abs().max((first.y - last.y).abs());
                let (dx, dy) = ((first.x - last.x).signum(), (first.y - last.y).signum());
                for k in 1..steps {
                    out.push(Pixel::new(last.x + k * dx, last.y + k * dy));
                }
            }
            if out.len() > 1 && out.first() == out.last() {
                out.pop();
            }
            cycles.push(out);
        }
        Some(CycleCover::new(cycles))
    }

    pub fn to_json(&self) -> String {
        let file = if self.is_tour() {
            TourFile {
                model: Model::Ortho,
                tour: Some(self.cycles[0].clone()),
                cycles: None,
            }
        } else {
            TourFile {
                model: Model::Ortho,
                tour: None,
                cycles: Some(self.cycles.clone()),
            }
        };
        serde_json::to_string(&file).expect("a tour always serializes")
    }

    /// Reads a tour file's text; `name` is used in error messages (`name:line:column: ...`).
    pub fn from_json(text: &str, name: &str) -> Result<Tour> {
        let file: TourFile = serde_json::from_str(text).map_err(|e| {
            Error::parse(
                name,
                e.line(),
                e.column(),
                format!(
                    "expected an exact tour {{\"model\": \"ortho\", \"tour\": [[\"x\", \"y\"], \
                     ...]}}: {e}"
                ),
            )
        })?;
        let cycles = match (file.tour, file.cycles) {
            (Some(walk), None) => vec![walk],
            (None, Some(cycles)) => cycles,
            _ => {
                return Err(Error::parse(
                    name,
                    1,
                    1,
                    "expected exactly one of the keys \"tour\" (one closed walk) and \"cycles\" \
                     (a list of them)",
                ));
            }
        };
        let points: usize = cycles.iter().map(Vec::len).sum();
        if points > MAX_TOUR_POINTS {
            return Err(Error::parse(
                name,
                1,
                1,
                format!("the tour has {points} points; expected at most {MAX_TOUR_POINTS}"),
            ));
        }
        Ok(Tour { cycles })
    }

    pub fn read(path: &Path) -> Result<Tour> {
        let text = crate::input::read_text(path, "a tour JSON file")?;
        Tour::from_json(&text, &path.display().to_string())
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        std::fs::write(path, self.to_json() + "\n").map_err(|e| Error::io(path, e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ortho::Rational;
    use crate::region::Pixel;

    #[test]
    fn pixel_walks_come_back_in_unit_moves() {
        // A 3 × 2 boustrophedon with long moves: written out in unit moves, the closing move
        // implied.
        let c = |x, y| Point::pixel_centre(x, y);
        let tour = Tour::new(vec![c(0, 0), c(2, 0), c(2, 1), c(0, 1)]);
        let cover = tour.to_pixel_cover().unwrap();
        let p = |x, y| Pixel::new(x, y);
        assert_eq!(
            cover.cycles,
            vec![vec![p(0, 0), p(1, 0), p(2, 0), p(2, 1), p(1, 1), p(0, 1)]]
        );
        // Round trip of a pixel cover, repeated points dropped.
        let back = Tour::from_cover(&cover).to_pixel_cover().unwrap();
        assert_eq!(back, cover);
        let repeated = Tour::new(vec![c(0, 0), c(0, 0), c(1, 0)]);
        assert_eq!(
            repeated.to_pixel_cover().unwrap().cycles,
            vec![vec![p(0, 0), p(1, 0)]]
        );
        // Not pixel centres, or a diagonal move: none.
        let q = |a: i128, b: i128| Rational::new(a, b).unwrap();
        assert!(
            Tour::new(vec![Point::new(q(1, 4), q(1, 2))])
                .to_pixel_cover()
                .is_none()
        );
        assert!(Tour::new(vec![c(0, 0), c(1, 1)]).to_pixel_cover().is_none());
        assert!(
            Tour::new(vec![Point::new(q(1, 1), q(1, 2))])
                .to_pixel_cover()
                .is_none()
        );
    }

    #[test]
    fn json_round_trip() {
        let cover = CycleCover::tour(vec![Pixel::new(0, 1), Pixel::new(1, 1)]);
        let tour = Tour::from_cover(&cover);
        let text = tour.to_json();
        assert_eq!(
            text,
            r#"{"model":"ortho","tour":[["0.5","1.5"],["1.5","1.5"]]}"#
        );
        assert_eq!(Tour::from_json(&text, "t.json").unwrap(), tour);
        let two = Tour {
            cycles: vec![tour.cycles[0].clone(), tour.cycles[0].clone()],
        };
        let text = two.to_json();
        assert!(
            text.starts_with(r#"{"model":"ortho","cycles":[[["#),
            "{text}"
        );
        assert_eq!(Tour::from_json(&text, "t.json").unwrap(), two);
        let thirds = r#"{"model": "ortho", "tour": [["1/3", 2], ["7/3", "2"]]}"#;
        let t = Tour::from_json(thirds, "t.json").unwrap();
        assert_eq!(t.cycles[0][1].x.to_string(), "7/3");
    }

    #[test]
    fn errors_name_file_and_position() {
        let cases = [
            (
                r#"{"model": "ortho", "tour": [[0.5, 1]]}"#,
                "t.json:1:",
                "as strings",
            ),
            (
                r#"{"model": "grid", "tour": []}"#,
                "t.json:1:",
                "unknown variant",
            ),
            (r#"{"model": "ortho"}"#, "t.json:1:1:", "exactly one of"),
            (
                "{\"model\": \"ortho\",\n \"tour\": [[\"1/0\", \"1\"]]}",
                "t.json:2:",
                "malformed number 1/0",
            ),
            (
                r#"{"model": "ortho", "tour": [["1"]]}"#,
                "t.json:1:",
                "expected an exact tour",
            ),
        ];
        for (text, place, words) in cases {
            let e = Tour::from_json(text, "t.json").unwrap_err().to_string();
            assert!(e.starts_with(place) && e.contains(words), "{text}: {e}");
        }
    }
}
