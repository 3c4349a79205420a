use crate::check::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::rules::declare_rule;
use crate::syntax::{Line, LineEnding, Span};

declare_rule! {
    /// ## What it does
    /// Flags a file with Windows (CRLF) line endings, once, and converts them all to LF.
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

/// The span the fix replaces by `\n` in a line that ends with CRLF.
///
/// A file converted to CRLF twice ends its lines with `\r\r\n`: the `\r`s before the
/// ending (with any blanks among them) are one ending to convert, or converting `\r\n`
/// would leave another CRLF behind, pass after pass.
pub fn ending(line: &Line, text: &str) -> Option<Span> {
    if line.ending != LineEnding::CrLf {
        return None;
    }
    let bytes = text.as_bytes();
    let mut start = line.trailing.end as usize;
    let mut at = start;
    while at > line.span.start as usize && matches!(bytes[at - 1], b'\r' | b' ' | b'\t') {
        at -= 1;
        if bytes[at] == b'\r' {
            start = at;
        }
    }
    Some(Span::new(start, line.span.end as usize))
}

/// `endings` are the spans [`ending`] gave for every line that ends with CRLF, in order.
pub fn check(endings: &[Span], out: &mut Diagnostics) {
    let Some(&first) = endings.first() else {
        return;
    };
    let count = endings.len();
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
            endings.iter().map(|&span| Edit::replace(span, "\n")).collect(),
        ),
    );
}
