use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a control character (other than tab) inside a line's values: NUL, a lone
    /// carriage return, escape sequences, DEL, or a C1 control.
    ///
    /// ## Why it matters
    /// Control characters are invisible in most editors. The robot's text-to-speech may
    /// stop at a NUL or read the rest as noise, and escape sequences can rewrite the
    /// terminal of whoever prints the file.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      2 This is\x1b[31m the Pepper robot
    /// ```
    pub static CONTROL_CHARACTER = {
        name: "control-character",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a control character (other than tab) inside a value",
    };
}

/// Reports the first control character in `span`.
pub fn check(span: Span, text: &str, out: &mut Vec<Diagnostic>) {
    let value = span.text(text);
    // Fast path: nearly every value is printable ASCII. A fold without early exit, so
    // that the compiler vectorises it (this runs on every byte of every value).
    if !value.bytes().fold(false, |odd, b| {
        odd | ((b < 0x20 && b != b'\t') | (b >= 0x7f))
    }) {
        return;
    }
    let Some((offset, ch)) = value
        .char_indices()
        .find(|&(_, ch)| ch.is_control() && ch != '\t')
    else {
        return;
    };
    let start = span.start as usize + offset;
    out.push(
        Diagnostic::new(
            &CONTROL_CHARACTER,
            Span::new(start, start + ch.len_utf8()),
            format!(
                "control character U+{:04X} inside a value: the robot would speak or print it as noise",
                ch as u32
            ),
        )
        .with_help("delete it; if it came from a copy and paste, retype the text around it"),
    );
}
