use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::source::SourceFile;

declare_rule! {
    /// ## What it does
    /// Flags bytes that are not valid UTF-8, with their line and byte offset.
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
