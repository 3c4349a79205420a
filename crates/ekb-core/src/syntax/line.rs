use super::{first_gap, is_blank, newline, next_non_blank, Span};

/// The UTF-8 byte-order mark.
pub const BOM: &str = "\u{FEFF}";

/// How a line ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineEnding {
    Lf,
    CrLf,
    /// The last line of a file that does not end with a newline.
    None,
}

impl LineEnding {
    pub fn as_str(self) -> &'static str {
        match self {
            LineEnding::Lf => "\n",
            LineEnding::CrLf => "\r\n",
            LineEnding::None => "",
        }
    }
}

/// What a line holds between its indentation and its trailing whitespace.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Body {
    /// Nothing but whitespace.
    Blank,
    /// `# …`, from the `#` to the last non-blank character.
    Comment(Span),
    /// A key and, after the blanks that follow it, its arguments (an id and a value, or the
    /// tour). `args` is empty (and placed right after the key) when the key stands alone.
    Entry { key: Span, args: Span },
}

/// One line of a file, as spans into its text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Line {
    /// 1-based line number.
    pub number: u32,
    /// The whole line, line ending included.
    pub span: Span,
    /// Leading spaces and tabs.
    pub indent: Span,
    pub body: Body,
    /// Spaces and tabs after the body (for a blank line: empty, the indent holds them).
    pub trailing: Span,
    pub ending: LineEnding,
}

impl Line {
    /// The line without its ending.
    pub fn content(&self) -> Span {
        Span {
            start: self.span.start,
            end: self.trailing.end,
        }
    }

    /// The line's bytes in order, each part once: indent, key, gap, args (or comment), trailing
    /// whitespace, ending. Empty parts are included; together they cover [`Line::span`].
    pub fn parts(&self) -> Vec<Span> {
        let mut parts = vec![self.indent];
        match self.body {
            Body::Blank => {}
            Body::Comment(comment) => parts.push(comment),
            Body::Entry { key, args } => {
                parts.push(key);
                parts.push(Span {
                    start: key.end,
                    end: args.start,
                });
                parts.push(args);
            }
        }
        parts.push(self.trailing);
        parts.push(Span {
            start: self.trailing.end,
            end: self.span.end,
        });
        parts
    }
}

/// The lines of `text`, lexed lazily (nothing is stored, so this is cheap on any file size).
pub fn lines(text: &str) -> Lines<'_> {
    lines_from(text, 0)
}

/// The lines of `text` from byte `offset`, the start of a line, on; numbered from 1 at that
/// line (so not the file's line numbers, unless `offset` is 0).
pub fn lines_from(text: &str, offset: usize) -> Lines<'_> {
    Lines {
        text,
        offset,
        number: 0,
    }
}

/// Iterator returned by [`lines`] and [`lines_from`].
#[derive(Debug, Clone)]
pub struct Lines<'a> {
    text: &'a str,
    offset: usize,
    number: u32,
}

impl Iterator for Lines<'_> {
    type Item = Line;

    fn next(&mut self) -> Option<Line> {
        let bytes = self.text.as_bytes();
        let start = self.offset;
        if start >= bytes.len() {
            return None;
        }
        self.number += 1;
        let (content_end, ending, end) = match newline::find(&bytes[start..]) {
            Some(i) if i > 0 && bytes[start + i - 1] == b'\r' => {
                (start + i - 1, LineEnding::CrLf, start + i + 1)
            }
            Some(i) => (start + i, LineEnding::Lf, start + i + 1),
            None => (bytes.len(), LineEnding::None, bytes.len()),
        };
        self.offset = end;
        Some(lex_line(
            bytes,
            self.number,
            start,
            content_end,
            ending,
            end,
        ))
    }
}

fn lex_line(
    bytes: &[u8],
    number: u32,
    start: usize,
    content_end: usize,
    ending: LineEnding,
    end: usize,
) -> Line {
    // A byte-order mark belongs to the first line's indentation, not to its key.
    let after_bom = if start == 0 && bytes.starts_with(BOM.as_bytes()) {
        BOM.len()
    } else {
        start
    };
    // Nearly every line starts with its key: no search then.
    let body_start = match bytes.get(after_bom) {
        Some(&first) if after_bom < content_end && !is_blank(first) => after_bom,
        _ => next_non_blank(bytes, after_bom, content_end),
    };
    let mut body_end = content_end;
    while body_end > body_start && is_blank(bytes[body_end - 1]) {
        body_end -= 1;
    }
    let body = if body_start == body_end {
        Body::Blank
    } else if bytes[body_start] == b'#' {
        Body::Comment(Span::new(body_start, body_end))
    } else {
        let (key_end, args_start) = first_gap(bytes, body_start, body_end);
        Body::Entry {
            key: Span::new(body_start, key_end),
            args: Span::new(args_start, body_end),
        }
    };
    let trailing_start = if body == Body::Blank {
        content_end
    } else {
        body_end
    };
    Line {
        number,
        span: Span::new(start, end),
        indent: Span::new(start, body_start.min(trailing_start)),
        body,
        trailing: Span::new(trailing_start, content_end),
        ending,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rebuild(text: &str) -> String {
        lines(text)
            .flat_map(|line| line.parts())
            .map(|span| span.text(text))
            .collect()
    }

    #[test]
    fn every_byte_belongs_to_one_part() {
        for text in [
            "",
            "\n",
            "  \t \r\n",
            "key 1 value  \r\nnext\t2\tv\n# comment \nlast",
            "tourSpecification 5 1 4 3 2 5",
            "   # indented comment\n\n\nkey",
            "\u{FEFF}key 1 v\n\u{FEFF}not a mark\n",
            "\u{FEFF} \tkey\n",
            "\u{FEFF}\n",
        ] {
            assert_eq!(rebuild(text), text);
        }
    }

    #[test]
    fn an_entry_is_split_into_key_and_args() {
        let text = "  gestureTarget\t 1 0.0 0.0 0.0  \r\n";
        let line = lines(text).next().unwrap();
        let Body::Entry { key, args } = line.body else {
            panic!("not an entry: {line:?}")
        };
        assert_eq!(key.text(text), "gestureTarget");
        assert_eq!(args.text(text), "1 0.0 0.0 0.0");
        assert_eq!(line.trailing.text(text), "  ");
        assert_eq!(line.indent.text(text), "  ");
        assert_eq!(line.ending, LineEnding::CrLf);
    }

    #[test]
    fn a_byte_order_mark_is_indentation_on_the_first_line_only() {
        for (text, indent) in [
            ("\u{FEFF}key 1 v", "\u{FEFF}"),
            ("\u{FEFF}\t key 1 v", "\u{FEFF}\t "),
        ] {
            let line = lines(text).next().unwrap();
            assert_eq!(line.indent.text(text), indent);
            let Body::Entry { key, .. } = line.body else {
                panic!("not an entry: {line:?}")
            };
            assert_eq!(key.text(text), "key");
        }
        let text = "a\n\u{FEFF}b 1";
        let second = lines(text).nth(1).unwrap();
        assert!(second.indent.is_empty());
        assert!(matches!(second.body, Body::Entry { key, .. } if key.text(text) == "\u{FEFF}b"));
    }

    #[test]
    fn blank_and_comment_lines() {
        let text = " \t\n # note \n";
        let all: Vec<Line> = lines(text).collect();
        assert_eq!(all[0].body, Body::Blank);
        assert_eq!(all[0].indent.text(text), " \t");
        assert!(matches!(all[1].body, Body::Comment(c) if c.text(text) == "# note"));
        assert_eq!(all[1].number, 2);
    }
}
