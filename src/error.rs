//! The library's error type. Input errors name the file, line and column and say what was
//! expected; the binary maps them to exit code 2.

use std::path::Path;

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Malformed input: `file:line:column: message` (line and column start at 1).
    #[error("{file}:{line}:{column}: {message}")]
    Parse {
        file: String,
        line: usize,
        column: usize,
        message: String,
    },

    /// A file could not be read or written.
    #[error("{file}: {source}")]
    Io {
        file: String,
        #[source]
        source: std::io::Error,
    },

    /// Well-formed input that the operation cannot accept (an empty region, a precondition of
    /// an algorithm, a parameter out of range).
    #[error("{0}")]
    Invalid(String),
}

impl Error {
    pub fn parse(file: &str, line: usize, column: usize, message: impl Into<String>) -> Error {
        Error::Parse {
            file: file.to_string(),
            line,
            column,
            message: message.into(),
        }
    }

    pub fn io(file: &Path, source: std::io::Error) -> Error {
        Error::Io {
            file: file.display().to_string(),
            source,
        }
    }

    pub fn invalid(message: impl Into<String>) -> Error {
        Error::Invalid(message.into())
    }
}
