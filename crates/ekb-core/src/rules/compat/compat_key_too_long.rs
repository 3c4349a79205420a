use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::build::leading_id;
use crate::model::{Key, KnowledgeBase};
use crate::reader::chunks;
use crate::render::clip;
use crate::robot::key_buffer;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::{self, Body, Span};

declare_rule! {
    /// ## What it does
    /// Flags a word of 100 bytes or more where the robot's reader copies a word into a
    /// 100-byte buffer (200 bytes on `2026-03` and `2026-04`): the first word of every line it reads (a
    /// comment's too, and the rest of a line it cut), and each `culturalKnowledge` word.
    ///
    /// ## Why it matters
    /// The reader copies the word with no bound (`sscanf("%s")`), so a longer one is written
    /// past the end of the buffer, over the memory that follows: what it loads afterwards is
    /// undefined, and the reader may crash.
    ///
    /// ## Example
    /// ```text
    /// #See_https://example.org/a/very/long/link/without/a/single/blank/in/it/that/runs/on/and/on/and/on/and/on
    /// ```
    /// Put a blank within the first 99 bytes of the word, or shorten it.
    pub static COMPAT_KEY_TOO_LONG = {
        name: "compat-key-too-long",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a first word of a line, or a culturalKnowledge word, of 100 bytes or more (200 on 2026-03 and 2026-04): it overflows the reader's word buffer",
    };
}

/// Checks the words of `kb`'s lines, as `reader` cuts them, and its culturalKnowledge words.
pub fn check(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    let buffer = reader.key_buffer();
    let mut lines: Vec<Span> = kb.lines.long_first_words.clone();
    lines.extend(&kb.lines.long_lines);
    lines.sort_unstable_by_key(|span| span.start);
    for span in lines {
        let line = &text.as_bytes()[span.range()];
        // Found once a line (reading the line is as long as the line), not at each piece.
        let mut location = None;
        for (offset, piece) in chunks(line, reader.line_buffer()) {
            let Some(word) = key_buffer::first_word(piece).filter(|w| w.len() >= buffer) else {
                continue;
            };
            // The reader cuts bytes: a word may start or end inside a character.
            let at = span.start as usize + offset;
            let word_span = Span::of_characters(text, at + word.start, at + word.end);
            let what = if offset == 0 {
                "the first word of this line"
            } else {
                "the first word of the rest of this line, which the reader reads as a line of its own,"
            };
            let bytes = word.len();
            let location = *location.get_or_insert_with(|| location_of(span, text));
            report(word_span, bytes, buffer, text, what, location, out);
        }
    }
    if !reader.reads(Key::CulturalKnowledge) {
        return;
    }
    for location in kb.locations().iter() {
        let Some(words) = location.cultural_knowledge() else {
            continue;
        };
        for (word_span, word) in syntax::tokens(words.value, words.span.start as usize) {
            if word.len() >= buffer {
                let what = "this culturalKnowledge word";
                let id = Some(location.id);
                report(word_span, word.len(), buffer, text, what, id, out);
            }
        }
    }
}

/// The location whose line starts at `line`, if it is a location's.
fn location_of(line: Span, text: &str) -> Option<u32> {
    let Body::Entry { key, args } = syntax::lines_from(text, line.start as usize).next()?.body
    else {
        return None;
    };
    Key::from_name(key.text(text))
        .filter(|&key| key != Key::TourSpecification)
        .and_then(|_| leading_id(args.text(text)))
}

/// Reports the word at `span`, of which the reader copies `bytes` bytes.
fn report(
    span: Span,
    bytes: usize,
    buffer: usize,
    text: &str,
    what: &str,
    location: Option<u32>,
    out: &mut Diagnostics,
) {
    out.push_with(&COMPAT_KEY_TOO_LONG, || {
        let word = &text[span.range()];
        Diagnostic::new(
            &COMPAT_KEY_TOO_LONG,
            span,
            format!(
                "{what} is {bytes} bytes long (`{}`): the robot's reader copies it into a buffer of {buffer} bytes and writes past its end, so what it loads is undefined and it may crash",
                clip::shown(word),
            ),
        )
        .at_location(location)
        .with_help(format!("put a blank within its first {} bytes, or shorten it", buffer - 1))
    });
}
