use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::encoding::Detected;
use crate::rules::declare_rule;
use crate::source::SourceFile;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags bytes that are not valid UTF-8, with their line and byte offset; or, once, a
    /// whole file in UTF-16 or UTF-32, from which the robot's reader loads nothing.
    ///
    /// ## Why it matters
    /// The knowledge base is UTF-8 text. A file saved in another encoding (Latin-1, UTF-16)
    /// or damaged by a copy turns the robot's speech into garbage, and isiZulu or
    /// Kinyarwanda letters are the first to suffer.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      1 Caf\xE9      <- a Latin-1 é
    /// ```
    /// Save the file as UTF-8 in your editor.
    ///
    /// ## Fix (unsafe)
    /// `ekb fix --unsafe-fixes` reads every byte that is not UTF-8 as Windows-1252 (the
    /// Latin-1 of Windows editors) and writes the file as UTF-8; a guess, as the bytes could
    /// be another encoding. A file with NUL bytes (UTF-16?) is refused.
    pub static INVALID_UTF8 = {
        name: "invalid-utf8",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "the file is not UTF-8",
    };
}

/// Reports the first invalid sequence of each line.
pub fn check(source: &SourceFile, out: &mut Diagnostics) {
    let text = source.text().as_bytes();
    let mut previous_line_end = None;
    for &span in source.invalid_utf8() {
        if previous_line_end.is_some_and(|end| span.start < end) {
            continue;
        }
        previous_line_end = Some(
            memchr::memchr(b'\n', &text[span.end as usize..])
                .map_or(text.len() as u32, |i| span.end + i as u32),
        );
        out.push_with(&INVALID_UTF8, || Diagnostic::new(&INVALID_UTF8,
                span,
                format!(
                    "{} at byte offset {} is not valid UTF-8: the robot would speak or match garbage here",
                    if span.len() == 1 { "this byte" } else { "these bytes" },
                    span.start
                ),
            )
            .with_help(
                "save the file as UTF-8 (ekb shows the bad bytes as `?`); if it is Latin-1, \
                 `ekb fix --unsafe-fixes` converts it",
            ),
        );
    }
}

/// The finding about a file in a wide encoding (UTF-16 or UTF-32): the robot's reader reads
/// its bytes as if they were single-byte text, finds the first word of each line cut short
/// by a NUL byte (`r\0o\0b…`), and loads nothing.
pub fn wide(wide: Detected) -> Diagnostic {
    let name = wide.encoding.name();
    Diagnostic::new(
        &INVALID_UTF8,
        Span::empty_at(0),
        format!(
            "this file is {name} text, not UTF-8: the robot's reader reads it byte by byte, finds no key on any line (each is cut short by a NUL byte), and loads nothing from it"
        ),
    )
    .with_help(format!(
        "convert it to UTF-8, e.g. `iconv -f {name} -t UTF-8 FILE > NEW` (ekb rewrites no such file)"
    ))
}
