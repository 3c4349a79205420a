use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::reader::chunks;
use crate::rules::declare_rule;
use crate::syntax::{floor_char_boundary, Span};

declare_rule! {
    /// ## What it does
    /// Flags a line of the culture knowledge base or its types file of 200 bytes or more,
    /// newline included (300 or more with `--reader 2026-02`).
    ///
    /// ## Why it matters
    /// The robot reads both files with a 200-byte line buffer (`2026-02`'s copy of the
    /// reader: 300), as it reads the environment knowledge base (SPEC §2): it cuts the line
    /// after 199 bytes, keeps the first part as the value, and reads the rest as a line of
    /// its own. A long phrase is said cut off.
    ///
    /// ## Example
    /// A `utilityPhraseEnglish4` whose welcome runs past the 199th byte of its line.
    pub static CULTURE_LINE_TOO_LONG = {
        name: "culture-line-too-long",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "a culture line of 200 bytes or more, which the robot cuts in two",
    };
}

/// Checks `text` as a reader with a buffer of `line_buffer` bytes reads it.
pub fn check(text: &str, line_buffer: usize, out: &mut Diagnostics) {
    let mut pieces = chunks(text.as_bytes(), line_buffer).peekable();
    while let Some((start, piece)) = pieces.next() {
        if piece.ends_with(b"\n") || pieces.peek().is_none() {
            continue;
        }
        let cut = start + piece.len();
        // The robot cuts bytes, sometimes inside a character: the finding is about the
        // character cut in two and what follows.
        let at = floor_char_boundary(text, cut);
        let line_end = text[at..]
            .find('\n')
            .map_or(text.len(), |newline| at + newline);
        let rest = text[at..line_end].trim_end_matches('\r');
        // Point at what is cut off, or at the last character kept if only the newline is.
        let span = match rest.is_empty() {
            false => Span::new(at, at + rest.len()),
            true => {
                let last = text[..at].chars().next_back().map_or(0, char::len_utf8);
                Span::new(at - last, at)
            }
        };
        let key = text[floor_char_boundary(text, start)..at]
            .split_whitespace()
            .next()
            .unwrap_or("");
        out.push(
            Diagnostic::new(
                &CULTURE_LINE_TOO_LONG,
                span,
                format!(
                    "the line of `{}` is {line_buffer} bytes or more: the robot cuts it after \
                     {} bytes, reads the rest ({} bytes) as a line of its own, and a PHRASE \
                     loses its last character",
                    crate::rules::excerpt(key),
                    line_buffer - 1,
                    line_end + 1 - cut.min(line_end + 1),
                ),
            )
            .with_help(format!(
                "shorten the value to fit in {} bytes with its key and newline",
                line_buffer - 1
            )),
        );
    }
}
