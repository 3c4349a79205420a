//! Standard error and standard output without a panic.
//!
//! `eprintln!` and `println!` panic when their stream is a pipe nobody reads any more
//! (`ekb fix a b c d 2>&1 | head -1`), which would stop the work half-way: `c` and `d`
//! never fixed. So messages go through [`stderr`], a writer that never fails (once
//! standard error fails, the rest of the messages are dropped), or the
//! [`stderr_line!`](crate::stderr_line) macro; what a command writes to standard output
//! reports its errors as usual, and whoever goes on after one calls [`stdout_failed`].
//! Either way the failure is remembered, and [`failure`] tells the command line to exit 2
//! once the work that did not need the stream is done: an export nobody received is not
//! a success.
//!
//! The library denies `print!`, `println!`, `eprint!` and `eprintln!` (clippy's
//! `print_stdout` and `print_stderr`, in `lib.rs`), so that none comes back.

use std::fmt;
use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

static STDOUT_FAILED: AtomicBool = AtomicBool::new(false);
static STDERR_FAILED: AtomicBool = AtomicBool::new(false);

/// Standard error, locked, as a writer that never fails.
pub struct Stderr(io::StderrLock<'static>);

/// Standard error: see [`Stderr`].
pub fn stderr() -> Stderr {
    Stderr(io::stderr().lock())
}

impl Write for Stderr {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        if !STDERR_FAILED.load(Ordering::Relaxed) {
            if let Err(error) = self.0.write_all(bytes) {
                remember_stderr_failure(&error);
            }
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if let Err(error) = self.0.flush() {
            remember_stderr_failure(&error);
        }
        Ok(())
    }
}

fn remember_stderr_failure(error: &io::Error) {
    // An interrupted write is retried by `write_all`; anything else means it is gone.
    if error.kind() != io::ErrorKind::Interrupted {
        STDERR_FAILED.store(true, Ordering::Relaxed);
    }
}

/// Writes one line on standard error; see [`stderr_line!`](crate::stderr_line).
pub fn line(message: fmt::Arguments<'_>) {
    let _ = writeln!(stderr(), "{message}");
}

/// `eprintln!` that never panics: the line goes to [`stderr`].
#[macro_export]
macro_rules! stderr_line {
    ($($arg:tt)*) => {
        $crate::streams::line(format_args!($($arg)*))
    };
}

/// Remembers that standard output could not be written, for a command that goes on with
/// work that does not need it.
pub fn stdout_failed() {
    STDOUT_FAILED.store(true, Ordering::Relaxed);
}

/// The stream that could not be written, if one could not: the exit must then be 2.
pub fn failure() -> Option<&'static str> {
    if STDOUT_FAILED.load(Ordering::Relaxed) {
        Some("standard output")
    } else if STDERR_FAILED.load(Ordering::Relaxed) {
        Some("standard error")
    } else {
        None
    }
}
