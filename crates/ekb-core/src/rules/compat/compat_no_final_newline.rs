use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit, Severity};
use crate::model::build::leading_id;
use crate::model::{Key, ValueKind};
use crate::reader;
use crate::reader::line::{LineRead, LoadedValue};
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::{self, Body, Line, LineEnding, Span};

declare_rule! {
    /// ## What it does
    /// Flags a file whose last line does not end with a newline, and adds one. An error
    /// when that line is a text value that the chosen reader reads; a warning otherwise (a
    /// last tour or pose line loads whole).
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
        summary: "the last line has no newline (an error where a text value loses its last letter)",
    };
}

/// Checks the file's last line: an error where `reader` loses a letter of it, a warning
/// otherwise.
pub fn check(text: &str, reader: Reader, out: &mut Diagnostics) {
    // Only a last line without a newline can lack one: the line after the last newline.
    let last_line_start = memchr::memrchr(b'\n', text.as_bytes()).map_or(0, |at| at + 1);
    let Some(last) = syntax::lines_from(text, last_line_start).next() else {
        return;
    };
    if last.ending != LineEnding::None || last.span.is_empty() {
        return;
    }
    let end = last.span.end as usize;
    let loses_letter = loses_a_letter(&text.as_bytes()[last_line_start..], last_line_start, reader);
    let message = match text_value(&last, text).filter(|_| loses_letter) {
        Some(value) => {
            let mut shortened = value.chars();
            shortened.next_back();
            format!(
                "the file does not end with a newline: the robot's reader ({reader}) takes the last character for one and drops it, loading `…{}` instead of `…{}`",
                tail(shortened.as_str()),
                tail(value)
            )
        }
        None => "the file does not end with a newline: the robot's reader loads this last line whole, but drops the last character of a text value that lacks one".to_string(),
    };
    let severity = if loses_letter {
        Severity::Error
    } else {
        Severity::Warning
    };
    let id = match last.body {
        Body::Entry { key, args } if key.text(text) != Key::TourSpecification.name() => {
            leading_id(args.text(text))
        }
        _ => None,
    };
    out.push_with(&COMPAT_NO_FINAL_NEWLINE, || {
        Diagnostic::new(&COMPAT_NO_FINAL_NEWLINE, Span::empty_at(end), message)
            .with_severity(severity)
            .at_location(id)
            .with_help("end the file with a newline")
            // LF even in a CRLF file: `compat-crlf` converts the other endings to LF.
            .with_fix(
                "add a newline at the end of the file",
                vec![Edit::insert(end as u32, "\n")],
            )
    });
}

/// Whether `reader` loads a text from `last`, the file's last line (at `offset`), and so
/// takes its last letter for a newline.
fn loses_a_letter(last: &[u8], offset: usize, reader: Reader) -> bool {
    let Some((offset, chunk)) = reader::chunks(last, reader.line_buffer())
        .last()
        .map(|(at, chunk)| (offset + at, chunk))
    else {
        return false;
    };
    matches!(
        reader::line::read(chunk, offset, reader),
        LineRead::Value {
            value: LoadedValue::Text(_),
            ..
        }
    )
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
