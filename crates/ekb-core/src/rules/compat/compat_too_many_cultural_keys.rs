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
/// past the buffer's two is written over what follows it (the third over the location's
/// word count), and the reader crashes the next time it updates the location, which each
/// of its other lines that it reads makes it do, before or after. A line of a key that the
/// version ignores (`gestureArm` but on `2026-03`, the other pose key) updates nothing: on
/// an id with no line the reader reads but this one, the words make a new location, which
/// loads with its word count overwritten and no crash (measured on the real readers).
pub fn crashes(location: &Location<'_>, reader: Reader) -> bool {
    let read_keys = Key::ALL
        .into_iter()
        .filter(|&key| key != Key::CulturalKnowledge && reader.reads(key))
        .fold(0u16, |keys, key| keys | 1 << key.order());
    let other_lines = location.given & read_keys != 0;
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
    /// line of the location, before or after, makes it update the location. Where no other
    /// line of the location is one the chosen reader reads (a location of that line alone,
    /// or with a `gestureArm` line that the version ignores), it does not crash, but the
    /// third word's pointer lands on the location's word count: the location loads with a
    /// word count that is garbage, and whatever reads its culture knowledge reads memory that
    /// holds no word.
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
    let id = location.id;
    let consequence = if crashes(location, reader) {
        " and crashes while the robot starts".to_string()
    } else {
        format!(
            ", the third word's pointer over the location's word count; no other line of location {id} that reader {reader} reads makes it update the location, so it does not crash, but location {id} loads with a garbage word count, and whatever reads its culture knowledge reads memory that holds no word"
        )
    };
    out.push_with(&COMPAT_TOO_MANY_CULTURAL_KEYS, || Diagnostic::new(&COMPAT_TOO_MANY_CULTURAL_KEYS,
            span,
            format!(
                "location {id} has {} culturalKnowledge words, but the robot's reader has room for {MAX_CULTURAL_KEYS}: it writes {} past the end of its buffer{consequence}",
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
