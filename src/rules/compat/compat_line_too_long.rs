use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::syntax::{Line, Span};

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

pub fn check(line: &Line, text: &str, out: &mut Vec<Diagnostic>) {
    let length = line.span.len();
    if length < LINE_BUFFER {
        return;
    }
    let content = line.content();
    // The part the robot would not read with the line: from byte 199 on.
    let mut cut = (line.span.start as usize + LINE_BUFFER - 1).min(content.end as usize);
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let mut start = cut;
    if start == content.end as usize {
        // Only the newline spills over: the last character is what gets lost.
        start = text[..start]
            .char_indices()
            .next_back()
            .map_or(start, |(i, _)| i);
    }
    let kept = &text[content.start as usize..cut];
    let kept_tail: String = kept
        .chars()
        .rev()
        .take(24)
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect();
    out.push(
        Diagnostic::new(
            &COMPAT_LINE_TOO_LONG,
            Span::new(start, content.end as usize),
            format!(
                "this line is {length} bytes long, but the robot reads at most {} per line: it would stop at \"…{kept_tail}\" and read the rest as another line",
                LINE_BUFFER - 1
            ),
        )
        .with_help(format!(
            "shorten the line by {} bytes or more",
            length - (LINE_BUFFER - 1)
        )),
    );
}
