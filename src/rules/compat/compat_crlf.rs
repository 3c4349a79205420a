use crate::check::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::rules::declare_rule;
use crate::syntax::Span;

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

/// `endings` are the spans of every `\r\n` in the file, in order.
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
