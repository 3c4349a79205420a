use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Key, KnowledgeBase, Location};
use crate::reader::chunks;
use crate::reader::line::{self, word_pieces, LineRead, LoadedValue};
use crate::render::clip;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::{self, Span};

/// The robot's buffer holds this many culturalKnowledge words per location.
pub const MAX_CULTURAL_KEYS: usize = 2;

/// How many words the reader loads from a culturalKnowledge value: one at each run of
/// letters and digits, so `Bow's` counts twice.
pub fn loaded_words(value: &str) -> usize {
    syntax::tokens(value, 0)
        .map(|(_, word)| word_pieces(word).len())
        .sum()
}

/// Whether `reader` crashes on `location`'s culturalKnowledge words, counted as the reader
/// reads their line (written apart, split by the reader, or an indented line's id). A word
/// past the buffer's two is written over what follows it, and the reader crashes the next
/// time it updates the location, which each of its other lines makes it do, before or after
/// (measured on the real readers: a location of that one line alone loads, its memory
/// corrupt).
pub fn crashes(location: &Location<'_>, reader: Reader) -> bool {
    let other_lines = location.given & !(1 << Key::CulturalKnowledge.order()) != 0;
    reader.reads(Key::CulturalKnowledge)
        && other_lines
        && location.cultural_knowledge().is_some_and(|words| {
            let loaded = match read_line_at(location.file_text(), words.span.start, reader) {
                Some(LineRead::Value {
                    value: LoadedValue::Words(loaded),
                    ..
                }) => loaded.len(),
                _ => 0,
            };
            loaded > MAX_CULTURAL_KEYS
        })
}

/// What `reader` reads from the line of `text` that holds byte `at` (its first `fgets`
/// call's worth).
fn read_line_at(text: &str, at: u32, reader: Reader) -> Option<LineRead> {
    let start =
        memchr::memrchr(b'\n', &text.as_bytes()[..at as usize]).map_or(0, |newline| newline + 1);
    let (_, piece) = chunks(&text.as_bytes()[start..], reader.line_buffer()).next()?;
    Some(line::read(piece, start, reader))
}

declare_rule! {
    /// ## What it does
    /// Flags a `culturalKnowledge` line with more than 2 words.
    ///
    /// ## Why it matters
    /// The robot's reader has room for 2 culture-knowledge keys per location and writes
    /// the rest past the end of that buffer, over the memory that follows: a third word
    /// (counted as the reader counts them, `compat-cultural-word-split`) corrupts the
    /// location's words, and the reader crashes while the robot starts as soon as another
    /// line of the location, before or after, makes it update the location.
    ///
    /// ## Example
    /// ```text
    /// culturalKnowledge             1 SymbolicShapeRespect BowExtentRespect DeicticShape
    /// ```
    pub static COMPAT_TOO_MANY_CULTURAL_KEYS = {
        name: "compat-too-many-cultural-keys",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "more than 2 `culturalKnowledge` words",
    };
}

pub fn check(location: &Location<'_>, reader: Reader, out: &mut Diagnostics) {
    let Some(value) = location
        .cultural_knowledge()
        .filter(|_| reader.reads(Key::CulturalKnowledge))
    else {
        return;
    };
    let words: Vec<(Span, &str)> = syntax::tokens(value.value, value.span.start as usize).collect();
    if words.len() <= MAX_CULTURAL_KEYS {
        return;
    }
    let dropped = &words[MAX_CULTURAL_KEYS..];
    let span = dropped[0].0.cover(dropped[dropped.len() - 1].0);
    let names: Vec<&str> = dropped.iter().map(|(_, word)| *word).collect();
    let consequence = if crashes(location, reader) {
        "and crashes while the robot starts"
    } else {
        "and corrupts the robot's memory"
    };
    out.push_with(&COMPAT_TOO_MANY_CULTURAL_KEYS, || Diagnostic::new(&COMPAT_TOO_MANY_CULTURAL_KEYS,
            span,
            format!(
                "location {} has {} culturalKnowledge words, but the robot's reader has room for {MAX_CULTURAL_KEYS}: it writes {} past the end of its buffer {consequence}",
                location.id,
                words.len(),
                clip::shown(&names.join(", "))
            ),
        )
        .at_location(Some(location.id))
        .with_help("keep the two that matter most"),
    );
}

/// Checks the culturalKnowledge lines that a later line of their location overwrites: the
/// reader still reads each, and one of more words than its buffer holds writes past it
/// before the later line is read (measured: `culturalKnowledge 1 A B C`, then the robot's
/// file, crashes `2025-06`). Looked for only in a file with such lines.
pub fn check_overwritten(
    kb: &KnowledgeBase<'_>,
    text: &str,
    reader: Reader,
    out: &mut Diagnostics,
) {
    if !reader.reads(Key::CulturalKnowledge) {
        return;
    }
    let mut kept: Vec<u32> = kb
        .locations()
        .iter()
        .filter_map(|location| location.cultural_knowledge().map(|words| words.span.start))
        .collect();
    if kb.lines.count(Key::CulturalKnowledge) <= kept.len() {
        return;
    }
    kept.sort_unstable();
    for (key, args) in super::lines_of_key(text, Key::CulturalKnowledge) {
        let first_kept = kept.partition_point(|&start| start < key.start);
        if kept.get(first_kept).is_some_and(|&start| start <= args.end) {
            continue;
        }
        let Some(LineRead::Value {
            id,
            value: LoadedValue::Words(words),
            ..
        }) = read_line_at(text, key.start, reader)
        else {
            continue;
        };
        if words.len() > MAX_CULTURAL_KEYS {
            out.push_with(&COMPAT_TOO_MANY_CULTURAL_KEYS, || {
                Diagnostic::new(
                    &COMPAT_TOO_MANY_CULTURAL_KEYS,
                    args,
                    format!(
                        "the robot's reader loads {} culturalKnowledge words from this line, which a later line of location {id} overwrites, but it has room for {MAX_CULTURAL_KEYS}: it writes past the end of its buffer first, and crashes while the robot starts",
                        words.len()
                    ),
                )
                .at_location(u32::try_from(id).ok())
                .with_help("delete this line, or keep two words on it")
            });
        }
    }
}
