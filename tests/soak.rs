//! The soak's library half (`docs/soak.md`): every reader is fed random bytes and
//! mutations of the committed fixtures; it must return `Ok` or an `Err` with a message, never
//! panic. 64 cases per reader by default; `PROPTEST_CASES` raises it (`scripts/soak.sh` does).

use mowmill::claims::{read_hunts, read_tight};
use mowmill::discrete::format::{DiscreteCover, parse_discrete, parse_json, parse_text};
use mowmill::discrete::lattice::{HexRegion, VoxelRegion};
use mowmill::gridfile::GridFile;
use mowmill::harness::config::Config;
use mowmill::harness::manifest::Recorded;
use mowmill::harness::{rows, stats};
use mowmill::ortho::Polygon;
use mowmill::pixel_list::parse_pixel_list;
use mowmill::wkt::{parse_poly, parse_wkt};
use mowmill::{CycleCover, Result};
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Seed inputs: the committed fixtures and small hand-written files of the formats that have
/// none committed (WKT, `.vox`, `.hex`, discrete JSON, configs, result CSVs).
const SEEDS: &[&str] = &[
    include_str!("../instances/fixtures/two-holes.grid"),
    include_str!("../instances/fixtures/square-3x3.grid"),
    include_str!("../instances/fixtures/tailed-frame.grid"),
    include_str!("../instances/fixtures/peers/l-shape.gg"),
    include_str!("../instances/fixtures/peers/notched-frame.poly"),
    include_str!("../instances/fixtures/square-3x3.tour.json"),
    include_str!("../instances/fixtures/rect-2x3.tour.json"),
    include_str!("../instances/discrete/bridge.dm"),
    include_str!("../instances/discrete/hub-first.dm"),
    "POLYGON ((0 0, 7 0, 7 5, 0 5, 0 0), (2 2, 2 3, 3 3, 3 2, 2 2), (4 2, 4 3, 5 3, 5 2, 4 2))\n",
    "MULTIPOLYGON (((0 0, 2.5 0, 2.5 1.5, 0 1.5, 0 0)), ((4 0, 5 0, 5 1, 4 1, 4 0)))\n",
    "x,y\n0,0\n1,0\n-3,2\n2147483647,0\n",
    "; voxels\n..\n#.\n---\n#.\n##\n---\n.#\n.#\n",
    "; hex\n.##\n###\n.#.\n",
    "{\"vertices\": 6, \"edges\": [[0,1],[0,2],[1,3],[2,3],[2,4],[3,5],[4,5]], \
     \"collinear\": [[2,0,4],[3,1,5]], \"coords\": [[0,0],[1,0],[0,1],[1,1],[0,2],[1,2]], \
     \"directions\": 2}\n",
    "{\"model\": \"discrete\", \"cycles\": [[0, 1, 3, 2]]}\n",
    "discrete 6\nd 2\ne 0 1\ne 0 2\ne 1 3\ne 2 3\np 0 0 0\np 1 1 0\np 2 0 1\np 3 1 1\n",
    "name = \"tiny\"\nseed = 1\n\n[[family]]\nfamily = \"rect\"\nwidth = [2, 3]\nheight = 2\n\n\
     [[exact]]\nobjective = \"turns\"\ntime_limit = 1\n",
    include_str!("../experiments/ci.toml"),
    "run_id,instance,sha256,family,params,seed,n,holes,algorithm,objective,value,length,turns,\
     cycles,max_coverage,opt,opt_status,lower_bound,lb_source,ratio_opt,ratio_lb,ratio_n,\
     guarantee,within_guarantee,valid,seconds,error\n\
     r,i0,ab,rect,w=2,1,4,0,boundary-cc,cc-turns,4,4,4,1,1,4,optimal,4,n,1.0,1.0,1.0,,,true,0.1,\n",
    "family,size_bin,algorithm,objective,count,ratio_opt_count,ratio_opt_mean,ratio_opt_median,\
     ratio_opt_p95,ratio_opt_max,ratio_lb_count,ratio_lb_mean,ratio_lb_median,ratio_lb_p95,\
     ratio_lb_max,ratio_n_count,ratio_n_mean,ratio_n_median,ratio_n_p95,ratio_n_max,guarantee,\
     violations,invalid,errors\n\
     donut,32-63,boundary-cc,cc-turns,1,1,1.0,1.0,1.0,1.0,1,1.0,1.0,1.0,1.0,1,0.125,0.125,0.125,\
     0.125,,0,0,0\n",
    "{\"run_id\": \"r\", \"config\": \"c.toml\", \"seed\": 1}\n",
];

/// Tokens spliced in by the mutations: the edges of the integer types and of `f64`.
const HUGE: &[&str] = &[
    "2147483647",
    "-2147483648",
    "2147483648",
    "4294967296",
    "9223372036854775807",
    "-9223372036854775808",
    "99999999999999999999999",
    "1e300",
    "-1e300",
    "NaN",
    "inf",
    "-1",
    "0",
    "50000000",
    "",
];

/// One mutation: a kind, a position and a value, applied in order by [`mutate`].
type Op = (u8, usize, usize);

fn mutate(seed: &str, ops: &[Op]) -> Vec<u8> {
    let mut b = seed.as_bytes().to_vec();
    for &(kind, pos, val) in ops {
        let at = if b.is_empty() { 0 } else { pos % (b.len() + 1) };
        match kind % 8 {
            0 if !b.is_empty() => {
                let i = pos % b.len();
                b[i] ^= 1 << (val % 8);
            }
            1 => b.truncate(at),
            2 => {
                // Duplicate the line holding `at` (possibly many times).
                let start = b[..at]
                    .iter()
                    .rposition(|&c| c == b'\n')
                    .map_or(0, |i| i + 1);
                let end = b[at..]
                    .iter()
                    .position(|&c| c == b'\n')
                    .map_or(b.len(), |i| at + i + 1);
                let line = b[start..end].to_vec();
                for _ in 0..1 + val % 4 {
                    b.splice(end..end, line.iter().copied());
                }
            }
            3 => {
                // Replace the number (or word) at `at` with a huge one.
                let is_tok = |c: u8| c.is_ascii_alphanumeric() || c == b'.' || c == b'-';
                let start = b[..at]
                    .iter()
                    .rposition(|&c| !is_tok(c))
                    .map_or(0, |i| i + 1);
                let end = b[at..]
                    .iter()
                    .position(|&c| !is_tok(c))
                    .map_or(b.len(), |i| at + i);
                let tok = HUGE[val % HUGE.len()].as_bytes().to_vec();
                b.splice(start..end, tok);
            }
            4 => {
                let end = (at + 1 + val % 16).min(b.len());
                b.drain(at..end);
            }
            5 => b.insert(at, (val % 256) as u8),
            6 => {
                // Insert a character that matters to some format.
                const SPECIAL: &[u8] = b"\n#;,-.()[]{}\"=:e ---";
                b.insert(at, SPECIAL[val % SPECIAL.len()]);
            }
            _ => {
                // Swap two lines' worth: move a chunk elsewhere.
                let len = (val % 32).min(b.len() - at.min(b.len()));
                let chunk: Vec<u8> = b.drain(at..at + len).collect();
                let to = if b.is_empty() { 0 } else { val % (b.len() + 1) };
                b.splice(to..to, chunk);
            }
        }
    }
    b
}

/// Random bytes (half of them from a small alphabet, so that they parse some way) or a
/// mutated seed.
fn input() -> impl Strategy<Value = Vec<u8>> {
    let alphabet: Vec<u8> = b"#.;\n 0123456789-,()[]{}\":POLYGONe---".to_vec();
    prop_oneof![
        1 => proptest::collection::vec(any::<u8>(), 0..256),
        1 => proptest::collection::vec(proptest::sample::select(alphabet), 0..256),
        4 => (
            0..SEEDS.len(),
            proptest::collection::vec((any::<u8>(), any::<usize>(), any::<usize>()), 1..5)
        )
            .prop_map(|(i, ops)| mutate(SEEDS[i], &ops)),
    ]
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// An `Err` must say something.
fn check<T>(result: Result<T>) {
    if let Err(e) = result {
        assert!(!e.to_string().trim().is_empty(), "empty error message");
    }
}

/// A fresh file for a path-taking reader in the temporary folder (removed after the read).
fn temp_file(name: &str, bytes: &[u8]) -> PathBuf {
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let n = COUNT.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!("mowmill-soak-{}-{n}-{name}", std::process::id()));
    std::fs::write(&path, bytes).unwrap();
    path
}

/// Runs a path-taking reader on `bytes` written to a file, then removes the file.
fn through_file<T>(name: &str, bytes: &[u8], read: impl FnOnce(&std::path::Path) -> Result<T>) {
    let path = temp_file(name, bytes);
    check(read(&path));
    let _ = std::fs::remove_file(&path);
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(64),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn grid(b in input()) { check(GridFile::parse(&text(&b), "soak.grid")); }

    #[test]
    fn pixel_list(b in input()) { check(parse_pixel_list(&text(&b), "soak.gg")); }

    #[test]
    fn wkt(b in input()) { check(parse_wkt(&text(&b), "soak.wkt")); }

    #[test]
    fn poly(b in input()) { check(parse_poly(&text(&b), "soak.poly")); }

    #[test]
    fn ortho_polygon(b in input()) { check(Polygon::parse(&text(&b), "soak.wkt")); }

    #[test]
    fn discrete_any(b in input()) { check(parse_discrete(&text(&b), "soak.dm")); }

    #[test]
    fn discrete_json(b in input()) { check(parse_json(&text(&b), "soak.json")); }

    #[test]
    fn discrete_text(b in input()) { check(parse_text(&text(&b), "soak.dm")); }

    #[test]
    fn vox(b in input()) { check(VoxelRegion::parse(&text(&b), "soak.vox")); }

    #[test]
    fn hex(b in input()) { check(HexRegion::parse(&text(&b), "soak.hex")); }

    #[test]
    fn config_toml(b in input()) { check(Config::parse(&text(&b), "soak.toml")); }

    #[test]
    fn tour_json(b in input()) { through_file("tour.json", &b, CycleCover::read); }

    #[test]
    fn ortho_tour_json(b in input()) {
        through_file("tour.json", &b, mowmill::ortho::Tour::read);
    }

    #[test]
    fn discrete_tour_json(b in input()) { through_file("tour.json", &b, DiscreteCover::read); }

    #[test]
    fn results_csv(b in input()) { through_file("results.csv", &b, rows::read_rows); }

    #[test]
    fn stats_csv(b in input()) { through_file("stats.csv", &b, stats::read); }

    #[test]
    fn tight_csv(b in input()) { through_file("tight.csv", &b, read_tight); }

    #[test]
    fn hunt_summary_csv(b in input()) { through_file("summary.csv", &b, read_hunts); }

    #[test]
    fn manifest_json(b in input()) { through_file("manifest.json", &b, Recorded::read_path); }
}

/// The mutations themselves are deterministic and reach every kind.
#[test]
fn mutations_change_the_input() {
    let seed = SEEDS[0];
    for kind in 0..8u8 {
        let out = mutate(seed, &[(kind, 17, 5)]);
        assert_ne!(
            out,
            seed.as_bytes(),
            "mutation {kind} left the seed unchanged"
        );
        assert_eq!(out, mutate(seed, &[(kind, 17, 5)]));
    }
}
