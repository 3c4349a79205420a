use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::{Key, ValueKind};
use crate::rules::{declare_rule, excerpt};
use crate::syntax::{Body, Line, Span};

/// The robot reads lines with a buffer of this many bytes (one of them the terminating NUL).
pub const LINE_BUFFER: usize = 200;

declare_rule! {
    /// ## What it does
    /// Flags a line of 200 bytes or more, counting its newline. Bytes, not characters: an
    /// isiZulu or Kinyarwanda letter with an accent takes two.
    ///
    /// ## Why it matters
    /// The robot's reader reads lines into a 200-byte buffer. A longer line is cut after
    /// 199 bytes; the rest is read as a line of its own (and ignored), so the robot stops
    /// talking mid-sentence, and the message also loses its last letter.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      2 And this one is another Pepper robot, just like me! We are semi-humanoid robots … (230 bytes)
    /// ```
    /// Shorten the message to fit in 199 bytes with its key and id.
    pub static COMPAT_LINE_TOO_LONG = {
        name: "compat-line-too-long",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a line of 200 bytes or more, newline included",
    };
}

pub fn check(line: &Line, text: &str, out: &mut Diagnostics) {
    let length = line.span.len();
    if length < LINE_BUFFER {
        return;
    }
    out.push_with(&COMPAT_LINE_TOO_LONG, || diagnostic(line, text));
}

/// The finding about `line`, which is too long.
fn diagnostic(line: &Line, text: &str) -> Diagnostic {
    let length = line.span.len();
    let content = line.content();
    let content_end = content.end as usize;
    // The robot reads the first 199 bytes (here never half a character) ...
    let read_end = line.span.start as usize + LINE_BUFFER - 1;
    let mut cut = read_end.min(content_end);
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    // ... and, for a text value, drops the last of them, taking it for the newline (unless
    // that is the `\r` of a CRLF ending, which then costs no letter).
    let is_text = match line.body {
        Body::Entry { key, .. } => {
            Key::from_name(key.text(text)).is_some_and(|key| key.value_kind() == ValueKind::Text)
        }
        _ => false,
    };
    let drops_letter = is_text && read_end <= content_end;
    let last_char = |end: usize| {
        text[..end]
            .char_indices()
            .next_back()
            .map_or(end, |(i, _)| i)
    };
    let kept_end = if drops_letter {
        last_char(cut).max(content.start as usize)
    } else {
        cut
    };
    let what = if cut < content_end {
        format!(
            "the robot's reader stops at \"…{}\" and reads the rest, \"{}\", as a line of its own",
            tail(&text[content.start as usize..kept_end]),
            excerpt(&text[cut..content_end])
        )
    } else if drops_letter {
        "only its newline does not fit, so the robot's reader drops its last character instead"
            .to_string()
    } else {
        "only its line ending does not fit, and the robot's reader reads it as an empty line"
            .to_string()
    };
    // Point at what the robot loses; when that is only the newline, at the last character.
    let lost = if kept_end < content_end {
        kept_end
    } else {
        last_char(content_end)
    };
    Diagnostic::new(
        &COMPAT_LINE_TOO_LONG,
            Span::new(lost, content_end),
            format!(
                "this line is {length} bytes long, but the robot reads at most {} bytes per line: {what}",
                LINE_BUFFER - 1
            ),
        )
        .with_help(format!(
            "shorten the line by {} bytes or more",
            length - (LINE_BUFFER - 1)
        ))
}

/// The last few characters of `text`.
fn tail(text: &str) -> &str {
    let start = text.char_indices().rev().nth(23).map_or(0, |(i, _)| i);
    &text[start..]
}
