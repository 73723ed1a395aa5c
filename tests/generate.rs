//! End-to-end tests of the instance generator through its public API.

use mowmill::generate::{Family, GenParams, Style, generate};
use mowmill::gridfile::GridFile;
use mowmill::topology;
use std::time::Instant;

fn params(family: Family, seed: u64) -> GenParams {
    GenParams::new(family, seed)
}

#[test]
fn generated_files_read_back_byte_for_byte() {
    let cases = [
        GenParams {
            n: Some(120),
            ..params(Family::RandomSimple, 3)
        },
        GenParams {
            n: Some(300),
            holes: Some(2),
            no_cut: true,
            ..params(Family::RandomHoled, 4)
        },
        GenParams {
            n: Some(90),
            holes: Some(3),
            ..params(Family::Thin, 5)
        },
        GenParams {
            n: Some(100),
            parts: Some(4),
            ..params(Family::LawnScattered, 6)
        },
        GenParams {
            side: Some(9),
            k: Some(3),
            ..params(Family::Donut, 7)
        },
        GenParams {
            width: Some(4),
            height: Some(6),
            ..params(Family::Rect, 8)
        },
        GenParams {
            n: Some(80),
            ..params(Family::Boundary, 9)
        },
        GenParams {
            n: Some(70),
            holes: Some(2),
            ..params(Family::ThinArms, 10)
        },
        GenParams {
            n: Some(90),
            holes: Some(5),
            ..params(Family::Pinholes, 11)
        },
    ];
    for p in cases {
        let f = generate(&p).unwrap();
        let text = f.to_text().unwrap();
        let g = GridFile::parse(&text, "gen.grid").unwrap();
        assert_eq!(g, f, "{p:?}");
        assert_eq!(g.to_text().unwrap(), text);
        let keys: Vec<String> = g.meta_pairs().into_iter().map(|(k, _)| k).collect();
        assert_eq!(keys, ["family", "params", "seed", "n", "holes"]);
        assert_eq!(
            g.meta("n").unwrap().parse::<usize>().unwrap(),
            g.region.len()
        );
        assert_eq!(
            g.meta("holes").unwrap().parse::<usize>().unwrap(),
            topology::holes(&g.region).count
        );
    }
}

/// The same request gives the same bytes on every machine. These instances are frozen: if a
/// change to the generator alters them, every committed instance set generated from seeds
/// changes too, so update them only on purpose.
#[test]
fn frozen_instances() {
    let simple = GenParams {
        n: Some(24),
        style: Some(Style::Blob),
        compactness: Some(0.5),
        ..params(Family::RandomSimple, 1)
    };
    let holed = GenParams {
        n: Some(40),
        holes: Some(2),
        style: Some(Style::Rectangles),
        compactness: Some(0.9),
        ..params(Family::RandomHoled, 3)
    };
    let thin = GenParams {
        n: Some(25),
        holes: Some(1),
        compactness: Some(0.3),
        ..params(Family::Thin, 3)
    };
    // The hard-shape families (boundary-only, thin with arms, pinholes), frozen from their first
    // version.
    let boundary = GenParams {
        n: Some(24),
        style: Some(Style::Blob),
        compactness: Some(0.5),
        ..params(Family::Boundary, 1)
    };
    let arms = GenParams {
        n: Some(25),
        holes: Some(1),
        compactness: Some(0.8),
        ..params(Family::ThinArms, 3)
    };
    let pinholes = GenParams {
        n: Some(40),
        holes: Some(3),
        style: Some(Style::Rectangles),
        compactness: Some(0.9),
        ..params(Family::Pinholes, 3)
    };
    let got: Vec<String> = [simple, holed, thin, boundary, arms, pinholes]
        .iter()
        .map(|p| generate(p).unwrap().to_text().unwrap())
        .collect();
    let expected = [
        FROZEN_SIMPLE,
        FROZEN_HOLED,
        FROZEN_THIN,
        FROZEN_BOUNDARY,
        FROZEN_ARMS,
        FROZEN_PINHOLES,
    ];
    for (g, e) in got.iter().zip(expected) {
        assert_eq!(g, e, "got:\n{g}");
    }
}

const FROZEN_SIMPLE: &str = "; family: random-simple\n\
     ; params: n=24 no_cut=false style=blob compactness=0.5\n\
     ; seed: 1\n\
     ; n: 24\n\
     ; holes: 0\n\
     ..#...\n\
     .##...\n\
     .####.\n\
     ######\n\
     .#####\n\
     .####.\n\
     .##...\n";
const FROZEN_HOLED: &str = "; family: random-holed\n\
     ; params: n=40 holes=2 no_cut=false style=rectangles compactness=0.9\n\
     ; seed: 3\n\
     ; n: 40\n\
     ; holes: 2\n\
     ######...\n\
     #.####...\n\
     ######...\n\
     ..#######\n\
     ..##.####\n\
     ..####..#\n\
     .####....\n\
     ..#......\n";
const FROZEN_THIN: &str = "; family: thin\n\
     ; params: n=25 holes=1 compactness=0.3\n\
     ; seed: 3\n\
     ; n: 25\n\
     ; holes: 1\n\
     ....#..\n\
     #####..\n\
     ..#.#..\n\
     ..#####\n\
     ..#...#\n\
     ..#...#\n\
     ..#...#\n\
     ###.###\n";

const FROZEN_BOUNDARY: &str = "; family: boundary\n\
     ; params: n=24 style=blob compactness=0.5\n\
     ; seed: 1\n\
     ; n: 24\n\
     ; holes: 1\n\
     .#.....\n\
     .#####.\n\
     .#.#.#.\n\
     .##.###\n\
     ####..#\n\
     ...####\n\
     ...#...\n";
const FROZEN_ARMS: &str = "; family: thin-arms\n\
     ; params: n=25 holes=1 compactness=0.8\n\
     ; seed: 3\n\
     ; n: 25\n\
     ; holes: 1\n\
     .#.....\n\
     .#...#.\n\
     .##..#.\n\
     ..#####\n\
     ###.#..\n\
     ..###..\n\
     .#.#...\n\
     .####..\n\
     ..#....\n";
const FROZEN_PINHOLES: &str = "; family: pinholes\n\
     ; params: n=40 holes=3 style=rectangles compactness=0.9\n\
     ; seed: 3\n\
     ; n: 40\n\
     ; holes: 3\n\
     #...##.\n\
     #######\n\
     ###.##.\n\
     #.##...\n\
     #####..\n\
     #.#.#..\n\
     #####..\n\
     .###...\n\
     ..##...\n\
     ..##...\n\
     ..##...\n";

/// The sizes the README reports. Prints the generation time (release build):
/// `cargo test --release --test generate -- --ignored --nocapture`.
#[test]
#[ignore]
fn big_instances() {
    let mut cases = vec![
        (
            "rect 1000x1000",
            GenParams {
                width: Some(1000),
                height: Some(1000),
                ..params(Family::Rect, 1)
            },
        ),
        (
            "thin n=1e5 holes=100",
            GenParams {
                n: Some(100_000),
                holes: Some(100),
                ..params(Family::Thin, 1)
            },
        ),
        (
            "lawn-scattered n=1e6 parts=3",
            GenParams {
                n: Some(1_000_000),
                ..params(Family::LawnScattered, 1)
            },
        ),
    ];
    for style in [Style::Blob, Style::Rectangles, Style::Snake, Style::Rooms] {
        for no_cut in [false, true] {
            let st = Some(style);
            cases.push((
                "random-simple n=1e6",
                GenParams {
                    n: Some(1_000_000),
                    style: st,
                    no_cut,
                    ..params(Family::RandomSimple, 1)
                },
            ));
            cases.push((
                "random-holed n=1e6 holes=100",
                GenParams {
                    n: Some(1_000_000),
                    holes: Some(100),
                    style: st,
                    no_cut,
                    ..params(Family::RandomHoled, 1)
                },
            ));
        }
    }
    for (name, p) in cases {
        let start = Instant::now();
        let f = generate(&p).unwrap();
        let elapsed = start.elapsed();
        let expected_n = p.n.unwrap_or(1_000_000);
        assert_eq!(f.region.len(), expected_n, "{name}");
        assert_eq!(
            f.meta("holes"),
            Some(p.holes.unwrap_or(0).to_string().as_str()),
            "{name}"
        );
        println!(
            "{name:32} {:60} {:>8.2} s",
            f.meta("params").unwrap(),
            elapsed.as_secs_f64()
        );
    }
}

/// The requests of the fingerprint test: every family, with and without its optional
/// parameters (every style, `no_cut`, explicit compactness), several seeds each.
fn fingerprint_requests() -> Vec<GenParams> {
    let mut out = Vec::new();
    let styles = [
        None,
        Some(Style::Mixed),
        Some(Style::Blob),
        Some(Style::Rectangles),
        Some(Style::Snake),
        Some(Style::Rooms),
    ];
    for seed in 0..3 {
        for (w, h) in [(1, 1), (1, 7), (5, 3)] {
            out.push(GenParams {
                width: Some(w),
                height: Some(h),
                ..params(Family::Rect, seed)
            });
        }
        for (side, k) in [(3, 1), (9, 2), (12, 6)] {
            out.push(GenParams {
                side: Some(side),
                k: Some(k),
                ..params(Family::Donut, seed)
            });
        }
        for k in [1, 2, 7] {
            out.push(GenParams {
                k: Some(k),
                ..params(Family::Band, seed)
            });
        }
        for s in [0, 1, 2] {
            out.push(GenParams {
                s: Some(s),
                ..params(Family::Thin43, seed)
            });
        }
        for style in styles {
            for no_cut in [false, true] {
                for n in [1, 9, 60, 250] {
                    out.push(GenParams {
                        n: Some(n),
                        no_cut,
                        style,
                        ..params(Family::RandomSimple, seed)
                    });
                }
                for (n, holes) in [(40, None), (120, Some(3)), (300, Some(6))] {
                    out.push(GenParams {
                        n: Some(n),
                        holes,
                        no_cut,
                        style,
                        ..params(Family::RandomHoled, seed)
                    });
                }
            }
            for (n, parts) in [(30, None), (90, Some(1)), (200, Some(5))] {
                out.push(GenParams {
                    n: Some(n),
                    parts,
                    style,
                    ..params(Family::LawnScattered, seed)
                });
            }
            for n in [5, 60, 200] {
                out.push(GenParams {
                    n: Some(n),
                    style,
                    ..params(Family::Boundary, seed)
                });
            }
            for (n, holes) in [(30, 1), (150, 8)] {
                out.push(GenParams {
                    n: Some(n),
                    holes: Some(holes),
                    style,
                    ..params(Family::Pinholes, seed)
                });
            }
        }
        for compactness in [None, Some(0.0), Some(0.37), Some(1.0)] {
            for (n, holes) in [(7, None), (40, Some(2)), (200, Some(9))] {
                out.push(GenParams {
                    n: Some(n),
                    holes,
                    compactness,
                    ..params(Family::Thin, seed)
                });
                out.push(GenParams {
                    n: Some(n),
                    holes,
                    compactness,
                    ..params(Family::ThinArms, seed)
                });
            }
            out.push(GenParams {
                n: Some(150),
                holes: Some(2),
                compactness,
                style: Some(Style::Blob),
                ..params(Family::RandomHoled, seed)
            });
            out.push(GenParams {
                n: Some(150),
                compactness,
                no_cut: true,
                ..params(Family::RandomSimple, seed)
            });
        }
    }
    out
}

/// One line per request: its `Debug` form and the sha256 of the generated text (or of the
/// refusal's message).
fn fingerprints() -> String {
    use sha2::{Digest, Sha256};
    let mut out = String::new();
    for p in fingerprint_requests() {
        let text = match generate(&p) {
            Ok(f) => f.to_text().unwrap(),
            Err(e) => format!("error: {e}"),
        };
        let digest = Sha256::digest(text.as_bytes());
        let hex: String = digest.iter().map(|b| format!("{b:02x}")).collect();
        out.push_str(&format!("{hex} {p:?}\n"));
    }
    out
}

/// Generated instances are bit-identical to the recorded ones (tests/data/generate_sha256.txt,
/// written by the generator before it was split into one module per family). Rewrite the file
/// only on purpose: `MOWMILL_BLESS=1 cargo test --release --test generate fingerprints`.
#[test]
fn generated_bytes_match_the_recorded_fingerprints() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/generate_sha256.txt");
    let got = fingerprints();
    if std::env::var_os("MOWMILL_BLESS").is_some() {
        std::fs::write(&path, &got).unwrap();
    }
    let expected = std::fs::read_to_string(&path).unwrap();
    let (g, e): (Vec<&str>, Vec<&str>) = (got.lines().collect(), expected.lines().collect());
    assert_eq!(g.len(), e.len(), "number of requests");
    let differ: Vec<&&str> = g
        .iter()
        .zip(&e)
        .filter(|(a, b)| a != b)
        .map(|(a, _)| a)
        .collect();
    assert!(
        differ.is_empty(),
        "{} of {} differ, first: {}",
        differ.len(),
        g.len(),
        differ[0]
    );
}

fn mowmill(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_mowmill"))
        .args(args)
        .output()
        .unwrap()
}

/// The deterministic families need no seed (it defaults to 0); the random ones refuse to run
/// without one, with exit code 2 and a message naming the family.
#[test]
fn gen_requires_a_seed_only_for_random_families() {
    let dir = std::env::temp_dir().join(format!("mowmill-gen-seed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("x.grid");
    let out = out.to_str().unwrap();
    let deterministic: [(&str, &[&str], usize); 4] = [
        ("rect", &["--width", "3", "--height", "2"], 6),
        ("donut", &["--side", "5", "--k", "1"], 16),
        ("band", &["--k", "3"], 19),
        ("thin43", &["--s", "0"], 222),
    ];
    for (family, params, n) in deterministic {
        let o = mowmill(&[&["gen", family], params, &["--out", out]].concat());
        assert!(
            o.status.success(),
            "{family}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let f = GridFile::parse(&std::fs::read_to_string(out).unwrap(), out).unwrap();
        assert_eq!((f.meta("seed"), f.region.len()), (Some("0"), n), "{family}");
    }
    let o = mowmill(&["gen", "random-simple", "--n", "20", "--out", out]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("random-simple") && err.contains("--seed"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `gen --help` lists every family with its parameters, and the styles, from the registry.
#[test]
fn gen_help_lists_families_parameters_and_styles() {
    let o = mowmill(&["gen", "--help"]);
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout);
    for f in Family::ALL {
        assert!(help.contains(f.name()), "{f} missing from:\n{help}");
    }
    for s in Style::ALL {
        assert!(help.contains(s.name()), "{s} missing from:\n{help}");
    }
    for p in &mowmill::generate::PARAMS {
        assert!(
            help.contains(&format!("--{} ", p.flag)),
            "--{} missing",
            p.flag
        );
    }
    assert!(help.contains("pinholes        --n --holes [--style] [--compactness] --seed"));
}

/// A band larger than the pixel limit is refused with exit code 2 before anything is built.
#[test]
fn gen_refuses_a_band_above_the_pixel_limit() {
    let k = (mowmill::region::MAX_PIXELS / 5).to_string();
    let o = mowmill(&["gen", "band", "--k", &k, "--out", "/nonexistent/x.grid"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("band") && err.contains("limit"), "{err}");
}

/// Config `[[family]]` tables take exactly the registry's parameter names (plus family, count
/// and algorithms); an unknown key is an error naming the file and the key.
#[test]
fn config_keys_are_the_registry_parameters() {
    use mowmill::harness::config::Config;
    for p in &mowmill::generate::PARAMS {
        let value = match p.kind {
            mowmill::generate::ParamKind::Count => "1",
            mowmill::generate::ParamKind::Flag => "false",
            mowmill::generate::ParamKind::Style => "\"blob\"",
            mowmill::generate::ParamKind::Fraction => "0.5",
            mowmill::generate::ParamKind::Pattern => "\"staggered\"",
        };
        let text = format!(
            "name = \"t\"\n[[family]]\nfamily = \"rect\"\n{} = {value}\n",
            p.name
        );
        // Every registry name is a known key; rect refuses the ones it does not take by name.
        let e = Config::parse(&text, "ok.toml")
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(!e.contains("unknown field"), "{}: {e}", p.name);
        if !["width", "height"].contains(&p.name) {
            let refusal = format!(
                "ok.toml:4:1: family[0].{0}: parameter `{0}` does not apply",
                p.name
            );
            assert!(e.contains(&refusal), "{}: {e}", p.name);
        }
    }
    let e = Config::parse(
        "name = \"t\"\n[[family]]\nfamily = \"rect\"\nwidht = 3\n",
        "bad.toml",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("bad.toml") && e.contains("widht"), "{e}");
    let e = Config::parse(
        "name = \"t\"\n[[family]]\nfamily = \"rect\"\nno-cut = true\n",
        "bad.toml",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("bad.toml") && e.contains("no-cut"), "{e}");
}

/// `Param::spec` indexes `PARAMS` by the variant: rows and variants agree, names round-trip.
#[test]
fn params_rows_match_the_enum_and_names_round_trip() {
    use mowmill::generate::{PARAMS, Param};
    for (i, spec) in PARAMS.iter().enumerate() {
        assert_eq!(spec.param as usize, i, "{}", spec.name);
        assert_eq!(spec.param.name(), spec.name);
        assert_eq!(Param::from_name(spec.name), Some(spec.param));
    }
}

fn eroded(n: usize, style: Style, seed: u64) -> GridFile {
    let p = GenParams {
        n: Some(n),
        style: Some(style),
        ..params(Family::Eroded, seed)
    };
    generate(&p).unwrap_or_else(|e| panic!("eroded n {n} {style} seed {seed}: {e}"))
}

/// `eroded`: exactly N pixels, 4-connected, inside the square of side round(√(3N)), the same bytes for the
/// same seed, in both styles from 100 to 2900 pixels.
#[test]
fn eroded_has_exactly_n_connected_pixels_in_its_square() {
    for style in [Style::Dense, Style::Sparse] {
        for (i, n) in [100usize, 101, 700, 2900].into_iter().enumerate() {
            let seed = 40 + i as u64;
            let f = eroded(n, style, seed);
            let r = &f.region;
            assert_eq!(r.len(), n);
            assert_eq!(topology::components(r).count, 1, "{style} n {n}");
            let side = (3.0 * n as f64).sqrt().round() as i32;
            let (w, h) = r
                .pixels()
                .iter()
                .fold((0, 0), |(w, h), p| (w.max(p.x + 1), h.max(p.y + 1)));
            assert!(w <= side && h <= side, "{style} n {n}: {w} x {h} > {side}");
            assert_eq!(
                f.meta("holes").unwrap(),
                topology::holes(r).count.to_string()
            );
            assert_eq!(
                f.meta("params"),
                Some(format!("n={n} style={style}").as_str())
            );
            let again = eroded(n, style, seed);
            assert_eq!(f.to_text().unwrap(), again.to_text().unwrap());
        }
    }
    // Different seeds give different shapes.
    assert_ne!(
        eroded(300, Style::Sparse, 1).to_text().unwrap(),
        eroded(300, Style::Sparse, 2).to_text().unwrap()
    );
}

/// Sparse erosion leaves a much rougher region than dense: more boundary pixels and a larger
/// minimum strip cover (measured over seeds 0..10 at N = 1000: boundary pixels dense 202 to
/// 236, sparse 487 to 575; strip covers 697 and 1817 in all; the assertions leave a margin).
/// The hole counts are alike (135 and 121 in all): sparse holes merge and open to the outside.
#[test]
fn eroded_sparse_is_rougher_than_dense() {
    let stats = |style| -> Vec<(usize, usize)> {
        (0..10)
            .map(|seed| {
                let r = eroded(1000, style, seed).region;
                let boundary = topology::summary(&r).boundary;
                (boundary, mowmill::strip_cover::min_strip_cover_size(&r))
            })
            .collect()
    };
    let (dense, sparse) = (stats(Style::Dense), stats(Style::Sparse));
    let most_dense = dense.iter().map(|s| s.0).max().unwrap();
    let least_sparse = sparse.iter().map(|s| s.0).min().unwrap();
    assert!(
        least_sparse >= 3 * most_dense / 2,
        "boundary pixels: dense up to {most_dense}, sparse from {least_sparse}"
    );
    let strips = |v: &[(usize, usize)]| v.iter().map(|s| s.1).sum::<usize>();
    assert!(
        strips(&sparse) >= 2 * strips(&dense),
        "strip covers: dense {}, sparse {}",
        strips(&dense),
        strips(&sparse)
    );
}

/// `dense` and `sparse` are `eroded`'s styles only, and `eroded` takes no shape style.
#[test]
fn eroded_styles_are_refused_elsewhere() {
    let p = GenParams {
        n: Some(100),
        style: Some(Style::Blob),
        ..params(Family::Eroded, 1)
    };
    let e = generate(&p).unwrap_err().to_string();
    assert!(e.contains("blob") && e.contains("dense, sparse"), "{e}");
    let p = GenParams {
        n: Some(100),
        style: Some(Style::Sparse),
        ..params(Family::RandomSimple, 1)
    };
    let e = generate(&p).unwrap_err().to_string();
    assert!(e.contains("sparse") && e.contains("eroded only"), "{e}");
    // No style: one of the two, drawn from the seed and written to the file.
    let f = generate(&GenParams {
        n: Some(100),
        ..params(Family::Eroded, 5)
    })
    .unwrap();
    let line = f.meta("params").unwrap().to_string();
    assert!(
        line == "n=100 style=dense" || line == "n=100 style=sparse",
        "{line}"
    );
}
