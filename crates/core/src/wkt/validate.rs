//! Validity of the geometry as a whole: no crossing or overlapping edges, rings touching only
//! at points, holes inside their outer ring and polygons apart (OGC rules, by sweeps).

use super::lexer::Pos;
use super::parser::{Coordinate, Corner, Ring, point};
use crate::error::{Error, Result};
use crate::region::Dir;
use std::collections::BTreeMap;
use std::ops::Bound::Excluded;

/// An edge as a segment: `fixed` is its y (horizontal) or x (vertical), `lo < hi` its extent.
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment<C> {
    pub(super) fixed: C,
    pub(super) lo: C,
    pub(super) hi: C,
    pub(super) ring: usize,
    pub(super) edge: usize,
}

pub(super) struct Geometry<'a, C> {
    pub(super) rings: Vec<Ring<C>>,
    pub(super) file: &'a str,
}

/// Whether a ring runs counter-clockwise: at its lowest, then leftmost, corner (a convex one,
/// its edges heading east and north) the edge leaving it heads east.
pub(super) fn counter_clockwise<C: Coordinate>(ring: &Ring<C>) -> bool {
    ring.corners
        .iter()
        .min_by_key(|c| (c.y, c.x))
        .is_some_and(|c| c.dir == Dir::E)
}

impl<C: Coordinate> Geometry<'_, C> {
    pub(super) fn error(&self, pos: Pos, message: impl Into<String>) -> Error {
        Error::parse(self.file, pos.line, pos.column, message)
    }

    pub(super) fn edge_ends(&self, ring: usize, edge: usize) -> (Corner<C>, Corner<C>) {
        let corners = &self.rings[ring].corners;
        (corners[edge], corners[(edge + 1) % corners.len()])
    }

    pub(super) fn describe_edge(&self, ring: usize, edge: usize) -> String {
        let (a, b) = self.edge_ends(ring, edge);
        format!("edge from {} to {}", point(a.x, a.y), point(b.x, b.y))
    }

    /// An error about two edges, placed where the later one is complete: "`later` `verb`
    /// `earlier` `place`".
    pub(super) fn edges_error(
        &self,
        a: &Segment<C>,
        b: &Segment<C>,
        verb: &str,
        place: String,
    ) -> Error {
        let pos_a = self.rings[a.ring].corners[a.edge].edge_end;
        let pos_b = self.rings[b.ring].corners[b.edge].edge_end;
        let (first, second) = if pos_a <= pos_b { (a, b) } else { (b, a) };
        self.error(
            pos_a.max(pos_b),
            format!(
                "{} {verb} {} {place}; expected rings that meet at most at single points",
                self.describe_edge(second.ring, second.edge),
                self.describe_edge(first.ring, first.edge)
            ),
        )
    }

    /// Horizontal and vertical edges of all rings.
    pub(super) fn segments(&self) -> (Vec<Segment<C>>, Vec<Segment<C>>) {
        let (mut horizontal, mut vertical) = (Vec::new(), Vec::new());
        for (ring, r) in self.rings.iter().enumerate() {
            for edge in 0..r.corners.len() {
                let (a, b) = self.edge_ends(ring, edge);
                if a.y == b.y {
                    let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
                    horizontal.push(Segment {
                        fixed: a.y,
                        lo,
                        hi,
                        ring,
                        edge,
                    });
                } else {
                    let (lo, hi) = (a.y.min(b.y), a.y.max(b.y));
                    vertical.push(Segment {
                        fixed: a.x,
                        lo,
                        hi,
                        ring,
                        edge,
                    });
                }
            }
        }
        (horizontal, vertical)
    }

    /// Refuses edges that overlap or cross, and rings that touch themselves.
    ///
    /// Corners are right angles, so a corner lying inside another edge always makes one of its
    /// own edges overlap that edge; what remains are proper crossings and shared corners, and a
    /// shared corner is a crossing only if both rings go straight through it, which they don't.
    pub(super) fn check_rings_meet_at_points(&self) -> Result<()> {
        let (mut horizontal, mut vertical) = self.segments();
        self.check_overlaps(&mut horizontal, point)?;
        self.check_overlaps(&mut vertical, |along, fixed| point(fixed, along))?;
        self.check_crossings(&horizontal, &vertical)?;
        let mut corners: Vec<(C, C, usize, Pos)> = Vec::new();
        for (ring, r) in self.rings.iter().enumerate() {
            corners.extend(r.corners.iter().map(|c| (c.x, c.y, ring, c.pos)));
        }
        corners.sort_unstable();
        for pair in corners.windows(2) {
            let ((x, y, ring, _), (x2, y2, ring2, pos)) = (pair[0], pair[1]);
            if (x, y, ring) == (x2, y2, ring2) {
                return Err(self.error(
                    pos,
                    format!(
                        "ring passes through {} twice; expected a simple ring (write the parts \
                         as separate polygons, or as an outer ring and a hole, touching there)",
                        point(x, y)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Refuses two parallel edges on one line whose extents share more than a point.
    pub(super) fn check_overlaps(
        &self,
        segments: &mut [Segment<C>],
        point: impl Fn(C, C) -> String,
    ) -> Result<()> {
        segments.sort_unstable_by_key(|s| (s.fixed, s.lo, s.hi));
        // The segment reaching farthest among those already seen on the current line.
        let mut reach: Option<Segment<C>> = None;
        for s in segments.iter() {
            match reach {
                Some(r) if r.fixed == s.fixed && s.lo < r.hi => {
                    let shared = format!(
                        "along {}-{}",
                        point(s.lo, s.fixed),
                        point(s.hi.min(r.hi), s.fixed)
                    );
                    return Err(self.edges_error(s, &r, "overlaps", shared));
                }
                Some(r) if r.fixed == s.fixed && r.hi >= s.hi => {}
                _ => reach = Some(*s),
            }
        }
        Ok(())
    }

    /// Refuses a horizontal and a vertical edge whose interiors cross, by a sweep in x over
    /// the horizontal edges open at each vertical edge.
    pub(super) fn check_crossings(
        &self,
        horizontal: &[Segment<C>],
        vertical: &[Segment<C>],
    ) -> Result<()> {
        const CLOSE: u8 = 0;
        const QUERY: u8 = 1;
        const OPEN: u8 = 2;
        let mut events: Vec<(C, u8, usize)> =
            Vec::with_capacity(2 * horizontal.len() + vertical.len());
        for (k, s) in horizontal.iter().enumerate() {
            events.push((s.lo, OPEN, k));
            events.push((s.hi, CLOSE, k));
        }
        events.extend(
            vertical
                .iter()
                .enumerate()
                .map(|(k, s)| (s.fixed, QUERY, k)),
        );
        events.sort_unstable();
        // Open horizontal edges by y: no two overlap, so a line holds at most one at a time.
        let mut open: BTreeMap<C, usize> = BTreeMap::new();
        for (_, kind, k) in events {
            match kind {
                CLOSE => {
                    open.remove(&horizontal[k].fixed);
                }
                OPEN => {
                    open.insert(horizontal[k].fixed, k);
                }
                _ => {
                    let v = &vertical[k];
                    if let Some((&y, &h)) = open.range((Excluded(v.lo), Excluded(v.hi))).next() {
                        let at = format!("at {}", point(v.fixed, y));
                        return Err(self.edges_error(v, &horizontal[h], "crosses", at));
                    }
                }
            }
        }
        Ok(())
    }

    /// For each ring, the innermost ring that encloses it (rings no longer cross, so this is
    /// a tree). Found by a sweep in y: at the lowest row a ring occupies, the nearest vertical
    /// edge to its left belongs to its parent when the parent's interior lies to the right of
    /// that edge, and otherwise to a sibling, whose parent it shares.
    pub(super) fn enclosing_rings(&self) -> Result<Vec<Option<usize>>> {
        let counter_clockwise: Vec<bool> = self.rings.iter().map(counter_clockwise).collect();
        let (_, vertical) = self.segments();
        // The lowest row of each ring and its leftmost edge there.
        let mut lowest: Vec<Option<(C, C)>> = vec![None; self.rings.len()];
        for v in &vertical {
            let slot = &mut lowest[v.ring];
            if slot.is_none_or(|low| (v.lo, v.fixed) < low) {
                *slot = Some((v.lo, v.fixed));
            }
        }
        const CLOSE: u8 = 0;
        const OPEN: u8 = 1;
        const QUERY: u8 = 2;
        let mut events: Vec<(C, u8, C, usize)> = Vec::with_capacity(3 * vertical.len());
        for (k, v) in vertical.iter().enumerate() {
            events.push((v.lo, OPEN, v.fixed, k));
            events.push((v.hi, CLOSE, v.fixed, k));
        }
        for (ring, low) in lowest.iter().enumerate() {
            if let Some((y, x)) = low {
                events.push((*y, QUERY, *x, ring));
            }
        }
        events.sort_unstable();
        // Vertical edges crossing the current row by x: (ring, its interior lies to the right).
        let mut open: BTreeMap<C, (usize, bool)> = BTreeMap::new();
        let mut parent: Vec<Option<Option<usize>>> = vec![None; self.rings.len()];
        for (_, kind, x, k) in events {
            match kind {
                CLOSE => {
                    open.remove(&x);
                }
                OPEN => {
                    let v = &vertical[k];
                    let (a, _) = self.edge_ends(v.ring, v.edge);
                    let southward = a.y == v.hi;
                    open.insert(x, (v.ring, southward == counter_clockwise[v.ring]));
                }
                _ => {
                    parent[k] = match open.range(..x).next_back() {
                        None => Some(None),
                        Some((_, &(left, true))) => Some(Some(left)),
                        Some((_, &(left, false))) => parent[left],
                    };
                }
            }
        }
        parent
            .into_iter()
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| Error::invalid("internal error: a ring was missed by the nesting sweep"))
    }

    /// Refuses holes outside their outer ring or inside another hole, and polygons inside
    /// other polygons (their interiors would overlap).
    pub(super) fn check_nesting(&self, parent: &[Option<usize>]) -> Result<()> {
        let mut outer_of = vec![usize::MAX; self.rings.len()];
        for (k, r) in self.rings.iter().enumerate().rev() {
            outer_of[r.polygon] = k;
        }
        for (k, r) in self.rings.iter().enumerate() {
            let at = r.corners[0].pos;
            let container = parent[k].map(|p| &self.rings[p]);
            if r.hole {
                match container {
                    _ if parent[k] == Some(outer_of[r.polygon]) => {}
                    Some(c) if c.hole && c.polygon == r.polygon => {
                        return Err(self.error(
                            at,
                            "hole lies inside another hole of its polygon; expected holes with \
                             disjoint interiors",
                        ));
                    }
                    _ => {
                        return Err(self.error(
                            at,
                            "hole is not inside its outer ring; expected every inner ring of a \
                             polygon to lie inside its first ring",
                        ));
                    }
                }
            } else if let Some(c) = container
                && !c.hole
            {
                return Err(self.error(
                    at,
                    format!(
                        "polygon {} lies inside polygon {}, so their interiors overlap; expected \
                         the polygons of a MULTIPOLYGON not to overlap",
                        r.polygon + 1,
                        c.polygon + 1
                    ),
                ));
            }
        }
        Ok(())
    }
}
