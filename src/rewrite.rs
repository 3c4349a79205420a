//! What `ekb fmt` and `ekb fix` share once they know a file's new text: show it as a diff,
//! write it in place, or send it to standard output; and the refusals that come before.
//!
//! A command that rewrites a knowledge base (`fix`, `fmt`, and `set` or `import --po` to
//! come) takes its files from [`crate::commands::Context::files_to_rewrite`] (which will
//! not rewrite a configured file outside the configuration's project unless it is named),
//! takes [`lock`] before it reads each with [`crate::commands::Context::read`] (and holds it
//! until the file is written), calls [`ensure_rewritable`], then
//! [`deliver`], which writes through [`crate::write::rewrite`]: refused if the file changed
//! since it was read, and every other guard of [`crate::write`]. [`for_each_file`] goes
//! on after a file that failed.

use std::io::{self, Write};
use std::path::Path;

use crate::commands::{CommandError, Exit};
use crate::render::escape::escape;
use crate::rules::structure::not_a_knowledge_base;
use crate::source::{LineIndex, SourceFile};
use crate::unified::{self, InOrder, NewLines};
use crate::write;

/// What to do with a file's new text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Replace the file (standard input: print the new text).
    Write,
    /// Print a unified diff and write nothing.
    Diff,
}

/// How a diff is printed.
#[derive(Debug, Clone, Copy, Default)]
pub struct DiffStyle {
    pub color: bool,
}

/// Refuses a file that was not valid UTF-8: rewriting it would replace the bad bytes; and a
/// file that is not an environment knowledge base (the culture knowledge base, say), which
/// the layout would reorder and no fix would mend.
pub fn ensure_rewritable(source: &SourceFile) -> Result<(), CommandError> {
    if let Some(first) = source.invalid_utf8().first() {
        let position = LineIndex::new(source.text()).position(source.text(), first.start);
        return Err(CommandError::Failed(format!(
            "{} is not valid UTF-8 (line {}, column {}): ekb does not rewrite it, as that would \
             lose the bad bytes; save it as UTF-8 and run again (if it is Latin-1, \
             `ekb fix --unsafe-fixes` converts it)",
            escape(source.name()),
            position.line,
            position.column
        )));
    }
    match not_a_knowledge_base::check(source.text()) {
        Some(foreign) => Err(CommandError::Failed(format!(
            "{}: {}; ekb does not rewrite it",
            escape(source.name()),
            foreign.message
        ))),
        None => Ok(()),
    }
}

/// The lock a command holds on `path` from reading it to writing it back, if `mode` writes
/// ([`crate::write::lock_to_rewrite`]): two ekb rewriting one file take turns, the second
/// reading what the first wrote.
pub fn lock(path: &Path, mode: Mode) -> Result<Option<write::RewriteLock>, CommandError> {
    match mode {
        Mode::Write => Ok(write::lock_to_rewrite(path)?),
        Mode::Diff => Ok(None),
    }
}

/// Delivers `new`, the new text of `source` read from `path`, as `mode` says. Returns whether
/// it differs from the old text.
pub fn deliver(
    path: &Path,
    source: &SourceFile,
    new: &str,
    mode: Mode,
    style: DiffStyle,
) -> Result<bool, CommandError> {
    let old = source.text();
    let changed = old != new;
    let stdin = path == Path::new("-");
    match mode {
        Mode::Diff if changed => {
            print_diff(source.name(), old, &InOrder { old, new }, style)?;
        }
        Mode::Diff => {}
        Mode::Write if stdin => io::stdout().lock().write_all(new.as_bytes())?,
        Mode::Write if changed => match source.stamp() {
            Some(read_as) => write::rewrite(path, new.as_bytes(), read_as)?,
            None => write::write_atomically(path, new.as_bytes())?,
        },
        Mode::Write => {}
    }
    Ok(changed)
}

/// Writes the new text of `source`, read from `path`, made by `fill` as it is written, in
/// place of the file (standard output for `-`): for a text too large to hold whole. Written
/// through [`crate::write::rewrite_streamed`], so refused as [`deliver`] is if the file
/// changed since it was read. If `fill` fails, the file is left as it was.
pub fn deliver_streamed(
    path: &Path,
    source: &SourceFile,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), CommandError> {
    if path == Path::new("-") {
        let mut stdout = io::BufWriter::with_capacity(1 << 16, io::stdout().lock());
        fill(&mut stdout)?;
        stdout.flush()?;
        return Ok(());
    }
    match source.stamp() {
        Some(read_as) => write::rewrite_streamed(path, read_as, fill)?,
        None => write::write_streamed(path, fill)?,
    }
    Ok(())
}

/// Runs `each` on every path, going on after a failure (reported on standard error; a
/// closed standard output is told once, at the end), and returns the worst exit.
pub fn for_each_file(
    paths: &[std::path::PathBuf],
    mut each: impl FnMut(&Path) -> Result<Exit, CommandError>,
) -> Exit {
    let mut worst = Exit::Clean;
    for path in paths {
        let exit = each(path).unwrap_or_else(|error| {
            error.report();
            Exit::Failure
        });
        if exit as u8 > worst as u8 {
            worst = exit;
        }
    }
    worst
}

/// How many lines a refusal names before it says "and N more".
pub const NAMED_LINES: usize = 5;

/// `line 4 (`gestureArm`), line 11 (`culturalKnowledge`) and 3 more`: the lines a refusal is
/// about, each with a short description.
pub fn name_lines(lines: &[(u32, String)]) -> String {
    let named: Vec<String> = lines
        .iter()
        .take(NAMED_LINES)
        .map(|(number, what)| format!("line {number} (`{what}`)"))
        .collect();
    match lines.len().saturating_sub(NAMED_LINES) {
        0 => named.join(", "),
        more => format!("{} and {more} more", named.join(", ")),
    }
}

/// Prints the unified diff of `old` and the new text `new` (nothing if they are equal),
/// written from where each new line came from ([`crate::unified`]). Returns whether they
/// differ.
pub fn print_diff(
    name: &str,
    old: &str,
    new: &(impl NewLines + Sync),
    style: DiffStyle,
) -> io::Result<bool> {
    let style = unified::Style {
        name,
        color: style.color,
    };
    unified::write_diff(&mut io::stdout().lock(), old, new, style)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_a_few_lines() {
        let lines: Vec<(u32, String)> = (1..=7).map(|n| (n, format!("k{n}"))).collect();
        assert_eq!(name_lines(&lines[..1]), "line 1 (`k1`)");
        assert_eq!(
            name_lines(&lines),
            "line 1 (`k1`), line 2 (`k2`), line 3 (`k3`), line 4 (`k4`), line 5 (`k5`) and 2 more"
        );
    }
}
