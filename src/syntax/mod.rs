//! The lossless syntax layer: every byte of a file belongs to exactly one part of one line.
//!
//! A file is a sequence of [`Line`]s; each line is leading whitespace, an optional body (a
//! comment, or a key followed by its arguments), trailing whitespace and a line ending.
//! Concatenating [`Line::parts`] of every line gives back the file byte for byte, which is
//! what lets `fix` and `fmt` change exactly what they mean to. The typed model in
//! [`crate::model`] is built on top of this layer and never looks at raw bytes itself.

mod blanks;
mod line;
mod span;

pub use line::{lines, lines_from, Body, Line, LineEnding, Lines, BOM};
pub use span::Span;

use blanks::{next_blank, next_non_blank};

/// Space and tab separate the fields of a line; nothing else does.
pub fn is_blank(byte: u8) -> bool {
    byte == b' ' || byte == b'\t'
}

/// Splits `text` (a slice of the file starting at `offset`) into blank-separated tokens.
pub fn tokens(text: &str, offset: usize) -> impl Iterator<Item = (Span, &str)> {
    let bytes = text.as_bytes();
    let mut pos = 0;
    std::iter::from_fn(move || {
        let start = next_non_blank(bytes, pos, bytes.len());
        if start == bytes.len() {
            return None;
        }
        pos = next_blank(bytes, start, bytes.len());
        Some((Span::new(offset + start, offset + pos), &text[start..pos]))
    })
}
