use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::leading_id;
use crate::model::{Key, KnowledgeBase, Value};
use crate::reader;
use crate::reader::line::{LineRead, LoadedValue};
use crate::robot::Reader;
use crate::rules::compat::compat_too_many_cultural_keys::{crashes, MAX_CULTURAL_KEYS};
use crate::rules::{declare_rule, excerpt};
use crate::syntax::{self, Body, Span, BOM};

declare_rule! {
    /// ## What it does
    /// Flags a line of a key that starts with a space or a tab, and removes the indentation.
    ///
    /// ## Why it matters
    /// The robot's reader finds a value by counting from the start of the line as if the key
    /// stood there. Indented, it reads from the wrong place: the id becomes the first number
    /// or the first word of the text, and an indented tour is not read at all. On an indented
    /// `culturalKnowledge` line the id is a third word for a buffer of two: with another line
    /// of that location, the reader crashes.
    ///
    /// ## Example
    /// ```text
    ///  robotLocationPose            1 2.0 3.0 90
    /// ```
    /// loads the pose `1 2 3`, and
    /// ```text
    ///  preGestureMessageEnglish     1 Hello
    /// ```
    /// the text `1 Hello`.
    pub static COMPAT_INDENTED_LINE = {
        name: "compat-indented-line",
        category: Compat,
        severity: Error,
        fixable: true,
        summary: "a keyed line that starts with a space or a tab",
    };
}

/// Checks the indented lines of `kb` that `reader` reads.
pub fn check(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    for &span in &kb.lines.indented_lines {
        let Some(line) = syntax::lines_from(text, span.start as usize).next() else {
            continue;
        };
        let Body::Entry {
            key: key_span,
            args,
        } = line.body
        else {
            continue;
        };
        let Some(key) = Key::from_name(key_span.text(text)).filter(|&key| reader.reads(key)) else {
            continue;
        };
        let id = (key != Key::TourSpecification)
            .then(|| leading_id(args.text(text)))
            .flatten();
        // A byte-order mark before the blanks is `compat-bom`'s to remove.
        let bom = if text[span.range()].starts_with(BOM) {
            BOM.len()
        } else {
            0
        };
        let indentation = Span::new(span.start as usize + bom, key_span.start as usize);
        let crash = if crashes_on_words_of(kb, id, span.start as usize, reader) {
            ", and crashes while the robot starts"
        } else {
            ""
        };
        out.push_with(&COMPAT_INDENTED_LINE, || {
            Diagnostic::new(
                &COMPAT_INDENTED_LINE,
                indentation,
                format!(
                    "`{}` is indented: the robot's reader counts from the start of the line and {}{crash}",
                    key.name(),
                    what_loads(text, span, reader)
                ),
            )
            .at_location(id)
            .with_help("start the line with its key")
            .with_fix("remove the indentation", vec![Edit::delete(indentation)])
        });
    }
}

/// Whether the indented line whose indentation starts at `indentation` holds location
/// `id`'s culturalKnowledge words (not overwritten by a later line) and `reader` crashes on
/// them: the line's id counts as a word.
pub fn crashes_on_words_of(
    kb: &KnowledgeBase<'_>,
    id: Option<u32>,
    indentation: usize,
    reader: Reader,
) -> bool {
    id.and_then(|id| kb.location(id)).is_some_and(|location| {
        let on_this_line = |words: Value<&str>| {
            let before = location
                .file_text()
                .as_bytes()
                .get(indentation..words.span.start as usize);
            before.is_some_and(|before| memchr::memchr(b'\n', before).is_none())
        };
        location.cultural_knowledge().is_some_and(on_this_line) && crashes(location, reader)
    })
}

/// What `reader` loads from the line at `span`, in words.
fn what_loads(text: &str, span: Span, reader: Reader) -> String {
    let line = &text.as_bytes()[span.range()];
    let (_, chunk) = reader::chunks(line, reader.line_buffer())
        .next()
        .expect("a line is not empty");
    let loaded = |span: &Span| {
        excerpt(&String::from_utf8_lossy(&text.as_bytes()[span.range()])).into_owned()
    };
    match reader::line::read(chunk, span.start as usize, reader) {
        LineRead::Value { value, .. } => match value {
            LoadedValue::Numbers([a, b, c]) => format!("loads the numbers `{a} {b} {c}`"),
            LoadedValue::Text(span) => format!("loads the text \"{}\"", loaded(&span)),
            LoadedValue::Words(words) => {
                let overflow = if words.len() > MAX_CULTURAL_KEYS {
                    format!(", more than its buffer of {MAX_CULTURAL_KEYS} holds: it writes past its end")
                } else {
                    String::new()
                };
                let words: Vec<String> = words.iter().map(loaded).collect();
                format!("loads the words `{}`{overflow}", words.join(" "))
            }
            LoadedValue::Undefined => "loads whatever its buffer held before".to_string(),
        },
        LineRead::TourFailed => "loads no tour at all".to_string(),
        LineRead::Tour { .. } => "loads the tour from the wrong place".to_string(),
        LineRead::Failed { .. } | LineRead::Ignored { .. } | LineRead::Skipped => {
            "cannot read the value, so it ignores the line".to_string()
        }
    }
}
