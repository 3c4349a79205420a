//! Output formats for findings: one module per `ekb check --format`.
//!
//! Every format works from [`FileReport`]s: a file's diagnostics with positions already
//! converted to lines and columns ([`located`]).

pub use ekb_core::render::{clip, escape, located, safe_json};

pub mod compact;
pub mod concise;
pub mod github;
pub mod human;
pub mod json;
pub mod markup;
pub mod sarif;
pub mod statistics;

use std::io::{self, Write};

use clap::ValueEnum;

use crate::check::Checked;
use crate::check::Summary;
use crate::robot::Reader;
pub use located::{FileReport, LocatedDiagnostic};

/// `ekb check --format`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// For people: each finding with the lines around it, underlined, and what to do
    #[default]
    Human,
    /// One line per finding: `file:line:col: severity[rule] message`
    Concise,
    /// One JSON object: every finding, with its fix, and a summary
    Json,
    /// GitHub Actions workflow commands (annotations)
    Github,
    /// SARIF 2.1.0, for GitHub code scanning and other SARIF viewers
    Sarif,
}

/// Writes the findings of `files` in `format`.
pub fn render(
    format: Format,
    files: &[Checked<'_>],
    summary: &Summary,
    out: &mut dyn Write,
    options: &RenderOptions,
) -> io::Result<()> {
    let mut reports: Vec<FileReport> = files.iter().map(FileReport::new).collect();
    // Findings are sorted by file, then position (SPEC §5); each file's are already in order.
    reports.sort_by(|a, b| a.checked.source.name().cmp(b.checked.source.name()));
    match format {
        Format::Human => human::render(&reports, summary, out, options),
        Format::Concise => concise::render(&reports, summary, out, options),
        Format::Json => json::render(&reports, summary, out),
        Format::Github => github::render(&reports, out),
        Format::Sarif => sarif::render(&reports, out),
    }
}

/// The versions of the robot's reader that the files were checked against, for the
/// summary line: `, checked against reader 2025-06`, or with several `, checked against
/// readers d5.4.2 for a.dat, …`; for people (`in_words`), which of the robot's software
/// that is: `; as the robot's software of June 2025 reads it (2025-06)`.
pub fn reader_note(reports: &[FileReport<'_>], in_words: bool) -> String {
    let reports: Vec<&FileReport> = reports.iter().filter(|r| r.read_by_reader()).collect();
    let mut readers: Vec<Reader> = reports.iter().map(|r| r.checked.reader).collect();
    readers.dedup();
    match readers.as_slice() {
        [] => String::new(),
        [one] if in_words => format!(
            "; as the robot's software {} reads it ({one})",
            one.in_words()
        ),
        [one] => format!(", checked against reader {one}"),
        _ => {
            let each: Vec<String> = reports
                .iter()
                .map(|r| {
                    format!(
                        "{} for {}",
                        r.checked.reader,
                        escape::escape(r.checked.source.name())
                    )
                })
                .collect();
            match in_words {
                true => format!("; as the robot's software reads it: {}", each.join(", ")),
                false => format!(", checked against readers {}", each.join(", ")),
            }
        }
    }
}

/// How human-facing formats are written.
#[derive(Debug, Clone, Copy)]
pub struct RenderOptions {
    pub color: bool,
    /// Leave out the closing summary.
    pub quiet: bool,
    /// Where `--format human` wraps messages and help ([`stdout_width`]).
    pub width: usize,
    /// Draw every finding, not one paragraph for a rule's many warnings (`--show-all`).
    pub show_all: bool,
}

impl Default for RenderOptions {
    fn default() -> RenderOptions {
        RenderOptions {
            color: false,
            quiet: false,
            width: DEFAULT_WIDTH,
            show_all: false,
        }
    }
}

/// Where human output wraps when it does not go to a terminal (a file, a pipe, a CI log).
pub const DEFAULT_WIDTH: usize = 100;

/// Human output never wraps narrower than this: below it, a finding's frame and indents
/// leave no room for words.
const MIN_WIDTH: usize = 40;

/// The width to wrap standard output at: `COLUMNS` (which wins, as for other tools), else
/// the terminal's, else [`DEFAULT_WIDTH`] (standard output is no terminal).
pub fn stdout_width() -> usize {
    let terminal = || terminal_size::terminal_size_of(std::io::stdout()).map(|(width, _)| width.0);
    columns()
        .or_else(terminal)
        .map_or(DEFAULT_WIDTH, |width| usize::from(width).max(MIN_WIDTH))
}

/// `COLUMNS`, when it holds a width of at least 20.
pub fn columns() -> Option<u16> {
    std::env::var("COLUMNS")
        .ok()
        .and_then(|value| value.trim().parse::<u16>().ok())
        .filter(|&width| width >= 20)
}
