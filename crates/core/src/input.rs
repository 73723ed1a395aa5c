//! Reading files that others wrote: instance files, tours, configs, results folders. Every
//! reader goes through [`open_regular`] / [`read_bytes`], so that no file makes mowmill wait
//! or fill its memory: a FIFO (whose `open` blocks until a writer comes), a device such as
//! `/dev/zero` (which never ends) and a directory are refused before they are opened, and a
//! regular file is read up to a bound only.

use crate::error::{Error, Result};
use std::fs::File;
use std::io::Read;
use std::path::Path;

/// The largest input file read (1 GiB): far above any instance the pixel limit admits
/// ([`crate::region::MAX_PIXELS`] pixels as a pixel list is some 200 MB), a bound so that a
/// file that grows while it is read cannot exhaust the memory.
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

/// Opens `path` for reading if it is a regular file (a symbolic link to one is followed) of at
/// most `limit` bytes; refuses a directory, a device such as `/dev/zero`, a FIFO or a socket,
/// or a larger file, naming it and what was expected (`expected`, e.g. "an instance file").
///
/// # Errors
/// [`Error::Io`] when the file cannot be read; [`Error::Invalid`] when it is not a regular
/// file or is too large.
pub fn open_regular(path: &Path, limit: u64, expected: &str) -> Result<impl Read + use<>> {
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() {
            "a directory"
        } else {
            "not a regular file (a device, FIFO or socket)"
        };
        return Err(Error::invalid(format!(
            "{}: is {kind}: expected {expected} (a regular file)",
            path.display()
        )));
    }
    if meta.len() > limit {
        return Err(Error::invalid(format!(
            "{}: is {} bytes, larger than {limit}: expected {expected} of at most {limit} bytes",
            path.display(),
            meta.len()
        )));
    }
    let file = File::open(path).map_err(|e| Error::io(path, e))?;
    // A file that grows while it is read stops one byte past the bound, so that the reader
    // can tell (see [`read_bytes`]).
    Ok(file.take(limit.saturating_add(1)))
}

/// The whole of a regular file of at most [`MAX_INPUT_BYTES`] (see [`open_regular`]).
///
/// # Errors
/// As [`open_regular`], and [`Error::Io`] when reading fails.
pub fn read_bytes(path: &Path, expected: &str) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    open_regular(path, MAX_INPUT_BYTES, expected)?
        .read_to_end(&mut bytes)
        .map_err(|e| Error::io(path, e))?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(Error::invalid(format!(
            "{}: grew while read, larger than {MAX_INPUT_BYTES} bytes: expected {expected}",
            path.display()
        )));
    }
    Ok(bytes)
}

/// [`read_bytes`] as UTF-8 text; invalid UTF-8 is an error naming the file.
///
/// # Errors
/// As [`read_bytes`], and [`Error::Invalid`] on bytes that are not UTF-8.
pub fn read_text(path: &Path, expected: &str) -> Result<String> {
    String::from_utf8(read_bytes(path, expected)?).map_err(|e| {
        Error::invalid(format!(
            "{}: expected {expected} in UTF-8: {e}",
            path.display()
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A directory, /dev/zero and a FIFO are refused without blocking; a regular file is read.
    #[test]
    fn only_regular_files_are_read() {
        let dir = tempfile::tempdir().unwrap();
        assert!(read_bytes(dir.path(), "x").is_err());
        assert!(read_bytes(Path::new("/dev/zero"), "x").is_err());
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let e = read_bytes(&fifo, "an instance file")
                .unwrap_err()
                .to_string();
            assert!(e.contains("not a regular file"), "{e}");
        }
        let f = dir.path().join("f");
        std::fs::write(&f, "abc").unwrap();
        assert_eq!(read_text(&f, "x").unwrap(), "abc");
    }
}
