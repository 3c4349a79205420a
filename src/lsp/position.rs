//! LSP positions (0-based line, column in the negotiated encoding) and the byte offsets the
//! library works in (SPEC §9).
//!
//! LSP ends a line at `\n`, `\r\n` or a lone `\r`; the knowledge-base format (and so
//! [`crate::source::LineIndex`]) knows only `\n`. A lone `\r` is rare in a knowledge base,
//! but client and server must count the same lines, so this index follows LSP.

use lsp_types::{Position, PositionEncodingKind, Range};

use crate::syntax::Span;

/// How a position's column counts: the client's choice among those it offers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Encoding {
    Utf8,
    /// The protocol's default, which every client supports.
    #[default]
    Utf16,
    Utf32,
}

impl Encoding {
    /// The encoding to use given those the client offers (none offered: UTF-16). UTF-8 is
    /// preferred: byte offsets are what the library works in.
    pub fn negotiate(offered: Option<&[PositionEncodingKind]>) -> Encoding {
        let offered = offered.unwrap_or_default();
        let offers = |kind: &PositionEncodingKind| offered.contains(kind);
        if offers(&PositionEncodingKind::UTF8) {
            Encoding::Utf8
        } else if offers(&PositionEncodingKind::UTF32) && !offers(&PositionEncodingKind::UTF16) {
            Encoding::Utf32
        } else {
            Encoding::Utf16
        }
    }

    pub fn kind(self) -> PositionEncodingKind {
        match self {
            Encoding::Utf8 => PositionEncodingKind::UTF8,
            Encoding::Utf16 => PositionEncodingKind::UTF16,
            Encoding::Utf32 => PositionEncodingKind::UTF32,
        }
    }

    /// How many units `c` counts for.
    fn units(self, c: char) -> u32 {
        match self {
            Encoding::Utf8 => c.len_utf8() as u32,
            Encoding::Utf16 => c.len_utf16() as u32,
            Encoding::Utf32 => 1,
        }
    }

    /// How many units `text` counts for.
    fn len(self, text: &str) -> u32 {
        match self {
            Encoding::Utf8 => text.len() as u32,
            _ if text.is_ascii() => text.len() as u32,
            _ => text.chars().map(|c| self.units(c)).sum(),
        }
    }
}

/// Where each line of a text starts, LSP's way.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct LineIndex {
    /// The byte offset of each line's first byte; the first is 0.
    starts: Vec<u32>,
    /// The text's length in bytes.
    len: u32,
}

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let bytes = text.as_bytes();
        let mut starts = vec![0];
        for at in memchr::memchr2_iter(b'\n', b'\r', bytes) {
            // The `\r` of a `\r\n` is not an end of its own.
            if bytes[at] == b'\r' && bytes.get(at + 1) == Some(&b'\n') {
                continue;
            }
            starts.push(at as u32 + 1);
        }
        LineIndex {
            starts,
            len: text.len() as u32,
        }
    }

    /// The index of the text after its bytes `span` were replaced by `new` (which must be
    /// what the text now holds there): only the line starts the edit can change are found
    /// again, the others shifted (a 60 MB document is not scanned again for every key typed).
    pub fn edited(&mut self, text: &str, span: Span, new: &str) {
        let (start, end) = (span.start, span.end);
        let inserted = new.len() as u32;
        // A line start depends on the byte before it and (for `\r\n`) on itself: those
        // from `start` to the end of the new text may have changed.
        let first = self.starts.partition_point(|&p| p < start.max(1));
        let after = self.starts.partition_point(|&p| p <= end);
        let bytes = text.as_bytes();
        let starts_line = |p: u32| match bytes[p as usize - 1] {
            b'\n' => true,
            b'\r' => bytes.get(p as usize) != Some(&b'\n'),
            _ => false,
        };
        let found: Vec<u32> = (start.max(1)..=start + inserted)
            .filter(|&p| starts_line(p))
            .collect();
        for p in &mut self.starts[after..] {
            *p = *p - end + start + inserted;
        }
        self.starts.splice(first..after, found);
        self.len = text.len() as u32;
    }

    /// The 0-based line that holds byte `offset`.
    fn line_of(&self, offset: u32) -> usize {
        self.starts.partition_point(|&start| start <= offset) - 1
    }

    /// The bytes of 0-based `line` without its line ending, or `None` past the last line.
    fn line_content(&self, text: &str, line: usize) -> Option<(u32, u32)> {
        let start = *self.starts.get(line)?;
        let end = self.starts.get(line + 1).map_or(self.len, |&next| next);
        let line = &text[start as usize..end as usize];
        // The line's own ending (the last line has none): `\r\n`, `\n` or `\r`.
        let content = match line.strip_suffix("\r\n") {
            Some(content) => content,
            None => line.strip_suffix(['\n', '\r']).unwrap_or(line),
        };
        Some((start, start + content.len() as u32))
    }
}

/// Converts between byte offsets of one text and LSP positions in one encoding.
#[derive(Debug, Clone, Copy)]
pub struct Positions<'a> {
    pub text: &'a str,
    pub index: &'a LineIndex,
    pub encoding: Encoding,
}

impl Positions<'_> {
    /// The position of byte `offset` (clamped to the text, and back to a character's start).
    pub fn position(&self, offset: u32) -> Position {
        let offset = self.boundary(offset.min(self.index.len));
        let line = self.index.line_of(offset);
        let start = self.index.starts[line];
        let before = &self.text[start as usize..offset as usize];
        Position::new(line as u32, self.encoding.len(before))
    }

    /// The LSP range of `span`.
    pub fn range(&self, span: Span) -> Range {
        Range::new(self.position(span.start), self.position(span.end))
    }

    /// The byte offset of `position`. A line past the last is the end of the text; a column
    /// past the end of its line is the line's end (as the protocol asks); a column inside a
    /// character is that character's start.
    pub fn offset(&self, position: Position) -> u32 {
        let Some((start, end)) = self.index.line_content(self.text, position.line as usize) else {
            return self.index.len;
        };
        let line = &self.text[start as usize..end as usize];
        if self.encoding == Encoding::Utf8 || line.is_ascii() {
            let at = start + position.character.min(end - start);
            return self.boundary(at);
        }
        let mut units = 0;
        for (at, c) in line.char_indices() {
            units += self.encoding.units(c);
            if units > position.character {
                return start + at as u32;
            }
        }
        end
    }

    /// The byte span of `range` (its ends in order, whatever the client sent).
    pub fn span(&self, range: Range) -> Span {
        let (a, b) = (self.offset(range.start), self.offset(range.end));
        Span::new(a.min(b) as usize, a.max(b) as usize)
    }

    /// `offset`, moved back to the start of the character it is in.
    fn boundary(&self, mut offset: u32) -> u32 {
        while !self.text.is_char_boundary(offset as usize) {
            offset -= 1;
        }
        offset
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn positions(text: &str, encoding: Encoding) -> (LineIndex, Encoding) {
        (LineIndex::new(text), encoding)
    }

    #[test]
    fn lines_end_at_any_of_the_three_line_endings() {
        let text = "a\nb\r\nc\rd";
        let (index, encoding) = positions(text, Encoding::Utf16);
        let p = Positions {
            text,
            index: &index,
            encoding,
        };
        assert_eq!(
            p.position(text.find('d').unwrap() as u32),
            Position::new(3, 0)
        );
        assert_eq!(
            p.position(text.find('c').unwrap() as u32),
            Position::new(2, 0)
        );
        // Past the end of a line: its end, before the `\r\n`.
        assert_eq!(p.offset(Position::new(1, 9)), 3);
        assert_eq!(p.offset(Position::new(9, 0)), text.len() as u32);
        assert_eq!(p.position(text.len() as u32), Position::new(3, 1));
    }

    #[test]
    fn columns_count_in_the_negotiated_encoding() {
        // `Ù` is 2 bytes, 1 UTF-16 unit; `😀` is 4 bytes, 2 UTF-16 units, 1 scalar value.
        let text = "Ù😀x\n";
        let x = text.find('x').unwrap() as u32;
        for (encoding, column) in [
            (Encoding::Utf8, 6),
            (Encoding::Utf16, 3),
            (Encoding::Utf32, 2),
        ] {
            let (index, encoding) = positions(text, encoding);
            let p = Positions {
                text,
                index: &index,
                encoding,
            };
            assert_eq!(p.position(x), Position::new(0, column), "{encoding:?}");
            assert_eq!(p.offset(Position::new(0, column)), x, "{encoding:?}");
        }
        // Inside the surrogate pair, or inside a UTF-8 sequence: the character's start.
        let index = LineIndex::new(text);
        let p = Positions {
            text,
            index: &index,
            encoding: Encoding::Utf16,
        };
        assert_eq!(p.offset(Position::new(0, 2)), 2);
        let p = Positions {
            encoding: Encoding::Utf8,
            ..p
        };
        assert_eq!(p.offset(Position::new(0, 3)), 2);
        assert_eq!(p.position(3), Position::new(0, 2));
    }

    proptest::proptest! {
        #[test]
        fn an_edited_index_is_the_index_of_the_edited_text(
            text in "[ab\r\n]{0,12}",
            new in "[ab\r\n]{0,4}",
            a in 0usize..13,
            b in 0usize..13,
        ) {
            let (start, end) = (a.min(b).min(text.len()), a.max(b).min(text.len()));
            let mut index = LineIndex::new(&text);
            let mut edited = text.clone();
            edited.replace_range(start..end, &new);
            index.edited(&edited, Span::new(start, end), &new);
            proptest::prop_assert_eq!(index, LineIndex::new(&edited));
        }
    }

    #[test]
    fn the_client_chooses_among_those_offered() {
        let utf8 = [PositionEncodingKind::UTF16, PositionEncodingKind::UTF8];
        assert_eq!(Encoding::negotiate(Some(&utf8)), Encoding::Utf8);
        assert_eq!(Encoding::negotiate(None), Encoding::Utf16);
        let utf32 = [PositionEncodingKind::UTF32];
        assert_eq!(Encoding::negotiate(Some(&utf32)), Encoding::Utf32);
    }
}
