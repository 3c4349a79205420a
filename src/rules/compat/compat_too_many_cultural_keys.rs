use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::{Key, Location};
use crate::reader::line::word_pieces;
use crate::reader::Reader;
use crate::render::clip;
use crate::rules::declare_rule;
use crate::syntax::{self, Span};

/// The robot's buffer holds this many culturalKnowledge words per location.
pub const MAX_CULTURAL_KEYS: usize = 2;

/// From this many words loaded, the ones written past the buffer reach far enough to crash
/// the reader (SPEC §2.12: two words that it splits in two, four words in all).
const CRASHING_WORDS: usize = 2 * MAX_CULTURAL_KEYS;

/// How many words the reader loads from a culturalKnowledge value: one at each run of
/// letters and digits, so `Bow's` counts twice.
pub fn loaded_words(value: &str) -> usize {
    syntax::tokens(value, 0)
        .map(|(_, word)| word_pieces(word).len())
        .sum()
}

/// Whether `reader` crashes on `location`'s culturalKnowledge words (the same number of
/// words crashes it, written apart or split by the reader).
pub fn crashes(location: &Location<'_>, reader: Reader) -> bool {
    reader.reads(Key::CulturalKnowledge)
        && location
            .cultural_knowledge()
            .is_some_and(|words| loaded_words(words.value) >= CRASHING_WORDS)
}

declare_rule! {
    /// ## What it does
    /// Flags a `culturalKnowledge` line with more than 2 words.
    ///
    /// ## Why it matters
    /// The robot's reader has room for 2 culture-knowledge keys per location and writes
    /// the rest past the end of that buffer, over the memory that follows: a third word
    /// corrupts the location's count of words, and from four words (counted as the reader
    /// counts them, `compat-cultural-word-split`) the reader crashes while the robot starts.
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
