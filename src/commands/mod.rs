//! One module per `ekb` subcommand, and what they share: the context and the exit codes
//! ([`crate::context`]), and for those that rewrite files, [`rewrite`].

pub mod check;
pub mod completions;
pub mod diff;
pub mod explain;
pub mod export;
pub mod fix;
pub mod fmt;
pub mod import;
pub mod locations;
pub mod lsp;
pub mod man;
pub mod map;
pub mod mission;
pub mod named_values;
pub mod report;
pub mod rewrite;
pub mod rules;
pub mod serve;
pub mod set;
pub mod settings;
pub mod show;
pub mod timeline;
pub mod tour;
pub mod translations;

use crate::check::{Checked, Summary};
use crate::diagnostic::Severity;
use crate::render::{concise, FileReport, RenderOptions};
use crate::streams;

pub use crate::context::{CommandError, CommandResult, Context, Exit};

/// Lists the errors of `checked` on standard error, a concise line each, and drops its
/// other findings (for commands that write a file and tell what a person must still do).
fn errors_to_stderr(checked: &mut Checked<'_>) {
    checked
        .diagnostics
        .retain(|diagnostic| diagnostic.severity() == Severity::Error);
    let findings_only = RenderOptions {
        color: false,
        quiet: true,
        ..RenderOptions::default()
    };
    // Standard error never fails (streams::stderr); a failure is remembered there.
    let _ = concise::render(
        &[FileReport::new(checked)],
        &Summary::default(),
        &mut streams::stderr(),
        &findings_only,
    );
}
