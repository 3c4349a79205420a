//! The lossless syntax layer: every byte of a file belongs to exactly one part of one line.
//!
//! A file is a sequence of [`Line`]s; each line is leading whitespace, an optional body (a
//! comment, or a key followed by its arguments), trailing whitespace and a line ending.
//! Concatenating [`Line::parts`] of every line gives back the file byte for byte, which is
//! what lets `fix` and `fmt` change exactly what they mean to. The typed model in
//! [`crate::model`] is built on top of this layer and never looks at raw bytes itself.

mod blanks;
pub mod decimal;
mod line;
pub(crate) mod newline;
mod span;
pub mod suppression;

pub use line::{lines, lines_from, Body, Line, LineEnding, Lines, BOM};
pub use span::{floor_char_boundary, Span};

use blanks::{first_gap, next_blank, next_non_blank};

/// Space and tab separate the fields of a line; nothing else does.
pub fn is_blank(byte: u8) -> bool {
    byte == b' ' || byte == b'\t'
}

/// [`is_blank`], for a `char`.
pub fn is_blank_char(c: char) -> bool {
    c == ' ' || c == '\t'
}

/// Whether `bytes` are all white space to C's `isspace` (space, tab, newline, vertical tab,
/// form feed, carriage return): such a line is blank to the robot's reader.
pub fn is_c_space_only(bytes: &[u8]) -> bool {
    bytes.iter().all(|&byte| is_c_space(byte))
}

/// C's `isspace` in the "C" locale.
pub fn is_c_space(byte: u8) -> bool {
    matches!(byte, b' ' | b'\t' | b'\n' | 0x0b | 0x0c | b'\r')
}

/// Splits `span` of `text`, which starts with a token (as a line's arguments do), into that
/// token and the rest after the blanks that follow it (each empty if there is none): an id
/// and its value (`blanks::first_gap`).
#[inline]
pub fn first_token(text: &str, span: Span) -> (Span, Span) {
    let (start, end) = (span.start as usize, span.end as usize);
    debug_assert!(start == end || !is_blank(text.as_bytes()[start]));
    let (token_end, rest_start) = first_gap(text.as_bytes(), start, end);
    (Span::new(start, token_end), Span::new(rest_start, end))
}

/// Splits `text` (a slice of the file starting at `offset`) into blank-separated tokens.
pub fn tokens(text: &str, offset: usize) -> Tokens<'_> {
    Tokens {
        text,
        offset,
        pos: 0,
    }
}

/// Iterator returned by [`tokens`].
#[derive(Debug, Clone)]
pub struct Tokens<'a> {
    text: &'a str,
    /// Where `text` starts in the file.
    offset: usize,
    /// Where the next token is looked for in `text`.
    pos: usize,
}

impl<'a> Iterator for Tokens<'a> {
    type Item = (Span, &'a str);

    // Every value is split into tokens: inlined into each caller's loop, as the compiler
    // does not always choose to (measured: its choice moved with unrelated changes).
    #[inline(always)]
    fn next(&mut self) -> Option<(Span, &'a str)> {
        let bytes = self.text.as_bytes();
        let start = next_non_blank(bytes, self.pos, bytes.len());
        if start == bytes.len() {
            return None;
        }
        self.pos = next_blank(bytes, start, bytes.len());
        let span = Span::new(self.offset + start, self.offset + self.pos);
        // SAFETY: `start` and `pos` are at blanks (ASCII) or at the end of the text, so in
        // it and on characters' boundaries.
        let token = unsafe { self.text.get_unchecked(start..self.pos) };
        Some((span, token))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_token_and_the_rest() {
        let text = "key 12 \t value  here\nkey 7\nkey ";
        let split = |start: usize, end: usize| {
            let (token, rest) = first_token(text, Span::new(start, end));
            (token.text(text), rest.text(text), rest.start as usize)
        };
        assert_eq!(split(4, 20), ("12", "value  here", 9));
        assert_eq!(split(25, 26), ("7", "", 26));
        assert_eq!(split(31, 31), ("", "", 31));
        // As the tokens are.
        let mut tokens = tokens(&text[4..20], 4);
        assert_eq!(tokens.next(), Some((Span::new(4, 6), "12")));
        assert_eq!(tokens.next().map(|(span, _)| span.start), Some(9));
    }
}
