use crate::diagnostic::{Diagnostic, Edit};
use crate::rules::declare_rule;
use crate::syntax::{Body, Line, LineEnding, Span};

declare_rule! {
    /// ## What it does
    /// Flags a file whose last line does not end with a newline, and adds one.
    ///
    /// ## Why it matters
    /// The robot's reader removes the last character of every text value, assuming it is
    /// the newline. On a last line without one, it removes a real letter: `Sawubona`
    /// becomes `Sawubon`, and the last tour stop `5` can be lost.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 5 1 4 3 2 5⟨end of file⟩
    /// ```
    pub static COMPAT_NO_FINAL_NEWLINE = {
        name: "compat-no-final-newline",
        category: Compat,
        severity: Error,
        fixable: true,
        summary: "the last line has no newline",
    };
}

/// Checks the file's last line.
pub fn check(last: &Line, text: &str, out: &mut Vec<Diagnostic>) {
    if last.ending != LineEnding::None || last.span.is_empty() {
        return;
    }
    let end = last.span.end as usize;
    let message = match last.body {
        Body::Entry { args, .. } if !args.is_empty() => {
            let value = args.text(text);
            let mut shortened = value.chars();
            shortened.next_back();
            format!(
                "the file does not end with a newline: the robot's reader drops the last character of the last line, reading `…{}` instead of `…{}`",
                tail(shortened.as_str()),
                tail(value)
            )
        }
        _ => "the file does not end with a newline: the robot's reader drops the last character of the last line".to_string(),
    };
    let crlf = text.contains("\r\n");
    out.push(
        Diagnostic::new(&COMPAT_NO_FINAL_NEWLINE, Span::empty_at(end), message)
            .with_help("end the file with a newline")
            .with_fix(
                "add a newline at the end of the file",
                vec![Edit::insert(end as u32, if crlf { "\r\n" } else { "\n" })],
            ),
    );
}

fn tail(text: &str) -> &str {
    let start = text.char_indices().rev().nth(11).map_or(0, |(i, _)| i);
    &text[start..]
}
