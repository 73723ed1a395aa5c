//! Inputs far larger than their file: a tiny WKT asking for 4·10^18 pixels and `.grid` rows of
//! 10^8 characters. Each is refused with a clear error and exit code 2, or read into a sparse
//! region, without allocating anything proportional to the bounding box: the binary runs under
//! a 1 GB address-space limit (`ulimit -v`), where a dense index over the box would abort.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("mowmill-region-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// `mowmill info FILE` under a 1 GB limit on the address space.
fn info_in_1gb(file: &Path) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 1000000 && exec \"$0\" info \"$1\"")
        .arg(env!("CARGO_BIN_EXE_mowmill"))
        .arg(file)
        .output()
        .unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn a_108_byte_wkt_asking_for_4e18_pixels_exits_2() {
    let dir = temp_dir("wkt");
    let file = dir.join("huge.wkt");
    // Within the coordinate limit (|x|, |y| < 2^30): 10^18 pixels, refused from the area.
    let wkt = "POLYGON((0 0, 1000000000 0, 1000000000 1000000000, 0 1000000000, 0 0))\n";
    std::fs::write(&file, wkt).unwrap();
    let out = info_in_1gb(&file);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("huge.wkt:1:1: the geometry encloses 1000000000000000000 pixels; expected at most 20000000"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn grid_rows_of_10_8_characters() {
    let dir = temp_dir("grid");
    const WIDTH: usize = 100_000_000;

    // 10^8 pixels in one row: refused by the pixel limit, naming the line and column.
    let full = dir.join("full.grid");
    let mut body = vec![b'#'; WIDTH];
    body.push(b'\n');
    std::fs::write(&full, [b"; one long row\n".as_slice(), &body].concat()).unwrap();
    let out = info_in_1gb(&full);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("full.grid:2:20000001: more than 20000000 pixels"),
        "{err}"
    );

    // Two pixels 10^8 - 1 apart: a sparse region of two components.
    let sparse = dir.join("sparse.grid");
    body.iter_mut().for_each(|b| *b = b'.');
    body[0] = b'#';
    body[WIDTH - 1] = b'#';
    std::fs::write(&sparse, &body).unwrap();
    let out = info_in_1gb(&sparse);
    let (stdout, err) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{err}");
    for line in [
        "n                    2",
        "components           2",
        "holes                0",
    ] {
        assert!(stdout.contains(line), "{line:?} in\n{stdout}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
