use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::reader::is_carriage_return_at_a_cut;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::{Body, Span};

declare_rule! {
    /// ## What it does
    /// Flags a control character (other than tab) inside a line's values: NUL, a lone
    /// carriage return, escape sequences, DEL, a C1 control, or an invisible
    /// text-direction control (U+202A–U+202E, U+2066–U+2069).
    ///
    /// Not a lone carriage return that is the last byte the chosen reader's line buffer
    /// holds of its line (byte 199, 299 or 599, or a multiple of 199, 299 or 599, for a
    /// buffer of 200, 300 or 600 bytes): the reader takes it for the line's end, drops it as
    /// it would the newline, and reads what follows as a line of its own. The robot neither
    /// says nor prints it (whether that cut changes what it loads is
    /// `compat-line-too-long`'s).
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

/// Reports the first control character in `span`, but a lone `\r` where some version's
/// line buffer cuts the line ([`at_some_cut`]): [`check_at_cuts`] reports those that the
/// chosen version does not cut at.
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
    let Some(start) = first_control(span, text, |at| at_some_cut(text.as_bytes(), at)) else {
        return;
    };
    report(span, start, text, out);
}

/// Where the first control character of the value at `span` is, but any at an offset that
/// `passed` passes over.
fn first_control(span: Span, text: &str, passed: impl Fn(usize) -> bool) -> Option<usize> {
    span.text(text)
        .char_indices()
        .map(|(offset, ch)| (span.start as usize + offset, ch))
        .find(|&(at, ch)| ((ch.is_control() && ch != '\t') || is_bidi_control(ch)) && !passed(at))
        .map(|(at, _)| at)
}

/// Whether the byte at `at` is a lone `\r` where the line buffer of some version of the
/// reader cuts its line.
fn at_some_cut(text: &[u8], at: usize) -> bool {
    Reader::ALL
        .into_iter()
        .any(|reader| is_carriage_return_at_a_cut(text, at, reader.line_buffer()))
}

/// Reports the lone `\r`s that [`check`] passed over and that `reader` does not take for a
/// line's end: where one is the first control character of its value that `reader` would
/// say or print.
pub fn check_at_cuts(text: &str, reader: Reader, out: &mut Diagnostics) {
    let bytes = text.as_bytes();
    let buffer = reader.line_buffer();
    for at in memchr::memchr_iter(b'\r', bytes) {
        if !at_some_cut(bytes, at) || is_carriage_return_at_a_cut(bytes, at, buffer) {
            continue;
        }
        let line_start = memchr::memrchr(b'\n', &bytes[..at]).map_or(0, |newline| newline + 1);
        let Some(line) = crate::syntax::lines_from(text, line_start).next() else {
            continue;
        };
        let Body::Entry { args, .. } = line.body else {
            continue;
        };
        let first = first_control(args, text, |at| {
            is_carriage_return_at_a_cut(bytes, at, buffer)
        });
        if first == Some(at) {
            report(args, at, text, out);
        }
    }
}

/// Reports the control character at `start` in the value at `span`.
fn report(span: Span, start: usize, text: &str, out: &mut Diagnostics) {
    let value = span.text(text);
    let ch = text[start..]
        .chars()
        .next()
        .expect("a character starts there");
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
        .at_location(crate::model::build::leading_id(value))
        .with_help("delete it; if it came from a copy and paste, retype the text around it"),
    );
}

/// Whether `text` has a byte that a control character or a text-direction control can
/// start with, in UTF-8: below U+0020 (but not a tab or a newline), U+007F, `0xC2` (U+0080
/// to U+00BF) or `0xE2` (U+2000 to U+2FFF). If not, no value in it needs [`check`].
pub fn possible_in(bytes: &[u8]) -> bool {
    // Every byte of a file passes through here: on a processor with AVX2, the same loop
    // compiled for it tests twice as many bytes an instruction.
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, as just checked.
        return unsafe { possible_in_avx2(bytes) };
    }
    possible_in_bytes(bytes)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn possible_in_avx2(bytes: &[u8]) -> bool {
    possible_in_bytes(bytes)
}

#[inline(always)]
fn possible_in_bytes(bytes: &[u8]) -> bool {
    // Folded without an early exit, so that the compiler tests many bytes at a time.
    let possible = |byte: u8| {
        (u8::from(byte < 0x20) & u8::from(byte != b'\t') & u8::from(byte != b'\n'))
            | u8::from(byte == 0x7f)
            | u8::from(byte == 0xc2)
            | u8::from(byte == 0xe2)
    };
    bytes
        .chunks(4096)
        .any(|chunk| chunk.iter().fold(0, |any, &byte| any | possible(byte)) != 0)
}

/// The bidirectional embedding, override and isolate controls: invisible, they reorder the
/// text around them on screen (the "Trojan Source" trick) while the robot says it in order.
fn is_bidi_control(ch: char) -> bool {
    matches!(ch, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_character_the_rule_flags_makes_it_possible() {
        let mut buffer = [0; 4];
        for ch in (0..=0x10FFFF).filter_map(char::from_u32) {
            if (ch.is_control() && ch != '\t' && ch != '\n') || is_bidi_control(ch) {
                let text = format!("value {}", ch.encode_utf8(&mut buffer));
                assert!(possible_in(text.as_bytes()), "U+{:04X}", ch as u32);
                assert!(possible_in_bytes(text.as_bytes()), "U+{:04X}", ch as u32);
            }
        }
    }

    #[test]
    fn a_byte_anywhere_in_a_long_text_is_found() {
        let plain = "gestureTarget 1 0.5 -2 1.25 é\n".repeat(400);
        assert!(!possible_in(plain.as_bytes()) && !possible_in_bytes(plain.as_bytes()));
        for at in [0, 31, 32, 63, 64, 4095, 4096, 8191, plain.len() - 1] {
            for flagged in ["\u{7}", "\r", "\u{7f}", "\u{85}", "\u{202e}"] {
                let mut text = plain.clone();
                text.replace_range(at..at + 1, flagged);
                assert!(possible_in(text.as_bytes()), "{flagged:?} at {at}");
                assert!(possible_in_bytes(text.as_bytes()), "{flagged:?} at {at}");
            }
        }
    }

    #[test]
    fn plain_text_needs_no_check() {
        let text = "robotLocationDescription\t1 Ùmuntu, é, ñ, ß and 中文\nnext line\n";
        assert!(!possible_in(text.as_bytes()));
        assert!(!possible_in_bytes(text.as_bytes()));
    }
}
