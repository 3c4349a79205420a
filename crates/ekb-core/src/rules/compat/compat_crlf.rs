use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit, Severity};
use crate::reader::chunks;
use crate::reader::line::{self, LineRead, LoadedValue};
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::{Line, LineEnding, Span};

declare_rule! {
    /// ## What it does
    /// Flags a file with Windows (CRLF) line endings, once, and converts them to LF. A
    /// line whose text ends in another `\r` (`\r\r\n`) is flagged on its own and left for
    /// a person: converting its ending would make that `\r` the next one.
    ///
    /// An error where the chosen reader keeps a `\r` in a text value; a warning where it
    /// keeps none (the `\r`s end tour, number or culturalKnowledge lines, blank lines,
    /// comments, or a cut drops them): the robot loads the same, yet the fix still helps.
    ///
    /// ## Why it matters
    /// The robot's reader removes only the `\n`: the `\r` stays at the end of every text
    /// value, so descriptions compare unequal and the speech engine may read a stray
    /// character at the end of every sentence.
    ///
    /// ## Example
    /// A file saved by a Windows editor: `robotLocationDescription 1 Roomba\r\n`.
    pub static COMPAT_CRLF = {
        name: "compat-crlf",
        category: Compat,
        severity: Error,
        fixable: true,
        summary: "CRLF line endings",
    };
}

/// The CRLF endings of a file's lines, as the fix sees them.
#[derive(Debug, Default)]
pub struct CrlfEndings {
    /// The `\r\n` of each line that the fix makes `\n`.
    convertible: Vec<Span>,
    /// The last `\r` of the text of each line that ends in another `\r` before its CRLF
    /// (`\r\r\n`, as in a file converted to CRLF twice; blanks may come between). The fix
    /// leaves such a line: converting its ending would make that `\r` the next one, and
    /// take away, pass after pass, characters of the line's text.
    after_carriage_return: Vec<Span>,
}

impl CrlfEndings {
    /// Takes note of `line`'s ending if it is CRLF.
    pub fn add(&mut self, line: &Line, text: &str) {
        if line.ending != LineEnding::CrLf {
            return;
        }
        let before_blanks = line.trailing.start as usize;
        if before_blanks > line.span.start as usize && text.as_bytes()[before_blanks - 1] == b'\r' {
            self.after_carriage_return
                .push(Span::new(before_blanks - 1, before_blanks));
        } else {
            self.convertible.push(Span::new(
                line.trailing.end as usize,
                line.span.end as usize,
            ));
        }
    }
}

/// One finding for all the CRLF endings the fix converts, and one for each line it leaves.
pub fn check(endings: &CrlfEndings, out: &mut Diagnostics) {
    for &carriage_return in &endings.after_carriage_return {
        out.push_with(&COMPAT_CRLF, || {
            Diagnostic::new(
                &COMPAT_CRLF,
                carriage_return,
                "this line ends with CRLF after another `\\r`, part of its text: the robot's \
                 reader keeps both; `ekb fix` converts no ending after a `\\r` (that `\\r` \
                 would become the next ending)",
            )
            .with_help("delete the `\\r` before the line ending by hand")
        });
    }
    let Some(&first) = endings.convertible.first() else {
        return;
    };
    let count = endings.convertible.len();
    out.push_with(&COMPAT_CRLF, || Diagnostic::new(&COMPAT_CRLF,
            first,
            format!(
                "{count} line{} end{} with CRLF: the robot's reader keeps the `\\r` at the end of every text value",
                if count == 1 { "" } else { "s" },
                if count == 1 { "s" } else { "" }
            ),
        )
        .with_help("save the file with LF (Unix) line endings")
        .with_fix(
            "convert CRLF line endings to LF",
            endings.convertible.iter().map(|&span| Edit::replace(span, "\n")).collect(),
        ),
    );
}

/// Makes a warning of each finding about `\r`s that `reader` keeps in no text value, and
/// says so: the robot loads the same from those lines as it would with LF endings.
pub fn grade(text: &str, reader: Reader, out: &mut Diagnostics) {
    let bytes = text.as_bytes();
    for diagnostic in out.iter_mut() {
        if !std::ptr::eq(diagnostic.rule, &COMPAT_CRLF) {
            continue;
        }
        let kept = match diagnostic.fix.is_some() {
            // The finding for every CRLF ending of the file.
            true => memchr::memmem::find_iter(bytes, b"\r\n").any(|at| is_kept(bytes, at, reader)),
            false => is_kept(bytes, diagnostic.span.start as usize, reader),
        };
        if !kept {
            diagnostic.set_severity(Severity::Warning);
            diagnostic.message = format!(
                "{}; but reader {reader} keeps no such `\\r` in a text value (they end tour, number or culturalKnowledge lines, blank lines or comments, or a cut drops them): it loads the same as with LF endings",
                diagnostic.message.split(": the robot").next().unwrap_or_default()
            );
        }
    }
}

/// Whether `reader` keeps the `\r` at `at` in a text value it loads.
fn is_kept(bytes: &[u8], at: usize, reader: Reader) -> bool {
    let line_start = memchr::memrchr(b'\n', &bytes[..at]).map_or(0, |newline| newline + 1);
    let Some((offset, piece)) = chunks(&bytes[line_start..], reader.line_buffer())
        .find(|(offset, piece)| line_start + offset + piece.len() > at)
    else {
        return false;
    };
    match line::read(piece, line_start + offset, reader) {
        LineRead::Value {
            value: LoadedValue::Text(span),
            ..
        } => span.range().contains(&at),
        _ => false,
    }
}
