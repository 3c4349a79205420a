use crate::check::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::{Key, ValueKind};
use crate::rules::declare_rule;
use crate::syntax::{self, Body, Line, LineEnding, Span};

declare_rule! {
    /// ## What it does
    /// Flags a file whose last line does not end with a newline, and adds one.
    ///
    /// ## Why it matters
    /// The robot's reader removes the last character of every text value, assuming it is
    /// the newline. On a last line without one, it removes a real letter: `Sawubona`
    /// becomes `Sawubon`.
    ///
    /// ## Example
    /// ```text
    /// postGestureMessageIsiZulu     5 Sawubona⟨end of file⟩
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
pub fn check(last: &Line, text: &str, out: &mut Diagnostics) {
    if last.ending != LineEnding::None || last.span.is_empty() {
        return;
    }
    let end = last.span.end as usize;
    let message = match text_value(last, text) {
        Some(value) => {
            let mut shortened = value.chars();
            shortened.next_back();
            format!(
                "the file does not end with a newline: the robot's reader takes the last character for one and drops it, loading `…{}` instead of `…{}`",
                tail(shortened.as_str()),
                tail(value)
            )
        }
        None => "the file does not end with a newline: the robot's reader expects one after every line, and drops the last character of a text value that lacks it".to_string(),
    };
    out.push_with(&COMPAT_NO_FINAL_NEWLINE, || {
        Diagnostic::new(&COMPAT_NO_FINAL_NEWLINE, Span::empty_at(end), message)
            .with_help("end the file with a newline")
            // LF even in a CRLF file: `compat-crlf` converts the other endings to LF.
            .with_fix(
                "add a newline at the end of the file",
                vec![Edit::insert(end as u32, "\n")],
            )
    });
}

/// The text value of a line of a text key (after its id), if it is one.
fn text_value<'a>(line: &Line, text: &'a str) -> Option<&'a str> {
    let Body::Entry { key, args } = line.body else {
        return None;
    };
    let key = Key::from_name(key.text(text))?;
    if key.value_kind() != ValueKind::Text {
        return None;
    }
    let mut tokens = syntax::tokens(args.text(text), args.start as usize);
    tokens.next()?; // the id
    let (first, _) = tokens.next()?;
    Some(&text[first.start as usize..args.end as usize])
}

fn tail(text: &str) -> &str {
    let start = text.char_indices().rev().nth(11).map_or(0, |(i, _)| i);
    &text[start..]
}
