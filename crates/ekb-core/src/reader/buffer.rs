//! The reader's line buffer as `fgets` leaves it (SPEC §2.17): each call writes one line
//! and a closing NUL over the start of the buffer, and leaves the rest as an earlier,
//! longer line left it. The reader's loops that skip to a value test `isalnum` byte by byte
//! and do not stop at a NUL: past the line's end (or a NUL in it) they run on into those
//! leftovers, so a short line can load what is left of a longer one before it.

/// The lines read so far, as far as they still show in the buffer.
#[derive(Debug)]
pub struct LineBuffer {
    /// Its size: no line writes at or past it.
    size: usize,
    /// Each earlier line that still shows past the lines after it, as where it starts in
    /// the file and how long it is: longer the earlier, so that a byte's line is the last
    /// one long enough to hold it.
    earlier: Vec<(usize, usize)>,
}

impl LineBuffer {
    /// A buffer of `size` bytes, to read the lines of a file from its start.
    pub fn new(size: usize) -> LineBuffer {
        LineBuffer {
            size,
            earlier: Vec::new(),
        }
    }

    /// The line of `length` bytes at `start` in the file was read into the buffer.
    pub fn push(&mut self, start: usize, length: usize) {
        while self
            .earlier
            .last()
            .is_some_and(|&(_, earlier)| earlier <= length)
        {
            self.earlier.pop();
        }
        self.earlier.push((start, length));
    }

    /// The earlier line (where it starts, how long it is) whose bytes or closing NUL are at
    /// `at` in the buffer, if any.
    fn line_at(&self, at: usize) -> Option<(usize, usize)> {
        if at >= self.size {
            return None;
        }
        self.earlier
            .iter()
            .rev()
            .find(|&&(_, length)| length >= at)
            .copied()
    }
}

/// The buffer while the reader reads one line: the line, at `offset` in the file `text`,
/// over what `earlier` lines left.
#[derive(Debug, Clone, Copy)]
pub struct InBuffer<'a> {
    line: &'a [u8],
    offset: usize,
    /// How long the line is as a C string (up to its first NUL).
    c_length: usize,
    text: &'a [u8],
    earlier: Option<&'a LineBuffer>,
}

impl<'a> InBuffer<'a> {
    /// `line`, at `offset` in the file `text`, read after the lines of `earlier`.
    pub fn new(line: &'a [u8], offset: usize, text: &'a [u8], earlier: &'a LineBuffer) -> Self {
        InBuffer {
            earlier: Some(earlier),
            text,
            ..InBuffer::alone(line, offset)
        }
    }

    /// `line`, at `offset`, with nothing known of what the buffer held before.
    pub fn alone(line: &'a [u8], offset: usize) -> Self {
        InBuffer {
            line,
            offset,
            c_length: memchr::memchr(0, line).unwrap_or(line.len()),
            text: line,
            earlier: None,
        }
    }

    /// [`InBuffer::new`] of a line known to hold no NUL byte (not searched for one).
    pub fn without_nul(self) -> Self {
        InBuffer {
            c_length: self.line.len(),
            ..self
        }
    }

    /// The line as a C string: up to its first NUL.
    pub fn c_line(&self) -> &'a [u8] {
        &self.line[..self.c_length]
    }

    /// Where the line starts in the file.
    pub fn offset(&self) -> usize {
        self.offset
    }

    /// The byte at `at` in the buffer, or `None` if no line wrote it (undefined).
    pub fn byte(&self, at: usize) -> Option<u8> {
        match at.cmp(&self.line.len()) {
            std::cmp::Ordering::Less => Some(self.line[at]),
            std::cmp::Ordering::Equal => Some(0),
            std::cmp::Ordering::Greater => {
                let (start, length) = self.earlier?.line_at(at)?;
                Some(
                    self.text
                        .get(start + at)
                        .copied()
                        .filter(|_| at < length)
                        .unwrap_or(0),
                )
            }
        }
    }

    /// The C string at `at` in the buffer (up to the next NUL), with where its bytes are in
    /// the file and where the line that wrote them starts; `None` if no line wrote it.
    pub fn c_string(&self, at: usize) -> Option<CString<'a>> {
        let (piece, bytes) = match at <= self.line.len() {
            true => (self.offset, self.line),
            false => {
                let (start, length) = self.earlier?.line_at(at)?;
                (start, &self.text[start..start + length])
            }
        };
        let rest = &bytes[at..];
        let end = memchr::memchr(0, rest).unwrap_or(rest.len());
        Some(CString {
            bytes: &rest[..end],
            piece,
            at,
        })
    }

    /// The first position at or after `at` whose byte `skip` does not match, as the
    /// reader's `while (skip(input_string[i])) i++` finds it: on past the line's C string,
    /// a NUL and the line's end; `None` where it runs into bytes no line wrote.
    pub fn skip(&self, at: usize, skip: impl Fn(u8) -> bool + Copy) -> Option<usize> {
        if let Some(found) = crate::robot::scan::skip_while(self.c_line(), at, skip) {
            return Some(found);
        }
        (at.max(self.c_length)..).find_map(|at| match self.byte(at) {
            None => Some(None),
            Some(byte) if !skip(byte) => Some(Some(at)),
            Some(_) => None,
        })?
    }
}

/// A C string in the buffer.
#[derive(Debug, Clone, Copy)]
pub struct CString<'a> {
    pub bytes: &'a [u8],
    /// Where the line that wrote it starts in the file.
    pub piece: usize,
    /// Where it starts in the buffer.
    pub at: usize,
}

impl CString<'_> {
    /// Where it starts in the file.
    pub fn file_offset(&self) -> usize {
        self.piece + self.at
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn past_a_line_the_buffer_holds_what_the_last_longer_line_left() {
        let text = b"abcdefgh\nxy\nlong line\n";
        let mut history = LineBuffer::new(200);
        history.push(0, 9);
        history.push(9, 3);
        let line = InBuffer::new(b"12345678901\n", 100, text, &history);
        assert_eq!(line.byte(12), Some(0));
        assert_eq!(line.byte(13), None, "no line wrote it");
        let short = InBuffer::new(b"q\n", 100, text, &history);
        // `q\n\0`, then `xy\n\0`'s NUL at 3, then `abcdefgh\n\0` from 4.
        assert_eq!(short.byte(2), Some(0));
        assert_eq!(short.byte(3), Some(0));
        assert_eq!(short.byte(4), Some(b'e'));
        let rest = short.c_string(4).unwrap();
        assert_eq!(
            (rest.bytes, rest.piece, rest.file_offset()),
            (&b"efgh\n"[..], 0, 4)
        );
        assert_eq!(short.skip(1, |b| !b.is_ascii_alphanumeric()), Some(4));
        history.push(12, 10);
        let after = InBuffer::new(b"q\n", 100, text, &history);
        assert_eq!(after.c_string(4).unwrap().bytes, b" line\n");
    }

    #[test]
    fn the_skip_goes_on_past_a_nul() {
        let line = InBuffer::alone(b"key 1\0Hall\n", 0);
        assert_eq!(line.c_line(), b"key 1");
        assert_eq!(line.skip(5, |b| !b.is_ascii_alphanumeric()), Some(6));
        assert_eq!(line.c_string(6).unwrap().bytes, b"Hall\n");
        assert_eq!(line.skip(10, |b| !b.is_ascii_alphanumeric()), None);
    }
}
