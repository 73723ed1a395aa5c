//! Contour walks: the boundary of a region offset inwards by 1/2, as closed walks of pixels.
//!
//! Every boundary component of the region (the outer boundary of each grid component and the
//! boundary of every hole) is traced with the region on its left, along the pixel sides that
//! separate the region from its complement. The contour walk visits, in order, the pixels on
//! the left of these sides, and at a reflex corner the pixel diagonal to the missing one: it
//! is the path of the centre of a unit square cutter sliding along that boundary component
//! (δB_i in Section 5 of *Lawn mowing and milling*; the contour C of Section 6 when the
//! region is simple and has no cut vertices).
//!
//! At a vertex where two region pixels touch only diagonally the trace turns left, so that
//! the two pixels stay apart (4-connected region, 8-connected complement).

use crate::region::{Dir, Region};

/// One traced boundary component.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct ContourWalk {
    /// The closed walk of pixel indices (wrap-around implied); one pixel for an isolated
    /// pixel.
    pub walk: Vec<usize>,
    /// True for the outer boundary of a component (counter-clockwise), false for a hole.
    pub outer: bool,
}

impl ContourWalk {
    /// Number of unit moves of the closed walk (the tests' check of a contour's length).
    #[cfg(test)]
    fn len_moves(&self) -> usize {
        if self.walk.len() < 2 {
            0
        } else {
            self.walk.len()
        }
    }
}

/// All contour walks of `region`: one per boundary component, in order of their first
/// boundary side (so the outer boundary of the component holding pixel 0 comes first).
///
/// # Complexity
/// O(N) time and space.
pub(crate) fn contour_walks(region: &Region) -> Vec<ContourWalk> {
    let n = region.len();
    // seen[i] bit d: the side of pixel i facing direction d has been traced.
    let mut seen = vec![0u8; n];
    let mut out = Vec::new();
    for start in 0..n {
        for side in Dir::ALL {
            if seen[start] & (1 << side.index()) != 0 || region.neighbor(start, side).is_some() {
                continue;
            }
            out.push(trace(region, start, side, &mut seen));
        }
    }
    out
}

/// Traces the boundary component through side `side` of pixel `start`.
fn trace(region: &Region, start: usize, side: Dir, seen: &mut [u8]) -> ContourWalk {
    let mut walk = vec![start];
    let (mut p, mut s) = (start, side);
    let mut left_minus_right = 0i32;
    loop {
        seen[p] |= 1 << s.index();
        // Walking along side s of p with p on the left: heading s.left().
        let w = s.left();
        if region.neighbor(p, w).is_none() {
            // Left turn around a convex corner of p: next side of the same pixel.
            s = w;
            left_minus_right += 1;
        } else {
            let q = region.neighbor(p, w).expect("checked above");
            match region.neighbor(q, s) {
                None => {
                    // Straight on along side s of q.
                    walk.push(q);
                    p = q;
                }
                Some(r) => {
                    // Right turn at a reflex corner: through q, the pixel diagonal to the
                    // missing one, onto side w.opposite() of r.
                    walk.push(q);
                    walk.push(r);
                    p = r;
                    s = w.opposite();
                    left_minus_right -= 1;
                }
            }
        }
        if p == start && s == side {
            break;
        }
    }
    if walk.len() > 1 && walk.last() == walk.first() {
        walk.pop();
    }
    ContourWalk {
        walk,
        outer: left_minus_right > 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::checker::{Mode, check};
    use crate::region::Pixel;
    use crate::tour::CycleCover;

    fn pixels(r: &Region, c: &ContourWalk) -> Vec<(i32, i32)> {
        c.walk
            .iter()
            .map(|&i| (r.pixel(i).x, r.pixel(i).y))
            .collect()
    }

    #[test]
    fn rectangle_contour_is_its_ring() {
        let r = Region::rectangle(3, 3);
        let cs = contour_walks(&r);
        assert_eq!(cs.len(), 1);
        assert!(cs[0].outer);
        assert_eq!(
            pixels(&r, &cs[0]),
            vec![
                (0, 0),
                (1, 0),
                (2, 0),
                (2, 1),
                (2, 2),
                (1, 2),
                (0, 2),
                (0, 1)
            ]
        );
    }

    #[test]
    fn row_contour_goes_there_and_back() {
        let r = Region::rectangle(3, 1);
        let cs = contour_walks(&r);
        assert_eq!(pixels(&r, &cs[0]), vec![(0, 0), (1, 0), (2, 0), (1, 0)]);
        let single = Region::rectangle(1, 1);
        assert_eq!(contour_walks(&single)[0].walk, vec![0]);
        assert_eq!(contour_walks(&single)[0].len_moves(), 0);
    }

    #[test]
    fn reflex_corner_passes_the_diagonal_pixel() {
        // An L of width 2: the contour passes (1, 1), which touches the boundary at a corner.
        let r = Region::from_ascii("##..\n##..\n####\n####\n");
        let cs = contour_walks(&r);
        assert_eq!(cs.len(), 1);
        let walk = pixels(&r, &cs[0]);
        assert!(walk.contains(&(1, 1)));
        assert_eq!(walk.len(), 12);
        let rep = check(
            &r,
            &CycleCover::tour(walk.iter().map(|&p| p.into()).collect()),
            Mode::Milling,
        );
        assert!(rep.valid, "{:?}", rep.error);
    }

    #[test]
    fn holes_are_traced_clockwise() {
        let r = Region::from_ascii("#####\n#.#.#\n#####\n");
        let cs = contour_walks(&r);
        assert_eq!(cs.len(), 3);
        assert_eq!(cs.iter().filter(|c| c.outer).count(), 1);
        for c in &cs {
            let walk: Vec<Pixel> = c.walk.iter().map(|&i| r.pixel(i)).collect();
            let rep = check(&r, &CycleCover::tour(walk), Mode::Lawn);
            assert!(rep.length > 0);
        }
        // Each hole's contour is the ring of 8 pixels around it.
        assert!(cs.iter().filter(|c| !c.outer).all(|c| c.walk.len() == 8));
    }
}
