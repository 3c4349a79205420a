//! The lossless syntax layer: every byte of a file belongs to exactly one part of one line.
//!
//! A file is a sequence of [`Line`]s; each line is leading whitespace, an optional body (a
//! comment, or a key followed by its arguments), trailing whitespace and a line ending.
//! Concatenating [`Line::parts`] of every line gives back the file byte for byte, which is
//! what lets `fix` and `fmt` change exactly what they mean to. The typed model in
//! [`crate::model`] is built on top of this layer and never looks at raw bytes itself.

mod blanks;
mod line;
mod newline;
mod span;
pub(crate) mod swar;

pub use line::{lines, lines_from, Body, Line, LineEnding, Lines, BOM};
pub use span::Span;

use blanks::{first_gap, next_blank, next_non_blank};

/// Space and tab separate the fields of a line; nothing else does.
pub fn is_blank(byte: u8) -> bool {
    byte == b' ' || byte == b'\t'
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
