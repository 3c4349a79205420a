//! `ekb fmt [FILE...] [--check]`: rewrite files in the canonical layout ([`crate::canonical`]).

use std::io;
use std::path::{Path, PathBuf};

use super::rewrite::{self, DiffStyle, Mode};
use super::{CommandError, CommandResult, Context, Exit};
use crate::canonical::{Document, WriteError};
use crate::render::escape::escape;
use crate::stderr_line;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base files (`-`: read standard input, write standard output) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub files: Vec<PathBuf>,

    /// Write nothing; print a diff and exit 1 if a file is not in the canonical layout
    #[arg(long)]
    pub check: bool,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let mode = if args.check { Mode::Diff } else { Mode::Write };
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let paths = context.files_to_rewrite(&args.files)?;
    let (mut changed, mut done) = (0, 0);
    let worst = rewrite::for_each_file(&paths, |path| {
        let did_change = format_file(path, context, mode, style)?;
        let on_disk = path.as_os_str() != "-";
        changed += usize::from(did_change && on_disk);
        done += usize::from(on_disk);
        Ok(if did_change && mode == Mode::Diff {
            Exit::Findings
        } else {
            Exit::Clean
        })
    });
    if !context.quiet && done > 0 {
        stderr_line!("{}", summary(mode, changed, done));
    }
    Ok(worst)
}

/// Formats one file as `mode` says; returns whether it was not in the canonical layout.
fn format_file(
    path: &Path,
    context: &Context,
    mode: Mode,
    style: DiffStyle,
) -> Result<bool, CommandError> {
    let _lock = rewrite::lock(path, mode)?;
    let source = context.read(path)?;
    rewrite::ensure_rewritable(&source)?;
    let cannot = |reason: String| {
        CommandError::Failed(format!("cannot format {}: {reason}", escape(source.name())))
    };
    let document = Document::parse(source.text()).map_err(|e| cannot(e.to_string()))?;
    if document.renders_as(source.text()) {
        // Already canonical: reading it back is reading the file again, which gave `document`.
        return rewrite::deliver(path, &source, source.text(), mode, style);
    }
    if mode == Mode::Diff {
        // The layout keeps every line and value: each line written is read back.
        return rewrite::print_diff_streamed(source.name(), source.text(), style, |mut out| {
            document
                .write_checked(&mut out)
                .map_err(|e| cannot(e.to_string()))
        });
    }
    // A formatted file can be several times the original (every id padded to column 31): it
    // is written as it is made, never held whole; each line is read back as it is written
    // (the layout keeps every line and value).
    let mut read_back = true;
    let written = rewrite::deliver_streamed(path, &source, |mut out| {
        document
            .write_checked(&mut out)
            .map_err(|error| match error {
                WriteError::Io(error) => error,
                WriteError::NotReadBack => {
                    read_back = false;
                    io::Error::other(WriteError::NotReadBack.to_string())
                }
            })
    });
    match written {
        _ if !read_back => Err(cannot(WriteError::NotReadBack.to_string())),
        Ok(()) => Ok(true),
        Err(error) => Err(error),
    }
}

/// `1 file reformatted, 2 files left unchanged` (or `would be`, with `--check`).
fn summary(mode: Mode, changed: usize, total: usize) -> String {
    let files = |n: usize| if n == 1 { "file" } else { "files" };
    let (verb, unchanged_verb) = match mode {
        Mode::Write => ("reformatted", "left unchanged"),
        Mode::Diff => ("would be reformatted", "already formatted"),
    };
    let unchanged = total - changed;
    match (changed, unchanged) {
        (0, n) => format!("{n} {} {unchanged_verb}", files(n)),
        (c, 0) => format!("{c} {} {verb}", files(c)),
        (c, n) => format!("{c} {} {verb}, {n} {} {unchanged_verb}", files(c), files(n)),
    }
}
