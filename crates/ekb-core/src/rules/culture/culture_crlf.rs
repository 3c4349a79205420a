use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a culture knowledge base with CRLF (Windows) line endings, once, at the first.
    ///
    /// ## Why it matters
    /// The robot drops only the last character of a `PHRASE`'s line, taking it for the
    /// newline: with CRLF endings every phrase keeps a carriage return, which the
    /// text-to-speech engine receives with every sentence (SPEC §2).
    ///
    /// ## Example
    /// `utilityPhraseEnglish7 Goodbye␍␊`: the robot holds `Goodbye␍`.
    pub static CULTURE_CRLF = {
        name: "culture-crlf",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "CRLF line endings in the culture knowledge base",
    };
}

pub fn check(text: &str, out: &mut Diagnostics) {
    let Some(at) = text.find("\r\n") else {
        return;
    };
    let lines = text.matches("\r\n").count();
    out.push(
        Diagnostic::new(
            &CULTURE_CRLF,
            Span::new(at, at + 1),
            format!(
                "{lines} line(s) end with CRLF: the robot keeps the carriage return at the \
                 end of every PHRASE it reads"
            ),
        )
        .with_help("save the file with LF (Unix) line endings"),
    );
}
