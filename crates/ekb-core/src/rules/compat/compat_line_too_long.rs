use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::build::leading_id;
use crate::model::{Key, KnowledgeBase, ValueKind};
use crate::reader::line as reader_line;
use crate::reader::{chunks, is_carriage_return_at_a_cut};
use crate::robot::Reader;
use crate::rules::{declare_rule, excerpt};
use crate::syntax::{self, Body, Line, Span};

declare_rule! {
    /// ## What it does
    /// Flags a line as long as the chosen reader's line buffer or longer, counting its
    /// newline: 200 bytes for `d5.4.2` and `2025-06`, 300 for `2026-02`, 600 for `2026-03`
    /// and `2026-04`. Bytes, not characters: an isiZulu or Kinyarwanda letter with an
    /// accent takes two.
    ///
    /// Not a line whose cut changes nothing the reader loads: a line of blanks, a comment
    /// whose rest is no line the reader reads, a CRLF line cut between its `\r` and `\n`,
    /// a line cut right after a lone `\r` (the reader takes that `\r` for the line's end,
    /// drops it as it would the newline, and reads what follows as a line of its own, as
    /// if the `\r` were a `\n`). A cut in what follows such a `\r` is still one.
    ///
    /// ## Why it matters
    /// The robot's reader reads lines into a fixed buffer. A longer line is cut after 199
    /// (299, 599) bytes; the rest is read as a line of its own (and ignored), so the robot
    /// stops talking mid-sentence, and the message also loses its last letter.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      2 And this one is another Pepper robot, just like me! We are semi-humanoid robots … (230 bytes)
    /// ```
    /// Shorten the message to fit in 199 bytes with its key and id (for `2025-06`).
    pub static COMPAT_LINE_TOO_LONG = {
        name: "compat-line-too-long",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a line as long as the reader's line buffer or longer (200, 300 or 600 bytes, newline included)",
    };
}

/// Checks the long lines of `kb` against `reader`'s line buffer.
pub fn check(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    let buffer = reader.line_buffer();
    for &span in &kb.lines.long_lines {
        if span.len() < buffer {
            continue;
        }
        let Some(after) = changing_part(&text.as_bytes()[span.range()], reader) else {
            continue;
        };
        out.push_with(&COMPAT_LINE_TOO_LONG, || {
            let line = syntax::lines_from(text, span.start as usize + after)
                .next()
                .expect("a line starts there");
            diagnostic(&line, text, reader, after)
        });
    }
}

/// Where the first part of `line` (its ending included) starts whose cut changes what
/// `reader` loads ([`cut_changes_what_loads`]), if one does: the parts are what the reader
/// reads as lines, the line cut after each lone `\r` that ends what its buffer holds
/// ([`is_carriage_return_at_a_cut`]), which the reader takes for the line's end.
fn changing_part(line: &[u8], reader: Reader) -> Option<usize> {
    let buffer = reader.line_buffer();
    let mut ends: Vec<usize> = memchr::memchr_iter(b'\r', line)
        .filter(|&at| is_carriage_return_at_a_cut(line, at, buffer))
        .map(|at| at + 1)
        .collect();
    ends.push(line.len());
    let mut start = 0;
    for end in ends {
        if cut_changes_what_loads(&line[start..end], reader) {
            return Some(start);
        }
        start = end;
    }
    None
}

/// Whether cutting `line` (its ending included) into the pieces that `reader` reads
/// changes what it loads: a piece after the first loads something, or the first loads
/// other than the line whole would, with a `\n` for its ending (the `\r` of a CRLF ending
/// is `compat-crlf`'s; a lone `\r` that ends a part of a line, [`changing_part`], is its
/// ending).
fn cut_changes_what_loads(line: &[u8], reader: Reader) -> bool {
    let mut pieces = chunks(line, reader.line_buffer());
    let Some((_, first)) = pieces.next() else {
        return false;
    };
    if pieces.any(|(offset, piece)| {
        !reader_line::loads_nothing(&reader_line::read(piece, offset, reader))
    }) {
        return true;
    }
    let content = line.strip_suffix(b"\n").unwrap_or(line);
    let content = content.strip_suffix(b"\r").unwrap_or(content);
    let whole = [content, b"\n"].concat();
    let cut = reader_line::read(first, 0, reader);
    !reader_line::same_load(&cut, first, &reader_line::read(&whole, 0, reader), &whole)
}

/// The finding about `line`, which is too long for `reader`; or, if `after` is not 0, about
/// what follows the first `after` bytes of it, which end in a lone `\r` that the reader
/// takes for the line's end (`line` then starts after that `\r`).
fn diagnostic(line: &Line, text: &str, reader: Reader, after: usize) -> Diagnostic {
    let buffer = reader.line_buffer();
    let length = line.span.len();
    let content = line.content();
    let content_end = content.end as usize;
    // The robot reads the first `buffer - 1` bytes (here never half a character) ...
    let read_end = line.span.start as usize + buffer - 1;
    let mut cut = read_end.min(content_end);
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    // ... and, for a text value, drops the last of them, taking it for the newline (unless
    // that is the `\r` of a CRLF ending, which then costs no letter).
    let (key, id) = match line.body {
        Body::Entry { key, args } => {
            let key = Key::from_name(key.text(text));
            let id = key
                .filter(|&key| key != Key::TourSpecification)
                .and_then(|_| leading_id(args.text(text)));
            (key, id)
        }
        _ => (None, None),
    };
    let is_text = key.is_some_and(|key| key.value_kind() == ValueKind::Text);
    let drops_letter = is_text && read_end <= content_end;
    let last_char = |end: usize| {
        text[..end]
            .char_indices()
            .next_back()
            .map_or(end, |(i, _)| i)
    };
    let kept_end = if drops_letter {
        last_char(cut).max(content.start as usize)
    } else {
        cut
    };
    let what = if cut < content_end {
        format!(
            "the robot's reader stops at \"…{}\" and reads the rest, \"{}\", as a line of its own",
            tail(&text[content.start as usize..kept_end]),
            excerpt(&text[cut..content_end])
        )
    } else {
        // A line whose content fits and that is still reported is a text that loses its
        // last letter ([`cut_changes_what_loads`]).
        "only its newline does not fit, so the robot's reader drops its last character instead"
            .to_string()
    };
    // Point at what the robot loses; when that is only the newline, at the last character.
    let lost = if kept_end < content_end {
        kept_end
    } else {
        last_char(content_end)
    };
    let this = match after {
        0 => "this line".to_string(),
        _ => format!(
            "what follows the `\\r` after the first {after} bytes of this line, which reader {reader} takes for the line's end and reads as a line of its own,"
        ),
    };
    Diagnostic::new(
        &COMPAT_LINE_TOO_LONG,
        Span::new(lost, content_end),
        format!(
            "{this} is {length} bytes long, but reader {reader} reads at most {} bytes per line: {what}",
            buffer - 1
        ),
    )
    .at_location(id)
    .with_help(format!(
        "shorten the line by {} bytes or more",
        length - (buffer - 1)
    ))
}

/// The last few characters of `text`.
fn tail(text: &str) -> &str {
    let start = text.char_indices().rev().nth(23).map_or(0, |(i, _)| i);
    &text[start..]
}
