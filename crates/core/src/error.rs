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

    /// An algorithm's precondition does not hold on this region (e.g. it has cut vertices,
    /// holes or is not thin); the message names the algorithm and the condition.
    #[error("{0}")]
    Precondition(String),

    /// A solver (HiGHS, a matching solver, an outside algorithm's process) failed or gave up:
    /// not the input's fault.
    #[error("{0}")]
    Solver(String),

    /// An algorithm produced output the checker rejects or that cannot be read (a malformed
    /// tour file from an outside algorithm, an invalid walk).
    #[error("{0}")]
    InvalidOutput(String),
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

    pub fn precondition(message: impl Into<String>) -> Error {
        Error::Precondition(message.into())
    }

    pub fn solver(message: impl Into<String>) -> Error {
        Error::Solver(message.into())
    }

    pub fn invalid_output(message: impl Into<String>) -> Error {
        Error::InvalidOutput(message.into())
    }

    /// The process exit code for this error: 2 for bad input (parse, I/O, invalid parameters,
    /// a precondition the user asked for), 3 for a solver failure, 1 for invalid output.
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Parse { .. } | Error::Io { .. } | Error::Invalid(_) | Error::Precondition(_) => {
                2
            }
            Error::Solver(_) => 3,
            Error::InvalidOutput(_) => 1,
        }
    }
}
