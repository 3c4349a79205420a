use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::mission::culture::{Entry, LINE_BUFFER};
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a line of the culture knowledge base or its types file of 200 bytes or more,
    /// newline included.
    ///
    /// ## Why it matters
    /// The robot reads both files with a 200-byte line buffer, as it reads the environment
    /// knowledge base (SPEC §2): it cuts the line after 199 bytes, keeps the first part as
    /// the value, and reads the rest as a line of its own. A long phrase is said cut off.
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

pub fn check(entries: &[Entry<'_>], text: &str, out: &mut Diagnostics) {
    for (entry, next) in entries.iter().zip(entries.iter().skip(1)) {
        if !next.continuation {
            continue;
        }
        let cut = entry.span.end as usize;
        let line_end = text[cut..].find('\n').map_or(text.len(), |at| cut + at);
        let lost = text[cut..line_end].trim_end_matches('\r');
        out.push(
            Diagnostic::new(
                &CULTURE_LINE_TOO_LONG,
                Span::new(cut, cut + lost.len()),
                format!(
                    "the line of `{}` is {} bytes or more: the robot cuts it after {} bytes, \
                     and reads \"{}\" as a line of its own",
                    entry.key,
                    LINE_BUFFER,
                    LINE_BUFFER - 1,
                    crate::rules::excerpt(lost)
                ),
            )
            .with_help("shorten the value to fit in 199 bytes with its key"),
        );
    }
}
