//! Output formats for findings: one module per `ekb check --format`.
//!
//! Every format works from [`FileReport`]s: a file's diagnostics with positions already
//! converted to lines and columns ([`located`]).

pub mod concise;
pub mod escape;
pub mod github;
pub mod json;
pub mod located;

use std::io::{self, Write};

use clap::ValueEnum;

use crate::check::Checked;
use crate::diagnostic::Summary;
pub use located::{FileReport, LocatedDiagnostic};

/// `ekb check --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One line per finding: `file:line:col: severity[rule] message`
    Concise,
    /// One JSON object (SPEC §5)
    Json,
    /// GitHub Actions workflow commands (annotations)
    Github,
}

/// Writes the findings of `files` in `format`.
pub fn render(
    format: Format,
    files: &[Checked<'_>],
    summary: &Summary,
    out: &mut dyn Write,
    options: &RenderOptions,
) -> io::Result<()> {
    let reports: Vec<FileReport> = files.iter().map(FileReport::new).collect();
    match format {
        Format::Concise => concise::render(&reports, summary, out, options),
        Format::Json => json::render(&reports, summary, out),
        Format::Github => github::render(&reports, out),
    }
}

/// How human-facing formats are written.
#[derive(Debug, Clone, Copy, Default)]
pub struct RenderOptions {
    pub color: bool,
    /// Leave out the closing summary.
    pub quiet: bool,
}
