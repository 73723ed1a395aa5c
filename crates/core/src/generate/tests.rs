//! Unit tests of the generator (private constructions, promises, refusals).

use super::band::band_pixels;
use super::checks::{CutRule, Promise, verify};
use super::random_holed::holed_canvas;
use super::random_simple::simple_canvas;
use super::registry::{FAMILY_TABLE, Family};
use super::rng::rng_for;
use super::spec::structured;
use super::staircase::{min_holed_pixels, rows_pixels, rows_plan};
use super::styles::{ShapeOpts, Style};
use super::thin::{ceil_sqrt, min_thin_pixels, thin_capacity, thin_pixels};
use super::{GenParams, MAX_PIXELS, Provenance, generate, generate_traced};
use crate::error::Error;
use crate::gridfile::GridFile;
use crate::region::Dir;
use crate::region::Pixel;
use crate::region::Region;
use crate::topology;
use proptest::prelude::*;
use std::collections::BTreeSet;

fn params(family: Family, seed: u64) -> GenParams {
    GenParams::new(family, seed)
}

fn simple(n: usize, seed: u64) -> GenParams {
    GenParams {
        n: Some(n),
        ..params(Family::RandomSimple, seed)
    }
}

fn holed(n: usize, holes: usize, seed: u64) -> GenParams {
    GenParams {
        n: Some(n),
        holes: Some(holes),
        ..params(Family::RandomHoled, seed)
    }
}

fn thin(n: usize, holes: usize, seed: u64) -> GenParams {
    GenParams {
        n: Some(n),
        holes: Some(holes),
        ..params(Family::Thin, seed)
    }
}

fn lawn(n: usize, parts: usize, seed: u64) -> GenParams {
    GenParams {
        n: Some(n),
        parts: Some(parts),
        ..params(Family::LawnScattered, seed)
    }
}

/// Every promise of a generated file, recounted independently of `verify`.
fn assert_promises(f: &GridFile, p: &GenParams) {
    let r = &f.region;
    let s = topology::summary(r);
    assert_eq!(r.bbox().min_x, 0, "normalized");
    assert_eq!(r.bbox().min_y, 0, "normalized");
    assert_eq!(f.meta("n"), Some(s.n.to_string().as_str()));
    assert_eq!(f.meta("holes"), Some(s.holes.to_string().as_str()));
    assert_eq!(f.meta("family"), Some(p.family.name()));
    assert_eq!(f.meta("seed"), Some(p.seed.to_string().as_str()));
    // The structured families take n as an approximate size (`structured_tests`).
    if let Some(n) = p.n
        && !structured(p.family)
        && p.family != Family::ThinEulerian
    {
        assert_eq!(s.n, n, "exact n\n{r:?}");
    }
    match p.family {
        Family::RandomSimple => {
            assert_eq!((s.components, s.holes), (1, 0), "{r:?}");
            if p.no_cut {
                assert_eq!(s.cut_vertices, 0, "no cut vertex\n{r:?}");
            }
        }
        Family::RandomHoled => {
            assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(1)), "{r:?}");
            if p.no_cut {
                assert_eq!(s.local_cut_vertices, 0, "no local cut vertex\n{r:?}");
            }
        }
        Family::Thin => {
            assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(0)), "{r:?}");
            assert!(s.thin, "thin\n{r:?}");
        }
        Family::LawnScattered => {
            let parts = p.parts.unwrap_or(3);
            assert_eq!((s.components, s.holes), (parts, 0), "{r:?}");
            // 8-separation: dilating each component by one cell meets no other component.
            let comps = topology::components(r);
            for (i, &px) in r.pixels().iter().enumerate() {
                for q in topology::ring(px) {
                    if let Some(j) = r.index_of(q) {
                        assert_eq!(
                            comps.label[i], comps.label[j],
                            "parts touch at {px} and {q}\n{r:?}"
                        );
                    }
                }
            }
        }
        Family::Boundary => {
            assert_eq!(s.components, 1, "{r:?}");
            assert!(
                (0..r.len()).all(|i| topology::is_boundary(r, i)),
                "every pixel a boundary pixel\n{r:?}"
            );
        }
        Family::ThinArms => {
            assert_eq!((s.components, s.holes), (1, p.holes.unwrap_or(0)), "{r:?}");
            assert!(s.thin, "thin\n{r:?}");
        }
        Family::Pinholes => {
            assert_eq!((s.components, s.holes), (1, p.holes.unwrap()), "{r:?}");
            let cells = topology::holes(r).hole_cells();
            assert!(cells.iter().all(|h| h.len() == 1), "one-pixel holes\n{r:?}");
        }
        Family::Eroded => assert_eq!(s.components, 1, "{r:?}"),
        Family::BoundaryRooms => {
            assert_eq!(s.components, 1, "{r:?}");
            assert!(
                (0..r.len()).all(|i| topology::is_boundary(r, i)),
                "every pixel a boundary pixel\n{r:?}"
            );
        }
        Family::ThinEulerian => {
            let n = p.n.unwrap();
            assert!(s.n.abs_diff(n) <= n / 50 + 32, "{} pixels for n = {n}", s.n);
            assert_eq!(s.components, 1, "{r:?}");
            assert!(s.thin, "thin\n{r:?}");
            assert!(
                (0..r.len()).all(|i| r.degree(i).is_multiple_of(2)),
                "every degree even\n{r:?}"
            );
        }
        Family::Rect | Family::Donut | Family::Band | Family::Thin43 => {}
        // Checked with their formulas in `structured_tests`.
        Family::HoleLattice
        | Family::Comb
        | Family::DoubleComb
        | Family::Spiral
        | Family::Windows
        | Family::Outlines
        | Family::Ring
        | Family::CorridorStar => assert_eq!(s.components, 1, "{r:?}"),
    }
}

fn gen_ok(p: &GenParams) -> GridFile {
    let f = generate(p).unwrap_or_else(|e| panic!("{p:?}: {e}"));
    assert_promises(&f, p);
    f
}

fn refused(p: &GenParams) -> String {
    match generate(p) {
        Err(Error::Invalid(m)) => m,
        other => panic!("expected a refusal for {p:?}, got {other:?}"),
    }
}

#[test]
fn registry_rows_match_the_enum_and_names_round_trip() {
    for (i, f) in Family::ALL.into_iter().enumerate() {
        assert_eq!(FAMILY_TABLE[i].family, f);
        assert_eq!(f.to_string().parse::<Family>().unwrap(), f);
        for q in f.info().required {
            assert!(
                f.info().params.contains(q),
                "{f}: required {q:?} is a parameter"
            );
        }
    }
    for s in Style::ALL.into_iter().chain(Style::ERODED) {
        assert_eq!(s.to_string().parse::<Style>().unwrap(), s);
        assert!(Style::NAMES.contains(&s.name()), "{s}");
    }
    let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    assert_eq!(
        names,
        [
            "rect",
            "random-simple",
            "random-holed",
            "thin",
            "lawn-scattered",
            "donut",
            "band",
            "thin43",
            "boundary",
            "thin-arms",
            "pinholes",
            "eroded",
            "hole-lattice",
            "comb",
            "double-comb",
            "spiral",
            "windows",
            "outlines",
            "ring",
            "corridor-star",
            "boundary-rooms",
            "thin-eulerian"
        ]
    );
    let e = "disc".parse::<Family>().unwrap_err().to_string();
    assert!(e.contains("expected one of rect, random-simple"), "{e}");
    assert!("round".parse::<Style>().is_err());
}

#[test]
fn metadata_lines_are_fixed() {
    let p = GenParams {
        style: Some(Style::Blob),
        compactness: Some(0.5),
        ..simple(50, 9)
    };
    let f = gen_ok(&p);
    assert_eq!(
        f.comments,
        [
            " family: random-simple",
            " params: n=50 no_cut=false style=blob compactness=0.5",
            " seed: 9",
            " n: 50",
            " holes: 0"
        ]
    );
    let f = gen_ok(&GenParams {
        no_cut: true,
        ..holed(200, 2, 4)
    });
    let line = f.meta("params").unwrap();
    assert!(
        line.starts_with("n=200 holes=2 no_cut=true style="),
        "{line}"
    );
    let f = gen_ok(&GenParams {
        width: Some(3),
        height: Some(2),
        ..params(Family::Rect, 1)
    });
    assert_eq!(
        f.to_text().unwrap(),
        "; family: rect\n; params: width=3 height=2\n; seed: 1\n; n: 6\n; holes: 0\n###\n###\n"
    );
    let f = gen_ok(&GenParams {
        n: Some(40),
        ..params(Family::Thin, 3)
    });
    assert!(
        f.meta("params")
            .unwrap()
            .starts_with("n=40 holes=0 compactness=")
    );
    let f = gen_ok(&GenParams {
        n: Some(40),
        ..params(Family::LawnScattered, 3)
    });
    assert!(f.meta("params").unwrap().starts_with("n=40 parts=3 style="));
}

#[test]
fn same_seed_same_bytes_other_seed_other_bytes() {
    let cases = [
        simple(300, 0),
        holed(400, 3, 0),
        thin(300, 2, 0),
        lawn(300, 4, 0),
    ];
    for p in cases {
        let a = generate(&p).unwrap().to_text().unwrap();
        let b = generate(&p).unwrap().to_text().unwrap();
        assert_eq!(a, b, "{p:?}");
        let other = GenParams {
            seed: 1,
            ..p.clone()
        };
        let c = generate(&other).unwrap().to_text().unwrap();
        assert_ne!(
            a.lines().skip(5).collect::<Vec<_>>(),
            c.lines().skip(5).collect::<Vec<_>>(),
            "{p:?}"
        );
    }
}

#[test]
fn written_style_and_compactness_reproduce_the_instance() {
    for seed in 0..6 {
        for p in [
            simple(250, seed),
            holed(400, 2, seed),
            lawn(200, 3, seed),
            thin(150, 1, seed),
        ] {
            let f = gen_ok(&p);
            let line = f.meta("params").unwrap().to_string();
            let mut q = p.clone();
            for kv in line.split(' ') {
                let (k, v) = kv.split_once('=').unwrap();
                match k {
                    "style" => q.style = Some(v.parse().unwrap()),
                    "compactness" => q.compactness = Some(v.parse().unwrap()),
                    _ => {}
                }
            }
            assert_eq!(
                generate(&q).unwrap().to_text().unwrap(),
                f.to_text().unwrap(),
                "{line}"
            );
        }
    }
}

#[test]
fn rect_and_donut_counts() {
    let f = gen_ok(&GenParams {
        width: Some(7),
        height: Some(3),
        ..params(Family::Rect, 0)
    });
    assert_eq!(f.region, Region::rectangle(7, 3));
    for side in 3..14usize {
        for k in 1..=(side - 1) / 2 {
            let f = gen_ok(&GenParams {
                side: Some(side),
                k: Some(k),
                ..params(Family::Donut, 0)
            });
            let inner = side - 2 * k;
            assert_eq!(f.region.len(), side * side - inner * inner);
            assert_eq!(topology::holes(&f.region).count, 1);
            assert_eq!(topology::components(&f.region).count, 1);
            assert_eq!(f.region.bbox().width(), side);
            // The hole is the centred square.
            let cells = topology::holes(&f.region).hole_cells();
            assert_eq!(cells[0].len(), inner * inner);
            assert!(cells[0].contains(&Pixel::new(k as i32, k as i32)));
        }
    }
    assert_eq!(
        gen_ok(&GenParams {
            side: Some(5),
            k: Some(1),
            ..params(Family::Donut, 0)
        })
        .region,
        Region::from_ascii("#####\n#...#\n#...#\n#...#\n#####\n")
    );
}

#[test]
fn refusals_are_clear() {
    assert!(refused(&simple(0, 0)).contains("n ≥ 1"));
    for n in [3, 5, 7] {
        let m = refused(&GenParams {
            no_cut: true,
            ..simple(n, 0)
        });
        assert!(m.contains("cut vertex"), "{m}");
    }
    let m = refused(&holed(7, 1, 0));
    assert!(m.contains("needs n ≥ 8"), "{m}");
    let m = refused(&holed(12, 2, 0));
    assert!(m.contains("needs n ≥ 13"), "{m}");
    let m = refused(&GenParams {
        no_cut: true,
        ..holed(23, 1, 0)
    });
    assert!(m.contains("needs n ≥ 24"), "{m}");
    let m = refused(&GenParams {
        no_cut: true,
        ..holed(25, 1, 0)
    });
    assert!(
        m.contains("cannot build exactly 1 holes in exactly 25"),
        "{m}"
    );
    assert!(refused(&holed(10, 11, 0)).contains("do not fit"));
    assert!(refused(&holed(10, usize::MAX, 0)).contains("do not fit"));
    assert!(refused(&thin(7, 1, 0)).contains("n ≥ 8"));
    assert!(refused(&thin(12, 2, 0)).contains("n ≥ 13"));
    assert!(refused(&lawn(3, 4, 0)).contains("parts ≤ n"));
    assert!(refused(&lawn(3, 0, 0)).contains("parts"));
    let m = refused(&GenParams {
        no_cut: true,
        ..thin(30, 0, 0)
    });
    assert!(m.contains("`no_cut` does not apply to family thin"), "{m}");
    let m = refused(&GenParams {
        holes: Some(2),
        ..simple(30, 0)
    });
    assert!(m.contains("`holes` does not apply to family random-simple (it takes: n, no_cut, style, compactness)"), "{m}");
    let m = refused(&GenParams {
        n: Some(30),
        ..params(Family::Rect, 0)
    });
    assert!(m.contains("`n` does not apply"), "{m}");
    assert!(
        refused(&GenParams {
            width: Some(3),
            ..params(Family::Rect, 0)
        })
        .contains("needs parameter `height`")
    );
    assert!(refused(&params(Family::RandomHoled, 0)).contains("needs parameter `n`"));
    assert!(
        refused(&GenParams {
            width: Some(0),
            height: Some(3),
            ..params(Family::Rect, 0)
        })
        .contains("width ≥ 1")
    );
    assert!(
        refused(&GenParams {
            side: Some(4),
            k: Some(2),
            ..params(Family::Donut, 0)
        })
        .contains("side ≥ 2k + 1")
    );
    assert!(
        refused(&GenParams {
            side: Some(4),
            k: Some(0),
            ..params(Family::Donut, 0)
        })
        .contains("k ≥ 1")
    );
    assert!(
        refused(&GenParams {
            compactness: Some(1.5),
            ..simple(30, 0)
        })
        .contains("between 0 and 1")
    );
    assert!(
        refused(&GenParams {
            compactness: Some(f64::NAN),
            ..simple(30, 0)
        })
        .contains("between 0 and 1")
    );
    assert!(refused(&simple(MAX_PIXELS + 1, 0)).contains("limit"));
    let big = GenParams {
        width: Some(1 << 40),
        height: Some(1 << 40),
        ..params(Family::Rect, 0)
    };
    assert!(refused(&big).contains("limit"));
}

/// All fixed polyominoes with up to `max` cells, as sorted pixel sets at the origin.
fn polyominoes(max: usize) -> Vec<Vec<BTreeSet<(i32, i32)>>> {
    let mut by_size = vec![Vec::new()];
    let mut layer: BTreeSet<Vec<(i32, i32)>> = BTreeSet::from([vec![(0, 0)]]);
    for _ in 1..=max {
        by_size.push(layer.iter().map(|v| v.iter().copied().collect()).collect());
        let mut next = BTreeSet::new();
        for cells in &layer {
            for &(x, y) in cells {
                for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
                    let c = (x + dx, y + dy);
                    if cells.contains(&c) {
                        continue;
                    }
                    let mut v: Vec<(i32, i32)> = cells.iter().copied().chain([c]).collect();
                    let (mx, my) = (
                        v.iter().map(|p| p.0).min().unwrap(),
                        v.iter().map(|p| p.1).min().unwrap(),
                    );
                    v.iter_mut().for_each(|p| *p = (p.0 - mx, p.1 - my));
                    v.sort_unstable();
                    next.insert(v);
                }
            }
        }
        layer = next;
    }
    by_size
}

#[test]
fn no_cut_sizes_match_an_exhaustive_search() {
    let all = polyominoes(9);
    assert_eq!(all[7].len(), 760, "fixed heptominoes");
    for (n, polys) in all.iter().enumerate().skip(1) {
        let exists = polys.iter().any(|cells| {
            let r = Region::from_pixels(cells.iter().map(|&(x, y)| Pixel::new(x, y))).unwrap();
            topology::holes(&r).count == 0 && !topology::cut_vertices(&r).contains(&true)
        });
        let p = GenParams {
            no_cut: true,
            ..simple(n, 1)
        };
        assert_eq!(generate(&p).is_ok(), exists, "n = {n}");
        if exists {
            gen_ok(&p);
        }
    }
}

#[test]
fn staircases_keep_their_promises() {
    let mut rng = rng_for(0, 0);
    for no_cut in [false, true] {
        for holes in 0..6 {
            for n in 1..400 {
                let Some(pixels) = rows_pixels(n, holes, no_cut, &mut rng) else {
                    if !no_cut {
                        assert!(n < min_holed_pixels(holes, false), "n {n} holes {holes}");
                    }
                    continue;
                };
                assert!(n >= min_holed_pixels(holes, no_cut), "n {n} holes {holes}");
                let region = Region::from_pixels(pixels).unwrap();
                let cut = if no_cut {
                    CutRule::NoLocalCut
                } else {
                    CutRule::Any
                };
                let promise = Promise {
                    n,
                    n_slack: 0,
                    components: 1,
                    holes,
                    cut,
                    thin: false,
                    separated: false,
                    any_holes: false,
                    boundary_only: false,
                    even_degrees: false,
                };
                assert_eq!(
                    verify(&region, &promise),
                    Ok(holes),
                    "n {n} holes {holes} no_cut {no_cut}\n{region:?}"
                );
            }
        }
    }
    // Every size from the minimum up is possible without no_cut.
    for holes in 0..30 {
        let min = min_holed_pixels(holes, false);
        assert!(
            (min..min + 200).all(|n| rows_plan(n, holes, false).is_some()),
            "holes {holes}"
        );
    }
}

#[test]
fn thin_capacity_is_the_harary_harborth_bound() {
    for t in 1..5000 {
        // At most ⌊2t − 2√t⌋ = 2t − ⌈2√t⌉ = 2t − ⌈√(4t)⌉ lattice edges among t nodes.
        let max_edges = 2 * t - ceil_sqrt(4 * t);
        assert_eq!(thin_capacity(t), max_edges + 1 - t, "t = {t}");
    }
    assert_eq!(min_thin_pixels(0), 1);
    assert_eq!(min_thin_pixels(1), 8);
    assert_eq!(min_thin_pixels(2), 13);
}

#[test]
fn thin_fallback_keeps_its_promises() {
    let mut rng = rng_for(0, 0);
    for holes in 0..12 {
        for n in min_thin_pixels(holes)..min_thin_pixels(holes) + 60 {
            let pixels =
                thin_pixels(n, holes, 0.5, None, &mut rng).expect("fallback always succeeds");
            let region = Region::from_pixels(pixels).unwrap();
            let promise = Promise {
                n,
                n_slack: 0,
                components: 1,
                holes,
                cut: CutRule::Any,
                thin: true,
                separated: false,
                any_holes: false,
                boundary_only: false,
                even_degrees: false,
            };
            assert_eq!(
                verify(&region, &promise),
                Ok(holes),
                "n {n} holes {holes}\n{region:?}"
            );
        }
    }
}

/// The random constructions never return a region that breaks its promise: the retry in
/// `with_attempts` is a safety net, not a filter.
#[test]
fn random_constructions_return_only_valid_regions() {
    let (mut made, mut none) = (0, 0);
    for seed in 0..6u64 {
        for style in Style::CONCRETE {
            for no_cut in [false, true] {
                let o = ShapeOpts {
                    style,
                    compactness: seed as f64 / 5.0,
                    no_cut,
                };
                let cut = |holed: bool| match (no_cut, holed) {
                    (false, _) => CutRule::Any,
                    (true, false) => CutRule::NoCut,
                    (true, true) => CutRule::NoLocalCut,
                };
                for n in [8usize, 30, 100, 400, 1500] {
                    let mut rng = rng_for(seed, n as u64);
                    let promise = Promise {
                        n,
                        n_slack: 0,
                        components: 1,
                        holes: 0,
                        cut: cut(false),
                        thin: false,
                        separated: false,
                        any_holes: false,
                        boundary_only: false,
                        even_degrees: false,
                    };
                    match simple_canvas(n, &o, &mut rng) {
                        Some((c, _)) => {
                            let r = Region::from_pixels(c.pixels()).unwrap();
                            assert_eq!(
                                verify(&r, &promise),
                                Ok(0),
                                "{style} no_cut {no_cut} n {n}\n{r:?}"
                            );
                            made += 1;
                        }
                        None => none += 1,
                    }
                    let holes = 1 + (seed as usize + n) % 4;
                    if n < min_holed_pixels(holes, no_cut) {
                        continue;
                    }
                    let promise = Promise {
                        holes,
                        cut: cut(true),
                        ..promise
                    };
                    match holed_canvas(n, holes, &o, &mut rng) {
                        Some(c) => {
                            let r = Region::from_pixels(c.pixels()).unwrap();
                            assert_eq!(
                                verify(&r, &promise),
                                Ok(holes),
                                "{style} no_cut {no_cut} n {n}\n{r:?}"
                            );
                            made += 1;
                        }
                        None => none += 1,
                    }
                }
            }
        }
    }
    for seed in 0..40u64 {
        let (n, holes) = (20 + 23 * seed as usize, seed as usize % 6);
        let mut rng = rng_for(seed, 0);
        if let Some(pixels) = thin_pixels(n, holes, seed as f64 / 40.0, Some(seed % 3), &mut rng) {
            let r = Region::from_pixels(pixels).unwrap();
            let promise = Promise {
                n,
                n_slack: 0,
                components: 1,
                holes,
                cut: CutRule::Any,
                thin: true,
                separated: false,
                any_holes: false,
                boundary_only: false,
                even_degrees: false,
            };
            assert_eq!(verify(&r, &promise), Ok(holes), "thin n {n}\n{r:?}");
        }
    }
    assert!(
        none * 5 <= made,
        "{none} failed constructions for {made} successes"
    );
}

/// The random constructions, not the fallbacks, make the instances of ordinary sizes.
#[test]
fn fallback_stays_rare() {
    let mut fallbacks = Vec::new();
    let mut later = 0;
    let mut total = 0;
    for seed in 0..12 {
        for style in Style::ALL {
            for no_cut in [false, true] {
                let st = Some(style);
                let cases = [
                    GenParams {
                        style: st,
                        no_cut,
                        ..simple(60 + 97 * seed as usize, seed)
                    },
                    GenParams {
                        style: st,
                        no_cut,
                        ..holed(300 + 211 * seed as usize, 1 + seed as usize % 5, seed)
                    },
                ];
                for p in cases {
                    let (_, provenance) = generate_traced(&p).unwrap();
                    total += 1;
                    match provenance {
                        Provenance::Fallback => fallbacks.push(p),
                        Provenance::Attempt(a) if a > 0 => later += 1,
                        _ => {}
                    }
                }
            }
        }
    }
    assert!(fallbacks.is_empty(), "fallbacks: {fallbacks:?}");
    assert!(
        later * 10 <= total,
        "{later} of {total} needed a second attempt"
    );
    for seed in 0..20 {
        let (_, provenance) =
            generate_traced(&thin(100 + 37 * seed as usize, seed as usize % 7, seed)).unwrap();
        assert!(
            matches!(provenance, Provenance::Attempt(_)),
            "thin seed {seed}"
        );
    }
}

/// The hard-shape families come from their random constructions, not their fallbacks,
/// and show the features they are for.
#[test]
fn hard_shapes_are_random_and_show_their_features() {
    let (mut total, mut fallbacks) = (0, Vec::new());
    let (mut holed, mut links, mut crossings, mut columns) = (0, 0, 0, 0);
    for seed in 0..40u64 {
        let n = 12 + 7 * seed as usize;
        let cases = [
            GenParams {
                n: Some(n),
                ..params(Family::Boundary, seed)
            },
            GenParams {
                n: Some(n),
                holes: Some(seed as usize % 3),
                ..params(Family::ThinArms, seed)
            },
            GenParams {
                n: Some(n + 30),
                holes: Some(1 + seed as usize % 6),
                ..params(Family::Pinholes, seed)
            },
        ];
        for p in cases {
            let (f, provenance) = generate_traced(&p).unwrap();
            assert_promises(&f, &p);
            total += 1;
            if provenance == Provenance::Fallback {
                fallbacks.push(p.clone());
            }
            let r = &f.region;
            match p.family {
                Family::Boundary => {
                    holed += usize::from(topology::holes(r).count > 0);
                    // A pixel without its north and south neighbours: a one-pixel link.
                    links += usize::from((0..r.len()).any(|i| {
                        r.neighbor(i, Dir::N).is_none()
                            && r.neighbor(i, Dir::S).is_none()
                            && r.degree(i) == 2
                    }));
                }
                Family::ThinArms => {
                    crossings += usize::from((0..r.len()).any(|i| r.degree(i) == 4));
                }
                _ => {
                    let cells: BTreeSet<(i32, i32)> = topology::holes(r)
                        .hole_cells()
                        .iter()
                        .flatten()
                        .map(|p| (p.x, p.y))
                        .collect();
                    columns += usize::from(cells.iter().any(|&(x, y)| {
                        (2..=4).any(|d| cells.contains(&(x, y + d)) || cells.contains(&(x + d, y)))
                    }));
                }
            }
        }
    }
    assert!(fallbacks.len() * 20 <= total, "fallbacks: {fallbacks:?}");
    assert!(
        holed >= 10 && links >= 20,
        "boundary: {holed} holed, {links} with links"
    );
    assert!(crossings >= 10, "thin-arms: {crossings} with a crossing");
    assert!(columns >= 10, "pinholes: {columns} with holes in line");
}

fn boundary_fraction(f: &GridFile) -> f64 {
    let s = topology::summary(&f.region);
    s.boundary as f64 / s.n as f64
}

#[test]
fn compactness_and_style_change_the_shape() {
    for seed in 0..5 {
        let blob = |c: f64| GenParams {
            style: Some(Style::Blob),
            compactness: Some(c),
            ..simple(3000, seed)
        };
        let round = boundary_fraction(&gen_ok(&blob(1.0)));
        let ragged = boundary_fraction(&gen_ok(&blob(0.0)));
        assert!(
            round < 0.2 && ragged > 0.6,
            "seed {seed}: round {round}, ragged {ragged}"
        );
        let snake = GenParams {
            style: Some(Style::Snake),
            ..simple(3000, seed)
        };
        let snake = boundary_fraction(&gen_ok(&snake));
        assert!(
            snake > 2.0 * round,
            "seed {seed}: snake {snake}, round {round}"
        );
    }
    // Mixed draws every style.
    let drawn: BTreeSet<String> = (0..40)
        .map(|s| {
            gen_ok(&simple(50, s))
                .meta("params")
                .unwrap()
                .split(' ')
                .nth(2)
                .unwrap()
                .to_string()
        })
        .collect();
    assert_eq!(drawn.len(), 4, "{drawn:?}");
}

#[test]
fn holes_vary_in_size() {
    let mut sizes = BTreeSet::new();
    for seed in 0..4 {
        let f = gen_ok(&GenParams {
            style: Some(Style::Blob),
            compactness: Some(0.8),
            ..holed(4000, 6, seed)
        });
        sizes.extend(topology::holes(&f.region).hole_cells().iter().map(Vec::len));
    }
    assert!(
        sizes.len() >= 8 && *sizes.last().unwrap() >= 20,
        "hole sizes {sizes:?}"
    );
}

fn style_strategy() -> impl Strategy<Value = Option<Style>> {
    proptest::option::of(proptest::sample::select(Style::ALL.to_vec()))
}

fn compactness_strategy() -> impl Strategy<Value = Option<f64>> {
    proptest::option::of((0u32..=20).prop_map(|k| f64::from(k) / 20.0))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn random_simple_keeps_its_promises(n in 1usize..400, seed: u64, no_cut: bool,
                                        style in style_strategy(), c in compactness_strategy()) {
        prop_assume!(!(no_cut && [3, 5, 7].contains(&n)));
        gen_ok(&GenParams { no_cut, style, compactness: c, ..simple(n, seed) });
    }

    #[test]
    fn random_holed_keeps_its_promises(n in 1usize..500, holes in 0usize..7, seed: u64, no_cut: bool,
                                       style in style_strategy(), c in compactness_strategy()) {
        let p = GenParams { no_cut, style, compactness: c, ..holed(n, holes, seed) };
        if n < min_holed_pixels(holes, no_cut) || (no_cut && rows_plan(n, holes, true).is_none()) {
            refused(&p);
        } else {
            gen_ok(&p);
        }
    }

    #[test]
    fn thin_keeps_its_promises(n in 1usize..500, holes in 0usize..10, seed: u64, c in compactness_strategy()) {
        let p = GenParams { compactness: c, ..thin(n, holes, seed) };
        if n < min_thin_pixels(holes) {
            refused(&p);
        } else {
            gen_ok(&p);
        }
    }

    #[test]
    fn boundary_keeps_its_promises(n in 1usize..400, seed: u64, style in style_strategy(), c in compactness_strategy()) {
        gen_ok(&GenParams { n: Some(n), style, compactness: c, ..params(Family::Boundary, seed) });
    }

    #[test]
    fn thin_arms_keeps_its_promises(n in 1usize..400, holes in 0usize..8, seed: u64, c in compactness_strategy()) {
        let p = GenParams { n: Some(n), holes: Some(holes), compactness: c, ..params(Family::ThinArms, seed) };
        if n < min_thin_pixels(holes) {
            refused(&p);
        } else {
            gen_ok(&p);
        }
    }

    #[test]
    fn pinholes_keeps_its_promises(n in 1usize..400, holes in 0usize..12, seed: u64, style in style_strategy()) {
        let p = GenParams { n: Some(n), holes: Some(holes), style, ..params(Family::Pinholes, seed) };
        if n < min_holed_pixels(holes, false) {
            refused(&p);
        } else {
            gen_ok(&p);
        }
    }

    #[test]
    fn lawn_keeps_its_promises(n in 1usize..400, parts in 1usize..9, seed: u64, style in style_strategy()) {
        prop_assume!(parts <= n);
        gen_ok(&GenParams { style, ..lawn(n, parts, seed) });
    }
}

/// The band is built row by row in O(N): the same pixels as the definition, and a band with
/// 50 000 diagonal steps costs its 250 004 pixels, not its 2.5 · 10⁹ bounding-box cells.
#[test]
fn band_pixels_follow_the_definition_in_linear_size() {
    for k in 1..12 {
        let m = k as i32 + 1;
        let expected: Vec<Pixel> = (0..=m)
            .flat_map(|y| (0..=m).map(move |x| Pixel::new(x, y)))
            .filter(|p| (p.x - p.y).abs() <= 2)
            .collect();
        assert_eq!(band_pixels(k), expected, "k = {k}");
    }
    assert_eq!(band_pixels(50_000).len(), 5 * 50_000 + 4);
}

/// The large-scale families at test sizes: their promises (checked by `assert_promises`
/// independently of `verify`), determinism by seed, no fallback, and the features the module
/// docs name (holes; one-pixel links or crossings).
#[test]
fn large_scale_families_keep_their_promises() {
    for family in [Family::BoundaryRooms, Family::ThinEulerian] {
        let mut features = 0;
        for (i, n) in [300usize, 1000, 4000, 10_000].into_iter().enumerate() {
            for c in [0.0, 0.5, 1.0] {
                let seed = 11 + i as u64;
                let p = GenParams {
                    n: Some(n),
                    compactness: Some(c),
                    ..params(family, seed)
                };
                let (f, provenance) = generate_traced(&p).unwrap();
                assert_promises(&f, &p);
                assert_ne!(provenance, Provenance::Fallback, "{p:?}");
                assert_eq!(
                    f.to_text().unwrap(),
                    generate(&p).unwrap().to_text().unwrap(),
                    "deterministic"
                );
                let other = generate(&GenParams {
                    seed: seed + 100,
                    ..p.clone()
                })
                .unwrap();
                assert_ne!(f.region, other.region, "the seed matters");
                let r = &f.region;
                let holes = topology::holes(r).count > 0;
                let special = (0..r.len()).any(|i| match family {
                    Family::ThinEulerian => r.degree(i) == 4,
                    _ => {
                        r.neighbor(i, Dir::N).is_none()
                            && r.neighbor(i, Dir::S).is_none()
                            && r.degree(i) == 2
                    }
                });
                features += usize::from(holes && special);
            }
        }
        assert!(
            features >= 10,
            "{family}: {features} of 12 with holes and links/crossings"
        );
    }
}
