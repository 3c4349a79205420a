use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a control character (other than tab) inside a line's values: NUL, a lone
    /// carriage return, escape sequences, DEL, a C1 control, or an invisible
    /// text-direction control (U+202A–U+202E, U+2066–U+2069).
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
pub fn check(span: Span, text: &str, out: &mut Diagnostics) {
    let value = span.text(text);
    // Fast path: nearly every value is printable ASCII. Folded into a byte without an
    // early exit, so that the compiler tests 16 bytes at a time (this runs on every byte of
    // every value). `b - 0x20 >= 0x5f` is `b < 0x20 || b >= 0x7f`.
    let suspect = |chunk: &[u8]| {
        chunk.iter().fold(0u8, |odd, &b| {
            odd | (u8::from(b.wrapping_sub(0x20) >= 0x5f) & u8::from(b != b'\t'))
        }) != 0
    };
    if !value.as_bytes().chunks(64).any(suspect) {
        return;
    }
    let Some((offset, ch)) = value
        .char_indices()
        .find(|&(_, ch)| (ch.is_control() && ch != '\t') || is_bidi_control(ch))
    else {
        return;
    };
    let start = span.start as usize + offset;
    out.push_with(&CONTROL_CHARACTER, || Diagnostic::new(&CONTROL_CHARACTER,
            Span::new(start, start + ch.len_utf8()),
            if is_bidi_control(ch) {
                format!(
                    "invisible text-direction control U+{:04X} inside a value: it reorders the text on screen, so what you read is not what the robot says",
                    ch as u32
                )
            } else {
                format!(
                    "control character U+{:04X} inside a value: the robot would speak or print it as noise",
                    ch as u32
                )
            },
        )
        .with_help("delete it; if it came from a copy and paste, retype the text around it"),
    );
}

/// The bidirectional embedding, override and isolate controls: invisible, they reorder the
/// text around them on screen (the "Trojan Source" trick) while the robot says it in order.
fn is_bidi_control(ch: char) -> bool {
    matches!(ch, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}
